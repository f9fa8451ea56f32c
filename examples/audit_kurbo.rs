//! Audit another library's tolerance claims: kurbo 0.13's own accuracy
//! parameters, property-tested with lncert's certified verdicts.
//!
//! Run: `cargo run --release --example audit_kurbo [-- CASES]` (default 48
//! cases per claim and tolerance).
//!
//! For random cubics (control points on a 1/8 grid in [-2, 2]², regular ones
//! only, since an exact offset needs `c′ ≠ 0`) and tolerances 1e-1 … 1e-4,
//! each claim is decided by [`lncert::kurbo_bridge`] (`d_H ≤ tol` with
//! certified bounds, the input converted exactly):
//!
//! * `offset_cubic(c, d, tol)` with `d = ±1/4`: the output path against the
//!   exact offset `c + d N` (the side is checked at run time: kurbo's first
//!   output point must be the exact offset's first point);
//! * `CubicBez::to_quads(tol)`: the quadratics against the cubic;
//! * `flatten(c, tol)`: the polyline against the cubic.
//!
//! A claim counts as **violated only when proven** (a certified lower bound
//! above the tolerance); undecided cases (budget) are counted apart. The first
//! violation of each claim is shrunk by proptest to a minimal case, printed
//! with its certified lower bound.

use kurbo::{BezPath, CubicBez, ParamCurve, Shape};
use lncert::kurbo_bridge::{
    certify_within, offset_within, shape_from_cubic, shape_from_path, Verdict,
};
use proptest::strategy::{Strategy, ValueTree};
use proptest::test_runner::{Config, TestRunner};

const TOLS: [f64; 4] = [1e-1, 1e-2, 1e-3, 1e-4];

#[derive(Clone, Copy, Debug)]
struct Case {
    c: CubicBez,
    /// offset distance (used by the offset claim only)
    d: f64,
}

fn cases() -> impl Strategy<Value = Case> {
    let coord = -16i32..=16;
    (proptest::array::uniform8(coord), proptest::bool::ANY).prop_map(|(v, left)| {
        let p = |i: usize| (v[2 * i] as f64 / 8.0, v[2 * i + 1] as f64 / 8.0);
        Case {
            c: CubicBez::new(p(0), p(1), p(2), p(3)),
            d: if left { 0.25 } else { -0.25 },
        }
    })
}

/// One claim: builds kurbo's output for a case and decides it with lncert.
/// `None`: lncert rejects the input (a cubic that is not regular).
type Claim = fn(&Case, f64) -> Option<Verdict>;

fn offset_claim(k: &Case, tol: f64) -> Option<Verdict> {
    let mut path = BezPath::new();
    kurbo::offset::offset_cubic(k.c, k.d, tol, &mut path);
    regular(k)?;
    // the side: kurbo's first point must be p0 + d N for lncert's N (left of
    // travel, y-up); checked, not assumed
    let first = path.elements().first().and_then(|e| e.end_point())?;
    let tangent = kurbo::ParamCurveDeriv::deriv(&k.c).eval(0.0).to_vec2();
    let n = kurbo::Vec2::new(-tangent.y, tangent.x).normalize();
    let (left, right) = (k.c.p0 + k.d * n, k.c.p0 - k.d * n);
    assert!(
        first.distance(left) <= first.distance(right),
        "kurbo offset the other side: {k:?}"
    );
    offset_within(k.c, k.d, &path, tol).ok()
}

fn quads_claim(k: &Case, tol: f64) -> Option<Verdict> {
    let mut path = BezPath::new();
    for (i, (_, _, q)) in k.c.to_quads(tol).enumerate() {
        if i == 0 {
            path.move_to(q.p0);
        } else if path.elements().last().and_then(|e| e.end_point()) != Some(q.p0) {
            path.move_to(q.p0);
        }
        path.quad_to(q.p1, q.p2);
    }
    regular(k)?;
    certify_within(
        &shape_from_cubic(k.c).ok()?,
        &shape_from_path(&path).ok()?,
        tol,
    )
    .ok()
}

