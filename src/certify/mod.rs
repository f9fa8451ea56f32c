//! Certified Hausdorff bounds and tolerance certificates.
//!
//! [`hausdorff`] returns rigorous bounds `lo ≤ d_H(A, B) ≤ hi` between two
//! [`ShapeDesc`]s — polynomial Bézier curves (piecewise, any degree), circular
//! arcs, exact offsets `x + r N` of polynomial curves and exact convolutions of
//! polynomial curves with ellipses — with both one-sided distances
//! `h(A, B) = sup_{a∈A} dist(a, B)` and `h(B, A)` bounded separately
//! (`d_H = max(h(A, B), h(B, A))`). A circular arc against a curve inside its
//! sector from one end ray to the other has `d_H` computed as the curve's
//! largest radial distance to the circle ([`RadialProof`]). Otherwise upper
//! bounds come from interval branch and bound over the parameter domains
//! (second-order Taylor forms, see [`Config`]),
//! lower bounds from witness points whose distance is bounded below by a second
//! branch and bound. Nothing is sampled: every figure is an outward-rounded
//! interval bound.
//!
//! When a tolerance is certified, [`Certificate`] records the inputs exactly,
//! the claim and the proof: the parametric map ([`Parametric`]) or the search's
//! final parameter boxes with their foot maps; [`verify`](verify::verify)
//! re-checks it without searching, with its own evaluation code (it shares
//! only the scalar layer with the proofs).
//!
//! # Examples
//! ```
//! use lncert::certify::{hausdorff, Config};
//! use lncert::shape::ShapeDesc;
//! // The quadratic (0,0), (1/2, 1/2), (1, 0) against the segment (0,0)-(1,0):
//! // the farthest point is B(1/2) = (1/2, 1/4), at distance 1/4 from the segment.
//! let a = ShapeDesc::parse(r#"{"bezier": [[0, 0], ["1/2", "1/2"], [1, 0]]}"#).unwrap();
//! let b = ShapeDesc::parse("M 0 0 L 1 0").unwrap();
//! let r = hausdorff(&a, &b, &Config { rel: 1e-6, ..Config::default() }).unwrap();
//! assert!(r.lo <= 0.25 && 0.25 <= r.hi && r.hi - r.lo <= 1e-6 * r.hi);
//! ```

mod arcquad;
mod bern;
mod cert;
mod jet;
mod param;
pub(crate) mod piece;
mod radial;
mod same;
pub(crate) mod search;
pub mod verify;

use crate::shape::ShapeDesc;
use piece::Pieces;

pub use arcquad::circular_arc_quadratics;
pub use cert::{Certificate, MapCover};
pub use param::{ParamBox, Parametric};
pub use radial::{RadialCell, RadialProof};
pub use same::{verify_against, verify_expecting, Expected};

pub use search::{Config, CoverBox, OneSided};

/// Errors of the certification layer: the offending field and the reason —
/// lncert's one input error, [`crate::Error`].
pub type CertifyError = crate::Error;

/// Certified bounds on the Hausdorff distance and on both one-sided distances.
#[derive(Clone, Debug, PartialEq)]
pub struct HausdorffBounds {
    /// `lo ≤ d_H(A, B) ≤ hi`.
    pub lo: f64,
    /// Certified upper bound on `d_H(A, B)`.
    pub hi: f64,
    /// Bounds on `h(A, B) = sup_{a∈A} dist(a, B)`.
    pub a_to_b: OneSided,
    /// Bounds on `h(B, A)`.
    pub b_to_a: OneSided,
    /// The parametric proof of `hi` when that path decided (then both
    /// one-sided results are `[0, hi]` with no boxes, and `lo` is 0).
    pub parametric: Option<param::Parametric>,
    /// The radial proof when that path decided (an arc against a chain of
    /// pieces in its sector: `d_H` is the curve's largest radial distance; no
    /// boxes: [`Certificate::new`] proves the claim again by the other proofs).
    pub radial: Option<RadialProof>,
}

impl HausdorffBounds {
    /// True if the search stopped on its budget or the float resolution.
    pub fn incomplete(&self) -> bool {
        self.a_to_b.incomplete || self.b_to_a.incomplete
    }
}

fn check_config(cfg: &Config) -> Result<(), CertifyError> {
    let bad = |field: &str, reason: &str| {
        Err(CertifyError {
            field: field.to_string(),
            reason: reason.to_string(),
        })
    };
    if !(cfg.rel.is_finite() && cfg.rel > 0.0 && cfg.rel < 1.0) {
        return bad("rel", "must be a number in (0, 1)");
    }
    if cfg.rel < 1e-12 {
        return bad(
            "rel",
            "below 1e-12 the f64 end points of the bounds cannot resolve the gap",
        );
    }
    if !(cfg.abs.is_finite() && cfg.abs >= 0.0) {
        return bad("abs", "must be a finite number ≥ 0");
    }
    if cfg.max_boxes == 0 {
        return bad("max_boxes", "must be ≥ 1");
    }
    Ok(())
}

