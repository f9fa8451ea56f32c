//! One check function per kernel family: run the kernel in the three
//! arithmetics on one generated case and record the comparison.

use super::KernelStats;
use lncert::curve::V2;
use lncert::gen::{ArcCase, FrameCase, HermiteCase, PairCase, TauCase};
use lncert::ln::circle::ArcApprox;
use lncert::ln::cubic::{deltas_from_rho, deltas_from_tau, prop_3_1_regular, LnFrame, Tau};
use lncert::ln::direct::{is_regular_on, normal_form_regular};
use lncert::ln::hermite::HermiteData;
use lncert::ln::pair::{convolution_deltas, pair_decision};
use lncert::ln::LnError;
use lncert::poly::Span;
use lncert::scalar::{rational_from_f64, Interval, IntervalExt, Rational, Scalar};

fn iv(x: f64) -> Interval {
    Interval::point(x).unwrap_or(Interval::ENTIRE)
}

/// Exact values of finite inputs; `None` (and the case is rejected) otherwise.
fn exact<const N: usize>(xs: [f64; N]) -> Option<[Rational; N]> {
    let v: Option<Vec<Rational>> = xs.iter().map(|x| rational_from_f64(*x)).collect();
    v?.try_into().ok()
}

/// Relative distance of `x` to the nearest of `bounds` (relative to the bound,
/// or absolute for a bound 0).
fn rel_dist(x: f64, bounds: &[f64]) -> f64 {
    bounds
        .iter()
        .map(|b| {
            if *b == 0.0 {
                x.abs()
            } else {
                ((x - b) / b).abs()
            }
        })
        .fold(f64::INFINITY, f64::min)
}

fn frame_from<S: Scalar>(c: &FrameCase, f: impl Fn(f64) -> S) -> (V2<S>, V2<S>, V2<S>) {
    let p = |a: [f64; 2]| V2::new(f(a[0]), f(a[1]));
    (p(c.b0), p(c.bm), p(c.b3))
}

fn frame_decision<S: Scalar>(r: &Result<LnFrame<S>, LnError>) -> Option<bool> {
    match r {
        Ok(_) => Some(true),
        Err(LnError::Collinear { .. }) => Some(false),
        Err(_) => None,
    }
}

/// Frames: the collinearity decision (sign of a cross product) and `λ²`.
pub fn check_frame(c: &FrameCase, st: &mut KernelStats) {
    let Some(_) = exact([c.b0[0], c.b0[1], c.bm[0], c.bm[1], c.b3[0], c.b3[1]]) else {
        st.rejected += 1;
        return;
    };
    let q = |x: f64| rational_from_f64(x).unwrap_or_default();
    let mk = |p: (V2<Rational>, V2<Rational>, V2<Rational>)| LnFrame::new(p.0, p.1, p.2);
    let fr = mk(frame_from(c, q));
    let (a, b, d) = frame_from(c, iv);
    let fi = LnFrame::new(a, b, d);
    let (a, b, d) = frame_from(c, |x| x);
    let ff = LnFrame::new(a, b, d);
    st.cases += 1;
    // sin of the angle between ∇b0 and ∇b1, from exact values.
    let (p0, pm, p3) = frame_from(c, q);
    let (d0, d1) = (pm.sub(&p0), p3.sub(&pm));
    let n = d0.norm2() * d1.norm2();
    let deg = if n == Rational::default() {
        0.0
    } else {
        (d0.cross(&d1).sqr() / n).approx().sqrt()
    };
    st.decision(
        "frame: non-collinear",
        frame_decision(&fr),
        frame_decision(&fi),
        frame_decision(&ff),
        deg,
    );
    if let Ok(fr) = &fr {
        let e = fr.lambda2();
        let (a, b, d) = frame_from(c, iv);
        let i = LnFrame::new_unchecked(a, b, d).lambda2();
        let (a, b, d) = frame_from(c, |x| x);
        if let Some(f) = LnFrame::new_unchecked(a, b, d).lambda2() {
            st.value("frame: λ²", e.as_ref(), i, f);
        }
    }
}

