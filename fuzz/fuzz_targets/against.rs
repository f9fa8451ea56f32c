#![no_main]
//! Fuzz target `against`: `lncert::certify::verify_against` (what `lncert
//! verify CERT --against A B` runs) on genuine certificates and user shapes
//! derived from the same base pair.
//!
//! The bytes are *choices* (read with `arbitrary::Unstructured`; an exhausted
//! input reads as the first choice everywhere, so a one-byte input is the bare
//! scenario):
//!
//! 1. a scenario (first byte, modulo 32, through [`PICK`]; bytes 0–10 pick the
//!    scenarios in order): a base pair `(A0, B0)` of tiny shapes — two near
//!    cubics, a segment and a quadratic, a polyline and a near copy, an offset
//!    and a cubic, an arc and a cubic, a union (segment and arc) and a curve,
//!    an offset and a convolution — and the four cases of issue 24, which also
//!    fix the user's base shapes and sometimes the tol;
//! 2. the certificate's shapes `(Ac, Bc)` and the user's shapes `(Au, Bu)`,
//!    each by 0–4 rewrites of its base (the user's may start from the
//!    certificate's shape instead). Set-preserving rewrites: split a piece at a
//!    rational (small, dyadic or 8-digit), elevate a piece (by 1–3, or to degree
//!    20–24), reverse a plain curve, insert a one-point piece at a piece's end
//!    or at the curve's start (2 or 3 equal points: the readers take no
//!    1-point piece), turn an offset into the equal convolution
//!    (`M = r R`, `R` orthogonal), scale an arc's directions. Set-changing
//!    ones: a one-point piece elsewhere, a control point moved by a small or
//!    large rational, a piece dropped, an offset's distance or side changed, a
//!    convolution's matrix or side changed, an arc's centre, radius or
//!    direction changed. A rewrite whose result a constructor rejects is skipped;
//! 3. a genuine certificate about `(Ac, Bc)` (box covers, `parametric: false`,
//!    `max_boxes: 48`): tol a little above the search's `hi`, exactly its next
//!    float, on a 1/1024 grid, or fixed (1/4, 1/10, …, searched for); none, no
//!    run. Memoized per shapes and tol choice (the search dominates the cost);
//! 4. optionally one canonical number of its shapes replaced (copied, nudged).
//!
//! Then `verify_against(text, Au, Bu)`. Must never panic, except on a false
//! accept: when it returns `Ok`, `d_H(Au, Bu) ≤ tol` must not be refuted
//! (a) by float samples (33 points per piece of one side against 257 per piece
//! of the other, both directions; the estimate minus the other side's largest
//! sample chord, a lower bound up to float error, must not clearly exceed tol)
//! and (b) by the certified lower bound of `lncert::certify::hausdorff` on the
//! user's shapes (run whenever the user's point sets may differ from the
//! certificate's, and on the other accepts of one input in 8, chosen by a hash
//! of its bytes: `lncert_cli::audit::fuzz::sample_hash`).
//!
//! Issue 24 (scenarios 5–8, seeds fuzz/seeds/against/issue24-*): (1) a
//! certificate whose A has an extra one-point piece at (2, 0) against the
//! segment alone, and (2) one against a user B with a dot at (5, 0), must be
//! rejected; (3) an SVG arc read as its cubic approximation is accepted (the
//! certificate is about the same cubics; the oracles sample the cubics
//! themselves), and (4) a cubic elevated to degree 63 and split at 8-digit
//! rationals in the certificate, the plain cubic as the user's, must be
//! accepted (its certificate's shapes are never rewritten and its tol is 1/8:
//! a search on degree-63 pieces costs 0.2–1 s, the verification 0.1 s; it
//! also has 1 of the 32 slots of the first byte). Unmodified (no rewrites,
//! default choices) a wrong verdict on one of them panics (`AGAINST_STRICT=0`
//! only counts them).
//!
//! `AGAINST_STATS=N`: every `N` runs print the counts (runs, certificates,
//! accepts, rejects by reason, "false rejects": shapes equal in form, with
//! point pieces only where the walk meets them, rejected — a completeness
//! question, never a panic — oracle searches, slowest `verify_against`). `AGAINST_PRINT=1`: print every case.
//! `AGAINST_TIMING=1`: print the time of every run and of its parts.
//! Each run costs 2–20 ms (issue 24's (4): 0.1–0.3 s); `-max_len=1024`.

use libfuzzer_sys::arbitrary::{Result, Unstructured};
use libfuzzer_sys::{fuzz_target, Corpus};
use lncert::certify::{hausdorff, verify_against, Certificate, Config};
use lncert::curve::{Bezier, V2};
use lncert::scalar::{
    frac, interval_from_rational, parse_rational, rational_from_f64, Rational, Scalar,
};
use lncert::shape::ShapeDesc;
use lncert::Tolerance;
use serde_json::Value;
use std::collections::BTreeMap;
use std::sync::atomic::{AtomicU64, Ordering::Relaxed};
use std::sync::{Mutex, OnceLock};
use std::time::Instant;

fn q(p: i64, d: i64) -> Rational {
    frac::<Rational>(p, d)
}

fn zero() -> Rational {
    q(0, 1)
}

fn shape(text: &str) -> ShapeDesc {
    ShapeDesc::parse(text).unwrap_or_else(|e| panic!("scenario shape {text}: {e}"))
}

/// What an unmodified issue-24 case must give.
#[derive(Clone, Copy, PartialEq, Debug)]
enum Expect {
    Any,
    Accept,
    Reject,
}

