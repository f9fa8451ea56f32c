//! `lncert convolve CURVE (--ellipse A,B [--angle θ] | --pen-matrix M11,M12,M21,M22)
//! --tol T [--side plus|minus|both] [--method g2] [--certificate OUT] [--svg OUT]
//! [--json]`: the convolution of a curve with an elliptical pen (the boundary of
//! the region an elliptical nib sweeps), approximated by seed 001's G²/C¹ method
//! and proven within `T` on each side (see [`lncert::offset::conv`]).
//!
//! `A ≥ B > 0` are the **semi**-axes; `θ` is `pi/6`, `30deg` or radians (exact:
//! a rotation that is not a quarter turn is represented by an exactly rational
//! one within a proven angle, and the tolerance certified for it is `T` less the
//! proven distance this can make, printed as the pen's margin). Side `plus` is
//! the pen point whose outer normal is the left normal of the trajectory.
//!
//! With `--certificate OUT`, one certificate of `d_H(A, B) ≤ T − margin` for
//! the exact pen is written to `OUT`: `A` the exact convolution of the side, or
//! for `both` the union of the two sides' exact convolutions, `B` the
//! approximant(s) (a union of the two splines, in the order plus, minus);
//! every piece is proven against its own exact span, so the certificate also
//! shows each side within `T − margin`. `lncert verify OUT` re-checks it.
//!
//! Exit codes as `offset`: 0 = every side proven within `T`, 3 = not reached
//! within the limits, 2 = bad input.

use super::args::{bad, number, offset_err, q};
use super::modes::{Accept, Method, Output, Side, Subdivision};
use super::pen::ellipse_pen;
use super::{print_report, CliError};
use lncert::curve::{Bezier, V2};
use lncert::offset::{
    convolve, union_certificate, union_certificate_all, OffsetOptions, OffsetResult,
};
use lncert::offset::{Angle, Pen};
use lncert::scalar::{Rational, Scalar};
use lncert::shape::parse_curve;
use lncert::Tolerance;
use serde_json::json;
use std::fmt::Write as _;
use std::path::{Path, PathBuf};

