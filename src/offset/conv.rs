//! Seed 001: the convolution of a curve with an ellipse (an elliptical pen),
//! approximated by G²/C¹ Hermite interpolation of degree `n + 3`.
//!
//! # The pen
//!
//! An ellipse `E = M · S¹` (`det M ≠ 0`), given either as the matrix `M` or as
//! semi-axes `a ≥ b > 0` and a rotation `θ` (`M = R(θ) diag(a, b)`). Only
//! `Q = M Mᵀ` matters: the point of `E` whose outer normal is the unit vector
//! `u` is `p(u) = Q u / √(uᵀ Q u)`, so the convolution curves of a regular
//! curve `x` are
//!
//! ```text
//! (x ∗ e_σ)(t) = x(t) + σ Q n / √(nᵀ Q n),   n = x′(t)⊥ = (−y′, x′)  (left normal),  σ = ±1
//! ```
//!
//! (`σ = +1`: the side to the left of the travel direction; for a circle of
//! radius `r` this is the offset at distance `σ r`).
//!
//! **Rotations are never rounded silently.** `cos θ` and `sin θ` are irrational
//! for most angles (θ = π/6 gives √3/2), and a certificate states exact
//! rational data. So the pen that is certified is `E' = R(θ') diag(a, b)` with
//! an exactly rational rotation `(cos θ', sin θ') = ((1 − u²)/(1 + u²), 2u/(1 + u²))`,
//! `u` a dyadic close to `tan(θ/2)`, and [`Pen::rotation_error`] is a proven
//! bound `δ ≥ |θ − θ'|` (from interval enclosures of `cos θ`, `sin θ`:
//! `δ ≤ (π/2)·|(cos θ', sin θ') − (cos θ, sin θ)|`). Rotating an ellipse by
//! `δ` moves every support point by at most `(a + a²/b) δ` (the radius of
//! curvature of `E` is at most `a²/b`, and a rotation moves a point at distance
//! `≤ a` by at most `a δ`), at the *same* normal, hence the same `t`: so
//! `d_H(x ∗ e_σ, x ∗ e'_σ) ≤ (a + a²/b) δ` = [`Pen::margin`], and a tolerance
//! `TOL` for the pen as given is proven by certifying `TOL − margin` for `E'`.
//! Multiples of π/2 (and of 90°) are exact (`δ = 0`). A pen given by its matrix
//! is exact.
//!
//! # The approximant (seed 001 §3)
//!
//! `eᵃ(t) = e_σ(0) + ∫₀ᵗ x′ α` with a cubic `α = Σ αᵢ B³ᵢ`, so `(eᵃ)′ ∥ x′` and
//! `x + eᵃ` is a polynomial of degree `n + 3`:
//!
//! * `α₀ = λ(0)`, `α₃ = λ(1)` where `e′_σ = λ x′`; with `k = x′ × x″`,
//!   `λ = −σ k det Q / (nᵀ Q n)^{3/2}` (= `−σ κ_x ρ_E`, `ρ_E` the radius of
//!   curvature of the ellipse at the compatible point). This is seed 001's
//!   (3.8)/(3.10)/(3.14) — `|α₃ᵢ| = κ_x/κ_e` with the sign of the travel —
//!   written without case distinction; it gives `(eᵃ)′ = e′` at both ends (C¹,
//!   (3.12)) and equal curvature (G², Prop 3.1).
//! * `α₁, α₂` from `eᵃ(1) = e_σ(1)`: eq. (3.2)–(3.4), the same 2×2 system as
//!   seed 004's offsets ([`super::g2::solve_alpha`] with `e_σ(0), e_σ(1)` in
//!   place of the normals).
//!
//! The convolution curve has a **cusp** where `(x ∗ e_σ)′ = (1 + λ) x′ = 0`,
//! i.e. `σ k det Q = (nᵀQn)^{3/2}`: the roots in `[0, 1]` of
//! `(det Q)² k² − (nᵀQn)³` with `σ k > 0` ([`conv_cusps`], exact). They
//! differ between the two sides (seed 001 §4). As in the paper, each side's
//! trajectory is split at its own cusps, at inflections, and where the Gauss
//! map turns too far.
//!
//! The construction runs in floats and is a heuristic: every accepted segment
//! is certified against the exact convolution ([`crate::certify`]).

