//! Multivariate polynomials and rational functions over Q: a *symbolic* scalar.
//!
//! Every kernel of lncert (Bézier evaluation, hodographs, the papers'
//! constructions) is generic over [`Scalar`]. [`RatFunc`] implements
//! [`Scalar`] with values that are rational functions in named variables, so
//! the very same kernels can be run *symbolically*: feed them variables
//! (`τ`, `b0`, `bm`, `b3`, ...) instead of numbers and compare what comes out
//! with the closed forms the papers' proofs rely on, e.g.
//! `b'(t) = -6(t-τ){...}/((3τ-1)(3τ-2))`. The comparison
//! ([`identity_holds`], or `==` on [`RatFunc`]) is exact: two rational
//! functions are equal iff their cross-multiplied numerators are equal as
//! polynomials, so a passing check is a machine-checked algebraic identity
//! (valid wherever both sides are defined).
//!
//! * [`MPoly`]: sparse polynomial over [`Rational`], terms keyed by exponent
//!   vectors (index = variable number, trailing zeros trimmed), so equal
//!   polynomials compare equal with `==`.
//! * [`RatFunc`]: `num / den` with `den != 0`; no gcds are computed, but
//!   constant denominators are folded into the numerator, denominators are
//!   made primitive (coprime integer coefficients), common monomial factors
//!   are cancelled and exact polynomial divisions are tried, which keeps
//!   expressions small in practice.
//! * [`Scalar::sign`] of a [`RatFunc`] is exact for constants and
//!   [`Sign::Unknown`] otherwise: the sign of a function is not a number.
//!
//! # Examples
//! ```
//! use lncert::poly::{identity_holds, Poly, RatFunc};
//! // Run the generic kernel `Poly::eval` on symbolic data: p(t) = a + b t at t = s.
//! let (a, b, s) = (RatFunc::var(0), RatFunc::var(1), RatFunc::var(2));
//! let p = Poly::new(vec![a.clone(), b.clone()]);
//! assert!(identity_holds(&p.eval(&s), &(a + b * s)));
//! ```

use crate::scalar::{Rational, Scalar, Sign};
use num_bigint::BigInt;
use num_integer::Integer;
use num_traits::{One, Signed, Zero};
use std::collections::{BTreeMap, HashMap};
use std::fmt;

// ---------------------------------------------------------------------------
// Exponent vectors
// ---------------------------------------------------------------------------

/// Removes trailing zero exponents (the canonical form of a monomial key).
fn trim(mut e: Vec<u32>) -> Vec<u32> {
    while e.last() == Some(&0) {
        e.pop();
    }
    e
}

/// `buf = a + b` componentwise. The sum of two trimmed vectors is trimmed.
fn add_exps_into(buf: &mut Vec<u32>, a: &[u32], b: &[u32]) {
    buf.clear();
    let n = a.len().max(b.len());
    buf.extend((0..n).map(|i| a.get(i).copied().unwrap_or(0) + b.get(i).copied().unwrap_or(0)));
}

/// `a / b` if the monomial `b` divides `a` (trimmed), else `None`.
fn monomial_quotient(a: &[u32], b: &[u32]) -> Option<Vec<u32>> {
    if b.len() > a.len() {
        return None;
    }
    let mut m = Vec::with_capacity(a.len());
    for (i, &x) in a.iter().enumerate() {
        m.push(x.checked_sub(b.get(i).copied().unwrap_or(0))?);
    }
    Some(trim(m))
}

/// The name of variable `i`: `names[i]` if given, else `x{i}`.
fn var_name(names: &[&str], i: usize) -> String {
    match names.get(i) {
        Some(n) => (*n).to_string(),
        None => format!("x{i}"),
    }
}

// ---------------------------------------------------------------------------
// MPoly
// ---------------------------------------------------------------------------

/// A sparse multivariate polynomial over [`Rational`].
///
/// Terms are stored as `exponent vector -> coefficient`, where the exponent
/// vector is indexed by variable number and has no trailing zeros, and no
/// coefficient is zero. This form is canonical, so `==` is equality of
/// polynomials. Variables are plain numbers `x0, x1, ...`; names are only for
/// printing ([`MPoly::display_with`]).
///
/// The inherent arithmetic methods ([`MPoly::add`], [`MPoly::mul`], ...) take
/// references; the std operators `+ - * -x` take owned values (and references).
/// (Where `std::ops::Add` is imported, `p.add(&q)` on an *owned* `p` resolves
/// to the std operator and consumes `p`; `&p + &q` never does.)
///
/// # Examples
/// ```
/// use lncert::poly::MPoly;
/// use lncert::scalar::Rational;
/// let (x, y) = (MPoly::var(0), MPoly::var(1));
/// let p = (x.clone() + y.clone()).pow(2);
/// let two = MPoly::constant(Rational::from_integer(2.into()));
/// assert_eq!(p, x.pow(2) + two * x.clone() * y.clone() + y.pow(2));
/// assert_eq!(p.to_string(), "x0^2 + 2*x0*x1 + x1^2");
/// ```
#[derive(Clone, PartialEq, Eq, Hash, Default)]
pub struct MPoly {
    terms: BTreeMap<Vec<u32>, Rational>,
}

impl MPoly {
    /// The zero polynomial.
    ///
    /// # Examples
    /// ```
    /// use lncert::poly::MPoly;
    /// assert!(MPoly::zero().is_zero());
    /// assert_eq!(MPoly::zero().to_string(), "0");
    /// ```
    pub fn zero() -> Self {
        MPoly {
            terms: BTreeMap::new(),
        }
    }

    /// The constant polynomial 1.
    ///
    /// # Examples
    /// ```
    /// use lncert::poly::MPoly;
    /// let x = MPoly::var(0);
    /// assert_eq!(x.clone() * MPoly::one(), x);
    /// ```
    pub fn one() -> Self {
        Self::constant(<Rational as One>::one())
    }

    /// A constant polynomial.
    ///
    /// # Examples
    /// ```
    /// use lncert::poly::MPoly;
    /// use lncert::scalar::Rational;
    /// let c = MPoly::constant(Rational::new(3.into(), 2.into()));
    /// assert_eq!(c.to_string(), "3/2");
    /// assert_eq!(c.as_constant(), Some(Rational::new(3.into(), 2.into())));
    /// ```
    pub fn constant(c: Rational) -> Self {
        Self::monomial(&[], c)
    }

