//! Exact oracle for the circle-tangency system (independent of the interval
//! solver; the tests' ground truth, also usable as a backend).
//!
//! Eq. (7) is linear in `a2` (the curve `K` is linear in `a2`):
//! `A(m) a2 + B(m) = 0`, and eq. (6) is quadratic: `C2 a2² + C1 a2 + C0 = 0`.
//! Where `A(m) ≠ 0`, `a2 = -B(m)/A(m)`, and eq. (6)·`A²` becomes the univariate
//! **eliminant** `R(m) = C2 B² - C1 A B + C0 A²` (formal degree 18, degree 14
//! on generic data, see [`eliminant_prime_part`]). Hence:
//!
//! * the solutions with `A(m) ≠ 0` are exactly `(m, -B(m)/A(m))` for the real
//!   roots `m` of `R̃`, the part of `R` prime to `A` (`R` divided by `gcd(R, A)`
//!   until the gcd is constant), isolated exactly by Sturm sequences on `[0, u]`;
//!   distinct `m` give distinct solutions;
//! * the solutions with `A(m) = 0` need `B(m) = 0`: roots of `gcd(A, B)`. At
//!   `m = 0` and `m = u` (always roots of `A`: the `a2`-part of `f` is
//!   `t²(u-t)²/u²`) the system does not depend on `a2`: no solution or a
//!   whole line ([`TangencySystem::solution_lines`]). At a rational root `m0`
//!   in `(0, u)`, eq. (6) is a quadratic in `a2` solved exactly; irrational
//!   common roots are reported as unhandled (`degenerate`).
//!
//! The `a2`-window test `lo ≤ -B/A ≤ hi` is decided exactly: the sign of a
//! polynomial at an algebraic root is read off after refining the isolating
//! interval until the polynomial has no root in it (or shares the root).

use super::system::{SolutionLine, TangencySystem};
use crate::poly::{
    count_distinct_roots, div_rem, has_common_root_in, isolate_roots, poly_gcd, refine_root,
    square_free, Poly, RealRoot, RootCount, Span,
};
use crate::scalar::{interval_from_rational, Interval, Rational, Scalar, Sign};
use num_traits::{One, Zero};

/// One exact solution `(m, a2)` of the system.
#[derive(Clone, Debug)]
pub struct OracleRoot {
    /// Isolating interval of `m` (exact when `lo == hi`), a root of `defining`.
    pub m: RealRoot,
    /// The square-free polynomial whose root `m` is.
    pub defining: Poly<Rational>,
    /// Enclosure of `m` (refined, outward rounded).
    pub m_enclosure: Interval,
    /// Enclosure of `a2`.
    pub a2: Interval,
    /// `a2` exactly, when it is rational and known.
    pub a2_exact: Option<Rational>,
}

/// All real solutions with `m ∈ [0, u]` and `a2` in the window.
#[derive(Clone, Debug, Default)]
pub struct OracleSolution {
    /// Isolated solutions, sorted by `m`.
    pub roots: Vec<OracleRoot>,
    /// Lines of solutions (`m = 0` or `m = u`, every `a2`).
    pub lines: Vec<SolutionLine>,
    /// Irrational common roots of `A` and `B` in `(0, u)` (not handled: the
    /// solutions there are not reported; the answer is then incomplete).
    pub degenerate: Vec<RealRoot>,
    /// True when the eliminant vanishes identically (not handled).
    pub eliminant_vanishes: bool,
}

impl OracleSolution {
    /// True when every solution is reported as an isolated root.
    pub fn complete(&self) -> bool {
        self.lines.is_empty() && self.degenerate.is_empty() && !self.eliminant_vanishes
    }
}

/// `R(m) = C2 B² - C1 A B + C0 A²`, the eliminant of `a2`.
pub fn eliminant(sys: &TangencySystem) -> Poly<Rational> {
    let (a, b) = sys.eq7_linear();
    let (c2, c1, c0) = sys.eq6_quadratic();
    c2.mul(&b.mul(&b))
        .sub(&c1.mul(&a.mul(&b)))
        .add(&c0.mul(&a.mul(&a)))
        .trimmed()
}

/// `R̃`: the eliminant with every factor shared with `A` removed; its roots
/// are exactly the `m` of the solutions with `A(m) ≠ 0`. On generic data
/// (`tests/tangency.rs::eliminant_degrees`) `deg R = 14` (formal degree 18)
/// with the factor `m²(u - m)²`, and `deg R̃ = 10`: at most 10 solutions with
/// `A(m) ≠ 0`, a much sharper bound than Bézout's 60.
pub fn eliminant_prime_part(sys: &TangencySystem) -> Poly<Rational> {
    prime_part(&eliminant(sys), &sys.eq7_linear().0)
}

