//! The on-side tests of a sub-piece (step 4): points proven outside `S`,
//! the kept test ([`prove_kept`]) and the removal test ([`prove_removed`]).

use super::sides::approx_dir;
use super::types::Piece;
use crate::curve::{bernstein_product, Bezier, V2};
use crate::scalar::{interval_from_rational, rational_from_f64, Interval, Rational, Scalar};
use crate::stroke::circle::Arc;
use crate::stroke::ellipse::Form;
use num_traits::{Signed, Zero};

// ---------------------------------------------------------------------------
// distance to the input curve

/// Float estimate of the pen distance of `p` to `x` ([`Form::estimate`] of
/// `min_t g(p − x(t))`; for a circle `dist(p, x)`) and the foot `(piece, t)`.
pub(super) fn foot(curve: &[Bezier<f64>], form: &Form, p: (f64, f64)) -> (f64, usize, f64) {
    let mut best = (f64::INFINITY, 0usize, 0.0f64);
    // for a circular pen g = |v|²: pieces nearest by their control-point box
    // first, and a piece whose box is farther than the best so far skipped
    // (it cannot hold a nearer point; floats, a search heuristic only)
    let box_d2 = |b: &Bezier<f64>| {
        let (mut lo, mut hi) = (
            (f64::INFINITY, f64::INFINITY),
            (f64::NEG_INFINITY, f64::NEG_INFINITY),
        );
        for q in b.points() {
            lo = (lo.0.min(q.x), lo.1.min(q.y));
            hi = (hi.0.max(q.x), hi.1.max(q.y));
        }
        let gx = (lo.0 - p.0).max(p.0 - hi.0).max(0.0);
        let gy = (lo.1 - p.1).max(p.1 - hi.1).max(0.0);
        gx * gx + gy * gy
    };
    let mut order: Vec<(f64, usize)> = curve.iter().map(box_d2).zip(0..).collect();
    if form.circle {
        order.sort_by(|a, b| a.0.total_cmp(&b.0));
    }
    for (lower, i) in order {
        if form.circle && lower > best.0 {
            break;
        }
        let b = &curve[i];
        // samples at most about reach/4 apart along the control polygon (which
        // bounds the arc length), so the global minimum's basin is not missed
        let poly: f64 = b
            .points()
            .windows(2)
            .map(|w| (w[1].x - w[0].x).hypot(w[1].y - w[0].y))
            .sum();
        let n = ((4.0 * poly / form.reach.max(1e-300)).ceil() as usize).clamp(64, 4096);
        let d2 = |t: f64| {
            let v = b.eval_fast(t);
            form.value_f64(v.x - p.0, v.y - p.1)
        };
        let mut bt = 0.0;
        let mut bd = f64::INFINITY;
        for k in 0..=n {
            let t = k as f64 / n as f64;
            let d = d2(t);
            if d < bd {
                bd = d;
                bt = t;
            }
        }
        // golden-section refinement on the bracket
        let (mut lo, mut hi) = (
            (bt - 1.0 / n as f64).max(0.0),
            (bt + 1.0 / n as f64).min(1.0),
        );
        for _ in 0..50 {
            let m1 = lo + (hi - lo) * 0.382;
            let m2 = lo + (hi - lo) * 0.618;
            if d2(m1) < d2(m2) {
                hi = m2;
            } else {
                lo = m1;
            }
        }
        let t = 0.5 * (lo + hi);
        let d = d2(t).min(bd);
        let t = if d2(t) <= bd { t } else { bt };
        if d < best.0 {
            best = (d, i, t);
        }
    }
    (form.estimate(best.0), best.1, best.2)
}

/// The input curve as the kept test reads it: the exact pieces, and per
/// piece a float box that encloses its exact control points (outward
/// rounded), the cheap first exclusion of [`ExactCurve::outside`].
pub(crate) struct ExactCurve<'a> {
    pub(crate) pieces: &'a [Bezier<Rational>],
    /// Per piece `[[x_lo, y_lo], [x_hi, y_hi]]`; `None` where a coordinate
    /// has no finite enclosure (the exact tests decide there).
    boxes: Vec<Option<[[f64; 2]; 2]>>,
}

