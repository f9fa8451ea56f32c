//! [`Tolerance`]: the one tolerance type of lncert's options, results and
//! certificates — an exact positive rational and the largest `f64` below it.

use crate::scalar::{interval_from_rational, parse_rational, rational_from_f64, Rational};
use crate::Error;
use num_traits::Signed;
use std::fmt;
use std::str::FromStr;

/// A tolerance `tol > 0`: the exact rational the user claims, and the float
/// the engines compare their proven bounds with.
///
/// [`value`](Tolerance::value) is the exact rational **rounded down** to an
/// `f64`, so a bound proven `≤ value()` is `≤ exact()`: the claim written into
/// a certificate ([`exact`](Tolerance::exact)) is the one the engines proved.
/// A tolerance is always valid: positive, and its float is a positive normal
/// finite number (tolerances that round to 0, to a subnormal or beyond the
/// `f64` range are refused with a typed [`Error`] of field `tol`).
///
/// The same value is given once to the options ([`crate::OffsetOptions`],
/// [`crate::StrokeOptions`], [`crate::HausdorffConfig`]) and the certificates
/// built from their results ([`crate::Certificate`],
/// [`crate::union_certificate`]).
///
/// # Examples
/// ```
/// use lncert::{parse_rational, Tolerance};
/// let tol: Tolerance = "1e-3".parse().unwrap();
/// assert_eq!(tol.to_string(), "1/1000");
/// assert_eq!(*tol.exact(), parse_rational("1/1000").unwrap());
/// // 1e-3 as an f64 is slightly above 1/1000: the float compared with is one below
/// assert!(tol.value() < 1e-3 && tol.value().next_up() == 1e-3);
/// // a float tolerance is exactly that float
/// assert_eq!(Tolerance::from_f64(0.25).unwrap().value(), 0.25);
/// assert_eq!(Tolerance::from_f64(-1.0).unwrap_err().field, "tol");
/// ```
#[derive(Clone, Debug, PartialEq)]
pub struct Tolerance {
    exact: Rational,
    value: f64,
}

fn bad(reason: impl Into<String>) -> Error {
    Error::new("tol", reason)
}

impl Tolerance {
    /// The tolerance `exact`; refused (field `tol`) when it is not positive,
    /// when its largest float below is 0 or subnormal (below
    /// `f64::MIN_POSITIVE` ≈ 2.2e-308), or when it is beyond the `f64` range.
    pub fn new(exact: Rational) -> Result<Self, Error> {
        if !exact.is_positive() {
            return Err(bad(format!("{exact} is not > 0")));
        }
        let enclosure = interval_from_rational(&exact);
        if !enclosure.sup().is_finite() {
            return Err(bad(format!(
                "too large: {exact} is beyond the f64 range (above {:e})",
                f64::MAX
            )));
        }
        let mut value = enclosure.inf();
        // the enclosure is outward rounded, so `value ≤ exact`; checked exactly
        while value > 0.0 && rational_from_f64(value).is_none_or(|v| v > exact) {
            value = value.next_down();
        }
        if !value.is_normal() {
            return Err(bad(format!(
                "too small: {exact} rounds down to {value:e}, below the smallest normal f64 {:e}",
                f64::MIN_POSITIVE
            )));
        }
        Ok(Tolerance { exact, value })
    }

    /// The tolerance equal to the float `x` (`value() == x`, `exact()` its
    /// exact dyadic value); refused (field `tol`) for NaN, infinities,
    /// `x ≤ 0` and subnormals.
    pub fn from_f64(x: f64) -> Result<Self, Error> {
        if x.is_nan() || x.is_infinite() {
            return Err(bad(format!("{x} is not a finite number")));
        }
        if x <= 0.0 {
            return Err(bad(format!("{x:e} is not > 0")));
        }
        if !x.is_normal() {
            return Err(bad(format!(
                "too small: {x:e} is below the smallest normal f64 {:e}",
                f64::MIN_POSITIVE
            )));
        }
        let exact = rational_from_f64(x).ok_or_else(|| bad("not a finite number"))?;
        Ok(Tolerance { exact, value: x })
    }

