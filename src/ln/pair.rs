//! Seed 000 §4: pairs of compatible cubic LN curves with one linear normal map.
//!
//! Two frames are *compatible* when their end tangents are parallel:
//! `∇b0ʳ = c0 ∇b0ˡ`, `∇b1ʳ = c1 ∇b1ˡ` with `c0 c1 > 0`. Both signs occur in the
//! paper: Fig. 5(a) has `c0, c1 > 0`, Fig. 5(b) has `c0, c1 < 0` (the right curve
//! runs against the left one, so its normals `R∇b` point the other way; the
//! Gauss maps agree up to orientation).
//!
//! The key quantity `q = λr/λl = c1/c0` is **rational** for rational data, so
//! Prop 4.2 (`1/4 < q < 4`) and Remark 4.3 (`1/4 <= q <= 4`) are decided
//! exactly without square roots. With `ρl = κ/λl`, the right curve has
//! `ρr = κ/λr = ρl/q`; the admissible `ρl` form the open interval
//! `(1/2, 2) ∩ (q/2, 2q)`.

use super::cubic::{deltas_from_rho, tau_from_delta0, LnFrame, Tau};
use super::{checked_div, nonzero, LnError, OpenRange};
use crate::curve::{Bezier, V2};
use crate::scalar::{frac, Scalar, ScalarSqrt, Sign};

/// Two compatible frames and their end ratios `c0`, `c1`.
///
/// # Examples
/// ```
/// use lncert::curve::V2;
/// use lncert::ln::cubic::LnFrame;
/// use lncert::ln::pair::CompatiblePair;
/// use lncert::scalar::{frac, Rational};
/// let p = |x: i64, y: i64, d: i64| V2::<Rational>::new(frac(x, d), frac(y, d));
/// // Seed 000 Fig. 5(a).
/// let l = LnFrame::new(p(5, -2, 2), p(1, 2, 2), p(7, 10, 2)).unwrap();
/// let r = LnFrame::new(p(15, -24, 6), p(6, -15, 6), p(12, -7, 6)).unwrap();
/// let pair = CompatiblePair::new(l, r).unwrap();
/// assert_eq!(pair.ratio(), frac(4, 9)); // λr/λl
/// assert_eq!(pair.prop_4_2(), Some(true));
/// ```
#[derive(Clone, Debug, PartialEq)]
pub struct CompatiblePair<S> {
    /// The left frame (`b0ˡ, bmˡ, b3ˡ`).
    pub left: LnFrame<S>,
    /// The right frame (`b0ʳ, bmʳ, b3ʳ`), compatible with the left one.
    pub right: LnFrame<S>,
    /// `∇b0ʳ = c0 ∇b0ˡ`.
    pub c0: S,
    /// `∇b1ʳ = c1 ∇b1ˡ`.
    pub c1: S,
}

/// How to choose κ inside the admissible interval.
#[derive(Clone, Debug, PartialEq)]
pub enum KappaChoice<S> {
    /// `κ = sqrt(λl λr)`, the paper's choice: `ρl = sqrt(q)` (needs square roots).
    GeometricMean,
    /// The midpoint of the admissible `ρl` interval (exact for rational data).
    Midpoint,
    /// A given `ρl = κ/λl`, checked against the admissible interval.
    Rho(S),
}

/// A pair of LN cubics with one normal map, and their convolution.
#[derive(Clone, Debug, PartialEq)]
pub struct LnPair<S> {
    /// `ρl = κ/λl`.
    pub rho_left: S,
    /// `ρr = κ/λr = ρl/q`.
    pub rho_right: S,
    /// `(δ0ˡ, δ1ˡ)` of the left cubic, from `ρl` by eq. (5).
    pub deltas_left: (S, S),
    /// `(δ0ʳ, δ1ʳ)` of the right cubic, from `ρr` by eq. (5).
    pub deltas_right: (S, S),
    /// The left LN cubic `bl`.
    pub left: Bezier<S>,
    /// The right LN cubic `br`.
    pub right: Bezier<S>,
}

