//! Certified root exclusion and enclosure for polynomials with interval
//! coefficients, by subdivision and the Bernstein convex-hull property.
//!
//! A polynomial `p` with [`Interval`] coefficients stands for the whole family
//! of real polynomials whose coefficients lie in those intervals. "No root on a
//! piece" below always means: *no member of the family* has a root there. On a
//! piece `[a, b]` the coefficients of `p(a + (b - a) s)` in the Bernstein basis
//! of `[0, 1]` are enclosed with outward-rounded interval arithmetic; the
//! polynomial is a convex combination of them for `s` in `[0, 1]`, so if they
//! are all strictly positive (or all strictly negative) the piece holds no
//! root. That exclusion is a proof; everything else is only a candidate.

use super::Poly;
use crate::scalar::{interval_from_rational, Interval, Rational, Scalar, Sign};
use num_bigint::BigInt;

/// The outcome of [`enclose_roots`].
///
/// `candidates` are closed float intervals, sorted, pairwise disjoint (adjacent
/// pieces are merged) and inside `[lo, hi]`; every root in `[lo, hi]` of every
/// member of the polynomial family lies in one of them. The complement of the
/// candidates in `[lo, hi]` is *proven* root-free. A candidate is not a proof
/// that a root exists.
///
/// # Examples
/// ```
/// use lncert::poly::{enclose_roots, Poly};
/// use lncert::scalar::Interval;
/// let c = |x: f64| Interval::try_from((x, x)).unwrap();
/// let p = Poly::new(vec![c(-0.5), c(1.0)]); // t - 1/2
/// let e = enclose_roots(&p, 0.0, 1.0, 1e-3, 1000);
/// assert!(!e.excluded_everywhere && !e.budget_exhausted);
/// assert_eq!(e.candidates.len(), 1); // the two pieces touching 1/2, merged
/// let (a, b) = e.candidates[0];
/// assert!(a < 0.5 && 0.5 < b && b - a < 4e-3);
/// ```
#[derive(Clone, Debug, PartialEq)]
pub struct RootEnclosure {
    /// Pieces that could not be excluded (may or may not contain roots).
    pub candidates: Vec<(f64, f64)>,
    /// `true` only if it is proven that no member of the family has a root in
    /// `[lo, hi]` (equivalently, `candidates` is empty).
    pub excluded_everywhere: bool,
    /// Number of pieces examined with the Bernstein test.
    pub boxes: usize,
    /// Whether the `max_boxes` budget ran out (unexamined pieces were then
    /// reported as candidates).
    pub budget_exhausted: bool,
}

/// Exact binomial coefficient as a big integer (any size).
fn big_binomial(n: usize, k: usize) -> BigInt {
    if k > n {
        return BigInt::from(0);
    }
    let k = k.min(n - k);
    let mut r = BigInt::from(1);
    for i in 0..k {
        r = r * BigInt::from(n - i) / BigInt::from(i + 1);
    }
    r
}

/// Enclosures of the Bernstein coefficients of degree `n = formal_degree(q)` of
/// `q` on `[0, 1]`: `b_i = sum_{k <= i} C(i,k)/C(n,k) q_k`.
fn bernstein_enclosure(q: &Poly<Interval>) -> Vec<Interval> {
    let n = q.formal_degree();
    let c = q.coeffs();
    let w = weights(n);
    (0..=n)
        .map(|i| {
            let row = &w[i * (i + 1) / 2..];
            let mut s = <Interval as Scalar>::zero();
            for (k, a) in c.iter().enumerate().take(i + 1) {
                s += *a * row[k];
            }
            s
        })
        .collect()
}

thread_local! {
    /// Enclosures of `C(i, k)/C(n, k)`, `k ≤ i ≤ n`, per degree `n` (row `i`
    /// starts at `i(i+1)/2`): computed once per thread and degree — the
    /// subdivisions of a root isolation convert thousands of polynomials of the
    /// same degree.
    static WEIGHTS: std::cell::RefCell<std::collections::HashMap<usize, std::rc::Rc<Vec<Interval>>>> =
        std::cell::RefCell::new(std::collections::HashMap::new());
}

