//! Proven stroke outlines of small icon elements against peers, timed in one
//! run on this machine: lncert's `stroke` (circular pen of radius 1, i.e.
//! `stroke-width="2"`, round caps and joins, `Output::Cubic`, TOL 1e-2) next to
//! kurbo 0.13's stroker and, when the Python package `skia-pathops` is
//! importable, Skia's stroker followed by Skia's `Simplify`.
//!
//! ```sh
//! cargo run --release --example icon_strokes
//! SKIA_PYTHON=/tmp/skvenv/bin/python cargo run --release --example icon_strokes
//! # only the elements whose names contain `heart`, 50 lncert runs (profiling)
//! LNCERT_RUNS=50 cargo run --release --example icon_strokes -- heart
//! ```
//!
//! The icon elements are written below ([`ICONS`], viewBox 0 0 24 24) and read
//! by `lncert::shape::parse_svg_document`; circles, ellipses, rounded corners
//! and arcs come out as Bézier pieces within the parser's certified bound.
//! kurbo and Skia stroke **those pieces** (read in f64; lines, quads and
//! cubics by degree; a closed chain ends with a close command), so all three
//! stroke the same geometry.
//!
//! Columns per element:
//!
//! * **lncert**: wall time of `stroke` (construction and all proofs) — the
//!   first run and the median of [`LNCERT_RUNS`] runs; which of the claims
//!   (a) (b) (c) are proven (`abc` = all, `-` marks an unproven one, from the
//!   first run; a later run that disagrees is reported on stderr); output
//!   pieces; whether the outline is closed (every contour closed, with the
//!   number of contours).
//! * **kurbo**: `kurbo::stroke(path, &Stroke::new(2.0).with_caps(Cap::Round)
//!   .with_join(Join::Round), &StrokeOpts::default(), TOL)`, median of
//!   [`KURBO_RUNS`] runs (each timed alone, after a warm-up), its output
//!   segments, and the ratio lncert median / kurbo median.
//! * **Skia**: `cli/examples/skia_stroke_time.py` run by the interpreter in
//!   `SKIA_PYTHON` (default `python3`) when `import pathops` works there: per
//!   call `Path` copy + `stroke(2, ROUND_CAP, ROUND_JOIN, 4)` + `simplify`,
//!   timed with `time.perf_counter` over batches of many calls (median per
//!   call). Skia's stroker works to an error of `1/(4·resScale)` units and
//!   pathops uses resScale 1, so the path is scaled by `0.25/TOL` for the
//!   TOL-matched column (`Skia`, the ratio's base); `Skia res 1` is the call
//!   on the unscaled path (error ~0.25). Otherwise "skia-pathops not
//!   available" is printed and the columns are left out.

use kurbo::{BezPath, Cap, Join, PathEl, Point};
use lncert::curve::Bezier;
use lncert::offset::Output;
use lncert::scalar::{Rational, Scalar};
use lncert::stroke::{stroke, Stroke, StrokeOptions};
use serde_json::{json, Value};
use std::io::Write;
use std::process::{Command, Stdio};
use std::time::{Duration, Instant};

