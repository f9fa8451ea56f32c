//! Elliptical arcs — SVG path data `A`/`a`, and the `<circle>`, `<ellipse>`
//! and rounded `<rect>` elements — as cubic Bézier pieces with a *certified*
//! bound on their Hausdorff distance from the exact arc.
//!
//! An elliptical arc has (in general) an irrational centre and irrational
//! angles, so lncert's exact polynomial pieces cannot represent it. It is
//! approximated, and the approximation is proven and reported:
//!
//! * **Construction** (floats): SVG's endpoint parameterisation is converted
//!   to the centre parameterisation (SVG 1.1, implementation notes F.6.5, with
//!   the out-of-range radii correction F.6.6); the sweep is split into `n`
//!   equal sub-arcs of at most [`ARC_TARGET_REL`]'s angle, one cubic each (the
//!   usual handles `4/3·tan(δ/4)`). Every control point is the exact rational
//!   `p0 + (offset as float)`, the offset computed in the arc's own frame (so
//!   the rounding is relative to the radius, not to the coordinates). The
//!   first control point is the current point `p0` and the last one the
//!   arc's end point `p1`, exactly as read, and consecutive pieces share their
//!   end point (the same rational): the path stays connected exactly.
//! * **Certificate** (intervals, no float shortcut): with `E = c + A u`,
//!   `|u| = 1`, `A = R(φ) diag(rx, ry)`, every cubic `B` is mapped to the
//!   pre-image `b = A⁻¹(B − c)` and compared with the unit-circle arc from
//!   `u0 = A⁻¹(p0 − c)` to `u1 = A⁻¹(p1 − c)`:
//!   `d_H(B-chain, E-arc) ≤ ‖A‖₂ · max(sup ρ, sup_undecided min(|b − u0|, |b − u1|))`,
//!   `ρ = | |b| − 1 |`, provided every point of the chain has its direction in
//!   the arc's sector widened by a margin. See `proofs/svg-arcs.md` and
//!   `certify_chain` for the argument.
//! * **Report**: every approximated element is listed in an [`InputApprox`]
//!   with its certified bound (rounded up).
//!
//! `n` is chosen so that the bound meets [`ARC_TARGET_REL`]` · max(rx, ry)`
//! (and doubled, at most twice, when the certificate misses it): a half
//! ellipse takes 9 pieces, certified within `3.5·10⁻⁸ · max(rx, ry)`. The
//! target can be missed only where the float construction's rounding,
//! magnified by the axis ratio in the pre-image, dominates — ellipses with
//! an axis ratio beyond about 10⁹ — and the report then says the larger,
//! still certified, bound. F.6.6's decision (are the radii too small?) is
//! exact for rotations by multiples of 90° and for circles; otherwise `Λ` is
//! enclosed to about `2⁻¹²⁰` (its square root, the centre's offset, to
//! `2⁻⁶⁰`), so a half arc with its end points on a diameter costs nothing.

use crate::curve::{bernstein_product, Bezier, V2};
use crate::scalar::{
    abs_le_pow10, interval_from_rational, rational_from_f64, sin_cos_enclosure, Interval, Rational,
};
use num_bigint::BigInt;
use num_traits::{One, Signed, Zero};
use std::f64::consts::{FRAC_PI_2, TAU};

pub(crate) use exact::{axis_ellipse_arc, ellipse, exact_mixed, rational_sqrt, svg_exact_arc};
pub use exact::{ExactElement, ExactPiece};
pub(crate) use near::{attach_near, Layout, Pending};

/// Target of the approximation of an elliptical arc, relative to its larger
/// radius (after the F.6.6 correction): the construction aims at a certified
/// Hausdorff distance `≤ 1e-7 · max(rx, ry)`.
pub const ARC_TARGET_REL: f64 = 1e-7;

/// Largest subdivision depth of one piece's parameter interval in the proof.
const MAX_DEPTH: u32 = 60;
/// Most parameter boxes examined per piece in the proof.
const MAX_BOXES_PER_PIECE: usize = 4096;
/// Most cubic pieces per arc.
const MAX_PIECES_PER_ARC: usize = 1024;

// ---------------------------------------------------------------------------
// The report
// ---------------------------------------------------------------------------

/// What kind of input was approximated.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum ApproxKind {
    /// An elliptical arc command of SVG path data (`A`/`a`).
    Arc,
    /// An SVG `<circle>`.
    Circle,
    /// An SVG `<ellipse>`.
    Ellipse,
    /// An SVG `<rect>` with rounded corners.
    RoundedRect,
    /// An element under `rotate(θ)` with `cos θ` or `sin θ` irrational: mapped
    /// by an exactly rational rotation within a certified angle (its pieces
    /// are exact images, not approximations; the bound is the displacement).
    Rotation,
    /// An element under `skewX(θ)`/`skewY(θ)` with `tan θ` irrational: mapped
    /// by the skew of a rational `t` within a certified `|tan θ − t|`.
    Skew,
    /// A circular arc of SVG path data with an irrational centre, replaced
    /// by a circular arc with a rational centre and radius through the same
    /// end points (its [`NearElement`], as [`crate::stroke::exact_path`]
    /// reports it).
    NearArc,
}

impl ApproxKind {
    fn noun(self) -> &'static str {
        match self {
            ApproxKind::Arc => "SVG arc(s)",
            ApproxKind::Circle => "circle(s)",
            ApproxKind::Ellipse => "ellipse(s)",
            ApproxKind::RoundedRect => "rounded rect(s)",
            ApproxKind::Rotation => "element(s) under an irrational rotate",
            ApproxKind::Skew => "element(s) under an irrational skew",
            ApproxKind::NearArc => "SVG arc(s) with an irrational centre",
        }
    }
    /// An approximated curve (replaced by cubic pieces), rather than an
    /// exactly mapped element under an approximated transform.
    pub fn is_curve(self) -> bool {
        !matches!(
            self,
            ApproxKind::Rotation | ApproxKind::Skew | ApproxKind::NearArc
        )
    }
}

