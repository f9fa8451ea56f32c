//! Offset approximation with a proven tolerance.
//!
//! [`offset`] approximates the offset `x + d N` (`N` the unit **left** normal,
//! `d > 0` to the left) of a piecewise polynomial curve by a polynomial spline
//! and proves the result: every output segment carries a certified Hausdorff
//! bound against the exact offset of its input span ([`crate::certify`]), and
//! the divide-and-conquer loop only accepts a segment whose certified bound is
//! `≤ tol`. Since `d_H(∪Aᵢ, ∪Bᵢ) ≤ maxᵢ d_H(Aᵢ, Bᵢ)`, the spline is within `tol`
//! of the whole offset; [`union_certificate`] writes that as a certificate
//! (the per-segment maps and covers, no further search) that `lncert verify` re-checks,
//! and [`global_bounds`] (opt-in) encloses the global distance from both sides.
//!
//! Two constructions, both from the seeds:
//!
//! | [`OffsetMethod`] | seed | segment | continuity |
//! |---|---|---|---|
//! | `G2` | 004 | degree `n + 3` from the approximated normal field ([`g2`]) | G², C¹ at the joints |
//! | `LnPair` | 000 §6 | a cubic `pa + ca` from a pair of LN cubics ([`lnpair`]) | G¹ |
//!
//! | [`Output`] | segment | continuity |
//! |---|---|---|
//! | `Native` (default) | the construction of the method above | as above |
//! | `Cubic` | a cubic fitted to the exact offset of the span ([`fit`]) | G¹, shared end points |
//! | `Quadratic` | the tangent-intersection quadratic ([`fit`]) | G¹, shared end points |
//!
//! With [`OffsetOptions::grid`] every control point is rounded to a dyadic
//! grid and the rounded segment is what is proven.
//!
//! The constructions run in `f64` and are heuristics; only the certification
//! decides. Preprocessing ([`prep`]) splits the input at inflections and
//! where its Gauss map turns by 0.9π or more, reports the cusps of the exact offset (where
//! the radius of curvature equals `d`; the approximation continues through
//! them) and the G⁰ corners (a join arc, or an overlap to trim).
//!
//! # Examples
//! ```
//! use lncert::approx::{offset, OffsetMethod, OffsetOptions};
//! use lncert::shape::parse_curve;
//! use lncert::scalar::parse_rational;
//! let c = parse_curve("M 0 0 C 1 1 2 1 3 0").unwrap();
//! let opts = OffsetOptions::new(parse_rational("0.25").unwrap(), 1e-3);
//! let r = offset(&c, &opts).unwrap();
//! assert!(r.reached());
//! assert!(r.certified_hi <= 1e-3);
//! assert_eq!(r.degree(), 6);
//! assert_eq!(r.control_points(), 6 * r.segments.len() + 1);
//! ```

pub mod arc;
pub mod conv;
pub mod fit;
pub mod g2;
pub mod gridfit;
pub mod lnpair;
pub mod prep;

use crate::certify::{hausdorff, Certificate, Config, CoverBox, HausdorffBounds, MapCover};
use crate::curve::{Bezier, V2};
use crate::scalar::{interval_from_rational, rational_from_f64, Interval, Rational, Scalar};
use crate::shape::ShapeDesc;
use num_traits::Zero;
use prep::{Junction, OffsetCusp};
use rayon::prelude::*;

pub use fit::Output;

/// Which construction builds the segments.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Default)]
pub enum OffsetMethod {
    /// Seed 004: G²/C¹ normal-field approximant of degree `n + 3`.
    #[default]
    G2,
    /// Seed 000 §6: cubic LN pair `pa + ca`.
    LnPair,
}

impl OffsetMethod {
    /// The CLI name: `g2` or `ln-pair`.
    pub fn name(self) -> &'static str {
        match self {
            OffsetMethod::G2 => "g2",
            OffsetMethod::LnPair => "ln-pair",
        }
    }
    /// Parses a CLI name.
    pub fn parse(s: &str) -> Option<Self> {
        match s {
            "g2" => Some(OffsetMethod::G2),
            "ln-pair" | "lnpair" => Some(OffsetMethod::LnPair),
            _ => None,
        }
    }
}

/// Settings of [`offset`].
#[derive(Clone, Debug, PartialEq)]
pub struct OffsetOptions {
    /// Signed offset distance (`> 0` to the left), exact.
    pub distance: Rational,
    /// The tolerance to prove: `d_H(offset, approximant) ≤ tol`.
    pub tol: f64,
    /// Which construction builds the segments (default [`OffsetMethod::G2`]).
    pub method: OffsetMethod,
    /// Subdivision depth limit per input piece (default 24: segments of
    /// parameter length ≥ 2⁻²⁴).
    pub max_depth: u32,
    /// Most output segments (default 20 000): no span is split once the split
    /// would exceed it, so a result has at most `max(max_segments, initial spans)`
    /// segments (the initial spans: one per input piece, more at inflections
    /// and turns of 0.9π).
    pub max_segments: usize,
    /// Box budget of each segment's certification (default 50 000).
    pub max_boxes: usize,
    /// Also evaluate seed 000's error measure per LN-pair segment (one more
    /// certified bound per segment; default false): for offsets eq. (8)
    /// `d_H(p, pa) + |r| d_H(c, ca)`, for convolutions §5's
    /// `d_H(p, pa) + d_H(q, qa)` (`q` the pen's elliptic arc).
    pub paper_error: bool,
    /// Accept a segment when the paper's measure ([`OffsetSegment::paper_error`],
    /// an upper bound of it) is `≤ tol`, and split it when it is above, as the
    /// paper does, instead of by its certified true error (default false; a
    /// segment without a measure — a straight span — is judged by its true
    /// error). The true error is still certified
    /// and reported, and may exceed `tol`: the result is then *not* proven
    /// within `tol` (`certified_hi > tol`), and no certificate is written.
    pub accept_paper: bool,
    /// Prove each segment (default true). `false` accepts segments on an
    /// **unproven** sampled estimate instead ([`crate::certify::sampled_estimate`],
    /// 32 samples per direction) — the same construction, left unproven, for
    /// comparison; the result says so ([`OffsetResult::proven`]).
    pub certify: bool,
    /// Prove every segment by the two-directional search (default false).
    /// Without it, a segment is first tried by the parametric proof
    /// ([`crate::certify::Parametric`]: one cover of the segment's parameter for
    /// both directions, several times cheaper), with the search as fallback;
    /// [`SegmentProof::path`] says which proved it. Either way the proofs are
    /// kept for [`union_certificate`].
    pub search_only: bool,
    /// Where an LN-pair span that missed the tolerance is split: seed 000
    /// §5's rule (a), (b) or (c) ([`lnpair::Subdivision`]; default (a), the
    /// mid-angle). G² spans are halved.
    pub subdivision: lnpair::Subdivision,
    /// What the segments are (default [`Output::Native`]: the construction's
    /// own). `Cubic` / `Quadratic` fit cubics / quadratics to the exact curve
    /// of each span ([`fit`]) instead of running the construction of `method`;
    /// `method` still chooses the split rule (G2: halves, LN pair: the
    /// mid-angle) and, for convolutions, whether the sides are cut at their
    /// cusps first (G2). The paper's error measure belongs to native LN pairs
    /// and is not evaluated for fitted segments.
    pub output: Output,
    /// Round every output control point to the nearest multiple of this exact
    /// dyadic grid (default none; see [`fit::check_grid`]) and prove the
    /// rounded segment. The construction is pre-checked (sampled) within
    /// `tol − grid·√2/2` ([`fit::rounding_move`]), the rest of the tolerance
    /// is left to the rounding; the certification decides.
    pub grid: Option<Rational>,
    /// Treat near-smooth corners as smooth (default false; fitted output
    /// without a grid only): where the two offsets' ends at a G⁰ corner are
    /// within `tol` of each other, both neighbouring segments are made to end
    /// at their midpoint and re-proven against their spans, and the join arc
    /// (convex side) is proven to lie within `tol` of them; the corner is then
    /// [`Corner::absorbed`]. A corner where any of these proofs fails keeps its
    /// join arc or overlap.
    pub smooth_kinks: bool,
}

