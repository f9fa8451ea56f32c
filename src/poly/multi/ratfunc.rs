//! Rational functions over Q: the symbolic scalar.

use super::mpoly::{trim, MPoly};
use crate::scalar::{Rational, Scalar, Sign};
use num_traits::{One, Zero};
use std::fmt;
// ---------------------------------------------------------------------------
// RatFunc
// ---------------------------------------------------------------------------

/// A rational function `num / den` over Q, `den` never the zero polynomial:
/// the symbolic [`Scalar`].
///
/// Equality (`==`) is equality *as functions*: `a.num * b.den == b.num * a.den`
/// as polynomials, so no gcds are needed. Representations are kept small
/// without gcds: a constant denominator is folded into the numerator (so
/// polynomials have `den = 1`), denominators are primitive (coprime integer
/// coefficients, positive leading coefficient), common monomial factors
/// cancel, and exact polynomial divisions are tried (numerator by
/// denominator, across the factors of a product, between the denominators of
/// a sum).
///
/// As a [`Scalar`]: `KIND = "symbolic"`, `EXACT = true`; [`Scalar::sign`] is
/// exact when the function is a constant and [`Sign::Unknown`] otherwise;
/// [`Scalar::approx`] is the constant's value or NaN.
///
/// # Examples
/// ```
/// use lncert::poly::{MPoly, RatFunc};
/// use lncert::scalar::{Scalar, Sign};
/// let (x, y) = (RatFunc::var(0), RatFunc::var(1));
/// let q = (x.sqr() - y.sqr()).div(&(x.clone() - y.clone())).unwrap();
/// assert_eq!(q, x.clone() + y.clone());
/// assert_eq!(q.sign(), Sign::Unknown);
/// assert_eq!(x.div(&x).unwrap().sign(), Sign::Positive);
/// ```
#[derive(Clone)]
pub struct RatFunc {
    num: MPoly,
    den: MPoly,
}

impl RatFunc {
    /// `num / den` in normal form; `None` if `den` is the zero polynomial.
    ///
    /// # Examples
    /// ```
    /// use lncert::poly::{MPoly, RatFunc};
    /// let (x, y) = (MPoly::var(0), MPoly::var(1));
    /// let f = RatFunc::new(x.pow(2) - y.pow(2), x.clone() - y.clone()).unwrap();
    /// assert_eq!(f, RatFunc::from_mpoly(x + y));
    /// assert!(RatFunc::new(MPoly::one(), MPoly::zero()).is_none());
    /// ```
    pub fn new(num: MPoly, den: MPoly) -> Option<Self> {
        if den.is_zero() {
            return None;
        }
        if num.is_zero() {
            return Some(RatFunc::from_mpoly(MPoly::zero()));
        }
        if let Some(c) = den.as_constant() {
            return Some(RatFunc {
                num: num.scale(&c.recip()),
                den: MPoly::one(),
            });
        }
        // Cancel the common monomial factor.
        let g = trim(
            num.monomial_content()
                .iter()
                .zip(&den.monomial_content())
                .map(|(&a, &b)| a.min(b))
                .collect(),
        );
        let (num, den) = if g.is_empty() {
            (num, den)
        } else {
            (num.div_monomial(&g), den.div_monomial(&g))
        };
        if let Some(c) = den.as_constant() {
            return Some(RatFunc {
                num: num.scale(&c.recip()),
                den: MPoly::one(),
            });
        }
        // A polynomial after all?
        if let Some(q) = num.div_exact(&den) {
            return Some(RatFunc::from_mpoly(q));
        }
        // Canonical denominator: integer coefficients without common factor,
        // positive leading coefficient (lex order).
        let k = den.primitive_factor();
        if k.is_one() {
            Some(RatFunc { num, den })
        } else {
            Some(RatFunc {
                num: num.scale(&k),
                den: den.scale(&k),
            })
        }
    }

    /// The polynomial `p` as a rational function.
    ///
    /// # Examples
    /// ```
    /// use lncert::poly::{MPoly, RatFunc};
    /// let f = RatFunc::from_mpoly(MPoly::var(0) + MPoly::one());
    /// assert!(f.den().is_one());
    /// ```
    pub fn from_mpoly(p: MPoly) -> Self {
        RatFunc {
            num: p,
            den: MPoly::one(),
        }
    }

