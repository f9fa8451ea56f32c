//! Proven stroke outlines: the boundary of the region swept by a pen along a
//! curve, as closed simple contours of exact Bézier pieces and exact arcs, with
//! the three claims proven — (a) every output point is within the tolerance
//! of `∂S`, (b) every point of `∂S` is within the tolerance of the output, (c)
//! the contours are closed and simple — or reported undecided.
//!
//! | task | entry points |
//! |---|---|
//! | stroke a curve with a circular or elliptical pen | [`stroke()`], [`StrokeOptions`], [`PenShape`], [`Cap`], [`Stroke`], [`Claim`], [`Contour`], [`Piece`], [`Orientation`] |
//! | certified crossings of polynomial pieces (complete: every crossing proven, none missed, or undecided) | [`intersections`], [`intersections_skipping`], [`IntersectOptions`], [`Intersections`], [`Crossing`], [`Joint`], [`Undecided`] |
//! | exact circular arcs and their crossings with Bézier pieces | [`Arc`], [`bezier_arc`], [`ArcHit`], [`arcs_meet`], [`ArcMeet`] |
//! | the referee: certified `d_H(X, ∂S)` for any outline `X` (kurbo's, Skia's, yours) and the exact stroke boundary | [`referee`], [`distance_to_stroke`], [`StrokeShape`], [`StrokeDistance`], [`StrokeVerdict`] |
//! | the elliptical pen's quadratic form and its round caps | [`Form`], [`outside_of`], [`half_ellipse_cap`], [`EllipseCap`] |
//!
//! The construction (offsets or convolutions at `∓r` within `tol/8`, exact
//! closure, split at certified crossings, one decision per sub-piece, pinched
//! loops and spurs dropped by a certified reach, chaining, the simplicity
//! check) and every soundness argument are in `proofs/trimming.md`.
//!
//! # Examples
//! ```
//! use lncert::stroke::{stroke, StrokeOptions};
//! use lncert::{parse_curve, parse_rational};
//! # fn main() -> Result<(), lncert::Error> {
//! let curve = parse_curve("M 0 0 L 4 0")?;
//! let s = stroke(&curve, &StrokeOptions::new(parse_rational("1")?, "1e-2".parse()?))?;
//! assert!(s.proven()); // claims (a), (b) and (c)
//! assert_eq!(s.contours.len(), 1); // one closed contour: two sides, two round caps
//! # Ok(())
//! # }
//! ```

mod cert;
pub(crate) mod circle;
pub(crate) mod ellipse;
pub(crate) mod intersect;
mod lines_arcs;
pub(crate) mod onside;
pub(crate) mod path;
mod referee;
pub(crate) mod trim;

pub use cert::{certificate, certificate_path, certificate_set, distance_certificate};
pub use circle::{arcs_meet, bezier_arc, Arc, ArcHit, ArcMeet};
pub use ellipse::{half_ellipse_cap, outside_of, EllipseCap, Form};
pub use intersect::{
    intersections, intersections_skipping, Crossing, IntersectOptions, Intersections, Joint,
    Undecided,
};
pub use path::{exact_path, parse_path, stroke_path, PathPiece};
pub use referee::{
    distance_through, distance_to_stroke, distance_to_stroke_path, referee, StrokeDistance,
    StrokeShape, StrokeVerdict,
};
pub use trim::{
    stroke, Cap, CapReport, Claim, Classified, Contour, Orientation, PenShape, Piece, RawCrossing,
    Stroke, StrokeError, StrokeOptions,
};
