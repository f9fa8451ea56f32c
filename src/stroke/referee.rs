//! The referee: certified bounds on the Hausdorff distance between **any**
//! outline (kurbo's, Skia's, a font editor's, your own) and the exact boundary
//! `∂S` of a stroke `S = x ⊕ pen`.
//!
//! `∂S` has irrational crossing parameters, so it is not a shape the
//! certification engine can take directly. The referee strokes the curve with
//! lncert's proven stroker at a tolerance `ε` of its own, giving an outline `L`
//! with claims (a) `h(L, ∂S) ≤ a` and (b) `h(∂S, L) ≤ b` proven, and bounds the
//! two one-sided distances between the outline `X` under test and `L` with the
//! certified search. The triangle inequality (`h(X, Y) = sup_{x ∈ X} dist(x, Y)`)
//! then gives, each end rounded outward:
//!
//! ```text
//! h(X, L) − b ≤ h(X, ∂S) ≤ h(X, L) + a
//! h(L, X) − a ≤ h(∂S, X) ≤ h(L, X) + b
//! ```
//!
//! and `d_H(X, ∂S)` is the larger of the two. Nothing here is sampled: the
//! bounds are as sound as the stroke's claims and the search's covers. When
//! (a) or (b) is not proven the distance is reported as `[0, ∞]` (undecided),
//! never estimated. The proof is in `proofs/trimming.md` ("The referee").

use super::trim::{stroke, Cap, PenShape, Stroke, StrokeOptions};
use crate::certify::{hausdorff_each_direction, Config, HausdorffBounds};
use crate::curve::Bezier;
use crate::offset::conv::Pen;
use crate::scalar::{interval_from_rational, Rational};
use crate::shape::{
    check_keys, curve_value, number, parse_json_value, point, InputApprox, ShapeDesc, ShapeError,
};
use crate::{Error, Tolerance};
use num_traits::Signed;
use serde_json::Value;

/// The exact stroke boundary `∂S`, `S = curve ⊕ pen`, as a shape users name:
/// `{"stroke": {"curve": CURVE, "pen": {"circle": R} | {"ellipse": [[m11, m12], [m21, m22]]}}}`
/// (round caps on open curves; `CURVE` as an offset's curve: `{"bezier": …}`,
/// `{"beziers": …}` or SVG path data, several contours allowed).
#[derive(Clone, Debug, PartialEq)]
pub struct StrokeShape {
    /// The stroked curve's pieces (closed contours end where they start).
    pub curve: Vec<Bezier<Rational>>,
    /// The pen.
    pub pen: PenShape,
    /// The curve exactly, with its circular arcs (SVG arcs with a rational
    /// centre, read by [`super::exact_path`]), when it has any and the pen
    /// is a circle: the referee then strokes it with
    /// [`super::stroke_path`], and `∂S` is that of the exact arcs. `curve`
    /// holds their certified cubics.
    pub path: Option<Vec<super::PathPiece>>,
}

fn err(field: impl Into<String>, reason: impl Into<String>) -> ShapeError {
    ShapeError {
        field: field.into(),
        reason: reason.into(),
    }
}

