//! Seed 003: Prop 2.1's example, the §6 convolution example (recomputed
//! exactly in Q(√3) from the printed end points and normals), Prop 7.1's range.

use super::seed000::{judge, show};
use super::{data, Claim, ClaimGroup, Verdict};
use lncert::curve::V2;
use lncert::ln::cubic::{deltas_from_tau, LnFrame, Tau};
use lncert::ln::direct::{is_regular_on, normal_form_regular};
use lncert::ln::hermite::{
    cubic_nonsingular_u_range, normal_form, prop_7_1_recommended, HermiteData,
};
use lncert::poly::{Poly, Span};
use lncert::scalar::{frac, Rational, Scalar, Sign, Surd};
use serde_json::Value;

type R<T> = Result<T, String>;

fn num(v: &Value) -> R<Rational> {
    super::json_rational(v)
}
fn printed_digits(v: &Value) -> String {
    // serde_json prints the shortest round-trip form, which is the printed text.
    v.to_string()
}
fn s(r: Rational) -> Surd {
    Surd::rational(r)
}

fn prop_2_1_example(out: &mut Vec<Claim>) -> R<()> {
    let text: Value = serde_json::from_str(data::TEXT).map_err(|e| e.to_string())?;
    let ex = &text["seed003"]["prop21_example"];
    let (x1, y1) = (num(&ex["x1"])?, num(&ex["y1"])?);
    let (lo, hi) = (num(&ex["range"][0])?, num(&ex["range"][1])?);
    let r = cubic_nonsingular_u_range(&x1, &y1).map_err(|e| e.to_string())?;
    // Direct check at the ends (singular) and inside (nonsingular), by Sturm on f''.
    let direct = |u: &Rational| -> R<bool> {
        let h = HermiteData::new(x1.clone(), y1.clone(), u.clone()).map_err(|e| e.to_string())?;
        Ok(normal_form_regular(&h.cubic_f(), u))
    };
    let mid = (lo.clone() + hi.clone()) * frac::<Rational>(1, 2);
    let ok = r.lo == lo && r.hi == hi && !direct(&lo)? && !direct(&hi)? && direct(&mid)?;
    out.push(Claim::new(
        "003-prop2.1-example",
        "seed 003 Prop 2.1",
        format!("for x1 = {x1}, y1 = {y1} the cubic interpolant is nonsingular exactly for u in ({lo}, {hi})"),
        if ok { Verdict::Certified } else { Verdict::Refuted },
        format!("engine: ({}, {}); direct (Sturm on f''): singular at u = {lo} and u = {hi}, nonsingular at u = {mid}", r.lo, r.hi),
    ));
    Ok(())
}

/// The rotation by θ = π/3 of the §6 example: cos θ and sin θ, exact in Q(√3).
struct Rot {
    c: Surd,
    sn: Surd,
}

impl Rot {
    /// `R(sign θ) v`.
    fn rot(&self, v: &V2<Surd>, sign: i64) -> V2<Surd> {
        let c = &self.c;
        let sn = self.sn.scale(sign);
        V2::new(
            c.clone() * v.x.clone() - sn.clone() * v.y.clone(),
            sn * v.x.clone() + c.clone() * v.y.clone(),
        )
    }
}

/// The §6 example: two cubic LN curves in normal form rotated by θ = π/3.
fn sec6(out: &mut Vec<Claim>) -> R<()> {
    let d: Value = serde_json::from_str(data::SEC6).map_err(|e| e.to_string())?;
    // θ = π/3: cos θ = 1/2, sin θ = √3/2 (exact in Q(√3)).
    let r3 = Surd::sqrt_of(&frac(3, 1)).ok_or("√3")?;
    let (c, sn) = (s(frac(1, 2)), r3.clone() * s(frac(1, 2)));
    let th = Rot { c, sn };
    let u = sec6_normals(out, &th, &r3)?;
    let (fs, start_sum) = sec6_coefficients(out, &d, &th, &u)?;
    sec6_convolution(out, &d, &th, &fs, &start_sum)?;
    sec6_common_gauss_map(out, &fs);
    Ok(())
}

/// The source of the §6 claims.
const SEC6: &str = "seed 003 §6";

