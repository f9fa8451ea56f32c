//! The radial proof: the Hausdorff distance between arcs of one circle and
//! a chain of polynomial Bézier pieces that turns about the centre as the
//! arcs do, each piece inside the sector of its own end rays, **computed**
//! (not only bounded) as the curve's largest radial distance to the circle.
//!
//! **Statement.** Let `A` be one circular arc, or a union of arcs of one
//! circle (centre `c`, radius `R`) each starting on the ray the previous one
//! ends on — one chain of directions, counter-clockwise, of total sweep `Σ`
//! (a whole circle when `Σ ≥ 2π`). Let `P` be a continuous chain of pieces
//! `P_i` (in its order, or all reversed) with
//!
//! 1. each piece turning counter-clockwise from the ray `ρ_i` of its first
//!    point to the ray `ρ_{i+1}` of its last by `Θ_i ∈ (0, π]`
//!    (`ρ_i × ρ_{i+1} > 0`, or `ρ_{i+1} = −λ ρ_i`), with every control point
//!    `q` in that closed sector (`ρ_i × q ≥ 0` and, when `Θ_i < π`,
//!    `q × ρ_{i+1} ≥ 0`) — so, by the convex hull property, every point of
//!    `P_i`;
//! 2. `P(t) ≠ c` for all `t` (below: `|P − c|² − R² > −R²`);
//! 3. the same directions as `A`: `A` and `P` both whole turns, or `ρ_0` on
//!    the ray `A` starts on, the last `ρ` on the ray it ends on, and `Σ Θ_i =
//!    Σ` (the same number of passes through the angle 0).
//!
//! Then `d_H(P, A) = sup_t | |P(t) − c| − R |`. On each piece the angle of
//! `P(t) − c` is a continuous function into `[θ_i, θ_i + Θ_i]` (the sector,
//! less its apex, is cut nowhere else) with those end values; the pieces
//! join, so the angles of `P` run continuously over `[θ_0, θ_0 + Σ Θ_i]`,
//! whose directions are exactly `A`'s (condition 3). So every point `P(t)`
//! has the point of `A` on its own ray, at distance `||P(t) − c| − R|`, and
//! every point of `A` is on the ray of some `P(t)` (the intermediate value
//! theorem): `d_H ≤ sup`. Conversely `dist(P(t), A) ≥ dist(P(t), circle) =
//! ||P(t) − c| − R|` for every `t`: `d_H ≥ h(P, A) ≥ sup`. Conditions 1
//! and 3 are decided exactly in rationals (angles compared by half-plane and
//! cross product, never computed); nothing about monotonicity is needed.
//! One arc of sweep `≤ π` against a curve from one end ray to the other in
//! its sector is the first case; a `<circle>` against its four cubics, or a
//! 270° arc against three, are others.
//!
//! **The bounds.** With `f = |P − c|² − R²` (a polynomial of degree `2n` per
//! piece, its Bernstein coefficients enclosed in intervals from the exact
//! control points), `||P − c| − R| = |f| / (√(R² + f) + R)`, increasing in
//! `|f|` on each side of 0. A branch and bound over the pieces' parameter
//! intervals encloses `max f` and `min f`: an interval's Bernstein
//! coefficients bound `f` over it (convex hull), and the end coefficients are
//! values of `f` at true parameters (witnesses). It stops when the upper and
//! lower bounds meet the relative gap. No Taylor forms, no foot points: a
//! degree-6 polynomial per cubic piece.
//!
//! Used first by [`super::hausdorff`] (for a distance and for a claimed
//! tolerance); it falls back to the other proofs whenever a condition fails.
//! A certificate states the final cover ([`RadialProof::cells`]) for the
//! verifier to check on its own (version 4, [`super::cert`]).

use crate::curve::{Bezier, V2};
use crate::scalar::{interval_from_rational, ulp, Interval, Rational};
use crate::shape::{ArcDesc, ShapeDesc};
use std::collections::BinaryHeap;

/// The largest piece degree handled (binomials of `2n` exact in `f64`).
const MAX_DEGREE: usize = 20;
/// Parameter intervals split before the proof gives up.
const MAX_SPLITS: usize = 20_000;

/// What the radial proof runs for.
#[derive(Clone, Copy, Debug, PartialEq)]
pub(crate) enum Goal {
    /// `hi − lo ≤ max(rel · hi, abs)`.
    Gap(f64),
    /// `hi ≤ tol` or `lo > tol` (else down to a relative gap of `1e-12`).
    Tol(f64),
}

