//! Time per decision of Prop 4.2 + Prop 4.4 (seed 000) on random compatible
//! pairs: the paper's form (`pair_decision`) in f64, interval, filtered
//! (interval, then exact fallback), filtered with the static stage first
//! (float with error bound, interval, exact) and rationals; then the
//! division-free form (`pair_decision_signs`, what `filtered` evaluates) in
//! f64, its static stage (`pair_decision_static`), float with error bound,
//! small exact rationals (`SmallRat`), the five stages, `filtered` itself (converting its inputs) and rationals. Prints the
//! filter's fallback rate and how often the f64 path disagrees with the exact
//! answer.
//!
//! Run: `cargo bench --bench decisions`.

// `criterion_group!` defines an undocumented `pub fn benches`.
#![allow(missing_docs)]

use criterion::{criterion_group, criterion_main, Criterion};
use lncert::ln::pair::{pair_decision, pair_decision_signs, pair_decision_static, PairDecision};
use lncert::scalar::{
    filter_stats, filtered, frac, reset_filter_stats, FloatErr, Interval, Predicate, Rational,
    Scalar, SmallRat,
};
use std::hint::black_box;

/// Deterministic pseudo-random pairs (64-bit LCG), c0, c1 of one sign, ρl
/// anywhere in (0, 3): a mix of admissible and inadmissible choices.
/// One in eight cases is planted near a boundary (q ≈ 4, δ ≈ 1).
fn cases(n: usize) -> Vec<PairDecision> {
    let mut s: u64 = 0x9E37_79B9_7F4A_7C15;
    let mut next = |m: u64| {
        s = s
            .wrapping_mul(6364136223846793005)
            .wrapping_add(1442695040888963407);
        (s >> 33) % m
    };
    (0..n)
        .map(|i| {
            let sign = if next(2) == 0 { 1 } else { -1 };
            let c0: Rational = frac(sign * (1 + next(997) as i64), 1 + next(97) as i64);
            let k: Rational = if i % 8 == 0 {
                frac(4_000_000 - 1 + next(3) as i64, 1_000_000)
            } else {
                frac(1 + next(1999) as i64, 1 + next(499) as i64)
            };
            let c1 = &c0 * &k;
            let rho = frac(1 + next(2999) as i64, 1000);
            PairDecision {
                c0,
                c1,
                rho_left: rho,
            }
        })
        .collect()
}

/// The inputs in arithmetic `S` (converted once, outside the timed loops).
fn convert<S: Scalar>(rat: &[(Rational, Rational, Rational)]) -> Vec<(S, S, S)> {
    rat.iter()
        .map(|(a, b, r)| {
            (
                S::from_rational(a),
                S::from_rational(b),
                S::from_rational(r),
            )
        })
        .collect()
}

type Decide<S> = fn(&S, &S, &S) -> Option<(bool, Option<bool>)>;

/// How many of `v` the decision `f` decides (the timed body of one arithmetic).
fn decided<S>(v: &[(S, S, S)], f: Decide<S>) -> usize {
    v.iter()
        .filter_map(|(a, c, r)| f(black_box(a), c, r))
        .count()
}

