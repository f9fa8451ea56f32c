//! Seed 003 §4.1: the circle-tangency system in the unknowns `(m, a2)`.
//!
//! Normal form (seed 003 §2–3): the quartic LN curve with Hermite data
//! `[0,0]`, normal `(0,1)` and `[x1,y1]`, normal `(u,1)` is
//! `f(t) = a2 t² + a3 t³ + a4 t⁴` with `a3, a4` linear in `a2` (eq. (3)), and
//! `K(t) = (x(t), y(t)) = (-f'(t), t f'(t) - f(t))` has the normal `(t, 1)`.
//! For a circle with centre `O = (Ox, Oy)` and signed radius `r` the tangency
//! point `K(m)` satisfies
//!
//! * eq. (6): `(x(m) - Ox)² + (y(m) - Oy)² - r² = 0` (total degree 10 in `(m, a2)`),
//! * eq. (7): `x(m) - Ox - m (y(m) - Oy) = 0` (total degree 6).
//!
//! Both are built exactly over Q as [`Poly2`] in `x = m`, `y = a2`.
//!
//! The `a2`-part of `f` is `g(t) = t²(u - t)²/u²` (eq. (3) with `x1 = y1 = 0`),
//! so `K(0) = (0, 0)` and `K(u) = (x1, y1)` for every `a2`: on the lines
//! `m = 0` and `m = u` the system does not depend on `a2`, and either has no
//! solution there or a whole line of solutions ([`TangencySystem::solution_lines`]).

use super::poly2::Poly2;
use crate::ln::hermite::HermiteData;
use crate::poly::Poly;
use crate::scalar::{Rational, Scalar};
use num_traits::Zero;

/// Why a tangency problem was rejected: the parameter out of the domain
/// (`r`, `u`, `x1`, `y1`, `a2_range`, …) and why — lncert's one input error,
/// [`crate::Error`].
pub type TangencyError = crate::Error;

/// A line of solutions `m = m0`, every `a2` (the circle touches the end point
/// `K(0)` or `K(u)`, shared by every quartic of the family).
#[derive(Clone, Debug, PartialEq)]
pub struct SolutionLine {
    /// The parameter `m0` (`0` or `u`).
    pub m: Rational,
}

/// The circle-tangency system of seed 003 §4 for exact data.
///
/// # Examples
/// ```
/// use lncert::tangency::TangencySystem;
/// use lncert::scalar::frac;
/// let s = TangencySystem::new(frac(3, 1), frac(-1, 1), frac(1, 1), frac(1, 1), frac(1, 1), frac(1, 2)).unwrap();
/// assert_eq!(s.eq6.total_degree(), Some(10));
/// assert_eq!(s.eq7.total_degree(), Some(6));
/// assert_eq!(s.bezout_bound(), Some(60));
/// ```
#[derive(Clone, Debug)]
pub struct TangencySystem {
    /// The Hermite data `[x1, y1]`, `(u, 1)`.
    pub hermite: HermiteData<Rational>,
    /// Circle centre `Ox`.
    pub ox: Rational,
    /// Circle centre `Oy`.
    pub oy: Rational,
    /// Signed radius: `r > 0` asks for the centre on the side of the normal
    /// `(m, 1)`, i.e. `(O - K(m))·(m, 1) > 0`; `r < 0` the opposite side.
    pub r: Rational,
    /// `x(m, a2)` of the normal form.
    pub x: Poly2<Rational>,
    /// `y(m, a2)` of the normal form.
    pub y: Poly2<Rational>,
    /// Eq. (6) in `(m, a2)`.
    pub eq6: Poly2<Rational>,
    /// Eq. (7) in `(m, a2)`.
    pub eq7: Poly2<Rational>,
}