/// One approximated input element.
#[derive(Clone, Debug, PartialEq)]
pub struct ApproxElement {
    /// What it is.
    pub kind: ApproxKind,
    /// Where it is: `byte 12` of path data, or the element of an SVG document
    /// (`svg/g[0]/circle[1]`, `svg/path[0].d, byte 12`).
    pub at: String,
    /// The cubic pieces that replace it (for [`ApproxKind::Rotation`] and
    /// [`ApproxKind::Skew`]: the element's pieces, mapped exactly by the
    /// rational transform).
    pub pieces: usize,
    /// The certified bound: the Hausdorff distance between the pieces and the
    /// exact element is at most this (an `f64` rounded up).
    pub bound: f64,
    /// What was used instead of the exact input, when it is not a cubic
    /// chain (the exact rational rotation or skew and its certified error);
    /// empty for arcs.
    pub detail: String,
    /// The element exactly, as circular arcs (and lines), when its circle
    /// has a rational centre and radius: the shape readers put it in place
    /// of the pieces (see [`ExactElement`]). `None` for ellipses, arcs with
    /// an irrational centre and for [`ApproxKind::Rotation`]/[`ApproxKind::Skew`].
    pub exact: Option<ExactElement>,
    /// For a circular arc with an irrational centre: a circular arc with a
    /// rational centre and radius through the same end points, certified
    /// near the element ([`NearElement`]). Engines that take exact arcs
    /// ([`crate::stroke::exact_path`]) use it in place of the cubic pieces,
    /// and report the element within [`NearElement::bound`] instead.
    pub near: Option<NearElement>,
}

/// Exact pieces (circular arcs and lines with rational data) certified near
/// an element that has no exact form of that kind (a circular SVG arc whose
/// centre is irrational).
#[derive(Clone, Debug, PartialEq)]
pub struct NearElement {
    /// The pieces and the range of the reader's pieces they replace.
    pub element: ExactElement,
    /// The Hausdorff distance between these pieces and the exact element is
    /// at most this (an `f64` rounded up).
    pub bound: f64,
}

/// The report of a curve reader: every input element that was *approximated*
/// (rather than read exactly), with its certified Hausdorff bound. Empty when
/// the curve is exactly the input.
///
/// # Examples
/// ```
/// use lncert::shape::parse_curve_reported;
/// let (pieces, approx) = parse_curve_reported("M 0 0 A 1 1 0 0 1 2 0").unwrap();
/// assert_eq!(approx.elements.len(), 1);
/// assert_eq!(approx.pieces(), pieces.len());
/// assert!(approx.bound() <= 1e-7);
/// let (_, exact) = parse_curve_reported("M 0 0 L 1 1").unwrap();
/// assert!(exact.is_empty() && exact.summary().is_none());
/// ```
#[derive(Clone, Debug, Default, PartialEq)]
pub struct InputApprox {
    /// The approximated elements, in input order.
    pub elements: Vec<ApproxElement>,
}

impl InputApprox {
    /// Nothing was approximated.
    pub fn is_empty(&self) -> bool {
        self.elements.is_empty()
    }
    /// Total cubic pieces that replace approximated curves (arcs, circles,
    /// ellipses, rounded rects).
    pub fn pieces(&self) -> usize {
        self.elements
            .iter()
            .filter(|e| e.kind.is_curve())
            .map(|e| e.pieces)
            .sum()
    }
    /// The overall certified bound: the Hausdorff distance between the curve
    /// read and the exact input is at most this (0 when nothing was approximated).
    pub fn bound(&self) -> f64 {
        self.elements.iter().map(|e| e.bound).fold(0.0, f64::max)
    }
    /// `ε + ε′`, the two overall bounds added and rounded up (`∞` if either is
    /// not finite). For exact shapes `A`, `B` read as `A′`, `B′`, the triangle
    /// inequality gives `|d_H(A, B) − d_H(A′, B′)| ≤ d_H(A, A′) + d_H(B, B′)`:
    /// a bound proven for the shapes read holds for the exact ones up to this.
    ///
    /// # Examples
    /// ```
    /// use lncert::shape::parse_curve_reported;
    /// let (_, arc) = parse_curve_reported("M 0 0 A 1 1 0 0 1 2 0").unwrap();
    /// let (_, line) = parse_curve_reported("M 0 0 L 2 0").unwrap();
    /// assert_eq!(arc.combined_bound(&line), arc.bound());
    /// assert!(arc.combined_bound(&arc) >= 2.0 * arc.bound());
    /// ```
    pub fn combined_bound(&self, other: &InputApprox) -> f64 {
        match (
            Interval::try_from((self.bound(), self.bound())),
            Interval::try_from((other.bound(), other.bound())),
        ) {
            (Ok(x), Ok(y)) => (x + y).sup(),
            _ => f64::INFINITY,
        }
    }
    /// One line for a report, or `None` when nothing was approximated:
    /// `3 SVG arc(s) approximated by 27 cubic pieces, certified within 5.9e-8`.
    pub fn summary(&self) -> Option<String> {
        if self.is_empty() {
            return None;
        }
        let count = |k: ApproxKind| self.elements.iter().filter(|e| e.kind == k).count();
        let what: Vec<String> = [
            ApproxKind::Arc,
            ApproxKind::Circle,
            ApproxKind::Ellipse,
            ApproxKind::RoundedRect,
        ]
        .iter()
        .filter(|&&k| count(k) > 0)
        .map(|&k| format!("{} {}", count(k), k.noun()))
        .collect();
        let mut parts = Vec::new();
        if !what.is_empty() {
            parts.push(format!(
                "{} approximated by {} cubic pieces",
                what.join(", "),
                self.pieces()
            ));
        }
        if count(ApproxKind::NearArc) > 0 {
            parts.push(format!(
                "{} {} replaced by arcs with a rational centre and radius",
                count(ApproxKind::NearArc),
                ApproxKind::NearArc.noun()
            ));
        }
        for k in [ApproxKind::Rotation, ApproxKind::Skew] {
            if let Some(first) = self.elements.iter().find(|e| e.kind == k) {
                parts.push(format!(
                    "{} {} mapped exactly by a rational matrix ({}{})",
                    count(k),
                    k.noun(),
                    first.detail,
                    if count(k) > 1 { ", …" } else { "" }
                ));
            }
        }
        Some(format!(
            "{}, certified within {}",
            parts.join("; "),
            format_up(self.bound())
        ))
    }
    /// `{"elements": n, "bound": x}`, or `null` when nothing was approximated.
    pub fn to_json(&self) -> serde_json::Value {
        if self.is_empty() {
            serde_json::Value::Null
        } else {
            serde_json::json!({"elements": self.elements.len(), "bound": self.bound()})
        }
    }
    pub(crate) fn push(&mut self, e: ApproxElement) {
        self.elements.push(e);
    }
    /// The exact elements' piece indices moved by `by` (their pieces were
    /// appended after `by` others).
    pub(crate) fn shift(&mut self, by: usize) {
        for e in &mut self.elements {
            for x in e
                .exact
                .iter_mut()
                .chain(e.near.iter_mut().map(|n| &mut n.element))
            {
                x.first += by;
            }
        }
    }
    /// Appends `other`'s elements, their places prefixed (`{prefix}, byte 12`)
    /// and their bounds multiplied by `factor` (rounded up).
    pub(crate) fn extend_scaled(&mut self, other: InputApprox, prefix: &str, factor: f64) {
        for mut e in other.elements {
            e.at = if prefix.is_empty() {
                e.at
            } else {
                format!("{prefix}, {}", e.at)
            };
            e.bound = mul_up(e.bound, factor);
            if let Some(n) = &mut e.near {
                n.bound = mul_up(n.bound, factor);
            }
            self.elements.push(e);
        }
    }
}

