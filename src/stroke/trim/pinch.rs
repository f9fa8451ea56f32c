//! Pinched loops and spurs among the kept pieces, dropped with a certified
//! reach ([`pinched_loops`], [`reach_hi`]).

use super::classify::{box_dist_hi, iv_point, Part};
use super::sides::approx_dir;
use super::types::Piece;
use crate::curve::V2;
use crate::scalar::{interval_from_rational, rational_from_f64, Interval, Rational, Scalar};

/// A dropped group: its point `X` (`None` for an isolated loop or a surplus
/// piece, measured against the live pieces near it) and its pieces.
type Group = (Option<V2<Rational>>, Vec<usize>);

/// The live pieces outside `chain` that start or end at `x`.
fn live_at<'a>(
    pieces: &[&'a Piece],
    x: &V2<Rational>,
    chain: &[usize],
    dropped: &[bool],
) -> Vec<&'a Piece> {
    (0..pieces.len())
        .filter(|&j| {
            !chain.contains(&j) && !dropped[j] && (pieces[j].start() == x || pieces[j].end() == x)
        })
        .map(|j| pieces[j])
        .collect()
}

/// Marks `chain` dropped as a group without a point; a group restored earlier
/// that shares a piece (restored groups are wholly live) is replaced by it.
fn drop_group(chain: Vec<usize>, dropped: &mut [bool], groups: &mut Vec<Group>) {
    for &k in &chain {
        dropped[k] = true;
    }
    groups.retain(|(_, c)| !c.iter().any(|k| chain.contains(k)));
    groups.push((None, chain));
}

/// Pieces to drop from the output, each with its certified *reach*: an upper
/// bound of the distance from any of its points to the pieces that stay.
///
/// - *Pinched loops*: a chain of pieces `p_i, …, p_j` (following exact
///   end = start) that starts and ends at one exact point `X` where another
///   live piece starts, every piece within its cap of `X` or of the live
///   pieces at `X` outside the chain ([`reach_hi`]).
/// - *Spurs*: a piece with a dangling end (no live piece continues it), within
///   its cap of its other end `Y` or of the live pieces at `Y`.
/// - *Isolated loops* ([`isolated_loops`]): a small closed chain that touches
///   no other piece, within its caps of the other live pieces.
/// - *Surplus pieces* ([`surplus_pieces`]): a second path between two points,
///   within its cap of the other live pieces.
///
/// `caps[k]` is how far piece `k` may be from the output for claim (b) to
/// stay within tol. Every dropped group is re-checked against the final live
/// pieces (a piece it was measured against may have been dropped after it)
/// and restored if the check fails; restoring only adds pieces, so this
/// repeats until nothing changes. Finally every dropped group's point must
/// still end a live piece.
pub(super) fn pinched_loops(pieces: &[&Piece], caps: &[f64]) -> Vec<(usize, f64)> {
    let n = pieces.len();
    let mut dropped = vec![false; n];
    let live_at =
        |x: &V2<Rational>, chain: &[usize], dropped: &[bool]| live_at(pieces, x, chain, dropped);
    let mut groups: Vec<Group> = Vec::new();
    for s in 0..n {
        if dropped[s] {
            continue;
        }
        let x = pieces[s].start().clone();
        // X must be a pinch: at least two live pieces start there
        let starts = (0..n)
            .filter(|&k| !dropped[k] && pieces[k].start() == &x)
            .count();
        if starts < 2 {
            continue;
        }
        // follow the chain from s while it stays near X and the pieces there
        let mut chain = vec![s];
        let mut cur = s;
        let closed = loop {
            let refs = live_at(&x, &chain, &dropped);
            if reach_hi(pieces[cur], &refs, Some(&x), caps[cur]).is_none() {
                break false;
            }
            let end = pieces[cur].end();
            if end == &x {
                break true;
            }
            let next =
                (0..n).find(|&k| !dropped[k] && !chain.contains(&k) && pieces[k].start() == end);
            match next {
                Some(k) if chain.len() < 64 => {
                    chain.push(k);
                    cur = k;
                }
                _ => break false,
            }
        };
        if closed {
            for &k in &chain {
                dropped[k] = true;
            }
            groups.push((Some(x), chain));
        }
    }
    // spurs
    loop {
        let mut changed = false;
        for k in 0..n {
            if dropped[k] {
                continue;
            }
            let (a, b) = (pieces[k].start(), pieces[k].end());
            let live_end = |x: &V2<Rational>, starts: bool| {
                (0..n).any(|j| {
                    j != k
                        && !dropped[j]
                        && if starts {
                            pieces[j].start() == x
                        } else {
                            pieces[j].end() == x
                        }
                })
            };
            let touches = |x: &V2<Rational>| {
                (0..n).any(|j| {
                    j != k && !dropped[j] && (pieces[j].start() == x || pieces[j].end() == x)
                })
            };
            let y = if !live_end(b, true) && touches(a) {
                a.clone()
            } else if !live_end(a, false) && touches(b) {
                b.clone()
            } else {
                continue;
            };
            if reach_hi(pieces[k], &live_at(&y, &[k], &dropped), Some(&y), caps[k]).is_some() {
                dropped[k] = true;
                groups.push((Some(y), vec![k]));
                changed = true;
            }
        }
        if !changed {
            break;
        }
    }
    // re-check against the final live pieces; a group's point must still end
    // a live piece (the argument of (b) needs X in the output). Isolated
    // loops and surplus pieces are looked for after each re-check (a pinched
    // loop it restored may be one), each piece tried at most once, so this
    // ends.
    let mut reach = vec![None; n];
    let mut tried = vec![false; n];
    loop {
        recheck(pieces, caps, &groups, &mut dropped, &mut reach);
        let isolated = isolated_loops(pieces, caps, &mut dropped, &mut groups, &mut tried);
        let surplus = surplus_pieces(pieces, caps, &mut dropped, &mut groups, &mut tried);
        if !isolated && !surplus {
            break;
        }
    }
    (0..n)
        .filter(|&k| dropped[k])
        .filter_map(|k| reach[k].map(|r| (k, r)))
        .collect()
}

