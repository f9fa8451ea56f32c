//! Seed 003: LN curves in normal form `K(t) = [-f'(t), -f(t) + t f'(t)]` with
//! polynomial `f`; the normal at `K(t)` is `(t, 1)` and `K'(t) = f''(t) [-1, t]`,
//! so `K` is singular exactly where `f'' = 0`.
//!
//! Hermite data: start `[0, 0]` with normal `(0, 1)`, end `[x1, y1]` with normal
//! `(u, 1)`, parameter interval `[0, u]`; `s = -y1/x1`.
//!
//! * Prop 2.1: the cubic interpolant is nonsingular on `[0,u]` iff `3s/2 < u < 3s`.
//! * eq. (3), (4): the quartic interpolants, a one-parameter family in `a2`, and
//!   `g4 = u⁴ f''/2`.
//! * Props 3.1/3.2: a nonsingular quartic exists iff `(3-√3)s < u < (3+√3)s`, with
//!   the `a2` intervals of Prop 3.2.
//! * Prop 3.3: valid intercepts `b` of a tangent line `m x + y + b = 0`.
//! * Prop 6.1: `K_f + K_F = K_{f+F}` (common Gauss map ⇒ polynomial convolution).
//! * Prop 7.1: the general-interval cubic (same construction as seed 000 eq. (1)).
//!
//! Irrational bounds (`√3`, `√D1`) are decided exactly with
//! [`sign_a_plus_b_sqrt_c`] (squares and signs only) and enclosed with intervals
//! for display ([`HermiteData::alphas`]).

use super::{checked_div, finite, nonzero, LnError, OpenRange};
use crate::poly::Poly;
use crate::scalar::{frac, sign_a_plus_b_sqrt_c, Scalar, ScalarSqrt, Sign};

/// The normal-form curve `K(t) = [-f', -f + t f']` as coordinate polynomials.
///
/// # Examples
/// ```
/// use lncert::ln::hermite::normal_form;
/// use lncert::poly::Poly;
/// let f = Poly::new(vec![0.0, 0.0, -1.0, 1.0]); // -t² + t³
/// let (x, y) = normal_form(&f);
/// assert_eq!(x.eval(&1.0), -1.0); // -f'(1) = -(-2 + 3)
/// assert_eq!(y.eval(&1.0), 1.0);  // -f(1) + f'(1) = 0 + 1
/// ```
pub fn normal_form<S: Scalar>(f: &Poly<S>) -> (Poly<S>, Poly<S>) {
    let fp = f.derivative();
    (fp.neg(), f.neg().add(&Poly::t().mul(&fp)))
}

/// Hermite data `[x1, y1]`, end normal `(u, 1)`; `x1 ≠ 0`, `u > 0`.
#[derive(Clone, Debug, PartialEq)]
pub struct HermiteData<S> {
    /// First coordinate of the end point `[x1, y1]` (`≠ 0`).
    pub x1: S,
    /// Second coordinate of the end point `[x1, y1]`.
    pub y1: S,
    /// End of the parameter interval `[0, u]`, where the normal is `(u, 1)` (`> 0`).
    pub u: S,
}

/// Which `a2` interval of Prop 3.2 applies.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum A2Case {
    /// `(3-√3)s < u < 4s/3` or `4s < u < (3+√3)s`: `a2 ∈ (α0, α1)`.
    Alpha0Alpha1,
    /// `4s/3 <= u <= 2s`: `a2 ∈ (α0, 0)`.
    Alpha0Zero,
    /// `2s < u <= 4s`: `a2 ∈ (α0, α2)`.
    Alpha0Alpha2,
    /// `u` outside `((3-√3)s, (3+√3)s)`: no nonsingular quartic.
    Empty,
}

