//! Interval sums and products rounded to nearest, then widened by one ulp on
//! each side: outward enclosures without switching the rounding mode.
//!
//! inari rounds each end in the right direction by changing the rounding mode
//! around every operation (two `ldmxcsr` per operation) and classifies both
//! operands of a product into 49 cases; in the stroke verifier's inner loops
//! (de Casteljau steps, mean-value forms) that was a third of the time. These
//! functions compute the ends in the default mode, round to nearest (`RN`),
//! and step the lower end down and the upper end up once
//! ([`f64::next_down`], [`f64::next_up`]).
//!
//! **Why the result encloses the exact one.** For finite operands the exact
//! ends are `min`/`max` of the exact end sums (products). `RN` is monotone,
//! so `min RN(xᵢ) = RN(min xᵢ)` (and likewise `max`). For a real `x`,
//! `RN(x)` is a float nearest to `x`, so no float lies strictly between `x`
//! and `RN(x)`: if `RN(x) > x` then `next_down(RN(x)) ≤ x`, otherwise
//! `next_down(RN(x)) ≤ RN(x) ≤ x`. This holds at the extremes too: an
//! overflow to `+∞` steps down to `f64::MAX ≤ x`, an underflow to `0` steps
//! to `∓` the least subnormal. The upper end is symmetric. Finite operands
//! give no `NaN` (no `0 · ∞`, no `∞ − ∞`); any other operand (an unbounded
//! or empty interval) is left to inari. Tested against exact
//! rational sums and products.

use super::Interval;

/// `true` when both ends are finite (so the interval is bounded and not empty).
#[inline]
fn bounded(a: Interval) -> bool {
    a.inf().is_finite() && a.sup().is_finite()
}

#[inline]
fn widened(lo: f64, hi: f64) -> Interval {
    // lo ≤ hi by construction; the only failure would be lo = +∞ or
    // hi = −∞, impossible after the steps (next_down(+∞) = MAX)
    Interval::try_from((lo.next_down(), hi.next_up())).expect("ordered ends")
}

/// `a + b`, enclosed (see the module docs).
#[inline]
pub fn add(a: Interval, b: Interval) -> Interval {
    if !(bounded(a) && bounded(b)) {
        return a + b;
    }
    widened(a.inf() + b.inf(), a.sup() + b.sup())
}

/// `a − b`, enclosed (see the module docs).
#[inline]
pub fn sub(a: Interval, b: Interval) -> Interval {
    if !(bounded(a) && bounded(b)) {
        return a - b;
    }
    widened(a.inf() - b.sup(), a.sup() - b.inf())
}

/// `a · b`, enclosed (see the module docs).
#[inline]
pub fn mul(a: Interval, b: Interval) -> Interval {
    if !(bounded(a) && bounded(b)) {
        return a * b;
    }
    let (al, ah, bl, bh) = (a.inf(), a.sup(), b.inf(), b.sup());
    let (p, q, r, s) = (al * bl, al * bh, ah * bl, ah * bh);
    widened(p.min(q).min(r.min(s)), p.max(q).max(r.max(s)))
}