/// Re-checks every dropped group against the live pieces (those at its
/// point `X`, or near it for an isolated loop) and restores a group whose
/// reach is no longer proven; restoring only adds pieces, so this repeats
/// until nothing changes. `reach[k]` is set for every piece still dropped.
fn recheck(
    pieces: &[&Piece],
    caps: &[f64],
    groups: &[Group],
    dropped: &mut [bool],
    reach: &mut [Option<f64>],
) {
    loop {
        let mut changed = false;
        for (x, chain) in groups {
            if chain.iter().all(|&k| !dropped[k]) {
                continue;
            }
            let refs = match x {
                Some(x) => live_at(pieces, x, chain, dropped),
                None => near_live(pieces, chain, caps, dropped),
            };
            let reaches: Option<Vec<f64>> = if refs.is_empty() {
                None
            } else {
                chain
                    .iter()
                    .map(|&k| reach_hi(pieces[k], &refs, x.as_ref(), caps[k]))
                    .collect()
            };
            match reaches {
                Some(r) => {
                    for (&k, r) in chain.iter().zip(r) {
                        reach[k] = Some(r);
                    }
                }
                None => {
                    for &k in chain {
                        dropped[k] = false;
                        reach[k] = None;
                    }
                    changed = true;
                }
            }
        }
        if !changed {
            break;
        }
    }
}

/// *Isolated loops*: a closed chain of live pieces (each continued by exactly
/// one live piece) that no other live piece touches, whose outward float box
/// is at most its smallest cap across, and every piece of which is within its
/// cap of the other live pieces ([`reach_hi`] without a point `X`). Such a
/// chain is a small closed contour of its own (e.g. a swallowtail loop of an
/// offset kept within tolerance beside a cap); dropping it moves the boundary
/// points it stood for by at most its reach, which (b) adds, as for pinched
/// loops. Found chains are marked dropped and pushed with point `None`;
/// `tried` marks every chain measured (true: one was dropped).
fn isolated_loops(
    pieces: &[&Piece],
    caps: &[f64],
    dropped: &mut [bool],
    groups: &mut Vec<Group>,
    tried: &mut [bool],
) -> bool {
    let n = pieces.len();
    let mut seen = vec![false; n];
    let mut found = false;
    for s in 0..n {
        if dropped[s] || seen[s] || tried[s] {
            continue;
        }
        let x = pieces[s].start();
        let mut chain = vec![s];
        let mut cur = s;
        let closed = loop {
            let end = pieces[cur].end();
            if end == x {
                break true;
            }
            let mut next =
                (0..n).filter(|&k| !dropped[k] && !chain.contains(&k) && pieces[k].start() == end);
            match (next.next(), next.next()) {
                (Some(k), None) if chain.len() < 64 => {
                    chain.push(k);
                    cur = k;
                }
                _ => break false,
            }
        };
        for &k in &chain {
            seen[k] = true;
        }
        if !closed {
            continue;
        }
        // no live piece outside the chain touches its points (a dropped one
        // restored later leaves an open end, which claim (c) reports)
        let touched = (0..n).any(|j| {
            !dropped[j]
                && !chain.contains(&j)
                && chain.iter().any(|&k| {
                    let v = pieces[k].start();
                    pieces[j].start() == v || pieces[j].end() == v
                })
        });
        let cap = chain.iter().map(|&k| caps[k]).fold(f64::INFINITY, f64::min);
        let small =
            chain_box(pieces, &chain).is_some_and(|b| (b[2] - b[0]).max(b[3] - b[1]) <= cap);
        if touched || !small {
            continue;
        }
        for &k in &chain {
            tried[k] = true;
        }
        let refs = near_live(pieces, &chain, caps, dropped);
        if refs.is_empty() {
            continue;
        }
        if chain
            .iter()
            .all(|&k| reach_hi(pieces[k], &refs, None, caps[k]).is_some())
        {
            drop_group(chain, dropped, groups);
            found = true;
        }
    }
    found
}

