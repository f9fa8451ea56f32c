//! Exact B-spline curves, converted into their Bézier pieces.
//!
//! # The curve
//!
//! A B-spline of degree `p` with control points `P_0, ..., P_{n-1}` and the
//! non-decreasing knot vector `u_0 <= u_1 <= ... <= u_{n+p}` (`n + p + 1`
//! knots) is
//!
//! ```text
//! c(u) = sum_i N_{i,p}(u) P_i,        u in [u_p, u_n]   (the valid range),
//! ```
//!
//! with the B-spline basis functions `N_{i,p}` of the knot vector. On every
//! non-empty knot span `[u_i, u_{i+1}]` (`p <= i < n`, `u_i < u_{i+1}`) the
//! curve is one polynomial of degree ≤ `p`, determined by the `p + 1` control
//! points `P_{i-p}, ..., P_i` and the `2p` knots `u_{i-p+1}, ..., u_{i+p}`.
//!
//! # Bézier pieces by knot insertion
//!
//! [`BSpline::to_beziers`] writes each such polynomial as a Bézier curve of
//! degree `p` over the local parameter `t = (u - u_i) / (u_{i+1} - u_i)` in
//! `[0, 1]`. It works on the local window of `p + 1` control points and `2p`
//! knots of the span and inserts the knot `u_i` (Boehm's algorithm) until all
//! `p` knots left of the span equal `u_i`, then `u_{i+1}` until all `p` knots
//! right of it equal `u_{i+1}`. One insertion of `x in [u_i, u_{i+1}]` replaces
//! the window points by
//!
//! ```text
//! Q'_k = (1 - a_k) Q_{k-1} + a_k Q_k,   a_k = (x - t_k) / (t_{k+p} - t_k),   k = 1..p
//! ```
//!
//! (`t_1..t_{2p}` the window's knots), whose denominators are never zero since
//! `t_k <= u_i < u_{i+1} <= t_{k+p}`. With knots `u_i^p u_{i+1}^p` the window's
//! control points are the Bézier control points (in blossom terms:
//! `b_j = f(u_i^{p-j}, u_{i+1}^j)`). Every operation is a rational affine
//! combination, so the pieces are **exact**: no rounding anywhere, and the
//! result is the same polynomial as de Boor's evaluation [`BSpline::eval`],
//! which the tests check point by point. The work is at most `p(p - 1)`
//! affine combinations per span (combinations with a zero weight are
//! skipped), computed in integers: the window's knots are mapped affinely to
//! integers (which leaves the Bézier points unchanged), the points are kept as
//! `(x, y) / d`, and each is reduced to lowest terms once, at the end.
//!
//! # Knot vectors accepted
//!
//! [`BSpline::new`] accepts exactly the knot vectors for which every basis
//! function is non-zero and the valid range holds at least one span:
//!
//! * `1 <= p <= 63` (the degree limit of a Bézier segment);
//! * at least `p + 1` control points;
//! * exactly `n + p + 1` knots, non-decreasing;
//! * no knot value repeated more than `p + 1` times (a value of multiplicity
//!   `p + 2` would make a basis function identically zero); a knot of
//!   multiplicity `m <= p` inside the valid range leaves the curve (at least)
//!   `C^{p-m}` there, one of multiplicity `p + 1` may break it (the pieces on
//!   its two sides need not meet);
//! * `u_p < u_n`: the valid range is not a single point.
//!
//! Zero-length spans produce no piece.
//!
//! # Examples
//! ```
//! use lncert::curve::{BSpline, V2};
//! use lncert::scalar::Rational;
//! let p = |x: i64, y: i64| V2::new(Rational::from_integer(x.into()), Rational::from_integer(y.into()));
//! // A clamped quadratic with 4 control points: knots 0 0 0 1 2 2 2, two pieces.
//! let s = BSpline::clamped_uniform(2, vec![p(0, 0), p(2, 4), p(4, 0), p(6, 4)]).unwrap();
//! let pieces = s.to_beziers();
//! assert_eq!(pieces.len(), 2);
//! assert_eq!(pieces[0].points()[0], p(0, 0));
//! assert_eq!(pieces[0].points()[2], p(3, 2)); // the junction, midpoint of P1 P2
//! assert_eq!(pieces[1].points()[2], p(6, 4));
//! ```