    /// The variable `x_i`.
    ///
    /// # Examples
    /// ```
    /// use lncert::poly::MPoly;
    /// assert_eq!(MPoly::var(2).to_string(), "x2");
    /// assert_eq!(MPoly::var(2).degree_in(2), 1);
    /// ```
    pub fn var(i: usize) -> Self {
        let mut e = vec![0; i + 1];
        e[i] = 1;
        MPoly {
            terms: BTreeMap::from([(e, <Rational as One>::one())]),
        }
    }

    /// The term `c * x0^e[0] * x1^e[1] * ...` (trailing zero exponents allowed).
    ///
    /// # Examples
    /// ```
    /// use lncert::poly::MPoly;
    /// use lncert::scalar::Rational;
    /// let m = MPoly::monomial(&[2, 1, 0], Rational::from_integer((-5).into()));
    /// assert_eq!(m.to_string(), "-5*x0^2*x1");
    /// ```
    pub fn monomial(exponents: &[u32], c: Rational) -> Self {
        let mut terms = BTreeMap::new();
        if !c.is_zero() {
            terms.insert(trim(exponents.to_vec()), c);
        }
        MPoly { terms }
    }

    /// Whether this is the zero polynomial.
    ///
    /// # Examples
    /// ```
    /// use lncert::poly::MPoly;
    /// let x = MPoly::var(0);
    /// assert!((x.clone() - x).is_zero());
    /// ```
    pub fn is_zero(&self) -> bool {
        self.terms.is_empty()
    }

    /// Whether this is the constant 1.
    ///
    /// # Examples
    /// ```
    /// use lncert::poly::MPoly;
    /// assert!(MPoly::one().is_one());
    /// assert!(!MPoly::var(0).is_one());
    /// ```
    pub fn is_one(&self) -> bool {
        self.terms.len() == 1 && self.terms.get(&Vec::new()).is_some_and(|c| c.is_one())
    }

    /// The value if the polynomial is a constant (`Some(0)` for zero).
    ///
    /// # Examples
    /// ```
    /// use lncert::poly::MPoly;
    /// use lncert::scalar::Rational;
    /// assert_eq!(MPoly::zero().as_constant(), Some(Rational::from_integer(0.into())));
    /// assert_eq!(MPoly::var(0).as_constant(), None);
    /// ```
    pub fn as_constant(&self) -> Option<Rational> {
        match self.terms.len() {
            0 => Some(<Rational as Zero>::zero()),
            1 => self.terms.get(&Vec::new()).cloned(),
            _ => None,
        }
    }

    /// Number of (nonzero) terms.
    ///
    /// # Examples
    /// ```
    /// use lncert::poly::MPoly;
    /// let p = (MPoly::var(0) + MPoly::one()).pow(3);
    /// assert_eq!(p.num_terms(), 4);
    /// ```
    pub fn num_terms(&self) -> usize {
        self.terms.len()
    }