/// `x · y` rounded up (both ≥ 0).
pub(crate) fn mul_up(x: f64, y: f64) -> f64 {
    if y == 1.0 {
        return x;
    }
    match (Interval::try_from((x, x)), Interval::try_from((y, y))) {
        (Ok(a), Ok(b)) => (a * b).sup(),
        _ => f64::INFINITY,
    }
}

/// A positive number printed with two significant digits, rounded *up*
/// (the printed decimal is ≥ `x`, decided exactly).
///
/// # Examples
/// ```
/// use lncert::shape::format_up;
/// assert_eq!(format_up(2.01e-8), "2.1e-8");
/// assert_eq!(format_up(0.25), "2.5e-1");
/// // the float nearest 2e-8 is a little above it
/// assert_eq!(format_up(2e-8), "2.1e-8");
/// assert_eq!(format_up(9.96e-8), "1.0e-7");
/// ```
pub fn format_up(x: f64) -> String {
    let Some(exact) = rational_from_f64(x).filter(|_| x > 0.0) else {
        return format!("{x:e}");
    };
    let s = format!("{x:.1e}");
    let Some((m, e)) = s.split_once('e') else {
        return s;
    };
    let (Ok(m), Ok(e)) = (m.parse::<f64>(), e.parse::<i32>()) else {
        return s;
    };
    // tenths of the mantissa, then step up until the decimal is ≥ x
    let (mut tenths, mut e) = ((m * 10.0).round() as i64, e);
    for _ in 0..4 {
        let text = format!("{}.{}e{e}", tenths / 10, tenths % 10);
        match crate::scalar::parse_rational(&text) {
            Ok(v) if v >= exact => return text,
            _ => {}
        }
        tenths += 1;
        if tenths >= 100 {
            tenths = 10;
            e += 1;
        }
    }
    format!("{x:e}")
}

// ---------------------------------------------------------------------------
// Interval helpers
// ---------------------------------------------------------------------------

type IV = V2<Interval>;

fn point(x: f64) -> Interval {
    Interval::try_from((x, x)).unwrap_or(Interval::ENTIRE)
}

fn ivr(r: &Rational) -> Interval {
    interval_from_rational(r)
}

fn finite(x: Interval) -> bool {
    !x.is_empty() && x.inf().is_finite() && x.sup().is_finite()
}

fn finite_v(v: &IV) -> bool {
    finite(v.x) && finite(v.y)
}

/// Certainly positive.
fn pos(x: Interval) -> bool {
    !x.is_empty() && x.inf() > 0.0
}

fn dot(a: &IV, b: &IV) -> Interval {
    a.x * b.x + a.y * b.y
}

fn cross(a: &IV, b: &IV) -> Interval {
    a.x * b.y - a.y * b.x
}

/// `v` rotated by the angle whose cosine and sine are `(c, s)`.
fn rotate(v: &IV, c: Interval, s: Interval) -> IV {
    V2::new(c * v.x - s * v.y, s * v.x + c * v.y)
}

fn hull(xs: &[Interval]) -> Interval {
    xs.iter()
        .copied()
        .reduce(Interval::convex_hull)
        .unwrap_or(Interval::EMPTY)
}

/// De Casteljau at `t = 1/2` (interval coefficients; outward rounded).
fn halve(c: &[Interval]) -> (Vec<Interval>, Vec<Interval>) {
    let half = point(0.5);
    let mut work = c.to_vec();
    let n = work.len();
    let mut left = Vec::with_capacity(n);
    let mut right = vec![Interval::EMPTY; n];
    for k in 0..n {
        left.push(work[0]);
        right[n - 1 - k] = work[n - 1 - k];
        for i in 0..n - 1 - k {
            work[i] = (work[i] + work[i + 1]) * half;
        }
    }
    (left, right)
}

// ---------------------------------------------------------------------------
// The arc in its centre parameterisation
// ---------------------------------------------------------------------------

/// An elliptical arc `E(θ) = c + A (cos θ, sin θ)`, `A = R(φ) diag(rx, ry)`,
/// from `u0` to `u1` on the unit circle (the pre-image), in enclosures of the
/// exact values; plus float hints for the construction.
#[derive(Clone, Debug)]
struct Frame {
    /// `cos φ`, `sin φ`.
    cos: Interval,
    sin: Interval,
    /// The radii after the F.6.6 correction (> 0).
    rx: Interval,
    ry: Interval,
    /// `A⁻¹(p0 − c)` and `A⁻¹(p1 − c)`: exactly on the unit circle.
    u0: IV,
    u1: IV,
    /// Increasing angle (SVG's sweep flag 1) or decreasing.
    ccw: bool,
    /// The sweep's magnitude in `(0, 2π)`, as a float (construction only).
    sweep: f64,
}

impl Frame {
    /// `A⁻¹ v`.
    fn inv(&self, v: &IV) -> IV {
        V2::new(
            (self.cos * v.x + self.sin * v.y) / self.rx,
            (self.cos * v.y - self.sin * v.x) / self.ry,
        )
    }
    /// `‖A‖₂ = max(rx, ry)` (a rotation times a diagonal), bounded above.
    fn norm_sup(&self) -> f64 {
        self.rx.sup().max(self.ry.sup())
    }
    fn check(&self) -> Result<(), String> {
        let ok = [self.cos, self.sin, self.rx, self.ry]
            .into_iter()
            .all(finite)
            && finite_v(&self.u0)
            && finite_v(&self.u1)
            && pos(self.rx)
            && pos(self.ry)
            && self.sweep.is_finite();
        if !ok {
            return Err(RANGE.to_string());
        }
        if self.norm_sup() > crate::shape::MAX_COORDINATE {
            return Err(format!(
                "the arc's ellipse (radii {:.3e}, {:.3e} after the SVG out-of-range radii correction) is larger than the coordinate limit 1e100",
                self.rx.mid(),
                self.ry.mid()
            ));
        }
        Ok(())
    }
}

