//! Exact parsing of command-line values. Every number goes through
//! [`parse_rational`] (never through `f64`), and every error names the flag.
//!
//! | syntax | example | parser |
//! |---|---|---|
//! | number | `0.95`, `-1/3`, `2.5e-1` | [`number`] |
//! | tolerance `--tol` | `1e-3` (exactly 1/1000) | [`tolerance`] |
//! | point `x,y` | `2.5,-1` | [`point`] |
//! | frame `b0x,b0y;bmx,bmy;b3x,b3y` | `0,0;1,1;2,0` | [`frame`] |
//! | power coefficients `c0,c1,...` | `0,0,-1,1` | [`coefficients`] |
//! | cusp parameter τ | `-1`, `3/2`, `inf` | [`tau`] |

use super::CliError;
use lncert::curve::V2;
use lncert::ln::cubic::{LnFrame, Tau};
use lncert::ln::LnError;
use lncert::offset::OffsetError;
use lncert::poly::Poly;
use lncert::scalar::{parse_rational, Rational};
use lncert::Tolerance;

/// A bad-input error `--flag: reason`.
pub fn bad(flag: &str, reason: impl std::fmt::Display) -> CliError {
    CliError {
        field: flag.to_string(),
        reason: reason.to_string(),
    }
}

/// Checks, before any work, that `path` can be written as an output file:
/// not a directory, its parent directory exists, and the file can be opened
/// for writing (created and removed again if it did not exist). A run that
/// would otherwise fail at the end, losing its results, fails at once.
pub fn output_file(flag: &str, path: &std::path::Path) -> Result<(), CliError> {
    let shown = path.display();
    if path.as_os_str().is_empty() {
        return Err(bad(flag, "empty path"));
    }
    if path.is_dir() {
        return Err(bad(flag, format!("{shown} is a directory, not a file")));
    }
    if let Some(parent) = path.parent().filter(|p| !p.as_os_str().is_empty()) {
        if !parent.is_dir() {
            return Err(bad(
                flag,
                format!(
                    "cannot write {shown}: the directory {} does not exist",
                    parent.display()
                ),
            ));
        }
    }
    let existed = path.exists();
    std::fs::OpenOptions::new()
        .append(true)
        .create(true)
        .open(path)
        .map_err(|e| bad(flag, format!("cannot write {shown}: {e}")))?;
    if !existed {
        let _ = std::fs::remove_file(path);
    }
    Ok(())
}

/// Checks, before any work, that `dir` is or can become an output directory
/// (created now if missing, as the output would).
pub fn output_dir(flag: &str, dir: &std::path::Path) -> Result<(), CliError> {
    std::fs::create_dir_all(dir).map_err(|e| {
        bad(
            flag,
            format!("cannot create the directory {}: {e}", dir.display()),
        )
    })?;
    let probe = dir.join(format!(".lncert-write-test-{}", std::process::id()));
    std::fs::write(&probe, b"")
        .map_err(|e| bad(flag, format!("cannot write into {}: {e}", dir.display())))?;
    let _ = std::fs::remove_file(probe);
    Ok(())
}

/// An [`LnError`] reported against the command-line flag that produced it.
/// The library's own field name is kept in parentheses when it adds information.
pub fn ln_error(flag: &str, e: LnError) -> CliError {
    let (field, reason) = match &e {
        LnError::Collinear { field } => (
            *field,
            "points b0, bm, b3 are collinear or coincide (cross product is 0)".to_string(),
        ),
        LnError::InvalidParameter { field, reason } => (*field, reason.to_string()),
        LnError::NotCompatible { field, reason } => {
            (*field, format!("curves are not compatible: {reason}"))
        }
        LnError::Undecided { field } => (
            *field,
            "undecided in interval arithmetic (enclosure straddles a boundary)".to_string(),
        ),
    };
    if flag.trim_start_matches('-') == field || matches!(e, LnError::Collinear { .. }) {
        bad(flag, reason)
    } else {
        bad(flag, format!("{reason} ({field})"))
    }
}

/// An [`LnError`] whose library field is itself a flag name (`x1`, `u`, `tau`, ...).
pub fn ln_error_own_field(e: LnError) -> CliError {
    let field = match &e {
        LnError::Collinear { field }
        | LnError::InvalidParameter { field, .. }
        | LnError::NotCompatible { field, .. }
        | LnError::Undecided { field } => *field,
    };
    ln_error(&format!("--{field}"), e)
}

/// The value of a required flag, or an error naming it.
pub fn required<'a>(
    flag: &str,
    value: &'a Option<String>,
    usage: &str,
) -> Result<&'a str, CliError> {
    value
        .as_deref()
        .ok_or_else(|| bad(flag, format!("missing; usage: {usage}")))
}

