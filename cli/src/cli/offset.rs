//! `lncert offset CURVE --distance R --tol T [--method g2|ln-pair] [--certificate OUT]
//! [--svg OUT] [--global-bounds] [--no-certify] [--json]`: an offset approximant proven
//! within `T` of the exact offset (see [`lncert::offset`]). The certified error is the
//! union bound of the per-segment proofs (each the parametric proof or the
//! two-directional search, said per piece), and the certificate is assembled from them;
//! `--global-bounds` adds a two-sided search over the whole offset; `--no-certify`
//! builds the same construction unproven (labelled so) to measure the proof's cost.
//!
//! `CURVE` is a file with a curve (`{"bezier": ...}`, `{"beziers": ...}`,
//! `{"bspline": ...}`, SVG path data or an SVG document), an arc (`{"arc": {...}}`)
//! or a circle (`{"circle": {"center": [x, y], "radius": r}}`). `R > 0` offsets to
//! the left of the direction of travel. Arcs and circles are offset exactly (seed
//! 004's circular precision). SVG elliptical arcs, `<circle>`, `<ellipse>` and
//! rounded `<rect>` are read as cubic pieces within a certified bound: the report
//! says so (`input: … approximated …`, JSON `"input_approximation": {"elements",
//! "bound"}`, `null` when the curve is exactly the input), and every result is
//! about the approximated curve. With `--glyph GLYPH`, `CURVE` is a
//! TrueType/OpenType font and `GLYPH` one of its glyphs: a character (`A`), a
//! code point (`uni0041`) or a glyph name (`@A`, `Aacute`)
//! ([`super::curve_input`]).
//!
//! Exit codes: 0 = every segment certified within `T`, 3 = the tolerance was not
//! reached within the limits (the best segments are still printed, with their
//! certified bounds), 2 = bad input.

use super::args::{arc_json, bad, grid, grid_line, number, offset_err, point_json, q};
use super::curve_input::{input_line, CurveInput};
use super::modes::{Cap, Method, Subdivision};
use super::{print_out, CliError};
use lncert::curve::Bezier;
use lncert::offset::kernels::Junction;
use lncert::offset::{
    global_bounds, offset, union_certificate, OffsetMethod, OffsetOptions, OffsetResult, Output,
    ProofPath,
};
use lncert::offset::{offset_arc, ArcOffset};
use lncert::scalar::Rational;
use lncert::shape::InputApprox;
use lncert::shape::TravelledArc;
use lncert::{Certificate, Tolerance};
use serde_json::{json, Value};
use std::path::{Path, PathBuf};

/// Relative gap of the global bounds `[lo, hi]` that `--global-bounds` prints as
/// `certified_error` (the proof of `hi ≤ tol` is per segment and does not depend on it).
pub const GLOBAL_REL: f64 = 1e-2;

