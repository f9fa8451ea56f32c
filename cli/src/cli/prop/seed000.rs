//! Seed 000 propositions on cubic LN frames `b0, bm, b3` (Prop 3.1, Lemma 4.1,
//! Prop 4.2, Remark 4.3, Prop 4.4).
//!
//! All data are exact rationals: the control points depend only on `τ` or
//! `ρ = κ/λ`, and `q = λr/λl` is rational, so every verdict is exact. Each is
//! compared with [`is_regular_on`] / [`singular_points`] (exact root isolation
//! of the hodograph), which look at the curve itself.

use super::PropArgs;
use crate::cli::args::{
    bad, frame, ln_error, optional_number, point_json, q, required, required_number, show_frame,
    show_point, show_tau,
};
use crate::cli::report::Report;
use crate::cli::CliError;
use lncert::curve::Bezier;
use lncert::ln::cubic::{
    deltas_from_rho, deltas_from_tau, lemma_4_1_regular, prop_3_1_regular, tau_from_rho, LnFrame,
    Tau,
};
use lncert::ln::direct::{is_regular_on, singular_points};
use lncert::ln::pair::{
    convolution_has_interior_cusp, cusp_parameter, prop_4_4_as_printed, CompatiblePair, LnPair,
};
use lncert::ln::OpenRange;
use lncert::poly::Span;
use lncert::scalar::{frac, Rational};
use serde_json::{json, Value};

const USAGE_3_1: &str = "prop 000:3.1 --frame b0x,b0y;bmx,bmy;b3x,b3y --tau T";
const USAGE_4_1: &str = "prop 4.1 --frame b0x,b0y;bmx,bmy;b3x,b3y --rho R";
const USAGE_PAIR: &str =
    "prop 4.2|4.3|4.4 --left b0x,b0y;bmx,bmy;b3x,b3y --right b0x,b0y;bmx,bmy;b3x,b3y [--rho R]";

/// Records a curve's exact control points.
fn control_points(r: &mut Report, key: &str, label: &str, c: &Bezier<Rational>) {
    let json: Vec<Value> = c.points().iter().map(point_json).collect();
    let text: Vec<String> = c.points().iter().map(show_point).collect();
    r.value(key, json!(json), format!("{label}: {}", text.join(" ")));
}

/// The eq. (1) cubic on `frame` with cusp parameter `τ`: δ's, control points,
/// Prop 3.1 verdict and the direct check. Returns the direct answer.
pub fn tau_construction(
    r: &mut Report,
    frame: &LnFrame<Rational>,
    tau: &Tau<Rational>,
    prop: &str,
) -> Result<bool, CliError> {
    r.input("frame", show_frame(frame));
    r.input("tau", show_tau(tau));
    let (d0, d1) = deltas_from_tau(tau).map_err(|e| ln_error("--tau", e))?;
    r.exact("delta0", "δ0 = 2τ/(3τ-1)", &d0);
    r.exact("delta1", "δ1 = 2(τ-1)/(3τ-2)", &d1);
    let curve = frame.cubic(&d0, &d1);
    control_points(r, "control_points", "control points", &curve);
    let v = prop_3_1_regular(tau);
    r.verdict(
        &format!("{prop}: regular on [0,1] iff τ ∉ [0,1]"),
        v,
        "regular on [0, 1]",
        "singular on [0, 1]",
    );
    let d = direct_regularity(r, &curve, v);
    Ok(d)
}

/// `000:3.1 --frame F --tau T` (`T` may be `inf`).
pub fn prop_3_1(a: &PropArgs, id: &'static str) -> Result<Report, CliError> {
    a.only(id, USAGE_3_1, &["--frame", "--tau"])?;
    let mut r = Report::new(
        id,
        "Prop 3.1 (seed 000): the cubic of eq. (1) is a regular LN curve on [0,1] iff τ ∉ [0,1]",
    );
    let f = frame("--frame", required("--frame", &a.frame, USAGE_3_1)?)?;
    let tau = crate::cli::args::tau("--tau", required("--tau", &a.tau, USAGE_3_1)?)?;
    tau_construction(&mut r, &f, &tau, "Prop 3.1")?;
    Ok(r)
}