use super::field_err;
use super::{Bezier, CurveParseError, V2};
use crate::scalar::{rational_to_string, Rational};
use num_bigint::BigInt;
use num_integer::Integer;
use num_traits::{One, Zero};

/// Largest degree accepted: the degree of a Bézier segment with
/// [`crate::shape::MAX_CONTROL_POINTS`] control points.
const MAX_DEGREE: usize = 63;

/// An exact planar B-spline curve: degree, knot vector and control points,
/// validated on construction (see [`BSpline::new`] for the rules).
///
/// # Examples
/// ```
/// use lncert::curve::{BSpline, V2};
/// use lncert::scalar::{parse_rational, Rational};
/// let q = |s: &str| parse_rational(s).unwrap();
/// let pts = vec![V2::new(q("0"), q("0")), V2::new(q("1"), q("1")), V2::new(q("2"), q("0"))];
/// let s = BSpline::new(1, vec![q("0"), q("0"), q("1/2"), q("1"), q("1")], pts).unwrap();
/// assert_eq!(s.degree(), 1);
/// assert_eq!(s.eval(&q("1/4")), V2::new(q("1/2"), q("1/2")));
/// assert_eq!(s.to_beziers().len(), 2);
/// ```
#[derive(Clone, Debug, PartialEq)]
pub struct BSpline {
    degree: usize,
    knots: Vec<Rational>,
    control_points: Vec<V2<Rational>>,
}

fn int(n: usize) -> Rational {
    Rational::from_integer(n.into())
}

/// Checks `1 <= degree <= 63`.
/// The degree check and `n ≥ degree + 1` control points; returns `n`.
fn check_degree_and_count(degree: usize, n: usize, what: &str) -> Result<usize, CurveParseError> {
    check_degree(degree)?;
    if n < degree + 1 {
        return Err(field_err(
            "bspline.control_points",
            format!(
                "a {what} of degree {degree} needs at least {} control points, found {n}",
                degree + 1
            ),
        ));
    }
    Ok(n)
}

fn check_degree(degree: usize) -> Result<(), CurveParseError> {
    if degree == 0 || degree > MAX_DEGREE {
        return Err(field_err(
            "bspline.degree",
            format!("the degree must be between 1 and {MAX_DEGREE}, found {degree}"),
        ));
    }
    Ok(())
}

impl BSpline {
    /// A B-spline of degree `degree` with the given knot vector and control
    /// points, validated:
    ///
    /// * `1 <= degree <= 63` (else the error names `bspline.degree`);
    /// * at least `degree + 1` control points (`bspline.control_points`);
    /// * exactly `control_points.len() + degree + 1` knots (`bspline.knots`);
    /// * knots non-decreasing (`bspline.knots[i]`, the first knot smaller than
    ///   its predecessor);
    /// * no knot value of multiplicity above `degree + 1` (`bspline.knots[i]`,
    ///   the first knot over the limit);
    /// * a valid range `[knots[degree], knots[n]]` (`n` control points) of
    ///   positive length (`bspline.knots`).
    ///
    /// The errors are [`CurveParseError::Field`].
    ///
    /// # Examples
    /// ```
    /// use lncert::curve::{BSpline, V2};
    /// use lncert::shape::CurveParseError;
    /// use lncert::scalar::Rational;
    /// let k = |v: &[i64]| v.iter().map(|&x| Rational::from_integer(x.into())).collect::<Vec<_>>();
    /// let pts = vec![V2::new(k(&[0])[0].clone(), k(&[0])[0].clone()); 4];
    /// // Degree 2, 4 control points: 7 knots.
    /// assert!(BSpline::new(2, k(&[0, 0, 0, 1, 2, 2, 2]), pts.clone()).is_ok());
    /// let err = BSpline::new(2, k(&[0, 0, 0, 2, 1, 2, 2]), pts.clone()).unwrap_err();
    /// assert!(matches!(&err, CurveParseError::Field { field, .. } if field == "bspline.knots[4]"));
    /// let err = BSpline::new(2, k(&[0, 0, 0, 1, 2, 2]), pts.clone()).unwrap_err();
    /// assert!(matches!(&err, CurveParseError::Field { field, .. } if field == "bspline.knots"));
    /// let err = BSpline::new(0, k(&[0, 0, 1, 1]), pts).unwrap_err();
    /// assert!(err.to_string().contains("bspline.degree"));
    /// ```
    pub fn new(
        degree: usize,
        knots: Vec<Rational>,
        control_points: Vec<V2<Rational>>,
    ) -> Result<Self, CurveParseError> {
        let n = check_degree_and_count(degree, control_points.len(), "B-spline")?;
        let expected = n + degree + 1;
        if knots.len() != expected {
            return Err(field_err(
                "bspline.knots",
                format!(
                    "expected {expected} knots (control points + degree + 1 = {n} + {degree} + 1), found {}",
                    knots.len()
                ),
            ));
        }
        let mut run = 1;
        for i in 1..knots.len() {
            if knots[i] < knots[i - 1] {
                return Err(field_err(
                    &format!("bspline.knots[{i}]"),
                    format!(
                        "knots must be non-decreasing, but {} is smaller than the previous knot {}",
                        rational_to_string(&knots[i]),
                        rational_to_string(&knots[i - 1])
                    ),
                ));
            }
            run = if knots[i] == knots[i - 1] { run + 1 } else { 1 };
            if run > degree + 1 {
                return Err(field_err(
                    &format!("bspline.knots[{i}]"),
                    format!(
                        "the knot {} is repeated {run} times, more than degree + 1 = {}",
                        rational_to_string(&knots[i]),
                        degree + 1
                    ),
                ));
            }
        }
        if knots[degree] >= knots[n] {
            return Err(field_err(
                "bspline.knots",
                format!(
                    "the valid range [knots[{degree}], knots[{n}]] = [{}, {}] is empty",
                    rational_to_string(&knots[degree]),
                    rational_to_string(&knots[n])
                ),
            ));
        }
        Ok(BSpline {
            degree,
            knots,
            control_points,
        })
    }