    /// The terms `(exponents, coefficient)` in increasing lex order
    /// (`x0 > x1 > ...`); exponent slices have no trailing zeros.
    ///
    /// # Examples
    /// ```
    /// use lncert::poly::MPoly;
    /// use lncert::scalar::Rational;
    /// let p = MPoly::var(1) + MPoly::one();
    /// let t: Vec<_> = p.terms().collect();
    /// assert_eq!(t, vec![(&[][..], &Rational::from_integer(1.into())),
    ///                    (&[0, 1][..], &Rational::from_integer(1.into()))]);
    /// ```
    pub fn terms(&self) -> impl Iterator<Item = (&[u32], &Rational)> + '_ {
        self.terms.iter().map(|(e, c)| (e.as_slice(), c))
    }

    /// The degree in variable `var` (0 for the zero polynomial).
    ///
    /// # Examples
    /// ```
    /// use lncert::poly::MPoly;
    /// let p = MPoly::var(0).pow(3) * MPoly::var(1) + MPoly::var(1).pow(2);
    /// assert_eq!((p.degree_in(0), p.degree_in(1), p.degree_in(5)), (3, 2, 0));
    /// ```
    pub fn degree_in(&self, var: usize) -> u32 {
        self.terms
            .keys()
            .map(|e| e.get(var).copied().unwrap_or(0))
            .max()
            .unwrap_or(0)
    }

    /// The total degree (0 for the zero polynomial).
    ///
    /// # Examples
    /// ```
    /// use lncert::poly::MPoly;
    /// let p = MPoly::var(0).pow(3) * MPoly::var(1) + MPoly::var(1).pow(2);
    /// assert_eq!(p.total_degree(), 4);
    /// ```
    pub fn total_degree(&self) -> u32 {
        self.terms
            .keys()
            .map(|e| e.iter().sum::<u32>())
            .max()
            .unwrap_or(0)
    }

    /// Degree in each variable, up to the last variable that occurs.
    fn degrees(&self) -> Vec<u32> {
        let mut d: Vec<u32> = Vec::new();
        for e in self.terms.keys() {
            if e.len() > d.len() {
                d.resize(e.len(), 0);
            }
            for (a, &b) in d.iter_mut().zip(e) {
                *a = (*a).max(b);
            }
        }
        d
    }

    /// `self += c * x^e` (in place, keeping the canonical form).
    fn add_term(&mut self, e: Vec<u32>, c: Rational) {
        if c.is_zero() {
            return;
        }
        match self.terms.entry(e) {
            std::collections::btree_map::Entry::Vacant(v) => {
                v.insert(c);
            }
            std::collections::btree_map::Entry::Occupied(mut o) => {
                *o.get_mut() += c;
                if o.get().is_zero() {
                    o.remove();
                }
            }
        }
    }

    /// `self += o` in place.
    fn add_assign_ref(&mut self, o: &MPoly) {
        for (e, c) in &o.terms {
            match self.terms.get_mut(e) {
                Some(v) => {
                    *v += c;
                    if v.is_zero() {
                        self.terms.remove(e);
                    }
                }
                None => {
                    self.terms.insert(e.clone(), c.clone());
                }
            }
        }
    }

    /// The sum.
    ///
    /// # Examples
    /// ```
    /// use lncert::poly::MPoly;
    /// let (x, y) = (MPoly::var(0), MPoly::var(1));
    /// assert_eq!(MPoly::add(&x, &y).to_string(), "x0 + x1");
    /// ```
    pub fn add(&self, o: &MPoly) -> MPoly {
        let (mut big, small) = if self.terms.len() >= o.terms.len() {
            (self.clone(), o)
        } else {
            (o.clone(), self)
        };
        big.add_assign_ref(small);
        big
    }

    /// The difference.
    ///
    /// # Examples
    /// ```
    /// use lncert::poly::MPoly;
    /// let (x, y) = (MPoly::var(0), MPoly::var(1));
    /// assert_eq!(MPoly::sub(&x, &y).to_string(), "x0 - x1");
    /// ```
    pub fn sub(&self, o: &MPoly) -> MPoly {
        let mut r = self.clone();
        for (e, c) in &o.terms {
            r.add_term(e.clone(), -c.clone());
        }
        r
    }

    /// The negation.
    ///
    /// # Examples
    /// ```
    /// use lncert::poly::MPoly;
    /// assert_eq!(MPoly::neg(&MPoly::var(0)).to_string(), "-x0");
    /// ```
    pub fn neg(&self) -> MPoly {
        MPoly {
            terms: self
                .terms
                .iter()
                .map(|(e, c)| (e.clone(), -c.clone()))
                .collect(),
        }
    }

    /// `c * self`.
    ///
    /// # Examples
    /// ```
    /// use lncert::poly::MPoly;
    /// use lncert::scalar::Rational;
    /// let p = MPoly::var(0).scale(&Rational::new(1.into(), 2.into()));
    /// assert_eq!(p.to_string(), "1/2*x0");
    /// ```
    pub fn scale(&self, c: &Rational) -> MPoly {
        if c.is_zero() {
            return MPoly::zero();
        }
        if c.is_one() {
            return self.clone();
        }
        MPoly {
            terms: self.terms.iter().map(|(e, a)| (e.clone(), a * c)).collect(),
        }
    }

    /// Common denominator `l` and the integer coefficients of `l * self`.
    fn integer_form(&self) -> (BigInt, Vec<(&[u32], BigInt)>) {
        let mut l = BigInt::one();
        for c in self.terms.values() {
            if !c.denom().is_one() {
                l = l.lcm(c.denom());
            }
        }
        let t = self
            .terms
            .iter()
            .map(|(e, c)| {
                let k = if l.is_one() {
                    c.numer().clone()
                } else {
                    c.numer() * (&l / c.denom())
                };
                (e.as_slice(), k)
            })
            .collect();
        (l, t)
    }

    /// The product.
    ///
    /// # Examples
    /// ```
    /// use lncert::poly::MPoly;
    /// let (x, y) = (MPoly::var(0), MPoly::var(1));
    /// let p = MPoly::mul(&(x.clone() + y.clone()), &(x - y));
    /// assert_eq!(p.to_string(), "x0^2 - x1^2");
    /// ```
    pub fn mul(&self, o: &MPoly) -> MPoly {
        if self.is_zero() || o.is_zero() {
            return MPoly::zero();
        }
        if let Some(c) = self.as_constant() {
            return o.scale(&c);
        }
        if let Some(c) = o.as_constant() {
            return self.scale(&c);
        }
        // Multiply in integers (no gcd per operation), divide once at the end.
        let (la, ta) = self.integer_form();
        let (lb, tb) = o.integer_form();
        let mut acc: HashMap<Vec<u32>, BigInt> =
            HashMap::with_capacity((ta.len() * tb.len()).min(1 << 16));
        let mut buf = Vec::new();
        for (ea, ca) in &ta {
            for (eb, cb) in &tb {
                add_exps_into(&mut buf, ea, eb);
                let prod = ca * cb;
                match acc.get_mut(buf.as_slice()) {
                    Some(v) => *v += prod,
                    None => {
                        acc.insert(buf.clone(), prod);
                    }
                }
            }
        }
        let den = la * lb;
        let den_is_one = den.is_one();
        let terms = acc
            .into_iter()
            .filter(|(_, c)| !c.is_zero())
            .map(|(e, c)| {
                let r = if den_is_one {
                    Rational::from_integer(c)
                } else {
                    Rational::new(c, den.clone())
                };
                (e, r)
            })
            .collect();
        MPoly { terms }
    }

    /// `self^k` (`self^0 = 1`).
    ///
    /// # Examples
    /// ```
    /// use lncert::poly::MPoly;
    /// let p = (MPoly::var(0) - MPoly::one()).pow(2);
    /// assert_eq!(p.to_string(), "x0^2 - 2*x0 + 1");
    /// assert!(MPoly::zero().pow(0).is_one());
    /// ```
    pub fn pow(&self, k: u32) -> MPoly {
        // Repeated multiplication by the (small) base is cheaper than squaring
        // for sparse multivariate polynomials.
        let mut acc = MPoly::one();
        for _ in 0..k {
            acc = acc.mul(self);
        }
        acc
    }

    /// The value at `x_i = values[i]`.
    ///
    /// # Panics
    /// If a variable that occurs has no value (`values` too short).
    ///
    /// # Examples
    /// ```
    /// use lncert::poly::MPoly;
    /// use lncert::scalar::Rational;
    /// let p = MPoly::var(0) * MPoly::var(1) + MPoly::one();
    /// let v = [Rational::from_integer(2.into()), Rational::new(1.into(), 3.into())];
    /// assert_eq!(p.eval(&v), Rational::new(5.into(), 3.into()));
    /// ```
    pub fn eval(&self, values: &[Rational]) -> Rational {
        let mut acc = <Rational as Zero>::zero();
        for (e, c) in &self.terms {
            assert!(
                e.len() <= values.len(),
                "MPoly::eval: no value for variable x{} (only {} given)",
                e.len() - 1,
                values.len()
            );
            let mut t = c.clone();
            for (v, &k) in values.iter().zip(e) {
                if k > 0 {
                    t *= num_traits::pow(v.clone(), k as usize);
                }
            }
            acc += t;
        }
        acc
    }

    /// The polynomial with `x_var` replaced by `q`.
    ///
    /// # Examples
    /// ```
    /// use lncert::poly::MPoly;
    /// use lncert::scalar::Rational;
    /// let (x, y) = (MPoly::var(0), MPoly::var(1));
    /// let p = x.pow(2) + y.clone();
    /// // x -> y + 1
    /// let r = p.substitute(0, &(y.clone() + MPoly::one()));
    /// let three = MPoly::constant(Rational::from_integer(3.into()));
    /// assert_eq!(r, y.pow(2) + three * y.clone() + MPoly::one());
    /// ```
    pub fn substitute(&self, var: usize, q: &MPoly) -> MPoly {
        let coeffs = self.coefficients_in(var);
        let mut acc = MPoly::zero();
        for c in coeffs.iter().rev() {
            acc = acc.mul(q);
            acc.add_assign_ref(c);
        }
        acc
    }

    /// The polynomial as univariate in `x_var`: entry `k` is the coefficient of
    /// `x_var^k` (a polynomial free of `x_var`). Empty for the zero polynomial,
    /// otherwise of length `degree_in(var) + 1`.
    ///
    /// # Examples
    /// ```
    /// use lncert::poly::MPoly;
    /// let (x, y) = (MPoly::var(0), MPoly::var(1));
    /// let p = x.pow(2) * y.clone() + x.clone() + y.clone();
    /// let c = p.coefficients_in(0);
    /// assert_eq!(c, vec![y.clone(), MPoly::one(), y]);
    /// ```
    pub fn coefficients_in(&self, var: usize) -> Vec<MPoly> {
        if self.is_zero() {
            return Vec::new();
        }
        let mut out = vec![MPoly::zero(); self.degree_in(var) as usize + 1];
        for (e, c) in &self.terms {
            let k = e.get(var).copied().unwrap_or(0);
            let key = if k == 0 {
                e.clone()
            } else {
                let mut f = e.clone();
                f[var] = 0;
                trim(f)
            };
            out[k as usize].terms.insert(key, c.clone());
        }
        out
    }

    /// The partial derivative with respect to `x_var`.
    ///
    /// # Examples
    /// ```
    /// use lncert::poly::MPoly;
    /// let (x, y) = (MPoly::var(0), MPoly::var(1));
    /// let p = x.pow(3) * y.clone() + y.clone();
    /// assert_eq!(p.derivative(0).to_string(), "3*x0^2*x1");
    /// ```
    pub fn derivative(&self, var: usize) -> MPoly {
        let mut terms = BTreeMap::new();
        for (e, c) in &self.terms {
            let k = e.get(var).copied().unwrap_or(0);
            if k > 0 {
                let mut f = e.clone();
                f[var] = k - 1;
                terms.insert(trim(f), c * Rational::from_integer(k.into()));
            }
        }
        MPoly { terms }
    }

    /// The leading term in lex order (`x0 > x1 > ...`), `None` for zero.
    fn leading(&self) -> Option<(&Vec<u32>, &Rational)> {
        self.terms.last_key_value()
    }

    /// The exact quotient `self / d` if `d` divides `self`, else `None`
    /// (also `None` for `d = 0`).
    ///
    /// # Examples
    /// ```
    /// use lncert::poly::MPoly;
    /// let (x, y) = (MPoly::var(0), MPoly::var(1));
    /// let p = x.pow(2) - y.pow(2);
    /// assert_eq!(p.div_exact(&(x.clone() - y.clone())), Some(x.clone() + y.clone()));
    /// assert_eq!(p.div_exact(&(x + MPoly::one())), None);
    /// ```
    pub fn div_exact(&self, d: &MPoly) -> Option<MPoly> {
        let (dlm, _) = d.leading()?;
        if self.is_zero() {
            return Some(MPoly::zero());
        }
        if let Some(c) = d.as_constant() {
            return Some(self.scale(&c.recip()));
        }
        // If d*q = self then deg_v(q) = deg_v(self) - deg_v(d) for every v and
        // likewise for total degrees: bound the quotient's terms by that box,
        // which also bounds the work when d does not divide.
        let ds = self.degrees();
        let dd = d.degrees();
        if dd.len() > ds.len() {
            return None;
        }
        let mut bound = Vec::with_capacity(ds.len());
        for (i, &a) in ds.iter().enumerate() {
            bound.push(a.checked_sub(dd.get(i).copied().unwrap_or(0))?);
        }
        let total_bound = self.total_degree().checked_sub(d.total_degree())?;
        // Leading and trailing terms of a product are products of the
        // factors' leading and trailing terms.
        let (slm, _) = self.leading()?;
        let (stm, _) = self.terms.first_key_value()?;
        let (dtm, _) = d.terms.first_key_value()?;
        monomial_quotient(slm, dlm)?;
        monomial_quotient(stm, dtm)?;
        // Divide in integers. With self = R / ls and d = g * D / ld, D
        // primitive, Gauss's lemma says that if D divides R over Q the
        // quotient has integer coefficients: a non-integer step means "no".
        let (ls, rs) = self.integer_form();
        let (ld, dt) = d.integer_form();
        let g = dt.iter().fold(BigInt::zero(), |g, (_, c)| g.gcd(c));
        let dt: Vec<(&[u32], BigInt)> = dt.into_iter().map(|(e, c)| (e, c / &g)).collect();
        let dlc = dt.last().map(|(_, c)| c.clone()).expect("d is nonzero");
        let mut r: BTreeMap<Vec<u32>, BigInt> =
            rs.into_iter().map(|(e, c)| (e.to_vec(), c)).collect();
        let mut q: Vec<(Vec<u32>, BigInt)> = Vec::new();
        let mut buf = Vec::new();
        while let Some((lm, lc)) = r.last_key_value() {
            let m = monomial_quotient(lm, dlm)?;
            if m.iter()
                .enumerate()
                .any(|(i, &k)| k > bound.get(i).copied().unwrap_or(0))
                || m.iter().sum::<u32>() > total_bound
            {
                return None;
            }
            let (cq, rem) = lc.div_rem(&dlc);
            if !rem.is_zero() {
                return None;
            }
            for (e, dc) in &dt {
                add_exps_into(&mut buf, &m, e);
                let delta = &cq * dc;
                match r.get_mut(buf.as_slice()) {
                    Some(v) => {
                        *v -= delta;
                        if v.is_zero() {
                            r.remove(buf.as_slice());
                        }
                    }
                    None => {
                        r.insert(buf.clone(), -delta);
                    }
                }
            }
            q.push((m, cq));
        }
        // self / d = (R / D) * ld / (ls * g).
        let f = Rational::new(ld, ls * g);
        Some(MPoly {
            terms: q
                .into_iter()
                .map(|(m, c)| (m, Rational::from_integer(c) * &f))
                .collect(),
        })
    }

    /// The rational `k` such that `k * self` has coprime integer coefficients
    /// and a positive leading coefficient (`self` nonzero).
    fn primitive_factor(&self) -> Rational {
        let mut l = BigInt::one();
        for c in self.terms.values() {
            if !c.denom().is_one() {
                l = l.lcm(c.denom());
            }
        }
        let mut g = BigInt::zero();
        for c in self.terms.values() {
            g = g.gcd(&(c.numer() * (&l / c.denom())));
        }
        let k = Rational::new(l, g);
        match self.leading() {
            Some((_, c)) if c.is_negative() => -k,
            _ => k,
        }
    }

    /// Largest monomial dividing every term (trimmed), empty for zero.
    fn monomial_content(&self) -> Vec<u32> {
        let mut it = self.terms.keys();
        let Some(first) = it.next() else {
            return Vec::new();
        };
        let mut g = first.clone();
        for e in it {
            g.truncate(e.len());
            for (a, &b) in g.iter_mut().zip(e) {
                *a = (*a).min(b);
            }
        }
        trim(g)
    }

    /// Divides every term by the monomial `x^g` (which must divide them all).
    fn div_monomial(&self, g: &[u32]) -> MPoly {
        let terms = self
            .terms
            .iter()
            .map(|(e, c)| {
                let f: Vec<u32> = e
                    .iter()
                    .enumerate()
                    .map(|(i, &a)| a - g.get(i).copied().unwrap_or(0))
                    .collect();
                (trim(f), c.clone())
            })
            .collect();
        MPoly { terms }
    }

    /// `Some(c)` if `self = c * o` for a rational `c` (`o` nonzero).
    fn ratio_to(&self, o: &MPoly) -> Option<Rational> {
        if self.terms.len() != o.terms.len() || o.is_zero() {
            return None;
        }
        let mut ratio: Option<Rational> = None;
        for ((ea, ca), (eb, cb)) in self.terms.iter().zip(&o.terms) {
            if ea != eb {
                return None;
            }
            let r = ca / cb;
            match &ratio {
                None => ratio = Some(r),
                Some(x) if *x == r => {}
                Some(_) => return None,
            }
        }
        ratio
    }

    /// The polynomial printed with variable names (`names[i]` for `x_i`,
    /// falling back to `x{i}` beyond the slice).
    ///
    /// # Examples
    /// ```
    /// use lncert::poly::MPoly;
    /// use lncert::scalar::Rational;
    /// let p = MPoly::monomial(&[2, 1], Rational::new(3.into(), 2.into())) - MPoly::var(2) + MPoly::one();
    /// assert_eq!(p.to_string(), "3/2*x0^2*x1 - x2 + 1");
    /// assert_eq!(p.display_with(&["t", "tau"]), "3/2*t^2*tau - x2 + 1");
    /// ```
    pub fn display_with(&self, names: &[&str]) -> String {
        let mut s = String::new();
        self.write_with(&mut s, names)
            .expect("writing to a String cannot fail");
        s
    }

    fn write_with(&self, f: &mut impl fmt::Write, names: &[&str]) -> fmt::Result {
        if self.is_zero() {
            return f.write_str("0");
        }
        for (i, (e, c)) in self.terms.iter().rev().enumerate() {
            let neg = c.is_negative();
            match (i == 0, neg) {
                (true, true) => f.write_str("-")?,
                (true, false) => {}
                (false, true) => f.write_str(" - ")?,
                (false, false) => f.write_str(" + ")?,
            }
            let a = c.abs();
            if e.is_empty() {
                write!(f, "{a}")?;
                continue;
            }
            if !a.is_one() {
                write!(f, "{a}*")?;
            }
            let mut first = true;
            for (v, &k) in e.iter().enumerate() {
                if k == 0 {
                    continue;
                }
                if !first {
                    f.write_str("*")?;
                }
                first = false;
                f.write_str(&var_name(names, v))?;
                if k > 1 {
                    write!(f, "^{k}")?;
                }
            }
        }
        Ok(())
    }
}

