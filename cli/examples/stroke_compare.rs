//! Stroke outlines for a circular pen: lncert's proven `stroke` against kurbo
//! 0.13's stroker (`kurbo::stroke`, round caps and joins), with kurbo's output
//! **measured** by lncert's certified engines (issue 13, closed outlines).
//!
//! ```sh
//! cargo run --release --example stroke_compare            # TOL 1e-1, 1e-2, 1e-3
//! cargo run --release --example stroke_compare -- --quick # TOL 1e-1, 1e-2
//! cargo run --release --example stroke_compare -- --only pawn # curves whose name contains `pawn`
//! ```
//!
//! Cases: every curve of `data/offset_test_curves.json` (B-splines split
//! exactly into Bézier pieces; the unit circle has no control points there and
//! is skipped) with each distinct `|d|` of its listed offsets as pen radius
//! (`cubic_bezier` is the test cubic `[[-0.95, 0.7], [-0.3, 0.5], [0.3, -2.5],
//! [0.9, -0.2]]`, so r = 0.4 covers it), plus the closed lens B-spline of
//! `lncert reproduce` (`stroke-closed-lens-inner-loops`) at r = 1/4.
//!
//! Columns:
//!
//! * **lncert native / cubic**: `stroke` with `Output::Native` (degree n + 3
//!   offset segments) / `Output::Cubic` (fitted cubics), round caps:
//!   output pieces, control points (degree per Bézier piece, 2 per exact arc —
//!   end point and centre —, 1 per contour), raw crossings found and cut,
//!   wall time (construction + all proofs), and which of the claims (a) (b) (c)
//!   are proven (`abc` = all; `-` marks an unproven one).
//! * **kurbo**: `kurbo::stroke(path, Stroke::new(2r), StrokeOpts::default(), TOL)`
//!   (round caps and joins; a closed input ends with `ClosePath`): segments,
//!   control points (1 per line, 2 per quad, 3 per cubic, 1 per subpath), its
//!   time (µs).
//! * **kurbo loops**: the certified self-crossings of kurbo's output
//!   (`lncert::stroke::intersections` on its segments read exactly,
//!   all pairs and self-intersections, zero-length segments dropped): proven
//!   crossings `+` segment pairs with an undecided part, with the solver's
//!   reasons (`joint`: consecutive segments leaving a shared point in one
//!   direction, e.g. kurbo's back-and-forth inner joins; `singular`: a zero
//!   derivative; `tangential`; `budget`) — never counted as crossings.
//! * **kurbo → ∂S**, **∂S → kurbo**: certified bounds `[lo, hi]` of the two
//!   one-sided distances between kurbo's output `K` and the exact boundary `∂S`
//!   of `x ⊕ disk(r)`. With `L` an lncert outline (claims (a), (b) proven with
//!   bounds `a`, `b`) and the certified
//!   Hausdorff engine on `K` and `L`; `L` is, per case, the lncert outline of
//!   the run (native or cubic, any TOL) with (a), (b) proven and the smallest
//!   `max(a, b)` — printed on stderr:
//!   `h(K, L) − b ≤ h(K, ∂S) ≤ h(K, L) + a` and
//!   `h(L, K) − a ≤ h(∂S, K) ≤ h(L, K) + b` (triangle inequality; `h(X, Y) =
//!   sup_{x ∈ X} dist(x, Y)`). kurbo → ∂S is large when kurbo keeps loops or
//!   inner parts that are not on ∂S (kurbo's fill is right under the nonzero
//!   rule; the *path* is not the boundary). `✗` marks `lo > TOL` (proven
//!   above TOL; no row of the run in docs/comparisons.md has it), `✓` marks `hi ≤ TOL` for
//!   ∂S → kurbo (kurbo covers the boundary within its tolerance).

use kurbo::{BezPath, PathEl, Point};
use lncert::certify::{hausdorff, Config};
use lncert::curve::Bezier;
use lncert::kurbo_bridge::shape_from_path;
use lncert::offset::Output;
use lncert::scalar::{Rational, Scalar};
use lncert::shape::ShapeDesc;
use lncert::stroke::{intersections, IntersectOptions};
use lncert::stroke::{stroke, Stroke, StrokeOptions};
use lncert_cli::reproduce::strokes::{
    control_points, lens, lens_radius, outline_shape, test_cases,
};
use std::time::Instant;

const TOLS: [f64; 3] = [1e-1, 1e-2, 1e-3];

fn to_kurbo_path(curve: &[Bezier<Rational>]) -> BezPath {
    let pt = |v: &lncert::curve::V2<Rational>| Point::new(v.x.approx(), v.y.approx());
    let mut p = BezPath::new();
    p.move_to(pt(&curve[0].points()[0]));
    for b in curve {
        let mut b = b.clone();
        while b.degree() < 2 {
            b = b.elevate();
        }
        assert!(b.degree() <= 3, "kurbo takes pieces of degree ≤ 3");
        let q = b.points();
        if q.len() == 3 {
            p.quad_to(pt(&q[1]), pt(&q[2]));
        } else {
            p.curve_to(pt(&q[1]), pt(&q[2]), pt(&q[3]));
        }
    }
    if curve[0].points()[0] == *curve[curve.len() - 1].points().last().unwrap() {
        p.close_path();
    }
    p
}