    /// The open (clamped) uniform B-spline: knots `0` repeated `degree + 1`
    /// times, then `1, 2, ..., n - degree - 1`, then `n - degree` repeated
    /// `degree + 1` times (`n` control points). The curve starts at the first
    /// control point and ends at the last, and has `n - degree` pieces.
    ///
    /// # Examples
    /// ```
    /// use lncert::curve::{BSpline, V2};
    /// use lncert::scalar::Rational;
    /// let p = |x: i64, y: i64| V2::new(Rational::from_integer(x.into()), Rational::from_integer(y.into()));
    /// let s = BSpline::clamped_uniform(3, vec![p(0, 0), p(1, 2), p(3, 2), p(4, 0), p(6, 1)]).unwrap();
    /// let knots: Vec<i64> = s.knots().iter().map(|k| k.to_integer().try_into().unwrap()).collect();
    /// assert_eq!(knots, [0, 0, 0, 0, 1, 2, 2, 2, 2]);
    /// let pieces = s.to_beziers();
    /// assert_eq!(pieces.len(), 2);
    /// assert_eq!(pieces[0].points()[0], p(0, 0));
    /// assert_eq!(pieces[1].points()[3], p(6, 1));
    /// assert!(BSpline::clamped_uniform(3, vec![p(0, 0); 3]).is_err()); // too few points
    /// ```
    pub fn clamped_uniform(
        degree: usize,
        control_points: Vec<V2<Rational>>,
    ) -> Result<Self, CurveParseError> {
        let n = check_degree_and_count(degree, control_points.len(), "clamped B-spline")?;
        let last = n - degree;
        let knots = std::iter::repeat_n(0, degree)
            .chain(0..=last)
            .chain(std::iter::repeat_n(last, degree))
            .map(int)
            .collect();
        BSpline::new(degree, knots, control_points)
    }

