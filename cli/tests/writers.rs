//! Issue 28, items 3 and 4: results out — SVG path data, SVG documents
//! (library and `--out FILE.svg`), and kurbo `BezPath`s.

mod common;

use common::qs as q;
use common::{lncert, tmp};
use lncert::curve::{Bezier, V2};
use lncert::scalar::{rational_from_f64, Rational, Scalar};
use lncert::shape::{parse_curve, parse_svg_document, parse_svg_document_elements};
use lncert::stroke::{stroke, Piece, Stroke, StrokeOptions};
use lncert::write::{offset_path_data, path_data, svg_document, SvgOptions, SvgShape};

/// A stroke with cubic sides (no piece above degree 3).
fn stroke_cubic(curve: &[Bezier<Rational>], r: &str, tol: f64) -> Stroke {
    let mut o = StrokeOptions::new(q(r), common::tol(tol));
    o.output = lncert::offset::Output::Cubic;
    let s = stroke(curve, &o).unwrap();
    assert!(s.proven(), "{:?} {:?} {:?}", s.a, s.b, s.c);
    s
}

/// An independent reader of the path data the writer emits: absolute
/// commands, each followed by its numbers. Returns per subpath the commands
/// with their numbers, and whether it ends with `Z`.
/// A subpath read back: its commands with their numbers, and whether it was closed.
type Subpath = (Vec<(char, Vec<f64>)>, bool);

fn read_path(d: &str) -> Vec<Subpath> {
    let mut subpaths: Vec<Subpath> = Vec::new();
    for tok in d.split_whitespace() {
        match tok {
            "M" => subpaths.push((vec![('M', vec![])], false)),
            "L" | "Q" | "C" | "A" => subpaths
                .last_mut()
                .unwrap()
                .0
                .push((tok.chars().next().unwrap(), vec![])),
            "Z" => subpaths.last_mut().unwrap().1 = true,
            n => {
                let sp = subpaths.last_mut().unwrap();
                assert!(!sp.1, "a number after Z: {d}");
                sp.0.last_mut()
                    .unwrap()
                    .1
                    .push(n.parse::<f64>().unwrap_or_else(|_| panic!("{n:?} in {d}")));
            }
        }
    }
    subpaths
}

fn f(p: &V2<Rational>) -> (f64, f64) {
    (p.x.approx(), p.y.approx())
}

/// Path data of a stroke's outline, read back by an independent reader: one
/// subpath per contour, `Z` after each closed one, every control point and
/// end point the nearest float of the exact one (shortest decimals read back
/// to the same float), arcs with the radius and the exact flags.
#[test]
fn path_data_of_a_stroke_reads_back_to_the_same_points() {
    let x = parse_curve("M 0 0 C 1 2 3 2 4 0").unwrap();
    let s = stroke_cubic(&x, "1/3", 1e-3);
    let d = path_data(&s.contours).unwrap();
    let read = read_path(&d);
    assert_eq!(read.len(), s.contours.len());
    let mut arcs = 0;
    for (c, (cmds, closed)) in s.contours.iter().zip(&read) {
        assert!(c.closed && *closed, "{d}");
        assert_eq!(
            cmds[0].1,
            vec![f(c.pieces[0].start()).0, f(c.pieces[0].start()).1]
        );
        assert_eq!(cmds.len(), c.pieces.len() + 1, "{d}");
        for (p, (cmd, nums)) in c.pieces.iter().zip(&cmds[1..]) {
            match p {
                Piece::Bezier(b) => {
                    assert_eq!(*cmd, ['L', 'Q', 'C'][b.degree() - 1]);
                    let want: Vec<f64> = b.points()[1..]
                        .iter()
                        .flat_map(|v| [f(v).0, f(v).1])
                        .collect();
                    assert_eq!(*nums, want);
                }
                Piece::Arc(a) => {
                    arcs += 1;
                    assert_eq!(*cmd, 'A');
                    let r = 1.0 / 3.0;
                    // the two caps of an open curve: half turns, counter-clockwise
                    assert_eq!(nums[..5], [r, r, 0.0, 0.0, 1.0]);
                    assert_eq!(nums[5..], [f(&a.to).0, f(&a.to).1]);
                }
            }
        }
    }
    assert_eq!(arcs, 2, "{d}");
    // lncert's own reader takes it (arcs as certified cubics)
    assert!(parse_curve(&d).is_ok());
    // an open contour has no Z
    let mut open = s.contours[0].clone();
    open.closed = false;
    assert!(!path_data(&[open]).unwrap().contains('Z'));
}

