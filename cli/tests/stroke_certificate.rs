//! Issue 25, stroke certificates on the command line: `stroke --certificate`
//! writes a certificate that `verify` accepts alone, and with `--against`
//! only for the outline and the curve it speaks about, also for an elliptical
//! pen; an edited certificate is refused at the named field; the flag is
//! refused before any work where the certificate cannot state the stroke
//! (butt caps, a `{"circle"}` input); an SVG document stroked per element
//! gets a set of certificates, one per element.

mod common;

use common::{lncert, tmp};
use lncert::stroke::{stroke, StrokeOptions};

const CURVE: &str = "M 0 0 C 1 2 3 2 4 0 L 5 1";

fn cert_of(name: &str) -> (std::path::PathBuf, std::path::PathBuf) {
    let curve = tmp(&format!("{name}.txt"), CURVE);
    let cert = curve.with_file_name(format!("{name}.cert.json"));
    let o = lncert(&[
        "stroke",
        curve.to_str().unwrap(),
        "--pen",
        "circle:1/2",
        "--tol",
        "2e-2",
        "--certificate",
        cert.to_str().unwrap(),
    ]);
    assert_eq!(
        o.status.code(),
        Some(0),
        "{}",
        String::from_utf8_lossy(&o.stderr)
    );
    assert!(
        String::from_utf8_lossy(&o.stderr).contains("stroke certificate written"),
        "{}",
        String::from_utf8_lossy(&o.stderr)
    );
    (curve, cert)
}

/// `lncert verify CERT --json EXTRA…`: the exit code and the JSON report
/// (`null` when stdout is not JSON, e.g. a usage error).
fn verify_json(cert: &std::path::Path, extra: &[&str]) -> (Option<i32>, serde_json::Value) {
    let mut args = vec!["verify", cert.to_str().unwrap(), "--json"];
    args.extend_from_slice(extra);
    let o = lncert(&args);
    let v = serde_json::from_slice(&o.stdout).unwrap_or_default();
    (o.status.code(), v)
}

#[test]
fn stroke_certificate_verifies_and_names_its_shapes() {
    let (curve, cert) = cert_of("sc");
    let o = lncert(&["verify", cert.to_str().unwrap()]);
    let out = String::from_utf8_lossy(&o.stdout);
    assert_eq!(o.status.code(), Some(0), "{out}");
    assert!(out.contains("valid: proven d_H(A, B) ≤ 1/50"), "{out}");
    assert!(out.contains("r = 1/2"), "{out}");

    // --against: the outline (as the library builds it) and the curve
    let x = lncert::parse_curve(CURVE).unwrap();
    let s = stroke(
        &x,
        &StrokeOptions::new(
            lncert::parse_rational("1/2").unwrap(),
            "2e-2".parse().unwrap(),
        ),
    )
    .unwrap();
    let outline = tmp(
        "sc-outline.json",
        &s.outline_shape().unwrap().to_json().to_string(),
    );
    let o = lncert(&[
        "verify",
        cert.to_str().unwrap(),
        "--against",
        outline.to_str().unwrap(),
        curve.to_str().unwrap(),
    ]);
    assert_eq!(
        o.status.code(),
        Some(0),
        "{}",
        String::from_utf8_lossy(&o.stdout)
    );
    let other = tmp("sc-other.txt", "M 0 0 C 1 2 3 2 4 0 L 5 2");
    let o = lncert(&[
        "verify",
        cert.to_str().unwrap(),
        "--against",
        outline.to_str().unwrap(),
        other.to_str().unwrap(),
    ]);
    let out = String::from_utf8_lossy(&o.stdout);
    assert_eq!(o.status.code(), Some(1), "{out}");
    assert!(out.contains("invalid: curve:"), "{out}");
}