/// The start and end normals; returns `u`, the end normal's parameter.
fn sec6_normals(out: &mut Vec<Claim>, th: &Rot, r3: &Surd) -> R<Surd> {
    let (src, c, sn) = (SEC6, &th.c, &th.sn);
    let rot = |v: &V2<Surd>, sign: i64| th.rot(v, sign);
    // Start normal (-tan θ, 1) ∥ R(θ)(0, 1).
    let n0 = V2::new(-(sn.div(c).ok_or("tan")?), Surd::one());
    let start_ok = n0
        .cross(&rot(&V2::new(Surd::zero(), Surd::one()), 1))
        .sign()
        == Sign::Zero;
    // End normal (-tan(π/12), 1), tan(π/12) = tan(π/3 - π/4) = (√3 - 1)/(1 + √3).
    let t12 = (r3.clone() - Surd::one())
        .div(&(r3.clone() + Surd::one()))
        .ok_or("tan")?;
    let local_n1 = rot(&V2::new(-t12, Surd::one()), -1);
    let u = local_n1.x.div(&local_n1.y).ok_or("u")?; // (u, 1) ∥ local normal
    out.push(Claim::new(
        "003-sec6-normals",
        src,
        "start normal (-tan(π/3), 1) is R(π/3)(0,1); the end normal (-tan(π/12), 1) gives the parameter interval [0, 1]",
        if start_ok && u.exact_eq(&Surd::one()) == Some(true) { Verdict::Certified } else { Verdict::Refuted },
        format!("engine: u = {}", show(&u)),
    ));
    Ok(u)
}

/// Exact f and F from the printed end points (Prop 2.1's system (1)) against
/// their printed coefficients; returns f, F and the sum of the start points.
fn sec6_coefficients(
    out: &mut Vec<Claim>,
    d: &Value,
    th: &Rot,
    u: &Surd,
) -> R<(Vec<Poly<Surd>>, V2<Surd>)> {
    let src = SEC6;
    let rot = |v: &V2<Surd>, sign: i64| th.rot(v, sign);
    let mut fs: Vec<Poly<Surd>> = Vec::new();
    let mut start_sum = V2::new(Surd::zero(), Surd::zero());
    for (key, coef_key, name) in [("c1", "f", "f"), ("c2", "F", "F")] {
        let cd = &d[key];
        let p0 = V2::new(s(num(&cd["start"][0])?), s(num(&cd["start"][1])?));
        let p1 = V2::new(
            s(num(&cd["end_printed"][0])?),
            s(num(&cd["end_printed"][1])?),
        );
        start_sum = start_sum.add(&p0);
        let local = rot(&p1.sub(&p0), -1);
        let h = HermiteData::new(local.x, local.y, u.clone()).map_err(|e| e.to_string())?;
        let (a2, a3) = h.cubic_coefficients();
        for (i, (exact, k)) in [(&a2, "t2"), (&a3, "t3")].into_iter().enumerate() {
            let p = printed_digits(&cd[coef_key][k]);
            let (v, det) = judge(&p, exact);
            out.push(Claim::new(
                &format!("003-sec6-{name}-t{}", i + 2),
                src,
                format!("{name}(t) has t^{} coefficient {p}", i + 2),
                v,
                format!("recomputed from the printed end points and normals (system (1)); {det}"),
            ));
        }
        fs.push(h.cubic_f());
    }
    Ok((fs, start_sum))
}

/// The convolution c1 + c2 = R(θ) K_{f+F} + (start1 + start2), exact, against
/// its printed coefficients.
fn sec6_convolution(
    out: &mut Vec<Claim>,
    d: &Value,
    th: &Rot,
    fs: &[Poly<Surd>],
    start_sum: &V2<Surd>,
) -> R<()> {
    let (src, c, sn) = (SEC6, &th.c, &th.sn);
    let conv = |g: &Poly<Surd>| -> (Poly<Surd>, Poly<Surd>) {
        let (kx, ky) = normal_form(g);
        let x = kx
            .scale(c)
            .sub(&ky.scale(sn))
            .add(&Poly::constant(start_sum.x.clone()));
        let y = kx
            .scale(sn)
            .add(&ky.scale(c))
            .add(&Poly::constant(start_sum.y.clone()));
        (x, y)
    };
    let (cx, cy) = conv(&fs[0].add(&fs[1]));
    // The same from the printed (rounded) f and F, to explain last-digit differences.
    let printed_f = |k: &str| -> R<Poly<Surd>> {
        Ok(Poly::new(vec![
            Surd::zero(),
            Surd::zero(),
            s(num(&d[if k == "f" { "c1" } else { "c2" }][k]["t2"])?),
            s(num(&d[if k == "f" { "c1" } else { "c2" }][k]["t3"])?),
        ]))
    };
    let (rx, ry) = conv(&printed_f("f")?.add(&printed_f("F")?));
    for (axis, exact, from_rounded, key) in [("x", &cx, &rx, "x"), ("y", &cy, &ry, "y")] {
        for i in 0..4 {
            let pv = &d["convolution_printed"][key][i];
            let p = printed_digits(pv);
            let e = exact.coeffs().get(i).cloned().unwrap_or_else(Surd::zero);
            let r = from_rounded
                .coeffs()
                .get(i)
                .cloned()
                .unwrap_or_else(Surd::zero);
            let (v, det) = judge(&p, &e);
            let (vr, _) = judge(&p, &r);
            let note = match (v, vr) {
                (Verdict::Erratum, Verdict::Certified) => " — but it does round the value computed from the ROUNDED f, F: the printed digit comes from rounded intermediate data",
                (Verdict::Erratum, _) => " — nor does it round the value from the printed (rounded) f, F",
                _ => "",
            };
            out.push(Claim::new(
                &format!("003-sec6-conv-{axis}{i}"),
                src,
                format!("(c1*c2)(t).{axis} has t^{i} coefficient {p}"),
                v,
                format!("{det}; from the printed f, F: {}{note}", show(&r)),
            ));
        }
    }
    Ok(())
}