fn kurbo_cp(path: &BezPath) -> usize {
    path.elements()
        .iter()
        .map(|e| match e {
            PathEl::MoveTo(_) => 1,
            PathEl::LineTo(_) => 1,
            PathEl::QuadTo(..) => 2,
            PathEl::CurveTo(..) => 3,
            PathEl::ClosePath => 0,
        })
        .sum()
}

fn claims(s: &Stroke) -> String {
    [(&s.a, 'a'), (&s.b, 'b'), (&s.c, 'c')]
        .iter()
        .map(|(c, n)| if c.proven { *n } else { '-' })
        .collect()
}

struct Lncert {
    cell: String,
    stroke: Option<Stroke>,
    secs: f64,
}

fn run_lncert(curve: &[Bezier<Rational>], r: &Rational, tol: f64, out: Output) -> Lncert {
    let mut o = StrokeOptions::new(r.clone(), lncert::Tolerance::from_f64(tol).unwrap());
    o.output = out;
    let t0 = Instant::now();
    let s = stroke(curve, &o);
    let secs = t0.elapsed().as_secs_f64();
    if let Ok(s) = &s {
        for (n, c) in [("a", &s.a), ("b", &s.b), ("c", &s.c)] {
            if !c.proven {
                eprintln!(
                    "  [{out:?} TOL {tol:e} r {}] ({n}) unproven: {}",
                    r.approx(),
                    c.note
                );
            }
        }
    }
    match s {
        Ok(s) => Lncert {
            cell: format!(
                "{} / {} / {} / {:.2} s / {}",
                s.pieces(),
                control_points(&s),
                s.crossings.len(),
                secs,
                claims(&s)
            ),
            stroke: Some(s),
            secs,
        },
        Err(e) => Lncert {
            cell: format!("error: {e}"),
            stroke: None,
            secs,
        },
    }
}

/// Certified self-crossings of kurbo's output: (proven crossings, undecided
/// piece pairs with their reasons, seconds).
fn kurbo_loops(k: &ShapeDesc) -> (usize, String, f64) {
    let ShapeDesc::Curve(pieces) = k else {
        return (0, String::new(), 0.0);
    };
    let pieces: Vec<Bezier<Rational>> = pieces
        .iter()
        .filter(|b| b.points().iter().any(|p| p != &b.points()[0]))
        .cloned()
        .collect();
    let t0 = Instant::now();
    let r = intersections(&pieces, &IntersectOptions::default());
    let secs = t0.elapsed().as_secs_f64();
    let mut pairs: Vec<((usize, usize), &str)> =
        r.undecided.iter().map(|u| (u.pieces, u.reason)).collect();
    pairs.sort();
    pairs.dedup();
    let mut reasons: Vec<&str> = pairs.iter().map(|p| p.1).collect();
    reasons.sort();
    reasons.dedup();
    let und = if pairs.is_empty() {
        "0".to_string()
    } else {
        format!("{} ({})", pairs.len(), reasons.join(", "))
    };
    (r.crossings.len(), und, secs)
}

/// `A ∪ B` as one union shape (members of a union are flattened).
fn union(a: &ShapeDesc, b: &ShapeDesc) -> ShapeDesc {
    let members = |s: &ShapeDesc| match s {
        ShapeDesc::Union(m) => m.clone(),
        other => vec![other.clone()],
    };
    let mut m = members(a);
    m.extend(members(b));
    ShapeDesc::union(m).expect("a union of checked shapes")
}

/// Certified `[lo, hi]` of the one-sided `h(A, B)`: `d_H(A ∪ B, B) = h(A, B)`
/// (every point of `B` is in `A ∪ B`), so the two-sided engine's stopping rule
/// applies to this direction alone.
fn one_sided(a: &ShapeDesc, b: &ShapeDesc) -> Result<(f64, f64, bool), String> {
    let cfg = Config {
        rel: 1e-2,
        max_boxes: 400_000,
        ..Config::default()
    };
    let h = hausdorff(&union(a, b), b, &cfg).map_err(|e| e.to_string())?;
    Ok((h.lo, h.hi, h.incomplete()))
}

fn interval(lo: f64, hi: f64) -> String {
    format!("[{:.2e}, {:.2e}]", lo.max(0.0), hi)
}