/// The convolution `bl + br` of an [`LnPair`]: again an LN cubic (Prop 4.4).
#[derive(Clone, Debug, PartialEq)]
pub struct Convolution<S> {
    /// Its frame `(b0ˡ+b0ʳ, bmˡ+bmʳ, b3ˡ+b3ʳ)`.
    pub frame: LnFrame<S>,
    /// `δ0 = (δ0ˡ + c0 δ0ʳ) / (1 + c0)`, `δ1 = (δ1ˡ + c1 δ1ʳ) / (1 + c1)`.
    pub deltas: (S, S),
    /// The cubic `bl + br` (control points summed).
    pub curve: Bezier<S>,
}

/// The ratio `c` with `b = c a` for parallel `a, b` (`a ≠ 0`), or an error.
fn parallel_ratio<S: Scalar>(a: &V2<S>, b: &V2<S>, field: &'static str) -> Result<S, LnError> {
    match a.cross(b).sign() {
        Sign::Zero => {}
        Sign::Unknown => return Err(LnError::Undecided { field }),
        _ => {
            return Err(LnError::NotCompatible {
                field,
                reason: "end tangents are not parallel",
            })
        }
    }
    let c = b
        .dot(a)
        .div(&a.norm2())
        .ok_or(LnError::Undecided { field })?;
    nonzero(c.sign(), field, "degenerate end tangent")?;
    Ok(c)
}

