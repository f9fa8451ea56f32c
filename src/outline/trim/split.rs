//! Splitting the raw pieces at their certified crossings (step 3).

use super::sides::{approx_dir, dist_hi, set_end};
use super::types::Piece;
use crate::curve::{Bezier, V2};
use crate::scalar::{rational_from_f64, Rational};
use num_traits::{One, Signed, Zero};

// ---------------------------------------------------------------------------
// splitting

#[derive(Clone, Debug)]
pub(super) struct Split {
    /// Bézier: the parameter; arc: unused.
    pub(super) param: Rational,
    /// The exact crossing point shared by both pieces.
    pub(super) point: V2<Rational>,
}

#[derive(Clone, Debug)]
pub(super) struct Sub {
    pub(super) raw: usize,
    /// The exact sub-piece of the raw piece (its union over the raw piece is
    /// the raw piece).
    pub(super) pre: Piece,
    /// With the crossing points as end points (what is output).
    pub(super) post: Piece,
    /// Largest end move.
    pub(super) delta: f64,
    /// The sub-piece's ends are crossing points (not raw piece ends).
    pub(super) end_splits: [bool; 2],
    /// Bézier: its parameter range on the raw piece (`pre` is the exact
    /// restriction to it).
    pub(super) range: (Rational, Rational),
}

pub(super) fn split_piece(raw: usize, p: &Piece, splits: &mut [Split]) -> Vec<Sub> {
    match p {
        Piece::Bezier(b) => {
            splits.sort_by(|a, b| a.param.cmp(&b.param));
            let zero = <Rational as Zero>::zero();
            let one = <Rational as One>::one();
            let mut out = Vec::new();
            let mut prev: Option<&Split> = None;
            for k in 0..=splits.len() {
                let next = splits.get(k);
                let a = prev.map(|s| s.param.clone()).unwrap_or(zero.clone());
                let bb = next.map(|s| s.param.clone()).unwrap_or(one.clone());
                let pre = b.restrict(&a, &bb);
                let post = set_end(&pre, prev.map(|s| &s.point), next.map(|s| &s.point));
                let mut delta: f64 = 0.0;
                if let Some(s) = prev {
                    delta = delta.max(dist_hi(&pre.points()[0], &s.point));
                }
                if let Some(s) = next {
                    delta = delta.max(dist_hi(pre.points().last().expect("nonempty"), &s.point));
                }
                out.push(Sub {
                    raw,
                    pre: Piece::Bezier(pre),
                    post: Piece::Bezier(post),
                    delta,
                    end_splits: [prev.is_some(), next.is_some()],
                    range: (a, bb),
                });
                prev = next;
            }
            out
        }
        Piece::Arc(a) => {
            // order along the travel direction by the angle from the start
            let ang = |pt: &V2<Rational>| {
                let u = approx_dir(&a.from.sub(&a.center));
                let v = approx_dir(&pt.sub(&a.center));
                let mut d = v.1.atan2(v.0) - u.1.atan2(u.0);
                if a.clockwise {
                    d = -d;
                }
                d.rem_euclid(2.0 * std::f64::consts::PI)
            };
            splits.sort_by(|x, y| ang(&x.point).total_cmp(&ang(&y.point)));
            let mut out = Vec::new();
            let mut cur = a.clone();
            let mut first = true;
            for s in splits.iter() {
                let (l, r) = cur.split_at(&s.point);
                out.push(Sub {
                    raw,
                    pre: Piece::Arc(l.clone()),
                    post: Piece::Arc(l),
                    delta: 0.0,
                    end_splits: [!first, true],
                    range: (<Rational as Zero>::zero(), <Rational as One>::one()),
                });
                first = false;
                cur = r;
            }
            out.push(Sub {
                raw,
                pre: Piece::Arc(cur.clone()),
                post: Piece::Arc(cur),
                delta: 0.0,
                end_splits: [!first, false],
                range: (<Rational as Zero>::zero(), <Rational as One>::one()),
            });
            out
        }
    }
}

/// The crossing of two degree-1 pieces with non-parallel directions, exact:
/// the point and both parameters (inside `[0, 1]`), `None` otherwise.
pub(super) fn segment_crossing(
    a: &Bezier<Rational>,
    b: &Bezier<Rational>,
) -> Option<(V2<Rational>, Rational, Rational)> {
    if a.degree() != 1 || b.degree() != 1 {
        return None;
    }
    let (p, q) = (&a.points()[0], &a.points()[1]);
    let (u, v) = (&b.points()[0], &b.points()[1]);
    let (d1, d2) = (q.sub(p), v.sub(u));
    let den = d1.cross(&d2);
    if den.is_zero() {
        return None;
    }
    let w = u.sub(p);
    let s = w.cross(&d2) / &den;
    let t = w.cross(&d1) / &den;
    let unit = |x: &Rational| !x.is_negative() && *x <= <Rational as One>::one();
    (unit(&s) && unit(&t)).then(|| (p.add(&d1.scale(&s)), s, t))
}

/// The exact projection of `x` onto a degree-1 piece and its parameter,
/// when that parameter is strictly inside `(0, 1)`.
pub(super) fn project_on_segment(
    a: &Bezier<Rational>,
    x: &V2<Rational>,
) -> Option<(V2<Rational>, Rational)> {
    let (p, q) = (&a.points()[0], &a.points()[1]);
    let d = q.sub(p);
    let n2 = d.norm2();
    if n2.is_zero() {
        return None;
    }
    let u = x.sub(p).dot(&d) / n2;
    (u.is_positive() && u < <Rational as One>::one()).then(|| (p.add(&d.scale(&u)), u))
}

pub(super) fn mid_rational(lo: f64, hi: f64) -> Option<Rational> {
    rational_from_f64(0.5 * lo + 0.5 * hi)
}
