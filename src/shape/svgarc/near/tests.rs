//! Tests of the near arcs: their structure (which construction, which end
//! points, the path kept connected), and their certified bound against the
//! exact SVG arc computed independently in floats (SVG F.6.5 written out
//! here), sample by sample.

use super::*;
use crate::scalar::Scalar;
use crate::shape::ApproxKind;
use crate::shape::{parse_curve_reported, parse_svg_path_reported};
use crate::stroke::{exact_path, stroke_path, PathPiece, StrokeOptions};
use crate::test_util::q;

fn f(x: &Rational) -> f64 {
    x.approx()
}

fn pt(p: &V2<Rational>) -> (f64, f64) {
    (f(&p.x), f(&p.y))
}

/// The exact circle of `A r r 0 large sweep p1` from `p0` in floats (SVG
/// F.6.5 for a circle): centre, and the signed sweep.
fn svg_circle(
    p0: (f64, f64),
    p1: (f64, f64),
    r: f64,
    large: bool,
    sweep: bool,
) -> ((f64, f64), f64) {
    let (mx, my) = ((p0.0 + p1.0) / 2.0, (p0.1 + p1.1) / 2.0);
    let (dx, dy) = (p1.0 - p0.0, p1.1 - p0.1);
    let len = dx.hypot(dy);
    let mut h = (r * r / (len * len) - 0.25).max(0.0).sqrt();
    if large == sweep {
        h = -h;
    }
    let c = (mx - h * dy, my + h * dx);
    let a0 = (p0.1 - c.1).atan2(p0.0 - c.0);
    let a1 = (p1.1 - c.1).atan2(p1.0 - c.0);
    let mut d = a1 - a0;
    if sweep && d < 0.0 {
        d += std::f64::consts::TAU;
    }
    if !sweep && d > 0.0 {
        d -= std::f64::consts::TAU;
    }
    (c, d)
}

/// Float samples of an [`ArcDesc`] counter-clockwise from `from` to `to`.
fn samples(a: &ArcDesc, n: usize) -> Vec<(f64, f64)> {
    let c = pt(&a.center);
    let r = f(&a.radius);
    let a0 = f(&a.from.y).atan2(f(&a.from.x));
    let mut d = f(&a.to.y).atan2(f(&a.to.x)) - a0;
    if d <= 0.0 {
        d += std::f64::consts::TAU;
    }
    (0..=n)
        .map(|k| {
            let t = a0 + d * k as f64 / n as f64;
            (c.0 + r * t.cos(), c.1 + r * t.sin())
        })
        .collect()
}

/// The distance from `x` to the arc of centre `c`, radius `r`, from angle
/// `a0` through the signed sweep `d` (floats).
fn to_arc(x: (f64, f64), c: (f64, f64), r: f64, a0: f64, d: f64) -> f64 {
    let end = |t: f64| (c.0 + r * t.cos(), c.1 + r * t.sin());
    let ang = (x.1 - c.1).atan2(x.0 - c.0);
    // is the direction within the swept range?
    let rel = if d >= 0.0 {
        (ang - a0).rem_euclid(std::f64::consts::TAU)
    } else {
        (a0 - ang).rem_euclid(std::f64::consts::TAU)
    };
    if rel <= d.abs() {
        ((x.0 - c.0).hypot(x.1 - c.1) - r).abs()
    } else {
        let (e0, e1) = (end(a0), end(a0 + d));
        (x.0 - e0.0)
            .hypot(x.1 - e0.1)
            .min((x.0 - e1.0).hypot(x.1 - e1.1))
    }
}

/// Every sample of the near arc is within its bound of the exact arc, and
/// every sample of the exact arc within the bound of the near arc (floats,
/// with room for their rounding); returns the bound.
fn check_bound(
    near: &NearElement,
    p0: (f64, f64),
    p1: (f64, f64),
    r: f64,
    large: bool,
    sweep: bool,
) -> f64 {
    let ExactPiece::Arc(a) = &near.element.pieces[0] else {
        panic!("a near arc first")
    };
    let b = near.bound;
    assert!(b > 0.0 && b <= 1e-9 * r, "bound {b}");
    let (c, d) = svg_circle(p0, p1, r, large, sweep);
    let a0 = (p0.1 - c.1).atan2(p0.0 - c.0);
    let slack = 1e-13 * (1.0 + r);
    for x in samples(a, 2000) {
        let e = to_arc(x, c, r, a0, d);
        assert!(
            e <= b + slack,
            "near sample {x:?}: {e} from the exact arc, bound {b}"
        );
    }
    let nc = pt(&a.center);
    let nr = f(&a.radius);
    let na0 = f(&a.from.y).atan2(f(&a.from.x));
    let mut nd = f(&a.to.y).atan2(f(&a.to.x)) - na0;
    if nd <= 0.0 {
        nd += std::f64::consts::TAU;
    }
    for k in 0..=2000 {
        let t = a0 + d * k as f64 / 2000.0;
        let x = (c.0 + r * t.cos(), c.1 + r * t.sin());
        let e = to_arc(x, nc, nr, na0, nd);
        assert!(
            e <= b + slack,
            "exact sample {x:?}: {e} from the near arc, bound {b}"
        );
    }
    b
}

