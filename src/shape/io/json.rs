//! The JSON forms of a curve — `{"bezier"}`, `{"beziers"}`, `{"bspline"}` —
//! read field by field, every number exactly, every error naming its field.

use super::{
    exact_number, field_err, CurveParseError, MAX_BSPLINE_WORK, MAX_CONTROL_POINTS, MAX_SEGMENTS,
};
use crate::curve::{BSpline, Bezier, V2};
use crate::scalar::Rational;
use serde_json::Value;

pub(crate) fn describe(v: &Value) -> String {
    match v {
        Value::Null => "null".to_string(),
        Value::Bool(_) => "a boolean".to_string(),
        Value::Number(_) => "a number".to_string(),
        Value::String(_) => "a string".to_string(),
        Value::Array(a) => format!("an array of {} elements", a.len()),
        Value::Object(_) => "an object".to_string(),
    }
}

pub(crate) fn json_coordinate(v: &Value, field: &str) -> Result<Rational, CurveParseError> {
    let text = match v {
        Value::String(s) => s.clone(),
        // With serde_json's `arbitrary_precision`, this is the number's digits
        // exactly as written.
        Value::Number(n) => n.to_string(),
        other => {
            return Err(field_err(
                field,
                format!(
                    "expected a number or a numeric string, found {}",
                    describe(other)
                ),
            ))
        }
    };
    exact_number(&text).map_err(|reason| field_err(field, reason))
}

pub(crate) fn json_point(v: &Value, field: &str) -> Result<V2<Rational>, CurveParseError> {
    match v.as_array().map(Vec::as_slice) {
        Some([x, y]) => Ok(V2::new(
            json_coordinate(x, &format!("{field}[0]"))?,
            json_coordinate(y, &format!("{field}[1]"))?,
        )),
        _ => Err(field_err(
            field,
            format!("expected [x, y], found {}", describe(v)),
        )),
    }
}

fn json_bezier(v: &Value, field: &str) -> Result<Bezier<Rational>, CurveParseError> {
    let Some(items) = v.as_array() else {
        return Err(field_err(
            field,
            format!(
                "expected a list of control points [[x, y], ...], found {}",
                describe(v)
            ),
        ));
    };
    if items.len() > MAX_CONTROL_POINTS {
        return Err(CurveParseError::TooLarge {
            what: format!(
                "the number of control points ({}) in field `{field}`",
                items.len()
            ),
            limit: MAX_CONTROL_POINTS,
        });
    }
    let pts = items
        .iter()
        .enumerate()
        .map(|(i, p)| json_point(p, &format!("{field}[{i}]")))
        .collect::<Result<Vec<_>, _>>()?;
    if pts.len() < 2 {
        return Err(field_err(
            field,
            format!(
                "a Bézier curve needs at least 2 control points (degree ≥ 1), found {}",
                pts.len()
            ),
        ));
    }
    Ok(Bezier::new(pts))
}

/// The keys of the `"bspline"` object.
const BSPLINE_KEYS: [&str; 3] = ["degree", "knots", "control_points"];

/// Reads the `"bspline"` object `{"degree": p, "knots": "clamped" |
/// "periodic" | [k0, ...], "control_points": [[x, y], ...]}` into its Bézier
/// pieces.
fn json_bspline(v: &Value) -> Result<Vec<Bezier<Rational>>, CurveParseError> {
    let Value::Object(obj) = v else {
        return Err(field_err(
            "bspline",
            format!(
                "expected an object {{\"degree\": ..., \"knots\": ..., \"control_points\": ...}}, found {}",
                describe(v)
            ),
        ));
    };
    if let Some(key) = obj.keys().find(|k| !BSPLINE_KEYS.contains(&k.as_str())) {
        return Err(field_err(
            &format!("bspline.{key}"),
            "unknown field; expected \"degree\", \"knots\" and \"control_points\"",
        ));
    }
    let get = |key: &str| {
        obj.get(key)
            .ok_or_else(|| field_err(&format!("bspline.{key}"), "missing"))
    };
    let degree = bspline_degree(get("degree")?)?;
    let pts = bspline_control_points(get("control_points")?, degree)?;
    let spline = bspline_knots(get("knots")?, degree, pts)?;
    Ok(spline.to_beziers())
}