/// Arguments of `lncert convolve`.
#[derive(clap::Args, Debug)]
pub struct ConvolveArgs {
    /// The trajectory: a curve file (JSON Bézier / B-spline, SVG path data or an SVG document).
    pub curve: PathBuf,
    /// The pen's semi-axes `A,B` (`A ≥ B > 0`), exact numbers.
    #[arg(long, conflicts_with = "pen_matrix")]
    pub ellipse: Option<String>,
    /// The pen's rotation: `pi/6`, `2pi/3`, `30deg`, or radians (default 0).
    #[arg(long, allow_hyphen_values = true, requires = "ellipse")]
    pub angle: Option<String>,
    /// The pen as a matrix `M11,M12,M21,M22` (`E = M · unit circle`, det M ≠ 0).
    #[arg(long, allow_hyphen_values = true)]
    pub pen_matrix: Option<String>,
    /// The tolerance to prove on each side.
    #[arg(long, allow_hyphen_values = true)]
    pub tol: String,
    /// Which convolution curve: `plus`, `minus` or `both`.
    #[arg(long, value_enum, default_value_t = Side::Both)]
    pub side: Side,
    /// The construction: `g2` (seed 001, degree n + 3) or `ln-pair` (seed 000 §5, cubic).
    #[arg(long, value_enum, default_value_t = Method::G2)]
    pub method: Method,
    /// Where an LN-pair span that missed `T` is split: seed 000 §5's rule
    /// `a` (mid-angle), `b` (the approximant's chord) or `c` (the angles of the
    /// two distances, weighted; the paper's choice for the font 'H').
    #[arg(long, value_enum, default_value_t = Subdivision::MidAngle)]
    pub subdivision: Subdivision,
    /// Output curves: native, cubic or quadratic (fitted to the exact
    /// convolution of each span, proven the same way).
    #[arg(long, value_enum, default_value_t = Output::Native)]
    pub output: Output,
    /// Round every output control point to a multiple of this exact dyadic
    /// grid (e.g. 1/2048) and prove the rounded curve.
    #[arg(long, allow_hyphen_values = true)]
    pub grid: Option<String>,
    /// Also compute seed 000 §5's error measure d_H(p, pa) + d_H(q, qa) per
    /// LN-pair segment (certified upper bounds; reported, not used).
    #[arg(long)]
    pub paper_error: bool,
    /// Acceptance of a segment: `certified` (its certified true error ≤ T) or
    /// `paper` (seed 000 §5's measure ≤ T, as the paper does; the true error is
    /// still certified and reported, and the result is proven only if it is ≤ T).
    #[arg(long, value_enum, default_value_t = Accept::Certified)]
    pub accept: Accept,
    /// Write the certificate(s) (see the module docs for the names); with
    /// `--trim`, the outline's stroke certificate.
    #[arg(long)]
    pub certificate: Option<PathBuf>,
    /// Write a picture: trajectory, exact convolution, approximants, cusps.
    #[arg(long)]
    pub svg: Option<PathBuf>,
    /// Subdivision depth limit per trajectory piece.
    #[arg(long, default_value_t = 24)]
    pub max_depth: u32,
    /// Most output segments per side.
    #[arg(long, default_value_t = 20_000)]
    pub max_segments: usize,
    /// Box budget per segment certification.
    #[arg(long, default_value_t = 50_000)]
    pub max_boxes: usize,
    /// Build the same construction without proofs (labelled unproven).
    #[arg(long, conflicts_with = "certificate")]
    pub no_certify: bool,
    /// Trim: the proven outline of the region the pen sweeps (both sides
    /// trimmed at their crossings, loops removed, closed by half-ellipse
    /// caps), as `lncert stroke --pen ellipse:…` computes it; `--side` is
    /// not used, `--svg` draws the outline, `--certificate` writes the
    /// outline's stroke certificate (`lncert stroke --certificate`).
    #[arg(long, conflicts_with = "grid")]
    pub trim: bool,
    /// Write the result as an SVG document (`.svg`): one path per side
    /// (`data-lncert-side`, `data-lncert-proven`), or with `--trim` the
    /// outline, in the input's frame (an SVG input's `viewBox`, y down as
    /// read; JSON curves drawn upright). SVG stores degree ≤ 3: use
    /// `--output cubic`/`quadratic` or `--method ln-pair`.
    #[arg(long, value_name = "FILE.svg")]
    pub out: Option<PathBuf>,
    /// One JSON document on stdout.
    #[arg(long)]
    pub json: bool,
}

fn numbers(flag: &str, text: &str, n: usize) -> Result<Vec<Rational>, CliError> {
    let parts: Vec<&str> = text.split(',').map(str::trim).collect();
    if parts.len() != n {
        return Err(bad(flag, format!("expected {n} comma-separated numbers")));
    }
    parts.iter().map(|p| number(flag, p)).collect()
}

/// The pen; a rotation is represented within `min(1e-6, tol/1000 / (A + A²/B))`
/// radians, so its margin costs at most a thousandth of the tolerance while the
/// exact numbers stay small.
fn pen_of(a: &ConvolveArgs, tol: f64) -> Result<Pen, CliError> {
    let shape_err =
        |flag: &str, e: lncert::shape::ShapeError| bad(flag, format!("{}: {}", e.field, e.reason));
    match (&a.ellipse, &a.pen_matrix) {
        (Some(e), None) => {
            let ab = numbers("--ellipse", e, 2)?;
            let angle = match &a.angle {
                Some(t) => Angle::parse(t).map_err(|e| shape_err("--angle", e))?,
                None => Angle::Radians(Rational::from_integer(0.into())),
            };
            ellipse_pen("--ellipse", &ab[0], &ab[1], &angle, tol)
        }
        (None, Some(m)) => {
            let v = numbers("--pen-matrix", m, 4)?;
            Pen::from_matrix([[v[0].clone(), v[1].clone()], [v[2].clone(), v[3].clone()]])
                .map_err(|e| shape_err("--pen-matrix", e))
        }
        _ => Err(bad(
            "--ellipse",
            "give the pen: --ellipse A,B [--angle θ] or --pen-matrix M11,M12,M21,M22",
        )),
    }
}

