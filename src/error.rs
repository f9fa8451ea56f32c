//! The one input error of lncert: which field, and why.
//!
//! The engines that only ever refuse an input (shapes, Hausdorff bounds,
//! offsets, strokes, tangency) return [`Error`] itself (their error names —
//! `ShapeError`, `CertifyError`, `OffsetError`, `StrokeError`, `TangencyError`
//! — are aliases of it); the readers and kernels whose errors carry more
//! (positions, kinds, limits) keep their own enums, and every one of them
//! converts into [`Error`], so `?` works across all engines.

use crate::{certify, json, ln, scalar, shape, tangency};

/// The one input error of lncert: which field of the input, and why.
///
/// Every error of the engine converts into it (`?` works across all
/// engines); the readers' and kernels' own error enums keep their variants for
/// callers who match on them.
///
/// # Examples
/// ```
/// use lncert::ShapeDesc;
/// let e = ShapeDesc::parse(r#"{"arc": {"center": [0, 0], "radius": 0, "from": [1, 0], "to": [0, 1]}}"#)
///     .unwrap_err();
/// assert_eq!((e.field.as_str(), e.reason.as_str()), ("arc.radius", "must be > 0"));
/// assert_eq!(e.to_string(), "invalid `arc.radius`: must be > 0");
/// ```
#[derive(Clone, Debug, PartialEq, Eq, thiserror::Error)]
#[error("invalid `{field}`: {reason}")]
pub struct Error {
    /// The field, e.g. `arc.radius`, `bezier[2][1]`, `tol`, `directions[0].boxes[3]`.
    pub field: String,
    /// What is wrong with it.
    pub reason: String,
}

impl Error {
    /// An error of `field` for `reason`.
    pub fn new(field: impl Into<String>, reason: impl Into<String>) -> Self {
        Error {
            field: field.into(),
            reason: reason.into(),
        }
    }
}

impl From<ln::LnError> for Error {
    fn from(e: ln::LnError) -> Self {
        let field = match &e {
            ln::LnError::Collinear { field }
            | ln::LnError::InvalidParameter { field, .. }
            | ln::LnError::NotCompatible { field, .. }
            | ln::LnError::Undecided { field } => *field,
        };
        let text = e.to_string();
        let reason = text
            .strip_prefix(&format!("{field}: "))
            .unwrap_or(&text)
            .to_string();
        Error::new(field, reason)
    }
}

impl From<shape::io::CurveParseError> for Error {
    fn from(e: shape::io::CurveParseError) -> Self {
        use shape::io::CurveParseError as C;
        match e {
            C::Json { message } => Error::new("(document)", format!("malformed JSON: {message}")),
            C::Field { field, reason } => Error::new(field, reason),
            C::Svg { position, reason } => {
                Error::new(format!("SVG path data, byte {position}"), reason)
            }
            C::Empty { what } => Error::new(what, "no curve segments"),
            C::TooLarge { what, limit } => {
                Error::new(what, format!("too large: exceeds the limit of {limit}"))
            }
        }
    }
}

impl From<scalar::ParseNumberError> for Error {
    fn from(e: scalar::ParseNumberError) -> Self {
        Error::new(format!("{:?}", e.input), e.reason)
    }
}

impl From<certify::verify::Invalid> for Error {
    fn from(e: certify::verify::Invalid) -> Self {
        Error::new(e.at, e.reason)
    }
}

impl From<json::JsonError> for Error {
    fn from(e: json::JsonError) -> Self {
        Error::new(
            e.path,
            format!("{} (line {}, column {})", e.reason, e.line, e.column),
        )
    }
}

impl From<tangency::raster::RasterError> for Error {
    fn from(e: tangency::raster::RasterError) -> Self {
        use tangency::raster::RasterError as R;
        match e {
            R::InvalidGrid { field, reason } => Error::new(format!("grid.{field}"), reason),
            R::InvalidPoly { field, reason } => Error::new(field, reason),
            R::NoAdapter(reason) => Error::new("backend", format!("no GPU adapter: {reason}")),
            R::Gpu(reason) => Error::new("backend", format!("GPU error: {reason}")),
        }
    }
}

impl From<tangency::poly2::Poly2ParseError> for Error {
    fn from(e: tangency::poly2::Poly2ParseError) -> Self {
        let text = e.to_string();
        let reason = text.strip_prefix("expression: ").unwrap_or(&text);
        Error::new("expression", reason)
    }
}
