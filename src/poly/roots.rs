//! Exact real root isolation over Q: gcd, square-free part, Sturm sequences,
//! exact root counting on open / closed / half-open spans, isolating intervals
//! and their refinement by bisection. Everything is exact (`BigRational`); no
//! decision here depends on rounding.

use super::Poly;
use crate::scalar::{Rational, Scalar, Sign};
use num_traits::{One, Signed, Zero};

// ---------------------------------------------------------------------------
// Polynomial arithmetic over Q
// ---------------------------------------------------------------------------

/// Leading coefficient of a trimmed polynomial (`None` for zero).
fn leading(p: &Poly<Rational>) -> Option<&Rational> {
    p.coeffs().last()
}

/// `p / |lc(p)|`: same roots and same signs everywhere, leading coefficient ±1.
fn normalize_abs(p: Poly<Rational>) -> Poly<Rational> {
    let p = p.trimmed();
    match leading(&p) {
        Some(lc) => {
            let k = lc.abs().recip();
            p.scale(&k)
        }
        None => p,
    }
}

/// `p / lc(p)` (monic), or zero for zero.
fn monic(p: Poly<Rational>) -> Poly<Rational> {
    let p = p.trimmed();
    match leading(&p) {
        Some(lc) => {
            let k = lc.recip();
            p.scale(&k)
        }
        None => p,
    }
}

/// Euclidean division `a = q b + r` with `deg r < deg b`; `None` if `b` is zero.
pub(crate) fn div_rem(
    a: &Poly<Rational>,
    b: &Poly<Rational>,
) -> Option<(Poly<Rational>, Poly<Rational>)> {
    let b = b.clone().trimmed();
    let lb = leading(&b)?.clone();
    let db = b.coeffs().len() - 1;
    let mut r: Vec<Rational> = a.clone().trimmed().coeffs().to_vec();
    if r.len() <= db {
        return Some((Poly::zero(), Poly::new(r)));
    }
    let mut q = vec![<Rational as Zero>::zero(); r.len() - db];
    let bc = b.coeffs();
    for k in (0..q.len()).rev() {
        // The current top coefficient sits at index k + db.
        let coef = &r[k + db] / &lb;
        if !coef.is_zero() {
            for (j, bj) in bc.iter().enumerate() {
                r[k + j] -= &coef * bj;
            }
        }
        q[k] = coef;
    }
    r.truncate(db);
    Some((Poly::new(q).trimmed(), Poly::new(r).trimmed()))
}

/// The monic greatest common divisor of two polynomials over Q.
///
/// Computed by Euclid's algorithm with exact rational arithmetic, normalising
/// every remainder to be monic. The result is monic and divides both inputs;
/// every common divisor divides it. Conventions: `gcd(0, 0)` is the zero
/// polynomial and `gcd(p, 0) = gcd(0, p)` is `p` made monic. The result is
/// always trimmed (no trailing zero coefficients).
///
/// # Examples
/// ```
/// use lncert::poly::{poly_gcd, Poly};
/// use lncert::scalar::Rational;
/// let q = |n: i64| Rational::from_integer(n.into());
/// // (t-1)(t-2) = t^2 - 3t + 2 and (t-2)(t-3) = t^2 - 5t + 6
/// let a = Poly::new(vec![q(2), q(-3), q(1)]);
/// let b = Poly::new(vec![q(6), q(-5), q(1)]);
/// assert_eq!(poly_gcd(&a, &b), Poly::new(vec![q(-2), q(1)])); // t - 2
/// assert_eq!(poly_gcd(&Poly::zero(), &Poly::zero()).degree(), None);
/// ```
pub fn poly_gcd(a: &Poly<Rational>, b: &Poly<Rational>) -> Poly<Rational> {
    let mut x = monic(a.clone());
    let mut y = monic(b.clone());
    while leading(&y).is_some() {
        let (_, r) = div_rem(&x, &y).expect("y is nonzero");
        x = y;
        y = monic(r);
    }
    x
}

/// The square-free part `p / gcd(p, p')` of a polynomial over Q.
///
/// The result has exactly the same distinct complex (hence real) roots as `p`,
/// each of multiplicity one, and the same leading coefficient as `p`. A nonzero
/// constant is returned unchanged (trimmed); the zero polynomial maps to the
/// zero polynomial.
///
/// # Examples
/// ```
/// use lncert::poly::{square_free, Poly};
/// use lncert::scalar::Rational;
/// let q = |n: i64| Rational::from_integer(n.into());
/// // (t-1)^2 (t+1) = t^3 - t^2 - t + 1  ->  (t-1)(t+1) = t^2 - 1
/// let p = Poly::new(vec![q(1), q(-1), q(-1), q(1)]);
/// assert_eq!(square_free(&p), Poly::new(vec![q(-1), q(0), q(1)]));
/// ```
pub fn square_free(p: &Poly<Rational>) -> Poly<Rational> {
    let p = p.clone().trimmed();
    if leading(&p).is_none() {
        return p;
    }
    let g = poly_gcd(&p, &p.derivative());
    let (quot, _) = div_rem(&p, &g).expect("gcd of a nonzero polynomial is nonzero");
    quot
}

