//! `lncert hausdorff A B [--rel R] [--tol T] [--certificate OUT] [--json]`:
//! certified bounds on the Hausdorff distance of two shapes (see
//! [`lncert::certify`]), a verdict on a claimed tolerance, and its certificate.
//!
//! Shapes are files holding a curve (`{"bezier": [[x, y], ...]}`,
//! `{"beziers": [...]}` or SVG path data), an arc
//! (`{"arc": {"center": [x, y], "radius": r, "from": [dx, dy], "to": [dx, dy]}}`,
//! counter-clockwise), an offset (`{"offset": {"curve": CURVE, "distance": r}}`)
//! or a convolution with an ellipse
//! (`{"convolution": {"curve": CURVE, "ellipse": [[m11, m12], [m21, m22]], "side": 1}}`).
//!
//! SVG elliptical arcs, `<circle>`, `<ellipse>` and rounded `<rect>` are read as
//! cubic pieces within a certified bound (see [`lncert::shape::InputApprox`]); the
//! report then says so per shape (`input A: … approximated …`) and the bounds
//! and verdict are about the approximated shapes. With JSON:
//! `"input_approximation": {"elements", "bound", "a", "b"}` (`null` when both
//! shapes are exactly the input), `bound` the sum of the two shapes' bounds, so
//! `d_H` of the exact inputs lies in `[lo − bound, hi + bound]`.
//!
//! Exit codes: 0 = with `--tol` certified, without it the gap reached; 1 = with
//! `--tol` refuted; 3 = undecided (the budget ran out first; the bounds printed
//! are still sound); 2 = bad input.

use super::args::{bad, number};
use super::curve_input::MAX_FILE_BYTES;
use super::{print_report, CliError, EXIT_OK, EXIT_REFUTED, EXIT_UNDECIDED};
use lncert::certify::{hausdorff, Certificate, Config, HausdorffBounds, OneSided};
use lncert::scalar::interval_from_rational;
use lncert::shape::{InputApprox, ShapeDesc};
use lncert::stroke::StrokeShape;
use lncert::Tolerance;
use serde_json::json;
use std::path::{Path, PathBuf};

/// Arguments of `lncert hausdorff`.
#[derive(clap::Args, Debug)]
pub struct HausdorffArgs {
    /// First shape (JSON or SVG path data file).
    pub a: PathBuf,
    /// Second shape.
    pub b: PathBuf,
    /// Stop when hi − lo ≤ rel·hi (1e-12 to 0.5).
    #[arg(long, default_value = "1e-3")]
    pub rel: String,
    /// A claimed tolerance: certify d_H ≤ TOL (exit 0) or refute it (exit 1). Read exactly.
    #[arg(long)]
    pub tol: Option<String>,
    /// Write the certificate of d_H ≤ TOL here (needs --tol).
    #[arg(long)]
    pub certificate: Option<PathBuf>,
    /// Box budget per direction.
    #[arg(long, default_value_t = 200_000)]
    pub max_boxes: usize,
    /// With a stroke shape (`{"stroke": …}`): the tolerance of the proven
    /// outline the bounds go through (default TOL/16, or a thousandth of the
    /// pen's size without --tol).
    #[arg(long)]
    pub stroke_tol: Option<String>,
    /// Print one JSON document.
    #[arg(long)]
    pub json: bool,
}

fn parse_shape(flag: &str, path: &Path, text: &str) -> Result<(ShapeDesc, InputApprox), CliError> {
    ShapeDesc::parse_reported(text).map_err(|e| bad(flag, format!("{}: {e}", path.display())))
}

/// A shape argument: an exact shape, or the exact boundary of a stroke.
pub(crate) enum Arg {
    Shape(ShapeDesc, InputApprox),
    Stroke(StrokeShape, InputApprox),
}

fn read_arg(flag: &str, path: &Path) -> Result<Arg, CliError> {
    let text = super::curve_input::read_text_limited(flag, path, MAX_FILE_BYTES)?;
    if let Some((s, ap)) = StrokeShape::parse_reported(&text)
        .map_err(|e| bad(flag, format!("{}: {e}", path.display())))?
    {
        return Ok(Arg::Stroke(s, ap));
    }
    let (s, ap) = parse_shape(flag, path, &text)?;
    Ok(Arg::Shape(s, ap))
}

