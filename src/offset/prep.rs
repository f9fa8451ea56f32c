//! Preprocessing and exact facts about the input: split parameters
//! (inflections, Gauss map), canonical unit normals at split points, the cusps
//! of the exact offset, and the corners of a piecewise curve.

use crate::curve::{Bezier, V2};
use crate::poly::{
    certify_no_root, isolate_roots, isolate_simple_roots, square_free, Poly, RealRoot, Span,
};
use crate::scalar::{interval_from_rational, rational_from_f64, Interval, Rational};
use num_traits::{Signed, Zero};

/// `x′ × x″` of a Bézier piece as an exact power-basis polynomial.
pub fn curvature_numerator(x: &Bezier<Rational>) -> Poly<Rational> {
    curvature_numerator_in(x).trimmed()
}

/// `x′ × x″` in any arithmetic.
fn curvature_numerator_in<S: crate::scalar::Scalar>(x: &Bezier<S>) -> Poly<S> {
    let (dx, dy) = x.hodograph().power_coords();
    let (ddx, ddy) = (dx.derivative(), dy.derivative());
    dx.mul(&ddy).sub(&dy.mul(&ddx))
}

/// `d² (x′ × x″)² − |x′|⁶`, whose roots are the cusps of the offset at distance `d`.
pub(super) fn cusp_polynomial<S: crate::scalar::Scalar>(
    x: &Bezier<S>,
    k: &Poly<S>,
    d: &S,
) -> Poly<S> {
    let (dx, dy) = x.hodograph().power_coords();
    let speed2 = dx.mul(&dx).add(&dy.mul(&dy));
    Poly::constant(d.clone() * d.clone())
        .mul(k)
        .mul(k)
        .sub(&speed2.mul(&speed2).mul(&speed2))
}

fn is_zero_poly(p: &Poly<Rational>) -> bool {
    p.coeffs().iter().all(Zero::is_zero)
}

/// Bisects an isolating interval of a simple root of the square-free `sf` down to
/// width `2^-bits` (exact sign evaluations at dyadic midpoints). `refine_root`
/// recomputes the square-free part on every call; here it is computed once.
pub(crate) fn bisect(sf: &Poly<Rational>, r: &RealRoot, bits: u32) -> RealRoot {
    let w = Rational::new(1.into(), num_bigint::BigInt::from(1u8) << bits);
    let (mut l, mut h) = (r.lo.clone(), r.hi.clone());
    // the sign by an interval enclosure of `sf(x)` first (the coefficients
    // enclosed once, Horner at the enclosure of `x`), exactly only when that
    // enclosure contains 0: most bisection steps are far from the root
    let sf_iv = sf.map(interval_from_rational);
    let sign = |x: &Rational| {
        let e = sf_iv.eval(&interval_from_rational(x));
        if e.inf() > 0.0 {
            return 1;
        }
        if e.sup() < 0.0 {
            return -1;
        }
        let v = sf.eval(x);
        if v.is_zero() {
            0
        } else if v.is_positive() {
            1
        } else {
            -1
        }
    };
    let sl = sign(&l);
    if sl == 0 || sign(&h) == sl {
        return r.clone();
    }
    while &h - &l > w {
        let m = (&l + &h) / Rational::from_integer(2.into());
        let sm = sign(&m);
        if sm == 0 {
            return RealRoot {
                lo: m.clone(),
                hi: m,
            };
        }
        if sm == sl {
            l = m;
        } else {
            h = m;
        }
    }
    RealRoot { lo: l, hi: h }
}

