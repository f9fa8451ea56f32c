//! The drawing elements — `<path>`, `<line>`, `<polyline>`, `<polygon>`,
//! `<rect>`, `<circle>`, `<ellipse>` — as pieces in their own coordinates,
//! with what was approximated.

use super::{err, CurveParseError};
use crate::curve::{Bezier, V2};
use crate::scalar::Rational;
use crate::shape::io::{parse_svg_path_reported, svg_number_list};
use crate::shape::svgarc::{
    axis_arc, axis_ellipse_arc, ellipse, ApproxElement, ApproxKind, ExactElement, ExactPiece,
    InputApprox,
};
use num_traits::{Signed, Zero};

/// A plain coordinate attribute (no unit suffix), exactly; a missing one is 0.
pub(super) fn coordinate(
    node: roxmltree::Node,
    name: &str,
    at: &str,
) -> Result<Rational, CurveParseError> {
    match node.attribute(name) {
        None => Ok(Rational::zero()),
        Some(v) => match svg_number_list(v) {
            Ok(xs) if xs.len() == 1 => Ok(xs[0].clone()),
            _ => Err(err(
                format!("{at}.{name}"),
                format!("{v:?} is not a plain number (units such as px or % are not read)"),
            )),
        },
    }
}

fn polyline(points: &[V2<Rational>], closed: bool) -> Vec<Bezier<Rational>> {
    let mut out: Vec<Bezier<Rational>> = points
        .windows(2)
        .filter(|w| w[0] != w[1])
        .map(|w| Bezier::new(vec![w[0].clone(), w[1].clone()]))
        .collect();
    if out.is_empty() && points.len() >= 2 {
        // every point the same: a zero-length subpath (a dot, for the caller)
        return vec![Bezier::new(vec![points[0].clone(), points[0].clone()])];
    }
    if closed {
        if let (Some(a), Some(b)) = (points.last(), points.first()) {
            if a != b {
                out.push(Bezier::new(vec![a.clone(), b.clone()]));
            }
        }
    }
    out
}

/// A radius attribute: `None` when absent or `auto` (SVG 2), an error when
/// negative.
fn radius(
    node: roxmltree::Node,
    name: &str,
    at: &str,
) -> Result<Option<Rational>, CurveParseError> {
    match node.attribute(name) {
        None => return Ok(None),
        Some(v) if v.trim() == "auto" => return Ok(None),
        Some(_) => {}
    }
    let r = coordinate(node, name, at)?;
    if r.is_negative() {
        return Err(err(format!("{at}.{name}"), "a radius must be ≥ 0"));
    }
    Ok(Some(r))
}

/// The arcs of an axis-aligned ellipse about `c`: `(start, quarters)` runs,
/// each a run of quarter turns counter-clockwise from an axis direction.
fn ellipse_arcs(
    c: &V2<Rational>,
    rx: &Rational,
    ry: &Rational,
    runs: &[(u8, u8)],
    at: &str,
) -> Result<(Vec<Bezier<Rational>>, f64), CurveParseError> {
    let mut out = Vec::new();
    let mut bound = 0.0f64;
    for &(start, quarters) in runs {
        let (pieces, b, _) =
            axis_arc(c, rx, ry, start, quarters).map_err(|reason| err(at, reason))?;
        out.extend(pieces);
        bound = bound.max(b);
    }
    Ok((out, bound))
}

/// The shapes of one element in its own coordinates, with what was
/// approximated, or `None` for an element that draws nothing (groups,
/// metadata, …).
#[allow(clippy::type_complexity)]
pub(super) fn element_pieces(
    node: roxmltree::Node,
    at: &str,
) -> Result<Option<(Vec<Bezier<Rational>>, InputApprox)>, CurveParseError> {
    let name = node.tag_name().name();
    let mut approx = InputApprox::default();
    let pieces = match name {
        "path" => match node.attribute("d") {
            None => Vec::new(),
            Some(d) => {
                let (pieces, a) = parse_svg_path_reported(d)
                    .map_err(|e| err(format!("{at}.d"), e.to_string()))?;
                approx.extend_scaled(a, &format!("{at}.d"), 1.0);
                pieces
            }
        },
        "line" => {
            let p = |x: &str, y: &str| -> Result<V2<Rational>, CurveParseError> {
                Ok(V2::new(coordinate(node, x, at)?, coordinate(node, y, at)?))
            };
            polyline(&[p("x1", "y1")?, p("x2", "y2")?], false)
        }
        "polyline" | "polygon" => points_pieces(node, at, name == "polygon")?,
        "rect" => rect_pieces(node, at, &mut approx)?,
        "circle" | "ellipse" => ellipse_pieces(node, at, &mut approx)?,
        "text" | "image" | "foreignObject" => {
            return Err(err(
                at,
                format!(
                    "<{name}> is not read (only path, line, polyline, polygon, rect, circle and ellipse)"
                ),
            ))
        }
        _ => return Ok(None),
    };
    Ok(Some((pieces, approx)))
}

/// Reports the element at `at` as approximated within `bound` by the cubics
/// among `pieces`.
/// `exact`: the element's exact pieces (circular arcs and lines), which
/// replace all of `pieces`.
fn approximated(
    approx: &mut InputApprox,
    kind: ApproxKind,
    at: &str,
    pieces: &[Bezier<Rational>],
    bound: f64,
    exact: Option<Vec<ExactPiece>>,
) {
    approx.push(ApproxElement {
        kind,
        at: at.to_string(),
        pieces: pieces.iter().filter(|b| b.degree() == 3).count(),
        bound,
        detail: String::new(),
        exact: exact.map(|x| ExactElement {
            first: 0,
            count: pieces.len(),
            pieces: x,
        }),
        near: None,
    })
}

