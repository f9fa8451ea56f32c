//! Certified Hausdorff bounds (issue 4): soundness against independent exact
//! computations (Sturm isolation of foot points), Prop 6.1's closed form,
//! certificates and their mutation tests.

mod common;

use common::{exact_dist2, q};
use lncert::certify::verify::verify;
use lncert::certify::{hausdorff, Certificate, Config};
use lncert::curve::{Bezier, V2};
use lncert::ln::circle::ArcApprox;
use lncert::poly::{Poly, Span};
use lncert::scalar::{interval_from_rational, parse_rational, Rational, Scalar};
use lncert::shape::{ArcDesc, ShapeDesc};
use proptest::prelude::*;
use serde_json::Value;

fn shape(s: &str) -> ShapeDesc {
    ShapeDesc::parse(s).unwrap()
}

fn cfg(rel: f64) -> Config {
    Config {
        rel,
        ..Config::default()
    }
}

#[test]
fn quadratic_against_segment_is_a_quarter() {
    let a = shape("M 0 0 Q 0.5 0.5 1 0");
    let b = shape("M 0 0 L 1 0");
    for rel in [1e-3, 1e-6, 1e-9] {
        let r = hausdorff(&a, &b, &cfg(rel)).unwrap();
        assert!(r.lo <= 0.25 && 0.25 <= r.hi, "{r:?}");
        assert!(r.hi - r.lo <= rel * r.hi);
    }
}

#[test]
fn arc_and_chord() {
    // Arc of the unit circle from (4/5, −3/5) to (4/5, 3/5) against the segment from the
    // centre to (1, 0): h(arc → seg) = 3/5 (the arc's ends), h(seg → arc) = 1 (the centre).
    let a = shape(
        r#"{"arc": {"center": [0, 0], "radius": 1, "from": ["4/5", "-3/5"], "to": ["4/5", "3/5"]}}"#,
    );
    let b = shape("M 0 0 L 1 0");
    let r = hausdorff(&a, &b, &cfg(1e-6)).unwrap();
    assert!(r.a_to_b.lo <= 0.6 && 0.6 <= r.a_to_b.hi, "{:?}", r.a_to_b);
    assert!(r.b_to_a.lo <= 1.0 && 1.0 <= r.b_to_a.hi);
    assert!(r.hi - r.lo <= 1e-6 * r.hi);
}

