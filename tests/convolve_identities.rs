//! Seed 001's propositions as machine-checked obligations
//! (proofs/001-convolution.md): the compatible-point derivative `e′ = λ x′` and
//! the curvature of a reparametrised curve as polynomial identities, then
//! Props 3.1 and 3.2 (C¹ and G² at both ends) in exact arithmetic on an
//! example whose data are rational, against the direct curvature formula of
//! the ellipse and the paper's (2.1) — and the erratum in (3.5).

use lncert::curve::{Bezier, V2};
use lncert::offset::kernels::{elevate_by, moments, normal_approximant, solve_alpha, G2Ends};
use lncert::poly::MPoly;
use lncert::scalar::{frac, Rational};

fn v(i: usize) -> MPoly {
    MPoly::var(i)
}

/// `e(t) = σ Q n/√s`, `s = nᵀQn`, `n = J x′`. With `m = n′`,
/// `s^{3/2} e′/σ = s Q m − (nᵀQm) Q n`, and the claim `e′ = λ x′`,
/// `λ = −σ k det Q/s^{3/2}`, `k = x′ × x″ = n × m`, is the identity
/// `s Q m − (nᵀQm) Q n + k det(Q) x′ = 0` with `x′ = (n₂, −n₁)`.
#[test]
fn compatible_point_derivative_is_lambda_times_x_prime() {
    let (n1, n2, m1, m2, q11, q12, q22) = (v(0), v(1), v(2), v(3), v(4), v(5), v(6));
    let qv = |a: &MPoly, b: &MPoly| (q11.mul(a).add(&q12.mul(b)), q12.mul(a).add(&q22.mul(b)));
    let (qn1, qn2) = qv(&n1, &n2);
    let (qm1, qm2) = qv(&m1, &m2);
    let s = n1.mul(&qn1).add(&n2.mul(&qn2));
    let nqm = n1.mul(&qm1).add(&n2.mul(&qm2));
    let k = n1.mul(&m2).sub(&n2.mul(&m1));
    let det = q11.mul(&q22).sub(&q12.mul(&q12));
    let (xp1, xp2) = (n2.clone(), n1.neg());
    let c1 = s.mul(&qm1).sub(&nqm.mul(&qn1)).add(&k.mul(&det).mul(&xp1));
    let c2 = s.mul(&qm2).sub(&nqm.mul(&qn2)).add(&k.mul(&det).mul(&xp2));
    assert!(c1.is_zero() && c2.is_zero(), "{c1} / {c2}");
    // and k = x′ × x″ with x″ = (m₂, −m₁)
    let (xpp1, xpp2) = (m2.clone(), m1.neg());
    assert!(xp1.mul(&xpp2).sub(&xp2.mul(&xpp1)).sub(&k).is_zero());
}

/// `(a u) × (a u)′ = a² (u × u′)`: a curve whose derivative is `a(t) x′(t)` has
/// curvature `κ_x / |a|` with the sign of `κ_x` where `a ≠ 0` — for `eᵃ`
/// (`a = α`, Prop 3.1) and for the convolution (`a = 1 + λ`, eq. (2.1)).
#[test]
fn curvature_of_a_scaled_derivative() {
    let (a, da, u1, u2, w1, w2) = (v(0), v(1), v(2), v(3), v(4), v(5));
    // (a u)′ = a′ u + a w with w = u′
    let (p1, p2) = (a.mul(&u1), a.mul(&u2));
    let (d1, d2) = (da.mul(&u1).add(&a.mul(&w1)), da.mul(&u2).add(&a.mul(&w2)));
    let lhs = p1.mul(&d2).sub(&p2.mul(&d1));
    let rhs = a.mul(&a).mul(&u1.mul(&w2).sub(&u2.mul(&w1)));
    assert!(lhs.sub(&rhs).is_zero());
}

mod common;
use common::q;

fn cross(a: &V2<Rational>, b: &V2<Rational>) -> Rational {
    &a.x * &b.y - &a.y * &b.x
}

