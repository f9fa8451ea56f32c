//! Offsets with a proven tolerance (issue 5): the whole certified offset of the
//! test cubic (`data/offset_test_curves.json`, d = 0.5) per method at TOL = 1e-2
//! and 1e-3 (criterion), the float construction alone per segment (what the
//! certification costs on top), and one-shot figures printed first: the
//! certified offset at TOL = 1e-5 with its time per certified search; then
//! the exact cusps of offsets and convolutions (group `cusps`).
//!
//! Run: `cargo bench --bench offset`. The peer comparison with kurbo is
//! `cargo run --release --example offset_compare`.

// `criterion_group!` defines an undocumented `pub fn benches`.
#![allow(missing_docs)]

use criterion::{criterion_group, criterion_main, Criterion};
use lncert::curve::{Bezier, V2};
use lncert::offset::kernels::{conv_cusps, ln_pair, offset_approximant_f64, offset_cusps};
use lncert::offset::{offset, OffsetMethod, OffsetOptions};
use lncert::offset::{Angle, Pen};
use lncert::scalar::{parse_rational, Scalar};
use lncert::shape::parse_curve;
use std::hint::black_box;

const CUBIC: &str = r#"{"bezier": [[-0.95, 0.7], [-0.3, 0.5], [0.3, -2.5], [0.9, -0.2]]}"#;

fn opts(m: OffsetMethod, tol: f64) -> OffsetOptions {
    let tol = lncert::Tolerance::from_f64(tol).unwrap();
    let mut o = OffsetOptions::new(parse_rational("0.5").unwrap(), tol);
    o.method = m;
    o
}

fn bench(c: &mut Criterion) {
    let curve = parse_curve(CUBIC).unwrap();
    for m in [OffsetMethod::G2, OffsetMethod::LnPair] {
        let t = std::time::Instant::now();
        let r = offset(&curve, &opts(m, 1e-5)).unwrap();
        let s = t.elapsed().as_secs_f64();
        println!(
            "one shot, {} TOL 1e-5: {} segments, {} control points, certified d_H ≤ {:.3e}, {:.2} s, {} certified searches ({:.1} ms each)",
            m.name(),
            r.segments.len(),
            r.control_points(),
            r.certified_hi,
            s,
            r.certifications,
            1e3 * s / r.certifications as f64
        );
    }
    let mut g = c.benchmark_group("offset");
    g.sample_size(10);
    for m in [OffsetMethod::G2, OffsetMethod::LnPair] {
        for tol in [1e-2, 1e-3] {
            g.bench_function(format!("{}_tol{tol:e}", m.name()), |b| {
                b.iter(|| offset(black_box(&curve), &opts(m, tol)).unwrap())
            });
        }
    }
    // the float constructions alone, on a span of the cubic
    let x: Bezier<f64> = curve[0].map(|v| v.approx()).restrict(&0.2, &0.4);
    let n = |t: f64| {
        let v = x.hodograph().eval(&t);
        let l = v.norm2().sqrt();
        V2::new(-v.y / l, v.x / l)
    };
    let (n0, n1) = (n(0.0), n(1.0));
    g.bench_function("construct_g2_segment", |b| {
        b.iter(|| offset_approximant_f64(black_box(&x), 0.5))
    });
    g.bench_function("construct_ln_pair_segment", |b| {
        b.iter(|| ln_pair(black_box(&x), &n0, &n1, 0.5))
    });
    g.finish();

    // the exact cusps (scaled Bernstein integers): the test cubic's offset at
    // d = 0.5 (inner side) and seed 000's nonic ∗ ellipse (0.7, 0.3, π/6),
    // whose cusp polynomial has degree 48
    let mut g = c.benchmark_group("cusps");
    g.sample_size(20);
    let d = parse_rational("0.5").unwrap();
    g.bench_function("offset_cubic_both_sides", |b| {
        b.iter(|| {
            offset_cusps(0, black_box(&curve[0]), &d).len()
                + offset_cusps(0, &curve[0], &-d.clone()).len()
        })
    });
    let nonic = parse_curve(NONIC).unwrap();
    let pen = Pen::ellipse(
        &parse_rational("0.7").unwrap(),
        &parse_rational("0.3").unwrap(),
        &Angle::parse("pi/6").unwrap(),
    )
    .unwrap();
    g.bench_function("convolution_nonic_both_sides", |b| {
        b.iter(|| {
            conv_cusps(0, black_box(&nonic[0]), &pen, 1).len()
                + conv_cusps(0, &nonic[0], &pen, -1).len()
        })
    });
    g.finish();
}

/// Seed 000 §5's degree-9 skeleton (`data/seed000_nonic_ellipse.json`).
const NONIC: &str = r#"{"bezier": [[0.2, 6.6], [8.9, -1.8], [7.2, -15.8], [-43.4, 41.8], [70.8, -41.3],
    [-29.6, 30.4], [20.9, 20.0], [-6.1, 4.1], [8.2, -7.8], [9.1, 3.8]]}"#;

criterion_group!(benches, bench);
criterion_main!(benches);