    /// The variable `x_i`.
    ///
    /// # Examples
    /// ```
    /// use lncert::poly::RatFunc;
    /// assert_eq!(RatFunc::var(1).to_string(), "x1");
    /// ```
    pub fn var(i: usize) -> Self {
        RatFunc::from_mpoly(MPoly::var(i))
    }

    /// A constant.
    ///
    /// # Examples
    /// ```
    /// use lncert::poly::RatFunc;
    /// use lncert::scalar::{Rational, Scalar, Sign};
    /// let c = RatFunc::constant(Rational::new((-1).into(), 3.into()));
    /// assert_eq!(c.sign(), Sign::Negative);
    /// ```
    pub fn constant(c: Rational) -> Self {
        RatFunc::from_mpoly(MPoly::constant(c))
    }

    /// The numerator.
    ///
    /// # Examples
    /// ```
    /// use lncert::poly::{MPoly, RatFunc};
    /// use lncert::scalar::Scalar;
    /// let f = RatFunc::one().div(&(RatFunc::var(0) + RatFunc::one())).unwrap();
    /// assert!(f.num().is_one());
    /// ```
    pub fn num(&self) -> &MPoly {
        &self.num
    }

    /// The denominator (never zero; `1` when the function is a polynomial).
    ///
    /// # Examples
    /// ```
    /// use lncert::poly::{MPoly, RatFunc};
    /// use lncert::scalar::Scalar;
    /// let f = RatFunc::one().div(&(RatFunc::var(0) + RatFunc::one())).unwrap();
    /// assert_eq!(f.den(), &(MPoly::var(0) + MPoly::one()));
    /// ```
    pub fn den(&self) -> &MPoly {
        &self.den
    }

    /// The value if the function is a constant (detected when numerator and
    /// denominator are proportional; no gcd is computed beyond that).
    ///
    /// # Examples
    /// ```
    /// use lncert::poly::RatFunc;
    /// use lncert::scalar::{Rational, Scalar};
    /// let x = RatFunc::var(0);
    /// assert_eq!(RatFunc::from_i64(4).as_constant(), Some(Rational::from_integer(4.into())));
    /// assert_eq!(x.as_constant(), None);
    /// ```
    pub fn as_constant(&self) -> Option<Rational> {
        match (self.num.as_constant(), self.den.as_constant()) {
            (Some(n), Some(d)) => Some(n / d),
            _ if self.num.is_zero() => Some(<Rational as Zero>::zero()),
            _ => self.num.ratio_to(&self.den),
        }
    }

    /// The value at `x_i = values[i]`, `None` where the denominator vanishes.
    ///
    /// # Panics
    /// If a variable that occurs has no value (`values` too short).
    ///
    /// # Examples
    /// ```
    /// use lncert::poly::RatFunc;
    /// use lncert::scalar::{Rational, Scalar};
    /// let f = RatFunc::one().div(&RatFunc::var(0)).unwrap();
    /// assert_eq!(f.eval(&[Rational::from_integer(4.into())]), Some(Rational::new(1.into(), 4.into())));
    /// assert_eq!(f.eval(&[Rational::from_integer(0.into())]), None);
    /// ```
    pub fn eval(&self, values: &[Rational]) -> Option<Rational> {
        let d = self.den.eval(values);
        if d.is_zero() {
            None
        } else {
            Some(self.num.eval(values) / d)
        }
    }

