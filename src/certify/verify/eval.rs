//! The verifier's own evaluation: second-order Taylor triples over inari
//! intervals, de Casteljau, the arc and offset/convolution formulas, and the
//! bound of one box. Nothing here is shared with the search.

use crate::scalar::interval_from_rational;
use crate::scalar::ulp;
use crate::scalar::{rational_from_f64, Interval, Rational};

// ----- Taylor triples (value, d/ds, d²/ds²) over intervals -------------------

#[derive(Clone, Copy)]
struct T3([Interval; 3]);

pub(crate) fn ic(x: i64) -> Interval {
    Interval::try_from((x as f64, x as f64)).expect("small integer")
}

impl T3 {
    fn c(v: Interval) -> T3 {
        T3([v, ic(0), ic(0)])
    }
    fn add(self, o: T3) -> T3 {
        T3([self.0[0] + o.0[0], self.0[1] + o.0[1], self.0[2] + o.0[2]])
    }
    fn sub(self, o: T3) -> T3 {
        T3([self.0[0] - o.0[0], self.0[1] - o.0[1], self.0[2] - o.0[2]])
    }
    fn mul(self, o: T3) -> T3 {
        let [a, b, c] = self.0;
        let [x, y, z] = o.0;
        T3([a * x, a * y + b * x, a * z + ic(2) * b * y + c * x])
    }
    fn k(self, s: Interval) -> T3 {
        T3([self.0[0] * s, self.0[1] * s, self.0[2] * s])
    }
    /// `1/self`; `None` if the value may vanish.
    fn inv(self) -> Option<T3> {
        let [a, b, c] = self.0;
        if a.contains(0.0) || a.is_empty() {
            return None;
        }
        let r = ic(1) / a;
        Some(T3([r, -b * r * r, ic(2) * b * b * r * r * r - c * r * r]))
    }
    /// `√self`; `None` if the value may be ≤ 0.
    fn sqrt(self) -> Option<T3> {
        let [a, b, c] = self.0;
        if a.inf().is_nan() || a.inf() <= 0.0 {
            return None;
        }
        let w = a.sqrt();
        let h = ic(1) / (ic(2) * w);
        Some(T3([w, b * h, c * h - b * b * h * h * h * ic(2)]))
    }
}

// ----- shapes ------------------------------------------------------------------

/// One piece of a shape, with interval data.
pub(crate) enum VPiece {
    /// A Bézier piece: its control points and those of its first and second
    /// derivatives (`[pts, x′, x″]`).
    Poly([Vec<[Interval; 2]>; 3]),
    /// `c + M (cos φ e0 + sin φ e0⊥)`, `M = [[m0, m1], [m2, m3]]` (`r I` for
    /// a circle of radius `r`), in the rational parameter `t = tan(φ/4)`.
    Arc {
        c: [Interval; 2],
        m: [Interval; 4],
        e0: [Interval; 2],
    },
    /// An offset or convolution piece: the curve's control points and those of
    /// its first three derivatives (`[x, x′, x″, x‴]`), `Q`, the side.
    Conv {
        pts: [Vec<[Interval; 2]>; 4],
        q: [Interval; 3],
        sigma: Interval,
    },
}

/// A shape as the verifier reads it.
pub(crate) struct VShape {
    pub pieces: Vec<VPiece>,
    /// Exact end of each piece's domain as an enclosure (1 for polynomial pieces).
    pub ends: Vec<Interval>,
    /// What the shape is, in words, from the exact data.
    pub text: String,
    /// The exact data of the shapes the radial check reads (a curve of
    /// Bézier pieces, a circular arc); `None` for the other kinds and unions.
    pub exact: Option<Exact>,
}