/// Runs the command; returns the exit code.
pub fn run(a: &ConvolveArgs) -> Result<i32, CliError> {
    let sides = a.side.signs();
    for (flag, path) in [("--certificate", &a.certificate), ("--svg", &a.svg)] {
        if let Some(p) = path {
            super::args::output_file(flag, p)?;
        }
    }
    let output = lncert::offset::Output::from(a.output);
    if let Some(p) = &a.out {
        super::svg_out::check(p)?;
        if !a.trim && a.method == Method::G2 && output == lncert::offset::Output::Native {
            return Err(super::svg_out::native_g2_refused("--out"));
        }
    }
    let grid = super::args::grid(a.grid.as_deref())?;
    let tolerance = super::args::tolerance(&a.tol)?;
    let tol = tolerance.value();
    let pen = pen_of(a, tol)?;
    let text = super::curve_input::read_text(&a.curve)?;
    let curve = parse_curve(&text).map_err(|e| bad("CURVE", e))?;
    if a.trim {
        return run_trim(a, &curve, pen);
    }
    let opts = options(a, tolerance, output, &grid)?;
    let start = std::time::Instant::now();
    let mut results = Vec::new();
    for (sigma, name) in &sides {
        let t0 = std::time::Instant::now();
        let r = convolve(&curve, &pen, *sigma, &opts).map_err(offset_err)?;
        results.push((*name, r, t0.elapsed().as_secs_f64()));
    }
    let total = start.elapsed().as_secs_f64();
    let cert_notes = match &a.certificate {
        Some(path) => write_certificate(path, &curve, &results)?,
        None => Vec::new(),
    };
    if let Some(path) = &a.svg {
        let svg = render(&curve, &pen, &results);
        std::fs::write(path, svg).map_err(|e| bad("--svg", format!("{}: {e}", path.display())))?;
    }
    let judge = Judge {
        tol,
        proven: opts.certify,
    };
    if let Some(path) = &a.out {
        let y_down = super::curve_input::y_down(&text);
        let frame = super::svg_out::frame(&a.curve, false, y_down)?;
        let shapes = results
            .iter()
            .map(|(name, r, _)| {
                let shape = lncert::write::SvgShape::offset(r).map_err(|e| bad("--out", e))?;
                let shape = shape.with("data-lncert-side", *name);
                Ok(super::svg_out::proven(
                    shape,
                    opts.certify && judge.within(r),
                ))
            })
            .collect::<Result<Vec<_>, CliError>>()?;
        super::svg_out::write(path, &shapes, &frame)?;
    }
    let within_all = results
        .iter()
        .all(|(_, r, _)| judge.within(r) || !opts.certify && r.reached());
    let report = Report {
        a,
        pen: &pen,
        output,
        grid: &grid,
        tol,
        results: &results,
        total,
        cert_notes: &cert_notes,
        judge,
        within_all,
    };
    print_report(a.json, || report.json(), || report.text());
    Ok(if within_all {
        super::EXIT_OK
    } else {
        super::EXIT_UNDECIDED
    })
}

/// `--trim`: the outline of the region the pen sweeps, as `lncert stroke`.
fn run_trim(a: &ConvolveArgs, curve: &[Bezier<Rational>], pen: Pen) -> Result<i32, CliError> {
    let sa = super::stroke::StrokeArgs {
        curve: a.curve.clone(),
        glyph: None,
        em: false,
        pen: Some(String::new()),
        tol: a.tol.clone(),
        cap: super::modes::Cap::Round,
        output: Some(a.output),
        method: a.method,
        svg: a.svg.clone(),
        path_out: None,
        out: a.out.clone(),
        certificate: a.certificate.clone(),
        json: a.json,
    };
    super::stroke::run_with(&sa, curve, lncert::stroke::PenShape::Ellipse(pen))
}

/// The engine's options from the flags (limits checked).
fn options(
    a: &ConvolveArgs,
    tol: Tolerance,
    output: lncert::offset::Output,
    grid: &Option<Rational>,
) -> Result<OffsetOptions, CliError> {
    if a.max_boxes == 0 || a.max_boxes > 50_000_000 {
        return Err(bad("--max-boxes", "out of range (1 to 50000000)"));
    }
    let mut opts = OffsetOptions::new(Rational::from_integer(0.into()), tol);
    opts.method = a.method.into();
    opts.subdivision = a.subdivision.for_method(a.method)?;
    opts.output = output;
    opts.grid = grid.clone();
    opts.paper_error = a.paper_error;
    opts.accept_paper = match (a.accept, a.method) {
        (Accept::Certified, _) => false,
        (Accept::Paper, Method::LnPair) => true,
        (Accept::Paper, Method::G2) => {
            return Err(bad(
                "--accept",
                "the paper's measure belongs to seed 000 §5's LN pairs: use --method ln-pair",
            ))
        }
    };
    opts.max_depth = a.max_depth;
    opts.max_segments = a.max_segments;
    opts.max_boxes = a.max_boxes;
    opts.certify = !a.no_certify;
    Ok(opts)
}

