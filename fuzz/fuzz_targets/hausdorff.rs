#![no_main]
//! Fuzz target `hausdorff`: two small shapes built from the input ->
//! `lncert::certify::hausdorff` with a small box budget.
//!
//! Shapes: a curve of 1-2 Bézier pieces of degree 0-4 (coordinates `k/16`,
//! `k` an `i8`), an arc (integer centre, radius 1..=8, integer direction
//! vectors) or the offset of one Bézier piece at a small nonzero rational
//! distance. Constructor errors are fine (the input is rejected).
//!
//! Budget: `max_boxes: 16` keeps the mean cost near 5 ms per input. It does
//! not bound all work: every witness runs `lower_distance` with its own fixed
//! budget of 4000 boxes (src/certify/search.rs), which dominates for offsets.
//!
//! Checks (all exact consequences of soundness, no sampling):
//! * no panic; `0 <= lo <= hi`, none NaN, for `d_H` and both one-sided bounds;
//! * a result not flagged `incomplete` has a finite `hi` (it met the gap);
//! * swapping the arguments bounds the same numbers: the intervals for
//!   `h(A, B)` from `hausdorff(A, B)` and from `hausdorff(B, A)` intersect;
//! * for two curves, `h(A, B) <= max_i |A_i - B(0)|` (every point of A is in
//!   the convex hull of A's control points and `B(0)` is a point of B), so the
//!   certified lower bound of `h(A, B)` cannot exceed it;
//! * when A is an arc, the radial scenario ([`radial_scenario`]): a cubic
//!   between its end rays inside its sector, the radial proof's bounds against
//!   the other proofs' and against exact radial distances.

use libfuzzer_sys::arbitrary::{Result, Unstructured};
use libfuzzer_sys::{fuzz_target, Corpus};
use lncert::certify::{hausdorff, Config, HausdorffBounds, OneSided};
use lncert::shape::{ArcDesc, ShapeDesc};
use lncert::curve::{Bezier, V2};
use lncert::scalar::{frac, rational_from_f64, Rational};

fn q(p: i64, den: i64) -> Rational {
    frac::<Rational>(p, den)
}

fn bezier(u: &mut Unstructured, min_degree: u8) -> Result<Bezier<Rational>> {
    let degree = u.int_in_range(min_degree..=4)?;
    let mut pts = Vec::new();
    for _ in 0..=degree {
        let x: i8 = u.arbitrary()?;
        let y: i8 = u.arbitrary()?;
        pts.push(V2::new(q(x.into(), 16), q(y.into(), 16)));
    }
    Ok(Bezier::new(pts))
}

/// `Ok(None)`: the constructor rejected the data.
fn shape(u: &mut Unstructured) -> Result<Option<ShapeDesc>> {
    let kind: u8 = u.int_in_range(0..=2)?;
    let desc = match kind {
        0 => {
            let pieces = u.int_in_range(1..=2u8)?;
            let mut c = Vec::new();
            for _ in 0..pieces {
                c.push(bezier(u, 0)?);
            }
            ShapeDesc::curve(c)
        }
        1 => {
            let mut int =
                |lo: i64, hi: i64| -> Result<Rational> { Ok(q(u.int_in_range(lo..=hi)?, 1)) };
            let arc = ArcDesc {
                center: V2::new(int(-8, 8)?, int(-8, 8)?),
                radius: int(1, 8)?,
                from: V2::new(int(-4, 4)?, int(-4, 4)?),
                to: V2::new(int(-4, 4)?, int(-4, 4)?),
            };
            ShapeDesc::arc(arc)
        }
        _ => {
            let b = bezier(u, 1)?;
            let num: i8 = u.int_in_range(-16..=16)?;
            let den: u8 = u.int_in_range(1..=16)?;
            ShapeDesc::offset(vec![b], q(num.into(), den.into()))
        }
    };
    Ok(desc.ok())
}

fn check_one_sided(s: &OneSided, what: &str) {
    assert!(
        !s.lo.is_nan() && !s.hi.is_nan() && s.lo >= 0.0 && s.lo <= s.hi,
        "{what}: bad bounds [{}, {}]",
        s.lo,
        s.hi
    );
}