    /// The closed (periodic) uniform B-spline of the control polygon
    /// `P_0, ..., P_{m-1}`: the control points `P_0, ..., P_{m-1}, P_0, ...,
    /// P_{degree-1}` (the first `degree` wrapped around, indices taken modulo
    /// `m` when `m < degree`) with the uniform knots `0, 1, ..., m + 2 degree`.
    /// The valid range is `[degree, degree + m]`, one piece per original
    /// control point, and the curve is closed and `C^{degree-1}` everywhere,
    /// including where it closes. Needs at least 2 control points.
    ///
    /// # Examples
    /// ```
    /// use lncert::curve::{BSpline, V2};
    /// use lncert::scalar::Rational;
    /// let p = |x: i64, y: i64| V2::new(Rational::from_integer(x.into()), Rational::from_integer(y.into()));
    /// let square = vec![p(1, 1), p(1, -1), p(-1, -1), p(-1, 1)];
    /// let s = BSpline::periodic_uniform(3, square).unwrap();
    /// assert_eq!(s.control_points().len(), 7);
    /// let pieces = s.to_beziers();
    /// assert_eq!(pieces.len(), 4);
    /// assert_eq!(pieces[3].points()[3], pieces[0].points()[0]); // closed
    /// ```
    pub fn periodic_uniform(
        degree: usize,
        control_points: Vec<V2<Rational>>,
    ) -> Result<Self, CurveParseError> {
        check_degree(degree)?;
        let m = control_points.len();
        if m < 2 {
            return Err(field_err(
                "bspline.control_points",
                format!("a periodic B-spline needs at least 2 control points, found {m}"),
            ));
        }
        let mut pts = control_points;
        pts.reserve(degree);
        for i in 0..degree {
            pts.push(pts[i % m].clone());
        }
        let knots = (0..=m + 2 * degree).map(int).collect();
        BSpline::new(degree, knots, pts)
    }

    /// The degree `p`.
    ///
    /// # Examples
    /// ```
    /// use lncert::curve::{BSpline, V2};
    /// use lncert::scalar::Rational;
    /// let s = BSpline::clamped_uniform(2, vec![V2::<Rational>::zero(); 3]).unwrap();
    /// assert_eq!(s.degree(), 2);
    /// ```
    pub fn degree(&self) -> usize {
        self.degree
    }

    /// The knot vector (`control_points().len() + degree() + 1` knots).
    ///
    /// # Examples
    /// ```
    /// use lncert::curve::{BSpline, V2};
    /// use lncert::scalar::Rational;
    /// let s = BSpline::clamped_uniform(1, vec![V2::<Rational>::zero(); 3]).unwrap();
    /// assert_eq!(s.knots().len(), 5);
    /// ```
    pub fn knots(&self) -> &[Rational] {
        &self.knots
    }

    /// The control points (for a periodic spline, including the wrapped ones).
    ///
    /// # Examples
    /// ```
    /// use lncert::curve::{BSpline, V2};
    /// use lncert::scalar::Rational;
    /// let s = BSpline::periodic_uniform(2, vec![V2::<Rational>::zero(); 3]).unwrap();
    /// assert_eq!(s.control_points().len(), 5);
    /// ```
    pub fn control_points(&self) -> &[V2<Rational>] {
        &self.control_points
    }

    /// The valid parameter range `(knots[degree], knots[n])`.
    ///
    /// # Examples
    /// ```
    /// use lncert::curve::{BSpline, V2};
    /// use lncert::scalar::Rational;
    /// let s = BSpline::periodic_uniform(3, vec![V2::<Rational>::zero(); 4]).unwrap();
    /// let (a, b) = s.domain();
    /// assert_eq!((a.to_integer(), b.to_integer()), (3.into(), 7.into()));
    /// ```
    pub fn domain(&self) -> (Rational, Rational) {
        (
            self.knots[self.degree].clone(),
            self.knots[self.control_points.len()].clone(),
        )
    }

