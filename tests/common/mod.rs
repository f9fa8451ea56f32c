//! Shared generators for the property tests: small exact rationals, LN frames,
//! compatible pairs and Hermite data, with planted boundary cases.
#![allow(dead_code)]

use lncert::curve::{Bezier, V2};
use lncert::ln::cubic::LnFrame;
use lncert::poly::{isolate_roots, refine_root, Poly, Span};
use lncert::scalar::{frac, interval_from_rational, parse_rational, Interval, Rational};
use proptest::prelude::*;

/// Cases per property: `LNCERT_PROPTEST_CASES` (default 2000, the CI setting).
pub fn cases() -> u32 {
    std::env::var("LNCERT_PROPTEST_CASES")
        .ok()
        .and_then(|v| v.parse().ok())
        .unwrap_or(2000)
}

pub fn config() -> ProptestConfig {
    ProptestConfig {
        cases: cases(),
        failure_persistence: None,
        ..ProptestConfig::default()
    }
}

/// The tolerance equal to the float `x` (`value() == x`); panics when `x` is
/// not a positive normal float.
pub fn tol(x: f64) -> lncert::Tolerance {
    lncert::Tolerance::from_f64(x).expect("a positive tolerance")
}

pub fn q(p: i64, d: i64) -> Rational {
    frac(p, d)
}

/// The exact rational written `s` (`"1/3"`, `"-2.5"`, ...); panics on bad text.
pub fn qs(s: &str) -> Rational {
    parse_rational(s).unwrap()
}

/// A rational `n/d` with `|n| <= 40`, `1 <= d <= 12`.
pub fn rat() -> impl Strategy<Value = Rational> {
    (-40i64..=40, 1i64..=12).prop_map(|(n, d)| q(n, d))
}

/// A nonzero rational.
pub fn rat_nonzero() -> impl Strategy<Value = Rational> {
    rat().prop_filter("nonzero", |r| *r != q(0, 1))
}

/// A positive rational in (0, 10].
pub fn rat_pos() -> impl Strategy<Value = Rational> {
    (1i64..=60, 1i64..=8).prop_map(|(n, d)| q(n, d))
}

pub fn point() -> impl Strategy<Value = V2<Rational>> {
    (rat(), rat()).prop_map(|(x, y)| V2::new(x, y))
}

/// A non-collinear frame `b0, bm, b3`.
pub fn frame() -> impl Strategy<Value = LnFrame<Rational>> {
    (point(), point(), point()).prop_filter_map("collinear", |(a, b, c)| LnFrame::new(a, b, c).ok())
}

/// τ: random rationals, the boundary values 0 and 1, and values near them.
pub fn tau() -> impl Strategy<Value = Rational> {
    prop_oneof![
        3 => rat(),
        1 => prop::sample::select(vec![q(0, 1), q(1, 1), q(-1, 1), q(1, 2), q(1, 6), q(5, 6), q(-1, 1000), q(1001, 1000), q(1, 1000), q(999, 1000)]),
    ]
}

/// ρ = κ/λ: random positive and negative rationals and the boundaries 1/2, 2.
pub fn rho() -> impl Strategy<Value = Rational> {
    prop_oneof![
        3 => rat_nonzero(),
        1 => prop::sample::select(vec![q(1, 2), q(2, 1), q(1, 1), q(501, 1000), q(1999, 1000), q(499, 1000), q(2001, 1000)]),
    ]
}

/// A frame compatible with `left`: `∇b0ʳ = c0 ∇b0ˡ`, `∇b1ʳ = c1 ∇b1ˡ`, `c0 c1 > 0`.
pub fn compatible_right(
    left: &LnFrame<Rational>,
    b0: V2<Rational>,
    c0: Rational,
    c1: Rational,
) -> LnFrame<Rational> {
    let bm = b0.add(&left.d0().scale(&c0));
    let b3 = bm.add(&left.d1().scale(&c1));
    LnFrame::new(b0, bm, b3).expect("scaled frame stays non-collinear")
}

/// End ratios c0, c1 of one sign; q = c1/c0 includes the boundaries 1/4 and 4.
pub fn end_ratios() -> impl Strategy<Value = (Rational, Rational)> {
    let pos = (1i64..=30, 1i64..=6).prop_map(|(n, d)| q(n, d));
    prop_oneof![
        3 => (pos.clone(), pos.clone(), any::<bool>()).prop_map(|(a, b, neg)| if neg { (-a, -b) } else { (a, b) }),
        1 => (pos, prop::sample::select(vec![q(1, 4), q(4, 1), q(1, 1), q(1, 5), q(5, 1)]), any::<bool>())
            .prop_map(|(a, k, neg)| { let b = &a * &k; if neg { (-a, -b) } else { (a, b) } }),
    ]
}