    /// The exact tolerance, as claimed (and written into certificates).
    pub fn exact(&self) -> &Rational {
        &self.exact
    }

    /// The largest `f64` not above [`exact`](Tolerance::exact): what proven
    /// float bounds are compared with (a positive normal float).
    pub fn value(&self) -> f64 {
        self.value
    }

    /// The float nearest to the exact tolerance, for messages and reports
    /// (`1e-3` prints as `1e-3`); never for comparisons with proven bounds,
    /// which use [`value`](Tolerance::value).
    pub fn approx(&self) -> f64 {
        crate::scalar::Scalar::approx(&self.exact)
    }

    /// A search goal from a float the engine derived (a share of a
    /// tolerance, a target): `x` clamped to the positive normal floats, so a
    /// goal at or below 0 becomes the smallest one (the search then refutes
    /// it early). `None` for NaN. Only for search goals: a claim must be a
    /// checked tolerance.
    #[cfg_attr(not(feature = "kurbo"), allow(dead_code))]
    pub(crate) fn goal(x: f64) -> Option<Self> {
        if x.is_nan() {
            return None;
        }
        Tolerance::from_f64(x.clamp(f64::MIN_POSITIVE, f64::MAX)).ok()
    }
}

impl FromStr for Tolerance {
    type Err = Error;
    /// A decimal or a fraction ([`crate::parse_rational`]): `"1e-3"` is
    /// exactly 1/1000.
    fn from_str(s: &str) -> Result<Self, Error> {
        let exact = parse_rational(s).map_err(|e| bad(format!("{:?}: {}", e.input, e.reason)))?;
        Tolerance::new(exact)
    }
}

impl TryFrom<f64> for Tolerance {
    type Error = Error;
    fn try_from(x: f64) -> Result<Self, Error> {
        Tolerance::from_f64(x)
    }
}

impl TryFrom<Rational> for Tolerance {
    type Error = Error;
    fn try_from(r: Rational) -> Result<Self, Error> {
        Tolerance::new(r)
    }
}

impl fmt::Display for Tolerance {
    /// The exact rational (`1/1000`), as certificates write it.
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        write!(f, "{}", self.exact)
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use num_bigint::BigInt;
    use proptest::prelude::*;

    fn q(s: &str) -> Rational {
        parse_rational(s).unwrap()
    }

    /// `value ≤ exact < next float up`, checked with exact rationals.
    fn rounded_down(t: &Tolerance) -> bool {
        let v = Rational::from_float(t.value()).unwrap();
        let up = Rational::from_float(t.value().next_up()).unwrap();
        v <= *t.exact() && (v == *t.exact() || up > *t.exact())
    }

    #[test]
    fn non_dyadic_rounds_down() {
        for s in ["1/10", "1/1000", "1e-3", "2/3", "1e-11", "123456789/1000"] {
            let t: Tolerance = s.parse().unwrap();
            let v = Rational::from_float(t.value()).unwrap();
            assert!(v < *t.exact(), "{s}: the float must be below");
            let up = Rational::from_float(t.value().next_up()).unwrap();
            assert!(up > *t.exact(), "{s}: the next float up must be above");
            assert!(rounded_down(&t));
        }
        // 1e-3 and 0.1 as f64 are above the decimals: the value is one float below
        let t: Tolerance = "1e-3".parse().unwrap();
        assert_eq!(t.value().next_up(), 1e-3);
        assert_eq!(*t.exact(), q("1/1000"));
        assert_eq!(t.to_string(), "1/1000");
        assert_eq!(Tolerance::new(q("1/10")).unwrap().value().next_up(), 0.1);
        assert_eq!(t.approx(), 1e-3);
    }

