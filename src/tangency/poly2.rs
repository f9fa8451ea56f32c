//! Dense bivariate polynomials `p(x, y) = Σ c_ij x^i y^j`, generic over the
//! scalar (exact [`Rational`], certified [`crate::scalar::Interval`], `f64`),
//! and an exact parser for small polynomial expressions.
//!
//! Layout: `coeffs[i * (deg_y + 1) + j]` is the coefficient of `x^i y^j`, the
//! layout of the raster module's `DensePoly2` (for the tangency system
//! `x = m`, the tangency parameter, and `y = a2`, seed 003 eq. (6), (7)).

use crate::scalar::{parse_rational, Rational, Scalar, Sign};

/// Largest degree in each variable accepted by the parser and by products
/// built from parsed input (keeps hostile input cheap).
pub const MAX_DEGREE: usize = 32;

/// A dense bivariate polynomial (see the module docs for the layout).
///
/// # Examples
/// ```
/// use lncert::tangency::Poly2;
/// let p = Poly2::<f64>::x().mul(&Poly2::y()).add(&Poly2::constant(1.0)); // xy + 1
/// assert_eq!(p.eval(&2.0, &3.0), 7.0);
/// assert_eq!(p.dx().eval(&2.0, &3.0), 3.0);
/// assert_eq!(p.total_degree(), Some(2));
/// ```
#[derive(Clone, Debug, PartialEq)]
pub struct Poly2<S> {
    deg_x: usize,
    deg_y: usize,
    coeffs: Vec<S>,
}

