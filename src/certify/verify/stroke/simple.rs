//! Claim (c) of a stroke certificate, checked by the verifier's own search:
//! the outline's contours are **simple and pairwise disjoint** (consecutive
//! pieces meet only at their shared end point) and each has a decided
//! **orientation** (the sign of its enclosed area).
//!
//! The parts of the cover (claim (a)) are the segments: each is proven
//! injective (a Bézier part whose hodograph's control points all have a
//! positive component along one direction; a sub-arc of less than `π/2`).
//! Two segments that are not consecutive must have disjoint hulls (a
//! separating axis, with interval ends), after bisecting them if needed; two
//! consecutive ones, sharing the point `J`, must lie on the two sides of a
//! line through `J`: every hull point but `J` strictly behind it for the
//! first, strictly ahead for the second — then they meet only at `J`.
//! Candidates are the pairs whose boxes meet, found with a box index (work
//! proportional to the pairs, memory to the segments: nothing is collected);
//! a certificate with more than [`MAX_PAIRS_PER_PART`] candidate pairs per
//! part (plus [`BASE_PAIRS`]) is refused before any is checked — a simple
//! outline's parts meet only their neighbours and the parts across a thin
//! place — and every bisection step is charged to the check's budget.
//!
//! The area `½∮(x dy − y dx)` is enclosed piece by piece: a Bézier's by its
//! Bernstein coefficients (degree `2n − 1`, each integrating to `1/2n`), an
//! arc's as `½(ρ² θ + c × (v − u))` with `θ` the sum of its parts' angles
//! (each `atan(cross/dot)` of directions less than `π/2` apart), which must be
//! proven below `2π` so that the parts do not wind around more than the arc.

use super::super::index::{meet, BoxIndex};
use super::super::Budget;
use super::geom::{arc_hull, bprod, ic, ip, iq, Bez, P};
use super::{cross, dotq, OPiece, Q2};
use crate::scalar::{atan_enclosure, Interval, Rational};
use rayon::prelude::*;
use std::borrow::Cow;

/// The range of one part: a Bézier's parameters or an arc's radius
/// directions (boxed: most parts are Béziers', and every part of a
/// certificate is held at once).
#[derive(Clone, Debug)]
pub(crate) enum Span {
    Bez(Rational, Rational),
    Arc(Box<Q2>, Box<Q2>),
}

impl Span {
    /// An arc's part from the direction `d0` to `d1`.
    pub(crate) fn arc(d0: Q2, d1: Q2) -> Span {
        Span::Arc(Box::new(d0), Box::new(d1))
    }
}

/// A part's span, borrowed from the certificate's parts or owned by a
/// bisection (boxed: a pointer either way).
enum SpanRef<'a> {
    Ref(&'a Span),
    Own(Box<Span>),
}

impl std::ops::Deref for SpanRef<'_> {
    type Target = Span;
    fn deref(&self) -> &Span {
        match self {
            SpanRef::Ref(s) => s,
            SpanRef::Own(s) => s,
        }
    }
}

struct Seg<'a> {
    piece: &'a OPiece,
    span: SpanRef<'a>,
    hull: Cow<'a, [P]>,
    lo: [f64; 2],
    hi: [f64; 2],
}

fn hull_of(piece: &OPiece, span: &Span) -> Option<Vec<P>> {
    match (piece, span) {
        (OPiece::Bezier { iv, .. }, Span::Bez(a, b)) => Some(iv.restrict(iq(a), iq(b))),
        (OPiece::Arc { t, .. }, Span::Arc(d0, d1)) => arc_hull(t.c, t.rho, ip(d0), ip(d1)),
        _ => None,
    }
}

