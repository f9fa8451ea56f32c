//! Seed 000 (cubic LN Béziers, pairs, convolution, Prop 6.1): every "iff" is
//! checked against the direct decision by exact root isolation of the curve's
//! own hodograph (Sturm sequences), never against the proposition's formula.
//! Cases per property: `LNCERT_PROPTEST_CASES` (default 2000).

mod common;

use common::*;
use lncert::curve::Bezier;
use lncert::ln::circle::{ArcApprox, Prop61Case};
use lncert::ln::cubic::{
    deltas_from_rho, deltas_from_tau, lemma_4_1_regular, prop_3_1_regular, LnFrame, Tau,
};
use lncert::ln::direct::{is_regular_on, singular_points};
use lncert::ln::pair::{
    convolution_has_interior_cusp, cusp_parameter, prop_4_4_as_printed, CompatiblePair, KappaChoice,
};
use lncert::ln::LnError;
use lncert::poly::{isolate_roots, refine_root, Poly, Span};
use lncert::scalar::{Interval, IntervalExt, Rational, Scalar};
use proptest::prelude::*;

fn zero() -> Rational {
    q(0, 1)
}
fn one() -> Rational {
    q(1, 1)
}

/// Hodographs parallel for all t: x'l y'r - y'l x'r is the zero polynomial.
fn parallel(a: &Bezier<Rational>, b: &Bezier<Rational>) -> bool {
    let (ax, ay) = a.hodograph().power_coords();
    let (bx, by) = b.hodograph().power_coords();
    ax.mul(&by).sub(&ay.mul(&bx)).trimmed().degree().is_none()
}

