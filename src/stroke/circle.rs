//! Exact circular arcs for outlines: rational points exactly on a circle,
//! angle-range tests, the crossings of a Bézier piece with an arc, and the
//! exact area term of an arc.
//!
//! An [`Arc`] has a rational centre and radius and **rational end points that
//! lie exactly on its circle**: `|from − c|² = r²` holds in exact arithmetic.
//! Such points come from the rational parametrisation of the circle,
//! `c + r ((1 − u²)/(1 + u²), 2u/(1 + u²))` with rational `u` ([`snap`]), so
//! an arc can be split and joined to polynomial pieces at exact shared points.

use crate::curve::{bernstein_product, Bezier, V2};
use crate::poly::{isolate_roots, refine_root, Poly, Span};
use crate::scalar::{
    atan_enclosure, interval_from_rational, rational_from_f64, Interval, Rational, Scalar,
};
use num_traits::{One, Signed, Zero};

/// A circular arc with exact end points on its circle.
#[derive(Clone, Debug, PartialEq)]
pub struct Arc {
    /// Centre.
    pub center: V2<Rational>,
    /// Radius (`> 0`).
    pub radius: Rational,
    /// Start point (exactly on the circle).
    pub from: V2<Rational>,
    /// End point (exactly on the circle).
    pub to: V2<Rational>,
    /// Travels clockwise from `from` to `to`.
    pub clockwise: bool,
}

fn half() -> Rational {
    Rational::new(1.into(), 2.into())
}

/// A rational point exactly on the circle `(c, r)` near the ray from `c` in
/// the (approximate) direction `dir`: the rational parametrisation at a
/// tangent of the half angle rounded to `2⁻⁴⁰`. `None` for a zero or
/// non-finite direction.
pub fn snap(c: &V2<Rational>, r: &Rational, dir: (f64, f64)) -> Option<V2<Rational>> {
    let th = dir.1.atan2(dir.0);
    if !th.is_finite() || (dir.0 == 0.0 && dir.1 == 0.0) {
        return None;
    }
    // use the half-turn on the left side so that |u| ≤ tan(π/4) = 1
    let (th, flip) = if th.abs() <= std::f64::consts::FRAC_PI_2 {
        (th, false)
    } else if th > 0.0 {
        (th - std::f64::consts::PI, true)
    } else {
        (th + std::f64::consts::PI, true)
    };
    let u = ((th / 2.0).tan() * 2f64.powi(40)).round() / 2f64.powi(40);
    let u = rational_from_f64(u)?;
    let one = <Rational as One>::one();
    let den = &one + &u * &u;
    let cx = (&one - &u * &u) / &den;
    let sy = (&u + &u) / &den;
    let (cx, sy) = if flip { (-cx, -sy) } else { (cx, sy) };
    Some(V2::new(&c.x + r * cx, &c.y + r * sy))
}

/// True when `p` lies exactly on the circle.
pub fn on_circle(c: &V2<Rational>, r: &Rational, p: &V2<Rational>) -> bool {
    p.sub(c).norm2() == r * r
}

/// The range test from the signs of `a × v` and `v × b`, for a range below
/// π (`minor`) or of π or more.
fn in_ccw_range_signs(
    minor: bool,
    av: crate::scalar::Sign,
    vb: crate::scalar::Sign,
) -> Option<bool> {
    use crate::scalar::Sign;
    let nonneg = |s: Sign| match s {
        Sign::Positive | Sign::Zero => Some(true),
        Sign::Negative => Some(false),
        Sign::Unknown => None,
    };
    let (av, vb) = (nonneg(av), nonneg(vb));
    if minor {
        match (av, vb) {
            (Some(false), _) | (_, Some(false)) => Some(false),
            (Some(true), Some(true)) => Some(true),
            _ => None,
        }
    } else {
        match (av, vb) {
            (Some(true), _) | (_, Some(true)) => Some(true),
            (Some(false), Some(false)) => Some(false),
            _ => None,
        }
    }
}

impl Arc {
    /// The counter-clockwise start and end directions (from the centre).
    pub fn ccw_dirs(&self) -> (V2<Rational>, V2<Rational>) {
        let (a, b) = (self.from.sub(&self.center), self.to.sub(&self.center));
        if self.clockwise {
            (b, a)
        } else {
            (a, b)
        }
    }
    /// Whether the direction `v` from the centre is within the arc.
    pub fn contains_dir<S: Scalar>(&self, v: &V2<S>) -> Option<bool> {
        let (a, b) = self.ccw_dirs();
        // the shape of the range is decided exactly, only `v` is uncertain
        let ab = a.cross(&b);
        let (af, bf) = (a.map(S::from_rational), b.map(S::from_rational));
        if ab.is_positive() {
            let av = af.cross(v).sign();
            let vb = v.cross(&bf).sign();
            return in_ccw_range_signs(true, av, vb);
        }
        if ab.is_zero() && a.dot(&b).is_positive() {
            // a degenerate (zero) arc: not produced by the outline code
            return None;
        }
        in_ccw_range_signs(false, af.cross(v).sign(), v.cross(&bf).sign())
    }
    /// The same arc travelled the other way.
    pub fn reversed(&self) -> Arc {
        Arc {
            from: self.to.clone(),
            to: self.from.clone(),
            clockwise: !self.clockwise,
            ..self.clone()
        }
    }
    /// A rational point on the circle strictly inside the arc, near its middle
    /// angle (`None` for a degenerate arc).
    pub fn midpoint(&self) -> Option<V2<Rational>> {
        let (a, b) = self.ccw_dirs();
        let (af, bf) = (a.map(Scalar::approx), b.map(Scalar::approx));
        let ta = af.y.atan2(af.x);
        let mut tb = bf.y.atan2(bf.x);
        if tb <= ta {
            tb += 2.0 * std::f64::consts::PI;
        }
        let tm = 0.5 * (ta + tb);
        let m = snap(&self.center, &self.radius, (tm.cos(), tm.sin()))?;
        let v = m.sub(&self.center);
        let strictly = a.cross(&v).is_positive() && v.cross(&b).is_positive()
            || (!a.cross(&b).is_positive()
                && (a.cross(&v).is_positive() || v.cross(&b).is_positive()));
        if strictly && m != self.from && m != self.to {
            Some(m)
        } else {
            None
        }
    }
    /// Splits at a point of the arc (exactly on the circle, inside the range).
    pub fn split_at(&self, m: &V2<Rational>) -> (Arc, Arc) {
        (
            Arc {
                to: m.clone(),
                ..self.clone()
            },
            Arc {
                from: m.clone(),
                ..self.clone()
            },
        )
    }
    /// Travel angle below π (exact test).
    pub fn is_minor(&self) -> bool {
        let (a, b) = self.ccw_dirs();
        a.cross(&b).is_positive()
    }
    /// For a minor arc: the control polygon `[from, apex, to]` whose convex
    /// hull holds the arc (the apex is where the end tangents meet:
    /// `c + (a + b)·2r²/|a + b|²`, exact).
    pub fn hull(&self) -> Option<[V2<Rational>; 3]> {
        if !self.is_minor() {
            return None;
        }
        let (a, b) = (self.from.sub(&self.center), self.to.sub(&self.center));
        let s = a.add(&b);
        let n2 = s.norm2();
        if n2.is_zero() {
            return None;
        }
        let k = (&self.radius * &self.radius * Rational::from_integer(2.into())) / n2;
        let apex = self.center.add(&s.scale(&k));
        Some([self.from.clone(), apex, self.to.clone()])
    }
    /// Minor sub-arcs covering the arc, split at rational points of the circle.
    pub fn minor_parts(&self) -> Option<Vec<Arc>> {
        let mut out = Vec::new();
        let mut todo = vec![self.clone()];
        while let Some(a) = todo.pop() {
            // split arcs of a quarter turn or more: keeps the hulls small
            let (u, v) = a.ccw_dirs();
            if a.is_minor() && u.dot(&v).is_positive() {
                out.push(a);
            } else {
                if out.len() + todo.len() > 64 {
                    return None;
                }
                let m = a.midpoint()?;
                let (l, r) = a.split_at(&m);
                todo.push(r);
                todo.push(l);
            }
        }
        Some(out)
    }
    /// `½∫(x dy − y dx)` along the arc, enclosed: `½ cross(c, to − from) ± ½ r² Δφ`.
    pub fn area_term(&self) -> Option<Interval> {
        let poly = self.center.cross(&self.to.sub(&self.from)) * half();
        let phi = self.sweep();
        let r2 = interval_from_rational(&(&self.radius * &self.radius * half()));
        let sector = r2 * phi;
        let poly = interval_from_rational(&poly);
        Some(if self.clockwise {
            poly - sector
        } else {
            poly + sector
        })
    }
    /// The angle the arc turns through, in `(0, 2π]` (a full turn when
    /// `from == to`), enclosed: twice the half angle `h = atan2(s, k)`,
    /// `s = a × b`, `k = r² + a·b` (`a`, `b` the counter-clockwise end
    /// directions), whose branch the exact signs of `s` and `k` decide.
    pub fn sweep(&self) -> Interval {
        let (a, b) = self.ccw_dirs();
        let s = a.cross(&b);
        let k = &self.radius * &self.radius + a.dot(&b);
        let pi = Interval::PI;
        let two = Interval::try_from((2.0, 2.0)).expect("finite");
        let h = if s.is_zero() {
            // a full turn (a = b, k = 2r²) or a half turn (a = −b, k = 0)
            if k.is_zero() {
                pi / two
            } else {
                pi
            }
        } else {
            // k ≥ 0 always, and k = 0 only at a half turn (s = 0)
            let t = atan_enclosure(interval_from_rational(&s) / interval_from_rational(&k));
            if s.is_positive() {
                t
            } else {
                pi + t
            }
        };
        two * h
    }
    /// As an `ArcDesc` (counter-clockwise directions) and the travel flag.
    pub fn desc(&self) -> crate::shape::ArcDesc {
        let (a, b) = self.ccw_dirs();
        crate::shape::ArcDesc {
            center: self.center.clone(),
            radius: self.radius.clone(),
            from: a,
            to: b,
        }
    }
}

