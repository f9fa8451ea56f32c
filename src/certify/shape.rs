//! The shapes whose Hausdorff distance lncert certifies, their exact description
//! (read from JSON or SVG path data, written back canonically for certificates)
//! and their parametrisations as [`Jet`] evaluators.
//!
//! | shape | parametrisation over `t` |
//! |---|---|
//! | Bézier piece (any degree) | `B(t)`, `t ∈ [0, 1]` (de Casteljau) |
//! | circular arc, centre `c`, radius `R`, counter-clockwise from direction `d0` to `d1` | `c + R (cos φ e0 + sin φ e0⊥)` with `φ = 4 atan t`, i.e. `cos φ = ((1−t²)² − 4t²)/(1+t²)²`, `sin φ = 4t(1−t²)/(1+t²)²`, `t ∈ [0, tan(Θ/4)]` (`Θ` the sweep, `0 < Θ < 2π`) |
//! | offset `x + r N` of a polynomial piece | `x(t) + sign(r) Q n / √(nᵀ Q n)` with `n = x′(t)⊥` (left normal, not normalised) and `Q = r² I` |
//! | convolution of a polynomial piece with the ellipse `M · unit circle` | the same with `Q = M Mᵀ` and `side = ±1`: the ellipse point whose outer normal is `± n` |
//!
//! No sine or cosine is ever needed: `d0`, `d1` are vectors and the arc's end
//! parameter `tan(Θ/4)` is enclosed from half-angle identities.  The end parameter
//! is known only as an interval `[u⁻, u⁺]`, so each piece has an *outer* domain
//! `[0, u⁺]` (covers the whole arc: used where a superset is sound, i.e. upper
//! bounds on distances *from* the shape and lower bounds on distances *to* it) and
//! an *inner* domain `[0, u⁻]` (every parameter is a true point: used for foot
//! points and witnesses).  For the other shapes both are `[0, 1]`.

use super::jet::{Jet, JetPoint};
use super::CertifyError;
use crate::curve::io::{describe, json_coordinate, json_point, parse_curve, parse_svg_path};
use crate::curve::{Bezier, V2};
use crate::poly::{has_common_root_in, Span};
use crate::scalar::{interval_from_rational, Interval, Rational, Scalar, ScalarSqrt, Sign};
use num_traits::{Signed, Zero};
use serde_json::{json, Value};

/// Largest accepted coordinate magnitude, `10¹⁰⁰` (compared exactly): squares of
/// distances must stay far from the f64 overflow threshold in interval arithmetic.
pub const MAX_COORDINATE: f64 = 1e100;

/// A circular arc, counter-clockwise from direction `from` to direction `to`
/// (both seen from the centre).
#[derive(Clone, Debug, PartialEq)]
pub struct ArcDesc {
    /// Centre of the arc's circle.
    pub center: V2<Rational>,
    /// Radius (`> 0`).
    pub radius: Rational,
    /// Direction from the centre to the start point (nonzero, any length).
    pub from: V2<Rational>,
    /// Direction from the centre to the end point (nonzero, any length).
    pub to: V2<Rational>,
}

/// An exactly described shape.
#[derive(Clone, Debug, PartialEq)]
pub enum ShapeDesc {
    /// A (piecewise) polynomial Bézier curve.
    Curve(Vec<Bezier<Rational>>),
    /// A circular arc.
    Arc(ArcDesc),
    /// The exact offset `x + r N` (left unit normal `N`, signed distance `r`) of
    /// each piece of a regular polynomial curve.
    Offset {
        /// The pieces of the regular polynomial curve that is offset.
        curve: Vec<Bezier<Rational>>,
        /// Signed offset distance `r ≠ 0` (`> 0` to the left).
        distance: Rational,
    },
    /// The exact convolution of each piece of a regular polynomial curve with the
    /// ellipse `{M u : |u| = 1}`: `x(t) + side · Q n/√(nᵀQn)`, `Q = M Mᵀ`,
    /// `n` the left normal (seed 001's convolution curve).
    Convolution {
        /// The pieces of the regular polynomial curve that is convolved.
        curve: Vec<Bezier<Rational>>,
        /// The matrix `M` by rows, `[[m11, m12], [m21, m22]]` (`det M ≠ 0`).
        ellipse: [[Rational; 2]; 2],
        /// `+1` or `−1`: the ellipse point whose outer normal is `side · n`.
        side: i8,
    },
}

fn err(field: impl Into<String>, reason: impl Into<String>) -> CertifyError {
    CertifyError::Input {
        field: field.into(),
        reason: reason.into(),
    }
}