/// `a²`, enclosed (see the module docs; an interval containing 0 starts at 0).
#[inline]
pub fn sqr(a: Interval) -> Interval {
    if !bounded(a) {
        return a.sqr();
    }
    let (l, h) = (a.inf(), a.sup());
    let (p, q) = (l * l, h * h);
    if l >= 0.0 {
        widened(p, q)
    } else if h <= 0.0 {
        widened(q, p)
    } else {
        widened(0.0, p.max(q))
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::scalar::{interval_from_rational, rational_from_f64, Rational};
    use num_traits::{Signed, Zero};

    /// The exact rational ends of `a ∘ b` for float-ended intervals.
    fn exact(a: Interval, b: Interval, op: char) -> (Rational, Rational) {
        let q = |x: f64| rational_from_f64(x).expect("finite");
        let (al, ah, bl, bh) = (q(a.inf()), q(a.sup()), q(b.inf()), q(b.sup()));
        let mut v = match op {
            '+' => vec![&al + &bl, &ah + &bh],
            '-' => vec![&al - &bh, &ah - &bl],
            // a², exactly: 0 when a straddles it
            '²' if al.is_negative() && ah.is_positive() => {
                vec![Rational::zero(), &al * &al, &ah * &ah]
            }
            '²' => vec![&al * &al, &ah * &ah],
            _ => vec![&al * &bl, &al * &bh, &ah * &bl, &ah * &bh],
        };
        v.sort();
        (v[0].clone(), v[v.len() - 1].clone())
    }

    fn encloses(r: Interval, (lo, hi): &(Rational, Rational)) -> bool {
        let q = |x: f64| rational_from_f64(x);
        // the exact ends against the float ends, exactly (∞ ends enclose)
        let lo_ok = r.inf() == f64::NEG_INFINITY || q(r.inf()).is_some_and(|x| &x <= lo);
        let hi_ok = r.sup() == f64::INFINITY || q(r.sup()).is_some_and(|x| &x >= hi);
        lo_ok && hi_ok
    }

    #[test]
    fn sums_and_products_enclose_the_exact_ones() {
        let mut s = 0x9e37_79b9_7f4a_7c15u64;
        let mut next = move || {
            s ^= s << 13;
            s ^= s >> 7;
            s ^= s << 17;
            s
        };
        let mut rounded_inward = 0;
        for k in 0..20_000 {
            // random floats of every sign, spread over 2^±40 with full
            // mantissas, so most sums and products are inexact
            let mut f = || {
                let m = (next() >> 11) as f64 / (1u64 << 53) as f64 + 0.5;
                let e = (next() % 81) as i32 - 40;
                let sign = if next() % 2 == 0 { 1.0 } else { -1.0 };
                sign * m * 2f64.powi(e)
            };
            let (x, y, z, w) = (f(), f(), f(), f());
            let a = Interval::try_from((x.min(y), x.max(y))).unwrap();
            let b = if k % 5 == 0 {
                Interval::try_from((z, z)).unwrap()
            } else {
                Interval::try_from((z.min(w), z.max(w))).unwrap()
            };
            for (op, r) in [
                ('+', add(a, b)),
                ('-', sub(a, b)),
                ('*', mul(a, b)),
                ('²', sqr(a)),
            ] {
                let e = exact(a, b, op);
                assert!(encloses(r, &e), "{a:?} {op} {b:?} = {r:?} misses {e:?}");
                // the rounding-to-nearest ends alone (no widening) would miss
                // the exact end in many cases: the widening is needed
                let (lo, hi) = (r.inf().next_up(), r.sup().next_down());
                if let Ok(inner) = Interval::try_from((lo, hi)) {
                    if !encloses(inner, &e) {
                        rounded_inward += 1;
                    }
                }
                // never wider than inari's by more than one ulp per end
                let i = match op {
                    '+' => a + b,
                    '-' => a - b,
                    '²' => a.sqr(),
                    _ => a * b,
                };
                assert!(r.inf() >= i.inf().next_down() && r.sup() <= i.sup().next_up());
            }
        }
        assert!(rounded_inward > 15_000, "{rounded_inward}");
    }

    #[test]
    fn extremes_and_unbounded_operands() {
        let big = Interval::try_from((f64::MAX / 2.0, f64::MAX)).unwrap();
        let p = mul(big, big);
        assert!(p.inf() >= f64::MAX / 4.0 && p.sup() == f64::INFINITY);
        let s = add(big, big);
        assert!(s.sup() == f64::INFINITY && s.inf() <= f64::MAX);
        let tiny = Interval::try_from((f64::MIN_POSITIVE, f64::MIN_POSITIVE)).unwrap();
        let u = mul(tiny, tiny);
        assert!(u.inf() < 0.0 && u.sup() > 0.0);
        // unbounded or empty operands go to inari
        let ent = Interval::ENTIRE;
        assert_eq!(mul(ent, tiny), ent * tiny);
        assert!(add(Interval::EMPTY, tiny).is_empty());
        let one = interval_from_rational(&Rational::from_integer(1.into()));
        assert_eq!(sub(one, one).inf(), 0f64.next_down());
    }
}