struct Scenario {
    name: &'static str,
    /// The certificate's base shapes.
    a: ShapeDesc,
    b: ShapeDesc,
    /// The user's base shapes when not the certificate's, and whether each is
    /// the same point set as the certificate's base (`same_as` should accept).
    user_a: Option<(ShapeDesc, bool)>,
    user_b: Option<(ShapeDesc, bool)>,
    /// A fixed tolerance (the issue's), else chosen from the search.
    tol: Option<Rational>,
    expect: Expect,
    /// No rewrites of the certificate's shapes (their certificate is built
    /// once): issue 24's (4), whose search on degree-63 pieces costs 0.2–1 s.
    fixed_cert: bool,
}

const N_SCENARIOS: usize = 11;

/// The first byte modulo 32 picks the scenario: bytes 0–10 are the scenarios
/// in order (the seeds' first bytes), the other slots weight the cheap ones
/// (issue 24's (4), with its degree-63 pieces, costs 20 times a typical run).
const PICK: [u8; 32] = [
    0, 1, 2, 3, 4, 5, 6, 7, 8, 9, 10, // each once
    0, 1, 2, 3, 4, 9, 10, 0, 1, 2, 3, 4, 9, 10, 0, 2, 3, 4, 9, 5, 6,
];

/// The scenarios, built once.
#[allow(non_snake_case)]
fn SCENARIOS() -> &'static [Scenario] {
    static S: OnceLock<Vec<Scenario>> = OnceLock::new();
    S.get_or_init(|| {
        let plain = |name, a: &str, b: &str| Scenario {
            name,
            a: shape(a),
            b: shape(b),
            user_a: None,
            user_b: None,
            tol: None,
            expect: Expect::Any,
            fixed_cert: false,
        };
        let cubic = r#"{"bezier": [[0, 0], ["1/3", "1/2"], ["2/3", "1/2"], [1, 0]]}"#;
        let cubic_near = r#"{"bezier": [[0, "1/32"], ["1/3", "17/32"], ["2/3", "15/32"], [1, 0]]}"#;
        let quarter = r#"{"arc": {"center": [0, 0], "radius": 1, "from": [1, 0], "to": [0, 1]}}"#;
        // issue 24 (4): the cubic elevated to degree 63, split at 8-digit rationals
        let deg63 = {
            let ShapeDesc::Curve(c) = shape(cubic) else {
                unreachable!()
            };
            let mut p = c[0].clone();
            while p.degree() < 63 {
                p = p.elevate();
            }
            let (l, r) = p.split(&q(31_415_926, 99_999_989));
            let (m, r) = r.split(&q(27_182_818, 86_602_540));
            ShapeDesc::curve(vec![l, m, r]).expect("a valid curve")
        };
        let v = vec![
            plain("two near cubics", cubic, cubic_near),
            plain(
                "segment / quadratic",
                "M 0 0 L 1 0",
                r#"{"bezier": [[0, 0], ["1/2", "1/4"], [1, 0]]}"#,
            ),
            plain(
                "polyline / near copy",
                "M 0 0 L 1 0 L 1 1 L 2 1",
                r#"{"beziers": [[[0, "1/64"], [1, 0]], [[1, 0], ["63/64", 1]], [["63/64", 1], [2, 1]]]}"#,
            ),
            plain(
                "offset / cubic",
                r#"{"offset": {"curve": {"bezier": [[0, 0], [1, 1], [2, 0]]}, "distance": "1/4"}}"#,
                r#"{"bezier": [["-1/8", "1/8"], ["2/3", "11/12"], ["4/3", "11/12"], ["17/8", "1/8"]]}"#,
            ),
            plain(
                "arc / cubic",
                quarter,
                r#"{"bezier": [[1, 0], [1, "11/20"], ["11/20", 1], [0, 1]]}"#,
            ),
            Scenario {
                name: "issue 24 (1): extra one-point piece at (2, 0) in the certificate's A",
                a: shape(r#"{"beziers": [[[0, 0], [1, 0]], [[2, 0], [2, 0]]]}"#),
                b: shape("M 0 0 L 2 0"),
                user_a: Some((shape("M 0 0 L 1 0"), false)),
                user_b: None,
                tol: Some(q(51, 100)),
                expect: Expect::Reject,
                fixed_cert: false,
            },
            Scenario {
                name: "issue 24 (2): user B has a dot at (5, 0)",
                a: shape("M 0 0 L 1 0"),
                b: shape("M 0 0 L 1 0"),
                user_a: None,
                user_b: Some((shape("M 0 0 L 1 0 M 5 0 L 5 0"), false)),
                tol: Some(q(1, 1000)),
                expect: Expect::Reject,
                fixed_cert: false,
            },
            Scenario {
                name: "issue 24 (3): SVG arc read as cubics / exact arc",
                a: shape("M 1 0 A 1 1 0 0 1 0 1"),
                b: shape(quarter),
                user_a: None,
                user_b: None,
                tol: None,
                expect: Expect::Accept,
                fixed_cert: false,
            },
            Scenario {
                name: "issue 24 (4): degree 63 split at 8-digit rationals / plain cubic",
                a: deg63,
                b: shape(cubic_near),
                user_a: Some((shape(cubic), true)),
                user_b: None,
                // loose (d_H is about 1/32): few boxes of degree 63 to verify
                tol: Some(q(1, 8)),
                expect: Expect::Accept,
                fixed_cert: true,
            },
            plain(
                "union (segment, arc) / curve",
                r#"{"union": ["M 0 0 L 1 0", {"arc": {"center": [1, 1], "radius": 1, "from": [0, -1], "to": [1, 0]}}]}"#,
                r#"{"beziers": [[[0, 0], [1, 0]], [[1, 0], ["31/20", 0], [2, "9/20"], [2, 1]]]}"#,
            ),
            plain(
                "offset / convolution",
                r#"{"offset": {"curve": "M 0 0 C 1 1 2 1 3 0", "distance": "-1/2"}}"#,
                r#"{"convolution": {"curve": "M 0 0 C 1 1 2 1 3 0", "ellipse": [["1/2", 0], [0, "1/4"]], "side": -1}}"#,
            ),
        ];
        assert_eq!(v.len(), N_SCENARIOS);
        v
    })
}

