//! Audit another library's tolerance claims: kurbo 0.13's own accuracy
//! parameters, property-tested with lncert's certified verdicts.
//!
//! Run: `cargo run --release --features kurbo,proptest --example audit_kurbo [-- CASES]`
//! (default 48 cases per claim and tolerance).
//!
//! For tolerances 1e-1 … 1e-4, each claim is decided by [`lncert::kurbo_bridge`]
//! (`d_H ≤ tol` with certified bounds, the input converted exactly). On random
//! cubics (control points on a 1/8 grid in [-2, 2]², regular ones only, since an
//! exact offset needs `c′ ≠ 0`):
//!
//! * `offset_cubic(c, d, tol)` with `d = ±1/4`: the output path against the
//!   exact offset `c + d N` (the side is checked at run time: kurbo's first
//!   output point must be the exact offset's first point);
//! * `CubicBez::to_quads(tol)`: the quadratics against the cubic;
//! * `flatten(c, tol)`: the polyline against the cubic;
//! * `fit_to_bezpath(source, tol)` and `fit_to_bezpath_opt(source, tol)` with
//!   `source` the exact offset `c + d N`, `d = ±1/4`, sampled in f64 by this
//!   harness ([`OffsetSource`]: kurbo 0.13's own `CubicOffset` is private and no
//!   longer a `ParamCurveFit`): the fitted path against the exact offset. kurbo
//!   documents the accuracy as a Fréchet distance, which is ≥ the Hausdorff
//!   distance, so a proven Hausdorff excess refutes it too.
//!
//! On random circular arcs (centre on a 1/2 grid in [-2, 2]², radius k/4 for
//! k = 1 … 16, start angle a random float in [-π, π), sweep a random float in
//! [0.1, 6) of either sign, `x_rotation` 0):
//!
//! * `Arc::path_elements(tol)` (`append_iter` after a `MoveTo`): the cubics
//!   against kurbo's exact arc, known through an exact lncert arc within a proven
//!   `eps` of it ([`lncert::kurbo_bridge::arc_enclosure`]); a violation counts only
//!   when the certified lower bound minus `eps` exceeds the tolerance.
//!
//! On random circles (centre on a 1/2 grid in [-2, 2]², radius k/4, k = 1 … 16):
//!
//! * `Circle::path_elements(tol)`: the closed path against the whole circle, the
//!   union of its four exact quarter arcs (distances to the union: the path is
//!   not split, so nothing depends on where kurbo's segments end).
//!
//! A claim counts as **violated only when proven** (a certified lower bound
//! above the tolerance); undecided cases (budget) are counted apart. The first
//! violation of each claim is shrunk by proptest to a minimal case, printed
//! with its certified lower bound.

use kurbo::{
    Arc, BezPath, Circle, CubicBez, CurveFitSample, ParamCurve, ParamCurveDeriv, ParamCurveFit,
    Point, Shape, Vec2,
};
use lncert::kurbo_bridge::{
    arc_within, certify_within, circle_within, offset_within, shape_from_cubic, shape_from_path,
    Verdict,
};
use proptest::strategy::{Strategy, ValueTree};
use proptest::test_runner::{Config, TestRunner};
use std::f64::consts::PI;
use std::fmt::Debug;
use std::ops::Range;

const TOLS: [f64; 4] = [1e-1, 1e-2, 1e-3, 1e-4];