impl<'a> ExactCurve<'a> {
    pub(crate) fn new(pieces: &'a [Bezier<Rational>]) -> Self {
        let boxes = pieces
            .iter()
            .map(|x| {
                let mut b = [[f64::INFINITY; 2], [f64::NEG_INFINITY; 2]];
                for p in x.points() {
                    for (k, c) in [&p.x, &p.y].into_iter().enumerate() {
                        let i = interval_from_rational(c);
                        if !(i.inf().is_finite() && i.sup().is_finite()) {
                            return None;
                        }
                        b[0][k] = b[0][k].min(i.inf());
                        b[1][k] = b[1][k].max(i.sup());
                    }
                }
                Some(b)
            })
            .collect();
        ExactCurve { pieces, boxes }
    }

    /// `w ∉ S = x ⊕ E`, proven (`false`: not proven), as [`outside`]; a
    /// piece whose box is proven farther than `√a2_hi` from `w` (`E` lies in
    /// that disk) is passed over without exact arithmetic. The same answer as
    /// [`outside`] always: the box test is the exact bounding-box exclusion
    /// of [`outside_piece`] with a box that is only larger.
    pub(crate) fn outside(&self, w: &V2<Rational>, form: &Form) -> bool {
        let wi = [interval_from_rational(&w.x), interval_from_rational(&w.y)];
        let r2_hi = interval_from_rational(&form.a2_hi).sup();
        (0..self.pieces.len())
            .all(|i| self.far(i, &wi, r2_hi) || outside_piece(&self.pieces[i], w, form))
    }

    /// Piece `i`'s box is proven at a squared distance `> r2_hi` from every
    /// point of `wi`.
    pub(super) fn far(&self, i: usize, wi: &[Interval; 2], r2_hi: f64) -> bool {
        let Some([lo, hi]) = self.boxes[i] else {
            return false;
        };
        let point = crate::scalar::point_interval;
        // an enclosure of the gap between w and the box along axis k, when
        // it is proven positive on one side; 0 otherwise (a lower bound)
        let gap = |k: usize| {
            let below = point(lo[k]) - wi[k];
            let above = wi[k] - point(hi[k]);
            if below.inf() > 0.0 {
                below
            } else if above.inf() > 0.0 {
                above
            } else {
                point(0.0)
            }
        };
        (gap(0).sqr() + gap(1).sqr()).inf() > r2_hi
    }
}

/// Proves `g(w − x(t)) > d` for all `t` in `[0, 1]` (`w ∉ x(t) + E`; for a
/// circle `|w − x(t)|² > r²`) by exact Bernstein signs, subdividing.
pub(crate) fn outside_piece(x: &Bezier<Rational>, w: &V2<Rational>, form: &Form) -> bool {
    let r2 = &form.a2_hi;
    // bounding-box exclusion first
    let p = x.points();
    let mut d2 = <Rational as Zero>::zero();
    for k in 0..2 {
        let get = |v: &V2<Rational>| if k == 0 { v.x.clone() } else { v.y.clone() };
        let lo = p.iter().map(get).min().expect("nonempty");
        let hi = p.iter().map(get).max().expect("nonempty");
        let wk = get(w);
        if wk < lo {
            d2 += (&lo - &wk) * (&lo - &wk);
        } else if wk > hi {
            d2 += (&wk - &hi) * (&wk - &hi);
        }
    }
    if &d2 > r2 {
        return true;
    }
    // interval filter first (rigorous enclosures), exact only when it cannot decide
    {
        let xi = x.map(interval_from_rational);
        let wi = w.map(interval_from_rational);
        let (xs, ys) = xi.coords();
        let dx: Vec<Interval> = xs.iter().map(|v| *v - wi.x).collect();
        let dy: Vec<Interval> = ys.iter().map(|v| *v - wi.y).collect();
        let di = interval_from_rational(&form.d);
        let g: Vec<Interval> = if form.circle {
            bernstein_product(&dx, &dx)
                .into_iter()
                .zip(bernstein_product(&dy, &dy))
                .map(|(a, b)| a + b - di)
                .collect()
        } else {
            let (fa, fb, fc) = (
                interval_from_rational(&form.a),
                interval_from_rational(&form.b),
                interval_from_rational(&form.c),
            );
            let two = Interval::try_from((2.0, 2.0)).expect("two");
            bernstein_product(&dx, &dx)
                .into_iter()
                .zip(bernstein_product(&dy, &dy))
                .zip(bernstein_product(&dx, &dy))
                .map(|((xx, yy), xy)| fa * xx + fc * yy + two * fb * xy - di)
                .collect()
        };
        if let Some(v) = positive_bernstein_iv(g, 14) {
            return v;
        }
    }
    let (xs, ys) = x.coords();
    let dx: Vec<Rational> = xs.iter().map(|v| v - &w.x).collect();
    let dy: Vec<Rational> = ys.iter().map(|v| v - &w.y).collect();
    let g: Vec<Rational> = if form.circle {
        bernstein_product(&dx, &dx)
            .into_iter()
            .zip(bernstein_product(&dy, &dy))
            .map(|(a, b)| a + b - &form.d)
            .collect()
    } else {
        let two_b = Rational::from_integer(2.into()) * &form.b;
        bernstein_product(&dx, &dx)
            .into_iter()
            .zip(bernstein_product(&dy, &dy))
            .zip(bernstein_product(&dx, &dy))
            .map(|((xx, yy), xy)| &form.a * xx + &form.c * yy + &two_b * xy - &form.d)
            .collect()
    };
    positive_bernstein(g, 14)
}

