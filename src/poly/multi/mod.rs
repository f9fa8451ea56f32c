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

mod mpoly;
mod ratfunc;
#[cfg(test)]
mod tests;

pub use mpoly::MPoly;
pub use ratfunc::{identity_holds, poly_in, univariate_coeffs, RatFunc};
