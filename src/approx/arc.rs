//! Offsets of circular arcs: exact (seed 004 §3.1, circular precision).
//!
//! For an arc `x(t) = c + γ (cos(t₀ + l t), sin(t₀ + l t))` seed 004's
//! construction gives `α ≡ 1/γ`, hence `Nᵃ ≡ N` and the approximant *is* the
//! exact offset. lncert proves this identity once for all arcs, symbolically,
//! by running the engine's own [`super::g2::solve_alpha`] on the arc's moments
//! in `Q(γ, 1/l, tan(l/2), tan(t₀/2))` (`tests/offset_identities.rs`,
//! `proofs/004-circular-precision.md`). So the offset of an arc is returned as
//! the exact concentric arc, with error `0`.

use super::{bad, OffsetError};
use crate::certify::ArcDesc;
use crate::curve::V2;
use crate::scalar::Rational;
use num_traits::{Signed, Zero};
use serde_json::Value;

/// An arc as travelled: `arc` is stored counter-clockwise (as
/// [`crate::certify::ShapeDesc`] does); `clockwise` says the travel direction,
/// which decides the side of the left normal.
#[derive(Clone, Debug, PartialEq)]
pub struct TravelledArc {
    /// The arc, stored counter-clockwise.
    pub arc: ArcDesc,
    /// True when the arc is travelled clockwise (from `arc.to` to `arc.from`).
    pub clockwise: bool,
}

/// The exact offset of an arc.
#[derive(Clone, Debug, PartialEq)]
pub enum ArcOffset {
    /// The concentric arc of radius `|γ ∓ d|` (directions negated when the
    /// offset passes through the centre).
    Arc(TravelledArc),
    /// `d` equals the radius on the concave side: the offset collapses to the
    /// centre (every point is a cusp of the offset).
    Collapsed {
        /// The arc's centre: the whole offset is this one point.
        center: V2<Rational>,
    },
}

/// The exact offset at signed distance `d` (`d > 0` to the left of the travel
/// direction) of an arc.
///
/// # Examples
/// ```
/// use lncert::approx::arc::{offset_arc, ArcOffset, TravelledArc};
/// use lncert::certify::ArcDesc;
/// use lncert::curve::V2;
/// use lncert::scalar::{frac, Rational};
/// let q = |p, r| frac::<Rational>(p, r);
/// let quarter = ArcDesc { center: V2::new(q(0, 1), q(0, 1)), radius: q(1, 1),
///                         from: V2::new(q(1, 1), q(0, 1)), to: V2::new(q(0, 1), q(1, 1)) };
/// // counter-clockwise: the left normal points to the centre, radius 1 − 1/2
/// let o = offset_arc(&TravelledArc { arc: quarter, clockwise: false }, &q(1, 2)).unwrap();
/// let ArcOffset::Arc(a) = o else { panic!() };
/// assert_eq!(a.arc.radius, q(1, 2));
/// ```
pub fn offset_arc(a: &TravelledArc, d: &Rational) -> Result<ArcOffset, OffsetError> {
    if d.is_zero() {
        return Err(bad("distance", "must be nonzero"));
    }
    // left normal: inward for counter-clockwise travel, outward for clockwise
    let rho = if a.clockwise {
        &a.arc.radius + d
    } else {
        &a.arc.radius - d
    };
    if rho.is_zero() {
        return Ok(ArcOffset::Collapsed {
            center: a.arc.center.clone(),
        });
    }
    let mut arc = a.arc.clone();
    if rho.is_negative() {
        arc.radius = -rho;
        arc.from = arc.from.neg();
        arc.to = arc.to.neg();
    } else {
        arc.radius = rho;
    }
    Ok(ArcOffset::Arc(TravelledArc {
        arc,
        clockwise: a.clockwise,
    }))
}

/// Reads `{"arc": {...}}` (the [`crate::certify::ShapeDesc`] syntax, with
/// `"clockwise"`) or `{"circle": {"center": [x, y], "radius": r}}` (a full
/// counter-clockwise circle, returned as four quarter arcs). `None` when the
/// document is neither (e.g. a curve).
pub fn parse_arc_input(text: &str) -> Option<Result<Vec<TravelledArc>, OffsetError>> {
    // the bounded, duplicate-refusing reader; a document it refuses is left to
    // the curve reader, which refuses it with the same message
    let doc: Value = crate::json::parse(text, &crate::json::Limits::DEFAULT)
        .ok()?
        .to_value();
    let map = doc.as_object()?;
    if map.contains_key("arc") {
        let clockwise = map["arc"]
            .get("clockwise")
            .and_then(Value::as_bool)
            .unwrap_or(false);
        return Some(match crate::certify::ShapeDesc::from_value(&doc) {
            Ok(crate::certify::ShapeDesc::Arc(arc)) => Ok(vec![TravelledArc { arc, clockwise }]),
            Ok(_) => Err(bad("arc", "not an arc")),
            Err(e) => Err(bad("curve", e.to_string())),
        });
    }
    let c = map.get("circle")?;
    Some(parse_circle(c, map.len()))
}

fn parse_circle(c: &Value, keys: usize) -> Result<Vec<TravelledArc>, OffsetError> {
    if keys != 1 {
        return Err(bad(
            "(top level)",
            "a circle document has the single key \"circle\"",
        ));
    }
    let Some(m) = c.as_object() else {
        return Err(bad(
            "circle",
            "expected {\"center\": [x, y], \"radius\": r}",
        ));
    };
    if let Some(k) = m.keys().find(|k| *k != "center" && *k != "radius") {
        return Err(bad(
            format!("circle.{k}"),
            "unknown field; expected center, radius",
        ));
    }
    let num = |v: Option<&Value>, f: &str| -> Result<Rational, OffsetError> {
        let v = v.ok_or_else(|| bad(f, "missing"))?;
        crate::curve::io::json_coordinate(v, f).map_err(|e| bad(f, e.to_string()))
    };
    let center = match m.get("center").and_then(Value::as_array) {
        Some(p) if p.len() == 2 => V2::new(
            num(p.first(), "circle.center[0]")?,
            num(p.get(1), "circle.center[1]")?,
        ),
        _ => return Err(bad("circle.center", "expected [x, y]")),
    };
    let radius = num(m.get("radius"), "circle.radius")?;
    let one = Rational::from_integer(1.into());
    let zero = Rational::zero();
    let dirs = [
        V2::new(one.clone(), zero.clone()),
        V2::new(zero.clone(), one.clone()),
        V2::new(-one.clone(), zero.clone()),
        V2::new(zero.clone(), -one),
    ];
    (0..4)
        .map(|i| {
            let arc = ArcDesc {
                center: center.clone(),
                radius: radius.clone(),
                from: dirs[i].clone(),
                to: dirs[(i + 1) % 4].clone(),
            };
            match crate::certify::ShapeDesc::arc(arc) {
                Ok(crate::certify::ShapeDesc::Arc(arc)) => Ok(TravelledArc {
                    arc,
                    clockwise: false,
                }),
                Ok(_) => Err(bad("circle", "not an arc")),
                Err(e) => Err(bad("circle", e.to_string().replace("arc.", "circle."))),
            }
        })
        .collect()
}