fn curve_value(v: &Value, field: &str) -> Result<Vec<Bezier<Rational>>, CertifyError> {
    let parsed = match v {
        Value::String(s) => parse_svg_path(s),
        Value::Object(_) => parse_curve(&v.to_string()),
        other => {
            return Err(err(
                field,
                format!(
                    "expected a curve ({{\"bezier\": ...}}, {{\"beziers\": ...}} or SVG path data), found {}",
                    describe(other)
                ),
            ))
        }
    };
    parsed.map_err(|e| err(field, e.to_string()))
}

fn number(v: Option<&Value>, field: &str) -> Result<Rational, CertifyError> {
    let v = v.ok_or_else(|| err(field, "missing"))?;
    json_coordinate(v, field).map_err(|e| err(field, e.to_string()))
}

fn point(v: Option<&Value>, field: &str) -> Result<V2<Rational>, CertifyError> {
    let v = v.ok_or_else(|| err(field, "missing"))?;
    json_point(v, field).map_err(|e| err(field, e.to_string()))
}

fn check_keys(
    map: &serde_json::Map<String, Value>,
    field: &str,
    keys: &[&str],
) -> Result<(), CertifyError> {
    match map.keys().find(|k| !keys.contains(&k.as_str())) {
        Some(k) => Err(err(
            if field == "(top level)" {
                k.to_string()
            } else {
                format!("{field}.{k}")
            },
            format!("unknown field; expected one of {keys:?}"),
        )),
        None => Ok(()),
    }
}

impl ShapeDesc {
    /// Reads a shape: a curve (`{"bezier": ...}`, `{"beziers": ...}` or SVG path
    /// data), `{"arc": {"center": [x, y], "radius": r, "from": [dx, dy], "to": [dx, dy]}}`
    /// (counter-clockwise; add `"clockwise": true` to go the other way),
    /// `{"offset": {"curve": CURVE, "distance": r}}` or
    /// `{"convolution": {"curve": CURVE, "ellipse": [[m11, m12], [m21, m22]], "side": 1}}`.
    /// Numbers are read exactly (JSON numbers by their digits, or strings like `"1/3"`).
    ///
    /// # Examples
    /// ```
    /// use lncert::certify::ShapeDesc;
    /// let arc = ShapeDesc::parse(r#"{"arc": {"center": [0, 0], "radius": 1, "from": [1, 0], "to": [0, 1]}}"#).unwrap();
    /// assert!(matches!(arc, ShapeDesc::Arc(_)));
    /// let e = ShapeDesc::parse(r#"{"arc": {"center": [0, 0], "radius": -1, "from": [1, 0], "to": [0, 1]}}"#).unwrap_err();
    /// assert!(e.to_string().contains("arc.radius"));
    /// ```
    pub fn parse(text: &str) -> Result<ShapeDesc, CertifyError> {
        let trimmed = text.trim();
        if trimmed.starts_with('<') {
            return ShapeDesc::curve(
                crate::curve::svgdoc::parse_svg_document(trimmed)
                    .map_err(|e| err("svg", e.to_string()))?,
            );
        }
        if !trimmed.starts_with('{') {
            return ShapeDesc::curve(
                parse_svg_path(trimmed).map_err(|e| err("path", e.to_string()))?,
            );
        }
        let doc =
            crate::json::parse(trimmed, &crate::json::Limits::DEFAULT).map_err(|e| {
                match e.kind {
                    crate::json::ErrorKind::Syntax => err("(json)", format!("malformed JSON: {e}")),
                    _ => err(
                        e.path.clone(),
                        format!("{} (line {}, column {})", e.reason, e.line, e.column),
                    ),
                }
            })?;
        Self::from_value(&doc.to_value())
    }

