//! Second-order Taylor jets: a value with its first and second derivative with
//! respect to one parameter, carried through `+ − × ÷ √` (forward-mode automatic
//! differentiation).
//!
//! Over [`Interval`] a jet evaluated on a parameter *box* `S` holds enclosures of
//! `f(S)`, `f′(S)` and `f″(S)`: each component is the natural interval extension
//! of the exact derivative formula, so every enclosure is sound. Over `f64` the
//! same code gives the float values the search uses for its heuristics.

use crate::scalar::{Scalar, ScalarSqrt};
use std::ops::{Add, Mul, Neg, Sub};

/// `(f, f′, f″)` of a function of one parameter.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Jet<S> {
    /// The value `f`.
    pub v: S,
    /// The first derivative `f′`.
    pub d: S,
    /// The second derivative `f″`.
    pub dd: S,
}

impl<S: Scalar + Copy> Jet<S> {
    /// A constant (both derivatives zero).
    pub fn constant(v: S) -> Self {
        Jet {
            v,
            d: S::zero(),
            dd: S::zero(),
        }
    }
    /// The affine function `v + d·(s − s₀)` seen at `s₀` (or over a box): value `v`, slope `d`.
    pub fn affine(v: S, d: S) -> Self {
        Jet {
            v,
            d,
            dd: S::zero(),
        }
    }
    /// The parameter itself, at `v`.
    pub fn variable(v: S) -> Self {
        Self::affine(v, S::one())
    }
    /// `self · k` for a constant `k`.
    pub fn scale(self, k: S) -> Self {
        Jet {
            v: self.v * k,
            d: self.d * k,
            dd: self.dd * k,
        }
    }
    /// `1/self`, `None` where the value may vanish.
    pub fn recip(self) -> Option<Self> {
        let r = self.v.recip()?;
        let r2 = r * r;
        // (1/v)' = −v′/v², (1/v)″ = 2v′²/v³ − v″/v².
        let d = -(self.d * r2);
        let dd = (self.d * self.d * r2 * r).scale(2) - self.dd * r2;
        Some(Jet { v: r, d, dd })
    }
}

impl<S: ScalarSqrt + Copy> Jet<S> {
    /// `√self`, `None` where the value may be ≤ 0 (the derivative is unbounded at 0).
    pub fn sqrt(self) -> Option<Self> {
        let w = self.v.sqrt()?;
        let inv = w.recip()?;
        let half = S::from_frac(1, 2);
        // w′ = v′/(2w), w″ = v″/(2w) − v′²/(4w³).
        let d = self.d * inv * half;
        let dd = self.dd * inv * half - self.d * self.d * inv * inv * inv * S::from_frac(1, 4);
        Some(Jet { v: w, d, dd })
    }
}

impl<S: Scalar + Copy> Add for Jet<S> {
    type Output = Self;
    fn add(self, o: Self) -> Self {
        Jet {
            v: self.v + o.v,
            d: self.d + o.d,
            dd: self.dd + o.dd,
        }
    }
}

impl<S: Scalar + Copy> Sub for Jet<S> {
    type Output = Self;
    fn sub(self, o: Self) -> Self {
        Jet {
            v: self.v - o.v,
            d: self.d - o.d,
            dd: self.dd - o.dd,
        }
    }
}

impl<S: Scalar + Copy> Neg for Jet<S> {
    type Output = Self;
    fn neg(self) -> Self {
        Jet {
            v: -self.v,
            d: -self.d,
            dd: -self.dd,
        }
    }
}

impl<S: Scalar + Copy> Mul for Jet<S> {
    type Output = Self;
    fn mul(self, o: Self) -> Self {
        Jet {
            v: self.v * o.v,
            d: self.d * o.v + self.v * o.d,
            dd: self.dd * o.v + (self.d * o.d).scale(2) + self.v * o.dd,
        }
    }
}

/// A point of the plane as two jets.
pub type JetPoint<S> = (Jet<S>, Jet<S>);

/// The squared distance `|p − q|²` of two jet points.
pub fn dist2<S: Scalar + Copy>(p: &JetPoint<S>, q: &JetPoint<S>) -> Jet<S> {
    let dx = p.0 - q.0;
    let dy = p.1 - q.1;
    dx * dx + dy * dy
}

/// The jet of the parameter over the box `[lo, hi]` (value `[lo, hi]`, slope 1).
#[cfg(test)]
pub(crate) fn param_box(lo: f64, hi: f64) -> Option<Jet<crate::scalar::Interval>> {
    use crate::scalar::Interval;
    let v = Interval::try_from((lo, hi)).ok()?;
    Some(Jet::variable(v))
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::scalar::Interval;

    #[test]
    fn derivatives_of_a_rational_expression() {
        // f(s) = sqrt(1 + s²) / s at s = 2: f = √5/2,
        // f′ = s/(s√(1+s²)) − √(1+s²)/s² = 2/(2√5) − √5/4,
        // checked against central differences of the f64 formula.
        let f = |s: f64| (1.0 + s * s).sqrt() / s;
        let s = Jet::variable(2.0f64);
        let j = (s * s + Jet::constant(1.0)).sqrt().unwrap() * s.recip().unwrap();
        let h = 1e-4;
        let d_num = (f(2.0 + h) - f(2.0 - h)) / (2.0 * h);
        let dd_num = (f(2.0 + h) - 2.0 * f(2.0) + f(2.0 - h)) / (h * h);
        assert!((j.v - f(2.0)).abs() < 1e-15);
        assert!((j.d - d_num).abs() < 1e-7, "{} vs {d_num}", j.d);
        assert!((j.dd - dd_num).abs() < 1e-5, "{} vs {dd_num}", j.dd);
    }

    #[test]
    fn interval_jet_encloses_float_jet() {
        let s = param_box(0.25, 0.5).unwrap();
        let j = (s * s * s + s.scale(Interval::try_from((3.0, 3.0)).unwrap()))
            .recip()
            .unwrap();
        for k in 0..=10 {
            let t = 0.25 + 0.025 * k as f64;
            let jf = (Jet::variable(t) * Jet::variable(t) * Jet::variable(t)
                + Jet::variable(t).scale(3.0))
            .recip()
            .unwrap();
            assert!(j.v.contains(jf.v) && j.d.contains(jf.d) && j.dd.contains(jf.dd));
        }
    }
}
