//! The cubic (or quadratic) between two joints: fitted to the exact
//! samples, inner control points moved over the grid.

use super::fit::{self, dv, FitEnds};
use super::outline::{Contour, Ctx, Joint, Pos};
use crate::curve::{Bezier, V2};
use glam::DVec2;
use std::cell::Cell;

impl Ctx<'_> {
    /// A cubic from `a.g` to `b.g` with inner control points on the grid.
    /// On a chain whose stretch between the joints turns a sharp corner, the
    /// smooth fit competes with cubics (quadratics) whose inner control
    /// points are grid points near the corner ([`Self::corner_fit`]).
    pub(super) fn fit(
        &self,
        c: &Contour,
        a: &Joint,
        b: &Joint,
        dense: &[(Pos, DVec2)],
    ) -> Option<Bezier<f64>> {
        if !self.corner_joints {
            return self.fit_smooth(c, a, b, dense);
        }
        let pts: Vec<DVec2> = dense.iter().map(|d| d.1).collect();
        let corners = self.corners_in(c, dense);
        // a smooth fit cannot turn a corner (the caller splits until the
        // corner's cubic can)
        let (smooth, cornered) = if corners.is_empty() {
            (self.fit_smooth(c, a, b, dense), None)
        } else {
            (None, self.corner_fit(&pts, a.g, b.g, &corners))
        };
        // the segment between the joints is the last resort (the proof
        // decides; a failed fit has nothing better to offer)
        let line =
            (a.g != b.g).then(|| Bezier::new(vec![V2::new(a.g.x, a.g.y), V2::new(b.g.x, b.g.y)]));
        let best = [smooth, cornered]
            .into_iter()
            .flatten()
            .map(|b| (self.score(&pts, &b, f64::INFINITY), b))
            .filter(|(s, _)| *s < 1e6)
            .min_by(|x, y| x.0.total_cmp(&y.0))
            .map(|x| x.1);
        best.or(line)
    }

    /// The sharp corners (turning by more than 20°) at the joints between
    /// parts among the samples.
    fn corners_in(&self, c: &Contour, dense: &[(Pos, DVec2)]) -> Vec<DVec2> {
        let cos_max = 20f64.to_radians().cos();
        let n = c.parts.len();
        let last = dense.len().saturating_sub(1);
        dense
            .iter()
            .enumerate()
            .filter(|(i, (pos, _))| {
                *i > 0 && *i < last && pos.u == 1.0 && (pos.part + 1 < n || c.closed)
            })
            .map(|(_, d)| d)
            .filter(|(pos, _)| {
                match (
                    self.frame(&c.parts[pos.part], 1.0),
                    self.frame(&c.parts[(pos.part + 1) % n], 0.0),
                ) {
                    (Some((t0, _)), Some((t1, _))) => t0.dot(t1) < cos_max,
                    _ => true,
                }
            })
            .map(|d| d.1)
            .collect()
    }

    /// A cubic from `a` to `b` turning a corner: its two inner control
    /// points at the grid point within two grid steps of a corner with the
    /// least sampled two-sided error (a cubic with both at one point turns
    /// sharply there without a loop), then moved apart by grid steps while
    /// the error falls. A quadratic takes the best such point.
    fn corner_fit(
        &self,
        pts: &[DVec2],
        a: DVec2,
        b: DVec2,
        corners: &[DVec2],
    ) -> Option<Bezier<f64>> {
        let mut near: Vec<DVec2> = Vec::new();
        for &c in corners.iter().take(4) {
            let g = self.nearest_grid(c);
            for i in -2i32..=2 {
                for j in -2i32..=2 {
                    if i * i + j * j <= 5 {
                        let q = g + DVec2::new(f64::from(i), f64::from(j)) * self.gf;
                        if !near.contains(&q) {
                            near.push(q);
                        }
                    }
                }
            }
        }
        let v = |p: DVec2| V2::new(p.x, p.y);
        let mut best: Option<(f64, Bezier<f64>)> = None;
        let mut consider = |bz: Bezier<f64>| {
            let s = self.score(pts, &bz, best.as_ref().map_or(f64::INFINITY, |b| b.0));
            if best.as_ref().is_none_or(|b| s < b.0) {
                best = Some((s, bz));
            }
        };
        // both inner points at each place (a quadratic's one), then the two
        // moved apart by grid steps while the sampled error falls
        for &q in &near {
            consider(if self.quadratic {
                Bezier::new(vec![v(a), v(q), v(b)])
            } else {
                Bezier::new(vec![v(a), v(q), v(q), v(b)])
            });
        }
        let (mut err, mut out) = best?;
        if !self.quadratic {
            let steps = [
                DVec2::new(self.gf, 0.0),
                DVec2::new(-self.gf, 0.0),
                DVec2::new(0.0, self.gf),
                DVec2::new(0.0, -self.gf),
            ];
            for _ in 0..16 {
                let p: Vec<DVec2> = out.points().iter().map(dv).collect();
                let mut improved = false;
                for i in 1..=2 {
                    for d in steps {
                        let mut t = p.clone();
                        t[i] += d;
                        let cand = Bezier::new(t.iter().map(|x| v(*x)).collect());
                        let e2 = self.score(pts, &cand, err);
                        if e2 < err {
                            (err, out) = (e2, cand);
                            improved = true;
                        }
                    }
                }
                if !improved {
                    break;
                }
            }
        }
        fit::round_to_grid(&out, &self.grid).filter(|r| *r == out)
    }

    /// On a chain, between two joints on one piece of the same degree as the
    /// output: that piece restricted to the joints' span, its ends replaced by
    /// the joints' grid points and its inner control points rounded to the
    /// grid, when its sampled error is within half the tolerance (the
    /// chain's pieces are fitted curves already: refitting them costs more
    /// and rarely does better).
    fn chain_restriction(
        &self,
        c: &Contour,
        a: &Joint,
        b: &Joint,
        pts: &[DVec2],
    ) -> Option<Bezier<f64>> {
        let degree = if self.quadratic { 2 } else { 3 };
        if !self.corner_joints || a.pos.part != b.pos.part || !a.pos.before(b.pos) {
            return None;
        }
        let part = &c.parts[a.pos.part];
        let super::outline::Part::Span { piece, .. } = part else {
            return None;
        };
        let x = &self.xf[*piece];
        if x.degree() != degree {
            return None;
        }
        let sub = x.restrict(&part.param(a.pos.u), &part.param(b.pos.u));
        let p = sub.points();
        let v = |p: DVec2| V2::new(p.x, p.y);
        let mut out = vec![v(a.g)];
        for q in &p[1..degree] {
            out.push(v(self.exact_grid(dv(q))?));
        }
        out.push(v(b.g));
        let out = Bezier::new(out);
        let thr = 0.5 * self.tol.value();
        (self.score(pts, &out, thr.next_up()) <= thr).then_some(out)
    }

    /// The smooth fit between two joints (see [`Self::fit`]).
    fn fit_smooth(
        &self,
        c: &Contour,
        a: &Joint,
        b: &Joint,
        dense: &[(Pos, DVec2)],
    ) -> Option<Bezier<f64>> {
        let (t0, k0) = self.frame(&c.parts[a.pos.part], a.pos.u)?;
        let (t1, k1) = self.frame(&c.parts[b.pos.part], b.pos.u)?;
        let v = |p: DVec2| V2::new(p.x, p.y);
        let e = FitEnds {
            p0: v(a.g),
            p1: v(b.g),
            t0: v(t0),
            t1: v(t1),
            k0,
            k1,
        };
        let pts: Vec<DVec2> = dense.iter().map(|d| d.1).collect();
        // a chain's straight (or nearly straight) stretch: the segment
        // between the joints, when it is already well within the tolerance
        if self.corner_joints && a.g != b.g {
            let line = Bezier::new(vec![v(a.g), v(b.g)]);
            let thr = LINE_SHARE * self.tol.value();
            if two_sided_capped(&pts, &line, thr.next_up()) <= thr {
                return Some(line);
            }
        }
        if let Some(sub) = self.chain_restriction(c, a, b, &pts) {
            return Some(sub);
        }
        if self.quadratic {
            return self.fit_quadratic(&e, &pts, a.g, b.g);
        }
        let interior: Vec<V2<f64>> = pts[1..pts.len() - 1]
            .iter()
            .step_by(3)
            .map(|p| v(*p))
            .collect();
        let mut cands = fit::g2_hermite_cubics(&e);
        cands.extend(fit::least_squares_cubic(&e, &interior, 2));
        let len = (b.g - a.g).length();
        if len > 0.0 {
            cands.push(fit::hermite(&e, len / 3.0, len / 3.0));
        }
        // the first least error (later ones capped at the best so far)
        let mut best: Option<(f64, Bezier<f64>)> = None;
        for c in cands {
            let cap = best.as_ref().map_or(f64::INFINITY, |b| b.0);
            let err = two_sided_capped(&pts, &c, cap);
            if err.is_finite() && best.as_ref().is_none_or(|b| err < b.0) {
                best = Some((err, c));
            }
        }
        let best = best?;
        let refined = fit::refine_minimax(&e, &pts, best);
        // where the end tangents constrain too much (a hairpin round a cusp,
        // joints moved off their nominal places) free both inner points
        // (on a chain, whose fits are proven cheaply, only when far off)
        let free_above = if self.corner_joints { 0.6 } else { 0.25 };
        let thr = free_above * self.tol.value();
        let refined = if two_sided_capped(&pts, &refined, thr.next_up()) > thr {
            free_inner_points(&pts, refined)
        } else {
            refined
        };
        // inner control points onto the grid, then coordinate descent
        let p = refined.points();
        let mut q = [self.exact_grid(dv(&p[1]))?, self.exact_grid(dv(&p[2]))?];
        let make = |q: &[DVec2; 2]| Bezier::new(vec![v(a.g), v(q[0]), v(q[1]), v(b.g)]);
        let score = |b: &Bezier<f64>, cap: f64| self.score(&pts, b, cap);
        let mut err = score(&make(&q), f64::INFINITY);
        for _ in 0..48 {
            let mut improved = false;
            for i in 0..2 {
                for d in [
                    DVec2::new(self.gf, 0.0),
                    DVec2::new(-self.gf, 0.0),
                    DVec2::new(0.0, self.gf),
                    DVec2::new(0.0, -self.gf),
                ] {
                    let mut t = q;
                    t[i] += d;
                    let e2 = score(&make(&t), err);
                    if e2 < err {
                        err = e2;
                        q = t;
                        improved = true;
                    }
                }
            }
            if !improved {
                break;
            }
        }
        let out = self.chain_shape(&pts, a.g, b.g, make(&q))?;
        // the moved points are grid multiples: check they are exact
        fit::round_to_grid(&out, &self.grid).filter(|r| *r == out)
    }

    /// What the grid descent lowers: the sampled two-sided error, and on a
    /// chain ([`super::chain_on_grid`]) a large penalty for a control polygon
    /// that turns back on itself (consecutive legs turning by 120° or
    /// more: a curve that retraces or nearly cusps, which the simplicity
    /// check of the output cannot pass), so that such a polygon is left
    /// whenever a neighbour is not.
    ///
    /// Capped ([`two_sided_capped`]): below `cap` the value, else some
    /// value `≥ cap`, so that `score(b, cap) < cap` decides as in full.
    fn score(&self, pts: &[DVec2], b: &Bezier<f64>, cap: f64) -> f64 {
        let penalty = 1e6 * (1.0 + self.tol.value());
        if self.corner_joints && !forward_legs(b, self.hairpin_cos) {
            if cap < penalty {
                // e + penalty ≥ penalty > cap, whatever e
                return f64::INFINITY;
            }
            two_sided(pts, b) + penalty
        } else {
            two_sided_capped(pts, b, cap)
        }
    }

    /// On a chain, a fit whose control polygon turns back is not kept: the
    /// segment between the joints instead when its sampled error is within
    /// the tolerance, else nothing (the caller splits).
    fn chain_shape(
        &self,
        pts: &[DVec2],
        a: DVec2,
        b: DVec2,
        fitted: Bezier<f64>,
    ) -> Option<Bezier<f64>> {
        if !self.corner_joints || forward_legs(&fitted, self.hairpin_cos) {
            return Some(fitted);
        }
        let v = |p: DVec2| V2::new(p.x, p.y);
        let line = Bezier::new(vec![v(a), v(b)]);
        let thr = self.tol.value();
        (a != b && two_sided_capped(pts, &line, thr.next_up()) <= thr).then_some(line)
    }

    /// The quadratic between two grid joints: the control point at the end
    /// tangents' intersection ([`fit::tangent_quadratic`]; `None` when they do
    /// not meet ahead — the caller splits), moved onto the grid, then
    /// coordinate descent of that one point on the sampled two-sided error.
    fn fit_quadratic(&self, e: &FitEnds, pts: &[DVec2], a: DVec2, b: DVec2) -> Option<Bezier<f64>> {
        let v = |p: DVec2| V2::new(p.x, p.y);
        let first = fit::tangent_quadratic(e)?;
        let mut q = self.exact_grid(dv(&first.points()[1]))?;
        let make = |q: DVec2| Bezier::new(vec![v(a), v(q), v(b)]);
        let mut err = self.score(pts, &make(q), f64::INFINITY);
        for _ in 0..96 {
            let mut improved = false;
            for d in [
                DVec2::new(self.gf, 0.0),
                DVec2::new(-self.gf, 0.0),
                DVec2::new(0.0, self.gf),
                DVec2::new(0.0, -self.gf),
            ] {
                let e2 = self.score(pts, &make(q + d), err);
                if e2 < err {
                    err = e2;
                    q += d;
                    improved = true;
                }
            }
            if !improved {
                break;
            }
        }
        let out = self.chain_shape(pts, a, b, make(q))?;
        fit::round_to_grid(&out, &self.grid).filter(|r| *r == out)
    }
}

