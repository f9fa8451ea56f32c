//! Planar vectors and Bézier curves of any degree, generic over the scalar, and
//! exact B-spline curves split into their Bézier pieces. Reading curves from
//! JSON, SVG and fonts is the [`crate::shape`] layer's job.

mod bezier;
mod bspline;
mod error;
mod vec2;

pub use bezier::{bernstein_halves, bernstein_product, Bezier};
pub use bspline::BSpline;
pub(crate) use error::field_err;
pub use error::CurveParseError;
pub use vec2::V2;