fn check(r: &HausdorffBounds, a: &ShapeDesc, b: &ShapeDesc) {
    assert!(
        !r.lo.is_nan() && !r.hi.is_nan() && r.lo >= 0.0 && r.lo <= r.hi,
        "bad bounds [{}, {}]",
        r.lo,
        r.hi
    );
    check_one_sided(&r.a_to_b, "h(A, B)");
    check_one_sided(&r.b_to_a, "h(B, A)");
    // Without `tol` the search stops at `hi - lo <= max(rel hi, abs)` or on its
    // budget (then `incomplete`): an infinite `hi` is never converged.
    assert!(
        r.incomplete() || r.hi.is_finite(),
        "search reported complete with an infinite upper bound [{}, {}] ({} + {} boxes evaluated); A = {}, B = {}",
        r.lo,
        r.hi,
        r.a_to_b.evaluated,
        r.b_to_a.evaluated,
        a.to_json(),
        b.to_json()
    );
}

/// The exact square of an upper bound on `h(A, B)` for two curves:
/// `max_i |A_i - B(0)|^2`.
fn hull_bound_sq(a: &[Bezier<Rational>], b: &[Bezier<Rational>]) -> Rational {
    let b0 = &b[0].points()[0];
    let mut best = q(0, 1);
    for p in a.iter().flat_map(|c| c.points().iter()) {
        let (dx, dy) = (p.x.clone() - b0.x.clone(), p.y.clone() - b0.y.clone());
        let d2 = dx.clone() * dx + dy.clone() * dy;
        if d2 > best {
            best = d2;
        }
    }
    best
}

/// `lo <= sqrt(bound_sq)`, exactly.
fn lower_ok(lo: f64, bound_sq: &Rational) -> bool {
    match rational_from_f64(lo) {
        Some(l) => lo <= 0.0 || &(l.clone() * l) <= bound_sq,
        None => false,
    }
}

/// When shape A is an arc, the bytes left build a cubic from a point of its
/// start ray to a point of its end ray, its inner points `c + α·from + β·to`
/// (`α, β ≥ 0`: in the sector whenever the sweep is at most π), where the
/// radial proof applies (`src/certify/radial.rs`); or, one time in two, the
/// arc's whole circle (a union of two half arcs) against four such cubics,
/// one per quarter turn from the arc's start direction. Its bounds must overlap the
/// other proofs' on the same pair, and the exact radial distance of the cubic
/// at 9 rational parameters (a lower bound of `d_H` for any shapes) must not
/// exceed its `hi`.
fn radial_scenario(u: &mut Unstructured, arc: &ArcDesc, cfg: &Config) {
    let Ok(k) = (0..6)
        .map(|_| u.int_in_range(0..=24u8).map(|v| q(v.into(), 8)))
        .collect::<Result<Vec<_>>>()
    else {
        return;
    };
    let c = &arc.center;
    let at = |a: &Rational, b: &Rational| c.add(&arc.from.scale(a)).add(&arc.to.scale(b));
    let zero = q(0, 1);
    // only where the proof's exact conditions hold by construction (a sweep of
    // at most π, both ends strictly on their rays): elsewhere the pair would
    // only rerun the other proofs
    let cr = arc.from.cross(&arc.to);
    let half_turn = cr == zero && arc.from.dot(&arc.to) < zero;
    if !(cr > zero || half_turn) || k[0] == zero || k[5] == zero {
        return;
    }
    // one byte in two: the whole circle (two half arcs) against four
    // quarters, each `s e_i → s e_{i+1}` with inner points `α e_i + β e_{i+1}`
    // (`e_i` the arc's start direction turned by i quarters)
    let whole = u.arbitrary::<bool>().unwrap_or(false);
    let (arc_shape, pieces) = if whole {
        let e = [arc.from.clone(), arc.from.rot90(), arc.from.scale(&q(-1, 1)), arc.from.rot90().scale(&q(-1, 1))];
        let pieces: Vec<Bezier<Rational>> = (0..4)
            .map(|i| {
                let (a, b) = (&e[i], &e[(i + 1) % 4]);
                let pt = |x: &Rational, y: &Rational| c.add(&a.scale(x)).add(&b.scale(y));
                Bezier::new(vec![pt(&k[0], &zero), pt(&k[1], &k[2]), pt(&k[3], &k[4]), pt(&zero, &k[0])])
            })
            .collect();
        let half = |from: &V2<Rational>, to: &V2<Rational>| {
            ShapeDesc::arc(ArcDesc { center: c.clone(), radius: arc.radius.clone(), from: from.clone(), to: to.clone() })
        };
        let (Ok(h0), Ok(h1)) = (half(&e[0], &e[2]), half(&e[2], &e[0])) else {
            return;
        };
        let Ok(circle) = ShapeDesc::union(vec![h0, h1]) else {
            return;
        };
        (circle, pieces)
    } else {
        let cubic = Bezier::new(vec![at(&k[0], &zero), at(&k[1], &k[2]), at(&k[3], &k[4]), at(&zero, &k[5])]);
        let Ok(a) = ShapeDesc::arc(arc.clone()) else {
            return;
        };
        (a, vec![cubic])
    };
    let Ok(curve) = ShapeDesc::curve(pieces.clone()) else {
        return;
    };
    let Ok(r) = hausdorff(&arc_shape, &curve, cfg) else {
        return;
    };
    check(&r, &arc_shape, &curve);
    if r.radial.is_none() {
        return;
    }
    // coarse (rel 1/4): soundness is what is compared, and fewer witnesses run
    let other = Config { radial: false, rel: 0.25, ..cfg.clone() };
    if let Ok(o) = hausdorff(&arc_shape, &curve, &other) {
        assert!(
            r.lo <= o.hi && o.lo <= r.hi,
            "radial [{}, {}] and the other proofs' [{}, {}] are disjoint: A = {}, B = {}",
            r.lo,
            r.hi,
            o.lo,
            o.hi,
            arc_shape.to_json(),
            curve.to_json()
        );
    }
    let Some(hi) = rational_from_f64(r.hi) else {
        panic!("radial hi {} is not finite", r.hi);
    };
    let radius = &arc.radius;
    for (cubic, j) in pieces.iter().flat_map(|p| (0..=8).map(move |j| (p, j))) {
        let d2 = cubic.eval(&q(j, 8)).sub(c).norm2();
        let (out, inner) = (radius.clone() + hi.clone(), radius.clone() - hi.clone());
        assert!(
            d2 <= out.clone() * out && (inner < zero || d2 >= inner.clone() * inner),
            "the radial distance at t = {j}/8 exceeds the radial hi {}: A = {}, B = {}",
            r.hi,
            arc_shape.to_json(),
            curve.to_json()
        );
    }
}

