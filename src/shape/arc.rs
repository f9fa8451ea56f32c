//! Arcs as travelled, and the arc and circle documents that `offset` reads.

use super::desc::{checked_arc, err, ArcDesc, ShapeDesc};
use super::io::json_coordinate;
use super::ShapeError;
use crate::curve::V2;
use crate::scalar::Rational;
use num_traits::Zero;
use serde_json::Value;

/// An arc as travelled: `arc` is stored counter-clockwise (as
/// [`ShapeDesc`] does); `clockwise` says the travel direction,
/// which decides the side of the left normal.
#[derive(Clone, Debug, PartialEq)]
pub struct TravelledArc {
    /// The arc, stored counter-clockwise.
    pub arc: ArcDesc,
    /// True when the arc is travelled clockwise (from `arc.to` to `arc.from`).
    pub clockwise: bool,
}

/// Reads `{"arc": {...}}` (the [`ShapeDesc`] syntax, with
/// `"clockwise"`) or `{"circle": {"center": [x, y], "radius": r}}` (a full
/// counter-clockwise circle, returned as four quarter arcs). `None` when the
/// document is neither (e.g. a curve).
pub fn parse_arc_input(text: &str) -> Option<Result<Vec<TravelledArc>, ShapeError>> {
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
        return Some(match ShapeDesc::from_value(&doc) {
            Ok(ShapeDesc::Arc(arc)) => Ok(vec![TravelledArc { arc, clockwise }]),
            Ok(_) => Err(err("arc", "not an arc")),
            Err(e) => Err(e),
        });
    }
    let c = map.get("circle")?;
    Some(parse_circle(c, map.len()))
}

fn parse_circle(c: &Value, keys: usize) -> Result<Vec<TravelledArc>, ShapeError> {
    if keys != 1 {
        return Err(err(
            "(top level)",
            "a circle document has the single key \"circle\"",
        ));
    }
    let Some(m) = c.as_object() else {
        return Err(err(
            "circle",
            "expected {\"center\": [x, y], \"radius\": r}",
        ));
    };
    if let Some(k) = m.keys().find(|k| *k != "center" && *k != "radius") {
        return Err(err(
            format!("circle.{k}"),
            "unknown field; expected center, radius",
        ));
    }
    let num = |v: Option<&Value>, f: &str| -> Result<Rational, ShapeError> {
        let v = v.ok_or_else(|| err(f, "missing"))?;
        json_coordinate(v, f).map_err(|e| err(f, e.to_string()))
    };
    let center = match m.get("center").and_then(Value::as_array) {
        Some(p) if p.len() == 2 => V2::new(
            num(p.first(), "circle.center[0]")?,
            num(p.get(1), "circle.center[1]")?,
        ),
        _ => return Err(err("circle.center", "expected [x, y]")),
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
            Ok(TravelledArc {
                arc: checked_arc(arc, "circle")?,
                clockwise: false,
            })
        })
        .collect()
}
