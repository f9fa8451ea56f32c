//! Polynomials on `[0, 1]` in the **scaled Bernstein basis**
//! `t^k (1 − t)^(n−k)`, `k = 0..=n`: the coefficient `c_k` is the Bernstein
//! coefficient times `C(n, k)`.
//!
//! In this basis a product is a plain convolution of the coefficient lists
//! and degree elevation (multiplying by `1 = t + (1 − t)`) is a convolution
//! with a row of Pascal's triangle, so a polynomial built from integer
//! Bernstein data stays an integer list: no denominators and no gcds. The
//! signs of the `c_k` are those of the Bernstein coefficients (`C(n, k) > 0`),
//! so coefficients of one strict sign prove that sign on all of `[0, 1]`, and
//! the Bernstein coefficients `c_k / C(n, k)` enclosed in intervals feed the
//! interval subdivision of [`super::isolate_simple_roots_bernstein`]. The exact
//! sign at a rational `t = a/q ∈ [0, 1]` is that of the integer
//! `q^n p(t) = Σ c_k a^k (q − a)^(n−k)` (homogeneous Horner).

use super::roots::RealRoot;
use crate::scalar::{interval_from_rational, rational_from_f64, Interval, Rational};
use num_bigint::{BigInt, Sign};
use num_traits::{One, Zero};
use std::ops::{Add, Mul, Sub};

/// The coefficient rings of [`Scaled`]: exact integers and intervals.
pub(crate) trait Ring:
    Clone + Add<Output = Self> + Sub<Output = Self> + Mul<Output = Self>
{
    /// `0`.
    fn zero() -> Self;
    /// An integer (exactly, or enclosed).
    fn from_int(b: &BigInt) -> Self;
}

impl Ring for BigInt {
    fn zero() -> Self {
        <BigInt as Zero>::zero()
    }
    fn from_int(b: &BigInt) -> Self {
        b.clone()
    }
}

impl Ring for Interval {
    fn zero() -> Self {
        Interval::try_from((0.0, 0.0)).expect("0 is an interval")
    }
    fn from_int(b: &BigInt) -> Self {
        interval_from_rational(&Rational::from_integer(b.clone()))
    }
}

/// Row `n` of Pascal's triangle.
fn pascal_row(n: usize) -> Vec<BigInt> {
    let mut row = vec![BigInt::one()];
    for k in 0..n {
        let next = &row[k] * (n - k) / (k + 1);
        row.push(next);
    }
    row
}

/// A polynomial on `[0, 1]` by its coefficients in the basis
/// `t^k (1 − t)^(n−k)` (never empty).
#[derive(Clone, Debug, PartialEq)]
pub(crate) struct Scaled<T>(pub(crate) Vec<T>);

impl<T: Ring> Scaled<T> {
    /// From Bernstein coefficients `b_k` (degree `b.len() − 1`, at least one).
    pub(crate) fn from_bernstein(b: &[T]) -> Self {
        let row = pascal_row(b.len().saturating_sub(1));
        Scaled(
            b.iter()
                .zip(&row)
                .map(|(x, c)| x.clone() * T::from_int(c))
                .collect(),
        )
    }

    /// The degree `n`.
    pub(crate) fn degree(&self) -> usize {
        self.0.len().saturating_sub(1)
    }

    /// The product (degrees add).
    pub(crate) fn mul(&self, o: &Self) -> Self {
        let mut out = vec![T::zero(); self.0.len() + o.0.len() - 1];
        for (i, a) in self.0.iter().enumerate() {
            for (j, b) in o.0.iter().enumerate() {
                out[i + j] = out[i + j].clone() + a.clone() * b.clone();
            }
        }
        Scaled(out)
    }

    /// The same polynomial at degree `n + by`.
    pub(crate) fn elevate(&self, by: usize) -> Self {
        if by == 0 {
            return self.clone();
        }
        let row: Vec<T> = pascal_row(by).iter().map(T::from_int).collect();
        self.mul(&Scaled(row))
    }

    /// `self − o`, the lower degree elevated first.
    pub(crate) fn sub(&self, o: &Self) -> Self {
        let n = self.degree().max(o.degree());
        let (a, b) = (self.elevate(n - self.degree()), o.elevate(n - o.degree()));
        Scaled(a.0.into_iter().zip(b.0).map(|(x, y)| x - y).collect())
    }

