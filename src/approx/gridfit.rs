//! Offsets fitted **on a grid finer than the tolerance allows rounding**:
//! cubic (or quadratic, `Output::Quadratic`: TrueType) splines whose every
//! control point is a grid multiple (integer font units) proven within a
//! tolerance below the rounding move `grid·√2/2`.
//!
//! Rounding a fitted spline to the grid moves a shared end point up to
//! `grid·√2/2` off the exact curve, so below that tolerance the end points
//! must be chosen, not rounded. [`offset_on_grid`]:
//!
//! 1. fits the exact offset by proven cubics at `tol/2` without a grid
//!    ([`super::offset`], `Output::Cubic`), and takes the exact outline as a
//!    sequence of **parts** per contour: the spans of those segments and, at
//!    every G⁰ corner of the input, the circular arc of radius `|d|` about the
//!    corner from one piece's end normal to the next piece's start normal
//!    (the join arc at a convex corner; at a concave corner the arc inside the
//!    loop the two offsets make — the offset of the corner point itself);
//! 2. moves each joint between parts along the exact curve (within 32 grid
//!    steps, and within 45 % of the neighbouring parts) to a position where
//!    the exact curve passes within `tol/2` of a grid point, and takes that
//!    grid point as the shared end point;
//! 3. fits a cubic between consecutive joints (G² Hermite, least squares and
//!    chord-thirds candidates, Nelder–Mead on the sampled error, as
//!    [`super::fit`]), then moves its two inner control points over the grid
//!    (coordinate descent on the sampled two-sided error); a quadratic takes
//!    its control point at the intersection of the exact end tangents
//!    ([`fit::tangent_quadratic`]; tangents that do not meet ahead split the
//!    span) and moves it over the grid the same way. Nothing of steps 1, 2
//!    and 4 depends on the degree: the proof is the same;
//! 4. proves each cubic against the exact curve **between its two joint
//!    positions** — one or more exact spans or sub-arcs, so the targets of the
//!    cubics partition the exact outline — with the certification engine; a
//!    cubic that fails is split at the middle of its target (a new joint, moved
//!    to a grid point the same way) and both halves are re-fitted.
//!
//! The targets partition the exact outline `A` and the cubics make up `B`, so
//! `d_H(A, B) ≤ max` of the per-cubic bounds. The certificate states exactly
//! that: `A` is the union of the exact offset of the target spans and the
//! target sub-arcs, `B` the cubics, every cover box naming its target.
//!
//! Open contours keep their exact end points: an end can only move inwards by
//! `tol/2`, so an open offset whose end is far from every grid point is not
//! reached (reported, never guessed). Convolutions are not supported on such
//! grids yet (their corners need elliptic arcs).

use super::driver::Kernel;
use super::fit::{self, dv, FitEnds, Reach};
use super::options::{bad, check_options};
use super::results::sub_exact;
use super::{exact_bezier, prep, OffsetError, OffsetOptions, Output};
use crate::certify::piece::Piece as CPiece;
use crate::certify::{Certificate, Config, CoverBox, HausdorffBounds, MapCover};
use crate::curve::{Bezier, V2};
use crate::scalar::{rational_from_f64, Rational, Scalar};
use crate::shape::{ArcDesc, ShapeDesc};
use glam::DVec2;
use num_traits::{Signed, Zero};
use rayon::prelude::*;

/// How far (in grid steps of arc length) a joint may move along the exact
/// curve to reach a grid point.
const WINDOW_STEPS: f64 = 32.0;
/// The part of the tolerance a joint's grid point may be off the exact curve.
const JOINT_SHARE: f64 = 0.5;
/// How far off the curve a joint made by a split may be (as a share of the
/// tolerance) when no grid point within `JOINT_SHARE` is found.
const SPLIT_SHARE: f64 = 0.9;
/// The tolerance of the first, grid-free fit (its joints are the nominal ones).
const FIT_SHARE: f64 = 0.5;
/// Initial joints closer than this many grid steps (of arc length) merge.
const MIN_GAP_STEPS: f64 = 16.0;
/// Splits of one cubic after a failed proof.
const MAX_DEPTH: u32 = 12;

