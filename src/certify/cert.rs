//! The certificate format (version 3; version 2 is still read).
//!
//! A certificate is a JSON document with exactly these keys (any order):
//!
//! ```text
//! {
//!   "format": "lncert-hausdorff-certificate", "version": 3,
//!   "claim": "hausdorff(a, b) <= tol",       the one claim of this format
//!   "tol": Q,                                 exact rational, ≥ 0
//!   "a": SHAPE, "b": SHAPE,                   canonical shapes
//!   "maps": [                                 parametric covers (may be empty)
//!     {"from": "b", "piece": j, "to": "a", "target": i, "boxes": [
//!        {"t": [Q, Q], "phi": [Q, Q, Q, Q]}, ...]}, ...],
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
//! the proofs are written exactly, so the verifier reads the very numbers the
//! proofs used.
//!
//! **A map** (the parametric proof, [`super::param`]) proves both one-sided
//! distances between one piece of each shape: its boxes cover the source
//! piece's parameter domain exactly and in order (`t`), and on each box the
//! map `φ` into the target piece's parameter is the cubic with Bernstein
//! coefficients `phi`; consecutive boxes share their end value (`φ` is
//! continuous), every coefficient lies in the target's domain, and
//! `sup |src(t) − dst(φ(t))|` over each box, plus `sup |dst′| · length` for the
//! parts of the target's domain before and after the values of `φ` at the ends,
//! must be ≤ `tol`. Then every point of either piece is within `tol` of the
//! other (`φ` is onto the range between its end values).
//!
//! **A direction's boxes** (the two-directional search) cover the pieces of
//! the source shape that no map covers: for each box `[s0, s1]` of piece `i`,
//! the foot map `τ(s) = t + k (s − (s0+s1)/2)` must stay inside the domain of
//! piece `j` of the target, and `sup |A(s) − B(τ(s))|` over the box —
//! recomputed by the verifier — must be ≤ `tol`.
//!
//! Each piece of each shape is covered, in each direction, exactly once: by one
//! map (as its source or its target) or by that direction's boxes. That proves
//! `h(a, b) ≤ tol` and `h(b, a) ≤ tol`, hence the claim. Version 2 is the same
//! document without `maps`.
//!
//! **Version 4: the radial proof** ([`super::RadialProof`]). For a circular
//! arc and a chain of Bézier pieces, the document has, in place of `maps` and
//! `directions`, one key
//!
//! ```text
//!   "radial": {"arc": "b", "cells": [        which shape is the arc
//!      {"piece": i, "t": [Q, Q]}, ...]}      the curve's cover, in order
//! ```
//!
//! The verifier decides exactly, in rationals, the statement's conditions (a
//! sweep `≤ π`, a continuous chain of degree `≤ 20`, every control point in
//! the arc's closed sector, the chain's ends positively on the two end rays),
//! checks that the cells cover every piece's `[0, 1]` exactly and in order,
//! and on each cell encloses `f = |P − c|² − R²` by the Bernstein
//! coefficients of the piece restricted to (a superset of) the cell: `R² + f >
//! 0` and `|f| / (√(R² + f) + R) ≤ tol` there. Then `d_H ≤ tol`
//! (`proofs/certify-hausdorff.md`, "The radial proof"). The writer uses
//! version 4 only for a radial result, and version 3 otherwise.
//!
//! Every field is checked: there is nothing informational, and an unknown or
//! duplicate key anywhere makes the certificate invalid. There is no digest: an
//! unkeyed hash authenticates nothing (anyone who edits a certificate can
//! recompute it), and the verifier does not need one — it checks what the
//! document *says*. A reader who wants to know *which* shapes a certificate
//! speaks about asks `lncert verify CERT --against A B`.

use super::param::ParamBox;
use super::search::CoverBox;
use super::HausdorffBounds;
use crate::scalar::rational_from_f64;
use crate::shape::ShapeDesc;
use crate::Tolerance;
use serde_json::{json, Value};

/// Format name in the `format` field.
pub const FORMAT: &str = "lncert-hausdorff-certificate";
/// Current format version.
pub const VERSION: u64 = 3;
/// The older version the verifier still reads (no `maps`).
pub const VERSION_2: u64 = 2;
/// The version of a radial certificate (`radial` in place of `maps` and
/// `directions`).
pub const VERSION_RADIAL: u64 = 4;
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