fn defined<T>(r: &Result<T, LnError>) -> Option<bool> {
    match r {
        Ok(_) => Some(true),
        Err(LnError::InvalidParameter { .. }) => Some(false),
        Err(_) => None,
    }
}

fn tau_values<S: Scalar>(c: &TauCase, f: impl Fn(f64) -> S + Copy) -> Result<Vec<S>, LnError> {
    let (a, b, d) = frame_from(&c.frame, f);
    let fr = LnFrame::new_unchecked(a, b, d);
    let (d0, d1) = deltas_from_tau(&Tau::Finite(f(c.tau)))?;
    let cubic = fr.cubic(&d0, &d1);
    let p = cubic.points();
    Ok(vec![
        d0,
        d1,
        p[1].x.clone(),
        p[1].y.clone(),
        p[2].x.clone(),
        p[2].y.clone(),
    ])
}

/// Seed 000 eq. (1) and Prop 3.1: `δ(τ)`, the control points, the regularity
/// decision, and the direct check by root isolation.
pub fn check_tau(c: &TauCase, st: &mut KernelStats) {
    let Some([tau]) = exact([c.tau]) else {
        st.rejected += 1;
        return;
    };
    let q = |x: f64| rational_from_f64(x).unwrap_or_default();
    let (a, b, d) = frame_from(&c.frame, q);
    let Ok(frame) = LnFrame::new(a, b, d) else {
        st.rejected += 1;
        return;
    };
    st.cases += 1;
    let (er, ir, fr) = (tau_values(c, q), tau_values(c, iv), tau_values(c, |x| x));
    let deg = rel_dist(c.tau, &[1.0 / 3.0, 2.0 / 3.0]);
    st.decision(
        "cubic: δ(τ) defined",
        defined(&er),
        defined(&ir),
        defined(&fr),
        deg,
    );
    if let (Ok(e), Ok(i), Ok(f)) = (&er, &ir, &fr) {
        for (k, name) in ["δ0", "δ1", "b1.x", "b1.y", "b2.x", "b2.y"]
            .iter()
            .enumerate()
        {
            st.value(&format!("cubic: {name}"), Some(&e[k]), Some(i[k]), f[k]);
        }
    }
    let deg = rel_dist(c.tau, &[0.0, 1.0]);
    let ex = prop_3_1_regular(&Tau::Finite(tau.clone()));
    st.decision(
        "cubic: Prop 3.1 regular",
        ex,
        prop_3_1_regular(&Tau::Finite(iv(c.tau))),
        prop_3_1_regular(&Tau::Finite(c.tau)),
        deg,
    );
    if let Ok(e) = &er {
        let curve = frame.cubic(&e[0], &e[1]);
        st.direct(
            "cubic: Prop 3.1 vs root isolation",
            ex,
            is_regular_on(&curve, &Span::unit_closed()),
        );
    }
}

fn conv_deltas<S: Scalar>(c0: &S, c1: &S, rho: &S) -> Option<(S, S)> {
    let q = c1.div(c0)?;
    let dl = deltas_from_rho(rho).ok()?;
    let dr = deltas_from_rho(&rho.div(&q)?).ok()?;
    convolution_deltas(c0, c1, &dl, &dr).ok()
}

/// Seed 000 Props 4.2 and 4.4 on a compatible pair: the two decisions and the
/// convolution's δ's.
pub fn check_pair(c: &PairCase, st: &mut KernelStats) {
    let Some([c0, c1, rho]) = exact([c.c0, c.c1, c.rho]) else {
        st.rejected += 1;
        return;
    };
    if c0 == Rational::default() {
        st.rejected += 1;
        return;
    }
    st.cases += 1;
    let e = pair_decision(&c0, &c1, &rho);
    let i = pair_decision(&iv(c.c0), &iv(c.c1), &iv(c.rho));
    let f = pair_decision(&c.c0, &c.c1, &c.rho);
    let q = (&c1 / &c0).approx();
    let conv = conv_deltas(&c0, &c1, &rho);
    let mut deg = rel_dist(q, &[0.25, 4.0]);
    st.decision(
        "pair: Prop 4.2",
        e.map(|x| x.0),
        i.map(|x| x.0),
        f.map(|x| x.0),
        deg,
    );
    deg = deg.min(rel_dist(c.rho, &[0.5, 2.0, q / 2.0, 2.0 * q]));
    if let Some((d0, d1)) = &conv {
        deg = deg
            .min(rel_dist(d0.approx(), &[0.0, 1.0]))
            .min(rel_dist(d1.approx(), &[0.0, 1.0]));
    }
    st.decision(
        "pair: Prop 4.4 cusp",
        e.map(|x| x.1),
        i.map(|x| x.1),
        f.map(|x| x.1),
        deg,
    );
    if let (Some((e0, e1)), Some((f0, f1))) = (&conv, conv_deltas(&c.c0, &c.c1, &c.rho)) {
        let ic = conv_deltas(&iv(c.c0), &iv(c.c1), &iv(c.rho));
        st.value("pair: convolution δ0", Some(e0), ic.map(|x| x.0), f0);
        st.value("pair: convolution δ1", Some(e1), ic.map(|x| x.1), f1);
    }
}

