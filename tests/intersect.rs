//! Certified intersections of Bézier pieces (`lncert::stroke::intersect`)
//! against an independent oracle: the crossings of dense polylines of the
//! pieces. When the result is complete, every polyline crossing must lie next
//! to a listed crossing or a shared end point (nothing missed), and every
//! listed crossing must have its two point enclosures overlap (the two pieces
//! really meet there) and a polyline crossing next to it (nothing invented).

mod common;

use lncert::curve::{Bezier, V2};
use lncert::scalar::{interval_from_rational, Rational, Scalar};
use lncert::stroke::{intersections, IntersectOptions, Intersections};
use proptest::prelude::*;

const N: usize = 2048;

fn samples(b: &Bezier<Rational>) -> Vec<(f64, f64)> {
    samples_on(b, (0.0, 1.0), N)
}

/// The points of `b` at `n + 1` equally spaced parameters over `lo..=hi`.
fn samples_on(b: &Bezier<Rational>, (lo, hi): (f64, f64), n: usize) -> Vec<(f64, f64)> {
    let f = b.map(|v| v.approx());
    (0..=n)
        .map(|k| {
            let p = f.eval(&(lo + (hi - lo) * k as f64 / n as f64));
            (p.x, p.y)
        })
        .collect()
}

/// Proper crossing of segments `p0 p1` and `q0 q1`: the parameters on each,
/// and the sine of the angle between them.
fn seg_cross(
    p0: (f64, f64),
    p1: (f64, f64),
    q0: (f64, f64),
    q1: (f64, f64),
) -> Option<(f64, f64, f64)> {
    let r = (p1.0 - p0.0, p1.1 - p0.1);
    let s = (q1.0 - q0.0, q1.1 - q0.1);
    let den = r.0 * s.1 - r.1 * s.0;
    if den == 0.0 {
        return None;
    }
    let w = (q0.0 - p0.0, q0.1 - p0.1);
    let u = (w.0 * s.1 - w.1 * s.0) / den;
    let v = (w.0 * r.1 - w.1 * r.0) / den;
    let sin = den.abs() / ((r.0 * r.0 + r.1 * r.1).sqrt() * (s.0 * s.0 + s.1 * s.1).sqrt());
    (0.0..=1.0).contains(&u).then_some(())?;
    (0.0..=1.0).contains(&v).then_some((u, v, sin))
}

/// Polyline crossings of pieces `i`, `j` (`i ≤ j`; for `i = j` non-adjacent
/// segments with `s < t`): `(s, t, sin angle)`.
fn polyline_crossings(a: &[(f64, f64)], b: &[(f64, f64)], same: bool) -> Vec<(f64, f64, f64)> {
    let mut out = Vec::new();
    for k in 0..N {
        let (lo, hi) = (a[k].0.min(a[k + 1].0), a[k].0.max(a[k + 1].0));
        let (ylo, yhi) = (a[k].1.min(a[k + 1].1), a[k].1.max(a[k + 1].1));
        let start = if same { k + 2 } else { 0 };
        for l in start..N {
            let (blo, bhi) = (b[l].0.min(b[l + 1].0), b[l].0.max(b[l + 1].0));
            let (bylo, byhi) = (b[l].1.min(b[l + 1].1), b[l].1.max(b[l + 1].1));
            if bhi < lo || blo > hi || byhi < ylo || bylo > yhi {
                continue;
            }
            if let Some((u, v, sin)) = seg_cross(a[k], a[k + 1], b[l], b[l + 1]) {
                out.push(((k as f64 + u) / N as f64, (l as f64 + v) / N as f64, sin));
            }
        }
    }
    out
}

