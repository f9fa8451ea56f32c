//! Helpers for the library's unit tests: a deterministic generator
//! (xorshift64: the same cases on every run, no dependency) and the exact
//! rationals `q("1/3")` and `qi(1, 3)`.

use crate::scalar::{frac, parse_rational, Rational};

/// The exact rational written `s` (`"1/3"`, `"-2.5"`, ...); panics on bad text.
pub(crate) fn q(s: &str) -> Rational {
    parse_rational(s).unwrap()
}

/// The exact rational `p/d`.
pub(crate) fn qi(p: i64, d: i64) -> Rational {
    frac(p, d)
}

/// The tolerance equal to the float `x` (`value() == x`); panics when `x` is
/// not a positive normal float.
pub(crate) fn tol(x: f64) -> crate::Tolerance {
    crate::Tolerance::from_f64(x).unwrap()
}

/// Claims (a) of a stroke looked at from outside: every float sample of
/// every outline piece of `s` is within `tol` of `∂S` as far as the dense
/// samples `input` of the input tell (`|dist(p, input) − r| ≤ tol`), by
/// distances to points, not by the engine's predicates.
pub(crate) fn outline_near_boundary(
    s: &crate::stroke::Stroke,
    input: &[(f64, f64)],
    r: f64,
    tol: f64,
    what: &str,
) {
    for piece in s.contours.iter().flat_map(|c| &c.pieces) {
        for (x, y) in piece.sample(40) {
            let dist = input
                .iter()
                .map(|(u, v)| (x - u).hypot(y - v))
                .fold(f64::INFINITY, f64::min);
            assert!(
                (dist - r).abs() <= tol,
                "{what}: ({x}, {y}) is {dist} from the input"
            );
        }
    }
}

/// Xorshift64 state.
pub(crate) struct TestRng(u64);

impl TestRng {
    /// A generator from a nonzero seed.
    pub(crate) fn new(seed: u64) -> Self {
        TestRng(seed.max(1))
    }
    /// A uniform-ish integer in `[-m, m]`.
    pub(crate) fn int(&mut self, m: i64) -> i64 {
        let s = &mut self.0;
        *s ^= *s << 13;
        *s ^= *s >> 7;
        *s ^= *s << 17;
        (*s % (2 * m as u64 + 1)) as i64 - m
    }
}