/// [`positive_bernstein`] on interval coefficients: `Some(true)` proven
/// positive, `Some(false)` proven not (an end value ≤ 0), `None` undecided.
pub(crate) fn positive_bernstein_iv(g: Vec<Interval>, depth: u32) -> Option<bool> {
    if g.iter().all(|c| c.inf() > 0.0) {
        return Some(true);
    }
    if g[0].sup() <= 0.0 || g[g.len() - 1].sup() <= 0.0 {
        return Some(false);
    }
    if depth == 0 {
        return None;
    }
    let (left, right) = crate::curve::bernstein_halves(&g);
    match positive_bernstein_iv(left, depth - 1)? {
        false => Some(false),
        true => positive_bernstein_iv(right, depth - 1),
    }
}

/// All of a Bernstein polynomial on `[0, 1]` is `> 0`: coefficients positive,
/// or split in half (exact de Casteljau) up to `depth`.
pub(crate) fn positive_bernstein(g: Vec<Rational>, depth: u32) -> bool {
    if g.iter().all(|c| c.is_positive()) {
        return true;
    }
    if !g[0].is_positive() || !g[g.len() - 1].is_positive() || depth == 0 {
        return false;
    }
    let (left, right) = crate::curve::bernstein_halves(&g);
    positive_bernstein(left, depth - 1) && positive_bernstein(right, depth - 1)
}

/// `w ∉ S = x ⊕ E`, proven (`false`: not proven).
pub(crate) fn outside(curve: &[Bezier<Rational>], w: &V2<Rational>, form: &Form) -> bool {
    curve.iter().all(|x| outside_piece(x, w, form))
}

// ---------------------------------------------------------------------------
// sub-pieces and their parts

/// A part of a sub-piece: boxes enclosing its hull points and how to split
/// it. A Bézier part is held in interval form: its control points are
/// enclosures of the exact ones (outward rounded de Casteljau halves), so
/// every statement proven about the boxes' hull holds for the exact part.
#[derive(Clone, Debug)]
#[allow(clippy::large_enum_variant)]
pub(super) enum Part {
    Bez(Bezier<Interval>),
    Arc(Arc),
}

pub(super) fn iv_point(p: &V2<Rational>) -> V2<Interval> {
    p.map(interval_from_rational)
}

/// An upper bound of `|p − w|` over the box `p`.
pub(super) fn box_dist_hi(p: &V2<Interval>, w: &V2<Interval>) -> f64 {
    let (dx, dy) = (p.x - w.x, p.y - w.y);
    let d = (dx * dx + dy * dy).sqrt();
    if d.is_empty() {
        f64::INFINITY
    } else {
        d.sup()
    }
}

