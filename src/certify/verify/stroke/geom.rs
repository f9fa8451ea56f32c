//! The stroke verifier's own interval geometry: Béziers with their first two
//! hodographs, the exact offsets and the cone arcs of `∂(x ⊕ disk r)` with
//! their derivatives, and the four box tests of the certificate (near a
//! Bézier, near an arc, strictly inside `S`, and a part of the outline between
//! a point of `S` and a point outside `S`). Every test is a mean-value
//! enclosure over inari intervals (outward rounding); nothing is shared with
//! the stroke engine. The writer ([`crate::stroke::certificate`]) calls the same
//! tests to choose its boxes, so what it writes is what this code accepts.

use super::super::Budget;
use crate::scalar::{interval_from_rational, ulp, Interval, Rational};

/// A point or vector of intervals.
pub(crate) type P = [Interval; 2];

/// The point interval `[x, x]`; the whole line when `x` is not finite (an
/// overflowed hint or bound: every test then fails, undecided, instead of
/// panicking — issue 65).
pub(crate) fn ic(x: f64) -> Interval {
    crate::scalar::point_interval(x)
}

pub(crate) fn iq(r: &Rational) -> Interval {
    interval_from_rational(r)
}

pub(crate) fn ip(p: &[Rational; 2]) -> P {
    [iq(&p[0]), iq(&p[1])]
}

// The vector helpers use the one-ulp-widened sums and products of
// `scalar::ulp` (outward enclosures without rounding-mode switches; the
// argument is in that module).
fn sub(a: P, b: P) -> P {
    [ulp::sub(a[0], b[0]), ulp::sub(a[1], b[1])]
}
fn add(a: P, b: P) -> P {
    [ulp::add(a[0], b[0]), ulp::add(a[1], b[1])]
}
fn scale(a: P, k: Interval) -> P {
    [ulp::mul(a[0], k), ulp::mul(a[1], k)]
}
fn dot(a: P, b: P) -> Interval {
    ulp::add(ulp::mul(a[0], b[0]), ulp::mul(a[1], b[1]))
}
/// The left normal `J v = (−v.y, v.x)`.
fn perp(v: P) -> P {
    [-v[1], v[0]]
}

/// Hull of two intervals.
fn hull(a: Interval, b: Interval) -> Interval {
    a.convex_hull(b)
}

/// `true` when every number of the enclosure is finite (not empty, no NaN).
fn finite(x: Interval) -> bool {
    !x.is_empty() && x.inf().is_finite() && x.sup().is_finite()
}

/// A Bézier with interval control points and its first and second hodographs.
#[derive(Clone, Debug)]
pub(crate) struct Bez {
    pub(crate) pts: Vec<P>,
    d: Vec<P>,
    dd: Vec<P>,
    /// The distance form of [`outside_near`], computed once per input piece
    /// ([`Bez::with_distance_form`]; `None` for the outline's pieces, which
    /// are never tested against): `|x − p|²` has the Bernstein coefficients
    /// `sq_k − 2 p·elev_k + |p|²` (degree `2n`), where `sq` are those of
    /// `|x|²` and `elev` the control points raised to degree `2n`.
    dform: Option<DistForm>,
    /// The control polygon's box `[lo, hi]`, its ends rounded outward
    /// (`None` if not finite).
    bbox: Option<([f64; 2], [f64; 2])>,
}

fn hodograph(p: &[P]) -> Vec<P> {
    let n = ic((p.len().max(1) - 1) as f64);
    p.windows(2).map(|w| scale(sub(w[1], w[0]), n)).collect()
}

