//! The radial proof: the Hausdorff distance between a circular arc and a
//! chain of polynomial Bézier pieces that runs from one end ray of the arc to
//! the other inside its sector, **computed** (not only bounded) as the curve's
//! largest radial distance to the circle.
//!
//! **Statement.** Let the arc have centre `c`, radius `R` and sweep `Θ ≤ π`,
//! counter-clockwise from the direction `d0` to `d1`, and let `P` be a
//! continuous chain of pieces with
//!
//! 1. every control point `q` (relative to `c`) in the closed sector:
//!    `d0 × q ≥ 0` and, when `Θ < π`, `q × d1 ≥ 0` — so, by the convex hull
//!    property, every point of `P`;
//! 2. `P(t) ≠ c` for all `t` (below: `|P − c|² − R² > −R²`);
//! 3. `P`'s first point on the ray of `d0` and its last on the ray of `d1`
//!    (positively parallel), or the other way round.
//!
//! Then `d_H(P, arc) = sup_t | |P(t) − c| − R |`. The angle of `P(t) − c` is a
//! continuous function into `[θ0, θ0 + Θ]` (the sector, less its apex, is cut
//! nowhere else) with the end values `θ0` and `θ0 + Θ`. So every point
//! `P(t)` has the arc point on its own ray, at distance `||P(t) − c| − R|`,
//! and every arc point is on the ray of some `P(t)` (the intermediate value
//! theorem): `d_H ≤ sup`. Conversely `dist(P(t), arc) ≥ dist(P(t), circle) =
//! ||P(t) − c| − R|` for every `t`: `d_H ≥ h(P, arc) ≥ sup`. Conditions 1
//! and 3 are decided exactly in rationals; nothing about monotonicity is needed.
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

/// The arc and the curve of a radial pair, in either order.
fn pair<'s>(a: &'s ShapeDesc, b: &'s ShapeDesc) -> Option<(ArcDesc, &'s [Bezier<Rational>], bool)> {
    let arc_of = |s: &ShapeDesc| match s {
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
    };
    match (a, b) {
        (ShapeDesc::Curve(p), other) => Some((arc_of(other)?, p.as_slice(), true)),
        (other, ShapeDesc::Curve(p)) => Some((arc_of(other)?, p.as_slice(), false)),
        _ => None,
    }
}

/// Conditions 1 and 3 of the module statement, exactly; `None` when one fails.
fn applies(arc: &ArcDesc, curve: &[Bezier<Rational>]) -> Option<()> {
    let zero = Rational::from_integer(0.into());
    let (d0, d1, c) = (&arc.from, &arc.to, &arc.center);
    let cr = d0.cross(d1);
    // Θ < π (d0 × d1 > 0) or Θ = π (d1 = −λ d0)
    let half_turn = cr == zero && d0.dot(d1) < zero;
    if !(cr > zero || half_turn) {
        return None;
    }
    let (first, last) = (curve.first()?, curve.last()?);
    if first.degree() > MAX_DEGREE || curve.iter().any(|p| p.degree() > MAX_DEGREE) {
        return None;
    }
    // a continuous chain
    for w in curve.windows(2) {
        if w[0].points().last() != w[1].points().first() {
            return None;
        }
    }
    let on_ray =
        |p: &V2<Rational>, d: &V2<Rational>| super::same::positively_parallel(&p.sub(c), d);
    let (p0, p1) = (first.points().first()?, last.points().last()?);
    if !((on_ray(p0, d0) && on_ray(p1, d1)) || (on_ray(p0, d1) && on_ray(p1, d0))) {
        return None;
    }
    let in_sector = |p: &V2<Rational>| {
        let q = p.sub(c);
        d0.cross(&q) >= zero && (half_turn || q.cross(d1) >= zero)
    };
    curve
        .iter()
        .all(|b| b.points().iter().all(in_sector))
        .then_some(())
}

fn exact(x: f64) -> Interval {
    Interval::try_from((x, x)).expect("a finite float")
}

/// `C(n, k)` as a float (exact for `n ≤ 2·MAX_DEGREE`).
fn binom(n: usize, k: usize) -> f64 {
    (0..k)
        .fold(1.0, |acc, i| acc * (n - i) as f64 / (i + 1) as f64)
        .round()
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
