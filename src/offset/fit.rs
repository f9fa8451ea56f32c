//! Fitted output: the cubic or quadratic Bézier segments users store (CFF,
//! SVG, PDF: cubics; TrueType: quadratics), fitted to the **exact** offset or
//! convolution of a span and then proven against it like any other segment.
//!
//! The fit is a float heuristic: only the certification of the written numbers
//! decides (see `proofs/offset-fit.md`). Per span `[t₀, t₁]`:
//!
//! | [`Output`] | segment | ends | inner control points |
//! |---|---|---|---|
//! | `Native` | the construction of [`super::OffsetMethod`] (degree `n + 3` or LN-pair cubic) | canonical | the construction's |
//! | `Cubic` | cubic | canonical | on the exact end tangents; handle lengths from the G² Hermite system ([`g2_hermite_cubics`]), least squares ([`least_squares_cubic`]) or thirds of the chord, the one with the smallest sampled error, then lowered by a Nelder–Mead search on the sampled max error |
//! | `Quadratic` | quadratic | canonical | the intersection of the exact end tangents ([`tangent_quadratic`]); none when they do not meet ahead (the span is split) |
//!
//! *Canonical* end points are those of the native path: `x(tᵢ) + d Nᵢ` with
//! [`super::prep::unit_left_normal`] (or the pen point
//! [`super::conv::pen_point_at`] of a convolution), computed with the same
//! float operations, so neighbouring segments share their end points bit for
//! bit. The exact curve's tangent at a parameter is `(1 + λ) x′`
//! (`λ = −d κ` for an offset, `κ` the signed curvature of `x`: past a cusp of
//! the offset, `1 − d κ < 0`, its tangent is reversed) and its signed
//! curvature along its own parameter is `κ / |1 + λ|`.
//!
//! [`round_to_grid`] rounds control points to multiples of a dyadic grid
//! ([`check_grid`]); the driver proves the rounded segment.

use super::driver::Kernel;
use super::{conv, prep, OffsetError};
use crate::curve::{Bezier, V2};
use crate::scalar::{interval_from_rational, rational_from_f64, Rational, Scalar};
use glam::DVec2;
use num_traits::Signed;
use std::cell::Cell;

/// Which curves the output consists of.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Default)]
pub enum Output {
    /// The construction's own segments ([`super::OffsetMethod`]: degree `n + 3`
    /// for G2, cubic LN pairs) — today's behaviour.
    #[default]
    Native,
    /// Cubic Béziers fitted to the exact curve (G¹ at the joints: shared end
    /// points and tangent directions).
    Cubic,
    /// Quadratic Béziers (tangent-intersection control point, G¹).
    Quadratic,
}

impl Output {
    /// The name in reports: `native`, `cubic` or `quadratic`.
    ///
    /// # Examples
    /// ```
    /// use lncert::offset::Output;
    /// assert_eq!(Output::Cubic.name(), "cubic");
    /// assert_eq!(Output::default().name(), "native");
    /// ```
    pub fn name(self) -> &'static str {
        match self {
            Output::Native => "native",
            Output::Cubic => "cubic",
            Output::Quadratic => "quadratic",
        }
    }
}

/// The end data of a fit: end points, unit tangents in the direction of
/// travel (from the first end to the second), signed curvatures along it.
#[derive(Clone, Debug, PartialEq)]
pub struct FitEnds {
    /// Start point.
    pub p0: V2<f64>,
    /// End point.
    pub p1: V2<f64>,
    /// Unit tangent at the start.
    pub t0: V2<f64>,
    /// Unit tangent at the end.
    pub t1: V2<f64>,
    /// Signed curvature at the start (`> 0` turning left); may be non-finite.
    pub k0: f64,
    /// Signed curvature at the end.
    pub k1: f64,
}

pub(super) fn dv(p: &V2<f64>) -> DVec2 {
    DVec2::new(p.x, p.y)
}

pub(super) fn v2(p: DVec2) -> V2<f64> {
    V2::new(p.x, p.y)
}

/// The cubic `p0, p0 + a t0, p1 − b t1, p1`.
pub(super) fn hermite(e: &FitEnds, a: f64, b: f64) -> Bezier<f64> {
    let (p0, p1, t0, t1) = (dv(&e.p0), dv(&e.p1), dv(&e.t0), dv(&e.t1));
    Bezier::new(vec![
        e.p0.clone(),
        v2(p0 + t0 * a),
        v2(p1 - t1 * b),
        e.p1.clone(),
    ])
}

/// The G² cubic Hermite interpolants (de Boor, Höllig, Sabin 1987): the cubics
/// `p0, p0 + a t0, p1 − b t1, p1` with `a, b > 0` whose end curvatures are
/// `k0`, `k1`, from
///
/// ```text
/// (3/2) k0 a² = t0 × c − (t0 × t1) b,    (3/2) k1 b² = c × t1 − (t0 × t1) a
/// ```
///
/// (`c = p1 − p0`): eliminating `b` leaves a quartic in `a`, whose roots in
/// `(0, 3|c|]` are found by sign changes on a grid and bisection. Parallel end
/// tangents give the decoupled `a = √(2 (t0 × c)/(3 k0))` and likewise `b`.
/// Empty when there is no positive solution (the caller falls back).
///
/// # Examples
/// ```
/// use lncert::offset::kernels::{g2_hermite_cubics, FitEnds};
/// use lncert::curve::V2;
/// // a quarter of the unit circle: a = b = (√7 − 1)/3 ≈ 0.5486 (3a²/2 + a − 1 = 0)
/// let e = FitEnds {
///     p0: V2::new(1.0, 0.0), p1: V2::new(0.0, 1.0),
///     t0: V2::new(0.0, 1.0), t1: V2::new(-1.0, 0.0), k0: 1.0, k1: 1.0,
/// };
/// let c = g2_hermite_cubics(&e);
/// assert!(!c.is_empty());
/// let a = c[0].points()[1].y;
/// assert!((a - (7f64.sqrt() - 1.0) / 3.0).abs() < 1e-9, "{a}");
/// ```
pub fn g2_hermite_cubics(e: &FitEnds) -> Vec<Bezier<f64>> {
    let (p0, p1, t0, t1) = (dv(&e.p0), dv(&e.p1), dv(&e.t0), dv(&e.t1));
    let c = p1 - p0;
    let len = c.length();
    let (k0, k1) = (e.k0, e.k1);
    if !(len > 0.0 && k0.is_finite() && k1.is_finite()) {
        return Vec::new();
    }
    let aa = t0.perp_dot(c);
    let bb = c.perp_dot(t1);
    let cr = t0.perp_dot(t1);
    let ok = |a: f64, b: f64| a > 0.0 && b > 0.0 && a < 3.0 * len && b < 3.0 * len;
    let mut out = Vec::new();
    if cr.abs() < 1e-9 {
        if k0 == 0.0 || k1 == 0.0 {
            return out;
        }
        let (a2, b2) = (2.0 * aa / (3.0 * k0), 2.0 * bb / (3.0 * k1));
        if a2 > 0.0 && b2 > 0.0 && ok(a2.sqrt(), b2.sqrt()) {
            out.push(hermite(e, a2.sqrt(), b2.sqrt()));
        }
        return out;
    }
    // b(a) = (aa − 1.5 k0 a²)/cr;  f(a) = 1.5 k1 b(a)² + cr a − bb = 0
    let b_of = |a: f64| (aa - 1.5 * k0 * a * a) / cr;
    let f = |a: f64| {
        let b = b_of(a);
        1.5 * k1 * b * b + cr * a - bb
    };
    const GRID: usize = 240;
    let hi = 3.0 * len;
    let mut prev = (0.0, f(0.0));
    for i in 1..=GRID {
        let a = hi * i as f64 / GRID as f64;
        let fa = f(a);
        if prev.1 == 0.0 || prev.1.signum() != fa.signum() {
            let (mut lo, mut up, flo) = (prev.0, a, prev.1);
            for _ in 0..60 {
                let m = 0.5 * (lo + up);
                if f(m).signum() == flo.signum() && flo != 0.0 {
                    lo = m;
                } else {
                    up = m;
                }
            }
            let a = 0.5 * (lo + up);
            let b = b_of(a);
            if ok(a, b) {
                out.push(hermite(e, a, b));
            }
        }
        prev = (a, fa);
    }
    out
}