/// `{"elements", "bound", "a", "b"}` of both shapes' approximations (the
/// bound their sum, rounded up), or `null` when both are exact.
pub(crate) fn approx_json(a: &InputApprox, b: &InputApprox) -> serde_json::Value {
    if a.is_empty() && b.is_empty() {
        return serde_json::Value::Null;
    }
    json!({
        "elements": a.elements.len() + b.elements.len(),
        "bound": a.combined_bound(b),
        "a": a.to_json(),
        "b": b.to_json(),
    })
}

fn one_json(d: &OneSided) -> serde_json::Value {
    json!({
        "lo": d.lo, "hi": d.hi,
        "boxes": d.boxes.len(), "evaluated": d.evaluated,
        "witness": d.witness.map(|(p, s)| json!({"piece": p, "s": s})),
        "incomplete": d.incomplete,
    })
}

/// Runs the command; returns the exit code.
pub fn run(a: &HausdorffArgs) -> Result<i32, CliError> {
    let (rel_f, tol) = checked_flags(a)?;
    let (sa, approx_a, sb, approx_b) =
        match (read_arg("A", &a.a)?, read_arg("B", &a.b)?) {
            (Arg::Shape(sa, pa), Arg::Shape(sb, pb)) => (sa, pa, sb, pb),
            (Arg::Stroke(..), Arg::Stroke(..)) => return Err(bad(
                "B",
                "at most one shape may be a stroke (the other is the outline it is compared with)",
            )),
            (x, y) => return super::hausdorff_stroke::run(a, x, y, rel_f, tol),
        };
    // The search compares f64 bounds with the largest f64 ≤ tol (sound).
    let tol_f = tol.as_ref().map(Tolerance::value);
    let cfg = Config {
        rel: rel_f,
        max_boxes: a.max_boxes,
        tol: tol.clone(),
        ..Config::default()
    };
    let start = std::time::Instant::now();
    let r = hausdorff(&sa, &sb, &cfg).map_err(|e| CliError {
        field: e.field,
        reason: e.reason,
    })?;
    let elapsed = start.elapsed();
    let verdict = tol_f.map(|t| {
        if r.hi <= t {
            "certified"
        } else if r.lo > t {
            "refuted"
        } else {
            "undecided"
        }
    });
    let cert_note = match (&a.certificate, &tol) {
        (Some(path), Some(t)) => write_certificate(path, &sa, &sb, t, &r)?,
        _ => None,
    };
    let report = Report {
        r: &r,
        shapes: (&sa, &sb),
        approx: (&approx_a, &approx_b),
        rel_f,
        tol: &tol,
        verdict,
        cert_note: &cert_note,
        seconds: elapsed.as_secs_f64(),
    };
    print_report(a.json, || report.json(), || report.text());
    Ok(match verdict {
        Some("certified") => EXIT_OK,
        Some("refuted") => EXIT_REFUTED,
        Some(_) => EXIT_UNDECIDED,
        // no claim: the bounds are all there is; incomplete when the budget
        // stopped the search before the gap was reached
        None if r.incomplete() => EXIT_UNDECIDED,
        None => EXIT_OK,
    })
}

/// The flags checked before any work: returns `--rel` (as a float) and
/// `--tol` (exact).
fn checked_flags(a: &HausdorffArgs) -> Result<(f64, Option<Tolerance>), CliError> {
    if let Some(path) = &a.certificate {
        super::args::output_file("--certificate", path)?;
    }
    let rel = number("--rel", &a.rel)?;
    let rel_f = interval_from_rational(&rel).sup();
    if !(1e-12..=0.5).contains(&rel_f) {
        return Err(bad("--rel", "must be between 1e-12 and 0.5"));
    }
    let tol = a.tol.as_deref().map(super::args::tolerance).transpose()?;
    if let Some(t) = &tol {
        if interval_from_rational(t.exact()).sup() > lncert::shape::MAX_COORDINATE {
            return Err(bad("--tol", "absurdly large"));
        }
    }
    if a.certificate.is_some() && tol.is_none() {
        return Err(bad(
            "--certificate",
            "needs --tol (a certificate proves a claimed tolerance)",
        ));
    }
    if a.max_boxes == 0 || a.max_boxes > 50_000_000 {
        return Err(bad("--max-boxes", "out of range (1 to 50000000)"));
    }
    Ok((rel_f, tol))
}

