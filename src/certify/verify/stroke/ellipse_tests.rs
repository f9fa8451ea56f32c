//! Stroke certificates of elliptical pens (`"pen": {"ellipse": M}`): the
//! writer's certificates verify with the orientation of the outline itself
//! (also for `det M < 0`), and forgeries — another matrix, the disk claim on
//! the same witnesses, a tolerance below what `‖M‖₂` allows, a singular
//! matrix, an exact arc in the outline — are refused at the named field.

// the helpers of the disk certificate's tests
use super::tests::{check, q, qv, refused};
use crate::curve::Bezier;
use crate::offset::Pen;
use crate::scalar::{rational_from_f64, Rational};
use crate::stroke::{certificate, stroke, PenShape, Stroke, StrokeOptions};
use serde_json::{json, Value};
use std::sync::OnceLock;

/// `(curve, M by rows, tol)`: an open cubic under an axis-aligned pen of
/// norm 2, a closed G¹ oval under a rotated pen, and the cubic under a
/// mirroring matrix (`det M < 0`).
const CASES: [(&str, [[&str; 2]; 2], &str); 3] = [
    ("M 0 0 C 1 2 3 2 4 0", [["2", "0"], ["0", "1/2"]], "5e-2"),
    (
        "M 0 0 C 0 2 4 2 4 0 C 4 -2 0 -2 0 0 Z",
        [["3/5", "-1/5"], ["2/5", "9/20"]],
        "2e-2",
    ),
    ("M 0 0 C 1 2 3 2 4 0", [["0", "1/2"], ["1", "0"]], "5e-2"),
];

struct Fixture {
    curve: Vec<Bezier<Rational>>,
    stroke: Stroke,
    m: [[Rational; 2]; 2],
    cert: Value,
}

static FIXTURES: [OnceLock<Fixture>; 3] = [const { OnceLock::new() }; 3];

fn fixture(k: usize) -> &'static Fixture {
    FIXTURES[k].get_or_init(|| {
        let (path, m, tol) = CASES[k];
        let curve = crate::shape::parse_curve(path).unwrap();
        let m = m.map(|r| r.map(q));
        let pen = Pen::from_matrix(m.clone()).unwrap();
        let opts = StrokeOptions::with_pen(PenShape::Ellipse(pen), tol.parse().unwrap());
        let s = stroke(&curve, &opts).unwrap();
        assert!(s.proven(), "{path}: not proven: {:?}", s.notes);
        let cert = certificate(&curve, &s, &Rational::from_integer(1.into())).unwrap();
        Fixture {
            curve,
            stroke: s,
            m,
            cert,
        }
    })
}

#[test]
fn elliptical_pen_certificates_verify_with_the_outlines_orientation() {
    for k in 0..CASES.len() {
        let f = fixture(k);
        let v = check(&f.cert).unwrap_or_else(|e| panic!("case {k}: refused: {e}"));
        assert_eq!(v.tol, q(f.cert["tol"].as_str().unwrap()));
        assert_eq!(v.tol, f.stroke.tol.exact().clone());
        assert!(v.max_bound > 0.0 && v.max_bound <= f.stroke.tol.value());
        assert!(v.b.contains("M = [["), "{}", v.b);
        assert!(v.b.contains(&format!("x = {} Bézier", f.curve.len())));
        // the statement's orientations are those of the stated outline (the
        // stroke's own area signs), not of its pre-image
        let ccw = f
            .stroke
            .contours
            .iter()
            .filter(|c| c.orientation == crate::stroke::Orientation::CounterClockwise)
            .count();
        let cw = f.stroke.contours.len() - ccw;
        assert!(
            v.a.contains(&format!("{ccw} counter-clockwise and {cw} clockwise")),
            "case {k}: {}",
            v.a
        );
        // the statement is about x and L themselves
        let m = &f.cert["pen"]["ellipse"];
        assert_eq!(m[0][1], qv(&f.m[0][1]));
        assert_eq!(m[1][0], qv(&f.m[1][0]));
        let p = f.curve[0].points()[1].clone();
        assert_eq!(f.cert["curve"][0][1], json!([qv(&p.x), qv(&p.y)]));
    }
}