const RANGE: &str = "the arc's radii and end points are too far apart in scale to compute its centre (values beyond the float range)";

/// The outcome of an SVG arc command.
#[derive(Clone, Debug, PartialEq)]
pub(crate) enum SvgArc {
    /// Identical end points: the arc is omitted (SVG F.6.2).
    Omitted,
    /// `rx = 0` or `ry = 0`: a straight line to the end point (F.6.2).
    Line,
    /// The cubic pieces and their certified Hausdorff bound.
    Cubics {
        pieces: Vec<Bezier<Rational>>,
        bound: f64,
    },
}

/// The exact cosine and sine of a multiple of 90° (`deg` in `[0, 360)`).
fn quarter(deg: &Rational) -> Option<(Rational, Rational)> {
    let (o, z) = (Rational::one(), Rational::zero());
    let n = |k: i64| Rational::from_integer(k.into());
    if *deg == n(0) {
        Some((o, z))
    } else if *deg == n(90) {
        Some((z, o))
    } else if *deg == n(180) {
        Some((-o, z))
    } else if *deg == n(270) {
        Some((z, -o))
    } else {
        None
    }
}

/// An SVG elliptical arc from the current point `p0` to `p1` (`rx ry
/// x-axis-rotation large-arc-flag sweep-flag`), per SVG 1.1 F.6.5 and F.6.6:
/// omitted for identical end points, a line for a zero radius, otherwise the
/// certified cubic pieces. Errors are reasons (the caller adds the place).
pub(crate) fn svg_arc(
    p0: &V2<Rational>,
    rx: &Rational,
    ry: &Rational,
    phi: &Rational,
    large: bool,
    sweep: bool,
    p1: &V2<Rational>,
) -> Result<SvgArc, String> {
    match svg_frame(p0, rx, ry, phi, large, sweep, p1)? {
        Err(special) => Ok(special),
        Ok(frame) => {
            let (pieces, bound) = approximate(&frame, p0, p1)?;
            Ok(SvgArc::Cubics { pieces, bound })
        }
    }
}

/// A circular arc of radius `r > 0` from `p0` to `p1` (SVG's `A r r 0 large
/// sweep p1` from `p0`; `sweep` true = increasing angle, counter-clockwise in
/// y-up coordinates) as cubic pieces, with the certified Hausdorff bound of the
/// pieces from the exact arc ([`ARC_TARGET_REL`]` · r` targeted). The first
/// and last control points are `p0` and `p1` exactly. Empty when `p0 = p1`.
///
/// Errors: the reason (a radius too small for the chord is enlarged by SVG's
/// rule, so callers with `p0`, `p1` on the circle get the arc itself).
pub fn circular_arc_cubics(
    p0: &V2<Rational>,
    r: &Rational,
    large: bool,
    sweep: bool,
    p1: &V2<Rational>,
) -> Result<(Vec<Bezier<Rational>>, f64), String> {
    match svg_arc(p0, r, r, &Rational::zero(), large, sweep, p1)? {
        SvgArc::Omitted => Ok((Vec::new(), 0.0)),
        SvgArc::Line => Err("the radius must be > 0".into()),
        SvgArc::Cubics { pieces, bound } => Ok((pieces, bound)),
    }
}

