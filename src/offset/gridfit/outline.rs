//! The exact outline of a contour as parts (offset spans and corner arcs),
//! positions on it, and its float evaluation.

use crate::curve::{Bezier, V2};
use crate::offset::driver::Kernel;
use crate::offset::fit::{self, dv, Reach};
use crate::offset::{prep, OffsetResult};
use crate::scalar::{rational_from_f64, Rational, Scalar};
use glam::DVec2;
use num_traits::Signed;

/// One part of a contour's exact outline, in travel order.
#[derive(Clone, Debug)]
#[allow(clippy::large_enum_variant)]
pub(super) enum Part {
    Span {
        piece: usize,
        t: (f64, f64),
    },
    Arc {
        center: V2<Rational>,
        radius: Rational,
        from: V2<Rational>,
        to: V2<Rational>,
        c: DVec2,
        r: f64,
        phi0: f64,
        /// Signed sweep (`< 0`: clockwise travel).
        sweep: f64,
    },
}

/// A position on a contour: part and local parameter `u ∈ [0, 1]`.
#[derive(Clone, Copy, Debug, PartialEq)]
pub(super) struct Pos {
    pub(super) part: usize,
    pub(super) u: f64,
}

impl Pos {
    pub(super) fn before(self, o: Pos) -> bool {
        self.part < o.part || (self.part == o.part && self.u < o.u)
    }
}

/// A joint: its position and its grid point.
#[derive(Clone, Copy, Debug)]
pub(super) struct Joint {
    pub(super) pos: Pos,
    pub(super) g: DVec2,
}

pub(super) struct Ctx<'a> {
    pub(super) curve: &'a [Bezier<Rational>],
    pub(super) xf: Vec<Bezier<f64>>,
    /// The exact curve's kernel (`None`: the curve itself, [`super::chain_on_grid`]).
    pub(super) kernel: Option<&'a Kernel>,
    /// Sharp corners of the exact curve are nominal joints too (a chain's
    /// corners; an offset's cusps are not).
    pub(super) corner_joints: bool,
    /// [`super::ChainGridOptions::hairpin_cos`].
    pub(super) hairpin_cos: f64,
    pub(super) reach: Reach,
    pub(super) grid: Rational,
    pub(super) gf: f64,
    pub(super) tol: crate::Tolerance,
    pub(super) max_boxes: usize,
    /// Splits after failed proofs, in all (`OffsetOptions::max_segments`).
    pub(super) max_splits: usize,
    /// Quadratic output (TrueType): one inner control point per piece.
    pub(super) quadratic: bool,
}

pub(super) struct Contour {
    pub(super) parts: Vec<Part>,
    pub(super) closed: bool,
}

impl Part {
    /// The span parameter at `u` (the end values exactly).
    pub(super) fn param(&self, u: f64) -> f64 {
        match self {
            Part::Span { t, .. } => {
                if u <= 0.0 {
                    t.0
                } else if u >= 1.0 {
                    t.1
                } else {
                    (t.0 + u * (t.1 - t.0)).clamp(t.0, t.1)
                }
            }
            Part::Arc { .. } => u,
        }
    }
    /// The exact direction of an arc at `u` (the end directions exactly).
    pub(super) fn arc_dir(&self, u: f64) -> Option<V2<Rational>> {
        match self {
            Part::Arc {
                from,
                to,
                phi0,
                sweep,
                ..
            } => {
                if u <= 0.0 {
                    Some(from.clone())
                } else if u >= 1.0 {
                    Some(to.clone())
                } else {
                    let phi = phi0 + u * sweep;
                    Some(V2::new(
                        rational_from_f64(phi.cos())?,
                        rational_from_f64(phi.sin())?,
                    ))
                }
            }
            Part::Span { .. } => None,
        }
    }
}

fn f64_dir(v: &V2<Rational>) -> DVec2 {
    DVec2::new(v.x.approx(), v.y.approx())
}

