//! The stroke certificate (format `lncert-stroke-certificate`, version 1) and
//! its independent checker: **an outline `L` lies within `tol` of the exact
//! boundary `∂S` of the stroke `S = x ⊕ disk(r)`, in Hausdorff distance, and
//! its contours are closed.** The argument is in `proofs/stroke-certificate.md`.
//!
//! ```text
//! {
//!   "format": "lncert-stroke-certificate", "version": 1,
//!   "claim": "hausdorff(outline, boundary(curve + disk(radius))) <= tol",
//!   "tol": Q, "radius": Q,                     exact, > 0
//!   "curve": [CURVE_PIECE, ...],               the input x
//!   "outline": [[PIECE, ...], ...],            closed contours, consecutive pieces sharing
//!                                              exact end points
//!   "cover": [[[PART, ...], ...], ...],        per contour, per piece: its parts in order
//!   "boundary": [{"of": NAME, "boxes": [BOX, ...]}, ...],
//!   "simple": BOOL                             claim (c): simple, disjoint contours
//! }
//! ```
//!
//! **An elliptical pen** `E = M · disk(1)`: `"pen": {"ellipse": [[m11, m12],
//! [m21, m22]]}` (exact, `det M ≠ 0`) in place of `"radius"`, claim
//! `hausdorff(outline, boundary(curve + ellipse(pen))) <= tol`. Since
//! `x ⊕ E = M (M⁻¹x ⊕ disk(1))`, the verifier maps `curve` and `outline` by
//! `M⁻¹` exactly (Bézier pieces only: an exact arc is refused) and checks
//! `cover`, `boundary` and `simple` below for the disk of radius 1: the parts
//! at `t′ = inf(tol / ‖M‖₂)` (outward enclosure of the norm), so
//! `h(L → ∂S) ≤ ‖M‖₂ h(M⁻¹L → ∂(M⁻¹x ⊕ disk(1))) ≤ tol`; the boxes' near
//! tests through `M` (`|M (F′ − L′)| = |F − L| ≤ tol`). Orientations are
//! stated for `L` (those of `M⁻¹L` times `sign det M`).
//!
//! ```text
//! CURVE_PIECE = [[Q, Q], ...]                 a Bézier (degree ≥ 1, nonzero end tangents)
//!       | {"arc": {"center": [Q, Q], "radius": Q, "from": [Q, Q], "to": [Q, Q], "clockwise": BOOL}}
//!                                              an exact arc turning by more than 0 and less
//!                                              than π from `from` to `to` (ends exactly on
//!                                              the circle; a circular pen only)
//! PIECE = {"bezier": [[Q, Q], ...]}
//!       | {"arc": {"center": [Q, Q], "radius": Q, "from": [Q, Q], "to": [Q, Q], "clockwise": BOOL}}
//!                                              (ends exactly on the circle; from = to: the whole circle)
//! PART  = {"s": [Q, Q], "o": IN, "w": OUT}             (a Bézier's parameter range)
//!       | {"dirs": [[Q, Q], [Q, Q]], "o": IN, "w": OUT}  (an arc's radius directions)
//! IN    = {"piece": j, "u": Q}                          the disk B(x_j(u), r) ⊆ S
//!       | {"segment": j}                                the capsule of radius r about the
//!                                              segment x_j(0) x_j(1), piece j straight
//! OUT   = {"at": [Q, Q], "mu": Q}                       the disk B(at, mu) outside S
//! BOX   = {"t": [Q, Q], "near": {"contour": c, "piece": i, "s": Q, "k": Q}}   (a Bézier)
//!       | {"t": [Q, Q], "near": {"contour": c, "piece": i}}                   (an arc)
//!       | {"t": [Q, Q], "inside": {"piece": j, "u": Q}}
//! ```
//!
//! **(a) every point of `L` is within `tol` of `∂S`.** Each part of a piece
//! (a parameter range, or a counter-clockwise sub-arc of less than `π/2`)
//! carries a set in `S` (the disk `B(y, r)`, `y = x_j(u)` a point of the
//! curve; or, for a straight input piece — control points exactly on the line
//! through its end points — the capsule of radius `r` about the segment
//! between its end points, which its image holds) and a
//! disk outside `S` (`B(w, μ)`: `|w − x(u)|² − (r + μ)² > 0` on every input
//! piece, Bernstein signs; for an arc, `w` farther than `r + μ` from its whole
//! circle, or outside its sector with both ends farther). For a point `q`, the segment between the two
//! disks' points nearest to `q` meets `∂S`, so `q` is within
//! `max(|q − y| − r, |q − w| − μ, 0)` of `∂S`; that maximum over the part's
//! hull (the restricted control points, or the sub-arc's tangent triangle)
//! must be `≤ tol`. Both distances grow only quadratically along `∂S` away
//! from where the disks touch it, so a part may be about `√(tol·r)` long.
//! The parts chain over each piece exactly (rational comparisons).
//!
//! **(b) every point of `∂S` is within `tol` of `L`.** `∂S` lies in the exact
//! offsets `x_j ± r N` of the input pieces (for an arc of centre `c` and
//! radius `ρ`: the concentric arcs of radii `ρ ∓ r` over its directions) and the arcs of radius `r` about
//! the input's vertices in their normal cones (caps at open ends, joins at
//! corners) — the verifier derives this list (`NAME`s `piece j left|right`,
//! `start j a|b`, `end j a|b`) from `curve` alone. Each is covered over its
//! parameter `[0, 1]` by boxes that are either within `tol` of one outline
//! piece (a linear foot map into a Bézier, or directions inside an arc's range)
//! or **strictly inside** `S` (within less than `r` of an input point: not on
//! `∂S`). Crossings of the raw boundary need no exact parameter: near one the
//! boxes on the removed branch are still near the outline, then inside.
//!
//! **(c) with `"simple": true`: the contours are simple and pairwise disjoint**
//! (consecutive pieces meet only at their shared end) and each has a decided
//! orientation, checked by the verifier's own search over the parts of (a)
//! (`simple.rs`); the statement then gives the orientations.
//!
//! Every number is a canonical exact rational; unknown or duplicate keys are
//! refused; every failure names its field.

pub(crate) mod geom;
mod simple;
pub(crate) use simple::{simple as simple_check, Span};

use super::index::{BoxIndex, FBox};
use super::read::{canonical_index, canonical_rational, exact_object, join};
use super::{inv, Budget, Invalid, Valid};
use crate::json::Json;
use crate::scalar::Rational;
use crate::shape::io::{MAX_CONTROL_POINTS, MAX_SEGMENTS};
use geom::{
    arc_hull, inside, ip, iq, near_arc, near_bezier, outside_arc, outside_bez, part_bound, ArcT,
    Bez, BoxT, ConeArc, Core, Path, Side, P,
};
use num_traits::{Signed, ToPrimitive, Zero};
use rayon::prelude::*;

/// Format name in the `format` field.
pub const FORMAT: &str = "lncert-stroke-certificate";
/// Current format version.
pub const VERSION: u64 = 1;
/// The claim of this format.
pub const CLAIM: &str = "hausdorff(outline, boundary(curve + disk(radius))) <= tol";
/// The format of a stroke distance certificate: `d_H(X, ∂S) ≤ tol` for any
/// shape `X`, through a proven outline `L` — a Hausdorff certificate of
/// `d_H(X, L) ≤ tol₁` and a stroke certificate of `d_H(L, ∂S) ≤ tol₂` about
/// the same `L` (exact geometry), with `tol₁ + tol₂ ≤ tol` (triangle inequality).
///
/// ```text
/// {"format": "lncert-stroke-distance-certificate", "version": 1,
///  "claim": "hausdorff(shape, boundary(curve + disk(radius))) <= tol", "tol": Q,
///  "shape_to_outline": HAUSDORFF_CERTIFICATE,     a = X, b = L
///  "outline_to_stroke": STROKE_CERTIFICATE}       outline = L
/// ```
pub const DISTANCE_FORMAT: &str = "lncert-stroke-distance-certificate";
/// The claim of a stroke distance certificate.
pub const DISTANCE_CLAIM: &str = "hausdorff(shape, boundary(curve + disk(radius))) <= tol";
/// The format of a set of stroke certificates: one per stroked element of an
/// SVG document (each element its own curve and pen), every member a stroke
/// certificate checked on its own.
///
/// ```text
/// {"format": "lncert-stroke-certificate-set", "version": 1,
///  "claim": "every member's claim holds",
///  "members": [{"at": LABEL, "certificate": STROKE_CERTIFICATE}, ...]}
/// ```
///
/// Valid: for each member `k`, `d_H(L_k, ∂S_k) ≤ tol_k`; the statement's
/// `tol` is the largest, and `d_H(∪ L_k, ∪ ∂S_k) ≤ max tol_k` follows. The
/// labels are the writer's (e.g. `svg/path[2]`), not checked.
pub const SET_FORMAT: &str = "lncert-stroke-certificate-set";
/// The claim of a certificate set.
pub const SET_CLAIM: &str = "every member's claim holds";
/// Most members of a certificate set.
pub const MAX_SET_MEMBERS: usize = 4096;