/// End ratios c0, c1 of one sign with 1/4 < c1/c0 < 4 (Prop 4.2 holds).
pub fn end_ratios_admissible() -> impl Strategy<Value = (Rational, Rational)> {
    ((1i64..=30, 1i64..=6), (1i64..=15, 1i64..=15), any::<bool>()).prop_filter_map(
        "q in (1/4, 4)",
        |((a, b), (kn, kd), neg)| {
            let k = q(kn, kd);
            if k <= q(1, 4) || k >= q(4, 1) {
                return None;
            }
            let c0 = q(a, b);
            let c1 = &c0 * &k;
            Some(if neg { (-c0, -c1) } else { (c0, c1) })
        },
    )
}

/// Encloses `dist(p, B)²` for a rational point `p` and a polynomial Bézier `B`:
/// the minimum of `|p − B(t)|²` over the end points and the real roots in `(0, 1)`
/// of `(B(t) − p)·B′(t)`, isolated exactly by Sturm sequences and refined.
pub fn exact_dist2(p: &V2<Rational>, b: &Bezier<Rational>) -> Interval {
    let (x, y) = b.power_coords();
    let fx = x.sub(&Poly::new(vec![p.x.clone()]));
    let fy = y.sub(&Poly::new(vec![p.y.clone()]));
    let foot = fx.mul(&x.derivative()).add(&fy.mul(&y.derivative()));
    let d2 = fx.mul(&fx).add(&fy.mul(&fy));
    let d2i = d2.map(interval_from_rational);
    let mut best = interval_from_rational(&d2.eval(&frac::<Rational>(0, 1)))
        .min(interval_from_rational(&d2.eval(&frac::<Rational>(1, 1))));
    let zero_poly = foot.coeffs().iter().all(|c| *c == Rational::default());
    if !zero_poly {
        for r in isolate_roots(&foot, &Span::unit_open()) {
            let r = refine_root(&foot, &r, &parse_rational("1e-12").unwrap());
            let t = interval_from_rational(&r.lo).convex_hull(interval_from_rational(&r.hi));
            best = best.min(d2i.eval(&t));
        }
    }
    best
}

/// Symbolic helpers of the identity tests: the `i`-th variable, a constant, a
/// quotient, and an identity assertion.
pub mod symbolic {
    use lncert::poly::{identity_holds, RatFunc};
    use lncert::scalar::{frac, Scalar};

    pub fn v(i: usize) -> RatFunc {
        RatFunc::var(i)
    }
    pub fn k(p: i64, q: i64) -> RatFunc {
        frac(p, q)
    }
    pub fn div(a: RatFunc, b: RatFunc) -> RatFunc {
        a.div(&b).expect("nonzero denominator")
    }
    pub fn assert_id(lhs: &RatFunc, rhs: &RatFunc, what: &str) {
        assert!(
            identity_holds(lhs, rhs),
            "identity fails: {what}\n  lhs = {lhs}\n  rhs = {rhs}"
        );
    }
}

/// Seed 003's Fig. 4 tangency problem on the command line, up to `--radius`
/// (whose value the caller appends): two tangent quartics, complete.
pub const FIG4: [&str; 10] = [
    "tangency",
    "--x1",
    "3",
    "--y1",
    "-1",
    "--u",
    "1",
    "--center",
    "15/16,-319/128",
    "--radius",
];

/// Writes `text` to `name` in a temporary directory of this test binary and
/// process, and returns the path.
pub fn tmp(name: &str, text: &str) -> std::path::PathBuf {
    let dir = std::env::temp_dir().join(format!(
        "lncert-{}-{}",
        env!("CARGO_CRATE_NAME"),
        std::process::id()
    ));
    std::fs::create_dir_all(&dir).unwrap();
    let p = dir.join(name);
    std::fs::write(&p, text).unwrap();
    p
}

/// A system font for the glyph tests: CI installs DejaVu (fonts-dejavu-core)
/// and sets `LNCERT_REQUIRE_FONT=1`; elsewhere the tests skip without it.
pub fn dejavu() -> Option<std::path::PathBuf> {
    let p = std::path::PathBuf::from("/usr/share/fonts/truetype/dejavu/DejaVuSans.ttf");
    if p.exists() {
        return Some(p);
    }
    assert!(
        std::env::var("LNCERT_REQUIRE_FONT").is_err(),
        "LNCERT_REQUIRE_FONT is set but {} is missing",
        p.display()
    );
    eprintln!("skipped: no DejaVu font at {}", p.display());
    None
}

/// The largest distance between consecutive samples (a sampled one-sided
/// distance exceeds the true one by at most half of the target's).
pub fn max_spacing(v: &[V2<f64>]) -> f64 {
    v.windows(2)
        .map(|w| w[1].sub(&w[0]).norm2().sqrt())
        .fold(0.0, f64::max)
}

/// The sampled one-sided distance `max_{p ∈ from} min_{q ∈ to} |p − q|`.
pub fn sampled_one_sided(from: &[V2<f64>], to: &[V2<f64>]) -> f64 {
    from.iter()
        .map(|p| {
            to.iter()
                .map(|q| p.sub(q).norm2().sqrt())
                .fold(f64::INFINITY, f64::min)
        })
        .fold(0.0, f64::max)
}