// ---------------------------------------------------------------- choices

/// A parameter in (0, 1): 1/2, small `n/d`, dyadic, or 8-digit `n/d`.
fn param(u: &mut Unstructured) -> Result<Rational> {
    Ok(match u.int_in_range(0..=3u8)? {
        0 => q(1, 2),
        1 => {
            let d = u.int_in_range(2..=16i64)?;
            q(u.int_in_range(1..=d - 1)?, d)
        }
        2 => {
            let d = 1i64 << u.int_in_range(1..=24u32)?;
            q(u.int_in_range(1..=d - 1)?, d)
        }
        _ => {
            let d = u.int_in_range(10_000_000..=99_999_999i64)?;
            q(u.int_in_range(1..=d - 1)?, d)
        }
    })
}

/// A signed move, small (1/1000, 2⁻²⁰, 10⁻⁸, k/64) or large (1, 5/2).
fn delta(u: &mut Unstructured) -> Result<Rational> {
    let s = if u.arbitrary::<bool>()? { -1 } else { 1 };
    Ok(match u.int_in_range(0..=5u8)? {
        0 => q(s, 1000),
        1 => q(s, 1 << 20),
        2 => q(s, 100_000_000),
        3 => q(s, 1),
        4 => q(5 * s, 2),
        _ => q(s * u.int_in_range(1..=64i64)?, 64),
    })
}

/// A point piece (equal control points).
fn dot(u: &mut Unstructured, p: &V2<Rational>) -> Result<Bezier<Rational>> {
    // 2 or 3 points: the readers (user language and certificate) take no
    // 1-point piece, which `ShapeDesc::curve` would accept
    let n = u.int_in_range(2..=3usize)?;
    Ok(Bezier::new(vec![p.clone(); n]))
}

fn reversed(b: &Bezier<Rational>) -> Bezier<Rational> {
    Bezier::new(b.points().iter().rev().cloned().collect())
}

fn end(b: &Bezier<Rational>) -> &V2<Rational> {
    &b.points()[b.degree()]
}

fn is_point(b: &Bezier<Rational>) -> bool {
    b.points().iter().all(|p| *p == b.points()[0])
}

/// Every point piece lies where `same_as`'s walk meets it from either end: at
/// the end of the nearest non-point piece before it and at the start of the
/// nearest one after it (a curve of point pieces alone: one point). Two curves
/// with such point pieces and the same non-point pieces up to splitting,
/// elevation and reversal are accepted by the walk; an isolated point (a dot
/// off the curve's pieces, or at a gap) is matched only by position.
fn walkable(s: &ShapeDesc) -> bool {
    match s {
        ShapeDesc::Curve(c) => {
            let solid: Vec<usize> = (0..c.len()).filter(|&k| !is_point(&c[k])).collect();
            if solid.is_empty() {
                return c.iter().all(|b| b.points()[0] == c[0].points()[0]);
            }
            (0..c.len()).filter(|&k| is_point(&c[k])).all(|k| {
                let p = &c[k].points()[0];
                let before = solid.iter().rev().find(|&&j| j < k);
                let after = solid.iter().find(|&&j| j > k);
                before.map_or(true, |&j| end(&c[j]) == p)
                    && after.map_or(true, |&j| &c[j].points()[0] == p)
            })
        }
        ShapeDesc::Union(m) => m.iter().all(walkable),
        _ => true,
    }
}

/// How a rewrite relates the new shape to the old one.
#[derive(Clone, Copy, PartialEq, Debug)]
enum Kind {
    /// Same point set, and a form `same_as` is documented to accept.
    Form,
    /// Same point set only (e.g. a point of the curve appended at its end).
    Set,
    /// The point set may differ.
    Changed,
}

fn worst(a: Kind, b: Kind) -> Kind {
    use Kind::*;
    match (a, b) {
        (Changed, _) | (_, Changed) => Changed,
        (Set, _) | (_, Set) => Set,
        _ => Form,
    }
}

/// The curve of a curve, offset or convolution.
fn curve_of(s: &ShapeDesc) -> Option<&Vec<Bezier<Rational>>> {
    match s {
        ShapeDesc::Curve(c) => Some(c),
        ShapeDesc::Offset { curve, .. } | ShapeDesc::Convolution { curve, .. } => Some(curve),
        _ => None,
    }
}

/// `s` with its curve replaced (the constructor's checks applied).
fn with_curve(s: &ShapeDesc, c: Vec<Bezier<Rational>>) -> Option<ShapeDesc> {
    match s {
        ShapeDesc::Curve(_) => ShapeDesc::curve(c).ok(),
        ShapeDesc::Offset { distance, .. } => ShapeDesc::offset(c, distance.clone()).ok(),
        ShapeDesc::Convolution { ellipse, side, .. } => {
            ShapeDesc::convolution(c, ellipse.clone(), *side).ok()
        }
        _ => None,
    }
}

/// Orthogonal matrices with rational entries (`M = r R` keeps `Q = r² I`).
fn orthogonal(i: u8) -> [[Rational; 2]; 2] {
    let one = q(1, 1);
    let m1 = q(-1, 1);
    match i % 4 {
        0 => [[one.clone(), zero()], [zero(), one]],
        1 => [[zero(), one], [m1, zero()]],
        2 => [[q(3, 5), q(4, 5)], [q(-4, 5), q(3, 5)]],
        _ => [[m1, zero()], [zero(), one]],
    }
}