proptest! {
    #![proptest_config(config())]

    /// Prop 3.1: regular on [0,1] iff τ ∉ [0,1]; the cusp is at τ itself;
    /// δ0, δ1 ∈ [0,1] in the regular range. τ = 1/3, 2/3 are typed errors.
    #[test]
    fn prop_3_1_iff(f in frame(), t in tau()) {
        let res = deltas_from_tau(&Tau::Finite(t.clone()));
        if t == q(1, 3) || t == q(2, 3) {
            let is_invalid = matches!(res, Err(LnError::InvalidParameter { field: "tau", .. }));
            prop_assert!(is_invalid);
            return Ok(());
        }
        let (d0, d1) = res.unwrap();
        let curve = f.cubic(&d0, &d1);
        let direct = is_regular_on(&curve, &Span::unit_closed());
        prop_assert_eq!(prop_3_1_regular(&Tau::Finite(t.clone())), Some(direct));
        // The interval path never contradicts the exact answer.
        let ti = Interval::from_rational(&t);
        if let Some(v) = prop_3_1_regular(&Tau::Finite(ti)) { prop_assert_eq!(v, direct); }
        if direct {
            prop_assert!(zero() <= d0 && d0 <= one() && zero() <= d1 && d1 <= one());
        } else {
            let h = curve.hodograph().eval(&t);
            prop_assert!(h.x == zero() && h.y == zero(), "hodograph vanishes at τ");
            let roots = singular_points(&curve, &Span::unit_closed()).unwrap();
            prop_assert_eq!(roots.len(), 1);
        }
    }

    /// Lemma 4.1: with the normal map N0(1-t) + κ N1 t the curve is regular iff
    /// ρ = κ/λ ∈ (1/2, 2).
    #[test]
    fn lemma_4_1_iff(f in frame(), r in rho()) {
        let (d0, d1) = deltas_from_rho(&r).unwrap();
        let curve = f.cubic(&d0, &d1);
        prop_assert_eq!(lemma_4_1_regular(&r), Some(is_regular_on(&curve, &Span::unit_closed())));
        // The curve's normal map is linear: its hodograph is parallel to
        // (3τ-2)∇b0(1-t) + (3τ-1)∇b1 t, here with ρ: ∇b0(1-t) + ρ ∇b1 t.
        let (hx, hy) = curve.hodograph().power_coords();
        let dir_x = Poly::new(vec![f.d0().x.clone(), f.d1().x.clone() * r.clone() - f.d0().x.clone()]);
        let dir_y = Poly::new(vec![f.d0().y.clone(), f.d1().y.clone() * r.clone() - f.d0().y.clone()]);
        prop_assert!(hx.mul(&dir_y).sub(&hy.mul(&dir_x)).trimmed().degree().is_none());
    }

    /// Prop 4.2 and Remark 4.3, against direct regularity of both curves.
    #[test]
    fn prop_4_2_iff(l in frame(), b0 in point(), (c0, c1) in end_ratios(), probes in prop::collection::vec(rat_pos(), 8)) {
        let r = compatible_right(&l, b0, c0, c1);
        let pair = CompatiblePair::new(l, r).unwrap();
        let ratio = pair.ratio();
        let holds = pair.prop_4_2().unwrap();
        let holds_closed = pair.remark_4_3().unwrap();
        let both_regular = |rho: &Rational, span: &Span| -> Result<bool, TestCaseError> {
            let p = pair.curves_for_rho(rho).unwrap();
            prop_assert!(parallel(&p.left, &p.right), "one normal map for every ρ");
            Ok(is_regular_on(&p.left, span) && is_regular_on(&p.right, span))
        };
        // Probe κ values: random ones, the interval ends and midpoints.
        let mut rhos: Vec<Rational> = probes;
        let h = q(1, 2);
        for x in [h.clone(), q(2, 1), &ratio * &h, &ratio * q(2, 1), (h.clone() + &ratio * &h) * &h, (q(2, 1) + &ratio * q(2, 1)) * &h] {
            rhos.push(x);
        }
        if holds {
            let p = pair.ln_pair_exact(&KappaChoice::Midpoint).unwrap();
            prop_assert!(is_regular_on(&p.left, &Span::unit_closed()) && is_regular_on(&p.right, &Span::unit_closed()));
            prop_assert!(parallel(&p.left, &p.right));
        } else {
            for rho in &rhos {
                prop_assert!(!both_regular(rho, &Span::unit_closed())?, "ρ = {} regularises both though q = {}", rho, ratio);
            }
            prop_assert!(pair.ln_pair_exact(&KappaChoice::Midpoint).is_err());
        }
        if holds_closed {
            // The closed intersection [1/2,2] ∩ [q/2,2q] is non-empty: its lower end works.
            let lo = if &ratio * &h > h { &ratio * &h } else { h.clone() };
            prop_assert!(both_regular(&lo, &Span::unit_open())?);
        } else {
            for rho in &rhos {
                prop_assert!(!both_regular(rho, &Span::unit_open())?);
            }
        }
    }

    /// Prop 4.4: the convolution of a regular pair has a cusp in (0,1) iff
    /// δ0 ∉ [0,1] or δ1 ∉ [0,1] (the engine's corrected form); the printed
    /// form (open interval) errs exactly when a δ is 0 or 1.
    #[test]
    fn prop_4_4_iff(l in frame(), b0 in point(), (c0, c1) in end_ratios_admissible(), t in (1i64..=99)) {
        let r = compatible_right(&l, b0, c0, c1);
        let pair = CompatiblePair::new(l, r).unwrap();
        prop_assert_eq!(pair.prop_4_2(), Some(true));
        let range = pair.admissible_rho_left().unwrap();
        let s = q(t, 100);
        let rho = range.lo.clone() + (range.hi.clone() - range.lo.clone()) * s;
        let p = pair.ln_pair_exact(&KappaChoice::Rho(rho)).unwrap();
        let conv = match pair.convolution(&p) {
            Ok(c) => c,
            Err(e) => {
                prop_assert!(pair.c0 == q(-1, 1) || pair.c1 == q(-1, 1), "unexpected {e}");
                return Ok(());
            }
        };
        let roots = singular_points(&conv.curve, &Span::unit_open()).unwrap();
        let direct = !roots.is_empty();
        prop_assert_eq!(convolution_has_interior_cusp(&conv.deltas), Some(direct));
        let printed = prop_4_4_as_printed(&conv.deltas).unwrap();
        if printed != direct {
            let boundary = |d: &Rational| *d == zero() || *d == one();
            prop_assert!(boundary(&conv.deltas.0) || boundary(&conv.deltas.1));
        }
        // Parallel pairs (c0, c1 > 0) never have a cusp: δ0, δ1 of the sum are
        // convex combinations of the parts' δ's, which lie in (0, 1).
        if pair.c0 > zero() {
            prop_assert!(!direct, "a parallel pair with a cusp");
        }
        if direct {
            let Some(Tau::Finite(tau)) = cusp_parameter(&conv.deltas) else { return Err(TestCaseError::fail("no τ")) };
            prop_assert!(roots[0].lo <= tau && tau <= roots[0].hi);
            let h = conv.curve.hodograph().eval(&tau);
            prop_assert!(h.x == zero() && h.y == zero());
        }
        // The convolution is again LN: its hodograph is parallel to both.
        prop_assert!(parallel(&conv.curve, &p.left));
    }

    /// Prop 6.1 (seed 000): the critical points of ‖ca‖ inside (0,1) are exactly
    /// the s1, s2 of eq. (9) that the printed κ-ranges select, and the closed
    /// form equals the maximum of |‖ca‖ - 1| over them. Arcs with rational
    /// (cos α, sin α) = ((1-m²)/(1+m²), 2m/(1+m²)), m ∈ (0, 1).
    #[test]
    fn prop_6_1_critical_points(mn in 1i64..=40, kn in 50i64..=200) {
        let m = q(mn, 41);
        let (c, s) = ((one() - &m * &m) / (one() + &m * &m), (q(2, 1) * &m) / (one() + &m * &m));
        let kappa = q(kn, 100);
        prop_assume!(kappa != one());
        let arc = ArcApprox::new(c.clone(), s.clone(), kappa.clone()).unwrap();
        let ca = arc.cubic().unwrap();
        // Direct: g(s) = ca'(s)·ca(s), roots in (0,1) by Sturm isolation.
        let (x, y) = ca.power_coords();
        let g = x.derivative().mul(&x).add(&y.derivative().mul(&y));
        let roots = isolate_roots(&g, &Span::unit_open());
        // Closed form with intervals.
        let iv = |r: &Rational| Interval::from_rational(r);
        let arc_i = ArcApprox::new(iv(&c), iv(&s), iv(&kappa)).unwrap();
        let Some((in1, in2)) = arc_i.params_in_unit() else { return Ok(()) }; // undecided near a boundary: allowed
        let (s1, s2) = arc_i.critical_params().unwrap();
        let inside: Vec<Interval> = [(in1, s1), (in2, s2)].into_iter().filter(|(b, _)| *b).map(|(_, v)| v).collect();
        prop_assert_eq!(inside.len(), roots.len(), "critical points: closed form {:?}, direct {:?}", inside, roots);
        for (r, si) in roots.iter().zip(inside.iter().rev().collect::<Vec<_>>().iter().rev()) {
            let r = refine_root(&g, r, &q(1, 1_000_000_000));
            let ri = Interval::from_rational(&r.lo).convex_hull(Interval::from_rational(&r.hi));
            let _ = si;
            prop_assert!(inside.iter().any(|v| !v.disjoint(ri)), "root {:?} not among s1, s2", ri);
        }
        // The printed case split agrees with the computed membership (Fig. 9).
        let case = arc.prop_6_1_case().unwrap();
        let expect = match (in1, in2) { (true, false) => Prop61Case::S1, (false, true) => Prop61Case::S2, (true, true) => Prop61Case::Both, _ => return Err(TestCaseError::fail("no interior critical point")) };
        prop_assert_eq!(case, expect);
        // The closed form encloses the max of |‖ca‖ - 1| at the exact roots.
        let d = arc_i.prop_6_1_distance().unwrap();
        let at_roots = roots.iter().map(|r| {
            let r = refine_root(&g, r, &q(1, 1_000_000_000_000));
            let ri = Interval::from_rational(&r.lo).convex_hull(Interval::from_rational(&r.hi));
            arc_i.radial_error(&ri).unwrap()
        }).fold(Interval::point(0.0).unwrap(), |a: Interval, b| a.max(b));
        prop_assert!(!d.disjoint(at_roots), "closed form {:?} vs direct {:?}", d, at_roots);
    }
}

