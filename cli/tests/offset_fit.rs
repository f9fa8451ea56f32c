//! Fitted output (`Output::Cubic`, `Output::Quadratic`) and grid rounding
//! (`OffsetOptions::grid`): every fitted result is certified, independently
//! checked by dense samples of the exact curve computed directly, connected
//! exactly, G¹ inside each piece, and its union certificate verifies; grid
//! results consist of exact grid multiples; bad `--output`/`--grid` exit 2.

mod common;
use common::qs as q;
use common::{lncert, max_spacing, sampled_one_sided, tmp};

use lncert::certify::verify::verify;
use lncert::curve::{Bezier, V2};
use lncert::offset::{
    convolve, offset, union_certificate, OffsetError, OffsetOptions, OffsetResult, Output,
};
use lncert::offset::{kernels::pen_point, Angle, Pen};
use lncert::scalar::{rational_from_f64, Rational, Scalar};
use lncert_cli::reproduce::offsets::test_curves;

fn curve(name: &str) -> (Vec<Bezier<Rational>>, Vec<Rational>) {
    let (_, pieces, ds) = test_curves()
        .unwrap()
        .into_iter()
        .find(|c| c.0 == name)
        .unwrap();
    (pieces, ds)
}

/// The exact curve at parameter `t` of a float piece: `x + d N` or `x + pen point`.
enum Exact {
    Offset(f64),
    Pen([f64; 3], i8),
}

fn exact_point(x: &Bezier<f64>, t: f64, e: &Exact) -> V2<f64> {
    let d = x.hodograph().eval(&t);
    let l = d.norm2().sqrt();
    let n = V2::new(-d.y / l, d.x / l);
    let v = match e {
        Exact::Offset(r) => n.scale(r),
        Exact::Pen(qf, s) => pen_point(&n, *qf, *s).unwrap(),
    };
    x.eval(&t).add(&v)
}

/// Dense samples: the distance from each sample of one curve to the other's
/// samples exceeds the true distance by at most half the sample spacing, and
/// the true distance is ≤ d_H ≤ the certified bound.
fn check_samples(x: &[Bezier<Rational>], e: &Exact, r: &OffsetResult) {
    const N: usize = 600;
    for s in &r.segments {
        let xs = x[s.piece].map(|v| v.approx()).restrict(&s.t.0, &s.t.1);
        let exact: Vec<V2<f64>> = (0..=N)
            .map(|i| exact_point(&xs, i as f64 / N as f64, e))
            .collect();
        let approx: Vec<V2<f64>> = (0..=N)
            .map(|i| s.bezier.eval(&(i as f64 / N as f64)))
            .collect();
        let h1 = sampled_one_sided(&exact, &approx);
        let h2 = sampled_one_sided(&approx, &exact);
        let (sa, se) = (
            max_spacing(&approx) / 2.0 + 1e-9,
            max_spacing(&exact) / 2.0 + 1e-9,
        );
        assert!(
            h1 <= s.error.1 + sa,
            "exact→fit {h1} > {} + {sa}",
            s.error.1
        );
        assert!(
            h2 <= s.error.1 + se,
            "fit→exact {h2} > {} + {se}",
            s.error.1
        );
    }
}

/// Consecutive segments of one piece share their end point bit for bit, and
/// their tangent lines agree (G¹; the direction may reverse only at a cut at a
/// cusp of the exact curve).
fn check_joints(r: &OffsetResult) -> usize {
    let mut joints = 0;
    for w in r.segments.windows(2) {
        let (a, b) = (&w[0], &w[1]);
        if a.piece != b.piece || a.t.1 != b.t.0 {
            continue;
        }
        let (pa, pb) = (a.bezier.points(), b.bezier.points());
        assert_eq!(pa[pa.len() - 1], pb[0], "joint at t = {}", a.t.1);
        let ta = pa[pa.len() - 1].sub(&pa[pa.len() - 2]);
        let tb = pb[1].sub(&pb[0]);
        let sin = ta.cross(&tb) / (ta.norm2() * tb.norm2()).sqrt();
        assert!(sin.abs() < 1e-9, "tangents at t = {}: sin {sin}", a.t.1);
        joints += 1;
    }
    joints
}

/// The certificate of `r` verifies, and claims exactly `tol`.
fn certificate_verifies(x: &[Bezier<Rational>], r: &OffsetResult, tol: &Rational) {
    let cert = union_certificate(x, r)
        .unwrap()
        .expect("a certificate of a reached result");
    let v = verify(&cert.to_json_string());
    assert!(v.is_ok(), "{:?}", v.err());
    assert_eq!(&v.unwrap().tol, tol);
}

