//! Seed 003 (LN normal form, Hermite interpolation): every "iff" against the
//! direct decision — exact root isolation of `f''` on `[0, u]` (`K'(t) = f''(t)[-1, t]`).
//! Cases per property: `LNCERT_PROPTEST_CASES` (default 2000).

mod common;

use common::*;
use lncert::ln::cubic::{deltas_from_tau, prop_3_1_regular, Tau};
use lncert::ln::direct::{is_regular_on, normal_form_regular};
use lncert::ln::hermite::{
    convolve_normal_forms, cubic_nonsingular_u_range, normal_form, prop_7_1_recommended,
    HermiteData,
};
use lncert::ln::LnError;
use lncert::poly::{Poly, Span};
use lncert::scalar::{rational_from_f64, Interval, Rational, Scalar};
use proptest::prelude::*;

fn hermite() -> impl Strategy<Value = HermiteData<Rational>> {
    (rat_nonzero(), rat(), rat_pos())
        .prop_filter_map("valid", |(x1, y1, u)| HermiteData::new(x1, y1, u).ok())
}

/// Hermite data with s > 0 and u placed around the interesting ratios u/s.
fn hermite_interesting() -> impl Strategy<Value = HermiteData<Rational>> {
    (rat_nonzero(), 1i64..=20, 1i64..=6, 1i64..=500).prop_filter_map("valid", |(x1, sn, sd, k)| {
        let s = q(sn, sd);
        let y1 = -(s.clone() * x1.clone());
        let u = s * q(k, 100); // u/s ∈ (0, 5]
        HermiteData::new(x1, y1, u).ok()
    })
}

/// A rational inside the certified open interval (lo, hi).
fn rational_inside(lo: f64, hi: f64, t: i64) -> Option<Rational> {
    let (l, h) = (rational_from_f64(lo)?, rational_from_f64(hi)?);
    Some(l.clone() + (h - l) * q(t, 100))
}

