//! The error of curve construction and reading (shared with the readers of
//! [`crate::shape`]).

/// Why a curve could not be read; always says where and why.
///
/// # Examples
/// ```
/// use lncert::shape::{parse_json_curve, CurveParseError};
/// let err = parse_json_curve(r#"{"bezier": [[1, "abc"], [0, 0]]}"#).unwrap_err();
/// assert!(matches!(&err, CurveParseError::Field { field, .. } if field == "bezier[0][1]"));
/// assert!(err.to_string().contains("abc"));
/// ```
#[derive(Clone, Debug, PartialEq, thiserror::Error)]
pub enum CurveParseError {
    /// The text is not well-formed JSON.
    #[error("malformed JSON: {message}")]
    Json {
        /// serde_json's description, with line and column.
        message: String,
    },
    /// A JSON field has the wrong shape or an unreadable number.
    #[error("invalid field `{field}`: {reason}")]
    Field {
        /// Path of the field, e.g. `bezier[2][1]`.
        field: String,
        /// What is wrong with it.
        reason: String,
    },
    /// The SVG path data is malformed or unsupported at a byte offset.
    #[error("SVG path data, at byte {position}: {reason}")]
    Svg {
        /// Byte offset in the path data.
        position: usize,
        /// What is wrong there.
        reason: String,
    },
    /// Nothing to read.
    #[error("no curve segments in {what}")]
    Empty {
        /// What is empty.
        what: String,
    },
    /// Input over one of the limits.
    #[error("too large: {what} exceeds the limit of {limit}")]
    TooLarge {
        /// What is too large.
        what: String,
        /// The limit.
        limit: usize,
    },
}

pub(crate) fn field_err(field: &str, reason: impl Into<String>) -> CurveParseError {
    CurveParseError::Field {
        field: field.to_string(),
        reason: reason.into(),
    }
}
