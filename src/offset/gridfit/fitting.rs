//! The cubic (or quadratic) between two joints: fitted to the exact
//! samples, inner control points moved over the grid.

use super::fit::{self, dv, FitEnds};
use super::outline::{Contour, Ctx, Joint, Pos};
use crate::curve::{Bezier, V2};
use glam::DVec2;

impl Ctx<'_> {
    /// A cubic from `a.g` to `b.g` with inner control points on the grid.
    pub(super) fn fit(
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
        let best = cands
            .into_iter()
            .map(|c| (two_sided(&pts, &c), c))
            .filter(|(err, _)| err.is_finite())
            .min_by(|x, y| x.0.total_cmp(&y.0))?;
        let refined = fit::refine_minimax(&e, &pts, best);
        // where the end tangents constrain too much (a hairpin round a cusp,
        // joints moved off their nominal places) free both inner points
        let refined = if two_sided(&pts, &refined) > 0.25 * self.tol.value() {
            free_inner_points(&pts, refined)
        } else {
            refined
        };
        // inner control points onto the grid, then coordinate descent
        let p = refined.points();
        let mut q = [self.exact_grid(dv(&p[1]))?, self.exact_grid(dv(&p[2]))?];
        let make = |q: &[DVec2; 2]| Bezier::new(vec![v(a.g), v(q[0]), v(q[1]), v(b.g)]);
        let mut err = two_sided(&pts, &make(&q));
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
                    let e2 = two_sided(&pts, &make(&t));
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
        let out = make(&q);
        // the moved points are grid multiples: check they are exact
        fit::round_to_grid(&out, &self.grid).filter(|r| *r == out)
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
        let mut err = two_sided(pts, &make(q));
        for _ in 0..96 {
            let mut improved = false;
            for d in [
                DVec2::new(self.gf, 0.0),
                DVec2::new(-self.gf, 0.0),
                DVec2::new(0.0, self.gf),
                DVec2::new(0.0, -self.gf),
            ] {
                let e2 = two_sided(pts, &make(q + d));
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
        let out = make(q);
        fit::round_to_grid(&out, &self.grid).filter(|r| *r == out)
    }
}

/// The sampled two-sided distance between the exact samples (a polyline) and
/// a cubic (float estimate: chooses candidates only).
pub(super) fn two_sided(exact: &[DVec2], c: &Bezier<f64>) -> f64 {
    // a quadratic is measured as its exact degree elevation (the same curve)
    let elevated;
    let c = if c.degree() == 2 {
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
    let ab = fit::sampled_error(exact, c);
    let ba = (0..=32)
        .map(|i| {
            let p = c.eval_fast(i as f64 / 32.0);
            exact
                .windows(2)
                .map(|w| {
                    let d = w[1] - w[0];
                    let l2 = d.length_squared();
                    let s = if l2 > 0.0 {
                        ((p - w[0]).dot(d) / l2).clamp(0.0, 1.0)
                    } else {
                        0.0
                    };
                    (w[0] + d * s - p).length()
                })
                .fold(f64::INFINITY, f64::min)
        })
        .fold(0.0, f64::max);
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
    let f = |x: &[f64; 4]| two_sided(exact, &make(x));
    let x0 = [p[1].x, p[1].y, p[2].x, p[2].y];
    let step = 0.05
        * (p[3] - p[0])
            .length()
            .max((p[1] - p[0]).length())
            .max(1e-300);
    let mut simplex: Vec<([f64; 4], f64)> = vec![(x0, f(&x0))];
    for k in 0..4 {
        let mut x = x0;
        x[k] += step;
        simplex.push((x, f(&x)));
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
        let fr = f(&r);
        evals += 1;
        if fr < simplex[0].1 {
            let e = at(-2.0);
            let fe = f(&e);
            evals += 1;
            simplex[4] = if fe < fr { (e, fe) } else { (r, fr) };
        } else if fr < simplex[3].1 {
            simplex[4] = (r, fr);
        } else {
            let k = at(0.5);
            let fk = f(&k);
            evals += 1;
            if fk < simplex[4].1 {
                simplex[4] = (k, fk);
            } else {
                let best = simplex[0].0;
                for v in simplex.iter_mut().skip(1) {
                    for (x, b) in v.0.iter_mut().zip(best) {
                        *x = 0.5 * (*x + b);
                    }
                    v.1 = f(&v.0);
                    evals += 1;
                }
            }
        }
    }
    simplex.sort_by(|a, b| a.1.total_cmp(&b.1));
    if simplex[0].1 < f(&x0) {
        make(&simplex[0].0)
    } else {
        c
    }
}