/// Erratum (Prop 4.4): a regular compatible pair whose convolution has δ0 = 0
/// exactly: τ = 0, the cusp is at the end point t = 0, not in (0,1), yet the
/// printed statement ("δ0 ∉ (0,1) ⇒ cusp in (0,1)") says it is inside.
#[test]
fn erratum_prop_4_4_cusp_at_end_point() {
    let p = |x: i64, y: i64| lncert::curve::V2::new(q(x, 1), q(y, 1));
    let l = LnFrame::new(p(0, 0), p(1, 0), p(1, 1)).unwrap();
    // ρl = 1, ρr = 1 ⇒ q = 1, δ0ˡ = δ0ʳ = 2/3; c0 = -δ0ˡ/δ0ʳ = -1 is degenerate,
    // so take ρr = 3/2 (δ0ʳ = 8/9): c0 = -(2/3)/(8/9) = -3/4, c1 = q c0 = -1/2.
    let (c0, c1) = (q(-3, 4), q(-1, 2));
    let r = compatible_right(&l, p(5, 5), c0, c1);
    let pair = CompatiblePair::new(l, r).unwrap();
    assert_eq!(pair.ratio(), q(2, 3));
    let pr = pair.ln_pair_exact(&KappaChoice::Rho(q(1, 1))).unwrap();
    assert_eq!(pr.rho_right, q(3, 2));
    let conv = pair.convolution(&pr).unwrap();
    assert_eq!(conv.deltas.0, q(0, 1));
    assert_eq!(prop_4_4_as_printed(&conv.deltas), Some(true));
    assert_eq!(convolution_has_interior_cusp(&conv.deltas), Some(false));
    let inside = singular_points(&conv.curve, &Span::unit_open()).unwrap();
    assert!(inside.is_empty(), "no cusp in the open interval");
    let closed = singular_points(&conv.curve, &Span::unit_closed()).unwrap();
    assert_eq!(closed.len(), 1);
    assert!(
        closed[0].is_exact() && closed[0].lo == q(0, 1),
        "the cusp is at t = 0"
    );
}

