//! `lncert stroke CURVE --pen circle:R|ellipse:A,B[,θ] --tol T [--method g2|ln-pair]
//! [--cap round|butt] [--output native|cubic|quadratic] [--svg OUT]
//! [--path-out OUT] [--out FILE.svg] [--json]`: the proven outline of the region a pen sweeps
//! along the curve ([`lncert::stroke::stroke`]): closed contours of
//! exact Bézier pieces and exact arcs, the crossings where the sides were cut,
//! and claims (a) output ⊂ TOL-neighbourhood of the exact boundary, (b) exact
//! boundary ⊂ TOL-neighbourhood of the output, (c) closed, simple, oriented
//! (see `proofs/trimming.md`).
//!
//! * `circle:R`: a disk of radius `R > 0` (exact); the sides are the offsets
//!   at `∓R`, the round caps exact arcs.
//! * `ellipse:A,B[,θ]`: the filled ellipse with semi-axes `A ≥ B > 0` rotated
//!   by `θ` (`pi/6`, `30deg`, radians; default 0), parsed as `lncert convolve
//!   --ellipse A,B --angle θ` does. An irrational rotation is represented by an
//!   exactly rational one within a proven angle (printed as the pen's margin):
//!   the outline and its claims are those of **that exact pen** (its matrix is
//!   in the JSON). The sides are the convolution curves `x ∗ e_∓`
//!   ([`lncert::offset::convolve`], each certified within TOL/8), the round
//!   caps half ellipses made of proven cubics (error ≤ TOL/8, printed).
//!   The curve must be G¹ (no join pieces for elliptical pens yet).
//!
//! Without `--pen`, an SVG document is stroked element by element, each with
//! a circle of its own `stroke-width / 2` ([`super::stroke_doc`]).
//!
//! `CURVE` is read as `lncert offset` reads it ([`super::curve_input`]):
//! curve files and SVG documents (the approximation of SVG arcs reported,
//! JSON `"input_approximation"`), `--glyph GLYPH [--em]` with a font (a
//! character, `uni0041` or a glyph name: [`super::glyph_item`]), and
//! `{"circle"}`, whose stroke with a circular pen is exact ([`circle_stroke`]).
//!
//! JSON `outline.complete` is true only when the outline is decided: every
//! contour closed and (a), (b), (c) proven; `outline.uncertain` lists the
//! unproven claims (with their notes) and the open contours (by index).
//!
//! Exit codes: 0 = decided (all contours closed, all three claims proven),
//! 3 = something undecided, 2 = bad input (naming the flag).

use super::args::{arc_json, bad, point_json, q};
use super::curve_input::{read_curve_input, CurveInput};
use super::modes::{Cap, Method, Output};
use super::{print_out, CliError};
use lncert::curve::V2;
use lncert::scalar::{interval_from_rational, Rational, Scalar};
use lncert::shape::InputApprox;
use lncert::stroke::Arc;
use lncert::stroke::{stroke, Claim, Contour, Orientation, PenShape, Piece, Stroke, StrokeOptions};
use lncert::Tolerance;
use serde_json::json;
use std::fmt::Write as _;
use std::path::PathBuf;

