//! Machine-checked algebraic identities that the seeds' proofs rely on. The
//! engine's own generic kernels run on symbolic scalars ([`RatFunc`], rational
//! functions over Q) and are compared with the printed formulas as identities
//! of rational functions (cross-multiplied numerators equal as polynomials).
//! Each test names the proof obligation it discharges (see `proofs/`).

mod common;
use common::symbolic::{assert_id, div, k, v};
use lncert::curve::V2;
use lncert::ln::circle::ArcApprox;
use lncert::ln::cubic::{deltas_from_rho, deltas_from_tau, LnFrame, Tau};
use lncert::ln::hermite::{convolve_normal_forms, normal_form, HermiteData};
use lncert::ln::pair::{convolution_deltas, CompatiblePair};
use lncert::poly::{identity_holds, poly_in, Poly, RatFunc};
use lncert::scalar::Scalar;

fn symbolic_frame(first_var: usize) -> LnFrame<RatFunc> {
    let p = |i: usize| V2::new(v(first_var + i), v(first_var + i + 1));
    LnFrame::new_unchecked(p(0), p(2), p(4))
}

/// The checker itself can fail: (x + y)² ≠ x² + y².
#[test]
fn identity_checker_rejects_a_false_identity() {
    let (x, y) = (v(0), v(1));
    assert!(!identity_holds(
        &(x.clone() + y.clone()).sqr(),
        &(x.sqr() + y.sqr())
    ));
}

/// Seed 000 §3 (Prop 3.1): with δ from eq. (1),
/// b'(t) = -6(t-τ){(3τ-2)∇b0(1-t) + (3τ-1)∇b1 t} / ((3τ-1)(3τ-2)).
#[test]
fn s000_prop_3_1_hodograph_factorisation() {
    let f = symbolic_frame(0);
    let (tau, t) = (v(6), v(7));
    let (d0, d1) = deltas_from_tau(&Tau::Finite(tau.clone())).unwrap();
    let (hx, hy) = f.cubic(&d0, &d1).hodograph().power_coords();
    let a = tau.scale(3) - k(2, 1);
    let b = tau.scale(3) - k(1, 1);
    let den = a.clone() * b.clone();
    let rhs = |g0: RatFunc, g1: RatFunc| {
        let inner = a.clone() * g0 * (k(1, 1) - t.clone()) + b.clone() * g1 * t.clone();
        div(k(-6, 1) * (t.clone() - tau.clone()) * inner, den.clone())
    };
    assert_id(&poly_in(7, &hx), &rhs(f.d0().x, f.d1().x), "x'(t)");
    assert_id(&poly_in(7, &hy), &rhs(f.d0().y, f.d1().y), "y'(t)");
}

/// Seed 000 eq. (5) from eq. (1) with τ = (2ρ-1)/(3(ρ-1)) (Lemma 4.1's proof),
/// and ρ(τ) = (3τ-1)/(3τ-2) = 1 + 1/(3τ-2) (Fig. 3).
#[test]
fn s000_eq5_and_lemma_4_1_maps() {
    let rho = v(0);
    let tau = div(rho.scale(2) - k(1, 1), (rho.clone() - k(1, 1)).scale(3));
    let (a0, a1) = deltas_from_tau(&Tau::Finite(tau.clone())).unwrap();
    let (b0, b1) = deltas_from_rho(&rho).unwrap();
    assert_id(&a0, &b0, "δ0");
    assert_id(&a1, &b1, "δ1");
    let t = v(1);
    let rho_t = div(t.scale(3) - k(1, 1), t.scale(3) - k(2, 1));
    assert_id(
        &rho_t,
        &(k(1, 1) + div(k(1, 1), t.scale(3) - k(2, 1))),
        "ρ(τ)",
    );
    // ρ - 1/2 = 3τ/(2(3τ-2)) and 2 - ρ = 3(τ-1)/(3τ-2): both positive iff τ ∉ [0,1].
    assert_id(
        &(rho_t.clone() - k(1, 2)),
        &div(t.scale(3), (t.scale(3) - k(2, 1)).scale(2)),
        "ρ - 1/2",
    );
    assert_id(
        &(k(2, 1) - rho_t),
        &div((t.clone() - k(1, 1)).scale(3), t.scale(3) - k(2, 1)),
        "2 - ρ",
    );
}