    /// [`ShapeDesc::parse`] on a parsed JSON value.
    pub fn from_value(doc: &Value) -> Result<ShapeDesc, CertifyError> {
        let Value::Object(map) = doc else {
            return Err(err(
                "(top level)",
                format!("expected an object, found {}", describe(doc)),
            ));
        };
        let kinds = [
            "arc",
            "offset",
            "convolution",
            "bezier",
            "beziers",
            "bspline",
        ];
        let given: Vec<&str> = kinds.into_iter().filter(|k| map.contains_key(*k)).collect();
        if given.len() > 1 {
            return Err(err(
                "(top level)",
                format!(
                    "a shape has exactly one of the keys {kinds:?}; found {}",
                    given.join(" and ")
                ),
            ));
        }
        if let Some(a) = map.get("arc") {
            check_keys(map, "(top level)", &["arc"])?;
            let Value::Object(m) = a else {
                return Err(err(
                    "arc",
                    format!("expected an object, found {}", describe(a)),
                ));
            };
            check_keys(m, "arc", &["center", "radius", "from", "to", "clockwise"])?;
            let clockwise = match m.get("clockwise") {
                None => false,
                Some(Value::Bool(b)) => *b,
                Some(v) => {
                    return Err(err(
                        "arc.clockwise",
                        format!("expected true or false, found {}", describe(v)),
                    ))
                }
            };
            let (mut from, mut to) = (
                point(m.get("from"), "arc.from")?,
                point(m.get("to"), "arc.to")?,
            );
            if clockwise {
                std::mem::swap(&mut from, &mut to);
            }
            let arc = ArcDesc {
                center: point(m.get("center"), "arc.center")?,
                radius: number(m.get("radius"), "arc.radius")?,
                from,
                to,
            };
            return ShapeDesc::arc(arc);
        }
        if let Some(o) = map.get("offset") {
            check_keys(map, "(top level)", &["offset"])?;
            let Value::Object(m) = o else {
                return Err(err(
                    "offset",
                    format!("expected an object, found {}", describe(o)),
                ));
            };
            check_keys(m, "offset", &["curve", "distance"])?;
            let curve = curve_value(
                m.get("curve")
                    .ok_or_else(|| err("offset.curve", "missing"))?,
                "offset.curve",
            )?;
            let distance = number(m.get("distance"), "offset.distance")?;
            return ShapeDesc::offset(curve, distance);
        }
        if let Some(o) = map.get("convolution") {
            check_keys(map, "(top level)", &["convolution"])?;
            let Value::Object(m) = o else {
                return Err(err(
                    "convolution",
                    format!("expected an object, found {}", describe(o)),
                ));
            };
            check_keys(m, "convolution", &["curve", "ellipse", "side"])?;
            let curve = curve_value(
                m.get("curve")
                    .ok_or_else(|| err("convolution.curve", "missing"))?,
                "convolution.curve",
            )?;
            let rows = m
                .get("ellipse")
                .and_then(Value::as_array)
                .filter(|r| r.len() == 2)
                .ok_or_else(|| {
                    err(
                        "convolution.ellipse",
                        "expected the 2×2 matrix [[m11, m12], [m21, m22]]",
                    )
                })?;
            let r0 = point(Some(&rows[0]), "convolution.ellipse[0]")?;
            let r1 = point(Some(&rows[1]), "convolution.ellipse[1]")?;
            let side = match m.get("side") {
                None => 1,
                Some(v) if v.to_string() == "1" => 1,
                Some(v) if v.to_string() == "-1" => -1,
                Some(v) => {
                    return Err(err(
                        "convolution.side",
                        format!("expected 1 or -1, found {}", describe(v)),
                    ))
                }
            };
            return ShapeDesc::convolution(curve, [[r0.x, r0.y], [r1.x, r1.y]], side);
        }
        ShapeDesc::curve(parse_curve(&doc.to_string()).map_err(|e| err("curve", e.to_string()))?)
    }

    /// A curve shape, with the coordinate-size check.
    pub fn curve(pieces: Vec<Bezier<Rational>>) -> Result<ShapeDesc, CertifyError> {
        check_pieces(&pieces, "curve")?;
        Ok(ShapeDesc::Curve(pieces))
    }

    /// An arc: `radius > 0`, nonzero directions, a nonzero sweep (`from` and `to`
    /// not the same direction; full circles are not supported).
    pub fn arc(a: ArcDesc) -> Result<ShapeDesc, CertifyError> {
        check_magnitude(&a.center.x, "arc.center[0]")?;
        check_magnitude(&a.center.y, "arc.center[1]")?;
        check_magnitude(&a.radius, "arc.radius")?;
        if !a.radius.is_positive() {
            return Err(err("arc.radius", "must be > 0"));
        }
        for (v, f) in [(&a.from, "arc.from"), (&a.to, "arc.to")] {
            check_magnitude(&v.x, f)?;
            check_magnitude(&v.y, f)?;
            if v.x.is_zero() && v.y.is_zero() {
                return Err(err(f, "the direction vector is zero"));
            }
        }
        if a.from.cross(&a.to).is_zero() && a.from.dot(&a.to).is_positive() {
            return Err(err(
                "arc.to",
                "same direction as arc.from: zero sweep (full circles are not supported)",
            ));
        }
        Ok(ShapeDesc::Arc(a))
    }