/// An **unproven** float estimate of `d_H(A, B)`: the larger of the two
/// one-sided sampled maxima (`samples + 1` points per piece, float foot points on
/// the other shape). Not a bound — it can be below the true distance; lncert uses
/// it only where the user asked for no proof (`lncert offset --no-certify`), and
/// labels it unproven there.
///
/// # Examples
/// ```
/// use lncert::certify::sampled_estimate;
/// use lncert::shape::ShapeDesc;
/// let a = ShapeDesc::parse("M 0 0 Q 0.5 0.5 1 0").unwrap();
/// let b = ShapeDesc::parse("M 0 0 L 1 0").unwrap();
/// let e = sampled_estimate(&a, &b, 32).unwrap();
/// assert!((e - 0.25).abs() < 1e-9); // the sample hits the maximum at t = 1/2
/// ```
pub fn sampled_estimate(a: &ShapeDesc, b: &ShapeDesc, samples: usize) -> Result<f64, CertifyError> {
    let (pa, pb) = (a.pieces()?, b.pieces()?);
    Ok(sampled_pieces(&pa, &pb, samples))
}

/// Certified bounds on `d_H(A, B)`.
///
/// Stops when `hi − lo ≤ max(rel · hi, abs)` — or, with `cfg.tol`, when the
/// tolerance is decided (`hi ≤ tol` or `lo > tol`) — or when the box budget is spent (then
/// [`HausdorffBounds::incomplete`] is true; the bounds are sound anyway).
pub fn hausdorff(
    a: &ShapeDesc,
    b: &ShapeDesc,
    cfg: &Config,
) -> Result<HausdorffBounds, CertifyError> {
    check_config(cfg)?;
    // (the coordinate scale converts every rational: only computed when used)
    let abs_of = || {
        if cfg.abs > 0.0 {
            cfg.abs
        } else {
            1e-10 * (1.0 + a.scale().max(b.scale()))
        }
    };
    // an arc and a curve in its sector: the distance computed
    if cfg.parametric && cfg.radial {
        let goal = match &cfg.tol {
            Some(t) => radial::Goal::Tol(t.value()),
            None => radial::Goal::Gap(cfg.rel),
        };
        // its halvings count against the box budget
        if let Some(p) = radial::prove(a, b, goal, &abs_of, cfg.max_boxes) {
            return Ok(radial_bounds(p));
        }
    }
    let pa = a.pieces()?;
    let pb = b.pieces()?;
    Ok(hausdorff_pieces(&pa, &pb, cfg, &abs_of))
}

/// The bounds of a radial proof: `h(curve, arc) ∈ [lo, hi]` (the witness a
/// point of the curve), `h(arc, curve) ≤ hi`.
fn radial_bounds(p: RadialProof) -> HausdorffBounds {
    let side = |lo, witness| OneSided {
        lo,
        hi: p.hi,
        witness,
        boxes: Vec::new(),
        evaluated: p.splits,
        incomplete: false,
    };
    let (curve, arc) = (side(p.lo, Some(p.witness)), side(0.0, None));
    let (a_to_b, b_to_a) = if p.curve_is_a {
        (curve, arc)
    } else {
        (arc, curve)
    };
    HausdorffBounds {
        lo: p.lo,
        hi: p.hi,
        a_to_b,
        b_to_a,
        parametric: None,
        radial: Some(p),
    }
}