impl fmt::Display for MPoly {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        self.write_with(f, &[])
    }
}

impl fmt::Debug for MPoly {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        write!(f, "MPoly({self})")
    }
}

impl From<Rational> for MPoly {
    fn from(c: Rational) -> Self {
        MPoly::constant(c)
    }
}

// The std operators are implemented with full paths and the traits are not
// imported here, so that `p.mul(&q)` in this module always means the inherent
// (by-reference) method.

impl std::ops::Add for MPoly {
    type Output = MPoly;
    fn add(self, o: MPoly) -> MPoly {
        let (mut big, small) = if self.terms.len() >= o.terms.len() {
            (self, o)
        } else {
            (o, self)
        };
        big.add_assign_ref(&small);
        big
    }
}

impl std::ops::Add<&MPoly> for MPoly {
    type Output = MPoly;
    fn add(mut self, o: &MPoly) -> MPoly {
        self.add_assign_ref(o);
        self
    }
}

impl std::ops::Add<MPoly> for &MPoly {
    type Output = MPoly;
    fn add(self, mut o: MPoly) -> MPoly {
        o.add_assign_ref(self);
        o
    }
}

impl std::ops::Add<&MPoly> for &MPoly {
    type Output = MPoly;
    fn add(self, o: &MPoly) -> MPoly {
        MPoly::add(self, o)
    }
}