impl TangencySystem {
    /// Builds eq. (6) and (7). Rejects (naming the field) `x1 = 0`, `u <= 0`
    /// (via [`HermiteData::new`]) and `r = 0` (a point, not a circle).
    pub fn new(
        x1: Rational,
        y1: Rational,
        u: Rational,
        ox: Rational,
        oy: Rational,
        r: Rational,
    ) -> Result<Self, TangencyError> {
        let hermite = HermiteData::new(x1, y1, u)?;
        if r.is_zero() {
            return Err(TangencyError::new(
                "r",
                "radius 0: a point, not a circle (the sign of r selects the side)",
            ));
        }
        let (x, y) = curve_polys(&hermite);
        let dx = x.sub(&Poly2::constant(ox.clone()));
        let dy = y.sub(&Poly2::constant(oy.clone()));
        let eq6 = dx
            .mul(&dx)
            .add(&dy.mul(&dy))
            .sub(&Poly2::constant(r.clone() * r.clone()))
            .trimmed();
        let eq7 = dx.sub(&Poly2::x().mul(&dy)).trimmed();
        Ok(TangencySystem {
            hermite,
            ox,
            oy,
            r,
            x,
            y,
            eq6,
            eq7,
        })
    }
    /// `u`.
    pub fn u(&self) -> &Rational {
        &self.hermite.u
    }
    /// Bézout's bound `deg(6) · deg(7)` on the number of isolated complex
    /// solutions (`None` if an equation is identically zero).
    pub fn bezout_bound(&self) -> Option<usize> {
        Some(self.eq6.total_degree()? * self.eq7.total_degree()?)
    }
    /// Eq. (7) as `A(m) a2 + B(m)` (it is linear in `a2`): `(A, B)`.
    pub fn eq7_linear(&self) -> (Poly<Rational>, Poly<Rational>) {
        (
            self.eq7.y_coefficient(1).trimmed(),
            self.eq7.y_coefficient(0).trimmed(),
        )
    }
    /// Eq. (6) as `C2(m) a2² + C1(m) a2 + C0(m)`: `(C2, C1, C0)`.
    pub fn eq6_quadratic(&self) -> (Poly<Rational>, Poly<Rational>, Poly<Rational>) {
        (
            self.eq6.y_coefficient(2).trimmed(),
            self.eq6.y_coefficient(1).trimmed(),
            self.eq6.y_coefficient(0).trimmed(),
        )
    }
    /// The point `K(m)` of the quartic with coefficient `a2`.
    pub fn point<S: Scalar>(&self, m: &S, a2: &S) -> (S, S) {
        let x = self.x.map(S::from_rational).eval(m, a2);
        let y = self.y.map(S::from_rational).eval(m, a2);
        (x, y)
    }
    /// `(O - K(m))·(m, 1)`: positive when the centre lies on the side of the
    /// normal `(m, 1)` (the side a positive radius asks for).
    pub fn side_value<S: Scalar>(&self, m: &S, a2: &S) -> S {
        let (x, y) = self.point(m, a2);
        (S::from_rational(&self.ox) - x) * m.clone() + (S::from_rational(&self.oy) - y)
    }
    /// Lines of solutions `m = 0` or `m = u` (all `a2`), decided exactly: the
    /// circle touches `K(0) = (0,0)` with normal `(0,1)`, or `K(u) = (x1,y1)` with
    /// normal `(u,1)`. Such solutions are not isolated; the complete solver
    /// cannot certify them and the CLI reports them separately.
    pub fn solution_lines(&self) -> Vec<SolutionLine> {
        let zero = <Rational as Zero>::zero();
        [zero.clone(), self.u().clone()]
            .into_iter()
            .filter(|m| {
                let e6 = self.eq6.at_x(m).trimmed();
                let e7 = self.eq7.at_x(m).trimmed();
                e6.coeffs().is_empty() && e7.coeffs().is_empty()
            })
            .map(|m| SolutionLine { m })
            .collect()
    }
}

/// `x(m, a2) = -f'(m)` and `y(m, a2) = m f'(m) - f(m)` for the quartic family
/// of eq. (3), as exact polynomials in `(m, a2)`.
pub fn curve_polys(h: &HermiteData<Rational>) -> (Poly2<Rational>, Poly2<Rational>) {
    let zero = <Rational as Zero>::zero();
    let one = Rational::from_integer(1.into());
    let (p3, p4) = h.quartic_coefficients(&zero);
    let (s3, s4) = h.quartic_coefficients(&one);
    let (q3, q4) = (&s3 - &p3, &s4 - &p4);
    // f(t, a2): coefficient of t^i a2^j at index i*2 + j.
    let mut c = vec![zero; 10];
    c[2 * 2 + 1] = one;
    c[3 * 2] = p3;
    c[3 * 2 + 1] = q3;
    c[4 * 2] = p4;
    c[4 * 2 + 1] = q4;
    let f = Poly2::from_coeffs(4, 1, c).expect("5 x 2 coefficients");
    let fp = f.dx();
    let x = fp.neg();
    let y = Poly2::x().mul(&fp).sub(&f);
    (x.trimmed(), y.trimmed())
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::test_util::qi as q;

    #[test]
    fn curve_interpolates_the_hermite_data_for_every_a2() {
        let h = HermiteData::new(q(3, 1), q(-1, 1), q(1, 2)).unwrap();
        let (x, y) = curve_polys(&h);
        for a2 in [q(0, 1), q(7, 3), q(-5, 2)] {
            assert_eq!(x.eval(&q(0, 1), &a2), q(0, 1));
            assert_eq!(y.eval(&q(0, 1), &a2), q(0, 1));
            assert_eq!(x.eval(&q(1, 2), &a2), q(3, 1));
            assert_eq!(y.eval(&q(1, 2), &a2), q(-1, 1));
            // Against the normal form of the univariate quartic.
            let f = h.quartic_f(&a2);
            let (xu, yu) = crate::ln::hermite::normal_form(&f);
            let t = q(1, 7);
            assert_eq!(x.eval(&t, &a2), xu.eval(&t));
            assert_eq!(y.eval(&t, &a2), yu.eval(&t));
        }
    }
}
