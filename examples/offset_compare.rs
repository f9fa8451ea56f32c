//! Peer comparison of offset approximations: lncert (G2 and LN-pair, both
//! certified by construction) against kurbo's `offset_cubic` (0.13), with every
//! error figure a **certified** Hausdorff bound against the exact offset.
//!
//! ```sh
//! cargo run --release --example offset_compare             # full run (several minutes)
//! cargo run --release --example offset_compare -- --quick  # TOL 1e-1..1e-3, first distance only
//! ```
//!
//! # What it measures
//!
//! For every curve of `data/offset_test_curves.json` (the plain cubic and, when
//! `lncert::curve::BSpline` is available, the B-spline test curves split exactly
//! into their Bézier pieces), every listed offset distance `d` and every
//! tolerance `TOL` in {1e-1, …, 1e-5}:
//!
//! * **lncert G2 / LN-pair** (`lncert::offset::offset`): control points (`degree ·
//!   segments + 1` per connected run), segments, wall time of `offset()` (rayon,
//!   2 cores on the reference machine), the proven per-segment bound
//!   `certified_hi` (`seg-hi`), and one global certified Hausdorff search of the
//!   exact offset of the whole input against the whole approximant (rel 1e-2),
//!   giving `[lo, hi]` (`hi` = the smaller of the global search's and `seg-hi`,
//!   both sound). `✓` means `certified_hi ≤ TOL` (the tolerance is proven).
//! * **kurbo** `kurbo::offset::offset_cubic(c, d, TOL, &mut path)` per cubic
//!   input piece (quadratic pieces are degree-elevated exactly first), outputs
//!   concatenated: control points (`3 · segments + 1` per connected run), segments,
//!   wall time of kurbo alone (averaged over repeated runs), and the certified
//!   Hausdorff bounds `[lo, hi]` of its output (control points read exactly as
//!   dyadic rationals) against the exact offset: `lo` (and a first `hi`) from
//!   one global search (rel 1e-2), a second `hi` piecewise, exactly as lncert
//!   certifies its own output: each kurbo segment against the exact offset of
//!   its source span (span ends recovered in f64 from the segment end points;
//!   consecutive spans share their exact end parameter so they cover the input,
//!   and `d_H(∪Aᵢ, ∪Bᵢ) ≤ maxᵢ d_H(Aᵢ, Bᵢ)`); `hi` is the smaller. When that
//!   does not decide `TOL`, both searches are repeated with the tolerance as
//!   goal. Verdict: `✓` within TOL (`hi ≤ TOL`), `EXCEEDS` (`lo > TOL`, proven),
//!   `?` undecided.
//!
//! A `†` after `[lo, hi]` marks a global search that stopped before its goal
//! (box at float resolution or budget): on swallowtail offsets the global
//! foot-point search can lock onto the wrong branch, so its `hi` stalls above
//! the truth; the bounds stay sound and the piecewise `hi` takes over.
//!   kurbo receives the f64 rounding of the exact input (≤ 1 ulp away, about
//!   1e-16, negligible against every TOL here).
//!
//! The exact offset is the untrimmed one, `x(t) + d N(t)` over every input piece
//! (swallowtails included); all three methods produce untrimmed offsets too.
//!
//! # Sign conventions
//!
//! lncert: `d > 0` is to the LEFT of the direction of travel, `N = rot90(T) =
//! (-Ty, Tx)`. kurbo 0.13 (`src/offset.rs`): the offset starts at `c.p0 + d *
//! utan0.turn_90()` with `Vec2::turn_90(v) = (-v.y, v.x)` — the same formula, so
//! kurbo's `d > 0` is also the left side in a y-up frame (kurbo's docs call
//! `turn_90` "clockwise in a Y-down coordinate system", i.e. the same rotation
//! drawn on screen). Both receive the same signed `d`; the program also checks
//! the first output point of kurbo against `p0 + d N` at run time.
//!
//! Cusps of kurbo's output are counted as joints where consecutive output
//! cubics' tangents reverse; loops as self-crossings of a polyline sampled
//! from the output (approximate, 12 samples per cubic — a float diagnostic,
//! not a certified figure).

use kurbo::{BezPath, CubicBez, ParamCurve, ParamCurveDeriv, PathSeg, Point};
use lncert::certify::{hausdorff, Config, HausdorffBounds};
use lncert::curve::{Bezier, V2};
use lncert::offset::{exact_bezier, offset, OffsetMethod, OffsetOptions, OffsetResult};
use lncert::scalar::{parse_rational, rational_from_f64, Rational, Scalar};
use lncert::shape::ShapeDesc;
use serde_json::Value;
use std::time::Instant;

