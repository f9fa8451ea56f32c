//! Replays every certificate committed under `fuzz/regressions/verify/` through
//! the verifier (`lncert::certify::verify::verify`, the function the `verify`
//! and `verify_struct` fuzz targets call), so a forgery that was once accepted
//! — or found by the fuzzers — stays rejected, at the right field.
//!
//! - `valid-seed*.json` are real certificates: they must verify.
//! - Every other `.json` file is a forgery of a real certificate: it must be
//!   rejected, and `Invalid.at` must be the field recorded in [`EXPECTED`]
//!   (and the reason must mention the recorded keyword). A file without an
//!   entry fails the test, so every new regression gets an expectation; an
//!   entry without a file fails too. `README.md` describes the files.
//!
//! The binary is run on a few of them too (exit codes 0, 1 and 2 of
//! `lncert verify`).

use lncert::certify::verify::verify;
use lncert::shape::ShapeDesc;
use std::path::{Path, PathBuf};
use std::process::Command;
use std::time::{Duration, Instant};

/// File name → the field the verifier must name (`Invalid.at`, exactly) and a
/// word of its reason.
const EXPECTED: &[(&str, &str, &str)] = &[
    // 1. an arc given a direction flag the canonical form does not have
    ("arc_clockwise_added.json", "a.arc.clockwise", "unknown key"),
    ("issue_arc_clockwise_tol_3e-4.json", "a.arc.clockwise", "unknown key"),
    // 2. shapes that are not in the canonical form
    ("two_shape_keys.json", "a", "exactly one key"),
    ("unknown_shape_subkey.json", "a.arc.sweep", "unknown key"),
    ("lenient_bezier_key.json", "a.bezier", "unknown key"),
    ("svg_string_shape.json", "b", "shape object"),
    ("singular_ellipse.json", "a.convolution.ellipse", "singular"),
    ("coordinate_above_1e100.json", "a.beziers[0][1][0]", "1e100"),
    // 3. fields that nobody checks have no place in a certificate
    ("bounds_field.json", "bounds", "unknown key"),
    ("box_bound_field.json", "directions[0].boxes[0].bound", "unknown key"),
    ("digest_field.json", "digest", "unknown key"),
    ("extra_key.json", "extra", "unknown key"),
    ("claim_changed.json", "claim", "the one claim"),
    ("v1_certificate.json", "version", "version 1"),
    // 4. a key said twice (readers disagree on which one counts)
    ("duplicate_tol.json", "tol", "duplicate"),
    // 5. sizes, nesting and non-canonical numbers
    ("tol_100k_digits.json", "tol", "4096"),
    ("tol_100k_digit_number.json", "tol", "4096"),
    (
        "deep_nesting.json",
        "tol[0][0][0][0][0][0][0][0][0][0][0][0][0][0][0][0][0][0][0][0][0][0][0][0][0][0][0][0][0][0][0]",
        "nested",
    ),
    ("noncanonical_tol.json", "tol", "canonical"),
    ("noncanonical_tol_unreduced.json", "tol", "canonical"),
    ("noncanonical_tol_plus.json", "tol", "canonical"),
    ("noncanonical_tol_leading_zero.json", "tol", "canonical"),
    ("noncanonical_coordinate.json", "a.beziers[0][2][0]", "canonical"),
    ("json_number_tol.json", "tol", "rational string"),
    // well-formed certificates of false claims: the recomputation refuses them
    ("false_tol.json", "directions[0].boxes[1]", "exceeds the tolerance"),
    ("box_deleted.json", "directions[0].boxes[2]", "gap or overlap"),
    // 6. unions: strict reading, and the pieces proven against their own sides
    ("union_empty.json", "a.union", "1 or more"),
    ("union_nested.json", "a.union[0].union", "unknown key"),
    ("union_member_deleted.json", "maps[1].piece", "out of range"),
    ("union_members_swapped.json", "maps[0].boxes[0]", "exceeds the tolerance"),
    ("union_side_flipped.json", "maps[0].boxes[0]", "exceeds the tolerance"),
];

fn dir() -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR"))
        .join("fuzz")
        .join("regressions")
        .join("verify")
}

/// The committed files (all but `README.md`), sorted by name.
fn files() -> Vec<(String, PathBuf)> {
    let d = dir();
    let mut out: Vec<(String, PathBuf)> = std::fs::read_dir(&d)
        .unwrap_or_else(|e| panic!("reading {}: {e}", d.display()))
        .map(|e| {
            e.unwrap_or_else(|e| panic!("reading {}: {e}", d.display()))
                .path()
        })
        .filter(|p| p.is_file())
        .map(|p| (p.file_name().unwrap().to_string_lossy().into_owned(), p))
        .filter(|(n, _)| n != "README.md")
        .collect();
    out.sort();
    out
}

