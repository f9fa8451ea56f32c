//! The stroker audit: other strokers' outlines certified against the exact
//! stroke boundary `∂S` of `S = x ⊕ disk(r)` by lncert's referee
//! ([`lncert::stroke::distance_through`]: lncert's proven outline `L` at
//! `TOL/16` and the certified Hausdorff search between the outline and `L`).
//!
//! ```sh
//! cargo run --release --example audit_strokers                 # every case
//! cargo run --release --example audit_strokers -- --only heart # cases whose name contains `heart`
//! cargo run --release --example audit_strokers -- --skia-job > job.json   # the Skia script's input
//! python3 cli/examples/skia_stroke_dump.py < job.json > cli/examples/data/skia_strokes.json
//! ```
//!
//! Cases: the icon elements of `icon_strokes` (r 1, TOL 1e-2, in a 24-unit
//! viewBox), the test curves of `stroke_compare` with the pen radii of their
//! listed offsets (TOL 1e-2; pieces of degree above 3 are skipped, kurbo and
//! Skia take cubics), and 20 glyphs of DejaVu Sans (r 20 units, TOL 0.5
//! units, when the font is installed).
//!
//! Strokers: kurbo 0.13 `kurbo::stroke` (round caps and joins, tolerance
//! TOL), and Skia (skia-pathops) stroke + `simplify` at the matched
//! tolerance, read from the committed `cli/examples/data/skia_strokes.json`
//! (see `skia_stroke_dump.py`; conics written as quadratics, as SVG needs).
//!
//! lncert's outline is made at `ε = TOL/16` (where its claims (a), (b) are not
//! proven there: `TOL/4`, then `TOL/64`), and where the bounds straddle TOL
//! once more at `TOL/128`; the column `lncert's ε` says which decided.
//!
//! Per case and stroker: `h(X→∂S)` (how far the outline strays from ∂S: an
//! outline with parts inside S is far from ∂S even though it fills right),
//! `h(∂S→X)` (how far ∂S is from being covered), both certified `[lo, hi]`,
//! the verdict on `d_H(X, ∂S) ≤ TOL` (within / OVER / undecided) and on the
//! coverage `h(∂S→X) ≤ TOL` (covers / MISSES / undecided). A case counts as
//! decided when both verdicts are.

use kurbo::{BezPath, Cap, Join, Point};
use lncert::certify::Config;
use lncert::curve::Bezier;
use lncert::kurbo_bridge::shape_from_path;
use lncert::offset::Output;
use lncert::scalar::{Rational, Scalar};
use lncert::shape::ShapeDesc;
use lncert::stroke::{distance_through, stroke, StrokeDistance, StrokeOptions};
use lncert::Tolerance;
use serde_json::{json, Value};
use std::time::Instant;

