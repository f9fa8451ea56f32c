//! Outlines: what turns offset and convolution approximants into the boundary
//! of a swept region: certified intersections of polynomial pieces
//! ([`intersect`]), exact circular arcs and their crossings with Bézier pieces
//! ([`circle`]), and proven stroke outlines for a circular pen ([`trim`]).

pub mod circle;
pub mod ellipse;
pub mod intersect;
pub(crate) mod onside;
pub mod trim;
