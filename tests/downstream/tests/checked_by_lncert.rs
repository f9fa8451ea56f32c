//! The user's claims, proven (or refuted) by lncert through its root API.

use lncert::gen::{strategy, BezierCase};
use lncert::{hausdorff, parse_rational, verify, Certificate, HausdorffConfig, ShapeDesc};
use lncert_downstream::{bezier_point, quarter_circle_cubic, QUARTER_CIRCLE_CLAIM};
use proptest::prelude::*;

fn cubic_shape(p: [[f64; 2]; 4]) -> ShapeDesc {
    // the f64 control points, written exactly (Rust prints the shortest
    // decimal that reads back to the same float, which lncert reads exactly)
    let pts: Vec<String> = p.iter().map(|q| format!("[{:?}, {:?}]", q[0], q[1])).collect();
    ShapeDesc::parse(&format!("{{\"bezier\": [{}]}}", pts.join(", "))).unwrap()
}

/// The claimed tolerance holds, with a certificate that re-checks; a claim
/// ten times smaller is refuted.
#[test]
fn quarter_circle_claim_is_proven() -> Result<(), lncert::Error> {
    for r in [1.0, 0.001, 250.0] {
        let arc = ShapeDesc::parse(&format!(
            "{{\"arc\": {{\"center\": [0, 0], \"radius\": {r:?}, \"from\": [1, 0], \"to\": [0, 1]}}}}"
        ))?;
        let cubic = cubic_shape(quarter_circle_cubic(r));
        let claim = QUARTER_CIRCLE_CLAIM * r;
        let cfg = HausdorffConfig { tol: Some(claim), ..Default::default() };
        let proof = hausdorff(&arc, &cubic, &cfg)?;
        assert!(proof.hi <= claim, "r = {r}: not proven ({})", proof.hi);
        let tol = parse_rational(&format!("{claim:?}"))?;
        let cert = Certificate::new(&arc, &cubic, &tol, &proof).expect("a certificate");
        verify(&cert.to_json_string())?;
        let too_small = HausdorffConfig { tol: Some(claim / 10.0), ..Default::default() };
        let refuted = hausdorff(&arc, &cubic, &too_small)?;
        assert!(refuted.lo > claim / 10.0, "r = {r}: a false claim was not refuted");
    }
    Ok(())
}

/// Bad input is a typed error naming the field, through the one root error type.
#[test]
fn bad_input_is_one_error_type() {
    let e: lncert::Error = ShapeDesc::parse(r#"{"arc": {"center": [0, 0], "radius": -1, "from": [1, 0], "to": [0, 1]}}"#)
        .unwrap_err()
        .into();
    assert!(e.field.contains("radius"), "{e}");
}

proptest! {
    #![proptest_config(ProptestConfig { cases: 256, ..ProptestConfig::default() })]

    /// The user's f64 de Casteljau against lncert's exact evaluation, on
    /// lncert's generated curves (planted near-degeneracies, 1e-8 to 1e8).
    #[test]
    fn float_de_casteljau_is_accurate(c in strategy::<BezierCase>(), k in 0u32..=16) {
        let exact = c.exact().unwrap();
        let t = lncert::Rational::new(k.into(), 16.into());
        let e = exact.eval(&t);
        let p: Vec<[f64; 2]> = c.points.clone();
        let f = bezier_point(&p, k as f64 / 16.0);
        let scale = p.iter().flat_map(|q| q.iter()).fold(1.0f64, |m, x| m.max(x.abs()));
        for (fx, ex) in [(f[0], &e.x), (f[1], &e.y)] {
            let err = lncert::scalar::rational_from_f64(fx).unwrap() - ex.clone();
            let bound = lncert::scalar::rational_from_f64(1e-12 * scale).unwrap();
            prop_assert!(-bound.clone() <= err && err <= bound, "error {} above {}", err, bound);
        }
    }
}