fn near_of(d: &str, k: usize) -> (NearElement, Vec<Bezier<Rational>>) {
    let (pieces, approx) = parse_svg_path_reported(d).unwrap();
    let e = &approx.elements[k];
    assert!(e.exact.is_none(), "{d}: element {k} is exact");
    (
        e.near
            .clone()
            .unwrap_or_else(|| panic!("{d}: no near arc for element {k}")),
        pieces,
    )
}

fn arc_of(n: &NearElement) -> &ArcDesc {
    match &n.element.pieces[0] {
        ExactPiece::Arc(a) => a,
        _ => panic!("not an arc"),
    }
}

fn on_circle(a: &ArcDesc, u: &V2<Rational>) -> V2<Rational> {
    // |u| = radius for the near arcs' direction vectors
    assert_eq!(u.norm2(), &a.radius * &a.radius);
    a.center.add(u)
}

#[test]
fn a_rounded_corner_keeps_its_radius_and_moves_the_next_piece() {
    // Lucide's `component`: a corner of radius 1 whose chord is 1.414, not √2
    let d = "M2.297 11.293a1 1 0 0 0 0 1.414l2.377 2.377";
    let (n, pieces) = near_of(d, 0);
    let a = arc_of(&n);
    assert_eq!(a.radius, q("1"), "the radius is kept");
    // sweep 0: the arc runs clockwise, so `to` is its start
    assert_eq!(on_circle(a, &a.to), V2::new(q("2.297"), q("11.293")));
    let end = on_circle(a, &a.from);
    assert_ne!(end, V2::new(q("2.297"), q("12.707")));
    // the segment after it starts where the near arc ends, ends as before
    assert_eq!(n.element.pieces.len(), 2);
    let ExactPiece::Bezier(l) = &n.element.pieces[1] else {
        panic!("the moved segment")
    };
    assert_eq!(l.points()[0], end);
    assert_eq!(l.points()[1], V2::new(q("4.674"), q("15.084")));
    assert_eq!(
        n.element.count,
        pieces.len(),
        "the arc's cubics and the segment"
    );
    let b = check_bound(&n, (2.297, 11.293), (2.297, 12.707), 1.0, false, false);
    // the segment moved by at most the bound
    let (e, p) = (pt(&end), (2.297, 12.707));
    assert!((e.0 - p.0).hypot(e.1 - p.1) <= b);
}

#[test]
fn an_arc_at_the_end_of_a_path_keeps_its_end_points() {
    let d = "M0 0 l1 1 a1 1 0 0 1 1.414 0";
    let (n, pieces) = near_of(d, 0);
    let a = arc_of(&n);
    assert_ne!(a.radius, q("1"), "the radius cannot be kept");
    assert_eq!(n.element.pieces.len(), 1);
    assert_eq!(n.element.first + n.element.count, pieces.len());
    // sweep 1: counter-clockwise from the start to the end
    assert_eq!(on_circle(a, &a.from), V2::new(q("1"), q("1")));
    assert_eq!(on_circle(a, &a.to), V2::new(q("2.414"), q("1")));
    // the smaller radius is preferred
    assert!(a.radius < q("1"));
    check_bound(&n, (1.0, 1.0), (2.414, 1.0), 1.0, false, true);
}

#[test]
fn consecutive_arcs_chain_and_the_path_stays_connected() {
    let d = "M0 0a1 1 0 0 0 1.414 0a1 1 0 0 0 1.414 0l1 0";
    let (pieces, approx) = parse_svg_path_reported(d).unwrap();
    let n: Vec<NearElement> = approx
        .elements
        .iter()
        .map(|e| e.near.clone().unwrap())
        .collect();
    let (a, b) = (arc_of(&n[0]), arc_of(&n[1]));
    assert_eq!((&a.radius, &b.radius), (&q("1"), &q("1")));
    // the first ends where the second begins (sweep 0: `from` is the end)
    assert_eq!(on_circle(a, &a.from), on_circle(b, &b.to));
    assert_eq!(n[0].element.pieces.len(), 1);
    assert_eq!(
        n[1].element.pieces.len(),
        2,
        "the last arc moves the segment"
    );
    check_bound(&n[0], (0.0, 0.0), (1.414, 0.0), 1.0, false, false);
    // the second's bound includes its moved start
    check_bound(&n[1], (1.414, 0.0), (2.828, 0.0), 1.0, false, false);
    let (path, rest) = exact_path(&pieces, &approx).expect("an exact path");
    assert_eq!(path.len(), 3);
    for w in path.windows(2) {
        assert_eq!(w[0].end(), w[1].start());
    }
    assert_eq!(rest.elements.len(), 2);
    assert!(rest.elements.iter().all(|e| e.kind == ApproxKind::NearArc));
    assert!(rest.summary().unwrap().contains(
        "2 SVG arc(s) with an irrational centre replaced by arcs with a rational centre and radius"
    ));
}