/// de Casteljau at an interval parameter (a valid enclosure of `B(t)` for
/// every `t` in it); the zero vector for an empty list (a constant's hodograph).
fn casteljau(p: &[P], t: Interval) -> P {
    if p.is_empty() {
        return [ic(0.0), ic(0.0)];
    }
    // (a stack buffer for the usual degrees: this runs for every box)
    let mut buf = [[ic(0.0), ic(0.0)]; 16];
    let mut heap = Vec::new();
    let b: &mut [P] = if p.len() <= buf.len() {
        buf[..p.len()].copy_from_slice(p);
        &mut buf[..p.len()]
    } else {
        heap.extend_from_slice(p);
        &mut heap
    };
    // Over a parameter box of width `w`, `b_i + t (b_{i+1} − b_i)`: its
    // enclosure grows by `w |b_{i+1} − b_i|` where the convex form's grows by
    // `w (|b_i| + |b_{i+1}|)` (control points far from the origin made boxes
    // 10× narrower). At a point parameter the convex form `(1 − t) b_i +
    // t b_{i+1}`, which does not multiply the control points' own widths by
    // `1 + 2t` per level (as `certify::verify::eval` explains).
    let thin = t.inf() == t.sup();
    let u = ulp::sub(ic(1.0), t);
    for k in (1..b.len()).rev() {
        for i in 0..k {
            b[i] = if thin {
                add(scale(b[i], u), scale(b[i + 1], t))
            } else {
                add(b[i], scale(sub(b[i + 1], b[i]), t))
            };
        }
    }
    b[0]
}

/// `|x|²` and `x` at degree `2n` (see [`Bez`]'s `dform`).
#[derive(Clone, Debug)]
struct DistForm {
    sq: Vec<Interval>,
    elev: Vec<P>,
}

impl DistForm {
    fn new(pts: &[P]) -> DistForm {
        let xs: Vec<Interval> = pts.iter().map(|q| q[0]).collect();
        let ys: Vec<Interval> = pts.iter().map(|q| q[1]).collect();
        let ones = vec![ic(1.0); pts.len()];
        let sq = bprod(&xs, &xs)
            .iter()
            .zip(bprod(&ys, &ys))
            .map(|(a, b)| *a + b)
            .collect();
        let elev = bprod(&xs, &ones)
            .into_iter()
            .zip(bprod(&ys, &ones))
            .map(|(x, y)| [x, y])
            .collect();
        DistForm { sq, elev }
    }
}

impl Bez {
    /// A piece of the input: with the distance form of [`outside_near`].
    pub(crate) fn with_distance_form(pts: Vec<P>) -> Bez {
        let dform = Some(DistForm::new(&pts));
        Bez {
            dform,
            ..Bez::new(pts)
        }
    }

    /// A piece (of the outline) without the distance form.
    pub(crate) fn new(pts: Vec<P>) -> Bez {
        let d = hodograph(&pts);
        let dd = hodograph(&d);
        let bbox = pts.iter().try_fold(
            [[f64::INFINITY; 2], [f64::NEG_INFINITY; 2]],
            |[mut lo, mut hi], q| {
                for i in 0..2 {
                    if !finite(q[i]) {
                        return None;
                    }
                    lo[i] = lo[i].min(q[i].inf());
                    hi[i] = hi[i].max(q[i].sup());
                }
                Some([lo, hi])
            },
        );
        let bbox = bbox.map(|[lo, hi]| (lo, hi));
        Bez {
            pts,
            d,
            dd,
            dform: None,
            bbox,
        }
    }
    pub(crate) fn at(&self, t: Interval) -> P {
        casteljau(&self.pts, t)
    }
    /// The control polygon's box, its ends rounded outward (`None` if not
    /// finite): it holds the piece.
    pub(crate) fn bbox(&self) -> Option<([f64; 2], [f64; 2])> {
        self.bbox
    }
    /// The work of one enclosure of the piece over a box (de Casteljau
    /// steps of its points and hodographs), in the budget's units.
    pub(crate) fn work(&self) -> u64 {
        let n = self.pts.len() as u64;
        n * n
    }
    pub(crate) fn d_at(&self, t: Interval) -> P {
        casteljau(&self.d, t)
    }
    /// The control points of the restriction to `[a, b]` (blossom values
    /// `B(a, …, a, b, …, b)`), each enclosed: the left part at `b` (the
    /// curve on `[0, b]`), then that part's right part at `a / b` (its
    /// blossom values `B(a^{n−k} b^k)`), each de Casteljau step in interval
    /// arithmetic, so with `a / b` enclosed the exact points are inside.
    pub(crate) fn restrict(&self, a: Interval, b: Interval) -> Vec<P> {
        let n = self.pts.len() - 1;
        let step = |q: &mut [P], t: Interval, level: usize| {
            let u = ulp::sub(ic(1.0), t);
            for i in 0..=(n - level) {
                q[i] = add(scale(q[i], u), scale(q[i + 1], t));
            }
        };
        let mut q = self.pts.clone();
        let mut left = Vec::with_capacity(n + 1);
        left.push(q[0]);
        for level in 1..=n {
            step(&mut q, b, level);
            left.push(q[0]);
        }
        if a.inf() == 0.0 && a.sup() == 0.0 {
            return left;
        }
        let t = a / b;
        let mut right = left.clone();
        for level in 1..=n {
            step(&mut left, t, level);
            right[n - level] = left[n - level];
        }
        right
    }
}

