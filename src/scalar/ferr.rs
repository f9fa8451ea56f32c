//! [`FloatErr`]: a float with a running a-priori error bound — the static stage
//! of the filtered decisions, before intervals.
//!
//! A value `(v, e)` stands for a real `x` with `|x − v| ≤ e`. Every operation
//! is one float operation on the values plus a few on the bounds, in the
//! default rounding mode (no rounding-mode switches, no branches on the hot
//! path), so a decision costs a small multiple of the plain `f64` one.
//!
//! **Soundness.** Unit roundoff `u = 2⁻⁵³`, `η = 2⁻¹⁰²²` (covers the absolute
//! error of a rounding in the subnormal range). For `x ∈ [a ± ea]`,
//! `y ∈ [b ± eb]`, `v = fl(a ∘ b)`:
//!
//! * `±`: `|x ± y − v| ≤ ea + eb + u|a ± b| ≤ ea + eb + 2u|v|`;
//! * `×`: `|xy − v| ≤ |a| eb + |b| ea + ea eb + 2u|v| + η`;
//! * `1/x` (only when `|a| > ea`): `|1/x − 1/a| ≤ ea / (|a| (|a| − ea))`,
//!   plus the rounding `2u|v| + η`.
//!
//! The bound itself is computed in floats from nonnegative terms, each of at
//! most 7 operations rounding by a relative `u`; it is multiplied by
//! `1 + 16u` (itself rounded) and `η` is added, which makes the computed bound
//! at least the exact one (`(1 − u)⁸ (1 + 16u) > 1`). Signs are read by exact
//! float comparisons: positive iff `v > e`, negative iff `v < −e`, zero only
//! for `(0, 0)`. Non-finite values or bounds give `Unknown` signs.
//!
//! Tested against exact rationals (`tests` below: every operation's bound
//! contains the exact result; a planted bug that drops the rounding term is
//! caught) and through [`super::filtered`]'s property test.

use super::rational::rational_to_f64_bracket;
use super::{Rational, Scalar, Sign};
use std::ops::{Add, Mul, Neg, Sub};

const U: f64 = f64::EPSILON * 0.5;
const ETA: f64 = f64::MIN_POSITIVE;
/// `1 + 16u`: covers the rounding of the bound's own computation.
const UP: f64 = 1.0 + 16.0 * U;

/// A float `v` with an error bound `e`: the real it stands for is in `[v − e, v + e]`.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct FloatErr {
    /// The float value.
    pub v: f64,
    /// `|exact − v| ≤ e`.
    pub e: f64,
}

impl FloatErr {
    /// An exactly known float.
    pub fn exact(v: f64) -> FloatErr {
        FloatErr { v, e: 0.0 }
    }
    fn bound(terms: f64, v: f64, eta: f64) -> f64 {
        (terms + 2.0 * U * v.abs()) * UP + eta
    }
}

impl Add for FloatErr {
    type Output = FloatErr;
    fn add(self, o: FloatErr) -> FloatErr {
        let v = self.v + o.v;
        FloatErr {
            v,
            e: FloatErr::bound(self.e + o.e, v, 0.0),
        }
    }
}

impl Sub for FloatErr {
    type Output = FloatErr;
    fn sub(self, o: FloatErr) -> FloatErr {
        let v = self.v - o.v;
        FloatErr {
            v,
            e: FloatErr::bound(self.e + o.e, v, 0.0),
        }
    }
}

impl Mul for FloatErr {
    type Output = FloatErr;
    fn mul(self, o: FloatErr) -> FloatErr {
        let zero = |x: &FloatErr| x.v == 0.0 && x.e == 0.0;
        if zero(&self) || zero(&o) {
            return FloatErr::exact(0.0); // an exact zero factor: an exact zero
        }
        let v = self.v * o.v;
        let terms = self.v.abs() * o.e + o.v.abs() * self.e + self.e * o.e;
        FloatErr {
            v,
            e: FloatErr::bound(terms, v, ETA),
        }
    }
}

