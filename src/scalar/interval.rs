//! Certified enclosures: [`Scalar`] for inari's `Interval`, the tightest enclosure
//! of a rational, and rigorous `sin`/`cos` (inari is built without its `gmp`
//! feature, which is where its elementary functions live).

use super::rational::{rational_from_f64, rational_to_f64_bracket};
use super::{Rational, Scalar, ScalarSqrt, Sign};
pub use inari::Interval;

impl Scalar for Interval {
    const KIND: &'static str = "interval";
    const EXACT: bool = false;
    fn from_rational(r: &Rational) -> Self {
        interval_from_rational(r)
    }
    fn from_i64(n: i64) -> Self {
        if n.unsigned_abs() < 1 << 53 {
            let x = n as f64;
            Interval::try_from((x, x)).expect("finite")
        } else {
            interval_from_rational(&Rational::from_integer(n.into()))
        }
    }
    fn from_frac(p: i64, q: i64) -> Self {
        if p.unsigned_abs() < 1 << 53 && q.unsigned_abs() < 1 << 53 && q != 0 {
            // Exact point intervals; inari's division rounds outward.
            Self::from_i64(p) / Self::from_i64(q)
        } else {
            interval_from_rational(&Rational::new(p.into(), q.into()))
        }
    }
    fn sign(&self) -> Sign {
        if self.is_empty() {
            Sign::Unknown
        } else if self.inf() > 0.0 {
            Sign::Positive
        } else if self.sup() < 0.0 {
            Sign::Negative
        } else if self.inf() == 0.0 && self.sup() == 0.0 {
            Sign::Zero
        } else {
            Sign::Unknown
        }
    }
    fn recip(&self) -> Option<Self> {
        if self.is_empty() || self.contains(0.0) {
            None
        } else {
            Some(Interval::recip(*self))
        }
    }
    fn div(&self, d: &Self) -> Option<Self> {
        if d.is_empty() || d.contains(0.0) {
            None
        } else {
            Some(*self / *d)
        }
    }
    fn approx(&self) -> f64 {
        self.mid()
    }
    fn is_finite(&self) -> bool {
        !self.is_empty() && self.inf().is_finite() && self.sup().is_finite()
    }
    fn sqr(&self) -> Self {
        Interval::sqr(*self)
    }
    fn abs_val(&self) -> Self {
        Interval::abs(*self)
    }
}

impl ScalarSqrt for Interval {
    fn sqrt(&self) -> Option<Self> {
        if self.is_empty() || self.inf() < 0.0 {
            None
        } else {
            Some(Interval::sqrt(*self))
        }
    }
}

/// The point interval `[x, x]` of a float computed along the way (a hint, a
/// midpoint, a bound), and the whole line when `x` is not finite: an
/// overflowed value then makes every test that uses it fail (undecided or
/// invalid), never a panic (issue 65). Sound either way: the whole line
/// encloses every value.
///
/// # Examples
/// ```
/// use lncert::scalar::{point_interval, Interval};
/// assert_eq!(point_interval(0.5).inf(), 0.5);
/// assert_eq!(point_interval(f64::INFINITY), Interval::ENTIRE);
/// assert_eq!(point_interval(f64::NAN), Interval::ENTIRE);
/// ```
pub fn point_interval(x: f64) -> Interval {
    Interval::try_from((x, x)).unwrap_or(Interval::ENTIRE)
}

/// The tightest interval with float ends containing `r` (a point interval when
/// `r` is a float). Beyond the float range the enclosure is unbounded on that side.
///
/// # Examples
/// ```
/// use lncert::scalar::{interval_from_rational, parse_rational};
/// let x = interval_from_rational(&parse_rational("1/10").unwrap());
/// assert!(x.inf() < 0.1 || x.sup() > 0.1);
/// assert_eq!(x.inf().next_up(), x.sup());
/// ```
pub fn interval_from_rational(r: &Rational) -> Interval {
    let (lo, hi) = rational_to_f64_bracket(r);
    Interval::try_from((lo, hi)).expect("bracket is ordered")
}

/// Convenience methods on intervals.
pub trait IntervalExt {
    /// The point interval of a float, or `None` for NaN.
    fn point(x: f64) -> Option<Interval>;
    /// Whether the exact rational lies in the interval.
    fn contains_rational(&self, r: &Rational) -> bool;
    /// Encloses the printed decimal `digits` together with its rounding
    /// uncertainty (half a unit of its last printed digit).
    fn printed(digits: &str) -> Option<Interval>;
}