/// A sub-arc of an exact arc enclosed by intervals: the circle `(c, r)` and
/// boxes `a`, `b` holding the unit directions of its counter-clockwise start
/// and end, with `a·b > 0` and `a × b > 0` for every pair of points of the
/// boxes (a minor arc below a quarter turn). Splitting one needs no exact
/// point: the true middle direction `(a + b)/|a + b|` lies in the interval
/// evaluation of that formula, so the two halves cover the sub-arc.
#[derive(Clone, Debug)]
pub(crate) struct ArcBox {
    c: V2<Interval>,
    r: Interval,
    a: V2<Interval>,
    b: V2<Interval>,
    /// Travelled from `b` to `a` (as the exact arc it came from).
    clockwise: bool,
}

impl ArcBox {
    /// The enclosure of an exact arc below a quarter turn (`None` if that is
    /// not proven on the boxes).
    pub(crate) fn new(arc: &Arc) -> Option<ArcBox> {
        let (u, v) = arc.ccw_dirs();
        let r = interval_from_rational(&arc.radius);
        let unit = |d: &V2<Rational>| {
            V2::new(
                interval_from_rational(&d.x) / r,
                interval_from_rational(&d.y) / r,
            )
        };
        let c = V2::new(
            interval_from_rational(&arc.center.x),
            interval_from_rational(&arc.center.y),
        );
        ArcBox {
            c,
            r,
            a: unit(&u),
            b: unit(&v),
            clockwise: arc.clockwise,
        }
        .checked()
    }
    fn checked(self) -> Option<ArcBox> {
        let (a, b) = (&self.a, &self.b);
        let cross = a.x * b.y - a.y * b.x;
        let dot = a.x * b.x + a.y * b.y;
        (cross.inf() > 0.0 && dot.inf() > 0.0 && self.r.inf() > 0.0).then_some(self)
    }
    /// The two halves at the (enclosed) middle direction, in the order of
    /// travel.
    pub(crate) fn halves(&self) -> Option<(ArcBox, ArcBox)> {
        let s = V2::new(self.a.x + self.b.x, self.a.y + self.b.y);
        let n = (s.x * s.x + s.y * s.y).sqrt();
        if n.inf().partial_cmp(&0.0) != Some(std::cmp::Ordering::Greater) {
            return None;
        }
        let m = V2::new(s.x / n, s.y / n);
        let l = ArcBox {
            b: m.clone(),
            ..self.clone()
        }
        .checked()?;
        let r = ArcBox {
            a: m,
            ..self.clone()
        }
        .checked()?;
        Some(if self.clockwise { (r, l) } else { (l, r) })
    }
    /// Boxes holding the start, the apex (where the end tangents meet:
    /// `c + r (a + b)/(1 + a·b)`) and the end of every sub-arc enclosed: the
    /// sub-arc lies in the triangle of those three points.
    pub(crate) fn hull(&self) -> [V2<Interval>; 3] {
        let (a, b, c, r) = (&self.a, &self.b, &self.c, self.r);
        let k = r
            / (Interval::try_from((1.0, 1.0)).unwrap_or(Interval::ENTIRE) + a.x * b.x + a.y * b.y);
        let at = |d: &V2<Interval>, k: Interval| V2::new(c.x + k * d.x, c.y + k * d.y);
        [at(a, r), at(&V2::new(a.x + b.x, a.y + b.y), k), at(b, r)]
    }
}

/// One point where a Bézier piece meets the circle of an arc inside the arc's
/// range: parameter enclosure `[lo, hi]` on the piece.
#[derive(Clone, Debug, PartialEq)]
pub struct ArcHit {
    /// Isolating interval of the parameter (exact root when `lo == hi`).
    pub t: (Rational, Rational),
    /// True when the root is a multiple root of `|B − c|² − r²` (a tangential
    /// contact).
    pub multiple: bool,
}

/// What [`bezier_arc`] found.
#[derive(Clone, Debug, Default)]
pub struct ArcMeet {
    /// Points of the piece on the arc (range decided).
    pub hits: Vec<ArcHit>,
    /// Roots whose position relative to the arc's range could not be decided.
    pub undecided: Vec<(Rational, Rational)>,
}

/// `|B(t) − c|² − r²` as an exact polynomial (power basis).
pub fn circle_poly(b: &Bezier<Rational>, c: &V2<Rational>, r: &Rational) -> Poly<Rational> {
    let (x, y) = b.coords();
    let dx: Vec<Rational> = x.iter().map(|v| v - &c.x).collect();
    let dy: Vec<Rational> = y.iter().map(|v| v - &c.y).collect();
    let g: Vec<Rational> = bernstein_product(&dx, &dx)
        .into_iter()
        .zip(bernstein_product(&dy, &dy))
        .map(|(p, q)| p + q - r * r)
        .collect();
    Poly::from_bernstein(&g)
}

fn circle_bernstein_iv(bi: &Bezier<Interval>, ci: &V2<Interval>, r: &Rational) -> Vec<Interval> {
    let (x, y) = bi.coords();
    let r2 = interval_from_rational(&(r * r));
    let dx: Vec<Interval> = x.iter().map(|v| *v - ci.x).collect();
    let dy: Vec<Interval> = y.iter().map(|v| *v - ci.y).collect();
    crate::stroke::onside::bprod(&dx, &dx)
        .into_iter()
        .zip(crate::stroke::onside::bprod(&dy, &dy))
        .map(|(p, q)| p + q - r2)
        .collect()
}

/// The exact Bernstein coefficients of `|B − c|² − r²`.
fn circle_bernstein(b: &Bezier<Rational>, c: &V2<Rational>, r: &Rational) -> Vec<Rational> {
    let (x, y) = b.coords();
    let dx: Vec<Rational> = x.iter().map(|v| v - &c.x).collect();
    let dy: Vec<Rational> = y.iter().map(|v| v - &c.y).collect();
    let r2 = r * r;
    bernstein_product(&dx, &dx)
        .into_iter()
        .zip(bernstein_product(&dy, &dy))
        .map(|(p, q)| p + q - &r2)
        .collect()
}

