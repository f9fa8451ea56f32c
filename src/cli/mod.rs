//! The `lncert` command line (the contract is in `DESIGN.md`, "The CLI contract").
//!
//! * `lncert reproduce [--json] [--out DIR]` — every claim of [`lncert::reproduce`];
//! * `lncert prop ID [ARGS] [--json]` — one proposition on user data;
//! * `lncert audit [--cases N] [--seed S] [--json]` — the float path audited;
//! * `lncert hausdorff A B [--rel R] [--tol T] [--certificate OUT] [--json]` — certified
//!   Hausdorff bounds and tolerance certificates;
//! * `lncert offset CURVE --distance R --tol T [--method g2|ln-pair] [--certificate OUT] [--svg OUT]
//!   [--global-bounds] [--no-certify] [--json]` — an offset approximant proven within a tolerance;
//! * `lncert verify CERT [--against A B] [--json]` — the independent certificate check, and
//!   whether it speaks about the shapes `A`, `B`.
//! * `lncert tangency --x1 X --y1 Y --u U --center OX,OY --radius R [...]` —
//!   quartic LN curves tangent to a circle (seed 003 §4).
//!
//! Exit codes: 0 = certified / the proposition agrees with the direct check,
//! 1 = refuted / erratum / undecided, 2 = bad input (message on stderr naming
//! the field and the reason; never a panic).
//!
//! | module | content |
//! |---|---|
//! | [`args`] | exact parsing of numbers, points, frames, coefficient lists, τ |
//! | [`report`] | one result as text lines or one JSON document, and its exit code |
//! | [`reproduce`] | `lncert reproduce` |
//! | [`svg`] | the Fig. 5 pictures of `reproduce --out` |
//! | [`prop`] | `lncert prop`: ID resolution and one module per seed |
//! | [`audit`] | `lncert audit` |
//! | [`tangency`] | `lncert tangency` |
//! | [`offset`], [`offset_svg`] | `lncert offset` and its picture |

pub mod args;
pub mod audit;
pub mod hausdorff;
pub mod offset;
pub mod offset_svg;
pub mod prop;
pub mod report;
pub mod reproduce;
pub mod svg;
pub mod tangency;
pub mod verify;

use clap::{Parser, Subcommand};

/// Exit code for bad input.
pub const EXIT_BAD_INPUT: i32 = 2;

/// Proven answers about planar curves with linear normals (LN curves).
#[derive(Parser, Debug)]
#[command(name = "lncert", version, about)]
pub struct Cli {
    #[command(subcommand)]
    pub command: Command,
}

/// The subcommands.
#[derive(Subcommand, Debug)]
pub enum Command {
    /// Recompute every worked example and printed value of the seeds, with verdicts.
    Reproduce(reproduce::ReproduceArgs),
    /// Check one proposition on given data (numbers are read exactly: 0.95 is 19/20).
    Prop(Box<prop::PropArgs>),
    /// Audit the f64 and interval paths against the exact path on generated cases.
    Audit(audit::AuditArgs),
    /// Certified bounds [lo, hi] on the Hausdorff distance of two shapes; with --tol a verdict and a certificate.
    Hausdorff(Box<hausdorff::HausdorffArgs>),
    /// An offset approximant proven within a tolerance (seed 004 G2 or seed 000 LN pairs).
    Offset(Box<offset::OffsetArgs>),
    /// Re-check a Hausdorff tolerance certificate without searching.
    Verify(verify::VerifyArgs),
    /// Quartic LN curves tangent to a circle (seed 003 §4): all solutions, proven.
    Tangency(Box<tangency::TangencyArgs>),
}

/// A bad-input error: the message names the field and the reason (exit code 2).
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct CliError(pub String);

impl std::fmt::Display for CliError {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.write_str(&self.0)
    }
}

/// Writes `text` to stdout, ignoring write errors (a closed pipe, as in
/// `lncert reproduce | head`, must not panic).
pub fn print_out(text: &str) {
    use std::io::Write;
    let mut out = std::io::stdout().lock();
    let _ = out.write_all(text.as_bytes()).and_then(|_| out.flush());
}

/// Runs a parsed command line and returns the process exit code.
pub fn run(cli: Cli) -> i32 {
    let result = match cli.command {
        Command::Reproduce(a) => reproduce::run(&a),
        Command::Prop(a) => prop::run(&a),
        Command::Audit(a) => audit::run(&a),
        Command::Hausdorff(a) => hausdorff::run(&a),
        Command::Offset(a) => offset::run(&a),
        Command::Verify(a) => verify::run(&a),
        Command::Tangency(a) => tangency::run(&a),
    };
    match result {
        Ok(code) => code,
        Err(e) => {
            eprintln!("error: {e}");
            EXIT_BAD_INPUT
        }
    }
}
