//! Unit tests of the stroke certificate (format `lncert-stroke-certificate`
//! v1): certificates written by [`crate::stroke::certificate`] for small
//! curves verify; forgeries, each one edit of a valid certificate's JSON, are
//! refused at the field they touch; and a float cross-check of the outline
//! against the stroke boundary that shares nothing with the checker.

use super::super::{verify, Invalid, Valid};
use crate::curve::Bezier;
use crate::scalar::{rational_to_string, Rational, Scalar};
use crate::stroke::Stroke;
use serde_json::{json, Value};
use std::sync::OnceLock;

/// The curves: `(path, radius, tol)`.
const CASES: [(&str, &str, &str); 5] = [
    ("M 0 0 L 4 0", "1", "1e-1"),
    ("M 0 0 L 3 0 L 0 2", "1", "1e-1"),
    ("M 0 0 C 1 2 3 2 4 0", "1/2", "5e-2"),
    ("M 0 0 L 4 0 L 4 4 L 0 4 Z", "1", "1e-1"),
    ("M 0 0 L 4 0 M 0 3 L 4 3", "3/4", "1e-1"),
];
const SEGMENT: usize = 0;
const CORNER: usize = 1;
const CUBIC: usize = 2;
const SQUARE: usize = 3;
const TWO: usize = 4;

/// A proven stroke and its certificate.
struct Fixture {
    name: &'static str,
    curve: Vec<Bezier<Rational>>,
    stroke: Stroke,
    r: Rational,
    tol: Rational,
    cert: Value,
}

static FIXTURES: [OnceLock<Fixture>; 5] = [const { OnceLock::new() }; 5];

fn fixture(k: usize) -> &'static Fixture {
    FIXTURES[k].get_or_init(|| {
        let (name, r, tol) = CASES[k];
        let curve = crate::shape::parse_curve(name).unwrap();
        let r = q(r);
        let tol: crate::Tolerance = tol.parse().unwrap();
        let stroke = crate::stroke::stroke(
            &curve,
            &crate::stroke::StrokeOptions::new(r.clone(), tol.clone()),
        )
        .unwrap();
        assert!(stroke.proven(), "{name}: the stroke is not proven");
        let cert = crate::stroke::certificate(&curve, &stroke, &r).unwrap();
        Fixture {
            name,
            curve,
            stroke,
            r,
            tol: tol.exact().clone(),
            cert,
        }
    })
}

pub(super) fn q(s: &str) -> Rational {
    crate::parse_rational(s).unwrap()
}
/// A canonical number of the document, read.
fn num(v: &Value) -> Rational {
    let s = v.as_str().expect("a rational string");
    assert_eq!(rational_to_string(&q(s)), s, "not canonical in the writer");
    q(s)
}
pub(super) fn qv(r: &Rational) -> Value {
    Value::String(rational_to_string(r))
}
fn arr(v: &mut Value) -> &mut Vec<Value> {
    v.as_array_mut().expect("a list")
}
pub(super) fn check(doc: &Value) -> Result<Valid, Invalid> {
    verify(&doc.to_string())
}
#[track_caller]
pub(super) fn refused(doc: &Value) -> Invalid {
    match check(doc) {
        Ok(v) => panic!("a forgery was accepted: {}", v.statement()),
        Err(e) => e,
    }
}
/// Refused at a field starting with `prefix`.
#[track_caller]
fn refused_at(doc: &Value, prefix: &str) -> Invalid {
    let e = refused(doc);
    assert!(
        e.at.starts_with(prefix),
        "refused at `{}` ({}), expected at `{prefix}…`",
        e.at,
        e.reason
    );
    e
}
/// Refused at exactly `at`.
#[track_caller]
fn refused_exactly(doc: &Value, at: &str) -> Invalid {
    let e = refused(doc);
    assert_eq!(e.at, at, "refused for: {}", e.reason);
    e
}

/// The outline piece kinds of the certificate: `(contour, piece, is_arc)`.
fn kinds(cert: &Value) -> Vec<(usize, usize, bool)> {
    let mut out = Vec::new();
    for (c, ps) in cert["outline"].as_array().unwrap().iter().enumerate() {
        for (i, p) in ps.as_array().unwrap().iter().enumerate() {
            out.push((c, i, p.get("arc").is_some()));
        }
    }
    out
}

// ---- float geometry, independent of the checker ----

type F2 = (f64, f64);

fn fpts(b: &Bezier<Rational>) -> Vec<F2> {
    b.points()
        .iter()
        .map(|p| (p.x.approx(), p.y.approx()))
        .collect()
}
fn casteljau(p: &[F2], t: f64) -> F2 {
    let mut b = p.to_vec();
    for k in (1..b.len()).rev() {
        for i in 0..k {
            b[i] = (
                b[i].0 * (1.0 - t) + b[i + 1].0 * t,
                b[i].1 * (1.0 - t) + b[i + 1].1 * t,
            );
        }
    }
    b[0]
}
fn deriv(p: &[F2], t: f64) -> F2 {
    let n = (p.len() - 1) as f64;
    let d: Vec<F2> = p
        .windows(2)
        .map(|w| (n * (w[1].0 - w[0].0), n * (w[1].1 - w[0].1)))
        .collect();
    casteljau(&d, t)
}
fn dist(a: F2, b: F2) -> f64 {
    (a.0 - b.0).hypot(a.1 - b.1)
}
/// The exact offset point `x(t) + σ r J x′/|x′|` (σ = +1: left), in floats.
fn offset_point(p: &[F2], t: f64, sigma: f64, r: f64) -> F2 {
    let x = casteljau(p, t);
    let d = deriv(p, t);
    let l = d.0.hypot(d.1);
    (x.0 - sigma * r * d.1 / l, x.1 + sigma * r * d.0 / l)
}
/// Distance from `p` to the segment `[a, b]`.
fn seg_dist(p: F2, a: F2, b: F2) -> f64 {
    let (dx, dy) = (b.0 - a.0, b.1 - a.1);
    let l2 = dx * dx + dy * dy;
    let t = if l2 > 0.0 {
        (((p.0 - a.0) * dx + (p.1 - a.1) * dy) / l2).clamp(0.0, 1.0)
    } else {
        0.0
    };
    dist(p, (a.0 + t * dx, a.1 + t * dy))
}

// ---- 1. valid certificates ----

#[test]
fn valid_certificates_verify_within_tol() {
    for k in 0..CASES.len() {
        let f = fixture(k);
        let v = check(&f.cert).unwrap_or_else(|e| panic!("{}: refused: {e}", f.name));
        let tol = f.tol.approx();
        assert_eq!(v.tol, f.tol, "{}", f.name);
        assert_eq!(num(&f.cert["tol"]), f.tol);
        assert_eq!(num(&f.cert["radius"]), f.r);
        assert!(
            v.max_bound > 0.0 && v.max_bound <= tol,
            "{}: max bound {} vs tol {tol}",
            f.name,
            v.max_bound
        );
        // the count is every part and every box of the document
        let parts: usize = f.cert["cover"]
            .as_array()
            .unwrap()
            .iter()
            .flat_map(|c| c.as_array().unwrap())
            .map(|p| p.as_array().unwrap().len())
            .sum();
        let boxes: usize = f.cert["boundary"]
            .as_array()
            .unwrap()
            .iter()
            .map(|b| b["boxes"].as_array().unwrap().len())
            .sum();
        assert!(parts > 0 && boxes > 0, "{}", f.name);
        assert_eq!(v.boxes, parts + boxes, "{}", f.name);
        let st = v.statement();
        assert!(st.contains(&format!("r = {}", f.r)), "{}: {st}", f.name);
        assert!(st.contains(&format!("≤ {}", f.tol)), "{}: {st}", f.name);
        assert!(
            v.a.contains(&format!(
                "an outline of {} closed contour(s)",
                f.stroke.contours.len()
            )),
            "{}: {}",
            f.name,
            v.a
        );
        assert!(
            v.b.contains(&format!("x = {} Bézier piece(s)", f.curve.len())),
            "{}: {}",
            f.name,
            v.b
        );
    }
}

#[test]
fn boundary_families_follow_the_curve() {
    let names = |k: usize| -> Vec<String> {
        fixture(k).cert["boundary"]
            .as_array()
            .unwrap()
            .iter()
            .map(|b| b["of"].as_str().unwrap().to_string())
            .collect()
    };
    let sides = |n: usize| -> Vec<String> {
        (0..n)
            .flat_map(|j| [format!("piece {j} left"), format!("piece {j} right")])
            .collect()
    };
    let cone = |s: &str| vec![format!("{s} a"), format!("{s} b")];
    // open: start cap, then the end cone of every piece (joins and the end cap)
    let open = |first: usize, end: usize| -> Vec<String> {
        let mut v = cone(&format!("start {first}"));
        for j in first..end {
            v.extend(cone(&format!("end {j}")));
        }
        v
    };
    let mut want = sides(1);
    want.extend(open(0, 1));
    assert_eq!(names(SEGMENT), want);
    assert_eq!(names(CUBIC), want);
    let mut want = sides(2);
    want.extend(open(0, 2));
    assert_eq!(names(CORNER), want);
    // closed: a join at every vertex, the closing one last, no caps
    let mut want = sides(4);
    for j in 0..4 {
        want.extend(cone(&format!("end {j}")));
    }
    assert_eq!(names(SQUARE), want);
    let mut want = sides(2);
    want.extend(open(0, 1));
    want.extend(open(1, 2));
    assert_eq!(names(TWO), want);
    // the statement counts the components
    let v = check(&fixture(SQUARE).cert).unwrap();
    assert!(v.b.contains("1 component(s) (1 closed)"), "{}", v.b);
    let v = check(&fixture(TWO).cert).unwrap();
    assert!(v.b.contains("2 component(s) (0 closed)"), "{}", v.b);
    assert!(v.a.contains("2 closed contour(s)"), "{}", v.a);
}

