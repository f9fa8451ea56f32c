//! Tests of the symbolic scalar.
use super::*;
use crate::poly::Poly;
use crate::scalar::{Rational, Scalar, Sign};
use crate::test_util::q;
use num_traits::Zero;

fn c(n: i64) -> RatFunc {
    RatFunc::from_i64(n)
}

#[test]
fn square_of_sum_mpoly() {
    let (x, y) = (MPoly::var(0), MPoly::var(1));
    let lhs = (x.clone() + y.clone()).pow(2);
    let rhs = x.pow(2) + MPoly::constant(q("2")) * x.clone() * y.clone() + y.pow(2);
    assert_eq!(lhs, rhs);
    assert_eq!(lhs.total_degree(), 2);
    assert_eq!(lhs.num_terms(), 3);
}

#[test]
fn canonical_form_trims_and_drops_zeros() {
    let a = MPoly::monomial(&[1, 0, 0], q("2"));
    let b = MPoly::monomial(&[1], q("2"));
    assert_eq!(a, b);
    let x = MPoly::var(3);
    assert!((x.clone() - x.clone()).is_zero());
    assert_eq!(x.clone() - x, MPoly::zero());
    assert!(MPoly::monomial(&[5], q("0")).is_zero());
    // A product whose high variable cancels.
    let y = MPoly::var(4);
    let p = (y.clone() + MPoly::one()) * (y.clone() - MPoly::one()) - y.pow(2);
    assert_eq!(p, MPoly::constant(q("-1")));
}

#[test]
fn difference_of_squares_over_difference() {
    let (x, y) = (RatFunc::var(0), RatFunc::var(1));
    let f = (x.clone() * x.clone() - y.clone() * y.clone())
        .div(&(x.clone() - y.clone()))
        .unwrap();
    assert_eq!(f, x.clone() + y.clone());
    assert!(identity_holds(&f, &(x.clone() + y.clone())));
    // Also when built without the simplifying paths.
    let g = RatFunc::new(
        MPoly::var(0).pow(2) - MPoly::var(1).pow(2),
        MPoly::var(0) - MPoly::var(1),
    )
    .unwrap();
    assert_eq!(g, x + y);
}

#[test]
fn symbolic_poly_eval() {
    // p(t) = a + b t + c t^2 with symbolic a, b, c.
    let (a, b, cc, s) = (
        RatFunc::var(0),
        RatFunc::var(1),
        RatFunc::var(2),
        RatFunc::var(3),
    );
    let p = Poly::new(vec![a.clone(), b.clone(), cc.clone()]);
    let v = p.eval(&s);
    assert_eq!(
        v,
        a.clone() + b.clone() * s.clone() + cc.clone() * s.clone() * s.clone()
    );
    // At a rational point.
    let half = RatFunc::constant(q("1/2"));
    let w = p.eval(&half);
    assert_eq!(
        w,
        a.clone() + b.clone() * half.clone() + cc.clone() * c(1).div(&c(4)).unwrap()
    );
    // Evaluate the symbolic result numerically: a=1, b=2, c=4 at t=1/2 -> 3.
    assert_eq!(w.eval(&[q("1"), q("2"), q("4")]), Some(q("3")));
    // The derivative kernel.
    assert_eq!(p.derivative().eval(&s), b + cc.scale(2) * s);
    // poly_in builds the same function.
    assert_eq!(poly_in(3, &p), v);
}

#[test]
fn cubic_bernstein_derivative_identity() {
    let b: Vec<RatFunc> = (0..4).map(RatFunc::var).collect();
    let p = Poly::from_bernstein(&b);
    let d = p.derivative();
    let hodograph = Poly::from_bernstein(&[
        (b[1].clone() - b[0].clone()).scale(3),
        (b[2].clone() - b[1].clone()).scale(3),
        (b[3].clone() - b[2].clone()).scale(3),
    ]);
    assert_eq!(d.coeffs().len(), hodograph.coeffs().len());
    assert_eq!(d, hodograph);
    let t = 4;
    assert!(identity_holds(&poly_in(t, &d), &poly_in(t, &hodograph)));
    // And the polynomial in t as an MPoly has the expected shape.
    let f = poly_in(t, &p);
    assert!(f.den().is_one());
    assert_eq!(f.num().degree_in(t), 3);
    let cs = univariate_coeffs(f.num(), t);
    assert_eq!(cs.len(), 4);
    assert_eq!(cs[0], MPoly::var(0));
    // Derivative in t of the symbolic function agrees with the kernel.
    assert_eq!(f.derivative(t), poly_in(t, &d));
}

