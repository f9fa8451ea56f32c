//! Integration tests of `lncert tangency`: one JSON document with the
//! documented keys, exit codes 0/1/2, bad input naming the flag, the exact
//! backend agreeing with the complete one.

mod common;
use common::lncert;
use common::FIG4;
use serde_json::Value;
use std::process::Output;

fn with(extra: &[&str]) -> Vec<String> {
    FIG4.iter().chain(extra).map(|s| s.to_string()).collect()
}

fn run(args: &[String]) -> Output {
    let a: Vec<&str> = args.iter().map(|s| s.as_str()).collect();
    lncert(&a)
}

fn json(args: &[String]) -> (Value, i32) {
    let mut all = args.to_vec();
    all.push("--json".into());
    let o = run(&all);
    let out = String::from_utf8_lossy(&o.stdout);
    let doc: Value = serde_json::from_str(&out).unwrap_or_else(|e| panic!("not JSON ({e}): {out}"));
    (doc, o.status.code().unwrap())
}

fn assert_bad(args: &[String], needle: &str) {
    let o = run(args);
    let err = String::from_utf8_lossy(&o.stderr);
    assert_eq!(o.status.code(), Some(2), "{args:?}: {err}");
    assert!(err.contains(needle), "{args:?}: {err:?} lacks {needle:?}");
    assert!(!err.contains("panicked"));
}

#[test]
fn fig4_like_json_two_nonsingular_roots_exit_0() {
    let (doc, code) = json(&with(&["-5/2"]));
    assert_eq!(code, 0, "{doc}");
    assert_eq!(doc["complete"], true);
    assert_eq!(doc["backend"], "complete");
    assert_eq!(doc["bezout_bound"], 60);
    let roots = doc["roots"].as_array().unwrap();
    assert_eq!(roots.len(), 2);
    for r in roots {
        assert_eq!(r["certified"], true);
        assert_eq!(r["nonsingular"], true);
        assert_eq!(r["side"], "requested");
        let m = r["m"].as_array().unwrap();
        assert!(m[0].as_f64().unwrap() <= m[1].as_f64().unwrap());
    }
    assert!(doc["undecided_boxes"].as_array().unwrap().is_empty());
    assert!(doc["krawczyk_iterations"].as_u64().unwrap() > 0);
    assert!(doc["boxes"].as_u64().unwrap() > 0);
    // The planted root m = 3/4, a2 = -5.
    assert!(roots.iter().any(|r| {
        let m = r["m"].as_array().unwrap();
        let a = r["a2"].as_array().unwrap();
        m[0].as_f64().unwrap() <= 0.75
            && 0.75 <= m[1].as_f64().unwrap()
            && a[0].as_f64().unwrap() <= -5.0
            && -5.0 <= a[1].as_f64().unwrap()
    }));
}

#[test]
fn exact_backend_agrees_and_opposite_radius_flips_the_side() {
    let (c, _) = json(&with(&["-5/2"]));
    let (e, code) = json(&with(&["-5/2", "--backend", "exact"]));
    assert_eq!(code, 0);
    assert_eq!(e["backend"], "exact");
    let (cr, er) = (
        c["roots"].as_array().unwrap(),
        e["roots"].as_array().unwrap(),
    );
    assert_eq!(cr.len(), er.len());
    for (a, b) in cr.iter().zip(er) {
        let lo = |v: &Value, k: &str, i: usize| v[k][i].as_f64().unwrap();
        // Enclosures of the same root overlap.
        assert!(lo(a, "m", 0) <= lo(b, "m", 1) && lo(b, "m", 0) <= lo(a, "m", 1));
    }
    let (o, code) = json(&with(&["5/2"]));
    assert_eq!(code, 0);
    assert!(o["roots"]
        .as_array()
        .unwrap()
        .iter()
        .all(|r| r["side"] == "opposite"));
}

#[test]
fn radii_flag_reports_inner_and_outer() {
    let (doc, code) = json(&with(&["-5/2", "--radii"]));
    assert_eq!(code, 0);
    let outer = doc["radii"]["outer"].as_array().unwrap();
    assert!(outer
        .iter()
        .any(|o| o[0].as_f64().unwrap() <= -2.5 && -2.5 <= o[1].as_f64().unwrap()));
    assert!(!doc["radii"]["inner"].as_array().unwrap().is_empty());
}