/// The share of the tolerance under which a chain's segment between two
/// joints is written as a line.
const LINE_SHARE: f64 = 0.5;

/// Every two consecutive legs of the control polygon (non-zero) turn by
/// less than 120°; or, for a quadratic and for a cubic whose middle leg is
/// zero, the two (outer) legs turn by less than `acos(−hairpin_cos)`.
fn forward_legs(b: &Bezier<f64>, hairpin_cos: f64) -> bool {
    let p: Vec<DVec2> = b.points().iter().map(dv).collect();
    let legs: Vec<DVec2> = p.windows(2).map(|w| w[1] - w[0]).collect();
    // a quadratic (hodograph `(1−t)·l₀ + t·l₁`), or a cubic with its two
    // inner points at one place (hodograph `(1−t)²·l₀ + t²·l₂`): the tangent
    // turns by less than a half turn and the curve does not retrace itself,
    // unless the two legs are opposite (`hairpin_cos < 1` refuses sharper
    // turns too: they nearly retrace and cross their neighbours)
    let outer = match legs[..] {
        [l0, l1] => Some((l0, l1)),
        [l0, l1, l2] if l1 == DVec2::ZERO => Some((l0, l2)),
        _ => None,
    };
    if let Some((l0, l1)) = outer {
        return l0 != DVec2::ZERO
            && l1 != DVec2::ZERO
            && l0.dot(l1) > -hairpin_cos * l0.length() * l1.length();
    }
    legs.iter().all(|l| *l != DVec2::ZERO)
        && legs
            .windows(2)
            .all(|w| w[0].dot(w[1]) > -0.5 * w[0].length() * w[1].length())
}