// ---- 2. forgeries ----

#[test]
fn a_lowered_tol_is_refused_at_a_part() {
    for k in 0..CASES.len() {
        let f = fixture(k);
        let mut doc = f.cert.clone();
        doc["tol"] = qv(&(&f.tol / Rational::from_integer(10.into())));
        // (a) is checked first: a part's bound is above tol/10
        let e = refused_at(&doc, "cover[");
        assert!(e.reason.contains("above the tolerance"), "{}: {e}", f.name);
    }
}

#[test]
fn a_changed_radius_is_refused() {
    for k in [SEGMENT, CUBIC, SQUARE] {
        let f = fixture(k);
        // doubled: the outside disks now meet S
        let mut doc = f.cert.clone();
        doc["radius"] = qv(&(&f.r * Rational::from_integer(2.into())));
        let e = refused_at(&doc, "cover[");
        assert!(e.reason.starts_with("w:"), "{}: {e}", f.name);
        // halved: the outline is r/2 away from the new boundary
        let mut doc = f.cert.clone();
        doc["radius"] = qv(&(&f.r / Rational::from_integer(2.into())));
        let e = refused_at(&doc, "cover[");
        assert!(e.reason.contains("above the tolerance"), "{}: {e}", f.name);
        // nudged by tol: still refused (parts' bounds are close to tol)
        let mut doc = f.cert.clone();
        doc["radius"] = qv(&(&f.r + &f.tol));
        refused(&doc);
        for bad in ["0", "-1"] {
            let mut doc = f.cert.clone();
            doc["radius"] = json!(bad);
            refused_exactly(&doc, "radius");
        }
    }
}

#[test]
fn a_missing_or_extra_boundary_family_is_refused_at_boundary() {
    for k in [SEGMENT, CORNER, SQUARE, TWO] {
        let f = fixture(k);
        // the last half of a cap or join removed
        let mut doc = f.cert.clone();
        let last = arr(&mut doc["boundary"]).pop().unwrap();
        let name = last["of"].as_str().unwrap();
        assert!(name.ends_with(" b") && name.starts_with("end "), "{name}");
        let e = refused_exactly(&doc, "boundary");
        assert!(e.reason.contains("families"), "{e}");
        // the first offset removed
        let mut doc = f.cert.clone();
        arr(&mut doc["boundary"]).remove(0);
        refused_exactly(&doc, "boundary");
        // a family given twice
        let mut doc = f.cert.clone();
        let b0 = doc["boundary"][0].clone();
        arr(&mut doc["boundary"]).push(b0);
        refused_exactly(&doc, "boundary");
        // no families at all
        let mut doc = f.cert.clone();
        doc["boundary"] = json!([]);
        refused_exactly(&doc, "boundary");
    }
}

#[test]
fn swapped_boundary_families_are_refused_at_of() {
    let f = fixture(SQUARE);
    let n = f.cert["boundary"].as_array().unwrap().len();
    for (a, b) in [(0, 1), (0, 2), (8, 9), (n - 2, n - 1)] {
        let mut doc = f.cert.clone();
        arr(&mut doc["boundary"]).swap(a, b);
        refused_exactly(&doc, &format!("boundary[{a}].of"));
    }
    // renamed to another family's name, boxes kept
    let mut doc = f.cert.clone();
    doc["boundary"][3]["of"] = json!("piece 1 left");
    refused_exactly(&doc, "boundary[3].of");
    let mut doc = f.cert.clone();
    doc["boundary"][0]["of"] = json!("piece 0 left ");
    refused_exactly(&doc, "boundary[0].of");
}

#[test]
fn boxes_of_one_family_under_another_name_are_refused_at_a_box() {
    // the segment's two sides (y = ±1) exchange their boxes, names kept
    for k in [SEGMENT, TWO] {
        let f = fixture(k);
        let mut doc = f.cert.clone();
        let left = doc["boundary"][0]["boxes"].clone();
        let right = doc["boundary"][1]["boxes"].clone();
        doc["boundary"][0]["boxes"] = right;
        doc["boundary"][1]["boxes"] = left;
        refused_at(&doc, "boundary[0].boxes[");
        // the two halves of the start cap exchange theirs
        let (a, b) = (2 * f.curve.len(), 2 * f.curve.len() + 1);
        let mut doc = f.cert.clone();
        let ba = doc["boundary"][a]["boxes"].clone();
        let bb = doc["boundary"][b]["boxes"].clone();
        doc["boundary"][a]["boxes"] = bb;
        doc["boundary"][b]["boxes"] = ba;
        refused_at(&doc, &format!("boundary[{a}].boxes["));
    }
}

#[test]
fn box_edits_that_break_the_chain_are_refused_at_that_box() {
    let f = fixture(CUBIC);
    let boxes = f.cert["boundary"][0]["boxes"].as_array().unwrap();
    assert!(boxes.len() >= 3);
    let t0 = num(&boxes[0]["t"][0]);
    let t1 = num(&boxes[0]["t"][1]);
    assert_eq!(t0, q("0"));
    // an empty box, a reversed one, one beyond 1
    for bad in [t0.clone(), q("-1/8"), q("2")] {
        let mut doc = f.cert.clone();
        doc["boundary"][0]["boxes"][0]["t"][1] = qv(&bad);
        refused_exactly(&doc, "boundary[0].boxes[0].t[1]");
    }
    // the first box shortened: a gap before the second one (or the first
    // box itself fails with its foot map moved)
    let mut doc = f.cert.clone();
    doc["boundary"][0]["boxes"][0]["t"][1] = qv(&((&t0 + &t1) / Rational::from_integer(2.into())));
    let e = refused(&doc);
    assert!(
        e.at == "boundary[0].boxes[1].t[0]" || e.at == "boundary[0].boxes[0]",
        "{e}"
    );
    // the first box lengthened over the second: an overlap (the chain is exact)
    let t2 = num(&boxes[1]["t"][1]);
    let mut doc = f.cert.clone();
    doc["boundary"][0]["boxes"][0]["t"][1] = qv(&((&t1 + &t2) / Rational::from_integer(2.into())));
    let e = refused(&doc);
    assert!(
        e.at == "boundary[0].boxes[1].t[0]" || e.at == "boundary[0].boxes[0]",
        "{e}"
    );
    // the first box starting after 0
    let mut doc = f.cert.clone();
    doc["boundary"][0]["boxes"][0]["t"][0] = qv(&(&t1 / Rational::from_integer(4.into())));
    let e = refused_exactly(&doc, "boundary[0].boxes[0].t[0]");
    assert!(e.reason.contains("expected 0"), "{e}");
    // a middle box removed: a gap
    let mut doc = f.cert.clone();
    arr(&mut doc["boundary"][0]["boxes"]).remove(1);
    refused_exactly(&doc, "boundary[0].boxes[1].t[0]");
    // the last box removed: [0, 1] not covered
    let mut doc = f.cert.clone();
    arr(&mut doc["boundary"][0]["boxes"]).pop();
    let e = refused_exactly(&doc, "boundary[0].boxes");
    assert!(e.reason.contains("not covered"), "{e}");
    // a family without boxes
    let mut doc = f.cert.clone();
    doc["boundary"][0]["boxes"] = json!([]);
    refused_exactly(&doc, "boundary[0].boxes");
    // a box without t
    let mut doc = f.cert.clone();
    arr_obj(&mut doc["boundary"][0]["boxes"][0]).remove("t");
    refused_exactly(&doc, "boundary[0].boxes[0].t");
}

fn arr_obj(v: &mut Value) -> &mut serde_json::Map<String, Value> {
    v.as_object_mut().expect("an object")
}

/// The first `inside` box of an offset family: `(family, box, piece j, σ)`.
fn first_inside_box(cert: &Value) -> Option<(usize, usize, usize, f64)> {
    for (k, fam) in cert["boundary"].as_array().unwrap().iter().enumerate() {
        let name = fam["of"].as_str().unwrap();
        let w: Vec<&str> = name.split(' ').collect();
        if w[0] != "piece" {
            continue;
        }
        let sigma = if w[2] == "left" { 1.0 } else { -1.0 };
        for (i, b) in fam["boxes"].as_array().unwrap().iter().enumerate() {
            if b.get("inside").is_some() {
                return Some((k, i, w[1].parse().unwrap(), sigma));
            }
        }
    }
    None
}

#[test]
fn a_moved_inside_witness_is_refused_at_its_box() {
    let mut tried = 0;
    for k in [CORNER, SQUARE] {
        let f = fixture(k);
        let Some((fam, i, j, sigma)) = first_inside_box(&f.cert) else {
            assert_ne!(
                k, CORNER,
                "the corner's inner offsets cross: inside boxes expected"
            );
            continue;
        };
        tried += 1;
        let bx = &f.cert["boundary"][fam]["boxes"][i];
        let t = (num(&bx["t"][0]).approx() + num(&bx["t"][1]).approx()) / 2.0;
        let r = f.r.approx();
        // the boundary point at the box's middle, and the witness piece
        let p = offset_point(&fpts(&f.curve[j]), t, sigma, r);
        let wj = bx["inside"]["piece"].as_u64().unwrap() as usize;
        let wp = fpts(&f.curve[wj]);
        let u0 = num(&bx["inside"]["u"]).approx();
        assert!(dist(casteljau(&wp, u0), p) < r, "the writer's witness");
        // the farthest of 17 points of the witness piece: the claim
        // |p − x(u)| < r is then false at p
        let (u, d) = (0..=16)
            .map(|m| m as f64 / 16.0)
            .map(|u| (u, dist(casteljau(&wp, u), p)))
            .fold((0.0, 0.0), |a, b| if b.1 > a.1 { b } else { a });
        assert!(d > 1.2 * r, "{}: only {d} away", f.name);
        let mut doc = f.cert.clone();
        doc["boundary"][fam]["boxes"][i]["inside"]["u"] =
            qv(&Rational::new(((u * 16.0) as i64).into(), 16.into()));
        let at = format!("boundary[{fam}].boxes[{i}]");
        let e = refused_exactly(&doc, &at);
        assert!(e.reason.contains("not proven below r²"), "{e}");
        // a witness piece the curve does not have, and u outside [0, 1]
        let mut doc = f.cert.clone();
        doc["boundary"][fam]["boxes"][i]["inside"]["piece"] = json!(f.curve.len());
        refused_exactly(&doc, &at);
        let mut doc = f.cert.clone();
        doc["boundary"][fam]["boxes"][i]["inside"]["u"] = json!("3/2");
        refused_exactly(&doc, &at);
        // the inside box's claim turned into a claim near an arc far away
        // is no better
        let far = kinds(&f.cert)
            .into_iter()
            .find(|x| x.2)
            .expect("an arc in the outline");
        let mut doc = f.cert.clone();
        doc["boundary"][fam]["boxes"][i] = json!({
            "t": bx["t"].clone(),
            "near": {"contour": far.0, "piece": far.1},
        });
        refused_exactly(&doc, &at);
    }
    assert!(tried >= 1);
}

