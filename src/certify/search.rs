//! Certified bounds on one-sided Hausdorff distances by interval branch and bound.
//!
//! For shapes `A`, `B` with parametrised pieces, `h(A, B) = sup_{a∈A} dist(a, B)`.
//!
//! **Upper bound over a parameter box `S` of a piece of `A`.** Any function `τ`
//! from `S` into (true) parameters of a piece of `B` gives
//! `dist(A(s), B) ≤ |A(s) − B(τ(s))|`. The search takes `τ(s) = t* + k (s − s_c)`,
//! `s_c` the centre of `S`, `t*` a float foot point of `A(s_c)` on `B` and `k` the
//! float slope of the foot point (implicit function theorem); `t*`, `k` are just
//! numbers, their quality affects tightness, never soundness. With
//! `g(s) = |A(s) − B(τ(s))|²` and Taylor's theorem,
//! `sup_S g ≤ g(s_c) + |g′(s_c)| w/2 + max(0, sup_S g″) w²/8` (`w` the width of `S`),
//! where `g(s_c), g′(s_c)` are enclosed by a point [`Jet`] and `sup_S g″` by a jet over
//! the box, all in outward-rounded interval arithmetic; the naive enclosure
//! `sup g(S)` is used when smaller. Over the box, `g″ = 2(|D′|² + D·D″)` is
//! evaluated from `D = A − B∘τ` and `D′` enclosed twice — directly, and by the
//! mean-value forms `D(s_c) + D′(S)(S − s_c)`, `D′(s_c) + D″(S)(S − s_c)` — keeping
//! the meet: the direct enclosure of `D` is as wide as the curves move over the box,
//! the mean-value one as small as the distance when the foot map follows `B`
//! (4× fewer boxes on the offsets of the test cubic). The bound is second order in `w` where the
//! distance function is flat, i.e. near its maximum, which is where refinement
//! happens.
//!
//! **Lower bound.** `h(A, B) ≥ dist(a, B)` for every `a ∈ A`. The witness `a = A(s)`
//! (at a dyadic `s` of the inner domain, so a true point of `A`) is enclosed by a
//! box `P`; `dist(P, B)` is bounded below by branch and bound over the outer
//! parameter domains of `B`: each parameter box `T` maps into `B(t_c) + B′(T)(T − t_c)`
//! (mean value form) intersected with the natural enclosure `B(T)`, boxes farther than
//! the best true distance found are pruned.
//!
//! **Search.** Boxes of `A` sit in a max-heap by upper bound; the top box is split
//! (and its centre tried as a witness) until `hi − lo ≤ max(rel · hi, abs)`, a
//! tolerance is decided, or the budget runs out. The final boxes cover every
//! outer domain of `A`: they are the proof data of a certificate.

use super::jet::{dist2, Jet, JetPoint};
use super::piece::Piece;
use crate::scalar::{Interval, Scalar};
use crate::Tolerance;
use std::cmp::Ordering;
use std::collections::BinaryHeap;

/// Search settings.
#[derive(Clone, Debug, PartialEq)]
pub struct Config {
    /// Stop when `hi − lo ≤ rel · hi` (default `1e-3`).
    pub rel: f64,
    /// Absolute gap that also stops the search (default `0`: automatic,
    /// `1e-10 · (1 + coordinate scale)`, so that coinciding shapes terminate: where
    /// the distance is 0 everywhere the upper bounds shrink only like `w²`).
    pub abs: f64,
    /// Maximum number of parameter boxes per direction (default 200 000).
    pub max_boxes: usize,
    /// A claimed tolerance: the search then runs until it is decided (`hi ≤ tol`
    /// or `lo > tol`, compared with [`Tolerance::value`], the largest float ≤
    /// the exact tolerance), down to a relative gap of `1e-12`, instead of
    /// stopping at `rel`.
    pub tol: Option<Tolerance>,
    /// With `tol`: once the first direction refutes the tolerance, skip the second
    /// (its bounds are reported as `[0, ∞]`) instead of bounding it coarsely.
    /// For callers that only need the verdict (the offset driver splits a refuted span).
    pub verdict_only: bool,
    /// For one piece against one piece: try the parametric proof
    /// ([`super::Parametric`]) first — one cover for both directions, lower bounds
    /// from witness points of one side — and run the search only if it does not
    /// reach the goal (default true).
    /// Its result has no box covers, so a [`super::Certificate`] cannot be
    /// built from it: set `false` when one is wanted.
    pub parametric: bool,
    /// For a circular arc of sweep `≤ π` against a chain of pieces running
    /// from one end ray to the other inside its sector: try the radial proof
    /// first (`d_H` is the curve's largest radial distance to the circle, see
    /// [`super::RadialProof`]), tens of µs where it applies, its halvings
    /// limited by `max_boxes` (default true; off with `parametric: false`). A certificate built from its result is proven
    /// again by the other proofs ([`super::Certificate::new`]).
    pub radial: bool,
}

