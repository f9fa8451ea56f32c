//! The oracle shared by the `verify` and `verify_struct` fuzz targets
//! (included by each with `#[path]`).

use lncert::certify::{hausdorff, Config};
use lncert::shape::ShapeDesc;
use lncert::scalar::{rational_from_f64, Rational};
use serde_json::Value;
use std::collections::BTreeMap;
use std::sync::Mutex;
use std::time::{Duration, Instant};

/// The resource oracle (issue 64): `verify` runs `lncert::certify::verify::verify`
/// on `text` and the run must take at most `TIME_FACTOR` times as long as
/// reading the same bytes with serde_json, plus `TIME_FLOOR` (thread start-up,
/// a noisy shared machine). The verifier's work is bounded by the
/// certificate's size (48 units per byte of compact JSON plus 2²¹), so a run
/// past this is a finding: a loop the budget does not meter. Genuine
/// certificates take 5-10 times their reading time. `LNCERT_FUZZ_TIME_FACTOR`
/// overrides the factor (0 turns the oracle off, e.g. under valgrind).
pub const TIME_FACTOR: u32 = 200;
/// See [`TIME_FACTOR`].
pub const TIME_FLOOR: Duration = Duration::from_millis(250);

pub fn verify_timed(
    text: &str,
) -> Result<lncert::certify::verify::Valid, lncert::certify::verify::Invalid> {
    static FACTOR: std::sync::OnceLock<u32> = std::sync::OnceLock::new();
    let factor = *FACTOR.get_or_init(|| {
        std::env::var("LNCERT_FUZZ_TIME_FACTOR")
            .ok()
            .and_then(|v| v.parse().ok())
            .unwrap_or(TIME_FACTOR)
    });
    let start = Instant::now();
    let verdict = lncert::certify::verify::verify(text);
    let took = start.elapsed();
    if factor > 0 && took > TIME_FLOOR {
        let start = Instant::now();
        let _ = serde_json::from_str::<Value>(text);
        let read = start.elapsed();
        assert!(
            took <= read * factor + TIME_FLOOR,
            "resource oracle: verify took {took:?} on {} bytes, more than {factor} x the {read:?} of reading them + {TIME_FLOOR:?} (verdict {:?})",
            text.len(),
            verdict.as_ref().map(|v| &v.tol),
        );
    }
    verdict
}

/// An accepted certificate must state a true claim about canonical shapes.
///
/// The search is deterministic, so its lower bound is memoized per pair of
/// shapes (the same text of `a` and `b`): most accepted certificates speak
/// about the shapes of a seed, and the search dominates the cost otherwise.
pub fn check_accepted(text: &str, tol: &Rational) {
    static LOWER: Mutex<BTreeMap<String, (Rational, String)>> = Mutex::new(BTreeMap::new());
    let doc: Value = serde_json::from_str(text)
        .unwrap_or_else(|e| panic!("verify accepted a text serde_json cannot read: {e}"));
    if doc["format"] == "lncert-stroke-certificate" {
        return check_stroke(&doc, tol);
    }
    if doc["format"] == "lncert-stroke-certificate-set" {
        // every member was accepted: each member's claim must hold
        for m in doc["members"].as_array().expect("members") {
            let c = &m["certificate"];
            let t = lncert::parse_rational(c["tol"].as_str().expect("a tolerance")).expect("canonical");
            check_stroke(c, &t);
        }
        return;
    }
    if doc["format"] == "lncert-stroke-distance-certificate" {
        // both parts were accepted: each claim must hold (the sum follows)
        let part_tol = |d: &Value| {
            lncert::parse_rational(d["tol"].as_str().expect("a tolerance")).expect("canonical")
        };
        let h = &doc["shape_to_outline"];
        check_accepted(&h.to_string(), &part_tol(h));
        let s = &doc["outline_to_stroke"];
        return check_stroke(s, &part_tol(s));
    }
    let key = format!("{}\n{}", doc["a"], doc["b"]);
    let known = LOWER.lock().unwrap().get(&key).cloned();
    let (lo, what) = match known {
        Some(x) => x,
        None => {
            let mut shapes = Vec::new();
            for name in ["a", "b"] {
                let x = &doc[name];
                let s = ShapeDesc::from_value(x).unwrap_or_else(|e| {
                    panic!("verify accepted a certificate whose shape {name} does not parse: {e}; {name} = {x}")
                });
                assert_eq!(
                    &s.to_json(),
                    x,
                    "verify accepted a non-canonical shape {name} (to_json differs)"
                );
                shapes.push(s);
            }
            let (a, b) = (&shapes[0], &shapes[1]);
            // not the radial proof: the oracle of a radial certificate must
            // not share its argument
            let cfg = Config {
                rel: 1e-2,
                max_boxes: 2000,
                radial: false,
                ..Default::default()
            };
            let r = hausdorff(a, b, &cfg).expect("shapes accepted by verify must be searchable");
            let lo = rational_from_f64(r.lo).expect("a finite lower bound");
            let what = format!("{} / {}", a.summary(), b.summary());
            let mut memo = LOWER.lock().unwrap();
            if memo.len() >= 4096 {
                memo.clear();
            }
            memo.insert(key, (lo.clone(), what.clone()));
            (lo, what)
        }
    };
    assert!(
        &lo <= tol,
        "SOUNDNESS: verify accepted d_H <= {tol}, but the certified lower bound is {lo} ({what})\ncertificate: {text}",
    );
}

