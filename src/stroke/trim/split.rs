//! Splitting the raw pieces at their certified crossings (step 3).

use super::add_note;
use super::sides::{approx_dir, dist_hi, set_end, Kind, Raw};
use super::types::{Piece, RawCrossing};
use crate::curve::{Bezier, V2};
use crate::scalar::{rational_from_f64, Interval, Rational, Scalar};
use crate::stroke::circle::{arc_meetings, bezier_arc_all, snap, Arc, ArcMeet, Meetings};
use crate::stroke::intersect::{intersections, Crossing, IntersectOptions};
use num_traits::{One, Signed, Zero};
use std::time::Instant;

// ---------------------------------------------------------------------------
// splitting

#[derive(Clone, Debug)]
pub(super) struct Split {
    /// Bézier: the parameter; arc: unused.
    pub(super) param: Rational,
    /// The exact crossing point shared by both pieces.
    pub(super) point: V2<Rational>,
}

#[derive(Clone, Debug)]
pub(super) struct Sub {
    pub(super) raw: usize,
    /// The exact sub-piece of the raw piece (its union over the raw piece is
    /// the raw piece).
    pub(super) pre: Piece,
    /// With the crossing points as end points (what is output).
    pub(super) post: Piece,
    /// Largest end move.
    pub(super) delta: f64,
    /// The sub-piece's ends are crossing points (not raw piece ends).
    pub(super) end_splits: [bool; 2],
    /// Bézier: its parameter range on the raw piece (`pre` is the exact
    /// restriction to it).
    pub(super) range: (Rational, Rational),
}

pub(super) fn split_piece(raw: usize, p: &Piece, splits: &mut [Split]) -> Vec<Sub> {
    match p {
        Piece::Bezier(b) => {
            splits.sort_by(|a, b| a.param.cmp(&b.param));
            let zero = <Rational as Zero>::zero();
            let one = <Rational as One>::one();
            let mut out = Vec::new();
            let mut prev: Option<&Split> = None;
            for k in 0..=splits.len() {
                let next = splits.get(k);
                let a = prev.map(|s| s.param.clone()).unwrap_or(zero.clone());
                let bb = next.map(|s| s.param.clone()).unwrap_or(one.clone());
                let pre = b.restrict(&a, &bb);
                let post = set_end(&pre, prev.map(|s| &s.point), next.map(|s| &s.point));
                let mut delta: f64 = 0.0;
                if let Some(s) = prev {
                    delta = delta.max(dist_hi(&pre.points()[0], &s.point));
                }
                if let Some(s) = next {
                    delta = delta.max(dist_hi(pre.points().last().expect("nonempty"), &s.point));
                }
                out.push(Sub {
                    raw,
                    pre: Piece::Bezier(pre),
                    post: Piece::Bezier(post),
                    delta,
                    end_splits: [prev.is_some(), next.is_some()],
                    range: (a, bb),
                });
                prev = next;
            }
            out
        }
        Piece::Arc(a) => {
            // order along the travel direction by the angle from the start
            let ang = |pt: &V2<Rational>| {
                let u = approx_dir(&a.from.sub(&a.center));
                let v = approx_dir(&pt.sub(&a.center));
                let mut d = v.1.atan2(v.0) - u.1.atan2(u.0);
                if a.clockwise {
                    d = -d;
                }
                d.rem_euclid(2.0 * std::f64::consts::PI)
            };
            splits.sort_by(|x, y| ang(&x.point).total_cmp(&ang(&y.point)));
            let mut out = Vec::new();
            let mut cur = a.clone();
            let mut first = true;
            for s in splits.iter() {
                let (l, r) = cur.split_at(&s.point);
                out.push(Sub {
                    raw,
                    pre: Piece::Arc(l.clone()),
                    post: Piece::Arc(l),
                    delta: 0.0,
                    end_splits: [!first, true],
                    range: (<Rational as Zero>::zero(), <Rational as One>::one()),
                });
                first = false;
                cur = r;
            }
            out.push(Sub {
                raw,
                pre: Piece::Arc(cur.clone()),
                post: Piece::Arc(cur),
                delta: 0.0,
                end_splits: [!first, false],
                range: (<Rational as Zero>::zero(), <Rational as One>::one()),
            });
            out
        }
    }
}