fn seg<'a>(piece: &'a OPiece, span: SpanRef<'a>, hull: Option<&'a [P]>) -> Option<Seg<'a>> {
    let hull = match hull {
        Some(h) => Cow::Borrowed(h),
        None => Cow::Owned(hull_of(piece, &span)?),
    };
    let mut lo = [f64::INFINITY; 2];
    let mut hi = [f64::NEG_INFINITY; 2];
    for p in hull.iter() {
        for i in 0..2 {
            if p[i].is_empty() || !p[i].inf().is_finite() || !p[i].sup().is_finite() {
                return None;
            }
            lo[i] = lo[i].min(p[i].inf());
            hi[i] = hi[i].max(p[i].sup());
        }
    }
    Some(Seg {
        piece,
        span,
        hull,
        lo,
        hi,
    })
}

fn halves<'a>(s: &Seg<'a>) -> Option<(Seg<'a>, Seg<'a>)> {
    let (a, b) = match &*s.span {
        Span::Bez(s0, s1) => {
            let m = (s0 + s1) / Rational::from_integer(2.into());
            (Span::Bez(s0.clone(), m.clone()), Span::Bez(m, s1.clone()))
        }
        Span::Arc(d0, d1) => {
            // a positive combination: strictly between (less than π/2 apart)
            let m = [&d0[0] + &d1[0], &d0[1] + &d1[1]];
            (
                Span::Arc(d0.clone(), Box::new(m.clone())),
                Span::Arc(Box::new(m), d1.clone()),
            )
        }
    };
    Some((
        seg(s.piece, SpanRef::Own(Box::new(a)), None)?,
        seg(s.piece, SpanRef::Own(Box::new(b)), None)?,
    ))
}

fn mid(x: Interval) -> f64 {
    0.5 * (x.inf() + x.sup())
}

fn dot(t: [f64; 2], p: P) -> Interval {
    ic(t[0]) * p[0] + ic(t[1]) * p[1]
}

/// The part is injective: a Bézier part's hodograph has a positive component
/// along its chord (all restricted hodograph control points); a sub-arc of
/// less than `π/2` is.
fn injective(s: &Seg) -> bool {
    match *s.span {
        Span::Arc(..) => true,
        Span::Bez(..) => {
            let h = &s.hull;
            let n = h.len() - 1;
            let t = [mid(h[n][0] - h[0][0]), mid(h[n][1] - h[0][1])];
            h.windows(2)
                .all(|w| dot(t, [w[1][0] - w[0][0], w[1][1] - w[0][1]]).inf() > 0.0)
        }
    }
}

/// A separating axis between the two hulls (candidates: the axes and the
/// normals of both control polygons' edges).
fn disjoint(a: &[P], b: &[P]) -> bool {
    let mut axes = vec![[1.0, 0.0], [0.0, 1.0]];
    for h in [a, b] {
        for i in 0..h.len() {
            let (p, q) = (h[i], h[(i + 1) % h.len()]);
            let e = [mid(q[0] - p[0]), mid(q[1] - p[1])];
            if e[0] != 0.0 || e[1] != 0.0 {
                axes.push([-e[1], e[0]]);
            }
        }
    }
    axes.iter().any(|t| {
        let range = |h: &[P]| {
            h.iter()
                .fold((f64::INFINITY, f64::NEG_INFINITY), |(lo, hi), p| {
                    let d = dot(*t, *p);
                    (lo.min(d.inf()), hi.max(d.sup()))
                })
        };
        let (ra, rb) = (range(a), range(b));
        ra.1 < rb.0 || rb.1 < ra.0
    })
}

/// `p` ends where `q` starts (`J`): a line through `J` with every hull point
/// of `p` but `J` strictly behind it and every one of `q` but `J` ahead.
fn separated_at(p: &[P], q: &[P]) -> bool {
    let (n, m) = (p.len() - 1, q.len() - 1);
    let j = [p[n][0].convex_hull(q[0][0]), p[n][1].convex_hull(q[0][1])];
    let unit = |v: [f64; 2]| {
        let l = (v[0] * v[0] + v[1] * v[1]).sqrt();
        (l > 0.0).then(|| [v[0] / l, v[1] / l])
    };
    let (Some(a), Some(b)) = (
        unit([mid(j[0] - p[0][0]), mid(j[1] - p[0][1])]),
        unit([mid(q[m][0] - j[0]), mid(q[m][1] - j[1])]),
    ) else {
        return false;
    };
    let t = [a[0] + b[0], a[1] + b[1]];
    let rel = |x: P| [x[0] - j[0], x[1] - j[1]];
    p[..n].iter().all(|x| dot(t, rel(*x)).sup() < 0.0)
        && q[1..].iter().all(|x| dot(t, rel(*x)).inf() > 0.0)
}

