//! Seed 004 §3.1 — circular precision of the G²/C¹ offset approximant, machine-checked.
//!
//! The engine's kernel (`lncert::offset::kernels::{system, solve_alpha}`, eq. (3.2)–(3.4)) runs
//! on the *symbolic* moments `mᵢ = ∫₀¹ x′ B³ᵢ` of a circular arc, computed here
//! independently of the engine, and the result is compared with `α ≡ 1/γ` as identities of
//! rational functions over Q (see `proofs/004-circular-precision.md`).
//!
//! Symbols (variables of `RatFunc`): `x0 = γ` (radius), `x1 = L = 1/l` (`l` the angle of the
//! arc), `x2 = τ = tan(l/2)`, `x3 = σ = tan(t0/2)` (`t0` the start angle), with
//! `cos l = (1−τ²)/(1+τ²)`, `sin l = 2τ/(1+τ²)` and likewise for `t0`. The moments are
//! rational in `γ, 1/l, cos l, sin l, cos t0, sin t0` (integration by parts below), so every
//! identity here is an identity in `Q(γ, L, τ, σ)`, with `L` and `τ` independent symbols: it
//! then holds at `L = 1/l`, `τ = tan(l/2)` for every `l` where the denominators do not vanish.
//!
//! Arc: `x(t) = c0 + γ(cos θ(t), sin θ(t))`, `θ(t) = t0 + s·l·t` with `s = +1`
//! (counter-clockwise, left turning — the paper's case) or `s = −1` (clockwise). As a complex
//! number `x′(t) = s γ l · i e^{i t0} e^{i s l t}`; the centre `c0` does not enter.

mod common;
use common::symbolic::{assert_id, div, k, v};
use lncert::curve::V2;
use lncert::offset::kernels::{rot_cw, solve_alpha, system, G2Ends};
use lncert::poly::{identity_holds, RatFunc};
use lncert::scalar::{frac, rational_from_f64, Rational, Scalar, Sign};

const GAMMA: usize = 0;
const LINV: usize = 1;
const TAU: usize = 2;
const SIGMA: usize = 3;

fn assert_v2_id(lhs: &V2<RatFunc>, rhs: &V2<RatFunc>, what: &str) {
    assert_id(&lhs.x, &rhs.x, &format!("{what} (x)"));
    assert_id(&lhs.y, &rhs.y, &format!("{what} (y)"));
}
fn v2_holds(lhs: &V2<RatFunc>, rhs: &V2<RatFunc>) -> bool {
    identity_holds(&lhs.x, &rhs.x) && identity_holds(&lhs.y, &rhs.y)
}

// ---------------------------------------------------------------------------
// Complex numbers over RatFunc (independent of the engine)
// ---------------------------------------------------------------------------

#[derive(Clone, Debug)]
struct Cx {
    re: RatFunc,
    im: RatFunc,
}

impl Cx {
    fn new(re: RatFunc, im: RatFunc) -> Cx {
        Cx { re, im }
    }
    fn real(r: RatFunc) -> Cx {
        Cx::new(r, k(0, 1))
    }
    fn add(&self, o: &Cx) -> Cx {
        Cx::new(&self.re + &o.re, &self.im + &o.im)
    }
    fn sub(&self, o: &Cx) -> Cx {
        Cx::new(&self.re - &o.re, &self.im - &o.im)
    }
    fn mul(&self, o: &Cx) -> Cx {
        Cx::new(
            &self.re * &o.re - &self.im * &o.im,
            &self.re * &o.im + &self.im * &o.re,
        )
    }
    fn scale(&self, r: &RatFunc) -> Cx {
        Cx::new(&self.re * r, &self.im * r)
    }
    fn to_v2(&self) -> V2<RatFunc> {
        V2::new(self.re.clone(), self.im.clone())
    }
}

/// `e^{iφ}` from `t = tan(φ/2)`: `((1−t²)/(1+t²), 2t/(1+t²))`.
fn unit_from_half_tan(t: &RatFunc) -> Cx {
    let den = k(1, 1) + t.sqr();
    Cx::new(div(k(1, 1) - t.sqr(), den.clone()), div(t.scale(2), den))
}

// ---------------------------------------------------------------------------
// Bernstein polynomials with integer coefficients, and ∫ e^{at} p(t) dt
// ---------------------------------------------------------------------------