#[test]
fn edited_stroke_certificates_are_refused_at_the_field() {
    let (_, cert) = cert_of("se");
    let doc: serde_json::Value =
        serde_json::from_str(&std::fs::read_to_string(&cert).unwrap()).unwrap();
    let check = |edit: &dyn Fn(&mut serde_json::Value), at: &str| {
        let mut d = doc.clone();
        edit(&mut d);
        let p = cert.with_file_name(format!("se-{}.json", at.replace(['[', ']', '.'], "_")));
        std::fs::write(&p, d.to_string()).unwrap();
        let o = lncert(&["verify", p.to_str().unwrap(), "--json"]);
        let out = String::from_utf8_lossy(&o.stdout);
        assert_eq!(o.status.code(), Some(1), "{at}: {out}");
        let v: serde_json::Value = serde_json::from_str(&out).unwrap();
        assert!(
            v["at"].as_str().unwrap().starts_with(at),
            "expected {at}, got {out}"
        );
    };
    // a smaller tolerance than the parts reach
    check(&|d| d["tol"] = "1/5000".into(), "cover[");
    // the end cap's second half dropped
    check(
        &|d| {
            d["boundary"].as_array_mut().unwrap().pop();
        },
        "boundary",
    );
    // the curve moved: its boundary is elsewhere
    check(
        &|d| d["curve"][1][1] = serde_json::json!(["5", "3/2"]),
        "cover[",
    );
    // the radius doubled
    check(&|d| d["radius"] = "1".into(), "cover[");
}

#[test]
fn certificate_flag_is_refused_where_it_cannot_state_the_stroke() {
    let curve = tmp("sr.txt", CURVE);
    let c = curve.to_str().unwrap();
    let out = curve.with_file_name("sr.cert.json");
    let o = out.to_str().unwrap();
    // butt caps: x ⊕ disk(R) has round ends
    let r = lncert(&[
        "stroke",
        c,
        "--pen",
        "circle:1/2",
        "--tol",
        "1e-1",
        "--cap",
        "butt",
        "--certificate",
        o,
    ]);
    let err = String::from_utf8_lossy(&r.stderr);
    assert_eq!(r.status.code(), Some(2), "{err}");
    assert!(
        err.contains("--certificate") && err.contains("round"),
        "{err}"
    );
    assert!(!out.exists(), "nothing written");
    let circle = tmp(
        "sr-circle.json",
        r#"{"circle": {"center": [0, 0], "radius": 2}}"#,
    );
    let r = lncert(&[
        "stroke",
        circle.to_str().unwrap(),
        "--pen",
        "circle:1/2",
        "--tol",
        "1e-2",
        "--certificate",
        o,
    ]);
    // a {"circle"} is certified as its four exact quarter arcs
    assert_eq!(
        r.status.code(),
        Some(0),
        "{}",
        String::from_utf8_lossy(&r.stderr)
    );
    let v = lncert(&["verify", o]);
    let vout = String::from_utf8_lossy(&v.stdout);
    assert_eq!(v.status.code(), Some(0), "{vout}");
    assert!(
        vout.contains("4 exact arcs") && vout.contains("(1 closed)"),
        "{vout}"
    );
    std::fs::remove_file(&out).unwrap();
    // with an elliptical pen it is refused
    let r = lncert(&[
        "stroke",
        circle.to_str().unwrap(),
        "--pen",
        "ellipse:1,1/2",
        "--tol",
        "1e-2",
        "--certificate",
        o,
    ]);
    assert_eq!(r.status.code(), Some(2));
    assert!(!out.exists());
}