impl StrokeShape {
    /// Reads a stroke shape. `Ok(None)` when the text is not a JSON object
    /// with the top-level key `"stroke"` (it is then some other shape, or
    /// bad input that [`ShapeDesc::parse`] reports); an error, naming the
    /// field, when it is one but malformed. The report says what SVG arcs in
    /// the curve were approximated (the results are then about that curve).
    ///
    /// # Examples
    /// ```
    /// use lncert::stroke::{PenShape, StrokeShape};
    /// let (s, _) = StrokeShape::parse_reported(
    ///     r#"{"stroke": {"curve": "M 0 0 L 4 0", "pen": {"circle": "1/2"}}}"#,
    /// )?.expect("a stroke shape");
    /// assert!(matches!(s.pen, PenShape::Circle(_)));
    /// assert!(StrokeShape::parse_reported("M 0 0 L 1 1")?.is_none()); // path data: another shape
    /// let e = StrokeShape::parse_reported(r#"{"stroke": {"curve": "M 0 0 L 4 0", "pen": {"circle": 0}}}"#)
    ///     .unwrap_err();
    /// assert_eq!(e.field, "stroke.pen.circle");
    /// # Ok::<(), lncert::Error>(())
    /// ```
    pub fn parse_reported(text: &str) -> Result<Option<(StrokeShape, InputApprox)>, ShapeError> {
        let trimmed = text.trim();
        if !trimmed.starts_with('{') {
            return Ok(None);
        }
        let Ok(doc) = parse_json_value(trimmed) else {
            return Ok(None);
        };
        let Value::Object(map) = &doc else {
            return Ok(None);
        };
        let Some(s) = map.get("stroke") else {
            return Ok(None);
        };
        check_keys(map, "(top level)", &["stroke"])?;
        let Value::Object(m) = s else {
            return Err(err("stroke", "expected an object {\"curve\", \"pen\"}"));
        };
        check_keys(m, "stroke", &["curve", "pen"])?;
        let mut approx = InputApprox::default();
        let curve = curve_value(
            m.get("curve")
                .ok_or_else(|| err("stroke.curve", "missing"))?,
            "stroke.curve",
            &mut approx,
        )?;
        let pen = pen_value(m.get("pen"))?;
        let (path, approx) = match (&pen, super::exact_path(&curve, &approx)) {
            (PenShape::Circle(_), Some((path, rest))) => (Some(path), rest),
            _ => (None, approx),
        };
        Ok(Some((StrokeShape { curve, pen, path }, approx)))
    }

    /// The stroker's options for this shape at tolerance `tol`: round caps,
    /// fitted cubic sides (low degree keeps the distance search fast), the
    /// default budgets.
    pub fn options(&self, tol: Tolerance) -> StrokeOptions {
        let mut o = StrokeOptions::with_pen(self.pen.clone(), tol);
        o.output = crate::offset::Output::Cubic;
        o
    }

    /// The stroke tolerance the referee uses unless told: `T/16` for a
    /// claimed tolerance `T` (so that `T` is decided unless the distance is
    /// within about `T/16` of it), else a thousandth of the pen's size (its
    /// radius, or the largest entry of its matrix).
    ///
    /// # Examples
    /// ```
    /// use lncert::stroke::{PenShape, StrokeShape};
    /// let s = StrokeShape { curve: lncert::parse_curve("M 0 0 L 1 0")?, pen: PenShape::Circle(lncert::parse_rational("2")?), path: None };
    /// assert_eq!(s.default_tolerance(Some(&"1/100".parse()?)).to_string(), "1/1600");
    /// assert_eq!(s.default_tolerance(None).to_string(), "1/500");
    /// # Ok::<(), lncert::Error>(())
    /// ```
    pub fn default_tolerance(&self, claim: Option<&Tolerance>) -> Tolerance {
        let exact = match claim {
            Some(t) => t.exact() / Rational::from_integer(16.into()),
            None => {
                let size = match &self.pen {
                    PenShape::Circle(r) => r.abs(),
                    PenShape::Ellipse(p) => {
                        p.m.iter()
                            .flatten()
                            .map(Signed::abs)
                            .max()
                            .expect("four entries")
                    }
                };
                size / Rational::from_integer(1000.into())
            }
        };
        // a positive rational within the shape limits always converts; the
        // fallback keeps this total (a sixteenth of a tiny claim can round
        // to a subnormal)
        Tolerance::new(exact.clone()).unwrap_or_else(|_| {
            Tolerance::from_f64(f64::MIN_POSITIVE.max(interval_from_rational(&exact).inf()))
                .expect("a normal positive float")
        })
    }
}

