//! Exact arithmetic in one real quadratic field `Q(√d)`: numbers `a + b√d`.
//!
//! The worked examples of seed 000 live in such fields (`λ = 5√2/4`,
//! `δ0 = (4 - 2√3)/3`, `τ = (1 + √3)/6`). Running the generic kernels with
//! [`Surd`] computes them *exactly*, so printed closed forms can be certified or
//! refuted without rounding. Mixing two different fields (`√2 · √3` inside a
//! sum) is outside the type: the result is [`Surd::Mixed`], whose sign is
//! `Unknown` — never a wrong answer.

use super::{Rational, Scalar, Sign};
use num_bigint::BigInt;
use num_integer::Integer;
use num_traits::{One, Signed, ToPrimitive, Zero};
use std::fmt;
use std::ops::{Add, Mul, Neg, Sub};

/// `a + b√d` with `d > 1` square-free (or `d = 1`, `b = 0` for rationals).
///
/// # Examples
/// ```
/// use lncert::scalar::{Scalar, Sign, Surd, frac};
/// let r3 = Surd::sqrt_of(&frac(3, 1)).unwrap();          // √3
/// let x = (r3.clone() + Surd::from_i64(1)) * frac::<Surd>(1, 6); // (1 + √3)/6
/// assert_eq!(x.to_string(), "1/6 + 1/6*sqrt(3)");
/// assert_eq!((r3.clone() * r3).to_string(), "3");
/// assert_eq!((Surd::from_i64(2) - Surd::sqrt_of(&frac(3, 1)).unwrap()).sign(), Sign::Positive);
/// ```
#[derive(Clone, Debug, PartialEq, Eq)]
pub enum Surd {
    /// `a + b√d`.
    Num {
        /// The rational part `a`.
        a: Rational,
        /// The coefficient `b` of `√d`.
        b: Rational,
        /// The radicand `d`: square-free and `> 1`, or `1` for a rational (`b = 0`).
        d: BigInt,
    },
    /// The result of mixing two different quadratic fields: not representable.
    Mixed,
}

impl Surd {
    /// A rational as a surd.
    pub fn rational(a: Rational) -> Surd {
        Surd::Num {
            a,
            b: q0(),
            d: BigInt::one(),
        }
    }
    /// `√r` for a rational `r >= 0`, reduced (`√(8/9) = (2/3)√2`); `None` if `r < 0`
    /// or the numbers are too large to factor (> 10^12 after reduction).
    pub fn sqrt_of(r: &Rational) -> Option<Surd> {
        if r.is_negative() {
            return None;
        }
        // √(p/q) = √(p q) / q
        let pq = r.numer() * r.denom();
        let (outside, inside) = square_part(&pq)?;
        let coeff = Rational::new(outside, r.denom().clone());
        Some(
            if inside.is_one() {
                Surd::rational(coeff)
            } else {
                Surd::Num {
                    a: q0(),
                    b: coeff,
                    d: inside,
                }
            }
            .normalised(),
        )
    }
    fn normalised(self) -> Surd {
        match self {
            Surd::Num { a, b, d } if d.is_one() => Surd::rational(a + b),
            Surd::Num { a, b, .. } if b.is_zero() => Surd::rational(a),
            s => s,
        }
    }
    /// `Some(r)` if the number is rational.
    pub fn as_rational(&self) -> Option<Rational> {
        match self {
            Surd::Num { a, b, .. } if b.is_zero() => Some(a.clone()),
            _ => None,
        }
    }
    /// The field of both operands, or `None` if they live in different fields.
    fn common_d(x: &Surd, y: &Surd) -> Option<BigInt> {
        match (x, y) {
            (Surd::Num { b: b1, d: d1, .. }, Surd::Num { b: b2, d: d2, .. }) => {
                if b1.is_zero() {
                    Some(d2.clone())
                } else if b2.is_zero() || d1 == d2 {
                    Some(d1.clone())
                } else {
                    None
                }
            }
            _ => None,
        }
    }
    fn parts(&self) -> (Rational, Rational) {
        match self {
            Surd::Num { a, b, .. } => (a.clone(), b.clone()),
            Surd::Mixed => (q0(), q0()),
        }
    }
    /// Exact equality, also across fields: `a + b√d1 = c + e√d2` with `d1 ≠ d2`
    /// square-free and `b, e ≠ 0` is impossible (1, √d1, √d2 are linearly
    /// independent over Q). `None` only for [`Surd::Mixed`].
    pub fn exact_eq(&self, o: &Surd) -> Option<bool> {
        let ((a1, b1, d1), (a2, b2, d2)) = (self.triple()?, o.triple()?);
        if b1.is_zero() || b2.is_zero() || d1 == d2 {
            Some(a1 == a2 && b1 == b2 && (b1.is_zero() || d1 == d2))
        } else {
            Some(false)
        }
    }
    /// `(a, b, d)` of `a + b√d`; `None` for [`Surd::Mixed`].
    fn triple(&self) -> Option<(&Rational, &Rational, &BigInt)> {
        match self {
            Surd::Num { a, b, d } => Some((a, b, d)),
            Surd::Mixed => None,
        }
    }
    /// The conjugate `a - b√d`.
    pub fn conjugate(&self) -> Surd {
        match self {
            Surd::Num { a, b, d } => Surd::Num {
                a: a.clone(),
                b: -b.clone(),
                d: d.clone(),
            },
            Surd::Mixed => Surd::Mixed,
        }
    }
    /// A certified enclosure.
    pub fn enclosure(&self) -> Option<super::Interval> {
        match self {
            Surd::Num { a, b, d } => {
                let ia = super::interval_from_rational(a);
                if b.is_zero() {
                    return Some(ia);
                }
                let ib = super::interval_from_rational(b);
                let id = super::interval_from_rational(&Rational::from_integer(d.clone()));
                Some(ia + ib * id.sqrt())
            }
            Surd::Mixed => None,
        }
    }
}

