//! Unit tests of the certified reach, the spur drop and the interval areas.

use super::pinch::{pinched_loops, reach_hi};
use super::types::{bezier_area_iv, Piece};
use crate::curve::{Bezier, V2};
use crate::scalar::{interval_from_rational, Rational, Scalar};
use num_traits::Zero;

/// `½∫₀¹ (x y′ − y x′) dt`, exact.
fn bezier_area(b: &Bezier<Rational>) -> Rational {
    let (x, y) = b.power_coords();
    let integrand = x.mul(&y.derivative()).sub(&y.mul(&x.derivative()));
    let mut s = <Rational as Zero>::zero();
    for (k, c) in integrand.coeffs().iter().enumerate() {
        s += c / Rational::from_integer((k as i64 + 1).into());
    }
    s / Rational::from_integer(2.into())
}

/// Dense float distance from the point to the piece (a lower bound of
/// nothing, an estimate: the certified reach must not be below it).
fn sampled_dist(p: (f64, f64), q: &Piece) -> f64 {
    q.sample(4000)
        .iter()
        .map(|v| (v.0 - p.0).hypot(v.1 - p.1))
        .fold(f64::INFINITY, f64::min)
}

#[test]
fn the_certified_reach_is_never_below_the_sampled_distance() {
    let q = |n: i64, d: i64| Rational::new(n.into(), d.into());
    let mut rng = crate::test_util::TestRng::new(0x9e37_79b9_7f4a_7c15);
    let (mut decided, mut refused) = (0, 0);
    for _ in 0..60 {
        // a short cubic near the start of a reference cubic (a spur at Y)
        let y = V2::new(q(rng.int(1000), 100), q(rng.int(1000), 100));
        let mut r = vec![y.clone()];
        let mut c = vec![y.clone()];
        for _ in 0..3 {
            r.push(V2::new(
                &r[r.len() - 1].x + q(rng.int(1000).abs() + 100, 50),
                &r[r.len() - 1].y + q(rng.int(1000), 200),
            ));
            c.push(V2::new(
                &c[c.len() - 1].x + q(rng.int(1000).abs(), 2000),
                &c[c.len() - 1].y + q(rng.int(1000), 2000),
            ));
        }
        let spur = Piece::Bezier(Bezier::new(c));
        let refp = Piece::Bezier(Bezier::new(r));
        let sampled = spur
            .sample(400)
            .iter()
            .map(|&p| sampled_dist(p, &refp).min((p.0 - y.x.approx()).hypot(p.1 - y.y.approx())))
            .fold(0.0, f64::max);
        for cap in [0.05, 0.2, 1.0] {
            match reach_hi(&spur, &[&refp], Some(&y), cap) {
                Some(reach) => {
                    decided += 1;
                    assert!(reach <= cap, "{reach} above the cap {cap}");
                    assert!(
                        reach >= sampled - 1e-9,
                        "certified reach {reach} below the sampled {sampled}"
                    );
                }
                None => {
                    refused += 1;
                    // refused only where the cap is not far above the truth
                    assert!(sampled > cap / 4.0, "refused: sampled {sampled}, cap {cap}");
                }
            }
        }
    }
    assert!(
        decided > 20 && refused > 5,
        "{decided} decided, {refused} refused"
    );
}

#[test]
fn a_spur_near_the_output_is_dropped_and_a_far_one_is_kept() {
    let q = |n: i64| Rational::from_integer(n.into());
    let p = |x: i64, y: i64| V2::new(q(x), q(y));
    let seg = |a: V2<Rational>, b: V2<Rational>| Piece::Bezier(Bezier::new(vec![a, b]));
    // a closed square with a short spur at (10, 0) running along the edge
    // back toward (9, 0) at a height of 1/100, and a long one sticking out
    let near = Piece::Bezier(Bezier::new(vec![
        p(10, 0),
        V2::new(
            Rational::new(29.into(), 3.into()),
            Rational::new(1.into(), 100.into()),
        ),
        V2::new(
            Rational::new(28.into(), 3.into()),
            Rational::new(1.into(), 100.into()),
        ),
        V2::new(q(9), Rational::new(1.into(), 100.into())),
    ]));
    let far = seg(p(10, 10), p(15, 15));
    let pieces = [
        seg(p(0, 0), p(10, 0)),
        near,
        seg(p(10, 0), p(10, 10)),
        far,
        seg(p(10, 10), p(0, 10)),
        seg(p(0, 10), p(0, 0)),
    ];
    let refs: Vec<&Piece> = pieces.iter().collect();
    let caps = vec![0.5; pieces.len()];
    let dropped = pinched_loops(&refs, &caps);
    assert_eq!(dropped.len(), 1, "{dropped:?}");
    let (k, reach) = dropped[0];
    assert_eq!(k, 1);
    // the spur's far end is 1/100 above the edge
    assert!((0.01..0.5).contains(&reach), "{reach}");
}