/// The referee with its default stroke tolerances: [`distance_to_stroke`]
/// at [`StrokeShape::default_tolerance`] `ε`; when the stroke's claims (a),
/// (b) are not proven there, again at `4ε` and at `ε/4` (a different
/// construction often decides); when a claimed `tol` is left undecided by
/// bounds that straddle it, once more at `ε/8` (a narrower bracket). The
/// first decided result is returned, else the last one with a proven
/// stroke, else the last one. The stroke tolerance used is the result's
/// `stroke.tol`.
///
/// # Examples
/// ```
/// use lncert::certify::Config;
/// use lncert::shape::ShapeDesc;
/// use lncert::stroke::{referee, StrokeShape, StrokeVerdict};
/// # fn main() -> Result<(), lncert::Error> {
/// let (s, _) = StrokeShape::parse_reported(
///     r#"{"stroke": {"curve": "M 0 0 L 4 0", "pen": {"circle": "1/2"}}}"#,
/// )?.expect("a stroke shape");
/// let x = ShapeDesc::parse("M 0 -0.5 L 4 -0.5")?; // one side only: the rest of ∂S is not covered
/// let tol = "1e-2".parse()?;
/// let d = referee(&x, &s, Some(&tol), &Config::default())?;
/// assert_eq!(d.verdict(&tol), StrokeVerdict::Over);
/// assert!(d.to_stroke.1 <= 1e-2 && d.from_stroke.0 > 0.9); // on ∂S, but covers little of it
/// # Ok(())
/// # }
/// ```
pub fn referee(
    x: &ShapeDesc,
    shape: &StrokeShape,
    tol: Option<&Tolerance>,
    cfg: &Config,
) -> Result<StrokeDistance, Error> {
    let e0 = shape.default_tolerance(tol);
    let scaled = |num: i64, den: i64| {
        Tolerance::new(e0.exact() * Rational::new(num.into(), den.into())).ok()
    };
    let decided = |d: &StrokeDistance| match tol {
        Some(t) => d.verdict(t) != StrokeVerdict::Undecided,
        None => d.outline.is_some(),
    };
    let mut best: Option<StrokeDistance> = None;
    let mut tried = vec![e0.clone()];
    let mut next = Some(e0.clone());
    while let Some(e) = next.take() {
        let d = match &shape.path {
            Some(p) => distance_to_stroke_path(x, p, &shape.options(e), cfg)?,
            None => distance_to_stroke(x, &shape.curve, &shape.options(e), cfg)?,
        };
        if decided(&d) {
            return Ok(d);
        }
        let proven = d.outline.is_some();
        let candidates = if proven {
            // bounds straddle the claim: a narrower bracket
            vec![scaled(1, 8)]
        } else {
            vec![scaled(4, 1), scaled(1, 4)]
        };
        if proven || best.as_ref().is_none_or(|b| b.outline.is_none()) {
            best = Some(d);
        }
        next = candidates
            .into_iter()
            .flatten()
            .find(|c| !tried.contains(c));
        if let Some(c) = &next {
            tried.push(c.clone());
        }
    }
    Ok(best.expect("at least one run"))
}

fn pen_value(v: Option<&Value>) -> Result<PenShape, ShapeError> {
    let v = v.ok_or_else(|| err("stroke.pen", "missing"))?;
    let Value::Object(m) = v else {
        return Err(err(
            "stroke.pen",
            "expected {\"circle\": R} or {\"ellipse\": [[m11, m12], [m21, m22]]}",
        ));
    };
    if m.len() != 1 {
        return Err(err(
            "stroke.pen",
            "expected exactly one of the keys \"circle\" and \"ellipse\"",
        ));
    }
    if m.contains_key("circle") {
        let r = number(m.get("circle"), "stroke.pen.circle")?;
        if !r.is_positive() {
            return Err(err("stroke.pen.circle", "the radius must be > 0"));
        }
        if !crate::scalar::abs_le_pow10(&r, 100) {
            return Err(err(
                "stroke.pen.circle",
                "magnitude above the supported limit 1e100",
            ));
        }
        return Ok(PenShape::Circle(r));
    }
    if let Some(e) = m.get("ellipse") {
        let rows = e.as_array().filter(|r| r.len() == 2).ok_or_else(|| {
            err(
                "stroke.pen.ellipse",
                "expected the 2×2 matrix [[m11, m12], [m21, m22]]",
            )
        })?;
        let r0 = point(Some(&rows[0]), "stroke.pen.ellipse[0]")?;
        let r1 = point(Some(&rows[1]), "stroke.pen.ellipse[1]")?;
        let pen = Pen::from_matrix([[r0.x, r0.y], [r1.x, r1.y]]).map_err(|e| {
            err(
                e.field.replacen("pen.matrix", "stroke.pen.ellipse", 1),
                e.reason,
            )
        })?;
        return Ok(PenShape::Ellipse(pen));
    }
    Err(err(
        "stroke.pen",
        "unknown pen; expected \"circle\" or \"ellipse\"",
    ))
}

