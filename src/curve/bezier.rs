//! Bézier curves of any degree: evaluation, hodograph, subdivision, restriction,
//! degree elevation, and products of Bernstein polynomials.

use super::V2;
use crate::poly::{binomial_big, ratio_scalar, Poly};
use crate::scalar::{Rational, Scalar};

/// A planar Bézier curve `b(t) = sum_i p_i B^n_i(t)`, `t in [0, 1]`.
///
/// # Examples
/// ```
/// use lncert::curve::{Bezier, V2};
/// let c = Bezier::new(vec![V2::new(0.0, 0.0), V2::new(1.0, 2.0), V2::new(2.0, 0.0)]);
/// assert_eq!(c.eval(&0.5), V2::new(1.0, 1.0));
/// assert_eq!(c.hodograph().points()[0], V2::new(2.0, 4.0));
/// ```
#[derive(Clone, Debug, PartialEq)]
pub struct Bezier<S> {
    pts: Vec<V2<S>>,
}

impl<S: Scalar> Bezier<S> {
    /// From control points.
    ///
    /// # Panics
    /// If `pts` is empty. Parsed input never reaches this (the parsers in
    /// [`crate::shape::parse_curve`] reject curves with fewer than 2 points).
    pub fn new(pts: Vec<V2<S>>) -> Self {
        assert!(
            !pts.is_empty(),
            "a Bézier curve needs at least one control point"
        );
        Bezier { pts }
    }
    /// Converts exact control points into `S`.
    pub fn from_rational(c: &Bezier<Rational>) -> Self {
        Bezier {
            pts: c.pts.iter().map(V2::from_rational).collect(),
        }
    }
    /// The control points, in order (at least one).
    pub fn points(&self) -> &[V2<S>] {
        &self.pts
    }
    /// The degree: the number of control points minus one.
    pub fn degree(&self) -> usize {
        self.pts.len() - 1
    }
    /// de Casteljau evaluation.
    pub fn eval(&self, t: &S) -> V2<S> {
        let (xs, ys) = self.coords();
        if let (Some(x), Some(y)) = (S::bernstein_eval(&xs, t), S::bernstein_eval(&ys, t)) {
            return V2::new(x, y);
        }
        let mut p = self.pts.clone();
        let n = p.len();
        for r in 1..n {
            for i in 0..n - r {
                p[i] = p[i].lerp(&p[i + 1], t);
            }
        }
        p.swap_remove(0)
    }
    /// `[b′(0), b′(1)]` exactly: the end points of [`Bezier::hodograph`]
    /// (`n·(P₁ − P₀)`, `n·(Pₙ − Pₙ₋₁)`), without the rest of it.
    ///
    /// ```
    /// use lncert::curve::{Bezier, V2};
    /// let b = Bezier::new(vec![V2::new(0.0, 0.0), V2::new(1.0, 2.0), V2::new(3.0, 2.0)]);
    /// let h = b.hodograph();
    /// assert_eq!(b.end_derivatives(), [h.points()[0].clone(), h.points()[1].clone()]);
    /// ```
    pub fn end_derivatives(&self) -> [V2<S>; 2] {
        let n = self.degree();
        if n == 0 {
            return [V2::zero(), V2::zero()];
        }
        let k = S::from_i64(n as i64);
        let p = &self.pts;
        [p[1].sub(&p[0]).scale(&k), p[n].sub(&p[n - 1]).scale(&k)]
    }