    /// The function with `x_var` replaced by `value`; `None` if the resulting
    /// denominator is the zero polynomial.
    ///
    /// # Examples
    /// ```
    /// use lncert::poly::RatFunc;
    /// use lncert::scalar::Scalar;
    /// let (x, y) = (RatFunc::var(0), RatFunc::var(1));
    /// let f = x.sqr() + RatFunc::one();
    /// let g = f.substitute(0, &RatFunc::one().div(&y).unwrap()).unwrap(); // 1/y^2 + 1
    /// assert_eq!(g * y.sqr(), y.sqr() + RatFunc::one());
    /// // x -> 0 in 1/x has no value
    /// assert!(RatFunc::one().div(&x).unwrap().substitute(0, &RatFunc::zero()).is_none());
    /// ```
    pub fn substitute(&self, var: usize, value: &RatFunc) -> Option<RatFunc> {
        if value.den.is_one() {
            return RatFunc::new(
                self.num.substitute(var, &value.num),
                self.den.substitute(var, &value.num),
            );
        }
        let (p, q) = (&value.num, &value.den);
        let n = self.num.degree_in(var);
        let m = self.den.degree_in(var);
        let mut qpow = vec![MPoly::one()];
        for k in 1..=n.max(m) as usize {
            let next = qpow[k - 1].mul(q);
            qpow.push(next);
        }
        // hom(P, deg) = q^deg * P(p/q) = sum c_k p^k q^(deg-k)  (Horner in p).
        let hom = |poly: &MPoly, deg: u32| {
            let c = poly.coefficients_in(var);
            let mut acc = MPoly::zero();
            for (k, ck) in c.iter().enumerate().rev() {
                acc = acc.mul(p);
                acc.add_assign_ref(&ck.mul(&qpow[deg as usize - k]));
            }
            acc
        };
        let hn = hom(&self.num, n);
        let hd = hom(&self.den, m);
        // num/den = (hn / q^n) / (hd / q^m)
        if n >= m {
            RatFunc::new(hn, hd.mul(&qpow[(n - m) as usize]))
        } else {
            RatFunc::new(hn.mul(&qpow[(m - n) as usize]), hd)
        }
    }

    /// The partial derivative with respect to `x_var` (quotient rule).
    ///
    /// # Examples
    /// ```
    /// use lncert::poly::RatFunc;
    /// use lncert::scalar::Scalar;
    /// let x = RatFunc::var(0);
    /// let f = RatFunc::one().div(&x).unwrap();
    /// assert_eq!(f.derivative(0), -RatFunc::one().div(&x.sqr()).unwrap());
    /// ```
    pub fn derivative(&self, var: usize) -> RatFunc {
        if self.den.is_one() {
            return RatFunc::from_mpoly(self.num.derivative(var));
        }
        let n = self
            .num
            .derivative(var)
            .mul(&self.den)
            .sub(&self.num.mul(&self.den.derivative(var)));
        RatFunc::new(n, self.den.mul(&self.den)).expect("den^2 is nonzero")
    }

    /// The function printed with variable names, as `num` or `(num)/(den)`
    /// (the denominator is printed with coprime integer coefficients).
    ///
    /// # Examples
    /// ```
    /// use lncert::poly::RatFunc;
    /// use lncert::scalar::Scalar;
    /// let (t, tau) = (RatFunc::var(0), RatFunc::var(1));
    /// let f = t.div(&(tau.scale(3) - RatFunc::one())).unwrap();
    /// assert_eq!(f.display_with(&["t", "tau"]), "t/(3*tau - 1)");
    /// assert_eq!(f.to_string(), "x0/(3*x1 - 1)");
    /// ```
    pub fn display_with(&self, names: &[&str]) -> String {
        let n = self.num.display_with(names);
        if self.den.is_one() {
            return n;
        }
        let d = self.den.display_with(names);
        let wrap = |s: String, chars: &[char]| {
            if s.contains(chars) {
                format!("({s})")
            } else {
                s
            }
        };
        format!("{}/{}", wrap(n, &[' ']), wrap(d, &[' ', '*', '/']))
    }

    /// Normal form of a known-valid `num / den`.
    fn make(num: MPoly, den: MPoly) -> RatFunc {
        RatFunc::new(num, den).expect("denominator of a product of nonzero polynomials is nonzero")
    }
}

impl fmt::Display for RatFunc {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str(&self.display_with(&[]))
    }
}

impl fmt::Debug for RatFunc {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        write!(f, "RatFunc({self})")
    }
}

impl PartialEq for RatFunc {
    fn eq(&self, o: &RatFunc) -> bool {
        identity_holds(self, o)
    }
}

impl Eq for RatFunc {}

impl From<MPoly> for RatFunc {
    fn from(p: MPoly) -> Self {
        RatFunc::from_mpoly(p)
    }
}

impl From<Rational> for RatFunc {
    fn from(c: Rational) -> Self {
        RatFunc::constant(c)
    }
}