use super::prep;
use crate::curve::{Bezier, V2};
use crate::poly::Poly;
use crate::scalar::{
    interval_from_rational, parse_rational, rational_from_f64, sin_cos_enclosure, Interval,
    Rational, Scalar,
};
use crate::shape::ShapeError;
use num_traits::{One, Signed, Zero};

/// How an angle is written: radians, degrees, or a rational multiple of π.
#[derive(Clone, Debug, PartialEq)]
pub enum Angle {
    /// `θ` in radians (an exact rational).
    Radians(Rational),
    /// `θ` in degrees (an exact rational).
    Degrees(Rational),
    /// `θ = k π` for an exact rational `k` (written `pi/6`, `2pi/3`, `0.25pi`).
    PiTimes(Rational),
}

impl Angle {
    /// Reads `pi/6`, `2pi/3`, `-pi`, `0.25pi`, `30deg`, `30°`, or radians
    /// (`0.5`, `1/3`); every number exactly.
    ///
    /// # Examples
    /// ```
    /// use lncert::offset::Angle;
    /// assert_eq!(Angle::parse("pi/6").unwrap(), Angle::PiTimes(lncert::parse_rational("1/6").unwrap()));
    /// assert_eq!(Angle::parse("30deg").unwrap(), Angle::Degrees(lncert::parse_rational("30").unwrap()));
    /// assert!(Angle::parse("pi/0").is_err());
    /// ```
    pub fn parse(text: &str) -> Result<Angle, ShapeError> {
        let bad = |reason: &str| ShapeError {
            field: "angle".into(),
            reason: format!("{reason}: {text:?}"),
        };
        let s: String = text.chars().filter(|c| !c.is_whitespace()).collect();
        let num = |t: &str| -> Result<Rational, ShapeError> {
            parse_rational(t).map_err(|e| bad(&format!("not an exact number ({e})")))
        };
        if s.is_empty() || s.len() > 200 {
            return Err(bad("expected an angle such as pi/6, 30deg or 0.5"));
        }
        if let Some(d) = s.strip_suffix("deg").or_else(|| s.strip_suffix('°')) {
            return Ok(Angle::Degrees(num(d)?));
        }
        let lower = s.to_ascii_lowercase();
        if let Some(i) = lower.find("pi").or_else(|| lower.find('π')) {
            let plen = if lower[i..].starts_with("pi") {
                2
            } else {
                'π'.len_utf8()
            };
            let (before, after) = (&lower[..i], &lower[i + plen..]);
            let factor = match before {
                "" | "+" => <Rational as One>::one(),
                "-" => -<Rational as One>::one(),
                b => num(b.strip_suffix('*').unwrap_or(b))?,
            };
            let divisor = match after {
                "" => <Rational as One>::one(),
                a => match a.strip_prefix('/') {
                    Some(d) => num(d)?,
                    None => return Err(bad("expected pi, k·pi or pi/q")),
                },
            };
            if divisor.is_zero() {
                return Err(bad("division by zero"));
            }
            return Ok(Angle::PiTimes(factor / divisor));
        }
        Ok(Angle::Radians(num(&s)?))
    }

    /// The angle as a multiple of π when it is one exactly (`PiTimes`, or
    /// degrees: `θ°= θ/180 π`).
    fn pi_multiple(&self) -> Option<Rational> {
        match self {
            Angle::PiTimes(k) => Some(k.clone()),
            Angle::Degrees(d) => Some(d / Rational::from_integer(180.into())),
            Angle::Radians(r) if r.is_zero() => Some(<Rational as Zero>::zero()),
            Angle::Radians(_) => None,
        }
    }

    /// An enclosure of the angle in radians.
    fn enclosure(&self) -> Interval {
        match self {
            Angle::Radians(r) => interval_from_rational(r),
            _ => {
                let k = self.pi_multiple().unwrap_or_else(<Rational as Zero>::zero);
                interval_from_rational(&k) * Interval::PI
            }
        }
    }
}