/// The cubic `p0, p0 + a t0, p1 − b t1, p1` closest in least squares to the
/// interior `samples` (in order along the curve), parametrised by chord length
/// and then `passes` times by projecting each sample onto the current cubic
/// (a linear 2 × 2 problem in `a`, `b` per pass). `None` when `a` or `b` comes
/// out non-positive or the system is singular.
///
/// # Examples
/// ```
/// use lncert::offset::kernels::{least_squares_cubic, FitEnds};
/// use lncert::curve::V2;
/// let s: Vec<V2<f64>> = (1..16)
///     .map(|j| { let u = std::f64::consts::FRAC_PI_2 * j as f64 / 16.0; V2::new(u.cos(), u.sin()) })
///     .collect();
/// let e = FitEnds {
///     p0: V2::new(1.0, 0.0), p1: V2::new(0.0, 1.0),
///     t0: V2::new(0.0, 1.0), t1: V2::new(-1.0, 0.0), k0: 1.0, k1: 1.0,
/// };
/// let c = least_squares_cubic(&e, &s, 2).unwrap();
/// assert!((c.points()[1].y - 0.552).abs() < 5e-3);
/// ```
pub fn least_squares_cubic(e: &FitEnds, samples: &[V2<f64>], passes: usize) -> Option<Bezier<f64>> {
    let (p0, p1) = (dv(&e.p0), dv(&e.p1));
    let q: Vec<DVec2> = samples.iter().map(dv).collect();
    if q.is_empty() {
        return None;
    }
    // chord-length parameters (the ends at 0 and 1)
    let mut u = Vec::with_capacity(q.len());
    let mut acc = 0.0;
    let mut last = p0;
    for p in &q {
        acc += (*p - last).length();
        u.push(acc);
        last = *p;
    }
    let total = acc + (p1 - last).length();
    if !(total > 0.0 && total.is_finite()) {
        return None;
    }
    for x in &mut u {
        *x /= total;
    }
    let mut best = solve_ls(e, &q, &u)?;
    for _ in 0..passes {
        for (p, t) in q.iter().zip(u.iter_mut()) {
            *t = project(&best, *p, *t);
        }
        best = solve_ls(e, &q, &u)?;
    }
    Some(best)
}

fn solve_ls(e: &FitEnds, q: &[DVec2], u: &[f64]) -> Option<Bezier<f64>> {
    let (p0, p1, t0, t1) = (dv(&e.p0), dv(&e.p1), dv(&e.t0), dv(&e.t1));
    let (mut m11, mut m12, mut m22, mut r1, mut r2) = (0.0, 0.0, 0.0, 0.0, 0.0);
    let tt = t0.dot(t1);
    for (p, &s) in q.iter().zip(u) {
        let w = 1.0 - s;
        let (b0, b1, b2, b3) = (w * w * w, 3.0 * w * w * s, 3.0 * w * s * s, s * s * s);
        // p − (b0 + b1) p0 − (b2 + b3) p1 = a b1 t0 − b b2 t1
        let r = *p - p0 * (b0 + b1) - p1 * (b2 + b3);
        m11 += b1 * b1;
        m12 -= b1 * b2 * tt;
        m22 += b2 * b2;
        r1 += b1 * t0.dot(r);
        r2 -= b2 * t1.dot(r);
    }
    let det = m11 * m22 - m12 * m12;
    if det.abs().partial_cmp(&1e-300) != Some(std::cmp::Ordering::Greater) {
        return None;
    }
    let a = (r1 * m22 - m12 * r2) / det;
    let b = (m11 * r2 - m12 * r1) / det;
    (a > 0.0 && b > 0.0 && a.is_finite() && b.is_finite()).then(|| hermite(e, a, b))
}

/// The parameter of the point of the cubic nearest `p`, by Newton steps from `u`.
pub(super) fn project(c: &Bezier<f64>, p: DVec2, u: f64) -> f64 {
    let q = c.points();
    project4(&[dv(&q[0]), dv(&q[1]), dv(&q[2]), dv(&q[3])], p, u)
}

