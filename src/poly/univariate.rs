//! Univariate polynomials in power form, generic over the scalar.

use crate::scalar::{Rational, Scalar, Sign};

/// `c[0] + c[1] t + ... + c[n] t^n`, coefficients in any [`Scalar`].
///
/// # Examples
/// ```
/// use lncert::poly::Poly;
/// let p = Poly::new(vec![1.0, -3.0, 2.0]); // 1 - 3t + 2t^2 = (1-t)(1-2t)
/// assert_eq!(p.eval(&1.0), 0.0);
/// assert_eq!(p.derivative().coeffs(), &[-3.0, 4.0]);
/// ```
#[derive(Clone, Debug, PartialEq)]
pub struct Poly<S> {
    c: Vec<S>,
}

impl<S: Scalar> Poly<S> {
    /// From coefficients, constant term first.
    pub fn new(c: Vec<S>) -> Self {
        Poly { c }
    }
    /// The zero polynomial.
    pub fn zero() -> Self {
        Poly { c: Vec::new() }
    }
    /// A constant.
    pub fn constant(a: S) -> Self {
        Poly { c: vec![a] }
    }
    /// The monomial `t`.
    pub fn t() -> Self {
        Poly {
            c: vec![S::zero(), S::one()],
        }
    }
    /// `a + b t`.
    pub fn linear(a: S, b: S) -> Self {
        Poly { c: vec![a, b] }
    }
    /// Coefficients, constant term first (may include trailing zeros).
    pub fn coeffs(&self) -> &[S] {
        &self.c
    }
    /// Number of stored coefficients minus one (an upper bound of the degree).
    pub fn formal_degree(&self) -> usize {
        self.c.len().saturating_sub(1)
    }
    /// Horner evaluation.
    pub fn eval(&self, t: &S) -> S {
        let mut acc = S::zero();
        for a in self.c.iter().rev() {
            acc = acc * t.clone() + a.clone();
        }
        acc
    }
    /// The derivative.
    pub fn derivative(&self) -> Self {
        Poly {
            c: self
                .c
                .iter()
                .enumerate()
                .skip(1)
                .map(|(i, a)| a.scale(i as i64))
                .collect(),
        }
    }
    /// `k * self`.
    pub fn scale(&self, k: &S) -> Self {
        Poly {
            c: self.c.iter().map(|a| a.clone() * k.clone()).collect(),
        }
    }
    /// Sum.
    pub fn add(&self, o: &Self) -> Self {
        let n = self.c.len().max(o.c.len());
        let get = |v: &Vec<S>, i: usize| v.get(i).cloned().unwrap_or_else(S::zero);
        Poly {
            c: (0..n).map(|i| get(&self.c, i) + get(&o.c, i)).collect(),
        }
    }
    /// Difference.
    pub fn sub(&self, o: &Self) -> Self {
        self.add(&o.neg())
    }
    /// Negation.
    pub fn neg(&self) -> Self {
        Poly {
            c: self.c.iter().map(|a| -a.clone()).collect(),
        }
    }
    /// Product.
    pub fn mul(&self, o: &Self) -> Self {
        if self.c.is_empty() || o.c.is_empty() {
            return Poly::zero();
        }
        let mut c = vec![S::zero(); self.c.len() + o.c.len() - 1];
        for (i, a) in self.c.iter().enumerate() {
            for (j, b) in o.c.iter().enumerate() {
                c[i + j] = c[i + j].clone() + a.clone() * b.clone();
            }
        }
        Poly { c }
    }
    /// Composition `self(a + b t)` (an affine change of parameter).
    pub fn compose_affine(&self, a: &S, b: &S) -> Self {
        let lin = Poly::linear(a.clone(), b.clone());
        let mut acc = Poly::zero();
        for k in self.c.iter().rev() {
            acc = acc.mul(&lin).add(&Poly::constant(k.clone()));
        }
        acc
    }
    /// Converts to another scalar through exact rationals is not possible in
    /// general; this maps each coefficient.
    pub fn map<T: Scalar>(&self, f: impl Fn(&S) -> T) -> Poly<T> {
        Poly {
            c: self.c.iter().map(f).collect(),
        }
    }
    /// Power form of the Bernstein polynomial `sum b_i B^n_i(t)`.
    pub fn from_bernstein(b: &[S]) -> Self {
        if let Some(c) = S::bernstein_to_power(b) {
            return Poly::new(c);
        }
        let n = b.len().saturating_sub(1);
        let mut acc = Poly::zero();
        for (i, bi) in b.iter().enumerate() {
            // B^n_i(t) = C(n,i) t^i (1-t)^(n-i)
            let mut term = Poly::constant(ratio_scalar(binomial_big(n, i), 1.into()));
            for _ in 0..i {
                term = term.mul(&Poly::t());
            }
            for _ in 0..(n - i) {
                term = term.mul(&Poly::linear(S::one(), -S::one()));
            }
            acc = acc.add(&term.scale(bi));
        }
        acc
    }
    /// Bernstein coefficients of degree `n >= formal_degree` on `[0, 1]`.
    /// Returns `None` if `n` is below the formal degree.
    pub fn to_bernstein(&self, n: usize) -> Option<Vec<S>> {
        if self.c.len() > n + 1 {
            return None;
        }
        // b_i = sum_{k<=i} C(i,k)/C(n,k) a_k
        Some(
            (0..=n)
                .map(|i| {
                    let mut s = S::zero();
                    for (k, a) in self.c.iter().enumerate().take(i + 1) {
                        let w: S = ratio_scalar(binomial_big(i, k), binomial_big(n, k));
                        s = s + a.clone() * w;
                    }
                    s
                })
                .collect(),
        )
    }
    /// Whether every coefficient is exactly zero (`None` if some sign is unknown).
    pub fn is_zero(&self) -> Option<bool> {
        let mut unknown = false;
        for a in &self.c {
            match a.sign() {
                Sign::Zero => {}
                Sign::Unknown => unknown = true,
                _ => return Some(false),
            }
        }
        if unknown {
            None
        } else {
            Some(true)
        }
    }
}

