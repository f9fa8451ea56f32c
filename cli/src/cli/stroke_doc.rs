//! `lncert stroke DOC.svg --tol T` without `--pen`: an SVG document stroked
//! as a browser strokes it — every drawn element whose computed `stroke` is
//! not `none` (SVG's initial value is `none`) with a circular pen of radius
//! `stroke-width / 2` in document units (the element's own `stroke-width`,
//! from its attribute, its `style` or an ancestor; default 1; scaled by its
//! transform, which must be a similarity with a rational scale, or the pen
//! would be an ellipse: refused, naming the element). Elements with a zero
//! width draw nothing and are skipped. What is skipped or instanced
//! (`display`, `visibility`, `<defs>`, `<use>`) is
//! [`lncert::shape::parse_svg_document_elements`]'s.
//!
//! Every element is stroked and proven on its own (claims (a)–(c) of
//! `lncert stroke`, in parallel); the run is decided (exit 0) when every
//! element's stroke is. An element that is exactly a circle ([`exact_circle`])
//! is stroked exactly, as a `{"circle"}` input is (concentric circles, bound
//! 0, nothing approximated), unless `--certificate` asks for stroke
//! certificates, which state Bézier curves. `--svg` draws all outlines (y down, as the input),
//! `--path-out` writes them one after the other (each element's contours
//! are oriented; their union is the nonzero fill), `--out FILE.svg` writes
//! an SVG document with the input's `viewBox`, `width` and `height`, y down
//! as the input, one filled `<path>` per stroked element, in document order,
//! with `data-lncert-at` (the element, as in the JSON `at`) and
//! `data-lncert-proven="true"`/`"false"` (an undecided element is written
//! and marked, never dropped). JSON: `{"elements":
//! [{"at", "pen_radius", "stroke_width", "input_approximation", "verdict",
//! "outline", ...}], "verdict", "seconds", "tol", "input_approximation"}`.

use super::args::{bad, q};
use super::modes::Cap;
use super::stroke::{options, path_data, stroke_err, stroke_json, stroke_text, StrokeArgs};
use super::{print_out, CliError};
use lncert::curve::V2;
use lncert::scalar::Rational;
use lncert::shape::svgarc::{ApproxKind, ExactPiece};
use lncert::shape::{parse_svg_document_elements, InputApprox, SvgElement};
use lncert::stroke::{exact_path, stroke_path, PathPiece, PenShape, Stroke};
use num_traits::{Signed, Zero};
use rayon::prelude::*;
use serde_json::json;
use std::fmt::Write as _;

/// Each element's dots (zero-length subpaths) as elements of their own, one
/// dot each, named `AT/dot[k]`, after the element's pieces (an element that
/// is only one dot keeps its name). With butt caps SVG draws no dot: each is
/// listed in the notes instead (never dropped silently).
fn with_dots(elements: Vec<SvgElement>, cap: Cap) -> (Vec<SvgElement>, Vec<String>) {
    let mut out = Vec::new();
    let mut notes = Vec::new();
    for mut e in elements {
        let dots = std::mem::take(&mut e.dots);
        let alone = e.pieces.is_empty() && dots.len() == 1;
        let at = e.at.clone();
        let template = SvgElement {
            at: String::new(),
            pieces: Vec::new(),
            dots: Vec::new(),
            approx: InputApprox::default(),
            stroked: e.stroked,
            stroke_width: e.stroke_width.clone(),
            pen_radius: e.pen_radius.clone(),
        };
        if !e.pieces.is_empty() {
            out.push(e);
        }
        for (k, p) in dots.into_iter().enumerate() {
            let name = if alone {
                at.clone()
            } else {
                format!("{at}/dot[{k}]")
            };
            if matches!(cap, Cap::Butt) {
                if template.stroked && !template.stroke_width.is_zero() {
                    notes.push(format!(
                        "{name}: a zero-length subpath at ({}, {}) draws nothing with butt caps (SVG 2)",
                        q(&p.x),
                        q(&p.y)
                    ));
                }
                continue;
            }
            let mut d = SvgElement {
                at: name,
                ..template.clone()
            };
            d.dots = vec![p];
            out.push(d);
        }
    }
    (out, notes)
}