impl OffsetOptions {
    /// Defaults for a distance and a tolerance (method G2).
    pub fn new(distance: Rational, tol: f64) -> Self {
        OffsetOptions {
            distance,
            tol,
            method: OffsetMethod::G2,
            max_depth: 24,
            max_segments: 20_000,
            max_boxes: 50_000,
            paper_error: false,
            accept_paper: false,
            certify: true,
            search_only: false,
            subdivision: lnpair::Subdivision::MidAngle,
            output: Output::Native,
            grid: None,
            smooth_kinks: false,
        }
    }
}

/// Why an offset could not be computed; names the field.
#[derive(Clone, Debug, PartialEq, thiserror::Error)]
pub enum OffsetError {
    /// An input or setting is invalid.
    #[error("invalid `{field}`: {reason}")]
    Input {
        /// Name of the offending input or setting (e.g. `tol`, `curve`).
        field: String,
        /// Why it was rejected.
        reason: String,
    },
}

impl From<crate::shape::ShapeError> for OffsetError {
    fn from(e: crate::shape::ShapeError) -> Self {
        OffsetError::Input {
            field: e.field,
            reason: e.reason,
        }
    }
}

fn bad(field: impl Into<String>, reason: impl Into<String>) -> OffsetError {
    OffsetError::Input {
        field: field.into(),
        reason: reason.into(),
    }
}

/// One certified output segment.
#[derive(Clone, Debug, PartialEq)]
pub struct OffsetSegment {
    /// The input piece it approximates the offset of.
    pub piece: usize,
    /// Its parameter span `[t0, t1]` on that piece (dyadic floats, exact).
    pub t: (f64, f64),
    /// The approximant (its control points are exact dyadic rationals).
    pub bezier: Bezier<f64>,
    /// Certified `lo ≤ d_H(exact offset of the span, bezier) ≤ hi`.
    pub error: (f64, f64),
    /// Seed 000 eq. (8) for LN-pair segments when requested (an upper bound of
    /// the paper's error measure).
    pub paper_error: Option<f64>,
    /// The proof of `error.1 ≤ tol` when the segment was accepted.
    pub proof: Option<SegmentProof>,
    /// With `certify: false` only: the **unproven** sampled estimate the
    /// segment was accepted on (`error` is then `(0, ∞)`: nothing is certified).
    pub estimate: Option<f64>,
}

/// Which proof accepted a segment.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum ProofPath {
    /// The parametric proof: one cover of the segment's parameter, with a
    /// cubic map into the span's exact offset, proves both directions
    /// ([`crate::certify::Parametric`]). Its map is kept ([`SegmentProof::map`]).
    Parametric,
    /// The two-directional branch and bound (`certify::search`).
    Search,
}

impl ProofPath {
    /// `"parametric"` or `"search"`.
    pub fn name(self) -> &'static str {
        match self {
            ProofPath::Parametric => "parametric",
            ProofPath::Search => "search",
        }
    }
}

/// The proof of one accepted segment, which [`union_certificate`] assembles
/// into a certificate of the whole result: for the parametric path its map
/// (from the segment's parameter onto the span's exact offset), for the search
/// its final covers, both directions (piece and target 0: the exact offset of
/// the span, the segment); the other path's fields are empty.
#[derive(Clone, Debug, PartialEq)]
pub struct SegmentProof {
    /// The proof that accepted the segment.
    pub path: ProofPath,
    /// The parametric proof (its map's cover, in order), for that path.
    pub map: Option<crate::certify::Parametric>,
    /// Cover of the span's exact offset, foot maps into the segment.
    pub exact_to_segment: Vec<CoverBox>,
    /// Cover of the segment, foot maps into the span's exact offset.
    pub segment_to_exact: Vec<CoverBox>,
}

/// A junction of two input pieces that needs attention.
#[derive(Clone, Debug, PartialEq)]
pub struct Corner {
    /// The junction is between piece `after` and the next piece (cyclically for a closed curve).
    pub after: usize,
    /// What happens there: a join arc to add or an overlap to trim.
    pub kind: Junction,
    /// The kink is absorbed ([`OffsetOptions::smooth_kinks`]): the two
    /// neighbouring segments meet at one point, the approximant has no join
    /// arc here, and the exact curve's join arc (kept in the exact shape) is
    /// proven to lie within `tol` of those two segments.
    pub absorbed: bool,
}

/// The result of [`offset`].
#[derive(Clone, Debug, PartialEq)]
pub struct OffsetResult {
    /// The construction that built the segments.
    pub method: OffsetMethod,
    /// Signed offset distance (`> 0` to the left), exact, from the options.
    pub distance: Rational,
    /// The tolerance to prove, from the options.
    pub tol: f64,
    /// Segments in input order.
    pub segments: Vec<OffsetSegment>,
    /// Indices of segments whose certified bound stayed above `tol` (depth or
    /// segment limit reached); empty when the tolerance is proven.
    pub unreached: Vec<usize>,
    /// `max` of the segments' certified upper bounds: `d_H ≤ certified_hi`
    /// (`∞` when nothing is certified, `certify: false`).
    pub certified_hi: f64,
    /// Cusps of the exact offset (radius of curvature = distance).
    pub cusps: Vec<OffsetCusp>,
    /// G⁰ corners: join arcs to add, or overlaps to trim.
    pub corners: Vec<Corner>,
    /// Certified Hausdorff searches run (accepted and rejected segments; a span
    /// whose sampled error is above `tol` is split without one).
    pub certifications: usize,
    /// Spans tried in all (each ends as one segment or two halves), with or
    /// without a proof search: `certifications ≤ spans`.
    pub spans: usize,
    /// True when the segments are certified; false with `certify: false`, where
    /// every `error` is the trivial `(0, ∞)` and the segments carry an unproven
    /// `estimate` instead.
    pub proven: bool,
    /// Set by [`convolve`]: the result approximates the convolution `x ∗ e_σ`
    /// with this pen and side instead of an offset (`distance` is then 0,
    /// `cusps` and `corners` are empty and the cusps are in
    /// [`ConvSide::cusps`]).
    pub convolution: Option<ConvSide>,
}

/// The convolution side a result of [`convolve`] approximates.
#[derive(Clone, Debug, PartialEq)]
pub struct ConvSide {
    /// The pen (exact matrix; its [`conv::Pen::margin`] is the proven distance
    /// to the pen as the user gave it).
    pub pen: conv::Pen,
    /// `+1`: the pen point whose outer normal is the left normal of `x`; `−1`:
    /// the right.
    pub side: i8,
    /// The cusps of the exact convolution curve on this side (exact).
    pub cusps: Vec<conv::ConvCusp>,
    /// The tolerance certified for the exact pen: `tol − margin` (the claim
    /// for the pen as given is `tol`).
    pub certified_tol: f64,
}

impl OffsetResult {
    /// True when every segment is certified within `tol` (with `certify: false`:
    /// estimated within it, see [`OffsetResult::proven`]).
    pub fn reached(&self) -> bool {
        self.unreached.is_empty()
    }
    /// With `certify: false`: the largest **unproven** sampled estimate of the
    /// segments (`None` when the result is proven). Not a bound.
    pub fn estimated_hi(&self) -> Option<f64> {
        if self.proven {
            return None;
        }
        Some(
            self.segments
                .iter()
                .map(|s| s.estimate.unwrap_or(f64::INFINITY))
                .fold(0.0, f64::max),
        )
    }
    /// The largest segment degree.
    pub fn degree(&self) -> usize {
        self.segments
            .iter()
            .map(|s| s.bezier.degree())
            .max()
            .unwrap_or(0)
    }
    /// Control points as the papers count them: `degree · segments + 1` per
    /// connected run (consecutive segments sharing an end point).
    pub fn control_points(&self) -> usize {
        let mut n = 0;
        for (i, s) in self.segments.iter().enumerate() {
            n += s.bezier.degree();
            let starts_run = i == 0 || {
                let prev = self.segments[i - 1].bezier.points();
                prev[prev.len() - 1] != s.bezier.points()[0]
            };
            if starts_run {
                n += 1;
            }
        }
        n
    }
    /// The approximant with its join arcs ([`join_arcs`]) as one exact shape:
    /// the curve of the segments, or the union of it and the arcs when there are
    /// join arcs (the shape `b` of [`union_certificate`], so a file written from
    /// it is what `lncert verify --against` compares).
    pub fn outline_shape(&self) -> Result<ShapeDesc, OffsetError> {
        with_arcs(self.approximant_shape()?, join_arcs(self))
    }