/// The f64 path agrees with the exact path on well-conditioned data.
#[test]
fn f64_path_matches_exact_on_fig5a() {
    let p = |x: i64, y: i64, d: i64| lncert::curve::V2::new(q(x, d), q(y, d));
    let l = LnFrame::new(p(5, -2, 2), p(1, 2, 2), p(7, 10, 2)).unwrap();
    let r = LnFrame::new(p(15, -24, 6), p(6, -15, 6), p(12, -7, 6)).unwrap();
    let exact = CompatiblePair::new(l.clone(), r.clone()).unwrap();
    let to_f = |f: &LnFrame<Rational>| {
        LnFrame::<f64>::new(
            f.b0.map(|v| v.approx()),
            f.bm.map(|v| v.approx()),
            f.b3.map(|v| v.approx()),
        )
        .unwrap()
    };
    let fl = CompatiblePair::new(to_f(&l), to_f(&r)).unwrap();
    assert!((fl.ratio() - exact.ratio().approx()).abs() < 1e-15);
    let pf = fl.ln_pair(&KappaChoice::GeometricMean).unwrap();
    assert!(
        (pf.deltas_left.0 - 1.0 / 3.0).abs() < 1e-15
            && (pf.deltas_left.1 - 8.0 / 9.0).abs() < 1e-15
    );
}

/// Bad input is a typed error naming the field, in every arithmetic; never a panic.
#[test]
fn bad_input_is_a_typed_error() {
    use lncert::curve::V2;
    use lncert::ln::circle::ArcApprox;
    use lncert::ln::hermite::{cubic_nonsingular_u_range, HermiteData};
    let field = |e: LnError| match e {
        LnError::InvalidParameter { field, .. }
        | LnError::Collinear { field }
        | LnError::Undecided { field }
        | LnError::NotCompatible { field, .. } => field,
    };
    let p = |x: f64, y: f64| V2::new(x, y);
    assert_eq!(
        field(LnFrame::new(p(f64::NAN, 0.0), p(1.0, 1.0), p(2.0, 0.0)).unwrap_err()),
        "b0"
    );
    assert_eq!(
        field(LnFrame::new(p(0.0, 0.0), p(f64::INFINITY, 1.0), p(2.0, 0.0)).unwrap_err()),
        "bm"
    );
    assert_eq!(
        field(LnFrame::new(p(0.0, 0.0), p(1.0, 1.0), p(2.0, 2.0)).unwrap_err()),
        "b0,bm,b3"
    );
    assert_eq!(
        field(LnFrame::new(p(1.0, 1.0), p(1.0, 1.0), p(2.0, 0.0)).unwrap_err()),
        "b0,bm,b3"
    );
    assert_eq!(
        field(deltas_from_tau(&Tau::Finite(f64::NAN)).unwrap_err()),
        "tau"
    );
    assert_eq!(field(deltas_from_rho(&0.0f64).unwrap_err()), "rho");
    assert_eq!(
        field(HermiteData::new(1.0, f64::NAN, 1.0).unwrap_err()),
        "y1"
    );
    assert_eq!(
        field(cubic_nonsingular_u_range(&f64::NEG_INFINITY, &1.0).unwrap_err()),
        "x1"
    );
    assert_eq!(
        field(ArcApprox::new(0.5, 0.5, f64::NAN).unwrap_err()),
        "kappa"
    );
    assert_eq!(
        field(ArcApprox::new(-0.5, 0.5, 1.0).unwrap_err()),
        "cos_alpha"
    );
    // Huge and tiny coordinates stay exact on the rational path.
    let big = q(10, 1).pow(300);
    let tiny = q(1, 1) / &big;
    let f = LnFrame::new(
        lncert::curve::V2::new(tiny.clone(), q(0, 1)),
        lncert::curve::V2::new(big.clone(), big.clone()),
        lncert::curve::V2::new(q(2, 1) * &big, tiny),
    )
    .unwrap();
    let (d0, d1) = deltas_from_tau(&Tau::Finite(q(-1, 1))).unwrap();
    assert!(is_regular_on(&f.cubic(&d0, &d1), &Span::unit_closed()));
    // Incompatible pairs are rejected with the reason.
    let l = LnFrame::new(p(0.0, 0.0), p(1.0, 0.0), p(1.0, 1.0)).unwrap();
    let r = LnFrame::new(p(0.0, 0.0), p(0.0, 1.0), p(1.0, 1.0)).unwrap();
    assert!(matches!(
        CompatiblePair::new(l, r),
        Err(LnError::NotCompatible { .. })
    ));
}