/// One rewrite of a shape that is not a union; `None`: skipped.
fn rewrite_member(u: &mut Unstructured, s: &ShapeDesc) -> Result<Option<(ShapeDesc, Kind)>> {
    let op = u.int_in_range(0..=9u8)?;
    if let ShapeDesc::Arc(a) = s {
        // arcs: directions scaled (same), or centre / radius / direction moved
        let mut a = a.clone();
        let kind = match op % 4 {
            0 => {
                let k = q(u.int_in_range(1..=9i64)?, u.int_in_range(1..=9i64)?);
                a.from = a.from.scale(&k);
                let k = q(u.int_in_range(1..=9i64)?, u.int_in_range(1..=9i64)?);
                a.to = a.to.scale(&k);
                Kind::Form
            }
            1 => {
                a.radius = &a.radius + &delta(u)?;
                Kind::Changed
            }
            2 => {
                let d = delta(u)?;
                if u.arbitrary::<bool>()? {
                    a.center.x = &a.center.x + &d;
                } else {
                    a.center.y = &a.center.y + &d;
                }
                Kind::Changed
            }
            _ => {
                // a direction turned a little (its perpendicular added)
                let d = delta(u)?;
                if u.arbitrary::<bool>()? {
                    a.from = a.from.add(&a.from.rot90().scale(&d));
                } else {
                    a.to = a.to.add(&a.to.rot90().scale(&d));
                }
                Kind::Changed
            }
        };
        return Ok(ShapeDesc::arc(a).ok().map(|s| (s, kind)));
    }
    let Some(c) = curve_of(s) else {
        return Ok(None);
    };
    let mut c = c.clone();
    let i = u.choose_index(c.len())?;
    let plain = matches!(s, ShapeDesc::Curve(_));
    let kind = match op {
        0 => {
            let t = param(u)?;
            let (l, r) = c[i].split(&t);
            c.splice(i..=i, [l, r]);
            Kind::Form
        }
        1 => {
            let target = if u.int_in_range(0..=7u8)? == 7 {
                u.int_in_range(20..=24usize)?
            } else {
                c[i].degree() + u.int_in_range(1..=3usize)?
            };
            if c[i].degree() >= 24 {
                return Ok(None);
            }
            while c[i].degree() < target {
                c[i] = c[i].elevate();
            }
            Kind::Form
        }
        2 => {
            if !plain {
                return Ok(None);
            }
            c = c.iter().rev().map(reversed).collect();
            Kind::Form
        }
        3 => {
            if !plain {
                return Ok(None);
            }
            // a one-point piece where the walk meets it: after a piece ending
            // where the next starts (or the last), or before the first. Next
            // to an isolated point (a point piece) it is only the same set:
            // the walk matches a point piece at the other side's cursor, and
            // a second copy of an isolated point meets the next piece there
            match u.int_in_range(0..=1u8)? {
                0 => {
                    let p = end(&c[i]).clone();
                    let walk = !is_point(&c[i])
                        && c.get(i + 1)
                            .map_or(true, |n| n.points()[0] == p && !is_point(n));
                    c.insert(i + 1, dot(u, &p)?);
                    if walk {
                        Kind::Form
                    } else {
                        Kind::Set
                    }
                }
                _ => {
                    let p = c[0].points()[0].clone();
                    let walk = !is_point(&c[0]);
                    c.insert(0, dot(u, &p)?);
                    if walk {
                        Kind::Form
                    } else {
                        Kind::Set
                    }
                }
            }
        }
        4 => {
            // a one-point piece elsewhere, appended or inserted
            let (p, kind) = match u.int_in_range(0..=3u8)? {
                0 => (V2::new(q(5, 1), zero()), Kind::Changed),
                1 => {
                    let j = u.choose_index(c[i].points().len())?;
                    let on = j == 0 || j == c[i].degree() || is_point(&c[i]);
                    (
                        c[i].points()[j].clone(),
                        if on { Kind::Set } else { Kind::Changed },
                    )
                }
                2 => (c[0].points()[0].clone(), Kind::Set),
                _ => (c[i].eval(&param(u)?), Kind::Set),
            };
            if !plain {
                return Ok(None);
            }
            let at = if u.arbitrary::<bool>()? {
                c.len()
            } else {
                u.int_in_range(0..=c.len())?
            };
            c.insert(at, dot(u, &p)?);
            kind
        }
        5 => {
            let j = u.choose_index(c[i].points().len())?;
            let mut pts = c[i].points().to_vec();
            let d = delta(u)?;
            if u.arbitrary::<bool>()? {
                pts[j].x = &pts[j].x + &d;
            } else {
                pts[j].y = &pts[j].y + &d;
            }
            c[i] = Bezier::new(pts);
            Kind::Changed
        }
        6 => {
            if c.len() < 2 {
                return Ok(None);
            }
            c.remove(i);
            Kind::Changed
        }
        7 => {
            // offsets and convolutions: the pen or the side
            return Ok(match s {
                ShapeDesc::Offset { curve, distance } => match u.int_in_range(0..=2u8)? {
                    0 => ShapeDesc::offset(curve.clone(), distance + &delta(u)?)
                        .ok()
                        .map(|s| (s, Kind::Changed)),
                    1 => ShapeDesc::offset(curve.clone(), -distance.clone())
                        .ok()
                        .map(|s| (s, Kind::Changed)),
                    _ => {
                        // the convolution with M = r R on the side of sign r
                        let pos = *distance > zero();
                        let r = if pos {
                            distance.clone()
                        } else {
                            -distance.clone()
                        };
                        let mut m = orthogonal(u.arbitrary()?);
                        for row in m.iter_mut() {
                            for x in row.iter_mut() {
                                *x = &*x * &r;
                            }
                        }
                        let same = !u.arbitrary::<bool>()?;
                        let side = if pos == same { 1 } else { -1 };
                        ShapeDesc::convolution(curve.clone(), m, side)
                            .ok()
                            .map(|s| (s, if same { Kind::Form } else { Kind::Changed }))
                    }
                },
                ShapeDesc::Convolution {
                    curve,
                    ellipse,
                    side,
                } => {
                    if u.arbitrary::<bool>()? {
                        ShapeDesc::convolution(curve.clone(), ellipse.clone(), -side)
                            .ok()
                            .map(|s| (s, Kind::Changed))
                    } else if u.arbitrary::<bool>()? {
                        // M R, R orthogonal: the same ellipse
                        let r = orthogonal(u.arbitrary()?);
                        let m = ellipse;
                        let mr = [0, 1]
                            .map(|i| [0, 1].map(|j| &m[i][0] * &r[0][j] + &m[i][1] * &r[1][j]));
                        ShapeDesc::convolution(curve.clone(), mr, *side)
                            .ok()
                            .map(|s| (s, Kind::Form))
                    } else {
                        let mut m = ellipse.clone();
                        let (a, b) = (u.choose_index(2)?, u.choose_index(2)?);
                        m[a][b] = &m[a][b] + &delta(u)?;
                        ShapeDesc::convolution(curve.clone(), m, *side)
                            .ok()
                            .map(|s| (s, Kind::Changed))
                    }
                }
                _ => None,
            });
        }
        _ => {
            // splits again: the most common rewrite of real certificates
            let t = param(u)?;
            let (l, r) = c[i].split(&t);
            c.splice(i..=i, [l, r]);
            Kind::Form
        }
    };
    Ok(with_curve(s, c).map(|s| (s, kind)))
}

