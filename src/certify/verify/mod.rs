//! The independent certificate checker behind `lncert verify`.
//!
//! It shares nothing with the search but the scalar layer (inari intervals,
//! exact rationals) and the crate's bounded JSON reader: its own
//! strict reader of the canonical shapes (`read`), its own de Casteljau
//! evaluation, arc and offset formulas and its own second-order Taylor
//! arithmetic (`eval`). It never searches: it walks the boxes of the
//! certificate, checks that they cover every parameter domain exactly (rational
//! comparisons), that each foot map stays inside its target's domain, and that
//! the recomputed bound of each box is ≤ the tolerance; the first failure is
//! reported with its field, or its direction and box index.
//!
//! # What is read, and what is refused
//!
//! A certificate is read *strictly*: the document is parsed under
//! the input limits (at most [`MAX_INPUT_BYTES`](crate::shape::MAX_INPUT_BYTES) bytes; depth, values,
//! number length — checked while parsing), duplicate keys are refused at every
//! level, every object must have exactly the keys of the format (no key is
//! ignored, none is informational), every number must be in canonical form
//! (`"p/q"` in lowest terms) and within `10¹⁰⁰` in magnitude, and every shape
//! must be in the canonical shape form (see `proofs/certify-hausdorff.md`). So
//! the statement a valid certificate makes is exactly the one [`Valid::statement`]
//! prints, and nothing in the file is left unchecked.
//!
//! Work is linear in the size of the document: each box costs at most
//! `O(64²)` interval operations (64 control points per piece), and each number
//! at most 4 096 characters of big-integer parsing.

mod budget;
mod eval;
pub(crate) mod index;
mod radial;
mod read;
pub mod stroke;

pub(crate) use budget::Budget;
pub use budget::{BASE_WORK, WORK_PER_BYTE};

use super::cert::{CLAIM, FORMAT, VERSION, VERSION_2, VERSION_RADIAL};
use crate::json::{parse, Json, Limits};
use crate::scalar::{rational_from_f64, Interval, Rational};
use eval::{check_box, check_map_box, le_rational, reach, VShape};
use num_traits::{Signed, Zero};
use rayon::prelude::*;
use read::{canonical_index, canonical_rational, exact_object, read_shape};

/// Why a certificate is invalid.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct Invalid {
    /// Where: a field (`a.arc.radius`), or `directions[d].boxes[i]`.
    pub at: String,
    /// What failed.
    pub reason: String,
}

impl std::fmt::Display for Invalid {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        write!(f, "{}: {}", self.at, self.reason)
    }
}

/// A valid certificate: what it proves, and the figures of the check.
#[derive(Clone, Debug, PartialEq)]
pub struct Valid {
    /// The tolerance proven: `d_H(A, B) ≤ tol`.
    pub tol: Rational,
    /// Shape `A`, described from its exact data.
    pub a: String,
    /// Shape `B`, described from its exact data.
    pub b: String,
    /// The largest recomputed box bound (an upper bound on the Hausdorff distance).
    pub max_bound: f64,
    /// Boxes checked.
    pub boxes: usize,
}

impl Valid {
    /// The statement proven, in words.
    pub fn statement(&self) -> String {
        format!(
            "d_H(A, B) ≤ {} where
  A = {}
  B = {}",
            self.tol, self.a, self.b
        )
    }
}

pub(crate) fn inv(at: impl Into<String>, reason: impl Into<String>) -> Invalid {
    Invalid {
        at: at.into(),
        reason: reason.into(),
    }
}

/// Reads one shape document in the canonical form exactly as the verifier
/// reads a certificate's `a` and `b`; `Ok` is its description in words.
///
/// Regularity of an offset's or convolution's curve is not decided here: a
/// certificate proves it, since its boxes evaluate the normal of every piece
/// over its whole domain with `nᵀQn` enclosed away from 0.
///
/// # Examples
/// ```
/// use lncert::certify::verify::read_canonical_shape;
/// let ok = read_canonical_shape(r#"{"beziers": [[["0", "0"], ["1/2", "1"]]]}"#).unwrap();
/// assert!(ok.contains("1 Bézier piece of degree ≤ 1"));
/// // the user language accepts JSON numbers; the canonical form does not
/// let e = read_canonical_shape(r#"{"beziers": [[[0, 0], ["1/2", "1"]]]}"#).unwrap_err();
/// assert_eq!(e.at, "beziers[0][0][0]");
/// ```
pub fn read_canonical_shape(text: &str) -> Result<String, Invalid> {
    let doc = parse(text, &Limits::DEFAULT).map_err(|e| inv(e.path.clone(), e.reason))?;
    read_shape(&doc, "").map(|s| s.text).map_err(top_level)
}

