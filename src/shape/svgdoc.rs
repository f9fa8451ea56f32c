//! Whole SVG documents: every rendered `<path>`, `<line>`, `<polyline>`,
//! `<polygon>`, `<rect>`, `<circle>` and `<ellipse>`, with the `transform`s
//! of the element and its ancestors applied.
//!
//! The XML is read by roxmltree; the path data and every number (coordinates,
//! transform arguments) by lncert's own exact reader, never through `f64`: an
//! affine map of a Bézier curve is the Bézier curve of the mapped control
//! points, so the transforms round nothing. Transforms: `matrix`,
//! `translate`, `scale`, and `rotate`/`skewX`/`skewY` by angles whose sine
//! and cosine are rational (`rotate` by a multiple of 90°, skews by 0°); any
//! other angle is refused, naming the element, since applying it would round.
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
//! singular value, enclosed from the exact matrix).
//!
//! Refused with an error naming the element (nothing is dropped silently):
//! `<use>`, `<text>`, `<image>`, `<foreignObject>`, negative radii, and unit
//! suffixes on coordinates. Elements inside `<defs>`, `<clipPath>`, `<mask>`,
//! `<symbol>`, `<marker>` and `<pattern>` are not rendered, and are skipped.
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

use super::io::{parse_svg_path_reported, svg_number_list, CurveParseError, MAX_SEGMENTS};
use super::svgarc::{axis_arc, ApproxElement, ApproxKind, InputApprox};
use crate::curve::{Bezier, V2};
use crate::scalar::{interval_from_rational, Interval, Rational};
use num_traits::{One, Signed, Zero};

/// Largest SVG document read, in bytes.
pub const MAX_DOCUMENT_BYTES: usize = 16 << 20;

/// An affine map `(x, y) ↦ (a x + c y + e, b x + d y + f)`, SVG's
/// `matrix(a b c d e f)`.
#[derive(Clone, Debug, PartialEq)]
struct Affine([Rational; 6]);

impl Affine {
    fn identity() -> Self {
        let (o, z) = (Rational::one(), Rational::zero());
        Affine([o.clone(), z.clone(), z.clone(), o, z.clone(), z])
    }
    /// `self ∘ other` (apply `other` first).
    fn then_inner(&self, o: &Affine) -> Affine {
        let [a, b, c, d, e, f] = &self.0;
        let [a2, b2, c2, d2, e2, f2] = &o.0;
        Affine([
            a * a2 + c * b2,
            b * a2 + d * b2,
            a * c2 + c * d2,
            b * c2 + d * d2,
            a * e2 + c * f2 + e,
            b * e2 + d * f2 + f,
        ])
    }
    fn apply(&self, p: &V2<Rational>) -> V2<Rational> {
        let [a, b, c, d, e, f] = &self.0;
        V2::new(a * &p.x + c * &p.y + e, b * &p.x + d * &p.y + f)
    }
    /// An upper bound of `‖L‖₂` for the linear part `L`, its largest singular
    /// value `√((s + √(s² − 4 det²))/2)`, `s = a² + b² + c² + d²`, enclosed
    /// from the exact `s` and `s² − 4 det² ≥ 0`: `d_H(T X, T Y) ≤ ‖L‖₂ d_H(X, Y)`.
    fn norm_sup(&self) -> f64 {
        let [a, b, c, d, _, _] = &self.0;
        let s = a * a + b * b + c * c + d * d;
        let det = a * d - b * c;
        let four = Rational::from_integer(4.into());
        if s == Rational::one() + Rational::one() && det.abs() == Rational::one() {
            return 1.0; // a rotation or reflection by a multiple of 90°
        }
        let disc = &s * &s - four * &det * &det;
        let half = Interval::try_from((0.5, 0.5)).unwrap_or(Interval::ENTIRE);
        let sigma2 = (interval_from_rational(&s) + interval_from_rational(&disc).sqrt()) * half;
        let n = sigma2.sqrt();
        if n.is_empty() {
            f64::INFINITY
        } else {
            n.sup()
        }
    }
}

