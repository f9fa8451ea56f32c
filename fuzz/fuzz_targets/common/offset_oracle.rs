//! The inputs and checks shared by the `offset` and `convolve` fuzz targets
//! (included by each with `#[path]`): the curves, tolerances and budgets they
//! build, float geometry, and the parts of an `OffsetResult`'s contract that
//! both engines keep (bounds, tiling, counts, degrees, joints, pinning and
//! soundness spot checks).

use libfuzzer_sys::arbitrary::{Result, Unstructured};
use lncert::curve::{Bezier, V2};
use lncert::offset::kernels::Subdivision;
use lncert::offset::{OffsetMethod, OffsetOptions, OffsetResult, OffsetSegment};
use lncert::scalar::{frac, Rational, Scalar};
use lncert::Tolerance;

/// Tolerances: absurd ones (must be errors, except the huge 1e9) and a few
/// reachable ones.
pub const TOLS: [f64; 10] = [
    0.0,
    -1.0,
    f64::NAN,
    f64::INFINITY,
    1e-300,
    1e-1,
    3e-2,
    1e9,
    1e-2,
    1e-3,
];

pub fn q(p: i64, den: i64) -> Rational {
    frac::<Rational>(p, den)
}

fn point(u: &mut Unstructured) -> Result<V2<Rational>> {
    let x: i8 = u.arbitrary()?;
    let y: i8 = u.arbitrary()?;
    Ok(V2::new(q(x.into(), 16), q(y.into(), 16)))
}

/// 1-2 Bézier pieces of degree 1-4 on the 1/16 grid; the second one free,
/// joined to the first, or also closing the curve. A piece's degree is read
/// from one byte modulo 16: 0-3 give degree 1-4 (as before, so the seeds keep
/// their curves), 7 also degree 4, the rest degree 1-3. Degree 4 on one piece
/// in 8 (was one in 4): the exact offset and convolution cusp isolation works
/// on polynomials of degree `6(n - 1)` and costs most at `n = 4`.
pub fn curve(u: &mut Unstructured) -> Result<Vec<Bezier<Rational>>> {
    let pieces: u8 = u.int_in_range(1..=2)?;
    let mut curve: Vec<Bezier<Rational>> = Vec::new();
    // 0: free, 1: starts at the previous end, 2: also ends at the first start
    let link: u8 = if pieces == 2 {
        u.int_in_range(0..=2)?
    } else {
        0
    };
    for i in 0..pieces {
        let degree: u8 = match u.int_in_range(0..=15u8)? {
            3 | 7 => 4,
            k => 1 + k % 3,
        };
        let mut pts = Vec::new();
        for k in 0..=degree {
            let p = if i == 1 && k == 0 && link >= 1 {
                let prev = curve[0].points();
                prev[prev.len() - 1].clone()
            } else if i == 1 && k == degree && link == 2 {
                curve[0].points()[0].clone()
            } else {
                point(u)?
            };
            pts.push(p);
        }
        curve.push(Bezier::new(pts));
    }
    Ok(curve)
}

/// One of [`TOLS`] as a [`Tolerance`]. The absurd floats (0, -1, NaN, inf)
/// are refused where the tolerance is made, with an error naming `tol` (checked
/// here); the input is then rejected. The others (1e-300 and 1e9 included)
/// make a tolerance equal to the float.
pub fn tol(u: &mut Unstructured) -> Result<Tolerance> {
    let x = TOLS[usize::from(u.int_in_range(0..=(TOLS.len() - 1) as u8)?)];
    match Tolerance::from_f64(x) {
        Ok(t) => {
            assert!(x.is_normal() && x > 0.0, "tolerance {x} accepted");
            assert_eq!(t.value(), x, "the tolerance of a float is that float");
            Ok(t)
        }
        Err(e) => {
            assert!(!(x.is_normal() && x > 0.0), "tolerance {x} refused: {e}");
            assert!(e.field == "tol" && !e.reason.is_empty(), "{e:?}");
            Err(libfuzzer_sys::arbitrary::Error::IncorrectFormat)
        }
    }
}