proptest! {
    #![proptest_config(config())]

    /// Prop 2.1: the cubic interpolant is nonsingular on [0,u] iff 3s/2 < u < 3s.
    #[test]
    fn prop_2_1_iff(h in hermite()) {
        let direct = normal_form_regular(&h.cubic_f(), &h.u);
        prop_assert_eq!(h.prop_2_1(), Some(direct));
        // The interpolant meets its end conditions exactly.
        let (x, y) = normal_form(&h.cubic_f());
        prop_assert_eq!((x.eval(&h.u), y.eval(&h.u)), (h.x1.clone(), h.y1.clone()));
        prop_assert_eq!(h.cubic_f().derivative().eval(&h.u) , -h.x1.clone()); // normal (u, 1) at the end
    }

    /// Props 3.1/3.2: a nonsingular quartic exists iff (3-√3)s < u < (3+√3)s;
    /// the engine's a2 interval (Prop 3.2, corrected for x1 < 0) is exactly the
    /// nonsingular set; the printed table is right for x1 > 0.
    #[test]
    fn prop_3_2_iff(h in prop_oneof![hermite(), hermite_interesting()], a2 in rat(), probes in prop::collection::vec(-400i64..=400, 6), t in 1i64..=99) {
        let exists = h.prop_3_2_exists().unwrap();
        let direct = |a: &Rational| normal_form_regular(&h.quartic_f(a), &h.u);
        // Membership of a random a2 and of probes around the interval ends.
        let hi = HermiteData::new(Interval::from_rational(&h.x1), Interval::from_rational(&h.y1), Interval::from_rational(&h.u)).unwrap();
        let mut samples = vec![a2];
        if let Some((lo, up)) = hi.nonsingular_a2_interval() {
            for p in &probes {
                let w = (up.sup() - lo.inf()).abs().max(1e-3);
                for end in [lo.inf(), up.sup()] {
                    if let Some(r) = rational_from_f64(end + w * (*p as f64) / 4000.0) { samples.push(r); }
                }
            }
        }
        for a in &samples {
            let d = direct(a);
            prop_assert_eq!(h.nonsingular_a2_contains(a), Some(d), "a2 = {}", a);
            if h.x1 > q(0, 1) {
                prop_assert_eq!(h.prop_3_2_contains(a), Some(d), "printed table, x1 > 0, a2 = {}", a);
            }
            if d { prop_assert!(exists, "a nonsingular quartic exists though Prop 3.1 says none"); }
        }
        // Inside the certified interval every a2 is nonsingular. (The interval
        // path may leave the interval undecided at exact case boundaries.)
        if let (true, Some((lo, up))) = (exists, hi.nonsingular_a2_interval()) {
            if let Some(a) = rational_inside(lo.sup(), up.inf(), t) {
                if lo.sup() < up.inf() { prop_assert!(direct(&a), "a2 = {} inside the certified interval", a); }
            }
        }
    }

    /// Prop 3.3: a line m x + y + b = 0 (0 < m < u) is a valid tangent of a
    /// nonsingular quartic iff b lies in the (corrected) interval; the printed
    /// β_i formulas are b(α_i).
    #[test]
    fn prop_3_3_iff(h in prop_oneof![hermite(), hermite_interesting()], mt in 1i64..=99, b in rat(), alpha in rat()) {
        let m = h.u.clone() * q(mt, 100);
        let a2 = h.a2_from_b(&m, &b).unwrap();
        prop_assert_eq!(h.b_from_a2(&m, &a2), b.clone());
        let direct = normal_form_regular(&h.quartic_f(&a2), &h.u);
        prop_assert_eq!(h.valid_intercept(&m, &b), Some(direct));
        if h.x1 > q(0, 1) { prop_assert_eq!(h.prop_3_3_contains(&m, &b), Some(direct)); }
        prop_assert_eq!(h.beta_i(&m, &alpha), Some(h.b_from_a2(&m, &alpha)));
        // The tangency: K(m) lies on the line and the normal there is (m, 1).
        let (x, y) = normal_form(&h.quartic_f(&a2));
        prop_assert_eq!(m.clone() * x.eval(&m) + y.eval(&m) + b, q(0, 1));
    }

    /// Seed 003 Prop 6.1: K_f + K_F = K_{f+F}, and both have normal (t, 1) at t.
    #[test]
    fn prop_6_1_convolution(f in prop::collection::vec(rat(), 1..6), g in prop::collection::vec(rat(), 1..6)) {
        let (f, g) = (Poly::new(f), Poly::new(g));
        let (kx, ky) = normal_form(&f);
        let (gx, gy) = normal_form(&g);
        let (cx, cy) = convolve_normal_forms(&f, &g);
        prop_assert_eq!(cx.trimmed(), kx.add(&gx).trimmed());
        prop_assert_eq!(cy.trimmed(), ky.add(&gy).trimmed());
        // K'(t) · (t, 1) = 0 for both curves: the common Gauss map.
        let t = Poly::t();
        for (x, y) in [(kx, ky), (gx, gy)] {
            prop_assert!(x.derivative().mul(&t).add(&y.derivative()).trimmed().degree().is_none());
        }
    }

    /// Prop 7.1: same construction as seed 000 eq. (1): singular in [0,1] iff
    /// τ ∈ [0,1]; the recommended range (-∞,-1) ∪ (1,∞) is sufficient.
    #[test]
    fn prop_7_1(f in frame(), t in tau()) {
        prop_assume!(t != q(1, 3) && t != q(2, 3));
        let (d0, d1) = deltas_from_tau(&Tau::Finite(t.clone())).unwrap();
        let direct = is_regular_on(&f.cubic(&d0, &d1), &Span::unit_closed());
        prop_assert_eq!(prop_3_1_regular(&Tau::Finite(t.clone())), Some(direct));
        if prop_7_1_recommended(&t) == Some(true) { prop_assert!(direct); }
    }
}

/// Erratum (Prop 3.2): the printed table assumes x1 > 0. For x1 = -1, y1 = 2/3,
/// u = 11/4 (u/s = 33/8 > 4) the quartic with a2 = 4/7 is nonsingular, but the
/// printed interval (α0, α1) is empty because α0 ≈ 0.727 > α1 ≈ 0.563 when x1 < 0.
#[test]
fn erratum_prop_3_2_negative_x1() {
    let h = HermiteData::new(q(-1, 1), q(2, 3), q(11, 4)).unwrap();
    let a2 = q(4, 7);
    assert!(normal_form_regular(&h.quartic_f(&a2), &h.u));
    assert_eq!(h.prop_3_2_contains(&a2), Some(false));
    assert_eq!(h.nonsingular_a2_contains(&a2), Some(true));
}

