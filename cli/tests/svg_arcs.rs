//! SVG elliptical arcs, circles and ellipses as input: the reported bound
//! checked against lncert's own certified Hausdorff search between the cubic
//! pieces and the *exact* circular arc (`{"arc"}`, an independent exact
//! shape), and the CLI's report of what was approximated (`offset`,
//! `hausdorff`, text and `--json`).

mod common;
use common::{json_of, lncert, tmp};

use lncert::certify::{hausdorff, Config};
use lncert::shape::{parse_curve_reported, ShapeDesc};

/// Circular arcs whose end points are exact decimals on the circle
/// (Pythagorean directions (0.96, 0.28), (0.6, 0.8)): the certified lower
/// bound of `d_H(exact arc, pieces)` never exceeds the reported bound.
#[test]
fn reported_bound_holds_against_the_exact_circular_arc() {
    let cases = [
        // (path data, the same arc as {"arc"})
        (
            "M 1 0 A 1 1 0 0 1 0.96 0.28",
            r#"{"arc": {"center": [0, 0], "radius": 1, "from": [1, 0], "to": [0.96, 0.28]}}"#,
        ),
        (
            "M 0.96 0.28 A 1 1 0 0 0 1 0",
            r#"{"arc": {"center": [0, 0], "radius": 1, "from": [0.96, 0.28], "to": [1, 0], "clockwise": true}}"#,
        ),
        (
            "M 4.4 -0.3 a 2.5 2.5 0 0 1 -3.9 1.3",
            r#"{"arc": {"center": [2, -1], "radius": 2.5, "from": [0.96, 0.28], "to": [-0.6, 0.8]}}"#,
        ),
    ];
    let cfg = Config {
        rel: 0.05,
        ..Config::default()
    };
    for (path, arc) in cases {
        let (pieces, approx) = parse_curve_reported(path).unwrap();
        assert_eq!(approx.elements.len(), 1, "{path}");
        let bound = approx.bound();
        let a = ShapeDesc::parse(arc).unwrap();
        let b = ShapeDesc::curve(pieces).unwrap();
        let r = hausdorff(&a, &b, &cfg).unwrap();
        assert!(
            r.lo <= bound,
            "{path}: the exact arc is at least {:e} away, the report says ≤ {bound:e}",
            r.lo
        );
        // and the bound is tight: within 10 % of the search's upper bound
        assert!(
            bound <= 1.1 * r.hi,
            "{path}: {bound:e} vs [{:e}, {:e}]",
            r.lo,
            r.hi
        );
    }
}

