//! Tests of the exact circular elements: centres against SVG's own centre
//! construction in floats (F.6.5, F.6.6, written out here independently),
//! and the exact shapes against the certified cubic approximations.

use super::*;
use crate::certify::{hausdorff, Config};
use crate::scalar::Scalar;
use crate::shape::{parse_svg_document_reported, parse_svg_path_reported};
use crate::test_util::q;
use crate::tolerance::Tolerance;
use std::f64::consts::{PI, TAU};

fn f(x: &Rational) -> f64 {
    x.approx()
}

/// SVG 1.1 F.6.5/F.6.6 in floats: the centre, the corrected radius and the
/// signed sweep `Δθ` of `A rx ry φ large sweep p1` from `p0`.
fn svg_centre(
    p0: (f64, f64),
    p1: (f64, f64),
    (rx, ry, phi): (f64, f64, f64),
    large: bool,
    sweep: bool,
) -> ((f64, f64), f64, f64) {
    let (c, s) = (phi.cos(), phi.sin());
    let (hx, hy) = ((p0.0 - p1.0) / 2.0, (p0.1 - p1.1) / 2.0);
    let (x1, y1) = (c * hx + s * hy, -s * hx + c * hy);
    let (mut rx, mut ry) = (rx.abs(), ry.abs());
    let lambda = x1 * x1 / (rx * rx) + y1 * y1 / (ry * ry);
    if lambda > 1.0 {
        rx *= lambda.sqrt();
        ry *= lambda.sqrt();
    }
    let num = rx * rx * ry * ry - rx * rx * y1 * y1 - ry * ry * x1 * x1;
    let den = rx * rx * y1 * y1 + ry * ry * x1 * x1;
    let mut k = (num / den).max(0.0).sqrt();
    if large == sweep {
        k = -k;
    }
    let (cx1, cy1) = (k * rx * y1 / ry, -k * ry * x1 / rx);
    let centre = (
        c * cx1 - s * cy1 + (p0.0 + p1.0) / 2.0,
        s * cx1 + c * cy1 + (p0.1 + p1.1) / 2.0,
    );
    let angle = |ux: f64, uy: f64| uy.atan2(ux);
    let t1 = angle((x1 - cx1) / rx, (y1 - cy1) / ry);
    let t2 = angle((-x1 - cx1) / rx, (-y1 - cy1) / ry);
    let mut dt = (t2 - t1) % TAU;
    if !sweep && dt > 0.0 {
        dt -= TAU;
    }
    if sweep && dt < 0.0 {
        dt += TAU;
    }
    (centre, rx, dt)
}

/// The counter-clockwise angle from direction `a` to direction `b`, in `(0, 2π]`.
fn ccw(a: &V2<Rational>, b: &V2<Rational>) -> f64 {
    let t = (f(&b.y).atan2(f(&b.x)) - f(&a.y).atan2(f(&a.x))).rem_euclid(TAU);
    if t == 0.0 {
        TAU
    } else {
        t
    }
}

/// A deterministic xorshift generator of integers in `[−m, m]`.
fn xorshift(mut seed: u64) -> impl FnMut(i64) -> i64 {
    move |m: i64| {
        seed ^= seed << 13;
        seed ^= seed >> 7;
        seed ^= seed << 17;
        (seed % (2 * m as u64 + 1)) as i64 - m
    }
}

/// A rational `p/q`, `|p| ≤ num`, `1 ≤ q ≤ den + 1`.
fn ratio(next: &mut impl FnMut(i64) -> i64, num: i64, den: i64) -> Rational {
    Rational::new(next(num).into(), (1 + next(den).abs()).into())
}

/// A rational point of the circle about `c` of radius `r`: the direction
/// `((1 − t²), 2t)/(1 + t²)` (every rational point but `(−1, 0)`).
fn on_circle(c: &V2<Rational>, r: &Rational, t: &Rational) -> V2<Rational> {
    let one = <Rational as One>::one();
    let d = &one + t * t;
    V2::new(
        &c.x + r * (&one - t * t) / &d,
        &c.y + r * Rational::from_integer(2.into()) * t / &d,
    )
}