impl Default for Config {
    fn default() -> Self {
        Config {
            rel: 1e-3,
            abs: 0.0,
            max_boxes: 200_000,
            tol: None,
            verdict_only: false,
            parametric: true,
            radial: true,
        }
    }
}

/// One box of the final cover of a piece of `A`, with the proof data of its bound.
#[derive(Clone, Debug, PartialEq)]
pub struct CoverBox {
    /// Index of the piece of `A`.
    pub piece: usize,
    /// The parameter box `[s0, s1]` (dyadic floats, exact).
    pub s: (f64, f64),
    /// Index of the piece of `B` the foot map goes to.
    pub target: usize,
    /// Foot map `τ(s) = t + k (s − s_c)`, `s_c = (s0 + s1)/2` (computed in f64, exact for dyadics).
    pub t: f64,
    /// Slope `k` of the foot map `τ(s) = t + k (s − s_c)`.
    pub k: f64,
    /// Certified `sup_{s ∈ [s0, s1]} dist(A(s), B)` upper bound.
    pub bound: f64,
}

/// Certified bounds on one one-sided distance `h(A, B)`.
#[derive(Clone, Debug, PartialEq)]
pub struct OneSided {
    /// `lo ≤ h(A, B) ≤ hi`.
    pub lo: f64,
    /// Certified upper bound on `h(A, B)`.
    pub hi: f64,
    /// The witness of `lo`: piece and parameter of `A`.
    pub witness: Option<(usize, f64)>,
    /// The final cover, sorted by piece and parameter.
    pub boxes: Vec<CoverBox>,
    /// Boxes evaluated in all.
    pub evaluated: usize,
    /// True if the budget or the float resolution stopped the search before its
    /// goal; the bounds are still sound.
    pub incomplete: bool,
}

#[derive(Clone, Debug)]
struct HeapBox {
    b: CoverBox,
    splittable: bool,
}

/// A max-heap entry ordered by an upper bound (`total_cmp`): the box with the
/// largest bound is refined first, by the search and by the parametric proof.
#[derive(Clone, Debug)]
pub(crate) struct ByBound<T> {
    pub bound: f64,
    pub item: T,
}

impl<T> ByBound<T> {
    pub(crate) fn new(bound: f64, item: T) -> Self {
        ByBound { bound, item }
    }
}

impl<T> std::ops::Deref for ByBound<T> {
    type Target = T;
    fn deref(&self) -> &T {
        &self.item
    }
}

impl<T> PartialEq for ByBound<T> {
    fn eq(&self, o: &Self) -> bool {
        self.bound.total_cmp(&o.bound) == Ordering::Equal
    }
}
impl<T> Eq for ByBound<T> {}
impl<T> PartialOrd for ByBound<T> {
    fn partial_cmp(&self, o: &Self) -> Option<Ordering> {
        Some(self.cmp(o))
    }
}
impl<T> Ord for ByBound<T> {
    fn cmp(&self, o: &Self) -> Ordering {
        self.bound.total_cmp(&o.bound)
    }
}

/// `n` consecutive boxes covering `[lo, hi]` exactly (the ends are the domain's own).
fn split_domain((lo, hi): (f64, f64), n: usize) -> Vec<(f64, f64)> {
    let at = |k: usize| match k {
        0 => lo,
        k if k == n => hi,
        k => lo + (hi - lo) * (k as f64 / n as f64),
    };
    (0..n).map(|k| (at(k), at(k + 1))).collect()
}

pub(crate) fn point_iv(x: f64) -> Interval {
    Interval::try_from((x, x)).unwrap_or(Interval::ENTIRE)
}

fn jet_f64(p: &Piece, t: f64) -> Option<JetPoint<f64>> {
    p.fl.eval(Jet::variable(t))
}