impl<S: Scalar> Poly2<S> {
    /// From the layout `coeffs[i * (deg_y + 1) + j]`; `None` if the length is not
    /// `(deg_x + 1) (deg_y + 1)`.
    pub fn from_coeffs(deg_x: usize, deg_y: usize, coeffs: Vec<S>) -> Option<Self> {
        let n = deg_x.checked_add(1)?.checked_mul(deg_y.checked_add(1)?)?;
        (coeffs.len() == n).then_some(Poly2 {
            deg_x,
            deg_y,
            coeffs,
        })
    }
    /// The constant `a`.
    pub fn constant(a: S) -> Self {
        Poly2 {
            deg_x: 0,
            deg_y: 0,
            coeffs: vec![a],
        }
    }
    /// The zero polynomial.
    pub fn zero() -> Self {
        Self::constant(S::zero())
    }
    /// The monomial `x`.
    pub fn x() -> Self {
        Poly2 {
            deg_x: 1,
            deg_y: 0,
            coeffs: vec![S::zero(), S::one()],
        }
    }
    /// The monomial `y`.
    pub fn y() -> Self {
        Poly2 {
            deg_x: 0,
            deg_y: 1,
            coeffs: vec![S::zero(), S::one()],
        }
    }
    /// Formal degree in `x` (an upper bound of the degree in `x`).
    pub fn deg_x(&self) -> usize {
        self.deg_x
    }
    /// Formal degree in `y`.
    pub fn deg_y(&self) -> usize {
        self.deg_y
    }
    /// The coefficients in the documented layout.
    pub fn coeffs(&self) -> &[S] {
        &self.coeffs
    }
    /// The coefficient of `x^i y^j` (zero outside the formal degrees).
    pub fn coeff(&self, i: usize, j: usize) -> S {
        if i <= self.deg_x && j <= self.deg_y {
            self.coeffs[i * (self.deg_y + 1) + j].clone()
        } else {
            S::zero()
        }
    }
    fn build(deg_x: usize, deg_y: usize, f: impl Fn(usize, usize) -> S) -> Self {
        let mut coeffs = Vec::with_capacity((deg_x + 1) * (deg_y + 1));
        for i in 0..=deg_x {
            for j in 0..=deg_y {
                coeffs.push(f(i, j));
            }
        }
        Poly2 {
            deg_x,
            deg_y,
            coeffs,
        }
    }
    /// `self + o`.
    pub fn add(&self, o: &Self) -> Self {
        Self::build(self.deg_x.max(o.deg_x), self.deg_y.max(o.deg_y), |i, j| {
            self.coeff(i, j) + o.coeff(i, j)
        })
    }
    /// `self - o`.
    pub fn sub(&self, o: &Self) -> Self {
        self.add(&o.neg())
    }
    /// `-self`.
    pub fn neg(&self) -> Self {
        self.scale(&-S::one())
    }
    /// `k · self`.
    pub fn scale(&self, k: &S) -> Self {
        Poly2 {
            deg_x: self.deg_x,
            deg_y: self.deg_y,
            coeffs: self.coeffs.iter().map(|c| c.clone() * k.clone()).collect(),
        }
    }
    /// `self · o`.
    pub fn mul(&self, o: &Self) -> Self {
        let (dx, dy) = (self.deg_x + o.deg_x, self.deg_y + o.deg_y);
        let mut out = Self::build(dx, dy, |_, _| S::zero());
        for i in 0..=self.deg_x {
            for j in 0..=self.deg_y {
                let a = &self.coeffs[i * (self.deg_y + 1) + j];
                if a.sign() == Sign::Zero {
                    continue;
                }
                for k in 0..=o.deg_x {
                    for l in 0..=o.deg_y {
                        let idx = (i + k) * (dy + 1) + j + l;
                        let b = o.coeffs[k * (o.deg_y + 1) + l].clone();
                        out.coeffs[idx] = out.coeffs[idx].clone() + a.clone() * b;
                    }
                }
            }
        }
        out
    }
    /// `self^k`.
    pub fn pow(&self, k: u32) -> Self {
        (0..k).fold(Self::constant(S::one()), |acc, _| acc.mul(self))
    }
    /// `p(x, y)`: outer Horner over the powers of `x`, inner over `y`.
    pub fn eval(&self, x: &S, y: &S) -> S {
        let mut acc = S::zero();
        for i in (0..=self.deg_x).rev() {
            let mut inner = S::zero();
            for j in (0..=self.deg_y).rev() {
                inner = inner * y.clone() + self.coeffs[i * (self.deg_y + 1) + j].clone();
            }
            acc = acc * x.clone() + inner;
        }
        acc
    }
    /// `∂p/∂x`.
    pub fn dx(&self) -> Self {
        if self.deg_x == 0 {
            return Self::build(0, self.deg_y, |_, _| S::zero());
        }
        Self::build(self.deg_x - 1, self.deg_y, |i, j| {
            self.coeff(i + 1, j).scale(i as i64 + 1)
        })
    }
    /// `∂p/∂y`.
    pub fn dy(&self) -> Self {
        if self.deg_y == 0 {
            return Self::build(self.deg_x, 0, |_, _| S::zero());
        }
        Self::build(self.deg_x, self.deg_y - 1, |i, j| {
            self.coeff(i, j + 1).scale(j as i64 + 1)
        })
    }
    /// The total degree `max{i + j : c_ij ≠ 0}`; `None` for the zero polynomial
    /// or when a coefficient's sign is unknown (enclosures).
    pub fn total_degree(&self) -> Option<usize> {
        let mut best: Option<usize> = None;
        for i in 0..=self.deg_x {
            for j in 0..=self.deg_y {
                match self.coeffs[i * (self.deg_y + 1) + j].sign() {
                    Sign::Zero => {}
                    Sign::Unknown => return None,
                    _ => best = Some(best.map_or(i + j, |b| b.max(i + j))),
                }
            }
        }
        best
    }
    /// The same polynomial with formal degrees reduced to the true degrees in
    /// `x` and `y` (coefficients of unknown sign are kept).
    pub fn trimmed(&self) -> Self {
        let nonzero = |i: usize, j: usize| self.coeff(i, j).sign() != Sign::Zero;
        let dx = (0..=self.deg_x)
            .rev()
            .find(|&i| (0..=self.deg_y).any(|j| nonzero(i, j)))
            .unwrap_or(0);
        let dy = (0..=self.deg_y)
            .rev()
            .find(|&j| (0..=self.deg_x).any(|i| nonzero(i, j)))
            .unwrap_or(0);
        Self::build(dx, dy, |i, j| self.coeff(i, j))
    }
    /// The coefficients in another arithmetic.
    pub fn map<T: Scalar>(&self, f: impl Fn(&S) -> T) -> Poly2<T> {
        Poly2 {
            deg_x: self.deg_x,
            deg_y: self.deg_y,
            coeffs: self.coeffs.iter().map(f).collect(),
        }
    }
    /// `(deg_x, deg_y, coeffs)` with every coefficient rounded to the nearest
    /// `f64`, in the raster module's layout `coeffs[i * (deg_y + 1) + j]`.
    ///
    /// # Examples
    /// ```
    /// use lncert::tangency::parse_poly2;
    /// let p = parse_poly2("x^2*y + 1/10").unwrap();
    /// assert_eq!(p.coeffs_f64(), (2, 1, vec![0.1, 0.0, 0.0, 0.0, 0.0, 1.0]));
    /// ```
    pub fn coeffs_f64(&self) -> (usize, usize, Vec<f64>) {
        (
            self.deg_x,
            self.deg_y,
            self.coeffs.iter().map(Scalar::approx).collect(),
        )
    }
    /// The polynomial in `x` obtained by fixing `y` (coefficients `Σ_j c_ij y^j`).
    pub fn at_y(&self, y: &S) -> crate::poly::Poly<S> {
        crate::poly::Poly::new(
            (0..=self.deg_x)
                .map(|i| {
                    (0..=self.deg_y)
                        .rev()
                        .fold(S::zero(), |acc, j| acc * y.clone() + self.coeff(i, j))
                })
                .collect(),
        )
    }
    /// The polynomial in `y` obtained by fixing `x`.
    pub fn at_x(&self, x: &S) -> crate::poly::Poly<S> {
        crate::poly::Poly::new(
            (0..=self.deg_y)
                .map(|j| {
                    (0..=self.deg_x)
                        .rev()
                        .fold(S::zero(), |acc, i| acc * x.clone() + self.coeff(i, j))
                })
                .collect(),
        )
    }
    /// The coefficient of `y^j` as a polynomial in `x`.
    pub fn y_coefficient(&self, j: usize) -> crate::poly::Poly<S> {
        crate::poly::Poly::new((0..=self.deg_x).map(|i| self.coeff(i, j)).collect())
    }
}

