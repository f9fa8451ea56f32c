#![no_main]
//! Fuzz target `verify_struct`: structure-aware forgeries of real certificates.
//!
//! The bytes are *choices* (read with `arbitrary::Unstructured`): one of the
//! seed certificates of fuzz/seeds/verify/ (embedded; version 2 with box
//! covers, version 3 with parametric maps, version 4 with radial cells, stroke certificates (a disk pen on
//! segments, on a quadratic and on exact arcs, and an elliptical one), a stroke distance certificate and a certificate set), then
//! 1 to 4 mutations of
//! its JSON tree ([`Mutation`]): add a key (from the keys of the certificate and
//! shape formats, plus `clockwise`, `bounds`, `bound`, `digest`, `extra`) with a
//! boolean, a small integer, a canonical rational or a copy of a subtree; remove
//! a key; duplicate a key at the text level; swap two values of the same kind;
//! move a number to a nearby canonical rational; remove or duplicate an array
//! element; put another seed's shape in `a` or `b`. The result is serialized
//! compactly (with the text-level duplications inserted) and given to
//! `lncert::certify::verify::verify`.
//!
//! A run much slower than reading the bytes is a finding too (the resource
//! oracle `verify_timed`: at most 200 x the reading time + 250 ms, issue 64).
//!
//! Must never panic, except on an oracle violation: an accepted certificate must
//! have canonical shapes (`ShapeDesc::from_value(x).to_json() == x`) and a true
//! claim (the certified lower bound of an independent search ≤ `tol`), as in the
//! `verify` target. 256-1024 bytes of choices are plenty (`-max_len=1024`).

use arbitrary::{Arbitrary, Unstructured};
use libfuzzer_sys::{fuzz_target, Corpus};
use lncert::scalar::{parse_rational, Rational};

#[path = "common/verify_oracle.rs"]
mod verify_oracle;
use serde_json::Value;
use std::fmt::Write;
use std::sync::OnceLock;
use verify_oracle::{check_accepted, verify_timed};

const SEED_TEXTS: [&str; 22] = [
    include_str!("../seeds/verify/cert_quad_seg.json"),
    include_str!("../seeds/verify/cert_quad_seg_tol1.json"),
    include_str!("../seeds/verify/cert_box_deleted.json"),
    include_str!("../seeds/verify/cert_arc_cubic.json"),
    include_str!("../seeds/verify/cert_ellipse_arc_cubic.json"),
    include_str!("../seeds/verify/cert_offset_quad.json"),
    include_str!("../seeds/verify/cert_convolution_quad.json"),
    include_str!("../seeds/verify/cert_convolution_segment.json"),
    include_str!("../seeds/verify/cert_map_quad_seg.json"),
    include_str!("../seeds/verify/cert_map_arc_cubic.json"),
    include_str!("../seeds/verify/cert_map_offset_quad.json"),
    include_str!("../seeds/verify/cert_union_conv_sides.json"),
    include_str!("../seeds/verify/stroke_segment.json"),
    include_str!("../seeds/verify/stroke_corner.json"),
    include_str!("../seeds/verify/stroke_distance_rect.json"),
    include_str!("../seeds/verify/stroke_ellipse_segment.json"),
    include_str!("../seeds/verify/stroke_set_two.json"),
    include_str!("../seeds/verify/stroke_curve.json"),
    include_str!("../seeds/verify/stroke_arcs.json"),
    include_str!("../seeds/verify/cert_radial_arc_cubic.json"),
    include_str!("../seeds/verify/cert_radial_half_arc.json"),
    include_str!("../seeds/verify/cert_radial_circle.json"),
];

fn seeds() -> &'static [Value] {
    static SEEDS: OnceLock<Vec<Value>> = OnceLock::new();
    SEEDS.get_or_init(|| {
        SEED_TEXTS
            .iter()
            .map(|t| serde_json::from_str(t).expect("an embedded seed is JSON"))
            .collect()
    })
}

/// Keys a forger may add: every key of the formats, and the classic extras.
#[rustfmt::skip]
const KEYS: [&str; 53] = [
    "clockwise", "bounds", "bound", "digest", "beziers", "bezier", "arc", "ellipse_arc", "matrix", "offset",
    "convolution", "side", "ellipse", "curve", "distance", "radius", "center", "from", "to",
    "piece", "target", "s", "t", "k", "tol", "claim", "extra", "format", "version", "directions",
    "maps", "phi", "union",
    // stroke and stroke distance certificates
    "outline", "cover", "boundary", "of", "boxes", "near", "inside", "contour", "u", "o", "w",
    "mu", "dirs", "at", "pen", "members", "certificate", "segment",
    // radial certificates (version 4)
    "radial", "cells",
];