/// An exact rational: `0.95` is `19/20`, `1/3` is `1/3`.
///
/// Every number is bounded like every coordinate of every input (shapes,
/// curves, certificates): `|x| ≤ 10¹⁰⁰`, decided exactly.
pub fn number(flag: &str, text: &str) -> Result<Rational, CliError> {
    let r = parse_rational(text).map_err(|e| bad(flag, e))?;
    if !lncert::scalar::abs_le_pow10(&r, 100) {
        return Err(bad(
            flag,
            "magnitude above the limit 1e100 (the one limit of every lncert input)",
        ));
    }
    Ok(r)
}

/// `--tol T`: the tolerance, exactly as written (`1e-3` is 1/1000), parsed
/// once and given both to the engine's options and to the certificates.
pub fn tolerance(text: &str) -> Result<Tolerance, CliError> {
    Tolerance::new(number("--tol", text)?).map_err(|e| bad("--tol", e.reason))
}

/// A required exact number.
pub fn required_number(
    flag: &str,
    value: &Option<String>,
    usage: &str,
) -> Result<Rational, CliError> {
    number(flag, required(flag, value, usage)?)
}

/// An optional exact number.
pub fn optional_number(flag: &str, value: &Option<String>) -> Result<Option<Rational>, CliError> {
    value.as_deref().map(|t| number(flag, t)).transpose()
}

/// A point `x,y`.
pub fn point(flag: &str, text: &str) -> Result<V2<Rational>, CliError> {
    let parts: Vec<&str> = text.split(',').collect();
    if parts.len() != 2 {
        return Err(bad(flag, format!("expected a point `x,y`, got {text:?}")));
    }
    Ok(V2::new(number(flag, parts[0])?, number(flag, parts[1])?))
}

/// A frame `b0x,b0y;bmx,bmy;b3x,b3y`, checked non-collinear.
pub fn frame(flag: &str, text: &str) -> Result<LnFrame<Rational>, CliError> {
    let parts: Vec<&str> = text.split(';').collect();
    if parts.len() != 3 {
        return Err(bad(
            flag,
            format!("expected three points `b0x,b0y;bmx,bmy;b3x,b3y`, got {text:?}"),
        ));
    }
    let names = ["b0", "bm", "b3"];
    let mut pts = Vec::with_capacity(3);
    for (p, name) in parts.iter().zip(names) {
        pts.push(point(&format!("{flag} ({name})"), p)?);
    }
    let b3 = pts.pop().expect("three points");
    let bm = pts.pop().expect("three points");
    let b0 = pts.pop().expect("three points");
    LnFrame::new(b0, bm, b3).map_err(|e| ln_error(flag, e))
}

/// Power-basis coefficients `c0,c1,c2,...` (constant term first).
pub fn coefficients(flag: &str, text: &str) -> Result<Poly<Rational>, CliError> {
    let cs = text
        .split(',')
        .map(|c| number(flag, c))
        .collect::<Result<Vec<_>, _>>()?;
    Ok(Poly::new(cs))
}

/// A cusp parameter: an exact number, or `inf` / `infinity` / `∞` (with an
/// optional sign: τ = ±∞ is the same projective point).
pub fn tau(flag: &str, text: &str) -> Result<Tau<Rational>, CliError> {
    let t = text.trim().to_ascii_lowercase();
    let unsigned = t.trim_start_matches(['+', '-']);
    if matches!(unsigned, "inf" | "infinity" | "∞") {
        return Ok(Tau::Infinite);
    }
    Ok(Tau::Finite(number(flag, text)?))
}

/// Rejects flags that the chosen proposition does not read, so that nothing
/// is silently ignored. `given` pairs each flag with whether it was set.
pub fn reject_unused(
    id: &str,
    usage: &str,
    allowed: &[&str],
    given: &[(&str, bool)],
) -> Result<(), CliError> {
    for (flag, set) in given {
        if *set && !allowed.contains(flag) {
            return Err(bad(flag, format!("not used by prop {id}; usage: {usage}")));
        }
    }
    Ok(())
}

/// `"p/q"` (or `"p"`), the exact output format.
pub fn q(r: &Rational) -> String {
    r.to_string()
}

/// `"(x, y)"` with exact coordinates.
pub fn show_point(p: &V2<Rational>) -> String {
    format!("({}, {})", q(&p.x), q(&p.y))
}

/// `["x", "y"]` with exact coordinates.
pub fn point_json(p: &V2<Rational>) -> serde_json::Value {
    serde_json::json!([q(&p.x), q(&p.y)])
}