/// An elliptical pen `E = M · S¹`, exact, with what it costs to represent the
/// pen the user asked for (see the module docs).
#[derive(Clone, Debug, PartialEq)]
pub struct Pen {
    /// `M` by rows (exact; `det M ≠ 0`).
    pub m: [[Rational; 2]; 2],
    /// `Q = M Mᵀ`: `[q₁₁, q₁₂, q₂₂]`.
    pub q: [Rational; 3],
    /// Proven bound on `|θ − θ'|` (radians) between the requested rotation and
    /// the exactly rational one used; `0` when exact.
    pub rotation_error: f64,
    /// Proven bound on the Hausdorff distance between the convolution curves
    /// with the requested pen and with [`Pen::m`]: `(a + a²/b) δ`; `0` when exact.
    pub margin: f64,
    /// A short description, e.g. `ellipse a = 1.4, b = 0.6, θ = pi/6`.
    pub description: String,
}

fn pen_err(field: &str, reason: impl Into<String>) -> ShapeError {
    ShapeError {
        field: field.into(),
        reason: reason.into(),
    }
}

fn check_entry(r: &Rational, field: &str) -> Result<(), ShapeError> {
    if !crate::scalar::abs_le_pow10(r, 100) {
        return Err(pen_err(field, "magnitude above the supported limit 1e100"));
    }
    Ok(())
}

impl Pen {
    /// The pen `E = M · S¹` for an exact matrix (`det M ≠ 0`).
    ///
    /// # Examples
    /// ```
    /// use lncert::offset::Pen;
    /// let q = |s: &str| lncert::parse_rational(s).unwrap();
    /// let p = Pen::from_matrix([[q("2"), q("0")], [q("0"), q("1")]]).unwrap();
    /// assert_eq!(p.q, [q("4"), q("0"), q("1")]);
    /// assert!(Pen::from_matrix([[q("1"), q("2")], [q("2"), q("4")]]).is_err()); // singular
    /// ```
    pub fn from_matrix(m: [[Rational; 2]; 2]) -> Result<Pen, ShapeError> {
        for (i, row) in m.iter().enumerate() {
            for (j, x) in row.iter().enumerate() {
                check_entry(x, &format!("pen.matrix[{i}][{j}]"))?;
            }
        }
        if (&m[0][0] * &m[1][1] - &m[0][1] * &m[1][0]).is_zero() {
            return Err(pen_err(
                "pen.matrix",
                "the matrix is singular (the ellipse is degenerate)",
            ));
        }
        let description = format!(
            "ellipse M = [[{}, {}], [{}, {}]]",
            m[0][0], m[0][1], m[1][0], m[1][1]
        );
        Ok(Pen {
            q: q_of(&m),
            m,
            rotation_error: 0.0,
            margin: 0.0,
            description,
        })
    }

    /// The pen with semi-axes `a ≥ b > 0` (`a` along the rotated x axis) and
    /// rotation `θ`: `M = R(θ') diag(a, b)` with `θ'` exactly rational-rotated
    /// and `|θ − θ'| ≤ rotation_error` (see the module docs).
    ///
    /// # Examples
    /// ```
    /// use lncert::offset::{Angle, Pen};
    /// let q = |s: &str| lncert::parse_rational(s).unwrap();
    /// let p = Pen::ellipse(&q("0.7"), &q("0.3"), &Angle::parse("pi/6").unwrap()).unwrap();
    /// assert!(p.rotation_error > 0.0 && p.rotation_error <= 1e-12);
    /// assert!(p.margin < 1e-11);
    /// let exact = Pen::ellipse(&q("2"), &q("1"), &Angle::parse("90deg").unwrap()).unwrap();
    /// assert_eq!(exact.margin, 0.0);
    /// assert_eq!(exact.q, [q("1"), q("0"), q("4")]);
    /// ```
    pub fn ellipse(a: &Rational, b: &Rational, theta: &Angle) -> Result<Pen, ShapeError> {
        Self::ellipse_within(a, b, theta, 1e-12)
    }

