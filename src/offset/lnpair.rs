//! Seed 000 §6: offsets from pairs of cubic LN curves with one normal map.
//!
//! A convex segment `p` (no inflection, turning less than π) is replaced by the
//! cubic LN curve `pa` of its frame `b0 = p(0)`, `bm` = the intersection of the
//! end tangents, `b3 = p(1)` (Prop 3.1), and the circular arc `c_r = r N` of
//! the same normals by its cubic LN approximation `ca_r` (frame `r N0`,
//! `r (N0 + N1)/(1 + N0·N1)`, `r N1`, so `λ_c = 1`). Both take the common `κ`
//! of eq. (5) with the paper's choice `κ = √(λ_p λ_c) = √λ_p` (the geometric
//! mean, §4), which exists iff `1/4 ≤ λ_p ≤ 4` (eq. (7), Remark 4.3). By
//! Prop 4.2 the two have parallel hodographs, so the offset approximant is the
//! cubic `pa + ca_r` (Prop 4.4).
//!
//! The paper measures the error by eq. (8), `d_H(p, pa) + |r| d_H(c, ca)`, with
//! `d_H(c, ca)` from the closed form of Prop 6.1 ([`paper_error`]); lncert also
//! certifies the Hausdorff distance of the final offset itself (the driver in
//! [`crate::offset`]).

use crate::curve::{Bezier, V2};
use crate::ln::circle::ArcApprox;
use crate::ln::cubic::LnFrame;
use crate::scalar::{Interval, ScalarSqrt};

/// One LN-pair approximation of an offset segment (floats; checked afterwards).
#[derive(Clone, Debug, PartialEq)]
pub struct LnPairPiece {
    /// The cubic LN approximation of the curve segment.
    pub pa: Bezier<f64>,
    /// The cubic LN approximation of the arc `r N(t)`.
    pub ca: Bezier<f64>,
    /// `pa + ca`: the offset approximant (a cubic).
    pub offset: Bezier<f64>,
    /// `λ_p = |b3 − bm| / |bm − b0|` (1 for a straight segment).
    pub lambda: f64,
    /// The common `κ = √λ_p`.
    pub kappa: f64,
}

/// Why a segment has no LN pair (the driver then subdivides it).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum NoPair {
    /// The end tangents do not meet ahead of both ends (an inflection or a turn ≥ π).
    TangentsDoNotMeet,
    /// `λ_p ∉ [1/4, 4]`: eq. (7) fails, no common `κ` exists.
    LambdaOutOfRange,
    /// A value was not finite.
    NotFinite,
}

/// The cubic of an LN pair member ([`LnFrame::cubic`]): the frame `b0`, `bm`,
/// `b3` of ratio `λ` with the pair's common `κ` (eq. (5)),
/// `δ0 = 2/3 (2 − λ/κ)`, `δ1 = 2/3 (2 − κ/λ)`.
fn ln_cubic(b0: &V2<f64>, bm: &V2<f64>, b3: &V2<f64>, lambda: f64, kappa: f64) -> Bezier<f64> {
    LnFrame::new_unchecked(b0.clone(), bm.clone(), b3.clone()).cubic(
        &(2.0 / 3.0 * (2.0 - lambda / kappa)),
        &(2.0 / 3.0 * (2.0 - kappa / lambda)),
    )
}

/// A straight member: the segment from `a` to `b` as the cubic of the frame
/// through its midpoint with `δ0 = δ1 = 2/3` (one point when `a = b`).
fn straight_cubic(a: &V2<f64>, b: &V2<f64>) -> Bezier<f64> {
    let third = 1.0 / 3.0;
    LnFrame::new_unchecked(a.clone(), a.lerp(b, &0.5), b.clone())
        .cubic(&(2.0 * third), &(2.0 * third))
}

/// The curve segment's half of an LN pair: its end points, its unit tangents
/// at the ends and their cross product, and unless it is straight its frame's
/// middle point `bm` and ratio `λ_p`.
struct Segment {
    b0: V2<f64>,
    b3: V2<f64>,
    t0: V2<f64>,
    t1: V2<f64>,
    den: f64,
    /// `(bm, λ_p)`; `None` for a straight segment.
    frame: Option<(V2<f64>, f64)>,
}

