//! `lncert::certify::verify_expecting` (issue 65): a valid certificate is
//! confirmed to state the shapes, the pen and the tolerance the user expects,
//! for every format that states them — a stroke certificate (circular and
//! elliptical pen), a stroke distance certificate, a Hausdorff certificate —
//! and each mismatch is invalid at the field that differs.

use lncert::certify::{hausdorff, verify_expecting, Certificate, Config, Expected};
use lncert::offset::{Angle, Pen};
use lncert::scalar::Rational;
use lncert::shape::ShapeDesc;
use lncert::stroke::{
    certificate, distance_certificate, distance_to_stroke, stroke, PenShape, StrokeOptions,
};

fn q(s: &str) -> Rational {
    lncert::parse_rational(s).unwrap()
}

fn at(text: &str, want: &Expected) -> String {
    verify_expecting(text, want).unwrap_err().at
}

#[test]
fn a_stroke_distance_certificate_is_confirmed_part_by_part() {
    let curve_text = "M 0 0 L 4 0";
    let curve = lncert::parse_curve(curve_text).unwrap();
    let curve_shape = ShapeDesc::parse(curve_text).unwrap();
    let r = q("1/2");
    let x = ShapeDesc::parse("M -0.5 -0.51 L 4.5 -0.51 L 4.5 0.51 L -0.5 0.51 Z").unwrap();
    let opts = StrokeOptions::new(r.clone(), "1e-2".parse().unwrap());
    let d = distance_to_stroke(&x, &curve, &opts, &Config::default()).unwrap();
    let tol: lncert::Tolerance = "1/4".parse().unwrap();
    let text = distance_certificate(&x, &d, &curve, &r, &tol)
        .unwrap()
        .to_string();
    let pen = PenShape::Circle(r.clone());
    let t = q("1/4");
    let all = Expected {
        a: Some(&x),
        b: Some(&curve_shape),
        pen: Some(&pen),
        tol: Some(&t),
    };
    let v = verify_expecting(&text, &all).unwrap();
    assert_eq!(v.tol, t);
    // each part of the statement, wrong
    let other_x = ShapeDesc::parse("M -0.5 -0.52 L 4.5 -0.51 L 4.5 0.51 L -0.5 0.51 Z").unwrap();
    let other_curve = ShapeDesc::parse("M 0 0 L 4 0.001").unwrap();
    let wide = PenShape::Circle(q("1/3"));
    let tight = q("1/5");
    assert_eq!(
        at(
            &text,
            &Expected {
                a: Some(&other_x),
                ..all.clone()
            }
        ),
        "shape_to_outline.a"
    );
    assert_eq!(
        at(
            &text,
            &Expected {
                b: Some(&other_curve),
                ..all.clone()
            }
        ),
        "outline_to_stroke.curve"
    );
    assert_eq!(
        at(
            &text,
            &Expected {
                pen: Some(&wide),
                ..all.clone()
            }
        ),
        "outline_to_stroke.radius"
    );
    assert_eq!(
        at(
            &text,
            &Expected {
                tol: Some(&tight),
                ..all.clone()
            }
        ),
        "tol"
    );
    // nothing expected: the certificate alone
    assert!(verify_expecting(&text, &Expected::default()).is_ok());
}

/// Two matrices are the same pen exactly when `M Mᵀ` agree: `M`, `−M` and
/// `M` times a rotation by 90° (the ellipse with the axes' names swapped) are
/// one pen; its transpose-like reflection across the diagonal is another.
#[test]
fn an_elliptical_pen_is_confirmed_as_a_set() {
    let x = lncert::parse_curve("M 0 0 C 1 1 2 1 3 0").unwrap();
    let pen = Pen::ellipse(&q("2"), &q("1"), &Angle::parse("90deg").unwrap()).unwrap();
    let m = pen.m.clone();
    let opts = StrokeOptions::with_pen(PenShape::Ellipse(pen.clone()), "1e-2".parse().unwrap());
    let s = stroke(&x, &opts).unwrap();
    let text = certificate(&x, &s, &q("1")).unwrap().to_string();
    let neg = |r: &Rational| -r.clone();
    let same = [
        pen.clone(),
        Pen::from_matrix([
            [neg(&m[0][0]), neg(&m[0][1])],
            [neg(&m[1][0]), neg(&m[1][1])],
        ])
        .unwrap(),
        // M R(90°): columns (m₁, m₀) with one sign flipped
        Pen::from_matrix([
            [m[0][1].clone(), neg(&m[0][0])],
            [m[1][1].clone(), neg(&m[1][0])],
        ])
        .unwrap(),
    ];
    for p in same {
        let p = PenShape::Ellipse(p);
        let want = Expected {
            pen: Some(&p),
            ..Default::default()
        };
        assert!(verify_expecting(&text, &want).is_ok(), "{p:?}");
    }
    let unrotated =
        PenShape::Ellipse(Pen::ellipse(&q("2"), &q("1"), &Angle::parse("0deg").unwrap()).unwrap());
    let disk = PenShape::Circle(q("2"));
    for p in [unrotated, disk] {
        let want = Expected {
            pen: Some(&p),
            ..Default::default()
        };
        assert_eq!(at(&text, &want), "pen", "{p:?}");
    }
}

#[test]
fn a_hausdorff_certificate_states_no_pen() {
    let a = ShapeDesc::parse("M 0 0 Q 0.5 0.5 1 0").unwrap();
    let b = ShapeDesc::parse("M 0 0 L 1 0").unwrap();
    let tol: lncert::Tolerance = "0.26".parse().unwrap();
    let cfg = Config {
        tol: Some(tol.clone()),
        parametric: false,
        ..Config::default()
    };
    let r = hausdorff(&a, &b, &cfg).unwrap();
    let text = Certificate::new(&a, &b, &tol, &r).unwrap().to_json_string();
    let pen = PenShape::Circle(q("1"));
    assert_eq!(
        at(
            &text,
            &Expected {
                pen: Some(&pen),
                ..Default::default()
            }
        ),
        "format"
    );
    let (loose, tight) = (q("1/2"), q("1/4"));
    assert!(verify_expecting(
        &text,
        &Expected {
            b: Some(&b),
            tol: Some(&loose),
            ..Default::default()
        }
    )
    .is_ok());
    assert_eq!(
        at(
            &text,
            &Expected {
                tol: Some(&tight),
                ..Default::default()
            }
        ),
        "tol"
    );
    // B alone, wrong
    let other = ShapeDesc::parse("M 0 0 L 2 0").unwrap();
    assert_eq!(
        at(
            &text,
            &Expected {
                b: Some(&other),
                ..Default::default()
            }
        ),
        "b"
    );
}