/// [`project`] on the four control points (no allocation).
fn project4(pts: &[DVec2; 4], p: DVec2, mut u: f64) -> f64 {
    for _ in 0..4 {
        let w = 1.0 - u;
        let b = pts[0] * (w * w * w)
            + pts[1] * (3.0 * w * w * u)
            + pts[2] * (3.0 * w * u * u)
            + pts[3] * (u * u * u);
        let d1 = (pts[1] - pts[0]) * (3.0 * w * w)
            + (pts[2] - pts[1]) * (6.0 * w * u)
            + (pts[3] - pts[2]) * (3.0 * u * u);
        let d2 = (pts[2] - pts[1] * 2.0 + pts[0]) * (6.0 * w)
            + (pts[3] - pts[2] * 2.0 + pts[1]) * (6.0 * u);
        let r = b - p;
        let den = d1.dot(d1) + r.dot(d2);
        if den.is_nan() || den <= 0.0 {
            break;
        }
        let next = (u - r.dot(d1) / den).clamp(0.0, 1.0);
        if !next.is_finite() {
            break;
        }
        u = next;
    }
    u
}

/// The quadratic whose control point is the intersection of the end tangent
/// lines `p0 + a t0`, `p1 − b t1` (`a, b > 0`: the tangents meet ahead), the G¹
/// quadratic of the ends; for collinear ends on a line, the midpoint. `None`
/// otherwise.
///
/// # Examples
/// ```
/// use lncert::offset::kernels::{tangent_quadratic, FitEnds};
/// use lncert::curve::V2;
/// let e = FitEnds {
///     p0: V2::new(1.0, 0.0), p1: V2::new(0.0, 1.0),
///     t0: V2::new(0.0, 1.0), t1: V2::new(-1.0, 0.0), k0: 1.0, k1: 1.0,
/// };
/// assert_eq!(tangent_quadratic(&e).unwrap().points()[1], V2::new(1.0, 1.0));
/// ```
pub fn tangent_quadratic(e: &FitEnds) -> Option<Bezier<f64>> {
    let (p0, p1, t0, t1) = (dv(&e.p0), dv(&e.p1), dv(&e.t0), dv(&e.t1));
    let c = p1 - p0;
    let len = c.length();
    let cr = t0.perp_dot(t1);
    let (aa, bb) = (t0.perp_dot(c), c.perp_dot(t1));
    if cr.abs() <= 1e-12 {
        // parallel tangents: only a straight span along them has a quadratic
        let straight = aa.abs() <= 1e-12 * len && bb.abs() <= 1e-12 * len;
        return (len > 0.0 && straight && t0.dot(c) > 0.0 && t1.dot(c) > 0.0)
            .then(|| Bezier::new(vec![e.p0.clone(), v2((p0 + p1) * 0.5), e.p1.clone()]));
    }
    // a t0 + b t1 = c
    let a = bb / cr;
    let b = aa / cr;
    (a > 0.0 && b > 0.0 && a.is_finite() && b.is_finite())
        .then(|| Bezier::new(vec![e.p0.clone(), v2(p0 + t0 * a), e.p1.clone()]))
}

/// The exact curve's offset vector in floats: `d N` or the pen point.
#[derive(Clone, Copy)]
pub(super) enum Reach {
    Offset(f64),
    Pen([f64; 3], i8),
}

impl Reach {
    pub(super) fn of(kernel: &Kernel) -> Reach {
        match kernel {
            Kernel::Offset { df, .. } => Reach::Offset(*df),
            Kernel::Conv { qf, sigma, .. } => Reach::Pen(*qf, *sigma),
        }
    }
    /// The offset vector for the (not necessarily unit) derivative `v`.
    pub(super) fn vector(self, v: DVec2) -> Option<DVec2> {
        let l = v.length();
        if !(l > 0.0 && l.is_finite()) {
            return None;
        }
        let n = DVec2::new(-v.y / l, v.x / l);
        match self {
            Reach::Offset(d) => Some(n * d),
            Reach::Pen(q, s) => conv::pen_point(&v2(n), q, s).map(|p| dv(&p)),
        }
    }
    /// `λ` with `e′ = λ x′` (`v = x′`, `k = x′ × x″`).
    pub(super) fn lambda(self, v: DVec2, k: f64) -> f64 {
        match self {
            Reach::Offset(d) => -d * k / v.length().powi(3),
            Reach::Pen(q, s) => {
                let n = DVec2::new(-v.y, v.x);
                let qn = q[0] * n.x * n.x + 2.0 * q[1] * n.x * n.y + q[2] * n.y * n.y;
                let det = q[0] * q[2] - q[1] * q[1];
                -f64::from(s) * k * det / (qn * qn.sqrt())
            }
        }
    }
}

/// The canonical end point at `t` (the bits of the native path).
fn end_point(
    sub: &Bezier<f64>,
    x: &Bezier<Rational>,
    t: f64,
    first: bool,
    kernel: &Kernel,
) -> Option<V2<f64>> {
    let p = sub.points();
    let base = if first { &p[0] } else { &p[p.len() - 1] };
    match kernel {
        Kernel::Offset { df, .. } => {
            let n = prep::unit_left_normal(x, t)?;
            Some(base.add(&n.scale(df)))
        }
        Kernel::Conv { qf, sigma, .. } => Some(base.add(&conv::pen_point_at(x, t, *qf, *sigma)?)),
    }
}

/// Tangent (unit, direction of travel of the exact curve) and signed
/// curvature of the exact curve at one end of the span.
fn end_frame(
    sub: &Bezier<f64>,
    x: &Bezier<Rational>,
    t: f64,
    first: bool,
    reach: Reach,
) -> Option<(V2<f64>, f64)> {
    let n = prep::unit_left_normal(x, t)?;
    let tan = DVec2::new(n.y, -n.x);
    let h = sub.hodograph();
    let s = if first { 0.0 } else { 1.0 };
    let v = h.eval_fast(s);
    let a = if h.degree() == 0 {
        DVec2::ZERO
    } else {
        h.hodograph().eval_fast(s)
    };
    let k = v.perp_dot(a);
    let f = 1.0 + reach.lambda(v, k);
    if !f.is_finite() || f == 0.0 {
        return None;
    }
    let kappa = k / v.length().powi(3) / f.abs();
    // at (or next to) a cusp of the exact curve `f` is ≈ 0 and its sign is
    // noise: the direction of travel is that just inside the span
    let sign = if f.abs() < 1e-3 {
        let s = if first { 1.0 / 32.0 } else { 31.0 / 32.0 };
        let (v, a) = (
            h.eval_fast(s),
            if h.degree() == 0 {
                DVec2::ZERO
            } else {
                h.hodograph().eval_fast(s)
            },
        );
        (1.0 + reach.lambda(v, v.perp_dot(a))).signum()
    } else {
        f.signum()
    };
    Some((v2(tan * sign), kappa))
}