/// Arguments of `lncert stroke`.
#[derive(clap::Args, Debug)]
pub struct StrokeArgs {
    /// The curve file, read as `lncert offset` reads it (JSON Bézier /
    /// B-spline, SVG path data or document, `{"circle": ...}`), or with
    /// `--glyph` a TrueType/OpenType font.
    pub curve: PathBuf,
    /// Stroke the outline of one glyph of the font CURVE (font units; every
    /// contour, exactly as stored: quadratics or cubics): a character (`A`),
    /// a code point (`uni0041`, `u1F600`) or a glyph name (`@A`, `Aacute`).
    #[arg(long, value_name = "GLYPH")]
    pub glyph: Option<String>,
    /// With `--glyph`: coordinates in em (the outline divided by the font's
    /// units per em, exactly).
    #[arg(long, requires = "glyph")]
    pub em: bool,
    /// The pen: `circle:R` (`R > 0`, exact) or `ellipse:A,B[,θ]` (semi-axes
    /// `A ≥ B > 0`, rotation `θ`: `pi/6`, `30deg` or radians). Without it, an
    /// SVG document is stroked element by element, each with its own
    /// `stroke-width` (a circle of radius width/2 in document units).
    #[arg(long)]
    pub pen: Option<String>,
    /// The tolerance to prove for claims (a) and (b).
    #[arg(long, allow_hyphen_values = true)]
    pub tol: String,
    /// End caps of an open curve: `round` or `butt`.
    #[arg(long, value_enum, default_value_t = Cap::Round)]
    pub cap: Cap,
    /// Offset segments: native (degree n + 3), cubic or quadratic (fitted, proven;
    /// needed for `--path-out` when the native degree is above 3). Default:
    /// native, or cubic with `--out` (SVG has no command above degree 3).
    #[arg(long, value_enum)]
    pub output: Option<Output>,
    /// The sides' construction: `g2` (degree n + 3, seeds 004 / 001) or
    /// `ln-pair` (cubic LN pairs, seed 000).
    #[arg(long, value_enum, default_value_t = Method::G2)]
    pub method: Method,
    /// Write a picture: the filled outline over the skeleton.
    #[arg(long)]
    pub svg: Option<PathBuf>,
    /// Write the outline as SVG path data (`L`/`Q`/`C`, arcs as `A`, `Z` after
    /// each closed contour; numbers that read back to the same floats).
    #[arg(long)]
    pub path_out: Option<PathBuf>,
    /// Write the outline as an SVG document (FILE.svg): one filled `<path>`
    /// (nonzero), marked `data-lncert-proven="true"` or `"false"`, in the
    /// input's frame: an SVG document's `viewBox` (and size) kept and y down
    /// as the input; y-up input (JSON curves, glyphs) flipped upright. For an
    /// SVG document without `--pen`: one `<path>` per stroked element.
    #[arg(long, value_name = "FILE.svg")]
    pub out: Option<PathBuf>,
    /// Write a stroke certificate (FILE.json) of the proven outline: that it
    /// lies within TOL of the exact boundary of `x ⊕ disk(R)` in Hausdorff
    /// distance, re-checked by `lncert verify FILE.json` on its own. Circular
    /// pens and round caps; not written for an outline that is not proven.
    #[arg(long, value_name = "FILE.json")]
    pub certificate: Option<PathBuf>,
    /// One JSON document on stdout.
    #[arg(long)]
    pub json: bool,
}

fn claim_json(c: &Claim) -> serde_json::Value {
    json!({
        "proven": c.proven,
        "bound": if c.bound.is_finite() { json!(c.bound) } else { json!(null) },
        "note": c.note,
    })
}

fn piece_json(p: &Piece) -> serde_json::Value {
    match p {
        Piece::Bezier(b) => {
            json!({"control_points": b.points().iter().map(point_json).collect::<Vec<_>>()})
        }
        Piece::Arc(a) => arc_json(
            &a.center,
            &a.radius,
            &a.from.sub(&a.center),
            &a.to.sub(&a.center),
            a.clockwise,
        ),
    }
}

fn f(r: &Rational) -> f64 {
    r.approx()
}

/// SVG path data of the outline ([`lncert::write::path_data`]); a piece of
/// degree above 3 has no SVG command: an error naming `--path-out` and the piece.
pub fn path_data(s: &Stroke) -> Result<String, CliError> {
    lncert::write::path_data(&s.contours).map_err(|e| bad("--path-out", e))
}