#[test]
fn dropped_parts_are_refused() {
    for k in [SEGMENT, CUBIC, SQUARE] {
        let f = fixture(k);
        for (c, i, is_arc) in kinds(&f.cert) {
            let n = f.cert["cover"][c][i].as_array().unwrap().len();
            if n < 2 {
                continue;
            }
            let at = format!("cover[{c}][{i}]");
            // the last part dropped: the parts stop before the end
            let mut doc = f.cert.clone();
            arr(&mut doc["cover"][c][i]).pop();
            let e = refused_exactly(&doc, &at);
            assert!(e.reason.contains("stop before the end"), "{e}");
            // the first part dropped: the cover does not start at the start
            let mut doc = f.cert.clone();
            arr(&mut doc["cover"][c][i]).remove(0);
            let key = if is_arc { "dirs[0]" } else { "s[0]" };
            refused_exactly(&doc, &format!("{at}[0].{key}"));
            // a middle part dropped: a gap
            if n >= 3 {
                let mut doc = f.cert.clone();
                arr(&mut doc["cover"][c][i]).remove(1);
                refused_exactly(&doc, &format!("{at}[1].{key}"));
            }
            // no parts
            let mut doc = f.cert.clone();
            doc["cover"][c][i] = json!([]);
            let e = refused_exactly(&doc, &at);
            assert!(e.reason.contains("no parts"), "{e}");
        }
    }
}

#[test]
fn part_range_edits_are_refused_at_the_part() {
    let f = fixture(SEGMENT);
    let (c, i, _) = kinds(&f.cert).into_iter().find(|x| !x.2).unwrap();
    let at = format!("cover[{c}][{i}]");
    // s1 beyond 1, s1 ≤ s0
    for bad in ["2", "0"] {
        let mut doc = f.cert.clone();
        doc["cover"][c][i][0]["s"][1] = json!(bad);
        refused_exactly(&doc, &format!("{at}[0].s[1]"));
    }
    // the last part running past 1
    let n = f.cert["cover"][c][i].as_array().unwrap().len();
    let mut doc = f.cert.clone();
    doc["cover"][c][i][n - 1]["s"][1] = json!("3/2");
    refused_exactly(&doc, &format!("{at}[{}].s[1]", n - 1));
    // an arc part turning by π/2 or more, or backwards
    let (c, i, _) = kinds(&f.cert).into_iter().find(|x| x.2).unwrap();
    let at = format!("cover[{c}][{i}][0]");
    let d0 = f.cert["cover"][c][i][0]["dirs"][0].clone();
    let (x, y) = (num(&d0[0]), num(&d0[1]));
    for d1 in [
        [-&y, x.clone()],                             // π/2
        [-&x, -&y],                                   // π
        [y.clone(), -&x],                             // −π/2
        [&x + &y * q("1/100"), &y - &x * q("1/100")], // slightly clockwise
    ] {
        let mut doc = f.cert.clone();
        doc["cover"][c][i][0]["dirs"][1] = json!([qv(&d1[0]), qv(&d1[1])]);
        refused_exactly(&doc, &format!("{at}.dirs"));
    }
}

#[test]
fn an_outside_disk_on_the_curve_is_refused() {
    for k in [SEGMENT, CORNER, CUBIC] {
        let f = fixture(k);
        let p0 = f.cert["curve"][0][0].clone();
        let p_last = f.cert["curve"][0]
            .as_array()
            .unwrap()
            .last()
            .unwrap()
            .clone();
        for (c, i, _) in kinds(&f.cert) {
            let at = format!("cover[{c}][{i}][0]");
            // w.at on an input control point that is on the curve
            for p in [&p0, &p_last] {
                let mut doc = f.cert.clone();
                doc["cover"][c][i][0]["w"]["at"] = p.clone();
                let e = refused_exactly(&doc, &at);
                assert!(e.reason.starts_with("w:"), "{e}");
            }
            // w.at on the inside witness's curve point (the part's own y)
            // — exactly representable for the segment and the polyline
            if k != CUBIC {
                let o = &f.cert["cover"][c][i][0]["o"];
                // a disk's centre, or the middle of a capsule's segment
                let (j, u) = match o.get("segment") {
                    Some(j) => (j.as_u64().unwrap() as usize, q("1/2")),
                    None => (o["piece"].as_u64().unwrap() as usize, num(&o["u"])),
                };
                let pts = f.curve[j].points();
                let one = Rational::from_integer(1.into());
                let y = [
                    &pts[0].x * (&one - &u) + &pts[1].x * &u,
                    &pts[0].y * (&one - &u) + &pts[1].y * &u,
                ];
                let mut doc = f.cert.clone();
                doc["cover"][c][i][0]["w"]["at"] = json!([qv(&y[0]), qv(&y[1])]);
                let e = refused_exactly(&doc, &at);
                assert!(e.reason.starts_with("w:"), "{e}");
            }
        }
    }
}

#[test]
fn an_enlarged_outside_disk_is_refused() {
    for k in [SEGMENT, CORNER, CUBIC, SQUARE, TWO] {
        let f = fixture(k);
        for (c, i, _) in kinds(&f.cert) {
            let at = format!("cover[{c}][{i}][0]");
            let mut doc = f.cert.clone();
            let big = num(&f.cert["cover"][c][i][0]["w"]["mu"]) + &f.r;
            doc["cover"][c][i][0]["w"]["mu"] = qv(&big);
            let e = refused_exactly(&doc, &at);
            assert!(e.reason.starts_with("w:"), "{e}");
            // the radius of the disk grown by tol only is refused too: the
            // writer leaves a gap of tol/64
            let mut doc = f.cert.clone();
            let mu = num(&f.cert["cover"][c][i][0]["w"]["mu"]);
            doc["cover"][c][i][0]["w"]["mu"] = qv(&(mu + &f.tol));
            refused_exactly(&doc, &at);
        }
        let mut doc = f.cert.clone();
        doc["cover"][0][0][0]["w"]["mu"] = json!("-1/2");
        let e = refused_exactly(&doc, "cover[0][0][0]");
        assert!(e.reason.contains("negative"), "{e}");
    }
}

#[test]
fn a_far_outside_disk_is_refused() {
    // B(w, μ) far away is outside S (a true claim), but the part is far
    // from it: the bound is then above tol
    for k in [SEGMENT, CUBIC, TWO] {
        let f = fixture(k);
        for (c, i, _) in kinds(&f.cert) {
            let at = format!("cover[{c}][{i}][0]");
            for (w, mu) in [(["100", "100"], "0"), (["-7", "1/3"], "1")] {
                let mut doc = f.cert.clone();
                doc["cover"][c][i][0]["w"] = json!({"at": w, "mu": mu});
                let e = refused_exactly(&doc, &at);
                assert!(e.reason.contains("above the tolerance"), "{e}");
            }
        }
    }
}

#[test]
fn a_moved_inside_disk_is_refused() {
    for k in [SEGMENT, CUBIC] {
        let f = fixture(k);
        for (c, i, _) in kinds(&f.cert) {
            let at = format!("cover[{c}][{i}][0]");
            let o = &f.cert["cover"][c][i][0]["o"];
            if let Some(j) = o.get("segment") {
                // a disk at the end of the straight piece farther from the
                // part leaves the part far from the disk
                let ju = j.as_u64().unwrap() as usize;
                let fin = fpts(&f.curve[ju]);
                // (the outside disk's centre lies off the part's middle)
                let w = &f.cert["cover"][c][i][0]["w"]["at"];
                let m = (num(&w[0]).approx(), num(&w[1]).approx());
                let far = if dist(m, fin[0]) > dist(m, fin[fin.len() - 1]) {
                    "0"
                } else {
                    "1"
                };
                let mut doc = f.cert.clone();
                doc["cover"][c][i][0]["o"] = json!({"piece": j, "u": far});
                let e = refused_exactly(&doc, &at);
                assert!(e.reason.contains("above the tolerance"), "{e}");
                let mut doc = f.cert.clone();
                doc["cover"][c][i][0]["o"] = json!({"segment": 7});
                let e = refused_exactly(&doc, &at);
                assert!(e.reason.contains("o.segment"), "{e}");
                continue;
            }
            // the capsule about a curved piece's chord is not in S: refused
            // for the piece, whatever the part
            let mut doc = f.cert.clone();
            doc["cover"][c][i][0]["o"] = json!({"segment": o["piece"]});
            let e = refused_exactly(&doc, &at);
            assert_eq!(
                e.reason.contains("not straight"),
                k == CUBIC,
                "{}: {e}",
                f.name
            );
            let u = num(&o["u"]);
            // to the far end of the piece: the part is then far from B(y, r)
            let far = if u.approx() < 0.5 { "1" } else { "0" };
            let mut doc = f.cert.clone();
            doc["cover"][c][i][0]["o"]["u"] = json!(far);
            let e = refused_exactly(&doc, &at);
            assert!(e.reason.contains("above the tolerance"), "{e}");
            let mut doc = f.cert.clone();
            doc["cover"][c][i][0]["o"]["u"] = json!("2");
            let e = refused_exactly(&doc, &at);
            assert!(e.reason.contains("o.u"), "{e}");
            let mut doc = f.cert.clone();
            doc["cover"][c][i][0]["o"]["piece"] = json!(7);
            let e = refused_exactly(&doc, &at);
            assert!(e.reason.contains("o.piece"), "{e}");
        }
    }
}