/// The power → Bernstein weights of degree `n`, enclosed (exact binomials,
/// each ratio enclosed from the exact rational).
fn weights(n: usize) -> std::rc::Rc<Vec<Interval>> {
    WEIGHTS.with(|cache| {
        if let Some(w) = cache.borrow().get(&n) {
            return w.clone();
        }
        let denom: Vec<BigInt> = (0..=n).map(|k| big_binomial(n, k)).collect();
        let mut w = Vec::with_capacity((n + 1) * (n + 2) / 2);
        for i in 0..=n {
            for (k, d) in denom.iter().enumerate().take(i + 1) {
                w.push(interval_from_rational(&Rational::new(
                    big_binomial(i, k),
                    d.clone(),
                )));
            }
        }
        let w = std::rc::Rc::new(w);
        cache.borrow_mut().insert(n, w.clone());
        w
    })
}

fn point(x: f64) -> Interval {
    crate::scalar::point_interval(x)
}

/// The sign of every member of the family on the whole of `[a, b]`, if the
/// Bernstein test proves it (`Positive` or `Negative`), else `Unknown`.
fn certified_sign(p: &Poly<Interval>, a: f64, b: f64) -> Sign {
    let (ia, ib) = (point(a), point(b));
    // The exact width b - a lies in ib - ia (outward rounded), so every
    // coefficient of p(a + (b - a) s) is enclosed.
    let q = p.compose_affine(&ia, &(ib - ia));
    let bern = bernstein_enclosure(&q);
    let first = match bern.first().map(Scalar::sign) {
        Some(s @ (Sign::Positive | Sign::Negative)) => s,
        _ => return Sign::Unknown,
    };
    if bern.iter().all(|c| Scalar::sign(c) == first) {
        first
    } else {
        Sign::Unknown
    }
}

/// Isolates the roots of an interval polynomial in `[lo, hi]` when they are all
/// simple, by Bernstein subdivision and Descartes' rule of signs: on a piece
/// whose Bernstein coefficients all have a decided sign (no enclosure contains
/// 0), every member of the family has the same number `V` of sign variations,
/// which bounds its roots in the open piece (counted with multiplicity) and has
/// their parity. `V = 0`: no root; `V = 1`: exactly one root, simple; else the
/// piece is halved.
///
/// `Some(pieces)`: sorted float intervals `(a, b)`, each holding exactly one root
/// of every member of the family, in its interior, and no root in `[lo, hi]`
/// outside them (the ends of every piece are proven non-roots). `None` when that
/// could not be decided within `max_pieces` pieces (a multiple or clustered
/// root, a root at a split point, coefficients too wide) — the caller falls back
/// to exact isolation.
///
/// # Examples
/// ```
/// use lncert::poly::{isolate_simple_roots, Poly};
/// use lncert::scalar::Interval;
/// let c = |x: f64| Interval::try_from((x, x)).unwrap();
/// // (t - 0.3)(t - 0.7) = t² - t + 0.21
/// let p = Poly::new(vec![c(0.21), c(-1.0), c(1.0)]);
/// let r = isolate_simple_roots(&p, 0.0, 1.0, 1000).unwrap();
/// assert_eq!(r.len(), 2);
/// assert!(r[0].0 < 0.3 && 0.3 < r[0].1 && r[1].0 < 0.7 && 0.7 < r[1].1);
/// // a double root is not decided here
/// let q = Poly::new(vec![c(0.25), c(-1.0), c(1.0)]);
/// assert!(isolate_simple_roots(&q, 0.0, 1.0, 1000).is_none());
/// ```
pub fn isolate_simple_roots(
    p: &Poly<Interval>,
    lo: f64,
    hi: f64,
    max_pieces: usize,
) -> Option<Vec<(f64, f64)>> {
    if !(lo.is_finite() && hi.is_finite() && lo < hi) {
        return None;
    }
    isolate_pieces(
        (lo, hi, ()),
        max_pieces,
        |a, b, _| {
            let q = p.compose_affine(&point(a), &(point(b) - point(a)));
            strict_variations(&bernstein_enclosure(&q))
        },
        |_, _, _, _| ((), ()),
    )
}

/// The sign variations of `c` when every coefficient has a strict sign;
/// `None` when a sign is undecided (an enclosure holds 0).
fn strict_variations(c: &[Interval]) -> Option<usize> {
    let signs: Option<Vec<Sign>> = c
        .iter()
        .map(|x| match Scalar::sign(x) {
            s @ (Sign::Positive | Sign::Negative) => Some(s),
            _ => None,
        })
        .collect();
    signs.map(|s| s.windows(2).filter(|w| w[0] != w[1]).count())
}

