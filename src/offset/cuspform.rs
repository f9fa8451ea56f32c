//! The cusp polynomials of offsets and convolutions of one Bézier piece in
//! the scaled Bernstein basis ([`crate::poly::scaled`]), built from the
//! control points without the power basis: in intervals (a filter that
//! decides most pieces, which have no cusp) and in exact integers (no
//! rational arithmetic, no gcds).
//!
//! For `x` of degree `n ≥ 2` with control points `x_i = X_i / D` (`D > 0`
//! the least common denominator), let `U_i = X_{i+1} − X_i` and
//! `V_i = U_{i+1} − U_i` (Bernstein coefficients of degree `n − 1`, `n − 2`):
//! `x′ = (n/D) U`, `x″ = (n(n−1)/D) V`, so `k = x′ × x″ = n²(n−1)/D² · U × V`.
//! With the quadratic form `w(v) = a v_y² − 2b v_x v_y + c v_x²`:
//!
//! * offset at `d = p/q`: `d² k² − |x′|⁶ = (q² D⁶ / n⁴)⁻¹ ·
//!   [p² (n−1)² D² (U×V)² − n² q² |U|⁶]`;
//! * convolution with the pen's `Q` (`q₁₁, q₁₂, q₂₂ = (a, b, c)/E`): `(det Q)² k² − (nᵀQn)³ =
//!   (E⁴ D⁶ / n⁴)⁻¹ · [(ac − b²)² (n−1)² D² (U×V)² − n² E w(U)³]`.
//!
//! Both are `P = α (n−1)² D² (U×V)² − β n² w(U)³` with `α, β > 0` integers: a
//! positive multiple of the cusp polynomial (the same signs and roots), and
//! `U × V` a positive multiple of `k`. In intervals the same formulas are
//! evaluated with `D = E = 1` and the rational constants enclosed.

use crate::curve::Bezier;
use crate::poly::scaled::{Ring, Scaled};
use crate::poly::{has_root_in, Poly, RealRoot, Span};
use crate::scalar::{interval_from_rational, Interval, Rational};
use num_bigint::BigInt;
use num_traits::{One, Zero};

/// The cusp polynomial `P` and `K = U × V` (see the module docs).
pub(crate) struct CuspForm<T> {
    pub(crate) p: Scaled<T>,
    pub(crate) k: Scaled<T>,
}

/// `P = α (n−1)² D² (U×V)² − β n² w(U)³` and `U × V` from the scaled
/// differences; `w = [a, b, c]`. `None` for degree below 2 (`k ≡ 0`: no cusp).
fn form<T: Ring>(x: &[(T, T)], d: &T, w: &[T; 3], alpha: &T, beta: &T) -> Option<CuspForm<T>> {
    let n = x.len().checked_sub(1)?;
    if n < 2 {
        return None;
    }
    let diff = |p: &[(T, T)]| -> Vec<(T, T)> {
        p.windows(2)
            .map(|s| {
                (
                    s[1].0.clone() - s[0].0.clone(),
                    s[1].1.clone() - s[0].1.clone(),
                )
            })
            .collect()
    };
    let u = diff(x);
    let v = diff(&u);
    let coord = |p: &[(T, T)], y: bool| {
        let c: Vec<T> = p
            .iter()
            .map(|q| if y { q.1.clone() } else { q.0.clone() })
            .collect();
        Scaled::from_bernstein(&c)
    };
    let (ux, uy, vx, vy) = (
        coord(&u, false),
        coord(&u, true),
        coord(&v, false),
        coord(&v, true),
    );
    let k = ux.mul(&vy).sub(&uy.mul(&vx));
    let two = T::from_int(&BigInt::from(2));
    let wu = uy
        .mul(&uy)
        .scale(&w[0])
        .sub(&ux.mul(&uy).scale(&(two * w[1].clone())))
        .add(&ux.mul(&ux).scale(&w[2]));
    let int = |m: usize| T::from_int(&BigInt::from(m));
    let c1 = alpha.clone() * int((n - 1) * (n - 1)) * d.clone() * d.clone();
    let c2 = beta.clone() * int(n * n);
    let p = k.mul(&k).scale(&c1).sub(&wu.mul(&wu).mul(&wu).scale(&c2));
    Some(CuspForm { p, k })
}

