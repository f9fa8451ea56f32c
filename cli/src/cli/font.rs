//! `lncert font IN (--offset D | --stroke R) --tol T --out OUT.ufo [--glyphs SPEC]
//! [--grid G | --grid none] [--report FILE.json|FILE.html] [--jobs N] [--force] [--json]`:
//! every glyph of a TrueType/OpenType font or a UFO (a directory, or a name
//! ending in `.ufo`: [`super::ufo_input`]) offset or stroked, each proven on
//! its own, written as a UFO (norad) with a report (`proofs/font.md`).
//!
//! * `--stroke R`: the outline of the region a disk of radius `R > 0` sweeps
//!   along the glyph's contours ([`lncert::stroke::stroke`]).
//! * `--offset D`: the boundary of the glyph's filled region (nonzero rule)
//!   grown by `D > 0` or shrunk by `D < 0`: the stroke of radius `|D|`, of
//!   which the contours outside the fill (`D > 0`) or inside it (`D < 0`) are
//!   kept. In or out is decided exactly: the exact winding number of the
//!   glyph's contours about a contour's first point
//!   ([`lncert::shape::winding_number`]); the stroke's claim (a) puts every
//!   output point at distance `≥ |D| − bound > 0` from the glyph's contours, so
//!   a contour does not cross them and one point decides it. With `TOL ≥ |D|`
//!   the selection is not proven.
//! * `--glyphs SPEC`: a comma list of characters (`a`), ranges (`A-Z`),
//!   code points (`uni0041`, `u1F600`) and names (`@period`, or `period`
//!   when the item is not one character), read as `offset --glyph` reads its
//!   one item ([`super::glyph_item`]); default every glyph of the font
//!   (glyphs without outline, such as the space, are written empty).
//!   Composites are decomposed.
//! * `--grid G` (default `1`: integer font units; a positive dyadic rational
//!   such as `1/2`, or `none`): every control point on the grid. While the
//!   grid's rounding move `δ = G·√2/2` is at most `TOL/2`, every control point
//!   is rounded (`none`: to the nearest `f64`); the move of each control point
//!   is at most `δ`, so the pieces move pointwise at most `δ` (Bernstein
//!   weights sum to 1), `δ` is charged to the bound, and the stroke is asked
//!   for `0.9 (TOL − δ)`. Above that the stroke is asked for `0.3·TOL` (then
//!   `0.2·TOL`) and its outline is refitted on the grid
//!   ([`lncert::offset::chain_on_grid`]: joints moved along the outline to
//!   grid points, every piece proven against its span of it), the fit's
//!   certified bound charged instead. Either way claim (c) — closed, simple,
//!   disjoint contours — is checked again on the contours written.
//! * Output: cubic pieces (and lines); the stroke's exact arcs are converted to
//!   certified cubics ([`lncert::shape::svgarc::circular_arc_cubics`]) and
//!   their bound charged. `--output quadratic` (TrueType): the stroke's sides
//!   are fitted by quadratics and its arcs replaced by quadratics certified by
//!   the Hausdorff search ([`lncert::certify::circular_arc_quadratics`],
//!   target `0.05 (TOL − δ)`), written as `qcurve` points. Contours are oriented by the UFO's convention
//!   (PostScript: outer contours counter-clockwise, holes clockwise, for
//!   TrueType and CFF input alike; a TrueType compiler such as ufo2ft
//!   reverses them), the outer ones found by exact nesting.
//! * The UFO: fontinfo (units per em, family, style `"<style> offset D"`,
//!   ascender, descender, x height, cap height), every selected glyph with its
//!   name, code points and the input's advance width (kept as it is). Each
//!   glyph's lib holds `org.lncert.proven` (bool), `org.lncert.bound` (the
//!   certified bound, font units, when finite) and `org.lncert.reason` when
//!   not proven; glyphs not proven are written with their best outline. An
//!   existing `OUT` is refused unless `--force` (then replaced).
//! * `--report FILE.json`: per glyph the name, id, code points, verdict
//!   (`proven`, `not proven`, `error`, `empty`), reason, bound, pieces, time;
//!   and the summary. `FILE.html`: a table with a picture per glyph (input
//!   grey, output black).
//! * `--jobs N`: rayon threads (default: all cores). A progress bar with the
//!   glyph count and ETA is drawn on stderr when it is a terminal.
//!
//! Exit codes: 0 = every glyph proven (or empty), 3 = some glyph not proven or
//! refused by the engine (still written, marked), 2 = bad input.

use super::args::{bad, number};
use super::glyph_item::Resolver;
use super::modes::FontOutput;
use super::CliError;
use lncert::curve::{Bezier, V2};
use lncert::scalar::{interval_from_rational, rational_from_f64, Rational, Scalar};
use lncert::shape::{font_info, glyph_outline_by_id, winding_number, FontInfo};
use lncert::stroke::{intersections, IntersectOptions};
use lncert::stroke::{stroke, Contour, Piece, StrokeOptions};
use num_traits::{One, Signed, Zero};
use rayon::prelude::*;
use serde_json::json;
use std::fmt::Write as _;
use std::path::{Path, PathBuf};

/// Arguments of `lncert font`.
#[derive(clap::Args, Debug)]
pub struct FontArgs {
    /// The font: TrueType or OpenType (`.ttf`, `.otf`), or a UFO directory.
    pub input: PathBuf,
    /// Grow (D > 0) or shrink (D < 0) every glyph's filled region by D font units.
    #[arg(long, allow_hyphen_values = true)]
    pub offset: Option<String>,
    /// Stroke every glyph's contours with a disk of radius R font units.
    #[arg(long, allow_hyphen_values = true)]
    pub stroke: Option<String>,
    /// The tolerance to prove per glyph (font units), rounding included.
    #[arg(long, allow_hyphen_values = true)]
    pub tol: String,
    /// The UFO directory to write.
    #[arg(long)]
    pub out: PathBuf,
    /// Which glyphs: chars, ranges A-Z, uniXXXX, @name (comma separated).
    #[arg(long)]
    pub glyphs: Option<String>,
    /// The pieces written: `cubic` (PostScript-style) or `quadratic`
    /// (TrueType-style: the stroke's sides fitted by quadratics, its arcs by
    /// certified quadratics).
    #[arg(long, value_enum, default_value_t = FontOutput::Cubic)]
    pub output: FontOutput,
    /// The grid every control point is on (`1`, `1/2`, ... or `none`):
    /// rounded to it, or fitted on it when its rounding move exceeds TOL/2.
    #[arg(long, default_value = "1")]
    pub grid: String,
    /// Write a report: `.json` or `.html`.
    #[arg(long)]
    pub report: Option<PathBuf>,
    /// Threads (default: all cores).
    #[arg(long)]
    pub jobs: Option<usize>,
    /// Replace an existing output directory.
    #[arg(long)]
    pub force: bool,
    /// The summary as one JSON document on stdout.
    #[arg(long)]
    pub json: bool,
}