/// The subdivision of the root isolators: pieces `(a, b, data)` depth-first
/// from `start`, left piece first (the output comes out sorted). A piece with
/// `variations(a, b, &data)` = 0 holds no root, with 1 exactly one (it is
/// returned); any other piece is halved at its midpoint `m`, `split(data, a,
/// m, b)` giving the halves' data. `None` after `max_pieces` pieces or when a
/// midpoint is not strictly inside its piece.
fn isolate_pieces<T>(
    start: (f64, f64, T),
    max_pieces: usize,
    variations: impl Fn(f64, f64, &T) -> Option<usize>,
    split: impl Fn(T, f64, f64, f64) -> (T, T),
) -> Option<Vec<(f64, f64)>> {
    let mut out = Vec::new();
    let mut stack = vec![start];
    let mut examined = 0usize;
    while let Some((a, b, data)) = stack.pop() {
        examined += 1;
        if examined > max_pieces {
            return None;
        }
        match variations(a, b, &data) {
            Some(0) => {}
            Some(1) => out.push((a, b)),
            _ => {
                let m = 0.5 * a + 0.5 * b;
                if !(a < m && m < b) {
                    return None;
                }
                let (left, right) = split(data, a, m, b);
                stack.push((m, b, right));
                stack.push((a, m, left));
            }
        }
    }
    Some(out)
}

/// [`isolate_simple_roots`] on `[0, 1]` for a polynomial given by enclosures
/// of its **Bernstein** coefficients of degree `bern.len() − 1` (for example
/// the exact Bernstein coefficients of a rational polynomial, each enclosed
/// once). Subdivision runs de Casteljau at the midpoint in interval arithmetic,
/// which stays tight where the power basis of a high-degree polynomial with
/// large coefficients cancels catastrophically. Each returned piece holds
/// exactly one root (one sign variation of strictly signed coefficients, for
/// every polynomial in the enclosures: Descartes' rule in Bernstein form) and
/// the rest of `[0, 1]` none; `None` when some piece stays undecided within
/// `max_pieces` (a multiple root, a root at a dyadic split point).
///
/// # Examples
/// ```
/// use lncert::poly::isolate_simple_roots_bernstein;
/// use lncert::scalar::Interval;
/// let c = |x: f64| Interval::try_from((x, x)).unwrap();
/// // Bernstein form of (t − 1/4)(t − 3/4) = t² − t + 3/16: [3/16, −5/16, 3/16]
/// let r = isolate_simple_roots_bernstein(&[c(0.1875), c(-0.3125), c(0.1875)], 1000).unwrap();
/// assert_eq!(r.len(), 2);
/// assert!(r[0].0 < 0.25 && 0.25 < r[0].1 && r[1].0 < 0.75 && 0.75 < r[1].1);
/// ```
pub fn isolate_simple_roots_bernstein(
    bern: &[Interval],
    max_pieces: usize,
) -> Option<Vec<(f64, f64)>> {
    if bern.is_empty() {
        return None;
    }
    let half = point(0.5);
    isolate_pieces(
        (0.0f64, 1.0f64, bern.to_vec()),
        max_pieces,
        |_, _, c| strict_variations(c),
        |c, _, _, _| {
            // de Casteljau at 1/2: the left and right coefficient lists
            let n = c.len();
            let mut work = c;
            let mut left = Vec::with_capacity(n);
            let mut right = Vec::with_capacity(n);
            for level in 0..n {
                left.push(work[0]);
                right.push(work[n - 1 - level]);
                for i in 0..n - 1 - level {
                    work[i] = (work[i] + work[i + 1]) * half;
                }
            }
            right.reverse();
            (left, right)
        },
    )
}

