//! Input arcs in stroke certificates: the families derived from an exact
//! arc hold the stroke boundary sampled without the checker; the arc's
//! outside test agrees with distances sampled from the circle; forged
//! certificates about arcs are refused at the field they touch.

use super::geom::{ic, outside_arc, ConeArc, P};
use super::tests::{check, q, qv, refused};
use super::{CurvePiece, Input};
use crate::certify::verify::Invalid;
use crate::scalar::{Interval, Rational, Scalar};
use crate::stroke::{parse_path, stroke_path, PathPiece, StrokeOptions};
use serde_json::{json, Value};
use std::sync::OnceLock;

type F2 = (f64, f64);

/// The cases: `(path, radius, tol)`; the last pen is wider than its arcs.
const CASES: [(&str, &str, &str); 4] = [
    (
        r#"<svg><rect x="0" y="0" width="10" height="6" rx="2"/></svg>"#,
        "1",
        "1e-2",
    ),
    (r#"<svg><circle cx="1" cy="2" r="3"/></svg>"#, "1/2", "1e-2"),
    ("M 2 0 A 2 2 0 0 1 -2 0 L -2 -3", "1/2", "1e-2"),
    ("M 0 0 A 1 1 0 0 1 2 0 A 1 1 0 0 0 4 0", "3/2", "1e-2"),
];
const RECT: usize = 0;
const CIRCLE: usize = 1;
const HALF: usize = 2;

struct Fixture {
    path: Vec<PathPiece>,
    r: Rational,
    cert: Value,
}

static FIXTURES: [OnceLock<Fixture>; 4] = [const { OnceLock::new() }; 4];

fn fixture(k: usize) -> &'static Fixture {
    FIXTURES[k].get_or_init(|| {
        let (src, r, tol) = CASES[k];
        let (path, rest) = parse_path(src).unwrap();
        assert!(rest.is_empty());
        let r = q(r);
        let s = stroke_path(&path, &StrokeOptions::new(r.clone(), tol.parse().unwrap())).unwrap();
        assert!(s.proven(), "{src}: {:?} {:?}", s.a, s.b);
        let cert = *s.certificate.expect("a certificate");
        Fixture { path, r, cert }
    })
}

/// The exact path as a dense float polyline per piece (arcs by angle from
/// their circle, Béziers by de Casteljau).
fn polylines(path: &[PathPiece], n: usize) -> Vec<Vec<F2>> {
    path.iter()
        .map(|p| match p {
            PathPiece::Bezier(b) => {
                let f = b.map(Scalar::approx);
                (0..=n)
                    .map(|k| {
                        let v = f.eval_fast(k as f64 / n as f64);
                        (v.x, v.y)
                    })
                    .collect()
            }
            PathPiece::Arc(a) => crate::stroke::Piece::Arc(a.clone()).sample(n),
        })
        .collect()
}

fn seg_dist(p: F2, a: F2, b: F2) -> f64 {
    let (dx, dy) = (b.0 - a.0, b.1 - a.1);
    let l2 = dx * dx + dy * dy;
    let t = if l2 > 0.0 {
        (((p.0 - a.0) * dx + (p.1 - a.1) * dy) / l2).clamp(0.0, 1.0)
    } else {
        0.0
    };
    (p.0 - a.0 - t * dx).hypot(p.1 - a.1 - t * dy)
}

fn poly_dist(polys: &[Vec<F2>], p: F2) -> f64 {
    polys
        .iter()
        .flat_map(|pl| pl.windows(2).map(move |w| seg_dist(p, w[0], w[1])))
        .fold(f64::INFINITY, f64::min)
}

fn curve_of(path: &[PathPiece]) -> Vec<CurvePiece> {
    crate::stroke::path::curve_pieces(path).unwrap()
}