/// The icon elements: (name, SVG element in a 24 × 24 viewBox).
const ICONS: [(&str, &str); 8] = [
    ("circle", r#"<circle cx="12" cy="12" r="3"/>"#),
    (
        "rect rx",
        r#"<rect x="3" y="3" width="18" height="18" rx="1.5"/>"#,
    ),
    ("ellipse", r#"<ellipse cx="12" cy="12" rx="8" ry="4"/>"#),
    (
        "arc path",
        r#"<path d="M12 2a10 10 0 1 0 10 10h-4a6 6 0 1 1-6-6z"/>"#,
    ),
    (
        "heart",
        r#"<path d="M20.84 4.61a5.5 5.5 0 0 0-7.78 0L12 5.67l-1.06-1.06a5.5 5.5 0 0 0-7.78 7.78l1.06 1.06L12 21.23l7.78-7.78 1.06-1.06a5.5 5.5 0 0 0 0-7.78z"/>"#,
    ),
    ("polyline", r#"<polyline points="4 17 10 11 4 5"/>"#),
    ("corners", r#"<path d="M20 6 9 17l-5-5"/>"#),
    (
        "relative curves",
        r#"<path d="M3 12c3-6 6-6 9 0s6 6 9 0"/>"#,
    ),
];

/// Pen radius (stroke-width 2).
const RADIUS: i64 = 1;
const TOL: f64 = 1e-2;
/// lncert runs per element (the environment variable `LNCERT_RUNS` overrides).
const LNCERT_RUNS: usize = 5;
const KURBO_RUNS: usize = 1000;

fn document(element: &str) -> String {
    format!(
        r#"<svg xmlns="http://www.w3.org/2000/svg" viewBox="0 0 24 24" fill="none" stroke="currentColor" stroke-width="2">{element}</svg>"#
    )
}

fn median(v: &[f64]) -> f64 {
    let mut v = v.to_vec();
    v.sort_by(f64::total_cmp);
    let n = v.len();
    if n == 0 {
        f64::NAN
    } else if n % 2 == 1 {
        v[n / 2]
    } else {
        0.5 * (v[n / 2 - 1] + v[n / 2])
    }
}

/// The parsed pieces as a kurbo path in f64: a line, quad or cubic per piece
/// by degree; a new subpath where a piece does not start at the previous end;
/// a subpath that returns exactly to its start is closed.
fn to_kurbo_path(curve: &[Bezier<Rational>]) -> BezPath {
    let pt = |v: &lncert::curve::V2<Rational>| Point::new(v.x.approx(), v.y.approx());
    let mut p = BezPath::new();
    let mut start: Option<&lncert::curve::V2<Rational>> = None;
    let mut last: Option<&lncert::curve::V2<Rational>> = None;
    for b in curve {
        let q = b.points();
        if last != Some(&q[0]) {
            if let (Some(s), Some(l)) = (start, last) {
                if s == l {
                    p.close_path();
                }
            }
            p.move_to(pt(&q[0]));
            start = Some(&q[0]);
        }
        match b.degree() {
            1 => p.line_to(pt(&q[1])),
            2 => p.quad_to(pt(&q[1]), pt(&q[2])),
            3 => p.curve_to(pt(&q[1]), pt(&q[2]), pt(&q[3])),
            d => panic!("a piece of degree {d}: kurbo takes degree ≤ 3"),
        }
        last = q.last();
    }
    if let (Some(s), Some(l)) = (start, last) {
        if s == l {
            p.close_path();
        }
    }
    p
}

/// The same path as commands for the Python script.
fn path_commands(p: &BezPath) -> Value {
    let xy = |q: Point| [json!(q.x), json!(q.y)];
    let cmds: Vec<Value> = p
        .elements()
        .iter()
        .map(|e| {
            let mut c = Vec::new();
            match *e {
                PathEl::MoveTo(a) => {
                    c.push(json!("M"));
                    c.extend(xy(a));
                }
                PathEl::LineTo(a) => {
                    c.push(json!("L"));
                    c.extend(xy(a));
                }
                PathEl::QuadTo(a, b) => {
                    c.push(json!("Q"));
                    c.extend(xy(a));
                    c.extend(xy(b));
                }
                PathEl::CurveTo(a, b, d) => {
                    c.push(json!("C"));
                    c.extend(xy(a));
                    c.extend(xy(b));
                    c.extend(xy(d));
                }
                PathEl::ClosePath => c.push(json!("Z")),
            }
            Value::Array(c)
        })
        .collect();
    Value::Array(cmds)
}

fn claims(s: &Stroke) -> String {
    [(&s.a, 'a'), (&s.b, 'b'), (&s.c, 'c')]
        .iter()
        .map(|(c, n)| if c.proven { *n } else { '-' })
        .collect()
}

struct LncertRun {
    first: f64,
    median: f64,
    stroke: Stroke,
}

fn lncert_runs() -> usize {
    std::env::var("LNCERT_RUNS")
        .ok()
        .and_then(|v| v.parse().ok())
        .filter(|&n| n > 0)
        .unwrap_or(LNCERT_RUNS)
}

fn run_lncert(name: &str, curve: &[Bezier<Rational>]) -> Result<LncertRun, String> {
    let tol = lncert::Tolerance::from_f64(TOL).map_err(|e| e.to_string())?;
    let mut o = StrokeOptions::new(Rational::from_integer(RADIUS.into()), tol);
    o.output = Output::Cubic;
    let mut times = Vec::new();
    let mut first: Option<Stroke> = None;
    for _ in 0..lncert_runs() {
        let t0 = Instant::now();
        let s = stroke(curve, &o).map_err(|e| e.to_string())?;
        times.push(t0.elapsed().as_secs_f64());
        match &first {
            None => first = Some(s),
            Some(f) => {
                if claims(f) != claims(&s) || f.pieces() != s.pieces() {
                    eprintln!(
                        "  {name}: a later run differs: claims {} / pieces {} (first: {} / {})",
                        claims(&s),
                        s.pieces(),
                        claims(f),
                        f.pieces()
                    );
                }
            }
        }
    }
    let stroke = first.expect("at least one run");
    for (n, c) in [("a", &stroke.a), ("b", &stroke.b), ("c", &stroke.c)] {
        if !c.proven {
            eprintln!("  {name}: ({n}) unproven: {}", c.note);
        }
    }
    Ok(LncertRun {
        first: times[0],
        median: median(&times),
        stroke,
    })
}

/// Median seconds of `kurbo::stroke` over [`KURBO_RUNS`] runs, and its output
/// segments.
fn run_kurbo(path: &BezPath) -> (f64, usize) {
    let style = kurbo::Stroke::new(2.0 * RADIUS as f64)
        .with_caps(Cap::Round)
        .with_join(Join::Round);
    let opts = kurbo::StrokeOpts::default();
    let once = || kurbo::stroke(std::hint::black_box(path).iter(), &style, &opts, TOL);
    let segs = once().segments().count();
    for _ in 0..KURBO_RUNS / 10 {
        std::hint::black_box(once());
    }
    let mut times = Vec::with_capacity(KURBO_RUNS);
    for _ in 0..KURBO_RUNS {
        let t0 = Instant::now();
        let out = once();
        times.push(t0.elapsed().as_secs_f64());
        std::hint::black_box(out);
    }
    (median(&times), segs)
}

struct Skia {
    version: String,
    scale: f64,
    /// Per element (by name): (µs TOL-matched, µs at res 1, copy overhead µs,
    /// calls, output segments TOL-matched, output segments at res 1).
    results: Vec<(String, f64, f64, f64, u64, u64, u64)>,
}

/// Skia through `cli/examples/skia_stroke_time.py`, or why not.
fn run_skia(paths: &[(String, Value)]) -> Result<Skia, String> {
    let python = std::env::var("SKIA_PYTHON").unwrap_or_else(|_| "python3".to_string());
    let probe = Command::new(&python)
        .args(["-c", "import pathops"])
        .stdout(Stdio::null())
        .stderr(Stdio::null())
        .status();
    match probe {
        Ok(s) if s.success() => {}
        Ok(_) => return Err(format!("`{python} -c \"import pathops\"` failed")),
        Err(e) => return Err(format!("cannot run `{python}`: {e}")),
    }
    let script = concat!(env!("CARGO_MANIFEST_DIR"), "/examples/skia_stroke_time.py");
    let job = json!({
        "width": 2.0 * RADIUS as f64,
        "tol": TOL,
        "min_batch_seconds": 0.02,
        "batches": 7,
        "paths": paths
            .iter()
            .map(|(n, c)| json!({"name": n, "cmds": c}))
            .collect::<Vec<_>>(),
    });
    let mut child = Command::new(&python)
        .arg(script)
        .stdin(Stdio::piped())
        .stdout(Stdio::piped())
        .stderr(Stdio::piped())
        .spawn()
        .map_err(|e| format!("cannot run {script}: {e}"))?;
    child
        .stdin
        .take()
        .expect("piped stdin")
        .write_all(job.to_string().as_bytes())
        .map_err(|e| format!("writing to {script}: {e}"))?;
    let out = child
        .wait_with_output()
        .map_err(|e| format!("{script}: {e}"))?;
    if !out.status.success() {
        return Err(format!(
            "{script} failed: {}",
            String::from_utf8_lossy(&out.stderr).trim()
        ));
    }
    let v: Value = serde_json::from_slice(&out.stdout)
        .map_err(|e| format!("{script}: unreadable output: {e}"))?;
    let num = |r: &Value, k: &str| r[k].as_f64().ok_or_else(|| format!("{script}: no `{k}`"));
    let int = |r: &Value, k: &str| r[k].as_u64().ok_or_else(|| format!("{script}: no `{k}`"));
    let mut results = Vec::new();
    for r in v["results"].as_array().ok_or("no results")? {
        results.push((
            r["name"].as_str().unwrap_or("?").to_string(),
            num(r, "us")?,
            num(r, "us_default_res")?,
            num(r, "overhead_us")?,
            int(r, "calls")?,
            int(r, "verbs_out")?,
            int(r, "verbs_out_default_res")?,
        ));
    }
    Ok(Skia {
        version: format!(
            "skia-pathops {} (Python {})",
            v["pathops"].as_str().unwrap_or("?"),
            v["python"].as_str().unwrap_or("?")
        ),
        scale: num(&v, "scale")?,
        results,
    })
}

fn cpu_model() -> String {
    std::fs::read_to_string("/proc/cpuinfo")
        .ok()
        .and_then(|t| {
            t.lines()
                .find(|l| l.starts_with("model name"))
                .and_then(|l| l.split(':').nth(1))
                .map(|s| s.trim().to_string())
        })
        .unwrap_or_else(|| "unknown CPU".to_string())
}

fn ms(secs: f64) -> String {
    format!("{:.1} ms", secs * 1e3)
}

fn ratio(x: f64) -> String {
    if x >= 100.0 {
        format!("{x:.0}×")
    } else {
        format!("{x:.1}×")
    }
}

struct Row {
    name: &'static str,
    input: usize,
    lncert: Result<LncertRun, String>,
    kurbo: (f64, usize),
}

fn main() {
    let start = Instant::now();
    println!(
        "icon_strokes: pen radius {RADIUS} (stroke-width {}), TOL {TOL:e}, lncert Output::Cubic, \
         round caps and joins; {} threads available; CPU: {}",
        2 * RADIUS,
        std::thread::available_parallelism().map_or(0, |n| n.get()),
        cpu_model()
    );
    let mut rows = Vec::new();
    let mut paths = Vec::new();
    // names given on the command line select the elements containing them
    let only: Vec<String> = std::env::args().skip(1).collect();
    for (name, element) in ICONS {
        if !only.is_empty() && !only.iter().any(|o| name.contains(o.as_str())) {
            continue;
        }
        let curve = match lncert::shape::parse_svg_document(&document(element)) {
            Ok(c) => c,
            Err(e) => {
                eprintln!("icon_strokes: {name}: {e}");
                std::process::exit(2);
            }
        };
        let kp = to_kurbo_path(&curve);
        let lncert = run_lncert(name, &curve);
        let kurbo = run_kurbo(&kp);
        paths.push((name.to_string(), path_commands(&kp)));
        rows.push(Row {
            name,
            input: curve.len(),
            lncert,
            kurbo,
        });
    }
    let skia = run_skia(&paths);
    let skia_cols = skia.is_ok();

    print!(
        "| element | input pieces | lncert first | lncert median ({}) | claims | pieces out | closed | \
         kurbo median ({KURBO_RUNS}) | kurbo segs | lncert/kurbo |",
        lncert_runs()
    );
    if skia_cols {
        print!(" Skia (TOL) | Skia segs | Skia res 1 | lncert/Skia |");
    }
    println!();
    print!("|---|---|---|---|---|---|---|---|---|---|");
    if skia_cols {
        print!("---|---|---|---|");
    }
    println!();
    let (mut proven, mut t_med, mut r_kurbo, mut r_skia) = (0, Vec::new(), Vec::new(), Vec::new());
    for row in &rows {
        let (k_secs, k_segs) = row.kurbo;
        let kurbo_cells = format!("{:.1} µs | {k_segs}", k_secs * 1e6);
        let sk = skia
            .as_ref()
            .ok()
            .and_then(|s| s.results.iter().find(|r| r.0 == row.name));
        match &row.lncert {
            Ok(l) => {
                let s = &l.stroke;
                if s.proven() {
                    proven += 1;
                }
                t_med.push(l.median);
                let rk = l.median / k_secs;
                r_kurbo.push(rk);
                let closed = if !s.contours.is_empty() && s.contours.iter().all(|c| c.closed) {
                    format!("yes ({})", s.contours.len())
                } else {
                    format!(
                        "no ({} of {} closed)",
                        s.contours.iter().filter(|c| c.closed).count(),
                        s.contours.len()
                    )
                };
                print!(
                    "| {} | {} | {} | {} | {} | {} | {closed} | {kurbo_cells} | {} |",
                    row.name,
                    row.input,
                    ms(l.first),
                    ms(l.median),
                    claims(s),
                    s.pieces(),
                    ratio(rk)
                );
                if skia_cols {
                    match sk {
                        Some(r) => {
                            let rs = l.median / (r.1 * 1e-6);
                            r_skia.push(rs);
                            print!(
                                " {:.1} µs | {} | {:.1} µs ({}) | {} |",
                                r.1,
                                r.5,
                                r.2,
                                r.6,
                                ratio(rs)
                            );
                        }
                        None => print!(" – | – | – | – |"),
                    }
                }
            }
            Err(e) => {
                print!(
                    "| {} | {} | error: {e} | – | – | – | – | {kurbo_cells} | – |",
                    row.name, row.input
                );
                if skia_cols {
                    match sk {
                        Some(r) => {
                            print!(" {:.1} µs | {} | {:.1} µs ({}) | – |", r.1, r.5, r.2, r.6)
                        }
                        None => print!(" – | – | – | – |"),
                    }
                }
            }
        }
        println!();
    }
    println!();
    match &skia {
        Ok(s) => {
            let calls: u64 = s.results.iter().map(|r| r.4).sum();
            let overhead = s.results.iter().map(|r| r.3).fold(0.0, f64::max);
            let share = s.results.iter().map(|r| r.3 / r.1).fold(0.0, f64::max);
            println!(
                "Skia: {}; stroke + simplify per call, TOL-matched by scaling the path {}× \
                 (Skia's stroker error is 1/(4·resScale) units); {calls} timed calls in all; \
                 Path copy overhead included, at most {overhead:.2} µs per call ({:.1}% of a call). \
                 Segs: output segments (lines, quads, conics, cubics); Skia res 1: the unscaled call \
                 (its segments in parentheses).",
                s.version,
                s.scale,
                100.0 * share
            );
        }
        Err(e) => println!("skia-pathops not available ({e})"),
    }
    let skia_summary = if r_skia.is_empty() {
        "Skia not measured".to_string()
    } else {
        format!("median ratio to Skia {}", ratio(median(&r_skia)))
    };
    println!(
        "Summary: {proven}/{} elements proven (a)(b)(c); median lncert time {}; \
         median ratio to kurbo {}; {skia_summary}. Total {:.1} s.",
        rows.len(),
        ms(median(&t_med)),
        ratio(median(&r_kurbo)),
        Duration::as_secs_f64(&start.elapsed())
    );
}