/// `n = outside² · inside` with `inside` square-free, by trial division.
fn square_part(n: &BigInt) -> Option<(BigInt, BigInt)> {
    let mut m = n.to_u64()?;
    if m > 1_000_000_000_000 {
        return None;
    }
    let (mut outside, mut inside) = (1u64, 1u64);
    let mut p = 2u64;
    while p * p <= m {
        let mut e = 0;
        while m % p == 0 {
            m /= p;
            e += 1;
        }
        outside *= p.pow(e / 2);
        if e % 2 == 1 {
            inside *= p;
        }
        p += 1;
    }
    inside *= m;
    Some((outside.into(), inside.into()))
}

fn combine(
    x: Surd,
    y: Surd,
    f: impl Fn((Rational, Rational), (Rational, Rational), &BigInt) -> (Rational, Rational),
) -> Surd {
    match Surd::common_d(&x, &y) {
        Some(d) => {
            let (a, b) = f(x.parts(), y.parts(), &d);
            Surd::Num { a, b, d }.normalised()
        }
        None => Surd::Mixed,
    }
}

impl Add for Surd {
    type Output = Surd;
    fn add(self, o: Surd) -> Surd {
        combine(self, o, |(a1, b1), (a2, b2), _| (a1 + a2, b1 + b2))
    }
}
impl Sub for Surd {
    type Output = Surd;
    fn sub(self, o: Surd) -> Surd {
        combine(self, o, |(a1, b1), (a2, b2), _| (a1 - a2, b1 - b2))
    }
}
impl Mul for Surd {
    type Output = Surd;
    fn mul(self, o: Surd) -> Surd {
        // Two pure surds of different fields multiply into a third field.
        if let (Some((a1, b1, d1)), Some((a2, b2, d2))) = (self.triple(), o.triple()) {
            if a1.is_zero() && a2.is_zero() && !b1.is_zero() && !b2.is_zero() && d1 != d2 {
                let g = d1.gcd(d2);
                let d = (d1 / &g) * (d2 / &g);
                let k = b1 * b2 * Rational::from_integer(g);
                return Surd::Num { a: q0(), b: k, d }.normalised();
            }
        }
        combine(self, o, |(a1, b1), (a2, b2), d| {
            let dd = Rational::from_integer(d.clone());
            (&a1 * &a2 + &b1 * &b2 * dd, a1 * b2 + b1 * a2)
        })
    }
}
impl Neg for Surd {
    type Output = Surd;
    fn neg(self) -> Surd {
        match self {
            Surd::Num { a, b, d } => Surd::Num { a: -a, b: -b, d },
            Surd::Mixed => Surd::Mixed,
        }
    }
}