/// Every point of the outline moved by `(dx, 0)`.
fn translate_outline(doc: &mut Value, dx: &Rational) {
    let shift = |p: &mut Value| {
        let x = num(&p[0]);
        p[0] = qv(&(x + dx));
    };
    for c in arr(&mut doc["outline"]) {
        for piece in arr(c) {
            if let Some(b) = piece.get_mut("bezier") {
                for p in arr(b) {
                    shift(p);
                }
            } else {
                let a = &mut piece["arc"];
                for key in ["center", "from", "to"] {
                    shift(&mut a[key]);
                }
            }
        }
    }
}

#[test]
fn a_translated_outline_is_refused() {
    for k in 0..CASES.len() {
        let f = fixture(k);
        let mut doc = f.cert.clone();
        translate_outline(&mut doc, &(&f.tol * Rational::from_integer(3.into())));
        let e = refused_at(&doc, "cover[");
        assert!(e.reason.contains("above the tolerance"), "{}: {e}", f.name);
        // the translation itself keeps the document well-formed: by tol/1000
        // the outline is still within tol of ∂S (a check of the edit, not of
        // the checker)
        let mut doc = f.cert.clone();
        translate_outline(&mut doc, &(&f.tol / Rational::from_integer(1000.into())));
        if let Err(e) = check(&doc) {
            // refused only where a bound was already close to tol
            assert!(e.reason.contains("above the tolerance"), "{}: {e}", f.name);
        }
    }
}

#[test]
fn an_open_outline_contour_is_refused_at_the_outline() {
    for k in [SEGMENT, CUBIC, SQUARE, TWO] {
        let f = fixture(k);
        for (c, i, _) in kinds(&f.cert) {
            let n = f.cert["outline"][c].as_array().unwrap().len();
            // a piece removed: the next one does not start where the previous ends
            let mut doc = f.cert.clone();
            arr(&mut doc["outline"][c]).remove(i);
            let e = refused_at(&doc, &format!("outline[{c}]["));
            assert!(e.reason.contains("not closed"), "{e}");
            assert_eq!(e.at, format!("outline[{c}][{}]", i % (n - 1)));
        }
        // one end point moved by 1/1000: the joint is exact
        let (c, i, _) = kinds(&f.cert).into_iter().find(|x| !x.2).unwrap();
        let n = f.cert["outline"][c].as_array().unwrap().len();
        let mut doc = f.cert.clone();
        let b = &mut doc["outline"][c][i]["bezier"];
        let last = arr(b).len() - 1;
        let x = num(&b[last][0]);
        b[last][0] = qv(&(x + q("1/1000")));
        refused_exactly(&doc, &format!("outline[{c}][{}]", (i + 1) % n));
        // an empty contour, no contours
        let mut doc = f.cert.clone();
        doc["outline"][0] = json!([]);
        refused_exactly(&doc, "outline[0]");
        let mut doc = f.cert.clone();
        doc["outline"] = json!([]);
        refused_exactly(&doc, "outline");
    }
}

#[test]
fn an_arc_end_off_its_circle_is_refused() {
    let f = fixture(SEGMENT);
    let (c, i, _) = kinds(&f.cert).into_iter().find(|x| x.2).unwrap();
    let mut doc = f.cert.clone();
    let r = num(&doc["outline"][c][i]["arc"]["radius"]);
    doc["outline"][c][i]["arc"]["radius"] = qv(&(r + q("1/1000")));
    let e = refused_exactly(&doc, &format!("outline[{c}][{i}].arc"));
    assert!(e.reason.contains("not exactly on the circle"), "{e}");
    let mut doc = f.cert.clone();
    doc["outline"][c][i]["arc"]["clockwise"] = json!("false");
    refused_exactly(&doc, &format!("outline[{c}][{i}].arc.clockwise"));
    // the other way round the circle: the cover's parts no longer fit
    let mut doc = f.cert.clone();
    let cw = doc["outline"][c][i]["arc"]["clockwise"].as_bool().unwrap();
    doc["outline"][c][i]["arc"]["clockwise"] = json!(!cw);
    refused_at(&doc, &format!("cover[{c}][{i}]"));
}

/// One edit of a document.
type Edit = dyn Fn(&mut Value);

#[test]
fn unknown_keys_and_noncanonical_numbers_are_refused_at_their_field() {
    let f = fixture(SEGMENT);
    let cases: Vec<(&Edit, &str)> = vec![
        (&|d| d["extra"] = json!(1), "extra"),
        (
            &|d| d["cover"][0][0][0]["note"] = json!("x"),
            "cover[0][0][0].note",
        ),
        (
            &|d| d["cover"][0][0][0]["w"]["r"] = json!("1"),
            "cover[0][0][0].w.r",
        ),
        (
            &|d| d["boundary"][0]["boxes"][0]["extra"] = json!(0),
            "boundary[0].boxes[0].extra",
        ),
        (&|d| d["boundary"][0]["k"] = json!(0), "boundary[0].k"),
        (
            &|d| d["outline"][0][0]["arc"] = json!(null),
            "outline[0][0].arc",
        ),
        (&|d| d["tol"] = json!("0.1"), "tol"),
        (&|d| d["tol"] = json!(0.1), "tol"),
        (&|d| d["tol"] = json!("2/20"), "tol"),
        (&|d| d["tol"] = json!("0"), "tol"),
        (&|d| d["radius"] = json!("1/1"), "radius"),
        (&|d| d["radius"] = json!("+1"), "radius"),
        (&|d| d["radius"] = json!(1), "radius"),
        (
            &|d| d["boundary"][0]["boxes"][0]["t"][1] = json!("0.5"),
            "boundary[0].boxes[0].t[1]",
        ),
        (
            &|d| d["boundary"][0]["boxes"][0]["t"][1] = json!("2/4"),
            "boundary[0].boxes[0].t[1]",
        ),
        (
            &|d| d["boundary"][0]["boxes"][0]["t"][0] = json!("-0"),
            "boundary[0].boxes[0].t[0]",
        ),
        (&|d| d["curve"][0][1][0] = json!("04"), "curve[0][1][0]"),
        (&|d| d["curve"][0][1][0] = json!("4.0"), "curve[0][1][0]"),
        (
            &|d| d["cover"][0][0][0]["w"]["mu"] = json!(0),
            "cover[0][0][0].w.mu",
        ),
        (
            &|d| d["cover"][0][0][0]["o"]["piece"] = json!("0"),
            "cover[0][0][0].o.piece",
        ),
        (&|d| d["version"] = json!(2), "version"),
        (&|d| d["version"] = json!("1"), "version"),
        (
            &|d| d["claim"] = json!("hausdorff(outline, curve) <= tol"),
            "claim",
        ),
        (
            &|d| d["format"] = json!("lncert-stroke-certificat"),
            "format",
        ),
    ];
    // the edited fields hold what the edits assume
    assert_eq!(f.cert["boundary"][0]["boxes"][0]["t"][1], json!("1/2"));
    assert_eq!(f.cert["curve"][0][1][0], json!("4"));
    for (edit, at) in cases {
        let mut doc = f.cert.clone();
        edit(&mut doc);
        refused_exactly(&doc, at);
    }
    // a missing key, a duplicate key (written by hand: a JSON map cannot hold one)
    let mut doc = f.cert.clone();
    arr_obj(&mut doc).remove("cover");
    refused_exactly(&doc, "cover");
    let text = f.cert.to_string();
    let tol = rational_to_string(&f.tol);
    let dup = text.replacen(
        &format!("\"tol\":\"{tol}\""),
        &format!("\"tol\":\"1\",\"tol\":\"{tol}\""),
        1,
    );
    assert_ne!(dup, text);
    let e = verify(&dup).unwrap_err();
    assert!(e.at.contains("tol"), "{e}");
}

#[test]
fn a_changed_curve_is_refused() {
    // the cubic's first inner control point moved by 1/2
    let f = fixture(CUBIC);
    for (p, coord) in [(1, 0), (1, 1), (2, 1), (3, 0)] {
        let mut doc = f.cert.clone();
        let x = num(&doc["curve"][0][p][coord]);
        doc["curve"][0][p][coord] = qv(&(x + q("1/2")));
        refused_at(&doc, "cover[");
    }
    // the segment lengthened by 1/2 (every witness y = x(u) moves along it)
    let f = fixture(SEGMENT);
    let mut doc = f.cert.clone();
    doc["curve"][0][1][0] = json!("9/2");
    refused_at(&doc, "cover[");
    // a piece added far away: the families change (two more sides, caps)
    let mut doc = f.cert.clone();
    arr(&mut doc["curve"]).push(json!([["10", "10"], ["11", "10"]]));
    refused(&doc);
    // the two segments' curve joined into a polyline: the cones change
    let f = fixture(TWO);
    let mut doc = f.cert.clone();
    doc["curve"][1][0] = json!(["4", "0"]);
    refused(&doc);
    // a zero end tangent, a piece of one point
    let f = fixture(SEGMENT);
    let mut doc = f.cert.clone();
    doc["curve"][0] = json!([["0", "0"], ["0", "0"], ["4", "0"]]);
    refused_exactly(&doc, "curve[0]");
    let mut doc = f.cert.clone();
    doc["curve"][0] = json!([["0", "0"]]);
    refused_exactly(&doc, "curve[0]");
}