/// A shape's exact data, for the radial check (`radial.rs`).
// two per certificate: the size of a variant does not matter
#[allow(clippy::large_enum_variant)]
pub(crate) enum Exact {
    /// The control points of each piece.
    Curve(Vec<Vec<[Rational; 2]>>),
    /// Arcs of one circle: centre, radius, and each arc's directions
    /// `(from, to)`, counter-clockwise, in the order given (an elliptic arc
    /// whose matrix is `r I` is a circular one; a union of arcs of one circle
    /// lists its members).
    Circle {
        c: [Rational; 2],
        r: Rational,
        arcs: Vec<([Rational; 2], [Rational; 2])>,
    },
}

/// The range of a polynomial over an interval parameter.
///
/// For `t = [t₀, t₁] ⊆ [0, 1]` with `t₀ < t₁`: the hull of its Bernstein
/// coefficients on `[τ t₁, t₁] ⊇ t`, obtained by two subdivisions at *point*
/// parameters in interval arithmetic (at `t₁`, keeping `[0, t₁]`; then at
/// `τ = inf(t₀ / t₁)`, keeping `[τ, 1]` of that), so every operation is
/// outward rounded and the hull converges to the true range quadratically
/// in the width. Otherwise (a point, or a parameter outside `[0, 1]`): de
/// Casteljau at the interval itself.
fn casteljau(pts: &[[Interval; 2]], t: Interval) -> [Interval; 2] {
    let (t0, t1) = (t.inf(), t.sup());
    if !(t0 >= 0.0 && t0 < t1 && t1 <= 1.0) || pts.len() < 2 {
        return casteljau_at(pts, t);
    }
    let p1 = Interval::try_from((t1, t1)).expect("finite");
    let left = subdivide(pts, p1, true);
    let tau = (Interval::try_from((t0, t0)).expect("finite") / p1)
        .inf()
        .max(0.0);
    let sub = if tau > 0.0 {
        subdivide(
            &left,
            Interval::try_from((tau, tau)).expect("finite"),
            false,
        )
    } else {
        left
    };
    let hull = |k: usize| {
        let lo = sub.iter().map(|p| p[k].inf()).fold(f64::INFINITY, f64::min);
        let hi = sub
            .iter()
            .map(|p| p[k].sup())
            .fold(f64::NEG_INFINITY, f64::max);
        Interval::try_from((lo, hi)).unwrap_or(Interval::ENTIRE)
    };
    [hull(0), hull(1)]
}

/// The control points of the piece on `[0, t]` (`left`) or `[t, 1]`.
pub(crate) fn subdivide(pts: &[[Interval; 2]], t: Interval, left: bool) -> Vec<[Interval; 2]> {
    let n = pts.len();
    let u = ic(1) - t;
    let mut tri: Vec<[Interval; 2]> = pts.to_vec();
    let mut edge = Vec::with_capacity(n);
    edge.push(if left { tri[0] } else { tri[n - 1] });
    for level in 1..n {
        for i in 0..n - level {
            tri[i] = convex(u, tri[i], t, tri[i + 1]);
        }
        edge.push(if left { tri[0] } else { tri[n - 1 - level] });
    }
    if !left {
        edge.reverse();
    }
    edge
}

/// One de Casteljau step `(1 − t) a + t b`, with `u ⊇ 1 − t`.
///
/// The convex form, not `a + t (b − a)`: for a thin `t` its width is about
/// the widths of `a` and `b` (plus rounding), while the difference form counts
/// `a`'s width `1 + 2t` times, so `n` levels multiply the control points'
/// widths by up to `3ⁿ` and a degree-27 piece with non-dyadic control points
/// could no longer be evaluated (issue 24, item 5).
///
/// In [`ulp`] arithmetic (rounded to nearest, then one ulp outward): no
/// rounding-mode switch per operation, a third of the cost of inari's
/// products in the de Casteljau loops of high-degree pieces.
fn convex(u: Interval, a: [Interval; 2], t: Interval, b: [Interval; 2]) -> [Interval; 2] {
    let step = |x: Interval, y: Interval| ulp::add(ulp::mul(u, x), ulp::mul(t, y));
    [step(a[0], b[0]), step(a[1], b[1])]
}

