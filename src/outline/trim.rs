//! Proven stroke outlines for a circular pen: the boundary of the swept region
//! `S = x ⊕ disk(r)` as closed contours of exact Bézier pieces and exact arcs —
//! and for an elliptical pen `E` ([`StrokeOptions::with_pen`],
//! [`PenShape::Ellipse`]): `S = x ⊕ E`, the sides the convolution curves
//! `x ∗ e_∓` ([`crate::approx::convolve`], certified within `tol/8`), round caps
//! half ellipses of proven cubics ([`super::ellipse::half_ellipse_cap`]), and
//! the kept/removed tests below with the pen's exact quadratic form
//! ([`super::ellipse::Form`]; see `proofs/trimming.md`, "Elliptical pens").
//!
//! # Construction
//!
//! 1. The offsets at `−r` and `+r` ([`crate::approx::offset`], each segment
//!    certified within `tol/8` of the exact offset of its span) are chained
//!    into raw contours: the `−r` side forward, the `+r` side reversed, joined by
//!    round caps (exact arcs of radius `r` about the end points) for an open
//!    curve, or kept as two contours for a closed one. At G⁰ corners a join
//!    arc is added on the convex side and a straight *connector* chord on the
//!    concave side (its points lie inside the disk of the corner, so inside `S`).
//!    With this order the outside of `S` is locally on the **right** of every
//!    raw piece.
//! 2. Exact closure: arc end points are rational points **exactly on** the
//!    circle ([`super::circle::snap`], the rational parametrisation of the
//!    circle); the neighbouring offset segment's end control point is replaced
//!    by that point. Replacing an end control point by a point `δ` away moves
//!    every point of the Bézier by at most `δ` (the end basis function is ≤ 1),
//!    so `δ` (enclosed exactly) is added to the piece's certified bound.
//! 3. The raw pieces are split at their certified crossings
//!    ([`super::intersect::intersections`] for Bézier pairs,
//!    [`super::circle::bezier_arc`] for a Bézier and an arc). **Split
//!    convention**: a Bézier–Bézier crossing with enclosures `s`, `t` and point
//!    box `P` is split at the dyadic midpoints `s*`, `t*` of the enclosures, and
//!    the crossing is represented by one exact point `X` (the dyadic midpoint of
//!    `P`) that replaces the end control points of the halves on both pieces; a
//!    Bézier–arc crossing is split at the midpoint `s*` of an isolating interval
//!    refined to `2⁻⁴⁰`, and `X` is a rational point exactly on the circle near
//!    `B(s*)` (so the arc splits exactly at `X`). Each half moves by at most
//!    `|B(s*) − X|` (enclosed), added to its bound.
//! 4. Every sub-piece is classified (see `proofs/trimming.md`):
//!    **kept** when every point `q` of it has, within the claimed bound, a point
//!    `w` proven outside `S` (`dist(w, x) > r`, exact Bernstein signs of
//!    `|w − x(t)|² − r²` on every input piece) — together with a point of `S`
//!    within the piece's certified bound, the segment between them crosses `∂S`;
//!    **removed** when every point `q` of it has `dist(q, x) < r − e` (`e` the
//!    piece's two-sided bound; an exact witness point of `x` for each part of a
//!    subdivision) or lies within `λ = tol/2` of a kept crossing point;
//!    otherwise **undecided**, never guessed.
//! 5. Kept pieces are chained into contours by their exact shared end points;
//!    the orientation is the sign of the enclosed area `½∮(x dy − y dx)`
//!    (exact for Bézier pieces, an enclosure for arcs); outer contours come out
//!    counter-clockwise, holes clockwise.
//! 6. Claim (c) is checked on the output: [`super::intersect::intersections`]
//!    on its Bézier pieces, [`super::circle::bezier_arc`] and
//!    [`super::circle::arcs_meet`] for the arcs; contours must be closed, with no
//!    crossing and no contact besides the joints of consecutive pieces.

use super::circle::{arcs_meet, bezier_arc, snap, Arc};
use super::ellipse::{half_ellipse_cap, pen_point_enclosure, Form};
use super::intersect::{intersections, IntersectOptions};
use crate::approx::conv::Pen;
use crate::approx::prep::Junction;
use crate::approx::{convolve, exact_bezier, offset, OffsetMethod, OffsetOptions, OffsetResult};
use crate::curve::{bernstein_product, Bezier, V2};
use crate::scalar::{interval_from_rational, rational_from_f64, Interval, Rational, Scalar};
use num_traits::{One, Signed, Zero};

/// How an open curve's ends are closed.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Cap {
    /// A half circle of radius `r` about the end point (exact arc).
    Round,
    /// The straight segment between the two offset ends. The region is then
    /// not `x ⊕ disk`: claims (a) and (b) are not made for butt caps.
    Butt,
}

/// Settings of [`stroke`].
#[derive(Clone, Debug)]
pub struct StrokeOptions {
    /// Pen radius `r > 0`, exact.
    pub radius: Rational,
    /// The tolerance to prove for claims (a) and (b).
    pub tol: f64,
    /// End caps of an open curve (default round).
    pub cap: Cap,
    /// Solver boxes per pair for the intersection searches (default 20 000).
    pub max_boxes_per_pair: usize,
    /// The offset segments' form (default native: degree `n + 3`; `Cubic` /
    /// `Quadratic` for SVG-expressible output, see [`crate::approx::fit`]).
    pub output: crate::approx::Output,
    /// The construction of the sides (default G², seeds 004 / 001; `LnPair`:
    /// seed 000's cubic LN pairs).
    pub method: OffsetMethod,
    /// An elliptical pen: when set, the stroke is `x ⊕ E` for this exact pen
    /// and `radius` is not used (see [`StrokeOptions::with_pen`]).
    pub ellipse: Option<Pen>,
}

/// The pen of a stroke.
#[derive(Clone, Debug, PartialEq)]
#[allow(clippy::large_enum_variant)]
pub enum PenShape {
    /// A disk of radius `r > 0` (exact).
    Circle(Rational),
    /// A filled ellipse `E = M · disk(1)` with an exact rational matrix: the
    /// stroke is that of **this** pen (a rotation given as an irrational angle
    /// is represented by an exactly rational one, see [`Pen`]).
    Ellipse(Pen),
}

impl StrokeOptions {
    /// Round caps and the default budgets.
    pub fn new(radius: Rational, tol: f64) -> Self {
        StrokeOptions {
            radius,
            tol,
            cap: Cap::Round,
            max_boxes_per_pair: 20_000,
            output: crate::approx::Output::Native,
            method: OffsetMethod::G2,
            ellipse: None,
        }
    }

    /// Round caps and the default budgets for a circular or elliptical pen.
    ///
    /// # Examples
    /// ```
    /// use lncert::approx::conv::{Angle, Pen};
    /// use lncert::outline::trim::{PenShape, StrokeOptions};
    /// let q = |s: &str| lncert::parse_rational(s).unwrap();
    /// let pen = Pen::ellipse(&q("0.7"), &q("0.3"), &Angle::parse("pi/6").unwrap()).unwrap();
    /// let o = StrokeOptions::with_pen(PenShape::Ellipse(pen), 0.1);
    /// assert!(matches!(o.pen(), PenShape::Ellipse(_)));
    /// let c = StrokeOptions::with_pen(PenShape::Circle(q("1")), 0.1);
    /// assert_eq!(c.pen(), PenShape::Circle(q("1")));
    /// ```
    pub fn with_pen(pen: PenShape, tol: f64) -> Self {
        match pen {
            PenShape::Circle(r) => Self::new(r, tol),
            PenShape::Ellipse(p) => {
                let mut o = Self::new(<Rational as One>::one(), tol);
                o.ellipse = Some(p);
                o
            }
        }
    }

    /// The pen these options stroke with.
    pub fn pen(&self) -> PenShape {
        match &self.ellipse {
            Some(p) => PenShape::Ellipse(p.clone()),
            None => PenShape::Circle(self.radius.clone()),
        }
    }

    fn form(&self) -> Result<Form, StrokeError> {
        match &self.ellipse {
            Some(p) => Form::ellipse(p).ok_or_else(|| bad("pen", "the ellipse is degenerate")),
            None => Ok(Form::circle(&self.radius)),
        }
    }
}

/// One proven half-ellipse cap of an elliptical pen.
#[derive(Clone, Debug)]
pub struct CapReport {
    /// `"start"` or `"end"` of the curve.
    pub end: &'static str,
    /// Number of cubics.
    pub pieces: usize,
    /// Certified Hausdorff bound to the exact half ellipse (the pen used).
    pub error: f64,
    /// The pre-image cubics' proven radial deviation from the unit circle.
    pub circle_error: f64,
}

/// Why a stroke could not be computed; names the field.
#[derive(Clone, Debug, PartialEq, thiserror::Error)]
#[error("invalid `{field}`: {reason}")]
pub struct StrokeError {
    /// The offending input (`radius`, `tol`, `curve`, …).
    pub field: String,
    /// Why.
    pub reason: String,
}

fn bad(field: &str, reason: impl Into<String>) -> StrokeError {
    StrokeError {
        field: field.into(),
        reason: reason.into(),
    }
}

/// One output piece: a Bézier of any degree or an exact arc.
#[derive(Clone, Debug, PartialEq)]
#[allow(clippy::large_enum_variant)]
pub enum Piece {
    /// Exact control points.
    Bezier(Bezier<Rational>),
    /// An arc with exact end points on its circle.
    Arc(Arc),
}

impl Piece {
    /// The start point.
    pub fn start(&self) -> &V2<Rational> {
        match self {
            Piece::Bezier(b) => &b.points()[0],
            Piece::Arc(a) => &a.from,
        }
    }
    /// The end point.
    pub fn end(&self) -> &V2<Rational> {
        match self {
            Piece::Bezier(b) => b.points().last().expect("nonempty"),
            Piece::Arc(a) => &a.to,
        }
    }
    fn reversed(&self) -> Piece {
        match self {
            Piece::Bezier(b) => {
                let mut p = b.points().to_vec();
                p.reverse();
                Piece::Bezier(Bezier::new(p))
            }
            Piece::Arc(a) => Piece::Arc(a.reversed()),
        }
    }
    /// `n + 1` float points of the piece, from its start to its end (for
    /// pictures and sampled checks; nothing certified rests on them).
    pub fn sample(&self, n: usize) -> Vec<(f64, f64)> {
        let n = n.max(1);
        match self {
            Piece::Bezier(b) => {
                let f = b.map(Scalar::approx);
                (0..=n)
                    .map(|k| {
                        let v = f.eval_fast(k as f64 / n as f64);
                        (v.x, v.y)
                    })
                    .collect()
            }
            Piece::Arc(a) => {
                let c = (a.center.x.approx(), a.center.y.approx());
                let r = a.radius.approx();
                let t0 = (a.from.y.approx() - c.1).atan2(a.from.x.approx() - c.0);
                let t1 = (a.to.y.approx() - c.1).atan2(a.to.x.approx() - c.0);
                let tau = std::f64::consts::TAU;
                let d = if a.clockwise {
                    -(t0 - t1).rem_euclid(tau)
                } else {
                    (t1 - t0).rem_euclid(tau)
                };
                (0..=n)
                    .map(|k| {
                        let t = t0 + d * k as f64 / n as f64;
                        (c.0 + r * t.cos(), c.1 + r * t.sin())
                    })
                    .collect()
            }
        }
    }

    /// `½∫(x dy − y dx)` along the piece: exact for a Bézier, enclosed for an arc.
    pub fn area_term(&self) -> Option<Interval> {
        match self {
            Piece::Bezier(b) => bezier_area_iv(b),
            Piece::Arc(a) => a.area_term(),
        }
    }
}