    /// [`Pen::ellipse`] with the rotation represented within `max_angle`
    /// radians (at least about 1e-15: the accuracy of the enclosures). A
    /// coarser bound gives smaller exact numbers (faster exact cusp
    /// isolation) and a larger [`Pen::margin`].
    pub fn ellipse_within(
        a: &Rational,
        b: &Rational,
        theta: &Angle,
        max_angle: f64,
    ) -> Result<Pen, ShapeError> {
        check_entry(a, "pen.a")?;
        check_entry(b, "pen.b")?;
        if !b.is_positive() {
            return Err(pen_err("pen.b", "the semi-axis must be > 0"));
        }
        if a < b {
            return Err(pen_err(
                "pen.a",
                "must be ≥ b (a is the major semi-axis; rotate by 90° to swap)",
            ));
        }
        let (c, s, delta) = rational_rotation(theta, max_angle)?;
        let m = [[&c * a, -(&s * b)], [&s * a, &c * b]];
        let (af, bf) = (a.approx(), b.approx());
        // (a + a²/b) δ, rounded up
        let margin = if delta == 0.0 {
            0.0
        } else {
            let ai = interval_from_rational(a);
            let bi = interval_from_rational(b);
            let di = Interval::try_from((delta, delta)).unwrap_or(Interval::ENTIRE);
            ((ai + ai * ai / bi) * di).sup()
        };
        let th = match theta {
            Angle::Radians(r) => format!("{r} rad"),
            Angle::Degrees(d) => format!("{d}°"),
            Angle::PiTimes(k) => format!("{k}·pi"),
        };
        Ok(Pen {
            q: q_of(&m),
            m,
            rotation_error: delta,
            margin,
            description: format!("ellipse a = {af}, b = {bf}, θ = {th}"),
        })
    }

    /// `Q` in floats (construction only).
    pub fn q_f64(&self) -> [f64; 3] {
        [self.q[0].approx(), self.q[1].approx(), self.q[2].approx()]
    }

    /// Enclosures of `Q`.
    pub fn q_interval(&self) -> (Interval, Interval, Interval) {
        (
            interval_from_rational(&self.q[0]),
            interval_from_rational(&self.q[1]),
            interval_from_rational(&self.q[2]),
        )
    }
}

fn q_of(m: &[[Rational; 2]; 2]) -> [Rational; 3] {
    [
        &m[0][0] * &m[0][0] + &m[0][1] * &m[0][1],
        &m[0][0] * &m[1][0] + &m[0][1] * &m[1][1],
        &m[1][0] * &m[1][0] + &m[1][1] * &m[1][1],
    ]
}