/// `--certificate`: one certificate for all sides, written to `path`; the
/// claim for the exact pen is tol − margin (as a float ≤ it: the results'
/// `certified_tol`). Returns the notes printed about it.
fn write_certificate(
    path: &Path,
    curve: &[Bezier<Rational>],
    results: &[(&str, OffsetResult, f64)],
) -> Result<Vec<String>, CliError> {
    let mut cert_notes = Vec::new();
    let t0 = std::time::Instant::now();
    let claim = results
        .iter()
        .map(|(_, r, _)| r.certified_tol())
        .min_by(|x, y| x.exact().cmp(y.exact()))
        .map(ToString::to_string)
        .unwrap_or_default();
    let rs: Vec<&OffsetResult> = results.iter().map(|(_, r, _)| r).collect();
    let names = results
        .iter()
        .map(|(n, _, _)| *n)
        .collect::<Vec<_>>()
        .join(" and ");
    let cert = if rs.len() == 1 {
        union_certificate(curve, rs[0])
    } else {
        union_certificate_all(curve, &rs)
    }
    .map_err(offset_err)?;
    match cert {
        Some(c) => {
            std::fs::write(path, c.to_json_string())
                .map_err(|e| bad("--certificate", format!("{}: {e}", path.display())))?;
            cert_notes.push(format!(
                "side {names}: written to {} (d_H ≤ {claim}) in {:.1} ms",
                path.display(),
                1e3 * t0.elapsed().as_secs_f64()
            ));
        }
        None => cert_notes.push(format!(
            "side {names}: not written (the tolerance is not certified)"
        )),
    }
    Ok(cert_notes)
}

/// How a side's result is judged.
struct Judge {
    tol: f64,
    /// The segments were certified (not `--no-certify`).
    proven: bool,
}

impl Judge {
    /// Proven within tol: every segment's certified bound ≤ the tolerance
    /// certified for the exact pen (with --accept paper a segment may be
    /// accepted above it).
    fn within(&self, r: &OffsetResult) -> bool {
        r.reached()
            && r.certified_hi
                <= r.convolution
                    .as_ref()
                    .map_or(self.tol, |c| c.certified_tol.value())
    }

    fn verdict(&self, r: &OffsetResult) -> &'static str {
        match (r.reached(), self.proven, self.within(r)) {
            (true, true, true) => "certified",
            (true, true, false) => "accepted by the paper's measure, NOT proven within tol",
            (true, false, _) => "unproven: within tol by a sampled estimate",
            (false, _, _) => "not reached",
        }
    }
}

/// Everything the printed report (JSON or text) shows.
struct Report<'a> {
    a: &'a ConvolveArgs,
    pen: &'a Pen,
    output: lncert::offset::Output,
    grid: &'a Option<Rational>,
    tol: f64,
    results: &'a [(&'a str, OffsetResult, f64)],
    total: f64,
    cert_notes: &'a [String],
    judge: Judge,
    within_all: bool,
}