/// [`bisect`] for an isolating interval `[a, b]` with float ends (the
/// interval isolation's), kept in floats: each midpoint is a float strictly
/// between the ends, its sign taken from the interval enclosure of `sf` at
/// the point and exactly (the float as a rational) only when the enclosure
/// holds 0. Stops once the float width is at most `2^-bits / 2` (the exact
/// width is then below `2^-bits`). The ends are exact floats, so the result
/// is the same proof as [`bisect`]'s, without rational midpoints.
pub(crate) fn bisect_f64(
    sf: &Poly<Rational>,
    sf_iv: &Poly<Interval>,
    (mut a, mut b): (f64, f64),
    bits: u32,
) -> Option<RealRoot> {
    let exact = |x: f64| rational_from_f64(x);
    // the exact sign by integers: the numerators over a common denominator
    // (computed once, on the first point the enclosure leaves undecided)
    let mut ints: Option<Vec<num_bigint::BigInt>> = None;
    let mut sign = |x: f64| -> Option<i8> {
        let e = sf_iv.eval(&Interval::try_from((x, x)).ok()?);
        if e.inf() > 0.0 {
            return Some(1);
        }
        if e.sup() < 0.0 {
            return Some(-1);
        }
        let n = ints.get_or_insert_with(|| common_numerators(sf));
        dyadic_sign(n, x)
    };
    let sa = sign(a)?;
    if sa == 0 || sign(b)? == sa {
        return None;
    }
    let w = 0.5 * 2f64.powi(-(bits as i32));
    while b - a > w {
        let m = 0.5 * a + 0.5 * b;
        if !(a < m && m < b) {
            break;
        }
        let sm = sign(m)?;
        if sm == 0 {
            let e = exact(m)?;
            return Some(RealRoot {
                lo: e.clone(),
                hi: e,
            });
        }
        if sm == sa {
            a = m;
        } else {
            b = m;
        }
    }
    Some(RealRoot {
        lo: exact(a)?,
        hi: exact(b)?,
    })
}

/// The numerators of `p`'s coefficients over their least common denominator
/// (positive), so that `p` and `Σ nᵢ xⁱ` have the same signs.
fn common_numerators(p: &Poly<Rational>) -> Vec<num_bigint::BigInt> {
    let l = p.coeffs().iter().fold(num_bigint::BigInt::from(1), |l, c| {
        num_integer::Integer::lcm(&l, c.denom())
    });
    p.coeffs()
        .iter()
        .map(|c| c.numer() * (&l / c.denom()))
        .collect()
}

/// The exact sign of `Σ nᵢ xⁱ` at the finite float `x ≥ 0`, in integers:
/// with `x = k/2^s`, `2^{s·deg} Σ nᵢ xⁱ = Σ nᵢ kⁱ 2^{s(deg − i)}` by Horner
/// (no rational arithmetic).
fn dyadic_sign(n: &[num_bigint::BigInt], x: f64) -> Option<i8> {
    use num_bigint::{BigInt, Sign};
    if !(x.is_finite() && x >= 0.0) {
        return None;
    }
    // x = m·2^e = k/2^s
    let (m, e) = crate::scalar::float_parts(x);
    let (k, s) = if e >= 0 {
        (BigInt::from(m) << e as usize, 0usize)
    } else {
        (BigInt::from(m), (-e) as usize)
    };
    let mut acc = BigInt::from(0);
    for (j, c) in n.iter().rev().enumerate() {
        acc = acc * &k + (c << (s * j));
    }
    Some(match acc.sign() {
        Sign::Plus => 1,
        Sign::Minus => -1,
        Sign::NoSign => 0,
    })
}

/// The roots of `p` in `span`, exactly isolated, refined to width `2^-bits`.
pub(crate) fn roots_refined(p: &Poly<Rational>, span: &Span, bits: u32) -> Vec<RealRoot> {
    if is_zero_poly(p) || no_root_in_unit(p) {
        return Vec::new();
    }
    // Simple roots isolated by interval Bernstein subdivision (Descartes' rule)
    // before the exact Sturm path: proven isolating intervals with ends that are
    // not roots, so `[0, 1]` and `(0, 1)` hold the same roots. Exact bisection
    // then refines each (a sign change of `p` itself: the root is simple).
    let unit = span.lo.is_zero() && span.hi == Rational::from_integer(1.into());
    if unit && p.coeffs().len() <= 61 {
        let pi = p.map(interval_from_rational);
        if let Some(pieces) = isolate_simple_roots(&pi, 0.0, 1.0, 2_000) {
            let exact = |x: f64| rational_from_f64(x).expect("finite dyadic");
            return pieces
                .into_iter()
                .map(|(a, b)| {
                    bisect_f64(p, &pi, (a, b), bits).unwrap_or_else(|| {
                        bisect(
                            p,
                            &RealRoot {
                                lo: exact(a),
                                hi: exact(b),
                            },
                            bits,
                        )
                    })
                })
                .collect();
        }
    }
    let sf = square_free(p);
    isolate_roots(&sf, span)
        .iter()
        .map(|r| {
            if r.is_exact() {
                r.clone()
            } else {
                bisect(&sf, r, bits)
            }
        })
        .collect()
}

