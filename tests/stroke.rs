//! Proven stroke outlines for a circular pen (issue 13): closure, simplicity,
//! orientation, and an independent dense-sampling check of claims (a), (b).

use lncert::curve::Bezier;
use lncert::outline::trim::{stroke, Cap, Orientation, Piece, Stroke, StrokeOptions};
use lncert::parse_rational;
use lncert::scalar::{Rational, Scalar};
use lncert::shape::parse_curve;

fn q(s: &str) -> Rational {
    parse_rational(s).unwrap()
}

fn test_cubic() -> Vec<Bezier<Rational>> {
    parse_curve(r#"{"bezier": [[-0.95, 0.7], [-0.3, 0.5], [0.3, -2.5], [0.9, -0.2]]}"#).unwrap()
}

/// Points along a piece (floats).
fn sample_piece(p: &Piece, n: usize) -> Vec<(f64, f64)> {
    match p {
        Piece::Bezier(b) => {
            let f = b.map(Scalar::approx);
            (0..=n)
                .map(|k| {
                    let v = f.eval_fast(k as f64 / n as f64);
                    (v.x, v.y)
                })
                .collect()
        }
        Piece::Arc(a) => {
            let c = (a.center.x.approx(), a.center.y.approx());
            let r = a.radius.approx();
            let u = (a.from.x.approx() - c.0, a.from.y.approx() - c.1);
            let v = (a.to.x.approx() - c.0, a.to.y.approx() - c.1);
            let t0 = u.1.atan2(u.0);
            let mut d = v.1.atan2(v.0) - t0;
            if a.clockwise {
                d = -(-d).rem_euclid(2.0 * std::f64::consts::PI);
            } else {
                d = d.rem_euclid(2.0 * std::f64::consts::PI);
            }
            (0..=n)
                .map(|k| {
                    let t = t0 + d * k as f64 / n as f64;
                    (c.0 + r * t.cos(), c.1 + r * t.sin())
                })
                .collect()
        }
    }
}

/// Distance from p to the curve by dense sampling and golden-section refinement.
fn dist_to_curve(curve: &[Bezier<f64>], p: (f64, f64)) -> f64 {
    let mut best = f64::INFINITY;
    for b in curve {
        let d2 = |t: f64| {
            let v = b.eval_fast(t);
            (v.x - p.0).powi(2) + (v.y - p.1).powi(2)
        };
        let n = 400;
        let (mut bt, mut bd) = (0.0, f64::INFINITY);
        for k in 0..=n {
            let t = k as f64 / n as f64;
            if d2(t) < bd {
                bd = d2(t);
                bt = t;
            }
        }
        let (mut lo, mut hi) = (
            (bt - 1.0 / n as f64).max(0.0),
            (bt + 1.0 / n as f64).min(1.0),
        );
        for _ in 0..60 {
            let m1 = lo + (hi - lo) * 0.382;
            let m2 = lo + (hi - lo) * 0.618;
            if d2(m1) < d2(m2) {
                hi = m2;
            } else {
                lo = m1;
            }
        }
        best = best.min(d2(0.5 * (lo + hi))).min(bd);
    }
    best.sqrt()
}

fn output_points(s: &Stroke, n: usize) -> Vec<(f64, f64)> {
    s.contours
        .iter()
        .flat_map(|c| c.pieces.iter().flat_map(|p| sample_piece(p, n)))
        .collect()
}

/// Points of the exact boundary: exact offset points x ± r N and cap points
/// whose sampled distance to x is ≥ r − small.
fn boundary_points(curve: &[Bezier<Rational>], r: f64, closed: bool) -> Vec<(f64, f64)> {
    let cf: Vec<Bezier<f64>> = curve.iter().map(|b| b.map(Scalar::approx)).collect();
    let mut cand = Vec::new();
    for b in &cf {
        let h = b.hodograph();
        for k in 0..=600 {
            let t = k as f64 / 600.0;
            let p = b.eval_fast(t);
            let d = h.eval_fast(t);
            let n = (-d.y / d.length(), d.x / d.length());
            for s in [r, -r] {
                cand.push((p.x + s * n.0, p.y + s * n.1));
            }
        }
    }
    if !closed {
        for (b, e) in [(&cf[0], 0.0), (&cf[cf.len() - 1], 1.0)] {
            let c = b.eval_fast(e);
            for k in 0..200 {
                let t = k as f64 / 200.0 * 2.0 * std::f64::consts::PI;
                cand.push((c.x + r * t.cos(), c.y + r * t.sin()));
            }
        }
    }
    cand.into_iter()
        .filter(|p| dist_to_curve(&cf, *p) >= r - 1e-9)
        .collect()
}

fn dist_to_points(pts: &[(f64, f64)], p: (f64, f64)) -> f64 {
    pts.iter()
        .map(|q| ((q.0 - p.0).powi(2) + (q.1 - p.1).powi(2)).sqrt())
        .fold(f64::INFINITY, f64::min)
}

/// The independent check of (a) and (b) by sampling; `slack` covers the
/// sampling density.
fn sampled_check(curve: &[Bezier<Rational>], s: &Stroke, r: f64, tol: f64, slack: f64) {
    let cf: Vec<Bezier<f64>> = curve.iter().map(|b| b.map(Scalar::approx)).collect();
    let out = output_points(s, 60);
    for p in &out {
        let d = dist_to_curve(&cf, *p);
        assert!(
            (d - r).abs() <= tol + 1e-9,
            "output point {p:?} at distance {d} from x (r = {r})"
        );
    }
    let dense = output_points(s, 400);
    for b in boundary_points(curve, r, s.closed_curve) {
        let d = dist_to_points(&dense, b);
        assert!(
            d <= tol + slack,
            "boundary point {b:?} is {d} from the output"
        );
    }
}

fn check_closed_simple(s: &Stroke) {
    assert!(s.c.proven, "{:?}", s.c);
    assert!(s.complete);
    for c in &s.contours {
        assert!(c.closed);
        for w in c.pieces.windows(2) {
            assert_eq!(w[0].end(), w[1].start());
        }
        assert_eq!(c.pieces.last().unwrap().end(), c.pieces[0].start());
    }
}

#[test]
fn stadium_of_a_segment() {
    let x = parse_curve("M 0 0 L 2 0").unwrap();
    let tol = 1e-3;
    let s = stroke(&x, &StrokeOptions::new(q("1/2"), tol)).unwrap();
    assert!(s.proven(), "{:?} {:?} {:?}", s.a, s.b, s.c);
    check_closed_simple(&s);
    assert_eq!(s.contours.len(), 1);
    let c = &s.contours[0];
    assert_eq!(c.orientation, Orientation::CounterClockwise);
    // 2 segments + 2 half circles; the area is 2·1 + π/4
    let arcs = c
        .pieces
        .iter()
        .filter(|p| matches!(p, Piece::Arc(_)))
        .count();
    assert_eq!(arcs, 2);
    assert_eq!(c.pieces.len(), 4, "{:?}", c.pieces);
    let area = 2.0 + std::f64::consts::PI / 4.0;
    assert!(
        c.area.0 - tol * 8.0 <= area && area <= c.area.1 + tol * 8.0,
        "{:?}",
        c.area
    );
    for p in &c.pieces {
        if let Piece::Arc(a) = p {
            assert_eq!(a.radius, q("1/2"));
            assert!(!a.clockwise);
        }
    }
    sampled_check(&x, &s, 0.5, tol, 5e-3);
}

#[test]
fn test_cubic_swallowtail_is_trimmed() {
    let x = test_cubic();
    let tol = 1e-3;
    let t0 = std::time::Instant::now();
    let s = stroke(&x, &StrokeOptions::new(q("0.4"), tol)).unwrap();
    eprintln!(
        "test cubic: {} raw pieces, {} crossings, {} output pieces, {} contours, {:?}, {:?}",
        s.raw_pieces,
        s.crossings.len(),
        s.pieces(),
        s.contours.len(),
        s.classified,
        t0.elapsed()
    );
    eprintln!("{:?}\n{:?}\n{:?}", s.a, s.b, s.c);
    assert!(s.proven(), "{:?} {:?} {:?}", s.a, s.b, s.c);
    check_closed_simple(&s);
    assert_eq!(s.contours.len(), 1);
    assert_eq!(s.contours[0].orientation, Orientation::CounterClockwise);
    assert!(!s.crossings.is_empty(), "the swallowtail must be cut");
    assert!(s.classified.removed > 0);
    sampled_check(&x, &s, 0.4, tol, 5e-3);
}

/// A closed rounded square (G¹ quarter-circle-like cubics joined by straight
/// sides), radius larger than its corner radius: the inner offset's loops go.
fn rounded_square() -> Vec<Bezier<Rational>> {
    // side 2, corner radius 0.3 (cubic quarter circles, k = 0.55)
    parse_curve(
        "M -0.7 -1 L 0.7 -1 C 0.865 -1 1 -0.865 1 -0.7 L 1 0.7 C 1 0.865 0.865 1 0.7 1 \
         L -0.7 1 C -0.865 1 -1 0.865 -1 0.7 L -1 -0.7 C -1 -0.865 -0.865 -1 -0.7 -1 Z",
    )
    .unwrap()
}

#[test]
fn closed_rounded_square_inner_loops_go() {
    let x = rounded_square();
    let tol = 1e-3;
    let t0 = std::time::Instant::now();
    let s = stroke(&x, &StrokeOptions::new(q("0.4"), tol)).unwrap();
    eprintln!(
        "rounded square: {} raw pieces, {} crossings, {} output pieces, {} contours, {:?}, {:?}",
        s.raw_pieces,
        s.crossings.len(),
        s.pieces(),
        s.contours.len(),
        s.classified,
        t0.elapsed()
    );
    assert!(s.closed_curve);
    assert!(s.proven(), "{:?} {:?} {:?} {:?}", s.a, s.b, s.c, s.notes);
    check_closed_simple(&s);
    // the outer contour (ccw) and the hole (cw), the hole's corner loops cut away
    assert_eq!(s.contours.len(), 2);
    let ccw = s
        .contours
        .iter()
        .filter(|c| c.orientation == Orientation::CounterClockwise)
        .count();
    let cw = s
        .contours
        .iter()
        .filter(|c| c.orientation == Orientation::Clockwise)
        .count();
    assert_eq!((ccw, cw), (1, 1));
    assert!(s.crossings.len() >= 4, "each inner corner is cut");
    sampled_check(&x, &s, 0.4, tol, 5e-3);
}

#[test]
fn bad_inputs_are_typed_errors() {
    let x = parse_curve("M 0 0 L 2 0").unwrap();
    let e = stroke(&x, &StrokeOptions::new(q("0"), 1e-3)).unwrap_err();
    assert_eq!(e.field, "radius");
    let e = stroke(&x, &StrokeOptions::new(q("-1"), 1e-3)).unwrap_err();
    assert_eq!(e.field, "radius");
    let e = stroke(&x, &StrokeOptions::new(q("1"), f64::NAN)).unwrap_err();
    assert_eq!(e.field, "tol");
    let e = stroke(&[], &StrokeOptions::new(q("1"), 1e-3)).unwrap_err();
    assert_eq!(e.field, "curve");
}

#[test]
fn butt_caps_close_but_make_no_distance_claims() {
    let x = parse_curve("M 0 0 C 1 1 2 1 3 0").unwrap();
    let mut o = StrokeOptions::new(q("1/4"), 1e-3);
    o.cap = Cap::Butt;
    let s = stroke(&x, &o).unwrap();
    assert!(s.c.proven, "{:?} {:?}", s.c, s.notes);
    assert!(!s.a.proven && !s.b.proven);
    assert_eq!(s.contours.len(), 1);
    assert!(s.contours[0]
        .pieces
        .iter()
        .all(|p| matches!(p, Piece::Bezier(_))));
}

#[test]
fn cli_stroke_json_path_and_exit_codes() {
    let dir = std::env::temp_dir().join(format!("lncert-stroke-{}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    let curve = dir.join("seg.txt");
    std::fs::write(&curve, "M 0 0 L 2 0").unwrap();
    let path_out = dir.join("seg.path");
    let bin = env!("CARGO_BIN_EXE_lncert");
    let out = std::process::Command::new(bin)
        .args([
            "stroke",
            curve.to_str().unwrap(),
            "--pen",
            "circle:1/2",
            "--tol",
            "1e-3",
        ])
        .args([
            "--output",
            "cubic",
            "--json",
            "--path-out",
            path_out.to_str().unwrap(),
        ])
        .output()
        .unwrap();
    assert_eq!(
        out.status.code(),
        Some(0),
        "{}",
        String::from_utf8_lossy(&out.stderr)
    );
    let doc: serde_json::Value = serde_json::from_slice(&out.stdout).unwrap();
    assert_eq!(doc["verdict"], "proven");
    let contours = doc["outline"]["contours"].as_array().unwrap();
    assert_eq!(contours.len(), 1);
    assert_eq!(contours[0]["closed"], true);
    assert_eq!(contours[0]["orientation"], "ccw");
    let pieces = contours[0]["pieces"].as_array().unwrap();
    assert_eq!(pieces.iter().filter(|p| p.get("arc").is_some()).count(), 2);
    assert_eq!(
        pieces
            .iter()
            .filter(|p| p.get("control_points").is_some())
            .count(),
        2
    );
    assert_eq!(doc["outline"]["claims"]["c"]["proven"], true);
    let d = std::fs::read_to_string(&path_out).unwrap();
    assert!(
        d.starts_with("M ") && d.contains(" A 1/2 1/2 ") && d.trim_end().ends_with('Z'),
        "{d}"
    );
    // bad input: exit 2, naming the flag
    for (pen, tol) in [
        ("ellipse:1,2", "1e-3"),
        ("circle:NaN", "1e-3"),
        ("circle:0", "1e-3"),
        ("circle:1", "0"),
    ] {
        let out = std::process::Command::new(bin)
            .args([
                "stroke",
                curve.to_str().unwrap(),
                "--pen",
                pen,
                "--tol",
                tol,
            ])
            .output()
            .unwrap();
        assert_eq!(out.status.code(), Some(2), "{pen} {tol}");
        let err = String::from_utf8_lossy(&out.stderr);
        assert!(err.contains("--pen") || err.contains("--tol"), "{err}");
    }
    let _ = std::fs::remove_dir_all(&dir);
}