/// A curve of `∂S`'s cover: its value at a point parameter and its
/// derivative over an interval, each enclosed (`None`: undefined there).
pub(crate) trait Path: Sync {
    fn val(&self, t: Interval) -> Option<P>;
    fn der(&self, t: Interval) -> Option<P>;
    /// The work of one mean-value enclosure over a box, in the budget's
    /// units (see `budget`).
    fn work(&self) -> u64 {
        1
    }
}

/// The exact offset `x(t) + σ r J x′(t)/|x′(t)|` of one input piece.
pub(crate) struct Side<'a> {
    pub(crate) b: &'a Bez,
    /// `+1` left (`J x′`), `−1` right.
    pub(crate) sigma: f64,
    pub(crate) r: Interval,
}

impl Path for Side<'_> {
    fn val(&self, t: Interval) -> Option<P> {
        let x = self.b.at(t);
        let d = self.b.d_at(t);
        let n2 = dot(d, d);
        if !finite(n2) || n2.inf() <= 0.0 {
            return None;
        }
        let k = self.r * ic(self.sigma) / n2.sqrt();
        let e = add(x, scale(perp(d), k));
        (finite(e[0]) && finite(e[1])).then_some(e)
    }
    fn der(&self, t: Interval) -> Option<P> {
        let d = self.b.d_at(t);
        let dd = casteljau(&self.b.dd, t);
        let n2 = dot(d, d);
        if !finite(n2) || n2.inf() <= 0.0 {
            return None;
        }
        let len = n2.sqrt();
        // (x′/|x′|)′ = x″/|x′| − x′ (x′·x″)/|x′|³
        let nd = sub(scale(dd, ic(1.0) / len), scale(d, dot(d, dd) / (n2 * len)));
        let e = add(d, scale(perp(nd), self.r * ic(self.sigma)));
        (finite(e[0]) && finite(e[1])).then_some(e)
    }
    fn work(&self) -> u64 {
        self.b.work()
    }
}

/// The arc `c + r d(λ)/|d(λ)|`, `d(λ) = (1 − λ) a + λ b`, `λ ∈ [0, 1]`: half
/// of a cap or join cone (`a`, `b` exact rational directions less than `π`
/// apart, so `d` never vanishes).
pub(crate) struct ConeArc {
    pub(crate) c: P,
    pub(crate) r: Interval,
    pub(crate) a: P,
    pub(crate) b: P,
}

impl Path for ConeArc {
    fn val(&self, t: Interval) -> Option<P> {
        let d = add(self.a, scale(sub(self.b, self.a), t));
        let n2 = dot(d, d);
        if !finite(n2) || n2.inf() <= 0.0 {
            return None;
        }
        let p = add(self.c, scale(d, self.r / n2.sqrt()));
        (finite(p[0]) && finite(p[1])).then_some(p)
    }
    fn der(&self, t: Interval) -> Option<P> {
        let d = add(self.a, scale(sub(self.b, self.a), t));
        let dd = sub(self.b, self.a);
        let n2 = dot(d, d);
        if !finite(n2) || n2.inf() <= 0.0 {
            return None;
        }
        let len = n2.sqrt();
        let v = sub(scale(dd, ic(1.0) / len), scale(d, dot(d, dd) / (n2 * len)));
        let p = scale(v, self.r);
        (finite(p[0]) && finite(p[1])).then_some(p)
    }
}

/// A parameter box `[t0, t1]` of a family, enclosed: the box, its midpoint
/// (a point interval when the ends are floats) and `I − m`.
pub(crate) struct BoxT {
    pub(crate) all: Interval,
    pub(crate) mid: Interval,
    pub(crate) off: Interval,
}

