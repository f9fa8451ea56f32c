//! Sets of stroke certificates (format `lncert-stroke-certificate-set`): a
//! set of valid members verifies with the largest member tolerance; a forged
//! member is refused at `members[k].certificate.…`; a malformed set at the
//! named field; `--against` is refused for a set.

// the helpers of the disk certificate's tests
use super::tests::{check, refused};
use crate::stroke::{certificate, certificate_set, stroke, StrokeOptions};
use serde_json::{json, Value};
use std::sync::OnceLock;

/// Two members: a segment at r 1/2, TOL 1/10, and a corner at r 1/4, TOL 1/20.
fn set() -> &'static Value {
    static SET: OnceLock<Value> = OnceLock::new();
    SET.get_or_init(|| {
        let members = [
            ("M 0 0 L 4 0", "1/2", "1e-1"),
            ("M 0 3 L 4 3 L 4 5", "1/4", "5e-2"),
        ]
        .iter()
        .map(|(path, r, tol)| {
            let x = crate::shape::parse_curve(path).unwrap();
            let r = crate::parse_rational(r).unwrap();
            let s = stroke(&x, &StrokeOptions::new(r.clone(), tol.parse().unwrap())).unwrap();
            assert!(s.proven());
            (path.to_string(), certificate(&x, &s, &r).unwrap())
        })
        .collect();
        certificate_set(members)
    })
}

#[test]
fn a_set_verifies_with_the_largest_member_tolerance() {
    let v = check(set()).unwrap();
    assert_eq!(v.tol, crate::parse_rational("1/10").unwrap());
    assert!(
        v.a.contains("2 stroked element(s) (M 0 0 L 4 0, M 0 3 L 4 3 L 4 5"),
        "{}",
        v.a
    );
    assert!(v.max_bound > 0.0 && v.max_bound <= 0.1);
    // the count is both members' parts and boxes
    let each: usize = set()["members"]
        .as_array()
        .unwrap()
        .iter()
        .map(|m| check(&m["certificate"]).unwrap().boxes)
        .sum();
    assert_eq!(v.boxes, each);
}

#[test]
fn a_forged_member_is_refused_at_its_field() {
    // the second member's tolerance below its parts' bounds
    let mut doc = set().clone();
    doc["members"][1]["certificate"]["tol"] = json!("1/5000");
    let e = refused(&doc);
    assert!(e.at.starts_with("members[1].certificate.cover["), "{e}");
    // the first member's radius changed
    let mut doc = set().clone();
    doc["members"][0]["certificate"]["radius"] = json!("1");
    assert!(refused(&doc).at.starts_with("members[0].certificate."));
    // a member of another format
    let mut doc = set().clone();
    doc["members"][0]["certificate"]["format"] = json!("lncert-hausdorff-certificate");
    assert_eq!(refused(&doc).at, "members[0].certificate.format");
    // a set inside a set
    let mut doc = set().clone();
    doc["members"][0]["certificate"] = set().clone();
    assert_eq!(refused(&doc).at, "members[0].certificate.format");
}

#[test]
fn a_malformed_set_is_refused_at_the_named_field() {
    type Edit<'a> = &'a dyn Fn(&mut Value);
    let cases: [(Edit, &str); 6] = [
        (&|d| d["members"] = json!([]), "members"),
        (&|d| d["members"] = json!({}), "members"),
        (&|d| d["claim"] = json!("all fine"), "claim"),
        (&|d| d["version"] = json!(2), "version"),
        (&|d| d["members"][0]["at"] = json!(3), "members[0].at"),
        (&|d| d["members"][1]["extra"] = json!(1), "members[1].extra"),
    ];
    for (edit, at) in cases {
        let mut doc = set().clone();
        edit(&mut doc);
        assert_eq!(refused(&doc).at, at);
    }
}

#[test]
fn against_is_refused_for_a_set() {
    let a = crate::shape::ShapeDesc::parse("M 0 0 L 1 0").unwrap();
    let e = crate::certify::verify_against(&set().to_string(), &a, &a).unwrap_err();
    assert_eq!(e.at, "format");
}