fn fitted(x: &[Bezier<Rational>], d: &Rational, tol: &str, out: Output) -> OffsetResult {
    let mut o = OffsetOptions::new(d.clone(), tol.parse().unwrap());
    o.output = out;
    offset(x, &o).unwrap()
}

#[test]
fn fitted_cubics_are_certified_sampled_and_connected() {
    for name in ["cubic_bezier", "doc_bspline"] {
        let (x, ds) = curve(name);
        for d in &ds {
            for tol in ["1e-2", "1e-4"] {
                let r = fitted(&x, d, tol, Output::Cubic);
                assert!(
                    r.reached()
                        && r.certified_hi <= r.tol.value()
                        && r.tol.value() < q(tol).approx(),
                    "{name} {d} {tol}"
                );
                assert_eq!(r.degree(), 3);
                assert!(r.segments.iter().all(|s| s.bezier.degree() == 3));
                check_samples(&x, &Exact::Offset(d.approx()), &r);
                check_joints(&r);
            }
        }
    }
}

/// The offset of a B-spline (C² at its knots) is one connected run in every
/// output: the segments on both sides of a knot share the offset point bit for
/// bit, so the papers' count is `Σ degree + 1` (before, the two pieces'
/// float normals differed in the last bits and every knot of the pawn started
/// a new run: 7 control points more at every TOL).
#[test]
fn b_spline_offsets_are_one_run_across_the_knots() {
    for name in ["pawn_bspline", "doc_bspline", "cross_bspline"] {
        let (x, ds) = curve(name);
        for d in &ds {
            for out in [Output::Native, Output::Cubic] {
                let r = fitted(&x, d, "1e-2", out);
                assert!(r.reached(), "{name} {d} {out:?}");
                let mut knots = 0;
                for w in r.segments.windows(2) {
                    let (a, b) = (&w[0], &w[1]);
                    if b.piece == a.piece + 1 && a.t.1 == 1.0 && b.t.0 == 0.0 {
                        let pa = a.bezier.points();
                        assert_eq!(
                            pa[pa.len() - 1],
                            b.bezier.points()[0],
                            "{name} {d} {out:?} knot {}",
                            b.piece
                        );
                        knots += 1;
                    }
                }
                assert_eq!(
                    knots + 1,
                    x.len(),
                    "{name} {d} {out:?}: every knot is a joint"
                );
                let degrees: usize = r.segments.iter().map(|s| s.bezier.degree()).sum();
                assert_eq!(r.control_points(), degrees + 1, "{name} {d} {out:?}");
            }
        }
    }
}

#[test]
fn fitted_quadratics_are_certified_sampled_and_connected() {
    let (x, ds) = curve("cubic_bezier");
    for d in &ds[..2] {
        let r = fitted(&x, d, "1e-3", Output::Quadratic);
        assert!(r.reached() && r.certified_hi <= 1e-3);
        assert_eq!(r.degree(), 2);
        check_samples(&x, &Exact::Offset(d.approx()), &r);
        assert!(check_joints(&r) > 0);
        certificate_verifies(&x, &r, &q("1e-3"));
    }
}

#[test]
fn fitted_union_certificate_verifies() {
    let (x, ds) = curve("cubic_bezier");
    let r = fitted(&x, &ds[0], "1e-3", Output::Cubic);
    certificate_verifies(&x, &r, &q("1e-3"));
    // the certificate is about the written numbers: forging one breaks it
    let mut forged = r.clone();
    let mut pts = forged.segments[0].bezier.points().to_vec();
    pts[1] = pts[1].add(&V2::new(0.25, 0.0));
    forged.segments[0].bezier = Bezier::new(pts);
    let cert = union_certificate(&x, &forged).unwrap().unwrap();
    assert!(verify(&cert.to_json_string()).is_err());
}

#[test]
fn native_is_the_default_and_unchanged_by_the_new_fields() {
    let (x, ds) = curve("cubic_bezier");
    let o = OffsetOptions::new(ds[0].clone(), common::tol(1e-3));
    assert_eq!(o.output, Output::Native);
    assert_eq!(o.grid, None);
    let r = offset(&x, &o).unwrap();
    assert_eq!(r.degree(), 6);
    let explicit = OffsetOptions {
        output: Output::Native,
        grid: None,
        ..o.clone()
    };
    assert_eq!(offset(&x, &explicit).unwrap(), r);
}

/// Every coordinate is an exact multiple of the grid: `p / grid` is an integer
/// (exact rationals, the numbers the certificate is about).
fn on_grid(r: &OffsetResult, grid: &Rational) {
    for s in &r.segments {
        for p in s.bezier.points() {
            for c in [p.x, p.y] {
                let k = rational_from_f64(c).unwrap() / grid;
                assert!(k.is_integer(), "{c} is not a multiple of {grid}");
            }
        }
    }
}