const DEPTH: u32 = 12;

/// Most candidate pairs (parts whose boxes meet) per part of the outline.
pub const MAX_PAIRS_PER_PART: u64 = 64;
/// Candidate pairs allowed to every outline, whatever its size.
pub const BASE_PAIRS: u64 = 4096;

/// The work of one separation test of two hulls, in the budget's units.
fn work(a: &Seg, b: &Seg) -> u64 {
    let n = (a.hull.len() + b.hull.len()) as u64;
    n * n
}

fn apart(a: &Seg, b: &Seg, depth: u32, budget: &Budget) -> bool {
    if a.hi[0] < b.lo[0] || b.hi[0] < a.lo[0] || a.hi[1] < b.lo[1] || b.hi[1] < a.lo[1] {
        return true;
    }
    if budget.charge(work(a, b)).is_err() {
        return false;
    }
    if disjoint(&a.hull, &b.hull) {
        return true;
    }
    if depth >= DEPTH {
        return false;
    }
    let size = |s: &Seg| (s.hi[0] - s.lo[0]).max(s.hi[1] - s.lo[1]);
    let (big, small) = if size(a) >= size(b) { (a, b) } else { (b, a) };
    match halves(big) {
        Some((x, y)) => apart(&x, small, depth + 1, budget) && apart(&y, small, depth + 1, budget),
        None => false,
    }
}

/// `a` ends where `b` starts: they meet only there.
fn touch_once(a: &Seg, b: &Seg, depth: u32, budget: &Budget) -> bool {
    if budget.charge(work(a, b)).is_err() {
        return false;
    }
    if separated_at(&a.hull, &b.hull) {
        return true;
    }
    if depth >= DEPTH {
        return false;
    }
    // the far halves are apart from the other part, the near halves recurse
    match (halves(a), halves(b)) {
        (Some((a0, a1)), Some((b0, b1))) => {
            apart(&a0, b, depth + 1, budget)
                && apart(&a1, &b1, depth + 1, budget)
                && touch_once(&a1, &b0, depth + 1, budget)
        }
        _ => false,
    }
}

/// One outline piece's parts for claim (c): their spans, in order, and
/// their hulls when the caller has them already (as `hull_of` computes them
/// from the same spans — claim (a) does).
#[derive(Clone, Copy)]
pub(crate) struct PieceParts<'a> {
    pub(crate) spans: &'a [Span],
    pub(crate) hulls: Option<&'a [Vec<P>]>,
}

/// Claim (c) on the outline whose parts are `spans` (per contour, per piece,
/// in order): `Ok(orientations)` (`true` counter-clockwise), or why not.
pub(crate) fn simple(
    outline: &[Vec<OPiece>],
    spans: &[Vec<Vec<Span>>],
) -> Result<Vec<bool>, String> {
    let parts: Vec<Vec<PieceParts>> = spans
        .iter()
        .map(|c| {
            c.iter()
                .map(|s| PieceParts {
                    spans: s,
                    hulls: None,
                })
                .collect()
        })
        .collect();
    simple_with(outline, &parts, &Budget::unlimited())
}