/// A decided radial proof: `lo ≤ d_H ≤ hi`.
#[derive(Clone, Debug, PartialEq)]
pub struct RadialProof {
    /// Certified lower bound (a witness's radial distance).
    pub lo: f64,
    /// Certified upper bound.
    pub hi: f64,
    /// The witness: piece of the curve and parameter.
    pub witness: (usize, f64),
    /// Parameter intervals split.
    pub splits: usize,
    /// The curve is shape `A` of [`super::hausdorff`] (the arc is `B`).
    pub curve_is_a: bool,
    /// The final cover: every piece's parameter domain `[0, 1]` cut into
    /// cells, in order (by piece, then parameter), each with its bound
    /// (`≤ hi`). A certificate states them (see [`super::Certificate`]).
    pub cells: Vec<RadialCell>,
}

/// One cell of a radial proof's cover: the radial distance over parameters
/// `t` of curve piece `piece` is at most `bound`.
#[derive(Clone, Debug, PartialEq)]
pub struct RadialCell {
    /// The curve piece.
    pub piece: usize,
    /// The parameter interval (dyadic ends).
    pub t: (f64, f64),
    /// The bound over it.
    pub bound: f64,
}

/// A circle's arcs: centre, radius, and the members' `(from, to)`
/// directions (counter-clockwise), in the order given.
struct Arcs {
    center: V2<Rational>,
    radius: Rational,
    members: Vec<(V2<Rational>, V2<Rational>)>,
}

/// One circular arc (or an elliptic arc with `M = r I`) as [`Arcs`].
fn arc_of(s: &ShapeDesc) -> Option<ArcDesc> {
    match s {
        ShapeDesc::Arc(arc) => Some(arc.clone()),
        ShapeDesc::EllipseArc(e) => {
            // a circle written as an ellipse: M = r I
            let [[m11, m12], [m21, m22]] = &e.matrix;
            let zero = Rational::from_integer(0.into());
            (m11 == m22 && *m12 == zero && *m21 == zero && *m11 > zero).then(|| ArcDesc {
                center: e.center.clone(),
                radius: m11.clone(),
                from: e.from.clone(),
                to: e.to.clone(),
            })
        }
        _ => None,
    }
}

/// An arc, or a union of arcs of one circle (same centre and radius).
fn arcs_of(s: &ShapeDesc) -> Option<Arcs> {
    let list: Vec<ArcDesc> = match s {
        ShapeDesc::Union(members) => members.iter().map(arc_of).collect::<Option<_>>()?,
        other => vec![arc_of(other)?],
    };
    let first = list.first()?;
    let (center, radius) = (first.center.clone(), first.radius.clone());
    if list
        .iter()
        .any(|a| a.center != center || a.radius != radius)
    {
        return None;
    }
    Some(Arcs {
        center,
        radius,
        members: list.into_iter().map(|a| (a.from, a.to)).collect(),
    })
}

/// The arcs and the curve of a radial pair, in either order.
fn pair<'s>(a: &'s ShapeDesc, b: &'s ShapeDesc) -> Option<(Arcs, &'s [Bezier<Rational>], bool)> {
    match (a, b) {
        (ShapeDesc::Curve(p), other) => Some((arcs_of(other)?, p.as_slice(), true)),
        (other, ShapeDesc::Curve(p)) => Some((arcs_of(other)?, p.as_slice(), false)),
        _ => None,
    }
}

/// Exact angle order of directions: the half-plane (`[0, π)` is 0, `[π, 2π)`
/// is 1), then the cross product.
fn half(v: &V2<Rational>) -> u8 {
    let zero = Rational::from_integer(0.into());
    u8::from(!(v.y > zero || (v.y == zero && v.x > zero)))
}

/// `angle(u) < angle(v)` in `[0, 2π)`, exactly.
fn before(u: &V2<Rational>, v: &V2<Rational>) -> bool {
    let (hu, hv) = (half(u), half(v));
    hu < hv || (hu == hv && u.cross(v) > Rational::from_integer(0.into()))
}

/// A counter-clockwise angular chain: its first and last rays and how many
/// times it passes the angle 0 (its total sweep is `angle(last) −
/// angle(first) + 2π · wraps`).
struct Sweep {
    first: V2<Rational>,
    last: V2<Rational>,
    wraps: usize,
}

impl Sweep {
    /// The chain covers every direction (total sweep `≥ 2π`).
    fn full(&self) -> bool {
        self.wraps >= 2 || (self.wraps == 1 && !before(&self.last, &self.first))
    }

    /// The same set of directions.
    fn same_set(&self, o: &Sweep) -> bool {
        let pp = super::same::positively_parallel;
        if self.full() || o.full() {
            return self.full() && o.full();
        }
        pp(&self.first, &o.first) && pp(&self.last, &o.last) && self.wraps == o.wraps
    }
}