/// Encloses the real roots of an interval polynomial in `[lo, hi]` by
/// certified subdivision.
///
/// Pieces of `[lo, hi]` are tested with the Bernstein convex-hull property in
/// outward-rounded interval arithmetic (affine reparametrisation of the piece
/// to `[0, 1]`, then Bernstein coefficients); a piece whose coefficients all
/// have the same strict sign is proven root-free for every polynomial whose
/// coefficients lie in `p`'s intervals. Other pieces are halved while their
/// width is at least `min_width` and the float midpoint splits them, and at
/// most `max_boxes` pieces are examined in all; what is left is reported in
/// [`RootEnclosure::candidates`], sorted, with adjacent pieces merged. So
/// `excluded_everywhere == true` is a proof that there is no root in
/// `[lo, hi]`, and every root lies in some candidate. Always terminates. If the
/// ends are not finite or `lo > hi`, nothing is examined and `[lo, hi]` itself
/// is the single candidate.
///
/// # Examples
/// ```
/// use lncert::poly::{enclose_roots, Poly};
/// use lncert::scalar::Interval;
/// let c = |x: f64| Interval::try_from((x, x)).unwrap();
/// // t^2 - 1/4 = (t - 1/2)(t + 1/2): the root 1/2 is enclosed, [-0.4, 0.4] is cleared.
/// let p = Poly::new(vec![c(-0.25), c(0.0), c(1.0)]);
/// let e = enclose_roots(&p, 0.0, 1.0, 1e-6, 1000);
/// assert!(!e.excluded_everywhere);
/// assert!(e.candidates.iter().all(|&(a, b)| a <= 0.5 && 0.5 <= b && b - a < 1e-5));
/// assert!(enclose_roots(&p, -0.4, 0.4, 1e-6, 1000).excluded_everywhere);
/// ```
pub fn enclose_roots(
    p: &Poly<Interval>,
    lo: f64,
    hi: f64,
    min_width: f64,
    max_boxes: usize,
) -> RootEnclosure {
    if !(lo.is_finite() && hi.is_finite() && lo <= hi) {
        return RootEnclosure {
            candidates: vec![(lo, hi)],
            excluded_everywhere: false,
            boxes: 0,
            budget_exhausted: false,
        };
    }
    let mut raw: Vec<(f64, f64)> = Vec::new();
    // Depth-first, left piece popped first, so `raw` comes out sorted.
    let mut stack = vec![(lo, hi)];
    let mut boxes = 0usize;
    let mut budget_exhausted = false;
    while let Some((a, b)) = stack.pop() {
        if boxes >= max_boxes {
            budget_exhausted = true;
            raw.push((a, b));
            continue;
        }
        boxes += 1;
        if certified_sign(p, a, b) != Sign::Unknown {
            continue;
        }
        // a/2 + b/2 cannot overflow (b - a might).
        let m = a * 0.5 + b * 0.5;
        let splittable = b - a >= min_width && a < m && m < b;
        if splittable {
            stack.push((m, b));
            stack.push((a, m));
        } else {
            raw.push((a, b));
        }
    }
    let mut candidates: Vec<(f64, f64)> = Vec::with_capacity(raw.len());
    for (a, b) in raw {
        match candidates.last_mut() {
            Some(last) if last.1 == a => last.1 = b,
            _ => candidates.push((a, b)),
        }
    }
    RootEnclosure {
        excluded_everywhere: candidates.is_empty(),
        candidates,
        boxes,
        budget_exhausted,
    }
}