#[test]
fn human_output_is_a_table() {
    let o = run(&with(&["-5/2"]));
    let out = String::from_utf8_lossy(&o.stdout);
    assert_eq!(o.status.code(), Some(0));
    assert!(
        out.contains("nonsingular") && out.contains("2 roots, complete"),
        "{out}"
    );
}

#[test]
fn user_window_and_incomplete_exit_3() {
    // A window with no solution: complete and empty, exit 0.
    let (doc, code) = json(&with(&["-5/2", "--a2-range", "100,200"]));
    assert_eq!(code, 0);
    assert!(doc["roots"].as_array().unwrap().is_empty());
    assert_eq!(doc["a2_range"][0], "100");
    // Circle through the start point with the start normal: a line of
    // solutions at m = 0, never certifiable -> exit 3.
    let (doc, code) = json(
        &[
            "tangency",
            "--x1",
            "3",
            "--y1",
            "-1",
            "--u",
            "1",
            "--center",
            "0,2",
            "--radius",
            "2",
            "--a2-range",
            "-1,1",
        ]
        .map(String::from),
    );
    assert_eq!(code, 3, "{doc}");
    assert_eq!(doc["complete"], false);
    assert_eq!(doc["lines_of_solutions"][0]["m"], "0");
}

#[test]
fn bad_input_names_the_flag() {
    assert_bad(&with(&["0"]), "--radius");
    assert_bad(&with(&["1/0"]), "--radius");
    assert_bad(&with(&["NaN"]), "--radius");
    assert_bad(&with(&["1", "--a2-range", "2,1"]), "--a2-range");
    assert_bad(&with(&["1", "--a2-range", "1,1"]), "--a2-range");
    assert_bad(&with(&["1", "--a2-range", "inf,1"]), "--a2-range");
    assert_bad(&with(&["1", "--a2-range", "-1e400,1"]), "--a2-range");
    assert_bad(
        &with(&["1", "--backend", "gpu", "--resolution", "0"]),
        "--resolution",
    );
    assert_bad(
        &with(&["1", "--backend", "cpu", "--resolution", "16385"]),
        "--resolution",
    );
    assert_bad(&with(&["1", "--backend", "quantum"]), "--backend");
    let base = |x1: &str, u: &str| -> Vec<String> {
        [
            "tangency", "--x1", x1, "--y1", "1", "--u", u, "--center", "0,0", "--radius", "1",
        ]
        .map(String::from)
        .to_vec()
    };
    assert_bad(&base("0", "1"), "--x1");
    assert_bad(&base("1", "0"), "--u");
    assert_bad(&base("1", "-2"), "--u");
    assert_bad(&["tangency", "--x1", "1"].map(String::from), "--y1");
    assert_bad(&with(&["1", "--center", "1"]), "--center");
}

/// The raster backends (the paper's scheme): candidates certified by Krawczyk and
/// compared with the complete solver; CPU and GPU (or its CPU fallback) agree.
#[test]
fn raster_backends_find_the_two_roots_and_report_misses() {
    let mut cells = Vec::new();
    for backend in ["cpu", "gpu"] {
        let (doc, code) = json(&with(&[
            "-5/2",
            "--backend",
            backend,
            "--resolution",
            "256",
        ]));
        assert_eq!(code, 0, "{doc}");
        assert_eq!(doc["complete"], false, "a raster alone is never complete");
        let r = &doc["raster"];
        assert_eq!(r["resolution"], 256);
        assert_eq!(r["complete_roots"], 2);
        assert_eq!(r["missed"], 0);
        assert_eq!(r["checked_complete"], true);
        assert_eq!(doc["roots"].as_array().unwrap().len(), 2);
        cells.push(r["candidates"].clone());
    }
    assert_eq!(cells[0], cells[1], "CPU and GPU rasters disagree");
    // A coarse raster misses roots; the comparison says so and the exit code is 3.
    let (doc, code) = json(&with(&["-5/2", "--backend", "cpu", "--resolution", "2"]));
    let missed = doc["raster"]["missed"].as_u64().unwrap();
    assert_eq!(code, if missed == 0 { 0 } else { 3 }, "{doc}");
}
