//! What the offset engine returns: the proven segments, their proofs, the
//! corners, and the exact shapes the result approximates.

use super::conv;
use super::options::{bad, OffsetError, OffsetMethod};
use super::prep::{Junction, OffsetCusp};
use crate::certify::{CoverBox, HausdorffBounds};
use crate::curve::{Bezier, V2};
use crate::scalar::{rational_from_f64, Rational};
use crate::shape::ShapeDesc;
use crate::Tolerance;
use num_traits::Zero;

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
    /// The path that proved the bounds `r`: parametric when they carry a map.
    pub(super) fn of(r: &HausdorffBounds) -> Self {
        if r.parametric.is_some() {
            ProofPath::Parametric
        } else {
            ProofPath::Search
        }
    }
}

/// The proof of one accepted segment, which
/// [`union_certificate`](super::union_certificate) assembles into a
/// certificate of the whole result: for the parametric path its map
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

impl SegmentProof {
    /// The proof kept from the bounds `r` of an accepted segment: its map, or
    /// its two search covers.
    pub(super) fn of(r: &HausdorffBounds) -> Self {
        SegmentProof {
            path: ProofPath::of(r),
            map: r.parametric.clone(),
            exact_to_segment: r.a_to_b.boxes.clone(),
            segment_to_exact: r.b_to_a.boxes.clone(),
        }
    }
}

/// A junction of two input pieces that needs attention.
#[derive(Clone, Debug, PartialEq)]
pub struct Corner {
    /// The junction is between piece `after` and the next piece (cyclically for a closed curve).
    pub after: usize,
    /// What happens there: a join arc to add or an overlap to trim.
    pub kind: Junction,
    /// The kink is absorbed ([`OffsetOptions::smooth_kinks`](super::OffsetOptions::smooth_kinks)):
    /// the two
    /// neighbouring segments meet at one point, the approximant has no join
    /// arc here, and the exact curve's join arc (kept in the exact shape) is
    /// proven to lie within `tol` of those two segments.
    pub absorbed: bool,
}

/// The result of [`offset`](super::offset).
#[derive(Clone, Debug, PartialEq)]
pub struct OffsetResult {
    /// The construction that built the segments.
    pub method: OffsetMethod,
    /// Signed offset distance (`> 0` to the left), exact, from the options.
    pub distance: Rational,
    /// The tolerance to prove, from the options (segments are accepted when
    /// their proven bound is `≤ tol.value()`, hence `≤ tol.exact()`).
    pub tol: Tolerance,
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
    /// Set by [`convolve`](super::convolve): the result approximates the convolution `x ∗ e_σ`
    /// with this pen and side instead of an offset (`distance` is then 0,
    /// `cusps` and `corners` are empty and the cusps are in
    /// [`ConvSide::cusps`]).
    pub convolution: Option<ConvSide>,
}

/// The convolution side a result of [`convolve`](super::convolve) approximates.
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
    /// The tolerance certified for the exact pen: `tol − margin`, rounded
    /// down to a float (the claim for the pen as given is `tol`); `tol`
    /// itself when the margin is 0.
    pub certified_tol: Tolerance,
}

impl OffsetResult {
    /// The tolerance the segments are certified within against the exact
    /// curve of the result: [`OffsetResult::tol`], or for a convolution
    /// [`ConvSide::certified_tol`] (`tol` less the pen's rotation margin).
    /// The claim of [`union_certificate`](super::union_certificate).
    pub fn certified_tol(&self) -> &Tolerance {
        match &self.convolution {
            Some(c) => &c.certified_tol,
            None => &self.tol,
        }
    }
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
    /// join arcs (the shape `b` of [`union_certificate`](super::union_certificate),
    /// so a file written from
    /// it is what `lncert verify --against` compares).
    pub fn outline_shape(&self) -> Result<ShapeDesc, OffsetError> {
        with_arcs(self.approximant_shape()?, join_arcs(self))
    }

    /// The exact curve the result approximates, as one shape over the input's
    /// own pieces: the offset (or convolution) of `curve`, and with join arcs
    /// the union of it and the arcs — the absorbed corners' arcs last (the
    /// shape `a` of [`union_certificate`](super::union_certificate),
    /// up to how the pieces are split,
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
        approximant_of(self.segments.iter().map(|s| &s.bezier))
    }
}

/// Float Bézier pieces as one exact curve shape (every float control point
/// is an exact dyadic rational); an error names `approximant`.
pub(super) fn approximant_of<'a>(
    pieces: impl Iterator<Item = &'a Bezier<f64>>,
) -> Result<ShapeDesc, OffsetError> {
    let pieces = pieces
        .map(exact_bezier)
        .collect::<Option<Vec<_>>>()
        .ok_or_else(|| bad("approximant", "a control point is not finite"))?;
    ShapeDesc::curve(pieces).map_err(|e| bad("approximant", e.to_string()))
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
    ShapeDesc::union(members)
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

pub(super) fn sub_exact(x: &Bezier<Rational>, t: (f64, f64)) -> Option<Bezier<Rational>> {
    Some(x.restrict(&rational_from_f64(t.0)?, &rational_from_f64(t.1)?))
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
pub(super) fn join_arc_of(c: &Corner, distance: &Rational) -> Option<crate::shape::ArcDesc> {
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
