//! Exact rationals (`BigRational`): parsing decimal and fraction literals exactly,
//! exact conversion from `f64`, and the [`Scalar`] impl.

use super::{Scalar, Sign};
use num_bigint::BigInt;
use num_traits::{One, Signed, ToPrimitive, Zero};

/// Exact rational numbers, the ground truth of every decision.
pub type Rational = num_rational::BigRational;

impl Scalar for Rational {
    const KIND: &'static str = "rational";
    const EXACT: bool = true;
    fn from_rational(r: &Rational) -> Self {
        r.clone()
    }
    fn from_i64(n: i64) -> Self {
        Rational::from_integer(BigInt::from(n))
    }
    fn sign(&self) -> Sign {
        if self.is_zero() {
            Sign::Zero
        } else if self.is_positive() {
            Sign::Positive
        } else {
            Sign::Negative
        }
    }
    fn recip(&self) -> Option<Self> {
        if self.is_zero() {
            None
        } else {
            Some(num_traits::Inv::inv(self.clone()))
        }
    }
    fn approx(&self) -> f64 {
        rational_to_f64_nearest(self)
    }
    fn bernstein_eval(c: &[Self], t: &Self) -> Option<Self> {
        if c.is_empty() {
            return None;
        }
        if t.is_zero() {
            return Some(c[0].clone());
        }
        if t.is_one() {
            return Some(c[c.len() - 1].clone());
        }
        let (mut p, den) = common_numerators(c);
        let (pt, qt) = (t.numer(), t.denom());
        let rest = qt - pt;
        let n = p.len() - 1;
        for r in 0..n {
            for j in 0..n - r {
                p[j] = &rest * &p[j] + pt * &p[j + 1];
            }
        }
        Some(Rational::new(p.swap_remove(0), den * qt.pow(n as u32)))
    }
    fn bernstein_restrict(c: &[Self], a: &Self, b: &Self) -> Option<Vec<Self>> {
        if c.is_empty() {
            return None;
        }
        let (nums, den) = common_numerators(c);
        let n = nums.len() - 1;
        let (pa, qa) = (a.numer(), a.denom());
        let (pb, qb) = (b.numer(), b.denom());
        let (ra, rb) = (qa - pa, qb - pb);
        Some(
            (0..=n)
                .map(|i| {
                    // blossom c(a^(n−i), b^i): de Casteljau steps with
                    // integer weights (q − p, p), the denominators collected
                    let mut p = nums.clone();
                    for r in 0..n {
                        let (pu, ru) = if r < n - i { (pa, &ra) } else { (pb, &rb) };
                        for j in 0..n - r {
                            p[j] = ru * &p[j] + pu * &p[j + 1];
                        }
                    }
                    let d = &den * qa.pow((n - i) as u32) * qb.pow(i as u32);
                    Rational::new(p.swap_remove(0), d)
                })
                .collect(),
        )
    }
    fn bernstein_to_power(b: &[Self]) -> Option<Vec<Self>> {
        if b.is_empty() {
            return None;
        }
        // c_k = C(n, k) Σ_{j ≤ k} (−1)^(k−j) C(k, j) b_j
        let (nums, den) = common_numerators(b);
        let n = nums.len() - 1;
        let binom = |n: usize, k: usize| -> BigInt {
            let mut v = BigInt::from(1u32);
            for i in 0..k {
                v = v * BigInt::from(n - i) / BigInt::from(i + 1);
            }
            v
        };
        Some(
            (0..=n)
                .map(|k| {
                    let mut s = BigInt::zero();
                    for (j, x) in nums.iter().enumerate().take(k + 1) {
                        let w = binom(k, j);
                        if (k - j) % 2 == 0 {
                            s += w * x;
                        } else {
                            s -= w * x;
                        }
                    }
                    Rational::new(s * binom(n, k), den.clone())
                })
                .collect(),
        )
    }
}

