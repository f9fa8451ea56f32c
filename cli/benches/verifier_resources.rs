//! The resources table of `proofs/stroke-certificate.md` ("Resources"):
//! `lncert verify` on the hostile stroke certificates of
//! `lncert::gen::hostile` (issue 64) and on genuine ones written by
//! `lncert stroke --certificate`, each run as its own process.
//!
//! Per document: its size, the verdict (exit code), the wall time (best of
//! three), the time spent reading the JSON (the verifier's own `debug` log),
//! the time beyond reading per 100 kB (goal ≤ 50 ms), and the peak resident
//! memory (`VmHWM`, logged by `lncert` at `debug`) as a multiple of the size
//! (goal ≤ 20×), also beyond the peak of a baseline run: the stroke
//! certificate of one segment (a few kB), whose run pages in the checker's
//! code and starts its threads — memory that does not grow with the
//! document.
//!
//! Run: `cargo bench -p lncert-cli --bench verifier_resources` (a Markdown
//! table on stdout; `QUICK=1` skips the documents above 10 MB). Linux only
//! (the memory figure is read from `/proc`).

use std::path::{Path, PathBuf};
use std::process::Command;
use std::time::{Duration, Instant};

use lncert::gen::hostile;

const LNCERT: &str = env!("CARGO_BIN_EXE_lncert");

/// One `lncert verify` run: exit code, wall time, reading time, peak kB.
fn run(path: &Path) -> (i32, Duration, Option<Duration>, Option<u64>) {
    let t0 = Instant::now();
    let out = Command::new(LNCERT)
        .arg("verify")
        .arg(path)
        .env("RUST_LOG", "lncert=debug")
        .output()
        .expect("lncert runs");
    let wall = t0.elapsed();
    let log = String::from_utf8_lossy(&out.stderr);
    let peak = log
        .lines()
        .find_map(|l| l.split("peak memory: ").nth(1))
        .and_then(|r| r.split(' ').next())
        .and_then(|n| n.parse().ok());
    let read = log
        .lines()
        .find_map(|l| l.split(" bytes read in ").nth(1))
        .and_then(parse_duration);
    (out.status.code().unwrap_or(-1), wall, read, peak)
}

/// A `Debug`-printed duration (`12.3ms`, `456µs`, `1.2s`).
fn parse_duration(s: &str) -> Option<Duration> {
    let s = s.trim();
    let (num, unit) = s.split_at(s.find(|c: char| c.is_alphabetic() || c == 'µ')?);
    let x: f64 = num.parse().ok()?;
    let secs = match unit {
        "s" => x,
        "ms" => x * 1e-3,
        "µs" => x * 1e-6,
        "ns" => x * 1e-9,
        _ => return None,
    };
    Some(Duration::from_secs_f64(secs))
}

fn verdict(code: i32) -> &'static str {
    match code {
        0 => "valid",
        1 => "invalid / refused",
        2 => "bad input",
        _ => "?",
    }
}

/// A genuine certificate: `lncert stroke ARGS --certificate PATH`.
fn genuine(dir: &Path, name: &str, args: &[&str]) -> Option<PathBuf> {
    let path = dir.join(format!("{name}.json"));
    let ok = Command::new(LNCERT)
        .args(args)
        .arg("--certificate")
        .arg(&path)
        .output()
        .map(|o| o.status.success())
        .unwrap_or(false);
    ok.then_some(path)
}

