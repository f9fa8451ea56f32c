//! Input generators shared by the property tests, the fuzz targets and
//! `lncert audit` — and exported so that *your* CI can check *your* float
//! geometry against lncert.
//!
//! Every case is built from raw bytes through [`arbitrary::Unstructured`]
//! (feature `arbitrary`), so a fuzzer, a property test (feature `proptest`:
//! `strategy`) and a seeded audit ([`cases_from_seed`]) all draw from the same
//! distribution. All inputs are **finite `f64` values**: the exact path reads
//! them exactly ([`crate::scalar::rational_from_f64`]), so the f64 path and the
//! exact path see identical data and every difference is computation, not input.
//!
//! The distribution is adversarial on purpose: small dyadic numbers, decimals
//! scaled from 1e-8 to 1e8, values a few ulps from a boundary, and *planted
//! degeneracies* — cusp parameters `τ` near 0 and 1, ratios `λr/λl` near 1/4
//! and 4, nearly collinear control points, `u` near every case boundary of seed
//! 003 Props 2.1–3.2, `κ` near the case boundaries of seed 000 Prop 6.1.
//!
//! # Check your float geometry against lncert in your CI
//!
//! With the `proptest` feature, `strategy` turns any case type into a proptest
//! strategy. Compare your own float code with lncert's exact answer:
//!
//! ```
//! # #[cfg(feature = "proptest")] {
//! use lncert::gen::{strategy, PairCase};
//! use lncert::ln::pair::pair_decision;
//! use lncert::scalar::{rational_from_f64, Rational};
//! use proptest::prelude::*;
//!
//! /// Your float code: does the pair admit one linear normal map (seed 000 Prop 4.2)?
//! fn my_pair_test(c0: f64, c1: f64) -> bool { let q = c1 / c0; 0.25 < q && q < 4.0 }
//!
//! proptest!(|(c in strategy::<PairCase>())| {
//!     let ex = |x: f64| rational_from_f64(x).unwrap();
//!     let exact = pair_decision::<Rational>(&ex(c.c0), &ex(c.c1), &ex(c.rho)).unwrap().0;
//!     // Allow disagreement only within a band around the boundaries 1/4 and 4.
//!     let q = c.c1 / c.c0;
//!     if (q - 4.0).abs() > 1e-9 * 4.0 && (q - 0.25).abs() > 1e-9 * 0.25 {
//!         prop_assert_eq!(my_pair_test(c.c0, c.c1), exact);
//!     }
//! });
//! # }
//! ```
//!
//! # Examples
//! ```
//! use lncert::gen::{cases_from_seed, PairCase};
//! let cases: Vec<PairCase> = cases_from_seed(7, 100);
//! assert_eq!(cases.len(), 100);
//! assert!(cases.iter().all(|c| c.c0.is_finite() && c.c1.is_finite() && c.rho.is_finite()));
//! ```

use arbitrary::{Arbitrary, Result, Unstructured};

pub mod hostile;

/// A finite float from one of several stress distributions.
pub fn coord(u: &mut Unstructured) -> Result<f64> {
    let x = match u.int_in_range(0u8..=4)? {
        // Small dyadic rationals: exact everywhere.
        0 => f64::from(u.int_in_range(-64i16..=64)?) / f64::from(1u16 << u.int_in_range(0u8..=6)?),
        // Decimals scaled from 1e-8 to 1e8.
        1 => {
            f64::from(u.int_in_range(-999_999i32..=999_999)?)
                * 1e-6
                * 10f64.powi(u.int_in_range(-8i32..=8)?)
        }
        // Small integers.
        2 => f64::from(u.int_in_range(-20i8..=20)?),
        // Raw bits, kept if finite and of moderate size.
        3 => {
            let b = f64::from_bits(u64::arbitrary(u)?);
            if b.is_finite() && (b == 0.0 || (1e-8..=1e8).contains(&b.abs())) {
                b
            } else {
                f64::from(u.int_in_range(-9i8..=9)?)
            }
        }
        // Values in [-1, 1] with full mantissas.
        _ => f64::from(u32::arbitrary(u)?) / f64::from(u32::MAX) * 2.0 - 1.0,
    };
    Ok(x)
}

/// `base` moved by a few ulps or by a tiny relative amount (10⁻¹ … 10⁻¹⁵), or
/// left exactly on it: for planting near-degenerate inputs.
pub fn near(u: &mut Unstructured, base: f64) -> Result<f64> {
    let x = match u.int_in_range(0u8..=3)? {
        0 => base,
        1 => {
            let mut x = base;
            let k = u.int_in_range(-4i8..=4)?;
            for _ in 0..k.unsigned_abs() {
                x = if k > 0 { x.next_up() } else { x.next_down() };
            }
            x
        }
        _ => {
            let e = 10f64.powi(-i32::from(u.int_in_range(1u8..=15)?));
            let sign = if bool::arbitrary(u)? { 1.0 } else { -1.0 };
            base * (1.0 + sign * e) + sign * e * if base == 0.0 { 1.0 } else { 0.0 }
        }
    };
    Ok(if x.is_finite() { x } else { base })
}