impl Ctx<'_> {
    pub(super) fn point(&self, part: &Part, u: f64) -> Option<DVec2> {
        match part {
            Part::Span { piece, .. } => {
                let x = &self.xf[*piece];
                let t = part.param(u);
                let p = x.eval_fast(t) + self.reach.vector(x.hodograph().eval_fast(t))?;
                p.is_finite().then_some(p)
            }
            Part::Arc {
                c, r, phi0, sweep, ..
            } => {
                let phi = phi0 + u * sweep;
                Some(*c + DVec2::new(phi.cos(), phi.sin()) * *r)
            }
        }
    }
    /// Unit tangent in the direction of travel, and signed curvature.
    pub(super) fn frame(&self, part: &Part, u: f64) -> Option<(DVec2, f64)> {
        match part {
            Part::Span { piece, .. } => {
                let x = &self.xf[*piece];
                let t = part.param(u);
                let h = x.hodograph();
                let v = h.eval_fast(t);
                let a = if h.degree() == 0 {
                    DVec2::ZERO
                } else {
                    h.hodograph().eval_fast(t)
                };
                let k = v.perp_dot(a);
                let f = 1.0 + self.reach.lambda(v, k);
                let l = v.length();
                if !(f.is_finite() && f != 0.0 && l > 0.0) {
                    return None;
                }
                Some((v / l * f.signum(), k / l.powi(3) / f.abs()))
            }
            Part::Arc { r, phi0, sweep, .. } => {
                let phi = phi0 + u * sweep;
                let s = sweep.signum();
                Some((DVec2::new(-phi.sin(), phi.cos()) * s, s / r))
            }
        }
    }
    pub(super) fn speed(&self, part: &Part, u: f64) -> f64 {
        let e = 1e-6;
        let (a, b) = ((u - e).max(0.0), (u + e).min(1.0));
        match (self.point(part, a), self.point(part, b)) {
            (Some(p), Some(q)) if b > a => (q - p).length() / (b - a),
            _ => 0.0,
        }
    }
    pub(super) fn nearest_grid(&self, p: DVec2) -> DVec2 {
        DVec2::new(
            (p.x / self.gf).round() * self.gf,
            (p.y / self.gf).round() * self.gf,
        )
    }
    /// The grid point nearest `p`, exactly (`None` when it is not an exact f64).
    pub(super) fn exact_grid(&self, p: DVec2) -> Option<DVec2> {
        let b = Bezier::new(vec![V2::new(p.x, p.y)]);
        let r = fit::round_to_grid(&b, &self.grid)?;
        Some(dv(&r.points()[0]))
    }

    /// The ranges `(part, u0, u1)` between two positions (cyclic on a closed
    /// contour when `b` is not after `a`).
    pub(super) fn ranges(&self, c: &Contour, a: Pos, b: Pos) -> Vec<(usize, f64, f64)> {
        let mut out = Vec::new();
        let mut push = |k: usize, u0: f64, u1: f64| {
            if u1 > u0 {
                out.push((k, u0, u1));
            }
        };
        if a.before(b) {
            for k in a.part..=b.part {
                let u0 = if k == a.part { a.u } else { 0.0 };
                let u1 = if k == b.part { b.u } else { 1.0 };
                push(k, u0, u1);
            }
        } else {
            for k in a.part..c.parts.len() {
                push(k, if k == a.part { a.u } else { 0.0 }, 1.0);
            }
            for k in 0..=b.part {
                push(k, 0.0, if k == b.part { b.u } else { 1.0 });
            }
        }
        out
    }

    /// Float samples of the exact curve over `ranges`, `n + 1` points at about
    /// equal arc length, each with its position.
    pub(super) fn dense(
        &self,
        c: &Contour,
        ranges: &[(usize, f64, f64)],
        n: usize,
    ) -> Option<Vec<(Pos, DVec2)>> {
        const RAW: usize = 24;
        let mut raw: Vec<(Pos, DVec2, f64)> = Vec::new();
        for &(k, u0, u1) in ranges {
            for i in 0..=RAW {
                if i == 0 && !raw.is_empty() {
                    continue;
                }
                let u = u0 + (u1 - u0) * i as f64 / RAW as f64;
                let u = if i == RAW { u1 } else { u };
                let p = self.point(&c.parts[k], u)?;
                let s = raw.last().map_or(0.0, |l| l.2 + (p - l.1).length());
                raw.push((Pos { part: k, u }, p, s));
            }
        }
        let total = raw.last()?.2;
        if !(total > 0.0 && total.is_finite()) {
            return None;
        }
        let mut out = Vec::with_capacity(n + 1);
        let mut j = 0;
        for i in 0..=n {
            let s = total * i as f64 / n as f64;
            while j + 2 < raw.len() && raw[j + 1].2 < s {
                j += 1;
            }
            let (a, b) = (&raw[j], &raw[(j + 1).min(raw.len() - 1)]);
            let pos = if i == 0 {
                a.0
            } else if i == n {
                raw[raw.len() - 1].0
            } else if a.0.part == b.0.part && b.2 > a.2 {
                let w = ((s - a.2) / (b.2 - a.2)).clamp(0.0, 1.0);
                Pos {
                    part: a.0.part,
                    u: a.0.u + w * (b.0.u - a.0.u),
                }
            } else {
                a.0
            };
            out.push((s, pos, self.point(&c.parts[pos.part], pos.u)?));
        }
        // the joints between parts (a cusp's tip among them) are samples too:
        // a range's last raw sample (`u = 1`) when another range follows
        for (k, r) in raw.iter().enumerate() {
            if k > 0 && k + 1 < raw.len() && r.0.u == 1.0 {
                out.push((r.2, r.0, r.1));
            }
        }
        out.sort_by(|x, y| x.0.total_cmp(&y.0));
        out.dedup_by(|x, y| x.0 == y.0);
        Some(out.into_iter().map(|(_, pos, p)| (pos, p)).collect())
    }

    /// Arc length between two positions (sampled).
    pub(super) fn length(&self, c: &Contour, a: Pos, b: Pos) -> f64 {
        let r = self.ranges(c, a, b);
        let mut len = 0.0;
        for (k, u0, u1) in r {
            let mut prev: Option<DVec2> = None;
            for i in 0..=8 {
                let Some(p) = self.point(&c.parts[k], u0 + (u1 - u0) * i as f64 / 8.0) else {
                    return 0.0;
                };
                if let Some(q) = prev {
                    len += (p - q).length();
                }
                prev = Some(p);
            }
        }
        len
    }
}