/// The picture: the filled outlines (path data `path`) over the skeleton.
/// `y_down`: the coordinates are SVG's (the input was SVG path data or a
/// document), drawn as a browser draws the input; otherwise y points up
/// (JSON curves, glyphs, the seeds' figures) and the picture flips it
/// (`scale(1,-1)`).
pub fn svg(
    strokes: &[&Stroke],
    curve: &[lncert::curve::Bezier<Rational>],
    path: &str,
    y_down: bool,
) -> String {
    let all: Vec<Contour> = strokes
        .iter()
        .flat_map(|s| s.contours.iter().cloned())
        .collect();
    let [x0, y0, x1, y1] = lncert::write::contour_bounds(&all).unwrap_or([0.0, 0.0, 1.0, 1.0]);
    let (lo, hi) = ((x0, y0), (x1, y1));
    let w = (hi.0 - lo.0).max(1e-9);
    let h = (hi.1 - lo.1).max(1e-9);
    let m = 0.05 * w.max(h);
    let mut skel = String::new();
    for b in curve {
        let p = b.points();
        let _ = write!(skel, "M {} {} ", f(&p[0].x), f(&p[0].y));
        let pts: Vec<String> = p[1..]
            .iter()
            .map(|v| format!("{} {}", f(&v.x), f(&v.y)))
            .collect();
        let cmd = match b.degree() {
            1 => "L",
            2 => "Q",
            _ => "C",
        };
        if b.degree() <= 3 {
            let _ = write!(skel, "{cmd} {} ", pts.join(" "));
        } else {
            let _ = write!(skel, "L {} ", pts.join(" L "));
        }
    }
    let (top, flip) = if y_down {
        (lo.1 - m, "")
    } else {
        (-hi.1 - m, " transform=\"scale(1,-1)\"")
    };
    format!(
        "<svg xmlns=\"http://www.w3.org/2000/svg\" viewBox=\"{} {} {} {}\" width=\"800\">\n\
         <g{flip}>\n\
         <path d=\"{path}\" fill=\"#9cc3e6\" fill-rule=\"nonzero\" stroke=\"#1f4e79\" stroke-width=\"{}\"/>\n\
         <path d=\"{skel}\" fill=\"none\" stroke=\"#c00000\" stroke-width=\"{}\"/>\n\
         </g>\n</svg>\n",
        lo.0 - m,
        top,
        w + 2.0 * m,
        h + 2.0 * m,
        w.max(h) / 400.0,
        w.max(h) / 300.0,
    )
}

/// `--tol`: an exact number `> 0` ([`super::args::tolerance`]).
pub(crate) fn tol(a: &StrokeArgs) -> Result<Tolerance, CliError> {
    super::args::tolerance(&a.tol)
}

/// Runs `lncert stroke` with `--pen` (the text `pen`); without it
/// [`super::run`] runs [`super::stroke_doc::run`].
pub fn run(a: &StrokeArgs, pen: &str) -> Result<i32, CliError> {
    let tol = tol(a)?;
    let pen = super::pen::pen_shape(pen, tol.value())?;
    let input = read_curve_input(&a.curve, a.glyph.as_deref(), a.em)?;
    run_input(a, &input, pen)
}

