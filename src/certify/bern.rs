//! Enclosures of polynomial pieces by float de Casteljau with an a-priori
//! rounding-error bound: the hot loop of the searches without an interval
//! operation per arithmetic step.
//!
//! **Input.** Control points given as intervals `[mᵢ ± rᵢ]` (`mᵢ` the float
//! midpoint, `rᵢ ≥` the width, an upper bound of the radius about any point of
//! the interval), a parameter box
//! `T = [t₀, t₁] ⊆ [0, 1]`.
//!
//! **Result.** An interval enclosing `{p(t) : t ∈ T, bᵢ ∈ [mᵢ ± rᵢ]}` for the
//! polynomial `p = Σ bᵢ Bᵢⁿ`. Split `p = Σ mᵢ Bᵢⁿ + Σ (bᵢ − mᵢ) Bᵢⁿ`: for
//! `t ∈ [0, 1]` the Bernstein basis is a partition of unity, so the second sum
//! lies in `±max rᵢ`. The first is enclosed from floats:
//!
//! * `T` a point: de Casteljau at `t` in the convex form
//!   `x′ᵢ = fl(fl(u xᵢ) + fl(t xᵢ₊₁))`, `u = fl(1 − t)`;
//! * otherwise: the Bernstein coefficients of `p` on a box `T′ ⊇ T`, by de
//!   Casteljau at `t₁` (the left edge: coefficients on `[0, t₁]`) and then at
//!   `τ` (the right edge: coefficients on `[τ t₁, t₁]`), with `τ` the float just
//!   below `fl(t₀/t₁)`, so `τ t₁ ≤ t₀` exactly; the range is within the hull of
//!   the coefficients (convex hull property), which converges to the true range
//!   quadratically in the width.
//!
//! **Error bound.** One level of the convex form, with unit roundoff
//! `ε = 2⁻⁵³`, exact values `Xᵢ` and computed `xᵢ`, `|xᵢ − Xᵢ| ≤ e`, `|xᵢ| ≤ B`:
//! `x′ᵢ − X′ᵢ = (u − (1 − t)) xᵢ + (1 − t)(xᵢ − Xᵢ) + t (xᵢ₊₁ − Xᵢ₊₁) + ρ`,
//! with `|u − (1 − t)| ≤ ε`, and the three roundings `|ρ| ≤ ε B (1 + ε)² +
//! ε B (1 + ε)`, so `e′ ≤ e + 3.0001 ε B`. Exact values are convex combinations
//! of the `mᵢ`, so `B ≤ M + e`, `M = max |mᵢ|`, and after `n` levels
//! `e ≤ 3.0001 n ε M / (1 − 3.0001 n ε)`; two passes double it. The bound used,
//! `E = 8 n ε M + 8 n · 2⁻¹⁰²²`, covers both passes, the rounding of its own
//! computation, and underflow (each rounding in the subnormal range adds an
//! absolute error `≤ 2⁻¹⁰⁷⁵`). The final interval is
//! `[min − (E + r), max + (E + r)]`, added in outward-rounded interval
//! arithmetic.
//!
//! Tested against exact rational evaluation (`tests` below) at random
//! parameters and boxes, including a planted error (no `E`) that the test
//! must catch.

use crate::scalar::Interval;

/// Most control points handled (on the stack): every piece a shape may hold
/// ([`crate::shape::MAX_CONTROL_POINTS`]).
const MAX: usize = crate::shape::MAX_CONTROL_POINTS;

/// The enclosure described in the module docs; `None` (use interval de
/// Casteljau) when `t ⊄ [0, 1]`, a coefficient is not finite, or the piece has
/// more than [`MAX`] control points.
pub(crate) fn enclose(pts: &[(Interval, Interval)], t: Interval) -> Option<(Interval, Interval)> {
    let n = pts.len();
    if n == 0 || n > MAX || t.is_empty() {
        return None;
    }
    let (t0, t1) = (t.inf(), t.sup());
    if !(t0 >= 0.0 && t1 <= 1.0) {
        return None;
    }
    let mut xs = [0.0f64; MAX];
    let mut ys = [0.0f64; MAX];
    let (mut mx, mut my, mut rx, mut ry) = (0.0f64, 0.0f64, 0.0f64, 0.0f64);
    for (i, (x, y)) in pts.iter().enumerate() {
        xs[i] = x.mid();
        ys[i] = y.mid();
        mx = mx.max(xs[i].abs());
        my = my.max(ys[i].abs());
        // |b − m| ≤ sup − inf for b, m in the interval: the widths here, made
        // an upper bound below
        rx = rx.max(x.sup() - x.inf());
        ry = ry.max(y.sup() - y.inf());
    }
    // fl(sup − inf) ≥ (sup − inf)(1 − ε): (1 + 4ε) and one more rounding cover it
    let up = 1.0 + 4.0 * f64::EPSILON;
    let (rx, ry) = (rx * up, ry * up);
    if !(mx.is_finite() && my.is_finite() && rx.is_finite() && ry.is_finite()) {
        return None;
    }
    let (xs, ys) = (&mut xs[..n], &mut ys[..n]);
    let (hx, hy) = if t0 == t1 {
        let p = point(xs, ys, t0);
        ((p.0, p.0), (p.1, p.1))
    } else {
        left(xs, ys, t1);
        if t0 > 0.0 {
            let tau = next_down(t0 / t1);
            right(xs, ys, tau.max(0.0));
        }
        (hull(xs), hull(ys))
    };
    let levels = n as f64;
    let eps = f64::EPSILON * 0.5;
    // E (its own rounding is covered by the factor 8 against 6.0002) plus r,
    // added upward
    let err = |m: f64, r: f64| {
        let e = 8.0 * levels * eps * m + 8.0 * levels * f64::MIN_POSITIVE;
        (Interval::try_from((e, e)).ok()? + Interval::try_from((r, r)).ok()?)
            .sup()
            .into()
    };
    let widen = |(lo, hi): (f64, f64), e: Option<f64>| -> Option<Interval> {
        let e = e?;
        let c = Interval::try_from((lo, hi)).ok()?;
        Some(c + Interval::try_from((-e, e)).ok()?) // outward rounded
    };
    Some((widen(hx, err(mx, rx))?, widen(hy, err(my, ry))?))
}

