//! Tests of the curve readers: the helpers shared by the topics, the format
//! dispatch, and the never-panic properties over any text.

mod json;
mod svg_path;

use super::*;
use crate::curve::V2;
use crate::test_util::q;
use proptest::prelude::*;

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