/// `hausdorff X STROKE.json --tol T --certificate C`: a stroke distance
/// certificate that `verify` accepts; edited so that its parts no longer add
/// up, or about another outline, it is refused.
#[test]
fn distance_certificate_of_another_outline_verifies() {
    let stroke = tmp(
        "sd-stroke.json",
        r#"{"stroke": {"curve": "M 0 0 L 4 0", "pen": {"circle": "1/2"}}}"#,
    );
    let x = tmp(
        "sd-x.txt",
        "M -0.5 -0.51 L 4.5 -0.51 L 4.5 0.51 L -0.5 0.51 Z",
    );
    let cert = x.with_file_name("sd.cert.json");
    let run = |tol: &str| {
        lncert(&[
            "hausdorff",
            x.to_str().unwrap(),
            stroke.to_str().unwrap(),
            "--tol",
            tol,
            "--certificate",
            cert.to_str().unwrap(),
        ])
    };
    // the corners are ≈ 0.2163 from the caps: 1/5 is refuted, nothing written
    let o = run("1/5");
    assert_eq!(
        o.status.code(),
        Some(1),
        "{}",
        String::from_utf8_lossy(&o.stdout)
    );
    assert!(!cert.exists());
    let o = run("1/4");
    assert_eq!(
        o.status.code(),
        Some(0),
        "{}",
        String::from_utf8_lossy(&o.stderr)
    );
    let v = lncert(&["verify", cert.to_str().unwrap()]);
    let out = String::from_utf8_lossy(&v.stdout);
    assert_eq!(v.status.code(), Some(0), "{out}");
    assert!(out.contains("≤ 1/4") && out.contains("r = 1/2"), "{out}");
    let doc: serde_json::Value =
        serde_json::from_str(&std::fs::read_to_string(&cert).unwrap()).unwrap();
    let refused_at = |d: serde_json::Value, at: &str| {
        let p = cert.with_file_name("sd-edit.json");
        std::fs::write(&p, d.to_string()).unwrap();
        let o = lncert(&["verify", p.to_str().unwrap(), "--json"]);
        assert_eq!(o.status.code(), Some(1));
        let v: serde_json::Value = serde_json::from_slice(&o.stdout).unwrap();
        assert!(v["at"].as_str().unwrap().starts_with(at), "{at}: {v}");
    };
    // a claim smaller than the parts' sum
    let mut d = doc.clone();
    d["tol"] = "1/5".into();
    refused_at(d, "tol");
    // the Hausdorff part about another outline (its b translated)
    let mut d = doc.clone();
    let b = d["shape_to_outline"]["b"]
        .to_string()
        .replace("\"1/2\"", "\"3/5\"");
    d["shape_to_outline"]["b"] = serde_json::from_str(&b).unwrap();
    refused_at(d, "shape_to_outline");

    // issue 65: `verify --against X STROKE.json` (either order, as `hausdorff`
    // takes them) confirms the shape, the curve and the pen of a distance
    // certificate; `--against X CURVE --pen circle:R` the same
    let verify = |extra: &[&str]| verify_json(&cert, extra);
    let (xs, ss) = (x.to_str().unwrap(), stroke.to_str().unwrap());
    let curve = tmp("sd-curve.txt", "M 0 0 L 4 0");
    for args in [
        vec!["--against", xs, ss],
        vec!["--against", ss, xs],
        vec!["--against", ss],
        vec![
            "--against",
            xs,
            curve.to_str().unwrap(),
            "--pen",
            "circle:1/2",
            "--tol",
            "1/4",
        ],
    ] {
        let (code, v) = verify(&args);
        assert_eq!(code, Some(0), "{args:?}: {v}");
    }
    let wide = tmp(
        "sd-stroke-wide.json",
        r#"{"stroke": {"curve": "M 0 0 L 4 0", "pen": {"circle": "3/5"}}}"#,
    );
    let longer = tmp(
        "sd-stroke-long.json",
        r#"{"stroke": {"curve": "M 0 0 L 5 0", "pen": {"circle": "1/2"}}}"#,
    );
    let other_x = tmp(
        "sd-x2.txt",
        "M -0.5 -0.52 L 4.5 -0.51 L 4.5 0.51 L -0.5 0.51 Z",
    );
    for (args, at) in [
        (
            vec!["--against", xs, wide.to_str().unwrap()],
            "outline_to_stroke.radius",
        ),
        (
            vec!["--against", xs, longer.to_str().unwrap()],
            "outline_to_stroke.curve",
        ),
        (
            vec!["--against", other_x.to_str().unwrap(), ss],
            "shape_to_outline.a",
        ),
        (vec!["--tol", "1/5"], "tol"),
    ] {
        let (code, v) = verify(&args);
        assert_eq!(
            (code, v["at"].as_str()),
            (Some(1), Some(at)),
            "{args:?}: {v}"
        );
    }
    // a --pen that contradicts the stroke given: a usage error
    assert_eq!(
        verify(&["--against", xs, ss, "--pen", "circle:1"]).0,
        Some(2)
    );
}

