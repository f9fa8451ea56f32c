//! The check of a radial certificate (version 4, `super::super::cert`): arcs
//! of one circle against a chain of Bézier pieces that turns about the
//! centre as they do, each piece inside the sector of its own end rays, the
//! distance bounded by the largest radial distance `||P − c| − R|` over cells
//! of the curve's parameter domains.
//!
//! Independent of the prover (`certify/radial.rs`): the conditions of the
//! statement are decided here again in rationals, and each cell's enclosure
//! comes from the piece's control points restricted to the cell (two de
//! Casteljau subdivisions at float parameters, outward rounded), whose
//! products give the Bernstein coefficients of `f = |P − c|² − R²` on the
//! cell — the prover instead halves `f`'s coefficients on `[0, 1]`.
//!
//! Why it proves the claim: `proofs/certify-hausdorff.md`, "The radial proof".

use super::eval::{subdivide, Exact, VShape};
use super::read::{canonical_index, canonical_rational, exact_object};
use super::{inv, within, Invalid, Tol};
use crate::json::Json;
use crate::scalar::{interval_from_rational, Interval, Rational};
use num_traits::{One, Signed, Zero};

/// The largest piece degree read (binomials of `2n` exact as floats).
const MAX_DEGREE: usize = 20;

type P = [Rational; 2];

fn sub(p: &P, c: &P) -> P {
    [&p[0] - &c[0], &p[1] - &c[1]]
}

fn cross(u: &P, v: &P) -> Rational {
    &u[0] * &v[1] - &u[1] * &v[0]
}

fn dot(u: &P, v: &P) -> Rational {
    &u[0] * &v[0] + &u[1] * &v[1]
}

/// `q = λ d` with `λ > 0`.
fn on_ray(q: &P, d: &P) -> bool {
    cross(q, d).is_zero() && dot(q, d).is_positive()
}

fn point_iv(x: f64) -> Interval {
    crate::scalar::point_interval(x)
}

/// `C(n, k)` as a float: the crate's exact integer binomial, below `2⁵³`
/// for `n ≤ 2·MAX_DEGREE`, so the conversion is exact.
fn binom(n: usize, k: usize) -> f64 {
    crate::poly::binomial(n, k) as f64
}

/// Checks the `radial` member against the shapes; returns the largest cell
/// bound and the number of cells.
pub(super) fn check(v: &Json, shapes: &[VShape; 2], tol: &Tol) -> Result<(f64, usize), Invalid> {
    let names = ["a", "b"];
    let [arc, cells] = exact_object(v, "radial", ["arc", "cells"])?;
    let (ai, ci) = match arc.as_str() {
        Some("a") => (0, 1),
        Some("b") => (1, 0),
        _ => {
            return Err(inv(
                "radial.arc",
                "expected \"a\" or \"b\": the shape that is the arc",
            ))
        }
    };
    let Some(Exact::Circle { c, r, arcs }) = &shapes[ai].exact else {
        return Err(inv(
            "radial.arc",
            format!(
                "shape {} is not a circular arc or a union of arcs of one circle",
                names[ai]
            ),
        ));
    };
    let Some(Exact::Curve(curve)) = &shapes[ci].exact else {
        return Err(inv(
            "radial.arc",
            format!(
                "the other shape, {}, is not a curve of Bézier pieces",
                names[ci]
            ),
        ));
    };
    conditions(c, arcs, curve, names[ai], names[ci])?;

    // the cover: every piece's [0, 1], in order
    let cells = cells
        .as_array()
        .filter(|l| !l.is_empty())
        .ok_or_else(|| inv("radial.cells", "expected a non-empty list of cells"))?;
    let r_iv = interval_from_rational(r);
    let r2 = interval_from_rational(&(r * r));
    // the control points relative to the centre, exactly, then enclosed
    let rel: Vec<Vec<[Interval; 2]>> = curve
        .iter()
        .map(|b| {
            b.iter()
                .map(|p| {
                    let q = sub(p, c);
                    [interval_from_rational(&q[0]), interval_from_rational(&q[1])]
                })
                .collect()
        })
        .collect();
    let (mut piece, mut cursor) = (0usize, Rational::zero());
    let mut max_bound = 0.0f64;
    for (i, cell) in cells.iter().enumerate() {
        let at = format!("radial.cells[{i}]");
        let [p, t] = exact_object(cell, &at, ["piece", "t"])?;
        let p = canonical_index(p, &format!("{at}.piece"))?;
        let (t0, t1) = match t.as_array() {
            Some([t0, t1]) => (
                canonical_rational(t0, &format!("{at}.t[0]"))?,
                canonical_rational(t1, &format!("{at}.t[1]"))?,
            ),
            _ => return Err(inv(format!("{at}.t"), "expected [t0, t1]")),
        };
        if p != piece || piece >= curve.len() || t0 != cursor || t0 >= t1 || t1 > Rational::one() {
            return Err(inv(
                &at,
                if piece < curve.len() {
                    format!("gap or overlap in the cover: expected a cell of piece {piece} starting at {cursor}, ending after it, at most at 1")
                } else {
                    format!("every piece of {} is already covered", names[ci])
                },
            ));
        }
        let bound = cell_bound(&rel[p], &t0, &t1, r_iv, r2).map_err(|e| inv(&at, e))?;
        if !within(bound, tol) {
            return Err(inv(
                &at,
                format!("the recomputed bound {bound:e} exceeds the tolerance {tol}"),
            ));
        }
        max_bound = max_bound.max(bound);
        if t1.is_one() {
            piece += 1;
            cursor = Rational::zero();
        } else {
            cursor = t1;
        }
    }
    if piece < curve.len() {
        return Err(inv(
            "radial.cells",
            format!("piece {piece} of {} is not covered to its end 1", names[ci]),
        ));
    }
    Ok((max_bound, cells.len()))
}