/// A grid whose rounding move is at most this share of TOL is rounded to;
/// a coarser one is fitted ([`lncert::offset::chain_on_grid`]).
const ROUND_SHARE: f64 = 0.5;
/// The share of TOL the stroke is asked for when the outline is fitted on the
/// grid (the rest, less the arcs' bound, goes to the fit).
const FIT_STROKE_SHARE: f64 = 0.3;

/// Largest font file read.
const MAX_FONT_BYTES: u64 = super::curve_input::MAX_FONT_BYTES;

/// Offset or stroke, with the exact distance.
#[derive(Clone, Debug)]
enum Op {
    Offset(Rational),
    Stroke(Rational),
}

impl Op {
    fn radius(&self) -> Rational {
        match self {
            Op::Offset(d) => d.abs(),
            Op::Stroke(r) => r.clone(),
        }
    }
    fn describe(&self) -> String {
        match self {
            Op::Offset(d) => format!("offset {d}"),
            Op::Stroke(r) => format!("stroke {r}"),
        }
    }
}

/// The verdict of one glyph.
#[derive(Clone, Debug, PartialEq, Eq)]
enum Verdict {
    Proven,
    NotProven,
    Error,
    Empty,
}

impl Verdict {
    fn name(&self) -> &'static str {
        match self {
            Verdict::Proven => "proven",
            Verdict::NotProven => "not proven",
            Verdict::Error => "error",
            Verdict::Empty => "empty",
        }
    }
}

/// One glyph's result.
struct GlyphResult {
    id: u16,
    verdict: Verdict,
    reason: String,
    bound: f64,
    /// The written contours (exact, after rounding), oriented.
    contours: Vec<Vec<Bezier<Rational>>>,
    /// The input's contours (for pictures).
    input: Vec<Bezier<Rational>>,
    ms: f64,
}

/// The settings shared by every glyph.
struct Job {
    op: Op,
    tol: f64,
    /// `Some(g)`: round to multiples of `g`; `None`: to the nearest f64.
    grid: Option<Rational>,
    /// Quadratic output (`--output quadratic`).
    quadratic: bool,
}

fn parse_grid(text: &str) -> Result<Option<Rational>, CliError> {
    if text == "none" {
        return Ok(None);
    }
    let g = number("--grid", text)?;
    if !g.is_positive() {
        return Err(bad("--grid", "must be > 0 (or none)"));
    }
    let d = g.denom().clone();
    let two = num_bigint::BigInt::from(2);
    let mut k = d;
    while (&k % &two).is_zero() {
        k /= &two;
    }
    if !k.is_one() {
        return Err(bad(
            "--grid",
            "must be a dyadic rational (1, 1/2, 1/64, ...): its multiples are then exact floats in the UFO",
        ));
    }
    Ok(Some(g))
}

/// Resolves `--glyphs` to glyph ids, in the order given, without repeats
/// (each item as [`super::glyph_item`] reads it).
fn select(spec: Option<&str>, info: &FontInfo, src: &Source) -> Result<Vec<u16>, CliError> {
    let Some(spec) = spec else {
        return Ok(info.glyphs.iter().map(|g| g.id).collect());
    };
    let resolver = Resolver {
        flag: "--glyphs",
        info,
        by_char: |ch| src.id_by_char(ch),
    };
    let mut out: Vec<u16> = Vec::new();
    for item in spec.split(',') {
        if item.is_empty() {
            return Err(bad(
                "--glyphs",
                "an empty item (two commas, or a comma at an end)",
            ));
        }
        let ids = resolver.ids(item)?;
        for id in ids {
            if !out.contains(&id) {
                out.push(id);
            }
        }
    }
    Ok(out)
}

/// `½∫(x dy − y dx)`, exact.
fn area(c: &[Bezier<Rational>]) -> Rational {
    let mut s = <Rational as Zero>::zero();
    for b in c {
        let (x, y) = b.power_coords();
        let i = x.mul(&y.derivative()).sub(&y.mul(&x.derivative()));
        for (k, a) in i.coeffs().iter().enumerate() {
            s += a / Rational::from_integer((k as i64 + 1).into());
        }
    }
    s / Rational::from_integer(2.into())
}

fn round_to(x: &Rational, grid: &Option<Rational>) -> Rational {
    match grid {
        Some(g) => (x / g).round() * g,
        None => rational_from_f64(x.approx()).unwrap_or_else(|| x.clone()),
    }
}

/// The largest squared distance between the exact control points `p` and
/// control points `q_i` on the segment `a b` (`q_0 = a`, `q_n = b`, inner ones
/// the projections clamped to the segment, made monotone): the Bézier with
/// the `q_i` traces the segment exactly once, and it is within
/// `max |p_i − q_i|` of the Bézier with the `p_i` at every parameter.
fn segment_move2(p: &[V2<Rational>], a: &V2<Rational>, b: &V2<Rational>) -> Rational {
    let zero = <Rational as Zero>::zero();
    let one = Rational::from_integer(1.into());
    let d = b.sub(a);
    let l2 = d.dot(&d);
    let n = p.len() - 1;
    let mut ts: Vec<Rational> = Vec::with_capacity(n + 1);
    for (i, pi) in p.iter().enumerate() {
        let t = if i == 0 {
            zero.clone()
        } else if i == n {
            one.clone()
        } else {
            let t = pi.sub(a).dot(&d) / &l2;
            t.max(zero.clone()).min(one.clone())
        };
        ts.push(t);
    }
    // monotone: each inner parameter at least the previous one
    for i in 1..=n {
        if ts[i] < ts[i - 1] {
            ts[i] = ts[i - 1].clone();
        }
    }
    p.iter()
        .zip(&ts)
        .map(|(pi, t)| {
            let q = a.add(&d.scale(t));
            let e = q.sub(pi);
            e.dot(&e)
        })
        .max()
        .unwrap_or(zero)
}

/// Upper bound of `√v`.
fn sqrt_up(v: &Rational) -> f64 {
    let s = interval_from_rational(v).sqrt();
    if s.is_empty() {
        f64::INFINITY
    } else {
        s.sup()
    }
}