fn binom(n: i64, r: i64) -> i64 {
    (0..r).fold(1, |acc, j| acc * (n - j) / (j + 1))
}

/// `B³ᵢ(t) = C(3,i) tⁱ (1−t)^{3−i}` in the power basis (ascending coefficients).
fn bernstein3(i: usize) -> Vec<i64> {
    let mut c = vec![0i64; 4];
    let n = 3 - i as i64;
    for j in 0..=n {
        let sgn = if j % 2 == 0 { 1 } else { -1 };
        c[i + j as usize] += binom(3, i as i64) * binom(n, j) * sgn;
    }
    c
}
fn deriv(p: &[i64]) -> Vec<i64> {
    p.iter()
        .enumerate()
        .skip(1)
        .map(|(j, c)| c * j as i64)
        .collect()
}
fn at0(p: &[i64]) -> i64 {
    p.first().copied().unwrap_or(0)
}
fn at1(p: &[i64]) -> i64 {
    p.iter().sum()
}

/// `∫₀¹ e^{at} p(t) dt = Σ_{k=0}^{3} (−1)^k [p^{(k)}(1) e^a − p^{(k)}(0)] / a^{k+1}` for
/// `deg p ≤ 3` (repeated integration by parts; `p⁽⁴⁾ = 0`, so exact). `e_a = e^a`,
/// `inv_a = 1/a`.
fn exp_poly_integral(e_a: &Cx, inv_a: &Cx, p: &[i64]) -> Cx {
    assert!(p.len() <= 4, "degree ≤ 3");
    let mut acc = Cx::real(k(0, 1));
    let mut q = p.to_vec();
    let mut inv_pow = inv_a.clone();
    for kk in 0..4 {
        let bracket = e_a.scale(&k(at1(&q), 1)).sub(&Cx::real(k(at0(&q), 1)));
        let term = bracket.mul(&inv_pow);
        acc = if kk % 2 == 0 {
            acc.add(&term)
        } else {
            acc.sub(&term)
        };
        q = deriv(&q);
        inv_pow = inv_pow.mul(inv_a);
    }
    assert!(q.iter().all(|&c| c == 0), "p⁽⁴⁾ = 0");
    acc
}

// ---------------------------------------------------------------------------
// The circular arc
// ---------------------------------------------------------------------------

/// `x(t) = c0 + γ(cos θ, sin θ)`, `θ = t0 + turn·l·t`.
struct Arc {
    gamma: RatFunc,
    /// `L = 1/l`.
    linv: RatFunc,
    /// `e^{i t0}`.
    e_t0: Cx,
    /// `e^{i l}` (the angle `l > 0`).
    e_l: Cx,
    /// `+1` counter-clockwise (left turning), `−1` clockwise.
    turn: i64,
}

impl Arc {
    fn l(&self) -> RatFunc {
        div(k(1, 1), self.linv.clone())
    }
    /// `e^{i·turn·l}`.
    fn e_step(&self) -> Cx {
        Cx::new(self.e_l.re.clone(), self.e_l.im.scale(self.turn))
    }
    /// `x′(0) = turn·γ l · i e^{i t0}`.
    fn xp0(&self) -> Cx {
        Cx::new(k(0, 1), (&self.gamma * &self.l()).scale(self.turn)).mul(&self.e_t0)
    }
    /// `x′(1) = x′(0) e^{i·turn·l}`.
    fn xp1(&self) -> Cx {
        self.xp0().mul(&self.e_step())
    }
    /// `x″ = i·turn·l · x′`.
    fn xpp(&self, xp: &Cx) -> Cx {
        Cx::new(k(0, 1), self.l().scale(self.turn)).mul(xp)
    }
    /// `x(1) − x(0) = γ (e^{iθ(1)} − e^{iθ(0)})`.
    fn chord(&self) -> V2<RatFunc> {
        self.e_t0
            .mul(&self.e_step())
            .sub(&self.e_t0)
            .scale(&self.gamma)
            .to_v2()
    }
    /// `mᵢ = ∫₀¹ x′ B³ᵢ = x′(0) ∫₀¹ e^{a t} B³ᵢ(t) dt`, `a = i·turn·l`, `1/a = −i·turn·L`.
    fn moments(&self) -> [V2<RatFunc>; 4] {
        let inv_a = Cx::new(k(0, 1), self.linv.scale(-self.turn));
        let xp0 = self.xp0();
        std::array::from_fn(|i| {
            xp0.mul(&exp_poly_integral(&self.e_step(), &inv_a, &bernstein3(i)))
                .to_v2()
        })
    }
    /// The unit normals `N = R T` at the ends, written down from the geometry:
    /// `turn·(cos θ, sin θ)` (outward for a left-turning arc, inward otherwise).
    fn normals(&self) -> (V2<RatFunc>, V2<RatFunc>) {
        let t = k(self.turn, 1);
        let n0 = self.e_t0.scale(&t).to_v2();
        let n1 = self.e_t0.mul(&self.e_step()).scale(&t).to_v2();
        (n0, n1)
    }
    /// Signed curvature `turn/γ`.
    fn kappa(&self) -> RatFunc {
        div(k(self.turn, 1), self.gamma.clone())
    }
    fn ends(&self) -> G2Ends<RatFunc> {
        let (n0, n1) = self.normals();
        G2Ends {
            n0,
            n1,
            alpha0: self.kappa(),
            alpha3: self.kappa(),
        }
    }
}