/// The Sturm sequence of the square-free part of `p`.
///
/// The sequence is `s0 = square_free(p)`, `s1 = s0'`, `s(i+1) = -rem(s(i-1), s(i))`,
/// each term divided by the absolute value of its leading coefficient (a
/// positive factor, so signs are preserved), stopping before the first zero
/// remainder. For `a < b`, the number of distinct real roots of `p` in the
/// half-open interval `(a, b]` equals `V(a) - V(b)`, where `V(x)` is the number
/// of sign changes (zeros skipped) of the sequence evaluated at `x`. The zero
/// polynomial gives an empty sequence; a nonzero constant gives a one-term
/// sequence.
///
/// # Examples
/// ```
/// use lncert::poly::{sturm_sequence, Poly};
/// use lncert::scalar::Rational;
/// let q = |n: i64| Rational::from_integer(n.into());
/// let s = sturm_sequence(&Poly::new(vec![q(-2), q(0), q(1)])); // t^2 - 2
/// assert_eq!(s.len(), 3); // t^2 - 2, t, 1
/// ```
pub fn sturm_sequence(p: &Poly<Rational>) -> Vec<Poly<Rational>> {
    let s0 = normalize_abs(square_free(p));
    if leading(&s0).is_none() {
        return Vec::new();
    }
    let s1 = normalize_abs(s0.derivative());
    let mut seq = vec![s0];
    if leading(&s1).is_none() {
        return seq;
    }
    seq.push(s1);
    loop {
        let n = seq.len();
        let (_, r) = div_rem(&seq[n - 2], &seq[n - 1]).expect("last term is nonzero");
        let r = normalize_abs(r.neg());
        if leading(&r).is_none() {
            break;
        }
        seq.push(r);
    }
    seq
}

/// Number of sign changes of the sequence at `x`, zeros skipped.
fn sign_changes(seq: &[Poly<Rational>], x: &Rational) -> usize {
    let mut last: Option<Sign> = None;
    let mut changes = 0;
    for s in seq {
        let v = s.eval(x).sign();
        if v == Sign::Zero {
            continue;
        }
        if last.is_some_and(|l| l != v) {
            changes += 1;
        }
        last = Some(v);
    }
    changes
}

// ---------------------------------------------------------------------------
// Spans and root counting
// ---------------------------------------------------------------------------

/// An interval of the real line with rational ends, each end open or closed.
///
/// The span is the set of `x` with `lo <= x` (or `lo < x` if `lo_closed` is
/// false) and `x <= hi` (or `x < hi`); a span with `lo > hi`, or with
/// `lo == hi` and an open end, is empty. Every counting and isolating function
/// of this module respects the openness of each end exactly.
///
/// # Examples
/// ```
/// use lncert::poly::Span;
/// use lncert::scalar::Rational;
/// let one = Rational::from_integer(1.into());
/// assert!(Span::unit_closed().contains(&one) && !Span::unit_open().contains(&one));
/// let half_open = Span { lo_closed: true, ..Span::unit_open() }; // [0, 1)
/// assert!(half_open.contains(&Rational::from_integer(0.into())));
/// assert!(Span::open(one.clone(), one).is_empty());
/// ```
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct Span {
    /// Lower end.
    pub lo: Rational,
    /// Upper end.
    pub hi: Rational,
    /// True when `lo` belongs to the span (`lo <= x`), false when open (`lo < x`).
    pub lo_closed: bool,
    /// True when `hi` belongs to the span (`x <= hi`), false when open (`x < hi`).
    pub hi_closed: bool,
}

impl Span {
    /// The closed interval `[lo, hi]`.
    pub fn closed(lo: Rational, hi: Rational) -> Self {
        Span {
            lo,
            hi,
            lo_closed: true,
            hi_closed: true,
        }
    }
    /// The open interval `(lo, hi)`.
    pub fn open(lo: Rational, hi: Rational) -> Self {
        Span {
            lo,
            hi,
            lo_closed: false,
            hi_closed: false,
        }
    }
    /// `[0, 1]`.
    pub fn unit_closed() -> Self {
        Span::closed(<Rational as Zero>::zero(), <Rational as One>::one())
    }
    /// `(0, 1)`.
    pub fn unit_open() -> Self {
        Span::open(<Rational as Zero>::zero(), <Rational as One>::one())
    }
    /// Whether the span contains no point.
    pub fn is_empty(&self) -> bool {
        self.lo > self.hi || (self.lo == self.hi && !(self.lo_closed && self.hi_closed))
    }
    /// Whether the rational `x` lies in the span (respecting open ends).
    pub fn contains(&self, x: &Rational) -> bool {
        let lo_ok = if self.lo_closed {
            &self.lo <= x
        } else {
            &self.lo < x
        };
        let hi_ok = if self.hi_closed {
            x <= &self.hi
        } else {
            x < &self.hi
        };
        lo_ok && hi_ok
    }
}