/// Arcs between rational points of a circle with a rational centre: all
/// four flag choices are exact, with the centre, radius and sweep of SVG's
/// own construction (in floats), for any `φ` (a circle has no axis).
#[test]
fn circular_arcs_have_the_centre_and_sweep_of_svg() {
    let mut next = xorshift(0x2545_F491_4F6C_DD1Du64);
    let mut checked = 0;
    for _ in 0..60 {
        let c = V2::new(ratio(&mut next, 50, 9), ratio(&mut next, 50, 9));
        let r = Rational::new((1 + next(40).abs()).into(), (1 + next(6).abs()).into());
        let (t0, t1) = (ratio(&mut next, 20, 7), ratio(&mut next, 20, 7));
        if t0 == t1 {
            continue;
        }
        let (p0, p1) = (on_circle(&c, &r, &t0), on_circle(&c, &r, &t1));
        let phi = next(180) as f64 * PI / 180.0;
        for (large, sweep) in [(false, false), (false, true), (true, false), (true, true)] {
            let a = circular_svg_arc(&p0, &p1, &r, large, sweep)
                .unwrap_or_else(|| panic!("{p0:?} {p1:?} r {r}: not exact"));
            let (centre, radius, dt) = svg_centre(
                (f(&p0.x), f(&p0.y)),
                (f(&p1.x), f(&p1.y)),
                (f(&r), f(&r), phi),
                large,
                sweep,
            );
            // (the float construction loses half the digits for a chord
            // near a diameter: √ of a difference near 0)
            let scale = 1e3 * (1.0 + f(&r) + f(&c.x).abs() + f(&c.y).abs());
            assert!(
                (f(&a.center.x) - centre.0).abs() < 1e-9 * scale,
                "{a:?} {centre:?}"
            );
            assert!(
                (f(&a.center.y) - centre.1).abs() < 1e-9 * scale,
                "{a:?} {centre:?}"
            );
            assert!((f(&a.radius) - radius).abs() < 1e-9 * scale);
            // the arc is exactly on its circle: both end points at the radius
            for p in [&p0, &p1] {
                assert_eq!(p.sub(&a.center).norm2(), &a.radius * &a.radius);
            }
            // the same sweep: |Δθ| counter-clockwise from `from` to `to`
            assert!((ccw(&a.from, &a.to) - dt.abs()).abs() < 1e-7, "{a:?} {dt}");
            // and the arc starts at p0 when it runs counter-clockwise
            let start = if sweep { &p0 } else { &p1 };
            assert!(a.from.cross(&start.sub(&a.center)).is_zero());
            checked += 1;
        }
    }
    assert!(checked >= 200, "{checked}");
}

/// Irrational centres and radii are not exact; a radius below half a
/// rational chord is enlarged to it exactly (SVG F.6.6).
#[test]
fn irrational_circles_are_not_exact() {
    let p = |x: &str, y: &str| V2::new(q(x), q(y));
    // h² = 1 − 1/4 = 3/4
    assert!(circular_svg_arc(&p("0", "0"), &p("1", "0"), &q("1"), false, true).is_none());
    // enlarged to |d|/2 = √2/2
    assert!(circular_svg_arc(&p("0", "0"), &p("1", "1"), &q("1/2"), false, true).is_none());
    // enlarged to |d|/2 = 5/2, centre the midpoint; a negative radius is its magnitude
    let a = circular_svg_arc(&p("0", "0"), &p("3", "4"), &q("-1"), true, false).unwrap();
    assert_eq!((a.center, a.radius), (p("3/2", "2"), q("5/2")));
    // quarter circle: h² = 1/2 − 1/4
    let a = circular_svg_arc(&p("12", "2"), &p("22", "12"), &q("10"), true, false).unwrap();
    assert_eq!(a.center, p("12", "12"));
    assert!((ccw(&a.from, &a.to) - 1.5 * PI).abs() < 1e-12);
    assert_eq!(rational_sqrt(&q("9/16")), Some(q("3/4")));
    assert_eq!(rational_sqrt(&q("2")), None);
    assert_eq!(rational_sqrt(&q("-4")), None);
}

