//! Seed 000 §3–4: cubic Bézier curves with linear normals built from three
//! points `b0, bm, b3` and two ratios `δ0, δ1`:
//! `b1 = (1-δ0) b0 + δ0 bm`, `b2 = (1-δ1) b3 + δ1 bm`.
//!
//! * eq. (1): a cusp at `t = τ` iff `δ0 = 2τ/(3τ-1)`, `δ1 = 2(τ-1)/(3τ-2)`;
//! * Prop 3.1: the curve is a regular LN curve on `[0,1]` iff `τ ∉ [0,1]`;
//! * eq. (5): with `ρ = κ/λ`, `δ0 = 2/3 (2 - 1/ρ)`, `δ1 = 2/3 (2 - ρ)`;
//! * Lemma 4.1: regular iff `κ ∈ (λ/2, 2λ)`, i.e. `ρ ∈ (1/2, 2)`.
//!
//! Only the ratio `ρ = κ/λ` enters the control points, so for rational data and
//! rational `ρ` every curve here is exact. `λ = |bm - b3| / |b0 - bm|` itself is
//! irrational in general: exact code compares `λ²` (see [`LnFrame::lambda2`]).

use super::{checked_div, finite, LnError};
use crate::curve::{Bezier, V2};
use crate::scalar::{frac, Scalar, ScalarSqrt, Sign};

/// The control triangle `b0, bm, b3` of a cubic LN curve (`bm` is where the end
/// tangents meet). Guaranteed non-collinear.
///
/// # Examples
/// ```
/// use lncert::curve::V2;
/// use lncert::ln::cubic::LnFrame;
/// let f = LnFrame::new(V2::new(2.5, -1.0), V2::new(0.5, 1.0), V2::new(3.5, 5.0)).unwrap();
/// assert_eq!(f.lambda2(), Some(25.0 / 8.0)); // λ = 5√2/4
/// assert!(LnFrame::new(V2::new(0.0, 0.0), V2::new(1.0, 1.0), V2::new(2.0, 2.0)).is_err());
/// ```
#[derive(Clone, Debug, PartialEq)]
pub struct LnFrame<S> {
    /// Start point `b0` (the first control point).
    pub b0: V2<S>,
    /// `bm`, where the end tangents meet.
    pub bm: V2<S>,
    /// End point `b3` (the last control point).
    pub b3: V2<S>,
}

/// A cusp parameter `τ`, possibly infinite (`τ = ∞` gives `δ0 = δ1 = 2/3`, a
/// quadratic curve written as a cubic).
#[derive(Clone, Debug, PartialEq)]
pub enum Tau<S> {
    /// A finite cusp parameter `τ`.
    Finite(S),
    /// `τ = ∞`: no cusp, `δ0 = δ1 = 2/3`.
    Infinite,
}

impl<S: Scalar> LnFrame<S> {
    /// Checks that `b0, bm, b3` are not collinear (which also excludes coincident points).
    pub fn new(b0: V2<S>, bm: V2<S>, b3: V2<S>) -> Result<Self, LnError> {
        finite(&[&b0.x, &b0.y], "b0")?;
        finite(&[&bm.x, &bm.y], "bm")?;
        finite(&[&b3.x, &b3.y], "b3")?;
        let f = LnFrame { b0, bm, b3 };
        match f.d0().cross(&f.d1()).sign() {
            Sign::Zero => Err(LnError::Collinear { field: "b0,bm,b3" }),
            Sign::Unknown => Err(LnError::Undecided { field: "b0,bm,b3" }),
            _ => Ok(f),
        }
    }
    /// Builds a frame without the collinearity check, for symbolic scalars
    /// (whose signs are unknown). The caller guarantees non-collinearity.
    pub fn new_unchecked(b0: V2<S>, bm: V2<S>, b3: V2<S>) -> Self {
        LnFrame { b0, bm, b3 }
    }
    /// `∇b0 = bm - b0`.
    pub fn d0(&self) -> V2<S> {
        self.bm.sub(&self.b0)
    }
    /// `∇b1 = b3 - bm`.
    pub fn d1(&self) -> V2<S> {
        self.b3.sub(&self.bm)
    }
    /// `λ² = |∇b1|² / |∇b0|²` (exact for rational data). `None` only when
    /// `|∇b0|²` is not representable as nonzero (f64 underflow, e.g. `∇b0 ~ 1e-200`).
    pub fn lambda2(&self) -> Option<S> {
        self.d1().norm2().div(&self.d0().norm2())
    }
    /// `λ = |∇b1| / |∇b0|` (needs square roots).
    pub fn lambda(&self) -> Option<S>
    where
        S: ScalarSqrt,
    {
        self.lambda2()?.sqrt()
    }
    /// The cubic with control points `[b0, (1-δ0)b0 + δ0 bm, (1-δ1)b3 + δ1 bm, b3]`.
    pub fn cubic(&self, delta0: &S, delta1: &S) -> Bezier<S> {
        Bezier::new(vec![
            self.b0.clone(),
            self.b0.lerp(&self.bm, delta0),
            self.b3.lerp(&self.bm, delta1),
            self.b3.clone(),
        ])
    }
    /// The direction field `(3τ-2)∇b0(1-t) + (3τ-1)∇b1 t` of seed 000 §3: the
    /// tangent of the eq. (1) curve is parallel to it.
    pub fn tangent_direction(&self, tau: &S, t: &S) -> V2<S> {
        let a = tau.scale(3) - S::from_i64(2);
        let b = tau.scale(3) - S::one();
        self.d0()
            .scale(&(a * (S::one() - t.clone())))
            .add(&self.d1().scale(&(b * t.clone())))
    }
}