#[test]
fn bernstein_with_rational_function_control_values() {
    // Control values with denominators like the papers' (3τ-1)(3τ-2).
    let tau = RatFunc::var(0);
    let b0 = RatFunc::var(1);
    let b1 = b0.clone().div(&(tau.scale(3) - c(1))).unwrap();
    let b2 = b0.clone().div(&(tau.scale(3) - c(2))).unwrap();
    let b3 = RatFunc::var(2);
    let p = Poly::from_bernstein(&[b0.clone(), b1.clone(), b2.clone(), b3.clone()]);
    let hodo = Poly::from_bernstein(&[
        (b1.clone() - b0.clone()).scale(3),
        (b2.clone() - b1.clone()).scale(3),
        (b3.clone() - b2.clone()).scale(3),
    ]);
    assert_eq!(p.derivative(), hodo);
    // Endpoint interpolation: p(0) = b0, p(1) = b3.
    assert_eq!(p.eval(&c(0)), b0);
    assert_eq!(p.eval(&c(1)), b3);
    let t = 3;
    let f = poly_in(t, &p);
    assert_eq!(f.substitute(t, &c(1)).unwrap(), b3);
    // Denominators stay factors of (3τ-1)(3τ-2), not their squares.
    assert!(f.den().total_degree() <= 2, "den = {}", f.den());
}

#[test]
fn sign_and_recip() {
    let (x, y) = (RatFunc::var(0), RatFunc::var(1));
    assert_eq!(x.sign(), Sign::Unknown);
    assert_eq!((x.clone() * x.clone() + c(1)).sign(), Sign::Unknown);
    assert_eq!(x.clone().div(&y).unwrap().sign(), Sign::Unknown);
    assert_eq!(c(-3).sign(), Sign::Negative);
    assert_eq!(c(0).sign(), Sign::Zero);
    assert_eq!((x.clone() - x.clone()).sign(), Sign::Zero);
    assert_eq!(RatFunc::constant(q("2/7")).sign(), Sign::Positive);
    // Proportional numerator and denominator: a constant.
    let k = RatFunc::new(
        MPoly::var(0).scale(&q("-2")) + MPoly::var(1),
        MPoly::var(0) - MPoly::var(1).scale(&q("1/2")),
    )
    .unwrap();
    assert_eq!(k.sign(), Sign::Negative);
    assert_eq!(k.approx(), -2.0);
    assert!(x.approx().is_nan());
    assert_eq!(RatFunc::constant(q("1/4")).approx(), 0.25);
    // recip
    assert!(c(0).recip().is_none());
    assert!((x.clone() - x.clone()).recip().is_none());
    assert!(x.div(&c(0)).is_none());
    let r = (x.clone() + y.clone()).recip().unwrap();
    assert_eq!(r * (x.clone() + y.clone()), c(1));
    assert_eq!(RatFunc::KIND, "symbolic");
    const { assert!(RatFunc::EXACT) };
}

#[test]
fn identity_checker_can_fail() {
    let (x, y) = (RatFunc::var(0), RatFunc::var(1));
    let s = x.clone() + y.clone();
    assert!(!identity_holds(
        &(s.clone() * s.clone()),
        &(x.clone() * x.clone() + y.clone() * y.clone())
    ));
    assert_ne!(s.clone() * s, x.sqr() + y.sqr());
    // Different denominators, unequal functions.
    let a = c(1).div(&x).unwrap();
    let b = c(1).div(&(x + c(1))).unwrap();
    assert_ne!(a, b);
    assert_ne!(MPoly::var(0).pow(2), MPoly::var(0).pow(2) + MPoly::one());
}