fn hermite_in<S: Scalar>(c: &HermiteCase, f: impl Fn(f64) -> S) -> Option<HermiteData<S>> {
    HermiteData::new(f(c.x1), f(c.y1), f(c.u)).ok()
}

/// A Hermite case in the three arithmetics: exact, and interval and `f64`
/// (when they build).
struct HermiteIn3<'a> {
    he: &'a HermiteData<Rational>,
    hi: &'a Option<HermiteData<Interval>>,
    hf: &'a Option<HermiteData<f64>>,
}

/// Seed 003 Props 2.1, 3.1/3.2 (corrected for `x1 < 0`), 3.3: decisions,
/// coefficients, and the direct checks by root isolation of `f''`.
pub fn check_hermite(c: &HermiteCase, st: &mut KernelStats) {
    check_hermite_with(c, st, true);
}

/// [`check_hermite`], with the two comparisons against exact root isolation
/// (Props 2.1 and 3.2 against Sturm counts of the cubic and quartic normal
/// forms, the most expensive part) only when `isolate`: the fuzz target
/// `hermite` runs them on a sample of its inputs chosen by an input byte.
pub fn check_hermite_with(c: &HermiteCase, st: &mut KernelStats, isolate: bool) {
    let Some([_, _, _, a2, m, b]) = exact([c.x1, c.y1, c.u, c.a2, c.m, c.b]) else {
        st.rejected += 1;
        return;
    };
    let q = |x: f64| rational_from_f64(x).unwrap_or_default();
    let Some(he) = hermite_in(c, q) else {
        st.rejected += 1;
        return;
    };
    st.cases += 1;
    let hi = hermite_in(c, iv);
    let hf = hermite_in(c, |x| x);
    let h = HermiteIn3 {
        he: &he,
        hi: &hi,
        hf: &hf,
    };
    let (du, da) = hermite_degeneracy(c, &h);
    hermite_decisions(c, st, &h, [&a2, &m, &b], (du, da), isolate);
    hermite_values(c, st, &h, &a2);
}

/// Degeneracy: u/s against every case boundary (`du`); and that or a2
/// against 0, α2 and α0, α1 (`da`).
fn hermite_degeneracy(c: &HermiteCase, h: &HermiteIn3) -> (f64, f64) {
    let HermiteIn3 { he, hi, .. } = *h;
    let s = he.s().approx();
    let r3 = 3f64.sqrt();
    let du = if s > 0.0 {
        rel_dist(
            c.u / s,
            &[1.5, 3.0, 4.0 / 3.0, 2.0, 4.0, 3.0 - r3, 3.0 + r3],
        )
    } else {
        f64::INFINITY
    };
    let mut alphas = vec![0.0, he.alpha2().approx()];
    if let Some((a0, a1)) = hi.as_ref().and_then(|h| h.alphas()) {
        alphas.extend([a0.mid(), a1.mid()]);
    }
    let da = du.min(rel_dist(c.a2, &alphas));
    (du, da)
}