/// An enclosure of `½∫₀¹ (x y′ − y x′) dt` in interval arithmetic: the
/// integrand's Bernstein coefficients `c_k` (degree `m = 2n − 1`, products
/// enclosed) give `∫₀¹ Σ c_k B_k^m = Σ c_k / (m + 1)` (each Bernstein basis
/// polynomial integrates to `1/(m + 1)`).
fn bezier_area_iv(b: &Bezier<Rational>) -> Option<Interval> {
    let n = b.degree();
    if n == 0 {
        return Interval::try_from((0.0, 0.0)).ok();
    }
    let x = b.map(interval_from_rational);
    let h = x.hodograph();
    let (xs, ys): (Vec<Interval>, Vec<Interval>) = x.points().iter().map(|p| (p.x, p.y)).unzip();
    let (hx, hy): (Vec<Interval>, Vec<Interval>) = h.points().iter().map(|p| (p.x, p.y)).unzip();
    let a = super::onside::bprod(&xs, &hy);
    let c = super::onside::bprod(&ys, &hx);
    let mut s = Interval::try_from((0.0, 0.0)).ok()?;
    for (u, v) in a.iter().zip(&c) {
        s += *u - *v;
    }
    let m = Interval::try_from(((2 * n) as f64, (2 * n) as f64)).ok()?;
    let two = Interval::try_from((2.0, 2.0)).ok()?;
    let r = s / m / two;
    (!r.is_empty() && r.inf().is_finite() && r.sup().is_finite()).then_some(r)
}

/// `½∫₀¹ (x y′ − y x′) dt`, exact.
#[cfg(test)]
fn bezier_area(b: &Bezier<Rational>) -> Rational {
    let (x, y) = b.power_coords();
    let integrand = x.mul(&y.derivative()).sub(&y.mul(&x.derivative()));
    let mut s = <Rational as Zero>::zero();
    for (k, c) in integrand.coeffs().iter().enumerate() {
        s += c / Rational::from_integer((k as i64 + 1).into());
    }
    s / Rational::from_integer(2.into())
}

/// Orientation of a closed contour.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Orientation {
    /// Positive area (an outer contour).
    CounterClockwise,
    /// Negative area (a hole).
    Clockwise,
    /// The area enclosure contains 0, or the contour is open.
    Undecided,
}

impl Orientation {
    /// `"ccw"`, `"cw"` or `"undecided"`.
    pub fn name(self) -> &'static str {
        match self {
            Orientation::CounterClockwise => "ccw",
            Orientation::Clockwise => "cw",
            Orientation::Undecided => "undecided",
        }
    }
}

/// One output contour.
#[derive(Clone, Debug)]
pub struct Contour {
    /// Pieces in travel order; consecutive pieces share exact end points.
    pub pieces: Vec<Piece>,
    /// The last end point equals the first start point exactly.
    pub closed: bool,
    /// From the sign of the enclosed area.
    pub orientation: Orientation,
    /// Enclosure of the signed area `½∮(x dy − y dx)`.
    pub area: (f64, f64),
}

/// A proven crossing of two raw (untrimmed) pieces where they were split.
#[derive(Clone, Debug)]
pub struct RawCrossing {
    /// Raw piece indices (`i ≤ j`).
    pub pieces: (usize, usize),
    /// Parameter enclosure on the first piece (for an arc: `[0, 0]`).
    pub s: (f64, f64),
    /// Parameter enclosure on the second piece (for an arc: `[0, 0]`).
    pub t: (f64, f64),
}

/// The status of one claim.
#[derive(Clone, Debug, PartialEq)]
pub struct Claim {
    /// True when proven.
    pub proven: bool,
    /// The certified bound (claims (a), (b); `∞` when not established).
    pub bound: f64,
    /// What was shown, or why not.
    pub note: String,
}

/// Counts of the classification.
#[derive(Clone, Copy, Debug, Default)]
pub struct Classified {
    /// Sub-pieces proven on the boundary.
    pub kept: usize,
    /// Sub-pieces proven interior.
    pub removed: usize,
    /// Connectors dropped (no proof needed).
    pub dropped_connectors: usize,
    /// Sub-pieces neither proven kept nor removed.
    pub undecided: usize,
}

/// The result of [`stroke`].
#[derive(Clone, Debug)]
pub struct Stroke {
    /// The outline.
    pub contours: Vec<Contour>,
    /// The crossings where the raw pieces were split.
    pub crossings: Vec<RawCrossing>,
    /// Raw pieces (offset segments, caps, joins, connectors) before trimming.
    pub raw_pieces: usize,
    /// The raw arrangement's intersections were complete (nothing undecided).
    pub raw_complete: bool,
    /// The output check of claim (c) was complete.
    pub complete: bool,
    /// Claim (a): every output point within `bound` of `∂S`.
    pub a: Claim,
    /// Claim (b): every point of `∂S` within `bound` of the output.
    pub b: Claim,
    /// Claim (c): closed, simple (certified), oriented contours.
    pub c: Claim,
    /// Classification counts.
    pub classified: Classified,
    /// The tolerance asked for.
    pub tol: f64,
    /// The curve is closed.
    pub closed_curve: bool,
    /// What was left undecided on the way (raw regions, sub-pieces, offsets);
    /// informational: the claims are decided on the output itself.
    pub notes: Vec<String>,
    /// The elliptical pen actually used (exact), when there is one.
    pub pen: Option<Pen>,
    /// The round caps of an elliptical pen (empty for a circle or butt caps).
    pub caps: Vec<CapReport>,
}

impl Stroke {
    /// All three claims proven.
    pub fn proven(&self) -> bool {
        self.a.proven && self.b.proven && self.c.proven
    }
    /// Output pieces in all.
    pub fn pieces(&self) -> usize {
        self.contours.iter().map(|c| c.pieces.len()).sum()
    }
}

/// What a raw piece is.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
enum Kind {
    /// Approximates an exact part of a candidate boundary (offset span, cap, join).
    Boundary,
    /// A concave-corner chord: no exact counterpart, inside `S`.
    Connector,
    /// A butt cap: always part of the outline (no distance claims).
    Butt,
}

#[derive(Clone, Debug)]
struct Raw {
    piece: Piece,
    /// Hausdorff bound to its exact counterpart (Boundary) — also a bound of
    /// the distance of each of its points to `S`.
    e: f64,
    /// For connectors: every point is within `e_in` of `S`.
    e_in: f64,
    kind: Kind,
    /// For offset segments proven by the parametric path: the map from the
    /// segment's parameter onto its span's exact offset (see [`Link`]).
    link: Option<Link>,
}

/// How a raw offset segment's points correspond to exact offset points:
/// every `B(s)` is within the raw piece's `e_in` of `E(t)` for some `t` in
/// `span.0 + hull(c)·(span.1 − span.0)` over the map boxes whose range meets
/// `s` (the parametric proof of [`crate::certify::param`]; `B` with its end
/// moves, fact 4, which `e_in` includes).
#[derive(Clone, Debug)]
struct Link {
    /// The input piece (index into the whole curve).
    piece: usize,
    /// Its span (dyadic floats).
    span: (f64, f64),
    /// The signed offset distance.
    d: Rational,
    /// The map's cover of the segment's parameter.
    boxes: std::sync::Arc<Vec<crate::certify::ParamBox>>,
    /// The raw piece runs against the segment's parameter (the `+r` side).
    reversed: bool,
    /// The segment's certified error when the link was made: `raw.e − seg_e`
    /// bounds how far the raw piece's points have moved since (end snaps).
    seg_e: f64,
}

impl Link {
    /// The largest certified `|B(t) − A(φ(t))|` over the map's boxes that meet
    /// the raw parameters `[s0, s1]` (`None` if none does).
    fn local_bound(&self, s0: f64, s1: f64) -> Option<f64> {
        let (lo, hi) = if self.reversed {
            (1.0 - s1, 1.0 - s0)
        } else {
            (s0, s1)
        };
        self.boxes
            .iter()
            .filter(|b| b.t.1 >= lo && b.t.0 <= hi)
            .map(|b| b.bound)
            .reduce(f64::max)
    }
    /// The exact parameters (on the input piece) whose offset points lie
    /// within `e_in` of the raw piece's points over `[s0, s1]`, enclosed.
    fn exact_range(&self, s0: f64, s1: f64) -> Option<(f64, f64)> {
        let (lo, hi) = if self.reversed {
            (1.0 - s1, 1.0 - s0)
        } else {
            (s0, s1)
        };
        let iv = |x: f64| Interval::try_from((x, x)).ok();
        let (mut u0, mut u1) = (f64::INFINITY, f64::NEG_INFINITY);
        for b in self.boxes.iter() {
            if b.t.1 >= lo && b.t.0 <= hi {
                // φ on the part of the box inside [lo, hi]: the cubic's
                // Bernstein coefficients restricted there (interval blossom)
                let w = iv(b.t.1)? - iv(b.t.0)?;
                let a = (iv(lo.max(b.t.0))? - iv(b.t.0)?) / w;
                let z = (iv(hi.min(b.t.1))? - iv(b.t.0)?) / w;
                let coef = Bezier::new(
                    b.c.iter()
                        .map(|&c| Some(V2::new(iv(c)?, iv(0.0)?)))
                        .collect::<Option<Vec<_>>>()?,
                );
                for p in coef.restrict(&a, &z).points() {
                    u0 = u0.min(p.x.inf());
                    u1 = u1.max(p.x.sup());
                }
            }
        }
        if u0.is_nan() || u1.is_nan() || u0 > u1 || u0 < 0.0 || u1 > 1.0 {
            return None;
        }
        let (a, b) = (iv(self.span.0)?, iv(self.span.1)?);
        let t0 = a + iv(u0)? * (b - a);
        let t1 = a + iv(u1)? * (b - a);
        Some((t0.inf().max(0.0), t1.sup().min(1.0)))
    }
}

fn fsq(v: &V2<Rational>) -> Interval {
    let w = v.map(interval_from_rational);
    (w.x * w.x + w.y * w.y).sqrt()
}

/// `|p − q|` upper bound.
fn dist_hi(p: &V2<Rational>, q: &V2<Rational>) -> f64 {
    fsq(&p.sub(q)).sup()
}

fn unit_normal_point(c: &V2<Rational>, r: &Rational, dir: &V2<Rational>) -> V2<Interval> {
    let d = dir.map(interval_from_rational);
    let n = (d.x * d.x + d.y * d.y).sqrt();
    let ri = interval_from_rational(r);
    let ci = c.map(interval_from_rational);
    V2::new(ci.x + ri * d.x / n, ci.y + ri * d.y / n)
}

fn dist_hi_iv(p: &V2<Rational>, q: &V2<Interval>) -> f64 {
    let pi = p.map(interval_from_rational);
    let (dx, dy) = (pi.x - q.x, pi.y - q.y);
    (dx * dx + dy * dy).sqrt().sup()
}

fn set_end(
    b: &Bezier<Rational>,
    first: Option<&V2<Rational>>,
    last: Option<&V2<Rational>>,
) -> Bezier<Rational> {
    let mut p = b.points().to_vec();
    if let Some(f) = first {
        p[0] = f.clone();
    }
    if let Some(l) = last {
        let n = p.len() - 1;
        p[n] = l.clone();
    }
    Bezier::new(p)
}

/// The first nonzero derivative direction at an end (`e = 0` or `1`), exact.
fn end_tangent(b: &Bezier<Rational>, e: u8) -> Option<V2<Rational>> {
    let h = b.hodograph();
    let hp = h.points();
    let z = |v: &&V2<Rational>| !v.x.is_zero() || !v.y.is_zero();
    if e == 0 {
        hp.iter().find(z).cloned()
    } else {
        hp.iter().rev().find(z).cloned()
    }
}

fn approx_dir(v: &V2<Rational>) -> (f64, f64) {
    (v.x.approx(), v.y.approx())
}