#[test]
fn arc_families_hold_the_sampled_stroke_boundary() {
    // ∂S sampled without the checker: points y + r·e (y on the exact path,
    // e one of 64 directions) whose sampled distance to the path is r; each
    // must lie on a family the checker derives from the curve
    for (k, (src, r, _)) in CASES.iter().enumerate() {
        let (path, _) = parse_path(src).unwrap();
        let r = q(r);
        let rf = r.approx();
        let fams = Input::with_pieces(curve_of(&path), r, "curve")
            .unwrap()
            .families();
        let fam_polys: Vec<Vec<F2>> = fams
            .iter()
            .map(|f| {
                (0..=1000)
                    .map(|m| {
                        let v = f.path.val(ic(m as f64 / 1000.0)).expect("a regular family");
                        (v[0].mid(), v[1].mid())
                    })
                    .collect()
            })
            .collect();
        let fine = polylines(&path, 4000);
        let (mut on, mut worst) = (0, 0.0f64);
        for (piece, pl) in path.iter().zip(polylines(&path, 60)) {
            for (i, y) in pl.iter().enumerate() {
                // the two unit normals (exact directions in floats), and 64
                // directions (caps and joins)
                let n = match piece {
                    PathPiece::Arc(a) => {
                        let rho = a.radius.approx();
                        (
                            (y.0 - a.center.x.approx()) / rho,
                            (y.1 - a.center.y.approx()) / rho,
                        )
                    }
                    PathPiece::Bezier(b) => {
                        let h = b.map(Scalar::approx).hodograph();
                        let v = h.eval_fast(i as f64 / 60.0);
                        let l = v.x.hypot(v.y);
                        (-v.y / l, v.x / l)
                    }
                };
                let mut es: Vec<F2> = vec![n, (-n.0, -n.1)];
                for e in 0..64 {
                    let a = std::f64::consts::TAU * (e as f64 + 0.25) / 64.0;
                    es.push((a.cos(), a.sin()));
                }
                for e in es {
                    let p = (y.0 + rf * e.0, y.1 + rf * e.1);
                    if poly_dist(&fine, p) < rf - 1e-6 {
                        continue;
                    }
                    on += 1;
                    worst = worst.max(poly_dist(&fam_polys, p));
                }
            }
        }
        assert!(on >= 100, "case {k}: {on} boundary samples");
        assert!(
            worst < 1e-4,
            "case {k}: a boundary point {worst} off the families"
        );
    }
}

/// A small deterministic generator (no dependence on the engine).
struct Lcg(u64);
impl Lcg {
    fn next(&mut self) -> f64 {
        self.0 = self
            .0
            .wrapping_mul(6364136223846793005)
            .wrapping_add(1442695040888963407);
        (self.0 >> 11) as f64 / (1u64 << 53) as f64
    }
}

#[test]
fn the_arc_outside_test_agrees_with_sampled_distances() {
    // arcs of radius 1 about 0 between Pythagorean directions, sweeps below
    // π either way; points near the arc, near its circle elsewhere, inside
    let dirs: [(i64, i64, i64); 8] = [
        (5, 3, 4),
        (5, -3, 4),
        (5, -4, -3),
        (13, 5, 12),
        (13, -12, 5),
        (25, 7, 24),
        (25, -24, -7),
        (17, 15, -8),
    ];
    let mut g = Lcg(7);
    let (mut accepted, mut refused_far) = (0, 0);
    for (i, a) in dirs.iter().enumerate() {
        for b in &dirs[i + 1..] {
            let (u, v): (F2, F2) = (
                (a.1 as f64 / a.0 as f64, a.2 as f64 / a.0 as f64),
                (b.1 as f64 / b.0 as f64, b.2 as f64 / b.0 as f64),
            );
            let cr = u.0 * v.1 - u.1 * v.0;
            if cr == 0.0 {
                continue;
            }
            let turn = cr.signum();
            let qd = |d: &(i64, i64, i64)| {
                [
                    Rational::new(d.1.into(), d.0.into()),
                    Rational::new(d.2.into(), d.0.into()),
                ]
            };
            let arc = ConeArc {
                c: [ic(0.0), ic(0.0)],
                r: ic(1.0),
                a: super::geom::ip(&qd(a)),
                b: super::geom::ip(&qd(b)),
            };
            // the exact arc, sampled by angle the short way
            let (t0, t1) = (u.1.atan2(u.0), v.1.atan2(v.0));
            let mut sw = t1 - t0;
            while sw > std::f64::consts::PI {
                sw -= std::f64::consts::TAU;
            }
            while sw < -std::f64::consts::PI {
                sw += std::f64::consts::TAU;
            }
            let samples: Vec<F2> = (0..=20000)
                .map(|k| {
                    let t = t0 + sw * k as f64 / 20000.0;
                    (t.cos(), t.sin())
                })
                .collect();
            for _ in 0..300 {
                let p: F2 = ((g.next() - 0.5) * 5.0, (g.next() - 0.5) * 5.0);
                let big_r = 0.05 + g.next() * 1.2;
                let d = samples
                    .iter()
                    .map(|s| (s.0 - p.0).hypot(s.1 - p.1))
                    .fold(f64::INFINITY, f64::min);
                let pi: P = [ic(p.0), ic(p.1)];
                let r2 = Interval::try_from((big_r * big_r, big_r * big_r)).unwrap();
                match outside_arc(pi, 0, &arc, turn, r2) {
                    // sampled d ≥ the true distance > R
                    Ok(()) => {
                        accepted += 1;
                        assert!(
                            d > big_r,
                            "accepted at sampled distance {d} ≤ R {big_r}: p {p:?}"
                        );
                    }
                    // the true distance ≥ d − (sampling step ≤ 2e-4) must
                    // not clearly exceed R
                    Err(_) => {
                        assert!(
                            d - 2e-4 <= big_r * (1.0 + 1e-9) + 1e-9,
                            "refused at distance {d} > R {big_r}: p {p:?}"
                        );
                        refused_far += 1;
                    }
                }
            }
        }
    }
    assert!(
        accepted > 1000 && refused_far > 1000,
        "{accepted} {refused_far}"
    );
}