fuzz_target!(|data: &[u8]| -> Corpus {
    let mut u = Unstructured::new(data);
    let (Ok(Some(a)), Ok(Some(b))) = (shape(&mut u), shape(&mut u)) else {
        return Corpus::Reject;
    };
    let cfg = Config {
        rel: 1e-2,
        max_boxes: 16,
        ..Default::default()
    };
    // A typed error is allowed (e.g. an arc whose end parameter cannot be
    // enclosed); only Ok results are checked.
    let Ok(r) = hausdorff(&a, &b, &cfg) else {
        return Corpus::Reject;
    };
    check(&r, &a, &b);
    let Ok(s) = hausdorff(&b, &a, &cfg) else {
        panic!("hausdorff(A, B) is Ok but hausdorff(B, A) is an error");
    };
    check(&s, &b, &a);
    for (x, y, what) in [
        (&r.a_to_b, &s.b_to_a, "h(A, B)"),
        (&r.b_to_a, &s.a_to_b, "h(B, A)"),
    ] {
        assert!(
            x.lo <= y.hi && y.lo <= x.hi,
            "{what}: disjoint certified bounds [{}, {}] and [{}, {}] (A = {}, B = {})",
            x.lo,
            x.hi,
            y.lo,
            y.hi,
            a.summary(),
            b.summary()
        );
    }
    if let ShapeDesc::Arc(arc) = &a {
        radial_scenario(&mut u, arc, &cfg);
    }
    if let (ShapeDesc::Curve(ca), ShapeDesc::Curve(cb)) = (&a, &b) {
        for (lo, bound_sq, what) in [
            (r.a_to_b.lo, hull_bound_sq(ca, cb), "h(A, B)"),
            (r.b_to_a.lo, hull_bound_sq(cb, ca), "h(B, A)"),
        ] {
            assert!(
                lower_ok(lo, &bound_sq),
                "certified lower bound {lo} of {what} exceeds the exact upper bound sqrt({bound_sq})"
            );
        }
    }
    Corpus::Keep
});