/// One side's segments chained forward, with join arcs and connectors at the
/// corners (the closing corner too when `closed`).
/// The raw pieces of one offset side, in order, joined exactly.
///
/// **Joints are not crossings** (issue 27): at a G⁰ corner whose join arc or
/// concave connector would be shorter than `merge` (a corner of a few ulps in
/// data written by float code, a path whose tangents agree to a few digits),
/// no piece is inserted: the next segment's start control point is moved onto
/// the previous segment's end (fact 4: the move `d` is added to its bounds),
/// so the two segments meet at one exact point with nearly opposite
/// directions, a joint the crossing search decides to first order. For a
/// convex corner the exact join arc (from `E₁ = c + r·from/|from|` to `E₂`,
/// turning by less than π) has every point within `|E₁ − E₂|` of `E₁`, hence
/// within `e_J = 2|x₁ − E₁| + |x₁ − x₂| + |x₂ − E₂|` of the kept end `x₁`:
/// the previous segment stands for its exact span **and** the join arc, its
/// bound `e` raised to `e_J` (claim (b) uses `e` only through "every exact
/// point is within `e` of the raw piece"; `e_in` is unchanged since the raw
/// piece still lies within `e_in` of `S`). A concave connector's points are
/// never needed for (b) (fact 3), so dropping a short one costs only the move.
fn chain_side(
    res: &OffsetResult,
    r: &Rational,
    closed: bool,
    merge: f64,
    first: usize,
    lines: Option<&[Bezier<Rational>]>,
) -> Result<Vec<Raw>, StrokeError> {
    let segs: Vec<(usize, Bezier<Rational>, f64)> = res
        .segments
        .iter()
        .map(|s| {
            exact_bezier(&s.bezier)
                .map(|b| (s.piece, b, s.error.1))
                .ok_or_else(|| bad("curve", "an offset control point is not finite"))
        })
        .collect::<Result<_, _>>()?;
    if segs.is_empty() {
        return Err(bad("curve", "no offset segments"));
    }
    let link = |s: &crate::approx::OffsetSegment| -> Option<Link> {
        let proof = s.proof.as_ref()?;
        let map = proof.map.as_ref()?;
        if map.source_a || map.boxes.is_empty() || s.error.1.is_nan() || s.error.1 > res.tol {
            return None;
        }
        Some(Link {
            piece: first + s.piece,
            span: s.t,
            d: res.distance.clone(),
            boxes: std::sync::Arc::new(map.boxes.clone()),
            reversed: false,
            seg_e: s.error.1,
        })
    };
    let mut raws: Vec<Raw> = segs
        .iter()
        .zip(&res.segments)
        .map(|((_, b, e), s)| {
            // a straight input piece with a rational unit normal: its exact
            // offset is the piece translated, written exactly (error 0, the
            // identity map), not the float construction
            if let Some(x) = lines.and_then(|c| c.get(s.piece)) {
                if let Some(exact) = exact_line_offset(x, &res.distance, s.t) {
                    return Raw {
                        piece: Piece::Bezier(exact),
                        e: 0.0,
                        e_in: 0.0,
                        kind: Kind::Boundary,
                        link: Some(Link {
                            piece: first + s.piece,
                            span: s.t,
                            d: res.distance.clone(),
                            boxes: std::sync::Arc::new(vec![crate::certify::ParamBox {
                                t: (0.0, 1.0),
                                c: [0.0, 1.0 / 3.0, 2.0 / 3.0, 1.0],
                                bound: 0.0,
                            }]),
                            reversed: false,
                            seg_e: 0.0,
                        }),
                    };
                }
            }
            Raw {
                piece: Piece::Bezier(b.clone()),
                e: *e,
                e_in: *e,
                kind: Kind::Boundary,
                link: link(s),
            }
        })
        .collect();
    let n = raws.len();
    let mut out: Vec<Raw> = Vec::new();
    // junction k: between segment k and k + 1 (cyclic for closed)
    let mut inserts: Vec<Option<Raw>> = vec![None; n];
    let last = if closed { n } else { n - 1 };
    for k in 0..last {
        let k1 = (k + 1) % n;
        let corner = if segs[k].0 != segs[k1].0 || (closed && k1 == 0) {
            res.corners
                .iter()
                .find(|c| c.after == segs[k].0)
                .map(|c| c.kind.clone())
        } else {
            None
        };
        let (p1, p2) = (raws[k].piece.end().clone(), raws[k1].piece.start().clone());
        match corner {
            Some(Junction::Join {
                center,
                from,
                to,
                clockwise,
            }) => {
                let x1 = on_or_snap(&center, r, &p1, &from).ok_or_else(|| bad("curve", "join"))?;
                let x2 = on_or_snap(&center, r, &p2, &to).ok_or_else(|| bad("curve", "join"))?;
                let d1 = dist_hi(&p1, &x1);
                let e1 = dist_hi_iv(&x1, &unit_normal_point(&center, r, &from));
                let e2 = dist_hi_iv(&x2, &unit_normal_point(&center, r, &to));
                let gap = dist_hi(&x1, &x2);
                if gap <= merge {
                    // a join arc shorter than `merge`: no arc, one exact point
                    let e_j = (2.0 * e1 + gap + e2) * (1.0 + 1e-12);
                    if let Piece::Bezier(b) = &raws[k].piece {
                        raws[k].piece = Piece::Bezier(set_end(b, None, Some(&x1)));
                    }
                    raws[k].e = (raws[k].e + d1).max(e_j);
                    raws[k].e_in += d1;
                    let d = dist_hi(&p2, &x1);
                    if let Piece::Bezier(b) = &raws[k1].piece {
                        raws[k1].piece = Piece::Bezier(set_end(b, Some(&x1), None));
                    }
                    raws[k1].e += d;
                    raws[k1].e_in += d;
                    continue;
                }
                attach(&mut raws[k], true, &x1, &center, merge);
                attach(&mut raws[k1], false, &x2, &center, merge);
                if x1 != x2 {
                    inserts[k] = Some(Raw {
                        piece: Piece::Arc(Arc {
                            center,
                            radius: r.clone(),
                            from: x1,
                            to: x2,
                            clockwise,
                        }),
                        e: e1.max(e2),
                        e_in: 0.0,
                        kind: Kind::Boundary,
                        link: None,
                    });
                } else if let Piece::Bezier(b) = &raws[k1].piece {
                    let _ = b;
                }
            }
            Some(Junction::Overlap { center }) => {
                let d = dist_hi(&p1, &p2);
                if p1 != p2 && d <= merge {
                    // a connector shorter than `merge`: move the next start
                    if let Piece::Bezier(b) = &raws[k1].piece {
                        raws[k1].piece = Piece::Bezier(set_end(b, Some(&p1), None));
                    }
                    raws[k1].e += d;
                    raws[k1].e_in += d;
                } else if p1 != p2 {
                    let e_in = (dist_hi(&p1, &center).max(dist_hi(&p2, &center)) - r.approx())
                        .max(0.0)
                        * (1.0 + 1e-12);
                    inserts[k] = Some(Raw {
                        piece: Piece::Bezier(Bezier::new(vec![p1, p2])),
                        e: f64::INFINITY,
                        e_in,
                        kind: Kind::Connector,
                        link: None,
                    });
                }
            }
            _ => {
                if p1 != p2 {
                    // smooth junction with float ends that differ: move the next start
                    let d = dist_hi(&p1, &p2);
                    if let Piece::Bezier(b) = &raws[k1].piece {
                        raws[k1].piece = Piece::Bezier(set_end(b, Some(&p1), None));
                    }
                    raws[k1].e += d;
                    raws[k1].e_in += d;
                }
            }
        }
    }
    for (k, r) in raws.into_iter().enumerate() {
        out.push(r);
        if let Some(ins) = inserts[k].take() {
            out.push(ins);
        }
    }
    Ok(out)
}

/// The exact offset at signed distance `d` (to the left) of the span
/// `[t₀, t₁]` of a straight piece `x` whose unit normal is rational: every
/// hodograph control point a positive multiple of `v = x(1) − x(0)` (so
/// `x′ ≠ 0` and the direction is constant) and `|v|` rational. Then
/// `E(t) = x(t) + d·n` for the one normal `n = (−v_y, v_x)/|v|`: the control
/// points shifted by `d·n`, restricted to the span — exactly `E` with the
/// same parameter (the identity map).
fn exact_line_offset(
    x: &Bezier<Rational>,
    d: &Rational,
    t: (f64, f64),
) -> Option<Bezier<Rational>> {
    let p = x.points();
    let v = p[p.len() - 1].sub(&p[0]);
    for w in p.windows(2) {
        let h = w[1].sub(&w[0]);
        if !(&h.x * &v.y - &h.y * &v.x).is_zero() || !(&h.x * &v.x + &h.y * &v.y).is_positive() {
            return None;
        }
    }
    let n2 = &v.x * &v.x + &v.y * &v.y;
    let (sn, sd) = (n2.numer().sqrt(), n2.denom().sqrt());
    if &sn * &sn != *n2.numer() || &sd * &sd != *n2.denom() {
        return None;
    }
    let len = Rational::new(sn, sd);
    let shift = V2::new(-(&v.y) * d / &len, &v.x * d / &len);
    let moved = Bezier::new(p.iter().map(|q| q.add(&shift)).collect());
    Some(moved.restrict(&rational_from_f64(t.0)?, &rational_from_f64(t.1)?))
}

/// The end of a raw offset segment where it meets an exact arc about
/// `center` at the arc's end point `x` (on the circle): the end control point
/// becomes `x` (fact 4: the move is added to `e`, `e_in`), and the control
/// point next to it is projected onto the circle's tangent at `x`, so the
/// segment leaves the arc with an **exactly** common tangent (its float
/// construction is tangent up to rounding, which would leave a second
/// contact with the circle a few ulps from the joint that no interval test
/// can place). Both moves add up: a point of the Bézier moves by at most
/// `B_n(t)·δ_end + B_{n−1}(t)·δ_handle ≤ δ_end + δ_handle`. The projection
/// is skipped for lines and when it would move the handle by more than
/// `max_move`.
fn attach(raw: &mut Raw, at_end: bool, x: &V2<Rational>, center: &V2<Rational>, max_move: f64) {
    let Piece::Bezier(b) = &raw.piece else {
        return;
    };
    let p = b.points();
    let n = p.len() - 1;
    let old = if at_end { &p[n] } else { &p[0] };
    let d = dist_hi(old, x);
    let mut pts = p.to_vec();
    if at_end {
        pts[n] = x.clone();
    } else {
        pts[0] = x.clone();
    }
    let mut moved = d;
    if n >= 2 {
        let k = if at_end { n - 1 } else { 1 };
        // the tangent line at x: x + s·τ, τ ⟂ (x − c)
        let tau = x.sub(center).rot90();
        let t2 = tau.norm2();
        if !t2.is_zero() {
            let s = pts[k].sub(x).dot(&tau) / &t2;
            let q = x.add(&tau.scale(&s));
            let dq = dist_hi(&pts[k], &q);
            if dq <= max_move {
                pts[k] = q;
                moved += dq;
            }
        }
    }
    raw.piece = Piece::Bezier(Bezier::new(pts));
    raw.e += moved;
    raw.e_in += moved;
}

/// `p` itself when it lies exactly on the circle (an exact offset end),
/// else a rational point exactly on it in the direction `dir`.
fn on_or_snap(
    c: &V2<Rational>,
    r: &Rational,
    p: &V2<Rational>,
    dir: &V2<Rational>,
) -> Option<V2<Rational>> {
    if super::circle::on_circle(c, r, p) && !p.sub(c).dot(dir).is_negative() {
        return Some(p.clone());
    }
    snap(c, r, approx_dir(dir))
}

fn reverse_side(side: Vec<Raw>) -> Vec<Raw> {
    side.into_iter()
        .rev()
        .map(|r| Raw {
            piece: r.piece.reversed(),
            link: r.link.map(|l| Link {
                reversed: !l.reversed,
                ..l
            }),
            ..r
        })
        .collect()
}

