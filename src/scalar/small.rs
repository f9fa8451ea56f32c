//! [`SmallRat`]: exact rationals in machine integers (`i128` numerator and
//! positive denominator) that give up instead of growing — the filter's exact
//! stage for small inputs, between floats with an error bound and big rationals.
//!
//! Sums and products are computed with checked `i128` operations and no gcd
//! reduction (only common factors of two are stripped, with a shift): a
//! predicate of low degree in inputs with small numerators and denominators is
//! evaluated exactly in a few integer operations, where a float cannot decide an
//! exact tie and a big rational allocates and reduces at every step. An
//! operation that would overflow makes the value *lost*: its sign is
//! [`Sign::Unknown`] and every value computed from it is lost too, so the
//! predicate returns `None` and the next stage decides. A decided sign is
//! therefore always the exact sign (tested against [`Rational`] below, with a
//! planted bug).

use super::{Rational, Scalar, Sign};
use num_traits::ToPrimitive;
use std::ops::{Add, Mul, Neg, Sub};

/// An exact rational `n/d` with `d > 0` in `i128`s, or lost after an overflow.
///
/// # Examples
/// ```
/// use lncert::scalar::{frac, Scalar, Sign, SmallRat};
/// let third: SmallRat = frac(1, 3);
/// // an exact tie, which no float with an error bound decides
/// assert_eq!((third + third + third - SmallRat::one()).sign(), Sign::Zero);
/// // overflow loses the value: the sign is unknown, never wrong
/// let big = SmallRat::from_i64(i64::MAX);
/// assert_eq!((big * big * big).sign(), Sign::Unknown);
/// ```
/// (No `PartialEq`: representations are not reduced; compare [`SmallRat::value`].)
#[derive(Clone, Copy, Debug)]
pub struct SmallRat(Option<(i128, i128)>);

impl SmallRat {
    /// `n/d`, `None` (lost) for `d = 0`; the sign moved to the numerator.
    fn new(n: i128, d: i128) -> SmallRat {
        if d == 0 {
            return SmallRat(None);
        }
        let (n, d) = if d < 0 {
            match (n.checked_neg(), d.checked_neg()) {
                (Some(n), Some(d)) => (n, d),
                _ => return SmallRat(None),
            }
        } else {
            (n, d)
        };
        if n == 0 {
            return SmallRat(Some((0, 1)));
        }
        let k = n.trailing_zeros().min(d.trailing_zeros());
        SmallRat(Some((n >> k, d >> k)))
    }
    /// The exact value, `None` when lost.
    pub fn value(&self) -> Option<Rational> {
        self.0.map(|(n, d)| Rational::new(n.into(), d.into()))
    }
}

/// `a·b`, `None` on overflow; factors that fit in `i64` take one widening
/// multiply, which cannot overflow (`|a·b| ≤ 2¹²⁶`).
fn mul(a: i128, b: i128) -> Option<i128> {
    match (i64::try_from(a), i64::try_from(b)) {
        (Ok(x), Ok(y)) => Some(i128::from(x) * i128::from(y)),
        _ => a.checked_mul(b),
    }
}

fn both(a: SmallRat, b: SmallRat) -> Option<((i128, i128), (i128, i128))> {
    Some((a.0?, b.0?))
}

impl Add for SmallRat {
    type Output = SmallRat;
    fn add(self, o: SmallRat) -> SmallRat {
        let Some(((a, b), (c, d))) = both(self, o) else {
            return SmallRat(None);
        };
        if b == d {
            return a
                .checked_add(c)
                .map_or(SmallRat(None), |n| SmallRat::new(n, b));
        }
        let n = mul(a, d).zip(mul(c, b)).and_then(|(x, y)| x.checked_add(y));
        match (n, mul(b, d)) {
            (Some(n), Some(den)) => SmallRat::new(n, den),
            _ => SmallRat(None),
        }
    }
}

impl Neg for SmallRat {
    type Output = SmallRat;
    fn neg(self) -> SmallRat {
        SmallRat(self.0.and_then(|(n, d)| Some((n.checked_neg()?, d))))
    }
}

impl Sub for SmallRat {
    type Output = SmallRat;
    fn sub(self, o: SmallRat) -> SmallRat {
        self + (-o)
    }
}

impl Mul for SmallRat {
    type Output = SmallRat;
    fn mul(self, o: SmallRat) -> SmallRat {
        let Some(((a, b), (c, d))) = both(self, o) else {
            return SmallRat(None);
        };
        match (mul(a, c), mul(b, d)) {
            (Some(n), Some(den)) => SmallRat::new(n, den),
            _ => SmallRat(None),
        }
    }
}

