//! Exact curve input: Bézier curves from JSON or SVG path data, with every
//! number read *exactly* as a rational (`0.95` is `19/20`, `1/3` is `1/3`),
//! never through `f64`.
//!
//! # JSON
//!
//! One Bézier curve of any degree ≥ 1 (2 to 64 control points):
//!
//! ```json
//! {"bezier": [["-0.95", "0.7"], [-0.3, 0.5], ["3/10", "-2.5"], [0.9, -0.2]]}
//! ```
//!
//! or a piecewise curve, a list of such control-point lists (at most 100 000):
//!
//! ```json
//! {"beziers": [[[0, 0], [1, 1]], [[1, 1], [2, 0], [3, 1]]]}
//! ```
//!
//! or a B-spline curve of degree 1 to 63 (at most 100 000 control points),
//! read as its polynomial pieces (one Bézier curve of the spline's degree per
//! non-empty knot span, computed exactly; see [`crate::curve::BSpline`]):
//!
//! ```json
//! {"bspline": {"degree": 3, "knots": "clamped", "control_points": [[0, 0], [1, 2], [3, 2], [4, 0]]}}
//! ```
//!
//! `"knots"` is `"clamped"` (open uniform: `degree + 1` zeros, `1, 2, ...`,
//! `degree + 1` equal end knots; the curve runs from the first control point
//! to the last), `"periodic"` (closed uniform: the first `degree` control
//! points are wrapped around, one piece per given control point) or an
//! explicit non-decreasing list of `control points + degree + 1` numbers.
//! No other key is accepted inside `"bspline"`.
//!
//! Each coordinate (and each knot, and the degree) is a JSON number or a JSON
//! string holding a decimal (`"-1.5e-3"`) or fraction (`"-7/6"`) literal. JSON
//! numbers are read from their digits as written (`0.1` is exactly `1/10`).
//! Exactly one of `"bezier"`, `"beziers"` and `"bspline"` is given, and no
//! other top-level field is accepted, so a misspelt key is reported instead of
//! ignored.
//!
//! # SVG path data
//!
//! ```text
//! M 0 0 C 1 2 3 4 5 6 S 7 8 9 10 L 0 0 Z
//! ```
//!
//! The commands `M m L l H h V v C c S s Q q T t A a Z z` are understood, with
//! the implicit repetition of parameters of the SVG specification (`M`
//! followed by further pairs draws lines). Every drawing segment becomes one
//! Bézier curve: lines of degree 1, quadratics of degree 2, cubics of degree
//! 3; `Z` adds a closing line when the current point is not the subpath's
//! start.
//!
//! Elliptical arcs (`A a`, SVG 1.1 F.6.5–F.6.6: flags `0`/`1`, radii made
//! absolute and scaled up when too small, identical end points omit the arc,
//! a zero radius draws a line) are not polynomial curves: each is
//! *approximated* by cubic pieces whose Hausdorff distance from the exact arc
//! is certified (target `1e-7 · max(rx, ry)`, see [`super::svgarc`]). The
//! pieces start and end exactly at the arc's end points as read.
//! [`parse_svg_path_reported`] and [`parse_curve_reported`] return the list
//! of approximated commands with their bounds ([`InputApprox`]);
//! [`parse_svg_path`] and [`parse_curve`] drop it.
//!
//! # Errors and limits
//!
//! Every error names *where* (a JSON field path such as `bezier[2][1]` or
//! `bspline.knots[3]`, or a byte offset in the path data) and *why*; see
//! [`CurveParseError`]. The parsers never panic and do bounded work: at most 64
//! control points per segment, 100 000 segments, 100 000 B-spline control
//! points of degree at most 63, 1 000 000 bytes of SVG path data, 4 096
//! characters per number literal (whose decimal exponent `parse_rational`
//! bounds further).

use super::svgarc::{svg_arc, ApproxElement, ApproxKind, InputApprox, SvgArc};
pub(crate) use crate::curve::field_err;
pub use crate::curve::CurveParseError;
use crate::curve::{BSpline, Bezier, V2};
use crate::scalar::{parse_rational, ParseNumberError, Rational};
use serde_json::Value;

/// Most control points accepted in one segment (degree ≤ 63).
pub const MAX_CONTROL_POINTS: usize = 64;
/// Most segments accepted in one curve.
pub const MAX_SEGMENTS: usize = 100_000;
/// Largest SVG path data accepted, in bytes.
pub const MAX_SVG_BYTES: usize = 1_000_000;
/// Largest `control points × degree³` of a B-spline (the exact conversion's work).
pub const MAX_BSPLINE_WORK: u128 = 50_000_000;
/// Longest number literal accepted, in characters.
pub const MAX_NUMBER_CHARS: usize = 4096;

