//! Unit tests of the certified reach, the spur drop and the interval areas.

use super::chain::{chain, check_simple, Known};
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

/// Closed squares of segments, tagged as raw pieces `first, first + 1, …`.
fn tagged_square(x0: i64, y0: i64, side: i64, first: usize) -> Vec<(Piece, Option<usize>)> {
    let q = |n: i64| Rational::from_integer(n.into());
    let p = |x: i64, y: i64| V2::new(q(x), q(y));
    let c = [
        p(x0, y0),
        p(x0 + side, y0),
        p(x0 + side, y0 + side),
        p(x0, y0 + side),
    ];
    (0..4)
        .map(|k| {
            let seg = Bezier::new(vec![c[k].clone(), c[(k + 1) % 4].clone()]);
            (Piece::Bezier(seg), Some(first + k))
        })
        .collect()
}

/// Claim (c) with the raw search's answers reused, and without.
fn check_both(
    pieces: Vec<(Piece, Option<usize>)>,
    unsure: &[(usize, usize)],
) -> [(bool, String); 2] {
    let (contours, origin) = chain(pieces);
    let unsure = unsure.iter().copied().collect();
    let known = Known {
        origin,
        unsure: &unsure,
    };
    let iopts = crate::stroke::IntersectOptions::default();
    let (a, _, na) = check_simple(&contours, &iopts, Some(&known));
    let (b, _, nb) = check_simple(&contours, &iopts, None);
    [(a, na), (b, nb)]
}

#[test]
fn claim_c_with_the_raw_search_reused_still_refuses_touching_and_crossing_contours() {
    // two squares apart: simple either way, and the reuse skips every pair
    let mut apart = tagged_square(0, 0, 10, 0);
    apart.extend(tagged_square(20, 0, 10, 4));
    let [(with, note), (without, _)] = check_both(apart, &[]);
    assert!(with && without, "{note}");
    assert!(note.contains("known from the raw search"), "{note}");
    // two squares touching at one corner (10, 10): the raw search proves
    // the touching pieces meet only there, a shared end point, but they are
    // not consecutive, so (c) must fail with the reuse as without it
    let mut touch = tagged_square(0, 0, 10, 0);
    touch.extend(tagged_square(10, 10, 10, 4));
    let [(with, note), (without, note_full)] = check_both(touch, &[]);
    assert!(!with, "reuse accepted a touching pair: {note}");
    assert!(!without, "{note_full}");
    assert!(note.contains("touch but are not consecutive"), "{note}");
    // two crossing squares: the crossing pairs are unsure in the raw search,
    // so (c) solves them again and finds the crossings
    let mut cross = tagged_square(0, 0, 10, 0);
    cross.extend(tagged_square(5, 5, 10, 4));
    let unsure = [(1, 4), (1, 7), (2, 4), (2, 7)];
    let [(with, note), (without, _)] = check_both(cross, &unsure);
    assert!(!with && !without, "{note}");
    assert!(note.contains("crossings left"), "{note}");
    // a piece that is not a whole raw piece (no tag) is always solved
    let mut untagged = tagged_square(0, 0, 10, 0);
    untagged.extend(
        tagged_square(5, 5, 10, 4)
            .into_iter()
            .map(|(p, _)| (p, None)),
    );
    let [(with, note), _] = check_both(untagged, &[]);
    assert!(!with && note.contains("crossings left"), "{note}");
}