/// Prop 2.1: the open `u`-range `(3s/2, 3s)` (`s = -y1/x1`) on which the cubic
/// Hermite interpolant is nonsingular; empty when `s <= 0`.
///
/// # Examples
/// ```
/// use lncert::ln::hermite::cubic_nonsingular_u_range;
/// use lncert::scalar::{frac, Rational};
/// let r = cubic_nonsingular_u_range::<Rational>(&frac(3, 1), &frac(-1, 1)).unwrap();
/// assert_eq!((r.lo, r.hi), (frac(1, 2), frac(1, 1)));
/// ```
pub fn cubic_nonsingular_u_range<S: Scalar>(x1: &S, y1: &S) -> Result<OpenRange<S>, LnError> {
    finite(&[x1], "x1")?;
    finite(&[y1], "y1")?;
    nonzero(
        x1.sign(),
        "x1",
        "x1 = 0: the end point lies on the start normal, s = -y1/x1 undefined",
    )?;
    let s = (-y1.clone()).div(x1).expect("checked");
    Ok(OpenRange {
        lo: s.clone() * frac(3, 2),
        hi: s.scale(3),
    })
}

impl<S: Scalar> HermiteData<S> {
    /// Validates `x1 ≠ 0` and `u > 0`.
    pub fn new(x1: S, y1: S, u: S) -> Result<Self, LnError> {
        finite(&[&x1], "x1")?;
        finite(&[&y1], "y1")?;
        finite(&[&u], "u")?;
        nonzero(x1.sign(), "x1", "x1 = 0: s = -y1/x1 undefined")?;
        match u.sign() {
            Sign::Positive => {
                let h = HermiteData { x1, y1, u };
                // Every formula divides by u, ..., u⁴ and by x1: they must be
                // representable as nonzero (f64 underflow, e.g. u = 1e-100).
                checked_div(
                    S::one(),
                    &h.upow(4),
                    "u",
                    "u⁴ underflows to 0 (u too small for this arithmetic)",
                )?;
                checked_div(S::one(), &h.x1, "x1", "x1 is too small for this arithmetic")?;
                Ok(h)
            }
            Sign::Unknown => Err(LnError::Undecided { field: "u" }),
            _ => Err(LnError::InvalidParameter {
                field: "u",
                reason: "u must be > 0 (parameter interval [0, u])",
            }),
        }
    }
    /// `s = -y1/x1`.
    pub fn s(&self) -> S {
        (-self.y1.clone()).div(&self.x1).expect("x1 ≠ 0")
    }
    fn upow(&self, k: u32) -> S {
        (0..k).fold(S::one(), |a, _| a * self.u.clone())
    }

    // ---- cubic (Prop 2.1) ----

    /// System (1): `a2 = (-2u x1 - 3y1)/u²`, `a3 = (u x1 + 2y1)/u³`.
    pub fn cubic_coefficients(&self) -> (S, S) {
        let (x1, y1, u) = (&self.x1, &self.y1, &self.u);
        let a2 = (-(u.clone() * x1.clone()).scale(2) - y1.scale(3))
            .div(&self.upow(2))
            .expect("u > 0");
        let a3 = (u.clone() * x1.clone() + y1.scale(2))
            .div(&self.upow(3))
            .expect("u > 0");
        (a2, a3)
    }
    /// `f(t) = a2 t² + a3 t³` of the cubic interpolant.
    pub fn cubic_f(&self) -> Poly<S> {
        let (a2, a3) = self.cubic_coefficients();
        Poly::new(vec![S::zero(), S::zero(), a2, a3])
    }
    /// `t* = -a2/(3a3)` where `f'' = 0` (`None` for the quadratic case `a3 = 0`).
    pub fn cubic_singular_parameter(&self) -> Option<S> {
        let (a2, a3) = self.cubic_coefficients();
        (-a2).div(&a3.scale(3))
    }
    /// Prop 2.1's verdict for this `u`: nonsingular on `[0, u]` iff `3s/2 < u < 3s`.
    pub fn prop_2_1(&self) -> Option<bool> {
        cubic_nonsingular_u_range(&self.x1, &self.y1)
            .ok()?
            .contains(&self.u)
    }

    // ---- quartic (Props 3.1–3.3) ----

