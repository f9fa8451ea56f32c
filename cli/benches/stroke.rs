//! Time per trimmed outline and per intersection (issue 13, closed outlines).
//!
//! * `stroke/…`: the whole proven stroke (`lncert::stroke::stroke`: offsets,
//!   crossings, classification, claims (a)–(c)) of the closed lens of `lncert
//!   reproduce` (r = 1/4, TOL 1e-2, cubic output) and of the test cubic
//!   (r = 0.4, TOL 1e-3, cubic output);
//! * `intersections/…`: the certified crossing search
//!   (`lncert::stroke::intersections`) on two cubics that cross three
//!   times, on a cubic with a loop (one self-crossing), and on kurbo's stroke
//!   of the test cubic (r = 0.4, TOL 1e-2; its segments read exactly).
//!
//! One-shot figures are printed first: crossings found, and time per crossing.
//!
//! Run: `cargo bench --bench stroke`. The table against kurbo is
//! `cargo run --release --example stroke_compare`.

// `criterion_group!` defines an undocumented `pub fn benches`.
#![allow(missing_docs)]

use criterion::{criterion_group, criterion_main, Criterion};
use lncert::curve::Bezier;
use lncert::kurbo_bridge::shape_from_path;
use lncert::offset::Output;
use lncert::scalar::{parse_rational, Rational, Scalar};
use lncert::shape::{parse_curve, ShapeDesc};
use lncert::stroke::{intersections, IntersectOptions};
use lncert::stroke::{stroke, StrokeOptions};
use lncert_cli::reproduce::strokes::{lens, lens_radius};
use std::hint::black_box;
use std::time::Instant;

const CUBIC: &str = r#"{"bezier": [[-0.95, 0.7], [-0.3, 0.5], [0.3, -2.5], [0.9, -0.2]]}"#;

fn opts(r: Rational, tol: f64) -> StrokeOptions {
    let mut o = StrokeOptions::new(r, lncert::Tolerance::from_f64(tol).unwrap());
    o.output = Output::Cubic;
    o
}

/// kurbo's stroke of the test cubic, its segments exactly (zero-length ones dropped).
fn kurbo_pieces(curve: &[Bezier<Rational>]) -> Vec<Bezier<Rational>> {
    let p = curve[0].points();
    let pt = |i: usize| kurbo::Point::new(p[i].x.approx(), p[i].y.approx());
    let mut path = kurbo::BezPath::new();
    path.move_to(pt(0));
    path.curve_to(pt(1), pt(2), pt(3));
    let out = kurbo::stroke(
        path,
        &kurbo::Stroke::new(0.8),
        &kurbo::StrokeOpts::default(),
        1e-2,
    );
    let ShapeDesc::Curve(pieces) = shape_from_path(&out).expect("finite") else {
        unreachable!("a path reads as a curve")
    };
    pieces
        .into_iter()
        .filter(|b| b.points().iter().any(|q| q != &b.points()[0]))
        .collect()
}

fn bench(c: &mut Criterion) {
    let cubic = parse_curve(CUBIC).unwrap();
    let strokes = [
        ("lens_r0.25_tol1e-2", lens(), opts(lens_radius(), 1e-2)),
        (
            "test_cubic_r0.4_tol1e-3",
            cubic.clone(),
            opts(parse_rational("0.4").unwrap(), 1e-3),
        ),
    ];
    for (name, x, o) in &strokes {
        let t = Instant::now();
        let s = stroke(x, o).unwrap();
        let secs = t.elapsed().as_secs_f64();
        println!(
            "one shot, stroke {name}: {} raw pieces, {} crossings cut, {} output pieces, \
             claims proven: {}, {:.2} s ({:.2} s per crossing cut)",
            s.raw_pieces,
            s.crossings.len(),
            s.pieces(),
            s.proven(),
            secs,
            secs / s.crossings.len().max(1) as f64
        );
    }
    let two = [
        parse_curve("M 0 0 C 1 3 2 -2 3 1").unwrap()[0].clone(),
        parse_curve("M 0 1 C 1 -2 2 3 3 0").unwrap()[0].clone(),
    ];
    let looped = [parse_curve("M 0 0 C 3 2 -1 2 2 0").unwrap()[0].clone()];
    let kp = kurbo_pieces(&cubic);
    let sets: [(&str, &[Bezier<Rational>]); 3] = [
        ("two_cubics", &two),
        ("loop_cubic", &looped),
        ("kurbo_stroke_test_cubic", &kp),
    ];
    let iopts = IntersectOptions::default();
    for (name, pieces) in &sets {
        let t = Instant::now();
        let r = intersections(pieces, &iopts);
        let secs = t.elapsed().as_secs_f64();
        let pairs = pieces.len() * (pieces.len() + 1) / 2;
        println!(
            "one shot, intersections {name}: {} pieces ({pairs} pairs), {} crossings, \
             {} undecided boxes, complete: {}, {:.2} ms ({:.2} ms per crossing, {:.3} ms per pair)",
            pieces.len(),
            r.crossings.len(),
            r.undecided.len(),
            r.complete,
            1e3 * secs,
            1e3 * secs / r.crossings.len().max(1) as f64,
            1e3 * secs / pairs as f64
        );
    }
    let mut g = c.benchmark_group("stroke");
    g.sample_size(10);
    for (name, x, o) in &strokes {
        g.bench_function(*name, |b| b.iter(|| stroke(black_box(x), o).unwrap()));
    }
    g.finish();
    let mut g = c.benchmark_group("intersections");
    g.sample_size(20);
    for (name, pieces) in &sets {
        g.bench_function(*name, |b| {
            b.iter(|| intersections(black_box(pieces), &iopts))
        });
    }
    g.finish();
}

criterion_group!(benches, bench);
criterion_main!(benches);