/// The decisions of Props 2.1, 3.1, 3.2 and 3.3 in the three arithmetics, and
/// (if `isolate`) Props 2.1 and 3.2 against root isolation.
fn hermite_decisions(
    c: &HermiteCase,
    st: &mut KernelStats,
    h: &HermiteIn3,
    [a2, m, b]: [&Rational; 3],
    (du, da): (f64, f64),
    isolate: bool,
) {
    let HermiteIn3 { he, hi, hf } = *h;
    let (ia2, im, ib) = (iv(c.a2), iv(c.m), iv(c.b));
    let e21 = he.prop_2_1();
    st.decision(
        "hermite: Prop 2.1",
        e21,
        hi.as_ref().and_then(|h| h.prop_2_1()),
        hf.as_ref().and_then(|h| h.prop_2_1()),
        du,
    );
    st.decision(
        "hermite: Prop 3.1 exists",
        he.prop_3_2_exists(),
        hi.as_ref().and_then(|h| h.prop_3_2_exists()),
        hf.as_ref().and_then(|h| h.prop_3_2_exists()),
        du,
    );
    let ea = he.nonsingular_a2_contains(a2);
    st.decision(
        "hermite: Prop 3.2 a2",
        ea,
        hi.as_ref().and_then(|h| h.nonsingular_a2_contains(&ia2)),
        hf.as_ref().and_then(|h| h.nonsingular_a2_contains(&c.a2)),
        da,
    );
    let eb = he.valid_intercept(m, b);
    st.decision(
        "hermite: Prop 3.3 b",
        eb,
        hi.as_ref().and_then(|h| h.valid_intercept(&im, &ib)),
        hf.as_ref().and_then(|h| h.valid_intercept(&c.m, &c.b)),
        da,
    );
    if isolate {
        st.direct(
            "hermite: Prop 2.1 vs root isolation",
            e21,
            normal_form_regular(&he.cubic_f(), &he.u),
        );
        st.direct(
            "hermite: Prop 3.2 vs root isolation",
            ea,
            normal_form_regular(&he.quartic_f(a2), &he.u),
        );
    }
}

/// The coefficients, α2 and D(a2) in the three arithmetics.
fn hermite_values(c: &HermiteCase, st: &mut KernelStats, h: &HermiteIn3, a2: &Rational) {
    let HermiteIn3 { he, hi, hf } = *h;
    let ia2 = iv(c.a2);
    if let (Some(hi), Some(hf)) = (hi, hf) {
        // each coefficient pair computed once per arithmetic
        let (ec, eq) = (he.cubic_coefficients(), he.quartic_coefficients(a2));
        let e = [ec.0, ec.1, eq.0, eq.1, he.alpha2(), he.discriminant_d(a2)];
        let (ic, iq) = (hi.cubic_coefficients(), hi.quartic_coefficients(&ia2));
        let i = [ic.0, ic.1, iq.0, iq.1, hi.alpha2(), hi.discriminant_d(&ia2)];
        let (fc, fq) = (hf.cubic_coefficients(), hf.quartic_coefficients(&c.a2));
        let f = [
            fc.0,
            fc.1,
            fq.0,
            fq.1,
            hf.alpha2(),
            hf.discriminant_d(&c.a2),
        ];
        for (k, name) in [
            "cubic a2",
            "cubic a3",
            "quartic a3",
            "quartic a4",
            "α2",
            "D(a2)",
        ]
        .iter()
        .enumerate()
        {
            st.value(&format!("hermite: {name}"), Some(&e[k]), Some(i[k]), f[k]);
        }
    }
}

