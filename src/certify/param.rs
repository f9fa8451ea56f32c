//! The parametric proof: both one-sided distances at once, through one map
//! between the parameters of two single pieces.
//!
//! **Statement.** Let `A : [a₀, a₁] → R²` and `B : [0, 1] → R²` be pieces and
//! `φ : [0, 1] → [a₀, a₁]` *any* continuous map with `φ(0) = a₀`, `φ(1) = a₁`
//! (or the reverse). Then
//!
//! ```text
//! d_H(A, B) ≤ sup_{t ∈ [0,1]} |B(t) − A(φ(t))|.
//! ```
//!
//! Every `B(t)` has the point `A(φ(t))` of `A` within that distance, and every
//! `A(s)` is some `A(φ(t))` (the intermediate value theorem: `φ` is onto), with
//! `B(t)` within it. Neither monotonicity nor the quality of `φ` matters for
//! soundness; only continuity, the end values, and `φ(t)` staying in the domain
//! of `A`.
//!
//! **The map.** Nodes `0 = t₀ < … < t_m = 1` (dyadic floats) carry values `sᵢ`
//! (float foot points of `B(tᵢ)` on `A`, Newton) and slopes `kᵢ` (implicit
//! function theorem); on `[tᵢ, tᵢ₊₁]`, `φ` is the cubic with Bernstein
//! coefficients `c = (sᵢ, sᵢ + w kᵢ/3, sᵢ₊₁ − w kᵢ₊₁/3, sᵢ₊₁)`, `w = tᵢ₊₁ − tᵢ`.
//! Neighbouring boxes share the node value exactly, so `φ` is continuous; the
//! inner coefficients are just floats. Over a box, `φ ∈ hull(c)`,
//! `φ′ ∈ (3/w) hull(Δc)`, `φ″ ∈ (6/w²) hull(Δ²c)` (Bernstein convex hulls),
//! enclosed in interval arithmetic; a box whose `hull(c)` leaves the inner
//! domain of `A` is not accepted.
//!
//! **The bound on a box** is the second-order Taylor bound of
//! `g = |B − A∘φ|²` of the branch and bound ([`super::search`]), with the same
//! mean-value-form meets: the jets of `B` over the box and at its centre, and
//! of `A` at the jets of `φ`. Because the foot map is followed to third order
//! (not linearly, as by a box of the two-directional search), boxes can be
//! wide, and one cover proves both directions.
//!
//! **Ends of `A` not exactly representable** (an arc's end parameter is only
//! enclosed): `φ` runs over the inner domain `[a₀, a₁]` of true points; the
//! points `A(s)` with `s` between `a₁` and the true end lie within
//! `sup |A′| · (outer₁ − a₁)` of `A(a₁)`, which is added to the bound (and the
//! same at `a₀`).
//!
//! The proof is used where it applies (one piece against one piece, `B` with an
//! exact parameter domain) and falls back to the two-directional search when it
//! does not decide: it never refutes (it has no lower bounds of its own).

use super::jet::Jet;
use super::piece::Piece;
use super::search::{difference_bound, foot_newton, foot_slope_of, point_iv as point, ByBound};
use crate::scalar::{Interval, Scalar};
use std::collections::BinaryHeap;

/// The narrowest box split before the path gives up (relative to `B`'s domain).
const MIN_WIDTH: f64 = 1.0 / (1u64 << 24) as f64;

/// The steepest top box split, relative to the mean slope of `φ`.
const MAX_SLOPE: f64 = 256.0;

/// One box of the parametric cover: `t` the box of `B`'s parameter, `c` the
/// Bernstein coefficients of the map `φ` on it.
#[derive(Clone, Debug, PartialEq)]
pub struct ParamBox {
    /// `[t₀, t₁]` (dyadic floats).
    pub t: (f64, f64),
    /// Bernstein coefficients of `φ` on the box; `c[0]`, `c[3]` are the node values.
    pub c: [f64; 4],
    /// Certified `sup_{t∈box} |B(t) − A(φ(t))|`.
    pub bound: f64,
}

/// What the parametric proof runs for.
#[derive(Clone, Copy, Debug, PartialEq)]
pub(crate) enum Goal {
    /// `hi ≤ tol`.
    Tol(f64),
    /// `hi − lo ≤ max(rel · hi, abs)`, `lo` from witness points of `B`.
    Gap { rel: f64, abs: f64 },
}