impl IntervalExt for Interval {
    fn point(x: f64) -> Option<Interval> {
        Interval::try_from((x, x)).ok()
    }
    fn contains_rational(&self, r: &Rational) -> bool {
        if self.is_empty() {
            return false;
        }
        let lo_ok = self.inf() == f64::NEG_INFINITY
            || rational_from_f64(self.inf()).is_some_and(|l| &l <= r);
        let hi_ok =
            self.sup() == f64::INFINITY || rational_from_f64(self.sup()).is_some_and(|h| &h >= r);
        lo_ok && hi_ok
    }
    fn printed(digits: &str) -> Option<Interval> {
        let r = super::parse_rational(digits).ok()?;
        let decimals = digits.trim().split_once('.').map_or(0, |(_, f)| {
            f.bytes().take_while(|b| b.is_ascii_digit()).count()
        });
        let half_unit = Rational::new(1.into(), 2.into())
            / Rational::from_integer(num_traits::pow(num_bigint::BigInt::from(10), decimals));
        let lo = interval_from_rational(&(&r - &half_unit));
        let hi = interval_from_rational(&(&r + &half_unit));
        Some(lo.convex_hull(hi))
    }
}

/// An interval as the JSON pair `[lo, hi]` (outward-rounded ends).
pub fn interval_to_json(x: &Interval) -> serde_json::Value {
    serde_json::json!([x.inf(), x.sup()])
}

/// Rigorous enclosures of `sin x` and `cos x` for every `x` in the interval.
///
/// Range reduction by an enclosure of pi/2, then Taylor series with a Lagrange
/// remainder bound `|r|^(n+1)/(n+1)!`. Intervals wider than 1 or with
/// `|x| > 1e6` get the trivial enclosure `[-1, 1]`.
///
/// # Examples
/// ```
/// use lncert::scalar::{sin_cos_enclosure, Interval};
/// let pi6 = Interval::PI / Interval::try_from((6.0, 6.0)).unwrap();
/// let (s, _c) = sin_cos_enclosure(pi6);
/// assert!(s.contains(0.5));
/// assert!(s.wid() < 1e-14);
/// ```
pub fn sin_cos_enclosure(x: Interval) -> (Interval, Interval) {
    let unit = Interval::try_from((-1.0, 1.0)).unwrap();
    if x.is_empty() || x.wid() > 1.0 || x.mag() > 1e6 {
        return (unit, unit);
    }
    let half_pi = Interval::PI / Interval::try_from((2.0, 2.0)).unwrap();
    let k = (x.mid() / half_pi.mid()).round();
    let r = x - Interval::try_from((k, k)).unwrap() * half_pi;
    let (s, c) = (sin_taylor(r), cos_taylor(r));
    let (s, c) = match (k as i64).rem_euclid(4) {
        0 => (s, c),
        1 => (c, -s),
        2 => (-s, -c),
        _ => (-c, s),
    };
    (s.intersection(unit), c.intersection(unit))
}

/// A rigorous enclosure of `atan x` for every `x` in the interval (any
/// finite or half-infinite interval; the empty interval gives the empty one).
///
/// Arguments beyond ±1 use `atan x = ±π/2 − atan(1/x)`. Three argument
/// halvings `atan x = 2 atan(x/(1 + √(1 + x²)))` then bring every argument
/// into `|z| ≤ tan(π/32) < 0.1`, where the alternating series
/// `z − z³/3 + …` with 12 terms leaves a tail below its next term,
/// `0.1²⁷/27 < 10⁻²⁸`; each step is evaluated with outward rounding.
///
/// # Examples
/// ```
/// use lncert::scalar::{atan_enclosure, Interval};
/// let one = Interval::try_from((1.0, 1.0)).unwrap();
/// let a = atan_enclosure(one);
/// assert!(a.contains(std::f64::consts::FRAC_PI_4));
/// assert!(a.wid() < 1e-14);
/// ```
pub fn atan_enclosure(x: Interval) -> Interval {
    if x.is_empty() {
        return x;
    }
    let half_pi = Interval::PI / Interval::try_from((2.0, 2.0)).unwrap();
    // beyond ±1: atan x = ±π/2 − atan(1/x), which keeps huge arguments tight
    let a = if x.inf() > 1.0 {
        half_pi - atan_reduced(x.recip())
    } else if x.sup() < -1.0 {
        -half_pi - atan_reduced(x.recip())
    } else {
        atan_reduced(x)
    };
    // atan is odd and below π/2 in magnitude
    a.intersection(Interval::try_from((-half_pi.sup(), half_pi.sup())).unwrap())
}