/// The cap at the end `e` (0: start, 1: end) of the curve: returns the arc or
/// chord from `p_from` (moved to the snapped point) to `p_to`.
fn cap_piece(
    x: &Bezier<Rational>,
    e: u8,
    r: &Rational,
    cap: Cap,
    from_piece: &mut Raw,
    to_piece: &mut Raw,
    max_move: f64,
) -> Result<Raw, StrokeError> {
    let c = if e == 0 {
        x.points()[0].clone()
    } else {
        x.points().last().expect("nonempty").clone()
    };
    let t = end_tangent(x, e).ok_or_else(|| bad("curve", "a degenerate end"))?;
    let n = t.rot90(); // left normal (not unit)
    let neg_n = n.neg();
    // at the end: from −N (the −r side) to +N; at the start: from +N to −N
    let (dir_from, dir_to) = if e == 1 { (neg_n, n) } else { (n, neg_n) };
    let p1 = from_piece.piece.end().clone();
    let p2 = to_piece.piece.start().clone();
    match cap {
        Cap::Butt => {
            let ex1 = unit_normal_point(&c, r, &dir_from);
            let ex2 = unit_normal_point(&c, r, &dir_to);
            let e = dist_hi_iv(&p1, &ex1).max(dist_hi_iv(&p2, &ex2));
            let e_in =
                (dist_hi(&p1, &c).max(dist_hi(&p2, &c)) - r.approx()).max(0.0) * (1.0 + 1e-12);
            Ok(Raw {
                piece: Piece::Bezier(Bezier::new(vec![p1, p2])),
                e,
                e_in,
                kind: Kind::Butt,
                link: None,
            })
        }
        Cap::Round => {
            let x1 = on_or_snap(&c, r, &p1, &dir_from).ok_or_else(|| bad("curve", "cap"))?;
            let x2 = on_or_snap(&c, r, &p2, &dir_to).ok_or_else(|| bad("curve", "cap"))?;
            attach(from_piece, true, &x1, &c, max_move);
            attach(to_piece, false, &x2, &c, max_move);
            let e1 = dist_hi_iv(&x1, &unit_normal_point(&c, r, &dir_from));
            let e2 = dist_hi_iv(&x2, &unit_normal_point(&c, r, &dir_to));
            Ok(Raw {
                piece: Piece::Arc(Arc {
                    center: c,
                    radius: r.clone(),
                    from: x1,
                    to: x2,
                    clockwise: false,
                }),
                e: e1.max(e2),
                e_in: 0.0,
                kind: Kind::Boundary,
                link: None,
            })
        }
    }
}

/// Checks the inputs; `true` when the curve is closed.
/// The connected components of the curve (pieces joined end to start):
/// `(first, end, closed)` with `curve[first..end]` one component.
fn components(curve: &[Bezier<Rational>]) -> Vec<(usize, usize, bool)> {
    let mut out: Vec<(usize, usize, bool)> = Vec::new();
    for i in 0..curve.len() {
        let joined = i > 0 && curve[i - 1].points().last() == curve[i].points().first();
        match out.last_mut() {
            Some(c) if joined => c.1 = i + 1,
            _ => out.push((i, i + 1, false)),
        }
    }
    for c in &mut out {
        let part = &curve[c.0..c.1];
        let closed = part.len() > 1 || part[0].degree() > 1;
        c.2 = closed && part.last().and_then(|b| b.points().last()) == part[0].points().first();
    }
    out
}

fn check(
    curve: &[Bezier<Rational>],
    opts: &StrokeOptions,
) -> Result<Vec<(usize, usize, bool)>, StrokeError> {
    if curve.is_empty() {
        return Err(bad("curve", "no pieces"));
    }
    if opts.ellipse.is_none() && !opts.radius.is_positive() {
        return Err(bad("radius", "must be > 0"));
    }
    if !(opts.tol.is_finite() && opts.tol > 0.0) {
        return Err(bad("tol", "must be a positive number"));
    }
    for (i, b) in curve.iter().enumerate() {
        if b.degree() == 0 {
            return Err(bad("curve", format!("piece {i} is a point")));
        }
    }
    let comps = components(curve);
    if comps.len() > MAX_COMPONENTS {
        return Err(bad(
            "curve",
            format!(
                "{} separate contours (at most {MAX_COMPONENTS})",
                comps.len()
            ),
        ));
    }
    for &(first, end, closed) in &comps {
        if opts.ellipse.is_none() {
            continue;
        }
        // the elliptical pen has no join pieces yet: the curve must be G¹
        let part = &curve[first..end];
        let n = part.len();
        let joints = if closed { n } else { n - 1 };
        for i in 0..joints {
            let (a, b) = (&part[i], &part[(i + 1) % n]);
            let g1 = match (end_tangent(a, 1), end_tangent(b, 0)) {
                (Some(u), Some(v)) => u.cross(&v).is_zero() && u.dot(&v).is_positive(),
                _ => false,
            };
            if !g1 {
                return Err(bad(
                    "curve",
                    format!("a G⁰ corner after piece {}: the elliptical pen needs a G¹ curve (join pieces are not supported yet)", first + i),
                ));
            }
        }
    }
    Ok(comps)
}

/// Most separate contours of one stroke.
const MAX_COMPONENTS: usize = 256;

/// The raw contours (before trimming).
#[allow(clippy::type_complexity)]
fn raw_contours(
    curve: &[Bezier<Rational>],
    opts: &StrokeOptions,
    closed: bool,
    first: usize,
    raw_div: f64,
) -> Result<(Vec<Vec<Raw>>, Vec<String>, Vec<CapReport>), StrokeError> {
    let r = &opts.radius;
    let tol_off = opts.tol / raw_div;
    let run = |d: Rational| {
        let mut o = OffsetOptions::new(d.clone(), tol_off);
        o.output = opts.output;
        o.method = opts.method;
        match &opts.ellipse {
            // the convolution sides x ∗ e_σ, σ = sign(d), certified for the exact pen
            Some(pen) => {
                let side = if d.is_negative() { -1 } else { 1 };
                convolve(curve, pen, side, &o).map_err(|e| bad("curve", e.to_string()))
            }
            None => offset(curve, &o).map_err(|e| bad("curve", e.to_string())),
        }
    };
    let (minus, plus) = rayon::join(|| run(-r.clone()), || run(r.clone()));
    let (minus, plus) = (minus?, plus?);
    let mut notes = Vec::new();
    for (name, res) in [("-r", &minus), ("+r", &plus)] {
        if !res.reached() || !res.proven {
            notes.push(format!(
                "the {name} offset did not reach tol/{raw_div} (certified {:.3e})",
                res.certified_hi
            ));
        }
    }
    // joins and connectors shorter than this are merged into one exact point
    let merge = opts.tol / 64.0;
    // the exact-interval kept test is for a circular pen (offset sides)
    let strip = |mut side: Vec<Raw>| {
        if opts.ellipse.is_some() {
            for raw in &mut side {
                raw.link = None;
            }
        }
        side
    };
    // exact offsets of straight pieces: for a circular pen only
    let lines = opts.ellipse.is_none().then_some(curve);
    let a = strip(chain_side(&minus, r, closed, merge, first, lines)?);
    let b = strip(reverse_side(chain_side(
        &plus, r, closed, merge, first, lines,
    )?));
    if closed {
        return Ok((vec![a, b], notes, Vec::new()));
    }
    let (mut a, mut b) = (a, b);
    let x_end = curve.last().expect("nonempty");
    let (na, nb) = (a.len() - 1, b.len() - 1);
    let mut caps = Vec::new();
    let end_cap = {
        let (a_last, b_first) = (&mut a[na].clone(), &mut b[0].clone());
        let cap = match &opts.ellipse {
            Some(pen) => ellipse_cap_piece(x_end, 1, pen, opts, a_last, b_first, &mut caps)?,
            None => vec![cap_piece(x_end, 1, r, opts.cap, a_last, b_first, merge)?],
        };
        a[na] = a_last.clone();
        b[0] = b_first.clone();
        cap
    };
    let start_cap = {
        let (b_last, a_first) = (&mut b[nb].clone(), &mut a[0].clone());
        let cap = match &opts.ellipse {
            Some(pen) => ellipse_cap_piece(&curve[0], 0, pen, opts, b_last, a_first, &mut caps)?,
            None => vec![cap_piece(
                &curve[0], 0, r, opts.cap, b_last, a_first, merge,
            )?],
        };
        b[nb] = b_last.clone();
        a[0] = a_first.clone();
        cap
    };
    let mut all = a;
    all.extend(end_cap);
    all.extend(b);
    all.extend(start_cap);
    Ok((vec![all], notes, caps))
}

/// The cap of an elliptical pen at the end `e` (0: start, 1: end): the half
/// ellipse as proven cubics ([`half_ellipse_cap`], within `tol/8`), the
/// neighbouring sides' end control points replaced by its exact ends (the
/// moves added to their bounds), or the butt chord.
#[allow(clippy::too_many_arguments)]
fn ellipse_cap_piece(
    x: &Bezier<Rational>,
    e: u8,
    pen: &Pen,
    opts: &StrokeOptions,
    from_piece: &mut Raw,
    to_piece: &mut Raw,
    caps: &mut Vec<CapReport>,
) -> Result<Vec<Raw>, StrokeError> {
    let c = if e == 0 {
        x.points()[0].clone()
    } else {
        x.points().last().expect("nonempty").clone()
    };
    let t = end_tangent(x, e).ok_or_else(|| bad("curve", "a degenerate end"))?;
    let n = t.rot90();
    let (dir_from, dir_to, out) = if e == 1 {
        (n.neg(), n, t)
    } else {
        (n.clone(), n.neg(), t.neg())
    };
    let p1 = from_piece.piece.end().clone();
    let p2 = to_piece.piece.start().clone();
    let ex1 = pen_point_enclosure(&c, pen, &dir_from);
    let ex2 = pen_point_enclosure(&c, pen, &dir_to);
    if opts.cap == Cap::Butt {
        let err = dist_hi_iv(&p1, &ex1).max(dist_hi_iv(&p2, &ex2));
        // the chord lies within `err` of the convex c + E
        return Ok(vec![Raw {
            piece: Piece::Bezier(Bezier::new(vec![p1, p2])),
            e: err,
            e_in: err,
            kind: Kind::Butt,
            link: None,
        }]);
    }
    let cap = half_ellipse_cap(&c, pen, &dir_from, &out, opts.tol / 8.0)
        .ok_or_else(|| bad("pen", "the half-ellipse cap could not be proven"))?;
    let x1 = cap.pieces[0].points()[0].clone();
    let x2 = cap.pieces.last().expect("k ≥ 2").points()[3].clone();
    let d1 = dist_hi(&p1, &x1);
    let d2 = dist_hi(&p2, &x2);
    if let Piece::Bezier(b) = &from_piece.piece {
        from_piece.piece = Piece::Bezier(set_end(b, None, Some(&x1)));
    }
    from_piece.e += d1;
    from_piece.e_in += d1;
    if let Piece::Bezier(b) = &to_piece.piece {
        to_piece.piece = Piece::Bezier(set_end(b, Some(&x2), None));
    }
    to_piece.e += d2;
    to_piece.e_in += d2;
    caps.push(CapReport {
        end: if e == 1 { "end" } else { "start" },
        pieces: cap.pieces.len(),
        error: cap.error,
        circle_error: cap.circle_error,
    });
    Ok(cap
        .pieces
        .into_iter()
        .map(|b| Raw {
            piece: Piece::Bezier(b),
            e: cap.error,
            e_in: cap.error,
            kind: Kind::Boundary,
            link: None,
        })
        .collect())
}

// ---------------------------------------------------------------------------
// distance to the input curve