impl std::ops::Sub for MPoly {
    type Output = MPoly;
    fn sub(self, o: MPoly) -> MPoly {
        self - &o
    }
}

impl std::ops::Sub<&MPoly> for MPoly {
    type Output = MPoly;
    fn sub(mut self, o: &MPoly) -> MPoly {
        for (e, c) in &o.terms {
            self.add_term(e.clone(), -c.clone());
        }
        self
    }
}

impl std::ops::Sub<MPoly> for &MPoly {
    type Output = MPoly;
    fn sub(self, o: MPoly) -> MPoly {
        -o + self
    }
}

impl std::ops::Sub<&MPoly> for &MPoly {
    type Output = MPoly;
    fn sub(self, o: &MPoly) -> MPoly {
        MPoly::sub(self, o)
    }
}

impl std::ops::Mul for MPoly {
    type Output = MPoly;
    fn mul(self, o: MPoly) -> MPoly {
        MPoly::mul(&self, &o)
    }
}

impl std::ops::Mul<&MPoly> for MPoly {
    type Output = MPoly;
    fn mul(self, o: &MPoly) -> MPoly {
        MPoly::mul(&self, o)
    }
}

impl std::ops::Mul<MPoly> for &MPoly {
    type Output = MPoly;
    fn mul(self, o: MPoly) -> MPoly {
        MPoly::mul(self, &o)
    }
}