/// Glyphs: a certificate for DejaVu Sans `A` (straight pieces whose foot maps
/// end exactly at a piece's end: the writer once stepped past it by a rounding)
/// and `S` (curved, with join arcs), both simple with one hole or none.
#[test]
fn glyph_stroke_certificates_verify() {
    let Some(font) = common::dejavu() else { return };
    for (g, holes) in [("A", 1), ("S", 0)] {
        let cert = tmp(&format!("glyph-{g}.cert.json"), "");
        let o = lncert(&[
            "stroke",
            font.to_str().unwrap(),
            "--glyph",
            g,
            "--pen",
            "circle:20",
            "--tol",
            "1/2",
            "--certificate",
            cert.to_str().unwrap(),
        ]);
        let err = String::from_utf8_lossy(&o.stderr);
        assert_eq!(o.status.code(), Some(0), "{g}: {err}");
        let v = lncert(&["verify", cert.to_str().unwrap()]);
        let out = String::from_utf8_lossy(&v.stdout);
        assert_eq!(v.status.code(), Some(0), "{g}: {out}");
        assert!(out.contains("simple and disjoint"), "{g}: {out}");
        // the stroke of a glyph outline with h holes: the contours' outer and
        // inner boundaries, 2 (h + 1) contours, half of them clockwise
        let want = format!("{} clockwise", holes + 1);
        assert!(out.contains(&want), "{g}: {out}");
    }
}