impl std::ops::Add for RatFunc {
    type Output = RatFunc;
    fn add(self, o: RatFunc) -> RatFunc {
        if self.num.is_zero() {
            return o;
        }
        if o.num.is_zero() {
            return self;
        }
        if self.den == o.den {
            return RatFunc::make(self.num + o.num, self.den);
        }
        if self.den.is_one() {
            return RatFunc::make(self.num.mul(&o.den) + o.num, o.den);
        }
        if o.den.is_one() {
            return RatFunc::make(self.num + o.num.mul(&self.den), self.den);
        }
        if let Some(q) = self.den.div_exact(&o.den) {
            return RatFunc::make(self.num + o.num.mul(&q), self.den);
        }
        if let Some(q) = o.den.div_exact(&self.den) {
            return RatFunc::make(self.num.mul(&q) + o.num, o.den);
        }
        let num = self.num.mul(&o.den) + o.num.mul(&self.den);
        RatFunc::make(num, self.den.mul(&o.den))
    }
}

impl std::ops::Sub for RatFunc {
    type Output = RatFunc;
    fn sub(self, o: RatFunc) -> RatFunc {
        self + (-o)
    }
}

impl std::ops::Neg for RatFunc {
    type Output = RatFunc;
    fn neg(self) -> RatFunc {
        RatFunc {
            num: -self.num,
            den: self.den,
        }
    }
}

impl std::ops::Mul for RatFunc {
    type Output = RatFunc;
    fn mul(self, o: RatFunc) -> RatFunc {
        if self.num.is_zero() || o.num.is_zero() {
            return RatFunc::from_mpoly(MPoly::zero());
        }
        // Cancel across: (n1/d1) * (n2/d2) where d2 | n1, n1 | d2, ...
        let (n1, d2) = cancel(self.num, o.den);
        let (n2, d1) = cancel(o.num, self.den);
        RatFunc::make(n1.mul(&n2), d1.mul(&d2))
    }
}

/// `(a, b)` with a factor common to both removed when one divides the other
/// (nothing is done for constants: normalisation handles them).
fn cancel(a: MPoly, b: MPoly) -> (MPoly, MPoly) {
    if a.as_constant().is_some() || b.as_constant().is_some() {
        return (a, b);
    }
    if let Some(q) = a.div_exact(&b) {
        return (q, MPoly::one());
    }
    if let Some(q) = b.div_exact(&a) {
        return (MPoly::one(), q);
    }
    (a, b)
}

/// Operator impls on references and mixed owned/reference operands (by cloning).
macro_rules! ref_ops {
    ($t:ty) => {
        impl std::ops::Add<&$t> for $t {
            type Output = $t;
            fn add(self, o: &$t) -> $t {
                self + o.clone()
            }
        }
        impl std::ops::Add<$t> for &$t {
            type Output = $t;
            fn add(self, o: $t) -> $t {
                self.clone() + o
            }
        }
        impl std::ops::Add<&$t> for &$t {
            type Output = $t;
            fn add(self, o: &$t) -> $t {
                self.clone() + o.clone()
            }
        }
        impl std::ops::Sub<&$t> for $t {
            type Output = $t;
            fn sub(self, o: &$t) -> $t {
                self - o.clone()
            }
        }
        impl std::ops::Sub<$t> for &$t {
            type Output = $t;
            fn sub(self, o: $t) -> $t {
                self.clone() - o
            }
        }
        impl std::ops::Sub<&$t> for &$t {
            type Output = $t;
            fn sub(self, o: &$t) -> $t {
                self.clone() - o.clone()
            }
        }
        impl std::ops::Mul<&$t> for $t {
            type Output = $t;
            fn mul(self, o: &$t) -> $t {
                self * o.clone()
            }
        }
        impl std::ops::Mul<$t> for &$t {
            type Output = $t;
            fn mul(self, o: $t) -> $t {
                self.clone() * o
            }
        }
        impl std::ops::Mul<&$t> for &$t {
            type Output = $t;
            fn mul(self, o: &$t) -> $t {
                self.clone() * o.clone()
            }
        }
        impl std::ops::Neg for &$t {
            type Output = $t;
            fn neg(self) -> $t {
                -self.clone()
            }
        }
    };
}

