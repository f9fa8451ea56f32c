//! Seed 004: the G²/C¹ offset approximant from an approximated normal field.
//!
//! For a regular curve `x : [0, 1] → R²` with unit normal `N = R T` (`R` the
//! clockwise quarter turn, as in the paper, eq. (2.1)) the approximant of the
//! normal field is (eq. (3.1))
//!
//! ```text
//! Nᵃ(t) = N(0) + ∫₀ᵗ x′(u) α(u) du,   α = Σᵢ αᵢ B³ᵢ  (a cubic)
//! ```
//!
//! so `(Nᵃ)′ ∥ x′` and the offset approximant `x + r Nᵃ` is a polynomial of
//! degree `n + 3` when `x` has degree `n` (§3.2). The coefficients:
//!
//! * `α₀ = κ(0)`, `α₃ = κ(1)` (eq. (3.8), signed curvature) — `G²` at the ends;
//! * `α₁, α₂` from `Nᵃ(1) = N(1)`, the 2×2 system `v₁ α₁ + v₂ α₂ = v` (eq. (3.2)–(3.4)),
//!   `vᵢ = ∫ x′ B³ᵢ`, `v = N(1) − N(0) − α₀ ∫ x′ B³₀ − α₃ ∫ x′ B³₃`.
//!
//! The kernels are split so that each part runs in any arithmetic:
//! [`moments`] (the integrals `mᵢ = ∫₀¹ x′ B³ᵢ`, exact closed Bernstein forms for
//! Bézier curves), [`solve_alpha`] (eq. (3.4) from end data and moments — the
//! identity tests run it on symbolic moments of a circular arc to prove circular
//! precision, §3.1), and [`normal_approximant`] (the Bernstein control points of
//! `Nᵃ`, degree `n + 3`).
//!
//! The construction is a *heuristic* in the sense of lncert: its output is
//! checked afterwards by a certified Hausdorff bound ([`crate::certify`]), so
//! float rounding in the construction can only cost tightness, never soundness.

use crate::curve::{bernstein_product, Bezier, V2};
use crate::scalar::{Scalar, ScalarSqrt, Sign};

/// End data of seed 004's construction, in the paper's orientation: `n0`,
/// `n1` are the unit normals `N = R T` (clockwise rotation of the unit tangent)
/// at `t = 0, 1`, `alpha0`, `alpha3` the signed curvatures there (eq. (3.8)).
#[derive(Clone, Debug, PartialEq)]
pub struct G2Ends<S> {
    /// Unit normal `N(0) = R T(0)` at the start.
    pub n0: V2<S>,
    /// Unit normal `N(1) = R T(1)` at the end.
    pub n1: V2<S>,
    /// `α₀ = κ(0)`: the signed curvature at the start.
    pub alpha0: S,
    /// `α₃ = κ(1)`: the signed curvature at the end.
    pub alpha3: S,
}

/// The clockwise quarter turn `R (x, y) = (y, −x)` of seed 004 eq. (2.1).
pub fn rot_cw<S: Scalar>(v: &V2<S>) -> V2<S> {
    V2::new(v.y.clone(), -v.x.clone())
}

/// The moments `mᵢ = ∫₀¹ x′(t) B³ᵢ(t) dt`, `i = 0..3`, of a Bézier curve, from
/// the closed Bernstein forms of seed 004 §3.2: the product `x′ B³ᵢ` has degree
/// `n + 2` and every Bernstein polynomial of degree `n + 2` integrates to
/// `1/(n + 3)`. Exact for rationals.
///
/// # Examples
/// ```
/// use lncert::offset::kernels::moments;
/// use lncert::curve::{Bezier, V2};
/// // The moments sum to ∫ x′ = x(1) − x(0).
/// let x = Bezier::new(vec![V2::new(0.0, 0.0), V2::new(1.0, 2.0), V2::new(3.0, 1.0)]);
/// let m = moments(&x);
/// let s = m.iter().fold(V2::new(0.0, 0.0), |a, b| a.add(b));
/// assert!((s.x - 3.0).abs() < 1e-15 && (s.y - 1.0).abs() < 1e-15);
/// ```
pub fn moments<S: Scalar>(x: &Bezier<S>) -> [V2<S>; 4] {
    let h = x.hodograph();
    let (hx, hy) = h.coords();
    let n3 = S::from_i64(h.degree() as i64 + 4); // (n − 1) + 3 + 1 = n + 3
    let inv = n3.recip().expect("n + 3 > 0");
    std::array::from_fn(|i| {
        let e: Vec<S> = (0..4)
            .map(|k| if k == i { S::one() } else { S::zero() })
            .collect();
        let sum = |c: &[S]| {
            bernstein_product(c, &e)
                .into_iter()
                .fold(S::zero(), |a, b| a + b)
                * inv.clone()
        };
        V2::new(sum(&hx), sum(&hy))
    })
}