#[derive(Clone, Copy, Debug)]
struct Case {
    c: CubicBez,
    /// offset distance (used by the offset claims only)
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

fn arc_cases() -> impl Strategy<Value = Arc> {
    (
        -4i32..=4,
        -4i32..=4,
        1i32..=16,
        -PI..PI,
        0.1f64..6.0,
        proptest::bool::ANY,
    )
        .prop_map(|(x, y, k, start, sweep, cw)| {
            let r = k as f64 / 4.0;
            Arc::new(
                (x as f64 / 2.0, y as f64 / 2.0),
                (r, r),
                start,
                if cw { -sweep } else { sweep },
                0.0,
            )
        })
}

fn circle_cases() -> impl Strategy<Value = Circle> {
    (-4i32..=4, -4i32..=4, 1i32..=16)
        .prop_map(|(x, y, k)| Circle::new((x as f64 / 2.0, y as f64 / 2.0), k as f64 / 4.0))
}

/// One claim: builds kurbo's output for a case and decides it with lncert.
/// `None`: lncert rejects the input (a cubic that is not regular).
type Claim<T> = fn(&T, f64) -> Option<Verdict>;

/// How a case is printed.
type Text<T> = fn(&T) -> String;

fn offset_claim(k: &Case, tol: f64) -> Option<Verdict> {
    let mut path = BezPath::new();
    kurbo::offset::offset_cubic(k.c, k.d, tol, &mut path);
    regular(k)?;
    // the side: kurbo's first point must be p0 + d N for lncert's N (left of
    // travel, y-up); checked, not assumed
    let first = path.elements().first().and_then(|e| e.end_point())?;
    let tangent = k.c.deriv().eval(0.0).to_vec2();
    let n = Vec2::new(-tangent.y, tangent.x).normalize();
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
        if i == 0 || path.elements().last().and_then(|e| e.end_point()) != Some(q.p0) {
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

/// The exact offset `c + d N` of a regular cubic (`N` the left unit normal,
/// y-up: lncert's side) as a source for kurbo's curve fitting, evaluated in f64.
///
/// With `κ = (c′ × c″)/|c′|³`, `N′ = −κ c′`, so the offset's derivative is
/// `(1 − d κ) c′`: it vanishes (a cusp of the offset) where
/// `g = |c′|³ − d (c′ × c″)` changes sign.
struct OffsetSource {
    c: CubicBez,
    d: f64,
}

impl OffsetSource {
    /// The point, `c′`, and `g` (the sign of `1 − d κ`) at `t`.
    fn parts(&self, t: f64) -> (Point, Vec2, f64) {
        let d1 = self.c.deriv().eval(t).to_vec2();
        let d2 = self.c.deriv().deriv().eval(t).to_vec2();
        let len = d1.hypot();
        let n = Vec2::new(-d1.y, d1.x) / len;
        let g = len * len * len - self.d * d1.cross(d2);
        (self.c.eval(t) + self.d * n, d1, g)
    }
}

impl ParamCurveFit for OffsetSource {
    fn sample_pt_deriv(&self, t: f64) -> (Point, Vec2) {
        let (p, d1, g) = self.parts(t);
        let len = d1.hypot();
        (p, d1 * (g / (len * len * len)))
    }

    fn sample_pt_tangent(&self, t: f64, sign: f64) -> CurveFitSample {
        let (p, d1, g) = self.parts(t);
        // at a cusp, the tangent of the side `sign` points to
        let g = if g.abs() > 1e-12 * d1.hypot().powi(3) {
            g
        } else {
            self.parts((t + sign * 1e-7).clamp(0.0, 1.0)).2
        };
        CurveFitSample {
            p,
            tangent: if g < 0.0 { -d1 } else { d1 },
        }
    }

    fn break_cusp(&self, range: Range<f64>) -> Option<f64> {
        // a sign change of g on a 32-step grid, bisected; cusps at the ends of
        // the range are not reported (the trait's contract)
        const STEPS: usize = 32;
        let at = |i: usize| range.start + (range.end - range.start) * i as f64 / STEPS as f64;
        let (mut a, mut b) = (0..STEPS).map(|i| (at(i), at(i + 1))).find(|&(a, b)| {
            let (ga, gb) = (self.parts(a).2, self.parts(b).2);
            ga != 0.0 && gb != 0.0 && (ga < 0.0) != (gb < 0.0)
        })?;
        let ga = self.parts(a).2;
        for _ in 0..60 {
            let m = 0.5 * (a + b);
            if (self.parts(m).2 < 0.0) == (ga < 0.0) {
                a = m;
            } else {
                b = m;
            }
        }
        let t = 0.5 * (a + b);
        let margin = 1e-9 * (range.end - range.start);
        (t > range.start + margin && t < range.end - margin).then_some(t)
    }
}

fn fit_claim(k: &Case, tol: f64) -> Option<Verdict> {
    regular(k)?;
    let path = kurbo::fit_to_bezpath(&OffsetSource { c: k.c, d: k.d }, tol);
    offset_within(k.c, k.d, &path, tol).ok()
}

fn fit_opt_claim(k: &Case, tol: f64) -> Option<Verdict> {
    regular(k)?;
    let path = kurbo::fit_to_bezpath_opt(&OffsetSource { c: k.c, d: k.d }, tol);
    offset_within(k.c, k.d, &path, tol).ok()
}

fn arc_claim(a: &Arc, tol: f64) -> Option<Verdict> {
    let path = BezPath::from_vec(a.path_elements(tol).collect());
    arc_within(a, &path, tol).ok()
}

fn circle_claim(c: &Circle, tol: f64) -> Option<Verdict> {
    circle_within(*c, &c.to_path(tol), tol).ok()
}

/// The same input set for every cubic claim: regular cubics (the exact offset
/// of the others is not a curve lncert accepts).
fn regular(k: &Case) -> Option<()> {
    lncert::kurbo_bridge::exact_offset(k.c, 0.25)
        .ok()
        .map(|_| ())
}

fn cubic_text(k: &Case) -> String {
    let c = k.c;
    format!(
        "cubic ({}, {}) ({}, {}) ({}, {}) ({}, {})",
        c.p0.x, c.p0.y, c.p1.x, c.p1.y, c.p2.x, c.p2.y, c.p3.x, c.p3.y
    )
}

fn offset_text(k: &Case) -> String {
    format!("{}, d = {}", cubic_text(k), k.d)
}

fn arc_text(a: &Arc) -> String {
    format!(
        "arc centre ({}, {}), radius {}, start_angle {:?}, sweep_angle {:?}",
        a.center.x, a.center.y, a.radii.x, a.start_angle, a.sweep_angle
    )
}

fn circle_text(c: &Circle) -> String {
    format!(
        "circle centre ({}, {}), radius {}",
        c.center.x, c.center.y, c.radius
    )
}

/// Runs one claim at every tolerance: prints its rows, and its shrunk first
/// violation into `minimal`.
fn audit<T: Clone + Debug, S: Strategy<Value = T>>(
    name: &str,
    n: usize,
    strategy: &S,
    claim: Claim<T>,
    text: Text<T>,
    minimal: &mut Vec<String>,
) {
    for tol in TOLS {
        let mut runner = TestRunner::new(Config {
            rng_seed: proptest::test_runner::RngSeed::Fixed(0x6c6e_6365_7274),
            ..Config::default()
        });
        let (mut within, mut exceeds, mut undecided, mut worst) = (0, 0, 0, 0.0f64);
        let mut first_failure = None;
        let mut seen = 0;
        while seen < n {
            let tree = strategy.new_tree(&mut runner).expect("a case");
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
            let fails = |c: &T| matches!(claim(c, tol), Some(Verdict::Exceeds { .. }));
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
                "- `{name}` at tol {tol:e}: {}: d_H ≥ {lo:.4e} (proven)",
                text(&last)
            ));
        }
    }
}

fn main() {
    let n: usize = std::env::args()
        .nth(1)
        .and_then(|s| s.parse().ok())
        .unwrap_or(48);
    println!(
        "# kurbo 0.13 audited by lncert ({n} random cases per claim and tolerance: regular cubics, circular arcs, circles)\n"
    );
    println!(
        "| claim | tol | within (proven) | exceeds (proven) | undecided | worst proven excess |"
    );
    println!("|---|---|---|---|---|---|");
    let mut minimal = Vec::new();
    let cubic_claims: [(&str, Claim<Case>, Text<Case>); 5] = [
        ("offset_cubic(c, ±1/4, tol)", offset_claim, offset_text),
        ("CubicBez::to_quads(tol)", quads_claim, cubic_text),
        ("flatten(c, tol)", flatten_claim, cubic_text),
        ("fit_to_bezpath(offset ±1/4, tol)", fit_claim, offset_text),
        (
            "fit_to_bezpath_opt(offset ±1/4, tol)",
            fit_opt_claim,
            offset_text,
        ),
    ];
    for (name, claim, text) in cubic_claims {
        audit(name, n, &cases(), claim, text, &mut minimal);
    }
    audit(
        "Arc::path_elements(tol)",
        n,
        &arc_cases(),
        arc_claim,
        arc_text,
        &mut minimal,
    );
    audit(
        "Circle::path_elements(tol)",
        n,
        &circle_cases(),
        circle_claim,
        circle_text,
        &mut minimal,
    );
    if !minimal.is_empty() {
        println!("\nMinimal proven violations (shrunk by proptest):\n");
        for m in minimal {
            println!("{m}");
        }
    }
}