#[test]
fn grid_rounded_results_are_grid_multiples_and_proven() {
    let (x, ds) = curve("cubic_bezier");
    let grid = q("1/1024");
    for (out, deg) in [(Output::Cubic, 3), (Output::Native, 6)] {
        let mut o = OffsetOptions::new(ds[1].clone(), "1e-3".parse().unwrap());
        o.output = out;
        o.grid = Some(grid.clone());
        let r = offset(&x, &o).unwrap();
        assert!(r.reached() && r.certified_hi <= 1e-3);
        assert_eq!(r.degree(), deg);
        on_grid(&r, &grid);
        // rounding is deterministic: the shared end points stay shared
        for w in r.segments.windows(2) {
            if w[0].t.1 == w[1].t.0 {
                assert_eq!(w[0].bezier.points().last(), w[1].bezier.points().first());
            }
        }
        check_samples(&x, &Exact::Offset(ds[1].approx()), &r);
        certificate_verifies(&x, &r, &q("1e-3"));
    }
}

#[test]
fn grid_errors_name_the_field() {
    let (x, ds) = curve("cubic_bezier");
    let field = |g: &str, tol: f64| {
        let mut o = OffsetOptions::new(ds[0].clone(), common::tol(tol));
        o.grid = Some(q(g));
        match offset(&x, &o) {
            Err(OffsetError { field, .. }) => field,
            Ok(_) => "ok".to_string(),
        }
    };
    assert_eq!(field("1/1000", 1e-2), "grid"); // not dyadic
    assert_eq!(field("0", 1e-2), "grid");
    assert_eq!(field("-1/8", 1e-2), "grid");
    assert_eq!(field("1/64", 1e-2), "grid"); // moves by 1.1e-2 ≥ tol
    assert_eq!(field("1/256", 1e-2), "ok");
}

fn test_pen() -> Pen {
    Pen::ellipse(&q("0.3"), &q("0.1"), &Angle::parse("pi/6").unwrap()).unwrap()
}

#[test]
fn fitted_convolutions_are_certified_sampled_and_verified() {
    let (x, _) = curve("cubic_bezier");
    let pen = test_pen();
    for side in [1i8, -1] {
        for (out, deg) in [(Output::Cubic, 3), (Output::Quadratic, 2)] {
            let mut o = OffsetOptions::new(q("0"), common::tol(1e-3));
            o.output = out;
            let r = convolve(&x, &pen, side, &o).unwrap();
            let certified_tol = &r.convolution.as_ref().unwrap().certified_tol;
            assert!(r.reached() && r.certified_hi <= certified_tol.value());
            // the rotation margin is charged: certified below the tolerance
            assert!(certified_tol.exact() < r.tol.exact());
            assert_eq!(r.certified_tol(), certified_tol);
            assert_eq!(r.degree(), deg);
            check_samples(&x, &Exact::Pen(pen.q_f64(), side), &r);
            check_joints(&r);
            certificate_verifies(&x, &r, certified_tol.exact());
        }
    }
    // with a grid
    let mut o = OffsetOptions::new(q("0"), common::tol(1e-3));
    o.output = Output::Cubic;
    o.grid = Some(q("1/2048"));
    let r = convolve(&x, &pen, 1, &o).unwrap();
    assert!(r.reached());
    on_grid(&r, &q("1/2048"));
}

const CUBIC: &str = r#"{"bezier": [["-0.95","0.7"],["-0.3","1.6"],["0.9","-0.4"],["1.1","0.6"]]}"#;

#[test]
fn cli_output_and_grid() {
    let c = tmp("c.json", CUBIC);
    let cs = c.to_str().unwrap();
    let o = lncert(&[
        "offset",
        cs,
        "--distance",
        "0.4",
        "--tol",
        "1e-3",
        "--output",
        "cubic",
        "--grid",
        "1/2048",
        "--json",
    ]);
    assert_eq!(
        o.status.code(),
        Some(0),
        "{}",
        String::from_utf8_lossy(&o.stderr)
    );
    let doc: serde_json::Value = serde_json::from_slice(&o.stdout).unwrap();
    assert_eq!(doc["output"], "cubic");
    assert_eq!(doc["degree"], 3);
    assert_eq!(doc["grid"]["grid"], "1/2048");
    assert!(doc["grid"]["fit_tol"].as_f64().unwrap() < 1e-3);
    let o = lncert(&[
        "convolve",
        cs,
        "--ellipse",
        "0.3,0.1",
        "--tol",
        "1e-3",
        "--output",
        "quadratic",
        "--side",
        "plus",
        "--json",
    ]);
    assert_eq!(
        o.status.code(),
        Some(0),
        "{}",
        String::from_utf8_lossy(&o.stderr)
    );
    let doc: serde_json::Value = serde_json::from_slice(&o.stdout).unwrap();
    assert_eq!(doc["output"], "quadratic");
    assert_eq!(doc["sides"][0]["degree"], 2);
}