/// Why a polynomial expression was rejected (positions are byte offsets).
#[derive(Clone, Debug, PartialEq, Eq, thiserror::Error)]
pub enum Poly2ParseError {
    /// The text is longer than [`MAX_INPUT`] bytes.
    #[error("expression: longer than {max} bytes")]
    TooLong {
        /// The limit, [`MAX_INPUT`].
        max: usize,
    },
    /// A character that is not part of the grammar.
    #[error("expression: unexpected {found:?} at byte {pos}")]
    Unexpected {
        /// Byte offset of the character.
        pos: usize,
        /// The character found there.
        found: String,
    },
    /// The text ended where an operand was expected.
    #[error("expression: unexpected end of input")]
    UnexpectedEnd,
    /// A number literal that [`parse_rational`] rejects.
    #[error("expression: bad number at byte {pos}: {reason}")]
    BadNumber {
        /// Byte offset where the literal starts.
        pos: usize,
        /// Why [`parse_rational`] rejected it.
        reason: String,
    },
    /// An exponent that is not a small non-negative integer.
    #[error("expression: exponent at byte {pos} must be an integer 0..={max}")]
    BadExponent {
        /// Byte offset where the exponent starts.
        pos: usize,
        /// The largest accepted exponent, [`MAX_DEGREE`].
        max: usize,
    },
    /// Division by a non-constant or zero expression.
    #[error("expression: division at byte {pos} by {reason}")]
    BadDivision {
        /// Byte offset of the `/`.
        pos: usize,
        /// What the divisor is: `"zero"` or `"a non-constant expression"`.
        reason: &'static str,
    },
    /// The degree in `x` or `y` exceeds [`MAX_DEGREE`].
    #[error("expression: degree in {var} exceeds {max}")]
    DegreeTooHigh {
        /// The variable, `"x"` or `"y"`.
        var: &'static str,
        /// The limit, [`MAX_DEGREE`].
        max: usize,
    },
    /// Parentheses nested deeper than [`MAX_NESTING`].
    #[error("expression: nested deeper than {max}")]
    TooDeep {
        /// The limit, [`MAX_NESTING`].
        max: usize,
    },
}