/// The subdivision rule (a), (b) or (c) of seed 000 §5 for LN pairs, small
/// budgets so an input costs a few ms, and `paper_error` off (it runs a
/// search with the default 200 000 boxes).
pub fn budgets(u: &mut Unstructured, opts: &mut OffsetOptions) -> Result<()> {
    if opts.method == OffsetMethod::LnPair {
        opts.subdivision = [
            Subdivision::MidAngle,
            Subdivision::Chord,
            Subdivision::Weighted,
        ][usize::from(u.int_in_range(0..=2u8)?)];
    }
    opts.max_depth = u.int_in_range(0..=3u8)?.into();
    opts.max_segments = u.int_in_range(1..=8u8)?.into();
    opts.max_boxes = u.int_in_range(8..=64u8)?.into();
    opts.paper_error = false;
    Ok(())
}

pub fn f(r: &Rational) -> f64 {
    r.approx()
}

pub fn fp(p: &V2<Rational>) -> (f64, f64) {
    (f(&p.x), f(&p.y))
}

pub fn dist(a: (f64, f64), b: (f64, f64)) -> f64 {
    (a.0 - b.0).hypot(a.1 - b.1)
}

fn cross(o: (f64, f64), a: (f64, f64), b: (f64, f64)) -> f64 {
    (a.0 - o.0) * (b.1 - o.1) - (a.1 - o.1) * (b.0 - o.0)
}

fn seg_dist(p: (f64, f64), a: (f64, f64), b: (f64, f64)) -> f64 {
    let (vx, vy) = (b.0 - a.0, b.1 - a.1);
    let l2 = vx * vx + vy * vy;
    if l2 == 0.0 {
        return dist(p, a);
    }
    let s = (((p.0 - a.0) * vx + (p.1 - a.1) * vy) / l2).clamp(0.0, 1.0);
    dist(p, (a.0 + s * vx, a.1 + s * vy))
}

/// Distance from `p` to the convex hull of `pts` (Andrew's monotone chain).
fn dist_to_hull(p: (f64, f64), pts: &[(f64, f64)]) -> f64 {
    let mut v = pts.to_vec();
    v.sort_by(|a, b| a.0.total_cmp(&b.0).then(a.1.total_cmp(&b.1)));
    v.dedup();
    if v.len() == 1 {
        return dist(p, v[0]);
    }
    let mut hull: Vec<(f64, f64)> = Vec::new();
    for pass in 0..2 {
        let start = hull.len();
        let it: Box<dyn Iterator<Item = &(f64, f64)>> = if pass == 0 {
            Box::new(v.iter())
        } else {
            Box::new(v.iter().rev())
        };
        for &q in it {
            while hull.len() >= start + 2
                && cross(hull[hull.len() - 2], hull[hull.len() - 1], q) <= 0.0
            {
                hull.pop();
            }
            hull.push(q);
        }
        hull.pop();
    }
    // counter-clockwise; 2 points for a collinear set
    let n = hull.len();
    let edges = (0..n).map(|i| (hull[i], hull[(i + 1) % n]));
    if n >= 3 && edges.clone().all(|(a, b)| cross(a, b, p) >= 0.0) {
        return 0.0;
    }
    edges
        .map(|(a, b)| seg_dist(p, a, b))
        .fold(f64::INFINITY, f64::min)
}

/// The largest coordinate (in absolute value) of the curve's control points.
pub fn in_scale(curve: &[Bezier<Rational>]) -> f64 {
    curve
        .iter()
        .flat_map(|b| b.points().iter())
        .map(|p| f(&p.x).abs().max(f(&p.y).abs()))
        .fold(0.0, f64::max)
}

/// A segment of degree 1: the placeholder of a span without a construction.
pub fn placeholder(s: &OffsetSegment) -> bool {
    s.bezier.degree() == 1
}

fn check_segment_bounds(i: usize, s: &OffsetSegment) {
    let (lo, hi) = s.error;
    assert!(
        !lo.is_nan() && !hi.is_nan() && lo >= 0.0 && lo <= hi,
        "segment {i}: bad bounds [{lo}, {hi}]"
    );
}

