//! Issue 25, stroke certificates on the command line: `stroke --certificate`
//! writes a certificate that `verify` accepts alone, and with `--against`
//! only for the outline and the curve it speaks about; an edited certificate
//! is refused at the named field; the flag is refused before any work where
//! the certificate cannot state the stroke (elliptical pen, butt caps, a
//! `{"circle"}` input, a per-element SVG document).

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
    for (args, why) in [
        (vec!["--pen", "ellipse:1,1/2", "--tol", "1e-1"], "disk"),
        (
            vec!["--pen", "circle:1/2", "--tol", "1e-1", "--cap", "butt"],
            "round",
        ),
    ] {
        let mut all = vec!["stroke", c];
        all.extend(args);
        all.extend(["--certificate", o]);
        let r = lncert(&all);
        let err = String::from_utf8_lossy(&r.stderr);
        assert_eq!(r.status.code(), Some(2), "{err}");
        assert!(err.contains("--certificate") && err.contains(why), "{err}");
        assert!(!out.exists(), "nothing written");
    }
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
    assert_eq!(r.status.code(), Some(2));
    assert!(String::from_utf8_lossy(&r.stderr).contains("--certificate"));
}