/// [`run`] on a `CURVE` already read (`a.curve`, `a.glyph` and `a.pen` are not
/// read): shared with `offset --trim`, so that both accept the same inputs.
/// A `{"circle"}` with a circular pen is stroked exactly ([`circle_stroke`]);
/// a single `{"arc"}`, or a circle with an elliptical pen, is refused (exit 2).
pub fn run_input(a: &StrokeArgs, input: &CurveInput, pen: PenShape) -> Result<i32, CliError> {
    let circle_pen = match &pen {
        PenShape::Circle(r) => Some(r.clone()),
        _ => None,
    };
    let opts = options(a, pen)?;
    match input {
        CurveInput::Curve {
            pieces,
            approx,
            y_down,
        } => match circle_pen
            .is_some()
            .then(|| lncert::stroke::exact_path(pieces, approx))
            .flatten()
        {
            Some((path, rest)) => run_path(a, pieces, &path, &rest, &opts, *y_down),
            None => run_curve(a, pieces, approx, &opts, *y_down),
        },
        CurveInput::Circle {
            center,
            radius,
            arcs,
        } => {
            if a.certificate.is_some() {
                // the certificate states the circle's four quarter arcs
                let path: Option<Vec<_>> = arcs
                    .iter()
                    .map(lncert::stroke::PathPiece::from_travelled)
                    .collect();
                return match (path, circle_pen) {
                    (Some(path), Some(_)) => {
                        run_path(a, &[], &path, &InputApprox::default(), &opts, false)
                    }
                    _ => Err(bad(
                        "--certificate",
                        "a {\"circle\"} is certified as its exact quarter arcs with a circular pen only",
                    )),
                };
            }
            let Some(r) = circle_pen else {
                return Err(bad(
                    "CURVE",
                    "a {\"circle\"} document is stroked exactly, with a circular pen only (--pen circle:R, or offset --trim); for an elliptical pen give the circle as an SVG <circle> (read as cubics within a certified bound)",
                ));
            };
            let t0 = std::time::Instant::now();
            let s = circle_stroke(center, radius, &r, opts.tol.clone());
            report(
                a,
                &s,
                &[],
                &InputApprox::default(),
                t0.elapsed().as_secs_f64(),
                false,
            )
        }
        CurveInput::Arc(arc) => match (lncert::stroke::PathPiece::from_travelled(arc), circle_pen) {
            (Some(p), Some(_)) => run_path(a, &[], &[p], &InputApprox::default(), &opts, false),
            _ => Err(bad(
                "CURVE",
                "an {\"arc\"} document is stroked or trimmed with a circular pen when its end points are rational (its from and to vectors of rational length); this one's are not, or the pen is elliptical: give the arc as SVG path data (an A command, read as cubics within a certified bound), or use offset without --trim for its exact one-sided offset",
            )),
        },
    }
}

/// [`run`] on a curve already read and a pen already parsed (`a.curve` and
/// `a.pen` are not read): shared with `convolve --trim`.
pub fn run_with(
    a: &StrokeArgs,
    curve: &[lncert::curve::Bezier<Rational>],
    pen: PenShape,
) -> Result<i32, CliError> {
    let opts = options(a, pen)?;
    run_curve(a, curve, &InputApprox::default(), &opts, false)
}

/// The options of a run, every flag checked before any work.
pub(crate) fn options(a: &StrokeArgs, pen: PenShape) -> Result<StrokeOptions, CliError> {
    let tol = tol(a)?;
    for (flag, path) in [("--svg", &a.svg), ("--path-out", &a.path_out)] {
        if let Some(p) = path {
            super::args::output_file(flag, p)?;
        }
    }
    if let Some(p) = &a.out {
        super::svg_out::check(p)?;
    }
    if let Some(p) = &a.certificate {
        super::args::output_file("--certificate", p)?;
        if matches!(a.cap, Cap::Butt) {
            return Err(bad(
                "--certificate",
                "stroke certificates state x ⊕ disk(R), whose ends are round: use --cap round",
            ));
        }
    }
    let mut opts = StrokeOptions::with_pen(pen, tol);
    opts.cap = a.cap.into();
    opts.method = a.method.into();
    let output = a.output.unwrap_or(if a.out.is_some() {
        Output::Cubic
    } else {
        Output::Native
    });
    opts.output = output.into();
    Ok(opts)
}

/// The stroke of polynomial pieces by [`stroke`].
fn run_curve(
    a: &StrokeArgs,
    curve: &[lncert::curve::Bezier<Rational>],
    approx: &InputApprox,
    opts: &StrokeOptions,
    y_down: bool,
) -> Result<i32, CliError> {
    let t0 = std::time::Instant::now();
    let s = stroke(curve, opts).map_err(stroke_err)?;
    let secs = t0.elapsed().as_secs_f64();
    let code = report(a, &s, curve, approx, secs, y_down)?;
    match &a.certificate {
        Some(p) => write_certificate(p, curve, &s, &opts.radius, code),
        None => Ok(code),
    }
}