    /// Indices `i` (`degree <= i < n`) of the non-empty knot spans
    /// `[knots[i], knots[i+1]]` of the valid range, in order.
    fn span_indices(&self) -> impl Iterator<Item = usize> + '_ {
        (self.degree..self.control_points.len()).filter(|&i| self.knots[i] < self.knots[i + 1])
    }

    /// The non-empty knot spans `(knots[i], knots[i+1])` of the valid range,
    /// in order: the parameter interval of each piece of
    /// [`BSpline::to_beziers`], which maps it onto `[0, 1]`.
    ///
    /// # Examples
    /// ```
    /// use lncert::curve::{BSpline, V2};
    /// use lncert::scalar::Rational;
    /// let k = |v: &[i64]| v.iter().map(|&x| Rational::from_integer(x.into())).collect::<Vec<_>>();
    /// // Degree 1, 4 points, a double interior knot: the span [1, 1] is empty.
    /// let s = BSpline::new(1, k(&[0, 0, 1, 1, 3, 3]), vec![V2::zero(); 4]).unwrap();
    /// assert_eq!(s.spans(), vec![(k(&[0])[0].clone(), k(&[1])[0].clone()), (k(&[1])[0].clone(), k(&[3])[0].clone())]);
    /// assert_eq!(s.to_beziers().len(), 2);
    /// ```
    pub fn spans(&self) -> Vec<(Rational, Rational)> {
        self.span_indices()
            .map(|i| (self.knots[i].clone(), self.knots[i + 1].clone()))
            .collect()
    }

    /// The polynomial pieces, one Bézier curve of degree `degree()` per
    /// non-empty knot span of the valid range (see [`BSpline::spans`]), each
    /// over the local parameter `t = (u - knots[i]) / (knots[i+1] - knots[i])`
    /// in `[0, 1]`; computed exactly by knot insertion (see the module docs).
    ///
    /// # Examples
    /// ```
    /// use lncert::curve::{BSpline, V2};
    /// use lncert::scalar::{parse_rational, Rational};
    /// let q = |s: &str| parse_rational(s).unwrap();
    /// let p = |x: &str, y: &str| V2::new(q(x), q(y));
    /// let s = BSpline::clamped_uniform(3, vec![p("0", "0"), p("1", "3"), p("2", "0"), p("3", "3"), p("4", "0")]).unwrap();
    /// let pieces = s.to_beziers();
    /// assert_eq!(pieces.len(), 2);
    /// // The first piece is exact: knots 0 0 0 0 1 2 2 2 2.
    /// assert_eq!(pieces[0].points(), [p("0", "0"), p("1", "3"), p("3/2", "3/2"), p("2", "3/2")]);
    /// // Same polynomial as de Boor's evaluation.
    /// assert_eq!(pieces[1].eval(&q("1/3")), s.eval(&q("4/3")));
    /// ```
    pub fn to_beziers(&self) -> Vec<Bezier<Rational>> {
        self.span_indices().map(|i| self.piece(i)).collect()
    }

    /// The Bézier piece over the non-empty span `[knots[i], knots[i+1]]`, by
    /// Boehm insertion in the local window of the span.
    ///
    /// The arithmetic is integral: the window's knots are mapped affinely to
    /// integers (the control points of a piece do not depend on an affine
    /// change of parameter), each point is kept as `(x, y) / d` with integers,
    /// combinations with a zero weight are skipped, and the fractions are
    /// reduced once, at the end. The result is exactly the rational one.
    fn piece(&self, i: usize) -> Bezier<Rational> {
        let p = self.degree;
        let a = &self.knots[i];
        // Window: Q_k = P_{i-p+k} (k = 0..=p), knots u_{i-p+1..=i+p} as the
        // integers t[0..2p] = (u - a) * L, with t[p-1] = 0 < t[p] = B
        // throughout.
        let local = &self.knots[i - p + 1..=i + p];
        let scale = local
            .iter()
            .fold(BigInt::one(), |l, u| l.lcm((u - a).denom()));
        let mut t: Vec<BigInt> = local
            .iter()
            .map(|u| ((u - a) * &scale).to_integer())
            .collect();
        let zero = BigInt::zero();
        let end = t[p].clone();
        let mut q: Vec<Homogeneous> = self.control_points[i - p..=i]
            .iter()
            .map(Homogeneous::from_point)
            .collect();
        // Insert 0 until the p knots left of the span are 0: the new points
        // Q'_k = ((t[k+p-1] - 0) Q_{k-1} + (0 - t[k-1]) Q_k) / (t[k+p-1] - t[k-1])
        // replace Q_{k-1} (the window keeps Q'_1..Q'_p, Q_p), in place in
        // increasing k.
        while t[0] != zero {
            for k in 1..=p {
                let w2 = -&t[k - 1];
                if !w2.is_zero() {
                    q[k - 1] = q[k - 1].combine(&q[k], &t[k + p - 1], &w2);
                }
            }
            t.remove(0);
            t.insert(p - 1, zero.clone());
        }
        // Insert B until the p knots right of the span are B: the window keeps
        // Q_0, Q'_1..Q'_p, in place in decreasing k.
        while t[2 * p - 1] != end {
            for k in (1..=p).rev() {
                let w1 = &t[k + p - 1] - &end;
                if !w1.is_zero() {
                    q[k] = q[k - 1].combine(&q[k], &w1, &(&end - &t[k - 1]));
                }
            }
            t.pop();
            t.insert(p, end.clone());
        }
        Bezier::new(q.iter().map(Homogeneous::to_point).collect())
    }

    /// The point at parameter `u`, by de Boor's algorithm (independent of
    /// [`BSpline::to_beziers`]). Inside the valid range the spans are
    /// half-open `[knots[i], knots[i+1])` (the right-continuous convention,
    /// which matters only at a knot of multiplicity `degree + 1`), except
    /// that the end of the range belongs to the last span. Outside the valid
    /// range the first or last span's polynomial is extended.
    ///
    /// # Examples
    /// ```
    /// use lncert::curve::{BSpline, V2};
    /// use lncert::scalar::{parse_rational, Rational};
    /// let q = |s: &str| parse_rational(s).unwrap();
    /// let p = |x: &str, y: &str| V2::new(q(x), q(y));
    /// let s = BSpline::clamped_uniform(2, vec![p("0", "0"), p("1", "2"), p("2", "0")]).unwrap();
    /// // A single quadratic Bézier piece on [0, 1].
    /// assert_eq!(s.eval(&q("1/2")), p("1", "1"));
    /// assert_eq!(s.eval(&q("1")), p("2", "0"));
    /// ```
    pub fn eval(&self, u: &Rational) -> V2<Rational> {
        let p = self.degree;
        let n = self.control_points.len();
        let k = &self.knots;
        let i = if *u < k[p] {
            self.span_indices().next()
        } else if *u >= k[n] {
            self.span_indices().last()
        } else {
            // The largest i in [p, n-1] with k[i] <= u; then u < k[i+1].
            Some(p + k[p..n].partition_point(|x| x <= u) - 1)
        }
        .expect("a validated B-spline has a non-empty span");
        let mut d: Vec<V2<Rational>> = self.control_points[i - p..=i].to_vec();
        for r in 1..=p {
            for j in (r..=p).rev() {
                let lo = &k[j + i - p];
                let hi = &k[j + 1 + i - r];
                let alpha = (u - lo) / (hi - lo);
                d[j] = d[j - 1].lerp(&d[j], &alpha);
            }
        }
        d.swap_remove(p)
    }
}