    /// `self + o`, the lower degree elevated first.
    pub(crate) fn add(&self, o: &Self) -> Self {
        let n = self.degree().max(o.degree());
        let (a, b) = (self.elevate(n - self.degree()), o.elevate(n - o.degree()));
        Scaled(a.0.into_iter().zip(b.0).map(|(x, y)| x + y).collect())
    }

    /// `s · self`.
    pub(crate) fn scale(&self, s: &T) -> Self {
        Scaled(self.0.iter().map(|c| s.clone() * c.clone()).collect())
    }
}

impl Scaled<Interval> {
    /// `1` or `−1` when every coefficient has that strict sign: then the
    /// polynomial (each polynomial in the enclosures) has it on all of `[0, 1]`.
    pub(crate) fn strict_sign(&self) -> Option<i8> {
        if self.0.iter().all(|c| c.inf() > 0.0) {
            Some(1)
        } else if self.0.iter().all(|c| c.sup() < 0.0) {
            Some(-1)
        } else {
            None
        }
    }

    /// An enclosure of the range over `t ∈ [lo, hi] ⊆ [0, 1]`: de Casteljau
    /// on the Bernstein coefficients (`c_k / C(n, k)`) in interval arithmetic
    /// with `t` the interval itself (each step a continuous function of `t`,
    /// evaluated in outward rounded arithmetic).
    pub(crate) fn range(&self, lo: f64, hi: f64) -> Interval {
        let Ok(t) = Interval::try_from((lo, hi)) else {
            return Interval::ENTIRE;
        };
        let one = Interval::try_from((1.0, 1.0)).expect("1");
        let row = pascal_row(self.degree());
        let mut w: Vec<Interval> = self
            .0
            .iter()
            .zip(&row)
            .map(|(c, b)| *c / Interval::from_int(b))
            .collect();
        for level in 1..w.len() {
            for i in 0..w.len() - level {
                w[i] = w[i] * (one - t) + w[i + 1] * t;
            }
        }
        w[0]
    }
}

fn sign_of(b: &BigInt) -> i8 {
    match b.sign() {
        Sign::Plus => 1,
        Sign::Minus => -1,
        Sign::NoSign => 0,
    }
}

impl Scaled<BigInt> {
    /// `1` or `−1` when every coefficient has that strict sign.
    pub(crate) fn strict_sign(&self) -> Option<i8> {
        let s = sign_of(&self.0[0]);
        (s != 0 && self.0.iter().all(|c| sign_of(c) == s)).then_some(s)
    }

    /// `Σ c_k t^k (1 − t)^(n−k)`, exactly (for tests).
    #[cfg(test)]
    pub(crate) fn value(&self, t: &Rational) -> Rational {
        let n = self.degree();
        let one = Rational::one();
        self.0
            .iter()
            .enumerate()
            .fold(Rational::zero(), |acc, (k, c)| {
                acc + Rational::from_integer(c.clone())
                    * num_traits::pow(t.clone(), k)
                    * num_traits::pow(&one - t, n - k)
            })
    }

    /// Whether every coefficient is zero (the zero polynomial).
    pub(crate) fn is_zero(&self) -> bool {
        self.0.iter().all(Zero::is_zero)
    }

    /// The exact sign of `p(t)` at a rational `t ∈ [0, 1]` (`None` outside):
    /// with `t = a/q`, `q > 0`, the integer `q^n p(t) = Σ c_k a^k (q − a)^(n−k)`
    /// by homogeneous Horner.
    pub(crate) fn sign_at(&self, t: &Rational) -> Option<i8> {
        let (a, q) = (t.numer(), t.denom());
        if a.sign() == Sign::Minus || a > q || q.sign() != Sign::Plus {
            return None;
        }
        let b = q - a;
        let n = self.degree();
        let mut v = self.0[n].clone();
        let mut pw = BigInt::one();
        for k in (0..n).rev() {
            pw *= &b;
            v = v * a + &self.0[k] * &pw;
        }
        Some(sign_of(&v))
    }