/// Claim (c) on Bézier contours: each closed, no crossing, and pieces meet only
/// at the joints of consecutive pieces (certified, [`intersections`]).
fn simple(contours: &[Vec<Bezier<Rational>>]) -> Result<(), String> {
    let mut flat = Vec::new();
    let mut at = Vec::new();
    for (ci, c) in contours.iter().enumerate() {
        if c.first().map(|b| &b.points()[0]) != c.last().and_then(|b| b.points().last()) {
            return Err(format!("contour {ci} is not closed"));
        }
        for (k, b) in c.iter().enumerate() {
            flat.push(b.clone());
            at.push((ci, k));
        }
    }
    let r = intersections(&flat, &IntersectOptions::default());
    if !r.complete {
        return Err(format!(
            "the rounded contours' simplicity is undecided ({} regions)",
            r.undecided.len()
        ));
    }
    if !r.crossings.is_empty() {
        return Err(format!(
            "the rounded contours cross ({} crossings)",
            r.crossings.len()
        ));
    }
    for j in &r.joints {
        let ((ca, ka), (cb, kb)) = (at[j.pieces.0], at[j.pieces.1]);
        let n = contours[ca].len();
        let consecutive = ca == cb && ((ka + 1) % n == kb || (kb + 1) % n == ka);
        if !consecutive {
            return Err(format!(
                "contour {ca} piece {ka} and contour {cb} piece {kb} touch but are not consecutive"
            ));
        }
    }
    Ok(())
}

/// Where the glyphs come from.
enum Source {
    /// A TrueType/OpenType file's bytes.
    Binary(Vec<u8>),
    /// A UFO, read and decomposed ([`super::ufo_input`]).
    Ufo(super::ufo_input::UfoSource),
}

impl Source {
    fn outline(&self, id: u16) -> Result<Vec<Bezier<Rational>>, String> {
        match self {
            Source::Binary(data) => glyph_outline_by_id(data, id).map_err(|e| e.to_string()),
            Source::Ufo(u) => u
                .outlines
                .get(usize::from(id))
                .cloned()
                .unwrap_or_else(|| Err(format!("glyph id {id} out of range"))),
        }
    }
    fn id_by_char(&self, ch: char) -> Result<Option<u16>, CliError> {
        match self {
            Source::Binary(data) => {
                lncert::shape::glyph_id_by_char(data, ch).map_err(|e| bad("IN", e))
            }
            Source::Ufo(u) => Ok(u.by_codepoint.get(&u32::from(ch)).copied()),
        }
    }
    fn width(&self, info: &FontInfo, id: u16) -> f64 {
        match self {
            Source::Binary(_) => f64::from(info.glyphs[usize::from(id)].advance),
            Source::Ufo(u) => u.widths[usize::from(id)],
        }
    }
}

/// The whole proof of one glyph (see the module docs).
fn process(src: &Source, id: u16, job: &Job) -> GlyphResult {
    let t0 = std::time::Instant::now();
    let mut g = GlyphResult {
        id,
        verdict: Verdict::Error,
        reason: String::new(),
        bound: f64::INFINITY,
        contours: Vec::new(),
        input: Vec::new(),
        ms: 0.0,
    };
    let res = std::panic::catch_unwind(std::panic::AssertUnwindSafe(|| prove(src, job, &mut g)));
    if res.is_err() {
        g.verdict = Verdict::Error;
        g.reason = "internal error (a panic) while proving this glyph".into();
    }
    g.ms = t0.elapsed().as_secs_f64() * 1e3;
    g
}

fn prove(src: &Source, job: &Job, g: &mut GlyphResult) {
    let pieces = match src.outline(g.id) {
        Ok(p) => p,
        Err(e) => {
            g.reason = e;
            return;
        }
    };
    g.input = pieces.clone();
    if pieces.is_empty() {
        g.verdict = Verdict::Empty;
        g.bound = 0.0;
        return;
    }
    let modes = job.modes();
    for (k, &mode) in modes.iter().enumerate() {
        match attempt(job, &pieces, mode) {
            Err(e) => {
                g.reason = e;
                return;
            }
            Ok(mut a) => {
                if !a.reasons.is_empty() && k + 1 < modes.len() {
                    continue;
                }
                g.bound = a.bound;
                g.contours = std::mem::take(&mut a.contours);
                if a.reasons.is_empty() {
                    g.verdict = Verdict::Proven;
                } else {
                    g.verdict = Verdict::NotProven;
                    a.reasons.truncate(6);
                    g.reason = a.reasons.join("; ");
                }
                return;
            }
        }
    }
}

/// One stroke of a glyph and its outline on the grid.
struct Attempt {
    /// Why it is not proven (empty: proven).
    reasons: Vec<String>,
    /// The written contours, oriented.
    contours: Vec<Vec<Bezier<Rational>>>,
    /// The certified bound (stroke + arcs + grid).
    bound: f64,
}

/// How a glyph's stroke is put on the grid.
#[derive(Clone, Copy, Debug)]
enum Mode {
    /// Every control point rounded, the stroke at `0.9 (TOL − δ)`.
    Round,
    /// The outline refitted on the grid, the stroke at this share of TOL,
    /// corner turns up to `acos(−hairpin_cos)`
    /// ([`lncert::offset::ChainGridOptions::hairpin_cos`]).
    Fit(f64, f64),
}

impl Job {
    /// The modes tried in turn until one proves the glyph: rounding while
    /// the grid's move `δ` leaves the stroke room (`δ ≤ ROUND_SHARE·TOL`:
    /// alone; `δ < 0.9·TOL`: first), then the grid fit with any corner turn,
    /// with turns below 154°, and both again with a second stroke share
    /// (other stroke pieces give other joints and corner fits).
    fn modes(&self) -> Vec<Mode> {
        let Some(grid) = &self.grid else {
            return vec![Mode::Round];
        };
        let delta = lncert::offset::kernels::rounding_move(grid);
        if delta <= ROUND_SHARE * self.tol {
            return vec![Mode::Round];
        }
        let mut modes = Vec::new();
        if delta < 0.9 * self.tol {
            modes.push(Mode::Round);
        }
        modes.extend([
            Mode::Fit(FIT_STROKE_SHARE, 1.0),
            Mode::Fit(FIT_STROKE_SHARE, 0.9),
            Mode::Fit(0.2, 1.0),
            Mode::Fit(0.2, 0.9),
        ]);
        modes
    }
}