/// Quadrant of a nonzero direction: `[0, π/2)` is 0, `[π/2, π)` 1,
/// `[π, 3π/2)` 2, `[3π/2, 2π)` 3.
fn quadrant(v: &P) -> u8 {
    let (x, y) = (&v[0], &v[1]);
    if x.is_positive() && !y.is_negative() {
        0
    } else if !x.is_positive() && y.is_positive() {
        1
    } else if x.is_negative() && !y.is_positive() {
        2
    } else {
        3
    }
}

/// The angle of `u` in `[0, 2π)` is below that of `v`, exactly.
fn earlier(u: &P, v: &P) -> bool {
    let (qu, qv) = (quadrant(u), quadrant(v));
    qu < qv || (qu == qv && cross(u, v).is_positive())
}

/// A counter-clockwise chain of directions: first, last, and how often its
/// steps (each in `(0, 2π)`) pass the angle 0.
struct Turn {
    first: P,
    last: P,
    zeros: usize,
}

impl Turn {
    fn whole_circle(&self) -> bool {
        self.zeros >= 2 || (self.zeros == 1 && !earlier(&self.last, &self.first))
    }
}

/// The statement's conditions, exactly: the arcs form one chain
/// (each starts on the ray the previous ends on); the curve is a continuous
/// chain of degree `≤ 20` whose pieces (in its order or reversed) each turn
/// counter-clockwise about the centre from the ray of their first point to
/// the ray of their last by more than 0 and at most π, with every control
/// point in that closed sector; and the curve's directions are the arcs'.
fn conditions(
    c: &P,
    arcs: &[(P, P)],
    curve: &[Vec<P>],
    arc_name: &str,
    name: &str,
) -> Result<(), Invalid> {
    // the arcs' chain
    let mut zeros = 0;
    for (k, (from, to)) in arcs.iter().enumerate() {
        if k > 0 && !on_ray(from, &arcs[k - 1].1) {
            return Err(inv(
                format!("{arc_name}.union[{k}]"),
                "does not start where the previous arc ends: the radial proof needs one chain of arcs",
            ));
        }
        zeros += usize::from(!earlier(from, to));
    }
    let target = Turn {
        first: arcs[0].0.clone(),
        last: arcs[arcs.len() - 1].1.clone(),
        zeros,
    };
    let n = curve.len();
    for (i, b) in curve.iter().enumerate() {
        if b.len() > MAX_DEGREE + 1 {
            return Err(inv(
                format!("{name}.beziers[{i}]"),
                format!("degree above {MAX_DEGREE}: not read by the radial check"),
            ));
        }
        if i > 0 && curve[i - 1].last() != b.first() {
            return Err(inv(
                format!("{name}.beziers[{i}][0]"),
                "not the end of the previous piece: the radial proof needs a continuous chain",
            ));
        }
    }
    // the orientation: the first piece's turn (both ways for a half turn)
    let r0 = sub(&curve[0][0], c);
    let r1 = sub(&curve[0][curve[0].len() - 1], c);
    let first_turn = cross(&r0, &r1);
    let forward = piece_turns(c, curve, false, name);
    let turn = if first_turn.is_negative() {
        piece_turns(c, curve, true, name)?
    } else if first_turn.is_zero() {
        forward.or_else(|e| piece_turns(c, curve, true, name).map_err(|_| e))?
    } else {
        forward?
    };
    let same = if target.whole_circle() || turn.whole_circle() {
        target.whole_circle() && turn.whole_circle()
    } else {
        on_ray(&turn.first, &target.first)
            && on_ray(&turn.last, &target.last)
            && turn.zeros == target.zeros
    };
    if !same {
        return Err(inv(
            format!("{name}.beziers[{}][0]", if first_turn.is_negative() { n - 1 } else { 0 }),
            "the curve does not sweep the arcs' directions: it must run from one end ray of the arcs to the other (either way round), or around the whole circle",
        ));
    }
    Ok(())
}