fn main() {
    let args: Vec<String> = std::env::args().collect();
    let quick = args.iter().any(|a| a == "--quick");
    let only = args
        .iter()
        .position(|a| a == "--only")
        .and_then(|i| args.get(i + 1).cloned());
    let tols: &[f64] = if quick { &TOLS[..2] } else { &TOLS[..] };
    let mut cases = match test_cases() {
        Ok(c) => c,
        Err(e) => {
            eprintln!("stroke_compare: {e}");
            std::process::exit(2);
        }
    };
    cases.push(("closed lens (reproduce)".into(), lens(), lens_radius()));
    if let Some(o) = &only {
        cases.retain(|c| c.0.contains(o.as_str()));
    }
    let start = Instant::now();
    let (mut t_lncert, mut n_lncert, mut crossings) = (0.0, 0, 0usize);
    let (mut t_kloops, mut kpairs) = (0.0, 0usize);
    println!(
        "| curve | r | TOL | lncert native: pieces / cp / crossings / time / claims | \
         lncert cubic: pieces / cp / crossings / time / claims | kurbo: segs / cp / time | \
         kurbo loops: crossings + undecided | kurbo → ∂S | ∂S → kurbo |"
    );
    println!("|---|---|---|---|---|---|---|---|---|");
    for (name, curve, r) in &cases {
        // every lncert stroke of the case first: the reference outline L is
        // the one with (a), (b) proven and the smallest max(bound_a, bound_b)
        let runs: Vec<(Lncert, Lncert)> = tols
            .iter()
            .map(|&tol| {
                (
                    run_lncert(curve, r, tol, Output::Native),
                    run_lncert(curve, r, tol, Output::Cubic),
                )
            })
            .collect();
        for (native, cubic) in &runs {
            for l in [native, cubic] {
                t_lncert += l.secs;
                n_lncert += 1;
                if let Some(s) = &l.stroke {
                    crossings += s.crossings.len();
                }
            }
        }
        let reference = runs
            .iter()
            .flat_map(|(n, c)| [n, c])
            .filter_map(|l| l.stroke.as_ref())
            .filter(|s| s.a.proven && s.b.proven)
            .min_by(|x, y| {
                x.a.bound
                    .max(x.b.bound)
                    .total_cmp(&y.a.bound.max(y.b.bound))
            });
        let ref_shape = reference.and_then(|s| outline_shape(s).ok());
        if let Some(s) = reference {
            eprintln!(
                "  {name} r {}: reference L with bounds a {:.2e}, b {:.2e}",
                r.approx(),
                s.a.bound,
                s.b.bound
            );
        }
        for (&tol, (native, cubic)) in tols.iter().zip(&runs) {
            let input = to_kurbo_path(curve);
            let w = 2.0 * r.approx();
            let t0 = Instant::now();
            let kp = kurbo::stroke(
                input,
                &kurbo::Stroke::new(w),
                &kurbo::StrokeOpts::default(),
                tol,
            );
            let kt = t0.elapsed().as_secs_f64() * 1e6;
            let segs = kp.segments().count();
            let kcp = kurbo_cp(&kp);
            let (kshape, loops) = match shape_from_path(&kp) {
                Err(e) => (None, format!("error: {e}")),
                Ok(k) => {
                    let (c, u, secs) = kurbo_loops(&k);
                    t_kloops += secs;
                    kpairs += segs * (segs + 1) / 2;
                    (Some(k), format!("{c} + {u}"))
                }
            };
            let dist_cells = match (&kshape, &ref_shape, reference) {
                (Some(k), Some(l), Some(s)) => {
                    let (a, b) = (s.a.bound, s.b.bound);
                    let inc = |i: bool| if i { " (budget)" } else { "" };
                    let to_s = match one_sided(k, l) {
                        Ok((lo, hi, i)) => format!("{}{}", interval(lo - b, hi + a), inc(i)),
                        Err(e) => format!("error: {e}"),
                    };
                    let from_s = match one_sided(l, k) {
                        Ok((lo, hi, i)) => format!(
                            "{}{}{}",
                            interval(lo - a, hi + b),
                            if hi + b <= tol {
                                " ✓"
                            } else if lo - a > tol {
                                " ✗"
                            } else {
                                ""
                            },
                            inc(i)
                        ),
                        Err(e) => format!("error: {e}"),
                    };
                    format!("{to_s} | {from_s}")
                }
                _ => "no proven reference | ".to_string(),
            };
            println!(
                "| {name} | {} | {tol:e} | {} | {} | {segs} / {kcp} / {kt:.0} µs | {loops} | {dist_cells} |",
                r.approx(),
                native.cell,
                cubic.cell
            );
        }
    }
    println!();
    println!(
        "lncert: {n_lncert} strokes in {t_lncert:.1} s ({:.2} s per trimmed outline), \
         {crossings} raw crossings cut in all ({} per crossing cut, stroke time / crossings); certifying kurbo's self-crossings: \
         {t_kloops:.2} s for {kpairs} segment pairs ({:.1} µs per pair). \
         Total {:.1} s.",
        t_lncert / n_lncert.max(1) as f64,
        if crossings == 0 {
            "n/a".to_string()
        } else {
            format!("{:.2} s", t_lncert / crossings as f64)
        },
        1e6 * t_kloops / kpairs.max(1) as f64,
        start.elapsed().as_secs_f64()
    );
}