/// Props 3.1 and 3.2 exactly, on data chosen so that every square root is
/// rational: the pen `M = diag(2, 1)` (`Q = diag(4, 1)`), side `+1`, and the
/// cubic `(0,0), (1,0), (2,1), (2,2)` (`x′(0) = (3, 0)`, `x′(1) = (0, 3)`: `nᵀQn`
/// is 9 and 36). Checked: G⁰ and C¹ of `x + eᵃ` at both ends, and its end
/// curvatures against (2.1) evaluated with the ellipse's curvature from the
/// direct formula `κ_E(Mu) = det M/|M J u|³`.
#[test]
fn props_3_1_and_3_2_hold_exactly() {
    let pts = vec![
        V2::new(q(0, 1), q(0, 1)),
        V2::new(q(1, 1), q(0, 1)),
        V2::new(q(2, 1), q(1, 1)),
        V2::new(q(2, 1), q(2, 1)),
    ];
    let x = Bezier::new(pts.clone());
    let d1 = x.hodograph();
    let d2 = d1.hodograph();
    let ends = [q(0, 1), q(1, 1)];
    let (qd, det_q) = ([q(4, 1), q(1, 1)], q(4, 1)); // Q = diag(4, 1)
                                                     // the ends, with √s rational: s = 9 at t = 0, 36 at t = 1
    let roots = [q(3, 1), q(6, 1)];
    let mut e = Vec::new();
    let mut lambda = Vec::new();
    for (t, r) in ends.iter().zip(&roots) {
        let xp = d1.eval(t);
        let xpp = d2.eval(t);
        let n = V2::new(-xp.y.clone(), xp.x.clone());
        let s = &qd[0] * &n.x * &n.x + &qd[1] * &n.y * &n.y;
        assert_eq!(&s, &(r * r));
        e.push(V2::new(&qd[0] * &n.x / r, &qd[1] * &n.y / r));
        // λ = −σ k det Q / s^{3/2}
        lambda.push(-(cross(&xp, &xpp) * &det_q) / (r * r * r));
    }
    // by hand: k = 18 at both ends, det Q = 4, s^{3/2} = 27 and 216
    assert_eq!(lambda, vec![q(-8, 3), q(-1, 3)]);
    let g = G2Ends {
        n0: e[0].clone(),
        n1: e[1].clone(),
        alpha0: lambda[0].clone(),
        alpha3: lambda[1].clone(),
    };
    let alpha = solve_alpha(&g, &moments(&x)).expect("Gauss map shorter than π");
    let ea = normal_approximant(&x, &e[0], &alpha);
    let xe = elevate_by(&x, 3);
    let c = Bezier::new(
        xe.points()
            .iter()
            .zip(ea.points())
            .map(|(p, q)| p.add(q))
            .collect(),
    );
    let (c1, c2) = (c.hodograph(), c.hodograph().hodograph());
    for (i, t) in ends.iter().enumerate() {
        // G⁰: eᵃ(1) = e(1) is eq. (3.2), solved exactly
        assert_eq!(c.eval(t), x.eval(t).add(&e[i]), "G0 at {t}");
        // C¹ (3.13): (x + eᵃ)′ = (1 + λ) x′ = (x ∗ e)′
        let xp = d1.eval(t);
        let one_plus = q(1, 1) + &lambda[i];
        assert_eq!(c1.eval(t), xp.scale(&one_plus), "C1 at {t}");
        // G² (Prop 3.2) against (2.1) with the ellipse's curvature computed directly
        let u = V2::new(&e[i].x / q(2, 1), e[i].y.clone()); // M⁻¹ p
        let mju = V2::new(-(q(2, 1) * &u.y), u.x.clone()); // M J u
        let len2 = mju.dot(&mju);
        // |M J u|³ is rational here: len2 is a perfect square (4 or 1)
        let len = if len2 == q(4, 1) { q(2, 1) } else { q(1, 1) };
        assert_eq!(&len * &len, len2);
        let kappa_e = q(2, 1) / (&len * &len * &len); // det M = 2
        let speed = xp.dot(&xp);
        let speed_len = q(3, 1); // |x′| = 3 at both ends
        assert_eq!(&speed_len * &speed_len, speed);
        let kappa_x = cross(&xp, &d2.eval(t)) / (&speed_len * &speed_len * &speed_len);
        // (2.1): anti-parallel (λ < 0) takes the minus sign
        assert!(lambda[i] < q(0, 1));
        let abs = |r: Rational| if r < q(0, 1) { -r } else { r };
        let kappa_conv = abs(&kappa_x * &kappa_e / (abs(kappa_x.clone()) - abs(kappa_e.clone())));
        let cp = c1.eval(t);
        let cl = abs(one_plus.clone()) * &speed_len; // |C′|
        let kappa_c = cross(&cp, &c2.eval(t)) / (&cl * &cl * &cl);
        assert_eq!(abs(kappa_c), kappa_conv, "G2 at {t}");
        // Prop 3.1: |α₃ᵢ| = κ_x/κ_e
        assert_eq!(abs(lambda[i].clone()), &kappa_x / &kappa_e);
    }
    // Erratum in (3.5): the printed e_a″(0) = α₀² x″(0) + 3Δα₀ x′(0) does not
    // hold; e_a″(0) = α₀ x″(0) + 3Δα₀ x′(0) does (and (3.6) follows from it).
    let ea2 = ea.hodograph().hodograph().eval(&q(0, 1));
    let (xp0, xpp0) = (d1.eval(&q(0, 1)), d2.eval(&q(0, 1)));
    let delta = q(3, 1) * (&alpha[1] - &alpha[0]);
    let correct = xpp0.scale(&alpha[0]).add(&xp0.scale(&delta));
    let printed = xpp0.scale(&(&alpha[0] * &alpha[0])).add(&xp0.scale(&delta));
    assert_eq!(ea2, correct);
    assert_ne!(ea2, printed);
}