/// An elliptical pen (a rotated one, whose matrix is the rational rotation
/// the stroke used): `stroke --certificate` writes a certificate that
/// `verify` accepts and whose statement names the matrix; `--against` the
/// outline and the curve it speaks about; `hausdorff X STROKE.json
/// --certificate` through it; a doubled matrix entry is refused.
#[test]
fn elliptical_pen_certificates_verify() {
    let curve = tmp("se-ell.txt", "M 0 0 C 1 2 3 2 4 0");
    let cert = curve.with_file_name("se-ell.cert.json");
    let path = curve.with_file_name("se-ell.path");
    let o = lncert(&[
        "stroke",
        curve.to_str().unwrap(),
        "--pen",
        "ellipse:0.7,0.3,pi/6",
        "--tol",
        "1e-2",
        "--output",
        "cubic",
        "--path-out",
        path.to_str().unwrap(),
        "--certificate",
        cert.to_str().unwrap(),
    ]);
    let err = String::from_utf8_lossy(&o.stderr);
    assert_eq!(o.status.code(), Some(0), "{err}");
    assert!(err.contains("stroke certificate written"), "{err}");
    let v = lncert(&["verify", cert.to_str().unwrap()]);
    let out = String::from_utf8_lossy(&v.stdout);
    assert_eq!(v.status.code(), Some(0), "{out}");
    assert!(out.contains("≤ 1/100") && out.contains("M = [["), "{out}");
    // --pen: the pen as `stroke` builds it at this tolerance is the
    // certificate's; another rotation, or no --tol to build it at, is not
    let pen_check = |pen: &str, tol: Option<&str>| match tol {
        Some(t) => verify_json(&cert, &["--pen", pen, "--tol", t]),
        None => verify_json(&cert, &["--pen", pen]),
    };
    let (code, v) = pen_check("ellipse:0.7,0.3,pi/6", Some("1e-2"));
    assert_eq!(code, Some(0), "{v}");
    assert_eq!(v["confirmed"], serde_json::json!(["pen", "tol"]), "{v}");
    let (code, v) = pen_check("ellipse:0.7,0.3,pi/5", Some("1e-2"));
    assert_eq!((code, v["at"].as_str()), (Some(1), Some("pen")), "{v}");
    let (code, v) = pen_check("circle:0.7", Some("1e-2"));
    assert_eq!((code, v["at"].as_str()), (Some(1), Some("pen")), "{v}");
    assert_eq!(pen_check("ellipse:0.7,0.3,pi/6", None).0, Some(2));
    let doc: serde_json::Value =
        serde_json::from_str(&std::fs::read_to_string(&cert).unwrap()).unwrap();
    let m = &doc["pen"]["ellipse"];
    // --against: the outline as the library builds it, and the curve
    let q = |s: &str| lncert::parse_rational(s).unwrap();
    // the pen the stroke used: the certificate's matrix (a rational rotation
    // chosen for the tolerance)
    let e = |i: usize, j: usize| q(m[i][j].as_str().unwrap());
    let pen = lncert::offset::Pen::from_matrix([[e(0, 0), e(0, 1)], [e(1, 0), e(1, 1)]]).unwrap();
    let mut opts = StrokeOptions::with_pen(
        lncert::stroke::PenShape::Ellipse(pen),
        "1e-2".parse().unwrap(),
    );
    opts.output = lncert::offset::Output::Cubic;
    let s = stroke(&lncert::parse_curve("M 0 0 C 1 2 3 2 4 0").unwrap(), &opts).unwrap();
    let outline = tmp(
        "se-ell-outline.json",
        &s.outline_shape().unwrap().to_json().to_string(),
    );
    let o = lncert(&[
        "verify",
        cert.to_str().unwrap(),
        "--against",
        outline.to_str().unwrap(),
        curve.to_str().unwrap(),
    ]);
    assert_eq!(
        o.status.code(),
        Some(0),
        "{}",
        String::from_utf8_lossy(&o.stdout)
    );
    // the stroke's own matrix in a stroke shape: a distance certificate
    let shape = tmp(
        "se-ell-stroke.json",
        &serde_json::json!({"stroke": {"curve": "M 0 0 C 1 2 3 2 4 0", "pen": {"ellipse": m}}})
            .to_string(),
    );
    let dcert = curve.with_file_name("se-ell.dist.json");
    let o = lncert(&[
        "hausdorff",
        path.to_str().unwrap(),
        shape.to_str().unwrap(),
        "--tol",
        "1/20",
        "--certificate",
        dcert.to_str().unwrap(),
    ]);
    assert_eq!(
        o.status.code(),
        Some(0),
        "{}",
        String::from_utf8_lossy(&o.stderr)
    );
    let v = lncert(&["verify", dcert.to_str().unwrap()]);
    let out = String::from_utf8_lossy(&v.stdout);
    assert_eq!(v.status.code(), Some(0), "{out}");
    assert!(out.contains("≤ 1/20") && out.contains("M = [["), "{out}");
    // a doubled matrix entry: refused in the cover or the boundary
    let mut d = doc.clone();
    let e = lncert::parse_rational(m[0][0].as_str().unwrap()).unwrap()
        * lncert::Rational::from_integer(2.into());
    d["pen"]["ellipse"][0][0] = lncert::scalar::rational_to_string(&e).into();
    let p = cert.with_file_name("se-ell-edit.json");
    std::fs::write(&p, d.to_string()).unwrap();
    let o = lncert(&["verify", p.to_str().unwrap(), "--json"]);
    assert_eq!(o.status.code(), Some(1));
    let v: serde_json::Value = serde_json::from_slice(&o.stdout).unwrap();
    let at = v["at"].as_str().unwrap();
    assert!(
        at.starts_with("cover[") || at.starts_with("boundary["),
        "{v}"
    );
}

