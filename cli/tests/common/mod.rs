//! Shared helpers of the command-line tests: the engine tests' generators and
//! helpers (`tests/common/` of the engine crate), and running the binary.
#![allow(dead_code)]

#[path = "../../../tests/common/mod.rs"]
mod engine;
#[allow(unused_imports)]
pub use engine::*;

/// Runs the `lncert` binary with `args`.
pub fn lncert(args: &[&str]) -> std::process::Output {
    std::process::Command::new(env!("CARGO_BIN_EXE_lncert"))
        .args(args)
        .output()
        .expect("the binary runs")
}

/// The JSON document a run printed on stdout (panics with stdout and stderr
/// when it is not JSON).
pub fn json_of(o: &std::process::Output) -> serde_json::Value {
    serde_json::from_slice(&o.stdout).unwrap_or_else(|e| {
        panic!(
            "not JSON ({e}): {}\nstderr: {}",
            String::from_utf8_lossy(&o.stdout),
            String::from_utf8_lossy(&o.stderr)
        )
    })
}
