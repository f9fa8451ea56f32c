//! Independent decisions by exact root isolation (Sturm sequences over Q).
//!
//! These are the ground truth the propositions are tested against: they look at
//! the curve itself (its hodograph or `f''`), never at a proposition's formula.

use crate::curve::Bezier;
use crate::poly::{has_common_root_in, has_root_in, isolate_roots, poly_gcd, Poly, RealRoot, Span};
use crate::scalar::Rational;

/// Where a Bézier curve is singular: the common real roots of `x'(t)` and
/// `y'(t)` in `span` (isolating intervals of the roots of `gcd(x', y')`).
/// `None` when the hodograph is identically zero (every point is singular).
///
/// # Examples
/// ```
/// use lncert::curve::{Bezier, V2};
/// use lncert::ln::direct::singular_points;
/// use lncert::poly::Span;
/// use lncert::scalar::{frac, Rational};
/// let p = |x: i64, y: i64| V2::<Rational>::new(frac(x, 1), frac(y, 1));
/// // Seed 000 eq. (1) with τ = 1/2 on the frame (0,0), (1,1), (2,0): δ0 = δ1 = 2.
/// let c = Bezier::new(vec![p(0, 0), p(2, 2), p(0, 2), p(2, 0)]);
/// let roots = singular_points(&c, &Span::unit_closed()).unwrap();
/// assert_eq!(roots.len(), 1);
/// let half: Rational = frac(1, 2);
/// assert!(roots[0].lo <= half && half <= roots[0].hi);
/// ```
pub fn singular_points(curve: &Bezier<Rational>, span: &Span) -> Option<Vec<RealRoot>> {
    let (x, y) = curve.hodograph().power_coords();
    let g = poly_gcd(&x, &y);
    // no degree: the gcd is zero, the hodograph vanishes identically
    g.clone().trimmed().degree()?;
    Some(isolate_roots(&g, span))
}

/// `true` iff the curve is regular on `span` (its hodograph has no zero there).
pub fn is_regular_on(curve: &Bezier<Rational>, span: &Span) -> bool {
    let (x, y) = curve.hodograph().power_coords();
    !has_common_root_in(&x, &y, span)
}

/// `true` iff `p` has no real root in `span` (e.g. `f''` of a normal-form curve:
/// `K'(t) = f''(t) [-1, t]`).
pub fn has_no_root_on(p: &Poly<Rational>, span: &Span) -> bool {
    !has_root_in(p, span)
}

/// A normal-form curve `K = [-f', -f + t f']` is regular on `[0, u]` iff `f''`
/// has no root there.
pub fn normal_form_regular(f: &Poly<Rational>, u: &Rational) -> bool {
    let f2 = f.derivative().derivative();
    has_no_root_on(
        &f2,
        &Span::closed(Rational::from_integer(0.into()), u.clone()),
    )
}