    /// Enclosures of the coefficients `c_k / 2^s`, one power of two `2^s ≥ 1`
    /// for all, so that the largest stays far inside the float range (a
    /// positive factor: the same signs and roots).
    fn scaled_enclosure(&self) -> Vec<Interval> {
        let bits = self.0.iter().map(BigInt::bits).max().unwrap_or(0);
        let shift = bits.saturating_sub(900);
        let den = BigInt::one() << shift;
        self.0
            .iter()
            .map(|c| {
                if shift == 0 {
                    Interval::from_int(c)
                } else {
                    interval_from_rational(&Rational::new(c.clone(), den.clone()))
                }
            })
            .collect()
    }

    /// Enclosures of the Bernstein coefficients `c_k / C(n, k)`, all divided
    /// by the power of two of [`Scaled::scaled_enclosure`].
    pub(crate) fn bernstein_enclosure(&self) -> Vec<Interval> {
        let row = pascal_row(self.degree());
        self.scaled_enclosure()
            .into_iter()
            .zip(&row)
            .map(|(c, b)| c / Interval::from_int(b))
            .collect()
    }

    /// The roots in `[0, 1]`, each simple, isolated by interval Bernstein
    /// subdivision ([`super::isolate_simple_roots_bernstein`]: one strict sign
    /// variation per piece, none elsewhere) and bisected to width `2^-bits`,
    /// each sign from an interval de Casteljau evaluation and exactly
    /// ([`Scaled::sign_at`]) where that holds 0. `None` when the isolation
    /// leaves a piece undecided (a multiple root, a root at a split point):
    /// the caller's exact path decides then.
    pub(crate) fn simple_roots(&self, bits: u32, max_pieces: usize) -> Option<Vec<RealRoot>> {
        if self.strict_sign().is_some() {
            return Some(Vec::new());
        }
        if self.is_zero() {
            return None;
        }
        let pieces =
            super::isolate_simple_roots_bernstein(&self.bernstein_enclosure(), max_pieces)?;
        let scaled = self.scaled_enclosure();
        pieces
            .into_iter()
            .map(|(a, b)| self.bisect(&scaled, a, b, bits))
            .collect()
    }

    /// The sign at the float `t ∈ [0, 1]` from the enclosed scaled
    /// coefficients `c` (Bernstein–Horner, O(n)): for `t ≤ 1/2`,
    /// `p(t) = (1 − t)^n Σ c_k s^k` with `s = t/(1 − t) ∈ [0, 1]`, else
    /// `p(t) = t^n Σ c_k u^(n−k)` with `u = (1 − t)/t`; the positive power
    /// aside, Horner in interval arithmetic with `s` (`u`) enclosed. Exactly
    /// ([`Scaled::sign_at`]) when the enclosure holds 0.
    fn sign_at_f64(&self, c: &[Interval], t: f64) -> Option<i8> {
        let ti = Interval::try_from((t, t)).ok()?;
        let one = Interval::try_from((1.0, 1.0)).ok()?;
        let horner = |x: Interval, coefs: &mut dyn Iterator<Item = &Interval>| {
            coefs.fold(Interval::zero(), |acc, ck| acc * x + *ck)
        };
        let v = if t <= 0.5 {
            horner(ti / (one - ti), &mut c.iter().rev())
        } else {
            horner((one - ti) / ti, &mut c.iter())
        };
        if v.inf() > 0.0 {
            return Some(1);
        }
        if v.sup() < 0.0 {
            return Some(-1);
        }
        self.sign_at(&rational_from_f64(t)?)
    }