/// The sampled two-sided distance between the exact samples (a polyline) and
/// a cubic (float estimate: chooses candidates only).
pub(super) fn two_sided(exact: &[DVec2], c: &Bezier<f64>) -> f64 {
    two_sided_capped(exact, c, f64::INFINITY)
}

/// [`two_sided`] when it is below `cap`; otherwise some value `≥ cap` (a
/// sample found at least `cap` away in either direction: the maximum is not
/// smaller). A comparison `< cap` decides as with the full value; for `≤ x`
/// or `> x` pass `cap = x.next_up()`.
pub(super) fn two_sided_capped(exact: &[DVec2], c: &Bezier<f64>, cap: f64) -> f64 {
    two_sided_hinted(exact, c, cap, &Cell::new(0))
}

/// [`two_sided_capped`] with the first direction's sample order hinted
/// ([`fit::sampled_error_hinted`]: the same value, only the work depends on
/// `first`).
pub(super) fn two_sided_hinted(
    exact: &[DVec2],
    c: &Bezier<f64>,
    cap: f64,
    first: &Cell<usize>,
) -> f64 {
    // a quadratic is measured as its exact degree elevation (the same curve)
    let elevated;
    let c = if c.degree() == 1 {
        let p = c.points();
        let at = |w: f64| {
            V2::new(
                p[0].x + (p[1].x - p[0].x) * w,
                p[0].y + (p[1].y - p[0].y) * w,
            )
        };
        elevated = Bezier::new(vec![
            p[0].clone(),
            at(1.0 / 3.0),
            at(2.0 / 3.0),
            p[1].clone(),
        ]);
        &elevated
    } else if c.degree() == 2 {
        let p = c.points();
        let third = |a: &V2<f64>, b: &V2<f64>| {
            V2::new(a.x + (b.x - a.x) * 2.0 / 3.0, a.y + (b.y - a.y) * 2.0 / 3.0)
        };
        elevated = Bezier::new(vec![
            p[0].clone(),
            third(&p[0], &p[1]),
            third(&p[2], &p[1]),
            p[2].clone(),
        ]);
        &elevated
    } else {
        c
    };
    let ab = fit::sampled_error_hinted(exact, c, cap, first);
    if ab >= cap {
        return ab;
    }
    let mut ba = 0.0f64;
    let q = c.points();
    let cp = [dv(&q[0]), dv(&q[1]), dv(&q[2]), dv(&q[3])];
    let segs = exact.len().saturating_sub(1);
    // the segment nearest to the previous sample first (the samples follow
    // the curve), and a sample's scan stopped once its distance is below the
    // maximum so far: it cannot raise it. The minimum over segments does not
    // depend on their order (and `sqrt` is monotone), so the value is the
    // full scan's, bit for bit; only the work is less.
    let mut start = 0usize;
    for i in 0..=32 {
        let p = fit::casteljau4(&cp, i as f64 / 32.0);
        let mut best = (f64::INFINITY, start);
        for k in 0..segs {
            let j = (start + k) % segs;
            let (a, b) = (exact[j], exact[j + 1]);
            let d = b - a;
            let l2 = d.length_squared();
            let s = if l2 > 0.0 {
                ((p - a).dot(d) / l2).clamp(0.0, 1.0)
            } else {
                0.0
            };
            let e = (a + d * s - p).length_squared();
            if e < best.0 {
                best = (e, j);
                if e.sqrt() < ba {
                    break;
                }
            }
        }
        start = best.1;
        let d = if segs == 0 {
            f64::INFINITY
        } else {
            best.0.sqrt()
        };
        if d >= cap {
            return if ab.is_finite() && d.is_finite() {
                d
            } else {
                f64::INFINITY
            };
        }
        ba = ba.max(d);
    }
    if ab.is_finite() && ba.is_finite() {
        ab.max(ba)
    } else {
        f64::INFINITY
    }
}