/// Degree above 3: refused, naming the piece.
#[test]
fn high_degree_pieces_are_refused_naming_the_piece() {
    let s = stroke(
        &parse_curve("M 0 0 C 1 2 3 2 4 0").unwrap(),
        &StrokeOptions::new(q("1/3"), common::tol(1e-3)),
    )
    .unwrap();
    let e = path_data(&s.contours).unwrap_err();
    assert!(e.field.starts_with("contours[0].pieces["), "{e:?}");
    assert!(e.reason.contains("degree"), "{e:?}");
}

/// Offset path data: exact decimals, read back by lncert's exact reader as
/// the very control points of the segments.
#[test]
fn offset_path_data_reads_back_exactly() {
    let x = parse_curve("M 0 0 C 1 2 3 2 4 0").unwrap();
    let mut o = lncert::OffsetOptions::new(q("-0.5"), common::tol(1e-3));
    o.method = lncert::OffsetMethod::LnPair;
    let r = lncert::offset(&x, &o).unwrap();
    let d = offset_path_data(&r).unwrap();
    let back = parse_curve(&d).unwrap();
    assert_eq!(back.len(), r.segments.len());
    for (b, s) in back.iter().zip(&r.segments) {
        let want: Vec<V2<Rational>> = s
            .bezier
            .points()
            .iter()
            .map(|p| {
                V2::new(
                    rational_from_f64(p.x).unwrap(),
                    rational_from_f64(p.y).unwrap(),
                )
            })
            .collect();
        assert_eq!(b.points(), &want[..]);
    }
}

fn bounds_of(pieces: &[Bezier<Rational>]) -> [f64; 4] {
    let mut b = [
        f64::INFINITY,
        f64::INFINITY,
        f64::NEG_INFINITY,
        f64::NEG_INFINITY,
    ];
    for p in pieces.iter().flat_map(|c| c.points()) {
        let (x, y) = f(p);
        b = [b[0].min(x), b[1].min(y), b[2].max(x), b[3].max(y)];
    }
    b
}

const CORNER: &str = r#"<svg xmlns="http://www.w3.org/2000/svg" viewBox="0 0 100 50" width="200" height="100">
  <polyline points="5 5 20 5 20 15" fill="none" stroke="black" stroke-width="2"/>
  <line x1="5" y1="12" x2="12" y2="12" stroke="black" stroke-width="1"/>
</svg>"#;

