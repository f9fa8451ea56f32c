//! Control points of the offset at a proven tolerance: lncert's fitted cubics
//! (`Output::Cubic`), lncert's native G² segments (degree `n + 3`) and kurbo
//! 0.13's `offset_cubic`, with kurbo's error **certified** against the exact
//! offset (issue 16, item 4; the table in docs/fitted-output.md).
//!
//! ```sh
//! cargo run --release --example offset_fit_compare            # TOL 1e-1 … 1e-5
//! cargo run --release --example offset_fit_compare -- --quick # TOL 1e-1 … 1e-3
//! cargo run --release --example offset_fit_compare -- --glyphs /usr/share/fonts/truetype/dejavu/DejaVuSans.ttf
//! ```
//!
//! With `--glyphs FONT`: the outlines of `a e g s R & @ 3 S O` (every contour,
//! font units), offset by ±20 units, at TOL 2 and 0.2 units.
//!
//! For every curve of `data/offset_test_curves.json` (the plain cubic and the
//! B-splines, split exactly into their Bézier pieces), every listed distance
//! (both sides) and every TOL:
//!
//! * **lncert cubic / native**: `offset()` with `Output::Cubic` / `Output::Native`
//!   (method G2): control points (`degree · segments + 1` per connected run);
//!   `!` marks a result whose tolerance was not proven (never expected).
//! * **kurbo**: `kurbo::offset::offset_cubic(piece, d, TOL)` per input piece
//!   (quadratic pieces degree-elevated exactly first), control points counted
//!   the same way over the concatenated output (a gap > 1e-9 starts a run).
//!   kurbo's claim is per call: the output of piece `i` is within `TOL` of the
//!   offset of piece `i`. Each call's output (read exactly) is certified against
//!   the **exact** offset of its exact input piece with
//!   `lncert::kurbo_bridge::shape_from_path` and a certified Hausdorff search
//!   (relative gap 1e-2, then with `TOL` as the goal when that does not decide):
//!   the column shows the largest certified `[lo, hi]` over the calls and the
//!   verdict, `✓` all within `TOL`, `EXCEEDS` some call proven above `TOL`
//!   (`lo > TOL`), `?` undecided.

use kurbo::{BezPath, CubicBez, ParamCurve, PathSeg, Point};
use lncert::certify::{hausdorff, Config};
use lncert::curve::Bezier;
use lncert::kurbo_bridge::shape_from_path;
use lncert::offset::{offset, OffsetOptions, Output};
use lncert::scalar::{Rational, Scalar};
use lncert::shape::ShapeDesc;
use rayon::prelude::*;
use std::time::Instant;

const TOLS: [f64; 5] = [1e-1, 1e-2, 1e-3, 1e-4, 1e-5];
const GLYPH_TOLS: [f64; 3] = [2.0, 0.2, 0.02];
const GLYPHS: &str = "aegsR&@3SO";

type Curves = Vec<(String, Vec<Bezier<Rational>>, Vec<Rational>)>;

/// The outlines of [`GLYPHS`] in a TrueType/OpenType font, offset by ±20 units.
fn glyph_curves(font: &str) -> Result<Curves, String> {
    let data = std::fs::read(font).map_err(|e| format!("{font}: {e}"))?;
    let d = Rational::from_integer(60.into());
    GLYPHS
        .chars()
        .map(|ch| {
            let pieces = lncert::shape::glyph_outline(&data, ch)
                .map_err(|e| format!("glyph {ch:?}: {e}"))?;
            Ok((format!("glyph '{ch}'"), pieces, vec![d.clone(), -d.clone()]))
        })
        .collect()
}

fn to_kurbo(b: &Bezier<Rational>) -> Option<CubicBez> {
    let mut b = b.clone();
    while b.degree() < 3 {
        b = b.elevate();
    }
    let p: Vec<Point> = b
        .points()
        .iter()
        .map(|v| Point::new(v.x.approx(), v.y.approx()))
        .collect();
    (p.len() == 4).then(|| CubicBez::new(p[0], p[1], p[2], p[3]))
}

fn kurbo_cp(paths: &[BezPath]) -> usize {
    let segs: Vec<PathSeg> = paths.iter().flat_map(|p| p.segments()).collect();
    let mut cp = 0;
    for (i, s) in segs.iter().enumerate() {
        cp += match s {
            PathSeg::Line(_) => 1,
            PathSeg::Quad(_) => 2,
            PathSeg::Cubic(_) => 3,
        };
        if i == 0 || segs[i - 1].end().distance(s.start()) > 1e-9 {
            cp += 1;
        }
    }
    cp
}

/// Certified `[lo, hi]` of one kurbo call's output against the exact offset of its piece.
fn certify_call(
    piece: &Bezier<Rational>,
    d: &Rational,
    path: &BezPath,
    tol: f64,
) -> Result<(f64, f64), String> {
    let a = ShapeDesc::offset(vec![piece.clone()], d.clone()).map_err(|e| e.to_string())?;
    let b = shape_from_path(path).map_err(|e| e.to_string())?;
    let run = |goal: Option<f64>| {
        hausdorff(
            &a,
            &b,
            &Config {
                rel: 1e-2,
                max_boxes: 2_000_000,
                tol: goal.map(|t| lncert::Tolerance::from_f64(t).expect("a positive goal")),
                ..Config::default()
            },
        )
        .map_err(|e| e.to_string())
    };
    let r = run(None)?;
    let (mut lo, mut hi) = (r.lo, r.hi);
    if lo <= tol && hi > tol {
        let r = run(Some(tol))?;
        lo = lo.max(r.lo);
        hi = hi.min(r.hi);
    }
    Ok((lo, hi))
}

