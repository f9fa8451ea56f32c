//! The pens of `lncert stroke --pen circle:R|ellipse:A,B[,θ]` and `lncert
//! convolve --ellipse A,B [--angle θ]`: exact semi-axes and angles, the
//! rotation represented exactly rationally within a proven angle.

use super::args::{bad, number};
use super::CliError;
use lncert::offset::{Angle, Pen};
use lncert::scalar::{Rational, Scalar};
use lncert::stroke::PenShape;

/// `stroke --pen`: `circle:R` or `ellipse:A,B[,θ]`.
pub fn pen_shape(text: &str, tol: f64) -> Result<PenShape, CliError> {
    if let Some(r) = text.strip_prefix("circle:") {
        let r = number("--pen", r)?;
        if r <= Rational::from_integer(0.into()) {
            return Err(bad("--pen", "the radius must be > 0"));
        }
        return Ok(PenShape::Circle(r));
    }
    if let Some(spec) = text.strip_prefix("ellipse:") {
        let pen = parse_ellipse_spec("--pen", spec, tol)?;
        return Ok(PenShape::Ellipse(pen));
    }
    Err(bad(
        "--pen",
        format!("expected circle:R or ellipse:A,B[,θ], got {text:?}"),
    ))
}

/// The pen with semi-axes `A ≥ B > 0` and rotation `angle`, its rotation
/// represented within `min(1e-6, tol/1000 / (A + A²/B))` radians; errors name
/// `flag`. Shared by `lncert convolve --ellipse` and `lncert stroke --pen ellipse:`.
pub fn ellipse_pen(
    flag: &str,
    a: &Rational,
    b: &Rational,
    angle: &Angle,
    tol: f64,
) -> Result<Pen, CliError> {
    let (af, bf) = (a.approx(), b.approx());
    let reach = af + af * af / bf;
    let max_angle = (tol * 1e-3 / reach).clamp(1e-12, 1e-6);
    let max_angle = if max_angle.is_finite() {
        max_angle
    } else {
        1e-12
    };
    Pen::ellipse_within(a, b, angle, max_angle)
        .map_err(|e| bad(flag, format!("{}: {}", e.field, e.reason)))
}

/// `A,B` or `A,B,θ` (the angle as `lncert convolve --angle` reads it) for
/// `lncert stroke --pen ellipse:…`; errors name `flag` and the field.
pub fn parse_ellipse_spec(flag: &str, spec: &str, tol: f64) -> Result<Pen, CliError> {
    let parts: Vec<&str> = spec.split(',').map(str::trim).collect();
    if parts.len() != 2 && parts.len() != 3 {
        return Err(bad(
            flag,
            format!("expected ellipse:A,B or ellipse:A,B,θ (semi-axes A ≥ B > 0), got {spec:?}"),
        ));
    }
    let a = number(&format!("{flag} (semi-axis A)"), parts[0])?;
    let b = number(&format!("{flag} (semi-axis B)"), parts[1])?;
    let angle = match parts.get(2) {
        Some(t) => Angle::parse(t).map_err(|e| {
            bad(
                &format!("{flag} (angle θ)"),
                format!("{}: {}", e.field, e.reason),
            )
        })?,
        None => Angle::Radians(Rational::from_integer(0.into())),
    };
    ellipse_pen(flag, &a, &b, &angle, tol)
}
