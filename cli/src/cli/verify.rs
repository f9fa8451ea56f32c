//! `lncert verify CERT [--against A B] [--json]`: re-checks a tolerance
//! certificate written by `lncert hausdorff --certificate` or `lncert offset
//! --certificate` (see [`lncert::certify::cert`] for the format) with the
//! independent checker [`lncert::certify::verify`], without searching, and
//! prints the statement it proved with both shapes described.
//!
//! `--against A B` (shape files in any accepted input form) also confirms that
//! the certificate speaks about exactly those shapes, compared as exact
//! geometry ([`lncert::shape::ShapeDesc::same_as`]: pieces may be split,
//! degrees elevated, arc directions scaled).
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
use super::hausdorff::read_shape_reported;
use super::{print_out, CliError};
use lncert::certify::verify::{verify, Invalid};
use lncert::certify::verify_against;
use lncert::scalar::{interval_from_rational, Interval, IntervalExt, Rational};
use lncert::shape::{format_up, InputApprox};
use serde_json::json;
use std::io::Read;
use std::path::PathBuf;

/// Arguments of `lncert verify`.
#[derive(clap::Args, Debug)]
pub struct VerifyArgs {
    /// The certificate file.
    pub cert: PathBuf,
    /// Also check that the certificate is about these two shapes (files: JSON
    /// shapes, curves or SVG path data), in this order.
    #[arg(long, num_args = 2, value_names = ["A", "B"])]
    pub against: Option<Vec<PathBuf>>,
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
    if file.metadata().map(|m| m.len() > limit).unwrap_or(false) {
        return Ok(Err(too_big()));
    }
    let mut bytes = Vec::new();
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

/// Runs the command; returns the exit code.
pub fn run(a: &VerifyArgs) -> Result<i32, CliError> {
    // every input is read and checked before any work
    let text = read_cert(&a.cert)?;
    let against = match &a.against {
        Some(files) => Some((
            read_shape_reported("--against A", &files[0])?,
            read_shape_reported("--against B", &files[1])?,
        )),
        None => None,
    };
    let start = std::time::Instant::now();
    let res = text.and_then(|text| match &against {
        Some(((sa, _), (sb, _))) => verify_against(&text, sa, sb),
        None => verify(&text),
    });
    let secs = start.elapsed().as_secs_f64();
    // shapes read as approximations: the certificate is not about the exact ones
    let approx = match (&res, &against) {
        (Ok(v), Some(((_, xa), (_, xb)))) => approximated(&v.tol, xa, xb),
        _ => None,
    };
    let code = i32::from(res.is_err() || approx.is_some());
    if a.json {
        let doc = match &res {
            Ok(v) => {
                let mut doc = json!({
                    "valid": approx.is_none(),
                    "certificate_valid": true,
                    "statement": {"claim": "d_H(A, B) <= tol", "tol": v.tol.to_string(), "a": v.a, "b": v.b},
                    "against": against.is_some(),
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
                    (None, Some(_)) => "A and B are exactly the shapes given to --against\n".into(),
                    (None, None) => String::new(),
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