/// Errors about the document itself name it `(top level)`.
fn top_level(mut e: Invalid) -> Invalid {
    if e.at.is_empty() {
        e.at = "(top level)".to_string();
    }
    e
}

#[cfg(test)]
mod tests;

/// The keys of a version 3 certificate, all required (the certificate
/// writes them in this order).
pub(super) const KEYS: [&str; 8] = [
    "format",
    "version",
    "claim",
    "tol",
    "a",
    "b",
    "maps",
    "directions",
];
/// The keys of a version 2 certificate (no maps), all required.
const KEYS_2: [&str; 7] = ["format", "version", "claim", "tol", "a", "b", "directions"];
/// The keys of a version 4 (radial) certificate, all required.
const KEYS_RADIAL: [&str; 7] = ["format", "version", "claim", "tol", "a", "b", "radial"];

/// Verifies a certificate document.
///
/// # Examples
/// ```
/// use lncert::certify::{hausdorff, Certificate, Config};
/// use lncert::shape::ShapeDesc;
/// use lncert::certify::verify::verify;
/// use lncert::Tolerance;
/// let a = ShapeDesc::parse("M 0 0 Q 0.5 0.5 1 0").unwrap();
/// let b = ShapeDesc::parse("M 0 0 L 1 0").unwrap();
/// let tol: Tolerance = "0.26".parse().unwrap();
/// // a certificate is built from the search's box covers: `parametric: false`
/// let cfg = Config { tol: Some(tol.clone()), parametric: false, ..Config::default() };
/// let r = hausdorff(&a, &b, &cfg).unwrap();
/// let cert = Certificate::new(&a, &b, &tol, &r).unwrap();
/// let valid = verify(&cert.to_json_string()).unwrap();
/// assert!(valid.statement().contains("d_H(A, B) ≤ 13/50"));
/// let mut forged = cert.doc.clone();
/// forged["tol"] = "1/5".into(); // 0.2 < 1/4: false claim
/// assert!(verify(&forged.to_string()).is_err());
/// forged["tol"] = "0.26".into(); // not canonical
/// assert_eq!(verify(&forged.to_string()).unwrap_err().at, "tol");
/// ```
pub fn verify(text: &str) -> Result<Valid, Invalid> {
    verify_json(&read_document(text)?)
}

/// A certificate's text read by the crate's bounded JSON reader (the
/// reading time logged at `debug`: `cli/benches/verifier_resources.rs`
/// reads it).
pub(crate) fn read_document(text: &str) -> Result<Json<'_>, Invalid> {
    let t0 = std::time::Instant::now();
    let doc = parse(text, &Limits::DEFAULT).map_err(|e| {
        inv(
            e.path.clone(),
            format!("{} (line {}, column {})", e.reason, e.line, e.column),
        )
    })?;
    log::debug!(
        "certificate: {} bytes read in {:?}",
        text.len(),
        t0.elapsed()
    );
    Ok(doc)
}

/// [`verify`] on a document already read by the crate's bounded JSON reader.
///
/// The check's work is bounded by the document's size: at most
/// [`WORK_PER_BYTE`] work units per byte of its compact JSON, plus
/// [`BASE_WORK`] (see `budget`); a document that needs more is refused as
/// too costly to check.
pub(crate) fn verify_json(doc: &Json) -> Result<Valid, Invalid> {
    let budget = Budget::for_size(budget::json_size(doc));
    let r = check_document(doc, &budget).map_err(top_level);
    log::debug!(
        "certificate: {} of {} work units used",
        budget.used(),
        budget.limit()
    );
    r
}