/// The float point of a piece at `t`.
pub(crate) fn point_f64(p: &Piece, t: f64) -> Option<(f64, f64)> {
    let (x, y) = p.fl.point(t)?;
    (x.is_finite() && y.is_finite()).then_some((x, y))
}

/// `|q − B(t)|²` in floats (`None` where the piece is undefined).
fn dist2_f64(p: &Piece, q: (f64, f64), t: f64) -> Option<f64> {
    p.fl.point(t)
        .map(|(x, y)| (x - q.0).powi(2) + (y - q.1).powi(2))
}

/// Newton's float foot point of `q` on `piece` from `guess` (kept in the inner
/// domain; `guess` itself when Newton cannot start).
pub(crate) fn foot_newton(piece: &Piece, q: (f64, f64), guess: f64) -> f64 {
    let d2 = |t: f64| dist2_f64(piece, q, t);
    let Some(mut cur) = d2(guess).filter(|v| v.is_finite()).map(|v| (guess, v)) else {
        return guess;
    };
    // Newton converges only linearly where the piece is nearly stationary (an
    // offset's cusp): run it again while it still improves.
    for _ in 0..8 {
        let next = newton_foot(piece, q, cur, &d2);
        if next.1.is_nan() || cur.1.is_nan() || next.1 >= cur.1 {
            break;
        }
        cur = next;
    }
    cur.0
}

/// The float slope `ds/dt` of the foot point `s` of `B(t)` on `A`:
/// `F(t, s) = (B(t) − A(s))·A′(s) = 0` gives `ds/dt = −F_t/F_s` (`None` where
/// `F_s ≥ 0`, i.e. not a strict local minimum).
pub(crate) fn foot_slope_of(b: &Piece, t: f64, a: &Piece, s: f64) -> Option<f64> {
    let (bx, by) = jet_f64(b, t)?;
    let (ax, ay) = jet_f64(a, s)?;
    let (ex, ey) = (bx.v - ax.v, by.v - ay.v);
    let ft = bx.d * ax.d + by.d * ay.d;
    let fs = -(ax.d * ax.d + ay.d * ay.d) + ex * ax.dd + ey * ay.dd;
    let k = -ft / fs;
    (fs < 0.0 && k.is_finite()).then_some(k)
}

/// Float foot point of `q` on one piece: every local minimum of a sample
/// (at most [`FOOT_CANDIDATES`], lowest first) refined by Newton on
/// `φ(t) = |q − B(t)|²`, kept in the inner domain; the best wins. Several
/// candidates matter where the piece passes close to `q` twice (an offset's
/// swallowtail): Newton from the best sample alone can settle on the wrong
/// branch, and no box bound around a wrong foot point converges.
/// Returns `(t, distance)`.
pub(crate) fn foot_f64(piece: &Piece, q: (f64, f64), samples: usize) -> Option<(f64, f64)> {
    let (lo, hi) = piece.inner;
    let d2 = |t: f64| dist2_f64(piece, q, t);
    let vals: Vec<(f64, f64)> = (0..=samples)
        .filter_map(|i| {
            let t = lo + (hi - lo) * (i as f64 / samples as f64);
            d2(t).filter(|v| v.is_finite()).map(|v| (t, v))
        })
        .collect();
    let mut cands: Vec<(f64, f64)> = vals
        .iter()
        .enumerate()
        .filter(|(i, (_, v))| {
            (*i == 0 || vals[i - 1].1 >= *v) && (*i + 1 == vals.len() || vals[i + 1].1 >= *v)
        })
        .map(|(_, c)| *c)
        .collect();
    cands.sort_by(|a, b| a.1.total_cmp(&b.1));
    cands.truncate(FOOT_CANDIDATES);
    // Re-sample the bracket of each candidate finely before Newton: near a cusp
    // of the piece (an offset's swallowtail) φ is not convex between samples.
    let h = (hi - lo) / samples as f64;
    cands
        .into_iter()
        .map(|c| {
            let start = (1..FOOT_REFINE)
                .map(|k| c.0 - h + 2.0 * h * (k as f64 / FOOT_REFINE as f64))
                .filter(|t| *t >= lo && *t <= hi)
                .filter_map(|t| d2(t).filter(|v| v.is_finite()).map(|v| (t, v)))
                .fold(c, |a, b| if b.1 < a.1 { b } else { a });
            newton_foot(piece, q, start, &d2)
        })
        .min_by(|a, b| a.1.total_cmp(&b.1))
        .map(|(t, v)| (t, v.sqrt()))
}