/// De Casteljau at an interval parameter: the convex form for a thin
/// parameter (see [`convex`]), the difference form for a wide one (where
/// `t`'s width, not the data's, dominates and `b − a` is small).
fn casteljau_at(pts: &[[Interval; 2]], t: Interval) -> [Interval; 2] {
    let mut p: Vec<[Interval; 2]> = pts.to_vec();
    let thin = t.inf() == t.sup();
    let u = ic(1) - t;
    for n in (1..p.len()).rev() {
        for i in 0..n {
            let (a, b) = (p[i], p[i + 1]);
            p[i] = if thin {
                convex(u, a, t, b)
            } else {
                let step = |x: Interval, y: Interval| ulp::add(x, ulp::mul(t, ulp::sub(y, x)));
                [step(a[0], b[0]), step(a[1], b[1])]
            };
        }
    }
    p[0]
}

/// The Taylor triples of `P(τ(s))` for a polynomial `P` given by the control
/// points of `P`, `P′`, `P″`: value, `P′(τ) τ′`, `P″(τ) τ′² + P′(τ) τ″`.
fn poly_at(c: &[Vec<[Interval; 2]>], t: T3) -> [T3; 2] {
    let [tv, td, tdd] = t.0;
    let p0 = casteljau(&c[0], tv);
    let p1 = casteljau(&c[1], tv);
    let p2 = casteljau(&c[2], tv);
    let coord = |i: usize| T3([p0[i], p1[i] * td, p2[i] * td * td + p1[i] * tdd]);
    [coord(0), coord(1)]
}

impl VPiece {
    fn at(&self, t: T3) -> Option<[T3; 2]> {
        match self {
            VPiece::Poly(p) => Some(poly_at(p, t)),
            VPiece::Arc { c, m, e0 } => {
                let one = T3::c(ic(1));
                let t2 = t.mul(t);
                let a = one.sub(t2);
                let d = one.add(t2);
                let inv = d.mul(d).inv()?;
                let cs = a.mul(a).sub(t2.k(ic(4))).mul(inv);
                let sn = t.mul(a).k(ic(4)).mul(inv);
                // the pre-image point u = cos φ e0 + sin φ e0⊥, e0⊥ = (−e0y, e0x)
                let u = cs.k(e0[0]).sub(sn.k(e0[1]));
                let v = cs.k(e0[1]).add(sn.k(e0[0]));
                Some([
                    T3::c(c[0]).add(u.k(m[0])).add(v.k(m[1])),
                    T3::c(c[1]).add(u.k(m[2])).add(v.k(m[3])),
                ])
            }
            VPiece::Conv { pts, q, sigma } => {
                let [x, y] = poly_at(&pts[0..3], t);
                let [dx, dy] = poly_at(&pts[1..4], t);
                let (n1, n2) = (T3::c(ic(0)).sub(dy), dx);
                let m1 = n1.k(q[0]).add(n2.k(q[1]));
                let m2 = n1.k(q[1]).add(n2.k(q[2]));
                let s = n1.mul(m1).add(n2.mul(m2)).sqrt()?.inv()?;
                Some([x.add(m1.mul(s).k(*sigma)), y.add(m2.mul(s).k(*sigma))])
            }
        }
    }
}

impl VPiece {
    /// The point at the parameter enclosure `t` (tests compare it with the
    /// search's evaluation).
    #[cfg(test)]
    pub(crate) fn point_at(&self, t: Interval) -> Option<[Interval; 2]> {
        self.at(T3([t, ic(1), ic(0)]))
            .map(|[x, y]| [x.0[0], y.0[0]])
    }
}

pub(crate) fn le_rational(x: f64, r: &Rational) -> bool {
    rational_from_f64(x).is_some_and(|q| &q <= r)
}