/// The symbolic arc: `γ`, `L`, `τ`, `σ` all symbols.
fn symbolic_arc(turn: i64) -> Arc {
    Arc {
        gamma: v(GAMMA),
        linv: v(LINV),
        e_t0: unit_from_half_tan(&v(SIGMA)),
        e_l: unit_from_half_tan(&v(TAU)),
        turn,
    }
}

/// The symbolic arc with a fixed start direction `e^{i t0}` (the chart `σ = tan(t0/2)`
/// misses `t0 = π`).
fn arc_with_start(turn: i64, e_t0: Cx) -> Arc {
    Arc {
        e_t0,
        ..symbolic_arc(turn)
    }
}

// ---------------------------------------------------------------------------
// Running solve_alpha symbolically
// ---------------------------------------------------------------------------

/// The engine's `solve_alpha` on the arc's symbolic end data and moments.
fn engine_alpha(arc: &Arc, m: &[V2<RatFunc>; 4]) -> Option<[RatFunc; 4]> {
    // `solve_alpha` declines only a zero (or, for an inexact arithmetic, an
    // undecided) `v₁ × v₂`; a nonconstant rational function is not zero.
    solve_alpha(&arc.ends(), m)
}

fn assert_alpha_constant(arc: &Arc, what: &str) {
    let alpha = engine_alpha(arc, &arc.moments())
        .unwrap_or_else(|| panic!("{what}: solve_alpha declined (v₁ × v₂ ≡ 0?)"));
    for (i, a) in alpha.iter().enumerate() {
        assert_id(a, &arc.kappa(), &format!("{what}: α{i} = turn/γ"));
    }
}

// ---------------------------------------------------------------------------
// Task 1: the arc's data, and circular precision through the engine
// ---------------------------------------------------------------------------