/// The stroke and everything after it for one glyph in one mode; `Err`: the
/// engine refused the glyph.
fn attempt(job: &Job, pieces: &[Bezier<Rational>], mode: Mode) -> Result<Attempt, String> {
    let r = job.op.radius();
    let delta_grid = job
        .grid
        .as_ref()
        .map(lncert::offset::kernels::rounding_move)
        .unwrap_or(0.0);
    let mut reasons: Vec<String> = Vec::new();
    let (fit_on_grid, stroke_tol) = match mode {
        Mode::Fit(share, _) if job.grid.is_some() => (true, share * job.tol),
        _ => (false, 0.9 * (job.tol - delta_grid)),
    };
    let stroke_tol = match lncert::Tolerance::from_f64(stroke_tol) {
        Ok(t) => t,
        Err(e) => return Err(format!("no tolerance is left for the stroke: {e}")),
    };
    let mut opts = StrokeOptions::new(r.clone(), stroke_tol);
    opts.output = if job.quadratic {
        lncert::offset::Output::Quadratic
    } else {
        lncert::offset::Output::Cubic
    };
    // what is left of TOL for the arcs' quadratics (cubic arcs take ~1e-7 r)
    let arc_target = 0.05 * (job.tol - if fit_on_grid { 0.0 } else { delta_grid });
    let s = match stroke(pieces, &opts) {
        Ok(s) => s,
        Err(e) => return Err(format!("the stroke engine refused the glyph: {e}")),
    };
    for (name, c) in [("a", &s.a), ("b", &s.b), ("c", &s.c)] {
        if !c.proven {
            reasons.push(format!("stroke claim ({name}) not proven: {}", c.note));
        }
    }
    let stroke_bound = s.a.bound.max(s.b.bound);
    let kept = select_contours(job, pieces, &s.contours, &mut reasons);
    if matches!(job.op, Op::Offset(_)) && !(stroke_bound < r.approx() && s.a.proven) {
        reasons.push(format!(
            "the in/out selection is not proven: it needs claim (a) with a bound below |D| = {r}"
        ));
    }
    let (contours, arc_bound) = to_beziers(kept, job.quadratic, arc_target, &mut reasons);
    let (rounded, grid_bound, grid_what) = match (&job.grid, fit_on_grid) {
        (Some(grid), true) => {
            let left = (job.tol - (stroke_bound + arc_bound).next_up()) * 0.999;
            let hairpin_cos = match mode {
                Mode::Fit(_, h) => h,
                Mode::Round => 1.0,
            };
            let fitted = fit_contours(
                &contours,
                grid,
                left,
                (job.quadratic, hairpin_cos),
                &mut reasons,
            );
            if !fitted.1.is_finite() && delta_grid >= job.tol {
                if let Some(f) = finer_grid(job.tol) {
                    reasons.push(format!(
                        "the grid's rounding move {delta_grid:.4} is not below TOL {} (--grid {f} leaves room)",
                        job.tol
                    ));
                }
            }
            fitted
        }
        _ => {
            let (rounded, move2) = round_contours(&contours, &job.grid, &mut reasons);
            (rounded, sqrt_up(&move2), "rounding")
        }
    };
    // rounded up: the sum of three proven bounds
    let bound = ((stroke_bound + arc_bound).next_up() + grid_bound).next_up();
    // (a NaN bound is not proven either)
    if bound.is_nan() || bound > job.tol {
        reasons.push(format!(
            "the bound {bound:.4} (stroke {stroke_bound:.4} + arcs {arc_bound:.2e} + {grid_what} {grid_bound:.4}) exceeds TOL {}",
            job.tol
        ));
    }
    let simple_ok = match simple(&rounded) {
        Ok(()) => true,
        Err(e) => {
            reasons.push(e);
            false
        }
    };
    let contours = orient(&rounded, simple_ok, &mut reasons);
    Ok(Attempt {
        reasons,
        contours,
        bound,
    })
}

/// The selection of `--offset`: the stroke's contours outside the glyph's
/// fill (`D > 0`) or inside it (`D < 0`), decided by the exact winding number
/// at each contour's first point (every contour for `--stroke`).
fn select_contours<'s>(
    job: &Job,
    pieces: &[Bezier<Rational>],
    contours: &'s [Contour],
    reasons: &mut Vec<String>,
) -> Vec<&'s Contour> {
    let mut kept = Vec::new();
    for (k, c) in contours.iter().enumerate() {
        let keep = match &job.op {
            Op::Stroke(_) => true,
            Op::Offset(d) => {
                let p = c.pieces[0].start();
                match winding_number(pieces, p) {
                    Some(w) => (w != 0) == d.is_negative(),
                    None => {
                        reasons.push(format!(
                            "contour {k}: the winding number at its first point is undecided (kept)"
                        ));
                        true
                    }
                }
            }
        };
        if keep {
            kept.push(c);
        }
    }
    kept
}

/// The stroke's pieces as Béziers: its exact arcs converted to certified
/// cubics (or quadratics); returns the contours and the arcs' bound.
fn to_beziers(
    kept: Vec<&Contour>,
    quadratic: bool,
    arc_target: f64,
    reasons: &mut Vec<String>,
) -> (Vec<Vec<Bezier<Rational>>>, f64) {
    let zero = <Rational as Zero>::zero();
    let mut arc_bound: f64 = 0.0;
    let mut contours: Vec<Vec<Bezier<Rational>>> = Vec::new();
    for c in kept {
        let mut out = Vec::new();
        for p in &c.pieces {
            match p {
                Piece::Bezier(b) => out.push(b.clone()),
                Piece::Arc(a) if quadratic => {
                    match lncert::certify::circular_arc_quadratics(
                        &a.center,
                        &a.radius,
                        &a.from,
                        &a.to,
                        a.clockwise,
                        arc_target,
                    ) {
                        Ok((quads, bound)) => {
                            arc_bound = arc_bound.max(bound);
                            out.extend(quads);
                        }
                        Err(e) => {
                            reasons.push(format!("an arc could not be converted: {e}"));
                            out.push(Bezier::new(vec![a.from.clone(), a.to.clone()]));
                            arc_bound = f64::INFINITY;
                        }
                    }
                }
                Piece::Arc(a) => {
                    let (u, v) = (a.from.sub(&a.center), a.to.sub(&a.center));
                    let cross = u.cross(&v);
                    let large = if a.clockwise {
                        cross > zero
                    } else {
                        cross < zero
                    };
                    match lncert::shape::svgarc::circular_arc_cubics(
                        &a.from,
                        &a.radius,
                        large,
                        !a.clockwise,
                        &a.to,
                    ) {
                        Ok((cubics, bound)) => {
                            arc_bound = arc_bound.max(bound);
                            out.extend(cubics);
                        }
                        Err(e) => {
                            reasons.push(format!("an arc could not be converted: {e}"));
                            out.push(Bezier::new(vec![a.from.clone(), a.to.clone()]));
                            arc_bound = f64::INFINITY;
                        }
                    }
                }
            }
        }
        contours.push(out);
    }
    (contours, arc_bound)
}