#[test]
fn an_arc_that_closes_its_subpath_keeps_it_closed() {
    // the arc ends at the subpath's start; the next piece begins a subpath
    for d in [
        "M0 0 L2 0 A1.1 1.1 0 0 1 0 0 z",
        "M0 0 L2 0 A1.1 1.1 0 0 1 0 0 M0 0 l0 1",
    ] {
        let (n, _) = near_of(d, 0);
        let a = arc_of(&n);
        assert_eq!(n.element.pieces.len(), 1, "{d}");
        assert_eq!(on_circle(a, &a.from), V2::new(q("2"), q("0")), "{d}");
        assert_eq!(on_circle(a, &a.to), V2::new(q("0"), q("0")), "{d}");
        check_bound(&n, (2.0, 0.0), (0.0, 0.0), 1.1, false, true);
    }
}

#[test]
fn rational_centres_and_ellipses_have_no_near_arc() {
    let (_, a) = parse_svg_path_reported("M0 0 a1 1 0 0 1 2 0").unwrap();
    assert!(a.elements[0].exact.is_some() && a.elements[0].near.is_none());
    let (_, a) = parse_svg_path_reported("M0 0 a1 2 0 0 1 1.5 0").unwrap();
    assert!(a.elements[0].exact.is_none() && a.elements[0].near.is_none());
}

#[test]
fn near_arcs_follow_transforms() {
    // a similarity with a rational scale keeps them (the bound scaled);
    // an irrational rotation drops them (the cubics stay)
    let doc = |t: &str| {
        format!(
            r#"<svg><path transform="{t}" d="M2.297 11.293a1 1 0 0 0 0 1.414l2.377 2.377"/></svg>"#
        )
    };
    let (_, plain) = parse_curve_reported(&doc("translate(0)")).unwrap();
    let (_, scaled) = parse_curve_reported(&doc("scale(2)")).unwrap();
    let (b1, b2) = (
        plain.elements[0].near.as_ref().unwrap().bound,
        scaled.elements[0].near.as_ref().unwrap().bound,
    );
    assert!(
        b2 >= 2.0 * b1 && b2 <= 2.0 * b1 * (1.0 + 1e-12),
        "{b1} {b2}"
    );
    let ExactPiece::Arc(a) = &scaled.elements[0].near.as_ref().unwrap().element.pieces[0] else {
        panic!()
    };
    assert_eq!(a.radius, q("2"));
    let (_, rotated) = parse_curve_reported(&doc("rotate(30)")).unwrap();
    assert!(rotated.elements.iter().all(|e| e.near.is_none()));
}

#[test]
fn the_stroke_of_near_arcs_is_built_exactly_and_proven() {
    // Lucide's `component` (one diamond) and `layers` (two sides): rounded
    // corners of radius 1 = the pen's, chords rounded to three decimals
    for d in [
        "M2.297 11.293a1 1 0 0 0 0 1.414l2.377 2.377a1 1 0 0 0 1.414 0l2.377-2.377a1 1 0 0 0 0-1.414L6.088 8.916a1 1 0 0 0-1.414 0z",
        "M2 12a1 1 0 0 0 .58.91l8.6 3.91a2 2 0 0 0 1.65 0l8.58-3.9A1 1 0 0 0 22 12",
        // chords 1.415: the pen circles about each corner's ends cross
        // exactly at its (near) centre, a rational crossing of two circles
        "M8.916 17.912a1 1 0 0 0 0 1.415l2.377 2.376a1 1 0 0 0 1.414 0l2.377-2.376a1 1 0 0 0 0-1.415l-2.377-2.376a1 1 0 0 0-1.414 0z",
    ] {
        let doc = format!("<svg><path d=\"{d}\"/></svg>");
        let (pieces, approx) = parse_curve_reported(&doc).unwrap();
        let (path, rest) = exact_path(&pieces, &approx).expect("an exact path");
        assert!(path.iter().any(|p| matches!(p, PathPiece::Arc(_))));
        assert!(rest.bound() <= 1e-9, "{d}: {}", rest.bound());
        let opts = StrokeOptions::new(q("1"), "1e-2".parse().unwrap());
        let s = stroke_path(&path, &opts).unwrap();
        assert!(s.proven(), "{d}: {:?}", s.notes);
        assert!(s.notes.iter().any(|n| n.contains("built exactly")), "{d}: {:?}", s.notes);
        // independently: every outline sample is within TOL (and the near
        // arcs' and the cubics' bounds) of ∂S as the reader's certified
        // cubic pieces give the input, sampled densely
        let input: Vec<(f64, f64)> = pieces
            .iter()
            .flat_map(|b| crate::stroke::Piece::Bezier(b.clone()).sample(400))
            .collect();
        crate::test_util::outline_near_boundary(&s, &input, 1.0, 1e-2 + 1e-6, d);
    }
}
