//! Seed 000 §6, Prop 6.1: the cubic LN approximation `ca` of the unit circular
//! arc `c(s) = (cos s, sin s)`, `s ∈ [-α, α]`, `2α < π`, with normal map
//! `n(t) = N0 (1-t) + κ N1 t`, and the closed form of `max |‖ca(t)‖ - 1|`.
//!
//! Control points: `c0 = (cos α, -sin α)`, `c3 = (cos α, sin α)`, tangent
//! intersection `cm = (sec α, 0)`, and `δ0 = 2/3 (2 - 1/κ)`, `δ1 = 2/3 (2 - κ)`
//! (eq. (11) = eq. (5) with `λ = 1`). The critical points of `‖ca‖` inside
//! `(0,1)` are among the roots `s1, s2` of `A s² + B s + C` (eq. (9), (10)).
//!
//! The half-angle is given as `(cos α, sin α)`, a vector, never as radians: exact
//! data stays exact, and radians are enclosed with
//! [`crate::scalar::sin_cos_enclosure`].

use super::cubic::{deltas_from_rho, LnFrame};
use super::LnError;
use crate::curve::{Bezier, V2};
use crate::scalar::{sign_a_plus_b_sqrt_c, Scalar, ScalarSqrt, Sign};

/// A unit arc of half-angle `α` and the parameter `κ` of its LN approximation.
///
/// # Examples
/// ```
/// use lncert::ln::circle::ArcApprox;
/// // α = π/4, κ = 1.5 (seed 000 Fig. 10, left): only s2 lies in (0,1).
/// let h = std::f64::consts::FRAC_1_SQRT_2;
/// let arc = ArcApprox::new(h, h, 1.5).unwrap();
/// let (s1, s2) = arc.critical_params().unwrap();
/// assert!(!(0.0 < s1 && s1 < 1.0) && (0.0 < s2 && s2 < 1.0));
/// ```
#[derive(Clone, Debug, PartialEq)]
pub struct ArcApprox<S> {
    /// `cos α` of the half-angle `α` (`> 0`).
    pub cos_a: S,
    /// `sin α` of the half-angle `α` (`> 0`).
    pub sin_a: S,
    /// The parameter `κ > 0` of the normal map `n(t) = N0 (1-t) + κ N1 t`.
    pub kappa: S,
}

/// Which of the three cases of Prop 6.1 applies.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Prop61Case {
    /// `κ ∈ [1/2, 1 - sin α] ∪ [1/(1 - sin α), 2]`: `dH = |‖ca(s1)‖ - 1|`.
    S1,
    /// `κ ∈ (1 - sin α, 1/(1 + sin α)) ∪ (1 + sin α, 1/(1 - sin α))`: the max of both.
    Both,
    /// `κ ∈ [1/(1 + sin α), 1 + sin α]`: `dH = |‖ca(s2)‖ - 1|`.
    S2,
}