/// The stroke's outline refitted on the grid ([`lncert::offset::chain_on_grid`]),
/// each output piece proven within `left` of its part of the outline; returns
/// the contours, the certified bound (infinite when some piece is not proven
/// or nothing is left of TOL) and what it is called in reasons.
fn fit_contours(
    contours: &[Vec<Bezier<Rational>>],
    grid: &Rational,
    left: f64,
    (quadratic, hairpin_cos): (bool, f64),
    reasons: &mut Vec<String>,
) -> (Vec<Vec<Bezier<Rational>>>, f64, &'static str) {
    let what = "grid fit";
    let tol = match lncert::Tolerance::from_f64(left) {
        Ok(t) if left > 0.0 => t,
        _ => {
            reasons.push(format!(
                "nothing is left of TOL for the grid fit ({left:.4})"
            ));
            return (contours.to_vec(), f64::INFINITY, what);
        }
    };
    let mut opts = lncert::offset::ChainGridOptions::new(grid.clone(), tol);
    opts.quadratic = quadratic;
    opts.hairpin_cos = hairpin_cos;
    let r = match lncert::offset::chain_on_grid(contours, &opts) {
        Ok(r) => r,
        Err(e) => {
            reasons.push(format!("the grid fit refused the outline: {e}"));
            return (contours.to_vec(), f64::INFINITY, what);
        }
    };
    if !r.reached() {
        reasons.push(format!(
            "grid fit: {} of {} pieces not proven within {left:.4}",
            r.unreached.len(),
            r.segments.len()
        ));
    }
    let mut out = Vec::new();
    for &(first, n, _) in &r.contours {
        let c: Option<Vec<Bezier<Rational>>> = r.segments[first..first + n]
            .iter()
            .map(|s| lncert::offset::exact_bezier(&s.bezier))
            .collect();
        match c {
            Some(c) if !c.is_empty() => out.push(c),
            Some(_) => {}
            None => {
                reasons.push("grid fit: a control point is not finite".into());
                return (contours.to_vec(), f64::INFINITY, what);
            }
        }
    }
    let bound = if r.reached() {
        r.certified_hi
    } else {
        f64::INFINITY
    };
    (out, bound, what)
}

/// Every control point rounded to the grid; returns the rounded contours
/// and the largest squared move of a control point.
fn round_contours(
    contours: &[Vec<Bezier<Rational>>],
    grid: &Option<Rational>,
    reasons: &mut Vec<String>,
) -> (Vec<Vec<Bezier<Rational>>>, Rational) {
    let mut move2 = <Rational as Zero>::zero();
    let mut rounded: Vec<Vec<Bezier<Rational>>> = Vec::new();
    for c in contours {
        let mut out = Vec::new();
        for b in c {
            let pts: Vec<V2<Rational>> = b
                .points()
                .iter()
                .map(|p| {
                    let q = V2::new(round_to(&p.x, grid), round_to(&p.y, grid));
                    let d = q.sub(p);
                    let m = d.dot(&d);
                    if m > move2 {
                        move2 = m;
                    }
                    q
                })
                .collect();
            if b.degree() > 3 {
                reasons.push(format!("a degree-{} piece has no UFO form", b.degree()));
            }
            if pts.iter().all(|p| *p == pts[0]) {
                continue; // collapsed by the rounding
            }
            let n = pts.len() - 1;
            if n >= 2 && (pts[0] == pts[1] || pts[n - 1] == pts[n]) && pts[0] != pts[n] {
                // a short piece whose end tangent the rounding erased: written
                // as the segment between its rounded ends, charged with the
                // distance of each exact control point to its projection on
                // that segment (a collinear monotone Bézier traces the segment)
                let m = segment_move2(b.points(), &pts[0], &pts[n]);
                if m > move2 {
                    move2 = m;
                }
                out.push(Bezier::new(vec![pts[0].clone(), pts[n].clone()]));
                continue;
            }
            out.push(Bezier::new(pts));
        }
        if !out.is_empty() {
            rounded.push(out);
        }
    }
    (rounded, move2)
}

/// Orientation by exact nesting (meaningful when the contours are simple and
/// disjoint): the UFO convention, outer contours counter-clockwise.
fn orient(
    rounded: &[Vec<Bezier<Rational>>],
    simple_ok: bool,
    reasons: &mut Vec<String>,
) -> Vec<Vec<Bezier<Rational>>> {
    let n = rounded.len();
    let mut oriented = Vec::with_capacity(n);
    for i in 0..n {
        let p = rounded[i][0].points()[0].clone();
        let mut depth = 0;
        let mut decided = true;
        for (j, other) in rounded.iter().enumerate() {
            if j == i {
                continue;
            }
            match winding_number(other, &p) {
                Some(0) => {}
                Some(_) => depth += 1,
                None => decided = false,
            }
        }
        let a = area(&rounded[i]);
        if !decided || a.is_zero() {
            if simple_ok {
                reasons.push(format!("contour {i}: orientation undecided"));
            }
            oriented.push(rounded[i].clone());
            continue;
        }
        let outer = depth % 2 == 0;
        // the UFO convention: outer counter-clockwise (positive area)
        let want_positive = outer;
        if a.is_positive() == want_positive {
            oriented.push(rounded[i].clone());
        } else {
            oriented.push(
                rounded[i]
                    .iter()
                    .rev()
                    .map(|b| {
                        let mut p = b.points().to_vec();
                        p.reverse();
                        Bezier::new(p)
                    })
                    .collect(),
            );
        }
    }
    oriented
}

/// The UFO contour of exact pieces (every coordinate an exact f64 after the rounding).
fn ufo_contour(c: &[Bezier<Rational>]) -> norad::Contour {
    use norad::{ContourPoint, PointType};
    let pt = |p: &V2<Rational>, t: PointType| {
        ContourPoint::new(p.x.approx(), p.y.approx(), t, false, None, None)
    };
    let mut pts = Vec::new();
    for b in c {
        let p = b.points();
        match b.degree() {
            1 => pts.push(pt(&p[1], PointType::Line)),
            2 => {
                pts.push(pt(&p[1], PointType::OffCurve));
                pts.push(pt(&p[2], PointType::QCurve));
            }
            3 => {
                pts.push(pt(&p[1], PointType::OffCurve));
                pts.push(pt(&p[2], PointType::OffCurve));
                pts.push(pt(&p[3], PointType::Curve));
            }
            _ => {
                // no UFO form (reported): the chords of the control polygon
                for q in &p[1..] {
                    pts.push(pt(q, PointType::Line));
                }
            }
        }
    }
    norad::Contour::new(pts, None)
}