    /// The derivative curve `b'(t)`, of degree `n - 1` (a single zero point for
    /// a constant curve).
    pub fn hodograph(&self) -> Bezier<S> {
        let n = self.degree();
        if n == 0 {
            return Bezier {
                pts: vec![V2::zero()],
            };
        }
        let k = S::from_i64(n as i64);
        Bezier {
            pts: self
                .pts
                .windows(2)
                .map(|w| w[1].sub(&w[0]).scale(&k))
                .collect(),
        }
    }
    /// Splits at `t` into the pieces over `[0, t]` and `[t, 1]`, each
    /// reparametrised to `[0, 1]`.
    pub fn split(&self, t: &S) -> (Bezier<S>, Bezier<S>) {
        self.split_by(|p, q| p.lerp(q, t))
    }
    /// [`Bezier::split`] with its de Casteljau step given: `step(p, q)` is
    /// the point at the split parameter between `p` and `q` (an arithmetic
    /// of the caller's own, e.g. outward-rounded enclosures).
    pub fn split_by(&self, step: impl Fn(&V2<S>, &V2<S>) -> V2<S>) -> (Bezier<S>, Bezier<S>) {
        let mut p = self.pts.clone();
        let n = p.len();
        let mut left = Vec::with_capacity(n);
        let mut right = Vec::with_capacity(n);
        left.push(p[0].clone());
        right.push(p[n - 1].clone());
        for r in 1..n {
            for i in 0..n - r {
                p[i] = step(&p[i], &p[i + 1]);
            }
            left.push(p[0].clone());
            right.push(p[n - 1 - r].clone());
        }
        right.reverse();
        (Bezier { pts: left }, Bezier { pts: right })
    }
    /// The piece over `[a, b]` reparametrised to `[0, 1]` (`a > b` reverses).
    pub fn restrict(&self, a: &S, b: &S) -> Bezier<S> {
        // Blossom: control point i = blossom(a^(n-i), b^i), by de Casteljau in
        // the convex form (1 − u) p + u q: in floats a parameter 0 or 1 gives an
        // end control point bit for bit, and neighbouring spans share the
        // point at their common parameter.
        let (xs, ys) = self.coords();
        if let (Some(x), Some(y)) = (
            S::bernstein_restrict(&xs, a, b),
            S::bernstein_restrict(&ys, a, b),
        ) {
            return Bezier {
                pts: x.into_iter().zip(y).map(|(x, y)| V2::new(x, y)).collect(),
            };
        }
        let n = self.degree();
        let pts = (0..=n)
            .map(|i| {
                let mut p = self.pts.clone();
                for r in 0..n {
                    let u = if r < n - i { a } else { b };
                    let v = S::one() - u.clone();
                    for j in 0..n - r {
                        p[j] = p[j].scale(&v).add(&p[j + 1].scale(u));
                    }
                }
                p.swap_remove(0)
            })
            .collect();
        Bezier { pts }
    }
    /// The same curve written with one more control point.
    pub fn elevate(&self) -> Bezier<S> {
        let n = self.degree();
        let n1 = S::from_i64(n as i64 + 1);
        let mut pts = vec![self.pts[0].clone()];
        for i in 1..=n {
            let a = S::from_i64(i as i64).div(&n1).expect("n+1 > 0");
            pts.push(self.pts[i - 1].lerp(&self.pts[i], &(S::one() - a)));
        }
        pts.push(self.pts[n].clone());
        Bezier { pts }
    }
    /// Bernstein coefficients of the x and y coordinates.
    pub fn coords(&self) -> (Vec<S>, Vec<S>) {
        (
            self.pts.iter().map(|p| p.x.clone()).collect(),
            self.pts.iter().map(|p| p.y.clone()).collect(),
        )
    }
    /// Power-form coordinate polynomials `(x(t), y(t))`.
    pub fn power_coords(&self) -> (Poly<S>, Poly<S>) {
        let (x, y) = self.coords();
        (Poly::from_bernstein(&x), Poly::from_bernstein(&y))
    }
    /// Bernstein coefficients (degree `2n - 3`) of `x' y'' - y' x''`, whose
    /// sign is the sign of the curvature.
    pub fn cross_hodograph(&self) -> Vec<S> {
        let d1 = self.hodograph();
        let d2 = d1.hodograph();
        let (x1, y1) = d1.coords();
        let (x2, y2) = d2.coords();
        let a = bernstein_product(&x1, &y2);
        let b = bernstein_product(&y1, &x2);
        a.into_iter().zip(b).map(|(p, q)| p - q).collect()
    }
    /// Maps every coordinate.
    pub fn map<T: Scalar>(&self, f: impl Fn(&S) -> T + Copy) -> Bezier<T> {
        Bezier {
            pts: self.pts.iter().map(|p| p.map(f)).collect(),
        }
    }
}

impl Bezier<f64> {
    /// Evaluation with glam vectors (the f64 fast path for hot loops).
    pub fn eval_fast(&self, t: f64) -> glam::DVec2 {
        let mut buf: smallvec_like::Buf = smallvec_like::Buf::new(&self.pts);
        let n = buf.len();
        for r in 1..n {
            for i in 0..n - r {
                let (a, b) = (buf.get(i), buf.get(i + 1));
                buf.set(i, a + (b - a) * t);
            }
        }
        buf.get(0)
    }
}