const TOLS: [f64; 5] = [1e-1, 1e-2, 1e-3, 1e-4, 1e-5];
/// Box budget of the global Hausdorff searches (per direction).
const GLOBAL_MAX_BOXES: usize = 4_000_000;

struct TestCurve {
    name: String,
    pieces: Vec<Bezier<Rational>>,
    /// (text as listed, exact value)
    offsets: Vec<(String, Rational)>,
}

fn number(v: &Value) -> Result<Rational, String> {
    let text = match v {
        Value::Number(n) => n.to_string(),
        Value::String(s) => s.clone(),
        other => return Err(format!("not a number: {other}")),
    };
    parse_rational(&text).map_err(|e| format!("{text}: {e}"))
}

fn points(v: &Value) -> Result<Vec<V2<Rational>>, String> {
    v.as_array()
        .ok_or("control_points: not an array")?
        .iter()
        .map(|p| {
            let a = p.as_array().ok_or("control point: not an array")?;
            if a.len() != 2 {
                return Err("control point: not a pair".to_string());
            }
            Ok(V2::new(number(&a[0])?, number(&a[1])?))
        })
        .collect()
}

fn offsets(v: &Value) -> Result<Vec<(String, Rational)>, String> {
    v.get("offsets")
        .and_then(Value::as_array)
        .ok_or("offsets: missing")?
        .iter()
        .map(|x| Ok((x.to_string(), number(x)?)))
        .collect()
}

fn bspline_pieces(v: &Value) -> Result<Vec<Bezier<Rational>>, String> {
    use lncert::curve::BSpline;
    let degree = v
        .get("degree")
        .and_then(Value::as_u64)
        .ok_or("degree: missing")? as usize;
    let knots = v
        .get("knots")
        .and_then(Value::as_str)
        .ok_or("knots: missing")?;
    let pts = points(v.get("control_points").ok_or("control_points: missing")?)?;
    let s = if knots.contains("periodic") {
        BSpline::periodic_uniform(degree, pts)
    } else if knots.contains("clamped") || knots.contains("open") {
        BSpline::clamped_uniform(degree, pts)
    } else {
        return Err(format!("unknown knot description {knots:?}"));
    };
    Ok(s.map_err(|e| e.to_string())?.to_beziers())
}

fn load_curves() -> Result<(Vec<TestCurve>, Vec<String>), String> {
    let path = concat!(env!("CARGO_MANIFEST_DIR"), "/data/offset_test_curves.json");
    let text = std::fs::read_to_string(path).map_err(|e| format!("{path}: {e}"))?;
    let doc: Value = serde_json::from_str(&text).map_err(|e| format!("{path}: {e}"))?;
    let map = doc.as_object().ok_or("top level: not an object")?;
    let mut curves = Vec::new();
    let mut skipped = Vec::new();
    for (name, v) in map {
        if !v.is_object() {
            continue; // "source"
        }
        let pieces = if name == "cubic_bezier" {
            points(
                v.get("control_points")
                    .ok_or("cubic_bezier.control_points: missing")?,
            )
            .map(|p| vec![Bezier::new(p)])
        } else if name.ends_with("_bspline") {
            bspline_pieces(v)
        } else {
            skipped.push(format!(
                "`{name}`: no polynomial control points (an exact circle is not a Bézier curve)"
            ));
            continue;
        };
        match (pieces, offsets(v)) {
            (Ok(pieces), Ok(offsets)) => curves.push(TestCurve {
                name: name.clone(),
                pieces,
                offsets,
            }),
            (Err(e), _) | (_, Err(e)) => skipped.push(format!("`{name}`: {e}")),
        }
    }
    // the plain cubic first, then the file's order (serde_json without
    // preserve_order sorts keys; keep it deterministic)
    curves.sort_by_key(|c| (c.name != "cubic_bezier", c.name.clone()));
    Ok((curves, skipped))
}

#[derive(Clone, Copy, PartialEq)]
enum Verdict {
    Within,
    Exceeds,
    Undecided,
}

struct Cell {
    cp: usize,
    segs: usize,
    secs: f64,
    /// lncert only: the proven per-segment bound.
    seg_hi: Option<f64>,
    /// Certified `(lo, hi, global search stalled)`.
    global: Result<(f64, f64, bool), String>,
    verdict: Verdict,
    note: String,
    certifications: usize,
}

