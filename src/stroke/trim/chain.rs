//! Chaining the kept pieces into contours (step 5) and the simplicity check
//! of claim (c) (step 6).

use super::types::{Contour, Orientation, Piece};
use crate::curve::Bezier;
use crate::scalar::{Interval, Rational};
use crate::stroke::circle::{arcs_meet, bezier_arc_all, Arc};
use crate::stroke::intersect::{intersections, IntersectOptions};
use num_traits::{One, Zero};

/// Chains pieces into contours by exact shared end points.
pub(super) fn chain(pieces: Vec<Piece>) -> Vec<Contour> {
    let n = pieces.len();
    let mut used = vec![false; n];
    let mut out = Vec::new();
    for s in 0..n {
        if used[s] {
            continue;
        }
        used[s] = true;
        let mut cur = vec![pieces[s].clone()];
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
    }
    out
}

/// Claim (c): closed, oriented, and no contact besides consecutive joints.
/// Returns (proven, complete, note).
pub(super) fn check_simple(contours: &[Contour], iopts: &IntersectOptions) -> (bool, bool, String) {
    // flat list with (contour, position)
    let mut flat: Vec<(&Piece, usize, usize)> = Vec::new();
    for (ci, c) in contours.iter().enumerate() {
        for (k, p) in c.pieces.iter().enumerate() {
            flat.push((p, ci, k));
        }
    }
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
    let r = intersections(&bz, iopts);
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
    let mut meets = bezier_arc_all(&bz_refs, &arc_refs);
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
    let ok = problems.is_empty();
    let note = if ok {
        format!(
            "{} closed contours, {} pieces: no crossing, only joints of consecutive pieces (certified), orientation from the area sign",
            contours.len(),
            flat.len()
        )
    } else {
        problems.truncate(10);
        problems.join("; ")
    };
    (ok, complete, note)
}
