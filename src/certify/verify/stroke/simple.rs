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
//! Candidates come from a sweep over the segments' boxes.
//!
//! The area `½∮(x dy − y dx)` is enclosed piece by piece: a Bézier's by its
//! Bernstein coefficients (degree `2n − 1`, each integrating to `1/2n`), an
//! arc's as `½(ρ² θ + c × (v − u))` with `θ` the sum of its parts' angles
//! (each `atan(cross/dot)` of directions less than `π/2` apart), which must be
//! proven below `2π` so that the parts do not wind around more than the arc.

use super::geom::{arc_hull, bprod, ic, ip, iq, Bez, P};
use super::{cross, dotq, OPiece, Q2};
use crate::scalar::{atan_enclosure, Interval, Rational};
use rayon::prelude::*;

/// The range of one part: a Bézier's parameters or an arc's radius directions.
#[derive(Clone, Debug)]
pub(crate) enum Span {
    Bez(Rational, Rational),
    Arc(Q2, Q2),
}

struct Seg<'a> {
    piece: &'a OPiece,
    span: Span,
    hull: Vec<P>,
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

fn seg<'a>(piece: &'a OPiece, span: Span, hull: Option<Vec<P>>) -> Option<Seg<'a>> {
    let hull = match hull {
        Some(h) => h,
        None => hull_of(piece, &span)?,
    };
    let mut lo = [f64::INFINITY; 2];
    let mut hi = [f64::NEG_INFINITY; 2];
    for p in &hull {
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
    let (a, b) = match &s.span {
        Span::Bez(s0, s1) => {
            let m = (s0 + s1) / Rational::from_integer(2.into());
            (Span::Bez(s0.clone(), m.clone()), Span::Bez(m, s1.clone()))
        }
        Span::Arc(d0, d1) => {
            // a positive combination: strictly between (less than π/2 apart)
            let m = [&d0[0] + &d1[0], &d0[1] + &d1[1]];
            (Span::Arc(d0.clone(), m.clone()), Span::Arc(m, d1.clone()))
        }
    };
    Some((seg(s.piece, a, None)?, seg(s.piece, b, None)?))
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
    match s.span {
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

fn apart(a: &Seg, b: &Seg, depth: u32) -> bool {
    if a.hi[0] < b.lo[0] || b.hi[0] < a.lo[0] || a.hi[1] < b.lo[1] || b.hi[1] < a.lo[1] {
        return true;
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
        Some((x, y)) => apart(&x, small, depth + 1) && apart(&y, small, depth + 1),
        None => false,
    }
}

/// `a` ends where `b` starts: they meet only there.
fn touch_once(a: &Seg, b: &Seg, depth: u32) -> bool {
    if separated_at(&a.hull, &b.hull) {
        return true;
    }
    if depth >= DEPTH {
        return false;
    }
    // the far halves are apart from the other part, the near halves recurse
    match (halves(a), halves(b)) {
        (Some((a0, a1)), Some((b0, b1))) => {
            apart(&a0, b, depth + 1)
                && apart(&a1, &b1, depth + 1)
                && touch_once(&a1, &b0, depth + 1)
        }
        _ => false,
    }
}

/// Claim (c) on the outline whose parts are `spans` (per contour, per piece,
/// in order): `Ok(orientations)` (`true` counter-clockwise), or why not.
pub(crate) fn simple(
    outline: &[Vec<OPiece>],
    spans: &[Vec<Vec<Span>>],
) -> Result<Vec<bool>, String> {
    simple_with(outline, spans, None)
}

/// [`simple`] with the parts' hulls when the caller has them already
/// (`hulls[c][i][k]`: part `k` of piece `i` of contour `c`, as `hull_of`
/// computes it from the same span — claim (a) does).
pub(crate) fn simple_with(
    outline: &[Vec<OPiece>],
    spans: &[Vec<Vec<Span>>],
    hulls: Option<&[Vec<Vec<Vec<P>>>]>,
) -> Result<Vec<bool>, String> {
    // the segments in travel order per contour: (contour, index in contour)
    // (contour, index in contour, piece, span, its hull if given)
    type Flat<'a> = (usize, usize, &'a OPiece, &'a Span, Option<&'a Vec<P>>);
    let mut flat: Vec<Flat> = Vec::new();
    let mut count = Vec::new();
    for (c, (pieces, sp)) in outline.iter().zip(spans).enumerate() {
        let mut k = 0;
        for (i, (piece, parts)) in pieces.iter().zip(sp).enumerate() {
            for (l, s) in parts.iter().enumerate() {
                let h = hulls.and_then(|h| h.get(c)?.get(i)?.get(l));
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
            let sg = seg(piece, s.clone(), h.cloned()).ok_or("a part's hull is not finite")?;
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
    // the sweep's candidate pairs (boxes overlapping in x), then each pair
    // decided, in parallel; the first failing pair in sweep order is reported
    let mut order: Vec<usize> = (0..segs.len()).collect();
    order.sort_by(|&a, &b| segs[a].2.lo[0].total_cmp(&segs[b].2.lo[0]));
    let mut pairs: Vec<(usize, usize)> = Vec::new();
    for (oi, &i) in order.iter().enumerate() {
        let si = &segs[i].2;
        for &j in &order[oi + 1..] {
            if segs[j].2.lo[0] > si.hi[0] {
                break;
            }
            pairs.push((i, j));
        }
    }
    let failed = pairs.par_iter().find_first(|&&(i, j)| {
        let (ci, ki, si) = &segs[i];
        let (cj, kj, sj) = &segs[j];
        !if adjacent((*ci, *ki), (*cj, *kj)) {
            if (ki + 1) % count[*ci] == *kj {
                touch_once(si, sj, 0)
            } else {
                touch_once(sj, si, 0)
            }
        } else {
            apart(si, sj, 0)
        }
    });
    if let Some(&(i, j)) = failed {
        let ((ci, ki, _), (cj, kj, _)) = (&segs[i], &segs[j]);
        return Err(format!(
            "parts {ki} of contour {ci} and {kj} of contour {cj} are not proven apart (except at a shared end)"
        ));
    }
    // orientation: the sign of the enclosed area
    outline
        .iter()
        .zip(spans)
        .enumerate()
        .map(|(c, (pieces, sp))| {
            let mut area = ic(0.0);
            for (piece, parts) in pieces.iter().zip(sp) {
                area += area_term(piece, parts)
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
            Span::Arc(d("1", "0"), d("1", "1")),
            Span::Arc(d("1", "1"), d("0", "1")),
            Span::Arc(d("0", "1"), d("-1", "1")),
            Span::Arc(d("-1", "1"), d("-1", "0")),
        ];
        let lower = vec![
            Span::Arc(d("-1", "0"), d("-1", "-1")),
            Span::Arc(d("-1", "-1"), d("0", "-1")),
            Span::Arc(d("0", "-1"), d("1", "-1")),
            Span::Arc(d("1", "-1"), d("1", "0")),
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