impl<S: Scalar> CompatiblePair<S> {
    /// Checks compatibility: parallel end tangents with `c0 c1 > 0`.
    pub fn new(left: LnFrame<S>, right: LnFrame<S>) -> Result<Self, LnError> {
        let c0 = parallel_ratio(&left.d0(), &right.d0(), "right.bm-right.b0")?;
        let c1 = parallel_ratio(&left.d1(), &right.d1(), "right.b3-right.bm")?;
        match c0.sign() * c1.sign() {
            Sign::Positive => Ok(CompatiblePair {
                left,
                right,
                c0,
                c1,
            }),
            Sign::Unknown => Err(LnError::Undecided { field: "c0*c1" }),
            _ => Err(LnError::NotCompatible {
                field: "right",
                reason: "one end tangent is parallel, the other anti-parallel (Gauss maps differ)",
            }),
        }
    }
    /// `q = λr/λl = c1/c0` (exact, no square root).
    pub fn ratio(&self) -> S {
        self.c1.div(&self.c0).expect("c0 ≠ 0 checked")
    }
    /// Prop 4.2: one linear normal map with both curves regular iff `1/4 < q < 4`.
    pub fn prop_4_2(&self) -> Option<bool> {
        let q = self.ratio();
        Some(q.cmp_sign(&frac(1, 4)).is_positive()? && S::from_i64(4).cmp_sign(&q).is_positive()?)
    }
    /// Remark 4.3: one *extended* linear normal map (cusps allowed at the end
    /// points only) iff `1/4 <= q <= 4`.
    pub fn remark_4_3(&self) -> Option<bool> {
        let q = self.ratio();
        Some(
            !q.cmp_sign(&frac(1, 4)).is_negative()?
                && !S::from_i64(4).cmp_sign(&q).is_negative()?,
        )
    }
    /// The admissible `ρl = κ/λl`: `(1/2, 2) ∩ (q/2, 2q)` (empty iff Prop 4.2 fails).
    pub fn admissible_rho_left(&self) -> Option<OpenRange<S>> {
        let q = self.ratio();
        let half = frac::<S>(1, 2);
        let lo_q = q.clone() * half.clone();
        let hi_q = q.scale(2);
        let lo = if lo_q.cmp_sign(&half).is_positive()? {
            lo_q
        } else {
            half
        };
        let hi = if hi_q.cmp_sign(&S::from_i64(2)).is_negative()? {
            hi_q
        } else {
            S::from_i64(2)
        };
        Some(OpenRange { lo, hi })
    }
    /// Builds the two curves for `ρl`, without checking regularity.
    pub fn curves_for_rho(&self, rho_left: &S) -> Result<LnPair<S>, LnError> {
        let rho_right = checked_div(
            rho_left.clone(),
            &self.ratio(),
            "lambda_r/lambda_l",
            "q = c1/c0 underflows to 0",
        )?;
        let dl = deltas_from_rho(rho_left)?;
        let dr = deltas_from_rho(&rho_right)?;
        Ok(LnPair {
            left: self.left.cubic(&dl.0, &dl.1),
            right: self.right.cubic(&dr.0, &dr.1),
            rho_left: rho_left.clone(),
            rho_right,
            deltas_left: dl,
            deltas_right: dr,
        })
    }
    /// Chooses κ and builds the regular pair; fails if Prop 4.2 does not hold
    /// or a given `ρl` is not admissible.
    pub fn ln_pair(&self, choice: &KappaChoice<S>) -> Result<LnPair<S>, LnError>
    where
        S: ScalarSqrt,
    {
        let rho = match choice {
            KappaChoice::GeometricMean => self
                .ratio()
                .sqrt()
                .ok_or(LnError::Undecided { field: "sqrt(q)" })?,
            _ => return self.ln_pair_exact(choice),
        };
        self.ln_pair_exact(&KappaChoice::Rho(rho))
    }
    /// As [`Self::ln_pair`] for choices that need no square root (`Midpoint`, `Rho`).
    pub fn ln_pair_exact(&self, choice: &KappaChoice<S>) -> Result<LnPair<S>, LnError> {
        let range = self
            .admissible_rho_left()
            .ok_or(LnError::Undecided { field: "q" })?;
        if range.is_empty().ok_or(LnError::Undecided { field: "q" })? {
            return Err(LnError::InvalidParameter {
                field: "lambda_r/lambda_l",
                reason:
                    "outside (1/4, 4): no pair of regular LN cubics with one normal map (Prop 4.2)",
            });
        }
        let rho = match choice {
            KappaChoice::Midpoint => (range.lo.clone() + range.hi.clone()) * frac(1, 2),
            KappaChoice::Rho(r) => r.clone(),
            KappaChoice::GeometricMean => {
                return Err(LnError::InvalidParameter {
                    field: "kappa",
                    reason: "geometric mean needs square roots",
                })
            }
        };
        if !range
            .contains(&rho)
            .ok_or(LnError::Undecided { field: "kappa" })?
        {
            return Err(LnError::InvalidParameter {
                field: "kappa",
                reason: "κ/λl outside the admissible interval (1/2, 2) ∩ (q/2, 2q)",
            });
        }
        self.curves_for_rho(&rho)
    }
    /// The convolution `bl + br` (sum of control points) of a pair built from this frame pair.
    pub fn convolution(&self, pair: &LnPair<S>) -> Result<Convolution<S>, LnError> {
        let (d0, d1) =
            convolution_deltas(&self.c0, &self.c1, &pair.deltas_left, &pair.deltas_right)?;
        let frame = LnFrame::new(
            self.left.b0.add(&self.right.b0),
            self.left.bm.add(&self.right.bm),
            self.left.b3.add(&self.right.b3),
        )?;
        let pts = pair
            .left
            .points()
            .iter()
            .zip(pair.right.points())
            .map(|(a, b)| a.add(b))
            .collect();
        Ok(Convolution {
            frame,
            deltas: (d0, d1),
            curve: Bezier::new(pts),
        })
    }
}

/// Prop 4.4 **as printed**: the convolution has a cusp in `(0,1)` iff `δ0 ∉ (0,1)`
/// or `δ1 ∉ (0,1)`. Wrong when `δ0 ∈ {0, 1}` (cusp at an end point): see
/// [`convolution_has_interior_cusp`] and `proofs/000-prop-4.4.md`.
pub fn prop_4_4_as_printed<S: Scalar>(deltas: &(S, S)) -> Option<bool> {
    let inside = |d: &S| -> Option<bool> {
        Some(d.sign().is_positive()? && S::one().cmp_sign(d).is_positive()?)
    };
    Some(!inside(&deltas.0)? || !inside(&deltas.1)?)
}

