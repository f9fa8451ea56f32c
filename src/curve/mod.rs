//! Planar vectors and Bézier curves of any degree, generic over the scalar, and
//! exact B-spline curves split into their Bézier pieces.

mod bezier;
mod bspline;
#[cfg(feature = "font")]
pub mod font;
pub mod svgdoc;
mod vec2;

pub use bezier::{bernstein_product, Bezier};
pub use bspline::BSpline;
pub use vec2::V2;
pub(crate) mod io;
pub use io::{
    parse_curve, parse_json_curve, parse_svg_path, CurveParseError, MAX_BSPLINE_WORK,
    MAX_CONTROL_POINTS, MAX_NUMBER_CHARS, MAX_SEGMENTS, MAX_SVG_BYTES,
};