/// The control points over their least common denominator: `(X_i, D)`.
fn integer_points(x: &Bezier<Rational>) -> (Vec<(BigInt, BigInt)>, BigInt) {
    let l = x.points().iter().fold(BigInt::one(), |l, p| {
        let l = num_integer::Integer::lcm(&l, p.x.denom());
        num_integer::Integer::lcm(&l, p.y.denom())
    });
    let int = |r: &Rational| r.numer() * (&l / r.denom());
    let pts = x.points().iter().map(|p| (int(&p.x), int(&p.y))).collect();
    (pts, l)
}

/// Integers over a common positive denominator: `(numerators, E)`.
fn integer_list(v: &[&Rational]) -> (Vec<BigInt>, BigInt) {
    let l = v.iter().fold(BigInt::one(), |l, r| {
        num_integer::Integer::lcm(&l, r.denom())
    });
    (v.iter().map(|r| r.numer() * (&l / r.denom())).collect(), l)
}

fn iv_points(x: &Bezier<Rational>) -> Vec<(Interval, Interval)> {
    x.points()
        .iter()
        .map(|p| (interval_from_rational(&p.x), interval_from_rational(&p.y)))
        .collect()
}

/// The offset's cusp form at signed distance `d`, enclosed in intervals.
pub(crate) fn offset_form_iv(x: &Bezier<Rational>, d: &Rational) -> Option<CuspForm<Interval>> {
    let one = Interval::from_int(&BigInt::one());
    let di = interval_from_rational(d);
    let w = [one, Interval::zero(), one];
    form(&iv_points(x), &one, &w, &(di * di), &one)
}

/// The offset's cusp form at signed distance `d`, exactly.
pub(crate) fn offset_form(x: &Bezier<Rational>, d: &Rational) -> Option<CuspForm<BigInt>> {
    let (pts, den) = integer_points(x);
    let (p, q) = (d.numer(), d.denom());
    let w = [BigInt::one(), BigInt::from(0), BigInt::one()];
    form(&pts, &den, &w, &(p * p), &(q * q))
}

/// The convolution's cusp form with the pen form `q = [q₁₁, q₁₂, q₂₂]`,
/// enclosed in intervals.
pub(crate) fn conv_form_iv(x: &Bezier<Rational>, q: &[Rational; 3]) -> Option<CuspForm<Interval>> {
    let one = Interval::from_int(&BigInt::one());
    let w = q.clone().map(|r| interval_from_rational(&r));
    let det = w[0] * w[2] - w[1] * w[1];
    form(&iv_points(x), &one, &w, &(det * det), &one)
}

/// The convolution's cusp form with the pen form `q = [q₁₁, q₁₂, q₂₂]`, exactly.
pub(crate) fn conv_form(x: &Bezier<Rational>, q: &[Rational; 3]) -> Option<CuspForm<BigInt>> {
    let (pts, den) = integer_points(x);
    let (w, e) = integer_list(&[&q[0], &q[1], &q[2]]);
    let w = [w[0].clone(), w[1].clone(), w[2].clone()];
    let det = &w[0] * &w[2] - &w[1] * &w[1];
    form(&pts, &den, &w, &(&det * &det), &e)
}