/// `hausdorff` says which input was approximated and by how much, in text
/// and JSON; an exact input reports nothing (`null`). A circular arc whose
/// centre is rational is read exactly (nothing to report); one whose centre
/// is irrational (`(1/2, √3/2)` below) is approximated.
#[test]
fn hausdorff_reports_the_approximated_input() {
    let arc = tmp(
        "arc.json",
        r#"{"arc": {"center": [0, 0], "radius": 1, "from": [1, 0], "to": [0.96, 0.28]}}"#,
    );
    let same = tmp("arc.svg", "M 1 0 A 1 1 0 0 1 0.96 0.28");
    let (a, s) = (arc.to_str().unwrap(), same.to_str().unwrap());
    let o = lncert(&["hausdorff", a, s, "--rel", "0.05", "--json"]);
    let d = json_of(&o);
    assert!(d["input_approximation"].is_null(), "{d}");
    assert!(d["hi"].as_f64().unwrap() <= 1e-9, "{d}");
    let near = tmp(
        "near.json",
        r#"{"arc": {"center": [0.5, 0.866], "radius": 1, "from": [-0.5, -0.866], "to": [0.5, -0.866]}}"#,
    );
    let path = tmp("irr.svg", "M 0 0 A 1 1 0 0 1 1 0");
    let (a, b) = (near.to_str().unwrap(), path.to_str().unwrap());
    let o = lncert(&["hausdorff", a, b, "--rel", "0.05"]);
    assert_eq!(
        o.status.code(),
        Some(0),
        "{}",
        String::from_utf8_lossy(&o.stderr)
    );
    let text = String::from_utf8_lossy(&o.stdout);
    assert!(
        text.contains("input B: 1 SVG arc(s) approximated by ")
            && text.contains("; the results are about the approximated curve"),
        "{text}"
    );
    assert!(!text.contains("input A"), "{text}");
    let o = lncert(&["hausdorff", a, b, "--rel", "0.05", "--json"]);
    let d = json_of(&o);
    let ia = &d["input_approximation"];
    assert_eq!(ia["elements"], 1);
    assert!(ia["a"].is_null());
    assert_eq!(ia["b"]["elements"], 1);
    let bound = ia["bound"].as_f64().unwrap();
    assert!(bound > 0.0 && bound <= 1e-7, "{bound}");
    assert_eq!(bound, ia["b"]["bound"].as_f64().unwrap());
    // both approximated: the bound is the sum (d_H of the exact inputs is
    // within it of d_H of the pieces)
    let other = tmp("irr2.svg", "M 0 0 A 1.001 1.001 0 0 1 1 0");
    let o = lncert(&[
        "hausdorff",
        b,
        other.to_str().unwrap(),
        "--rel",
        "0.05",
        "--json",
    ]);
    assert_eq!(
        o.status.code(),
        Some(0),
        "{}",
        String::from_utf8_lossy(&o.stderr)
    );
    let ia = json_of(&o)["input_approximation"].clone();
    assert_eq!(ia["elements"], 2);
    let (ba, bb) = (
        ia["a"]["bound"].as_f64().unwrap(),
        ia["b"]["bound"].as_f64().unwrap(),
    );
    assert!(ia["bound"].as_f64().unwrap() >= ba + bb);
    // both exact: null
    let o = lncert(&["hausdorff", a, a, "--rel", "0.05", "--json"]);
    assert!(json_of(&o)["input_approximation"].is_null());
}

/// `offset` says when its input was approximated: a circle element and arcs.
#[test]
fn offset_reports_the_approximated_input() {
    let doc = tmp(
        "circle.svg",
        r#"<svg xmlns="http://www.w3.org/2000/svg"><circle cx="1" cy="1" r="2"/></svg>"#,
    );
    let o = lncert(&[
        "offset",
        doc.to_str().unwrap(),
        "--distance",
        "0.25",
        "--tol",
        "1e-4",
        "--method",
        "ln-pair",
    ]);
    assert_eq!(
        o.status.code(),
        Some(0),
        "{}",
        String::from_utf8_lossy(&o.stderr)
    );
    let text = String::from_utf8_lossy(&o.stdout);
    assert!(
        text.starts_with("input: 1 circle(s) approximated by 18 cubic pieces, certified within "),
        "{text}"
    );
    assert!(text.contains("; the results are about the approximated curve\n"));
    let path = tmp("arcs.svg", "M 0 0 A 1 1 0 0 1 2 0 A 1 2 30 0 1 3 1");
    let o = lncert(&[
        "offset",
        path.to_str().unwrap(),
        "--distance",
        "0.1",
        "--tol",
        "1e-4",
        "--json",
    ]);
    assert_eq!(
        o.status.code(),
        Some(0),
        "{}",
        String::from_utf8_lossy(&o.stderr)
    );
    let d = json_of(&o);
    assert_eq!(d["input_approximation"]["elements"], 2);
    let bound = d["input_approximation"]["bound"].as_f64().unwrap();
    assert!(bound > 0.0 && bound <= 2e-7, "{bound}");
    // exact input: null
    let line = tmp("line.svg", "M 0 0 L 1 0");
    let o = lncert(&[
        "offset",
        line.to_str().unwrap(),
        "--distance",
        "0.1",
        "--tol",
        "1e-4",
        "--json",
    ]);
    assert!(json_of(&o)["input_approximation"].is_null());
    // a bad arc is bad input naming the byte
    let bad = tmp("bad.svg", "M 0 0 A 1 1 0 2 1 2 0");
    let o = lncert(&[
        "offset",
        bad.to_str().unwrap(),
        "--distance",
        "0.1",
        "--tol",
        "1e-4",
    ]);
    assert_eq!(o.status.code(), Some(2));
    assert!(String::from_utf8_lossy(&o.stderr).contains("byte 14"));
}