/// The arcs' directions as one chain: each member starts on the ray the
/// previous one ends on; `None` otherwise.
fn arc_sweep(arcs: &Arcs) -> Option<Sweep> {
    let mut wraps = 0;
    for (k, (from, to)) in arcs.members.iter().enumerate() {
        if k > 0 && !super::same::positively_parallel(&arcs.members[k - 1].1, from) {
            return None;
        }
        // a sweep in (0, 2π) passes the angle 0 when it does not increase it
        wraps += usize::from(!before(from, to));
    }
    Some(Sweep {
        first: arcs.members.first()?.0.clone(),
        last: arcs.members.last()?.1.clone(),
        wraps,
    })
}

/// The statement's conditions on the curve, pieces `pts` in this order:
/// a continuous chain; each piece from the ray of its first point to the ray
/// of its last counter-clockwise, less than a full turn and at most a half
/// turn (`ρ × ρ′ > 0`, or `ρ′ = −λ ρ`), every control point in that closed
/// sector. Returns the chain's sweep.
fn curve_sweep(c: &V2<Rational>, pts: &[Vec<V2<Rational>>]) -> Option<Sweep> {
    let zero = Rational::from_integer(0.into());
    let mut wraps = 0;
    for (i, p) in pts.iter().enumerate() {
        if p.len() > MAX_DEGREE + 1 || (i > 0 && pts[i - 1].last() != p.first()) {
            return None;
        }
        let (r0, r1) = (p.first()?.sub(c), p.last()?.sub(c));
        let cr = r0.cross(&r1);
        let half_turn = cr == zero && r0.dot(&r1) < zero;
        if !(cr > zero || half_turn) {
            return None;
        }
        let in_sector = |q: &V2<Rational>| {
            let q = q.sub(c);
            r0.cross(&q) >= zero && (half_turn || q.cross(&r1) >= zero)
        };
        if !p.iter().all(in_sector) {
            return None;
        }
        wraps += usize::from(!before(&r0, &r1));
    }
    Some(Sweep {
        first: pts.first()?.first()?.sub(c),
        last: pts.last()?.last()?.sub(c),
        wraps,
    })
}

/// The module's conditions, exactly: `None` when one fails. The curve is
/// read in its order, then reversed (a clockwise chain).
fn applies(arcs: &Arcs, curve: &[Bezier<Rational>]) -> Option<()> {
    let target = arc_sweep(arcs)?;
    let forward: Vec<Vec<V2<Rational>>> = curve.iter().map(|b| b.points().to_vec()).collect();
    let backward: Vec<Vec<V2<Rational>>> = forward
        .iter()
        .rev()
        .map(|p| p.iter().rev().cloned().collect())
        .collect();
    [forward, backward]
        .iter()
        .any(|pts| curve_sweep(&arcs.center, pts).is_some_and(|s| s.same_set(&target)))
        .then_some(())
}

fn exact(x: f64) -> Interval {
    crate::scalar::point_interval(x)
}

/// `C(n, k)` as a float: the crate's exact integer binomial, below `2⁵³`
/// for `n ≤ 2·MAX_DEGREE`, so the conversion is exact.
fn binom(n: usize, k: usize) -> f64 {
    crate::poly::binomial(n, k) as f64
}

/// Bernstein coefficients of `|P − c|² − R²` (degree `2n`) on `[0, 1]`.
fn radial_form(b: &Bezier<Rational>, c: &V2<Rational>, r2: Interval) -> Vec<Interval> {
    let n = b.degree();
    let q: Vec<(Interval, Interval)> = b
        .points()
        .iter()
        .map(|p| {
            let d = p.sub(c);
            (interval_from_rational(&d.x), interval_from_rational(&d.y))
        })
        .collect();
    (0..=2 * n)
        .map(|k| {
            let mut s = exact(0.0);
            for i in k.saturating_sub(n)..=k.min(n) {
                let j = k - i;
                let w = exact(binom(n, i) * binom(n, j));
                s += w * (q[i].0 * q[j].0 + q[i].1 * q[j].1);
            }
            s / exact(binom(2 * n, k)) - r2
        })
        .collect()
}

/// Both halves of Bernstein coefficients at `1/2` (sums and halvings enclosed
/// by [`ulp`]'s one-ulp widening, no rounding-mode switches).
fn halves(c: &[Interval]) -> (Vec<Interval>, Vec<Interval>) {
    let half = exact(0.5);
    let mut w = c.to_vec();
    let m = w.len();
    let mut left = Vec::with_capacity(m);
    let mut right = Vec::with_capacity(m);
    left.push(w[0]);
    right.push(w[m - 1]);
    for step in 1..m {
        for i in 0..m - step {
            w[i] = ulp::mul(ulp::add(w[i], w[i + 1]), half);
        }
        left.push(w[0]);
        right.push(w[m - 1 - step]);
    }
    right.reverse();
    (left, right)
}