/// One rewrite (of one member of a union).
fn rewrite(u: &mut Unstructured, s: &ShapeDesc) -> Result<Option<(ShapeDesc, Kind)>> {
    if let ShapeDesc::Union(m) = s {
        let i = u.choose_index(m.len())?;
        let Some((x, kind)) = rewrite_member(u, &m[i])? else {
            return Ok(None);
        };
        let mut m = m.clone();
        m[i] = x;
        return Ok(ShapeDesc::union(m).ok().map(|s| (s, kind)));
    }
    rewrite_member(u, s)
}

/// 0–4 rewrites; the result and how it relates to `s`, and the count done.
fn derive(u: &mut Unstructured, s: &ShapeDesc) -> Result<(ShapeDesc, Kind, usize)> {
    let n = u.int_in_range(0..=4u8)?;
    let (mut s, mut kind, mut done) = (s.clone(), Kind::Form, 0);
    for _ in 0..n {
        if let Some((x, k)) = rewrite(u, &s)? {
            s = x;
            kind = worst(kind, k);
            done += 1;
        }
    }
    Ok((s, kind, done))
}

// ---------------------------------------------------------------- the float oracle

/// Samples `0..=n` of every piece (a union: of every member's pieces).
fn samples(s: &ShapeDesc, n: usize, out: &mut Vec<Vec<(f64, f64)>>) {
    let ts = (0..=n).map(move |k| k as f64 / n as f64);
    let f = |r: &Rational| r.approx();
    match s {
        ShapeDesc::Curve(c) => {
            for b in c {
                let b: Bezier<f64> = b.map(f);
                out.push(ts.clone().map(|t| b.eval(&t)).map(|p| (p.x, p.y)).collect());
            }
        }
        ShapeDesc::Arc(_) | ShapeDesc::EllipseArc(_) => {
            // c + M u, u on the unit circle (M = r I for a circle)
            let (c, m, from, to) = match s {
                ShapeDesc::Arc(a) => {
                    let r = f(&a.radius);
                    (&a.center, [[r, 0.0], [0.0, r]], &a.from, &a.to)
                }
                ShapeDesc::EllipseArc(a) => {
                    let m = &a.matrix;
                    let m = [[f(&m[0][0]), f(&m[0][1])], [f(&m[1][0]), f(&m[1][1])]];
                    (&a.center, m, &a.from, &a.to)
                }
                _ => unreachable!(),
            };
            let (cx, cy) = (f(&c.x), f(&c.y));
            let t0 = f(&from.y).atan2(f(&from.x));
            let mut sweep = f(&to.y).atan2(f(&to.x)) - t0;
            if sweep <= 0.0 {
                sweep += std::f64::consts::TAU;
            }
            out.push(
                ts.map(|t| {
                    let (u, v) = ((t0 + sweep * t).cos(), (t0 + sweep * t).sin());
                    (
                        cx + m[0][0] * u + m[0][1] * v,
                        cy + m[1][0] * u + m[1][1] * v,
                    )
                })
                .collect(),
            );
        }
        ShapeDesc::Offset { .. } | ShapeDesc::Convolution { .. } => {
            // an offset at distance d is the convolution with Q = d² I on the
            // side of sign d: x + side · Q n / √(nᵀQn), n = x′⊥
            let (curve, qm, sd) = match s {
                ShapeDesc::Offset { curve, distance } => {
                    let d = f(distance);
                    (curve, [d * d, 0.0, d * d], d.signum())
                }
                ShapeDesc::Convolution {
                    curve,
                    ellipse: m,
                    side,
                } => {
                    let m = [[f(&m[0][0]), f(&m[0][1])], [f(&m[1][0]), f(&m[1][1])]];
                    let qm = [
                        m[0][0] * m[0][0] + m[0][1] * m[0][1],
                        m[0][0] * m[1][0] + m[0][1] * m[1][1],
                        m[1][0] * m[1][0] + m[1][1] * m[1][1],
                    ];
                    (curve, qm, f64::from(*side))
                }
                _ => unreachable!(),
            };
            for b in curve {
                let b: Bezier<f64> = b.map(f);
                let h = b.hodograph();
                out.push(
                    ts.clone()
                        .map(|t| {
                            let (p, v) = (b.eval(&t), h.eval(&t));
                            let (nx, ny) = (-v.y, v.x);
                            let (qx, qy) = (qm[0] * nx + qm[1] * ny, qm[1] * nx + qm[2] * ny);
                            let l = (nx * qx + ny * qy).sqrt();
                            (p.x + sd * qx / l, p.y + sd * qy / l)
                        })
                        .collect(),
                );
            }
        }
        ShapeDesc::Union(ms) => {
            for m in ms {
                samples(m, n, out);
            }
        }
    }
}