/// The stroke of an exact path with circular arcs by
/// [`lncert::stroke::stroke_path`] (claims (a) and (b) proven against the
/// exact arcs by its certificate); `pieces` (the arcs' cubics) only draw the
/// skeleton of `--svg`, `rest` is what is still approximated.
fn run_path(
    a: &StrokeArgs,
    pieces: &[lncert::curve::Bezier<Rational>],
    path: &[lncert::stroke::PathPiece],
    rest: &InputApprox,
    opts: &StrokeOptions,
    y_down: bool,
) -> Result<i32, CliError> {
    let t0 = std::time::Instant::now();
    let s = lncert::stroke::stroke_path(path, opts).map_err(stroke_err)?;
    let secs = t0.elapsed().as_secs_f64();
    let code = report(a, &s, pieces, rest, secs, y_down)?;
    match &a.certificate {
        Some(p) => {
            if code != super::EXIT_OK {
                eprintln!(
                    "lncert: --certificate {}: not written (the outline is not proven)",
                    p.display()
                );
                return Ok(code);
            }
            let doc = s
                .certificate
                .as_deref()
                .cloned()
                .ok_or_else(|| "the stroke has no certificate".to_string());
            write_built_certificate(p, "stroke certificate (exact arcs)", doc, t0)
        }
        None => Ok(code),
    }
}

/// `--certificate FILE`: the stroke certificate of a proven outline, written
/// and announced on stderr; an unproven outline gets none (exit code kept),
/// and a proven one whose certificate cannot be built exits 3.
fn write_certificate(
    path: &std::path::Path,
    curve: &[lncert::curve::Bezier<Rational>],
    s: &Stroke,
    radius: &Rational,
    code: i32,
) -> Result<i32, CliError> {
    if code != super::EXIT_OK {
        eprintln!(
            "lncert: --certificate {}: not written (the outline is not proven)",
            path.display()
        );
        return Ok(code);
    }
    let t0 = std::time::Instant::now();
    let doc = lncert::stroke::certificate(curve, s, radius).map_err(|e| e.reason);
    write_built_certificate(path, "stroke certificate", doc, t0)
}

/// Writes a built certificate (announced on stderr with its size and time,
/// exit 0) or says why it was not built (exit 3): shared by `--certificate`
/// of one stroke and of an SVG document's set.
pub(crate) fn write_built_certificate(
    path: &std::path::Path,
    what: &str,
    doc: Result<serde_json::Value, String>,
    t0: std::time::Instant,
) -> Result<i32, CliError> {
    match doc {
        Ok(doc) => {
            let text = doc.to_string();
            std::fs::write(path, &text).map_err(|e| bad("--certificate", e))?;
            eprintln!(
                "lncert: {what} written to {} ({} kB in {:.3} s); check it with: lncert verify {}",
                path.display(),
                text.len().div_ceil(1000),
                t0.elapsed().as_secs_f64(),
                path.display()
            );
            Ok(super::EXIT_OK)
        }
        Err(why) => {
            eprintln!(
                "lncert: --certificate {}: not written: {why}",
                path.display()
            );
            Ok(super::EXIT_UNDECIDED)
        }
    }
}

/// A stroke engine error, naming the flag.
pub(crate) fn stroke_err(e: lncert::stroke::StrokeError) -> CliError {
    bad(
        match e.field.as_str() {
            "radius" | "pen" => "--pen",
            "tol" => "--tol",
            _ => "CURVE",
        },
        e.reason,
    )
}

/// One exact circle contour of radius `radius` about `center`: four quarter
/// arcs whose end points `center ± radius·e` are exact rational points on it.
fn circle_contour(center: &V2<Rational>, radius: &Rational, clockwise: bool) -> Contour {
    let (one, zero) = (
        Rational::from_integer(1.into()),
        Rational::from_integer(0.into()),
    );
    let dirs = [
        V2::new(one.clone(), zero.clone()),
        V2::new(zero.clone(), one.clone()),
        V2::new(-one.clone(), zero.clone()),
        V2::new(zero, -one),
    ];
    let mut pts: Vec<V2<Rational>> = dirs.iter().map(|d| center.add(&d.scale(radius))).collect();
    if clockwise {
        pts.reverse();
    }
    let pieces: Vec<Piece> = (0..4)
        .map(|k| {
            Piece::Arc(Arc {
                center: center.clone(),
                radius: radius.clone(),
                from: pts[k].clone(),
                to: pts[(k + 1) % 4].clone(),
                clockwise,
            })
        })
        .collect();
    let area = pieces.iter().map(Piece::area_term).try_fold(
        interval_from_rational(&Rational::from_integer(0.into())),
        |s, t| t.map(|t| s + t),
    );
    let (lo, hi) = area.map_or((f64::NEG_INFINITY, f64::INFINITY), |i| (i.inf(), i.sup()));
    Contour {
        pieces,
        closed: true,
        // a circle travelled counter-clockwise encloses the area +π r²
        // (exact); the enclosure above agrees
        orientation: if clockwise {
            Orientation::Clockwise
        } else {
            Orientation::CounterClockwise
        },
        area: (lo, hi),
    }
}