/// Longest accepted expression.
pub const MAX_INPUT: usize = 10_000;
/// Deepest accepted nesting of parentheses and unary minus.
pub const MAX_NESTING: usize = 64;

/// Parses an exact polynomial in `x` and `y`: `+ - * / ^`, parentheses, unary
/// minus, decimal and fraction literals read exactly (`1.995` is `399/200`).
/// Division only by nonzero constants; exponents are integers `0..=MAX_DEGREE`.
///
/// # Examples
/// ```
/// use lncert::tangency::parse_poly2;
/// use lncert::scalar::{frac, Rational};
/// let p = parse_poly2("y*(x - 1.995)*(y - x^2)*(y - x + 1)").unwrap();
/// assert_eq!(p.eval(&frac(1995, 1000), &frac(7, 3)), frac::<Rational>(0, 1));
/// assert!(parse_poly2("x^2 + ").is_err());
/// assert!(parse_poly2("x / y").is_err());
/// ```
pub fn parse_poly2(text: &str) -> Result<Poly2<Rational>, Poly2ParseError> {
    if text.len() > MAX_INPUT {
        return Err(Poly2ParseError::TooLong { max: MAX_INPUT });
    }
    let mut p = Parser {
        s: text.as_bytes(),
        pos: 0,
        depth: 0,
    };
    let e = p.expr()?;
    p.skip_ws();
    if p.pos < p.s.len() {
        return Err(p.unexpected());
    }
    Ok(e.trimmed())
}

struct Parser<'a> {
    s: &'a [u8],
    pos: usize,
    depth: usize,
}

type PResult = Result<Poly2<Rational>, Poly2ParseError>;

fn check_degree(p: Poly2<Rational>) -> PResult {
    let p = p.trimmed();
    if p.deg_x > MAX_DEGREE {
        return Err(Poly2ParseError::DegreeTooHigh {
            var: "x",
            max: MAX_DEGREE,
        });
    }
    if p.deg_y > MAX_DEGREE {
        return Err(Poly2ParseError::DegreeTooHigh {
            var: "y",
            max: MAX_DEGREE,
        });
    }
    Ok(p)
}