/// An **unproven** float estimate of `h(A, B)`: the largest float distance from
/// `samples + 1` points of each piece of `A` to their float foot points on `B`.
/// A sampled maximum, not a bound (it may be below the true distance); for
/// `--no-certify` comparisons only.
pub(crate) fn sampled_one_sided(a: &[Piece], b: &[Piece], samples: usize) -> f64 {
    let mut worst = 0.0f64;
    for p in a {
        let (lo, hi) = p.inner;
        for i in 0..=samples {
            let s = lo + (hi - lo) * (i as f64 / samples as f64);
            let Some((x, y)) = jet_f64(p, s) else {
                return f64::INFINITY;
            };
            let d = b
                .iter()
                .filter_map(|q| foot_f64(q, (x.v, y.v), 16).map(|r| r.1))
                .fold(f64::INFINITY, f64::min);
            worst = worst.max(d);
        }
    }
    worst
}

/// Local minima of the sample refined by [`foot_f64`].
const FOOT_CANDIDATES: usize = 4;
/// Sub-samples of each candidate's bracket `[t − h, t + h]`.
const FOOT_REFINE: usize = 8;

fn newton_foot(
    piece: &Piece,
    q: (f64, f64),
    (mut t, mut v): (f64, f64),
    d2: &dyn Fn(f64) -> Option<f64>,
) -> (f64, f64) {
    let (lo, hi) = piece.inner;
    for _ in 0..12 {
        let Some((x, y)) = jet_f64(piece, t) else {
            break;
        };
        let (ex, ey) = (x.v - q.0, y.v - q.1);
        let g = ex * x.d + ey * y.d;
        let h = x.d * x.d + y.d * y.d + ex * x.dd + ey * y.dd;
        if h.is_nan() || h <= 0.0 {
            break;
        }
        // Newton with backtracking: halve the step until φ does not grow.
        let mut step = g / h;
        let mut moved = false;
        for _ in 0..8 {
            let tn = (t - step).clamp(lo, hi);
            if let Some(vn) = d2(tn).filter(|vn| *vn <= v) {
                let done = (tn - t).abs() <= 1e-16 * (1.0 + t.abs());
                t = tn;
                v = vn;
                moved = !done;
                break;
            }
            step *= 0.5;
        }
        if !moved {
            break;
        }
    }
    (t, v)
}

/// A rough lower estimate of `dist(q, piece)`: distance to the centre of nine
/// samples minus twice their radius (0 when a sample fails).
fn coarse_lower(p: &Piece, q: (f64, f64)) -> f64 {
    let (lo, hi) = p.inner;
    let mut pts = [(0.0, 0.0); 9];
    for (k, slot) in pts.iter_mut().enumerate() {
        match p.fl.point(lo + (hi - lo) * (k as f64 / 8.0)) {
            Some((x, y)) if x.is_finite() && y.is_finite() => *slot = (x, y),
            _ => return 0.0,
        }
    }
    let c = (
        pts.iter().map(|p| p.0).sum::<f64>() / 9.0,
        pts.iter().map(|p| p.1).sum::<f64>() / 9.0,
    );
    let r = pts
        .iter()
        .map(|p| ((p.0 - c.0).powi(2) + (p.1 - c.1).powi(2)).sqrt())
        .fold(0.0, f64::max);
    (((q.0 - c.0).powi(2) + (q.1 - c.1).powi(2)).sqrt() - 2.0 * r).max(0.0)
}