/// Checks a set of stroke certificates: each member on its own.
pub(crate) fn check_set(doc: &Json, budget: &Budget) -> Result<Valid, Invalid> {
    let [_f, version, claim, members] =
        exact_object(doc, "", ["format", "version", "claim", "members"])?;
    if !matches!(version, Json::Number(v) if *v == VERSION.to_string()) {
        return Err(inv(
            "version",
            format!("this verifier reads version {VERSION} of {SET_FORMAT}"),
        ));
    }
    if claim.as_str() != Some(SET_CLAIM) {
        return Err(inv("claim", format!("expected \"{SET_CLAIM}\"")));
    }
    let ms = arr(members, "members", "members")?;
    if ms.is_empty() || ms.len() > MAX_SET_MEMBERS {
        return Err(inv(
            "members",
            format!(
                "expected 1 to {MAX_SET_MEMBERS} members, found {}",
                ms.len()
            ),
        ));
    }
    let mut labels = Vec::new();
    let mut out: Option<Valid> = None;
    for (k, m) in ms.iter().enumerate() {
        let at = format!("members[{k}]");
        let [label, cert] = exact_object(m, &at, ["at", "certificate"])?;
        let label = label
            .as_str()
            .ok_or_else(|| inv(join(&at, "at"), "expected a string label"))?;
        if cert.get("format").and_then(|f| f.as_str()) != Some(FORMAT) {
            return Err(inv(
                format!("{at}.certificate.format"),
                format!("expected \"{FORMAT}\""),
            ));
        }
        let v = check(cert, budget).map_err(|e| {
            let w = format!("{at}.certificate");
            inv(if e.at.is_empty() { w } else { join(&w, &e.at) }, e.reason)
        })?;
        labels.push(label.to_string());
        out = Some(match out {
            None => v,
            Some(o) => Valid {
                tol: if v.tol > o.tol { v.tol } else { o.tol },
                a: o.a,
                b: o.b,
                max_bound: o.max_bound.max(v.max_bound),
                boxes: o.boxes + v.boxes,
            },
        });
    }
    let mut v = out.expect("at least one member");
    let shown = labels
        .iter()
        .take(8)
        .cloned()
        .collect::<Vec<_>>()
        .join(", ");
    let more = if labels.len() > 8 { ", …" } else { "" };
    v.a = format!(
        "the outlines of {} stroked element(s) ({shown}{more}, as labelled by the writer), each proven on its own",
        labels.len()
    );
    v.b = "the boundaries of their strokes, each element's ∂(x_k ⊕ pen_k) with its own curve and pen (d_H of the unions ≤ the largest member tolerance)".to_string();
    Ok(v)
}

/// The claim of a stroke distance certificate whose stroke certificate is
/// of an elliptical pen.
pub const DISTANCE_CLAIM_ELLIPSE: &str = "hausdorff(shape, boundary(curve + ellipse(pen))) <= tol";
/// Its keys, in the order the writer writes them.
pub const DISTANCE_KEYS: [&str; 6] = [
    "format",
    "version",
    "claim",
    "tol",
    "shape_to_outline",
    "outline_to_stroke",
];

/// Checks a stroke distance certificate: both parts valid, about the same
/// outline, tolerances adding up to at most `tol`.
pub(crate) fn check_distance(doc: &Json, budget: &Budget) -> Result<Valid, Invalid> {
    let [_f, version, claim, tol, h, st] = exact_object(doc, "", DISTANCE_KEYS)?;
    if !matches!(version, Json::Number(v) if *v == VERSION.to_string()) {
        return Err(inv(
            "version",
            format!("this verifier reads version {VERSION} of {DISTANCE_FORMAT}"),
        ));
    }
    let want = if st.get("pen").is_some() {
        DISTANCE_CLAIM_ELLIPSE
    } else {
        DISTANCE_CLAIM
    };
    if claim.as_str() != Some(want) {
        return Err(inv(
            "claim",
            format!("expected \"{want}\" (the pen of outline_to_stroke)"),
        ));
    }
    let tol = canonical_rational(tol, "tol")?;
    fn nest(at: &'static str) -> impl Fn(Invalid) -> Invalid {
        move |e| {
            let w = if e.at.is_empty() {
                at.to_string()
            } else {
                join(at, &e.at)
            };
            inv(w, e.reason)
        }
    }
    let vh = super::check_hausdorff_document(h, budget).map_err(nest("shape_to_outline"))?;
    if st.get("format").and_then(|f| f.as_str()) != Some(FORMAT) {
        return Err(inv(
            "outline_to_stroke.format",
            format!("expected \"{FORMAT}\""),
        ));
    }
    let vs = check(st, budget).map_err(nest("outline_to_stroke"))?;
    if &vh.tol + &vs.tol > tol {
        return Err(inv(
            "tol",
            format!(
                "the parts prove {} + {} = {}, more than the claimed {tol}",
                vh.tol,
                vs.tol,
                &vh.tol + &vs.tol
            ),
        ));
    }
    // the Hausdorff certificate's b must be the stroke certificate's outline
    let b = h
        .get("b")
        .ok_or_else(|| inv("shape_to_outline.b", "missing"))?
        .to_value();
    let b = crate::shape::ShapeDesc::from_value(&b)
        .map_err(|e| inv("shape_to_outline.b", e.to_string()))?;
    let (outline, _) = shapes(st).map_err(nest("outline_to_stroke"))?;
    b.same_as(&outline).map_err(|why| {
        inv(
            "shape_to_outline.b",
            format!("not the stroke certificate's outline: {why}"),
        )
    })?;
    Ok(Valid {
        tol,
        a: vh.a,
        b: vs.b,
        max_bound: (vh.max_bound + vs.max_bound).next_up(),
        boxes: vh.boxes + vs.boxes,
    })
}

/// The top-level keys, in the order the writer writes them.
pub const KEYS: [&str; 10] = [
    "format", "version", "claim", "tol", "radius", "curve", "outline", "cover", "boundary",
    "simple",
];

/// The claim of a certificate for an elliptical pen `E = M · disk(1)`.
pub const CLAIM_ELLIPSE: &str = "hausdorff(outline, boundary(curve + ellipse(pen))) <= tol";
/// The top-level keys of a certificate for an elliptical pen: `"pen"`
/// (`{"ellipse": [[m11, m12], [m21, m22]]}`) in place of `"radius"`.
pub const KEYS_ELLIPSE: [&str; 10] = [
    "format", "version", "claim", "tol", "pen", "curve", "outline", "cover", "boundary", "simple",
];

/// An elliptical pen `E = M · disk(1)` read exactly: `M`, its inverse, and
/// the stroke tolerance `t′` at which the pre-image `M⁻¹ L` is checked
/// against `∂(M⁻¹ x ⊕ disk(1))` so that `‖M‖₂ · t′ ≤ tol`.
pub(crate) struct PenMap {
    pub(crate) m: [Q2; 2],
    pub(crate) inv: [Q2; 2],
    pub(crate) det_negative: bool,
    /// A proven upper bound of `‖M‖₂`.
    pub(crate) norm_sup: f64,
}

impl PenMap {
    /// Reads `{"ellipse": [[m11, m12], [m21, m22]]}` (rows, exact, `det M ≠ 0`).
    pub(crate) fn read(v: &Json) -> Result<PenMap, Invalid> {
        let [e] = exact_object(v, "pen", ["ellipse"])?;
        let rows = arr(e, "pen.ellipse", "2 rows")?;
        if rows.len() != 2 {
            return Err(inv(
                "pen.ellipse",
                "expected 2 rows [[m11, m12], [m21, m22]]",
            ));
        }
        let r0 = point(&rows[0], &|| "pen.ellipse[0]".to_string())?;
        let r1 = point(&rows[1], &|| "pen.ellipse[1]".to_string())?;
        PenMap::new([r0, r1]).ok_or_else(|| inv("pen.ellipse", "a singular matrix (det M = 0)"))
    }

    /// `M` by rows; `None` when `det M = 0`.
    pub(crate) fn new(m: [Q2; 2]) -> Option<PenMap> {
        let det = &m[0][0] * &m[1][1] - &m[0][1] * &m[1][0];
        if det.is_zero() {
            return None;
        }
        let inv = [
            [&m[1][1] / &det, -&m[0][1] / &det],
            [-&m[1][0] / &det, &m[0][0] / &det],
        ];
        // ‖M‖₂² = (s + √(s² − 4 det²)) / 2, s the squared Frobenius norm
        let s = m
            .iter()
            .flatten()
            .map(|x| {
                let xi = iq(x);
                xi * xi
            })
            .fold(iq(&Rational::zero()), |a, b| a + b);
        let d = iq(&det);
        let disc = (s * s - iq(&Rational::from_integer(4.into())) * d * d)
            .intersection(crate::scalar::Interval::try_from((0.0, f64::INFINITY)).ok()?);
        let half = crate::scalar::Interval::try_from((0.5, 0.5)).ok()?;
        let norm = ((s + disc.sqrt()) * half).sqrt();
        let norm_sup = norm.sup();
        if !norm_sup.is_finite() || norm_sup <= 0.0 {
            return None;
        }
        Some(PenMap {
            m,
            inv,
            det_negative: det.is_negative(),
            norm_sup,
        })
    }

    /// `M`, enclosed.
    pub(crate) fn metric(&self) -> [[crate::scalar::Interval; 2]; 2] {
        [ip(&self.m[0]), ip(&self.m[1])]
    }

    /// `M⁻¹ p`, exactly.
    pub(crate) fn pre(&self, p: &Q2) -> Q2 {
        [
            &self.inv[0][0] * &p[0] + &self.inv[0][1] * &p[1],
            &self.inv[1][0] * &p[0] + &self.inv[1][1] * &p[1],
        ]
    }

    /// The pre-image tolerance `t′ > 0` with `‖M‖₂ · t′ ≤ tol` (rounded
    /// down), as an exact rational; `None` when it underflows.
    pub(crate) fn pre_tol(&self, tol: &Rational) -> Option<Rational> {
        let norm = crate::scalar::Interval::try_from((self.norm_sup, self.norm_sup)).ok()?;
        let t = (iq(tol) / norm).inf();
        (t.is_finite() && t > 0.0)
            .then(|| crate::scalar::rational_from_f64(t))
            .flatten()
    }
}

/// An exact point.
pub(crate) type Q2 = [Rational; 2];