/// [`hausdorff`] with **each** one-sided distance bounded to the goal
/// (`rel`, or `tol`), not only the larger one: [`hausdorff`] stops the smaller
/// direction as soon as it cannot change `d_H`, which leaves it coarse. Here
/// both searches run on their own (no parametric shortcut); for callers that
/// report `h(A, B)` and `h(B, A)` separately, such as the stroke referee.
///
/// # Examples
/// ```
/// use lncert::certify::{hausdorff_each_direction, Config};
/// use lncert::shape::ShapeDesc;
/// let a = ShapeDesc::parse("M 0 0 L 4 0").unwrap();
/// let b = ShapeDesc::parse("M 0 1 L 2 1").unwrap();
/// let r = hausdorff_each_direction(&a, &b, &Config::default()).unwrap();
/// // h(A, B) = |(4, 0) − (2, 1)| = √5, h(B, A) = 1: both bounded to 1e-3
/// assert!(r.a_to_b.lo <= 5f64.sqrt() && 5f64.sqrt() <= r.a_to_b.hi);
/// assert!(r.b_to_a.lo <= 1.0 && 1.0 <= r.b_to_a.hi && r.b_to_a.hi - r.b_to_a.lo <= 1e-3);
/// ```
pub fn hausdorff_each_direction(
    a: &ShapeDesc,
    b: &ShapeDesc,
    cfg: &Config,
) -> Result<HausdorffBounds, CertifyError> {
    check_config(cfg)?;
    let (pa, pb) = (a.pieces()?, b.pieces()?);
    let abs = if cfg.abs > 0.0 {
        cfg.abs
    } else {
        1e-10 * (1.0 + a.scale().max(b.scale()))
    };
    let ab = search::one_sided(&pa, &pb, cfg, abs, (0.0, 0.0));
    let ba = search::one_sided(&pb, &pa, cfg, abs, (0.0, 0.0));
    Ok(HausdorffBounds {
        lo: ab.lo.max(ba.lo),
        hi: ab.hi.max(ba.hi),
        a_to_b: ab,
        b_to_a: ba,
        parametric: None,
        radial: None,
    })
}

/// An elliptic arc `center + M·(the unit-circle arc counter-clockwise from the
/// direction `from` to the direction `to`)` — the directions are those of the
/// pre-image, of any nonzero length, not the same direction. Seed 001's pen
/// segments are such arcs (`center` 0, `M` the pen). Not a shape of the
/// certificate language: [`hausdorff_ellipse_arc`] bounds distances to it.
#[derive(Clone, Debug, PartialEq)]
pub struct EllipseArc {
    /// The ellipse's centre.
    pub center: crate::curve::V2<crate::scalar::Rational>,
    /// `M` by rows (`det M ≠ 0`).
    pub m: [[crate::scalar::Rational; 2]; 2],
    /// The pre-image direction of the start.
    pub from: crate::curve::V2<crate::scalar::Rational>,
    /// The pre-image direction of the end.
    pub to: crate::curve::V2<crate::scalar::Rational>,
}

/// Certified bounds on `d_H(arc, curve)` for an elliptic arc and a piecewise
/// polynomial curve: the same proofs as [`hausdorff`] (the arc parametrised
/// by `c + M u(t)`, `u(t)` the rational unit-circle parametrisation of the
/// arcs, with the outer/inner end-parameter domains).
///
/// # Examples
/// ```
/// use lncert::certify::{hausdorff_ellipse_arc, Config, EllipseArc};
/// use lncert::curve::{Bezier, V2};
/// let q = |s: &str| lncert::parse_rational(s).unwrap();
/// // the quarter of the ellipse x²/4 + y² = 1 from (2, 0) to (0, 1) against its chord
/// let arc = EllipseArc { center: V2::new(q("0"), q("0")), m: [[q("2"), q("0")], [q("0"), q("1")]],
///                        from: V2::new(q("1"), q("0")), to: V2::new(q("0"), q("1")) };
/// let chord = Bezier::new(vec![V2::new(q("2"), q("0")), V2::new(q("0"), q("1"))]);
/// let r = hausdorff_ellipse_arc(&arc, &[chord], &Config::default()).unwrap();
/// // the farthest point of the arc from the chord: (√2, √2/2), at distance (2√2 − 2)/√5
/// let exact = (2.0 * 2f64.sqrt() - 2.0) / 5f64.sqrt();
/// assert!(r.lo <= exact && exact <= r.hi);
/// ```
pub fn hausdorff_ellipse_arc(
    arc: &EllipseArc,
    curve: &[crate::curve::Bezier<crate::scalar::Rational>],
    cfg: &Config,
) -> Result<HausdorffBounds, CertifyError> {
    use num_traits::Zero;
    check_config(cfg)?;
    let m = &arc.m;
    if (&m[0][0] * &m[1][1] - &m[0][1] * &m[1][0]).is_zero() {
        return Err(CertifyError {
            field: "arc.m".into(),
            reason: "the matrix is singular".into(),
        });
    }
    let shape = ShapeDesc::curve(curve.to_vec())?;
    for v in [&arc.from, &arc.to] {
        if v.x.is_zero() && v.y.is_zero() {
            return Err(CertifyError {
                field: "arc.from".into(),
                reason: "a direction is zero".into(),
            });
        }
    }
    let pa = vec![piece::Piece::ellipse_arc(
        &arc.center,
        m,
        &arc.from,
        &arc.to,
    )?];
    let pb = shape.pieces()?;
    let scale = {
        use crate::scalar::Scalar;
        let c = arc.center.x.approx().abs().max(arc.center.y.approx().abs());
        let mm: f64 = m.iter().flatten().map(|x| x.approx().abs()).sum();
        c + mm + shape.scale()
    };
    let abs_of = || {
        if cfg.abs > 0.0 {
            cfg.abs
        } else {
            1e-10 * (1.0 + scale)
        }
    };
    Ok(hausdorff_pieces(&pa, &pb, cfg, &abs_of))
}