/// [`svg_arc`]'s centre parameterisation (F.6.5, F.6.6), or the special
/// cases (omitted, line).
fn svg_frame(
    p0: &V2<Rational>,
    rx: &Rational,
    ry: &Rational,
    phi: &Rational,
    large: bool,
    sweep: bool,
    p1: &V2<Rational>,
) -> Result<Result<Frame, SvgArc>, String> {
    if p0 == p1 {
        return Ok(Err(SvgArc::Omitted));
    }
    let (rx, ry) = (rx.abs(), ry.abs());
    if rx.is_zero() || ry.is_zero() {
        return Ok(Err(SvgArc::Line));
    }
    for (r, name) in [(&rx, "rx"), (&ry, "ry")] {
        if !abs_le_pow10(r, 100) {
            return Err(format!(
                "the arc's radius {name} is larger than the coordinate limit 1e100"
            ));
        }
    }
    let two = Rational::from_integer(2.into());
    // (x1', y1') before rotation: half the chord, p0 − p1 over 2
    let (hx, hy) = ((&p0.x - &p1.x) / &two, (&p0.y - &p1.y) / &two);
    if !abs_le_pow10(&hx, 100) || !abs_le_pow10(&hy, 100) {
        return Err(
            "the arc's end points are farther apart than the coordinate limit 1e100".into(),
        );
    }
    // φ mod 360, exactly; a circle's rotation does not matter
    let deg360 = Rational::from_integer(360.into());
    let phi = if rx == ry {
        Rational::zero()
    } else {
        phi - &deg360 * (phi / &deg360).floor()
    };
    let sigma = if large != sweep { 1.0 } else { -1.0 };
    let sigma_i = point(sigma);
    // The pre-image of the half chord under diag(rx, ry): z = (x1'/rx, y1'/ry),
    // Λ = |z|² (F.6.6). u0 = ẑ + σ q J ẑ, u1 = −ẑ + σ q J ẑ with ẑ = z / max(1, |z|),
    // q = √((1 − |ẑ|²)/|ẑ|²), J the quarter turn: F.6.5.2–3 divided by the radii.
    // `scale` = max(1, √Λ), the F.6.6 factor of the radii
    let (cos, sin, z, lam_f, q, scale) = match quarter(&phi) {
        Some((c, s)) => {
            // Exact: Λ is rational, the F.6.6 decision is exact.
            let a = (&c * &hx + &s * &hy) / &rx;
            let b = (&c * &hy - &s * &hx) / &ry;
            let lam = &a * &a + &b * &b;
            let one = Rational::one();
            let (scale, q) = if lam > one {
                (ivr(&lam).sqrt(), point(0.0))
            } else if lam == one {
                (point(1.0), point(0.0))
            } else {
                (point(1.0), ivr(&((&one - &lam) / &lam)).sqrt())
            };
            let z = V2::new(ivr(&a) / scale, ivr(&b) / scale);
            (ivr(&c), ivr(&s), z, ivr(&lam).mid(), q, scale)
        }
        None => {
            // cos φ, sin φ to ~2⁻¹²⁰ and Λ exactly from them: the centre's
            // √((1 − Λ)/Λ) is ill-conditioned where Λ ≈ 1 (a half arc), so Λ
            // is enclosed far below the float resolution
            let (c, s) = rotation_enclosure(&phi);
            let (inv_rx, inv_ry) = (Rational::one() / &rx, Rational::one() / &ry);
            let a = c.scale(&hx).add(&s.scale(&hy)).scale(&inv_rx);
            let b = c.scale(&hy).add(&s.scale(&hx).neg()).scale(&inv_ry);
            let lam = a.sqr().add(&b.sqr());
            let (ai, bi, lam_i) = (a.interval(), b.interval(), lam.interval());
            let one = Rational::one();
            if !finite(ai) || !finite(bi) || !finite(lam_i) || !lam.lo.is_positive() {
                return Err(RANGE.into());
            }
            // (1 − Λ)/Λ decreases with Λ
            let q2 = |l: &Rational| ivr(&((&one - l) / l));
            let (q, scale) = if lam.lo > one {
                (point(0.0), lam_i.sqrt())
            } else if lam.hi < one {
                (q2(&lam.hi).convex_hull(q2(&lam.lo)).sqrt(), point(1.0))
            } else {
                // Λ = 1 within ~2⁻¹²⁰: both F.6.6 branches at once (both
                // formulas are continuous there)
                let top = q2(&lam.lo).sup();
                let q = Interval::try_from((0.0, top)).unwrap_or(Interval::ENTIRE);
                (q.sqrt(), lam_i.max(point(1.0)).sqrt())
            };
            let z = V2::new(ai / scale, bi / scale);
            (c.interval(), s.interval(), z, lam_i.mid(), q, scale)
        }
    };
    let jz = V2::new(-z.y, z.x);
    let sq = sigma_i * q;
    let u0 = V2::new(z.x + sq * jz.x, z.y + sq * jz.y);
    let u1 = V2::new(-z.x + sq * jz.x, -z.y + sq * jz.y);
    // |Δθ|: 2·asin|ẑ| for the small arc, 2π minus that for the large one; π
    // when the radii were scaled up
    let half = if lam_f >= 1.0 {
        FRAC_PI_2
    } else {
        lam_f.sqrt().min(1.0).asin()
    };
    let sweep_abs = if large && lam_f < 1.0 {
        TAU - 2.0 * half
    } else {
        2.0 * half
    };
    let frame = Frame {
        cos,
        sin,
        rx: ivr(&rx) * scale,
        ry: ivr(&ry) * scale,
        u0,
        u1,
        ccw: sweep,
        sweep: sweep_abs,
    };
    frame.check()?;
    Ok(Ok(frame))
}

/// [`axis_arc`]'s pieces, their certified bound and the exact end point.
pub(crate) type AxisArc = (Vec<Bezier<Rational>>, f64, V2<Rational>);

/// The arc of the axis-aligned ellipse `((x − cx)/rx)² + ((y − cy)/ry)² = 1`
/// from the end of its axis direction `start` (0: +x, 1: +y, 2: −x, 3: −y)
/// through `quarters` quarter turns of increasing angle (counter-clockwise
/// in the user coordinate system, from +x towards +y). Returns the pieces,
/// the certified bound, and the exact end point.
pub(crate) fn axis_arc(
    c: &V2<Rational>,
    rx: &Rational,
    ry: &Rational,
    start: u8,
    quarters: u8,
) -> Result<AxisArc, String> {
    if !rx.is_positive() || !ry.is_positive() {
        return Err("the radii must be > 0".into());
    }
    if !abs_le_pow10(rx, 100) || !abs_le_pow10(ry, 100) {
        return Err("a radius is larger than the coordinate limit 1e100".into());
    }
    if !(1..=3).contains(&quarters) {
        return Err("internal error: 1 to 3 quarter turns".into());
    }
    let unit = |k: u8| -> (i64, i64) {
        match k % 4 {
            0 => (1, 0),
            1 => (0, 1),
            2 => (-1, 0),
            _ => (0, -1),
        }
    };
    let at = |k: u8| {
        let (ex, ey) = unit(k);
        V2::new(
            &c.x + rx * Rational::from_integer(ex.into()),
            &c.y + ry * Rational::from_integer(ey.into()),
        )
    };
    let iv = |k: u8| {
        let (ex, ey) = unit(k);
        V2::new(point(ex as f64), point(ey as f64))
    };
    let (p0, p1) = (at(start), at(start + quarters));
    let frame = Frame {
        cos: point(1.0),
        sin: point(0.0),
        rx: ivr(rx),
        ry: ivr(ry),
        u0: iv(start),
        u1: iv(start + quarters),
        ccw: true,
        sweep: FRAC_PI_2 * quarters as f64,
    };
    frame.check()?;
    let (pieces, bound) = approximate(&frame, &p0, &p1)?;
    Ok((pieces, bound, p1))
}

// ---------------------------------------------------------------------------
// cos φ and sin φ to 120 bits
// ---------------------------------------------------------------------------

/// Bits of the fixed-point grid of [`rotation_enclosure`]'s series.
const TRIG_BITS: usize = 128;

/// π to 50 decimals; the truncation error is below `10⁻⁵⁰`.
const PI_50: &str = "3.14159265358979323846264338327950288419716939937510";

/// A closed interval `[lo, hi]` of exact rationals.
#[derive(Clone, Debug)]
struct RatInterval {
    lo: Rational,
    hi: Rational,
}

impl RatInterval {
    fn add(&self, o: &RatInterval) -> RatInterval {
        RatInterval {
            lo: &self.lo + &o.lo,
            hi: &self.hi + &o.hi,
        }
    }
    fn neg(&self) -> RatInterval {
        RatInterval {
            lo: -&self.hi,
            hi: -&self.lo,
        }
    }
    /// Times an exact rational.
    fn scale(&self, k: &Rational) -> RatInterval {
        let (a, b) = (&self.lo * k, &self.hi * k);
        if k.is_negative() {
            RatInterval { lo: b, hi: a }
        } else {
            RatInterval { lo: a, hi: b }
        }
    }
    fn sqr(&self) -> RatInterval {
        let (a, b) = (&self.lo * &self.lo, &self.hi * &self.hi);
        if !self.lo.is_positive() && !self.hi.is_negative() {
            RatInterval {
                lo: Rational::zero(),
                hi: a.max(b),
            }
        } else {
            RatInterval {
                lo: a.clone().min(b.clone()),
                hi: a.max(b),
            }
        }
    }
    /// The tightest float interval containing it.
    fn interval(&self) -> Interval {
        ivr(&self.lo).convex_hull(ivr(&self.hi))
    }
}

