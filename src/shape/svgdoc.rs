//! Whole SVG documents: every rendered `<path>`, `<line>`, `<polyline>`,
//! `<polygon>` and `<rect>` (without rounded corners), with the `transform`s
//! of the element and its ancestors applied — all exactly.
//!
//! The XML is read by roxmltree; the path data and every number (coordinates,
//! transform arguments) by lncert's own exact reader, never through `f64`: an
//! affine map of a Bézier curve is the Bézier curve of the mapped control
//! points, so nothing is approximated. Transforms: `matrix`, `translate`,
//! `scale`, and `rotate`/`skewX`/`skewY` by angles whose sine and cosine are
//! rational (`rotate` by a multiple of 90°, skews by 0°); any other angle is
//! refused, naming the element, since applying it would round.
//!
//! Refused with an error naming the element (nothing is dropped silently):
//! `<circle>`, `<ellipse>`, rounded `<rect>`, `<use>`, `<text>`, `<image>`,
//! path data with `A` arcs (lncert's arcs are circular arcs given exactly;
//! an SVG arc is an ellipse given by end points and flags), and unit suffixes
//! on coordinates. Elements inside `<defs>`, `<clipPath>`, `<mask>`,
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
//! assert!(parse_svg_document(r#"<svg><circle r="1"/></svg>"#).is_err());
//! ```

use super::io::{parse_svg_path, svg_number_list, CurveParseError, MAX_SEGMENTS};
use crate::curve::{Bezier, V2};
use crate::scalar::Rational;
use num_traits::{One, Zero};

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

/// The shapes of one element in its own coordinates, or `None` for an
/// element that draws nothing (groups, metadata, …).
fn element_pieces(
    node: roxmltree::Node,
    at: &str,
) -> Result<Option<Vec<Bezier<Rational>>>, CurveParseError> {
    let name = node.tag_name().name();
    Ok(Some(match name {
        "path" => match node.attribute("d") {
            None => Vec::new(),
            Some(d) => parse_svg_path(d).map_err(|e| err(format!("{at}.d"), e.to_string()))?,
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
            if node.attribute("rx").is_some() || node.attribute("ry").is_some() {
                return Err(err(
                    at,
                    "rounded rectangles (rx, ry) are elliptical arcs: not read",
                ));
            }
            let (x, y) = (coordinate(node, "x", at)?, coordinate(node, "y", at)?);
            let (w, h) = (
                coordinate(node, "width", at)?,
                coordinate(node, "height", at)?,
            );
            let pts = [
                V2::new(x.clone(), y.clone()),
                V2::new(&x + &w, y.clone()),
                V2::new(&x + &w, &y + &h),
                V2::new(x, &y + &h),
            ];
            polyline(&pts, true)
        }
        "circle" | "ellipse" | "use" | "text" | "image" | "foreignObject" => {
            return Err(err(
                at,
                format!("<{name}> is not read (only path, line, polyline, polygon and rect)"),
            ))
        }
        _ => return Ok(None),
    }))
}

/// Every rendered shape of an SVG document, transformed to the document's
/// user coordinates, as exact Bézier pieces in document order. Errors name
/// the element (`svg/g[1]/path[0]`) and the attribute.
pub fn parse_svg_document(text: &str) -> Result<Vec<Bezier<Rational>>, CurveParseError> {
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
    walk(root, "svg".to_string(), &Affine::identity(), &mut out)?;
    if out.is_empty() {
        return Err(CurveParseError::Empty {
            what: "the SVG document".to_string(),
        });
    }
    Ok(out)
}

fn walk(
    node: roxmltree::Node,
    at: String,
    parent: &Affine,
    out: &mut Vec<Bezier<Rational>>,
) -> Result<(), CurveParseError> {
    let m = match node.attribute("transform") {
        Some(t) => parent.then_inner(&parse_transform(t, &format!("{at}.transform"))?),
        None => parent.clone(),
    };
    if let Some(pieces) = element_pieces(node, &at)? {
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
        walk(child, child_at, &m, out)?;
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
                r#"<svg><g/><g><circle r="1"/></g></svg>"#,
                "svg/g[1]/circle[0]",
            ),
            (
                r#"<svg><path d="M 0 0 A 1 1 0 0 1 2 2"/></svg>"#,
                "svg/path[0].d",
            ),
            (
                r#"<svg><g transform="rotate(30)"><path d="M0 0 L1 1"/></g></svg>"#,
                "svg/g[0].transform",
            ),
            (r#"<svg><line x1="1px" x2="2"/></svg>"#, "svg/line[0].x1"),
            (
                r#"<svg><rect rx="1" width="2" height="2"/></svg>"#,
                "svg/rect[0]",
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
}