/// [`simple`] on the parts as [`PieceParts`] (`parts[c][i]`: piece `i` of
/// contour `c`), the work charged to `budget`. Nothing is copied: the
/// segments borrow the spans and hulls.
pub(crate) fn simple_with(
    outline: &[Vec<OPiece>],
    parts: &[Vec<PieceParts>],
    budget: &Budget,
) -> Result<Vec<bool>, String> {
    // the segments in travel order per contour:
    // (contour, index in contour, piece, span, its hull if given)
    type Flat<'a> = (usize, usize, &'a OPiece, &'a Span, Option<&'a [P]>);
    let mut flat: Vec<Flat> = Vec::new();
    let mut count = Vec::new();
    for (c, (pieces, pp)) in outline.iter().zip(parts).enumerate() {
        let mut k = 0;
        for (piece, p) in pieces.iter().zip(pp) {
            for (l, s) in p.spans.iter().enumerate() {
                let h = p.hulls.and_then(|h| h.get(l)).map(|h| h.as_slice());
                flat.push((c, k, piece, s, h));
                k += 1;
            }
        }
        if k < 3 {
            return Err(format!("contour {c} has fewer than 3 parts"));
        }
        count.push(k);
    }
    let segs: Vec<(usize, usize, Seg)> = flat
        .into_par_iter()
        .map(|(c, k, piece, s, h)| {
            let sg = seg(piece, SpanRef::Ref(s), h).ok_or("a part's hull is not finite")?;
            if !injective(&sg) {
                return Err(format!("part {k} of contour {c} is not proven injective"));
            }
            Ok((c, k, sg))
        })
        .collect::<Vec<_>>()
        .into_iter()
        .collect::<Result<_, String>>()?;
    let adjacent = |(c1, k1): (usize, usize), (c2, k2): (usize, usize)| {
        c1 == c2 && ((k1 + 1) % count[c1] == k2 || (k2 + 1) % count[c1] == k1)
    };
    let count_of = |c: usize| count[c];
    // the candidate pairs: parts `j > i` whose boxes meet part `i`'s, found
    // through the index (never collected). First counted, and refused when
    // there are too many; then each decided, in parallel over `i`, the
    // first failing pair in the order of `(i, j)` reported.
    let index = BoxIndex::new(segs.iter().map(|s| (s.2.lo, s.2.hi)).collect());
    let later = |i: usize, f: &mut dyn FnMut(usize)| -> Result<(), String> {
        let si = &segs[i].2;
        let visited = index.query(
            |lo, hi| meet(&(si.lo, si.hi), lo, hi),
            |j| {
                if j > i {
                    f(j);
                }
                Ok::<(), std::convert::Infallible>(())
            },
        );
        let Ok(visited) = visited;
        budget.charge(visited).map_err(|e| e.to_string())
    };
    let n = segs.len() as u64;
    let limit = MAX_PAIRS_PER_PART
        .saturating_mul(n)
        .saturating_add(BASE_PAIRS);
    let count = (0..segs.len())
        .into_par_iter()
        .map(|i| {
            let mut k = 0u64;
            later(i, &mut |_| k += 1).map(|()| k)
        })
        .try_reduce(|| 0, |a, b| Ok(a + b))?;
    log::debug!("stroke certificate (c): {count} candidate pairs of {n} parts (limit {limit})");
    if count > limit {
        return Err(format!(
            "the outline's {n} parts have {count} pairs whose boxes meet, more than the {limit} a simple outline may have ({MAX_PAIRS_PER_PART} per part + {BASE_PAIRS}): too costly to check"
        ));
    }
    let failed = (0..segs.len()).into_par_iter().find_map_first(|i| {
        let mut js = Vec::new();
        if let Err(e) = later(i, &mut |j| js.push(j)) {
            return Some(Err(e));
        }
        js.sort_unstable();
        let (ci, ki, si) = &segs[i];
        for j in js {
            let (cj, kj, sj) = &segs[j];
            let ok = if adjacent((*ci, *ki), (*cj, *kj)) {
                if (ki + 1) % count_of(*ci) == *kj {
                    touch_once(si, sj, 0, budget)
                } else {
                    touch_once(sj, si, 0, budget)
                }
            } else {
                apart(si, sj, 0, budget)
            };
            if !ok {
                return Some(Ok((i, j)));
            }
        }
        None
    });
    if budget.spent() {
        return Err(budget.exhausted().to_string());
    }
    match failed {
        Some(Err(e)) => return Err(e),
        Some(Ok((i, j))) => {
            let ((ci, ki, _), (cj, kj, _)) = (&segs[i], &segs[j]);
            return Err(format!(
                "parts {ki} of contour {ci} and {kj} of contour {cj} are not proven apart (except at a shared end)"
            ));
        }
        None => {}
    }
    // orientation: the sign of the enclosed area
    outline
        .iter()
        .zip(parts)
        .enumerate()
        .map(|(c, (pieces, pp))| {
            let mut area = ic(0.0);
            for (piece, p) in pieces.iter().zip(pp) {
                area += area_term(piece, p.spans)
                    .ok_or_else(|| format!("contour {c}: an area term is not finite"))?;
            }
            if area.inf() > 0.0 {
                Ok(true)
            } else if area.sup() < 0.0 {
                Ok(false)
            } else {
                Err(format!("contour {c}: the sign of its area is not decided"))
            }
        })
        .collect()
}