impl std::ops::Mul<&MPoly> for &MPoly {
    type Output = MPoly;
    fn mul(self, o: &MPoly) -> MPoly {
        MPoly::mul(self, o)
    }
}

impl std::ops::Neg for MPoly {
    type Output = MPoly;
    fn neg(mut self) -> MPoly {
        for c in self.terms.values_mut() {
            *c = -std::mem::take(c);
        }
        self
    }
}

impl std::ops::Neg for &MPoly {
    type Output = MPoly;
    fn neg(self) -> MPoly {
        MPoly::neg(self)
    }
}

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

#[cfg(test)]
mod tests {
    use super::*;
    use crate::poly::Poly;
    use crate::scalar::parse_rational;

    fn q(s: &str) -> Rational {
        parse_rational(s).unwrap()
    }

    fn c(n: i64) -> RatFunc {
        RatFunc::from_i64(n)
    }

    #[test]
    fn square_of_sum_mpoly() {
        let (x, y) = (MPoly::var(0), MPoly::var(1));
        let lhs = (x.clone() + y.clone()).pow(2);
        let rhs = x.pow(2) + MPoly::constant(q("2")) * x.clone() * y.clone() + y.pow(2);
        assert_eq!(lhs, rhs);
        assert_eq!(lhs.total_degree(), 2);
        assert_eq!(lhs.num_terms(), 3);
    }

    #[test]
    fn canonical_form_trims_and_drops_zeros() {
        let a = MPoly::monomial(&[1, 0, 0], q("2"));
        let b = MPoly::monomial(&[1], q("2"));
        assert_eq!(a, b);
        let x = MPoly::var(3);
        assert!((x.clone() - x.clone()).is_zero());
        assert_eq!(x.clone() - x, MPoly::zero());
        assert!(MPoly::monomial(&[5], q("0")).is_zero());
        // A product whose high variable cancels.
        let y = MPoly::var(4);
        let p = (y.clone() + MPoly::one()) * (y.clone() - MPoly::one()) - y.pow(2);
        assert_eq!(p, MPoly::constant(q("-1")));
    }

    #[test]
    fn difference_of_squares_over_difference() {
        let (x, y) = (RatFunc::var(0), RatFunc::var(1));
        let f = (x.clone() * x.clone() - y.clone() * y.clone())
            .div(&(x.clone() - y.clone()))
            .unwrap();
        assert_eq!(f, x.clone() + y.clone());
        assert!(identity_holds(&f, &(x.clone() + y.clone())));
        // Also when built without the simplifying paths.
        let g = RatFunc::new(
            MPoly::var(0).pow(2) - MPoly::var(1).pow(2),
            MPoly::var(0) - MPoly::var(1),
        )
        .unwrap();
        assert_eq!(g, x + y);
    }

    #[test]
    fn symbolic_poly_eval() {
        // p(t) = a + b t + c t^2 with symbolic a, b, c.
        let (a, b, cc, s) = (
            RatFunc::var(0),
            RatFunc::var(1),
            RatFunc::var(2),
            RatFunc::var(3),
        );
        let p = Poly::new(vec![a.clone(), b.clone(), cc.clone()]);
        let v = p.eval(&s);
        assert_eq!(
            v,
            a.clone() + b.clone() * s.clone() + cc.clone() * s.clone() * s.clone()
        );
        // At a rational point.
        let half = RatFunc::constant(q("1/2"));
        let w = p.eval(&half);
        assert_eq!(
            w,
            a.clone() + b.clone() * half.clone() + cc.clone() * c(1).div(&c(4)).unwrap()
        );
        // Evaluate the symbolic result numerically: a=1, b=2, c=4 at t=1/2 -> 3.
        assert_eq!(w.eval(&[q("1"), q("2"), q("4")]), Some(q("3")));
        // The derivative kernel.
        assert_eq!(p.derivative().eval(&s), b + cc.scale(2) * s);
        // poly_in builds the same function.
        assert_eq!(poly_in(3, &p), v);
    }

    #[test]
    fn cubic_bernstein_derivative_identity() {
        let b: Vec<RatFunc> = (0..4).map(RatFunc::var).collect();
        let p = Poly::from_bernstein(&b);
        let d = p.derivative();
        let hodograph = Poly::from_bernstein(&[
            (b[1].clone() - b[0].clone()).scale(3),
            (b[2].clone() - b[1].clone()).scale(3),
            (b[3].clone() - b[2].clone()).scale(3),
        ]);
        assert_eq!(d.coeffs().len(), hodograph.coeffs().len());
        assert_eq!(d, hodograph);
        let t = 4;
        assert!(identity_holds(&poly_in(t, &d), &poly_in(t, &hodograph)));
        // And the polynomial in t as an MPoly has the expected shape.
        let f = poly_in(t, &p);
        assert!(f.den().is_one());
        assert_eq!(f.num().degree_in(t), 3);
        let cs = univariate_coeffs(f.num(), t);
        assert_eq!(cs.len(), 4);
        assert_eq!(cs[0], MPoly::var(0));
        // Derivative in t of the symbolic function agrees with the kernel.
        assert_eq!(f.derivative(t), poly_in(t, &d));
    }