fn write_ufo(
    out: &Path,
    info: &FontInfo,
    src: &Source,
    job: &Job,
    results: &[GlyphResult],
) -> Result<(), CliError> {
    let mut font = norad::Font::new();
    let fi = &mut font.font_info;
    fi.units_per_em = norad::fontinfo::NonNegativeIntegerOrFloat::new(f64::from(info.units_per_em));
    fi.family_name = Some(info.family.clone().unwrap_or_else(|| "Untitled".into()));
    fi.style_name = Some(format!(
        "{} {}",
        info.style.clone().unwrap_or_else(|| "Regular".into()),
        job.op.describe()
    ));
    fi.ascender = Some(f64::from(info.ascender));
    fi.descender = Some(f64::from(info.descender));
    fi.x_height = info.x_height.map(f64::from);
    fi.cap_height = info.cap_height.map(f64::from);
    let mut used = std::collections::HashSet::new();
    for r in results {
        let gi = &info.glyphs[usize::from(r.id)];
        let mut name = gi.name.clone();
        if norad::Name::new(&name).is_err() || !used.insert(name.clone()) {
            name = format!("gid{}", r.id);
            used.insert(name.clone());
        }
        let mut glyph = norad::Glyph::new(&name);
        glyph.width = src.width(info, r.id);
        glyph.codepoints = gi
            .codepoints
            .iter()
            .filter_map(|&c| char::from_u32(c))
            .collect();
        glyph.contours = r.contours.iter().map(|c| ufo_contour(c)).collect();
        let proven = matches!(r.verdict, Verdict::Proven | Verdict::Empty);
        glyph
            .lib
            .insert("org.lncert.proven".into(), plist::Value::Boolean(proven));
        if r.bound.is_finite() {
            glyph
                .lib
                .insert("org.lncert.bound".into(), plist::Value::Real(r.bound));
        }
        if !proven {
            glyph.lib.insert(
                "org.lncert.reason".into(),
                plist::Value::String(r.reason.clone()),
            );
        }
        font.default_layer_mut().insert_glyph(glyph);
    }
    font.save(out)
        .map_err(|e| bad("--out", format!("{}: {e}", out.display())))
}

fn report_json(
    a: &FontArgs,
    info: &FontInfo,
    results: &[GlyphResult],
    secs: f64,
) -> serde_json::Value {
    let count = |v: Verdict| results.iter().filter(|r| r.verdict == v).count();
    json!({
        "input": a.input.display().to_string(),
        "operation": if a.offset.is_some() { "offset" } else { "stroke" },
        "distance": a.offset.clone().or(a.stroke.clone()),
        "tol": a.tol,
        "grid": a.grid,
        "output": a.output.name(),
        "glyphs": results.iter().map(|r| {
            let gi = &info.glyphs[usize::from(r.id)];
            json!({
                "name": gi.name,
                "id": r.id,
                "codepoints": gi.codepoints.iter().map(|c| format!("U+{c:04X}")).collect::<Vec<_>>(),
                "verdict": r.verdict.name(),
                "reason": r.reason,
                "bound": if r.bound.is_finite() { json!(r.bound) } else { json!(null) },
                "contours": r.contours.len(),
                "pieces": r.contours.iter().map(Vec::len).sum::<usize>(),
                "ms": (r.ms * 10.0).round() / 10.0,
            })
        }).collect::<Vec<_>>(),
        "summary": {
            "glyphs": results.len(),
            "proven": count(Verdict::Proven),
            "not_proven": count(Verdict::NotProven),
            "errors": count(Verdict::Error),
            "empty": count(Verdict::Empty),
            "seconds": secs,
            "glyphs_per_second": if secs > 0.0 { results.len() as f64 / secs } else { 0.0 },
        },
    })
}

fn svg_path(c: &[Vec<Bezier<Rational>>]) -> String {
    let mut d = String::new();
    for k in c {
        let Some(first) = k.first() else { continue };
        let p = &first.points()[0];
        let _ = write!(d, "M{:.1} {:.1}", p.x.approx(), p.y.approx());
        for b in k {
            let cmd = match b.degree() {
                1 => "L",
                2 => "Q",
                3 => "C",
                _ => "L",
            };
            d.push_str(cmd);
            for q in &b.points()[1..] {
                let _ = write!(d, "{:.1} {:.1} ", q.x.approx(), q.y.approx());
            }
        }
        d.push('Z');
    }
    d
}

fn report_html(doc: &serde_json::Value, info: &FontInfo, results: &[GlyphResult]) -> String {
    let esc = |s: &str| {
        s.replace('&', "&amp;")
            .replace('<', "&lt;")
            .replace('>', "&gt;")
            .replace('"', "&quot;")
    };
    let s = &doc["summary"];
    let mut h = String::new();
    let _ = write!(
        h,
        "<!DOCTYPE html><html><head><meta charset=\"utf-8\"><title>lncert font report</title>\
         <style>body{{font-family:sans-serif}}td,th{{border:1px solid #ccc;padding:2px 6px}}\
         table{{border-collapse:collapse}}.no{{background:#fdd}}</style></head><body>\
         <h1>lncert font: {}</h1><p>{} {}, TOL {}, grid {}: {} glyphs, {} proven, {} not proven, \
         {} errors, {} empty, {:.1} s</p><table><tr><th>glyph</th><th>code points</th><th>verdict</th>\
         <th>bound</th><th>pieces</th><th>ms</th><th>picture</th><th>reason</th></tr>",
        esc(&doc["input"].to_string()),
        doc["operation"].as_str().unwrap_or_default(),
        esc(&doc["distance"].to_string()),
        esc(&doc["tol"].to_string()),
        esc(&doc["grid"].to_string()),
        s["glyphs"],
        s["proven"],
        s["not_proven"],
        s["errors"],
        s["empty"],
        s["seconds"].as_f64().unwrap_or(0.0),
    );
    let upm = f64::from(info.units_per_em.max(1));
    for (r, j) in results
        .iter()
        .zip(doc["glyphs"].as_array().into_iter().flatten())
    {
        let input = svg_path(std::slice::from_ref(&r.input));
        let output = svg_path(&r.contours);
        let (lo, hi) = (-0.5 * upm, 1.5 * upm);
        let _ = write!(
            h,
            "<tr class=\"{}\"><td>{}</td><td>{}</td><td>{}</td><td>{}</td><td>{}</td><td>{}</td>\
             <td><svg width=\"80\" height=\"80\" viewBox=\"{lo} {lo} {} {}\"><g transform=\"translate(0 {}) scale(1 -1)\">\
             <path d=\"{input}\" fill=\"#ccc\"/><path d=\"{output}\" fill=\"none\" stroke=\"#000\" stroke-width=\"{}\"/>\
             </g></svg></td><td>{}</td></tr>",
            if r.verdict == Verdict::NotProven || r.verdict == Verdict::Error { "no" } else { "" },
            esc(j["name"].as_str().unwrap_or_default()),
            esc(&j["codepoints"].to_string()),
            r.verdict.name(),
            if r.bound.is_finite() { format!("{:.3}", r.bound) } else { "–".into() },
            j["pieces"],
            j["ms"],
            hi - lo,
            hi - lo,
            upm,
            upm / 100.0,
            esc(&r.reason),
        );
    }
    h.push_str("</table></body></html>\n");
    h
}