impl BoxT {
    pub(crate) fn new(t0: &Rational, t1: &Rational) -> BoxT {
        // the midpoint enclosed from the ends' enclosures (exact, a point,
        // for float ends): the mean-value form holds for any enclosure of it
        let (a, b) = (iq(t0), iq(t1));
        let all = hull(a, b);
        let mid = (a + b) * ic(0.5);
        BoxT {
            all,
            mid,
            off: all - mid,
        }
    }
}

/// The mean-value enclosure of `path` over the box: `val(m) + der(I)(I − m)`,
/// with `val(m)` and `der(I)`.
fn mean_value(path: &dyn Path, bx: &BoxT) -> Option<(P, P, P)> {
    let v = path.val(bx.mid)?;
    let d = path.der(bx.all)?;
    Some((add(v, scale(d, bx.off)), v, d))
}

fn bad(s: &str) -> String {
    format!("{s} is undefined or not finite on the box (a singular input piece?)")
}

/// `sup |path(t) − L(s + k (t − m))|` over the box, for a Bézier `L`; an
/// error when the foot map leaves `[0, 1]` or the bound exceeds `tol2` (the
/// square of the tolerance, enclosed).
pub(crate) fn near_bezier(
    path: &dyn Path,
    bx: &BoxT,
    l: &Bez,
    s: &Rational,
    k: &Rational,
    tol2: Interval,
    metric: Option<&[[Interval; 2]; 2]>,
) -> Result<f64, String> {
    let (si, ki) = (iq(s), iq(k));
    let tau = si + ki * bx.off;
    if !(tau.inf() >= 0.0 && tau.sup() <= 1.0) {
        return Err(format!(
            "the foot map s + k (t − m) reaches [{:e}, {:e}], outside [0, 1]",
            tau.inf(),
            tau.sup()
        ));
    }
    let v = path.val(bx.mid).ok_or_else(|| bad("the boundary point"))?;
    let d = path
        .der(bx.all)
        .ok_or_else(|| bad("the boundary tangent"))?;
    let gm = sub(v, l.at(si));
    let gd = sub(d, scale(l.d_at(tau), ki));
    let g = add(gm, scale(gd, bx.off));
    // an elliptical pen's pre-images: the distance of the images under M
    let g = match metric {
        Some(m) => [
            m[0][0] * g[0] + m[0][1] * g[1],
            m[1][0] * g[0] + m[1][1] * g[1],
        ],
        None => g,
    };
    let n2 = g[0].sqr() + g[1].sqr();
    if !finite(n2) || n2.sup() > tol2.inf() {
        return Err(format!(
            "distance to the outline piece up to {:e}, above the tolerance",
            n2.sup().sqrt()
        ));
    }
    Ok(sqrt_up(n2.sup()))
}

/// An exact arc of the outline, counter-clockwise from `u` to `v` (radius
/// vectors; `u = v`: the whole circle).
pub(crate) struct ArcT {
    pub(crate) c: P,
    pub(crate) rho: Interval,
    pub(crate) u: P,
    pub(crate) v: P,
    /// `cross(u, v)` exactly: its sign, and whether `u = v`.
    pub(crate) sign: i8,
    pub(crate) full: bool,
}

impl ArcT {
    /// Every direction of the box `w` lies in the arc's angular range (proven).
    fn contains(&self, w: P) -> bool {
        if self.full {
            return true;
        }
        let cr = |a: P, b: P| a[0] * b[1] - a[1] * b[0];
        let (cu, cv) = (cr(self.u, w), cr(w, self.v));
        match self.sign {
            1 => cu.inf() >= 0.0 && cv.inf() >= 0.0,
            -1 => cu.inf() >= 0.0 || cv.inf() >= 0.0,
            // a half circle: `u = −v`
            _ => cu.inf() >= 0.0,
        }
    }
}