/// The foot map `(target, t, k)` for the box centred at `s_c` of piece `a`.
fn foot_map(a: &Piece, s_c: f64, b: &[Piece], s_half: f64) -> Option<(usize, f64, f64)> {
    let (ax, ay) = jet_f64(a, s_c)?;
    let q = (ax.v, ay.v);
    let samples = 32;
    // Visit the target pieces nearest first and skip those that a coarse sample
    // places (with a margin of twice their sampled radius) beyond the best foot
    // found so far. Only tightness depends on the foot point, never soundness.
    let mut order: Vec<(usize, f64)> = b
        .iter()
        .enumerate()
        .map(|(j, p)| (j, if b.len() > 2 { coarse_lower(p, q) } else { 0.0 }))
        .collect();
    order.sort_by(|x, y| x.1.total_cmp(&y.1));
    let mut found: Option<(usize, f64, f64)> = None;
    for (j, est) in order {
        if found.is_some_and(|f| est >= f.2) {
            break;
        }
        if let Some((t, d)) = foot_f64(&b[j], q, samples) {
            if found.is_none_or(|f| d < f.2) {
                found = Some((j, t, d));
            }
        }
    }
    let (j, t, _) = found?;
    let piece = &b[j];
    let (bx, by) = jet_f64(piece, t)?;
    // F(s, t) = (A(s) − B(t))·B′(t) = 0 ⇒ k = −F_s/F_t.
    let (ex, ey) = (ax.v - bx.v, ay.v - by.v);
    let fs = ax.d * bx.d + ay.d * by.d;
    let ft = -(bx.d * bx.d + by.d * by.d) + ex * bx.dd + ey * by.dd;
    let mut k = if ft < 0.0 { -fs / ft } else { 0.0 };
    let (lo, hi) = piece.inner;
    if !k.is_finite() || t - k.abs() * s_half < lo || t + k.abs() * s_half > hi {
        k = 0.0;
    }
    Some((j, t, k))
}

/// The source's jets on one box: over the box and at its centre (shared by
/// every foot map tried on the box).
pub(crate) struct SourceJets {
    sb: Interval,
    sc: Interval,
    over: JetPoint<Interval>,
    centre: JetPoint<Interval>,
}

impl SourceJets {
    /// `None` if the piece cannot be evaluated on the box.
    pub(crate) fn new(a: &Piece, s: (f64, f64)) -> Option<SourceJets> {
        let sb = Interval::try_from((s.0, s.1)).ok()?;
        let sc = point_iv(0.5 * (s.0 + s.1));
        Some(SourceJets {
            sb,
            sc,
            over: a.iv.eval(Jet::variable(sb))?,
            centre: a.iv.eval(Jet::variable(sc))?,
        })
    }
}

/// Certified upper bound on `sup_{s∈[s0,s1]} dist(A(s), B(τ(s)))` with `τ(s) = t + k(s − s_c)`,
/// from the source's jets on the box. `None` if `τ` leaves the inner domain of the
/// target or an evaluation is undefined.
pub(crate) fn box_bound_from(src: &SourceJets, b: &Piece, t: f64, k: f64) -> Option<f64> {
    let (sb, sc) = (src.sb, src.sc);
    let (ti, ki) = (point_iv(t), point_iv(k));
    let tau_box = ti + ki * (sb - sc);
    if !(tau_box.inf() >= b.inner.0 && tau_box.sup() <= b.inner.1) {
        return None;
    }
    // Over the box.
    let pb = b.iv.eval(Jet::affine(tau_box, ki))?;
    // At the centre (the same point when the foot map is constant).
    let pb_c = if k == 0.0 {
        pb
    } else {
        b.iv.eval(Jet::affine(ti, ki))?
    };
    difference_bound(&src.over, &src.centre, &pb, &pb_c, src.sb - src.sc)
}

/// Certified upper bound on `sup_S |D|`, `D(s) = P(s) − Q(s)`, from jets of `P`
/// and `Q` over the box `S` (`p_over`, `q_over`) and at its centre `s_c`
/// (`p_c`, `q_c`); `w ⊇ S − s_c`. Both must be `C²` on `S`. The second-order
/// Taylor bound of `g = |D|²` with the mean-value-form meets described in the
/// module docs; `None` if the bound is not finite.
pub(crate) fn difference_bound(
    p_over: &JetPoint<Interval>,
    p_c: &JetPoint<Interval>,
    q_over: &JetPoint<Interval>,
    q_c: &JetPoint<Interval>,
    w: Interval,
) -> Option<f64> {
    let g_c = dist2(p_c, q_c);
    // The difference D over the box. Its value and slope are also enclosed by
    // mean-value forms around the centre, D(c) + D′(S)(S − c) and
    // D′(c) + D″(S)(S − c) (sound by the mean value theorem), and the tighter of
    // the two enclosures is kept: the separate enclosures of P(S) and Q(S) are as
    // wide as the curves move over the box, while D itself stays as small as the
    // distance when the map between the parameters follows the curves.
    let tighten = |over: Jet<Interval>, centre: Jet<Interval>| {
        let v = over.v.intersection(centre.v + over.d * w);
        let d = over.d.intersection(centre.d + over.dd * w);
        // both enclose the same set: an empty meet can only come from a NaN
        if v.is_empty() || d.is_empty() {
            over
        } else {
            Jet { v, d, dd: over.dd }
        }
    };
    let dx = tighten(p_over.0 - q_over.0, p_c.0 - q_c.0);
    let dy = tighten(p_over.1 - q_over.1, p_c.1 - q_c.1);
    // g = |D|² over the box: g = Dx² + Dy², g″ = 2 (Dx′² + Dy′² + Dx Dx″ + Dy Dy″)
    let two = Interval::from_frac(2, 1);
    let g_box_v = dx.v.sqr() + dy.v.sqr();
    let g_box_dd = two * (dx.d.sqr() + dy.d.sqr() + dx.v * dx.dd + dy.v * dy.dd);
    let half_w = w.mag();
    let hw = point_iv(half_w);
    let dd_pos = Interval::try_from((0.0, g_box_dd.sup().max(0.0))).ok()?;
    let taylor = g_c.v + g_c.d.abs() * hw + dd_pos * hw * hw * Interval::from_frac(1, 2);
    let g_sup = taylor.sup().min(g_box_v.sup());
    if !g_sup.is_finite() {
        return None;
    }
    let g = Interval::try_from((0.0, g_sup.max(0.0))).ok()?;
    Some(g.sqrt().sup())
}