fn degree(p: &Poly<Rational>) -> Option<usize> {
    p.clone().trimmed().degree()
}

/// `p` with every factor it shares with `a` removed.
fn prime_part(p: &Poly<Rational>, a: &Poly<Rational>) -> Poly<Rational> {
    let mut p = p.clone().trimmed();
    for _ in 0..64 {
        let g = poly_gcd(&p, a);
        if degree(&g).unwrap_or(0) == 0 {
            break;
        }
        match div_rem(&p, &g) {
            Some((q, _)) => p = q,
            None => break,
        }
    }
    p
}

/// The exact sign of `p` at the root of the square-free `def` isolated by
/// `root` (`Unknown` only if the refinement budget runs out).
pub fn sign_at_root(p: &Poly<Rational>, def: &Poly<Rational>, root: &RealRoot) -> Sign {
    if root.is_exact() {
        return p.eval(&root.lo).sign();
    }
    let span = |r: &RealRoot| Span::closed(r.lo.clone(), r.hi.clone());
    if has_common_root_in(p, def, &span(root)) {
        return Sign::Zero;
    }
    let mut r = root.clone();
    for _ in 0..400 {
        if r.is_exact() {
            return p.eval(&r.lo).sign();
        }
        if count_distinct_roots(p, &span(&r)) == RootCount::Finite(0) {
            return p.eval(&r.midpoint()).sign();
        }
        let w = r.width() / Rational::from_integer(4.into());
        r = refine_root(def, &r, &w);
    }
    Sign::Unknown
}

/// Encloses `m` and `a2 = -B(m)/A(m)` by refining the isolating interval
/// until the interval value of `A` excludes 0 and the widths are at f64 level.
fn enclose_root(
    a: &Poly<Rational>,
    b: &Poly<Rational>,
    def: &Poly<Rational>,
    root: &RealRoot,
) -> (RealRoot, Interval, Interval) {
    let ai = a.map(interval_from_rational);
    let bi = b.map(interval_from_rational);
    let mut r = root.clone();
    let mut width = Rational::new(1.into(), num_bigint::BigInt::from(1u64 << 62));
    for _ in 0..8 {
        r = refine_root(def, &r, &width);
        let m = interval_from_rational(&r.lo).convex_hull(interval_from_rational(&r.hi));
        if let Some(a2) = (-bi.eval(&m)).div(&ai.eval(&m)) {
            if a2.wid() <= 1e-9 * (1.0 + a2.mag()) || r.is_exact() {
                return (r, m, a2);
            }
        }
        width = &width * Rational::new(1.into(), num_bigint::BigInt::from(1u64 << 40));
    }
    let m = interval_from_rational(&r.lo).convex_hull(interval_from_rational(&r.hi));
    let a2 = (-bi.eval(&m)).div(&ai.eval(&m)).unwrap_or(Interval::ENTIRE);
    (r, m, a2)
}