/// Bounds, `certified_hi`, `unreached` and `reached()` against `bound` (the
/// tolerance the segments must meet, named `bound_what` in the message), the
/// segments' order and tiling of every piece's `[0, 1]`, and the counts.
pub fn check_spans(
    curve: &[Bezier<Rational>],
    opts: &OffsetOptions,
    r: &OffsetResult,
    bound: f64,
    bound_what: &str,
) {
    let segs = &r.segments;
    let n = segs.len();
    assert!(n >= curve.len(), "{n} segments for {} pieces", curve.len());

    // bounds, certified_hi, unreached, reached()
    for (i, s) in segs.iter().enumerate() {
        check_segment_bounds(i, s);
    }
    let max_hi = segs.iter().map(|s| s.error.1).fold(0.0, f64::max);
    assert!(
        r.certified_hi == max_hi,
        "certified_hi {} is not the max {max_hi} of the segments' bounds",
        r.certified_hi
    );
    let over: Vec<usize> = (0..n).filter(|&i| segs[i].error.1 > bound).collect();
    assert_eq!(
        r.unreached, over,
        "unreached != segments with hi > {bound_what}"
    );
    assert_eq!(r.reached(), segs.iter().all(|s| s.error.1 <= bound));
    assert_eq!(r.reached(), r.certified_hi <= bound);

    // order and tiling of every piece's [0, 1]
    for (i, s) in segs.iter().enumerate() {
        assert!(
            s.piece < curve.len(),
            "segment {i}: piece {} out of range",
            s.piece
        );
        assert!(
            0.0 <= s.t.0 && s.t.0 < s.t.1 && s.t.1 <= 1.0,
            "segment {i}: bad span {:?}",
            s.t
        );
        let first_of_piece = i == 0 || segs[i - 1].piece != s.piece;
        if first_of_piece {
            let want = if i == 0 { 0 } else { segs[i - 1].piece + 1 };
            assert_eq!(
                s.piece, want,
                "segment {i}: a piece is skipped or out of order"
            );
            assert!(
                s.t.0 == 0.0,
                "segment {i}: first span of piece {} starts at {}",
                s.piece,
                s.t.0
            );
        } else {
            assert!(
                segs[i - 1].t.1 == s.t.0,
                "segment {i}: gap or overlap, {:?} then {:?}",
                segs[i - 1].t,
                s.t
            );
        }
        if i + 1 == n || segs[i + 1].piece != s.piece {
            assert!(
                s.t.1 == 1.0,
                "segment {i}: last span of piece {} ends at {}",
                s.piece,
                s.t.1
            );
        }
    }
    assert_eq!(
        segs[n - 1].piece,
        curve.len() - 1,
        "the last piece has no segment"
    );

    // counts: N = S + splits, C = S + 2 splits
    let c = r.spans;
    assert!(
        c >= n && c <= 2 * n,
        "spans {c} inconsistent with {n} segments"
    );
    assert!(
        r.certifications <= c,
        "{} certified searches for {c} spans",
        r.certifications
    );
    let s0 = 2 * n - c;
    let m = opts.max_segments;
    assert!(
        s0 >= curve.len(),
        "{s0} initial spans for {} pieces (N = {n}, C = {c})",
        curve.len()
    );
    assert!(
        n <= s0 << opts.max_depth,
        "{n} segments from {s0} initial spans at max_depth {}",
        opts.max_depth
    );
    let cap = s0.max(m);
    assert!(
        n <= cap,
        "{n} segments > {cap} (max_segments {m}, {s0} initial spans, C = {c})"
    );
}

/// Degrees: a placeholder is an unreached `(0, inf)`; every other segment
/// has degree `n + 3` (G2, `n` the piece's degree) or 3 (LN pair), else the
/// message `segment {i}: {what}`; `degree()` is the largest segment degree.
pub fn check_degrees(
    curve: &[Bezier<Rational>],
    opts: &OffsetOptions,
    r: &OffsetResult,
    what: &str,
) {
    let segs = &r.segments;
    for (i, s) in segs.iter().enumerate() {
        if placeholder(s) {
            assert!(
                s.error.0 == 0.0 && s.error.1 == f64::INFINITY && r.unreached.contains(&i),
                "segment {i}: degree 1 but not an unreached placeholder: {:?}",
                s.error
            );
        } else {
            let want = match opts.method {
                OffsetMethod::G2 => curve[s.piece].degree() + 3,
                OffsetMethod::LnPair => 3,
            };
            assert_eq!(s.bezier.degree(), want, "segment {i}: {what}");
        }
    }
    assert_eq!(
        r.degree(),
        segs.iter().map(|s| s.bezier.degree()).max().unwrap_or(0)
    );
}

