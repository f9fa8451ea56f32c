//! Strokes a corpus of SVG icons element by element, as `lncert stroke
//! ICON.svg --tol T --json --output cubic` does (each element with its own
//! `stroke-width`; cubic output is what `--out OUT.svg` writes, `--output
//! native` the outline's own pieces), and prints what was proven, undecided and refused, why,
//! and how long it took.
//!
//! ```sh
//! scripts/fetch-lucide.sh                       # the development corpus, not committed
//! cargo build --release -p lncert-cli
//! cargo run --release -p lncert-cli --example corpus -- target/corpus/lucide/icons
//! # every 10th icon, TOL 1e-2, 60 s per icon at most, 2 icons at once
//! cargo run --release -p lncert-cli --example corpus -- DIR --every 10 --tol 1e-2 --timeout 60 --jobs 2
//! ```
//!
//! Each icon is one process of the release binary next to this example
//! (`target/release/lncert`), killed after
//! `--timeout` seconds (counted as undecided, "timeout"). Printed: counts of
//! proven (exit 0), undecided (exit 3, or the timeout) and refused (exit 2),
//! the undecided elements' first unproven note and the refusals' reasons,
//! grouped by their text up to the first digit, with counts; dots stroked;
//! and the time per icon (median, p90, p99, max). `--json FILE` writes every
//! icon's outcome.

use std::collections::BTreeMap;
use std::path::{Path, PathBuf};
use std::process::{Command, Stdio};
use std::time::{Duration, Instant};

struct Outcome {
    icon: String,
    verdict: &'static str,
    secs: f64,
    reasons: Vec<String>,
    elements: usize,
    dots: usize,
}

fn arg<T: std::str::FromStr>(args: &[String], name: &str, default: T) -> T {
    args.iter()
        .position(|a| a == name)
        .and_then(|i| args.get(i + 1))
        .and_then(|v| v.parse().ok())
        .unwrap_or(default)
}

/// A reason's class: its text up to the first digit (so that numbers and
/// indices do not split one kind of reason into many).
fn class(s: &str) -> String {
    let cut = s.find(|c: char| c.is_ascii_digit()).unwrap_or(s.len());
    let mut t: String = s[..cut].chars().take(110).collect();
    t.truncate(t.trim_end().len());
    t
}

fn run_icon(lncert: &Path, icon: &Path, tol: &str, output: &str, timeout: Duration) -> Outcome {
    let name = icon
        .file_name()
        .map(|n| n.to_string_lossy().to_string())
        .unwrap_or_default();
    let t0 = Instant::now();
    let child = Command::new(lncert)
        .args(["stroke", &icon.to_string_lossy(), "--tol", tol, "--json"])
        .args(["--output", output])
        .stdout(Stdio::piped())
        .stderr(Stdio::piped())
        .spawn();
    let Ok(mut child) = child else {
        return Outcome {
            icon: name,
            verdict: "refused",
            secs: 0.0,
            reasons: vec!["lncert could not be started".into()],
            elements: 0,
            dots: 0,
        };
    };
    // the pipes are drained while the child runs (a child whose output
    // fills a pipe that nobody reads would block until the timeout)
    let drain = |pipe: Option<Box<dyn std::io::Read + Send>>| {
        std::thread::spawn(move || {
            let mut buf = Vec::new();
            if let Some(mut p) = pipe {
                let _ = p.read_to_end(&mut buf);
            }
            buf
        })
    };
    let stdout = drain(child.stdout.take().map(|p| Box::new(p) as _));
    let stderr = drain(child.stderr.take().map(|p| Box::new(p) as _));
    let status = loop {
        match child.try_wait() {
            Ok(Some(status)) => break status,
            Ok(None) if t0.elapsed() > timeout => {
                let _ = child.kill();
                let _ = child.wait();
                return Outcome {
                    icon: name,
                    verdict: "undecided",
                    secs: t0.elapsed().as_secs_f64(),
                    reasons: vec![format!("timeout ({} s)", timeout.as_secs())],
                    elements: 0,
                    dots: 0,
                };
            }
            Ok(None) => std::thread::sleep(Duration::from_millis(2)),
            Err(e) => {
                return Outcome {
                    icon: name,
                    verdict: "refused",
                    secs: t0.elapsed().as_secs_f64(),
                    reasons: vec![format!("lncert could not be waited for: {e}")],
                    elements: 0,
                    dots: 0,
                }
            }
        }
    };
    let out = std::process::Output {
        status,
        stdout: stdout.join().unwrap_or_default(),
        stderr: stderr.join().unwrap_or_default(),
    };
    let secs = t0.elapsed().as_secs_f64();
    let code = out.status.code().unwrap_or(-1);
    let stderr = String::from_utf8_lossy(&out.stderr);
    let v: serde_json::Value = serde_json::from_slice(&out.stdout).unwrap_or_default();
    let els = v["elements"].as_array().cloned().unwrap_or_default();
    let dots = els
        .iter()
        .filter(|e| {
            e["outline"]["notes"][0]
                .as_str()
                .is_some_and(|n| n.starts_with("a dot"))
        })
        .count();
    let mut reasons = Vec::new();
    for e in &els {
        // the first unproven claim of each element
        if let Some(u) = e["outline"]["uncertain"].as_array().and_then(|a| a.first()) {
            reasons.push(u["note"].as_str().unwrap_or("?").to_string());
        }
    }
    let verdict = match code {
        0 => "proven",
        3 => "undecided",
        _ => {
            reasons.push(stderr.lines().next().unwrap_or("?").to_string());
            "refused"
        }
    };
    Outcome {
        icon: name,
        verdict,
        secs,
        reasons,
        elements: els.len(),
        dots,
    }
}

