#![no_main]
//! Fuzz target `frame`: raw bytes -> `lncert_cli::audit::fuzz::fuzz_frame`.
//! Inputs the generator or kernel rejects are not kept in the corpus; a
//! certified-path failure panics with its message (libFuzzer saves the input).

use libfuzzer_sys::{fuzz_target, Corpus};
use lncert_cli::audit::fuzz::Outcome;

fuzz_target!(|data: &[u8]| -> Corpus {
    match lncert_cli::audit::fuzz::fuzz_frame(data) {
        Ok(Outcome::Rejected) => Corpus::Reject,
        Ok(Outcome::Checked) => Corpus::Keep,
        Err(e) => panic!("{e}"),
    }
});