    /// An offset at signed distance `distance ≠ 0` of a regular curve.
    pub fn offset(
        curve: Vec<Bezier<Rational>>,
        distance: Rational,
    ) -> Result<ShapeDesc, CertifyError> {
        check_pieces(&curve, "offset.curve")?;
        check_regular(&curve, "offset.curve")?;
        check_magnitude(&distance, "offset.distance")?;
        if distance.is_zero() {
            return Err(err(
                "offset.distance",
                "must be nonzero (the offset at distance 0 is the curve itself)",
            ));
        }
        Ok(ShapeDesc::Offset { curve, distance })
    }

    /// A convolution with the ellipse `M · unit circle`, `det M ≠ 0`, `side = ±1`.
    pub fn convolution(
        curve: Vec<Bezier<Rational>>,
        m: [[Rational; 2]; 2],
        side: i8,
    ) -> Result<ShapeDesc, CertifyError> {
        check_pieces(&curve, "convolution.curve")?;
        check_regular(&curve, "convolution.curve")?;
        for (i, row) in m.iter().enumerate() {
            for (j, x) in row.iter().enumerate() {
                check_magnitude(x, &format!("convolution.ellipse[{i}][{j}]"))?;
            }
        }
        if (&m[0][0] * &m[1][1] - &m[0][1] * &m[1][0]).is_zero() {
            return Err(err(
                "convolution.ellipse",
                "the matrix is singular (the ellipse is degenerate)",
            ));
        }
        if side != 1 && side != -1 {
            return Err(err("convolution.side", "must be 1 or -1"));
        }
        Ok(ShapeDesc::Convolution {
            curve,
            ellipse: m,
            side,
        })
    }

    /// The canonical JSON form (exact rational strings), as stored in certificates.
    pub fn to_json(&self) -> Value {
        fn q(r: &Rational) -> Value {
            Value::String(r.to_string())
        }
        fn p(v: &V2<Rational>) -> Value {
            json!([q(&v.x), q(&v.y)])
        }
        fn curve(c: &[Bezier<Rational>]) -> Value {
            json!({"beziers": c.iter().map(|b| b.points().iter().map(p).collect::<Vec<_>>()).collect::<Vec<_>>()})
        }
        match self {
            ShapeDesc::Curve(c) => curve(c),
            ShapeDesc::Arc(a) => {
                json!({"arc": {"center": p(&a.center), "radius": q(&a.radius), "from": p(&a.from), "to": p(&a.to)}})
            }
            ShapeDesc::Offset { curve: c, distance } => {
                json!({"offset": {"curve": curve(c), "distance": q(distance)}})
            }
            ShapeDesc::Convolution {
                curve: c,
                ellipse,
                side,
            } => json!({"convolution": {
                "curve": curve(c),
                "ellipse": [[q(&ellipse[0][0]), q(&ellipse[0][1])], [q(&ellipse[1][0]), q(&ellipse[1][1])]],
                "side": side}}),
        }
    }

    /// A short human description.
    pub fn summary(&self) -> String {
        match self {
            ShapeDesc::Curve(c) => format!(
                "curve, {} Bézier piece(s) of degree ≤ {}",
                c.len(),
                c.iter().map(|b| b.degree()).max().unwrap_or(0)
            ),
            ShapeDesc::Arc(a) => format!("arc of radius {}", a.radius),
            ShapeDesc::Offset { curve, distance } => {
                format!("offset at {} of {} piece(s)", distance, curve.len())
            }
            ShapeDesc::Convolution { curve, .. } => {
                format!("convolution of {} piece(s) with an ellipse", curve.len())
            }
        }
    }

    /// The largest coordinate magnitude involved (for scale-aware tolerances).
    pub fn scale(&self) -> f64 {
        let pts_scale = |c: &[Bezier<Rational>]| {
            c.iter()
                .flat_map(|b| b.points().iter())
                .map(|p| p.x.approx().abs().max(p.y.approx().abs()))
                .fold(0.0, f64::max)
        };
        match self {
            ShapeDesc::Curve(c) => pts_scale(c),
            ShapeDesc::Arc(a) => {
                a.center.x.approx().abs().max(a.center.y.approx().abs()) + a.radius.approx()
            }
            ShapeDesc::Offset { curve, distance } => pts_scale(curve) + distance.approx().abs(),
            ShapeDesc::Convolution { curve, ellipse, .. } => {
                pts_scale(curve)
                    + ellipse
                        .iter()
                        .flatten()
                        .map(|x| x.approx().abs())
                        .sum::<f64>()
            }
        }
    }