/// The exact stroke of the circle `(c, ρ)` with the disk of radius `r`:
/// `S = {p : ρ − r ≤ |p − c| ≤ ρ + r}`, whose boundary is the circle of radius
/// `ρ + r` (counter-clockwise) and, when `r < ρ`, the hole of radius `ρ − r`
/// (clockwise); for `r ≥ ρ` the disk is filled. Every output point is exactly
/// on `∂S` and every point of `∂S` is on the output: claims (a), (b) with
/// bound 0; (c) because concentric circles of different radii do not meet.
pub fn circle_stroke(c: &V2<Rational>, rho: &Rational, r: &Rational, tol: Tolerance) -> Stroke {
    let mut contours = vec![circle_contour(c, &(rho + r), false)];
    let hole = rho > r;
    if hole {
        contours.push(circle_contour(c, &(rho - r), true));
    }
    let boundary = if hole {
        format!(
            "the circles of radius {} and {} about the centre",
            rho + r,
            rho - r
        )
    } else {
        format!(
            "the circle of radius {} about the centre (the pen's radius is at least the circle's: the disk is filled)",
            rho + r
        )
    };
    let exact = |what: &str| {
        Claim {
        proven: true,
        bound: 0.0,
        note: format!("exact: ∂S is {boundary}, and the output is exactly {what} (four quarter arcs per circle, their end points exact rational points on it)"),
    }
    };
    let pieces = contours.iter().map(|k| k.pieces.len()).sum();
    Stroke {
        a: exact(if hole { "these circles" } else { "this circle" }),
        b: exact(if hole { "these circles" } else { "this circle" }),
        c: Claim {
            proven: true,
            bound: 0.0,
            note: format!(
                "{} closed contour(s) of exact arcs{}; the outer one counter-clockwise{}",
                contours.len(),
                if hole { ": concentric circles of different radii do not meet" } else { "" },
                if hole { ", the hole clockwise" } else { "" }
            ),
        },
        contours,
        crossings: Vec::new(),
        raw_pieces: pieces,
        raw_complete: true,
        complete: true,
        classified: Default::default(),
        tol,
        closed_curve: true,
        notes: vec!["a circle ({\"circle\"}, or an SVG <circle> stroked with its stroke-width): the stroke is computed exactly (concentric circles), no offset is approximated".to_string()],
        pen: None,
        caps: Vec::new(),
        certificate: None,
    }
}

/// The stroke of a dot (a zero-length subpath with round caps) at `p` with
/// the pen of radius `r`: the disk `B(p, r)`, its boundary the circle
/// stated exactly (four quarter arcs), bound 0 — [`circle_stroke`] of the
/// circle of radius 0 about `p`.
pub fn dot_stroke(p: &V2<Rational>, r: &Rational, tol: Tolerance) -> Stroke {
    let mut s = circle_stroke(p, &Rational::from_integer(0.into()), r, tol);
    let exact = |what: &str| {
        Claim {
        proven: true,
        bound: 0.0,
        note: format!("exact: ∂S is the pen's circle of radius {} about the dot, and the output is exactly {what} (four quarter arcs, their end points exact rational points on it)", q(r)),
    }
    };
    s.a = exact("this circle");
    s.b = exact("this circle");
    s.c.note = "1 closed contour of exact arcs, counter-clockwise".to_string();
    s.closed_curve = false;
    s.notes = vec!["a dot (a zero-length subpath, SVG 2): with round caps it is stroked as the pen's disk about the point; its outline is computed exactly, nothing is approximated".to_string()];
    s
}

