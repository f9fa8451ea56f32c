//! Offsets as cubics (and quadratics) on a grid finer than rounding allows
//! (`lncert::offset::gridfit`, `offset --output cubic|quadratic --grid G --tol T` with
//! `T ≤ G·√2/2`): every control point is a grid multiple, contours close
//! exactly, the certificate verifies, dense samples of the exact offset
//! (computed directly) agree with the bound, and an offset whose end no grid
//! point can reach is reported not reached.

mod common;
use common::qs as q;
use common::{dejavu, lncert, max_spacing, sampled_one_sided, tmp};

use lncert::curve::{Bezier, V2};
use lncert::offset::{offset_on_grid, GridOffset};
use lncert::offset::{OffsetOptions, Output};
use lncert::scalar::{Rational, Scalar};
use lncert::shape::parse_curve;

fn opts(d: &str, tol: f64, grid: &str) -> OffsetOptions {
    let mut o = OffsetOptions::new(q(d), common::tol(tol));
    o.output = Output::Cubic;
    o.grid = Some(q(grid));
    o
}

/// A smooth closed curve in "font units" (G¹ at both joints).
const SMOOTH: &str = "M 0 0 C 300 -100 500 200 400 400 C 300 600 -300 100 0 0";

fn on_grid(r: &GridOffset, g: f64) {
    for s in &r.segments {
        assert_eq!(s.bezier.points().len(), 4);
        for p in s.bezier.points() {
            assert!(
                (p.x / g).fract() == 0.0 && (p.y / g).fract() == 0.0,
                "{p:?} is not on the grid {g}"
            );
        }
    }
    // contours close exactly: each cubic starts where the previous one ends
    for &(first, n, closed) in &r.contours {
        let segs = &r.segments[first..first + n];
        for w in segs.windows(2) {
            assert_eq!(w[0].bezier.points()[3], w[1].bezier.points()[0]);
        }
        if closed {
            assert_eq!(segs[n - 1].bezier.points()[3], segs[0].bezier.points()[0]);
        }
    }
}

/// Dense samples of the exact offset, computed directly (`x + d N`), against
/// dense samples of the cubics: both one-sided distances are within the
/// certified bound up to half the sample spacing.
fn sampled_agrees(x: &[Bezier<Rational>], d: f64, r: &GridOffset) {
    const N: usize = 2000;
    let mut exact = Vec::new();
    for piece in x {
        let xf = piece.map(|v| v.approx());
        let h = xf.hodograph();
        for i in 0..=N {
            let t = i as f64 / N as f64;
            let v = h.eval(&t);
            let l = v.norm2().sqrt();
            exact.push(xf.eval(&t).add(&V2::new(-v.y / l * d, v.x / l * d)));
        }
    }
    let fit: Vec<V2<f64>> = r
        .segments
        .iter()
        .flat_map(|s| (0..=200).map(move |i| s.bezier.eval(&(i as f64 / 200.0))))
        .collect();
    let h1 = sampled_one_sided(&exact, &fit);
    let h2 = sampled_one_sided(&fit, &exact);
    assert!(
        h1 <= r.certified_hi + max_spacing(&fit) / 2.0 + 1e-9,
        "exact→fit {h1}"
    );
    assert!(
        h2 <= r.certified_hi + max_spacing(&exact) / 2.0 + 1e-9,
        "fit→exact {h2}"
    );
    // the grid really is coarser than the tolerance: plain rounding of the
    // exact curve would not do
    assert!(r.tol.value() < 0.5);
}

#[test]
fn a_smooth_closed_offset_is_proven_on_integer_units_below_the_rounding_move() {
    let x = parse_curve(SMOOTH).unwrap();
    for d in ["40", "-25"] {
        let r = offset_on_grid(&x, &opts(d, 0.2, "1")).unwrap();
        assert!(r.reached(), "d = {d}: unreached {:?}", r.unreached);
        assert!(r.certified_hi <= 0.2);
        on_grid(&r, 1.0);
        sampled_agrees(&x, q(d).approx(), &r);
        let cert = r.certificate.as_ref().expect("a certificate");
        let v = lncert::verify(&cert.to_json_string());
        assert!(v.is_ok(), "{:?}", v.err());
        // every joint's grid point is within tol/2 of the exact curve or the
        // proofs would not have held with room; it is reported
        assert!(r.max_joint_offset <= 0.2, "{}", r.max_joint_offset);
    }
}