fn is_valid_seed(name: &str) -> bool {
    name.starts_with("valid-seed") && name.ends_with(".json")
}

fn read(path: &Path) -> String {
    let bytes = std::fs::read(path).unwrap_or_else(|e| panic!("reading {}: {e}", path.display()));
    String::from_utf8(bytes).unwrap_or_else(|e| panic!("{}: not UTF-8: {e}", path.display()))
}

#[test]
fn every_committed_certificate_is_judged_as_recorded() {
    let files = files();
    assert!(
        files.iter().any(|(n, _)| is_valid_seed(n)),
        "no valid-seed*.json in {}",
        dir().display()
    );
    let mut failures = Vec::new();
    let mut slowest = (Duration::ZERO, String::new());
    for (name, path) in &files {
        let text = read(path);
        let start = Instant::now();
        let res = verify(&text);
        let took = start.elapsed();
        eprintln!(
            "{name}: {:.3} ms ({} bytes)",
            took.as_secs_f64() * 1e3,
            text.len()
        );
        if took > slowest.0 {
            slowest = (took, name.clone());
        }
        if is_valid_seed(name) {
            match res {
                Ok(v) if v.boxes > 0 => {}
                Ok(v) => failures.push(format!("{name}: valid with no boxes: {v:?}")),
                Err(e) => failures.push(format!("{name}: a valid seed is rejected: {e}")),
            }
            continue;
        }
        let Some(&(_, at, word)) = EXPECTED.iter().find(|(f, _, _)| f == name) else {
            failures.push(format!(
                "{name}: no expectation: add it to EXPECTED (file name, the field `Invalid.at` \
                 the verifier must name, a word of its reason) and to README.md"
            ));
            continue;
        };
        match res {
            Ok(v) => failures.push(format!(
                "{name}: FORGERY ACCEPTED: {} ({} boxes)",
                v.statement(),
                v.boxes
            )),
            Err(e) if e.at != at => failures.push(format!(
                "{name}: rejected at `{}` (expected `{at}`): {}",
                e.at, e.reason
            )),
            Err(e) if !e.reason.contains(word) => failures.push(format!(
                "{name}: rejected at `{at}`, but the reason does not mention {word:?}: {}",
                e.reason
            )),
            Err(_) => {}
        }
    }
    for (f, _, _) in EXPECTED {
        if !files.iter().any(|(n, _)| n == f) {
            failures.push(format!("{f}: expected in {} but missing", dir().display()));
        }
    }
    eprintln!(
        "slowest: {} ({:.3} ms)",
        slowest.1,
        slowest.0.as_secs_f64() * 1e3
    );
    assert!(failures.is_empty(), "{}", failures.join("\n"));
}

/// The shapes of a valid certificate are canonical: the user-language reader
/// reads them, and writes them back unchanged.
#[test]
fn valid_seeds_have_canonical_shapes() {
    for (name, path) in files().iter().filter(|(n, _)| is_valid_seed(n)) {
        let doc: serde_json::Value = serde_json::from_str(&read(path)).unwrap();
        for key in ["a", "b"] {
            let shape = ShapeDesc::from_value(&doc[key])
                .unwrap_or_else(|e| panic!("{name}: {key} does not parse: {e}"));
            assert_eq!(shape.to_json(), doc[key], "{name}: {key} is not a fixpoint");
        }
    }
}

fn lncert_verify(file: &Path) -> (Option<i32>, String) {
    let out = Command::new(env!("CARGO_BIN_EXE_lncert"))
        .arg("verify")
        .arg(file)
        .output()
        .expect("running lncert");
    (
        out.status.code(),
        format!(
            "{}{}",
            String::from_utf8_lossy(&out.stdout),
            String::from_utf8_lossy(&out.stderr)
        ),
    )
}

#[test]
fn the_binary_names_the_forged_field() {
    for (file, says) in [
        (
            "arc_clockwise_added.json",
            "invalid: a.arc.clockwise: unknown key",
        ),
        ("duplicate_tol.json", "invalid: tol: duplicate key \"tol\""),
        (
            "tol_100k_digits.json",
            "invalid: tol: longer than the limit",
        ),
    ] {
        let (code, out) = lncert_verify(&dir().join(file));
        assert_eq!(code, Some(1), "lncert verify {file}: {out}");
        assert!(
            out.contains(says),
            "lncert verify {file} should say {says:?}: {out}"
        );
    }
    let (code, out) = lncert_verify(&dir().join("valid-seed.json"));
    assert_eq!(code, Some(0), "lncert verify valid-seed.json: {out}");
    assert!(out.starts_with("valid: proven"), "{out}");
    let missing = dir().join("no-such-certificate.json");
    let (code, out) = lncert_verify(&missing);
    assert_eq!(code, Some(2), "lncert verify on a missing file: {out}");
    assert!(out.contains("no-such-certificate.json"), "{out}");
}