/// `sin x` and `cos x` for `x ∈ [lo, hi]·2^-TRIG_BITS ⊂ [0, 0.8]` (`lo`, `hi`
/// nonnegative integers): Taylor series in fixed point, every product
/// rounded outward, plus the alternating series' remainder (bounded by its
/// next term: the terms decrease since `x < 1`).
fn sin_cos_series(lo: &BigInt, hi: &BigInt) -> (RatInterval, RatInterval) {
    let one = BigInt::one() << TRIG_BITS;
    // a·b·2^-P / d rounded down or up, for a, b ≥ 0
    let down = |a: &BigInt, b: &BigInt, d: u32| ((a * b) >> TRIG_BITS) / BigInt::from(d);
    let up = |a: &BigInt, b: &BigInt, d: u32| {
        let p: BigInt = a * b;
        let q: BigInt = (p + &one - 1) >> TRIG_BITS;
        (q + BigInt::from(d - 1)) / BigInt::from(d)
    };
    let (x2_lo, x2_hi) = (down(lo, lo, 1), up(hi, hi, 1));
    let series = |first: (BigInt, BigInt), start: u32| {
        let (mut t_lo, mut t_hi) = first;
        let (mut s_lo, mut s_hi) = (t_lo.clone(), t_hi.clone());
        let mut n = start;
        for k in 1..=24 {
            let d = (n + 1) * (n + 2);
            t_lo = down(&t_lo, &x2_lo, d);
            t_hi = up(&t_hi, &x2_hi, d);
            n += 2;
            if k % 2 == 1 {
                s_lo -= &t_hi;
                s_hi -= &t_lo;
            } else {
                s_lo += &t_lo;
                s_hi += &t_hi;
            }
        }
        let next = up(&t_hi, &x2_hi, (n + 1) * (n + 2));
        let g = Rational::from_integer(one.clone());
        RatInterval {
            lo: Rational::from_integer(s_lo - &next) / &g,
            hi: Rational::from_integer(s_hi + &next) / &g,
        }
    };
    (
        series((lo.clone(), hi.clone()), 1),
        series((one.clone(), one.clone()), 0),
    )
}

/// `cos φ` and `sin φ` for `φ` in degrees, `[0, 360)`, enclosed to about
/// `2⁻¹²⁰`: the quadrant and octant exactly, then [`sin_cos_series`] on
/// `[0, π/4]` with `π` from [`PI_50`].
fn rotation_enclosure(deg: &Rational) -> (RatInterval, RatInterval) {
    let n = |k: i64| Rational::from_integer(k.into());
    let quadrant = (deg / n(90)).floor();
    let t = deg - &quadrant * n(90);
    let (t, swap) = if t > n(45) {
        (n(90) - t, true)
    } else {
        (t, false)
    };
    let pi = crate::scalar::parse_rational(PI_50).unwrap_or_else(|_| n(3));
    let pi_hi = &pi + Rational::new(1.into(), num_traits::pow(BigInt::from(10), 50));
    // x = t·π/180 on the grid 2^-TRIG_BITS, rounded outward
    let g = Rational::from_integer(BigInt::one() << TRIG_BITS);
    let x_lo = (&t * &pi / n(180) * &g).floor().to_integer();
    let x_hi = (&t * &pi_hi / n(180) * &g).ceil().to_integer();
    let (s, c) = sin_cos_series(&x_lo, &x_hi);
    // angle 90°·quadrant + t (or + 90° − t when swapped)
    let (s, c) = if swap { (c, s) } else { (s, c) };
    let four = BigInt::from(4);
    let q: BigInt = (quadrant.to_integer() % &four + &four) % &four;
    match q.to_string().as_str() {
        "0" => (c, s),
        "1" => (s.neg(), c),
        "2" => (c.neg(), s.neg()),
        _ => (s, c.neg()),
    }
}

// ---------------------------------------------------------------------------
// Construction
// ---------------------------------------------------------------------------

/// The radial error of the `4/3·tan(δ/4)` cubic of a unit-circle arc of
/// angle `δ`: `(2/27)·sin⁶(δ/4)/cos²(δ/4)` (a float estimate that chooses
/// `n`; the proof does not use it).
fn cubic_error_estimate(delta: f64) -> f64 {
    let q = delta.abs() / 4.0;
    2.0 / 27.0 * q.sin().powi(6) / q.cos().powi(2)
}

