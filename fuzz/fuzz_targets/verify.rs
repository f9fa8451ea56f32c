#![no_main]
//! Fuzz target `verify`: raw bytes -> JSON -> `lncert::certify::verify::verify`.
//!
//! Must never panic. A certificate is sealed by a SHA-256 digest, so almost
//! every mutation of a seed stops at the digest check; to reach the checks
//! behind it the target also verifies a *re-sealed* copy (digest recomputed
//! with `cert::digest_of`), i.e. a forged certificate with a valid digest.
//! If a (re-sealed) document is accepted, its claim `d_H(a, b) <= tol` must
//! be true: the certified lower bound of an independent search
//! (`certify::hausdorff`, small budget, sound at any budget) must not exceed `tol`.
//!
//! The seeds (fuzz/seeds/verify/) are real certificates of 1.4-4 kB: with
//! libFuzzer's `-max_len=256` they would be cut to invalid JSON, so this target
//! needs a larger `-max_len` (e.g. 8192).

use libfuzzer_sys::{fuzz_target, Corpus};
use lncert::certify::cert::digest_of;
use lncert::certify::verify::verify;
use lncert::certify::{hausdorff, Config, ShapeDesc};
use lncert::scalar::rational_from_f64;
use serde_json::Value;

/// An accepted certificate must state a true claim.
fn check_accepted(doc: &Value, tol: &lncert::scalar::Rational) {
    let (Ok(a), Ok(b)) = (
        ShapeDesc::from_value(&doc["a"]),
        ShapeDesc::from_value(&doc["b"]),
    ) else {
        panic!("verify accepted a certificate whose shapes do not parse");
    };
    let cfg = Config {
        rel: 1e-2,
        max_boxes: 2000,
        ..Default::default()
    };
    let r = hausdorff(&a, &b, &cfg).expect("shapes accepted by verify must be searchable");
    let lo = rational_from_f64(r.lo).expect("a finite lower bound");
    assert!(
        &lo <= tol,
        "verify accepted d_H <= {tol}, but the certified lower bound is {} ({} / {})",
        r.lo,
        a.summary(),
        b.summary()
    );
}

fuzz_target!(|data: &[u8]| -> Corpus {
    let Ok(doc) = serde_json::from_slice::<Value>(data) else {
        return Corpus::Reject;
    };
    if let Ok(v) = verify(&doc) {
        check_accepted(&doc, &v.tol);
    }
    if let Value::Object(_) = doc {
        let mut sealed = doc.clone();
        let dg = digest_of(&sealed);
        if let Value::Object(m) = &mut sealed {
            m.insert("digest".to_string(), Value::String(dg));
        }
        if let Ok(v) = verify(&sealed) {
            check_accepted(&sealed, &v.tol);
        }
    }
    Corpus::Keep
});