/// Float estimate of the pen distance of `p` to `x` ([`Form::estimate`] of
/// `min_t g(p − x(t))`; for a circle `dist(p, x)`) and the foot `(piece, t)`.
fn foot(curve: &[Bezier<f64>], form: &Form, p: (f64, f64)) -> (f64, usize, f64) {
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
enum Part {
    Bez(Bezier<Interval>),
    Arc(Arc),
}

fn iv_point(p: &V2<Rational>) -> V2<Interval> {
    p.map(interval_from_rational)
}

/// An upper bound of `|p − w|` over the box `p`.
fn box_dist_hi(p: &V2<Interval>, w: &V2<Interval>) -> f64 {
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
    fn hull(&self) -> Option<Vec<V2<Interval>>> {
        match self {
            Part::Bez(b) => Some(b.points().to_vec()),
            Part::Arc(a) => a.hull().map(|h| h.iter().map(iv_point).collect()),
        }
    }
    fn halves(&self) -> Option<(Part, Part)> {
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
    fn mid_right_normal(&self) -> ((f64, f64), (f64, f64)) {
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
    fn initial(p: &Piece) -> Option<Vec<Part>> {
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

/// Kept test: every point of the piece is within the returned bound of a
/// point proven outside `S`. Returns the largest such distance.
fn prove_kept(
    curve: &[Bezier<Rational>],
    curve_f: &[Bezier<f64>],
    piece: &Piece,
    e_in: f64,
    form: &Form,
    budget: f64,
) -> Option<f64> {
    let rf = form.reach;
    let mut todo: Vec<(Part, u32)> = Part::initial(piece)?.into_iter().map(|p| (p, 0)).collect();
    let mut worst: f64 = 0.0;
    let mut n = 0;
    while let Some((part, depth)) = todo.pop() {
        n += 1;
        if n > 4000 {
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
                if outside(curve, &w, form) {
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
/// `lambda` of one of `near` (kept crossing points). Returns whether `near`
/// was used.
#[allow(clippy::too_many_arguments)]
fn prove_removed(
    curve: &[Bezier<Rational>],
    curve_f: &[Bezier<f64>],
    piece: &Piece,
    e: f64,
    local: &dyn Fn(f64, f64) -> Option<f64>,
    form: &Form,
    near: &[V2<Rational>],
    lambda: &Rational,
) -> Option<bool> {
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
    let mut used = false;
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
        if near.iter().any(|x| {
            hull.iter().all(|p| {
                let d = p.sub(x).norm2();
                !d.is_empty() && d.sup() < l2
            })
        }) {
            used = true;
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

// ---------------------------------------------------------------------------
// splitting

#[derive(Clone, Debug)]
struct Split {
    /// Bézier: the parameter; arc: unused.
    param: Rational,
    /// The exact crossing point shared by both pieces.
    point: V2<Rational>,
}

#[derive(Clone, Debug)]
struct Sub {
    raw: usize,
    /// The exact sub-piece of the raw piece (its union over the raw piece is
    /// the raw piece).
    pre: Piece,
    /// With the crossing points as end points (what is output).
    post: Piece,
    /// Largest end move.
    delta: f64,
    /// The sub-piece's ends are crossing points (not raw piece ends).
    end_splits: [bool; 2],
    /// Bézier: its parameter range on the raw piece (`pre` is the exact
    /// restriction to it).
    range: (Rational, Rational),
}

fn split_piece(raw: usize, p: &Piece, splits: &mut [Split]) -> Vec<Sub> {
    match p {
        Piece::Bezier(b) => {
            splits.sort_by(|a, b| a.param.cmp(&b.param));
            let zero = <Rational as Zero>::zero();
            let one = <Rational as One>::one();
            let mut out = Vec::new();
            let mut prev: Option<&Split> = None;
            for k in 0..=splits.len() {
                let next = splits.get(k);
                let a = prev.map(|s| s.param.clone()).unwrap_or(zero.clone());
                let bb = next.map(|s| s.param.clone()).unwrap_or(one.clone());
                let pre = b.restrict(&a, &bb);
                let post = set_end(&pre, prev.map(|s| &s.point), next.map(|s| &s.point));
                let mut delta: f64 = 0.0;
                if let Some(s) = prev {
                    delta = delta.max(dist_hi(&pre.points()[0], &s.point));
                }
                if let Some(s) = next {
                    delta = delta.max(dist_hi(pre.points().last().expect("nonempty"), &s.point));
                }
                out.push(Sub {
                    raw,
                    pre: Piece::Bezier(pre),
                    post: Piece::Bezier(post),
                    delta,
                    end_splits: [prev.is_some(), next.is_some()],
                    range: (a, bb),
                });
                prev = next;
            }
            out
        }
        Piece::Arc(a) => {
            // order along the travel direction by the angle from the start
            let ang = |pt: &V2<Rational>| {
                let u = approx_dir(&a.from.sub(&a.center));
                let v = approx_dir(&pt.sub(&a.center));
                let mut d = v.1.atan2(v.0) - u.1.atan2(u.0);
                if a.clockwise {
                    d = -d;
                }
                d.rem_euclid(2.0 * std::f64::consts::PI)
            };
            splits.sort_by(|x, y| ang(&x.point).total_cmp(&ang(&y.point)));
            let mut out = Vec::new();
            let mut cur = a.clone();
            let mut first = true;
            for s in splits.iter() {
                let (l, r) = cur.split_at(&s.point);
                out.push(Sub {
                    raw,
                    pre: Piece::Arc(l.clone()),
                    post: Piece::Arc(l),
                    delta: 0.0,
                    end_splits: [!first, true],
                    range: (<Rational as Zero>::zero(), <Rational as One>::one()),
                });
                first = false;
                cur = r;
            }
            out.push(Sub {
                raw,
                pre: Piece::Arc(cur.clone()),
                post: Piece::Arc(cur),
                delta: 0.0,
                end_splits: [!first, false],
                range: (<Rational as Zero>::zero(), <Rational as One>::one()),
            });
            out
        }
    }
}

/// The crossing of two degree-1 pieces with non-parallel directions, exact:
/// the point and both parameters (inside `[0, 1]`), `None` otherwise.
fn segment_crossing(
    a: &Bezier<Rational>,
    b: &Bezier<Rational>,
) -> Option<(V2<Rational>, Rational, Rational)> {
    if a.degree() != 1 || b.degree() != 1 {
        return None;
    }
    let (p, q) = (&a.points()[0], &a.points()[1]);
    let (u, v) = (&b.points()[0], &b.points()[1]);
    let (d1, d2) = (q.sub(p), v.sub(u));
    let den = d1.cross(&d2);
    if den.is_zero() {
        return None;
    }
    let w = u.sub(p);
    let s = w.cross(&d2) / &den;
    let t = w.cross(&d1) / &den;
    let unit = |x: &Rational| !x.is_negative() && *x <= <Rational as One>::one();
    (unit(&s) && unit(&t)).then(|| (p.add(&d1.scale(&s)), s, t))
}

/// The exact projection of `x` onto a degree-1 piece and its parameter,
/// when that parameter is strictly inside `(0, 1)`.
fn project_on_segment(a: &Bezier<Rational>, x: &V2<Rational>) -> Option<(V2<Rational>, Rational)> {
    let (p, q) = (&a.points()[0], &a.points()[1]);
    let d = q.sub(p);
    let n2 = d.norm2();
    if n2.is_zero() {
        return None;
    }
    let u = x.sub(p).dot(&d) / n2;
    (u.is_positive() && u < <Rational as One>::one()).then(|| (p.add(&d.scale(&u)), u))
}

fn mid_rational(lo: f64, hi: f64) -> Option<Rational> {
    rational_from_f64(0.5 * lo + 0.5 * hi)
}

/// Builds the proven stroke outline of `curve` with a circular pen of radius
/// `opts.radius` (see the module docs and `proofs/trimming.md`).
///
/// Errors name the field: an empty or disconnected curve, a point piece, a
/// radius that is not positive, a tolerance that is not a positive number, or
/// an offset error (a singular input piece). Claims that cannot be decided are
/// not errors: they come back unproven with a note.
///
/// # Examples
/// ```
/// use lncert::outline::trim::{stroke, StrokeOptions, Orientation};
/// use lncert::shape::parse_curve;
/// use lncert::parse_rational;
/// // a straight segment: the stadium, two segments and two half circles
/// let x = parse_curve("M 0 0 L 2 0").unwrap();
/// let s = stroke(&x, &StrokeOptions::new(parse_rational("1/2").unwrap(), 1e-3)).unwrap();
/// assert!(s.proven(), "{:?} {:?} {:?}", s.a, s.b, s.c);
/// assert_eq!(s.contours.len(), 1);
/// assert_eq!(s.contours[0].orientation, Orientation::CounterClockwise);
/// assert!(s.contours[0].closed);
/// ```
pub fn stroke(curve: &[Bezier<Rational>], opts: &StrokeOptions) -> Result<Stroke, StrokeError> {
    let first = stroke_at(curve, opts, 8.0)?;
    if first.classified.undecided == 0 && first.c.proven {
        return Ok(first);
    }
    // refinement on demand: sub-pieces that neither test decides are most
    // often a raw piece whose error bound `e` is as large as the geometry it
    // must resolve (a shallow crossing, a tail inside S by less than `e`);
    // the sides are rebuilt once at TOL/64 and the better outcome is kept
    let second = stroke_at(curve, opts, 64.0)?;
    let score = |s: &Stroke| {
        (
            [s.a.proven, s.b.proven, s.c.proven]
                .iter()
                .filter(|p| **p)
                .count(),
            std::cmp::Reverse(s.classified.undecided),
        )
    };
    if score(&second) > score(&first) {
        let mut second = second;
        second.notes.push(format!(
            "the sides were rebuilt at TOL/64 (at TOL/8 {} sub-pieces were undecided{})",
            first.classified.undecided,
            if first.c.proven {
                ""
            } else {
                ", claim (c) not proven"
            }
        ));
        Ok(second)
    } else {
        Ok(first)
    }
}

/// [`stroke`] with the sides built within `TOL / raw_div`.
fn stroke_at(
    curve: &[Bezier<Rational>],
    opts: &StrokeOptions,
    raw_div: f64,
) -> Result<Stroke, StrokeError> {
    let comps = check(curve, opts)?;
    let closed = comps.iter().all(|c| c.2);
    let form = opts.form()?;
    let form = &form;
    let dbg = std::env::var("LNCERT_TRIM_DEBUG").is_ok();
    let t0 = std::time::Instant::now();
    // every component's sides and caps; the trimming below is over all of
    // them (the region is the union of the components' regions)
    let mut raw_contours_all = Vec::new();
    let mut notes = Vec::new();
    let mut caps = Vec::new();
    for &(first, end, c_closed) in &comps {
        let (rc, n, cp) = raw_contours(&curve[first..end], opts, c_closed, first, raw_div)?;
        raw_contours_all.extend(rc);
        notes.extend(n);
        caps.extend(cp);
    }
    let raw_contours = raw_contours_all;
    if dbg {
        eprintln!("offsets: {:?}", t0.elapsed());
    }
    let raws: Vec<Raw> = raw_contours.into_iter().flatten().collect();
    let curve_f: Vec<Bezier<f64>> = curve.iter().map(|b| b.map(Scalar::approx)).collect();

    // --- crossings of the raw arrangement
    let iopts = IntersectOptions {
        max_boxes_per_pair: opts.max_boxes_per_pair,
        self_intersections: true,
    };
    let bez_idx: Vec<usize> = (0..raws.len())
        .filter(|&i| matches!(raws[i].piece, Piece::Bezier(_)))
        .collect();
    let arc_idx: Vec<usize> = (0..raws.len())
        .filter(|&i| matches!(raws[i].piece, Piece::Arc(_)))
        .collect();
    let bez: Vec<Bezier<Rational>> = bez_idx
        .iter()
        .map(|&i| match &raws[i].piece {
            Piece::Bezier(b) => b.clone(),
            Piece::Arc(_) => unreachable!(),
        })
        .collect();
    let inter = intersections(&bez, &iopts);
    if dbg {
        eprintln!(
            "raw intersections: {:?} {} boxes",
            t0.elapsed(),
            inter.boxes
        );
        for (k, r) in raws.iter().enumerate() {
            eprintln!(
                "raw {k}: {:?} e={:.3e} {:?}",
                r.kind,
                r.e,
                match &r.piece {
                    Piece::Bezier(b) => format!(
                        "bez deg {} {:?}",
                        b.degree(),
                        b.map(Scalar::approx).points()
                    ),
                    Piece::Arc(a) => format!("arc {:?}", a.desc()),
                }
            );
        }
        for u in &inter.undecided {
            eprintln!("undecided {:?}", u);
        }
    }
    let mut raw_complete = inter.complete;
    let mut splits: Vec<Vec<Split>> = vec![Vec::new(); raws.len()];
    let mut crossings = Vec::new();
    let fail = |notes: &mut Vec<String>, s: String| {
        if notes.len() < 20 && !notes.contains(&s) {
            notes.push(s);
        }
    };
    for u in &inter.undecided {
        fail(
            &mut notes,
            format!(
                "raw pieces {} and {}: {} region undecided",
                bez_idx[u.pieces.0], bez_idx[u.pieces.1], u.reason
            ),
        );
    }
    for c in &inter.crossings {
        let (i, j) = (bez_idx[c.pieces.0], bez_idx[c.pieces.1]);
        let (px, py) = (
            mid_rational(c.point.0 .0, c.point.0 .1),
            mid_rational(c.point.1 .0, c.point.1 .1),
        );
        let (s, t) = (mid_rational(c.s.0, c.s.1), mid_rational(c.t.0, c.t.1));
        // two straight segments: their crossing is rational, split exactly
        // there (no end moves; an exact point keeps later joints exact)
        let exact = match (&raws[i].piece, &raws[j].piece) {
            (Piece::Bezier(a), Piece::Bezier(b)) => segment_crossing(a, b),
            _ => None,
        };
        let (px, py, s, t) = match exact {
            Some((p, s, t)) => (Some(p.x), Some(p.y), Some(s), Some(t)),
            None => match (&raws[i].piece, &raws[j].piece, &px, &py) {
                // one straight segment: the crossing point projected onto
                // it exactly, so its halves stay on its line (a half tilted
                // by an ulp would meet the next join arc almost tangentially)
                (Piece::Bezier(a), _, Some(x), Some(y)) if a.degree() == 1 => {
                    match project_on_segment(a, &V2::new(x.clone(), y.clone())) {
                        Some((q, u)) => (Some(q.x), Some(q.y), Some(u), t),
                        None => (px, py, s, t),
                    }
                }
                (_, Piece::Bezier(b), Some(x), Some(y)) if b.degree() == 1 => {
                    match project_on_segment(b, &V2::new(x.clone(), y.clone())) {
                        Some((q, u)) => (Some(q.x), Some(q.y), s, Some(u)),
                        None => (px, py, s, t),
                    }
                }
                _ => (px, py, s, t),
            },
        };
        if let (Some(xx), Some(xy), Some(s), Some(t)) = (px, py, s, t) {
            let point = V2::new(xx, xy);
            splits[i].push(Split {
                param: s,
                point: point.clone(),
            });
            splits[j].push(Split { param: t, point });
            crossings.push(RawCrossing {
                pieces: (i, j),
                s: c.s,
                t: c.t,
            });
        }
    }
    // Bézier–arc
    for &ai in &arc_idx {
        let Piece::Arc(arc) = &raws[ai].piece else {
            continue;
        };
        for &bi in &bez_idx {
            let Piece::Bezier(b) = &raws[bi].piece else {
                continue;
            };
            let m = bezier_arc(b, arc);
            if dbg && (!m.hits.is_empty() || !m.undecided.is_empty()) {
                eprintln!("bez {bi} arc {ai}: {:?}", m);
            }
            if !m.undecided.is_empty() {
                raw_complete = false;
                fail(
                    &mut notes,
                    format!("raw pieces {bi} and {ai}: arc range undecided"),
                );
            }
            for h in m.hits {
                // the joint: the Bézier's end point is the arc's end point
                if h.t.0 == h.t.1 {
                    let zero = <Rational as Zero>::zero();
                    let one = <Rational as One>::one();
                    let pt = if h.t.0 == zero {
                        Some(b.points()[0].clone())
                    } else if h.t.0 == one {
                        b.points().last().cloned()
                    } else {
                        None
                    };
                    if let Some(pt) = pt {
                        if pt == arc.from || pt == arc.to {
                            continue;
                        }
                    }
                }
                if h.multiple {
                    raw_complete = false;
                    fail(
                        &mut notes,
                        format!("raw pieces {bi} and {ai}: tangential contact"),
                    );
                    continue;
                }
                let s = (&h.t.0 + &h.t.1) / Rational::from_integer(2.into());
                let p = b.eval(&s);
                let x = snap(&arc.center, &arc.radius, approx_dir(&p.sub(&arc.center)));
                match x {
                    Some(x)
                        if arc.contains_dir(&x.sub(&arc.center)) == Some(true)
                            && x != arc.from
                            && x != arc.to =>
                    {
                        splits[bi].push(Split {
                            param: s,
                            point: x.clone(),
                        });
                        splits[ai].push(Split {
                            param: <Rational as Zero>::zero(),
                            point: x,
                        });
                        crossings.push(RawCrossing {
                            pieces: (bi.min(ai), bi.max(ai)),
                            s: (h.t.0.approx(), h.t.1.approx()),
                            t: (0.0, 0.0),
                        });
                    }
                    _ => {
                        raw_complete = false;
                        fail(
                            &mut notes,
                            format!("raw pieces {bi} and {ai}: crossing at an arc end"),
                        );
                    }
                }
            }
        }
    }
    // arc–arc: a crossing cannot be split exactly: undecided
    for (k, &ai) in arc_idx.iter().enumerate() {
        for &aj in &arc_idx[k + 1..] {
            let (Piece::Arc(a), Piece::Arc(b)) = (&raws[ai].piece, &raws[aj].piece) else {
                continue;
            };
            let shared = [&a.from, &a.to]
                .into_iter()
                .find(|p| **p == b.from || **p == b.to);
            if arcs_meet(a, b, shared) != Some(false) {
                raw_complete = false;
                fail(
                    &mut notes,
                    format!("raw arcs {ai} and {aj} may meet (arc–arc crossings are not split)"),
                );
            }
        }
    }

    if dbg {
        eprintln!("arcs: {:?}", t0.elapsed());
    }
    // --- split
    let mut subs: Vec<Sub> = Vec::new();
    for (i, raw) in raws.iter().enumerate() {
        subs.extend(split_piece(i, &raw.piece, &mut splits[i]));
    }

    // --- classify: kept first (the near-crossing relaxation of removal needs them)
    let tol = opts.tol;
    use rayon::prelude::*;
    let estimates: Vec<f64> = subs
        .par_iter()
        .map(|s| {
            let (m, _) = Part::initial(&s.pre)
                .and_then(|p| p.into_iter().next())
                .map(|p| p.mid_right_normal())
                .unwrap_or(((0.0, 0.0), (0.0, 0.0)));
            foot(&curve_f, form, m).0
        })
        .collect();
    if dbg {
        eprintln!("estimates: {:?}", t0.elapsed());
    }
    let rf = form.reach;
    let onside_input = form
        .circle
        .then(|| super::onside::Input::new(curve, &comps, &opts.radius));
    let kept_bounds: Vec<Option<f64>> = subs
        .par_iter()
        .zip(&estimates)
        .map(|(s, est)| {
            let tt = std::time::Instant::now();
            let r = (|| {
                let raw = &raws[s.raw];
                let e_in = raw.e_in + s.delta;
                if raw.kind == Kind::Butt {
                    return Some(e_in);
                }
                if *est < rf - 4.0 * e_in.max(tol / 8.0) {
                    return None;
                }
                // one decision for the whole sub-piece where the exact offset
                // points it stands for are proven on ∂S (module `onside`); an
                // exact cap or join arc is its own exact counterpart
                if let (Piece::Arc(arc), Some(input)) = (&s.pre, &onside_input) {
                    let budget = tol - e_in;
                    if budget > 0.0 {
                        if let Some(l) = input.prove_arc(arc, budget, 2048) {
                            return Some(e_in + l);
                        }
                    }
                    if dbg {
                        eprintln!("onside failed: raw {} (arc)", s.raw);
                    }
                }
                if let (Some(link), Some(input)) = (&raw.link, &onside_input) {
                    let budget = tol - e_in;
                    let range = (s.range.0.approx(), s.range.1.approx());
                    let pad = 1e-12;
                    if budget > 0.0 {
                        if let Some((t0, t1)) = link.exact_range(range.0 - pad, range.1 + pad) {
                            if let Some(l) =
                                input.prove_interval(link.piece, &link.d, t0, t1, budget, 2048)
                            {
                                return Some(e_in + l);
                            }
                            if dbg {
                                eprintln!(
                                    "onside failed: raw {} piece {} t [{t0}, {t1}]",
                                    s.raw, link.piece
                                );
                            }
                        } else if dbg {
                            eprintln!("onside: no exact range for raw {}", s.raw);
                        }
                    }
                }
                prove_kept(curve, &curve_f, &s.post, e_in, form, tol)
            })();
            if dbg {
                eprintln!("kept raw {} {:?} {:?}", s.raw, tt.elapsed(), r);
            }
            r
        })
        .collect();
    if dbg {
        eprintln!("kept: {:?}", t0.elapsed());
    }
    let near: Vec<V2<Rational>> = subs
        .iter()
        .zip(&kept_bounds)
        .filter(|(_, k)| k.is_some())
        .flat_map(|(s, _)| {
            let mut v = Vec::new();
            if s.end_splits[0] {
                v.push(s.post.start().clone());
            }
            if s.end_splits[1] {
                v.push(s.post.end().clone());
            }
            v
        })
        .collect();
    // λ of the removal: a removed part within λ of a kept crossing point
    // costs (b) e + λ, so λ may use what TOL leaves above e (at least TOL/2)
    let lambda_f = |e: f64| (0.95 * (tol - e)).max(tol / 2.0);
    let lambda_for =
        |e: f64| rational_from_f64(lambda_f(e)).unwrap_or_else(<Rational as Zero>::zero);
    let removed: Vec<Option<bool>> = subs
        .par_iter()
        .zip(&kept_bounds)
        .map(|(s, k)| {
            let raw = &raws[s.raw];
            if k.is_some() || raw.kind != Kind::Boundary {
                return None;
            }
            let tt = std::time::Instant::now();
            // the error bound of a part of `pre` (parameters `[t0, t1]` on it):
            // the map's boxes over it plus the raw piece's moves since
            let local = |t0: f64, t1: f64| -> Option<f64> {
                let link = raw.link.as_ref()?;
                let (r0, r1) = (s.range.0.approx(), s.range.1.approx());
                let pad = 1e-9;
                let lb = link.local_bound(r0 + t0 * (r1 - r0) - pad, r0 + t1 * (r1 - r0) + pad)?;
                // `raw.e − seg_e` is a float difference: a few ulps of
                // `raw.e` cover its rounding (and that of raw.e's sums)
                let moved = (raw.e - link.seg_e).max(0.0) + 8.0 * f64::EPSILON * raw.e;
                Some((lb + moved) * (1.0 + 1e-12))
            };
            let lambda = lambda_for(raw.e);
            let r = prove_removed(curve, &curve_f, &s.pre, raw.e, &local, form, &near, &lambda);
            if dbg {
                eprintln!("removed raw {} {:?} {:?}", s.raw, tt.elapsed(), r);
            }
            r
        })
        .collect();
    let mut classified = Classified::default();
    let mut a_bound: f64 = 0.0;
    let mut b_bound: f64 = 0.0;
    let mut a_ok = true;
    let mut b_ok = true;
    let mut keep = vec![false; subs.len()];
    for (k, s) in subs.iter().enumerate() {
        let raw = &raws[s.raw];
        if let Some(bd) = kept_bounds[k] {
            classified.kept += 1;
            keep[k] = true;
            a_bound = a_bound.max(bd);
            if raw.kind == Kind::Boundary {
                b_bound = b_bound.max(raw.e + s.delta);
            }
        } else if raw.kind == Kind::Connector {
            classified.dropped_connectors += 1;
        } else if let Some(used) = removed[k] {
            classified.removed += 1;
            b_bound = b_bound.max(raw.e);
            if used {
                // the λ the removal test was given (its rational is exactly
                // this f64), plus a hair for the sum's rounding
                b_bound = b_bound.max((raw.e + lambda_f(raw.e)) * (1.0 + 1e-12));
            }
        } else {
            classified.undecided += 1;
            a_ok = false;
            b_ok = false;
            // shown, not proven: keep what looks like boundary
            keep[k] = estimates[k] >= rf - 2.0 * (raw.e_in + s.delta);
            fail(
                &mut notes,
                format!(
                    "sub-piece of raw piece {} undecided (distance estimate {:.6})",
                    s.raw, estimates[k]
                ),
            );
        }
    }
    for raw in &raws {
        if raw.kind == Kind::Boundary && !raw.e.is_finite() {
            b_ok = false;
        }
    }

    if dbg {
        eprintln!("classified: {:?}", t0.elapsed());
    }
    // --- pinched loops and spurs: kept pieces that close a loop at an exact
    // point X of the output, or dangle from one, each within a certified reach
    // of the pieces that stay at X, are dropped (a boundary point near them
    // is within e + δ + reach of the output)
    let kept_idx: Vec<usize> = (0..subs.len()).filter(|&k| keep[k]).collect();
    // a spur may reach as far from the live pieces as keeps (b) within tol
    let spur_caps: Vec<f64> = kept_idx
        .iter()
        .map(|&k| {
            let raw = &raws[subs[k].raw];
            if raw.kind == Kind::Boundary {
                tol - raw.e - subs[k].delta
            } else {
                // a connector or butt chord stands for no point of ∂S
                tol
            }
        })
        .collect();
    let dropped = pinched_loops(
        &kept_idx.iter().map(|&k| &subs[k].post).collect::<Vec<_>>(),
        &spur_caps,
    );
    if !dropped.is_empty() {
        for &(d, reach) in &dropped {
            let k = kept_idx[d];
            keep[k] = false;
            let raw = &raws[subs[k].raw];
            if raw.kind == Kind::Boundary {
                b_bound = b_bound.max(raw.e + subs[k].delta + reach);
            }
        }
        fail(
            &mut notes,
            format!(
                "{} kept pieces forming pinched loops or spurs dropped (each within a certified reach of the pieces that stay at its point, added to (b))",
                dropped.len()
            ),
        );
    }
    // --- chain
    let out_pieces: Vec<Piece> = subs
        .iter()
        .zip(&keep)
        .filter(|(_, k)| **k)
        .map(|(s, _)| s.post.clone())
        .collect();
    let contours = chain(out_pieces);

    // --- claim (c)
    let (c_ok, c_complete, c_note) = check_simple(&contours, &iopts);
    if dbg {
        eprintln!("checked: {:?}", t0.elapsed());
        for (k, s) in subs.iter().enumerate() {
            eprintln!(
                "sub {k}: raw {} [{:.6}, {:.6}] keep {} kept {:?} removed {:?} est {:.6} delta {:.2e}",
                s.raw, s.range.0.approx(), s.range.1.approx(), keep[k], kept_bounds[k], removed[k], estimates[k], s.delta
            );
        }
    }
    let offsets_ok = notes.iter().all(|n| !n.contains("did not reach"));
    let butt = !closed && opts.cap == Cap::Butt;
    let a = Claim {
        proven: a_ok && offsets_ok && a_bound <= tol && !butt,
        bound: if a_ok { a_bound } else { f64::INFINITY },
        note: if butt {
            "not claimed for butt caps (the region is not x ⊕ pen)".into()
        } else if a_ok {
            format!("every kept sub-piece is within {a_bound:.3e} of exact offset points proven on ∂S, or of a point proven outside S and a point of S")
        } else {
            "some sub-pieces could not be classified".into()
        },
    };
    let b = Claim {
        proven: b_ok && offsets_ok && b_bound <= tol && !butt,
        bound: if b_ok { b_bound } else { f64::INFINITY },
        note: if butt {
            "not claimed for butt caps (the region is not x ⊕ pen)".into()
        } else if b_ok {
            format!(
                "every sub-piece of the raw pieces is kept or proven interior; bound {b_bound:.3e}"
            )
        } else {
            "some sub-pieces could not be classified".into()
        },
    };
    let c = Claim {
        proven: c_ok,
        bound: 0.0,
        note: c_note,
    };

    Ok(Stroke {
        contours,
        crossings,
        raw_pieces: raws.len(),
        raw_complete,
        complete: c_complete,
        a,
        b,
        c,
        classified,
        tol,
        closed_curve: closed,
        notes,
        pen: opts.ellipse.clone(),
        caps,
    })
}

/// Pieces to drop from the output, each with its certified *reach*: an upper
/// bound of the distance from any of its points to the pieces that stay.
///
/// - *Pinched loops*: a chain of pieces `p_i, …, p_j` (following exact
///   end = start) that starts and ends at one exact point `X` where another
///   live piece starts, every piece within its cap of `X` or of the live
///   pieces at `X` outside the chain ([`reach_hi`]).
/// - *Spurs*: a piece with a dangling end (no live piece continues it), within
///   its cap of its other end `Y` or of the live pieces at `Y`.
///
/// `caps[k]` is how far piece `k` may be from the output for claim (b) to
/// stay within tol. Every dropped group is re-checked against the final live
/// pieces (a piece it was measured against may have been dropped after it)
/// and restored if the check fails; restoring only adds pieces, so this
/// repeats until nothing changes. Finally every dropped group's point must
/// still end a live piece.
fn pinched_loops(pieces: &[&Piece], caps: &[f64]) -> Vec<(usize, f64)> {
    let n = pieces.len();
    let mut dropped = vec![false; n];
    // the live pieces at `x` outside `chain`
    let live_at = |x: &V2<Rational>, chain: &[usize], dropped: &[bool]| -> Vec<&Piece> {
        (0..n)
            .filter(|&j| {
                !chain.contains(&j)
                    && !dropped[j]
                    && (pieces[j].start() == x || pieces[j].end() == x)
            })
            .map(|j| pieces[j])
            .collect()
    };
    let mut groups: Vec<(V2<Rational>, Vec<usize>)> = Vec::new();
    for s in 0..n {
        if dropped[s] {
            continue;
        }
        let x = pieces[s].start().clone();
        // X must be a pinch: at least two live pieces start there
        let starts = (0..n)
            .filter(|&k| !dropped[k] && pieces[k].start() == &x)
            .count();
        if starts < 2 {
            continue;
        }
        // follow the chain from s while it stays near X and the pieces there
        let mut chain = vec![s];
        let mut cur = s;
        let closed = loop {
            let refs = live_at(&x, &chain, &dropped);
            if reach_hi(pieces[cur], &refs, &x, caps[cur]).is_none() {
                break false;
            }
            let end = pieces[cur].end();
            if end == &x {
                break true;
            }
            let next =
                (0..n).find(|&k| !dropped[k] && !chain.contains(&k) && pieces[k].start() == end);
            match next {
                Some(k) if chain.len() < 64 => {
                    chain.push(k);
                    cur = k;
                }
                _ => break false,
            }
        };
        if closed {
            for &k in &chain {
                dropped[k] = true;
            }
            groups.push((x, chain));
        }
    }
    // spurs
    loop {
        let mut changed = false;
        for k in 0..n {
            if dropped[k] {
                continue;
            }
            let (a, b) = (pieces[k].start(), pieces[k].end());
            let live_end = |x: &V2<Rational>, starts: bool| {
                (0..n).any(|j| {
                    j != k
                        && !dropped[j]
                        && if starts {
                            pieces[j].start() == x
                        } else {
                            pieces[j].end() == x
                        }
                })
            };
            let touches = |x: &V2<Rational>| {
                (0..n).any(|j| {
                    j != k && !dropped[j] && (pieces[j].start() == x || pieces[j].end() == x)
                })
            };
            let y = if !live_end(b, true) && touches(a) {
                a.clone()
            } else if !live_end(a, false) && touches(b) {
                b.clone()
            } else {
                continue;
            };
            if reach_hi(pieces[k], &live_at(&y, &[k], &dropped), &y, caps[k]).is_some() {
                dropped[k] = true;
                groups.push((y, vec![k]));
                changed = true;
            }
        }
        if !changed {
            break;
        }
    }
    // re-check against the final live pieces; a group's point must still end
    // a live piece (the argument of (b) needs X in the output)
    let mut reach = vec![None; n];
    loop {
        let mut changed = false;
        for (x, chain) in &groups {
            if chain.iter().all(|&k| !dropped[k]) {
                continue;
            }
            let refs = live_at(x, chain, &dropped);
            let reaches: Option<Vec<f64>> = if refs.is_empty() {
                None
            } else {
                chain
                    .iter()
                    .map(|&k| reach_hi(pieces[k], &refs, x, caps[k]))
                    .collect()
            };
            match reaches {
                Some(r) => {
                    for (&k, r) in chain.iter().zip(r) {
                        reach[k] = Some(r);
                    }
                }
                None => {
                    for &k in chain {
                        dropped[k] = false;
                        reach[k] = None;
                    }
                    changed = true;
                }
            }
        }
        if !changed {
            break;
        }
    }
    (0..n)
        .filter(|&k| dropped[k])
        .filter_map(|k| reach[k].map(|r| (k, r)))
        .collect()
}

/// A certified upper bound of `sup_{p ∈ piece} dist(p, refs ∪ {y})` if it is
/// at most `cap`: the piece is halved (interval Bézier halves, exact arc
/// midpoints) until each part's hull lies within `cap` of one point proven on
/// a reference piece (a point of the exact piece enclosed in intervals, the
/// float nearest point only choosing where) or of `y`.
fn reach_hi(piece: &Piece, refs: &[&Piece], y: &V2<Rational>, cap: f64) -> Option<f64> {
    if cap.is_nan() || cap <= 0.0 {
        return None;
    }
    let yi = iv_point(y);
    let mut todo: Vec<(Part, u32)> = Part::initial(piece)?.into_iter().map(|p| (p, 0)).collect();
    let mut worst: f64 = 0.0;
    let mut budget = 256usize;
    while let Some((part, depth)) = todo.pop() {
        let h = part.hull()?;
        let far = |q: &V2<Interval>| h.iter().map(|p| box_dist_hi(p, q)).fold(0.0, f64::max);
        let c = {
            let k = h.len() as f64;
            let (sx, sy) = h
                .iter()
                .fold((0.0, 0.0), |(x, y), p| (x + p.x.mid(), y + p.y.mid()));
            (sx / k, sy / k)
        };
        let mut best = far(&yi);
        for r in refs {
            if let Some(q) = nearest_on(r, c) {
                best = best.min(far(&q));
            }
        }
        if best <= cap {
            worst = worst.max(best);
            continue;
        }
        if depth >= 14 || budget == 0 {
            return None;
        }
        budget -= 1;
        let (l, r) = part.halves()?;
        todo.push((l, depth + 1));
        todo.push((r, depth + 1));
    }
    Some(worst)
}

/// A point of the exact piece (enclosed in intervals) near the float point
/// `c`: the float nearest point chooses a dyadic parameter (Bézier) or one of
/// the exact points of the arc's halvings.
fn nearest_on(piece: &Piece, c: (f64, f64)) -> Option<V2<Interval>> {
    let d2 = |x: f64, y: f64| (x - c.0) * (x - c.0) + (y - c.1) * (y - c.1);
    match piece {
        Piece::Bezier(b) => {
            let bf = b.map(|x| x.approx());
            let f = |t: f64| {
                let v = bf.eval_fast(t);
                d2(v.x, v.y)
            };
            let n = 64;
            let (mut bt, mut bd) = (0.0, f64::INFINITY);
            for k in 0..=n {
                let t = k as f64 / n as f64;
                let d = f(t);
                if d < bd {
                    (bt, bd) = (t, d);
                }
            }
            let (mut lo, mut hi) = (
                (bt - 1.0 / n as f64).max(0.0),
                (bt + 1.0 / n as f64).min(1.0),
            );
            for _ in 0..60 {
                let (m1, m2) = (lo + (hi - lo) * 0.382, lo + (hi - lo) * 0.618);
                if f(m1) < f(m2) {
                    hi = m2;
                } else {
                    lo = m1;
                }
            }
            let t = rational_from_f64(0.5 * (lo + hi))?;
            let ti = interval_from_rational(&t);
            let p = b.map(interval_from_rational).eval(&ti);
            (!p.x.is_empty() && !p.y.is_empty()).then_some(p)
        }
        Piece::Arc(a) => {
            let mut pts = vec![a.from.clone(), a.to.clone()];
            let mut todo = vec![(a.clone(), 0)];
            while let Some((arc, depth)) = todo.pop() {
                if depth >= 4 {
                    continue;
                }
                let Some(m) = arc.midpoint() else { continue };
                let (l, r) = arc.split_at(&m);
                pts.push(m);
                todo.push((l, depth + 1));
                todo.push((r, depth + 1));
            }
            pts.iter()
                .min_by(|p, q| {
                    let (pf, qf) = (approx_dir(p), approx_dir(q));
                    d2(pf.0, pf.1).total_cmp(&d2(qf.0, qf.1))
                })
                .map(iv_point)
        }
    }
}

/// Chains pieces into contours by exact shared end points.
fn chain(pieces: Vec<Piece>) -> Vec<Contour> {
    let n = pieces.len();
    let mut used = vec![false; n];
    let mut out = Vec::new();
    for s in 0..n {
        if used[s] {
            continue;
        }
        used[s] = true;
        let mut cur = vec![pieces[s].clone()];
        loop {
            let end = cur.last().expect("nonempty").end().clone();
            if &end == cur[0].start() {
                break;
            }
            let next = (0..n).find(|&k| !used[k] && pieces[k].start() == &end);
            match next {
                Some(k) => {
                    used[k] = true;
                    cur.push(pieces[k].clone());
                }
                None => break,
            }
        }
        let closed = cur.last().expect("nonempty").end() == cur[0].start();
        let area = cur
            .iter()
            .map(|p| p.area_term())
            .try_fold(Interval::try_from((0.0, 0.0)).expect("zero"), |acc, a| {
                a.map(|a| acc + a)
            });
        let (orientation, area) = match (closed, area) {
            (true, Some(a)) if a.inf() > 0.0 => (Orientation::CounterClockwise, (a.inf(), a.sup())),
            (true, Some(a)) if a.sup() < 0.0 => (Orientation::Clockwise, (a.inf(), a.sup())),
            (_, Some(a)) => (Orientation::Undecided, (a.inf(), a.sup())),
            _ => (Orientation::Undecided, (f64::NEG_INFINITY, f64::INFINITY)),
        };
        out.push(Contour {
            pieces: cur,
            closed,
            orientation,
            area,
        });
    }
    out
}

/// Claim (c): closed, oriented, and no contact besides consecutive joints.
/// Returns (proven, complete, note).
fn check_simple(contours: &[Contour], iopts: &IntersectOptions) -> (bool, bool, String) {
    // flat list with (contour, position)
    let mut flat: Vec<(&Piece, usize, usize)> = Vec::new();
    for (ci, c) in contours.iter().enumerate() {
        for (k, p) in c.pieces.iter().enumerate() {
            flat.push((p, ci, k));
        }
    }
    let consecutive = |i: usize, j: usize| -> bool {
        let (a, b) = (&flat[i], &flat[j]);
        if a.1 != b.1 {
            return false;
        }
        let n = contours[a.1].pieces.len();
        let closed = contours[a.1].closed;
        let (x, y) = (a.2, b.2);
        (x + 1 == y || y + 1 == x) || (closed && ((x + 1) % n == y || (y + 1) % n == x))
    };
    let mut problems = Vec::new();
    if let Some(c) = contours.iter().position(|c| !c.closed) {
        problems.push(format!("contour {c} is not closed"));
    }
    if let Some(c) = contours
        .iter()
        .position(|c| c.orientation == Orientation::Undecided)
    {
        problems.push(format!("contour {c}: orientation undecided"));
    }
    let bez: Vec<usize> = (0..flat.len())
        .filter(|&i| matches!(flat[i].0, Piece::Bezier(_)))
        .collect();
    let arcs: Vec<usize> = (0..flat.len())
        .filter(|&i| matches!(flat[i].0, Piece::Arc(_)))
        .collect();
    let bz: Vec<Bezier<Rational>> = bez
        .iter()
        .map(|&i| match flat[i].0 {
            Piece::Bezier(b) => b.clone(),
            Piece::Arc(_) => unreachable!(),
        })
        .collect();
    let r = intersections(&bz, iopts);
    let mut complete = r.complete;
    if !r.crossings.is_empty() {
        problems.push(format!("{} crossings left", r.crossings.len()));
    }
    if !r.complete {
        problems.push(format!("{} undecided regions", r.undecided.len()));
    }
    for j in &r.joints {
        let (a, b) = (bez[j.pieces.0], bez[j.pieces.1]);
        if !consecutive(a, b) {
            problems.push(format!("pieces {a} and {b} touch but are not consecutive"));
        }
    }
    for &ai in &arcs {
        let Piece::Arc(arc) = flat[ai].0 else {
            continue;
        };
        for &bi in &bez {
            let Piece::Bezier(b) = flat[bi].0 else {
                continue;
            };
            let m = bezier_arc(b, arc);
            if !m.undecided.is_empty() {
                complete = false;
                problems.push(format!("pieces {bi} and {ai}: undecided"));
            }
            for h in &m.hits {
                let joint = h.t.0 == h.t.1 && {
                    let pt = if h.t.0.is_zero() {
                        Some(&b.points()[0])
                    } else if h.t.0 == <Rational as One>::one() {
                        b.points().last()
                    } else {
                        None
                    };
                    pt.is_some_and(|p| *p == arc.from || *p == arc.to) && consecutive(ai, bi)
                };
                if !joint {
                    problems.push(format!("pieces {bi} and {ai} meet"));
                }
            }
        }
    }
    for (k, &ai) in arcs.iter().enumerate() {
        for &aj in &arcs[k + 1..] {
            let (Piece::Arc(a), Piece::Arc(b)) = (flat[ai].0, flat[aj].0) else {
                continue;
            };
            let shared = if consecutive(ai, aj) {
                [&a.from, &a.to]
                    .into_iter()
                    .find(|p| **p == b.from || **p == b.to)
            } else {
                None
            };
            match arcs_meet(a, b, shared) {
                Some(false) => {}
                Some(true) => problems.push(format!("arcs {ai} and {aj} meet")),
                None => {
                    complete = false;
                    problems.push(format!("arcs {ai} and {aj}: undecided"));
                }
            }
        }
    }
    let ok = problems.is_empty();
    let note = if ok {
        format!(
            "{} closed contours, {} pieces: no crossing, only joints of consecutive pieces (certified), orientation from the area sign",
            contours.len(),
            flat.len()
        )
    } else {
        problems.truncate(10);
        problems.join("; ")
    };
    (ok, complete, note)
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Dense float distance from the point to the piece (a lower bound of
    /// nothing, an estimate: the certified reach must not be below it).
    fn sampled_dist(p: (f64, f64), q: &Piece) -> f64 {
        q.sample(4000)
            .iter()
            .map(|v| (v.0 - p.0).hypot(v.1 - p.1))
            .fold(f64::INFINITY, f64::min)
    }

    #[test]
    fn the_certified_reach_is_never_below_the_sampled_distance() {
        let q = |n: i64, d: i64| Rational::new(n.into(), d.into());
        let mut rng = crate::test_rng::TestRng::new(0x9e37_79b9_7f4a_7c15);
        let (mut decided, mut refused) = (0, 0);
        for _ in 0..60 {
            // a short cubic near the start of a reference cubic (a spur at Y)
            let y = V2::new(q(rng.int(1000), 100), q(rng.int(1000), 100));
            let mut r = vec![y.clone()];
            let mut c = vec![y.clone()];
            for _ in 0..3 {
                r.push(V2::new(
                    &r[r.len() - 1].x + q(rng.int(1000).abs() + 100, 50),
                    &r[r.len() - 1].y + q(rng.int(1000), 200),
                ));
                c.push(V2::new(
                    &c[c.len() - 1].x + q(rng.int(1000).abs(), 2000),
                    &c[c.len() - 1].y + q(rng.int(1000), 2000),
                ));
            }
            let spur = Piece::Bezier(Bezier::new(c));
            let refp = Piece::Bezier(Bezier::new(r));
            let sampled = spur
                .sample(400)
                .iter()
                .map(|&p| {
                    sampled_dist(p, &refp).min((p.0 - y.x.approx()).hypot(p.1 - y.y.approx()))
                })
                .fold(0.0, f64::max);
            for cap in [0.05, 0.2, 1.0] {
                match reach_hi(&spur, &[&refp], &y, cap) {
                    Some(reach) => {
                        decided += 1;
                        assert!(reach <= cap, "{reach} above the cap {cap}");
                        assert!(
                            reach >= sampled - 1e-9,
                            "certified reach {reach} below the sampled {sampled}"
                        );
                    }
                    None => {
                        refused += 1;
                        // refused only where the cap is not far above the truth
                        assert!(sampled > cap / 4.0, "refused: sampled {sampled}, cap {cap}");
                    }
                }
            }
        }
        assert!(
            decided > 20 && refused > 5,
            "{decided} decided, {refused} refused"
        );
    }

    #[test]
    fn a_spur_near_the_output_is_dropped_and_a_far_one_is_kept() {
        let q = |n: i64| Rational::from_integer(n.into());
        let p = |x: i64, y: i64| V2::new(q(x), q(y));
        let seg = |a: V2<Rational>, b: V2<Rational>| Piece::Bezier(Bezier::new(vec![a, b]));
        // a closed square with a short spur at (10, 0) running along the edge
        // back toward (9, 0) at a height of 1/100, and a long one sticking out
        let near = Piece::Bezier(Bezier::new(vec![
            p(10, 0),
            V2::new(
                Rational::new(29.into(), 3.into()),
                Rational::new(1.into(), 100.into()),
            ),
            V2::new(
                Rational::new(28.into(), 3.into()),
                Rational::new(1.into(), 100.into()),
            ),
            V2::new(q(9), Rational::new(1.into(), 100.into())),
        ]));
        let far = seg(p(10, 10), p(15, 15));
        let pieces = [
            seg(p(0, 0), p(10, 0)),
            near,
            seg(p(10, 0), p(10, 10)),
            far,
            seg(p(10, 10), p(0, 10)),
            seg(p(0, 10), p(0, 0)),
        ];
        let refs: Vec<&Piece> = pieces.iter().collect();
        let caps = vec![0.5; pieces.len()];
        let dropped = pinched_loops(&refs, &caps);
        assert_eq!(dropped.len(), 1, "{dropped:?}");
        let (k, reach) = dropped[0];
        assert_eq!(k, 1);
        // the spur's far end is 1/100 above the edge
        assert!((0.01..0.5).contains(&reach), "{reach}");
    }

    #[test]
    fn interval_areas_enclose_the_exact_ones() {
        let q = |n: i64, d: i64| Rational::new(n.into(), d.into());
        let mut rng = crate::test_rng::TestRng::new(0x2545_f491_4f6c_dd1d);
        let mut next = || rng.int(1000);
        for deg in 1..=6 {
            for _ in 0..20 {
                let b = Bezier::new(
                    (0..=deg)
                        .map(|_| V2::new(q(next(), 7), q(next(), 3)))
                        .collect(),
                );
                let exact = interval_from_rational(&bezier_area(&b));
                let iv = bezier_area_iv(&b).expect("finite");
                assert!(
                    iv.inf() <= exact.inf() && exact.sup() <= iv.sup(),
                    "{exact:?} not in {iv:?}"
                );
                assert!(iv.wid() <= 1e-9 * (1.0 + exact.mag()), "{iv:?}");
            }
        }
    }
}