fn main() {
    let args: Vec<String> = std::env::args().collect();
    let quick = args.iter().any(|a| a == "--quick");
    let glyph_font = args
        .iter()
        .position(|a| a == "--glyphs")
        .and_then(|i| args.get(i + 1));
    let (tols, curves): (&[f64], _) = match glyph_font {
        // glyph outlines in font units: TOL 2 and 0.2 (about 1e-3 and 1e-4 em
        // at 2048 units per em), offsets ±20 units
        Some(font) => (&GLYPH_TOLS[..], glyph_curves(font)),
        None => (
            if quick { &TOLS[..3] } else { &TOLS[..] },
            lncert_cli::reproduce::offsets::test_curves(),
        ),
    };
    let curves = match curves {
        Ok(c) => c,
        Err(e) => {
            eprintln!("offset_fit_compare: {e}");
            std::process::exit(2);
        }
    };
    let start = Instant::now();
    let (mut t_cubic, mut t_native, mut t_cert) = (0.0, 0.0, 0.0);
    let (mut cases, mut fewer_or_equal, mut kurbo_exceeds, mut kurbo_undecided) = (0, 0, 0, 0);
    println!("| curve | d | TOL | lncert cubic | lncert native (G2) | kurbo offset_cubic | kurbo certified error [lo, hi] |");
    println!("|---|---|---|---|---|---|---|");
    for (name, pieces, ds) in &curves {
        let Some(cubics) = pieces.iter().map(to_kurbo).collect::<Option<Vec<_>>>() else {
            println!("| {name} | | | skipped: a piece of degree > 3 |");
            continue;
        };
        for d in ds {
            for &tol in tols {
                let mut cells = Vec::new();
                for (out, t_acc) in [
                    (Output::Cubic, &mut t_cubic),
                    (Output::Native, &mut t_native),
                ] {
                    let mut o =
                        OffsetOptions::new(d.clone(), lncert::Tolerance::from_f64(tol).unwrap());
                    o.output = out;
                    let t0 = Instant::now();
                    let cell = match offset(pieces, &o) {
                        Ok(r) => {
                            let ok = r.reached() && r.certified_hi <= tol;
                            (r.control_points(), if ok { "" } else { "!" }.to_string())
                        }
                        Err(e) => (0, format!("error: {e}")),
                    };
                    *t_acc += t0.elapsed().as_secs_f64();
                    cells.push(cell);
                }
                let df = d.approx();
                let paths: Vec<BezPath> = cubics
                    .iter()
                    .map(|c| {
                        let mut p = BezPath::new();
                        kurbo::offset::offset_cubic(*c, df, tol, &mut p);
                        p
                    })
                    .collect();
                let kcp = kurbo_cp(&paths);
                let t0 = Instant::now();
                let certs: Vec<Result<(f64, f64), String>> = pieces
                    .par_iter()
                    .zip(paths.par_iter())
                    .map(|(x, p)| certify_call(x, d, p, tol))
                    .collect();
                t_cert += t0.elapsed().as_secs_f64();
                let kcell = match certs.iter().cloned().collect::<Result<Vec<_>, _>>() {
                    Err(e) => format!("error: {e}"),
                    Ok(v) => {
                        let lo = v.iter().map(|b| b.0).fold(0.0, f64::max);
                        let hi = v.iter().map(|b| b.1).fold(0.0, f64::max);
                        let verdict = if v.iter().any(|b| b.0 > tol) {
                            kurbo_exceeds += 1;
                            format!("**EXCEEDS** ({:.3}× TOL)", lo / tol)
                        } else if hi <= tol {
                            "✓".to_string()
                        } else {
                            kurbo_undecided += 1;
                            "?".to_string()
                        };
                        format!("[{lo:.2e}, {hi:.2e}] {verdict}")
                    }
                };
                cases += 1;
                if cells[0].0 <= kcp && cells[0].1.is_empty() {
                    fewer_or_equal += 1;
                }
                println!(
                    "| {name} | {d} | {tol:e} | {}{} | {}{} | {kcp} | {kcell} |",
                    cells[0].0, cells[0].1, cells[1].0, cells[1].1
                );
            }
        }
    }
    println!();
    println!(
        "lncert cubic (proven ≤ TOL) used no more control points than kurbo in {fewer_or_equal} of {cases} cases; \
         kurbo proven above its TOL in {kurbo_exceeds}, undecided in {kurbo_undecided}."
    );
    println!(
        "Time: lncert cubic {t_cubic:.2} s, lncert native {t_native:.2} s (construction + proofs), \
         certifying kurbo {t_cert:.2} s; total {:.1} s.",
        start.elapsed().as_secs_f64()
    );
}