/// A forged cubic (one inner control point moved by one grid step) makes the
/// certificate invalid: the verifier re-checks the numbers written.
#[test]
fn a_moved_control_point_breaks_the_certificate() {
    let x = parse_curve(SMOOTH).unwrap();
    let r = offset_on_grid(&x, &opts("40", 0.2, "1")).unwrap();
    let text = r.certificate.as_ref().unwrap().to_json_string();
    let p = r.segments[0].bezier.points()[1].clone();
    let needle = format!("[\"{}\", \"{}\"]", p.x, p.y);
    let compact = format!("[\"{}\",\"{}\"]", p.x, p.y);
    let (from, to) = if text.contains(&needle) {
        (needle, format!("[\"{}\", \"{}\"]", p.x + 5.0, p.y))
    } else {
        assert!(text.contains(&compact), "control point {p:?} not found");
        (compact, format!("[\"{}\",\"{}\"]", p.x + 5.0, p.y))
    };
    let forged = text.replacen(&from, &to, 1);
    assert!(lncert::verify(&forged).is_err());
}

/// The exact offset of a horizontal line at `y = 0.75` ends at `(0.5, 0.75)`:
/// every grid point is at least 0.25 away from that end's neighbourhood, so no
/// cubic spline on the integer grid is within 0.2: not reached, no certificate.
#[test]
fn an_open_end_no_grid_point_can_reach_is_not_reached() {
    let x = parse_curve("M 0.5 0.5 C 30.5 0.5 70.5 0.5 100.5 0.5").unwrap();
    let r = offset_on_grid(&x, &opts("1/4", 0.2, "1")).unwrap();
    assert!(!r.reached());
    assert!(r.certificate.is_none());
    assert!(r.certified_hi > 0.2);
}

#[test]
fn bad_grid_options_are_typed_errors() {
    let x = parse_curve(SMOOTH).unwrap();
    let mut o = opts("40", 0.2, "1/1000");
    let e = offset_on_grid(&x, &o).unwrap_err();
    assert!(e.to_string().contains("grid"), "{e}");
    o.grid = None;
    assert!(offset_on_grid(&x, &o)
        .unwrap_err()
        .to_string()
        .contains("grid"));
    let mut o = opts("40", 0.2, "1");
    o.output = Output::Native;
    assert!(offset_on_grid(&x, &o)
        .unwrap_err()
        .to_string()
        .contains("output"));
}

/// Quadratic output (TrueType) on the grid below the rounding move: the same
/// partition, joints and proofs, one inner control point per piece; every
/// point a grid multiple, contours closed exactly, the certificate verifies,
/// and dense samples agree with the bound.
#[test]
fn quadratics_on_the_grid_below_the_rounding_move() {
    let x = parse_curve(SMOOTH).unwrap();
    for d in ["40", "-25"] {
        let mut o = opts(d, 0.2, "1");
        o.output = Output::Quadratic;
        let r = offset_on_grid(&x, &o).unwrap();
        assert!(r.reached(), "d = {d}: unreached {:?}", r.unreached);
        assert!(r.certified_hi <= 0.2);
        for s in &r.segments {
            assert_eq!(s.bezier.degree(), 2);
            for p in s.bezier.points() {
                assert!(p.x.fract() == 0.0 && p.y.fract() == 0.0, "{p:?}");
            }
        }
        for &(first, n, closed) in &r.contours {
            let segs = &r.segments[first..first + n];
            for w in segs.windows(2) {
                assert_eq!(w[0].bezier.points()[2], w[1].bezier.points()[0]);
            }
            assert!(closed);
            assert_eq!(segs[n - 1].bezier.points()[2], segs[0].bezier.points()[0]);
        }
        sampled_agrees(&x, q(d).approx(), &r);
        // two per quadratic: the shared end points counted once
        assert_eq!(r.control_points(), 2 * r.segments.len());
        let cert = r.certificate.as_ref().expect("a certificate");
        assert!(lncert::verify(&cert.to_json_string()).is_ok());
    }
}

/// The CLI: DejaVu Sans "O" grown by 60 font units in em, quadratics on
/// integer font units within 1e-4 em (0.2 units), verified against the files.
#[test]
fn cli_glyph_quadratics_on_integer_font_units() {
    let Some(font) = dejavu() else { return };
    let (cert, exact, path) = (
        tmp("gridq-cert.json", ""),
        tmp("gridq-exact.json", ""),
        tmp("gridq-path.txt", ""),
    );
    let out = lncert(&[
        "offset",
        font.to_str().unwrap(),
        "--glyph",
        "O",
        "--em",
        "--distance",
        "60/2048",
        "--tol",
        "1e-4",
        "--output",
        "quadratic",
        "--grid",
        "1/2048",
        "--json",
        "--certificate",
        cert.to_str().unwrap(),
        "--exact-out",
        exact.to_str().unwrap(),
        "--path-out",
        path.to_str().unwrap(),
    ]);
    assert_eq!(out.status.code(), Some(0));
    let doc: serde_json::Value = serde_json::from_slice(&out.stdout).unwrap();
    assert_eq!(doc["degree"], 2);
    assert_eq!(doc["output"], "quadratic");
    assert!(std::fs::read_to_string(&path).unwrap().contains(" Q "));
    let v = lncert(&[
        "verify",
        cert.to_str().unwrap(),
        "--against",
        exact.to_str().unwrap(),
        path.to_str().unwrap(),
    ]);
    assert_eq!(
        v.status.code(),
        Some(0),
        "{}",
        String::from_utf8_lossy(&v.stdout)
    );
}

