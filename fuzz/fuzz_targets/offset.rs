#![no_main]
//! Fuzz target `offset`: a small curve, distance, tolerance and budget built
//! from the input -> `lncert::offset::offset`, and the result's contract.
//!
//! Input: 1-2 Bézier pieces of degree 1-4 (coordinates `k/16`, `k` an `i8`);
//! the second piece is free, starts at the first's end point (a junction:
//! corners), or also ends at the first's start point (a closed curve). A
//! distance `num/den`, `num` in `-16..=16` (0 included), `den` in `1..=16`; a
//! tolerance from [`TOLS`] (with absurd values: 0, -1, NaN, inf, 1e-300, 1e9);
//! the method (G2 or LN pair); small budgets (`max_depth` 0..=3,
//! `max_segments` 1..=8, `max_boxes` 8..=64) so an input costs a few ms.
//! `paper_error` stays off (it runs a search with the default 200 000 boxes).
//!
//! Checks (exact consequences of the contract and of the driver in
//! src/approx/mod.rs; no sampled "expected" geometry):
//! * no panic; an `Err` is fine (the input is rejected) but names a non-empty
//!   field and reason, both in its `Display`;
//! * a tolerance that is not a finite number `>= 1e-11 (1 + scale)` (0, -1,
//!   NaN, inf, 1e-300) and a zero distance are errors;
//! * every segment has `0 <= lo <= hi` (no NaN); `certified_hi` is the max of
//!   the segments' `hi`; `unreached` is exactly the (sorted) indices of the
//!   segments with `hi > tol`; `reached()` iff every `hi <= tol`;
//! * segments are sorted by `(piece, t0)` and tile every piece's `[0, 1]`:
//!   the first starts at 0, the last ends at 1, `t0 < t1`, and consecutive
//!   spans share their end point exactly;
//! * counts: each task ends as one segment or two child tasks, so with `N`
//!   segments and `C = spans` (tasks tried), `S = 2N - C` is the number of initial
//!   spans; `pieces <= S <= N`, `N <= S 2^max_depth`, and
//!   `N <= max(S, max_segments)` (a span is split only when the segments
//!   done, the tasks queued and the outcomes still pending in the round leave
//!   room for both halves);
//! * a segment of degree 1 is the placeholder of a span without a
//!   construction: error `(0, inf)`, listed as unreached; every other segment
//!   has degree `n + 3` (G2, `n` the piece's degree) or 3 (LN pair);
//!   `degree()` is the largest segment degree;
//! * consecutive constructed segments of one piece share their joint control
//!   point exactly (both ends are pinned to `x(t) + d N(t)` with the canonical
//!   float normal), and `sum deg + 1 <= control_points() <= sum deg + 1 +
//!   #joints that need not be shared <= sum (deg + 1)`;
//! * pinning: a constructed segment's first and last control points are within
//!   `1e-9 (1 + scale)` of `x(t0) + d N(t0)` and `x(t1) + d N(t1)`, computed
//!   here in f64 from the exact piece (the contract's weaker form, `<= hi +
//!   slack`, is implied);
//! * soundness of `hi`, exact up to float slack: the offset points
//!   `P(t) = x(t) + d N(t)`, `t` in `{t0, (t0 + t1)/2, t1}`, lie on the exact
//!   offset of the span and the approximant lies in the convex hull of its
//!   control points, so `hi >= dist(P(t), hull)`;
//! * soundness of `lo`: `d_H <= max(max_j |B_j - P(t0)|, max_i |X_i - B_0| +
//!   |d|)` (B in the hull of its control points, the offset within `|d|` of the
//!   hull of the piece's control points `X_i`), so `lo` is at most that;
//! * `corners` are at junctions where the pieces meet (`after` in range,
//!   centre = the shared point) and equal `lncert::offset::corners`;
//!   `join_arcs` has one arc of radius `|d|` per `Join` corner; cusps lie on
//!   existing pieces with `lo <= hi` in `[0, 1]`;
//! * with one more input byte: the grid path (`check_grid`).