fn global_bounds(
    input: &[Bezier<Rational>],
    d: &Rational,
    approx: &[Bezier<f64>],
    tol: Option<f64>,
) -> Result<HausdorffBounds, String> {
    // The exact offset of each input piece split exactly into 8 sub-pieces (the
    // same point set): short pieces keep the certification's foot-point search
    // on the right branch where the offset folds over itself near cusps.
    let split: Vec<Bezier<Rational>> = input
        .iter()
        .flat_map(|x| {
            (0..8).map(move |k| {
                let q = |n: i64| Rational::new(n.into(), 8.into());
                x.restrict(&q(k), &q(k + 1))
            })
        })
        .collect();
    let a = ShapeDesc::offset(split, d.clone()).map_err(|e| e.to_string())?;
    let pieces = approx
        .iter()
        .map(exact_bezier)
        .collect::<Option<Vec<_>>>()
        .ok_or("non-finite control point in the approximant")?;
    let b = ShapeDesc::curve(pieces).map_err(|e| e.to_string())?;
    hausdorff(
        &a,
        &b,
        &Config {
            rel: 1e-2,
            max_boxes: GLOBAL_MAX_BOXES,
            tol: tol.map(|t| lncert::Tolerance::from_f64(t).expect("a positive tolerance")),
            ..Config::default()
        },
    )
    .map_err(|e| e.to_string())
}

fn verdict_of(lo: f64, hi: f64, tol: f64) -> Verdict {
    if hi <= tol {
        Verdict::Within
    } else if lo > tol {
        Verdict::Exceeds
    } else {
        Verdict::Undecided
    }
}

/// The offset point `x(t) + d N(t)` of a float curve (`N` the unit left normal).
fn offset_point_f64(x: &Bezier<f64>, h: &Bezier<f64>, d: f64, t: f64) -> Option<(f64, f64)> {
    let p = x.eval_fast(t);
    let v = h.eval_fast(t);
    let l = v.x.hypot(v.y);
    (l > 0.0).then(|| (p.x - d * v.y / l, p.y + d * v.x / l))
}

/// The source parameter `t ∈ [t_min, 1]` whose offset point is nearest `q`
/// (grid search, then golden-section refinement). Only affects tightness: the
/// spans built from these parameters cover the input exactly whatever they are.
fn recover_t(x: &Bezier<f64>, h: &Bezier<f64>, d: f64, q: Point, t_min: f64) -> f64 {
    let dist = |t: f64| {
        offset_point_f64(x, h, d, t).map_or(f64::INFINITY, |(a, b)| (a - q.x).hypot(b - q.y))
    };
    const GRID: usize = 4096;
    let mut best = (t_min, dist(t_min));
    for k in 1..=GRID {
        let t = t_min + (1.0 - t_min) * k as f64 / GRID as f64;
        let e = dist(t);
        if e < best.1 {
            best = (t, e);
        }
    }
    let h_step = (1.0 - t_min) / GRID as f64;
    let (mut a, mut b) = ((best.0 - h_step).max(t_min), (best.0 + h_step).min(1.0));
    let g = 0.5 * (5f64.sqrt() - 1.0);
    for _ in 0..80 {
        let (c, e) = (b - g * (b - a), a + g * (b - a));
        if dist(c) < dist(e) {
            b = e;
        } else {
            a = c;
        }
    }
    0.5 * (a + b)
}

/// Certified `d_H` bound of one span's exact offset against one approximant segment.
fn span_bound(
    piece: &Bezier<Rational>,
    d: &Rational,
    t: (f64, f64),
    seg: &Bezier<f64>,
    tol: Option<f64>,
) -> Result<f64, String> {
    let (Some(t0), Some(t1)) = (rational_from_f64(t.0), rational_from_f64(t.1)) else {
        return Err("non-finite span parameter".into());
    };
    if t0 >= t1 {
        return Err(format!("empty span [{}, {}]", t.0, t.1));
    }
    let span = piece.restrict(&t0, &t1);
    let a = ShapeDesc::offset(vec![span], d.clone()).map_err(|e| e.to_string())?;
    let b = ShapeDesc::curve(vec![exact_bezier(seg).ok_or("non-finite control point")?])
        .map_err(|e| e.to_string())?;
    let r = hausdorff(
        &a,
        &b,
        &Config {
            rel: 1e-2,
            max_boxes: 400_000,
            tol: tol.map(|t| lncert::Tolerance::from_f64(t).expect("a positive tolerance")),
            ..Config::default()
        },
    )
    .map_err(|e| e.to_string())?;
    Ok(r.hi)
}