/// The exact outline of every contour of the input (pieces joined end to
/// start) as parts: the spans of the grid-free fit `base`'s segments and, at
/// every G⁰ corner, the corner arc; and the number of corner arcs.
pub(super) fn contours(
    curve: &[Bezier<Rational>],
    base: &OffsetResult,
    d: &Rational,
) -> (Vec<Contour>, usize) {
    // contours of the input: pieces joined end to start
    let mut groups: Vec<(usize, usize)> = Vec::new();
    for i in 0..curve.len() {
        let joined = i > 0 && {
            let p = curve[i - 1].points();
            p[p.len() - 1] == curve[i].points()[0]
        };
        match groups.last_mut() {
            Some(g) if joined => g.1 = i + 1,
            _ => groups.push((i, i + 1)),
        }
    }
    let r_abs = d.abs();
    let mut corner_arcs = 0;
    let mut contours = Vec::new();
    for &(first, end) in &groups {
        let closed = {
            let p = curve[end - 1].points();
            p[p.len() - 1] == curve[first].points()[0]
        };
        let mut parts = Vec::new();
        for i in first..end {
            parts.extend(
                base.segments
                    .iter()
                    .filter(|s| s.piece == i)
                    .map(|s| Part::Span { piece: i, t: s.t }),
            );
            let next = if i + 1 < end {
                Some(i + 1)
            } else if closed {
                Some(first)
            } else {
                None
            };
            if let Some(arc) = next.and_then(|j| corner_arc(&curve[i], &curve[j], d)) {
                corner_arcs += 1;
                parts.push(arc_part(arc, &r_abs));
            }
        }
        contours.push(Contour { parts, closed });
    }
    (contours, corner_arcs)
}

/// The part of a corner arc of radius `r_abs`, travelled clockwise or not as
/// the arc says (a zero sweep is a half turn).
fn arc_part((center, from, to, cw): CornerArc, r_abs: &Rational) -> Part {
    let (f, t) = (f64_dir(&from), f64_dir(&to));
    let (phi0, phi1) = (f.y.atan2(f.x), t.y.atan2(t.x));
    let tau = std::f64::consts::TAU;
    let sweep = if cw {
        -(phi0 - phi1).rem_euclid(tau)
    } else {
        (phi1 - phi0).rem_euclid(tau)
    };
    let sweep = if sweep == 0.0 {
        if cw {
            -tau / 2.0
        } else {
            tau / 2.0
        }
    } else {
        sweep
    };
    Part::Arc {
        c: DVec2::new(center.x.approx(), center.y.approx()),
        center,
        r: r_abs.approx(),
        radius: r_abs.clone(),
        from,
        to,
        phi0,
        sweep,
    }
}

/// A corner arc: centre, start and end directions, clockwise.
type CornerArc = (V2<Rational>, V2<Rational>, V2<Rational>, bool);

/// The corner arc between `a` (its end) and `b` (its start) for the distance
/// `d`: `(center, from, to, clockwise)` at every G⁰ corner (convex: the join
/// arc; concave: the arc of the corner point's own offset), `None` where the
/// pieces meet smoothly or do not meet.
fn corner_arc(a: &Bezier<Rational>, b: &Bezier<Rational>, d: &Rational) -> Option<CornerArc> {
    match prep::junction(a, b, d) {
        prep::Junction::Join {
            center,
            from,
            to,
            clockwise,
        } => Some((center, from, to, clockwise)),
        prep::Junction::Overlap { center } => {
            let ha = a.hodograph();
            let ta = ha.points()[ha.points().len() - 1].clone();
            let tb = b.hodograph().points()[0].clone();
            let sgn = Rational::from_integer(if d.is_positive() { 1 } else { -1 }.into());
            let left = ta.cross(&tb).is_positive();
            Some((
                center,
                ta.rot90().scale(&sgn),
                tb.rot90().scale(&sgn),
                !left,
            ))
        }
        _ => None,
    }
}