/// Reads a number literal exactly, guarding `parse_rational` against inputs
/// that are too long or whose exponents do not fit an `i64`; the error is a
/// human-readable reason.
fn exact_number(text: &str) -> Result<Rational, String> {
    let err = |reason: &'static str| {
        ParseNumberError {
            input: text.to_string(),
            reason,
        }
        .to_string()
    };
    if text.chars().count() > MAX_NUMBER_CHARS {
        return Err(format!(
            "number literal of {} characters is longer than the limit of {MAX_NUMBER_CHARS}",
            text.chars().count()
        ));
    }
    let bare = text
        .trim()
        .trim_start_matches(['+', '-'])
        .to_ascii_lowercase();
    if bare == "nan" {
        return Err("NaN is not a finite number".to_string());
    }
    if bare == "inf" || bare == "infinity" {
        return Err(format!("{} is not a finite number", text.trim()));
    }
    // Any exponent with more than 6 significant digits is beyond
    // parse_rational's bound anyway; rejecting it here keeps its i64
    // arithmetic far from overflow.
    let bytes = text.as_bytes();
    for (i, &b) in bytes.iter().enumerate() {
        if b == b'e' || b == b'E' {
            let rest = bytes.get(i + 1..).unwrap_or(&[]);
            let rest = match rest.first() {
                Some(b'+') | Some(b'-') => rest.get(1..).unwrap_or(&[]),
                _ => rest,
            };
            let significant = rest
                .iter()
                .take_while(|c| c.is_ascii_digit())
                .skip_while(|&&c| c == b'0')
                .count();
            if significant > 6 {
                return Err(err("exponent out of range (|e| > 400)"));
            }
        }
    }
    parse_rational(text).map_err(|e| e.to_string())
}

// ---------------------------------------------------------------------------
// JSON
// ---------------------------------------------------------------------------

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

    // Degree: an exact integer in 1..=63 (checked before any conversion, so
    // `1e400` or `-3` is an error, not an overflow).
    let degree_value = json_coordinate(get("degree")?, "bspline.degree")?;
    let degree = if degree_value.is_integer()
        && degree_value >= Rational::from_integer(1.into())
        && degree_value <= Rational::from_integer((MAX_CONTROL_POINTS - 1).into())
    {
        usize::try_from(degree_value.to_integer()).unwrap_or(usize::MAX)
    } else {
        return Err(field_err(
            "bspline.degree",
            format!(
                "expected an integer from 1 to {}, found {}",
                MAX_CONTROL_POINTS - 1,
                match crate::scalar::rational_to_string(&degree_value) {
                    text if text.len() <= 40 => text,
                    _ => "a number far out of that range".to_string(),
                }
            ),
        ));
    };

    let cps = get("control_points")?;
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
    let pts = items
        .iter()
        .enumerate()
        .map(|(i, p)| json_point(p, &format!("bspline.control_points[{i}]")))
        .collect::<Result<Vec<_>, _>>()?;

    let knots = get("knots")?;
    let spline = match knots {
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
    };
    Ok(spline.to_beziers())
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
        [_] => {
            let list = &map["beziers"];
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
    }
}

// ---------------------------------------------------------------------------
// SVG path data
// ---------------------------------------------------------------------------

/// The exact path-data state machine: scanner plus current point, subpath
/// start and the control points that `S` and `T` reflect.
struct SvgParser<'a> {
    text: &'a str,
    bytes: &'a [u8],
    pos: usize,
    out: Vec<Bezier<Rational>>,
    cur: V2<Rational>,
    start: V2<Rational>,
    /// Second control point of the previous segment if it was `C`/`S`.
    last_cubic: Option<V2<Rational>>,
    /// Control point of the previous segment if it was `Q`/`T`.
    last_quad: Option<V2<Rational>>,
    /// The approximated arcs.
    approx: InputApprox,
}

fn is_wsp(b: u8) -> bool {
    matches!(b, b' ' | b'\t' | b'\n' | b'\r' | 0x0C)
}

fn is_number_start(b: u8) -> bool {
    b.is_ascii_digit() || matches!(b, b'.' | b'+' | b'-')
}

/// Parameter names of a command (its length is the parameter count).
fn params(cmd: u8) -> &'static [&'static str] {
    match cmd.to_ascii_uppercase() {
        b'M' | b'L' | b'T' => &["x", "y"],
        b'H' => &["x"],
        b'V' => &["y"],
        b'C' => &["x1", "y1", "x2", "y2", "x", "y"],
        b'S' => &["x2", "y2", "x", "y"],
        b'Q' => &["x1", "y1", "x", "y"],
        b'A' => &[
            "rx",
            "ry",
            "x-axis-rotation",
            "large-arc-flag",
            "sweep-flag",
            "x",
            "y",
        ],
        _ => &[],
    }
}

impl<'a> SvgParser<'a> {
    fn new(text: &'a str) -> Self {
        SvgParser {
            text,
            bytes: text.as_bytes(),
            pos: 0,
            out: Vec::new(),
            cur: V2::new(zero(), zero()),
            start: V2::new(zero(), zero()),
            last_cubic: None,
            last_quad: None,
            approx: InputApprox::default(),
        }
    }

    fn err(&self, position: usize, reason: impl Into<String>) -> CurveParseError {
        CurveParseError::Svg {
            position,
            reason: reason.into(),
        }
    }

    fn peek(&self) -> Option<u8> {
        self.bytes.get(self.pos).copied()
    }

    /// The character at `pos`, for messages.
    fn char_at(&self, pos: usize) -> String {
        match self.text.get(pos..).and_then(|s| s.chars().next()) {
            Some(c) => format!("{c:?}"),
            None => "the end of the data".to_string(),
        }
    }

    fn skip_wsp(&mut self) {
        while self.peek().is_some_and(is_wsp) {
            self.pos += 1;
        }
    }

