//! The `lncert` command line (the contract is in `docs/architecture.md`, "The CLI contract";
//! the manual is `docs/cli.md`).
//!
//! * `lncert reproduce [--json] [--out DIR]` — every claim of [`lncert_cli::reproduce`];
//! * `lncert prop ID [ARGS] [--json]` — one proposition on user data;
//! * `lncert audit [--cases N] [--seed S] [--json]` — the float path audited;
//! * `lncert hausdorff A B [--rel R] [--tol T] [--certificate OUT] [--json]` — certified
//!   Hausdorff bounds and tolerance certificates;
//! * `lncert offset CURVE --distance R --tol T [--method g2|ln-pair] [--certificate OUT] [--svg OUT]
//!   [--out FILE.svg] [--global-bounds] [--no-certify] [--json]` — an offset approximant proven within a tolerance;
//! * `lncert stroke CURVE --pen circle:R --tol T [--cap round|butt] [--svg OUT] [--path-out OUT]
//!   [--out FILE.svg] [--json]` — the proven outline of a circular pen's stroke;
//! * `lncert font IN --offset D | --stroke R --tol T --out OUT.ufo [--glyphs SPEC] [--grid G]
//!   [--report FILE.json|FILE.html] [--jobs N] [--force] [--json]` — every glyph of a font
//!   offset or stroked, each proven, written as a UFO ([`font`]);
//! * `lncert verify CERT [--against A B] [--json]` — the independent certificate check, and
//!   whether it speaks about the shapes `A`, `B`.
//! * `lncert tangency --x1 X --y1 Y --u U --center OX,OY --radius R [...]` —
//!   quartic LN curves tangent to a circle (seed 003 §4).
//!
//! Exit codes, the same for every subcommand ([`EXIT_OK`], [`EXIT_REFUTED`],
//! [`EXIT_BAD_INPUT`], [`EXIT_UNDECIDED`]):
//!
//! | code | meaning | reproduce | prop | audit | hausdorff | offset | verify | tangency |
//! |---|---|---|---|---|---|---|---|---|
//! | 0 | proven / complete | every claim decided | agrees with the direct check | no disagreement | `d_H ≤ tol` certified, or the gap reached | every segment certified | valid | complete |
//! | 1 | refuted | — | disagrees (an erratum) | a disagreement | `d_H > tol` proven | — | invalid (malformed JSON included), or about other shapes | — |
//! | 2 | bad input | | | | | | the file cannot be read | |
//! | 3 | undecided / incomplete | a claim undecided | a verdict undecided | — | budget ran out | tolerance not reached within the limits | — | undecided boxes remain |
//!
//! A bad input's message names the field and the reason, on stderr — and with
//! `--json` also as `{"error": {"field", "reason"}, "exit_code": 2}` on stdout;
//! never a panic.
//!
//! | module | content |
//! |---|---|
//! | [`args`] | exact parsing of numbers, points, frames, coefficient lists, τ |
//! | [`modes`] | the flags with a fixed set of values (`--method`, `--output`, `--side`, …) as value enums |
//! | [`pen`] | the pens of `stroke --pen` and `convolve --ellipse` |
//! | [`report`] | one result as text lines or one JSON document, and its exit code |
//! | [`reproduce`] | `lncert reproduce` |
//! | [`svg`] | the Fig. 5 pictures of `reproduce --out` |
//! | [`prop`] | `lncert prop`: ID resolution and one module per seed |
//! | [`audit`] | `lncert audit` |
//! | [`tangency`] | `lncert tangency` |
//! | [`offset`], [`offset_svg`] | `lncert offset` and its picture |
//! | [`curve_input`] | the `CURVE` argument of `offset` and `stroke` (curve files, arcs, circles, `--glyph`) |
//! | [`glyph_item`] | one glyph of a font by character, code point (`uni0041`) or name (`@A`, `Aacute`): `--glyph` and `font --glyphs` |
//! | [`svg_out`] | `--out FILE.svg` of `stroke` and `offset`: the results as an SVG document in the input's frame |
//! | [`stroke_doc`] | `lncert stroke DOC.svg` without `--pen`: each element with its own `stroke-width` |
//! | [`ufo_input`] | UFO input of `lncert font` (norad; qcurve runs, components decomposed exactly) |

pub mod args;
pub mod audit;
pub mod convolve;
pub mod curve_input;
pub mod font;
pub mod glyph_item;
pub mod hausdorff;
pub mod hausdorff_stroke;
pub mod modes;
pub mod offset;
pub mod offset_grid;
pub mod offset_svg;
pub mod pen;
pub mod progress;
pub mod prop;
pub mod report;
pub mod reproduce;
pub mod stroke;
pub mod stroke_doc;
pub mod svg;
pub mod svg_out;
pub mod tangency;
pub mod ufo_input;
pub mod verify;

use clap::{Parser, Subcommand};

/// Exit code: proven, complete, valid, or in agreement with the direct check.
pub const EXIT_OK: i32 = 0;
/// Exit code: refuted — a claim proven false, an invalid certificate, a
/// proposition that disagrees with the direct check (an erratum), an audit
/// that found a disagreement.
pub const EXIT_REFUTED: i32 = 1;
/// Exit code for bad input (the message names the field and the reason).
pub const EXIT_BAD_INPUT: i32 = 2;
/// Exit code: undecided or incomplete — a budget or a limit ran out before
/// the question was settled (whatever was printed is still sound).
pub const EXIT_UNDECIDED: i32 = 3;

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
    /// The convolution with an elliptical pen (seed 001's G² method), proven within a tolerance on each side.
    Convolve(Box<convolve::ConvolveArgs>),
    /// The proven outline of a circular pen's stroke: closed, simple contours with exact arcs.
    Stroke(Box<stroke::StrokeArgs>),
    /// A whole font offset or stroked, every glyph proven, written as a UFO.
    Font(Box<font::FontArgs>),
    /// Re-check a Hausdorff tolerance certificate without searching.
    Verify(verify::VerifyArgs),
    /// Quartic LN curves tangent to a circle (seed 003 §4): all solutions, proven.
    Tangency(Box<tangency::TangencyArgs>),
}

