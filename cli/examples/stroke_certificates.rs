//! Stroke certificates, timed in one run (medians of 11 interleaved runs): for each icon element of
//! `icon_strokes` (circular pen of radius 1, round caps and joins, cubic
//! output, TOL 1e-2) and for the test cubic (pen radius 0.4, native output,
//! TOL 1e-2 and 1e-3) and elliptical pens on the test cubic and a closed oval
//! (cubic output; the certificate of the pre-image under `M⁻¹`), the proven stroke, the certificate's writing
//! (`lncert::stroke::certificate`) and its check by the independent verifier
//! (`lncert::certify::verify::verify` on the JSON text), with the ratio
//! verify / stroke, the document's size, its parts (claim (a)) and boxes
//! (claim (b)), the largest bound the verifier recomputed, and whether the
//! certificate states claim (c) (simple, disjoint, oriented contours).
//!
//! ```sh
//! cargo run --release -p lncert-cli --example stroke_certificates [NAME]
//! ```

use lncert::curve::Bezier;
use lncert::offset::Output;
use lncert::scalar::{Rational, Scalar};
use lncert::stroke::{certificate, stroke, PenShape, StrokeOptions};
use std::time::Instant;

/// The icon elements (viewBox 0 0 24 24), as in `icon_strokes`.
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

/// Runs per row: the stroke and the verifier each, medians reported.
const RUNS: usize = 11;

fn median(mut v: Vec<f64>) -> f64 {
    v.sort_by(f64::total_cmp);
    v[v.len() / 2]
}

fn row(name: &str, curve: &[Bezier<Rational>], pen: PenShape, tol: f64, output: Output) {
    let r = match &pen {
        PenShape::Circle(r) => r.clone(),
        PenShape::Ellipse(_) => Rational::from_integer(1.into()),
    };
    let r = &r;
    let mut o = StrokeOptions::with_pen(pen, lncert::Tolerance::from_f64(tol).expect("tol"));
    o.output = output;
    let s = match stroke(curve, &o) {
        Ok(x) => x,
        Err(e) => return println!("| {name} | {tol:e} | stroke error: {e} |"),
    };
    if !s.proven() {
        return println!("| {name} | {tol:e} | not proven: no certificate |");
    }
    let t1 = Instant::now();
    let c = match certificate(curve, &s, r) {
        Ok(c) => c,
        Err(e) => return println!("| {name} | {tol:e} | not written: {e} |"),
    };
    let tw = t1.elapsed().as_secs_f64();
    let count = |v: &serde_json::Value| v.as_array().map_or(0, Vec::len);
    let parts: usize = c["cover"]
        .as_array()
        .into_iter()
        .flatten()
        .flat_map(|x| x.as_array().into_iter().flatten())
        .map(count)
        .sum();
    let boxes: usize = c["boundary"]
        .as_array()
        .into_iter()
        .flatten()
        .map(|f| count(&f["boxes"]))
        .sum();
    let text = c.to_string();
    // medians of RUNS interleaved runs (a stroke, then a check): one run of
    // a few milliseconds is at the mercy of the shared machine, and a burst
    // of load then hits both sides of the ratio
    let (mut times_s, mut times_v) = (Vec::new(), Vec::new());
    let mut v = None;
    for _ in 0..RUNS {
        let t0 = Instant::now();
        let again = stroke(curve, &o);
        times_s.push(t0.elapsed().as_secs_f64());
        assert!(
            again.is_ok_and(|x| x.proven()),
            "the stroke is deterministic"
        );
        let t2 = Instant::now();
        v = Some(lncert::certify::verify::verify(&text));
        times_v.push(t2.elapsed().as_secs_f64());
    }
    let v = v.expect("RUNS ≥ 1");
    let (ts, tv) = (median(times_s), median(times_v));
    match v {
        Ok(v) => println!(
            "| {name} | {tol:e} | {ts:.3} s | {tw:.3} s | {tv:.3} s | {:.2} | {} kB | {parts} + {boxes} | {:.3e} | {} |",
            tv / ts,
            text.len().div_ceil(1000),
            v.max_bound,
            if c["simple"] == true { "yes" } else { "no" }
        ),
        Err(e) => println!("| {name} | {tol:e} | {ts:.3} s | {tw:.3} s | REFUSED: {e} |"),
    }
}

fn main() {
    let only = std::env::args().nth(1);
    println!("| input | TOL | stroke | write | verify | verify/stroke | size | parts + boxes | largest bound | (c) simple |");
    println!("|---|---|---|---|---|---|---|---|---|---|");
    let one = Rational::from_integer(1.into());
    for (name, el) in ICONS {
        if only.as_deref().is_some_and(|o| o != name) {
            continue;
        }
        let doc = format!(
            r#"<svg xmlns="http://www.w3.org/2000/svg" viewBox="0 0 24 24" fill="none" stroke="currentColor" stroke-width="2">{el}</svg>"#
        );
        let curve = lncert::shape::parse_svg_document(&doc).expect("icon");
        row(
            name,
            &curve,
            PenShape::Circle(one.clone()),
            1e-2,
            Output::Cubic,
        );
    }
    if only.as_deref().is_none_or(|o| o == "cubic") {
        let curve = lncert::parse_curve("M -0.95 0.7 C -0.3 0.5 0.3 -2.5 0.9 -0.2").expect("cubic");
        let r = lncert::parse_rational("2/5").expect("radius");
        for tol in [1e-2, 1e-3] {
            row(
                "test cubic r 0.4",
                &curve,
                PenShape::Circle(r.clone()),
                tol,
                Output::Native,
            );
        }
    }
    // elliptical pens: the certificate of the pre-image under M⁻¹
    if only.as_deref().is_none_or(|o| o == "ellipse pen") {
        let q = |s: &str| lncert::parse_rational(s).expect("number");
        let pen = |a: &str, b: &str, th: &str, tol: f64| {
            let angle = lncert::offset::Angle::parse(th).expect("angle");
            // the rotation as `lncert stroke --pen ellipse:` represents it
            let (af, bf) = (q(a).approx(), q(b).approx());
            let max_angle = (tol * 1e-3 / (af + af * af / bf)).clamp(1e-12, 1e-6);
            let p =
                lncert::offset::Pen::ellipse_within(&q(a), &q(b), &angle, max_angle).expect("pen");
            PenShape::Ellipse(p)
        };
        let curve = lncert::parse_curve("M -0.95 0.7 C -0.3 0.5 0.3 -2.5 0.9 -0.2").expect("cubic");
        for tol in [1e-2, 1e-3] {
            row(
                "test cubic, ellipse 0.4, 0.2, π/6",
                &curve,
                pen("0.4", "0.2", "pi/6", tol),
                tol,
                Output::Cubic,
            );
        }
        let oval = lncert::parse_curve("M 0 0 C 0 2 4 2 4 0 C 4 -2 0 -2 0 0 Z").expect("oval");
        row(
            "closed oval, ellipse 0.7, 0.3, π/6",
            &oval,
            pen("0.7", "0.3", "pi/6", 1e-2),
            1e-2,
            Output::Cubic,
        );
    }
}