#[test]
fn claim_c_reusing_the_raw_search_agrees_with_the_full_search_on_strokes() {
    use crate::offset::Output;
    use crate::stroke::{stroke, StrokeOptions};
    let docs = [
        r#"<svg viewBox="0 0 24 24"><circle cx="12" cy="12" r="3"/></svg>"#,
        r#"<svg viewBox="0 0 24 24"><rect x="3" y="3" width="18" height="18" rx="1.5"/></svg>"#,
        r#"<svg viewBox="0 0 24 24"><path d="M12 2a10 10 0 1 0 10 10h-4a6 6 0 1 1-6-6z"/></svg>"#,
        r#"<svg viewBox="0 0 24 24"><path d="M20.84 4.61a5.5 5.5 0 0 0-7.78 0L12 5.67l-1.06-1.06a5.5 5.5 0 0 0-7.78 7.78l1.06 1.06L12 21.23l7.78-7.78 1.06-1.06a5.5 5.5 0 0 0 0-7.78z"/></svg>"#,
        r#"<svg viewBox="0 0 24 24"><path d="M3 12c3-6 6-6 9 0s6 6 9 0"/></svg>"#,
        r#"<svg viewBox="0 0 24 24"><path d="M4 8 C16 16 0 16 12 8"/></svg>"#,
    ];
    let mut reused = 0;
    for doc in docs {
        let curve = crate::shape::parse_svg_document(doc).expect("parses");
        let mut opts = StrokeOptions::new(
            Rational::from_integer(1.into()),
            crate::Tolerance::from_f64(1e-2).expect("tolerance"),
        );
        opts.output = Output::Cubic;
        let with = stroke(&curve, &opts).expect("strokes");
        super::driver::REUSE_RAW.with(|c| c.set(false));
        let without = stroke(&curve, &opts).expect("strokes");
        super::driver::REUSE_RAW.with(|c| c.set(true));
        assert_eq!(
            with.c.proven, without.c.proven,
            "{doc}: {} / {}",
            with.c.note, without.c.note
        );
        let pieces = |s: &crate::stroke::Stroke| -> Vec<Vec<Piece>> {
            s.contours.iter().map(|c| c.pieces.clone()).collect()
        };
        assert_eq!(pieces(&with), pieces(&without), "{doc}");
        assert!(with.c.proven, "{doc}: {}", with.c.note);
        if with.c.note.contains("known from the raw search") {
            reused += 1;
        }
    }
    assert_eq!(reused, docs.len());
}

/// A sub-piece's bound from its chunks: every chunk proven, once, in the
/// order given, the largest bound kept (wherever it is); `None` for a gap, an
/// overlap, a missing end, an empty chunk or one unproven chunk.
#[test]
fn chunk_bounds_need_a_tiling_of_the_whole_sub_piece() {
    use super::driver::tiled;
    use std::cell::RefCell;
    let e = 1.0 / 16.0;
    let calls = RefCell::new(Vec::new());
    let bound = |k: usize, u0: f64, u1: f64| {
        calls.borrow_mut().push((k, u0, u1));
        Some([0.1, 0.2, 0.3][k])
    };
    let three = [(e, 1.0 - e), (0.0, e), (1.0 - e, 1.0)];
    assert_eq!(tiled(&three, bound), Some(0.3));
    assert_eq!(
        *calls.borrow(),
        vec![(0, e, 1.0 - e), (1, 0.0, e), (2, 1.0 - e, 1.0)]
    );
    // the largest bound first or in the middle is kept as well
    let first = |k: usize, _: f64, _: f64| Some([0.3, 0.1, 0.2][k]);
    assert_eq!(tiled(&three, first), Some(0.3));
    let middle = |k: usize, _: f64, _: f64| Some([0.1, 0.3, 0.2][k]);
    assert_eq!(tiled(&three, middle), Some(0.3));
    // not a tiling: nothing is tried
    calls.borrow_mut().clear();
    for chunks in [
        vec![(e, 1.0 - e)],
        vec![(e, 1.0 - e), (0.0, e)],
        vec![(0.0, 0.4), (0.5, 1.0)],
        vec![(0.0, 0.6), (0.5, 1.0)],
        vec![(0.0, 0.5), (0.5, 0.5), (0.5, 1.0)],
        vec![],
    ] {
        assert_eq!(tiled(&chunks, bound), None, "{chunks:?}");
    }
    assert!(calls.borrow().is_empty());
    // one unproven chunk: no bound
    let fails = |k: usize, _: f64, _: f64| (k != 2).then_some(0.1);
    assert_eq!(tiled(&three, fails), None);
}