/// The values `x_k = n_k / d` with one common denominator `d` (the least
/// common multiple of theirs): `(n_k, d)`.
fn common_numerators(xs: &[Rational]) -> (Vec<BigInt>, BigInt) {
    use num_integer::Integer;
    let mut d = BigInt::from(1u32);
    for x in xs {
        if !x.denom().is_one() {
            d = d.lcm(x.denom());
        }
    }
    let nums = xs
        .iter()
        .map(|x| {
            if x.denom() == &d {
                x.numer().clone()
            } else {
                x.numer() * (&d / x.denom())
            }
        })
        .collect();
    (nums, d)
}

/// Why a number literal was rejected.
#[derive(Clone, Debug, PartialEq, Eq, thiserror::Error)]
#[error("cannot read {input:?} as an exact number: {reason}")]
pub struct ParseNumberError {
    /// The text as given.
    pub input: String,
    /// What is wrong with it.
    pub reason: &'static str,
}

/// Largest decimal scale accepted, `|e| <= 400` after the decimal point is
/// accounted for: beyond the f64 range (1e±308) with room to spare, and small
/// enough that hostile input (thousands of `1e-4000` literals) stays cheap.
pub const MAX_EXPONENT: i64 = 400;

/// Reads a decimal (`-0.95`, `1.5e-3`) or fraction (`1/3`, `-7/6`) literal
/// *exactly*: `0.95` is `19/20`, never the nearest float.
///
/// # Examples
/// ```
/// use lncert::scalar::{parse_rational, rational_to_string};
/// assert_eq!(rational_to_string(&parse_rational("0.95").unwrap()), "19/20");
/// assert_eq!(rational_to_string(&parse_rational("-1/3").unwrap()), "-1/3");
/// assert_eq!(rational_to_string(&parse_rational("2.5e-1").unwrap()), "1/4");
/// assert!(parse_rational("NaN").is_err());
/// assert!(parse_rational("1/0").is_err());
/// ```
pub fn parse_rational(text: &str) -> Result<Rational, ParseNumberError> {
    let err = |reason| ParseNumberError {
        input: text.to_string(),
        reason,
    };
    let s = text.trim();
    if s.is_empty() {
        return Err(err("empty"));
    }
    if let Some((num, den)) = s.split_once('/') {
        let n = parse_decimal(num.trim()).map_err(err)?;
        let d = parse_decimal(den.trim()).map_err(err)?;
        if d.is_zero() {
            return Err(err("zero denominator"));
        }
        return Ok(n / d);
    }
    parse_decimal(s).map_err(err)
}

fn parse_decimal(s: &str) -> Result<Rational, &'static str> {
    let (neg, body) = match s.as_bytes().first() {
        Some(b'-') => (true, &s[1..]),
        Some(b'+') => (false, &s[1..]),
        Some(_) => (false, s),
        None => return Err("empty"),
    };
    let (mantissa, exp) = match body.find(['e', 'E']) {
        Some(i) => {
            let e: i64 = body[i + 1..].parse().map_err(|_| "malformed exponent")?;
            (&body[..i], e)
        }
        None => (body, 0),
    };
    let (int_part, frac_part) = mantissa.split_once('.').unwrap_or((mantissa, ""));
    if int_part.is_empty() && frac_part.is_empty() {
        return Err("no digits");
    }
    if !int_part
        .bytes()
        .chain(frac_part.bytes())
        .all(|b| b.is_ascii_digit())
    {
        return Err("not a finite decimal or fraction (digits, '.', 'e', '/' only)");
    }
    let digits = format!("{int_part}{frac_part}");
    let scale = i64::try_from(frac_part.len())
        .ok()
        .and_then(|f| exp.checked_sub(f))
        .filter(|s| s.abs() <= MAX_EXPONENT)
        .ok_or("exponent out of range (|e| > 400)")?;
    let mut value = Rational::from_integer(digits.parse::<BigInt>().map_err(|_| "no digits")?);
    let ten = BigInt::from(10u32);
    let pow = num_traits::pow(ten, scale.unsigned_abs() as usize);
    if scale >= 0 {
        value *= Rational::from_integer(pow);
    } else {
        value /= Rational::from_integer(pow);
    }
    Ok(if neg { -value } else { value })
}