/// A bad-input error (exit code 2): the field (a flag such as `--tol`, or a
/// field inside an input file such as `A: arc.radius`) and the reason.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct CliError {
    /// The flag or field.
    pub field: String,
    /// What is wrong with it.
    pub reason: String,
}

impl std::fmt::Display for CliError {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        write!(f, "{}: {}", self.field, self.reason)
    }
}

impl CliError {
    /// The error as the JSON document `--json` prints on stdout.
    pub fn to_json(&self) -> serde_json::Value {
        serde_json::json!({
            "error": {"field": self.field, "reason": self.reason},
            "exit_code": EXIT_BAD_INPUT,
        })
    }
}

/// Writes `text` to stdout, ignoring write errors (a closed pipe, as in
/// `lncert reproduce | head`, must not panic).
pub fn print_out(text: &str) {
    use std::io::Write;
    let mut out = std::io::stdout().lock();
    let _ = out.write_all(text.as_bytes()).and_then(|_| out.flush());
}

/// Prints a command's report: the JSON document (pretty) with `--json`,
/// else the text.
pub(crate) fn print_report(
    json: bool,
    doc: impl FnOnce() -> serde_json::Value,
    text: impl FnOnce() -> String,
) {
    if json {
        print_out(&format!(
            "{}\n",
            serde_json::to_string_pretty(&doc()).unwrap_or_default()
        ));
    } else {
        print_out(&text());
    }
}

/// A command line that clap rejects (an unknown flag, a value that is not
/// one of a flag's names, a number out of its type): clap's message on
/// stderr and exit code [`EXIT_BAD_INPUT`] as for every bad input — with
/// `--json` also the error document on stdout, its field the flag. `--help`
/// and `--version` print and exit 0, as clap does.
pub fn usage_error(e: &clap::Error) -> i32 {
    use clap::error::{ContextKind, ContextValue};
    if !e.use_stderr() {
        e.exit();
    }
    let _ = e.print();
    if std::env::args_os().skip(1).any(|a| a == "--json") {
        let arg = match e.get(ContextKind::InvalidArg) {
            Some(ContextValue::String(s)) => Some(s.as_str()),
            Some(ContextValue::Strings(v)) => v.first().map(String::as_str),
            _ => None,
        };
        // `--method <METHOD>` names the flag `--method`
        let field = arg
            .and_then(|s| s.split([' ', '=']).next())
            .unwrap_or("arguments");
        let text = e.render().to_string();
        let reason = text
            .lines()
            .map(str::trim)
            .filter(|l| !l.is_empty() && !l.starts_with("For more information"))
            .collect::<Vec<_>>()
            .join(" ");
        let err = CliError {
            field: field.to_string(),
            reason: reason.trim_start_matches("error: ").to_string(),
        };
        print_out(&format!("{}\n", err.to_json()));
    }
    EXIT_BAD_INPUT
}

/// Runs a parsed command line and returns the process exit code.
pub fn run(cli: Cli) -> i32 {
    let json = match &cli.command {
        Command::Reproduce(a) => a.json,
        Command::Prop(a) => a.json,
        Command::Audit(a) => a.json,
        Command::Hausdorff(a) => a.json,
        Command::Offset(a) => a.json,
        Command::Convolve(a) => a.json,
        Command::Stroke(a) => a.json,
        Command::Font(a) => a.json,
        Command::Verify(a) => a.json,
        Command::Tangency(a) => a.json,
    };
    let name = match &cli.command {
        Command::Reproduce(_) => "reproduce",
        Command::Prop(_) => "prop",
        Command::Audit(_) => "audit",
        Command::Hausdorff(_) => "hausdorff",
        Command::Offset(_) => "offset",
        Command::Convolve(_) => "convolve",
        Command::Stroke(_) => "stroke",
        Command::Font(_) => "font",
        Command::Verify(_) => "verify",
        Command::Tangency(_) => "tangency",
    };
    // `font` draws its own progress bar (glyph counts, ETA)
    let progress = (name != "font").then(|| progress::Progress::start(name));
    let result = match cli.command {
        Command::Reproduce(a) => reproduce::run(&a),
        Command::Prop(a) => prop::run(&a),
        Command::Audit(a) => audit::run(&a),
        Command::Hausdorff(a) => hausdorff::run(&a),
        Command::Offset(a) => offset::run(&a),
        Command::Convolve(a) => convolve::run(&a),
        Command::Stroke(a) => match &a.pen {
            Some(pen) => stroke::run(&a, pen),
            // an SVG document, each element with its own stroke-width
            None => stroke_doc::run(&a),
        },
        Command::Font(a) => font::run(&a),
        Command::Verify(a) => verify::run(&a),
        Command::Tangency(a) => tangency::run(&a),
    };
    if let Some(p) = progress {
        p.finish();
    }
    match result {
        Ok(code) => code,
        Err(e) => {
            eprintln!("error: {e}");
            if json {
                print_out(&format!("{}\n", e.to_json()));
            }
            EXIT_BAD_INPUT
        }
    }
}