/// One of `options`, then [`near`] it.
fn near_one_of(u: &mut Unstructured, options: &[f64], scale: f64) -> Result<f64> {
    let base = *u.choose(options)? * scale;
    near(u, base)
}

fn point(u: &mut Unstructured) -> Result<[f64; 2]> {
    Ok([coord(u)?, coord(u)?])
}

/// Three points `b0, bm, b3` of a seed-000 LN frame; sometimes nearly or exactly collinear.
#[derive(Clone, Debug, PartialEq)]
pub struct FrameCase {
    /// Start point `b0`.
    pub b0: [f64; 2],
    /// `bm`, where the end tangents meet.
    pub bm: [f64; 2],
    /// End point `b3`.
    pub b3: [f64; 2],
}

impl<'a> Arbitrary<'a> for FrameCase {
    fn arbitrary(u: &mut Unstructured<'a>) -> Result<Self> {
        let b0 = point(u)?;
        let bm = point(u)?;
        let b3 = if u.ratio(1u8, 4)? {
            // Nearly collinear: b3 = bm + t (bm - b0) + ε R(bm - b0).
            let (dx, dy) = (bm[0] - b0[0], bm[1] - b0[1]);
            let t = coord(u)?.abs() + 0.5;
            let e = near(u, 0.0)?;
            [bm[0] + t * dx - e * dy, bm[1] + t * dy + e * dx]
        } else {
            point(u)?
        };
        Ok(FrameCase { b0, bm, b3 })
    }
}

/// A frame and a cusp parameter `τ` (seed 000 eq. (1), Prop 3.1), planted near 0, 1, 1/3, 2/3.
#[derive(Clone, Debug, PartialEq)]
pub struct TauCase {
    /// The LN frame `b0, bm, b3`.
    pub frame: FrameCase,
    /// The cusp parameter `τ` that gives `δ0, δ1` by eq. (1).
    pub tau: f64,
}

impl<'a> Arbitrary<'a> for TauCase {
    fn arbitrary(u: &mut Unstructured<'a>) -> Result<Self> {
        let frame = FrameCase::arbitrary(u)?;
        let tau = match u.int_in_range(0u8..=2)? {
            0 => coord(u)?,
            _ => near_one_of(u, &[0.0, 1.0, 1.0 / 3.0, 2.0 / 3.0, -1.0, 0.5], 1.0)?,
        };
        Ok(TauCase { frame, tau })
    }
}

/// A compatible pair given by its end ratios (`∇b0ʳ = c0 ∇b0ˡ`, `∇b1ʳ = c1 ∇b1ˡ`)
/// and `ρl = κ/λl` (seed 000 Props 4.2, 4.4): `q = c1/c0` planted near 1/4 and 4,
/// `ρl` near the ends of the admissible interval and near the values that put a
/// δ of the convolution on 0 or 1.
#[derive(Clone, Debug, PartialEq)]
pub struct PairCase {
    /// Start ratio `c0`: `∇b0ʳ = c0 ∇b0ˡ` (nonzero).
    pub c0: f64,
    /// End ratio `c1`: `∇b1ʳ = c1 ∇b1ˡ` (same sign as `c0`).
    pub c1: f64,
    /// `ρl = κ/λl`, the choice of κ for the left curve.
    pub rho: f64,
}

impl<'a> Arbitrary<'a> for PairCase {
    fn arbitrary(u: &mut Unstructured<'a>) -> Result<Self> {
        let sign = if bool::arbitrary(u)? { 1.0 } else { -1.0 };
        let c0 = sign * (coord(u)?.abs() + 1.0 / 64.0);
        let q = match u.int_in_range(0u8..=2)? {
            0 => coord(u)?.abs() + 1.0 / 64.0,
            _ => near_one_of(u, &[0.25, 4.0, 1.0], 1.0)?.abs(),
        };
        let c1 = c0 * q;
        let rho = match u.int_in_range(0u8..=3)? {
            0 => coord(u)?.abs() + 1.0 / 64.0,
            1 => near_one_of(u, &[0.5, 2.0, q / 2.0, 2.0 * q], 1.0)?,
            2 => {
                // δ0 of the sum is 0 when δ0ˡ + c0 δ0ʳ = 0; solve for ρ on a grid
                // and perturb: a boundary case of Prop 4.4.
                let r = 0.5 + f64::from(u.int_in_range(1u8..=99)?) / 100.0 * 1.5;
                near(u, r)?
            }
            _ => (0.5f64.max(q / 2.0) + 2.0f64.min(2.0 * q)) / 2.0,
        };
        Ok(PairCase { c0, c1, rho })
    }
}