/// The crossing of two degree-1 pieces with non-parallel directions, exact:
/// the point and both parameters (inside `[0, 1]`), `None` otherwise.
fn segment_crossing(
    a: &Bezier<Rational>,
    b: &Bezier<Rational>,
) -> Option<(V2<Rational>, Rational, Rational)> {
    if a.degree() != 1 || b.degree() != 1 {
        return None;
    }
    let (p, q) = (&a.points()[0], &a.points()[1]);
    let (u, v) = (&b.points()[0], &b.points()[1]);
    let (d1, d2) = (q.sub(p), v.sub(u));
    let den = d1.cross(&d2);
    if den.is_zero() {
        return None;
    }
    let w = u.sub(p);
    let s = w.cross(&d2) / &den;
    let t = w.cross(&d1) / &den;
    let unit = |x: &Rational| !x.is_negative() && *x <= <Rational as One>::one();
    (unit(&s) && unit(&t)).then(|| (p.add(&d1.scale(&s)), s, t))
}

/// The exact projection of `x` onto a degree-1 piece and its parameter,
/// when that parameter is strictly inside `(0, 1)`.
fn project_on_segment(a: &Bezier<Rational>, x: &V2<Rational>) -> Option<(V2<Rational>, Rational)> {
    let (p, q) = (&a.points()[0], &a.points()[1]);
    let d = q.sub(p);
    let n2 = d.norm2();
    if n2.is_zero() {
        return None;
    }
    let u = x.sub(p).dot(&d) / n2;
    (u.is_positive() && u < <Rational as One>::one()).then(|| (p.add(&d.scale(&u)), u))
}

fn mid_rational(lo: f64, hi: f64) -> Option<Rational> {
    rational_from_f64(0.5 * lo + 0.5 * hi)
}

// ---------------------------------------------------------------------------
// the crossings of the raw arrangement

/// What the crossing search found: the split points of every raw piece, the
/// crossings where pieces were split, and whether the search was complete.
pub(super) struct Crossings {
    /// `splits[i]`: the split points of raw piece `i`.
    pub(super) splits: Vec<Vec<Split>>,
    /// The crossings where two raw pieces were split.
    pub(super) crossings: Vec<RawCrossing>,
    /// Nothing of the raw arrangement was left undecided.
    pub(super) complete: bool,
    /// The raw pairs `(i, j)`, `i ≤ j`, that the search did not prove to meet
    /// only at shared end points: a crossing, an undecided region or range,
    /// a tangential contact, a crossing left unsplit. Every other pair of raw
    /// pieces (and single piece, `i = j`) meets exactly at the end points
    /// the two share, which claim (c) reuses ([`super::chain::Known`]).
    pub(super) unsure: std::collections::HashSet<(usize, usize)>,
    /// The split points of arc–arc crossings, one per arc (see
    /// [`arc_arc_crossings`]).
    pub(super) bridges: Vec<Bridge>,
}

/// The two split points of one arc–arc crossing: `ends[0]` on the first
/// arc's circle, `ends[1]` on the second's, about `2μ` apart.
#[derive(Clone, Debug)]
pub(super) struct Bridge {
    pub(super) ends: [V2<Rational>; 2],
}