/// A float lower estimate of `h(X, Y)`: the farthest of 33 samples per piece
/// of `X` from 257 samples per piece of `Y`, less the largest chord between
/// consecutive samples of `Y` (a point of `Y` is that close to a sample, up to
/// the pieces' bulge, which the margin of the caller absorbs).
fn sampled_lower(x: &ShapeDesc, y: &ShapeDesc) -> f64 {
    let (mut xs, mut ys) = (Vec::new(), Vec::new());
    samples(x, 32, &mut xs);
    samples(y, 256, &mut ys);
    let d = |a: (f64, f64), b: (f64, f64)| ((a.0 - b.0).powi(2) + (a.1 - b.1).powi(2)).sqrt();
    let gap = ys
        .iter()
        .flat_map(|p| p.windows(2).map(|w| d(w[0], w[1])))
        .fold(0.0, f64::max);
    let far = xs
        .iter()
        .flatten()
        .map(|&a| {
            ys.iter()
                .flatten()
                .map(|&b| d(a, b))
                .fold(f64::INFINITY, f64::min)
        })
        .fold(0.0, f64::max);
    far - gap
}

// ---------------------------------------------------------------- statistics

struct Stats {
    runs: AtomicU64,
    certs: AtomicU64,
    accepted: AtomicU64,
    accepted_changed: AtomicU64,
    rejected_shape: AtomicU64,
    rejected_cert: AtomicU64,
    rejected_cert_mutated: AtomicU64,
    false_rejects: AtomicU64,
    oracle_searches: AtomicU64,
    oracle_search_errors: AtomicU64,
    issue_ok: AtomicU64,
    issue_wrong: AtomicU64,
    slowest_us: AtomicU64,
}

static STATS: Stats = Stats {
    runs: AtomicU64::new(0),
    certs: AtomicU64::new(0),
    accepted: AtomicU64::new(0),
    accepted_changed: AtomicU64::new(0),
    rejected_shape: AtomicU64::new(0),
    rejected_cert: AtomicU64::new(0),
    rejected_cert_mutated: AtomicU64::new(0),
    false_rejects: AtomicU64::new(0),
    oracle_searches: AtomicU64::new(0),
    oracle_search_errors: AtomicU64::new(0),
    issue_ok: AtomicU64::new(0),
    issue_wrong: AtomicU64::new(0),
    slowest_us: AtomicU64::new(0),
};

fn env_flag(name: &str) -> Option<u64> {
    std::env::var(name).ok().and_then(|v| v.parse().ok())
}

fn stats_every() -> u64 {
    static N: OnceLock<u64> = OnceLock::new();
    *N.get_or_init(|| env_flag("AGAINST_STATS").unwrap_or(0))
}

fn print_all() -> bool {
    static P: OnceLock<bool> = OnceLock::new();
    *P.get_or_init(|| env_flag("AGAINST_PRINT").unwrap_or(0) != 0)
}

fn timing() -> bool {
    static P: OnceLock<bool> = OnceLock::new();
    *P.get_or_init(|| env_flag("AGAINST_TIMING").unwrap_or(0) != 0)
}

fn strict() -> bool {
    static P: OnceLock<bool> = OnceLock::new();
    *P.get_or_init(|| env_flag("AGAINST_STRICT").unwrap_or(1) != 0)
}

fn print_stats() {
    let g = |a: &AtomicU64| a.load(Relaxed);
    let s = &STATS;
    eprintln!(
        "against stats: runs {} | certificates {} | verify_against Ok {} (user sets possibly changed: {}) | Err: shape {} , certificate {} (of which mutated {}) | false rejects {} | oracle searches {} (errors {}) | issue-24 unmodified right {} wrong {} | slowest verify_against {} us",
        g(&s.runs),
        g(&s.certs),
        g(&s.accepted),
        g(&s.accepted_changed),
        g(&s.rejected_shape),
        g(&s.rejected_cert),
        g(&s.rejected_cert_mutated),
        g(&s.false_rejects),
        g(&s.oracle_searches),
        g(&s.oracle_search_errors),
        g(&s.issue_ok),
        g(&s.issue_wrong),
        g(&s.slowest_us),
    );
}

// ---------------------------------------------------------------- the run

/// A string node of shape `a` or `b` of the certificate replaced by another
/// canonical rational (copied from elsewhere in the shapes, or nudged).
fn mutate(u: &mut Unstructured, text: &str) -> Result<Option<String>> {
    let Ok(mut doc) = serde_json::from_str::<Value>(text) else {
        return Ok(None);
    };
    fn leaves<'v>(v: &'v mut Value, out: &mut Vec<&'v mut Value>) {
        match v {
            Value::String(_) => out.push(v),
            Value::Array(a) => a.iter_mut().for_each(|x| leaves(x, out)),
            Value::Object(m) => m.values_mut().for_each(|x| leaves(x, out)),
            _ => {}
        }
    }
    let key = if u.arbitrary::<bool>()? { "b" } else { "a" };
    let mut ls = Vec::new();
    leaves(&mut doc[key], &mut ls);
    if ls.is_empty() {
        return Ok(None);
    }
    let i = u.choose_index(ls.len())?;
    let j = u.choose_index(ls.len())?;
    let Some(x) = ls[i].as_str().and_then(|s| parse_rational(s).ok()) else {
        return Ok(None);
    };
    let y = match u.int_in_range(0..=4u8)? {
        0 => match ls[j].as_str() {
            Some(s) => s.to_string(),
            None => return Ok(None),
        },
        1 => (&x + &q(1, 1000)).to_string(),
        2 => (&x - &q(1, 1 << 50)).to_string(),
        3 => (-x).to_string(),
        _ => (&x + &delta(u)?).to_string(),
    };
    *ls[i] = Value::String(y);
    Ok(serde_json::to_string(&doc).ok())
}

