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
//! Exit codes: 0 = valid (and, with `--against`, about those shapes);
//! 1 = invalid, or about other shapes (the first failing field or box is named);
//! 2 = a file cannot be read, or a shape given to `--against` is bad input.

use super::args::bad;
use super::hausdorff::read_shape;
use super::{print_out, CliError};
use lncert::certify::verify::{verify, Invalid};
use lncert::json::Limits;
use lncert::shape::ShapeDesc;
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

/// Reads the certificate, refusing files over the reader's byte limit before
/// reading them (and again while reading, should the file grow).
fn read_cert(path: &PathBuf) -> Result<Vec<u8>, CliError> {
    let limit = Limits::DEFAULT.max_bytes as u64;
    let file =
        std::fs::File::open(path).map_err(|e| bad("CERT", format!("{}: {e}", path.display())))?;
    let too_big = || {
        bad(
            "CERT",
            format!("{}: larger than the limit of {limit} bytes", path.display()),
        )
    };
    if file.metadata().map(|m| m.len() > limit).unwrap_or(false) {
        return Err(too_big());
    }
    let mut bytes = Vec::new();
    file.take(limit + 1)
        .read_to_end(&mut bytes)
        .map_err(|e| bad("CERT", format!("{}: {e}", path.display())))?;
    if bytes.len() as u64 > limit {
        return Err(too_big());
    }
    Ok(bytes)
}

/// The certificate's shapes against the user's, exactly.
fn check_against(text: &str, a: &ShapeDesc, b: &ShapeDesc) -> Result<(), Invalid> {
    // the certificate is valid, so its shapes are canonical and read by the
    // user-language reader too (tests/shape_language.rs keeps the two in step)
    let doc = lncert::json::parse(text, &Limits::DEFAULT).map_err(|e| Invalid {
        at: e.path,
        reason: e.reason,
    })?;
    for (key, mine) in [("a", a), ("b", b)] {
        let theirs = doc
            .get(key)
            .ok_or_else(|| Invalid {
                at: key.into(),
                reason: "missing".into(),
            })
            .and_then(|v| {
                ShapeDesc::from_value(&v.to_value()).map_err(|e| Invalid {
                    at: key.into(),
                    reason: e.to_string(),
                })
            })?;
        theirs.same_as(mine).map_err(|why| Invalid {
            at: key.to_string(),
            reason: format!(
                "the certificate is about another shape than --against {}: {why}",
                key.to_uppercase()
            ),
        })?;
    }
    Ok(())
}

/// Runs the command; returns the exit code.
pub fn run(a: &VerifyArgs) -> Result<i32, CliError> {
    // every input is read and checked before any work
    let bytes = read_cert(&a.cert)?;
    let against = match &a.against {
        Some(files) => Some((
            read_shape("--against A", &files[0])?,
            read_shape("--against B", &files[1])?,
        )),
        None => None,
    };
    let text =
        std::str::from_utf8(&bytes).map_err(|e| bad("CERT", format!("not UTF-8 text: {e}")))?;
    let start = std::time::Instant::now();
    let res = verify(text).and_then(|v| {
        if let Some((sa, sb)) = &against {
            check_against(text, sa, sb)?;
        }
        Ok(v)
    });
    let secs = start.elapsed().as_secs_f64();
    let code = i32::from(res.is_err());
    if a.json {
        let doc = match &res {
            Ok(v) => json!({
                "valid": true,
                "statement": {"claim": "d_H(A, B) <= tol", "tol": v.tol.to_string(), "a": v.a, "b": v.b},
                "against": against.is_some(),
                "max_bound": v.max_bound,
                "boxes": v.boxes,
                "seconds": secs,
            }),
            Err(e) => json!({"valid": false, "at": e.at, "reason": e.reason, "seconds": secs}),
        };
        print_out(&format!(
            "{}\n",
            serde_json::to_string_pretty(&doc).unwrap_or_default()
        ));
    } else {
        match &res {
            Ok(v) => print_out(&format!(
                "valid: proven {}\n{}({} boxes re-checked, largest bound {:e}, {:.3} ms)\n",
                v.statement(),
                if against.is_some() {
                    "A and B are exactly the shapes given to --against\n"
                } else {
                    ""
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