    /// Scans one number in SVG syntax (`-1.5e-3`, `.5`, `1.`) and reads its
    /// text exactly.
    fn number(&mut self) -> Result<Rational, CurveParseError> {
        let begin = self.pos;
        let mut p = self.pos;
        let at = |i: usize| self.bytes.get(i).copied();
        if matches!(at(p), Some(b'+') | Some(b'-')) {
            p += 1;
        }
        let int_start = p;
        while at(p).is_some_and(|b| b.is_ascii_digit()) {
            p += 1;
        }
        let mut digits = p - int_start;
        if at(p) == Some(b'.') {
            p += 1;
            let frac_start = p;
            while at(p).is_some_and(|b| b.is_ascii_digit()) {
                p += 1;
            }
            digits += p - frac_start;
        }
        if digits == 0 {
            return Err(self.err(
                begin,
                format!("expected a number, found {}", self.char_at(begin)),
            ));
        }
        if matches!(at(p), Some(b'e') | Some(b'E')) {
            let mut q = p + 1;
            if matches!(at(q), Some(b'+') | Some(b'-')) {
                q += 1;
            }
            if at(q).is_some_and(|b| b.is_ascii_digit()) {
                while at(q).is_some_and(|b| b.is_ascii_digit()) {
                    q += 1;
                }
                p = q;
            }
        }
        self.pos = p;
        let text = self.text.get(begin..p).unwrap_or("");
        exact_number(text).map_err(|reason| self.err(begin, reason))
    }

    /// Reads the parameters of one segment of `cmd`; `first` says whether
    /// they directly follow the command letter (no comma allowed there).
    fn read_params(&mut self, cmd: u8, first: bool) -> Result<Vec<Rational>, CurveParseError> {
        let names = params(cmd);
        let mut vals = Vec::with_capacity(names.len());
        for (i, name) in names.iter().enumerate() {
            self.skip_wsp();
            if (i > 0 || !first) && self.peek() == Some(b',') {
                self.pos += 1;
                self.skip_wsp();
            }
            if name.ends_with("-flag") {
                // a flag is the single character 0 or 1 (SVG's path grammar:
                // `A 1 1 0 1120 20` has the flags 1, 1 and then x = 20)
                match self.peek() {
                    Some(c @ (b'0' | b'1')) => {
                        self.pos += 1;
                        vals.push(Rational::from_integer(i64::from(c - b'0').into()));
                        continue;
                    }
                    _ => {
                        return Err(self.err(
                            self.pos,
                            format!(
                                "command {} expects the flag `{name}` (0 or 1), found {}",
                                cmd as char,
                                self.char_at(self.pos)
                            ),
                        ))
                    }
                }
            }
            if !self.peek().is_some_and(is_number_start) {
                return Err(self.err(
                    self.pos,
                    format!(
                        "missing parameter: command {} takes {} number{} ({}), expected `{name}` but found {}",
                        cmd as char,
                        names.len(),
                        if names.len() == 1 { "" } else { "s" },
                        names.join(" "),
                        self.char_at(self.pos)
                    ),
                ));
            }
            vals.push(self.number()?);
        }
        Ok(vals)
    }

    fn push(&mut self, pts: Vec<V2<Rational>>, at: usize) -> Result<(), CurveParseError> {
        // Every caller passes at least two points.
        self.push_bezier(Bezier::new(pts), at)
    }

    fn push_bezier(&mut self, b: Bezier<Rational>, at: usize) -> Result<(), CurveParseError> {
        if self.out.len() >= MAX_SEGMENTS {
            return Err(CurveParseError::TooLarge {
                what: format!("the number of segments in the SVG path data (at byte {at})"),
                limit: MAX_SEGMENTS,
            });
        }
        self.out.push(b);
        Ok(())
    }

    /// Point `(x, y)`, relative to the current point for lower-case commands.
    fn point(&self, relative: bool, x: &Rational, y: &Rational) -> V2<Rational> {
        let p = V2::new(x.clone(), y.clone());
        if relative {
            self.cur.add(&p)
        } else {
            p
        }
    }