fn ranked(h: HeapBox) -> ByBound<HeapBox> {
    ByBound::new(h.b.bound, h)
}

fn make_box(a: &[Piece], i: usize, s: (f64, f64), b: &[Piece]) -> HeapBox {
    let s_c = 0.5 * (s.0 + s.1);
    let splittable = s_c > s.0 && s_c < s.1;
    let mut cb = CoverBox {
        piece: i,
        s,
        target: 0,
        t: b[0].inner.0,
        k: 0.0,
        bound: f64::INFINITY,
    };
    let src = SourceJets::new(&a[i], s);
    if let (Some(src), Some((j, t, k))) = (&src, foot_map(&a[i], s_c, b, 0.5 * (s.1 - s.0))) {
        let with_k = box_bound_from(src, &b[j], t, k);
        let without = if k != 0.0 {
            box_bound_from(src, &b[j], t, 0.0)
        } else {
            None
        };
        let (bound, kk) = match (with_k, without) {
            (Some(x), Some(y)) if y < x => (y, 0.0),
            (Some(x), _) => (x, k),
            (None, Some(y)) => (y, 0.0),
            (None, None) => (f64::INFINITY, k),
        };
        cb = CoverBox {
            piece: i,
            s,
            target: j,
            t,
            k: kk,
            bound,
        };
    }
    HeapBox { b: cb, splittable }
}