use libfuzzer_sys::arbitrary::{Result, Unstructured};
use libfuzzer_sys::{fuzz_target, Corpus};
use lncert::offset::offset_on_grid;
use lncert::offset::kernels::Subdivision;
use lncert::offset::kernels::Junction;
use lncert::offset::{
    corners, join_arcs, offset, OffsetError, OffsetMethod, OffsetOptions, OffsetResult,
    OffsetSegment,
};
use lncert::curve::{Bezier, V2};
use lncert::scalar::{frac, rational_from_f64, Rational, Scalar};

/// Tolerances: absurd ones (must be errors, except the huge 1e9) and a few
/// reachable ones.
const TOLS: [f64; 10] = [
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

fn q(p: i64, den: i64) -> Rational {
    frac::<Rational>(p, den)
}

fn point(u: &mut Unstructured) -> Result<V2<Rational>> {
    let x: i8 = u.arbitrary()?;
    let y: i8 = u.arbitrary()?;
    Ok(V2::new(q(x.into(), 16), q(y.into(), 16)))
}

struct Input {
    curve: Vec<Bezier<Rational>>,
    opts: OffsetOptions,
    num: i8,
}

fn input(u: &mut Unstructured) -> Result<Input> {
    let pieces: u8 = u.int_in_range(1..=2)?;
    let mut curve: Vec<Bezier<Rational>> = Vec::new();
    // 0: free, 1: starts at the previous end, 2: also ends at the first start
    let link: u8 = if pieces == 2 {
        u.int_in_range(0..=2)?
    } else {
        0
    };
    for i in 0..pieces {
        let degree: u8 = u.int_in_range(1..=4)?;
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
    let num: i8 = u.int_in_range(-16..=16)?;
    let den: u8 = u.int_in_range(1..=16)?;
    let tol = TOLS[usize::from(u.int_in_range(0..=(TOLS.len() - 1) as u8)?)];
    let mut opts = OffsetOptions::new(q(num.into(), den.into()), tol);
    opts.method = if u.arbitrary::<bool>()? {
        OffsetMethod::LnPair
    } else {
        OffsetMethod::G2
    };
    if opts.method == OffsetMethod::LnPair {
        opts.subdivision = [Subdivision::MidAngle, Subdivision::Chord, Subdivision::Weighted]
            [usize::from(u.int_in_range(0..=2u8)?)];
    }
    opts.max_depth = u.int_in_range(0..=3u8)?.into();
    opts.max_segments = u.int_in_range(1..=8u8)?.into();
    opts.max_boxes = u.int_in_range(8..=64u8)?.into();
    opts.paper_error = false;
    Ok(Input { curve, opts, num })
}

fn f(r: &Rational) -> f64 {
    r.approx()
}

fn fp(p: &V2<Rational>) -> (f64, f64) {
    (f(&p.x), f(&p.y))
}

fn dist(a: (f64, f64), b: (f64, f64)) -> f64 {
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

/// `x(t) + d N(t)` in f64 from the exact piece (`N` the unit left normal of
/// the exact derivative rounded to floats, as the engine computes it).
fn offset_point(x: &Bezier<Rational>, t: f64, d: f64) -> (f64, f64) {
    let tr = rational_from_f64(t).expect("finite parameter");
    let p = fp(&x.eval(&tr));
    let (vx, vy) = fp(&x.hodograph().eval(&tr));
    let m = vx.abs().max(vy.abs());
    assert!(
        m > 0.0,
        "zero derivative at t = {t} on a piece the engine accepted"
    );
    let (vx, vy) = (vx / m, vy / m);
    let l = vx.hypot(vy);
    (p.0 + (-vy / l) * d, p.1 + (vx / l) * d)
}

fn check_error(e: &OffsetError, inp: &Input) {
    let shown = e.to_string();
    #[allow(unreachable_patterns)]
    let (field, reason) = match e {
        OffsetError::Input { field, reason } => (field.clone(), reason.clone()),
        _ => (shown.clone(), shown.clone()),
    };
    assert!(
        !field.is_empty()
            && !reason.is_empty()
            && shown.contains(field.as_str())
            && shown.contains(reason.as_str()),
        "error without a field or reason: {shown:?} ({e:?}) for tol {}",
        inp.opts.tol
    );
}

fn check_segment_bounds(i: usize, s: &OffsetSegment) {
    let (lo, hi) = s.error;
    assert!(
        !lo.is_nan() && !hi.is_nan() && lo >= 0.0 && lo <= hi,
        "segment {i}: bad bounds [{lo}, {hi}]"
    );
}

fn check_ok(inp: &Input, r: &OffsetResult) {
    let curve = &inp.curve;
    let opts = &inp.opts;
    let tol = opts.tol;
    let segs = &r.segments;
    let n = segs.len();
    let d = f(&opts.distance);
    assert!(r.tol == tol && r.distance == opts.distance && r.method == opts.method);
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
    let over: Vec<usize> = (0..n).filter(|&i| segs[i].error.1 > tol).collect();
    assert_eq!(
        r.unreached, over,
        "unreached != segments with hi > tol {tol}"
    );
    assert_eq!(r.reached(), segs.iter().all(|s| s.error.1 <= tol));
    assert_eq!(r.reached(), r.certified_hi <= tol);

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

    // degrees
    let placeholder = |s: &OffsetSegment| s.bezier.degree() == 1;
    for (i, s) in segs.iter().enumerate() {
        let want = match opts.method {
            OffsetMethod::G2 => curve[s.piece].degree() + 3,
            OffsetMethod::LnPair => 3,
        };
        if placeholder(s) {
            assert!(
                s.error.0 == 0.0 && s.error.1 == f64::INFINITY && r.unreached.contains(&i),
                "segment {i}: degree 1 but not an unreached placeholder: {:?}",
                s.error
            );
        } else {
            assert_eq!(
                s.bezier.degree(),
                want,
                "segment {i}: degree for {:?}",
                opts.method
            );
        }
        assert!(
            s.paper_error.is_none(),
            "segment {i}: paper_error without the option"
        );
    }
    assert_eq!(
        r.degree(),
        segs.iter().map(|s| s.bezier.degree()).max().unwrap_or(0)
    );

    // joints and control points
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

    // pinning and soundness spot checks
    let in_scale = curve
        .iter()
        .flat_map(|b| b.points().iter())
        .map(|p| f(&p.x).abs().max(f(&p.y).abs()))
        .fold(0.0, f64::max);
    for (i, s) in segs.iter().enumerate() {
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
        let eps = 1e-9 * (1.0 + in_scale + d.abs() + b_scale);
        let (t0, t1) = s.t;
        let p0 = offset_point(x, t0, d);
        let p1 = offset_point(x, t1, d);
        let pm = offset_point(x, 0.5 * (t0 + t1), d);
        let (b0, b1) = (b[0], b[b.len() - 1]);
        assert!(
            dist(p0, b0) <= eps && dist(p1, b1) <= eps,
            "segment {i}: ends {b0:?}, {b1:?} not pinned to the offset points {p0:?}, {p1:?}"
        );
        let (lo, hi) = s.error;
        for (t, p) in [(t0, p0), (0.5 * (t0 + t1), pm), (t1, p1)] {
            let g = dist_to_hull(p, &b);
            assert!(
                g <= hi + eps,
                "segment {i} {:?}: certified hi {hi} below the distance {g} of the offset point at t = {t} to the approximant's hull",
                s.t
            );
        }
        let hb = b.iter().map(|&q| dist(q, p0)).fold(0.0, f64::max);
        let ha = x
            .points()
            .iter()
            .map(|q| dist(fp(q), b0))
            .fold(0.0, f64::max)
            + d.abs();
        let up = hb.max(ha);
        assert!(
            lo <= up + eps,
            "segment {i} {:?}: certified lo {lo} above the hull upper bound {up} of d_H",
            s.t
        );
    }

    // corners, join arcs, cusps
    assert!(
        corners(curve, &opts.distance) == r.corners,
        "corners differ from approx::corners"
    );
    let np = curve.len();
    let mut joins = 0;
    for cnr in &r.corners {
        assert!(cnr.after < np, "corner after piece {} of {np}", cnr.after);
        let a = curve[cnr.after].points();
        let b = curve[(cnr.after + 1) % np].points();
        assert!(
            np >= 2 && a[a.len() - 1] == b[0],
            "corner {cnr:?} where the pieces do not meet"
        );
        match &cnr.kind {
            Junction::Join { center, .. } => {
                joins += 1;
                assert!(center == &b[0], "join centre is not the junction");
            }
            Junction::Overlap { center } => {
                assert!(center == &b[0], "overlap centre is not the junction")
            }
            k => panic!("corner of kind {k:?} reported"),
        }
    }
    let arcs = join_arcs(r);
    assert_eq!(arcs.len(), joins, "join_arcs count");
    let abs_d = if inp.num < 0 {
        -opts.distance.clone()
    } else {
        opts.distance.clone()
    };
    for a in &arcs {
        assert!(
            a.radius == abs_d,
            "join arc radius {} != |d| = {abs_d}",
            a.radius
        );
    }
    let (zero, one) = (q(0, 1), q(1, 1));
    for cu in &r.cusps {
        assert!(cu.piece < np, "cusp on piece {} of {np}", cu.piece);
        assert!(
            zero <= cu.t.0 && cu.t.0 <= cu.t.1 && cu.t.1 <= one,
            "cusp parameter interval [{}, {}] outside [0, 1]",
            cu.t.0,
            cu.t.1
        );
    }
}

/// The grid path ([`offset_on_grid`], cubics on the 1/16 grid the inputs
/// live on): no panic; an error names a field; every control point is a grid
/// multiple; contours close exactly; `unreached` is exactly the segments whose
/// `hi > tol`; a certificate exists iff every segment is proven, and it
/// verifies.
fn check_grid(inp: &Input) {
    let mut o = inp.opts.clone();
    o.output = lncert::offset::Output::Cubic;
    o.grid = Some(q(1, 16));
    let r = match offset_on_grid(&inp.curve, &o) {
        Err(e) => {
            check_error(&e, inp);
            return;
        }
        Ok(r) => r,
    };
    for s in &r.segments {
        for p in s.bezier.points() {
            assert!((p.x * 16.0).fract() == 0.0 && (p.y * 16.0).fract() == 0.0, "{p:?} off the grid");
        }
        assert!(s.error.0 <= s.error.1, "{:?}", s.error);
        assert_eq!(s.proof.is_some(), s.error.1 <= o.tol, "{:?}", s.error);
    }
    for &(first, n, closed) in &r.contours {
        let segs = &r.segments[first..first + n];
        for w in segs.windows(2) {
            assert_eq!(w[0].bezier.points()[3], w[1].bezier.points()[0]);
        }
        if closed && n > 0 {
            assert_eq!(segs[n - 1].bezier.points()[3], segs[0].bezier.points()[0]);
        }
    }
    let unreached: Vec<usize> = (0..r.segments.len())
        .filter(|&i| r.segments[i].proof.is_none())
        .collect();
    assert_eq!(unreached, r.unreached);
    assert_eq!(r.certificate.is_some(), r.reached() && !r.segments.is_empty());
    if let Some(c) = &r.certificate {
        let v = lncert::verify(&c.to_json_string());
        assert!(v.is_ok(), "grid certificate refused: {:?}", v.err());
    }
}

fuzz_target!(|data: &[u8]| -> Corpus {
    let mut u = Unstructured::new(data);
    let Ok(inp) = input(&mut u) else {
        return Corpus::Reject;
    };
    if u.arbitrary::<bool>().unwrap_or(false) {
        check_grid(&inp);
    }
    let tol = inp.opts.tol;
    let must_fail = !(tol.is_finite() && tol >= 1e-11) || inp.num == 0;
    match offset(&inp.curve, &inp.opts) {
        Err(e) => {
            check_error(&e, &inp);
            Corpus::Reject
        }
        Ok(r) => {
            assert!(
                !must_fail,
                "accepted tolerance {tol} / distance {} (must be errors)",
                inp.opts.distance
            );
            check_ok(&inp, &r);
            Corpus::Keep
        }
    }
});