/// Polyline crossings (`sin ≥ 10⁻³`) of the pieces restricted to windows of
/// half-width `8/N` around `u` on `a` and `v` on `b`, each sampled with `32·16`
/// segments (32 times the resolution of [`samples`]); parameters are the
/// pieces' own. For `same`, crossings of a segment with itself or its
/// neighbours are skipped.
fn refined_crossings(
    a: &Bezier<Rational>,
    b: &Bezier<Rational>,
    u: f64,
    v: f64,
    same: bool,
) -> Vec<(f64, f64, f64)> {
    const M: usize = 512;
    let h = 8.0 / N as f64;
    let window = |c: f64| ((c - h).max(0.0), (c + h).min(1.0));
    let (wa, wb) = (window(u), window(v));
    let (pa, pb) = (samples_on(a, wa, M), samples_on(b, wb, M));
    let at = |(lo, hi): (f64, f64), k: usize| lo + (hi - lo) * k as f64 / M as f64;
    let mut out = Vec::new();
    for k in 0..M {
        for l in 0..M {
            let (s0, s1) = (at(wa, k), at(wa, k + 1));
            let (t0, t1) = (at(wb, l), at(wb, l + 1));
            // the same piece: skip a segment against itself or a neighbour
            if same && (t0 - s1).abs().min((s0 - t1).abs()).min((s0 - t0).abs()) < 1e-12 {
                continue;
            }
            if let Some((x, y, sin)) = seg_cross(pa[k], pa[k + 1], pb[l], pb[l + 1]) {
                if sin >= 1e-3 {
                    out.push((s0 + (s1 - s0) * x, t0 + (t1 - t0) * y, sin));
                }
            }
        }
    }
    out
}

fn near(x: f64, r: (f64, f64), slack: f64) -> bool {
    x >= r.0 - slack && x <= r.1 + slack
}

fn check(pieces: &[Bezier<Rational>], r: &Intersections) {
    let slack = 4.0 / N as f64;
    let s: Vec<_> = pieces.iter().map(samples).collect();
    // every listed crossing: the two pieces' enclosures at (s, t) overlap
    for c in &r.crossings {
        let (i, j) = c.pieces;
        let iv = |x: (f64, f64)| lncert::Interval::try_from(x).unwrap();
        let pa = pieces[i].map(interval_from_rational).eval(&iv(c.s));
        let pb = pieces[j].map(interval_from_rational).eval(&iv(c.t));
        assert!(
            !pa.x.disjoint(pb.x) && !pa.y.disjoint(pb.y),
            "{c:?}: the pieces do not meet there"
        );
    }
    if !r.complete {
        return;
    }
    for i in 0..pieces.len() {
        for j in i..pieces.len() {
            if pieces[i].degree() == 0 || pieces[j].degree() == 0 {
                continue;
            }
            let found = polyline_crossings(&s[i], &s[j], i == j);
            let listed: Vec<_> = r.crossings.iter().filter(|c| c.pieces == (i, j)).collect();
            // nothing missed: a clear polyline crossing is next to a listed
            // crossing or to a shared end point
            for &(u, v, sin) in &found {
                if sin < 1e-3 {
                    continue; // nearly tangent polylines: not a clear crossing
                }
                let explained = |u: f64, v: f64| {
                    let by_crossing = listed
                        .iter()
                        .any(|c| near(u, c.s, slack) && near(v, c.t, slack));
                    let by_joint = r.joints.iter().any(|jn| {
                        jn.pieces == (i, j)
                            && (u - f64::from(jn.at.0)).abs() < slack
                            && (v - f64::from(jn.at.1)).abs() < slack
                    });
                    by_crossing || by_joint
                };
                if explained(u, v) {
                    continue;
                }
                // Chord sag: next to a shared end point where the pieces
                // leave in nearly one direction, the coarse polylines can
                // cross where the curves do not. Look again at 32 times the
                // resolution around (u, v): a crossing of the curves is still
                // there, and must be listed.
                let finer = refined_crossings(&pieces[i], &pieces[j], u, v, i == j);
                for (fu, fv, fsin) in finer {
                    assert!(
                        explained(fu, fv),
                        "pieces {i}, {j}: the polylines cross at s ≈ {fu}, t ≈ {fv} (sin {fsin}; coarse s ≈ {u}, t ≈ {v}, sin {sin}), not listed: {r:?}"
                    );
                }
            }
            // nothing invented: a listed crossing away from the ends has a
            // polyline crossing next to it
            for c in &listed {
                let interior =
                    c.s.0 > slack && c.s.1 < 1.0 - slack && c.t.0 > slack && c.t.1 < 1.0 - slack;
                if !interior {
                    continue;
                }
                assert!(
                    found
                        .iter()
                        .any(|&(u, v, _)| near(u, c.s, 2.0 * slack) && near(v, c.t, 2.0 * slack)),
                    "{c:?}: no polyline crossing next to it"
                );
            }
        }
    }
}