/// The exact control points of a Bézier, as the certificate states them.
pub(crate) fn exact_points(b: &crate::curve::Bezier<Rational>) -> Vec<Q2> {
    b.points()
        .iter()
        .map(|p| [p.x.clone(), p.y.clone()])
        .collect()
}

pub(super) fn cross(a: &Q2, b: &Q2) -> Rational {
    &a[0] * &b[1] - &a[1] * &b[0]
}
pub(super) fn dotq(a: &Q2, b: &Q2) -> Rational {
    &a[0] * &b[0] + &a[1] * &b[1]
}

/// `cross(a, b) > 0 ∧ dot(a, b) > 0`, decided exactly: the interval
/// enclosure (outward rounding) decides when it excludes 0, the exact
/// rational products only when it does not.
fn turns_ccw_less_than_right_angle(a: &Q2, b: &Q2) -> bool {
    let (ai, bi) = (ip(a), ip(b));
    let cr = ai[0] * bi[1] - ai[1] * bi[0];
    let dt = ai[0] * bi[0] + ai[1] * bi[1];
    let cross_pos = if cr.inf() > 0.0 {
        true
    } else if cr.sup() < 0.0 {
        false
    } else {
        cross(a, b).is_positive()
    };
    cross_pos
        && if dt.inf() > 0.0 {
            true
        } else if dt.sup() < 0.0 {
            false
        } else {
            dotq(a, b).is_positive()
        }
}
fn subq(a: &Q2, b: &Q2) -> Q2 {
    [&a[0] - &b[0], &a[1] - &b[1]]
}

/// One family of the cover of `∂S`: its name and its curve.
pub(crate) struct Family {
    pub(crate) name: String,
    pub(crate) path: Box<dyn Path + Send>,
}

/// One piece of the input curve as a certificate states it: a Bézier's
/// control points, or an exact circular arc of sweep in `(0, π)` (ends
/// exactly on the circle, travelled the short way from `from` to `to`).
#[derive(Clone, Debug, PartialEq)]
#[allow(clippy::large_enum_variant)]
pub(crate) enum CurvePiece {
    Bezier(Vec<Q2>),
    Arc {
        c: Q2,
        rho: Rational,
        from: Q2,
        to: Q2,
        clockwise: bool,
    },
}

impl CurvePiece {
    /// The start and end points, exact.
    pub(crate) fn ends(&self) -> (&Q2, &Q2) {
        match self {
            CurvePiece::Bezier(p) => (&p[0], &p[p.len() - 1]),
            CurvePiece::Arc { from, to, .. } => (from, to),
        }
    }

    /// The tangent directions at the start and at the end, exact (a
    /// Bézier's first and last control polygon legs; an arc's `±J(p − c)`).
    fn tangents(&self) -> (Q2, Q2) {
        match self {
            CurvePiece::Bezier(p) => (subq(&p[1], &p[0]), subq(&p[p.len() - 1], &p[p.len() - 2])),
            CurvePiece::Arc {
                c,
                from,
                to,
                clockwise,
                ..
            } => {
                // counter-clockwise: J(p − c) = (−(p_y − c_y), p_x − c_x)
                let t = |p: &Q2| {
                    let v = subq(p, c);
                    if *clockwise {
                        [v[1].clone(), -&v[0]]
                    } else {
                        [-&v[1], v[0].clone()]
                    }
                };
                (t(from), t(to))
            }
        }
    }

    /// Checks an arc: radius `> 0`, ends exactly on the circle, and a sweep
    /// in `(0, π)` the way `clockwise` says (`(from − c) × (to − c)` nonzero,
    /// of the sign of that direction).
    pub(crate) fn checked_arc(
        c: Q2,
        rho: Rational,
        from: Q2,
        to: Q2,
        clockwise: bool,
    ) -> Result<CurvePiece, String> {
        let (u, v) = radius_vectors(&c, &rho, &from, &to)?;
        let cr = cross(&u, &v);
        if cr.is_zero() || cr.is_negative() != clockwise {
            return Err(format!(
                "an input arc must turn by more than 0 and less than π {} from `from` to `to` (split longer arcs)",
                if clockwise { "clockwise" } else { "counter-clockwise" }
            ));
        }
        Ok(CurvePiece::Arc {
            c,
            rho,
            from,
            to,
            clockwise,
        })
    }
}

/// An arc's radius vectors `from − c`, `to − c`, checked: radius `> 0`,
/// both ends exactly on the circle.
fn radius_vectors(c: &Q2, rho: &Rational, from: &Q2, to: &Q2) -> Result<(Q2, Q2), String> {
    if !rho.is_positive() {
        return Err("radius: must be > 0".into());
    }
    let (u, v) = (subq(from, c), subq(to, c));
    let r2 = rho * rho;
    if dotq(&u, &u) != r2 || dotq(&v, &v) != r2 {
        return Err("an end point is not exactly on the circle".into());
    }
    Ok((u, v))
}

/// One input piece, enclosed.
pub(crate) enum InPiece {
    /// A Bézier with its hodographs.
    Bez(Bez),
    /// An arc `x(λ) = c + ρ d(λ)/|d(λ)|`, `d(λ) = (1 − λ)(from − c) +
    /// λ(to − c)`, `λ ∈ [0, 1]` (a sweep below `π`: `d` never vanishes), and
    /// the sign of its turn (`+1` counter-clockwise).
    Arc { path: ConeArc, turn: f64 },
}

impl InPiece {
    /// An enclosure of the point `x(u)`.
    pub(crate) fn at(&self, u: crate::scalar::Interval) -> Option<P> {
        match self {
            InPiece::Bez(b) => Some(b.at(u)),
            InPiece::Arc { path, .. } => path.val(u),
        }
    }
}

/// The input curve read exactly, with interval pieces.
pub(crate) struct Input {
    /// The pieces as stated.
    pub(crate) curve: Vec<CurvePiece>,
    /// The same pieces, enclosed.
    pub(crate) pieces: Vec<InPiece>,
    pub(crate) r: Rational,
    /// For an elliptical pen, `M` enclosed: the pieces are pre-images under
    /// `M⁻¹`, and the near tests of claim (b) measure `|M (F′ − L′)| = |F − L|`
    /// in the stated coordinates.
    pub(crate) metric: Option<[[crate::scalar::Interval; 2]; 2]>,
    /// Per piece: its control points all lie on the line through its end
    /// points (exactly), so its image holds the segment between them.
    pub(crate) straight: Vec<bool>,
    /// The pieces' boxes (a Bézier's control polygon, an arc's circle),
    /// indexed: a part's outside disk is tested only against the pieces
    /// whose box is within its reach.
    pub(crate) index: BoxIndex,
    /// The work budget of the check (unlimited for the writer).
    pub(crate) budget: Budget,
}

/// The box of one input piece, rounded outward: it holds the piece (a
/// Bézier's control polygon's box; an arc's circle's box `c ± ρ`). An
/// unbounded box when it is not finite (never pruned).
fn piece_box(p: &InPiece) -> FBox {
    let unbounded = ([f64::NEG_INFINITY; 2], [f64::INFINITY; 2]);
    match p {
        InPiece::Bez(b) => b.bbox().unwrap_or(unbounded),
        InPiece::Arc { path, .. } => {
            let r = path.r.mag();
            let lo = [0, 1].map(|i| (path.c[i].inf() - r).next_down());
            let hi = [0, 1].map(|i| (path.c[i].sup() + r).next_up());
            if lo.iter().chain(&hi).all(|x| x.is_finite()) {
                (lo, hi)
            } else {
                unbounded
            }
        }
    }
}

/// Whether every control point of `p` lies on the line through its end points
/// (exactly). `pi` encloses `p`: a control point whose enclosed cross product
/// with the chord excludes 0 is off the line, so a curved piece is decided in
/// intervals; only pieces that pass every interval test are checked exactly.
fn on_chord(p: &[Q2], pi: &[P]) -> bool {
    let n = p.len() - 1;
    let d = [pi[n][0] - pi[0][0], pi[n][1] - pi[0][1]];
    let off = |q: &P| {
        let c = (q[0] - pi[0][0]) * d[1] - (q[1] - pi[0][1]) * d[0];
        !c.contains(0.0)
    };
    if pi[1..n].iter().any(off) {
        return false;
    }
    let d = subq(&p[n], &p[0]);
    p.iter().all(|q| cross(&subq(q, &p[0]), &d).is_zero())
}

impl Input {
    /// [`Input::with_pieces`] of Bézier pieces only.
    #[cfg(test)]
    pub(crate) fn new(exact: Vec<Vec<Q2>>, r: Rational, at: &str) -> Result<Input, Invalid> {
        Input::with_pieces(exact.into_iter().map(CurvePiece::Bezier).collect(), r, at)
    }

    /// Checks the pieces (a Bézier: degree ≥ 1, nonzero end tangents; an arc
    /// as [`CurvePiece::checked_arc`] leaves it) and encloses them.
    pub(crate) fn with_pieces(
        curve: Vec<CurvePiece>,
        r: Rational,
        at: &str,
    ) -> Result<Input, Invalid> {
        if curve.is_empty() {
            return Err(inv(at, "no pieces"));
        }
        if !r.is_positive() {
            return Err(inv("radius", "must be > 0"));
        }
        for (j, p) in curve.iter().enumerate() {
            let CurvePiece::Bezier(p) = p else { continue };
            let n = p.len();
            if n < 2 {
                return Err(inv(
                    format!("{at}[{j}]"),
                    "a piece needs at least 2 control points",
                ));
            }
            if p[0] == p[1] || p[n - 1] == p[n - 2] {
                return Err(inv(
                    format!("{at}[{j}]"),
                    "a zero end tangent (a repeated end control point): the boundary of the stroke is only derived for pieces with nonzero end tangents",
                ));
            }
        }
        let mut pieces = Vec::with_capacity(curve.len());
        let mut straight = Vec::with_capacity(curve.len());
        for p in &curve {
            match p {
                CurvePiece::Bezier(p) => {
                    let b = Bez::with_distance_form(p.iter().map(ip).collect());
                    straight.push(on_chord(p, &b.pts));
                    pieces.push(InPiece::Bez(b));
                }
                CurvePiece::Arc {
                    c,
                    rho,
                    from,
                    to,
                    clockwise,
                } => {
                    straight.push(false);
                    pieces.push(InPiece::Arc {
                        path: ConeArc {
                            c: ip(c),
                            r: iq(rho),
                            a: ip(&subq(from, c)),
                            b: ip(&subq(to, c)),
                        },
                        turn: if *clockwise { -1.0 } else { 1.0 },
                    });
                }
            }
        }
        let index = BoxIndex::new(pieces.iter().map(piece_box).collect());
        Ok(Input {
            curve,
            pieces,
            r,
            metric: None,
            straight,
            index,
            budget: Budget::unlimited(),
        })
    }

