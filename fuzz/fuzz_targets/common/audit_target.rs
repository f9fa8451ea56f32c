//! The verdict shared by the fuzz targets that run one of the command line's
//! self-audit entry points (`lncert_cli::audit::fuzz::fuzz_*`; included by
//! each with `#[path]`).

use libfuzzer_sys::Corpus;
use lncert_cli::audit::fuzz::Outcome;

/// Inputs the generator or kernel rejects are not kept in the corpus; a
/// certified-path failure panics with its message (libFuzzer saves the input).
pub fn corpus(outcome: Result<Outcome, String>) -> Corpus {
    match outcome {
        Ok(Outcome::Rejected) => Corpus::Reject,
        Ok(Outcome::Checked) => Corpus::Keep,
        Err(e) => panic!("{e}"),
    }
}