/// A genuine certificate about `(ac, bc)` and its tol (`None`: the search
/// found none), memoized: the same certificate's shapes recur with other
/// user shapes, and the search dominates the cost.
fn certificate(
    ac: &ShapeDesc,
    bc: &ShapeDesc,
    mode: u8,
    fixed: Option<Rational>,
) -> Option<(Rational, String)> {
    static MEMO: Mutex<BTreeMap<String, Option<(Rational, String)>>> = Mutex::new(BTreeMap::new());
    let key = format!(
        "{}\n{}\n{mode}\n{}",
        ac.to_json(),
        bc.to_json(),
        fixed.as_ref().map(|t| t.to_string()).unwrap_or_default()
    );
    if let Some(x) = MEMO.lock().unwrap().get(&key) {
        return x.clone();
    }
    let x = certificate_uncached(ac, bc, mode, fixed);
    let mut memo = MEMO.lock().unwrap();
    if memo.len() >= 1024 {
        memo.clear();
    }
    memo.insert(key, x.clone());
    x
}

fn certificate_uncached(
    ac: &ShapeDesc,
    bc: &ShapeDesc,
    mode: u8,
    fixed: Option<Rational>,
) -> Option<(Rational, String)> {
    let search = |tol: Option<Tolerance>| Config {
        rel: 1e-2,
        max_boxes: 48,
        tol,
        parametric: false,
        ..Config::default()
    };
    let (tol, r) = match fixed {
        // searched for the fixed tol (its float rounded down: the boxes' bounds
        // must be below the rational)
        Some(tol) => {
            let tol = Tolerance::new(tol).ok()?;
            let r = hausdorff(ac, bc, &search(Some(tol.clone()))).ok()?;
            (tol, r)
        }
        None => {
            let r = hausdorff(ac, bc, &search(None)).ok()?;
            if !r.hi.is_finite() {
                return None;
            }
            let hi = r.hi.max(0.0);
            let tol = match mode {
                // a little above: hi (1 + 2⁻⁶) + 2⁻⁴⁰, on the 2⁻⁴⁰ grid
                0 => {
                    let g = (1u64 << 40) as f64;
                    rational_from_f64(((hi * (1.0 + 1.0 / 64.0) + 1.0 / g) * g).ceil() / g)
                }
                // the next float: as tight as the search's bounds allow (a
                // tolerance is a normal float at least)
                1 => rational_from_f64(hi.next_up().max(f64::MIN_POSITIVE)),
                _ => rational_from_f64(((hi * 1024.0).floor() + 1.0) / 1024.0),
            }?;
            (Tolerance::new(tol).ok()?, r)
        }
    };
    let cert = Certificate::new(ac, bc, &tol, &r)?;
    Some((tol.exact().clone(), cert.to_json_string()))
}