/// Eq. (1): `(δ0, δ1) = (2τ/(3τ-1), 2(τ-1)/(3τ-2))`; `(2/3, 2/3)` for `τ = ∞`.
/// Undefined for `τ = 1/3` and `τ = 2/3`.
///
/// # Examples
/// ```
/// use lncert::ln::cubic::{deltas_from_tau, Tau};
/// use lncert::scalar::{frac, Rational};
/// let (d0, d1) = deltas_from_tau::<Rational>(&Tau::Finite(frac(-1, 1))).unwrap();
/// assert_eq!((d0, d1), (frac(1, 2), frac(4, 5)));
/// ```
pub fn deltas_from_tau<S: Scalar>(tau: &Tau<S>) -> Result<(S, S), LnError> {
    if let Tau::Finite(t) = tau {
        finite(&[t], "tau")?;
    }
    match tau {
        Tau::Infinite => Ok((frac(2, 3), frac(2, 3))),
        Tau::Finite(t) => {
            let d0den = t.scale(3) - S::one();
            let d1den = t.scale(3) - S::from_i64(2);
            let d0 = checked_div(
                t.scale(2),
                &d0den,
                "tau",
                "τ = 1/3 makes δ0 = 2τ/(3τ-1) undefined",
            )?;
            let d1 = checked_div(
                (t.clone() - S::one()).scale(2),
                &d1den,
                "tau",
                "τ = 2/3 makes δ1 = 2(τ-1)/(3τ-2) undefined",
            )?;
            Ok((d0, d1))
        }
    }
}

/// Prop 3.1 (seed 000): the curve of eq. (1) is regular on `[0,1]` iff `τ ∉ [0,1]`.
/// `None` if undecided (intervals only).
pub fn prop_3_1_regular<S: Scalar>(tau: &Tau<S>) -> Option<bool> {
    match tau {
        Tau::Infinite => Some(true),
        Tau::Finite(t) => {
            let below = t.sign().is_negative()?;
            let above = t.cmp_sign(&S::one()).is_positive()?;
            Some(below || above)
        }
    }
}

/// Eq. (5): `(δ0, δ1) = (2/3 (2 - 1/ρ), 2/3 (2 - ρ))` with `ρ = κ/λ`.
///
/// # Examples
/// ```
/// use lncert::ln::cubic::deltas_from_rho;
/// use lncert::scalar::{frac, Rational};
/// // Seed 000 Fig. 4(c): κ = λ/3 gives [δ0, δ1] = [-2/3, 10/9].
/// let (d0, d1) = deltas_from_rho::<Rational>(&frac(1, 3)).unwrap();
/// assert_eq!((d0, d1), (frac(-2, 3), frac(10, 9)));
/// ```
pub fn deltas_from_rho<S: Scalar>(rho: &S) -> Result<(S, S), LnError> {
    finite(&[rho], "rho")?;
    let inv = checked_div(
        S::one(),
        rho,
        "rho",
        "ρ = κ/λ = 0 makes δ0 = 2/3 (2 - 1/ρ) undefined",
    )?;
    let two = S::from_i64(2);
    let d0 = (two.clone() - inv) * frac(2, 3);
    let d1 = (two - rho.clone()) * frac(2, 3);
    Ok((d0, d1))
}

/// The cusp parameter of the curve with `ρ = κ/λ`: `τ = (2ρ-1)/(3(ρ-1))`, `∞` for `ρ = 1`.
pub fn tau_from_rho<S: Scalar>(rho: &S) -> Option<Tau<S>> {
    let den = (rho.clone() - S::one()).scale(3);
    match den.sign() {
        Sign::Zero => Some(Tau::Infinite),
        Sign::Unknown => None,
        _ => Some(Tau::Finite((rho.scale(2) - S::one()).div(&den)?)),
    }
}

/// `ρ = (3τ-1)/(3τ-2)` (`1` for `τ = ∞`); `None` at `τ = 2/3` or if undecided.
pub fn rho_from_tau<S: Scalar>(tau: &Tau<S>) -> Option<S> {
    match tau {
        Tau::Infinite => Some(S::one()),
        Tau::Finite(t) => (t.scale(3) - S::one()).div(&(t.scale(3) - S::from_i64(2))),
    }
}

/// Lemma 4.1: the LN cubic with normal map `N0 (1-t) + κ N1 t` is regular on
/// `[0,1]` iff `κ ∈ (λ/2, 2λ)`, i.e. `ρ = κ/λ ∈ (1/2, 2)`.
pub fn lemma_4_1_regular<S: Scalar>(rho: &S) -> Option<bool> {
    let lo = rho.cmp_sign(&frac(1, 2)).is_positive()?;
    let hi = S::from_i64(2).cmp_sign(rho).is_positive()?;
    Some(lo && hi)
}

/// The cusp parameter of an LN cubic read off its `δ0`: `τ = δ0/(3δ0 - 2)`
/// (inverse of eq. (1)); `∞` when `δ0 = 2/3`.
pub fn tau_from_delta0<S: Scalar>(delta0: &S) -> Option<Tau<S>> {
    let den = delta0.scale(3) - S::from_i64(2);
    match den.sign() {
        Sign::Zero => Some(Tau::Infinite),
        Sign::Unknown => None,
        _ => Some(Tau::Finite(delta0.scale(1).div(&den)?)),
    }
}