/// The checker can fail (as in `tests/identities.rs`), and the complex/integration helpers
/// are right: `Σ mᵢ = ∫₀¹ x′ = x(1) − x(0)` (since `Σ B³ᵢ = 1`), and the closed form of the
/// integral matches quadrature at `l = 1`, `t0 = 0`, `γ = 1` (τ = tan(1/2) rounded to a
/// rational; tolerance 1e-9).
#[test]
fn s004_moments_of_the_arc_are_right() {
    assert!(!identity_holds(
        &(v(0) + v(1)).sqr(),
        &(v(0).sqr() + v(1).sqr())
    ));
    for (i, want) in [[1, -3, 3, -1], [0, 3, -6, 3], [0, 0, 3, -3], [0, 0, 0, 1]]
        .iter()
        .enumerate()
    {
        assert_eq!(&bernstein3(i), want, "B³{i}");
    }
    for turn in [1, -1] {
        let arc = symbolic_arc(turn);
        let m = arc.moments();
        let sum = m.iter().skip(1).fold(m[0].clone(), |a, b| a.add(b));
        assert_v2_id(
            &sum,
            &arc.chord(),
            &format!("turn {turn}: Σ mᵢ = x(1) − x(0)"),
        );
    }
    // Quadrature: x′(t) = (−sin t, cos t) for γ = l = 1, t0 = 0, counter-clockwise.
    let tau = rational_from_f64((0.5f64).tan()).unwrap();
    let vals = [
        Rational::from_integer(1.into()),
        Rational::from_integer(1.into()),
        tau,
        Rational::from_integer(0.into()),
    ];
    let m = symbolic_arc(1).moments();
    let n = 2000;
    let h = 1.0 / n as f64;
    for (i, mi) in m.iter().enumerate() {
        let c = bernstein3(i);
        let b = |t: f64| c.iter().rev().fold(0.0, |a, &ck| a * t + ck as f64);
        let f = |t: f64, comp: usize| {
            let xp = if comp == 0 { -t.sin() } else { t.cos() };
            xp * b(t)
        };
        for (comp, got) in [&mi.x, &mi.y].into_iter().enumerate() {
            let simpson = (0..n)
                .map(|j| {
                    let (a, bb) = (j as f64 * h, (j + 1) as f64 * h);
                    (f(a, comp) + 4.0 * f(0.5 * (a + bb), comp) + f(bb, comp)) * h / 6.0
                })
                .sum::<f64>();
            let exact = got.eval(&vals).unwrap();
            let exact = Scalar::approx(&exact);
            assert!(
                (exact - simpson).abs() < 1e-9,
                "m{i}[{comp}]: closed form {exact} vs quadrature {simpson}"
            );
        }
    }
}

/// The end data: `N = R T` with `R` the clockwise quarter turn equals `turn·(cos θ, sin θ)`
/// (so `N = (x − c0)/γ` for the left-turning arc, as §3.1 says), `‖x′‖ = γ l`, and the
/// signed curvature `x′ × x″ / ‖x′‖³ = turn/γ` (eq. (3.8): `α0 = α3 = 1/γ` for the paper's
/// arc, `−1/γ` clockwise).
#[test]
fn s004_arc_end_data_are_r_t_and_signed_curvature() {
    for turn in [1, -1] {
        let arc = symbolic_arc(turn);
        let (n0, n1) = arc.normals();
        let speed = &arc.gamma * &arc.l();
        for (end, xp, n) in [(0, arc.xp0(), n0), (1, arc.xp1(), n1)] {
            let xpv = xp.to_v2();
            assert_id(
                &xpv.norm2(),
                &speed.sqr(),
                &format!("turn {turn}: ‖x′({end})‖² = γ²l²"),
            );
            assert_id(
                &n.norm2(),
                &k(1, 1),
                &format!("turn {turn}: ‖N({end})‖ = 1"),
            );
            let rt = rot_cw(&xpv).scale(&div(k(1, 1), speed.clone()));
            assert_v2_id(&rt, &n, &format!("turn {turn}: R T({end}) = N({end})"));
            let kappa = div(
                xpv.cross(&arc.xpp(&xp).to_v2()),
                speed.sqr() * speed.clone(),
            );
            assert_id(
                &kappa,
                &arc.kappa(),
                &format!("turn {turn}: κ({end}) = turn/γ"),
            );
        }
    }
}

/// §3.1 (circular precision), the paper's case: for a left-turning arc the engine's
/// `solve_alpha` returns `α = (1/γ, 1/γ, 1/γ, 1/γ)` identically in `γ, L, τ, σ` (every
/// radius, angle and rotation), and also for `t0 = π` (the point the `σ` chart misses).
/// With `α ≡ 1/γ`, eq. (3.1) gives `Nᵃ(t) = N(0) + (x(t) − x(0))/γ = N(t)` because
/// `N = (x − c0)/γ`, so `Nᵃ ≡ N` and the offset `x + r Nᵃ` is exact.
#[test]
fn s004_circular_precision_left_turning_arc() {
    assert_alpha_constant(&symbolic_arc(1), "symbolic σ");
    assert_alpha_constant(&arc_with_start(1, Cx::real(k(-1, 1))), "t0 = π");
    // The boundary l = π (τ = ∞, missed by the τ chart): e^{il} = −1.
    let half_circle = Arc {
        e_l: Cx::real(k(-1, 1)),
        ..symbolic_arc(1)
    };
    assert_alpha_constant(&half_circle, "l = π");
}