/// `atan` by three argument halvings and 12 terms of the series.
fn atan_reduced(x: Interval) -> Interval {
    let one = Interval::try_from((1.0, 1.0)).unwrap();
    let mut z = x;
    for _ in 0..3 {
        z = z / (one + (one + z.sqr()).sqrt());
    }
    let z2 = z.sqr();
    let mut term = z;
    let mut sum = z;
    let mut n = 1.0;
    for _ in 0..12 {
        term = -(term * z2);
        n += 2.0;
        sum += term / Interval::try_from((n, n)).unwrap();
    }
    let next = (term * z2 / Interval::try_from((n + 2.0, n + 2.0)).unwrap()).mag();
    let rem = Interval::try_from((-next, next)).unwrap_or(Interval::ENTIRE);
    Interval::try_from((8.0, 8.0)).unwrap() * (sum + rem)
}

/// Taylor polynomial of degree 2N+1 plus remainder, valid for |r| <= 1.
fn sin_taylor(r: Interval) -> Interval {
    taylor(r, 1)
}
fn cos_taylor(r: Interval) -> Interval {
    taylor(r, 0)
}

fn taylor(r: Interval, start: u32) -> Interval {
    const TERMS: u32 = 14;
    let one = Interval::try_from((1.0, 1.0)).unwrap();
    let mut term = if start == 1 { r } else { one };
    let mut sum = term;
    let mut n = start;
    for _ in 0..TERMS {
        let a = Interval::try_from(((n + 1) as f64, (n + 1) as f64)).unwrap();
        let b = Interval::try_from(((n + 2) as f64, (n + 2) as f64)).unwrap();
        term = -(term * r * r) / (a * b);
        sum += term;
        n += 2;
    }
    // Remainder of the alternating tail: bounded by the next term in magnitude.
    let a = Interval::try_from(((n + 1) as f64, (n + 1) as f64)).unwrap();
    let b = Interval::try_from(((n + 2) as f64, (n + 2) as f64)).unwrap();
    let next = (term * r * r / (a * b)).mag();
    let rem = Interval::try_from((-next, next)).unwrap();
    sum + rem
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::scalar::parse_rational;

    #[test]
    fn enclosure_contains_the_rational() {
        for s in ["1/3", "-7/6", "0.95", "1e-300", "-123456789/1000", "5"] {
            let r = parse_rational(s).unwrap();
            let x = interval_from_rational(&r);
            assert!(x.contains_rational(&r), "{s}");
        }
    }

    #[test]
    fn atan_encloses_std_and_is_tight() {
        let mut xs: Vec<f64> = (-60..=60).map(|i| i as f64 * 0.173).collect();
        xs.extend([1e-300, -1e-9, 1.0, -1.0, 1e6, -3e12, 1e300]);
        for x in xs {
            let a = atan_enclosure(Interval::point(x).unwrap());
            // f64 atan is within an ulp or two of the truth
            let t = x.atan();
            assert!(
                a.inf() <= t.next_up() && t.next_down() <= a.sup(),
                "atan {x}: {a:?}"
            );
            assert!(a.wid() < 1e-14, "atan {x}: {a:?}");
        }
        // exact values: atan 1 = π/4, atan √3 = π/3 (√3 enclosed)
        let pi = Interval::PI;
        let four = Interval::point(4.0).unwrap();
        let one = atan_enclosure(Interval::point(1.0).unwrap());
        assert!(!(pi / four).disjoint(one));
        let r3 = Interval::point(3.0).unwrap().sqrt();
        assert!(!(pi / Interval::point(3.0).unwrap()).disjoint(atan_enclosure(r3)));
        // a wide argument: every value inside
        let w = atan_enclosure(Interval::try_from((-2.0, 0.5)).unwrap());
        assert!(w.contains((-2f64).atan()) && w.contains(0.5f64.atan()) && w.contains(0.0));
    }

    #[test]
    fn sin_cos_match_std_and_are_tight() {
        for i in -40..=40 {
            let x = i as f64 * 0.37;
            let (s, c) = sin_cos_enclosure(Interval::point(x).unwrap());
            assert!(
                s.contains(x.sin()) || (s.inf() - x.sin()).abs() < 1e-15,
                "sin {x}"
            );
            assert!(
                c.contains(x.cos()) || (c.inf() - x.cos()).abs() < 1e-15,
                "cos {x}"
            );
            assert!(s.wid() < 1e-13 && c.wid() < 1e-13);
            // sin^2 + cos^2 = 1 must be inside the enclosure.
            assert!((s.sqr() + c.sqr()).contains(1.0));
        }
    }

    #[test]
    fn printed_digits_enclose_half_unit() {
        let p = Interval::printed("1.29").unwrap();
        assert!(p.contains(1.285) && p.contains(1.2949) && !p.contains(1.296));
    }
}
