#![no_main]
//! Fuzz target `verify`: raw bytes -> UTF-8 text -> `lncert::certify::verify::verify`.
//!
//! A run much slower than reading the bytes is a finding too (the resource
//! oracle `verify_timed`: at most 200 x the reading time + 250 ms, issue 64).
//!
//! Must never panic. The verifier reads the text itself (strict bounded JSON:
//! duplicate keys, over-limit input, unknown keys and non-canonical numbers or
//! shapes are refused), so the bytes go to it unchanged. If a text is accepted:
//!
//! - its claim `d_H(a, b) <= tol` must be true: both shapes must read with the
//!   user-language reader (`ShapeDesc::from_value`), and the certified lower
//!   bound of an independent search (`certify::hausdorff`, small budget, sound
//!   at any budget) must not exceed `tol`;
//! - its shapes must be canonical: `ShapeDesc::from_value(x).to_json() == x`.
//!
//! The seeds (fuzz/seeds/verify/) are real certificates of 0.9-4.7 kB: with
//! libFuzzer's `-max_len=256` they would be cut to invalid JSON, so this target
//! needs a larger `-max_len` (e.g. 8192), and the dictionary fuzz/verify.dict
//! (every key and literal of the format). The structure-aware target
//! `verify_struct` mutates the same seeds as JSON trees.

use libfuzzer_sys::{fuzz_target, Corpus};

#[path = "common/verify_oracle.rs"]
mod verify_oracle;
use verify_oracle::{check_accepted, verify_timed};


fuzz_target!(|data: &[u8]| -> Corpus {
    let Ok(text) = std::str::from_utf8(data) else {
        return Corpus::Reject;
    };
    if let Ok(v) = verify_timed(text) {
        check_accepted(text, &v.tol);
    }
    Corpus::Keep
});