/// What keeps a stroke from being decided, for the JSON `uncertain` list:
/// every claim not proven (with its note) and every open contour (by index).
pub(crate) fn uncertain(s: &Stroke) -> Vec<serde_json::Value> {
    let mut out = Vec::new();
    for (name, c) in [("a", &s.a), ("b", &s.b), ("c", &s.c)] {
        if !c.proven {
            out.push(json!({"claim": name, "note": c.note}));
        }
    }
    for (k, c) in s.contours.iter().enumerate() {
        if !c.closed {
            out.push(json!({"contour": k, "note": format!("contour {k} is open")}));
        }
    }
    out
}

/// Prints a stroke (text or JSON) and writes `--svg`, `--path-out`, `--out`; returns
/// the exit code: 0 only when the outline is decided — every contour closed
/// and claims (a), (b), (c) proven — and 3 otherwise.
fn report(
    a: &StrokeArgs,
    s: &Stroke,
    curve: &[lncert::curve::Bezier<Rational>],
    approx: &InputApprox,
    secs: f64,
    y_down: bool,
) -> Result<i32, CliError> {
    let uncertain = uncertain(s);
    // decided: every claim proven and every contour closed
    let complete = uncertain.is_empty();
    let code = if complete {
        super::EXIT_OK
    } else {
        super::EXIT_UNDECIDED
    };
    let verdict = if complete { "proven" } else { "undecided" };
    let path = path_data(s);
    if let Some(p) = &a.path_out {
        let d = path.clone()?;
        std::fs::write(p, d + "\n").map_err(|e| bad("--path-out", e))?;
    }
    if let Some(p) = &a.svg {
        // the picture draws higher-degree pieces as their control polygons' chords
        let d = path.clone().unwrap_or_else(|_| fallback_path(s));
        std::fs::write(p, svg(&[s], curve, &d, y_down)).map_err(|e| bad("--svg", e))?;
    }
    if let Some(p) = &a.out {
        let frame = super::svg_out::frame(&a.curve, a.glyph.is_some(), y_down)?;
        let shape = lncert::write::SvgShape::outline(&s.contours).map_err(|e| bad("--out", e))?;
        super::svg_out::write(p, &[super::svg_out::proven(shape, complete)], &frame)?;
    }
    if a.json {
        let mut doc = stroke_json(s, a.pen.as_deref().unwrap_or_default());
        doc["seconds"] = json!(secs);
        doc["tol"] = json!(a.tol);
        doc["verdict"] = json!(verdict);
        doc["input_approximation"] = approx.to_json();
        print_out(&format!("{doc}\n"));
    } else {
        let mut out = super::curve_input::input_line("input", approx).unwrap_or_default();
        out += &stroke_text(s, secs);
        let _ = writeln!(out, "verdict: {verdict}");
        print_out(&out);
    }
    Ok(code)
}

/// The JSON of one stroke: `outline` (contours, intersections, `complete`,
/// `uncertain`, claims, notes), `pen`, `caps`, `raw_pieces`, `pieces`.
pub(crate) fn stroke_json(s: &Stroke, pen_given: &str) -> serde_json::Value {
    let uncertain = uncertain(s);
    let complete = uncertain.is_empty();
    json!({
            "outline": {
                "contours": s.contours.iter().map(|c| json!({
                    "closed": c.closed,
                    "orientation": c.orientation.name(),
                    "pieces": c.pieces.iter().map(piece_json).collect::<Vec<_>>(),
                })).collect::<Vec<_>>(),
                "intersections": s.crossings.iter().map(|c| json!({
                    "pieces": [c.pieces.0, c.pieces.1],
                    "s": [c.s.0, c.s.1],
                    "t": [c.t.0, c.t.1],
                    "certified": true,
                })).collect::<Vec<_>>(),
                "complete": complete,
                "uncertain": uncertain,
                "output_check_complete": s.complete,
                "raw_check_complete": s.raw_complete,
                "claims": {"a": claim_json(&s.a), "b": claim_json(&s.b), "c": claim_json(&s.c)},
                "notes": s.notes,
            },
            "pen": pen_json(s, pen_given),
            "caps": s.caps.iter().map(|c| json!({
                "end": c.end,
                "pieces": c.pieces,
                "error": c.error,
                "circle_error": c.circle_error,
            })).collect::<Vec<_>>(),
            "raw_pieces": s.raw_pieces,
            "pieces": s.pieces(),

    })
}

