//! Planar vectors and Bézier curves of any degree, generic over the scalar.

mod bezier;
mod vec2;

pub use bezier::{bernstein_product, Bezier};
pub use vec2::V2;