/// The engine's (corrected) Prop 4.4: an LN cubic of eq. (1) has a cusp in the
/// open interval `(0,1)` iff `τ ∈ (0,1)` iff `δ0 ∉ [0,1]` or `δ1 ∉ [0,1]`.
///
/// # Examples
/// ```
/// use lncert::ln::pair::{convolution_has_interior_cusp, prop_4_4_as_printed};
/// use lncert::scalar::{frac, Rational};
/// // δ0 = 0, δ1 = 1 is τ = 0: the cusp is at the end point t = 0, not inside.
/// let d: (Rational, Rational) = (frac(0, 1), frac(1, 1));
/// assert_eq!(convolution_has_interior_cusp(&d), Some(false));
/// assert_eq!(prop_4_4_as_printed(&d), Some(true)); // the printed statement errs here
/// ```
pub fn convolution_has_interior_cusp<S: Scalar>(deltas: &(S, S)) -> Option<bool> {
    let in_closed = |d: &S| -> Option<bool> {
        Some(!d.sign().is_negative()? && !d.cmp_sign(&S::one()).is_positive()?)
    };
    Some(!in_closed(&deltas.0)? || !in_closed(&deltas.1)?)
}

/// Where the convolution's cusp is: `τ = δ0/(3δ0 - 2)` (eq. (1) inverted).
pub fn cusp_parameter<S: Scalar>(deltas: &(S, S)) -> Option<Tau<S>> {
    tau_from_delta0(&deltas.0)
}

/// The δ's of the convolution `bl + br` in its own frame `(b0ˡ+b0ʳ, bmˡ+bmʳ, b3ˡ+b3ʳ)`:
/// `δ0 = (δ0ˡ + c0 δ0ʳ)/(1 + c0)`, `δ1 = (δ1ˡ + c1 δ1ʳ)/(1 + c1)`.
/// `c0 = -1` or `c1 = -1` collapses a side of the convolution's frame: an error.
pub fn convolution_deltas<S: Scalar>(
    c0: &S,
    c1: &S,
    left: &(S, S),
    right: &(S, S),
) -> Result<(S, S), LnError> {
    let den0 = S::one() + c0.clone();
    let den1 = S::one() + c1.clone();
    let d0 = checked_div(
        left.0.clone() + c0.clone() * right.0.clone(),
        &den0,
        "c0",
        "c0 = -1: the convolution's b0 and bm coincide",
    )?;
    let d1 = checked_div(
        left.1.clone() + c1.clone() * right.1.clone(),
        &den1,
        "c1",
        "c1 = -1: the convolution's bm and b3 coincide",
    )?;
    Ok((d0, d1))
}

/// The decisions of Prop 4.2 and Prop 4.4 for a compatible pair given by its
/// end ratios `c0, c1` (exact) and a choice `ρl = κ/λl`, as a [`crate::scalar::Predicate`]:
/// evaluate it in any arithmetic, or [`crate::scalar::filtered`] (intervals
/// first, rationals when they cannot decide).
///
/// The answer is `(one normal map exists, convolution has a cusp in (0,1))`,
/// the second `None` when `ρl` is not admissible or the convolution degenerates.
///
/// # Examples
/// ```
/// use lncert::ln::pair::PairDecision;
/// use lncert::scalar::{filtered, frac, Predicate};
/// // Fig. 5(b): c0 = -3/2, c1 = -1/2 (q = 1/3), ρl = 7/12 ∈ (1/2, 2/3).
/// let d = PairDecision { c0: frac(-3, 2), c1: frac(-1, 2), rho_left: frac(7, 12) };
/// assert_eq!(filtered(&d), Some((true, Some(true))));
/// assert_eq!(d.decide::<f64>(), Some((true, Some(true))));
/// ```
#[derive(Clone, Debug, PartialEq)]
pub struct PairDecision {
    /// Start ratio: `∇b0ʳ = c0 ∇b0ˡ`.
    pub c0: crate::scalar::Rational,
    /// End ratio: `∇b1ʳ = c1 ∇b1ˡ`.
    pub c1: crate::scalar::Rational,
    /// The chosen `ρl = κ/λl`.
    pub rho_left: crate::scalar::Rational,
}