#[test]
fn near_boxes_pointing_elsewhere_are_refused_at_the_box() {
    let f = fixture(SEGMENT);
    let ks = kinds(&f.cert);
    let fams = f.cert["boundary"].as_array().unwrap();
    let mut tried = 0;
    for (fam, b) in fams.iter().enumerate() {
        for (i, bx) in b["boxes"].as_array().unwrap().iter().enumerate() {
            let Some(near) = bx.get("near") else { continue };
            let at = format!("boundary[{fam}].boxes[{i}]");
            let (c, p) = (
                near["contour"].as_u64().unwrap() as usize,
                near["piece"].as_u64().unwrap() as usize,
            );
            // another piece of the same kind (the other side, the other cap)
            let other = ks
                .iter()
                .find(|x| x.0 == c && x.1 != p && x.2 == ks.iter().find(|y| y.1 == p).unwrap().2)
                .unwrap();
            let mut doc = f.cert.clone();
            doc["boundary"][fam]["boxes"][i]["near"]["piece"] = json!(other.1);
            refused_exactly(&doc, &at);
            // a piece the outline does not have, a contour it does not have
            let mut doc = f.cert.clone();
            doc["boundary"][fam]["boxes"][i]["near"]["piece"] = json!(ks.len());
            refused_exactly(&doc, &at);
            let mut doc = f.cert.clone();
            doc["boundary"][fam]["boxes"][i]["near"]["contour"] = json!(1);
            refused_exactly(&doc, &at);
            if near.get("s").is_some() {
                // the foot moved to the far end of the Bézier
                let s = num(&near["s"]);
                let far = if s.approx() < 0.5 { "1" } else { "0" };
                let mut doc = f.cert.clone();
                doc["boundary"][fam]["boxes"][i]["near"]["s"] = json!(far);
                refused_exactly(&doc, &at);
                // the near claim turned into an `inside` claim: the box is on ∂S
                let mut doc = f.cert.clone();
                doc["boundary"][fam]["boxes"][i] = json!({
                    "t": bx["t"].clone(),
                    "inside": {"piece": 0, "u": "1/2"},
                });
                refused_exactly(&doc, &at);
            }
            tried += 1;
        }
    }
    assert!(tried >= 10, "{tried}");
}

#[test]
fn cover_contours_must_match_the_outline() {
    let f = fixture(TWO);
    // exchanged: each contour's parts are the other's, 3 away
    let mut doc = f.cert.clone();
    arr(&mut doc["cover"]).swap(0, 1);
    refused_at(&doc, "cover[0]");
    let mut doc = f.cert.clone();
    arr(&mut doc["cover"]).pop();
    refused_exactly(&doc, "cover");
    let mut doc = f.cert.clone();
    arr(&mut doc["cover"][0]).pop();
    refused_exactly(&doc, "cover[0]");
    let mut doc = f.cert.clone();
    let extra = doc["cover"][0][0].clone();
    arr(&mut doc["cover"][0]).push(extra);
    refused_exactly(&doc, "cover[0]");
}

// ---- 3. a cross-check of the outline against ∂S, independent of the checker ----

#[test]
fn outline_samples_are_within_tol_of_the_stroke_boundary() {
    let f = fixture(CUBIC);
    assert_eq!(f.r, q("1/2"));
    assert_eq!(f.tol, q("1/20"));
    let v = check(&f.cert).unwrap();
    assert!(v.max_bound <= 0.05);
    let (r, tol) = (f.r.approx(), f.tol.approx());
    // the curve, densely
    let mut xs: Vec<F2> = Vec::new();
    for b in &f.curve {
        let p = fpts(b);
        xs.extend((0..=20_000).map(|k| casteljau(&p, k as f64 / 20_000.0)));
    }
    // |dist(q, x) − r| ≤ dist(q, ∂S) ≤ tol for every outline point q
    let mut worst = 0.0f64;
    let mut n = 0;
    for c in &f.stroke.contours {
        for piece in &c.pieces {
            for qp in piece.sample(400) {
                let d = xs
                    .iter()
                    .map(|&x| dist(x, qp))
                    .fold(f64::INFINITY, f64::min);
                worst = worst.max((d - r).abs());
                n += 1;
            }
        }
    }
    assert!(n >= 6 * 401, "{n}");
    assert!(worst <= tol + 1e-9, "an outline point {worst} off r");
    // the outline is not a trivial one: it does reach around the curve
    assert!(worst < tol / 4.0, "{worst}");
}

#[test]
fn stroke_boundary_samples_are_within_tol_of_the_outline() {
    // the converse direction for the cubic, whose raw boundary (both offsets,
    // both caps) is all of ∂S: no offset folds (curvature radius ≥ 1.6 > r)
    let f = fixture(CUBIC);
    let (r, tol) = (f.r.approx(), f.tol.approx());
    let p = fpts(&f.curve[0]);
    let mut bd: Vec<F2> = Vec::new();
    for sigma in [1.0, -1.0] {
        bd.extend((0..=500).map(|k| offset_point(&p, k as f64 / 500.0, sigma, r)));
    }
    for (y, t) in [(p[0], deriv(&p, 0.0)), (p[3], deriv(&p, 1.0))] {
        // the cap: directions in the half plane away from the curve
        let out = if y == p[0] { -1.0 } else { 1.0 };
        let l = t.0.hypot(t.1);
        let (tx, ty) = (out * t.0 / l, out * t.1 / l);
        for k in 0..=100 {
            let phi = -std::f64::consts::FRAC_PI_2 + std::f64::consts::PI * k as f64 / 100.0;
            let (c, s) = (phi.cos(), phi.sin());
            bd.push((y.0 + r * (c * tx - s * ty), y.1 + r * (c * ty + s * tx)));
        }
    }
    // the outline as a fine polyline (its chords sag by under 1e-6)
    let poly: Vec<Vec<F2>> = f
        .stroke
        .contours
        .iter()
        .flat_map(|c| c.pieces.iter().map(|p| p.sample(1000)))
        .collect();
    let mut worst = 0.0f64;
    for &b in &bd {
        let d = poly
            .iter()
            .flat_map(|pl| pl.windows(2).map(move |w| seg_dist(b, w[0], w[1])))
            .fold(f64::INFINITY, f64::min);
        worst = worst.max(d);
    }
    assert!(
        worst <= tol + 1e-6,
        "a boundary point {worst} from the outline"
    );
}

/// Float distance from `p` to the input curve: exact for segments, a fine
/// polyline (chords sagging by under 1e-6) for curved pieces.
fn dist_to_curve(curve: &[Vec<F2>], p: F2) -> f64 {
    curve
        .iter()
        .map(|b| {
            if b.len() == 2 {
                return seg_dist(p, b[0], b[1]);
            }
            let pl: Vec<F2> = (0..=2000)
                .map(|k| casteljau(b, k as f64 / 2000.0))
                .collect();
            pl.windows(2)
                .map(|w| seg_dist(p, w[0], w[1]))
                .fold(f64::INFINITY, f64::min)
        })
        .fold(f64::INFINITY, f64::min)
}

#[test]
fn the_families_hold_the_sampled_stroke_boundary() {
    // ∂S sampled without the checker: points y + r·e (y on the curve, e its
    // two normals and 48 directions) whose distance to the curve is r; each
    // must lie on one of the families the checker derives from the curve
    for k in [CORNER, CUBIC, SQUARE, TWO] {
        let f = fixture(k);
        let r = f.r.approx();
        let curve: Vec<Vec<F2>> = f.curve.iter().map(fpts).collect();
        let exact: Vec<Vec<super::Q2>> = f.curve.iter().map(super::exact_points).collect();
        let fams = super::Input::new(exact, f.r.clone(), "curve")
            .unwrap()
            .families();
        let polys: Vec<Vec<F2>> = fams
            .iter()
            .map(|fam| {
                (0..=500)
                    .map(|m| {
                        let t = super::geom::ic(m as f64 / 500.0);
                        let v = fam.path.val(t).expect("a regular family");
                        (
                            0.5 * (v[0].inf() + v[0].sup()),
                            0.5 * (v[1].inf() + v[1].sup()),
                        )
                    })
                    .collect()
            })
            .collect();
        let (mut on, mut worst) = (0, 0.0f64);
        for b in &curve {
            for m in 0..=50 {
                let u = m as f64 / 50.0;
                let y = casteljau(b, u);
                // both normals, and 48 directions (the caps and joins)
                let mut ps = vec![offset_point(b, u, 1.0, r), offset_point(b, u, -1.0, r)];
                for e in 0..48 {
                    let a = std::f64::consts::TAU * (e as f64 + 0.5) / 48.0;
                    ps.push((y.0 + r * a.cos(), y.1 + r * a.sin()));
                }
                for p in ps {
                    if dist_to_curve(&curve, p) < r - 2e-6 {
                        continue;
                    }
                    on += 1;
                    let d = polys
                        .iter()
                        .flat_map(|pl| pl.windows(2).map(move |w| seg_dist(p, w[0], w[1])))
                        .fold(f64::INFINITY, f64::min);
                    worst = worst.max(d);
                }
            }
        }
        assert!(on >= 100, "{}: {on} boundary samples", f.name);
        assert!(
            worst < 1e-3,
            "{}: a boundary point {worst} off the families",
            f.name
        );
    }
}

// ---- the interval tests of geom.rs at their edges ----

mod geom_edges {
    use super::super::geom::{
        inside, ip, iq, near_arc, near_bezier, outside_near, part_bound, Bez, BoxT, ConeArc, Core,
        Path, P,
    };
    use super::super::OPiece;
    use super::q;
    use crate::scalar::Interval;