/// A point `(x / d, y / d)` with integers `x, y, d` and `d > 0`, not
/// necessarily in lowest terms: a shared denominator and no gcd but one per
/// combination, about ten times faster than `Rational` coordinates at high
/// degree. Denominators cannot grow out of hand: after `s` insertions every
/// `d` divides the lcm of the window's initial denominators times, for each
/// insertion, the lcm of its weight sums `w1 + w2` (knot differences), so
/// their sizes add up, never multiply.
struct Homogeneous {
    x: BigInt,
    y: BigInt,
    d: BigInt,
}

impl Homogeneous {
    fn from_point(p: &V2<Rational>) -> Self {
        let d = p.x.denom().lcm(p.y.denom());
        Homogeneous {
            x: p.x.numer() * (&d / p.x.denom()),
            y: p.y.numer() * (&d / p.y.denom()),
            d,
        }
    }

    /// The exact point, in lowest terms.
    fn to_point(&self) -> V2<Rational> {
        V2::new(
            Rational::new(self.x.clone(), self.d.clone()),
            Rational::new(self.y.clone(), self.d.clone()),
        )
    }

    /// `(w1 self + w2 other) / (w1 + w2)` for integers `w1, w2 > 0`, over the
    /// denominator `(w1 + w2) lcm(d_self, d_other)`.
    fn combine(&self, other: &Self, w1: &BigInt, w2: &BigInt) -> Self {
        let g = self.d.gcd(&other.d);
        let c1 = w1 * (&other.d / &g);
        let c2 = w2 * (&self.d / &g);
        Homogeneous {
            x: &c1 * &self.x + &c2 * &other.x,
            y: &c1 * &self.y + &c2 * &other.y,
            d: (w1 + w2) * (&self.d / &g) * &other.d,
        }
    }
}