fn bench(c: &mut Criterion) {
    let data = cases(512);
    reset_filter_stats();
    let mut f64_errors = 0;
    for d in &data {
        let exact = d.decide::<Rational>();
        let _ = filtered(d);
        if d.decide::<f64>() != exact {
            f64_errors += 1;
        }
    }
    let st = filter_stats();
    println!(
        "decisions: {} random pairs; filter fallback rate {:.2}% ({} of {}); f64 decisions differing from exact: {}",
        data.len(),
        100.0 * st.rate(),
        st.fallbacks,
        st.calls,
        f64_errors
    );
    // Inputs converted once, outside the timed loops: each path gets its own
    // arithmetic's values, as a caller of that path would hold them.
    let conv = |d: &PairDecision| (d.c0.clone(), d.c1.clone(), d.rho_left.clone());
    let rat: Vec<_> = data.iter().map(conv).collect();
    let flt: Vec<(f64, f64, f64)> = rat
        .iter()
        .map(|(a, b, r)| (a.approx(), b.approx(), r.approx()))
        .collect();
    let ivs: Vec<(Interval, Interval, Interval)> = convert(&rat);
    let fes: Vec<(FloatErr, FloatErr, FloatErr)> = convert(&rat);
    let undecided = fes
        .iter()
        .filter(|(a, c, r)| pair_decision(a, c, r).is_none())
        .count();
    println!(
        "decisions: the float-with-error-bound stage leaves {undecided} of {} undecided",
        fes.len()
    );
    let mut g = c.benchmark_group("prop_4_2_and_4_4");
    g.bench_function("f64", |b| b.iter(|| decided(&flt, pair_decision)));
    g.bench_function("interval", |b| b.iter(|| decided(&ivs, pair_decision)));
    g.bench_function("filtered", |b| {
        b.iter(|| {
            ivs.iter()
                .zip(&rat)
                .filter_map(|((a, c, r), (ea, ec, er))| {
                    pair_decision(black_box(a), c, r).or_else(|| pair_decision(ea, ec, er))
                })
                .count()
        })
    });
    // the static stage alone (decides all but the near-boundary cases)
    g.bench_function("float_err", |b| b.iter(|| decided(&fes, pair_decision)));
    // the paper form's former filter: float with error bound, then intervals, then rationals
    g.bench_function("filtered_static", |b| {
        b.iter(|| {
            fes.iter()
                .zip(&ivs)
                .zip(&rat)
                .filter_map(|(((a, c, r), (ia, ic, ir)), (ea, ec, er))| {
                    pair_decision(black_box(a), c, r)
                        .or_else(|| pair_decision(ia, ic, ir))
                        .or_else(|| pair_decision(ea, ec, er))
                })
                .count()
        })
    });
    g.bench_function("rational", |b| b.iter(|| decided(&rat, pair_decision)));
    g.finish();
    // The division-free form (`pair_decision_signs`, what `filtered` evaluates):
    // the same decisions as signs of polynomials of degree ≤ 1 in each input.
    let undecided = fes
        .iter()
        .filter(|(a, c, r)| pair_decision_signs(a, c, r).is_none())
        .count();
    let undecided_iv = ivs
        .iter()
        .filter(|(a, c, r)| pair_decision_signs(a, c, r).is_none())
        .count();
    println!(
        "decisions, division-free form: the float-with-error-bound stage leaves {undecided} of {} undecided, intervals {undecided_iv}",
        fes.len()
    );
    let mut g = c.benchmark_group("prop_4_2_and_4_4_division_free");
    g.bench_function("f64", |b| b.iter(|| decided(&flt, pair_decision_signs)));
    // the static stage: plain f64 tests against one bound from the inputs' magnitude
    let by_static = |d: &[(FloatErr, FloatErr, FloatErr)]| {
        d.iter()
            .filter_map(|(a, c, r)| pair_decision_static(*black_box(a), *c, *r))
            .count()
    };
    println!(
        "decisions, division-free form: the static stage decides {} of {}",
        by_static(&fes),
        fes.len()
    );
    g.bench_function("static", |b| b.iter(|| by_static(&fes)));
    g.bench_function("float_err", |b| {
        b.iter(|| decided(&fes, pair_decision_signs))
    });
    let sms: Vec<(SmallRat, SmallRat, SmallRat)> = convert(&rat);
    g.bench_function("small_rational", |b| {
        b.iter(|| decided(&sms, pair_decision_signs))
    });
    // the five stages as `filtered` runs them, inputs held in each arithmetic
    g.bench_function("filtered_static", |b| {
        b.iter(|| {
            fes.iter()
                .zip(&sms)
                .zip(&ivs)
                .zip(&rat)
                .filter_map(
                    |((((a, c, r), (sa, sc, sr)), (ia, ic, ir)), (ea, ec, er))| {
                        pair_decision_static(*black_box(a), *c, *r)
                            .or_else(|| pair_decision_signs(a, c, r))
                            .or_else(|| pair_decision_signs(sa, sc, sr))
                            .or_else(|| pair_decision_signs(ia, ic, ir))
                            .or_else(|| pair_decision_signs(ea, ec, er))
                    },
                )
                .count()
        })
    });
    // `filtered` itself: each stage converts the exact inputs on entry
    g.bench_function("filtered_converting", |b| {
        b.iter(|| data.iter().filter_map(|d| filtered(black_box(d))).count())
    });
    g.bench_function("rational", |b| {
        b.iter(|| decided(&rat, pair_decision_signs))
    });
    g.finish();
}

criterion_group!(benches, bench);
criterion_main!(benches);
