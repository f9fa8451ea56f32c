//! The exact winding number of closed piecewise-polynomial contours about a
//! rational point (the nonzero fill rule of fonts and SVG), decided with exact
//! root isolation ([`crate::poly::isolate_roots`]).
//!
//! **Method.** A ray from `p` in the direction `d = (1, k)` with a rational
//! slope `k` chosen so that the line through `p` meets no piece end point (a
//! finite set of slopes is excluded). For each piece `B`, `f(t) = d × (B(t) − p)`
//! (the side of the line `B(t)` is on) has no root at `t = 0` or `t = 1`; its
//! roots in `(0, 1)` are isolated exactly, and a root is on the ray (not the
//! opposite half line) when `g(t) = d · (B(t) − p) > 0` there, decided on the
//! root's isolating interval refined until an enclosure of `g` has one sign
//! (it has, unless `B(t) = p`: `p` on the curve, the only case answered
//! `None`). A root where `f` goes from negative to positive counts `+1` (the
//! curve crosses the ray counter-clockwise about `p`), positive to negative
//! `−1`, and a touching root (same sign on both sides) `0`; the signs are
//! those of `f` at the ends of the isolating interval of the square-free part
//! (never roots), or for a root found exactly from the first derivative that
//! does not vanish there. The sum over every piece of closed contours is the
//! winding number (each closed contour crosses the ray as often
//! counter-clockwise as its winding number more than clockwise).

use crate::curve::{Bezier, V2};
use crate::poly::{isolate_roots, refine_root, square_free, Poly, RealRoot, Span};
use crate::scalar::Rational;
use num_traits::{Signed, Zero};

fn sign(x: &Rational) -> i32 {
    if x.is_positive() {
        1
    } else if x.is_negative() {
        -1
    } else {
        0
    }
}

/// Sign of `g` at the root of `f` isolated by `r` (`None`: undecided after
/// the refinement budget, i.e. `g` vanishes there or nearly).
fn sign_at_root(f: &Poly<Rational>, r: &RealRoot, g: &Poly<Rational>) -> Option<i32> {
    if r.is_exact() {
        return match sign(&g.eval(&r.lo)) {
            0 => None,
            s => Some(s),
        };
    }
    let mut r = r.clone();
    for _ in 0..64 {
        let (a, b) = g.range_on_nonnegative(&r.lo, &r.hi);
        if a.is_positive() {
            return Some(1);
        }
        if b.is_negative() {
            return Some(-1);
        }
        let w = r.width() / Rational::from_integer(16.into());
        r = refine_root(f, &r, &w);
        if r.is_exact() {
            return match sign(&g.eval(&r.lo)) {
                0 => None,
                s => Some(s),
            };
        }
    }
    None
}

/// Signs of `f` just before and just after its root `t0` (exact).
fn sides_exact(f: &Poly<Rational>, t0: &Rational) -> (i32, i32) {
    let mut d = f.clone();
    for k in 0..=f.coeffs().len() {
        let s = sign(&d.eval(t0));
        if s != 0 {
            let before = if k % 2 == 0 { s } else { -s };
            return (before, s);
        }
        d = d.derivative();
    }
    (0, 0)
}