/// The halves of an interval Bézier at `t = 1/2` by de Casteljau in the
/// convex form `(p + q)/2` ([`crate::curve::bernstein_halves`] per
/// coordinate: the boxes' widths average instead of growing, as they would
/// with `p + t(q − p)`).
fn halves_iv(b: &Bezier<Interval>) -> (Bezier<Interval>, Bezier<Interval>) {
    use crate::curve::bernstein_halves;
    let (xs, ys): (Vec<Interval>, Vec<Interval>) = b.points().iter().map(|p| (p.x, p.y)).unzip();
    let ((xl, xr), (yl, yr)) = (bernstein_halves(&xs), bernstein_halves(&ys));
    let zip = |x: Vec<Interval>, y: Vec<Interval>| {
        Bezier::new(x.into_iter().zip(y).map(|(a, b)| V2::new(a, b)).collect())
    };
    (zip(xl, yl), zip(xr, yr))
}

impl Part {
    pub(super) fn hull(&self) -> Option<Vec<V2<Interval>>> {
        match self {
            Part::Bez(b) => Some(b.points().to_vec()),
            Part::Arc(a) => a.hull().map(|h| h.iter().map(iv_point).collect()),
        }
    }
    pub(super) fn halves(&self) -> Option<(Part, Part)> {
        match self {
            Part::Bez(b) => {
                let (l, r) = halves_iv(b);
                Some((Part::Bez(l), Part::Bez(r)))
            }
            Part::Arc(a) => {
                let m = a.midpoint()?;
                let (l, r) = a.split_at(&m);
                Some((Part::Arc(l), Part::Arc(r)))
            }
        }
    }
    /// A point near the middle and the unit right normal of travel there (floats).
    pub(super) fn mid_right_normal(&self) -> ((f64, f64), (f64, f64)) {
        match self {
            Part::Bez(b) => {
                let bf = b.map(|i| i.mid());
                let p = bf.eval_fast(0.5);
                let h = bf.hodograph();
                let mut d = h.eval_fast(0.5);
                if d.length() == 0.0 {
                    let q = bf.points();
                    d = q[q.len() - 1].to_dvec2() - q[0].to_dvec2();
                }
                let l = d.length().max(f64::MIN_POSITIVE);
                ((p.x, p.y), (d.y / l, -d.x / l))
            }
            Part::Arc(a) => {
                // the middle of a minor part in floats (it only chooses a
                // candidate): the centre plus r times the unit bisector
                let (u, w) = (
                    approx_dir(&a.from.sub(&a.center)),
                    approx_dir(&a.to.sub(&a.center)),
                );
                let (lu, lw) = (u.0.hypot(u.1), w.0.hypot(w.1));
                let bis = (u.0 / lu + w.0 / lw, u.1 / lu + w.1 / lw);
                let lb = bis.0.hypot(bis.1);
                let rf = a.radius.approx();
                let cf = approx_dir(&a.center);
                let mf = if lb > 1e-12 && lb.is_finite() {
                    (cf.0 + rf * bis.0 / lb, cf.1 + rf * bis.1 / lb)
                } else {
                    approx_dir(&a.from)
                };
                let v = (mf.0 - cf.0, mf.1 - cf.1);
                let l = (v.0 * v.0 + v.1 * v.1).sqrt().max(f64::MIN_POSITIVE);
                let out = (v.0 / l, v.1 / l);
                let mm = mf;
                // right of travel: outward for counter-clockwise travel
                if a.clockwise {
                    (mm, (-out.0, -out.1))
                } else {
                    (mm, out)
                }
            }
        }
    }
    pub(super) fn initial(p: &Piece) -> Option<Vec<Part>> {
        match p {
            Piece::Bezier(b) => Some(vec![Part::Bez(b.map(interval_from_rational))]),
            Piece::Arc(a) => Some(a.minor_parts()?.into_iter().map(Part::Arc).collect()),
        }
    }
}