fn main() {
    let args: Vec<String> = std::env::args().skip(1).collect();
    let Some(dir) = args.first().filter(|a| !a.starts_with("--")) else {
        eprintln!("usage: corpus DIR|FILE.svg [--tol T] [--output cubic|native] [--every K] [--timeout S] [--jobs N] [--json FILE]");
        std::process::exit(2);
    };
    let tol: String = arg(&args, "--tol", "1e-2".to_string());
    let output: String = arg(&args, "--output", "cubic".to_string());
    let every: usize = arg(&args, "--every", 1).max(1);
    let timeout = Duration::from_secs(arg(&args, "--timeout", 60));
    let jobs: usize = arg(&args, "--jobs", 2).max(1);
    let lncert = std::env::current_exe()
        .ok()
        .and_then(|p| Some(p.parent()?.parent()?.join("lncert")))
        .filter(|p| p.exists());
    let Some(lncert) = lncert else {
        eprintln!("corpus: build the binary first: cargo build --release -p lncert-cli");
        std::process::exit(2);
    };
    let path = PathBuf::from(dir);
    let mut icons: Vec<PathBuf> = if path.is_dir() {
        std::fs::read_dir(&path)
            .map(|r| r.filter_map(|e| e.ok().map(|e| e.path())).collect())
            .unwrap_or_default()
    } else {
        vec![path]
    };
    icons.retain(|p| p.extension().is_some_and(|e| e == "svg"));
    icons.sort();
    let icons: Vec<PathBuf> = icons.into_iter().step_by(every).collect();
    if icons.is_empty() {
        eprintln!("corpus: no .svg files in {dir}");
        std::process::exit(2);
    }
    eprintln!(
        "corpus: {} icons, TOL {tol}, {output} output, {jobs} at once",
        icons.len()
    );
    let next = std::sync::atomic::AtomicUsize::new(0);
    let results = std::sync::Mutex::new(Vec::new());
    let t0 = Instant::now();
    std::thread::scope(|s| {
        for _ in 0..jobs {
            s.spawn(|| loop {
                let i = next.fetch_add(1, std::sync::atomic::Ordering::Relaxed);
                let Some(icon) = icons.get(i) else { break };
                let o = run_icon(&lncert, icon, &tol, &output, timeout);
                let mut r = results.lock().expect("results");
                r.push(o);
                if r.len() % 50 == 0 {
                    eprintln!(
                        "corpus: {} of {} ({:.0} s)",
                        r.len(),
                        icons.len(),
                        t0.elapsed().as_secs_f64()
                    );
                }
            });
        }
    });
    let mut results = results.into_inner().expect("results");
    results.sort_by(|a, b| a.icon.cmp(&b.icon));
    let n = results.len();
    let count = |v: &str| results.iter().filter(|o| o.verdict == v).count();
    let pct = |k: usize| 100.0 * k as f64 / n as f64;
    let (p, u, r) = (count("proven"), count("undecided"), count("refused"));
    println!(
        "{n} icons ({} elements, {} dots stroked), TOL {tol}, {output} output, {:.0} s in all",
        results.iter().map(|o| o.elements).sum::<usize>(),
        results.iter().map(|o| o.dots).sum::<usize>(),
        t0.elapsed().as_secs_f64()
    );
    println!(
        "proven {p} ({:.1} %), undecided {u} ({:.1} %), refused {r} ({:.1} %)",
        pct(p),
        pct(u),
        pct(r)
    );
    let mut secs: Vec<f64> = results.iter().map(|o| o.secs).collect();
    secs.sort_by(f64::total_cmp);
    let q = |f: f64| secs[((n - 1) as f64 * f).round() as usize];
    println!(
        "time per icon: median {:.3} s, p90 {:.3} s, p99 {:.3} s, max {:.3} s",
        q(0.5),
        q(0.9),
        q(0.99),
        secs[n - 1]
    );
    let mut classes: BTreeMap<(String, String), usize> = BTreeMap::new();
    for o in &results {
        for reason in &o.reasons {
            *classes
                .entry((o.verdict.to_string(), class(reason)))
                .or_default() += 1;
        }
    }
    let mut classes: Vec<_> = classes.into_iter().collect();
    classes.sort_by_key(|c| std::cmp::Reverse(c.1));
    println!("\nreasons (an element's first unproven claim, or the refusal), by kind:");
    for ((verdict, c), k) in classes {
        println!("  {k:5}  {verdict:9}  {c}");
    }
    if let Some(file) = args
        .iter()
        .position(|a| a == "--json")
        .and_then(|i| args.get(i + 1))
    {
        let doc: Vec<serde_json::Value> = results
            .iter()
            .map(|o| {
                serde_json::json!({"icon": o.icon, "verdict": o.verdict, "seconds": o.secs,
                    "elements": o.elements, "dots": o.dots, "reasons": o.reasons})
            })
            .collect();
        if let Err(e) = std::fs::write(file, serde_json::to_string_pretty(&doc).unwrap_or_default())
        {
            eprintln!("corpus: --json {file}: {e}");
        }
    }
}