    /// The connected components (pieces joined end to start): `(first, end,
    /// closed)` — the same rule as the stroke's input.
    fn components(&self) -> Vec<(usize, usize, bool)> {
        let c = &self.curve;
        let mut out: Vec<(usize, usize, bool)> = Vec::new();
        for i in 0..c.len() {
            let joined = i > 0 && c[i - 1].ends().1 == c[i].ends().0;
            match out.last_mut() {
                Some(k) if joined => k.1 = i + 1,
                _ => out.push((i, i + 1, false)),
            }
        }
        for k in &mut out {
            let part = &c[k.0..k.1];
            // one piece closes only as a Bézier of degree ≥ 2 (an arc's
            // sweep is below π)
            let closed = part.len() > 1 || matches!(&part[0], CurvePiece::Bezier(p) if p.len() > 2);
            k.2 = closed && part[part.len() - 1].ends().1 == part[0].ends().0;
        }
        out
    }

    /// The families whose union holds `∂S`, in the certificate's order: both
    /// offsets of every piece, then per component its start cap (open) and the
    /// cone at the end of each piece (a join, the closing join, or the end
    /// cap), each cone as two halves `a`, `b` (none at a G¹ joint).
    ///
    /// An arc's offsets are the concentric arcs `c + (ρ ∓ r) d/|d|` over the
    /// same directions (left is towards the centre for a counter-clockwise
    /// arc; a negative radius is the arc through the opposite directions,
    /// which the same formula states).
    pub(crate) fn families(&self) -> Vec<Family> {
        let r = iq(&self.r);
        let mut out: Vec<Family> = Vec::new();
        for (j, p) in self.pieces.iter().enumerate() {
            for (side, sigma) in [("left", 1.0), ("right", -1.0)] {
                let path: Box<dyn Path + Send> = match p {
                    InPiece::Bez(b) => Box::new(OwnedSide {
                        b: b.clone(),
                        sigma,
                        r,
                    }),
                    // left normal J x′/|x′| = −turn·(x − c)/ρ: the offset
                    // radius is ρ − σ·turn·r
                    InPiece::Arc { path, turn } => Box::new(ConeArc {
                        c: path.c,
                        r: path.r - geom::ic(sigma * turn) * r,
                        a: path.a,
                        b: path.b,
                    }),
                };
                out.push(Family {
                    name: format!("piece {j} {side}"),
                    path,
                });
            }
        }
        let tin = |j: usize| self.curve[j].tangents().1;
        let tout = |j: usize| self.curve[j].tangents().0;
        for (first, end, closed) in self.components() {
            let mut cones: Vec<(String, Q2, Option<[Q2; 3]>)> = Vec::new();
            if !closed {
                let t = tout(first);
                let t = [-&t[0], -&t[1]];
                cones.push((
                    format!("start {first}"),
                    self.curve[first].ends().0.clone(),
                    Some(half_plane(&t)),
                ));
            }
            for j in first..end {
                let next = if j + 1 < end {
                    Some(j + 1)
                } else if closed {
                    Some(first)
                } else {
                    None
                };
                let y = self.curve[j].ends().1.clone();
                let rays = match next {
                    None => Some(half_plane(&tin(j))),
                    Some(k) => joint(&tin(j), &tout(k)),
                };
                cones.push((format!("end {j}"), y, rays));
            }
            for (name, y, rays) in cones {
                let Some([a, m, b]) = rays else { continue };
                for (half, (u, v)) in [("a", (&a, &m)), ("b", (&m, &b))] {
                    out.push(Family {
                        name: format!("{name} {half}"),
                        path: Box::new(ConeArc {
                            c: ip(&y),
                            r,
                            a: ip(u),
                            b: ip(v),
                        }),
                    });
                }
            }
        }
        out
    }
}

/// The half plane `{u : u·t ≥ 0}` as the rays `−J t`, `t`, `J t`.
fn half_plane(t: &Q2) -> [Q2; 3] {
    [[t[1].clone(), -&t[0]], t.clone(), [-&t[1], t[0].clone()]]
}

/// The normal cone `{u : u·t_in ≥ 0, u·t_out ≤ 0}` at a joint as three rays
/// (its two edges and a direction between them), or `None` at a G¹ joint
/// (the cone is the normal line: the two offsets' end points).
fn joint(t_in: &Q2, t_out: &Q2) -> Option<[Q2; 3]> {
    let cr = cross(t_in, t_out);
    if cr.is_zero() {
        return if dotq(t_in, t_out).is_positive() {
            None
        } else {
            Some(half_plane(t_in))
        };
    }
    // a = −s J t_in, b = −s J t_out with s the sign of the turn
    let s = if cr.is_positive() {
        Rational::from_integer(1.into())
    } else {
        Rational::from_integer((-1).into())
    };
    let a = [&t_in[1] * &s, -&t_in[0] * &s];
    let b = [&t_out[1] * &s, -&t_out[0] * &s];
    let m = [&a[0] + &b[0], &a[1] + &b[1]];
    Some([a, m, b])
}

/// [`Side`] owning its piece (families outlive the borrow).
struct OwnedSide {
    b: Bez,
    sigma: f64,
    r: crate::scalar::Interval,
}
impl Path for OwnedSide {
    fn val(&self, t: crate::scalar::Interval) -> Option<P> {
        Side {
            b: &self.b,
            sigma: self.sigma,
            r: self.r,
        }
        .val(t)
    }
    fn der(&self, t: crate::scalar::Interval) -> Option<P> {
        Side {
            b: &self.b,
            sigma: self.sigma,
            r: self.r,
        }
        .der(t)
    }
    fn work(&self) -> u64 {
        self.b.work()
    }
}

/// One outline piece, exact and enclosed. (An arc's fields are boxed: an
/// outline holds up to 100 000 pieces, most of them Béziers, and the enum
/// is as large as its largest variant.)
pub(crate) enum OPiece {
    Bezier {
        exact: Vec<Q2>,
        iv: Bez,
    },
    Arc {
        start: Box<Q2>,
        end: Box<Q2>,
        ccw_u: Box<Q2>,
        ccw_v: Box<Q2>,
        t: Box<ArcT>,
        clockwise: bool,
    },
}

impl OPiece {
    fn start(&self) -> &Q2 {
        match self {
            OPiece::Bezier { exact, .. } => &exact[0],
            OPiece::Arc { start, .. } => start,
        }
    }
    fn end(&self) -> &Q2 {
        match self {
            OPiece::Bezier { exact, .. } => exact.last().expect("≥ 2 points"),
            OPiece::Arc { end, .. } => end,
        }
    }
    /// An exact arc: centre `c`, radius `rho > 0`, ends exactly on the circle.
    pub(crate) fn arc(
        c: Q2,
        rho: Rational,
        from: Q2,
        to: Q2,
        clockwise: bool,
    ) -> Result<OPiece, String> {
        let (u, v) = radius_vectors(&c, &rho, &from, &to)?;
        let (cu, cv) = if clockwise { (v, u) } else { (u, v) };
        let cr = cross(&cu, &cv);
        let t = ArcT {
            c: ip(&c),
            rho: iq(&rho),
            u: ip(&cu),
            v: ip(&cv),
            sign: if cr.is_positive() {
                1
            } else if cr.is_negative() {
                -1
            } else {
                0
            },
            full: cu == cv,
        };
        Ok(OPiece::Arc {
            start: Box::new(from),
            end: Box::new(to),
            ccw_u: Box::new(cu),
            ccw_v: Box::new(cv),
            t: Box::new(t),
            clockwise,
        })
    }
    pub(crate) fn bezier(exact: Vec<Q2>) -> OPiece {
        let iv = Bez::new(exact.iter().map(ip).collect());
        OPiece::Bezier { exact, iv }
    }
}

fn arr<'j, 'a>(v: &'j Json<'a>, at: &str, what: &str) -> Result<&'j [Json<'a>], Invalid> {
    v.as_array().ok_or_else(|| {
        inv(
            at,
            format!("expected a list of {what}, found {}", v.describe()),
        )
    })
}

/// A field's path, formatted only when an error names it: the readers of
/// the per-part and per-box fields run tens of thousands of times per
/// certificate, and building their paths eagerly cost more than reading them.
type At<'a> = &'a dyn Fn() -> String;

/// Names the error of a reader called with the empty path: `at()` followed
/// by the field path the reader gave relative to it.
fn named<T>(r: Result<T, Invalid>, at: impl FnOnce() -> String) -> Result<T, Invalid> {
    r.map_err(|e| {
        let base = at();
        let at = if e.at.is_empty() {
            base
        } else if e.at.starts_with('[') {
            format!("{base}{}", e.at)
        } else {
            join(&base, &e.at)
        };
        Invalid {
            at,
            reason: e.reason,
        }
    })
}