/// The kept test's float boxes (`ExactCurve::far`) exclude a piece only
/// where its exact control points are farther than `r` from the witness
/// (checked exactly), they do exclude the clearly far ones, and
/// `ExactCurve::outside` answers as the exact `outside` on witnesses placed
/// a hair inside, on and outside the box distance `r` (non-dyadic control
/// points, so the boxes are rounded outward).
#[test]
fn float_boxes_exclude_only_what_is_far() {
    use super::classify::{outside, ExactCurve};
    use crate::stroke::ellipse::Form;
    let q = |n: i64, d: i64| Rational::new(n.into(), d.into());
    let curve: Vec<Bezier<Rational>> = (0..6i64)
        .map(|k| {
            Bezier::new(vec![
                V2::new(q(3 * k, 7), q(k * k, 3)),
                V2::new(q(3 * k + 1, 7), q(k * k + 2, 3)),
                V2::new(q(3 * k + 2, 7), q(k * k - 1, 3)),
                V2::new(q(3 * k + 3, 7), q((k + 1) * (k + 1), 3)),
            ])
        })
        .collect();
    let r = q(1, 3);
    let form = Form::circle(&r);
    let exact = ExactCurve::new(&curve);
    let r2_hi = interval_from_rational(&form.a2_hi).sup();
    // the exact squared distance from w to piece i's control-point box
    let box_d2 = |i: usize, w: &V2<Rational>| {
        let pts = curve[i].points();
        let mut d2 = <Rational as Zero>::zero();
        for get in [
            |v: &V2<Rational>| v.x.clone(),
            |v: &V2<Rational>| v.y.clone(),
        ] {
            let lo = pts.iter().map(get).min().unwrap();
            let hi = pts.iter().map(get).max().unwrap();
            let c = get(w);
            let g = if c < lo {
                lo - c
            } else if c > hi {
                c - hi
            } else {
                <Rational as Zero>::zero()
            };
            d2 += &g * &g;
        }
        d2
    };
    let (mut far, mut near) = (0, 0);
    for i in 0..curve.len() {
        let pts = curve[i].points();
        let lo_x = pts.iter().map(|v| v.x.clone()).min().unwrap();
        let mid_y = (&pts[0].y + &pts[3].y) / Rational::from_integer(2.into());
        for eps in [
            q(-1, 1 << 40),
            <Rational as Zero>::zero(),
            q(1, 1 << 40),
            q(1, 1000),
            q(1, 3),
        ] {
            // left of the box by r + eps, at the height of its middle
            let w = V2::new(&lo_x - &r - &eps, mid_y.clone());
            let wi = [interval_from_rational(&w.x), interval_from_rational(&w.y)];
            for j in 0..curve.len() {
                if exact.far(j, &wi, r2_hi) {
                    assert!(
                        box_d2(j, &w) > form.a2_hi,
                        "piece {j}, witness near piece {i}"
                    );
                    far += 1;
                } else {
                    near += 1;
                }
            }
            assert_eq!(
                exact.outside(&w, &form),
                outside(&curve, &w, &form),
                "piece {i}, eps {eps}"
            );
        }
    }
    assert!(far > 0 && near > 0, "far {far}, near {near}");
}

/// The stroke of an SVG path of Bézier pieces at `r = 1`, TOL 1e-2: proven,
/// and its outline looked at from outside (dense samples of the input, not
/// the engine's predicates).
fn proven_bezier_stroke(d: &str) -> super::types::Stroke {
    let curve = crate::shape::parse_curve(d).unwrap();
    let opts = super::types::StrokeOptions::new(
        <Rational as num_traits::One>::one(),
        crate::test_util::tol(1e-2),
    );
    let s = super::stroke(&curve, &opts).unwrap();
    assert!(
        s.proven(),
        "{d}: {:?} {:?} {:?} {:?}",
        s.a,
        s.b,
        s.c,
        s.notes
    );
    let input: Vec<(f64, f64)> = curve
        .iter()
        .flat_map(|b| Piece::Bezier(b.clone()).sample(2000))
        .collect();
    crate::test_util::outline_near_boundary(&s, &input, 1.0, 1e-2, d);
    s
}

fn coincident_note(s: &super::types::Stroke) -> bool {
    s.notes.iter().any(|n| n.contains("coincide exactly"))
}

#[test]
fn caps_and_joins_on_one_circle_are_split_at_each_others_points() {
    // class 1 with Bézier pieces: a leaf of quadratics that passes through
    // its start point three times (joins and the closing join on one circle)
    let s = proven_bezier_stroke("M15 9q4 4 7 0-3-4-7 0 4-4 0-7-4 3 0 7");
    assert!(coincident_note(&s), "{:?}", s.notes);
    // an arrowhead of three subpaths from one point, two of them curved:
    // three round caps on one circle
    let s = proven_bezier_stroke("M7.5 12q-2 1-3.75 3.75m0 0q2 1 3.75 3.75m-3.75-3.75h16.5");
    assert!(coincident_note(&s), "{:?}", s.notes);
}