/// [`hausdorff`] on pieces built by the caller (`cfg` already checked);
/// `abs_of` gives the absolute gap, called only when it is used.
pub(crate) fn hausdorff_pieces(
    pa: &[piece::Piece],
    pb: &[piece::Piece],
    cfg: &Config,
    abs_of: &dyn Fn() -> f64,
) -> HausdorffBounds {
    // a tolerance goal does not use the absolute gap
    let gap_abs = if cfg.tol.is_some() { 0.0 } else { abs_of() };
    if let Some(r) = parametric_path(pa, pb, cfg, gap_abs) {
        return r;
    }
    let abs = abs_of();
    let ab = search::one_sided(pa, pb, cfg, abs, (0.0, 0.0));
    let refuted = cfg.tol.as_ref().is_some_and(|t| ab.lo > t.value());
    let ba = if refuted && cfg.verdict_only {
        OneSided {
            lo: 0.0,
            hi: f64::INFINITY,
            witness: None,
            boxes: Vec::new(),
            evaluated: 0,
            incomplete: true,
        }
    } else if refuted {
        // already refuted: the other direction is not needed for the verdict, but its
        // bounds are still reported (coarse).
        search::one_sided(
            pb,
            pa,
            &Config {
                rel: 0.5,
                tol: None,
                ..cfg.clone()
            },
            abs,
            (ab.lo, ab.hi),
        )
    } else {
        search::one_sided(pb, pa, cfg, abs, (ab.lo, ab.hi))
    };
    HausdorffBounds {
        lo: ab.lo.max(ba.lo),
        hi: ab.hi.max(ba.hi),
        a_to_b: ab,
        b_to_a: ba,
        parametric: None,
        radial: None,
    }
}

/// The unproven sampled estimate of [`sampled_estimate`] on pieces.
pub(crate) fn sampled_pieces(pa: &[piece::Piece], pb: &[piece::Piece], samples: usize) -> f64 {
    let samples = samples.clamp(1, 4096);
    search::sampled_one_sided(pa, pb, samples).max(search::sampled_one_sided(pb, pa, samples))
}

/// The parametric proof where it applies (one piece each, one of them with
/// an exact parameter domain; see [`param`]): for `cfg.tol`, or for the
/// relative gap `cfg.rel` with witness lower bounds.
fn parametric_path(
    pa: &[piece::Piece],
    pb: &[piece::Piece],
    cfg: &Config,
    abs: f64,
) -> Option<HausdorffBounds> {
    if !cfg.parametric || pa.len() != 1 || pb.len() != 1 {
        return None;
    }
    let goal = match &cfg.tol {
        Some(t) => param::Goal::Tol(t.value()),
        None => param::Goal::Gap { rel: cfg.rel, abs },
    };
    let (a, b) = (&pa[0], &pb[0]);
    let budget = cfg.max_boxes.min(PARAMETRIC_BOXES);
    // the parametrised side needs an exact domain: a polynomial piece
    let (mut p, swapped) = if b.inner == b.outer {
        (param::prove(a, b, goal, budget)?, false)
    } else if a.inner == a.outer {
        (param::prove(b, a, goal, budget)?, true)
    } else {
        return None;
    };
    p.source_a = swapped;
    // the witness is a point of the parametrised side, at distance ≥ lo from the other
    let side = |evaluated, lo, witness: Option<f64>| OneSided {
        lo,
        hi: p.hi,
        witness: witness.map(|t| (0, t)),
        boxes: Vec::new(),
        evaluated,
        incomplete: false,
    };
    let (ab, ba) = if swapped {
        (side(p.evaluated, p.lo, p.witness), side(0, 0.0, None))
    } else {
        (side(p.evaluated, 0.0, None), side(0, p.lo, p.witness))
    };
    Some(HausdorffBounds {
        lo: p.lo,
        hi: p.hi,
        a_to_b: ab,
        b_to_a: ba,
        parametric: Some(p),
        radial: None,
    })
}

/// Box budget of the parametric proof before the search takes over.
const PARAMETRIC_BOXES: usize = 2_000;
