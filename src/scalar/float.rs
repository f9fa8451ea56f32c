//! The float fast path: [`Scalar`] for `f64`. Fast, and may be wrong near
//! degeneracy; checked against the exact and interval paths by the test suite.

use super::rational::rational_to_f64_nearest;
use super::{Rational, Scalar, ScalarSqrt, Sign};

impl Scalar for f64 {
    const KIND: &'static str = "f64";
    const EXACT: bool = false;
    fn from_rational(r: &Rational) -> Self {
        rational_to_f64_nearest(r)
    }
    fn from_i64(n: i64) -> Self {
        n as f64
    }
    fn from_frac(p: i64, q: i64) -> Self {
        if p.unsigned_abs() < 1 << 53 && q.unsigned_abs() < 1 << 53 && q != 0 {
            // Both exact, and IEEE division rounds the quotient correctly.
            p as f64 / q as f64
        } else {
            Self::from_rational(&Rational::new(p.into(), q.into()))
        }
    }
    fn sign(&self) -> Sign {
        if self.is_nan() {
            Sign::Unknown
        } else if *self > 0.0 {
            Sign::Positive
        } else if *self < 0.0 {
            Sign::Negative
        } else {
            Sign::Zero
        }
    }
    fn recip(&self) -> Option<Self> {
        if *self == 0.0 || self.is_nan() {
            None
        } else {
            Some(1.0 / self)
        }
    }
    fn div(&self, d: &Self) -> Option<Self> {
        if *d == 0.0 || d.is_nan() {
            None
        } else {
            Some(self / d)
        }
    }
    fn approx(&self) -> f64 {
        *self
    }
    fn is_finite(&self) -> bool {
        f64::is_finite(*self)
    }
    fn abs_val(&self) -> Self {
        f64::abs(*self)
    }
}

impl ScalarSqrt for f64 {
    fn sqrt(&self) -> Option<Self> {
        if *self < 0.0 || self.is_nan() {
            None
        } else {
            Some(f64::sqrt(*self))
        }
    }
}