/// The result of counting roots: a finite number, or "every point is a root"
/// (the zero polynomial on a nonempty span).
///
/// `Finite(n)` is the exact number of distinct real roots; `Everywhere` is only
/// ever returned for the identically zero polynomial on a nonempty span.
///
/// # Examples
/// ```
/// use lncert::poly::{count_distinct_roots, Poly, RootCount, Span};
/// let c = count_distinct_roots(&Poly::zero(), &Span::unit_closed());
/// assert_eq!(c, RootCount::Everywhere);
/// assert!(c.any() && c.finite().is_none());
/// assert_eq!(RootCount::Finite(2).finite(), Some(2));
/// ```
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum RootCount {
    /// Exactly this many distinct real roots.
    Finite(usize),
    /// The polynomial is identically zero: every point of the span is a root.
    Everywhere,
}

impl RootCount {
    /// The finite count, or `None` for [`RootCount::Everywhere`].
    pub fn finite(self) -> Option<usize> {
        match self {
            RootCount::Finite(n) => Some(n),
            RootCount::Everywhere => None,
        }
    }
    /// Whether there is at least one root.
    pub fn any(self) -> bool {
        !matches!(self, RootCount::Finite(0))
    }
}

/// Counts in a square-free setting with a precomputed Sturm sequence.
struct Counter {
    seq: Vec<Poly<Rational>>,
}

impl Counter {
    fn new(p: &Poly<Rational>) -> Self {
        Counter {
            seq: sturm_sequence(p),
        }
    }
    /// The square-free polynomial (nonzero; caller checks `seq` is nonempty).
    fn p0(&self) -> &Poly<Rational> {
        &self.seq[0]
    }
    fn is_root(&self, x: &Rational) -> bool {
        self.p0().eval(x).is_zero()
    }
    fn v(&self, x: &Rational) -> usize {
        sign_changes(&self.seq, x)
    }
    /// Distinct roots in `span` (the sequence must be nonempty).
    fn count(&self, span: &Span) -> usize {
        if span.is_empty() {
            return 0;
        }
        if span.lo == span.hi {
            return usize::from(self.is_root(&span.lo));
        }
        // Sturm: V(lo) - V(hi) roots in (lo, hi]. V is non-increasing in x.
        let mut n = self.v(&span.lo) - self.v(&span.hi);
        if span.lo_closed && self.is_root(&span.lo) {
            n += 1;
        }
        if !span.hi_closed && self.is_root(&span.hi) {
            n -= 1;
        }
        n
    }
}

/// The number of distinct real roots of `p` in `span`, exactly.
///
/// Uses Sturm's theorem on the square-free part (which counts roots in
/// `(lo, hi]`) and decides the ends exactly by evaluating at them, so open and
/// closed ends are respected. An empty span gives `Finite(0)`. The zero
/// polynomial gives [`RootCount::Everywhere`] on a nonempty span (every point
/// is a root); a nonzero constant gives `Finite(0)`. Never panics.
///
/// # Examples
/// ```
/// use lncert::poly::{count_distinct_roots, Poly, RootCount, Span};
/// use lncert::scalar::Rational;
/// let q = |n: i64, d: i64| Rational::new(n.into(), d.into());
/// // (t - 1/2)^2 (t - 1): roots 1/2 (double) and 1.
/// let p = Poly::new(vec![q(-1, 4), q(5, 4), q(-2, 1), q(1, 1)]);
/// assert_eq!(count_distinct_roots(&p, &Span::unit_closed()), RootCount::Finite(2));
/// assert_eq!(count_distinct_roots(&p, &Span::unit_open()), RootCount::Finite(1));
/// assert_eq!(count_distinct_roots(&Poly::zero(), &Span::unit_open()), RootCount::Everywhere);
/// ```
pub fn count_distinct_roots(p: &Poly<Rational>, span: &Span) -> RootCount {
    if span.is_empty() {
        return RootCount::Finite(0);
    }
    let c = Counter::new(p);
    if c.seq.is_empty() {
        return RootCount::Everywhere;
    }
    RootCount::Finite(c.count(span))
}

/// Whether `p` has at least one real root in `span`, exactly.
///
/// True for the zero polynomial on any nonempty span; false on an empty span.
///
/// # Examples
/// ```
/// use lncert::poly::{has_root_in, Poly, Span};
/// use lncert::scalar::Rational;
/// let q = |n: i64| Rational::from_integer(n.into());
/// let p = Poly::new(vec![q(-1), q(1)]); // t - 1
/// assert!(has_root_in(&p, &Span::unit_closed()));
/// assert!(!has_root_in(&p, &Span::unit_open()));
/// ```
pub fn has_root_in(p: &Poly<Rational>, span: &Span) -> bool {
    count_distinct_roots(p, span).any()
}