/// What one output cubic is proven against: an exact span of an input piece's
/// offset, or an exact sub-arc of a corner arc.
#[derive(Clone, Debug, PartialEq)]
#[allow(clippy::large_enum_variant)]
pub enum Target {
    /// The exact offset of `curve[piece]` over the parameters `t` (dyadic).
    Span {
        /// Input piece.
        piece: usize,
        /// Parameter range, `t.0 < t.1`.
        t: (f64, f64),
    },
    /// A sub-arc (counter-clockwise from `from` to `to`) of a corner arc.
    Arc(ArcDesc),
}

/// One cubic of [`GridOffset`].
#[derive(Clone, Debug, PartialEq)]
pub struct GridSegment {
    /// The cubic; every coordinate is a multiple of the grid.
    pub bezier: Bezier<f64>,
    /// Index of its contour (input pieces joined end to start).
    pub contour: usize,
    /// The exact curve it is proven against, in travel order.
    pub targets: Vec<Target>,
    /// Certified `lo ≤ d_H(targets, cubic) ≤ hi`.
    pub error: (f64, f64),
    /// How the bound was proven (`None`: not within the tolerance).
    pub proof: Option<super::ProofPath>,
}

/// The result of [`offset_on_grid`].
#[derive(Clone, Debug, PartialEq)]
pub struct GridOffset {
    /// The grid (exact, dyadic).
    pub grid: Rational,
    /// The tolerance.
    pub tol: f64,
    /// The cubics, contour after contour, in travel order.
    pub segments: Vec<GridSegment>,
    /// Per contour: first segment, number of segments, closed.
    pub contours: Vec<(usize, usize, bool)>,
    /// Segments whose certified bound stayed above `tol`.
    pub unreached: Vec<usize>,
    /// `max` of the segments' certified upper bounds.
    pub certified_hi: f64,
    /// Segments of the grid-free fit whose joints were moved (step 1).
    pub base_segments: usize,
    /// Cubics split after a failed proof.
    pub refits: usize,
    /// Certified searches run.
    pub certifications: usize,
    /// Corner arcs in the exact outline.
    pub corner_arcs: usize,
    /// The largest (float) distance of a joint's grid point from the exact
    /// curve at its position: information only.
    pub max_joint_offset: f64,
    /// The certificate of `d_H(exact outline, cubics) ≤ tol` (when reached).
    pub certificate: Option<Certificate>,
}

impl GridOffset {
    /// Every cubic proven within `tol`.
    pub fn reached(&self) -> bool {
        self.unreached.is_empty()
    }
    /// Control points in all (4 per cubic, 3 per quadratic, shared end points
    /// counted once per closed contour).
    pub fn control_points(&self) -> usize {
        self.contours
            .iter()
            .map(|&(first, n, closed)| {
                let inner: usize = self.segments[first..first + n]
                    .iter()
                    .map(|s| s.bezier.degree())
                    .sum();
                inner + usize::from(!closed)
            })
            .sum()
    }
    /// The cubics as one exact shape (the certificate's `b`).
    pub fn approximant_shape(&self) -> Result<ShapeDesc, OffsetError> {
        let pieces = self
            .segments
            .iter()
            .map(|s| exact_bezier(&s.bezier))
            .collect::<Option<Vec<_>>>()
            .ok_or_else(|| bad("approximant", "a control point is not finite"))?;
        ShapeDesc::curve(pieces).map_err(|e| bad("approximant", e.to_string()))
    }
    /// The exact outline the cubics are proven against (the certificate's
    /// `a`): the exact offset of every target span, and with corner arcs the
    /// union of it and the target sub-arcs.
    pub fn exact_shape(
        &self,
        curve: &[Bezier<Rational>],
        distance: &Rational,
    ) -> Result<ShapeDesc, OffsetError> {
        let (spans, arcs) = self.numbered_targets();
        exact_shape_of(curve, distance, &spans, &arcs)
    }
    fn numbered_targets(&self) -> (Vec<SpanTarget>, Vec<ArcDesc>) {
        let mut spans = Vec::new();
        let mut arcs = Vec::new();
        for s in &self.segments {
            for t in &s.targets {
                match t {
                    Target::Span { piece, t } => spans.push((*piece, *t)),
                    Target::Arc(a) => arcs.push(a.clone()),
                }
            }
        }
        (spans, arcs)
    }
}

/// An input piece and a parameter range of it.
type SpanTarget = (usize, (f64, f64));