/// Samples of the exact curve at `m − 1` interior parameters `j/m` of the span.
fn samples(sub: &Bezier<f64>, reach: Reach, m: usize) -> Option<Vec<V2<f64>>> {
    let h = sub.hodograph();
    (1..m)
        .map(|j| {
            let s = j as f64 / m as f64;
            let p = sub.eval_fast(s) + reach.vector(h.eval_fast(s))?;
            (p.is_finite()).then(|| v2(p))
        })
        .collect()
}

/// A sampled one-sided distance from the exact curve's samples to the cubic
/// (each sample projected by Newton steps; a float estimate, used only to
/// choose and refine candidates), when it is below `cap`; otherwise some
/// value `≥ cap`
/// (the first sample found at least `cap` away: the maximum cannot be
/// smaller). A comparison `< cap` decides as with the full value; for
/// `≤ x`, pass `cap = x.next_up()`.
pub(super) fn sampled_error_capped(exact: &[DVec2], c: &Bezier<f64>, cap: f64) -> f64 {
    sampled_error_hinted(exact, c, cap, &Cell::new(0))
}

/// [`sampled_error_capped`], measuring the sample `exact[first]` first and
/// leaving in `first` the index of the sample that decided: the first found
/// at least `cap` away, else the farthest. Across the evaluations of a
/// search (nearby cubics) that sample is the likeliest to be over the next
/// cap, so a rejected candidate costs one projection instead of a scan. The
/// value is the same whatever the order (the same distances, and the
/// maximum of a set when below `cap`; some value `≥ cap` otherwise): only
/// the work depends on `first`.
pub(super) fn sampled_error_hinted(
    exact: &[DVec2],
    c: &Bezier<f64>,
    cap: f64,
    first: &Cell<usize>,
) -> f64 {
    const N: usize = 48;
    let q = c.points();
    let pts = [dv(&q[0]), dv(&q[1]), dv(&q[2]), dv(&q[3])];
    let mut cs = [DVec2::ZERO; N + 1];
    for (i, x) in cs.iter_mut().enumerate() {
        *x = casteljau4(&pts, i as f64 / N as f64);
    }
    // exact samples onto the cubic: nearest sample, then Newton (one-sided:
    // the curves are close, and the proofs check both directions)
    let dist = |p: &DVec2| {
        let (i, _) = cs
            .iter()
            .enumerate()
            .map(|(i, q)| (i, (*q - *p).length_squared()))
            .fold((0, f64::INFINITY), |a, b| if b.1 < a.1 { b } else { a });
        let u = project4(&pts, *p, i as f64 / N as f64);
        (casteljau4(&pts, u) - *p).length()
    };
    let h = first.get();
    let order = exact
        .get(h)
        .map(|p| (h, p))
        .into_iter()
        .chain(exact.iter().enumerate().filter(|&(i, _)| i != h));
    // (a NaN distance raises nothing, as `f64::max` ignores it)
    let (mut max, mut arg) = (0.0f64, h.min(exact.len().saturating_sub(1)));
    for (i, p) in order {
        let d = dist(p);
        if d >= cap {
            first.set(i);
            return d;
        }
        if d > max {
            (max, arg) = (d, i);
        }
    }
    first.set(arg);
    max
}

/// A cubic's point at `t` by de Casteljau, the same operations in the same
/// order as [`Bezier::eval_fast`] (so the same value, bit for bit), without
/// its general buffer.
pub(super) fn casteljau4(p: &[DVec2; 4], t: f64) -> DVec2 {
    let (b0, b1, b2) = (
        p[0] + (p[1] - p[0]) * t,
        p[1] + (p[2] - p[1]) * t,
        p[2] + (p[3] - p[2]) * t,
    );
    let (c0, c1) = (b0 + (b1 - b0) * t, b1 + (b2 - b1) * t);
    c0 + (c1 - c0) * t
}

/// Evaluations of the sampled error spent by [`refine_minimax`].
const REFINE_EVALS: usize = 40;

/// Lowers the sampled (max) error of a cubic on the end tangents by a
/// Nelder–Mead search over the two handle lengths (in log space), starting at
/// `start`: the least squares and Hermite candidates minimise other measures.
pub(super) fn refine_minimax(
    e: &FitEnds,
    dense: &[DVec2],
    start: (f64, Bezier<f64>),
) -> Bezier<f64> {
    refine_round(e, dense, start).1
}

/// The band (as a multiple of the goal) where the search along the curve of
/// equal area ([`equal_area_search`]) may bring the sampled error of
/// [`refine_minimax`]'s cubic below the goal; above it, the span is split
/// without trying.
const AREA_BAND: f64 = 4.0;

/// [`refine_minimax`], then — only where its sampled error is above `goal`
/// (within [`AREA_BAND`] of it), so below the goal nothing changes — the
/// better of it and [`equal_area_search`]'s cubic. Returns the sampled error
/// with the cubic.
pub(super) fn refine_rounds(
    e: &FitEnds,
    dense: &[DVec2],
    start: (f64, Bezier<f64>),
    goal: f64,
    outline: impl FnOnce() -> Option<Vec<DVec2>>,
) -> (f64, Bezier<f64>) {
    let best = refine_round(e, dense, start);
    if !(best.0 > goal && best.0 < AREA_BAND * goal) {
        return best;
    }
    let Some(outline) = outline() else {
        return best;
    };
    match equal_area_search(e, dense, &outline, &best.1) {
        Some(c) if c.0 < best.0 => c,
        _ => best,
    }
}

/// Twice the signed area between a cubic and its chord: `∫ (x y′ − y x′) dt`
/// over the curve (by 3-point Gauss–Legendre, exact for the degree-5
/// integrand) plus `p3 × p0` for the chord back. In floats (a heuristic's).
fn cubic_area2(p: &[DVec2; 4]) -> f64 {
    let d = [
        (p[1] - p[0]) * 3.0,
        (p[2] - p[1]) * 3.0,
        (p[3] - p[2]) * 3.0,
    ];
    let at = |t: f64| {
        let x = casteljau4(p, t);
        let u = 1.0 - t;
        let v = d[0] * (u * u) + d[1] * (2.0 * u * t) + d[2] * (t * t);
        x.perp_dot(v)
    };
    let r = (0.6f64).sqrt() / 2.0;
    let integral = (5.0 * at(0.5 - r) + 8.0 * at(0.5) + 5.0 * at(0.5 + r)) / 18.0;
    integral + p[3].perp_dot(p[0])
}