/// Arguments of `lncert offset`.
#[derive(clap::Args, Debug)]
pub struct OffsetArgs {
    /// The curve file (JSON curve/B-spline/arc/circle or SVG path data), or
    /// with `--glyph` a TrueType/OpenType font.
    pub curve: PathBuf,
    /// Offset the outline of one glyph of the font CURVE (font units; every
    /// contour, exactly as stored: quadratics or cubics): a character (`A`),
    /// a code point (`uni0041`, `u1F600`) or a glyph name (`@A`, `Aacute`).
    #[arg(long, value_name = "GLYPH")]
    pub glyph: Option<String>,
    /// With `--glyph`: coordinates in em (the outline divided by the font's
    /// units per em, exactly), so that `--grid 1/2048` is one font unit of a
    /// 2048-unit font.
    #[arg(long, requires = "glyph")]
    pub em: bool,
    /// Signed offset distance, > 0 to the left of the direction of travel (read exactly).
    #[arg(long, allow_hyphen_values = true)]
    pub distance: String,
    /// The tolerance to prove: d_H(exact offset, approximant) ≤ TOL.
    #[arg(long, allow_hyphen_values = true)]
    pub tol: String,
    /// Construction: g2 (seed 004, degree n+3, G2/C1) or ln-pair (seed 000 §6, cubic, G1).
    #[arg(long, value_enum, default_value_t = Method::G2)]
    pub method: Method,
    /// Where an LN-pair span that missed TOL is split: seed 000 §5's rule `a`
    /// (mid-angle), `b` (the approximant's chord) or `c` (the angles of the two
    /// distances, weighted).
    #[arg(long, value_enum, default_value_t = Subdivision::MidAngle)]
    pub subdivision: Subdivision,
    /// Output curves: native (the method's own segments), cubic or quadratic
    /// (Béziers fitted to the exact offset of each span, proven the same way).
    #[arg(long, value_enum, default_value_t = super::modes::Output::Native)]
    pub output: super::modes::Output,
    /// Round every output control point to a multiple of this exact dyadic
    /// grid (e.g. 1/2048) and prove the rounded curve.
    #[arg(long, allow_hyphen_values = true)]
    pub grid: Option<String>,
    /// Write a certificate of d_H ≤ TOL (re-check it with `lncert verify`).
    #[arg(long)]
    pub certificate: Option<PathBuf>,
    /// Write an SVG: curve, approximant, control polygons, curvature plot.
    #[arg(long)]
    pub svg: Option<PathBuf>,
    /// Write the approximant as a curve file (`{"beziers": ...}`, every control
    /// point exact; with join arcs the union of the curve and the arcs) that
    /// `offset`, `hausdorff` and `verify --against` read back.
    #[arg(long)]
    pub curve_out: Option<PathBuf>,
    /// Write the exact curve approximated (`{"offset": ...}`; with join arcs
    /// the union of the exact offset and the arcs): the shape `A` of the
    /// certificate, for `verify --against`.
    #[arg(long)]
    pub exact_out: Option<PathBuf>,
    /// Write the approximant as SVG path data (`M … C …`; pieces of degree ≤ 3
    /// only: `--method ln-pair`), numbers that read back to the same floats.
    #[arg(long)]
    pub path_out: Option<PathBuf>,
    /// Write the approximant as an SVG document (FILE.svg): one `<path>`
    /// (a line, `fill="none"`), marked `data-lncert-proven="true"` or
    /// `"false"`, in the input's frame (an SVG document's `viewBox` kept, y
    /// down as the input; y-up input flipped upright). Pieces of degree ≤ 3
    /// only, as `--path-out`. With `--trim`: the outline, filled.
    #[arg(long, value_name = "FILE.svg")]
    pub out: Option<PathBuf>,
    /// Also compute seed 000's error measure (8) per LN-pair segment.
    #[arg(long)]
    pub paper_error: bool,
    /// Subdivision depth limit per input span (0 to 40).
    #[arg(long, default_value_t = 24)]
    pub max_depth: u32,
    /// Most output segments.
    #[arg(long, default_value_t = 20_000)]
    pub max_segments: usize,
    /// Box budget of each segment's certified search (per direction).
    #[arg(long, default_value_t = 50_000)]
    pub max_boxes: usize,
    /// Also enclose the global distance from both sides by a search over all
    /// segments (its cost grows with the square of the number of segments;
    /// without it the certified error is the union bound of the per-segment proofs).
    #[arg(long)]
    pub global_bounds: bool,
    /// Do not prove the segments: accept them on a sampled error estimate
    /// (UNPROVEN, labelled so everywhere), to compare the cost of the proof.
    #[arg(long, conflicts_with = "certificate")]
    pub no_certify: bool,
    /// With fitted output: keep every G⁰ corner as a corner (join arc or
    /// overlap), instead of absorbing the kinks whose offset ends are within
    /// TOL of each other (the default: their neighbouring segments meet at one
    /// point, re-proven, and the exact join arc proven within TOL of them).
    #[arg(long)]
    pub keep_kinks: bool,
    /// Trim: the proven outline of the offset region `x ⊕ disk(|R|)` (both
    /// sides trimmed at their crossings, loops removed, round caps on an open
    /// curve), as `lncert stroke --pen circle:|R|` computes it; `--svg` and
    /// `--path-out` write the outline.
    #[arg(long, conflicts_with_all = ["grid", "curve_out", "exact_out"])]
    pub trim: bool,
    /// Print one JSON document.
    #[arg(long)]
    pub json: bool,
}