/// A finite float as `(m, e)` with `|x| = m·2^e`, `m` odd (or `0` for a
/// zero): the exact dyadic value, without rounding.
pub(crate) fn float_parts(x: f64) -> (u64, i64) {
    let bits = x.to_bits();
    let exp = ((bits >> 52) & 0x7ff) as i64;
    let frac = bits & ((1u64 << 52) - 1);
    let (m, e) = if exp == 0 {
        (frac, -1074)
    } else {
        (frac | (1u64 << 52), exp - 1075)
    };
    if m == 0 {
        return (0, 0);
    }
    let tz = m.trailing_zeros();
    (m >> tz, e + tz as i64)
}

/// The exact rational value of a finite float; `None` for NaN and infinities.
///
/// # Examples
/// ```
/// use lncert::scalar::{rational_from_f64, rational_to_string};
/// assert_eq!(rational_to_string(&rational_from_f64(0.75).unwrap()), "3/4");
/// assert!(rational_from_f64(f64::NAN).is_none());
/// ```
pub fn rational_from_f64(x: f64) -> Option<Rational> {
    if !x.is_finite() {
        return None;
    }
    if x == 0.0 {
        return Some(<Rational as Zero>::zero());
    }
    // x = ±m·2^e with m odd: already in lowest terms (an odd numerator over
    // a power of two), so no gcd is needed
    let (m, e) = float_parts(x);
    let n = if x < 0.0 {
        -BigInt::from(m)
    } else {
        BigInt::from(m)
    };
    Some(if e >= 0 {
        Rational::from_integer(n << e as usize)
    } else {
        Rational::new_raw(n, BigInt::one() << (-e) as usize)
    })
}

/// `|r| ≤ 10^e`, decided exactly.
///
/// # Examples
/// ```
/// use lncert::scalar::{abs_le_pow10, parse_rational};
/// assert!(abs_le_pow10(&parse_rational("-1e100").unwrap(), 100));
/// let just_above = parse_rational("1e100").unwrap() + parse_rational("1e-400").unwrap();
/// assert!(!abs_le_pow10(&just_above, 100));
/// ```
pub fn abs_le_pow10(r: &Rational, e: u32) -> bool {
    // |n/d| < 2^(bits(n) − bits(d) + 1) ≤ 2^⌊e·log₂10⌋ < 10^e: no big power needed
    let (nb, db) = (r.numer().bits(), r.denom().bits());
    if nb < db + (e as u64 * 3321928) / 1000000 {
        return true;
    }
    let bound = num_traits::pow(BigInt::from(10u32), e as usize);
    r.numer().abs() <= bound * r.denom().abs()
}

/// `"p/q"` (or `"p"` for integers), the CLI's and JSON's exact format.
pub fn rational_to_string(r: &Rational) -> String {
    r.to_string()
}

/// Nearest float (ties to even) of a rational; `±inf` beyond the float range.
pub(crate) fn rational_to_f64_nearest(r: &Rational) -> f64 {
    if let Some(x) = dyadic_f64(r) {
        return x;
    }
    if let Some(x) = normal_nearest(r) {
        return x;
    }
    nearest_by_bracket(r)
}

/// [`rational_to_f64_nearest`] by the bracket and an exact comparison of the
/// distances to its ends (the general path, and the tests' oracle).
fn nearest_by_bracket(r: &Rational) -> f64 {
    let (lo, hi) = rational_to_f64_bracket(r);
    if lo == hi {
        return lo;
    }
    // Pick the nearer end exactly.
    match (rational_from_f64(lo), rational_from_f64(hi)) {
        (Some(l), Some(h)) => {
            let dl = r - &l;
            let dh = &h - r;
            if dl < dh || (dl == dh && lo.to_bits() % 2 == 0) {
                lo
            } else {
                hi
            }
        }
        (None, _) => hi,
        (_, None) => lo,
    }
}