impl Scalar for SmallRat {
    const KIND: &'static str = "small rational";
    /// Exact when decided, but an overflow loses the value (`Unknown` signs).
    const EXACT: bool = false;
    fn from_rational(r: &Rational) -> Self {
        match (r.numer().to_i128(), r.denom().to_i128()) {
            (Some(n), Some(d)) => SmallRat::new(n, d),
            _ => SmallRat(None),
        }
    }
    fn from_i64(n: i64) -> Self {
        SmallRat(Some((n.into(), 1)))
    }
    fn from_frac(p: i64, q: i64) -> Self {
        SmallRat::new(p.into(), q.into())
    }
    fn sign(&self) -> Sign {
        match self.0 {
            None => Sign::Unknown,
            Some((n, _)) if n > 0 => Sign::Positive,
            Some((n, _)) if n < 0 => Sign::Negative,
            Some(_) => Sign::Zero,
        }
    }
    fn recip(&self) -> Option<Self> {
        let (n, d) = self.0?;
        (n != 0)
            .then(|| SmallRat::new(d, n))
            .filter(|r| r.0.is_some())
    }
    fn approx(&self) -> f64 {
        match self.0 {
            Some((n, d)) => n as f64 / d as f64,
            None => f64::NAN,
        }
    }
    fn is_finite(&self) -> bool {
        self.0.is_some()
    }
    fn scale(&self, k: i64) -> Self {
        match self.0 {
            Some((n, d)) => mul(n, k.into()).map_or(SmallRat(None), |n| SmallRat::new(n, d)),
            None => SmallRat(None),
        }
    }
}

impl SmallRat {
    /// True when the value is lost (an overflow) — for tests and statistics.
    pub fn is_lost(&self) -> bool {
        self.0.is_none()
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::scalar::frac;
    use num_traits::Zero;
    use proptest::prelude::*;

    fn rat() -> impl Strategy<Value = Rational> {
        prop_oneof![
            3 => (-1_000i64..1_000, 1i64..100).prop_map(|(p, q)| frac::<Rational>(p, q)),
            1 => (any::<i64>(), 1i64..=i64::MAX).prop_map(|(p, q)| frac::<Rational>(p, q)),
            // a large numerator over a small denominator and the reverse: sums
            // of these overflow in one cross product but not the other
            1 => (any::<i64>(), 1i64..100).prop_map(|(p, q)| frac::<Rational>(p, q)),
            1 => (-100i64..100, 1i64..=i64::MAX).prop_map(|(p, q)| frac::<Rational>(p, q)),
        ]
    }

    fn exact_sign(x: &Rational) -> Sign {
        if x.is_zero() {
            Sign::Zero
        } else if *x > <Rational as Zero>::zero() {
            Sign::Positive
        } else {
            Sign::Negative
        }
    }

    proptest! {
        #![proptest_config(ProptestConfig::with_cases(3000))]
        /// Every value that is not lost is the exact one, after single operations
        /// and chains of them (where large inputs overflow), and a decided sign is
        /// the exact sign.
        #[test]
        fn values_are_exact_or_lost(a in rat(), b in rat(), c in rat()) {
            let s = |r: &Rational| SmallRat::from_rational(r);
            let (sa, sb, sc) = (s(&a), s(&b), s(&c));
            prop_assert_eq!(sa.value(), Some(a.clone()));
            let cases = [
                (sa + sb, &a + &b),
                (sa - sb, &a - &b),
                (sa * sb, &a * &b),
                (sa * sb - sc, &a * &b - &c),
                (sc + sa * sb, &c + &a * &b),
                ((sa * sb - sc) * (sa + sc), (&a * &b - &c) * (&a + &c)),
                (sa * sb * sc * sa * sb * sc, &a * &b * &c * &a * &b * &c),
                (-sa, -a.clone()),
                (sa.scale(-3), &a * frac::<Rational>(-3, 1)),
                ((sa * sb).scale(i64::MAX), &a * &b * frac::<Rational>(i64::MAX, 1)),
            ];
            for (v, x) in &cases {
                if let Some(got) = v.value() {
                    prop_assert_eq!(&got, x);
                }
                let sg = v.sign();
                prop_assert!(sg == Sign::Unknown || sg == exact_sign(x), "{:?} vs {}", v, x);
                prop_assert_eq!(sg == Sign::Unknown, v.is_lost());
            }
            if !b.is_zero() {
                if let Some(q) = sa.div(&sb) {
                    prop_assert_eq!(q.value(), Some(&a / &b));
                }
            }
        }
    }

    #[test]
    fn ties_are_zero_and_overflow_is_lost() {
        let t: SmallRat = frac(1, 3);
        assert_eq!((t + t + t - SmallRat::one()).sign(), Sign::Zero);
        let big = SmallRat::from_i64(i64::MAX);
        assert!((big * big * big).is_lost());
        assert_eq!((big * big * big - big).sign(), Sign::Unknown);
        assert!(SmallRat::zero().recip().is_none());
        assert_eq!(SmallRat::from_frac(3, -6).value(), Some(frac(-1, 2)));
        assert!(SmallRat::from_frac(1, 0).is_lost());
        // i128::MIN cannot be negated: lost, not wrapped
        let min = SmallRat(Some((i128::MIN, 1)));
        assert!((-min).is_lost());
        assert!(SmallRat::new(1, i128::MIN).is_lost());
        let huge = Rational::new(num_bigint::BigInt::from(1) << 200, 3.into());
        assert!(SmallRat::from_rational(&huge).is_lost());
    }
}
