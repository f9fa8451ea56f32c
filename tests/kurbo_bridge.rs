//! The kurbo bridge: exact conversions and certified verdicts (feature `kurbo`).

use kurbo::{BezPath, CubicBez, Line, PathEl, QuadBez};
use lncert::kurbo_bridge::{
    certify_within, offset_within, shape_from_cubic, shape_from_line, shape_from_path,
    shape_from_quad, Verdict,
};
use lncert::scalar::{parse_rational, rational_from_f64};
use lncert::ShapeDesc;

fn pieces(s: &ShapeDesc) -> Vec<Vec<(String, String)>> {
    let ShapeDesc::Curve(ps) = s else {
        panic!("a curve")
    };
    ps.iter()
        .map(|b| {
            b.points()
                .iter()
                .map(|p| (p.x.to_string(), p.y.to_string()))
                .collect()
        })
        .collect()
}

/// Every float becomes its exact value (0.1 is the double nearest 1/10, not
/// 1/10); `ClosePath` adds the closing line; a segment per element.
#[test]
fn conversions_are_exact() {
    let mut p = BezPath::new();
    p.move_to((0.1, 0.0));
    p.line_to((1.0, 0.0));
    p.quad_to((1.5, 0.5), (1.0, 1.0));
    p.curve_to((0.5, 1.5), (0.0, 1.0), (0.0, 0.5));
    p.close_path();
    let s = shape_from_path(&p).unwrap();
    let ps = pieces(&s);
    assert_eq!(ps.iter().map(Vec::len).collect::<Vec<_>>(), [2, 3, 4, 2]);
    let tenth = rational_from_f64(0.1).unwrap();
    assert_ne!(tenth, parse_rational("0.1").unwrap());
    assert_eq!(ps[0][0].0, tenth.to_string());
    // the closing line ends where the subpath started
    assert_eq!(ps[3][1], ps[0][0]);
    // the single-segment conversions agree with the path's pieces
    let c = CubicBez::new((1.0, 1.0), (0.5, 1.5), (0.0, 1.0), (0.0, 0.5));
    assert_eq!(pieces(&shape_from_cubic(c).unwrap())[0], ps[2]);
    let q = QuadBez::new((1.0, 0.0), (1.5, 0.5), (1.0, 1.0));
    assert_eq!(pieces(&shape_from_quad(q).unwrap())[0], ps[1]);
    let l = Line::new((0.1, 0.0), (1.0, 0.0));
    assert_eq!(pieces(&shape_from_line(l).unwrap())[0], ps[0]);
}

/// Bad paths are errors naming the element, never panics.
#[test]
fn bad_paths_name_the_element() {
    // (kurbo's `from_vec` refuses such a path with a debug assertion: make a valid
    // path and overwrite its MoveTo, as a release-built caller's data may be)
    let mut p = BezPath::new();
    p.move_to((0.0, 0.0));
    p.elements_mut()[0] = PathEl::LineTo((1.0, 0.0).into());
    assert_eq!(shape_from_path(&p).unwrap_err().field, "path[0]");
    let mut p = BezPath::new();
    p.move_to((0.0, 0.0));
    p.line_to((f64::NAN, 0.0));
    assert_eq!(shape_from_path(&p).unwrap_err().field, "path[1][1].x");
    let mut p = BezPath::new();
    p.move_to((0.0, 0.0));
    p.line_to((f64::INFINITY, 0.0));
    assert!(shape_from_path(&p).is_err());
    // nothing to certify
    assert!(shape_from_path(&BezPath::new()).is_err());
}

/// The offset of a straight cubic (evenly spaced control points) by `d` is
/// the segment translated by `d N`: an exact answer to hold the verdicts to.
#[test]
fn offset_verdicts_on_an_exact_case() {
    let c = CubicBez::new((0.0, 0.0), (1.0, 0.0), (2.0, 0.0), (3.0, 0.0));
    let d = 0.25; // left of travel (+x): N = (0, 1)
    let path = |y: f64| {
        let mut p = BezPath::new();
        p.move_to((0.0, y));
        p.line_to((3.0, y));
        p
    };
    let tol = 1e-3;
    match offset_within(c, d, &path(0.25), tol).unwrap() {
        Verdict::Within { hi } => assert!(hi <= 1e-9, "{hi}"),
        v => panic!("{v:?}"),
    }
    // 2·tol away: proven exceeded, with a lower bound at most the true 2e-3
    match offset_within(c, d, &path(0.25 + 2e-3), tol).unwrap() {
        Verdict::Exceeds { lo } => assert!(lo > tol && lo <= 2e-3 * (1.0 + 1e-9), "{lo}"),
        v => panic!("{v:?}"),
    }
    // the other side is far off
    assert!(matches!(
        offset_within(c, d, &path(-0.25), tol).unwrap(),
        Verdict::Exceeds { .. }
    ));
    // a cubic with a cusp has no regular offset: an error, not a verdict
    let cusp = CubicBez::new((0.0, 0.0), (1.0, 1.0), (0.0, 1.0), (1.0, 0.0));
    assert!(offset_within(cusp, d, &path(0.25), tol).is_err());
    // any two shapes
    let q = shape_from_quad(QuadBez::new((0.0, 0.0), (0.5, 0.5), (1.0, 0.0))).unwrap();
    let l = shape_from_line(Line::new((0.0, 0.0), (1.0, 0.0))).unwrap();
    assert!(matches!(
        certify_within(&q, &l, 0.26).unwrap(),
        Verdict::Within { .. }
    ));
    assert!(matches!(
        certify_within(&q, &l, 0.24).unwrap(),
        Verdict::Exceeds { .. }
    ));
}