/// Whether the part `[lo, hi]` of the piece lies in the arc's range of
/// directions from `c`, decided on the box of its restricted control points
/// (`None`: undecided, or a box that is not finite).
fn part_in_range(
    b: &Bezier<Interval>,
    c: &V2<Interval>,
    arc: &Arc,
    (lo, hi): (f64, f64),
) -> Option<bool> {
    let iv = |x: f64| Interval::try_from((x, x)).ok();
    let part = b.restrict(&iv(lo)?, &iv(hi)?);
    let pts = part.points();
    let hull = |f: &dyn Fn(&V2<Interval>) -> Interval| {
        let (mut a, mut z) = (f64::INFINITY, f64::NEG_INFINITY);
        for p in pts {
            a = a.min(f(p).inf());
            z = z.max(f(p).sup());
        }
        Interval::try_from((a, z)).ok()
    };
    let (x, y) = (hull(&|p| p.x)?, hull(&|p| p.y)?);
    arc.contains_dir(&V2::new(x - c.x, y - c.y))
}

/// Every root on `[lo, hi]` of the polynomial with interval Bernstein
/// coefficients `g` (on that range) is at a point of `B` outside the arc's
/// range, or there is none: `g` of one strict sign on every part of a
/// subdivision, or a part whose point enclosure `B([lo, hi]) − c` is proven
/// outside the arc's range of directions ([`Arc::contains_dir`] on the box).
fn no_hit(
    g: Vec<Interval>,
    b: &Bezier<Interval>,
    c: &V2<Interval>,
    arc: &Arc,
    (lo, hi): (f64, f64),
    depth: u32,
) -> bool {
    if g.iter().all(|v| v.inf() > 0.0) || g.iter().all(|v| v.sup() < 0.0) {
        return true;
    }
    if hi - lo <= 1.0 / 64.0 && part_in_range(b, c, arc, (lo, hi)) == Some(false) {
        return true;
    }
    // parts at a piece end go deeper: a second root a few ulps from a
    // (nearly tangential) joint sits just outside the arc, and only a tiny
    // part's point box shows it
    let at_end = lo == 0.0 || hi == 1.0;
    if depth == 0 && !(at_end && hi - lo > f64::powi(2.0, -50)) {
        return false;
    }
    let (left, right) = crate::curve::bernstein_halves(&g);
    let m = 0.5 * (lo + hi);
    let d = depth.saturating_sub(1);
    no_hit(left, b, c, arc, (lo, m), d) && no_hit(right, b, c, arc, (m, hi), d)
}

/// The hits of the piece on the arc when every root of `g = |B − c|² − r²`
/// on `[0, 1]` is simple and decided by intervals, `None` otherwise (the exact
/// isolation decides). `g` (interval Bernstein coefficients) is subdivided:
/// a part where every coefficient has one strict sign has no root; a part
/// whose point box is proven outside the arc's range has no hit; a part where
/// every coefficient of `g′` has one strict sign (monotone) has no root when
/// its end values have the same strict sign, and exactly one when they have
/// strictly opposite signs. That root is narrowed by bisection on the sign
/// of `g` at the midpoint (while it is strict, to width `2⁻⁴⁰`), and counts as
/// a hit when the point box of its parameter interval is proven inside the
/// arc's range (outside: no hit; undecided: `None`).
fn simple_hits(
    g: Vec<Interval>,
    b: &Bezier<Interval>,
    c: &V2<Interval>,
    arc: &Arc,
    (lo, hi): (f64, f64),
    depth: u32,
) -> Option<Vec<ArcHit>> {
    let strict = |v: &Interval| -> i8 {
        if v.inf() > 0.0 {
            1
        } else if v.sup() < 0.0 {
            -1
        } else {
            0
        }
    };
    let sg = strict(&g[0]);
    if sg != 0 && g.iter().all(|v| strict(v) == sg) {
        return Some(Vec::new());
    }
    let box_dir = |lo: f64, hi: f64| part_in_range(b, c, arc, (lo, hi));
    if box_dir(lo, hi) == Some(false) {
        return Some(Vec::new());
    }
    let n = g.len() - 1;
    let ds = strict(&(g[1] - g[0]));
    let monotone = n >= 1 && ds != 0 && (1..n).all(|j| strict(&(g[j + 1] - g[j])) == ds);
    let (s0, s1) = (strict(&g[0]), strict(&g[n]));
    if monotone && s0 != 0 && s1 != 0 {
        if s0 == s1 {
            return Some(Vec::new());
        }
        // one simple root: narrow it while the midpoint sign is strict
        let (mut a, mut z, mut part) = (lo, hi, g);
        while z - a > f64::powi(2.0, -40) {
            let (left, right) = crate::curve::bernstein_halves(&part);
            let sm = strict(&left[left.len() - 1]);
            let m = 0.5 * (a + z);
            if sm == 0 || !(a < m && m < z) {
                break;
            }
            if sm == s0 {
                (a, part) = (m, right);
            } else {
                (z, part) = (m, left);
            }
        }
        return match box_dir(a, z)? {
            false => Some(Vec::new()),
            true => Some(vec![ArcHit {
                t: (rational_from_f64(a)?, rational_from_f64(z)?),
                multiple: false,
            }]),
        };
    }
    if depth == 0 {
        return None;
    }
    let (left, right) = crate::curve::bernstein_halves(&g);
    let m = 0.5 * (lo + hi);
    let mut hits = simple_hits(left, b, c, arc, (lo, m), depth - 1)?;
    hits.extend(simple_hits(right, b, c, arc, (m, hi), depth - 1)?);
    Some(hits)
}

/// When `B(0)` or `B(1)` lies exactly on the circle: `g = |B − c|² − r²` is
/// `t^a (1 − t)^b h` with `a`, `b` the multiplicities of the exact end roots
/// (a vanishing first Bernstein coefficient divides out one factor `t`:
/// `h_j = g_{j+1}·n/(j+1)`; likewise at `1`: `h_j = g_j·n/(n − j)`). When the
/// interval Bernstein coefficients of `h` have one strict sign on every part
/// of a subdivision, `h` has no root on `[0, 1]` and the end roots are all of
/// `g`'s: returns them as hits (when in the arc's range; `multiple` for a
/// double root, a tangential joint). `None`: not decided this way.
///
/// The multiplicities come from the exact coefficients next to each end
/// (`g_k = Σ_{i+j=k} C(n,i) C(n,j)/C(2n,k) (B_i − c)·(B_j − c) − r²`, a few
/// terms each; up to a double root, e.g. the tangential joint of an offset
/// and its cap or join arc). The factors are then divided out of the interval
/// enclosures `gi` of `g` (the divided coefficients are exactly zero and the
/// factors `n/(j + 1)` exact small integers, so the results enclose `h`);
/// only a root of multiplicity three or more at an end takes the exact
/// coefficients of all of `g`.
fn end_roots_only(
    b: &Bezier<Rational>,
    c: &V2<Rational>,
    r: &Rational,
    arc: &Arc,
    (gi, bi, ci): (&[Interval], &Bezier<Interval>, &V2<Interval>),
) -> Option<Vec<ArcHit>> {
    let n = b.degree();
    let big_n = 2 * n;
    let r2 = r * r;
    let d: Vec<V2<Rational>> = b.points().iter().map(|p| p.sub(c)).collect();
    // the exact coefficient g_k (from the end at 1 when `rev`)
    let coeff = |k: usize, rev: bool| -> Rational {
        let q = |i: usize| if rev { &d[n - i] } else { &d[i] };
        let mut s = -r2.clone();
        for i in k.saturating_sub(n)..=k.min(n) {
            let j = k - i;
            let w = Rational::new(
                crate::poly::binomial_big(n, i) * crate::poly::binomial_big(n, j),
                crate::poly::binomial_big(big_n, k),
            );
            s += w * q(i).dot(q(j));
        }
        s
    };
    // g_k is nonzero where its enclosure `gi` (the same Bernstein coefficient,
    // from the enclosed control points) excludes 0: exact only otherwise
    let excludes_zero = |k: usize, rev: bool| {
        let e = gi[if rev { big_n - k } else { k }];
        e.inf() > 0.0 || e.sup() < 0.0
    };
    let mult = |rev: bool| {
        (0..3)
            .take_while(|&k| !excludes_zero(k, rev) && coeff(k, rev).is_zero())
            .count()
    };
    let (at0, at1) = (mult(false), mult(true));
    if at0 + at1 == 0 {
        return None;
    }
    if at0 >= 3 || at1 >= 3 || at0 + at1 >= gi.len() {
        return end_roots_exact(b, c, r, arc);
    }
    let iv = |x: usize| Interval::try_from((x as f64, x as f64)).expect("small integer");
    let mut h = gi.to_vec();
    for _ in 0..at0 {
        let m = h.len() - 1;
        h = (0..m).map(|j| h[j + 1] * iv(m) / iv(j + 1)).collect();
    }
    for _ in 0..at1 {
        let m = h.len() - 1;
        h = (0..m).map(|j| h[j] * iv(m) / iv(m - j)).collect();
    }
    if let Some(hits) = end_hits(b, c, arc, (h.clone(), bi, ci), (at0, at1)) {
        return Some(hits);
    }
    // the rest `h` has roots (a crossing next to the joint, as where a cap
    // meets its own side's offset again): on `(0, 1)` they are exactly
    // `g`'s other roots (`h(0) ≠ 0`, `h(1) ≠ 0` exactly: the multiplicities
    // are below three), found by intervals when they are simple
    let inner = simple_hits(h, bi, ci, arc, (0.0, 1.0), 14)?;
    let ends = end_point_hits(b, c, arc, (at0, at1))?;
    let (first, last): (Vec<ArcHit>, Vec<ArcHit>) = ends.into_iter().partition(|e| e.t.0.is_zero());
    Some(first.into_iter().chain(inner).chain(last).collect())
}