/// Runs the command; returns the exit code.
pub fn run(a: &OffsetArgs) -> Result<i32, CliError> {
    check_outputs(a)?;
    let distance = number("--distance", &a.distance)?;
    let tolerance = super::args::tolerance(&a.tol)?;
    let tol = tolerance.value();
    let method = OffsetMethod::from(a.method);
    let output = Output::from(a.output);
    let grid = grid(a.grid.as_deref())?;
    check_path_degree(a, method, output)?;
    let input = super::curve_input::read_curve_input(&a.curve, a.glyph.as_deref(), a.em)?;
    if a.trim {
        return run_trim(a, &input, &distance);
    }
    let (curve, approx, y_down) = match input {
        CurveInput::Curve {
            pieces,
            approx,
            y_down,
        } => (pieces, approx, y_down),
        CurveInput::Arc(arc) => return run_arcs(a, &[*arc], &distance, tol),
        CurveInput::Circle { arcs, .. } => return run_arcs(a, &arcs, &distance, tol),
    };
    let opts = options(a, distance, tolerance, method, output, &grid)?;
    if let Some(g) = &grid {
        if matches!(output, Output::Cubic | Output::Quadratic)
            && lncert::offset::kernels::rounding_move(g) >= tol
        {
            return run_on_grid(a, &curve, &opts, y_down);
        }
    }
    let start = std::time::Instant::now();
    let res = offset(&curve, &opts).map_err(offset_err)?;
    let build = start.elapsed().as_secs_f64();
    let cert = match a.certificate {
        Some(_) => union_certificate(&curve, &res).map_err(offset_err)?,
        None => None,
    };
    // without --global-bounds: 0 ≤ d_H ≤ the union bound of the per-segment proofs
    let (lo, hi) = if a.global_bounds {
        let g = global_bounds(&curve, &res, GLOBAL_REL).map_err(offset_err)?;
        // (with --no-certify, certified_hi is ∞: nothing per segment is certified)
        (g.lo, g.hi.min(res.certified_hi))
    } else {
        (0.0, res.certified_hi)
    };
    let proven = res.proven || a.global_bounds;
    let total = start.elapsed().as_secs_f64();
    let cert_note = write_certificate(a.certificate.as_deref(), cert)?;
    // unproven: every segment within tol by its sampled estimate (res.reached())
    let within = res.reached() && (hi <= tol || !proven);
    write_outputs(a, &curve, &res, y_down, within && proven)?;
    let verdict = match (within, proven) {
        (true, true) => "certified",
        (true, false) => "unproven: within tol by a sampled estimate",
        (false, _) => "not reached",
    };
    let report = Report {
        res: &res,
        method,
        output,
        grid: &grid,
        tol,
        tol_text: &a.tol,
        bounds: (lo, hi),
        proven,
        verdict,
        seconds: (build, total),
        cert_note,
        global: a.global_bounds,
    };
    if a.json {
        let doc = report.json(&approx);
        print_out(&format!(
            "{}\n",
            serde_json::to_string_pretty(&doc).unwrap_or_default()
        ));
    } else {
        if let Some(line) = input_line("input", &approx) {
            print_out(&line);
        }
        if let Some(line) = grid_line(&grid, tol) {
            print_out(&format!("{line}\n"));
        }
        print_out(&report.text());
    }
    Ok(if within {
        super::EXIT_OK
    } else {
        super::EXIT_UNDECIDED
    })
}

/// The output files: writable, checked before any work.
fn check_outputs(a: &OffsetArgs) -> Result<(), CliError> {
    for (flag, path) in [
        ("--certificate", &a.certificate),
        ("--svg", &a.svg),
        ("--curve-out", &a.curve_out),
        ("--exact-out", &a.exact_out),
        ("--path-out", &a.path_out),
    ] {
        if let Some(p) = path {
            super::args::output_file(flag, p)?;
        }
    }
    if let Some(p) = &a.out {
        super::svg_out::check(p)?;
    }
    Ok(())
}