/// The end data of a Bézier curve: unit normals `R T` and signed curvatures at
/// both ends. `None` if an end derivative is (or may be) zero.
///
/// # Examples
/// ```
/// use lncert::offset::kernels::ends;
/// use lncert::curve::{Bezier, V2};
/// // A quadratic turning left: positive curvature, N = R T points right.
/// let x = Bezier::new(vec![V2::new(0.0, 0.0), V2::new(1.0, 0.0), V2::new(1.0, 1.0)]);
/// let e = ends(&x).unwrap();
/// assert_eq!(e.n0, V2::new(0.0, -1.0));
/// assert!(e.alpha0 > 0.0 && e.alpha3 > 0.0);
/// ```
pub fn ends<S: ScalarSqrt>(x: &Bezier<S>) -> Option<G2Ends<S>> {
    let d1 = x.hodograph();
    let d2 = d1.hodograph();
    let last = d1.degree();
    let at = |c: &Bezier<S>, end: bool| {
        let p = c.points();
        if end {
            p[p.len() - 1].clone()
        } else {
            p[0].clone()
        }
    };
    let one_end = |end: bool| -> Option<(V2<S>, S)> {
        let v = at(&d1, end);
        // x″ at the end: the hodograph of the hodograph (a zero point for lines).
        let a = if last == 0 { V2::zero() } else { at(&d2, end) };
        let len2 = v.norm2();
        if len2.sign() != Sign::Positive {
            return None;
        }
        let len = len2.sqrt()?;
        let inv = len.recip()?;
        let n = rot_cw(&v).scale(&inv);
        let kappa = v.cross(&a) * inv.clone() * inv.clone() * inv;
        Some((n, kappa))
    };
    let (n0, alpha0) = one_end(false)?;
    let (n1, alpha3) = one_end(true)?;
    Some(G2Ends {
        n0,
        n1,
        alpha0,
        alpha3,
    })
}

/// The right-hand side and columns of eq. (3.2): `(v₁, v₂, v)`.
pub fn system<S: Scalar>(e: &G2Ends<S>, m: &[V2<S>; 4]) -> (V2<S>, V2<S>, V2<S>) {
    let v =
        e.n1.sub(&e.n0)
            .sub(&m[0].scale(&e.alpha0))
            .sub(&m[3].scale(&e.alpha3));
    (m[1].clone(), m[2].clone(), v)
}

/// Eq. (3.4): `α₁ = (v × v₂)/(v₁ × v₂)`, `α₂ = (v₁ × v)/(v₁ × v₂)`, with
/// `α₀, α₃` from the end data. `None` when `v₁ × v₂` is (or may be) zero — by
/// Prop 3.1 it is not for a convex curve whose Gauss map is shorter than π.
///
/// # Examples
/// ```
/// use lncert::offset::kernels::{ends, moments, solve_alpha};
/// use lncert::curve::{Bezier, V2};
/// let x = Bezier::new(vec![V2::new(0.0, 0.0), V2::new(1.0, 0.0), V2::new(1.0, 1.0)]);
/// let a = solve_alpha(&ends(&x).unwrap(), &moments(&x)).unwrap();
/// assert!(a.iter().all(|v| v.is_finite() && *v > 0.0));
/// ```
pub fn solve_alpha<S: Scalar>(e: &G2Ends<S>, m: &[V2<S>; 4]) -> Option<[S; 4]> {
    let (v1, v2, v) = system(e, m);
    let det = v1.cross(&v2);
    // Zero: singular. Unknown: an enclosure that may be zero — undecided; a
    // symbolic (exact) nonconstant function is not the zero function, and
    // `div` rejects a zero divisor in every arithmetic.
    match det.sign() {
        Sign::Zero => return None,
        Sign::Unknown if !S::EXACT => return None,
        _ => {}
    }
    let a1 = v.cross(&v2).div(&det)?;
    let a2 = v1.cross(&v).div(&det)?;
    Some([e.alpha0.clone(), a1, a2, e.alpha3.clone()])
}

