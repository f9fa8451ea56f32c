//! Seed 003 propositions on user data: Hermite data `[x1, y1]`, end normal
//! `(u, 1)`, normal form `K(t) = [-f', -f + t f']` (singular where `f'' = 0`).
//!
//! Each verdict is compared with [`normal_form_regular`] (exact Sturm root
//! isolation of `f''` on `[0, u]`), which never looks at a proposition's formula.

use super::PropArgs;
use crate::cli::args::{
    coefficients, ln_error, ln_error_own_field, optional_number, q, required, required_number,
};
use crate::cli::report::Report;
use crate::cli::CliError;
use lncert::ln::direct::normal_form_regular;
use lncert::ln::hermite::{
    convolve_normal_forms, cubic_nonsingular_u_range, normal_form, A2Case, HermiteData,
};
use lncert::poly::Poly;
use lncert::scalar::{interval_from_rational, Interval, Rational, Scalar};
use serde_json::{json, Value};

const USAGE_2_1: &str = "prop 2.1 --x1 X --y1 Y [--u U]";
const USAGE_3_2: &str = "prop 3.2 --x1 X --y1 Y --u U [--a2 A]";
const USAGE_3_3: &str = "prop 3.3 --x1 X --y1 Y --u U --m M [--b B]";
const USAGE_6_1: &str = "prop 003:6.1 --f c0,c1,... --g c0,c1,...";
const USAGE_7_1: &str = "prop 7.1 --tau T [--frame b0x,b0y;bmx,bmy;b3x,b3y]";

/// Reads `--x1 --y1 --u` and validates them (`x1 ≠ 0`, `u > 0`).
fn hermite(a: &PropArgs, r: &mut Report, usage: &str) -> Result<HermiteData<Rational>, CliError> {
    let x1 = required_number("--x1", &a.x1, usage)?;
    let y1 = required_number("--y1", &a.y1, usage)?;
    let u = required_number("--u", &a.u, usage)?;
    let data = HermiteData::new(x1, y1, u).map_err(ln_error_own_field)?;
    r.input("x1", q(&data.x1));
    r.input("y1", q(&data.y1));
    r.input("u", q(&data.u));
    r.exact("s", "s = -y1/x1", &data.s());
    Ok(data)
}

/// The same data as certified intervals (for the irrational printed bounds).
fn enclosed(d: &HermiteData<Rational>) -> HermiteData<Interval> {
    HermiteData {
        x1: interval_from_rational(&d.x1),
        y1: interval_from_rational(&d.y1),
        u: interval_from_rational(&d.u),
    }
}

/// `003:2.1 --x1 X --y1 Y [--u U]`: the exact range `(3s/2, 3s)`, and for a
/// given `u` the Prop 2.1 verdict against the direct check.
pub fn prop_2_1(a: &PropArgs, id: &'static str) -> Result<Report, CliError> {
    a.only(id, USAGE_2_1, &["--x1", "--y1", "--u"])?;
    let mut r = Report::new(id, "Prop 2.1 (seed 003): the cubic Hermite interpolant is nonsingular on [0, u] iff 3s/2 < u < 3s");
    let x1 = required_number("--x1", &a.x1, USAGE_2_1)?;
    let y1 = required_number("--y1", &a.y1, USAGE_2_1)?;
    let range = cubic_nonsingular_u_range(&x1, &y1).map_err(|e| ln_error("--x1", e))?;
    r.input("x1", q(&x1));
    r.input("y1", q(&y1));
    r.exact("s", "s = -y1/x1", &(-y1.clone() / x1.clone()));
    let (lo, hi) = (q(&range.lo), q(&range.hi));
    r.value(
        "u_range",
        json!([lo, hi]),
        format!("nonsingular u-range (3s/2, 3s) = ({lo}, {hi})"),
    );
    if range.is_empty() == Some(true) {
        r.line("the range is empty (s <= 0): no u > 0 gives a nonsingular cubic");
    }
    if let Some(u) = optional_number("--u", &a.u)? {
        let data = HermiteData::new(x1, y1, u.clone()).map_err(ln_error_own_field)?;
        r.input("u", q(&u));
        cubic_details(&mut r, &data);
        let v = data.prop_2_1();
        r.verdict(
            "Prop 2.1: 3s/2 < u < 3s",
            v,
            "nonsingular on [0, u]",
            "singular on [0, u]",
        );
        let d = normal_form_regular(&data.cubic_f(), &u);
        r.direct(
            "f'' has no root on [0, u]",
            Some(d),
            "nonsingular on [0, u]",
            "singular on [0, u]",
            v,
        );
    }
    Ok(r)
}