/// Why circular precision holds, without any closed form: if `α0 = α3 = κ` and the moments
/// satisfy `N(1) − N(0) = κ Σ mᵢ`, then the right side of eq. (3.2) is
/// `v = N(1) − N(0) − κ(m₀ + m₃) = κ v₁ + κ v₂`, so by uniqueness (`v₁ × v₂ ≠ 0`)
/// `α1 = α2 = κ`. For a circle `N′ = κ x′` with `κ = 1/γ` constant, hence
/// `N(1) − N(0) = κ ∫x′ = κ Σ mᵢ`. Checked through the engine with `m₀, m₁, m₂, N(0), N(1), κ`
/// all symbols (11 variables) and `m₃ := (N(1) − N(0))/κ − m₀ − m₁ − m₂`.
#[test]
fn s004_constant_alpha_needs_only_the_sum_of_the_moments() {
    let p = |i: usize| V2::new(v(i), v(i + 1));
    let (m0, m1, m2, n0, n1) = (p(0), p(2), p(4), p(6), p(8));
    let kappa = v(10);
    let m3 = n1
        .sub(&n0)
        .scale(&div(k(1, 1), kappa.clone()))
        .sub(&m0)
        .sub(&m1)
        .sub(&m2);
    let e = G2Ends {
        n0,
        n1,
        alpha0: kappa.clone(),
        alpha3: kappa.clone(),
    };
    let m = [m0, m1, m2, m3];
    let alpha = solve_alpha(&e, &m).expect("v₁ × v₂ is not the zero function");
    for (i, a) in alpha.iter().enumerate() {
        assert_id(a, &kappa, &format!("α{i} = κ"));
    }
}

/// A clockwise (right-turning) arc, outside the paper's standing assumption: the engine
/// still reproduces the curvature, now signed, `α ≡ −1/γ` (and `Nᵃ ≡ N = −(x − c0)/γ`).
#[test]
fn s004_circular_precision_right_turning_arc_signed_curvature() {
    assert_alpha_constant(&symbolic_arc(-1), "clockwise, symbolic σ");
    assert_alpha_constant(&arc_with_start(-1, Cx::real(k(-1, 1))), "clockwise, t0 = π");
}

/// The test can fail: perturb one moment (`m₁.x += γL²`) and `α ≡ 1/γ` no longer holds.
#[test]
fn s004_circular_precision_fails_for_a_perturbed_moment() {
    let arc = symbolic_arc(1);
    let mut m = arc.moments();
    m[1].x = &m[1].x + &(&arc.gamma * &arc.linv.sqr());
    let alpha = engine_alpha(&arc, &m).expect("still solvable");
    assert!(
        !identity_holds(&alpha[1], &arc.kappa()) || !identity_holds(&alpha[2], &arc.kappa()),
        "perturbed moments still give α ≡ 1/γ"
    );
    // α0, α3 are end data, untouched.
    assert_id(&alpha[0], &arc.kappa(), "α0");
}

/// The engine on plain `RatFunc`: the sign of the symbolic `det = v₁ × v₂` is
/// `Unknown` (a nonconstant function), which `solve_alpha` must accept for an exact
/// arithmetic — and the result is `α ≡ 1/γ`. A zero `det` must be declined.
#[test]
fn s004_solve_alpha_on_plain_ratfunc_guard() {
    let arc = symbolic_arc(1);
    let (v1, v2, _) = system(&arc.ends(), &arc.moments());
    assert_eq!(Scalar::sign(&v1.cross(&v2)), Sign::Unknown);
    let alpha = solve_alpha(&arc.ends(), &arc.moments()).expect("symbolic det accepted");
    for (i, a) in alpha.iter().enumerate() {
        assert_id(a, &arc.kappa(), &format!("plain RatFunc: α{i}"));
    }
    // parallel columns: det ≡ 0 is declined
    let mut m = arc.moments();
    m[2] = m[1].clone();
    assert!(
        solve_alpha(&arc.ends(), &m).is_none(),
        "a zero det must be declined"
    );
}