/// Hermite data of seed 003 (`[x1, y1]`, `u`, quartic parameter `a2`, tangent
/// line slope `m` and intercept `b`), with `u` planted near `s·{3/2, 3, 3±√3,
/// 4/3, 2, 4}` and `a2` near `0` and `α2`.
#[derive(Clone, Debug, PartialEq)]
pub struct HermiteCase {
    /// First coordinate of the end point `[x1, y1]`.
    pub x1: f64,
    /// Second coordinate of the end point `[x1, y1]`.
    pub y1: f64,
    /// End of the parameter interval `[0, u]`, where the normal is `(u, 1)` (`> 0`).
    pub u: f64,
    /// The `t²` coefficient `a2` that picks a quartic interpolant (eq. (3)).
    pub a2: f64,
    /// Slope `m ∈ (0, u)` of the tangent line `m x + y + b = 0` (Prop 3.3).
    pub m: f64,
    /// Intercept `b` of the tangent line `m x + y + b = 0` (Prop 3.3).
    pub b: f64,
}

impl<'a> Arbitrary<'a> for HermiteCase {
    fn arbitrary(u: &mut Unstructured<'a>) -> Result<Self> {
        let x1 = coord(u)?;
        let y1 = coord(u)?;
        let s = if x1 != 0.0 { -y1 / x1 } else { 1.0 };
        let r3 = 3f64.sqrt();
        let uu = match u.int_in_range(0u8..=2)? {
            0 => coord(u)?.abs() + 1.0 / 64.0,
            _ => {
                near_one_of(
                    u,
                    &[1.5, 3.0, 3.0 - r3, 3.0 + r3, 4.0 / 3.0, 2.0, 4.0],
                    s.abs(),
                )?
                .abs()
                    + f64::MIN_POSITIVE
            }
        };
        let alpha2 = if uu != 0.0 {
            (6.0 * s - 3.0 * uu) * x1 / (uu * uu)
        } else {
            0.0
        };
        let a2 = match u.int_in_range(0u8..=2)? {
            0 => coord(u)?,
            1 => near(u, alpha2)?,
            _ => near(u, 0.0)?,
        };
        let m = uu * f64::from(u.int_in_range(1u8..=99)?) / 100.0;
        let b = coord(u)?;
        Ok(HermiteCase {
            x1,
            y1,
            u: uu,
            a2,
            m,
            b,
        })
    }
}

/// A circular arc of half-angle `α ∈ (0, π/2)` given as `(cos α, sin α)` and
/// `κ ∈ [1/2, 2]` (seed 000 Prop 6.1), `κ` planted near `1 ± sin α`, `1/(1 ± sin α)` and 1.
#[derive(Clone, Debug, PartialEq)]
pub struct ArcCase {
    /// `cos α` of the half-angle `α`.
    pub cos_a: f64,
    /// `sin α` of the half-angle `α`.
    pub sin_a: f64,
    /// The parameter `κ ∈ [1/2, 2]` of the LN approximation.
    pub kappa: f64,
}

impl<'a> Arbitrary<'a> for ArcCase {
    fn arbitrary(u: &mut Unstructured<'a>) -> Result<Self> {
        let alpha = (f64::from(u.int_in_range(1u16..=999)?) / 1000.0) * std::f64::consts::FRAC_PI_2;
        let (s, c) = alpha.sin_cos();
        let kappa = match u.int_in_range(0u8..=2)? {
            0 => 0.5 + f64::from(u.int_in_range(0u16..=1500)?) / 1000.0,
            _ => near_one_of(
                u,
                &[1.0 - s, 1.0 + s, 1.0 / (1.0 - s), 1.0 / (1.0 + s), 1.0],
                1.0,
            )?,
        };
        Ok(ArcCase {
            cos_a: c,
            sin_a: s,
            kappa: kappa.clamp(0.5, 2.0),
        })
    }
}

/// A planar Bézier curve of degree 1 to 9 as float control points, sometimes
/// with planted degeneracies: coincident consecutive points, all points on a
/// line, or points a few ulps apart.
///
/// # Examples
/// ```
/// use lncert::gen::{cases_from_seed, BezierCase};
/// let c: Vec<BezierCase> = cases_from_seed(3, 20);
/// assert!(c.iter().all(|b| (2..=10).contains(&b.points.len())));
/// let exact = c[0].exact().unwrap(); // the same curve with exact rational coordinates
/// assert_eq!(exact.points().len(), c[0].points.len());
/// ```
#[derive(Clone, Debug, PartialEq)]
pub struct BezierCase {
    /// The control points `[x, y]`, in order (2 to 10).
    pub points: Vec<[f64; 2]>,
}