/// `rx` and `ry` of a `<rect>` or an `<ellipse>`: one given is both (SVG 2),
/// none is 0.
fn radii(node: roxmltree::Node, at: &str) -> Result<(Rational, Rational), CurveParseError> {
    Ok(match (radius(node, "rx", at)?, radius(node, "ry", at)?) {
        (None, None) => (Rational::zero(), Rational::zero()),
        (Some(r), None) | (None, Some(r)) => (r.clone(), r),
        (Some(rx), Some(ry)) => (rx, ry),
    })
}

/// `<polyline>`, or `<polygon>` (`closed`): the lines between its `points`.
fn points_pieces(
    node: roxmltree::Node,
    at: &str,
    closed: bool,
) -> Result<Vec<Bezier<Rational>>, CurveParseError> {
    let xs = svg_number_list(node.attribute("points").unwrap_or(""))
        .map_err(|e| err(format!("{at}.points"), e.to_string()))?;
    if xs.len() % 2 != 0 {
        return Err(err(format!("{at}.points"), "an odd number of coordinates"));
    }
    let pts: Vec<V2<Rational>> = xs
        .chunks(2)
        .map(|c| V2::new(c[0].clone(), c[1].clone()))
        .collect();
    Ok(polyline(&pts, closed))
}

/// `<rect>`: four lines, or with rounded corners SVG 2's path of lines and
/// four quarter arcs from `(x + rx, y)`, reported.
fn rect_pieces(
    node: roxmltree::Node,
    at: &str,
    approx: &mut InputApprox,
) -> Result<Vec<Bezier<Rational>>, CurveParseError> {
    let (x, y) = (coordinate(node, "x", at)?, coordinate(node, "y", at)?);
    let (w, h) = (
        coordinate(node, "width", at)?,
        coordinate(node, "height", at)?,
    );
    // SVG 2: one radius given is both; each at most half the side
    let (rx, ry) = radii(node, at)?;
    let two = Rational::from_integer(2.into());
    let (rx, ry) = (rx.min(w.abs() / &two), ry.min(h.abs() / &two));
    if rx.is_zero() || ry.is_zero() {
        let pts = [
            V2::new(x.clone(), y.clone()),
            V2::new(&x + &w, y.clone()),
            V2::new(&x + &w, &y + &h),
            V2::new(x, &y + &h),
        ];
        return Ok(polyline(&pts, true));
    }
    let (x1, y1, x2, y2) = (&x + &rx, &y + &ry, &x + &w - &rx, &y + &h - &ry);
    let mut out = Vec::new();
    // the same pieces exactly, when the corners are circular
    let mut exact = Vec::new();
    let mut bound = 0.0f64;
    // SVG 2's path: M (x+rx, y) H (x+w−rx) A … (x+w, y+ry) V … Z
    for (corner, start, line_to) in [
        (
            V2::new(x2.clone(), y1.clone()),
            3,
            V2::new(&x + &w, y2.clone()),
        ),
        (
            V2::new(x2.clone(), y2.clone()),
            0,
            V2::new(x1.clone(), &y + &h),
        ),
        (
            V2::new(x1.clone(), y2.clone()),
            1,
            V2::new(x.clone(), y1.clone()),
        ),
        (
            V2::new(x1.clone(), y1.clone()),
            2,
            V2::new(x2.clone(), y.clone()),
        ),
    ] {
        let (pieces, b, end) =
            axis_arc(&corner, &rx, &ry, start, 1).map_err(|reason| err(at, reason))?;
        out.extend(pieces);
        exact.push(axis_ellipse_arc(&corner, &rx, &ry, start, 1));
        bound = bound.max(b);
        if end != line_to {
            let line = Bezier::new(vec![end, line_to]);
            out.push(line.clone());
            exact.push(ExactPiece::Bezier(line));
        }
    }
    // start at (x + rx, y): the last line (into it) first
    if let Some(last) = out.last().filter(|b| b.degree() == 1).cloned() {
        out.pop();
        out.insert(0, last);
        exact.rotate_right(1);
    }
    approximated(
        approx,
        ApproxKind::RoundedRect,
        at,
        &out,
        bound,
        Some(exact),
    );
    Ok(out)
}

/// `<circle>` and `<ellipse>`: two half arcs from `(cx + rx, cy)`, reported;
/// nothing for a zero radius.
fn ellipse_pieces(
    node: roxmltree::Node,
    at: &str,
    approx: &mut InputApprox,
) -> Result<Vec<Bezier<Rational>>, CurveParseError> {
    let name = node.tag_name().name();
    let c = V2::new(coordinate(node, "cx", at)?, coordinate(node, "cy", at)?);
    let (rx, ry) = if name == "circle" {
        let r = radius(node, "r", at)?.unwrap_or_else(Rational::zero);
        (r.clone(), r)
    } else {
        radii(node, at)?
    };
    if rx.is_zero() || ry.is_zero() {
        return Ok(Vec::new()); // SVG: a zero radius disables rendering
    }
    let (pieces, bound) = ellipse_arcs(&c, &rx, &ry, &[(0, 2), (2, 2)], at)?;
    let kind = if name == "circle" {
        ApproxKind::Circle
    } else {
        ApproxKind::Ellipse
    };
    let exact = ellipse(&c, &rx, &ry);
    approximated(approx, kind, at, &pieces, bound, Some(exact));
    Ok(pieces)
}
