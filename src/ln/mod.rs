//! The papers' propositions as scalar-generic kernels.
//!
//! | module | seed | content |
//! |---|---|---|
//! | [`cubic`] | 000 §3–4 | cubic LN Béziers from `(b0, bm, b3, δ0, δ1)`, eq. (1), Prop 3.1, eq. (5), Lemma 4.1 |
//! | [`pair`] | 000 §4 | compatible pairs, Prop 4.2, Remark 4.3, choice of κ, convolution, Prop 4.4 |
//! | [`circle`] | 000 §6 | cubic LN approximation of a circular arc, Prop 6.1 (A, B, C, s1, s2) |
//! | [`hermite`] | 003 §2–3, 6–7 | normal form `K(t) = [-f', -f + t f']`, Props 2.1, 3.1–3.3, 6.1, 7.1 |
//! | [`direct`] | — | independent decisions by exact root isolation (the tests' ground truth) |
//!
//! Every kernel is generic over [`crate::scalar::Scalar`]: with `Rational` it is
//! exact, with `Interval` it is certified (and may answer "undecided"), with
//! `f64` it is the fast path.

pub mod circle;
pub mod cubic;
pub mod direct;
pub mod hermite;
pub mod pair;

use crate::scalar::Sign;

/// Why a kernel could not produce its result. Every variant names the field.
#[derive(Clone, Debug, PartialEq, Eq, thiserror::Error)]
pub enum LnError {
    /// The three points of an LN frame are collinear (or two coincide).
    #[error("{field}: points b0, bm, b3 are collinear or coincide (cross product is 0)")]
    Collinear {
        /// The points named, e.g. `b0,bm,b3`.
        field: &'static str,
    },
    /// A parameter is outside the domain of a formula.
    #[error("{field}: {reason}")]
    InvalidParameter {
        /// The parameter that is out of the domain.
        field: &'static str,
        /// Why it is out of the domain.
        reason: &'static str,
    },
    /// Two frames are not compatible (their end normals differ).
    #[error("{field}: curves are not compatible: {reason}")]
    NotCompatible {
        /// The input that breaks compatibility.
        field: &'static str,
        /// Which condition fails.
        reason: &'static str,
    },
    /// Interval arithmetic cannot decide a sign the result depends on.
    #[error("{field}: undecided in interval arithmetic (enclosure straddles a boundary)")]
    Undecided {
        /// The quantity whose sign could not be decided.
        field: &'static str,
    },
}

/// Fails with `InvalidParameter` if the sign is zero, `Undecided` if unknown.
pub(crate) fn nonzero(s: Sign, field: &'static str, reason: &'static str) -> Result<(), LnError> {
    match s {
        Sign::Zero => Err(LnError::InvalidParameter { field, reason }),
        Sign::Unknown => Err(LnError::Undecided { field }),
        _ => Ok(()),
    }
}

/// Fails with `InvalidParameter` naming `field` if a value is not a finite number.
pub(crate) fn finite<S: crate::scalar::Scalar>(
    values: &[&S],
    field: &'static str,
) -> Result<(), LnError> {
    if values.iter().all(|v| v.is_finite()) {
        Ok(())
    } else {
        Err(LnError::InvalidParameter {
            field,
            reason: "not a finite number (NaN or infinite)",
        })
    }
}

/// `num / den`, or `InvalidParameter` if `den` is zero, `Undecided` if it may
/// be zero. Symbolic scalars divide whenever `den` is not the zero function.
pub(crate) fn checked_div<S: crate::scalar::Scalar>(
    num: S,
    den: &S,
    field: &'static str,
    reason: &'static str,
) -> Result<S, LnError> {
    num.div(den).ok_or(match den.sign() {
        Sign::Unknown => LnError::Undecided { field },
        _ => LnError::InvalidParameter { field, reason },
    })
}

/// An open interval `(lo, hi)` of a parameter; empty when `lo >= hi`.
#[derive(Clone, Debug, PartialEq)]
pub struct OpenRange<S> {
    /// Lower end (excluded).
    pub lo: S,
    /// Upper end (excluded).
    pub hi: S,
}

impl<S: crate::scalar::Scalar> OpenRange<S> {
    /// `Some(true)` iff `lo < x < hi`; `None` if undecided.
    pub fn contains(&self, x: &S) -> Option<bool> {
        let a = x.cmp_sign(&self.lo).is_positive()?;
        let b = self.hi.cmp_sign(x).is_positive()?;
        Some(a && b)
    }
    /// `Some(true)` iff the range is empty (`lo >= hi`).
    pub fn is_empty(&self) -> Option<bool> {
        self.hi.cmp_sign(&self.lo).is_positive().map(|p| !p)
    }
}