    /// Applies one parameter set of `cmd`; `repeat` marks implicit repetitions.
    fn apply(
        &mut self,
        cmd: u8,
        v: &[Rational],
        repeat: bool,
        at: usize,
    ) -> Result<(), CurveParseError> {
        let rel = cmd.is_ascii_lowercase();
        let arg = |i: usize| -> Result<&Rational, CurveParseError> {
            v.get(i).ok_or_else(|| CurveParseError::Svg {
                position: at,
                reason: "internal error: missing parameter".to_string(),
            })
        };
        let mut cubic = None;
        let mut quad = None;
        match cmd.to_ascii_uppercase() {
            b'M' if !repeat => {
                let p = self.point(rel, arg(0)?, arg(1)?);
                self.start = p.clone();
                self.cur = p;
            }
            b'M' | b'L' => {
                let p = self.point(rel, arg(0)?, arg(1)?);
                self.line_to(p, at)?;
            }
            b'H' => {
                let x = if rel {
                    self.cur.x.clone() + arg(0)?.clone()
                } else {
                    arg(0)?.clone()
                };
                let p = V2::new(x, self.cur.y.clone());
                self.line_to(p, at)?;
            }
            b'V' => {
                let y = if rel {
                    self.cur.y.clone() + arg(0)?.clone()
                } else {
                    arg(0)?.clone()
                };
                let p = V2::new(self.cur.x.clone(), y);
                self.line_to(p, at)?;
            }
            b'C' => {
                let c1 = self.point(rel, arg(0)?, arg(1)?);
                let c2 = self.point(rel, arg(2)?, arg(3)?);
                let p = self.point(rel, arg(4)?, arg(5)?);
                self.push(vec![self.cur.clone(), c1, c2.clone(), p.clone()], at)?;
                self.cur = p;
                cubic = Some(c2);
            }
            b'S' => {
                let c1 = self.reflect(&self.last_cubic);
                let c2 = self.point(rel, arg(0)?, arg(1)?);
                let p = self.point(rel, arg(2)?, arg(3)?);
                self.push(vec![self.cur.clone(), c1, c2.clone(), p.clone()], at)?;
                self.cur = p;
                cubic = Some(c2);
            }
            b'Q' => {
                let c = self.point(rel, arg(0)?, arg(1)?);
                let p = self.point(rel, arg(2)?, arg(3)?);
                self.push(vec![self.cur.clone(), c.clone(), p.clone()], at)?;
                self.cur = p;
                quad = Some(c);
            }
            b'T' => {
                let c = self.reflect(&self.last_quad);
                let p = self.point(rel, arg(0)?, arg(1)?);
                self.push(vec![self.cur.clone(), c.clone(), p.clone()], at)?;
                self.cur = p;
                quad = Some(c);
            }
            b'A' => {
                // (an arc resets what S and T reflect: neither `cubic` nor `quad`)
                let p = self.point(rel, arg(5)?, arg(6)?);
                let (large, sweep) = (
                    !num_traits::Zero::is_zero(arg(3)?),
                    !num_traits::Zero::is_zero(arg(4)?),
                );
                let arc = svg_arc(&self.cur, arg(0)?, arg(1)?, arg(2)?, large, sweep, &p)
                    .map_err(|reason| self.err(at, reason))?;
                match arc {
                    SvgArc::Omitted => {}
                    SvgArc::Line => self.line_to(p.clone(), at)?,
                    SvgArc::Cubics { pieces, bound } => {
                        let n = pieces.len();
                        for b in pieces {
                            self.push_bezier(b, at)?;
                        }
                        self.approx.push(ApproxElement {
                            kind: ApproxKind::Arc,
                            at: format!("byte {at}"),
                            pieces: n,
                            bound,
                            detail: String::new(),
                        });
                    }
                }
                self.cur = p;
            }
            _ => return Err(self.err(at, format!("unknown command {:?}", cmd as char))),
        }
        self.last_cubic = cubic;
        self.last_quad = quad;
        Ok(())
    }

    /// The reflection of `ctrl` about the current point, or the current
    /// point when the previous segment was of another kind.
    fn reflect(&self, ctrl: &Option<V2<Rational>>) -> V2<Rational> {
        match ctrl {
            Some(c) => self.cur.add(&self.cur.sub(c)),
            None => self.cur.clone(),
        }
    }

    fn line_to(&mut self, p: V2<Rational>, at: usize) -> Result<(), CurveParseError> {
        self.push(vec![self.cur.clone(), p.clone()], at)?;
        self.cur = p;
        Ok(())
    }

    fn close(&mut self, at: usize) -> Result<(), CurveParseError> {
        if self.cur != self.start {
            let (cur, start) = (self.cur.clone(), self.start.clone());
            self.push(vec![cur, start], at)?;
        }
        self.cur = self.start.clone();
        self.last_cubic = None;
        self.last_quad = None;
        Ok(())
    }

    fn run(mut self) -> Result<(Vec<Bezier<Rational>>, InputApprox), CurveParseError> {
        if self.bytes.len() > MAX_SVG_BYTES {
            return Err(CurveParseError::TooLarge {
                what: format!("the SVG path data ({} bytes)", self.bytes.len()),
                limit: MAX_SVG_BYTES,
            });
        }
        self.skip_wsp();
        if self.pos >= self.bytes.len() {
            return Err(CurveParseError::Empty {
                what: "the SVG path data".to_string(),
            });
        }
        let mut seen_move = false;
        while let Some(c) = self.peek() {
            let at = self.pos;
            if !c.is_ascii_alphabetic() {
                let reason = if seen_move {
                    format!("expected a command letter, found {}", self.char_at(at))
                } else {
                    format!(
                        "path data must begin with a moveto command (M or m), found {}",
                        self.char_at(at)
                    )
                };
                return Err(self.err(at, reason));
            }
            self.pos += 1;
            match c {
                b'M' | b'm' | b'L' | b'l' | b'H' | b'h' | b'V' | b'v' | b'C' | b'c' | b'S'
                | b's' | b'Q' | b'q' | b'T' | b't' | b'A' | b'a' | b'Z' | b'z' => {}
                _ => {
                    return Err(self.err(at, format!("unknown command {:?}", c as char)));
                }
            }
            if !seen_move && !matches!(c, b'M' | b'm') {
                return Err(self.err(
                    at,
                    format!(
                        "drawing command {:?} before any moveto: path data must begin with M or m",
                        c as char
                    ),
                ));
            }
            seen_move = true;
            if matches!(c, b'Z' | b'z') {
                self.close(at)?;
                self.skip_wsp();
                continue;
            }
            let mut repeat = false;
            loop {
                let seg_at = self.pos;
                let vals = self.read_params(c, !repeat)?;
                self.apply(c, &vals, repeat, if repeat { seg_at } else { at })?;
                repeat = true;
                self.skip_wsp();
                if self.peek() == Some(b',') {
                    let comma = self.pos;
                    self.pos += 1;
                    self.skip_wsp();
                    if !self.peek().is_some_and(is_number_start) {
                        return Err(self.err(
                            comma,
                            format!(
                                "a comma must be followed by a number, found {}",
                                self.char_at(self.pos)
                            ),
                        ));
                    }
                }
                if !self.peek().is_some_and(is_number_start) {
                    break;
                }
            }
        }
        if self.out.is_empty() {
            return Err(CurveParseError::Empty {
                what: "the SVG path data (it has only moveto commands)".to_string(),
            });
        }
        Ok((self.out, self.approx))
    }
}