/// Piecewise certified upper bound of kurbo's output: each output segment against
/// the exact offset of its source span (spans recovered from the segments' end
/// points, consecutive spans sharing their exact end parameter, so they cover
/// every input piece). `d_H(∪Aᵢ, ∪Bᵢ) ≤ maxᵢ d_H(Aᵢ, Bᵢ)` — the same argument as
/// lncert's own per-segment certification. Returns the max and the spans.
fn kurbo_piecewise_hi(
    tc: &TestCurve,
    d: &Rational,
    per_piece: &[Vec<Bezier<f64>>],
    tol: Option<f64>,
) -> Result<f64, String> {
    use rayon::prelude::*;
    let df = d.approx();
    let mut jobs: Vec<(usize, (f64, f64), Bezier<f64>)> = Vec::new();
    for (i, segs) in per_piece.iter().enumerate() {
        let x = tc.pieces[i].map(|v| v.approx());
        let h = x.hodograph();
        let mut t_prev = 0.0;
        for (k, seg) in segs.iter().enumerate() {
            let t_next = if k + 1 == segs.len() {
                1.0
            } else {
                let p = &seg.points()[seg.points().len() - 1];
                recover_t(&x, &h, df, Point::new(p.x, p.y), t_prev)
            };
            jobs.push((i, (t_prev, t_next), seg.clone()));
            t_prev = t_next;
        }
    }
    let his = jobs
        .par_iter()
        .map(|(i, t, seg)| span_bound(&tc.pieces[*i], d, *t, seg, tol))
        .collect::<Result<Vec<f64>, String>>()?;
    Ok(his.into_iter().fold(0.0, f64::max))
}

/// kurbo's output decided against `tol`: global search (rel 1e-2) for `lo` and a
/// first `hi`, the piecewise bound for a second `hi`; `hi = min` of the two. When
/// that leaves `tol` undecided, both searches are repeated with `tol` as the goal.
fn decide_kurbo(
    tc: &TestCurve,
    d: &Rational,
    per_piece: &[Vec<Bezier<f64>>],
    tol: f64,
) -> (Result<(f64, f64, bool), String>, Verdict) {
    let approx: Vec<Bezier<f64>> = per_piece.iter().flatten().cloned().collect();
    let g = match global_bounds(&tc.pieces, d, &approx, None) {
        Ok(g) => g,
        Err(e) => return (Err(e), Verdict::Undecided),
    };
    let stalled = g.incomplete();
    let pw = kurbo_piecewise_hi(tc, d, per_piece, None);
    let (mut lo, mut hi) = (g.lo, pw.as_ref().map_or(g.hi, |&p| p.min(g.hi)));
    if verdict_of(lo, hi, tol) == Verdict::Undecided {
        if let Ok(g2) = global_bounds(&tc.pieces, d, &approx, Some(tol)) {
            lo = lo.max(g2.lo);
            hi = hi.min(g2.hi);
        }
        if verdict_of(lo, hi, tol) == Verdict::Undecided {
            if let Ok(p2) = kurbo_piecewise_hi(tc, d, per_piece, Some(tol)) {
                hi = hi.min(p2);
            }
        }
    }
    (Ok((lo, hi, stalled)), verdict_of(lo, hi, tol))
}

fn run_lncert(
    tc: &TestCurve,
    d: &Rational,
    tol: f64,
    method: OffsetMethod,
) -> Result<Cell, String> {
    let mut opts = OffsetOptions::new(
        d.clone(),
        lncert::Tolerance::from_f64(tol).map_err(|e| e.to_string())?,
    );
    opts.method = method;
    let t0 = Instant::now();
    let r: OffsetResult = offset(&tc.pieces, &opts).map_err(|e| e.to_string())?;
    let secs = t0.elapsed().as_secs_f64();
    let approx: Vec<Bezier<f64>> = r.segments.iter().map(|s| s.bezier.clone()).collect();
    // lo from the global search; hi = min(global hi, proven per-segment bound)
    let global = global_bounds(&tc.pieces, d, &approx, None)
        .map(|g| (g.lo, g.hi.min(r.certified_hi), g.incomplete()));
    let verdict = if r.reached() && r.certified_hi <= tol {
        Verdict::Within
    } else if global.as_ref().is_ok_and(|b| b.0 > tol) {
        Verdict::Exceeds
    } else {
        Verdict::Undecided
    };
    let mut note = String::new();
    if !r.reached() {
        note.push_str(&format!(", {} unreached", r.unreached.len()));
    }
    Ok(Cell {
        cp: r.control_points(),
        segs: r.segments.len(),
        secs,
        seg_hi: Some(r.certified_hi),
        global,
        verdict,
        note,
        certifications: r.certifications,
    })
}