/// `sup dist(path(t), arc)` over the box: the direction from the centre is
/// proven inside the arc's range, and `||p − c| − ρ| = |q|/(|p − c| + ρ)`
/// with `q = |p − c|² − ρ²` enclosed by its mean value form. Otherwise (a
/// box at an end of the arc, whose directions straddle the end's), the
/// distance to the nearer end point of the arc, which is a point of it.
pub(crate) fn near_arc(path: &dyn Path, bx: &BoxT, a: &ArcT, tol: Interval) -> Result<f64, String> {
    let (all, v, d) = mean_value(path, bx).ok_or_else(|| bad("the boundary point"))?;
    let w = sub(all, a.c);
    if !a.contains(w) {
        let to_end = |e: P| {
            let g = sub(w, e);
            sqrt_up(dot(g, g).sup())
        };
        let b = to_end(a.u).min(to_end(a.v));
        if b.is_finite() && b <= tol.inf() {
            return Ok(b);
        }
        return Err("the boundary points' directions are not proven inside the arc's range, nor near its ends".into());
    }
    let wm = sub(v, a.c);
    let q = dot(wm, wm) - a.rho.sqr() + ic(2.0) * dot(w, d) * bx.off;
    let num = ic(q.inf().abs().max(q.sup().abs()));
    let lo = (a.rho.sqr() + q).inf().max(0.0);
    let den = a.rho + ic(lo).sqrt();
    let b = num / den;
    if !finite(b) || b.sup() > tol.inf() {
        return Err(format!(
            "distance to the outline arc up to {:e}, above the tolerance",
            b.sup()
        ));
    }
    Ok(b.sup())
}

/// `|path(t) − y|² < r²` on the whole box: every boundary point of the box is
/// strictly inside `S` (within less than `r` of the input point `y`).
pub(crate) fn inside(path: &dyn Path, bx: &BoxT, y: P, r2: Interval) -> Result<(), String> {
    let (all, v, d) = mean_value(path, bx).ok_or_else(|| bad("the boundary point"))?;
    let wm = sub(v, y);
    let q = dot(wm, wm) + ic(2.0) * dot(sub(all, y), d) * bx.off;
    if finite(q) && q.sup() < r2.inf() {
        Ok(())
    } else {
        Err(format!(
            "distance² to the input point up to {:e}, not proven below r² {:e}",
            q.sup(),
            r2.inf()
        ))
    }
}

/// `|p − x(u)|² > r²` for every `u ∈ [0, 1]` and every input piece: `p` is
/// outside `S`. Bernstein coefficients of `|x − p|² − r²`, subdivided (depth
/// ≤ 24, at most 4 096 leaves per piece) until all are positive.
///
/// With a hint `(j, u)`: the point of piece `j` nearest to `p`
/// is about `x_j(u)`. That piece's form is split at `u` first: the distance
/// is least there, and each side then needs far fewer halvings. The hint
/// only orders the work; `[0, u]` and `[u, 1]` cover `[0, 1]` whatever `u`.
#[cfg(test)]
pub(crate) fn outside_near(
    p: P,
    input: &[Bez],
    r2: Interval,
    hint: Option<(usize, f64)>,
) -> Result<(), String> {
    for (j, b) in input.iter().enumerate() {
        let h = hint.filter(|h| h.0 == j).map(|h| h.1);
        outside_bez(p, j, b, r2, h, &Budget::unlimited())?;
    }
    Ok(())
}

/// [`outside_near`] for one Bézier piece `j`, with the hint's parameter
/// when the hint names this piece.
pub(crate) fn outside_bez(
    p: P,
    j: usize,
    b: &Bez,
    r2: Interval,
    hint: Option<f64>,
    budget: &Budget,
) -> Result<(), String> {
    // (called with r2 = (r + μ)² for a disk of radius μ about p)
    let split = |g: Vec<Interval>| -> Result<(), String> {
        let n = g.len() as u64;
        budget.charge(n * n).map_err(|e| e.to_string())?;
        match hint {
            Some(u) if u > 0.0 && u < 1.0 => {
                let (a, b) = split_at(&g, ic(u));
                positive(a, j, budget)?;
                positive(b, j, budget)
            }
            _ => positive(g, j, budget),
        }
    };
    // the control polygon's box: farther than r from p ⇒ the piece is
    if let Some((lo, hi)) = b.bbox {
        if box_farther(lo, hi, p, r2) {
            return Ok(());
        }
    }
    // the form computed once per piece first; the coefficients of
    // `x − p` squared when it does not decide (they are tighter far
    // from the origin)
    if let Some(f) = &b.dform {
        let p2 = dot(p, p);
        let g: Vec<Interval> =
            f.sq.iter()
                .zip(&f.elev)
                .map(|(s, e)| {
                    let two_pe = ulp::mul(ic(2.0), dot(p, *e));
                    ulp::sub(ulp::add(ulp::sub(*s, two_pe), p2), r2)
                })
                .collect();
        if split(g).is_ok() {
            return Ok(());
        }
    }
    let xs: Vec<Interval> = b.pts.iter().map(|q| ulp::sub(q[0], p[0])).collect();
    let ys: Vec<Interval> = b.pts.iter().map(|q| ulp::sub(q[1], p[1])).collect();
    let g: Vec<Interval> = bprod(&xs, &xs)
        .iter()
        .zip(bprod(&ys, &ys))
        .map(|(a, c)| ulp::sub(ulp::add(*a, c), r2))
        .collect();
    split(g)
}