fn rational_at(v: &Json, at: At) -> Result<Rational, Invalid> {
    named(canonical_rational(v, ""), at)
}

fn point(v: &Json, at: At) -> Result<Q2, Invalid> {
    let a = named(arr(v, "", "2 coordinates"), at)?;
    if a.len() != 2 {
        return Err(inv(at(), "expected a point [x, y]"));
    }
    Ok([
        rational_at(&a[0], &|| format!("{}[0]", at()))?,
        rational_at(&a[1], &|| format!("{}[1]", at()))?,
    ])
}

fn points(v: &Json, at: &str) -> Result<Vec<Q2>, Invalid> {
    let a = arr(v, at, "control points")?;
    if a.len() < 2 || a.len() > MAX_CONTROL_POINTS {
        return Err(inv(
            at,
            format!(
                "a Bézier has 2 to {MAX_CONTROL_POINTS} control points, found {}",
                a.len()
            ),
        ));
    }
    // (collected at its exact size: a `Result` collect starts at 4 points,
    // and most pieces are segments)
    let mut out = Vec::with_capacity(a.len());
    for (i, p) in a.iter().enumerate() {
        out.push(point(p, &|| format!("{at}[{i}]"))?);
    }
    Ok(out)
}

/// The fields of `{"arc": {"center", "radius", "from", "to", "clockwise"}}`
/// read exactly (no other key), and the path `at.arc` that names them.
#[allow(clippy::type_complexity)]
fn arc_fields(v: &Json, at: &str) -> Result<(String, (Q2, Rational, Q2, Q2, bool)), Invalid> {
    let [a] = exact_object(v, at, ["arc"])?;
    let at = join(at, "arc");
    let [c, rho, from, to, cw] =
        exact_object(a, &at, ["center", "radius", "from", "to", "clockwise"])?;
    let cw = match cw {
        Json::Bool(b) => *b,
        o => {
            return Err(inv(
                join(&at, "clockwise"),
                format!("expected true or false, found {}", o.describe()),
            ))
        }
    };
    let fields = (
        point(c, &|| join(&at, "center"))?,
        canonical_rational(rho, &join(&at, "radius"))?,
        point(from, &|| join(&at, "from"))?,
        point(to, &|| join(&at, "to"))?,
        cw,
    );
    Ok((at, fields))
}

fn read_piece(v: &Json, at: &str) -> Result<OPiece, Invalid> {
    if let Some(b) = v.get("bezier") {
        let [_] = exact_object(v, at, ["bezier"])?;
        return Ok(OPiece::bezier(points(b, &join(at, "bezier"))?));
    }
    let (at, (c, rho, from, to, cw)) = arc_fields(v, at)?;
    OPiece::arc(c, rho, from, to, cw).map_err(|e| inv(at, e))
}

/// One input piece: a Bézier's control points `[[x, y], ...]`, or
/// `{"arc": {"center", "radius", "from", "to", "clockwise"}}` of sweep in
/// `(0, π)`.
fn read_curve_piece(v: &Json, at: &str) -> Result<CurvePiece, Invalid> {
    if v.as_array().is_some() {
        return Ok(CurvePiece::Bezier(points(v, at)?));
    }
    let (at, (c, rho, from, to, cw)) = arc_fields(v, at)?;
    CurvePiece::checked_arc(c, rho, from, to, cw).map_err(|e| inv(at, e))
}

/// The outline's contours, each closed by exact shared end points.
pub(crate) fn read_outline(v: &Json) -> Result<Vec<Vec<OPiece>>, Invalid> {
    let cs = arr(v, "outline", "contours")?;
    if cs.is_empty() {
        return Err(inv("outline", "no contours"));
    }
    let mut total = 0usize;
    let mut out = Vec::new();
    for (ci, c) in cs.iter().enumerate() {
        let at = format!("outline[{ci}]");
        let ps = arr(c, &at, "pieces")?;
        total += ps.len();
        if ps.is_empty() || total > MAX_SEGMENTS {
            return Err(inv(
                at,
                format!(
                    "a contour has at least 1 piece, and the outline at most {MAX_SEGMENTS} in all"
                ),
            ));
        }
        let pieces: Vec<OPiece> = ps
            .iter()
            .enumerate()
            .map(|(i, p)| read_piece(p, &format!("{at}[{i}]")))
            .collect::<Result<_, _>>()?;
        check_closed(&pieces).map_err(|i| {
            inv(
                format!("{at}[{i}]"),
                "does not start exactly where the previous piece ends: the contour is not closed",
            )
        })?;
        out.push(pieces);
    }
    Ok(out)
}

pub(crate) fn check_closed(pieces: &[OPiece]) -> Result<(), usize> {
    let n = pieces.len();
    for i in 0..n {
        if pieces[(i + n - 1) % n].end() != pieces[i].start() {
            return Err(i);
        }
    }
    Ok(())
}

/// The verifier's count of what it checked: `(max bound, boxes)`.
type Tally = (f64, usize);

/// A part's set in `S` (its `"o"`): the disk `B(x_j(u), r)`, or the capsule
/// of radius `r` about the segment between the end points of a straight
/// input piece `j` (`{"segment": j}`), which lies in `S` since the piece's
/// image holds that segment.
#[derive(Clone, Debug, PartialEq, Eq)]
pub(crate) enum Inside {
    Disk { piece: usize, u: Rational },
    Segment { piece: usize },
}

/// A part of the cover checked: a set in `S` ([`Inside`]), the disk
/// `B(w, μ)` outside `S`, and the bound over the hull `≤ tol`. Returns the
/// bound (sup).
pub(crate) fn check_part(
    input: &Input,
    hull: &geom::Hull,
    o: &Inside,
    w: &Q2,
    mu: &Rational,
    tol: crate::scalar::Interval,
) -> Result<f64, String> {
    let (r, mu_i) = (iq(&input.r), iq(mu));
    let wi = ip(w);
    if mu.is_negative() {
        return Err("w.mu: negative".into());
    }
    let n = input.pieces.len();
    let (core, hint) = match o {
        Inside::Disk { piece, u } => {
            let p = input
                .pieces
                .get(*piece)
                .ok_or_else(|| format!("o.piece {piece}: the curve has {n} pieces"))?;
            if u.is_negative() || u > &Rational::from_integer(1.into()) {
                return Err("o.u: outside [0, 1]".into());
            }
            // the disk's centre lies along the normal at the witness point
            // `x_j(u)` in certificates lncert writes: `u` hints where the
            // distance is least
            let y = p
                .at(iq(u))
                .ok_or_else(|| format!("o.piece {piece}: its point at u is not finite"))?;
            (Core::Point(y), (*piece, u.to_f64().unwrap_or(0.5)))
        }
        Inside::Segment { piece } => {
            let p = input
                .pieces
                .get(*piece)
                .ok_or_else(|| format!("o.segment {piece}: the curve has {n} pieces"))?;
            let (InPiece::Bez(bez), true) = (p, input.straight[*piece]) else {
                return Err(format!(
                    "o.segment {piece}: the piece is not straight (its control points are not all on the line through its end points)"
                ));
            };
            let (a, b) = (bez.pts[0], bez.pts[bez.pts.len() - 1]);
            // where `w` projects on the segment (a hint only)
            (Core::Segment(a, b), (*piece, geom::segment_param(a, b, wi)))
        }
    };
    let r2 = (r + mu_i).sqr();
    // the pieces within reach of the disk (every other piece's box is
    // proven farther than r + μ from w, so the piece is)
    let budget = &input.budget;
    let visited = input.index.query(
        |lo, hi| !geom::box_farther(*lo, *hi, wi, r2),
        |j| {
            let h = (hint.0 == j).then_some(hint.1);
            match &input.pieces[j] {
                InPiece::Bez(b) => outside_bez(wi, j, b, r2, h, budget),
                InPiece::Arc { path, turn } => budget
                    .charge(1)
                    .map_err(|e| e.to_string())
                    .and_then(|()| outside_arc(wi, j, path, *turn, r2)),
            }
            .map_err(|e| format!("w: {e}"))
        },
    )?;
    budget.charge(visited).map_err(|e| e.to_string())?;
    let b = part_bound(hull, core, r, wi, mu_i);
    if b > tol.inf() {
        return Err(format!(
            "the part is only proven within {b:e} of the boundary, above the tolerance"
        ));
    }
    Ok(b)
}

fn read_witness(v: &Json, at: At) -> Result<Inside, Invalid> {
    if v.get("segment").is_some() {
        let [p] = named(exact_object(v, "", ["segment"]), at)?;
        return Ok(Inside::Segment {
            piece: named(canonical_index(p, ""), || join(&at(), "segment"))?,
        });
    }
    let [p, u] = named(exact_object(v, "", ["piece", "u"]), at)?;
    Ok(Inside::Disk {
        piece: named(canonical_index(p, ""), || join(&at(), "piece"))?,
        u: rational_at(u, &|| join(&at(), "u"))?,
    })
}

fn read_outside(v: &Json, at: At) -> Result<(Q2, Rational), Invalid> {
    let [a, m] = named(exact_object(v, "", ["at", "mu"]), at)?;
    Ok((
        point(a, &|| join(&at(), "at"))?,
        rational_at(m, &|| join(&at(), "mu"))?,
    ))
}

/// Where the parts of one piece have reached: the end parameter of the last
/// Bézier part, or the end direction of the last arc part.
struct Chain {
    s: Rational,
    dir: Option<Q2>,
}

