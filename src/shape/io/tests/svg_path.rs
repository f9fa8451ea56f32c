//! Tests of SVG path data: every command, relative and implicit forms,
//! number syntax, errors naming the byte position, the limits.

use super::*;

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