/// The [`Segment`] of `x` with the unit left normals `n0`, `n1` at its ends;
/// `TangentsDoNotMeet` when the end tangents do not meet ahead of both ends.
fn segment(x: &Bezier<f64>, n0: &V2<f64>, n1: &V2<f64>) -> Result<Segment, NoPair> {
    let pts = x.points();
    let (b0, b3) = (pts[0].clone(), pts[pts.len() - 1].clone());
    // unit tangents from the left normals: T = −rot90(N_L) = (N.y, −N.x)
    let t0 = V2::new(n0.y, -n0.x);
    let t1 = V2::new(n1.y, -n1.x);
    let c = b3.sub(&b0);
    let den = t0.cross(&t1);
    let scale = c.norm2().sqrt();
    let frame = if den.abs() <= 1e-12 && t0.dot(&t1) > 0.0 && c.cross(&t0).abs() <= 1e-12 * scale {
        None
    } else {
        if den == 0.0 {
            return Err(NoPair::TangentsDoNotMeet);
        }
        let s = c.cross(&t1) / den;
        let u = t0.cross(&c) / den;
        if !(s > 0.0 && u > 0.0) || t0.dot(&t1) <= -1.0 + 1e-12 {
            return Err(NoPair::TangentsDoNotMeet);
        }
        Some((b0.add(&t0.scale(&s)), u / s))
    };
    Ok(Segment {
        b0,
        b3,
        t0,
        t1,
        den,
        frame,
    })
}

/// The pair `pa`, `ca` with its `λ_p`, `κ` and the approximant `pa + ca`;
/// `NotFinite` when a control point of the sum is not finite.
fn pair_piece(
    pa: Bezier<f64>,
    ca: Bezier<f64>,
    lambda: f64,
    kappa: f64,
) -> Result<LnPairPiece, NoPair> {
    let offset = Bezier::new(
        pa.points()
            .iter()
            .zip(ca.points())
            .map(|(p, q)| p.add(q))
            .collect(),
    );
    let finite = offset
        .points()
        .iter()
        .all(|p| p.x.is_finite() && p.y.is_finite());
    if !finite {
        return Err(NoPair::NotFinite);
    }
    Ok(LnPairPiece {
        pa,
        ca,
        offset,
        lambda,
        kappa,
    })
}

/// The LN pair of a segment `x` for the signed distance `d` (`d > 0` to the
/// left). `n0`, `n1` are the unit **left** normals at the ends (passed in, so
/// that neighbouring segments share them bit for bit and the spline is exactly
/// connected).
///
/// # Examples
/// ```
/// use lncert::offset::kernels::ln_pair;
/// use lncert::curve::{Bezier, V2};
/// // A quarter of the unit circle, roughly, offset by 1/2 outwards (to the right).
/// let k = 0.5523;
/// let x = Bezier::new(vec![V2::new(1.0, 0.0), V2::new(1.0, k), V2::new(k, 1.0), V2::new(0.0, 1.0)]);
/// let p = ln_pair(&x, &V2::new(-1.0, 0.0), &V2::new(0.0, -1.0), -0.5).unwrap();
/// assert!((p.lambda - 1.0).abs() < 1e-12 && (p.kappa - 1.0).abs() < 1e-12);
/// assert_eq!(p.offset.points()[0], V2::new(1.5, 0.0));
/// ```
pub fn ln_pair(x: &Bezier<f64>, n0: &V2<f64>, n1: &V2<f64>, d: f64) -> Result<LnPairPiece, NoPair> {
    let seg = segment(x, n0, n1)?;
    let c0 = n0.scale(&d);
    let c3 = n1.scale(&d);
    let Some((bm, lambda)) = seg.frame else {
        // straight: the segment and a constant normal
        let pa = straight_cubic(&seg.b0, &seg.b3);
        let ca = straight_cubic(&c0, &c3);
        return pair_piece(pa, ca, 1.0, 1.0);
    };
    if !(0.25..=4.0).contains(&lambda) {
        return Err(NoPair::LambdaOutOfRange);
    }
    let kappa = lambda.sqrt();
    let pa = ln_cubic(&seg.b0, &bm, &seg.b3, lambda, kappa);
    // the arc's frame has λ_c = 1
    let cm = n0.add(n1).scale(&(d / (1.0 + n0.dot(n1))));
    let ca = ln_cubic(&c0, &cm, &c3, 1.0, kappa);
    pair_piece(pa, ca, lambda, kappa)
}