/// A parametric proof of `lo ≤ d_H(A, B) ≤ hi`.
#[derive(Clone, Debug, PartialEq)]
pub struct Parametric {
    /// `d_H(A, B) ≤ hi` (the largest box bound plus the end terms).
    pub hi: f64,
    /// `lo ≤ d_H(A, B)`: a certified lower bound on `dist(B(t), A)` at a
    /// witness `t` (0 when the goal was a tolerance).
    pub lo: f64,
    /// The witness parameter of `B` for `lo`.
    pub witness: Option<f64>,
    /// The cover of `[0, 1]`, in order.
    pub boxes: Vec<ParamBox>,
    /// Boxes evaluated in all.
    pub evaluated: usize,
    /// The map's source (the covered parameter) is shape `A` of
    /// [`super::hausdorff`] (else `B`); `prove` itself always maps `B`.
    pub source_a: bool,
}

struct Node {
    t: f64,
    s: f64,
    k: f64,
    /// Float distance `|B(t) − A(s)|` (the witness heuristics).
    fd: f64,
}

struct HeapBox {
    b: ParamBox,
    k: (f64, f64),
}

fn hull(xs: &[Interval]) -> Interval {
    let lo = xs.iter().map(|x| x.inf()).fold(f64::INFINITY, f64::min);
    let hi = xs.iter().map(|x| x.sup()).fold(f64::NEG_INFINITY, f64::max);
    Interval::try_from((lo, hi)).unwrap_or(Interval::ENTIRE)
}

/// Interval de Casteljau of 1-D Bernstein coefficients at `u`.
fn de_casteljau(c: &[Interval], u: Interval) -> Interval {
    let mut v = [Interval::zero(); 4];
    let n = c.len().min(4);
    v[..n].copy_from_slice(&c[..n]);
    let one = Interval::one();
    for level in 1..n {
        for i in 0..n - level {
            v[i] = (one - u) * v[i] + u * v[i + 1];
        }
    }
    v[0]
}

/// Certified `sup_{t∈[t₀,t₁]} |B(t) − A(φ(t))|` for the cubic map with
/// Bernstein coefficients `c`; `None` where `hull(c)` leaves the inner domain
/// of `A` or an evaluation is undefined.
pub(crate) fn box_bound(a: &Piece, b: &Piece, t: (f64, f64), c: [f64; 4]) -> Option<f64> {
    if !c.iter().all(|x| x.is_finite()) {
        return None;
    }
    let ci = c.map(point);
    let v = hull(&ci);
    if !(v.inf() >= a.inner.0 && v.sup() <= a.inner.1) {
        return None;
    }
    let tb = Interval::try_from((t.0, t.1)).ok()?;
    let tc = point(0.5 * (t.0 + t.1));
    let w = point(t.1) - point(t.0);
    if w.inf().is_nan() || w.inf() <= 0.0 {
        return None;
    }
    let d1 = [ci[1] - ci[0], ci[2] - ci[1], ci[3] - ci[2]];
    let d2 = [d1[1] - d1[0], d1[2] - d1[1]];
    let three = Interval::from_frac(3, 1);
    let six = Interval::from_frac(6, 1);
    let inv_w = Scalar::recip(&w)?;
    let phi_over = Jet {
        v,
        d: three * hull(&d1) * inv_w,
        dd: six * hull(&d2) * inv_w * inv_w,
    };
    // At the centre `t_c` as the search evaluates `B` there: `t_c` is the float
    // nearest the midpoint, not always the midpoint itself (a box one ulp wide),
    // so `φ` is evaluated at the enclosure of `u_c = (t_c − t₀)/w`, never at 1/2.
    let uc = (tc - point(t.0)) * inv_w;
    let phi_c = Jet {
        v: de_casteljau(&ci, uc),
        d: three * de_casteljau(&d1, uc) * inv_w,
        dd: six * de_casteljau(&d2, uc) * inv_w * inv_w,
    };
    let b_over = b.iv.eval(Jet::variable(tb))?;
    let b_c = b.iv.eval(Jet::variable(tc))?;
    let a_over = a.iv.eval(phi_over)?;
    let a_c = a.iv.eval(phi_c)?;
    difference_bound(&b_over, &b_c, &a_over, &a_c, tb - tc)
}