fn arc_index(cert: &Value) -> usize {
    cert["curve"]
        .as_array()
        .unwrap()
        .iter()
        .position(|p| p.get("arc").is_some())
        .expect("an input arc")
}

#[track_caller]
fn refused_at(doc: &Value, prefix: &str) -> Invalid {
    let e = refused(doc);
    assert!(
        e.at.starts_with(prefix),
        "refused at `{}` ({}), expected at `{prefix}…`",
        e.at,
        e.reason
    );
    e
}

#[test]
fn arc_certificates_verify_and_forged_arcs_are_refused() {
    for k in 0..CASES.len() {
        let v = check(&fixture(k).cert).expect("the written certificate verifies");
        assert!(v.b.contains("exact arcs"), "{}", v.b);
    }
    let f = fixture(RECT);
    let j = arc_index(&f.cert);
    let at = format!("curve[{j}].arc");
    // the clockwise flag flipped: the sweep is the other way (above π)
    let mut d = f.cert.clone();
    let cw = d["curve"][j]["arc"]["clockwise"].as_bool().unwrap();
    d["curve"][j]["arc"]["clockwise"] = json!(!cw);
    refused_at(&d, &at);
    // an end off the circle
    let mut d = f.cert.clone();
    let x = q(d["curve"][j]["arc"]["to"][0].as_str().unwrap());
    d["curve"][j]["arc"]["to"][0] = qv(&(x + q("1/1000")));
    refused_at(&d, &at);
    // a zero sweep, and a half turn
    let mut d = f.cert.clone();
    d["curve"][j]["arc"]["to"] = d["curve"][j]["arc"]["from"].clone();
    refused_at(&d, &at);
    let mut d = f.cert.clone();
    let c = d["curve"][j]["arc"]["center"].clone();
    let from = d["curve"][j]["arc"]["from"].clone();
    let opp = |i: usize| {
        let (cq, fq) = (q(c[i].as_str().unwrap()), q(from[i].as_str().unwrap()));
        qv(&(&cq + &cq - fq))
    };
    d["curve"][j]["arc"]["to"] = json!([opp(0), opp(1)]);
    refused_at(&d, &at);
    // a stray key, a radius of 0
    let mut d = f.cert.clone();
    d["curve"][j]["arc"]["sweep"] = json!("1");
    refused_at(&d, &at);
    let mut d = f.cert.clone();
    d["curve"][j]["arc"]["radius"] = json!("0");
    refused_at(&d, &at);
    // the arc replaced by its chord: another curve, whose stroke the outline
    // is not (the corner's boundary moves inward by about 0.6)
    let mut d = f.cert.clone();
    let (a0, a1) = (
        d["curve"][j]["arc"]["from"].clone(),
        d["curve"][j]["arc"]["to"].clone(),
    );
    d["curve"][j] = json!([a0, a1]);
    let e = refused(&d);
    assert!(
        e.at.starts_with("cover") || e.at.starts_with("boundary"),
        "{e:?}"
    );
}

