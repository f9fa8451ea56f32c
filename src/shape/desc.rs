//! The exact shape descriptions: what a shape *is* (curve, arc, offset,
//! convolution), how it is read from JSON or SVG and written back canonically
//! (certificates store this form), and the checks every constructor applies.
//! How the certification engine parametrises each kind is in
//! `certify::piece`.

use super::io::{describe, json_coordinate, json_point, parse_curve, parse_svg_path_reported};
use super::svgarc::exact_mixed;
use super::{InputApprox, ShapeError};
use crate::curve::{Bezier, V2};
use crate::poly::{has_common_root_in, Span};
use crate::scalar::{Rational, Scalar};
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

/// An arc of an ellipse: `center + M u` for `u` on the unit circle,
/// counter-clockwise from the direction `from` to the direction `to` (both
/// directions of the pre-image `u`, any nonzero length). `M` is any
/// nonsingular matrix: a circle of radius `r` is `M = r I`; an SVG ellipse
/// with radii `rx`, `ry` rotated by `φ` is `M = R(φ) diag(rx, ry)`.
#[derive(Clone, Debug, PartialEq)]
pub struct EllipseArcDesc {
    /// Centre of the ellipse.
    pub center: V2<Rational>,
    /// `M` by rows, `[[m11, m12], [m21, m22]]` (`det M ≠ 0`).
    pub matrix: [[Rational; 2]; 2],
    /// Direction of the pre-image from the centre to the start point.
    pub from: V2<Rational>,
    /// Direction of the pre-image from the centre to the end point.
    pub to: V2<Rational>,
}

/// An exactly described shape.
#[derive(Clone, Debug, PartialEq)]
pub enum ShapeDesc {
    /// A (piecewise) polynomial Bézier curve.
    Curve(Vec<Bezier<Rational>>),
    /// A circular arc.
    Arc(ArcDesc),
    /// An arc of an ellipse (the image of a unit-circle arc by an affine map).
    EllipseArc(Box<EllipseArcDesc>),
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
    /// The union of the point sets of its members (none a union itself), its
    /// pieces numbered member after member: both sides of a stroke, or an
    /// outline that mixes arcs and curves. At most [`super::MAX_SEGMENTS`]
    /// pieces in all.
    Union(Vec<ShapeDesc>),
}

/// [`ShapeDesc::arc`]'s checks, errors naming `{name}.radius`, `{name}.from`, ….
pub(crate) fn checked_arc(a: ArcDesc, name: &str) -> Result<ArcDesc, ShapeError> {
    check_magnitude(&a.center.x, &format!("{name}.center[0]"))?;
    check_magnitude(&a.center.y, &format!("{name}.center[1]"))?;
    check_magnitude(&a.radius, &format!("{name}.radius"))?;
    if !a.radius.is_positive() {
        return Err(err(format!("{name}.radius"), "must be > 0"));
    }
    check_sweep(&a.from, &a.to, name, "circles")?;
    Ok(a)
}

/// An arc's directions `from`, `to` (named `{name}.from`, `{name}.to`):
/// nonzero, within the coordinate limit, not the same direction (a zero
/// sweep; full `what` are not supported).
fn check_sweep(
    from: &V2<Rational>,
    to: &V2<Rational>,
    name: &str,
    what: &str,
) -> Result<(), ShapeError> {
    for (v, f) in [(from, "from"), (to, "to")] {
        let f = &format!("{name}.{f}");
        check_magnitude(&v.x, f)?;
        check_magnitude(&v.y, f)?;
        if v.x.is_zero() && v.y.is_zero() {
            return Err(err(f, "the direction vector is zero"));
        }
    }
    if from.cross(to).is_zero() && from.dot(to).is_positive() {
        return Err(err(
            format!("{name}.to"),
            format!("same direction as {name}.from: zero sweep (full {what} are not supported)"),
        ));
    }
    Ok(())
}