impl Neg for FloatErr {
    type Output = FloatErr;
    fn neg(self) -> FloatErr {
        FloatErr {
            v: -self.v,
            e: self.e,
        }
    }
}

impl Scalar for FloatErr {
    const KIND: &'static str = "float with error bound";
    const EXACT: bool = false;
    fn from_rational(r: &Rational) -> Self {
        let (lo, hi) = rational_to_f64_bracket(r);
        if lo == hi {
            FloatErr::exact(lo)
        } else {
            // the exact value lies in [lo, hi]; hi − lo is exact or rounds up to
            // at most twice it, and 2 (hi − lo) ≥ the distance from either end
            let v = 0.5 * lo + 0.5 * hi;
            FloatErr {
                v,
                e: 2.0 * (hi - lo) + ETA,
            }
        }
    }
    fn from_i64(n: i64) -> Self {
        if n.unsigned_abs() < 1 << 53 {
            FloatErr::exact(n as f64)
        } else {
            Self::from_rational(&Rational::from_integer(n.into()))
        }
    }
    fn from_frac(p: i64, q: i64) -> Self {
        if p.unsigned_abs() < 1 << 53
            && q.unsigned_abs().is_power_of_two()
            && q.unsigned_abs() < 1 << 53
        {
            // a quotient by a power of two is exact (the result is a normal float)
            FloatErr::exact(p as f64 / q as f64)
        } else if p.unsigned_abs() < 1 << 53 && q.unsigned_abs() < 1 << 53 && q != 0 {
            let v = p as f64 / q as f64;
            // one rounding of exact operands: |p/q − v| ≤ u |p/q| ≤ 2u |v| (+ η)
            FloatErr {
                v,
                e: 2.0 * U * v.abs() + ETA,
            }
        } else {
            Self::from_rational(&Rational::new(p.into(), q.into()))
        }
    }
    fn sign(&self) -> Sign {
        if !(self.v.is_finite() && self.e.is_finite()) {
            Sign::Unknown
        } else if self.v > self.e {
            Sign::Positive
        } else if self.v < -self.e {
            Sign::Negative
        } else if self.v == 0.0 && self.e == 0.0 {
            Sign::Zero
        } else {
            Sign::Unknown
        }
    }
    fn recip(&self) -> Option<Self> {
        let a = self.v.abs();
        if !(self.is_finite() && a > self.e) {
            return None;
        }
        // a lower bound of |a| − ea (the subtraction may round up by u)
        let m = (a - self.e) * (1.0 - 4.0 * U);
        if m.is_nan() || m <= 0.0 {
            return None;
        }
        let v = 1.0 / self.v;
        let terms = self.e / (a * m);
        let e = FloatErr::bound(terms, v, ETA);
        (v.is_finite() && e.is_finite()).then_some(FloatErr { v, e })
    }
    fn approx(&self) -> f64 {
        self.v
    }
    fn is_finite(&self) -> bool {
        self.v.is_finite() && self.e.is_finite()
    }
    /// A power of two `k` (|k| ≤ 2⁵²) scales value and bound exactly (an
    /// overflow gives an infinity, whose sign is `Unknown`); any other `k` is a
    /// product.
    fn scale(&self, k: i64) -> Self {
        if k != 0 && k.unsigned_abs().is_power_of_two() && k.unsigned_abs() <= 1 << 52 {
            let f = k as f64;
            FloatErr {
                v: self.v * f,
                e: self.e * f.abs(),
            }
        } else {
            *self * FloatErr::from_i64(k)
        }
    }
    fn abs_val(&self) -> Self {
        // ||x| − |v|| ≤ |x − v|
        FloatErr {
            v: self.v.abs(),
            e: self.e,
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::scalar::{frac, rational_from_f64};
    use proptest::prelude::*;

    /// `x` lies within the bound of `f`, exactly.
    fn contains(f: &FloatErr, x: &Rational) -> bool {
        let (Some(v), Some(e)) = (rational_from_f64(f.v), rational_from_f64(f.e)) else {
            return false;
        };
        let d = x.clone() - v;
        let d = if d < Rational::from_integer(0.into()) {
            -d
        } else {
            d
        };
        d <= e
    }

    fn rat() -> impl Strategy<Value = Rational> {
        (-1_000_000i64..1_000_000, 1i64..10_000, -30i32..30).prop_map(|(p, q, k)| {
            let s = if k >= 0 {
                Rational::from_integer(num_bigint::BigInt::from(1) << k as u32)
            } else {
                Rational::new(1.into(), num_bigint::BigInt::from(1) << (-k) as u32)
            };
            frac::<Rational>(p, q) * s
        })
    }

    proptest! {
        #![proptest_config(ProptestConfig::with_cases(2000))]
        /// Every operation's bound contains the exact result, also after chains
        /// of operations, and a decided sign is the exact sign.
        #[test]
        fn bounds_contain_exact_results(a in rat(), b in rat(), c in rat()) {
            let (fa, fb, fc) = (FloatErr::from_rational(&a), FloatErr::from_rational(&b), FloatErr::from_rational(&c));
            prop_assert!(contains(&fa, &a));
            let cases = [
                (fa + fb, a.clone() + b.clone()),
                (fa - fb, a.clone() - b.clone()),
                (fa * fb, a.clone() * b.clone()),
                ((fa * fb - fc) * (fa + fc), (a.clone() * b.clone() - c.clone()) * (a.clone() + c.clone())),
                (fa * fa - fb * fc, a.clone() * a.clone() - b.clone() * c.clone()),
            ];
            let scaled = [(fa.scale(4), a.clone() * frac::<Rational>(4, 1)), (fb.scale(-2), b.clone() * frac::<Rational>(-2, 1)), (fc.scale(3), c.clone() * frac::<Rational>(3, 1))];
            for (f, x) in cases.iter().chain(&scaled) {
                prop_assert!(contains(f, x), "{f:?} does not contain {x}");
                let s = f.sign();
                let exact = if *x > Rational::from_integer(0.into()) { Sign::Positive }
                    else if *x < Rational::from_integer(0.into()) { Sign::Negative } else { Sign::Zero };
                prop_assert!(s == Sign::Unknown || s == exact, "sign {s:?} of {x}");
            }
            if b != Rational::from_integer(0.into()) {
                if let Some(q) = fa.div(&fb) {
                    prop_assert!(contains(&q, &(a.clone() / b.clone())), "{q:?} vs {}", a.clone() / b.clone());
                }
            }
        }
    }

    #[test]
    fn cancellation_is_unknown_not_wrong() {
        let third = FloatErr::from_frac(1, 3);
        let s = third + third + third - FloatErr::one();
        assert_eq!(s.sign(), Sign::Unknown);
        assert_eq!(FloatErr::from_frac(1, 2).sign(), Sign::Positive);
        // quotients by powers of two are exact; others carry a bound
        assert_eq!(FloatErr::from_frac(-3, 4), FloatErr::exact(-0.75));
        assert_eq!(
            FloatErr::from_frac(1, 1 << 52),
            FloatErr::exact(2f64.powi(-52))
        );
        assert!(FloatErr::from_frac(1, 3).e > 0.0);
        assert_eq!(
            (FloatErr::from_frac(1, 4).scale(4) - FloatErr::one()).sign(),
            Sign::Zero
        );
        assert_eq!((FloatErr::zero() * FloatErr::one()).sign(), Sign::Zero);
        assert!(FloatErr::exact(0.0).recip().is_none());
        assert!(FloatErr::exact(f64::NAN).recip().is_none());
        assert_eq!(FloatErr::exact(f64::INFINITY).sign(), Sign::Unknown);
    }
}
