//! The scalar layer: one trait, three arithmetics.
//!
//! Every kernel of lncert is written once, generic over [`Scalar`], and runs in
//!
//! | type | meaning | [`Scalar::sign`] |
//! |---|---|---|
//! | `f64` | fast float path, may be wrong near degeneracy | never `Unknown` (except NaN) |
//! | [`Rational`] (`BigRational`) | exact | never `Unknown` |
//! | [`Interval`] (inari) | certified enclosure, outward rounded | `Unknown` when the enclosure straddles 0 |
//! | [`FloatErr`] | a float with a running a-priori error bound (the static filter) | `Unknown` when the bound reaches 0 |
//! | [`SmallRat`] | exact rationals in `i128`s, lost on overflow (the filter's small exact stage) | `Unknown` once lost |
//! | [`crate::poly::RatFunc`] | symbolic rational functions over Q | exact for constants, else `Unknown` |
//!
//! Square roots are a separate capability ([`ScalarSqrt`]): only `f64` and
//! [`Interval`] have them. Exact decisions on irrational quantities square first
//! (compare `lambda^2`, not `lambda`).

mod ferr;
mod filter;
mod float;
mod interval;
mod rational;
mod small;
mod surd;
pub mod ulp;

pub use ferr::FloatErr;
pub use filter::{filter_stats, filtered, reset_filter_stats, Decision, FilterStats, Predicate};
pub use interval::{
    atan_enclosure, interval_from_rational, interval_to_json, point_interval, sin_cos_enclosure,
    Interval, IntervalExt,
};
pub(crate) use rational::float_parts;
pub use rational::{
    abs_le_pow10, parse_rational, rational_from_f64, rational_to_string, ParseNumberError, Rational,
};
pub use small::SmallRat;
pub use surd::Surd;

use std::fmt::Debug;
use std::ops::{Add, Mul, Neg, Sub};

/// The sign of a quantity, with an honest `Unknown` (only enclosures say it).
///
/// # Examples
/// ```
/// use lncert::scalar::{Scalar, Sign, Interval};
/// assert_eq!(Scalar::sign(&-2.0f64), Sign::Negative);
/// let straddles = Interval::try_from((-1.0, 1.0)).unwrap();
/// assert_eq!(Scalar::sign(&straddles), Sign::Unknown);
/// ```
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum Sign {
    /// Strictly negative.
    Negative,
    /// Exactly zero.
    Zero,
    /// Strictly positive.
    Positive,
    /// Not decided by the arithmetic (e.g. an enclosure that contains 0).
    Unknown,
}

impl Sign {
    /// `Some(true)` if positive, `Some(false)` if zero or negative, `None` if unknown.
    pub fn is_positive(self) -> Option<bool> {
        match self {
            Sign::Positive => Some(true),
            Sign::Zero | Sign::Negative => Some(false),
            Sign::Unknown => None,
        }
    }
    /// `Some(true)` if negative, `Some(false)` if zero or positive, `None` if unknown.
    pub fn is_negative(self) -> Option<bool> {
        self.neg().is_positive()
    }
    /// `Some(true)` if zero, `None` if unknown.
    pub fn is_zero(self) -> Option<bool> {
        match self {
            Sign::Zero => Some(true),
            Sign::Unknown => None,
            _ => Some(false),
        }
    }
    /// The sign of `-x`.
    #[allow(clippy::should_implement_trait)]
    pub fn neg(self) -> Sign {
        match self {
            Sign::Negative => Sign::Positive,
            Sign::Positive => Sign::Negative,
            s => s,
        }
    }
}

/// The sign of a product.
impl Mul for Sign {
    type Output = Sign;
    fn mul(self, o: Sign) -> Sign {
        use Sign::*;
        match (self, o) {
            (Zero, _) | (_, Zero) => Zero,
            (Unknown, _) | (_, Unknown) => Unknown,
            (a, b) if a == b => Positive,
            _ => Negative,
        }
    }
}