/// A value to put somewhere.
#[derive(Arbitrary, Debug)]
enum NewValue {
    Bool(bool),
    SmallInt(i8),
    /// `p/q` in canonical form (`q` made ≥ 1).
    Rational(i16, u16),
    /// A copy of the `n`-th node (pre-order, modulo the node count).
    Copy(u16),
    /// A copy of a seed's shape `a` (or `b`).
    SeedShape(u8, bool),
    Null,
}

/// A nearby canonical rational.
#[derive(Arbitrary, Debug, Clone, Copy)]
enum Nudge {
    PlusThousandth,
    MinusThousandth,
    TimesOnePlusThousandth,
    TimesOneMinusThousandth,
    /// ± 2⁻⁵⁰: a few ulps at magnitude 1 (below the search's rounding slack).
    PlusTiny,
    MinusTiny,
    Negate,
    Zero,
}

/// One structured mutation; node and object choices are indices (pre-order,
/// taken modulo the number of candidates).
#[derive(Arbitrary, Debug)]
enum Mutation {
    AddKey {
        object: u16,
        key: u8,
        value: NewValue,
    },
    RemoveKey {
        object: u16,
        which: u8,
    },
    /// Text level: `"key":value,` right after the object's `{`; the key is one
    /// of the object's own (`own`) or one of [`KEYS`].
    DuplicateKey {
        object: u16,
        own: bool,
        key: u8,
        value: Option<NewValue>,
    },
    SwapValues {
        first: u16,
        second: u16,
    },
    NudgeNumber {
        node: u16,
        how: Nudge,
    },
    RemoveElement {
        array: u16,
        which: u8,
    },
    DuplicateElement {
        array: u16,
        which: u8,
    },
    ReplaceShape {
        b: bool,
        seed: u8,
        other: bool,
    },
}

#[derive(Clone, Debug, PartialEq)]
enum Seg {
    Key(String),
    Idx(usize),
}

/// The paths of the nodes satisfying `keep`, pre-order (the root is `[]`).
fn paths(v: &Value, keep: &dyn Fn(&Value) -> bool) -> Vec<Vec<Seg>> {
    fn walk(v: &Value, keep: &dyn Fn(&Value) -> bool, at: &mut Vec<Seg>, out: &mut Vec<Vec<Seg>>) {
        if keep(v) {
            out.push(at.clone());
        }
        match v {
            Value::Object(m) => {
                for (k, x) in m {
                    at.push(Seg::Key(k.clone()));
                    walk(x, keep, at, out);
                    at.pop();
                }
            }
            Value::Array(a) => {
                for (i, x) in a.iter().enumerate() {
                    at.push(Seg::Idx(i));
                    walk(x, keep, at, out);
                    at.pop();
                }
            }
            _ => {}
        }
    }
    let mut out = Vec::new();
    walk(v, keep, &mut Vec::new(), &mut out);
    out
}

fn get<'v>(v: &'v Value, path: &[Seg]) -> Option<&'v Value> {
    path.iter().try_fold(v, |x, s| match s {
        Seg::Key(k) => x.get(k),
        Seg::Idx(i) => x.get(*i),
    })
}

fn get_mut<'v>(v: &'v mut Value, path: &[Seg]) -> Option<&'v mut Value> {
    path.iter().try_fold(v, |x, s| match s {
        Seg::Key(k) => x.get_mut(k),
        Seg::Idx(i) => x.get_mut(*i),
    })
}

/// The `n`-th (modulo) of the nodes satisfying `keep`.
fn pick(doc: &Value, n: u16, keep: impl Fn(&Value) -> bool) -> Option<Vec<Seg>> {
    let mut c = paths(doc, &keep);
    let i = n as usize % c.len().max(1);
    (i < c.len()).then(|| c.swap_remove(i))
}

fn kind(v: &Value) -> u8 {
    match v {
        Value::Null => 0,
        Value::Bool(_) => 1,
        Value::Number(_) => 2,
        Value::String(_) => 3,
        Value::Array(_) => 4,
        Value::Object(_) => 5,
    }
}

fn q(r: &Rational) -> Value {
    Value::String(r.to_string())
}