/// Evaluated through [`pair_decision_signs`], the division-free form of
/// [`pair_decision`] (the same answer in exact arithmetic, tested against it).
impl crate::scalar::Predicate for PairDecision {
    type Out = (bool, Option<bool>);
    fn decide<S: Scalar>(&self) -> Option<Self::Out> {
        let conv = |r: &crate::scalar::Rational| S::from_rational(r);
        pair_decision_signs(&conv(&self.c0), &conv(&self.c1), &conv(&self.rho_left))
    }
    fn decide_static(&self) -> Option<Self::Out> {
        let conv = |r: &crate::scalar::Rational| crate::scalar::FloatErr::from_rational(r);
        pair_decision_static(conv(&self.c0), conv(&self.c1), conv(&self.rho_left))
    }
}

/// [`pair_decision`] without divisions: every test is the sign of a polynomial of
/// degree ≤ 1 in each of `c0, c1, ρ`, which a float with an error bound
/// ([`crate::scalar::FloatErr`]) decides in a few operations and rationals
/// decide without reducing quotients. The same answer as [`pair_decision`] in
/// exact arithmetic (`None` for `c0 = 0`, as its `q = c1/c0` gives), by:
///
/// * `q > 1/4 ⟺ (4c1 − c0)·c0 > 0`, `q < 4 ⟺ (4c0 − c1)·c0 > 0`,
///   `ρ > q/2 ⟺ (2ρc0 − c1)·c0 > 0`, `ρ < 2q ⟺ (2c1 − ρc0)·c0 > 0`
///   (each side times `c0² > 0`);
/// * with `A = 2ρ(1 + c0) − (1 + c1)`, `B = 2(1 + c1) − ρ(1 + c0)` and `ρ > 0`,
///   `δ0 = 2A/(3ρ(1 + c0))`, `1 − δ0 = B/(3ρ(1 + c0))`, `δ1 = 2B/(3(1 + c1))`,
///   `1 − δ1 = A/(3(1 + c1))` (eq. (1)'s `δ`s of `ρ` and `ρ/q`, summed as in
///   [`convolution_deltas`], with `c0 q = c1`); so `δ0 ∈ [0, 1]` iff `A` and `B`
///   have no sign opposite to `1 + c0`'s, and `δ1 ∈ [0, 1]` likewise with
///   `1 + c1`; `1 + c0 = 0` or `1 + c1 = 0` is the degenerate frame
///   [`convolution_deltas`] refuses (the second answer `None`).
///
/// # Examples
/// ```
/// use lncert::ln::pair::{pair_decision, pair_decision_signs};
/// use lncert::scalar::{frac, FloatErr, Rational, Scalar};
/// let (c0, c1, rho): (Rational, Rational, Rational) = (frac(-3, 2), frac(-1, 2), frac(7, 12));
/// assert_eq!(pair_decision_signs(&c0, &c1, &rho), Some((true, Some(true))));
/// assert_eq!(pair_decision_signs(&c0, &c1, &rho), pair_decision(&c0, &c1, &rho));
/// // q = c1/c0 = 4 exactly: a float with an error bound cannot decide `q < 4`
/// let f = |r: &Rational| FloatErr::from_rational(r);
/// let (c0, c1): (Rational, Rational) = (frac(1, 3), frac(4, 3));
/// assert_eq!(pair_decision_signs(&f(&c0), &f(&c1), &f(&rho)), None);
/// assert_eq!(pair_decision_signs(&c0, &c1, &rho), Some((false, None)));
/// ```
pub fn pair_decision_signs<S: Scalar>(c0: &S, c1: &S, rho: &S) -> Option<(bool, Option<bool>)> {
    let s = c0.sign();
    if !matches!(s, Sign::Positive | Sign::Negative) {
        return None; // c0 = 0 (q undefined) or undecided
    }
    let exists = ((c1.scale(4) - c0.clone()).sign() * s).is_positive()?
        && ((c0.scale(4) - c1.clone()).sign() * s).is_positive()?;
    let rc0 = rho.clone() * c0.clone();
    let admissible = exists
        && rho.cmp_sign(&frac(1, 2)).is_positive()?
        && S::from_i64(2).cmp_sign(rho).is_positive()?
        && ((rc0.scale(2) - c1.clone()).sign() * s).is_positive()?
        && ((c1.scale(2) - rc0).sign() * s).is_positive()?;
    if !admissible {
        return Some((exists, None));
    }
    let p0 = S::one() + c0.clone();
    let p1 = S::one() + c1.clone();
    let (s0, s1) = (p0.sign(), p1.sign());
    for side in [s0, s1] {
        match side {
            Sign::Unknown => return None,
            Sign::Zero => return Some((exists, None)),
            _ => {}
        }
    }
    let m = rho.clone() * p0;
    let a = (m.scale(2) - p1.clone()).sign();
    let b = (p1.scale(2) - m).sign();
    // δ ∈ [0, 1] iff neither factor has the sign opposite to its denominator's
    let closed = |side: Sign| -> Option<bool> {
        Some(!(a * side).is_negative()? && !(b * side).is_negative()?)
    };
    Some((exists, Some(!closed(s0)? || !closed(s1)?)))
}