/// Whether `p` and `q` have a common real root in `span`, exactly.
///
/// Decided as `has_root_in(gcd(p, q), span)`: the common roots of `p` and `q`
/// are exactly the roots of their gcd. If both are the zero polynomial, every
/// point is a common root (true on any nonempty span).
///
/// # Examples
/// ```
/// use lncert::poly::{has_common_root_in, Poly, Span};
/// use lncert::scalar::Rational;
/// let q = |n: i64, d: i64| Rational::new(n.into(), d.into());
/// let a = Poly::new(vec![q(1, 6), q(-5, 6), q(1, 1)]); // (t - 1/2)(t - 1/3)
/// let b = Poly::new(vec![q(-1, 2), q(1, 1)]); // t - 1/2
/// let c = Poly::new(vec![q(-3, 4), q(1, 1)]); // t - 3/4
/// assert!(has_common_root_in(&a, &b, &Span::unit_open()));
/// assert!(!has_common_root_in(&a, &c, &Span::unit_open()));
/// ```
pub fn has_common_root_in(p: &Poly<Rational>, q: &Poly<Rational>, span: &Span) -> bool {
    has_root_in(&poly_gcd(p, q), span)
}

// ---------------------------------------------------------------------------
// Isolation and refinement
// ---------------------------------------------------------------------------

/// An isolating interval: exactly one distinct real root of the polynomial it
/// was computed for lies in the closed interval `[lo, hi]`; `lo == hi` means
/// the root is exactly that rational.
///
/// Produced by [`isolate_roots`] / [`isolate_roots_all`] and narrowed by
/// [`refine_root`], which keep that guarantee.
///
/// # Examples
/// ```
/// use lncert::poly::RealRoot;
/// use lncert::scalar::Rational;
/// let q = |n: i64, d: i64| Rational::new(n.into(), d.into());
/// let r = RealRoot { lo: q(1, 4), hi: q(3, 4) };
/// assert!(!r.is_exact());
/// assert_eq!(r.midpoint(), q(1, 2));
/// assert_eq!(r.width(), q(1, 2));
/// assert!(RealRoot { lo: q(1, 3), hi: q(1, 3) }.is_exact());
/// ```
#[derive(Clone, Debug)]
pub struct RealRoot {
    /// Lower end of the isolating interval.
    pub lo: Rational,
    /// Upper end of the isolating interval.
    pub hi: Rational,
}

impl RealRoot {
    /// Whether the root is known exactly (`lo == hi`).
    pub fn is_exact(&self) -> bool {
        self.lo == self.hi
    }
    /// `(lo + hi) / 2` (the root itself when exact).
    pub fn midpoint(&self) -> Rational {
        (&self.lo + &self.hi) / Rational::from_integer(2.into())
    }
    /// `hi - lo`.
    pub fn width(&self) -> Rational {
        &self.hi - &self.lo
    }
}

fn mid(a: &Rational, b: &Rational) -> Rational {
    (a + b) / Rational::from_integer(2.into())
}

impl Counter {
    /// Roots in the open interval `(a, b)`, `a < b`, given `V(a)`, `V(b)`.
    fn open_count(&self, b: &Rational, va: usize, vb: usize) -> usize {
        (va - vb) - usize::from(self.is_root(b))
    }

    /// Appends, in increasing order, isolating intervals of the `n` roots in
    /// the open interval `(a, b)`; every reported interval lies strictly inside
    /// `(a, b)`, so intervals from disjoint open pieces are disjoint.
    fn isolate_open(&self, a: Rational, b: Rational, va: usize, n: usize, out: &mut Vec<RealRoot>) {
        if n == 0 {
            return;
        }
        if n == 1 {
            out.push(self.shrink_inside(a, b, va));
            return;
        }
        let m = mid(&a, &b);
        let vm = self.v(&m);
        let left = self.open_count(&m, va, vm);
        let m_root = self.is_root(&m);
        let right = n - left - usize::from(m_root);
        self.isolate_open(a, m.clone(), va, left, out);
        if m_root {
            out.push(RealRoot {
                lo: m.clone(),
                hi: m.clone(),
            });
        }
        self.isolate_open(m, b, vm, right, out);
    }

    /// Given exactly one root in the open `(a, b)`, returns an isolating
    /// interval `[l, h]` with `a < l <= h < b`.
    fn shrink_inside(&self, a: Rational, b: Rational, va: usize) -> RealRoot {
        let (mut l, mut h, mut vl) = (a.clone(), b.clone(), va);
        loop {
            if l != a && h != b {
                return RealRoot { lo: l, hi: h };
            }
            let m = mid(&l, &h);
            if self.is_root(&m) {
                return RealRoot {
                    lo: m.clone(),
                    hi: m,
                };
            }
            let vm = self.v(&m);
            // m is not a root: roots in (l, m) = V(l) - V(m).
            if vl - vm == 1 {
                h = m;
            } else {
                l = m;
                vl = vm;
            }
        }
    }
}