#[test]
fn interval_areas_enclose_the_exact_ones() {
    let q = |n: i64, d: i64| Rational::new(n.into(), d.into());
    let mut rng = crate::test_util::TestRng::new(0x2545_f491_4f6c_dd1d);
    let mut next = || rng.int(1000);
    for deg in 1..=6 {
        for _ in 0..20 {
            let b = Bezier::new(
                (0..=deg)
                    .map(|_| V2::new(q(next(), 7), q(next(), 3)))
                    .collect(),
            );
            let exact = interval_from_rational(&bezier_area(&b));
            let iv = bezier_area_iv(&b).expect("finite");
            assert!(
                iv.inf() <= exact.inf() && exact.sup() <= iv.sup(),
                "{exact:?} not in {iv:?}"
            );
            assert!(iv.wid() <= 1e-9 * (1.0 + exact.mag()), "{iv:?}");
        }
    }
}

#[test]
fn a_small_isolated_loop_is_dropped_a_large_or_far_one_is_kept() {
    let q = |n: i64, d: i64| Rational::new(n.into(), d.into());
    let p = |x: i64, y: i64| V2::new(q(x, 1), q(y, 1));
    let seg = |a: V2<Rational>, b: V2<Rational>| Piece::Bezier(Bezier::new(vec![a, b]));
    // a closed loop (a cubic whose ends coincide) of size `s`, at (x0, y0)
    let lp = |x0: Rational, y0: Rational, s: Rational| {
        let v = |dx: i64, dy: i64| V2::new(&x0 + &s * q(dx, 1), &y0 + &s * q(dy, 1));
        Piece::Bezier(Bezier::new(vec![v(0, 0), v(1, 1), v(-1, 1), v(0, 0)]))
    };
    let square = [
        seg(p(0, 0), p(10, 0)),
        seg(p(10, 0), p(10, 10)),
        seg(p(10, 10), p(0, 10)),
        seg(p(0, 10), p(0, 0)),
    ];
    let run = |extra: Vec<Piece>, cap: f64| {
        let all: Vec<Piece> = square.iter().cloned().chain(extra).collect();
        let refs: Vec<&Piece> = all.iter().collect();
        pinched_loops(&refs, &vec![cap; all.len()])
    };
    // 1/100 across, 1/20 above the bottom edge: within 0.06 of it
    let near = lp(q(5, 1), q(1, 20), q(1, 100));
    let dropped = run(vec![near.clone()], 0.5);
    assert_eq!(dropped.len(), 1, "{dropped:?}");
    let (k, reach) = dropped[0];
    assert_eq!(k, 4);
    // its farthest point is 0.05 + 3/4 · 0.01 above the edge; the reach is
    // not below the sampled distance to the square
    assert!((0.0575 - 1e-9..0.5).contains(&reach), "{reach}");
    let sampled = near
        .sample(400)
        .iter()
        .map(|&p| {
            square
                .iter()
                .map(|e| sampled_dist(p, e))
                .fold(f64::INFINITY, f64::min)
        })
        .fold(0.0, f64::max);
    assert!(
        reach >= sampled - 1e-9,
        "{reach} below the sampled {sampled}"
    );
    // the cap below that distance: kept
    assert!(run(vec![near], 0.05).is_empty());
    // the same loop 3 units inside: farther than the cap from everything
    assert!(run(vec![lp(q(5, 1), q(3, 1), q(1, 100))], 0.5).is_empty());
    // a loop larger than its cap across is not a candidate
    assert!(run(vec![lp(q(5, 1), q(1, 20), q(1, 1))], 0.5).is_empty());
}

#[test]
fn a_second_path_near_the_first_is_dropped_a_distant_one_is_kept() {
    let q = |n: i64, d: i64| Rational::new(n.into(), d.into());
    let p = |x: i64, y: i64| V2::new(q(x, 1), q(y, 1));
    let seg = |a: V2<Rational>, b: V2<Rational>| Piece::Bezier(Bezier::new(vec![a, b]));
    let square = [
        seg(p(0, 0), p(10, 0)),
        seg(p(10, 0), p(10, 10)),
        seg(p(10, 10), p(0, 10)),
        seg(p(0, 10), p(0, 0)),
    ];
    // a second path from (0, 0) to (10, 0): a quadratic bulging by h/2
    let path =
        |h: Rational| Piece::Bezier(Bezier::new(vec![p(0, 0), V2::new(q(5, 1), h), p(10, 0)]));
    let run = |extra: &Piece, cap: f64| {
        let all: Vec<Piece> = square.iter().cloned().chain([extra.clone()]).collect();
        let refs: Vec<&Piece> = all.iter().collect();
        pinched_loops(&refs, &vec![cap; all.len()])
    };
    let near = path(q(1, 50));
    let dropped = run(&near, 0.5);
    // one of the two paths goes, with a reach not below the sampled gap
    assert_eq!(dropped.len(), 1, "{dropped:?}");
    let (k, reach) = dropped[0];
    assert!(k == 0 || k == 4, "{dropped:?}");
    let sampled = near
        .sample(400)
        .iter()
        .map(|&v| sampled_dist(v, &square[0]))
        .fold(0.0, f64::max);
    assert!(
        (sampled - 1e-9..=0.5).contains(&reach),
        "{reach} vs {sampled}"
    );
    assert!(sampled > 0.0099, "{sampled}");
    // a cap below the gap, or a path 2 units away: both stay
    assert!(run(&near, 0.005).is_empty());
    assert!(run(&path(q(4, 1)), 0.5).is_empty());
}