fn to_kurbo(b: &Bezier<Rational>) -> Result<CubicBez, String> {
    let mut b = b.clone();
    while b.degree() < 3 {
        b = b.elevate();
    }
    if b.degree() > 3 {
        return Err(format!(
            "degree {} piece: kurbo offsets cubics only",
            b.degree()
        ));
    }
    let p: Vec<Point> = b
        .points()
        .iter()
        .map(|v| Point::new(v.x.approx(), v.y.approx()))
        .collect();
    Ok(CubicBez::new(p[0], p[1], p[2], p[3]))
}

fn seg_to_bezier(s: PathSeg) -> Bezier<f64> {
    let v = |p: Point| V2::new(p.x, p.y);
    match s {
        PathSeg::Line(l) => Bezier::new(vec![v(l.p0), v(l.p1)]),
        PathSeg::Quad(q) => Bezier::new(vec![v(q.p0), v(q.p1), v(q.p2)]),
        PathSeg::Cubic(c) => Bezier::new(vec![v(c.p0), v(c.p1), v(c.p2), v(c.p3)]),
    }
}

/// Polyline self-crossings (approximate): proper crossings of non-adjacent edges.
fn polyline_crossings(segs: &[PathSeg]) -> usize {
    const SAMPLES: usize = 12;
    let mut pts: Vec<Point> = Vec::new();
    for s in segs {
        for i in 0..=SAMPLES {
            if i == 0 && !pts.is_empty() {
                continue;
            }
            pts.push(s.eval(i as f64 / SAMPLES as f64));
        }
    }
    let orient = |a: Point, b: Point, c: Point| (b - a).cross(c - a);
    let n = pts.len().saturating_sub(1);
    let mut count = 0;
    for i in 0..n {
        let (a, b) = (pts[i], pts[i + 1]);
        for j in i + 2..n {
            if i == 0 && j == n - 1 && pts[0].distance(pts[n]) < 1e-9 {
                continue; // closed curve: first and last edges are adjacent
            }
            let (c, d) = (pts[j], pts[j + 1]);
            let (o1, o2) = (orient(a, b, c), orient(a, b, d));
            let (o3, o4) = (orient(c, d, a), orient(c, d, b));
            if o1 * o2 < 0.0 && o3 * o4 < 0.0 {
                count += 1;
            }
        }
    }
    count
}

fn run_kurbo(tc: &TestCurve, d: &Rational, tol: f64) -> Result<Cell, String> {
    let cubics = tc
        .pieces
        .iter()
        .map(to_kurbo)
        .collect::<Result<Vec<_>, _>>()?;
    let df = d.approx();
    let run = |out: &mut Vec<BezPath>| {
        for (c, p) in cubics.iter().zip(out.iter_mut()) {
            kurbo::offset::offset_cubic(*c, df, tol, p);
        }
    };
    let mut paths = vec![BezPath::new(); cubics.len()];
    // warm-up + timing: repeat until ≥ 50 ms or 10 000 runs
    run(&mut paths);
    let t0 = Instant::now();
    let mut reps = 0u32;
    while reps < 10_000 && (reps < 3 || t0.elapsed().as_secs_f64() < 0.05) {
        run(&mut paths);
        reps += 1;
    }
    let secs = t0.elapsed().as_secs_f64() / reps as f64;

    // sign check: kurbo's first point vs p0 + d N (N the left normal)
    let c0 = cubics[0];
    let tan = c0.deriv().eval(0.0).to_vec2().normalize();
    let expect = c0.p0 + df * kurbo::Vec2::new(-tan.y, tan.x);
    let first = paths[0].segments().next().map(|s| s.start());
    let mut note = String::new();
    if first.is_none_or(|p| p.distance(expect) > 1e-9) {
        note.push_str(", SIGN MISMATCH");
    }

    let segs: Vec<PathSeg> = paths.iter().flat_map(|p| p.segments()).collect();
    if segs.is_empty() {
        return Err("kurbo produced no segments".into());
    }
    // control points: 3·segments + 1 per connected run (gap > 1e-9 starts a run)
    let mut cp = 0;
    let mut cusps = 0;
    for (i, s) in segs.iter().enumerate() {
        let bz = seg_to_bezier(*s);
        cp += bz.degree();
        if i == 0 || segs[i - 1].end().distance(s.start()) > 1e-9 {
            cp += 1;
        } else {
            // tangent reversal at a joint: a cusp of the output
            let t_in = end_tangent(&segs[i - 1]);
            let t_out = start_tangent(s);
            if t_in.dot(t_out) < 0.0 {
                cusps += 1;
            }
        }
    }
    let loops = polyline_crossings(&segs);
    note.push_str(&format!(", {cusps} cusps, {loops} crossings"));
    let per_piece: Vec<Vec<Bezier<f64>>> = paths
        .iter()
        .map(|p| p.segments().map(seg_to_bezier).collect())
        .collect();
    let (global, verdict) = decide_kurbo(tc, d, &per_piece, tol);
    Ok(Cell {
        cp,
        segs: segs.len(),
        secs,
        seg_hi: None,
        global,
        verdict,
        note,
        certifications: 0,
    })
}