/// Sorted isolating intervals of all distinct real roots of `p` in `span`.
///
/// Each returned [`RealRoot`] contains exactly one distinct root of `p` in its
/// closed interval `[lo, hi]`, that root lies in `span`, and every root of `p`
/// in `span` is in exactly one returned interval. Intervals are pairwise
/// disjoint (`r[i].hi < r[i+1].lo`) and sorted increasingly. Every interval
/// lies inside the span (the ends of a non-exact interval lie strictly inside
/// it). Bisection points and span ends that are roots are reported exactly
/// (`lo == hi`). The zero polynomial (every point is a root) and an empty span
/// give an empty vector; use [`count_distinct_roots`] to tell the zero
/// polynomial apart.
///
/// # Examples
/// ```
/// use lncert::poly::{isolate_roots, Poly, Span};
/// use lncert::scalar::Rational;
/// let q = |n: i64, d: i64| Rational::new(n.into(), d.into());
/// let p = Poly::new(vec![q(1, 6), q(-5, 6), q(1, 1)]); // (t - 1/2)(t - 1/3)
/// let r = isolate_roots(&p, &Span::unit_closed());
/// assert_eq!(r.len(), 2);
/// assert!(r[0].lo <= q(1, 3) && q(1, 3) <= r[0].hi);
/// assert!(r[1].is_exact() && r[1].lo == q(1, 2)); // the first bisection point
/// ```
pub fn isolate_roots(p: &Poly<Rational>, span: &Span) -> Vec<RealRoot> {
    let mut out = Vec::new();
    if span.is_empty() {
        return out;
    }
    let c = Counter::new(p);
    if c.seq.is_empty() {
        return out;
    }
    if span.lo == span.hi {
        if c.is_root(&span.lo) {
            out.push(RealRoot {
                lo: span.lo.clone(),
                hi: span.lo.clone(),
            });
        }
        return out;
    }
    if span.lo_closed && c.is_root(&span.lo) {
        out.push(RealRoot {
            lo: span.lo.clone(),
            hi: span.lo.clone(),
        });
    }
    let (va, vb) = (c.v(&span.lo), c.v(&span.hi));
    let n = c.open_count(&span.hi, va, vb);
    c.isolate_open(span.lo.clone(), span.hi.clone(), va, n, &mut out);
    if span.hi_closed && c.is_root(&span.hi) {
        out.push(RealRoot {
            lo: span.hi.clone(),
            hi: span.hi.clone(),
        });
    }
    out
}

/// Narrows an isolating interval of a root of `p` to width at most `width`.
///
/// Bisects `[lo, hi]` exactly, keeping the half where the square-free part of
/// `p` changes sign; if a bisection point (or an end) is the root, the result
/// is exact (`lo == hi`). Exact inputs are returned unchanged. The result is an
/// isolating interval of the same root, contained in the input, with
/// `hi - lo <= width`. If `width` is not positive the target cannot be met for
/// an irrational root, so the input is returned unchanged; if `root` is not an
/// isolating interval of a root of `p` (or `p` is zero), the input is also
/// returned unchanged. Never panics.
///
/// # Examples
/// ```
/// use lncert::poly::{isolate_roots, refine_root, Poly, Span};
/// use lncert::scalar::Rational;
/// let q = |n: i64, d: i64| Rational::new(n.into(), d.into());
/// let p = Poly::new(vec![q(-2, 1), q(0, 1), q(1, 1)]); // t^2 - 2
/// let r = isolate_roots(&p, &Span::closed(q(0, 1), q(2, 1)));
/// let r = refine_root(&p, &r[0], &q(1, 1000000));
/// assert!(r.width() <= q(1, 1000000));
/// assert!(&r.lo * &r.lo < q(2, 1) && q(2, 1) < &r.hi * &r.hi);
/// ```
pub fn refine_root(p: &Poly<Rational>, root: &RealRoot, width: &Rational) -> RealRoot {
    if root.is_exact() || !width.is_positive() || root.lo > root.hi {
        return root.clone();
    }
    let p0 = square_free(p);
    if leading(&p0).is_none() {
        return root.clone();
    }
    let (mut l, mut h) = (root.lo.clone(), root.hi.clone());
    let mut sl = p0.eval(&l).sign();
    let sh = p0.eval(&h).sign();
    if sl == Sign::Zero {
        return RealRoot {
            lo: l.clone(),
            hi: l,
        };
    }
    if sh == Sign::Zero {
        return RealRoot {
            lo: h.clone(),
            hi: h,
        };
    }
    if sl == sh {
        // Not an isolating interval of a (necessarily simple) root of p0.
        return root.clone();
    }
    while &h - &l > *width {
        let m = mid(&l, &h);
        let sm = p0.eval(&m).sign();
        if sm == Sign::Zero {
            return RealRoot {
                lo: m.clone(),
                hi: m,
            };
        }
        if sm == sl {
            l = m;
            sl = sm;
        } else {
            h = m;
        }
    }
    RealRoot { lo: l, hi: h }
}