fn zero() -> Rational {
    Rational::from_integer(0.into())
}

/// Reads SVG path data (`M x y C ...`) exactly: one Bézier curve per drawing
/// segment (lines of degree 1, `Q`/`T` of degree 2, `C`/`S` of degree 3, a
/// closing line for `Z` when needed). Arcs `A`/`a` are *approximated* by
/// cubic pieces within a certified bound, and this function drops the report
/// of what was approximated: [`parse_svg_path_reported`] returns it.
///
/// # Examples
/// ```
/// use lncert::shape::parse_svg_path;
/// use lncert::scalar::parse_rational;
/// let c = parse_svg_path("M 0 0 C 1 2 3 4 5 6 S 7 8 9 10").unwrap();
/// assert_eq!(c.len(), 2);
/// // The S segment's first control point reflects (3, 4) about (5, 6).
/// assert_eq!(c[1].points()[1].x, parse_rational("7").unwrap());
///
/// let square = parse_svg_path("m 1 1 h 0.1 v 0.1 h -0.1 z").unwrap();
/// assert_eq!(square.len(), 4);
/// assert_eq!(square[0].points()[1].x, parse_rational("11/10").unwrap());
///
/// // a half circle: cubic pieces from (0, 0) to (2, 0), exactly
/// let arc = parse_svg_path("M 0 0 A 1 1 0 0 1 2 0").unwrap();
/// assert_eq!(arc[0].points()[0].x, parse_rational("0").unwrap());
/// assert_eq!(arc.last().unwrap().points()[3].x, parse_rational("2").unwrap());
/// ```
pub fn parse_svg_path(d: &str) -> Result<Vec<Bezier<Rational>>, CurveParseError> {
    parse_svg_path_reported(d).map(|(pieces, _)| pieces)
}

/// [`parse_svg_path`], with the list of the arcs it approximated (each named
/// by the byte offset of its command, with the certified Hausdorff bound of
/// its cubic pieces from the exact arc).
///
/// # Examples
/// ```
/// use lncert::shape::parse_svg_path_reported;
/// let (pieces, approx) =
///     parse_svg_path_reported("M 0 0 L 1 0 A 1 1 0 0 1 3 0 a 1 2 30 1 0 1 1").unwrap();
/// assert_eq!(approx.elements.len(), 2);
/// assert_eq!(approx.elements[0].at, "byte 12");
/// assert_eq!(1 + approx.pieces(), pieces.len());
/// assert!(approx.elements[0].bound <= 1e-7);
/// ```
pub fn parse_svg_path_reported(
    d: &str,
) -> Result<(Vec<Bezier<Rational>>, InputApprox), CurveParseError> {
    SvgParser::new(d).run()
}

/// Reads a list of numbers in SVG syntax (separated by whitespace and/or one
/// comma), each exactly: the arguments of an SVG `transform` function.
pub(crate) fn svg_number_list(text: &str) -> Result<Vec<Rational>, CurveParseError> {
    let mut p = SvgParser::new(text);
    let mut out = Vec::new();
    loop {
        p.skip_wsp();
        if !out.is_empty() && p.peek() == Some(b',') {
            p.pos += 1;
            p.skip_wsp();
        }
        if p.peek().is_none() {
            return Ok(out);
        }
        out.push(p.number()?);
    }
}

/// Reads a curve in any of its syntaxes: JSON when the text (after leading
/// whitespace) starts with `{`, an SVG document when it starts with `<`
/// ([`super::parse_svg_document`]), SVG path data otherwise. Elliptical arcs,
/// circles, ellipses and rounded rectangles of SVG input are approximated
/// within a certified bound, and this function drops the report of what was
/// approximated: [`parse_curve_reported`] returns it.
///
/// # Examples
/// ```
/// use lncert::shape::parse_curve;
/// let a = parse_curve(r#" {"bezier": [[0, 0], ["1/2", 1], [1, 0]]}"#).unwrap();
/// let b = parse_curve("M 0 0 Q 0.5 1 1 0").unwrap();
/// assert_eq!(a, b);
/// assert!(parse_curve("").is_err());
/// ```
pub fn parse_curve(text: &str) -> Result<Vec<Bezier<Rational>>, CurveParseError> {
    parse_curve_reported(text).map(|(pieces, _)| pieces)
}

