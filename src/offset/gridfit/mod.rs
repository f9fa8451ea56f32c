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

mod chain;
mod fitting;
mod joints;
mod outline;
mod prove;

use super::driver::Kernel;
use super::fit::{self, Reach};
use super::options::{bad, check_options};
use super::results::{approximant_of, sub_exact};
use super::{OffsetError, OffsetOptions, Output, ProofPath};
use crate::certify::Certificate;
use crate::curve::Bezier;
use crate::scalar::{Rational, Scalar};
use crate::shape::{ArcDesc, ShapeDesc};
use crate::Tolerance;
pub use chain::{chain_on_grid, ChainGridOptions};
use outline::Ctx;
use prove::{Built, Stats};

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
    pub proof: Option<ProofPath>,
}

/// The result of [`offset_on_grid`].
#[derive(Clone, Debug, PartialEq)]
pub struct GridOffset {
    /// The grid (exact, dyadic).
    pub grid: Rational,
    /// The tolerance, from the options (the certificate claims it exactly).
    pub tol: Tolerance,
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
        approximant_of(self.segments.iter().map(|s| &s.bezier))
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
    ShapeDesc::union(members)
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
/// use lncert::offset::{offset_on_grid, OffsetOptions, Output};
/// use lncert::shape::parse_curve;
/// let q = |s: &str| lncert::parse_rational(s).unwrap();
/// // a closed curve in "font units"; a grid of 1 and a tolerance of 0.2 units
/// let x = parse_curve("M 0 0 C 300 -100 500 200 400 400 C 300 600 -100 300 0 0").unwrap();
/// let mut opts = OffsetOptions::new(q("40"), "0.2".parse().unwrap());
/// opts.output = Output::Cubic;
/// opts.grid = Some(q("1"));
/// let r = offset_on_grid(&x, &opts).unwrap();
/// assert!(r.reached() && r.certified_hi <= r.tol.value());
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
    base_opts.tol = Tolerance::from_f64(opts.tol.value() * FIT_SHARE)?;
    let base = super::offset(curve, &base_opts)?;
    let d = opts.distance.clone();
    let kernel = Kernel::Offset {
        d: d.clone(),
        df: d.approx(),
    };
    let ctx = Ctx {
        curve,
        xf: curve.iter().map(|x| x.map(|v| v.approx())).collect(),
        kernel: Some(&kernel),
        corner_joints: false,
        hairpin_cos: 1.0,
        reach: Reach::of(&kernel),
        gf: grid.approx(),
        grid: grid.clone(),
        tol: opts.tol.clone(),
        max_boxes: opts.max_boxes,
        max_splits: opts.max_segments,
        quadratic: opts.output == Output::Quadratic,
    };
    let (contours, corner_arcs) = outline::contours(curve, &base, &d);
    let stats = Stats::default();
    let mut max_joint: f64 = 0.0;
    let mut built_contours: Vec<Vec<Built>> = Vec::new();
    for c in &contours {
        if c.parts.is_empty() {
            built_contours.push(Vec::new());
            continue;
        }
        let joints = ctx.joints(c)?;
        for j in &joints {
            if let Some(p) = ctx.point(&c.parts[j.pos.part], j.pos.u) {
                max_joint = max_joint.max((p - j.g).length());
            }
        }
        built_contours.push(ctx.build(c, &joints, &stats));
    }
    let (segments, bounds, contour_ranges) = prove::number(built_contours, &contours);
    let unreached: Vec<usize> = segments
        .iter()
        .enumerate()
        .filter(|(_, s)| s.proof.is_none())
        .map(|(i, _)| i)
        .collect();
    let certified_hi = segments.iter().map(|s| s.error.1).fold(0.0, f64::max);
    let mut out = GridOffset {
        grid,
        tol: opts.tol.clone(),
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
        out.certificate = prove::certificate(curve, &d, &out, &bounds)?;
    }
    Ok(out)
}