impl Report<'_> {
    /// The overall verdict.
    fn overall(&self) -> &'static str {
        if self.within_all {
            if self.judge.proven {
                "certified"
            } else {
                "unproven"
            }
        } else {
            "not reached"
        }
    }

    /// The `--json` document.
    fn json(&self) -> serde_json::Value {
        let Report {
            a,
            pen,
            output,
            grid,
            tol,
            results,
            total,
            cert_notes,
            ..
        } = self;
        let (tol, total) = (*tol, *total);
        let proven = self.judge.proven;
        json!({
            "pen": {
                "description": pen.description,
                "matrix": pen.m.iter().map(|r| r.iter().map(q).collect::<Vec<_>>()).collect::<Vec<_>>(),
                "rotation_error": pen.rotation_error,
                "margin": pen.margin,
            },
            "tol": a.tol,
            "method": a.method.name(),
            "output": output.name(),
            "grid": grid.as_ref().map(|g| json!({
                "grid": q(g),
                "rounding_move": lncert::offset::kernels::rounding_move(g),
                "fit_tol": tol - pen.margin - lncert::offset::kernels::rounding_move(g),
            })),
            "verdict": self.overall(),
            "sides": results.iter().map(|(name, r, secs)| {
                let c = r.convolution.as_ref();
                json!({
                    "side": if *name == "plus" { "+" } else { "-" },
                    "segments": r.segments.len(),
                    "control_points": r.control_points(),
                    "degree": r.degree(),
                    "certified_error": if proven { json!([0.0, r.certified_hi]) } else { serde_json::Value::Null },
                    "certified_tol": c.map(|c| c.certified_tol.value()),
                    "verdict": self.judge.verdict(r),
                    "split_points": split_points(r),
                    "cusps": c.map(|c| c.cusps.iter().map(|k| json!({
                        "piece": k.piece, "t": [q(&k.t.0), q(&k.t.1)], "point": [k.point.0, k.point.1],
                    })).collect::<Vec<_>>()).unwrap_or_default(),
                    "accept": a.accept.name(),
                    "pieces": r.segments.iter().map(|s| json!({
                        "piece": s.piece, "t": [s.t.0, s.t.1], "lo": s.error.0, "hi": s.error.1,
                        "proof": s.proof.as_ref().map(|p| p.path.name()),
                        "estimate": s.estimate, "paper_error": s.paper_error,
                        "control_points": s.bezier.points().iter().map(|p| json!([p.x, p.y])).collect::<Vec<_>>(),
                    })).collect::<Vec<_>>(),
                    "unreached": r.unreached,
                    "certifications": r.certifications,
                    "seconds": secs,
                })
            }).collect::<Vec<_>>(),
            "seconds": total,
            "certificates": cert_notes,
        })
    }

    /// The text report.
    fn text(&self) -> String {
        let Report {
            a,
            pen,
            output,
            grid,
            tol,
            results,
            cert_notes,
            ..
        } = self;
        let tol = *tol;
        let mut s = format!(
            "convolution with the pen {} ({}, tol {}):\n",
            pen.description,
            match (output, a.method) {
                (lncert::offset::Output::Cubic, _) => "fitted cubics",
                (lncert::offset::Output::Quadratic, _) => "fitted quadratics",
                (_, Method::G2) => "seed 001 G²",
                _ => "seed 000 §5 cubic LN pairs",
            },
            a.tol
        );
        if let Some(line) = super::args::grid_line(grid, tol - pen.margin) {
            s += &format!("  {line}\n");
        }
        if pen.margin > 0.0 {
            s += &format!(
                "  the rotation is represented exactly rationally within {:.1e} rad: the convolutions move by ≤ {:.1e}, certified for tol − that\n",
                pen.rotation_error, pen.margin
            );
        }
        for (name, r, secs) in results.iter() {
            let c = r.convolution.as_ref();
            s += &format!(
                "  side {name}: {} segment(s) of degree {}, {} control points; certified d_H ≤ {:.6e} — {} ({:.3} s)\n",
                r.segments.len(),
                r.degree(),
                r.control_points(),
                r.certified_hi,
                self.judge.verdict(r),
                secs
            );
            if let Some(c) = c {
                for k in &c.cusps {
                    s += &format!(
                        "    cusp of the exact convolution: piece {} at t ≈ {:.9} ({:.6}, {:.6})\n",
                        k.piece, k.t_approx, k.point.0, k.point.1
                    );
                }
            }
            for &i in &r.unreached {
                let g = &r.segments[i];
                s += &format!(
                    "    not reached: piece {} t ∈ [{}, {}], certified error ≤ {:.3e}\n",
                    g.piece, g.t.0, g.t.1, g.error.1
                );
            }
        }
        for n in cert_notes.iter() {
            s += &format!("  certificate {n}\n");
        }
        s
    }
}