/// [`parse_curve`], with the report of what was approximated (empty for JSON
/// curves and for SVG input without arcs, circles, ellipses or rounded
/// rectangles).
///
/// # Examples
/// ```
/// use lncert::shape::parse_curve_reported;
/// let doc = r#"<svg><circle cx="1" cy="1" r="2"/></svg>"#;
/// let (pieces, approx) = parse_curve_reported(doc).unwrap();
/// assert_eq!(approx.elements[0].at, "svg/circle[0]");
/// assert_eq!(approx.pieces(), pieces.len());
/// assert!(approx.bound() <= 2e-7);
/// ```
pub fn parse_curve_reported(
    text: &str,
) -> Result<(Vec<Bezier<Rational>>, InputApprox), CurveParseError> {
    let trimmed = text.trim();
    if trimmed.is_empty() {
        return Err(CurveParseError::Empty {
            what: "the input".to_string(),
        });
    }
    if trimmed.starts_with('{') {
        Ok((parse_json_curve(text)?, InputApprox::default()))
    } else if trimmed.starts_with('<') {
        super::svgdoc::parse_svg_document_reported(text)
    } else {
        parse_svg_path_reported(text)
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use proptest::prelude::*;

    fn q(s: &str) -> Rational {
        parse_rational(s).unwrap()
    }

    fn p(x: &str, y: &str) -> V2<Rational> {
        V2::new(q(x), q(y))
    }

    fn bz(pts: &[(&str, &str)]) -> Bezier<Rational> {
        Bezier::new(pts.iter().map(|(x, y)| p(x, y)).collect())
    }

    fn field_of(e: &CurveParseError) -> &str {
        match e {
            CurveParseError::Field { field, .. } => field,
            other => panic!("expected a Field error, got {other:?}"),
        }
    }

    fn position_of(e: &CurveParseError) -> usize {
        match e {
            CurveParseError::Svg { position, .. } => *position,
            other => panic!("expected an Svg error, got {other:?}"),
        }
    }

    #[test]
    fn json_numbers_are_exact() {
        let c = parse_json_curve(r#"{"bezier": [[0.1, "1/3"], [1e-3, "-2.5E+1"]]}"#).unwrap();
        assert_eq!(c, vec![bz(&[("1/10", "1/3"), ("1/1000", "-25")])]);
        // A float would not survive this.
        let c = parse_json_curve(r#"{"bezier": [[0.30000000000000000001, 0], [1, 1]]}"#).unwrap();
        assert_eq!(
            c[0].points()[0].x,
            q("30000000000000000001/100000000000000000000")
        );
    }

    #[test]
    fn seed_cubic() {
        let c = parse_json_curve(
            r#"{"bezier": [[-0.95, 0.7], [-0.3, 0.5], [0.3, -2.5], [0.9, -0.2]]}"#,
        )
        .unwrap();
        assert_eq!(
            c,
            vec![bz(&[
                ("-19/20", "7/10"),
                ("-3/10", "1/2"),
                ("3/10", "-5/2"),
                ("9/10", "-1/5")
            ])]
        );
        assert_eq!(c[0].degree(), 3);
        let s = parse_curve(
            r#"{"bezier": [["-0.95","0.7"], ["-0.3","0.5"], ["0.3","-2.5"], ["0.9","-0.2"]]}"#,
        )
        .unwrap();
        assert_eq!(s, c);
    }

    #[test]
    fn json_piecewise() {
        let c = parse_json_curve(r#"{"beziers": [[[0, 0], [1, 1]], [[1, 1], [2, 0], ["3", 1]]]}"#)
            .unwrap();
        assert_eq!(
            c,
            vec![
                bz(&[("0", "0"), ("1", "1")]),
                bz(&[("1", "1"), ("2", "0"), ("3", "1")])
            ]
        );
    }

    #[test]
    fn svg_cubic_and_smooth() {
        let c = parse_svg_path("M 0 0 C 1 2 3 4 5 6 S 7 8 9 10").unwrap();
        assert_eq!(
            c,
            vec![
                bz(&[("0", "0"), ("1", "2"), ("3", "4"), ("5", "6")]),
                bz(&[("5", "6"), ("7", "8"), ("7", "8"), ("9", "10")]),
            ]
        );
        // S without a preceding cubic: first control point = current point.
        let c = parse_svg_path("M 1 1 S 2 2 3 3").unwrap();
        assert_eq!(
            c,
            vec![bz(&[("1", "1"), ("1", "1"), ("2", "2"), ("3", "3")])]
        );
        // Relative c/s.
        let c = parse_svg_path("m 1 1 c 1 0 1 1 2 1 s 1 1 2 0").unwrap();
        assert_eq!(
            c,
            vec![
                bz(&[("1", "1"), ("2", "1"), ("2", "2"), ("3", "2")]),
                bz(&[("3", "2"), ("4", "2"), ("4", "3"), ("5", "2")]),
            ]
        );
    }

    #[test]
    fn svg_relative_and_close() {
        let c = parse_svg_path("m 1 1 l 2 0 v 3 h -1 z").unwrap();
        assert_eq!(
            c,
            vec![
                bz(&[("1", "1"), ("3", "1")]),
                bz(&[("3", "1"), ("3", "4")]),
                bz(&[("3", "4"), ("2", "4")]),
                bz(&[("2", "4"), ("1", "1")]),
            ]
        );
        // Z at the start point adds nothing; a command after Z starts from it.
        let c = parse_svg_path("M 0 0 L 1 0 L 0 0 Z l 0 1").unwrap();
        assert_eq!(
            c,
            vec![
                bz(&[("0", "0"), ("1", "0")]),
                bz(&[("1", "0"), ("0", "0")]),
                bz(&[("0", "0"), ("0", "1")]),
            ]
        );
        // Relative moveto after Z is relative to the subpath start.
        let c = parse_svg_path("M 1 1 L 2 2 z m 1 0 l 0 1").unwrap();
        assert_eq!(c[2], bz(&[("2", "1"), ("2", "2")]));
    }

    #[test]
    fn svg_number_syntax_and_implicit_commands() {
        let c = parse_svg_path("M0,0L10-5").unwrap();
        assert_eq!(c, vec![bz(&[("0", "0"), ("10", "-5")])]);
        let c = parse_svg_path("M.5.5L1.,-1.5e-3").unwrap();
        assert_eq!(c, vec![bz(&[("1/2", "1/2"), ("1", "-3/2000")])]);
        // M with extra pairs draws lines; m's extra pairs are relative.
        let c = parse_svg_path("M 0 0 1 0 1 1 m 1 1 1 0").unwrap();
        assert_eq!(
            c,
            vec![
                bz(&[("0", "0"), ("1", "0")]),
                bz(&[("1", "0"), ("1", "1")]),
                bz(&[("2", "2"), ("3", "2")]),
            ]
        );
        // Implicit repetition of L and C.
        let c = parse_svg_path("M 0 0 L 1 1, 2 0 C 0 0 0 0 1 1 2 2 2 2 3 3").unwrap();
        assert_eq!(c.len(), 4);
        assert_eq!(c[3], bz(&[("1", "1"), ("2", "2"), ("2", "2"), ("3", "3")]));
        let c = parse_svg_path("\n M 0 0\tL 0.1 0.2 \r\n").unwrap();
        assert_eq!(c, vec![bz(&[("0", "0"), ("1/10", "1/5")])]);
    }

    #[test]
    fn svg_quadratic_reflection() {
        let c = parse_svg_path("M 0 0 Q 1 1 2 0 T 4 0 T 6 0").unwrap();
        assert_eq!(
            c,
            vec![
                bz(&[("0", "0"), ("1", "1"), ("2", "0")]),
                bz(&[("2", "0"), ("3", "-1"), ("4", "0")]),
                bz(&[("4", "0"), ("5", "1"), ("6", "0")]),
            ]
        );
        // T after a non-quadratic: control point = current point.
        let c = parse_svg_path("M 0 0 L 1 0 t 1 1").unwrap();
        assert_eq!(c[1], bz(&[("1", "0"), ("1", "0"), ("2", "1")]));
        // S after a quadratic does not reflect the quadratic's control point.
        let c = parse_svg_path("M 0 0 Q 1 1 2 0 S 3 1 4 0").unwrap();
        assert_eq!(c[1], bz(&[("2", "0"), ("2", "0"), ("3", "1"), ("4", "0")]));
        // Relative q/t.
        let c = parse_svg_path("M 1 0 q 1 1 2 0 t 2 0").unwrap();
        assert_eq!(c[1], bz(&[("3", "0"), ("4", "-1"), ("5", "0")]));
    }

    #[test]
    fn parse_curve_dispatches() {
        assert_eq!(
            parse_curve("  {\"bezier\": [[0, 0], [1, 2]]}").unwrap(),
            parse_curve("M 0 0 L 1 2").unwrap()
        );
        assert!(matches!(
            parse_curve("  \n"),
            Err(CurveParseError::Empty { .. })
        ));
    }

    #[test]
    fn json_errors_name_the_field() {
        let e = parse_json_curve(r#"{"bezier": [[1, "abc"]]}"#).unwrap_err();
        assert_eq!(field_of(&e), "bezier[0][1]");
        assert!(e.to_string().contains("cannot read \"abc\""), "{e}");

        let e = parse_json_curve(r#"{"bezier": [[1, 2]]}"#).unwrap_err();
        assert_eq!(field_of(&e), "bezier");
        assert!(e.to_string().contains("at least 2 control points"), "{e}");

        let e = parse_json_curve(r#"{"bezier": "x"}"#).unwrap_err();
        assert_eq!(field_of(&e), "bezier");

        let e = parse_json_curve("not json {").unwrap_err();
        assert!(matches!(&e, CurveParseError::Json { message } if message.contains("line 1")));
        let e = parse_curve("not json {").unwrap_err();
        assert_eq!(position_of(&e), 0);

        let e = parse_json_curve(r#"{"bezier": [["NaN", 1], [0,0]]}"#).unwrap_err();
        assert_eq!(field_of(&e), "bezier[0][0]");
        assert!(e.to_string().contains("NaN is not a finite number"), "{e}");
        let e = parse_json_curve(r#"{"bezier": [[0, "-Infinity"], [0,0]]}"#).unwrap_err();
        assert_eq!(field_of(&e), "bezier[0][1]");
        assert!(e.to_string().contains("not a finite number"), "{e}");

        let e = parse_json_curve(r#"{"bezier": [[0, 0], [1, 2, 3]]}"#).unwrap_err();
        assert_eq!(field_of(&e), "bezier[1]");
        assert!(e.to_string().contains("expected [x, y]"), "{e}");
        let e = parse_json_curve(r#"{"bezier": [[0, 0], [null, 2]]}"#).unwrap_err();
        assert_eq!(field_of(&e), "bezier[1][0]");
        let e = parse_json_curve(r#"{"beziers": [[[0, 0], [1, 1]], [[0, "1/0"], [1, 1]]]}"#)
            .unwrap_err();
        assert_eq!(field_of(&e), "beziers[1][0][1]");
        let e = parse_json_curve(r#"{"bezier": [[0, "1e-99999999999999999999"], [1, 1]]}"#)
            .unwrap_err();
        assert_eq!(field_of(&e), "bezier[0][1]");
        let e =
            parse_json_curve(r#"{"bezier": [[0, 1e99999999999999999999], [1, 1]]}"#).unwrap_err();
        assert_eq!(field_of(&e), "bezier[0][1]");
        let e = parse_json_curve(r#"{"bezir": [[0, 0], [1, 1]]}"#).unwrap_err();
        assert_eq!(field_of(&e), "bezir");
        let e = parse_json_curve(r#"{}"#).unwrap_err();
        assert_eq!(field_of(&e), "bezier");
        let e = parse_json_curve(r#"[1, 2]"#).unwrap_err();
        assert_eq!(field_of(&e), "(top level)");
        let e = parse_json_curve(r#"{"beziers": []}"#).unwrap_err();
        assert!(matches!(e, CurveParseError::Empty { .. }));
    }

    #[test]
    fn json_limits() {
        let pts = vec!["[0, 0]"; MAX_CONTROL_POINTS + 1].join(",");
        let e = parse_json_curve(&format!("{{\"bezier\": [{pts}]}}")).unwrap_err();
        assert!(
            matches!(&e, CurveParseError::TooLarge { what, limit: 64 } if what.contains("`bezier`")),
            "{e:?}"
        );
        let pts = vec!["[0, 0]"; MAX_CONTROL_POINTS].join(",");
        assert_eq!(
            parse_json_curve(&format!("{{\"bezier\": [{pts}]}}")).unwrap()[0].degree(),
            63
        );
        let segs = vec!["0"; MAX_SEGMENTS + 1].join(",");
        let e = parse_json_curve(&format!("{{\"beziers\": [{segs}]}}")).unwrap_err();
        assert!(matches!(
            e,
            CurveParseError::TooLarge {
                limit: MAX_SEGMENTS,
                ..
            }
        ));
        let long = "1".repeat(MAX_NUMBER_CHARS + 1);
        let e = parse_json_curve(&format!("{{\"bezier\": [[{long}, 0], [1, 1]]}}")).unwrap_err();
        assert_eq!(field_of(&e), "bezier[0][0]");
    }

    #[test]
    fn svg_errors_name_the_position() {
        // an arc's parameters are checked where its command stands
        let e = parse_svg_path("M 0 0 A 1e101 1 0 0 1 2 2").unwrap_err();
        assert_eq!(position_of(&e), 6);
        assert!(e.to_string().contains("limit"), "{e}");
        let e = parse_svg_path("M 0 0 A 1 1 0 0 1 2 2 2 2 0 0 7 3 3").unwrap_err();
        assert_eq!(position_of(&e), 30);
        assert!(e.to_string().contains("sweep-flag"), "{e}");

        let e = parse_svg_path("L 1 1").unwrap_err();
        assert_eq!(position_of(&e), 0);
        assert!(e.to_string().contains("before any moveto"), "{e}");

        let e = parse_svg_path("M 1").unwrap_err();
        assert_eq!(position_of(&e), 3);
        assert!(e.to_string().contains("missing parameter"), "{e}");

        let e = parse_svg_path("M 0 0 L 1 1 X 2").unwrap_err();
        assert_eq!(position_of(&e), 12);
        assert!(e.to_string().contains("unknown command"), "{e}");

        let e = parse_svg_path("M 0 0 C 1 1 2 2 L 3 3").unwrap_err();
        assert_eq!(position_of(&e), 16);

        let e = parse_svg_path("M 0 0 Z 1 1").unwrap_err();
        assert_eq!(position_of(&e), 8);

        let e = parse_svg_path("M 0 0 L 1 1,").unwrap_err();
        assert_eq!(position_of(&e), 11);

        let e = parse_svg_path("M 0 0 L 1e99999999999999999999 1").unwrap_err();
        assert_eq!(position_of(&e), 8);

        let e = parse_svg_path("M 0 0 L 1 é").unwrap_err();
        assert_eq!(position_of(&e), 10);

        let e = parse_svg_path("M 0 0 L - 1").unwrap_err();
        assert_eq!(position_of(&e), 8);

        assert!(matches!(
            parse_svg_path("M 1 1 m 2 2"),
            Err(CurveParseError::Empty { .. })
        ));
        assert!(matches!(
            parse_svg_path(""),
            Err(CurveParseError::Empty { .. })
        ));
        let big = "M 0 0".to_string() + &" ".repeat(MAX_SVG_BYTES);
        assert!(matches!(
            parse_svg_path(&big),
            Err(CurveParseError::TooLarge {
                limit: MAX_SVG_BYTES,
                ..
            })
        ));
        let many = "M0 0".to_string() + &"h1".repeat(MAX_SEGMENTS + 1);
        assert!(matches!(
            parse_svg_path(&many),
            Err(CurveParseError::TooLarge {
                limit: MAX_SEGMENTS,
                ..
            })
        ));
    }

    proptest! {
        #![proptest_config(ProptestConfig::with_cases(512))]

        #[test]
        fn never_panics_on_any_text(s in ".*") {
            let _ = parse_json_curve(&s);
            let _ = parse_svg_path(&s);
            let _ = parse_curve(&s);
        }

        #[test]
        fn never_panics_on_pathish_text(s in "[MLCQSTZHVmlcqsthvz0-9., eE+-]{0,64}") {
            let _ = parse_json_curve(&s);
            let _ = parse_svg_path(&s);
            let _ = parse_curve(&s);
        }

        #[test]
        fn never_panics_on_jsonish_text(s in r#"\{"beziers?": [\[\]0-9., eE+"/NaI-]{0,64}\}?"#) {
            let _ = parse_json_curve(&s);
            let _ = parse_curve(&s);
        }
    }
}