/// The one dot of an element made by [`with_dots`].
fn dot_of(e: &SvgElement) -> Option<&V2<Rational>> {
    match (e.pieces.is_empty(), e.dots.as_slice()) {
        (true, [p]) => Some(p),
        _ => None,
    }
}

/// The elements to stroke and their pens, every one checked before any work.
fn stroked(elements: &[SvgElement]) -> Result<Vec<(&SvgElement, Rational)>, CliError> {
    let mut out = Vec::new();
    for e in elements.iter().filter(|e| e.stroked) {
        if e.stroke_width.is_zero() {
            continue;
        }
        let r = e
            .pen_radius
            .clone()
            .map_err(|reason| bad("CURVE", reason))?;
        out.push((e, r));
    }
    if out.is_empty() {
        return Err(bad(
            "--pen",
            "no element of the document is stroked (stroke unset or none — SVG's initial stroke is none — or stroke-width 0): give --pen to stroke every element with one pen",
        ));
    }
    Ok(out)
}

/// What the stroke of `e` approximated of the input: nothing for a circle
/// stroked exactly; for an exact path only what it could not state exactly
/// (and arcs with an irrational centre within their near arcs' bounds).
fn still_approximated(a: &StrokeArgs, e: &SvgElement) -> InputApprox {
    if a.certificate.is_none() && exact_circle(e).is_some() {
        return InputApprox::default();
    }
    match exact_path(&e.pieces, &e.approx) {
        Some((_, rest)) => rest,
        None => e.approx.clone(),
    }
}

/// Runs the per-element stroke of an SVG document.
pub fn run(a: &StrokeArgs) -> Result<i32, CliError> {
    if let Some(p) = &a.certificate {
        super::args::output_file("--certificate", p)?;
    }
    let (text, elements) = read_document(a)?;
    let (elements, notes) = with_dots(elements, a.cap);
    let jobs = stroked(&elements)?;
    let (strokes, secs) = stroke_all(a, &jobs)?;
    let mut approx = InputApprox::default();
    for (e, _) in &jobs {
        approx.elements.extend(still_approximated(a, e).elements);
    }
    let decided: Vec<bool> = strokes
        .iter()
        .map(|(s, _)| super::stroke::uncertain(s).is_empty())
        .collect();
    let all = decided.iter().all(|d| *d);
    let verdict = if all { "proven" } else { "undecided" };
    let refs: Vec<&Stroke> = strokes.iter().map(|(s, _)| s).collect();
    write_files(a, &text, &jobs, &refs, &decided)?;
    let report = Report {
        a,
        jobs: &jobs,
        strokes: &strokes,
        decided: &decided,
        secs,
        verdict,
        approx: &approx,
        notes: &notes,
    };
    if a.json {
        print_out(&format!("{}\n", report.json()));
    } else {
        print_out(&report.text());
    }
    let code = if all {
        super::EXIT_OK
    } else {
        super::EXIT_UNDECIDED
    };
    match &a.certificate {
        Some(p) => write_certificate_set(p, &jobs, &strokes, code),
        None => Ok(code),
    }
}

/// `--certificate FILE`: a set of stroke certificates, one per stroked
/// element (its own curve and pen), written when every element is proven
/// (else a note on stderr, the exit code kept); a proven run whose
/// certificates cannot all be built exits 3.
fn write_certificate_set(
    path: &std::path::Path,
    jobs: &[(&SvgElement, Rational)],
    strokes: &[(Stroke, f64)],
    code: i32,
) -> Result<i32, CliError> {
    if code != super::EXIT_OK {
        eprintln!(
            "lncert: --certificate {}: not written (not every element is proven)",
            path.display()
        );
        return Ok(code);
    }
    let t0 = std::time::Instant::now();
    let members: Result<Vec<(String, serde_json::Value)>, String> = jobs
        .par_iter()
        .zip(strokes.par_iter())
        .map(|((e, r), (s, _))| {
            // a stroke proven against exact arcs carries its certificate
            if let Some(c) = &s.certificate {
                return Ok((e.at.clone(), c.as_ref().clone()));
            }
            if dot_of(e).is_some() {
                return Err(format!(
                    "{}: a dot (a zero-length subpath) has no stroke certificate: a certificate states the offsets of a curve, and a point has none (its outline, the pen's circle about it, is exact)",
                    e.at
                ));
            }
            lncert::stroke::certificate(&e.pieces, s, r)
                .map(|c| (e.at.clone(), c))
                .map_err(|err| format!("{}: {}", e.at, err.reason))
        })
        .collect::<Vec<_>>()
        .into_iter()
        // the first element that fails, in document order (not whichever
        // parallel job failed first)
        .collect();
    let n = jobs.len();
    super::stroke::write_built_certificate(
        path,
        &format!("stroke certificate set ({n} elements)"),
        members.map(lncert::stroke::certificate_set),
        t0,
    )
}