/// Shapes read from SVG (exact circular arcs, approximated elliptic ones)
/// round-trip through their canonical JSON (what certificates store), and
/// reading the same text twice gives the same shape (so `verify --against`
/// recognises them).
#[test]
fn read_shapes_round_trip() {
    for (text, approximated, arcs) in [
        ("M 0 0 A 1 2 30 1 0 3 4 a 1 1 0 0 1 1 1 Z", true, 1),
        (
            r#"<svg><circle r="1"/><rect width="2" height="1" rx="0.25"/></svg>"#,
            false,
            6,
        ),
        (
            r#"{"offset": {"curve": "M 1 0 A 1 1 0 0 1 0.6 0.8", "distance": 0.1}}"#,
            true,
            0,
        ),
    ] {
        let (shape, approx) = ShapeDesc::parse_reported(text).unwrap();
        assert_eq!(!approx.is_empty(), approximated, "{text}");
        let n = match &shape {
            ShapeDesc::Union(m) => m.iter().filter(|s| matches!(s, ShapeDesc::Arc(_))).count(),
            _ => 0,
        };
        assert_eq!(n, arcs, "{text}: {shape:?}");
        assert_eq!(ShapeDesc::from_value(&shape.to_json()).unwrap(), shape);
        assert_eq!(ShapeDesc::parse(text).unwrap(), shape);
    }
}

/// An `<ellipse>` is read as two exact elliptic arcs: `hausdorff` certifies
/// its distance from the cubics that approximate it (the bound the reader
/// reports for them), `verify` re-checks the certificate, `--against` the
/// same document recognises it, and a forged matrix is refused.
#[test]
fn ellipses_are_exact_and_their_certificates_verify() {
    let svg = r#"<svg><ellipse cx="12" cy="12" rx="8" ry="4"/></svg>"#;
    let doc = tmp("ellipse.svg", svg);
    let (pieces, approx) = parse_curve_reported(svg).unwrap();
    let cubics = tmp(
        "ellipse-cubics.json",
        &ShapeDesc::curve(pieces).unwrap().to_json().to_string(),
    );
    let cert = tmp("ellipse-cert.json", "");
    let (a, b, c) = (
        doc.to_str().unwrap(),
        cubics.to_str().unwrap(),
        cert.to_str().unwrap(),
    );
    let tol = format!("{:e}", 2.0 * approx.bound());
    let o = lncert(&[
        "hausdorff",
        a,
        b,
        "--tol",
        &tol,
        "--certificate",
        c,
        "--json",
    ]);
    assert_eq!(
        o.status.code(),
        Some(0),
        "{}",
        String::from_utf8_lossy(&o.stderr)
    );
    let d = json_of(&o);
    assert!(d["input_approximation"]["a"].is_null(), "{d}");
    assert!(d["lo"].as_f64().unwrap() <= approx.bound(), "{d}");
    let o = lncert(&["verify", c, "--against", a, b]);
    let text = String::from_utf8_lossy(&o.stdout);
    assert_eq!(o.status.code(), Some(0), "{text}");
    assert!(text.contains("the elliptic arc c + M·u"), "{text}");
    assert!(
        text.contains("A and B are exactly the shapes given"),
        "{text}"
    );
    // forged: the ellipse's matrix entry 8 → 81/10 (the bounds no longer hold)
    let good = std::fs::read_to_string(&cert).unwrap();
    assert!(good.contains(r#""matrix":[["8","0"],["0","4"]]"#), "{good}");
    for (forged, field) in [
        (r#""matrix":[["81/10","0"],["0","4"]]"#, ""),
        (r#""matrix":[["8","4"],["16","8"]]"#, "ellipse_arc.matrix"),
    ] {
        let f = tmp(
            "ellipse-forged.json",
            &good.replacen(r#""matrix":[["8","0"],["0","4"]]"#, forged, 1),
        );
        let o = lncert(&["verify", f.to_str().unwrap()]);
        let text = String::from_utf8_lossy(&o.stdout);
        assert_eq!(o.status.code(), Some(1), "{forged}: {text}");
        assert!(text.starts_with("invalid"), "{forged}: {text}");
        assert!(text.contains(field), "{forged}: {text}");
    }
}
