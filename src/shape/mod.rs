//! The geometry model: what lncert reads, certifies and writes.
//!
//! This layer sits between the mathematics of [`crate::curve`] (Bézier and
//! B-spline curves, generic over the scalar) and the engines that use shapes
//! ([`crate::certify`], [`crate::offset`](mod@crate::offset)); every dependency points down:
//!
//! ```text
//!   cli, reproduce
//!        │
//!   certify, approx, tangency
//!        │
//!      shape          ← exact descriptions, readers, limits
//!        │
//!   curve, ln, poly, scalar
//! ```
//!
//! | what | where |
//! |---|---|
//! | exact shapes: curve, arc, elliptic arc, offset, convolution ([`ShapeDesc`], [`ArcDesc`], [`EllipseArcDesc`]); their checks and canonical JSON | `desc` |
//! | arcs as travelled ([`TravelledArc`]) and the `{"arc"}` / `{"circle"}` documents of `offset` | `arc` |
//! | curves from JSON (`bezier`, `beziers`, `bspline`) and SVG path data, every number exact ([`parse_curve`]) | `io` |
//! | whole SVG documents ([`parse_svg_document`]) | `svgdoc` |
//! | SVG elliptical arcs, circles, ellipses, rounded rects as cubic pieces with a certified Hausdorff bound, and the report of what was approximated ([`InputApprox`]) | [`svgarc`] |
//! | font glyphs (`glyph_outline`, feature `font`) | `font` |
//!
//! Every reader and constructor reports a [`ShapeError`] (or, for the curve
//! readers, a [`CurveParseError`]) naming the field and the reason, and every
//! limit is one of the constants below, shared by all subcommands.
//!
//! The shape readers ([`ShapeDesc::parse_reported`]) read `<circle>`,
//! `<ellipse>`, rounded `<rect>`s and SVG arcs whose centre is rational as
//! exact `{"arc"}` and `{"ellipse_arc"}` members ([`svgarc::ExactElement`]).
//! The curve readers, and the shape readers for the other arcs, read
//! exactly except elliptical arcs (SVG `A`/`a`, `<circle>`,
//! `<ellipse>`, rounded `<rect>`), which are not polynomial curves: they are
//! approximated within a certified bound, and the `*_reported` readers
//! ([`parse_curve_reported`], [`parse_svg_path_reported`],
//! [`parse_svg_document_reported`], [`ShapeDesc::parse_reported`]) say what
//! was approximated and by how much; the plain readers drop that report.
//!
//! # Limits
//!
//! | limit | value |
//! |---|---|
//! | input document (JSON, SVG, certificate) | [`MAX_INPUT_BYTES`] = 128 MiB |
//! | coordinate magnitude | [`MAX_COORDINATE`] = 10¹⁰⁰ (compared exactly) |
//! | control points per Bézier piece | [`MAX_CONTROL_POINTS`] = 64 (degree ≤ 63) |
//! | pieces per curve | [`MAX_SEGMENTS`] = 100 000 |
//! | SVG path data | [`MAX_SVG_BYTES`] = 1 MB |
//! | characters per number literal | [`MAX_NUMBER_CHARS`] = 4 096 |
//! | B-spline conversion work (`points × degree³`) | [`MAX_BSPLINE_WORK`] |
//! | SVG arc radii (also after SVG's out-of-range correction) | ≤ 10¹⁰⁰ |
//! | cubic pieces per SVG arc; proof boxes per piece | 1 024; 4 096 |
//!
//! # Examples
//! ```
//! use lncert::shape::{parse_curve, ShapeDesc};
//! let c = parse_curve("M 0 0 C 1 1 2 1 3 0").unwrap();
//! let o = ShapeDesc::offset(c, "1/4".parse().unwrap()).unwrap();
//! assert_eq!(o.summary(), "offset at 1/4 of 1 piece(s)");
//! let e = ShapeDesc::parse(r#"{"offset": {"curve": "M 0 0 L 1 0", "distance": 0}}"#).unwrap_err();
//! assert_eq!(e.field, "offset.distance");
//! ```

mod arc;
mod desc;
mod dots;
#[cfg(feature = "font")]
mod font;
pub(crate) mod io;
pub mod svgarc;
mod svgdoc;
mod winding;

pub use arc::{parse_arc_input, TravelledArc};
pub(crate) use desc::{check_keys, checked_offset, curve_value, number, parse_json_value, point};
pub use desc::{ArcDesc, EllipseArcDesc, ShapeDesc, MAX_COORDINATE};
pub use dots::{is_point_piece, split_dots};
#[cfg(feature = "font")]
pub use font::{
    font_info, glyph_id_by_char, glyph_id_by_name, glyph_outline, glyph_outline_by_id, regularize,
    units_per_em, FontInfo, GlyphInfo,
};
pub use io::{
    parse_curve, parse_curve_reported, parse_json_curve, parse_svg_path, parse_svg_path_reported,
    CurveParseError, MAX_BSPLINE_WORK, MAX_CONTROL_POINTS, MAX_NUMBER_CHARS, MAX_SEGMENTS,
    MAX_SVG_BYTES,
};
pub use svgarc::{format_up, ApproxElement, ApproxKind, InputApprox, NearElement, ARC_TARGET_REL};
pub use svgdoc::{
    parse_svg_document, parse_svg_document_elements, parse_svg_document_reported, SvgElement,
    MAX_USE_DEPTH, TRANSFORM_TARGET,
};
pub use winding::winding_number;

/// The largest input document any reader of lncert accepts (JSON curves,
/// shapes, certificates, SVG), in bytes: 128 MiB.
pub const MAX_INPUT_BYTES: usize = crate::json::Limits::DEFAULT.max_bytes;

/// Why a shape could not be built or read: the field (e.g. `arc.radius`,
/// `offset.curve[0]`, `convolution.side`) and the reason — lncert's one input
/// error, [`crate::Error`].
pub type ShapeError = crate::Error;
