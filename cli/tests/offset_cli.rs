//! Integration tests of `lncert offset`: the documented JSON keys, the control-point
//! count, a certificate that `lncert verify` accepts, the SVG, arcs and circles,
//! B-spline input, and exit codes 0/1/2 with bad input naming the flag.

mod common;
use common::{dejavu, json_of, lncert, tmp};

use serde_json::Value;
use std::process::Output;

const CUBIC: &str = r#"{"bezier": [[-0.95, 0.7], [-0.3, 0.5], [0.3, -2.5], [0.9, -0.2]]}"#;

/// `--tol 1e-3` is parsed once, exactly (1/1000): the bounds are compared
/// with the largest float ≤ 1/1000 (the f64 `1e-3` is above it), so the
/// proven bound is ≤ 1/1000 as a rational, and the certificate claims exactly
/// 1/1000 and verifies (issue 29).
#[test]
fn tol_1e_3_is_one_thousandth_for_the_proof_and_the_certificate() {
    use lncert::scalar::{parse_rational, rational_from_f64};
    let curve = tmp("cubic_seam.json", CUBIC);
    let cert = curve.with_file_name("cert_seam.json");
    let o = lncert(&[
        "offset",
        curve.to_str().unwrap(),
        "--distance",
        "-0.5",
        "--tol",
        "1e-3",
        "--certificate",
        cert.to_str().unwrap(),
        "--json",
    ]);
    assert_eq!(
        o.status.code(),
        Some(0),
        "{}",
        String::from_utf8_lossy(&o.stderr)
    );
    let doc = json_of(&o);
    assert_eq!(doc["tol"], "1e-3", "the tolerance as given");
    let hi = doc["certified_error"][1].as_f64().unwrap();
    let thousandth = parse_rational("1/1000").unwrap();
    assert!(rational_from_f64(hi).unwrap() <= thousandth, "{hi}");
    for p in doc["pieces"].as_array().unwrap() {
        let h = p["error"][1].as_f64().unwrap();
        assert!(rational_from_f64(h).unwrap() <= thousandth, "{h}");
    }
    let c: Value = serde_json::from_str(&std::fs::read_to_string(&cert).unwrap()).unwrap();
    assert_eq!(c["tol"], "1/1000");
    let v = lncert(&["verify", cert.to_str().unwrap(), "--json"]);
    assert_eq!(
        v.status.code(),
        Some(0),
        "{}",
        String::from_utf8_lossy(&v.stdout)
    );
    assert_eq!(json_of(&v)["statement"]["tol"], "1/1000");
}