/// Consecutive constructed segments of one piece share their joint control
/// point exactly, and `control_points()` counts accordingly.
pub fn check_joints(r: &OffsetResult) {
    let segs = &r.segments;
    let n = segs.len();
    let sum_deg: usize = segs.iter().map(|s| s.bezier.degree()).sum();
    let mut unshared = 0;
    for i in 1..n {
        let (a, b) = (&segs[i - 1], &segs[i]);
        if a.piece == b.piece && !placeholder(a) && !placeholder(b) {
            let pa = a.bezier.points();
            assert!(
                pa[pa.len() - 1] == b.bezier.points()[0],
                "segments {} and {i} of piece {} do not share the joint at t = {}: {:?} vs {:?}",
                i - 1,
                a.piece,
                a.t.1,
                pa[pa.len() - 1],
                b.bezier.points()[0]
            );
        } else {
            unshared += 1;
        }
    }
    let cp = r.control_points();
    assert!(
        sum_deg < cp && cp <= sum_deg + 1 + unshared && cp <= sum_deg + n,
        "control_points {cp}: sum of degrees {sum_deg}, {n} segments, {unshared} joints not shared"
    );
}

/// Pinning and soundness spot checks of every constructed segment against
/// `exact(x, t)`, the `what` point (offset or convolution) of piece `x` at
/// `t`: the ends pinned within `1e-9 (1 + scale)`, `hi` at least the distance
/// of three exact points to the approximant's hull, `lo` at most the hull
/// upper bound of `d_H` (`reach`: how far the exact curve gets from the
/// piece's control points).
pub fn check_pinning(
    curve: &[Bezier<Rational>],
    r: &OffsetResult,
    reach: f64,
    what: &str,
    exact: impl Fn(&Bezier<Rational>, f64) -> (f64, f64),
) {
    let in_scale = in_scale(curve);
    for (i, s) in r.segments.iter().enumerate() {
        if placeholder(s) {
            continue;
        }
        let x = &curve[s.piece];
        let b: Vec<(f64, f64)> = s.bezier.points().iter().map(|p| (p.x, p.y)).collect();
        assert!(
            b.iter().all(|p| p.0.is_finite() && p.1.is_finite()),
            "segment {i}: control point not finite"
        );
        let b_scale = b
            .iter()
            .map(|p| p.0.abs().max(p.1.abs()))
            .fold(0.0, f64::max);
        let eps = 1e-9 * (1.0 + in_scale + reach + b_scale);
        let (t0, t1) = s.t;
        let p0 = exact(x, t0);
        let p1 = exact(x, t1);
        let pm = exact(x, 0.5 * (t0 + t1));
        let (b0, b1) = (b[0], b[b.len() - 1]);
        assert!(
            dist(p0, b0) <= eps && dist(p1, b1) <= eps,
            "segment {i}: ends {b0:?}, {b1:?} not pinned to the {what} points {p0:?}, {p1:?}"
        );
        let (lo, hi) = s.error;
        for (t, p) in [(t0, p0), (0.5 * (t0 + t1), pm), (t1, p1)] {
            let g = dist_to_hull(p, &b);
            assert!(
                g <= hi + eps,
                "segment {i} {:?}: certified hi {hi} below the distance {g} of the {what} point at t = {t} to the approximant's hull",
                s.t
            );
        }
        let hb = b.iter().map(|&q| dist(q, p0)).fold(0.0, f64::max);
        let ha = x
            .points()
            .iter()
            .map(|q| dist(fp(q), b0))
            .fold(0.0, f64::max)
            + reach;
        let up = hb.max(ha);
        assert!(
            lo <= up + eps,
            "segment {i} {:?}: certified lo {lo} above the hull upper bound {up} of d_H",
            s.t
        );
    }
}