/// The document's text and its elements, after the flags' checks.
fn read_document(a: &StrokeArgs) -> Result<(String, Vec<SvgElement>), CliError> {
    super::stroke::tol(a)?;
    if a.glyph.is_some() {
        return Err(bad("--pen", "required with --glyph"));
    }
    let text = super::curve_input::read_text(&a.curve)?;
    if !text.trim_start().starts_with('<') {
        return Err(bad(
            "--pen",
            "required unless CURVE is an SVG document (only a document carries its own stroke-width)",
        ));
    }
    let elements = parse_svg_document_elements(&text).map_err(|e| bad("CURVE", e))?;
    Ok((text, elements))
}

/// The centre and radius of an element that is exactly one whole circle
/// (`<circle>`, `<ellipse>` with equal radii, under a similarity with a
/// rational scale): its one approximated element's exact form is two
/// complementary half circles that replace all its pieces.
pub(crate) fn exact_circle(e: &SvgElement) -> Option<(V2<Rational>, Rational)> {
    let [el] = e.approx.elements.as_slice() else {
        return None;
    };
    let x = el.exact.as_ref()?;
    if !matches!(el.kind, ApproxKind::Circle | ApproxKind::Ellipse)
        || x.first != 0
        || x.count != e.pieces.len()
    {
        return None;
    }
    let [ExactPiece::Arc(h0), ExactPiece::Arc(h1)] = x.pieces.as_slice() else {
        return None;
    };
    let same = |u: &V2<Rational>, v: &V2<Rational>| u.cross(v).is_zero() && u.dot(v).is_positive();
    let whole = h0.center == h1.center
        && h0.radius == h1.radius
        && same(&h0.from, &h1.to)
        && same(&h0.to, &h1.from);
    whole.then(|| (h0.center.clone(), h0.radius.clone()))
}

/// Every element stroked (in parallel) with its own pen; returns the strokes
/// with their seconds, and the seconds in all. An element that is exactly a
/// circle is stroked exactly (concentric circles,
/// [`super::stroke::circle_stroke`]) unless `--certificate` asks for the
/// certified general construction (a stroke certificate states Bézier
/// curves).
fn stroke_all(
    a: &StrokeArgs,
    jobs: &[(&SvgElement, Rational)],
) -> Result<(Vec<(Stroke, f64)>, f64), CliError> {
    // every flag checked once, before any work
    options(a, PenShape::Circle(jobs[0].1.clone()))?;
    let t0 = std::time::Instant::now();
    let strokes: Vec<(Stroke, f64)> = jobs
        .par_iter()
        .map(|(e, r)| {
            let t = std::time::Instant::now();
            let opts = options(a, PenShape::Circle(r.clone()))?;
            if let Some(p) = dot_of(e) {
                let s = super::stroke::dot_stroke(p, r, opts.tol.clone());
                return Ok((s, t.elapsed().as_secs_f64()));
            }
            let circle = exact_circle(e).filter(|_| a.certificate.is_none());
            let s = match (circle, exact_path(&e.pieces, &e.approx)) {
                (Some((c, rho)), _) => super::stroke::circle_stroke(&c, &rho, r, opts.tol.clone()),
                (None, Some((path, _))) => stroke_path(&path, &opts)
                    .map_err(stroke_err)
                    .map_err(|err| bad("CURVE", format!("{}: {}", e.at, err)))?,
                (None, None) => {
                    let path: Vec<PathPiece> =
                        e.pieces.iter().cloned().map(PathPiece::Bezier).collect();
                    stroke_path(&path, &opts)
                }
                .map_err(stroke_err)
                .map_err(|err| bad("CURVE", format!("{}: {}", e.at, err)))?,
            };
            Ok((s, t.elapsed().as_secs_f64()))
        })
        .collect::<Result<_, CliError>>()?;
    let secs = t0.elapsed().as_secs_f64();
    Ok((strokes, secs))
}

