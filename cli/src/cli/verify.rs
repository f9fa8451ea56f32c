//! `lncert verify CERT [--against [A] B] [--pen circle:R|ellipse:A,B[,θ]] [--tol T] [--json]`:
//! re-checks a certificate written by `lncert hausdorff --certificate`,
//! `lncert offset --certificate` or `lncert stroke --certificate` (see
//! [`lncert::certify::cert`] for the format) with the independent checker
//! [`lncert::certify::verify`], without searching, and prints the statement it
//! proved with both shapes described.
//!
//! A valid certificate proves *its* statement; these options confirm that it
//! is the statement the user wants ([`lncert::certify::verify_expecting`]),
//! else it is invalid (exit 1) at the field that differs:
//! - `--against A B` (shape files in any accepted input form): the certificate
//!   speaks about exactly those shapes, compared as exact geometry
//!   ([`lncert::shape::ShapeDesc::same_as`]: pieces may be split, degrees
//!   elevated, arc directions scaled). For a stroke certificate A is the
//!   outline and B the stroked curve; for a stroke distance certificate A is
//!   the shape measured and B the curve. With one file, it is B alone (e.g.
//!   the curve a stroke certificate is about).
//! - `--pen`: the stroke's pen is this one (the same set `M · disk(1)`: equal
//!   `Q = M Mᵀ`); every member's, for a certificate set. An elliptical pen is
//!   built as `lncert stroke` builds it at `--tol`, which it then needs.
//! - `--tol T`: the certificate proves `d_H ≤ tol` with `tol ≤ T`.
//!
//! A shape file whose SVG arcs, circles, ellipses or rounded rects were read
//! as certified cubic approximations is compared as read (the certificate can
//! only hold the approximation): the verdict then says that the certificate is
//! about the approximation, not the exact shape, and what it proves for the
//! exact shapes (`d_H ≤ tol + ε`, `ε` the certified approximation bounds).
//!
//! Exit codes: 0 = valid (and, with `--against`, about exactly those shapes);
//! 1 = invalid (the first failing field or box is named; a document that is
//! not a certificate — not UTF-8, over the size limit — is invalid), about
//! other shapes, or about an approximation of an `--against` shape; 2 = a file
//! cannot be read, or a shape given to `--against` is bad input.

use super::args::bad;
use super::{print_out, CliError};
use lncert::certify::verify::Invalid;
use lncert::certify::{verify_expecting, Expected};
use lncert::scalar::{interval_from_rational, Interval, IntervalExt, Rational};
use lncert::shape::{format_up, InputApprox};
use lncert::stroke::PenShape;
use serde_json::json;
use std::io::Read;
use std::path::PathBuf;

/// Arguments of `lncert verify`.
#[derive(clap::Args, Debug)]
pub struct VerifyArgs {
    /// The certificate file.
    pub cert: PathBuf,
    /// Also check that the certificate is about these shapes (files: JSON
    /// shapes, curves or SVG path data): A and B in this order, or B alone
    /// (for a stroke certificate: the outline and the curve, or the curve).
    #[arg(long, num_args = 1..=2, value_names = ["A", "B"])]
    pub against: Option<Vec<PathBuf>>,
    /// Also check that a stroke certificate's pen is this one: `circle:R` or
    /// `ellipse:A,B[,θ]` (as `lncert stroke --pen`; an ellipse needs `--tol`).
    #[arg(long)]
    pub pen: Option<String>,
    /// Also check that the certificate proves this tolerance (its own
    /// tolerance is at most `T`).
    #[arg(long)]
    pub tol: Option<String>,
    /// Print one JSON document.
    #[arg(long)]
    pub json: bool,
}

/// The certificate's bytes: `Ok(Err(_))` when the file is read but is not a
/// certificate (over the reader's byte limit, checked before reading and again
/// while reading, should the file grow; or not UTF-8): that is an invalid
/// certificate (exit 1), not a file that cannot be read (exit 2).
fn read_cert(path: &PathBuf) -> Result<Result<String, Invalid>, CliError> {
    let limit = lncert::shape::MAX_INPUT_BYTES as u64;
    let file =
        std::fs::File::open(path).map_err(|e| bad("CERT", format!("{}: {e}", path.display())))?;
    let too_big = || Invalid {
        at: "(top level)".into(),
        reason: format!("not a certificate: larger than the limit of {limit} bytes"),
    };
    let size = file.metadata().map(|m| m.len()).ok();
    if size.is_some_and(|n| n > limit) {
        return Ok(Err(too_big()));
    }
    // read at the file's size (one allocation, no growth: part of the peak
    // memory that `verify` keeps within a multiple of the certificate's size)
    let mut bytes = Vec::with_capacity(size.map_or(0, |n| n as usize + 1));
    file.take(limit + 1)
        .read_to_end(&mut bytes)
        .map_err(|e| bad("CERT", format!("{}: {e}", path.display())))?;
    if bytes.len() as u64 > limit {
        return Ok(Err(too_big()));
    }
    Ok(String::from_utf8(bytes).map_err(|e| Invalid {
        at: "(top level)".into(),
        reason: format!("not a certificate: not UTF-8 text ({e})"),
    }))
}