fn start_tangent(s: &PathSeg) -> kurbo::Vec2 {
    let b = seg_to_bezier(*s);
    let p = b.points();
    let p0 = Point::new(p[0].x, p[0].y);
    // first control point distinct from the start
    p.iter()
        .skip(1)
        .map(|q| Point::new(q.x, q.y) - p0)
        .find(|v| v.hypot() > 0.0)
        .unwrap_or_default()
}

fn end_tangent(s: &PathSeg) -> kurbo::Vec2 {
    let b = seg_to_bezier(*s);
    let p = b.points();
    let pn = Point::new(p[p.len() - 1].x, p[p.len() - 1].y);
    p.iter()
        .rev()
        .skip(1)
        .map(|q| pn - Point::new(q.x, q.y))
        .find(|v| v.hypot() > 0.0)
        .unwrap_or_default()
}

fn fmt_time(s: f64) -> String {
    if s >= 1.0 {
        format!("{s:.2} s")
    } else if s >= 1e-3 {
        format!("{:.1} ms", s * 1e3)
    } else {
        format!("{:.1} µs", s * 1e6)
    }
}

fn fmt_cell(c: &Result<Cell, String>) -> String {
    match c {
        Err(e) => format!("error: {}", e.replace('|', "/")),
        Ok(c) => {
            let v = match c.verdict {
                Verdict::Within => "✓",
                Verdict::Exceeds => "**EXCEEDS**",
                Verdict::Undecided => "?",
            };
            let g = match &c.global {
                Ok((lo, hi, stalled)) => format!(
                    "[{:.2e}, {:.2e}]{}",
                    lo,
                    hi,
                    if *stalled { "†" } else { "" }
                ),
                Err(e) => format!("global error: {}", e.replace('|', "/")),
            };
            let seg = c
                .seg_hi
                .map(|h| format!(" seg-hi {h:.2e}"))
                .unwrap_or_default();
            format!(
                "{} cp / {} seg, {}, {}{} {}{}",
                c.cp,
                c.segs,
                fmt_time(c.secs),
                g,
                seg,
                v,
                c.note
            )
        }
    }
}

