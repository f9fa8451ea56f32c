//! Sparse multivariate polynomials over Q.

use crate::scalar::Rational;
use num_bigint::BigInt;
use num_integer::Integer;
use num_traits::{One, Signed, Zero};
use std::collections::{BTreeMap, HashMap};
use std::fmt;

// ---------------------------------------------------------------------------
// Exponent vectors
// ---------------------------------------------------------------------------

/// Removes trailing zero exponents (the canonical form of a monomial key).
pub(super) fn trim(mut e: Vec<u32>) -> Vec<u32> {
    while e.last() == Some(&0) {
        e.pop();
    }
    e
}

/// `buf = a + b` componentwise. The sum of two trimmed vectors is trimmed.
pub(super) fn add_exps_into(buf: &mut Vec<u32>, a: &[u32], b: &[u32]) {
    buf.clear();
    let n = a.len().max(b.len());
    buf.extend((0..n).map(|i| a.get(i).copied().unwrap_or(0) + b.get(i).copied().unwrap_or(0)));
}

/// `a / b` if the monomial `b` divides `a` (trimmed), else `None`.
pub(super) fn monomial_quotient(a: &[u32], b: &[u32]) -> Option<Vec<u32>> {
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
pub(super) fn var_name(names: &[&str], i: usize) -> String {
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
    pub(super) fn degrees(&self) -> Vec<u32> {
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
    pub(super) fn add_term(&mut self, e: Vec<u32>, c: Rational) {
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
    pub(super) fn add_assign_ref(&mut self, o: &MPoly) {
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
    pub(super) fn integer_form(&self) -> (BigInt, Vec<(&[u32], BigInt)>) {
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
    pub(super) fn leading(&self) -> Option<(&Vec<u32>, &Rational)> {
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
    pub(super) fn primitive_factor(&self) -> Rational {
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
    pub(super) fn monomial_content(&self) -> Vec<u32> {
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
    pub(super) fn div_monomial(&self, g: &[u32]) -> MPoly {
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
    pub(super) fn ratio_to(&self, o: &MPoly) -> Option<Rational> {
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

    pub(super) fn write_with(&self, f: &mut impl fmt::Write, names: &[&str]) -> fmt::Result {
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