proptest! {
    #![proptest_config(config())]

    /// Prop 4.2 + 4.4 decisions: the interval path never contradicts the exact
    /// one, the filtered decision always equals it, and planted boundary cases
    /// (q = 4, q = 1/4 exactly) are decided.
    #[test]
    fn pair_decision_paths_agree((c0, c1) in end_ratios(), rn in 1i64..=300) {
        use lncert::ln::pair::PairDecision;
        use lncert::scalar::{filtered, Predicate};
        let d = PairDecision { c0, c1, rho_left: q(rn, 100) };
        let exact = d.decide::<Rational>();
        prop_assert!(exact.is_some());
        if let Some(v) = d.decide::<Interval>() { prop_assert_eq!(Some(v), exact); }
        prop_assert_eq!(filtered(&d), exact);
    }
}

/// ρ choices for the division-free form's test: random ones, and every
/// boundary the decision turns on (`1/2`, `2`, `q/2`, `2q`, and the zeros of
/// `A = 2ρ(1 + c0) − (1 + c1)` and `B = 2(1 + c1) − ρ(1 + c0)`).
fn rho_choices(c0: &Rational, c1: &Rational, k: usize, rn: i64) -> Option<Rational> {
    let qv = c1 / c0;
    let (p0, p1) = (q(1, 1) + c0, q(1, 1) + c1);
    Some(match k {
        0..=3 => q(rn, 97),
        4 => q(1, 2),
        5 => q(2, 1),
        6 => &qv / q(2, 1),
        7 => &qv * q(2, 1),
        8 if p0 != q(0, 1) => &p1 / (q(2, 1) * &p0),
        9 if p0 != q(0, 1) => q(2, 1) * &p1 / &p0,
        _ => return None,
    })
}

proptest! {
    #![proptest_config(config())]

    /// The division-free form of Props 4.2 + 4.4 (`pair_decision_signs`, what
    /// `filtered` evaluates) equals the paper's form (`pair_decision`, with the
    /// quotients `q`, `ρ/q` and the δs) in exact rationals on every input,
    /// boundaries planted (`q = 1/4, 4`, `ρ` at each end of its range, `A = 0`,
    /// `B = 0`, `1 + c0 = 0`, `1 + c1 = 0`, `c0 = 0`); its float-with-error-bound
    /// and interval evaluations never contradict it.
    #[test]
    fn division_free_pair_decision_is_the_papers(
        (c0, c1) in end_ratios(),
        edge in 0usize..8,
        k in 0usize..10,
        rn in -40i64..=300,
    ) {
        use lncert::ln::pair::{pair_decision, pair_decision_signs};
        use lncert::scalar::FloatErr;
        let (c0, c1) = match edge {
            0 => (q(-1, 1), c1),
            1 => (c0, q(-1, 1)),
            2 => (q(0, 1), c1),
            _ => (c0, c1),
        };
        let Some(rho) = (if c0 == q(0, 1) { Some(q(rn, 97)) } else { rho_choices(&c0, &c1, k, rn) }) else {
            return Ok(());
        };
        let exact = pair_decision_signs(&c0, &c1, &rho);
        prop_assert_eq!(&exact, &pair_decision(&c0, &c1, &rho), "c0 {} c1 {} rho {}", c0, c1, rho);
        let f = |r: &Rational| FloatErr::from_rational(r);
        if let Some(v) = pair_decision_signs(&f(&c0), &f(&c1), &f(&rho)) {
            prop_assert_eq!(Some(v), exact);
        }
        let i = |r: &Rational| Interval::from_rational(r);
        if let Some(v) = pair_decision_signs(&i(&c0), &i(&c1), &i(&rho)) {
            prop_assert_eq!(Some(v), exact);
        }
    }
}

