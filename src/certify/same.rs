//! Exact equality of shapes as geometry: does a certificate speak about *these*
//! shapes? (`lncert verify CERT --against A B`.)
//!
//! Two descriptions are the same shape when they describe the same parametrised
//! geometry up to what does not change the statement `d_H(A, B) ≤ tol`:
//!
//! - **curves**: the same sequence of polynomial arcs, up to splitting a piece at
//!   interior parameters (an offset's certificate stores its input split at
//!   dyadic parameters), degree elevation, and reversal of the whole curve;
//! - **arcs**: the same centre and radius, and direction vectors that are
//!   positive multiples of each other (the counter-clockwise sweep is the same);
//! - **offsets and convolutions**: the same curve up to splitting and elevation
//!   (not reversal: it flips the side), the same `Q = M Mᵀ` (the ellipse `M · unit
//!   circle` is the same set for `M` and `M R`, `R` orthogonal) and the same side;
//!   an offset at distance `r` is the convolution with `Q = r² I` on the side of
//!   `sign r`.
//!
//! Every comparison is exact (rational arithmetic).

use crate::curve::{Bezier, V2};
use crate::scalar::Rational;
use crate::shape::{ArcDesc, ShapeDesc};
use num_bigint::BigInt;
use num_traits::{One, Signed, Zero};

type Piece = Bezier<Rational>;

/// The normal form of an offset or convolution: curve, `Q = M Mᵀ`, side.
fn conv_form(s: &ShapeDesc) -> Option<(&[Piece], [Rational; 3], i8)> {
    match s {
        ShapeDesc::Offset { curve, distance } => {
            let r2 = distance * distance;
            let side = if distance.is_positive() { 1 } else { -1 };
            Some((curve, [r2.clone(), Rational::zero(), r2], side))
        }
        ShapeDesc::Convolution {
            curve,
            ellipse: m,
            side,
        } => Some((
            curve,
            [
                &m[0][0] * &m[0][0] + &m[0][1] * &m[0][1],
                &m[0][0] * &m[1][0] + &m[0][1] * &m[1][1],
                &m[1][0] * &m[1][0] + &m[1][1] * &m[1][1],
            ],
            *side,
        )),
        _ => None,
    }
}

impl ShapeDesc {
    /// `Ok(())` if `self` and `other` are the same shape (see the module docs),
    /// otherwise the first difference found.
    ///
    /// # Examples
    /// ```
    /// use lncert::shape::ShapeDesc;
    /// let whole = ShapeDesc::parse("M 0 0 Q 1 2 2 0").unwrap();
    /// let halves = ShapeDesc::parse(r#"{"beziers": [[[0, 0], ["1/2", 1], [1, 1]], [[1, 1], ["3/2", 1], [2, 0]]]}"#).unwrap();
    /// assert!(whole.same_as(&halves).is_ok());
    /// // the quadratic elevated to a cubic and reversed: the same point set
    /// let cubic = ShapeDesc::parse(r#"{"bezier": [[2, 0], ["4/3", "4/3"], ["2/3", "4/3"], [0, 0]]}"#).unwrap();
    /// assert!(whole.same_as(&cubic).is_ok());
    /// // decimals are exact: 1.3333 is not 4/3
    /// let near = ShapeDesc::parse("M 2 0 C 1.3333 1.3333 0.6667 1.3333 0 0").unwrap();
    /// assert!(whole.same_as(&near).is_err());
    /// ```
    pub fn same_as(&self, other: &ShapeDesc) -> Result<(), String> {
        match (self, other) {
            (ShapeDesc::Curve(x), ShapeDesc::Curve(y)) => same_curve(x, y).or_else(|e| {
                let rev: Vec<Piece> = y
                    .iter()
                    .rev()
                    .map(|b| Bezier::new(b.points().iter().rev().cloned().collect()))
                    .collect();
                same_curve(x, &rev).map_err(|_| e)
            }),
            (ShapeDesc::Arc(a), ShapeDesc::Arc(b)) => same_arc(a, b),
            (ShapeDesc::Union(x), ShapeDesc::Union(y)) => {
                if x.len() != y.len() {
                    return Err(format!("unions of {} and {} members", x.len(), y.len()));
                }
                for (i, (a, b)) in x.iter().zip(y).enumerate() {
                    a.same_as(b).map_err(|e| format!("member {i}: {e}"))?;
                }
                Ok(())
            }
            _ => match (conv_form(self), conv_form(other)) {
                (Some((cx, qx, sx)), Some((cy, qy, sy))) => {
                    if qx != qy {
                        return Err(
                            "different pen: the matrices Q = M Mᵀ (r² I for an offset) differ"
                                .into(),
                        );
                    }
                    if sx != sy {
                        return Err(
                            "different side (sign of the distance, or convolution side)".into()
                        );
                    }
                    same_curve(cx, cy).map_err(|e| format!("the curve: {e}"))
                }
                _ => Err(format!(
                    "different kinds of shape: {} against {}",
                    self.summary(),
                    other.summary()
                )),
            },
        }
    }
}