/// The end roots as hits, once the rest `h` of `g` (the end roots of
/// multiplicities `at0`, `at1` divided out; interval Bernstein coefficients)
/// is proven to have no root in the arc's range: each end root whose point is
/// in the range (`multiple` when its multiplicity is above 1). `None` when
/// that is not decided.
fn end_hits(
    b: &Bezier<Rational>,
    c: &V2<Rational>,
    arc: &Arc,
    (h, bi, ci): (Vec<Interval>, &Bezier<Interval>, &V2<Interval>),
    (at0, at1): (usize, usize),
) -> Option<Vec<ArcHit>> {
    if !no_hit(h, bi, ci, arc, (0.0, 1.0), 14) {
        return None;
    }
    end_point_hits(b, c, arc, (at0, at1))
}

/// The end roots (multiplicities `at0`, `at1`) whose points are in the arc's
/// range, as hits (`multiple` above multiplicity 1); `None` when a range test
/// is not decided.
fn end_point_hits(
    b: &Bezier<Rational>,
    c: &V2<Rational>,
    arc: &Arc,
    (at0, at1): (usize, usize),
) -> Option<Vec<ArcHit>> {
    let mut hits = Vec::new();
    for (k, t) in [
        (at0, <Rational as Zero>::zero()),
        (at1, <Rational as One>::one()),
    ] {
        if k == 0 {
            continue;
        }
        match arc.contains_dir(&b.eval(&t).sub(c)) {
            Some(true) => hits.push(ArcHit {
                t: (t.clone(), t),
                multiple: k > 1,
            }),
            Some(false) => {}
            None => return None,
        }
    }
    Some(hits)
}

/// [`end_roots_only`] on the exact coefficients of `g` (any multiplicity).
fn end_roots_exact(
    b: &Bezier<Rational>,
    c: &V2<Rational>,
    r: &Rational,
    arc: &Arc,
) -> Option<Vec<ArcHit>> {
    let mut g = circle_bernstein(b, c, r);
    let (mut at0, mut at1) = (0usize, 0usize);
    while g.len() > 1 && g[0].is_zero() {
        let n = g.len() - 1;
        g = (0..n)
            .map(|j| &g[j + 1] * Rational::new(n.into(), (j + 1).into()))
            .collect();
        at0 += 1;
    }
    while g.len() > 1 && g[g.len() - 1].is_zero() {
        let n = g.len() - 1;
        g = (0..n)
            .map(|j| &g[j] * Rational::new(n.into(), (n - j).into()))
            .collect();
        at1 += 1;
    }
    if at0 + at1 == 0 || g.iter().all(|v| v.is_zero()) {
        return None;
    }
    let bi = b.map(interval_from_rational);
    let ci = c.map(interval_from_rational);
    let h = g.iter().map(interval_from_rational).collect();
    end_hits(b, c, arc, (h, &bi, &ci), (at0, at1))
}

/// Every Bernstein coefficient of every part of a subdivision has one strict
/// sign (neighbouring parts share their end coefficient, so the sign is the
/// same everywhere): the polynomial has no root on `[0, 1]`.
fn one_sign(g: Vec<Interval>, depth: u32) -> bool {
    let pos = g.iter().all(|v| v.inf() > 0.0);
    let neg = g.iter().all(|v| v.sup() < 0.0);
    if pos || neg {
        return true;
    }
    if depth == 0 || g[0].contains(0.0) || g[g.len() - 1].contains(0.0) {
        return false;
    }
    let (left, right) = crate::curve::bernstein_halves(&g);
    one_sign(left, depth - 1) && one_sign(right, depth - 1)
}

/// Outward enclosure of a piece's control-point box, `[x, y]`.
fn control_box(b: &Bezier<Rational>) -> [Interval; 2] {
    let e = crate::stroke::onside::bbox(&b.map(interval_from_rational));
    [e.x, e.y]
}

/// [`bezier_arc`] on every pair `(Bézier i, arc j)` whose boxes may meet,
/// in parallel, in the order `(i, j)`: only pairs that meet or are undecided
/// are returned. A pair is skipped when the enclosed control box of the
/// Bézier and the enclosed box of the whole circle are disjoint (outward
/// rounded, so the skip is exact: the piece lies in its control box, the arc
/// in its circle's box); [`bezier_arc`] then finds nothing either.
pub fn bezier_arc_all(bez: &[&Bezier<Rational>], arcs: &[&Arc]) -> Vec<(usize, usize, ArcMeet)> {
    bezier_arc_all_skipping(bez, arcs, |_, _| false)
}

/// [`bezier_arc_all`] without the pairs `(i, j)` for which `known(i, j)`
/// holds (neither solved nor returned; the caller answers for them).
pub fn bezier_arc_all_skipping<F>(
    bez: &[&Bezier<Rational>],
    arcs: &[&Arc],
    known: F,
) -> Vec<(usize, usize, ArcMeet)>
where
    F: Fn(usize, usize) -> bool + Sync,
{
    use rayon::prelude::*;
    let bb: Vec<[Interval; 2]> = bez.iter().map(|b| control_box(b)).collect();
    let cb: Vec<[Interval; 2]> = arcs
        .iter()
        .map(|a| {
            let (c, r) = (
                a.center.map(interval_from_rational),
                interval_from_rational(&a.radius),
            );
            [c.x - r, c.y - r]
                .into_iter()
                .zip([c.x + r, c.y + r])
                .map(|(lo, hi)| lo.convex_hull(hi))
                .collect::<Vec<_>>()
                .try_into()
                .expect("two coordinates")
        })
        .collect();
    let apart = |a: &[Interval; 2], b: &[Interval; 2]| {
        (0..2).any(|k| a[k].sup() < b[k].inf() || b[k].sup() < a[k].inf())
    };
    let pairs: Vec<(usize, usize)> = (0..bez.len())
        .flat_map(|i| (0..arcs.len()).map(move |j| (i, j)))
        .filter(|&(i, j)| !apart(&bb[i], &cb[j]) && !known(i, j))
        .collect();
    pairs
        .into_par_iter()
        .filter_map(|(i, j)| {
            let m = bezier_arc(bez[i], arcs[j]);
            (!m.hits.is_empty() || !m.undecided.is_empty()).then_some((i, j, m))
        })
        .collect()
}