#[test]
fn offset_of_a_segment_is_a_parallel_segment() {
    // The offset at distance 1/2 (left) of (0,0)-(2,0) is (0,1/2)-(2,1/2) exactly.
    let off = shape(r#"{"offset": {"curve": {"bezier": [[0, 0], [2, 0]]}, "distance": "1/2"}}"#);
    let par = shape("M 0 0.5 L 2 0.5");
    let r = hausdorff(&off, &par, &cfg(1e-3)).unwrap();
    assert!(r.hi < 1e-12, "{r:?}");
    // and the segment is 1/2 away from its offset
    let r = hausdorff(&off, &shape("M 0 0 L 2 0"), &cfg(1e-6)).unwrap();
    assert!(r.lo <= 0.5 && 0.5 <= r.hi && r.hi - r.lo <= 1e-6);
}

#[test]
fn offset_of_a_quarter_circle_curve_matches_arc_radius() {
    // Offset of the arc-like quadratic at distance −1 vs the same quadratic: every
    // point is exactly 1 away along the normal, so d_H ≤ 1, and the end points give ≥ 1
    // unless the curve bends back; the bounds must contain a value in [0, 1].
    let c = r#"{"bezier": [[0, 0], [1, 1], [2, 0]]}"#;
    let off = shape(&format!(
        r#"{{"offset": {{"curve": {c}, "distance": -1}}}}"#
    ));
    let r = hausdorff(&off, &shape(c), &cfg(1e-4)).unwrap();
    assert!(
        r.lo <= 1.0 + 1e-12 && r.hi >= r.lo && r.hi <= 1.0 + 1e-3,
        "{r:?}"
    );
}

#[test]
fn ellipse_convolution_of_a_segment() {
    // Convolution of the horizontal segment with the ellipse diag(3, 1/2): the point
    // with outer normal (0, 1) is (0, 1/2), so the convolution is the segment raised by 1/2.
    let conv = shape(
        r#"{"convolution": {"curve": {"bezier": [[0, 0], [2, 0]]}, "ellipse": [[3, 0], [0, "1/2"]], "side": 1}}"#,
    );
    let r = hausdorff(&conv, &shape("M 0 0.5 L 2 0.5"), &cfg(1e-3)).unwrap();
    assert!(r.hi < 1e-12, "{r:?}");
}

#[test]
fn bad_input_is_a_typed_error() {
    for (text, field) in [
        (
            r#"{"arc": {"center": [0, 0], "radius": 0, "from": [1, 0], "to": [0, 1]}}"#,
            "arc.radius",
        ),
        (
            r#"{"arc": {"center": [0, 0], "radius": 1, "from": [0, 0], "to": [0, 1]}}"#,
            "arc.from",
        ),
        (
            r#"{"arc": {"center": [0, 0], "radius": 1, "from": [1, 0], "to": [2, 0]}}"#,
            "arc.to",
        ),
        (
            r#"{"offset": {"curve": {"bezier": [[0, 0], [0, 0]]}, "distance": 1}}"#,
            "offset.curve[0]",
        ),
        (
            r#"{"offset": {"curve": {"bezier": [[0, 0], [1, 0], [0, 0]]}, "distance": 1}}"#,
            "offset.curve[0]",
        ),
        (
            r#"{"offset": {"curve": {"bezier": [[0, 0], [1, 0]]}, "distance": 0}}"#,
            "offset.distance",
        ),
        (
            r#"{"convolution": {"curve": {"bezier": [[0, 0], [1, 0]]}, "ellipse": [[1, 2], [2, 4]]}}"#,
            "convolution.ellipse",
        ),
        (r#"{"bezier": [[1e200, 0], [1, 0]]}"#, "curve[0][0][0]"),
        (r#"{"bezier": [[0, 0], [1, 0]], "x": 1}"#, "curve"),
        (r#"{"arc": [1]}"#, "arc"),
        ("{", "(json)"),
        ("M 0 0 L", "path"),
    ] {
        let e = ShapeDesc::parse(text).unwrap_err().to_string();
        assert!(e.contains(field), "{text}: {e}");
    }
    let a = shape("M 0 0 L 1 0");
    for c in [
        Config {
            rel: 0.0,
            ..Config::default()
        },
        Config {
            rel: f64::NAN,
            ..Config::default()
        },
        Config {
            max_boxes: 0,
            ..Config::default()
        },
    ] {
        assert!(hausdorff(&a, &a, &c).is_err());
    }
    // a tolerance is valid by construction: the bad ones are refused where it is made
    for bad in [-1.0, 0.0, f64::NAN, f64::INFINITY] {
        assert_eq!(lncert::Tolerance::from_f64(bad).unwrap_err().field, "tol");
    }
}

#[test]
fn identical_shapes_terminate_at_zero() {
    let a = shape("M 0 0 C 1 2 3 -1 4 0");
    // The distance is 0 everywhere: upper bounds shrink like w², so the relative goal
    // is out of reach; the search must stop on its budget, say so, and stay sound.
    let r = hausdorff(
        &a,
        &a,
        &Config {
            max_boxes: 20_000,
            ..cfg(1e-3)
        },
    )
    .unwrap();
    assert!(r.lo == 0.0 && r.hi < 1e-6, "{}", r.hi);
    assert!(r.incomplete() || r.hi <= 1e-10 * 5.0);
}

// ----- independent exact distances ------------------------------------------------

fn small_bezier(deg: usize) -> impl Strategy<Value = Bezier<Rational>> {
    prop::collection::vec((-8i64..=8, -8i64..=8), deg + 1).prop_map(|pts| {
        Bezier::new(
            pts.into_iter()
                .map(|(x, y)| V2::new(q(x, 4), q(y, 4)))
                .collect(),
        )
    })
}

proptest! {
    #![proptest_config(ProptestConfig { cases: (common::cases() / 40).max(16), ..ProptestConfig::default() })]

    /// No exactly computed distance of a dense rational sample exceeds `hi`, and the
    /// witness's exact distance is at least `lo`.
    #[test]
    fn bounds_contain_dense_exact_samples(a in small_bezier(3), b in small_bezier(2)) {
        let (sa, sb) = (ShapeDesc::curve(vec![a.clone()]).unwrap(), ShapeDesc::curve(vec![b.clone()]).unwrap());
        let r = hausdorff(&sa, &sb, &cfg(1e-3)).unwrap();
        prop_assert!(r.lo <= r.hi);
        for (from, to, side) in [(&a, &b, &r.a_to_b), (&b, &a, &r.b_to_a)] {
            for k in 0..=64 {
                let d2 = exact_dist2(&from.eval(&q(k, 64)), to);
                let d = d2.inf().max(0.0).sqrt(); // an enclosure of a square may dip below 0
                prop_assert!(d <= side.hi * (1.0 + 1e-15), "sample {k}/64 at {d} > hi {}", side.hi);
            }
            if let Some((_, s)) = side.witness {
                let d2 = exact_dist2(&from.eval(&lncert::scalar::rational_from_f64(s).unwrap()), to);
                prop_assert!(d2.sup().sqrt() >= side.lo * (1.0 - 1e-15), "witness {} < lo {}", d2.sup().sqrt(), side.lo);
            }
        }
    }
}

// ----- seed 000 Prop 6.1 -------------------------------------------------------------

/// The closed form of Prop 6.1 lies in the certified bounds of `d_H(arc, ca)`, for
/// rational points `(cos α, sin α) = ((1−m²)/(1+m²), 2m/(1+m²))` and κ ∈ [1/2, 2].
#[test]
fn prop_6_1_closed_form_within_certified_bounds() {
    let mut checked = 0;
    let mut in_sector = 0;
    for (mn, md) in [(1, 8), (1, 5), (1, 3), (2, 5), (1, 2), (3, 5)] {
        for kappa in [
            (1, 2),
            (3, 5),
            (4, 5),
            (19, 20),
            (21, 20),
            (5, 4),
            (3, 2),
            (9, 5),
            (2, 1),
        ] {
            let m = q(mn, md);
            let one = q(1, 1);
            let den = &one + &m * &m;
            let (c, s) = ((&one - &m * &m) / &den, q(2, 1) * &m / &den);
            let k = q(kappa.0, kappa.1);
            let ex = ArcApprox::new(c.clone(), s.clone(), k.clone()).unwrap();
            let cubic = ex.cubic().unwrap();
            let iv = ArcApprox::new(
                interval_from_rational(&c),
                interval_from_rational(&s),
                interval_from_rational(&k),
            )
            .unwrap();
            let Some(closed) = iv.prop_6_1_distance() else {
                continue;
            };
            let arc = ShapeDesc::arc(ArcDesc {
                center: V2::new(q(0, 1), q(0, 1)),
                radius: q(1, 1),
                from: V2::new(c.clone(), -s.clone()),
                to: V2::new(c.clone(), s.clone()),
            })
            .unwrap();
            let ca = ShapeDesc::curve(vec![cubic]).unwrap();
            let r = hausdorff(&arc, &ca, &cfg(1e-7)).unwrap();
            assert!(!r.incomplete());
            if sector_holds(&c, &s, ex.cubic().as_ref().unwrap()) {
                in_sector += 1;
            }
            assert!(
                closed.inf() <= r.hi && closed.sup() >= r.lo,
                "α: m = {mn}/{md}, κ = {kappa:?}: closed form {closed:?} outside [{}, {}]",
                r.lo,
                r.hi
            );
            checked += 1;
        }
    }
    assert!(checked >= 40, "{checked}");
    // proofs/000-prop-6.1.md: the closed form is d_H whenever `ca` stays in the arc's
    // sector; the exact check holds on every tested case.
    assert_eq!(in_sector, checked, "sector condition failed on some case");
}

/// Exactly: `cross(e0, ca(s)) > 0` and `cross(ca(s), e1) > 0` on `(0, 1)` for the arc's
/// end directions `e0 = (cos α, −sin α)`, `e1 = (cos α, sin α)` (no root in `(0, 1)` by
/// Sturm, positive at `1/2`): every point of `ca` lies in the sector of the arc.
fn sector_holds(c: &Rational, s: &Rational, ca: &Bezier<Rational>) -> bool {
    use lncert::poly::has_root_in;
    let (x, y) = ca.power_coords();
    let cs = |k: &Rational| Poly::new(vec![k.clone()]);
    // cross(e0, p) = cos α · y + sin α · x ; cross(p, e1) = x sin α − y cos α
    let p1 = cs(c).mul(&y).add(&cs(s).mul(&x));
    let p2 = cs(s).mul(&x).sub(&cs(c).mul(&y));
    let half = q(1, 2);
    [p1, p2]
        .iter()
        .all(|p| !has_root_in(p, &Span::unit_open()) && p.eval(&half) > Rational::default())
}

// ----- certificates ------------------------------------------------------------------

/// The two kinds of proof a certificate carries.
#[derive(Clone, Copy, Debug, PartialEq)]
enum Kind {
    /// The two-directional search's box covers (`directions`).
    Search,
    /// The parametric proof's map (`maps`).
    Map,
}

const KINDS: [Kind; 2] = [Kind::Search, Kind::Map];

fn certified_by(a: &ShapeDesc, b: &ShapeDesc, tol: &str, kind: Kind) -> Certificate {
    let t: lncert::Tolerance = tol.parse().unwrap();
    let r = hausdorff(
        a,
        b,
        &Config {
            tol: Some(t.clone()),
            parametric: kind == Kind::Map,
            // the maps and boxes these tests forge (radial certificates:
            // `radial_certificates_are_refused_where_the_statement_fails`)
            radial: false,
            ..Config::default()
        },
    )
    .unwrap();
    let cert = Certificate::new(a, b, &t, &r).expect("certified");
    // the kind asked for, and only that kind of proof
    let n = |k: &str| cert.doc[k].as_array().map_or(0, Vec::len);
    let dir_boxes = cert.doc["directions"]
        .as_array()
        .unwrap()
        .iter()
        .map(|d| d["boxes"].as_array().unwrap().len())
        .sum::<usize>();
    match kind {
        Kind::Search => assert!(n("maps") == 0 && dir_boxes > 0),
        Kind::Map => assert!(
            n("maps") == 1 && dir_boxes == 0,
            "the parametric path did not decide"
        ),
    }
    cert
}

fn certified(a: &ShapeDesc, b: &ShapeDesc, tol: &str) -> Certificate {
    certified_by(a, b, tol, Kind::Search)
}

/// Verifies a (possibly edited) certificate document through its text.
fn check(doc: &Value) -> Result<lncert::certify::verify::Valid, lncert::certify::verify::Invalid> {
    verify(&doc.to_string())
}

/// Every string leaf that is a number, with its JSON pointer.
fn number_leaves(v: &Value, path: String, out: &mut Vec<String>) {
    match v {
        Value::Object(m) => m
            .iter()
            .for_each(|(k, x)| number_leaves(x, format!("{path}/{k}"), out)),
        Value::Array(a) => a
            .iter()
            .enumerate()
            .for_each(|(i, x)| number_leaves(x, format!("{path}/{i}"), out)),
        Value::String(s) if parse_rational(s).is_ok() => out.push(path),
        Value::Number(_) => out.push(path),
        _ => {}
    }
}

fn bumped(v: &Value) -> Value {
    match v {
        Value::String(s) => {
            let r = parse_rational(s).unwrap() + q(1, 1000);
            Value::String(r.to_string())
        }
        Value::Number(n) => Value::from(n.as_i64().unwrap_or(0) + 1),
        other => other.clone(),
    }
}

fn approximant_pair() -> (ShapeDesc, ShapeDesc) {
    let a = shape("M 0 0 C 1 1 2 1 3 0");
    let b = shape("M 0 0 C 1.01 1.02 1.98 0.99 3 0.01");
    (a, b)
}

#[test]
fn certificate_round_trip_and_every_number_is_bound() {
    for kind in KINDS {
        round_trip_and_every_number_is_bound(kind);
    }
}

fn round_trip_and_every_number_is_bound(kind: Kind) {
    let (a, b) = approximant_pair();
    let cert = certified_by(&a, &b, "0.02", kind);
    let valid = check(&cert.doc).expect("valid");
    assert!(valid.max_bound <= 0.02 && valid.boxes == cert.box_count());
    assert!(valid.statement().contains("d_H(A, B) ≤ 1/50"));
    let mut leaves = Vec::new();
    number_leaves(&cert.doc, String::new(), &mut leaves);
    assert!(leaves.len() > 50, "{kind:?}: {}", leaves.len());
    // No digest: an edited number is either rejected, or the edited certificate
    // still proves a true statement (an independent search cannot refute it).
    let mut rejected = 0;
    for p in &leaves {
        let mut doc = cert.doc.clone();
        *doc.pointer_mut(p).unwrap() = bumped(doc.pointer(p).unwrap());
        match check(&doc) {
            Err(_) => rejected += 1,
            Ok(v) => {
                let sa = ShapeDesc::from_value(&doc["a"]).unwrap();
                let sb = ShapeDesc::from_value(&doc["b"]).unwrap();
                let r = hausdorff(&sa, &sb, &cfg(1e-2)).unwrap();
                assert!(
                    Rational::from_float(r.lo).unwrap() <= v.tol,
                    "{kind:?} {p}: accepted d_H ≤ {}, refuted: {}",
                    v.tol,
                    r.lo
                );
            }
        }
    }
    assert!(rejected > 0);
}

/// Nothing rides along unchecked: removing any key, adding any key to any
/// object, or repeating any key is refused, and the error names that field.
#[test]
fn every_key_is_required_and_no_other_key_is_accepted() {
    for kind in KINDS {
        every_key_is_required(kind);
    }
}

fn every_key_is_required(kind: Kind) {
    let (a, b) = approximant_pair();
    let cert = certified_by(&a, &b, "0.02", kind);
    let text = cert.to_json_string();
    assert!(verify(&text).is_ok());
    // every object of the document, by JSON pointer and dotted field name
    fn objects(v: &Value, ptr: String, field: String, out: &mut Vec<(String, String)>) {
        match v {
            Value::Object(m) => {
                out.push((ptr.clone(), field.clone()));
                for (k, x) in m {
                    let f = if field.is_empty() {
                        k.clone()
                    } else {
                        format!("{field}.{k}")
                    };
                    objects(x, format!("{ptr}/{k}"), f, out);
                }
            }
            Value::Array(xs) => {
                for (i, x) in xs.iter().enumerate().take(3) {
                    objects(x, format!("{ptr}/{i}"), format!("{field}[{i}]"), out);
                }
            }
            _ => {}
        }
    }
    let mut objs = Vec::new();
    objects(&cert.doc, String::new(), String::new(), &mut objs);
    assert!(objs.len() >= 9, "{objs:?}");
    for (ptr, field) in &objs {
        let keys: Vec<String> = cert
            .doc
            .pointer(ptr)
            .unwrap()
            .as_object()
            .unwrap()
            .keys()
            .cloned()
            .collect();
        let join = |k: &str| {
            if field.is_empty() {
                k.to_string()
            } else {
                format!("{field}.{k}")
            }
        };
        for k in &keys {
            let mut doc = cert.doc.clone();
            doc.pointer_mut(ptr)
                .unwrap()
                .as_object_mut()
                .unwrap()
                .remove(k);
            let e = check(&doc).expect_err(&join(k));
            // a shape object without its one key is refused as a whole
            assert!(
                e.at == join(k) || e.at == *field || (field.is_empty() && e.at == "(top level)"),
                "removed {}: {e}",
                join(k)
            );
        }
        for extra in ["clockwise", "bound", "digest", "note"] {
            let mut doc = cert.doc.clone();
            doc.pointer_mut(ptr)
                .unwrap()
                .as_object_mut()
                .unwrap()
                .insert(extra.into(), Value::Bool(true));
            let e = check(&doc).expect_err(&join(extra));
            assert!(
                e.at == join(extra) || e.at == *field,
                "added {}: {e}",
                join(extra)
            );
        }
    }
    // a repeated key, at the top and deep inside a shape: the first occurrence
    // would otherwise be silently dropped
    let deep = match kind {
        Kind::Search => ("\"piece\":0", "\"piece\":0, \"piece\":0"),
        Kind::Map => ("\"phi\":[", "\"phi\":[\"0\",\"0\",\"0\",\"0\"], \"phi\":["),
    };
    for (from, to) in [
        ("\"tol\": \"1/50\"", "\"tol\": \"1\", \"tol\": \"1/50\""),
        deep,
    ] {
        assert!(text.contains(from), "{from}");
        let e = verify(&text.replacen(from, to, 1)).unwrap_err();
        assert!(e.reason.contains("duplicate"), "{e}");
    }
}

/// Numbers must be canonical and bounded: one spelling per value, so the text is
/// the statement.
#[test]
fn numbers_must_be_canonical_and_bounded() {
    let (a, b) = approximant_pair();
    let cert = certified(&a, &b, "0.02");
    for (tol, ok) in [
        (Value::from("1/50"), true),
        (Value::from("0.02"), false),
        (Value::from("2/100"), false),
        (Value::from("+1/50"), false),
        (Value::from("01/50"), false),
        (Value::from("1/050"), false),
        (Value::from("-0"), false),
        (Value::from("1/1"), false),
        (Value::from("0/7"), false),
        (Value::from("-0/7"), false),
        (Value::from("1/0"), false),
        (Value::from("-1/50"), false),
        (Value::from("4/200"), false),
        (Value::from(" 1/50"), false),
        (Value::from(1), false),
        (Value::from("1".to_string() + &"0".repeat(100)), true), // 10¹⁰⁰: the limit
        (Value::from("1".to_string() + &"0".repeat(99) + "1"), false),
        (Value::from("1".repeat(5000)), false),
        (Value::from("-1/50"), false),
    ] {
        let mut doc = cert.doc.clone();
        doc["tol"] = tol.clone();
        let r = check(&doc);
        assert_eq!(r.is_ok(), ok, "{tol}: {r:?}");
        if let Err(e) = r {
            assert_eq!(e.at, "tol", "{tol}: {e}");
        }
    }
    // box and map indices are plain integers
    let mcert = certified_by(&a, &b, "0.02", Kind::Map);
    for bad in [
        Value::from(-1),
        Value::from(0.0),
        Value::from("0"),
        Value::from(1u64 << 40),
    ] {
        let mut doc = cert.doc.clone();
        doc["directions"][0]["boxes"][0]["piece"] = bad.clone();
        let e = check(&doc).expect_err("bad index");
        assert_eq!(e.at, "directions[0].boxes[0].piece", "{bad}: {e}");
        for field in ["piece", "target"] {
            let mut doc = mcert.doc.clone();
            doc["maps"][0][field] = bad.clone();
            let e = check(&doc).expect_err("bad index");
            assert_eq!(e.at, format!("maps[0].{field}"), "{bad}: {e}");
        }
    }
    // map coefficients are canonical rationals too
    let mut doc = mcert.doc.clone();
    doc["maps"][0]["boxes"][1]["phi"][2] = Value::from(0.5);
    assert_eq!(check(&doc).unwrap_err().at, "maps[0].boxes[1].phi[2]");
    // the whole document: too large, too deep
    let deep = format!("{}{}", "[".repeat(40), "]".repeat(40));
    assert!(verify(&deep).unwrap_err().reason.contains("nested"));
}

#[test]
fn semantic_checks_reject_forged_certificates() {
    let (a, b) = approximant_pair();
    let cert = certified(&a, &b, "0.02");
    let hi = check(&cert.doc).unwrap().max_bound;
    let forge = |f: &dyn Fn(&mut Value)| {
        let mut d = cert.doc.clone();
        f(&mut d);
        check(&d)
    };
    // a tolerance below the proven bound
    let below = Rational::from_float(hi * 0.999).unwrap();
    let e = forge(&|d| d["tol"] = Value::String(below.to_string())).unwrap_err();
    assert!(e.reason.contains("exceeds the tolerance"), "{e}");
    // a box removed: the cover has a gap
    let e = forge(&|d| {
        d["directions"][0]["boxes"]
            .as_array_mut()
            .unwrap()
            .remove(1);
    })
    .unwrap_err();
    assert!(e.reason.contains("gap"), "{e}");
    // the last box cut short: the domain is not covered to its end
    let e = forge(&|d| {
        let bx = d["directions"][1]["boxes"].as_array_mut().unwrap();
        let last = bx.len() - 1;
        bx[last]["s"][1] = Value::String("999/1000".into());
    })
    .unwrap_err();
    assert!(
        e.reason.contains("not covered") || e.reason.contains("gap"),
        "{e}"
    );
    // a foot map sent outside the target's parameter domain
    let e =
        forge(&|d| d["directions"][0]["boxes"][0]["t"] = Value::String("2".into())).unwrap_err();
    assert!(e.reason.contains("domain"), "{e}");
    // indices out of range, wrong direction labels, wrong version
    assert!(forge(&|d| d["directions"][0]["boxes"][0]["target"] = Value::from(7)).is_err());
    assert!(forge(&|d| d["directions"][0]["from"] = Value::from("b")).is_err());
    assert!(forge(&|d| d["version"] = Value::from(1)).is_err());
    assert!(forge(&|d| d["version"] = Value::from(4)).is_err());
    // version 2 is still read: the same document without maps
    assert!(
        forge(&|d| d["version"] = Value::from(2)).is_err(),
        "v2 has no maps key"
    );
    let v2 = forge(&|d| {
        d["version"] = Value::from(2);
        d.as_object_mut().unwrap().remove("maps");
    });
    assert!(v2.is_ok(), "{v2:?}");
    assert!(forge(&|d| {
        d.as_object_mut().unwrap().remove("maps");
    })
    .is_err());
}

/// Forged maps: every rule of a parametric cover is checked.
#[test]
fn semantic_checks_reject_forged_maps() {
    let (a, b) = approximant_pair();
    let cert = certified_by(&a, &b, "0.02", Kind::Map);
    let hi = check(&cert.doc).unwrap().max_bound;
    let forge = |f: &dyn Fn(&mut Value)| {
        let mut d = cert.doc.clone();
        f(&mut d);
        check(&d)
    };
    let n = cert.doc["maps"][0]["boxes"].as_array().unwrap().len();
    assert!(n >= 3, "{n}");
    let expect = |r: Result<_, lncert::certify::verify::Invalid>, at: &str, why: &str| {
        let e = r.expect_err(why);
        assert!(
            e.at.starts_with(at) && e.reason.contains(why),
            "{at} / {why}: {e}"
        );
    };
    // a tolerance below the proven bound
    let below = Rational::from_float(hi * 0.999).unwrap();
    expect(
        forge(&|d| d["tol"] = Value::String(below.to_string())),
        "maps[0]",
        "exceeds the tolerance",
    );
    // a box removed: the cover has a gap
    expect(
        forge(&|d| {
            d["maps"][0]["boxes"].as_array_mut().unwrap().remove(1);
        }),
        "maps[0].boxes[1]",
        "gap",
    );
    // the last box removed: the source is not covered to its end
    expect(
        forge(&|d| {
            d["maps"][0]["boxes"].as_array_mut().unwrap().pop();
        }),
        "maps[0].boxes",
        "not covered",
    );
    // a box beyond the end of the source's domain
    expect(
        forge(&|d| d["maps"][0]["boxes"][n - 1]["t"][1] = "2".into()),
        &format!("maps[0].boxes[{}]", n - 1),
        "gap",
    );
    // the map made discontinuous (the box's bound alone could still hold)
    expect(
        forge(&|d| {
            let c = parse_rational(d["maps"][0]["boxes"][1]["phi"][0].as_str().unwrap()).unwrap();
            d["maps"][0]["boxes"][1]["phi"][0] = (c + q(1, 1 << 30)).to_string().into();
        }),
        "maps[0].boxes[1].phi[0]",
        "not continuous",
    );
    // a coefficient outside the target's domain [0, 1]
    expect(
        forge(&|d| {
            d["maps"][0]["boxes"][0]["phi"][0] = "-1/1024".into();
        }),
        "maps[0].boxes[0]",
        "domain",
    );
    // a map that is not onto: it stops short of the target's end — the end
    // term is added and the tolerance fails (the last value pulled back to 1/2
    // with the whole last box moved)
    expect(
        forge(&|d| {
            d["maps"][0]["boxes"][n - 1]["phi"] =
                serde_json::json!([d["maps"][0]["boxes"][n - 1]["phi"][0], "1/2", "1/2", "1/2"]);
        }),
        "maps[0]",
        "exceeds the tolerance",
    );
    // the wrong direction labels, a map and boxes for the same piece, two maps
    expect(
        forge(&|d| d["maps"][0]["to"] = "b".into()),
        "maps[0]",
        "expected from",
    );
    let boxes_too = forge(&|d| {
        d["directions"][0]["boxes"] = serde_json::json!([
            {"piece": 0, "s": ["0", "1"], "target": 0, "t": "1/2", "k": "1"}
        ]);
    });
    expect(boxes_too, "directions[0].boxes[0]", "covered by maps[0]");
    let twice = forge(&|d| {
        let m = d["maps"][0].clone();
        d["maps"].as_array_mut().unwrap().push(m);
    });
    expect(twice, "maps[1].piece", "already covered");
    // no maps and no boxes: nothing proven
    let empty = forge(&|d| d["maps"] = serde_json::json!([]));
    expect(empty, "directions[0].boxes", "not covered");
    // an arc as the source: its parameter domain is not exact
    let arc = shape(r#"{"arc": {"center": [0, 0], "radius": 1, "from": [1, 0], "to": [0, 1]}}"#);
    let cubic = shape("M 1 0 C 1 0.5523 0.5523 1 0 1");
    let ac = certified_by(&arc, &cubic, "0.0003", Kind::Map);
    assert!(check(&ac.doc).is_ok());
    assert_eq!(
        ac.doc["maps"][0]["from"], "b",
        "the polynomial side is the source"
    );
    let mut d = ac.doc.clone();
    d["maps"][0]["from"] = "a".into();
    d["maps"][0]["to"] = "b".into();
    expect(check(&d), "maps[0].piece", "exact parameter domain");
}

/// Moving a control point of the certified approximant by more than the slack
/// (tol − hi): the verifier never accepts a claim that an independent search refutes,
/// and it rejects the large moves.
#[test]
fn moved_control_points_fail_verification() {
    for kind in KINDS {
        moved_control_points(kind);
    }
}

fn moved_control_points(kind: Kind) {
    let (a, b) = approximant_pair();
    let tol = "0.03";
    let cert = certified_by(&a, &b, tol, kind);
    let hi = check(&cert.doc).unwrap().max_bound;
    let slack = 0.03 - hi;
    assert!(slack > 0.0);
    let ShapeDesc::Curve(pieces) = &b else {
        unreachable!()
    };
    let mut rejected = 0;
    let mut tried = 0;
    for k in 0..4 {
        for (dx, dy) in [(1, 0), (-1, 0), (0, 1), (0, -1)] {
            for factor in [3.0, 10.0] {
                let delta = Rational::from_float(factor * slack.max(0.01)).unwrap();
                let mut pts = pieces[0].points().to_vec();
                pts[k] = V2::new(&pts[k].x + &delta * q(dx, 1), &pts[k].y + &delta * q(dy, 1));
                let moved = ShapeDesc::curve(vec![Bezier::new(pts)]).unwrap();
                let mut doc = cert.doc.clone();
                doc["b"] = moved.to_json();
                let accepted = check(&doc).is_ok();
                let truth = hausdorff(
                    &a,
                    &moved,
                    &Config {
                        tol: Some(common::tol(0.03)),
                        ..Config::default()
                    },
                )
                .unwrap();
                assert!(
                    !(accepted && truth.lo > 0.03),
                    "accepted a refuted claim: point {k}, {dx},{dy} × {factor}"
                );
                tried += 1;
                if !accepted {
                    rejected += 1;
                }
                if factor == 10.0 && (k == 0 || k == 3) {
                    // an end point moved 10× the slack (≥ 0.1) away from a curve that ends there
                    assert!(
                        truth.lo > 0.03 && !accepted,
                        "end point {k} moved: {}",
                        truth.lo
                    );
                }
            }
        }
    }
    assert!(rejected * 2 >= tried, "{rejected} of {tried}");
}

#[test]
fn certificate_for_arc_and_offset_shapes() {
    let arc = shape(r#"{"arc": {"center": [0, 0], "radius": 1, "from": [1, 0], "to": [0, 1]}}"#);
    // the standard cubic approximation of the quarter circle (k = 0.5523)
    let cubic = shape("M 1 0 C 1 0.5523 0.5523 1 0 1");
    for kind in KINDS {
        let cert = certified_by(&arc, &cubic, "0.0003", kind);
        assert!(check(&cert.doc).is_ok(), "{kind:?}");
    }
    let off =
        shape(r#"{"offset": {"curve": {"bezier": [[0, 0], [1, 1], [2, 0]]}, "distance": "1/10"}}"#);
    let r = hausdorff(
        &off,
        &shape("M -0.0707 0.0707 Q 1 1.2 2.0707 0.0707"),
        &cfg(1e-3),
    )
    .unwrap();
    let tol = lncert::Tolerance::new(Rational::from_float(r.hi * 1.01).unwrap()).unwrap();
    let r = hausdorff(
        &off,
        &shape("M -0.0707 0.0707 Q 1 1.2 2.0707 0.0707"),
        &Config {
            tol: Some(tol.clone()),
            parametric: false,
            ..Config::default()
        },
    )
    .unwrap();
    let cert = Certificate::new(
        &off,
        &shape("M -0.0707 0.0707 Q 1 1.2 2.0707 0.0707"),
        &tol,
        &r,
    )
    .unwrap();
    assert!(check(&cert.doc).is_ok());
    let _ = Scalar::approx(tol.exact());
}

// ----- fuzz regressions (fuzz/regressions/hausdorff/) --------------------------------

/// An offset whose normal cannot be bounded on the first coarse boxes: the search
/// used to stop at once with `hi = ∞` and call itself complete (`∞ − lo ≤ rel·∞`).
#[test]
fn infinite_first_bounds_are_refined_not_accepted() {
    let a = shape(r#"{"offset":{"curve":"M 0 0 C 3 3 -2 3 1 0","distance":"1/4"}}"#);
    let b = shape("M 0 0 L 1 0");
    let r = hausdorff(&a, &b, &cfg(1e-3)).unwrap();
    assert!(
        r.hi.is_finite() && !r.incomplete(),
        "{} {}",
        r.hi,
        r.incomplete()
    );
    assert!(r.hi - r.lo <= 1e-3 * r.hi);
    // with a small budget the answer may stay unbounded, but then it says so
    let r = hausdorff(
        &a,
        &b,
        &Config {
            max_boxes: 4,
            ..cfg(1e-3)
        },
    )
    .unwrap();
    assert!(r.hi.is_finite() || r.incomplete());
}

/// Half circles whose directions do not normalise exactly: `|e1 + e0|` encloses 0 and
/// was squared with `x * x` (negative lower end), rejecting a valid arc.
#[test]
fn half_circle_arcs_with_inexact_directions() {
    for (from, to) in [
        ("[1, 1]", "[-1, -1]"),
        ("[1, 2]", "[-1, -2]"),
        ("[-4, 4]", "[3, -3]"),
    ] {
        let arc = shape(&format!(
            r#"{{"arc": {{"center": [0, 0], "radius": 2, "from": {from}, "to": {to}}}}}"#
        ));
        // the centre is at distance exactly 2 from every arc point
        let centre = shape("M 0 0 L 0 0");
        let r = hausdorff(&centre, &arc, &cfg(1e-6)).unwrap();
        assert!(
            r.a_to_b.lo <= 2.0 && 2.0 <= r.a_to_b.hi,
            "{from} {to}: {:?}",
            (r.a_to_b.lo, r.a_to_b.hi)
        );
    }
}

/// The verifier is never looser than the search that wrote a certificate: a
/// certificate whose tolerance is the float just above the search's `hi` (no
/// slack at all, as the `against` fuzz target writes one in four) verifies,
/// for every kind of shape pair the fuzz targets use. (Found by the `against`
/// target when the verifier's Taylor triples were moved to `ulp` arithmetic:
/// a quarter arc against itself was refused by one ulp.)
#[test]
fn certificates_at_the_searchs_own_bound_verify() {
    use lncert::scalar::rational_from_f64;
    use lncert::Tolerance;
    let quarter = r#"{"arc": {"center": [0, 0], "radius": 1, "from": [1, 0], "to": [0, 1]}}"#;
    let cubic = r#"{"bezier": [[0, 0], ["1/3", "1/2"], ["2/3", "1/2"], [1, 0]]}"#;
    let pairs = [
        (quarter, quarter),
        (
            quarter,
            r#"{"bezier": [[1, 0], [1, "11/20"], ["11/20", 1], [0, 1]]}"#,
        ),
        (
            cubic,
            r#"{"bezier": [[0, "1/32"], ["1/3", "17/32"], ["2/3", "15/32"], [1, 0]]}"#,
        ),
        (cubic, cubic),
        (
            "M 0 0 L 1 0",
            r#"{"bezier": [[0, 0], ["1/2", "1/4"], [1, 0]]}"#,
        ),
        (
            r#"{"offset": {"curve": {"bezier": [[0, 0], [1, 1], [2, 0]]}, "distance": "1/4"}}"#,
            r#"{"bezier": [["-1/8", "1/8"], ["2/3", "11/12"], ["4/3", "11/12"], ["17/8", "1/8"]]}"#,
        ),
        (
            r#"{"offset": {"curve": "M 0 0 C 1 1 2 1 3 0", "distance": "-1/2"}}"#,
            r#"{"convolution": {"curve": "M 0 0 C 1 1 2 1 3 0", "ellipse": [["1/2", 0], [0, "1/4"]], "side": -1}}"#,
        ),
    ];
    let mut checked = 0;
    for (a, b) in pairs {
        let (a, b) = (shape(a), shape(b));
        for (rel, max_boxes, parametric) in [(1e-2, 48, false), (1e-3, 400, true)] {
            let search = Config {
                rel,
                max_boxes,
                parametric,
                ..Config::default()
            };
            let r = hausdorff(&a, &b, &search).expect("a search");
            let tol = rational_from_f64(r.hi.next_up().max(f64::MIN_POSITIVE)).unwrap();
            let tol = Tolerance::new(tol).unwrap();
            let Some(cert) = Certificate::new(&a, &b, &tol, &r) else {
                continue;
            };
            let text = cert.to_json_string();
            let v = verify(&text);
            assert!(
                v.is_ok(),
                "{} vs {} (rel {rel}, parametric {parametric}) at tol {}: {:?}",
                a.to_json(),
                b.to_json(),
                tol.exact(),
                v.err()
            );
            checked += 1;
        }
    }
    assert!(checked >= 10, "only {checked} certificates written");
}

/// Pythagorean unit directions (exact rationals) and rational rotations by
/// angles in `(0, π]`: the arcs of the radial proof's tests.
fn unit_dirs() -> Vec<(i64, i64, i64)> {
    vec![
        (1, 0, 1),
        (3, 4, 5),
        (-5, 12, 13),
        (0, 1, 1),
        (-4, 3, 5),
        (8, -15, 17),
        (-1, 0, 1),
    ]
}
fn rotations() -> Vec<(i64, i64, i64)> {
    // (cos, sin, denominator): 36.9°, 67.4°, 90°, 126.9°, 163.7°, 180°
    vec![
        (4, 3, 5),
        (5, 12, 13),
        (0, 1, 1),
        (-3, 4, 5),
        (-24, 7, 25),
        (-1, 0, 1),
    ]
}

proptest! {
    #![proptest_config(common::config())]

    /// The radial proof (an arc against a chain of pieces in its sector, `d_H`
    /// the largest radial distance) against independent computations: the
    /// parametric / two-directional search on the same shapes (a different
    /// proof: Taylor forms and foot points) must overlap its bounds, and the
    /// exact radial distance at rational samples (a lower bound of `d_H`
    /// whatever the shapes) must not exceed its upper bound. Arcs of sweep 37°
    /// to 180° on rational circles; cubics near them whose ends move along or
    /// off the end rays and whose inner points move in or out of the sector
    /// (handles pointing backwards: out of it at both ends), as one piece or split in two, either way round, the arc as `A` or `B`.
    #[test]
    fn radial_proof_agrees_with_the_search(
        (cx, cy, rn) in (-8i64..=8, -8i64..=8, 4i64..=40),
        (di, ri) in (0usize..7, 0usize..6),
        ends in prop::array::uniform2(-3i64..=3),
        off_ray in prop::array::uniform2(prop_oneof![3 => Just(0i64), 1 => -2i64..=2]),
        inner in prop::array::uniform4(prop_oneof![2 => Just(0i64), 1 => -6i64..=6]),
        split in any::<bool>(),
        reverse in any::<bool>(),
        arc_first in any::<bool>(),
        behind in 0usize..4,
    ) {
        let (c, r) = (V2::new(q(cx, 4), q(cy, 4)), q(rn, 8));
        let (dx, dy, dn) = unit_dirs()[di];
        let (rc, rs, rd) = rotations()[ri];
        let u0 = V2::new(q(dx, dn), q(dy, dn));
        let (cos, sin) = (q(rc, rd), q(rs, rd));
        let u1 = V2::new(&cos * &u0.x - &sin * &u0.y, &sin * &u0.x + &cos * &u0.y);
        // the classical handle 4/3 tan(Θ/4), as a rational near it
        let theta = (rs as f64).atan2(rc as f64);
        let k = Rational::from_float(4.0 / 3.0 * (theta / 4.0).tan()).unwrap();
        let at = |u: &V2<Rational>, s: &Rational| c.add(&u.scale(s));
        let rad = |e: i64| &r * (q(1, 1) + q(e, 40));
        let p0 = at(&u0, &rad(ends[0])).add(&u0.rot90().scale(&(&r * q(off_ray[0], 50))));
        let p3 = at(&u1, &rad(ends[1])).add(&u1.rot90().scale(&(&r * q(off_ray[1], 50))));
        let h = &k * &r;
        let nudge = |p: V2<Rational>, a: i64, b: i64| p.add(&V2::new(&r * q(a, 30), &r * q(b, 30)));
        // one time in four, the handles point backwards: the curve leaves the sector
        let h1 = if behind == 0 { -&h } else { h.clone() };
        let p1 = nudge(p0.add(&u0.rot90().scale(&h1)), inner[0], inner[1]);
        let p2 = nudge(p3.sub(&u1.rot90().scale(&h1)), inner[2], inner[3]);
        let mut pts = vec![p0, p1, p2, p3];
        if reverse {
            pts.reverse();
        }
        let cubic = Bezier::new(pts);
        let pieces = if split {
            let (l, rr) = cubic.split(&q(1, 3));
            vec![l, rr]
        } else {
            vec![cubic.clone()]
        };
        let arc = ShapeDesc::arc(ArcDesc { center: c.clone(), radius: r.clone(), from: u0, to: u1 }).unwrap();
        let curve = ShapeDesc::curve(pieces).unwrap();
        let (a, b) = if arc_first { (&arc, &curve) } else { (&curve, &arc) };
        let rr = hausdorff(a, b, &cfg(1e-6)).unwrap();
        let other = hausdorff(a, b, &Config { radial: false, ..cfg(1e-6) }).unwrap();
        prop_assert!(other.radial.is_none());
        // the exact radial distance at samples: ≤ dist(P(t), arc) ≤ d_H ≤ hi
        let hi = Rational::from_float(rr.hi).unwrap();
        for j in 0..=12 {
            let d2 = cubic.eval(&q(j, 12)).sub(&c).norm2();
            let below = &r - &hi;
            prop_assert!(d2 <= (&r + &hi) * (&r + &hi), "sample {j}: outside R + hi ({:?})", rr.radial);
            prop_assert!(below < q(0, 1) || d2 >= &below * &below, "sample {j}: inside R − hi ({:?})", rr.radial);
        }
        let slack = 1e-12 * rr.hi.max(other.hi);
        prop_assert!(rr.lo <= other.hi + slack && other.lo <= rr.hi + slack,
            "radial [{}, {}] ({:?}) against the search [{}, {}]", rr.lo, rr.hi, rr.radial, other.lo, other.hi);
        // on the ray at both ends and every control point in the sector: decided radially
        if off_ray == [0, 0] && inner == [0, 0, 0, 0] && ends.iter().all(|e| *e >= 0) && behind != 0 {
            prop_assert!(rr.radial.is_some(), "not radial: {:?}", rr);
        }
        if off_ray != [0, 0] {
            prop_assert!(rr.radial.is_none(), "an end off its ray was taken radially");
        }
        if let Some(p) = &rr.radial {
            prop_assert!(rr.hi - rr.lo <= 1e-6 * rr.hi + 1e-10 * (1.0 + 3.0 * rn as f64));
            prop_assert_eq!(p.curve_is_a, !arc_first);
            // claims 1/1000 above and below d_H: the radial verdict is the search's
            for k in [999i64, 1001] {
                let t = Rational::from_float(rr.hi).unwrap() * q(k, 1000);
                let Ok(tol) = lncert::Tolerance::new(t) else { continue };
                let claim = |radial| Config { tol: Some(tol.clone()), radial, ..cfg(1e-3) };
                let (x, y) = (hausdorff(a, b, &claim(true)).unwrap(), hausdorff(a, b, &claim(false)).unwrap());
                prop_assert!(x.radial.is_some());
                let v = tol.value();
                let verdict = |h: &lncert::certify::HausdorffBounds| (h.hi <= v, h.lo > v);
                prop_assert_eq!(verdict(&x), (k > 1000, k < 1000), "radial {:?}", x);
                prop_assert_eq!(verdict(&x), verdict(&y), "radial {:?} against {:?}", x, y);
                // its certificate: radial, checked by the verifier, whose own
                // bound lies between the search's lower bound and the claim
                let cert = Certificate::new(a, b, &tol, &x);
                prop_assert_eq!(cert.is_some(), k > 1000);
                if let Some(c) = cert {
                    prop_assert!(c.is_radial());
                    let valid = verify(&c.to_json_string()).unwrap();
                    prop_assert!(valid.max_bound >= y.lo && valid.max_bound <= v, "{:?} {:?}", valid, y);
                }
            }
        }
    }
}

/// The radial proof's refusals: an end off its ray, a control point outside the
/// sector, a sweep above π, a chain with a gap; a chain through the centre (its
/// radial distance undefined there) is left to the search. A claimed tolerance
/// is decided either way, and a certificate of a radial result verifies.
#[test]
fn radial_proof_applies_only_where_its_statement_holds() {
    let arc = |from: &str, to: &str| {
        shape(&format!(
            r#"{{"arc": {{"center": [0, 0], "radius": 1, "from": {from}, "to": {to}}}}}"#
        ))
    };
    let quarter = arc("[1, 0]", "[0, 1]");
    let radial =
        |a: &ShapeDesc, b: &str, c: &Config| hausdorff(a, &shape(b), c).unwrap().radial.is_some();
    let c6 = cfg(1e-6);
    assert!(radial(&quarter, "M 1 0 C 1 0.5523 0.5523 1 0 1", &c6));
    assert!(radial(&quarter, "M 0 1 C 0.5523 1 1 0.5523 1 0", &c6)); // reversed
    assert!(!radial(&quarter, "M 1 0.01 C 1 0.5523 0.5523 1 0 1", &c6)); // off the ray
    assert!(!radial(&quarter, "M 1 0 C 1 0.5523 0.5523 1 -0.01 1", &c6)); // past the end ray
    assert!(!radial(&quarter, "M 1 0 C 1.1 -0.1 0.5523 1 0 1", &c6)); // a point below d0
    assert!(!radial(&quarter, "M 1 0 L 0.6 0.6 M 0.6 0.61 L 0 1", &c6)); // a gap
    let half = arc("[1, 0]", "[-1, 0]");
    assert!(radial(&half, "M 1 0 C 1 1.3333 -1 1.3333 -1 0", &c6));
    let three_quarters = arc("[1, 0]", "[0, -1]");
    assert!(!radial(&three_quarters, "M 1 0 C 1 2 -2 1 0 -1", &c6));
    // arcs of more than π, and whole circles, against chains of pieces that
    // each turn less: in either direction, from any start on a whole circle
    let k = "0.5523";
    let quarters = [
        format!("C 1 {k} {k} 1 0 1"),
        format!("C -{k} 1 -1 {k} -1 0"),
        format!("C -1 -{k} -{k} -1 0 -1"),
        format!("C {k} -1 1 -{k} 1 0"),
    ];
    let three_cubics = format!("M 1 0 {} {} {}", quarters[0], quarters[1], quarters[2]);
    assert!(radial(&three_quarters, &three_cubics, &c6));
    assert!(radial(
        &three_quarters,
        "M 0 -1 C -0.5523 -1 -1 -0.5523 -1 0 C -1 0.5523 -0.5523 1 0 1 C 0.5523 1 1 0.5523 1 0",
        &c6
    ));
    let circle =
        shape(r#"<svg xmlns="http://www.w3.org/2000/svg"><circle cx="0" cy="0" r="1"/></svg>"#);
    let four = format!("M 1 0 {}", quarters.join(" "));
    let from_top = format!(
        "M 0 1 {} {} {} {}",
        quarters[1], quarters[2], quarters[3], quarters[0]
    );
    for c in [&four, &from_top] {
        let r = hausdorff(&circle, &shape(c), &c6).unwrap();
        let s = hausdorff(
            &circle,
            &shape(c),
            &Config {
                radial: false,
                ..cfg(1e-3)
            },
        )
        .unwrap();
        assert!(r.radial.is_some(), "{c}");
        // the same d_H as one quarter's, inside the search's bounds
        assert!(
            r.lo <= s.hi && s.lo <= r.hi && (r.hi - 2.7607e-4).abs() < 1e-7,
            "{r:?} {s:?}"
        );
        // the claim 3/10000 and its radial certificate, which verifies
        let tol = lncert::Tolerance::new(q(3, 10_000)).unwrap();
        let claimed = Config {
            tol: Some(tol.clone()),
            ..cfg(1e-3)
        };
        let r = hausdorff(&circle, &shape(c), &claimed).unwrap();
        let cert = Certificate::new(&circle, &shape(c), &tol, &r).unwrap();
        assert!(cert.is_radial());
        let valid = verify(&cert.to_json_string()).unwrap();
        assert!(
            valid.max_bound >= s.lo && valid.max_bound <= 3e-4,
            "{valid:?}"
        );
    }
    assert!(
        !radial(&circle, &three_cubics, &c6),
        "three quarters of a circle"
    );
    assert!(
        !radial(&three_quarters, &four, &c6),
        "a whole turn against 270°"
    );
    // through the centre: refused; the search's bounds hold the true d_H = 1
    let through = hausdorff(&quarter, &shape("M 1 0 L 0 0 L 0 1"), &c6).unwrap();
    assert!(through.radial.is_none());
    assert!(through.lo <= 1.0 && 1.0 <= through.hi, "{through:?}");
    // a claimed tolerance is decided radially (certified, refuted); its
    // certificate is proven again by a proof the certificate language states
    let cubic = shape("M 1 0 C 1 0.5523 0.5523 1 0 1");
    for (t, holds) in [(q(277, 1_000_000), true), (q(276, 1_000_000), false)] {
        let tol = lncert::Tolerance::new(t).unwrap();
        let claimed = Config {
            tol: Some(tol.clone()),
            ..cfg(1e-3)
        };
        let r = hausdorff(&quarter, &cubic, &claimed).unwrap();
        assert!(r.radial.is_some());
        let v = tol.value();
        assert_eq!((r.hi <= v, r.lo > v), (holds, !holds), "{r:?}");
        let cert = Certificate::new(&quarter, &cubic, &tol, &r);
        assert_eq!(cert.is_some(), holds);
        if let Some(c) = cert {
            // a radial certificate (version 4), which the verifier checks
            assert!(c.is_radial());
            let text = c.to_json_string();
            let valid = verify(&text).unwrap_or_else(|e| panic!("{e}: {text}"));
            assert!(valid.max_bound >= r.lo && valid.max_bound <= v, "{valid:?}");
            assert_eq!(c.doc["version"], 4);
        }
    }
}

/// A version 4 document stating the radial proof of `d_H(arc, curve) ≤ tol`
/// over `per_piece` equal cells of each of the curve's `pieces` pieces.
fn radial_doc(
    arc: &ShapeDesc,
    curve: &ShapeDesc,
    tol: &str,
    pieces: usize,
    per_piece: i64,
) -> Value {
    let cells: Vec<Value> = (0..pieces)
        .flat_map(|p| {
            (0..per_piece).map(move |k| {
                serde_json::json!({"piece": p, "t": [q(k, per_piece).to_string(), q(k + 1, per_piece).to_string()]})
            })
        })
        .collect();
    serde_json::json!({
        "format": "lncert-hausdorff-certificate", "version": 4,
        "claim": "hausdorff(a, b) <= tol", "tol": tol,
        "a": arc.to_json(), "b": curve.to_json(),
        "radial": {"arc": "a", "cells": cells},
    })
}

/// Forged radial certificates: each states a **false** claim (its curve's
/// largest radial distance is below the tolerance, its true `d_H` far above),
/// and only the exact condition it breaks stands between it and acceptance.
/// Each is refused at the named field; so are broken covers, cells above the
/// claim and documents of the wrong shape.
#[test]
fn radial_certificates_are_refused_where_the_statement_fails() {
    let quarter =
        shape(r#"{"arc": {"center": [0, 0], "radius": 1, "from": [1, 0], "to": [0, 1]}}"#);
    let refused = |doc: &Value, at: &str, reason: &str| {
        let e = verify(&doc.to_string()).expect_err("a forged certificate was accepted");
        assert_eq!(e.at, at, "{e}");
        assert!(e.reason.contains(reason), "{e}");
    };
    // the true d_H of each curve is certified above twice its claim
    let far = |arc: &ShapeDesc, curve: &ShapeDesc, claim: f64| {
        let r = hausdorff(
            arc,
            curve,
            &Config {
                radial: false,
                ..cfg(1e-2)
            },
        )
        .unwrap();
        assert!(r.lo > 2.0 * claim, "{r:?}");
    };
    // a control point outside its piece's sector: the cubic leaves the
    // sector below d0 (radial distance 0.16, d_H 0.47)
    let poke = shape("M 1 0 C 1 -1.3 1.5 0.5 0 1");
    far(&quarter, &poke, 0.2);
    refused(
        &radial_doc(&quarter, &poke, "1/5", 1, 64),
        "b.beziers[0][1]",
        "outside the closed sector",
    );
    // a piece turning the other way: the chain dips below d0 along the
    // circle to (0.866, −0.5) and comes back, 0.52 from the arc there
    let dip = shape("M 1 0 Q 1 -0.268 0.866 -0.5 C 1.2509 0.1667 0.7698 1 0 1");
    far(&quarter, &dip, 0.1);
    refused(
        &radial_doc(&quarter, &dip, "1/10", 2, 64),
        "b.beziers[1]",
        "does not turn",
    );
    // an end off its ray: the 45°–90° half of the arc only
    let half = shape("M 0.70711 0.70711 C 0.51957 0.89464 0.26521 1 0 1");
    far(&quarter, &half, 0.1);
    refused(
        &radial_doc(&quarter, &half, "1/10", 1, 64),
        "b.beziers[0][0]",
        "does not sweep the arcs' directions",
    );
    // a gap in the chain: 0°–45° and 60°–90°
    let gap = shape(
        "M 1 0 C 1 0.26521 0.89464 0.51957 0.70711 0.70711 M 0.5 0.86603 C 0.59 0.8 0.17 1 0 1",
    );
    far(&quarter, &gap, 0.05);
    refused(
        &radial_doc(&quarter, &gap, "1/20", 2, 64),
        "b.beziers[1][0]",
        "continuous chain",
    );
    // a 270° arc against the chord of its missing quarter (turning 90° the
    // other way round): not its directions
    let three = shape(r#"{"arc": {"center": [0, 0], "radius": 1, "from": [1, 0], "to": [0, -1]}}"#);
    let line = shape("M 1 0 L 0 -1");
    refused(
        &radial_doc(&three, &line, "1", 1, 4),
        "b.beziers[0][0]",
        "does not sweep",
    );
    // a whole circle against three quarters of it
    let circle =
        shape(r#"<svg xmlns="http://www.w3.org/2000/svg"><circle cx="0" cy="0" r="1"/></svg>"#);
    let most = shape(
        "M 1 0 C 1 0.5523 0.5523 1 0 1 C -0.5523 1 -1 0.5523 -1 0 C -1 -0.5523 -0.5523 -1 0 -1",
    );
    far(&circle, &most, 0.1);
    refused(
        &radial_doc(&circle, &most, "1/10", 3, 64),
        "b.beziers[0][0]",
        "does not sweep",
    );
    // a chord through the centre, a half turn: refused on the cell reaching it
    let half_arc =
        shape(r#"{"arc": {"center": [0, 0], "radius": 1, "from": [1, 0], "to": [-1, 0]}}"#);
    let through = shape("M 1 0 L -1 0");
    refused(
        &radial_doc(&half_arc, &through, "2", 1, 4),
        "radial.cells[1]",
        "centre",
    );
    // a piece ending at the centre: no turn
    let stop = shape("M 1 0 L 0 0 L 0 1");
    refused(
        &radial_doc(&quarter, &stop, "2", 2, 4),
        "b.beziers[0]",
        "does not turn",
    );

    // the classical cubic, d_H = 2.7607e-4: 3/10000 holds, 2.76e-4 does not
    let cubic = shape("M 1 0 C 1 0.5523 0.5523 1 0 1");
    let good = radial_doc(&quarter, &cubic, "3/10000", 1, 256);
    let valid = verify(&good.to_string()).unwrap();
    assert!(
        valid.max_bound > 2.76e-4 && valid.max_bound <= 3e-4,
        "{valid:?}"
    );
    assert_eq!(valid.boxes, 256);
    let mut low = good.clone();
    low["tol"] = "69/250000".into(); // 2.76e-4
    assert!(verify(&low.to_string())
        .unwrap_err()
        .reason
        .contains("exceeds the tolerance"));
    // covers: a cell dropped, the last dropped, one too many, past 1
    let edited = |edit: &dyn Fn(&mut Vec<Value>)| {
        let mut d = good.clone();
        let mut c = d["radial"]["cells"].as_array().unwrap().clone();
        edit(&mut c);
        d["radial"]["cells"] = c.into();
        d
    };
    refused(
        &edited(&|c| drop(c.remove(7))),
        "radial.cells[7]",
        "gap or overlap",
    );
    refused(
        &edited(&|c| drop(c.pop())),
        "radial.cells",
        "not covered to its end",
    );
    let extra = |c: &mut Vec<Value>| c.push(serde_json::json!({"piece": 1, "t": ["0", "1"]}));
    refused(&edited(&extra), "radial.cells[256]", "already covered");
    let past = |c: &mut Vec<Value>| *c = vec![serde_json::json!({"piece": 0, "t": ["0", "2"]})];
    refused(&edited(&past), "radial.cells[0]", "at most at 1");
    // the arc named wrongly, a stray key, no cells
    let mut d = good.clone();
    d["radial"]["arc"] = "b".into();
    refused(&d, "radial.arc", "not a circular arc");
    // a union of arcs that is not one chain
    let broken = shape(
        r#"{"union": [{"arc": {"center": [0, 0], "radius": 1, "from": [1, 0], "to": [0, 1]}}, {"arc": {"center": [0, 0], "radius": 1, "from": [-1, 0], "to": [0, -1]}}]}"#,
    );
    refused(
        &radial_doc(&broken, &cubic, "1", 1, 4),
        "a.union[1]",
        "previous arc ends",
    );
    let mut d = good.clone();
    d["maps"] = serde_json::json!([]);
    refused(&d, "maps", "unknown key");
    let mut d = good.clone();
    d["radial"]["cells"] = serde_json::json!([]);
    refused(&d, "radial.cells", "non-empty");
}