/// The control points of `Nᵃ(t) = n0 + ∫₀ᵗ x′ α` (degree `n + 3`): the
/// hodograph `x′ α` has Bernstein coefficients `cₖ` of degree `n + 2`, and the
/// antiderivative's control points are `P₀ = n0`, `Pₖ₊₁ = Pₖ + cₖ/(n + 3)`.
///
/// # Examples
/// ```
/// use lncert::offset::kernels::normal_approximant;
/// use lncert::curve::{Bezier, V2};
/// // α ≡ 0: the normal field stays at n0.
/// let x = Bezier::new(vec![V2::new(0.0, 0.0), V2::new(1.0, 0.0)]);
/// let n = normal_approximant(&x, &V2::new(0.0, -1.0), &[0.0; 4]);
/// assert_eq!(n.degree(), 4);
/// assert!(n.points().iter().all(|p| *p == V2::new(0.0, -1.0)));
/// ```
pub fn normal_approximant<S: Scalar>(x: &Bezier<S>, n0: &V2<S>, alpha: &[S; 4]) -> Bezier<S> {
    let h = x.hodograph();
    let (hx, hy) = h.coords();
    let cx = bernstein_product(&hx, alpha);
    let cy = bernstein_product(&hy, alpha);
    let inv = S::from_i64(cx.len() as i64).recip().expect("n + 3 > 0");
    let mut pts = vec![n0.clone()];
    for (a, b) in cx.into_iter().zip(cy) {
        let last = pts[pts.len() - 1].clone();
        pts.push(last.add(&V2::new(a, b).scale(&inv)));
    }
    Bezier::new(pts)
}

/// `x` written with `k` more control points (degree elevation, exact).
pub fn elevate_by<S: Scalar>(x: &Bezier<S>, k: usize) -> Bezier<S> {
    (0..k).fold(x.clone(), |c, _| c.elevate())
}

/// Seed 004's offset approximant `x + d N_Lᵃ` of degree `n + 3` for the signed
/// distance `d` (`d > 0` to the **left**, lncert's convention: the left normal
/// `N_L = −R T`, so this is the paper's `x + r Nᵃ` with `r = −d`).
///
/// `None` if the end data are undefined (a zero end derivative) or eq. (3.4)
/// is singular; [`offset_approximant_f64`] adds the float fallbacks.
///
/// # Examples
/// ```
/// use lncert::offset::kernels::offset_approximant;
/// use lncert::curve::{Bezier, V2};
/// // A quarter-circle-like cubic offset by 1/10 to the left: degree 3 + 3, and the
/// // ends interpolate x + d N exactly in exact arithmetic (here to float rounding).
/// let x = Bezier::new(vec![V2::new(1.0, 0.0), V2::new(1.0, 0.55), V2::new(0.55, 1.0), V2::new(0.0, 1.0)]);
/// let o = offset_approximant(&x, &0.1).unwrap();
/// assert_eq!(o.degree(), 6);
/// assert!((o.points()[0].x - 0.9).abs() < 1e-15 && o.points()[0].y.abs() < 1e-15);
/// // a straight segment makes (3.4) singular (v₁ ∥ v₂): see `offset_approximant_f64`
/// let line = Bezier::new(vec![V2::new(0.0, 0.0), V2::new(2.0, 0.0)]);
/// assert!(offset_approximant(&line, &0.5).is_none());
/// ```
pub fn offset_approximant<S: ScalarSqrt>(x: &Bezier<S>, d: &S) -> Option<Bezier<S>> {
    let e = ends(x)?;
    let alpha = solve_alpha(&e, &moments(x))?;
    Some(combine(x, &e.n0, &alpha, d))
}

fn combine<S: Scalar>(x: &Bezier<S>, n0: &V2<S>, alpha: &[S; 4], d: &S) -> Bezier<S> {
    let na = normal_approximant(x, n0, alpha);
    let xe = elevate_by(x, 3);
    let r = -d.clone();
    Bezier::new(
        xe.points()
            .iter()
            .zip(na.points())
            .map(|(p, q)| p.add(&q.scale(&r)))
            .collect(),
    )
}

/// Relative size of `v₁ × v₂` against `|v₁| |v₂|` below which the float path
/// treats eq. (3.4) as singular (a nearly straight segment).
pub const SINGULAR_SYSTEM_REL: f64 = 1e-9;