/// Path data (also inside `--out`'s document) has no command above degree 3.
fn check_path_degree(a: &OffsetArgs, method: OffsetMethod, output: Output) -> Result<(), CliError> {
    let path_flag = [("--path-out", &a.path_out), ("--out", &a.out)]
        .into_iter()
        .find(|(_, p)| p.is_some())
        .map(|(flag, _)| flag);
    if let (Some(flag), OffsetMethod::G2, Output::Native) = (path_flag, method, output) {
        return Err(super::svg_out::native_g2_refused(flag));
    }
    Ok(())
}

/// `--trim`: the boundary of x ⊕ disk(|R|), as `lncert stroke --pen
/// circle:|R|` computes it, for every input `stroke` reads (a circle included).
fn run_trim(a: &OffsetArgs, input: &CurveInput, distance: &Rational) -> Result<i32, CliError> {
    let sa = super::stroke::StrokeArgs {
        curve: a.curve.clone(),
        glyph: a.glyph.clone(),
        em: a.em,
        pen: Some(format!("circle:{}", num_traits::Signed::abs(distance))),
        tol: a.tol.clone(),
        cap: Cap::Round,
        output: Some(a.output),
        method: a.method,
        svg: a.svg.clone(),
        path_out: a.path_out.clone(),
        out: a.out.clone(),
        certificate: a.certificate.clone(),
        json: a.json,
    };
    let r = num_traits::Signed::abs(distance);
    if r == Rational::from_integer(0.into()) {
        return Err(bad("--distance", "must be nonzero"));
    }
    super::stroke::run_input(&sa, input, lncert::stroke::PenShape::Circle(r))
}

/// The engine's options from the flags (limits checked).
fn options(
    a: &OffsetArgs,
    distance: Rational,
    tol: Tolerance,
    method: OffsetMethod,
    output: Output,
    grid: &Option<Rational>,
) -> Result<OffsetOptions, CliError> {
    let mut opts = OffsetOptions::new(distance, tol);
    opts.method = method;
    opts.subdivision = a.subdivision.for_method(a.method)?;
    opts.output = output;
    opts.grid = grid.clone();
    opts.max_depth = a.max_depth;
    opts.max_segments = a.max_segments;
    if a.max_boxes == 0 || a.max_boxes > 50_000_000 {
        return Err(bad("--max-boxes", "out of range (1 to 50000000)"));
    }
    opts.max_boxes = a.max_boxes;
    opts.paper_error = a.paper_error;
    opts.certify = !a.no_certify;
    opts.smooth_kinks = output != Output::Native && !a.keep_kinks;
    Ok(opts)
}

/// A tolerance below the grid's rounding move: the grid path
/// ([`super::offset_grid`]).
fn run_on_grid(
    a: &OffsetArgs,
    curve: &[Bezier<Rational>],
    opts: &OffsetOptions,
    y_down: bool,
) -> Result<i32, CliError> {
    if a.svg.is_some() || a.global_bounds || a.no_certify || a.paper_error {
        return Err(bad(
            "--grid",
            "with a tolerance below the grid's rounding move, --svg, --global-bounds, \
             --no-certify and --paper-error are not available",
        ));
    }
    let flags = super::offset_grid::GridFlags {
        curve: &a.curve,
        glyph: a.glyph.is_some(),
        tol: &a.tol,
        json: a.json,
        certificate: a.certificate.as_deref(),
        curve_out: a.curve_out.as_deref(),
        exact_out: a.exact_out.as_deref(),
        path_out: a.path_out.as_deref(),
        out: a.out.as_deref(),
    };
    super::offset_grid::run(&flags, curve, opts, y_down)
}

/// `--certificate`: writes it when the tolerance is certified; returns the
/// note printed about it.
fn write_certificate(
    path: Option<&Path>,
    cert: Option<Certificate>,
) -> Result<Option<String>, CliError> {
    let mut cert_note = None;
    if let Some(path) = path {
        match cert {
            Some(c) => {
                std::fs::write(path, c.to_json_string())
                    .map_err(|e| bad("--certificate", format!("{}: {e}", path.display())))?;
                cert_note = Some(format!(
                    "written to {} ({} boxes)",
                    path.display(),
                    c.box_count()
                ));
            }
            None => cert_note = Some("not written: the tolerance is not certified".to_string()),
        }
    }
    Ok(cert_note)
}