/// Floats `lo <= r <= hi` with `lo == hi` iff `r` is a float; adjacent otherwise.
/// Outside the float range the bracket ends at `±inf`.
pub(crate) fn rational_to_f64_bracket(r: &Rational) -> (f64, f64) {
    if let Some(x) = dyadic_f64(r) {
        return (x, x);
    }
    if let Some(b) = normal_bracket(r) {
        return b;
    }
    walk_bracket(r)
}

/// The bracket by comparisons: from a float near `r`, step by ulps.
fn walk_bracket(r: &Rational) -> (f64, f64) {
    let guess = approx_quotient(r);
    if !guess.is_finite() {
        return if r.is_negative() {
            (f64::NEG_INFINITY, -f64::MAX)
        } else {
            (f64::MAX, f64::INFINITY)
        };
    }
    let mut lo = guess;
    // Walk down until lo <= r, then up until the next float exceeds r.
    while rational_from_f64(lo).is_some_and(|v| &v > r) {
        lo = lo.next_down();
    }
    loop {
        let nx = lo.next_up();
        match rational_from_f64(nx) {
            Some(v) if &v <= r => lo = nx,
            _ => break,
        }
    }
    if rational_from_f64(lo).is_some_and(|v| &v == r) {
        (lo, lo)
    } else {
        (lo, lo.next_up())
    }
}

/// The float equal to `r` when `r = n / 2^k` with `|n| < 2^53` and `k ≤ 1022`
/// (every number the search writes into a certificate): `n` and `2^-k` are
/// floats, and their product is exact since it is a normal float or zero.
/// `None` otherwise (the caller brackets `r` by comparisons).
fn dyadic_f64(r: &Rational) -> Option<f64> {
    let (n, d) = (r.numer(), r.denom());
    let k = d.bits().checked_sub(1)?;
    if n.bits() > 53 || k > 1022 || d.trailing_zeros() != Some(k) {
        return None;
    }
    // n·2^-k ≥ 2^-1022 in magnitude (n ≠ 0) or zero: a normal float, exact
    let nf = n.to_f64()?;
    Some(nf * f64::from_bits((1023 - k) << 52))
}

/// `(q, exact, s)` with `q = ⌊|r|·2^s⌋` of exactly `k` significant bits and
/// `exact` when `q = |r|·2^s`, by one big-integer division (two when the
/// first quotient has a bit too many); `None` for `r = 0` or `|r|` beyond
/// `2^±1000` (the callers' normal range).
fn quotient_bits(r: &Rational, k: i64) -> Option<(BigInt, bool, i64)> {
    let (a, b) = (r.numer().magnitude(), r.denom().magnitude());
    if a.is_zero() {
        return None;
    }
    // 2^(e − 1) < |r| < 2^(e + 1)
    let e = a.bits() as i64 - b.bits() as i64;
    if !(-1000..=1000).contains(&e) {
        return None;
    }
    // s so that 2^(k−1) ≤ |r| 2^s < 2^(k+1); then one bit less if needed
    let div = |s: i64| {
        let (num, den) = if s >= 0 {
            (a << s as usize, b.clone())
        } else {
            (a.clone(), b << (-s) as usize)
        };
        let (q, rem) = num_integer::Integer::div_rem(&num, &den);
        (q, rem.is_zero())
    };
    let mut s = k - e;
    let (mut q, mut exact) = div(s);
    if q.bits() as i64 > k {
        s -= 1;
        (q, exact) = div(s);
    }
    (q.bits() as i64 == k).then(|| (BigInt::from(q), exact, s))
}

/// The bracket of `r` by one big-integer division when both ends are normal
/// floats: `q = ⌊|n| 2^s / d⌋` with 53 significant bits, so `q 2^-s ≤ |r| <
/// (q + 1) 2^-s` and both are floats (`q + 1 = 2^53` included). `None`
/// outside the normal range (the caller walks instead).
fn normal_bracket(r: &Rational) -> Option<(f64, f64)> {
    if r.numer().is_zero() {
        return Some((0.0, 0.0));
    }
    let (q, exact, s) = quotient_bits(r, 53)?;
    let qf = q.to_f64()?; // exact: 53 bits
    let scale = 2f64.powi(-(s as i32)); // exact power of two, normal for |s| ≤ 1060
    let lo = qf * scale;
    let hi = (qf + 1.0) * scale;
    if !(lo.is_normal() && hi.is_finite()) {
        return None;
    }
    Some(match (r.is_negative(), exact) {
        (false, true) => (lo, lo),
        (true, true) => (-lo, -lo),
        (false, false) => (lo, hi),
        (true, false) => (-hi, -lo),
    })
}

