//! Circle tangency (seed 003 §4): time per proven-complete solve of the
//! complete interval solver on representative problems, the exact
//! elimination oracle, and the radius set; prints box counts and Krawczyk
//! steps once.
//!
//! Run: `cargo bench --bench tangency`.

// `criterion_group!` defines an undocumented `pub fn benches`.
#![allow(missing_docs)]

use criterion::{criterion_group, criterion_main, Criterion};
use lncert::scalar::{frac, Rational};
use lncert::tangency::valid_radii;
use lncert::tangency::EnclosureForm;
use lncert::tangency::SolveOptions;
use lncert::tangency::TangencySystem;
use lncert::tangency::{solve_complete, solve_exact, TangencyProblem};
use std::hint::black_box;

fn q(p: i64, d: i64) -> Rational {
    frac(p, d)
}

/// `(name, x1, y1, u, ox, oy, r)`.
fn problems() -> Vec<(&'static str, TangencyProblem)> {
    let mk = |x1, y1, u, ox, oy, r| {
        TangencyProblem::new(TangencySystem::new(x1, y1, u, ox, oy, r).unwrap(), None).unwrap()
    };
    vec![
        // Two nonsingular solutions, like the paper's Fig. 4.
        (
            "fig4-like-2-roots",
            mk(
                q(3, 1),
                q(-1, 1),
                q(1, 1),
                q(15, 16),
                q(-319, 128),
                q(-5, 2),
            ),
        ),
        // Three solutions (one singular quartic).
        (
            "3-roots",
            mk(q(3, 1), q(-1, 1), q(1, 1), q(9, 8), q(-683, 256), q(-5, 2)),
        ),
        // A circle no quartic of the window touches.
        (
            "0-roots",
            mk(q(3, 1), q(-1, 1), q(1, 1), q(5, 1), q(5, 1), q(1, 10)),
        ),
    ]
}

fn bench(c: &mut Criterion) {
    let probs = problems();
    for (name, p) in &probs {
        let rep = solve_complete(p, &SolveOptions::default());
        println!(
            "{name}: {} roots, complete {}, {} boxes, {} Krawczyk steps, a2 window [{:.4}, {:.4}]",
            rep.roots.len(),
            rep.complete,
            rep.boxes,
            rep.krawczyk_iterations,
            lncert::scalar::Scalar::approx(&p.a2_window.0),
            lncert::scalar::Scalar::approx(&p.a2_window.1)
        );
        let mut mv = p.clone();
        mv.interval_system.form = EnclosureForm::MeanValue;
        let r2 = solve_complete(&mv, &SolveOptions::default());
        println!(
            "{name} (mean-value form): {} roots, complete {}, {} boxes",
            r2.roots.len(),
            r2.complete,
            r2.boxes
        );
    }
    let mut g = c.benchmark_group("tangency");
    g.sample_size(20);
    for (name, p) in &probs {
        g.bench_function(format!("complete/{name}"), |b| {
            b.iter(|| solve_complete(black_box(p), &SolveOptions::default()))
        });
    }
    g.bench_function("complete-with-system-build/fig4-like-2-roots", |b| {
        b.iter(|| {
            let s = TangencySystem::new(
                q(3, 1),
                q(-1, 1),
                q(1, 1),
                q(15, 16),
                q(-319, 128),
                q(-5, 2),
            )
            .unwrap();
            solve_complete(
                &TangencyProblem::new(s, None).unwrap(),
                &SolveOptions::default(),
            )
        })
    });
    g.sample_size(10);
    g.bench_function("exact-oracle/fig4-like-2-roots", |b| {
        b.iter(|| solve_exact(black_box(&probs[0].1)))
    });
    g.bench_function("radii/fig4-like-centre", |b| {
        let h = &probs[0].1.system.hermite;
        b.iter(|| valid_radii(black_box(h), &q(15, 16), &q(-319, 128)).unwrap())
    });
    g.finish();
}

criterion_group!(benches, bench);
criterion_main!(benches);