    /// The parametrised pieces, with interval and float data.
    pub(crate) fn pieces(&self) -> Result<Vec<Piece>, CertifyError> {
        match self {
            ShapeDesc::Curve(c) => Ok(c.iter().map(|b| Piece::bezier(b)).collect()),
            ShapeDesc::Arc(a) => Ok(vec![Piece::arc(a)?]),
            ShapeDesc::Offset { curve, distance } => {
                let r2 = distance * distance;
                let z = <Rational as Zero>::zero();
                let sigma = if distance.is_positive() { 1 } else { -1 };
                Ok(curve
                    .iter()
                    .map(|b| Piece::conv(b, [&r2, &z, &r2], sigma))
                    .collect())
            }
            ShapeDesc::Convolution {
                curve,
                ellipse: m,
                side,
            } => {
                let q11 = &m[0][0] * &m[0][0] + &m[0][1] * &m[0][1];
                let q12 = &m[0][0] * &m[1][0] + &m[0][1] * &m[1][1];
                let q22 = &m[1][0] * &m[1][0] + &m[1][1] * &m[1][1];
                Ok(curve
                    .iter()
                    .map(|b| Piece::conv(b, [&q11, &q12, &q22], *side))
                    .collect())
            }
        }
    }
}

fn check_magnitude(r: &Rational, field: &str) -> Result<(), CertifyError> {
    // exactly |r| ≤ 10¹⁰⁰ (`MAX_COORDINATE`), the rule the verifier applies too
    if !crate::scalar::abs_le_pow10(r, 100) {
        return Err(err(
            field,
            format!("magnitude above the supported limit {MAX_COORDINATE:e}"),
        ));
    }
    Ok(())
}

fn check_pieces(c: &[Bezier<Rational>], field: &str) -> Result<(), CertifyError> {
    if c.is_empty() {
        return Err(err(field, "no curve pieces"));
    }
    for (i, b) in c.iter().enumerate() {
        for (k, p) in b.points().iter().enumerate() {
            check_magnitude(&p.x, &format!("{field}[{i}][{k}][0]"))?;
            check_magnitude(&p.y, &format!("{field}[{i}][{k}][1]"))?;
        }
    }
    Ok(())
}

/// The offset and the convolution need a normal everywhere: `x′(t) ≠ 0` on `[0, 1]`,
/// decided exactly (no common root of `x′` and `y′`).
fn check_regular(c: &[Bezier<Rational>], field: &str) -> Result<(), CertifyError> {
    for (i, b) in c.iter().enumerate() {
        if b.degree() == 0 {
            return Err(err(format!("{field}[{i}]"), "a single point has no normal"));
        }
        let (dx, dy) = b.hodograph().power_coords();
        let (dx, dy) = (dx.trimmed(), dy.trimmed());
        let all_zero =
            dx.coeffs().iter().all(Zero::is_zero) && dy.coeffs().iter().all(Zero::is_zero);
        if all_zero || has_common_root_in(&dx, &dy, &Span::unit_closed()) {
            return Err(err(
                format!("{field}[{i}]"),
                "the curve is singular (its derivative vanishes) on [0, 1]: the normal is undefined there",
            ));
        }
    }
    Ok(())
}

/// Interval and float data of one parametrised piece.
#[derive(Clone, Debug)]
pub(crate) enum PieceData<S> {
    /// `pts` and its first and second hodographs (`d1`, `d2`; a single zero
    /// point where the degree is too low).
    Bez {
        pts: Vec<(S, S)>,
        d1: Vec<(S, S)>,
        d2: Vec<(S, S)>,
    },
    Arc {
        c: (S, S),
        r: S,
        e0: (S, S),
    },
    /// The curve `pts`, its hodographs `hod` (x′), `hod2` (x″), `hod3` (x‴).
    Conv {
        pts: Vec<(S, S)>,
        hod: Vec<(S, S)>,
        hod2: Vec<(S, S)>,
        hod3: Vec<(S, S)>,
        q: (S, S, S),
        sigma: S,
    },
}

/// One parametrised piece of a shape.
#[derive(Clone, Debug)]
pub(crate) struct Piece {
    pub iv: PieceData<Interval>,
    pub fl: PieceData<f64>,
    /// A parameter range covering the whole piece.
    pub outer: (f64, f64),
    /// A parameter range of true points of the piece (`⊆` the exact domain).
    pub inner: (f64, f64),
}

fn iv(r: &Rational) -> Interval {
    interval_from_rational(r)
}

fn mid(x: Interval) -> f64 {
    x.mid()
}

