//! The certificate format (version 1).
//!
//! A certificate is a JSON document:
//!
//! ```text
//! {
//!   "format": "lncert-hausdorff-certificate", "version": 1,
//!   "claim": "hausdorff(a, b) <= tol",
//!   "tol": "1/1000",                         exact rational
//!   "a": SHAPE, "b": SHAPE,                  canonical shapes, exact rational strings
//!   "bounds": {"lo": Q, "hi": Q},            the search's figures (information only)
//!   "directions": [                          exactly two: a→b and b→a
//!     {"from": "a", "to": "b", "boxes": [
//!        {"piece": i, "s": [Q, Q], "target": j, "t": Q, "k": Q, "bound": Q}, ...]},
//!     {"from": "b", "to": "a", "boxes": [...]}],
//!   "digest": "sha256:…"                     over the canonical serialisation of the rest
//! }
//! ```
//!
//! Every number is an exact rational string (`"p/q"` or an integer): floats of the
//! search are written exactly, so the verifier reads the very numbers the search
//! used. The boxes of each direction must cover every parameter domain of the
//! source shape; for each box `[s0, s1]` of piece `i`, the foot map
//! `τ(s) = t + k (s − (s0+s1)/2)` must stay inside the domain of piece `j` of the
//! target, and `sup |A(s) − B(τ(s))|` over the box — recomputed by the verifier —
//! must be ≤ `tol`. That proves `h(a, b) ≤ tol` and `h(b, a) ≤ tol`, hence the claim.
//! The digest detects accidental or deliberate edits of any field; the semantic
//! checks stand on their own (a certificate with a recomputed digest is still
//! rejected if its boxes do not prove the claim).

use super::search::OneSided;
use super::{HausdorffBounds, ShapeDesc};
use crate::scalar::{rational_from_f64, Rational};
use serde_json::{json, Value};
use sha2::{Digest, Sha256};

/// Format name in the `format` field.
pub const FORMAT: &str = "lncert-hausdorff-certificate";
/// Current format version.
pub const VERSION: u64 = 1;

/// A tolerance certificate (see the module docs for the format).
#[derive(Clone, Debug, PartialEq)]
pub struct Certificate {
    /// The JSON document, digest included.
    pub doc: Value,
}

fn q(x: f64) -> Value {
    Value::String(
        rational_from_f64(x)
            .map(|r| r.to_string())
            .unwrap_or_else(|| "NaN".to_string()),
    )
}

fn direction(from: &str, to: &str, d: &OneSided) -> Value {
    json!({
        "from": from,
        "to": to,
        "boxes": d.boxes.iter().map(|b| json!({
            "piece": b.piece,
            "s": [q(b.s.0), q(b.s.1)],
            "target": b.target,
            "t": q(b.t),
            "k": q(b.k),
            "bound": q(b.bound),
        })).collect::<Vec<_>>(),
    })
}

/// The digest of a certificate document: SHA-256 over the compact serialisation
/// (keys sorted) of the document without its `digest` field.
pub fn digest_of(doc: &Value) -> String {
    let mut d = doc.clone();
    if let Value::Object(m) = &mut d {
        m.remove("digest");
    }
    let bytes = serde_json::to_vec(&d).unwrap_or_default();
    let hash = Sha256::digest(&bytes);
    let hex: String = hash.iter().map(|b| format!("{b:02x}")).collect();
    format!("sha256:{hex}")
}

impl Certificate {
    /// Builds the certificate of `d_H(a, b) ≤ tol` from a search result, or
    /// `None` if the bounds do not prove it (some box bound above `tol`).
    pub fn new(
        a: &ShapeDesc,
        b: &ShapeDesc,
        tol: &Rational,
        r: &HausdorffBounds,
    ) -> Option<Certificate> {
        let tol_f = crate::scalar::interval_from_rational(tol).inf();
        let all = r.a_to_b.boxes.iter().chain(r.b_to_a.boxes.iter());
        if r.a_to_b.boxes.is_empty()
            || r.b_to_a.boxes.is_empty()
            || all.clone().any(|bx| !(bx.bound <= tol_f))
        {
            return None;
        }
        let mut doc = json!({
            "format": FORMAT,
            "version": VERSION,
            "claim": "hausdorff(a, b) <= tol",
            "tol": tol.to_string(),
            "a": a.to_json(),
            "b": b.to_json(),
            "bounds": {"lo": q(r.lo), "hi": q(r.hi)},
            "directions": [direction("a", "b", &r.a_to_b), direction("b", "a", &r.b_to_a)],
        });
        let dg = digest_of(&doc);
        if let Value::Object(m) = &mut doc {
            m.insert("digest".to_string(), Value::String(dg));
        }
        Some(Certificate { doc })
    }

    /// Pretty JSON text.
    pub fn to_json_string(&self) -> String {
        serde_json::to_string_pretty(&self.doc).unwrap_or_default()
    }

    /// Number of proof boxes.
    pub fn box_count(&self) -> usize {
        self.doc["directions"]
            .as_array()
            .map(|ds| {
                ds.iter()
                    .map(|d| d["boxes"].as_array().map_or(0, Vec::len))
                    .sum()
            })
            .unwrap_or(0)
    }
}