fn direction(from: &str, to: &str, boxes: &[CoverBox]) -> Value {
    json!({
        "from": from,
        "to": to,
        "boxes": boxes.iter().map(|b| json!({
            "piece": b.piece,
            "s": [q(b.s.0), q(b.s.1)],
            "target": b.target,
            "t": q(b.t),
            "k": q(b.k),
        })).collect::<Vec<_>>(),
    })
}

/// A certificate document: the format's head (format, version, claim,
/// tolerance, shapes) and the members of its proof (`proof`, an object).
fn document(a: &ShapeDesc, b: &ShapeDesc, tol: &Tolerance, version: u64, proof: Value) -> Value {
    let mut doc = json!({
        "format": FORMAT,
        "version": version,
        "claim": CLAIM,
        "tol": tol.exact().to_string(),
        "a": a.to_json(),
        "b": b.to_json(),
    });
    if let (Value::Object(d), Value::Object(p)) = (&mut doc, proof) {
        d.extend(p);
    }
    doc
}

/// One parametric cover for a certificate: the map from piece `piece` of the
/// source shape onto piece `target` of the other ([`super::Parametric`]).
#[derive(Clone, Debug, PartialEq)]
pub struct MapCover {
    /// The source is shape `a` (else `b`).
    pub from_a: bool,
    /// The source piece (its parameter is covered by the boxes).
    pub piece: usize,
    /// The target piece (the map runs onto its domain).
    pub target: usize,
    /// The cover, in order.
    pub boxes: Vec<ParamBox>,
    /// The proof's bound, end terms included.
    pub hi: f64,
}

fn map_json(m: &MapCover) -> Value {
    let (from, to) = if m.from_a { ("a", "b") } else { ("b", "a") };
    json!({
        "from": from,
        "piece": m.piece,
        "to": to,
        "target": m.target,
        "boxes": m.boxes.iter().map(|b| json!({
            "t": [q(b.t.0), q(b.t.1)],
            "phi": b.c.iter().map(|c| q(*c)).collect::<Vec<_>>(),
        })).collect::<Vec<_>>(),
    })
}

impl Certificate {
    /// Builds the certificate of `d_H(a, b) ≤ tol` from a proof of
    /// [`super::hausdorff`] (its radial cover, its parametric map, or its two
    /// box covers), or `None` if the bounds do not prove it (some bound above
    /// `tol`).
    ///
    /// A radial certificate is checked by the verifier before it is returned
    /// (microseconds): should the verifier's own enclosures not confirm a cell
    /// the proof placed at the tolerance to within rounding, the claim is
    /// proven again without the radial proof and stated by maps or boxes
    /// ([`Certificate::is_radial`] tells which).
    pub fn new(
        a: &ShapeDesc,
        b: &ShapeDesc,
        tol: &Tolerance,
        r: &HausdorffBounds,
    ) -> Option<Certificate> {
        if let Some(p) = &r.radial {
            if let Some(c) = Self::radial(a, b, tol, p) {
                if super::verify::verify(&c.to_json_string()).is_ok() {
                    return Some(c);
                }
            }
            // prove the claim again without the radial proof
            let cfg = super::Config {
                tol: Some(tol.clone()),
                radial: false,
                ..super::Config::default()
            };
            let again = super::hausdorff(a, b, &cfg).ok()?;
            return Self::new(a, b, tol, &again);
        }
        match &r.parametric {
            Some(p) => {
                let m = MapCover {
                    from_a: p.source_a,
                    piece: 0,
                    target: 0,
                    boxes: p.boxes.clone(),
                    hi: p.hi,
                };
                Self::assemble(a, b, tol, &[m], &[], &[])
            }
            None if r.a_to_b.boxes.is_empty() || r.b_to_a.boxes.is_empty() => None,
            None => Self::assemble(a, b, tol, &[], &r.a_to_b.boxes, &r.b_to_a.boxes),
        }
    }