/// A filter before the exact isolation: `true` when interval Bernstein bounds
/// (outward-rounded enclosures of `p`'s coefficients, [`certify_no_root`]) prove
/// that `p` has no root in `[0, 1]`. Exact root isolation of the cusp polynomial
/// (degree 12 for a cubic, coefficients of hundreds of digits for B-spline
/// input) cost 25 ms per piece; most pieces have no cusp, and this decides that
/// in microseconds. `false` only means "undecided here": the exact path runs.
fn no_root_in_unit(p: &Poly<Rational>) -> bool {
    let pi = p.map(interval_from_rational);
    certify_no_root(&pi, 0.0, 1.0) == Some(true)
}

/// Float midpoints of the roots of `p` in `(0, 1)`, refined to width `2⁻³⁰`
/// (exact isolation; the float split point is a heuristic choice).
fn roots_in_unit(p: &Poly<Rational>) -> Vec<f64> {
    let span = Span::open(Rational::zero(), Rational::from_integer(1.into()));
    roots_refined(p, &span, 30)
        .iter()
        .map(|r| crate::scalar::Scalar::approx(&r.midpoint()))
        .filter(|t| *t > 0.0 && *t < 1.0)
        .collect()
}

/// The inflection parameters of a piece in `(0, 1)` (sign changes of `x′ × x″`),
/// rounded to multiples of `2⁻²⁴`.
pub fn inflections(x: &Bezier<Rational>) -> Vec<f64> {
    let mut v: Vec<f64> = roots_in_unit(&curvature_numerator(x))
        .into_iter()
        .map(|t| (t * 16777216.0).round() / 16777216.0)
        .filter(|t| *t > 0.0 && *t < 1.0)
        .collect();
    v.dedup();
    v
}

/// Largest spread of the hodograph's control points (an enclosure of the
/// tangent directions) accepted for one span: `0.9 π`. Seed 004 Prop 3.1 needs
/// the Gauss map shorter than π; the margin keeps eq. (3.4) well conditioned.
pub const MAX_TURN: f64 = 0.9 * std::f64::consts::PI;

/// True when the hodograph's control points lie in a cone of opening below
/// [`MAX_TURN`] (so the span's tangent turns by less than that).
pub fn gauss_map_short(x: &Bezier<f64>) -> bool {
    let h = x.hodograph();
    let p = h.points();
    let Some(first) = p.iter().find(|v| v.norm2() > 0.0) else {
        return false;
    };
    let (mut lo, mut hi) = (0.0f64, 0.0f64);
    for v in p {
        if v.norm2() == 0.0 {
            continue;
        }
        let a = first.cross(v).atan2(first.dot(v));
        lo = lo.min(a);
        hi = hi.max(a);
    }
    hi - lo < MAX_TURN
}

/// The exact point of piece `x` at the float parameter `t`.
pub fn point_at(x: &Bezier<Rational>, t: f64) -> V2<Rational> {
    x.eval(&rational_from_f64(t).unwrap_or_else(Rational::zero))
}

/// The canonical unit **left** normal of piece `x` at `t` (a construction
/// input, never part of a proof): the derivative in floats, by de Casteljau
/// on the rounded control points, where it stands well above its rounding
/// error, else the exact derivative rounded to floats; normalised in floats.
/// At the piece's ends (`t` = 0 or 1) always the exact end derivative
/// `n·(p₁ − p₀)` or `n·(pₙ − pₙ₋₁)` rounded to floats.
///
/// Neighbouring segments of one piece call this with the same arguments, so
/// they share the normal bit for bit; and two pieces meeting with equal
/// derivatives (a C¹ junction: B-spline pieces, TrueType's implied on-curve
/// points) get the same normal from either side, so their offsets meet at one
/// float point and the output stays one connected run.
pub fn unit_left_normal(x: &Bezier<Rational>, t: f64) -> Option<V2<f64>> {
    let exact = || -> Option<V2<f64>> {
        let p = x.points();
        let n = p.len().checked_sub(1).filter(|&n| n > 0)?;
        let diff = if t == 0.0 {
            p[1].sub(&p[0])
        } else if t == 1.0 {
            p[n].sub(&p[n - 1])
        } else {
            return Some(
                x.hodograph()
                    .eval(&rational_from_f64(t)?)
                    .map(crate::scalar::Scalar::approx),
            );
        };
        let n = Rational::from_integer((n as i64).into());
        Some(diff.scale(&n).map(crate::scalar::Scalar::approx))
    };
    let d = if t == 0.0 || t == 1.0 {
        exact()?
    } else {
        derivative_f64(x, t).map_or_else(exact, Some)?
    };
    let l = d.norm2().sqrt();
    if !(l > 0.0 && l.is_finite()) {
        // rescale huge or tiny derivatives before normalising
        let m = d.x.abs().max(d.y.abs());
        if !(m > 0.0 && m.is_finite()) {
            return None;
        }
        let (x, y) = (d.x / m, d.y / m);
        let l = (x * x + y * y).sqrt();
        return Some(V2::new(-y / l, x / l));
    }
    Some(V2::new(-d.y / l, d.x / l))
}