/// All points where the Bézier piece meets the arc: the real roots of
/// `|B(t) − c|² − r²` on `[0, 1]` (exact isolation), each kept when its point
/// is in the arc's angle range (decided on an interval enclosure of the point
/// after refining the root; `undecided` when it cannot be).
pub fn bezier_arc(b: &Bezier<Rational>, arc: &Arc) -> ArcMeet {
    let mut out = ArcMeet::default();
    // exact bounding-box exclusion: the circle's box against the control box
    let (c, r) = (&arc.center, &arc.radius);
    let p = b.points();
    let minx = p.iter().map(|v| &v.x).min().expect("nonempty");
    let maxx = p.iter().map(|v| &v.x).max().expect("nonempty");
    let miny = p.iter().map(|v| &v.y).min().expect("nonempty");
    let maxy = p.iter().map(|v| &v.y).max().expect("nonempty");
    if maxx < &(&c.x - r) || minx > &(&c.x + r) || maxy < &(&c.y - r) || miny > &(&c.y + r) {
        return out;
    }
    // interval filter: the Bernstein coefficients of |B − c|² − r² (enclosed
    // in interval arithmetic from the enclosed control points) of one strict
    // sign on every part of a subdivision: no point on the circle
    let bi = b.map(interval_from_rational);
    let ci = c.map(interval_from_rational);
    let gi = circle_bernstein_iv(&bi, &ci, r);
    if one_sign(gi.clone(), 10) {
        return out;
    }
    // the exact values of `g` at the ends: `|B(0) − c|² − r²`, `|B(1) − c|² − r²`
    let r2 = r * r;
    let end_zero = |p: &V2<Rational>| (p.sub(c).norm2() - &r2).is_zero();
    if end_zero(&p[0]) || end_zero(&p[p.len() - 1]) {
        // a joint: an end point of the piece exactly on the circle is an exact
        // root; divided out (as often as it repeats), the rest of `g` is tested
        // by the interval filter, and when it has no root the ends are all
        if let Some(hits) = end_roots_only(b, c, r, arc, (&gi, &bi, &ci)) {
            out.hits = hits;
            return out;
        }
    } else {
        // no end root: every root outside the arc's range, by intervals
        if no_hit(gi.clone(), &bi, &ci, arc, (0.0, 1.0), 14) {
            return out;
        }
        if let Some(hits) = simple_hits(gi, &bi, &ci, arc, (0.0, 1.0), 14) {
            out.hits = hits;
            return out;
        }
    }
    log::trace!(
        "bezier_arc: exact isolation (degree {}, ends {:?} {:?}, arc centre {:?})",
        b.degree(),
        b.points()[0].map(Scalar::approx),
        b.points().last().map(|p| p.map(Scalar::approx)),
        arc.center.map(Scalar::approx)
    );
    exact_hits(b, arc)
}

/// [`bezier_arc`] by exact root isolation of `|B(t) − c|² − r²` alone (the
/// fallback of its interval filters, and their oracle in tests).
fn exact_hits(b: &Bezier<Rational>, arc: &Arc) -> ArcMeet {
    let mut out = ArcMeet::default();
    let (c, r) = (&arc.center, &arc.radius);
    let g = circle_poly(b, c, r);
    if g.clone().trimmed().degree().is_none() {
        // the piece lies on the circle: an overlap
        out.undecided
            .push((<Rational as Zero>::zero(), <Rational as One>::one()));
        return out;
    }
    let dg = g.derivative();
    let bi = b.map(interval_from_rational);
    let ci = c.map(interval_from_rational);
    for root in isolate_roots(&g, &Span::unit_closed()) {
        let multiple = if root.is_exact() {
            dg.eval(&root.lo).is_zero()
        } else {
            // a multiple root of g is a root of gcd(g, g′): g′ has a root in the interval
            crate::poly::has_root_in(&dg, &Span::closed(root.lo.clone(), root.hi.clone()))
                && crate::poly::has_common_root_in(
                    &g,
                    &dg,
                    &Span::closed(root.lo.clone(), root.hi.clone()),
                )
        };
        if root.is_exact() {
            // decide exactly at a rational root (e.g. a shared end point)
            let v = b.eval(&root.lo).sub(c);
            match arc.contains_dir(&v) {
                Some(true) => out.hits.push(ArcHit {
                    t: (root.lo.clone(), root.hi.clone()),
                    multiple,
                }),
                Some(false) => {}
                None => out.undecided.push((root.lo.clone(), root.hi.clone())),
            }
            continue;
        }
        let mut rt = root.clone();
        let mut decided = None;
        for w in [40, 60, 90] {
            let width = Rational::new(1.into(), num_bigint::BigInt::from(1) << w);
            rt = refine_root(&g, &rt, &width);
            let t = Interval::try_from((
                interval_from_rational(&rt.lo).inf(),
                interval_from_rational(&rt.hi).sup(),
            ))
            .expect("ordered");
            let v = bi.eval(&t).sub(&ci);
            decided = arc.contains_dir(&v);
            if decided.is_some() {
                break;
            }
        }
        match decided {
            Some(true) => out.hits.push(ArcHit {
                t: (rt.lo, rt.hi),
                multiple,
            }),
            Some(false) => {}
            None => out.undecided.push((rt.lo, rt.hi)),
        }
    }
    out
}

/// Whether two arcs can meet anywhere besides a shared end point `shared`:
/// `Some(false)` proven apart (apart from `shared`), `Some(true)` a contact,
/// `None` undecided.
pub fn arcs_meet(a: &Arc, b: &Arc, shared: Option<&V2<Rational>>) -> Option<bool> {
    match arc_meetings(a, b, shared)? {
        Meetings::Apart => Some(false),
        Meetings::Overlap => Some(true),
        Meetings::Points(ps) => Some(!ps.is_empty()),
    }
}

/// Where two arcs meet besides a shared end point (see [`arc_meetings`]).
#[derive(Clone, Debug, PartialEq)]
pub(crate) enum Meetings {
    /// Proven apart.
    Apart,
    /// Two arcs of one circle whose ranges overlap.
    Overlap,
    /// Meeting points of two different circles that are proven in both
    /// ranges, each enclosed (the enclosures of distinct points are
    /// disjoint unless the circles are tangent there).
    Points(Vec<V2<Interval>>),
}