fn run(u: &mut Unstructured, sampled: bool) -> Result<()> {
    let sc = &SCENARIOS()[PICK[u.choose_index(PICK.len())?] as usize];
    let start = Instant::now();
    // the certificate's shapes
    let (ac, kac, nac, bc, kbc, nbc) = if sc.fixed_cert {
        (sc.a.clone(), Kind::Form, 0, sc.b.clone(), Kind::Form, 0)
    } else {
        let (ac, kac, nac) = derive(u, &sc.a)?;
        let (bc, kbc, nbc) = derive(u, &sc.b)?;
        (ac, kac, nac, bc, kbc, nbc)
    };
    // the user's shapes: from the user's base, or from the certificate's shape
    let from_cert = u.int_in_range(0..=3u8)? == 3;
    // each with how it relates to the certificate's shape
    let user = |u: &mut Unstructured,
                base: &Option<(ShapeDesc, bool)>,
                cert_base: &ShapeDesc,
                cert: &ShapeDesc,
                kcert: Kind|
     -> Result<(ShapeDesc, Kind, usize)> {
        let (b0, k0) = match base {
            None if from_cert => (cert.clone(), Kind::Form),
            None => (cert_base.clone(), kcert),
            Some((s, true)) => (s.clone(), kcert),
            Some((s, false)) => (s.clone(), Kind::Changed),
        };
        let (s, k, n) = derive(u, &b0)?;
        Ok((s, worst(k0, k), n))
    };
    let (au, ka, nau) = user(u, &sc.user_a, &sc.a, &ac, kac)?;
    let (bu, kb, nbu) = user(u, &sc.user_b, &sc.b, &bc, kbc)?;

    // a genuine certificate about (Ac, Bc)
    let mode = if sc.tol.is_some() {
        3
    } else {
        u.int_in_range(0..=3u8)?
    };
    let fixed = match (&sc.tol, mode) {
        (Some(t), _) => Some(t.clone()),
        (None, 3) => Some(
            [q(1, 4), q(1, 10), q(1, 100), q(1, 1000), q(1, 1), q(1, 3)][u.choose_index(6)?]
                .clone(),
        ),
        _ => None,
    };
    let Some((tol, text)) = certificate(&ac, &bc, mode, fixed) else {
        return Ok(());
    };
    STATS.certs.fetch_add(1, Relaxed);
    let mut text = text;
    let mut mutated = false;
    if u.int_in_range(0..=7u8)? == 7 {
        if let Some(t) = mutate(u, &text)? {
            text = t;
            mutated = true;
        }
    }

    let t_cert = start.elapsed();
    let t0 = Instant::now();
    let verdict = verify_against(&text, &au, &bu);
    let us = t0.elapsed().as_micros() as u64;
    STATS.slowest_us.fetch_max(us, Relaxed);
    let describe = || {
        format!(
            "scenario {:?}; tol {tol}; certificate A = {} ({ka:?}), B = {} ({kb:?}); user A = {}, user B = {}; rewrites {nac}/{nbc}/{nau}/{nbu}, mutated {mutated}",
            sc.name,
            ac.to_json(),
            bc.to_json(),
            au.to_json(),
            bu.to_json()
        )
    };
    if print_all() {
        eprintln!("{}\n=> {:?}", describe(), verdict.as_ref().map(|v| &v.tol));
    }
    // the issue's verdicts, on the unmodified cases
    let unmodified = nac + nbc + nau + nbu == 0 && !mutated && !from_cert;
    if unmodified && sc.expect != Expect::Any {
        let right = match sc.expect {
            Expect::Accept => verdict.is_ok(),
            _ => verdict.is_err(),
        };
        if right {
            STATS.issue_ok.fetch_add(1, Relaxed);
        } else {
            STATS.issue_wrong.fetch_add(1, Relaxed);
            eprintln!(
                "against: {} expected {:?}, got {:?}",
                sc.name, sc.expect, verdict
            );
            assert!(!strict(), "issue-24 expectation failed: {}", describe());
        }
    }
    match &verdict {
        Ok(v) => {
            STATS.accepted.fetch_add(1, Relaxed);
            assert_eq!(
                v.tol,
                tol,
                "verify_against proved another tol ({})",
                describe()
            );
            let t1 = Instant::now();
            check_accepted(&au, &bu, &tol, ka, kb, sampled, &describe);
            if timing() {
                let t_oracle = t1.elapsed();
                let t2 = Instant::now();
                let _ = lncert::certify::verify::verify(&text);
                let t_verify = t2.elapsed();
                let t3 = Instant::now();
                let _ = (ac.same_as(&au), bc.same_as(&bu));
                eprintln!(
                    "timing {:?}: certificate {:?}, verify_against {us} us, oracles {:?}; of verify_against: verify {:?}, same_as {:?}; text {} bytes",
                    sc.name,
                    t_cert,
                    t_oracle,
                    t_verify,
                    t3.elapsed(),
                    text.len()
                );
            }
        }
        Err(e) if e.at == "a" || e.at == "b" => {
            STATS.rejected_shape.fetch_add(1, Relaxed);
            let (k, theirs, mine) = if e.at == "a" {
                (ka, &ac, &au)
            } else {
                (kb, &bc, &bu)
            };
            if k == Kind::Form
                && !mutated
                && walkable(theirs)
                && walkable(mine)
                && STATS.false_rejects.fetch_add(1, Relaxed) < 5
            {
                eprintln!("against: false reject? {e:?}\n  {}", describe());
            }
        }
        Err(e) => {
            STATS.rejected_cert.fetch_add(1, Relaxed);
            if mutated {
                STATS.rejected_cert_mutated.fetch_add(1, Relaxed);
            } else if STATS.rejected_cert.load(Relaxed) - STATS.rejected_cert_mutated.load(Relaxed)
                <= 5
            {
                eprintln!(
                    "against: a fresh certificate is invalid: {e:?}\n  {}",
                    describe()
                );
            }
        }
    }
    Ok(())
}

/// The oracles of an accept: `d_H(Au, Bu) ≤ tol` is not refuted.
fn check_accepted(
    au: &ShapeDesc,
    bu: &ShapeDesc,
    tol: &Rational,
    ka: Kind,
    kb: Kind,
    sampled: bool,
    describe: &dyn Fn() -> String,
) {
    let changed = ka == Kind::Changed || kb == Kind::Changed;
    if changed {
        STATS.accepted_changed.fetch_add(1, Relaxed);
    }
    // (a) float samples, both directions
    let scale = au.scale().max(bu.scale()).max(1.0);
    let est = sampled_lower(au, bu).max(sampled_lower(bu, au));
    let tf = tol.approx();
    assert!(
        !(est > tf + 1e-6 * scale + 1e-9),
        "FALSE ACCEPT (float samples): verify_against accepted d_H <= {tol}, but samples of the user's shapes are {est} apart; {}",
        describe()
    );
    // (b) the certified search on the user's shapes, where their point sets
    // may differ from the certificate's, and on the other accepts of inputs
    // whose bytes hash to 0 modulo 8 (so a replayed input re-runs it)
    if !(changed || sampled) {
        return;
    }
    STATS.oracle_searches.fetch_add(1, Relaxed);
    let cfg = Config {
        rel: 1e-2,
        max_boxes: 64,
        // the search's goal: the float just above the claim (a refutation
        // needs lo > tol)
        tol: Tolerance::from_f64(interval_from_rational(tol).sup()).ok(),
        verdict_only: true,
        ..Config::default()
    };
    let Ok(r) = hausdorff(au, bu, &cfg) else {
        STATS.oracle_search_errors.fetch_add(1, Relaxed);
        return;
    };
    let lo = rational_from_f64(r.lo).expect("a finite lower bound");
    assert!(
        &lo <= tol,
        "FALSE ACCEPT (certified): verify_against accepted d_H <= {tol}, but the certified lower bound on the user's shapes is {} ({lo}); {}",
        r.lo,
        describe()
    );
}

fuzz_target!(|data: &[u8]| -> Corpus {
    let t = Instant::now();
    let sampled = lncert_cli::audit::fuzz::sample_hash(data) % 8 == 0;
    let res = run(&mut Unstructured::new(data), sampled);
    if timing() {
        let i = PICK[data.first().map_or(0, |b| *b as usize % PICK.len())] as usize;
        eprintln!(
            "total {:?} {} us",
            SCENARIOS()[i].name,
            t.elapsed().as_micros()
        );
    }
    let n = STATS.runs.fetch_add(1, Relaxed) + 1;
    let every = stats_every();
    if every > 0 && n % every == 0 {
        print_stats();
    }
    match res {
        Ok(()) => Corpus::Keep,
        Err(_) => Corpus::Reject,
    }
});