/// Seed 000 Prop 6.1: which critical points lie in (0,1) (decided without
/// square roots), `A, B, C`, and the closed-form distance (f64 vs enclosure).
pub fn check_arc(c: &ArcCase, st: &mut KernelStats) {
    let Some([ce, se, ke]) = exact([c.cos_a, c.sin_a, c.kappa]) else {
        st.rejected += 1;
        return;
    };
    let Ok(ae) = ArcApprox::new(ce, se, ke) else {
        st.rejected += 1;
        return;
    };
    st.cases += 1;
    let ai = ArcApprox::new(iv(c.cos_a), iv(c.sin_a), iv(c.kappa)).ok();
    let af = ArcApprox::new(c.cos_a, c.sin_a, c.kappa).ok();
    let s = c.sin_a;
    let deg = rel_dist(
        c.kappa,
        &[1.0 - s, 1.0 + s, 1.0 / (1.0 - s), 1.0 / (1.0 + s), 1.0],
    );
    st.decision(
        "arc: s1, s2 in (0,1)",
        ae.critical_params_in_unit(),
        ai.as_ref().and_then(|a| a.critical_params_in_unit()),
        af.as_ref().and_then(|a| a.critical_params_in_unit()),
        deg,
    );
    if let (Some(ai), Some(af)) = (&ai, &af) {
        let (e, i, f) = (ae.abc(), ai.abc(), af.abc());
        st.value("arc: A", Some(&e.0), Some(i.0), f.0);
        st.value("arc: B", Some(&e.1), Some(i.1), f.1);
        st.value("arc: C", Some(&e.2), Some(i.2), f.2);
        if let (Some((i1, i2)), Some((f1, f2))) = (ai.critical_params(), af.critical_params()) {
            st.value("arc: s1", None, Some(i1), f1);
            st.value("arc: s2", None, Some(i2), f2);
        }
        if let (Some(i), Some(f)) = (ai.prop_6_1_distance(), af.prop_6_1_distance()) {
            st.value("arc: closed-form distance", None, Some(i), f);
        }
    }
}

/// Bézier curves of any degree: evaluation, subdivision and the hodograph
/// cross product (values, f64 inside the enclosure, error vs exact), and
/// regularity on [0, 1]: the interval path (Bernstein exclusion of
/// `x'² + y'²`) against the exact path (Sturm isolation of `gcd(x', y')`).
pub fn check_bezier(c: &lncert::gen::BezierCase, st: &mut KernelStats) {
    use lncert::poly::{enclose_roots, Poly};
    let Some(ce) = c.exact() else {
        st.rejected += 1;
        return;
    };
    st.cases += 1;
    let cf = c.float();
    let ci = cf.map(|x: &f64| iv(*x));
    let ts = [0.0, 0.125, 0.3, 0.5, 0.875, 1.0];
    for t in ts {
        let te = rational_from_f64(t).unwrap_or_default();
        let (e, i, f) = (ce.eval(&te), ci.eval(&iv(t)), cf.eval(&t));
        st.value("bezier: x(t)", Some(&e.x), Some(i.x), f.x);
        st.value("bezier: y(t)", Some(&e.y), Some(i.y), f.y);
    }
    let (le, _) = ce.split(&rational_from_f64(0.3).unwrap_or_default());
    let (li, _) = ci.split(&iv(0.3));
    let (lf, _) = cf.split(&0.3);
    for ((e, i), f) in le.points().iter().zip(li.points()).zip(lf.points()) {
        st.value("bezier: split point", Some(&e.x), Some(i.x), f.x);
    }
    if ce.degree() >= 2 {
        let (e, i, f) = (
            ce.cross_hodograph(),
            ci.cross_hodograph(),
            cf.cross_hodograph(),
        );
        for k in 0..e.len() {
            st.value("bezier: x'y'' - y'x''", Some(&e[k]), Some(i[k]), f[k]);
        }
    }
    let regular = is_regular_on(&ce, &Span::unit_closed());
    let (hx, hy) = ci.hodograph().power_coords();
    let speed2: Poly<Interval> = hx.mul(&hx).add(&hy.mul(&hy));
    // A small subdivision budget: the audit measures agreement, not reach.
    let e = enclose_roots(&speed2, 0.0, 1.0, 1.0 / 16.0, 32);
    let interval = if e.excluded_everywhere {
        Some(true)
    } else {
        None
    };
    // The f64 path has no regularity decider of its own: not compared.
    st.decision(
        "bezier: regular on [0,1]",
        Some(regular),
        interval,
        Some(regular),
        f64::INFINITY,
    );
}

#[cfg(test)]
mod tests {
    use super::super::run_kernel;

    #[test]
    fn every_kernel_runs_clean_on_a_small_seeded_batch() {
        for k in super::super::KERNELS {
            let st = run_kernel(k, 200, 1);
            assert!(st.cases > 50, "{k}: only {} cases", st.cases);
            assert!(st.certified_ok(), "{k}: {:?}", st.first_failure);
        }
    }
}