impl Parser<'_> {
    fn skip_ws(&mut self) {
        while self.pos < self.s.len() && self.s[self.pos].is_ascii_whitespace() {
            self.pos += 1;
        }
    }
    fn peek(&mut self) -> Option<u8> {
        self.skip_ws();
        self.s.get(self.pos).copied()
    }
    fn unexpected(&self) -> Poly2ParseError {
        match self.s.get(self.pos) {
            None => Poly2ParseError::UnexpectedEnd,
            Some(_) => {
                let rest = String::from_utf8_lossy(&self.s[self.pos..]);
                Poly2ParseError::Unexpected {
                    pos: self.pos,
                    found: rest.chars().next().map(String::from).unwrap_or_default(),
                }
            }
        }
    }
    fn enter(&mut self) -> Result<(), Poly2ParseError> {
        self.depth += 1;
        if self.depth > MAX_NESTING {
            Err(Poly2ParseError::TooDeep { max: MAX_NESTING })
        } else {
            Ok(())
        }
    }
    fn expr(&mut self) -> PResult {
        let mut acc = self.term()?;
        while let Some(c @ (b'+' | b'-')) = self.peek() {
            self.pos += 1;
            let t = self.term()?;
            acc = if c == b'+' { acc.add(&t) } else { acc.sub(&t) };
        }
        Ok(acc)
    }
    fn term(&mut self) -> PResult {
        let mut acc = self.unary()?;
        while let Some(c @ (b'*' | b'/')) = self.peek() {
            let at = self.pos;
            self.pos += 1;
            let f = self.unary()?;
            acc = if c == b'*' {
                check_degree(acc.mul(&f))?
            } else {
                let f = f.trimmed();
                if f.deg_x != 0 || f.deg_y != 0 {
                    return Err(Poly2ParseError::BadDivision {
                        pos: at,
                        reason: "a non-constant expression",
                    });
                }
                let inv = Scalar::recip(&f.coeffs[0]).ok_or(Poly2ParseError::BadDivision {
                    pos: at,
                    reason: "zero",
                })?;
                acc.scale(&inv)
            };
        }
        Ok(acc)
    }
    fn unary(&mut self) -> PResult {
        match self.peek() {
            Some(b'-') => {
                self.pos += 1;
                self.enter()?;
                let r = self.unary().map(|p| p.neg());
                self.depth -= 1;
                r
            }
            Some(b'+') => {
                self.pos += 1;
                self.enter()?;
                let r = self.unary();
                self.depth -= 1;
                r
            }
            _ => self.power(),
        }
    }
    fn power(&mut self) -> PResult {
        let base = self.atom()?;
        if self.peek() == Some(b'^') {
            self.pos += 1;
            self.skip_ws();
            let start = self.pos;
            while self.pos < self.s.len() && self.s[self.pos].is_ascii_digit() {
                self.pos += 1;
            }
            let err = Poly2ParseError::BadExponent {
                pos: start,
                max: MAX_DEGREE,
            };
            let digits = std::str::from_utf8(&self.s[start..self.pos]).map_err(|_| err.clone())?;
            let k: usize = digits.parse().map_err(|_| err.clone())?;
            if k > MAX_DEGREE {
                return Err(err);
            }
            let base = base.trimmed();
            if base.deg_x * k > MAX_DEGREE || base.deg_y * k > MAX_DEGREE {
                return Err(Poly2ParseError::DegreeTooHigh {
                    var: if base.deg_x * k > MAX_DEGREE {
                        "x"
                    } else {
                        "y"
                    },
                    max: MAX_DEGREE,
                });
            }
            return Ok(base.pow(k as u32));
        }
        Ok(base)
    }
    fn atom(&mut self) -> PResult {
        match self.peek() {
            None => Err(Poly2ParseError::UnexpectedEnd),
            Some(b'x' | b'X') => {
                self.pos += 1;
                Ok(Poly2::x())
            }
            Some(b'y' | b'Y') => {
                self.pos += 1;
                Ok(Poly2::y())
            }
            Some(b'(') => {
                self.pos += 1;
                self.enter()?;
                let e = self.expr()?;
                self.depth -= 1;
                if self.peek() != Some(b')') {
                    return Err(self.unexpected());
                }
                self.pos += 1;
                Ok(e)
            }
            Some(c) if c.is_ascii_digit() || c == b'.' => {
                let start = self.pos;
                while self.pos < self.s.len()
                    && (self.s[self.pos].is_ascii_digit() || self.s[self.pos] == b'.')
                {
                    self.pos += 1;
                }
                let lit = std::str::from_utf8(&self.s[start..self.pos]).unwrap_or("");
                let r = parse_rational(lit).map_err(|e| Poly2ParseError::BadNumber {
                    pos: start,
                    reason: e.reason.to_string(),
                })?;
                Ok(Poly2::constant(r))
            }
            Some(_) => Err(self.unexpected()),
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::test_util::qi as q;

    #[test]
    fn parses_and_evaluates_exactly() {
        let p = parse_poly2("x^2 + 4*y^2 - 4").unwrap();
        assert_eq!((p.deg_x(), p.deg_y()), (2, 2));
        assert_eq!(p.eval(&q(2, 1), &q(0, 1)), q(0, 1));
        assert_eq!(p.eval(&q(8, 5), &q(3, 5)), q(0, 1));
        assert_eq!(p.total_degree(), Some(2));
        let s = parse_poly2("y*(x - 1.995)*(y - x^2)*(y - x + 1)").unwrap();
        assert_eq!(s.total_degree(), Some(5));
        assert_eq!(s.eval(&q(3, 1), &q(9, 1)), q(0, 1));
        assert_ne!(s.eval(&q(3, 1), &q(8, 1)), q(0, 1));
        // -(2) and 1/3*x
        let t = parse_poly2("-(2) + 1/3*x - -y").unwrap();
        assert_eq!(t.eval(&q(3, 1), &q(5, 1)), q(4, 1));
    }

    #[test]
    fn derivatives_match_finite_differences_exactly() {
        let p = parse_poly2("x^3*y^2 - 2*x*y + y^3 - 7").unwrap();
        // d/dx = 3x^2y^2 - 2y, d/dy = 2x^3 y - 2x + 3y^2
        let (x, y) = (q(2, 3), q(-5, 7));
        let dx = q(3, 1) * &x * &x * &y * &y - q(2, 1) * &y;
        let dy = q(2, 1) * &x * &x * &x * &y - q(2, 1) * &x + q(3, 1) * &y * &y;
        assert_eq!(p.dx().eval(&x, &y), dx);
        assert_eq!(p.dy().eval(&x, &y), dy);
    }

    #[test]
    fn rejects_bad_input_with_typed_errors() {
        use Poly2ParseError::*;
        assert!(matches!(parse_poly2(""), Err(UnexpectedEnd)));
        assert!(matches!(parse_poly2("x +"), Err(UnexpectedEnd)));
        assert!(matches!(
            parse_poly2("x $ y"),
            Err(Unexpected { pos: 2, .. })
        ));
        assert!(matches!(parse_poly2("x/(y+1)"), Err(BadDivision { .. })));
        assert!(matches!(parse_poly2("x/(1-1)"), Err(BadDivision { .. })));
        assert!(matches!(parse_poly2("x^33"), Err(BadExponent { .. })));
        assert!(matches!(parse_poly2("x^"), Err(BadExponent { .. })));
        assert!(matches!(
            parse_poly2("(x^16)^3"),
            Err(DegreeTooHigh { var: "x", .. })
        ));
        assert!(matches!(
            parse_poly2("y^20*y^20"),
            Err(DegreeTooHigh { var: "y", .. })
        ));
        assert!(matches!(parse_poly2("1..2"), Err(BadNumber { .. })));
        assert!(matches!(parse_poly2("(x"), Err(UnexpectedEnd)));
        let deep = "(".repeat(100) + "x" + &")".repeat(100);
        assert!(matches!(parse_poly2(&deep), Err(TooDeep { .. })));
        let minus = "-".repeat(100) + "x";
        assert!(matches!(parse_poly2(&minus), Err(TooDeep { .. })));
        assert!(matches!(
            parse_poly2(&"x+".repeat(6000)),
            Err(TooLong { .. })
        ));
    }

    #[test]
    fn coeffs_f64_layout() {
        let p = parse_poly2("3*x^2*y + 2*y - x").unwrap();
        let (dx, dy, c) = p.coeffs_f64();
        assert_eq!((dx, dy), (2, 1));
        // index i*(dy+1)+j
        assert_eq!(c, vec![0.0, 2.0, -1.0, 0.0, 0.0, 3.0]);
    }
}
