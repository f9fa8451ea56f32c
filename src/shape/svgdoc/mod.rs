//! Whole SVG documents: every rendered `<path>`, `<line>`, `<polyline>`,
//! `<polygon>`, `<rect>`, `<circle>` and `<ellipse>`, with the `transform`s
//! of the element and its ancestors applied, `<use>` instances resolved, and
//! each element's stroke ([`parse_svg_document_elements`]).
//!
//! The XML is read by roxmltree; the path data and every number (coordinates,
//! transform arguments) by lncert's own exact reader, never through `f64`: an
//! affine map of a Bézier curve is the Bézier curve of the mapped control
//! points, so exact transforms round nothing. Transforms: `matrix`,
//! `translate`, `scale`, `rotate` and `skewX`/`skewY`. A rotation by a
//! multiple of 90° is exact; any other angle has an irrational cosine or sine
//! (or is given in degrees that are not), and is replaced by the **exactly
//! rational rotation** of the point `((1 − u²)/(1 + u²), 2u/(1 + u²))` of the
//! unit circle, `u` a continued-fraction convergent of `tan(θ/2)` (after exact
//! quarter turns), with `‖R_θ − R′‖₂ ≤ 10⁻¹²` certified (`sin`/`cos` enclosed
//! from an enclosure of `π`). Skews likewise use a rational `t` with
//! `|tan θ − t| ≤ 10⁻¹² max(1, |t|)` (90° is refused). The element is then
//! mapped exactly by that rational matrix, and the report
//! ([`ApproxKind::Rotation`](super::ApproxKind::Rotation),
//! [`ApproxKind::Skew`](super::ApproxKind::Skew)) says which matrix and the
//! certified displacement `sup |M(p) − M′(p)|` over the element (`err · |p −
//! centre|` summed over the approximated factors, times the Lipschitz bound
//! of the transforms above them; see [`parse_svg_document_elements`]).
//!
//! Elliptical arcs are *approximated* by cubic pieces with a certified
//! Hausdorff bound (see [`super::svgarc`]), reported per element by
//! [`parse_svg_document_reported`]: `A`/`a` in path data; `<circle cx cy r>`
//! and `<ellipse cx cy rx ry>` (a missing or `auto` `rx` or `ry` is the other
//! one, as in SVG 2; a zero radius draws nothing) as two half arcs, starting at
//! `(cx + rx, cy)` and running counter-clockwise in the user coordinate
//! system (from +x towards +y: clockwise on a y-down screen), as SVG 2 draws
//! them; rounded `<rect rx ry>` (one given is both, each clamped to half the
//! side) as SVG 2's path: lines and four quarter arcs, from `(x + rx, y)`.
//! The pieces are mapped through the transforms exactly, and each bound is
//! multiplied by an upper bound of the transform's norm `‖T‖₂` (its largest
//! singular value, enclosed from the exact matrix), plus the displacement of
//! an approximated rotation or skew above the element.
//!
//! Refused with an error naming the element (nothing is dropped silently):
//! `<text>`, `<image>`, `<foreignObject>`, negative radii, and unit
//! suffixes on coordinates. Elements inside `<defs>`, `<clipPath>`, `<mask>`,
//! `<symbol>`, `<marker>` and `<pattern>` are not rendered, and are skipped
//! (a `<use>` draws them); so are `display="none"` subtrees and
//! `visibility="hidden"` elements.
//!
//! # Examples
//! ```
//! use lncert::shape::parse_svg_document;
//! let doc = r#"<svg xmlns="http://www.w3.org/2000/svg">
//!   <g transform="translate(10, 0) scale(2)">
//!     <path d="M 0 0 C 1 1 2 1 3 0"/>
//!   </g>
//!   <line x1="0" y1="0" x2="1" y2="0.1"/>
//! </svg>"#;
//! let pieces = parse_svg_document(doc).unwrap();
//! assert_eq!(pieces.len(), 2);
//! // (3, 0) scaled by 2, then moved by 10: (16, 0), exactly
//! assert_eq!(pieces[0].points()[3].x, lncert::scalar::parse_rational("16").unwrap());
//! // a circle: two half arcs of cubic pieces, certified within 1e-7 of r = 1
//! let (circle, approx) = lncert::shape::parse_svg_document_reported(
//!     r#"<svg><circle r="1"/></svg>"#).unwrap();
//! assert_eq!(circle[0].points()[0].x, lncert::scalar::parse_rational("1").unwrap());
//! assert!(approx.bound() <= 1e-7);
//! assert!(parse_svg_document(r#"<svg><text>1</text></svg>"#).is_err());
//! ```

mod elements;
#[cfg(test)]
mod tests;
mod transform;
mod walk;

use super::io::CurveParseError;
use super::svgarc::InputApprox;
use crate::curve::Bezier;
use crate::scalar::Rational;
pub use walk::{parse_svg_document, parse_svg_document_elements, parse_svg_document_reported};

/// Largest SVG document read, in bytes.
pub const MAX_DOCUMENT_BYTES: usize = 16 << 20;

/// Largest error allowed of the rational rotation or skew that replaces an
/// irrational one: `‖R_θ − R′‖₂` (the chord between the two unit vectors,
/// about the angle error) or `|tan θ − t|` relative to `max(1, |t|)`.
pub const TRANSFORM_TARGET: f64 = 1e-12;

/// Largest nesting of `<use>` instances.
pub const MAX_USE_DEPTH: usize = 16;

fn err(field: impl Into<String>, reason: impl Into<String>) -> CurveParseError {
    CurveParseError::Field {
        field: field.into(),
        reason: reason.into(),
    }
}

/// One drawn element of an SVG document, in the document's user coordinates.
#[derive(Clone, Debug, PartialEq)]
pub struct SvgElement {
    /// Where it is: `svg/g[0]/path[1]`; an instance of `<use>` is
    /// `svg/use[0]/#id` (then the referenced element's own children).
    pub at: String,
    /// Its pieces, mapped exactly by the rational transform; without point
    /// pieces (all control points equal: [`crate::shape::split_dots`]).
    pub pieces: Vec<Bezier<Rational>>,
    /// Its zero-length subpaths (`<line>` with equal ends, `M 5 5 h 0`, …)
    /// in the document's user coordinates: dots, which round caps stroke as
    /// the pen's disk and butt caps do not draw (SVG 2).
    pub dots: Vec<crate::curve::V2<Rational>>,
    /// What was approximated to get them (arcs; irrational rotations and
    /// skews above it), bounds in the document's user coordinates.
    pub approx: InputApprox,
    /// The computed `stroke` is set and not `none` (SVG's initial value is
    /// `none`: an element without a `stroke` anywhere above it is not stroked).
    pub stroked: bool,
    /// The computed `stroke-width` (inherited; default 1), in the element's
    /// own coordinates.
    pub stroke_width: Rational,
    /// Half the stroke width in the document's user coordinates — the radius
    /// of the circular pen that strokes it — or why there is no such circle
    /// (a transform that is not a similarity with a rational scale).
    pub pen_radius: Result<Rational, String>,
}