#[test]
fn display() {
    let p = MPoly::monomial(&[2, 1], q("3/2")) - MPoly::var(2) + MPoly::one();
    assert_eq!(p.to_string(), "3/2*x0^2*x1 - x2 + 1");
    assert_eq!(p.display_with(&["a", "b", "c"]), "3/2*a^2*b - c + 1");
    assert_eq!((-p).to_string(), "-3/2*x0^2*x1 + x2 - 1");
    assert_eq!(MPoly::zero().to_string(), "0");
    assert_eq!(MPoly::constant(q("-5")).to_string(), "-5");
    let f = RatFunc::var(0)
        .div(&(RatFunc::var(1) * RatFunc::var(2) + c(1)))
        .unwrap();
    assert_eq!(f.to_string(), "x0/(x1*x2 + 1)");
    assert_eq!(format!("{f:?}"), "RatFunc(x0/(x1*x2 + 1))");
    let g = (RatFunc::var(0) + c(1)).div(&RatFunc::var(1)).unwrap();
    assert_eq!(g.to_string(), "(x0 + 1)/x1");
}

#[test]
fn eval_substitute_coefficients() {
    let (x, y, z) = (MPoly::var(0), MPoly::var(1), MPoly::var(2));
    let p = x.pow(2) * y.clone() - z.clone() * x.clone() + MPoly::constant(q("1/3"));
    assert_eq!(
        p.eval(&[q("2"), q("3"), q("5")]),
        q("12") - q("10") + q("1/3")
    );
    assert_eq!(p.degree_in(0), 2);
    assert_eq!(p.degree_in(2), 1);
    assert_eq!(p.degree_in(7), 0);
    assert_eq!(p.total_degree(), 3);
    let cs = p.coefficients_in(0);
    assert_eq!(cs, vec![MPoly::constant(q("1/3")), -z.clone(), y.clone()]);
    // Reassemble.
    let mut back = MPoly::zero();
    for (k, ck) in cs.iter().enumerate() {
        back = back + ck.clone() * x.pow(k as u32);
    }
    assert_eq!(back, p);
    assert!(MPoly::zero().coefficients_in(0).is_empty());
    // Substitution x -> y + z, checked at a point.
    let s = p.substitute(0, &(y.clone() + z.clone()));
    assert_eq!(s.degree_in(0), 0);
    let v = [q("7"), q("-2"), q("3/4")];
    assert_eq!(s.eval(&v), p.eval(&[q("-2") + q("3/4"), q("-2"), q("3/4")]));
    // Substitution of a rational function into a rational function.
    let f = RatFunc::new(x.clone() + y.clone(), x.clone() - y.clone()).unwrap();
    let val = RatFunc::new(y.clone(), z.clone() + MPoly::one()).unwrap();
    let g = f.substitute(0, &val).unwrap();
    let pt = [q("0"), q("2"), q("3")];
    let xv = q("2") / q("4");
    assert_eq!(g.eval(&pt), f.eval(&[xv, q("2"), q("3")]));
}

#[test]
#[should_panic(expected = "no value for variable")]
fn eval_panics_without_values() {
    MPoly::var(2).eval(&[q("1")]);
}

#[test]
fn exact_division() {
    let (x, y, z) = (MPoly::var(0), MPoly::var(1), MPoly::var(2));
    let a = x.clone() * y.clone() - z.clone() + MPoly::constant(q("2/3"));
    let b = y.pow(2) + x.clone() * z.clone() - MPoly::one();
    let p = a.clone() * b.clone();
    assert_eq!(p.div_exact(&a), Some(b.clone()));
    assert_eq!(p.div_exact(&b), Some(a.clone()));
    assert_eq!((p.clone() + MPoly::one()).div_exact(&a), None);
    assert_eq!(p.div_exact(&MPoly::zero()), None);
    assert_eq!(
        p.div_exact(&MPoly::constant(q("2"))),
        Some(p.scale(&q("1/2")))
    );
    assert_eq!(a.div_exact(&p), None);
    // Non-homogeneous divisor whose quotient search must stop.
    assert_eq!(x.pow(6).div_exact(&(x.clone() - y.pow(2))), None);
}