/// The derivative of `x` at `t` in floats (de Casteljau on the differences
/// of the rounded control points), when the points are within the normal
/// float range (`2⁻⁹⁰⁰ ≤ max|pᵢ| ≤ 2⁹⁰⁰`) and it is at least `2²⁰` times a
/// bound of its rounding error (`n·2⁻⁵⁰·max|pᵢ|` covers the rounding of the
/// points and of the arithmetic); `None` otherwise (the caller computes it
/// exactly).
fn derivative_f64(x: &Bezier<Rational>, t: f64) -> Option<V2<f64>> {
    let xf = x.map(crate::scalar::Scalar::approx);
    let n = xf.degree();
    if n == 0 {
        return None;
    }
    let d = xf.hodograph().eval_fast(t);
    let mag = xf
        .points()
        .iter()
        .map(|q| q.x.abs().max(q.y.abs()))
        .fold(0.0, f64::max);
    let err = (n * n) as f64 * mag * 2f64.powi(-50);
    let size = d.x.abs().max(d.y.abs());
    // rounding saturates beyond the float range and loses relative precision
    // below its normal range: such pieces take the exact path
    let normal_range = (2f64.powi(-900)..=2f64.powi(900)).contains(&mag);
    (normal_range && d.is_finite() && size > err * 2f64.powi(20)).then(|| V2::new(d.x, d.y))
}

/// A cusp of the exact offset `x + d N` (left normal): a parameter where the
/// signed curvature is `κ = 1/d`, i.e. `d (x′ × x″) = |x′|³`.
#[derive(Clone, Debug, PartialEq)]
pub struct OffsetCusp {
    /// Index of the input piece.
    pub piece: usize,
    /// An exact isolating interval of the cusp parameter (width ≤ 2⁻⁴⁰).
    pub t: (Rational, Rational),
    /// Float approximation of the parameter.
    pub t_approx: f64,
    /// The cusp point of the exact offset, approximately.
    pub point: (f64, f64),
}

/// The cusps of the exact offset at signed distance `d` (left normal) of piece
/// `x`, decided exactly: the roots in `[0, 1]` of `d²(x′×x″)² − (x′·x′)³` at
/// which `d (x′ × x″) > 0` (Sturm isolation; the sign is decided on an
/// isolating interval on which `x′ × x″` has no root, checked by Sturm).
pub fn offset_cusps(piece: usize, x: &Bezier<Rational>, d: &Rational) -> Vec<OffsetCusp> {
    use super::cuspform::{cusp_params, offset_form, offset_form_iv};
    // at a root of `p`, |d (x′×x″)| = |x′|³ > 0: the side is the sign of d·k
    let side = if d.is_positive() { 1 } else { -1 };
    let roots = cusp_params(
        x,
        offset_form_iv(x, d),
        || offset_form(x, d),
        side,
        || cusp_polynomial(x, &curvature_numerator(x), d),
    );
    let df = crate::scalar::Scalar::approx(d);
    roots
        .into_iter()
        .map(|r| {
            let m = r.midpoint();
            let ta = crate::scalar::Scalar::approx(&m);
            let pt = x.eval(&m);
            let n = unit_left_normal(x, ta).unwrap_or(V2::new(0.0, 0.0));
            OffsetCusp {
                piece,
                t: (r.lo, r.hi),
                t_approx: ta,
                point: (
                    crate::scalar::Scalar::approx(&pt.x) + df * n.x,
                    crate::scalar::Scalar::approx(&pt.y) + df * n.y,
                ),
            }
        })
        .collect()
}