/// `½∫(x dy − y dx)` along one piece, enclosed.
fn area_term(piece: &OPiece, parts: &[Span]) -> Option<Interval> {
    let v = match piece {
        OPiece::Bezier { iv, .. } => bezier_area(iv),
        OPiece::Arc {
            ccw_u,
            ccw_v,
            t,
            clockwise,
            ..
        } => {
            let mut theta = ic(0.0);
            for s in parts {
                let Span::Arc(d0, d1) = s else { return None };
                // the turn's tangent, enclosed from the directions' own
                // enclosures; exactly only when that quotient is not finite
                let (a, b) = (ip(d0), ip(d1));
                let q = (a[0] * b[1] - a[1] * b[0]) / (a[0] * b[0] + a[1] * b[1]);
                let q = if q.is_common_interval() {
                    q
                } else {
                    iq(&cross(d0, d1)) / iq(&dotq(d0, d1))
                };
                theta += atan_enclosure(q);
            }
            if theta.sup() >= 2.0 * std::f64::consts::PI {
                return None;
            }
            let (u, v) = (ip(ccw_u), ip(ccw_v));
            let cross = t.c[0] * (v[1] - u[1]) - t.c[1] * (v[0] - u[0]);
            let ccw = (t.rho.sqr() * theta + cross) * ic(0.5);
            // a clockwise arc travels the counter-clockwise one backwards
            if *clockwise {
                -ccw
            } else {
                ccw
            }
        }
    };
    (!v.is_empty() && v.inf().is_finite() && v.sup().is_finite()).then_some(v)
}

fn bezier_area(b: &Bez) -> Interval {
    let n = b.pts.len() - 1;
    let xs: Vec<Interval> = b.pts.iter().map(|p| p[0]).collect();
    let ys: Vec<Interval> = b.pts.iter().map(|p| p[1]).collect();
    let k = ic(n as f64);
    let hx: Vec<Interval> = b.pts.windows(2).map(|w| (w[1][0] - w[0][0]) * k).collect();
    let hy: Vec<Interval> = b.pts.windows(2).map(|w| (w[1][1] - w[0][1]) * k).collect();
    let a = bprod(&xs, &hy);
    let c = bprod(&ys, &hx);
    let mut s = ic(0.0);
    for (u, v) in a.iter().zip(&c) {
        s += *u - *v;
    }
    s / ic((2 * n) as f64) * ic(0.5)
}

#[cfg(test)]
mod tests {
    use super::*;

    fn q(s: &str) -> Rational {
        crate::parse_rational(s).unwrap()
    }
    /// A closed polygon (pieces: its edges), each edge in two parts.
    fn polygon(pts: &[(&str, &str)]) -> (Vec<OPiece>, Vec<Vec<Span>>) {
        let n = pts.len();
        let p = |i: usize| [q(pts[i % n].0), q(pts[i % n].1)];
        let pieces = (0..n)
            .map(|i| OPiece::bezier(vec![p(i), p(i + 1)]))
            .collect();
        let half = || vec![Span::Bez(q("0"), q("1/2")), Span::Bez(q("1/2"), q("1"))];
        (pieces, (0..n).map(|_| half()).collect())
    }

