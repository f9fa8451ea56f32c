//! `lncert reproduce [--json] [--out DIR]`: runs [`lncert_cli::reproduce::run_all`]
//! and prints every claim with its verdict, then a summary.
//!
//! Exit code 0 if no claim is `undecided`, else 3 (errata and refuted
//! claims are findings, not failures: they exit 0). `--out DIR` also writes one
//! SVG picture per Fig. 5 case of seed 000 (see [`super::svg`]), seed 001
//! Fig. 2(a), seed 000 Fig. 7(a), the proven font 'H' of seed 000 Fig. 7(c)
//! (`font-H.svg`) and one per proven stroke outline (`stroke-….svg`).

use super::{print_out, svg, CliError};
use lncert_cli::reproduce::{run_all_with_strokes, strokes::Run, Claim, Verdict};
use serde_json::{json, Map, Value};
use std::fmt::Write as _;
use std::path::PathBuf;

/// Arguments of `lncert reproduce`.
#[derive(clap::Args, Debug)]
pub struct ReproduceArgs {
    /// Print one JSON document `{"claims": [...], "summary": {...}}`.
    #[arg(long)]
    pub json: bool,
    /// Write SVG pictures (Fig. 5 cases of seed 000, the stroke outlines, …) into this directory.
    #[arg(long, value_name = "DIR")]
    pub out: Option<PathBuf>,
}

const VERDICTS: [Verdict; 4] = [
    Verdict::Certified,
    Verdict::Refuted,
    Verdict::Erratum,
    Verdict::Undecided,
];

/// Runs the command; returns the exit code.
pub fn run(a: &ReproduceArgs) -> Result<i32, CliError> {
    if let Some(dir) = &a.out {
        super::args::output_dir("--out", dir)?;
    }
    let (claims, strokes) = run_all_with_strokes();
    let written = match &a.out {
        Some(dir) => {
            let mut w = svg::write_fig5(dir)?;
            w.push(write_seed001_fig2a(dir)?);
            w.push(write_seed000_fig7a(dir)?);
            w.push(write_font_h(dir)?);
            w.extend(write_strokes(dir, &strokes)?);
            w
        }
        None => Vec::new(),
    };
    if a.json {
        print_json(&claims, &written);
    } else {
        print_text(&claims, &written);
    }
    let undecided = claims.iter().any(|c| c.verdict == Verdict::Undecided);
    Ok(if undecided {
        super::EXIT_UNDECIDED
    } else {
        super::EXIT_OK
    })
}

/// Number of claims per verdict, in the order of [`VERDICTS`].
fn summary(claims: &[Claim]) -> Vec<(Verdict, usize)> {
    VERDICTS
        .iter()
        .map(|v| (*v, claims.iter().filter(|c| c.verdict == *v).count()))
        .collect()
}

fn print_json(claims: &[Claim], written: &[PathBuf]) {
    let counts: Map<String, Value> = summary(claims)
        .into_iter()
        .map(|(v, n)| (v.to_string(), json!(n)))
        .collect();
    let mut doc = json!({ "claims": claims, "summary": counts });
    if !written.is_empty() {
        let files: Vec<String> = written.iter().map(|p| p.display().to_string()).collect();
        doc["pictures"] = json!(files);
    }
    print_out(&format!(
        "{}\n",
        serde_json::to_string_pretty(&doc).expect("claims serialize")
    ));
}

fn print_text(claims: &[Claim], written: &[PathBuf]) {
    let mut s = format!(
        "lncert reproduce — {} claims recomputed from the built-in data\n\n",
        claims.len()
    );
    for c in claims {
        let _ = writeln!(
            s,
            "{:<9}  {}  {} — {}",
            c.verdict.to_string(),
            c.id,
            c.source,
            c.statement
        );
        let _ = writeln!(s, "           {}", c.detail);
    }
    let parts: Vec<String> = summary(claims)
        .into_iter()
        .map(|(v, n)| format!("{n} {v}"))
        .collect();
    let _ = writeln!(s, "\nsummary: {}", parts.join(", "));
    for p in written {
        let _ = writeln!(s, "wrote {}", p.display());
    }
    print_out(&s);
}