/// An SVG document stroked per element (each its own `stroke-width`):
/// `--certificate` writes a certificate set that `verify` accepts, naming
/// every element; an element's certificate forged is refused under
/// `members[k]`; `--against` is refused for a set.
#[test]
fn svg_document_certificate_set_verifies() {
    let doc = tmp(
        "set-icon.svg",
        r#"<svg xmlns="http://www.w3.org/2000/svg" viewBox="0 0 24 24" fill="none" stroke="black" stroke-width="2"><circle cx="12" cy="12" r="3"/><polyline points="4 17 10 11 4 5" stroke-width="1"/><path d="M20 2 L22 2" stroke="none"/></svg>"#,
    );
    let cert = doc.with_file_name("set-icon.cert.json");
    let o = lncert(&[
        "stroke",
        doc.to_str().unwrap(),
        "--tol",
        "1e-2",
        "--certificate",
        cert.to_str().unwrap(),
    ]);
    let err = String::from_utf8_lossy(&o.stderr);
    assert_eq!(o.status.code(), Some(0), "{err}");
    assert!(err.contains("stroke certificate set (2 elements)"), "{err}");
    let v = lncert(&["verify", cert.to_str().unwrap()]);
    let out = String::from_utf8_lossy(&v.stdout);
    assert_eq!(v.status.code(), Some(0), "{out}");
    assert!(
        out.contains("≤ 1/100") && out.contains("svg/circle[0], svg/polyline[0]"),
        "{out}"
    );
    // each member states its own pen: the circle's radius 1, the polyline's 1/2
    let set: serde_json::Value =
        serde_json::from_str(&std::fs::read_to_string(&cert).unwrap()).unwrap();
    assert_eq!(set["members"][0]["certificate"]["radius"], "1");
    assert_eq!(set["members"][1]["certificate"]["radius"], "1/2");
    // the polyline's pen claimed as the circle's: refused under members[1]
    let mut forged = set.clone();
    forged["members"][1]["certificate"]["radius"] = "1".into();
    let p = cert.with_file_name("set-icon-forged.json");
    std::fs::write(&p, forged.to_string()).unwrap();
    let o = lncert(&["verify", p.to_str().unwrap(), "--json"]);
    assert_eq!(o.status.code(), Some(1));
    let v: serde_json::Value = serde_json::from_slice(&o.stdout).unwrap();
    assert!(
        v["at"]
            .as_str()
            .unwrap()
            .starts_with("members[1].certificate."),
        "{v}"
    );
    let o = lncert(&[
        "verify",
        cert.to_str().unwrap(),
        "--against",
        doc.to_str().unwrap(),
        doc.to_str().unwrap(),
    ]);
    assert_eq!(o.status.code(), Some(1));
    // --pen confirms every member's pen: the polyline's is not the circle's
    let o = lncert(&[
        "verify",
        cert.to_str().unwrap(),
        "--pen",
        "circle:1",
        "--json",
    ]);
    assert_eq!(o.status.code(), Some(1));
    let v: serde_json::Value = serde_json::from_slice(&o.stdout).unwrap();
    assert_eq!(v["at"], "members[1].certificate.radius", "{v}");
    let o = lncert(&["verify", cert.to_str().unwrap(), "--tol", "1/100"]);
    assert_eq!(o.status.code(), Some(0));
}