/// Twice the signed area between a polyline and its chord (shoelace).
fn polyline_area2(q: &[DVec2]) -> f64 {
    let closing = match (q.first(), q.last()) {
        (Some(a), Some(b)) => b.perp_dot(*a),
        _ => 0.0,
    };
    q.windows(2).map(|w| w[0].perp_dot(w[1])).sum::<f64>() + closing
}

/// Samples of the exact curve for its area (ends included).
const AREA_SAMPLES: usize = 256;

/// The cubics on the end tangents whose area (with the chord) is the exact
/// curve's form a curve in the plane of the handle lengths `(a, b)` (the
/// area is `α + β a + γ b + δ a b`, so `b` follows from `a`); the best of
/// them by the sampled error, found by a golden-section search over `ln a`
/// around `near`'s handle. Nelder–Mead over `(a, b)` stalls in the narrow
/// valley of a max error, which this curve runs along (the fits that keep
/// the area, as kurbo's, are near the best). `outline`: the exact curve's
/// samples, ends included, at [`AREA_SAMPLES`] intervals; its area is
/// extrapolated (Richardson, from every sample and every other one). A float
/// heuristic: `None` when nothing usable is found; the proofs decide.
fn equal_area_search(
    e: &FitEnds,
    dense: &[DVec2],
    outline: &[DVec2],
    near: &Bezier<f64>,
) -> Option<(f64, Bezier<f64>)> {
    if outline.len() < 5 || outline.len() % 2 == 0 {
        return None;
    }
    let half: Vec<DVec2> = outline.iter().step_by(2).copied().collect();
    let (fine, coarse) = (polyline_area2(outline), polyline_area2(&half));
    let target = fine + (fine - coarse) / 3.0;
    let area = |a: f64, b: f64| {
        let c = hermite(e, a, b);
        let q = c.points();
        cubic_area2(&[dv(&q[0]), dv(&q[1]), dv(&q[2]), dv(&q[3])])
    };
    let b_of = |a: f64| {
        let (z, one) = (area(a, 0.0), area(a, 1.0));
        let b = (target - z) / (one - z);
        (b.is_finite() && b > 0.0).then_some(b)
    };
    let eval = |u: f64| -> (f64, Option<Bezier<f64>>) {
        let a = u.exp();
        match b_of(a) {
            Some(b) => {
                let c = hermite(e, a, b);
                let err = sampled_error_capped(dense, &c, f64::INFINITY);
                (if err.is_finite() { err } else { f64::INFINITY }, Some(c))
            }
            None => (f64::INFINITY, None),
        }
    };
    let a0 = (dv(&near.points()[1]) - dv(&near.points()[0])).length();
    if !(a0 > 0.0 && a0.is_finite()) {
        return None;
    }
    let (mut lo, mut hi) = (a0.ln() - 1.0, a0.ln() + 1.0);
    let g = (5f64.sqrt() - 1.0) / 2.0;
    let (mut x1, mut x2) = (hi - g * (hi - lo), lo + g * (hi - lo));
    let (mut f1, mut f2) = (eval(x1), eval(x2));
    for _ in 0..GOLDEN_STEPS {
        if f1.0 <= f2.0 {
            (hi, x2, f2) = (x2, x1, f1);
            x1 = hi - g * (hi - lo);
            f1 = eval(x1);
        } else {
            (lo, x1, f1) = (x1, x2, f2);
            x2 = lo + g * (hi - lo);
            f2 = eval(x2);
        }
    }
    let best = if f1.0 <= f2.0 { f1 } else { f2 };
    best.1.map(|c| (best.0, c))
}

/// Golden-section steps of [`equal_area_search`] (the bracket shrinks to
/// `0.618²⁴ ≈ 1e-5` of its width).
const GOLDEN_STEPS: usize = 24;

/// One round of [`refine_minimax`]: [`REFINE_EVALS`] evaluations from
/// `start`; the best cubic found and its sampled error (`start` itself when
/// nothing is better).
fn refine_round(e: &FitEnds, dense: &[DVec2], start: (f64, Bezier<f64>)) -> (f64, Bezier<f64>) {
    let handle =
        |c: &Bezier<f64>, i: usize, j: usize| (dv(&c.points()[i]) - dv(&c.points()[j])).length();
    let (a0, b0) = (handle(&start.1, 1, 0), handle(&start.1, 3, 2));
    if !(a0 > 0.0 && b0 > 0.0) {
        return start;
    }
    // capped: a value ≥ cap decides every comparison with cap as the full one
    let hint = Cell::new(0);
    let eval = |p: [f64; 2], cap: f64| {
        let c = hermite(e, p[0].exp(), p[1].exp());
        let err = sampled_error_hinted(dense, &c, cap, &hint);
        (if err.is_finite() { err } else { f64::INFINITY }, c)
    };
    let (la, lb) = (a0.ln(), b0.ln());
    let mut simplex: Vec<([f64; 2], f64)> = vec![([la, lb], start.0)];
    for p in [[la + 0.2, lb], [la, lb + 0.2]] {
        simplex.push((p, eval(p, f64::INFINITY).0));
    }
    let mut evals = 2;
    while evals < REFINE_EVALS {
        simplex.sort_by(|x, y| x.1.total_cmp(&y.1));
        let (best, worst) = (simplex[0].0, simplex[2].0);
        let c = [
            (best[0] + simplex[1].0[0]) / 2.0,
            (best[1] + simplex[1].0[1]) / 2.0,
        ];
        let at = |k: f64| [c[0] + k * (worst[0] - c[0]), c[1] + k * (worst[1] - c[1])];
        // (fr is kept only below simplex[1].1, fx only below fr, fk only
        // below simplex[2].1: those caps change no decision)
        let r = at(-1.0);
        let fr = eval(r, simplex[1].1).0;
        evals += 1;
        if fr < simplex[0].1 {
            let x = at(-2.0);
            let fx = eval(x, fr).0;
            evals += 1;
            simplex[2] = if fx < fr { (x, fx) } else { (r, fr) };
        } else if fr < simplex[1].1 {
            simplex[2] = (r, fr);
        } else {
            let k = at(0.5);
            let fk = eval(k, simplex[2].1).0;
            evals += 1;
            if fk < simplex[2].1 {
                simplex[2] = (k, fk);
            } else {
                // shrink towards the best
                for v in simplex.iter_mut().skip(1) {
                    v.0 = [(v.0[0] + best[0]) / 2.0, (v.0[1] + best[1]) / 2.0];
                    v.1 = eval(v.0, f64::INFINITY).0;
                    evals += 1;
                }
            }
        }
    }
    simplex.sort_by(|x, y| x.1.total_cmp(&y.1));
    if simplex[0].1 < start.0 {
        eval(simplex[0].0, f64::INFINITY)
    } else {
        start
    }
}