/// The command: a glyph in em, `--grid 1/2048` (integer font units of
/// DejaVu's 2048 per em), `--tol 1e-4` (0.2 units, below the 0.707-unit
/// rounding move): a proven cubic spline on integer font units whose
/// certificate verifies against the files written.
#[test]
fn cli_glyph_on_integer_font_units() {
    let Some(font) = dejavu() else { return };
    let font = font.to_str().unwrap().to_string();
    for (ch, d) in [("O", "60/2048"), ("a", "-60/2048")] {
        let cert = tmp(&format!("grid-cert-{ch}.json"), "");
        let exact = tmp(&format!("grid-exact-{ch}.json"), "");
        let path = tmp(&format!("grid-path-{ch}.txt"), "");
        let (cert, exact, path) = (
            cert.to_str().unwrap(),
            exact.to_str().unwrap(),
            path.to_str().unwrap(),
        );
        let out = lncert(&[
            "offset",
            &font,
            "--glyph",
            ch,
            "--em",
            "--distance",
            d,
            "--tol",
            "1e-4",
            "--output",
            "cubic",
            "--grid",
            "1/2048",
            "--json",
            "--certificate",
            cert,
            "--exact-out",
            exact,
            "--path-out",
            path,
        ]);
        assert_eq!(
            out.status.code(),
            Some(0),
            "{}",
            String::from_utf8_lossy(&out.stderr)
        );
        let doc: serde_json::Value = serde_json::from_slice(&out.stdout).unwrap();
        assert_eq!(doc["verdict"], "certified");
        assert_eq!(doc["degree"], 3);
        assert!(doc["certified_error"][1].as_f64().unwrap() <= 1e-4);
        for p in doc["pieces"].as_array().unwrap() {
            for c in p["control_points"].as_array().unwrap() {
                for v in c.as_array().unwrap() {
                    let u = v.as_f64().unwrap() * 2048.0;
                    assert_eq!(u.fract(), 0.0, "{v} is not a font unit");
                }
            }
        }
        let v = lncert(&["verify", cert, "--against", exact, path]);
        assert_eq!(
            v.status.code(),
            Some(0),
            "{}",
            String::from_utf8_lossy(&v.stdout)
        );
    }
}

/// The grid path with a glyph named by code point and by name: the period of
/// DejaVu Sans in em on integer font units, certified, the same cubics
/// whichever way the glyph is named.
#[test]
fn cli_glyph_by_code_point_and_name_on_the_grid() {
    let Some(font) = dejavu() else { return };
    let f = font.to_str().unwrap();
    let pieces = |item: &str| {
        let out = lncert(&[
            "offset",
            f,
            "--glyph",
            item,
            "--em",
            "--distance",
            "20/2048",
            "--tol",
            "1e-4",
            "--output",
            "cubic",
            "--grid",
            "1/2048",
            "--json",
        ]);
        assert_eq!(
            out.status.code(),
            Some(0),
            "{item:?}: {}",
            String::from_utf8_lossy(&out.stderr)
        );
        let doc: serde_json::Value = serde_json::from_slice(&out.stdout).unwrap();
        assert_eq!(doc["verdict"], "certified", "{item:?}");
        assert_eq!(doc["grid"]["grid"], "1/2048", "{item:?}");
        doc["pieces"].clone()
    };
    let by_name = pieces("period");
    assert!(!by_name.as_array().unwrap().is_empty());
    assert_eq!(pieces("uni002E"), by_name);
    assert_eq!(pieces("@period"), by_name);
}

#[test]
fn cli_grid_refusals_name_the_flag() {
    let f = tmp("grid-smooth.txt", SMOOTH);
    let f = f.to_str().unwrap();
    // native segments (degree n + 3) cannot go below the rounding move
    let out = lncert(&[
        "offset",
        f,
        "--distance",
        "40",
        "--tol",
        "0.2",
        "--output",
        "native",
        "--grid",
        "1",
    ]);
    assert_eq!(out.status.code(), Some(2));
    assert!(String::from_utf8_lossy(&out.stderr).contains("--grid"));
    // --em needs --glyph
    let out = lncert(&["offset", f, "--distance", "40", "--tol", "0.2", "--em"]);
    assert_eq!(out.status.code(), Some(2));
    // the curve itself on the integer grid below the move: proven, exit 0
    let out = lncert(&[
        "offset",
        f,
        "--distance",
        "40",
        "--tol",
        "0.2",
        "--output",
        "cubic",
        "--grid",
        "1",
    ]);
    assert_eq!(
        out.status.code(),
        Some(0),
        "{}",
        String::from_utf8_lossy(&out.stdout)
    );
    assert!(String::from_utf8_lossy(&out.stdout).contains("certified"));
}