/// Seed 000 Prop 4.2/4.4: for a compatible pair (∇b0ʳ = c0∇b0ˡ, ∇b1ʳ = c1∇b1ˡ)
/// and any ρl, the two hodographs are parallel, the convolution's hodograph is
/// parallel to them, and its control points satisfy b1 = b0 + δ0(bm - b0),
/// b2 = b3 + δ1(bm - b3) with the δ's of `convolution_deltas`.
#[test]
fn s000_pair_and_convolution_identities() {
    let l = symbolic_frame(0);
    let (c0, c1, rho) = (v(6), v(7), v(8));
    let b0r = V2::new(v(9), v(10));
    let bmr = b0r.add(&l.d0().scale(&c0));
    let b3r = bmr.add(&l.d1().scale(&c1));
    let r = LnFrame::new_unchecked(b0r, bmr, b3r);
    let pair = CompatiblePair {
        left: l.clone(),
        right: r.clone(),
        c0: c0.clone(),
        c1: c1.clone(),
    };
    let p = pair.curves_for_rho(&rho).unwrap();
    let (lx, ly) = p.left.hodograph().power_coords();
    let (rx, ry) = p.right.hodograph().power_coords();
    let cross = lx.mul(&ry).sub(&ly.mul(&rx));
    assert_id(&poly_in(11, &cross), &k(0, 1), "b'l × b'r = 0");
    let (d0, d1) = convolution_deltas(&c0, &c1, &p.deltas_left, &p.deltas_right).unwrap();
    let pts: Vec<V2<RatFunc>> = p
        .left
        .points()
        .iter()
        .zip(p.right.points())
        .map(|(a, b)| a.add(b))
        .collect();
    let bm = l.bm.add(&r.bm);
    let b1 = pts[0].add(&bm.sub(&pts[0]).scale(&d0));
    let b2 = pts[3].add(&bm.sub(&pts[3]).scale(&d1));
    for (got, want, what) in [(&pts[1], &b1, "b1"), (&pts[2], &b2, "b2")] {
        assert_id(&got.x, &want.x, what);
        assert_id(&got.y, &want.y, what);
    }
}

/// Seed 003 system (1) and Prop 2.1: a2, a3 interpolate; t* = (u/3)(2ux1+3y1)/(ux1+2y1).
#[test]
fn s003_prop_2_1_system_and_singular_parameter() {
    let h = HermiteData {
        x1: v(0),
        y1: v(1),
        u: v(2),
    };
    let (a2, a3) = h.cubic_coefficients();
    let u = v(2);
    assert_id(
        &(k(-2, 1) * a2.clone() * u.clone() - k(3, 1) * a3.clone() * u.sqr()),
        &v(0),
        "-2a2u - 3a3u² = x1",
    );
    assert_id(
        &(a2.clone() * u.sqr() + k(2, 1) * a3.clone() * u.sqr() * u.clone()),
        &v(1),
        "a2u² + 2a3u³ = y1",
    );
    let ts = h.cubic_singular_parameter().unwrap();
    let ux = u.clone() * v(0);
    let printed = div(
        u.clone() * (ux.scale(2) + v(1).scale(3)),
        (ux + v(1).scale(2)).scale(3),
    );
    assert_id(&ts, &printed, "t*");
}