/// `000:4.1 --frame F --rho R` with `R = κ/λ`.
pub fn lemma_4_1(a: &PropArgs, id: &'static str) -> Result<Report, CliError> {
    a.only(id, USAGE_4_1, &["--frame", "--rho"])?;
    let mut r = Report::new(id, "Lemma 4.1 (seed 000): the LN cubic with normal map N0(1-t) + κN1 t is regular iff κ/λ ∈ (1/2, 2)");
    let f = frame("--frame", required("--frame", &a.frame, USAGE_4_1)?)?;
    let rho = required_number("--rho", &a.rho, USAGE_4_1)?;
    r.input("frame", show_frame(&f));
    r.input("rho", q(&rho));
    r.exact(
        "lambda2",
        "λ² = |b3 - bm|²/|bm - b0|²",
        &f.lambda2().expect("exact: ∇b0 ≠ 0 in a valid frame"),
    );
    let (d0, d1) = deltas_from_rho(&rho).map_err(|e| ln_error("--rho", e))?;
    r.exact("delta0", "δ0 = 2/3 (2 - 1/ρ)", &d0);
    r.exact("delta1", "δ1 = 2/3 (2 - ρ)", &d1);
    match tau_from_rho(&rho) {
        Some(t) => r.value(
            "tau",
            json!(show_tau(&t)),
            format!("cusp parameter τ = (2ρ-1)/(3(ρ-1)) = {}", show_tau(&t)),
        ),
        None => r.value("tau", Value::Null, "cusp parameter τ: undecided"),
    }
    let curve = f.cubic(&d0, &d1);
    control_points(&mut r, "control_points", "control points", &curve);
    let v = lemma_4_1_regular(&rho);
    r.verdict(
        "Lemma 4.1: 1/2 < ρ < 2",
        v,
        "regular on [0, 1]",
        "singular on [0, 1]",
    );
    direct_regularity(&mut r, &curve, v);
    Ok(r)
}

/// Reads `--left`, `--right` and checks compatibility; records `c0, c1, q`.
fn pair(a: &PropArgs, r: &mut Report) -> Result<CompatiblePair<Rational>, CliError> {
    let left = frame("--left", required("--left", &a.left, USAGE_PAIR)?)?;
    let right = frame("--right", required("--right", &a.right, USAGE_PAIR)?)?;
    r.input("left", show_frame(&left));
    r.input("right", show_frame(&right));
    let p = CompatiblePair::new(left, right).map_err(|e| ln_error("--right", e))?;
    r.exact("c0", "c0 (∇b0ʳ = c0 ∇b0ˡ)", &p.c0);
    r.exact("c1", "c1 (∇b1ʳ = c1 ∇b1ˡ)", &p.c1);
    r.exact(
        "lambda_l2",
        "λl²",
        &p.left.lambda2().expect("exact: ∇b0 ≠ 0 in a valid frame"),
    );
    r.exact(
        "lambda_r2",
        "λr²",
        &p.right.lambda2().expect("exact: ∇b0 ≠ 0 in a valid frame"),
    );
    r.exact("q", "q = λr/λl = c1/c0", &p.ratio());
    r.decision(
        "prop_4_2",
        "Prop 4.2: 1/4 < q < 4 (one linear normal map, both regular)",
        p.prop_4_2(),
        "yes",
        "no",
    );
    r.decision(
        "remark_4_3",
        "Remark 4.3: 1/4 <= q <= 4 (extended linear normal map)",
        p.remark_4_3(),
        "yes",
        "no",
    );
    Ok(p)
}

/// The admissible `κ/λl`: `(1/2, 2) ∩ (q/2, 2q)`, closed for Remark 4.3.
/// Returns the range and whether it is nonempty.
fn admissible(p: &CompatiblePair<Rational>, closed: bool) -> (OpenRange<Rational>, bool) {
    let qv = p.ratio();
    let lo = std::cmp::max(frac(1, 2), &qv * frac::<Rational>(1, 2));
    let hi = std::cmp::min(frac(2, 1), &qv * frac::<Rational>(2, 1));
    let nonempty = if closed { lo <= hi } else { lo < hi };
    (OpenRange { lo, hi }, nonempty)
}

fn in_range(range: &OpenRange<Rational>, x: &Rational, closed: bool) -> bool {
    if closed {
        &range.lo <= x && x <= &range.hi
    } else {
        &range.lo < x && x < &range.hi
    }
}