impl Scalar for Surd {
    const KIND: &'static str = "surd";
    const EXACT: bool = true;
    fn from_rational(r: &Rational) -> Self {
        Surd::rational(r.clone())
    }
    fn sign(&self) -> Sign {
        match self {
            Surd::Mixed => Sign::Unknown,
            Surd::Num { a, b, d } => {
                super::sign_a_plus_b_sqrt_c(a, b, &Rational::from_integer(d.clone()))
            }
        }
    }
    fn recip(&self) -> Option<Self> {
        match self {
            Surd::Mixed => None,
            Surd::Num { a, b, d } => {
                // 1/(a + b√d) = (a - b√d)/(a² - b² d)
                let n = a * a - b * b * Rational::from_integer(d.clone());
                if n.is_zero() {
                    return None;
                }
                Some(
                    Surd::Num {
                        a: a / &n,
                        b: -b / &n,
                        d: d.clone(),
                    }
                    .normalised(),
                )
            }
        }
    }
    fn approx(&self) -> f64 {
        self.enclosure().map_or(f64::NAN, |i| i.mid())
    }
}

impl super::ScalarSqrt for Surd {
    /// Square roots of rationals only (`√(a + b√d)` with `b ≠ 0` is outside the type).
    fn sqrt(&self) -> Option<Self> {
        Surd::sqrt_of(&self.as_rational()?)
    }
}

impl fmt::Display for Surd {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            Surd::Mixed => write!(f, "(mixed quadratic fields)"),
            Surd::Num { a, b, d } => {
                if b.is_zero() {
                    write!(f, "{a}")
                } else if a.is_zero() {
                    write!(f, "{b}*sqrt({d})")
                } else if b.is_negative() {
                    write!(f, "{a} - {}*sqrt({d})", -b)
                } else {
                    write!(f, "{a} + {b}*sqrt({d})")
                }
            }
        }
    }
}

fn q0() -> Rational {
    <Rational as Zero>::zero()
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::scalar::frac;

    #[test]
    fn sqrt_reduces() {
        assert_eq!(
            Surd::sqrt_of(&frac(8, 9)).unwrap().to_string(),
            "2/3*sqrt(2)"
        );
        assert_eq!(
            Surd::sqrt_of(&frac(1, 3)).unwrap().to_string(),
            "1/3*sqrt(3)"
        );
        assert_eq!(Surd::sqrt_of(&frac(49, 4)).unwrap().to_string(), "7/2");
        assert!(Surd::sqrt_of(&frac(-1, 1)).is_none());
    }

    #[test]
    fn field_ops_and_mixing() {
        let r2 = Surd::sqrt_of(&frac(2, 1)).unwrap();
        let r3 = Surd::sqrt_of(&frac(3, 1)).unwrap();
        assert_eq!((r2.clone() * r3.clone()).to_string(), "1*sqrt(6)");
        assert_eq!((r2.clone() + r3.clone()), Surd::Mixed);
        assert_eq!(r2.exact_eq(&r3), Some(false));
        assert_eq!(
            r2.exact_eq(&(Surd::sqrt_of(&frac(8, 1)).unwrap() * frac(1, 2))),
            Some(true)
        );
        assert_eq!(Surd::from_i64(1).exact_eq(&r2), Some(false));
        assert_eq!((r2.clone() + r3).sign(), Sign::Unknown);
        let x = Surd::from_i64(1) + r2.clone();
        let y = x.recip().unwrap();
        assert_eq!(x * y, Surd::from_i64(1));
        // 3 - 2√2 > 0 but tiny; 1.41 - √2 < 0
        assert_eq!(
            (Surd::from_i64(3) - r2.clone() * Surd::from_i64(2)).sign(),
            Sign::Positive
        );
        assert_eq!((frac::<Surd>(141, 100) - r2).sign(), Sign::Negative);
    }
}