/// An arc document's `from` and `to`, counter-clockwise: swapped when
/// `"clockwise": true`.
fn arc_directions(
    m: &serde_json::Map<String, Value>,
    name: &str,
) -> Result<(V2<Rational>, V2<Rational>), ShapeError> {
    let clockwise = match m.get("clockwise") {
        None => false,
        Some(Value::Bool(b)) => *b,
        Some(v) => {
            return Err(err(
                format!("{name}.clockwise"),
                format!("expected true or false, found {}", describe(v)),
            ))
        }
    };
    let from = point(m.get("from"), &format!("{name}.from"))?;
    let to = point(m.get("to"), &format!("{name}.to"))?;
    Ok(if clockwise { (to, from) } else { (from, to) })
}

/// [`ShapeDesc::ellipse_arc`]'s checks, errors naming `{name}.matrix`, `{name}.from`, ….
pub(crate) fn checked_ellipse_arc(
    a: EllipseArcDesc,
    name: &str,
) -> Result<EllipseArcDesc, ShapeError> {
    check_magnitude(&a.center.x, &format!("{name}.center[0]"))?;
    check_magnitude(&a.center.y, &format!("{name}.center[1]"))?;
    for (i, row) in a.matrix.iter().enumerate() {
        for (j, x) in row.iter().enumerate() {
            check_magnitude(x, &format!("{name}.matrix[{i}][{j}]"))?;
        }
    }
    let m = &a.matrix;
    if (&m[0][0] * &m[1][1] - &m[0][1] * &m[1][0]).is_zero() {
        return Err(err(
            format!("{name}.matrix"),
            "the matrix is singular (the ellipse is degenerate)",
        ));
    }
    check_sweep(&a.from, &a.to, name, "ellipses")?;
    Ok(a)
}

/// [`ShapeDesc::curve`]'s checks, errors naming `{field}[i]`.
pub(crate) fn checked_curve(
    pieces: Vec<Bezier<Rational>>,
    field: &str,
) -> Result<ShapeDesc, ShapeError> {
    check_pieces(&pieces, field)?;
    Ok(ShapeDesc::Curve(pieces))
}

/// [`ShapeDesc::offset`]'s checks, errors naming the fields as given.
pub(crate) fn checked_offset(
    curve: Vec<Bezier<Rational>>,
    distance: Rational,
    curve_field: &str,
    distance_field: &str,
) -> Result<ShapeDesc, ShapeError> {
    check_pieces(&curve, curve_field)?;
    check_regular(&curve, curve_field)?;
    check_magnitude(&distance, distance_field)?;
    if distance.is_zero() {
        return Err(err(
            distance_field,
            "must be nonzero (the offset at distance 0 is the curve itself)",
        ));
    }
    Ok(ShapeDesc::Offset { curve, distance })
}

pub(super) fn err(field: impl Into<String>, reason: impl Into<String>) -> ShapeError {
    ShapeError {
        field: field.into(),
        reason: reason.into(),
    }
}