#[test]
fn witnesses_on_arc_pieces_are_checked_against_the_arc() {
    let f = fixture(CIRCLE);
    // the circle's curve is arcs only: a capsule on an arc piece is refused
    let mut d = f.cert.clone();
    let parts = d["cover"][0][0].as_array_mut().unwrap();
    parts[0]["o"] = json!({"segment": 0});
    let e = refused_at(&d, "cover[0][0]");
    assert!(e.reason.contains("not straight"), "{}", e.reason);
    // a point of S off [0, 1]
    let mut d = f.cert.clone();
    d["cover"][0][0][0]["o"] = json!({"piece": 0, "u": "2"});
    refused_at(&d, "cover[0][0]");
    // a disk outside S moved onto the input circle, far from the arc's
    // ends: refused (it is within r of the arc's middle)
    let mut d = f.cert.clone();
    let arc = &f.cert["curve"][0]["arc"];
    let cq = |i: usize| q(arc["center"][i].as_str().unwrap());
    let (fx, fy) = (
        q(arc["from"][0].as_str().unwrap()),
        q(arc["from"][1].as_str().unwrap()),
    );
    let (tx, ty) = (
        q(arc["to"][0].as_str().unwrap()),
        q(arc["to"][1].as_str().unwrap()),
    );
    // the chord's midpoint pushed out to radius ρ + r/2 along its direction
    // (rational: scaled by a rational close to the true factor is enough,
    // the point only has to be within r of the arc's middle)
    let (mx, my) = ((&fx + &tx) / q("2") - cq(0), (&fy + &ty) / q("2") - cq(1));
    let w = [cq(0) + &mx * q("1.45"), cq(1) + &my * q("1.45")];
    let part = &mut d["cover"][0][0][0];
    part["w"] = json!({"at": [qv(&w[0]), qv(&w[1])], "mu": "0"});
    let e = refused_at(&d, "cover[0][0]");
    assert!(e.reason.contains("arc"), "{}", e.reason);
}

#[test]
fn the_half_arc_path_states_its_quarters() {
    // a half circle is stated as two quarter arcs, each exactly on the
    // circle, joined end to start
    let f = fixture(HALF);
    let curve = f.cert["curve"].as_array().unwrap();
    let arcs: Vec<&Value> = curve.iter().filter_map(|p| p.get("arc")).collect();
    assert_eq!(arcs.len(), 2);
    assert_eq!(arcs[0]["to"], arcs[1]["from"]);
    assert_eq!(f.path.len(), 2, "the path itself: one arc and one line");
}

#[test]
fn arc_points_lie_on_the_arc_between_its_ends() {
    // the disk centres of parts and inside boxes on an arc piece: points
    // exactly on the circle, in the arc's range of directions, in order
    let f = fixture(CIRCLE);
    let input = Input::with_pieces(curve_of(&f.path), f.r.clone(), "curve").unwrap();
    for (cp, ip_) in input.curve.iter().zip(&input.pieces) {
        let CurvePiece::Arc {
            c,
            rho,
            from,
            to,
            clockwise,
        } = cp
        else {
            continue;
        };
        let (cx, cy, r) = (c[0].approx(), c[1].approx(), rho.approx());
        let s = if *clockwise { -1.0 } else { 1.0 };
        let (a, b) = (
            (from[0].approx() - cx, from[1].approx() - cy),
            (to[0].approx() - cx, to[1].approx() - cy),
        );
        let mut last = -1.0f64;
        for k in 0..=16 {
            let y = ip_.at(ic(k as f64 / 16.0)).unwrap();
            let (x, yv) = (y[0].mid() - cx, y[1].mid() - cy);
            assert!(
                (x.hypot(yv) - r).abs() < 1e-12 * r.max(1.0),
                "off the circle"
            );
            assert!(s * (a.0 * yv - a.1 * x) >= -1e-12 && s * (x * b.1 - yv * b.0) >= -1e-12);
            // the angle from the start grows along the arc
            let ang = (s * (a.0 * yv - a.1 * x)).atan2(a.0 * x + a.1 * yv);
            assert!(ang >= last, "not in order");
            last = ang;
            assert!(y[0].wid() < 1e-12 && y[1].wid() < 1e-12);
        }
    }
}
