//! `lncert tangency --x1 X --y1 Y --u U --center OX,OY --radius R
//! [--backend complete|exact|cpu|gpu] [--resolution N] [--a2-range LO,HI]
//! [--radii] [--json]`: quartic LN curves (seed 003 §4) tangent to a circle.
//!
//! Backends: `complete` (default) — the complete interval solver of
//! [`lncert::tangency::solve`]; `exact` — the exact elimination oracle of
//! [`lncert::tangency::exact_solutions`]; `cpu` / `gpu` — raster candidates certified
//! by Krawczyk, then compared with the complete solver (the JSON `raster`
//! object says how many proven roots the raster missed). Without a GPU
//! adapter, `gpu` says so on stderr and uses the CPU backend.
//!
//! Exit code: 0 if the answer is complete (every solution in the domain is
//! reported and proven; for a raster backend: the complete solver proves the
//! raster missed none), 3 if undecided boxes (or unhandled degenerate cases)
//! remain, 2 for bad input (the message names the flag).

use super::args::{bad, number, point, q, required};
use super::modes::Backend;
use super::{print_out, CliError};
use lncert::scalar::{interval_to_json, Interval, Rational};
use lncert::tangency::{
    solve_complete, solve_exact, A2WindowSource, TangencyProblem, TangencyReport,
};
use lncert::tangency::{valid_radii, RadiiSet};
use lncert::tangency::{SolveOptions, UndecidedReason};
use lncert::tangency::{TangencyError, TangencySystem};
use serde_json::{json, Value};
use std::fmt::Write as _;

/// Largest raster resolution (mirrors the raster module's `MAX_RESOLUTION`).
pub const MAX_RESOLUTION: u32 = 16384;

const USAGE: &str = "lncert tangency --x1 X --y1 Y --u U --center OX,OY --radius R \
[--backend complete|exact|cpu|gpu] [--resolution N] [--a2-range LO,HI] [--radii] [--json]";

/// Arguments of `lncert tangency`.
#[derive(clap::Args, Debug)]
pub struct TangencyArgs {
    /// End point x of the Hermite data [x1, y1] (start [0, 0], normal (0, 1)).
    #[arg(long, value_name = "X", allow_hyphen_values = true)]
    pub x1: Option<String>,
    /// End point y of the Hermite data.
    #[arg(long, value_name = "Y", allow_hyphen_values = true)]
    pub y1: Option<String>,
    /// End normal (u, 1) and parameter interval [0, u].
    #[arg(long, value_name = "U", allow_hyphen_values = true)]
    pub u: Option<String>,
    /// Circle centre `OX,OY`.
    #[arg(long, value_name = "OX,OY", allow_hyphen_values = true)]
    pub center: Option<String>,
    /// Signed radius: R > 0 puts the centre on the side of the normal (m, 1).
    #[arg(long, value_name = "R", allow_hyphen_values = true)]
    pub radius: Option<String>,
    /// Solver: complete (interval branch-and-prune), exact (elimination oracle), cpu, gpu (raster).
    #[arg(long, value_enum, ignore_case = true, default_value_t = Backend::Complete)]
    pub backend: Backend,
    /// Raster resolution N x N for the cpu/gpu backends (2..=16384, default 1024).
    #[arg(long, value_name = "N", allow_hyphen_values = true)]
    pub resolution: Option<String>,
    /// Search window of a2 `LO,HI` (default: Prop 3.2's nonsingular interval widened).
    #[arg(long = "a2-range", value_name = "LO,HI", allow_hyphen_values = true)]
    pub a2_range: Option<String>,
    /// Also report the certified set of valid signed radii for this centre.
    #[arg(long)]
    pub radii: bool,
    /// Print one JSON document.
    #[arg(long)]
    pub json: bool,
}

fn tangency_error(e: TangencyError) -> CliError {
    let flag = match e.field.as_str() {
        "x1" => "--x1",
        "y1" => "--y1",
        "u" => "--u",
        "r" => "--radius",
        "a2_range" => "--a2-range",
        other => other,
    };
    bad(flag, e.reason)
}

