//! The oracle shared by the `verify` and `verify_struct` fuzz targets
//! (included by each with `#[path]`).

use lncert::certify::{hausdorff, Config};
use lncert::shape::ShapeDesc;
use lncert::scalar::{rational_from_f64, Rational};
use serde_json::Value;
use std::collections::BTreeMap;
use std::sync::Mutex;

/// An accepted certificate must state a true claim about canonical shapes.
///
/// The search is deterministic, so its lower bound is memoized per pair of
/// shapes (the same text of `a` and `b`): most accepted certificates speak
/// about the shapes of a seed, and the search dominates the cost otherwise.
pub fn check_accepted(text: &str, tol: &Rational) {
    static LOWER: Mutex<BTreeMap<String, (Rational, String)>> = Mutex::new(BTreeMap::new());
    let doc: Value = serde_json::from_str(text)
        .unwrap_or_else(|e| panic!("verify accepted a text serde_json cannot read: {e}"));
    let key = format!("{}\n{}", doc["a"], doc["b"]);
    let known = LOWER.lock().unwrap().get(&key).cloned();
    let (lo, what) = match known {
        Some(x) => x,
        None => {
            let mut shapes = Vec::new();
            for name in ["a", "b"] {
                let x = &doc[name];
                let s = ShapeDesc::from_value(x).unwrap_or_else(|e| {
                    panic!("verify accepted a certificate whose shape {name} does not parse: {e}; {name} = {x}")
                });
                assert_eq!(
                    &s.to_json(),
                    x,
                    "verify accepted a non-canonical shape {name} (to_json differs)"
                );
                shapes.push(s);
            }
            let (a, b) = (&shapes[0], &shapes[1]);
            let cfg = Config {
                rel: 1e-2,
                max_boxes: 2000,
                ..Default::default()
            };
            let r = hausdorff(a, b, &cfg).expect("shapes accepted by verify must be searchable");
            let lo = rational_from_f64(r.lo).expect("a finite lower bound");
            let what = format!("{} / {}", a.summary(), b.summary());
            let mut memo = LOWER.lock().unwrap();
            if memo.len() >= 4096 {
                memo.clear();
            }
            memo.insert(key, (lo.clone(), what.clone()));
            (lo, what)
        }
    };
    assert!(
        &lo <= tol,
        "SOUNDNESS: verify accepted d_H <= {tol}, but the certified lower bound is {lo} ({what})\ncertificate: {text}",
    );
}