/// `|p − x(λ)|² > r2` for every point of the input arc `j`,
/// `x = c + ρ d/|d|` over the directions `d` between `a` and `b` (less than
/// `π` apart, turning the way `turn` says): every point of the enclosure `p`
/// is farther than `R = √r2` from the arc. Either from the whole circle
/// (`|p − c| > ρ + R`, or `|p − c| < ρ − R`), or `p − c` is strictly outside
/// the closed sector of the arc's directions — then the distance to the
/// circle's point of direction `θ`, `|p − c|² + ρ² − 2ρ|p − c| cos(θ − φ)`,
/// is least at an end of the arc's range of `θ`, which does not hold `φ`
/// — and both end points are farther than `R`.
pub(crate) fn outside_arc(
    p: P,
    j: usize,
    arc: &ConeArc,
    turn: f64,
    r2: Interval,
) -> Result<(), String> {
    let e = sub(p, arc.c);
    let e2 = dot(e, e);
    let big_r = r2.sqrt();
    let far = ulp::add(arc.r, big_r).sqr();
    let near = ulp::sub(arc.r, big_r);
    if !(finite(e2) && finite(far) && finite(near)) {
        return Err(format!("input arc {j}: not finite"));
    }
    if e2.inf() > far.sup() || (near.inf() > 0.0 && e2.sup() < near.sqr().inf()) {
        return Ok(());
    }
    let cr = |u: P, v: P| ulp::sub(ulp::mul(u[0], v[1]), ulp::mul(u[1], v[0]));
    let s = ic(turn);
    let before = ulp::mul(s, cr(arc.a, e));
    let after = ulp::mul(s, cr(e, arc.b));
    let outside_sector = before.sup() < 0.0 || after.sup() < 0.0;
    let end_far = |d: P| {
        let v = sub(e, d);
        let v2 = dot(v, v);
        finite(v2) && v2.inf() > r2.sup()
    };
    if outside_sector && end_far(arc.a) && end_far(arc.b) {
        return Ok(());
    }
    Err(format!(
        "the point is not proven farther than r from input arc {j}"
    ))
}

/// The box `[lo, hi]` is farther than `√r2` from every point of `p`: its
/// squared distance, bounded below in floats (each rounded result stepped
/// down once, which is below the exact value under rounding to nearest),
/// exceeds `r2`. `false` when `p` or `r2` is empty or not finite.
pub(crate) fn box_farther(lo: [f64; 2], hi: [f64; 2], p: P, r2: Interval) -> bool {
    if !(finite(p[0]) && finite(p[1]) && finite(r2)) {
        return false;
    }
    let gap = |i: usize| {
        let below = (lo[i] - p[i].sup()).next_down();
        let above = (p[i].inf() - hi[i]).next_down();
        below.max(above).max(0.0)
    };
    let (g0, g1) = (gap(0), gap(1));
    ((g0 * g0).next_down() + (g1 * g1).next_down()).next_down() > r2.sup()
}

/// The Bernstein coefficients of `g` restricted to `[0, t]` and `[t, 1]`
/// (de Casteljau at the point `t`), each enclosed.
fn split_at(g: &[Interval], t: Interval) -> (Vec<Interval>, Vec<Interval>) {
    let mut w = g.to_vec();
    let n = w.len();
    let u = ulp::sub(ic(1.0), t);
    let mut left = Vec::with_capacity(n);
    let mut right = Vec::with_capacity(n);
    for k in 0..n {
        left.push(w[0]);
        right.push(w[n - 1 - k]);
        for i in 0..(n - 1 - k) {
            w[i] = ulp::add(ulp::mul(w[i], u), ulp::mul(w[i + 1], t));
        }
    }
    right.reverse();
    (left, right)
}