/// Issue 65: `verify --against CURVE --pen circle:R --tol T` confirms the
/// curve, the pen and the tolerance of a stroke certificate: each mismatch
/// is invalid (exit 1) at its field; a smaller proven tolerance proves a
/// larger one; the same pen given as an ellipse is the same pen.
#[test]
fn verify_confirms_the_pen_and_the_tolerance() {
    let (curve, cert) = cert_of("pt");
    let other = tmp("pt-other.txt", "M 0 0 C 1 2 3 2 4 0 L 5 2");
    let run = |extra: &[&str]| verify_json(&cert, extra);
    let c = curve.to_str().unwrap();
    let (code, v) = run(&["--against", c, "--pen", "circle:0.5", "--tol", "2e-2"]);
    assert_eq!(code, Some(0), "{v}");
    assert_eq!(v["confirmed"], serde_json::json!(["shapes", "pen", "tol"]));
    // a larger tolerance is proven too; the disk as a round ellipse is the disk
    assert_eq!(run(&["--tol", "1/10"]).0, Some(0));
    assert_eq!(
        run(&["--pen", "ellipse:1/2,1/2", "--tol", "2e-2"]).0,
        Some(0)
    );
    for (extra, at) in [
        (vec!["--pen", "circle:1/3"], "radius"),
        (vec!["--pen", "ellipse:1,1/2", "--tol", "2e-2"], "radius"),
        (vec!["--tol", "1e-2"], "tol"),
        (vec!["--against", other.to_str().unwrap()], "curve"),
    ] {
        let (code, v) = run(&extra);
        assert_eq!(
            (code, v["at"].as_str()),
            (Some(1), Some(at)),
            "{extra:?}: {v}"
        );
    }
    // bad options are usage errors, before any work
    assert_eq!(run(&["--pen", "circle:-1"]).0, Some(2));
    assert_eq!(run(&["--tol", "0"]).0, Some(2));
    // the text report says what was confirmed
    let o = lncert(&["verify", cert.to_str().unwrap(), "--pen", "circle:1/2"]);
    let out = String::from_utf8_lossy(&o.stdout);
    assert!(out.contains("the pen is the disk of radius 1/2"), "{out}");
}

/// `verify --against` takes the outline as the user has it: the SVG that
/// `stroke --out` wrote (lines and exact `A` arcs in path order), or its path
/// data, though the certificate lists all Bézier pieces before its arcs. The
/// same path with the inner corner moved, an arc replaced by a line, or an arc's sweep
/// flag flipped is refused.
#[test]
fn stroke_certificate_verifies_against_its_own_svg_output() {
    let curve = tmp("sco.txt", "M 0 0 L 4 0 L 4 3");
    let (cert, svg) = (
        curve.with_file_name("sco.cert.json"),
        curve.with_file_name("sco.svg"),
    );
    let o = lncert(&[
        "stroke",
        curve.to_str().unwrap(),
        "--pen",
        "circle:1",
        "--tol",
        "1e-3",
        "--certificate",
        cert.to_str().unwrap(),
        "--out",
        svg.to_str().unwrap(),
    ]);
    assert_eq!(
        o.status.code(),
        Some(0),
        "{}",
        String::from_utf8_lossy(&o.stderr)
    );
    let doc = std::fs::read_to_string(&svg).unwrap();
    let start = doc.find(" d=\"").expect("a path") + 4;
    let d = &doc[start..start + doc[start..].find('"').unwrap()];
    assert!(d.contains(" A "), "{d}");
    let path = tmp("sco-path.txt", d);
    let against = |outline: &std::path::Path| {
        lncert(&[
            "verify",
            cert.to_str().unwrap(),
            "--against",
            outline.to_str().unwrap(),
            curve.to_str().unwrap(),
        ])
    };
    for outline in [&svg, &path] {
        let o = against(outline);
        let out = String::from_utf8_lossy(&o.stdout);
        assert_eq!(o.status.code(), Some(0), "{}: {out}", outline.display());
        assert!(
            out.contains("exactly the shapes given to --against"),
            "{out}"
        );
    }
    // the inner corner (between two lines, no arc touched) moved by 1/1000;
    // the first arc replaced by a line
    let moved = d.replacen("L 3 1 L", "L 3.001 1 L", 1);
    assert_ne!(moved, d, "{d}");
    let mut tokens: Vec<&str> = d.split_whitespace().collect();
    let a = tokens.iter().position(|t| *t == "A").unwrap();
    // A rx ry φ fA fS x y  →  L x y
    tokens.splice(a..a + 6, ["L"]);
    let dropped = tokens.join(" ");
    // the first arc's sweep flag flipped: the other half of its circle
    let flipped = d.replacen("A 1 1 0 0 1", "A 1 1 0 0 0", 1);
    assert_ne!(flipped, d, "{d}");
    for (name, bad) in [("moved", moved), ("dropped", dropped), ("flipped", flipped)] {
        let o = against(&tmp(&format!("sco-{name}.txt"), &bad));
        let out = String::from_utf8_lossy(&o.stdout);
        assert_eq!(o.status.code(), Some(1), "{name}: {bad}: {out}");
        assert!(out.contains("invalid: outline:"), "{name}: {out}");
    }
}

