//! Offsets of circular arcs: exact (seed 004 §3.1, circular precision).
//!
//! For an arc `x(t) = c + γ (cos(t₀ + l t), sin(t₀ + l t))` seed 004's
//! construction gives `α ≡ 1/γ`, hence `Nᵃ ≡ N` and the approximant *is* the
//! exact offset. lncert proves this identity once for all arcs, symbolically,
//! by running the engine's own [`super::g2::solve_alpha`] on the arc's moments
//! in `Q(γ, 1/l, tan(l/2), tan(t₀/2))` (`tests/offset_identities.rs`,
//! `proofs/004-circular-precision.md`). So the offset of an arc is returned as
//! the exact concentric arc, with error `0`.

use super::options::bad;
use super::OffsetError;
use crate::curve::V2;
use crate::scalar::Rational;
pub use crate::shape::TravelledArc;
use num_traits::{Signed, Zero};

/// The exact offset of an arc.
#[derive(Clone, Debug, PartialEq)]
pub enum ArcOffset {
    /// The concentric arc of radius `|γ ∓ d|` (directions negated when the
    /// offset passes through the centre).
    /// (Boxed: an exact arc is far larger than the collapsed point.)
    Arc(Box<TravelledArc>),
    /// `d` equals the radius on the concave side: the offset collapses to the
    /// centre (every point is a cusp of the offset).
    Collapsed {
        /// The arc's centre: the whole offset is this one point.
        center: V2<Rational>,
    },
}

/// The exact offset at signed distance `d` (`d > 0` to the left of the travel
/// direction) of an arc.
///
/// # Examples
/// ```
/// use lncert::offset::{offset_arc, ArcOffset, TravelledArc};
/// use lncert::shape::ArcDesc;
/// use lncert::curve::V2;
/// use lncert::scalar::{frac, Rational};
/// let q = |p, r| frac::<Rational>(p, r);
/// let quarter = ArcDesc { center: V2::new(q(0, 1), q(0, 1)), radius: q(1, 1),
///                         from: V2::new(q(1, 1), q(0, 1)), to: V2::new(q(0, 1), q(1, 1)) };
/// // counter-clockwise: the left normal points to the centre, radius 1 − 1/2
/// let o = offset_arc(&TravelledArc { arc: quarter, clockwise: false }, &q(1, 2)).unwrap();
/// let ArcOffset::Arc(a) = o else { panic!() };
/// assert_eq!(a.arc.radius, q(1, 2));
/// ```
pub fn offset_arc(a: &TravelledArc, d: &Rational) -> Result<ArcOffset, OffsetError> {
    if d.is_zero() {
        return Err(bad("distance", "must be nonzero"));
    }
    // left normal: inward for counter-clockwise travel, outward for clockwise
    let rho = if a.clockwise {
        &a.arc.radius + d
    } else {
        &a.arc.radius - d
    };
    if rho.is_zero() {
        return Ok(ArcOffset::Collapsed {
            center: a.arc.center.clone(),
        });
    }
    let mut arc = a.arc.clone();
    if rho.is_negative() {
        arc.radius = -rho;
        arc.from = arc.from.neg();
        arc.to = arc.to.neg();
    } else {
        arc.radius = rho;
    }
    Ok(ArcOffset::Arc(Box::new(TravelledArc {
        arc,
        clockwise: a.clockwise,
    })))
}