/// `sup |A′| · |outer − inner|` at both ends of `A`: the distance from the
/// points of `A` beyond its inner domain to `A(inner end)`. `None` if it cannot
/// be enclosed.
fn end_terms(a: &Piece) -> Option<f64> {
    let mut total = Interval::zero();
    for (x, y) in [(a.outer.0, a.inner.0), (a.inner.1, a.outer.1)] {
        if x == y {
            continue;
        }
        let (lo, hi) = if x < y { (x, y) } else { (y, x) };
        let over =
            a.iv.eval(Jet::variable(Interval::try_from((lo, hi)).ok()?))?;
        let speed = crate::scalar::ScalarSqrt::sqrt(&(over.0.d.sqr() + over.1.d.sqr()))?;
        total += speed * (point(hi) - point(lo));
    }
    total.sup().is_finite().then_some(total.sup())
}

/// Tries to reach `goal` with one parametric cover of `B`'s parameter (`B`
/// must have an exact domain: `inner = outer`). `None` when it does not within
/// `max_boxes` boxes, or, for a tolerance, when a node's float distance
/// exceeds it (the tolerance is then probably false: the caller's
/// two-directional search refutes it with a lower bound).
pub(crate) fn prove(a: &Piece, b: &Piece, goal: Goal, max_boxes: usize) -> Option<Parametric> {
    if b.inner != b.outer {
        return None;
    }
    let ends = end_terms(a)?;
    let budget = match goal {
        Goal::Tol(tol) if tol >= 0.0 => tol - ends,
        Goal::Tol(_) => return None,
        Goal::Gap { .. } => f64::INFINITY,
    };
    if budget.is_nan() || budget < 0.0 {
        return None;
    }
    // lower bounds: witnesses B(t), dist(B(t), A) ≥ lower_distance ≤ h(B, A) ≤ d_H
    let mut lo = 0.0f64;
    let mut witness = None;
    let a_slice = std::slice::from_ref(a);
    // The candidate witness: the node farthest from `A` in floats; its lower
    // bound (a branch and bound of its own) is computed only once the float
    // distance says the gap would be met, and once per candidate.
    let mut cand: Option<(f64, f64)> = None; // (t, float distance)
    let mut cand_done = true;
    let note = |t: f64, fd: f64, cand: &mut Option<(f64, f64)>, done: &mut bool| {
        if fd.is_finite() && cand.is_none_or(|c| fd > c.1) {
            *cand = Some((t, fd));
            *done = false;
        }
    };
    let try_witness = |t: f64, float_dist: f64, lo: &mut f64, witness: &mut Option<f64>| {
        let Goal::Gap { rel, .. } = goal else {
            return;
        };
        if float_dist <= *lo {
            return;
        }
        let Some((x, y)) = b.iv.eval(Jet::constant(point(t))) else {
            return;
        };
        let l = super::search::lower_distance((x.v, y.v), a_slice, rel * 0.25, 4_000);
        if l > *lo {
            *lo = l;
            *witness = Some(t);
        }
    };
    let (b0, b1) = b.inner;
    let (a0, a1) = a.inner;
    let pa = |s: f64| super::search::point_f64(a, s);
    let pb = |t: f64| super::search::point_f64(b, t);
    let dist = |p: (f64, f64), q: (f64, f64)| (p.0 - q.0).hypot(p.1 - q.1);
    // orientation: B(0) near A(a₀), or near A(a₁)
    let (pb0, pb1, pa0, pa1) = (pb(b0)?, pb(b1)?, pa(a0)?, pa(a1)?);
    let reversed = dist(pb0, pa1) + dist(pb1, pa0) < dist(pb0, pa0) + dist(pb1, pa1);
    let (s_start, s_end) = if reversed { (a1, a0) } else { (a0, a1) };
    let node = |t: f64, guess: f64, fixed: Option<f64>| -> Option<Node> {
        let q = pb(t)?;
        let s = match fixed {
            Some(s) => s,
            None => foot_newton(a, q, guess.clamp(a0, a1)),
        };
        let fd = dist(q, pa(s)?);
        if fixed.is_none() && fd > budget {
            return None; // probably refuted: leave it to the search
        }
        let k = foot_slope_of(b, t, a, s).unwrap_or(0.0);
        Some(Node { t, s, k, fd })
    };
    let make = |n0: &Node, n1: &Node| -> HeapBox {
        let w = n1.t - n0.t;
        let c = [n0.s, n0.s + w * n0.k / 3.0, n1.s - w * n1.k / 3.0, n1.s];
        let c = if c.iter().all(|x| *x >= a0 && *x <= a1) {
            c
        } else {
            // a slope that overshoots the domain: the straight map instead
            [
                n0.s,
                (2.0 * n0.s + n1.s) / 3.0,
                (n0.s + 2.0 * n1.s) / 3.0,
                n1.s,
            ]
        };
        let bound = box_bound(a, b, (n0.t, n1.t), c).unwrap_or(f64::INFINITY);
        HeapBox {
            b: ParamBox {
                t: (n0.t, n1.t),
                c,
                bound,
            },
            k: (n0.k, n1.k),
        }
    };
    const START: usize = 4;
    let mut nodes = Vec::with_capacity(START + 1);
    for i in 0..=START {
        let t = b0 + (b1 - b0) * (i as f64 / START as f64);
        let guess = s_start + (s_end - s_start) * (i as f64 / START as f64);
        let fixed = match i {
            0 => Some(s_start),
            START => Some(s_end),
            _ => None,
        };
        nodes.push(node(t, guess, fixed)?);
    }
    let ranked = |h: HeapBox| ByBound::new(h.b.bound, h);
    let mut heap = BinaryHeap::new();
    let mut evaluated = 0usize;
    for w in nodes.windows(2) {
        heap.push(ranked(make(&w[0], &w[1])));
        evaluated += 1;
    }
    for n in &nodes {
        note(n.t, n.fd, &mut cand, &mut cand_done);
    }
    loop {
        let top = heap.peek()?;
        let done = match goal {
            Goal::Tol(_) => top.b.bound <= budget,
            Goal::Gap { rel, abs } => {
                let hi = top.b.bound + ends;
                let gap = |lo: f64| hi.is_finite() && hi - lo <= (rel * hi).max(abs);
                if !gap(lo) && !cand_done {
                    if let Some((t, fd)) = cand.filter(|c| gap(c.1)) {
                        try_witness(t, fd, &mut lo, &mut witness);
                        cand_done = true;
                    }
                }
                gap(lo)
            }
        };
        if done {
            break;
        }
        if evaluated + 2 > max_boxes {
            return None;
        }
        let top = heap.pop()?;
        let (t0, t1) = top.b.t;
        let tm = 0.5 * (t0 + t1);
        // A top box this narrow, or this steep, means φ cannot follow:
        // typically `h(A, B) > h(B, A)`, where `φ` must jump over a part of `A`
        // at the end of `B` and the bound of that box stops shrinking. Leave it
        // to the search.
        let mean_slope = (s_end - s_start).abs() / (b1 - b0);
        let steep = (top.b.c[3] - top.b.c[0]).abs() > MAX_SLOPE * mean_slope * (t1 - t0);
        if !(tm > t0 && tm < t1) || t1 - t0 < MIN_WIDTH * (b1 - b0) || steep {
            return None;
        }
        let n0 = Node {
            t: t0,
            s: top.b.c[0],
            k: top.k.0,
            fd: 0.0,
        };
        let n1 = Node {
            t: t1,
            s: top.b.c[3],
            k: top.k.1,
            fd: 0.0,
        };
        // Newton from the current map's value at the midpoint
        let c = top.b.c;
        let guess = (c[0] + 3.0 * (c[1] + c[2]) + c[3]) / 8.0;
        let nm = node(tm, guess, None)?;
        note(tm, nm.fd, &mut cand, &mut cand_done);
        heap.push(ranked(make(&n0, &nm)));
        heap.push(ranked(make(&nm, &n1)));
        evaluated += 2;
    }
    let mut boxes: Vec<ParamBox> = heap.into_iter().map(|h| h.item.b).collect();
    boxes.sort_by(|x, y| x.t.0.total_cmp(&y.t.0));
    let max = boxes.iter().map(|b| b.bound).fold(0.0, f64::max);
    let hi = (point(max) + point(ends)).sup();
    let decided = match goal {
        Goal::Tol(tol) => hi <= tol,
        Goal::Gap { .. } => hi.is_finite(),
    };
    decided.then_some(Parametric {
        hi,
        lo: lo.min(hi),
        witness,
        boxes,
        evaluated,
        source_a: false,
    })
}