#[test]
fn another_matrix_is_refused() {
    let f = fixture(0);
    // the other axis longer, the transpose of a rotated pen, a larger pen
    let edits: [(usize, [[&str; 2]; 2]); 3] = [
        (0, [["1/2", "0"], ["0", "2"]]),
        (1, [["3/5", "2/5"], ["-1/5", "9/20"]]),
        (1, [["6/5", "-2/5"], ["4/5", "9/10"]]),
    ];
    for (k, m) in edits {
        let mut doc = fixture(k).cert.clone();
        doc["pen"]["ellipse"] = json!(m.map(|r| r.map(|x| qv(&q(x)))));
        let e = refused(&doc);
        assert!(
            e.at.starts_with("cover[") || e.at.starts_with("boundary["),
            "{e}"
        );
    }
    // a singular matrix is named
    let mut doc = f.cert.clone();
    doc["pen"]["ellipse"] = json!([["1", "2"], ["1/2", "1"]]);
    let e = refused(&doc);
    assert_eq!(e.at, "pen.ellipse", "{e}");
    // a malformed one too
    let mut doc = f.cert.clone();
    doc["pen"]["ellipse"] = json!([["1", "2"]]);
    assert_eq!(refused(&doc).at, "pen.ellipse");
    let mut doc = f.cert.clone();
    doc["pen"] = json!({"circle": "1"});
    assert!(refused(&doc).at.starts_with("pen"));
}

#[test]
fn the_disk_claim_on_an_ellipse_certificate_is_refused() {
    let f = fixture(0);
    // the claim of the other form, keys unchanged
    let mut doc = f.cert.clone();
    doc["claim"] = json!(super::CLAIM);
    assert_eq!(refused(&doc).at, "claim");
    // the disk form of the same witnesses: radius 1 about x and L themselves
    let mut doc = f.cert.clone();
    let o = doc.as_object_mut().unwrap();
    o.remove("pen");
    o.insert("radius".into(), json!("1"));
    o.insert("claim".into(), json!(super::CLAIM));
    let e = refused(&doc);
    assert!(
        e.at.starts_with("cover[") || e.at.starts_with("boundary["),
        "{e}"
    );
    // both keys
    let mut doc = f.cert.clone();
    doc["radius"] = json!("1");
    assert_eq!(refused(&doc).at, "radius");
}

/// `‖M‖₂ = 2` for the first pen: the pre-image must be within `tol/2`. A
/// tolerance between the pre-image's largest bound and twice it is refused
/// (a checker that forgot the norm would accept it).
#[test]
fn a_tolerance_below_the_norm_is_refused() {
    let f = fixture(0);
    let v = check(&f.cert).unwrap();
    // the pre-image's largest bound, from the statement's (× ‖M‖₂ = 2)
    let pre_max = v.max_bound / 2.0;
    let mut doc = f.cert.clone();
    doc["tol"] = qv(&rational_from_f64(1.5 * pre_max).unwrap());
    let e = refused(&doc);
    assert!(
        e.at.starts_with("cover[") || e.at.starts_with("boundary["),
        "{e}"
    );
    // and just above 2 × the largest bound it verifies
    let mut doc = f.cert.clone();
    doc["tol"] = qv(&rational_from_f64(2.0 * pre_max * (1.0 + 1e-9)).unwrap());
    check(&doc).unwrap_or_else(|e| panic!("refused: {e}"));
}

#[test]
fn an_edited_outline_or_curve_is_refused() {
    let f = fixture(1);
    let mut doc = f.cert.clone();
    doc["outline"][0][0]["bezier"][1][0] = json!("1/3");
    assert!(refused(&doc).at.starts_with("cover[0][0]"));
    let mut doc = f.cert.clone();
    doc["curve"][0][1] = json!(["0", "3"]);
    let e = refused(&doc);
    assert!(
        e.at.starts_with("cover[") || e.at.starts_with("boundary[") || e.at.starts_with("curve"),
        "{e}"
    );
}

/// A disk certificate's outline has exact arcs (its caps): stated for an
/// elliptical pen (even `M = I`) it is refused at the first arc.
#[test]
fn an_exact_arc_in_an_ellipse_outline_is_refused() {
    let curve = crate::shape::parse_curve("M 0 0 L 2 0").unwrap();
    let r = Rational::from_integer(1.into());
    let s = stroke(
        &curve,
        &StrokeOptions::new(r.clone(), "1e-1".parse().unwrap()),
    )
    .unwrap();
    let mut doc = certificate(&curve, &s, &r).unwrap();
    check(&doc).unwrap();
    let arc = doc["outline"]
        .as_array()
        .unwrap()
        .iter()
        .enumerate()
        .flat_map(|(c, ps)| {
            ps.as_array()
                .unwrap()
                .iter()
                .enumerate()
                .filter(|(_, p)| p.get("arc").is_some())
                .map(move |(i, _)| (c, i))
        })
        .next()
        .expect("a cap arc");
    let o = doc.as_object_mut().unwrap();
    o.remove("radius");
    o.insert("pen".into(), json!({"ellipse": [["1", "0"], ["0", "1"]]}));
    o.insert("claim".into(), json!(super::CLAIM_ELLIPSE));
    let e = refused(&doc);
    assert_eq!(e.at, format!("outline[{}][{}]", arc.0, arc.1), "{e}");
    assert!(e.reason.contains("arc"), "{e}");
}
