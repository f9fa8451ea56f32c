//! Entry points of the fuzz targets (`fuzz/fuzz_targets/*.rs`), kept in the
//! library so that every crash input committed under `fuzz/regressions/` is
//! replayed by an ordinary test (`cli/tests/fuzz_regressions.rs`) through the very
//! same code.
//!
//! Each function takes raw fuzzer bytes and returns
//! * `Ok(Outcome::Rejected)` — the bytes do not make a useful case (the target
//!   answers `Corpus::Reject`, so libFuzzer does not keep them);
//! * `Ok(Outcome::Checked)` — the case ran in all arithmetics and the certified
//!   path held;
//! * `Err(message)` — a certified-path failure (the target panics with it).
//!
//! A panic inside the engine is itself a failure the fuzzer reports.

use super::{
    check_arc, check_bezier, check_frame, check_hermite_with, check_pair, check_tau, KernelStats,
};
use arbitrary::{Arbitrary, Unstructured};
use lncert::gen::{BezierCase, HermiteCase};

/// What one fuzz input did.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Outcome {
    /// Not a useful case (generator or kernel rejected it).
    Rejected,
    /// Checked, certified path consistent.
    Checked,
}

fn run<T: for<'a> Arbitrary<'a>>(
    name: &'static str,
    data: &[u8],
    check: impl Fn(&T, &mut KernelStats),
) -> Result<Outcome, String> {
    let Ok(case) = T::arbitrary(&mut Unstructured::new(data)) else {
        return Ok(Outcome::Rejected);
    };
    let mut st = KernelStats::new(name);
    check(&case, &mut st);
    if st.cases == 0 {
        return Ok(Outcome::Rejected);
    }
    if st.certified_ok() {
        Ok(Outcome::Checked)
    } else {
        Err(format!("{name}: {}", st.first_failure.unwrap_or_default()))
    }
}

/// The `bezier` target's curves: [`BezierCase`]'s distribution with a
/// smaller degree range, picked by the first byte modulo 64: 0 → degree 1–9
/// (as in `lncert audit` and the property tests), 1–31 → degree 1–4, else
/// degree 1–3. Exact root isolation of the hodograph's `gcd(x', y')` costs
/// about 0.2, 0.3, 0.6, 1.0 ms at degrees 1–4 and 2, 3, 5, 7, 10 ms at degrees
/// 5–9 (debug assertions on), so the full range on every input kept the target
/// near 700 runs/s.
struct FuzzBezier(BezierCase);

impl<'a> Arbitrary<'a> for FuzzBezier {
    fn arbitrary(u: &mut Unstructured<'a>) -> arbitrary::Result<Self> {
        let max_points = match u.int_in_range(0u8..=63)? {
            0 => 10,
            1..=31 => 5,
            _ => 4,
        };
        BezierCase::arbitrary_up_to(u, max_points).map(FuzzBezier)
    }
}

/// A deterministic hash of the input bytes (FNV-1a, 32 bits) that picks the
/// inputs on which an expensive oracle runs.
pub fn sample_hash(data: &[u8]) -> u32 {
    data.iter().fold(0x811c_9dc5u32, |h, &b| {
        (h ^ u32::from(b)).wrapping_mul(0x0100_0193)
    })
}

/// Bézier curves (mostly degree 1–4, one input in 64 up to 9): evaluation,
/// split, hodograph products, regularity.
pub fn fuzz_bezier(data: &[u8]) -> Result<Outcome, String> {
    run("bezier", data, |c: &FuzzBezier, st: &mut KernelStats| {
        check_bezier(&c.0, st)
    })
}
/// Seed 000 frames: collinearity decision and `λ²`.
pub fn fuzz_frame(data: &[u8]) -> Result<Outcome, String> {
    run("frame", data, check_frame)
}
/// Seed 000 eq. (1) / Prop 3.1.
pub fn fuzz_cubic(data: &[u8]) -> Result<Outcome, String> {
    run("cubic", data, check_tau)
}
/// Seed 000 Props 4.2 / 4.4.
pub fn fuzz_pair(data: &[u8]) -> Result<Outcome, String> {
    run("pair", data, check_pair)
}
/// Seed 003 Props 2.1, 3.1–3.3: every decision and value in the three
/// arithmetics on every input; the comparison of Props 2.1 and 3.2 with exact
/// root isolation (Sturm counts of the normal forms, an independent oracle that
/// took 40 % of the target's time) on one input in 4: those whose bytes hash
/// ([`sample_hash`]) to 0 modulo 4, so a replayed input re-runs the same
/// checks. A hash of all the bytes, not one byte: the fuzzer keeps the inputs
/// that reach the oracle's code and mutates them, and a mutation that keeps a
/// chosen byte would keep the oracle on (with the last byte, a third of the
/// time was still the oracle's).
pub fn fuzz_hermite(data: &[u8]) -> Result<Outcome, String> {
    let isolate = sample_hash(data) % 4 == 0;
    run("hermite", data, |c: &HermiteCase, st: &mut KernelStats| {
        check_hermite_with(c, st, isolate)
    })
}
/// Seed 000 Prop 6.1.
pub fn fuzz_arc(data: &[u8]) -> Result<Outcome, String> {
    run("arc", data, check_arc)
}

/// The CLI's input parsers on arbitrary text: number literals, JSON curves and
/// SVG path data. They must never panic; an accepted number literal must
/// print back to a string that parses to the same rational, and an accepted
/// curve must have finite exact coordinates whose f64 enclosures contain them.
pub fn fuzz_parse(data: &[u8]) -> Result<Outcome, String> {
    use lncert::scalar::{interval_from_rational, parse_rational, IntervalExt};
    let Ok(text) = std::str::from_utf8(data) else {
        return Ok(Outcome::Rejected);
    };
    if let Ok(r) = parse_rational(text) {
        let back = parse_rational(&r.to_string())
            .map_err(|e| format!("parse: {r} does not re-parse: {e}"))?;
        if back != r {
            return Err(format!("parse: {text:?} -> {r} -> {back}"));
        }
        if !interval_from_rational(&r).contains_rational(&r) {
            return Err(format!("parse: enclosure of {r} misses it"));
        }
    }
    for curves in [
        lncert::shape::parse_json_curve(text),
        lncert::shape::parse_svg_path(text),
    ]
    .into_iter()
    .flatten()
    {
        for c in &curves {
            for p in c.points() {
                for v in [&p.x, &p.y] {
                    if !interval_from_rational(v).contains_rational(v) {
                        return Err(format!("parse: enclosure of coordinate {v} misses it"));
                    }
                }
            }
        }
    }
    // the exact path (SVG arcs kept exact): every arc's ends exactly on its
    // circle, of radius > 0
    if let Ok((path, _)) = lncert::stroke::parse_path(text) {
        for p in &path {
            if let lncert::stroke::PathPiece::Arc(a) = p {
                let r2 = &a.radius * &a.radius;
                let on = |q: &lncert::curve::V2<lncert::scalar::Rational>| {
                    let d = q.sub(&a.center);
                    d.dot(&d) == r2
                };
                if a.radius <= lncert::scalar::Rational::from_integer(0.into())
                    || !on(&a.from)
                    || !on(&a.to)
                {
                    return Err(format!("parse_path: an arc off its circle: {a:?}"));
                }
            }
        }
    }
    Ok(Outcome::Checked)
}