fn flatten_claim(k: &Case, tol: f64) -> Option<Verdict> {
    let mut path = BezPath::new();
    kurbo::flatten(k.c.path_elements(0.1), tol, |el| path.push(el));
    regular(k)?;
    certify_within(
        &shape_from_cubic(k.c).ok()?,
        &shape_from_path(&path).ok()?,
        tol,
    )
    .ok()
}

/// The same input set for every claim: regular cubics (the exact offset of
/// the others is not a curve lncert accepts).
fn regular(k: &Case) -> Option<()> {
    lncert::kurbo_bridge::exact_offset(k.c, 0.25)
        .ok()
        .map(|_| ())
}

fn main() {
    let n: usize = std::env::args()
        .nth(1)
        .and_then(|s| s.parse().ok())
        .unwrap_or(48);
    let claims: [(&str, Claim); 3] = [
        ("offset_cubic(c, ±1/4, tol)", offset_claim),
        ("CubicBez::to_quads(tol)", quads_claim),
        ("flatten(c, tol)", flatten_claim),
    ];
    println!(
        "# kurbo 0.13 audited by lncert ({n} random regular cubics per claim and tolerance)\n"
    );
    println!(
        "| claim | tol | within (proven) | exceeds (proven) | undecided | worst proven excess |"
    );
    println!("|---|---|---|---|---|---|");
    let mut minimal = Vec::new();
    for (name, claim) in claims {
        for tol in TOLS {
            let mut runner = TestRunner::new(Config {
                rng_seed: proptest::test_runner::RngSeed::Fixed(0x6c6e_6365_7274),
                ..Config::default()
            });
            let (mut within, mut exceeds, mut undecided, mut worst) = (0, 0, 0, 0.0f64);
            let mut first_failure = None;
            let mut seen = 0;
            while seen < n {
                let tree = cases().new_tree(&mut runner).expect("a case");
                let case = tree.current();
                let Some(v) = claim(&case, tol) else { continue };
                seen += 1;
                match v {
                    Verdict::Within { .. } => within += 1,
                    Verdict::Exceeds { lo } => {
                        exceeds += 1;
                        worst = worst.max(lo / tol);
                        if first_failure.is_none() {
                            first_failure = Some(tree);
                        }
                    }
                    Verdict::Undecided { .. } => undecided += 1,
                }
            }
            let excess = if exceeds > 0 {
                format!("{worst:.3}× tol")
            } else {
                "—".to_string()
            };
            println!("| `{name}` | {tol:e} | {within} | {exceeds} | {undecided} | {excess} |");
            if let Some(mut tree) = first_failure {
                // shrink: keep the simplest case whose violation is still proven
                let fails = |c: &Case| matches!(claim(c, tol), Some(Verdict::Exceeds { .. }));
                let mut last = tree.current();
                loop {
                    if fails(&tree.current()) {
                        last = tree.current();
                        if !tree.simplify() {
                            break;
                        }
                    } else if !tree.complicate() {
                        break;
                    }
                }
                let lo = match claim(&last, tol) {
                    Some(Verdict::Exceeds { lo }) => lo,
                    _ => f64::NAN,
                };
                minimal.push(format!(
                    "- `{name}` at tol {tol:e}: cubic ({}, {}) ({}, {}) ({}, {}) ({}, {}){}: d_H ≥ {lo:.4e} (proven)",
                    last.c.p0.x, last.c.p0.y, last.c.p1.x, last.c.p1.y, last.c.p2.x, last.c.p2.y,
                    last.c.p3.x, last.c.p3.y,
                    if name.starts_with("offset") { format!(", d = {}", last.d) } else { String::new() },
                ));
            }
        }
    }
    if !minimal.is_empty() {
        println!("\nMinimal proven violations (shrunk by proptest):\n");
        for m in minimal {
            println!("{m}");
        }
    }
}