    fn pt(x: &str, y: &str) -> P {
        ip(&[q(x), q(y)])
    }
    fn bez(p: &[(&str, &str)]) -> Bez {
        Bez::with_distance_form(p.iter().map(|(x, y)| pt(x, y)).collect())
    }
    fn bx(t0: &str, t1: &str) -> BoxT {
        BoxT::new(&q(t0), &q(t1))
    }
    fn sq(x: &str) -> Interval {
        iq(&q(x)).sqr()
    }
    /// The segment `a + t (b − a)`.
    struct Line(P, P);
    impl Path for Line {
        fn val(&self, t: Interval) -> Option<P> {
            Some([
                self.0[0] + (self.1[0] - self.0[0]) * t,
                self.0[1] + (self.1[1] - self.0[1]) * t,
            ])
        }
        fn der(&self, _: Interval) -> Option<P> {
            Some([self.1[0] - self.0[0], self.1[1] - self.0[1]])
        }
    }
    fn arc_t(from: (&str, &str), to: (&str, &str), clockwise: bool) -> super::super::geom::ArcT {
        let c = [q("0"), q("0")];
        let f = [q(from.0), q(from.1)];
        let t = [q(to.0), q(to.1)];
        match OPiece::arc(c, q("1"), f, t, clockwise).unwrap() {
            OPiece::Arc { t, .. } => *t,
            OPiece::Bezier { .. } => unreachable!(),
        }
    }
    fn cone(a: (&str, &str), b: (&str, &str)) -> ConeArc {
        ConeArc {
            c: pt("0", "0"),
            r: iq(&q("1")),
            a: pt(a.0, a.1),
            b: pt(b.0, b.1),
        }
    }

    #[test]
    fn near_bezier_needs_the_foot_map_inside_the_piece() {
        // the path (1 + t, 0) over [0, 1]
        let path = Line(pt("1", "0"), pt("2", "0"));
        // on the line of L = [(0, 0), (1, 0)] but past its end: refused
        let l = bez(&[("0", "0"), ("1", "0")]);
        let e = near_bezier(
            &path,
            &bx("0", "1"),
            &l,
            &q("3/2"),
            &q("1"),
            sq("1/10"),
            None,
        );
        assert!(e.unwrap_err().contains("outside [0, 1]"));
        // L = [(0, 0), (2, 0)]: the foot 3/4 + (t − 1/2)/2 ∈ [1/2, 1] is exact
        let l = bez(&[("0", "0"), ("2", "0")]);
        let b = near_bezier(
            &path,
            &bx("0", "1"),
            &l,
            &q("3/4"),
            &q("1/2"),
            sq("1/10"),
            None,
        );
        assert!(b.unwrap() < 1e-12);
        // 1/10 above L: within 11/100, not within 9/100
        let path = Line(pt("1", "1/10"), pt("2", "1/10"));
        let b = near_bezier(
            &path,
            &bx("0", "1"),
            &l,
            &q("3/4"),
            &q("1/2"),
            sq("11/100"),
            None,
        );
        assert!((0.1..0.11).contains(&b.unwrap()));
        let e = near_bezier(
            &path,
            &bx("0", "1"),
            &l,
            &q("3/4"),
            &q("1/2"),
            sq("9/100"),
            None,
        );
        assert!(e.is_err());
        // measured through M = [[1, 1], [0, 2]] (an elliptical pen's
        // pre-images): the offset (0, 1/10) maps to (1/10, 1/5), |·| ≈ 0.2236
        let m = [[iq(&q("1")), iq(&q("1"))], [iq(&q("0")), iq(&q("2"))]];
        let b = near_bezier(
            &path,
            &bx("0", "1"),
            &l,
            &q("3/4"),
            &q("1/2"),
            sq("23/100"),
            Some(&m),
        );
        assert!((0.2236..0.2237).contains(&b.unwrap()));
        let e = near_bezier(
            &path,
            &bx("0", "1"),
            &l,
            &q("3/4"),
            &q("1/2"),
            sq("22/100"),
            Some(&m),
        );
        assert!(e.is_err());
        // a wrong slope k: the foot runs ahead of the path
        let path = Line(pt("1", "0"), pt("2", "0"));
        let e = near_bezier(
            &path,
            &bx("0", "1"),
            &l,
            &q("3/4"),
            &q("1/4"),
            sq("1/10"),
            None,
        );
        assert!(e.is_err());
    }

    /// `near_arc` over 32 boxes of `[0, 1]`: how many pass.
    fn passing(path: &ConeArc, arc: &super::super::geom::ArcT, tol: &str) -> usize {
        (0..32)
            .filter(|k| {
                let b = BoxT::new(
                    &crate::scalar::Rational::new((*k).into(), 32.into()),
                    &crate::scalar::Rational::new((k + 1).into(), 32.into()),
                );
                near_arc(path, &b, arc, iq(&q(tol))).is_ok()
            })
            .count()
    }

    #[test]
    fn near_arc_needs_the_directions_inside_the_arc() {
        // the quarter (1, 0) → (0, 1) counter-clockwise
        let quarter = arc_t(("1", "0"), ("0", "1"), false);
        assert_eq!(
            passing(&cone(("4", "1"), ("1", "4")), &quarter, "1/100"),
            32
        );
        // on the circle, outside the quarter
        assert_eq!(
            passing(&cone(("-1", "4"), ("-4", "1")), &quarter, "1/100"),
            0
        );
        assert_eq!(
            passing(&cone(("4", "-1"), ("1", "-4")), &quarter, "1/100"),
            0
        );
        let e = near_arc(
            &cone(("-1", "4"), ("-4", "1")),
            &bx("0", "1/32"),
            &quarter,
            iq(&q("1/100")),
        );
        assert!(e.unwrap_err().contains("not proven inside"));
        // clockwise (1, 0) → (0, 1): the other three quarters
        let major = arc_t(("1", "0"), ("0", "1"), true);
        assert_eq!(
            passing(&cone(("-1", "4"), ("-4", "1")), &major, "1/100"),
            32
        );
        assert_eq!(
            passing(&cone(("-4", "-1"), ("-1", "-4")), &major, "1/100"),
            32
        );
        assert_eq!(passing(&cone(("4", "1"), ("1", "4")), &major, "1/100"), 0);
        // a half circle (1, 0) → (−1, 0) counter-clockwise: the upper half
        let half = arc_t(("1", "0"), ("-1", "0"), false);
        assert_eq!(passing(&cone(("4", "1"), ("1", "4")), &half, "1/100"), 32);
        assert_eq!(passing(&cone(("-1", "4"), ("-4", "1")), &half, "1/100"), 32);
        assert_eq!(passing(&cone(("4", "-1"), ("1", "-4")), &half, "1/100"), 0);
        assert_eq!(
            passing(&cone(("-1", "-4"), ("-4", "-1")), &half, "1/100"),
            0
        );
        // inside the range but off the circle by 1/50: not within 1/100
        let off = ConeArc {
            c: pt("0", "0"),
            r: iq(&q("51/50")),
            a: pt("4", "1"),
            b: pt("1", "4"),
        };
        assert_eq!(passing(&off, &quarter, "1/100"), 0);
        assert_eq!(passing(&off, &quarter, "1/40"), 32);
    }

    #[test]
    fn inside_is_strict() {
        // the path (2t − 1, 1), y = (0, 0): at t = 1/2 exactly at distance 1
        let path = Line(pt("-1", "1"), pt("1", "1"));
        let y = pt("0", "0");
        assert!(inside(&path, &bx("1/4", "3/4"), y, sq("1")).is_err());
        assert!(inside(&path, &bx("1/2", "9/16"), y, sq("1")).is_err());
        assert!(inside(&path, &bx("1/4", "3/4"), y, sq("3/2")).is_ok());
        // a box that reaches distance √2 > 5/4 somewhere
        assert!(inside(&path, &bx("0", "1"), y, sq("5/4")).is_err());
        // the degenerate box at the tangency: |path − y|² = r² exactly, on
        // ∂B(y, r), not strictly inside
        assert!(inside(&path, &bx("1/2", "1/2"), y, sq("1")).is_err());
        assert!(inside(&path, &bx("1/2", "1/2"), y, sq("101/100")).is_ok());
    }

    #[test]
    fn outside_is_strict() {
        // the hint only orders the work: every hint gives the same verdict,
        // the right one, a wrong one, one at an end, one for another piece
        let outside = |p: P, x: &[Bez], r2: Interval| {
            let v = outside_near(p, x, r2, None);
            for h in [(0, 0.5), (0, 0.25), (0, 0.9), (0, 1e-12), (1, 0.7)] {
                assert_eq!(
                    outside_near(p, x, r2, Some(h)).is_ok(),
                    v.is_ok(),
                    "hint {h:?} changed the verdict"
                );
            }
            v
        };
        let x = [bez(&[("0", "0"), ("4", "0")])];
        // touching the piece's side and its end
        assert!(outside(pt("2", "3/2"), &x, sq("3/2")).is_err());
        assert!(outside(pt("2", "3/2"), &x, sq("7/5")).is_ok());
        assert!(outside(pt("5", "0"), &x, sq("1")).is_err());
        assert!(outside(pt("5", "0"), &x, sq("99/100")).is_ok());
        assert!(outside(pt("2", "0"), &x, sq("1/1000")).is_err());
        // a cubic: the arch's top is at y = 3/2
        let x = [bez(&[("0", "0"), ("1", "2"), ("3", "2"), ("4", "0")])];
        assert!(outside(pt("2", "3"), &x, sq("3/2")).is_err());
        assert!(outside(pt("2", "3"), &x, sq("149/100")).is_ok());
        // every input piece counts
        let x = [
            bez(&[("10", "10"), ("11", "10")]),
            bez(&[("0", "0"), ("4", "0")]),
        ];
        assert!(outside(pt("2", "1/2"), &x, sq("1")).is_err());
    }