/// Seed 000 §5: the LN pair of a trajectory segment `x` and its compatible
/// pen segment (the pen points `e0`, `e1` at the ends, e.g. of an ellipse),
/// with one linear normal map. `n0`, `n1` are the unit left normals of `x` at
/// the ends (passed in, as for [`ln_pair`]). The pen segment's frame is `e0`,
/// the intersection `em` of its end tangents (parallel to `x′` there), `e1`,
/// with ratio `λ_q = |e1 − em|/|em − e0|` (signed parameters: the pen arc may
/// run against `x′`); the common `κ = √(λ_p λ_q)` (the paper's geometric mean)
/// exists iff `λ_p/λ_q ∈ [1/4, 4]` (eq. (7)); the convolution approximant is
/// the cubic `pa + qa`. For a circle pen (`e = d N`) this is [`ln_pair`].
///
/// # Examples
/// ```
/// use lncert::offset::kernels::{ln_pair, ln_pair_pen};
/// use lncert::curve::{Bezier, V2};
/// let k = 0.5523;
/// let x = Bezier::new(vec![V2::new(1.0, 0.0), V2::new(1.0, k), V2::new(k, 1.0), V2::new(0.0, 1.0)]);
/// let (n0, n1) = (V2::new(-1.0, 0.0), V2::new(0.0, -1.0));
/// let a = ln_pair(&x, &n0, &n1, -0.5).unwrap();
/// let b = ln_pair_pen(&x, &n0, &n1, &n0.scale(&-0.5), &n1.scale(&-0.5)).unwrap();
/// for (p, q) in a.offset.points().iter().zip(b.offset.points()) {
///     assert!((p.x - q.x).abs() < 1e-12 && (p.y - q.y).abs() < 1e-12);
/// }
/// ```
pub fn ln_pair_pen(
    x: &Bezier<f64>,
    n0: &V2<f64>,
    n1: &V2<f64>,
    e0: &V2<f64>,
    e1: &V2<f64>,
) -> Result<LnPairPiece, NoPair> {
    let seg = segment(x, n0, n1)?;
    let Some((bm, lambda_p)) = seg.frame else {
        // straight: the segment, and the pen segment (one point when e0 = e1)
        let pa = straight_cubic(&seg.b0, &seg.b3);
        let qa = straight_cubic(e0, e1);
        return pair_piece(pa, qa, 1.0, 1.0);
    };
    let (t0, t1, den) = (&seg.t0, &seg.t1, seg.den);
    // the pen segment's frame: e0 + sq t0 = e1 − uq t1 (signed)
    let cq = e1.sub(e0);
    let (sq, uq) = (cq.cross(t1) / den, t0.cross(&cq) / den);
    let (em, lambda_q) = if sq == 0.0 && uq == 0.0 {
        // a pen corner (e0 = e1): the pen segment is one point
        (e0.clone(), 1.0)
    } else {
        let cross = sq * uq;
        if cross.is_nan() || cross <= 0.0 {
            return Err(NoPair::TangentsDoNotMeet);
        }
        (e0.add(&t0.scale(&sq)), uq / sq)
    };
    let ratio = lambda_p / lambda_q;
    if !(0.25..=4.0).contains(&ratio) {
        return Err(NoPair::LambdaOutOfRange);
    }
    let kappa = (lambda_p * lambda_q).sqrt();
    let pa = ln_cubic(&seg.b0, &bm, &seg.b3, lambda_p, kappa);
    let qa = ln_cubic(e0, &em, e1, lambda_q, kappa);
    pair_piece(pa, qa, lambda_p, kappa)
}