/// An exactly rational rotation `(cos θ', sin θ')` near `θ` and a proven bound
/// `δ ≥ |θ − θ'|` (radians, modulo 2π).
fn rational_rotation(
    theta: &Angle,
    max_delta: f64,
) -> Result<(Rational, Rational, f64), ShapeError> {
    let one = <Rational as One>::one();
    let zero = <Rational as Zero>::zero();
    if let Some(k) = theta.pi_multiple() {
        // exact quarter turns
        let two_k = &k * Rational::from_integer(2.into());
        if two_k.is_integer() {
            let four = num_bigint::BigInt::from(4);
            let q = ((two_k.to_integer() % &four) + &four) % &four;
            let (c, s) = match q.to_string().as_str() {
                "0" => (one, zero),
                "1" => (zero, one),
                "2" => (-one, zero),
                _ => (zero, -one),
            };
            return Ok((c, s, 0.0));
        }
    }
    let th = theta.enclosure();
    let mag = th.mag();
    if mag.is_nan() || mag >= 1e6 {
        return Err(pen_err(
            "pen.angle",
            "the angle must be at most 1e6 radians in magnitude",
        ));
    }
    let (sin_i, cos_i) = sin_cos_enclosure(th);
    // the proven angle bound of the exact unit vector of u = tan(θ'/2):
    // δ ≤ (π/2)·|(cos θ', sin θ') − (cos θ, sin θ)|
    let half_pi = Interval::PI / Interval::try_from((2.0, 2.0)).unwrap_or(Interval::ENTIRE);
    let rotation = |u: &Rational| {
        let u2 = u * u;
        let den = &one + &u2;
        let c = (&one - &u2) / &den;
        let s = (Rational::from_integer(2.into()) * u) / &den;
        let dc = interval_from_rational(&c) - cos_i;
        let ds = interval_from_rational(&s) - sin_i;
        let delta = (half_pi * (dc * dc + ds * ds).sqrt()).sup();
        (c, s, delta)
    };
    let tm = (th.mid() / 2.0).tan();
    if !tm.is_finite() || tm.abs() > 1e12 {
        return Err(pen_err(
            "pen.angle",
            "an angle of an odd multiple of π cannot be written as a half-angle tangent; use pi",
        ));
    }
    // The convergents of the continued fraction of tan(θ/2) (small numerators
    // and denominators keep the pen's exact data, and every exact polynomial
    // built from it, small): the first whose proven bound meets `max_delta`.
    let (mut h0, mut h1) = (num_bigint::BigInt::from(0), num_bigint::BigInt::from(1));
    let (mut k0, mut k1) = (num_bigint::BigInt::from(1), num_bigint::BigInt::from(0));
    let mut x = tm;
    for _ in 0..64 {
        let a = x.floor();
        let ai = num_bigint::BigInt::from(a as i64);
        let h2 = &ai * &h1 + &h0;
        let k2 = &ai * &k1 + &k0;
        (h0, h1, k0, k1) = (h1, h2, k1, k2);
        let u = Rational::new(h1.clone(), k1.clone());
        let r = rotation(&u);
        if r.2 <= max_delta {
            return Ok(r);
        }
        let frac = x - a;
        if frac.abs() < 1e-300 {
            break;
        }
        x = 1.0 / frac;
        if !x.is_finite() || x.abs() > 1e15 {
            break;
        }
    }
    // the float itself, exactly
    let u = rational_from_f64(tm).ok_or_else(|| pen_err("pen.angle", "not a finite angle"))?;
    let (c, s, delta) = rotation(&u);
    if !(delta.is_finite() && delta < 1e-6) {
        return Err(pen_err(
            "pen.angle",
            "the rotation could not be represented within 1e-6 rad",
        ));
    }
    Ok((c, s, delta))
}

/// The point `σ Q n/√(nᵀQn)` of the pen whose outer normal is `σ n` (floats).
pub fn pen_point(n: &V2<f64>, q: [f64; 3], sigma: i8) -> Option<V2<f64>> {
    let qn = V2::new(q[0] * n.x + q[1] * n.y, q[1] * n.x + q[2] * n.y);
    let s = n.dot(&qn);
    if !(s > 0.0 && s.is_finite()) {
        return None;
    }
    let f = f64::from(sigma) / s.sqrt();
    Some(V2::new(qn.x * f, qn.y * f))
}

/// The canonical pen point at parameter `t` of the exact piece `x`, from the
/// exact unit left normal rounded once (neighbouring spans compute the same
/// bits, so their end points coincide).
pub fn pen_point_at(x: &Bezier<Rational>, t: f64, q: [f64; 3], sigma: i8) -> Option<V2<f64>> {
    pen_point(&prep::unit_left_normal(x, t)?, q, sigma)
}

/// `λ` with `e′_σ = λ x′` at one end of a float piece:
/// `λ = −σ k det Q/(nᵀQn)^{3/2}`, `k = x′ × x″`.
fn lambda_at_end(x: &Bezier<f64>, end: bool, q: [f64; 3], sigma: i8) -> Option<f64> {
    let d1 = x.hodograph();
    let d2 = d1.hodograph();
    let pick = |c: &Bezier<f64>| {
        let p = c.points();
        if end {
            p[p.len() - 1].clone()
        } else {
            p[0].clone()
        }
    };
    let v = pick(&d1);
    let a = if d1.degree() == 0 {
        V2::new(0.0, 0.0)
    } else {
        pick(&d2)
    };
    let k = v.cross(&a);
    let n = V2::new(-v.y, v.x);
    let s = q[0] * n.x * n.x + 2.0 * q[1] * n.x * n.y + q[2] * n.y * n.y;
    let det = q[0] * q[2] - q[1] * q[1];
    let l = -f64::from(sigma) * k * det / (s * s.sqrt());
    l.is_finite().then_some(l)
}