    #[test]
    fn dyadic_round_trips() {
        for x in [
            0.25,
            1.0,
            3.0,
            1e-3,
            0.1,
            f64::MIN_POSITIVE,
            f64::MAX,
            1e300,
        ] {
            let t = Tolerance::from_f64(x).unwrap();
            assert_eq!(t.value(), x);
            assert_eq!(Rational::from_float(x).unwrap(), *t.exact());
            // through the exact rational and back: the same tolerance
            assert_eq!(Tolerance::new(t.exact().clone()).unwrap(), t);
            assert_eq!(Tolerance::try_from(x).unwrap(), t);
            assert_eq!(Tolerance::try_from(t.exact().clone()).unwrap(), t);
        }
        assert_eq!("0.25".parse::<Tolerance>().unwrap().to_string(), "1/4");
        assert_eq!(" 3/8 ".parse::<Tolerance>().unwrap().value(), 0.375);
    }

    #[test]
    fn errors_name_the_field_and_reason() {
        let reason = |e: Error| {
            assert_eq!(e.field, "tol");
            e.reason
        };
        assert!(reason(Tolerance::new(q("0")).unwrap_err()).contains("not > 0"));
        assert!(reason(Tolerance::new(q("-1/3")).unwrap_err()).contains("not > 0"));
        assert!(reason(Tolerance::new(q("1e-400")).unwrap_err()).starts_with("too small"));
        // subnormal: 2^-1074 · 3
        let sub = Rational::from_float(3.0 * f64::from_bits(1)).unwrap();
        assert!(reason(Tolerance::new(sub).unwrap_err()).starts_with("too small"));
        let huge = Rational::from_integer(BigInt::from(10).pow(400));
        assert!(reason(Tolerance::new(huge).unwrap_err()).starts_with("too large"));
        assert!(reason(Tolerance::from_f64(f64::NAN).unwrap_err()).contains("not a finite"));
        assert!(reason(Tolerance::from_f64(f64::INFINITY).unwrap_err()).contains("not a finite"));
        assert!(reason(Tolerance::from_f64(0.0).unwrap_err()).contains("not > 0"));
        assert!(reason(Tolerance::from_f64(-0.0).unwrap_err()).contains("not > 0"));
        assert!(reason(Tolerance::from_f64(-2.0).unwrap_err()).contains("not > 0"));
        assert!(
            reason(Tolerance::from_f64(f64::from_bits(5)).unwrap_err()).starts_with("too small")
        );
        assert!(reason("x".parse::<Tolerance>().unwrap_err()).contains("\"x\""));
        assert!(reason("1/0".parse::<Tolerance>().unwrap_err()).contains("zero denominator"));
        assert!(reason("-1e-3".parse::<Tolerance>().unwrap_err()).contains("not > 0"));
        assert!(reason(Tolerance::try_from(-1.0).unwrap_err()).contains("not > 0"));
        assert!(reason(Tolerance::try_from(q("0")).unwrap_err()).contains("not > 0"));
    }

    #[test]
    fn search_goals_are_clamped() {
        assert_eq!(Tolerance::goal(-1.0).unwrap().value(), f64::MIN_POSITIVE);
        assert_eq!(Tolerance::goal(0.0).unwrap().value(), f64::MIN_POSITIVE);
        assert_eq!(Tolerance::goal(f64::INFINITY).unwrap().value(), f64::MAX);
        assert_eq!(Tolerance::goal(0.5).unwrap().value(), 0.5);
        assert!(Tolerance::goal(f64::NAN).is_none());
    }

    proptest! {
        /// For random positive rationals in the normal range the float is the
        /// exact rational rounded down: `value ≤ exact` and the next float up
        /// is above it, compared as exact rationals (`Rational::from_float`).
        #[test]
        fn value_is_exact_rounded_down(
            n in 1u64..u64::MAX,
            d in 1u64..u64::MAX,
            e in -300i32..300,
        ) {
            let scale = Rational::from_integer(BigInt::from(2).pow(e.unsigned_abs()));
            let r = Rational::new(BigInt::from(n), BigInt::from(d));
            let r = if e >= 0 { r * scale } else { r / scale };
            let t = Tolerance::new(r.clone()).unwrap();
            prop_assert_eq!(t.exact(), &r);
            let v = Rational::from_float(t.value()).unwrap();
            prop_assert!(v <= r);
            let up = Rational::from_float(t.value().next_up()).unwrap();
            prop_assert!(v == r || up > r);
        }
    }
}