/// A Hausdorff certificate only (no other format): the first part of a
/// stroke distance certificate.
pub(crate) fn check_hausdorff_document(doc: &Json, budget: &Budget) -> Result<Valid, Invalid> {
    if doc.get("format").and_then(|f| f.as_str()) != Some(FORMAT) {
        return Err(inv("format", format!("expected \"{FORMAT}\"")));
    }
    check_document(doc, budget)
}

fn check_document(doc: &Json, budget: &Budget) -> Result<Valid, Invalid> {
    // the format and version first: another format's keys are not errors of this one
    if let Some(format) = doc.get("format") {
        if format.as_str() == Some(stroke::FORMAT) {
            return stroke::check(doc, budget);
        }
        if format.as_str() == Some(stroke::DISTANCE_FORMAT) {
            return stroke::check_distance(doc, budget);
        }
        if format.as_str() == Some(stroke::SET_FORMAT) {
            return stroke::check_set(doc, budget);
        }
        if format.as_str() != Some(FORMAT) {
            return Err(inv(
                "format",
                format!(
                    "expected \"{FORMAT}\", \"{}\", \"{}\" or \"{}\"",
                    stroke::FORMAT,
                    stroke::DISTANCE_FORMAT,
                    stroke::SET_FORMAT
                ),
            ));
        }
    }
    let version = match doc.get("version") {
        Some(Json::Number(v)) if **v == *VERSION_2.to_string() => VERSION_2,
        Some(Json::Number(v)) if **v == *VERSION.to_string() => VERSION,
        Some(Json::Number(v)) if **v == *VERSION_RADIAL.to_string() => VERSION_RADIAL,
        Some(_) => {
            return Err(inv(
                "version",
                format!("unsupported; this verifier reads versions {VERSION_2}, {VERSION} and {VERSION_RADIAL} (version 1 carried unverified fields and a digest that authenticated nothing: re-run the proof to get a version {VERSION} certificate)"),
            ))
        }
        None => VERSION,
    };
    if version == VERSION_RADIAL {
        let [_format, _version, claim, tol, a, b, radial] = exact_object(doc, "", KEYS_RADIAL)?;
        let (tol, shapes) = head(claim, tol, a, b)?;
        let (max_bound, boxes) = radial::check(radial, &shapes, &tol)?;
        let [a, b] = shapes.map(|s: VShape| s.text);
        return Ok(Valid {
            tol: tol.exact,
            a,
            b,
            max_bound,
            boxes,
        });
    }
    let (claim, tol, a, b, maps, dirs) = if version == VERSION {
        let [_format, _version, claim, tol, a, b, maps, dirs] = exact_object(doc, "", KEYS)?;
        (claim, tol, a, b, Some(maps), dirs)
    } else {
        let [_format, _version, claim, tol, a, b, dirs] = exact_object(doc, "", KEYS_2)?;
        (claim, tol, a, b, None, dirs)
    };
    let (tol, shapes) = head(claim, tol, a, b)?;
    let mut max_bound = 0.0f64;
    let mut count = 0;
    // which pieces the maps cover: `by_map[shape][piece]` (both directions)
    let mut by_map: [Vec<Option<usize>>; 2] = [
        vec![None; shapes[0].pieces.len()],
        vec![None; shapes[1].pieces.len()],
    ];
    if let Some(maps) = maps {
        let maps = maps
            .as_array()
            .ok_or_else(|| inv("maps", "expected a list of maps"))?;
        for (mi, m) in maps.iter().enumerate() {
            mark_map(m, &format!("maps[{mi}]"), &shapes, &mut by_map, mi)?;
        }
        // the maps are independent: checked in parallel, the first failure
        // in document order reported
        let checked: Vec<_> = maps
            .par_iter()
            .enumerate()
            .map(|(mi, m)| check_map(m, &format!("maps[{mi}]"), &shapes, &tol))
            .collect();
        for r in checked {
            let (bound, boxes) = r?;
            max_bound = max_bound.max(bound);
            count += boxes;
        }
    }
    let dirs = dirs
        .as_array()
        .filter(|d| d.len() == 2)
        .ok_or_else(|| inv("directions", "expected the two directions a→b and b→a"))?;
    for (di, (from, to)) in [(0usize, 1usize), (1, 0)].into_iter().enumerate() {
        let names = ["a", "b"];
        let at_d = format!("directions[{di}]");
        let [dfrom, dto, boxes] = exact_object(&dirs[di], &at_d, ["from", "to", "boxes"])?;
        if dfrom.as_str() != Some(names[from]) || dto.as_str() != Some(names[to]) {
            return Err(inv(
                at_d,
                format!("expected from \"{}\" to \"{}\"", names[from], names[to]),
            ));
        }
        let boxes = boxes
            .as_array()
            .ok_or_else(|| inv(format!("{at_d}.boxes"), "expected a list of boxes"))?;
        let (src, dst) = (&shapes[from], &shapes[to]);
        // coverage: per piece, boxes in increasing order, contiguous, from 0 to ≥ the end
        let mut cursor: Vec<Option<Rational>> = by_map[from]
            .iter()
            .map(|m| m.is_none().then(Rational::zero))
            .collect();
        let mut last_piece = 0usize;
        let mut jobs = Vec::with_capacity(boxes.len());
        for (bi, bx) in boxes.iter().enumerate() {
            let at = format!("{at_d}.boxes[{bi}]");
            let [piece, s, target, t, k] =
                exact_object(bx, &at, ["piece", "s", "target", "t", "k"])?;
            let piece = canonical_index(piece, &format!("{at}.piece"))?;
            let target = canonical_index(target, &format!("{at}.target"))?;
            if piece >= src.pieces.len() {
                return Err(inv(
                    format!("{at}.piece"),
                    format!(
                        "out of range: {} has {} pieces",
                        names[from],
                        src.pieces.len()
                    ),
                ));
            }
            if target >= dst.pieces.len() {
                return Err(inv(
                    format!("{at}.target"),
                    format!(
                        "out of range: {} has {} pieces",
                        names[to],
                        dst.pieces.len()
                    ),
                ));
            }
            if piece < last_piece {
                return Err(inv(at, "boxes are not ordered by piece"));
            }
            last_piece = piece;
            let s = match s.as_array() {
                Some([s0, s1]) => [s0, s1],
                _ => return Err(inv(format!("{at}.s"), "expected [s0, s1]")),
            };
            let (s0, s1) = (
                canonical_rational(s[0], &format!("{at}.s[0]"))?,
                canonical_rational(s[1], &format!("{at}.s[1]"))?,
            );
            match &cursor[piece] {
                Some(c) if *c == s0 && s0 < s1 => {}
                Some(c) => {
                    return Err(inv(at, format!("gap or overlap in the cover of piece {piece}: expected a box starting at {c}, ending after it")))
                }
                None => match by_map[from][piece] {
                    Some(m) => {
                        return Err(inv(
                            at,
                            format!("piece {piece} of {} is covered by maps[{m}]", names[from]),
                        ))
                    }
                    None => return Err(inv(at, format!("piece {piece} is already covered"))),
                },
            }
            let end = src.ends[piece];
            cursor[piece] = if le_rational(end.sup(), &s1) {
                None
            } else {
                Some(s1.clone())
            };
            let t = canonical_rational(t, &format!("{at}.t"))?;
            let k = canonical_rational(k, &format!("{at}.k"))?;
            jobs.push((at, piece, s0, s1, target, t, k));
        }
        if let Some(p) = cursor.iter().position(Option::is_some) {
            return Err(inv(
                format!("directions[{di}].boxes"),
                format!("piece {p} of {} is not covered to its end", names[from]),
            ));
        }
        // the boxes' bounds: independent, checked in parallel, the first
        // failure in document order reported
        let bounds: Vec<_> = jobs
            .par_iter()
            .map(|(at, piece, s0, s1, target, t, k)| {
                let bound = check_box(
                    &src.pieces[*piece],
                    s0,
                    s1,
                    &dst.pieces[*target],
                    dst.ends[*target],
                    t,
                    k,
                )
                .map_err(|r| inv(at, r))?;
                if !within(bound, &tol) {
                    return Err(inv(
                        at,
                        format!("the recomputed bound {bound:e} exceeds the tolerance {tol}"),
                    ));
                }
                Ok(bound)
            })
            .collect();
        for b in bounds {
            max_bound = max_bound.max(b?);
            count += 1;
        }
    }
    let [a, b] = shapes.map(|s: VShape| s.text);
    if count == 0 {
        return Err(inv("(top level)", "no boxes: nothing is proven"));
    }
    Ok(Valid {
        tol: tol.exact,
        a,
        b,
        max_bound,
        boxes: count,
    })
}