/// A certified lower bound on `dist(P, B)` for the box `P` (`|P − B| ≥` result),
/// refined until within the relative gap `rel` or the budget.
pub(crate) fn lower_distance(p: (Interval, Interval), b: &[Piece], rel: f64, budget: usize) -> f64 {
    #[derive(PartialEq)]
    struct TBox {
        lower: f64,
        j: usize,
        t: (f64, f64),
    }
    impl Eq for TBox {}
    impl PartialOrd for TBox {
        fn partial_cmp(&self, o: &Self) -> Option<Ordering> {
            Some(self.cmp(o))
        }
    }
    impl Ord for TBox {
        fn cmp(&self, o: &Self) -> Ordering {
            o.lower.total_cmp(&self.lower) // min-heap
        }
    }
    let q = (p.0.mid(), p.1.mid());
    // Upper bound from true points (inner domain).
    let point_dist = |j: usize, t: f64| -> Option<f64> {
        let (x, y) = b[j].iv.eval(Jet::constant(point_iv(t)))?;
        let (dx, dy) = (x.v - p.0, y.v - p.1);
        Some((dx * dx + dy * dy).sqrt().sup())
    };
    let mut best = f64::INFINITY;
    for (j, piece) in b.iter().enumerate() {
        if let Some((t, _)) = foot_f64(piece, q, 32) {
            if let Some(d) = point_dist(j, t) {
                best = best.min(d);
            }
        }
    }
    let box_lower = |j: usize, t: (f64, f64)| -> f64 {
        let Ok(tb) = Interval::try_from((t.0, t.1)) else {
            return 0.0;
        };
        let tc = point_iv(0.5 * (t.0 + t.1));
        let (Some(over), Some(at_c)) = (
            b[j].iv.eval(Jet::variable(tb)),
            b[j].iv.eval(Jet::variable(tc)),
        ) else {
            return 0.0;
        };
        let mv_x = at_c.0.v + over.0.d * (tb - tc);
        let mv_y = at_c.1.v + over.1.d * (tb - tc);
        let bx = over.0.v.intersection(mv_x);
        let by = over.1.v.intersection(mv_y);
        let gap = |a: Interval, c: Interval| -> f64 {
            if a.is_empty() || c.is_empty() {
                return 0.0;
            }
            // the separation of two intervals, rounded down
            let g1 = (Interval::try_from((a.inf(), a.inf())).unwrap_or(Interval::ENTIRE)
                - Interval::try_from((c.sup(), c.sup())).unwrap_or(Interval::ENTIRE))
            .inf();
            let g2 = (Interval::try_from((c.inf(), c.inf())).unwrap_or(Interval::ENTIRE)
                - Interval::try_from((a.sup(), a.sup())).unwrap_or(Interval::ENTIRE))
            .inf();
            g1.max(g2).max(0.0)
        };
        let (gx, gy) = (point_iv(gap(p.0, bx)), point_iv(gap(p.1, by)));
        let mut d2 = (gx * gx + gy * gy).inf();
        // Second-order Taylor lower bound of φ(t) = |P − B(t)|² over T:
        // φ(t) ≥ φ(t_c) − |φ′(t_c)| w/2 − max(0, −inf φ″(T)) w²/8. Tight where the
        // distance is flat (near the foot point, or along a concentric arc).
        let pj = (Jet::constant(p.0), Jet::constant(p.1));
        let phi_box = dist2(&pj, &over);
        let phi_c = dist2(&pj, &at_c);
        let hw = point_iv((tb - tc).mag());
        let neg_dd =
            Interval::try_from((0.0, (-phi_box.dd.inf()).max(0.0))).unwrap_or(Interval::ENTIRE);
        let taylor =
            (phi_c.v - phi_c.d.abs() * hw - neg_dd * hw * hw * Interval::from_frac(1, 2)).inf();
        if taylor > d2 {
            d2 = taylor;
        }
        if d2.is_nan() {
            return 0.0;
        }
        d2.max(0.0).sqrt() * (1.0 - 4.0 * f64::EPSILON) // sqrt rounded: step down
    };
    let mut heap = BinaryHeap::new();
    for (j, piece) in b.iter().enumerate() {
        for (t0, t1) in split_domain(piece.outer, 4) {
            heap.push(TBox {
                lower: box_lower(j, (t0, t1)),
                j,
                t: (t0, t1),
            });
        }
    }
    let mut count = 0;
    while let Some(top) = heap.pop() {
        if top.lower >= best * (1.0 - rel) || count >= budget {
            return top.lower.min(best);
        }
        count += 1;
        let tm = 0.5 * (top.t.0 + top.t.1);
        if !(tm > top.t.0 && tm < top.t.1) {
            return top.lower.min(best);
        }
        let inner = b[top.j].inner;
        if tm >= inner.0 && tm <= inner.1 {
            if let Some(d) = point_dist(top.j, tm) {
                best = best.min(d);
            }
        }
        for half in [(top.t.0, tm), (tm, top.t.1)] {
            let l = box_lower(top.j, half);
            if l <= best {
                heap.push(TBox {
                    lower: l,
                    j: top.j,
                    t: half,
                });
            }
        }
    }
    // Unreachable in exact arithmetic (the box holding the nearest point is never
    // pruned); 0 is always a sound lower bound.
    0.0
}