/// The certified crossings of the raw pieces and the split points they give
/// (see the split convention in the module docs): Bézier pairs, then Bézier–arc
/// pairs, then arc–arc pairs (split `bridge_mu` from the crossing, see
/// [`arc_arc_crossings`]).
pub(super) fn find_crossings(
    raws: &[Raw],
    iopts: &IntersectOptions,
    bridge_mu: f64,
    notes: &mut Vec<String>,
    t0: Instant,
) -> Crossings {
    let bez_idx: Vec<usize> = (0..raws.len())
        .filter(|&i| matches!(raws[i].piece, Piece::Bezier(_)))
        .collect();
    let arc_idx: Vec<usize> = (0..raws.len())
        .filter(|&i| matches!(raws[i].piece, Piece::Arc(_)))
        .collect();
    let mut found = Crossings {
        splits: vec![Vec::new(); raws.len()],
        crossings: Vec::new(),
        complete: true,
        bridges: Vec::new(),
        unsure: std::collections::HashSet::new(),
    };
    bezier_crossings(raws, &bez_idx, iopts, notes, &mut found, t0);
    let bez: Vec<&Bezier<Rational>> = bez_idx
        .iter()
        .filter_map(|&i| match &raws[i].piece {
            Piece::Bezier(b) => Some(b),
            Piece::Arc(_) => None,
        })
        .collect();
    let arcs: Vec<&Arc> = arc_idx
        .iter()
        .filter_map(|&i| match &raws[i].piece {
            Piece::Arc(a) => Some(a),
            Piece::Bezier(_) => None,
        })
        .collect();
    // arc by arc, Bézier by Bézier, as the pairs were always taken
    let mut meets = bezier_arc_all(&bez, &arcs);
    meets.sort_by_key(|m| (m.1, m.0));
    for (i, j, m) in meets {
        bezier_arc_crossings(
            (bez_idx[i], bez[i]),
            (arc_idx[j], arcs[j]),
            m,
            notes,
            &mut found,
        );
    }
    arc_arc_crossings(raws, &arc_idx, bridge_mu, notes, &mut found);
    log::debug!("arcs: {:?}", t0.elapsed());
    found
}

/// The crossings of the raw Bézier pieces (`bez_idx`), split at the exact
/// points of [`bezier_split`].
fn bezier_crossings(
    raws: &[Raw],
    bez_idx: &[usize],
    iopts: &IntersectOptions,
    notes: &mut Vec<String>,
    found: &mut Crossings,
    t0: Instant,
) {
    let bez: Vec<Bezier<Rational>> = bez_idx
        .iter()
        .map(|&i| match &raws[i].piece {
            Piece::Bezier(b) => b.clone(),
            Piece::Arc(_) => unreachable!(),
        })
        .collect();
    let inter = intersections(&bez, iopts);
    log::debug!(
        "raw intersections: {:?} {} boxes",
        t0.elapsed(),
        inter.boxes
    );
    if log::log_enabled!(log::Level::Trace) {
        for (k, r) in raws.iter().enumerate() {
            log::trace!(
                "raw {k}: {:?} e={:.3e} {:?}",
                r.kind,
                r.e,
                match &r.piece {
                    Piece::Bezier(b) => format!(
                        "bez deg {} {:?}",
                        b.degree(),
                        b.map(Scalar::approx).points()
                    ),
                    Piece::Arc(a) => format!("arc {:?}", a.desc()),
                }
            );
        }
        for u in &inter.undecided {
            log::trace!("undecided {:?}", u);
        }
    }
    found.complete = inter.complete;
    let pair = |i: usize, j: usize| (bez_idx[i].min(bez_idx[j]), bez_idx[i].max(bez_idx[j]));
    found
        .unsure
        .extend(inter.undecided.iter().map(|u| pair(u.pieces.0, u.pieces.1)));
    found
        .unsure
        .extend(inter.crossings.iter().map(|c| pair(c.pieces.0, c.pieces.1)));
    for u in &inter.undecided {
        add_note(
            notes,
            format!(
                "raw pieces {} and {}: {} region undecided",
                bez_idx[u.pieces.0], bez_idx[u.pieces.1], u.reason
            ),
        );
    }
    for c in &inter.crossings {
        let (i, j) = (bez_idx[c.pieces.0], bez_idx[c.pieces.1]);
        if let Some((point, s, t)) = bezier_split(&raws[i].piece, &raws[j].piece, c) {
            found.splits[i].push(Split {
                param: s,
                point: point.clone(),
            });
            found.splits[j].push(Split { param: t, point });
            found.crossings.push(RawCrossing {
                pieces: (i, j),
                s: c.s,
                t: c.t,
            });
        }
    }
}