fn err(field: impl Into<String>, reason: impl Into<String>) -> CurveParseError {
    CurveParseError::Field {
        field: field.into(),
        reason: reason.into(),
    }
}

/// `(cos, sin)` of a multiple of 90°, exactly; `None` for any other angle.
fn quarter_turn(deg: &Rational) -> Option<(Rational, Rational)> {
    let q = deg / Rational::from_integer(90.into());
    if !q.is_integer() {
        return None;
    }
    let four = num_bigint::BigInt::from(4);
    let k: num_bigint::BigInt = (q.to_integer() % &four + &four) % &four;
    let (o, z) = (Rational::one(), Rational::zero());
    Some(match k.to_string().as_str() {
        "0" => (o, z),
        "1" => (z, o),
        "2" => (-o, z),
        _ => (z, -o),
    })
}

/// Reads an SVG `transform` attribute.
fn parse_transform(text: &str, at: &str) -> Result<Affine, CurveParseError> {
    let mut m = Affine::identity();
    let mut rest = text.trim();
    while !rest.is_empty() {
        let open = rest
            .find('(')
            .ok_or_else(|| err(at, format!("expected name(arguments) in {rest:?}")))?;
        let close = rest
            .find(')')
            .filter(|c| *c > open)
            .ok_or_else(|| err(at, "a transform function is not closed by ')'"))?;
        let name = rest[..open].trim().trim_start_matches(',').trim();
        let args =
            svg_number_list(&rest[open + 1..close]).map_err(|e| err(at, format!("{name}: {e}")))?;
        let (o, z) = (Rational::one(), Rational::zero());
        let f = match (name, args.as_slice()) {
            ("matrix", [a, b, c, d, e, f]) => Affine([
                a.clone(),
                b.clone(),
                c.clone(),
                d.clone(),
                e.clone(),
                f.clone(),
            ]),
            ("translate", [x]) => Affine([o.clone(), z.clone(), z.clone(), o, x.clone(), z]),
            ("translate", [x, y]) => {
                Affine([o.clone(), z.clone(), z.clone(), o, x.clone(), y.clone()])
            }
            ("scale", [s]) => Affine([s.clone(), z.clone(), z.clone(), s.clone(), z.clone(), z]),
            ("scale", [sx, sy]) => {
                Affine([sx.clone(), z.clone(), z.clone(), sy.clone(), z.clone(), z])
            }
            ("rotate", [a, centre @ ..]) if centre.is_empty() || centre.len() == 2 => {
                let (c, s) = quarter_turn(a).ok_or_else(|| {
                    err(at, format!("rotate({a}): only multiples of 90° are exact (cos and sin of other angles are irrational)"))
                })?;
                let r = Affine([c.clone(), s.clone(), -s, c, z.clone(), z.clone()]);
                match centre {
                    [cx, cy] => {
                        let to = Affine([
                            o.clone(),
                            z.clone(),
                            z.clone(),
                            o.clone(),
                            cx.clone(),
                            cy.clone(),
                        ]);
                        let back =
                            Affine([o.clone(), z.clone(), z.clone(), o, -cx.clone(), -cy.clone()]);
                        to.then_inner(&r).then_inner(&back)
                    }
                    _ => r,
                }
            }
            ("skewX" | "skewY", [a]) if a.is_zero() => Affine::identity(),
            ("skewX" | "skewY", [a]) => {
                return Err(err(
                    at,
                    format!("{name}({a}): only 0° is exact (tan of other angles is irrational)"),
                ))
            }
            _ => {
                return Err(err(
                    at,
                    format!("unknown transform {name:?} with {} argument(s)", args.len()),
                ))
            }
        };
        m = m.then_inner(&f);
        rest = rest[close + 1..].trim_start();
    }
    Ok(m)
}

/// A plain coordinate attribute (no unit suffix), exactly; a missing one is 0.
fn coordinate(node: roxmltree::Node, name: &str, at: &str) -> Result<Rational, CurveParseError> {
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
    if closed {
        if let (Some(a), Some(b)) = (points.last(), points.first()) {
            if a != b {
                out.push(Bezier::new(vec![a.clone(), b.clone()]));
            }
        }
    }
    out
}