fn mid_data(d: &PieceData<Interval>) -> PieceData<f64> {
    let m2 = |p: &(Interval, Interval)| (mid(p.0), mid(p.1));
    let m2s = |v: &[(Interval, Interval)]| v.iter().map(m2).collect::<Vec<_>>();
    match d {
        PieceData::Bez { pts, d1, d2 } => PieceData::Bez {
            pts: m2s(pts),
            d1: m2s(d1),
            d2: m2s(d2),
        },
        PieceData::Arc { c, r, e0 } => PieceData::Arc {
            c: m2(c),
            r: mid(*r),
            e0: m2(e0),
        },
        PieceData::Conv {
            pts,
            hod,
            hod2,
            hod3,
            q,
            sigma,
        } => PieceData::Conv {
            pts: m2s(pts),
            hod: m2s(hod),
            hod2: m2s(hod2),
            hod3: m2s(hod3),
            q: (mid(q.0), mid(q.1), mid(q.2)),
            sigma: mid(*sigma),
        },
    }
}

impl Piece {
    fn from_iv(iv: PieceData<Interval>, outer: (f64, f64), inner: (f64, f64)) -> Piece {
        let fl = mid_data(&iv);
        Piece {
            iv,
            fl,
            outer,
            inner,
        }
    }

    fn bezier(b: &Bezier<Rational>) -> Piece {
        let [pts, d1, d2, _] = hodographs(b);
        Piece::from_iv(PieceData::Bez { pts, d1, d2 }, (0.0, 1.0), (0.0, 1.0))
    }

    fn conv(b: &Bezier<Rational>, q: [&Rational; 3], sigma: i8) -> Piece {
        let [pts, hod, hod2, hod3] = hodographs(b);
        let data = PieceData::Conv {
            pts,
            hod,
            hod2,
            hod3,
            q: (iv(q[0]), iv(q[1]), iv(q[2])),
            sigma: Interval::from_i64(sigma as i64),
        };
        Piece::from_iv(data, (0.0, 1.0), (0.0, 1.0))
    }

    fn arc(a: &ArcDesc) -> Result<Piece, CertifyError> {
        let unit = |v: &V2<Rational>| -> Option<(Interval, Interval)> {
            let (x, y) = (iv(&v.x), iv(&v.y));
            let n = ScalarSqrt::sqrt(&(x.sqr() + y.sqr()))?;
            Some((x.div(&n)?, y.div(&n)?))
        };
        let bad = || {
            err(
                "arc",
                "the directions cannot be normalised in interval arithmetic",
            )
        };
        let e0 = unit(&a.from).ok_or_else(bad)?;
        let e1 = unit(&a.to).ok_or_else(bad)?;
        let u = arc_end_parameter(&a.from, &a.to, e0, e1).ok_or_else(|| {
            err(
                "arc.to",
                "the sweep is too close to 0 or 2π to enclose its end parameter",
            )
        })?;
        if !(u.inf() > 0.0 && u.sup().is_finite()) {
            return Err(err(
                "arc.to",
                "the sweep is too close to 0 or 2π to enclose its end parameter",
            ));
        }
        let data = PieceData::Arc {
            c: (iv(&a.center.x), iv(&a.center.y)),
            r: iv(&a.radius),
            e0,
        };
        Ok(Piece::from_iv(data, (0.0, u.sup()), (0.0, u.inf())))
    }
}

/// Enclosures of the control points of `b` and of its first three hodographs:
/// the points enclosed once from the exact rationals, the hodographs
/// `m (pᵢ₊₁ − pᵢ)` then in interval arithmetic (sound enclosures of the exact
/// hodographs, without the rational arithmetic on large denominators).
fn hodographs(b: &Bezier<Rational>) -> [Vec<(Interval, Interval)>; 4] {
    hodographs_iv(b.points().iter().map(|p| (iv(&p.x), iv(&p.y))).collect())
}

/// [`hodographs`] from enclosures of the control points.
fn hodographs_iv(pts: Vec<(Interval, Interval)>) -> [Vec<(Interval, Interval)>; 4] {
    let hod = |c: &[(Interval, Interval)]| -> Vec<(Interval, Interval)> {
        let m = c.len().saturating_sub(1);
        if m == 0 {
            // the derivative of a constant: the zero polynomial
            let z = Interval::zero();
            return vec![(z, z)];
        }
        let k = Interval::from_i64(m as i64);
        c.windows(2)
            .map(|w| (k * (w[1].0 - w[0].0), k * (w[1].1 - w[0].1)))
            .collect()
    };
    let h1 = hod(&pts);
    let h2 = hod(&h1);
    let h3 = hod(&h2);
    [pts, h1, h2, h3]
}

