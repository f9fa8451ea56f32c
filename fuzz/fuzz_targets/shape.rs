#![no_main]
//! Fuzz target `shape`: raw bytes -> (lossy UTF-8) -> `lncert::shape::ShapeDesc::parse`
//! (and `lncert::stroke::StrokeShape::parse_reported`, the referee's stroke shape).
//!
//! Must never panic on any text (SVG path data or JSON). On success the canonical
//! JSON form (`to_json`) must read back (`from_value`) to an equal description:
//! certificates store shapes in that form and the verifier reads them back.

use libfuzzer_sys::{fuzz_target, Corpus};
use lncert::shape::ShapeDesc;

fuzz_target!(|data: &[u8]| -> Corpus {
    let text = String::from_utf8_lossy(data);
    // the stroke referee's shape: never a panic; a stroke it accepts has a
    // positive radius or a nonsingular pen matrix (checked by its reader)
    if let Ok(Some((s, _))) = lncert::stroke::StrokeShape::parse_reported(&text) {
        if let lncert::stroke::PenShape::Circle(r) = &s.pen {
            assert!(*r > lncert::scalar::Rational::from_integer(0.into()));
        }
    }
    let Ok(shape) = ShapeDesc::parse(&text) else {
        return Corpus::Reject;
    };
    let json = shape.to_json();
    match ShapeDesc::from_value(&json) {
        Ok(back) => assert_eq!(
            back, shape,
            "to_json/from_value round trip changed the shape; json = {json}"
        ),
        Err(e) => panic!("the canonical JSON of a parsed shape is rejected: {e}; json = {json}"),
    }
    // The canonical text form must parse too (certificates are stored as text).
    match ShapeDesc::parse(&json.to_string()) {
        Ok(back) => assert_eq!(
            back, shape,
            "canonical JSON text round trip changed the shape"
        ),
        Err(e) => {
            panic!("the canonical JSON text of a parsed shape is rejected: {e}; json = {json}")
        }
    }
    Corpus::Keep
});