/// Same normal at the same t: c1'(t) × c2'(t) ≡ 0, so the sum is the convolution.
fn sec6_common_gauss_map(out: &mut Vec<Claim>, fs: &[Poly<Surd>]) {
    let d1 = normal_form(&fs[0]);
    let d2 = normal_form(&fs[1]);
    let cross =
        d1.0.derivative()
            .mul(&d2.1.derivative())
            .sub(&d1.1.derivative().mul(&d2.0.derivative()));
    let parallel = cross.coeffs().iter().all(|x| x.sign() == Sign::Zero);
    out.push(Claim::new(
        "003-sec6-common-gauss-map",
        "seed 003 Prop 6.1",
        "c1 and c2 have the same normal at the same t, so c1 + c2 is their convolution, a polynomial curve",
        if parallel { Verdict::Certified } else { Verdict::Refuted },
        "c1'(t) × c2'(t) is the zero polynomial (exact, in Q(√3))",
    ));
}

/// Prop 7.1: the recommended τ-range versus the exact regular range.
fn prop_7_1(out: &mut Vec<Claim>) -> R<()> {
    let p = |x: i64, y: i64| V2::new(frac::<Rational>(x, 1), frac(y, 1));
    let f = LnFrame::new(p(0, 0), p(1, 1), p(2, 0)).map_err(|e| e.to_string())?;
    // Probe τ on a grid of [-2, 2] (excluding 1/3, 2/3 where δ is undefined):
    // which τ outside the recommended range still give a regular curve?
    let mut missed = Vec::new();
    let mut wrong = Vec::new();
    for k in -40..=40 {
        let tau: Rational = frac(k, 20);
        if tau == frac(1, 3) || tau == frac(2, 3) {
            continue;
        }
        let Ok((d0, d1)) = deltas_from_tau(&Tau::Finite(tau.clone())) else {
            continue;
        };
        let regular = is_regular_on(&f.cubic(&d0, &d1), &Span::unit_closed());
        let recommended = prop_7_1_recommended(&tau) == Some(true);
        let in01 = tau >= frac(0, 1) && tau <= frac(1, 1);
        if regular == in01 {
            wrong.push(tau.to_string());
        }
        if regular && !recommended {
            missed.push(tau.to_string());
        }
    }
    out.push(Claim::new(
        "003-prop7.1-iff",
        "seed 003 Prop 7.1",
        "the cubic LN curve has a singularity in [0,1] iff τ ∈ [0,1]",
        if wrong.is_empty() { Verdict::Certified } else { Verdict::Refuted },
        format!("direct check (Sturm on the hodograph) on τ = k/20, |τ| <= 2: counterexamples {wrong:?}"),
    ));
    out.push(Claim::new(
        "003-prop7.1-range",
        "seed 003 Prop 7.1",
        "choosing τ ∈ (-∞,-1) ∪ (1,+∞) we obtain (all) nonsingular cubic LN curves",
        if missed.is_empty() { Verdict::Certified } else { Verdict::Erratum },
        format!(
            "regular curves outside the recommended range: τ = {} — the exact range is seed 000's (-∞, 0) ∪ (1, ∞] (Prop 3.1)",
            missed.join(", ")
        ),
    ));
    Ok(())
}

pub(super) fn claims(out: &mut Vec<Claim>) {
    let parts: [(&str, ClaimGroup); 3] = [
        ("prop2.1", prop_2_1_example),
        ("sec6", sec6),
        ("prop7.1", prop_7_1),
    ];
    for (name, f) in parts {
        if let Err(e) = f(out) {
            out.push(Claim::new(
                &format!("003-{name}"),
                "seed 003",
                "built-in data",
                Verdict::Undecided,
                format!("error: {e}"),
            ));
        }
    }
}