/// The exact square root of `r ≥ 0` when it is rational.
fn rational_sqrt(r: &Rational) -> Option<Rational> {
    use num_traits::Signed;
    if r.is_negative() {
        return None;
    }
    let (n, d) = (r.numer(), r.denom());
    let (sn, sd) = (n.sqrt(), d.sqrt());
    (&sn * &sn == *n && &sd * &sd == *d).then(|| Rational::new(sn, sd))
}

/// The one JSON form of an arc in every output (`stroke` outlines,
/// `offset`'s join arcs and exact arc offsets), the shape language's
/// `{"arc": {"center", "radius", "from", "to", "clockwise"}}` (what
/// `hausdorff` and `verify --against` read): the arc is travelled from `from`
/// to `to`, clockwise when `clockwise` is true. `from` and `to` are vectors
/// from the centre: the radius vectors (`center + from` is the exact start
/// point) whenever the points are rational — always in stroke outlines —
/// and otherwise a direction of the same ray (its length irrational times
/// the radius), as given.
pub fn arc_json(
    center: &V2<Rational>,
    radius: &Rational,
    from: &V2<Rational>,
    to: &V2<Rational>,
    clockwise: bool,
) -> serde_json::Value {
    let radial = |v: &V2<Rational>| -> V2<Rational> {
        match rational_sqrt(&v.norm2()) {
            Some(len) if len != Rational::from_integer(0.into()) => v.scale(&(radius / len)),
            _ => v.clone(),
        }
    };
    serde_json::json!({"arc": {
        "center": point_json(center),
        "radius": q(radius),
        "from": point_json(&radial(from)),
        "to": point_json(&radial(to)),
        "clockwise": clockwise,
    }})
}

/// A frame as the exact string `b0x,b0y;bmx,bmy;b3x,b3y`.
pub fn show_frame(f: &LnFrame<Rational>) -> String {
    let p = |v: &V2<Rational>| format!("{},{}", q(&v.x), q(&v.y));
    format!("{};{};{}", p(&f.b0), p(&f.bm), p(&f.b3))
}

/// A τ as text (`"inf"` for ∞).
pub fn show_tau(t: &Tau<Rational>) -> String {
    match t {
        Tau::Finite(x) => q(x),
        Tau::Infinite => "inf".to_string(),
    }
}

/// An [`OffsetError`] of the engine's offset, convolution or arc reading,
/// reported against the flag it comes from (`CURVE: …` for a field of the input).
pub fn offset_err(e: OffsetError) -> CliError {
    let OffsetError { field, reason } = e;
    let flag = match field.as_str() {
        "distance" | "tol" | "side" | "method" | "max_depth" | "max_segments" | "grid" => {
            format!("--{}", field.replace('_', "-"))
        }
        f => format!("CURVE: {f}"),
    };
    bad(&flag, reason)
}

/// `--grid G` of `offset` and `convolve`: an exact number `> 0`.
pub fn grid(text: Option<&str>) -> Result<Option<Rational>, CliError> {
    let Some(text) = text else {
        return Ok(None);
    };
    let g = number("--grid", text)?;
    if g <= Rational::from_integer(0.into()) {
        return Err(bad("--grid", format!("{text} must be > 0")));
    }
    Ok(Some(g))
}

/// The line saying how the tolerance is split between the fit and the rounding.
pub fn grid_line(grid: &Option<Rational>, tol: f64) -> Option<String> {
    grid.as_ref().map(|g| {
        let mv = lncert::offset::kernels::rounding_move(g);
        format!(
            "grid {g}: control points rounded to multiples of {g}; the tolerance is split as fit ≤ {:.6e} (sampled pre-check) + rounding ≤ {mv:.6e} (grid·√2/2); the rounded curve is what is proven",
            tol - mv
        )
    })
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn numbers_are_exact_and_errors_name_the_flag() {
        assert_eq!(q(&number("--u", "0.95").unwrap()), "19/20");
        let e = number("--x1", "abc").unwrap_err();
        assert!(
            e.to_string().starts_with("--x1: cannot read \"abc\""),
            "{e}"
        );
    }

    #[test]
    fn frames_points_and_tau() {
        let f = frame("--frame", "0,0;1,1;2,0").unwrap();
        assert_eq!(show_point(&f.bm), "(1, 1)");
        assert!(frame("--frame", "0,0;1,1;2,2")
            .unwrap_err()
            .to_string()
            .contains("collinear"));
        assert!(frame("--frame", "0,0;1,1").is_err());
        assert!(point("--b0", "1").is_err());
        assert_eq!(tau("--tau", "-inf").unwrap(), Tau::Infinite);
        assert_eq!(show_tau(&tau("--tau", "-3/2").unwrap()), "-3/2");
    }
}