/// The pieces and, for the proof, each control point's offset from `p0`
/// (enclosures of the exact rational offsets).
///
/// Consecutive pieces are **exactly G¹**: at an interior joint `J` the two
/// handles are `J − T` and `J + T` for one rational vector `T`, so the
/// incoming and outgoing tangents are exactly parallel (an offset or stroke
/// of the path sees a smooth joint, not a corner of float-rounding size).
/// A tangent whose component is below `2⁻⁵⁰` of the other (an axis point of
/// an axis-aligned ellipse, where `cos(π/2)` rounds to `6·10⁻¹⁷`) is made
/// exactly axis-parallel, so `<circle>`, `<ellipse>` and `<rect rx>` quarters
/// join each other and the rectangle's edges with exact G¹ too. Neither
/// choice needs trust: the certificate is computed on the pieces as built.
#[allow(clippy::type_complexity)]
fn construct(
    fr: &Frame,
    n: usize,
    p0: &V2<Rational>,
    p1: &V2<Rational>,
) -> Result<(Vec<Bezier<Rational>>, Vec<[IV; 4]>), String> {
    let (c, s, rx, ry) = (fr.cos.mid(), fr.sin.mid(), fr.rx.mid(), fr.ry.mid());
    let th0 = fr.u0.y.mid().atan2(fr.u0.x.mid());
    let dir = if fr.ccw { 1.0 } else { -1.0 };
    let delta = dir * fr.sweep / n as f64;
    let kappa = 4.0 / 3.0 * (delta / 4.0).tan();
    // A·(x, y)
    let a_map = |x: f64, y: f64| (c * rx * x - s * ry * y, s * rx * x + c * ry * y);
    // the joints e(θk) − e(θ0) (by the difference formula: no cancellation)
    // and the unit tangents e′(θk), in the pre-image
    let joint = |k: usize| {
        let d = delta * k as f64;
        let chord = 2.0 * (d / 2.0).sin();
        let mid = th0 + d / 2.0;
        (
            (-chord * mid.sin(), chord * mid.cos()),
            (-(th0 + d).sin(), (th0 + d).cos()),
        )
    };
    let exact = |x: f64| {
        rational_from_f64(x).ok_or_else(|| {
            "the arc's construction left the float range (radii or coordinates too large)"
                .to_string()
        })
    };
    // the handle vector κ·A·e′(θk), exactly axis-parallel when nearly so
    let handle = |k: usize| -> Result<V2<Rational>, String> {
        let (_, (tx, ty)) = joint(k);
        let (mut hx, mut hy) = a_map(kappa * tx, kappa * ty);
        let tiny = f64::powi(2.0, -50);
        if hx.abs() < tiny * hy.abs() {
            hx = 0.0;
        } else if hy.abs() < tiny * hx.abs() {
            hy = 0.0;
        }
        Ok(V2::new(exact(hx)?, exact(hy)?))
    };
    let off = |q: &V2<Rational>| V2::new(ivr(&(&q.x - &p0.x)), ivr(&(&q.y - &p0.y)));
    let mut joints = Vec::with_capacity(n + 1);
    joints.push(p0.clone());
    for k in 1..n {
        let ((wx, wy), _) = joint(k);
        let (ox, oy) = a_map(wx, wy);
        joints.push(V2::new(&p0.x + exact(ox)?, &p0.y + exact(oy)?));
    }
    joints.push(p1.clone());
    let handles = (0..=n).map(handle).collect::<Result<Vec<_>, _>>()?;
    let mut pieces = Vec::with_capacity(n);
    let mut offs = Vec::with_capacity(n);
    for k in 0..n {
        let pts = vec![
            joints[k].clone(),
            joints[k].add(&handles[k]),
            joints[k + 1].sub(&handles[k + 1]),
            joints[k + 1].clone(),
        ];
        offs.push([off(&pts[0]), off(&pts[1]), off(&pts[2]), off(&pts[3])]);
        pieces.push(Bezier::new(pts));
    }
    Ok((pieces, offs))
}

/// Chooses `n`, builds and certifies; doubles `n` (at most twice) when the
/// certified bound misses the target. Returns the pieces and the bound on
/// their Hausdorff distance from the exact arc.
fn approximate(
    fr: &Frame,
    p0: &V2<Rational>,
    p1: &V2<Rational>,
) -> Result<(Vec<Bezier<Rational>>, f64), String> {
    // the target in the pre-image (‖A‖ = max(rx, ry)), a little inside
    let tau = ARC_TARGET_REL * 0.999;
    let mut n = 1usize;
    while n < MAX_PIECES_PER_ARC && cubic_error_estimate(fr.sweep / n as f64) > tau / 2.0 {
        n += 1;
    }
    let mut tries = 0;
    loop {
        let (pieces, offs) = construct(fr, n, p0, p1)?;
        // aim a little above the construction's error (not below τ/16:
        // tiny arcs need no tighter bound than that)
        let goal = (1.25 * cubic_error_estimate(fr.sweep / n as f64))
            .max(tau / 16.0)
            .min(tau);
        let pre = certify_chain(fr, &offs, goal)?;
        if pre <= tau || tries == 2 || 2 * n > MAX_PIECES_PER_ARC {
            let bound = (point(pre) * point(fr.norm_sup())).sup();
            return Ok((pieces, bound));
        }
        n *= 2;
        tries += 1;
    }
}

// ---------------------------------------------------------------------------
// The proof
// ---------------------------------------------------------------------------

/// A sector of directions, counter-clockwise from `e0` to `e1` (unit vectors,
/// enclosed) through an angle `Δ ∈ (0, 2π)`.
struct Sector {
    e0: IV,
    e1: IV,
    /// A positive multiple of the bisecting direction: `(e1 − e0)` turned by −90°.
    m: IV,
    /// `Δ > π`, certified (`cross(e0, e1) < 0`).
    wide: bool,
}

impl Sector {
    fn new(e0: IV, e1: IV) -> Sector {
        let d = e1.sub(&e0);
        let m = V2::new(d.y, -d.x);
        let wide = {
            let c = cross(&e0, &e1);
            !c.is_empty() && c.sup() < 0.0
        };
        Sector { e0, e1, m, wide }
    }
    /// Every point of the convex hull of `pts` (the control points of a
    /// piece of `b`) is nonzero with its direction inside the sector,
    /// certified. With the open half-planes (so `0` is in none)
    /// `H1 = {cross(e0, v) > 0}`, `H2 = {cross(v, e1) > 0}`, `H0 = {dot(m, v) > 0}`:
    /// the sector contains `H1 ∩ H2` always (it *is* that for `Δ ≤ π`), and
    /// each of `H0`, `H1`, `H2` when `Δ ≥ π`; a half-plane is convex, so it
    /// holds the hull when it holds every control point.
    fn contains(&self, pts: &[IV]) -> bool {
        let all = |f: &dyn Fn(&IV) -> Interval| pts.iter().all(|v| pos(f(v)));
        let h1 = || all(&|v| cross(&self.e0, v));
        let h2 = || all(&|v| cross(v, &self.e1));
        if self.wide {
            h1() || h2() || all(&|v| dot(&self.m, v))
        } else {
            h1() && h2()
        }
    }
}

/// One parameter box of one piece: the pre-image's Bernstein coefficients
/// (`x`, `y`, degree 3) and those of `f = |b|² − 1` (degree 6).
struct PBox {
    x: Vec<Interval>,
    y: Vec<Interval>,
    f: Vec<Interval>,
    depth: u32,
}

impl PBox {
    fn split(&self) -> (PBox, PBox) {
        let (xl, xr) = halve(&self.x);
        let (yl, yr) = halve(&self.y);
        let (fl, fr) = halve(&self.f);
        let d = self.depth + 1;
        (
            PBox {
                x: xl,
                y: yl,
                f: fl,
                depth: d,
            },
            PBox {
                x: xr,
                y: yr,
                f: fr,
                depth: d,
            },
        )
    }
}