/// The text lines of one stroke (contours, claims, notes, what is not decided).
pub(crate) fn stroke_text(s: &Stroke, secs: f64) -> String {
    let uncertain = uncertain(s);
    let mut out = String::new();
    let _ = writeln!(
        out,
        "stroke: {} contours, {} pieces ({} raw, {} crossings cut), {:.2} s",
        s.contours.len(),
        s.pieces(),
        s.raw_pieces,
        s.crossings.len(),
        secs
    );
    if let Some(p) = &s.pen {
        let _ = writeln!(
            out,
            "  pen used (exact): {}, M = [[{}, {}], [{}, {}]]{}",
            p.description,
            q(&p.m[0][0]),
            q(&p.m[0][1]),
            q(&p.m[1][0]),
            q(&p.m[1][1]),
            if p.margin > 0.0 {
                format!(
                        " (rotation within {:.1e} rad of the one given; the claims are for this exact pen)",
                        p.rotation_error
                    )
            } else {
                String::new()
            }
        );
    }
    for c in &s.caps {
        let _ = writeln!(
            out,
            "  {} cap: {} cubics, certified within {:.3e} of the exact half ellipse",
            c.end, c.pieces, c.error
        );
    }
    for (k, c) in s.contours.iter().enumerate() {
        let _ = writeln!(
            out,
            "  contour {k}: {} pieces, {}, {}",
            c.pieces.len(),
            if c.closed { "closed" } else { "open" },
            c.orientation.name()
        );
    }
    for (name, c) in [("a", &s.a), ("b", &s.b), ("c", &s.c)] {
        let _ = writeln!(
            out,
            "  ({name}) {}: {}",
            if c.proven { "proven" } else { "undecided" },
            c.note
        );
    }
    for n in &s.notes {
        let _ = writeln!(out, "  note: {n}");
    }
    for u in &uncertain {
        let _ = writeln!(
            out,
            "  not decided: {}",
            match u.get("claim").and_then(|c| c.as_str()) {
                Some(c) => format!("claim ({c})"),
                None => u["note"].as_str().unwrap_or_default().to_string(),
            }
        );
    }
    out
}

/// The pen actually used: the circle's radius, or the exact ellipse matrix.
fn pen_json(s: &Stroke, given: &str) -> serde_json::Value {
    match &s.pen {
        Some(p) => json!({
            "given": given,
            "kind": "ellipse",
            "description": p.description,
            "matrix": p.m.iter().map(|r| r.iter().map(q).collect::<Vec<_>>()).collect::<Vec<_>>(),
            "rotation_error": p.rotation_error,
            "margin": p.margin,
            "note": "the outline and its claims are for this exact pen",
        }),
        None => json!({"given": given, "kind": "circle"}),
    }
}

/// Path data drawing higher-degree pieces by 16 chords each (pictures only).
pub fn fallback_path(s: &Stroke) -> String {
    let mut d = String::new();
    for c in &s.contours {
        let p0 = c.pieces[0].start();
        let _ = write!(d, "M {} {} ", f(&p0.x), f(&p0.y));
        for p in &c.pieces {
            if let Piece::Bezier(b) = p {
                let n = 16;
                let bf = b.map(Scalar::approx);
                for k in 1..=n {
                    let v = bf.eval_fast(k as f64 / n as f64);
                    let _ = write!(d, "L {} {} ", v.x, v.y);
                }
            } else {
                let e = p.end();
                let _ = write!(d, "L {} {} ", f(&e.x), f(&e.y));
            }
        }
        d.push_str("Z ");
    }
    d
}