/// Issue 25 item 4: a stroke shape whose curve has exact arcs (a rounded
/// rect's path data) is the boundary of the exact arcs' stroke. Its exact
/// boundary — two rounded rects, radii 3 and 1 — is certified within 1e-2
/// (d_H = 0), the certificate verifies and states the exact arcs; the inner
/// corners drawn with radius 1.2 (about 0.083 off) are refuted.
#[test]
fn distance_certificate_against_a_curve_with_exact_arcs() {
    let stroke = tmp(
        "sda-stroke.json",
        r#"{"stroke": {"curve": "M 2 0 L 8 0 A 2 2 0 0 1 10 2 L 10 4 A 2 2 0 0 1 8 6 L 2 6 A 2 2 0 0 1 0 4 L 0 2 A 2 2 0 0 1 2 0 Z", "pen": {"circle": "1"}}}"#,
    );
    let exact = tmp(
        "sda-x.svg",
        r#"<svg><rect x="-1" y="-1" width="12" height="8" rx="3"/><rect x="1" y="1" width="8" height="4" rx="1"/></svg>"#,
    );
    let off = tmp(
        "sda-off.svg",
        r#"<svg><rect x="-1" y="-1" width="12" height="8" rx="3"/><rect x="1" y="1" width="8" height="4" rx="1.2"/></svg>"#,
    );
    let cert = exact.with_file_name("sda.cert.json");
    let run = |x: &std::path::Path| {
        lncert(&[
            "hausdorff",
            x.to_str().unwrap(),
            stroke.to_str().unwrap(),
            "--tol",
            "1e-2",
            "--certificate",
            cert.to_str().unwrap(),
        ])
    };
    let o = run(&off);
    let out = String::from_utf8_lossy(&o.stdout);
    assert_eq!(o.status.code(), Some(1), "{out}");
    assert!(!cert.exists());
    let o = run(&exact);
    let out = String::from_utf8_lossy(&o.stdout);
    assert_eq!(
        o.status.code(),
        Some(0),
        "{out}{}",
        String::from_utf8_lossy(&o.stderr)
    );
    assert!(!out.contains("approximated"), "{out}");
    let v = lncert(&["verify", cert.to_str().unwrap()]);
    let vout = String::from_utf8_lossy(&v.stdout);
    assert_eq!(v.status.code(), Some(0), "{vout}");
    assert!(
        vout.contains("≤ 1/100") && vout.contains("4 exact arcs"),
        "{vout}"
    );
    // the certificate's curve states the quarter arcs exactly
    let doc: serde_json::Value =
        serde_json::from_str(&std::fs::read_to_string(&cert).unwrap()).unwrap();
    let curve = doc["outline_to_stroke"]["curve"].as_array().unwrap();
    assert_eq!(curve.iter().filter(|p| p.get("arc").is_some()).count(), 4);
}