/// The piece of the exact offset at `distance` of the span `[t₀, t₁]` of `x`
/// (reparametrised to `[0, 1]`), the same piece as
/// `ShapeDesc::Offset { curve: [x restricted to the span], distance }`, without
/// rational arithmetic: [`Bezier::restrict`] (blossoms, one *point* parameter
/// per level) in interval arithmetic on enclosures of `x`'s control points. `None` if `t` is not a finite span or the input pieces are
/// degenerate (checked by the caller's shape validation).
pub(crate) fn offset_span(
    x: &Bezier<Rational>,
    t: (f64, f64),
    distance: &Rational,
) -> Option<Piece> {
    if !(t.0.is_finite() && t.1.is_finite() && t.0 < t.1) || x.points().is_empty() {
        return None;
    }
    let (p0, p1) = (
        Interval::try_from((t.0, t.0)).ok()?,
        Interval::try_from((t.1, t.1)).ok()?,
    );
    let span = x.map(iv).restrict(&p0, &p1);
    let pts: Vec<(Interval, Interval)> = span.points().iter().map(|p| (p.x, p.y)).collect();
    let [pts, hod, hod2, hod3] = hodographs_iv(pts);
    let r2 = iv(&(distance * distance));
    let sigma = if distance.is_positive() { 1 } else { -1 };
    let data = PieceData::Conv {
        pts,
        hod,
        hod2,
        hod3,
        q: (r2, Interval::zero(), r2),
        sigma: Interval::from_i64(sigma),
    };
    Some(Piece::from_iv(data, (0.0, 1.0), (0.0, 1.0)))
}

/// The piece of a Bézier curve with float (exact dyadic) control points.
pub(crate) fn bezier_f64(b: &Bezier<f64>) -> Option<Piece> {
    let pts = b
        .points()
        .iter()
        .map(|p| {
            Some((
                Interval::try_from((p.x, p.x)).ok()?,
                Interval::try_from((p.y, p.y)).ok()?,
            ))
        })
        .collect::<Option<Vec<_>>>()?;
    if pts.is_empty() {
        return None;
    }
    let [pts, d1, d2, _] = hodographs_iv(pts);
    Some(Piece::from_iv(
        PieceData::Bez { pts, d1, d2 },
        (0.0, 1.0),
        (0.0, 1.0),
    ))
}

/// `tan(Θ/4)` for the counter-clockwise sweep `Θ ∈ (0, 2π)` from `e0` to `e1`:
/// with `sin(Θ/2) = |e1 − e0|/2 > 0` and `cos(Θ/2) = ±|e1 + e0|/2` (the sign of
/// `e0 × e1`, decided exactly from the rational directions),
/// `tan(Θ/4) = sin(Θ/2)/(1 + cos(Θ/2)) = (1 − cos(Θ/2))/sin(Θ/2)`; the first form is
/// used for `Θ ≤ π`, the second beyond (no cancellation in either).
pub(crate) fn arc_end_parameter(
    from: &V2<Rational>,
    to: &V2<Rational>,
    e0: (Interval, Interval),
    e1: (Interval, Interval),
) -> Option<Interval> {
    let half = Interval::from_frac(1, 2);
    // `sqr` (not `x * x`): an interval around 0 must square to a nonnegative one.
    let norm = |x: Interval, y: Interval| ScalarSqrt::sqrt(&(x.sqr() + y.sqr()));
    let sin_h = norm(e1.0 - e0.0, e1.1 - e0.1)? * half;
    let cos_abs = norm(e1.0 + e0.0, e1.1 + e0.1)? * half;
    let cross = from.cross(to);
    let one = Interval::one();
    match cross.sign() {
        Sign::Positive => sin_h.div(&(one + cos_abs)),
        Sign::Zero if from.dot(to).is_negative() => Some(one), // Θ = π: tan(π/4) = 1
        Sign::Zero => None,
        _ => (one + cos_abs).div(&sin_h),
    }
}