    /// Bisects `[a, b]` (strict opposite signs at its ends, so a root inside;
    /// one root by the isolation) to float width at most `2^-bits`, or to an
    /// exact root at a float midpoint.
    fn bisect(&self, scaled: &[Interval], a: f64, b: f64, bits: u32) -> Option<RealRoot> {
        let (mut lo, mut hi) = (a, b);
        let s_lo = self.sign_at_f64(scaled, lo)?;
        if s_lo == 0 || self.sign_at_f64(scaled, hi)? != -s_lo {
            return None;
        }
        let width = 0.5f64.powi(bits as i32);
        while hi - lo > width {
            let m = 0.5 * lo + 0.5 * hi;
            if !(lo < m && m < hi) {
                break;
            }
            match self.sign_at_f64(scaled, m)? {
                0 => {
                    let r = rational_from_f64(m)?;
                    return Some(RealRoot {
                        lo: r.clone(),
                        hi: r,
                    });
                }
                s if s == s_lo => lo = m,
                _ => hi = m,
            }
        }
        Some(RealRoot {
            lo: rational_from_f64(lo)?,
            hi: rational_from_f64(hi)?,
        })
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::poly::Poly;
    use crate::test_util::q;

    /// The scaled product, elevation and difference against the power basis:
    /// `p(t)` evaluated exactly both ways at many rationals.
    #[test]
    fn scaled_arithmetic_matches_the_power_basis() {
        let big = |v: &[i64]| Scaled(v.iter().map(|&x| BigInt::from(x)).collect::<Vec<_>>());
        let a = big(&[3, -7, 2]);
        let b = big(&[-1, 4, 0, 5]);
        let ab = a.mul(&b);
        let e = a.elevate(3);
        let d = b.sub(&a);
        for k in 0..=20 {
            let t = Rational::new(BigInt::from(k), BigInt::from(20));
            assert_eq!(ab.value(&t), a.value(&t) * b.value(&t));
            assert_eq!(e.value(&t), a.value(&t));
            assert_eq!(d.value(&t), b.value(&t) - a.value(&t));
            let s = ab.value(&t);
            let want = if s.is_zero() {
                0
            } else if s > Rational::zero() {
                1
            } else {
                -1
            };
            assert_eq!(ab.sign_at(&t), Some(want), "t = {t}");
        }
        assert_eq!(a.sign_at(&q("-1/2")), None);
        assert_eq!(a.sign_at(&q("3/2")), None);
        // from Bernstein coefficients: (t − 1/4)(t − 3/4) = [3/16, −5/16, 3/16],
        // times 16: the scaled list is [3, −10, 3]
        let p = Scaled::from_bernstein(&[BigInt::from(3), BigInt::from(-5), BigInt::from(3)]);
        assert_eq!(p, big(&[3, -10, 3]));
    }

    /// Roots found by the scaled path against exact Sturm isolation of the
    /// same polynomial in the power basis, on products of linear factors with
    /// random rational roots (some outside `[0, 1]`).
    #[test]
    fn simple_roots_match_sturm() {
        use crate::poly::{isolate_roots, Span};
        let mut seed = 0x2545_f491_4f6c_dd1du64;
        let mut next = |m: u64| {
            seed ^= seed << 13;
            seed ^= seed >> 7;
            seed ^= seed << 17;
            seed % m
        };
        let mut decided = 0;
        for _ in 0..200 {
            let deg = 1 + next(7) as usize;
            // factor (den·t − num) = Bernstein [−num, den − num]
            let mut p = Scaled(vec![BigInt::one()]);
            let mut power = Poly::constant(Rational::one());
            for _ in 0..deg {
                let den = 1 + next(40) as i64;
                let num = next(60) as i64 - 10;
                p = p.mul(&Scaled::from_bernstein(&[
                    BigInt::from(-num),
                    BigInt::from(den - num),
                ]));
                power = power.mul(&Poly::new(vec![
                    Rational::from_integer((-num).into()),
                    Rational::from_integer(den.into()),
                ]));
            }
            let span = Span::closed(Rational::zero(), Rational::one());
            let exact = isolate_roots(&crate::poly::square_free(&power), &span);
            // (None: a double root, or a root on a dyadic split point)
            if let Some(rs) = p.simple_roots(40, 4_000) {
                decided += 1;
                assert_eq!(rs.len(), exact.len(), "{power:?}");
                for (r, e) in rs.iter().zip(&exact) {
                    // the same root: the isolating intervals meet
                    assert!(r.lo <= e.hi && e.lo <= r.hi, "{r:?} vs {e:?}");
                    assert!(&r.hi - &r.lo <= Rational::new(1.into(), BigInt::one() << 40));
                    // a sign change of the power form across it (or exact)
                    if r.lo != r.hi {
                        assert!(power.eval(&r.lo) * power.eval(&r.hi) < Rational::zero());
                    } else {
                        assert!(power.eval(&r.lo).is_zero());
                    }
                }
            }
        }
        assert!(decided >= 120, "only {decided} of 200 decided");
    }
}
