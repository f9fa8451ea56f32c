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
//! | `G2` | 004 | degree `n + 3` from the approximated normal field ([`kernels::offset_approximant`]) | G², C¹ at the joints |
//! | `LnPair` | 000 §6 | a cubic `pa + ca` from a pair of LN cubics ([`kernels::ln_pair`]) | G¹ |
//!
//! | [`Output`] | segment | continuity |
//! |---|---|---|
//! | `Native` (default) | the construction of the method above | as above |
//! | `Cubic` | a cubic fitted to the exact offset of the span ([`kernels::least_squares_cubic`], [`kernels::g2_hermite_cubics`]) | G¹, shared end points |
//! | `Quadratic` | the tangent-intersection quadratic ([`kernels::tangent_quadratic`]) | G¹, shared end points |
//!
//! With [`OffsetOptions::grid`] every control point is rounded to a dyadic
//! grid and the rounded segment is what is proven.
//!
//! The constructions run in `f64` and are heuristics; only the certification
//! decides. Preprocessing ([`kernels::inflections`], [`kernels::offset_cusps`]) splits the input at inflections and
//! where its Gauss map turns by 0.9π or more, reports the cusps of the exact offset (where
//! the radius of curvature equals `d`; the approximation continues through
//! them) and the G⁰ corners (a join arc, or an overlap to trim).
//!
//! # Examples
//! ```
//! use lncert::offset::{offset, OffsetMethod, OffsetOptions};
//! use lncert::shape::parse_curve;
//! use lncert::scalar::parse_rational;
//! let c = parse_curve("M 0 0 C 1 1 2 1 3 0").unwrap();
//! let opts = OffsetOptions::new(parse_rational("0.25").unwrap(), "1e-3".parse().unwrap());
//! let r = offset(&c, &opts).unwrap();
//! assert!(r.reached());
//! assert!(r.certified_hi <= r.tol.value()); // the largest f64 ≤ 1/1000
//! assert_eq!(r.degree(), 6);
//! assert_eq!(r.control_points(), 6 * r.segments.len() + 1);
//! ```

//! Convolutions with an elliptical pen (seed 001) are [`convolve`] with a
//! [`Pen`]; offsets rounded to a font's grid with a proof of the rounded
//! outline are [`offset_on_grid`]; exact offsets of circular arcs are
//! [`offset_arc`]. The seeds' constructions themselves — each a kernel that a
//! user can run and test on its own — are in [`kernels`].

pub(crate) mod arc;
pub(crate) mod conv;
mod cuspform;
pub(crate) mod fit;
pub(crate) mod g2;
pub(crate) mod gridfit;
pub(crate) mod lnpair;
pub(crate) mod prep;

mod convolve;
mod corners;
mod driver;
mod options;
mod results;
mod union;

pub use arc::{offset_arc, ArcOffset, TravelledArc};
pub use conv::{Angle, ConvCusp, Pen};
pub use convolve::convolve;
pub use corners::corners;
pub use driver::{offset, span_f64};
pub use fit::Output;
pub use gridfit::{
    chain_on_grid, offset_on_grid, ChainGridOptions, GridOffset, GridSegment, Target,
};
pub use options::{OffsetError, OffsetMethod, OffsetOptions, MIN_REL_TOL};
pub use results::{
    absorbed_arcs, exact_bezier, exact_offset_shape, join_arcs, ConvSide, Corner, OffsetResult,
    OffsetSegment, ProofPath, SegmentProof,
};
pub use union::{global_bounds, union_certificate, union_certificate_all};

/// The seeds' constructions, one kernel each, in `f64` or exact arithmetic:
/// seed 004's G² normal-field offset approximant, seed 000 §6's LN pairs,
/// seed 001's convolution approximant and cusps, the fitted cubic and
/// quadratic segments and their grid rounding, and the preprocessing
/// (inflections, offset cusps, junctions). [`offset`] and [`convolve`] run
/// them and prove the result; called directly they prove nothing.
pub mod kernels {
    pub use super::conv::{conv_cusps, convolution_approximant_f64, pen_point, pen_point_at};
    pub use super::fit::{
        check_grid, check_grid_storage, g2_hermite_cubics, least_squares_cubic, round_to_grid,
        rounding_move, tangent_quadratic, FitEnds,
    };
    pub use super::g2::{
        elevate_by, ends, moments, normal_approximant, offset_approximant, offset_approximant_f64,
        rot_cw, solve_alpha, solve_alpha_f64, system, G2Ends, SINGULAR_SYSTEM_REL,
    };
    pub use super::lnpair::{
        angle_param, arc_term, chord_param, k_piece_split, ln_pair, ln_pair_pen, mid_angle_param,
        paper_error, total_turn, weighted_param, LnPairPiece, NoPair, Subdivision,
    };
    pub use super::prep::{
        curvature_numerator, gauss_map_short, inflections, junction, offset_cusps, point_at,
        unit_left_normal, Junction, OffsetCusp, MAX_TURN,
    };
}