ref_ops!(RatFunc);

impl Scalar for RatFunc {
    const KIND: &'static str = "symbolic";
    const EXACT: bool = true;

    fn from_rational(r: &Rational) -> Self {
        RatFunc::constant(r.clone())
    }

    /// Exact for constants; `Unknown` for non-constant functions.
    fn sign(&self) -> Sign {
        match self.as_constant() {
            Some(c) => Scalar::sign(&c),
            None => Sign::Unknown,
        }
    }

    /// `None` iff the numerator is the zero polynomial.
    fn recip(&self) -> Option<Self> {
        if self.num.is_zero() {
            None
        } else {
            RatFunc::new(self.den.clone(), self.num.clone())
        }
    }

    /// The constant's value, NaN for a non-constant function.
    fn approx(&self) -> f64 {
        match self.as_constant() {
            Some(c) => Scalar::approx(&c),
            None => f64::NAN,
        }
    }
}

// ---------------------------------------------------------------------------
// Free functions
// ---------------------------------------------------------------------------

/// Whether `lhs == rhs` as rational functions (exact: cross-multiplied
/// numerators are equal polynomials). Same as `lhs == rhs`.
///
/// # Examples
/// ```
/// use lncert::poly::{identity_holds, RatFunc};
/// use lncert::scalar::Scalar;
/// let (x, y) = (RatFunc::var(0), RatFunc::var(1));
/// // x/(x+y) + y/(x+y) = 1
/// let s = x.clone() + y.clone();
/// let lhs = x.div(&s).unwrap() + y.div(&s).unwrap();
/// assert!(identity_holds(&lhs, &RatFunc::one()));
/// // (x+y)^2 = x^2 + 2xy + y^2, but not x^2 + y^2
/// let sq = x.sqr() + (x.clone() * y.clone()).scale(2) + y.sqr();
/// assert!(identity_holds(&s.sqr(), &sq));
/// assert!(!identity_holds(&s.sqr(), &(x.sqr() + y.sqr())));
/// ```
pub fn identity_holds(lhs: &RatFunc, rhs: &RatFunc) -> bool {
    if lhs.den == rhs.den {
        return lhs.num == rhs.num;
    }
    lhs.num.mul(&rhs.den) == rhs.num.mul(&lhs.den)
}

/// `p` as a univariate polynomial in `x_var`: entry `k` is the coefficient of
/// `x_var^k` (same as [`MPoly::coefficients_in`]; empty for zero).
///
/// # Examples
/// ```
/// use lncert::poly::{univariate_coeffs, MPoly};
/// let (t, a) = (MPoly::var(0), MPoly::var(1));
/// let p = a.clone() * t.pow(2) - MPoly::one();
/// assert_eq!(univariate_coeffs(&p, 0), vec![-MPoly::one(), MPoly::zero(), a]);
/// ```
pub fn univariate_coeffs(p: &MPoly, var: usize) -> Vec<MPoly> {
    p.coefficients_in(var)
}

/// The power-form polynomial `p` with symbolic coefficients as one rational
/// function in the variable `x_var`: `sum_k c_k * x_var^k`. Intended for
/// polynomial coefficients (denominator constant), which then give a
/// polynomial; other coefficients work too. `x_var` should not occur in the
/// coefficients.
///
/// # Examples
/// ```
/// use lncert::poly::{poly_in, Poly, RatFunc};
/// use lncert::scalar::Scalar;
/// let (b0, b1, t) = (RatFunc::var(0), RatFunc::var(1), RatFunc::var(2));
/// // Linear Bernstein polynomial b0 (1-t) + b1 t.
/// let p = Poly::from_bernstein(&[b0.clone(), b1.clone()]);
/// assert_eq!(poly_in(2, &p), b0.clone() * (RatFunc::one() - t.clone()) + b1 * t);
/// ```
pub fn poly_in(var: usize, p: &crate::poly::Poly<RatFunc>) -> RatFunc {
    let t = RatFunc::var(var);
    let mut acc = RatFunc::from_mpoly(MPoly::zero());
    for c in p.coeffs().iter().rev() {
        acc = acc * t.clone() + c.clone();
    }
    acc
}