/// The static stage of [`PairDecision`]'s filter: [`pair_decision_signs`]'
/// tests evaluated in plain `f64`, each sign read against **one error bound
/// computed once** from the inputs' magnitude, instead of a bound carried
/// through every operation ([`crate::scalar::FloatErr`]'s arithmetic). `None`
/// when a test's value is within the bound (exact ties are, but for the
/// degenerate frame `1 + c = 0` of an exact float `c = −1`), when an
/// input is not finite or has a negative bound, or when `M` (below) is 10¹⁵⁰ or more;
/// otherwise the exact answer of the inputs' reals.
///
/// **The bound.** The inputs stand for reals `x0, x1, ρ` with
/// `|x − v| ≤ e` (`E` the largest `e`); `M = max(1, |c0.v|, |c1.v|, |ρ.v|, E)`,
/// so `|x| ≤ 2M`. With unit roundoff `u = 2⁻⁵³`, `η = 2⁻¹⁰²²` (a product's
/// absolute error in the subnormal range) and scalings by 2 and 4 exact (no
/// overflow: `M < 10¹⁵⁰`, so every value is below `4M² < 2¹⁰²³`),
/// the computed tests differ from the exact ones by at most
///
/// | test | computed as | error ≤ |
/// |---|---|---|
/// | `c0`, `1/2 < ρ`, `ρ < 2` | `v`, `r − 1/2`, `2 − r` | `3uM + E` |
/// | `4c1 − c0`, `4c0 − c1` | one rounding | `5uM + 5E` |
/// | `2ρc0 − c1`, `2c1 − ρc0` | `P = fl(r·c0)`: `uM² + η + 3ME` from `ρx0` | `5uM² + 7ME + 2η` (+ `O(u²M²)`) |
/// | `1 + c0`, `1 + c1` | one rounding | `2uM + E` |
/// | `A = 2ρ(1 + c0) − (1 + c1)` | `m = fl(r·p0)`: `4uM² + 4ME + η` | `16uM² + 9ME + 2η` (+ `O(u²M²)`) |
/// | `B = 2(1 + c1) − ρ(1 + c0)` | the same `m` | `14uM² + 6ME + η` (+ `O(u²M²)`) |
///
/// (each product's rounding `u|r·p| ≤ u·2M²(1 + u)`, each sum's `u` times the
/// sum of its operands' magnitudes; `uM ≤ uM²`, `E ≤ ME` as `M ≥ 1`). The
/// stage uses `d = 32uM² + 16ME + 4η`, computed in three roundings of relative
/// `u` each: at least twice every row's leading terms, which covers the `O(u²M²)`
/// remainders and the bound's own rounding. A sign is read as positive iff
/// `t > d`, negative iff `t < −d`.
///
/// Tested against exact rationals on inputs a few ulps from every boundary
/// (`tests/seed000.rs`, `static_pair_decision_is_never_wrong`) and for deciding
/// every case [`crate::scalar::FloatErr`] decides away from ties (below).
///
/// # Examples
/// ```
/// use lncert::ln::pair::{pair_decision_signs, pair_decision_static};
/// use lncert::scalar::{frac, FloatErr, Rational, Scalar};
/// let f = |r: &Rational| FloatErr::from_rational(r);
/// let (c0, c1, rho): (Rational, Rational, Rational) = (frac(-3, 2), frac(-1, 2), frac(7, 12));
/// assert_eq!(pair_decision_static(f(&c0), f(&c1), f(&rho)), Some((true, Some(true))));
/// // q = 4 exactly: an exact tie, left to the exact stages
/// let (c0, c1) = (frac(1, 3), frac(4, 3));
/// assert_eq!(pair_decision_static(f(&c0), f(&c1), f(&rho)), None);
/// assert_eq!(pair_decision_signs(&c0, &c1, &rho), Some((false, None)));
/// ```
pub fn pair_decision_static(
    c0: crate::scalar::FloatErr,
    c1: crate::scalar::FloatErr,
    rho: crate::scalar::FloatErr,
) -> Option<(bool, Option<bool>)> {
    const U: f64 = f64::EPSILON * 0.5;
    let (a, b, r) = (c0.v, c1.v, rho.v);
    // `>=` is false for NaN; the sum below is not finite for an infinity or NaN
    let usable = c0.e >= 0.0 && c1.e >= 0.0 && rho.e >= 0.0 && (a + b + r).is_finite();
    if !usable {
        return None;
    }
    let e = c0.e.max(c1.e).max(rho.e);
    let m = 1f64.max(a.abs()).max(b.abs()).max(r.abs()).max(e);
    if m >= 1e150 {
        return None; // (an infinite bound too) every value below stays under 4M² < 2¹⁰²³
    }
    let d = 32.0 * U * (m * m) + 16.0 * (m * e) + 4.0 * f64::MIN_POSITIVE;
    // a test's sign: `Some(true)` positive, `Some(false)` negative, `None` within `d`
    let pos = |t: f64| {
        if t > d {
            Some(true)
        } else if t < -d {
            Some(false)
        } else {
            None
        }
    };
    let s = pos(a)?;
    // the sign of `t·c0`: whether `t` has `c0`'s sign
    let agree = |t: f64| Some(pos(t)? == s);
    let exists = agree(4.0 * b - a)? && agree(4.0 * a - b)?;
    let p = r * a;
    let admissible =
        exists && pos(r - 0.5)? && pos(2.0 - r)? && agree(2.0 * p - b)? && agree(2.0 * b - p)?;
    if !admissible {
        return Some((exists, None));
    }
    let (p0, p1) = (1.0 + a, 1.0 + b);
    // `1 + c = 0` is decided for an exact `c = −1` (the degenerate frame)
    let side = |t: f64, e: f64| {
        if t == 0.0 && e == 0.0 {
            Some(None)
        } else {
            pos(t).map(Some)
        }
    };
    let Some(s0) = side(p0, c0.e)? else {
        return Some((exists, None));
    };
    let Some(s1) = side(p1, c1.e)? else {
        return Some((exists, None));
    };
    let mm = r * p0;
    let (sa, sb) = (pos(2.0 * mm - p1), pos(2.0 * p1 - mm));
    // δ ∈ [0, 1] iff neither factor has the sign opposite to its denominator's
    let closed = |side: bool| Some(sa? == side && sb? == side);
    Some((exists, Some(!closed(s0)? || !closed(s1)?)))
}

