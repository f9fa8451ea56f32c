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
use crate::certify::piece::Pieces;
use crate::json::{parse, Limits};
use crate::scalar::Interval;
use crate::shape::ShapeDesc;
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
            Err(crate::shape::ShapeError { field, .. }) => field.clone(),
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

// ----- the box bound itself, against exact samples -----------------------------

use super::eval::check_box;
use crate::certify::search::{box_bound_from, SourceJets};
use crate::scalar::{rational_from_f64, Rational};
use proptest::prelude::*;

fn cases() -> u32 {
    std::env::var("LNCERT_PROPTEST_CASES")
        .ok()
        .and_then(|s| s.parse().ok())
        .unwrap_or(2000)
}

/// `|A(s) − B(τ(s))|²` exactly, for Bézier pieces with rational control points.
fn exact_gap2(a: &[(i64, i64)], b: &[(i64, i64)], s: &Rational, tau: &Rational) -> Rational {
    let eval = |p: &[(i64, i64)], t: &Rational| {
        let mut xs: Vec<(Rational, Rational)> = p
            .iter()
            .map(|&(x, y)| {
                (
                    Rational::from_integer(x.into()) / Rational::from_integer(8.into()),
                    Rational::from_integer(y.into()) / Rational::from_integer(8.into()),
                )
            })
            .collect();
        for n in (1..xs.len()).rev() {
            for i in 0..n {
                let (x0, y0) = xs[i].clone();
                let (x1, y1) = xs[i + 1].clone();
                xs[i] = (&x0 + t * (&x1 - &x0), &y0 + t * (&y1 - &y0));
            }
        }
        xs.swap_remove(0)
    };
    let (ax, ay) = eval(a, s);
    let (bx, by) = eval(b, tau);
    let (dx, dy) = (ax - bx, ay - by);
    &dx * &dx + &dy * &dy
}

fn shape_of(p: &[(i64, i64)]) -> String {
    let e = |v: i64| Rational::new(v.into(), 8.into()).to_string();
    let pts: Vec<String> = p
        .iter()
        .map(|&(x, y)| format!("[\"{}\", \"{}\"]", e(x), e(y)))
        .collect();
    format!("{{\"beziers\": [[{}]]}}", pts.join(", "))
}

proptest! {
    #![proptest_config(ProptestConfig { cases: cases(), ..ProptestConfig::default() })]

    /// Neither the search's box bound nor the verifier's is ever below
    /// `|A(s) − B(τ(s))|` at 33 exactly evaluated points of the box, for random
    /// cubics, boxes and (deliberately poor) foot maps `τ(s) = t + k (s − s_c)`.
    /// An upper bound that drops a term (say the slope of a mean-value form) fails
    /// here, in the search's code or in the verifier's.
    #[test]
    fn box_bounds_are_never_below_an_exact_sample(
        a in proptest::collection::vec((-16i64..16, -16i64..16), 2..5),
        b in proptest::collection::vec((-16i64..16, -16i64..16), 2..5),
        s0 in 0u32..64, len in 1u32..32, t_c in 8u32..56, k8 in -8i64..9,
    ) {
        let s1 = (s0 + len).min(64);
        prop_assume!(s1 > s0);
        let q = |n: i64, d: i64| Rational::new(n.into(), d.into());
        let (s0r, s1r) = (q(s0 as i64, 64), q(s1 as i64, 64));
        let (tr, kr) = (q(t_c as i64, 64), q(k8, 8));
        let half = (&s1r - &s0r) / q(2, 1);
        // keep τ(S) inside [0, 1]
        let reach = &half * if kr < q(0, 1) { -kr.clone() } else { kr.clone() };
        prop_assume!(&tr - &reach >= q(0, 1) && &tr + &reach <= q(1, 1));
        // the verifier's bound
        let (sa, sb) = (shape_of(&a), shape_of(&b));
        let va = read_shape(&parse(&sa, &Limits::DEFAULT).unwrap(), "a").unwrap();
        let vb = read_shape(&parse(&sb, &Limits::DEFAULT).unwrap(), "b").unwrap();
        let v = check_box(&va.pieces[0], &s0r, &s1r, &vb.pieces[0], vb.ends[0], &tr, &kr);
        // the search's bound (its box and foot map are the same dyadic numbers)
        let pa = ShapeDesc::parse(&sa).unwrap().pieces().unwrap();
        let pb = ShapeDesc::parse(&sb).unwrap().pieces().unwrap();
        let f = |r: &Rational| crate::scalar::Scalar::approx(r);
        let src = SourceJets::new(&pa[0], (f(&s0r), f(&s1r))).unwrap();
        let w = box_bound_from(&src, &pb[0], f(&tr), f(&kr));
        let sc = (&s0r + &s1r) / q(2, 1);
        for i in 0..=32 {
            let s = &s0r + (&s1r - &s0r) * q(i, 32);
            let tau = &tr + &kr * (&s - &sc);
            let g = exact_gap2(&a, &b, &s, &tau);
            for (who, bound) in [("verifier", v.as_ref().ok().copied()), ("search", w)] {
                if let Some(bd) = bound {
                    let bd = rational_from_f64(bd).unwrap();
                    prop_assert!(&bd * &bd >= g, "{who}: bound {} below the exact gap at s = {s}", bd);
                }
            }
        }
    }
}