#[test]
fn json_document_certificate_and_svg() {
    let curve = tmp("cubic.json", CUBIC);
    let cert = curve.with_file_name("cert.json");
    let svg = curve.with_file_name("offset.svg");
    let o = lncert(&[
        "offset",
        curve.to_str().unwrap(),
        "--distance",
        "-0.5",
        "--tol",
        "1e-2",
        "--certificate",
        cert.to_str().unwrap(),
        "--svg",
        svg.to_str().unwrap(),
        "--json",
    ]);
    assert_eq!(
        o.status.code(),
        Some(0),
        "{}",
        String::from_utf8_lossy(&o.stderr)
    );
    let doc = json_of(&o);
    for key in [
        "segments",
        "control_points",
        "degree",
        "certified_error",
        "tol",
        "pieces",
        "cusps",
    ] {
        assert!(doc.get(key).is_some(), "missing key {key}");
    }
    let segs = doc["segments"].as_u64().unwrap();
    assert_eq!(doc["degree"], 6);
    assert_eq!(doc["control_points"].as_u64().unwrap(), 6 * segs + 1);
    let e = doc["certified_error"].as_array().unwrap();
    let (lo, hi) = (e[0].as_f64().unwrap(), e[1].as_f64().unwrap());
    assert!(0.0 <= lo && lo <= hi && hi <= 1e-2, "[{lo}, {hi}]");
    assert_eq!(doc["pieces"].as_array().unwrap().len() as u64, segs);
    assert_eq!(doc["verdict"], "certified");
    // the certificate re-checks independently
    let v = lncert(&["verify", cert.to_str().unwrap(), "--json"]);
    assert_eq!(
        v.status.code(),
        Some(0),
        "{}",
        String::from_utf8_lossy(&v.stdout)
    );
    // it speaks about the offset of exactly this curve (stored split at dyadic
    // parameters), and not about a neighbouring one
    let c: Value = serde_json::from_str(&std::fs::read_to_string(&cert).unwrap()).unwrap();
    let b = tmp("approximant.json", &c["b"].to_string());
    for (distance, curve, code) in [
        ("-0.5", CUBIC, 0),
        ("-0.4", CUBIC, 1),
        (
            "-0.5",
            r#"{"bezier": [[-0.95, 0.7], [-0.3, 0.5], [0.3, -2.5], [0.9, -0.21]]}"#,
            1,
        ),
    ] {
        let a = tmp(
            "exact.json",
            &format!(r#"{{"offset": {{"curve": {curve}, "distance": {distance}}}}}"#),
        );
        let v = lncert(&[
            "verify",
            cert.to_str().unwrap(),
            "--against",
            a.to_str().unwrap(),
            b.to_str().unwrap(),
        ]);
        let out = String::from_utf8_lossy(&v.stdout);
        assert_eq!(v.status.code(), Some(code), "{distance} {curve}: {out}");
        if code == 0 {
            assert!(
                out.contains("exactly the shapes given to --against"),
                "{out}"
            );
            assert!(
                out.contains("A = the exact offset at signed distance -1/2"),
                "{out}"
            );
        } else {
            assert!(out.starts_with("invalid: a: "), "{out}");
        }
    }
    // a tampered certificate does not
    let mut c: Value = serde_json::from_str(&std::fs::read_to_string(&cert).unwrap()).unwrap();
    c["tol"] = Value::String("1/1000000".into());
    let bad = cert.with_file_name("tampered.json");
    std::fs::write(&bad, c.to_string()).unwrap();
    assert_eq!(
        lncert(&["verify", bad.to_str().unwrap()]).status.code(),
        Some(1)
    );
    let picture = std::fs::read_to_string(&svg).unwrap();
    assert!(
        picture.starts_with("<svg")
            && picture.contains("curvature")
            && picture.trim_end().ends_with("</svg>")
    );
}

#[test]
fn ln_pair_text_report_and_cusps() {
    let curve = tmp("cubic2.json", CUBIC);
    let o = lncert(&[
        "offset",
        curve.to_str().unwrap(),
        "--distance",
        "0.4",
        "--tol",
        "0.1",
        "--method",
        "ln-pair",
    ]);
    assert_eq!(o.status.code(), Some(0));
    let text = String::from_utf8_lossy(&o.stdout);
    assert!(
        text.contains("ln-pair") && text.contains("certified"),
        "{text}"
    );
    assert_eq!(
        text.matches("cusp of the exact offset").count(),
        2,
        "{text}"
    );
}

#[test]
fn bspline_svg_path_circle_and_arc_inputs() {
    let spline = tmp(
        "doc.json",
        r#"{"bspline": {"degree": 2, "knots": "clamped", "control_points": [[0.7, 0.0], [0.7, 0.06], [0.1, 0.1], [0.1, 0.6], [0.6, 0.6], [0.8, 0.8], [0.8, 1.4], [0.6, 1.6]]}}"#,
    );
    let o = lncert(&[
        "offset",
        spline.to_str().unwrap(),
        "--distance",
        "0.4",
        "--tol",
        "0.05",
        "--json",
    ]);
    assert_eq!(
        o.status.code(),
        Some(0),
        "{}",
        String::from_utf8_lossy(&o.stderr)
    );
    assert_eq!(
        json_of(&o)["degree"],
        5,
        "quadratic pieces give degree 2 + 3"
    );

    let path = tmp("l.svg", "M 0 0 L 1 0 L 1 -1");
    let o = lncert(&[
        "offset",
        path.to_str().unwrap(),
        "--distance",
        "1/4",
        "--tol",
        "1e-6",
        "--json",
    ]);
    assert_eq!(o.status.code(), Some(0));
    let doc = json_of(&o);
    assert_eq!(
        doc["joins"].as_array().unwrap().len(),
        1,
        "a right turn opens a gap on the left"
    );
    assert_eq!(doc["joins"][0]["arc"]["radius"], "1/4");

    let circle = tmp(
        "circle.json",
        r#"{"circle": {"center": [0, 0], "radius": 1}}"#,
    );
    let o = lncert(&[
        "offset",
        circle.to_str().unwrap(),
        "--distance",
        "-0.6",
        "--tol",
        "1e-5",
        "--json",
    ]);
    assert_eq!(o.status.code(), Some(0));
    let doc = json_of(&o);
    assert_eq!(doc["certified_error"], serde_json::json!([0.0, 0.0]));
    let arcs = doc["arcs"].as_array().unwrap();
    assert_eq!(arcs.len(), 4);
    assert!(arcs.iter().all(|a| a["arc"]["radius"] == "8/5"));

    let arc = tmp(
        "arc.json",
        r#"{"arc": {"center": [0, 0], "radius": 1, "from": [1, 0], "to": [0, 1], "clockwise": true}}"#,
    );
    let o = lncert(&[
        "offset",
        arc.to_str().unwrap(),
        "--distance",
        "1/2",
        "--tol",
        "1e-5",
        "--json",
    ]);
    assert_eq!(
        json_of(&o)["arcs"][0]["arc"]["radius"],
        "3/2",
        "clockwise: the left normal points out"
    );
}

#[test]
fn unreachable_tolerance_exits_1() {
    let curve = tmp("cubic3.json", CUBIC);
    let o = lncert(&[
        "offset",
        curve.to_str().unwrap(),
        "--distance",
        "0.5",
        "--tol",
        "1e-8",
        "--max-depth",
        "1",
        "--json",
    ]);
    // not reached within the limits: undecided, not refuted
    assert_eq!(o.status.code(), Some(3));
    let doc = json_of(&o);
    assert_eq!(doc["verdict"], "not reached");
    assert!(!doc["unreached"].as_array().unwrap().is_empty());
}

#[test]
fn bad_input_exits_2_naming_the_flag() {
    let curve = tmp("cubic4.json", CUBIC);
    let c = curve.to_str().unwrap();
    let cases: [(&[&str], &str); 8] = [
        (&["--distance", "0", "--tol", "0.1"], "--distance"),
        (&["--distance", "abc", "--tol", "0.1"], "--distance"),
        (&["--distance", "0.5", "--tol", "0"], "--tol"),
        (&["--distance", "0.5", "--tol", "-1"], "--tol"),
        (&["--distance", "0.5", "--tol", "1e-300"], "--tol"),
        (&["--distance", "0.5", "--tol", "NaN"], "--tol"),
        (
            &["--distance", "0.5", "--tol", "0.1", "--method", "g3"],
            "--method",
        ),
        (
            &["--distance", "0.5", "--tol", "0.1", "--max-depth", "99"],
            "--max-depth",
        ),
    ];
    for (args, flag) in cases {
        let mut all = vec!["offset", c];
        all.extend_from_slice(args);
        let o = lncert(&all);
        let err = String::from_utf8_lossy(&o.stderr);
        assert_eq!(o.status.code(), Some(2), "{args:?}: {err}");
        assert!(err.contains(flag), "{args:?}: {err}");
    }
    for (name, text) in [
        (
            "cusp.json",
            r#"{"bezier": [[0, 0], [1, 1], [0, 1], [1, 0]]}"#,
        ),
        ("broken.json", r#"{"bezier": [[0, 0], [1, "x"]]}"#),
        ("nan.json", r#"{"bezier": [[0, 0], [1, "NaN"]]}"#),
        (
            "circle0.json",
            r#"{"circle": {"center": [0, 0], "radius": 0}}"#,
        ),
        ("empty.svg", ""),
    ] {
        let p = tmp(name, text);
        let o = lncert(&[
            "offset",
            p.to_str().unwrap(),
            "--distance",
            "0.5",
            "--tol",
            "0.1",
        ]);
        let err = String::from_utf8_lossy(&o.stderr);
        assert_eq!(o.status.code(), Some(2), "{name}: {err}");
        assert!(err.contains("CURVE"), "{name}: {err}");
    }
}

/// Without `--global-bounds` the certified error is the union bound of the
/// per-segment proofs (no global search); with it, a two-sided global enclosure
/// that lies under the union bound.
#[test]
fn global_bounds_are_opt_in() {
    let curve = tmp("cubic-global.json", CUBIC);
    let run = |extra: &[&str]| {
        let mut args = vec!["--json"];
        args.extend_from_slice(extra);
        let o = run_offset(&curve, "0.4", "1e-2", &args);
        assert_eq!(
            o.status.code(),
            Some(0),
            "{}",
            String::from_utf8_lossy(&o.stderr)
        );
        json_of(&o)
    };
    let union = run(&[]);
    let global = run(&["--global-bounds"]);
    let bounds = |d: &Value| {
        let e = d["certified_error"].as_array().unwrap();
        (e[0].as_f64().unwrap(), e[1].as_f64().unwrap())
    };
    let (ulo, uhi) = bounds(&union);
    let (glo, ghi) = bounds(&global);
    assert_eq!(
        union["certified_error_from"],
        "union of the per-segment proofs"
    );
    assert_eq!(global["certified_error_from"], "global search");
    assert_eq!(ulo, 0.0);
    // the per-segment bounds are the same; the global search only adds a lower bound
    let seg_max = union["pieces"]
        .as_array()
        .unwrap()
        .iter()
        .map(|p| p["error"][1].as_f64().unwrap())
        .fold(0.0, f64::max);
    assert_eq!(uhi, seg_max);
    assert!(
        0.0 < glo && glo <= ghi && ghi <= uhi && uhi <= 1e-2,
        "[{glo}, {ghi}] vs {uhi}"
    );
}

/// `lncert offset CURVE --distance D --tol T EXTRA...`
fn run_offset(curve: &std::path::Path, distance: &str, tol: &str, extra: &[&str]) -> Output {
    let mut args = vec![
        "offset",
        curve.to_str().unwrap(),
        "--distance",
        distance,
        "--tol",
        tol,
    ];
    args.extend_from_slice(extra);
    lncert(&args)
}

/// `--no-certify` builds the same construction without proving it: the output
/// says so everywhere (no certified error, `proven: false`, an UNPROVEN estimate),
/// and it cannot be combined with a certificate.
#[test]
fn no_certify_is_labelled_unproven() {
    let curve = tmp("cubic-unproven.json", CUBIC);
    let o = run_offset(&curve, "0.4", "1e-3", &["--no-certify", "--json"]);
    assert_eq!(
        o.status.code(),
        Some(0),
        "{}",
        String::from_utf8_lossy(&o.stderr)
    );
    let d = json_of(&o);
    assert_eq!(d["proven"], false);
    assert!(d["certified_error"].is_null());
    assert_eq!(d["certified_error_from"], "none: --no-certify");
    assert!(d["verdict"].as_str().unwrap().starts_with("unproven"));
    let e = d["estimated_error"].as_f64().unwrap();
    assert!(e > 0.0 && e <= 1e-3, "{e}");
    // no piece claims a certified bound: its error is the trivial [0, ∞), the
    // estimate stands apart
    for p in d["pieces"].as_array().unwrap() {
        assert_eq!(p["error"][0].as_f64(), Some(0.0));
        assert!(p["error"][1].is_null(), "{p}");
        assert!(p["estimate"].as_f64().unwrap() <= e);
    }
    let text = run_offset(&curve, "0.4", "1e-3", &["--no-certify"]);
    let out = String::from_utf8_lossy(&text.stdout);
    assert!(
        out.contains("UNPROVEN") && !out.contains("certified error"),
        "{out}"
    );
    let cert = curve.with_file_name("never.json");
    let bad = run_offset(
        &curve,
        "0.4",
        "1e-3",
        &["--no-certify", "--certificate", cert.to_str().unwrap()],
    );
    assert_eq!(bad.status.code(), Some(2));
    assert!(!cert.exists());
}

/// The approximant written as a curve file and as SVG path data reads back as
/// exactly the certified curve: the certificate verifies against both (read
/// by the user-language reader every subcommand uses), and one ulp off does not.
#[test]
fn curve_out_and_path_out_read_back_as_the_certified_curve() {
    let curve = tmp("rt_cubic.json", CUBIC);
    let dir = std::env::temp_dir().join(format!("lncert-rt-{}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    let (cert, json_out, svg_out) = (dir.join("c.json"), dir.join("o.json"), dir.join("o.svg"));
    let o = lncert(&[
        "offset",
        curve.to_str().unwrap(),
        "--distance",
        "-0.5",
        "--tol",
        "1e-3",
        "--method",
        "ln-pair",
        "--certificate",
        cert.to_str().unwrap(),
        "--curve-out",
        json_out.to_str().unwrap(),
        "--path-out",
        svg_out.to_str().unwrap(),
    ]);
    assert_eq!(
        o.status.code(),
        Some(0),
        "{}",
        String::from_utf8_lossy(&o.stderr)
    );
    let path_data = std::fs::read_to_string(&svg_out).unwrap();
    assert!(
        path_data.starts_with("M ") && path_data.contains(" C "),
        "{path_data}"
    );
    let exact = tmp(
        "rt_exact.json",
        &format!(r#"{{"offset": {{"curve": {CUBIC}, "distance": -0.5}}}}"#),
    );
    for written in [&json_out, &svg_out] {
        let v = lncert(&[
            "verify",
            cert.to_str().unwrap(),
            "--against",
            exact.to_str().unwrap(),
            written.to_str().unwrap(),
        ]);
        assert_eq!(
            v.status.code(),
            Some(0),
            "{}: {}",
            written.display(),
            String::from_utf8_lossy(&v.stdout)
        );
    }
    // one control point moved by one ulp in the path data: another curve
    let first = path_data.split_whitespace().nth(1).unwrap().to_string();
    let x: f64 = first.parse().unwrap();
    let moved = path_data.replacen(&first, &format!("{:?}", x.next_up()), 1);
    let moved_file = tmp("rt_moved.svg", &moved);
    let v = lncert(&[
        "verify",
        cert.to_str().unwrap(),
        "--against",
        exact.to_str().unwrap(),
        moved_file.to_str().unwrap(),
    ]);
    assert_eq!(v.status.code(), Some(1));
    // G2 pieces have no SVG path command: refused before any work
    let g2 = lncert(&[
        "offset",
        curve.to_str().unwrap(),
        "--distance",
        "-0.5",
        "--tol",
        "1e-3",
        "--path-out",
        svg_out.to_str().unwrap(),
    ]);
    assert_eq!(g2.status.code(), Some(2));
    assert!(String::from_utf8_lossy(&g2.stderr).contains("--path-out"));
}

/// `--glyph`: a TrueType glyph's closed contours, exactly as stored
/// (quadratics, font units), offset with a proven tolerance and a certificate
/// that verifies; bad glyphs and non-fonts are bad input.
#[test]
fn glyph_outlines_are_offset_and_certified() {
    let Some(font) = dejavu() else { return };
    let data = std::fs::read(&font).unwrap();
    let o = lncert::shape::glyph_outline(&data, 'o').unwrap();
    assert!(
        o.iter().all(|b| b.points().len() <= 3),
        "TrueType: lines and quadratics"
    );
    // two closed contours: consecutive pieces meet, and each contour returns to its start
    let ends = |b: &lncert::Bezier<lncert::Rational>| {
        (b.points()[0].clone(), b.points().last().unwrap().clone())
    };
    let mut contours = 0;
    let mut start = ends(&o[0]).0;
    for (i, b) in o.iter().enumerate() {
        let (_, e) = ends(b);
        let next_start = o.get(i + 1).map(|n| ends(n).0);
        if e == start {
            contours += 1;
            if let Some(n) = next_start {
                start = n;
            }
        } else {
            assert_eq!(Some(e), next_start, "piece {i} does not meet the next");
        }
    }
    assert_eq!(contours, 2, "the outer and inner contours of 'o'");
    let cert = std::env::temp_dir().join(format!("lncert-glyph-{}.json", std::process::id()));
    let run = lncert(&[
        "offset",
        font.to_str().unwrap(),
        "--glyph",
        "o",
        "--distance",
        "20",
        "--tol",
        "0.5",
        "--certificate",
        cert.to_str().unwrap(),
        "--json",
    ]);
    assert_eq!(
        run.status.code(),
        Some(0),
        "{}",
        String::from_utf8_lossy(&run.stderr)
    );
    let doc = json_of(&run);
    assert_eq!(doc["verdict"], "certified");
    let v = lncert(&["verify", cert.to_str().unwrap()]);
    assert_eq!(v.status.code(), Some(0));
    // no such glyph; not a font
    let none = lncert(&[
        "offset",
        font.to_str().unwrap(),
        "--glyph",
        "\u{10FFFD}",
        "--distance",
        "20",
        "--tol",
        "0.5",
    ]);
    assert_eq!(none.status.code(), Some(2));
    assert!(String::from_utf8_lossy(&none.stderr).contains("--glyph"));
    let text = tmp("not_a_font.json", CUBIC);
    let nf = lncert(&[
        "offset",
        text.to_str().unwrap(),
        "--glyph",
        "o",
        "--distance",
        "20",
        "--tol",
        "0.5",
    ]);
    assert_eq!(nf.status.code(), Some(2));
    assert!(String::from_utf8_lossy(&nf.stderr).contains("font"));
}

/// `offset --glyph` at 20 font units, unproven (`--no-certify`: the outline
/// is what is compared), as JSON; exits 0.
fn glyph_offset(font: &str, item: &str) -> Value {
    let o = lncert(&[
        "offset",
        font,
        "--glyph",
        item,
        "--distance",
        "20",
        "--tol",
        "1",
        "--no-certify",
        "--json",
    ]);
    assert_eq!(
        o.status.code(),
        Some(0),
        "{item:?}: {}",
        String::from_utf8_lossy(&o.stderr)
    );
    let doc = json_of(&o);
    assert!(
        !doc["pieces"].as_array().unwrap().is_empty(),
        "{item:?}: no pieces"
    );
    doc
}

/// The geometry of an offset's JSON: its pieces and joins (not its timing).
fn geometry(doc: &Value) -> (Value, Value) {
    (doc["pieces"].clone(), doc["joins"].clone())
}

/// `--glyph` takes one item as `font --glyphs` reads it: a character, a code
/// point (`uniXXXX`, `uXXXX` to `uXXXXXX`), `@name` or a bare glyph name; every
/// way of naming a glyph gives the same offset, and different glyphs differ.
#[test]
fn glyph_items_by_character_code_point_and_name_give_one_offset() {
    let Some(font) = dejavu() else { return };
    let f = font.to_str().unwrap();
    let a = geometry(&glyph_offset(f, "A"));
    for item in ["uni0041", "u0041", "u000041", "@A"] {
        assert_eq!(geometry(&glyph_offset(f, item)), a, "{item}");
    }
    let period = geometry(&glyph_offset(f, "period"));
    for item in [".", "@period", "uni002E"] {
        assert_eq!(geometry(&glyph_offset(f, item)), period, "{item}");
    }
    assert_ne!(period, a);
    // names of glyphs that are not one ASCII character
    let aacute = geometry(&glyph_offset(f, "Aacute"));
    for item in ["\u{c1}", "uni00C1", "@Aacute"] {
        assert_eq!(geometry(&glyph_offset(f, item)), aacute, "{item}");
    }
    assert_ne!(aacute, a);
    // "@" alone is the character @, the glyph named "at"
    assert_eq!(
        geometry(&glyph_offset(f, "@")),
        geometry(&glyph_offset(f, "at"))
    );
}

/// Items that name no single glyph are bad input (exit 2) naming `--glyph`
/// and the reason, in JSON and in text; never a panic.
#[test]
fn glyph_items_that_name_no_single_glyph_are_refused() {
    let Some(font) = dejavu() else { return };
    let f = font.to_str().unwrap();
    for (item, why) in [
        ("", "empty"),
        ("A-Z", "a range"),
        ("A,B", "not a comma list"),
        ("@nosuchglyph", "no glyph named \"nosuchglyph\""),
        ("nosuchglyph", "no glyph named \"nosuchglyph\""),
        ("uD800", "not a Unicode scalar value"),
        ("u110000", "not a Unicode scalar value"),
        ("uni10FFFD", "no glyph for U+10FFFD"),
        ("space", "has no outline"),
    ] {
        let args = [
            "offset",
            f,
            "--glyph",
            item,
            "--distance",
            "20",
            "--tol",
            "1",
        ];
        let o = lncert(&[&args[..], &["--json"]].concat());
        assert_eq!(o.status.code(), Some(2), "{item:?}");
        let doc = json_of(&o);
        assert_eq!(doc["error"]["field"], "--glyph", "{item:?}");
        let reason = doc["error"]["reason"].as_str().unwrap();
        assert!(reason.contains(why), "{item:?}: {reason}");
        let o = lncert(&args);
        assert_eq!(o.status.code(), Some(2), "{item:?}");
        let err = String::from_utf8_lossy(&o.stderr);
        assert!(
            err.contains("--glyph") && err.contains(why),
            "{item:?}: {err}"
        );
    }
}

/// A whole SVG document is a curve input: its paths, under their transforms.
#[test]
fn offset_reads_an_svg_document() {
    let doc = tmp(
        "doc.svg",
        r#"<?xml version="1.0"?>
<svg xmlns="http://www.w3.org/2000/svg" viewBox="0 0 10 10">
  <defs><path d="M 100 100 L 200 200"/></defs>
  <g transform="translate(1 1) scale(0.5)"><path d="M -1.9 1.4 C -0.6 1 0.6 -5 1.8 -0.4"/></g>
</svg>"#,
    );
    let o = lncert(&[
        "offset",
        doc.to_str().unwrap(),
        "--distance",
        "0.2",
        "--tol",
        "1e-3",
        "--json",
    ]);
    assert_eq!(
        o.status.code(),
        Some(0),
        "{}",
        String::from_utf8_lossy(&o.stderr)
    );
    let d = json_of(&o);
    // the transformed start point: (−1.9, 1.4)/2 + (1, 1)
    // the offset starts at distance 0.2 from the transformed start point
    let p0 = &d["pieces"][0]["control_points"][0];
    let (x, y) = (p0[0].as_f64().unwrap(), p0[1].as_f64().unwrap());
    let start = (1.0 - 0.95, 1.0 + 0.7);
    let r = (x - start.0).hypot(y - start.1);
    assert!((r - 0.2).abs() < 1e-9, "{r}: {d}");
    let bad = tmp("doc_bad.svg", r#"<svg><ellipse rx="1" ry="-2"/></svg>"#);
    let e = lncert(&[
        "offset",
        bad.to_str().unwrap(),
        "--distance",
        "0.2",
        "--tol",
        "1e-3",
    ]);
    assert_eq!(e.status.code(), Some(2));
    assert!(String::from_utf8_lossy(&e.stderr).contains("svg/ellipse[0]"));
}

/// Join arcs at G⁰ corners are inside the proof and follow the direction of
/// travel: the certificate's shapes are unions ending with the exact arcs, it
/// verifies against `--exact-out` and `--curve-out`, the JSON arc (read by the
/// shape language, `clockwise` included) starts at the end of the piece before
/// the corner, and a certificate whose arc is removed from `b` is refused.
#[test]
fn join_arcs_are_certified_and_travel_with_the_contour() {
    let svg = "M 0 0 C 1 0 2 0.5 2 0 L 2 -1 L 1 -2";
    let curve = tmp("corner.svg", svg);
    let dir = std::env::temp_dir().join(format!("lncert-joins-{}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    let (cert, b, a) = (dir.join("c.json"), dir.join("b.json"), dir.join("a.json"));
    let o = lncert(&[
        "offset",
        curve.to_str().unwrap(),
        "--distance",
        "0.1",
        "--tol",
        "1e-4",
        "--certificate",
        cert.to_str().unwrap(),
        "--curve-out",
        b.to_str().unwrap(),
        "--exact-out",
        a.to_str().unwrap(),
        "--json",
    ]);
    assert_eq!(
        o.status.code(),
        Some(0),
        "{}",
        String::from_utf8_lossy(&o.stderr)
    );
    let doc = json_of(&o);
    let joins = doc["joins"].as_array().unwrap();
    assert_eq!(joins.len(), 1, "{doc}"); // the cubic joins the first line smoothly
                                         // each arc, read as the shape language reads it, starts where the piece
                                         // before the corner ends: at corner + d·(its end normal) = the travelled `from`
    let pieces = lncert::shape::parse_curve(svg).unwrap();
    for j in joins {
        let after = j["after_piece"].as_u64().unwrap() as usize;
        let end = pieces[after].points().last().unwrap().clone();
        let center =
            lncert::shape::ShapeDesc::parse(&serde_json::json!({"arc": j["arc"]}).to_string())
                .unwrap();
        let lncert::shape::ShapeDesc::Arc(arc) = center else {
            panic!("not an arc: {j}")
        };
        assert_eq!(arc.center, end);
        // clockwise travel is stored canonically with from/to swapped
        let travelled_from = if j["arc"]["clockwise"] == true {
            &arc.to
        } else {
            &arc.from
        };
        let n = pieces[after].hodograph().points().last().unwrap().clone();
        // the travelled start direction is the left normal (−n.y, n.x) of the piece's end
        let left = lncert::V2::new(-n.y.clone(), n.x.clone());
        assert_eq!(
            travelled_from.cross(&left),
            lncert::Rational::from_integer(0.into()),
            "{j}"
        );
        assert!(
            travelled_from.dot(&left) > lncert::Rational::from_integer(0.into()),
            "{j}"
        );
    }
    let v = lncert(&[
        "verify",
        cert.to_str().unwrap(),
        "--against",
        a.to_str().unwrap(),
        b.to_str().unwrap(),
    ]);
    let text = String::from_utf8_lossy(&v.stdout);
    assert_eq!(v.status.code(), Some(0), "{text}");
    assert!(
        text.contains("the union of 2 shapes") && text.contains("circular arc"),
        "{text}"
    );
    // the arcs removed from b: the corner points are not covered any more
    let c: Value = serde_json::from_str(&std::fs::read_to_string(&cert).unwrap()).unwrap();
    let mut forged = c.clone();
    forged["b"]["union"].as_array_mut().unwrap().truncate(1);
    let f = dir.join("forged.json");
    std::fs::write(&f, forged.to_string()).unwrap();
    let v = lncert(&["verify", f.to_str().unwrap()]);
    assert_eq!(
        v.status.code(),
        Some(1),
        "{}",
        String::from_utf8_lossy(&v.stdout)
    );
}

/// A certificate between two identical arcs verifies: the foot of the arc's end
/// point is the end point itself, so the search must keep its foot maps inside
/// the verifier's own enclosure of the end parameter (a join arc is the same arc
/// in both shapes of an offset certificate).
#[test]
fn identical_arc_certificates_verify() {
    // coarse tolerances too: one box covers the whole arc, its foot map reaching the end
    let dirs = [
        ("[1, 0]", "[0, 1]"),
        ("[3, 1]", "[-1, 2]"),
        ("[2, 7]", "[-5, -3]"),
        ("[5, -3]", "[1, 1]"),
        // a join arc of DejaVu Sans 'R' offset by 20 (centre (1147, 0), radius 20)
        ("[-383, -191]", "[0, -217]"),
    ];
    for ((from, to), tol) in dirs
        .into_iter()
        .flat_map(|d| ["1e-5", "1e-2", "1/2"].map(move |t| (d, t)))
    {
        let arc = tmp(
            "same_arc.json",
            &format!(
                r#"{{"arc": {{"center": [1147, 0], "radius": 20, "from": {from}, "to": {to}}}}}"#
            ),
        );
        let cert = arc.with_file_name("same_arc_cert.json");
        let o = lncert(&[
            "hausdorff",
            arc.to_str().unwrap(),
            arc.to_str().unwrap(),
            "--tol",
            tol,
            "--certificate",
            cert.to_str().unwrap(),
        ]);
        assert_eq!(
            o.status.code(),
            Some(0),
            "{}",
            String::from_utf8_lossy(&o.stderr)
        );
        let v = lncert(&["verify", cert.to_str().unwrap()]);
        assert_eq!(
            v.status.code(),
            Some(0),
            "{from} {to} {tol}: {}",
            String::from_utf8_lossy(&v.stdout)
        );
    }
}