/// The nearest float (ties to even) by one big-integer division when it is a
/// normal float: `q = ⌊|n| 2^s / d⌋` with 54 significant bits, whose last bit
/// is the half-ulp bit and whose remainder is the sticky bit, so `⌊q/2⌋`
/// rounded to nearest even by them is the significand. `None` outside the
/// normal range (the caller brackets instead).
fn normal_nearest(r: &Rational) -> Option<f64> {
    if r.numer().is_zero() {
        return Some(0.0);
    }
    let (q, exact, s) = quotient_bits(r, 54)?;
    let q = q.to_u64()?;
    let (mut m, half) = (q >> 1, q & 1 == 1);
    if half && (!exact || m & 1 == 1) {
        m += 1; // at most 2^53: still exact in a float
    }
    // |r| rounds to m·2^-(s − 1); the scale is an exact power of two
    let scale = 2f64.powi(-(s as i32 - 1));
    let v = m as f64 * scale;
    if !(v.is_normal() && scale.is_normal()) {
        return None;
    }
    Some(if r.is_negative() { -v } else { v })
}

/// A float close to `r` (within a few ulps) without overflow on huge numerators.
fn approx_quotient(r: &Rational) -> f64 {
    let (n, d) = (r.numer(), r.denom());
    let nb = n.bits() as i64;
    let db = d.bits() as i64;
    // Shift both to ~64 significant bits, then scale by 2^(shift difference).
    let sn = (nb - 64).max(0);
    let sd = (db - 64).max(0);
    let nf = (n >> sn as usize).to_f64().unwrap_or(f64::NAN);
    let df = (d >> sd as usize).to_f64().unwrap_or(f64::NAN);
    let e = sn - sd;
    let q = nf / df;
    if e > 2100 {
        return if q == 0.0 {
            0.0
        } else {
            q.signum() * f64::INFINITY
        };
    }
    if e < -2200 {
        return 0.0 * q.signum();
    }
    // Apply 2^e in two steps to avoid intermediate overflow/underflow.
    let half = e / 2;
    q * 2f64.powi(half as i32) * 2f64.powi((e - half) as i32)
}

#[cfg(test)]
mod tests {
    /// The dyadic fast path of `rational_to_f64_bracket` agrees with the
    /// comparison walk: every float is its own bracket, and a rational between
    /// two floats is bracketed by them.
    #[test]
    fn dyadic_fast_path_is_exact() {
        use super::*;
        let mut x = 1.0f64;
        let mut seen = 0;
        for i in 0..4000u64 {
            // a spread of magnitudes and signs, normal and subnormal
            x = f64::from_bits(
                x.to_bits()
                    .wrapping_mul(6364136223846793005)
                    .wrapping_add(i)
                    >> 1,
            );
            for v in [
                x,
                -x,
                x.sqrt(),
                1.0 / (1.0 + x.abs()),
                f64::MIN_POSITIVE * 3.0,
                5e-324,
            ] {
                if !v.is_finite() {
                    continue;
                }
                let r = rational_from_f64(v).unwrap();
                assert_eq!(rational_to_f64_bracket(&r), (v, v), "{v:e}");
                let next = rational_from_f64(v.next_up()).unwrap();
                let between = (&r + &next) / Rational::from_integer(2.into());
                assert_eq!(rational_to_f64_bracket(&between), (v, v.next_up()), "{v:e}");
                seen += 1;
            }
        }
        assert!(seen > 10_000);
    }

    use super::*;