/// Records the admissible interval and picks `ρl`: the given `--rho`, else its midpoint.
fn choose_rho(
    a: &PropArgs,
    r: &mut Report,
    range: &OpenRange<Rational>,
    nonempty: bool,
    closed: bool,
) -> Result<Option<Rational>, CliError> {
    let (open, close) = if closed { ("[", "]") } else { ("(", ")") };
    let text = if nonempty {
        format!("{open}{}, {}{close}", q(&range.lo), q(&range.hi))
    } else {
        "empty".to_string()
    };
    let json = if nonempty {
        json!([q(&range.lo), q(&range.hi)])
    } else {
        Value::Null
    };
    r.value(
        "admissible_rho_left",
        json,
        format!("admissible κ/λl: {text}"),
    );
    if let Some(rho) = optional_number("--rho", &a.rho)? {
        r.input("rho", q(&rho));
        return Ok(Some(rho));
    }
    Ok(nonempty.then(|| (&range.lo + &range.hi) * frac::<Rational>(1, 2)))
}

/// δ's and control points of both curves of a pair.
fn show_pair(r: &mut Report, ln: &LnPair<Rational>) {
    r.exact("rho_left", "ρl = κ/λl", &ln.rho_left);
    r.exact("rho_right", "ρr = κ/λr = ρl/q", &ln.rho_right);
    let d = |x: &(Rational, Rational)| json!([q(&x.0), q(&x.1)]);
    r.value(
        "deltas_left",
        d(&ln.deltas_left),
        format!(
            "[δ0, δ1] left = [{}, {}]",
            q(&ln.deltas_left.0),
            q(&ln.deltas_left.1)
        ),
    );
    r.value(
        "deltas_right",
        d(&ln.deltas_right),
        format!(
            "[δ0, δ1] right = [{}, {}]",
            q(&ln.deltas_right.0),
            q(&ln.deltas_right.1)
        ),
    );
    control_points(r, "left_control_points", "bl", &ln.left);
    control_points(r, "right_control_points", "br", &ln.right);
}

/// `000:4.2` / `000:4.3 --left F --right F [--rho R]`.
pub fn prop_4_2(a: &PropArgs, id: &'static str) -> Result<Report, CliError> {
    a.only(id, USAGE_PAIR, &["--left", "--right", "--rho"])?;
    let extended = id == "000:4.3";
    let title = if extended {
        "Remark 4.3 (seed 000): one extended linear normal map (cusps only at end points) iff 1/4 <= λr/λl <= 4"
    } else {
        "Prop 4.2 (seed 000): one linear normal map with both curves regular iff 1/4 < λr/λl < 4"
    };
    let mut r = Report::new(id, title);
    let p = pair(a, &mut r)?;
    let (range, nonempty) = admissible(&p, extended);
    let Some(rho) = choose_rho(a, &mut r, &range, nonempty, extended)? else {
        let v = if extended {
            p.remark_4_3()
        } else {
            p.prop_4_2()
        };
        r.verdict(
            if extended { "Remark 4.3" } else { "Prop 4.2" },
            v,
            "a pair exists",
            "no pair exists",
        );
        return Ok(r);
    };
    let ln = p.curves_for_rho(&rho).map_err(|e| ln_error("--rho", e))?;
    show_pair(&mut r, &ln);
    let span = if extended {
        Span::unit_open()
    } else {
        Span::unit_closed()
    };
    let [yes, no, both, not_both] = if extended {
        [
            "no singular point in (0, 1)",
            "singular inside (0, 1)",
            "both free of singular points in (0, 1)",
            "a singular point inside (0, 1)",
        ]
    } else {
        [
            "regular on [0, 1]",
            "singular on [0, 1]",
            "both regular on [0, 1]",
            "not both regular on [0, 1]",
        ]
    };
    let (dl, dr) = (
        is_regular_on(&ln.left, &span),
        is_regular_on(&ln.right, &span),
    );
    r.decision("left_regular", "bl", Some(dl), yes, no);
    r.decision("right_regular", "br", Some(dr), yes, no);
    let v = Some(in_range(&range, &rho, extended));
    r.verdict("κ/λl in the admissible interval", v, both, not_both);
    r.direct("hodographs of bl and br", Some(dl && dr), both, not_both, v);
    Ok(r)
}

