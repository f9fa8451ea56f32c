//! Chaining the kept pieces into contours (step 5) and the simplicity check
//! of claim (c) (step 6).

use super::types::{Contour, Orientation, Piece};
use crate::curve::Bezier;
use crate::scalar::{Interval, Rational};
use crate::stroke::circle::{arcs_meet, bezier_arc_all_skipping, Arc};
use crate::stroke::intersect::{intersections_skipping, IntersectOptions};
use num_traits::{One, Zero};

/// What the raw crossing search proved about the output's pieces, for claim
/// (c) to reuse instead of solving those pairs again.
///
/// A piece whose `origin` is `Some(i)` **is** raw piece `i`, exactly (an
/// unsplit raw piece, its control points unmoved). For two such pieces from
/// raw pieces `i ≠ j` (or one piece, `i = j`) whose pair is not `unsure`, the
/// raw search proved that they meet exactly at the end points they share and
/// nowhere else: in the pair's solved domain every box was excluded (no
/// crossing, nothing undecided), and each shared end point was proven the
/// only contact in a corner around it. The output pieces are the same point
/// sets, so the same holds for them, and (c) only has to check that pieces
/// sharing an end point are consecutive in their contour.
pub(crate) struct Known<'a> {
    /// Per contour, per piece (as [`chain`] returns them).
    pub(super) origin: Vec<Vec<Option<usize>>>,
    /// The raw pairs `(i, j)`, `i ≤ j`, not proven to meet only at shared
    /// end points (see [`super::split::Crossings::unsure`]).
    pub(super) unsure: &'a std::collections::HashSet<(usize, usize)>,
}

/// Chains pieces into contours by exact shared end points; each piece's
/// tag (the raw piece it is exactly, if any) is returned beside the
/// contours, in the same order.
pub(crate) fn chain(
    tagged: Vec<(Piece, Option<usize>)>,
) -> (Vec<Contour>, Vec<Vec<Option<usize>>>) {
    let (pieces, tags): (Vec<Piece>, Vec<Option<usize>>) = tagged.into_iter().unzip();
    let n = pieces.len();
    let mut used = vec![false; n];
    let mut out = Vec::new();
    let mut out_tags = Vec::new();
    for s in 0..n {
        if used[s] {
            continue;
        }
        used[s] = true;
        let mut cur = vec![pieces[s].clone()];
        let mut cur_tags = vec![tags[s]];
        loop {
            let end = cur.last().expect("nonempty").end().clone();
            if &end == cur[0].start() {
                break;
            }
            let next = (0..n).find(|&k| !used[k] && pieces[k].start() == &end);
            match next {
                Some(k) => {
                    used[k] = true;
                    cur.push(pieces[k].clone());
                    cur_tags.push(tags[k]);
                }
                None => break,
            }
        }
        let closed = cur.last().expect("nonempty").end() == cur[0].start();
        let area = cur
            .iter()
            .map(|p| p.area_term())
            .try_fold(Interval::try_from((0.0, 0.0)).expect("zero"), |acc, a| {
                a.map(|a| acc + a)
            });
        let (orientation, area) = match (closed, area) {
            (true, Some(a)) if a.inf() > 0.0 => (Orientation::CounterClockwise, (a.inf(), a.sup())),
            (true, Some(a)) if a.sup() < 0.0 => (Orientation::Clockwise, (a.inf(), a.sup())),
            (_, Some(a)) => (Orientation::Undecided, (a.inf(), a.sup())),
            _ => (Orientation::Undecided, (f64::NEG_INFINITY, f64::INFINITY)),
        };
        out.push(Contour {
            pieces: cur,
            closed,
            orientation,
            area,
        });
        out_tags.push(cur_tags);
    }
    (out, out_tags)
}