    /// The exact curve the result approximates, as one shape over the input's
    /// own pieces: the offset (or convolution) of `curve`, and with join arcs
    /// the union of it and the arcs — the absorbed corners' arcs last (the
    /// shape `a` of [`union_certificate`], up to how the pieces are split,
    /// which `verify --against` accepts).
    pub fn exact_outline_shape(
        &self,
        curve: &[Bezier<Rational>],
    ) -> Result<ShapeDesc, OffsetError> {
        let exact = match &self.convolution {
            None => ShapeDesc::offset(curve.to_vec(), self.distance.clone()),
            Some(c) => ShapeDesc::convolution(curve.to_vec(), c.pen.m.clone(), c.side),
        }?;
        let mut arcs = join_arcs(self);
        arcs.extend(absorbed_arcs(self));
        with_arcs(exact, arcs)
    }
    /// The approximant as an exact shape (every float control point is an exact
    /// dyadic rational).
    pub fn approximant_shape(&self) -> Result<ShapeDesc, OffsetError> {
        let pieces = self
            .segments
            .iter()
            .map(|s| exact_bezier(&s.bezier))
            .collect::<Option<Vec<_>>>()
            .ok_or_else(|| bad("approximant", "a control point is not finite"))?;
        ShapeDesc::curve(pieces).map_err(|e| bad("approximant", e.to_string()))
    }
}

/// `shape`, or with arcs the union of it and the arcs.
fn with_arcs(shape: ShapeDesc, arcs: Vec<crate::shape::ArcDesc>) -> Result<ShapeDesc, OffsetError> {
    if arcs.is_empty() {
        return Ok(shape);
    }
    let mut members = vec![shape];
    for a in arcs {
        members.push(ShapeDesc::arc(a)?);
    }
    Ok(ShapeDesc::union(members)?)
}

/// The exact rational curve of float control points.
pub fn exact_bezier(b: &Bezier<f64>) -> Option<Bezier<Rational>> {
    let pts = b
        .points()
        .iter()
        .map(|p| Some(V2::new(rational_from_f64(p.x)?, rational_from_f64(p.y)?)))
        .collect::<Option<Vec<_>>>()?;
    Some(Bezier::new(pts))
}

/// Smallest tolerance accepted, relative to `1 + coordinate scale`: below it
/// the float control points of the approximant cannot resolve the offset.
pub const MIN_REL_TOL: f64 = 1e-11;

/// What the driver approximates: the offset at a distance, or the
/// convolution with a pen on one side.
#[derive(Clone, Debug)]
enum Kernel {
    Offset {
        d: Rational,
        df: f64,
    },
    Conv {
        // boxed: a pen (exact matrix, rotation, margin) is far larger than an offset's distance
        pen: Box<conv::Pen>,
        qf: [f64; 3],
        sigma: i8,
    },
}

impl Kernel {
    /// The exact curve's piece over the span `t` of `x`, enclosed.
    fn span_piece(
        &self,
        x: &Bezier<Rational>,
        t: (f64, f64),
    ) -> Option<crate::certify::piece::Piece> {
        match self {
            Kernel::Offset { d, .. } => crate::certify::piece::offset_span(x, t, d),
            Kernel::Conv { pen, sigma, .. } => {
                crate::certify::piece::conv_span(x, t, pen.q_interval(), *sigma)
            }
        }
    }
    /// The size of the offset vector (for scale-aware gaps).
    fn reach(&self) -> f64 {
        match self {
            Kernel::Offset { df, .. } => df.abs(),
            Kernel::Conv { qf, .. } => qf[0].max(qf[2]).abs().sqrt(),
        }
    }
}

#[derive(Clone, Debug)]
struct Task {
    piece: usize,
    t: (f64, f64),
    depth: u32,
    /// The parent's certification ran out of budget on a (nearly) exact
    /// approximant; a second such level stops splitting.
    stuck_before: bool,
}

struct Outcome {
    task: Task,
    segment: Option<OffsetSegment>,
    /// Where to split when not accepted.
    split: f64,
    /// Splitting would not help (see `certify_segment`).
    stuck: bool,
}

fn check_options(
    curve: &[Bezier<Rational>],
    opts: &OffsetOptions,
) -> Result<ShapeDesc, OffsetError> {
    if curve.is_empty() {
        return Err(bad("curve", "no pieces"));
    }
    let shape =
        crate::shape::checked_offset(curve.to_vec(), opts.distance.clone(), "curve", "distance")?;
    check_limits(opts, shape.scale(), 0.0)?;
    Ok(shape)
}

/// The checks shared by [`offset`] and [`convolve`]: a finite positive
/// tolerance that, less `margin` (the pen's rotation margin; 0 for offsets),
/// is at least [`MIN_REL_TOL`] × (1 + scale), and sane limits.
fn check_limits(opts: &OffsetOptions, scale: f64, margin: f64) -> Result<(), OffsetError> {
    if !(opts.tol.is_finite() && opts.tol > 0.0) {
        return Err(bad("tol", "must be a finite number > 0"));
    }
    let min = MIN_REL_TOL * (1.0 + scale);
    if opts.tol - margin < min {
        let less = if margin > 0.0 {
            format!(" (less the pen's rotation margin {margin:e})")
        } else {
            String::new()
        };
        return Err(bad(
            "tol",
            format!(
                "{:e}{less} is below {:e} = 1e-11 × (1 + coordinate scale): float control points cannot resolve it",
                opts.tol, min
            ),
        ));
    }
    if opts.max_depth > 40 {
        return Err(bad("max_depth", "must be ≤ 40"));
    }
    if opts.max_segments == 0 || opts.max_boxes == 0 {
        return Err(bad("max_segments", "limits must be ≥ 1"));
    }
    if let Some(g) = &opts.grid {
        fit::check_grid(g, opts.tol - margin, scale)?;
    }
    Ok(())
}

/// Initial spans of one piece: split at inflections (unless `inflections` is
/// false: fitted cubics, which may inflect) and at the `extra` cuts (the cusps
/// of a convolution side, or of a fitted offset); then, for G², halve until the Gauss map
/// of each span turns by less than 0.9π ([`prep::MAX_TURN`]), and for LN
/// pairs split a span turning by `Δ ≥ π` into the `k` pieces of equal turn
/// of seed 000 §5 ([`lnpair::k_piece_split`], `k` the smallest integer with
/// `Δ/k < π`).
fn initial_spans(
    x: &Bezier<Rational>,
    extra: &[f64],
    method: OffsetMethod,
    inflections: bool,
) -> Vec<(f64, f64)> {
    let mut cuts = vec![0.0];
    if inflections {
        cuts.extend(prep::inflections(x));
    }
    cuts.extend(extra.iter().copied().filter(|t| *t > 0.0 && *t < 1.0));
    cuts.push(1.0);
    cuts.sort_by(f64::total_cmp);
    cuts.dedup();
    let mut out = Vec::new();
    for w in cuts.windows(2) {
        if method == OffsetMethod::LnPair {
            let mut ends = vec![w[0]];
            if let Some(sub) = span_f64(x, (w[0], w[1])) {
                let k = lnpair::k_piece_split(&sub, std::f64::consts::PI);
                ends.extend(k.iter().map(|u| w[0] + (w[1] - w[0]) * u));
            }
            ends.push(w[1]);
            out.extend(
                ends.windows(2)
                    .filter(|e| e[0] < e[1])
                    .map(|e| (e[0], e[1])),
            );
            continue;
        }
        let mut stack = vec![(w[0], w[1], 0u32)];
        while let Some((a, b, depth)) = stack.pop() {
            let sub = span_f64(x, (a, b));
            if depth >= 8 || sub.as_ref().is_some_and(prep::gauss_map_short) {
                out.push((a, b));
            } else {
                let m = 0.5 * (a + b);
                stack.push((m, b, depth + 1));
                stack.push((a, m, depth + 1));
            }
        }
    }
    out.sort_by(|p, q| p.0.total_cmp(&q.0));
    out
}