/// Evaluations of the sampled error spent by [`free_inner_points`].
const FREE_EVALS: usize = 240;

/// Lowers the sampled two-sided error of a cubic by a Nelder–Mead search over
/// its two inner control points (4 coordinates; the end points stay), starting
/// at `c`. A float heuristic: the proof decides.
fn free_inner_points(exact: &[DVec2], c: Bezier<f64>) -> Bezier<f64> {
    let p: Vec<DVec2> = c.points().iter().map(dv).collect();
    let make = |x: &[f64; 4]| {
        Bezier::new(vec![
            V2::new(p[0].x, p[0].y),
            V2::new(x[0], x[1]),
            V2::new(x[2], x[3]),
            V2::new(p[3].x, p[3].y),
        ])
    };
    // capped: fr is kept only below simplex[3].1, fe only below fr, fk only
    // below simplex[4].1, so those caps change no decision
    let hint = Cell::new(0);
    let f = |x: &[f64; 4], cap: f64| two_sided_hinted(exact, &make(x), cap, &hint);
    let x0 = [p[1].x, p[1].y, p[2].x, p[2].y];
    let step = 0.05
        * (p[3] - p[0])
            .length()
            .max((p[1] - p[0]).length())
            .max(1e-300);
    let f0 = f(&x0, f64::INFINITY);
    let mut simplex: Vec<([f64; 4], f64)> = vec![(x0, f0)];
    for k in 0..4 {
        let mut x = x0;
        x[k] += step;
        simplex.push((x, f(&x, f64::INFINITY)));
    }
    let mut evals = 5;
    while evals < FREE_EVALS {
        simplex.sort_by(|a, b| a.1.total_cmp(&b.1));
        let mut centroid = [0.0; 4];
        for v in &simplex[..4] {
            for (c, x) in centroid.iter_mut().zip(v.0) {
                *c += x / 4.0;
            }
        }
        let worst = simplex[4].0;
        let at = |t: f64| {
            let mut x = [0.0; 4];
            for k in 0..4 {
                x[k] = centroid[k] + t * (worst[k] - centroid[k]);
            }
            x
        };
        let r = at(-1.0);
        let fr = f(&r, simplex[3].1);
        evals += 1;
        if fr < simplex[0].1 {
            let e = at(-2.0);
            let fe = f(&e, fr);
            evals += 1;
            simplex[4] = if fe < fr { (e, fe) } else { (r, fr) };
        } else if fr < simplex[3].1 {
            simplex[4] = (r, fr);
        } else {
            let k = at(0.5);
            let fk = f(&k, simplex[4].1);
            evals += 1;
            if fk < simplex[4].1 {
                simplex[4] = (k, fk);
            } else {
                let best = simplex[0].0;
                for v in simplex.iter_mut().skip(1) {
                    for (x, b) in v.0.iter_mut().zip(best) {
                        *x = 0.5 * (*x + b);
                    }
                    v.1 = f(&v.0, f64::INFINITY);
                    evals += 1;
                }
            }
        }
    }
    simplex.sort_by(|a, b| a.1.total_cmp(&b.1));
    if simplex[0].1 < f0 {
        make(&simplex[0].0)
    } else {
        c
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The capped two-sided error is the full one below its cap and at
    /// least the cap otherwise (lines, quadratics and cubics, caps around
    /// the value; samples far from the curve, or on half of it so that the
    /// curve-to-samples direction decides), so every comparison with the
    /// cap decides as in full.
    #[test]
    fn capped_two_sided_error_decides_as_the_full_one() {
        let mut rng = crate::test_util::TestRng::new(0x6a09_e667_f3bc_c908);
        let mut f = |m: i64| rng.int(m) as f64 / 16.0;
        let mut checked = 0;
        for case in 0..300 {
            let n = 2 + case % 3;
            let c = Bezier::new((0..n).map(|_| V2::new(f(200), f(200))).collect());
            // random points (far in both directions), or points of the
            // curve over [0, 1/2] only (near one way, far the other)
            let exact: Vec<DVec2> = if case % 2 == 0 {
                (0..30).map(|_| DVec2::new(f(200), f(200))).collect()
            } else {
                (0..30).map(|k| c.eval_fast(k as f64 / 58.0)).collect()
            };
            let full = two_sided(&exact, &c);
            for cap in [full * 0.25, full, full.next_up(), full * 3.0, f64::INFINITY] {
                let v = two_sided_capped(&exact, &c, cap);
                if full < cap {
                    assert_eq!(v.to_bits(), full.to_bits(), "{c:?} cap {cap}");
                } else {
                    assert!(v >= cap && v <= full, "{v} vs {full}, cap {cap}");
                }
                checked += 1;
            }
        }
        assert!(checked == 1500);
    }
}
