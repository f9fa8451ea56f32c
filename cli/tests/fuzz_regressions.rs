//! Replays every input committed under `fuzz/regressions/<target>/` through the
//! same library entry point the fuzz target calls (`lncert_cli::audit::fuzz`), so a
//! crash found by `cargo fuzz` stays fixed without a fuzzer or a nightly
//! toolchain.
//!
//! Each target's directory holds `checked-seed`, a fixed input that reaches
//! `Outcome::Checked` (so the test always exercises every kernel path), plus any
//! crash inputs copied from `fuzz/artifacts/<target>/`. Every file must give
//! `Ok(_)`.

use lncert_cli::audit::fuzz::{
    fuzz_arc, fuzz_bezier, fuzz_cubic, fuzz_frame, fuzz_hermite, fuzz_pair, fuzz_parse, Outcome,
};
use std::path::{Path, PathBuf};

type Entry = fn(&[u8]) -> Result<Outcome, String>;

/// Target name (= `fuzz/fuzz_targets/<name>.rs`) and its entry point.
const TARGETS: [(&str, Entry); 7] = [
    ("bezier", fuzz_bezier),
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
        .join("..")
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

/// Runs one committed input; `Err` names the file, the target and the failure.
fn replay(target: &str, f: Entry, path: &Path) -> Result<Outcome, String> {
    let data = std::fs::read(path).map_err(|e| format!("reading {}: {e}", path.display()))?;
    let failed = |what: String| {
        format!(
            "fuzz regression {} (target {target}) {what}\n  input bytes: {data:?}",
            path.display()
        )
    };
    match std::panic::catch_unwind(|| f(&data)) {
        Ok(Ok(outcome)) => Ok(outcome),
        Ok(Err(msg)) => Err(failed(format!("fails the certified path: {msg}"))),
        Err(payload) => {
            let msg = payload
                .downcast_ref::<String>()
                .cloned()
                .or_else(|| payload.downcast_ref::<&str>().map(|s| s.to_string()))
                .unwrap_or_default();
            Err(failed(format!("panics in the engine: {msg}")))
        }
    }
}

#[test]
fn every_committed_fuzz_input_passes() {
    // Every input is replayed and every failure reported, each naming its file.
    let failures: Vec<String> = TARGETS
        .iter()
        .flat_map(|&(target, f)| {
            inputs(&regressions_dir(target))
                .into_iter()
                .filter_map(move |path| replay(target, f, &path).err())
        })
        .collect();
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
            replay(target, f, &seed).unwrap_or_else(|e| panic!("{e}")),
            Outcome::Checked,
            "{} (target {target}) no longer reaches Outcome::Checked",
            seed.display()
        );
    }
}
