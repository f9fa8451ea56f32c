//! The G⁰ corners of the input and [`OffsetOptions::smooth_kinks`]: the
//! absorption of near-smooth corners into their neighbouring segments.

use super::driver::Kernel;
use super::options::OffsetOptions;
use super::prep::{self, Junction};
use super::results::{join_arc_of, Corner, OffsetResult, OffsetSegment, SegmentProof};
use crate::certify::{Config, CoverBox};
use crate::curve::{Bezier, V2};
use crate::scalar::Rational;
use crate::Tolerance;

/// The junctions of consecutive pieces that need a join arc or trimming, and the
/// closing junction when the curve is closed.
pub fn corners(curve: &[Bezier<Rational>], d: &Rational) -> Vec<Corner> {
    let n = curve.len();
    let mut out = Vec::new();
    for i in 0..n {
        let j = i + 1;
        if j == n {
            // closed curve: last end = first start
            let last = curve[n - 1].points();
            if n == 1 || last[last.len() - 1] != curve[0].points()[0] {
                continue;
            }
        }
        let kind = prep::junction(&curve[i], &curve[j % n], d);
        if matches!(kind, Junction::Join { .. } | Junction::Overlap { .. }) {
            out.push(Corner {
                after: i,
                kind,
                absorbed: false,
            });
        }
    }
    out
}

/// The index of the last segment of piece `a` and of the first of piece `b`.
pub(super) fn corner_segments(res: &OffsetResult, a: usize, b: usize) -> Option<(usize, usize)> {
    let ia = res.segments.iter().rposition(|s| s.piece == a)?;
    let ib = res.segments.iter().position(|s| s.piece == b)?;
    (ia != ib).then_some((ia, ib))
}

/// Proves `bez` against the exact span `t` of `x` (both directions).
fn prove_given(
    x: &Bezier<Rational>,
    piece: usize,
    t: (f64, f64),
    bez: Bezier<f64>,
    opts: &OffsetOptions,
    kernel: &Kernel,
) -> Option<OffsetSegment> {
    let pa = kernel.span_piece(x, t)?;
    let pb = crate::certify::piece::bezier_f64(&bez)?;
    let cfg = Config {
        tol: Some(opts.tol.clone()),
        max_boxes: opts.max_boxes,
        verdict_only: true,
        parametric: !opts.search_only,
        ..Config::default()
    };
    let r = crate::certify::hausdorff_pieces(&[pa], &[pb], &cfg, &|| 0.0);
    (r.hi <= opts.tol.value()).then(|| OffsetSegment {
        piece,
        t,
        bezier: bez,
        error: (r.lo, r.hi),
        paper_error: None,
        proof: Some(SegmentProof::of(&r)),
        estimate: None,
    })
}

/// The cover of an absorbed join arc by its two neighbouring segments
/// (`None` when it is not proven within `tol`).
pub(super) fn arc_cover(
    arc: &crate::shape::ArcDesc,
    sa: &Bezier<f64>,
    sb: &Bezier<f64>,
    tol: &Tolerance,
    max_boxes: usize,
) -> Option<Vec<CoverBox>> {
    let pa = crate::certify::piece::Piece::arc(arc).ok()?;
    let pb = [
        crate::certify::piece::bezier_f64(sa)?,
        crate::certify::piece::bezier_f64(sb)?,
    ];
    let cfg = Config {
        tol: Some(tol.clone()),
        max_boxes,
        ..Config::default()
    };
    let r = crate::certify::search::one_sided(&[pa], &pb, &cfg, 0.0, (0.0, 0.0));
    (r.hi <= tol.value() && !r.boxes.is_empty()).then_some(r.boxes)
}

/// [`OffsetOptions::smooth_kinks`]: absorbs the corners whose offset ends are
/// within `tol` of each other (see there).
pub(super) fn absorb_kinks(
    curve: &[Bezier<Rational>],
    res: &mut OffsetResult,
    opts: &OffsetOptions,
    kernel: &Kernel,
) {
    let n = curve.len();
    for ci in 0..res.corners.len() {
        let a = res.corners[ci].after;
        let b = (a + 1) % n;
        let Some((ia, ib)) = corner_segments(res, a, b) else {
            continue;
        };
        let (sa, sb) = (&res.segments[ia], &res.segments[ib]);
        let (pa, pb) = (sa.bezier.points(), sb.bezier.points());
        let (p, q) = (&pa[pa.len() - 1], &pb[0]);
        let gap = (p.x - q.x).hypot(p.y - q.y);
        if gap.is_nan() || gap > opts.tol.value() {
            continue;
        }
        let m = V2::new(0.5 * (p.x + q.x), 0.5 * (p.y + q.y));
        let mut na = pa.to_vec();
        let last = na.len() - 1;
        na[last] = m.clone();
        let mut nb = pb.to_vec();
        nb[0] = m;
        let (Some(new_a), Some(new_b)) = (
            prove_given(&curve[a], a, sa.t, Bezier::new(na), opts, kernel),
            prove_given(&curve[b], b, sb.t, Bezier::new(nb), opts, kernel),
        ) else {
            continue;
        };
        // the convex side's join arc must lie within tol of the two segments
        if let Some(arc) = join_arc_of(&res.corners[ci], &res.distance) {
            if arc_cover(
                &arc,
                &new_a.bezier,
                &new_b.bezier,
                &opts.tol,
                opts.max_boxes,
            )
            .is_none()
            {
                continue;
            }
        }
        res.segments[ia] = new_a;
        res.segments[ib] = new_b;
        res.corners[ci].absorbed = true;
    }
    res.certified_hi = res.segments.iter().map(|s| s.error.1).fold(0.0, f64::max);
}