/// `r · d_H(c, ca)` of eq. (8) by Prop 6.1, in interval arithmetic: the unit
/// arc between the normals `n0`, `n1` (enclosures of the true unit normals),
/// half-angle `α` with `cos α = √((1 + n0·n1)/2)`, `sin α = √((1 − n0·n1)/2)`,
/// and the pair's `κ`. An upper end of the closed form; `None` when `κ` or the
/// angle is outside Prop 6.1's range (`κ ∈ [1/2, 2]`, `0 < 2α < π`) or a sign
/// is undecided. For a straight segment (`n0 = n1`) the arc is a point: 0.
///
/// Prop 6.1 equals the Hausdorff distance under the sector condition decided
/// per instance in `proofs/000-prop-6.1.md`; the driver also certifies the
/// offset itself, so nothing rests on this figure.
pub fn arc_term(n0: &V2<Interval>, n1: &V2<Interval>, kappa: f64, r: f64) -> Option<f64> {
    let c = n0.dot(n1);
    if c.inf() >= 1.0 {
        return Some(0.0);
    }
    let one = Interval::try_from((1.0, 1.0)).ok()?;
    let half = Interval::try_from((0.5, 0.5)).ok()?;
    let cos_a = ScalarSqrt::sqrt(&((one + c) * half))?;
    let sin_a = ScalarSqrt::sqrt(&((one - c) * half))?;
    let k = Interval::try_from((kappa, kappa)).ok()?;
    let arc = ArcApprox::new(cos_a, sin_a, k).ok()?;
    let dist = arc.prop_6_1_distance()?;
    let rr = Interval::try_from((r.abs(), r.abs())).ok()?;
    let v = (dist * rr).sup();
    v.is_finite().then_some(v)
}

/// Seed 000 eq. (8): `d_H(p, pa) + |r| d_H(c, ca)` from a certified upper bound of
/// `d_H(p, pa)` and [`arc_term`].
pub fn paper_error(dh_p_pa: f64, arc: f64) -> f64 {
    let s = Interval::try_from((dh_p_pa, dh_p_pa)).ok();
    let a = Interval::try_from((arc, arc)).ok();
    match (s, a) {
        (Some(s), Some(a)) => (s + a).sup(),
        _ => f64::INFINITY,
    }
}

/// Seed 000 §5's subdivision rules for an LN-pair span that missed the
/// tolerance: where to split it. Every rule is a float heuristic (any split is
/// sound: the halves are certified afresh); the split parameter is rounded to
/// a multiple of `2⁻²⁰` in `[1/8, 7/8]` of the span, so that the exact pieces
/// stay small and the recursion always makes progress.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Default)]
pub enum Subdivision {
    /// (a) where the tangent bisects the end directions,
    /// `arg p′(t) = (arg p′(t₀) + arg p′(t₁))/2` ([`mid_angle_param`]).
    #[default]
    MidAngle,
    /// (b) where the tangent is parallel to the approximant's chord,
    /// `arg p′(t) = arg(p(t₁) − p(t₀) + q(s₁) − q(s₀))` ([`chord_param`]).
    Chord,
    /// (c) the angles where `d_H(p, pa)` and `d_H(q, qa)` occur, weighted by
    /// the two distances ([`weighted_param`]); the rule the paper used for the
    /// font 'H'.
    Weighted,
}

impl Subdivision {
    /// The rule's letter in seed 000 §5: `a`, `b` or `c`.
    pub fn name(self) -> &'static str {
        match self {
            Subdivision::MidAngle => "a",
            Subdivision::Chord => "b",
            Subdivision::Weighted => "c",
        }
    }
}

fn unit(v: &V2<f64>) -> V2<f64> {
    let l = v.norm2().sqrt();
    V2::new(v.x / l, v.y / l)
}

/// The parameter in `[0, 1]` where `x′(t)` is parallel to `dir` (either
/// orientation), by bisection on `x′(t) × dir`; `None` when the sign does not
/// change across the span (or a value is not finite). Rounded as
/// [`Subdivision`] says.
pub fn angle_param(x: &Bezier<f64>, dir: &V2<f64>) -> Option<f64> {
    let h = x.hodograph();
    let f = |t: f64| h.eval(&t).cross(dir);
    let (fa, fb) = (f(0.0), f(1.0));
    if !(fa.is_finite() && fb.is_finite()) || fa * fb >= 0.0 {
        return None;
    }
    Some(round_split(bisect(f, 0.0, 1.0, fa)))
}