    #[test]
    fn part_bound_is_the_larger_gap() {
        let (y, w) = (pt("0", "0"), pt("0", "3"));
        let (r, mu) = (iq(&q("1")), iq(&q("1/2")));
        // q = (0, 2): 2 − 1 = 1 from B(y, 1), 1 − 1/2 from B(w, 1/2)
        let b = part_bound(&vec![pt("0", "2")], Core::Point(y), r, w, mu);
        assert!((1.0..1.0 + 1e-12).contains(&b), "{b}");
        // the worst hull point counts; a hull point inside both disks gives 0
        let b = part_bound(&vec![pt("0", "1"), pt("3", "3")], Core::Point(y), r, w, mu);
        assert!(b >= 10f64.sqrt() - 0.5 - 1e-12 && b >= 3.0 - 0.5, "{b}");
        let b = part_bound(
            &vec![pt("0", "1")],
            Core::Point(pt("0", "0")),
            r,
            pt("0", "3/2"),
            mu,
        );
        assert!((0.0..1e-12).contains(&b), "{b}");
        // q = y: deep inside B(y, r), 3 − 1/2 from B(w, 1/2): the outside
        // disk's gap counts as much as the inside one's
        let b = part_bound(&vec![pt("0", "0")], Core::Point(y), r, w, mu);
        assert!((2.5..2.5 + 1e-12).contains(&b), "{b}");
    }

    #[test]
    fn a_segment_core_measures_to_its_nearest_point() {
        // the capsule of radius 1 about [(0, 0), (4, 0)]; a disk outside far away
        let seg = Core::Segment(pt("0", "0"), pt("4", "0"));
        let (r, mu) = (iq(&q("1")), iq(&q("1000")));
        let w = pt("2", "1002");
        // along the segment the gap to the capsule is the height − 1 (not the
        // distance to one end point): 1/4 over the whole length
        // (the outside disk through the hull point itself: its gap is 0)
        for x in ["0", "1", "7/3", "4"] {
            let h = pt(x, "5/4");
            let b = part_bound(&vec![h], seg, r, h, iq(&q("0")));
            assert!((0.25..0.25 + 1e-9).contains(&b), "{x}: {b}");
        }
        // beyond an end the nearest point is the end point: 5 − 1
        let h = pt("7", "4");
        let b = part_bound(&vec![h], seg, r, h, iq(&q("0")));
        assert!((4.0..4.0 + 1e-9).contains(&b), "{b}");
        // a degenerate segment is a point
        let h = pt("3", "4");
        let b = part_bound(
            &vec![h],
            Core::Segment(pt("0", "0"), pt("0", "0")),
            r,
            h,
            iq(&q("0")),
        );
        assert!((4.0..4.0 + 1e-9).contains(&b), "{b}");
        let _ = (w, mu);
    }
}

/// The per-part and per-box fields are read with paths built only on
/// error; every malformed field is still named exactly, at each depth.
#[test]
fn malformed_part_and_box_fields_are_named_exactly() {
    // "2/4" is not in lowest terms, `true` is not a rational, `{}` not a list
    let bad_values = [json!("2/4"), json!(true)];
    for k in [CUBIC, SQUARE] {
        let f = fixture(k);
        for (c, i, is_arc) in kinds(&f.cert) {
            let part = format!("cover[{c}][{i}][0]");
            let span = if is_arc { "dirs" } else { "s" };
            let o_key = if f.cert["cover"][c][i][0]["o"].get("segment").is_some() {
                "segment"
            } else {
                "u"
            };
            let mut fields: Vec<(Vec<Value>, String)> = vec![
                (vec![json!("w"), json!("mu")], format!("{part}.w.mu")),
                (
                    vec![json!("w"), json!("at"), json!(1)],
                    format!("{part}.w.at[1]"),
                ),
                (vec![json!("o"), json!(o_key)], format!("{part}.o.{o_key}")),
            ];
            if is_arc {
                fields.push((
                    vec![json!(span), json!(1), json!(0)],
                    format!("{part}.dirs[1][0]"),
                ));
            } else {
                fields.push((vec![json!(span), json!(1)], format!("{part}.s[1]")));
            }
            for (path, at) in &fields {
                for bad in &bad_values {
                    let mut doc = f.cert.clone();
                    let mut v = &mut doc["cover"][c][i][0];
                    for key in path {
                        v = match key {
                            Value::String(s) => &mut v[s.as_str()],
                            Value::Number(n) => &mut v[n.as_u64().unwrap() as usize],
                            _ => unreachable!(),
                        };
                    }
                    *v = bad.clone();
                    refused_exactly(&doc, at);
                }
            }
            // a missing key and an unknown key are named under the part
            let mut doc = f.cert.clone();
            doc["cover"][c][i][0]["o"]
                .as_object_mut()
                .unwrap()
                .remove(o_key);
            refused_exactly(
                &doc,
                &format!("{part}.o.{}", if o_key == "u" { "u" } else { "piece" }),
            );
            let mut doc = f.cert.clone();
            doc["cover"][c][i][0]["w"]["extra"] = json!(1);
            refused_exactly(&doc, &format!("{part}.w.extra"));
            // a part that is not an object is named by its index
            let mut doc = f.cert.clone();
            doc["cover"][c][i][0] = json!([]);
            refused_exactly(&doc, &part);
        }
        // the boxes: the first box of each kind, every field
        for (fam, fv) in f.cert["boundary"].as_array().unwrap().iter().enumerate() {
            for (b, bx) in fv["boxes"].as_array().unwrap().iter().enumerate() {
                let at = format!("boundary[{fam}].boxes[{b}]");
                let keys: Vec<(&str, &str)> = if bx.get("inside").is_some() {
                    vec![("inside", "u"), ("inside", "piece")]
                } else if bx["near"].get("s").is_some() {
                    vec![("near", "s"), ("near", "k"), ("near", "contour")]
                } else {
                    vec![("near", "piece")]
                };
                for (outer, inner) in keys {
                    let mut doc = f.cert.clone();
                    doc["boundary"][fam]["boxes"][b][outer][inner] = json!(true);
                    refused_exactly(&doc, &format!("{at}.{outer}.{inner}"));
                }
                let mut doc = f.cert.clone();
                doc["boundary"][fam]["boxes"][b]["t"][1] = json!("2/4");
                refused_exactly(&doc, &format!("{at}.t[1]"));
                let mut doc = f.cert.clone();
                doc["boundary"][fam]["boxes"][b]["t"] = json!({});
                refused_exactly(&doc, &format!("{at}.t"));
            }
        }
    }
}

/// An arc part must turn counter-clockwise by less than a right angle: a
/// part that turns clockwise, by exactly π/2, or not at all is refused at
/// its `dirs` (the interval filter of that sign test decides none of these
/// wrongly; the exact products settle the boundary cases).
#[test]
fn an_arc_part_turning_the_wrong_way_is_refused() {
    let f = fixture(CUBIC);
    let mut tried = 0;
    for (c, i, is_arc) in kinds(&f.cert) {
        if !is_arc {
            continue;
        }
        let d = &f.cert["cover"][c][i][0]["dirs"];
        let (d0, d1) = (
            [num(&d[0][0]), num(&d[0][1])],
            [num(&d[1][0]), num(&d[1][1])],
        );
        let two = Rational::from_integer(2.into());
        let k = &two * (&d0[0] * &d1[0] + &d0[1] * &d1[1]) / (&d0[0] * &d0[0] + &d0[1] * &d0[1]);
        // d1 mirrored in d0: the same angle, clockwise
        let mirrored = [&k * &d0[0] - &d1[0], &k * &d0[1] - &d1[1]];
        // d0 turned by exactly π/2, and d0 itself
        let right = [-d0[1].clone(), d0[0].clone()];
        for bad in [mirrored, right, d0.clone()] {
            let mut doc = f.cert.clone();
            doc["cover"][c][i][0]["dirs"][1] = json!([qv(&bad[0]), qv(&bad[1])]);
            let e = refused_exactly(&doc, &format!("cover[{c}][{i}][0].dirs"));
            assert!(e.reason.contains("less than π/2"), "{e}");
            tried += 1;
        }
    }
    assert!(tried >= 3, "the fixture has arc parts");
}

/// A xorshift generator (deterministic test data without a dependency).
fn xorshift(mut state: u64) -> impl FnMut() -> u64 {
    move || {
        state ^= state << 13;
        state ^= state >> 7;
        state ^= state << 17;
        state
    }
}

/// The top 53 bits of `x` as a float in `[0, 1)`.
fn unit(x: u64) -> f64 {
    (x >> 11) as f64 / (1u64 << 53) as f64
}

