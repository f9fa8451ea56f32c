#![no_main]
//! Fuzz target `bezier`: raw bytes -> `lncert_cli::audit::fuzz::fuzz_bezier`.
//! Curves of degree 1-3 or 1-4 (picked by the first byte), degree 1-9 as in
//! `lncert audit` on one input in 64: exact root isolation costs ~1 ms at
//! degree 4 and ~10 ms at degree 9 (all degrees alike: ~700 runs/s).
//! Inputs the generator or kernel rejects are not kept in the corpus; a
//! certified-path failure panics with its message (libFuzzer saves the input).

use libfuzzer_sys::{fuzz_target, Corpus};

#[path = "common/audit_target.rs"]
mod audit_target;

fuzz_target!(|data: &[u8]| -> Corpus {
    audit_target::corpus(lncert_cli::audit::fuzz::fuzz_bezier(data))
});
