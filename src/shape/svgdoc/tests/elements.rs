//! Tests of the drawing elements: the simple shapes, circles, ellipses and
//! rounded rectangles, approximated within their reported bounds.

use super::*;
use crate::curve::V2;

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
    let (p2, _) = parse_svg_document_reported(r#"<svg><ellipse rx="2" ry="auto"/></svg>"#).unwrap();
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