fn hull_radius_hi(h: &[V2<Interval>], w: &V2<Rational>) -> f64 {
    let w = iv_point(w);
    h.iter().map(|p| box_dist_hi(p, &w)).fold(0.0, f64::max)
}

/// Parts the kept test may use on one piece before giving up.
pub(super) const KEPT_MAX_PARTS: usize = 4000;

/// Kept test: every point of the piece is within the returned bound of a
/// point proven outside `S`. Returns the largest such distance; `None` after
/// `max_parts` parts ([`KEPT_MAX_PARTS`], or a few for a cheap first try on a
/// short sub-piece, which one or two witnesses cover).
pub(super) fn prove_kept(
    curve: &ExactCurve,
    curve_f: &[Bezier<f64>],
    piece: &Piece,
    e_in: f64,
    form: &Form,
    budget: f64,
    max_parts: usize,
) -> Option<f64> {
    let rf = form.reach;
    let mut todo: Vec<(Part, u32)> = Part::initial(piece)?.into_iter().map(|p| (p, 0)).collect();
    let mut worst: f64 = 0.0;
    let mut n = 0;
    while let Some((part, depth)) = todo.pop() {
        n += 1;
        if n > max_parts {
            return None;
        }
        let hull = part.hull()?;
        let (m, nr) = part.mid_right_normal();
        // a point proven outside: the middle pushed out along the right normal
        let (est, fi, ft) = foot(curve_f, form, m);
        let mut done = None;
        let base = (2.0 * e_in).max(rf * 1e-12);
        // floats choose the candidates only: `outside` decides
        let (deficit, dirs) = if form.circle {
            // away from the float foot y (outward whichever way the piece
            // travels), then the right normal of travel
            let y = curve_f[fi].eval_fast(ft);
            let (zx, zy) = (m.0 - y.x, m.1 - y.y);
            let zl = zx.hypot(zy);
            let mut dirs = Vec::with_capacity(2);
            if zl > 0.0 && zl.is_finite() {
                dirs.push((zx / zl, zy / zl));
            }
            dirs.push(nr);
            ((rf - est).max(0.0), dirs)
        } else {
            // along the ray from the foot y: the pen boundary is |m − y|(1/γ − 1)
            // away (γ the gauge); push along the piece's normal and along the
            // outer normal Q⁻¹(m − y) of the translated pen
            let y = curve_f[fi].eval_fast(ft);
            let (zx, zy) = (m.0 - y.x, m.1 - y.y);
            let gamma = est / rf;
            let deficit = if gamma > 0.0 {
                (zx.hypot(zy) * (1.0 / gamma - 1.0)).max(0.0)
            } else {
                0.0
            };
            let [fa, fb, fc, _] = form.ff;
            let g = (fa * zx + fb * zy, fb * zx + fc * zy);
            let gl = g.0.hypot(g.1);
            let mut dirs = vec![nr];
            if gl > 0.0 && gl.is_finite() {
                dirs.push((g.0 / gl, g.1 / gl));
            }
            (deficit, dirs)
        };
        // the float deficit is an estimate: scaled up with the tries, and at
        // last a push of a fraction of the budget (a witness a hair outside
        // needs a proof finer than the subdivision can give)
        let tries = [
            1.25 * (base + deficit),
            2.0 * (base + deficit),
            3.0 * (base + deficit),
            deficit + budget / 16.0,
        ];
        'tries: for eta in tries {
            let mut over = true;
            for d in &dirs {
                let w = (m.0 + eta * d.0, m.1 + eta * d.1);
                let w = V2::new(rational_from_f64(w.0)?, rational_from_f64(w.1)?);
                let rho = hull_radius_hi(&hull, &w);
                if rho > budget {
                    continue;
                }
                over = false;
                if curve.outside(&w, form) {
                    done = Some(rho);
                    break 'tries;
                }
            }
            if over {
                break;
            }
        }
        match done {
            Some(rho) => worst = worst.max(rho),
            None => {
                if depth >= 14 {
                    return None;
                }
                let (l, rr) = part.halves()?;
                todo.push((rr, depth + 1));
                todo.push((l, depth + 1));
            }
        }
    }
    Some(worst.max(e_in))
}

