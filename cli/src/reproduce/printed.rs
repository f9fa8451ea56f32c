//! Reading the papers' printed values: small closed-form expressions such as
//! `(4-2*sqrt(2))/3 ~ .179`, `5*sqrt(2)/6 = sqrt(lambda_l*lambda_r)` or
//! `2(3t+1)/3 * <6t-3, t+3>`, evaluated *exactly* in a quadratic field
//! ([`Surd`]) as polynomials in `t` or vectors of them.
//!
//! Grammar: sums, products (`*` or juxtaposition), division by constants,
//! parentheses, unary minus, decimals, `t`, `sqrt(...)`/`sqrtN`, vectors `<a, b>`.
//! Alternatives separated by `=` or `~` are split by [`PrintedValue::parse`]:
//! symbolic parts are kept exact, plain decimals keep their printed precision,
//! and parts naming other quantities (`sqrt(lambda_l*lambda_r)`) are kept as text.

use lncert::poly::Poly;
use lncert::scalar::{parse_rational, Scalar, ScalarSqrt, Surd};

/// A printed expression's value: a polynomial in `t` or a vector of two.
#[derive(Clone, Debug, PartialEq)]
pub enum Val {
    /// A scalar: one polynomial in `t`.
    Scalar(Poly<Surd>),
    /// A vector `<a, b>`: its two coordinates as polynomials in `t`.
    Vector(Poly<Surd>, Poly<Surd>),
}

/// One printed value split into its parts.
#[derive(Clone, Debug, Default)]
pub struct PrintedValue {
    /// The text as printed.
    pub text: String,
    /// Parts that parsed as closed forms.
    pub exact: Vec<(String, Val)>,
    /// Plain decimal approximations (`~ .179`), with their printed digits.
    pub decimals: Vec<String>,
    /// Parts that name other quantities and are not evaluated.
    pub other: Vec<String>,
}

impl PrintedValue {
    /// Splits at `=` and `~` and parses each part.
    pub fn parse(text: &str) -> PrintedValue {
        let mut out = PrintedValue {
            text: text.to_string(),
            ..Default::default()
        };
        for part in text
            .split(['=', '~'])
            .map(str::trim)
            .filter(|p| !p.is_empty())
        {
            let is_decimal = part
                .chars()
                .all(|c| c.is_ascii_digit() || c == '.' || c == '-')
                && part.contains('.');
            if is_decimal {
                out.decimals.push(part.to_string());
            } else if let Ok(v) = parse_expr(part) {
                out.exact.push((part.to_string(), v));
            } else {
                out.other.push(part.to_string());
            }
        }
        out
    }
    /// The first exact part as a constant, if any.
    pub fn constant(&self) -> Option<Surd> {
        self.exact.iter().find_map(|(_, v)| match v {
            Val::Scalar(p) => constant_of(p),
            _ => None,
        })
    }
}

/// The constant value of a polynomial of degree 0.
pub fn constant_of(p: &Poly<Surd>) -> Option<Surd> {
    let c = p.coeffs();
    if c.iter().skip(1).all(|a| {
        a.as_rational()
            .is_some_and(|r| r == num_traits::Zero::zero())
    }) {
        Some(c.first().cloned().unwrap_or_else(Surd::zero))
    } else {
        None
    }
}

/// Parses one expression (no `=` or `~`).
///
/// # Examples
/// ```
/// use lncert_cli::reproduce::printed::{parse_expr, Val, constant_of};
/// let Val::Scalar(p) = parse_expr("(1+sqrt(3))/6").unwrap() else { panic!() };
/// assert_eq!(constant_of(&p).unwrap().to_string(), "1/6 + 1/6*sqrt(3)");
/// assert!(matches!(parse_expr("2(3t+1)/3 * <6t-3, t+3>").unwrap(), Val::Vector(..)));
/// assert!(parse_expr("lambda_l").is_err());
/// ```
pub fn parse_expr(text: &str) -> Result<Val, String> {
    let toks = tokenize(text)?;
    let mut p = Parser { toks, pos: 0 };
    let v = p.expr()?;
    if p.pos != p.toks.len() {
        return Err(format!("unexpected {:?} in {text:?}", p.toks[p.pos]));
    }
    Ok(v)
}

#[derive(Clone, Debug, PartialEq)]
enum Tok {
    Num(String),
    T,
    Sqrt,
    Op(char),
}

fn tokenize(s: &str) -> Result<Vec<Tok>, String> {
    let cs: Vec<char> = s.chars().collect();
    let mut out = Vec::new();
    let mut i = 0;
    while i < cs.len() {
        let c = cs[i];
        if c.is_whitespace() {
            i += 1;
        } else if c.is_ascii_digit() || c == '.' {
            let st = i;
            while i < cs.len() && (cs[i].is_ascii_digit() || cs[i] == '.') {
                i += 1;
            }
            out.push(Tok::Num(cs[st..i].iter().collect()));
        } else if c == 't'
            && !cs
                .get(i + 1)
                .is_some_and(|c| c.is_alphanumeric() || *c == '_')
        {
            out.push(Tok::T);
            i += 1;
        } else if s[s.char_indices().nth(i).map_or(0, |x| x.0)..].starts_with("sqrt") {
            out.push(Tok::Sqrt);
            i += 4;
        } else if "+-*/()<>,".contains(c) {
            out.push(Tok::Op(c));
            i += 1;
        } else {
            return Err(format!("unknown symbol {c:?}"));
        }
    }
    Ok(out)
}