    #[test]
    fn squares_are_simple_with_their_orientation_and_a_bowtie_is_not() {
        let sq = [("0", "0"), ("1", "0"), ("1", "1"), ("0", "1")];
        let (p, s) = polygon(&sq);
        assert_eq!(simple(&[p], &[s]), Ok(vec![true]));
        let rev: Vec<_> = sq.iter().rev().cloned().collect();
        let (p, s) = polygon(&rev);
        assert_eq!(simple(&[p], &[s]), Ok(vec![false]));
        // a bow tie: its edges 1 and 3 cross at (1/2, 1/2)
        let (p, s) = polygon(&[("0", "0"), ("1", "1"), ("1", "0"), ("0", "1")]);
        assert!(simple(&[p], &[s]).unwrap_err().contains("not proven apart"));
        // two squares, one inside the other: disjoint; overlapping: not
        let (a, sa) = polygon(&sq);
        let (b, sb) = polygon(&[
            ("1/4", "1/4"),
            ("1/2", "1/4"),
            ("1/2", "1/2"),
            ("1/4", "1/2"),
        ]);
        assert_eq!(simple(&[a, b], &[sa, sb]), Ok(vec![true, true]));
        let (a, sa) = polygon(&sq);
        let (b, sb) = polygon(&[("1/2", "1/2"), ("2", "1/2"), ("2", "2"), ("1/2", "2")]);
        assert!(simple(&[a, b], &[sa, sb]).is_err());
    }

    #[test]
    fn a_spike_back_along_itself_is_not_simple() {
        // (0,0) → (2,0) → (1,0) → (1,1): the third edge runs back over the first
        let (p, s) = polygon(&[("0", "0"), ("2", "0"), ("1", "0"), ("1", "1")]);
        assert!(simple(&[p], &[s]).is_err());
    }

    #[test]
    fn arcs_wound_twice_have_no_orientation() {
        // a full circle of radius 1 as one arc from (1, 0) to (1, 0)... written
        // as two half circles, with parts of a quarter each: oriented; the same
        // parts claimed twice over one half circle: wound past 2π, refused
        let c = [q("0"), q("0")];
        let a = OPiece::arc(
            c.clone(),
            q("1"),
            [q("1"), q("0")],
            [q("-1"), q("0")],
            false,
        )
        .unwrap();
        let b = OPiece::arc(c, q("1"), [q("-1"), q("0")], [q("1"), q("0")], false).unwrap();
        let d = |x: &str, y: &str| [q(x), q(y)];
        let upper = vec![
            Span::arc(d("1", "0"), d("1", "1")),
            Span::arc(d("1", "1"), d("0", "1")),
            Span::arc(d("0", "1"), d("-1", "1")),
            Span::arc(d("-1", "1"), d("-1", "0")),
        ];
        let lower = vec![
            Span::arc(d("-1", "0"), d("-1", "-1")),
            Span::arc(d("-1", "-1"), d("0", "-1")),
            Span::arc(d("0", "-1"), d("1", "-1")),
            Span::arc(d("1", "-1"), d("1", "0")),
        ];
        assert_eq!(
            simple(&[vec![a, b]], &[vec![upper.clone(), lower.clone()]]),
            Ok(vec![true])
        );
        let twice: Vec<Span> = upper.iter().chain(&lower).chain(&upper).cloned().collect();
        let a = OPiece::arc(
            [q("0"), q("0")],
            q("1"),
            [q("1"), q("0")],
            [q("-1"), q("0")],
            false,
        )
        .unwrap();
        let b = OPiece::arc(
            [q("0"), q("0")],
            q("1"),
            [q("-1"), q("0")],
            [q("1"), q("0")],
            false,
        )
        .unwrap();
        assert!(simple(&[vec![a, b]], &[vec![twice, lower]]).is_err());
    }
}