/// `--svg`, `--curve-out`, `--exact-out`, `--path-out` and `--out` (its
/// shape marked proven when `proven_within`).
fn write_outputs(
    a: &OffsetArgs,
    curve: &[Bezier<Rational>],
    res: &OffsetResult,
    y_down: bool,
    proven_within: bool,
) -> Result<(), CliError> {
    if let Some(path) = &a.svg {
        let svg = super::offset_svg::render(curve, res, y_down);
        std::fs::write(path, svg).map_err(|e| bad("--svg", format!("{}: {e}", path.display())))?;
    }
    if let Some(path) = &a.curve_out {
        let shape = res.outline_shape().map_err(offset_err)?;
        let text = format!("{}\n", shape.to_json());
        std::fs::write(path, text)
            .map_err(|e| bad("--curve-out", format!("{}: {e}", path.display())))?;
    }
    if let Some(path) = &a.exact_out {
        let shape = res.exact_outline_shape(curve).map_err(offset_err)?;
        let text = format!("{}\n", shape.to_json());
        std::fs::write(path, text)
            .map_err(|e| bad("--exact-out", format!("{}: {e}", path.display())))?;
    }
    if let Some(path) = &a.path_out {
        let text = lncert::write::offset_path_data(res).map_err(|e| bad("--path-out", e))? + "\n";
        std::fs::write(path, text)
            .map_err(|e| bad("--path-out", format!("{}: {e}", path.display())))?;
    }
    if let Some(path) = &a.out {
        let frame = super::svg_out::frame(&a.curve, a.glyph.is_some(), y_down)?;
        let shape = lncert::write::SvgShape::offset(res).map_err(|e| bad("--out", e))?;
        let shape = super::svg_out::proven(shape, proven_within);
        super::svg_out::write(path, &[shape], &frame)?;
    }
    Ok(())
}

/// The report's parts, computed by [`run`] (most as the pairs they are
/// printed in).
struct Report<'a> {
    res: &'a OffsetResult,
    method: OffsetMethod,
    output: Output,
    grid: &'a Option<Rational>,
    tol: f64,
    /// `--tol` as given.
    tol_text: &'a str,
    /// The certified `[lo, hi]`.
    bounds: (f64, f64),
    proven: bool,
    verdict: &'a str,
    /// Seconds to build and certify, and in all.
    seconds: (f64, f64),
    cert_note: Option<String>,
    /// `--global-bounds`.
    global: bool,
}