/// `x` as a float with an error bound whose value is moved `k` units of
/// `2^-j |x|` off the nearest float, its bound the exact distance rounded up
/// plus `extra` such units: the real `x` stays within the stated bound.
fn loose_float(x: &Rational, k: i64, j: i32, extra: u32) -> lncert::scalar::FloatErr {
    use lncert::scalar::{interval_from_rational, rational_from_f64, FloatErr};
    let unit = x.approx().abs() * 2f64.powi(-j);
    let v = x.approx() + k as f64 * unit;
    let dist = (x - rational_from_f64(v).unwrap()).abs_val();
    let e = interval_from_rational(&dist).sup() + extra as f64 * unit;
    FloatErr { v, e }
}

proptest! {
    #![proptest_config(config())]

    /// The static stage of Props 4.2 + 4.4 (`pair_decision_static`: plain f64
    /// tests against one bound from the inputs' magnitude) never contradicts the
    /// exact division-free decision, on inputs within a few ulps of every
    /// boundary (the planted ones of the test above, each input moved by
    /// `k·2⁻ʲ·x/3`, `j` in 50..=58), scaled by powers of two, and given as the
    /// nearest floats with their bounds, as floats with loose error bounds (value
    /// moved off the input, bound up to `2⁻²⁰·|x|`), or rounded to floats that
    /// are then the exact inputs (no input error: the rounding terms alone).
    #[test]
    fn static_pair_decision_is_never_wrong(
        (c0, c1) in end_ratios(),
        edge in 0usize..8,
        k in 0usize..10,
        rn in -40i64..=300,
        nudge in prop::array::uniform3(-6i64..=6),
        fine in 50u32..=58,
        scale in -30i32..=30,
        loose in prop::array::uniform3((-3i64..=3, 20i32..=53, 0u32..=2)),
        mode in 0usize..3,
    ) {
        use lncert::ln::pair::{pair_decision_signs, pair_decision_static};
        use lncert::scalar::FloatErr;
        let (c0, c1) = match edge {
            0 => (q(-1, 1), c1),
            1 => (c0, q(-1, 1)),
            _ => (c0, c1),
        };
        let pow = |s: i32| if s >= 0 { q(1 << s, 1) } else { q(1, 1 << -s) };
        let (c0, c1) = if edge == 7 { (&c0 * pow(scale), &c1 * pow(scale)) } else { (c0, c1) };
        let Some(rho) = rho_choices(&c0, &c1, k, rn) else { return Ok(()); };
        // each input moved a few units of 2⁻⁵⁰|x|/3 (non-dyadic, off every float)
        let nudged = |x: &Rational, n: i64| x + x * q(n, 3) * q(1, 1 << fine);
        let mut ins = [nudged(&c0, nudge[0]), nudged(&c1, nudge[1]), nudged(&rho, nudge[2])];
        if mode == 2 {
            // exact floats (no input error): the bound's rounding terms alone
            for x in &mut ins {
                *x = lncert::scalar::rational_from_f64(x.approx()).unwrap();
            }
        }
        let exact = pair_decision_signs(&ins[0], &ins[1], &ins[2]);
        prop_assert!(exact.is_some());
        let f: Vec<FloatErr> = ins
            .iter()
            .zip(loose)
            .map(|(x, (k, j, extra))| {
                if mode == 1 { loose_float(x, k, j, extra) } else { FloatErr::from_rational(x) }
            })
            .collect();
        if let Some(v) = pair_decision_static(f[0], f[1], f[2]) {
            prop_assert_eq!(Some(v), exact, "c0 {} c1 {} rho {} as {:?}", &ins[0], &ins[1], &ins[2], f);
        }
    }
}