/// The elements whose content is not rendered.
const NOT_RENDERED: [&str; 6] = ["defs", "clipPath", "mask", "symbol", "marker", "pattern"];

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
fn element_pieces(
    node: roxmltree::Node,
    at: &str,
) -> Result<Option<(Vec<Bezier<Rational>>, InputApprox)>, CurveParseError> {
    let name = node.tag_name().name();
    let mut approx = InputApprox::default();
    let approximated = |approx: &mut InputApprox, kind, pieces: &[Bezier<Rational>], bound| {
        approx.push(ApproxElement {
            kind,
            at: at.to_string(),
            pieces: pieces.iter().filter(|b| b.degree() == 3).count(),
            bound,
        })
    };
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
        "polyline" | "polygon" => {
            let xs = svg_number_list(node.attribute("points").unwrap_or(""))
                .map_err(|e| err(format!("{at}.points"), e.to_string()))?;
            if xs.len() % 2 != 0 {
                return Err(err(format!("{at}.points"), "an odd number of coordinates"));
            }
            let pts: Vec<V2<Rational>> = xs
                .chunks(2)
                .map(|c| V2::new(c[0].clone(), c[1].clone()))
                .collect();
            polyline(&pts, name == "polygon")
        }
        "rect" => {
            let (x, y) = (coordinate(node, "x", at)?, coordinate(node, "y", at)?);
            let (w, h) = (
                coordinate(node, "width", at)?,
                coordinate(node, "height", at)?,
            );
            // SVG 2: one radius given is both; each at most half the side
            let (rx, ry) = match (radius(node, "rx", at)?, radius(node, "ry", at)?) {
                (None, None) => (Rational::zero(), Rational::zero()),
                (Some(r), None) | (None, Some(r)) => (r.clone(), r),
                (Some(rx), Some(ry)) => (rx, ry),
            };
            let two = Rational::from_integer(2.into());
            let (rx, ry) = (rx.min(w.abs() / &two), ry.min(h.abs() / &two));
            if rx.is_zero() || ry.is_zero() {
                let pts = [
                    V2::new(x.clone(), y.clone()),
                    V2::new(&x + &w, y.clone()),
                    V2::new(&x + &w, &y + &h),
                    V2::new(x, &y + &h),
                ];
                polyline(&pts, true)
            } else {
                let (x1, y1, x2, y2) = (&x + &rx, &y + &ry, &x + &w - &rx, &y + &h - &ry);
                let mut out = Vec::new();
                let mut bound = 0.0f64;
                // SVG 2's path: M (x+rx, y) H (x+w−rx) A … (x+w, y+ry) V … Z
                for (corner, start, line_to) in [
                    (V2::new(x2.clone(), y1.clone()), 3, V2::new(&x + &w, y2.clone())),
                    (V2::new(x2.clone(), y2.clone()), 0, V2::new(x1.clone(), &y + &h)),
                    (V2::new(x1.clone(), y2.clone()), 1, V2::new(x.clone(), y1.clone())),
                    (V2::new(x1.clone(), y1.clone()), 2, V2::new(x2.clone(), y.clone())),
                ] {
                    let (pieces, b, end) = axis_arc(&corner, &rx, &ry, start, 1)
                        .map_err(|reason| err(at, reason))?;
                    out.extend(pieces);
                    bound = bound.max(b);
                    if end != line_to {
                        out.push(Bezier::new(vec![end, line_to]));
                    }
                }
                // start at (x + rx, y): the last line (into it) first
                if let Some(last) = out.last().filter(|b| b.degree() == 1).cloned() {
                    out.pop();
                    out.insert(0, last);
                }
                approximated(&mut approx, ApproxKind::RoundedRect, &out, bound);
                out
            }
        }
        "circle" | "ellipse" => {
            let c = V2::new(coordinate(node, "cx", at)?, coordinate(node, "cy", at)?);
            let (rx, ry) = if name == "circle" {
                let r = radius(node, "r", at)?.unwrap_or_else(Rational::zero);
                (r.clone(), r)
            } else {
                match (radius(node, "rx", at)?, radius(node, "ry", at)?) {
                    (None, None) => (Rational::zero(), Rational::zero()),
                    (Some(r), None) | (None, Some(r)) => (r.clone(), r),
                    (Some(rx), Some(ry)) => (rx, ry),
                }
            };
            if rx.is_zero() || ry.is_zero() {
                Vec::new() // SVG: a zero radius disables rendering
            } else {
                let (pieces, bound) = ellipse_arcs(&c, &rx, &ry, &[(0, 2), (2, 2)], at)?;
                let kind = if name == "circle" {
                    ApproxKind::Circle
                } else {
                    ApproxKind::Ellipse
                };
                approximated(&mut approx, kind, &pieces, bound);
                pieces
            }
        }
        "use" | "text" | "image" | "foreignObject" => {
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

/// Every rendered shape of an SVG document, transformed to the document's
/// user coordinates, as Bézier pieces in document order. Errors name the
/// element (`svg/g[1]/path[0]`) and the attribute. Arcs, circles, ellipses
/// and rounded rectangles are approximated within a certified bound, and
/// this function drops the report of what was approximated:
/// [`parse_svg_document_reported`] returns it.
pub fn parse_svg_document(text: &str) -> Result<Vec<Bezier<Rational>>, CurveParseError> {
    parse_svg_document_reported(text).map(|(pieces, _)| pieces)
}

/// [`parse_svg_document`], with the list of the approximated elements, each
/// with its certified Hausdorff bound in the document's user coordinates
/// (the transforms' norms applied).
pub fn parse_svg_document_reported(
    text: &str,
) -> Result<(Vec<Bezier<Rational>>, InputApprox), CurveParseError> {
    if text.len() > MAX_DOCUMENT_BYTES {
        return Err(CurveParseError::TooLarge {
            what: "the SVG document (bytes)".to_string(),
            limit: MAX_DOCUMENT_BYTES,
        });
    }
    let doc = roxmltree::Document::parse(text)
        .map_err(|e| err("(document)", format!("not a well-formed XML document: {e}")))?;
    let root = doc.root_element();
    if root.tag_name().name() != "svg" {
        return Err(err(
            "(document)",
            format!(
                "the root element is <{}>, not <svg>",
                root.tag_name().name()
            ),
        ));
    }
    let mut out = Vec::new();
    let mut approx = InputApprox::default();
    walk(
        root,
        "svg".to_string(),
        &Affine::identity(),
        &mut out,
        &mut approx,
    )?;
    if out.is_empty() {
        return Err(CurveParseError::Empty {
            what: "the SVG document".to_string(),
        });
    }
    Ok((out, approx))
}

fn walk(
    node: roxmltree::Node,
    at: String,
    parent: &Affine,
    out: &mut Vec<Bezier<Rational>>,
    approx: &mut InputApprox,
) -> Result<(), CurveParseError> {
    let m = match node.attribute("transform") {
        Some(t) => parent.then_inner(&parse_transform(t, &format!("{at}.transform"))?),
        None => parent.clone(),
    };
    if let Some((pieces, a)) = element_pieces(node, &at)? {
        if !a.is_empty() {
            let factor = m.norm_sup();
            approx.extend_scaled(a, "", factor);
        }
        for b in pieces {
            out.push(Bezier::new(b.points().iter().map(|p| m.apply(p)).collect()));
            if out.len() > MAX_SEGMENTS {
                return Err(CurveParseError::TooLarge {
                    what: "segments in the SVG document".to_string(),
                    limit: MAX_SEGMENTS,
                });
            }
        }
    }
    let mut counts: std::collections::HashMap<&str, usize> = Default::default();
    for child in node.children().filter(|c| c.is_element()) {
        let name = child.tag_name().name();
        let i = counts.entry(name).or_insert(0);
        let child_at = format!("{at}/{name}[{i}]");
        *i += 1;
        if NOT_RENDERED.contains(&name) {
            continue;
        }
        walk(child, child_at, &m, out, approx)?;
    }
    Ok(())
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::scalar::parse_rational;

    fn q(s: &str) -> Rational {
        parse_rational(s).unwrap()
    }

    fn pts(b: &Bezier<Rational>) -> Vec<(Rational, Rational)> {
        b.points()
            .iter()
            .map(|p| (p.x.clone(), p.y.clone()))
            .collect()
    }

    /// Transforms compose as SVG says (the parent's applies last; a list
    /// applies right to left), exactly, checked against hand-computed points.
    #[test]
    fn transforms_compose_exactly() {
        let doc = r#"<svg><g transform="translate(10,0)"><g transform="scale(2 3) rotate(90)">
            <path d="M 1 0 L 0.1 2"/></g></g></svg>"#;
        let p = parse_svg_document(doc).unwrap();
        // rotate(90): (x, y) ↦ (−y, x); scale(2, 3); translate(10, 0)
        // (1, 0) → (0, 1) → (0, 3) → (10, 3); (1/10, 2) → (−2, 1/10) → (−4, 3/10) → (6, 3/10)
        assert_eq!(pts(&p[0]), vec![(q("10"), q("3")), (q("6"), q("3/10"))]);
        // rotate about a centre, and matrix(a b c d e f) as x' = a x + c y + e
        let doc =
            r#"<svg><path transform="rotate(180 1 1) matrix(1 2 3 4 5 6)" d="M 1 1 L 0 0"/></svg>"#;
        let p = parse_svg_document(doc).unwrap();
        // matrix: (1, 1) → (1+3+5, 2+4+6) = (9, 12); rotate 180 about (1, 1): (2−9, 2−12)
        assert_eq!(pts(&p[0])[0], (q("-7"), q("-10")));
        assert_eq!(pts(&p[0])[1], (q("-3"), q("-4")));
        // rotate(-270) = rotate(90); skewX(0) is the identity
        let a = parse_svg_document(
            r#"<svg><path transform="rotate(-270) skewX(0)" d="M 1 0 L 2 0"/></svg>"#,
        )
        .unwrap();
        assert_eq!(pts(&a[0])[0], (q("0"), q("1")));
    }

    /// The simple shapes, closed where SVG closes them; non-rendered content skipped.
    #[test]
    fn shapes_and_skipped_content() {
        let doc = r#"<svg xmlns="http://www.w3.org/2000/svg">
            <defs><path d="M 0 0 L 100 100"/></defs>
            <clipPath><rect width="5" height="5"/></clipPath>
            <rect x="1" y="2" width="3" height="4"/>
            <polygon points="0,0 1,0 1,1"/>
            <polyline points="0 0 1 0 1 1"/>
            <line x1="0" y1="0" x2="0.5" y2="0"/>
        </svg>"#;
        let p = parse_svg_document(doc).unwrap();
        assert_eq!(p.len(), 4 + 3 + 2 + 1);
        assert_eq!(pts(&p[0])[0], (q("1"), q("2")));
        assert_eq!(pts(&p[3])[1], (q("1"), q("2")), "the rectangle closes");
        assert_eq!(pts(&p[6])[1], (q("0"), q("0")), "the polygon closes");
        assert_eq!(pts(&p[9])[1], (q("1/2"), q("0")), "0.5 is read exactly");
    }

    /// What is not read is an error naming the element, never dropped.
    #[test]
    fn unreadable_content_names_the_element() {
        for (doc, at) in [
            (
                r#"<svg><g/><g><circle r="-1"/></g></svg>"#,
                "svg/g[1]/circle[0].r",
            ),
            (
                r#"<svg><g/><g><text>a</text></g></svg>"#,
                "svg/g[1]/text[0]",
            ),
            (
                r#"<svg><path d="M 0 0 A 1 1 0 2 1 2 2"/></svg>"#,
                "svg/path[0].d",
            ),
            (
                r#"<svg><ellipse rx="1" ry="-2"/></svg>"#,
                "svg/ellipse[0].ry",
            ),
            (r#"<svg><circle r="1e101"/></svg>"#, "svg/circle[0]"),
            (
                r#"<svg><g transform="rotate(30)"><path d="M0 0 L1 1"/></g></svg>"#,
                "svg/g[0].transform",
            ),
            (r#"<svg><line x1="1px" x2="2"/></svg>"#, "svg/line[0].x1"),
            (
                r#"<svg><rect rx="-1" width="2" height="2"/></svg>"#,
                "svg/rect[0].rx",
            ),
            (
                r#"<svg><polygon points="0 0 1"/></svg>"#,
                "svg/polygon[0].points",
            ),
            (
                r#"<svg><path transform="wobble(1)" d="M0 0 L1 1"/></svg>"#,
                "svg/path[0].transform",
            ),
            (r#"<svg><path d="M0 0 L1 1"/>"#, "(document)"),
            (r#"<html/>"#, "(document)"),
        ] {
            match parse_svg_document(doc) {
                Err(CurveParseError::Field { field, .. }) => assert_eq!(field, at, "{doc}"),
                other => panic!("{doc}: {other:?}"),
            }
        }
        assert!(matches!(
            parse_svg_document("<svg><g/></svg>"),
            Err(CurveParseError::Empty { .. })
        ));
    }

    /// A lower estimate of the distance of a chain of pieces from the
    /// ellipse `((x − cx)/rx)² + ((y − cy)/ry)² = 1`, in floats: the largest
    /// `|‖((x − cx)/rx, (y − cy)/ry)‖ − 1| · min(rx, ry)` over dense samples
    /// (the map from the unit circle shrinks no distance by more than the
    /// smaller radius).
    fn radial_error(p: &[Bezier<Rational>], c: (f64, f64), r: (f64, f64)) -> f64 {
        use crate::scalar::Scalar;
        let mut worst = 0.0f64;
        for b in p {
            let pts: Vec<(f64, f64)> = b
                .points()
                .iter()
                .map(|q| (q.x.approx(), q.y.approx()))
                .collect();
            for k in 0..=64 {
                let t = k as f64 / 64.0;
                let v = Bezier::new(pts.iter().map(|&(x, y)| V2::new(x, y)).collect()).eval(&t);
                let (u, w) = ((v.x - c.0) / r.0, (v.y - c.1) / r.1);
                worst = worst.max((u.hypot(w) - 1.0).abs() * r.0.min(r.1));
            }
        }
        worst
    }

    /// `<circle>` and `<ellipse>`: two half arcs from (cx + rx, cy), counter-
    /// clockwise in user coordinates, closed exactly, reported with bounds.
    #[test]
    fn circles_and_ellipses_are_approximated_and_reported() {
        let doc = r#"<svg><circle cx="1" cy="2" r="3"/><ellipse cx="-1" cy="0" rx="2" ry="0.5"/>
            <ellipse rx="2"/><circle r="0"/></svg>"#;
        let (p, a) = parse_svg_document_reported(doc).unwrap();
        assert_eq!(a.elements.len(), 3, "the zero circle draws nothing");
        assert_eq!(a.elements[0].at, "svg/circle[0]");
        assert_eq!(a.elements[1].at, "svg/ellipse[0]");
        assert_eq!(a.elements[2].at, "svg/ellipse[1]");
        assert_eq!(a.elements[0].pieces, 18, "9 pieces per half circle");
        assert_eq!(a.pieces(), p.len());
        // starts at (cx + r, cy), goes towards +y first, closes exactly
        let circle = &p[..18];
        assert_eq!(pts(&circle[0])[0], (q("4"), q("2")));
        assert!(
            pts(&circle[0])[3].1 > q("2"),
            "counter-clockwise: y increases first"
        );
        assert_eq!(
            pts(&circle[8])[3],
            (q("-2"), q("2")),
            "the half point is exact"
        );
        assert_eq!(pts(&circle[17])[3], (q("4"), q("2")), "closed exactly");
        // bounds: within the target, and above the measured error
        assert!(a.elements[0].bound <= 3e-7);
        let measured = radial_error(circle, (1.0, 2.0), (3.0, 3.0));
        assert!(
            measured <= a.elements[0].bound,
            "{measured} > {}",
            a.elements[0].bound
        );
        let ellipse = &p[18..36];
        assert_eq!(pts(&ellipse[0])[0], (q("1"), q("0")));
        assert!(a.elements[1].bound <= 2e-7);
        // a missing ry is rx (SVG 2's auto)
        assert_eq!(pts(&p[36])[0], (q("2"), q("0")));
        let (p2, _) =
            parse_svg_document_reported(r#"<svg><ellipse rx="2" ry="auto"/></svg>"#).unwrap();
        assert_eq!(p2, p[36..].to_vec());
    }

    /// Rounded `<rect>`: SVG 2's path — lines and four quarter arcs from
    /// (x + rx, y); one radius given is both; radii clamped to half a side.
    #[test]
    fn rounded_rects_are_lines_and_quarter_arcs() {
        let (p, a) = parse_svg_document_reported(
            r#"<svg><rect x="1" y="2" width="10" height="4" rx="1"/></svg>"#,
        )
        .unwrap();
        assert_eq!(a.elements.len(), 1);
        let lines: Vec<_> = p.iter().filter(|b| b.degree() == 1).collect();
        assert_eq!(lines.len(), 4);
        assert_eq!(pts(lines[0]), vec![(q("2"), q("2")), (q("10"), q("2"))]);
        assert_eq!(a.elements[0].pieces, p.len() - 4);
        for w in p.windows(2) {
            assert_eq!(pts(&w[0]).last(), pts(&w[1]).first(), "connected exactly");
        }
        assert_eq!(pts(&p[p.len() - 1]).last(), pts(&p[0]).first(), "closed");
        assert!(a.bound() <= 1e-7);
        // rx larger than half the width: clamped, the top and bottom lines vanish
        let (p, _) =
            parse_svg_document_reported(r#"<svg><rect width="2" height="4" rx="5" ry="1"/></svg>"#)
                .unwrap();
        assert_eq!(p.iter().filter(|b| b.degree() == 1).count(), 2);
        // rx = 0: a plain rectangle, nothing approximated
        let (p, a) =
            parse_svg_document_reported(r#"<svg><rect width="2" height="4" rx="0" ry="1"/></svg>"#)
                .unwrap();
        assert_eq!(p.len(), 4);
        assert!(a.is_empty());
    }

    /// Transforms map the pieces exactly and scale the bound by ‖T‖₂.
    #[test]
    fn transforms_scale_the_bound() {
        let plain = parse_svg_document_reported(r#"<svg><circle r="1"/></svg>"#).unwrap();
        let (p, a) = parse_svg_document_reported(
            r#"<svg><g transform="translate(5 5) scale(3 2)"><circle r="1"/></g></svg>"#,
        )
        .unwrap();
        // the same pieces mapped: (x, y) ↦ (3x + 5, 2y + 5)
        assert_eq!(pts(&p[0])[1].0, q("3") * &pts(&plain.0[0])[1].0 + q("5"));
        let (b0, b) = (plain.1.bound(), a.bound());
        assert!(b >= 3.0 * b0 && b <= 3.0 * b0 * (1.0 + 1e-12), "{b0} {b}");
        // rotations by 90° keep the bound; a path's arcs are named inside it
        let (_, a) = parse_svg_document_reported(
            r#"<svg><path transform="rotate(90)" d="M 0 0 L 1 0 A 1 1 0 0 1 3 0"/></svg>"#,
        )
        .unwrap();
        assert_eq!(a.elements[0].at, "svg/path[0].d, byte 12");
        let (_, b) =
            parse_svg_document_reported(r#"<svg><path d="M 0 0 L 1 0 A 1 1 0 0 1 3 0"/></svg>"#)
                .unwrap();
        assert_eq!(a.bound(), b.bound());
        // ‖matrix(1 1 0 1 0 0)‖₂ = the golden ratio
        let m = Affine([q("1"), q("1"), q("0"), q("1"), q("0"), q("0")]);
        let g = (1.0 + 5f64.sqrt()) / 2.0;
        assert!(m.norm_sup() >= g && m.norm_sup() <= g * (1.0 + 1e-14));
    }
}
