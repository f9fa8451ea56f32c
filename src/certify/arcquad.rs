//! Circular arcs as **quadratic** Bézier pieces with a certified Hausdorff
//! bound (TrueType output of `lncert font --output quadratic`), proven by
//! [`super::hausdorff`] itself rather than by a formula.
//!
//! Construction (floats): the arc is split into `n` equal sub-arcs; the joints
//! are rational points near the circle (the first and last are the arc's own
//! end points, exactly), each piece's control point the intersection of the
//! circle's tangents at its two ends (the classical construction; the pieces
//! share their end points, the same rational, so the chain is connected).
//!
//! Proof: let `Aᵢ` be the sub-arc of the exact circle between the directions
//! (from the centre) of joint `i` and joint `i + 1`, travelled the arc's way.
//! The `Aᵢ` cover the arc exactly (consecutive sub-arcs share a direction, the
//! first and last directions are the arc's end points'), so for the chain
//! `Q = ∪ Qᵢ`, `d_H(Q, A) ≤ maxᵢ d_H(Qᵢ, Aᵢ)` (every point of one union is
//! within that of the other). Each `d_H(Qᵢ, Aᵢ)` is bounded by
//! [`super::hausdorff`] (a quadratic against an exact arc of the shape
//! language, certified by interval branch and bound) with the target as its
//! tolerance. `n` starts from the float estimate `r·φ⁴/128` of a piece of
//! angle `φ` (plus slack) and is doubled, at most four times, when a piece's
//! proof misses the target.

use super::{hausdorff, Config};
use crate::curve::{Bezier, V2};
use crate::scalar::{rational_from_f64, Rational, Scalar};
use crate::shape::{ArcDesc, ShapeDesc};

/// Most quadratic pieces per arc.
const MAX_PIECES: usize = 256;

fn f(r: &Rational) -> f64 {
    r.approx()
}

/// The arc of the circle `(center, radius)` from `from` to `to` (points on
/// the circle; `clockwise` the way it is travelled), as quadratic pieces from
/// `from` to `to` exactly, and a certified upper bound of their Hausdorff
/// distance from the exact arc, aiming at `target` (`> 0`). Empty when
/// `from = to`.
///
/// Errors: the reason (a non-finite float, no proof within 256 pieces).
///
/// # Examples
/// ```
/// use lncert::certify::circular_arc_quadratics;
/// use lncert::curve::V2;
/// use lncert::Rational;
/// let q = |x: i64| Rational::from_integer(x.into());
/// let (c, r) = (V2::new(q(0), q(0)), q(10));
/// // a quarter circle, counter-clockwise from (10, 0) to (0, 10)
/// let (pieces, bound) =
///     circular_arc_quadratics(&c, &r, &V2::new(q(10), q(0)), &V2::new(q(0), q(10)), false, 1e-3)
///         .unwrap();
/// assert!(bound <= 1e-3);
/// assert!(pieces.iter().all(|b| b.degree() == 2));
/// assert_eq!(pieces[0].points()[0], V2::new(q(10), q(0)));
/// assert_eq!(pieces.last().unwrap().points()[2], V2::new(q(0), q(10)));
/// ```
pub fn circular_arc_quadratics(
    center: &V2<Rational>,
    radius: &Rational,
    from: &V2<Rational>,
    to: &V2<Rational>,
    clockwise: bool,
    target: f64,
) -> Result<(Vec<Bezier<Rational>>, f64), String> {
    if from == to {
        return Ok((Vec::new(), 0.0));
    }
    if !(target > 0.0 && target.is_finite()) {
        return Err("the target must be a positive number".into());
    }
    let (cx, cy, r) = (f(&center.x), f(&center.y), f(radius));
    let a0 = (f(&from.y) - cy).atan2(f(&from.x) - cx);
    let a1 = (f(&to.y) - cy).atan2(f(&to.x) - cx);
    let tau = std::f64::consts::TAU;
    // the sweep, in (0, 2π), signed by the direction
    let mut sweep = (a1 - a0).rem_euclid(tau);
    if clockwise {
        sweep = -((a0 - a1).rem_euclid(tau));
    }
    if !(r.is_finite() && sweep.is_finite() && sweep != 0.0) {
        return Err("the arc is not finite".into());
    }
    // r·φ⁴/128 ≈ the radial error of the tangent-intersection quadratic of angle φ
    let mut n = 1usize;
    while n < MAX_PIECES && r * (sweep.abs() / n as f64).powi(4) / 128.0 > target / 4.0 {
        n += 1;
    }
    for _ in 0..5 {
        match attempt(center, radius, from, to, (cx, cy, r), a0, sweep, n, target) {
            Ok(done) => return Ok(done),
            Err(e) if n * 2 > MAX_PIECES => return Err(e),
            Err(_) => n *= 2,
        }
    }
    Err(format!(
        "no certified quadratic approximation within {target:e} with {n} pieces"
    ))
}