proptest! {
    #![proptest_config(ProptestConfig { cases: cases(), ..ProptestConfig::default() })]

    /// Neither the parametric proof's box bound nor the verifier's map-box
    /// bound is ever below `|A(t) − B(φ(t))|` at 33 exactly evaluated points of
    /// the box, for random polynomial pieces, boxes and cubic maps `φ` (random
    /// Bernstein coefficients in `[0, 1]`, so deliberately poor maps).
    #[test]
    fn map_box_bounds_are_never_below_an_exact_sample(
        a in proptest::collection::vec((-16i64..16, -16i64..16), 2..5),
        b in proptest::collection::vec((-16i64..16, -16i64..16), 2..5),
        t0 in 0u32..64, len in 1u32..32, narrow in any::<bool>(),
        c in proptest::array::uniform4(0i64..=64),
    ) {
        let t1 = (t0 + len).min(64);
        prop_assume!(t1 > t0);
        let q = |n: i64, d: i64| Rational::new(n.into(), d.into());
        // wide boxes, where the direct enclosure wins, and narrow ones (and
        // nearly linear maps), where the Taylor bound from the centre does
        let den = if narrow { 64 * 64 } else { 64 };
        let (t0r, t1r) = (q(t0 as i64, den), q(t1 as i64, den));
        let cr = if narrow {
            let base = q(c[0], 64) * q(1, 2);
            [0, 1, 2, 3].map(|j| &base + q(c[j] + 64 * j as i64, 64 * 64 * 2))
        } else {
            c.map(|x| q(x, 64))
        };
        let (sa, sb) = (shape_of(&a), shape_of(&b));
        let va = read_shape(&parse(&sa, &Limits::DEFAULT).unwrap(), "a").unwrap();
        let vb = read_shape(&parse(&sb, &Limits::DEFAULT).unwrap(), "b").unwrap();
        // source A (parameter t), target B (parameter φ(t))
        let v = super::eval::check_map_box(&va.pieces[0], &t0r, &t1r, &vb.pieces[0], vb.ends[0], &cr);
        prop_assert!(v.is_ok(), "{v:?}");
        let pa = ShapeDesc::parse(&sa).unwrap().pieces().unwrap();
        let pb = ShapeDesc::parse(&sb).unwrap().pieces().unwrap();
        let f = |r: &Rational| crate::scalar::Scalar::approx(r);
        let w = crate::certify::param::box_bound(&pb[0], &pa[0], (f(&t0r), f(&t1r)), cr.clone().map(|x| f(&x)));
        for i in 0..=32 {
            let u = q(i, 32);
            let t = &t0r + (&t1r - &t0r) * &u;
            // φ(t) by exact de Casteljau at u
            let mut d = cr.to_vec();
            for n in (1..4).rev() {
                for j in 0..n {
                    d[j] = &d[j] + &u * (&d[j + 1] - &d[j]);
                }
            }
            let g = exact_gap2(&a, &b, &t, &d[0]);
            for (who, bound) in [("verifier", v.as_ref().ok().copied()), ("parametric", w)] {
                if let Some(bd) = bound {
                    let bd = rational_from_f64(bd).unwrap();
                    prop_assert!(&bd * &bd >= g, "{who}: bound {} below the exact gap at t = {t}", bd);
                }
            }
        }
    }
}
