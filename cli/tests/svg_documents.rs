//! Issue 28, milestone 2: SVG documents in `lncert stroke` and `offset` —
//! irrational rotations as exact rational ones (reported), `<use>`,
//! `display`/`visibility`, per-element `stroke-width` (no `--pen`), and the
//! pictures written by `--svg` drawn as the input (y down for SVG input, y
//! up, flipped, for JSON curves).

mod common;

use common::{json_of, lncert, tmp};

/// An icon in the style of common icon sets: a group under `rotate(30)`,
/// per-element `stroke-width` (attribute, `style`, inherited), a circle, a
/// rounded rect, an arc, a polyline, a `<use>` of a `<defs>` path, and
/// content that is not drawn.
const ICON: &str = r##"<svg xmlns="http://www.w3.org/2000/svg" viewBox="0 0 24 24" fill="none" stroke="currentColor" stroke-width="2">
  <defs><path id="tick" d="M 9 12 L 11 14 L 15 10"/></defs>
  <g transform="rotate(30 12 12)">
    <rect x="3" y="3" width="18" height="18" rx="2"/>
    <polyline points="7 8 12 5 17 8" style="stroke-width: 1"/>
  </g>
  <circle cx="12" cy="12" r="4" stroke-width="1.5"/>
  <path d="M 4 20 A 8 8 0 0 1 20 20"/>
  <use href="#tick" y="1"/>
  <line x1="0" y1="0" x2="24" y2="24" display="none"/>
  <line x1="0" y1="24" x2="24" y2="0" visibility="hidden"/>
  <rect width="24" height="24" stroke="none"/>
</svg>"##;

#[test]
fn icon_document_is_stroked_per_element_and_proven() {
    let icon = tmp("icon.svg", ICON);
    let pic = tmp("icon-stroke.svg", "");
    let o = lncert(&[
        "stroke",
        icon.to_str().unwrap(),
        "--tol",
        "1e-2",
        "--json",
        "--svg",
        pic.to_str().unwrap(),
    ]);
    assert_eq!(
        o.status.code(),
        Some(0),
        "{}{}",
        String::from_utf8_lossy(&o.stdout),
        String::from_utf8_lossy(&o.stderr)
    );
    let doc = json_of(&o);
    assert_eq!(doc["verdict"], "proven");
    let els = doc["elements"].as_array().unwrap();
    let at: Vec<&str> = els.iter().map(|e| e["at"].as_str().unwrap()).collect();
    assert_eq!(
        at,
        [
            "svg/g[0]/rect[0]",
            "svg/g[0]/polyline[0]",
            "svg/circle[0]",
            "svg/path[0]",
            "svg/use[0]/#tick"
        ]
    );
    let radii: Vec<&str> = els
        .iter()
        .map(|e| e["pen_radius"].as_str().unwrap())
        .collect();
    assert_eq!(radii, ["1", "1/2", "3/4", "1", "1"]);
    for e in els {
        assert_eq!(e["verdict"], "proven", "{}", e["at"]);
        assert_eq!(e["outline"]["complete"], true);
    }
    // the rotated elements are reported, with a bound far below TOL
    let a = &doc["input_approximation"];
    assert!(a["bound"].as_f64().unwrap() < 1e-6, "{a}");
    assert!(els[0]["input_approximation"]["bound"].as_f64().unwrap() > 0.0);
    assert!(els[4]["input_approximation"].is_null(), "the tick is exact");
    // the circle is stroked exactly: ∂S is the circles of radius 4 ± 3/4,
    // written as exact arcs, bound 0, nothing approximated
    assert!(els[2]["input_approximation"].is_null(), "{}", els[2]);
    let contours = els[2]["outline"]["contours"].as_array().unwrap();
    for (c, (radius, orientation)) in contours.iter().zip([("19/4", "ccw"), ("13/4", "cw")]) {
        assert_eq!(c["orientation"], orientation);
        for p in c["pieces"].as_array().unwrap() {
            assert_eq!(p["arc"]["center"], serde_json::json!(["12", "12"]), "{p}");
            assert_eq!(p["arc"]["radius"], radius, "{p}");
        }
    }
    assert_eq!(contours.len(), 2);
    for claim in ["a", "b"] {
        assert_eq!(els[2]["outline"]["claims"][claim]["bound"], 0.0);
    }
    // the picture is drawn as the input: no flip, the viewBox's top is the
    // smallest y (the arc's top at y = 20 − (8 − 4√3)… ≥ 0 − pen)
    let svg = std::fs::read_to_string(&pic).unwrap();
    assert!(!svg.contains("scale(1,-1)"), "{svg}");
    let vb: Vec<f64> = svg
        .split("viewBox=\"")
        .nth(1)
        .unwrap()
        .split('"')
        .next()
        .unwrap()
        .split_whitespace()
        .map(|x| x.parse().unwrap())
        .collect();
    assert!(vb[1] > -5.0 && vb[1] < 3.0, "top {}", vb[1]);
    // the text report names the rotation used
    let o = lncert(&["stroke", icon.to_str().unwrap(), "--tol", "1e-2"]);
    let text = String::from_utf8_lossy(&o.stdout);
    assert!(
        text.contains(
            "under an irrational rotate mapped exactly by a rational matrix (rotate(30) as cos = "
        ),
        "{text}"
    );
    assert!(
        text.contains("element svg/circle[0] (pen circle:3/4): proven"),
        "{text}"
    );
}