impl<S: ScalarSqrt + Copy + Casteljau> PieceData<S> {
    /// The point of the piece at the parameter jet `t`, or `None` where the
    /// evaluation is undefined (a possibly vanishing normal or denominator).
    ///
    /// Polynomial parts are evaluated through their hodographs with scalar de
    /// Casteljau at `t.v` and the chain rule (`B(τ)′ = B′(τ) τ′`,
    /// `B(τ)″ = B″(τ) τ′² + B′(τ) τ″`): about a third of the interval products of
    /// de Casteljau on jets, and no wider.
    pub fn eval(&self, t: Jet<S>) -> Option<JetPoint<S>> {
        match self {
            PieceData::Bez { pts, d1, d2 } => {
                let p = S::casteljau(pts, t.v);
                let p1 = S::casteljau(d1, t.v);
                let p2 = S::casteljau(d2, t.v);
                Some(chain(p, p1, p2, t))
            }
            PieceData::Arc { c, r, e0 } => {
                let one = Jet::constant(S::one());
                let t2 = t * t;
                let a = one - t2;
                let den = (one + t2) * (one + t2);
                let inv = den.recip()?;
                let cs = (a * a - t2.scale(S::from_i64(4))) * inv;
                let sn = (t * a).scale(S::from_i64(4)) * inv;
                // c + r (cos φ e0 + sin φ e0⊥), e0⊥ = (−e0y, e0x)
                let x = Jet::constant(c.0) + (cs.scale(e0.0) - sn.scale(e0.1)).scale(*r);
                let y = Jet::constant(c.1) + (cs.scale(e0.1) + sn.scale(e0.0)).scale(*r);
                Some((x, y))
            }
            PieceData::Conv {
                pts,
                hod,
                hod2,
                hod3,
                q,
                sigma,
            } => {
                let p1 = S::casteljau(hod, t.v);
                let p2 = S::casteljau(hod2, t.v);
                let (x, y) = chain(S::casteljau(pts, t.v), p1, p2, t);
                let (dx, dy) = chain(p1, p2, S::casteljau(hod3, t.v), t);
                // n = (−y′, x′); Q n; nᵀ Q n
                let (n1, n2) = (-dy, dx);
                let qn1 = n1.scale(q.0) + n2.scale(q.1);
                let qn2 = n1.scale(q.1) + n2.scale(q.2);
                let nqn = n1 * qn1 + n2 * qn2;
                let inv = nqn.sqrt()?.recip()?;
                Some((x + (qn1 * inv).scale(*sigma), y + (qn2 * inv).scale(*sigma)))
            }
        }
    }
}

/// The jet of `B(τ(s))` from `B(τ)`, `B′(τ)`, `B″(τ)` and the jet `τ`.
fn chain<S: Scalar + Copy>(p: (S, S), p1: (S, S), p2: (S, S), t: Jet<S>) -> JetPoint<S> {
    let d2 = t.d * t.d;
    let coord = |v: S, d: S, dd: S| Jet {
        v,
        d: d * t.d,
        dd: dd * d2 + d * t.dd,
    };
    (coord(p.0, p1.0, p2.0), coord(p.1, p1.1, p2.1))
}

/// De Casteljau's algorithm at a scalar parameter (on the stack up to
/// [`STACK_POINTS`] control points: this runs for every box of a search).
fn casteljau<S: Scalar + Copy>(pts: &[(S, S)], t: S) -> (S, S) {
    fn run<S: Scalar + Copy>(buf: &mut [(S, S)], t: S) -> (S, S) {
        let n = buf.len();
        for level in 1..n {
            for i in 0..n - level {
                let (a, b) = (buf[i], buf[i + 1]);
                buf[i] = (a.0 + t * (b.0 - a.0), a.1 + t * (b.1 - a.1));
            }
        }
        buf[0]
    }
    let n = pts.len();
    if n <= STACK_POINTS {
        let mut buf = [pts[0]; STACK_POINTS];
        buf[..n].copy_from_slice(pts);
        run(&mut buf[..n], t)
    } else {
        run(&mut pts.to_vec(), t)
    }
}

/// Control points evaluated without a heap allocation.
const STACK_POINTS: usize = 24;

/// De Casteljau's algorithm as each scalar runs it in the hot loop of a search.
pub(crate) trait Casteljau: Sized {
    /// The point with Bézier control points `pts` at `t` (an enclosure of the
    /// range over `t` for intervals).
    fn casteljau(pts: &[(Self, Self)], t: Self) -> (Self, Self);
}

impl Casteljau for f64 {
    fn casteljau(pts: &[(f64, f64)], t: f64) -> (f64, f64) {
        casteljau(pts, t)
    }
}

impl Casteljau for Interval {
    /// [`super::bern::enclose`] (floats with an a-priori error bound, Bernstein
    /// hull over the parameter box) for parameters in `[0, 1]`; interval de
    /// Casteljau otherwise.
    fn casteljau(pts: &[(Interval, Interval)], t: Interval) -> (Interval, Interval) {
        super::bern::enclose(pts, t).unwrap_or_else(|| casteljau(pts, t))
    }
}