/// Seed 001's approximant `x + eᵃ` (degree `n + 3`) of the convolution of a
/// float piece with the pen `Q` on side `σ`, its ends pinned to `x(0) + e0`,
/// `x(1) + e1`. Where eq. (3.4) is singular or ill-conditioned (a nearly
/// straight piece) `α₁ = α₂` comes from least squares, as for offsets
/// ([`super::g2::offset_approximant_f64`]). Returns the approximant and `α`.
///
/// # Examples
/// ```
/// use lncert::offset::kernels::convolution_approximant_f64;
/// use lncert::curve::{Bezier, V2};
/// // a circle pen of radius 1/2 on the left: the offset at distance 1/2
/// let x = Bezier::new(vec![V2::new(0.0, 0.0), V2::new(1.0, 0.0), V2::new(1.0, 1.0)]);
/// let q = [0.25, 0.0, 0.25];
/// let (c, _) = convolution_approximant_f64(&x, &V2::new(0.0, 0.5), &V2::new(0.5, 1.0), q, 1).unwrap();
/// assert_eq!(c.degree(), 5);
/// assert_eq!(c.points()[0], V2::new(0.0, 0.5));
/// ```
pub fn convolution_approximant_f64(
    x: &Bezier<f64>,
    e0: &V2<f64>,
    e1: &V2<f64>,
    q: [f64; 3],
    sigma: i8,
) -> Option<(Bezier<f64>, [f64; 4])> {
    use super::g2;
    let ends = g2::G2Ends {
        n0: e0.clone(),
        n1: e1.clone(),
        alpha0: lambda_at_end(x, false, q, sigma)?,
        alpha3: lambda_at_end(x, true, q, sigma)?,
    };
    let alpha = g2::solve_alpha_f64(&ends, &g2::moments(x))?;
    let ea = g2::normal_approximant(x, e0, &alpha);
    let xe = g2::elevate_by(x, 3);
    let mut pts: Vec<V2<f64>> = xe
        .points()
        .iter()
        .zip(ea.points())
        .map(|(p, e)| p.add(e))
        .collect();
    let last = pts.len() - 1;
    let xp = x.points();
    pts[0] = xp[0].add(e0);
    pts[last] = xp[xp.len() - 1].add(e1);
    pts.iter()
        .all(|p| p.x.is_finite() && p.y.is_finite())
        .then(|| (Bezier::new(pts), alpha))
}

/// A cusp of the exact convolution curve `x ∗ e_σ`.
#[derive(Clone, Debug, PartialEq)]
pub struct ConvCusp {
    /// Index of the input piece.
    pub piece: usize,
    /// An exact isolating interval of the cusp parameter (width ≤ 2⁻⁴⁰).
    pub t: (Rational, Rational),
    /// Float approximation of the parameter.
    pub t_approx: f64,
    /// The cusp point of the exact convolution, approximately.
    pub point: (f64, f64),
}

/// `(det Q)² k² − (nᵀQn)³` with `k = x′ × x″`, `nᵀQn = q₁₁ y′² − 2 q₁₂ x′y′ + q₂₂ x′²`.
pub(super) fn conv_cusp_polynomial<S: Scalar>(x: &Bezier<S>, q: &[S; 3]) -> (Poly<S>, Poly<S>) {
    let (dx, dy) = x.hodograph().power_coords();
    let (ddx, ddy) = (dx.derivative(), dy.derivative());
    let k = dx.mul(&ddy).sub(&dy.mul(&ddx));
    let two = S::from_i64(2);
    let nqn = Poly::constant(q[0].clone())
        .mul(&dy.mul(&dy))
        .sub(&Poly::constant(two * q[1].clone()).mul(&dx.mul(&dy)))
        .add(&Poly::constant(q[2].clone()).mul(&dx.mul(&dx)));
    let det = q[0].clone() * q[2].clone() - q[1].clone() * q[1].clone();
    let p = Poly::constant(det.clone() * det)
        .mul(&k)
        .mul(&k)
        .sub(&nqn.mul(&nqn).mul(&nqn));
    (p, k)
}