fn exact_shape_of(
    curve: &[Bezier<Rational>],
    distance: &Rational,
    spans: &[SpanTarget],
    arcs: &[ArcDesc],
) -> Result<ShapeDesc, OffsetError> {
    let pieces = spans
        .iter()
        .map(|(p, t)| {
            curve
                .get(*p)
                .and_then(|x| sub_exact(x, *t))
                .ok_or_else(|| bad("segments", "a target does not name an input span"))
        })
        .collect::<Result<Vec<_>, _>>()?;
    let offset = ShapeDesc::offset(pieces, distance.clone())?;
    if arcs.is_empty() {
        return Ok(offset);
    }
    let mut members = vec![offset];
    for a in arcs {
        members.push(ShapeDesc::arc(a.clone())?);
    }
    Ok(ShapeDesc::union(members)?)
}

/// One part of a contour's exact outline, in travel order.
#[derive(Clone, Debug)]
#[allow(clippy::large_enum_variant)]
enum Part {
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
struct Pos {
    part: usize,
    u: f64,
}

impl Pos {
    fn before(self, o: Pos) -> bool {
        self.part < o.part || (self.part == o.part && self.u < o.u)
    }
}

/// A joint: its position and its grid point.
#[derive(Clone, Copy, Debug)]
struct Joint {
    pos: Pos,
    g: DVec2,
}

struct Ctx<'a> {
    curve: &'a [Bezier<Rational>],
    xf: Vec<Bezier<f64>>,
    kernel: &'a Kernel,
    reach: Reach,
    grid: Rational,
    gf: f64,
    tol: f64,
    max_boxes: usize,
    /// Splits after failed proofs, in all (`OffsetOptions::max_segments`).
    max_splits: usize,
    /// Quadratic output (TrueType): one inner control point per piece.
    quadratic: bool,
}

struct Contour {
    parts: Vec<Part>,
    closed: bool,
}