    /// The one-division bracket agrees with the comparison walk on rationals
    /// that are not dyadic, over signs and magnitudes (and declines outside
    /// the normal range).
    #[test]
    fn division_bracket_matches_the_walk() {
        let mut x = 0x9e3779b97f4a7c15u64;
        let mut next = || {
            x ^= x << 13;
            x ^= x >> 7;
            x ^= x << 17;
            x
        };
        let mut checked = 0;
        for _ in 0..3000 {
            let n = BigInt::from(next() >> (next() % 64)) * BigInt::from(next() % 1000 + 1);
            let d = BigInt::from((next() >> (next() % 64)) | 1) * BigInt::from(3 + next() % 5);
            let shift = (next() % 2200) as usize;
            let n = if next() % 2 == 0 { -n } else { n };
            for (nn, dd) in [
                (n.clone() << shift, d.clone()),
                (n.clone(), d.clone() << shift),
                (n.clone(), d.clone()),
            ] {
                let r = Rational::new(nn, dd);
                if let Some(b) = normal_bracket(&r) {
                    assert_eq!(b, walk_bracket(&r), "{r}");
                    checked += 1;
                }
            }
        }
        assert!(checked > 3000, "{checked}");
        assert_eq!(normal_bracket(&parse_rational("1e-320").unwrap()), None);
        assert_eq!(normal_bracket(&parse_rational("1e400").unwrap()), None);
    }

    /// The one-division nearest float agrees with the bracket and an exact
    /// comparison of distances, ties included (halfway rationals round to
    /// the even significand), and declines outside the normal range.
    #[test]
    fn division_nearest_matches_the_exact_comparison() {
        let mut x = 0x2545f4914f6cdd1du64;
        let mut next = || {
            x ^= x << 13;
            x ^= x >> 7;
            x ^= x << 17;
            x
        };
        let (mut checked, mut ties) = (0, 0);
        for _ in 0..3000 {
            let n = BigInt::from(next() >> (next() % 64)) * BigInt::from(next() % 1000 + 1);
            let d = BigInt::from((next() >> (next() % 64)) | 1) * BigInt::from(3 + next() % 5);
            let shift = (next() % 2200) as usize;
            let n = if next() % 2 == 0 { -n } else { n };
            // a halfway point between two adjacent floats (a tie) and points
            // a hair beside it
            let v = f64::from_bits(next() % 0x7fe0_0000_0000_0000);
            let (lo, hi) = (
                rational_from_f64(v).unwrap(),
                rational_from_f64(v.next_up()).unwrap(),
            );
            let mid = (&lo + &hi) / Rational::from_integer(2.into());
            let hair = (&hi - &lo) / Rational::from_integer(BigInt::from(1u64 << 40));
            for r in [
                Rational::new(n.clone() << shift, d.clone()),
                Rational::new(n.clone(), d.clone() << shift),
                Rational::new(n.clone(), d.clone()),
                mid.clone(),
                &mid + &hair,
                &mid - &hair,
            ] {
                if let Some(f) = normal_nearest(&r) {
                    assert_eq!(f.to_bits(), nearest_by_bracket(&r).to_bits(), "{r}");
                    checked += 1;
                    ties += usize::from(r == mid);
                }
            }
        }
        assert!(checked > 8000 && ties > 2000, "{checked} {ties}");
        assert_eq!(normal_nearest(&parse_rational("1e-320").unwrap()), None);
        assert_eq!(normal_nearest(&parse_rational("1e400").unwrap()), None);
    }

    /// The float to rational conversion is `num-rational`'s exactly (lowest
    /// terms), for normal, subnormal, integral and signed floats.
    #[test]
    fn float_to_rational_matches_num_rational() {
        let mut x = 0x9e3779b97f4a7c15u64;
        for i in 0..20_000u64 {
            x ^= x << 13;
            x ^= x >> 7;
            x ^= x << 17;
            let v = f64::from_bits(x);
            for v in [v, (i as f64) * 0.25, -(i as f64), 5e-324, -0.0, f64::MAX] {
                if v.is_finite() {
                    let r = rational_from_f64(v).unwrap();
                    assert_eq!(r, Rational::from_float(v).unwrap(), "{v:e}");
                    assert_eq!(r.reduced(), r, "{v:e}");
                }
            }
        }
        assert_eq!(rational_from_f64(f64::NAN), None);
        assert_eq!(rational_from_f64(f64::INFINITY), None);
    }