/// A part's object `{key: [a, b], "o": …, "w": …}`: its two range ends read
/// by `read` (named `key[0]`, `key[1]`; `what` the list, `ends` its expected
/// form, for the errors), and its witness fields.
fn read_pair<'j, 't, T>(
    p: &'j Json<'t>,
    atk: &dyn Fn() -> String,
    [key, what, ends]: [&str; 3],
    read: fn(&Json, At) -> Result<T, Invalid>,
) -> Result<([T; 2], &'j Json<'t>, &'j Json<'t>), Invalid> {
    let [v, o, w] = named(exact_object(p, "", [key, "o", "w"]), atk)?;
    let a = named(arr(v, "", what), || join(&atk(), key))?;
    if a.len() != 2 {
        return Err(inv(join(&atk(), key), format!("expected {ends}")));
    }
    let first = read(&a[0], &|| format!("{}.{key}[0]", atk()))?;
    let second = read(&a[1], &|| format!("{}.{key}[1]", atk()))?;
    Ok(([first, second], o, w))
}

/// One part as the certificate states it: its span on the outline piece
/// (checked to continue `chain`, which it advances), its hull, and its two
/// witness fields (not read yet).
fn read_part<'j, 't>(
    p: &'j Json<'t>,
    atk: &dyn Fn() -> String,
    piece: &OPiece,
    chain: &mut Chain,
) -> Result<(simple::Span, geom::Hull, &'j Json<'t>, &'j Json<'t>), Invalid> {
    match piece {
        OPiece::Bezier { iv, .. } => {
            let ([s0, s1], o, w) =
                read_pair(p, atk, ["s", "2 parameters", "[s0, s1]"], rational_at)?;
            if s0 != chain.s {
                return Err(inv(
                    format!("{}.s[0]", atk()),
                    format!("expected {}: the parts must cover [0, 1] in order", chain.s),
                ));
            }
            if s1 <= s0 || s1 > Rational::from_integer(1.into()) {
                return Err(inv(format!("{}.s[1]", atk()), "expected s0 < s1 ≤ 1"));
            }
            chain.s = s1.clone();
            let hull = iv.restrict(iq(&s0), iq(&s1));
            Ok((simple::Span::Bez(s0, s1), hull, o, w))
        }
        OPiece::Arc { ccw_u, t, .. } => {
            let ([d0, d1], o, w) = read_pair(p, atk, ["dirs", "2 directions", "[d0, d1]"], point)?;
            let start_ok = match &chain.dir {
                None => cross(&d0, ccw_u).is_zero() && dotq(&d0, ccw_u).is_positive(),
                Some(q) => *q == d0,
            };
            if !start_ok {
                return Err(inv(
                    format!("{}.dirs[0]", atk()),
                    "must continue the previous part exactly (the first: along the arc's counter-clockwise start)",
                ));
            }
            if !turns_ccw_less_than_right_angle(&d0, &d1) {
                return Err(inv(
                    join(&atk(), "dirs"),
                    "a part turns counter-clockwise by less than π/2",
                ));
            }
            chain.dir = Some(d1.clone());
            let h = arc_hull(t.c, t.rho, ip(&d0), ip(&d1))
                .ok_or_else(|| inv(join(&atk(), "dirs"), "hull not finite"))?;
            Ok((simple::Span::arc(d0, d1), h, o, w))
        }
    }
}

/// The parts chained over the whole piece: to its end parameter 1, or to the
/// arc's counter-clockwise end direction.
fn chain_complete(piece: &OPiece, chain: &Chain) -> bool {
    match piece {
        OPiece::Bezier { .. } => chain.s == Rational::from_integer(1.into()),
        OPiece::Arc { ccw_v, .. } => chain
            .dir
            .as_ref()
            .is_some_and(|d| cross(d, ccw_v).is_zero() && dotq(d, ccw_v).is_positive()),
    }
}

/// One outline piece's cover as read (no witness checked yet): per part its
/// span, hull and witness fields, in order, and the error that stopped the
/// reading (a malformed part, a gap in the chain, parts stopping short).
struct PieceRead<'j, 't> {
    // (boxed slices and a boxed error: one of these per outline piece is
    // alive for the whole check, part of the memory bound)
    spans: Box<[simple::Span]>,
    hulls: Box<[geom::Hull]>,
    witnesses: Box<[(&'j Json<'t>, &'j Json<'t>)]>,
    stop: Option<Box<Invalid>>,
}

/// Claim (a), first half: the parts of one piece read and chained over it.
fn read_cover_piece<'j, 't>(v: &'j Json<'t>, at: &str, piece: &OPiece) -> PieceRead<'j, 't> {
    let stopped = |e: Invalid| PieceRead {
        spans: Box::new([]),
        hulls: Box::new([]),
        witnesses: Box::new([]),
        stop: Some(Box::new(e)),
    };
    let parts = match arr(v, at, "parts") {
        Ok([]) => Err(inv(at, "no parts: the piece is not covered")),
        other => other,
    };
    let parts = match parts {
        Ok(p) => p,
        Err(e) => return stopped(e),
    };
    // at their exact sizes (a piece has one part or a few)
    let mut spans = Vec::with_capacity(parts.len());
    let mut hulls = Vec::with_capacity(parts.len());
    let mut witnesses = Vec::with_capacity(parts.len());
    let mut chain = Chain {
        s: Rational::zero(),
        dir: None,
    };
    let mut stop = None;
    for (k, p) in parts.iter().enumerate() {
        let atk = || format!("{at}[{k}]");
        match read_part(p, &atk, piece, &mut chain) {
            Ok((span, hull, o, w)) => {
                spans.push(span);
                hulls.push(hull);
                witnesses.push((o, w));
            }
            Err(e) => {
                stop = Some(Box::new(e));
                break;
            }
        }
    }
    if stop.is_none() && !chain_complete(piece, &chain) {
        stop = Some(Box::new(inv(
            at,
            "the parts stop before the end of the piece",
        )));
    }
    PieceRead {
        spans: spans.into_boxed_slice(),
        hulls: hulls.into_boxed_slice(),
        witnesses: witnesses.into_boxed_slice(),
        stop,
    }
}

/// Claim (a), second half: each part read is checked, in order; then the
/// reading's own error, if it stopped — the order in which reading and
/// checking part by part would meet them.
fn check_read_piece(
    r: &PieceRead,
    at: &str,
    input: &Input,
    tol: crate::scalar::Interval,
) -> Result<Tally, Invalid> {
    let mut max = 0.0f64;
    for (k, (hull, (o, w))) in r.hulls.iter().zip(&r.witnesses).enumerate() {
        let atk = || format!("{at}[{k}]");
        let inside = read_witness(o, &|| join(&atk(), "o"))?;
        let (w, mu) = read_outside(w, &|| join(&atk(), "w"))?;
        let b = check_part(input, hull, &inside, &w, &mu, tol).map_err(|e| inv(atk(), e))?;
        max = max.max(b);
    }
    match &r.stop {
        Some(e) => Err((**e).clone()),
        None => Ok((max, r.hulls.len())),
    }
}

/// One box of the cover of `∂S`.
pub(crate) enum BBox {
    NearBezier {
        contour: usize,
        piece: usize,
        s: Rational,
        k: Rational,
    },
    NearArc {
        contour: usize,
        piece: usize,
    },
    Inside {
        piece: usize,
        u: Rational,
    },
}

/// Checks one box of a family; its bound (0 for a box inside `S`).
pub(crate) fn check_bbox(
    path: &dyn Path,
    bx: &BoxT,
    what: &BBox,
    outline: &[Vec<OPiece>],
    input: &Input,
    tol: crate::scalar::Interval,
) -> Result<f64, String> {
    let get = |c: usize, i: usize| {
        outline
            .get(c)
            .and_then(|ps| ps.get(i))
            .ok_or_else(|| format!("near: no outline piece {i} in contour {c}"))
    };
    let target = match what {
        BBox::NearBezier { contour, piece, .. } => match get(*contour, *piece) {
            Ok(OPiece::Bezier { iv, .. }) => iv.work(),
            _ => 1,
        },
        _ => 1,
    };
    input
        .budget
        .charge(path.work() + target)
        .map_err(|e| e.to_string())?;
    match what {
        BBox::NearBezier {
            contour,
            piece,
            s,
            k,
        } => match get(*contour, *piece)? {
            OPiece::Bezier { iv, .. } => {
                near_bezier(path, bx, iv, s, k, tol.sqr(), input.metric.as_ref())
            }
            OPiece::Arc { .. } => Err("near: the piece is an arc (no s, k)".into()),
        },
        BBox::NearArc { contour, piece } => match get(*contour, *piece)? {
            OPiece::Arc { .. } if input.metric.is_some() => {
                Err("near: an arc under an elliptical pen's map".into())
            }
            OPiece::Arc { t, .. } => near_arc(path, bx, t, tol),
            OPiece::Bezier { .. } => Err("near: the piece is a Bézier (s and k needed)".into()),
        },
        BBox::Inside { piece, u } => {
            let b = input.pieces.get(*piece).ok_or_else(|| {
                format!(
                    "inside.piece {piece}: the curve has {} pieces",
                    input.pieces.len()
                )
            })?;
            if u.is_negative() || u > &Rational::from_integer(1.into()) {
                return Err("inside.u: outside [0, 1]".into());
            }
            let y = b
                .at(iq(u))
                .ok_or_else(|| format!("inside.piece {piece}: its point at u is not finite"))?;
            inside(path, bx, y, iq(&input.r).sqr()).map(|()| 0.0)
        }
    }
}