impl<'a> Arbitrary<'a> for BezierCase {
    fn arbitrary(u: &mut Unstructured<'a>) -> Result<Self> {
        Self::arbitrary_up_to(u, 10)
    }
}

impl BezierCase {
    /// The distribution of [`Arbitrary::arbitrary`] (which is this with
    /// `max_points = 10`) but with 2 to `max_points` (at least 2) control
    /// points: the fuzz target `bezier` draws mostly low degrees, where exact
    /// root isolation costs well under a millisecond.
    pub fn arbitrary_up_to(u: &mut Unstructured, max_points: u8) -> Result<Self> {
        let n = usize::from(u.int_in_range(2u8..=max_points.max(2))?);
        let mut points = Vec::with_capacity(n);
        let kind = u.int_in_range(0u8..=5)?;
        let (o, d) = (point(u)?, point(u)?);
        for i in 0..n {
            let p = match kind {
                // All on one line.
                0 => {
                    let t = coord(u)?;
                    [o[0] + t * d[0], o[1] + t * d[1]]
                }
                // A repeated point.
                1 if i > 0 && bool::arbitrary(u)? => points[i - 1],
                // A few ulps from the previous point.
                2 if i > 0 => {
                    let q: [f64; 2] = points[i - 1];
                    [near(u, q[0])?, near(u, q[1])?]
                }
                _ => point(u)?,
            };
            points.push(p);
        }
        Ok(BezierCase { points })
    }

    /// The curve with exact coordinates (`None` if a coordinate is not finite).
    pub fn exact(&self) -> Option<crate::curve::Bezier<crate::scalar::Rational>> {
        use crate::scalar::rational_from_f64;
        let pts = self
            .points
            .iter()
            .map(|p| {
                Some(crate::curve::V2::new(
                    rational_from_f64(p[0])?,
                    rational_from_f64(p[1])?,
                ))
            })
            .collect::<Option<Vec<_>>>()?;
        (!pts.is_empty()).then(|| crate::curve::Bezier::new(pts))
    }
    /// The curve in `f64`.
    pub fn float(&self) -> crate::curve::Bezier<f64> {
        crate::curve::Bezier::new(
            self.points
                .iter()
                .map(|p| crate::curve::V2::new(p[0], p[1]))
                .collect(),
        )
    }
}

/// `n` cases drawn from a deterministic byte stream (SplitMix64 from `seed`):
/// reproducible audits without a fuzzer.
pub fn cases_from_seed<T: for<'a> Arbitrary<'a>>(seed: u64, n: usize) -> Vec<T> {
    let mut state = seed;
    let mut next = move || {
        state = state.wrapping_add(0x9E37_79B9_7F4A_7C15);
        let mut z = state;
        z = (z ^ (z >> 30)).wrapping_mul(0xBF58_476D_1CE4_E5B9);
        z = (z ^ (z >> 27)).wrapping_mul(0x94D0_49BB_1331_11EB);
        z ^ (z >> 31)
    };
    let mut out = Vec::with_capacity(n);
    let mut attempts = 0;
    while out.len() < n && attempts < 20 * n + 100 {
        attempts += 1;
        let bytes: Vec<u8> = (0..32).flat_map(|_| next().to_le_bytes()).collect();
        if let Ok(c) = T::arbitrary(&mut Unstructured::new(&bytes)) {
            out.push(c);
        }
    }
    out
}

/// The same generators as proptest strategies (feature `proptest`). Shrinking
/// works on the underlying bytes.
///
/// # Examples
/// ```
/// # #[cfg(feature = "proptest")] {
/// use lncert::gen::{strategy, HermiteCase};
/// use proptest::strategy::{Strategy, ValueTree};
/// use proptest::test_runner::TestRunner;
/// let mut runner = TestRunner::deterministic();
/// let case: HermiteCase = strategy().new_tree(&mut runner).unwrap().current();
/// assert!(case.u > 0.0);
/// # }
/// ```
#[cfg(feature = "proptest")]
pub fn strategy<T>() -> impl proptest::strategy::Strategy<Value = T>
where
    T: for<'a> Arbitrary<'a> + std::fmt::Debug,
{
    use proptest::prelude::*;
    prop::collection::vec(any::<u8>(), 64..256)
        .prop_filter_map("generator rejected the bytes", |b| {
            T::arbitrary(&mut Unstructured::new(&b)).ok()
        })
}