/// The engine's `solve_alpha` in exact rational arithmetic (no wrapper) at specialisations
/// of the symbols — consistent ones are not needed, the identity holds for all values:
/// `α = (turn/γ, …)` exactly, both orientations.
#[test]
fn s004_circular_precision_rational_specialisations() {
    let q = |p: i64, r: i64| -> Rational { frac(p, r) };
    let mut checked = 0;
    for turn in [1, -1] {
        let arc = symbolic_arc(turn);
        let e = arc.ends();
        let m = arc.moments();
        for gamma in [q(1, 1), q(5, 2)] {
            for linv in [q(1, 1), q(3, 7), q(5, 1)] {
                for tau in [q(1, 5), q(1, 1), q(3, 1)] {
                    for sigma in [q(0, 1), q(-2, 3), q(7, 1)] {
                        let vals = [gamma.clone(), linv.clone(), tau.clone(), sigma];
                        let ev = |p: &V2<RatFunc>| {
                            V2::new(p.x.eval(&vals).unwrap(), p.y.eval(&vals).unwrap())
                        };
                        let er = G2Ends {
                            n0: ev(&e.n0),
                            n1: ev(&e.n1),
                            alpha0: e.alpha0.eval(&vals).unwrap(),
                            alpha3: e.alpha3.eval(&vals).unwrap(),
                        };
                        let mr: [V2<Rational>; 4] = std::array::from_fn(|i| ev(&m[i]));
                        let alpha = solve_alpha(&er, &mr).expect("det ≠ 0");
                        let want = q(turn, 1) / gamma.clone();
                        assert!(alpha.iter().all(|a| *a == want), "{vals:?}: {alpha:?}");
                        checked += 1;
                    }
                }
            }
        }
    }
    assert_eq!(checked, 108);
}

/// `det = v₁ × v₂ > 0` for `0 < l ≤ π` (so `solve_alpha` is defined on every arc of §3.1):
/// `v₁ × v₂ = ∫∫ x′(u) × x′(w) B³₁(u) B³₂(w) du dw` and `x′(u) × x′(w) = γ²l² sin(l(w − u))`
/// for the left-turning arc; symmetrising over `u < w`,
/// `v₁ × v₂ = γ²l² ∫∫_{u<w} sin(l(w−u)) K(u, w)`, with the kernel
/// `K = B³₁(u)B³₂(w) − B³₁(w)B³₂(u) = 9uw(1−u)(1−w)(w−u)` (checked here), positive on
/// `0 < u < w < 1`, and `sin(l(w−u)) > 0` there when `l ≤ π`. Also checked: the symbolic
/// `v₁ × v₂` equals `9γ² l⁻⁵ g(l)` with
/// `g = l³ sin l + l²(4 + 8 cos l) − 24 l sin l + 24(1 − cos l)` (Task 2's bracket).
#[test]
fn s004_det_kernel_is_positive_on_the_triangle() {
    let (u, w) = (v(0), v(1));
    let b = |i: usize, t: &RatFunc| {
        bernstein3(i)
            .iter()
            .rev()
            .fold(k(0, 1), |a, &c| a * t.clone() + k(c, 1))
    };
    let kernel = b(1, &u) * b(2, &w) - b(1, &w) * b(2, &u);
    let one = k(1, 1);
    let want = k(9, 1) * u.clone() * w.clone() * (&one - &u) * (&one - &w) * (&w - &u);
    assert_id(&kernel, &want, "K(u, w) = 9uw(1−u)(1−w)(w−u)");
}

// ---------------------------------------------------------------------------
// Task 2: the printed closed forms of §3.1 (left-turning arc)
// ---------------------------------------------------------------------------

/// The printed forms, with `N(0), N(1)`, `R` clockwise, `γ`, `L = 1/l`.
struct Printed {
    v1: V2<RatFunc>,
    v2: V2<RatFunc>,
    v: V2<RatFunc>,
    /// The bracket `N0×N1/l² + (4 − 8 N0×RN1)/l³ − 24 N0×N1/l⁴ + 24(1 + N0×RN1)/l⁵`.
    bracket: RatFunc,
}