#[test]
fn cli_bad_output_or_grid_exits_2_naming_the_flag() {
    let c = tmp("c2.json", CUBIC);
    let cs = c.to_str().unwrap();
    let cases: [(&[&str], &str); 6] = [
        (&["--output", "quintic"], "--output"),
        (&["--grid", "1/1000"], "--grid"),
        (&["--grid", "0"], "--grid"),
        (&["--grid", "-1/2"], "--grid"),
        (&["--grid", "NaN"], "--grid"),
        (&["--grid", "1/16"], "--grid"), // rounding move ≥ tol
    ];
    for (extra, flag) in cases {
        for cmd in ["offset", "convolve"] {
            let mut args = vec![cmd, cs, "--tol", "1e-3"];
            if cmd == "offset" {
                args.extend(["--distance", "0.4"]);
            } else {
                args.extend(["--ellipse", "0.3,0.1"]);
            }
            args.extend(extra);
            let o = lncert(&args);
            let err = String::from_utf8_lossy(&o.stderr);
            assert_eq!(o.status.code(), Some(2), "{cmd} {extra:?}: {err}");
            assert!(err.contains(flag), "{cmd} {extra:?}: {err}");
        }
    }
}

/// `smooth_kinks`: a corner whose tangent turns by 0.001 rad is absorbed on
/// both sides (its offset ends are 5e-4 apart, the tolerance 1e-3): the two
/// segments meet at one point, the certificate (with the exact join arc on the
/// convex side) verifies, and dense samples of that arc, computed directly,
/// lie within the tolerance of the output. Without the option the corner keeps
/// its arc or overlap.
#[test]
fn near_smooth_corners_are_absorbed_and_proven() {
    let x = lncert::shape::parse_curve("M 0 0 C 1 0 2 0 3 0 C 4 0.001 5 0.002 6 0.003").unwrap();
    for d in ["1/2", "-1/2"] {
        let mut o = OffsetOptions::new(q(d), "1/1000".parse().unwrap());
        o.output = Output::Cubic;
        let kept = offset(&x, &o).unwrap();
        assert_eq!(kept.corners.len(), 1);
        assert!(!kept.corners[0].absorbed);
        o.smooth_kinks = true;
        let r = offset(&x, &o).unwrap();
        assert!(r.reached() && r.certified_hi <= 1e-3);
        assert_eq!(r.corners.len(), 1);
        assert!(r.corners[0].absorbed, "d = {d}");
        assert!(lncert::offset::join_arcs(&r).is_empty());
        // the segments on both sides of the corner meet exactly
        let ia = r.segments.iter().rposition(|s| s.piece == 0).unwrap();
        let ib = r.segments.iter().position(|s| s.piece == 1).unwrap();
        let (pa, pb) = (
            r.segments[ia].bezier.points(),
            r.segments[ib].bezier.points(),
        );
        assert_eq!(pa[pa.len() - 1], pb[0]);
        certificate_verifies(&x, &r, &q("1/1000"));
        // the exact join arc (d < 0: the convex side) near the output
        if d == "-1/2" {
            let arcs = lncert::offset::absorbed_arcs(&r);
            assert_eq!(arcs.len(), 1);
            let out: Vec<V2<f64>> = r
                .segments
                .iter()
                .flat_map(|s| (0..=400).map(move |i| s.bezier.eval(&(i as f64 / 400.0))))
                .collect();
            // normals of the two pieces at the corner (3, 0), side d = -1/2
            let (n0, n1) = ((0.0f64, 1.0f64), (-0.001f64, 1.0f64));
            for i in 0..=20 {
                let w = i as f64 / 20.0;
                let (nx, ny) = (n0.0 + w * (n1.0 - n0.0), n0.1 + w * (n1.1 - n0.1));
                let l = nx.hypot(ny);
                let p = V2::new(3.0 - 0.5 * nx / l, -0.5 * ny / l);
                let dmin = out
                    .iter()
                    .map(|q| p.sub(q).norm2().sqrt())
                    .fold(f64::INFINITY, f64::min);
                assert!(dmin <= 1e-3, "arc point {p:?} is {dmin} from the output");
            }
        }
    }
}