fn sub_exact(x: &Bezier<Rational>, t: (f64, f64)) -> Option<Bezier<Rational>> {
    Some(x.restrict(&rational_from_f64(t.0)?, &rational_from_f64(t.1)?))
}

/// The span `t` of `x` in floats, the input of the constructions (heuristics:
/// only tightness depends on it): [`Bezier::restrict`] of the float control
/// points, whose end points are one canonical float de Casteljau at `t₀`, `t₁`,
/// so that neighbouring spans share them bit for bit.
pub fn span_f64(x: &Bezier<Rational>, t: (f64, f64)) -> Option<Bezier<f64>> {
    let sub = x.map(|v| v.approx()).restrict(&t.0, &t.1);
    sub.points()
        .iter()
        .all(|p| p.x.is_finite() && p.y.is_finite())
        .then_some(sub)
}

/// Builds the approximant of one span: the construction with canonical end
/// normals (so neighbours share end points exactly).
fn construct(
    method: OffsetMethod,
    output: Output,
    x: &Bezier<Rational>,
    t: (f64, f64),
    kernel: &Kernel,
) -> Option<(Bezier<f64>, Option<lnpair::LnPairPiece>)> {
    if output != Output::Native {
        return fit::construct(output, x, t, kernel).map(|b| (b, None));
    }
    let sub = span_f64(x, t)?;
    let d = match kernel {
        Kernel::Offset { df, .. } => *df,
        Kernel::Conv { qf, sigma, .. } => {
            // seed 001: the ends pinned to the canonical pen points
            let e0 = conv::pen_point_at(x, t.0, *qf, *sigma)?;
            let e1 = conv::pen_point_at(x, t.1, *qf, *sigma)?;
            return match method {
                OffsetMethod::G2 => conv::convolution_approximant_f64(&sub, &e0, &e1, *qf, *sigma)
                    .map(|(c, _)| (c, None)),
                OffsetMethod::LnPair => {
                    let n0 = prep::unit_left_normal(x, t.0)?;
                    let n1 = prep::unit_left_normal(x, t.1)?;
                    let pair = lnpair::ln_pair_pen(&sub, &n0, &n1, &e0, &e1).ok()?;
                    Some((pair.offset.clone(), Some(pair)))
                }
            };
        }
    };
    let n0 = prep::unit_left_normal(x, t.0)?;
    let n1 = prep::unit_left_normal(x, t.1)?;
    match method {
        OffsetMethod::G2 => {
            let (mut o, _) = g2::offset_approximant_f64(&sub, d)?;
            // pin the ends to x(tᵢ) + d Nᵢ with the canonical normals
            let p = sub.points();
            let last = o.points().len() - 1;
            let e0 = p[0].add(&n0.scale(&d));
            let e1 = p[p.len() - 1].add(&n1.scale(&d));
            let mut pts = o.points().to_vec();
            pts[0] = e0;
            pts[last] = e1;
            o = Bezier::new(pts);
            Some((o, None))
        }
        OffsetMethod::LnPair => {
            let pair = lnpair::ln_pair(&sub, &n0, &n1, d).ok()?;
            Some((pair.offset.clone(), Some(pair)))
        }
    }
}

/// Certifies one span: the segment (if constructed and certified at all), the
/// split point, and whether the search ran out of its box budget undecided while
/// its lower bound is far below `tol` ("stuck"). Near a cusp halving helps; on a
/// (nearly) exact approximant it does not (bounds on coinciding curves shrink
/// like `w^{3/2}` however the span is cut), so the driver splits a stuck span
/// once and gives up when a half is stuck again.
fn certify_segment(
    x: &Bezier<Rational>,
    task: &Task,
    opts: &OffsetOptions,
    kernel: &Kernel,
    searches: &std::sync::atomic::AtomicUsize,
) -> (Option<OffsetSegment>, f64, bool) {
    let split = 0.5;
    let d = kernel.reach();
    let Some((built, pair)) = construct(opts.method, opts.output, x, task.t, kernel) else {
        return (None, split_point(opts, x, task.t, kernel, None), false);
    };
    // with a grid: the written (rounded) numbers are proven; the construction
    // is pre-checked within `tol − rounding move`
    let (bez, unrounded, fit_tol) = match &opts.grid {
        None => (built, None, opts.tol),
        Some(g) => match fit::round_to_grid(&built, g) {
            Some(r) => (r, Some(built), opts.tol - fit::rounding_move(g)),
            None => {
                return (
                    None,
                    split_point(opts, x, task.t, kernel, pair.as_ref()),
                    false,
                )
            }
        },
    };
    // The pieces of the span's exact offset (`ShapeDesc::Offset` of the exact
    // restriction of `x`) and of the segment, enclosed without rationals.
    let (Some(pa), Some(pb)) = (
        kernel.span_piece(x, task.t),
        crate::certify::piece::bezier_f64(&bez),
    ) else {
        return (None, split, false);
    };
    let (pa, pb) = ([pa], [pb]);
    // a segment with nothing certified: the trivial bounds (and, with
    // `certify: false`, the sampled estimate apart)
    let unproven = |estimate: Option<f64>| OffsetSegment {
        piece: task.piece,
        t: task.t,
        bezier: bez.clone(),
        error: (0.0, f64::INFINITY),
        paper_error: None,
        proof: None,
        estimate,
    };
    if !opts.certify {
        // the same construction, accepted on a sampled estimate (unproven)
        let e = crate::certify::sampled_pieces(&pa, &pb, 32);
        return (
            Some(unproven(Some(e))),
            split_point(opts, x, task.t, kernel, pair.as_ref()),
            false,
        );
    }
    // A span whose sampled (float, unproven) error is already above `tol` is
    // split without a proof: only acceptance needs one, and refuting the span
    // with a certified lower bound costs more than the rest of its search. At
    // the depth limit the span is bounded anyway, to report it.
    let pre = |pb: &[crate::certify::piece::Piece]| crate::certify::sampled_pieces(&pa, pb, 8);
    if !opts.accept_paper
        && task.depth < opts.max_depth
        && match &unrounded {
            None => pre(&pb) > fit_tol,
            Some(u) => crate::certify::piece::bezier_f64(u).is_none_or(|p| pre(&[p]) > fit_tol),
        }
    {
        return (
            Some(unproven(None)),
            split_point(opts, x, task.t, kernel, pair.as_ref()),
            false,
        );
    }
    let cfg = Config {
        tol: Some(opts.tol),
        max_boxes: opts.max_boxes,
        // a refuted span is split: its other direction is not needed — unless it
        // cannot be split any more and its bounds are reported
        verdict_only: task.depth < opts.max_depth && !opts.accept_paper,
        parametric: !opts.search_only,
        ..Config::default()
    };
    searches.fetch_add(1, std::sync::atomic::Ordering::Relaxed);
    // the absolute gap of `hausdorff` for these shapes, from the float data
    let abs_of = || {
        let scale = bez
            .points()
            .iter()
            .map(|p| p.x.abs().max(p.y.abs()))
            .fold(0.0, f64::max);
        1e-10 * (1.0 + scale + d)
    };
    let r = crate::certify::hausdorff_pieces(&pa, &pb, &cfg, &abs_of);
    let paper_error = match (&pair, opts.paper_error || opts.accept_paper, kernel) {
        (Some(p), true, Kernel::Offset { df, .. }) => {
            sub_exact(x, task.t).and_then(|e| paper_error_of(x, task.t, &e, p, *df))
        }
        (Some(p), true, Kernel::Conv { pen, sigma, .. }) => {
            sub_exact(x, task.t).and_then(|e| conv_paper_error(&e, p, pen, *sigma))
        }
        _ => None,
    };
    let proof = (r.hi <= opts.tol).then(|| SegmentProof {
        path: if r.parametric.is_some() {
            ProofPath::Parametric
        } else {
            ProofPath::Search
        },
        map: r.parametric.clone(),
        exact_to_segment: r.a_to_b.boxes.clone(),
        segment_to_exact: r.b_to_a.boxes.clone(),
    });
    let seg = OffsetSegment {
        piece: task.piece,
        t: task.t,
        bezier: bez,
        error: (r.lo, r.hi),
        paper_error,
        proof,
        estimate: None,
    };
    let stuck = r.incomplete() && r.hi > opts.tol && r.lo * 64.0 < opts.tol;
    (
        Some(seg),
        split_point(opts, x, task.t, kernel, pair.as_ref()),
        stuck,
    )
}