/// Every Bernstein coefficient of `g` proven positive after subdivision;
/// each subdivision charges `n²` units of `budget` (`n` coefficients).
fn positive(g: Vec<Interval>, j: usize, budget: &Budget) -> Result<(), String> {
    let n = g.len() as u64;
    let mut stack = vec![(g, 0u32)];
    let mut leaves = 0usize;
    while let Some((g, depth)) = stack.pop() {
        if g.iter().all(|c| finite(*c) && c.inf() > 0.0) {
            continue;
        }
        let (first, last) = (g[0], g[g.len() - 1]);
        if first.sup() <= 0.0 || last.sup() <= 0.0 {
            return Err(format!("the point is within r of input piece {j}"));
        }
        leaves += 1;
        if depth >= 24 || leaves > 4096 {
            return Err(format!(
                "the point is not proven farther than r from input piece {j}"
            ));
        }
        budget.charge(n * n).map_err(|e| e.to_string())?;
        let (a, b) = split_at(&g, ic(0.5));
        stack.push((a, depth + 1));
        stack.push((b, depth + 1));
    }
    Ok(())
}

/// Bernstein coefficients of a product (degrees add).
pub(crate) fn bprod(a: &[Interval], b: &[Interval]) -> Vec<Interval> {
    let (m, n) = (a.len() - 1, b.len() - 1);
    // binomials enclosed (beyond 2⁵³ they are not floats)
    let binom = |n: usize| -> Vec<Interval> {
        let mut c = vec![ic(1.0); n + 1];
        for k in 1..n {
            c[k] = c[k - 1] * ic((n + 1 - k) as f64) / ic(k as f64);
        }
        c
    };
    let (bm, bn, bmn) = (binom(m), binom(n), binom(m + n));
    let mut out = vec![ic(0.0); m + n + 1];
    for i in 0..=m {
        for j in 0..=n {
            let c = ulp::mul(ulp::mul(bm[i], bn[j]), ulp::mul(a[i], b[j]));
            out[i + j] = ulp::add(out[i + j], c);
        }
    }
    for (k, o) in out.iter_mut().enumerate() {
        *o /= bmn[k];
    }
    out
}

/// The points whose convex hull holds one part of the outline.
pub(crate) type Hull = Vec<P>;

/// The hull of a counter-clockwise minor sub-arc between the radius
/// directions `d0`, `d1` (exact, `cross > 0`, `dot > 0` checked by the
/// caller): its ends and the meeting point of its end tangents.
pub(crate) fn arc_hull(c: P, rho: Interval, d0: P, d1: P) -> Option<Hull> {
    let u0 = scale(d0, ic(1.0) / dot(d0, d0).sqrt());
    let u1 = scale(d1, ic(1.0) / dot(d1, d1).sqrt());
    let apex = add(c, scale(add(u0, u1), rho / (ic(1.0) + dot(u0, u1))));
    let h = vec![add(c, scale(u0, rho)), apex, add(c, scale(u1, rho))];
    h.iter().all(|q| finite(q[0]) && finite(q[1])).then_some(h)
}

/// `max(|q − y| − r, |q − w| − μ, 0)` over the hull points `q`, enclosed
/// (its sup). The closed disk `B(y, r)` lies in `S` (`y` on the curve) and
/// the closed disk `B(w, μ)` outside it (checked by the caller), so the
/// segment between their points nearest to `q` meets `∂S`, within that
/// distance of `q`; both terms are convex in `q`, so their maximum over the
/// part is at a hull point.
pub(crate) fn part_bound(hull: &Hull, inside: Core, r: Interval, w: P, mu: Interval) -> f64 {
    let mut m = 0.0f64;
    for q in hull {
        for (z, rad) in [(inside.near(*q), r), (w, mu)] {
            let e = sub(*q, z);
            let d = ulp::sub(ulp::add(ulp::sqr(e[0]), ulp::sqr(e[1])).sqrt(), rad);
            m = m.max(if finite(d) { d.sup() } else { f64::INFINITY });
        }
    }
    m
}

/// The core of a part's set in `S`: a point `y` of the curve (the set is the
/// disk `B(y, r)`) or a segment `[a, b]` of a straight input piece (the
/// capsule of radius `r` about it).
#[derive(Clone, Copy)]
pub(crate) enum Core {
    Point(P),
    Segment(P, P),
}