fn read_bbox(v: &Json, at: At) -> Result<(Rational, Rational, BBox), Invalid> {
    let (t, what) = if v.get("near").is_some() {
        let [t, n] = named(exact_object(v, "", ["t", "near"]), at)?;
        let atn = || join(&at(), "near");
        let b = if n.get("s").is_some() {
            let [c, p, s, k] = named(exact_object(n, "", ["contour", "piece", "s", "k"]), atn)?;
            BBox::NearBezier {
                contour: named(canonical_index(c, ""), || join(&atn(), "contour"))?,
                piece: named(canonical_index(p, ""), || join(&atn(), "piece"))?,
                s: rational_at(s, &|| join(&atn(), "s"))?,
                k: rational_at(k, &|| join(&atn(), "k"))?,
            }
        } else {
            let [c, p] = named(exact_object(n, "", ["contour", "piece"]), atn)?;
            BBox::NearArc {
                contour: named(canonical_index(c, ""), || join(&atn(), "contour"))?,
                piece: named(canonical_index(p, ""), || join(&atn(), "piece"))?,
            }
        };
        (t, b)
    } else {
        let [t, i] = named(exact_object(v, "", ["t", "inside"]), at)?;
        let ati = || join(&at(), "inside");
        let [p, u] = named(exact_object(i, "", ["piece", "u"]), ati)?;
        (
            t,
            BBox::Inside {
                piece: named(canonical_index(p, ""), || join(&ati(), "piece"))?,
                u: rational_at(u, &|| join(&ati(), "u"))?,
            },
        )
    };
    let ta = named(arr(t, "", "2 parameters"), || join(&at(), "t"))?;
    if ta.len() != 2 {
        return Err(inv(join(&at(), "t"), "expected [t0, t1]"));
    }
    Ok((
        rational_at(&ta[0], &|| format!("{}.t[0]", at()))?,
        rational_at(&ta[1], &|| format!("{}.t[1]", at()))?,
        what,
    ))
}

fn check_family(
    v: &Json,
    at: &str,
    fam: &Family,
    outline: &[Vec<OPiece>],
    input: &Input,
    tol: crate::scalar::Interval,
) -> Result<Tally, Invalid> {
    let [of, boxes] = exact_object(v, at, ["of", "boxes"])?;
    if of.as_str() != Some(fam.name.as_str()) {
        return Err(inv(
            join(at, "of"),
            format!(
                "expected \"{}\" (the boundary families come in the order the curve gives them)",
                fam.name
            ),
        ));
    }
    let boxes = arr(boxes, &join(at, "boxes"), "boxes")?;
    let one = Rational::from_integer(1.into());
    let mut cursor = Rational::zero();
    let mut max = 0.0f64;
    for (k, b) in boxes.iter().enumerate() {
        let atk = || format!("{at}.boxes[{k}]");
        let (t0, t1, what) = read_bbox(b, &atk)?;
        if t0 != cursor {
            return Err(inv(
                format!("{}.t[0]", atk()),
                format!("expected {cursor}: the boxes must cover [0, 1] in order"),
            ));
        }
        if t1 <= t0 || t1 > one {
            return Err(inv(format!("{}.t[1]", atk()), "expected t0 < t1 ≤ 1"));
        }
        let bx = BoxT::new(&t0, &t1);
        let bound =
            check_bbox(&*fam.path, &bx, &what, outline, input, tol).map_err(|e| inv(atk(), e))?;
        max = max.max(bound);
        cursor = t1;
    }
    if cursor != one {
        return Err(inv(
            join(at, "boxes"),
            format!("the boxes stop at {cursor}: [0, 1] is not covered"),
        ));
    }
    Ok((max, boxes.len()))
}

/// The two shapes a valid stroke certificate speaks about, for `verify
/// --against OUTLINE CURVE`: its outline (Bézier pieces and exact arcs, as one
/// union) and its curve. Call it on a document [`check`] accepted.
pub(crate) fn shapes(
    doc: &Json,
) -> Result<(crate::shape::ShapeDesc, crate::shape::ShapeDesc), Invalid> {
    use crate::curve::{Bezier, V2};
    use crate::shape::{ArcDesc, ShapeDesc};
    fn shape_err(at: &str) -> impl Fn(crate::shape::ShapeError) -> Invalid + '_ {
        move |e| inv(at, e.to_string())
    }
    let bez = |pts: Vec<Q2>| Bezier::new(pts.into_iter().map(|[x, y]| V2::new(x, y)).collect());
    let outline = doc
        .get("outline")
        .ok_or_else(|| inv("outline", "missing"))?;
    let mut beziers = Vec::new();
    let mut members = Vec::new();
    for (ci, c) in arr(outline, "outline", "contours")?.iter().enumerate() {
        for (i, p) in arr(c, "outline", "pieces")?.iter().enumerate() {
            let at = format!("outline[{ci}][{i}]");
            match read_piece(p, &at)? {
                OPiece::Bezier { exact, .. } => beziers.push(bez(exact)),
                OPiece::Arc {
                    start,
                    ccw_u,
                    ccw_v,
                    ..
                } => {
                    let a = p.get("arc").ok_or_else(|| inv(&at, "missing arc"))?;
                    let c = point(
                        a.get("center").ok_or_else(|| inv(&at, "missing center"))?,
                        &|| at.clone(),
                    )?;
                    let rho = canonical_rational(
                        a.get("radius").ok_or_else(|| inv(&at, "missing radius"))?,
                        &at,
                    )?;
                    let _ = start;
                    let v = |q: Q2| V2::new(q[0].clone(), q[1].clone());
                    members.push(
                        ShapeDesc::arc(ArcDesc {
                            center: v(c),
                            radius: rho,
                            from: v(*ccw_u),
                            to: v(*ccw_v),
                        })
                        .map_err(shape_err(&at))?,
                    );
                }
            }
        }
    }
    if !beziers.is_empty() {
        members.insert(0, ShapeDesc::curve(beziers).map_err(shape_err("outline"))?);
    }
    let outline = ShapeDesc::union(members).map_err(shape_err("outline"))?;
    let curve = doc.get("curve").ok_or_else(|| inv("curve", "missing"))?;
    let mut pieces: Vec<Bezier<Rational>> = Vec::new();
    let mut arcs = Vec::new();
    for (j, p) in arr(curve, "curve", "pieces")?.iter().enumerate() {
        let at = format!("curve[{j}]");
        match read_curve_piece(p, &at)? {
            CurvePiece::Bezier(p) => pieces.push(bez(p)),
            CurvePiece::Arc {
                c,
                rho,
                from,
                to,
                clockwise,
            } => {
                let v = |q: &Q2| V2::new(q[0].clone(), q[1].clone());
                let (u, w) = (subq(&from, &c), subq(&to, &c));
                let (from, to) = if clockwise { (w, u) } else { (u, w) };
                arcs.push(
                    ShapeDesc::arc(ArcDesc {
                        center: v(&c),
                        radius: rho,
                        from: v(&from),
                        to: v(&to),
                    })
                    .map_err(shape_err(&at))?,
                );
            }
        }
    }
    if !pieces.is_empty() {
        arcs.insert(0, ShapeDesc::curve(pieces).map_err(shape_err("curve"))?);
    }
    let curve = ShapeDesc::union(arcs).map_err(shape_err("curve"))?;
    Ok((outline, curve))
}

/// The pen of a valid stroke certificate as the set it is, `E = M · disk(1)`
/// given by `Q = M Mᵀ` as `[q₁₁, q₁₂, q₂₂]` (a disk of radius `r`: `r² I`),
/// for `verify --pen`: two matrices give the same pen exactly when their `Q`
/// are equal. Call it on a document [`check`] accepted.
pub(crate) fn pen_q(doc: &Json) -> Result<[Rational; 3], Invalid> {
    if let Some(p) = doc.get("pen") {
        let m = PenMap::read(p)?.m;
        let dot = |u: &Q2, v: &Q2| &u[0] * &v[0] + &u[1] * &v[1];
        return Ok([dot(&m[0], &m[0]), dot(&m[0], &m[1]), dot(&m[1], &m[1])]);
    }
    let r = canonical_rational(
        doc.get("radius").ok_or_else(|| inv("radius", "missing"))?,
        "radius",
    )?;
    let r2 = &r * &r;
    Ok([r2.clone(), Rational::zero(), r2])
}

/// The pre-image `M⁻¹ L` of an outline under an elliptical pen's map: its
/// Bézier pieces mapped exactly; an exact circular arc has no Bézier or arc
/// pre-image and is refused.
pub(crate) fn pre_outline(
    outline: Vec<Vec<OPiece>>,
    pen: &PenMap,
) -> Result<Vec<Vec<OPiece>>, Invalid> {
    outline
        .into_iter()
        .enumerate()
        .map(|(ci, c)| {
            c.into_iter()
                .enumerate()
                .map(|(i, p)| match p {
                    OPiece::Bezier { exact, .. } => {
                        Ok(OPiece::bezier(exact.iter().map(|q| pen.pre(q)).collect()))
                    }
                    OPiece::Arc { .. } => Err(inv(
                        format!("outline[{ci}][{i}]"),
                        "an exact circular arc: the outline of an elliptical pen's stroke is stated with Bézier pieces",
                    )),
                })
                .collect()
        })
        .collect()
}