    /// The version 4 certificate of a radial proof (see the module docs);
    /// `None` if some cell's bound is above `tol` or some number is not finite.
    pub fn radial(
        a: &ShapeDesc,
        b: &ShapeDesc,
        tol: &Tolerance,
        p: &super::RadialProof,
    ) -> Option<Certificate> {
        let tol_f = tol.value();
        let ok = !p.cells.is_empty()
            && p.hi <= tol_f
            && p.cells
                .iter()
                .all(|c| c.bound <= tol_f && c.t.0.is_finite() && c.t.1.is_finite());
        if !ok {
            return None;
        }
        let doc = document(
            a,
            b,
            tol,
            VERSION_RADIAL,
            json!({
                "radial": {
                    "arc": if p.curve_is_a { "b" } else { "a" },
                    "cells": p.cells.iter().map(|c| json!({
                        "piece": c.piece,
                        "t": [q(c.t.0), q(c.t.1)],
                    })).collect::<Vec<_>>(),
                },
            }),
        );
        Some(Certificate { doc })
    }

    /// The certificate states a radial proof (version 4).
    pub fn is_radial(&self) -> bool {
        self.doc.get("radial").is_some()
    }

    /// Assembles a certificate from parametric maps and the two directions'
    /// boxes (for the pieces no map covers); `None` if some bound is above
    /// `tol` or some number is not finite. Whether the pieces are covered is
    /// for the verifier to say.
    pub fn assemble(
        a: &ShapeDesc,
        b: &ShapeDesc,
        tol: &Tolerance,
        maps: &[MapCover],
        a_to_b: &[CoverBox],
        b_to_a: &[CoverBox],
    ) -> Option<Certificate> {
        // the largest float ≤ the exact tolerance: a bound ≤ it is ≤ the claim
        let tol_f = tol.value();
        let boxes_ok = a_to_b.iter().chain(b_to_a).all(|bx| {
            bx.bound <= tol_f && [bx.s.0, bx.s.1, bx.t, bx.k].iter().all(|x| x.is_finite())
        });
        let maps_ok = maps.iter().all(|m| {
            m.hi <= tol_f
                && !m.boxes.is_empty()
                && m.boxes.iter().all(|bx| {
                    bx.bound <= tol_f && [bx.t.0, bx.t.1].iter().chain(&bx.c).all(|x| x.is_finite())
                })
        });
        if !boxes_ok || !maps_ok || (maps.is_empty() && (a_to_b.is_empty() || b_to_a.is_empty())) {
            return None;
        }
        let doc = document(
            a,
            b,
            tol,
            VERSION,
            json!({
                "maps": maps.iter().map(map_json).collect::<Vec<_>>(),
                "directions": [direction("a", "b", a_to_b), direction("b", "a", b_to_a)],
            }),
        );
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
        // the keys of the format in its order (the verifier's list), then any others
        let order = super::verify::KEYS;
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
                ("directions" | "maps", Value::Array(items)) if !items.is_empty() => {
                    out.push_str("[\n");
                    for (i, d) in items.iter().enumerate() {
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
                        out.push_str(if i + 1 == items.len() {
                            "]}\n"
                        } else {
                            "]},\n"
                        });
                    }
                    out.push_str("  ]");
                }
                ("radial", Value::Object(r)) => {
                    // {"arc":"b","cells":[ one cell per line ]}
                    let cells = r.get("cells").and_then(Value::as_array);
                    match (r.get("arc"), cells) {
                        (Some(arc), Some(cells)) if r.len() == 2 && !cells.is_empty() => {
                            out.push_str(&format!("{{\"arc\": {}, \"cells\": [", compact(arc)));
                            for (j, c) in cells.iter().enumerate() {
                                out.push_str(if j == 0 { "\n    " } else { ",\n    " });
                                out.push_str(&compact(c));
                            }
                            out.push_str("]}");
                        }
                        _ => out.push_str(&compact(v)),
                    }
                }
                _ => out.push_str(&compact(v)),
            }
        }
        out.push_str("\n}\n");
        out
    }

    /// Number of proof boxes (a radial certificate's cells).
    pub fn box_count(&self) -> usize {
        let cells = self.doc["radial"]["cells"].as_array().map_or(0, Vec::len);
        ["maps", "directions"]
            .iter()
            .filter_map(|k| self.doc[*k].as_array())
            .flatten()
            .map(|d| d["boxes"].as_array().map_or(0, Vec::len))
            .sum::<usize>()
            + cells
    }
}