/// The checker's interval evaluation of a Bézier and its hodograph over a
/// parameter box encloses every exact point (rational evaluation at rational
/// parameters of the box), and its width depends on the control polygon's
/// shape, not on how far the curve lies from the origin: the same cubic
/// moved by (1000, −700) gets an enclosure at most a rounding wider (the form
/// `(1 − t) b_i + t b_{i+1}` made it ~100× wider there, so boxes far from the
/// origin had to be ~10× narrower).
#[test]
fn box_evaluation_encloses_exact_points_and_ignores_translation() {
    use super::geom::{ip, Bez};
    use crate::scalar::Interval;
    let mut bits = xorshift(0x9e37_79b9_7f4a_7c15);
    let mut next = move || unit(bits());
    let width = |p: [Interval; 2]| (p[0].wid()).max(p[1].wid());
    for _ in 0..200 {
        let pts: Vec<[Rational; 2]> = (0..4)
            .map(|_| {
                [
                    crate::scalar::rational_from_f64(4.0 * next() - 2.0).unwrap(),
                    crate::scalar::rational_from_f64(4.0 * next() - 2.0).unwrap(),
                ]
            })
            .collect();
        let (dx, dy) = (q("1000"), q("-700"));
        let moved: Vec<[Rational; 2]> = pts.iter().map(|p| [&p[0] + &dx, &p[1] + &dy]).collect();
        let b = Bez::new(pts.iter().map(ip).collect());
        let m = Bez::new(moved.iter().map(ip).collect());
        let t0 = (next() * 64.0).floor() / 64.0;
        let w = 1.0 / 8.0;
        let t1 = (t0 + w).min(1.0);
        let box_t = Interval::try_from((t0, t1)).unwrap();
        // translation invariance of the enclosure's width (up to rounding at 1000)
        assert!(
            width(m.at(box_t)) <= width(b.at(box_t)) + 1e-9,
            "moved: {} vs {}",
            width(m.at(box_t)),
            width(b.at(box_t))
        );
        assert!(width(m.d_at(box_t)) <= width(b.d_at(box_t)) + 1e-9);
        // soundness: exact points of the box inside the enclosures
        let exact = Bezier::new(
            moved
                .iter()
                .map(|p| crate::curve::V2::new(p[0].clone(), p[1].clone()))
                .collect(),
        );
        let hodo = exact.hodograph();
        let (e, d) = (m.at(box_t), m.d_at(box_t));
        for k in 0..=16 {
            let t = crate::scalar::rational_from_f64(t0).unwrap()
                + crate::scalar::rational_from_f64(t1 - t0).unwrap()
                    * Rational::new(k.into(), 16.into());
            let (p, v) = (exact.eval(&t), hodo.eval(&t));
            use crate::scalar::IntervalExt;
            assert!(e[0].contains_rational(&p.x) && e[1].contains_rational(&p.y));
            assert!(d[0].contains_rational(&v.x) && d[1].contains_rational(&v.y));
        }
    }
}

/// The outside test's float box filter (`geom::box_farther`) never calls a
/// box farther than `√r2` when its exact squared distance from some point
/// of `p` is at most `r2` — here `r2` is the tightest enclosure of that exact
/// distance, the hardest case for rounding — and does call it farther when
/// `r2` is a little smaller (so the filter is not vacuous).
#[test]
fn box_filter_is_sound_at_the_exact_distance() {
    use super::geom::box_farther;
    use crate::scalar::{interval_from_rational, rational_from_f64, Interval};
    let mut bits = xorshift(0x2545_f491_4f6c_dd1d);
    let mut next = move || unit(bits());
    let rq = |x: f64| rational_from_f64(x).unwrap();
    let mut farther = 0;
    for k in 0..4000 {
        let scale = [1e-3, 1.0, 1e3, 1e6][k % 4];
        let c = [1000.0 * (next() - 0.5), 1000.0 * (next() - 0.5)];
        let lo = [c[0] + scale * next(), c[1] + scale * next()];
        let hi = [lo[0] + scale * next(), lo[1] + scale * next()];
        // a point interval or a short one, on either side of the box
        let pt = |i: usize, u: f64, w: f64| {
            let a = c[i] + scale * 4.0 * (u - 0.5);
            Interval::try_from((a, a + w)).unwrap()
        };
        let w = if k % 3 == 0 {
            0.0
        } else {
            scale * 1e-3 * next()
        };
        let p = [pt(0, next(), w), pt(1, next(), w)];
        // the exact squared distance from the nearest point of p to the box
        let gap = |i: usize| {
            let below = rq(lo[i]) - rq(p[i].sup());
            let above = rq(p[i].inf()) - rq(hi[i]);
            let z = Rational::from_integer(0.into());
            below.max(above).max(z)
        };
        let e = gap(0) * gap(0) + gap(1) * gap(1);
        let r2 = interval_from_rational(&e);
        assert!(
            !box_farther(lo, hi, p, r2),
            "box {lo:?}–{hi:?} called farther than its exact distance from {p:?}"
        );
        if e > Rational::from_integer(0.into()) {
            let smaller = interval_from_rational(&(e * Rational::new(999.into(), 1000.into())));
            if box_farther(lo, hi, p, smaller) {
                farther += 1;
            }
        }
    }
    assert!(farther > 1000, "the filter decided only {farther} boxes");
}

/// The verifier's restriction of a Bézier to `[a, b]` (two de Casteljau
/// splits, the second at `a / b`) encloses the exact restricted control
/// points, computed here independently as the blossom values
/// `B(a^{n−k} b^k)` (each its own de Casteljau run with `n − k` steps at `a`
/// and `k` at `b`, in exact rationals), for degrees 1 to 5 and rational ends
/// that are not floats (`a`, `b` with denominators 3, 7).
#[test]
fn restriction_encloses_the_exact_blossom_values() {
    use super::geom::{ip, iq, Bez};
    use crate::scalar::IntervalExt;
    let mut bits = xorshift(0x9e37_79b9_7f4a_7c15);
    let mut next = move |m: u64| bits() % m;
    let r = |n: i64, d: i64| Rational::new(n.into(), d.into());
    for case in 0..300 {
        let deg = 1 + (case % 5);
        let pts: Vec<[Rational; 2]> = (0..=deg)
            .map(|_| {
                [
                    r(next(20001) as i64 - 10000, 1 + next(997) as i64),
                    r(next(20001) as i64 - 10000 + 3000, 1 + next(997) as i64),
                ]
            })
            .collect();
        let (d1, d2) = (3 * (1 + next(50) as i64), 7 * (1 + next(50) as i64));
        let (x, y) = (r(next(d1 as u64) as i64, d1), r(next(d2 as u64) as i64, d2));
        let (a, b) = if x < y {
            (x, y)
        } else if y < x {
            (y, x)
        } else {
            continue;
        };
        let b_iv = Bez::new(pts.iter().map(ip).collect());
        let hull = b_iv.restrict(iq(&a), iq(&b));
        assert_eq!(hull.len(), deg + 1);
        for (k, h) in hull.iter().enumerate() {
            let mut q = pts.clone();
            for level in 0..deg {
                let t = if level < deg - k { &a } else { &b };
                let u = r(1, 1) - t;
                for i in 0..(deg - level) {
                    q[i] = [
                        &q[i][0] * &u + &q[i + 1][0] * t,
                        &q[i][1] * &u + &q[i + 1][1] * t,
                    ];
                }
            }
            assert!(
                h[0].contains_rational(&q[0][0]) && h[1].contains_rational(&q[0][1]),
                "degree {deg}, [{a}, {b}], control point {k}: {:?} misses ({}, {})",
                h,
                q[0][0],
                q[0][1]
            );
        }
    }
}

/// `on_chord` (whether a piece is straight) decides curved pieces in
/// intervals and the rest exactly: points exactly on the chord with
/// non-dyadic coordinates are straight, a point moved off it by far less than
/// an interval's width is not, and a clearly curved piece is not.
#[test]
fn straight_pieces_are_decided_exactly() {
    use super::geom::ip;
    let q = |n: i64, d: i64| Rational::new(n.into(), d.into());
    let check = |pts: &[[Rational; 2]]| {
        let iv: Vec<_> = pts.iter().map(ip).collect();
        super::on_chord(pts, &iv)
    };
    for k in 1..40i64 {
        // p(s) = a + s (b − a) at s = k/41 and s = 2k/83: on the chord
        let (a, b) = ([q(1, 3), q(-2, 7)], [q(5 * k, 9), q(k, 11)]);
        let on = |s: Rational| [&a[0] + &s * (&b[0] - &a[0]), &a[1] + &s * (&b[1] - &a[1])];
        let (m1, m2) = (on(q(k, 41)), on(q(2 * k, 83)));
        assert!(
            check(&[a.clone(), m1.clone(), m2.clone(), b.clone()]),
            "k = {k}"
        );
        // off the chord by 10⁻⁴⁰ (inside every interval's rounding)
        let mut off = m1.clone();
        off[1] += q(1, 10).pow(40);
        assert!(!check(&[a.clone(), off, m2.clone(), b.clone()]), "k = {k}");
        // clearly curved
        let mut bent = m2.clone();
        bent[0] += q(1, 2);
        assert!(!check(&[a.clone(), m1, bent, b.clone()]), "k = {k}");
    }
}

/// Claim (c) is checked on the certificate's own parts: a copy of the
/// outline's only contour (and of its cover) leaves claims (a) and (b) true —
/// every part is still near `∂S`, and `∂S` near the first copy — but the two
/// copies are not apart, so a certificate that claims a simple outline is
/// refused at `simple`; without the claim it is accepted, and claim (c) is
/// then not stated.
#[test]
fn a_doubled_contour_is_not_simple() {
    let f = fixture(SQUARE);
    assert_eq!(f.cert["simple"], true);
    let mut doc = f.cert.clone();
    for key in ["outline", "cover"] {
        let first = arr(&mut doc[key])[0].clone();
        arr(&mut doc[key]).push(first);
    }
    let e = refused_exactly(&doc, "simple");
    assert!(e.reason.contains("claimed, but"), "{}", e.reason);
    doc["simple"] = json!(false);
    let v = check(&doc).expect("(a) and (b) hold for the doubled outline");
    assert!(v.a.contains("simplicity not claimed"), "{}", v.a);
}

/// The work budget: a genuine certificate verifies within its size's budget
/// (using a small fraction of it), and the same certificate is refused as
/// too costly under a budget below the work it needs.
#[test]
fn a_certificate_beyond_its_budget_is_refused_as_too_costly() {
    use super::super::Budget;
    let f = fixture(CUBIC);
    let text = f.cert.to_string();
    let doc = crate::json::parse(&text, &crate::json::Limits::DEFAULT).unwrap();
    let size = super::super::budget::json_size(&doc);
    let budget = Budget::for_size(size);
    assert!(super::check(&doc, &budget).is_ok());
    let used = budget.used();
    assert!(used > 0, "the check charged nothing");
    // genuine certificates use a few units per byte
    assert!(used < 8 * size as u64, "{used} units for {size} bytes");
    let tight = Budget::with_limit(used / 2);
    let e = super::check(&doc, &tight).unwrap_err();
    assert!(e.reason.contains("too costly"), "{e}");
}
