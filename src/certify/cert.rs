//! The certificate format (version 2).
//!
//! A certificate is a JSON document with exactly these keys (any order):
//!
//! ```text
//! {
//!   "format": "lncert-hausdorff-certificate", "version": 2,
//!   "claim": "hausdorff(a, b) <= tol",       the one claim of this format
//!   "tol": Q,                                 exact rational, ≥ 0
//!   "a": SHAPE, "b": SHAPE,                   canonical shapes
//!   "directions": [                           exactly two: a→b and b→a
//!     {"from": "a", "to": "b", "boxes": [
//!        {"piece": i, "s": [Q, Q], "target": j, "t": Q, "k": Q}, ...]},
//!     {"from": "b", "to": "a", "boxes": [...]}]
//! }
//! ```
//!
//! `Q` is a canonical exact rational string (`"0"`, `"-3"`, `"7/2"`: lowest
//! terms, no `+`, no leading zeros, no `/1`, at most 4 096 characters, magnitude
//! ≤ 10¹⁰⁰); `i`, `j` are JSON integers. `SHAPE` is the canonical shape form of
//! [`ShapeDesc::to_json`] (`proofs/certify-hausdorff.md` specifies it). Floats of
//! the search are written exactly, so the verifier reads the very numbers the
//! search used. The boxes of each direction must cover every parameter domain of
//! the source shape; for each box `[s0, s1]` of piece `i`, the foot map
//! `τ(s) = t + k (s − (s0+s1)/2)` must stay inside the domain of piece `j` of the
//! target, and `sup |A(s) − B(τ(s))|` over the box — recomputed by the verifier —
//! must be ≤ `tol`. That proves `h(a, b) ≤ tol` and `h(b, a) ≤ tol`, hence the claim.
//!
//! Every field is checked: there is nothing informational (version 1's search
//! figures `bounds` and per-box `bound` are gone), and an unknown or duplicate
//! key anywhere makes the certificate invalid. There is no digest: an unkeyed
//! hash authenticates nothing (anyone who edits a certificate can recompute it),
//! and the verifier does not need one — it checks what the document *says*. A
//! reader who wants to know *which* shapes a certificate speaks about asks
//! `lncert verify CERT --against A B`.

use super::search::OneSided;
use super::{HausdorffBounds, ShapeDesc};
use crate::scalar::{rational_from_f64, Rational};
use serde_json::{json, Value};

/// Format name in the `format` field.
pub const FORMAT: &str = "lncert-hausdorff-certificate";
/// Current format version.
pub const VERSION: u64 = 2;
/// The claim of this format, the value of the `claim` field.
pub const CLAIM: &str = "hausdorff(a, b) <= tol";

/// A tolerance certificate (see the module docs for the format).
#[derive(Clone, Debug, PartialEq)]
pub struct Certificate {
    /// The JSON document.
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
        })).collect::<Vec<_>>(),
    })
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
            || all.clone().any(|bx| {
                !(bx.bound <= tol_f) || ![bx.s.0, bx.s.1, bx.t, bx.k].iter().all(|x| x.is_finite())
            })
        {
            return None;
        }
        let doc = json!({
            "format": FORMAT,
            "version": VERSION,
            "claim": CLAIM,
            "tol": tol.to_string(),
            "a": a.to_json(),
            "b": b.to_json(),
            "directions": [direction("a", "b", &r.a_to_b), direction("b", "a", &r.b_to_a)],
        });
        Some(Certificate { doc })
    }

    /// The JSON text: one field per line, one box per line (about half the size
    /// of fully pretty-printed JSON, and still readable and diffable).
    pub fn to_json_string(&self) -> String {
        let compact = |v: &Value| serde_json::to_string(v).unwrap_or_default();
        let Value::Object(m) = &self.doc else {
            return compact(&self.doc);
        };
        let mut out = String::from("{\n");
        let mut first = true;
        let order = ["format", "version", "claim", "tol", "a", "b", "directions"];
        let ordered = order
            .iter()
            .filter_map(|k| m.get_key_value(*k))
            .chain(m.iter().filter(|(k, _)| !order.contains(&k.as_str())));
        for (k, v) in ordered {
            if !first {
                out.push_str(",\n");
            }
            first = false;
            out.push_str(&format!("  {}: ", compact(&Value::String(k.clone()))));
            match (k.as_str(), v) {
                ("directions", Value::Array(dirs)) => {
                    out.push_str("[\n");
                    for (i, d) in dirs.iter().enumerate() {
                        let boxes = d["boxes"].as_array().map(Vec::as_slice).unwrap_or(&[]);
                        let mut head = d.clone();
                        if let Value::Object(h) = &mut head {
                            h.remove("boxes");
                        }
                        let head = compact(&head);
                        // {"from":"a","to":"b", "boxes": [
                        out.push_str(&format!("    {}, \"boxes\": [", &head[..head.len() - 1]));
                        for (j, b) in boxes.iter().enumerate() {
                            out.push_str(if j == 0 { "\n      " } else { ",\n      " });
                            out.push_str(&compact(b));
                        }
                        out.push_str(if i + 1 == dirs.len() { "]}\n" } else { "]},\n" });
                    }
                    out.push_str("  ]");
                }
                _ => out.push_str(&compact(v)),
            }
        }
        out.push_str("\n}\n");
        out
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