/// Seed 001 (4.1) `d_H(x ∗ e, x ∗ eᵃ) = d_H(e, eᵃ)` (from [8], for regular
/// curves without cusps): lncert never relies on it, and it is tested here as
/// far as lncert can state both sides exactly — a circle pen (an ellipse with
/// equal axes), whose pen arc `e` is an exact arc shape. On every segment of a
/// convolution of the test cubic, certified enclosures of both sides (relative
/// gap 1e-6) overlap: no counterexample (proofs/001-convolution.md). For a
/// non-circular pen the arc of an ellipse is not a shape lncert can certify
/// against yet, so (4.1) stays undecided there.
#[test]
fn equation_4_1_agrees_on_the_test_cubic_segments() {
    use lncert::certify::{hausdorff, Config};
    use lncert::offset::Pen;
    use lncert::offset::{convolve, exact_bezier, OffsetOptions};
    use lncert::scalar::rational_from_f64;
    use lncert::shape::{ArcDesc, ShapeDesc};
    let x = lncert::shape::parse_curve(
        r#"{"bezier": [[-0.95, 0.7], [-0.3, 0.5], [0.3, -2.5], [0.9, -0.2]]}"#,
    )
    .unwrap();
    let r = q(1, 2);
    let pen = Pen::from_matrix([[r.clone(), q(0, 1)], [q(0, 1), r.clone()]]).unwrap();
    let res = convolve(&x, &pen, 1, &OffsetOptions::new(q(0, 1), common::tol(3e-1))).unwrap();
    let cfg = Config {
        rel: 1e-6,
        ..Config::default()
    };
    let mut checked = 0;
    for s in &res.segments {
        let (t0, t1) = (
            rational_from_f64(s.t.0).unwrap(),
            rational_from_f64(s.t.1).unwrap(),
        );
        let xs = x[s.piece].restrict(&t0, &t1);
        let b = exact_bezier(&s.bezier).unwrap();
        // eᵃ = B − x (x elevated to B's degree, exactly)
        let xe = elevate_by(&xs, b.degree() - xs.degree());
        let ea = Bezier::new(
            b.points()
                .iter()
                .zip(xe.points())
                .map(|(p, q)| p.sub(q))
                .collect(),
        );
        // e: the arc of radius r from the left normal at t0 to the one at t1,
        // counter-clockwise when x turns left there (directions need not be unit)
        let n = |t: &Rational| {
            let d = xs.hodograph().eval(t);
            V2::new(-d.y.clone(), d.x.clone())
        };
        let (n0, n1) = (n(&q(0, 1)), n(&q(1, 1)));
        let left = cross(&n0, &n1) > q(0, 1);
        let arc = ArcDesc {
            center: V2::new(q(0, 1), q(0, 1)),
            radius: r.clone(),
            from: if left { n0.clone() } else { n1.clone() },
            to: if left { n1 } else { n0 },
        };
        let arc = ShapeDesc::arc(arc).unwrap();
        let lhs = hausdorff(
            &ShapeDesc::convolution(vec![xs.clone()], pen.m.clone(), 1).unwrap(),
            &ShapeDesc::curve(vec![b]).unwrap(),
            &cfg,
        )
        .unwrap();
        let rhs = hausdorff(&arc, &ShapeDesc::curve(vec![ea]).unwrap(), &cfg).unwrap();
        assert!(
            lhs.lo <= rhs.hi && rhs.lo <= lhs.hi,
            "(4.1) refuted on t ∈ {:?}: [{}, {}] vs [{}, {}]",
            s.t,
            lhs.lo,
            lhs.hi,
            rhs.lo,
            rhs.hi
        );
        checked += 1;
    }
    assert_eq!(checked, res.segments.len());
}