    #[test]
    fn bernstein_with_rational_function_control_values() {
        // Control values with denominators like the papers' (3τ-1)(3τ-2).
        let tau = RatFunc::var(0);
        let b0 = RatFunc::var(1);
        let b1 = b0.clone().div(&(tau.scale(3) - c(1))).unwrap();
        let b2 = b0.clone().div(&(tau.scale(3) - c(2))).unwrap();
        let b3 = RatFunc::var(2);
        let p = Poly::from_bernstein(&[b0.clone(), b1.clone(), b2.clone(), b3.clone()]);
        let hodo = Poly::from_bernstein(&[
            (b1.clone() - b0.clone()).scale(3),
            (b2.clone() - b1.clone()).scale(3),
            (b3.clone() - b2.clone()).scale(3),
        ]);
        assert_eq!(p.derivative(), hodo);
        // Endpoint interpolation: p(0) = b0, p(1) = b3.
        assert_eq!(p.eval(&c(0)), b0);
        assert_eq!(p.eval(&c(1)), b3);
        let t = 3;
        let f = poly_in(t, &p);
        assert_eq!(f.substitute(t, &c(1)).unwrap(), b3);
        // Denominators stay factors of (3τ-1)(3τ-2), not their squares.
        assert!(f.den().total_degree() <= 2, "den = {}", f.den());
    }

    #[test]
    fn sign_and_recip() {
        let (x, y) = (RatFunc::var(0), RatFunc::var(1));
        assert_eq!(x.sign(), Sign::Unknown);
        assert_eq!((x.clone() * x.clone() + c(1)).sign(), Sign::Unknown);
        assert_eq!(x.clone().div(&y).unwrap().sign(), Sign::Unknown);
        assert_eq!(c(-3).sign(), Sign::Negative);
        assert_eq!(c(0).sign(), Sign::Zero);
        assert_eq!((x.clone() - x.clone()).sign(), Sign::Zero);
        assert_eq!(RatFunc::constant(q("2/7")).sign(), Sign::Positive);
        // Proportional numerator and denominator: a constant.
        let k = RatFunc::new(
            MPoly::var(0).scale(&q("-2")) + MPoly::var(1),
            MPoly::var(0) - MPoly::var(1).scale(&q("1/2")),
        )
        .unwrap();
        assert_eq!(k.sign(), Sign::Negative);
        assert_eq!(k.approx(), -2.0);
        assert!(x.approx().is_nan());
        assert_eq!(RatFunc::constant(q("1/4")).approx(), 0.25);
        // recip
        assert!(c(0).recip().is_none());
        assert!((x.clone() - x.clone()).recip().is_none());
        assert!(x.div(&c(0)).is_none());
        let r = (x.clone() + y.clone()).recip().unwrap();
        assert_eq!(r * (x.clone() + y.clone()), c(1));
        assert_eq!(RatFunc::KIND, "symbolic");
        const { assert!(RatFunc::EXACT) };
    }

    #[test]
    fn identity_checker_can_fail() {
        let (x, y) = (RatFunc::var(0), RatFunc::var(1));
        let s = x.clone() + y.clone();
        assert!(!identity_holds(
            &(s.clone() * s.clone()),
            &(x.clone() * x.clone() + y.clone() * y.clone())
        ));
        assert_ne!(s.clone() * s, x.sqr() + y.sqr());
        // Different denominators, unequal functions.
        let a = c(1).div(&x).unwrap();
        let b = c(1).div(&(x + c(1))).unwrap();
        assert_ne!(a, b);
        assert_ne!(MPoly::var(0).pow(2), MPoly::var(0).pow(2) + MPoly::one());
    }

    #[test]
    fn display() {
        let p = MPoly::monomial(&[2, 1], q("3/2")) - MPoly::var(2) + MPoly::one();
        assert_eq!(p.to_string(), "3/2*x0^2*x1 - x2 + 1");
        assert_eq!(p.display_with(&["a", "b", "c"]), "3/2*a^2*b - c + 1");
        assert_eq!((-p).to_string(), "-3/2*x0^2*x1 + x2 - 1");
        assert_eq!(MPoly::zero().to_string(), "0");
        assert_eq!(MPoly::constant(q("-5")).to_string(), "-5");
        let f = RatFunc::var(0)
            .div(&(RatFunc::var(1) * RatFunc::var(2) + c(1)))
            .unwrap();
        assert_eq!(f.to_string(), "x0/(x1*x2 + 1)");
        assert_eq!(format!("{f:?}"), "RatFunc(x0/(x1*x2 + 1))");
        let g = (RatFunc::var(0) + c(1)).div(&RatFunc::var(1)).unwrap();
        assert_eq!(g.to_string(), "(x0 + 1)/x1");
    }

    #[test]
    fn eval_substitute_coefficients() {
        let (x, y, z) = (MPoly::var(0), MPoly::var(1), MPoly::var(2));
        let p = x.pow(2) * y.clone() - z.clone() * x.clone() + MPoly::constant(q("1/3"));
        assert_eq!(
            p.eval(&[q("2"), q("3"), q("5")]),
            q("12") - q("10") + q("1/3")
        );
        assert_eq!(p.degree_in(0), 2);
        assert_eq!(p.degree_in(2), 1);
        assert_eq!(p.degree_in(7), 0);
        assert_eq!(p.total_degree(), 3);
        let cs = p.coefficients_in(0);
        assert_eq!(cs, vec![MPoly::constant(q("1/3")), -z.clone(), y.clone()]);
        // Reassemble.
        let mut back = MPoly::zero();
        for (k, ck) in cs.iter().enumerate() {
            back = back + ck.clone() * x.pow(k as u32);
        }
        assert_eq!(back, p);
        assert!(MPoly::zero().coefficients_in(0).is_empty());
        // Substitution x -> y + z, checked at a point.
        let s = p.substitute(0, &(y.clone() + z.clone()));
        assert_eq!(s.degree_in(0), 0);
        let v = [q("7"), q("-2"), q("3/4")];
        assert_eq!(s.eval(&v), p.eval(&[q("-2") + q("3/4"), q("-2"), q("3/4")]));
        // Substitution of a rational function into a rational function.
        let f = RatFunc::new(x.clone() + y.clone(), x.clone() - y.clone()).unwrap();
        let val = RatFunc::new(y.clone(), z.clone() + MPoly::one()).unwrap();
        let g = f.substitute(0, &val).unwrap();
        let pt = [q("0"), q("2"), q("3")];
        let xv = q("2") / q("4");
        assert_eq!(g.eval(&pt), f.eval(&[xv, q("2"), q("3")]));
    }

