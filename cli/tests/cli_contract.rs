//! The CLI contract (issue 14): one exit-code table for every subcommand
//! (0 proven / complete, 1 refuted, 2 bad input, 3 undecided / incomplete),
//! output paths refused before any work, `--json` errors as one JSON document,
//! one numeric limit for every flag. Each case below is a small, fast input
//! that lands on the code it names.

mod common;
use common::lncert;
use common::FIG4;
use serde_json::Value;
use std::path::PathBuf;
use std::time::Instant;

const CUBIC: &str = r#"{"bezier": [[-0.95, 0.7], [-0.3, 0.5], [0.3, -2.5], [0.9, -0.2]]}"#;
const ARC: &str = r#"{"arc": {"center": [0, 0], "radius": 1, "from": [1, 0], "to": [0, 1]}}"#;
const ARC_CUBIC: &str = "M 1 0 C 1 0.5523 0.5523 1 0 1";

fn code(args: &[&str]) -> i32 {
    let o = lncert(args);
    let err = String::from_utf8_lossy(&o.stderr);
    assert!(!err.contains("panicked"), "{args:?} panicked: {err}");
    o.status.code().expect("an exit code")
}

fn dir() -> PathBuf {
    let d = std::env::temp_dir().join(format!("lncert-contract-{}", std::process::id()));
    std::fs::create_dir_all(&d).unwrap();
    d
}

/// Writes an input file. The tests run in parallel and share these names, so
/// the file is written beside and renamed into place: a reader never sees it
/// half written.
fn file(name: &str, text: &str) -> String {
    use std::sync::atomic::{AtomicUsize, Ordering};
    static N: AtomicUsize = AtomicUsize::new(0);
    let p = dir().join(name);
    let part = dir().join(format!("{name}.{}.part", N.fetch_add(1, Ordering::Relaxed)));
    std::fs::write(&part, text).unwrap();
    std::fs::rename(&part, &p).unwrap();
    p.to_str().unwrap().to_string()
}

fn fig4(extra: &[&str]) -> Vec<String> {
    FIG4.iter().chain(extra).map(|s| s.to_string()).collect()
}

#[test]
fn hausdorff_exit_codes() {
    let (a, b) = (file("arc.json", ARC), file("arc_cubic.svg", ARC_CUBIC));
    // d_H ≈ 2.7607e-4
    assert_eq!(
        code(&["hausdorff", &a, &b, "--tol", "3e-4"]),
        0,
        "certified"
    );
    assert_eq!(code(&["hausdorff", &a, &b, "--tol", "2e-4"]), 1, "refuted");
    assert_eq!(
        code(&[
            "hausdorff",
            &a,
            &b,
            "--tol",
            "2.7607e-4",
            "--max-boxes",
            "4"
        ]),
        3,
        "budget ran out before the claim was decided"
    );
    assert_eq!(code(&["hausdorff", &a, &b]), 0, "gap reached");
    assert_eq!(
        code(&["hausdorff", &a, &b, "--max-boxes", "4"]),
        3,
        "no claim, budget ran out before the gap"
    );
    assert_eq!(code(&["hausdorff", &a, &b, "--tol", "-1"]), 2);
    assert_eq!(code(&["hausdorff", &a, "/nonexistent/b.svg"]), 2);
}

#[test]
fn offset_exit_codes() {
    let c = file("cubic.json", CUBIC);
    assert_eq!(
        code(&["offset", &c, "--distance", "0.4", "--tol", "1e-2"]),
        0
    );
    assert_eq!(
        code(&[
            "offset",
            &c,
            "--distance",
            "0.5",
            "--tol",
            "1e-8",
            "--max-depth",
            "1"
        ]),
        3,
        "not reached within the limits: undecided, not refuted"
    );
    assert_eq!(code(&["offset", &c, "--distance", "0", "--tol", "1e-2"]), 2);
}

#[test]
fn verify_exit_codes() {
    let (a, b) = (file("arc.json", ARC), file("arc_cubic.svg", ARC_CUBIC));
    let cert = dir().join("contract_cert.json");
    let cert_s = cert.to_str().unwrap();
    // decided by the radial proof, and stated by it: a version 4 certificate
    let o = lncert(&[
        "hausdorff",
        &a,
        &b,
        "--tol",
        "3e-4",
        "--certificate",
        cert_s,
    ]);
    let out = String::from_utf8_lossy(&o.stdout);
    assert_eq!(o.status.code(), Some(0), "{out}");
    assert!(out.contains("proof: radial"), "{out}");
    assert!(out.contains("radial cells)"), "{out}");
    assert!(!out.contains("proven again"), "{out}");
    assert_eq!(code(&["verify", cert_s]), 0, "valid");
    let text = std::fs::read_to_string(&cert).unwrap();
    assert!(text.contains("\"version\": 4"), "{text}");
    let forged = file(
        "contract_forged.json",
        &text.replace("\"3/10000\"", "\"1/10000\""),
    );
    assert_eq!(code(&["verify", &forged]), 1, "a false claim is invalid");
    // a document that is not a certificate is an invalid certificate
    let junk = file("contract_junk.json", "{not json");
    assert_eq!(code(&["verify", &junk]), 1, "not a certificate");
    assert_eq!(code(&["verify", "/nonexistent/cert.json"]), 2, "no file");
}

#[test]
fn tangency_exit_codes() {
    let run = |extra: &[&str]| {
        let args = fig4(extra);
        let a: Vec<&str> = args.iter().map(String::as_str).collect();
        code(&a)
    };
    assert_eq!(run(&["-5/2"]), 0, "complete");
    // a 4×4 raster misses the roots, and says so: incomplete
    assert_eq!(
        run(&["-5/2", "--backend", "cpu", "--resolution", "4"]),
        3,
        "incomplete raster"
    );
    assert_eq!(run(&["0"]), 2, "radius 0");
}