#[allow(clippy::too_many_arguments)]
fn attempt(
    center: &V2<Rational>,
    radius: &Rational,
    from: &V2<Rational>,
    to: &V2<Rational>,
    (cx, cy, r): (f64, f64, f64),
    a0: f64,
    sweep: f64,
    n: usize,
    target: f64,
) -> Result<(Vec<Bezier<Rational>>, f64), String> {
    let exact = |x: f64| rational_from_f64(x).ok_or("a non-finite coordinate");
    let angle = |k: usize| a0 + sweep * k as f64 / n as f64;
    let mut joints = vec![from.clone()];
    for k in 1..n {
        let t = angle(k);
        joints.push(V2::new(exact(cx + r * t.cos())?, exact(cy + r * t.sin())?));
    }
    joints.push(to.clone());
    let half = (sweep / n as f64) / 2.0;
    let reach = r / half.cos(); // centre to the tangents' intersection
    let mut pieces = Vec::with_capacity(n);
    let mut bound = 0.0f64;
    for k in 0..n {
        let m = angle(k) + half;
        let ctrl = V2::new(exact(cx + reach * m.cos())?, exact(cy + reach * m.sin())?);
        let q = Bezier::new(vec![joints[k].clone(), ctrl, joints[k + 1].clone()]);
        // the sub-arc between the joints' directions, counter-clockwise
        let (u, v) = (joints[k].sub(center), joints[k + 1].sub(center));
        let (start, end) = if sweep > 0.0 { (u, v) } else { (v, u) };
        let arc = ShapeDesc::arc(ArcDesc {
            center: center.clone(),
            radius: radius.clone(),
            from: start,
            to: end,
        })
        .map_err(|e| e.to_string())?;
        let cfg = Config {
            tol: Some(crate::Tolerance::from_f64(target).map_err(|e| e.to_string())?),
            verdict_only: true,
            max_boxes: 20_000,
            ..Config::default()
        };
        let h =
            hausdorff(&ShapeDesc::Curve(vec![q.clone()]), &arc, &cfg).map_err(|e| e.to_string())?;
        if h.hi.is_nan() || h.hi > target {
            return Err(format!("piece {k}: certified only within {:e}", h.hi));
        }
        bound = bound.max(h.hi);
        pieces.push(q);
    }
    Ok((pieces, bound))
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Clockwise and counter-clockwise arcs of every size: connected, the
    /// exact end points, within the target, and the sampled radial error of
    /// every piece below the certified bound.
    #[test]
    fn arcs_both_ways_within_the_certified_bound() {
        let q = |x: i64| Rational::from_integer(x.into());
        let (c, r) = (V2::new(q(3), q(-2)), q(5));
        let pts = [
            V2::new(q(8), q(-2)),
            V2::new(q(3), q(3)),
            V2::new(q(-2), q(-2)),
            V2::new(q(6), q(-6)),
        ];
        for (i, a) in pts.iter().enumerate() {
            for b in &pts[i + 1..] {
                for cw in [false, true] {
                    let (p, bound) = circular_arc_quadratics(&c, &r, a, b, cw, 1e-4).unwrap();
                    assert!(bound <= 1e-4);
                    assert_eq!(&p[0].points()[0], a);
                    assert_eq!(&p.last().unwrap().points()[2], b);
                    for w in p.windows(2) {
                        assert_eq!(w[0].points()[2], w[1].points()[0]);
                    }
                    let mut worst = 0.0f64;
                    for piece in &p {
                        let pf = piece.map(|x| x.approx());
                        for k in 0..=50 {
                            let v = pf.eval(&(k as f64 / 50.0));
                            worst = worst.max(((v.x - 3.0).hypot(v.y + 2.0) - 5.0).abs());
                        }
                    }
                    assert!(worst <= bound, "{worst} > {bound}");
                }
            }
        }
        assert!(
            circular_arc_quadratics(&c, &r, &pts[0], &pts[0], false, 1e-4)
                .unwrap()
                .0
                .is_empty()
        );
    }
}