fn parse_resolution(text: Option<&str>) -> Result<u32, CliError> {
    let Some(t) = text else {
        return Ok(1024);
    };
    let n: u64 = t
        .trim()
        .parse()
        .map_err(|_| bad("--resolution", format!("{t:?} is not a whole number")))?;
    if !(2..=MAX_RESOLUTION as u64).contains(&n) {
        return Err(bad(
            "--resolution",
            format!("{n} is out of range (2 to {MAX_RESOLUTION})"),
        ));
    }
    Ok(n as u32)
}

fn parse_window(text: &str) -> Result<(Rational, Rational), CliError> {
    let p = point("--a2-range", text).map_err(|_| {
        bad(
            "--a2-range",
            format!("expected `LO,HI` (exact numbers), got {text:?}"),
        )
    })?;
    Ok((p.x, p.y))
}

/// Runs the command; returns the exit code.
pub fn run(a: &TangencyArgs) -> Result<i32, CliError> {
    let x1 = number("--x1", required("--x1", &a.x1, USAGE)?)?;
    let y1 = number("--y1", required("--y1", &a.y1, USAGE)?)?;
    let u = number("--u", required("--u", &a.u, USAGE)?)?;
    let c = point("--center", required("--center", &a.center, USAGE)?)?;
    let r = number("--radius", required("--radius", &a.radius, USAGE)?)?;
    let window = a.a2_range.as_deref().map(parse_window).transpose()?;
    parse_resolution(a.resolution.as_deref())?;
    if a.resolution.is_some() && !a.backend.is_raster() {
        return Err(bad("--resolution", "only used by the cpu and gpu backends"));
    }
    let sys =
        TangencySystem::new(x1, y1, u, c.x.clone(), c.y.clone(), r).map_err(tangency_error)?;
    let problem = TangencyProblem::new(sys, window).map_err(tangency_error)?;
    let mut raster_info: Option<Value> = None;
    let report = match a.backend {
        Backend::Complete => solve_complete(&problem, &SolveOptions::default()),
        Backend::Exact => solve_exact(&problem),
        raster_backend @ (Backend::Cpu | Backend::Gpu) => {
            let n = parse_resolution(a.resolution.as_deref())?;
            let (rep, info) = raster_solve(&problem, n, raster_backend == Backend::Gpu)?;
            raster_info = Some(info);
            rep
        }
    };
    let radii = if a.radii {
        Some(valid_radii(&problem.system.hermite, &c.x, &c.y).map_err(tangency_error)?)
    } else {
        None
    };
    // A raster answer alone is never complete; it is accepted (exit 0) when the
    // complete solver proves it missed nothing.
    let raster_ok = raster_info.as_ref().is_some_and(|i| {
        i["checked_complete"] == json!(true)
            && i["missed"] == json!(0)
            && report.undecided.is_empty()
    });
    let complete = (report.complete || raster_ok) && radii.as_ref().is_none_or(|s| s.complete);
    if a.json {
        let mut doc = to_json(&problem, &report, radii.as_ref());
        if let Some(info) = &raster_info {
            doc["raster"] = info.clone();
        }
        print_out(&format!("{doc}\n"));
    } else {
        let mut text = to_text(&problem, &report, radii.as_ref());
        if let Some(i) = &raster_info {
            let _ = writeln!(
                text,
                "raster {}x{} on {} ({}): {} candidate cells in {:.3} ms; against the complete solver: {} of {} roots missed{}",
                i["resolution"], i["resolution"], i["backend_used"].as_str().unwrap_or("?"),
                i["precision"].as_str().unwrap_or("?"), i["candidates"], i["raster_seconds"].as_f64().unwrap_or(0.0) * 1e3,
                i["missed"], i["complete_roots"],
                if i["checked_complete"] == json!(true) { "" } else { " (the complete solver itself left boxes undecided)" },
            );
            if let Some(note) = i["note"].as_str() {
                let _ = writeln!(text, "note: {note}");
            }
        }
        print_out(&text);
    }
    Ok(if complete {
        super::EXIT_OK
    } else {
        super::EXIT_UNDECIDED
    })
}