fn main() {
    if std::env::args().any(|a| a == "--list") {
        return; // `cargo test --benches` lists; nothing to list
    }
    let quick = std::env::var_os("QUICK").is_some();
    let dir =
        std::env::temp_dir().join(format!("lncert-verifier-resources-{}", std::process::id()));
    std::fs::create_dir_all(&dir).expect("a temporary directory");
    let write = |name: &str, doc: String| {
        let p = dir.join(format!("{name}.json"));
        std::fs::write(&p, doc).expect("written");
        p
    };
    // the baseline: a valid stroke certificate of one segment (a few kB),
    // whose run pages in the checker's code and starts its threads
    let seg = dir.join("segment.txt");
    std::fs::write(&seg, "M 0 0 L 1 0").expect("written");
    let seg = seg.to_string_lossy().to_string();
    let small = genuine(
        &dir,
        "segment",
        &["stroke", &seg, "--pen", "circle:1", "--tol", "1e-2"],
    )
    .expect("the segment's stroke certificate is written");
    let base_size = std::fs::metadata(&small).map(|m| m.len()).unwrap_or(0);
    let (code, _, _, base) = run(&small);
    assert_eq!(code, 0, "the segment's certificate verifies");
    let base = base.unwrap_or(0);

    let mut docs: Vec<(String, PathBuf)> = Vec::new();
    let curve = dir.join("cubic.txt");
    std::fs::write(&curve, "M -0.95 0.7 C -0.3 0.5 0.3 -2.5 0.9 -0.2").expect("written");
    let c = curve.to_string_lossy().to_string();
    for (name, args) in [
        (
            "genuine: the test cubic, r = 0.4, tol 1e-3",
            vec!["stroke", &c, "--pen", "circle:0.4", "--tol", "1e-3"],
        ),
        (
            "genuine: the test cubic, r = 0.4, tol 1e-2",
            vec!["stroke", &c, "--pen", "circle:0.4", "--tol", "1e-2"],
        ),
    ] {
        if let Some(p) = genuine(&dir, &format!("g{}", docs.len()), &args) {
            docs.push((name.to_string(), p));
        }
    }
    let font = "/usr/share/fonts/truetype/dejavu/DejaVuSans.ttf";
    if Path::new(font).exists() {
        for g in ["g", "@"] {
            let args = [
                "stroke",
                font,
                "--glyph",
                g,
                "--pen",
                "circle:20",
                "--tol",
                "1e-1",
            ];
            if let Some(p) = genuine(&dir, &format!("g{}", docs.len()), &args) {
                docs.push((format!("genuine: DejaVu Sans `{g}`, r = 20, tol 0.1"), p));
            }
        }
    }
    for k in [2_000, 8_000, 25_000, 80_000] {
        let name = format!("{k} stacked rectangles");
        docs.push((
            name,
            write(&format!("r{k}"), hostile::stacked_rectangles(k)),
        ));
    }
    docs.push((
        "20 000 far pieces and parts".into(),
        write("far", hostile::far_pieces(20_000)),
    ));
    for parts in [200, 2_000] {
        docs.push((
            format!("wiggly witnesses, {parts} parts × 100 copies, degree 20"),
            write(
                &format!("w{parts}"),
                hostile::wiggly_witnesses(parts, 100, 20),
            ),
        ));
    }

    println!(
        "peak of the baseline run (a segment's stroke certificate, {base_size} bytes): {base} kB\n"
    );
    println!("| document | size | verdict | time (best of 3) | reading | beyond reading per 100 kB | peak RSS | × size | × size beyond the baseline |");
    println!("|---|---|---|---|---|---|---|---|---|");
    for (name, path) in &docs {
        let size = std::fs::metadata(path).map(|m| m.len()).unwrap_or(0);
        if quick && size > 10_000_000 {
            continue;
        }
        let runs: Vec<_> = (0..3).map(|_| run(path)).collect();
        let best = runs.iter().min_by_key(|r| r.1).expect("three runs");
        let (code, wall, read, _) = *best;
        let peak = runs.iter().filter_map(|r| r.3).max().unwrap_or(0);
        let kib = size as f64 / 1024.0;
        let beyond = read.map(|r| wall.saturating_sub(r));
        let per100 = beyond.map(|b| b.as_secs_f64() * 1e3 / (size as f64 / 1e5));
        println!(
            "| {name} | {:.2} MB | {} | {:.3} s | {} | {} | {:.1} MB | {:.1}× | {:.1}× |",
            size as f64 / 1e6,
            verdict(code),
            wall.as_secs_f64(),
            read.map_or("?".into(), |r| format!("{:.1} ms", r.as_secs_f64() * 1e3)),
            per100.map_or("?".into(), |p| format!("{p:.1} ms")),
            peak as f64 * 1.024e-3,
            peak as f64 / kib,
            peak.saturating_sub(base) as f64 / kib,
        );
    }
    let _ = std::fs::remove_dir_all(&dir);
}
