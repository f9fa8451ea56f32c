//! Beyond the paper (seed 003 §4.3 asks for it, §5 says it was not
//! implemented): for a fixed centre `O`, the set of signed radii `r` for which a
//! quartic LN curve of the family, nonsingular on `[0, u]`, is tangent to the
//! circle `(O, r)` at a parameter `m ∈ [0, u]`.
//!
//! # Method
//!
//! Eq. (7), `A(m) a2 + B(m) = 0`, does not involve `r`: for `m ∈ (0, u)` with
//! `A(m) ≠ 0` the tangent quartic is `a2(m) = -B(m)/A(m)`, and eq. (6) then
//! *defines* the radius: `|r| = |O - K(m)|`, signed by the side convention of
//! [`super::solve`]: since `O - K(m) ∥ (m, 1)`,
//! `ρ(m) = (O - K(m))·(m, 1)/√(1 + m²)`. So the set is `ρ(M)` with
//! `M = {m ∈ (0, u) : A(m) ≠ 0, a2(m) ∈ N}`, `N` the open nonsingular interval
//! (corrected Prop 3.2), plus the end points below.
//!
//! The ends of `N` are among `α0, α1` (roots of Prop 3.1's `D(a2)`), `0` and `α2`,
//! so membership in `M` can change only at roots in `(0, u)` of the exact
//! rational polynomials `A`, `B`, `B + α2 A` and `D(-B/A)·A²`. These are isolated
//! exactly (Sturm) and refined to tiny *slivers*; between consecutive slivers
//! membership is constant and decided exactly at a rational sample point
//! ([`HermiteData::nonsingular_a2_contains`] over Q). For each valid gap:
//!
//! * **inner** enclosure: `ρ` is continuous on the gap, so by the intermediate
//!   value theorem `ρ(gap) ⊇ [min_i sup ρ(s_i), max_i inf ρ(s_i)]` for sample
//!   points `s_i` (interval-evaluated);
//! * **outer** enclosure: an interval branch-and-bound enclosure of `ρ` over the
//!   gap widened to the far ends of its two slivers (where the true boundary
//!   lies), refining the pieces that stick out of the sampled range.
//!
//! The slivers adjacent to valid gaps are reported as undecided `m`-intervals:
//! the true set lies between the union of the inner and the union of the outer
//! intervals. Common roots of `A` and `B` in `(0, u)` (a line of solutions in
//! `a2` at one `m`) are not handled and make the answer incomplete.
//!
//! **End points.** `K(0) = (0, 0)` with normal `(0, 1)` and `K(u) = (x1, y1)`
//! with normal `(u, 1)` for every `a2`: if `O` lies on one of these normal
//! lines, the circle through that point is tangent to every quartic, so that
//! single radius is valid iff a nonsingular quartic exists (Prop 3.2).

use super::krawczyk::{iv, pt};
use super::system::{TangencyError, TangencySystem};
use crate::ln::hermite::HermiteData;
use crate::poly::{isolate_roots, poly_gcd, square_free, Poly, Span};
use crate::scalar::{interval_from_rational, Interval, Rational, Scalar};
use num_traits::{One, Zero};

/// One valid component of the radius set.
#[derive(Clone, Copy, Debug)]
pub struct RadiusComponent {
    /// The `m`-gap on which membership is certain.
    pub m: Interval,
    /// Certified inner interval (`None` if the samples do not span one).
    pub inner: Option<Interval>,
    /// Certified outer enclosure (may be unbounded).
    pub outer: Interval,
}

/// The set of valid signed radii for a fixed centre.
#[derive(Clone, Debug, Default)]
pub struct RadiiSet {
    /// Components from tangency at `m ∈ (0, u)`.
    pub components: Vec<RadiusComponent>,
    /// Single valid radii from tangency at `m = 0` or `m = u` (enclosures).
    pub end_points: Vec<Interval>,
    /// `m`-slivers next to valid gaps where membership is not decided.
    pub undecided_m: Vec<Interval>,
    /// False when an unhandled degenerate case occurred.
    pub complete: bool,
}

impl RadiiSet {
    /// Certified inner intervals (each a subset of the true set).
    pub fn inner(&self) -> Vec<Interval> {
        let mut v: Vec<Interval> = self.components.iter().filter_map(|c| c.inner).collect();
        v.extend(self.end_points.iter().copied());
        v
    }
    /// Certified outer intervals (their union contains the true set).
    pub fn outer(&self) -> Vec<Interval> {
        let mut v: Vec<Interval> = self.components.iter().map(|c| c.outer).collect();
        v.extend(self.end_points.iter().copied());
        v
    }
}

fn rat(n: i64) -> Rational {
    Rational::from_integer(n.into())
}

/// `ρ(m) = P(m)/(A(m)√(1 + m²))` with the exact polynomial
/// `P = A·((Ox - x0)m + (Oy - y0)) + B·(gx m + gy)`, where `K = (x0, y0) + a2 (gx, gy)`
/// (so `P/A = (O - K(m))·(m, 1)` at `a2 = -B/A`); `P` and `A` are enclosed in
/// the centred form (Taylor shift to the midpoint of the `m`-interval).
struct Rho {
    a: Poly<Interval>,
    p: Poly<Interval>,
}

