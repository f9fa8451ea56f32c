//! `lncert audit [--cases N] [--seed S] [--json]`: the differential checks of
//! [`lncert_cli::audit`] on seeded generated cases, one row per kernel family.
//!
//! Exit code 0 when the certified path never failed (no interval decision
//! contradicting the exact one, no f64 value outside its enclosure, no engine
//! decision contradicting the direct root-isolation check), else 1.

use super::{print_out, CliError};
use lncert_cli::audit::{run_kernel, KernelStats, KERNELS};
use serde_json::json;
use std::fmt::Write as _;
use std::io::Write as _;

/// Arguments of `lncert audit`.
#[derive(clap::Args, Debug)]
pub struct AuditArgs {
    /// Generated cases per kernel family.
    #[arg(long, default_value_t = 2000)]
    pub cases: usize,
    /// Seed of the deterministic case generator.
    #[arg(long, default_value_t = 1)]
    pub seed: u64,
    /// Print one JSON document `{"kernels": [...]}`.
    #[arg(long)]
    pub json: bool,
}

/// Cases per progress step.
const CHUNK: usize = 250;

/// Runs the command; returns the exit code.
pub fn run(a: &AuditArgs) -> Result<i32, CliError> {
    if a.cases == 0 || a.cases > 10_000_000 {
        return Err(super::args::bad(
            "--cases",
            format!("{} is out of range (1 to 10000000)", a.cases),
        ));
    }
    let total = a.cases * KERNELS.len();
    let mut done = 0;
    let mut rows = Vec::new();
    for (k, name) in KERNELS.iter().enumerate() {
        let mut st = KernelStats::new(name);
        let mut left = a.cases;
        let mut chunk_seed = a
            .seed
            .wrapping_mul(0x100_0000)
            .wrapping_add(k as u64 * 0x1_0000);
        while left > 0 {
            let n = left.min(CHUNK);
            st.merge(&run_kernel(name, n, chunk_seed));
            chunk_seed += 1;
            left -= n;
            done += n;
            progress(done, total, name);
        }
        rows.push(st);
    }
    if std::io::IsTerminal::is_terminal(&std::io::stderr()) {
        eprint!("\r{:60}\r", "");
    }
    if a.json {
        print_json(&rows);
    } else {
        print_table(&rows);
    }
    Ok(if rows.iter().all(KernelStats::certified_ok) {
        super::EXIT_OK
    } else {
        super::EXIT_REFUTED
    })
}

/// A progress bar on stderr (only when stderr is a terminal).
fn progress(done: usize, total: usize, name: &str) {
    use std::io::IsTerminal;
    if !std::io::stderr().is_terminal() {
        return;
    }
    let width = 30;
    let filled = done * width / total.max(1);
    let _ = write!(
        std::io::stderr(),
        "\r[{}{}] {:>3}% {name:<8}",
        "#".repeat(filled),
        ".".repeat(width - filled),
        done * 100 / total.max(1)
    );
    let _ = std::io::stderr().flush();
}

fn print_table(rows: &[KernelStats]) {
    let mut s = String::new();
    let _ = writeln!(
        s,
        "audit: f64 and interval paths against the exact path, per kernel family"
    );
    let _ = writeln!(
        s,
        "{:<8} {:>7} {:>9} {:>10} {:>10} {:>9} {:>12} {:>12} {:>9} {:>8}",
        "kernel",
        "cases",
        "decisions",
        "certified",
        "f64 wrong",
        "f64 fail",
        "f64 band",
        "max f64 ulp",
        "fallback",
        "direct"
    );
    for r in rows {
        let _ = writeln!(
            s,
            "{:<8} {:>7} {:>9} {:>10} {:>10} {:>9} {:>12.3e} {:>12.3e} {:>8.2}% {:>8}",
            r.name,
            r.cases,
            r.decisions,
            r.disagreements_certified,
            r.f64_decision_errors,
            r.f64_failures,
            r.f64_error_band,
            r.max_f64_error_ulps,
            100.0 * r.fallback_rate(),
            r.direct_disagreements
        );
    }
    let _ = writeln!(
        s,
        "certified = interval/exact contradictions + f64 values outside their enclosure (must be 0); f64 band = largest relative\n\
         distance to a decision boundary at which f64 decided wrongly; f64 fail = f64 could not evaluate (overflow/underflow);\n\
         direct = engine vs root isolation (must be 0); fallback = decisions the interval filter left to exact arithmetic"
    );
    for r in rows.iter().filter(|r| r.first_failure.is_some()) {
        let _ = writeln!(
            s,
            "FAILURE in {}: {}",
            r.name,
            r.first_failure.as_deref().unwrap_or("")
        );
    }
    print_out(&s);
}

fn print_json(rows: &[KernelStats]) {
    let kernels: Vec<_> = rows
        .iter()
        .map(|r| {
            json!({
                "name": r.name,
                "cases": r.cases,
                "rejected": r.rejected,
                "decisions": r.decisions,
                "disagreements_certified": r.disagreements_certified,
                "direct_disagreements": r.direct_disagreements,
                "f64_decision_errors": r.f64_decision_errors,
                "f64_failures": r.f64_failures,
                "f64_error_band": r.f64_error_band,
                "max_f64_error_ulps": r.max_f64_error_ulps,
                "fallback_rate": r.fallback_rate(),
                "first_failure": r.first_failure,
            })
        })
        .collect();
    print_out(&format!("{}\n", json!({ "kernels": kernels })));
}