/// *Surplus pieces*: a live piece from `A` to `B ≠ A` where more live pieces
/// start than end at `A` and more end than start at `B` — a second path from
/// `A` to `B` beside another (a thin digon the coarse sides leave where an
/// offset runs along a cap) — within its cap of the other live pieces near it
/// ([`reach_hi`] without a point). Dropping it balances both points; the
/// argument for (b) is that of the isolated loops. Pushed with point `None`;
/// each piece is tried at most once.
fn surplus_pieces(
    pieces: &[&Piece],
    caps: &[f64],
    dropped: &mut [bool],
    groups: &mut Vec<Group>,
    tried: &mut [bool],
) -> bool {
    let n = pieces.len();
    let mut found = false;
    for k in 0..n {
        if dropped[k] || tried[k] {
            continue;
        }
        let (a, b) = (pieces[k].start(), pieces[k].end());
        if a == b {
            continue;
        }
        let count = |x: &V2<Rational>, starts: bool, dropped: &[bool]| {
            (0..n)
                .filter(|&j| {
                    !dropped[j]
                        && if starts {
                            pieces[j].start() == x
                        } else {
                            pieces[j].end() == x
                        }
                })
                .count()
        };
        if count(a, true, dropped) <= count(a, false, dropped)
            || count(b, false, dropped) <= count(b, true, dropped)
        {
            continue;
        }
        tried[k] = true;
        let refs = near_live(pieces, &[k], caps, dropped);
        if !refs.is_empty() && reach_hi(pieces[k], &refs, None, caps[k]).is_some() {
            drop_group(vec![k], dropped, groups);
            found = true;
        }
    }
    found
}

/// An outward float box `[x0, y0, x1, y1]` of the pieces: a Bézier's control
/// points (enclosed), an arc's whole circle. Only a filter: a box too large
/// keeps a chain from being a candidate or adds a reference, never more.
fn chain_box(pieces: &[&Piece], chain: &[usize]) -> Option<[f64; 4]> {
    let mut b = [
        f64::INFINITY,
        f64::INFINITY,
        f64::NEG_INFINITY,
        f64::NEG_INFINITY,
    ];
    let mut add = |p: V2<Interval>| {
        b = [
            b[0].min(p.x.inf()),
            b[1].min(p.y.inf()),
            b[2].max(p.x.sup()),
            b[3].max(p.y.sup()),
        ];
    };
    for &k in chain {
        match pieces[k] {
            Piece::Bezier(z) => z.points().iter().for_each(|p| add(iv_point(p))),
            Piece::Arc(a) => {
                let (c, r) = (iv_point(&a.center), interval_from_rational(&a.radius));
                add(V2::new(c.x - r, c.y - r));
                add(V2::new(c.x + r, c.y + r));
            }
        }
    }
    b.iter().all(|v| v.is_finite()).then_some(b)
}

/// The live pieces outside `chain` whose box comes within the chain's largest
/// cap of the chain's box (the others cannot be within a cap of it; leaving
/// them out only costs reach, never soundness: the reach is proven against
/// the pieces given).
fn near_live<'a>(
    pieces: &[&'a Piece],
    chain: &[usize],
    caps: &[f64],
    dropped: &[bool],
) -> Vec<&'a Piece> {
    let Some(cb) = chain_box(pieces, chain) else {
        return Vec::new();
    };
    let cap = chain.iter().map(|&k| caps[k]).fold(0.0, f64::max);
    (0..pieces.len())
        .filter(|&j| !dropped[j] && !chain.contains(&j))
        .filter(|&j| {
            chain_box(pieces, &[j]).is_some_and(|b| {
                b[0] <= cb[2] + cap
                    && cb[0] <= b[2] + cap
                    && b[1] <= cb[3] + cap
                    && cb[1] <= b[3] + cap
            })
        })
        .map(|j| pieces[j])
        .collect()
}