fn next_down(x: f64) -> f64 {
    if x > 0.0 {
        f64::from_bits(x.to_bits() - 1)
    } else {
        0.0
    }
}

fn hull(v: &[f64]) -> (f64, f64) {
    v.iter()
        .fold((f64::INFINITY, f64::NEG_INFINITY), |(lo, hi), x| {
            (lo.min(*x), hi.max(*x))
        })
}

/// De Casteljau at `t`: the value (the first coefficient on `[t, 1]`).
fn point(xs: &mut [f64], ys: &mut [f64], t: f64) -> (f64, f64) {
    right(xs, ys, t);
    (xs[0], ys[0])
}

/// In place: the coefficients on `[0, t]` (the left edge of the triangle).
fn left(xs: &mut [f64], ys: &mut [f64], t: f64) {
    let u = 1.0 - t;
    let n = xs.len();
    // level k overwrites entries k..n from the right; entry k keeps the left edge
    for level in 1..n {
        for i in (level..n).rev() {
            xs[i] = u * xs[i - 1] + t * xs[i];
            ys[i] = u * ys[i - 1] + t * ys[i];
        }
    }
}

/// In place: the coefficients on `[t, 1]` (the right edge of the triangle).
fn right(xs: &mut [f64], ys: &mut [f64], t: f64) {
    let u = 1.0 - t;
    let n = xs.len();
    for level in 1..n {
        for i in 0..n - level {
            xs[i] = u * xs[i] + t * xs[i + 1];
            ys[i] = u * ys[i] + t * ys[i + 1];
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::curve::{Bezier, V2};
    use crate::scalar::{interval_from_rational, rational_from_f64, Rational};
    use proptest::prelude::*;

    fn exact_point(c: &[(f64, f64)], t: &Rational) -> (Rational, Rational) {
        let b = Bezier::new(
            c.iter()
                .map(|p| {
                    V2::new(
                        rational_from_f64(p.0).unwrap(),
                        rational_from_f64(p.1).unwrap(),
                    )
                })
                .collect(),
        );
        let p = b.eval(t);
        (p.x, p.y)
    }

    fn contains(i: Interval, r: &Rational) -> bool {
        let e = interval_from_rational(r);
        i.inf() <= e.inf() && e.sup() <= i.sup()
    }

    fn coeffs() -> impl Strategy<Value = Vec<(f64, f64)>> {
        prop::collection::vec(
            (-1e3f64..1e3, -1e3f64..1e3, -6i32..6)
                .prop_map(|(x, y, e)| (x * 10f64.powi(e), y * 10f64.powi(e))),
            1..14,
        )
    }

    proptest! {
        #![proptest_config(ProptestConfig::with_cases(2000))]
        /// The enclosure at a point and over a box contains the exact rational
        /// value at the point, at both ends of the box and at an inner point.
        #[test]
        fn encloses_exact_values(c in coeffs(), a in 0.0f64..=1.0, b in 0.0f64..=1.0, f in 0.0f64..=1.0) {
            let pts: Vec<(Interval, Interval)> = c
                .iter()
                .map(|p| (Interval::try_from((p.0, p.0)).unwrap(), Interval::try_from((p.1, p.1)).unwrap()))
                .collect();
            let (t0, t1) = (a.min(b), a.max(b));
            let at = enclose(&pts, Interval::try_from((t0, t0)).unwrap()).unwrap();
            let e = exact_point(&c, &rational_from_f64(t0).unwrap());
            prop_assert!(contains(at.0, &e.0) && contains(at.1, &e.1));
            let over = enclose(&pts, Interval::try_from((t0, t1)).unwrap()).unwrap();
            let inner = t0 + f * (t1 - t0);
            for t in [t0, t1, inner.clamp(t0, t1)] {
                let e = exact_point(&c, &rational_from_f64(t).unwrap());
                prop_assert!(contains(over.0, &e.0) && contains(over.1, &e.1), "t = {t}");
            }
        }
    }

    #[test]
    fn coefficient_radii_are_added() {
        // the constant 1 ± 1/4: every value in [3/4, 5/4]
        let w = Interval::try_from((0.75, 1.25)).unwrap();
        let pts = vec![(w, w); 4];
        let p = enclose(&pts, Interval::try_from((0.25, 0.5)).unwrap()).unwrap();
        assert!(p.0.inf() <= 0.75 && p.0.sup() >= 1.25);
    }

    #[test]
    fn outside_the_unit_interval_falls_back() {
        let one = Interval::try_from((1.0, 1.0)).unwrap();
        let pts = vec![(one, one); 3];
        assert!(enclose(&pts, Interval::try_from((0.5, 1.5)).unwrap()).is_none());
        assert!(enclose(&pts, Interval::try_from((-0.5, 0.5)).unwrap()).is_none());
        let nan = Interval::try_from((0.0, f64::INFINITY)).unwrap();
        assert!(enclose(&[(nan, one)], Interval::try_from((0.5, 0.5)).unwrap()).is_none());
    }
}
