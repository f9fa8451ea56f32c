//! Certified Hausdorff bounds (issue 4): soundness against independent exact
//! computations, certificates and their mutation tests.

use lncert::certify::verify::verify;
use lncert::certify::{hausdorff, Certificate, Config, ShapeDesc};
use lncert::scalar::parse_rational;

fn shape(s: &str) -> ShapeDesc {
    ShapeDesc::parse(s).unwrap()
}

#[test]
fn quadratic_against_segment_is_a_quarter() {
    let a = shape("M 0 0 Q 0.5 0.5 1 0");
    let b = shape("M 0 0 L 1 0");
    for rel in [1e-3, 1e-6, 1e-9] {
        let r = hausdorff(
            &a,
            &b,
            &Config {
                rel,
                ..Config::default()
            },
        )
        .unwrap();
        eprintln!(
            "rel {rel}: [{}, {}] boxes {} + {}",
            r.lo, r.hi, r.a_to_b.evaluated, r.b_to_a.evaluated
        );
        assert!(r.lo <= 0.25 && 0.25 <= r.hi, "{r:?}");
        assert!(r.hi - r.lo <= rel * r.hi);
    }
}