/// Centred-form enclosure of a univariate polynomial over `m`.
fn centred(p: &Poly<Interval>, m: Interval) -> Interval {
    let c = m.mid();
    let ci = pt(c);
    let mut s: Vec<Interval> = p.coeffs().to_vec();
    let n = s.len();
    for k in 0..n.saturating_sub(1) {
        for i in (k..n - 1).rev() {
            s[i] = s[i + 1].mul_add(ci, s[i]);
        }
    }
    let h = m - ci;
    s.iter().rev().fold(pt(0.0), |acc, a| acc.mul_add(h, *a))
}

impl Rho {
    fn new(sys: &TangencySystem, a: &Poly<Rational>, b: &Poly<Rational>) -> Self {
        let (x0, gx) = (sys.x.y_coefficient(0), sys.x.y_coefficient(1));
        let (y0, gy) = (sys.y.y_coefficient(0), sys.y.y_coefficient(1));
        let t = Poly::t();
        let w0 = Poly::constant(sys.ox.clone())
            .sub(&x0)
            .mul(&t)
            .add(&Poly::constant(sys.oy.clone()).sub(&y0));
        let gm = gx.mul(&t).add(&gy);
        let p = w0.mul(a).add(&b.mul(&gm));
        Rho {
            a: a.map(interval_from_rational),
            p: p.map(interval_from_rational),
        }
    }
    fn eval(&self, m: Interval) -> Interval {
        let den = centred(&self.a, m) * (pt(1.0) + m.sqr()).sqrt();
        Scalar::div(&centred(&self.p, m), &den).unwrap_or(Interval::ENTIRE)
    }
    /// Outer enclosure over `m` by breadth-first branch and bound: pieces
    /// whose enclosure sticks out of the best known range (grown by midpoint
    /// samples) by more than a tolerance are bisected, at most `budget` times;
    /// the result is the hull of the enclosures of all final pieces.
    fn outer(&self, m: Interval, known: &mut Interval, mut budget: usize) -> Interval {
        let mut queue = std::collections::VecDeque::from([m]);
        let mut out: Option<Interval> = None;
        while let Some(piece) = queue.pop_front() {
            let v = self.eval(piece);
            let tol = 1e-7 * (1.0 + known.mag() + known.wid());
            let sticks_out = v.inf() < known.inf() - tol || v.sup() > known.sup() + tol;
            if budget == 0 || !sticks_out || piece.wid() < 1e-13 * (1.0 + piece.mag()) {
                out = Some(out.map_or(v, |o| o.convex_hull(v)));
                continue;
            }
            budget -= 1;
            let mid = piece.mid();
            let at_mid = self.eval(pt(mid));
            if at_mid.is_finite() {
                *known = known.convex_hull(at_mid);
            }
            queue.push_back(iv(piece.inf(), mid));
            queue.push_back(iv(mid, piece.sup()));
        }
        out.unwrap_or(Interval::ENTIRE)
    }
}

/// Narrows an isolating interval `[lo, hi]` of a simple root of the
/// square-free `p` by exact bisection to width `<= width` (exact root: `lo = hi`).
fn bisect_root(
    p: &Poly<Rational>,
    mut lo: Rational,
    mut hi: Rational,
    width: &Rational,
) -> (Rational, Rational) {
    let s_lo = p.eval(&lo).sign();
    if s_lo == crate::scalar::Sign::Zero {
        return (lo.clone(), lo);
    }
    if p.eval(&hi).sign() == crate::scalar::Sign::Zero {
        return (hi.clone(), hi);
    }
    for _ in 0..200 {
        if &(&hi - &lo) <= width {
            break;
        }
        let mid = (&lo + &hi) / rat(2);
        let sm = p.eval(&mid).sign();
        if sm == crate::scalar::Sign::Zero {
            return (mid.clone(), mid);
        }
        if sm == s_lo {
            lo = mid;
        } else {
            hi = mid;
        }
    }
    (lo, hi)
}