fn word(v: Option<bool>) -> Value {
    match v {
        Some(b) => Value::Bool(b),
        None => Value::Null,
    }
}

fn reason(r: UndecidedReason) -> Value {
    match r {
        UndecidedReason::MinWidth { near_double_root } => json!({
            "reason": "min-width", "near_double_root": near_double_root
        }),
        UndecidedReason::Budget => json!({"reason": "budget"}),
        UndecidedReason::DomainBoundary => json!({"reason": "domain-boundary"}),
        UndecidedReason::Ambiguous => json!({"reason": "ambiguous"}),
        UndecidedReason::Unresolved => json!({"reason": "unresolved"}),
    }
}

fn source(s: A2WindowSource) -> &'static str {
    match s {
        A2WindowSource::User => "user",
        A2WindowSource::Nonsingular => "nonsingular-widened",
        A2WindowSource::Fallback => "fallback",
    }
}

fn intervals(v: &[Interval]) -> Value {
    Value::Array(v.iter().map(interval_to_json).collect())
}

fn to_json(p: &TangencyProblem, rep: &TangencyReport, radii: Option<&RadiiSet>) -> Value {
    let roots: Vec<Value> = rep
        .roots
        .iter()
        .map(|r| {
            json!({
                "m": interval_to_json(&r.m),
                "a2": interval_to_json(&r.a2),
                "a3": interval_to_json(&r.a3),
                "a4": interval_to_json(&r.a4),
                "certified": r.certified,
                "nonsingular": word(r.nonsingular),
                "side": r.side.as_str(),
            })
        })
        .collect();
    let undecided: Vec<Value> = rep
        .undecided
        .iter()
        .map(|u| {
            let mut v = reason(u.reason);
            v["m"] = interval_to_json(&u.bx[0]);
            v["a2"] = interval_to_json(&u.bx[1]);
            v
        })
        .collect();
    let mut doc = json!({
        "roots": roots,
        "complete": rep.complete,
        "backend": rep.backend,
        "undecided_boxes": undecided,
        "krawczyk_iterations": rep.krawczyk_iterations,
        "boxes": rep.boxes,
        "lines_of_solutions": rep.lines.iter().map(|l| json!({"m": q(&l.m)})).collect::<Vec<_>>(),
        "a2_range": [q(&p.a2_window.0), q(&p.a2_window.1)],
        "a2_range_source": source(p.a2_source),
        "bezout_bound": p.system.bezout_bound(),
    });
    if let Some(s) = radii {
        doc["radii"] = json!({
            "inner": intervals(&s.inner()),
            "outer": intervals(&s.outer()),
            "undecided_m": intervals(&s.undecided_m),
            "complete": s.complete,
        });
    }
    doc
}

fn show(x: &Interval) -> String {
    format!("[{:.12}, {:.12}]", x.inf(), x.sup())
}

fn to_text(p: &TangencyProblem, rep: &TangencyReport, radii: Option<&RadiiSet>) -> String {
    let mut s = String::new();
    let _ = writeln!(
        s,
        "circle tangency (seed 003 §4), backend {}: a2 in [{}, {}] ({}), m in [0, {}]",
        rep.backend,
        q(&p.a2_window.0),
        q(&p.a2_window.1),
        source(p.a2_source),
        q(p.system.u())
    );
    let _ = writeln!(
        s,
        "{:<36} {:<36} {:<11} {:<10}",
        "m", "a2", "nonsingular", "side"
    );
    for r in &rep.roots {
        let ns = match r.nonsingular {
            Some(true) => "yes",
            Some(false) => "no",
            None => "undecided",
        };
        let _ = writeln!(
            s,
            "{:<36} {:<36} {:<11} {:<10}",
            show(&r.m),
            show(&r.a2),
            ns,
            r.side.as_str()
        );
    }
    for l in &rep.lines {
        let _ = writeln!(s, "line of solutions: m = {} (every a2)", q(&l.m));
    }
    for u in &rep.undecided {
        let _ = writeln!(
            s,
            "undecided box m {} a2 {}: {:?}",
            show(&u.bx[0]),
            show(&u.bx[1]),
            u.reason
        );
    }
    let _ = writeln!(
        s,
        "{} roots, {}; {} boxes, {} Krawczyk steps",
        rep.roots.len(),
        if rep.complete {
            "complete"
        } else {
            "NOT complete"
        },
        rep.boxes,
        rep.krawczyk_iterations
    );
    if let Some(set) = radii {
        let list = |v: Vec<Interval>| v.iter().map(show).collect::<Vec<_>>().join(" ∪ ");
        let _ = writeln!(s, "valid radii, inner: {}", list(set.inner()));
        let _ = writeln!(s, "valid radii, outer: {}", list(set.outer()));
        if !set.complete {
            let _ = writeln!(s, "valid radii: degenerate case not handled (incomplete)");
        }
    }
    s
}