impl Part {
    /// The span parameter at `u` (the end values exactly).
    fn param(&self, u: f64) -> f64 {
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
    fn arc_dir(&self, u: f64) -> Option<V2<Rational>> {
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
    fn point(&self, part: &Part, u: f64) -> Option<DVec2> {
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
    fn frame(&self, part: &Part, u: f64) -> Option<(DVec2, f64)> {
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
    fn speed(&self, part: &Part, u: f64) -> f64 {
        let e = 1e-6;
        let (a, b) = ((u - e).max(0.0), (u + e).min(1.0));
        match (self.point(part, a), self.point(part, b)) {
            (Some(p), Some(q)) if b > a => (q - p).length() / (b - a),
            _ => 0.0,
        }
    }
    fn nearest_grid(&self, p: DVec2) -> DVec2 {
        DVec2::new(
            (p.x / self.gf).round() * self.gf,
            (p.y / self.gf).round() * self.gf,
        )
    }
    /// The grid point nearest `p`, exactly (`None` when it is not an exact f64).
    fn exact_grid(&self, p: DVec2) -> Option<DVec2> {
        let b = Bezier::new(vec![V2::new(p.x, p.y)]);
        let r = fit::round_to_grid(&b, &self.grid)?;
        Some(dv(&r.points()[0]))
    }

    /// The ranges `(part, u0, u1)` between two positions (cyclic on a closed
    /// contour when `b` is not after `a`).
    fn ranges(&self, c: &Contour, a: Pos, b: Pos) -> Vec<(usize, f64, f64)> {
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
    fn dense(
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
        // the joints between parts (a cusp's tip among them) are samples too
        for (k, r) in raw.iter().enumerate() {
            if k > 0 && k + 1 < raw.len() && r.0.u == 0.0 {
                out.push((r.2, r.0, r.1));
            }
        }
        out.sort_by(|x, y| x.0.total_cmp(&y.0));
        out.dedup_by(|x, y| x.0 == y.0);
        Some(out.into_iter().map(|(_, pos, p)| (pos, p)).collect())
    }

    /// [`Self::snap_within`] in `window`, then (when nothing there is within
    /// `tol/2` of a grid point) anywhere between `lo` and `hi`.
    fn snap(
        &self,
        c: &Contour,
        nominal: Pos,
        lo: Pos,
        hi: Pos,
        window: f64,
    ) -> Option<(Joint, f64)> {
        let first = self.snap_within(c, nominal, lo, hi, window)?;
        if first.1 <= JOINT_SHARE * self.tol {
            return Some(first);
        }
        self.snap_within(c, nominal, lo, hi, f64::INFINITY)
    }

    /// Moves a joint from `nominal` along the exact curve, strictly between
    /// `lo` and `hi` (or onto them when they equal `nominal`), by at most
    /// `window` of arc length, to the position closest to `nominal` whose
    /// nearest grid point is within `tol/2`; else to the position with the
    /// nearest grid point. Returns the joint and its grid point's distance
    /// from the curve.
    fn snap_within(
        &self,
        c: &Contour,
        nominal: Pos,
        lo: Pos,
        hi: Pos,
        window: f64,
    ) -> Option<(Joint, f64)> {
        let delta = JOINT_SHARE * self.tol;
        let h = self.gf / 16.0;
        let p0 = self.point(&c.parts[nominal.part], nominal.u)?;
        let score = |p: DVec2| (p - self.nearest_grid(p)).length();
        let mut best = (score(p0), 0.0, nominal);
        let mut good: Option<(f64, Pos)> = (best.0 <= delta).then_some((0.0, nominal));
        for dir in [1.0f64, -1.0] {
            let (mut pos, mut walked, mut prev) = (nominal, 0.0, p0);
            for _ in 0..65536 {
                let part = &c.parts[pos.part];
                let sp = self.speed(part, pos.u);
                let du = if sp > 0.0 {
                    (h / sp).min(1.0 / 64.0)
                } else {
                    1.0 / 64.0
                };
                let mut u = pos.u + dir * du;
                let mut k = pos.part;
                if u >= 1.0 {
                    if k + 1 >= c.parts.len() {
                        break;
                    }
                    k += 1;
                    u = 0.0;
                } else if u < 0.0 {
                    if pos.u > 0.0 {
                        u = 0.0;
                    } else if k == 0 {
                        break;
                    } else {
                        k -= 1;
                        u = (1.0 - du).max(0.0);
                    }
                }
                pos = Pos { part: k, u };
                if !(lo.before(pos) && pos.before(hi)) {
                    break;
                }
                let Some(p) = self.point(&c.parts[k], u) else {
                    break;
                };
                walked += (p - prev).length();
                prev = p;
                if walked > window {
                    break;
                }
                let d = score(p);
                if d < best.0 {
                    best = (d, walked, pos);
                }
                if d <= delta && good.is_none_or(|g| walked < g.0) {
                    good = Some((walked, pos));
                }
            }
        }
        let pos = good.map_or(best.2, |g| g.1);
        let p = self.point(&c.parts[pos.part], pos.u)?;
        let g = self.exact_grid(p)?;
        Some((Joint { pos, g }, (p - g).length()))
    }

    /// Arc length between two positions (sampled).
    fn length(&self, c: &Contour, a: Pos, b: Pos) -> f64 {
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

    /// The exact outline turns back at the start of part `k` (a cusp: the
    /// ends of a concave corner's arc, a cusp of the offset of a piece).
    fn is_cusp(&self, c: &Contour, k: usize) -> bool {
        let prev = if k > 0 {
            k - 1
        } else if c.closed {
            c.parts.len() - 1
        } else {
            return false;
        };
        let e = 1e-4;
        let pts = (
            self.point(&c.parts[prev], 1.0 - e),
            self.point(&c.parts[prev], 1.0),
            self.point(&c.parts[k], 0.0),
            self.point(&c.parts[k], e),
        );
        match pts {
            (Some(a0), Some(a1), Some(b0), Some(b1)) => (a1 - a0).dot(b1 - b0) < 0.0,
            _ => false,
        }
    }

    /// The initial joints of a contour: the starts of its parts, except at
    /// cusps (a joint there could not move to a grid point: one cubic turns
    /// round the cusp instead) and within `MIN_GAP_STEPS` grid steps of the
    /// previous joint; arcs over 90° (and a concave corner's arc, whose two
    /// ends are cusps) get joints inside.
    fn nominal_joints(&self, c: &Contour) -> Vec<Pos> {
        let min_gap = MIN_GAP_STEPS * self.gf;
        let mut cands = Vec::new();
        for (k, p) in c.parts.iter().enumerate() {
            let cusp = self.is_cusp(c, k);
            if !cusp || (k == 0 && !c.closed) {
                cands.push(Pos { part: k, u: 0.0 });
            }
            // a part between two cusps (the middle of a swallowtail) gets a
            // joint in its middle
            if cusp
                && k + 1 < c.parts.len()
                && self.is_cusp(c, k + 1)
                && !matches!(p, Part::Arc { .. })
            {
                cands.push(Pos { part: k, u: 0.5 });
            }
            if let Part::Arc { sweep, r, .. } = p {
                let quarter = std::f64::consts::FRAC_PI_2;
                let mut n = (sweep.abs() / quarter).ceil().max(1.0) as usize;
                if cusp && sweep.abs() * r >= 2.0 * min_gap {
                    n = n.max(2);
                }
                cands.extend((1..n).map(|j| Pos {
                    part: k,
                    u: j as f64 / n as f64,
                }));
            }
        }
        let mut out: Vec<Pos> = Vec::new();
        for p in cands {
            if let Some(&q) = out.last() {
                if self.length(c, q, p) < min_gap {
                    continue;
                }
            }
            out.push(p);
        }
        if c.closed && out.len() > 1 {
            if let (Some(&l), Some(&f)) = (out.last(), out.first()) {
                if self.length(c, l, f) < min_gap {
                    out.pop();
                }
            }
        }
        if out.is_empty() {
            out.push(Pos { part: 0, u: 0.0 });
        }
        out
    }

    /// A cubic from `a.g` to `b.g` with inner control points on the grid.
    fn fit(
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
        let refined = if two_sided(&pts, &refined) > 0.25 * self.tol {
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

    fn target_of(&self, part: &Part, u0: f64, u1: f64) -> Option<Target> {
        match part {
            Part::Span { piece, .. } => Some(Target::Span {
                piece: *piece,
                t: (part.param(u0), part.param(u1)),
            }),
            Part::Arc {
                center,
                radius,
                sweep,
                ..
            } => {
                let (d0, d1) = (part.arc_dir(u0)?, part.arc_dir(u1)?);
                let (from, to) = if *sweep > 0.0 { (d0, d1) } else { (d1, d0) };
                Some(Target::Arc(ArcDesc {
                    center: center.clone(),
                    radius: radius.clone(),
                    from,
                    to,
                }))
            }
        }
    }

    fn target_piece(&self, t: &Target) -> Option<CPiece> {
        match t {
            Target::Span { piece, t } => self.kernel.span_piece(&self.curve[*piece], *t),
            Target::Arc(a) => CPiece::arc(a).ok(),
        }
    }
}

/// The sampled two-sided distance between the exact samples (a polyline) and
/// a cubic (float estimate: chooses candidates only).
fn two_sided(exact: &[DVec2], c: &Bezier<f64>) -> f64 {
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

/// One proven (or failed) cubic before numbering.
struct Built {
    bezier: Bezier<f64>,
    targets: Vec<Target>,
    bounds: Option<HausdorffBounds>,
    error: (f64, f64),
}

impl Ctx<'_> {
    /// Fits and proves the cubic between two joints, splitting on failure.
    fn segment(&self, c: &Contour, a: Joint, b: Joint, depth: u32, stats: &Stats) -> Vec<Built> {
        let ranges = self.ranges(c, a.pos, b.pos);
        let targets: Option<Vec<Target>> = ranges
            .iter()
            .map(|&(k, u0, u1)| self.target_of(&c.parts[k], u0, u1))
            .collect();
        let dense = self.dense(c, &ranges, 48);
        let fitted = dense.as_ref().and_then(|d| self.fit(c, &a, &b, d));
        let split = |stats: &Stats| -> Option<Vec<Built>> {
            if depth >= MAX_DEPTH
                || stats.refits.load(std::sync::atomic::Ordering::Relaxed) >= self.max_splits
            {
                return None;
            }
            let d = dense.as_ref()?;
            let mid = d[d.len() / 2].0;
            if mid == a.pos || mid == b.pos {
                return None;
            }
            // the walk stays inside (a, b); across the closing joint of a
            // closed contour it stays on mid's side of it
            let (lo, hi) = if a.pos.before(b.pos) {
                (a.pos, b.pos)
            } else if a.pos.before(mid) {
                (
                    a.pos,
                    Pos {
                        part: c.parts.len() - 1,
                        u: 1.0,
                    },
                )
            } else {
                (Pos { part: 0, u: 0.0 }, b.pos)
            };
            let len = self.length(c, a.pos, b.pos);
            let (m, dist) = self.snap(c, mid, lo, hi, (0.25 * len).min(WINDOW_STEPS * self.gf))?;
            // a joint off the curve by more than tol/2 leaves the cubics less
            // room, but may still be proven: up to 0.9 tol
            if dist.is_nan()
                || dist > SPLIT_SHARE * self.tol
                || m.pos == a.pos
                || m.pos == b.pos
                || m.g == a.g
                || m.g == b.g
            {
                return None;
            }
            stats
                .refits
                .fetch_add(1, std::sync::atomic::Ordering::Relaxed);
            let (l, r) = rayon::join(
                || self.segment(c, a, m, depth + 1, stats),
                || self.segment(c, m, b, depth + 1, stats),
            );
            Some(l.into_iter().chain(r).collect())
        };
        // nothing to prove: a straight placeholder keeps the contour closed and
        // is reported unreached
        let placeholder = |targets: Option<Vec<Target>>| {
            let v = |p: DVec2| V2::new(p.x, p.y);
            let bezier = if self.quadratic {
                Bezier::new(vec![v(a.g), v(a.g), v(b.g)])
            } else {
                Bezier::new(vec![v(a.g), v(a.g), v(b.g), v(b.g)])
            };
            vec![Built {
                bezier,
                targets: targets.unwrap_or_default(),
                bounds: None,
                error: (0.0, f64::INFINITY),
            }]
        };
        let (Some(targets), Some(bez)) = (targets.clone(), fitted) else {
            return split(stats).unwrap_or_else(|| placeholder(targets));
        };
        let pieces: Option<Vec<CPiece>> = targets.iter().map(|t| self.target_piece(t)).collect();
        let (Some(pa), Some(pb)) = (pieces, crate::certify::piece::bezier_f64(&bez)) else {
            return split(stats).unwrap_or_else(|| placeholder(Some(targets)));
        };
        // a sampled error above the tolerance: split without a proof
        let pts: Vec<DVec2> = dense
            .as_ref()
            .map_or(Vec::new(), |d| d.iter().map(|p| p.1).collect());
        if depth < MAX_DEPTH && two_sided(&pts, &bez) > self.tol {
            if let Some(v) = split(stats) {
                return v;
            }
        }
        let cfg = Config {
            tol: Some(self.tol),
            max_boxes: self.max_boxes,
            verdict_only: depth < MAX_DEPTH,
            ..Config::default()
        };
        stats
            .certifications
            .fetch_add(1, std::sync::atomic::Ordering::Relaxed);
        let abs = || 1e-10 * (1.0 + a.g.abs().max_element() + b.g.abs().max_element());
        let r = crate::certify::hausdorff_pieces(&pa, &[pb], &cfg, &abs);
        if r.hi <= self.tol {
            return vec![Built {
                bezier: bez,
                targets,
                error: (r.lo, r.hi),
                bounds: Some(r),
            }];
        }
        if let Some(v) = split(stats) {
            return v;
        }
        vec![Built {
            bezier: bez,
            targets,
            error: (r.lo, r.hi),
            bounds: None,
        }]
    }
}

#[derive(Default)]
struct Stats {
    refits: std::sync::atomic::AtomicUsize,
    certifications: std::sync::atomic::AtomicUsize,
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

/// The offset at `opts.distance` as cubics on `opts.grid`, proven within
/// `opts.tol` even when `tol ≤ grid·√2/2` (see the module docs).
///
/// Errors: those of [`super::offset`], `grid` missing or not dyadic, or its
/// multiples not exact `f64` numbers over the coordinates, `output` not
/// cubic.
///
/// # Examples
/// ```
/// use lncert::approx::{gridfit::offset_on_grid, OffsetOptions, Output};
/// use lncert::shape::parse_curve;
/// let q = |s: &str| lncert::parse_rational(s).unwrap();
/// // a closed curve in "font units"; a grid of 1 and a tolerance of 0.2 units
/// let x = parse_curve("M 0 0 C 300 -100 500 200 400 400 C 300 600 -100 300 0 0").unwrap();
/// let mut opts = OffsetOptions::new(q("40"), 0.2);
/// opts.output = Output::Cubic;
/// opts.grid = Some(q("1"));
/// let r = offset_on_grid(&x, &opts).unwrap();
/// assert!(r.reached() && r.certified_hi <= 0.2);
/// for s in &r.segments {
///     assert!(s.bezier.points().iter().all(|p| p.x.fract() == 0.0 && p.y.fract() == 0.0));
/// }
/// ```
pub fn offset_on_grid(
    curve: &[Bezier<Rational>],
    opts: &OffsetOptions,
) -> Result<GridOffset, OffsetError> {
    let Some(grid) = opts.grid.clone() else {
        return Err(bad("grid", "offset_on_grid needs a grid"));
    };
    if !matches!(opts.output, Output::Cubic | Output::Quadratic) {
        return Err(bad(
            "output",
            "a tolerance below the grid's rounding move is supported for cubic and quadratic output only",
        ));
    }
    let shape = check_options(curve, &{
        let mut o = opts.clone();
        o.grid = None;
        o
    })?;
    fit::check_grid_storage(&grid, shape.scale())?;
    let mut base_opts = opts.clone();
    base_opts.grid = None;
    base_opts.tol = opts.tol * FIT_SHARE;
    let base = super::offset(curve, &base_opts)?;
    let d = opts.distance.clone();
    let kernel = Kernel::Offset {
        d: d.clone(),
        df: d.approx(),
    };
    let ctx = Ctx {
        curve,
        xf: curve.iter().map(|x| x.map(|v| v.approx())).collect(),
        kernel: &kernel,
        reach: Reach::of(&kernel),
        gf: grid.approx(),
        grid: grid.clone(),
        tol: opts.tol,
        max_boxes: opts.max_boxes,
        max_splits: opts.max_segments,
        quadratic: opts.output == Output::Quadratic,
    };
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
            if let Some((center, from, to, cw)) =
                next.and_then(|j| corner_arc(&curve[i], &curve[j], &d))
            {
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
                corner_arcs += 1;
                parts.push(Part::Arc {
                    c: DVec2::new(center.x.approx(), center.y.approx()),
                    center,
                    r: r_abs.approx(),
                    radius: r_abs.clone(),
                    from,
                    to,
                    phi0,
                    sweep,
                });
            }
        }
        contours.push(Contour { parts, closed });
    }
    let stats = Stats::default();
    let mut max_joint: f64 = 0.0;
    let mut built_contours: Vec<Vec<Built>> = Vec::new();
    for c in &contours {
        if c.parts.is_empty() {
            built_contours.push(Vec::new());
            continue;
        }
        let nominal = ctx.nominal_joints(c);
        let last = Pos {
            part: c.parts.len() - 1,
            u: 1.0,
        };
        let mut joints: Vec<Joint> = Vec::new();
        let n = nominal.len();
        for (i, &pos) in nominal.iter().enumerate() {
            let lo = match joints.last() {
                Some(j) => j.pos,
                None => pos,
            };
            let hi = if i + 1 < n { nominal[i + 1] } else { last };
            let prev_len = if i > 0 {
                ctx.length(c, nominal[i - 1], pos)
            } else {
                f64::INFINITY
            };
            let next_len = ctx.length(c, pos, hi);
            let open_end = i == 0 && !c.closed;
            let found = if open_end {
                // an open end moves inwards by tol/2 at most
                ctx.snap_within(c, pos, lo, hi, JOINT_SHARE * opts.tol)
            } else {
                let window = (WINDOW_STEPS * ctx.gf).min(0.45 * prev_len.min(next_len));
                ctx.snap(c, pos, lo, hi, window)
            };
            let (j, dist) = found
                .ok_or_else(|| bad("curve", "the exact offset cannot be evaluated at a joint"))?;
            // no grid point near the curve up to the next joint: no joint here
            // (the cubic runs on), unless it is an open end
            if dist <= JOINT_SHARE * opts.tol || open_end || (i + 1 == n && joints.is_empty()) {
                joints.push(j);
            }
        }
        if !c.closed {
            let lo = joints.last().map_or(last, |j| j.pos);
            let (j, _) = ctx
                .snap_within(c, last, lo, last, JOINT_SHARE * opts.tol)
                .ok_or_else(|| bad("curve", "the exact offset cannot be evaluated at its end"))?;
            joints.push(j);
        }
        for j in &joints {
            if let Some(p) = ctx.point(&c.parts[j.pos.part], j.pos.u) {
                max_joint = max_joint.max((p - j.g).length());
            }
        }
        let pairs: Vec<(Joint, Joint)> = if c.closed {
            (0..joints.len())
                .map(|i| (joints[i], joints[(i + 1) % joints.len()]))
                .collect()
        } else {
            joints.windows(2).map(|w| (w[0], w[1])).collect()
        };
        let built: Vec<Vec<Built>> = pairs
            .par_iter()
            .map(|(a, b)| ctx.segment(c, *a, *b, 0, &stats))
            .collect();
        built_contours.push(built.into_iter().flatten().collect());
    }
    // number the targets: spans first (the offset member), then arcs
    let mut segments = Vec::new();
    let mut bounds = Vec::new();
    let mut contour_ranges = Vec::new();
    for (ci, built) in built_contours.into_iter().enumerate() {
        contour_ranges.push((segments.len(), built.len(), contours[ci].closed));
        for b in built {
            segments.push(GridSegment {
                bezier: b.bezier,
                contour: ci,
                targets: b.targets,
                error: b.error,
                proof: b.bounds.as_ref().map(|r| {
                    if r.parametric.is_some() {
                        super::ProofPath::Parametric
                    } else {
                        super::ProofPath::Search
                    }
                }),
            });
            bounds.push(b.bounds);
        }
    }
    let unreached: Vec<usize> = segments
        .iter()
        .enumerate()
        .filter(|(_, s)| s.proof.is_none())
        .map(|(i, _)| i)
        .collect();
    let certified_hi = segments.iter().map(|s| s.error.1).fold(0.0, f64::max);
    let mut out = GridOffset {
        grid,
        tol: opts.tol,
        segments,
        contours: contour_ranges,
        unreached,
        certified_hi: if bounds.is_empty() {
            f64::INFINITY
        } else {
            certified_hi
        },
        base_segments: base.segments.len(),
        refits: stats.refits.into_inner(),
        certifications: stats.certifications.into_inner(),
        corner_arcs,
        max_joint_offset: max_joint,
        certificate: None,
    };
    if out.reached() && !out.segments.is_empty() {
        out.certificate = certificate(curve, &d, &out, &bounds)?;
    }
    Ok(out)
}

/// The certificate of a reached [`GridOffset`]: every cover box renumbered to
/// the global pieces (`a`: spans, then arcs; `b`: the cubics).
fn certificate(
    curve: &[Bezier<Rational>],
    d: &Rational,
    res: &GridOffset,
    bounds: &[Option<HausdorffBounds>],
) -> Result<Option<Certificate>, OffsetError> {
    let spans_total = res
        .segments
        .iter()
        .flat_map(|s| &s.targets)
        .filter(|t| matches!(t, Target::Span { .. }))
        .count();
    let (mut next_span, mut next_arc) = (0usize, spans_total);
    let (mut maps, mut ab, mut ba) = (Vec::new(), Vec::new(), Vec::new());
    for (i, (s, b)) in res.segments.iter().zip(bounds).enumerate() {
        let Some(r) = b else {
            return Ok(None);
        };
        let global: Vec<usize> = s
            .targets
            .iter()
            .map(|t| match t {
                Target::Span { .. } => {
                    next_span += 1;
                    next_span - 1
                }
                Target::Arc(_) => {
                    next_arc += 1;
                    next_arc - 1
                }
            })
            .collect();
        match &r.parametric {
            Some(m) => {
                let a_idx = global[0];
                let (piece, target) = if m.source_a { (a_idx, i) } else { (i, a_idx) };
                maps.push(MapCover {
                    from_a: m.source_a,
                    piece,
                    target,
                    boxes: m.boxes.clone(),
                    hi: m.hi,
                });
            }
            None => {
                ab.extend(r.a_to_b.boxes.iter().map(|bx| CoverBox {
                    piece: global[bx.piece],
                    target: i,
                    ..bx.clone()
                }));
                ba.extend(r.b_to_a.boxes.iter().map(|bx| CoverBox {
                    piece: i,
                    target: global[bx.target],
                    ..bx.clone()
                }));
            }
        }
    }
    // the verifier reads each direction's boxes piece after piece
    for bs in [&mut ab, &mut ba] {
        bs.sort_by(|x: &CoverBox, y: &CoverBox| {
            x.piece.cmp(&y.piece).then(x.s.0.total_cmp(&y.s.0))
        });
    }
    let a = res.exact_shape(curve, d)?;
    let b = res.approximant_shape()?;
    let tol = rational_from_f64(res.tol).ok_or_else(|| bad("tol", "not finite"))?;
    if tol.is_zero() {
        return Err(bad("tol", "must be > 0"));
    }
    Ok(Certificate::assemble(&a, &b, &tol, &maps, &ab, &ba))
}