/// Interior samples for the least squares fit.
const LS_SAMPLES: usize = 16;
/// Interior samples (dense) for choosing among candidates.
const CHOICE_SAMPLES: usize = 48;

/// The sampled error band, as multiples of the span's target, in which a
/// cubic candidate is refined ([`refine_minimax`], about 40 sampled-error
/// evaluations): below it the proof has room to spare, above it no handle
/// lengths bring the span within its target (the driver splits it unproven).
const REFINE_BAND: (f64, f64) = (0.25, 16.0);

/// The fitted segment of one span (`output` Cubic or Quadratic): `None` when
/// no candidate exists (the driver splits the span). `target`: the error the
/// segment is to be proven within (only the effort spent on refining the
/// choice depends on it).
pub(super) fn construct(
    output: super::Output,
    x: &Bezier<Rational>,
    t: (f64, f64),
    kernel: &Kernel,
    target: f64,
) -> Option<Bezier<f64>> {
    let sub = super::span_f64(x, t)?;
    let reach = Reach::of(kernel);
    let p0 = end_point(&sub, x, t.0, true, kernel)?;
    let p1 = end_point(&sub, x, t.1, false, kernel)?;
    let (t0, k0) = end_frame(&sub, x, t.0, true, reach)?;
    let (t1, k1) = end_frame(&sub, x, t.1, false, reach)?;
    let e = FitEnds {
        p0,
        p1,
        t0,
        t1,
        k0,
        k1,
    };
    match output {
        Output::Quadratic => tangent_quadratic(&e),
        Output::Native | Output::Cubic => {
            let ls = samples(&sub, reach, LS_SAMPLES)?;
            let mut cands = g2_hermite_cubics(&e);
            cands.extend(least_squares_cubic(&e, &ls, 2));
            let len = (dv(&e.p1) - dv(&e.p0)).length();
            if len > 0.0 {
                cands.push(hermite(&e, len / 3.0, len / 3.0));
            }
            if cands.len() == 1 {
                return cands.pop();
            }
            let dense: Vec<DVec2> = std::iter::once(dv(&e.p0))
                .chain(samples(&sub, reach, CHOICE_SAMPLES)?.iter().map(dv))
                .chain(std::iter::once(dv(&e.p1)))
                .collect();
            // the first least error (later ones capped at the best so far:
            // a capped value is not below it, as the full one)
            let mut best: Option<(f64, Bezier<f64>)> = None;
            for c in cands {
                let cap = best.as_ref().map_or(f64::INFINITY, |b| b.0);
                let err = sampled_error_capped(&dense, &c, cap);
                if err.is_finite() && best.as_ref().is_none_or(|b| err < b.0) {
                    best = Some((err, c));
                }
            }
            let best = best?;
            let (lo, hi) = (REFINE_BAND.0 * target, REFINE_BAND.1 * target);
            if !(best.0 > lo && best.0 < hi) {
                return Some(best.1);
            }
            let outline = || {
                let inner = samples(&sub, reach, AREA_SAMPLES)?;
                Some(
                    std::iter::once(dv(&e.p0))
                        .chain(inner.iter().map(dv))
                        .chain(std::iter::once(dv(&e.p1)))
                        .collect(),
                )
            };
            Some(refine_rounds(&e, &dense, best, target, outline).1)
        }
    }
}

/// The cusps of an offset at which a fitted output cuts its initial spans:
/// `(piece, t)` of each cusp except those whose nearest other cusp is within
/// `tol` (a swallowtail smaller than the tolerance is spanned by one segment,
/// cutting it would only add segments). Heuristic; the proofs decide.
pub(super) fn cusps_to_cut(cusps: &[prep::OffsetCusp], tol: f64) -> Vec<(usize, f64)> {
    cusps
        .iter()
        .enumerate()
        .filter(|(i, c)| {
            !cusps.iter().enumerate().any(|(j, o)| {
                j != *i && (c.point.0 - o.point.0).hypot(c.point.1 - o.point.1) <= tol
            })
        })
        .map(|(_, c)| (c.piece, c.t_approx))
        .collect()
}

/// An upper bound (rounded up) of how far rounding to the grid moves a
/// Bézier curve: each control point moves by at most `grid/2` per coordinate,
/// `grid·√2/2` in all, and a Bézier curve (a convex combination of its control
/// points) by no more.
///
/// # Examples
/// ```
/// use lncert::offset::kernels::rounding_move;
/// let m = rounding_move(&lncert::parse_rational("1/2048").unwrap());
/// assert!(m >= 2f64.sqrt() / 4096.0 && m < 3.46e-4);
/// ```
pub fn rounding_move(grid: &Rational) -> f64 {
    let g = interval_from_rational(grid);
    let two = interval_from_rational(&Rational::from_integer(2.into()));
    let half_sqrt2 = crate::scalar::ScalarSqrt::sqrt(&two)
        .map(|s| s * interval_from_rational(&Rational::new(1.into(), 2.into())));
    match half_sqrt2 {
        Some(h) => (g * h).sup(),
        None => f64::INFINITY,
    }
}

/// Checks a grid for the driver: an exact positive **dyadic** rational
/// (`p/2ᵏ`: `1/2048`, `1/64`, `1/2`, `1`, `10`), so that every multiple in the
/// coordinate range (`8 (1 + scale)`) is an exact `f64` — the certified numbers
/// are the stored floats; and a rounding move below `tol` (the tolerance left
/// after the pen margin). Returns the rounding move ([`rounding_move`]).
///
/// A decimal grid such as `1/1000` is refused: its multiples (`37/1000`) are
/// not dyadic, no `f64` holds them, and the proof must cover exactly the
/// numbers written out. Scale the input instead (e.g. units of `1/1024`).
///
/// # Examples
/// ```
/// use lncert::offset::kernels::check_grid;
/// let q = |s: &str| lncert::parse_rational(s).unwrap();
/// assert!(check_grid(&q("1/2048"), 1e-3, 10.0).is_ok());
/// assert!(check_grid(&q("1/1000"), 1e-3, 10.0).is_err());
/// assert!(check_grid(&q("1/64"), 1e-3, 10.0).is_err()); // moves by 1.1e-2 > tol
/// assert!(check_grid(&q("0"), 1e-3, 10.0).is_err());
/// ```
pub fn check_grid(grid: &Rational, tol: f64, scale: f64) -> Result<f64, OffsetError> {
    check_grid_storage(grid, scale)?;
    let mv = rounding_move(grid);
    if mv.is_nan() || tol.is_nan() || mv >= tol {
        return Err(super::options::bad(
            "grid",
            format!(
                "rounding to {grid} moves the curve by up to {mv:e} (grid·√2/2) ≥ the tolerance {tol:e}: \
                 it cannot be reached by rounding; use a finer grid, or --output cubic or quadratic, whose \
                 end points are then placed where the exact curve passes near a grid point"
            ),
        ));
    }
    Ok(mv)
}