fn positively_parallel(u: &V2<Rational>, v: &V2<Rational>) -> bool {
    u.cross(v).is_zero() && u.dot(v).is_positive()
}

fn same_arc(a: &ArcDesc, b: &ArcDesc) -> Result<(), String> {
    if a.center != b.center {
        return Err("arcs with different centres".into());
    }
    if a.radius != b.radius {
        return Err("arcs with different radii".into());
    }
    if !positively_parallel(&a.from, &b.from) || !positively_parallel(&a.to, &b.to) {
        return Err(
            "arcs with different end directions (the counter-clockwise sweep differs)".into(),
        );
    }
    Ok(())
}

/// The exact `k`-th root of a positive rational, if it is rational.
fn rational_root(r: &Rational, k: u32) -> Option<Rational> {
    let root = |n: &BigInt| {
        let x = n.nth_root(k);
        (num_traits::pow(x.clone(), k as usize) == *n).then_some(x)
    };
    Some(Rational::new(root(r.numer())?, root(r.denom())?))
}

/// `h > 0` with `u = h^k v` for the first order `k` at which `v` (the
/// derivatives of the longer-or-equal piece at its start) is nonzero.
fn speed_ratio(u: &Piece, v: &Piece) -> Option<Rational> {
    let (mut du, mut dv) = (u.clone(), v.clone());
    for k in 1..=v.degree().max(1) as u32 {
        du = du.hodograph();
        dv = dv.hodograph();
        let (pu, pv) = (&du.points()[0], &dv.points()[0]);
        if pv.x.is_zero() && pv.y.is_zero() {
            if pu.x.is_zero() && pu.y.is_zero() {
                continue;
            }
            return None;
        }
        if !positively_parallel(pu, pv) && !(k % 2 == 0 && pu.cross(pv).is_zero()) {
            return None;
        }
        let ratio = if pv.x.is_zero() {
            &pu.y / &pv.y
        } else {
            &pu.x / &pv.x
        };
        if !ratio.is_positive() {
            return None;
        }
        return rational_root(&ratio, k);
    }
    None
}

fn elevate_to(b: &Piece, n: usize) -> Piece {
    let mut b = b.clone();
    while b.degree() < n {
        b = b.elevate();
    }
    b
}

fn is_point(b: &Piece) -> bool {
    b.points().iter().all(|p| *p == b.points()[0])
}