/// What `--against` found out about shapes read as approximations.
struct Approximated {
    /// `A` and/or `B` with the report line of each.
    which: Vec<(&'static str, String)>,
    /// The sum of the certified approximation bounds (rounded up).
    bound: f64,
    /// `tol + bound`, rounded up: what the certificate proves for the exact shapes.
    tol_for_exact: f64,
}

fn approximated(tol: &Rational, a: &InputApprox, b: &InputApprox) -> Option<Approximated> {
    if a.is_empty() && b.is_empty() {
        return None;
    }
    let which = [("A", a), ("B", b)]
        .into_iter()
        .filter_map(|(k, x)| x.summary().map(|s| (k, s)))
        .collect();
    // d_H(A, B) ≤ d_H(A, A′) + d_H(A′, B′) + d_H(B′, B), added upward
    let bound = a.combined_bound(b);
    let tol_for_exact = match Interval::point(bound) {
        Some(e) => (interval_from_rational(tol) + e).sup(),
        None => f64::INFINITY,
    };
    Some(Approximated {
        which,
        bound,
        tol_for_exact,
    })
}

impl Approximated {
    fn reason(&self, tol: &Rational) -> String {
        let parts: Vec<String> = self
            .which
            .iter()
            .map(|(k, s)| format!("--against {k}: {s}"))
            .collect();
        format!(
            "the certificate is about the certified cubic approximation of the shape(s) given, not the exact shape(s) ({}): it proves d_H ≤ {tol} for the approximations, hence only d_H(A, B) ≤ {} (tol + {}) for the exact shapes given",
            parts.join("; "),
            format_up(self.tol_for_exact),
            format_up(self.bound),
        )
    }
}

/// One `--against` file: a shape, or the exact boundary of a stroke
/// `{"stroke": {"curve": CURVE, "pen": PEN}}` (the form `lncert hausdorff`
/// reads), which stands for its curve, read as a curve file is, and its pen.
fn read_against(
    flag: &str,
    path: &std::path::Path,
) -> Result<((lncert::shape::ShapeDesc, InputApprox), Option<PenShape>), CliError> {
    use super::curve_input::{read_text_limited, MAX_FILE_BYTES};
    let text = read_text_limited(flag, path, MAX_FILE_BYTES)?;
    let at = |e: &dyn std::fmt::Display| bad(flag, format!("{}: {e}", path.display()));
    if let Some((stroke, _)) =
        lncert::stroke::StrokeShape::parse_reported(&text).map_err(|e| at(&e))?
    {
        let doc: serde_json::Value = serde_json::from_str(text.trim()).map_err(|e| at(&e))?;
        let curve = match &doc["stroke"]["curve"] {
            serde_json::Value::String(s) => s.clone(),
            other => other.to_string(),
        };
        let shape = lncert::shape::ShapeDesc::parse_reported(&curve)
            .map_err(|e| at(&format!("stroke.curve: {e}")))?;
        return Ok((shape, Some(stroke.pen)));
    }
    let shape = lncert::shape::ShapeDesc::parse_reported(&text).map_err(|e| at(&e))?;
    Ok((shape, None))
}

/// The shapes of `--against`: `(A, B)`, `A` absent when one file is given.
type Against = (
    Option<(lncert::shape::ShapeDesc, InputApprox)>,
    (lncert::shape::ShapeDesc, InputApprox),
);

/// Runs the command; returns the exit code.
pub fn run(a: &VerifyArgs) -> Result<i32, CliError> {
    // every input is read and checked before any work
    let tol = match &a.tol {
        Some(t) => Some(super::args::tolerance(t)?),
        None => None,
    };
    let pen: Option<PenShape> = match (&a.pen, &tol) {
        (None, _) => None,
        (Some(p), Some(t)) => Some(super::pen::pen_shape(p, t.value())?),
        (Some(p), None) if p.starts_with("ellipse:") => {
            return Err(bad(
                "--pen",
                "an elliptical pen needs --tol: its rotation is represented exactly within an angle set by the tolerance, as `lncert stroke` builds it",
            ))
        }
        (Some(p), None) => Some(super::pen::pen_shape(p, 1.0)?),
    };
    let text = read_cert(&a.cert)?;
    // a stroke boundary {"stroke": …} given to --against is B (its curve),
    // and states the pen, in either position (as `lncert hausdorff` takes it)
    let (against, stroke_pen): (Option<Against>, Option<PenShape>) = match a.against.as_deref() {
        Some([b]) => {
            let (b, pen) = read_against("--against B", b)?;
            (Some((None, b)), pen)
        }
        Some([fa, fb]) => {
            let (x, pa) = read_against("--against A", fa)?;
            let (y, pb) = read_against("--against B", fb)?;
            match (pa, pb) {
                (Some(_), Some(_)) => {
                    return Err(bad(
                        "--against",
                        "both files are strokes: give the shape measured (or the outline) and one stroke",
                    ))
                }
                (Some(p), None) => (Some((Some(y), x)), Some(p)),
                (None, p) => (Some((Some(x), y)), p),
            }
        }
        Some(_) => return Err(bad("--against", "expected one or two shape files")),
        None => (None, None),
    };
    let pen =
        match (pen, stroke_pen) {
            (Some(p), Some(q)) if p.q() != q.q() => return Err(bad(
                "--pen",
                "differs from the pen of the stroke given to --against: no certificate states both",
            )),
            (p, q) => p.or(q),
        };
    let want = Expected {
        a: against
            .as_ref()
            .and_then(|(x, _)| x.as_ref().map(|(s, _)| s)),
        b: against.as_ref().map(|(_, (s, _))| s),
        pen: pen.as_ref(),
        tol: tol.as_ref().map(|t| t.exact()),
    };
    let start = std::time::Instant::now();
    let res = text.and_then(|text| verify_expecting(&text, &want));
    let secs = start.elapsed().as_secs_f64();
    // shapes read as approximations: the certificate is not about the exact ones
    let no_approx = InputApprox::default();
    let approx = match (&res, &against) {
        (Ok(v), Some((xa, (_, xb)))) => approximated(
            &v.tol,
            xa.as_ref().map(|(_, x)| x).unwrap_or(&no_approx),
            xb,
        ),
        _ => None,
    };
    // what was confirmed beyond the certificate's own statement
    let confirmed: Vec<&str> = [
        (against.is_some(), "shapes"),
        (pen.is_some(), "pen"),
        (tol.is_some(), "tol"),
    ]
    .into_iter()
    .filter_map(|(on, k)| on.then_some(k))
    .collect();
    let code = i32::from(res.is_err() || approx.is_some());
    if a.json {
        let doc = match &res {
            Ok(v) => {
                let mut doc = json!({
                    "valid": approx.is_none(),
                    "certificate_valid": true,
                    "statement": {"claim": "d_H(A, B) <= tol", "tol": v.tol.to_string(), "a": v.a, "b": v.b},
                    "against": against.is_some(),
                    "confirmed": confirmed,
                    "max_bound": v.max_bound,
                    "boxes": v.boxes,
                    "seconds": secs,
                });
                if let Some(x) = &approx {
                    doc["at"] = json!("against");
                    doc["reason"] = json!(x.reason(&v.tol));
                    doc["approximation_bound"] = json!(x.bound);
                    doc["tol_for_exact_shapes"] = json!(x.tol_for_exact);
                }
                doc
            }
            Err(e) => json!({"valid": false, "at": e.at, "reason": e.reason, "seconds": secs}),
        };
        print_out(&format!(
            "{}\n",
            serde_json::to_string_pretty(&doc).unwrap_or_default()
        ));
    } else {
        match &res {
            Ok(v) => print_out(&format!(
                "{}: proven {}\n{}({} boxes re-checked, largest bound {:e}, {:.3} ms)\n",
                if approx.is_some() {
                    "valid certificate, not about the exact shapes"
                } else {
                    "valid"
                },
                v.statement(),
                match (&approx, &against) {
                    (Some(x), _) => format!("{}\n", x.reason(&v.tol)),
                    (None, _) => confirmation(&confirmed, &against, &pen, &tol),
                },
                v.boxes,
                v.max_bound,
                secs * 1e3
            )),
            Err(e) => print_out(&format!("invalid: {e}\n")),
        }
    }
    Ok(code)
}

/// The line saying what `--against`, `--pen` and `--tol` confirmed.
fn confirmation(
    confirmed: &[&str],
    against: &Option<Against>,
    pen: &Option<PenShape>,
    tol: &Option<lncert::Tolerance>,
) -> String {
    if confirmed.is_empty() {
        return String::new();
    }
    let mut parts = Vec::new();
    match against {
        Some((Some(_), _)) => {
            parts.push("A and B are exactly the shapes given to --against".to_string())
        }
        Some((None, _)) => parts.push("B is exactly the shape given to --against".to_string()),
        None => {}
    }
    match pen {
        Some(PenShape::Circle(r)) => parts.push(format!("the pen is the disk of radius {r}")),
        Some(PenShape::Ellipse(p)) => parts.push(format!("the pen is {}", p.description)),
        None => {}
    }
    if let Some(t) = tol {
        parts.push(format!("the proven tolerance is at most {}", t.exact()));
    }
    format!("{}\n", parts.join("; "))
}