/// The static stage decides what the float with an error bound decides on a
/// grid of small rationals (every test's value is 0 or far above either bound),
/// and refuses non-finite inputs, negative bounds and magnitudes of 10¹⁵⁰.
#[test]
fn static_pair_decision_decides_away_from_ties() {
    use lncert::ln::pair::{pair_decision_signs, pair_decision_static};
    use lncert::scalar::FloatErr;
    let f = |r: &Rational| FloatErr::from_rational(r);
    let (mut both, mut float_err_only) = (0, 0);
    for n0 in [-37i64, -12, -7, -3, -1, 1, 2, 5, 9, 31] {
        for n1 in [-40i64, -9, -4, -2, 1, 3, 4, 8, 13, 29] {
            for rn in [-5i64, 13, 40, 61, 97, 150, 193, 260] {
                let (c0, c1, rho) = (q(n0, 7), q(n1, 5), q(rn, 97));
                let exact = pair_decision_signs(&c0, &c1, &rho);
                let by_float_err = pair_decision_signs(&f(&c0), &f(&c1), &f(&rho));
                let by_static = pair_decision_static(f(&c0), f(&c1), f(&rho));
                if let Some(v) = by_static {
                    assert_eq!(Some(v), exact, "{c0} {c1} {rho}");
                }
                match (by_float_err, by_static) {
                    (Some(_), Some(_)) => both += 1,
                    (Some(_), None) => float_err_only += 1,
                    _ => {}
                }
            }
        }
    }
    assert!(both > 600, "static decided {both}");
    assert_eq!(float_err_only, 0);
    let one = FloatErr::exact(1.0);
    let half = FloatErr::exact(0.75);
    for bad in [
        FloatErr::exact(f64::NAN),
        FloatErr::exact(f64::INFINITY),
        FloatErr {
            v: 1.0,
            e: f64::NAN,
        },
        FloatErr { v: 1.0, e: -1.0 },
        FloatErr::exact(1e150),
        FloatErr { v: 1.0, e: 1e151 },
    ] {
        assert_eq!(pair_decision_static(bad, one, half), None, "{bad:?}");
        assert_eq!(pair_decision_static(one, bad, half), None, "{bad:?}");
        assert_eq!(pair_decision_static(one, one, bad), None, "{bad:?}");
    }
}

/// The static stage on exact float inputs at the float nearest each boundary
/// of `ρ` (`q/2`, `2q`, `A = 0`, `B = 0`) and a few ulps around it: the exact
/// tests' values are then below an ulp of the operands, where the float
/// evaluation's own roundings decide the sign, so only a bound that covers
/// them keeps the answers exact.
#[test]
fn static_pair_decision_at_float_ties() {
    use lncert::ln::pair::{pair_decision_signs, pair_decision_static};
    use lncert::scalar::{rational_from_f64, FloatErr};
    let exact_of = |x: f64| rational_from_f64(x).unwrap();
    let (mut decided, mut total) = (0, 0);
    for n0 in 1..=40i64 {
        for n1 in 1..=40i64 {
            for neg in [false, true] {
                let sg = if neg { -1.0 } else { 1.0 };
                let (a, b) = (sg * n0 as f64 / 7.0, sg * n1 as f64 / 9.0);
                let (p0, p1) = (1.0 + a, 1.0 + b);
                for tie in [b / (2.0 * a), 2.0 * b / a, p1 / (2.0 * p0), 2.0 * p1 / p0] {
                    let mut r = tie;
                    for _ in 0..3 {
                        r = f64::from_bits(r.to_bits() - 1);
                    }
                    for _ in 0..7 {
                        r = f64::from_bits(r.to_bits() + 1);
                        if !r.is_finite() {
                            continue;
                        }
                        total += 1;
                        let exact = pair_decision_signs(&exact_of(a), &exact_of(b), &exact_of(r));
                        let e = FloatErr::exact;
                        if let Some(v) = pair_decision_static(e(a), e(b), e(r)) {
                            decided += 1;
                            assert_eq!(Some(v), exact, "c0 {a:e} c1 {b:e} rho {r:e}");
                        }
                    }
                }
            }
        }
    }
    // most ties' tests are within the bound; the rest decide away from them
    assert!(decided > total / 10, "{decided} of {total}");
}