/// The exact shape of a document, against its certified cubic
/// approximation (a separate construction and proof): `d_H` is at most the
/// reported bound, so the certified lower bound cannot exceed it, and a
/// wrong centre, sweep or piece range would put `d_H` at the radius' scale.
#[test]
fn exact_shapes_are_within_the_approximations_bound() {
    let docs = [
        r#"<svg><circle cx="12" cy="12" r="3"/></svg>"#,
        r#"<svg><ellipse cx="1" cy="-2" rx="5" ry="5"/><path d="M 0 0 L 1 0"/></svg>"#,
        r#"<svg><path d="M 0 0 L 1 0"/><rect x="3" y="3" width="18" height="10" rx="1.5"/></svg>"#,
        r#"<svg><path d="M12 2a10 10 0 1 0 10 10h-4a6 6 0 1 1-6-6z"/></svg>"#,
        r#"<svg><g transform="rotate(90 1 1) scale(-2 2) translate(1 0)"><path d="M 0 0 A 2 2 0 0 1 4 0 L 5 1"/></g></svg>"#,
        r#"<svg><g transform="matrix(0.6 0.8 -0.8 0.6 3 4)"><rect width="4" height="2" rx="1"/><circle r="1"/></g></svg>"#,
        // ellipses, unequal corners, arcs at 90° and 180°, non-similar maps
        r#"<svg><ellipse cx="12" cy="12" rx="8" ry="4"/><rect x="1" y="1" width="10" height="6" rx="2" ry="1"/></svg>"#,
        r#"<svg><path d="M 0 0 A 2 1 90 0 1 0 4 A 3 1 180 1 0 6 4"/></svg>"#,
        r#"<svg><g transform="scale(2 3) skewX(45)"><circle cx="1" cy="1" r="1"/><path d="M 0 0 A 2 1 0 0 0 4 0"/></g></svg>"#,
        r#"<svg><g transform="matrix(1 2 -3 1 0 0) rotate(90)"><ellipse rx="2" ry="3"/></g></svg>"#,
        // a rotated ellipse's arc (M not diagonal) under a shear
        r#"<svg><g transform="matrix(1 2 -3 1 5 0)"><path d="M 0 0 A 2 1 90 0 1 0 4"/></g></svg>"#,
    ];
    for doc in docs {
        let (pieces, approx) = parse_svg_document_reported(doc).unwrap();
        let bound = approx.bound();
        let (shape, rest) = ShapeDesc::parse_reported(doc).unwrap();
        assert!(rest.is_empty(), "{doc}: {rest:?}");
        assert!(shape.piece_count() < pieces.len(), "{doc}: no arcs");
        let cubic = ShapeDesc::curve(pieces).unwrap();
        // (proving d_H ≤ 2·bound ≈ 10⁻⁷ takes seconds; 10⁻³ catches any
        // wrong centre, sweep or piece, which are off at the radius' scale)
        let cfg = Config {
            tol: Some(Tolerance::from_f64(1e-3).unwrap()),
            ..Config::default()
        };
        let d = hausdorff(&shape, &cubic, &cfg).unwrap();
        assert!(d.lo <= bound, "{doc}: {} > {bound}", d.lo);
        assert!(d.hi <= 1e-3, "{doc}: {} not ≤ 1e-3", d.hi);
    }
}