/// The radial distance `|f| / (√(R² + f) + R)` over an enclosure of `f`:
/// `None` when `R² + f` may reach 0 (the curve may pass through the centre).
fn radial_distance(f: Interval, r: Interval, r2: Interval) -> Option<Interval> {
    let s = r2 + f;
    if s.is_empty() || s.inf() <= 0.0 {
        return None;
    }
    Some(f.abs() / (s.sqrt() + r))
}

struct Cell {
    piece: usize,
    t: (f64, f64),
    coef: Vec<Interval>,
}

/// The radial proof of `d_H(a, b)` for `goal` (the absolute gap `abs_of()`
/// is formed only when the relative one is not met), when
/// one shape is a circular arc of sweep `≤ π` and the other a chain of pieces
/// satisfying the module's conditions; `None` otherwise (or when it does not
/// decide within `max_splits` halvings, at most 20 000).
pub(crate) fn prove(
    a: &ShapeDesc,
    b: &ShapeDesc,
    goal: Goal,
    abs_of: &dyn Fn() -> f64,
    max_splits: usize,
) -> Option<RadialProof> {
    let max_splits = max_splits.min(MAX_SPLITS);
    let (arc, curve, curve_is_a) = pair(a, b)?;
    applies(&arc, curve)?;
    let r = interval_from_rational(&arc.radius);
    let r2 = interval_from_rational(&(&arc.radius * &arc.radius));
    // a cell's bound: the radial distance over the hull of its coefficients;
    // infinite (split it) where the hull may reach the centre (`R² + f ≤ 0`)
    let cell_bound = |coef: &[Interval]| -> f64 {
        let (lo, hi) = coef
            .iter()
            .fold((f64::INFINITY, f64::NEG_INFINITY), |(l, h), x| {
                (l.min(x.inf()), h.max(x.sup()))
            });
        Interval::try_from((lo, hi))
            .ok()
            .and_then(|f| radial_distance(f, r, r2))
            .map_or(f64::INFINITY, |d| d.sup())
    };
    // the best witness: (lower bound, (piece, parameter))
    let mut best = (0.0f64, (0usize, 0.0f64));
    let note = |best: &mut (f64, (usize, f64)), coef: &[Interval], piece: usize, t: (f64, f64)| {
        // end coefficients are values of f at true parameters
        for (f, at) in [(coef[0], t.0), (coef[coef.len() - 1], t.1)] {
            if let Some(d) = radial_distance(f, r, r2) {
                if d.inf() > best.0 {
                    *best = (d.inf(), (piece, at));
                }
            }
        }
    };
    let mut heap = BinaryHeap::new();
    for (i, p) in curve.iter().enumerate() {
        let coef = radial_form(p, &arc.center, r2);
        note(&mut best, &coef, i, (0.0, 1.0));
        let bound = cell_bound(&coef);
        heap.push(super::search::ByBound::new(
            bound,
            Cell {
                piece: i,
                t: (0.0, 1.0),
                coef,
            },
        ));
    }
    let mut splits = 0usize;
    let mut abs = None; // the absolute gap (converts every coordinate): once, when needed
    loop {
        let top = heap.peek()?;
        let hi = top.bound;
        // a finite top bounds every cell: `R² + f > 0` on all of them (condition 2)
        let (lo, witness) = best;
        let gap = hi - lo;
        let done = hi.is_finite()
            && match goal {
                Goal::Gap(rel) => gap <= rel * hi || gap <= *abs.get_or_insert_with(abs_of),
                // decided, or as close as the bounds' floats resolve
                Goal::Tol(tol) => hi <= tol || lo > tol || gap <= 1e-12 * hi,
            };
        if done {
            let mut cells: Vec<RadialCell> = heap
                .into_iter()
                .map(|c| RadialCell {
                    piece: c.item.piece,
                    t: c.item.t,
                    bound: c.bound,
                })
                .collect();
            cells.sort_by(|x, y| {
                (x.piece, x.t.0)
                    .partial_cmp(&(y.piece, y.t.0))
                    .expect("finite")
            });
            return Some(RadialProof {
                lo,
                hi,
                witness,
                splits,
                curve_is_a,
                cells,
            });
        }
        if splits >= max_splits {
            return None;
        }
        let cell = heap.pop()?.item;
        let m = 0.5 * (cell.t.0 + cell.t.1);
        if !(cell.t.0 < m && m < cell.t.1) {
            return None; // the float resolution
        }
        splits += 1;
        let (l, rt) = halves(&cell.coef);
        for (coef, t) in [(l, (cell.t.0, m)), (rt, (m, cell.t.1))] {
            note(&mut best, &coef, cell.piece, t);
            let bound = cell_bound(&coef);
            heap.push(super::search::ByBound::new(
                bound,
                Cell {
                    piece: cell.piece,
                    t,
                    coef,
                },
            ));
        }
    }
}