/// The claim, the tolerance and the two shapes, read and checked.
fn head(claim: &Json, tol: &Json, a: &Json, b: &Json) -> Result<(Tol, [VShape; 2]), Invalid> {
    if claim.as_str() != Some(CLAIM) {
        return Err(inv(
            "claim",
            format!("expected \"{CLAIM}\", the one claim of this format"),
        ));
    }
    let tol = canonical_rational(tol, "tol")?;
    if tol.is_negative() {
        return Err(inv("tol", "negative"));
    }
    let tol = Tol {
        below: crate::scalar::interval_from_rational(&tol).inf(),
        exact: tol,
    };
    Ok((tol, [read_shape(a, "a")?, read_shape(b, "b")?]))
}

/// The head of a map: source shape and piece, target shape and piece (in
/// range), and its boxes.
#[allow(clippy::type_complexity)]
fn map_head<'j, 'a>(
    m: &'j Json<'a>,
    at: &str,
    shapes: &[VShape; 2],
) -> Result<((usize, usize), (usize, usize), &'j Json<'a>), Invalid> {
    let names = ["a", "b"];
    let [from, piece, to, target, boxes] =
        exact_object(m, at, ["from", "piece", "to", "target", "boxes"])?;
    let (f, t) = match (from.as_str(), to.as_str()) {
        (Some("a"), Some("b")) => (0, 1),
        (Some("b"), Some("a")) => (1, 0),
        _ => {
            return Err(inv(
                at,
                "expected from \"a\" to \"b\", or from \"b\" to \"a\"",
            ))
        }
    };
    let piece = canonical_index(piece, &format!("{at}.piece"))?;
    let target = canonical_index(target, &format!("{at}.target"))?;
    for (which, i, field) in [(f, piece, "piece"), (t, target, "target")] {
        if i >= shapes[which].pieces.len() {
            return Err(inv(
                format!("{at}.{field}"),
                format!(
                    "out of range: {} has {} pieces",
                    names[which],
                    shapes[which].pieces.len()
                ),
            ));
        }
    }
    Ok(((f, piece), (t, target), boxes))
}