    /// Eq. (3): `a3 = -(2a2u² + 3ux1 + 4y1)/u³`, `a4 = (a2u² + 2ux1 + 3y1)/u⁴`.
    pub fn quartic_coefficients(&self, a2: &S) -> (S, S) {
        let (x1, y1, u) = (&self.x1, &self.y1, &self.u);
        let ux = u.clone() * x1.clone();
        let a3 = (-(a2.clone() * self.upow(2)).scale(2) - ux.scale(3) - y1.scale(4))
            .div(&self.upow(3))
            .expect("u > 0");
        let a4 = (a2.clone() * self.upow(2) + ux.scale(2) + y1.scale(3))
            .div(&self.upow(4))
            .expect("u > 0");
        (a3, a4)
    }
    /// `f(t) = a2 t² + a3 t³ + a4 t⁴` of the quartic interpolant.
    pub fn quartic_f(&self, a2: &S) -> Poly<S> {
        let (a3, a4) = self.quartic_coefficients(a2);
        Poly::new(vec![S::zero(), S::zero(), a2.clone(), a3, a4])
    }
    /// Eq. (4): `g4(t) = 6t²(a2u² + 2ux1 + 3y1) - 3t(2u³a2 + 3u²x1 + 4uy1) + a2u⁴`.
    pub fn g4(&self, a2: &S) -> Poly<S> {
        let (x1, y1, u) = (&self.x1, &self.y1, &self.u);
        let c2 =
            (a2.clone() * self.upow(2) + (u.clone() * x1.clone()).scale(2) + y1.scale(3)).scale(6);
        let c1 = -(a2.clone() * self.upow(3)).scale(2)
            - (self.upow(2) * x1.clone()).scale(3)
            - (u.clone() * y1.clone()).scale(4);
        Poly::new(vec![a2.clone() * self.upow(4), c1.scale(3), c2])
    }
    /// The printed `D` (the discriminant of `g4` divided by `3u² > 0`), a quadratic in `a2`:
    /// `4u⁴a2² + (20u³x1 + 24u²y1)a2 + (27u²x1² + 72ux1y1 + 48y1²)`.
    pub fn discriminant_d(&self, a2: &S) -> S {
        let (a, b, c) = self.d_coefficients();
        a * a2.sqr() + b * a2.clone() + c
    }
    /// Coefficients `(A, B, C)` of `D = A a2² + B a2 + C`.
    pub fn d_coefficients(&self) -> (S, S, S) {
        let (x1, y1, u) = (&self.x1, &self.y1, &self.u);
        let a = self.upow(4).scale(4);
        let b = (self.upow(3) * x1.clone()).scale(20) + (self.upow(2) * y1.clone()).scale(24);
        let c = (self.upow(2) * x1.sqr()).scale(27)
            + (u.clone() * x1.clone() * y1.clone()).scale(72)
            + y1.sqr().scale(48);
        (a, b, c)
    }
    /// The printed `D1 = -2(u - (3-√3)s)(u - (3+√3)s) = -2(u² - 6us + 6s²)`.
    pub fn d1(&self) -> S {
        let (u, s) = (&self.u, self.s());
        -(u.sqr() - (u.clone() * s.clone()).scale(6) + s.sqr().scale(6)).scale(2)
    }
    /// `α2 = (6s - 3u)/(u²/x1)`, where `g4(u) = 0`.
    pub fn alpha2(&self) -> S {
        ((self.s().scale(6) - self.u.scale(3)) * self.x1.clone())
            .div(&self.upow(2))
            .expect("u > 0")
    }
    /// The printed `α0, α1 = (6s - 5u ∓ √D1)/(2u²/x1)` (needs square roots;
    /// `None` when `D1 < 0`). Note: for `x1 < 0`, `α0 > α1`.
    pub fn alphas(&self) -> Option<(S, S)>
    where
        S: ScalarSqrt,
    {
        let r = self.d1().sqrt()?;
        let k = self.x1.clone().div(&self.upow(2).scale(2))?;
        let v = self.s().scale(6) - self.u.scale(5);
        Some(((v.clone() - r.clone()) * k.clone(), (v + r) * k))
    }
    /// Sign of `a2 - α_i` (printed `α0` for `i = 0`, `α1` for `i = 1`), exact.
    fn cmp_alpha(&self, a2: &S, i: usize) -> Sign {
        // α_i = k (v ∓ √D1), k = x1/(2u²): a2 - α_i = (a2 - k v) ± k √D1.
        let k = self.x1.clone().div(&self.upow(2).scale(2)).expect("u > 0");
        let v = self.s().scale(6) - self.u.scale(5);
        let a = a2.clone() - k.clone() * v;
        let b = if i == 0 { k } else { -k };
        sign_a_plus_b_sqrt_c(&a, &b, &self.d1())
    }
    /// Sign of `u - (3 ∓ √3)s` (`minus = true` for `3 - √3`), exact.
    fn cmp_u_3_sqrt3(&self, minus: bool) -> Sign {
        let s = self.s();
        let a = self.u.clone() - s.scale(3);
        let b = if minus { s } else { -s };
        sign_a_plus_b_sqrt_c(&a, &b, &S::from_i64(3))
    }
    /// Props 3.1/3.2: a nonsingular quartic exists iff `(3-√3)s < u < (3+√3)s` (exact).
    pub fn prop_3_2_exists(&self) -> Option<bool> {
        let lo = self.cmp_u_3_sqrt3(true);
        let hi = self.cmp_u_3_sqrt3(false);
        // For s < 0 the printed bounds are in reverse order and the range is empty.
        let s_pos = self.s().sign().is_positive()?;
        Some(s_pos && lo.is_positive()? && hi.is_negative()?)
    }
    /// Which interval Prop 3.2 prints for this `u`.
    pub fn prop_3_2_case(&self) -> Option<A2Case> {
        if !self.prop_3_2_exists()? {
            return Some(A2Case::Empty);
        }
        let s = self.s();
        let u = &self.u;
        if u.cmp_sign(&(s.scale(4) * frac(1, 3))).is_negative()? {
            Some(A2Case::Alpha0Alpha1)
        } else if !u.cmp_sign(&s.scale(2)).is_positive()? {
            Some(A2Case::Alpha0Zero)
        } else if !u.cmp_sign(&s.scale(4)).is_positive()? {
            Some(A2Case::Alpha0Alpha2)
        } else {
            Some(A2Case::Alpha0Alpha1)
        }
    }
    /// Prop 3.2 **as printed**: is `a2` inside the printed interval? Exact, no
    /// square root (`a2 > α0` is decided as the sign of `a + b√D1`).
    pub fn prop_3_2_contains(&self, a2: &S) -> Option<bool> {
        let case = self.prop_3_2_case()?;
        if case == A2Case::Empty {
            return Some(false);
        }
        let above_a0 = self.cmp_alpha(a2, 0).is_positive()?;
        let upper = match case {
            A2Case::Empty => return Some(false),
            A2Case::Alpha0Alpha1 => self.cmp_alpha(a2, 1).is_negative()?,
            A2Case::Alpha0Zero => a2.sign().is_negative()?,
            A2Case::Alpha0Alpha2 => a2.cmp_sign(&self.alpha2()).is_negative()?,
        };
        Some(above_a0 && upper)
    }
    /// The mirrored data `(-x1, -y1, u)`: the point reflection `K → -K` maps
    /// `f → -f`, so `a2 → -a2` and `s` is unchanged.
    fn mirrored(&self) -> HermiteData<S> {
        HermiteData {
            x1: -self.x1.clone(),
            y1: -self.y1.clone(),
            u: self.u.clone(),
        }
    }
    /// The engine's Prop 3.2 (corrected for `x1 < 0`): is the quartic with this
    /// `a2` nonsingular on `[0, u]`? The printed table assumes `x1 > 0`; for
    /// `x1 < 0` the intervals are mirrored (`(α1, α0)`, `(0, α0)`, `(α2, α0)`),
    /// see `proofs/003-prop-3.2.md`. Exact, no square root.
    ///
    /// # Examples
    /// ```
    /// use lncert::ln::hermite::HermiteData;
    /// use lncert::scalar::{frac, Rational};
    /// let h = HermiteData::<Rational>::new(frac(-1, 1), frac(2, 3), frac(11, 4)).unwrap();
    /// assert_eq!(h.prop_3_2_contains(&frac(4, 7)), Some(false)); // as printed
    /// assert_eq!(h.nonsingular_a2_contains(&frac(4, 7)), Some(true)); // corrected
    /// ```
    pub fn nonsingular_a2_contains(&self, a2: &S) -> Option<bool> {
        if self.x1.sign().is_positive()? {
            self.prop_3_2_contains(a2)
        } else {
            self.mirrored().prop_3_2_contains(&-a2.clone())
        }
    }
    /// The open `a2` interval of nonsingular quartics (sorted ends; `None` if
    /// empty or undecided). Certified with intervals, approximate with `f64`.
    pub fn nonsingular_a2_interval(&self) -> Option<(S, S)>
    where
        S: ScalarSqrt,
    {
        if !self.x1.sign().is_positive()? {
            let (lo, hi) = self.mirrored().nonsingular_a2_interval()?;
            return Some((-hi, -lo));
        }
        let (a0, a1) = self.alphas()?;
        match self.prop_3_2_case()? {
            A2Case::Empty => None,
            A2Case::Alpha0Alpha1 => Some((a0, a1)),
            A2Case::Alpha0Zero => Some((a0, S::zero())),
            A2Case::Alpha0Alpha2 => Some((a0, self.alpha2())),
        }
    }
    /// The engine's Prop 3.3 (corrected for `x1 < 0` like
    /// [`Self::nonsingular_a2_contains`]): is the intercept `b` valid for slope `m ∈ (0, u)`?
    pub fn valid_intercept(&self, m: &S, b: &S) -> Option<bool> {
        self.nonsingular_a2_contains(&self.a2_from_b(m, b)?)
    }
    /// `b = f(m)` for the quartic with this `a2` (tangent line `m x + y + b = 0`).
    pub fn b_from_a2(&self, m: &S, a2: &S) -> S {
        self.quartic_f(a2).eval(m)
    }
    /// Inverse of [`Self::b_from_a2`]: `a2 = (u⁴ b - m³ x1 β)/(m² u² (u-m)²)`; `None` unless `0 < m < u`.
    pub fn a2_from_b(&self, m: &S, b: &S) -> Option<S> {
        if !(m.sign().is_positive()? && self.u.cmp_sign(m).is_positive()?) {
            return None;
        }
        self.a2_from_b_symbolic(m, b)
    }
    /// [`Self::a2_from_b`] without the `0 < m < u` check (for symbolic scalars);
    /// `None` if the denominator `m²u²(u-m)²` is (or may be) zero.
    pub fn a2_from_b_symbolic(&self, m: &S, b: &S) -> Option<S> {
        let m3 = m.sqr() * m.clone();
        let num = self.upow(4) * b.clone() - m3 * self.x1.clone() * self.beta(m);
        let den = m.sqr() * self.upow(2) * (self.u.clone() - m.clone()).sqr();
        num.div(&den)
    }
    /// The printed `β = -(m(3s - 2u) + u(3u - 4s))`.
    pub fn beta(&self, m: &S) -> S {
        let (s, u) = (self.s(), &self.u);
        -(m.clone() * (s.scale(3) - u.scale(2)) + u.clone() * (u.scale(3) - s.scale(4)))
    }
    /// The printed `βi = m²(mβ + u²(u-m)²αi/x1)/(u⁴/x1)` for a given `αi`.
    pub fn beta_i(&self, m: &S, alpha: &S) -> Option<S> {
        let (u, x1) = (&self.u, &self.x1);
        let inner = m.clone() * self.beta(m)
            + self.upow(2) * (u.clone() - m.clone()).sqr() * alpha.div(x1)?;
        (m.sqr() * inner).div(&self.upow(4).div(x1)?)
    }
    /// Prop 3.3 as printed: is the intercept `b` valid for slope `m ∈ (0, u)`?
    pub fn prop_3_3_contains(&self, m: &S, b: &S) -> Option<bool> {
        self.prop_3_2_contains(&self.a2_from_b(m, b)?)
    }
}

/// Seed 003 Prop 6.1: two normal-form curves with the same Gauss map (normal
/// `(t,1)` at parameter `t`) convolve to the normal-form curve of `f + F`.
pub fn convolve_normal_forms<S: Scalar>(f: &Poly<S>, g: &Poly<S>) -> (Poly<S>, Poly<S>) {
    normal_form(&f.add(g))
}

/// Seed 003 Prop 7.1's recommended range `τ ∈ (-∞, -1) ∪ (1, ∞)`.
pub fn prop_7_1_recommended<S: Scalar>(tau: &S) -> Option<bool> {
    Some(tau.cmp_sign(&S::from_i64(-1)).is_negative()? || tau.cmp_sign(&S::one()).is_positive()?)
}
