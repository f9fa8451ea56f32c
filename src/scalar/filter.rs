//! Filtered decisions (the idea of CGAL's filtered kernels): evaluate a predicate
//! with floats carrying an a-priori error bound first ([`FloatErr`]: plain float
//! operations, no rounding-mode switches), then exactly in machine integers
//! ([`SmallRat`]: decides exact ties of small inputs, gives up on overflow), then
//! with interval arithmetic, and only when none can decide, exactly with big
//! rationals. Exact answers at close to float speed.

use super::{FloatErr, Interval, Rational, Scalar, SmallRat};
use std::sync::atomic::{AtomicU64, Ordering};

/// A decision that can be evaluated in any arithmetic.
///
/// `decide` returns `None` only when the arithmetic cannot decide (an interval
/// straddling a boundary). With exact scalars ([`Rational`]) it must always
/// return `Some`, because exact signs are never `Unknown`.
pub trait Predicate {
    /// The answer (often a `bool` or an enum, possibly a `Result` for invalid input).
    type Out;
    /// Evaluate the predicate with scalar type `S`.
    fn decide<S: Scalar>(&self) -> Option<Self::Out>;
    /// A first stage specialised to the predicate (e.g. plain floats against one
    /// error bound derived for its expressions), tried by [`filtered`] before the
    /// generic stages. `None` when it cannot decide; the default has no such stage.
    fn decide_static(&self) -> Option<Self::Out> {
        None
    }
}

/// Alias kept for readability at call sites: `Some` = decided, `None` = unknown.
pub type Decision<T> = Option<T>;

static CALLS: AtomicU64 = AtomicU64::new(0);
static FALLBACKS: AtomicU64 = AtomicU64::new(0);

/// How often the interval filter had to fall back to exact arithmetic.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct FilterStats {
    /// Filtered decisions evaluated.
    pub calls: u64,
    /// Of those, decided only by the exact fallback.
    pub fallbacks: u64,
}

impl FilterStats {
    /// `fallbacks / calls` (0 when nothing ran).
    pub fn rate(&self) -> f64 {
        if self.calls == 0 {
            0.0
        } else {
            self.fallbacks as f64 / self.calls as f64
        }
    }
}

/// Process-wide counters of [`filtered`] (relaxed atomics; thread-safe).
pub fn filter_stats() -> FilterStats {
    FilterStats {
        calls: CALLS.load(Ordering::Relaxed),
        fallbacks: FALLBACKS.load(Ordering::Relaxed),
    }
}

/// Resets the counters of [`filter_stats`].
pub fn reset_filter_stats() {
    CALLS.store(0, Ordering::Relaxed);
    FALLBACKS.store(0, Ordering::Relaxed);
}

/// Decides `p` exactly: the predicate's own static stage
/// ([`Predicate::decide_static`]) first, then floats with an error bound, then small exact
/// rationals (`i128`, given up on overflow), then intervals, then big rationals
/// when none can decide.
///
/// Returns `None` only if the exact evaluation itself declines, which a correct
/// predicate never does.
///
/// # Examples
/// ```
/// use lncert::scalar::{filtered, Predicate, Scalar, Sign, parse_rational, Rational};
/// /// Is 1/3 + 1/3 + 1/3 - 1 positive? Intervals cannot tell (it is 0); rationals can.
/// struct ThirdsSum;
/// impl Predicate for ThirdsSum {
///     type Out = Sign;
///     fn decide<S: Scalar>(&self) -> Option<Sign> {
///         let t = S::from_rational(&parse_rational("1/3").unwrap());
///         let s = (t.clone() + t.clone() + t - S::one()).sign();
///         (s != Sign::Unknown).then_some(s)
///     }
/// }
/// assert_eq!(filtered(&ThirdsSum), Some(Sign::Zero));
/// ```
pub fn filtered<P: Predicate>(p: &P) -> Option<P::Out> {
    CALLS.fetch_add(1, Ordering::Relaxed);
    if let Some(out) = p.decide_static() {
        return Some(out);
    }
    if let Some(out) = p.decide::<FloatErr>() {
        return Some(out);
    }
    if let Some(out) = p.decide::<SmallRat>() {
        return Some(out);
    }
    if let Some(out) = p.decide::<Interval>() {
        return Some(out);
    }
    FALLBACKS.fetch_add(1, Ordering::Relaxed);
    p.decide::<Rational>()
}