const ICONS: [(&str, &str); 8] = [
    ("icon circle", r#"<circle cx="12" cy="12" r="3"/>"#),
    (
        "icon rect rx",
        r#"<rect x="3" y="3" width="18" height="18" rx="1.5"/>"#,
    ),
    (
        "icon ellipse",
        r#"<ellipse cx="12" cy="12" rx="8" ry="4"/>"#,
    ),
    (
        "icon arc path",
        r#"<path d="M12 2a10 10 0 1 0 10 10h-4a6 6 0 1 1-6-6z"/>"#,
    ),
    (
        "icon heart",
        r#"<path d="M20.84 4.61a5.5 5.5 0 0 0-7.78 0L12 5.67l-1.06-1.06a5.5 5.5 0 0 0-7.78 7.78l1.06 1.06L12 21.23l7.78-7.78 1.06-1.06a5.5 5.5 0 0 0 0-7.78z"/>"#,
    ),
    ("icon polyline", r#"<polyline points="4 17 10 11 4 5"/>"#),
    ("icon corners", r#"<path d="M20 6 9 17l-5-5"/>"#),
    (
        "icon relative curves",
        r#"<path d="M3 12c3-6 6-6 9 0s6 6 9 0"/>"#,
    ),
];

const GLYPHS: &str = "aeghkmnorsABGQRS&@25";

struct Case {
    name: String,
    curve: Vec<Bezier<Rational>>,
    /// The curve with its circular arcs exact (an icon's circles, rounded
    /// corners and SVG arcs with a rational centre), when it has any: `∂S`
    /// is then that of the exact arcs (`stroke_path`); kurbo and Skia stroke
    /// `curve`, the arcs' certified cubics.
    path: Option<Vec<lncert::stroke::PathPiece>>,
    r: Rational,
    tol: f64,
    /// The same tolerance, read exactly.
    tol_text: &'static str,
}

fn cases(only: Option<&str>) -> Vec<Case> {
    let mut out = Vec::new();
    for (name, el) in ICONS {
        let doc = format!(
            r#"<svg xmlns="http://www.w3.org/2000/svg" viewBox="0 0 24 24" fill="none" stroke="black" stroke-width="2">{el}</svg>"#
        );
        let (curve, approx) =
            lncert::shape::parse_svg_document_reported(&doc).expect("an icon element");
        let path = lncert::stroke::exact_path(&curve, &approx).map(|(p, _)| p);
        out.push(Case {
            name: name.to_string(),
            curve,
            path,
            r: Rational::from_integer(1.into()),
            tol: 1e-2,
            tol_text: "1e-2",
        });
    }
    for (name, curve, r) in lncert_cli::reproduce::strokes::test_cases().expect("the test curves") {
        if curve.iter().all(|b| b.degree() <= 3) {
            out.push(Case {
                name: format!("{name} r {}", r.approx()),
                curve,
                path: None,
                r,
                tol: 1e-2,
                tol_text: "1e-2",
            });
        } else {
            eprintln!("skipped {name}: pieces of degree above 3");
        }
    }
    let font = "/usr/share/fonts/truetype/dejavu/DejaVuSans.ttf";
    match std::fs::read(font) {
        Ok(data) => {
            for ch in GLYPHS.chars() {
                match lncert::shape::glyph_outline(&data, ch) {
                    Ok(curve) => out.push(Case {
                        name: format!("DejaVu Sans {ch}"),
                        curve,
                        path: None,
                        r: Rational::from_integer(20.into()),
                        tol: 0.5,
                        tol_text: "0.5",
                    }),
                    Err(e) => eprintln!("glyph {ch}: {e}"),
                }
            }
        }
        Err(e) => eprintln!("no glyph cases: {font}: {e}"),
    }
    out.retain(|c| only.is_none_or(|o| c.name.contains(o)));
    out
}

/// The pieces as a kurbo path (a new subpath where a piece does not start
/// at the previous end; a subpath back at its start is closed).
fn to_kurbo_path(curve: &[Bezier<Rational>]) -> BezPath {
    let pt = |v: &lncert::curve::V2<Rational>| Point::new(v.x.approx(), v.y.approx());
    let mut p = BezPath::new();
    let (mut start, mut last) = (None, None);
    let close = |p: &mut BezPath, s: Option<&_>, l: Option<&_>| {
        if s.is_some() && s == l {
            p.close_path();
        }
    };
    for b in curve {
        let q = b.points();
        if last != Some(&q[0]) {
            close(&mut p, start, last);
            p.move_to(pt(&q[0]));
            start = Some(&q[0]);
        }
        match q.len() {
            2 => p.line_to(pt(&q[1])),
            3 => p.quad_to(pt(&q[1]), pt(&q[2])),
            _ => p.curve_to(pt(&q[1]), pt(&q[2]), pt(&q[3])),
        }
        last = q.last();
    }
    close(&mut p, start, last);
    p
}

fn commands(p: &BezPath) -> Value {
    use kurbo::PathEl::*;
    let xy = |q: Point| vec![json!(q.x), json!(q.y)];
    Value::Array(
        p.elements()
            .iter()
            .map(|e| {
                let (v, pts): (&str, Vec<Point>) = match *e {
                    MoveTo(a) => ("M", vec![a]),
                    LineTo(a) => ("L", vec![a]),
                    QuadTo(a, b) => ("Q", vec![a, b]),
                    CurveTo(a, b, c) => ("C", vec![a, b, c]),
                    ClosePath => ("Z", vec![]),
                };
                let mut c = vec![json!(v)];
                c.extend(pts.into_iter().flat_map(xy));
                Value::Array(c)
            })
            .collect(),
    )
}

fn iv(x: (f64, f64)) -> String {
    format!("[{:.2e}, {:.2e}]", x.0, x.1)
}

fn verdicts(d: &StrokeDistance, tol: f64) -> (&'static str, &'static str) {
    let v = |lo: f64, hi: f64, yes, no| {
        if hi <= tol {
            yes
        } else if lo > tol {
            no
        } else {
            "undecided"
        }
    };
    (
        v(d.lo, d.hi, "within", "OVER"),
        v(d.from_stroke.0, d.from_stroke.1, "covers", "MISSES"),
    )
}

fn main() {
    let args: Vec<String> = std::env::args().collect();
    let only = args
        .iter()
        .position(|a| a == "--only")
        .and_then(|i| args.get(i + 1))
        .map(String::as_str);
    let cases = cases(only);
    if args.iter().any(|a| a == "--skia-job") {
        let paths: Vec<Value> = cases
            .iter()
            .map(|c| {
                json!({"name": c.name, "width": 2.0 * c.r.approx(), "tol": c.tol,
                       "cmds": commands(&to_kurbo_path(&c.curve))})
            })
            .collect();
        println!("{}", json!({ "paths": paths }));
        return;
    }
    let skia: Option<Value> = std::fs::read_to_string(concat!(
        env!("CARGO_MANIFEST_DIR"),
        "/examples/data/skia_strokes.json"
    ))
    .ok()
    .and_then(|t| serde_json::from_str(&t).ok());
    if skia.is_none() {
        eprintln!("no Skia data (cli/examples/data/skia_strokes.json): kurbo only");
    }
    println!("| case | r | TOL | stroker | segments | h(X→∂S) | h(∂S→X) | d_H ≤ TOL | covers ∂S | lncert's ε | stroke + search s |");
    println!("|---|---|---|---|---|---|---|---|---|---|---|");
    let (mut runs, mut decided) = (0, 0);
    for c in &cases {
        let t0 = Instant::now();
        // lncert's outline at TOL/16; where its claims (a), (b) are not
        // proven there, at TOL/4, then TOL/64 (the referee's fallbacks)
        let make = |div: i64| {
            let t: Tolerance = c.tol_text.parse().expect("a tolerance");
            let e = Tolerance::new(t.exact() / Rational::from_integer(div.into()))
                .expect("a tolerance");
            let mut o = StrokeOptions::new(c.r.clone(), e);
            o.output = Output::Cubic;
            match &c.path {
                Some(p) => lncert::stroke::stroke_path(p, &o),
                None => stroke(&c.curve, &o),
            }
        };
        let mut ours = None;
        for div in [16, 4, 64] {
            match make(div) {
                Ok(s) if s.a.proven && s.b.proven => {
                    ours = Some(s);
                    break;
                }
                Ok(s) => ours = Some(s),
                Err(e) => {
                    println!("| {} | — | — | — | — | — | — | lncert: {e} | | |", c.name);
                    break;
                }
            }
        }
        let Some(ours) = ours else { continue };
        let mut finer: Option<lncert::stroke::Stroke> = None;
        let stroke_secs = t0.elapsed().as_secs_f64();
        let path = to_kurbo_path(&c.curve);
        let kurbo_out = kurbo::stroke(
            path.iter(),
            &kurbo::Stroke::new(2.0 * c.r.approx())
                .with_caps(Cap::Round)
                .with_join(Join::Round),
            &kurbo::StrokeOpts::default(),
            c.tol,
        );
        let mut theirs: Vec<(&str, Result<ShapeDesc, String>)> = vec![(
            "kurbo",
            shape_from_path(&kurbo_out).map_err(|e| e.to_string()),
        )];
        if let Some(data) = skia.as_ref().and_then(|s| s["outlines"][&c.name].as_str()) {
            theirs.push(("Skia", ShapeDesc::parse(data).map_err(|e| e.to_string())));
        }
        for (who, x) in theirs {
            runs += 1;
            let x = match x {
                Ok(x) => x,
                Err(e) => {
                    println!("| {} | | | {who} | unreadable: {e} | | | | | |", c.name);
                    continue;
                }
            };
            let t1 = Instant::now();
            let cfg = Config::default();
            let mut d = match distance_through(&x, ours.clone(), &cfg) {
                Ok(d) => d,
                Err(e) => {
                    println!("| {} | | | {who} | referee error: {e} | | | | | |", c.name);
                    continue;
                }
            };
            let (mut v, mut cov) = verdicts(&d, c.tol);
            if d.outline.is_some() && (v == "undecided" || cov == "undecided") {
                // the bounds straddle TOL: a narrower bracket at TOL/128
                if finer.is_none() {
                    finer = make(128).ok();
                }
                if let Some(f) = finer.as_ref().filter(|f| f.a.proven && f.b.proven) {
                    if let Ok(d2) = distance_through(&x, f.clone(), &cfg) {
                        d = d2;
                        (v, cov) = verdicts(&d, c.tol);
                    }
                }
            }
            if v != "undecided" && cov != "undecided" {
                decided += 1;
            }
            println!(
                "| {} | {} | {:e} | {who} | {} | {} | {} | {v} | {cov} | {} | {:.2} + {:.2} |",
                c.name,
                c.r.approx(),
                c.tol,
                x.piece_count(),
                iv(d.to_stroke),
                iv(d.from_stroke),
                d.stroke.tol,
                stroke_secs,
                t1.elapsed().as_secs_f64()
            );
        }
    }
    println!(
        "\ndecided (both verdicts): {decided} of {runs} audits ({:.1} %)",
        100.0 * decided as f64 / runs.max(1) as f64
    );
}