#[test]
fn representations_stay_small() {
    let tau = RatFunc::var(0);
    let d1 = tau.scale(3) - c(1);
    let d2 = tau.scale(3) - c(2);
    let u = c(1).div(&d1).unwrap();
    let v = c(1).div(&d2).unwrap();
    let w = u.clone() * v.clone();
    // u + w and w + u use exact division of denominators.
    let s = u.clone() + w.clone();
    assert_eq!(s.den().total_degree(), 2);
    let back = (s - w) * d1.clone();
    assert_eq!(back, c(1));
    assert!(back.den().is_one());
    // Cancellation in products.
    let m = u * d1;
    assert!(m.den().is_one());
    // Monomial content cancels.
    let f = RatFunc::new(MPoly::var(0).pow(3) * MPoly::var(1), MPoly::var(0).pow(2)).unwrap();
    assert!(f.den().is_one());
    assert_eq!(f, RatFunc::var(0) * RatFunc::var(1));
}

/// A small deterministic generator of polynomials with rational
/// coefficients (the integer-only paths would hide scaling mistakes).
struct Lcg(u64);
impl Lcg {
    fn next(&mut self, n: u64) -> u64 {
        self.0 = self
            .0
            .wrapping_mul(6364136223846793005)
            .wrapping_add(1442695040888963407);
        (self.0 >> 33) % n
    }
    fn rational(&mut self) -> Rational {
        let num = self.next(19) as i64 - 9;
        let den = self.next(6) as i64 + 1;
        Rational::new(num.into(), den.into())
    }
    fn poly(&mut self, vars: usize, terms: usize, deg: u64) -> MPoly {
        let mut p = MPoly::zero();
        for _ in 0..terms {
            let e: Vec<u32> = (0..vars).map(|_| self.next(deg + 1) as u32).collect();
            p = p + MPoly::monomial(&e, self.rational());
        }
        p
    }
}

#[test]
fn arithmetic_agrees_with_evaluation() {
    let mut g = Lcg(7);
    let pt = [q("2/3"), q("-5/2"), q("7/4")];
    for _ in 0..40 {
        let p = g.poly(3, 5, 3);
        let r = g.poly(3, 4, 2);
        let s = g.poly(3, 3, 2);
        let (pv, rv, sv) = (p.eval(&pt), r.eval(&pt), s.eval(&pt));
        assert_eq!((&p * &r).eval(&pt), &pv * &rv);
        assert_eq!((&p + &r).eval(&pt), &pv + &rv);
        assert_eq!((&p - &r).eval(&pt), &pv - &rv);
        assert_eq!(p.pow(3).eval(&pt), &pv * &pv * &pv);
        assert_eq!(&p * &(&r + &s), &p * &r + &p * &s);
        assert_eq!((&p + &r) - &r, p);
        assert_eq!(
            p.substitute(1, &s).eval(&pt),
            p.eval(&[pt[0].clone(), sv.clone(), pt[2].clone()])
        );
        if !r.is_zero() {
            assert_eq!((&p * &r).div_exact(&r), Some(p.clone()));
            if r.total_degree() > 0 {
                // A non-constant r cannot divide p*r + 1/7.
                let shifted = &p * &r + MPoly::constant(q("1/7"));
                assert_eq!(shifted.div_exact(&r), None);
            }
        }
        // Rational functions: (p/r + s) * r - p == s * r, checked at the point.
        if !r.is_zero() && !rv.is_zero() {
            let (pf, rf, sf) = (
                RatFunc::from_mpoly(p.clone()),
                RatFunc::from_mpoly(r.clone()),
                RatFunc::from_mpoly(s.clone()),
            );
            let f = pf.div(&rf).unwrap() + sf.clone();
            assert_eq!(f.eval(&pt), Some(&pv / &rv + &sv));
            assert_eq!(f * rf.clone() - pf, sf * rf);
        }
    }
}

#[test]
fn moderate_size_identity() {
    // 6 variables, total degree 10: (s^5)(s^5) == s^10 and a derived
    // identity with a non-trivial denominator.
    let s = (0..6).map(MPoly::var).fold(MPoly::one(), |a, b| a + b);
    let s5 = s.pow(5);
    let s10 = s.pow(10);
    assert_eq!(s5.mul(&s5), s10);
    assert_eq!(s10.num_terms(), 8008); // C(16, 6)
    let f = RatFunc::new(s10.clone(), s.pow(3)).unwrap();
    assert_eq!(f, RatFunc::from_mpoly(s.pow(7)));
    assert_eq!(s10.div_exact(&s.pow(3)), Some(s.pow(7)));
}
