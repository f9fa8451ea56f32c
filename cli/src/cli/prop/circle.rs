//! Seed 000 Prop 6.1 on user data: the cubic LN approximation `ca` of the unit
//! arc of half-angle `α` with normal map `N0 (1-t) + κ N1 t`, the printed case
//! split and the closed-form distance `max |‖ca‖ - 1|`.
//!
//! The angle is given either in radians (`--alpha`, whose `sin`/`cos` are
//! enclosed rigorously) or as an exact unit vector (`--cos --sin`). The direct
//! check encloses `max_{t ∈ [0,1]} |‖ca(t)‖ - 1|` without the proposition: the
//! maximum is at `t = 0`, `t = 1` or a root of `(‖ca‖²)'`, and every such root
//! lies in a candidate box of [`enclose_roots`]; the closed form must overlap it.

use super::PropArgs;
use crate::cli::args::{bad, ln_error, optional_number, q, required_number};
use crate::cli::report::{show_interval, Report};
use crate::cli::CliError;
use lncert::ln::circle::{ArcApprox, Prop61Case};
use lncert::ln::LnError;
use lncert::poly::enclose_roots;
use lncert::scalar::{
    frac, interval_from_rational, interval_to_json, sin_cos_enclosure, Interval, Rational,
    ScalarSqrt,
};
use serde_json::{json, Value};

const USAGE: &str = "prop 000:6.1 (--alpha RADIANS | --cos C --sin S) --kappa K";

/// Candidate boxes narrower than this are not split further.
const ROOT_WIDTH: f64 = 1e-12;
/// Budget of subdivision boxes for the direct check.
const MAX_BOXES: usize = 200_000;

/// Reports an [`ArcApprox::new`] error against `--kappa` or the angle flag.
fn arc_error(e: LnError, angle_flag: &str) -> CliError {
    let kappa = matches!(
        &e,
        LnError::InvalidParameter { field: "kappa", .. } | LnError::Undecided { field: "kappa" }
    );
    ln_error(if kappa { "--kappa" } else { angle_flag }, e)
}

/// `--alpha`: radians, enclosed.
fn from_alpha(
    r: &mut Report,
    text: &str,
    kappa: &Rational,
) -> Result<ArcApprox<Interval>, CliError> {
    let alpha = crate::cli::args::number("--alpha", text)?;
    r.input("alpha", q(&alpha));
    let (s, c) = sin_cos_enclosure(interval_from_rational(&alpha));
    r.interval("sin_alpha", "sin α", &s);
    r.interval("cos_alpha", "cos α", &c);
    ArcApprox::new(c, s, interval_from_rational(kappa)).map_err(|e| arc_error(e, "--alpha"))
}

/// `--cos --sin`: an exact unit vector.
fn from_unit(
    r: &mut Report,
    c: &Rational,
    s: &Rational,
    kappa: &Rational,
) -> Result<ArcApprox<Rational>, CliError> {
    r.input("cos", q(c));
    r.input("sin", q(s));
    let n2 = c * c + s * s;
    if n2 != frac(1, 1) {
        let why = format!("(cos α, sin α) = ({}, {}) is not a unit vector: cos² + sin² = {} (give e.g. --cos 3/5 --sin 4/5, or --alpha)", q(c), q(s), q(&n2));
        return Err(bad("--cos/--sin", why));
    }
    ArcApprox::new(c.clone(), s.clone(), kappa.clone()).map_err(|e| arc_error(e, "--cos/--sin"))
}

fn enclose(arc: &ArcApprox<Rational>) -> ArcApprox<Interval> {
    ArcApprox {
        cos_a: interval_from_rational(&arc.cos_a),
        sin_a: interval_from_rational(&arc.sin_a),
        kappa: interval_from_rational(&arc.kappa),
    }
}

fn case_word(c: Option<Prop61Case>) -> (Value, &'static str) {
    match c {
        Some(Prop61Case::S1) => (json!("s1"), "dH = |‖ca(s1)‖ - 1|"),
        Some(Prop61Case::Both) => (json!("both"), "dH = max(|‖ca(s1)‖ - 1|, |‖ca(s2)‖ - 1|)"),
        Some(Prop61Case::S2) => (json!("s2"), "dH = |‖ca(s2)‖ - 1|"),
        None => (Value::Null, "undecided"),
    }
}