/// What happens at the junction of two consecutive input pieces.
// One value per junction of the input (never in bulk), matched by field in
// several layers: boxing the exact join data would buy nothing.
#[allow(clippy::large_enum_variant)]
#[derive(Clone, Debug, PartialEq)]
pub enum Junction {
    /// The pieces do not meet (`end ≠ start`): separate components.
    Gap,
    /// Tangent-continuous (G¹): the offsets meet.
    Smooth,
    /// A G⁰ corner whose offset leaves a gap: closed by a join arc of radius
    /// `|d|` about the corner, from the end normal of the first piece to the start
    /// normal of the second (directions exact, not normalised).
    Join {
        /// The corner point (end of the first piece, start of the second).
        center: V2<Rational>,
        /// Start direction of the arc: the first piece's end normal on the
        /// offset side (not normalised).
        from: V2<Rational>,
        /// End direction of the arc: the second piece's start normal on the
        /// offset side (not normalised).
        to: V2<Rational>,
        /// The arc turns clockwise from `from` to `to`.
        clockwise: bool,
    },
    /// A G⁰ corner on the inner side: the two offsets cross and must be trimmed.
    Overlap {
        /// The corner point (end of the first piece, start of the second).
        center: V2<Rational>,
    },
}

/// Classifies the junction between `a` (its end) and `b` (its start) for the
/// signed distance `d`, exactly.
pub fn junction(a: &Bezier<Rational>, b: &Bezier<Rational>, d: &Rational) -> Junction {
    let pa = a.points();
    let end = pa[pa.len() - 1].clone();
    if end != b.points()[0] {
        return Junction::Gap;
    }
    let [_, ta] = a.end_derivatives();
    let [tb, _] = b.end_derivatives();
    let cross = ta.cross(&tb);
    let dot = ta.dot(&tb);
    if cross.is_zero() && dot.is_positive() {
        return Junction::Smooth;
    }
    // Normals sweep by the turn of the tangent; the offset side gets a gap when
    // the curve turns away from it: d > 0 (left) and a right turn, or d < 0 and
    // a left turn. A reversal (cross = 0, dot < 0) opens a half circle.
    let left_turn = cross.is_positive();
    let gap = if cross.is_zero() {
        true
    } else {
        d.is_positive() != left_turn
    };
    if !gap {
        return Junction::Overlap { center: end };
    }
    let sgn = if d.is_positive() {
        Rational::from_integer(1.into())
    } else {
        Rational::from_integer((-1).into())
    };
    let from = ta.rot90().scale(&sgn);
    let to = tb.rot90().scale(&sgn);
    // the normals turn like the tangents: clockwise when the curve turns right;
    // a reversal: the arc goes round the far side of the offset.
    let clockwise = if cross.is_zero() {
        d.is_positive()
    } else {
        !left_turn
    };
    Junction::Join {
        center: end,
        from,
        to,
        clockwise,
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use proptest::prelude::*;

    proptest! {
        #![proptest_config(ProptestConfig::with_cases(256))]

        /// The float derivative, where it is used, is within a relative
        /// `2⁻³⁰` of the exact derivative rounded to floats, so the normal
        /// is the exact one's to within ~1e-9 rad.
        #[test]
        fn the_float_derivative_matches_the_exact_one(
            p in proptest::collection::vec((-1000i64..=1000, -1000i64..=1000), 2..=5),
            den in 1i64..=1024,
            t in 0.0f64..=1.0,
        ) {
            let b = Bezier::new(
                p.iter()
                    .map(|&(x, y)| V2::new(Rational::new(x.into(), den.into()), Rational::new(y.into(), den.into())))
                    .collect(),
            );
            let exact = b
                .hodograph()
                .eval(&rational_from_f64(t).unwrap())
                .map(crate::scalar::Scalar::approx);
            if let Some(d) = derivative_f64(&b, t) {
                let size = exact.x.abs().max(exact.y.abs());
                prop_assert!(size > 0.0);
                prop_assert!((d.x - exact.x).abs() <= size * 2f64.powi(-30));
                prop_assert!((d.y - exact.y).abs() <= size * 2f64.powi(-30));
            }
        }
    }

    proptest! {
        /// Two pieces meeting with equal derivatives (any degrees, control
        /// points with non-dyadic coordinates) get the same canonical normal
        /// from either side, bit for bit (before, the float derivatives of
        /// the two sides' rounded points differed in the last bits, and the
        /// offset of a B-spline broke into runs at its knots).
        #[test]
        fn a_c1_junction_has_one_normal(
            p in proptest::collection::vec((-1000i64..=1000, -1000i64..=1000), 2..=5),
            q in proptest::collection::vec((-1000i64..=1000, -1000i64..=1000), 0..=3),
            den in 1i64..=1024,
        ) {
            let r = |v: i64| Rational::new(v.into(), (3 * den).into());
            let pts: Vec<V2<Rational>> = p.iter().map(|&(x, y)| V2::new(r(x), r(y))).collect();
            let (n, m) = (pts.len() - 1, q.len() + 1);
            let end = pts[n].clone();
            let step = end.sub(&pts[n - 1]);
            prop_assume!(!step.x.is_zero() || !step.y.is_zero());
            // q₁ = q₀ + (n/m)(pₙ − pₙ₋₁): equal derivatives at the junction
            let k = Rational::new((n as i64).into(), (m as i64).into());
            let mut next = vec![end.clone(), end.add(&step.scale(&k))];
            next.extend(q.iter().map(|&(x, y)| V2::new(r(x), r(y))));
            let (a, b) = (Bezier::new(pts), Bezier::new(next));
            prop_assert_eq!(unit_left_normal(&a, 1.0), unit_left_normal(&b, 0.0));
            prop_assert!(unit_left_normal(&a, 1.0).is_some());
        }
    }

    proptest! {
        #![proptest_config(ProptestConfig::with_cases(128))]

        /// Refined roots of a product of known simple factors: one interval
        /// per root in `[0, 1]`, each of width at most `2⁻⁴⁰` and holding
        /// exactly that root (checked against the known roots, not by the
        /// code under test).
        #[test]
        fn refined_roots_hold_the_known_roots(
            roots in proptest::collection::btree_set(1i64..1000, 1..6),
            outside in proptest::collection::vec(1i64..3000, 0..3),
            den in 1i64..4,
        ) {
            let den = den * 1000;
            let q = |n: i64| Rational::new(n.into(), den.into());
            let known: Vec<Rational> = roots.iter().map(|&n| q(n)).collect();
            let mut p = Poly::new(vec![Rational::from_integer(1.into())]);
            // roots beyond 1 (and their factors) must not be reported
            for r in known.iter().cloned().chain(outside.iter().map(|&n| q(n + den))) {
                p = p.mul(&Poly::new(vec![-r, Rational::from_integer(1.into())]));
            }
            let span = Span::closed(Rational::zero(), Rational::from_integer(1.into()));
            let found = roots_refined(&p, &span, 40);
            let known: Vec<&Rational> = known.iter().collect();
            prop_assert_eq!(found.len(), known.len());
            let w = Rational::new(1.into(), num_bigint::BigInt::from(1u64 << 40));
            for (f, k) in found.iter().zip(&known) {
                prop_assert!(&f.hi - &f.lo <= w);
                prop_assert!(f.lo <= **k && **k <= f.hi, "{:?} misses {}", f, k);
            }
        }
    }

    proptest! {
        #![proptest_config(ProptestConfig::with_cases(256))]

        /// The integer sign at a float is the sign of the exact rational
        /// evaluation, zeros included (a dyadic root of the polynomial).
        #[test]
        fn the_integer_sign_matches_the_rational_evaluation(
            c in proptest::collection::vec((-1000i64..=1000, 1i64..=999), 1..8),
            x in 0.0f64..=1.0,
            root_at_x in any::<bool>(),
        ) {
            let mut p = Poly::new(c.iter().map(|&(n, d)| Rational::new(n.into(), d.into())).collect());
            let xr = rational_from_f64(x).unwrap();
            if root_at_x {
                p = p.mul(&Poly::new(vec![-xr.clone(), Rational::from_integer(1.into())]));
            }
            let v = p.eval(&xr);
            let expect = if v.is_zero() { 0 } else if v.is_positive() { 1 } else { -1 };
            prop_assert_eq!(dyadic_sign(&common_numerators(&p), x), Some(expect));
        }
    }

    #[test]
    fn a_vanishing_or_huge_derivative_is_left_to_the_exact_path() {
        let q = |x: i64, y: i64| {
            V2::new(
                Rational::from_integer(x.into()),
                Rational::from_integer(y.into()),
            )
        };
        // x′(1/2) = 0 (a cusp): the float value is below its error bound
        let cusp = Bezier::new(vec![q(0, 0), q(1, 1), q(0, 1), q(1, 0)]);
        assert!(derivative_f64(&cusp, 0.5).is_none());
        assert!(unit_left_normal(&cusp, 0.5).is_none());
        // coordinates beyond f64: no float value at all
        let big = Rational::from_integer(num_bigint::BigInt::from(10).pow(400));
        let huge = Bezier::new(vec![q(0, 0), V2::new(big.clone(), big)]);
        assert!(derivative_f64(&huge, 0.5).is_none());
        // an ordinary one: the left normal of a line to the right is up
        let line = Bezier::new(vec![q(0, 0), q(2, 0)]);
        assert_eq!(unit_left_normal(&line, 0.25), Some(V2::new(-0.0, 1.0)));
    }
}