/// The storage half of [`check_grid`]: an exact positive dyadic grid whose
/// multiples over coordinates up to `8 (1 + scale)` are exact `f64` numbers
/// (no condition on the tolerance).
pub fn check_grid_storage(grid: &Rational, scale: f64) -> Result<(), OffsetError> {
    let bad = |reason: String| super::options::bad("grid", reason);
    if !grid.is_positive() {
        return Err(bad(format!("{grid} must be > 0")));
    }
    let den = grid.denom();
    let k = den.bits().saturating_sub(1);
    if den.trailing_zeros() != Some(k) {
        return Err(bad(format!(
            "{grid} is not a dyadic rational p/2^k (e.g. 1/2048, 1/64, 1, 10): the control \
             points are stored and certified as f64 numbers, and multiples of a non-dyadic \
             grid (such as 37/1000) are not; scale the input instead"
        )));
    }
    // every multiple m·grid with |m·grid| ≤ bound is m·p/2ᵏ, exact when |m·p| < 2⁵³
    let bound = 8.0 * (1.0 + scale);
    let p = Rational::from_integer(grid.numer().clone()).approx().abs();
    let range = bound * 2f64.powi(k.min(2000) as i32) + p;
    if !(range.is_finite() && range < 2f64.powi(52)) {
        return Err(bad(format!(
            "{grid} is too fine for coordinates up to {bound:e}: its multiples are not exact f64 numbers"
        )));
    }
    Ok(())
}