/// `bspline.degree`: an exact integer in 1..=63 (checked before any
/// conversion, so `1e400` or `-3` is an error, not an overflow).
fn bspline_degree(v: &Value) -> Result<usize, CurveParseError> {
    let degree_value = json_coordinate(v, "bspline.degree")?;
    if degree_value.is_integer()
        && degree_value >= Rational::from_integer(1.into())
        && degree_value <= Rational::from_integer((MAX_CONTROL_POINTS - 1).into())
    {
        Ok(usize::try_from(degree_value.to_integer()).unwrap_or(usize::MAX))
    } else {
        Err(field_err(
            "bspline.degree",
            format!(
                "expected an integer from 1 to {}, found {}",
                MAX_CONTROL_POINTS - 1,
                match crate::scalar::rational_to_string(&degree_value) {
                    text if text.len() <= 40 => text,
                    _ => "a number far out of that range".to_string(),
                }
            ),
        ))
    }
}

/// `bspline.control_points`, within the limits of their number and of the
/// exact conversion's work at `degree`.
fn bspline_control_points(
    cps: &Value,
    degree: usize,
) -> Result<Vec<V2<Rational>>, CurveParseError> {
    let Some(items) = cps.as_array() else {
        return Err(field_err(
            "bspline.control_points",
            format!(
                "expected a list of control points [[x, y], ...], found {}",
                describe(cps)
            ),
        ));
    };
    if items.len() > MAX_SEGMENTS {
        return Err(CurveParseError::TooLarge {
            what: format!(
                "the number of control points ({}) in field `bspline.control_points`",
                items.len()
            ),
            limit: MAX_SEGMENTS,
        });
    }
    // Exact knot insertion costs about degree³ big-number operations per piece
    // (with numbers of up to ~40·degree bits): bound the work (a few seconds).
    let work = (items.len() as u128) * (degree as u128).pow(3);
    if work > MAX_BSPLINE_WORK {
        return Err(CurveParseError::TooLarge {
            what: format!(
                "control points × degree³ ({} × {degree}³) in field `bspline`",
                items.len()
            ),
            limit: MAX_BSPLINE_WORK as usize,
        });
    }
    items
        .iter()
        .enumerate()
        .map(|(i, p)| json_point(p, &format!("bspline.control_points[{i}]")))
        .collect()
}

/// The spline of `bspline.knots` (`"clamped"`, `"periodic"` or an explicit
/// list of `control points + degree + 1` numbers) over `pts`.
fn bspline_knots(
    knots: &Value,
    degree: usize,
    pts: Vec<V2<Rational>>,
) -> Result<BSpline, CurveParseError> {
    Ok(match knots {
        Value::String(s) if s == "clamped" => BSpline::clamped_uniform(degree, pts)?,
        Value::String(s) if s == "periodic" => BSpline::periodic_uniform(degree, pts)?,
        Value::Array(list) => {
            // The count first, so that no knot is read in vain.
            let expected = pts.len() + degree + 1;
            if list.len() != expected {
                return Err(field_err(
                    "bspline.knots",
                    format!(
                        "expected {expected} knots (control points + degree + 1 = {} + {degree} + 1), found {}",
                        pts.len(),
                        list.len()
                    ),
                ));
            }
            let ks = list
                .iter()
                .enumerate()
                .map(|(i, k)| json_coordinate(k, &format!("bspline.knots[{i}]")))
                .collect::<Result<Vec<_>, _>>()?;
            BSpline::new(degree, ks, pts)?
        }
        other => {
            return Err(field_err(
                "bspline.knots",
                format!(
                    "expected \"clamped\", \"periodic\" or a list of numbers, found {}",
                    match other {
                        Value::String(s) => format!("the string {s:?}"),
                        _ => describe(other),
                    }
                ),
            ))
        }
    })
}

/// The top-level curve fields of the JSON form; exactly one is given.
const CURVE_KEYS: [&str; 3] = ["bezier", "beziers", "bspline"];

