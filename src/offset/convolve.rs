//! [`convolve`]: the convolution with an elliptical pen, driven like an
//! offset, and seed 000 §5's error measure of its LN pairs.

use super::driver::{offset_segments, Kernel};
use super::fit::Output;
use super::options::{bad, check_limits, OffsetError, OffsetMethod, OffsetOptions};
use super::results::{exact_bezier, ConvSide, OffsetResult};
use super::{conv, lnpair};
use crate::certify::{hausdorff, Config};
use crate::curve::{Bezier, V2};
use crate::scalar::{interval_from_rational, rational_from_f64, Interval, IntervalExt, Rational};
use crate::shape::ShapeDesc;
use crate::Tolerance;
use num_traits::Zero;
use rayon::prelude::*;

/// Approximates the convolution `x ∗ e_σ` of a piecewise polynomial curve with
/// an elliptical pen on side `side` (`+1`: left of the travel direction, `−1`:
/// right) within `opts.tol`, by seed 001's G²/C¹ method ([`OffsetMethod::G2`],
/// degree `n + 3`) or seed 000 §5's cubic LN pairs ([`OffsetMethod::LnPair`]:
/// [`lnpair::ln_pair_pen`], split at the mid-angle, rule (a); `opts.distance`
/// is not used, and the paper's error measure is not evaluated), proving every segment
/// against the exact convolution (see [`Pen`](super::Pen) and [`super::kernels::convolution_approximant_f64`]). The trajectory is split first
/// at the side's own cusps (exact), then at inflections and turns.
///
/// When the pen's rotation was represented approximately, the segments are
/// certified within `tol − pen.margin` for the exact pen used, so that `tol`
/// holds for the pen as given ([`ConvSide::certified_tol`]).
///
/// # Examples
/// ```
/// use lncert::offset::{convolve, Angle, OffsetOptions, Pen};
/// use lncert::shape::parse_curve;
/// let q = |s: &str| lncert::parse_rational(s).unwrap();
/// let x = parse_curve("M 0 0 C 1 0.2 2 1 2.4 2.5").unwrap();
/// let pen = Pen::ellipse(&q("0.3"), &q("0.1"), &Angle::parse("pi/6").unwrap()).unwrap();
/// let r = convolve(&x, &pen, 1, &OffsetOptions::new(q("0"), "1e-4".parse().unwrap())).unwrap();
/// assert!(r.reached() && r.certified_hi <= r.tol.value());
/// // the pen's rotation is represented within a margin: certified below tol
/// assert!(r.certified_tol().exact() < r.tol.exact());
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
    // tol − margin rounded down (a bound ≤ it plus the margin is ≤ tol)
    let inner_tol = if pen.margin == 0.0 {
        opts.tol.clone()
    } else {
        let below = match (
            Interval::point(opts.tol.value()),
            Interval::point(pen.margin),
        ) {
            (Some(t), Some(m)) => (t - m).inf(),
            _ => f64::NAN,
        };
        Tolerance::from_f64(below)?
    };
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
        tol: inner_tol.clone(),
        ..opts.clone()
    };
    let (segments, unreached, certified_hi, certifications, spans) =
        offset_segments(curve, &inner, &kernel, &cuts);
    Ok(OffsetResult {
        method: opts.method,
        distance: <Rational as Zero>::zero(),
        tol: opts.tol.clone(),
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
            certified_tol: inner_tol,
        }),
    })
}

/// Seed 000 §5's error measure `d_H(p, pa) + d_H(q, qa)` of an LN pair of a
/// convolution, bounded above with certified bounds: `p` the exact span,
/// `q` the pen's elliptic arc between the compatible points (pre-image
/// directions `σ Mᵀ n(t₀)`, `σ Mᵀ n(t₁)`, `n` the exact left normal). `None`
/// for a straight span (the pen arc is a point) or when a bound fails.
pub(super) fn conv_paper_error(
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