pub(crate) fn curve_value(
    v: &Value,
    field: &str,
    approx: &mut InputApprox,
) -> Result<Vec<Bezier<Rational>>, ShapeError> {
    let parsed = match v {
        Value::String(s) => parse_svg_path_reported(s).map(|(pieces, a)| {
            approx.extend_scaled(a, field, 1.0);
            pieces
        }),
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

/// A JSON document read with the default limits (duplicate keys, depth,
/// size refused), errors naming the JSON path.
pub(crate) fn parse_json_value(text: &str) -> Result<Value, ShapeError> {
    let doc =
        crate::json::parse(text, &crate::json::Limits::DEFAULT).map_err(|e| match e.kind {
            crate::json::ErrorKind::Syntax => err("(json)", format!("malformed JSON: {e}")),
            _ => err(
                e.path.clone(),
                format!("{} (line {}, column {})", e.reason, e.line, e.column),
            ),
        })?;
    Ok(doc.to_value())
}

pub(crate) fn number(v: Option<&Value>, field: &str) -> Result<Rational, ShapeError> {
    let v = v.ok_or_else(|| err(field, "missing"))?;
    json_coordinate(v, field).map_err(|e| err(field, e.to_string()))
}

pub(crate) fn point(v: Option<&Value>, field: &str) -> Result<V2<Rational>, ShapeError> {
    let v = v.ok_or_else(|| err(field, "missing"))?;
    json_point(v, field).map_err(|e| err(field, e.to_string()))
}

pub(crate) fn check_keys(
    map: &serde_json::Map<String, Value>,
    field: &str,
    keys: &[&str],
) -> Result<(), ShapeError> {
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
    /// `{"ellipse_arc": {"center": [x, y], "matrix": [[m11, m12], [m21, m22]], "from": [dx, dy], "to": [dx, dy]}}`
    /// (the image `center + M u` of the unit-circle arc from `from` to `to`),
    /// `{"offset": {"curve": CURVE, "distance": r}}` or
    /// `{"convolution": {"curve": CURVE, "ellipse": [[m11, m12], [m21, m22]], "side": 1}}`.
    /// Numbers are read exactly (JSON numbers by their digits, or strings like `"1/3"`).
    ///
    /// # Examples
    /// ```
    /// use lncert::shape::ShapeDesc;
    /// let arc = ShapeDesc::parse(r#"{"arc": {"center": [0, 0], "radius": 1, "from": [1, 0], "to": [0, 1]}}"#).unwrap();
    /// assert!(matches!(arc, ShapeDesc::Arc(_)));
    /// let e = ShapeDesc::parse(r#"{"arc": {"center": [0, 0], "radius": -1, "from": [1, 0], "to": [0, 1]}}"#).unwrap_err();
    /// assert!(e.to_string().contains("arc.radius"));
    /// ```
    pub fn parse(text: &str) -> Result<ShapeDesc, ShapeError> {
        Self::parse_reported(text).map(|(shape, _)| shape)
    }

    /// [`ShapeDesc::parse`], with the report of what was approximated: SVG
    /// arcs, circles, ellipses and rounded rectangles become cubic pieces
    /// within a certified Hausdorff bound (see [`InputApprox`]);
    /// [`ShapeDesc::parse`] drops the report.
    ///
    /// # Examples
    /// ```
    /// use lncert::shape::ShapeDesc;
    /// let (shape, approx) =
    ///     ShapeDesc::parse_reported(r#"{"offset": {"curve": "M 0 0 A 1 1 0 0 1 1 1", "distance": 0.1}}"#)
    ///         .unwrap();
    /// assert!(matches!(shape, ShapeDesc::Offset { .. }));
    /// assert_eq!(approx.elements[0].at, "offset.curve, byte 6");
    /// ```
    pub fn parse_reported(text: &str) -> Result<(ShapeDesc, InputApprox), ShapeError> {
        let trimmed = text.trim();
        if trimmed.starts_with('<') {
            let (pieces, approx) = crate::shape::parse_svg_document_reported(trimmed)
                .map_err(|e| err("svg", e.to_string()))?;
            return exact_mixed(pieces, approx);
        }
        if !trimmed.starts_with('{') {
            let (pieces, approx) =
                parse_svg_path_reported(trimmed).map_err(|e| err("path", e.to_string()))?;
            return exact_mixed(pieces, approx);
        }
        Self::from_value_reported(&parse_json_value(trimmed)?)
    }

    /// [`ShapeDesc::parse`] on a parsed JSON value (SVG path data inside,
    /// as an offset's or a convolution's curve, may have arcs: approximated,
    /// and the report dropped; see [`ShapeDesc::parse_reported`]).
    pub fn from_value(doc: &Value) -> Result<ShapeDesc, ShapeError> {
        Self::from_value_reported(doc).map(|(shape, _)| shape)
    }

    fn from_value_reported(doc: &Value) -> Result<(ShapeDesc, InputApprox), ShapeError> {
        let mut approx = InputApprox::default();
        let shape = Self::from_value_into(doc, &mut approx)?;
        Ok((shape, approx))
    }

    fn from_value_into(doc: &Value, approx: &mut InputApprox) -> Result<ShapeDesc, ShapeError> {
        let Value::Object(map) = doc else {
            return Err(err(
                "(top level)",
                format!("expected an object, found {}", describe(doc)),
            ));
        };
        let kinds = [
            "arc",
            "ellipse_arc",
            "offset",
            "convolution",
            "union",
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
        if map.contains_key("stroke") {
            return Err(err(
                "stroke",
                "the exact boundary of a stroke is not a shape of certificates: `lncert hausdorff` referees it (lncert::stroke::StrokeShape), and `lncert verify --against` reads it as the curve and the pen a stroke certificate states",
            ));
        }
        if let Some(u) = map.get("union") {
            check_keys(map, "(top level)", &["union"])?;
            let Value::Array(members) = u else {
                return Err(err(
                    "union",
                    format!("expected a list of shapes, found {}", describe(u)),
                ));
            };
            let members = members
                .iter()
                .enumerate()
                .map(|(i, m)| {
                    if m.get("union").is_some() {
                        return Err(err(
                            format!("union[{i}]"),
                            "a union's members are not unions",
                        ));
                    }
                    if let Value::String(_) = m {
                        // SVG path data: a curve, as at the top level
                        return curve_value(m, &format!("union[{i}]"), approx)
                            .and_then(ShapeDesc::curve);
                    }
                    Self::from_value_into(m, approx).map_err(|e| {
                        let field = if e.field == "(top level)" {
                            format!("union[{i}]")
                        } else {
                            format!("union[{i}].{}", e.field)
                        };
                        err(field, e.reason)
                    })
                })
                .collect::<Result<Vec<_>, _>>()?;
            return ShapeDesc::union(members);
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
            let (from, to) = arc_directions(m, "arc")?;
            let arc = ArcDesc {
                center: point(m.get("center"), "arc.center")?,
                radius: number(m.get("radius"), "arc.radius")?,
                from,
                to,
            };
            return ShapeDesc::arc(arc);
        }
        if let Some(a) = map.get("ellipse_arc") {
            check_keys(map, "(top level)", &["ellipse_arc"])?;
            let Value::Object(m) = a else {
                return Err(err(
                    "ellipse_arc",
                    format!("expected an object, found {}", describe(a)),
                ));
            };
            check_keys(
                m,
                "ellipse_arc",
                &["center", "matrix", "from", "to", "clockwise"],
            )?;
            let (from, to) = arc_directions(m, "ellipse_arc")?;
            let rows = match m.get("matrix") {
                Some(Value::Array(rows)) if rows.len() == 2 => rows,
                _ => {
                    return Err(err(
                        "ellipse_arc.matrix",
                        "expected the 2×2 matrix [[m11, m12], [m21, m22]]",
                    ))
                }
            };
            let r0 = point(rows.first(), "ellipse_arc.matrix[0]")?;
            let r1 = point(rows.get(1), "ellipse_arc.matrix[1]")?;
            return ShapeDesc::ellipse_arc(EllipseArcDesc {
                center: point(m.get("center"), "ellipse_arc.center")?,
                matrix: [[r0.x, r0.y], [r1.x, r1.y]],
                from,
                to,
            });
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
                approx,
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
                approx,
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
                // the integers 1 and -1 (not 1.0, not the string "1")
                Some(v) if v.as_i64() == Some(1) => 1,
                Some(v) if v.as_i64() == Some(-1) => -1,
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

    /// A curve shape, with the checks of the canonical form: 2 to 64 control
    /// points per piece, coordinates within [`MAX_COORDINATE`].
    pub fn curve(pieces: Vec<Bezier<Rational>>) -> Result<ShapeDesc, ShapeError> {
        checked_curve(pieces, "curve")
    }

    /// An arc: `radius > 0`, nonzero directions, a nonzero sweep (`from` and `to`
    /// not the same direction; full circles are not supported).
    pub fn arc(a: ArcDesc) -> Result<ShapeDesc, ShapeError> {
        checked_arc(a, "arc").map(ShapeDesc::Arc)
    }

    /// An elliptic arc: a nonsingular matrix, nonzero directions, a nonzero
    /// sweep (full ellipses are not supported).
    ///
    /// # Examples
    /// ```
    /// use lncert::shape::ShapeDesc;
    /// let half = ShapeDesc::parse(
    ///     r#"{"ellipse_arc": {"center": [0, 0], "matrix": [[2, 0], [0, 1]], "from": [1, 0], "to": [-1, 0]}}"#,
    /// ).unwrap();
    /// assert_eq!(half.summary(), "elliptic arc");
    /// let e = ShapeDesc::parse(
    ///     r#"{"ellipse_arc": {"center": [0, 0], "matrix": [[2, 4], [1, 2]], "from": [1, 0], "to": [-1, 0]}}"#,
    /// ).unwrap_err();
    /// assert_eq!(e.field, "ellipse_arc.matrix");
    /// ```
    pub fn ellipse_arc(a: EllipseArcDesc) -> Result<ShapeDesc, ShapeError> {
        checked_ellipse_arc(a, "ellipse_arc").map(|a| ShapeDesc::EllipseArc(Box::new(a)))
    }

    /// An offset at signed distance `distance ≠ 0` of a regular curve.
    pub fn offset(
        curve: Vec<Bezier<Rational>>,
        distance: Rational,
    ) -> Result<ShapeDesc, ShapeError> {
        checked_offset(curve, distance, "offset.curve", "offset.distance")
    }

    /// A convolution with the ellipse `M · unit circle`, `det M ≠ 0`, `side = ±1`.
    pub fn convolution(
        curve: Vec<Bezier<Rational>>,
        m: [[Rational; 2]; 2],
        side: i8,
    ) -> Result<ShapeDesc, ShapeError> {
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

    /// The union of `members` (at least one, none a union, at most
    /// [`super::MAX_SEGMENTS`] pieces in all; each member already checked by
    /// its own constructor).
    ///
    /// # Examples
    /// ```
    /// use lncert::shape::ShapeDesc;
    /// let u = ShapeDesc::parse(r#"{"union": ["M 0 0 L 1 0", {"arc": {"center": [1, 1], "radius": 1, "from": [0, -1], "to": [1, 0]}}]}"#).unwrap();
    /// assert_eq!(u.piece_count(), 2);
    /// let e = ShapeDesc::parse(r#"{"union": [{"arc": {"center": [0, 0], "radius": 0, "from": [1, 0], "to": [0, 1]}}]}"#).unwrap_err();
    /// assert_eq!(e.field, "union[0].arc.radius");
    /// ```
    pub fn union(members: Vec<ShapeDesc>) -> Result<ShapeDesc, ShapeError> {
        if members.is_empty() {
            return Err(err("union", "no members"));
        }
        if let Some(i) = members
            .iter()
            .position(|m| matches!(m, ShapeDesc::Union(_)))
        {
            return Err(err(
                format!("union[{i}]"),
                "a union's members are not unions",
            ));
        }
        let n: usize = members.iter().map(ShapeDesc::piece_count).sum();
        if n > super::MAX_SEGMENTS {
            return Err(err(
                "union",
                format!("{n} pieces in all, above the limit {}", super::MAX_SEGMENTS),
            ));
        }
        Ok(ShapeDesc::Union(members))
    }

    /// How many pieces the shape has (a union: all its members').
    pub fn piece_count(&self) -> usize {
        match self {
            ShapeDesc::Curve(c) => c.len(),
            ShapeDesc::Arc(_) | ShapeDesc::EllipseArc(_) => 1,
            ShapeDesc::Offset { curve, .. } | ShapeDesc::Convolution { curve, .. } => curve.len(),
            ShapeDesc::Union(m) => m.iter().map(ShapeDesc::piece_count).sum(),
        }
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
            ShapeDesc::EllipseArc(a) => {
                let m = &a.matrix;
                json!({"ellipse_arc": {"center": p(&a.center),
                    "matrix": [[q(&m[0][0]), q(&m[0][1])], [q(&m[1][0]), q(&m[1][1])]],
                    "from": p(&a.from), "to": p(&a.to)}})
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
            ShapeDesc::Union(m) => {
                json!({"union": m.iter().map(ShapeDesc::to_json).collect::<Vec<_>>()})
            }
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
            ShapeDesc::EllipseArc(_) => "elliptic arc".to_string(),
            ShapeDesc::Offset { curve, distance } => {
                format!("offset at {} of {} piece(s)", distance, curve.len())
            }
            ShapeDesc::Convolution { curve, .. } => {
                format!("convolution of {} piece(s) with an ellipse", curve.len())
            }
            ShapeDesc::Union(m) if m.len() <= 3 => format!(
                "union of {}",
                m.iter()
                    .map(ShapeDesc::summary)
                    .collect::<Vec<_>>()
                    .join(" and ")
            ),
            ShapeDesc::Union(m) => {
                // many members (an SVG document): counted by kind
                let count = |f: fn(&ShapeDesc) -> bool| m.iter().filter(|s| f(s)).count();
                let kinds = [
                    (count(|s| matches!(s, ShapeDesc::Curve(_))), "curve(s)"),
                    (count(|s| matches!(s, ShapeDesc::Arc(_))), "circular arc(s)"),
                    (
                        count(|s| matches!(s, ShapeDesc::EllipseArc(_))),
                        "elliptic arc(s)",
                    ),
                    (
                        count(|s| matches!(s, ShapeDesc::Offset { .. })),
                        "offset(s)",
                    ),
                    (
                        count(|s| matches!(s, ShapeDesc::Convolution { .. })),
                        "convolution(s)",
                    ),
                ];
                let parts: Vec<String> = kinds
                    .iter()
                    .filter(|(n, _)| *n > 0)
                    .map(|(n, what)| format!("{n} {what}"))
                    .collect();
                format!(
                    "union of {} shapes ({} pieces): {}",
                    m.len(),
                    self.piece_count(),
                    parts.join(", ")
                )
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
            ShapeDesc::EllipseArc(a) => {
                a.center.x.approx().abs().max(a.center.y.approx().abs())
                    + a.matrix
                        .iter()
                        .flatten()
                        .map(|x| x.approx().abs())
                        .sum::<f64>()
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
            ShapeDesc::Union(m) => m.iter().map(ShapeDesc::scale).fold(0.0, f64::max),
        }
    }
}

fn check_magnitude(r: &Rational, field: &str) -> Result<(), ShapeError> {
    // exactly |r| ≤ 10¹⁰⁰ (`MAX_COORDINATE`), the rule the verifier applies too
    if !crate::scalar::abs_le_pow10(r, 100) {
        return Err(err(
            field,
            format!("magnitude above the supported limit {MAX_COORDINATE:e}"),
        ));
    }
    Ok(())
}

fn check_pieces(c: &[Bezier<Rational>], field: &str) -> Result<(), ShapeError> {
    if c.is_empty() {
        return Err(err(field, "no curve pieces"));
    }
    for (i, b) in c.iter().enumerate() {
        // the canonical form (what certificates store) writes 2 to 64 points
        // per piece: a single point is a piece with 2 equal points
        let n = b.points().len();
        if !(2..=super::io::MAX_CONTROL_POINTS).contains(&n) {
            return Err(err(
                format!("{field}[{i}]"),
                format!(
                    "{n} control points; a piece has 2 to {} (a single point is written with 2 equal points)",
                    super::io::MAX_CONTROL_POINTS
                ),
            ));
        }
        for (k, p) in b.points().iter().enumerate() {
            check_magnitude(&p.x, &format!("{field}[{i}][{k}][0]"))?;
            check_magnitude(&p.y, &format!("{field}[{i}][{k}][1]"))?;
        }
    }
    Ok(())
}

/// Some direction `v` (the first or last control point, or their sum) has
/// `v·h_k > 0` for every control point `h_k` of the hodograph `h`, exactly:
/// then `v·x′(t) = Σ B_k(t) v·h_k > 0` on `[0, 1]` (the Bernstein weights are
/// nonnegative and sum to 1), so `x′` has no zero there. The common case,
/// decided without the polynomial gcd.
fn one_sided(h: &Bezier<Rational>) -> bool {
    use crate::scalar::{interval_from_rational, Interval};
    let p = h.points();
    let pi: Vec<(Interval, Interval)> = p
        .iter()
        .map(|q| (interval_from_rational(&q.x), interval_from_rational(&q.y)))
        .collect();
    let (first, last) = (&p[0], &p[p.len() - 1]);
    let (fi, li) = (pi[0], pi[p.len() - 1]);
    let sum = first.add(last);
    let sum_i = (fi.0 + li.0, fi.1 + li.1);
    // each sign by the enclosure of the dot product, exactly only where it
    // holds 0 (the control points of an exact span have long numerators)
    [(first, fi), (last, li), (&sum, sum_i)]
        .iter()
        .any(|(v, vi)| {
            p.iter().zip(&pi).all(|(q, qi)| {
                let d = vi.0 * qi.0 + vi.1 * qi.1;
                d.inf() > 0.0 || (d.sup() > 0.0 && v.dot(q).is_positive())
            })
        })
}

/// The offset and the convolution need a normal everywhere: `x′(t) ≠ 0` on `[0, 1]`,
/// decided exactly (no common root of `x′` and `y′`).
fn check_regular(c: &[Bezier<Rational>], field: &str) -> Result<(), ShapeError> {
    for (i, b) in c.iter().enumerate() {
        if b.degree() == 0 {
            return Err(err(format!("{field}[{i}]"), "a single point has no normal"));
        }
        let h = b.hodograph();
        if one_sided(&h) {
            continue;
        }
        let (dx, dy) = h.power_coords();
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

#[cfg(test)]
mod tests {
    use super::*;
    use proptest::prelude::*;

    /// The exact decision alone: `x′` and `y′` have a common root on
    /// `[0, 1]` (or vanish identically).
    fn singular_by_gcd(b: &Bezier<Rational>) -> bool {
        let (dx, dy) = b.hodograph().power_coords();
        let (dx, dy) = (dx.trimmed(), dy.trimmed());
        (dx.coeffs().iter().all(Zero::is_zero) && dy.coeffs().iter().all(Zero::is_zero))
            || has_common_root_in(&dx, &dy, &Span::unit_closed())
    }

    fn cubic(p: [(i64, i64); 4]) -> Bezier<Rational> {
        Bezier::new(
            p.iter()
                .map(|&(x, y)| {
                    V2::new(
                        Rational::from_integer(x.into()),
                        Rational::from_integer(y.into()),
                    )
                })
                .collect(),
        )
    }

    #[test]
    fn singular_cubics_are_not_one_sided() {
        // a cusp at t = 1/2, a zero end derivative, a reversal (a quadratic
        // whose control point lies beyond its end), a point
        for b in [
            cubic([(0, 0), (1, 1), (0, 1), (1, 0)]),
            cubic([(0, 0), (0, 0), (1, 2), (3, 1)]),
            Bezier::new(cubic([(0, 0), (4, 0), (2, 0), (2, 0)]).points()[..3].to_vec()),
        ] {
            assert!(singular_by_gcd(&b), "{b:?}");
            assert!(!one_sided(&b.hodograph()), "{b:?}");
            assert!(check_regular(std::slice::from_ref(&b), "curve").is_err());
        }
    }

    proptest! {
        #![proptest_config(ProptestConfig::with_cases(512))]

        /// The hull filter never accepts a singular piece: wherever it
        /// decides, the exact gcd test finds no common root; and the checked
        /// verdict is the gcd's on every piece.
        #[test]
        fn the_hull_filter_agrees_with_the_exact_gcd(
            p in proptest::collection::vec((-6i64..=6, -6i64..=6), 2..=5)
        ) {
            let b = Bezier::new(
                p.iter()
                    .map(|&(x, y)| V2::new(Rational::from_integer(x.into()), Rational::from_integer(y.into())))
                    .collect(),
            );
            let singular = singular_by_gcd(&b);
            if one_sided(&b.hodograph()) {
                prop_assert!(!singular);
            }
            prop_assert_eq!(check_regular(std::slice::from_ref(&b), "curve").is_err(), singular);
        }
    }
}