/// Claim (c): closed, oriented, and no contact besides consecutive joints.
/// Pairs that `known` answers for (see [`Known`]) are not solved again: they
/// meet exactly at their shared end points, which must then be joints of
/// consecutive pieces. Returns (proven, complete, note).
pub(crate) fn check_simple(
    contours: &[Contour],
    iopts: &IntersectOptions,
    known: Option<&Known>,
) -> (bool, bool, String) {
    // flat list with (contour, position)
    let mut flat: Vec<(&Piece, usize, usize)> = Vec::new();
    for (ci, c) in contours.iter().enumerate() {
        for (k, p) in c.pieces.iter().enumerate() {
            flat.push((p, ci, k));
        }
    }
    let origin = |i: usize| known.and_then(|k| k.origin.get(flat[i].1)?.get(flat[i].2).copied()?);
    // flat pieces i, j (i = j: one piece alone) whose contacts the raw search
    // already proved to be their shared end points
    let is_known = |i: usize, j: usize| match (known, origin(i), origin(j)) {
        (Some(k), Some(a), Some(b)) => {
            (a != b || i == j) && !k.unsure.contains(&(a.min(b), a.max(b)))
        }
        _ => false,
    };
    let mut known_pairs = 0usize;
    let consecutive = |i: usize, j: usize| -> bool {
        let (a, b) = (&flat[i], &flat[j]);
        if a.1 != b.1 {
            return false;
        }
        let n = contours[a.1].pieces.len();
        let closed = contours[a.1].closed;
        let (x, y) = (a.2, b.2);
        (x + 1 == y || y + 1 == x) || (closed && ((x + 1) % n == y || (y + 1) % n == x))
    };
    let mut problems = Vec::new();
    if let Some(c) = contours.iter().position(|c| !c.closed) {
        problems.push(format!("contour {c} is not closed"));
    }
    if let Some(c) = contours
        .iter()
        .position(|c| c.orientation == Orientation::Undecided)
    {
        problems.push(format!("contour {c}: orientation undecided"));
    }
    let bez: Vec<usize> = (0..flat.len())
        .filter(|&i| matches!(flat[i].0, Piece::Bezier(_)))
        .collect();
    let arcs: Vec<usize> = (0..flat.len())
        .filter(|&i| matches!(flat[i].0, Piece::Arc(_)))
        .collect();
    let bz: Vec<Bezier<Rational>> = bez
        .iter()
        .map(|&i| match flat[i].0 {
            Piece::Bezier(b) => b.clone(),
            Piece::Arc(_) => unreachable!(),
        })
        .collect();
    let r = intersections_skipping(&bz, iopts, |i, j| is_known(bez[i], bez[j]));
    log::debug!(
        "(c) Bézier pairs: {} solved, {} known from the raw search, {} excluded by boxes",
        r.pairs_solved,
        r.pairs_known,
        r.pairs_excluded
    );
    known_pairs += r.pairs_known;
    let mut complete = r.complete;
    if !r.crossings.is_empty() {
        problems.push(format!("{} crossings left", r.crossings.len()));
    }
    if !r.complete {
        problems.push(format!("{} undecided regions", r.undecided.len()));
    }
    for j in &r.joints {
        let (a, b) = (bez[j.pieces.0], bez[j.pieces.1]);
        if !consecutive(a, b) {
            problems.push(format!("pieces {a} and {b} touch but are not consecutive"));
        }
    }
    let arc_refs: Vec<&Arc> = arcs
        .iter()
        .filter_map(|&i| match flat[i].0 {
            Piece::Arc(a) => Some(a),
            Piece::Bezier(_) => None,
        })
        .collect();
    let bz_refs: Vec<&Bezier<Rational>> = bz.iter().collect();
    let mut meets = bezier_arc_all_skipping(&bz_refs, &arc_refs, |i, j| is_known(bez[i], arcs[j]));
    meets.sort_by_key(|m| (m.1, m.0));
    for (i, j, m) in meets {
        let (bi, ai, b, arc) = (bez[i], arcs[j], bz_refs[i], arc_refs[j]);
        if !m.undecided.is_empty() {
            complete = false;
            problems.push(format!("pieces {bi} and {ai}: undecided"));
        }
        for h in &m.hits {
            let joint = h.t.0 == h.t.1 && {
                let pt = if h.t.0.is_zero() {
                    Some(&b.points()[0])
                } else if h.t.0 == <Rational as One>::one() {
                    b.points().last()
                } else {
                    None
                };
                pt.is_some_and(|p| *p == arc.from || *p == arc.to) && consecutive(ai, bi)
            };
            if !joint {
                problems.push(format!("pieces {bi} and {ai} meet"));
            }
        }
    }
    for (k, &ai) in arcs.iter().enumerate() {
        for &aj in &arcs[k + 1..] {
            let (Piece::Arc(a), Piece::Arc(b)) = (flat[ai].0, flat[aj].0) else {
                continue;
            };
            if is_known(ai, aj) {
                continue;
            }
            let shared = if consecutive(ai, aj) {
                [&a.from, &a.to]
                    .into_iter()
                    .find(|p| **p == b.from || **p == b.to)
            } else {
                None
            };
            match arcs_meet(a, b, shared) {
                Some(false) => {}
                Some(true) => problems.push(format!("arcs {ai} and {aj} meet")),
                None => {
                    complete = false;
                    problems.push(format!("arcs {ai} and {aj}: undecided"));
                }
            }
        }
    }
    // the known pairs: their only contacts are shared end points, which
    // must be joints of consecutive pieces
    for i in 0..flat.len() {
        for j in i + 1..flat.len() {
            if is_known(i, j) && shares_an_end(flat[i].0, flat[j].0) && !consecutive(i, j) {
                problems.push(format!("pieces {i} and {j} touch but are not consecutive"));
            }
        }
    }
    let ok = problems.is_empty();
    let note = if ok {
        format!(
            "{} closed contours, {} pieces: no crossing, only joints of consecutive pieces (certified{}), orientation from the area sign",
            contours.len(),
            flat.len(),
            if known.is_some() {
                format!("; {known_pairs} Bézier pairs known from the raw search")
            } else {
                String::new()
            }
        )
    } else {
        problems.truncate(10);
        problems.join("; ")
    };
    (ok, complete, note)
}

/// The two pieces have an end point in common (exactly).
fn shares_an_end(a: &Piece, b: &Piece) -> bool {
    let (a0, a1) = (a.start(), a.end());
    [b.start(), b.end()].into_iter().any(|p| p == a0 || p == a1)
}