/// Erratum (Prop 3.3, inherited from Prop 3.2): with the same data and the
/// tangent slope m = 1, the intercept b = f(1) of the nonsingular quartic with
/// a2 = 4/7 is valid, but the printed b-interval rejects it.
#[test]
fn erratum_prop_3_3_negative_x1() {
    let h = HermiteData::new(q(-1, 1), q(2, 3), q(11, 4)).unwrap();
    let (m, a2) = (q(1, 1), q(4, 7));
    let b = h.b_from_a2(&m, &a2);
    assert_eq!(h.a2_from_b(&m, &b), Some(a2.clone()));
    assert!(normal_form_regular(&h.quartic_f(&a2), &h.u));
    assert_eq!(h.prop_3_3_contains(&m, &b), Some(false));
    assert_eq!(h.valid_intercept(&m, &b), Some(true));
}

/// Erratum (Prop 7.1): τ = -1/2 lies outside the recommended range but the
/// curve is regular: the exact range is seed 000's (-∞, 0) ∪ (1, ∞].
#[test]
fn erratum_prop_7_1_range_too_small() {
    let p = |x: i64, y: i64| lncert::curve::V2::new(q(x, 1), q(y, 1));
    let f = lncert::ln::cubic::LnFrame::new(p(0, 0), p(1, 1), p(2, 0)).unwrap();
    for t in [q(-1, 2), q(-1, 1), q(-1, 10)] {
        let (d0, d1) = deltas_from_tau(&Tau::Finite(t.clone())).unwrap();
        assert!(is_regular_on(&f.cubic(&d0, &d1), &Span::unit_closed()));
        if t != q(-1, 1) {
            assert_eq!(prop_7_1_recommended(&t), Some(false));
        }
    }
}

/// Prop 2.1 worked example: x1 = 3, y1 = -1 gives the open range (1/2, 1).
#[test]
fn prop_2_1_example_and_bad_input() {
    let r = cubic_nonsingular_u_range(&q(3, 1), &q(-1, 1)).unwrap();
    assert_eq!((r.lo, r.hi), (q(1, 2), q(1, 1)));
    assert!(matches!(
        HermiteData::new(q(0, 1), q(1, 1), q(1, 1)),
        Err(LnError::InvalidParameter { field: "x1", .. })
    ));
    assert!(matches!(
        HermiteData::new(q(1, 1), q(1, 1), q(0, 1)),
        Err(LnError::InvalidParameter { field: "u", .. })
    ));
    assert!(matches!(
        HermiteData::new(q(1, 1), q(1, 1), q(-1, 1)),
        Err(LnError::InvalidParameter { field: "u", .. })
    ));
    assert!(HermiteData::new(f64::NAN, 1.0, 1.0).is_err());
}

proptest! {
    #![proptest_config(config())]

    /// The interval path never contradicts the exact path (it may say undecided),
    /// for Props 2.1, 3.2 and 3.3.
    #[test]
    fn interval_path_never_contradicts_exact(h in prop_oneof![hermite(), hermite_interesting()], a2 in rat(), mt in 1i64..=99, b in rat()) {
        let iv = |r: &Rational| Interval::from_rational(r);
        let hi = HermiteData::new(iv(&h.x1), iv(&h.y1), iv(&h.u)).unwrap();
        let m = h.u.clone() * q(mt, 100);
        let pairs = [
            (hi.prop_2_1(), h.prop_2_1()),
            (hi.prop_3_2_exists(), h.prop_3_2_exists()),
            (hi.nonsingular_a2_contains(&iv(&a2)), h.nonsingular_a2_contains(&a2)),
            (hi.valid_intercept(&iv(&m), &iv(&b)), h.valid_intercept(&m, &b)),
        ];
        for (i, (got, exact)) in pairs.into_iter().enumerate() {
            prop_assert!(exact.is_some(), "exact path undecided ({i})");
            if let Some(g) = got { prop_assert_eq!(Some(g), exact, "check {}", i); }
        }
    }
}