/// `000:6.1 (--alpha A | --cos C --sin S) --kappa K`.
pub fn prop_6_1(a: &PropArgs, id: &'static str) -> Result<Report, CliError> {
    a.only(id, USAGE, &["--alpha", "--cos", "--sin", "--kappa"])?;
    let mut r = Report::new(
        id,
        "Prop 6.1 (seed 000): Hausdorff distance of the cubic LN approximation of a circular arc",
    );
    let kappa = required_number("--kappa", &a.kappa, USAGE)?;
    let (cos, sin) = (
        optional_number("--cos", &a.cos)?,
        optional_number("--sin", &a.sin)?,
    );
    let (arc, case) = match (&a.alpha, cos, sin) {
        (Some(t), None, None) => {
            let arc = from_alpha(&mut r, t, &kappa)?;
            let case = arc.prop_6_1_case();
            (arc, case)
        }
        (None, Some(c), Some(s)) => {
            let exact = from_unit(&mut r, &c, &s, &kappa)?;
            abc_exact(&mut r, &exact);
            (enclose(&exact), exact.prop_6_1_case())
        }
        (Some(_), _, _) => {
            return Err(bad(
                "--alpha",
                "give either --alpha or --cos and --sin, not both",
            ))
        }
        _ => {
            return Err(bad(
                "--cos/--sin",
                format!("give --alpha, or both --cos and --sin; usage: {USAGE}"),
            ))
        }
    };
    r.input("kappa", q(&kappa));
    intervals(&mut r, &arc);
    let (key, text) = case_word(case);
    r.value("case", key, format!("case (printed κ-ranges): {text}"));
    compare(&mut r, &arc, &kappa);
    Ok(r)
}

/// Exact `A, B, C` of eq. (10) for an exact unit vector.
fn abc_exact(r: &mut Report, arc: &ArcApprox<Rational>) {
    let (a, b, c) = arc.abc();
    r.value(
        "abc_exact",
        json!({"A": q(&a), "B": q(&b), "C": q(&c)}),
        format!("A = {}, B = {}, C = {} (exact)", q(&a), q(&b), q(&c)),
    );
}

/// `A, B, C, s1, s2` as certified intervals, and whether `s1, s2 ∈ (0, 1)`.
fn intervals(r: &mut Report, arc: &ArcApprox<Interval>) {
    let (a, b, c) = arc.abc();
    r.interval("A", "A = (κ-1)³ + 4κ(κ-1) sin²α", &a);
    r.interval("B", "B = 2(κ-1)² + κ(3-5κ) sin²α", &b);
    r.interval("C", "C = -(κ-1)² + κ² sin²α", &c);
    match arc.critical_params() {
        Some((s1, s2)) => {
            r.interval("s1", "s1 = (-B + √(B² - 4AC))/2A", &s1);
            r.interval("s2", "s2 = (-B - √(B² - 4AC))/2A", &s2);
        }
        None => r.value(
            "s1",
            Value::Null,
            "s1, s2: undefined (A may vanish or B² - 4AC may be negative)",
        ),
    }
    if let Some((i1, i2)) = arc.params_in_unit() {
        r.decision("s1_in_unit", "s1 ∈ (0, 1)", Some(i1), "yes", "no");
        r.decision("s2_in_unit", "s2 ∈ (0, 1)", Some(i2), "yes", "no");
    }
}

/// The closed form against the direct enclosure (only inside the hypothesis κ ∈ [1/2, 2]).
fn compare(r: &mut Report, arc: &ArcApprox<Interval>, kappa: &Rational) {
    let closed = arc.prop_6_1_distance();
    let direct = direct_max_error(arc);
    let show = |x: &Option<Interval>| x.as_ref().map_or("undecided".to_string(), show_interval);
    let js = |x: &Option<Interval>| x.as_ref().map_or(Value::Null, interval_to_json);
    r.line(format!(
        "closed-form distance (Prop 6.1) ∈ {}",
        show(&closed)
    ));
    r.line(format!(
        "direct: max over t ∈ [0,1] of |‖ca(t)‖ - 1| ∈ {}",
        show(&direct)
    ));
    let hypothesis = &frac::<Rational>(1, 2) <= kappa && kappa <= &frac::<Rational>(2, 1);
    if !hypothesis {
        r.value(
            "distance",
            js(&closed),
            "κ ∉ [1/2, 2]: outside Prop 6.1's hypothesis, no comparison",
        );
        r.value("direct_distance", js(&direct), "");
        return;
    }
    let agrees = closed
        .zip(direct)
        .map(|(c, d)| c.inf() <= d.sup() && d.inf() <= c.sup());
    r.compared(js(&closed), js(&direct), agrees);
}

/// A certified enclosure of `max_{t ∈ [0,1]} |‖ca(t)‖ - 1|`, or `None` if the
/// root enclosure of `(‖ca‖²)'` ran out of budget.
fn direct_max_error(arc: &ArcApprox<Interval>) -> Option<Interval> {
    let curve = arc.cubic().ok()?;
    let (x, y) = curve.power_coords();
    let norm2 = x.mul(&x).add(&y.mul(&y));
    let roots = enclose_roots(&norm2.derivative(), 0.0, 1.0, ROOT_WIDTH, MAX_BOXES);
    if roots.budget_exhausted {
        return None;
    }
    let (mut lo, mut hi) = (0.0f64, 0.0f64);
    for (a, b) in roots.candidates.into_iter().chain([(0.0, 0.0), (1.0, 1.0)]) {
        let t = Interval::try_from((a, b)).ok()?;
        let err = (ScalarSqrt::sqrt(&norm2.eval(&t))? - Interval::try_from((1.0, 1.0)).ok()?).abs();
        lo = lo.max(err.inf());
        hi = hi.max(err.sup());
    }
    Interval::try_from((lo, hi)).ok()
}