/// Where to split a span that missed the tolerance, as a fraction of it: the
/// middle for G², the LN-pair rule of `opts.subdivision` (its pair when one was
/// built; rule (a) otherwise).
fn split_point(
    opts: &OffsetOptions,
    x: &Bezier<Rational>,
    t: (f64, f64),
    kernel: &Kernel,
    pair: Option<&lnpair::LnPairPiece>,
) -> f64 {
    if opts.method == OffsetMethod::G2 {
        return 0.5;
    }
    let Some(s) = span_f64(x, t) else {
        return 0.5;
    };
    match (opts.subdivision, pair) {
        (lnpair::Subdivision::Chord, Some(p)) => lnpair::chord_param(&s, p),
        (lnpair::Subdivision::Weighted, Some(p)) => {
            // the exact pen (or offset-circle) point compatible with s(u)
            let h = s.hodograph();
            let q = |u: f64| {
                let d = h.eval(&u);
                let l = d.norm2().sqrt();
                if !(l > 0.0 && l.is_finite()) {
                    return None;
                }
                let n = V2::new(-d.y / l, d.x / l);
                match kernel {
                    Kernel::Offset { df, .. } => Some(n.scale(df)),
                    Kernel::Conv { qf, sigma, .. } => conv::pen_point(&n, *qf, *sigma),
                }
            };
            lnpair::weighted_param(&s, p, &q)
        }
        _ => lnpair::mid_angle_param(&s),
    }
}

/// Interval enclosure of the unit left normal of `x` at `t`.
fn normal_enclosure(x: &Bezier<Rational>, t: f64) -> Option<V2<Interval>> {
    let d = x.hodograph().eval(&rational_from_f64(t)?);
    let v = V2::new(interval_from_rational(&d.x), interval_from_rational(&d.y));
    let l = crate::scalar::ScalarSqrt::sqrt(&v.norm2())?;
    let inv = Scalar::recip(&l)?;
    Some(V2::new(-v.y * inv, v.x * inv))
}

fn paper_error_of(
    x: &Bezier<Rational>,
    t: (f64, f64),
    exact: &Bezier<Rational>,
    p: &lnpair::LnPairPiece,
    d: f64,
) -> Option<f64> {
    let pa = exact_bezier(&p.pa)?;
    let r = hausdorff(
        &ShapeDesc::Curve(vec![exact.clone()]),
        &ShapeDesc::Curve(vec![pa]),
        &Config {
            rel: 1e-2,
            ..Config::default()
        },
    )
    .ok()?;
    let arc = lnpair::arc_term(
        &normal_enclosure(x, t.0)?,
        &normal_enclosure(x, t.1)?,
        p.kappa,
        d,
    )?;
    Some(lnpair::paper_error(r.hi, arc))
}

/// Seed 000 §5's error measure `d_H(p, pa) + d_H(q, qa)` of an LN pair of a
/// convolution, bounded above with certified bounds: `p` the exact span,
/// `q` the pen's elliptic arc between the compatible points (pre-image
/// directions `σ Mᵀ n(t₀)`, `σ Mᵀ n(t₁)`, `n` the exact left normal). `None`
/// for a straight span (the pen arc is a point) or when a bound fails.
fn conv_paper_error(
    exact: &Bezier<Rational>,
    p: &lnpair::LnPairPiece,
    pen: &conv::Pen,
    sigma: i8,
) -> Option<f64> {
    let pa = exact_bezier(&p.pa)?;
    let qa = exact_bezier(&p.ca)?;
    let cfg = Config {
        rel: 1e-2,
        ..Config::default()
    };
    let d_p = hausdorff(
        &ShapeDesc::Curve(vec![exact.clone()]),
        &ShapeDesc::Curve(vec![pa]),
        &cfg,
    )
    .ok()?;
    let h = exact.hodograph();
    let m = &pen.m;
    let s = Rational::from_integer(sigma.into());
    let dir = |t: &Rational| {
        let d = h.eval(t);
        let n = V2::new(-d.y.clone(), d.x.clone());
        // σ Mᵀ n
        V2::new(
            (&m[0][0] * &n.x + &m[1][0] * &n.y) * &s,
            (&m[0][1] * &n.x + &m[1][1] * &n.y) * &s,
        )
    };
    let (u0, u1) = (
        dir(&<Rational as Zero>::zero()),
        dir(&Rational::from_integer(1.into())),
    );
    let cross = u0.cross(&u1);
    if cross.is_zero() {
        return None;
    }
    let (from, to) = if cross > <Rational as Zero>::zero() {
        (u0, u1)
    } else {
        (u1, u0)
    };
    let arc = crate::certify::EllipseArc {
        center: V2::new(<Rational as Zero>::zero(), <Rational as Zero>::zero()),
        m: m.clone(),
        from,
        to,
    };
    let d_q = crate::certify::hausdorff_ellipse_arc(&arc, &[qa], &cfg).ok()?;
    let sum = interval_from_rational(&rational_from_f64(d_p.hi)?)
        + interval_from_rational(&rational_from_f64(d_q.hi)?);
    Some(sum.sup())
}

/// Approximates the offset at `opts.distance` of a piecewise polynomial curve
/// within `opts.tol`, proving every segment (see the module docs).
///
/// Errors: a typed [`OffsetError`] naming the field for a singular or cusped
/// input piece (its normal is undefined), a zero distance, a tolerance that is
/// not a positive number or is below [`MIN_REL_TOL`] × (1 + scale), or
/// coordinates beyond `1e100`. A tolerance that cannot be reached within the
/// depth and segment limits is not an error: the result lists the segments in
/// [`OffsetResult::unreached`] with their certified bounds.
pub fn offset(
    curve: &[Bezier<Rational>],
    opts: &OffsetOptions,
) -> Result<OffsetResult, OffsetError> {
    check_options(curve, opts)?;
    let find_cusps = || -> Vec<OffsetCusp> {
        curve
            .iter()
            .enumerate()
            .flat_map(|(i, x)| prep::offset_cusps(i, x, &opts.distance))
            .collect()
    };
    let kernel = Kernel::Offset {
        d: opts.distance.clone(),
        df: opts.distance.approx(),
    };
    let (cusps, segs) = if opts.output == Output::Native {
        // the exact cusp isolation does not depend on the segments: beside them
        rayon::join(find_cusps, || offset_segments(curve, opts, &kernel, &[]))
    } else {
        // a fitted cubic or quadratic cannot turn back: cut at the cusps first
        let cusps = find_cusps();
        let cuts = cusp_cuts(curve.len(), fit::cusps_to_cut(&cusps, opts.tol).into_iter());
        let segs = offset_segments(curve, opts, &kernel, &cuts);
        (cusps, segs)
    };
    let (segments, unreached, certified_hi, certifications, spans) = segs;
    let mut res = OffsetResult {
        method: opts.method,
        distance: opts.distance.clone(),
        tol: opts.tol,
        segments,
        unreached,
        certified_hi,
        cusps,
        corners: corners(curve, &opts.distance),
        certifications,
        spans,
        proven: opts.certify,
        convolution: None,
    };
    if opts.smooth_kinks && opts.output != Output::Native && opts.grid.is_none() && opts.certify {
        absorb_kinks(curve, &mut res, opts, &kernel);
    }
    Ok(res)
}