#[test]
fn per_element_stroke_refusals_name_the_field() {
    let curve = tmp("pe-curve.json", r#"{"bezier": [[0, 0], [1, 1], [2, 0]]}"#);
    let bare = tmp("pe-bare.svg", r#"<svg><line x2="1"/></svg>"#);
    let squash = tmp(
        "pe-squash.svg",
        r##"<svg stroke="#000"><g transform="scale(1 2)"><line x2="1"/></g></svg>"##,
    );
    let cycle = tmp(
        "pe-cycle.svg",
        r##"<svg stroke="#000"><g id="a"><use href="#a"/></g></svg>"##,
    );
    for (file, field) in [
        (&curve, "--pen"),
        (&bare, "--pen"),
        (&squash, "CURVE"),
        (&cycle, "CURVE"),
    ] {
        let o = lncert(&["stroke", file.to_str().unwrap(), "--tol", "1e-2", "--json"]);
        assert_eq!(o.status.code(), Some(2), "{}", file.display());
        let doc = json_of(&o);
        assert_eq!(doc["error"]["field"], field, "{doc}");
    }
    // an explicit pen strokes the bare document as before
    let o = lncert(&[
        "stroke",
        bare.to_str().unwrap(),
        "--pen",
        "circle:1/4",
        "--tol",
        "1e-2",
    ]);
    assert_eq!(o.status.code(), Some(0));
}

/// The y of the first and last point of the first polyline drawn in `colour`.
fn polyline_ends(svg: &str, colour: &str) -> (f64, f64) {
    let line = svg
        .lines()
        .find(|l| l.contains(&format!("stroke=\"{colour}\"")) && l.contains("points="))
        .unwrap();
    let pts: Vec<(f64, f64)> = line
        .split("points=\"")
        .nth(1)
        .unwrap()
        .split('"')
        .next()
        .unwrap()
        .split_whitespace()
        .map(|p| {
            let (x, y) = p.split_once(',').unwrap();
            (x.parse().unwrap(), y.parse().unwrap())
        })
        .collect();
    (pts[0].1, pts[pts.len() - 1].1)
}

/// `offset --svg` and `stroke --svg`: SVG input (path data or a document)
/// keeps its y-down axes; JSON curves are y-up and flipped.
#[test]
fn pictures_keep_the_input_orientation() {
    let down = tmp("orient-down.txt", "M 0 0 L 0 10");
    let up = tmp("orient-up.json", r#"{"bezier": [[0, 0], [0, 10]]}"#);
    for (file, y_down) in [(&down, true), (&up, false)] {
        let pic = tmp(&format!("orient-{y_down}.svg"), "");
        let o = lncert(&[
            "offset",
            file.to_str().unwrap(),
            "--distance",
            "1",
            "--tol",
            "1e-3",
            "--svg",
            pic.to_str().unwrap(),
        ]);
        assert_eq!(o.status.code(), Some(0));
        let svg = std::fs::read_to_string(&pic).unwrap();
        // the input runs from y = 0 to y = 10: down the screen when y is down
        let (y0, y1) = polyline_ends(&svg, "#1f4fd1");
        assert_eq!(y0 < y1, y_down, "y_down {y_down}: {y0} → {y1}");
        let pic = tmp(&format!("orient-stroke-{y_down}.svg"), "");
        let o = lncert(&[
            "stroke",
            file.to_str().unwrap(),
            "--pen",
            "circle:1",
            "--tol",
            "1e-2",
            "--svg",
            pic.to_str().unwrap(),
        ]);
        assert_eq!(o.status.code(), Some(0));
        let svg = std::fs::read_to_string(&pic).unwrap();
        assert_eq!(
            !svg.contains("<g transform=\"scale(1,-1)\">"),
            y_down,
            "{svg}"
        );
    }
}

/// Zero-length subpaths (issue 59, class 5): a `<line>` with equal ends, a
/// path's `h 0` subpath, zero-length segments touching the rest of a path,
/// and a closed subpath of one point (`M x y z`).
const DOTS: &str = r##"<svg xmlns="http://www.w3.org/2000/svg" viewBox="0 0 24 24" fill="none" stroke="black" stroke-width="2" stroke-linecap="round">
  <path d="M 4 4 h 16"/>
  <line x1="12" y1="16" x2="12" y2="16"/>
  <path d="M 2 20 L 6 20 M 9 20 h 0"/>
  <path d="M 0 10 L 0 10 L 5 10 L 5 10 L 5 12"/>
  <path d="M 20 22 z"/>
</svg>"##;

#[test]
fn zero_length_subpaths_are_dots_never_dropped() {
    let doc = tmp("dots.svg", DOTS);
    let d = doc.to_str().unwrap();
    let o = lncert(&["stroke", d, "--tol", "1e-2", "--json"]);
    assert_eq!(
        o.status.code(),
        Some(0),
        "{}",
        String::from_utf8_lossy(&o.stderr)
    );
    let v = json_of(&o);
    let els = v["elements"].as_array().unwrap();
    let at: Vec<&str> = els.iter().map(|e| e["at"].as_str().unwrap()).collect();
    assert_eq!(
        at,
        [
            "svg/path[0]",
            "svg/line[0]",
            "svg/path[1]",
            "svg/path[1]/dot[0]",
            "svg/path[2]",
            "svg/path[3]"
        ]
    );
    // each dot's outline is the pen's circle about it: arcs about the dot, of
    // radius stroke-width / 2, chained end to start around the full turn
    for (k, (x, y)) in [(1, ("12", "16")), (3, ("9", "20")), (5, ("20", "22"))] {
        let e = &els[k];
        assert_eq!(e["verdict"], "proven");
        let contours = e["outline"]["contours"].as_array().unwrap();
        assert_eq!(contours.len(), 1, "{}", e["at"]);
        let pieces = contours[0]["pieces"].as_array().unwrap();
        assert!(!pieces.is_empty());
        for p in pieces {
            let arc = &p["arc"];
            assert_eq!(arc["center"], serde_json::json!([x, y]), "{}", e["at"]);
            assert_eq!(arc["radius"], "1");
        }
        for w in 0..pieces.len() {
            let next = &pieces[(w + 1) % pieces.len()]["arc"];
            assert_eq!(
                pieces[w]["arc"]["to"], next["from"],
                "{}: not chained",
                e["at"]
            );
        }
    }
    // the touching zero-length segments draw nothing more: one contour, no dot
    assert_eq!(els[4]["outline"]["contours"].as_array().unwrap().len(), 1);

    // butt caps: SVG draws no dot; each is named in the notes
    let o = lncert(&["stroke", d, "--tol", "1e-2", "--cap", "butt", "--json"]);
    let v = json_of(&o);
    let at: Vec<&str> = v["elements"]
        .as_array()
        .unwrap()
        .iter()
        .map(|e| e["at"].as_str().unwrap())
        .collect();
    assert_eq!(at, ["svg/path[0]", "svg/path[1]", "svg/path[2]"]);
    let notes = v["notes"].as_array().unwrap();
    assert_eq!(notes.len(), 3, "{notes:?}");
    assert!(notes[0]
        .as_str()
        .unwrap()
        .starts_with("svg/line[0]: a zero-length subpath at (12, 16)"));
    assert!(notes[1]
        .as_str()
        .unwrap()
        .starts_with("svg/path[1]/dot[0]: a zero-length subpath at (9, 20)"));

    // a certificate set cannot state a dot: not written, said why, exit 3
    let cert = tmp("dots-cert.json", "");
    std::fs::remove_file(&cert).ok();
    let o = lncert(&[
        "stroke",
        d,
        "--tol",
        "1e-2",
        "--certificate",
        cert.to_str().unwrap(),
    ]);
    assert_eq!(o.status.code(), Some(3));
    assert!(String::from_utf8_lossy(&o.stderr).contains("svg/line[0]: a dot"));
    assert!(!cert.exists());

    // one pen for the whole document: one curve cannot hold a dot, refused by name
    let o = lncert(&["stroke", d, "--tol", "1e-2", "--pen", "circle:1"]);
    assert_eq!(o.status.code(), Some(2));
    assert!(String::from_utf8_lossy(&o.stderr).contains("svg/line[0]"));
}
