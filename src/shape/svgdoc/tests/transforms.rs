//! Tests of transforms: exact composition, the bound scaled by the norm,
//! exactly rational rotations and skews and their displacement.

use super::*;
use crate::shape::svgarc::ApproxKind;
use crate::shape::svgdoc::transform::{rational_rotation, to_f64, Affine};
use num_traits::One;

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

/// `rotate(30)`: an exactly rational rotation (a point of the unit
/// circle), within 1e-12 of the exact one, reported with the displacement.
#[test]
fn irrational_rotations_are_exact_rational_rotations() {
    let (c, s, e) = rational_rotation(&q("30")).unwrap();
    assert_eq!(&c * &c + &s * &s, Rational::one(), "on the unit circle");
    assert!(e <= TRANSFORM_TARGET);
    let (cf, sf) = (30f64.to_radians().cos(), 30f64.to_radians().sin());
    assert!((to_f64(&c) - cf).abs() < 1e-12 && (to_f64(&s) - sf).abs() < 1e-12);
    // every angle class: quarter turns exact, the rest within the target
    for deg in ["-179.5", "91", "225.25", "1e-9", "-44.99", "1/3", "720.1"] {
        let (c, s, e) = rational_rotation(&q(deg)).unwrap();
        let a = to_f64(&q(deg)).to_radians();
        assert_eq!(&c * &c + &s * &s, Rational::one());
        assert!(e <= TRANSFORM_TARGET, "{deg}: {e}");
        assert!((to_f64(&c) - a.cos()).abs() < 1e-11, "{deg}");
        assert!((to_f64(&s) - a.sin()).abs() < 1e-11, "{deg}");
    }
    // the document: a segment from (10, 0) to (20, 0) about the centre (10, 0)
    let doc = r#"<svg><g transform="translate(1 2)"><path transform="rotate(30 10 0)" d="M 10 0 L 20 0"/></g></svg>"#;
    let (p, a) = parse_svg_document_reported(doc).unwrap();
    assert_eq!(
        pts(&p[0])[0],
        (q("11"), q("2")),
        "the centre stays, exactly"
    );
    let end = &pts(&p[0])[1];
    assert!((to_f64(&end.0) - (11.0 + 10.0 * cf)).abs() < 1e-10);
    assert!((to_f64(&end.1) - (2.0 + 10.0 * sf)).abs() < 1e-10);
    assert_eq!(a.elements.len(), 1);
    let el = &a.elements[0];
    assert_eq!(
        (el.kind, el.at.as_str()),
        (ApproxKind::Rotation, "svg/g[0]/path[0]")
    );
    // displacement ≤ err · max |p − c| = err · 10
    assert!(el.bound > 0.0 && el.bound <= 10.0 * TRANSFORM_TARGET * (1.0 + 1e-9));
    assert!(
        el.detail.starts_with("rotate(30) as cos = "),
        "{}",
        el.detail
    );
    let summary = a.summary().unwrap();
    assert!(
        summary.contains(
            "1 element(s) under an irrational rotate mapped exactly by a rational matrix"
        ),
        "{summary}"
    );
    assert_eq!(a.pieces(), 0, "no curve was replaced");
}

/// A circle under a rotation: its arc bound plus the rotation's
/// displacement over the circle (radius + its own bound); a skew likewise.
#[test]
fn rotated_arcs_add_the_displacement() {
    let (_, plain) = parse_svg_document_reported(r#"<svg><circle cx="100" r="1"/></svg>"#).unwrap();
    let (_, a) = parse_svg_document_reported(
        r#"<svg><g transform="scale(2) rotate(10)"><circle cx="100" r="1"/></g></svg>"#,
    )
    .unwrap();
    assert_eq!(a.elements.len(), 2);
    let delta = a.elements[1].bound;
    // |p| ≤ 101 + ε on the circle, times ‖scale(2)‖ = 2
    assert!(delta > 0.0 && delta <= 2.0 * 101.0 * TRANSFORM_TARGET * 1.0001);
    assert!(a.elements[0].bound >= 2.0 * plain.bound() + delta);
    assert!(a.elements[0].bound <= (2.0 * plain.bound() + delta) * (1.0 + 1e-12));
    let (p, a) =
        parse_svg_document_reported(r#"<svg><path transform="skewX(30)" d="M 0 0 L 0 3"/></svg>"#)
            .unwrap();
    let t = 30f64.to_radians().tan();
    assert!((to_f64(&pts(&p[0])[1].0) - 3.0 * t).abs() < 1e-11);
    assert_eq!(a.elements[0].kind, ApproxKind::Skew);
    assert!(a.elements[0].bound <= 3.0 * TRANSFORM_TARGET);
    // skewX(180) and skewY(-45) are exact
    let (p, a) = parse_svg_document_reported(
        r#"<svg><path transform="skewX(180) skewY(-45)" d="M 0 0 L 2 3"/></svg>"#,
    )
    .unwrap();
    assert!(a.is_empty());
    assert_eq!(pts(&p[0])[1], (q("2"), q("1")));
}