/// The index of the last segment of piece `a` and of the first of piece `b`.
fn corner_segments(res: &OffsetResult, a: usize, b: usize) -> Option<(usize, usize)> {
    let ia = res.segments.iter().rposition(|s| s.piece == a)?;
    let ib = res.segments.iter().position(|s| s.piece == b)?;
    (ia != ib).then_some((ia, ib))
}

/// Proves `bez` against the exact span `t` of `x` (both directions).
fn prove_given(
    x: &Bezier<Rational>,
    piece: usize,
    t: (f64, f64),
    bez: Bezier<f64>,
    opts: &OffsetOptions,
    kernel: &Kernel,
) -> Option<OffsetSegment> {
    let pa = kernel.span_piece(x, t)?;
    let pb = crate::certify::piece::bezier_f64(&bez)?;
    let cfg = Config {
        tol: Some(opts.tol),
        max_boxes: opts.max_boxes,
        verdict_only: true,
        parametric: !opts.search_only,
        ..Config::default()
    };
    let r = crate::certify::hausdorff_pieces(&[pa], &[pb], &cfg, &|| 0.0);
    (r.hi <= opts.tol).then(|| OffsetSegment {
        piece,
        t,
        bezier: bez,
        error: (r.lo, r.hi),
        paper_error: None,
        proof: Some(SegmentProof {
            path: if r.parametric.is_some() {
                ProofPath::Parametric
            } else {
                ProofPath::Search
            },
            map: r.parametric.clone(),
            exact_to_segment: r.a_to_b.boxes.clone(),
            segment_to_exact: r.b_to_a.boxes.clone(),
        }),
        estimate: None,
    })
}

/// The cover of an absorbed join arc by its two neighbouring segments
/// (`None` when it is not proven within `tol`).
fn arc_cover(
    arc: &crate::shape::ArcDesc,
    sa: &Bezier<f64>,
    sb: &Bezier<f64>,
    tol: f64,
    max_boxes: usize,
) -> Option<Vec<CoverBox>> {
    let pa = crate::certify::piece::Piece::arc(arc).ok()?;
    let pb = [
        crate::certify::piece::bezier_f64(sa)?,
        crate::certify::piece::bezier_f64(sb)?,
    ];
    let cfg = Config {
        tol: Some(tol),
        max_boxes,
        ..Config::default()
    };
    let r = crate::certify::search::one_sided(&[pa], &pb, &cfg, 0.0, (0.0, 0.0));
    (r.hi <= tol && !r.boxes.is_empty()).then_some(r.boxes)
}

/// [`OffsetOptions::smooth_kinks`]: absorbs the corners whose offset ends are
/// within `tol` of each other (see there).
fn absorb_kinks(
    curve: &[Bezier<Rational>],
    res: &mut OffsetResult,
    opts: &OffsetOptions,
    kernel: &Kernel,
) {
    let n = curve.len();
    for ci in 0..res.corners.len() {
        let a = res.corners[ci].after;
        let b = (a + 1) % n;
        let Some((ia, ib)) = corner_segments(res, a, b) else {
            continue;
        };
        let (sa, sb) = (&res.segments[ia], &res.segments[ib]);
        let (pa, pb) = (sa.bezier.points(), sb.bezier.points());
        let (p, q) = (&pa[pa.len() - 1], &pb[0]);
        let gap = (p.x - q.x).hypot(p.y - q.y);
        if gap.is_nan() || gap > opts.tol {
            continue;
        }
        let m = V2::new(0.5 * (p.x + q.x), 0.5 * (p.y + q.y));
        let mut na = pa.to_vec();
        let last = na.len() - 1;
        na[last] = m.clone();
        let mut nb = pb.to_vec();
        nb[0] = m;
        let (Some(new_a), Some(new_b)) = (
            prove_given(&curve[a], a, sa.t, Bezier::new(na), opts, kernel),
            prove_given(&curve[b], b, sb.t, Bezier::new(nb), opts, kernel),
        ) else {
            continue;
        };
        // the convex side's join arc must lie within tol of the two segments
        if let Some(arc) = join_arc_of(&res.corners[ci], &res.distance) {
            if arc_cover(&arc, &new_a.bezier, &new_b.bezier, opts.tol, opts.max_boxes).is_none() {
                continue;
            }
        }
        res.segments[ia] = new_a;
        res.segments[ib] = new_b;
        res.corners[ci].absorbed = true;
    }
    res.certified_hi = res.segments.iter().map(|s| s.error.1).fold(0.0, f64::max);
}

/// Approximates the convolution `x ∗ e_σ` of a piecewise polynomial curve with
/// an elliptical pen on side `side` (`+1`: left of the travel direction, `−1`:
/// right) within `opts.tol`, by seed 001's G²/C¹ method ([`OffsetMethod::G2`],
/// degree `n + 3`) or seed 000 §5's cubic LN pairs ([`OffsetMethod::LnPair`]:
/// [`lnpair::ln_pair_pen`], split at the mid-angle, rule (a); `opts.distance`
/// is not used, and the paper's error measure is not evaluated), proving every segment
/// against the exact convolution (see [`conv`]). The trajectory is split first
/// at the side's own cusps (exact), then at inflections and turns.
///
/// When the pen's rotation was represented approximately, the segments are
/// certified within `tol − pen.margin` for the exact pen used, so that `tol`
/// holds for the pen as given ([`ConvSide::certified_tol`]).
///
/// # Examples
/// ```
/// use lncert::approx::{convolve, conv::{Angle, Pen}, OffsetOptions};
/// use lncert::shape::parse_curve;
/// let q = |s: &str| lncert::parse_rational(s).unwrap();
/// let x = parse_curve("M 0 0 C 1 0.2 2 1 2.4 2.5").unwrap();
/// let pen = Pen::ellipse(&q("0.3"), &q("0.1"), &Angle::parse("pi/6").unwrap()).unwrap();
/// let r = convolve(&x, &pen, 1, &OffsetOptions::new(q("0"), 1e-4)).unwrap();
/// assert!(r.reached() && r.certified_hi <= 1e-4);
/// assert_eq!(r.degree(), 6);
/// ```
pub fn convolve(
    curve: &[Bezier<Rational>],
    pen: &conv::Pen,
    side: i8,
    opts: &OffsetOptions,
) -> Result<OffsetResult, OffsetError> {
    if side != 1 && side != -1 {
        return Err(bad("side", "must be 1 or -1"));
    }
    if curve.is_empty() {
        return Err(bad("curve", "no pieces"));
    }
    let shape = ShapeDesc::convolution(curve.to_vec(), pen.m.clone(), side).map_err(|e| {
        let field = e
            .field
            .strip_prefix("convolution.")
            .unwrap_or(&e.field)
            .to_string();
        bad(field, e.reason)
    })?;
    check_limits(opts, shape.scale(), pen.margin)?;
    let certified_tol = opts.tol - pen.margin;
    let cusps: Vec<conv::ConvCusp> = curve
        .par_iter()
        .enumerate()
        .flat_map(|(i, x)| conv::conv_cusps(i, x, pen, side))
        .collect();
    // seed 001 §4 splits each side at its own cusps first; seed 000 §5's LN
    // pairs split only at inflections and turns
    let cuts: Vec<Vec<f64>> = (0..curve.len())
        .map(|i| {
            cusps
                .iter()
                .filter(|c| {
                    c.piece == i
                        && (opts.method == OffsetMethod::G2 || opts.output != Output::Native)
                })
                .map(|c| c.t_approx)
                .collect()
        })
        .collect();
    let kernel = Kernel::Conv {
        pen: Box::new(pen.clone()),
        qf: pen.q_f64(),
        sigma: side,
    };
    let inner = OffsetOptions {
        tol: certified_tol,
        ..opts.clone()
    };
    let (segments, unreached, certified_hi, certifications, spans) =
        offset_segments(curve, &inner, &kernel, &cuts);
    Ok(OffsetResult {
        method: opts.method,
        distance: <Rational as Zero>::zero(),
        tol: opts.tol,
        segments,
        unreached,
        certified_hi,
        cusps: Vec::new(),
        corners: Vec::new(),
        certifications,
        spans,
        proven: opts.certify,
        convolution: Some(ConvSide {
            pen: pen.clone(),
            side,
            cusps,
            certified_tol,
        }),
    })
}