/// A document of stroked elements in the input's frame: well-formed XML, the
/// input's viewBox and size, y down as the input (an element in the top-left
/// corner stays there when lncert's reader reads the output back), nonzero
/// fill, attributes escaped.
#[test]
fn svg_document_keeps_the_input_frame_and_orientation() {
    let els = parse_svg_document_elements(CORNER).unwrap();
    let mut shapes = Vec::new();
    for e in &els {
        let s = stroke_cubic(&e.pieces, &e.pen_radius.clone().unwrap().to_string(), 1e-3);
        shapes.push(
            SvgShape::outline(&s.contours)
                .unwrap()
                .with("data-at", format!("{}<&\"", e.at)),
        );
    }
    let frame = SvgOptions::from_svg(CORNER).unwrap();
    let doc = svg_document(&shapes, &frame).unwrap();
    let xml = roxmltree::Document::parse(&doc).unwrap();
    let root = xml.root_element();
    assert_eq!(root.tag_name().name(), "svg");
    assert_eq!(root.attribute("viewBox"), Some("0 0 100 50"));
    assert_eq!(
        (root.attribute("width"), root.attribute("height")),
        (Some("200"), Some("100"))
    );
    let paths: Vec<_> = root
        .descendants()
        .filter(|n| n.has_tag_name("path"))
        .collect();
    assert_eq!(paths.len(), 2);
    assert_eq!(paths[0].attribute("data-at"), Some("svg/polyline[0]<&\""));
    assert_eq!(paths[0].attribute("fill-rule"), Some("nonzero"));
    // read back: the outline of the corner polyline is in the top-left
    let back = parse_svg_document(&doc).unwrap();
    let b = bounds_of(&back);
    assert!(
        b[0] > 3.0 && b[1] > 3.0 && b[2] < 22.0 && b[3] < 17.0,
        "{b:?}"
    );
    // the y-up option flips (the same pieces would be drawn at y ∈ [−17, −3])
    let up = svg_document(
        &shapes,
        &SvgOptions {
            y_up: true,
            ..frame.clone()
        },
    )
    .unwrap();
    let b = bounds_of(&parse_svg_document(&up).unwrap());
    assert!(b[1] < -3.0 && b[3] > -17.0 && b[3] < 0.0, "{b:?}");
    assert!(up.contains(r#"viewBox="0 -50 100 50""#), "{up}");
    // an attribute name that is not one, or one the writer sets: refused
    for bad in ["d", "1x", "a b"] {
        let e = svg_document(&[shapes[0].clone().with(bad, "v")], &frame).unwrap_err();
        assert_eq!(e.field, "shapes[0].attributes[1]");
    }
}

/// The computed viewBox holds the shapes (with a margin).
#[test]
fn computed_view_box_holds_the_shapes() {
    let c = parse_curve("M 10 20 L 30 60").unwrap();
    let doc = svg_document(&[SvgShape::curve(&c).unwrap()], &SvgOptions::default()).unwrap();
    let xml = roxmltree::Document::parse(&doc).unwrap();
    let vb: Vec<f64> = xml
        .root_element()
        .attribute("viewBox")
        .unwrap()
        .split(' ')
        .map(|v| v.parse().unwrap())
        .collect();
    assert!(
        vb[0] < 10.0 && vb[1] < 20.0 && vb[0] + vb[2] > 30.0 && vb[1] + vb[3] > 60.0,
        "{vb:?}"
    );
    assert!(vb[0] > 7.0 && vb[1] > 17.0, "{vb:?}");
}

mod kurbo_out {
    use super::*;
    use kurbo::Shape;
    use lncert::kurbo_bridge::{path_from_beziers, path_from_contours, shape_from_path};

    fn circle_stroke() -> Stroke {
        let circle = parse_svg_document(r#"<svg><circle r="3"/></svg>"#).unwrap();
        stroke_cubic(&circle, "1", 1e-4)
    }

    /// Out to kurbo and back through the bridge: the same pieces (each
    /// control point the nearest float of the exact one).
    #[test]
    fn bezpath_out_and_back_gives_the_same_pieces() {
        let x = parse_curve("M 0 0 C 1 2 3 2 4 0 L 5 1 M 7 7 Q 8 9 9 7").unwrap();
        let back = shape_from_path(&path_from_beziers(&x).unwrap()).unwrap();
        assert_eq!(back, lncert::ShapeDesc::curve(x).unwrap());
        // a stroke of a circle (cubic sides, no arcs): closed contours
        let s = circle_stroke();
        let all: Vec<&Piece> = s.contours.iter().flat_map(|c| &c.pieces).collect();
        assert!(all.iter().all(|p| matches!(p, Piece::Bezier(_))));
        let path = path_from_contours(&s.contours, 1e-6).unwrap();
        let lncert::ShapeDesc::Curve(back) = shape_from_path(&path).unwrap() else {
            panic!("not a curve")
        };
        let want: Vec<Bezier<Rational>> = all
            .iter()
            .map(|p| match p {
                Piece::Bezier(b) => b.map(|v| rational_from_f64(v.approx()).unwrap()),
                Piece::Arc(_) => unreachable!(),
            })
            .collect();
        assert_eq!(back, want);
    }

    /// kurbo's own area and winding of the stroke of a circle of radius 3 with
    /// a pen of radius 1: the ring between radii 2 and 4, area π(4² − 2²)
    /// (outer contour counter-clockwise, the hole clockwise).
    #[test]
    fn kurbo_area_and_winding_of_a_stroked_circle() {
        let s = circle_stroke();
        assert_eq!(s.contours.len(), 2);
        let path = path_from_contours(&s.contours, 1e-6).unwrap();
        let want = std::f64::consts::PI * (16.0 - 4.0);
        assert!(
            ((path.area() - want) / want).abs() < 1e-3,
            "{} vs {want}",
            path.area()
        );
        assert_eq!(path.winding((3.0, 0.0).into()), 1);
        assert_eq!(path.winding((0.0, -3.0).into()), 1);
        assert_eq!(path.winding((0.0, 0.0).into()), 0);
        assert_eq!(path.winding((5.0, 0.0).into()), 0);
    }

    /// Arcs become kurbo's cubics within the tolerance, ending exactly at the
    /// arc's end point: the stadium of a segment (two half-circle caps).
    #[test]
    fn arcs_out_to_kurbo_keep_area_and_ends() {
        let x = parse_curve("M 0 0 L 2 0").unwrap();
        let s = stroke(&x, &StrokeOptions::new(q("1/2"), common::tol(1e-3))).unwrap();
        assert!(s.contours[0]
            .pieces
            .iter()
            .any(|p| matches!(p, Piece::Arc(_))));
        let path = path_from_contours(&s.contours, 1e-9).unwrap();
        let want = 2.0 + std::f64::consts::PI / 4.0;
        assert!((path.area() - want).abs() < 1e-6, "{}", path.area());
        let e = path_from_contours(&s.contours, 0.0).unwrap_err();
        assert_eq!(e.field, "arc_tolerance");
    }
}

/// Runs `lncert ARGS --out FILE.svg`, expects exit 0, and returns the
/// document written.
fn out_document(args: &[&str], name: &str) -> String {
    let out = tmp(name, "");
    let mut all = args.to_vec();
    all.extend(["--out", out.to_str().unwrap()]);
    let o = lncert(&all);
    let err = String::from_utf8_lossy(&o.stderr);
    assert_eq!(o.status.code(), Some(0), "{args:?}: {err}");
    let doc = std::fs::read_to_string(&out).unwrap();
    roxmltree::Document::parse(&doc).unwrap_or_else(|e| panic!("not XML ({e}): {doc}"));
    doc
}

/// The `<path>` elements of a document written, and the root's viewBox.
fn paths_of(doc: &str) -> (Option<String>, Vec<Vec<(String, String)>>) {
    let xml = roxmltree::Document::parse(doc).unwrap();
    let attrs = |n: roxmltree::Node| {
        n.attributes()
            .map(|a| (a.name().to_string(), a.value().to_string()))
            .collect::<Vec<_>>()
    };
    let paths = xml.descendants().filter(|n| n.has_tag_name("path"));
    let vb = xml.root_element().attribute("viewBox").map(str::to_string);
    (vb, paths.map(attrs).collect())
}

fn attr<'a>(path: &'a [(String, String)], name: &str) -> Option<&'a str> {
    path.iter().find(|a| a.0 == name).map(|a| a.1.as_str())
}

/// `lncert stroke DOC.svg --out out.svg`: every element's outline in one
/// document in the input's frame, marked proven, which lncert's reader reads
/// back where the input was (top-left).
#[test]
fn cli_stroke_document_out_reads_back() {
    let input = tmp("corner.svg", CORNER);
    let input = input.to_str().unwrap();
    let doc = out_document(&["stroke", input, "--tol", "1e-3"], "corner-out.svg");
    let (vb, paths) = paths_of(&doc);
    assert_eq!(vb.as_deref(), Some("0 0 100 50"));
    let at: Vec<_> = paths.iter().map(|p| attr(p, "data-lncert-at")).collect();
    assert_eq!(at, [Some("svg/polyline[0]"), Some("svg/line[0]")]);
    assert!(paths
        .iter()
        .all(|p| attr(p, "data-lncert-proven") == Some("true")));
    let b = bounds_of(&parse_svg_document(&doc).unwrap());
    assert!(
        b[0] > 3.0 && b[1] > 3.0 && b[2] < 22.0 && b[3] < 17.0,
        "{b:?}"
    );
    // with a pen, from a JSON curve (y up): flipped upright
    let json = tmp(
        "seg.json",
        r#"{"bezier": [[0, 0], [1, 2], [3, 2], [4, 0]]}"#,
    );
    let args = [
        "stroke",
        json.to_str().unwrap(),
        "--pen",
        "circle:1/4",
        "--tol",
        "1e-3",
    ];
    let doc = out_document(&args, "seg-out.svg");
    assert!(doc.contains("scale(1,-1)"), "{doc}");
    // bad --out: exit 2 naming --out, before any work, never a panic
    for bad in ["out.txt", "/nonexistent-dir/out.svg"] {
        let o = lncert(&["stroke", input, "--tol", "1e-3", "--out", bad, "--json"]);
        assert_eq!(o.status.code(), Some(2), "{bad}");
        let e = common::json_of(&o);
        assert_eq!(e["error"]["field"], "--out");
    }
}

/// `lncert offset CURVE --out out.svg`: the approximant as a line in the
/// input's frame (SVG: y down, as read).
#[test]
fn cli_offset_out_reads_back() {
    let input = tmp(
        "offset-in.svg",
        r#"<svg viewBox="0 0 10 10"><path d="M 1 1 C 2 3 4 3 5 1"/></svg>"#,
    );
    let args = [
        "offset",
        input.to_str().unwrap(),
        "--distance",
        "0.25",
        "--tol",
        "1e-3",
    ];
    let doc = out_document(
        &[&args[..], &["--method", "ln-pair"]].concat(),
        "offset-out.svg",
    );
    let (vb, paths) = paths_of(&doc);
    assert_eq!(vb.as_deref(), Some("0 0 10 10"));
    assert_eq!(attr(&paths[0], "data-lncert-proven"), Some("true"));
    assert_eq!(attr(&paths[0], "fill"), Some("none"));
    let b = bounds_of(&parse_svg_document(&doc).unwrap());
    assert!(
        b[0] > 0.5 && b[2] < 5.5 && b[1] > 0.5 && b[3] < 3.5,
        "{b:?}"
    );
    // native G2 pieces (degree ≥ 4): refused before any work, naming --out
    let g2 = tmp("offset-g2.svg", "");
    let o = lncert(&[&args[..], &["--out", g2.to_str().unwrap()]].concat());
    assert_eq!(o.status.code(), Some(2));
    assert!(String::from_utf8_lossy(&o.stderr).contains("--out"));
}

/// `lncert convolve CURVE --out out.svg`: one line per side, named and marked
/// proven, in the input's frame; each read back within the pen's reach of
/// the curve; `--trim --out` writes the outline; native G2 segments (degree
/// ≥ 4) are refused before any work, naming --out.
#[test]
fn cli_convolve_out_reads_back() {
    let input = tmp(
        "convolve-in.svg",
        r#"<svg viewBox="0 0 10 10"><path d="M 1 1 C 2 3 4 3 5 1"/></svg>"#,
    );
    let args = [
        "convolve",
        input.to_str().unwrap(),
        "--ellipse",
        "0.3,0.1",
        "--tol",
        "1e-3",
    ];
    let doc = out_document(
        &[&args[..], &["--output", "cubic"]].concat(),
        "convolve-out.svg",
    );
    let (vb, paths) = paths_of(&doc);
    assert_eq!(vb.as_deref(), Some("0 0 10 10"));
    let sides: Vec<_> = paths.iter().map(|p| attr(p, "data-lncert-side")).collect();
    assert_eq!(sides, [Some("plus"), Some("minus")]);
    assert!(paths
        .iter()
        .all(|p| attr(p, "data-lncert-proven") == Some("true")));
    // the curve's box is [1, 5] × [1, 2.5]: both sides within 0.3 + tol of it
    let b = bounds_of(&parse_svg_document(&doc).unwrap());
    let reach = 0.3 + 1e-3;
    assert!(
        b[0] >= 1.0 - reach && b[2] <= 5.0 + reach && b[1] >= 1.0 - reach && b[3] <= 2.5 + reach,
        "{b:?}"
    );
    assert!(b[0] < 1.0 && b[2] > 5.0, "{b:?}");
    // --trim: the outline, one path
    let doc = out_document(
        &[&args[..], &["--output", "cubic", "--trim"]].concat(),
        "convolve-trim-out.svg",
    );
    let (_, paths) = paths_of(&doc);
    assert_eq!(paths.len(), 1);
    assert_eq!(attr(&paths[0], "data-lncert-proven"), Some("true"));
    // native G2 pieces: refused, exit 2, naming --out
    let g2 = tmp("convolve-g2.svg", "");
    let o = lncert(&[&args[..], &["--out", g2.to_str().unwrap(), "--json"]].concat());
    assert_eq!(o.status.code(), Some(2));
    assert_eq!(common::json_of(&o)["error"]["field"], "--out");
}