/// The exact split point of a Bézier–Bézier crossing and its parameters on
/// both pieces: the dyadic midpoints of the enclosures, made exact on a
/// straight piece (`None` when a midpoint is not a finite rational).
fn bezier_split(a: &Piece, b: &Piece, c: &Crossing) -> Option<(V2<Rational>, Rational, Rational)> {
    let (px, py) = (
        mid_rational(c.point.0 .0, c.point.0 .1),
        mid_rational(c.point.1 .0, c.point.1 .1),
    );
    let (s, t) = (mid_rational(c.s.0, c.s.1), mid_rational(c.t.0, c.t.1));
    // two straight segments: their crossing is rational, split exactly
    // there (no end moves; an exact point keeps later joints exact)
    let exact = match (a, b) {
        (Piece::Bezier(a), Piece::Bezier(b)) => segment_crossing(a, b),
        _ => None,
    };
    let (px, py, s, t) = match exact {
        Some((p, s, t)) => (Some(p.x), Some(p.y), Some(s), Some(t)),
        None => match (a, b, &px, &py) {
            // one straight segment: the crossing point projected onto
            // it exactly, so its halves stay on its line (a half tilted
            // by an ulp would meet the next join arc almost tangentially)
            (Piece::Bezier(a), _, Some(x), Some(y)) if a.degree() == 1 => {
                match project_on_segment(a, &V2::new(x.clone(), y.clone())) {
                    Some((q, u)) => (Some(q.x), Some(q.y), Some(u), t),
                    None => (px, py, s, t),
                }
            }
            (_, Piece::Bezier(b), Some(x), Some(y)) if b.degree() == 1 => {
                match project_on_segment(b, &V2::new(x.clone(), y.clone())) {
                    Some((q, u)) => (Some(q.x), Some(q.y), s, Some(u)),
                    None => (px, py, s, t),
                }
            }
            _ => (px, py, s, t),
        },
    };
    match (px, py, s, t) {
        (Some(xx), Some(xy), Some(s), Some(t)) => Some((V2::new(xx, xy), s, t)),
        _ => None,
    }
}

/// The crossings of raw Bézier piece `bi` and raw arc `ai` (what
/// [`crate::stroke::circle::bezier_arc`] found, `m`), split at a
/// rational point exactly on the circle; joints (a shared end point) are
/// skipped, tangential contacts and crossings at an arc end are noted.
fn bezier_arc_crossings(
    (bi, b): (usize, &Bezier<Rational>),
    (ai, arc): (usize, &Arc),
    m: ArcMeet,
    notes: &mut Vec<String>,
    found: &mut Crossings,
) {
    if !m.hits.is_empty() || !m.undecided.is_empty() {
        log::trace!("bez {bi} arc {ai}: {:?}", m);
    }
    let pair = (bi.min(ai), bi.max(ai));
    if !m.undecided.is_empty() {
        found.unsure.insert(pair);
        found.complete = false;
        add_note(
            notes,
            format!("raw pieces {bi} and {ai}: arc range undecided"),
        );
    }
    for h in m.hits {
        // the joint: the Bézier's end point is the arc's end point
        if h.t.0 == h.t.1 {
            let zero = <Rational as Zero>::zero();
            let one = <Rational as One>::one();
            let pt = if h.t.0 == zero {
                Some(b.points()[0].clone())
            } else if h.t.0 == one {
                b.points().last().cloned()
            } else {
                None
            };
            if let Some(pt) = pt {
                if pt == arc.from || pt == arc.to {
                    continue;
                }
            }
        }
        found.unsure.insert(pair);
        if h.multiple {
            found.complete = false;
            add_note(
                notes,
                format!("raw pieces {bi} and {ai}: tangential contact"),
            );
            continue;
        }
        let s = (&h.t.0 + &h.t.1) / Rational::from_integer(2.into());
        let p = b.eval(&s);
        let x = snap(&arc.center, &arc.radius, approx_dir(&p.sub(&arc.center)));
        match x {
            Some(x)
                if arc.contains_dir(&x.sub(&arc.center)) == Some(true)
                    && x != arc.from
                    && x != arc.to =>
            {
                found.splits[bi].push(Split {
                    param: s,
                    point: x.clone(),
                });
                found.splits[ai].push(Split {
                    param: <Rational as Zero>::zero(),
                    point: x,
                });
                found.crossings.push(RawCrossing {
                    pieces: (bi.min(ai), bi.max(ai)),
                    s: (h.t.0.approx(), h.t.1.approx()),
                    t: (0.0, 0.0),
                });
            }
            _ => {
                found.complete = false;
                add_note(
                    notes,
                    format!("raw pieces {bi} and {ai}: crossing at an arc end"),
                );
            }
        }
    }
}