/// Certifies the chain of pieces (control points given as offsets from `p0`)
/// against the exact arc of `fr`, in the pre-image; returns
/// `D ≥ d_H(b-chain, unit arc)`, so that `d_H(B-chain, E-arc) ≤ ‖A‖₂ D`.
///
/// **Why.** Let `S` be the arc's sector of directions and `S′ ⊃ S` the sector
/// widened by a margin `μ` on both sides, with `Δ + 2μ < 2π` certified. The
/// chain `b` is continuous (the pieces share end points exactly) from `u0`
/// to `u1`, and every box of every piece is certified to lie in `S′` (so `b ≠ 0`).
///
/// (a) *chain → arc*: a chain point `v` with direction in `S` is within
/// `||v| − 1|` of the arc (its radial projection `v/|v|` is an arc point); any
/// chain point is within `min(|v − u0|, |v − u1|)` of the arc (the end points
/// are arc points). On boxes certified inside `S` the box's bound is `sup ρ`;
/// elsewhere the larger of both terms, since one of them applies.
///
/// (b) *arc → chain*: the lifted angle of `b(t)` is continuous, starts at
/// `θ0` and stays in the lift `[θ0 − μ, θ0 + Δ + μ]` of `S′` (it cannot jump
/// to another lift: those are disjoint intervals since `S′` is not the whole
/// circle); it ends at an angle `≡ θ0 + Δ` in that interval, which is
/// `θ0 + Δ` itself since `Δ + 2μ < 2π`. By the intermediate value theorem
/// every direction of the arc is attained: every arc point `w` is `v/|v|` for
/// a chain point `v`, at distance `||v| − 1| ≤ sup ρ`.
///
/// `ρ` on a box is bounded by the hull of the Bernstein coefficients of
/// `|b|² − 1`; the sector tests are open half-planes holding every control
/// point of `b` on the box, and `|b − u0|` is at most its largest value at a
/// control point (convex hull property); every quantity is an interval
/// enclosure of the exact one (the exact centre, radii, `cos φ`, `sin φ`,
/// `u0`, `u1` lie in theirs), so the conclusions hold for the exact arc.
fn certify_chain(fr: &Frame, offs: &[[IV; 4]], goal: f64) -> Result<f64, String> {
    // a clockwise arc is the mirror image (y ↦ −y) of a counter-clockwise one
    let mirror = |v: IV| if fr.ccw { v } else { V2::new(v.x, -v.y) };
    let u0 = mirror(fr.u0.clone());
    let u1 = mirror(fr.u1.clone());
    let exact = Sector::new(u0.clone(), u1.clone());
    // the margin μ = min(0.1, gap/4), and Δ + 2μ < 2π certified: either Δ < π
    // (then 2μ ≤ 0.2 < π < gap), or cos 2μ > cos Δ = dot(u0, u1) with 2μ < π
    // (cos decreasing on [0, π]: 2μ < gap when gap ≤ π)
    let margin = (0.1f64).min((TAU - fr.sweep) / 4.0);
    if margin.is_nan() || margin <= 1e-300 {
        return Err("the arc is closed or nearly closed (its end points coincide to rounding): no certified approximation".to_string());
    }
    let (sm, cm) = sin_cos_enclosure(point(margin));
    let (_, c2m) = sin_cos_enclosure(point(2.0 * margin));
    let narrow = pos(cross(&u0, &u1));
    if !(narrow || pos(c2m - dot(&u0, &u1))) {
        return Err("the arc nearly closes (its end points are too close for the certified sector test); split it in two".to_string());
    }
    let widened = Sector::new(rotate(&u0, cm, -sm), rotate(&u1, cm, sm));

    let mut sup = 0.0f64;
    for off in offs {
        let b: Vec<IV> = off.iter().map(|o| mirror(fr.u0.add(&fr.inv(o)))).collect();
        if !b.iter().all(finite_v) {
            return Err("the arc's pre-image left the float range".to_string());
        }
        let x: Vec<Interval> = b.iter().map(|p| p.x).collect();
        let y: Vec<Interval> = b.iter().map(|p| p.y).collect();
        let one = point(1.0);
        let f: Vec<Interval> = bernstein_product(&x, &x)
            .into_iter()
            .zip(bernstein_product(&y, &y))
            .map(|(a, b)| a + b - one)
            .collect();
        // what subdivision cannot remove: the rounding in the coefficients
        let noise = 16.0
            * x.iter()
                .chain(&y)
                .chain(&f)
                .map(|c| c.wid())
                .fold(0.0, f64::max)
            + 1e-15;
        let target = goal.max(noise);
        // breadth first: if the budget runs out, the cover is uniformly fine
        let mut queue = std::collections::VecDeque::from([PBox { x, y, f, depth: 0 }]);
        let mut boxes = 0usize;
        while let Some(bx) = queue.pop_front() {
            boxes += 1;
            let can_split = bx.depth < MAX_DEPTH && boxes + queue.len() < MAX_BOXES_PER_PIECE;
            let pts: Vec<IV> =
                bx.x.iter()
                    .zip(&bx.y)
                    .map(|(&x, &y)| V2::new(x, y))
                    .collect();
            if !widened.contains(&pts) {
                if can_split {
                    let (l, r) = bx.split();
                    queue.extend([l, r]);
                    continue;
                }
                return Err("the certified sector test failed (the arc is too thin or too degenerate for this construction)".to_string());
            }
            // ρ = ||b| − 1| with |b|² ∈ 1 + hull(f)
            let norm = (hull(&bx.f) + one).max(point(0.0)).sqrt();
            let mut bound = (norm - one).abs().sup();
            if !exact.contains(&pts) {
                // |v − u| is convex: its largest value on the hull is at a
                // control point
                let far = |u: &IV| {
                    pts.iter()
                        .map(|v| ((v.x - u.x).sqr() + (v.y - u.y).sqr()).sqrt().sup())
                        .fold(0.0, f64::max)
                };
                bound = bound.max(far(&u0).min(far(&u1)));
            }
            if (bound.is_nan() || bound > target) && can_split {
                let (l, r) = bx.split();
                queue.extend([l, r]);
                continue;
            }
            if !bound.is_finite() {
                return Err("the certified bound is not finite".to_string());
            }
            sup = sup.max(bound);
        }
    }
    Ok(sup)
}

mod exact;
mod near;
#[cfg(test)]
mod tests;