/// The valid signed radii for the centre `(ox, oy)` (see the module docs).
///
/// # Examples
/// ```
/// use lncert::tangency::valid_radii;
/// use lncert::ln::hermite::HermiteData;
/// use lncert::scalar::frac;
/// let h = HermiteData::new(frac(3, 1), frac(-1, 1), frac(1, 1)).unwrap();
/// let set = valid_radii(&h, &frac(15, 16), &frac(-319, 128)).unwrap();
/// // r = -5/2 is valid (two nonsingular tangent quartics, tests/tangency.rs).
/// assert!(set.outer().iter().any(|o| o.contains(-2.5)));
/// ```
pub fn valid_radii(
    h: &HermiteData<Rational>,
    ox: &Rational,
    oy: &Rational,
) -> Result<RadiiSet, TangencyError> {
    let sys = TangencySystem::new(
        h.x1.clone(),
        h.y1.clone(),
        h.u.clone(),
        ox.clone(),
        oy.clone(),
        rat(1),
    )?;
    let u = h.u.clone();
    let zero = <Rational as Zero>::zero();
    let mut set = RadiiSet {
        complete: true,
        ..RadiiSet::default()
    };
    let exists = h.prop_3_2_exists() == Some(true);
    // End points.
    if exists {
        if ox.is_zero() {
            set.end_points.push(interval_from_rational(oy));
        }
        // O = (x1, y1) + t (u, 1)  <=>  (Ox - x1) = u (Oy - y1).
        let t = oy - &h.y1;
        if ox - &h.x1 == &u * &t {
            let s = (pt(1.0) + interval_from_rational(&u).sqr()).sqrt();
            set.end_points.push(interval_from_rational(&t) * s);
        }
    }
    if !exists {
        return Ok(set);
    }
    let (a, b) = sys.eq7_linear();
    let g = square_free(&poly_gcd(&a, &b));
    if g.clone().trimmed().degree().unwrap_or(0) > 0
        && !isolate_roots(&g, &Span::open(zero.clone(), u.clone())).is_empty()
    {
        set.complete = false;
    }
    // Breakpoints: A, B, B + α2 A, D(-B/A) A².
    let (da, db, dc) = h.d_coefficients();
    let dnum = b
        .mul(&b)
        .scale(&da)
        .sub(&a.mul(&b).scale(&db))
        .add(&a.mul(&a).scale(&dc));
    let tiny = &u * Rational::new(One::one(), num_bigint::BigInt::from(1u64 << 36));
    let mut slivers: Vec<(Rational, Rational)> = Vec::new();
    for f in [a.clone(), b.clone(), b.add(&a.scale(&h.alpha2())), dnum] {
        let f = f.trimmed();
        if f.coeffs().is_empty() {
            continue;
        }
        let sq = square_free(&f);
        for r in isolate_roots(&sq, &Span::open(zero.clone(), u.clone())) {
            slivers.push(bisect_root(&sq, r.lo, r.hi, &tiny));
        }
    }
    // Sorted, overlapping slivers merged (membership is constant between them).
    slivers.sort_by(|x, y| x.0.cmp(&y.0));
    let mut merged: Vec<(Rational, Rational)> = Vec::new();
    for sl in slivers {
        match merged.last_mut() {
            Some(last) if sl.0 <= last.1 => {
                if sl.1 > last.1 {
                    last.1 = sl.1;
                }
            }
            _ => merged.push(sl),
        }
    }
    let rho = Rho::new(&sys, &a, &b);
    // Gaps between slivers: (prev.hi, next.lo); outer span (prev.lo, next.hi).
    let mut ends: Vec<(Rational, Rational)> = vec![(zero.clone(), zero)];
    ends.extend(merged);
    ends.push((u.clone(), u));
    for w in ends.windows(2) {
        let (g_lo, g_hi) = (&w[0].1, &w[1].0);
        if g_lo >= g_hi {
            continue;
        }
        let mid = (g_lo + g_hi) / rat(2);
        let am = a.eval(&mid);
        if am.is_zero() {
            set.complete = false;
            continue;
        }
        let a2 = -b.eval(&mid) / am;
        match h.nonsingular_a2_contains(&a2) {
            Some(true) => {}
            Some(false) => continue,
            None => {
                set.complete = false;
                continue;
            }
        }
        let gap = interval_from_rational(g_lo).convex_hull(interval_from_rational(g_hi));
        // Samples strictly inside the gap.
        let n = 16;
        let mut samples = Vec::with_capacity(n);
        for k in 1..n {
            let s = g_lo + (g_hi - g_lo) * Rational::new((k as i64).into(), (n as i64).into());
            samples.push(rho.eval(interval_from_rational(&s)));
        }
        let lo_h = samples
            .iter()
            .map(|v| v.sup())
            .fold(f64::INFINITY, f64::min);
        let hi_l = samples
            .iter()
            .map(|v| v.inf())
            .fold(f64::NEG_INFINITY, f64::max);
        let inner = (lo_h <= hi_l).then(|| iv(lo_h, hi_l));
        let mut known = samples
            .iter()
            .fold(samples[0], |acc, v| acc.convex_hull(*v));
        let span = interval_from_rational(&w[0].0).convex_hull(interval_from_rational(&w[1].1));
        let outer = rho.outer(span, &mut known, 4000);
        if w[0].0 != w[0].1 {
            set.undecided_m
                .push(interval_from_rational(&w[0].0).convex_hull(interval_from_rational(&w[0].1)));
        }
        if w[1].0 != w[1].1 {
            set.undecided_m
                .push(interval_from_rational(&w[1].0).convex_hull(interval_from_rational(&w[1].1)));
        }
        set.components.push(RadiusComponent {
            m: gap,
            inner,
            outer,
        });
    }
    set.undecided_m.retain(|m| m.wid() > 0.0);
    set.undecided_m
        .dedup_by(|x, y| x.inf() == y.inf() && x.sup() == y.sup());
    Ok(set)
}
