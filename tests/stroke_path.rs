//! Strokes of exact paths with circular arcs (`stroke_path`): claims (a) and
//! (b) proven against the exact arcs by a certificate the independent
//! verifier accepts, checked here against sampled distances to the exact
//! arcs (computed directly from the circle, not by the engine).

use lncert::certify::verify::verify;
use lncert::stroke::{parse_path, stroke_path, PathPiece, Piece, StrokeOptions};
use lncert::{parse_rational, Rational};

fn opts(r: &str, tol: &str) -> StrokeOptions {
    StrokeOptions::new(parse_rational(r).unwrap(), tol.parse().unwrap())
}

/// Distance from `p` to the exact path, sampled densely (arcs by angle,
/// Béziers by parameter): an upper bound of the true distance that is
/// within the sampling step of it.
fn dist_to_path(path: &[PathPiece], p: (f64, f64)) -> f64 {
    let mut best = f64::INFINITY;
    for piece in path {
        match piece {
            PathPiece::Arc(a) => {
                let c = (
                    lncert::scalar::Scalar::approx(&a.center.x),
                    lncert::scalar::Scalar::approx(&a.center.y),
                );
                let rho = lncert::scalar::Scalar::approx(&a.radius);
                let ang = |q: &lncert::curve::V2<Rational>| {
                    (lncert::scalar::Scalar::approx(&q.y) - c.1)
                        .atan2(lncert::scalar::Scalar::approx(&q.x) - c.0)
                };
                let (t0, t1) = (ang(&a.from), ang(&a.to));
                let tau = std::f64::consts::TAU;
                let mut sweep = if a.clockwise {
                    -(t0 - t1).rem_euclid(tau)
                } else {
                    (t1 - t0).rem_euclid(tau)
                };
                if sweep == 0.0 {
                    sweep = tau;
                }
                for k in 0..=4000 {
                    let t = t0 + sweep * k as f64 / 4000.0;
                    let q = (c.0 + rho * t.cos(), c.1 + rho * t.sin());
                    best = best.min((q.0 - p.0).hypot(q.1 - p.1));
                }
            }
            PathPiece::Bezier(b) => {
                let f = b.map(lncert::scalar::Scalar::approx);
                for k in 0..=4000 {
                    let q = f.eval_fast(k as f64 / 4000.0);
                    best = best.min((q.x - p.0).hypot(q.y - p.1));
                }
            }
        }
    }
    best
}

fn check_proven(src: &str, r: &str, tol: &str) -> (Vec<PathPiece>, lncert::stroke::Stroke) {
    let (path, rest) = parse_path(src).unwrap();
    assert!(rest.is_empty(), "{src}: everything exact");
    assert!(path.iter().any(|p| matches!(p, PathPiece::Arc(_))));
    let s = stroke_path(&path, &opts(r, tol)).unwrap();
    assert!(s.proven(), "{src}: {:?} {:?} {:?}", s.a, s.b, s.c);
    let cert = s.certificate.as_ref().expect("proven by a certificate");
    let v = verify(&cert.to_string()).expect("the verifier accepts it");
    let tolf: f64 = tol.parse().unwrap();
    assert!(v.max_bound <= tolf && s.a.bound <= tolf && s.b.bound <= tolf);
    // the certificate states the exact arcs
    let text = cert.to_string();
    assert!(text.contains("\"arc\""), "the curve holds exact arcs");
    // every outline point is at distance r from the exact path, within tol
    // (sampled independently of the engine: the sampled distance is an upper
    // bound, off by at most the sampling step, far below tol here)
    let rf: f64 = r.parse().unwrap_or_else(|_| {
        let q = parse_rational(r).unwrap();
        lncert::scalar::Scalar::approx(&q)
    });
    for c in &s.contours {
        for piece in &c.pieces {
            for q in piece.sample(16) {
                let d = dist_to_path(&path, q);
                assert!(
                    (d - rf).abs() <= tolf + 1e-3 * tolf.max(1e-9) + 5e-6,
                    "{src}: outline point {q:?} at {d} from the path, r = {rf}"
                );
            }
        }
    }
    (path, s)
}

