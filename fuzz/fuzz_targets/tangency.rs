#![no_main]
//! Fuzz target `tangency`: seed 003 §4 tangency systems and the `Poly2` parser.
//!
//! * The raw bytes, as (lossy UTF-8) text, go to
//!   `lncert::tangency::parse_poly2`: must never panic.
//! * The first 12 bytes give six small rationals `x1, y1, u, ox, oy, r`
//!   (per value: numerator an `i8`, denominator `1 + byte % 16`; missing
//!   bytes read as 0) -> `TangencySystem::new` -> `TangencyProblem::new`
//!   (default `a2` window) -> `solve_complete` with a small box budget from
//!   [`BUDGETS`] picked by byte 12 (missing: the first; the solver's cost grows
//!   with the boxes it splits, and a fixed 300 kept the target near 700
//!   runs/s): must not panic and must stop (constructor errors are fine). The report
//!   must be consistent: at most `max_boxes` boxes, not `complete` with
//!   undecided boxes, certified root enclosures inside the search domain,
//!   pairwise disjoint, and each containing 0 in the interval evaluation of
//!   eq. (6) and (7) (a true zero lies in it).

use libfuzzer_sys::{fuzz_target, Corpus};
use lncert::scalar::{frac, interval_from_rational, Rational};
use lncert::tangency::parse_poly2;
use lncert::tangency::SolveOptions;
use lncert::tangency::TangencySystem;
use lncert::tangency::{solve_complete, TangencyProblem};

fn small(data: &[u8], i: usize) -> Rational {
    let num = data.get(2 * i).copied().unwrap_or(0) as i8;
    let den = 1 + data.get(2 * i + 1).copied().unwrap_or(0) % 16;
    frac::<Rational>(num.into(), den.into())
}

/// Box budgets of `solve_complete`, one picked per input (byte 12 modulo 8):
/// mostly small, the former fixed 300 on one input in 8.
const BUDGETS: [usize; 8] = [16, 24, 32, 48, 64, 96, 128, 300];

fuzz_target!(|data: &[u8]| -> Corpus {
    let parsed = parse_poly2(&String::from_utf8_lossy(data)).is_ok();
    let v: Vec<Rational> = (0..6).map(|i| small(data, i)).collect();
    let Ok(sys) = TangencySystem::new(
        v[0].clone(),
        v[1].clone(),
        v[2].clone(),
        v[3].clone(),
        v[4].clone(),
        v[5].clone(),
    ) else {
        return if parsed { Corpus::Keep } else { Corpus::Reject };
    };
    let Ok(problem) = TangencyProblem::new(sys, None) else {
        return if parsed { Corpus::Keep } else { Corpus::Reject };
    };
    let opts = SolveOptions {
        max_boxes: BUDGETS[usize::from(data.get(12).copied().unwrap_or(0) % 8)],
        ..SolveOptions::default()
    };
    let rep = solve_complete(&problem, &opts);
    assert!(
        rep.boxes <= opts.max_boxes,
        "box budget {} exceeded: {} boxes",
        opts.max_boxes,
        rep.boxes
    );
    if rep.complete {
        assert!(
            rep.undecided.is_empty(),
            "report complete with {} undecided boxes",
            rep.undecided.len()
        );
    }
    let dom = problem.domain().outward();
    let eq6 = problem.system.eq6.map(interval_from_rational);
    let eq7 = problem.system.eq7.map(interval_from_rational);
    for (i, root) in rep.roots.iter().enumerate() {
        for (k, e) in [root.m, root.a2].into_iter().enumerate() {
            let d = dom[k];
            assert!(
                e.inf() >= d.inf() && e.sup() <= d.sup(),
                "certified root {i}: enclosure {k} = [{}, {}] outside the domain [{}, {}]",
                e.inf(),
                e.sup(),
                d.inf(),
                d.sup()
            );
        }
        // A true zero lies in the enclosure: interval evaluation must contain 0.
        for (name, eq) in [("eq6", &eq6), ("eq7", &eq7)] {
            let v = eq.eval(&root.m, &root.a2);
            assert!(
                v.contains(0.0),
                "certified root {i} (m in [{}, {}], a2 in [{}, {}]): {name} encloses [{}, {}], not 0",
                root.m.inf(),
                root.m.sup(),
                root.a2.inf(),
                root.a2.sup(),
                v.inf(),
                v.sup()
            );
        }
        for (j, other) in rep.roots.iter().enumerate().skip(i + 1) {
            let disjoint = root.m.disjoint(other.m) || root.a2.disjoint(other.a2);
            assert!(
                disjoint,
                "certified roots {i} and {j} have overlapping enclosures"
            );
        }
    }
    Corpus::Keep
});