fn printed(gamma: &RatFunc, linv: &RatFunc, n0: &V2<RatFunc>, n1: &V2<RatFunc>) -> Printed {
    let r = |p: &V2<RatFunc>| V2::new(p.y.clone(), -p.x.clone()); // R(x, y) = (y, −x)
    let (l1, l2) = (linv.clone(), linv.sqr());
    let (l3, l4) = (&l2 * linv, l2.sqr());
    let l5 = &l4 * linv;
    let s = |c: i64, p: &V2<RatFunc>, lk: &RatFunc| p.scale(&(k(c, 1) * lk.clone()));
    let three_g = gamma.scale(3);
    let d = n0.sub(n1);
    // v1 = 3γ( RN0/l − (4N0 + 2N1)/l² − 6R(N0 − N1)/l³ )
    let v1 = s(1, &r(n0), &l1)
        .sub(&s(4, n0, &l2).add(&s(2, n1, &l2)))
        .sub(&s(6, &r(&d), &l3))
        .scale(&three_g);
    // v2 = 3γ( RN1/l + (2N0 + 4N1)/l² + 6R(N0 − N1)/l³ )
    let v2 = s(1, &r(n1), &l1)
        .add(&s(2, n0, &l2).add(&s(4, n1, &l2)))
        .add(&s(6, &r(&d), &l3))
        .scale(&three_g);
    // v = 3( R(N0 + N1)/l − 2(N0 − N1)/l² )
    let v = s(1, &r(&n0.add(n1)), &l1)
        .sub(&s(2, &d, &l2))
        .scale(&k(3, 1));
    let c = n0.cross(n1);
    let cr = n0.cross(&r(n1));
    let bracket = c.clone() * l2 + (k(4, 1) - cr.scale(8)) * l3 - c.scale(24) * l4
        + (k(1, 1) + cr).scale(24) * l5;
    Printed { v1, v2, v, bracket }
}

fn printed_for(arc: &Arc) -> Printed {
    let (n0, n1) = arc.normals();
    printed(&arc.gamma, &arc.linv, &n0, &n1)
}

/// §3.1, printed `v₁ = 3γ(RN(0)/l − (4N(0) + 2N(1))/l² − 6R(N(0) − N(1))/l³)`:
/// holds (against the independent moment `m₁` and the engine's `system`).
#[test]
fn s004_3_1_printed_v1() {
    let arc = symbolic_arc(1);
    let m = arc.moments();
    let p = printed_for(&arc);
    assert_v2_id(&m[1], &p.v1, "v₁ = m₁ (printed)");
    let (v1, _, _) = system(&arc.ends(), &m);
    assert_v2_id(&v1, &p.v1, "engine v₁ (printed)");
}

/// §3.1, printed `v₂ = 3γ(RN(1)/l + (2N(0) + 4N(1))/l² + 6R(N(0) − N(1))/l³)`: holds.
#[test]
fn s004_3_1_printed_v2() {
    let arc = symbolic_arc(1);
    let m = arc.moments();
    let p = printed_for(&arc);
    assert_v2_id(&m[2], &p.v2, "v₂ = m₂ (printed)");
    let (_, v2, _) = system(&arc.ends(), &m);
    assert_v2_id(&v2, &p.v2, "engine v₂ (printed)");
}

/// §3.1, printed `v = 3(R(N(0) + N(1))/l − 2(N(0) − N(1))/l²)`: holds, for
/// `v = N(1) − N(0) − α0 m₀ − α3 m₃` with `α0 = α3 = 1/γ` (both from the independent
/// moments and from the engine's `system`). Also `v = (m₁ + m₂)/γ` (from `Σ mᵢ = γ(N(1) − N(0))`).
#[test]
fn s004_3_1_printed_v() {
    let arc = symbolic_arc(1);
    let m = arc.moments();
    let p = printed_for(&arc);
    let (n0, n1) = arc.normals();
    let ig = div(k(1, 1), arc.gamma.clone());
    let v_direct = n1.sub(&n0).sub(&m[0].scale(&ig)).sub(&m[3].scale(&ig));
    assert_v2_id(&v_direct, &p.v, "v (printed)");
    let (_, _, v_engine) = system(&arc.ends(), &m);
    assert_v2_id(&v_engine, &p.v, "engine v (printed)");
    assert_v2_id(&m[1].add(&m[2]).scale(&ig), &p.v, "v = (m₁ + m₂)/γ");
}