/// Certified bounds on the distances between an outline `X` and the exact
/// stroke boundary `∂S` (see the module documentation for the argument).
#[derive(Clone, Debug)]
pub struct StrokeDistance {
    /// `lo ≤ d_H(X, ∂S)`.
    pub lo: f64,
    /// `d_H(X, ∂S) ≤ hi` (`∞` when undecided).
    pub hi: f64,
    /// Bounds `[lo, hi]` on `h(X, ∂S)`: how far the outline strays from `∂S`.
    pub to_stroke: (f64, f64),
    /// Bounds `[lo, hi]` on `h(∂S, X)`: how far `∂S` is from being covered.
    pub from_stroke: (f64, f64),
    /// The certified search between `X` and the proven outline `L` (`None`
    /// when the stroke's claims (a), (b) were not both proven: then nothing
    /// is known and the bounds are `[0, ∞]`).
    pub outline: Option<HausdorffBounds>,
    /// The proven stroke `L` the bounds go through; its claims' bounds `a`,
    /// `b` are part of the result's width.
    pub stroke: Stroke,
}

/// How a [`StrokeDistance`] decides a claimed tolerance.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum StrokeVerdict {
    /// `d_H(X, ∂S) ≤ T` is proven.
    Within,
    /// `d_H(X, ∂S) > T` is proven.
    Over,
    /// Neither: the bounds straddle `T` (a smaller stroke tolerance or
    /// `rel` may decide it) or the stroke was not proven.
    Undecided,
}

impl StrokeDistance {
    /// The verdict on `d_H(X, ∂S) ≤ tol` (`hi ≤` the largest float `≤ tol`:
    /// within; `lo >` it: over, since no float lies strictly between it and
    /// `tol`).
    pub fn verdict(&self, tol: &Tolerance) -> StrokeVerdict {
        if self.hi <= tol.value() {
            StrokeVerdict::Within
        } else if self.lo > tol.value() {
            StrokeVerdict::Over
        } else {
            StrokeVerdict::Undecided
        }
    }
    /// The stroke's claims (a) and (b) are proven and the search between
    /// `X` and `L` ran to its goal.
    pub fn complete(&self) -> bool {
        self.outline.as_ref().is_some_and(|o| !o.incomplete())
    }
}

fn down(x: f64) -> f64 {
    if x.is_finite() {
        x.next_down().max(0.0)
    } else {
        0.0
    }
}

fn up(x: f64) -> f64 {
    if x.is_nan() {
        f64::INFINITY
    } else {
        x.next_up()
    }
}

/// Certified bounds on `d_H(X, ∂S)` for the outline `x` and the stroke of
/// `curve` with the pen of `opts`, through lncert's proven outline at
/// `opts.tol` (round caps only: with butt caps the region is not
/// `x ⊕ pen`). `cfg` drives the searches between `x` and that outline (its
/// `rel`, `max_boxes`): each direction is bounded to `rel` on its own
/// ([`crate::certify::hausdorff_each_direction`]), so both one-sided results
/// are tight, and both lower bounds come with witnesses.
///
/// # Examples
/// ```
/// use lncert::certify::Config;
/// use lncert::shape::ShapeDesc;
/// use lncert::stroke::{distance_to_stroke, StrokeShape, StrokeVerdict};
/// # fn main() -> Result<(), lncert::Error> {
/// // ∂(segment ⊕ disk(1/2)): two sides and two half circles
/// let (s, _) = StrokeShape::parse_reported(
///     r#"{"stroke": {"curve": "M 0 0 L 4 0", "pen": {"circle": "1/2"}}}"#,
/// )?.expect("a stroke shape");
/// // the bounding rectangle, 0.03 too high and too low: its long sides are
/// // 0.03 off ∂S, its corners √(0.5² + 0.53²) − 0.5 ≈ 0.228629 from the caps
/// let x = ShapeDesc::parse("M -0.5 -0.53 L 4.5 -0.53 L 4.5 0.53 L -0.5 0.53 Z")?;
/// let d = distance_to_stroke(&x, &s.curve, &s.options("1e-3".parse()?), &Config::default())?;
/// assert!(d.lo > 0.228 && d.hi < 0.23);
/// assert_eq!(d.verdict(&"0.1".parse()?), StrokeVerdict::Over);
/// assert_eq!(d.verdict(&"0.25".parse()?), StrokeVerdict::Within);
/// # Ok(())
/// # }
/// ```
pub fn distance_to_stroke(
    x: &ShapeDesc,
    curve: &[Bezier<Rational>],
    opts: &StrokeOptions,
    cfg: &Config,
) -> Result<StrokeDistance, Error> {
    round_caps(opts)?;
    distance_through(x, stroke(curve, opts)?, cfg)
}