/// The cusp parameters of piece `x`: isolating intervals (width ≤ 2⁻⁴⁰) of
/// the roots in `[0, 1]` of the cusp polynomial at which `side · k > 0`,
/// shared by offsets and convolutions. `iv` is the interval form (the filter:
/// one strict sign, no cusp), `exact` the integer form; `power` the
/// power-basis polynomial, built only for the exact Sturm path when the
/// isolation leaves a piece undecided (a multiple root, a root on a split
/// point). `k` is proven root-free on a root's interval by an enclosure (else
/// Sturm) and its sign taken exactly at the midpoint; if `k` may vanish
/// there, the root is kept: a possible cusp is reported, never dropped.
pub(crate) fn cusp_params(
    x: &Bezier<Rational>,
    iv: Option<CuspForm<Interval>>,
    exact: impl FnOnce() -> Option<CuspForm<BigInt>>,
    side: i8,
    power: impl FnOnce() -> Poly<Rational>,
) -> Vec<RealRoot> {
    // degree below 2: k ≡ 0, no cusp
    let Some(fi) = iv else {
        return Vec::new();
    };
    if fi.p.strict_sign().is_some() {
        return Vec::new();
    }
    let Some(f) = exact() else {
        return Vec::new();
    };
    if f.p.is_zero() || f.k.is_zero() {
        return Vec::new();
    }
    let span = Span::closed(Rational::zero(), Rational::one());
    let roots =
        f.p.simple_roots(40, 4_000)
            .unwrap_or_else(|| super::prep::roots_refined(&power().trimmed(), &span, 40));
    let mut k_exact: Option<Poly<Rational>> = None;
    roots
        .into_iter()
        .filter(|r| {
            let s = f.k.sign_at(&r.midpoint()).map(|k| k * side);
            let (lo, hi) = (
                interval_from_rational(&r.lo).inf(),
                interval_from_rational(&r.hi).sup(),
            );
            let k_iv = fi.k.range(lo, hi);
            let decided = k_iv.inf() > 0.0 || k_iv.sup() < 0.0 || {
                let k = k_exact.get_or_insert_with(|| super::prep::curvature_numerator(x));
                !has_root_in(k, &Span::closed(r.lo.clone(), r.hi.clone()))
            };
            !(decided && s.is_some_and(|s| s <= 0))
        })
        .collect()
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::curve::V2;
    use crate::offset::conv::{conv_cusp_polynomial, conv_cusps, Pen};
    use crate::offset::prep::{curvature_numerator, cusp_polynomial, offset_cusps};
    use crate::poly::{isolate_roots, refine_root, square_free};
    use crate::scalar::IntervalExt;
    use num_traits::Signed;

    /// A small xorshift generator (deterministic cases).
    struct Gen(u64);
    impl Gen {
        fn next(&mut self, m: u64) -> u64 {
            self.0 ^= self.0 << 13;
            self.0 ^= self.0 >> 7;
            self.0 ^= self.0 << 17;
            self.0 % m
        }
        fn rat(&mut self, range: i64) -> Rational {
            let den = [1i64, 2, 3, 4, 5, 7, 8, 10, 16][self.next(9) as usize];
            let num = self.next((2 * range * den + 1) as u64) as i64 - range * den;
            Rational::new(num.into(), den.into())
        }
        fn bezier(&mut self) -> Bezier<Rational> {
            let n = 2 + self.next(4) as usize;
            self.bezier_of(n)
        }
        fn bezier_of(&mut self, n: usize) -> Bezier<Rational> {
            Bezier::new((0..=n).map(|_| V2::new(self.rat(4), self.rat(4))).collect())
        }
        /// A pen from a random nonsingular matrix.
        fn pen(&mut self) -> Pen {
            loop {
                let m = [[self.rat(2), self.rat(2)], [self.rat(2), self.rat(2)]];
                if let Ok(p) = Pen::from_matrix(m) {
                    return p;
                }
            }
        }
    }

    /// `a` is `c · b` at every sample for one constant `c > 0`.
    fn positive_multiple(a: &Scaled<BigInt>, b: &Poly<Rational>, what: &str) {
        let ts: Vec<Rational> = (0..=12)
            .map(|k| Rational::new(k.into(), 12.into()))
            .collect();
        let Some(t0) = ts.iter().find(|t| !b.eval(t).is_zero()) else {
            assert!(ts.iter().all(|t| a.value(t).is_zero()), "{what}");
            return;
        };
        let (a0, b0) = (a.value(t0), b.eval(t0));
        assert!(
            (&a0 / &b0).is_positive(),
            "{what}: the factor is not positive"
        );
        for t in &ts {
            assert_eq!(a.value(t) * &b0, b.eval(t) * &a0, "{what} at {t}");
        }
    }

    /// The integer forms are positive multiples of the power-basis cusp
    /// polynomials and curvature numerators (computed independently in
    /// rationals), and the interval forms enclose the values of those
    /// multiples that the module docs give (`p/n⁴`, `k/(n²(n−1))`).
    #[test]
    fn forms_are_positive_multiples_of_the_cusp_polynomials() {
        let mut g = Gen(0x9e37_79b9_7f4a_7c15);
        for case in 0..120 {
            let x = g.bezier();
            let n = x.degree() as i64;
            let k = curvature_numerator(&x);
            let d = loop {
                let d = g.rat(3);
                if !d.is_zero() {
                    break d;
                }
            };
            let pen = g.pen().q;
            let p_off = cusp_polynomial(&x, &k, &d);
            let (p_conv, k_conv) = conv_cusp_polynomial(&x, &pen);
            let off = offset_form(&x, &d).expect("degree ≥ 2");
            let conv = conv_form(&x, &pen).expect("degree ≥ 2");
            positive_multiple(&off.p, &p_off, &format!("case {case}: offset P"));
            positive_multiple(&off.k, &k, &format!("case {case}: offset K"));
            positive_multiple(&conv.p, &p_conv, &format!("case {case}: convolution P"));
            positive_multiple(&conv.k, &k_conv, &format!("case {case}: convolution K"));
            let n4 = Rational::from_integer((n * n * n * n).into());
            let kn = Rational::from_integer((n * n * (n - 1)).into());
            let off_iv = offset_form_iv(&x, &d).expect("degree ≥ 2");
            let conv_iv = conv_form_iv(&x, &pen).expect("degree ≥ 2");
            for j in 0..=8 {
                let t = Rational::new(j.into(), 8.into());
                let tf = j as f64 / 8.0;
                for (f, p) in [(&off_iv, &p_off), (&conv_iv, &p_conv)] {
                    assert!(f.p.range(tf, tf).contains_rational(&(p.eval(&t) / &n4)));
                    assert!(f.k.range(tf, tf).contains_rational(&(k.eval(&t) / &kn)));
                }
            }
        }
    }

    /// The oracle: the roots of the power-basis cusp polynomial in `[0, 1]` by
    /// exact Sturm isolation, refined to `2⁻¹²`, kept where `s·k > 0` at the
    /// refined interval's midpoint.
    fn oracle(p: &Poly<Rational>, k: &Poly<Rational>, s: i8) -> Vec<RealRoot> {
        let p = p.clone().trimmed();
        if p.coeffs().iter().all(Zero::is_zero) || k.coeffs().iter().all(Zero::is_zero) {
            return Vec::new();
        }
        let span = Span::closed(Rational::zero(), Rational::one());
        let w = Rational::new(1.into(), BigInt::one() << 12);
        isolate_roots(&square_free(&p), &span)
            .into_iter()
            .map(|r| refine_root(&p, &r, &w))
            .filter(|r| {
                let v = k.eval(&r.midpoint()) * Rational::from_integer(s.into());
                v.is_positive()
            })
            .collect()
    }

    fn same_roots(got: &[(Rational, Rational)], want: &[RealRoot], what: &str) {
        assert_eq!(got.len(), want.len(), "{what}: {got:?} vs {want:?}");
        for ((lo, hi), w) in got.iter().zip(want) {
            assert!(lo <= &w.hi && &w.lo <= hi, "{what}: [{lo}, {hi}] vs {w:?}");
        }
    }

    /// Offset and convolution cusps (scaled integer path) against exact Sturm
    /// isolation of the power-basis polynomials, on random pieces with
    /// distances and pens chosen so that cusps occur often.
    #[test]
    fn cusps_match_exact_sturm_isolation() {
        let mut g = Gen(0x2545_f491_4f6c_dd1d);
        let (mut with_cusps, mut cases) = (0, 0);
        for case in 0..50 {
            let n = 2 + g.next(3) as usize;
            let x = g.bezier_of(n);
            let k = curvature_numerator(&x);
            let d = loop {
                let d = g.rat(3);
                if !d.is_zero() {
                    break d;
                }
            };
            let got: Vec<_> = offset_cusps(0, &x, &d).into_iter().map(|c| c.t).collect();
            let s = if d.is_positive() { 1 } else { -1 };
            let want = oracle(&cusp_polynomial(&x, &k, &d), &k, s);
            same_roots(&got, &want, &format!("case {case}: offset at {d}"));
            with_cusps += usize::from(!want.is_empty());
            let pen = g.pen();
            for sigma in [1i8, -1] {
                let got: Vec<_> = conv_cusps(0, &x, &pen, sigma)
                    .into_iter()
                    .map(|c| c.t)
                    .collect();
                let (p, kc) = conv_cusp_polynomial(&x, &pen.q);
                let want = oracle(&p, &kc, sigma);
                same_roots(&got, &want, &format!("case {case}: convolution {sigma}"));
                with_cusps += usize::from(!want.is_empty());
            }
            cases += 3;
        }
        assert!(
            with_cusps * 5 >= cases,
            "only {with_cusps} of {cases} cases had cusps"
        );
    }
}