/// Arc–arc crossings. Two different circles meet at irrational points in
/// general, so no exact point is shared: each arc is split at its own
/// rational point exactly on its circle, `μ` (arc length) from the enclosed
/// crossing on the side **outside the other arc's disk** (the disk of a cap
/// or join arc about an input point lies in `S`, so the part of an arc inside
/// it is never boundary; this choice only decides which half can be kept, it
/// is not used by any proof). The two split points are recorded as a
/// [`Bridge`]: where the kept halves end at them, a straight connector joins
/// them in the output, charged to (a) by its length. Pairs that may meet but
/// cannot be split (same circle, an undecided range test, a crossing too near
/// an arc end) leave the search incomplete with a note.
fn arc_arc_crossings(
    raws: &[Raw],
    arc_idx: &[usize],
    mu: f64,
    notes: &mut Vec<String>,
    found: &mut Crossings,
) {
    for (k, &ai) in arc_idx.iter().enumerate() {
        for &aj in &arc_idx[k + 1..] {
            let (Piece::Arc(a), Piece::Arc(b)) = (&raws[ai].piece, &raws[aj].piece) else {
                continue;
            };
            let shared = [&a.from, &a.to]
                .into_iter()
                .find(|p| **p == b.from || **p == b.to);
            let meetings = arc_meetings(a, b, shared);
            if matches!(meetings, Some(Meetings::Apart)) {
                continue;
            }
            found.unsure.insert((ai.min(aj), ai.max(aj)));
            if matches!(meetings, Some(Meetings::Overlap)) {
                // one circle: split at each other's points, exactly (see
                // [`share_circle_splits`]); no crossing to bridge
                continue;
            }
            let points = match meetings {
                Some(Meetings::Points(ps)) if ps.len() == 1 || disjoint(&ps[0], &ps[1]) => ps,
                _ => {
                    found.complete = false;
                    add_note(
                        notes,
                        format!("raw arcs {ai} and {aj} may meet (not split)"),
                    );
                    continue;
                }
            };
            for p in points {
                match (
                    split_point_outside(a, b, &p, mu),
                    split_point_outside(b, a, &p, mu),
                ) {
                    (Some(xa), Some(xb)) => {
                        found.splits[ai].push(Split {
                            param: <Rational as Zero>::zero(),
                            point: xa.clone(),
                        });
                        found.splits[aj].push(Split {
                            param: <Rational as Zero>::zero(),
                            point: xb.clone(),
                        });
                        found.crossings.push(RawCrossing {
                            pieces: (ai, aj),
                            s: (0.0, 0.0),
                            t: (0.0, 0.0),
                        });
                        found.bridges.push(Bridge { ends: [xa, xb] });
                    }
                    _ => {
                        found.complete = false;
                        add_note(
                            notes,
                            format!(
                                "raw arcs {ai} and {aj}: crossing too near an arc end (not split)"
                            ),
                        );
                    }
                }
            }
        }
    }
}

/// Raw arcs of **one circle** (equal centre and radius, exactly) overlap
/// along stretches, which no crossing search can decide. Their split points
/// are shared instead: every arc of such a group is split at every end point
/// and split point of the group that lies strictly inside its range (exact
/// tests: the points are rational points of the circle). After the split,
/// two sub-arcs of a group either are one point set or meet at most at end
/// points, and [`drop_coincident`] keeps one copy of each point set. Returns
/// the groups (raw indices, two or more each).
pub(super) fn share_circle_splits(raws: &[Raw], found: &mut Crossings) -> Vec<Vec<usize>> {
    let mut groups: Vec<Vec<usize>> = Vec::new();
    for (i, raw) in raws.iter().enumerate() {
        let Piece::Arc(a) = &raw.piece else { continue };
        if raw.kind != Kind::Boundary {
            continue;
        }
        let same = |g: &Vec<usize>| match &raws[g[0]].piece {
            Piece::Arc(b) => b.center == a.center && b.radius == a.radius,
            Piece::Bezier(_) => false,
        };
        match groups.iter_mut().find(|g| same(g)) {
            Some(g) => g.push(i),
            None => groups.push(vec![i]),
        }
    }
    groups.retain(|g| g.len() > 1);
    for g in &groups {
        let mut points: Vec<V2<Rational>> = Vec::new();
        for &i in g {
            let Piece::Arc(a) = &raws[i].piece else {
                continue;
            };
            let own = found.splits[i].iter().map(|s| &s.point);
            for p in [&a.from, &a.to].into_iter().chain(own) {
                if !points.contains(p) {
                    points.push(p.clone());
                }
            }
        }
        for &i in g {
            let Piece::Arc(a) = &raws[i].piece else {
                continue;
            };
            for p in &points {
                let inside =
                    *p != a.from && *p != a.to && a.contains_dir(&p.sub(&a.center)) == Some(true);
                if inside && !found.splits[i].iter().any(|s| s.point == *p) {
                    found.splits[i].push(Split {
                        param: <Rational as Zero>::zero(),
                        point: p.clone(),
                    });
                }
            }
        }
    }
    groups
}

