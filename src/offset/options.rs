//! The settings of [`offset`](super::offset) and [`convolve`](super::convolve), their checks, and
//! the typed error of the offset engine.

use super::fit::{self, Output};
use super::lnpair;
use crate::curve::Bezier;
use crate::scalar::Rational;
use crate::shape::ShapeDesc;
use crate::Tolerance;

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
    /// The name in reports: `g2` or `ln-pair`.
    pub fn name(self) -> &'static str {
        match self {
            OffsetMethod::G2 => "g2",
            OffsetMethod::LnPair => "ln-pair",
        }
    }
}

/// Settings of [`offset`](super::offset).
#[derive(Clone, Debug, PartialEq)]
pub struct OffsetOptions {
    /// Signed offset distance (`> 0` to the left), exact.
    pub distance: Rational,
    /// The tolerance to prove: `d_H(offset, approximant) ≤ tol` (the
    /// segments' proven bounds are compared with [`Tolerance::value`], the
    /// largest float ≤ the exact tolerance; certificates claim
    /// [`Tolerance::exact`]).
    pub tol: Tolerance,
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
    /// Accept a segment when the paper's measure
    /// ([`OffsetSegment::paper_error`](super::OffsetSegment::paper_error),
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
    /// comparison; the result says so ([`OffsetResult::proven`](super::OffsetResult::proven)).
    pub certify: bool,
    /// Prove every segment by the two-directional search (default false).
    /// Without it, a segment is first tried by the parametric proof
    /// ([`crate::certify::Parametric`]: one cover of the segment's parameter for
    /// both directions, several times cheaper), with the search as fallback;
    /// [`SegmentProof::path`](super::SegmentProof::path)
    /// says which proved it. Either way the proofs are
    /// kept for [`union_certificate`](super::union_certificate).
    pub search_only: bool,
    /// Where an LN-pair span that missed the tolerance is split: seed 000
    /// §5's rule (a), (b) or (c) ([`lnpair::Subdivision`]; default (a), the
    /// mid-angle). G² spans are halved.
    pub subdivision: lnpair::Subdivision,
    /// What the segments are (default [`Output::Native`]: the construction's
    /// own). `Cubic` / `Quadratic` fit cubics / quadratics to the exact curve
    /// of each span ([`super::kernels::least_squares_cubic`], [`super::kernels::tangent_quadratic`]) instead of running the construction of `method`;
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
    /// [`Corner::absorbed`](super::Corner::absorbed).
    /// A corner where any of these proofs fails keeps its
    /// join arc or overlap.
    pub smooth_kinks: bool,
}

impl OffsetOptions {
    /// Defaults for a distance and a tolerance (method G2).
    ///
    /// # Examples
    /// ```
    /// use lncert::{parse_rational, OffsetOptions, Tolerance};
    /// let opts = OffsetOptions::new(parse_rational("0.4").unwrap(), "1e-3".parse().unwrap());
    /// assert_eq!(opts.tol.to_string(), "1/1000");
    /// assert!(opts.tol.value() <= 1e-3);
    /// # let _: Tolerance = opts.tol;
    /// ```
    pub fn new(distance: Rational, tol: Tolerance) -> Self {
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

/// Why an offset or a convolution was refused: the field (`distance`, `tol`,
/// `curve[2]`, `pen.matrix`, …) and the reason — lncert's one input error,
/// [`crate::Error`].
pub type OffsetError = crate::Error;

pub(super) fn bad(field: impl Into<String>, reason: impl Into<String>) -> OffsetError {
    OffsetError::new(field, reason)
}

/// Smallest tolerance accepted, relative to `1 + coordinate scale`: below it
/// the float control points of the approximant cannot resolve the offset.
pub const MIN_REL_TOL: f64 = 1e-11;

pub(super) fn check_options(
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

/// The checks shared by [`offset`] and [`convolve`]: a tolerance that, less
/// `margin` (the pen's rotation margin; 0 for offsets), is at least
/// [`MIN_REL_TOL`] × (1 + scale), and sane limits.
pub(super) fn check_limits(
    opts: &OffsetOptions,
    scale: f64,
    margin: f64,
) -> Result<(), OffsetError> {
    let tol = opts.tol.value();
    let min = MIN_REL_TOL * (1.0 + scale);
    if tol - margin < min {
        let less = if margin > 0.0 {
            format!(" (less the pen's rotation margin {margin:e})")
        } else {
            String::new()
        };
        return Err(bad(
            "tol",
            format!(
                "{:e}{less} is below {:e} = 1e-11 × (1 + coordinate scale): float control points cannot resolve it",
                opts.tol.approx(), min
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
        fit::check_grid(g, tol - margin, scale)?;
    }
    Ok(())
}