/// `a2`, `a3` and the singular parameter `t*` of the cubic interpolant.
fn cubic_details(r: &mut Report, data: &HermiteData<Rational>) {
    let (a2, a3) = data.cubic_coefficients();
    r.exact("a2", "a2 = (-2u x1 - 3y1)/u²", &a2);
    r.exact("a3", "a3 = (u x1 + 2y1)/u³", &a3);
    match data.cubic_singular_parameter() {
        Some(t) => r.exact("t_star", "t* = -a2/(3a3) (where f'' = 0)", &t),
        None => r.value("t_star", Value::Null, "t*: none (a3 = 0, f'' is constant)"),
    }
}

fn case_name(c: A2Case) -> (&'static str, &'static str) {
    match c {
        A2Case::Alpha0Alpha1 => ("alpha0_alpha1", "a2 ∈ (α0, α1)"),
        A2Case::Alpha0Zero => ("alpha0_zero", "a2 ∈ (α0, 0)  [4s/3 <= u <= 2s]"),
        A2Case::Alpha0Alpha2 => ("alpha0_alpha2", "a2 ∈ (α0, α2)  [2s < u <= 4s]"),
        A2Case::Empty => ("empty", "no a2: u outside ((3-√3)s, (3+√3)s)"),
    }
}

/// Existence, case and the printed bounds `α0, α1` (certified intervals), `α2` (exact).
fn quartic_summary(r: &mut Report, data: &HermiteData<Rational>) {
    r.decision(
        "exists",
        "a nonsingular quartic exists ((3-√3)s < u < (3+√3)s)",
        data.prop_3_2_exists(),
        "yes",
        "no",
    );
    match data.prop_3_2_case() {
        Some(c) => {
            let (key, text) = case_name(c);
            r.value(
                "case",
                json!(key),
                format!("case (Prop 3.2 as printed): {text}"),
            );
        }
        None => r.value("case", Value::Null, "case: undecided"),
    }
    r.exact("D1", "D1 = -2(u² - 6us + 6s²)", &data.d1());
    match enclosed(data).alphas() {
        Some((a0, a1)) => {
            r.interval("alpha0", "α0 = (6s - 5u - √D1)/(2u²/x1)", &a0);
            r.interval("alpha1", "α1 = (6s - 5u + √D1)/(2u²/x1)", &a1);
        }
        None => {
            r.value(
                "alpha0",
                Value::Null,
                "α0: undefined (D1 < 0, or D1 not certified >= 0)",
            );
            r.value("alpha1", Value::Null, "α1: undefined");
        }
    }
    r.exact("alpha2", "α2 = (6s - 3u)/(u²/x1)", &data.alpha2());
}

/// `003:3.1` / `003:3.2 --x1 --y1 --u [--a2 A]`.
pub fn prop_3_2(a: &PropArgs, id: &'static str) -> Result<Report, CliError> {
    a.only(id, USAGE_3_2, &["--x1", "--y1", "--u", "--a2"])?;
    let mut r = Report::new(
        id,
        "Props 3.1/3.2 (seed 003): nonsingular quartic Hermite interpolants and their a2-interval",
    );
    let data = hermite(a, &mut r, USAGE_3_2)?;
    quartic_summary(&mut r, &data);
    if let Some(a2) = optional_number("--a2", &a.a2)? {
        r.input("a2", q(&a2));
        let v = data.prop_3_2_contains(&a2);
        quartic_check(
            &mut r,
            &data,
            &a2,
            v,
            "Prop 3.2 as printed: a2 in the printed interval",
        );
    }
    Ok(r)
}