/// `--certificate`: writes it when `d_H ≤ t` is certified; returns the note
/// printed about it.
fn write_certificate(
    path: &Path,
    sa: &ShapeDesc,
    sb: &ShapeDesc,
    t: &Tolerance,
    r: &HausdorffBounds,
) -> Result<Option<String>, CliError> {
    Ok(match Certificate::new(sa, sb, t, r) {
        Some(c) => {
            std::fs::write(path, c.to_json_string())
                .map_err(|e| bad("--certificate", format!("{}: {e}", path.display())))?;
            // a radial certificate the verifier did not confirm: Certificate::new
            // proved the claim again by a proof it states
            let again = if r.radial.is_some() && !c.is_radial() {
                ", the claim proven again by the parametric proof or the search, which the certificate states"
            } else {
                ""
            };
            let what = if c.is_radial() {
                "radial cells"
            } else {
                "boxes"
            };
            Some(format!(
                "written to {} ({} {what}{again})",
                path.display(),
                c.box_count()
            ))
        }
        None => Some("not written: the tolerance is not certified".to_string()),
    })
}

/// Everything the printed report (JSON or text) shows.
struct Report<'a> {
    r: &'a HausdorffBounds,
    /// A and B.
    shapes: (&'a ShapeDesc, &'a ShapeDesc),
    /// What of A and B was approximated.
    approx: (&'a InputApprox, &'a InputApprox),
    rel_f: f64,
    tol: &'a Option<Tolerance>,
    verdict: Option<&'a str>,
    cert_note: &'a Option<String>,
    seconds: f64,
}

impl Report<'_> {
    /// The `--json` document.
    fn json(&self) -> serde_json::Value {
        let Report {
            r,
            approx: (approx_a, approx_b),
            rel_f,
            tol,
            verdict,
            cert_note,
            ..
        } = self;
        json!({
            "lo": r.lo, "hi": r.hi,
            "a_to_b": one_json(&r.a_to_b), "b_to_a": one_json(&r.b_to_a),
            "rel": rel_f,
            "tol": tol.as_ref().map(|t| t.to_string()),
            "verdict": verdict,
            "incomplete": r.incomplete(),
            "proof": if r.parametric.is_some() {
                "parametric"
            } else if r.radial.is_some() {
                "radial"
            } else {
                "search"
            },
            "parametric_boxes": r.parametric.as_ref().map(|p| p.boxes.len()),
            "certificate": cert_note,
            "seconds": self.seconds,
            "input_approximation": approx_json(approx_a, approx_b),
        })
    }

    /// The text report.
    fn text(&self) -> String {
        let Report {
            r,
            shapes: (sa, sb),
            approx: (approx_a, approx_b),
            tol,
            verdict,
            cert_note,
            ..
        } = self;
        let mut out = String::new();
        out += &format!("A: {}\nB: {}\n", sa.summary(), sb.summary());
        for (name, ap) in [("input A", approx_a), ("input B", approx_b)] {
            if let Some(line) = super::curve_input::input_line(name, ap) {
                out += &line;
            }
        }
        out += &format!(
            "d_H(A, B) ∈ [{:e}, {:e}]  (certified bounds, gap {:.2e})\n",
            r.lo,
            r.hi,
            r.hi - r.lo
        );
        out += &text_directions(r);
        if r.incomplete() {
            out += "note: the box budget or the float resolution stopped the search; the bounds are sound but wider than asked\n";
        }
        if let (Some(v), Some(t)) = (verdict, tol) {
            out += &format!("verdict: {v} (d_H ≤ {t}?)\n");
        }
        if let Some(n) = cert_note {
            out += &format!("certificate: {n}\n");
        }
        out += &format!("time: {:.3} ms\n", self.seconds * 1e3);
        out
    }
}

/// The proof's lines: the parametric cover, the radial proof, or the two directions' searches.
fn text_directions(r: &HausdorffBounds) -> String {
    let mut out = String::new();
    if let Some(p) = &r.parametric {
        out += &format!(
            "  proof: parametric, one cover of {} boxes for both directions ({} evaluated)\n",
            p.boxes.len(),
            p.evaluated
        );
    }
    if let Some(p) = &r.radial {
        out += &format!(
            "  proof: radial, each piece of the {} lies in the sector of its end rays and they sweep the arcs' directions: d_H is its largest radial distance to the circle ({} Bernstein splits)\n",
            if p.curve_is_a { "curve A" } else { "curve B" },
            p.splits
        );
    }
    for (name, d) in [("h(A→B)", &r.a_to_b), ("h(B→A)", &r.b_to_a)] {
        if (r.parametric.is_some() || r.radial.is_some()) && d.witness.is_none() {
            continue;
        }
        out += &format!(
            "  {name} ∈ [{:e}, {:e}]  {} boxes",
            d.lo,
            d.hi,
            d.boxes.len()
        );
        if let Some((p, s)) = d.witness {
            out += &format!(", witness piece {p} at s = {s}");
        }
        out += "\n";
    }
    out
}