/// The segments of [`offset`]: `(segments, unreached, certified_hi, certified
/// searches, spans tried)`.
fn offset_segments(
    curve: &[Bezier<Rational>],
    opts: &OffsetOptions,
    kernel: &Kernel,
    cuts: &[Vec<f64>],
) -> (Vec<OffsetSegment>, Vec<usize>, f64, usize, usize) {
    let mut spans = 0usize;
    let mut tasks: Vec<Task> = Vec::new();
    for (i, x) in curve.iter().enumerate() {
        // a fitted cubic may have an inflection: the native constructions (and
        // a quadratic) need the input cut there
        let inflections = opts.output != Output::Cubic;
        for t in initial_spans(
            x,
            cuts.get(i).map_or(&[][..], |c| &c[..]),
            opts.method,
            inflections,
        ) {
            tasks.push(Task {
                piece: i,
                t,
                depth: 0,
                stuck_before: false,
            });
        }
    }
    let mut done: Vec<OffsetSegment> = Vec::new();
    let mut unreached_segs: Vec<OffsetSegment> = Vec::new();
    let searches = std::sync::atomic::AtomicUsize::new(0);
    while !tasks.is_empty() {
        spans += tasks.len();
        let outcomes: Vec<Outcome> = tasks
            .par_iter()
            .map(|task| {
                let (segment, s, stuck) =
                    certify_segment(&curve[task.piece], task, opts, kernel, &searches);
                Outcome {
                    task: task.clone(),
                    segment,
                    split: s,
                    stuck,
                }
            })
            .collect();
        let mut next = Vec::new();
        let mut pending = outcomes.len();
        for o in outcomes {
            pending -= 1;
            // proven within tol, or (certify: false) estimated within it
            // with the paper's acceptance a segment with a measure is accepted
            // by the measure alone, as the paper does (a segment whose measure
            // is above tol is split even when its true error is below it)
            let accepted = o.segment.as_ref().is_some_and(|s| match s.paper_error {
                Some(e) if opts.accept_paper => e <= opts.tol,
                _ => s.error.1 <= opts.tol || s.estimate.is_some_and(|e| e <= opts.tol),
            });
            if accepted {
                done.extend(o.segment);
                continue;
            }
            let (a, b) = o.task.t;
            let m = a + (b - a) * o.split;
            // every outcome still to be looked at ends as at least one segment
            let room =
                done.len() + unreached_segs.len() + next.len() + pending + 2 <= opts.max_segments;
            let give_up = o.stuck && o.task.stuck_before;
            if !give_up && o.task.depth < opts.max_depth && m > a && m < b && room {
                next.push(Task {
                    piece: o.task.piece,
                    t: (a, m),
                    depth: o.task.depth + 1,
                    stuck_before: o.stuck,
                });
                next.push(Task {
                    piece: o.task.piece,
                    t: (m, b),
                    depth: o.task.depth + 1,
                    stuck_before: o.stuck,
                });
            } else if let Some(s) = o.segment {
                unreached_segs.push(s);
            } else {
                // no construction at all: keep the exact span's chord offset? No —
                // report an unreached segment with an infinite bound.
                let x = &curve[o.task.piece];
                if let Some(sub) = span_f64(x, o.task.t) {
                    let p = sub.points();
                    unreached_segs.push(OffsetSegment {
                        piece: o.task.piece,
                        t: o.task.t,
                        bezier: Bezier::new(vec![p[0].clone(), p[p.len() - 1].clone()]),
                        error: (0.0, f64::INFINITY),
                        paper_error: None,
                        proof: None,
                        estimate: None,
                    });
                }
            }
        }
        tasks = next;
    }
    let mut segments: Vec<(OffsetSegment, bool)> = done
        .into_iter()
        .map(|s| (s, false))
        .chain(unreached_segs.into_iter().map(|s| (s, true)))
        .collect();
    segments.sort_by(|a, b| {
        (a.0.piece, a.0.t.0)
            .partial_cmp(&(b.0.piece, b.0.t.0))
            .unwrap_or(std::cmp::Ordering::Equal)
    });
    let unreached = segments
        .iter()
        .enumerate()
        .filter(|(_, s)| s.1)
        .map(|(i, _)| i)
        .collect();
    let segments: Vec<OffsetSegment> = segments.into_iter().map(|s| s.0).collect();
    let certified_hi = segments.iter().map(|s| s.error.1).fold(0.0, f64::max);
    (
        segments,
        unreached,
        certified_hi,
        searches.into_inner(),
        spans,
    )
}

/// Per piece, the parameters `(piece, t)` to cut the initial spans at.
fn cusp_cuts(pieces: usize, at: impl Iterator<Item = (usize, f64)>) -> Vec<Vec<f64>> {
    let mut cuts = vec![Vec::new(); pieces];
    for (i, t) in at {
        if let Some(c) = cuts.get_mut(i) {
            c.push(t);
        }
    }
    cuts
}

/// The junctions of consecutive pieces that need a join arc or trimming, and the
/// closing junction when the curve is closed.
pub fn corners(curve: &[Bezier<Rational>], d: &Rational) -> Vec<Corner> {
    let n = curve.len();
    let mut out = Vec::new();
    for i in 0..n {
        let j = i + 1;
        if j == n {
            // closed curve: last end = first start
            let last = curve[n - 1].points();
            if n == 1 || last[last.len() - 1] != curve[0].points()[0] {
                continue;
            }
        }
        let kind = prep::junction(&curve[i], &curve[j % n], d);
        if matches!(kind, Junction::Join { .. } | Junction::Overlap { .. }) {
            out.push(Corner {
                after: i,
                kind,
                absorbed: false,
            });
        }
    }
    out
}

/// Certified global bounds `lo ≤ d_H ≤ hi` between the exact offset of the
/// whole input and the whole approximant (relative gap `rel`), by a two-sided
/// search over all pieces (opt-in: its cost grows with the square of the number
/// of segments; the tolerance itself is proven by the per-segment proofs).
pub fn global_bounds(
    curve: &[Bezier<Rational>],
    res: &OffsetResult,
    rel: f64,
) -> Result<HausdorffBounds, OffsetError> {
    let a = exact_offset_shape(curve, res)?;
    let b = res.approximant_shape()?;
    hausdorff(
        &a,
        &b,
        &Config {
            rel,
            ..Config::default()
        },
    )
    .map_err(|e| bad("certify", e.to_string()))
}

/// The certificate of `d_H(exact offset, approximant) ≤ tol`, assembled from the
/// per-segment proofs without any further search (linear in the segments), or
/// `None` when the tolerance was not reached. `tol` is the claim, exactly as the
/// user gave it (every segment's bound is ≤ `res.tol`, the largest float ≤ it).
///
/// Shapes: the exact offset of the input split exactly at the segments'
/// parameters ([`exact_offset_shape`], piece `i` = segment `i`'s span) and the
/// approximant (piece `i` = segment `i`). Proofs: each segment's parametric
/// map (source and target `i`), or its two search covers (piece and target
/// `i`). Sound because `h(∪Aᵢ, ∪Bᵢ) ≤ maxᵢ h(Aᵢ, Bᵢ)`
/// (a point of `Aᵢ` within `tol` of `Bᵢ` is within `tol` of `∪B`), and
/// [`crate::certify::verify::verify`] re-checks every box against the whole
/// shapes. When the result has join arcs at G⁰ corners ([`join_arcs`]), both
/// shapes are unions ending with those exact arcs (the same in both, each
/// covered by its own search), so the certificate covers the whole offset
/// with its round joins.
pub fn union_certificate(
    curve: &[Bezier<Rational>],
    res: &OffsetResult,
    tol: &Rational,
) -> Result<Option<Certificate>, OffsetError> {
    assemble(curve, &[res], tol, false)
}