/// (4.1) with an elliptical pen is **false**: both sides certified on every
/// segment of a G² convolution of the test cubic (pen semi-axes 1/2, 1/5,
/// θ = π/6), the pen arc `e` as an exact elliptic arc (`certify::EllipseArc`);
/// on some segment the two enclosures are disjoint (a proven counterexample).
#[test]
fn equation_4_1_fails_with_an_ellipse() {
    use lncert::certify::{hausdorff, hausdorff_ellipse_arc, Config, EllipseArc};
    use lncert::offset::{convolve, exact_bezier, OffsetOptions};
    use lncert::offset::{Angle, Pen};
    use lncert::scalar::rational_from_f64;
    use lncert::shape::ShapeDesc;
    let x = lncert::shape::parse_curve(
        r#"{"bezier": [[-0.95, 0.7], [-0.3, 0.5], [0.3, -2.5], [0.9, -0.2]]}"#,
    )
    .unwrap();
    let pen = Pen::ellipse_within(
        &frac(1, 2),
        &frac(1, 5),
        &Angle::parse("pi/6").unwrap(),
        1e-6,
    )
    .unwrap();
    let cfg = Config {
        rel: 1e-6,
        ..Config::default()
    };
    let mut report = Vec::new();
    for side in [1i8, -1] {
        let res = convolve(
            &x,
            &pen,
            side,
            &OffsetOptions::new(q(0, 1), common::tol(2e-2)),
        )
        .unwrap();
        for s in &res.segments {
            let (t0, t1) = (
                rational_from_f64(s.t.0).unwrap(),
                rational_from_f64(s.t.1).unwrap(),
            );
            let xs = x[s.piece].restrict(&t0, &t1);
            let b = exact_bezier(&s.bezier).unwrap();
            let xe = elevate_by(&xs, b.degree() - xs.degree());
            let ea = Bezier::new(
                b.points()
                    .iter()
                    .zip(xe.points())
                    .map(|(p, q)| p.sub(q))
                    .collect(),
            );
            let m = &pen.m;
            let sg = Rational::from_integer(side.into());
            let dir = |t: &Rational| {
                let d = xs.hodograph().eval(t);
                let n = V2::new(-d.y.clone(), d.x.clone());
                V2::new(
                    (&m[0][0] * &n.x + &m[1][0] * &n.y) * &sg,
                    (&m[0][1] * &n.x + &m[1][1] * &n.y) * &sg,
                )
            };
            let (u0, u1) = (dir(&q(0, 1)), dir(&q(1, 1)));
            let ccw = cross(&u0, &u1) > q(0, 1);
            let arc = EllipseArc {
                center: V2::new(q(0, 1), q(0, 1)),
                m: m.clone(),
                from: if ccw { u0.clone() } else { u1.clone() },
                to: if ccw { u1 } else { u0 },
            };
            let lhs = hausdorff(
                &ShapeDesc::convolution(vec![xs.clone()], m.clone(), side).unwrap(),
                &ShapeDesc::curve(vec![b]).unwrap(),
                &cfg,
            )
            .unwrap();
            let rhs = hausdorff_ellipse_arc(&arc, &[ea], &cfg).unwrap();
            report.push((side, s.t, (lhs.lo, lhs.hi), (rhs.lo, rhs.hi)));
        }
    }
    let disjoint: Vec<_> = report
        .iter()
        .filter(|(_, _, l, r)| l.1 < r.0 || r.1 < l.0)
        .collect();
    for r in &disjoint {
        eprintln!(
            "(4.1) fails: side {}, t ∈ {:?}: d_H(x∗e, x∗eᵃ) ∈ {:?}, d_H(e, eᵃ) ∈ {:?}",
            r.0, r.1, r.2, r.3
        );
    }
    assert!(
        !disjoint.is_empty(),
        "no segment separates the two sides: {report:?}"
    );
}