/// The nonzero-rule winding number of the closed contours made of `pieces`
/// (in any order: every contour closed) about `p`, exactly; `None` when `p`
/// lies on a piece (or so near that 64 refinements do not separate them).
///
/// # Examples
/// ```
/// use lncert::curve::{Bezier, V2};
/// use lncert::shape::winding_number;
/// let q = |x: i64, y: i64| V2::new(lncert::Rational::from_integer(x.into()), lncert::Rational::from_integer(y.into()));
/// // a counter-clockwise square with a quadratic top edge
/// let sq = vec![
///     Bezier::new(vec![q(0, 0), q(4, 0)]),
///     Bezier::new(vec![q(4, 0), q(4, 4)]),
///     Bezier::new(vec![q(4, 4), q(2, 6), q(0, 4)]),
///     Bezier::new(vec![q(0, 4), q(0, 0)]),
/// ];
/// assert_eq!(winding_number(&sq, &q(2, 2)), Some(1));
/// assert_eq!(winding_number(&sq, &q(2, 4)), Some(1)); // under the bump, level with two end points
/// assert_eq!(winding_number(&sq, &q(2, 5)), None); // the top of the bump: on the curve
/// assert_eq!(winding_number(&sq, &q(5, 2)), Some(0));
/// assert_eq!(winding_number(&sq, &q(4, 2)), None);
/// ```
pub fn winding_number(pieces: &[Bezier<Rational>], p: &V2<Rational>) -> Option<i64> {
    // slopes through p and an end point are excluded
    let mut forbidden = Vec::new();
    for b in pieces {
        for q in [&b.points()[0], b.points().last()?] {
            if q == p {
                return None;
            }
            if q.x != p.x {
                forbidden.push((&q.y - &p.y) / (&q.x - &p.x));
            }
        }
    }
    let k = (0i64..)
        .flat_map(|n| [n, -n])
        .map(|n| Rational::new(n.into(), 7.into()))
        .find(|k| !forbidden.contains(k))?;
    let one = Rational::from_integer(1.into());
    let mut w = 0i64;
    let iv = crate::scalar::interval_from_rational;
    let (px, py, ki) = (iv(&p.x), iv(&p.y), iv(&k));
    for b in pieces {
        // filter: the Bernstein coefficients of f (or of g) all of one
        // strict sign prove that the piece misses the line (or lies behind
        // p along the ray), so it adds nothing
        let (mut f_pos, mut f_neg, mut g_neg) = (true, true, true);
        for q in b.points() {
            let (dx, dy) = (iv(&q.x) - px, iv(&q.y) - py);
            let (fi, gi) = (dy - ki * dx, dx + ki * dy);
            f_pos &= fi.inf() > 0.0;
            f_neg &= fi.sup() < 0.0;
            g_neg &= gi.sup() < 0.0;
        }
        if f_pos || f_neg || g_neg {
            continue;
        }
        let (x, y) = b.power_coords();
        let x = x.sub(&Poly::constant(p.x.clone()));
        let y = y.sub(&Poly::constant(p.y.clone()));
        let f = y.sub(&x.scale(&k)); // d × (B − p), d = (1, k)
        let g = x.add(&y.scale(&k)); // d · (B − p)
        if f.coeffs().iter().all(Zero::is_zero) {
            // the piece lies on the line: it has no end point off it, excluded above
            return None;
        }
        let sf = square_free(&f);
        for r in isolate_roots(&sf, &Span::open(Rational::zero(), one.clone())) {
            if sign_at_root(&sf, &r, &g)? < 0 {
                continue;
            }
            let (before, after) = if r.is_exact() {
                sides_exact(&f, &r.lo)
            } else {
                (sign(&f.eval(&r.lo)), sign(&f.eval(&r.hi)))
            };
            if before == 0 || after == 0 {
                return None;
            }
            w += i64::from((after - before) / 2);
        }
    }
    Some(w)
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::test_util::qi as q;
    use proptest::prelude::*;

    /// Oracle: the winding number of a closed polygon about `p` by signed
    /// crossings of a horizontal ray, in exact rationals (`None` when `p`
    /// is on an edge).
    fn polygon_winding(vs: &[V2<Rational>], p: &V2<Rational>) -> Option<i64> {
        let mut w = 0;
        for i in 0..vs.len() {
            let (a, b) = (&vs[i], &vs[(i + 1) % vs.len()]);
            let side = b.sub(a).cross(&p.sub(a));
            let within =
                |u: &Rational, v: &Rational, x: &Rational| (u.min(v) <= x) && (x <= u.max(v));
            if side.is_zero() && within(&a.x, &b.x, &p.x) && within(&a.y, &b.y, &p.y) {
                return None;
            }
            if a.y <= p.y && b.y > p.y && side.is_positive() {
                w += 1;
            } else if b.y <= p.y && a.y > p.y && side.is_negative() {
                w -= 1;
            }
        }
        Some(w)
    }

    proptest! {
        #![proptest_config(ProptestConfig::with_cases(256))]
        /// On closed polygons whose edges are written as cubics (and lines),
        /// the winding number agrees with the exact horizontal-ray oracle,
        /// and it is undecided only for points on the outline.
        #[test]
        fn winding_matches_the_polygon_oracle(
            vs in proptest::collection::vec((-6i64..6, -6i64..6), 3..8),
            (px, py) in (-13i64..13, -13i64..13),
            cubic in proptest::collection::vec(any::<bool>(), 8),
        ) {
            let vs: Vec<V2<Rational>> = vs.iter().map(|&(x, y)| V2::new(q(x, 1), q(y, 1))).collect();
            let p = V2::new(q(px, 2), q(py, 2));
            let mut pieces = Vec::new();
            for i in 0..vs.len() {
                let (a, b) = (&vs[i], &vs[(i + 1) % vs.len()]);
                if a == b {
                    continue;
                }
                pieces.push(if cubic[i] {
                    let d = b.sub(a);
                    let third = |k: i64| a.add(&d.scale(&q(k, 3)));
                    Bezier::new(vec![a.clone(), third(1), third(2), b.clone()])
                } else {
                    Bezier::new(vec![a.clone(), b.clone()])
                });
            }
            prop_assume!(!pieces.is_empty());
            let oracle = polygon_winding(&vs, &p);
            match winding_number(&pieces, &p) {
                Some(w) => prop_assert_eq!(Some(w), oracle),
                None => prop_assert!(oracle.is_none(), "undecided off the outline"),
            }
        }
    }
}