/// Cauchy's bound: every real root `x` of `p` satisfies `|x| <= bound`.
///
/// The bound is `1 + max |a_i / a_n|` over the trimmed coefficients (`a_n` the
/// leading one), in fact a strict bound `|x| < bound`. A nonzero constant
/// (no roots) gives 1. The zero polynomial has every point as a root, so no
/// bound exists; it gives 0 by convention.
///
/// # Examples
/// ```
/// use lncert::poly::{root_bound, Poly};
/// use lncert::scalar::Rational;
/// let q = |n: i64| Rational::from_integer(n.into());
/// let p = Poly::new(vec![q(-6), q(1), q(1)]); // (t + 3)(t - 2)
/// assert_eq!(root_bound(&p), q(7));
/// ```
pub fn root_bound(p: &Poly<Rational>) -> Rational {
    let p = p.clone().trimmed();
    let Some(lc) = leading(&p) else {
        return <Rational as Zero>::zero();
    };
    let lc = lc.abs();
    let n = p.coeffs().len() - 1;
    let max = p.coeffs()[..n]
        .iter()
        .map(|a| a.abs() / &lc)
        .max()
        .unwrap_or_else(<Rational as Zero>::zero);
    <Rational as One>::one() + max
}

/// Sorted, disjoint isolating intervals of all distinct real roots of `p`.
///
/// Same guarantees as [`isolate_roots`] on the closed span
/// `[-root_bound(p), root_bound(p)]`, which contains every real root. The zero
/// polynomial gives an empty vector.
///
/// # Examples
/// ```
/// use lncert::poly::{isolate_roots_all, Poly};
/// use lncert::scalar::Rational;
/// let q = |n: i64| Rational::from_integer(n.into());
/// let p = Poly::new(vec![q(-6), q(1), q(1)]); // (t + 3)(t - 2)
/// let r = isolate_roots_all(&p);
/// assert_eq!(r.len(), 2);
/// assert!(r[0].lo <= q(-3) && q(-3) <= r[0].hi && r[1].lo <= q(2) && q(2) <= r[1].hi);
/// ```
pub fn isolate_roots_all(p: &Poly<Rational>) -> Vec<RealRoot> {
    let b = root_bound(p);
    isolate_roots(p, &Span::closed(-b.clone(), b))
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::test_util::{q, qi};
    use proptest::prelude::*;

    /// `t - r`.
    fn lin(r: &Rational) -> Poly<Rational> {
        Poly::new(vec![-r.clone(), <Rational as One>::one()])
    }
    fn prod(fs: &[Poly<Rational>]) -> Poly<Rational> {
        fs.iter()
            .fold(Poly::constant(<Rational as One>::one()), |acc, f| {
                acc.mul(f)
            })
    }
    fn fin(n: usize) -> RootCount {
        RootCount::Finite(n)
    }
    fn sample() -> Poly<Rational> {
        // (t - 1/3)(t - 1/2)(t + 2)^2
        prod(&[lin(&q("1/3")), lin(&q("1/2")), lin(&q("-2")), lin(&q("-2"))])
    }
    fn assert_sorted_disjoint(r: &[RealRoot]) {
        for x in r {
            assert!(x.lo <= x.hi, "{x:?}");
        }
        for w in r.windows(2) {
            assert!(w[0].hi < w[1].lo, "not disjoint: {:?} {:?}", w[0], w[1]);
        }
    }

    #[test]
    fn counts_on_sample() {
        let p = sample();
        assert_eq!(count_distinct_roots(&p, &Span::unit_closed()), fin(2));
        assert_eq!(count_distinct_roots(&p, &Span::unit_open()), fin(2));
        assert_eq!(
            count_distinct_roots(&p, &Span::open(q("0"), q("1/2"))),
            fin(1)
        );
        assert_eq!(
            count_distinct_roots(&p, &Span::closed(q("0"), q("1/2"))),
            fin(2)
        );
        assert_eq!(
            count_distinct_roots(&p, &Span::closed(q("-3"), q("1"))),
            fin(3)
        );
        assert_eq!(
            count_distinct_roots(&p, &Span::open(q("-2"), q("1/3"))),
            fin(0)
        );
        assert_eq!(
            count_distinct_roots(&p, &Span::closed(q("-2"), q("1/3"))),
            fin(2)
        );
        let half_open = Span {
            lo: q("-2"),
            hi: q("1/3"),
            lo_closed: false,
            hi_closed: true,
        };
        assert_eq!(count_distinct_roots(&p, &half_open), fin(1));
        assert!(has_root_in(&p, &Span::unit_open()));
        assert!(!has_root_in(&p, &Span::open(q("1/2"), q("1"))));
    }

    #[test]
    fn wilkinson_like_sevenths() {
        let roots: Vec<Rational> = (1..=6).map(|k| qi(k, 7)).collect();
        let p = prod(&roots.iter().map(lin).collect::<Vec<_>>());
        assert_eq!(count_distinct_roots(&p, &Span::unit_open()), fin(6));
        let iso = isolate_roots(&p, &Span::unit_closed());
        assert_eq!(iso.len(), 6);
        assert_sorted_disjoint(&iso);
        for (k, r) in roots.iter().enumerate() {
            assert!(iso[k].lo <= *r && *r <= iso[k].hi, "{k}: {:?}", iso[k]);
            let inside = Span::closed(iso[k].lo.clone(), iso[k].hi.clone());
            assert_eq!(count_distinct_roots(&p, &inside), fin(1));
            let fine = refine_root(&p, &iso[k], &qi(1, 1000));
            assert!(fine.width() <= qi(1, 1000));
            assert!(fine.lo <= *r && *r <= fine.hi);
        }
        // Also with multiplicities: same isolation.
        let p2 = p.mul(&lin(&roots[2])).mul(&lin(&roots[4]));
        let iso2 = isolate_roots(&p2, &Span::unit_closed());
        assert_eq!(iso2.len(), 6);
        assert_sorted_disjoint(&iso2);
    }

    #[test]
    fn roots_at_span_ends() {
        // (t)(t - 1)(t - 1/3): roots at both ends of the unit span.
        let p = prod(&[lin(&q("0")), lin(&q("1")), lin(&q("1/3"))]);
        assert_eq!(count_distinct_roots(&p, &Span::unit_closed()), fin(3));
        assert_eq!(count_distinct_roots(&p, &Span::unit_open()), fin(1));
        let lo_closed = Span {
            lo_closed: true,
            ..Span::unit_open()
        };
        let hi_closed = Span {
            hi_closed: true,
            ..Span::unit_open()
        };
        assert_eq!(count_distinct_roots(&p, &lo_closed), fin(2));
        assert_eq!(count_distinct_roots(&p, &hi_closed), fin(2));

        let iso = isolate_roots(&p, &Span::unit_closed());
        assert_eq!(iso.len(), 3);
        assert_sorted_disjoint(&iso);
        assert!(iso[0].is_exact() && iso[0].lo == q("0"));
        assert!(iso[2].is_exact() && iso[2].lo == q("1"));
        assert!(iso[1].lo > q("0") && iso[1].hi < q("1"));
        let iso = isolate_roots(&p, &Span::unit_open());
        assert_eq!(iso.len(), 1);
        assert!(iso[0].lo > q("0") && iso[0].hi < q("1"));
        assert_eq!(isolate_roots(&p, &lo_closed).len(), 2);
        assert_eq!(isolate_roots(&p, &hi_closed).len(), 2);

        // Degenerate spans.
        let pt = Span::closed(q("1/3"), q("1/3"));
        assert_eq!(count_distinct_roots(&p, &pt), fin(1));
        assert_eq!(isolate_roots(&p, &pt).len(), 1);
        let empty = Span::open(q("1/3"), q("1/3"));
        assert!(empty.is_empty());
        assert_eq!(count_distinct_roots(&p, &empty), fin(0));
        assert_eq!(
            count_distinct_roots(&p, &Span::closed(q("1"), q("0"))),
            fin(0)
        );
        assert!(isolate_roots(&p, &Span::closed(q("1"), q("0"))).is_empty());
    }

    #[test]
    fn sqrt2_refined() {
        let p = Poly::new(vec![q("-2"), q("0"), q("1")]);
        let iso = isolate_roots(&p, &Span::closed(q("0"), q("2")));
        assert_eq!(iso.len(), 1);
        let w = q("1e-30");
        let r = refine_root(&p, &iso[0], &w);
        assert!(r.width() <= w);
        assert!(&r.lo * &r.lo < q("2") && q("2") < &r.hi * &r.hi);
        // Whole line: both roots.
        let all = isolate_roots_all(&p);
        assert_eq!(all.len(), 2);
        assert_sorted_disjoint(&all);
        let neg = refine_root(&p, &all[0], &w);
        assert!(neg.hi < q("0") && &neg.lo * &neg.lo > q("2") && &neg.hi * &neg.hi < q("2"));
        // Non-positive width leaves the interval unchanged.
        let same = refine_root(&p, &iso[0], &q("0"));
        assert_eq!((same.lo, same.hi), (iso[0].lo.clone(), iso[0].hi.clone()));
    }

    #[test]
    fn refine_hits_exact_root() {
        let p = lin(&q("1/4"));
        let r = refine_root(
            &p,
            &RealRoot {
                lo: q("0"),
                hi: q("1"),
            },
            &q("1/1000"),
        );
        assert!(r.is_exact() && r.lo == q("1/4"));
        let r = refine_root(
            &p,
            &RealRoot {
                lo: q("1/4"),
                hi: q("1"),
            },
            &q("1/1000"),
        );
        assert!(r.is_exact() && r.lo == q("1/4"));
        assert_eq!(
            RealRoot {
                lo: q("1"),
                hi: q("2")
            }
            .midpoint(),
            q("3/2")
        );
    }

    #[test]
    fn gcd_and_square_free() {
        let a = prod(&[lin(&q("1")), lin(&q("2"))]);
        let b = prod(&[lin(&q("2")), lin(&q("3"))]);
        assert_eq!(poly_gcd(&a, &b), lin(&q("2")));
        assert_eq!(
            poly_gcd(&a.scale(&q("-3/5")), &b.scale(&q("7"))),
            lin(&q("2"))
        );
        assert_eq!(poly_gcd(&Poly::zero(), &Poly::zero()), Poly::zero());
        assert_eq!(poly_gcd(&a.scale(&q("4")), &Poly::zero()), a);
        assert_eq!(poly_gcd(&Poly::zero(), &a.scale(&q("-2"))), a);
        assert_eq!(poly_gcd(&a, &lin(&q("5"))), Poly::constant(q("1")));
        let sq = prod(&[
            lin(&q("1")),
            lin(&q("1")),
            lin(&q("2")),
            lin(&q("2")),
            lin(&q("2")),
        ]);
        assert_eq!(square_free(&sq), a);
        assert!(has_common_root_in(&a, &b, &Span::closed(q("0"), q("2"))));
        assert!(!has_common_root_in(&a, &b, &Span::open(q("0"), q("2"))));
        assert!(!has_common_root_in(
            &a,
            &lin(&q("5")),
            &Span::closed(q("-10"), q("10"))
        ));
    }

    #[test]
    fn zero_and_constants_do_not_panic() {
        let z: Poly<Rational> = Poly::zero();
        let z2 = Poly::new(vec![q("0"), q("0")]);
        let c = Poly::constant(q("3"));
        for p in [&z, &z2] {
            assert_eq!(
                count_distinct_roots(p, &Span::unit_open()),
                RootCount::Everywhere
            );
            assert_eq!(count_distinct_roots(p, &Span::open(q("1"), q("1"))), fin(0));
            assert!(has_root_in(p, &Span::unit_closed()));
            assert!(isolate_roots(p, &Span::unit_closed()).is_empty());
            assert!(isolate_roots_all(p).is_empty());
            assert!(sturm_sequence(p).is_empty());
            assert_eq!(square_free(p), Poly::zero());
            assert_eq!(root_bound(p), q("0"));
            let r = RealRoot {
                lo: q("0"),
                hi: q("1"),
            };
            assert_eq!(refine_root(p, &r, &q("1/10")).hi, q("1"));
        }
        assert_eq!(count_distinct_roots(&c, &Span::unit_closed()), fin(0));
        assert!(!has_root_in(&c, &Span::unit_closed()));
        assert!(isolate_roots(&c, &Span::unit_closed()).is_empty());
        assert!(isolate_roots_all(&c).is_empty());
        assert_eq!(sturm_sequence(&c).len(), 1);
        assert_eq!(root_bound(&c), q("1"));
        assert!(!has_common_root_in(&z, &c, &Span::unit_closed()));
        assert!(has_common_root_in(&z, &z, &Span::unit_closed()));
    }

    fn small_rational() -> impl Strategy<Value = Rational> {
        (-12i64..=12, 1i64..=6).prop_map(|(n, d)| qi(n, d))
    }

    proptest! {
        #![proptest_config(ProptestConfig::with_cases(256))]
        #[test]
        fn planted_roots_are_counted(
            roots in prop::collection::vec(small_rational(), 0..6),
            lead in (1i64..=5, 1i64..=4, any::<bool>()),
            a in small_rational(),
            b in small_rational(),
            ends in (any::<bool>(), any::<bool>()),
        ) {
            let (n, d, neg) = lead;
            let k = if neg { qi(-n, d) } else { qi(n, d) };
            let irreducible = Poly::new(vec![q("1"), q("0"), q("1")]); // t^2 + 1
            let p = prod(&roots.iter().map(lin).collect::<Vec<_>>()).mul(&irreducible).scale(&k);
            let (lo, hi) = if a <= b { (a, b) } else { (b, a) };
            let span = Span { lo, hi, lo_closed: ends.0, hi_closed: ends.1 };
            let mut distinct = roots.clone();
            distinct.sort();
            distinct.dedup();
            let expected = distinct.iter().filter(|r| span.contains(r)).count();
            prop_assert_eq!(count_distinct_roots(&p, &span), RootCount::Finite(expected));
            let iso = isolate_roots(&p, &span);
            prop_assert_eq!(iso.len(), expected);
            for w in iso.windows(2) {
                prop_assert!(w[0].hi < w[1].lo);
            }
            let inside: Vec<&Rational> = distinct.iter().filter(|r| span.contains(r)).collect();
            for (r, x) in iso.iter().zip(inside) {
                prop_assert!(r.lo <= *x && *x <= r.hi);
            }
        }
    }
}