/// Seed 003 eq. (3), (4): the quartic interpolates (system (2)) and
/// g4 = u⁴ f''/2; g4(0) = a2u⁴, g4(u) = u⁴(a2 - α2).
#[test]
fn s003_eq3_eq4_g4() {
    let h = HermiteData {
        x1: v(0),
        y1: v(1),
        u: v(2),
    };
    let (a2, u, t) = (v(3), v(2), v(4));
    let f = h.quartic_f(&a2);
    let (x, y) = normal_form(&f);
    assert_id(&x.eval(&u), &v(0), "K(u).x = x1");
    assert_id(&y.eval(&u), &v(1), "K(u).y = y1");
    assert_id(
        &f.derivative().eval(&u),
        &-v(0),
        "f'(u) = -x1 (normal (u,1))",
    );
    let g4 = h.g4(&a2);
    let u4 = u.sqr().sqr();
    let fpp = f.derivative().derivative();
    assert_id(
        &poly_in(4, &g4),
        &div(u4.clone() * poly_in(4, &fpp), k(2, 1)),
        "g4 = u⁴ f''/2",
    );
    assert_id(&g4.eval(&k(0, 1)), &(a2.clone() * u4.clone()), "g4(0)");
    assert_id(&g4.eval(&u), &(u4 * (a2 - h.alpha2())), "g4(u)");
    let _ = t;
}

/// Seed 003 Prop 3.1: disc(g4) = 3u²·D (printed D), disc_a2(D) = 16u⁴x1²·D1,
/// D1 = -2(u² - 6us + 6s²), and the printed α0, α1 are D's roots (Vieta).
#[test]
fn s003_prop_3_1_discriminants() {
    let h = HermiteData {
        x1: v(0),
        y1: v(1),
        u: v(2),
    };
    let (a2, u, x1) = (v(3), v(2), v(0));
    let g = h.g4(&a2);
    let c = g.coeffs();
    let disc = c[1].sqr() - k(4, 1) * c[2].clone() * c[0].clone();
    assert_id(
        &disc,
        &(k(3, 1) * u.sqr() * h.discriminant_d(&a2)),
        "disc(g4) = 3u² D",
    );
    let (da, db, dc) = h.d_coefficients();
    let disc_d = db.sqr() - k(4, 1) * da.clone() * dc.clone();
    let u4 = u.sqr().sqr();
    assert_id(
        &disc_d,
        &(k(16, 1) * u4 * x1.sqr() * h.d1()),
        "disc(D) = 16u⁴x1² D1",
    );
    let s = h.s();
    assert_id(
        &h.d1(),
        &(k(-2, 1) * (u.sqr() - k(6, 1) * u.clone() * s.clone() + k(6, 1) * s.sqr())),
        "D1",
    );
    // α0 + α1 = -B/A, α0 α1 = C/A with α = (6s - 5u ∓ √D1) x1/(2u²).
    let kk = div(x1.clone(), u.sqr().scale(2));
    let vv = s.scale(6) - u.scale(5);
    assert_id(
        &(kk.clone() * vv.clone()).scale(2),
        &div(-db, da.clone()),
        "α0 + α1",
    );
    assert_id(&(kk.sqr() * (vv.sqr() - h.d1())), &div(dc, da), "α0 α1");
}

/// Seed 003 Prop 3.3: f(m) = m²(mβ + u²(u-m)²a2/x1)/(u⁴/x1), β = -(m(3s-2u) + u(3u-4s)).
#[test]
fn s003_prop_3_3_intercept() {
    let h = HermiteData {
        x1: v(0),
        y1: v(1),
        u: v(2),
    };
    let (a2, m) = (v(3), v(4));
    let b = h.b_from_a2(&m, &a2);
    let printed = h.beta_i(&m, &a2).unwrap();
    assert_id(&b, &printed, "b = f(m)");
    assert_id(
        &h.a2_from_b_symbolic(&m, &b).unwrap(),
        &a2,
        "a2(b(a2)) = a2",
    );
}

/// Seed 003 Prop 6.1: K_f + K_F = K_{f+F} for cubic f, F with symbolic coefficients.
#[test]
fn s003_prop_6_1_convolution() {
    let f = Poly::new(vec![v(0), v(1), v(2), v(3)]);
    let g = Poly::new(vec![v(4), v(5), v(6), v(7)]);
    let (cx, cy) = convolve_normal_forms(&f, &g);
    let ((fx, fy), (gx, gy)) = (normal_form(&f), normal_form(&g));
    assert_id(&poly_in(8, &cx), &poly_in(8, &fx.add(&gx)), "x");
    assert_id(&poly_in(8, &cy), &poly_in(8, &fy.add(&gy)), "y");
}