/// §3.1, printed `v₁ × v₂ = 9γ²(N0×N1/l² + (4 − 8 N0×RN1)/l³ − 24 N0×N1/l⁴
/// + 24(1 + N0×RN1)/l⁵)`: holds. With `N0 × N1 = sin l` and `N0 × RN1 = −cos l` the bracket
/// is `l⁻⁵ g(l)`, `g = l³ sin l + l²(4 + 8 cos l) − 24 l sin l + 24(1 − cos l)`.
#[test]
fn s004_3_1_printed_v1_cross_v2() {
    let arc = symbolic_arc(1);
    let m = arc.moments();
    let p = printed_for(&arc);
    let det = m[1].cross(&m[2]);
    assert_id(
        &det,
        &(k(9, 1) * arc.gamma.sqr() * p.bracket.clone()),
        "v₁ × v₂ (printed)",
    );
    let (n0, n1) = arc.normals();
    let r = |q: &V2<RatFunc>| V2::new(q.y.clone(), -q.x.clone());
    assert_id(&n0.cross(&n1), &arc.e_l.im, "N0 × N1 = sin l");
    assert_id(
        &n0.cross(&r(&n1)),
        &-arc.e_l.re.clone(),
        "N0 × RN1 = −cos l",
    );
    let (s, c, l) = (arc.e_l.im.clone(), arc.e_l.re.clone(), arc.l());
    let g = l.sqr() * l.clone() * s.clone() + l.sqr() * (k(4, 1) + c.scale(8))
        - k(24, 1) * l.clone() * s
        + (k(1, 1) - c).scale(24);
    let l5 = l.sqr().sqr() * l;
    assert_id(&p.bracket, &div(g, l5), "bracket = g(l)/l⁵");
}

/// §3.1, printed `v × v₂ = v₁ × v = 9γ(same bracket)`: both hold, hence
/// `α1 = (v × v₂)/(v₁ × v₂) = 1/γ = (v₁ × v)/(v₁ × v₂) = α2` (eq. (3.4)).
#[test]
fn s004_3_1_printed_v_cross_v2_and_v1_cross_v() {
    let arc = symbolic_arc(1);
    let m = arc.moments();
    let p = printed_for(&arc);
    let (v1, v2, v) = system(&arc.ends(), &m);
    let want = k(9, 1) * arc.gamma.clone() * p.bracket.clone();
    assert_id(&v.cross(&v2), &want, "v × v₂ (printed)");
    assert_id(&v1.cross(&v), &want, "v₁ × v (printed)");
}

/// Outside the paper's assumption: for a right-turning arc (with its own `N = R T`, now
/// inward) the printed `v₁, v₂, v, v₁ × v₂` are false as printed, and all hold with the
/// *signed* radius `−γ = 1/κ` and signed angle `−l` in place of `γ, l` (i.e. `γ → −γ`,
/// `L → −L`). Not an erratum — the paper assumes left turning — but the scope of §3.1's
/// formulas.
#[test]
fn s004_3_1_printed_forms_right_turning_need_signed_radius_and_angle() {
    let arc = symbolic_arc(-1);
    let m = arc.moments();
    let (n0, n1) = arc.normals();
    let lit = printed(&arc.gamma, &arc.linv, &n0, &n1);
    assert!(
        !v2_holds(&m[1], &lit.v1),
        "printed v₁ holds for a right-turning arc"
    );
    assert!(
        !v2_holds(&m[2], &lit.v2),
        "printed v₂ holds for a right-turning arc"
    );
    let (_, _, v) = system(&arc.ends(), &m);
    assert!(
        !v2_holds(&v, &lit.v),
        "printed v holds for a right-turning arc"
    );
    let signed = printed(&-arc.gamma.clone(), &-arc.linv.clone(), &n0, &n1);
    assert_v2_id(&m[1], &signed.v1, "v₁ with γ → −γ, l → −l");
    assert_v2_id(&m[2], &signed.v2, "v₂ with γ → −γ, l → −l");
    assert_v2_id(&v, &signed.v, "v with γ → −γ, l → −l");
    let det = m[1].cross(&m[2]);
    assert!(
        !identity_holds(&det, &(k(9, 1) * arc.gamma.sqr() * lit.bracket.clone())),
        "printed v₁ × v₂ holds for a right-turning arc"
    );
    assert_id(
        &det,
        &(k(9, 1) * arc.gamma.sqr() * signed.bracket.clone()),
        "v₁ × v₂ with γ → −γ, l → −l",
    );
}