/// The referee's stroke is `x ⊕ pen`: round caps only.
fn round_caps(opts: &StrokeOptions) -> Result<(), Error> {
    if opts.cap != Cap::Round {
        return Err(Error {
            field: "cap".into(),
            reason: "the referee needs round caps (with butt caps the region is not x ⊕ pen)"
                .into(),
        });
    }
    Ok(())
}

/// [`distance_to_stroke`] for an exact path with circular arcs
/// ([`super::stroke_path`]: the outline `L` is proven against the exact arcs
/// by its certificate, which [`super::distance_certificate`] then uses).
///
/// # Examples
/// ```
/// use lncert::certify::Config;
/// use lncert::shape::ShapeDesc;
/// use lncert::stroke::{distance_to_stroke_path, parse_path, StrokeOptions};
/// # fn main() -> Result<(), lncert::Error> {
/// // ∂(circle of radius 2 ⊕ disk(1/2)): the circles of radii 3/2 and 5/2
/// let (path, _) = parse_path(r#"<svg><circle cx="0" cy="0" r="2"/></svg>"#)?;
/// let x = ShapeDesc::parse(r#"<svg><circle cx="0" cy="0" r="2.5"/><circle cx="0" cy="0" r="1.5"/></svg>"#)?;
/// let o = StrokeOptions::new(lncert::parse_rational("1/2")?, "1e-3".parse()?);
/// let d = distance_to_stroke_path(&x, &path, &o, &Config::default())?;
/// assert!(d.hi <= 2e-3); // within the stroke's tolerance and the search's gap
/// # Ok(())
/// # }
/// ```
pub fn distance_to_stroke_path(
    x: &ShapeDesc,
    path: &[super::PathPiece],
    opts: &StrokeOptions,
    cfg: &Config,
) -> Result<StrokeDistance, Error> {
    round_caps(opts)?;
    distance_through(x, super::stroke_path(path, opts)?, cfg)
}

/// [`distance_to_stroke`] through a stroke already made (round caps, claims
/// (a), (b) as [`stroke`] proves them): to referee several outlines of one
/// stroke with one construction. A stroke with butt caps, or with (a) or (b)
/// unproven, gives `[0, ∞]`.
pub fn distance_through(x: &ShapeDesc, s: Stroke, cfg: &Config) -> Result<StrokeDistance, Error> {
    // (butt caps: (a) and (b) are not claimed, so not proven)
    if !(s.a.proven && s.b.proven) {
        return Ok(StrokeDistance {
            lo: 0.0,
            hi: f64::INFINITY,
            to_stroke: (0.0, f64::INFINITY),
            from_stroke: (0.0, f64::INFINITY),
            outline: None,
            stroke: s,
        });
    }
    let l = s.outline_shape()?;
    let (a, b) = (s.a.bound, s.b.bound);
    let cfg = Config {
        parametric: false,
        tol: None,
        verdict_only: false,
        // the bounds carry the outline's (a), (b), up to its tolerance E,
        // anyway: a gap below E/4 is not worth refining (where X coincides
        // with ∂S the gap shrinks only like w², and the search would run to
        // its automatic floor, 1e-10 of the coordinates, for seconds)
        abs: cfg.abs.max(s.tol.value() / 4.0),
        ..cfg.clone()
    };
    let h = hausdorff_each_direction(x, &l, &cfg)?;
    let to_stroke = (down(h.a_to_b.lo - b), up(h.a_to_b.hi + a));
    let from_stroke = (down(h.b_to_a.lo - a), up(h.b_to_a.hi + b));
    Ok(StrokeDistance {
        lo: to_stroke.0.max(from_stroke.0),
        hi: to_stroke.1.max(from_stroke.1),
        to_stroke,
        from_stroke,
        outline: Some(h),
        stroke: s,
    })
}