/// 60 bisection steps on `[a, b]` towards a sign change of `f` (`fa = f(a)`):
/// the midpoint of the last interval.
fn bisect(f: impl Fn(f64) -> f64, mut a: f64, mut b: f64, fa: f64) -> f64 {
    for _ in 0..60 {
        let m = 0.5 * (a + b);
        if f(m) * fa > 0.0 {
            a = m;
        } else {
            b = m;
        }
    }
    0.5 * (a + b)
}

/// `v` turned by the angle `a`.
fn rotate(v: &V2<f64>, a: f64) -> V2<f64> {
    let (cos, sin) = (a.cos(), a.sin());
    V2::new(v.x * cos - v.y * sin, v.x * sin + v.y * cos)
}

fn round_split(t: f64) -> f64 {
    let t = t.clamp(0.125, 0.875);
    (t * 1048576.0).round() / 1048576.0
}

/// Subdivision point (a) of seed 000 §5: the parameter where the tangent
/// direction bisects the end directions, `arg p′(t) = (arg p′(0) + arg p′(1))/2`
/// ([`angle_param`]); `1/2` when the sign does not change.
pub fn mid_angle_param(x: &Bezier<f64>) -> f64 {
    let hp = x.hodograph().points().to_vec();
    let dir = unit(&unit(&hp[0]).add(&unit(&hp[hp.len() - 1])));
    angle_param(x, &dir).unwrap_or(0.5)
}

/// Subdivision point (b) of seed 000 §5: where the tangent of `x` is parallel
/// to the chord of the approximant `pa + qa` (`p(t₁) − p(t₀) + q(s₁) − q(s₀)`,
/// the sum of the chords of the curve and of its pen or offset-circle
/// segment); rule (a) when that chord is zero or no tangent is parallel to it.
pub fn chord_param(x: &Bezier<f64>, pair: &LnPairPiece) -> f64 {
    let p = pair.offset.points();
    let chord = p[p.len() - 1].sub(&p[0]);
    let n2 = chord.norm2();
    if n2.is_nan() || n2 <= 0.0 {
        return mid_angle_param(x);
    }
    angle_param(x, &chord).unwrap_or_else(|| mid_angle_param(x))
}

/// Samples of the one-sided distance from `pts` to the curve `b`: the largest
/// distance from a point of `pts` to the polygon through 129 points of `b`,
/// and its index. A float estimate (a heuristic for where to split).
fn farthest(pts: &[V2<f64>], b: &Bezier<f64>) -> (f64, usize) {
    let poly: Vec<V2<f64>> = (0..=128).map(|j| b.eval(&(j as f64 / 128.0))).collect();
    let dist = |p: &V2<f64>| {
        poly.windows(2)
            .map(|w| {
                let e = w[1].sub(&w[0]);
                let l2 = e.norm2();
                let s = if l2 > 0.0 {
                    (p.sub(&w[0]).dot(&e) / l2).clamp(0.0, 1.0)
                } else {
                    0.0
                };
                p.sub(&w[0].add(&e.scale(&s))).norm2()
            })
            .fold(f64::INFINITY, f64::min)
            .sqrt()
    };
    pts.iter()
        .enumerate()
        .map(|(i, p)| (dist(p), i))
        .fold((0.0, 0), |m, d| if d.0 > m.0 { d } else { m })
}