fn num(v: &Value) -> f64 {
    let r = lncert::parse_rational(v.as_str().expect("a rational string")).expect("canonical");
    lncert::scalar::Scalar::approx(&r)
}

fn bez(p: &[(f64, f64)], t: f64) -> (f64, f64) {
    let mut b = p.to_vec();
    for k in (1..b.len()).rev() {
        for i in 0..k {
            b[i] = (b[i].0 * (1.0 - t) + b[i + 1].0 * t, b[i].1 * (1.0 - t) + b[i + 1].1 * t);
        }
    }
    b[0]
}

fn pts(v: &Value) -> Vec<(f64, f64)> {
    v.as_array()
        .expect("points")
        .iter()
        .map(|p| (num(&p[0]), num(&p[1])))
        .collect()
}

/// An accepted stroke certificate: every sampled outline point `q` must have
/// `|dist(q, x) − r| ≤ tol` (a point within `tol` of `∂S`, where the distance
/// to the curve is `r`, has it; `dist` is 1-Lipschitz). The distance is taken
/// to a dense polyline of the curve, within its sampling gap.
///
/// An elliptical pen `M · disk(1)`: points and curve are mapped by `M⁻¹`
/// (floats), where `∂S` is at distance 1 from the curve and `dist(M⁻¹ ·, ·)`
/// is `‖M⁻¹‖₂`-Lipschitz (bounded by the Frobenius norm), so
/// `|dist(M⁻¹q, M⁻¹x) − 1| ≤ ‖M⁻¹‖_F tol`.
fn check_stroke(doc: &Value, tol: &Rational) {
    let mut tol = lncert::scalar::Scalar::approx(tol);
    let (r, map) = match doc.get("pen") {
        Some(pen) => {
            let m = &pen["ellipse"];
            let (a, b, c, d) = (num(&m[0][0]), num(&m[0][1]), num(&m[1][0]), num(&m[1][1]));
            let det = a * d - b * c;
            let inv = [[d / det, -b / det], [-c / det, a / det]];
            let fro = inv.iter().flatten().map(|x| x * x).sum::<f64>().sqrt();
            tol *= fro * (1.0 + 1e-9);
            (1.0, Some(inv))
        }
        None => (num(&doc["radius"]), None),
    };
    let pre = |q: (f64, f64)| match &map {
        Some(m) => (m[0][0] * q.0 + m[0][1] * q.1, m[1][0] * q.0 + m[1][1] * q.1),
        None => q,
    };
    let pts = |v: &Value| -> Vec<(f64, f64)> { pts(v).into_iter().map(pre).collect() };
    let mut curve = Vec::new();
    let mut gap = 0.0f64;
    for p in doc["curve"].as_array().expect("curve") {
        // a Bézier by its control points; an exact arc (a circular pen
        // only) sampled by angle from its circle, the way its flag says
        let at: Box<dyn Fn(f64) -> (f64, f64)> = match p.get("arc") {
            Some(a) => {
                let c = (num(&a["center"][0]), num(&a["center"][1]));
                let rho = num(&a["radius"]);
                let ang = |v: &Value| (num(&v[1]) - c.1).atan2(num(&v[0]) - c.0);
                let (t0, t1) = (ang(&a["from"]), ang(&a["to"]));
                let tau = std::f64::consts::TAU;
                let sweep = if a["clockwise"] == Value::Bool(true) {
                    -(t0 - t1).rem_euclid(tau)
                } else {
                    (t1 - t0).rem_euclid(tau)
                };
                Box::new(move |u| {
                    let t = t0 + sweep * u;
                    (c.0 + rho * t.cos(), c.1 + rho * t.sin())
                })
            }
            None => {
                let p = pts(p);
                Box::new(move |u| bez(&p, u))
            }
        };
        let mut prev = at(0.0);
        for k in 0..=400 {
            let q = at(k as f64 / 400.0);
            gap = gap.max(((q.0 - prev.0).powi(2) + (q.1 - prev.1).powi(2)).sqrt());
            prev = q;
            curve.push(q);
        }
    }
    let scale = curve.iter().fold(r, |m, q| m.max(q.0.abs()).max(q.1.abs()));
    let slack = gap + 1e-9 * scale;
    for c in doc["outline"].as_array().expect("outline") {
        for piece in c.as_array().expect("contour").iter().take(64) {
            let samples: Vec<(f64, f64)> = if let Some(b) = piece.get("bezier") {
                let p = pts(b);
                (0..=16).map(|k| bez(&p, k as f64 / 16.0)).collect()
            } else {
                let a = &piece["arc"];
                let c = (num(&a["center"][0]), num(&a["center"][1]));
                let f = pts(&Value::Array(vec![a["from"].clone(), a["to"].clone()]));
                f.into_iter().chain(std::iter::once(c)).take(2).collect()
            };
            for q in samples {
                let d = curve
                    .iter()
                    .map(|p| ((p.0 - q.0).powi(2) + (p.1 - q.1).powi(2)).sqrt())
                    .fold(f64::INFINITY, f64::min);
                assert!(
                    d >= r - tol - 1e-9 * scale && d <= r + tol + slack,
                    "SOUNDNESS: verify accepted a stroke certificate whose outline point ({}, {}) is at distance {d} from the curve, not within tol {tol} of r {r}",
                    q.0,
                    q.1
                );
            }
        }
    }
}
