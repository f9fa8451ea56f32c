//! Exact curve input: Bézier curves from JSON or SVG path data, with every
//! number read *exactly* as a rational (`0.95` is `19/20`, `1/3` is `1/3`),
//! never through `f64`.
//!
//! # JSON
//!
//! One Bézier curve of any degree ≥ 1 (2 to 64 control points):
//!
//! ```json
//! {"bezier": [["-0.95", "0.7"], [-0.3, 0.5], ["3/10", "-2.5"], [0.9, -0.2]]}
//! ```
//!
//! or a piecewise curve, a list of such control-point lists (at most 100 000):
//!
//! ```json
//! {"beziers": [[[0, 0], [1, 1]], [[1, 1], [2, 0], [3, 1]]]}
//! ```
//!
//! or a B-spline curve of degree 1 to 63 (at most 100 000 control points),
//! read as its polynomial pieces (one Bézier curve of the spline's degree per
//! non-empty knot span, computed exactly; see [`crate::curve::BSpline`]):
//!
//! ```json
//! {"bspline": {"degree": 3, "knots": "clamped", "control_points": [[0, 0], [1, 2], [3, 2], [4, 0]]}}
//! ```
//!
//! `"knots"` is `"clamped"` (open uniform: `degree + 1` zeros, `1, 2, ...`,
//! `degree + 1` equal end knots; the curve runs from the first control point
//! to the last), `"periodic"` (closed uniform: the first `degree` control
//! points are wrapped around, one piece per given control point) or an
//! explicit non-decreasing list of `control points + degree + 1` numbers.
//! No other key is accepted inside `"bspline"`.
//!
//! Each coordinate (and each knot, and the degree) is a JSON number or a JSON
//! string holding a decimal (`"-1.5e-3"`) or fraction (`"-7/6"`) literal. JSON
//! numbers are read from their digits as written (`0.1` is exactly `1/10`).
//! Exactly one of `"bezier"`, `"beziers"` and `"bspline"` is given, and no
//! other top-level field is accepted, so a misspelt key is reported instead of
//! ignored.
//!
//! # SVG path data
//!
//! ```text
//! M 0 0 C 1 2 3 4 5 6 S 7 8 9 10 L 0 0 Z
//! ```
//!
//! The commands `M m L l H h V v C c S s Q q T t A a Z z` are understood, with
//! the implicit repetition of parameters of the SVG specification (`M`
//! followed by further pairs draws lines). Every drawing segment becomes one
//! Bézier curve: lines of degree 1, quadratics of degree 2, cubics of degree
//! 3; `Z` adds a closing line when the current point is not the subpath's
//! start.
//!
//! Elliptical arcs (`A a`, SVG 1.1 F.6.5–F.6.6: flags `0`/`1`, radii made
//! absolute and scaled up when too small, identical end points omit the arc,
//! a zero radius draws a line) are not polynomial curves: each is
//! *approximated* by cubic pieces whose Hausdorff distance from the exact arc
//! is certified (target `1e-7 · max(rx, ry)`, see [`super::svgarc`]). The
//! pieces start and end exactly at the arc's end points as read.
//! [`parse_svg_path_reported`] and [`parse_curve_reported`] return the list
//! of approximated commands with their bounds ([`InputApprox`]);
//! [`parse_svg_path`] and [`parse_curve`] drop it.
//!
//! # Errors and limits
//!
//! Every error names *where* (a JSON field path such as `bezier[2][1]` or
//! `bspline.knots[3]`, or a byte offset in the path data) and *why*; see
//! [`CurveParseError`]. The parsers never panic and do bounded work: at most 64
//! control points per segment, 100 000 segments, 100 000 B-spline control
//! points of degree at most 63, 1 000 000 bytes of SVG path data, 4 096
//! characters per number literal (whose decimal exponent `parse_rational`
//! bounds further).

mod json;
mod svg_path;
#[cfg(test)]
mod tests;

use super::svgarc::InputApprox;
pub(crate) use crate::curve::field_err;
use crate::curve::Bezier;
pub use crate::curve::CurveParseError;
use crate::scalar::{parse_rational, ParseNumberError, Rational};
pub use json::parse_json_curve;
pub(crate) use json::{describe, json_coordinate, json_point};
pub(crate) use svg_path::svg_number_list;
pub use svg_path::{parse_svg_path, parse_svg_path_reported};