/// Checks one box; `Ok(bound)` or the reason it fails.
#[allow(clippy::too_many_arguments)]
pub(crate) fn check_box(
    src: &VPiece,
    s0: &Rational,
    s1: &Rational,
    dst: &VPiece,
    dst_end: Interval,
    t: &Rational,
    k: &Rational,
) -> Result<f64, String> {
    let two = Rational::from_integer(2.into());
    let sc = (s0 + s1) / &two;
    let (i0, i1) = (interval_from_rational(s0), interval_from_rational(s1));
    let sbox = Interval::try_from((i0.inf(), i1.sup())).map_err(|_| "empty box".to_string())?;
    let scv = interval_from_rational(&sc);
    let (tv, kv) = (interval_from_rational(t), interval_from_rational(k));
    let tau = tv + kv * (sbox - scv);
    if !(tau.inf() >= 0.0 && tau.sup() <= dst_end.inf()) {
        return Err(format!(
            "the foot map leaves the target's parameter domain: τ(S) ⊆ [{}, {}]",
            tau.inf(),
            tau.sup()
        ));
    }
    taylor_bound(
        src,
        sbox,
        scv,
        T3([tau, kv, ic(0)]),
        T3([tv, kv, ic(0)]),
        dst,
    )
}

fn undefined() -> String {
    "the shapes cannot be evaluated on this box (undefined normal)".to_string()
}

/// `sup_{s∈S} |src(s) − dst(τ(s))|` from the Taylor triples of `τ` over the
/// box `S` and at its centre `c` (the enclosure `scv` of the exact rational
/// midpoint): the second-order Taylor bound of `|D|²`, `D = src − dst∘τ`, with
/// the mean-value meets.
fn taylor_bound(
    src: &VPiece,
    sbox: Interval,
    scv: Interval,
    tau_over: T3,
    tau_c: T3,
    dst: &VPiece,
) -> Result<f64, String> {
    // D(s) = A(s) − B(τ(s)), over the box and at its centre
    let diff = |sv: Interval, tau: T3| -> Option<[T3; 2]> {
        let a = src.at(T3([sv, ic(1), ic(0)]))?;
        let b = dst.at(tau)?;
        Some([a[0].sub(b[0]), a[1].sub(b[1])])
    };
    let over = diff(sbox, tau_over).ok_or_else(undefined)?;
    let at_c = diff(scv, tau_c).ok_or_else(undefined)?;
    let w = sbox - scv;
    // Over the box, D and D′ also lie in the mean-value forms D(c) + D′(S)(S − c)
    // and D′(c) + D″(S)(S − c); keep the meet with the direct enclosures.
    let meet = |direct: Interval, mv: Interval| {
        let m = direct.intersection(mv);
        if m.is_empty() {
            direct
        } else {
            m
        }
    };
    let tight = |o: T3, c: T3| {
        [
            meet(o.0[0], c.0[0] + o.0[1] * w),
            meet(o.0[1], c.0[1] + o.0[2] * w),
            o.0[2],
        ]
    };
    let [x, y] = [tight(over[0], at_c[0]), tight(over[1], at_c[1])];
    // g = |D|²: its value over the box, g″ = 2 (Dx′² + Dy′² + Dx Dx″ + Dy Dy″)
    let g_over = x[0].sqr() + y[0].sqr();
    let g_dd = ic(2) * (x[1].sqr() + y[1].sqr() + x[0] * x[2] + y[0] * y[2]);
    // g and g′ at the centre
    let g_c = at_c[0].mul(at_c[0]).add(at_c[1].mul(at_c[1]));
    let h = w.mag();
    let h = Interval::try_from((h, h)).map_err(|_| undefined())?;
    let curv = Interval::try_from((0.0, g_dd.sup().max(0.0))).map_err(|_| undefined())?;
    let taylor = g_c.0[0] + g_c.0[1].abs() * h + curv * h * h / ic(2);
    let g = taylor.sup().min(g_over.sup());
    if !g.is_finite() {
        return Err(undefined());
    }
    Ok(Interval::try_from((0.0, g.max(0.0)))
        .map_err(|_| undefined())?
        .sqrt()
        .sup())
}

