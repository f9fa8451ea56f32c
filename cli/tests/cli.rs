//! Integration tests of the `lncert` binary: the CLI contract of
//! `docs/architecture.md` (exact output, one JSON document, exit codes 0/1/2,
//! messages naming the field).

mod common;
use common::lncert;

use serde_json::Value;
use std::process::Output;

const FIG5A_LEFT: &str = "5/2,-1;1/2,1;7/2,5";
const FIG5A_RIGHT: &str = "5/2,-4;1,-5/2;2,-7/6";

fn stdout(o: &Output) -> String {
    String::from_utf8_lossy(&o.stdout).into_owned()
}

fn stderr(o: &Output) -> String {
    String::from_utf8_lossy(&o.stderr).into_owned()
}

/// Runs with `--json` appended and parses stdout as exactly one JSON document.
fn json(args: &[&str]) -> (Value, i32) {
    let mut all = args.to_vec();
    all.push("--json");
    let o = lncert(&all);
    let doc: Value = serde_json::from_str(&stdout(&o))
        .unwrap_or_else(|e| panic!("not one JSON document ({e}): {}", stdout(&o)));
    (doc, o.status.code().expect("exit code"))
}

fn assert_bad_input(args: &[&str], needle: &str) {
    let o = lncert(args);
    assert_eq!(
        o.status.code(),
        Some(2),
        "{args:?}: stdout {} stderr {}",
        stdout(&o),
        stderr(&o)
    );
    assert!(
        stderr(&o).contains(needle),
        "{args:?}: stderr {:?} should contain {needle:?}",
        stderr(&o)
    );
    assert!(!stderr(&o).contains("panicked"), "{args:?} panicked");
}

#[test]
fn prop_2_1_prints_the_exact_range() {
    let o = lncert(&["prop", "2.1", "--x1", "3", "--y1", "-1"]);
    assert_eq!(o.status.code(), Some(0), "{}", stderr(&o));
    assert!(stdout(&o).contains("(1/2, 1)"), "{}", stdout(&o));
}

#[test]
fn prop_2_1_json_has_the_range_as_strings() {
    let (doc, code) = json(&["prop", "2.1", "--x1", "3", "--y1", "-1"]);
    assert_eq!(code, 0);
    assert_eq!(doc["results"]["u_range"], serde_json::json!(["1/2", "1"]));
    assert_eq!(doc["inputs"]["y1"], "-1");
}

#[test]
fn prop_2_1_with_u_agrees_with_the_direct_check() {
    for (u, regular) in [("0.75", true), ("2", false), ("1", false)] {
        let (doc, code) = json(&["prop", "003:2.1", "--x1", "3", "--y1", "-1", "--u", u]);
        assert_eq!(code, 0, "u = {u}");
        assert_eq!(doc["verdict"], regular, "u = {u}");
        assert_eq!(doc["direct"], regular, "u = {u}");
        assert_eq!(doc["agrees"], true, "u = {u}");
    }
}

#[test]
fn bad_numbers_exit_2_naming_the_field() {
    assert_bad_input(&["prop", "2.1", "--x1", "0", "--y1", "1"], "x1");
    assert_bad_input(&["prop", "2.1", "--x1", "abc", "--y1", "1"], "--x1");
    assert_bad_input(&["prop", "2.1", "--x1", "NaN", "--y1", "1"], "--x1");
    assert_bad_input(
        &["prop", "2.1", "--x1", "3", "--y1", "-1", "--u", "-1"],
        "--u",
    );
    assert_bad_input(
        &["prop", "4.1", "--frame", "0,0;1,1;2,2", "--rho", "1"],
        "collinear",
    );
    assert_bad_input(&["prop", "7.1", "--tau", "1/3"], "--tau");
}

#[test]
fn missing_unknown_unused_and_ambiguous_are_bad_input() {
    assert_bad_input(&["prop", "2.1", "--x1", "3"], "--y1");
    assert_bad_input(
        &["prop", "3.1", "--x1", "3", "--y1", "-1", "--u", "1/2"],
        "ambiguous",
    );
    assert_bad_input(&["prop", "6.1"], "000:6.1");
    assert_bad_input(&["prop", "9.9"], "unknown");
    assert_bad_input(
        &["prop", "2.1", "--x1", "3", "--y1", "-1", "--tau", "2"],
        "--tau",
    );
    assert_eq!(lncert(&["prop"]).status.code(), Some(2));
}