impl Report<'_> {
    /// The `--json` document.
    fn json(&self, approx: &InputApprox) -> Value {
        let Report {
            res,
            method,
            output,
            grid,
            tol,
            tol_text,
            bounds: (lo, hi),
            proven,
            verdict,
            seconds: (build, total),
            cert_note,
            global,
        } = self;
        let (tol, proven, build, total) = (*tol, *proven, *build, *total);
        json!({
            "method": method.name(),
            "output": output.name(),
            "grid": grid.as_ref().map(|g| json!({
                "grid": q(g),
                "rounding_move": lncert::offset::kernels::rounding_move(g),
                "fit_tol": tol - lncert::offset::kernels::rounding_move(g),
            })),
            "distance": q(&res.distance),
            "tol": tol_text,
            "segments": res.segments.len(),
            "control_points": res.control_points(),
            "degree": res.degree(),
            "certified_error": if proven { json!([lo, hi]) } else { Value::Null },
            "certified_error_from": if *global { "global search" } else if res.proven { "union of the per-segment proofs" } else { "none: --no-certify" },
            "proven": proven,
            "estimated_error": res.estimated_hi(),
            "verdict": verdict,
            "pieces": res.segments.iter().map(|s| json!({
                "piece": s.piece, "t": [s.t.0, s.t.1],
                "control_points": s.bezier.points().iter().map(|p| json!([p.x, p.y])).collect::<Vec<_>>(),
                "error": [s.error.0, s.error.1],
                "proof": s.proof.as_ref().map(|p| p.path.name()),
                "estimate": s.estimate,
                "paper_error": s.paper_error,
            })).collect::<Vec<_>>(),
            "unreached": res.unreached,
            "cusps": res.cusps.iter().map(|c| json!({
                "piece": c.piece, "t": [q(&c.t.0), q(&c.t.1)], "point": [c.point.0, c.point.1],
            })).collect::<Vec<_>>(),
            // in the direction of travel: from the end of the piece before the
            // corner to the start of the next (the shape language's `clockwise`)
            "joins": res.corners.iter().filter_map(|c| match &c.kind {
                Junction::Join { center, from, to, clockwise } => Some(json!({
                    "after_piece": c.after,
                    "absorbed": c.absorbed,
                    "arc": arc_json(center, &num_traits::Signed::abs(&res.distance), from, to, *clockwise)["arc"],
                })),
                _ => None,
            }).collect::<Vec<_>>(),
            "overlaps": res.corners.iter().filter_map(|c| match &c.kind {
                Junction::Overlap { center } => Some(json!({"after_piece": c.after, "at": point_json(center), "absorbed": c.absorbed})),
                _ => None,
            }).collect::<Vec<_>>(),
            "certifications": res.certifications,
            "spans": res.spans,
            "seconds": {"construct_and_certify": build, "total": total, "global_bounds": global.then_some(total - build)},
            "certificate": cert_note,
            "input_approximation": approx.to_json(),
        })
    }

    /// The text report (after the input and grid lines).
    fn text(&self) -> String {
        let res = self.res;
        let mut s = format!(
            "offset at {} ({}{}, tol {}): {} segment(s) of degree {}, {} control points\n",
            res.distance,
            self.method.name(),
            match self.output {
                Output::Native => String::new(),
                o => format!(", output {}", o.name()),
            },
            self.tol_text,
            res.segments.len(),
            res.degree(),
            res.control_points()
        );
        s += &self.text_error();
        if res.proven {
            s += &text_proofs(res);
        }
        for c in &res.cusps {
            s += &format!(
                "  cusp of the exact offset: piece {} at t ≈ {:.9} ({:.6}, {:.6})\n",
                c.piece, c.t_approx, c.point.0, c.point.1
            );
        }
        s += &text_corners(res);
        for &i in &res.unreached {
            let g = &res.segments[i];
            s += &match g.estimate {
                Some(e) => format!(
                    "  not reached: piece {} t ∈ [{}, {}], estimated error (UNPROVEN) ≈ {e:.3e}\n",
                    g.piece, g.t.0, g.t.1
                ),
                None => format!(
                    "  not reached: piece {} t ∈ [{}, {}], certified error ≤ {:.3e}\n",
                    g.piece, g.t.0, g.t.1, g.error.1
                ),
            };
        }
        if let Some(n) = &self.cert_note {
            s += &format!("  certificate: {n}\n");
        }
        s
    }

    /// The error lines: estimated, global or per-segment union bound.
    fn text_error(&self) -> String {
        let Report {
            res,
            bounds: (lo, hi),
            verdict,
            seconds: (build, total),
            global,
            ..
        } = self;
        let global = *global;
        let mut s = String::new();
        if !res.proven && !global {
            let e = res.estimated_hi().unwrap_or(f64::INFINITY);
            s += &format!("  estimated error (sampled, UNPROVEN): d_H ≈ {e:.6e} — {verdict}\n");
            s += &format!(
                "  {} segments built, {:.3} s, nothing proven\n",
                res.segments.len(),
                build
            );
        } else if global {
            s += &format!(
                "  certified error: {lo:.6e} ≤ d_H ≤ {hi:.6e} (global search) — {verdict}\n"
            );
            s += &format!(
                "  {} certified searches, {:.3} s to build and certify, {:.3} s with the global bounds\n",
                res.certifications, build, total
            );
        } else {
            s += &format!(
                "  certified error: d_H ≤ {hi:.6e} (union of the per-segment proofs; --global-bounds for a two-sided enclosure) — {verdict}\n"
            );
            s += &format!(
                "  {} certified searches, {:.3} s to build and certify, {:.3} s in all\n",
                res.certifications, build, total
            );
        }
        s
    }
}

/// How the segments were proven.
fn text_proofs(res: &OffsetResult) -> String {
    let parametric = res
        .segments
        .iter()
        .filter(|g| {
            g.proof
                .as_ref()
                .is_some_and(|p| p.path == ProofPath::Parametric)
        })
        .count();
    let proven = res.segments.iter().filter(|g| g.proof.is_some()).count();
    format!(
        "  proofs: {parametric} parametric (one cover, both directions), {} by the two-directional search\n",
        proven - parametric
    )
}