#[test]
fn rounded_rect_circle_and_arc_paths_are_proven_against_the_exact_arcs() {
    // a rounded rect: four lines, four quarter arcs; a pen narrower than the
    // corners (two contours) and one wider (the inner corners sharp)
    let rect = r#"<svg><rect x="0" y="0" width="10" height="6" rx="2"/></svg>"#;
    let (_, s) = check_proven(rect, "1", "1e-2");
    assert_eq!(s.contours.len(), 2);
    let (_, s) = check_proven(rect, "5/2", "1e-2");
    assert_eq!(s.contours.len(), 2);
    // a circle: two concentric circles
    let (_, s) = check_proven(r#"<svg><circle cx="1" cy="2" r="3"/></svg>"#, "1/2", "1e-3");
    assert_eq!(s.contours.len(), 2);
    // an open path of a half circle and a line, and an S of two arcs
    let (_, s) = check_proven("M 2 0 A 2 2 0 0 1 -2 0 L -2 -3", "1/2", "1e-2");
    assert_eq!(s.contours.len(), 1);
    check_proven("M 0 0 A 1 1 0 0 1 2 0 A 1 1 0 0 0 4 0", "1/4", "1e-2");
    // the icon "arc path" (two 270° arcs of one centre, two lines), and a
    // closed path of a line, a quarter arc and a cubic
    let (_, s) = check_proven("M12 2a10 10 0 1 0 10 10h-4a6 6 0 1 1-6-6z", "1", "1e-2");
    assert_eq!(s.contours.len(), 2);
    let (_, s) = check_proven("M 0 0 L 4 0 A 2 2 0 0 1 6 2 C 6 4 4 6 2 6 Z", "1/2", "1e-2");
    assert_eq!(s.contours.len(), 2);
}

#[test]
fn a_path_with_a_cubic_is_the_plain_stroke_and_a_polyline_is_exact() {
    // a cubic: the general construction, its claims proven without a certificate
    let (path, _) = parse_path("M 0 0 L 4 0 C 5 1 5 2 4 3").unwrap();
    let s = stroke_path(&path, &opts("1", "1e-2")).unwrap();
    assert!(s.proven() && s.certificate.is_none());
    // segments only: constructed exactly, the offsets are straight segments
    // and the caps and join arcs of the pen's circle, proven by the
    // certificate
    let (path, _) = parse_path("M 0 0 L 4 0 L 4 3").unwrap();
    let s = stroke_path(&path, &opts("1", "1e-2")).unwrap();
    assert!(s.proven() && s.certificate.is_some());
    assert_eq!(s.contours.len(), 1);
    let one = lncert::parse_rational("1").unwrap();
    for p in s.contours.iter().flat_map(|c| &c.pieces) {
        match p {
            Piece::Bezier(b) => assert_eq!(b.points().len(), 2),
            Piece::Arc(a) => assert_eq!(a.radius, one),
        }
    }
}

#[test]
fn the_exact_certificate_is_not_about_the_approximation_alone() {
    // The outline is proven within tol/2 of the approximation's ∂S; a
    // certificate stating other arcs must not pass.
    let (path, s) = check_proven(r#"<svg><circle cx="0" cy="0" r="3"/></svg>"#, "1/2", "1e-3");
    let cert: serde_json::Value = s.certificate.as_ref().unwrap().as_ref().clone();
    // every input arc scaled about the centre by k (ends stay exactly on the
    // scaled circle): refused for k = 1 + 1/100 (∂S moves by 0.03 > tol),
    // accepted for k = 1 (the edit itself changes nothing)
    let scaled = |k: Rational| {
        let mut c = cert.clone();
        let mut n = 0;
        for piece in c["curve"].as_array_mut().unwrap() {
            let Some(arc) = piece.get_mut("arc") else {
                continue;
            };
            n += 1;
            let q = |v: &serde_json::Value| parse_rational(v.as_str().unwrap()).unwrap();
            let s = |x: Rational| serde_json::Value::String(lncert::scalar::rational_to_string(&x));
            arc["radius"] = s(q(&arc["radius"]) * &k);
            for key in ["from", "to"] {
                let p = arc[key].as_array().unwrap().clone();
                arc[key] = serde_json::json!([s(q(&p[0]) * &k), s(q(&p[1]) * &k)]);
            }
        }
        assert_eq!(n, 4, "the circle is four quarter arcs");
        c.to_string()
    };
    assert!(verify(&scaled(parse_rational("1").unwrap())).is_ok());
    let e = verify(&scaled(parse_rational("101/100").unwrap())).unwrap_err();
    assert!(
        e.at.starts_with("cover") || e.at.starts_with("boundary"),
        "refused at a part or a box: {} {}",
        e.at,
        e.reason
    );
    // and the writer does not certify this outline for another circle
    let other = r#"<svg><circle cx="0" cy="0" r="3.03"/></svg>"#;
    let (path2, _) = parse_path(other).unwrap();
    assert_ne!(path, path2);
    let c2 = lncert::stroke::certificate_path(&path2, &s, &parse_rational("1/2").unwrap());
    assert!(
        c2.is_err(),
        "no certificate of this outline for another circle"
    );
}

#[test]
fn arcs_with_an_elliptical_pen_are_refused_with_a_named_field() {
    let (path, _) = parse_path("M 2 0 A 2 2 0 0 1 -2 0").unwrap();
    let pen = lncert::offset::Pen::ellipse(
        &parse_rational("1").unwrap(),
        &parse_rational("1/2").unwrap(),
        &lncert::offset::Angle::parse("0").unwrap(),
    )
    .unwrap();
    let o = StrokeOptions::with_pen(
        lncert::stroke::PenShape::Ellipse(pen),
        "1e-2".parse().unwrap(),
    );
    let e = stroke_path(&path, &o).unwrap_err();
    assert_eq!(e.field, "pen");
}

#[test]
fn verify_against_compares_the_exact_curve() {
    // B is the user's exact shape (lines and arcs as read), A the outline;
    // the certificate states the arcs split in quarters, in the path's
    // order and direction: the same point set
    for (src, r) in [
        (
            r#"<svg><rect x="0" y="0" width="10" height="6" rx="2"/></svg>"#,
            "1",
        ),
        (r#"<svg><circle cx="1" cy="2" r="3"/></svg>"#, "1/2"),
        ("M12 2a10 10 0 1 0 10 10h-4a6 6 0 1 1-6-6z", "1"),
        ("M 2 0 A 2 2 0 0 0 -2 0 L -2 3", "1/2"),
    ] {
        let (_, s) = check_proven(src, r, "1e-2");
        let text = s.certificate.as_ref().unwrap().to_string();
        let outline = s.outline_shape().unwrap();
        let (b, rest) = lncert::shape::ShapeDesc::parse_reported(src).unwrap();
        assert!(rest.is_empty());
        lncert::certify::verify_against(&text, &outline, &b)
            .unwrap_or_else(|e| panic!("{src}: {} {}", e.at, e.reason));
    }
    // another rect, another circle: refused at the curve
    let (_, s) = check_proven(r#"<svg><circle cx="1" cy="2" r="3"/></svg>"#, "1/2", "1e-2");
    let text = s.certificate.as_ref().unwrap().to_string();
    let outline = s.outline_shape().unwrap();
    for other in [
        r#"<svg><circle cx="1" cy="2" r="3.5"/></svg>"#,
        r#"<svg><circle cx="1" cy="2.5" r="3"/></svg>"#,
        "M 4 2 A 3 3 0 0 1 -2 2",
    ] {
        let (b, _) = lncert::shape::ShapeDesc::parse_reported(other).unwrap();
        let e = lncert::certify::verify_against(&text, &outline, &b).unwrap_err();
        assert_eq!(e.at, "curve", "{other}: {}", e.reason);
    }
}

#[test]
fn butt_caps_keep_the_claims_unmade() {
    let (path, _) = parse_path("M 2 0 A 2 2 0 0 1 -2 0").unwrap();
    let mut o = opts("1/2", "1e-2");
    o.cap = lncert::stroke::Cap::Butt;
    let s = stroke_path(&path, &o).unwrap();
    assert!(s.c.proven && !s.a.proven && s.certificate.is_none());
    assert!(s.a.note.contains("not claimed"), "{}", s.a.note);
}