/// Raster candidates (CPU or GPU), certified by Krawczyk, and compared with the
/// complete solver (what the raster missed).
fn raster_solve(
    problem: &TangencyProblem,
    n: u32,
    gpu: bool,
) -> Result<(TangencyReport, Value), CliError> {
    use lncert::scalar::interval_from_rational;
    use lncert::tangency::raster::{
        raster_cpu, raster_gpu, BackendUsed, DensePoly2, Grid, Precision, RasterError,
    };
    use lncert::tangency::solve_candidates;
    let dense = |p: &lncert::tangency::Poly2<Rational>, field: &str| {
        let (dx, dy, c) = p.coeffs_f64();
        DensePoly2::new(dx, dy, c).map_err(|e| bad("--backend", format!("{field}: {e}")))
    };
    let p6 = dense(&problem.system.eq6, "eq. (6)")?;
    let p7 = dense(&problem.system.eq7, "eq. (7)")?;
    let mid = |r: &Rational| interval_from_rational(r).mid();
    let grid = Grid {
        n,
        x_lo: 0.0,
        x_hi: mid(problem.system.u()),
        y_lo: mid(&problem.a2_window.0),
        y_hi: mid(&problem.a2_window.1),
    };
    grid.validate()
        .map_err(|e| bad("--a2-range", e.to_string()))?;
    let start = std::time::Instant::now();
    let mut note = None;
    let out = if gpu {
        match raster_gpu(&p6, &p7, &grid) {
            Ok(o) => o,
            Err(RasterError::NoAdapter(why)) => {
                note = Some(format!("no GPU adapter ({why}); used the CPU backend"));
                eprintln!("note: no GPU adapter ({why}); using the CPU backend");
                raster_cpu(&p6, &p7, &grid).map_err(|e| bad("--grid", e))?
            }
            Err(e) => return Err(bad("--backend", format!("GPU raster failed: {e}"))),
        }
    } else {
        raster_cpu(&p6, &p7, &grid).map_err(|e| bad("--grid", e))?
    };
    let raster_seconds = start.elapsed().as_secs_f64();
    let cells: Vec<[(f64, f64); 2]> = out
        .cells
        .iter()
        .map(|c| {
            [
                (grid.x(c.i), grid.x(c.i + 1)),
                (grid.y(c.j), grid.y(c.j + 1)),
            ]
        })
        .collect();
    let (backend_used, software) = match &out.backend {
        BackendUsed::Cpu => ("cpu".to_string(), false),
        BackendUsed::Gpu { adapter, software } => (format!("gpu: {adapter}"), *software),
    };
    let rep = solve_candidates(problem, &cells, if gpu { "gpu" } else { "cpu" });
    let full = solve_complete(problem, &SolveOptions::default());
    let missed = full
        .roots
        .iter()
        .filter(|r| {
            !rep.roots
                .iter()
                .any(|x| !x.m.intersection(r.m).is_empty() && !x.a2.intersection(r.a2).is_empty())
        })
        .count();
    let info = json!({
        "resolution": n,
        "candidates": out.cells.len(),
        "backend_used": backend_used,
        "software_driver": software,
        "precision": match out.precision { Precision::F64 => "f64", Precision::F32 => "f32" },
        "raster_seconds": raster_seconds,
        "complete_roots": full.roots.len(),
        "missed": missed,
        "checked_complete": full.complete,
        "note": note,
    });
    Ok((rep, info))
}