/// `--path-out`, `--out` and `--svg`.
fn write_files(
    a: &StrokeArgs,
    text: &str,
    jobs: &[(&SvgElement, Rational)],
    refs: &[&Stroke],
    decided: &[bool],
) -> Result<(), CliError> {
    if let Some(p) = &a.path_out {
        let mut d = Vec::new();
        for s in refs {
            d.push(path_data(s)?);
        }
        std::fs::write(p, d.join(" ") + "\n").map_err(|e| bad("--path-out", e))?;
    }
    if let Some(p) = &a.out {
        let frame = lncert::write::SvgOptions::from_svg(text).map_err(|e| bad("CURVE", e))?;
        let mut shapes = Vec::new();
        for (((e, _), s), d) in jobs.iter().zip(refs).zip(decided) {
            let shape = lncert::write::SvgShape::outline(&s.contours)
                .map_err(|err| bad("--out", format!("{}: {err}", e.at)))?
                .with("data-lncert-at", e.at.clone());
            shapes.push(super::svg_out::proven(shape, *d));
        }
        super::svg_out::write(p, &shapes, &frame)?;
    }
    if let Some(p) = &a.svg {
        let d: Vec<String> = refs
            .iter()
            .map(|s| path_data(s).unwrap_or_else(|_| super::stroke::fallback_path(s)))
            .collect();
        let skeleton: Vec<_> = jobs
            .iter()
            .flat_map(|(e, _)| e.pieces.iter().cloned())
            .collect();
        std::fs::write(p, super::stroke::svg(refs, &skeleton, &d.join(" "), true))
            .map_err(|e| bad("--svg", e))?;
    }
    Ok(())
}

/// Everything the printed report (JSON or text) shows.
struct Report<'a> {
    a: &'a StrokeArgs,
    jobs: &'a [(&'a SvgElement, Rational)],
    strokes: &'a [(Stroke, f64)],
    decided: &'a [bool],
    secs: f64,
    verdict: &'a str,
    approx: &'a InputApprox,
    /// What the document holds that draws nothing (dots with butt caps).
    notes: &'a [String],
}

impl Report<'_> {
    /// The `--json` document.
    fn json(&self) -> serde_json::Value {
        let Report {
            a,
            jobs,
            strokes,
            decided,
            secs,
            verdict,
            approx,
            notes,
        } = self;
        let elements: Vec<serde_json::Value> = jobs
            .iter()
            .zip(strokes.iter())
            .zip(decided.iter())
            .map(|(((e, r), (s, t)), d)| {
                let mut v = stroke_json(s, &format!("circle:{}", q(r)));
                v["at"] = json!(e.at);
                v["pen_radius"] = json!(q(r));
                v["stroke_width"] = json!(q(&e.stroke_width));
                v["input_approximation"] = still_approximated(a, e).to_json();
                v["seconds"] = json!(t);
                v["verdict"] = json!(if *d { "proven" } else { "undecided" });
                v
            })
            .collect();
        json!({
            "elements": elements,
            "seconds": secs,
            "tol": a.tol,
            "verdict": verdict,
            "input_approximation": approx.to_json(),
            "notes": notes,
        })
    }

    /// The text report.
    fn text(&self) -> String {
        let Report {
            jobs,
            strokes,
            decided,
            secs,
            verdict,
            approx,
            notes,
            ..
        } = self;
        let mut out = super::curve_input::input_line("input", approx).unwrap_or_default();
        let _ = writeln!(
            out,
            "{} element(s) stroked with their own stroke-width, {:.2} s",
            jobs.len(),
            secs
        );
        for (((e, r), (s, t)), d) in jobs.iter().zip(strokes.iter()).zip(decided.iter()) {
            let _ = writeln!(
                out,
                "element {} (pen circle:{}): {}",
                e.at,
                q(r),
                if *d { "proven" } else { "undecided" }
            );
            for line in stroke_text(s, *t).lines() {
                let _ = writeln!(out, "  {line}");
            }
        }
        for n in notes.iter() {
            let _ = writeln!(out, "note: {n}");
        }
        let _ = writeln!(out, "verdict: {verdict}");
        out
    }
}