/// The parameters where consecutive segments meet (per piece, interior only).
fn split_points(r: &OffsetResult) -> Vec<f64> {
    r.segments
        .windows(2)
        .filter(|w| w[0].piece == w[1].piece)
        .map(|w| w[0].t.1)
        .collect()
}

/// The picture: trajectory (blue), exact convolution sampled (green),
/// approximants (red: plus, magenta: minus), cusps (black dots). An
/// illustration in floats; the proof is the printed certified bound.
pub(crate) fn render(
    curve: &[Bezier<Rational>],
    pen: &Pen,
    results: &[(&str, OffsetResult, f64)],
) -> String {
    let qf = pen.q_f64();
    let xs: Vec<Bezier<f64>> = curve.iter().map(|b| b.map(|v| v.approx())).collect();
    let sample = |b: &Bezier<f64>, n: usize| -> Vec<V2<f64>> {
        (0..=n).map(|i| b.eval(&(i as f64 / n as f64))).collect()
    };
    let mut exact: Vec<(i8, Vec<V2<f64>>)> = Vec::new();
    for (name, _, _) in results {
        let sigma = if *name == "plus" { 1 } else { -1 };
        for b in &xs {
            let pts = (0..=256)
                .filter_map(|i| {
                    let t = i as f64 / 256.0;
                    let d = b.hodograph().eval(&t);
                    lncert::offset::kernels::pen_point(&V2::new(-d.y, d.x), qf, sigma)
                        .map(|e| b.eval(&t).add(&e))
                })
                .collect();
            exact.push((sigma, pts));
        }
    }
    let mut all: Vec<V2<f64>> = xs.iter().flat_map(|b| sample(b, 64)).collect();
    all.extend(exact.iter().flat_map(|(_, p)| p.iter().cloned()));
    let (mut x0, mut y0, mut x1, mut y1) = (f64::MAX, f64::MAX, f64::MIN, f64::MIN);
    for p in &all {
        if p.x.is_finite() && p.y.is_finite() {
            x0 = x0.min(p.x);
            y0 = y0.min(p.y);
            x1 = x1.max(p.x);
            y1 = y1.max(p.y);
        }
    }
    let (w, h, pad) = (720.0, 720.0, 20.0);
    let s = ((w - 2.0 * pad) / (x1 - x0).max(1e-12)).min((h - 2.0 * pad) / (y1 - y0).max(1e-12));
    let map = |p: &V2<f64>| (pad + (p.x - x0) * s, h - pad - (p.y - y0) * s);
    let poly = |pts: &[V2<f64>], style: &str| -> String {
        let mut d = String::new();
        for (i, p) in pts.iter().enumerate() {
            let (x, y) = map(p);
            let _ = write!(d, "{}{x:.2},{y:.2} ", if i == 0 { "M" } else { "L" });
        }
        format!("<path d=\"{d}\" fill=\"none\" {style}/>\n")
    };
    let mut out = format!(
        "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"{w}\" height=\"{h}\" viewBox=\"0 0 {w} {h}\">\n<rect width=\"100%\" height=\"100%\" fill=\"white\"/>\n"
    );
    for (_, pts) in &exact {
        out += &poly(
            pts,
            "stroke=\"#2a2\" stroke-width=\"3\" stroke-opacity=\"0.35\"",
        );
    }
    for b in &xs {
        out += &poly(&sample(b, 128), "stroke=\"#24c\" stroke-width=\"1.2\"");
    }
    for (name, r, _) in results {
        let color = if *name == "plus" { "#d22" } else { "#c2c" };
        for g in &r.segments {
            out += &poly(
                &sample(&g.bezier, 48),
                &format!("stroke=\"{color}\" stroke-width=\"1\""),
            );
        }
        if let Some(c) = &r.convolution {
            for k in &c.cusps {
                let (x, y) = map(&V2::new(k.point.0, k.point.1));
                let _ = writeln!(
                    out,
                    "<circle cx=\"{x:.2}\" cy=\"{y:.2}\" r=\"3\" fill=\"black\"/>"
                );
            }
        }
    }
    out += &format!(
        "<text x=\"{pad}\" y=\"{}\" font-size=\"12\" font-family=\"sans-serif\">{} — red: side +, magenta: side −, green: exact (sampled), blue: trajectory</text>\n</svg>\n",
        h - 4.0,
        pen.description
    );
    out
}