/// Marks the pieces a map covers; a piece covered by two maps is refused.
fn mark_map(
    m: &Json,
    at: &str,
    shapes: &[VShape; 2],
    by_map: &mut [Vec<Option<usize>>; 2],
    index: usize,
) -> Result<(), Invalid> {
    let names = ["a", "b"];
    let (src, dst, _) = map_head(m, at, shapes)?;
    for ((which, i), field) in [(src, "piece"), (dst, "target")] {
        if let Some(other) = by_map[which][i] {
            return Err(inv(
                format!("{at}.{field}"),
                format!(
                    "piece {i} of {} is already covered by maps[{other}]",
                    names[which]
                ),
            ));
        }
        by_map[which][i] = Some(index);
    }
    Ok(())
}

/// Checks one map (see [`super::cert`]): its bound (end terms included) and
/// its number of boxes.
fn check_map(m: &Json, at: &str, shapes: &[VShape; 2], tol: &Tol) -> Result<(f64, usize), Invalid> {
    let ((f, piece), (t, target), boxes) = map_head(m, at, shapes)?;
    let (src, dst) = (&shapes[f].pieces[piece], &shapes[t].pieces[target]);
    let (src_end, dst_end) = (shapes[f].ends[piece], shapes[t].ends[target]);
    // the source's domain must be exact: the boxes cover exactly [0, end]
    let src_end = match rational_from_f64(src_end.inf()) {
        Some(e) if src_end.inf() == src_end.sup() => e,
        _ => {
            return Err(inv(
                format!("{at}.piece"),
                "the source of a map needs an exact parameter domain (a polynomial piece)",
            ))
        }
    };
    let boxes = boxes
        .as_array()
        .filter(|b| !b.is_empty())
        .ok_or_else(|| inv(format!("{at}.boxes"), "expected a non-empty list of boxes"))?;
    let mut cursor = Rational::zero();
    let mut value: Option<Rational> = None; // φ at the cursor
    let mut first = Rational::zero();
    let mut max_box = 0.0f64;
    for (bi, bx) in boxes.iter().enumerate() {
        let at_b = format!("{at}.boxes[{bi}]");
        let [tb, phi] = exact_object(bx, &at_b, ["t", "phi"])?;
        let (t0, t1) = match tb.as_array() {
            Some([t0, t1]) => (
                canonical_rational(t0, &format!("{at_b}.t[0]"))?,
                canonical_rational(t1, &format!("{at_b}.t[1]"))?,
            ),
            _ => return Err(inv(format!("{at_b}.t"), "expected [t0, t1]")),
        };
        let c = match phi.as_array() {
            Some(cs) if cs.len() == 4 => {
                let mut out: [Rational; 4] = Default::default();
                for (k, x) in cs.iter().enumerate() {
                    out[k] = canonical_rational(x, &format!("{at_b}.phi[{k}]"))?;
                }
                out
            }
            _ => {
                return Err(inv(
                    format!("{at_b}.phi"),
                    "expected the 4 Bernstein coefficients of the map",
                ))
            }
        };
        if t0 != cursor || t0 >= t1 || t1 > src_end {
            return Err(inv(
                at_b,
                format!("gap or overlap in the cover of the source piece: expected a box starting at {cursor}, ending after it, inside [0, {src_end}]"),
            ));
        }
        match &value {
            Some(v) if *v != c[0] => {
                return Err(inv(
                    format!("{at_b}.phi[0]"),
                    format!("the map is not continuous: the previous box ends at {v}"),
                ))
            }
            Some(_) => {}
            None => first = c[0].clone(),
        }
        let bound = check_map_box(src, &t0, &t1, dst, dst_end, &c).map_err(|r| inv(&at_b, r))?;
        if !within(bound, tol) {
            return Err(inv(
                at_b,
                format!("the recomputed bound {bound:e} exceeds the tolerance {tol}"),
            ));
        }
        max_box = max_box.max(bound);
        cursor = t1;
        value = Some(c[3].clone());
    }
    if cursor != src_end {
        return Err(inv(
            format!("{at}.boxes"),
            format!("the source piece is not covered to its end {src_end}"),
        ));
    }
    // φ is onto the range between its end values; the rest of the target's
    // domain, before and after, is within `sup |dst′| · length` of its ends
    let last = value.unwrap_or_default();
    let (lo, hi) = if first <= last {
        (first, last)
    } else {
        (last, first)
    };
    let iv = crate::scalar::interval_from_rational;
    let terms = reach(dst, crate::certify::verify::eval::ic(0), iv(&lo))
        .and_then(|x| Ok(x + reach(dst, iv(&hi), dst_end)?))
        .map_err(|r| inv(at, r))?;
    let total =
        (Interval::try_from((max_box, max_box)).map_err(|_| inv(at, "undefined"))? + terms).sup();
    if !within(total, tol) {
        return Err(inv(
            at,
            format!("the recomputed bound {total:e} (boxes {max_box:e}, ends of the target's domain {:e}) exceeds the tolerance {tol}", terms.sup()),
        ));
    }
    Ok((total, boxes.len()))
}

/// The tolerance, exactly and as the largest float below it.
struct Tol {
    exact: Rational,
    below: f64,
}

impl std::fmt::Display for Tol {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        self.exact.fmt(f)
    }
}

/// `x ≤ tol`, exactly (the float comparison first).
fn within(x: f64, tol: &Tol) -> bool {
    x <= tol.below || le_rational(x, &tol.exact)
}