/// Seed 000 Prop 6.1 (appendix): g(s) = ca'(s)·ca(s) factors as
/// c · tan²α/κ² · s(1-s) · (3(κ-1)s - 2κ + 1) · (A s² + B s + C) with c = -4
/// (printed: 12 — an erratum in the constant only), and the
/// printed cubic bracket is (3(κ-1)s - 2κ + 1)(A s² + B s + C). The arc uses
/// cos α = (1-m²)/(1+m²), sin α = 2m/(1+m²) with m symbolic.
#[test]
fn s000_prop_6_1_g_factorisation() {
    let (m, kappa, s) = (v(0), v(1), v(2));
    let den = k(1, 1) + m.sqr();
    let arc = ArcApprox {
        cos_a: div(k(1, 1) - m.sqr(), den.clone()),
        sin_a: div(m.scale(2), den),
        kappa: kappa.clone(),
    };
    let ca = arc.cubic().unwrap();
    let (x, y) = ca.power_coords();
    let g = x.derivative().mul(&x).add(&y.derivative().mul(&y));
    let (a, b, c) = arc.abc();
    let sin2 = arc.sin2();
    let tan2 = div(sin2.clone(), arc.cos_a.sqr());
    let km1 = kappa.clone() - k(1, 1);
    let lin = k(3, 1) * km1.clone() * s.clone() - kappa.scale(2) + k(1, 1);
    let quad = a * s.sqr() + b * s.clone() + c;
    let factored = |c: i64| {
        div(k(c, 1) * tan2.clone(), kappa.sqr())
            * s.clone()
            * (k(1, 1) - s.clone())
            * lin.clone()
            * quad.clone()
    };
    // Erratum: the printed constant 12 tan²α/κ² is wrong; the factorisation
    // holds with -4 tan²α/κ² (same roots, so the proposition is unaffected).
    assert!(
        !identity_holds(&poly_in(2, &g), &factored(12)),
        "the printed constant 12 would be right"
    );
    assert_id(
        &poly_in(2, &g),
        &factored(-4),
        "g(s) = -4 tan²α/κ² s(1-s)(3(κ-1)s-2κ+1)(As²+Bs+C)",
    );
    // The printed cubic bracket, with the sign of the sin²α part of its
    // s-coefficient as a parameter: printed `-(...) - κ(13κ²-14κ+3)sin²α`
    // (erratum), correct `+κ(13κ²-14κ+3)sin²α`.
    let sq = km1.sqr();
    let bracket = |sign: i64| {
        (kappa.scale(2) - k(1, 1)) * (sq.clone() - kappa.sqr() * sin2.clone())
            - (k(7, 1) * kappa.clone() - k(5, 1)) * sq.clone() * s.clone()
            + k(sign, 1)
                * kappa.clone()
                * (k(13, 1) * kappa.sqr() - k(14, 1) * kappa.clone() + k(3, 1))
                * sin2.clone()
                * s.clone()
            - km1.clone()
                * ((kappa.scale(2) - k(7, 1)) * sq.clone()
                    + kappa.clone() * (k(23, 1) * kappa.clone() - k(13, 1)) * sin2.clone())
                * s.sqr()
            + k(3, 1)
                * sq.clone()
                * (sq.clone() + k(4, 1) * kappa.clone() * sin2.clone())
                * s.sqr()
                * s.clone()
    };
    assert!(
        !identity_holds(&bracket(-1), &(lin.clone() * quad.clone())),
        "printed sign would be right"
    );
    let printed = bracket(1);
    assert_id(
        &printed,
        &(lin * quad),
        "corrected cubic = (3(κ-1)s - 2κ + 1)(As² + Bs + C)",
    );
}