/// Checks one box `[t₀, t₁]` of a parametric map: `φ` the cubic with Bernstein
/// coefficients `c` on it must stay in the target's domain `[0, dst_end]`;
/// `Ok(sup |src(t) − dst(φ(t))|)` over the box, or the reason it fails.
pub(crate) fn check_map_box(
    src: &VPiece,
    t0: &Rational,
    t1: &Rational,
    dst: &VPiece,
    dst_end: Interval,
    c: &[Rational; 4],
) -> Result<f64, String> {
    // every number enclosed once; the rest in interval arithmetic (exact for
    // the dyadic numbers lncert writes, outward rounded for any other)
    let ci = [0, 1, 2, 3].map(|k| interval_from_rational(&c[k]));
    if ci
        .iter()
        .any(|x| !(x.inf() >= 0.0 && x.sup() <= dst_end.inf()))
    {
        return Err(format!(
            "a coefficient of the map leaves the target's parameter domain [0, {}]",
            dst_end.inf()
        ));
    }
    let (i0, i1) = (interval_from_rational(t0), interval_from_rational(t1));
    let w = i1 - i0;
    if w.inf().is_nan() || w.inf() <= 0.0 {
        return Err("the box is too narrow to enclose its width".to_string());
    }
    let d1 = [ci[1] - ci[0], ci[2] - ci[1], ci[3] - ci[2]];
    let d2 = [d1[1] - d1[0], d1[2] - d1[1]];
    let k1 = ic(3) / w;
    let k2 = ic(6) / (w * w);
    let hull = |xs: &[Interval]| {
        let lo = xs.iter().map(|x| x.inf()).fold(f64::INFINITY, f64::min);
        let hi = xs.iter().map(|x| x.sup()).fold(f64::NEG_INFINITY, f64::max);
        Interval::try_from((lo, hi)).map_err(|_| undefined())
    };
    // over the box: the Bernstein hulls of φ, φ′ = (3/w) Δc, φ″ = (6/w²) Δ²c
    let tau_over = T3([hull(&ci)?, k1 * hull(&d1)?, k2 * hull(&d2)?]);
    // at the exact midpoint (u = 1/2): de Casteljau at 1/2
    let v = (ci[0] + ic(3) * (ci[1] + ci[2]) + ci[3]) / ic(8);
    let d = k1 * (d1[0] + ic(2) * d1[1] + d1[2]) / ic(4);
    let dd = k2 * (d2[0] + d2[1]) / ic(2);
    let tau_c = T3([v, d, dd]);
    let sbox = Interval::try_from((i0.inf(), i1.sup())).map_err(|_| "empty box".to_string())?;
    let scv = (i0 + i1) / ic(2); // encloses the exact midpoint
    taylor_bound(src, sbox, scv, tau_over, tau_c, dst)
}

/// `sup |dst′| · (hi − lo)` over `[lo, hi]` (enclosures of the ends): the
/// distance from any point of `dst` on that parameter range to `dst(lo)`.
pub(crate) fn reach(dst: &VPiece, lo: Interval, hi: Interval) -> Result<Interval, String> {
    if lo.inf() == hi.sup() {
        return Ok(ic(0));
    }
    let range = Interval::try_from((lo.inf(), hi.sup())).map_err(|_| undefined())?;
    let [x, y] = dst.at(T3([range, ic(1), ic(0)])).ok_or_else(undefined)?;
    let speed = (x.0[1].sqr() + y.0[1].sqr()).sqrt();
    let len = hi - lo;
    let r = speed * Interval::try_from((0.0, len.sup().max(0.0))).map_err(|_| undefined())?;
    if r.sup().is_finite() {
        Ok(r)
    } else {
        Err(undefined())
    }
}