/// Checks a stroke certificate (the format and version already read).
pub(crate) fn check(doc: &Json, budget: &Budget) -> Result<Valid, Invalid> {
    let elliptic = doc.get("pen").is_some();
    let [_f, version, claim, tol, pen_or_radius, curve, outline, cover, boundary, simple_claim] =
        if elliptic {
            exact_object(doc, "", KEYS_ELLIPSE)?
        } else {
            exact_object(doc, "", KEYS)?
        };
    if !matches!(version, Json::Number(v) if *v == VERSION.to_string()) {
        return Err(inv(
            "version",
            format!("this verifier reads version {VERSION} of {FORMAT}"),
        ));
    }
    let want = if elliptic { CLAIM_ELLIPSE } else { CLAIM };
    if claim.as_str() != Some(want) {
        return Err(inv(
            "claim",
            format!(
                "expected \"{want}\", the claim of this format with a \"{}\" key",
                if elliptic { "pen" } else { "radius" }
            ),
        ));
    }
    let tol_q = canonical_rational(tol, "tol")?;
    if !tol_q.is_positive() {
        return Err(inv("tol", "must be > 0"));
    }
    // an elliptical pen: everything below is checked on the pre-images under
    // M⁻¹ (a disk pen of radius 1) at t′ with ‖M‖₂ t′ ≤ tol, but for claim
    // (b)'s near tests, which measure in the stated coordinates at tol
    let tol_b = iq(&tol_q);
    let (pen, r, tol_i) = if elliptic {
        let pen = PenMap::read(pen_or_radius)?;
        let t = pen
            .pre_tol(&tol_q)
            .ok_or_else(|| inv("tol", "tol / ‖M‖₂ underflows: no pre-image tolerance"))?;
        (Some(pen), Rational::from_integer(1.into()), iq(&t))
    } else {
        (
            None,
            canonical_rational(pen_or_radius, "radius")?,
            iq(&tol_q),
        )
    };
    let pieces = arr(curve, "curve", "pieces")?;
    if pieces.len() > MAX_SEGMENTS {
        return Err(inv("curve", format!("more than {MAX_SEGMENTS} pieces")));
    }
    let mut exact: Vec<CurvePiece> = pieces
        .iter()
        .enumerate()
        .map(|(j, p)| read_curve_piece(p, &format!("curve[{j}]")))
        .collect::<Result<_, _>>()?;
    let t0 = std::time::Instant::now();
    let mut outline = read_outline(outline)?;
    if let Some(pen) = &pen {
        for (j, p) in exact.iter_mut().enumerate() {
            let CurvePiece::Bezier(p) = p else {
                return Err(inv(
                    format!("curve[{j}]"),
                    "an exact arc with an elliptical pen (its pre-image under M⁻¹ is not a circular arc)",
                ));
            };
            for q in p.iter_mut() {
                *q = pen.pre(q);
            }
        }
        outline = pre_outline(outline, pen)?;
    }
    let mut input = Input::with_pieces(exact, r, "curve")?;
    input.metric = pen.as_ref().map(PenMap::metric);
    input.budget = budget.clone();
    log::debug!(
        "stroke certificate: input and outline read in {:?}",
        t0.elapsed()
    );
    // (a): every piece's parts
    let cov = arr(cover, "cover", "contours")?;
    if cov.len() != outline.len() {
        return Err(inv(
            "cover",
            format!("expected {} contours, as the outline", outline.len()),
        ));
    }
    let cover_at = |(ci, i): (usize, usize)| format!("cover[{ci}][{i}]");
    let mut jobs = Vec::new();
    for (ci, (c, ps)) in cov.iter().zip(&outline).enumerate() {
        let at = format!("cover[{ci}]");
        let per = arr(c, &at, "pieces")?;
        if per.len() != ps.len() {
            return Err(inv(
                at,
                format!("expected {} pieces, as the outline's contour", ps.len()),
            ));
        }
        for (i, (v, p)) in per.iter().zip(ps).enumerate() {
            // (the path is formatted where it is used, `cover_at`: a string
            // per piece alive for the whole check would be part of the peak
            // memory)
            jobs.push(((ci, i), v, p));
        }
    }
    let simple_claimed = match simple_claim {
        Json::Bool(b) => Ok(*b),
        o => Err(inv(
            "simple",
            format!("expected true or false, found {}", o.describe()),
        )),
    };
    let bd = arr(boundary, "boundary", "families");
    // Two strands at once (each parallel inside): (a), every piece's parts
    // read, then their witnesses checked beside (c) when claimed (which needs
    // only the parts' spans and hulls); and the families of ∂S (exact joints
    // included), then (b), every family's cover. The errors are reported in
    // the order of the claims, (a) first, whichever strand finishes first;
    // (c)'s verdict counts only when (a) has passed.
    type StrandA = (
        // (the error boxed: one result per outline piece)
        Vec<Result<(f64, usize), Box<Invalid>>>,
        Option<Result<Vec<bool>, Invalid>>,
    );
    // a failure of (a) is reported before anything of (b): (b) stops once
    // one is seen (its results are then never read)
    let a_failed = std::sync::atomic::AtomicBool::new(false);
    let relaxed = std::sync::atomic::Ordering::Relaxed;
    let ((a, orient), (fams, b)): (StrandA, _) = rayon::join(
        || {
            let reads: Vec<PieceRead> = jobs
                .par_iter()
                .map(|(k, v, p)| read_cover_piece(v, &cover_at(*k), p))
                .collect();
            let all_read = reads.iter().all(|r| r.stop.is_none());
            rayon::join(
                || {
                    reads
                        .par_iter()
                        .zip(jobs.par_iter())
                        .map(|(r, (k, _, _))| {
                            let t = check_read_piece(r, &cover_at(*k), &input, tol_i);
                            if t.is_err() {
                                a_failed.store(true, relaxed);
                            }
                            t.map_err(Box::new)
                        })
                        .collect::<Vec<_>>()
                },
                || {
                    if !(all_read && matches!(simple_claimed, Ok(true))) {
                        return None;
                    }
                    let mut parts: Vec<Vec<simple::PieceParts>> =
                        outline.iter().map(|_| Vec::new()).collect();
                    for (r, ((c, _), _, _)) in reads.iter().zip(&jobs) {
                        parts[*c].push(simple::PieceParts {
                            spans: &r.spans,
                            hulls: Some(&r.hulls),
                        });
                    }
                    Some(
                        simple::simple_with(&outline, &parts, budget)
                            .map_err(|e| inv("simple", format!("claimed, but {e}"))),
                    )
                },
            )
        },
        || {
            let fams = input.families();
            let b = match &bd {
                Ok(bd) if bd.len() == fams.len() => Some(
                    bd.par_iter()
                        .zip(fams.par_iter())
                        .enumerate()
                        .map(|(k, (v, f))| {
                            let at = format!("boundary[{k}]");
                            if a_failed.load(relaxed) {
                                return Err(inv(at, "not checked: claim (a) failed"));
                            }
                            check_family(v, &at, f, &outline, &input, tol_b)
                        })
                        .collect::<Vec<Result<Tally, Invalid>>>(),
                ),
                _ => None,
            };
            (fams, b)
        },
    );
    // (c)'s verdict only once (a) has passed (then every piece was read)
    let orient = if a.iter().all(|t| t.is_ok()) {
        orient
    } else {
        None
    };
    let (mut max, mut count) = (0.0f64, 0usize);
    for t in a {
        let (m, n) = t.map_err(|e| *e)?;
        max = max.max(m);
        count += n;
    }
    log::debug!("stroke certificate: (a) checked at {:?}", t0.elapsed());
    let simple_claimed = simple_claimed?;
    let bd = bd?;
    if bd.len() != fams.len() {
        return Err(inv(
            "boundary",
            format!(
                "expected {} families (both offsets of each of the {} pieces, and the cap and join arcs), found {}",
                fams.len(),
                input.pieces.len(),
                bd.len()
            ),
        ));
    }
    let orient = if simple_claimed {
        Some(orient.expect("(c) ran: (a) passed and simplicity is claimed")?)
    } else {
        None
    };
    let mut max_b = 0.0f64;
    for t in b.expect("(b) ran: the family counts agree") {
        let (m, n) = t?;
        max_b = max_b.max(m);
        count += n;
    }
    log::debug!("stroke certificate: (b), (c) checked at {:?}", t0.elapsed());
    let n_pieces: usize = outline.iter().map(|c| c.len()).sum();
    // a linear map with det M < 0 reverses every contour's orientation
    let orient = orient.map(|o| {
        o.into_iter()
            .map(|ccw| ccw != pen.as_ref().is_some_and(|p| p.det_negative))
            .collect::<Vec<_>>()
    });
    let max = match &pen {
        // h(L → ∂S) ≤ ‖M‖₂ h(M⁻¹L → ∂S′); (b)'s bounds are in the stated
        // coordinates already; the figure is informational
        Some(p) => (max * p.norm_sup).next_up().max(max_b),
        None => max.max(max_b),
    };
    let arcs = outline
        .iter()
        .flatten()
        .filter(|p| matches!(p, OPiece::Arc { .. }))
        .count();
    let comps = input.components();
    Ok(Valid {
        tol: tol_q,
        a: format!(
            "an outline of {} closed contour(s), {} pieces ({} Bézier, {} exact arcs){}",
            outline.len(),
            n_pieces,
            n_pieces - arcs,
            arcs,
            match &orient {
                Some(o) => format!(
                    "; simple and disjoint, {} counter-clockwise and {} clockwise",
                    o.iter().filter(|c| **c).count(),
                    o.iter().filter(|c| !**c).count()
                ),
                None => "; simplicity not claimed".to_string(),
            }
        ),
        b: format!(
            "{}, x = {} in {} component(s) ({} closed)",
            match &pen {
                Some(p) => format!(
                    "∂(x ⊕ M·disk(1)), M = [[{}, {}], [{}, {}]] (checked as the pre-image under M⁻¹ at tol/‖M‖₂)",
                    p.m[0][0], p.m[0][1], p.m[1][0], p.m[1][1]
                ),
                None => format!("∂(x ⊕ disk(r)), r = {}", input.r),
            },
            {
                let arcs = input
                    .pieces
                    .iter()
                    .filter(|p| matches!(p, InPiece::Arc { .. }))
                    .count();
                if arcs == 0 {
                    format!("{} Bézier piece(s)", input.pieces.len())
                } else {
                    format!(
                        "{} piece(s) ({} Bézier, {arcs} exact arcs)",
                        input.pieces.len(),
                        input.pieces.len() - arcs
                    )
                }
            },
            comps.len(),
            comps.iter().filter(|c| c.2).count()
        ),
        max_bound: max,
        boxes: count,
    })
}

#[cfg(test)]
mod arc_tests;
#[cfg(test)]
mod ellipse_tests;
#[cfg(test)]
mod set_tests;
#[cfg(test)]
mod tests;