#[test]
fn reproduce_json_is_one_document_with_claims() {
    let (doc, code) = json(&["reproduce"]);
    let claims = doc["claims"].as_array().expect("claims array");
    assert!(!claims.is_empty());
    let words = ["certified", "refuted", "erratum", "undecided"];
    for c in claims {
        assert!(words.contains(&c["verdict"].as_str().unwrap_or("")), "{c}");
        for k in ["id", "source", "statement", "detail"] {
            assert!(c[k].is_string(), "{k} in {c}");
        }
    }
    assert!(claims.iter().any(|c| c["source"]
        .as_str()
        .is_some_and(|s| s.starts_with("seed 000 Fig. 5(a)"))));
    let undecided = claims.iter().any(|c| c["verdict"] == "undecided");
    assert_eq!(code, if undecided { 3 } else { 0 });
    let total: u64 = words
        .iter()
        .map(|w| doc["summary"][w].as_u64().expect("summary count"))
        .sum();
    assert_eq!(total as usize, claims.len());
}

#[test]
fn reproduce_out_writes_fig5_pictures() {
    let dir = std::env::temp_dir().join(format!("lncert-cli-test-{}", std::process::id()));
    let o = lncert(&["reproduce", "--out", dir.to_str().unwrap()]);
    assert!(matches!(o.status.code(), Some(0 | 3)), "{}", stderr(&o));
    for f in ["fig5a.svg", "fig5b.svg"] {
        let svg = std::fs::read_to_string(dir.join(f)).expect("picture written");
        assert!(svg.starts_with("<svg") && svg.contains(" C "));
    }
    let _ = std::fs::remove_dir_all(&dir);
}

#[test]
fn prop_4_4_on_fig5a_has_no_interior_cusp() {
    let (doc, code) = json(&["prop", "4.4", "--left", FIG5A_LEFT, "--right", FIG5A_RIGHT]);
    assert_eq!(code, 0);
    assert_eq!(doc["direct"], false);
    assert_eq!(doc["verdict"], false);
    assert_eq!(doc["results"]["engine"], false);
    assert_eq!(doc["results"]["singular_points"], serde_json::json!([]));
    // The paper's κ = sqrt(λl λr): ρl = sqrt(4/9) = 2/3.
    let (doc, _) = json(&[
        "prop",
        "4.4",
        "--left",
        FIG5A_LEFT,
        "--right",
        FIG5A_RIGHT,
        "--rho",
        "2/3",
    ]);
    assert_eq!(
        doc["results"]["deltas_left"],
        serde_json::json!(["1/3", "8/9"])
    );
    assert_eq!(doc["direct"], false);
}

#[test]
fn prop_4_2_with_incompatible_frames_is_bad_input() {
    assert_bad_input(
        &[
            "prop",
            "4.2",
            "--left",
            FIG5A_LEFT,
            "--right",
            "5/2,-4;1,-5/2;3,-7/6",
        ],
        "compatible",
    );
}

#[test]
fn prop_4_2_and_4_3_on_fig5a() {
    let (doc, code) = json(&["prop", "4.2", "--left", FIG5A_LEFT, "--right", FIG5A_RIGHT]);
    assert_eq!(code, 0);
    assert_eq!(doc["results"]["q"], "4/9");
    assert_eq!(
        doc["results"]["admissible_rho_left"],
        serde_json::json!(["1/2", "8/9"])
    );
    assert_eq!(
        (doc["verdict"].clone(), doc["direct"].clone()),
        (Value::Bool(true), Value::Bool(true))
    );
    let (doc, code) = json(&[
        "prop",
        "000:4.3",
        "--left",
        FIG5A_LEFT,
        "--right",
        FIG5A_RIGHT,
        "--rho",
        "2",
    ]);
    assert_eq!(code, 0);
    assert_eq!(doc["agrees"], true);
}

#[test]
fn prop_3_2_with_a2_inside_agrees_with_the_direct_check() {
    // x1 = 3, y1 = -1, u = 3/4: s = 1/3, case 2s < u <= 4s, a2 ∈ (α0 ≈ -6.63, α2 = -4/3).
    let (doc, code) = json(&[
        "prop", "3.2", "--x1", "3", "--y1", "-1", "--u", "0.75", "--a2", "-2",
    ]);
    assert_eq!(code, 0);
    assert_eq!(doc["results"]["case"], "alpha0_alpha2");
    assert_eq!(doc["results"]["alpha2"], "-4/3");
    assert_eq!(doc["verdict"], true);
    assert_eq!(doc["direct"], true);
    assert_eq!(doc["agrees"], true);
    let a0 = doc["results"]["alpha0"].as_array().expect("interval");
    assert!(a0[0].as_f64().unwrap() <= a0[1].as_f64().unwrap());
}