/// The same curve up to splitting pieces and degree elevation (same direction).
fn same_curve(x: &[Piece], y: &[Piece]) -> Result<(), String> {
    let one = Rational::one();
    // cursors: piece index and start parameter of its remaining part
    let (mut i, mut a) = (0usize, Rational::zero());
    let (mut j, mut c) = (0usize, Rational::zero());
    let rest = |p: &Piece, s: &Rational| {
        if s.is_zero() {
            p.clone()
        } else {
            p.restrict(s, &one)
        }
    };
    let mut steps = 0usize;
    while i < x.len() && j < y.len() {
        steps += 1;
        if steps > 4 * (x.len() + y.len()) {
            return Err("too many pieces to match".into());
        }
        let (u, v) = (rest(&x[i], &a), rest(&y[j], &c));
        let at = || format!("piece {i} (from its parameter {a}) against piece {j} (from {c})");
        if u.points()[0] != v.points()[0] {
            return Err(format!("{}: different start points", at()));
        }
        // single points add nothing to the point set once their neighbour starts there
        if is_point(&u) || is_point(&v) {
            if is_point(&u) {
                (i, a) = (i + 1, Rational::zero());
            }
            if is_point(&v) {
                (j, c) = (j + 1, Rational::zero());
            }
            continue;
        }
        let n = u.degree().max(v.degree());
        let (u, v) = (elevate_to(&u, n), elevate_to(&v, n));
        // u(s) = v(h s) with h ≤ 1, or v(s) = u(s / h) with h > 1
        let h = speed_ratio(&u, &v)
            .ok_or_else(|| format!("{}: different directions or speeds at the start", at()))?;
        if h <= one {
            if u != v.restrict(&Rational::zero(), &h) {
                return Err(format!("{}: different curves", at()));
            }
            // x's piece is used up; y's advances to c + h (1 − c)
            c = &c + &h * (&one - &c);
            (i, a) = (i + 1, Rational::zero());
            if c == one {
                (j, c) = (j + 1, Rational::zero());
            }
        } else {
            let g = one.clone() / &h;
            if v != u.restrict(&Rational::zero(), &g) {
                return Err(format!("{}: different curves", at()));
            }
            a = &a + &g * (&one - &a);
            (j, c) = (j + 1, Rational::zero());
        }
    }
    // trailing single points
    let trailing_points = |p: &[Piece], k: usize| p[k.min(p.len())..].iter().all(is_point);
    if (i < x.len() && !trailing_points(x, i)) || (j < y.len() && !trailing_points(y, j)) {
        return Err("one curve continues where the other ends".into());
    }
    Ok(())
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::scalar::parse_rational;

    fn shape(s: &str) -> ShapeDesc {
        ShapeDesc::parse(s).unwrap()
    }

    #[test]
    fn curves_equal_up_to_splitting_elevation_and_reversal() {
        let c = shape("M 0 0 C 1 2 3 2 4 0");
        let ShapeDesc::Curve(p) = &c else {
            unreachable!()
        };
        let third = parse_rational("1/3").unwrap();
        let (l, r) = p[0].split(&third);
        let (rl, rr) = r.split(&parse_rational("5/7").unwrap());
        let split = ShapeDesc::Curve(vec![l.elevate(), rl, rr.elevate().elevate()]);
        assert!(c.same_as(&split).is_ok());
        assert!(split.same_as(&c).is_ok());
        let rev = shape("M 4 0 C 3 2 1 2 0 0");
        assert!(c.same_as(&rev).is_ok());
        // a moved control point, a missing end, a different parametrisation
        assert!(c.same_as(&shape("M 0 0 C 1 2 3 2.001 4 0")).is_err());
        assert!(c.same_as(&ShapeDesc::Curve(vec![l])).is_err());
        assert!(c.same_as(&shape("M 0 0 C 2 4 3 2 4 0")).is_err());
    }

    #[test]
    fn arcs_offsets_and_convolutions() {
        let a = shape(r#"{"arc": {"center": [0, 0], "radius": 1, "from": [1, 0], "to": [0, 1]}}"#);
        let b =
            shape(r#"{"arc": {"center": [0, 0], "radius": 1, "from": [3, 0], "to": [0, "1/2"]}}"#);
        let cw = shape(
            r#"{"arc": {"center": [0, 0], "radius": 1, "from": [1, 0], "to": [0, 1], "clockwise": true}}"#,
        );
        assert!(a.same_as(&b).is_ok());
        assert!(a.same_as(&cw).is_err());
        let o = shape(r#"{"offset": {"curve": "M 0 0 Q 1 1 2 0", "distance": "-1/2"}}"#);
        let conv = shape(
            r#"{"convolution": {"curve": {"beziers": [[[0, 0], ["1/2", "1/2"], [1, "1/2"]], [[1, "1/2"], ["3/2", "1/2"], [2, 0]]]}, "ellipse": [[0, "1/2"], ["-1/2", 0]], "side": -1}}"#,
        );
        assert!(o.same_as(&conv).is_ok());
        let other_side = shape(r#"{"offset": {"curve": "M 0 0 Q 1 1 2 0", "distance": "1/2"}}"#);
        assert!(o.same_as(&other_side).is_err());
        let reversed = shape(r#"{"offset": {"curve": "M 2 0 Q 1 1 0 0", "distance": "-1/2"}}"#);
        assert!(o.same_as(&reversed).is_err());
        assert!(o.same_as(&a).is_err());
    }
}