    #[test]
    fn bracket_is_tight_and_correct() {
        for s in [
            "1/3",
            "-1/3",
            "0.1",
            "1e-320",
            "123456789012345678901234567890/7",
            "-2/3",
        ] {
            let r = parse_rational(s).unwrap();
            let (lo, hi) = rational_to_f64_bracket(&r);
            assert!(rational_from_f64(lo).unwrap() <= r, "{s}");
            assert!(rational_from_f64(hi).unwrap() >= r, "{s}");
            assert!(lo == hi || lo.next_up() == hi, "{s}");
        }
        let big = parse_rational("1e400").unwrap();
        assert_eq!(rational_to_f64_bracket(&big), (f64::MAX, f64::INFINITY));
    }

    #[test]
    fn nearest_matches_std_parse_for_decimals() {
        for s in ["0.1", "0.95", "-2.5e-3", "1e22", "3.14159", "7e-310"] {
            let r = parse_rational(s).unwrap();
            assert_eq!(
                rational_to_f64_nearest(&r),
                s.parse::<f64>().unwrap(),
                "{s}"
            );
        }
    }

    #[test]
    fn parse_rejects_garbage() {
        for s in [
            "", "-", "1/", "/2", "1.2.3", "inf", "1e", "0x10", "1/0", "1e99999", "--1",
        ] {
            assert!(parse_rational(s).is_err(), "{s:?} should be rejected");
        }
    }
}

#[cfg(test)]
mod bernstein_fast_path_tests {
    use super::*;
    use proptest::prelude::*;

    /// Σ C(n, k) t^k (1 − t)^(n − k) c_k, term by term (the oracle).
    fn bernstein_sum(c: &[Rational], t: &Rational) -> Rational {
        let n = c.len() - 1;
        let one = <Rational as One>::one();
        let mut s = <Rational as Zero>::zero();
        for (k, ck) in c.iter().enumerate() {
            let mut binom = BigInt::from(1u32);
            for i in 0..k {
                binom = binom * BigInt::from(n - i) / BigInt::from(i + 1);
            }
            let mut term = ck.clone() * Rational::from_integer(binom);
            for _ in 0..k {
                term *= t;
            }
            for _ in 0..n - k {
                term *= &one - t;
            }
            s += term;
        }
        s
    }

    fn rat() -> impl Strategy<Value = Rational> {
        (-10_000i64..10_000, 1i64..5_000).prop_map(|(p, q)| Rational::new(p.into(), q.into()))
    }

    proptest! {
        #[test]
        fn fast_paths_agree_with_the_bernstein_sum(
            c in prop::collection::vec(rat(), 1..8),
            a in rat(),
            b in rat(),
            u in rat(),
        ) {
            // eval at t, and at the end parameters
            for t in [&a, &<Rational as Zero>::zero(), &<Rational as One>::one()] {
                prop_assert_eq!(Rational::bernstein_eval(&c, t).unwrap(), bernstein_sum(&c, t));
            }
            // restrict: the part over [a, b] at u is the whole at a + u (b − a)
            let r = Rational::bernstein_restrict(&c, &a, &b).unwrap();
            prop_assert_eq!(r.len(), c.len());
            let at = &a + &u * (&b - &a);
            prop_assert_eq!(bernstein_sum(&r, &u), bernstein_sum(&c, &at));
            // power basis: Σ p_k t^k is the Bernstein sum
            let p = Rational::bernstein_to_power(&c).unwrap();
            prop_assert_eq!(p.len(), c.len());
            let mut v = <Rational as Zero>::zero();
            for pk in p.iter().rev() {
                v = v * &u + pk;
            }
            prop_assert_eq!(v, bernstein_sum(&c, &u));
        }
    }
}
