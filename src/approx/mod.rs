//! Offset approximation with a proven tolerance.
//!
//! [`offset`] approximates the offset `x + d N` (`N` the unit **left** normal,
//! `d > 0` to the left) of a piecewise polynomial curve by a polynomial spline
//! and proves the result: every output segment carries a certified Hausdorff
//! bound against the exact offset of its input span ([`crate::certify`]), and
//! the divide-and-conquer loop only accepts a segment whose certified bound is
//! `≤ tol`. Since `d_H(∪Aᵢ, ∪Bᵢ) ≤ maxᵢ d_H(Aᵢ, Bᵢ)`, the spline is within `tol`
//! of the whole offset; [`union_certificate`] writes that as a certificate
//! (the per-segment maps and covers, no further search) that `lncert verify` re-checks,
//! and [`global_bounds`] (opt-in) encloses the global distance from both sides.
//!
//! Two constructions, both from the seeds:
//!
//! | [`OffsetMethod`] | seed | segment | continuity |
//! |---|---|---|---|
//! | `G2` | 004 | degree `n + 3` from the approximated normal field ([`g2`]) | G², C¹ at the joints |
//! | `LnPair` | 000 §6 | a cubic `pa + ca` from a pair of LN cubics ([`lnpair`]) | G¹ |
//!
//! | [`Output`] | segment | continuity |
//! |---|---|---|
//! | `Native` (default) | the construction of the method above | as above |
//! | `Cubic` | a cubic fitted to the exact offset of the span ([`fit`]) | G¹, shared end points |
//! | `Quadratic` | the tangent-intersection quadratic ([`fit`]) | G¹, shared end points |
//!
//! With [`OffsetOptions::grid`] every control point is rounded to a dyadic
//! grid and the rounded segment is what is proven.
//!
//! The constructions run in `f64` and are heuristics; only the certification
//! decides. Preprocessing ([`prep`]) splits the input at inflections and
//! where its Gauss map turns by 0.9π or more, reports the cusps of the exact offset (where
//! the radius of curvature equals `d`; the approximation continues through
//! them) and the G⁰ corners (a join arc, or an overlap to trim).
//!
//! # Examples
//! ```
//! use lncert::approx::{offset, OffsetMethod, OffsetOptions};
//! use lncert::shape::parse_curve;
//! use lncert::scalar::parse_rational;
//! let c = parse_curve("M 0 0 C 1 1 2 1 3 0").unwrap();
//! let opts = OffsetOptions::new(parse_rational("0.25").unwrap(), 1e-3);
//! let r = offset(&c, &opts).unwrap();
//! assert!(r.reached());
//! assert!(r.certified_hi <= 1e-3);
//! assert_eq!(r.degree(), 6);
//! assert_eq!(r.control_points(), 6 * r.segments.len() + 1);
//! ```

pub mod arc;
pub mod conv;
pub mod fit;
pub mod g2;
pub mod gridfit;
pub mod lnpair;
pub mod prep;

mod convolve;
mod corners;
mod driver;
mod options;
mod results;
mod union;

pub use convolve::convolve;
pub use corners::corners;
pub use driver::{offset, span_f64};
pub use fit::Output;
pub use options::{OffsetError, OffsetMethod, OffsetOptions, MIN_REL_TOL};
pub use results::{
    absorbed_arcs, exact_bezier, exact_offset_shape, join_arcs, ConvSide, Corner, OffsetResult,
    OffsetSegment, ProofPath, SegmentProof,
};
pub use union::{global_bounds, union_certificate, union_certificate_all};
