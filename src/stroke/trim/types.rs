//! The public options and results of a stroke ([`super::StrokeOptions`],
//! [`super::Stroke`], its claims and contours) and the output [`super::Piece`].

use crate::curve::{Bezier, V2};
use crate::offset::conv::Pen;
use crate::offset::OffsetMethod;
use crate::scalar::{interval_from_rational, Interval, Rational, Scalar};
use crate::shape::{ArcDesc, ShapeDesc};
use crate::stroke::circle::Arc;
use crate::stroke::ellipse::Form;
use crate::Tolerance;
use num_traits::One;

/// How an open curve's ends are closed.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Cap {
    /// A half circle of radius `r` about the end point (exact arc).
    Round,
    /// The straight segment between the two offset ends. The region is then
    /// not `x ⊕ disk`: claims (a) and (b) are not made for butt caps.
    Butt,
}

/// Settings of [`stroke`](super::stroke).
#[derive(Clone, Debug)]
pub struct StrokeOptions {
    /// Pen radius `r > 0`, exact.
    pub radius: Rational,
    /// The tolerance to prove for claims (a) and (b) (their bounds are
    /// compared with [`Tolerance::value`], the largest float ≤ it).
    pub tol: Tolerance,
    /// End caps of an open curve (default round).
    pub cap: Cap,
    /// Solver boxes per pair for the intersection searches (default 20 000).
    pub max_boxes_per_pair: usize,
    /// The offset segments' form (default native: degree `n + 3`; `Cubic` /
    /// `Quadratic` for SVG-expressible output, see [`crate::offset::Output`]).
    pub output: crate::offset::Output,
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

impl PenShape {
    /// The pen as the set it is, `M · disk(1)` given by `Q = M Mᵀ` as
    /// `[q₁₁, q₁₂, q₂₂]` (a disk of radius `r`: `r² I`): two pens are the
    /// same set exactly when their `Q` are equal.
    ///
    /// # Examples
    /// ```
    /// use lncert::offset::{Angle, Pen};
    /// use lncert::stroke::PenShape;
    /// let q = |s: &str| lncert::parse_rational(s).unwrap();
    /// let round = Pen::ellipse(&q("2"), &q("2"), &Angle::parse("30deg").unwrap()).unwrap();
    /// assert_eq!(PenShape::Ellipse(round).q(), PenShape::Circle(q("2")).q());
    /// ```
    pub fn q(&self) -> [Rational; 3] {
        match self {
            PenShape::Circle(r) => {
                let r2 = r * r;
                [r2.clone(), Rational::from_integer(0.into()), r2]
            }
            PenShape::Ellipse(pen) => pen.q.clone(),
        }
    }
}

impl StrokeOptions {
    /// Round caps and the default budgets.
    pub fn new(radius: Rational, tol: Tolerance) -> Self {
        StrokeOptions {
            radius,
            tol,
            cap: Cap::Round,
            max_boxes_per_pair: 20_000,
            output: crate::offset::Output::Native,
            method: OffsetMethod::G2,
            ellipse: None,
        }
    }