/// `000:4.4 --left F --right F [--rho R]`: the convolution `bl + br` and its cusp.
pub fn prop_4_4(a: &PropArgs, id: &'static str) -> Result<Report, CliError> {
    a.only(id, USAGE_PAIR, &["--left", "--right", "--rho"])?;
    let mut r = Report::new(
        id,
        "Prop 4.4 (seed 000): the convolution has a cusp in (0,1) iff δ0 ∉ (0,1) or δ1 ∉ (0,1)",
    );
    let p = pair(a, &mut r)?;
    let (range, nonempty) = admissible(&p, false);
    let rho = choose_rho(a, &mut r, &range, nonempty, false)?.ok_or_else(|| {
        bad(
            "--rho",
            "required: q = λr/λl is outside (1/4, 4), so there is no admissible κ to default to",
        )
    })?;
    if !in_range(&range, &rho, false) {
        r.line("note: κ/λl is outside the admissible interval, so bl or br is singular (Prop 4.2)");
    }
    let ln = p.curves_for_rho(&rho).map_err(|e| ln_error("--rho", e))?;
    show_pair(&mut r, &ln);
    let conv = p.convolution(&ln).map_err(|e| ln_error("--right", e))?;
    let (d0, d1) = &conv.deltas;
    r.value(
        "deltas",
        json!([q(d0), q(d1)]),
        format!("convolution [δ0, δ1] = [{}, {}]", q(d0), q(d1)),
    );
    control_points(&mut r, "control_points", "bl + br", &conv.curve);
    match cusp_parameter(&conv.deltas) {
        Some(t) => r.value(
            "tau",
            json!(show_tau(&t)),
            format!("cusp parameter τ = δ0/(3δ0 - 2) = {}", show_tau(&t)),
        ),
        None => r.value("tau", Value::Null, "cusp parameter τ: undecided"),
    }
    let printed = prop_4_4_as_printed(&conv.deltas);
    let engine = convolution_has_interior_cusp(&conv.deltas);
    r.decision(
        "engine",
        "engine (corrected Prop 4.4: δ0 ∉ [0,1] or δ1 ∉ [0,1])",
        engine,
        "interior cusp",
        "no interior cusp",
    );
    r.verdict(
        "Prop 4.4 as printed",
        printed,
        "interior cusp",
        "no interior cusp",
    );
    let direct = interior_singularities(&mut r, &conv.curve);
    r.direct(
        "singular points of bl + br in (0, 1)",
        Some(direct),
        "interior cusp",
        "no interior cusp",
        printed,
    );
    if engine != Some(direct) {
        r.line("the engine's corrected Prop 4.4 disagrees with the direct check");
        r.set_agrees(Some(false));
    }
    Ok(r)
}

/// Exact isolation of the singular points in `(0, 1)`; records them, returns whether any exist.
fn interior_singularities(r: &mut Report, c: &Bezier<Rational>) -> bool {
    match singular_points(c, &Span::unit_open()) {
        None => {
            r.value(
                "singular_points",
                json!("all"),
                "singular points in (0, 1): every point (hodograph is zero)",
            );
            true
        }
        Some(roots) => {
            let show = |lo: &Rational, hi: &Rational| {
                if lo == hi {
                    q(lo)
                } else {
                    format!("[{}, {}]", q(lo), q(hi))
                }
            };
            let text: Vec<String> = roots.iter().map(|x| show(&x.lo, &x.hi)).collect();
            let json: Vec<Value> = roots.iter().map(|x| json!([q(&x.lo), q(&x.hi)])).collect();
            let shown = if text.is_empty() {
                "none".to_string()
            } else {
                text.join(", ")
            };
            r.value(
                "singular_points",
                json!(json),
                format!("singular points in (0, 1): {shown}"),
            );
            !roots.is_empty()
        }
    }
}

/// The direct check of regularity on [0, 1] (Sturm root isolation of the
/// hodograph), reported against the proposition's verdict `v`.
fn direct_regularity(
    r: &mut Report,
    curve: &lncert::curve::Bezier<Rational>,
    v: Option<bool>,
) -> bool {
    let d = is_regular_on(curve, &Span::unit_closed());
    r.direct(
        "hodograph has no zero on [0, 1]",
        Some(d),
        "regular on [0, 1]",
        "singular on [0, 1]",
        v,
    );
    d
}