fn new_value(doc: &Value, v: &NewValue) -> Value {
    match v {
        NewValue::Bool(b) => Value::Bool(*b),
        NewValue::SmallInt(i) => Value::from(*i),
        NewValue::Rational(p, d) => {
            let r = parse_rational(&format!("{p}/{}", (*d).max(1))).expect("p/q with q >= 1");
            q(&r)
        }
        NewValue::Copy(n) => pick(doc, *n, |_| true)
            .and_then(|p| get(doc, &p).cloned())
            .unwrap_or(Value::Null),
        NewValue::SeedShape(s, b) => {
            seeds()[*s as usize % seeds().len()][if *b { "b" } else { "a" }].clone()
        }
        NewValue::Null => Value::Null,
    }
}

fn nudge(x: &Value, how: Nudge) -> Option<Value> {
    if let Value::Number(n) = x {
        // JSON integers (piece, target, version, side): step by one
        let i: i64 = n.to_string().parse().ok()?;
        let j = match how {
            Nudge::PlusThousandth | Nudge::TimesOnePlusThousandth | Nudge::PlusTiny => i + 1,
            Nudge::Negate => -i,
            Nudge::Zero => 0,
            _ => i - 1,
        };
        return Some(Value::from(j));
    }
    let r = parse_rational(x.as_str()?).ok()?;
    let thousandth = parse_rational("1/1000").ok()?;
    let tiny = parse_rational(&format!("1/{}", 1u64 << 50)).ok()?;
    let one = parse_rational("1").ok()?;
    let y = match how {
        Nudge::PlusThousandth => &r + &thousandth,
        Nudge::MinusThousandth => &r - &thousandth,
        Nudge::TimesOnePlusThousandth => &r * (&one + &thousandth),
        Nudge::TimesOneMinusThousandth => &r * (&one - &thousandth),
        Nudge::PlusTiny => &r + &tiny,
        Nudge::MinusTiny => &r - &tiny,
        Nudge::Negate => -r.clone(),
        Nudge::Zero => parse_rational("0").ok()?,
    };
    Some(q(&y))
}

/// Applies one tree mutation; a text-level duplication is returned instead as
/// (object index among the objects, pre-order; the member text to insert).
fn apply(doc: &mut Value, m: &Mutation) -> Option<(usize, String)> {
    match m {
        Mutation::AddKey { object, key, value } => {
            let v = new_value(doc, value);
            let p = pick(doc, *object, Value::is_object)?;
            if let Some(Value::Object(o)) = get_mut(doc, &p) {
                o.insert(KEYS[*key as usize % KEYS.len()].to_string(), v);
            }
        }
        Mutation::RemoveKey { object, which } => {
            let p = pick(doc, *object, |v| {
                v.as_object().is_some_and(|o| !o.is_empty())
            })?;
            if let Some(Value::Object(o)) = get_mut(doc, &p) {
                let k = o.keys().nth(*which as usize % o.len())?.clone();
                o.remove(&k);
            }
        }
        Mutation::DuplicateKey {
            object,
            own,
            key,
            value,
        } => {
            let objects = paths(doc, &Value::is_object);
            if objects.is_empty() {
                return None;
            }
            let i = *object as usize % objects.len();
            let o = get(doc, &objects[i])?.as_object()?;
            let k = match o.keys().nth(*key as usize % o.len().max(1)) {
                Some(k) if *own => k.clone(),
                _ => KEYS[*key as usize % KEYS.len()].to_string(),
            };
            let v = match value {
                Some(v) => new_value(doc, v),
                None => o.get(&k).cloned().unwrap_or(Value::Bool(true)),
            };
            let mut member = String::new();
            write_str(&mut member, &k);
            member.push(':');
            write_compact(&v, &mut member, &mut Vec::new());
            member.push(',');
            return Some((i, member));
        }
        Mutation::SwapValues { first, second } => {
            let p1 = pick(doc, *first, |_| true)?;
            let k = kind(get(doc, &p1)?);
            let p2 = pick(doc, *second, |v| kind(v) == k)?;
            // not a node and one of its ancestors
            if p1.starts_with(&p2) || p2.starts_with(&p1) {
                return None;
            }
            let v1 = get(doc, &p1)?.clone();
            let v2 = std::mem::replace(get_mut(doc, &p2)?, v1);
            *get_mut(doc, &p1)? = v2;
        }
        Mutation::NudgeNumber { node, how } => {
            // a cheap look at the many candidates; `nudge` parses the one picked
            let p = pick(doc, *node, |v| {
                v.is_number()
                    || v.as_str().is_some_and(|s| {
                        !s.is_empty()
                            && s.len() < 200
                            && s.bytes()
                                .all(|c| c.is_ascii_digit() || c == b'-' || c == b'/')
                    })
            })?;
            let y = nudge(get(doc, &p)?, *how)?;
            *get_mut(doc, &p)? = y;
        }
        Mutation::RemoveElement { array, which } => {
            let p = pick(doc, *array, |v| v.as_array().is_some_and(|a| !a.is_empty()))?;
            if let Some(Value::Array(a)) = get_mut(doc, &p) {
                let i = *which as usize % a.len();
                a.remove(i);
            }
        }
        Mutation::DuplicateElement { array, which } => {
            let p = pick(doc, *array, |v| v.as_array().is_some_and(|a| !a.is_empty()))?;
            if let Some(Value::Array(a)) = get_mut(doc, &p) {
                let i = *which as usize % a.len();
                let x = a[i].clone();
                a.insert(i, x);
            }
        }
        Mutation::ReplaceShape { b, seed, other } => {
            let s = &seeds()[*seed as usize % seeds().len()];
            let from = if *other { "b" } else { "a" };
            if let Value::Object(o) = doc {
                o.insert(if *b { "b" } else { "a" }.to_string(), s[from].clone());
            }
        }
    }
    None
}