/// The quartic with this `a2`: coefficients, the verdict `v`, the direct check.
fn quartic_check(
    r: &mut Report,
    data: &HermiteData<Rational>,
    a2: &Rational,
    v: Option<bool>,
    label: &str,
) {
    let (a3, a4) = data.quartic_coefficients(a2);
    r.exact("a3", "a3 = -(2a2u² + 3ux1 + 4y1)/u³", &a3);
    r.exact("a4", "a4 = (a2u² + 2ux1 + 3y1)/u⁴", &a4);
    r.verdict(label, v, "nonsingular on [0, u]", "singular on [0, u]");
    r.decision(
        "engine",
        "engine (Prop 3.2 corrected: intervals mirrored for x1 < 0)",
        data.nonsingular_a2_contains(a2),
        "nonsingular on [0, u]",
        "singular on [0, u]",
    );
    let d = normal_form_regular(&data.quartic_f(a2), &data.u);
    r.direct(
        "f'' has no root on [0, u]",
        Some(d),
        "nonsingular on [0, u]",
        "singular on [0, u]",
        v,
    );
}

/// `003:3.3 --x1 --y1 --u --m M [--b B]`.
pub fn prop_3_3(a: &PropArgs, id: &'static str) -> Result<Report, CliError> {
    a.only(id, USAGE_3_3, &["--x1", "--y1", "--u", "--m", "--b"])?;
    let mut r = Report::new(
        id,
        "Prop 3.3 (seed 003): nonsingular quartics tangent to the line m x + y + b = 0",
    );
    let data = hermite(a, &mut r, USAGE_3_3)?;
    let m = required_number("--m", &a.m, USAGE_3_3)?;
    if !(m > Rational::zero() && m < data.u) {
        return Err(crate::cli::args::bad(
            "--m",
            format!("m = {} must satisfy 0 < m < u = {}", q(&m), q(&data.u)),
        ));
    }
    r.input("m", q(&m));
    quartic_summary(&mut r, &data);
    r.exact("beta", "β = -(m(3s - 2u) + u(3u - 4s))", &data.beta(&m));
    beta_bounds(&mut r, &data, &m);
    if let Some(b) = optional_number("--b", &a.b)? {
        r.input("b", q(&b));
        let Some(a2) = data.a2_from_b(&m, &b) else {
            return Err(crate::cli::args::bad(
                "--m",
                "0 < m < u is required to solve for a2",
            ));
        };
        r.exact("a2", "a2 (the quartic tangent to the line at t = m)", &a2);
        let v = data.prop_3_3_contains(&m, &b);
        quartic_check(
            &mut r,
            &data,
            &a2,
            v,
            "Prop 3.3 as printed: b in the printed interval",
        );
    }
    Ok(r)
}

/// The printed bounds `β0, β1` (intervals), `β2`, `β3` (exact) of eq. (5).
fn beta_bounds(r: &mut Report, data: &HermiteData<Rational>, m: &Rational) {
    let di = enclosed(data);
    let mi = interval_from_rational(m);
    match di.alphas() {
        Some((a0, a1)) => {
            let b0 = di.beta_i(&mi, &a0);
            let b1 = di.beta_i(&mi, &a1);
            for (key, label, v) in [("beta0", "β0", b0), ("beta1", "β1", b1)] {
                match v {
                    Some(x) => r.interval(key, label, &x),
                    None => r.value(key, Value::Null, format!("{label}: undefined")),
                }
            }
        }
        None => r.value("beta0", Value::Null, "β0, β1: undefined (D1 < 0)"),
    }
    if let Some(b2) = data.beta_i(m, &data.alpha2()) {
        r.exact("beta2", "β2 (from α2)", &b2);
    }
    if let Some(b3) = data.beta_i(m, &Rational::zero()) {
        r.exact("beta3", "β3 = m³β/(u⁴/x1)", &b3);
    }
}