fn piece() -> impl Strategy<Value = Bezier<Rational>> {
    (
        1usize..=3,
        proptest::collection::vec((-8i64..=8, -8i64..=8), 4),
    )
        .prop_map(|(deg, pts)| {
            Bezier::new(
                pts[..=deg]
                    .iter()
                    .map(|&(x, y)| V2::new(common::q(x, 4), common::q(y, 4)))
                    .collect(),
            )
        })
}

proptest! {
    #![proptest_config(ProptestConfig { cases: common::cases().min(300), ..common::config() })]

    /// Two or three free pieces, and a chained spline (shared end points).
    #[test]
    fn certified_crossings_match_the_polylines(
        free in proptest::collection::vec(piece(), 2..=3),
        chained in proptest::collection::vec(piece(), 2..=3),
    ) {
        let r = intersections(&free, &IntersectOptions::default());
        check(&free, &r);
        // chain: each piece starts where the previous ended
        let mut chain: Vec<Bezier<Rational>> = Vec::new();
        for b in chained {
            let mut pts = b.points().to_vec();
            if let Some(prev) = chain.last() {
                let p = prev.points();
                pts[0] = p[p.len() - 1].clone();
            }
            chain.push(Bezier::new(pts));
        }
        let r = intersections(&chain, &IntersectOptions::default());
        check(&chain, &r);
    }
}

/// The complete results of the property test are the common case, not the
/// exception: on a fixed family of loops and crossings everything is decided.
#[test]
fn loops_and_spline_joints_are_decided() {
    let c = lncert::shape::parse_curve("M 0 0 C 3 2 -1 2 2 0 C 3 -1 4 1 5 0 L 5 2 Q 2.5 -2 -1 2 Z")
        .unwrap();
    let r = intersections(&c, &IntersectOptions::default());
    assert!(r.complete, "{r:?}");
    check(&c, &r);
    // the loop's self-crossing, and every joint of the closed contour
    assert_eq!(r.crossings.iter().filter(|c| c.pieces == (0, 0)).count(), 1);
    assert!(r.joints.len() >= c.len() - 1, "{r:?}");
}

/// A cusp: two pieces leave their shared point in the same direction with
/// different curvature (a parabola's two branches y = x² and y = x²/4 on the
/// same side, and the mirror case y = −x²): the joint is isolated to second
/// order, the search is complete, and the polyline oracle agrees.
#[test]
fn tangential_joints_at_a_cusp_are_decided() {
    for (a, b) in [
        ("M 1 1 Q 0.5 0 0 0", "M 0 0 Q 1 0 2 1"),
        ("M 1 1 Q 0.5 0 0 0", "M 0 0 Q 0.5 0 1 -1"),
    ] {
        let mut c = lncert::shape::parse_curve(a).unwrap();
        c.extend(lncert::shape::parse_curve(b).unwrap());
        let r = intersections(&c, &IntersectOptions::default());
        assert!(r.complete, "{a} {b}: {r:?}");
        assert!(r.crossings.is_empty(), "{r:?}");
        assert_eq!(r.joints.len(), 1, "{r:?}");
        check(&c, &r);
    }
    // equal curvature at the joint (the same parabola traced twice): no
    // second-order separation, never claimed complete
    let mut c = lncert::shape::parse_curve("M 1 1 Q 0.5 0 0 0").unwrap();
    c.extend(lncert::shape::parse_curve("M 0 0 Q 0.5 0 1 1").unwrap());
    let r = intersections(&c, &IntersectOptions::default());
    assert!(!r.complete, "{r:?}");
}
