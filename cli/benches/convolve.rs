//! The convolution with an elliptical pen (seed 001, issue 12): the nonic of
//! seed 000 §5 with the font 'H' pen (semi-axes 0.7, 0.3, θ = π/6), both sides,
//! certified, at TOL = 1e-1 … 1e-3 (criterion); the exact cusp isolation alone
//! (its share of the time); and one-shot figures printed first: segments,
//! control points and time per side at TOL = 1e-1 … 1e-5, and the same runs
//! with `certify: false` (the float construction, unproven) for the ratio
//! proven / unproven.
//!
//! Run: `cargo bench --bench convolve`.

// `criterion_group!` defines an undocumented `pub fn benches`.
#![allow(missing_docs)]

use criterion::{criterion_group, criterion_main, Criterion};
use lncert::offset::kernels::conv_cusps;
use lncert::offset::kernels::Subdivision;
use lncert::offset::{convolve, OffsetMethod, OffsetOptions};
use lncert::scalar::Rational;
use lncert_cli::reproduce::seed001::{nonic, pen};
use std::hint::black_box;

fn opts(tol: f64, certify: bool) -> OffsetOptions {
    let tol = lncert::Tolerance::from_f64(tol).unwrap();
    let mut o = OffsetOptions::new(Rational::from_integer(0.into()), tol);
    o.certify = certify;
    o
}

fn bench(c: &mut Criterion) {
    let x = nonic().unwrap();
    let p = pen(1e-9).unwrap();
    for tol in [1e-1, 1e-2, 1e-3, 1e-4, 1e-5] {
        let mut line = format!("one shot, TOL {tol:e}:");
        for side in [-1i8, 1] {
            let t = std::time::Instant::now();
            let r = convolve(&x, &p, side, &opts(tol, true)).unwrap();
            let proven = t.elapsed().as_secs_f64();
            let t = std::time::Instant::now();
            let u = convolve(&x, &p, side, &opts(tol, false)).unwrap();
            let unproven = t.elapsed().as_secs_f64();
            line += &format!(
                " side {side:+}: {} segments ({} unproven), {} control points, d_H ≤ {:.3e}, {:.3} s proven / {:.3} s unproven ({:.1}×);",
                r.segments.len(),
                u.segments.len(),
                r.control_points(),
                r.certified_hi,
                proven,
                unproven,
                proven / unproven
            );
        }
        println!("{line}");
    }
    // seed 000 §5's LN pairs: segments per subdivision rule, and the paper's
    // measure d_H(p, pa) + d_H(q, qa) against the certified true error per piece
    for tol in [1e-1, 1e-2, 1e-3] {
        let mut line = format!("LN pairs, TOL {tol:e}:");
        for rule in [
            Subdivision::MidAngle,
            Subdivision::Chord,
            Subdivision::Weighted,
        ] {
            let mut o = opts(tol, true);
            o.method = OffsetMethod::LnPair;
            o.subdivision = rule;
            o.paper_error = true;
            let t = std::time::Instant::now();
            let rs: Vec<_> = [-1i8, 1]
                .iter()
                .map(|s| convolve(&x, &p, *s, &o).unwrap())
                .collect();
            let secs = t.elapsed().as_secs_f64();
            let pieces: Vec<_> = rs.iter().flat_map(|r| r.segments.iter()).collect();
            // pieces whose measure (an upper bound) is below the true error (a lower bound)
            let under = pieces
                .iter()
                .filter(|g| g.paper_error.is_some_and(|m| m < g.error.0))
                .count();
            let ratio = pieces
                .iter()
                .filter_map(|g| g.paper_error.map(|m| m / g.error.1))
                .fold((f64::INFINITY, 0.0f64), |(lo, hi), r| {
                    (lo.min(r), hi.max(r))
                });
            line += &format!(
                " rule ({}): {} / {} segments, {:.2} s both sides, measure < true error on {under} of {} pieces, measure/true-error ∈ [{:.2}, {:.2}];",
                rule.name(),
                rs[0].segments.len(),
                rs[1].segments.len(),
                secs,
                pieces.len(),
                ratio.0,
                ratio.1
            );
        }
        println!("{line}");
    }
    let mut g = c.benchmark_group("convolve");
    g.sample_size(10);
    for tol in [1e-1, 1e-2, 1e-3] {
        g.bench_function(format!("nonic_both_sides_tol{tol:e}"), |b| {
            b.iter(|| {
                for side in [-1i8, 1] {
                    convolve(black_box(&x), &p, side, &opts(tol, true)).unwrap();
                }
            })
        });
    }
    g.bench_function("nonic_cusps_both_sides", |b| {
        b.iter(|| conv_cusps(0, black_box(&x[0]), &p, -1).len() + conv_cusps(0, &x[0], &p, 1).len())
    });
    g.finish();
}

criterion_group!(benches, bench);
criterion_main!(benches);