/// The kernel of [`PairDecision`] on inputs already in `S` (the fast path takes
/// `f64` inputs directly): `(Prop 4.2 holds, convolution cusp in (0,1))`.
pub fn pair_decision<S: Scalar>(c0: &S, c1: &S, rho: &S) -> Option<(bool, Option<bool>)> {
    let q = c1.div(c0)?;
    let exists =
        q.cmp_sign(&frac(1, 4)).is_positive()? && S::from_i64(4).cmp_sign(&q).is_positive()?;
    let admissible = exists
        && rho.cmp_sign(&frac(1, 2)).is_positive()?
        && S::from_i64(2).cmp_sign(rho).is_positive()?
        && rho.cmp_sign(&(q.clone() * frac(1, 2))).is_positive()?
        && q.scale(2).cmp_sign(rho).is_positive()?;
    if !admissible {
        return Some((exists, None));
    }
    let dl = deltas_from_rho(rho).ok()?;
    let dr = deltas_from_rho(&rho.div(&q)?).ok()?;
    match convolution_deltas(c0, c1, &dl, &dr) {
        Ok(d) => Some((exists, Some(convolution_has_interior_cusp(&d)?))),
        Err(LnError::Undecided { .. }) => None,
        Err(_) => Some((exists, None)),
    }
}
