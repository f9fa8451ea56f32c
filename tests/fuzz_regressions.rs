//! Replays every input committed under `fuzz/regressions/<target>/` through the
//! same library entry point the fuzz target calls (`lncert::audit::fuzz`), so a
//! crash found by `cargo fuzz` stays fixed without a fuzzer or a nightly
//! toolchain.
//!
//! Each target's directory holds `checked-seed`, a fixed input that reaches
//! `Outcome::Checked` (so the test always exercises every kernel path), plus any
//! crash inputs copied from `fuzz/artifacts/<target>/`. Every file must give
//! `Ok(_)`.
#![cfg(feature = "arbitrary")]

use lncert::audit::fuzz::{
    fuzz_arc, fuzz_cubic, fuzz_frame, fuzz_hermite, fuzz_pair, fuzz_parse, Outcome,
};
use std::path::{Path, PathBuf};

type Entry = fn(&[u8]) -> Result<Outcome, String>;

/// Target name (= `fuzz/fuzz_targets/<name>.rs`) and its entry point.
const TARGETS: [(&str, Entry); 6] = [
    ("frame", fuzz_frame),
    ("cubic", fuzz_cubic),
    ("pair", fuzz_pair),
    ("hermite", fuzz_hermite),
    ("arc", fuzz_arc),
    ("parse", fuzz_parse),
];

/// The always-present input of each target that must reach `Outcome::Checked`.
const SEED: &str = "checked-seed";

fn regressions_dir(target: &str) -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR"))
        .join("fuzz")
        .join("regressions")
        .join(target)
}

/// Regular files of `dir`, sorted; none when the directory is absent.
fn inputs(dir: &Path) -> Vec<PathBuf> {
    let Ok(entries) = std::fs::read_dir(dir) else {
        return Vec::new();
    };
    let mut files: Vec<PathBuf> = entries
        .map(|e| {
            e.unwrap_or_else(|err| panic!("reading {}: {err}", dir.display()))
                .path()
        })
        .filter(|p| p.is_file())
        .collect();
    files.sort();
    files
}

fn replay(target: &str, f: Entry, path: &Path) -> Outcome {
    let data = std::fs::read(path).unwrap_or_else(|e| panic!("reading {}: {e}", path.display()));
    match std::panic::catch_unwind(|| f(&data)) {
        Ok(Ok(outcome)) => outcome,
        Ok(Err(msg)) => panic!(
            "fuzz regression {} (target {target}) fails the certified path: {msg}\ninput bytes: {data:?}",
            path.display()
        ),
        Err(_) => panic!(
            "fuzz regression {} (target {target}) panics in the engine\ninput bytes: {data:?}",
            path.display()
        ),
    }
}

#[test]
fn every_committed_fuzz_input_passes() {
    let mut failures = Vec::new();
    for (target, f) in TARGETS {
        for path in inputs(&regressions_dir(target)) {
            // Collect every failure (each names its file) before failing.
            if let Err(e) = std::panic::catch_unwind(|| replay(target, f, &path)) {
                let msg = e
                    .downcast_ref::<String>()
                    .cloned()
                    .unwrap_or_else(|| format!("{}: panic", path.display()));
                failures.push(msg);
            }
        }
    }
    assert!(
        failures.is_empty(),
        "{} fuzz regression(s) failed:\n{}",
        failures.len(),
        failures.join("\n")
    );
}

#[test]
fn every_target_has_a_checked_seed() {
    for (target, f) in TARGETS {
        let dir = regressions_dir(target);
        assert!(
            !inputs(&dir).is_empty(),
            "no regression input for fuzz target {target} in {}",
            dir.display()
        );
        let seed = dir.join(SEED);
        assert!(seed.is_file(), "missing {}", seed.display());
        assert_eq!(
            replay(target, f, &seed),
            Outcome::Checked,
            "{} (target {target}) no longer reaches Outcome::Checked",
            seed.display()
        );
    }
}