/// Keeps one copy of each point set among the sub-arcs of a group of
/// [`share_circle_splits`] (an arc and its reverse are one point set): the
/// copy of the raw piece with the largest error bound `e`, so that its
/// classification covers the exact counterparts of every copy (a kept copy
/// adds its `e` to claim (b); a removed one has the `e`-disk of each of its
/// points inside `S`). Returns the sub-pieces left and how many were dropped.
pub(super) fn drop_coincident(
    raws: &[Raw],
    subs: Vec<Sub>,
    groups: &[Vec<usize>],
) -> (Vec<Sub>, usize) {
    let group_of = |raw: usize| groups.iter().position(|g| g.contains(&raw));
    let same = |x: &Arc, y: &Arc| {
        (x.from == y.from && x.to == y.to && x.clockwise == y.clockwise)
            || (x.from == y.to && x.to == y.from && x.clockwise != y.clockwise)
    };
    let mut drop = vec![false; subs.len()];
    for k in 0..subs.len() {
        let (Some(gk), Piece::Arc(ak)) = (group_of(subs[k].raw), &subs[k].pre) else {
            continue;
        };
        for j in 0..subs.len() {
            if j == k || drop[j] || subs[j].raw == subs[k].raw || group_of(subs[j].raw) != Some(gk)
            {
                continue;
            }
            let Piece::Arc(aj) = &subs[j].pre else {
                continue;
            };
            if !same(ak, aj) {
                continue;
            }
            // the copy kept: the larger e, then the lower raw index
            let (ek, ej) = (raws[subs[k].raw].e, raws[subs[j].raw].e);
            if ej > ek || (ej == ek && subs[j].raw < subs[k].raw) {
                drop[k] = true;
                break;
            }
        }
    }
    let dropped = drop.iter().filter(|d| **d).count();
    let kept = subs
        .into_iter()
        .zip(drop)
        .filter(|(_, d)| !d)
        .map(|(s, _)| s)
        .collect();
    (kept, dropped)
}

fn disjoint(p: &V2<Interval>, q: &V2<Interval>) -> bool {
    p.x.disjoint(q.x) || p.y.disjoint(q.y)
}

/// A rational point exactly on `a`'s circle, strictly inside its range,
/// about `mu` (arc length) from the enclosed crossing `p` with `b`, and
/// strictly outside `b`'s disk (exact test); `None` when neither side works.
fn split_point_outside(a: &Arc, b: &Arc, p: &V2<Interval>, mu: f64) -> Option<V2<Rational>> {
    let r = a.radius.approx();
    let (px, py) = (
        p.x.mid() - a.center.x.approx(),
        p.y.mid() - a.center.y.approx(),
    );
    let th = py.atan2(px);
    let dth = mu / r;
    let rb2 = &b.radius * &b.radius;
    [th + dth, th - dth].into_iter().find_map(|t| {
        let x = snap(&a.center, &a.radius, (t.cos(), t.sin()))?;
        let inside_range = a.contains_dir(&x.sub(&a.center)) == Some(true);
        let outside_b = x.sub(&b.center).norm2() > rb2;
        (inside_range && outside_b && x != a.from && x != a.to).then_some(x)
    })
}