/// The float construction with fallbacks, as the adaptive driver uses it:
/// where eq. (3.4) is singular or ill-conditioned (a nearly straight piece,
/// `|v₁ × v₂| ≤ 1e-9 |v₁||v₂|`) it takes `α₁ = α₂` from the least-squares
/// solution of `(v₁ + v₂) a = v` (`0` for an exactly straight piece, whose
/// approximant is then the exact translate). Returns the approximant and
/// the coefficients used. `None` only if an end derivative is zero or a value
/// is not finite.
///
/// # Examples
/// ```
/// use lncert::offset::kernels::offset_approximant_f64;
/// use lncert::curve::{Bezier, V2};
/// let x = Bezier::new(vec![V2::new(0.0, 0.0), V2::new(2.0, 0.0)]);
/// let (o, alpha) = offset_approximant_f64(&x, 0.5).unwrap();
/// assert_eq!(alpha, [0.0; 4]);
/// assert!(o.points().iter().all(|p| p.y == 0.5)); // the translate, to the left
/// ```
pub fn offset_approximant_f64(x: &Bezier<f64>, d: f64) -> Option<(Bezier<f64>, [f64; 4])> {
    let e = ends(x)?;
    let alpha = solve_alpha_f64(&e, &moments(x))?;
    let o = combine(x, &e.n0, &alpha, &d);
    o.points()
        .iter()
        .all(|p| p.x.is_finite() && p.y.is_finite())
        .then_some((o, alpha))
}

/// Eq. (3.4) in floats with the fallback of [`offset_approximant_f64`]: where
/// the system is singular or ill-conditioned (`|v₁ × v₂| ≤ 1e-9 |v₁||v₂|`),
/// `α₁ = α₂` from the least-squares solution of `(v₁ + v₂) a = v` (`0` for an
/// exactly straight piece). `None` when a coefficient is not finite. Shared by
/// the offsets and seed 001's convolutions (`super::conv`).
pub fn solve_alpha_f64(e: &G2Ends<f64>, m: &[V2<f64>; 4]) -> Option<[f64; 4]> {
    let (v1, v2, v) = system(e, m);
    let det = v1.cross(&v2);
    let scale = v1.norm2().sqrt() * v2.norm2().sqrt();
    let alpha = if det.abs() > SINGULAR_SYSTEM_REL * scale {
        solve_alpha(e, m)?
    } else {
        let s = v1.add(&v2);
        let s2 = s.norm2();
        let a = if s2 > 0.0 { v.dot(&s) / s2 } else { 0.0 };
        [e.alpha0, a, a, e.alpha3]
    };
    alpha.iter().all(|a| a.is_finite()).then_some(alpha)
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::poly::Poly;
    use crate::scalar::Rational;
    use crate::test_util::qi as q;

    /// Moments against an independent computation: power-basis integration.
    #[test]
    fn moments_match_power_basis_integration() {
        let x = Bezier::new(vec![
            V2::new(q(-19, 20), q(7, 10)),
            V2::new(q(-3, 10), q(1, 2)),
            V2::new(q(3, 10), q(-5, 2)),
            V2::new(q(9, 10), q(-1, 5)),
            V2::new(q(2, 1), q(1, 3)),
        ]);
        let m = moments(&x);
        let (px, py) = x.power_coords();
        for (i, mi) in m.iter().enumerate() {
            let mut e = vec![Rational::from_integer(0.into()); 4];
            e[i] = Rational::from_integer(1.into());
            let b = Poly::from_bernstein(&e);
            let integ = |p: &Poly<Rational>| {
                let f = p.derivative().mul(&b);
                f.coeffs()
                    .iter()
                    .enumerate()
                    .fold(Rational::from_integer(0.into()), |a, (k, c)| {
                        a + c / Rational::from_integer((k as i64 + 1).into())
                    })
            };
            assert_eq!(mi.x, integ(&px), "m{i}.x");
            assert_eq!(mi.y, integ(&py), "m{i}.y");
        }
    }

    #[test]
    fn approximant_interpolates_position_and_normal_field_ends() {
        let x = Bezier::new(vec![
            V2::new(0.0, 0.0),
            V2::new(1.0, 0.3),
            V2::new(2.0, 1.5),
            V2::new(2.5, 3.0),
        ]);
        let e = ends(&x).unwrap();
        let alpha = solve_alpha(&e, &moments(&x)).unwrap();
        let na = normal_approximant(&x, &e.n0, &alpha);
        assert_eq!(na.degree(), 6);
        let last = na.points()[6].clone();
        assert!((last.x - e.n1.x).abs() < 1e-12 && (last.y - e.n1.y).abs() < 1e-12);
        // (Nᵃ)′(i) = αᵢ x′(i) = κ x′ = N′(i)   (eq. (3.9))
        let dn = na.hodograph();
        let dx = x.hodograph();
        let p0 = dn.points()[0].clone();
        let x0 = dx.points()[0].clone();
        assert!((p0.x - e.alpha0 * x0.x).abs() < 1e-12);
        assert!((p0.y - e.alpha0 * x0.y).abs() < 1e-12);
    }
}