/// Tries to decide whether the interval polynomial `p` has a root in `[lo, hi]`.
///
/// `Some(true)`: proven that no polynomial with coefficients in `p`'s intervals
/// has a root in `[lo, hi]` (by [`enclose_roots`] with `min_width =
/// (hi - lo) / 2^12` and at most 4096 pieces). `Some(false)`: proven that every
/// such polynomial has a root there (a certified strict sign change between two
/// float points of `[lo, hi]`, or an enclosure of `p` at a point that is
/// exactly `{0}`). `None`: neither could be proven (for instance a double root
/// or a root of a polynomial barely touching zero), or the ends are not finite
/// with `lo <= hi`.
///
/// # Examples
/// ```
/// use lncert::poly::{certify_no_root, Poly};
/// use lncert::scalar::Interval;
/// let c = |x: f64| Interval::try_from((x, x)).unwrap();
/// let p = Poly::new(vec![c(1.0), c(0.0), c(1.0)]); // t^2 + 1
/// assert_eq!(certify_no_root(&p, -10.0, 10.0), Some(true));
/// let q = Poly::new(vec![c(-0.5), c(1.0)]); // t - 1/2
/// assert_eq!(certify_no_root(&q, 0.0, 1.0), Some(false));
/// let d = Poly::new(vec![c(0.25), c(-1.0), c(1.0)]); // (t - 1/2)^2: touches zero
/// assert_eq!(certify_no_root(&d, 0.0, 0.25), Some(true));
/// ```
pub fn certify_no_root(p: &Poly<Interval>, lo: f64, hi: f64) -> Option<bool> {
    if !(lo.is_finite() && hi.is_finite() && lo <= hi) {
        return None;
    }
    let width = hi * 0.5 - lo * 0.5; // half the width, without overflow
    let e = enclose_roots(p, lo, hi, width / 2048.0, 4096);
    if e.excluded_everywhere {
        return Some(true);
    }
    // Look for a certified root: sign of p at the ends of [lo, hi] and of the
    // candidates (all float points of [lo, hi]).
    let mut seen: Option<Sign> = None;
    let points = std::iter::once(lo)
        .chain(e.candidates.iter().flat_map(|&(a, b)| [a, b]))
        .chain(std::iter::once(hi));
    for x in points {
        match Scalar::sign(&p.eval(&point(x))) {
            Sign::Zero => return Some(false),
            Sign::Unknown => {}
            s => match seen {
                Some(t) if t != s => return Some(false),
                _ => seen = Some(s),
            },
        }
    }
    None
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::poly::{count_distinct_roots, isolate_roots, RootCount, Span};
    use crate::scalar::{rational_from_f64, IntervalExt};
    use crate::test_util::{q, qi};
    use proptest::prelude::*;

    fn lin(r: &Rational) -> Poly<Rational> {
        Poly::new(vec![-r.clone(), Rational::from_integer(1.into())])
    }
    fn to_interval(p: &Poly<Rational>) -> Poly<Interval> {
        p.map(interval_from_rational)
    }
    fn rat(x: f64) -> Rational {
        rational_from_f64(x).unwrap()
    }

    /// Checks `e` against the exact answer for the rational polynomial `p`.
    fn check_against_exact(
        p: &Poly<Rational>,
        lo: f64,
        hi: f64,
        e: &RootEnclosure,
    ) -> Result<(), String> {
        let span = Span::closed(rat(lo), rat(hi));
        let total = count_distinct_roots(p, &span);
        if e.excluded_everywhere {
            if total != RootCount::Finite(0) {
                return Err(format!("falsely excluded: {total:?} roots in [{lo}, {hi}]"));
            }
            if !e.candidates.is_empty() {
                return Err("excluded but candidates given".into());
            }
        }
        for w in e.candidates.windows(2) {
            if w[0].1 >= w[1].0 {
                return Err(format!(
                    "candidates not sorted/disjoint: {:?}",
                    e.candidates
                ));
            }
        }
        for &(a, b) in &e.candidates {
            if !(lo <= a && a <= b && b <= hi) {
                return Err(format!("candidate ({a}, {b}) outside [{lo}, {hi}]"));
            }
        }
        // Candidates are disjoint closed pieces of [lo, hi]: they cover every
        // root iff their root counts add up to the total.
        let covered: usize = e
            .candidates
            .iter()
            .map(|&(a, b)| {
                count_distinct_roots(p, &Span::closed(rat(a), rat(b)))
                    .finite()
                    .unwrap_or(usize::MAX)
            })
            .sum();
        if let RootCount::Finite(n) = total {
            if covered != n {
                return Err(format!(
                    "{n} roots but candidates cover {covered}: {:?}",
                    e.candidates
                ));
            }
        }
        // And explicitly: each isolated root meets a candidate.
        for r in isolate_roots(p, &span) {
            if !e
                .candidates
                .iter()
                .any(|&(a, b)| rat(a) <= r.hi && r.lo <= rat(b))
            {
                return Err(format!("root {r:?} not in any candidate"));
            }
        }
        Ok(())
    }

    #[test]
    fn weights_path_agrees() {
        // the cached interval weights enclose the exact Bernstein coefficients
        for n in [3usize, 10, 48, 70] {
            let p = Poly::new(
                (0..=n)
                    .map(|k| qi((k as i64 * 7919) % 23 - 11, 1 + k as i64))
                    .collect(),
            );
            let exact = p.to_bernstein(n).unwrap();
            for _ in 0..2 {
                // twice: the second call reads the cache
                let b = bernstein_enclosure(&to_interval(&p));
                assert_eq!(b.len(), n + 1);
                for (e, i) in exact.iter().zip(&b) {
                    assert!(i.contains_rational(e), "degree {n}: {e} not in {i:?}");
                }
            }
        }
        // A degree-70 polynomial goes through the big-integer path.
        let mut c = vec![interval_from_rational(&qi(1, 1)); 71];
        c[0] = interval_from_rational(&qi(-1, 3));
        let p = Poly::new(c.clone());
        let b = bernstein_enclosure(&p);
        assert_eq!(b.len(), 71);
        assert!(b[0].contains_rational(&qi(-1, 3)));
        assert!(b[70].contains(70.0 - 1.0 / 3.0) || b[70].contains_rational(&qi(209, 3)));
        // Small degree: identical to Poly::to_bernstein.
        let small = Poly::new(c[..5].to_vec());
        assert_eq!(bernstein_enclosure(&small), small.to_bernstein(4).unwrap());
        // Root exclusion works at high degree: 1 + t + ... + t^70 > 0 on [0, 1].
        let pos = Poly::new(vec![interval_from_rational(&qi(1, 1)); 71]);
        assert_eq!(certify_no_root(&pos, 0.0, 1.0), Some(true));
    }

    #[test]
    fn near_double_root_never_excluded() {
        // (t - 1/2)^2 + 1e-20: the interval coefficients also hold (t - 1/2)^2.
        let p = lin(&q("1/2"))
            .mul(&lin(&q("1/2")))
            .add(&Poly::constant(q("1e-20")));
        let pi = to_interval(&p);
        let e = enclose_roots(&pi, 0.0, 1.0, 1e-9, 10_000);
        assert!(!e.excluded_everywhere);
        assert!(e.candidates.iter().any(|&(a, b)| a <= 0.5 && 0.5 <= b));
        assert_ne!(certify_no_root(&pi, 0.0, 1.0), Some(true));
        // Two real roots 1/2 +- 1e-10: both covered.
        let m = lin(&q("1/2"))
            .mul(&lin(&q("1/2")))
            .sub(&Poly::constant(q("1e-20")));
        let e = enclose_roots(&to_interval(&m), 0.0, 1.0, 1e-12, 10_000);
        check_against_exact(&m, 0.0, 1.0, &e).unwrap();
    }

    #[test]
    fn simple_cases() {
        let one = interval_from_rational(&qi(1, 1));
        let zero = interval_from_rational(&qi(0, 1));
        let p = Poly::new(vec![one, zero, one]); // t^2 + 1
        let e = enclose_roots(&p, -100.0, 100.0, 1e-6, 1000);
        assert!(e.excluded_everywhere && e.candidates.is_empty());
        assert_eq!(certify_no_root(&p, -1e3, 1e3), Some(true));
        // Zero polynomial and zero budget: never excluded, no panic.
        let z: Poly<Interval> = Poly::zero();
        assert!(!enclose_roots(&z, 0.0, 1.0, 1e-3, 100).excluded_everywhere);
        assert_eq!(certify_no_root(&z, 0.0, 1.0), Some(false));
        let e = enclose_roots(&p, 0.0, 1.0, 1e-3, 0);
        assert_eq!(e.candidates, vec![(0.0, 1.0)]);
        assert!(e.budget_exhausted);
        // Bad ends.
        assert!(!enclose_roots(&p, 1.0, 0.0, 1e-3, 100).excluded_everywhere);
        assert!(!enclose_roots(&p, f64::NAN, 0.0, 1e-3, 100).excluded_everywhere);
        assert_eq!(certify_no_root(&p, 0.0, f64::INFINITY), None);
        // A point span.
        let lin1 = to_interval(&lin(&q("1/2")));
        assert!(!enclose_roots(&lin1, 0.5, 0.5, 0.0, 10).excluded_everywhere);
        assert!(enclose_roots(&lin1, 0.25, 0.25, 0.0, 10).excluded_everywhere);
        // Budget cap: a tiny budget still covers the root.
        let e = enclose_roots(&lin1, 0.0, 1.0, 0.0, 7);
        assert!(e.budget_exhausted && e.boxes == 7);
        check_against_exact(&lin(&q("1/2")), 0.0, 1.0, &e).unwrap();
        // min_width = 0 stops at float resolution.
        let third = lin(&q("1/3"));
        let e = enclose_roots(&to_interval(&third), 0.0, 1.0, 0.0, 100_000);
        assert!(!e.budget_exhausted);
        assert_eq!(e.candidates.len(), 1);
        let (a, b) = e.candidates[0];
        assert!(a < b && b - a <= 4.0 * f64::EPSILON, "{a} {b}");
        check_against_exact(&third, 0.0, 1.0, &e).unwrap();
        assert_eq!(certify_no_root(&to_interval(&third), 0.0, 1.0), Some(false));
        assert_eq!(certify_no_root(&to_interval(&third), 0.5, 1.0), Some(true));
    }

    fn small_rational() -> impl Strategy<Value = Rational> {
        (-12i64..=12, 1i64..=8).prop_map(|(n, d)| qi(n, d))
    }

    fn random_poly() -> impl Strategy<Value = Poly<Rational>> {
        prop_oneof![
            // Planted rational roots (with repeats) times a positive or
            // sign-changing quadratic.
            (
                prop::collection::vec((-8i64..=8, 1i64..=4), 0..5),
                small_rational(),
                small_rational(),
            )
                .prop_map(|(roots, c, k)| {
                    let mut p = Poly::new(vec![c, qi(0, 1), qi(1, 1)]); // t^2 + c
                    for (n, d) in roots {
                        p = p.mul(&lin(&qi(n, d)));
                    }
                    p.scale(&if k == qi(0, 1) { qi(1, 1) } else { k })
                }),
            // Random coefficients.
            prop::collection::vec(small_rational(), 1..7).prop_map(Poly::new),
        ]
    }

    proptest! {
        #![proptest_config(ProptestConfig::with_cases(256))]
        #[test]
        fn agrees_with_sturm(
            p in random_poly(),
            a in -40i32..=40,
            b in -40i32..=40,
            min_width in prop_oneof![Just(1e-3), Just(1e-7), Just(0.0)],
            max_boxes in prop_oneof![Just(5usize), Just(200), Just(5000)],
        ) {
            let (lo, hi) = if a <= b { (a, b) } else { (b, a) };
            let (lo, hi) = (lo as f64 / 10.0, hi as f64 / 10.0);
            let e = enclose_roots(&to_interval(&p), lo, hi, min_width, max_boxes);
            prop_assert!(e.boxes <= max_boxes);
            if let Err(msg) = check_against_exact(&p, lo, hi, &e) {
                prop_assert!(false, "{:?} on [{}, {}]: {}", p, lo, hi, msg);
            }
            match certify_no_root(&to_interval(&p), lo, hi) {
                Some(true) => prop_assert!(!has_root(&p, lo, hi)),
                Some(false) => prop_assert!(has_root(&p, lo, hi)),
                None => {}
            }
        }
    }

    fn has_root(p: &Poly<Rational>, lo: f64, hi: f64) -> bool {
        crate::poly::has_root_in(p, &Span::closed(rat(lo), rat(hi)))
    }

    proptest! {
        #![proptest_config(ProptestConfig::with_cases(2000))]
        /// Every piece `isolate_simple_roots` returns holds exactly one root
        /// (Sturm count on the closed piece, ends included), the pieces hold all
        /// the roots in `[lo, hi]` (exact count), and every root is simple.
        #[test]
        fn simple_root_isolation_agrees_with_sturm(
            p in random_poly(),
            a in -40i32..=40,
            b in -40i32..=40,
        ) {
            let (lo, hi) = if a <= b { (a, b) } else { (b, a) };
            let (lo, hi) = (lo as f64 / 10.0, hi as f64 / 10.0);
            if let Some(pieces) = isolate_simple_roots(&to_interval(&p), lo, hi, 2000) {
                let count = |l: f64, h: f64| {
                    crate::poly::isolate_roots(&p, &Span::closed(rat(l), rat(h))).len()
                };
                prop_assert_eq!(count(lo, hi), pieces.len(), "{:?} on [{}, {}]: {:?}", p, lo, hi, pieces);
                for w in pieces.windows(2) {
                    prop_assert!(w[0].1 <= w[1].0);
                }
                for &(l, h) in &pieces {
                    prop_assert!(lo <= l && l < h && h <= hi);
                    prop_assert_eq!(count(l, h), 1);
                    // the ends are not roots, so the root is inside and simple:
                    // p changes sign across the piece
                    let (pl, ph) = (p.eval(&rat(l)), p.eval(&rat(h)));
                    prop_assert!(pl.clone() * ph < Rational::from_integer(0.into()), "{:?} on ({}, {})", p, l, h);
                }
            }
        }
    }
}