    /// Round caps and the default budgets for a circular or elliptical pen.
    ///
    /// # Examples
    /// ```
    /// use lncert::offset::{Angle, Pen};
    /// use lncert::stroke::{PenShape, StrokeOptions};
    /// let q = |s: &str| lncert::parse_rational(s).unwrap();
    /// let pen = Pen::ellipse(&q("0.7"), &q("0.3"), &Angle::parse("pi/6").unwrap()).unwrap();
    /// let tol: lncert::Tolerance = "0.1".parse().unwrap();
    /// let o = StrokeOptions::with_pen(PenShape::Ellipse(pen), tol.clone());
    /// assert!(matches!(o.pen(), PenShape::Ellipse(_)));
    /// let c = StrokeOptions::with_pen(PenShape::Circle(q("1")), tol);
    /// assert_eq!(c.pen(), PenShape::Circle(q("1")));
    /// ```
    pub fn with_pen(pen: PenShape, tol: Tolerance) -> Self {
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

    pub(super) fn form(&self) -> Result<Form, StrokeError> {
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

/// Why a stroke could not be computed: the offending input (`radius`, `tol`,
/// `curve`, …) and why — lncert's one input error, [`crate::Error`].
pub type StrokeError = crate::Error;

pub(super) fn bad(field: &str, reason: impl Into<String>) -> StrokeError {
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
    pub(super) fn reversed(&self) -> Piece {
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
pub(super) fn bezier_area_iv(b: &Bezier<Rational>) -> Option<Interval> {
    let n = b.degree();
    if n == 0 {
        return Interval::try_from((0.0, 0.0)).ok();
    }
    let x = b.map(interval_from_rational);
    let h = x.hodograph();
    let (xs, ys): (Vec<Interval>, Vec<Interval>) = x.points().iter().map(|p| (p.x, p.y)).unzip();
    let (hx, hy): (Vec<Interval>, Vec<Interval>) = h.points().iter().map(|p| (p.x, p.y)).unzip();
    let a = crate::stroke::onside::bprod(&xs, &hy);
    let c = crate::stroke::onside::bprod(&ys, &hx);
    let mut s = Interval::try_from((0.0, 0.0)).ok()?;
    for (u, v) in a.iter().zip(&c) {
        s += *u - *v;
    }
    let m = Interval::try_from(((2 * n) as f64, (2 * n) as f64)).ok()?;
    let two = Interval::try_from((2.0, 2.0)).ok()?;
    let r = s / m / two;
    (!r.is_empty() && r.inf().is_finite() && r.sup().is_finite()).then_some(r)
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

/// The result of [`stroke`](super::stroke).
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
    /// The tolerance asked for, from the options.
    pub tol: Tolerance,
    /// The curve is closed.
    pub closed_curve: bool,
    /// What was left undecided on the way (raw regions, sub-pieces, offsets);
    /// informational: the claims are decided on the output itself.
    pub notes: Vec<String>,
    /// The elliptical pen actually used (exact), when there is one.
    pub pen: Option<Pen>,
    /// The round caps of an elliptical pen (empty for a circle or butt caps).
    pub caps: Vec<CapReport>,
    /// The stroke certificate that proves claims (a) and (b), when they were
    /// proven by one ([`crate::stroke::stroke_path`] of a path with exact
    /// arcs: against the exact arcs); `None` otherwise.
    pub certificate: Option<Box<serde_json::Value>>,
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

    /// The output as one exact shape for the Hausdorff engine
    /// ([`crate::certify::hausdorff`]): the union of its Bézier pieces (one
    /// curve member) and its arcs (each a member; a clockwise arc is the same
    /// point set travelled counter-clockwise from its end).
    ///
    /// # Examples
    /// ```
    /// use lncert::stroke::{stroke, StrokeOptions};
    /// use lncert::{parse_curve, parse_rational};
    /// # fn main() -> Result<(), lncert::Error> {
    /// let s = stroke(&parse_curve("M 0 0 L 4 0")?, &StrokeOptions::new(parse_rational("1")?, "1e-2".parse()?))?;
    /// let shape = s.outline_shape()?;
    /// assert_eq!(shape.piece_count(), s.pieces());
    /// # Ok(())
    /// # }
    /// ```
    pub fn outline_shape(&self) -> Result<ShapeDesc, crate::shape::ShapeError> {
        let mut beziers = Vec::new();
        let mut members = Vec::new();
        for p in self.contours.iter().flat_map(|c| c.pieces.iter()) {
            match p {
                Piece::Bezier(b) => beziers.push(b.clone()),
                Piece::Arc(a) => {
                    let (u, v) = (a.from.sub(&a.center), a.to.sub(&a.center));
                    let (from, to) = if a.clockwise { (v, u) } else { (u, v) };
                    members.push(ShapeDesc::arc(ArcDesc {
                        center: a.center.clone(),
                        radius: a.radius.clone(),
                        from,
                        to,
                    })?);
                }
            }
        }
        if !beziers.is_empty() {
            members.insert(0, ShapeDesc::curve(beziers)?);
        }
        ShapeDesc::union(members)
    }
}