#[test]
fn prop_and_audit_exit_codes() {
    assert_eq!(code(&["prop", "2.1", "--x1", "3", "--y1", "-1"]), 0);
    assert_eq!(code(&["prop", "2.1", "--x1", "abc", "--y1", "-1"]), 2);
    assert_eq!(code(&["audit", "--cases", "20"]), 0);
    assert_eq!(code(&["audit", "--cases", "0"]), 2);
}

/// Output paths are checked before any work: a bad one fails at once (the
/// run below would take minutes at this tolerance), and no file is left.
#[test]
fn output_paths_are_checked_before_any_work() {
    let c = file("cubic.json", CUBIC);
    let (a, b) = (file("arc.json", ARC), file("arc_cubic.svg", ARC_CUBIC));
    let missing = "/nonexistent-lncert-dir/out.json";
    let d = dir();
    let d_s = d.to_str().unwrap();
    let cases: Vec<(Vec<&str>, &str)> = vec![
        (
            vec![
                "offset",
                &c,
                "--distance",
                "0.4",
                "--tol",
                "1e-12",
                "--svg",
                missing,
            ],
            "--svg",
        ),
        (
            vec![
                "offset",
                &c,
                "--distance",
                "0.4",
                "--tol",
                "1e-12",
                "--certificate",
                d_s,
            ],
            "--certificate",
        ),
        (
            vec![
                "hausdorff",
                &a,
                &b,
                "--rel",
                "1e-12",
                "--certificate",
                missing,
            ],
            "--certificate",
        ),
        (vec!["reproduce", "--out", "/dev/null/sub"], "--out"),
    ];
    for (args, flag) in cases {
        let start = Instant::now();
        let o = lncert(&args);
        let err = String::from_utf8_lossy(&o.stderr);
        assert_eq!(o.status.code(), Some(2), "{args:?}: {err}");
        assert!(err.contains(flag), "{args:?}: {err}");
        // no work was done: well under the run's own time
        assert!(
            start.elapsed().as_secs_f64() < 5.0,
            "{args:?} did work first"
        );
    }
    assert!(!std::path::Path::new(missing).exists());
    // a writable path that did not exist is not left behind by the check
    let fresh = d.join("contract_fresh.svg");
    let _ = std::fs::remove_file(&fresh);
    let o = lncert(&[
        "offset",
        &c,
        "--distance",
        "0",
        "--tol",
        "1e-2",
        "--svg",
        fresh.to_str().unwrap(),
    ]);
    assert_eq!(o.status.code(), Some(2));
    assert!(!fresh.exists(), "the output check left a file behind");
}

/// With `--json`, a bad input is one JSON document on stdout naming the field.
#[test]
fn json_errors_are_json() {
    let c = file("cubic.json", CUBIC);
    let (a, b) = (file("arc.json", ARC), file("arc_cubic.svg", ARC_CUBIC));
    let cases: Vec<(Vec<&str>, &str)> = vec![
        (
            vec!["offset", &c, "--distance", "0.4", "--tol", "x"],
            "--tol",
        ),
        (vec!["hausdorff", &a, &b, "--rel", "2"], "--rel"),
        (vec!["prop", "2.1", "--x1", "abc", "--y1", "1"], "--x1"),
        (vec!["audit", "--cases", "0"], "--cases"),
        (
            vec![
                "tangency", "--x1", "1e400", "--y1", "1", "--u", "1", "--center", "0,1",
                "--radius", "1",
            ],
            "--x1",
        ),
        (vec!["reproduce", "--out", "/dev/null/sub"], "--out"),
    ];
    for (mut args, field) in cases {
        args.push("--json");
        let o = lncert(&args);
        assert_eq!(o.status.code(), Some(2), "{args:?}");
        let doc: Value = serde_json::from_slice(&o.stdout).unwrap_or_else(|e| {
            panic!(
                "{args:?}: not JSON ({e}): {}",
                String::from_utf8_lossy(&o.stdout)
            )
        });
        assert_eq!(doc["error"]["field"], field, "{args:?}: {doc}");
        assert!(doc["error"]["reason"]
            .as_str()
            .is_some_and(|r| !r.is_empty()));
        assert_eq!(doc["exit_code"], 2);
    }
}

/// One limit for every number on every flag: |x| ≤ 1e100, as for shapes.
#[test]
fn every_flag_has_the_one_numeric_limit() {
    let c = file("cubic.json", CUBIC);
    let (a, b) = (file("arc.json", ARC), file("arc_cubic.svg", ARC_CUBIC));
    let too_big = "1e101";
    for args in [
        vec![
            "tangency", "--x1", too_big, "--y1", "1", "--u", "1", "--center", "0,1", "--radius",
            "1",
        ],
        [FIG4.as_slice(), &[too_big]].concat(),
        vec!["offset", &c, "--distance", too_big, "--tol", "1e-2"],
        vec!["hausdorff", &a, &b, "--tol", too_big],
        vec!["prop", "2.1", "--x1", too_big, "--y1", "1"],
    ] {
        let start = Instant::now();
        let o = lncert(&args);
        let err = String::from_utf8_lossy(&o.stderr);
        assert_eq!(o.status.code(), Some(2), "{args:?}: {err}");
        assert!(err.contains("1e100"), "{args:?}: {err}");
        assert!(start.elapsed().as_secs_f64() < 5.0);
    }
}