/// `003:6.1 --f c0,c1,... --g c0,c1,...`: the convolution `K_f + K_g = K_{f+g}`.
pub fn prop_6_1(a: &PropArgs, id: &'static str) -> Result<Report, CliError> {
    a.only(id, USAGE_6_1, &["--f", "--g"])?;
    let mut r = Report::new(
        id,
        "Prop 6.1 (seed 003): curves with a common Gauss map convolve to K_{f+g}",
    );
    let f = coefficients("--f", required("--f", &a.f, USAGE_6_1)?)?;
    let g = coefficients("--g", required("--g", &a.g, USAGE_6_1)?)?;
    r.input_json("f", coeffs_json(&f));
    r.input_json("g", coeffs_json(&g));
    let (x, y) = convolve_normal_forms(&f, &g);
    r.value(
        "f_plus_g",
        coeffs_json(&f.add(&g)),
        format!("f + g = {}", show_coeffs(&f.add(&g))),
    );
    r.value(
        "x",
        coeffs_json(&x),
        format!("x(t) = -(f+g)'  coefficients {}", show_coeffs(&x)),
    );
    r.value(
        "y",
        coeffs_json(&y),
        format!("y(t) = -(f+g) + t(f+g)'  coefficients {}", show_coeffs(&y)),
    );
    r.line("(power basis in t, coefficients of 1, t, t², ...)");
    let ((xf, yf), (xg, yg)) = (normal_form(&f), normal_form(&g));
    let same = x
        .sub(&xf.add(&xg))
        .is_zero()
        .zip(y.sub(&yf.add(&yg)).is_zero())
        .map(|(a, b)| a && b);
    r.verdict(
        "Prop 6.1: K_f + K_g = K_{f+g}",
        Some(true),
        "equal",
        "different",
    );
    r.direct(
        "K_f + K_g computed pointwise",
        same,
        "equal to K_{f+g}",
        "different from K_{f+g}",
        Some(true),
    );
    Ok(r)
}

fn coeffs_json(p: &Poly<Rational>) -> Value {
    json!(p.coeffs().iter().map(q).collect::<Vec<_>>())
}

fn show_coeffs(p: &Poly<Rational>) -> String {
    format!(
        "[{}]",
        p.coeffs().iter().map(q).collect::<Vec<_>>().join(", ")
    )
}

/// `003:7.1 --tau T [--frame F]`: the recommended range and the regularity of
/// the construction on a frame (default `b0 = (0,0), bm = (1,1), b3 = (2,0)`).
pub fn prop_7_1(a: &PropArgs, id: &'static str) -> Result<Report, CliError> {
    a.only(id, USAGE_7_1, &["--tau", "--frame"])?;
    let mut r = Report::new(id, "Prop 7.1 (seed 003): the cubic [P0, Q0, Q2, P2] is singular on [0,1] iff τ ∈ [0,1]; recommended τ ∈ (-∞,-1) ∪ (1,∞)");
    let tau = crate::cli::args::tau("--tau", required("--tau", &a.tau, USAGE_7_1)?)?;
    let frame_text = a.frame.as_deref().unwrap_or("0,0;1,1;2,0");
    let frame = crate::cli::args::frame("--frame", frame_text)?;
    let recommended = match &tau {
        lncert::ln::cubic::Tau::Finite(t) => lncert::ln::hermite::prop_7_1_recommended(t),
        lncert::ln::cubic::Tau::Infinite => Some(true),
    };
    r.decision(
        "recommended",
        "τ in the recommended range (-∞,-1) ∪ (1,∞) (τ = ∞ included)",
        recommended,
        "yes",
        "no",
    );
    let regular = super::seed000::tau_construction(&mut r, &frame, &tau, "Prop 7.1")?;
    if recommended == Some(true) && !regular {
        r.line("ERRATUM: a recommended τ gives a singular curve");
        r.set_agrees(Some(false));
    }
    Ok(r)
}