/// Each piece's turn about `c`, the pieces read in order or all reversed;
/// fields name the pieces and points as the document lists them.
fn piece_turns(c: &P, curve: &[Vec<P>], reversed: bool, name: &str) -> Result<Turn, Invalid> {
    let n = curve.len();
    let mut zeros = 0;
    let mut ends: Option<(P, P)> = None;
    for j in 0..n {
        let i = if reversed { n - 1 - j } else { j };
        let b = &curve[i];
        let m = b.len();
        let pt = |k: usize| if reversed { &b[m - 1 - k] } else { &b[k] };
        let (r0, r1) = (sub(pt(0), c), sub(pt(m - 1), c));
        let cr = cross(&r0, &r1);
        let half_turn = cr.is_zero() && dot(&r0, &r1).is_negative();
        if !(cr.is_positive() || half_turn) {
            return Err(inv(
                format!("{name}.beziers[{i}]"),
                "does not turn about the arc's centre the way the first piece does, by more than 0 and at most π",
            ));
        }
        for k in 0..m {
            let q = sub(pt(k), c);
            if cross(&r0, &q).is_negative() || (!half_turn && cross(&q, &r1).is_negative()) {
                let kk = if reversed { m - 1 - k } else { k };
                return Err(inv(
                    format!("{name}.beziers[{i}][{kk}]"),
                    "outside the closed sector of its piece's end rays: the radial proof does not apply",
                ));
            }
        }
        zeros += usize::from(!earlier(&r0, &r1));
        ends = Some(match ends {
            None => (r0, r1),
            Some((f, _)) => (f, r1),
        });
    }
    let (first, last) = ends.expect("a curve has pieces");
    Ok(Turn { first, last, zeros })
}

/// The largest radial distance over the cell `[t0, t1]` of the piece whose
/// control points relative to the centre are `q`: Bernstein coefficients of
/// `f = |P − c|² − R²` over a float interval `⊇ [t0, t1]`, their hull `F`,
/// then `|F| / (√(R² + F) + R)`.
fn cell_bound(
    q: &[[Interval; 2]],
    t0: &Rational,
    t1: &Rational,
    r: Interval,
    r2: Interval,
) -> Result<f64, String> {
    // float ends outside the cell
    let s0 = interval_from_rational(t0).inf().max(0.0);
    let s1 = interval_from_rational(t1).sup().min(1.0);
    let mut pts = q.to_vec();
    if s0 > 0.0 {
        pts = subdivide(&pts, point_iv(s0), false); // [s0, 1]
    }
    // [s0, s0 + σ (1 − s0)] ⊇ [s0, s1], σ rounded up
    let sigma = ((point_iv(s1) - point_iv(s0)) / (point_iv(1.0) - point_iv(s0))).sup();
    if sigma < 1.0 {
        pts = subdivide(&pts, point_iv(sigma), true);
    }
    let n = pts.len() - 1;
    let (mut lo, mut hi) = (f64::INFINITY, f64::NEG_INFINITY);
    for k in 0..=2 * n {
        let mut s = point_iv(0.0);
        for i in k.saturating_sub(n)..=k.min(n) {
            let j = k - i;
            let w = point_iv(binom(n, i) * binom(n, j));
            s += w * (pts[i][0] * pts[j][0] + pts[i][1] * pts[j][1]);
        }
        let coef = s / point_iv(binom(2 * n, k)) - r2;
        if coef.is_empty() {
            return Err("the radial form cannot be enclosed".to_string());
        }
        lo = lo.min(coef.inf());
        hi = hi.max(coef.sup());
    }
    let f = Interval::try_from((lo, hi)).map_err(|_| "the radial form cannot be enclosed")?;
    let s = r2 + f;
    if s.is_empty() || s.inf() <= 0.0 {
        return Err(
            "the curve may reach the arc's centre on this cell (R² + f ≤ 0 not excluded)"
                .to_string(),
        );
    }
    let d = f.abs() / (s.sqrt() + r);
    if !d.sup().is_finite() {
        return Err("the radial distance cannot be enclosed".to_string());
    }
    Ok(d.sup())
}