impl<S: Scalar> ArcApprox<S> {
    /// Requires `cos α > 0`, `sin α > 0` (so `0 < 2α < π`) and `κ > 0`.
    /// `(cos α, sin α)` need not be normalised exactly for intervals, but the
    /// formulas assume `cos² + sin² = 1`.
    pub fn new(cos_a: S, sin_a: S, kappa: S) -> Result<Self, LnError> {
        for (v, field) in [
            (&cos_a, "cos_alpha"),
            (&sin_a, "sin_alpha"),
            (&kappa, "kappa"),
        ] {
            match v.sign() {
                Sign::Positive => {}
                Sign::Unknown => return Err(LnError::Undecided { field }),
                _ => {
                    return Err(LnError::InvalidParameter {
                        field,
                        reason: "must be > 0 (0 < 2α < π, κ > 0)",
                    })
                }
            }
        }
        Ok(ArcApprox {
            cos_a,
            sin_a,
            kappa,
        })
    }
    /// `sin² α`.
    pub fn sin2(&self) -> S {
        self.sin_a.sqr()
    }
    /// The LN frame `(cos α, -sin α), (sec α, 0), (cos α, sin α)`.
    pub fn frame(&self) -> Result<LnFrame<S>, LnError> {
        let sec = self
            .cos_a
            .recip()
            .ok_or(LnError::Undecided { field: "cos_alpha" })?;
        // Never collinear: sin α > 0 and cos α > 0 are checked by `new`.
        Ok(LnFrame::new_unchecked(
            V2::new(self.cos_a.clone(), -self.sin_a.clone()),
            V2::new(sec, S::zero()),
            V2::new(self.cos_a.clone(), self.sin_a.clone()),
        ))
    }
    /// The cubic LN approximation `ca`.
    pub fn cubic(&self) -> Result<Bezier<S>, LnError> {
        let (d0, d1) = deltas_from_rho(&self.kappa)?;
        Ok(self.frame()?.cubic(&d0, &d1))
    }
    /// Eq. (10): `A = (κ-1)³ + 4κ(κ-1) sin²α`, `B = 2(κ-1)² + κ(3-5κ) sin²α`,
    /// `C = -(κ-1)² + κ² sin²α`.
    pub fn abc(&self) -> (S, S, S) {
        let k = &self.kappa;
        let km1 = k.clone() - S::one();
        let s2 = self.sin2();
        let a = km1.sqr() * km1.clone() + (k.clone() * km1.clone() * s2.clone()).scale(4);
        let b = km1.sqr().scale(2) + k.clone() * (S::from_i64(3) - k.scale(5)) * s2.clone();
        let c = -km1.sqr() + k.sqr() * s2;
        (a, b, c)
    }
    /// Squared distance from the origin minus one, `‖ca(s)‖² - 1` (exact for rationals).
    pub fn radial_defect2(&self, s: &S) -> Result<S, LnError> {
        Ok(self.cubic()?.eval(s).norm2() - S::one())
    }
    /// Whether `s1` and `s2` of eq. (9) lie in `(0, 1)`, decided **without square
    /// roots** (signs of `a + b√D` from squares), so exactly with rationals.
    /// For `κ = 1` (`A = 0`) the quadratic is linear: `s1` has gone to infinity
    /// and `s2 = -C/B`. `None` if undecided.
    ///
    /// # Examples
    /// ```
    /// use lncert::ln::circle::ArcApprox;
    /// use lncert::scalar::{frac, Rational};
    /// // cos α = 3/5, sin α = 4/5, κ = 3/2: only s2 lies in (0, 1).
    /// let arc = ArcApprox::<Rational>::new(frac(3, 5), frac(4, 5), frac(3, 2)).unwrap();
    /// assert_eq!(arc.critical_params_in_unit(), Some((false, true)));
    /// ```
    pub fn critical_params_in_unit(&self) -> Option<(bool, bool)> {
        let (a, b, c) = self.abc();
        let inside_linear =
            |s: &S| Some(s.sign().is_positive()? && S::one().cmp_sign(s).is_positive()?);
        match a.sign() {
            Sign::Unknown => return None,
            Sign::Zero => {
                let s2 = (-c).div(&b)?;
                return Some((false, inside_linear(&s2)?));
            }
            _ => {}
        }
        let d = b.sqr() - (a.clone() * c).scale(4);
        match d.sign() {
            Sign::Negative => return Some((false, false)),
            Sign::Unknown => return None,
            _ => {}
        }
        let sa = a.sign();
        // s = (-B + e√D)/(2A): s > 0 iff sign(-B + e√D) = sign(A);
        // s < 1 iff sign(-B - 2A + e√D) = -sign(A).
        let inside = |e: i64| -> Option<bool> {
            let pos = sign_a_plus_b_sqrt_c(&-b.clone(), &S::from_i64(e), &d);
            let below = sign_a_plus_b_sqrt_c(&(-b.clone() - a.scale(2)), &S::from_i64(e), &d);
            if pos == Sign::Unknown || below == Sign::Unknown {
                return None;
            }
            Some(pos == sa && below == sa.neg())
        };
        Some((inside(1)?, inside(-1)?))
    }
    /// Which case of Prop 6.1 the printed κ-ranges select.
    pub fn prop_6_1_case(&self) -> Option<Prop61Case> {
        let (k, sa) = (&self.kappa, &self.sin_a);
        let one = S::one();
        let lo1 = one.clone() - sa.clone();
        let hi1 = (one.clone() - sa.clone()).recip()?;
        let lo2 = (one.clone() + sa.clone()).recip()?;
        let hi2 = one + sa.clone();
        if !k.cmp_sign(&lo1).is_positive()? || !k.cmp_sign(&hi1).is_negative()? {
            Some(Prop61Case::S1)
        } else if !k.cmp_sign(&lo2).is_negative()? && !k.cmp_sign(&hi2).is_positive()? {
            Some(Prop61Case::S2)
        } else {
            Some(Prop61Case::Both)
        }
    }
}

impl<S: ScalarSqrt> ArcApprox<S> {
    /// Eq. (9): `s1, s2 = (-B ± √(B² - 4AC)) / 2A`; `None` if `A` may vanish or
    /// the discriminant may be negative.
    pub fn critical_params(&self) -> Option<(S, S)> {
        let (a, b, c) = self.abc();
        let r = (b.sqr() - (a.clone() * c).scale(4)).sqrt()?;
        let two_a = a.scale(2);
        Some(((-b.clone() + r.clone()).div(&two_a)?, (-b - r).div(&two_a)?))
    }
    /// `|‖ca(s)‖ - 1|`.
    pub fn radial_error(&self, s: &S) -> Option<S> {
        let d = self.cubic().ok()?.eval(s).norm2().sqrt()? - S::one();
        Some(d.abs_val())
    }
    /// Prop 6.1's closed form, following the printed case split. `None` if undecided.
    pub fn prop_6_1_distance(&self) -> Option<S> {
        let (s1, s2) = self.critical_params()?;
        match self.prop_6_1_case()? {
            Prop61Case::S1 => self.radial_error(&s1),
            Prop61Case::S2 => self.radial_error(&s2),
            Prop61Case::Both => {
                let (e1, e2) = (self.radial_error(&s1)?, self.radial_error(&s2)?);
                Some(if e1.cmp_sign(&e2).is_positive()? {
                    e1
                } else {
                    e2
                })
            }
        }
    }
    /// Whether `s1` and `s2` lie in `(0, 1)`, decided from their values (not from
    /// the printed κ-ranges), for checking Fig. 9.
    pub fn params_in_unit(&self) -> Option<(bool, bool)> {
        let (s1, s2) = self.critical_params()?;
        let inside = |s: &S| Some(s.sign().is_positive()? && S::one().cmp_sign(s).is_positive()?);
        Some((inside(&s1)?, inside(&s2)?))
    }
}
