#![no_main]
//! Fuzz target `hermite`: raw bytes -> `lncert_cli::audit::fuzz::fuzz_hermite`.
//! Every decision and value is compared in the three arithmetics on every
//! input; Props 2.1 and 3.2 are compared with exact root isolation (an
//! independent Sturm oracle, 40 % of the time when run on every input) only
//! on inputs whose bytes hash to 0 modulo 4 (`lncert_cli::audit::fuzz::
//! sample_hash`: one input in 4), so a replayed input re-runs the same checks.
//! Inputs the generator or kernel rejects are not kept in the corpus; a
//! certified-path failure panics with its message (libFuzzer saves the input).

use libfuzzer_sys::{fuzz_target, Corpus};

#[path = "common/audit_target.rs"]
mod audit_target;

fuzz_target!(|data: &[u8]| -> Corpus {
    audit_target::corpus(lncert_cli::audit::fuzz::fuzz_hermite(data))
});