fn main() {
    let quick = std::env::args().any(|a| a == "--quick");
    let start = Instant::now();
    let (curves, skipped) = match load_curves() {
        Ok(x) => x,
        Err(e) => {
            eprintln!("offset_compare: {e}");
            std::process::exit(2);
        }
    };
    let tols: &[f64] = if quick { &TOLS[..3] } else { &TOLS };
    println!(
        "# Certified offset comparison: lncert G2 / lncert LN-pair / kurbo 0.13 offset_cubic\n"
    );
    println!(
        "Cells: control points / segments, wall time, certified global Hausdorff [lo, hi] vs the exact offset \
         (rel 1e-2; hi = min of the global and the piecewise bound, † = global search stalled){}. lncert: `seg-hi` = proven per-segment bound (`certified_hi`); ✓ = proven ≤ TOL. \
         kurbo: ✓ hi ≤ TOL, **EXCEEDS** lo > TOL (proven), ? undecided; cusps = tangent reversals at joints, \
         crossings = approximate polyline self-crossings. d > 0 = left of travel for both libraries.\n",
        if quick { "; --quick" } else { "" }
    );
    for s in &skipped {
        println!("Skipped {s}.");
    }
    if !skipped.is_empty() {
        println!();
    }

    let (mut kurbo_cases, mut kurbo_exceeds, mut kurbo_undecided, mut kurbo_errors) = (0, 0, 0, 0);
    let mut ln_stats = [(0.0f64, 0usize, 0usize, 0usize), (0.0, 0, 0, 0)]; // time, certs, cases, proven
    let mut exceed_list = Vec::new();
    for tc in &curves {
        let dists: &[(String, Rational)] = if quick {
            &tc.offsets[..1.min(tc.offsets.len())]
        } else {
            &tc.offsets
        };
        for (dtext, d) in dists {
            println!(
                "## `{}` ({} piece{}, degree {}), d = {}\n",
                tc.name,
                tc.pieces.len(),
                if tc.pieces.len() == 1 { "" } else { "s" },
                tc.pieces.iter().map(|p| p.degree()).max().unwrap_or(0),
                dtext
            );
            println!("| TOL | lncert G2 | lncert LN-pair | kurbo offset_cubic |");
            println!("|---|---|---|---|");
            let mut exact_cusps: Option<usize> = None;
            for &tol in tols {
                let mut cells = Vec::new();
                for (k, m) in [OffsetMethod::G2, OffsetMethod::LnPair]
                    .into_iter()
                    .enumerate()
                {
                    let c = run_lncert(tc, d, tol, m);
                    if let Ok(c) = &c {
                        ln_stats[k].0 += c.secs;
                        ln_stats[k].1 += c.certifications;
                        ln_stats[k].2 += 1;
                        if c.verdict == Verdict::Within {
                            ln_stats[k].3 += 1;
                        }
                    }
                    cells.push(c);
                }
                if exact_cusps.is_none() {
                    // cusps of the exact offset (lncert prep: radius of curvature = |d|)
                    exact_cusps = Some(
                        tc.pieces
                            .iter()
                            .enumerate()
                            .map(|(i, x)| lncert::offset::kernels::offset_cusps(i, x, d).len())
                            .sum(),
                    );
                }
                let k = run_kurbo(tc, d, tol);
                kurbo_cases += 1;
                match &k {
                    Ok(c) => match c.verdict {
                        Verdict::Exceeds => {
                            kurbo_exceeds += 1;
                            let lo = c.global.as_ref().map(|b| b.0).unwrap_or(f64::NAN);
                            exceed_list.push(format!(
                                "{} d={} TOL={:e} (lo = {:.2e} = {:.3}×TOL)",
                                tc.name,
                                dtext,
                                tol,
                                lo,
                                lo / tol
                            ));
                        }
                        Verdict::Undecided => kurbo_undecided += 1,
                        Verdict::Within => {}
                    },
                    Err(_) => kurbo_errors += 1,
                }
                cells.push(k);
                println!(
                    "| {:e} | {} | {} | {} |",
                    tol,
                    fmt_cell(&cells[0]),
                    fmt_cell(&cells[1]),
                    fmt_cell(&cells[2])
                );
            }
            match exact_cusps {
                Some(n) => println!(
                    "\nExact offset: {n} cusp(s) (lncert prep, radius of curvature = |d|).\n"
                ),
                None => println!(),
            }
        }
    }
    println!("## Summary\n");
    println!(
        "kurbo exceeded its requested tolerance (proven, lo > TOL) in {kurbo_exceeds} of {kurbo_cases} \
         (curve, distance, TOL) cases; undecided {kurbo_undecided}; errors {kurbo_errors}."
    );
    for e in &exceed_list {
        println!("  - {e}");
    }
    for (k, name) in ["G2", "LN-pair"].iter().enumerate() {
        let (t, certs, cases, proven) = ln_stats[k];
        println!(
            "lncert {name}: {proven}/{cases} cases proven ≤ TOL; {} in offset() over {certs} certifications \
             = {} per certified segment (accepted and rejected).",
            fmt_time(t),
            if certs > 0 { fmt_time(t / certs as f64) } else { "n/a".into() }
        );
    }
    println!(
        "Total run time: {}.",
        fmt_time(start.elapsed().as_secs_f64())
    );
}