/// A field-like scalar the kernels are generic over.
///
/// Operations are total: division goes through [`Scalar::recip`], which returns
/// `None` when the divisor is (or, for an enclosure, may be) zero.
pub trait Scalar:
    Clone + Debug + Add<Output = Self> + Sub<Output = Self> + Mul<Output = Self> + Neg<Output = Self>
{
    /// Short name of the arithmetic: `"f64"`, `"rational"`, `"interval"`, `"symbolic"`.
    const KIND: &'static str;
    /// True when every operation is exact (no rounding at all).
    const EXACT: bool;

    /// The value of an exact rational (rounded to nearest for f64, tightest
    /// outward-rounded enclosure for intervals).
    fn from_rational(r: &Rational) -> Self;
    /// A small integer.
    fn from_i64(n: i64) -> Self {
        Self::from_rational(&Rational::from_integer(n.into()))
    }
    /// The fraction `p/q` (`q != 0`); arithmetics override this with a fast path.
    fn from_frac(p: i64, q: i64) -> Self {
        Self::from_rational(&Rational::new(p.into(), q.into()))
    }
    /// The additive identity `0`.
    fn zero() -> Self {
        Self::from_i64(0)
    }
    /// The multiplicative identity `1`.
    fn one() -> Self {
        Self::from_i64(1)
    }
    /// The sign; `Unknown` only when the arithmetic cannot decide.
    fn sign(&self) -> Sign;
    /// `1/self`, or `None` if `self` is zero (or an enclosure containing zero).
    fn recip(&self) -> Option<Self>;
    /// `self / d`, or `None` if `d` is (or may be) zero.
    fn div(&self, d: &Self) -> Option<Self> {
        d.recip().map(|r| self.clone() * r)
    }
    /// A float approximation, for display and for the fast path.
    fn approx(&self) -> f64;

    /// False for values that are not finite numbers (NaN, ±inf for `f64`;
    /// unbounded or empty enclosures). Exact arithmetics are always finite.
    fn is_finite(&self) -> bool {
        true
    }
    /// `|self|`. Enclosures override this with the enclosure of the absolute
    /// value (an interval straddling 0 maps to `[0, max |end|]`): branching on
    /// an unknown sign would break "f64 result ∈ interval result".
    fn abs_val(&self) -> Self {
        if self.sign() == Sign::Negative {
            -self.clone()
        } else {
            self.clone()
        }
    }
    /// `self * self`.
    fn sqr(&self) -> Self {
        self.clone() * self.clone()
    }
    /// The sign of `self - o`.
    fn cmp_sign(&self, o: &Self) -> Sign {
        (self.clone() - o.clone()).sign()
    }
    /// `self * k` for a small integer `k`.
    fn scale(&self, k: i64) -> Self {
        self.clone() * Self::from_i64(k)
    }

    // Fast paths of Bernstein-form operations on one coordinate. `None` (the
    // default) means "use the generic de Casteljau code"; an arithmetic that
    // overrides one must return exactly what the generic code computes (an
    // exact arithmetic: the same numbers; see `scalar::rational`).

    /// The coordinate of the Bézier with coordinates `c` at `t`.
    fn bernstein_eval(_c: &[Self], _t: &Self) -> Option<Self> {
        None
    }
    /// The coordinates of the Bézier with coordinates `c` restricted to
    /// `[a, b]` (blossoms `c(a^(n−i), b^i)`).
    fn bernstein_restrict(_c: &[Self], _a: &Self, _b: &Self) -> Option<Vec<Self>> {
        None
    }
    /// The power-basis coefficients of the polynomial with Bernstein
    /// coefficients `b` on `[0, 1]`.
    fn bernstein_to_power(_b: &[Self]) -> Option<Vec<Self>> {
        None
    }
}

/// Square roots: only arithmetics that can represent them (`f64`, [`Interval`]).
pub trait ScalarSqrt: Scalar {
    /// `sqrt(self)`, `None` if `self` is (or may be) negative.
    fn sqrt(&self) -> Option<Self>;
}

/// Builds the scalar `p/q` (exact for rationals, enclosed for intervals).
///
/// # Examples
/// ```
/// use lncert::scalar::{frac, Rational};
/// let x: Rational = frac(1, 3);
/// assert_eq!(x.to_string(), "1/3");
/// ```
pub fn frac<S: Scalar>(p: i64, q: i64) -> S {
    S::from_frac(p, q)
}

/// The exact sign of `a + b·sqrt(c)` (`c >= 0`) from signs and squares only:
/// no square root is taken, so with rationals the answer is exact. Returns
/// `Unknown` if `c` is (or may be) negative or a sign cannot be decided.
///
/// # Examples
/// ```
/// use lncert::scalar::{frac, sign_a_plus_b_sqrt_c, Rational, Sign};
/// // 3 - 2·sqrt(2) > 0 because 9 > 8.
/// let s = sign_a_plus_b_sqrt_c::<Rational>(&frac(3, 1), &frac(-2, 1), &frac(2, 1));
/// assert_eq!(s, Sign::Positive);
/// ```
pub fn sign_a_plus_b_sqrt_c<S: Scalar>(a: &S, b: &S, c: &S) -> Sign {
    let sc = c.sign();
    if sc == Sign::Negative || sc == Sign::Unknown {
        return Sign::Unknown;
    }
    let (sa, sb) = (
        a.sign(),
        if sc == Sign::Zero {
            Sign::Zero
        } else {
            b.sign()
        },
    );
    match (sa, sb) {
        (Sign::Unknown, _) | (_, Sign::Unknown) => Sign::Unknown,
        (x, Sign::Zero) => x,
        (Sign::Zero, y) => y,
        (x, y) if x == y => x,
        (x, y) => match (a.sqr() - b.sqr() * c.clone()).sign() {
            Sign::Positive => x,
            Sign::Negative => y,
            s => s,
        },
    }
}