/// The coarsest grid `1/2^k` (`k ≥ 1`) whose rounding move `2^−k·√2/2` is
/// below `0.8·TOL`, leaving the stroke a fifth of it: the suggestion when the
/// grid asked for is too coarse for `TOL`.
fn finer_grid(tol: f64) -> Option<String> {
    (1..=30)
        .map(|k| Rational::new(1.into(), (1i64 << k).into()))
        .find(|g| lncert::offset::kernels::rounding_move(g) < 0.8 * tol)
        .map(|g| g.to_string())
}

/// Runs `lncert font`.
pub fn run(a: &FontArgs) -> Result<i32, CliError> {
    let op = op_of(a)?;
    let tol = super::args::tolerance(&a.tol)?.value();
    let grid = parse_grid(&a.grid)?;
    let quadratic = a.output == FontOutput::Quadratic;
    let jobs = match a.jobs {
        Some(0) => return Err(bad("--jobs", "must be at least 1")),
        Some(n) if n > 1024 => return Err(bad("--jobs", "at most 1024")),
        j => j,
    };
    check_out(a)?;
    let html = report_is_html(a)?;
    let (src, info) = read_font(a)?;
    let ids = select(a.glyphs.as_deref(), &info, &src)?;
    let job = Job {
        op,
        tol,
        grid,
        quadratic,
    };
    let (results, secs) = prove_all(&src, &ids, &job, jobs)?;
    if a.out.exists() && a.force {
        std::fs::remove_dir_all(&a.out)
            .map_err(|e| bad("--out", format!("{}: {e}", a.out.display())))?;
    }
    write_ufo(&a.out, &info, &src, &job, &results)?;
    let doc = report_json(a, &info, &results, secs);
    if let Some(p) = &a.report {
        let text = if html {
            report_html(&doc, &info, &results)
        } else {
            format!("{doc:#}\n")
        };
        std::fs::write(p, text).map_err(|e| bad("--report", format!("{}: {e}", p.display())))?;
    }
    let s = &doc["summary"];
    let all = s["proven"].as_u64().unwrap_or(0) + s["empty"].as_u64().unwrap_or(0);
    let code = if all == results.len() as u64 {
        super::EXIT_OK
    } else {
        super::EXIT_UNDECIDED
    };
    if a.json {
        super::print_out(&format!(
            "{}\n",
            json!({"summary": s, "out": a.out.display().to_string(), "exit_code": code})
        ));
    } else {
        super::print_out(&summary_text(a, &info, &job, &results, s, secs));
    }
    Ok(code)
}

/// `--offset D` or `--stroke R`, exactly one.
fn op_of(a: &FontArgs) -> Result<Op, CliError> {
    Ok(match (&a.offset, &a.stroke) {
        (Some(d), None) => {
            let d = number("--offset", d)?;
            if d.is_zero() {
                return Err(bad("--offset", "must not be 0"));
            }
            Op::Offset(d)
        }
        (None, Some(r)) => {
            let r = number("--stroke", r)?;
            if !r.is_positive() {
                return Err(bad("--stroke", "the pen radius must be > 0"));
            }
            Op::Stroke(r)
        }
        _ => {
            return Err(bad(
                "--offset",
                "give exactly one of --offset D and --stroke R",
            ))
        }
    })
}

/// The output directory, checked before any work.
fn check_out(a: &FontArgs) -> Result<(), CliError> {
    if a.out.as_os_str().is_empty() {
        return Err(bad("--out", "empty path"));
    }
    if a.out.exists() && !a.force {
        return Err(bad(
            "--out",
            format!("{} exists (give --force to replace it)", a.out.display()),
        ));
    }
    if a.out.exists() && !a.out.is_dir() {
        return Err(bad(
            "--out",
            format!("{} is a file, not a UFO directory", a.out.display()),
        ));
    }
    if let Some(parent) = a.out.parent().filter(|p| !p.as_os_str().is_empty()) {
        if !parent.is_dir() {
            return Err(bad(
                "--out",
                format!("the directory {} does not exist", parent.display()),
            ));
        }
    }
    Ok(())
}

/// `--report`: HTML (`.html`, `.htm`) or JSON (`.json`; also without
/// `--report`); the file is checked before any work.
fn report_is_html(a: &FontArgs) -> Result<bool, CliError> {
    Ok(match &a.report {
        Some(p) => {
            let ext = p.extension().and_then(|e| e.to_str()).unwrap_or_default();
            let html = match ext {
                "json" => false,
                "html" | "htm" => true,
                _ => return Err(bad("--report", "must end in .json or .html")),
            };
            super::args::output_file("--report", p)?;
            html
        }
        None => false,
    })
}

/// The font: a UFO, or a TrueType/OpenType file.
fn read_font(a: &FontArgs) -> Result<(Source, FontInfo), CliError> {
    let ext = a
        .input
        .extension()
        .and_then(|e| e.to_str())
        .unwrap_or_default()
        .to_ascii_lowercase();
    Ok(if ext == "ufo" || a.input.is_dir() {
        let u = super::ufo_input::read_ufo(&a.input).map_err(|e| bad("IN", e))?;
        let info = u.info.clone();
        (Source::Ufo(u), info)
    } else {
        let data = super::curve_input::read_limited("IN", &a.input, MAX_FONT_BYTES)?;
        let info = font_info(&data).map_err(|e| bad("IN", e))?;
        (Source::Binary(data), info)
    })
}