/// All real solutions of eq. (6), (7) with `m ∈ [0, u]` and
/// `a2 ∈ [a2_lo, a2_hi]`, exactly (see the module docs).
///
/// # Examples
/// ```
/// use lncert::tangency::{exact_solutions, TangencySystem};
/// use lncert::scalar::frac;
/// let s = TangencySystem::new(frac(3, 1), frac(-1, 1), frac(1, 1), frac(1, 1), frac(1, 1), frac(1, 2)).unwrap();
/// let sol = exact_solutions(&s, &(frac(-100, 1), frac(100, 1)));
/// assert!(sol.complete());
/// for r in &sol.roots {
///     assert!(r.m_enclosure.inf() >= 0.0 && r.m_enclosure.sup() <= 1.0);
/// }
/// ```
pub fn exact_solutions(sys: &TangencySystem, a2_window: &(Rational, Rational)) -> OracleSolution {
    let mut out = OracleSolution {
        lines: sys.solution_lines(),
        ..OracleSolution::default()
    };
    let (a, b) = sys.eq7_linear();
    let u = sys.u().clone();
    let zero = <Rational as Zero>::zero();
    let (lo, hi) = a2_window;
    let r = eliminant(sys);
    if r.coeffs().is_empty() {
        out.eliminant_vanishes = true;
        return out;
    }
    let rt = square_free(&prime_part(&r, &a));
    // a2 - lo = (-B - lo A)/A, a2 - hi = (-B - hi A)/A.
    let p_lo = b.neg().sub(&a.scale(lo));
    let p_hi = b.neg().sub(&a.scale(hi));
    for root in isolate_roots(&rt, &Span::closed(zero.clone(), u.clone())) {
        let sa = sign_at_root(&a, &rt, &root);
        let s_lo = sign_at_root(&p_lo, &rt, &root) * sa;
        let s_hi = sign_at_root(&p_hi, &rt, &root) * sa;
        let inside = |s: Sign, want: Sign| s == want || s == Sign::Zero;
        if s_lo == Sign::Unknown || s_hi == Sign::Unknown {
            out.degenerate.push(root);
            continue;
        }
        if !(inside(s_lo, Sign::Positive) && inside(s_hi, Sign::Negative)) {
            continue;
        }
        let (mr, m, a2) = enclose_root(&a, &b, &rt, &root);
        let a2_exact = mr.is_exact().then(|| (-b.eval(&mr.lo)) / a.eval(&mr.lo));
        out.roots.push(OracleRoot {
            m: mr,
            defining: rt.clone(),
            m_enclosure: m,
            a2,
            a2_exact,
        });
    }
    // Common roots of A and B strictly inside (0, u).
    let g = square_free(&poly_gcd(&a, &b));
    if degree(&g).unwrap_or(0) > 0 {
        for root in isolate_roots(&g, &Span::open(zero, u)) {
            if !root.is_exact() {
                out.degenerate.push(root);
                continue;
            }
            let m0 = root.lo.clone();
            let q = sys.eq6.at_x(&m0).trimmed();
            if q.coeffs().is_empty() {
                out.lines.push(SolutionLine { m: m0 });
                continue;
            }
            let qs = square_free(&q);
            for ar in isolate_roots(&qs, &Span::closed(lo.clone(), hi.clone())) {
                let ar2 = refine_root(
                    &qs,
                    &ar,
                    &Rational::new(One::one(), num_bigint::BigInt::from(1u64 << 62)),
                );
                let a2 =
                    interval_from_rational(&ar2.lo).convex_hull(interval_from_rational(&ar2.hi));
                out.roots.push(OracleRoot {
                    m: root.clone(),
                    defining: g.clone(),
                    m_enclosure: interval_from_rational(&m0),
                    a2,
                    a2_exact: ar2.is_exact().then(|| ar2.lo.clone()),
                });
            }
        }
    }
    out.roots
        .sort_by(|x, y| x.m_enclosure.inf().total_cmp(&y.m_enclosure.inf()));
    out
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::test_util::qi as q;

    #[test]
    fn a_has_roots_at_both_ends_and_one_inside() {
        let s = TangencySystem::new(q(3, 1), q(-1, 1), q(1, 1), q(1, 1), q(1, 1), q(1, 2)).unwrap();
        let (a, _) = s.eq7_linear();
        assert_eq!(a.eval(&q(0, 1)), q(0, 1));
        assert_eq!(a.eval(&q(1, 1)), q(0, 1));
        let inner = isolate_roots(&square_free(&a), &Span::open(q(0, 1), q(1, 1)));
        assert_eq!(inner.len(), 1);
    }

    #[test]
    fn planted_root_is_found() {
        // K(m0) for a2_0, then O on the normal line at distance |r|.
        let (x1, y1, u) = (q(3, 1), q(-1, 1), q(1, 1));
        let h = crate::ln::hermite::HermiteData::new(x1.clone(), y1.clone(), u.clone()).unwrap();
        let (xp, yp) = super::super::system::curve_polys(&h);
        let (m0, a20) = (q(1, 3), q(2, 1));
        let (kx, ky) = (xp.eval(&m0, &a20), yp.eval(&m0, &a20));
        // r = 1/2 along (m0, 1)/|(m0,1)|: use t with O = K + t (m0, 1), r² = t²(1+m0²).
        let t = q(3, 4);
        let ox = &kx + &t * &m0;
        let oy = &ky + &t;
        let r2 = &t * &t * (q(1, 1) + &m0 * &m0); // 10/9 * 9/16 = 5/8, r irrational...
                                                  // choose r rational instead: pick m0 = 3/4 so 1 + m0² = 25/16.
        let _ = (ox, oy, r2);
        let m0 = q(3, 4);
        let (kx, ky) = (xp.eval(&m0, &a20), yp.eval(&m0, &a20));
        let ox = &kx + &t * &m0;
        let oy = &ky + &t;
        let r = &t * q(5, 4);
        let s = TangencySystem::new(x1, y1, u, ox, oy, r).unwrap();
        let sol = exact_solutions(&s, &(q(-50, 1), q(50, 1)));
        assert!(sol.complete());
        let hit = sol
            .roots
            .iter()
            .filter(|r| r.m.lo <= m0 && m0 <= r.m.hi)
            .count();
        assert_eq!(hit, 1, "{sol:?}");
        assert!(sol.roots.iter().any(|r| r.a2.contains(2.0)));
    }
}