/// Rounds every control point to the nearest multiple of `grid` (ties away
/// from zero, exactly in rationals: deterministic, so shared end points stay
/// shared). `None` when a rounded coordinate is not an exact `f64` (see
/// [`check_grid`]).
///
/// # Examples
/// ```
/// use lncert::offset::kernels::round_to_grid;
/// use lncert::curve::{Bezier, V2};
/// let b = Bezier::new(vec![V2::new(0.3, -0.26), V2::new(1.0, 0.5)]);
/// let r = round_to_grid(&b, &lncert::parse_rational("1/4").unwrap()).unwrap();
/// assert_eq!(r.points(), &[V2::new(0.25, -0.25), V2::new(1.0, 0.5)]);
/// ```
pub fn round_to_grid(b: &Bezier<f64>, grid: &Rational) -> Option<Bezier<f64>> {
    let round = |x: f64| -> Option<f64> {
        let m = (rational_from_f64(x)? / grid).round();
        let v = m * grid;
        let f = v.approx();
        (rational_from_f64(f)? == v).then_some(f)
    };
    let pts = b
        .points()
        .iter()
        .map(|p| Some(V2::new(round(p.x)?, round(p.y)?)))
        .collect::<Option<Vec<_>>>()?;
    Some(Bezier::new(pts))
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The tangent of the exact offset reverses past its cusp: a circle of
    /// radius 1 offset by 2 to the left (inwards) runs backwards.
    #[test]
    fn lambda_sign_past_the_cusp() {
        let v = DVec2::new(0.0, 1.0); // travelling up at (1, 0) on the ccw unit circle
        let a = DVec2::new(-1.0, 0.0);
        let k = v.perp_dot(a);
        assert!(k > 0.0);
        assert!(1.0 + Reach::Offset(0.5).lambda(v, k) > 0.0);
        assert!(1.0 + Reach::Offset(2.0).lambda(v, k) < 0.0);
        // a circular pen of radius 2 agrees with the offset
        let l_pen = Reach::Pen([4.0, 0.0, 4.0], 1).lambda(v, k);
        assert!((l_pen - Reach::Offset(2.0).lambda(v, k)).abs() < 1e-12);
    }

    /// The area of a cubic with its chord (Gauss–Legendre) against the
    /// shoelace area of a dense polyline of the cubic (an independent
    /// computation), and its bilinearity in the handle lengths, which
    /// [`equal_area_search`] relies on to solve for `b`.
    #[test]
    fn cubic_area_is_the_polyline_limit_and_bilinear_in_the_handles() {
        let mut rng = crate::test_util::TestRng::new(0x0801_f2e2_8584_1d0a);
        let mut f = |m: i64| rng.int(m) as f64 / 7.0;
        for _ in 0..200 {
            let p = [
                DVec2::new(f(700), f(700)),
                DVec2::new(f(700), f(700)),
                DVec2::new(f(700), f(700)),
                DVec2::new(f(700), f(700)),
            ];
            let n = 20_000;
            let poly: Vec<DVec2> = (0..=n)
                .map(|k| casteljau4(&p, k as f64 / n as f64))
                .collect();
            let (a, b) = (cubic_area2(&p), polyline_area2(&poly));
            let scale = (p[3] - p[0]).length_squared() + (p[1] - p[0]).length_squared() + 1.0;
            assert!((a - b).abs() < 1e-6 * scale, "{a} vs {b}");
            // bilinear: area(a, b) = α + β a + γ b + δ a b
            let t0 = (p[1] - p[0]).normalize_or_zero();
            let t1 = (p[3] - p[2]).normalize_or_zero();
            let e = FitEnds {
                p0: v2(p[0]),
                p1: v2(p[3]),
                t0: v2(t0),
                t1: v2(t1),
                k0: 0.0,
                k1: 0.0,
            };
            let area = |a: f64, b: f64| {
                let q = hermite(&e, a, b);
                let q = q.points();
                cubic_area2(&[dv(&q[0]), dv(&q[1]), dv(&q[2]), dv(&q[3])])
            };
            let (z, ea, eb, ab) = (
                area(0.0, 0.0),
                area(1.0, 0.0),
                area(0.0, 1.0),
                area(1.0, 1.0),
            );
            let (u, w) = (f(100).abs(), f(100).abs());
            let bil = z + (ea - z) * u + (eb - z) * w + (ab - ea - eb + z) * u * w;
            let s2 = scale + (u + w + 1.0).powi(2);
            assert!((area(u, w) - bil).abs() < 1e-9 * s2 * (1.0 + u * w));
        }
    }

    /// A span where Nelder–Mead over the handle lengths stalls above its
    /// target and the search along the cubics of equal area does not: the
    /// offset by −60 of a quadratic of DejaVu Sans's `&` (font units). With
    /// the target 0.03 the first round's cubic is kept (sampled error about
    /// 0.0225, above 0.02); with 0.02 the equal-area search finds one about
    /// 0.0045 (kurbo's one cubic: 0.0131), so one cubic suffices. Errors
    /// measured on 400 samples of the exact offset.
    #[test]
    fn equal_area_search_finds_what_nelder_mead_misses() {
        let q = |n: i64, d: i64| Rational::new(n.into(), d.into());
        let x = Bezier::new(vec![
            V2::new(q(299, 1), q(1161, 1)),
            V2::new(q(299, 1), q(1323, 1)),
            V2::new(q(410, 1), q(2843, 2)),
        ]);
        let kernel = Kernel::Offset {
            d: q(-60, 1),
            df: -60.0,
        };
        let sub = super::super::span_f64(&x, (0.0, 1.0)).unwrap();
        let dense: Vec<DVec2> = samples(&sub, Reach::of(&kernel), 400)
            .unwrap()
            .iter()
            .map(dv)
            .collect();
        let err = |target: f64| {
            let c = construct(super::super::Output::Cubic, &x, (0.0, 1.0), &kernel, target)
                .expect("a cubic");
            sampled_error_capped(&dense, &c, f64::INFINITY)
        };
        let (first_round, searched) = (err(0.03), err(0.02));
        assert!(first_round > 0.02, "Nelder–Mead alone: {first_round}");
        assert!(searched < 0.01, "with the equal-area search: {searched}");
    }

    #[test]
    fn g2_hermite_reproduces_end_curvatures() {
        // an arc of the ellipse (2 cos θ, sin θ), θ ∈ [0.2, 1.1]
        let (a, b) = (2.0f64, 1.0f64);
        let at = |th: f64| {
            let p = V2::new(a * th.cos(), b * th.sin());
            let d = DVec2::new(-a * th.sin(), b * th.cos());
            let k = a * b / (d.length().powi(3));
            (p, v2(d.normalize()), k)
        };
        let ((p0, t0, k0), (p1, t1, k1)) = (at(0.2), at(1.1));
        let e = FitEnds {
            p0,
            p1,
            t0,
            t1,
            k0,
            k1,
        };
        let cs = g2_hermite_cubics(&e);
        assert!(!cs.is_empty());
        for c in cs {
            let p: Vec<DVec2> = c.points().iter().map(dv).collect();
            let kap0 =
                2.0 / 3.0 * (p[1] - p[0]).perp_dot(p[2] - p[1]) / (p[1] - p[0]).length().powi(3);
            let kap1 =
                2.0 / 3.0 * (p[2] - p[1]).perp_dot(p[3] - p[2]) / (p[3] - p[2]).length().powi(3);
            assert!(
                (kap0 - e.k0).abs() < 1e-9 && (kap1 - e.k1).abs() < 1e-9,
                "{kap0} {kap1}"
            );
        }
    }

    #[test]
    fn quadratic_refuses_tangents_that_do_not_meet_ahead() {
        // an S: the tangents meet behind
        let e = FitEnds {
            p0: V2::new(0.0, 0.0),
            p1: V2::new(2.0, 0.0),
            t0: V2::new(0.6, 0.8),
            t1: V2::new(0.6, 0.8),
            k0: 0.0,
            k1: 0.0,
        };
        assert!(tangent_quadratic(&e).is_none());
    }

    /// `casteljau4` is `Bezier::eval_fast` bit for bit (the fits' choices,
    /// hence the written fonts, do not change), and the capped sampled error
    /// is the full one below its cap and at least the cap otherwise.
    #[test]
    fn fast_cubic_evaluation_and_capped_error_match() {
        let mut rng = crate::test_util::TestRng::new(0x2545_f491_4f6c_dd1d);
        for _ in 0..500 {
            let mut pt = || V2::new(rng.int(2000) as f64 / 7.0, rng.int(2000) as f64 / 13.0);
            let c = Bezier::new(vec![pt(), pt(), pt(), pt()]);
            let p = [
                dv(&c.points()[0]),
                dv(&c.points()[1]),
                dv(&c.points()[2]),
                dv(&c.points()[3]),
            ];
            for k in 0..=64 {
                let t = k as f64 / 64.0 + 1e-3 * (k % 3) as f64;
                let (a, b) = (casteljau4(&p, t), c.eval_fast(t));
                assert!(a.x.to_bits() == b.x.to_bits() && a.y.to_bits() == b.y.to_bits());
            }
            let exact: Vec<DVec2> = (0..40)
                .map(|_| DVec2::new(rng.int(2000) as f64 / 7.0, rng.int(2000) as f64 / 13.0))
                .collect();
            let full = sampled_error_capped(&exact, &c, f64::INFINITY);
            // the maximum of independent full scans (no early exit, no hint)
            let direct = exact
                .iter()
                .map(|p| sampled_error_capped(std::slice::from_ref(p), &c, f64::INFINITY))
                .fold(0.0f64, f64::max);
            assert_eq!(full.to_bits(), direct.to_bits());
            for cap in [full * 0.5, full, full.next_up(), full * 2.0] {
                let v = sampled_error_capped(&exact, &c, cap);
                if full < cap {
                    assert_eq!(v.to_bits(), full.to_bits());
                } else {
                    assert!(v >= cap && v <= full);
                }
                // any first sample (in range or not) gives a value that
                // decides as the full one, and names the sample it came from
                for h in [0, 1, 17, 39, 40, 1000] {
                    let cell = Cell::new(h);
                    let w = sampled_error_hinted(&exact, &c, cap, &cell);
                    if full < cap {
                        assert_eq!(w.to_bits(), full.to_bits(), "hint {h}");
                    } else {
                        assert!(w >= cap && w <= full, "hint {h}");
                    }
                    let at = exact.get(cell.get()).expect("a sample's index");
                    let d = sampled_error_capped(std::slice::from_ref(at), &c, f64::INFINITY);
                    assert_eq!(d.to_bits(), w.to_bits(), "hint {h}: the deciding sample");
                }
            }
        }
    }
}
