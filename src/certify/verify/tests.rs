//! The shape language has one meaning: the user-language reader
//! ([`ShapeDesc::parse`]) and the verifier's canonical reader
//! ([`read_canonical_shape`]) against one corpus of valid and invalid shape
//! documents (`tests/data/shape_corpus.json`: every documented key, every limit).
//!
//! For each document the corpus gives the verdict of each reader (`"ok"` or the
//! field an error must name). Where the canonical reader accepts, the user
//! reader must accept too, write the document back unchanged (the canonical
//! form is a fixpoint) and evaluate to the same points; where the user reader
//! accepts, its canonical form must be accepted by the canonical reader and
//! mean the same points.

use super::read::read_shape;
use super::read_canonical_shape;
use crate::certify::jet::Jet;
use crate::certify::ShapeDesc;
use crate::json::{parse, Limits};
use crate::scalar::Interval;
use serde_json::Value;

const CORPUS: &str = include_str!("../../../tests/data/shape_corpus.json");

fn text_of(doc: &Value) -> String {
    match doc {
        Value::String(s) => s.clone(),
        other => other.to_string(),
    }
}

/// Both readers' points agree (their enclosures overlap) at parameters across
/// each piece's inner domain.
fn same_points(user: &ShapeDesc, canonical_text: &str) {
    let doc = parse(canonical_text, &Limits::DEFAULT).unwrap();
    let v = read_shape(&doc, "").unwrap();
    let pieces = user.pieces().unwrap();
    assert_eq!(pieces.len(), v.pieces.len());
    for (p, q) in pieces.iter().zip(&v.pieces) {
        for k in 0..=8 {
            let t = p.inner.1 * k as f64 / 8.0;
            let ti = Interval::try_from((t, t)).unwrap();
            let Some((x, y)) = p.iv.eval(Jet::variable(ti)) else {
                continue;
            };
            let Some([qx, qy]) = q.point_at(ti) else {
                continue;
            };
            assert!(
                !x.v.disjoint(qx) && !y.v.disjoint(qy),
                "{canonical_text}: t = {t}: search ({:?}, {:?}) vs verifier ({qx:?}, {qy:?})",
                x.v,
                y.v
            );
        }
    }
}

#[test]
fn both_readers_follow_the_corpus() {
    let corpus: Vec<Value> = serde_json::from_str(CORPUS).unwrap();
    assert!(corpus.len() >= 50);
    let mut failures = Vec::new();
    for entry in &corpus {
        let note = entry["note"].as_str().unwrap();
        let text = text_of(&entry["doc"]);
        let (want_user, want_canon) = (
            entry["user"].as_str().unwrap(),
            entry["canonical"].as_str().unwrap(),
        );
        let user = ShapeDesc::parse(&text);
        let canon = read_canonical_shape(&text);
        let got_user = match &user {
            Ok(_) => "ok".to_string(),
            Err(crate::certify::CertifyError::Input { field, .. }) => field.clone(),
        };
        let got_canon = match &canon {
            Ok(_) => "ok".to_string(),
            Err(e) => e.at.clone(),
        };
        if got_user != want_user || got_canon != want_canon {
            failures.push(format!(
                "{note}: user reader {got_user} (want {want_user}), canonical reader {got_canon} (want {want_canon}); {:?} / {:?}",
                user.as_ref().err(),
                canon.as_ref().err()
            ));
            continue;
        }
        if let Ok(s) = &user {
            let written = s.to_json().to_string();
            assert!(
                read_canonical_shape(&written).is_ok(),
                "{note}: the canonical form {written} is refused"
            );
            same_points(s, &written);
            if canon.is_ok() {
                // accepted by both: the document *is* its canonical form
                let doc: Value = serde_json::from_str(&text).unwrap();
                assert_eq!(s.to_json(), doc, "{note}: not a fixpoint");
                same_points(s, &text);
            }
        }
    }
    assert!(failures.is_empty(), "{}", failures.join("\n"));
}