impl Core {
    /// An enclosure of one point of the core (the one nearest to `q`, up to
    /// rounding): `|q − z| ≥ dist(q, core)` for the exact point `z` inside.
    fn near(&self, q: P) -> P {
        match *self {
            Core::Point(y) => y,
            // any t in [0, 1] names a point of the segment; the float
            // projection only chooses which
            Core::Segment(a, b) => add(a, scale(sub(b, a), ic(segment_param(a, b, q)))),
        }
    }
}

/// The float parameter in `[0, 1]` of the point of the segment `[a, b]`
/// nearest to `q` (from the enclosures' midpoints; 0 when undefined). It only
/// chooses a point or orders work: every use is sound for any value in `[0, 1]`.
pub(crate) fn segment_param(a: P, b: P, q: P) -> f64 {
    let (dx, dy) = (b[0].mid() - a[0].mid(), b[1].mid() - a[1].mid());
    let t = ((q[0].mid() - a[0].mid()) * dx + (q[1].mid() - a[1].mid()) * dy) / (dx * dx + dy * dy);
    if t.is_finite() {
        t.clamp(0.0, 1.0)
    } else {
        0.0
    }
}

/// `√x` rounded up (for reporting a bound from its square's sup).
pub(crate) fn sqrt_up(x: f64) -> f64 {
    x.sqrt().next_up()
}

#[cfg(test)]
mod overflow_tests {
    use super::*;

    /// Issue 65: a boundary derivative near the top of the float range made
    /// `dot(w, d)` overflow and `near_arc` panicked building a point
    /// interval from ∞. It is now an ordinary failure of the box.
    #[test]
    fn near_arc_with_overflowing_enclosures_fails_without_panicking() {
        assert_eq!(ic(f64::INFINITY), Interval::ENTIRE);
        assert_eq!(ic(f64::NAN), Interval::ENTIRE);
        let path = ConeArc {
            c: [ic(0.0), ic(0.0)],
            r: ic(2e299),
            a: [ic(1e-100), ic(0.0)],
            b: [ic(0.0), ic(1e-100)],
        };
        let arc = ArcT {
            c: [ic(-5e299), ic(-5e299)],
            rho: ic(1e299),
            u: [ic(1.0), ic(0.0)],
            v: [ic(1.0), ic(0.0)],
            sign: 0,
            full: true,
        };
        let t = |x: f64| crate::scalar::rational_from_f64(x).unwrap();
        let bx = BoxT::new(&t(0.0), &t(0.5));
        assert!(near_arc(&path, &bx, &arc, ic(1e296)).is_err());
    }

    /// A family that ends exactly where an outline arc begins, on the same
    /// circle: its last boxes straddle the arc's first direction, and are
    /// accepted by their distance to the arc's end point, which is a point
    /// of the outline; a box reaching farther than TOL from that end is not.
    #[test]
    fn boxes_at_an_arc_end_are_near_by_the_end_point() {
        // the family: the unit quarter circle from (1, 0) to (0, 1)
        let path = ConeArc {
            c: [ic(0.0), ic(0.0)],
            r: ic(1.0),
            a: [ic(1.0), ic(0.0)],
            b: [ic(0.0), ic(1.0)],
        };
        // the outline arc: the next quarter, from (0, 1) to (−1, 0)
        let arc = ArcT {
            c: [ic(0.0), ic(0.0)],
            rho: ic(1.0),
            u: [ic(0.0), ic(1.0)],
            v: [ic(-1.0), ic(0.0)],
            sign: 1,
            full: false,
        };
        let t = |x: f64| crate::scalar::rational_from_f64(x).unwrap();
        let end = BoxT::new(&t(1.0 - 2f64.powi(-30)), &t(1.0));
        let b = near_arc(&path, &end, &arc, ic(1e-6)).expect("near the end point");
        assert!(b > 0.0 && b < 1e-8, "{b}");
        // farther than TOL from the end: neither in the range nor near an end
        let long = BoxT::new(&t(0.5), &t(1.0));
        assert!(near_arc(&path, &long, &arc, ic(1e-6)).is_err());
        assert!(near_arc(&path, &end, &arc, ic(1e-12)).is_err());
    }
}