/// Seed 001 Fig. 2(a) / seed 000 Fig. 7(a): the nonic, its exact convolution
/// with the pen (sampled) and both certified G² approximants at TOL 1e-2.
fn write_seed001_fig2a(dir: &std::path::Path) -> Result<PathBuf, CliError> {
    use lncert_cli::reproduce::seed001;
    let fail = |e: String| super::args::bad("--out", format!("seed 001 Fig. 2(a): {e}"));
    let (minus, plus) = seed001::both_sides(1e-2).map_err(fail)?;
    let x = seed001::nonic().map_err(fail)?;
    let pen = seed001::pen(1e-12).map_err(fail)?;
    let svg = super::convolve::render(&x, &pen, &[("minus", minus, 0.0), ("plus", plus, 0.0)]);
    let path = dir.join("seed001_fig2a.svg");
    std::fs::write(&path, svg)
        .map_err(|e| super::args::bad("--out", format!("cannot write {}: {e}", path.display())))?;
    Ok(path)
}

/// Seed 000 Fig. 7(a): the font 'H' by cubic LN pairs at TOL 0.1 (the paper's
/// acceptance), both sides, with the exact convolution (sampled).
fn write_seed000_fig7a(dir: &std::path::Path) -> Result<PathBuf, CliError> {
    use lncert::offset::OffsetMethod;
    use lncert_cli::reproduce::seed001;
    let fail = |e: String| super::args::bad("--out", format!("seed 000 Fig. 7(a): {e}"));
    let (minus, plus) = seed001::both_sides_with(0.1, OffsetMethod::LnPair, true).map_err(fail)?;
    let x = seed001::nonic().map_err(fail)?;
    let pen = seed001::pen(1e-12).map_err(fail)?;
    let svg = super::convolve::render(&x, &pen, &[("minus", minus, 0.0), ("plus", plus, 0.0)]);
    let path = dir.join("seed000_fig7a.svg");
    std::fs::write(&path, svg)
        .map_err(|e| super::args::bad("--out", format!("cannot write {}: {e}", path.display())))?;
    Ok(path)
}

/// One picture per computed stroke of the `stroke-…` claims (the outline over
/// its skeleton); a stroke that failed has no picture.
fn write_strokes(dir: &std::path::Path, runs: &[Run]) -> Result<Vec<PathBuf>, CliError> {
    let mut out = Vec::new();
    for r in runs {
        let Ok(s) = &r.stroke else { continue };
        let name: String =
            r.id.chars()
                .map(|c| {
                    if c.is_ascii_alphanumeric() || c == '-' {
                        c
                    } else {
                        '_'
                    }
                })
                .collect();
        let path = dir.join(format!("{name}.svg"));
        let d = super::stroke::path_data(s).unwrap_or_else(|_| super::stroke::fallback_path(s));
        let svg = super::stroke::svg(&[s], &r.curve, &d, false);
        std::fs::write(&path, svg).map_err(|e| {
            super::args::bad("--out", format!("cannot write {}: {e}", path.display()))
        })?;
        out.push(path);
    }
    Ok(out)
}

/// Seed 000 Fig. 7(c): the font 'H', the proven stroke outline of the nonic
/// with the elliptical pen at TOL 0.1 (cubic LN-pair sides, cubic caps).
fn write_font_h(dir: &std::path::Path) -> Result<PathBuf, CliError> {
    use lncert_cli::reproduce::seed001;
    let fail = |e: String| super::args::bad("--out", format!("seed 000 Fig. 7(c): {e}"));
    let (s, _) = seed001::font_h_stroke().map_err(fail)?;
    let x = seed001::nonic().map_err(fail)?;
    let d = super::stroke::path_data(&s).unwrap_or_else(|_| super::stroke::fallback_path(&s));
    let path = dir.join("font-H.svg");
    std::fs::write(&path, super::stroke::svg(&[&s], &x, &d, false))
        .map_err(|e| super::args::bad("--out", format!("cannot write {}: {e}", path.display())))?;
    Ok(path)
}