/// A small fixed buffer for the fast path (no allocation up to degree 15).
mod smallvec_like {
    use super::V2;
    use glam::DVec2;
    // The inline array is the point of the type (no heap allocation up to 16
    // points): boxing it, as clippy suggests, would defeat it.
    #[allow(clippy::large_enum_variant)]
    pub enum Buf {
        Inline([DVec2; 16], usize),
        Heap(Vec<DVec2>),
    }
    impl Buf {
        pub fn new(p: &[V2<f64>]) -> Buf {
            if p.len() <= 16 {
                let mut a = [DVec2::ZERO; 16];
                for (d, s) in a.iter_mut().zip(p) {
                    *d = s.to_dvec2();
                }
                Buf::Inline(a, p.len())
            } else {
                Buf::Heap(p.iter().map(|v| v.to_dvec2()).collect())
            }
        }
        pub fn len(&self) -> usize {
            match self {
                Buf::Inline(_, n) => *n,
                Buf::Heap(v) => v.len(),
            }
        }
        pub fn get(&self, i: usize) -> DVec2 {
            match self {
                Buf::Inline(a, _) => a[i],
                Buf::Heap(v) => v[i],
            }
        }
        pub fn set(&mut self, i: usize, x: DVec2) {
            match self {
                Buf::Inline(a, _) => a[i] = x,
                Buf::Heap(v) => v[i] = x,
            }
        }
    }
}

/// Bernstein coefficients of the product of two Bernstein polynomials of
/// degrees `m` and `n` (degree `m + n`):
/// `c_k = sum_{i+j=k} C(m,i) C(n,j) / C(m+n,k) a_i b_j`.
///
/// # Examples
/// ```
/// use lncert::curve::bernstein_product;
/// // (1 - t) * t = B^2_1 / 2
/// assert_eq!(bernstein_product(&[1.0, 0.0], &[0.0, 1.0]), vec![0.0, 0.5, 0.0]);
/// ```
// The index form mirrors the formula (i and j = k - i index a, b and the
// binomials together).
#[allow(clippy::needless_range_loop)]
pub fn bernstein_product<S: Scalar>(a: &[S], b: &[S]) -> Vec<S> {
    if a.is_empty() || b.is_empty() {
        return Vec::new();
    }
    let (m, n) = (a.len() - 1, b.len() - 1);
    (0..=m + n)
        .map(|k| {
            let mut s = S::zero();
            for i in k.saturating_sub(n)..=k.min(m) {
                let j = k - i;
                let w: S = ratio_scalar(
                    binomial_big(m, i) * binomial_big(n, j),
                    binomial_big(m + n, k),
                );
                s = s + w * a[i].clone() * b[j].clone();
            }
            s
        })
        .collect()
}

/// The Bernstein coefficients of a polynomial on `[0, 1/2]` and on `[1/2, 1]`
/// from those on `[0, 1]` (de Casteljau at `1/2`; exact for rationals,
/// outward rounded for intervals). Empty input gives two empty lists.
///
/// # Examples
/// ```
/// use lncert::curve::bernstein_halves;
/// let (l, r) = bernstein_halves(&[0.0, 1.0]); // t on [0, 1]
/// assert_eq!((l, r), (vec![0.0, 0.5], vec![0.5, 1.0]));
/// ```
pub fn bernstein_halves<S: Scalar>(g: &[S]) -> (Vec<S>, Vec<S>) {
    let n = g.len();
    if n == 0 {
        return (Vec::new(), Vec::new());
    }
    let half: S = S::from_frac(1, 2);
    let mut p = g.to_vec();
    let mut left = Vec::with_capacity(n);
    let mut right = Vec::with_capacity(n);
    left.push(p[0].clone());
    right.push(p[n - 1].clone());
    for k in 1..n {
        for i in 0..n - k {
            p[i] = (p[i].clone() + p[i + 1].clone()) * half.clone();
        }
        left.push(p[0].clone());
        right.push(p[n - 1 - k].clone());
    }
    right.reverse();
    (left, right)
}