/// The work: every glyph proven on `jobs` threads (with a progress bar);
/// returns the results and the seconds taken.
fn prove_all(
    src: &Source,
    ids: &[u16],
    job: &Job,
    jobs: Option<usize>,
) -> Result<(Vec<GlyphResult>, f64), CliError> {
    let t0 = std::time::Instant::now();
    let mut builder = rayon::ThreadPoolBuilder::new();
    if let Some(n) = jobs {
        builder = builder.num_threads(n);
    }
    let pool = builder.build().map_err(|e| bad("--jobs", e))?;
    let bar = progress_bar(ids.len());
    let results: Vec<GlyphResult> = pool.install(|| {
        ids.par_iter()
            .map(|&id| {
                let r = process(src, id, job);
                if let Some(b) = &bar {
                    b.inc(1);
                }
                r
            })
            .collect()
    });
    if let Some(b) = bar {
        b.finish_and_clear();
    }
    let secs = t0.elapsed().as_secs_f64();
    Ok((results, secs))
}

/// The text summary: the glyphs not proven, then one line.
fn summary_text(
    a: &FontArgs,
    info: &FontInfo,
    job: &Job,
    results: &[GlyphResult],
    s: &serde_json::Value,
    secs: f64,
) -> String {
    let mut out = String::new();
    for r in results {
        if matches!(r.verdict, Verdict::NotProven | Verdict::Error) {
            let _ = writeln!(
                out,
                "  {} {}: {}",
                info.glyphs[usize::from(r.id)].name,
                r.verdict.name(),
                r.reason
            );
        }
    }
    let _ = writeln!(
        out,
        "font: {} glyphs ({}), {} proven, {} not proven, {} errors, {} empty, {:.1} s ({:.1} glyphs/s); wrote {}",
        results.len(),
        job.op.describe(),
        s["proven"],
        s["not_proven"],
        s["errors"],
        s["empty"],
        secs,
        s["glyphs_per_second"].as_f64().unwrap_or(0.0),
        a.out.display()
    );
    out
}

fn progress_bar(n: usize) -> Option<indicatif::ProgressBar> {
    use std::io::IsTerminal;
    if !std::io::stderr().is_terminal() {
        return None;
    }
    let b = indicatif::ProgressBar::new(n as u64);
    if let Ok(style) = indicatif::ProgressStyle::with_template(
        "lncert font {bar:30} {pos}/{len} glyphs, {elapsed} elapsed, ETA {eta}",
    ) {
        b.set_style(style);
    }
    Some(b)
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The suggested grid is the coarsest dyadic one whose rounding move is
    /// below 0.8·TOL, and none is suggested beyond 2⁻³⁰.
    #[test]
    fn the_suggested_grid_is_the_coarsest_that_leaves_room() {
        for (tol, want) in [(0.5, Some("1/2")), (0.3, Some("1/4")), (0.1, Some("1/16"))] {
            assert_eq!(finer_grid(tol).as_deref(), want, "TOL {tol}");
        }
        for tol in [0.5, 0.3, 0.1, 1e-3, 1e-6] {
            let g = finer_grid(tol).expect("a grid");
            let k = g
                .trim_start_matches("1/")
                .parse::<u64>()
                .unwrap()
                .trailing_zeros() as i32;
            let mv = |k: i32| {
                lncert::offset::kernels::rounding_move(&Rational::new(1.into(), (1i64 << k).into()))
            };
            assert!(mv(k) < 0.8 * tol, "TOL {tol}: {g} moves too far");
            assert!(
                k == 1 || mv(k - 1) >= 0.8 * tol,
                "TOL {tol}: {g} is not the coarsest"
            );
        }
        assert_eq!(finer_grid(1e-12), None);
    }

    /// Dense two-sided check of [`segment_move2`]: every sampled point of the
    /// exact piece is within the bound of the segment, and every point of the
    /// segment within the bound of a sampled point of the piece (plus the
    /// sampling step).
    #[test]
    fn the_segment_replacing_a_degenerate_rounded_piece_is_within_the_charged_move() {
        let q = |n: i64, d: i64| Rational::new(n.into(), d.into());
        let mut seed = 0x2545_f491_4f6c_dd1d_u64;
        let mut next = || {
            seed ^= seed << 13;
            seed ^= seed >> 7;
            seed ^= seed << 17;
            (seed % 2001) as i64 - 1000
        };
        let grid = Some(Rational::from_integer(1.into()));
        for _ in 0..200 {
            // a short piece (about a unit long) at an arbitrary place
            let (x0, y0) = (q(next(), 7), q(next(), 3));
            let pts: Vec<V2<Rational>> = (0..4)
                .map(|_| V2::new(&x0 + q(next(), 700), &y0 + q(next(), 700)))
                .collect();
            let r = |p: &V2<Rational>| V2::new(round_to(&p.x, &grid), round_to(&p.y, &grid));
            let (a, b) = (r(&pts[0]), r(&pts[3]));
            if a == b {
                continue;
            }
            let bound = sqrt_up(&segment_move2(&pts, &a, &b));
            let f = |p: &V2<Rational>| (p.x.approx(), p.y.approx());
            let exact = Bezier::new(pts.clone()).map(|x| x.approx());
            let curve: Vec<(f64, f64)> = (0..=2000)
                .map(|k| {
                    let v = exact.eval_fast(k as f64 / 2000.0);
                    (v.x, v.y)
                })
                .collect();
            let (af, bf) = (f(&a), f(&b));
            let seg_dist = |p: (f64, f64)| {
                let d = (bf.0 - af.0, bf.1 - af.1);
                let t = (((p.0 - af.0) * d.0 + (p.1 - af.1) * d.1) / (d.0 * d.0 + d.1 * d.1))
                    .clamp(0.0, 1.0);
                (af.0 + t * d.0 - p.0).hypot(af.1 + t * d.1 - p.1)
            };
            for &p in &curve {
                assert!(seg_dist(p) <= bound + 1e-9, "{} > {bound}", seg_dist(p));
            }
            let step = curve
                .windows(2)
                .map(|w| (w[1].0 - w[0].0).hypot(w[1].1 - w[0].1))
                .fold(0.0, f64::max);
            for k in 0..=500 {
                let t = k as f64 / 500.0;
                let s = (af.0 + t * (bf.0 - af.0), af.1 + t * (bf.1 - af.1));
                let d = curve
                    .iter()
                    .map(|c| (c.0 - s.0).hypot(c.1 - s.1))
                    .fold(f64::INFINITY, f64::min);
                assert!(d <= bound + step + 1e-9, "segment point {d} > {bound}");
            }
        }
    }
}