/// Most control points accepted in one segment (degree ≤ 63).
pub const MAX_CONTROL_POINTS: usize = 64;
/// Most segments accepted in one curve.
pub const MAX_SEGMENTS: usize = 100_000;
/// Largest SVG path data accepted, in bytes.
pub const MAX_SVG_BYTES: usize = 1_000_000;
/// Largest `control points × degree³` of a B-spline (the exact conversion's work).
pub const MAX_BSPLINE_WORK: u128 = 50_000_000;
/// Longest number literal accepted, in characters.
pub const MAX_NUMBER_CHARS: usize = 4096;

/// Reads a number literal exactly, guarding `parse_rational` against inputs
/// that are too long or whose exponents do not fit an `i64`; the error is a
/// human-readable reason.
fn exact_number(text: &str) -> Result<Rational, String> {
    let err = |reason: &'static str| {
        ParseNumberError {
            input: text.to_string(),
            reason,
        }
        .to_string()
    };
    if text.chars().count() > MAX_NUMBER_CHARS {
        return Err(format!(
            "number literal of {} characters is longer than the limit of {MAX_NUMBER_CHARS}",
            text.chars().count()
        ));
    }
    let bare = text
        .trim()
        .trim_start_matches(['+', '-'])
        .to_ascii_lowercase();
    if bare == "nan" {
        return Err("NaN is not a finite number".to_string());
    }
    if bare == "inf" || bare == "infinity" {
        return Err(format!("{} is not a finite number", text.trim()));
    }
    // Any exponent with more than 6 significant digits is beyond
    // parse_rational's bound anyway; rejecting it here keeps its i64
    // arithmetic far from overflow.
    let bytes = text.as_bytes();
    for (i, &b) in bytes.iter().enumerate() {
        if b == b'e' || b == b'E' {
            let rest = bytes.get(i + 1..).unwrap_or(&[]);
            let rest = match rest.first() {
                Some(b'+') | Some(b'-') => rest.get(1..).unwrap_or(&[]),
                _ => rest,
            };
            let significant = rest
                .iter()
                .take_while(|c| c.is_ascii_digit())
                .skip_while(|&&c| c == b'0')
                .count();
            if significant > 6 {
                return Err(err("exponent out of range (|e| > 400)"));
            }
        }
    }
    parse_rational(text).map_err(|e| e.to_string())
}

/// Reads a curve in any of its syntaxes: JSON when the text (after leading
/// whitespace) starts with `{`, an SVG document when it starts with `<`
/// ([`super::parse_svg_document`]), SVG path data otherwise. Elliptical arcs,
/// circles, ellipses and rounded rectangles of SVG input are approximated
/// within a certified bound, and this function drops the report of what was
/// approximated: [`parse_curve_reported`] returns it.
///
/// # Examples
/// ```
/// use lncert::shape::parse_curve;
/// let a = parse_curve(r#" {"bezier": [[0, 0], ["1/2", 1], [1, 0]]}"#).unwrap();
/// let b = parse_curve("M 0 0 Q 0.5 1 1 0").unwrap();
/// assert_eq!(a, b);
/// assert!(parse_curve("").is_err());
/// ```
pub fn parse_curve(text: &str) -> Result<Vec<Bezier<Rational>>, CurveParseError> {
    parse_curve_reported(text).map(|(pieces, _)| pieces)
}

/// [`parse_curve`], with the report of what was approximated (empty for JSON
/// curves and for SVG input without arcs, circles, ellipses or rounded
/// rectangles).
///
/// # Examples
/// ```
/// use lncert::shape::parse_curve_reported;
/// let doc = r#"<svg><circle cx="1" cy="1" r="2"/></svg>"#;
/// let (pieces, approx) = parse_curve_reported(doc).unwrap();
/// assert_eq!(approx.elements[0].at, "svg/circle[0]");
/// assert_eq!(approx.pieces(), pieces.len());
/// assert!(approx.bound() <= 2e-7);
/// ```
pub fn parse_curve_reported(
    text: &str,
) -> Result<(Vec<Bezier<Rational>>, InputApprox), CurveParseError> {
    let trimmed = text.trim();
    if trimmed.is_empty() {
        return Err(CurveParseError::Empty {
            what: "the input".to_string(),
        });
    }
    if trimmed.starts_with('{') {
        Ok((parse_json_curve(text)?, InputApprox::default()))
    } else if trimmed.starts_with('<') {
        super::svgdoc::parse_svg_document_reported(text)
    } else {
        parse_svg_path_reported(text)
    }
}
