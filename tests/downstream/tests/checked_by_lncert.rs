//! The user's claims, proven (or refuted) by lncert through its root API.

use lncert::gen::{strategy, BezierCase};
use lncert::{hausdorff, parse_rational, verify, Certificate, HausdorffConfig, ShapeDesc, Tolerance};
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
        // one tolerance for the proof and the certificate: exactly the float
        let tol = Tolerance::from_f64(claim)?;
        let cfg = HausdorffConfig { tol: Some(tol.clone()), ..Default::default() };
        let proof = hausdorff(&arc, &cubic, &cfg)?;
        assert!(proof.hi <= claim, "r = {r}: not proven ({})", proof.hi);
        let cert = Certificate::new(&arc, &cubic, &tol, &proof).expect("a certificate");
        assert_eq!(&verify(&cert.to_json_string())?.tol, tol.exact());
        let too_small = HausdorffConfig { tol: Some(Tolerance::from_f64(claim / 10.0)?), ..Default::default() };
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

/// Every engine's error converts into `lncert::Error` with `?`, naming the
/// field: shapes and curves, Hausdorff bounds, offsets, strokes, the seeds'
/// kernels, the tangency solver and its raster and expression parser, the
/// certificate verifier, and exact numbers.
#[test]
fn question_mark_works_across_every_engine() {
    use lncert::scalar::Rational;
    let q = |s: &str| parse_rational(s).unwrap();
    let zero = || -> Rational { q("0") };
    type R = Result<(), lncert::Error>;
    let curve = || lncert::parse_curve("M 0 0 C 1 1 2 1 3 0").unwrap();
    let cases: Vec<(&str, &str, Box<dyn Fn() -> R>)> = vec![
        ("parse_curve", "SVG path data, byte 9", Box::new(|| lncert::parse_curve("M 0 0 Q 1").map(drop).map_err(Into::into))),
        ("shape", "arc.radius", Box::new(|| {
            ShapeDesc::parse(r#"{"arc": {"center": [0, 0], "radius": 0, "from": [1, 0], "to": [0, 1]}}"#)?;
            Ok(())
        })),
        ("number", "\"one half\"", Box::new(|| {
            parse_rational("one half")?;
            Ok(())
        })),
        ("hausdorff", "rel", Box::new(|| {
            let a = ShapeDesc::parse("M 0 0 L 1 0")?;
            hausdorff(&a, &a, &HausdorffConfig { rel: 2.0, ..Default::default() })?;
            Ok(())
        })),
        ("tolerance", "tol", Box::new(|| {
            Tolerance::from_f64(-1.0)?;
            Ok(())
        })),
        ("offset", "tol", Box::new(move || {
            let tiny: Tolerance = "1e-300".parse()?;
            lncert::offset(&curve(), &lncert::OffsetOptions::new(q("1/4"), tiny))?;
            Ok(())
        })),
        ("stroke", "radius", Box::new(move || {
            lncert::stroke(&curve(), &lncert::StrokeOptions::new(zero(), "1e-2".parse()?))?;
            Ok(())
        })),
        ("ln kernel", "b0,bm,b3", Box::new(move || {
            let p = |x: &str| lncert::V2::new(q(x), q("0"));
            lncert::ln::cubic::LnFrame::new(p("0"), p("1"), p("2"))?;
            Ok(())
        })),
        ("tangency", "r", Box::new(move || {
            lncert::TangencySystem::new(q("1"), q("0"), q("1"), zero(), zero(), zero())?;
            Ok(())
        })),
        ("expression", "expression", Box::new(|| {
            lncert::tangency::parse_poly2("x^^2")?;
            Ok(())
        })),
        ("raster", "deg_x", Box::new(|| {
            lncert::tangency::raster::DensePoly2::new(99, 0, vec![0.0; 100])?;
            Ok(())
        })),
        ("verify", "format", Box::new(|| {
            verify("{}")?;
            Ok(())
        })),
    ];
    for (engine, field, run) in cases {
        let e = run().expect_err(engine);
        assert_eq!(e.field, field, "{engine}: {e}");
        assert!(!e.reason.is_empty(), "{engine}: {e:?}");
        assert_eq!(e.to_string(), format!("invalid `{}`: {}", e.field, e.reason));
    }
}