#[test]
fn prop_3_3_tangent_line() {
    let (doc, code) = json(&[
        "prop", "3.3", "--x1", "3", "--y1", "-1", "--u", "3/4", "--m", "1/2", "--b", "-0.6",
    ]);
    assert_eq!(code, 0);
    assert_eq!(doc["results"]["beta"], "-7/16");
    assert_eq!(doc["agrees"], true);
    assert_bad_input(
        &[
            "prop", "3.3", "--x1", "3", "--y1", "-1", "--u", "3/4", "--m", "1",
        ],
        "--m",
    );
}

#[test]
fn seed_000_prop_3_1_lemma_4_1_and_prop_7_1() {
    let (doc, code) = json(&["prop", "000:3.1", "--frame", "0,0;1,1;2,0", "--tau", "1/2"]);
    assert_eq!(
        (code, doc["verdict"].clone(), doc["direct"].clone()),
        (0, Value::Bool(false), Value::Bool(false))
    );
    let (doc, _) = json(&["prop", "000:3.1", "--frame", "0,0;1,1;2,0", "--tau", "inf"]);
    assert_eq!(doc["results"]["delta0"], "2/3");
    let (doc, code) = json(&["prop", "4.1", "--frame", "0,0;1,1;2,0", "--rho", "1/3"]);
    assert_eq!(
        (code, doc["results"]["delta0"].clone()),
        (0, Value::from("-2/3"))
    );
    assert_eq!(doc["agrees"], true);
    let (doc, code) = json(&["prop", "7.1", "--tau", "-2"]);
    assert_eq!(
        (
            code,
            doc["results"]["recommended"].clone(),
            doc["direct"].clone()
        ),
        (0, Value::Bool(true), Value::Bool(true))
    );
}

#[test]
fn seed_003_prop_6_1_convolution() {
    let (doc, code) = json(&["prop", "003:6.1", "--f", "0,0,-1,1", "--g", "0,0,1/2"]);
    assert_eq!(code, 0);
    // f + g = -t²/2 + t³: x = -(f+g)' = t - 3t², y = -(f+g) + t(f+g)' = -t²/2 + 2t³.
    assert_eq!(doc["results"]["x"], serde_json::json!(["0", "1", "-3"]));
    assert_eq!(
        doc["results"]["y"],
        serde_json::json!(["0", "0", "-1/2", "2"])
    );
}

#[test]
fn seed_000_prop_6_1_closed_form_matches_the_direct_enclosure() {
    let (doc, code) = json(&[
        "prop", "000:6.1", "--cos", "3/5", "--sin", "4/5", "--kappa", "3/2",
    ]);
    assert_eq!(code, 0, "{doc}");
    assert_eq!(doc["agrees"], true);
    assert_eq!(doc["results"]["case"], "s2");
    let (doc, code) = json(&["prop", "000:6.1", "--alpha", "0.5", "--kappa", "0.9"]);
    assert_eq!((code, doc["agrees"].clone()), (0, Value::Bool(true)));
    assert_bad_input(
        &[
            "prop", "000:6.1", "--cos", "0.6", "--sin", "0.7", "--kappa", "1",
        ],
        "unit vector",
    );
}

/// `lncert audit --json`: one document, every kernel family, certified path clean.
#[test]
fn audit_json_reports_every_kernel_and_no_certified_failure() {
    let out = lncert(&["audit", "--cases", "60", "--json"]);
    assert_eq!(
        out.status.code(),
        Some(0),
        "stderr: {}",
        String::from_utf8_lossy(&out.stderr)
    );
    let doc: serde_json::Value = serde_json::from_slice(&out.stdout).expect("one JSON document");
    let kernels = doc["kernels"].as_array().expect("kernels array");
    let names: Vec<&str> = kernels.iter().filter_map(|k| k["name"].as_str()).collect();
    assert_eq!(
        names,
        ["bezier", "frame", "cubic", "pair", "hermite", "arc"]
    );
    for k in kernels {
        assert!(k["cases"].as_u64().unwrap() > 0, "{k}");
        assert_eq!(k["disagreements_certified"].as_u64(), Some(0), "{k}");
        for field in ["f64_decision_errors", "max_f64_error_ulps", "fallback_rate"] {
            assert!(k.get(field).is_some(), "missing {field}");
        }
    }
}

/// Bad `--cases` is a bad-input error (exit 2) naming the flag.
#[test]
fn audit_rejects_zero_cases() {
    let out = lncert(&["audit", "--cases", "0"]);
    assert_eq!(out.status.code(), Some(2));
    assert!(String::from_utf8_lossy(&out.stderr).contains("--cases"));
}