/// A certified upper bound of `sup_{p ∈ piece} dist(p, refs ∪ {y})` (`y`
/// optional) if it is
/// at most `cap`: the piece is halved (interval Bézier halves, exact arc
/// midpoints) until each part's hull lies within `cap` of one point proven on
/// a reference piece (a point of the exact piece enclosed in intervals, the
/// float nearest point only choosing where) or of `y`.
pub(super) fn reach_hi(
    piece: &Piece,
    refs: &[&Piece],
    y: Option<&V2<Rational>>,
    cap: f64,
) -> Option<f64> {
    if cap.is_nan() || cap <= 0.0 {
        return None;
    }
    let yi = y.map(iv_point);
    let mut todo: Vec<(Part, u32)> = Part::initial(piece)?.into_iter().map(|p| (p, 0)).collect();
    let mut worst: f64 = 0.0;
    let mut budget = 256usize;
    while let Some((part, depth)) = todo.pop() {
        let h = part.hull()?;
        let far = |q: &V2<Interval>| h.iter().map(|p| box_dist_hi(p, q)).fold(0.0, f64::max);
        let c = {
            let k = h.len() as f64;
            let (sx, sy) = h
                .iter()
                .fold((0.0, 0.0), |(x, y), p| (x + p.x.mid(), y + p.y.mid()));
            (sx / k, sy / k)
        };
        let mut best = yi.as_ref().map_or(f64::INFINITY, far);
        for r in refs {
            if let Some(q) = nearest_on(r, c) {
                best = best.min(far(&q));
            }
        }
        if best <= cap {
            worst = worst.max(best);
            continue;
        }
        if depth >= 14 || budget == 0 {
            return None;
        }
        budget -= 1;
        let (l, r) = part.halves()?;
        todo.push((l, depth + 1));
        todo.push((r, depth + 1));
    }
    Some(worst)
}

/// A point of the exact piece (enclosed in intervals) near the float point
/// `c`: the float nearest point chooses a dyadic parameter (Bézier) or, on an
/// arc, an exact rational point of the circle in the float nearest direction
/// when it is proven in the range (else an end or a halving point).
fn nearest_on(piece: &Piece, c: (f64, f64)) -> Option<V2<Interval>> {
    let d2 = |x: f64, y: f64| (x - c.0) * (x - c.0) + (y - c.1) * (y - c.1);
    match piece {
        Piece::Bezier(b) => {
            let bf = b.map(|x| x.approx());
            let f = |t: f64| {
                let v = bf.eval_fast(t);
                d2(v.x, v.y)
            };
            let n = 64;
            let (mut bt, mut bd) = (0.0, f64::INFINITY);
            for k in 0..=n {
                let t = k as f64 / n as f64;
                let d = f(t);
                if d < bd {
                    (bt, bd) = (t, d);
                }
            }
            let (mut lo, mut hi) = (
                (bt - 1.0 / n as f64).max(0.0),
                (bt + 1.0 / n as f64).min(1.0),
            );
            for _ in 0..60 {
                let (m1, m2) = (lo + (hi - lo) * 0.382, lo + (hi - lo) * 0.618);
                if f(m1) < f(m2) {
                    hi = m2;
                } else {
                    lo = m1;
                }
            }
            let t = rational_from_f64(0.5 * (lo + hi))?;
            let ti = interval_from_rational(&t);
            let p = b.map(interval_from_rational).eval(&ti);
            (!p.x.is_empty() && !p.y.is_empty()).then_some(p)
        }
        Piece::Arc(a) => {
            let mut pts = vec![a.from.clone(), a.to.clone()];
            // the float nearest direction from the centre, snapped exactly
            // onto the circle, when it is proven in the arc's range
            let cf = approx_dir(&a.center);
            if let Some(m) =
                crate::stroke::circle::snap(&a.center, &a.radius, (c.0 - cf.0, c.1 - cf.1))
            {
                if a.contains_dir(&m.sub(&a.center)) == Some(true) {
                    pts.push(m);
                }
            }
            let mut todo = vec![(a.clone(), 0)];
            while let Some((arc, depth)) = todo.pop() {
                if depth >= 2 {
                    continue;
                }
                let Some(m) = arc.midpoint() else { continue };
                let (l, r) = arc.split_at(&m);
                pts.push(m);
                todo.push((l, depth + 1));
                todo.push((r, depth + 1));
            }
            pts.iter()
                .min_by(|p, q| {
                    let (pf, qf) = (approx_dir(p), approx_dir(q));
                    d2(pf.0, pf.1).total_cmp(&d2(qf.0, qf.1))
                })
                .map(iv_point)
        }
    }
}