fn write_str(out: &mut String, s: &str) {
    out.push_str(&serde_json::to_string(s).unwrap_or_default());
}

/// Compact JSON, recording the offset of every object's `{` (pre-order).
fn write_compact(v: &Value, out: &mut String, objects: &mut Vec<usize>) {
    match v {
        Value::Null => out.push_str("null"),
        Value::Bool(b) => out.push_str(if *b { "true" } else { "false" }),
        Value::Number(n) => {
            let _ = write!(out, "{n}");
        }
        Value::String(s) => write_str(out, s),
        Value::Array(a) => {
            out.push('[');
            for (i, x) in a.iter().enumerate() {
                if i > 0 {
                    out.push(',');
                }
                write_compact(x, out, objects);
            }
            out.push(']');
        }
        Value::Object(m) => {
            objects.push(out.len());
            out.push('{');
            for (i, (k, x)) in m.iter().enumerate() {
                if i > 0 {
                    out.push(',');
                }
                write_str(out, k);
                out.push(':');
                write_compact(x, out, objects);
            }
            out.push('}');
        }
    }
}

/// The forged text: the compact tree, with the duplicated members inserted.
fn serialize(doc: &Value, dups: &[(usize, String)]) -> String {
    let mut text = String::new();
    let mut objects = Vec::new();
    write_compact(doc, &mut text, &mut objects);
    let mut inserts: Vec<(usize, &str)> = dups
        .iter()
        .filter_map(|(i, member)| {
            let at = *objects.get(i % objects.len().max(1))? + 1;
            // `{"k":v,}` is not JSON: into an empty object goes the member alone
            let member = if text.as_bytes().get(at) == Some(&b'}') {
                member.strip_suffix(',').unwrap_or(member)
            } else {
                member.as_str()
            };
            Some((at, member))
        })
        .collect();
    inserts.sort_by_key(|x| std::cmp::Reverse(x.0));
    for (at, member) in inserts {
        text.insert_str(at, member);
    }
    text
}

/// `VERIFY_STRUCT_PRINT=1`: print every forged text and its verdict (to
/// replay an input: `cargo fuzz run verify_struct FILE`).
static PRINT: OnceLock<bool> = OnceLock::new();

fn run(u: &mut Unstructured) -> arbitrary::Result<()> {
    let mut doc = seeds()[u.choose_index(seeds().len())?].clone();
    let n = u.int_in_range(1..=4)?;
    let mut dups = Vec::new();
    for _ in 0..n {
        let m: Mutation = u.arbitrary()?;
        if let Some(d) = apply(&mut doc, &m) {
            dups.push(d);
        }
    }
    let text = serialize(&doc, &dups);
    let verdict = verify_timed(&text);
    if *PRINT.get_or_init(|| std::env::var_os("VERIFY_STRUCT_PRINT").is_some()) {
        eprintln!("{text}\n=> {verdict:?}");
    }
    if let Ok(v) = verdict {
        check_accepted(&text, &v.tol);
    }
    Ok(())
}

fuzz_target!(|data: &[u8]| -> Corpus {
    match run(&mut Unstructured::new(data)) {
        Ok(()) => Corpus::Keep,
        Err(_) => Corpus::Reject,
    }
});