/// What stays approximated: arcs whose (pre-image) centre or enlarged
/// radius is irrational, rotations `φ` of an ellipse that are not multiples
/// of 90° (irrational cosine and sine).
#[test]
fn irrational_arcs_stay_approximated() {
    for doc in [
        r#"<svg><path d="M 0 0 A 1 1 0 0 1 1 0"/></svg>"#,
        r#"<svg><path d="M 0 0 A 2 1 30 0 1 3 1"/></svg>"#,
        r#"<svg><path d="M 0 0 A 2 1 0 0 1 1 1"/></svg>"#,
        r#"<svg><g transform="scale(2 3)"><path d="M 0 0 A 0.1 0.1 0 0 1 1 1"/></g></svg>"#,
    ] {
        let (pieces, approx) = parse_svg_document_reported(doc).unwrap();
        let (shape, rest) = ShapeDesc::parse_reported(doc).unwrap();
        assert_eq!(rest, approx, "{doc}");
        let ShapeDesc::Curve(c) = shape else {
            panic!("{doc}: {shape:?}")
        };
        assert_eq!(c, pieces);
    }
    // an irrational rotation: the circle is exact under the rational
    // rotation, whose displacement stays reported
    let doc = r#"<svg><g transform="rotate(30)"><circle cx="1" r="1"/></g></svg>"#;
    let (shape, rest) = ShapeDesc::parse_reported(doc).unwrap();
    assert!(matches!(shape, ShapeDesc::Union(ref m) if m.len() == 2));
    assert_eq!(rest.elements.len(), 1);
    assert_eq!(rest.elements[0].kind, super::super::ApproxKind::Rotation);
    // a circle under a map that is not a similarity is an elliptic arc
    let doc = r#"<svg><g transform="scale(2 3)"><circle r="1"/></g></svg>"#;
    let (shape, rest) = ShapeDesc::parse_reported(doc).unwrap();
    assert!(rest.is_empty());
    let ShapeDesc::Union(m) = shape else {
        panic!("{shape:?}")
    };
    let ShapeDesc::EllipseArc(e) = &m[0] else {
        panic!("{m:?}")
    };
    assert_eq!(e.matrix, [[q("2"), q("0")], [q("0"), q("3")]]);
}