impl Poly<Rational> {
    /// Removes trailing zero coefficients (exact).
    pub fn trimmed(mut self) -> Self {
        while self.c.last().is_some_and(|a| a.sign() == Sign::Zero) {
            self.c.pop();
        }
        self
    }
    /// Exact degree; `None` for the zero polynomial.
    pub fn degree(&self) -> Option<usize> {
        let t = self.clone().trimmed();
        t.c.len().checked_sub(1)
    }
}

/// The exact binomial coefficient `C(n, k)` (any size).
pub fn binomial_big(n: usize, k: usize) -> num_bigint::BigInt {
    if k > n {
        return 0.into();
    }
    let k = k.min(n - k);
    let mut r = num_bigint::BigInt::from(1);
    for i in 0..k {
        r = r * (n - i) / (i + 1);
    }
    r
}

/// `num / den` as a scalar: through the fast `from_frac` path when both fit
/// in `i64` (exact for rationals, correctly rounded for f64, enclosed for
/// intervals), else through the exact rational.
pub(crate) fn ratio_scalar<S: Scalar>(num: num_bigint::BigInt, den: num_bigint::BigInt) -> S {
    match (i64::try_from(&num), i64::try_from(&den)) {
        (Ok(p), Ok(q)) if q != 0 => S::from_frac(p, q),
        _ => S::from_rational(&Rational::new(num, den)),
    }
}

/// Binomial coefficient as `i64` (exact for the small degrees used here, n <= 60).
pub fn binomial(n: usize, k: usize) -> i64 {
    if k > n {
        return 0;
    }
    let k = k.min(n - k);
    let mut r: i128 = 1;
    for i in 0..k {
        r = r * (n - i) as i128 / (i + 1) as i128;
    }
    r as i64
}

impl Poly<crate::scalar::Rational> {
    /// An exact enclosure `[a, b]` of the values on `[lo, hi]` with
    /// `0 ≤ lo ≤ hi`: term by term, since each `c·tᵏ` is monotone for `t ≥ 0`
    /// (cheap, and tight on narrow intervals such as isolating intervals).
    ///
    /// # Examples
    /// ```
    /// use lncert::poly::Poly;
    /// use lncert::scalar::Rational;
    /// let q = |n: i64| Rational::from_integer(n.into());
    /// let p = Poly::new(vec![q(1), q(-3), q(1)]); // 1 − 3t + t²
    /// let (a, b) = p.range_on_nonnegative(&q(1), &q(2));
    /// assert!(a <= q(-1) && q(-1) <= b); // p(1) = −1, p(2) = −1
    /// ```
    pub fn range_on_nonnegative(
        &self,
        lo: &crate::scalar::Rational,
        hi: &crate::scalar::Rational,
    ) -> (crate::scalar::Rational, crate::scalar::Rational) {
        use num_traits::{One, Zero};
        type Q = crate::scalar::Rational;
        let (mut a, mut b) = (<Q as Zero>::zero(), <Q as Zero>::zero());
        let (mut pl, mut ph) = (<Q as One>::one(), <Q as One>::one());
        for c in &self.c {
            let (x, y) = (c * &pl, c * &ph);
            if x <= y {
                a += x;
                b += y;
            } else {
                a += y;
                b += x;
            }
            pl *= lo;
            ph *= hi;
        }
        (a, b)
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::test_util::q;

    #[test]
    fn bernstein_round_trip_exact() {
        let p = Poly::new(vec![q("1/3"), q("-2"), q("5/7"), q("4")]);
        for n in 3..7 {
            let b = p.to_bernstein(n).unwrap();
            assert_eq!(Poly::from_bernstein(&b).trimmed(), p.clone().trimmed());
        }
        assert!(p.to_bernstein(2).is_none());
    }

    #[test]
    fn compose_affine_shifts() {
        let p = Poly::new(vec![q("0"), q("0"), q("1")]); // t^2
        let r = p.compose_affine(&q("1"), &q("2")); // (1+2t)^2
        assert_eq!(r.coeffs(), &[q("1"), q("4"), q("4")]);
    }
}
