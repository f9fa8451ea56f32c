//! `lncert verify CERT [--json]`: re-checks a tolerance certificate written by
//! `lncert hausdorff --certificate` (see [`lncert::certify::cert`] for the format)
//! with the independent checker [`lncert::certify::verify`], without searching.
//!
//! Exit codes: 0 = valid, 1 = invalid (the first failing field or box is named),
//! 2 = the file cannot be read or is not JSON.

use super::args::bad;
use super::{print_out, CliError};
use lncert::certify::verify::verify;
use serde_json::json;
use std::path::PathBuf;

/// Arguments of `lncert verify`.
#[derive(clap::Args, Debug)]
pub struct VerifyArgs {
    /// The certificate file.
    pub cert: PathBuf,
    /// Print one JSON document.
    #[arg(long)]
    pub json: bool,
}

/// Runs the command; returns the exit code.
pub fn run(a: &VerifyArgs) -> Result<i32, CliError> {
    let meta = std::fs::metadata(&a.cert)
        .map_err(|e| bad("CERT", format!("{}: {e}", a.cert.display())))?;
    if meta.len() > 512 << 20 {
        return Err(bad("CERT", "larger than 512 MiB"));
    }
    let text = std::fs::read_to_string(&a.cert)
        .map_err(|e| bad("CERT", format!("{}: {e}", a.cert.display())))?;
    let doc: serde_json::Value =
        serde_json::from_str(&text).map_err(|e| bad("CERT", format!("malformed JSON: {e}")))?;
    let start = std::time::Instant::now();
    let res = verify(&doc);
    let secs = start.elapsed().as_secs_f64();
    let code = i32::from(res.is_err());
    if a.json {
        let doc = match &res {
            Ok(v) => {
                json!({"valid": true, "tol": v.tol.to_string(), "max_bound": v.max_bound, "boxes": v.boxes, "seconds": secs})
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
                "valid: d_H ≤ {} proven ({} boxes re-checked, largest bound {:e}, {:.3} ms)\n",
                v.tol,
                v.boxes,
                v.max_bound,
                secs * 1e3
            )),
            Err(e) => print_out(&format!("invalid: {e}\n")),
        }
    }
    Ok(code)
}