/// The meeting points of two arcs besides a shared end point `shared` (the
/// circles' intersection points, enclosed, `c_a + α d ± h d⊥`); `None` when a
/// range test is undecided.
pub(crate) fn arc_meetings(a: &Arc, b: &Arc, shared: Option<&V2<Rational>>) -> Option<Meetings> {
    let d = b.center.sub(&a.center);
    let d2 = d.norm2();
    let rs = &a.radius + &b.radius;
    if d2 > &rs * &rs {
        return Some(Meetings::Apart);
    }
    if d2.is_zero() {
        if a.radius != b.radius {
            return Some(Meetings::Apart);
        }
        // the same circle: the ranges may only share the point `shared`
        let other_in = |x: &Arc, y: &Arc| -> bool {
            // some point of y strictly inside x, or x's ends inside y beyond `shared`
            let ends_in = [&y.from, &y.to]
                .into_iter()
                .filter(|p| Some(*p) != shared)
                .any(|p| x.contains_dir(&p.sub(&x.center)) == Some(true));
            let mid_in = y
                .midpoint()
                .map(|m| x.contains_dir(&m.sub(&x.center)) == Some(true))
                .unwrap_or(true);
            ends_in || mid_in
        };
        return Some(if other_in(a, b) || other_in(b, a) {
            Meetings::Overlap
        } else {
            Meetings::Apart
        });
    }
    // two circles: the points c_a + α d ± h d⊥ (enclosed)
    let ra2 = &a.radius * &a.radius;
    let rb2 = &b.radius * &b.radius;
    let alpha = (&d2 + &ra2 - &rb2) / (&d2 * Rational::from_integer(2.into()));
    let h2 = &ra2 / &d2 - &alpha * &alpha; // h² in units of |d|²
    if h2.is_negative() {
        return Some(Meetings::Apart);
    }
    let hi = interval_from_rational(&h2).sqrt();
    let di = d.map(interval_from_rational);
    let base = a
        .center
        .map(interval_from_rational)
        .add(&di.scale(&interval_from_rational(&alpha)));
    let perp = di.rot90().scale(&hi);
    let mut points = Vec::new();
    for p in [base.add(&perp), base.sub(&perp)] {
        if let Some(s) = shared {
            let si = s.map(interval_from_rational);
            let near = |x: Interval, y: Interval| !x.disjoint(y);
            if near(p.x, si.x) && near(p.y, si.y) {
                // the shared end point itself (the circles meet there exactly)
                continue;
            }
        }
        let ina = a.contains_dir(&p.sub(&a.center.map(interval_from_rational)));
        let inb = b.contains_dir(&p.sub(&b.center.map(interval_from_rational)));
        match (ina, inb) {
            (Some(false), _) | (_, Some(false)) => {}
            (Some(true), Some(true)) => points.push(p),
            _ => return None,
        }
    }
    Some(if points.is_empty() {
        Meetings::Apart
    } else {
        Meetings::Points(points)
    })
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::test_util::qi as q;
    use proptest::prelude::*;

    fn in_box(b: &[V2<Interval>; 3], p: &V2<Rational>) -> bool {
        let inside = |x: &Rational, f: fn(&V2<Interval>) -> Interval| {
            let lo = b.iter().map(|v| f(v).inf()).fold(f64::INFINITY, f64::min);
            let hi = b
                .iter()
                .map(|v| f(v).sup())
                .fold(f64::NEG_INFINITY, f64::max);
            let xi = interval_from_rational(x);
            lo <= xi.inf() && xi.sup() <= hi
        };
        inside(&p.x, |v| v.x) && inside(&p.y, |v| v.y)
    }

    /// Oracle for [`Arc::sweep`]: the angle of a minor arc below a right angle (`a·b > 0`), enclosed:
    /// `2 atan(t)`, `t = cross(a, b)/(r² + a·b) ∈ (0, 1)`, by the alternating
    /// Taylor series of `atan` (partial sums bracket it for `0 ≤ t ≤ 1`).
    fn minor_angle(a: &Arc) -> Option<Interval> {
        let (u, v) = a.ccw_dirs();
        let t = u.cross(&v) / (&a.radius * &a.radius + u.dot(&v));
        if !(t.is_positive() && t <= <Rational as One>::one()) {
            return None;
        }
        let t2 = &t * &t;
        let (mut lo, mut hi) = (<Rational as Zero>::zero(), <Rational as Zero>::zero());
        let mut term = t.clone();
        let mut s = <Rational as Zero>::zero();
        for k in 0..12 {
            let c = &term / Rational::from_integer((2 * k + 1).into());
            if k % 2 == 0 {
                s += c;
                hi = s.clone();
            } else {
                s -= c;
                lo = s.clone();
            }
            term = &term * &t2;
        }
        let two = Interval::try_from((2.0, 2.0)).ok()?;
        let (l, h) = (interval_from_rational(&lo), interval_from_rational(&hi));
        Some(two * Interval::try_from((l.inf(), h.sup())).ok()?)
    }

    proptest! {
        #![proptest_config(ProptestConfig::with_cases(256))]
        /// [`Arc::sweep`] (interval `atan`, one formula for any arc) against
        /// an independent oracle: the sum over the exact minor parts of the
        /// bracketing partial sums of the `atan` series in exact rationals.
        /// The enclosures overlap and the sweep's is narrow.
        #[test]
        fn sweep_matches_the_rational_series(
            (cx, cy, rr) in (-4i64..4, -4i64..4, 1i64..8),
            (u0, u1) in (-31i64..31, -31i64..31),
            clockwise in any::<bool>(),
        ) {
            let c = V2::new(q(cx, 3), q(cy, 3));
            let r = q(rr, 3);
            let at = |u: i64| snap(&c, &r, ((u as f64 * 0.2).cos(), (u as f64 * 0.2).sin()));
            let (Some(from), Some(to)) = (at(u0), at(u1)) else { return Ok(()) };
            let arc = Arc { center: c, radius: r, from, to, clockwise };
            let Some(parts) = arc.minor_parts() else { return Ok(()) };
            let mut oracle = Interval::try_from((0.0, 0.0)).unwrap();
            for p in &parts {
                oracle += minor_angle(p).expect("a minor part");
            }
            let sweep = arc.sweep();
            prop_assert!(sweep.wid() < 1e-12, "{sweep:?}");
            prop_assert!(
                sweep.inf() <= oracle.sup() && oracle.inf() <= sweep.sup(),
                "sweep {sweep:?}, oracle {oracle:?}"
            );
        }
    }

    proptest! {
        #![proptest_config(ProptestConfig::with_cases(256))]
        /// [`ArcBox`] halving against exact points of the arc: the leaves,
        /// in the order [`ArcBox::halves`] gives them, start at the arc's
        /// start, end at its end, touch one another in turn, and every exact
        /// point of the arc (a rational point of the circle whose direction
        /// is proven in range by [`Arc::contains_dir`]) is in some leaf's box.
        #[test]
        fn arc_boxes_cover_the_arc_in_travel_order(
            (cx, cy, rr) in (-4i64..4, -4i64..4, 1i64..8),
            (u0, u1) in (-31i64..31, -31i64..31),
            clockwise in any::<bool>(),
            depth in 0usize..4,
        ) {
            let c = V2::new(q(cx, 3), q(cy, 3));
            let r = q(rr, 3);
            let dir = |u: f64| (u.cos(), u.sin());
            let at = |u: i64| snap(&c, &r, dir(u as f64 * 0.2));
            let (Some(from), Some(to)) = (at(u0), at(u1)) else { return Ok(()) };
            prop_assume!(from != to);
            let arc = Arc { center: c.clone(), radius: r.clone(), from, to, clockwise };
            let Some(parts) = arc.minor_parts() else { return Ok(()) };
            let mut leaves: Vec<ArcBox> = Vec::new();
            for p in &parts {
                let mut level = vec![ArcBox::new(p).expect("a minor part below a quarter turn")];
                for _ in 0..depth {
                    level = level
                        .iter()
                        .flat_map(|b| {
                            let (l, r) = b.halves().expect("halves of a small arc");
                            [l, r]
                        })
                        .collect();
                }
                leaves.extend(level);
            }
            let hulls: Vec<[V2<Interval>; 3]> = leaves.iter().map(ArcBox::hull).collect();
            prop_assert!(in_box(&hulls[0], &arc.from));
            prop_assert!(in_box(&hulls[hulls.len() - 1], &arc.to));
            let meets = |a: &[V2<Interval>; 3], b: &[V2<Interval>; 3]| {
                let span = |h: &[V2<Interval>; 3], f: fn(&V2<Interval>) -> Interval| {
                    (
                        h.iter().map(|v| f(v).inf()).fold(f64::INFINITY, f64::min),
                        h.iter().map(|v| f(v).sup()).fold(f64::NEG_INFINITY, f64::max),
                    )
                };
                let ov = |f: fn(&V2<Interval>) -> Interval| {
                    let ((a0, a1), (b0, b1)) = (span(a, f), span(b, f));
                    a0 <= b1 && b0 <= a1
                };
                ov(|v| v.x) && ov(|v| v.y)
            };
            for w in hulls.windows(2) {
                prop_assert!(meets(&w[0], &w[1]));
            }
            for k in 0..64 {
                let Some(p) = snap(&c, &r, dir(k as f64 * 0.0982)) else { continue };
                if arc.contains_dir(&p.sub(&c)) == Some(true) {
                    prop_assert!(hulls.iter().any(|h| in_box(h, &p)), "point {:?} not covered", p);
                }
            }
        }
    }

    proptest! {
        #![proptest_config(ProptestConfig::with_cases(256))]
        /// The interval path of `bezier_arc` ([`simple_hits`]) against exact
        /// root isolation: where it decides, each hit's parameter interval
        /// holds exactly one exact root of `|B − c|² − r²`, and it finds as
        /// many hits as there are exact roots whose refined point is proven
        /// in the arc's range (cases the oracle cannot decide are skipped).
        #[test]
        fn interval_hits_match_exact_isolation(
            pts in proptest::collection::vec((-8i64..8, -8i64..8), 4),
            (cx, cy, rr) in (-4i64..4, -4i64..4, 1i64..8),
            (u0, u1) in (-30i64..30, -30i64..30),
        ) {
            let b = Bezier::new(pts.iter().map(|&(x, y)| V2::new(q(x, 2), q(y, 2))).collect());
            let c = V2::new(q(cx, 2), q(cy, 2));
            let r = q(rr, 2);
            let at = |u: i64| snap(&c, &r, ((u as f64 * 0.2).cos(), (u as f64 * 0.2).sin()));
            let (Some(from), Some(to)) = (at(u0), at(u1)) else { return Ok(()) };
            prop_assume!(from != to);
            let arc = Arc { center: c.clone(), radius: r.clone(), from, to, clockwise: u1 < u0 };
            let g = circle_bernstein(&b, &c, &r);
            prop_assume!(!g[0].is_zero() && !g[g.len() - 1].is_zero());
            let bi = b.map(interval_from_rational);
            let ci = c.map(interval_from_rational);
            let gi: Vec<Interval> = g.iter().map(interval_from_rational).collect();
            let Some(hits) = simple_hits(gi, &bi, &ci, &arc, (0.0, 1.0), 14) else { return Ok(()) };
            let poly = circle_poly(&b, &c, &r);
            let roots: Vec<crate::poly::RealRoot> = isolate_roots(&poly, &Span::unit_closed())
                .iter()
                .map(|rt| refine_root(&poly, rt, &Rational::new(1.into(), num_bigint::BigInt::from(1) << 60)))
                .collect();
            for h in &hits {
                let inside = roots.iter().filter(|rt| rt.lo >= h.t.0 && rt.hi <= h.t.1).count();
                let meets = roots.iter().filter(|rt| !(rt.hi < h.t.0 || rt.lo > h.t.1)).count();
                prop_assert_eq!((inside, meets), (1, 1), "hit {:?} roots {:?}", h.t, roots);
            }
            let mut in_range = 0;
            for rt in &roots {
                let t = Interval::try_from((interval_from_rational(&rt.lo).inf(), interval_from_rational(&rt.hi).sup())).unwrap();
                let p = bi.eval(&t);
                match arc.contains_dir(&V2::new(p.x - ci.x, p.y - ci.y)) {
                    Some(true) => in_range += 1,
                    Some(false) => {}
                    None => return Ok(()),
                }
            }
            prop_assert_eq!(hits.len(), in_range);
        }
    }

    proptest! {
        #![proptest_config(ProptestConfig::with_cases(48))]
        /// The box-filtered, parallel pass finds exactly the pairs that
        /// [`bezier_arc`] on every pair finds, with the same hits (the
        /// filter only skips pairs that cannot meet).
        #[test]
        fn all_pairs_match_the_pairwise_test(
            bs in proptest::collection::vec(proptest::collection::vec((-12i64..12, -12i64..12), 2..=4), 1..6),
            arcs in proptest::collection::vec(((-6i64..6, -6i64..6, 1i64..8), (-30i64..30, -30i64..30)), 1..5),
        ) {
            let bez: Vec<Bezier<Rational>> = bs
                .iter()
                .map(|p| Bezier::new(p.iter().map(|&(x, y)| V2::new(q(x, 2), q(y, 2))).collect()))
                .collect();
            let arcs: Vec<Arc> = arcs
                .iter()
                .filter_map(|&((cx, cy, rr), (u0, u1))| {
                    let (c, r) = (V2::new(q(cx, 2), q(cy, 2)), q(rr, 2));
                    let at = |u: i64| snap(&c, &r, ((u as f64 * 0.2).cos(), (u as f64 * 0.2).sin()));
                    let (from, to) = (at(u0)?, at(u1)?);
                    (from != to).then(|| Arc { center: c.clone(), radius: r.clone(), from, to, clockwise: u1 < u0 })
                })
                .collect();
            let (br, ar): (Vec<&Bezier<Rational>>, Vec<&Arc>) = (bez.iter().collect(), arcs.iter().collect());
            let mut all = bezier_arc_all(&br, &ar);
            all.sort_by_key(|m| (m.0, m.1));
            let mut pairwise = Vec::new();
            for (i, b) in bez.iter().enumerate() {
                for (j, a) in arcs.iter().enumerate() {
                    let m = bezier_arc(b, a);
                    if !m.hits.is_empty() || !m.undecided.is_empty() {
                        pairwise.push((i, j, m));
                    }
                }
            }
            prop_assert_eq!(all.len(), pairwise.len());
            for (x, y) in all.iter().zip(&pairwise) {
                prop_assert_eq!((x.0, x.1), (y.0, y.1));
                let ts = |m: &ArcMeet| m.hits.iter().map(|h| h.t.clone()).collect::<Vec<_>>();
                prop_assert_eq!(ts(&x.2), ts(&y.2));
                prop_assert_eq!(&x.2.undecided, &y.2.undecided);
            }
        }
    }

    #[test]
    fn snapped_points_are_on_the_circle() {
        let c = V2::new(q(1, 3), q(-2, 7));
        let r = q(2, 5);
        for k in 0..16 {
            let th = k as f64 * 0.41 - 3.0;
            let p = snap(&c, &r, (th.cos(), th.sin())).unwrap();
            assert!(on_circle(&c, &r, &p));
            let v = p.sub(&c).map(Scalar::approx);
            let phi = v.y.atan2(v.x);
            let d = (phi - th).rem_euclid(2.0 * std::f64::consts::PI);
            assert!(
                !(1e-9..=2.0 * std::f64::consts::PI - 1e-9).contains(&d),
                "{th} {phi}"
            );
        }
    }

    #[test]
    fn half_circle_area_and_split() {
        let c = V2::new(q(0, 1), q(0, 1));
        let arc = Arc {
            center: c,
            radius: q(1, 1),
            from: V2::new(q(1, 1), q(0, 1)),
            to: V2::new(q(-1, 1), q(0, 1)),
            clockwise: false,
        };
        let a = arc.area_term().unwrap();
        assert!(
            a.contains(std::f64::consts::FRAC_PI_2) && a.wid() < 1e-9,
            "{a:?}"
        );
        let parts = arc.minor_parts().unwrap();
        assert!(parts.len() >= 2);
        assert_eq!(parts[0].from, arc.from);
        assert_eq!(parts.last().unwrap().to, arc.to);
        let cw = arc.reversed().area_term().unwrap();
        assert!(cw.contains(-std::f64::consts::FRAC_PI_2));
    }

    #[test]
    fn a_line_meets_the_upper_half_circle_once() {
        let arc = Arc {
            center: V2::new(q(0, 1), q(0, 1)),
            radius: q(1, 1),
            from: V2::new(q(1, 1), q(0, 1)),
            to: V2::new(q(-1, 1), q(0, 1)),
            clockwise: false,
        };
        // the vertical line x = 1/2 from y = -2 to 2 meets the circle twice,
        // the upper half once
        let l = Bezier::new(vec![V2::new(q(1, 2), q(-2, 1)), V2::new(q(1, 2), q(2, 1))]);
        let m = bezier_arc(&l, &arc);
        assert_eq!(m.hits.len(), 1, "{m:?}");
        assert!(m.undecided.is_empty());
        assert!(!m.hits[0].multiple);
        // a tangent line y = 1 touches at (0, 1): a multiple root
        let t = Bezier::new(vec![V2::new(q(-2, 1), q(1, 1)), V2::new(q(2, 1), q(1, 1))]);
        let m = bezier_arc(&t, &arc);
        assert_eq!(m.hits.len(), 1);
        assert!(m.hits[0].multiple);
        // an arc on a circle far away, and two crossing circles
        let far = Arc {
            center: V2::new(q(5, 1), q(0, 1)),
            ..arc.clone()
        };
        assert_eq!(arcs_meet(&arc, &far, None), Some(false));
        let near = Arc {
            center: V2::new(q(1, 1), q(0, 1)),
            from: V2::new(q(2, 1), q(0, 1)),
            to: V2::new(q(0, 1), q(0, 1)),
            ..arc.clone()
        };
        assert_eq!(arcs_meet(&arc, &near, None), Some(true));
    }

    /// A random circle (centre, radius at least `r_min/13`) and a rational
    /// point `p0` exactly on it at the angle `θ`: `(c, r, θ, p0, p0 − c)`.
    fn joint_on_a_circle(
        rng: &mut crate::test_util::TestRng,
        r_min: i64,
    ) -> (V2<Rational>, Rational, f64, V2<Rational>, V2<Rational>) {
        let c = V2::new(q(rng.int(200), 97), q(rng.int(200), 89));
        let r = q(r_min + rng.int(50).abs(), 13);
        let th = rng.int(1000) as f64 / 150.0;
        let p0 = snap(&c, &r, (th.cos(), th.sin())).expect("finite");
        let v = p0.sub(&c);
        (c, r, th, p0, v)
    }

    /// A joint on the circle and a second crossing next to it (a cap
    /// meeting its own side's offset again): [`end_roots_only`] finds the
    /// inner crossings by intervals on the deflated rest. Each decided case
    /// agrees with exact root isolation ([`exact_hits`]): the same hits in
    /// the same order, the same multiplicities, and each inner bracket holds
    /// the exact isolation's root (the brackets meet).
    #[test]
    fn inner_crossings_next_to_a_joint_match_exact_isolation() {
        let mut rng = crate::test_util::TestRng::new(0x2c9f_41d3_a0b7_5e61);
        let (mut decided, mut with_inner) = (0, 0);
        for case in 0..200 {
            let (c, r, th, p0, v) = joint_on_a_circle(&mut rng, 20);
            // leave the joint inwards or along the tangent, then come out
            // through the circle: the points beyond it lie outside
            let s = q(1 + rng.int(20).abs(), 60);
            let tangent = case % 2 == 1;
            let p1 = if tangent {
                V2::new(&p0.x - &v.y * &s, &p0.y + &v.x * &s)
            } else {
                V2::new(&p0.x - &v.x * &s, &p0.y - &v.y * &s)
            };
            let out = q(3 + rng.int(5).abs(), 2);
            let p2 = V2::new(&c.x + &v.x * &out, &c.y + &v.y * &out);
            let mut pts = vec![p0.clone(), p1, p2];
            if case % 3 == 0 {
                pts.push(V2::new(
                    &c.x + &v.x * &out + q(rng.int(50), 7),
                    &c.y + &v.y * &out + q(rng.int(50), 11),
                ));
            }
            if case % 4 == 0 {
                pts.reverse();
            }
            let b = Bezier::new(pts);
            // an arc around the joint's direction: the crossing next to the
            // joint is in its range (on either side of the joint)
            let dir = |a: f64| snap(&c, &r, (a.cos(), a.sin())).expect("finite");
            let arc = Arc {
                center: c.clone(),
                radius: r.clone(),
                from: dir(th - 1.5),
                to: dir(th + 1.5),
                clockwise: false,
            };
            let bi = b.map(interval_from_rational);
            let ci = c.map(interval_from_rational);
            let gi = circle_bernstein_iv(&bi, &ci, &r);
            let Some(fast) = end_roots_only(&b, &c, &r, &arc, (&gi, &bi, &ci)) else {
                continue;
            };
            decided += 1;
            let exact = exact_hits(&b, &arc);
            assert!(exact.undecided.is_empty(), "case {case}: {exact:?}");
            assert_eq!(
                fast.len(),
                exact.hits.len(),
                "case {case}: {fast:?} vs {exact:?}"
            );
            let zero = <Rational as Zero>::zero();
            let one = <Rational as One>::one();
            for (f, e) in fast.iter().zip(&exact.hits) {
                assert_eq!(f.multiple, e.multiple, "case {case}");
                assert!(
                    f.t.0 <= e.t.1 && e.t.0 <= f.t.1,
                    "case {case}: brackets {:?} and {:?} apart",
                    f.t,
                    e.t
                );
                if f.t.0 != zero && f.t.1 != one {
                    with_inner += 1;
                }
            }
            // the whole search gives the same hits
            let whole = bezier_arc(&b, &arc);
            assert_eq!(whole.hits.len(), exact.hits.len(), "case {case}");
        }
        assert!(decided > 100, "{decided} decided");
        assert!(with_inner > 50, "{with_inner} inner crossings found");
    }

    /// A piece leaving a point of the circle (transversally, or tangentially:
    /// a double root) and wandering off: the interval deflation of
    /// [`end_roots_only`] agrees with the exact one wherever both decide, and
    /// decides most cases.
    #[test]
    fn end_roots_by_interval_deflation_match_the_exact_coefficients() {
        let mut rng = crate::test_util::TestRng::new(0x51ed_270b_7f4a_7c15);
        let (mut both, mut fast_only, mut exact_only, mut tangential) = (0, 0, 0, 0);
        for case in 0..300 {
            let (c, r, th, p0, v) = joint_on_a_circle(&mut rng, 1);
            let tangent = case % 2 == 1;
            let deg = 1 + (case / 2) % 3;
            let mut pts = vec![p0.clone()];
            // the second point along the tangent (a double root) or outward
            let s = q(1 + rng.int(30).abs(), 17);
            pts.push(if tangent {
                V2::new(&p0.x - &v.y * &s, &p0.y + &v.x * &s)
            } else {
                V2::new(&p0.x + &v.x * &s, &p0.y + &v.y * &s)
            });
            while pts.len() <= deg {
                let last = pts[pts.len() - 1].clone();
                pts.push(V2::new(
                    &last.x + q(rng.int(100), 37),
                    &last.y + q(rng.int(100), 41),
                ));
            }
            if case % 3 == 0 {
                pts.reverse();
            }
            let b = Bezier::new(pts);
            // an arc of the circle from p0 a quarter turn either way
            let quarter = snap(&c, &r, ((th + 1.5).cos(), (th + 1.5).sin())).expect("finite");
            let arc = Arc {
                center: c.clone(),
                radius: r.clone(),
                from: p0.clone(),
                to: quarter,
                clockwise: rng.int(2) == 0,
            };
            let bi = b.map(interval_from_rational);
            let ci = c.map(interval_from_rational);
            let gi = circle_bernstein_iv(&bi, &ci, &r);
            // the interval enclosures hold the exact coefficients
            for (e, i) in circle_bernstein(&b, &c, &r).iter().zip(&gi) {
                let e = interval_from_rational(e);
                assert!(
                    i.inf() <= e.inf() && e.sup() <= i.sup(),
                    "{e:?} not in {i:?}"
                );
            }
            let fast = end_roots_only(&b, &c, &r, &arc, (&gi, &bi, &ci));
            let exact = end_roots_exact(&b, &c, &r, &arc);
            match (&fast, &exact) {
                (Some(f), Some(e)) => {
                    both += 1;
                    assert_eq!(f, e, "case {case}: {b:?}");
                    if f.iter().any(|h| h.multiple) {
                        tangential += 1;
                    }
                }
                (Some(_), None) => fast_only += 1,
                (None, Some(_)) => exact_only += 1,
                (None, None) => {}
            }
        }
        assert!(
            both > 150,
            "{both} decided by both, {fast_only} fast only, {exact_only} exact only"
        );
        assert!(tangential > 30, "{tangential} tangential joints");
        assert!(
            exact_only <= both / 10,
            "{exact_only} decided by the exact path only"
        );
    }
}
