#![no_main]
//! Fuzz target `cubic`: raw bytes -> `lncert_cli::audit::fuzz::fuzz_cubic`.
//! Inputs the generator or kernel rejects are not kept in the corpus; a
//! certified-path failure panics with its message (libFuzzer saves the input).

use libfuzzer_sys::{fuzz_target, Corpus};

#[path = "common/audit_target.rs"]
mod audit_target;

fuzz_target!(|data: &[u8]| -> Corpus {
    audit_target::corpus(lncert_cli::audit::fuzz::fuzz_cubic(data))
});