/// The certificate of [`union_certificate`] (one result) or
/// [`union_certificate_all`] (several; always a union): the exact curves and
/// approximants, then the join arcs of every result ([`join_arcs`], the same
/// exact arc in both shapes, proven by its own cover). Without join arcs, one
/// result keeps the plain shapes.
fn assemble(
    curve: &[Bezier<Rational>],
    results: &[&OffsetResult],
    tol: &Rational,
    always_union: bool,
) -> Result<Option<Certificate>, OffsetError> {
    if results.is_empty() {
        return Err(bad("results", "no results"));
    }
    if results
        .iter()
        .any(|r| !r.reached() || r.segments.iter().any(|s| s.proof.is_none()))
    {
        return Ok(None);
    }
    let mut a_members = Vec::new();
    let mut b_members = Vec::new();
    let mut maps = Vec::new();
    let (mut ab, mut ba) = (Vec::new(), Vec::new());
    let renumber = |i: usize, bs: &[CoverBox]| {
        bs.iter()
            .map(|bx| CoverBox {
                piece: i,
                target: i,
                ..bx.clone()
            })
            .collect::<Vec<_>>()
    };
    let mut base = 0usize;
    for res in results {
        a_members.push(exact_offset_shape(curve, res)?);
        b_members.push(res.approximant_shape()?);
        for (k, p) in res
            .segments
            .iter()
            .filter_map(|s| s.proof.as_ref())
            .enumerate()
        {
            let i = base + k;
            match &p.map {
                Some(m) => maps.push(MapCover {
                    from_a: m.source_a,
                    piece: i,
                    target: i,
                    boxes: m.boxes.clone(),
                    hi: m.hi,
                }),
                None => {
                    ab.extend(renumber(i, &p.exact_to_segment));
                    ba.extend(renumber(i, &p.segment_to_exact));
                }
            }
        }
        base += res.segments.len();
    }
    // the join arcs: the same exact arc on both sides, covered by a search
    let tol_f = interval_from_rational(tol).inf();
    for res in results {
        for arc in join_arcs(res) {
            let shape = ShapeDesc::arc(arc)?;
            let cfg = Config {
                tol: Some(tol_f),
                ..Config::default()
            };
            let Ok(h) = hausdorff(&shape, &shape, &cfg) else {
                return Ok(None);
            };
            if h.hi > tol_f || h.a_to_b.boxes.is_empty() || h.b_to_a.boxes.is_empty() {
                return Ok(None);
            }
            ab.extend(renumber(base, &h.a_to_b.boxes));
            ba.extend(renumber(base, &h.b_to_a.boxes));
            a_members.push(shape.clone());
            b_members.push(shape);
            base += 1;
        }
    }
    // absorbed corners: the exact arc (in `a` only) covered by the two
    // segments that meet there
    let mut seg_base = 0usize;
    for res in results {
        let n = res.segments.len();
        let pieces = res
            .segments
            .iter()
            .map(|s| s.piece)
            .max()
            .map_or(0, |m| m + 1);
        for c in res.corners.iter().filter(|c| c.absorbed) {
            let Some(arc) = join_arc_of(c, &res.distance) else {
                continue;
            };
            let after = (c.after + 1) % pieces.max(1);
            let Some((ia, ib)) = corner_segments(res, c.after, after) else {
                return Ok(None);
            };
            let Some(boxes) = arc_cover(
                &arc,
                &res.segments[ia].bezier,
                &res.segments[ib].bezier,
                tol_f,
                200_000,
            ) else {
                return Ok(None);
            };
            let a_index = base;
            ab.extend(boxes.into_iter().map(|bx| CoverBox {
                piece: a_index,
                target: seg_base + if bx.target == 0 { ia } else { ib },
                ..bx
            }));
            a_members.push(ShapeDesc::arc(arc)?);
            base += 1;
        }
        seg_base += n;
    }
    let (a, b) = if a_members.len() == 1 && !always_union {
        (a_members.remove(0), b_members.remove(0))
    } else {
        (ShapeDesc::union(a_members)?, ShapeDesc::union(b_members)?)
    };
    Ok(Certificate::assemble(&a, &b, tol, &maps, &ab, &ba))
}

/// One certificate for several results of the same curve (the two sides of
/// a convolution, or offsets at several distances): `d_H(A, B) ≤ tol` with
/// `A` the union of the exact curves ([`exact_offset_shape`] of each result)
/// and `B` the union of the approximants, each a member of a
/// [`ShapeDesc::Union`] in the order given, with every piece proven against
/// its own span as in [`union_certificate`]. `None` when a result is not
/// reached or a segment has no proof; an error when `results` is empty.
///
/// # Examples
/// ```
/// use lncert::approx::{convolve, union_certificate_all, conv::Pen, OffsetOptions};
/// use lncert::shape::parse_curve;
/// let q = |s: &str| lncert::parse_rational(s).unwrap();
/// let x = parse_curve("M 0 0 C 1 0.2 2 1 2.4 2.5").unwrap();
/// let pen = Pen::from_matrix([[q("0.3"), q("0")], [q("0.1"), q("0.2")]]).unwrap();
/// let opts = OffsetOptions::new(q("0"), 1e-3);
/// let plus = convolve(&x, &pen, 1, &opts).unwrap();
/// let minus = convolve(&x, &pen, -1, &opts).unwrap();
/// let cert = union_certificate_all(&x, &[&plus, &minus], &q("1/1000")).unwrap().unwrap();
/// let valid = lncert::verify(&cert.to_json_string()).unwrap();
/// assert!(valid.a.starts_with("the union of 2 shapes"));
/// ```
pub fn union_certificate_all(
    curve: &[Bezier<Rational>],
    results: &[&OffsetResult],
    tol: &Rational,
) -> Result<Option<Certificate>, OffsetError> {
    assemble(curve, results, tol, true)
}

/// The exact offset of the input, as the union of the exact offsets of the
/// spans of the result's segments (each span an exact restriction of its input
/// piece at dyadic parameters, so the union is the same point set as the offset
/// of the input). Splitting keeps the pieces short, which the foot-point search
/// of the certification needs where the offset folds over itself near cusps.
pub fn exact_offset_shape(
    curve: &[Bezier<Rational>],
    res: &OffsetResult,
) -> Result<ShapeDesc, OffsetError> {
    let pieces = res
        .segments
        .iter()
        .map(|s| {
            curve
                .get(s.piece)
                .and_then(|x| sub_exact(x, s.t))
                .ok_or_else(|| bad("segments", "a segment does not name an input span"))
        })
        .collect::<Result<Vec<_>, _>>()?;
    match &res.convolution {
        None => ShapeDesc::offset(pieces, res.distance.clone()),
        Some(c) => ShapeDesc::convolution(pieces, c.pen.m.clone(), c.side),
    }
    .map_err(|e| bad("curve", e.to_string()))
}

/// The join arcs of a result as exact arcs (radius `|d|`), for output: those
/// of the corners that are not [`Corner::absorbed`].
pub fn join_arcs(res: &OffsetResult) -> Vec<crate::shape::ArcDesc> {
    res.corners
        .iter()
        .filter(|c| !c.absorbed)
        .filter_map(|c| join_arc_of(c, &res.distance))
        .collect()
}

/// The join arcs of the [`Corner::absorbed`] corners: in the exact curve,
/// covered by the neighbouring segments, not in the approximant.
pub fn absorbed_arcs(res: &OffsetResult) -> Vec<crate::shape::ArcDesc> {
    res.corners
        .iter()
        .filter(|c| c.absorbed)
        .filter_map(|c| join_arc_of(c, &res.distance))
        .collect()
}

/// The counter-clockwise exact arc of a `Join` corner.
fn join_arc_of(c: &Corner, distance: &Rational) -> Option<crate::shape::ArcDesc> {
    let r = if *distance < <Rational as Zero>::zero() {
        -distance.clone()
    } else {
        distance.clone()
    };
    match &c.kind {
        Junction::Join {
            center,
            from,
            to,
            clockwise,
        } => Some(if *clockwise {
            crate::shape::ArcDesc {
                center: center.clone(),
                radius: r,
                from: to.clone(),
                to: from.clone(),
            }
        } else {
            crate::shape::ArcDesc {
                center: center.clone(),
                radius: r,
                from: from.clone(),
                to: to.clone(),
            }
        }),
        _ => None,
    }
}