/// Reads `{"bezier": [[x, y], ...]}` (one Bézier curve of degree ≥ 1),
/// `{"beziers": [[[x, y], ...], ...]}` (a piecewise curve) or
/// `{"bspline": {"degree": p, "knots": "clamped" | "periodic" | [k0, ...],
/// "control_points": [[x, y], ...]}}` (a B-spline, returned as its Bézier
/// pieces), every number a JSON number or a numeric string, read exactly.
///
/// # Examples
/// ```
/// use lncert::shape::parse_json_curve;
/// use lncert::scalar::parse_rational;
/// let c = parse_json_curve(r#"{"bezier": [[-0.95, "0.7"], ["1/3", 1e-3]]}"#).unwrap();
/// assert_eq!(c.len(), 1);
/// assert_eq!(c[0].degree(), 1);
/// assert_eq!(c[0].points()[0].x, parse_rational("-19/20").unwrap());
/// assert_eq!(c[0].points()[1].y, parse_rational("1/1000").unwrap());
///
/// let pieces = parse_json_curve(r#"{"beziers": [[[0, 0], [1, 1]], [[1, 1], [2, 0], [3, 1]]]}"#);
/// assert_eq!(pieces.unwrap().len(), 2);
///
/// let spline = r#"{"bspline": {"degree": 2, "knots": "clamped",
///                  "control_points": [[0, 0], [1, 2], [2, 0], [3, 2]]}}"#;
/// let pieces = parse_json_curve(spline).unwrap();
/// assert_eq!(pieces.len(), 2);
/// assert_eq!(pieces[0].points()[2].x, parse_rational("3/2").unwrap());
///
/// assert!(parse_json_curve(r#"{"bezier": [[1, 2]]}"#).is_err()); // too few points
/// ```
pub fn parse_json_curve(text: &str) -> Result<Vec<Bezier<Rational>>, CurveParseError> {
    let doc: Value = crate::json::parse(text, &crate::json::Limits::DEFAULT)
        .map_err(|e| match e.kind {
            // a duplicate or an over-limit value is a problem of a field
            crate::json::ErrorKind::Duplicate | crate::json::ErrorKind::Limit
                if e.path != "(top level)" =>
            {
                field_err(
                    &e.path,
                    format!("{} (line {}, column {})", e.reason, e.line, e.column),
                )
            }
            _ => CurveParseError::Json {
                message: e.to_string(),
            },
        })?
        .to_value();
    let Value::Object(map) = &doc else {
        return Err(field_err(
            "(top level)",
            format!(
                "expected an object {{\"bezier\": ...}}, {{\"beziers\": ...}} or {{\"bspline\": ...}}, found {}",
                describe(&doc)
            ),
        ));
    };
    if let Some(key) = map.keys().find(|k| !CURVE_KEYS.contains(&k.as_str())) {
        return Err(field_err(
            key,
            "unknown field; expected \"bezier\" (one curve), \"beziers\" (a list of curves) or \"bspline\" (a B-spline)",
        ));
    }
    let given: Vec<&str> = CURVE_KEYS
        .into_iter()
        .filter(|k| map.contains_key(*k))
        .collect();
    match given.as_slice() {
        [] => Err(field_err(
            "bezier",
            "missing; expected \"bezier\" (one curve), \"beziers\" (a list of curves) or \"bspline\" (a B-spline)",
        )),
        [first, second, ..] => Err(field_err(
            second,
            format!(
                "give exactly one of \"bezier\", \"beziers\" and \"bspline\", not both \"{first}\" and \"{second}\""
            ),
        )),
        ["bspline"] => json_bspline(&map["bspline"]),
        ["bezier"] => Ok(vec![json_bezier(&map["bezier"], "bezier")?]),
        // The one remaining key, "beziers".
        [_] => json_beziers(&map["beziers"]),
    }
}

/// Reads the `"beziers"` list of control-point lists (a piecewise curve).
fn json_beziers(list: &Value) -> Result<Vec<Bezier<Rational>>, CurveParseError> {
    let Some(items) = list.as_array() else {
        return Err(field_err(
            "beziers",
            format!(
                "expected a list of curves [[[x, y], ...], ...], found {}",
                describe(list)
            ),
        ));
    };
    if items.is_empty() {
        return Err(CurveParseError::Empty {
            what: "field `beziers`".to_string(),
        });
    }
    if items.len() > MAX_SEGMENTS {
        return Err(CurveParseError::TooLarge {
            what: format!(
                "the number of segments ({}) in field `beziers`",
                items.len()
            ),
            limit: MAX_SEGMENTS,
        });
    }
    items
        .iter()
        .enumerate()
        .map(|(i, b)| json_bezier(b, &format!("beziers[{i}]")))
        .collect()
}
