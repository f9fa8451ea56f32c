//! Tests of the JSON forms: exact numbers, the curve kinds, errors naming
//! the field, the limits.

use super::*;

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
    let c =
        parse_json_curve(r#"{"bezier": [[-0.95, 0.7], [-0.3, 0.5], [0.3, -2.5], [0.9, -0.2]]}"#)
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
    let c =
        parse_json_curve(r#"{"beziers": [[[0, 0], [1, 1]], [[1, 1], [2, 0], ["3", 1]]]}"#).unwrap();
    assert_eq!(
        c,
        vec![
            bz(&[("0", "0"), ("1", "1")]),
            bz(&[("1", "1"), ("2", "0"), ("3", "1")])
        ]
    );
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
    let e =
        parse_json_curve(r#"{"beziers": [[[0, 0], [1, 1]], [[0, "1/0"], [1, 1]]]}"#).unwrap_err();
    assert_eq!(field_of(&e), "beziers[1][0][1]");
    let e =
        parse_json_curve(r#"{"bezier": [[0, "1e-99999999999999999999"], [1, 1]]}"#).unwrap_err();
    assert_eq!(field_of(&e), "bezier[0][1]");
    let e = parse_json_curve(r#"{"bezier": [[0, 1e99999999999999999999], [1, 1]]}"#).unwrap_err();
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