impl Bezier<Rational> {
    /// The first nonzero difference of consecutive control points from the
    /// start (`from_end = false`, `P_{k+1} − P_k`) or from the end
    /// (`P_{k−1} − P_k`, pointing back into the curve): a positive multiple of
    /// the first nonzero hodograph control point from that end, so the
    /// direction in which the curve leaves it; `None` for a point.
    pub fn leaving_direction(&self, from_end: bool) -> Option<V2<Rational>> {
        let p = &self.pts;
        let n = p.len();
        (0..n.saturating_sub(1))
            .map(|k| {
                if from_end {
                    p[n - 2 - k].sub(&p[n - 1 - k])
                } else {
                    p[k + 1].sub(&p[k])
                }
            })
            .find(|v| !num_traits::Zero::is_zero(&v.x) || !num_traits::Zero::is_zero(&v.y))
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::test_util::q;

    fn pt(x: &str, y: &str) -> V2<Rational> {
        V2::new(q(x), q(y))
    }
    fn cubic() -> Bezier<Rational> {
        Bezier::new(vec![
            pt("-0.95", "0.7"),
            pt("-0.3", "0.5"),
            pt("0.3", "-2.5"),
            pt("0.9", "-0.2"),
        ])
    }

    #[test]
    fn split_pieces_agree_with_the_curve() {
        let c = cubic();
        let t = q("2/7");
        let (l, r) = c.split(&t);
        for s in ["0", "1/3", "1/2", "1"] {
            let s = q(s);
            assert_eq!(l.eval(&s), c.eval(&(&t * &s)));
            assert_eq!(r.eval(&s), c.eval(&(&t + (q("1") - &t) * &s)));
        }
    }

    #[test]
    fn restrict_and_elevate_are_exact() {
        let c = cubic();
        let (a, b) = (q("1/5"), q("3/4"));
        let r = c.restrict(&a, &b);
        let e = c.elevate();
        for s in ["0", "1/3", "2/3", "1"] {
            let s = q(s);
            assert_eq!(r.eval(&s), c.eval(&(&a + (&b - &a) * &s)));
            assert_eq!(e.eval(&s), c.eval(&s));
        }
    }

    /// The end derivatives are the hodograph's end points, and the leaving
    /// direction a positive multiple of its first nonzero control point from
    /// that end (negated at the end), on pieces with repeated control points.
    #[test]
    fn end_derivatives_and_leaving_directions_match_the_hodograph() {
        use num_traits::{Signed, Zero};
        let qq = |n: i64, d: i64| Rational::new(n.into(), d.into());
        let mut rng = crate::test_util::TestRng::new(0x005e_ed0f_d1ec);
        let mut checked = 0;
        for case in 0..300 {
            let deg = 1 + case % 4;
            let mut pts: Vec<V2<Rational>> = (0..=deg)
                .map(|_| V2::new(qq(rng.int(3), 2), qq(rng.int(3), 2)))
                .collect();
            if case % 3 == 0 {
                pts[1] = pts[0].clone(); // a repeated end point
            }
            let b = Bezier::new(pts);
            let h = b.hodograph();
            let hp = h.points();
            assert_eq!(
                b.end_derivatives(),
                [hp[0].clone(), hp[hp.len() - 1].clone()]
            );
            for from_end in [false, true] {
                let want = if from_end {
                    hp.iter()
                        .rev()
                        .find(|v| !v.x.is_zero() || !v.y.is_zero())
                        .map(|v| v.scale(&qq(-1, 1)))
                } else {
                    hp.iter()
                        .find(|v| !v.x.is_zero() || !v.y.is_zero())
                        .cloned()
                };
                let got = b.leaving_direction(from_end);
                match (got, want) {
                    (Some(g), Some(w)) => {
                        assert!(g.cross(&w).is_zero() && g.dot(&w).is_positive(), "{b:?}");
                        checked += 1;
                    }
                    (None, None) => {}
                    (g, w) => panic!("{b:?}: {g:?} vs {w:?}"),
                }
            }
        }
        assert!(checked > 400, "{checked}");
    }

    #[test]
    fn hodograph_matches_power_derivative() {
        let c = cubic();
        let (x, y) = c.power_coords();
        let (hx, hy) = c.hodograph().power_coords();
        assert_eq!(hx.trimmed(), x.derivative().trimmed());
        assert_eq!(hy.trimmed(), y.derivative().trimmed());
    }

    #[test]
    fn cross_hodograph_matches_power_form() {
        let c = cubic();
        let (x, y) = c.power_coords();
        let (x1, y1, x2, y2) = (
            x.derivative(),
            y.derivative(),
            x.derivative().derivative(),
            y.derivative().derivative(),
        );
        let direct = x1.mul(&y2).sub(&y1.mul(&x2));
        let bern = Poly::from_bernstein(&c.cross_hodograph());
        assert_eq!(bern.trimmed(), direct.trimmed());
    }

    #[test]
    fn fast_eval_matches_generic() {
        let c = cubic().map(|v: &Rational| v.approx());
        for i in 0..=10 {
            let t = i as f64 / 10.0;
            let g = c.eval(&t);
            let f = c.eval_fast(t);
            assert!((g.x - f.x).abs() < 1e-15 && (g.y - f.y).abs() < 1e-15);
        }
    }
}