/// The corners: absorbed kinks, join arcs, overlaps.
fn text_corners(res: &OffsetResult) -> String {
    let mut s = String::new();
    for c in &res.corners {
        if c.absorbed {
            s += &format!(
                "  corner after piece {}: a kink within the tolerance, absorbed: the segments meet at one point{}\n",
                c.after,
                if matches!(c.kind, Junction::Join { .. }) {
                    " and the exact join arc is proven within TOL of them"
                } else {
                    ""
                }
            );
            continue;
        }
        match &c.kind {
            Junction::Join { center, .. } => {
                s += &format!(
                    "  corner after piece {}: join arc of radius {} about ({}, {}) added (exact, not counted)\n",
                    c.after,
                    abs(&res.distance),
                    center.x,
                    center.y
                )
            }
            Junction::Overlap { center } => {
                s += &format!(
                    "  corner after piece {}: the offsets overlap at ({}, {}): trim needed\n",
                    c.after, center.x, center.y
                )
            }
            _ => {}
        }
    }
    s
}

fn abs(r: &Rational) -> Rational {
    if *r < Rational::from_integer(0.into()) {
        -r.clone()
    } else {
        r.clone()
    }
}

fn run_arcs(
    a: &OffsetArgs,
    arcs: &[TravelledArc],
    d: &Rational,
    tol: f64,
) -> Result<i32, CliError> {
    if !(tol.is_finite() && tol > 0.0) {
        return Err(bad("--tol", "must be a finite number > 0"));
    }
    let outs = arcs
        .iter()
        .map(|x| offset_arc(x, d))
        .collect::<Result<Vec<_>, _>>()
        .map_err(offset_err)?;
    // the one arc form of every JSON output (`args::arc_json`): travelled
    // from `from` to `to` (the stored counter-clockwise arc reversed when
    // travelled clockwise), as the shape language reads it back
    let arc_json = |o: &ArcOffset| match o {
        ArcOffset::Arc(t) => {
            let (from, to) = if t.clockwise {
                (&t.arc.to, &t.arc.from)
            } else {
                (&t.arc.from, &t.arc.to)
            };
            arc_json(&t.arc.center, &t.arc.radius, from, to, t.clockwise)
        }
        ArcOffset::Collapsed { center } => json!({"collapsed_to": point_json(center)}),
    };
    let collapsed = outs
        .iter()
        .any(|o| matches!(o, ArcOffset::Collapsed { .. }));
    let note = "exact: seed 004 reproduces an arc's offset exactly (circular precision, proven symbolically in tests/offset_identities.rs)";
    if a.svg.is_some() {
        eprintln!("note: --svg: no picture for an exact arc offset");
    }
    if a.curve_out.is_some() || a.path_out.is_some() || a.exact_out.is_some() || a.out.is_some() {
        eprintln!("note: --curve-out/--path-out/--exact-out/--out: the offset of an arc is an exact arc (printed above); no file is written");
    }
    if a.certificate.is_some() {
        eprintln!("note: --certificate: the offset of an arc is computed exactly; no certificate is needed or written");
    }
    if a.json {
        let doc = json!({
            "method": "g2", "distance": q(d), "tol": a.tol,
            "segments": outs.len(), "control_points": Value::Null, "degree": Value::Null,
            "certified_error": [0.0, 0.0], "verdict": "certified", "exact": note,
            "input_approximation": null,
            "arcs": outs.iter().map(arc_json).collect::<Vec<_>>(),
            "cusps": if collapsed { json!(["the offset collapses to the centre"]) } else { json!([]) },
        });
        print_out(&format!(
            "{}\n",
            serde_json::to_string_pretty(&doc).unwrap_or_default()
        ));
    } else {
        let mut s = format!("offset at {d} of {} arc(s): {note}\n", arcs.len());
        for o in &outs {
            s += &format!("  {}\n", arc_json(o));
        }
        s += "  certified error: 0 ≤ d_H ≤ 0 — certified\n";
        print_out(&s);
    }
    Ok(0)
}