    #[test]
    #[should_panic(expected = "no value for variable")]
    fn eval_panics_without_values() {
        MPoly::var(2).eval(&[q("1")]);
    }

    #[test]
    fn exact_division() {
        let (x, y, z) = (MPoly::var(0), MPoly::var(1), MPoly::var(2));
        let a = x.clone() * y.clone() - z.clone() + MPoly::constant(q("2/3"));
        let b = y.pow(2) + x.clone() * z.clone() - MPoly::one();
        let p = a.clone() * b.clone();
        assert_eq!(p.div_exact(&a), Some(b.clone()));
        assert_eq!(p.div_exact(&b), Some(a.clone()));
        assert_eq!((p.clone() + MPoly::one()).div_exact(&a), None);
        assert_eq!(p.div_exact(&MPoly::zero()), None);
        assert_eq!(
            p.div_exact(&MPoly::constant(q("2"))),
            Some(p.scale(&q("1/2")))
        );
        assert_eq!(a.div_exact(&p), None);
        // Non-homogeneous divisor whose quotient search must stop.
        assert_eq!(x.pow(6).div_exact(&(x.clone() - y.pow(2))), None);
    }

    #[test]
    fn representations_stay_small() {
        let tau = RatFunc::var(0);
        let d1 = tau.scale(3) - c(1);
        let d2 = tau.scale(3) - c(2);
        let u = c(1).div(&d1).unwrap();
        let v = c(1).div(&d2).unwrap();
        let w = u.clone() * v.clone();
        // u + w and w + u use exact division of denominators.
        let s = u.clone() + w.clone();
        assert_eq!(s.den().total_degree(), 2);
        let back = (s - w) * d1.clone();
        assert_eq!(back, c(1));
        assert!(back.den().is_one());
        // Cancellation in products.
        let m = u * d1;
        assert!(m.den().is_one());
        // Monomial content cancels.
        let f = RatFunc::new(MPoly::var(0).pow(3) * MPoly::var(1), MPoly::var(0).pow(2)).unwrap();
        assert!(f.den().is_one());
        assert_eq!(f, RatFunc::var(0) * RatFunc::var(1));
    }

    /// A small deterministic generator of polynomials with rational
    /// coefficients (the integer-only paths would hide scaling mistakes).
    struct Lcg(u64);
    impl Lcg {
        fn next(&mut self, n: u64) -> u64 {
            self.0 = self
                .0
                .wrapping_mul(6364136223846793005)
                .wrapping_add(1442695040888963407);
            (self.0 >> 33) % n
        }
        fn rational(&mut self) -> Rational {
            let num = self.next(19) as i64 - 9;
            let den = self.next(6) as i64 + 1;
            Rational::new(num.into(), den.into())
        }
        fn poly(&mut self, vars: usize, terms: usize, deg: u64) -> MPoly {
            let mut p = MPoly::zero();
            for _ in 0..terms {
                let e: Vec<u32> = (0..vars).map(|_| self.next(deg + 1) as u32).collect();
                p = p + MPoly::monomial(&e, self.rational());
            }
            p
        }
    }

    #[test]
    fn arithmetic_agrees_with_evaluation() {
        let mut g = Lcg(7);
        let pt = [q("2/3"), q("-5/2"), q("7/4")];
        for _ in 0..40 {
            let p = g.poly(3, 5, 3);
            let r = g.poly(3, 4, 2);
            let s = g.poly(3, 3, 2);
            let (pv, rv, sv) = (p.eval(&pt), r.eval(&pt), s.eval(&pt));
            assert_eq!((&p * &r).eval(&pt), &pv * &rv);
            assert_eq!((&p + &r).eval(&pt), &pv + &rv);
            assert_eq!((&p - &r).eval(&pt), &pv - &rv);
            assert_eq!(p.pow(3).eval(&pt), &pv * &pv * &pv);
            assert_eq!(&p * &(&r + &s), &p * &r + &p * &s);
            assert_eq!((&p + &r) - &r, p);
            assert_eq!(
                p.substitute(1, &s).eval(&pt),
                p.eval(&[pt[0].clone(), sv.clone(), pt[2].clone()])
            );
            if !r.is_zero() {
                assert_eq!((&p * &r).div_exact(&r), Some(p.clone()));
                if r.total_degree() > 0 {
                    // A non-constant r cannot divide p*r + 1/7.
                    let shifted = &p * &r + MPoly::constant(q("1/7"));
                    assert_eq!(shifted.div_exact(&r), None);
                }
            }
            // Rational functions: (p/r + s) * r - p == s * r, checked at the point.
            if !r.is_zero() && !rv.is_zero() {
                let (pf, rf, sf) = (
                    RatFunc::from_mpoly(p.clone()),
                    RatFunc::from_mpoly(r.clone()),
                    RatFunc::from_mpoly(s.clone()),
                );
                let f = pf.div(&rf).unwrap() + sf.clone();
                assert_eq!(f.eval(&pt), Some(&pv / &rv + &sv));
                assert_eq!(f * rf.clone() - pf, sf * rf);
            }
        }
    }

    #[test]
    fn moderate_size_identity() {
        // 6 variables, total degree 10: (s^5)(s^5) == s^10 and a derived
        // identity with a non-trivial denominator.
        let s = (0..6).map(MPoly::var).fold(MPoly::one(), |a, b| a + b);
        let s5 = s.pow(5);
        let s10 = s.pow(10);
        assert_eq!(s5.mul(&s5), s10);
        assert_eq!(s10.num_terms(), 8008); // C(16, 6)
        let f = RatFunc::new(s10.clone(), s.pow(3)).unwrap();
        assert_eq!(f, RatFunc::from_mpoly(s.pow(7)));
        assert_eq!(s10.div_exact(&s.pow(3)), Some(s.pow(7)));
    }
}