struct Parser {
    toks: Vec<Tok>,
    pos: usize,
}

fn mul(a: Val, b: Val) -> Result<Val, String> {
    match (a, b) {
        (Val::Scalar(p), Val::Scalar(q)) => Ok(Val::Scalar(p.mul(&q))),
        (Val::Scalar(p), Val::Vector(x, y)) | (Val::Vector(x, y), Val::Scalar(p)) => {
            Ok(Val::Vector(p.mul(&x), p.mul(&y)))
        }
        _ => Err("product of two vectors".into()),
    }
}

fn add(a: Val, b: Val, sign: i64) -> Result<Val, String> {
    let k = Poly::constant(Surd::from_i64(sign));
    match (a, b) {
        (Val::Scalar(p), Val::Scalar(q)) => Ok(Val::Scalar(p.add(&q.mul(&k)))),
        (Val::Vector(a, b), Val::Vector(c, d)) => {
            Ok(Val::Vector(a.add(&c.mul(&k)), b.add(&d.mul(&k))))
        }
        _ => Err("sum of a scalar and a vector".into()),
    }
}

impl Parser {
    fn peek(&self) -> Option<&Tok> {
        self.toks.get(self.pos)
    }
    fn eat(&mut self, c: char) -> bool {
        if self.peek() == Some(&Tok::Op(c)) {
            self.pos += 1;
            true
        } else {
            false
        }
    }
    fn expr(&mut self) -> Result<Val, String> {
        let mut v = self.term()?;
        loop {
            if self.eat('+') {
                v = add(v, self.term()?, 1)?;
            } else if self.eat('-') {
                v = add(v, self.term()?, -1)?;
            } else {
                return Ok(v);
            }
        }
    }
    fn term(&mut self) -> Result<Val, String> {
        let mut v = self.unary()?;
        loop {
            if self.eat('*') {
                v = mul(v, self.unary()?)?;
            } else if self.eat('/') {
                let d = self.unary()?;
                let Val::Scalar(d) = d else {
                    return Err("division by a vector".into());
                };
                let c = constant_of(&d).ok_or("division by a non-constant")?;
                let r = c.recip().ok_or("division by zero")?;
                v = mul(v, Val::Scalar(Poly::constant(r)))?;
            } else if matches!(
                self.peek(),
                Some(Tok::Num(_) | Tok::T | Tok::Sqrt | Tok::Op('(') | Tok::Op('<'))
            ) {
                v = mul(v, self.unary()?)?;
            } else {
                return Ok(v);
            }
        }
    }
    fn unary(&mut self) -> Result<Val, String> {
        if self.eat('-') {
            return add(Val::Scalar(Poly::zero()), self.unary()?, -1);
        }
        if self.eat('+') {
            return self.unary();
        }
        self.atom()
    }
    fn atom(&mut self) -> Result<Val, String> {
        let tok = self.peek().cloned().ok_or("unexpected end")?;
        self.pos += 1;
        match tok {
            Tok::Num(n) => {
                let r = parse_rational(&n).map_err(|e| e.to_string())?;
                Ok(Val::Scalar(Poly::constant(Surd::rational(r))))
            }
            Tok::T => Ok(Val::Scalar(Poly::t())),
            Tok::Sqrt => {
                let arg = if self.eat('(') {
                    let a = self.expr()?;
                    if !self.eat(')') {
                        return Err("missing ')'".into());
                    }
                    a
                } else {
                    self.atom()?
                };
                let Val::Scalar(p) = arg else {
                    return Err("sqrt of a vector".into());
                };
                let c = constant_of(&p).ok_or("sqrt of a non-constant")?;
                Ok(Val::Scalar(Poly::constant(
                    c.sqrt().ok_or("sqrt outside one quadratic field")?,
                )))
            }
            Tok::Op('(') => {
                let v = self.expr()?;
                if !self.eat(')') {
                    return Err("missing ')'".into());
                }
                Ok(v)
            }
            Tok::Op('<') => {
                let a = self.expr()?;
                if !self.eat(',') {
                    return Err("missing ',' in vector".into());
                }
                let b = self.expr()?;
                if !self.eat('>') {
                    return Err("missing '>'".into());
                }
                match (a, b) {
                    (Val::Scalar(x), Val::Scalar(y)) => Ok(Val::Vector(x, y)),
                    _ => Err("nested vectors".into()),
                }
            }
            t => Err(format!("unexpected {t:?}")),
        }
    }
}