/// `h(A, B)` bounded by branch and bound. `other` is the `(lo, hi)` of the
/// opposite direction, used only to stop early when this one no longer matters.
pub(crate) fn one_sided(
    a: &[Piece],
    b: &[Piece],
    cfg: &Config,
    abs: f64,
    other: (f64, f64),
) -> OneSided {
    let tol = cfg.tol.as_ref().map(Tolerance::value);
    let mut heap = BinaryHeap::new();
    let mut evaluated = 0usize;
    for (i, piece) in a.iter().enumerate() {
        for (s0, s1) in split_domain(piece.outer, 4) {
            heap.push(ranked(make_box(a, i, (s0, s1), b)));
            evaluated += 1;
        }
    }
    let mut lo = 0.0f64;
    let mut witness = None;
    let mut incomplete = false;
    // Witnesses. A point's float distance to `B` is cheap; its certified lower
    // bound is a branch and bound of its own. So each witness point is first
    // estimated, and only certified when it can matter: at once when its
    // estimate exceeds the tolerance (it may refute it), otherwise the best
    // pending one (largest estimate) once certifying it could close the gap,
    // and at the end.
    struct Cand {
        i: usize,
        s: f64,
        p: (Interval, Interval),
        est: f64,
    }
    let estimate = |i: usize, s: f64| -> Option<Cand> {
        let inner = a[i].inner;
        let s = s.clamp(inner.0, inner.1);
        let (x, y) = a[i].iv.eval(Jet::constant(point_iv(s)))?;
        let q = (x.v.mid(), y.v.mid());
        let est = b
            .iter()
            .filter_map(|p| foot_f64(p, q, 32).map(|r| r.1))
            .fold(f64::INFINITY, f64::min);
        Some(Cand {
            i,
            s,
            p: (x.v, y.v),
            est,
        })
    };
    let certify = |c: &Cand, lo: &mut f64, witness: &mut Option<(usize, f64)>| {
        // a witness cannot raise lo above its float distance; below the
        // absolute gap it is not worth a lower-distance search (coinciding
        // shapes would run every witness to its budget)
        if c.est <= *lo || c.est <= abs {
            return;
        }
        let l = lower_distance(c.p, b, cfg.rel * 0.25, cfg.max_boxes.clamp(16, 4_000));
        if l > *lo {
            *lo = l;
            *witness = Some((c.i, c.s));
        }
    };
    let mut pending: Option<Cand> = None;
    let offer =
        |c: Cand, lo: &mut f64, witness: &mut Option<(usize, f64)>, pending: &mut Option<Cand>| {
            if !(c.est > *lo && c.est > abs) {
                return;
            }
            if tol.is_some_and(|t| c.est > t) {
                certify(&c, lo, witness);
            } else if pending.as_ref().is_none_or(|p| c.est > p.est) {
                *pending = Some(c);
            }
        };
    // initial witnesses: the ends and centres of the pieces
    for (i, piece) in a.iter().enumerate() {
        for s in [
            piece.inner.0,
            0.5 * (piece.inner.0 + piece.inner.1),
            piece.inner.1,
        ] {
            if let Some(c) = estimate(i, s) {
                offer(c, &mut lo, &mut witness, &mut pending);
            }
        }
    }
    while let Some(top) = heap.peek() {
        let hi = top.b.bound;
        // Without a tolerance the goal is the relative gap; with one, it is the
        // verdict (refined down to a 1e-12 relative gap if need be).
        let rel = if tol.is_some() { 1e-12 } else { cfg.rel };
        let ohi = hi.max(other.1);
        let closes = |l: f64| ohi.is_finite() && ohi - l.max(other.0) <= (rel * ohi).max(abs);
        if pending.as_ref().is_some_and(|c| closes(c.est)) {
            if let Some(c) = pending.take() {
                certify(&c, &mut lo, &mut witness);
            }
        }
        // An infinite upper bound (a box whose normal could not be bounded yet) is
        // never convergence: keep splitting.
        if closes(lo) {
            break;
        }
        if let Some(tol) = tol {
            if hi <= tol || lo > tol {
                break;
            }
        }
        if hi <= other.0 {
            break; // this direction cannot raise the Hausdorff distance above the other's lower bound
        }
        if !top.splittable || evaluated >= cfg.max_boxes {
            incomplete = true;
            break;
        }
        let top = heap.pop().expect("peeked");
        let (s0, s1) = top.b.s;
        let sm = 0.5 * (s0 + s1);
        if let Some(c) = estimate(top.b.piece, sm) {
            offer(c, &mut lo, &mut witness, &mut pending);
        }
        for half in [(s0, sm), (sm, s1)] {
            heap.push(ranked(make_box(a, top.b.piece, half, b)));
            evaluated += 1;
        }
    }
    if let Some(c) = pending.take() {
        certify(&c, &mut lo, &mut witness);
    }
    let mut boxes: Vec<CoverBox> = heap.into_iter().map(|h| h.item.b).collect();
    boxes.sort_by(|x, y| x.piece.cmp(&y.piece).then(x.s.0.total_cmp(&y.s.0)));
    let hi = boxes.iter().map(|b| b.bound).fold(0.0, f64::max);
    OneSided {
        lo: lo.min(hi),
        hi,
        witness,
        boxes,
        evaluated,
        incomplete,
    }
}
