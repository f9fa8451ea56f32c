//! Tests of the document walk: errors naming the element, `<use>`,
//! display and visibility, strokes.

use super::*;

/// What is not read is an error naming the element, never dropped.
#[test]
fn unreadable_content_names_the_element() {
    for (doc, at) in [
        (
            r#"<svg><g/><g><circle r="-1"/></g></svg>"#,
            "svg/g[1]/circle[0].r",
        ),
        (
            r#"<svg><g/><g><text>a</text></g></svg>"#,
            "svg/g[1]/text[0]",
        ),
        (
            r#"<svg><path d="M 0 0 A 1 1 0 2 1 2 2"/></svg>"#,
            "svg/path[0].d",
        ),
        (
            r#"<svg><ellipse rx="1" ry="-2"/></svg>"#,
            "svg/ellipse[0].ry",
        ),
        (r#"<svg><circle r="1e101"/></svg>"#, "svg/circle[0]"),
        (
            r#"<svg><g transform="skewY(90)"><path d="M0 0 L1 1"/></g></svg>"#,
            "svg/g[0].transform",
        ),
        (r##"<svg><use href="#nowhere"/></svg>"##, "svg/use[0].href"),
        (
            r##"<svg><g id="a"><use href="#a"/><line x2="1"/></g></svg>"##,
            "svg/g[0]/use[0]/#a/use[0].href",
        ),
        (
            r#"<svg><path stroke-width="2px" d="M0 0 L1 1"/></svg>"#,
            "svg/path[0].stroke-width",
        ),
        (r#"<svg><line x1="1px" x2="2"/></svg>"#, "svg/line[0].x1"),
        (
            r#"<svg><rect rx="-1" width="2" height="2"/></svg>"#,
            "svg/rect[0].rx",
        ),
        (
            r#"<svg><polygon points="0 0 1"/></svg>"#,
            "svg/polygon[0].points",
        ),
        (
            r#"<svg><path transform="wobble(1)" d="M0 0 L1 1"/></svg>"#,
            "svg/path[0].transform",
        ),
        (r#"<svg><path d="M0 0 L1 1"/>"#, "(document)"),
        (r#"<html/>"#, "(document)"),
    ] {
        match parse_svg_document(doc) {
            Err(CurveParseError::Field { field, .. }) => assert_eq!(field, at, "{doc}"),
            other => panic!("{doc}: {other:?}"),
        }
    }
    assert!(matches!(
        parse_svg_document("<svg><g/></svg>"),
        Err(CurveParseError::Empty { .. })
    ));
}

/// `<use>` instances (with x, y, transforms, nested groups and symbols);
/// display, visibility and non-rendered containers skipped.
#[test]
fn use_display_and_visibility() {
    let doc = r##"<svg xmlns="http://www.w3.org/2000/svg" xmlns:xlink="http://www.w3.org/1999/xlink">
            <defs><g id="pair"><line x2="1"/><line y2="1"/></g></defs>
            <symbol id="s"><use xlink:href="#pair" transform="scale(2)"/></symbol>
            <use href="#s" x="10" y="20"/>
            <g style="display: none"><line x2="5"/></g>
            <g visibility="hidden"><line x2="6"/><line x2="7" visibility="visible"/></g>
            <mask><line x2="8"/></mask>
        </svg>"##;
    let e = parse_svg_document_elements(doc).unwrap();
    let ats: Vec<&str> = e.iter().map(|e| e.at.as_str()).collect();
    assert_eq!(
        ats,
        [
            "svg/use[0]/#s/use[0]/#pair/line[0]",
            "svg/use[0]/#s/use[0]/#pair/line[1]",
            "svg/g[1]/line[1]"
        ]
    );
    // (1, 0) scaled by 2 then moved by (10, 20)
    assert_eq!(pts(&e[0].pieces[0])[1], (q("12"), q("20")));
    assert_eq!(pts(&e[2].pieces[0])[1], (q("7"), q("0")));
    // depth: 16 nested uses are read, 17 are not
    let mut chain = String::from(r#"<svg><defs><line id="u0" x2="1"/>"#);
    for k in 1..=17 {
        chain += &format!(r##"<use id="u{k}" href="#u{}"/>"##, k - 1);
    }
    chain += r##"</defs><use href="#u15"/></svg>"##;
    assert!(parse_svg_document_elements(&chain).is_ok());
    let deeper = chain.replace(
        r##"<use href="#u15"/></svg>"##,
        r##"<use href="#u16"/></svg>"##,
    );
    match parse_svg_document_elements(&deeper) {
        Err(CurveParseError::Field { reason, .. }) => {
            assert!(reason.contains("deeper than 16"))
        }
        other => panic!("{other:?}"),
    }
    // a billion laughs stops at the visit limit
    let mut laughs = String::from(r#"<svg><defs><line id="l0" x2="1"/>"#);
    for k in 1..=9 {
        laughs += &format!(r#"<g id="l{k}">"#);
        for _ in 0..10 {
            laughs += &format!(r##"<use href="#l{}"/>"##, k - 1);
        }
        laughs += "</g>";
    }
    laughs += r##"</defs><use href="#l9"/></svg>"##;
    assert!(matches!(
        parse_svg_document_elements(&laughs),
        Err(CurveParseError::TooLarge { .. })
    ));
}

/// stroke and stroke-width: attribute, style over attribute, inherited,
/// through `<use>`; the pen radius is half the width times the scale.
#[test]
fn stroke_widths_per_element() {
    let doc = r##"<svg stroke="#000" stroke-width="3">
            <line x2="1"/>
            <g style="stroke-width:4" stroke-width="9" transform="scale(2) rotate(30)"><line x2="1"/></g>
            <line x2="1" stroke="none"/>
            <line x2="1" style="stroke: none; stroke: red"/>
            <g transform="scale(1 2)"><line x2="1"/></g>
            <g transform="matrix(3 4 -4 3 0 0)"><line x2="1" stroke-width="1"/></g>
        </svg>"##;
    let e = parse_svg_document_elements(doc).unwrap();
    assert_eq!(e.len(), 6);
    assert_eq!(e[0].pen_radius, Ok(q("3/2")));
    assert_eq!(e[1].stroke_width, q("4"));
    assert_eq!(
        e[1].pen_radius,
        Ok(q("4")),
        "4/2 · 2 (the rotation keeps lengths)"
    );
    assert!(!e[2].stroked && e[3].stroked, "the last declaration wins");
    assert!(
        e[4].pen_radius.is_err(),
        "a non-uniform scale makes an elliptical pen"
    );
    assert_eq!(e[5].pen_radius, Ok(q("5/2")), "‖(3, 4)‖ = 5");
    let e = parse_svg_document_elements(r#"<svg><line x2="1"/></svg>"#).unwrap();
    assert!(!e[0].stroked, "SVG's initial stroke is none");
}