/// Elliptic arcs between rational points of an axis-aligned (up to a
/// quarter turn) ellipse with a rational centre: the centre, the radii and
/// the sweep of SVG's construction (in floats), for all four flags.
#[test]
fn elliptic_arcs_have_the_centre_and_sweep_of_svg() {
    let mut next = xorshift(0x9E37_79B9_7F4A_7C15u64);
    let mut checked = 0;
    for i in 0..60 {
        let c = V2::new(ratio(&mut next, 50, 9), ratio(&mut next, 50, 9));
        let rx = Rational::new((1 + next(40).abs()).into(), (1 + next(6).abs()).into());
        let ry = Rational::new((1 + next(40).abs()).into(), (1 + next(6).abs()).into());
        if rx == ry {
            continue;
        }
        let deg = 90 * (i % 4);
        let (cs, sn) = [(1, 0), (0, 1), (-1, 0), (0, -1)][i as usize % 4];
        let (t0, t1) = (ratio(&mut next, 20, 7), ratio(&mut next, 20, 7));
        if t0 == t1 {
            continue;
        }
        // p = c + R(φ) diag(rx, ry) u, u a rational point of the unit circle
        let z = V2::new(<Rational as Zero>::zero(), <Rational as Zero>::zero());
        let at = |t: &Rational| {
            let u = on_circle(&z, &<Rational as One>::one(), t);
            let (x, y) = (&rx * &u.x, &ry * &u.y);
            let (cs, sn) = (
                Rational::from_integer(cs.into()),
                Rational::from_integer(sn.into()),
            );
            V2::new(&c.x + &cs * &x - &sn * &y, &c.y + &sn * &x + &cs * &y)
        };
        let (p0, p1) = (at(&t0), at(&t1));
        let phi = Rational::from_integer((deg as i64 + 360 * next(2)).into());
        for (large, sweep) in [(false, false), (false, true), (true, false), (true, true)] {
            let Some(ExactPiece::EllipseArc(a)) =
                svg_exact_arc(&p0, &p1, [&rx, &ry, &phi], large, sweep)
            else {
                panic!("{p0:?} {p1:?} {rx} {ry} {phi}: not exact")
            };
            let (centre, rxc, dt) = svg_centre(
                (f(&p0.x), f(&p0.y)),
                (f(&p1.x), f(&p1.y)),
                (f(&rx), f(&ry), f(&phi) * PI / 180.0),
                large,
                sweep,
            );
            let scale = 1e3 * (1.0 + f(&rx) + f(&ry) + f(&c.x).abs() + f(&c.y).abs());
            assert!(
                (f(&a.center.x) - centre.0).abs() < 1e-9 * scale,
                "{a:?} {centre:?}"
            );
            assert!(
                (f(&a.center.y) - centre.1).abs() < 1e-9 * scale,
                "{a:?} {centre:?}"
            );
            // the first column of M is R(φ) (rx·s, 0): its length is the corrected rx
            let col = (f(&a.matrix[0][0]).hypot(f(&a.matrix[1][0])) - rxc).abs();
            assert!(col < 1e-9 * scale, "{a:?} {rxc}");
            assert!((ccw(&a.from, &a.to) - dt.abs()).abs() < 1e-7, "{a:?} {dt}");
            // both end points exactly on the arc's ellipse: c + M u / |u| = p
            let m = &a.matrix;
            let (s0, s1) = if sweep { (&p0, &p1) } else { (&p1, &p0) };
            for (p, u) in [(s0, &a.from), (s1, &a.to)] {
                // M⁻¹ (p − c) is parallel to u, of length 1
                let d = p.sub(&a.center);
                let det = &m[0][0] * &m[1][1] - &m[0][1] * &m[1][0];
                let w = V2::new(
                    (&m[1][1] * &d.x - &m[0][1] * &d.y) / &det,
                    (&m[0][0] * &d.y - &m[1][0] * &d.x) / &det,
                );
                assert_eq!(w.norm2(), <Rational as One>::one(), "{a:?}");
                assert!(w.cross(u).is_zero() && w.dot(u).is_positive(), "{a:?}");
            }
            checked += 1;
        }
    }
    assert!(checked >= 150, "{checked}");
}

/// Pieces keep their order: lines before, between and after the arcs, and
/// arcs of several path data commands and elements.
#[test]
fn members_follow_the_input_order() {
    let (pieces, _) =
        parse_svg_path_reported("M 0 0 L 1 0 A 1 1 0 0 1 3 0 L 4 0 L 4 1 A 1 1 0 0 0 4 3 Z")
            .unwrap();
    let (shape, _) =
        ShapeDesc::parse_reported("M 0 0 L 1 0 A 1 1 0 0 1 3 0 L 4 0 L 4 1 A 1 1 0 0 0 4 3 Z")
            .unwrap();
    let ShapeDesc::Union(m) = shape else {
        panic!("{shape:?}")
    };
    let kinds: Vec<String> = m
        .iter()
        .map(|s| match s {
            ShapeDesc::Curve(c) => format!("curve {}", c.len()),
            ShapeDesc::Arc(a) => format!("arc {}", a.radius),
            _ => "other".into(),
        })
        .collect();
    assert_eq!(kinds, ["curve 1", "arc 1", "curve 2", "arc 1", "curve 1"]);
    // the last line is the closing one, from (4, 3) to (0, 0)
    let ShapeDesc::Curve(last) = &m[4] else {
        unreachable!()
    };
    assert_eq!(last[0], *pieces.last().unwrap());
    // the sweep-0 arc from (4, 1) to (4, 3) runs counter-clockwise from (4, 3)
    let ShapeDesc::Arc(a) = &m[3] else {
        unreachable!()
    };
    assert_eq!(a.center, V2::new(q("4"), q("2")));
    assert_eq!(
        (a.from.clone(), a.to.clone()),
        (V2::new(q("0"), q("1")), V2::new(q("0"), q("-1")))
    );
}