/// The cusps of the exact convolution `x ∗ e_σ` of piece `x` with the pen,
/// decided exactly: the roots in `[0, 1]` of `(det Q)² k² − (nᵀQn)³` at which
/// `σ k > 0` (Sturm isolation; the sign decided on an isolating interval free
/// of roots of `k`, else the root is kept: a possible cusp is reported, never
/// dropped).
///
/// # Examples
/// ```
/// use lncert::offset::{kernels::conv_cusps, Pen};
/// use lncert::curve::{Bezier, V2};
/// let q = |s: &str| lncert::parse_rational(s).unwrap();
/// // a circle pen of radius 1 and a parabola of curvature 2 at its vertex:
/// // the inner side (σ = +1, curving left) has two cusps, the outer none
/// let x = Bezier::new(vec![V2::new(q("-1"), q("1")), V2::new(q("0"), q("-1")), V2::new(q("1"), q("1"))]);
/// let pen = Pen::from_matrix([[q("1"), q("0")], [q("0"), q("1")]]).unwrap();
/// assert_eq!(conv_cusps(0, &x, &pen, 1).len(), 2);
/// assert!(conv_cusps(0, &x, &pen, -1).is_empty());
/// ```
pub fn conv_cusps(piece: usize, x: &Bezier<Rational>, pen: &Pen, sigma: i8) -> Vec<ConvCusp> {
    use super::cuspform::{conv_form, conv_form_iv, cusp_params};
    let roots = cusp_params(
        x,
        conv_form_iv(x, &pen.q),
        || conv_form(x, &pen.q),
        sigma,
        || conv_cusp_polynomial(x, &pen.q).0,
    );
    let qf = pen.q_f64();
    roots
        .into_iter()
        .map(|r| {
            let m = r.midpoint();
            let ta = m.approx();
            let pt = x.eval(&m);
            let e = pen_point_at(x, ta, qf, sigma).unwrap_or(V2::new(0.0, 0.0));
            ConvCusp {
                piece,
                t: (r.lo, r.hi),
                t_approx: ta,
                point: (pt.x.approx() + e.x, pt.y.approx() + e.y),
            }
        })
        .collect()
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::test_util::q;

    /// `λ` against a central difference of the exact pen point: `e′ = λ x′`.
    #[test]
    fn lambda_is_the_derivative_ratio() {
        let pen = Pen::ellipse(&q("1.4"), &q("0.6"), &Angle::parse("pi/6").unwrap()).unwrap();
        let qf = pen.q_f64();
        let x = Bezier::new(vec![
            V2::new(0.0, 0.0),
            V2::new(1.0, 0.3),
            V2::new(2.0, 1.5),
            V2::new(2.5, 3.0),
        ]);
        for sigma in [1i8, -1] {
            let e = |t: f64| {
                let d = x.hodograph().eval(&t);
                pen_point(&V2::new(-d.y, d.x), qf, sigma).unwrap()
            };
            let h = 1e-6;
            for (end, t) in [(false, 0.0), (true, 1.0)] {
                let tt = if end { t - h } else { t + h };
                let de = e(tt + h).sub(&e(tt - h)).scale(&(0.5 / h));
                let d = x.hodograph().eval(&tt);
                let l_num = de.dot(&d) / d.norm2();
                let l = lambda_at_end(&x, end, qf, sigma).unwrap();
                assert!((l - l_num).abs() < 1e-3 * (1.0 + l.abs()), "{l} vs {l_num}");
                assert!(de.cross(&d).abs() < 1e-6, "e′ ∥ x′");
            }
        }
    }

    /// C¹ and G² at both ends (seed 001 Prop 3.2) against direct formulas:
    /// the approximant's end derivatives equal `(1 + λ) x′` and its end
    /// curvatures equal those of the exact convolution (numerical derivatives
    /// of the exact curve).
    #[test]
    fn approximant_is_c1_and_g2_at_the_ends() {
        let pen = Pen::ellipse(&q("0.7"), &q("0.3"), &Angle::parse("pi/6").unwrap()).unwrap();
        let qf = pen.q_f64();
        let x = Bezier::new(vec![
            V2::new(0.0, 0.0),
            V2::new(1.0, 0.2),
            V2::new(2.0, 1.0),
            V2::new(2.4, 2.5),
        ]);
        for sigma in [1i8, -1] {
            let e = |t: f64| {
                let d = x.hodograph().eval(&t);
                x.eval(&t)
                    .add(&pen_point(&V2::new(-d.y, d.x), qf, sigma).unwrap())
            };
            let (c, _) = convolution_approximant_f64(
                &x,
                &e(0.0).sub(&x.eval(&0.0)),
                &e(1.0).sub(&x.eval(&1.0)),
                qf,
                sigma,
            )
            .unwrap();
            let h = 1e-4;
            for t in [0.0, 1.0] {
                let s = if t == 0.0 { h } else { -h };
                // one-sided second-order differences of the exact convolution
                let (p0, p1, p2) = (e(t), e(t + s), e(t + 2.0 * s));
                let d1 = p1
                    .scale(&4.0)
                    .sub(&p0.scale(&3.0))
                    .sub(&p2)
                    .scale(&(0.5 / s));
                let d2 = p0.sub(&p1.scale(&2.0)).add(&p2).scale(&(1.0 / (s * s)));
                let cd1 = c.hodograph().eval(&t);
                let cd2 = c.hodograph().hodograph().eval(&t);
                assert!(
                    cd1.sub(&d1).norm2().sqrt() < 1e-5 * (1.0 + d1.norm2().sqrt()),
                    "C¹ at {t}"
                );
                let kappa = |a: &V2<f64>, b: &V2<f64>| a.cross(b) / a.norm2().powf(1.5);
                let (ke, ka) = (kappa(&d1, &d2), kappa(&cd1, &cd2));
                assert!(
                    (ke - ka).abs() < 1e-2 * (1.0 + ke.abs()),
                    "G² at {t}: {ke} vs {ka}"
                );
            }
        }
    }

    #[test]
    fn angles_and_pens_refuse_bad_input() {
        for bad in ["", "pi/0", "abc", "1e5000", "pi*", "NaN"] {
            assert!(Angle::parse(bad).is_err(), "{bad}");
        }
        let a = Angle::parse("0.3").unwrap();
        assert!(Pen::ellipse(&q("1"), &q("0"), &a).is_err());
        assert!(Pen::ellipse(&q("1"), &q("-1"), &a).is_err());
        assert!(Pen::ellipse(&q("1"), &q("2"), &a).is_err());
        assert!(Pen::ellipse(&q("1e200"), &q("1"), &a).is_err());
        assert!(Pen::ellipse(&q("1"), &q("1"), &Angle::Radians(q("1e7"))).is_err());
        let z = q("0");
        assert!(Pen::from_matrix([[z.clone(), z.clone()], [z.clone(), z]]).is_err());
    }

    /// The rational rotation is within its proven bound of the angle, checked
    /// against f64 cos/sin (a loose, independent check of the enclosure).
    #[test]
    fn rational_rotation_is_close_to_the_angle() {
        for t in ["pi/6", "0.5", "-2.9", "pi/3", "100deg", "7pi/5"] {
            let a = Angle::parse(t).unwrap();
            let (c, s, delta) = rational_rotation(&a, 1e-12).unwrap();
            assert!((c.clone() * c.clone() + s.clone() * s.clone()) == <Rational as One>::one());
            let th = a.enclosure().mid();
            let err = ((c.approx() - th.cos()).powi(2) + (s.approx() - th.sin()).powi(2)).sqrt();
            assert!(err <= delta + 1e-15, "{t}: {err} > {delta}");
            assert!(delta <= 1e-12, "{t}: {delta}");
            // the coarse representation has small numbers
            let (c2, _, d2) = rational_rotation(&a, 1e-6).unwrap();
            assert!(d2 <= 1e-6 && c2.denom().bits() < 48, "{t}: {c2}");
        }
    }
}
