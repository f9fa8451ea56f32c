//! Second-order Taylor jets: a value with its first and second derivative with
//! respect to one parameter, carried through `+ − × ÷ √` (forward-mode automatic
//! differentiation).
//!
//! Over [`Interval`] a jet evaluated on a parameter *box* `S` holds enclosures of
//! `f(S)`, `f′(S)` and `f″(S)`: each component is the natural interval extension
//! of the exact derivative formula, so every enclosure is sound. Over `f64` the
//! same code gives the float values the search uses for its heuristics.

use crate::scalar::{ulp, Interval, Scalar, ScalarSqrt};
use std::ops::{Add, Mul, Neg, Sub};

/// The scalars jets run on, with the sums and products their inner loops
/// use: a float's own, and for intervals [`ulp`]'s (rounded to nearest, then
/// widened by one ulp each side: outward enclosures without switching the
/// rounding mode twice per operation, as inari does).
pub trait JetScalar: Scalar + Copy {
    /// `self + o` (enclosed, for intervals).
    fn plus(self, o: Self) -> Self;
    /// `self − o` (enclosed, for intervals).
    fn minus(self, o: Self) -> Self;
    /// `self · o` (enclosed, for intervals).
    fn times(self, o: Self) -> Self;
}

impl JetScalar for f64 {
    #[inline]
    fn plus(self, o: f64) -> f64 {
        self + o
    }
    #[inline]
    fn minus(self, o: f64) -> f64 {
        self - o
    }
    #[inline]
    fn times(self, o: f64) -> f64 {
        self * o
    }
}

impl JetScalar for Interval {
    #[inline]
    fn plus(self, o: Interval) -> Interval {
        ulp::add(self, o)
    }
    #[inline]
    fn minus(self, o: Interval) -> Interval {
        ulp::sub(self, o)
    }
    #[inline]
    fn times(self, o: Interval) -> Interval {
        ulp::mul(self, o)
    }
}

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

impl<S: JetScalar> Jet<S> {
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
            v: self.v.times(k),
            d: self.d.times(k),
            dd: self.dd.times(k),
        }
    }
    /// `1/self`, `None` where the value may vanish.
    pub fn recip(self) -> Option<Self> {
        let r = self.v.recip()?;
        let r2 = r.times(r);
        // (1/v)' = −v′/v², (1/v)″ = 2v′²/v³ − v″/v².
        let d = -self.d.times(r2);
        let dd = self
            .d
            .times(self.d)
            .times(r2)
            .times(r)
            .scale(2)
            .minus(self.dd.times(r2));
        Some(Jet { v: r, d, dd })
    }
}

impl<S: ScalarSqrt + JetScalar> Jet<S> {
    /// `√self`, `None` where the value may be ≤ 0 (the derivative is unbounded at 0).
    pub fn sqrt(self) -> Option<Self> {
        let w = self.v.sqrt()?;
        let inv = w.recip()?;
        let half = S::from_frac(1, 2);
        // w′ = v′/(2w), w″ = v″/(2w) − v′²/(4w³).
        let d = self.d.times(inv).times(half);
        let inv3 = inv.times(inv).times(inv);
        let dd = self
            .dd
            .times(inv)
            .times(half)
            .minus(self.d.times(self.d).times(inv3).times(S::from_frac(1, 4)));
        Some(Jet { v: w, d, dd })
    }
}

impl<S: JetScalar> Add for Jet<S> {
    type Output = Self;
    fn add(self, o: Self) -> Self {
        Jet {
            v: self.v.plus(o.v),
            d: self.d.plus(o.d),
            dd: self.dd.plus(o.dd),
        }
    }
}

impl<S: JetScalar> Sub for Jet<S> {
    type Output = Self;
    fn sub(self, o: Self) -> Self {
        Jet {
            v: self.v.minus(o.v),
            d: self.d.minus(o.d),
            dd: self.dd.minus(o.dd),
        }
    }
}

impl<S: JetScalar> Neg for Jet<S> {
    type Output = Self;
    fn neg(self) -> Self {
        Jet {
            v: -self.v,
            d: -self.d,
            dd: -self.dd,
        }
    }
}

impl<S: JetScalar> Mul for Jet<S> {
    type Output = Self;
    fn mul(self, o: Self) -> Self {
        Jet {
            v: self.v.times(o.v),
            d: self.d.times(o.v).plus(self.v.times(o.d)),
            dd: self
                .dd
                .times(o.v)
                .plus(self.d.times(o.d).scale(2))
                .plus(self.v.times(o.dd)),
        }
    }
}

/// A point of the plane as two jets.
pub type JetPoint<S> = (Jet<S>, Jet<S>);

/// The squared distance `|p − q|²` of two jet points.
pub fn dist2<S: JetScalar>(p: &JetPoint<S>, q: &JetPoint<S>) -> Jet<S> {
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

    /// Interval jets (on [`ulp`] sums and products) enclose the exact jet of
    /// `t⁴ − 3t² + 5` at floats `t` with full mantissas, so that the
    /// products are inexact: `(t⁴ − 3t² + 5, 4t³ − 6t, 12t² − 6)` in exact
    /// rationals, compared exactly with the interval ends.
    #[test]
    fn interval_jets_enclose_exact_jets() {
        use crate::scalar::{rational_from_f64, Rational};
        let mut rng = crate::test_util::TestRng::new(0x3c6e_f372_fe94_f82b);
        let q = |x: f64| rational_from_f64(x).unwrap();
        let inside = |i: Interval, x: &Rational| q(i.inf()) <= *x && *x <= q(i.sup());
        let mut inexact = 0;
        for _ in 0..2000 {
            let t = rng.int(1 << 40) as f64 / (1u64 << 38) as f64 * std::f64::consts::PI;
            let ti = Interval::try_from((t, t)).unwrap();
            let s = Jet::variable(ti);
            let j = s * s * s * s - (s * s).scale(Interval::try_from((3.0, 3.0)).unwrap())
                + Jet::constant(Interval::try_from((5.0, 5.0)).unwrap());
            let tq = q(t);
            let n = |k: i64| Rational::from_integer(k.into());
            let t2 = &tq * &tq;
            let v = &t2 * &t2 - n(3) * &t2 + n(5);
            let d = n(4) * &t2 * &tq - n(6) * &tq;
            let dd = n(12) * &t2 - n(6);
            assert!(
                inside(j.v, &v) && inside(j.d, &d) && inside(j.dd, &dd),
                "{t}"
            );
            // the float jet's value misses the exact one: rounding happened
            let f = Jet::variable(t);
            let jf = f * f * f * f - (f * f).scale(3.0) + Jet::constant(5.0);
            if q(jf.v) != v {
                inexact += 1;
            }
        }
        assert!(inexact > 1000, "{inexact}");
    }
}