/// Subdivision point (c) of seed 000 §5, the paper's rule for the font 'H':
/// the tangent angle `(d_p θ(t_p) + d_q θ(t_q)) / (d_p + d_q)`, where `d_p`
/// is the distance from `p` to `pa` attained at `t_p`, `d_q` the distance from
/// the pen (or offset-circle) segment `q` to `qa` attained at the pen point
/// compatible with `t_q`, and `θ(t)` the angle of `p′(t)` measured from
/// `p′(0)`. `q(t)` is the exact pen point compatible with `x(t)` (`d N(t)` for
/// an offset). The distances are float estimates over 33 samples of `p` and
/// `q` (one direction), a heuristic; rule (a) when both are zero.
pub fn weighted_param(
    x: &Bezier<f64>,
    pair: &LnPairPiece,
    q: &dyn Fn(f64) -> Option<V2<f64>>,
) -> f64 {
    let ts: Vec<f64> = (0..=32).map(|k| k as f64 / 32.0).collect();
    let ps: Vec<V2<f64>> = ts.iter().map(|t| x.eval(t)).collect();
    let Some(qs) = ts.iter().map(|t| q(*t)).collect::<Option<Vec<_>>>() else {
        return mid_angle_param(x);
    };
    let (dp, ip) = farthest(&ps, &pair.pa);
    let (dq, iq) = farthest(&qs, &pair.ca);
    let w = dp + dq;
    if !(w > 0.0 && w.is_finite()) {
        return mid_angle_param(x);
    }
    let h = x.hodograph();
    let h0 = unit(&h.eval(&0.0));
    let theta = |t: f64| {
        let v = h.eval(&t);
        h0.cross(&v).atan2(h0.dot(&v))
    };
    let target = (dp * theta(ts[ip]) + dq * theta(ts[iq])) / w;
    let dir = rotate(&h0, target);
    angle_param(x, &dir).unwrap_or_else(|| mid_angle_param(x))
}

const N: usize = 256;

/// The hodograph at `N + 1` equally spaced parameters and the cumulative
/// signed turn of `x′` at each (floats); `None` when `x′` vanishes or is not
/// finite at a sample.
fn turn_samples(x: &Bezier<f64>) -> Option<(Vec<V2<f64>>, Vec<f64>)> {
    let h = x.hodograph();
    let vs: Vec<V2<f64>> = (0..=N).map(|j| h.eval(&(j as f64 / N as f64))).collect();
    if vs
        .iter()
        .any(|v| !(v.norm2() > 0.0 && v.norm2().is_finite()))
    {
        return None;
    }
    let mut cum = vec![0.0f64];
    for w in vs.windows(2) {
        let last = cum[cum.len() - 1];
        cum.push(last + w[0].cross(&w[1]).atan2(w[0].dot(&w[1])));
    }
    Some((vs, cum))
}

/// The signed total turn `arg x′(1) − arg x′(0)` of a span without
/// inflections, summed over 256 samples of the hodograph (a float estimate).
pub fn total_turn(x: &Bezier<f64>) -> Option<f64> {
    turn_samples(x).map(|(_, c)| c[N])
}

/// Seed 000 §5's k-piece split of a convex span (no inflection) whose Gauss
/// map is longer than `max_turn`: `k` the smallest integer with
/// `Δ/k < max_turn` (`Δ` the total turn of `x′`), and the split parameters
/// `tᵢ` with `arg x′(tᵢ) = arg x′(0) + (i/k) Δ`, `i = 1 … k − 1`, in `(0, 1)`
/// (floats: a heuristic; the spans are certified afterwards). The turn is
/// summed over 256 samples of the hodograph. Empty when `Δ < max_turn` or a
/// value is not finite.
pub fn k_piece_split(x: &Bezier<f64>, max_turn: f64) -> Vec<f64> {
    let h = x.hodograph();
    let Some((vs, cum)) = turn_samples(x) else {
        return Vec::new();
    };
    let total = cum[N];
    if !total.is_finite() || max_turn.is_nan() || total.abs() < max_turn {
        return Vec::new();
    }
    let k = (total.abs() / max_turn).floor() as usize + 1;
    let mut out = Vec::new();
    for i in 1..k {
        let target = total * i as f64 / k as f64;
        // the sample cell where the cumulative turn passes the target
        let Some(j) = (0..N).find(|&j| (cum[j] - target) * (cum[j + 1] - target) <= 0.0) else {
            continue;
        };
        // inside the cell the turn is below π: bisect on the angle from vs[j]
        let rest = target - cum[j];
        let dir = rotate(&vs[j], rest);
        let f = |t: f64| h.eval(&t).cross(&dir);
        let (a, b) = (j as f64 / N as f64, (j + 1) as f64 / N as f64);
        let fa = f(a);
        let mid = if fa * f(b) < 0.0 {
            bisect(f, a, b, fa)
        } else {
            0.5 * (a + b)
        };
        let t = (mid * 1048576.0).round() / 1048576.0;
        if t > 0.0 && t < 1.0 && out.last().is_none_or(|l| t > *l) {
            out.push(t);
        }
    }
    out
}