/// Removal test: every point `q` of the piece has its closed `e`-disk in the
/// interior of `S` — an exact witness point `y = x(t*)` per part with
/// `g(p − y) < d (1 − e/b_lo)²` at every hull point `p` (so `q − y ∈ ρE`,
/// `ρ < 1 − e/b_lo`, and `q + disk(e) ⊆ y + (ρ + e/b_lo) E`, since
/// `disk(b_lo) ⊆ E`; for a circle: `|p − y| < r − e`) — or lies within
/// `lambda` of one of `near` (end points of kept sub-pieces). Returns the
/// indices into `near` of the points used (empty when none was needed).
#[allow(clippy::too_many_arguments)]
pub(super) fn prove_removed(
    curve: &[Bezier<Rational>],
    curve_f: &[Bezier<f64>],
    piece: &Piece,
    e: f64,
    local: &dyn Fn(f64, f64) -> Option<f64>,
    form: &Form,
    near: &[V2<Rational>],
    lambda: &Rational,
) -> Option<Vec<usize>> {
    // `d (1 − e/b_lo)²` enclosed from below, for the part's error bound
    let (d_iv, b_lo_iv) = (
        interval_from_rational(&form.d),
        interval_from_rational(&form.b_lo),
    );
    let one_iv = Interval::try_from((1.0, 1.0)).ok()?;
    let re2_for = |e: f64| -> Option<f64> {
        let sh = one_iv - Interval::try_from((e, e)).ok()? / b_lo_iv;
        if sh.is_empty() || sh.inf() <= 0.0 {
            return None;
        }
        let v = d_iv * sh * sh;
        (!v.is_empty()).then(|| v.inf())
    };
    re2_for(e)?;
    let l2 = interval_from_rational(&(lambda * lambda)).inf();
    let near: Vec<V2<Interval>> = near.iter().map(iv_point).collect();
    let fa = [&form.a, &form.b, &form.c].map(interval_from_rational);
    let two = Interval::try_from((2.0, 2.0)).ok()?;
    let value_hi = |z: &V2<Interval>| {
        let v = fa[0] * z.x * z.x + two * fa[1] * z.x * z.y + fa[2] * z.y * z.y;
        if v.is_empty() {
            f64::INFINITY
        } else {
            v.sup()
        }
    };
    // parts with their parameter range on `piece` (Bézier parts; an arc's
    // parts use the global bound)
    let mut todo: Vec<(Part, u32, (f64, f64))> = Part::initial(piece)?
        .into_iter()
        .map(|p| (p, 0, (0.0, 1.0)))
        .collect();
    let mut used: Vec<usize> = Vec::new();
    let mut n = 0;
    while let Some((part, depth, (t0, t1))) = todo.pop() {
        n += 1;
        if n > 4000 {
            return None;
        }
        let hull = part.hull()?;
        // the part's own error bound where the offset's map gives one
        let e_part = match part {
            Part::Bez(_) => local(t0, t1).map_or(e, |l| l.min(e)),
            Part::Arc(_) => e,
        };
        let re2 = re2_for(e_part).unwrap_or(f64::NEG_INFINITY);
        if let Some(i) = near.iter().position(|x| {
            hull.iter().all(|p| {
                let d = p.sub(x).norm2();
                !d.is_empty() && d.sup() < l2
            })
        }) {
            if !used.contains(&i) {
                used.push(i);
            }
            continue;
        }
        let (m, _) = part.mid_right_normal();
        let (_, i, t) = foot(curve_f, form, m);
        let y = iv_point(&curve[i].eval(&rational_from_f64(t)?));
        if hull.iter().all(|p| value_hi(&p.sub(&y)) < re2) {
            continue;
        }
        if depth >= 16 {
            return None;
        }
        let (l, rr) = part.halves()?;
        let tm = 0.5 * (t0 + t1);
        todo.push((rr, depth + 1, (tm, t1)));
        todo.push((l, depth + 1, (t0, tm)));
    }
    Some(used)
}
