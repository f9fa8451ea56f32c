//! Certified intersections of polynomial Bézier pieces: the crossings between
//! pieces and the self-intersections of a piece, complete over the whole
//! parameter domain.
//!
//! # Method
//!
//! Pieces `A(s)`, `B(t)` (exact rational control points) meet where
//! `A(s) − B(t) = 0`, a 2×2 polynomial system in `(s, t) ∈ [0, 1]²`, solved by
//! the complete interval solver of the tangency module
//! ([`crate::tangency::complete::solve`]: Krawczyk's operator proves each
//! transversal crossing unique in a box, and every other box is excluded by an
//! enclosure or by Krawczyk; what is left is reported undecided). A piece meets
//! itself where the divided difference `(A(s) − A(t))/(s − t) = 0` with
//! `s < t` (the diagonal `s = t` of that system is where `A′ = 0`: a singular
//! point, reported undecided when a box there cannot be excluded).
//!
//! Pairs whose control-point boxes are disjoint cannot meet (convex hull
//! property, compared exactly). Pieces that share an end point exactly (the
//! joints of a spline, the closing point of a contour) meet there by
//! construction; that contact is proven to be the **only** one in a corner
//! `[s₀ ± ε] × [t₀ ± ε]` of the domain by a projection: with a rational
//! direction `d`, `d · A` strictly decreases and `d · B` strictly increases as
//! the parameters leave the shared point (the exact Bernstein coefficients of
//! `d · A′`, `d · B′` over the corner have one strict sign), so `A(s) = B(t)`
//! there forces `s = s₀`, `t = t₀`. The rest of the domain is solved as above.
//! Where both leave in (nearly) the same direction (a cusp at the joint), a
//! second-order argument on both pieces as graphs over one direction decides
//! instead ([`isolate_tangential_joint`]); a joint neither decides (a
//! tangential contact or an overlap) is reported undecided. A piece whose hodograph's
//! control points lie strictly on one side of a line through 0 (proven in
//! outward rounded intervals) is monotone along a direction, so it meets
//! itself nowhere and its self-intersection system is not solved.
//!
//! `complete` is true when nothing is undecided: the crossings listed are then
//! all the intersections of the pieces besides their shared end points, each
//! in a box `s × t` holding exactly one.

use crate::curve::{Bezier, V2};
use crate::scalar::{interval_from_rational, rational_from_f64, Interval, Rational, Scalar};
use crate::stroke::onside::binom;
use crate::tangency::complete::{solve, RationalBox, SolveOptions, UndecidedReason};
use crate::tangency::krawczyk::{IBox, System2};
use crate::tangency::poly2::Poly2;
use num_traits::{One, Signed, Zero};

/// One proven transversal crossing: exactly one point with `A_i(s) = A_j(t)`
/// and `(s, t)` in the enclosures (`i < j`, or `i = j` with `s < t` for a
/// self-intersection).
#[derive(Clone, Debug, PartialEq)]
pub struct Crossing {
    /// The two pieces (`pieces.0 ≤ pieces.1`).
    pub pieces: (usize, usize),
    /// Enclosure of the parameter on the first piece.
    pub s: (f64, f64),
    /// Enclosure of the parameter on the second piece.
    pub t: (f64, f64),
    /// The crossing point, enclosed (the first piece at `s`).
    pub point: ((f64, f64), (f64, f64)),
}

/// A region of a pair's parameter domain that may hold intersections not
/// listed as crossings.
#[derive(Clone, Debug, PartialEq)]
pub struct Undecided {
    /// The two pieces.
    pub pieces: (usize, usize),
    /// Parameter range on the first piece.
    pub s: (f64, f64),
    /// Parameter range on the second piece.
    pub t: (f64, f64),
    /// Why: `"tangential"` (a multiple or tangential contact is likely),
    /// `"singular"` (a point where the piece's derivative may vanish),
    /// `"joint"` (a shared end point where the pieces leave in one direction),
    /// `"budget"`, `"boundary"` (a root on the edge of a sub-domain) or
    /// `"ambiguous"`.
    pub reason: &'static str,
}

/// A shared end point proven to be the only contact of the two pieces near it.
#[derive(Clone, Debug, PartialEq)]
pub struct Joint {
    /// The two pieces.
    pub pieces: (usize, usize),
    /// Which ends meet: the parameter (0 or 1) on each piece.
    pub at: (u8, u8),
}

/// The result of [`intersections`].
#[derive(Clone, Debug, Default, PartialEq)]
pub struct Intersections {
    /// Proven crossings, each unique in its box, sorted by pieces and `s`.
    pub crossings: Vec<Crossing>,
    /// Shared end points proven isolated.
    pub joints: Vec<Joint>,
    /// Regions left undecided (empty when `complete`).
    pub undecided: Vec<Undecided>,
    /// True when nothing is undecided: `crossings` and `joints` are then all
    /// the points where the pieces meet.
    pub complete: bool,
    /// Pairs (and single pieces) examined by the solver.
    pub pairs_solved: usize,
    /// Pairs excluded by their control-point boxes.
    pub pairs_excluded: usize,
    /// Pairs (and single pieces) not examined because the caller already
    /// knows how they meet ([`intersections_skipping`]).
    pub pairs_known: usize,
    /// Solver boxes processed in all.
    pub boxes: usize,
}

/// The default narrowest joint corner, `2⁻⁴⁹` (`1/8 · 4⁻²³`, the last of the
/// widths the joint proofs halve through).
const JOINT_MIN_WIDTH: f64 = 1.0 / 562_949_953_421_312.0;

/// Settings of [`intersections`].
#[derive(Clone, Copy, Debug)]
pub struct IntersectOptions {
    /// Solver boxes per pair (default 20 000); beyond it the rest of the pair's
    /// domain is reported undecided.
    pub max_boxes_per_pair: usize,
    /// Include self-intersections of each piece (default true).
    pub self_intersections: bool,
    /// Parameter width below which a box of a piece's self-intersection
    /// system that is neither excluded nor settled is reported undecided
    /// (default `1e-10`). Near a cusp of a piece the system is singular on
    /// the diagonal and boxes are refined down to this width; a larger
    /// width gives up there sooner (self-crossings closer than it to
    /// another event are then reported undecided, never dropped).
    pub self_min_width: f64,
    /// Narrowest corner at a shared end point that the joint proofs try
    /// (default `2⁻⁴⁹`, a power of two). A joint not proven the only contact
    /// on a corner at least this wide leaves a corner of width
    /// `max(joint_min_width, 2⁻²⁰)` undecided; a joint proven only on a
    /// corner narrower than `2⁻²⁰` keeps it (the rest is solved).
    pub joint_min_width: f64,
}

impl Default for IntersectOptions {
    fn default() -> Self {
        IntersectOptions {
            max_boxes_per_pair: 20_000,
            self_intersections: true,
            self_min_width: SolveOptions::default().min_width,
            joint_min_width: JOINT_MIN_WIDTH,
        }
    }
}

fn q(n: i64, d: i64) -> Rational {
    Rational::new(n.into(), d.into())
}

/// The coordinates of a piece in the power basis, exactly.
fn power(b: &Bezier<Rational>) -> (Vec<Rational>, Vec<Rational>) {
    let (x, y) = b.power_coords();
    (x.coeffs().to_vec(), y.coeffs().to_vec())
}

/// The power-basis coordinates of each piece, computed when first needed
/// (most pairs are decided by boxes, joints or the direction test and never
/// build a polynomial system; the conversion of 70-digit control points is
/// not free).
struct Powers<'a> {
    pieces: &'a [Bezier<Rational>],
    cache: Vec<std::sync::OnceLock<(Vec<Rational>, Vec<Rational>)>>,
}

impl<'a> Powers<'a> {
    fn new(pieces: &'a [Bezier<Rational>]) -> Self {
        Powers {
            pieces,
            cache: (0..pieces.len())
                .map(|_| std::sync::OnceLock::new())
                .collect(),
        }
    }
    fn get(&self, i: usize) -> &(Vec<Rational>, Vec<Rational>) {
        self.cache[i].get_or_init(|| power(&self.pieces[i]))
    }
}

/// `a(s) − b(t)` as a bivariate polynomial (`x = s`, `y = t`).
fn difference(a: &[Rational], b: &[Rational]) -> Poly2<Rational> {
    let (da, db) = (a.len().max(1) - 1, b.len().max(1) - 1);
    let mut c = vec![<Rational as Zero>::zero(); (da + 1) * (db + 1)];
    for (i, ai) in a.iter().enumerate() {
        c[i * (db + 1)] += ai;
    }
    for (j, bj) in b.iter().enumerate() {
        c[j] -= bj;
    }
    Poly2::from_coeffs(da, db, c).unwrap_or_else(Poly2::zero)
}

/// `(a(s) − a(t))/(s − t) = Σ_k a_k Σ_{i+j=k−1} s^i t^j`.
fn divided_difference(a: &[Rational]) -> Poly2<Rational> {
    let n = a.len().max(2) - 2; // degree of the result in each variable
    let mut c = vec![<Rational as Zero>::zero(); (n + 1) * (n + 1)];
    for (k, ak) in a.iter().enumerate().skip(1) {
        for i in 0..k {
            let j = k - 1 - i;
            c[i * (n + 1) + j] += ak;
        }
    }
    Poly2::from_coeffs(n, n, c).unwrap_or_else(Poly2::zero)
}

/// The exact control-point bounding box.
fn bbox(b: &Bezier<Rational>) -> [(Rational, Rational); 2] {
    let p = b.points();
    let mut lo = [p[0].x.clone(), p[0].y.clone()];
    let mut hi = lo.clone();
    for v in p {
        for (k, c) in [&v.x, &v.y].into_iter().enumerate() {
            if c < &lo[k] {
                lo[k] = c.clone();
            }
            if c > &hi[k] {
                hi[k] = c.clone();
            }
        }
    }
    [
        (lo[0].clone(), hi[0].clone()),
        (lo[1].clone(), hi[1].clone()),
    ]
}

fn boxes_disjoint(a: &[(Rational, Rational); 2], b: &[(Rational, Rational); 2]) -> bool {
    (0..2).any(|k| a[k].1 < b[k].0 || b[k].1 < a[k].0)
}

/// The end point of a piece at parameter `e` (0 or 1).
fn end(b: &Bezier<Rational>, e: u8) -> &V2<Rational> {
    let p = b.points();
    if e == 0 {
        &p[0]
    } else {
        &p[p.len() - 1]
    }
}

/// The part of `[0, 1]` of width `eps` at end `e`.
fn corner_range(e: u8, eps: &Rational) -> (Rational, Rational) {
    if e == 0 {
        (<Rational as Zero>::zero(), eps.clone())
    } else {
        (<Rational as One>::one() - eps, <Rational as One>::one())
    }
}

/// The direction leaving the end `e` of `b` into the piece (`±b′` there), in floats.
fn away(b: &Bezier<Rational>, e: u8) -> Option<V2<f64>> {
    // the first nonzero control point difference from that end, pointing
    // into the piece (a positive multiple of ±b′ there)
    let v = b.leaving_direction(e == 1)?.map(Scalar::approx);
    let l = v.norm2().sqrt();
    (l > 0.0 && l.is_finite()).then(|| V2::new(v.x / l, v.y / l))
}

/// Proves that on the corner `e`-range of width `eps` the derivative of
/// `d · b`, oriented away from the end, has the strict sign `sign`: every
/// Bernstein coefficient of `(d · b)′` over the range, times the orientation,
/// has that sign (exact).
///
/// In outward rounded interval arithmetic (the restriction in the convex
/// form, so an enclosure of the exact restricted coefficients): a strict sign
/// of every enclosure is a strict sign of every exact coefficient.
fn monotone(b: &Bezier<Rational>, e: u8, eps: &Rational, d: &V2<Rational>, sign: i8) -> bool {
    let (lo, hi) = corner_range(e, eps);
    let iv = b.map(interval_from_rational);
    let h = iv
        .restrict(&interval_from_rational(&lo), &interval_from_rational(&hi))
        .hodograph();
    let di = d.map(interval_from_rational);
    let orient = if e == 0 { 1 } else { -1 };
    h.points().iter().all(|c| {
        let v = di.dot(c);
        let s = if v.inf() > 0.0 {
            1
        } else if v.sup() < 0.0 {
            -1
        } else {
            0
        };
        s != 0 && s * orient == sign
    })
}

/// Proves the shared end point `(ea, eb)` of `a`, `b` the only contact in the
/// corner of width `eps` (see the module docs); returns the width proven.
fn isolate_joint(
    a: &Bezier<Rational>,
    ea: u8,
    b: &Bezier<Rational>,
    eb: u8,
    min_eps: &Rational,
) -> Option<Rational> {
    let (u, v) = (away(a, ea)?, away(b, eb)?);
    // d · u < 0 and d · v > 0 with d = v − u (fails only when u = v)
    let df = V2::new(v.x - u.x, v.y - u.y);
    if df.norm2() >= 1e-24 {
        let d = V2::new(rational_from_f64(df.x)?, rational_from_f64(df.y)?);
        // the whole pieces first (consecutive pieces of one offset side or
        // input path: then nothing is left to solve), then ever smaller corners
        let widths = [q(1, 1), q(1, 2), q(1, 4)]
            .into_iter()
            .chain(std::iter::successors(Some(q(1, 8)), |e| {
                Some(e / Rational::from_integer(4.into()))
            }))
            .take(27)
            .take_while(|e| e >= min_eps);
        for eps in widths {
            if monotone(a, ea, &eps, &d, -1) && monotone(b, eb, &eps, &d, 1) {
                return Some(eps);
            }
        }
    }
    // both leave in (nearly) the same direction: a cusp of the curve the
    // pieces approximate; second order
    let w = V2::new(u.x + v.x, u.y + v.y);
    isolate_tangential_joint(a, ea, b, eb, &w, min_eps)
}

/// The piece with its end `e` moved to parameter 0.
fn from_end(b: &Bezier<Rational>, e: u8) -> Bezier<Rational> {
    if e == 0 {
        b.clone()
    } else {
        Bezier::new(b.points().iter().rev().cloned().collect())
    }
}

/// Exact bounds of `c · p` over the Bernstein coefficients `p`.
fn dot_range(p: &[V2<Rational>], c: &V2<Rational>) -> (Rational, Rational) {
    let vals: Vec<Rational> = p.iter().map(|v| c.dot(v)).collect();
    let lo = vals.iter().min().cloned().unwrap_or_default();
    let hi = vals.iter().max().cloned().unwrap_or_default();
    (lo, hi)
}

fn mul_range(a: &(Rational, Rational), b: &(Rational, Rational)) -> (Rational, Rational) {
    let c = [&a.0 * &b.0, &a.0 * &b.1, &a.1 * &b.0, &a.1 * &b.1];
    (
        c.iter().min().cloned().unwrap_or_default(),
        c.iter().max().cloned().unwrap_or_default(),
    )
}

/// Bounds of the second derivative `y″(x)` of a part of a piece (its
/// restriction to `[0, eps]` from the end at parameter 0) as a graph over
/// the direction `w` (`x = w·(p − P)`, `y = w⊥·(p − P)`); `None` unless
/// `x′ > 0` there.
fn graph_curvature(part: &Bezier<Rational>, w: &V2<Rational>) -> Option<(Rational, Rational)> {
    let h = part.hodograph();
    let h2 = h.hodograph();
    let n = w.rot90();
    let xs = dot_range(h.points(), w);
    if !xs.0.is_positive() {
        return None;
    }
    let ys = dot_range(h.points(), &n);
    let (xss, yss) = if h2.points().is_empty() {
        {
            let z = <Rational as Zero>::zero();
            ((z.clone(), z.clone()), (z.clone(), z))
        }
    } else {
        (dot_range(h2.points(), w), dot_range(h2.points(), &n))
    };
    let p1 = mul_range(&xs, &yss);
    let p2 = mul_range(&ys, &xss);
    let num = (&p1.0 - &p2.1, &p1.1 - &p2.0);
    let c3 = (&xs.0 * &xs.0 * &xs.0, &xs.1 * &xs.1 * &xs.1);
    let q = [
        &num.0 / &c3.0,
        &num.0 / &c3.1,
        &num.1 / &c3.0,
        &num.1 / &c3.1,
    ];
    Some((q.iter().min().cloned()?, q.iter().max().cloned()?))
}

/// Two pieces leaving their shared end point in (nearly) the same direction:
/// on corner ranges where both are graphs `y_a(x)`, `y_b(x)` over one
/// rational direction `w` (`x′ > 0`, exact Bernstein bounds) with
/// `y_a(0) = y_b(0) = 0`, slopes `s_a`, `s_b` at the joint (exact) and
/// enclosures `[k_lo, k_hi]` of `y_a″ − y_b″`: by Taylor's theorem
/// `(y_a − y_b)(x) / x ∈ D + [k_lo, k_hi]·x/2` with `D = s_a − s_b`, for
/// every `x ∈ (0, X]` where both graphs are defined (`X` an upper bound of
/// the smaller corner's `x`-extent). When that interval excludes 0 for all
/// such `x` — `D = 0` and `k_lo > 0` or `k_hi < 0` (exactly tangent pieces, a
/// double zero at 0), `D > 0` and `D + min(k_lo, 0)·X/2 > 0`, or the mirror
/// image — `y_a − y_b` vanishes only at `x = 0`: the joint is their only
/// contact there (a point of both has one `x`, and `x` is strictly
/// increasing along each corner, so `x = 0` is the joint itself).
fn isolate_tangential_joint(
    a: &Bezier<Rational>,
    ea: u8,
    b: &Bezier<Rational>,
    eb: u8,
    w: &V2<f64>,
    min_eps: &Rational,
) -> Option<Rational> {
    let (fa, fb) = (from_end(a, ea), from_end(b, eb));
    // the directions leaving the joint, exactly (positive multiples of the
    // first nonzero hodograph control points: slopes and signs are the same)
    let (ta, tb) = (fa.leaving_direction(false)?, fb.leaving_direction(false)?);
    if !ta.dot(&tb).is_positive() {
        return None;
    }
    // the graphs' direction: the exact tangent when both share it, else a
    // rational direction between them (w only checks the float side)
    if ta.x.approx() * w.x + ta.y.approx() * w.y <= 0.0 {
        return None;
    }
    let dir = if ta.cross(&tb).is_zero() {
        ta.clone()
    } else {
        V2::new(rational_from_f64(w.x)?, rational_from_f64(w.y)?)
    };
    let n = dir.rot90();
    let (xa, xb) = (ta.dot(&dir), tb.dot(&dir));
    if !xa.is_positive() || !xb.is_positive() {
        return None;
    }
    let d = ta.dot(&n) / xa - tb.dot(&n) / xb;
    let zero = <Rational as Zero>::zero();
    let half = q(1, 2);
    let mut eps = q(1, 8);
    for _ in 0..24 {
        if eps < *min_eps {
            break;
        }
        let zero_eps = (<Rational as Zero>::zero(), eps.clone());
        let (pa, pb) = (
            fa.restrict(&zero_eps.0, &zero_eps.1),
            fb.restrict(&zero_eps.0, &zero_eps.1),
        );
        if let (Some(ka), Some(kb)) = (graph_curvature(&pa, &dir), graph_curvature(&pb, &dir)) {
            let (klo, khi) = (&ka.0 - &kb.1, &ka.1 - &kb.0);
            let separated = if d.is_zero() {
                klo.is_positive() || khi.is_negative()
            } else {
                let x = x_extent(&pa, &dir).min(x_extent(&pb, &dir));
                if d.is_positive() {
                    (&d + klo.min(zero.clone()) * &x * &half).is_positive()
                } else {
                    (&d + khi.max(zero.clone()) * &x * &half).is_negative()
                }
            };
            if separated {
                return Some(eps);
            }
        }
        eps /= Rational::from_integer(4.into());
    }
    None
}

/// An upper bound of `(c(t) − c(0)) · w` over a part `c` (its control
/// points, exactly).
fn x_extent(part: &Bezier<Rational>, w: &V2<Rational>) -> Rational {
    dot_range(part.points(), w).1 - part.points()[0].dot(w)
}

fn reason_name(r: UndecidedReason) -> &'static str {
    match r {
        UndecidedReason::MinWidth {
            near_double_root: true,
        } => "tangential",
        UndecidedReason::MinWidth { .. } => "ambiguous",
        UndecidedReason::Budget => "budget",
        UndecidedReason::DomainBoundary => "boundary",
        UndecidedReason::Ambiguous | UndecidedReason::Unresolved => "ambiguous",
    }
}

fn range(i: Interval) -> (f64, f64) {
    (i.inf(), i.sup())
}

/// The sub-domains of `[0, 1]²` left after cutting out the proven corners:
/// a list of rational boxes covering the rest.
fn minus_corners(corners: &[((u8, u8), Rational)]) -> Vec<RationalBox> {
    // cut the s-range into [0, e₀], [e₀, 1 − e₁], [1 − e₁, 1] strips, and in
    // the end strips remove the t-corner ranges
    let zero = <Rational as Zero>::zero();
    let one = <Rational as One>::one();
    let eps_at = |es: u8| {
        corners
            .iter()
            .filter(|((a, _), _)| *a == es)
            .map(|(_, e)| e.clone())
            .fold(zero.clone(), |m, e| if e > m { e } else { m })
    };
    let (e0, e1) = (eps_at(0), eps_at(1));
    let mut out = Vec::new();
    let mid = (e0.clone(), &one - &e1);
    if mid.0 < mid.1 {
        out.push(RationalBox {
            x: mid,
            y: (zero.clone(), one.clone()),
        });
    }
    for (es, e) in [(0u8, &e0), (1u8, &e1)] {
        if e.is_zero() {
            continue;
        }
        let srange = corner_range(es, e);
        // the t-ranges cut out at this s end
        let mut cuts: Vec<(Rational, Rational)> = corners
            .iter()
            .filter(|((a, _), _)| *a == es)
            .map(|((_, b), w)| corner_range(*b, w))
            .collect();
        cuts.sort();
        let mut t = zero.clone();
        for (lo, hi) in cuts {
            if lo > t {
                out.push(RationalBox {
                    x: srange.clone(),
                    y: (t.clone(), lo.clone()),
                });
            }
            if hi > t {
                t = hi;
            }
        }
        if t < one {
            out.push(RationalBox {
                x: srange.clone(),
                y: (t, one.clone()),
            });
        }
    }
    out
}

/// All intersections of the pieces (see the module docs). Pieces are given
/// exactly; a degree-0 piece (a point) is skipped.
///
/// # Examples
/// ```
/// use lncert::stroke::{intersections, IntersectOptions};
/// use lncert::shape::parse_curve;
/// // a cubic with a loop, and a line across it
/// let loopy = parse_curve("M 0 0 C 3 2 -1 2 2 0").unwrap();
/// let line = parse_curve("M -1 0.5 L 3 0.5").unwrap();
/// let pieces = [loopy[0].clone(), line[0].clone()];
/// let r = intersections(&pieces, &IntersectOptions::default());
/// assert!(r.complete);
/// // one self-crossing of the loop; the line crosses the cubic twice (y = 6s(1 − s) = 1/2)
/// assert_eq!(r.crossings.iter().filter(|c| c.pieces == (0, 0)).count(), 1);
/// assert_eq!(r.crossings.iter().filter(|c| c.pieces == (0, 1)).count(), 2);
/// ```
pub fn intersections(pieces: &[Bezier<Rational>], opts: &IntersectOptions) -> Intersections {
    intersections_skipping(pieces, opts, |_, _| false)
}

/// [`intersections`] without the pairs `(i, j)` (`i < j`) and single pieces
/// `(i, i)` for which `known(i, j)` holds: they are neither solved nor
/// reported, and `complete` then speaks only of the others. The caller
/// answers for the skipped pairs (e.g. from an earlier complete search over
/// the same exact pieces).
pub fn intersections_skipping<F>(
    pieces: &[Bezier<Rational>],
    opts: &IntersectOptions,
    known: F,
) -> Intersections
where
    F: Fn(usize, usize) -> bool + Sync,
{
    let mut out = Intersections::default();
    let powers = Powers::new(pieces);
    let boxes: Vec<_> = pieces.iter().map(bbox).collect();
    let sopts = SolveOptions {
        max_boxes: opts.max_boxes_per_pair,
        ..SolveOptions::default()
    };
    let joint_min = rational_from_f64(opts.joint_min_width)
        .filter(|w| w.is_positive())
        .unwrap_or_else(|| rational_from_f64(JOINT_MIN_WIDTH).expect("a power of two"));
    let self_opts = SolveOptions {
        min_width: opts.self_min_width,
        ..sopts
    };
    // sweep over the x-ranges: candidate pairs only
    let mut order: Vec<usize> = (0..pieces.len())
        .filter(|&i| pieces[i].degree() > 0)
        .collect();
    order.sort_by(|&i, &j| boxes[i][0].0.cmp(&boxes[j][0].0));
    let mut pairs = Vec::new();
    for (k, &i) in order.iter().enumerate() {
        for &j in &order[k + 1..] {
            if boxes[j][0].0 > boxes[i][0].1 {
                break;
            }
            if boxes_disjoint(&boxes[i], &boxes[j]) {
                out.pairs_excluded += 1;
            } else if known(i.min(j), i.max(j)) {
                out.pairs_known += 1;
            } else {
                pairs.push((i.min(j), i.max(j)));
            }
        }
    }
    let n_active = order.len();
    out.pairs_excluded += (n_active * n_active.saturating_sub(1) / 2)
        .saturating_sub(pairs.len() + out.pairs_excluded + out.pairs_known);
    let singles: Vec<usize> = if opts.self_intersections {
        order.iter().copied().filter(|&i| !known(i, i)).collect()
    } else {
        Vec::new()
    };
    if opts.self_intersections {
        out.pairs_known += order.len() - singles.len();
    }
    pairs.sort();
    use rayon::prelude::*;
    let results: Vec<Intersections> = pairs
        .par_iter()
        .map(|&(i, j)| {
            // two different pieces; a straight one: one exact univariate
            // equation instead of the box search
            segment_pair(pieces, i, j)
                .unwrap_or_else(|| pair_boxes(pieces, &powers, i, j, &sopts, &joint_min))
        })
        .chain(
            singles
                .par_iter()
                .map(|&i| self_pair(pieces, &powers, i, &self_opts)),
        )
        .collect();
    for r in results {
        out.crossings.extend(r.crossings);
        out.joints.extend(r.joints);
        out.undecided.extend(r.undecided);
        out.pairs_solved += r.pairs_solved;
        out.boxes += r.boxes;
    }
    out.crossings
        .sort_by(|a, b| a.pieces.cmp(&b.pieces).then(a.s.0.total_cmp(&b.s.0)));
    out.joints
        .sort_by(|a, b| a.pieces.cmp(&b.pieces).then(a.at.cmp(&b.at)));
    out.complete = out.undecided.is_empty();
    out
}

fn crossing_of(pieces: &[Bezier<Rational>], i: usize, j: usize, e: &IBox) -> Crossing {
    let b = pieces[i].map(interval_from_rational);
    let p = b.eval(&e[0]);
    Crossing {
        pieces: (i, j),
        s: range(e[0]),
        t: range(e[1]),
        point: (range(p.x), range(p.y)),
    }
}

/// Two different pieces, by the box search.
fn pair_boxes(
    pieces: &[Bezier<Rational>],
    powers: &Powers,
    i: usize,
    j: usize,
    sopts: &SolveOptions,
    joint_min: &Rational,
) -> Intersections {
    let mut out = Intersections {
        pairs_solved: 1,
        ..Intersections::default()
    };
    let (a, b) = (&pieces[i], &pieces[j]);
    // shared end points: prove each the only contact in its corner
    let mut corners = Vec::new();
    for ea in [0u8, 1] {
        for eb in [0u8, 1] {
            if end(a, ea) != end(b, eb) {
                continue;
            }
            match isolate_joint(a, ea, b, eb, joint_min) {
                Some(w) => {
                    out.joints.push(Joint {
                        pieces: (i, j),
                        at: (ea, eb),
                    });
                    corners.push(((ea, eb), w));
                }
                None => {
                    let w = q(1, 1 << 20).max(joint_min.clone());
                    let (s, t) = (corner_range(ea, &w), corner_range(eb, &w));
                    out.undecided.push(Undecided {
                        pieces: (i, j),
                        s: (s.0.approx(), s.1.approx()),
                        t: (t.0.approx(), t.1.approx()),
                        reason: "joint",
                    });
                    corners.push(((ea, eb), w));
                }
            }
        }
    }
    let doms = minus_corners(&corners);
    if doms.is_empty() {
        return out; // the joints' corners are the whole domain
    }
    let sys = System2::new(
        &difference(&powers.get(i).0, &powers.get(j).0),
        &difference(&powers.get(i).1, &powers.get(j).1),
    );
    for dom in doms {
        let sol = solve(&sys, &dom, sopts);
        out.boxes += sol.boxes;
        for r in &sol.roots {
            out.crossings.push(crossing_of(pieces, i, j, &r.enclosure));
        }
        for u in &sol.undecided {
            out.undecided.push(Undecided {
                pieces: (i, j),
                s: range(u.bx[0]),
                t: range(u.bx[1]),
                reason: reason_name(u.reason),
            });
        }
    }
    out
}

/// Two pieces of which at least one is a straight segment `A(s) = P + s·w`
/// (`w ≠ 0`), solved exactly in one variable: `B(t)` meets the segment's
/// line where `f(t) = w⊥ · (B(t) − P) = 0`, and then at `s(t) = w · (B(t) −
/// P) / |w|²`. A shared end point of the pieces is a root of `f` at `t = 0`
/// or `1`, divided out with its multiplicity; every other root in `[0, 1]`
/// is isolated exactly (Sturm), and each is a crossing when it is simple and
/// `s(t)` is enclosed strictly inside `(0, 1)` on its isolating interval,
/// no contact when `s(t)` is enclosed outside `[0, 1]`, and undecided
/// (`"tangential"` for a multiple root, `"boundary"` for a contact at an end
/// of a piece) otherwise. The roots found are then **all** the contacts: no
/// search, no budget. `None` (the box search decides) when neither piece is a
/// segment of positive length or `B` lies on the segment's line.
fn segment_pair(pieces: &[Bezier<Rational>], i: usize, j: usize) -> Option<Intersections> {
    segment_pair_opt(pieces, i, j, true)
}

/// [`segment_pair`], with the float-first root path or without it (the exact
/// path alone: for the tests that compare the two).
fn segment_pair_opt(
    pieces: &[Bezier<Rational>],
    i: usize,
    j: usize,
    float_first: bool,
) -> Option<Intersections> {
    use crate::poly::{has_common_root_in, isolate_roots, refine_root, Poly, RealRoot, Span};
    let (a, b) = (&pieces[i], &pieces[j]);
    // the segment and the other piece; `swap`: the segment is piece j
    let (seg, other, swap) = if a.degree() == 1 {
        (a, b, false)
    } else if b.degree() == 1 {
        (b, a, true)
    } else {
        return None;
    };
    let p0 = &seg.points()[0];
    let w = seg.points()[1].sub(p0);
    let w2 = w.norm2();
    if w2.is_zero() {
        return None;
    }
    let nrm = w.rot90();
    let fb: Vec<Rational> = other.points().iter().map(|v| nrm.dot(&v.sub(p0))).collect();
    if fb.iter().all(Zero::is_zero) {
        return None; // on the line: an overlap, for the box search to report
    }
    let mut out = Intersections {
        pairs_solved: 1,
        ..Intersections::default()
    };
    let (zero, one) = (<Rational as Zero>::zero(), <Rational as One>::one());
    let mut shared = [false; 2];
    for ea in [0u8, 1] {
        for eb in [0u8, 1] {
            if end(seg, ea) == end(other, eb) {
                shared[eb as usize] = true;
                out.joints.push(Joint {
                    pieces: (i, j),
                    at: if swap { (eb, ea) } else { (ea, eb) },
                });
            }
        }
    }
    // B on one side of the line: the Bernstein coefficients of f, apart from
    // the zeros of a shared end point, all of one strict sign (f = Σ f_k B_k
    // with B_k > 0 inside): no contact but the joints
    let n = fb.len();
    let z0 = if shared[0] {
        fb.iter().take_while(|c| c.is_zero()).count()
    } else {
        0
    };
    let z1 = if shared[1] {
        fb.iter().rev().take_while(|c| c.is_zero()).count()
    } else {
        0
    };
    if z0 + z1 < n {
        let mid = &fb[z0..n - z1];
        if mid.iter().all(|c| c.is_positive()) || mid.iter().all(|c| c.is_negative()) {
            out.complete = true;
            return Some(out);
        }
    }
    // B's parts that stay on one side of the line or project beyond the
    // segment's ends (interval Bernstein coefficients of f and of
    // s(t) = w·(B − P)/|w|², halved a few times) hold no contact. At a shared
    // end f is first divided by its root there: f = t^z0 (1 − t)^z1 g with
    // g's Bernstein coefficients g_(k−z0) = f_k C(n, k) / C(n − z0 − z1, k − z0)
    // (z0, z1 the exact zero coefficients at the ends), so g ≠ 0 on a part
    // means no contact there but the joint itself (z0, z1 are then the exact
    // multiplicities of the end roots).
    if z0 + z1 < n {
        let m = n - 1 - z0 - z1;
        let gi: Vec<Interval> = (z0..n - z1)
            .map(|k| interval_from_rational(&fb[k]) * binom(n - 1, k) / binom(m, k - z0))
            .collect();
        let si: Vec<Interval> = other
            .points()
            .iter()
            .map(|v| interval_from_rational(&(w.dot(&v.sub(p0)) / &w2)))
            .collect();
        if gi.iter().all(|c| !c.is_empty()) && no_contact(&gi, &si, 5) {
            out.complete = true;
            return Some(out);
        }
    }
    let mut f = Poly::from_bernstein(&fb).trimmed();
    // shared end points: joints (the root divided out, with its multiplicity)
    for ea in [0u8, 1] {
        for eb in [0u8, 1] {
            if end(seg, ea) != end(other, eb) {
                continue;
            }
            let root = if eb == 0 { zero.clone() } else { one.clone() };
            while f.degree().is_some_and(|d| d > 0) && f.eval(&root).is_zero() {
                f = deflate(&f, &root);
            }
        }
    }
    if f.degree().is_none_or(|d| d == 0) {
        out.complete = true;
        return Some(out);
    }
    let df = f.derivative();
    let bi = other.map(interval_from_rational);
    // s(t) exactly, and its exact enclosure on [lo, hi] ⊂ [0, 1] (term by
    // term: each c·tᵏ is monotone for t ≥ 0)
    let sb: Vec<Rational> = other
        .points()
        .iter()
        .map(|v| w.dot(&v.sub(p0)) / &w2)
        .collect();
    let sp = Poly::from_bernstein(&sb);
    let s_enc = |lo: &Rational, hi: &Rational| sp.range_on_nonnegative(lo, hi);
    let target = q(1, 1 << 30) * q(1, 1 << 20);
    // float first: interval Bernstein subdivision proves every root in
    // [0, 1] simple and isolated (strict end signs, one sign variation per
    // piece, none elsewhere), and float bisection with exact signs where
    // the enclosure cannot tell ([`crate::offset::prep::bisect_f64`])
    // narrows each to the target width; otherwise the exact path (Sturm
    // isolation, rational bisection, the tangency test)
    let fast: Option<Vec<RealRoot>> = (float_first && f.coeffs().len() <= 61)
        .then(|| {
            let fi = f.map(interval_from_rational);
            let pieces = crate::poly::isolate_simple_roots(&fi, 0.0, 1.0, 2_000)?;
            pieces
                .into_iter()
                .map(|ab| crate::offset::prep::bisect_f64(&f, &fi, ab, 50))
                .collect()
        })
        .flatten();
    let simple = fast.is_some();
    let roots = fast.unwrap_or_else(|| isolate_roots(&f, &Span::closed(zero.clone(), one.clone())));
    for root in roots {
        let mut r = root;
        // Some(None): no contact; Some(Some(())): a crossing inside the segment
        let mut verdict = None;
        for _ in 0..24 {
            let (lo, hi) = s_enc(&r.lo, &r.hi);
            if hi.is_negative() || lo > one {
                verdict = Some(None); // on the line, beyond the segment
                break;
            }
            if lo.is_positive() && hi < one {
                verdict = Some(Some(()));
                break;
            }
            if r.is_exact() {
                break; // B(t) is an end point of the segment
            }
            let width = r.width() / Rational::from_integer((1i64 << 16).into());
            r = refine_root(&f, &r, &width);
        }
        let t_range = (
            interval_from_rational(&r.lo).inf(),
            interval_from_rational(&r.hi).sup(),
        );
        let undecided = |reason: &'static str| Undecided {
            pieces: (i, j),
            s: if swap { t_range } else { (0.0, 1.0) },
            t: if swap { (0.0, 1.0) } else { t_range },
            reason,
        };
        match verdict {
            Some(None) => {}
            Some(Some(_)) => {
                let span = Span::closed(r.lo.clone(), r.hi.clone());
                if !simple && has_common_root_in(&f, &df, &span) {
                    out.undecided.push(undecided("tangential"));
                    continue;
                }
                // a simple root: narrow it for a tight split point (the
                // float path's roots are within the target already)
                let r = if simple {
                    r
                } else {
                    refine_root(&f, &r, &target)
                };
                if r.is_exact() && (r.lo == zero || r.lo == one) {
                    // at an end of B (not a shared end point): a T-contact
                    out.undecided.push(undecided("boundary"));
                    continue;
                }
                let (t_lo, t_hi) = (
                    interval_from_rational(&r.lo).inf(),
                    interval_from_rational(&r.hi).sup(),
                );
                let (s_lo, s_hi) = s_enc(&r.lo, &r.hi);
                let sr = (
                    interval_from_rational(&s_lo).inf(),
                    interval_from_rational(&s_hi).sup(),
                );
                let t_iv = Interval::try_from((t_lo, t_hi)).ok()?;
                let pt = bi.eval(&t_iv);
                let (s_rng, t_rng) = (sr, (t_lo, t_hi));
                out.crossings.push(Crossing {
                    pieces: (i, j),
                    s: if swap { t_rng } else { s_rng },
                    t: if swap { s_rng } else { t_rng },
                    point: (range(pt.x), range(pt.y)),
                });
            }
            None => out.undecided.push(undecided("boundary")),
        }
    }
    out.complete = out.undecided.is_empty();
    Some(out)
}

/// The Bernstein coefficients (intervals) of `f` on `[0, 1]` have one strict
/// sign, or those of `s` are all below 0 or all above 1, on every part after
/// up to `depth` halvings (outward rounded, convex form `(a + b)/2`).
fn no_contact(f: &[Interval], s: &[Interval], depth: u32) -> bool {
    let strict = f.iter().all(|c| c.inf() > 0.0) || f.iter().all(|c| c.sup() < 0.0);
    let beyond = s.iter().all(|c| c.sup() < 0.0) || s.iter().all(|c| c.inf() > 1.0);
    if strict || beyond {
        return true;
    }
    if depth == 0 {
        return false;
    }
    let (fl, fr) = crate::curve::bernstein_halves(f);
    let (sl, sr) = crate::curve::bernstein_halves(s);
    no_contact(&fl, &sl, depth - 1) && no_contact(&fr, &sr, depth - 1)
}

/// `f(t) / (t − r)` for a root `r` of `f` (synthetic division, exact).
fn deflate(f: &crate::poly::Poly<Rational>, r: &Rational) -> crate::poly::Poly<Rational> {
    let c = f.coeffs();
    let n = c.len();
    let mut out = vec![<Rational as Zero>::zero(); n.saturating_sub(1)];
    let mut acc = <Rational as Zero>::zero();
    for k in (1..n).rev() {
        acc = &acc * r + &c[k];
        out[k - 1] = acc.clone();
    }
    crate::poly::Poly::new(out).trimmed()
}

/// Proves that `b` meets itself nowhere, with no singular point: some
/// direction `d` (in floats, from the hodograph) has `d · c > 0` for every
/// Bernstein coefficient `c` of `b′`, enclosed outward from the exact control
/// points. Then `d · b′ > 0` on `[0, 1]` (a convex combination), so `d · b`
/// strictly increases and `b(s) ≠ b(t)` for `s ≠ t`. `false` decides nothing.
fn injective(b: &Bezier<Rational>) -> bool {
    let h = b.map(interval_from_rational).hodograph();
    let sum = h
        .points()
        .iter()
        .fold((0.0, 0.0), |(x, y), c| (x + c.x.mid(), y + c.y.mid()));
    if !(sum.0.is_finite() && sum.1.is_finite()) || (sum.0 == 0.0 && sum.1 == 0.0) {
        return false;
    }
    let (Ok(dx), Ok(dy)) = (
        Interval::try_from((sum.0, sum.0)),
        Interval::try_from((sum.1, sum.1)),
    ) else {
        return false;
    };
    let d = V2::new(dx, dy);
    h.points().iter().all(|c| d.dot(c).inf() > 0.0)
}

/// The self-intersections of one piece: the divided-difference system on
/// `[0, 1]²`, roots with `s < t` (their mirror images dropped); a box on the
/// diagonal that cannot be excluded is a possible singular point.
fn self_pair(
    pieces: &[Bezier<Rational>],
    powers: &Powers,
    i: usize,
    sopts: &SolveOptions,
) -> Intersections {
    let out = Intersections {
        pairs_solved: 1,
        ..Intersections::default()
    };
    if pieces[i].degree() < 2 || injective(&pieces[i]) {
        return out; // a segment, or a piece monotone along a direction
    }
    self_solve(pieces, powers, i, sopts)
}

/// [`self_pair`] by the complete solver alone (no direction test).
fn self_solve(
    pieces: &[Bezier<Rational>],
    powers: &Powers,
    i: usize,
    sopts: &SolveOptions,
) -> Intersections {
    let mut out = Intersections {
        pairs_solved: 1,
        ..Intersections::default()
    };
    let sys = System2::new(
        &divided_difference(&powers.get(i).0),
        &divided_difference(&powers.get(i).1),
    );
    let dom = RationalBox {
        x: (<Rational as Zero>::zero(), <Rational as One>::one()),
        y: (<Rational as Zero>::zero(), <Rational as One>::one()),
    };
    let sol = solve(&sys, &dom, sopts);
    out.boxes += sol.boxes;
    for r in &sol.roots {
        let (s, t) = (r.enclosure[0], r.enclosure[1]);
        if s.sup() < t.inf() {
            out.crossings.push(crossing_of(pieces, i, i, &r.enclosure));
        } else if t.sup() < s.inf() {
            // the mirror image of a root with s < t, which is listed too
        } else {
            // on the diagonal: A′(s) = 0
            out.undecided.push(Undecided {
                pieces: (i, i),
                s: range(s),
                t: range(t),
                reason: "singular",
            });
        }
    }
    for u in &sol.undecided {
        // keep one of each mirrored pair: the part with s ≤ t
        if u.bx[0].inf() > u.bx[1].sup() {
            continue;
        }
        let on_diagonal = !u.bx[0].disjoint(u.bx[1]);
        out.undecided.push(Undecided {
            pieces: (i, i),
            s: range(u.bx[0]),
            t: range(u.bx[1]),
            reason: if on_diagonal {
                "singular"
            } else {
                reason_name(u.reason)
            },
        });
    }
    out
}

#[cfg(test)]
mod tests {
    use super::*;

    fn pc(s: &str) -> Vec<Bezier<Rational>> {
        crate::shape::parse_curve(s).unwrap()
    }

    #[test]
    fn divided_difference_is_exact() {
        // x(s) = s³: (s³ − t³)/(s − t) = s² + st + t²
        let a = vec![q(0, 1), q(0, 1), q(0, 1), q(1, 1)];
        let p = divided_difference(&a);
        for (s, t) in [(q(1, 3), q(2, 5)), (q(-1, 2), q(3, 7))] {
            let want = &s * &s + &s * &t + &t * &t;
            assert_eq!(p.eval(&s, &t), want);
        }
    }

    #[test]
    fn spline_joints_are_isolated_and_crossings_found() {
        // two quadratics joined at (1, 0) with a corner, and a closed contour
        let c = pc("M 0 0 Q 0.5 1 1 0 Q 1.5 -1 2 0");
        let r = intersections(&c, &IntersectOptions::default());
        assert!(r.complete, "{r:?}");
        assert!(r.crossings.is_empty());
        assert_eq!(r.joints.len(), 1);
        // a figure eight made of two cubics closing on itself: one crossing
        let e = pc("M 0 0 C 1 1 2 -1 3 0 C 2 1 1 -1 0 0");
        let r = intersections(&e, &IntersectOptions::default());
        assert!(r.complete, "{r:?}");
        assert_eq!(r.joints.len(), 2, "{r:?}");
        assert_eq!(r.crossings.len(), 1, "{r:?}");
    }

    #[test]
    fn a_tangential_contact_is_undecided_not_dropped() {
        // y = x² touches y = 0 at the origin
        let c = pc("M -1 1 Q 0 -1 1 1 M -1 0 L 1 0");
        let r = intersections(&c, &IntersectOptions::default());
        assert!(!r.complete);
        assert!(r.undecided.iter().any(|u| u.pieces == (0, 1)), "{r:?}");
    }

    /// The float-first root path of the segment test against its exact path
    /// (Sturm isolation, rational bisection, the tangency test) on random
    /// segments and curves with small rational control points, many with
    /// crossings and tangencies: the same crossings (each pair of parameter
    /// ranges overlapping), joints, undecided pairs and completeness.
    #[test]
    fn segment_float_path_agrees_with_the_exact_path() {
        let mut rng = crate::test_util::TestRng::new(0x51_7cc1_b727_220a);
        let mut next = |m: i64| rng.int(m);
        let (mut compared, mut crossings) = (0, 0);
        for case in 0..400 {
            let deg = 1 + case % 3;
            let mut pt = || V2::new(q(next(12), 2), q(next(12), 2));
            let seg = Bezier::new(vec![pt(), pt()]);
            let mut pts: Vec<V2<Rational>> = (0..=deg).map(|_| pt()).collect();
            if case % 5 == 1 {
                pts[0] = seg.points()[1].clone();
            }
            let pieces = [seg, Bezier::new(pts)];
            let (Some(mut a), Some(mut b)) = (
                segment_pair_opt(&pieces, 0, 1, true),
                segment_pair_opt(&pieces, 0, 1, false),
            ) else {
                continue;
            };
            compared += 1;
            crossings += a.crossings.len();
            a.crossings.sort_by(|x, y| x.t.0.total_cmp(&y.t.0));
            b.crossings.sort_by(|x, y| x.t.0.total_cmp(&y.t.0));
            assert_eq!(
                a.crossings.len(),
                b.crossings.len(),
                "{pieces:?}\n{a:?}\n{b:?}"
            );
            for (x, y) in a.crossings.iter().zip(&b.crossings) {
                let meet = |p: (f64, f64), q: (f64, f64)| p.0 <= q.1 && q.0 <= p.1;
                assert!(meet(x.s, y.s) && meet(x.t, y.t), "{x:?} vs {y:?}");
            }
            assert_eq!(a.joints, b.joints);
            assert_eq!(
                a.undecided.len(),
                b.undecided.len(),
                "{pieces:?}\n{a:?}\n{b:?}"
            );
            assert_eq!(a.complete, b.complete);
        }
        assert!(compared > 200 && crossings > 60, "{compared} {crossings}");
    }

    /// The exact segment path against the box search, on segments and
    /// curves with small integer control points (a deterministic generator):
    /// the same crossings (each box of one holds a crossing of the other),
    /// and the same joints.
    #[test]
    fn segment_path_agrees_with_the_box_search() {
        let mut rng = crate::test_util::TestRng::new(0x9e37_79b9_7f4a_7c15);
        let mut next = |m: i64| rng.int(m);
        let sopts = SolveOptions::default();
        let mut compared = 0;
        let mut crossings = 0;
        for case in 0..300 {
            let deg = 1 + case % 3;
            let mut pt = || V2::new(q(next(6), 1), q(next(6), 1));
            let seg = Bezier::new(vec![pt(), pt()]);
            let mut pts: Vec<V2<Rational>> = (0..=deg).map(|_| pt()).collect();
            // every fourth case shares an end point with the segment
            if case % 4 == 1 {
                pts[0] = seg.points()[1].clone();
            }
            let other = Bezier::new(pts);
            let pieces = [seg, other];
            let powers = Powers::new(&pieces);
            let Some(fast) = segment_pair(&pieces, 0, 1) else {
                continue;
            };
            let mut fast = fast;
            let joint_min = rational_from_f64(JOINT_MIN_WIDTH).unwrap();
            let mut slow = pair_boxes(&pieces, &powers, 0, 1, &sopts, &joint_min);
            fast.crossings.sort_by(|a, b| a.s.0.total_cmp(&b.s.0));
            slow.crossings.sort_by(|a, b| a.s.0.total_cmp(&b.s.0));
            if !fast.undecided.is_empty() || !slow.undecided.is_empty() {
                continue;
            }
            compared += 1;
            crossings += fast.crossings.len();
            assert_eq!(
                fast.crossings.len(),
                slow.crossings.len(),
                "{pieces:?}\n{fast:?}\n{slow:?}"
            );
            for (x, y) in fast.crossings.iter().zip(&slow.crossings) {
                let meet = |a: (f64, f64), b: (f64, f64)| a.0 <= b.1 && b.0 <= a.1;
                assert!(meet(x.s, y.s) && meet(x.t, y.t), "{x:?} vs {y:?}");
            }
            assert_eq!(fast.joints, slow.joints, "{pieces:?}");
        }
        assert!(compared > 150 && crossings > 50, "{compared} {crossings}");
    }

    /// The direction test of [`injective`] against the complete solver on
    /// the divided-difference system ([`self_solve`], an independent
    /// computation): on random quadratics, cubics and quartics with small
    /// integer control points, many with loops, every piece the test passes
    /// has no self-crossing and nothing left undecided by the solver.
    #[test]
    fn injective_pieces_do_not_meet_themselves() {
        let mut rng = crate::test_util::TestRng::new(0x1f3c_77a2_90b1_5d03);
        let mut next = |m: i64| rng.int(m);
        let sopts = SolveOptions::default();
        let (mut passed, mut loops) = (0, 0);
        for case in 0..300 {
            let deg = 2 + case % 3;
            let pts: Vec<V2<Rational>> = (0..=deg)
                .map(|_| V2::new(q(next(6), 1), q(next(6), 1)))
                .collect();
            let pieces = [Bezier::new(pts)];
            let powers = Powers::new(&pieces);
            let solved = self_solve(&pieces, &powers, 0, &sopts);
            if !solved.crossings.is_empty() {
                loops += 1;
            }
            if injective(&pieces[0]) {
                passed += 1;
                assert!(
                    solved.crossings.is_empty() && solved.undecided.is_empty(),
                    "{pieces:?}: {solved:?}"
                );
                // and the whole search agrees
                let r = intersections(&pieces, &IntersectOptions::default());
                assert!(r.complete && r.crossings.is_empty(), "{r:?}");
            }
        }
        assert!(passed > 60 && loops > 20, "{passed} passed, {loops} loops");
    }

    /// A self-crossing closer than `self_min_width` to its mirror image is
    /// reported undecided, never dropped (found at `1e-6`, an undecided
    /// region holding it at `1e-4` and `1e-2`): the small loop of `x = u²`,
    /// `y = u³ − εu` (`u = 2t − 1`, `ε = 2⁻³⁰`), which crosses itself at
    /// `u = ±√ε`, parameters `2⁻¹⁵` apart.
    #[test]
    fn a_small_loop_is_found_or_left_undecided() {
        let e = q(1, 1 << 30);
        let third = q(1, 3);
        let one = q(1, 1);
        let pts = vec![
            V2::new(one.clone(), &e - &one),
            V2::new(-third.clone(), &one + &e * &third),
            V2::new(-third.clone(), -&one - &e * &third),
            V2::new(one.clone(), &one - &e),
        ];
        let pieces = [Bezier::new(pts)];
        let fine = intersections(&pieces, &IntersectOptions::default());
        assert!(fine.complete, "{fine:?}");
        assert_eq!(fine.crossings.len(), 1, "{fine:?}");
        let c = &fine.crossings[0];
        let (s, t) = (0.5 * (1.0 - 2f64.powi(-15)), 0.5 * (1.0 + 2f64.powi(-15)));
        assert!(
            c.s.0 <= s && s <= c.s.1 && c.t.0 <= t && t <= c.t.1,
            "{c:?}"
        );
        for w in [1e-6, 1e-4, 1e-2] {
            let coarse = intersections(
                &pieces,
                &IntersectOptions {
                    self_min_width: w,
                    ..IntersectOptions::default()
                },
            );
            if w < 1e-5 {
                assert!(coarse.complete && coarse.crossings.len() == 1, "{coarse:?}");
                continue;
            }
            // too coarse to separate s from t: the crossing lies in a region
            // reported undecided (with s ≤ t, the half kept of the mirror pair)
            assert!(
                !coarse.complete && coarse.crossings.is_empty(),
                "{coarse:?}"
            );
            assert!(
                coarse
                    .undecided
                    .iter()
                    .any(|u| u.s.0 <= s && s <= u.s.1 && u.t.0 <= t && t <= u.t.1),
                "width {w}: {coarse:?}"
            );
        }
    }

    /// The joint proofs against the exact contact of two parabolas leaving
    /// the origin: `y = m·x + k·x²` (`x = t`, quadratic Bézier pieces), whose
    /// only other contact is at `x* = (m_b − m_a)/(k_a − k_b)` (everywhere
    /// when `m` and `k` are equal). Slopes differ by at most `1/25` (nearly
    /// one direction, the generalised tangential proof) or are equal (the
    /// exactly tangent one): a corner proven must exclude `x*`, and the proofs
    /// must succeed on some pairs that have a contact beyond the corner and
    /// on some that are not exactly tangent.
    #[test]
    fn joint_corners_exclude_every_other_contact() {
        let mut rng = crate::test_util::TestRng::new(0x7a11_03e5_c4d2_9b6f);
        let mut next = |m: i64| rng.int(m);
        let min_eps = rational_from_f64(JOINT_MIN_WIDTH).unwrap();
        let para = |m: &Rational, k: &Rational| {
            Bezier::new(vec![
                V2::new(q(0, 1), q(0, 1)),
                V2::new(q(1, 2), m / Rational::from_integer(2.into())),
                V2::new(q(1, 1), m + k),
            ])
        };
        let (mut proven, mut beyond, mut skew) = (0, 0, 0);
        for case in 0..400 {
            let ma = q(next(20), 500);
            let mb = if case % 3 == 0 {
                ma.clone()
            } else {
                &ma + q(next(20), 500)
            };
            let (ka, kb) = (q(next(8), 4), q(next(8), 4));
            let (a, b) = (para(&ma, &ka), para(&mb, &kb));
            let contact = if ka == kb {
                (ma == mb).then(|| q(0, 1)) // identical: contacts everywhere
            } else {
                Some((&mb - &ma) / (&ka - &kb))
            };
            let u = away(&a, 0).unwrap();
            let v = away(&b, 0).unwrap();
            let w = V2::new(u.x + v.x, u.y + v.y);
            for (name, eps) in [
                ("joint", isolate_joint(&a, 0, &b, 0, &min_eps)),
                (
                    "tangential",
                    isolate_tangential_joint(&a, 0, &b, 0, &w, &min_eps),
                ),
            ] {
                let Some(eps) = eps else { continue };
                proven += 1;
                if let Some(x) = &contact {
                    let overlap = x.is_zero() && ka == kb;
                    let inside = x.is_positive() && *x <= eps;
                    assert!(
                        !overlap && !inside,
                        "{name}: m {ma} {mb} k {ka} {kb}: corner {eps} holds the contact at {x}"
                    );
                    if x.is_positive() && *x <= q(1, 1) {
                        beyond += 1;
                    }
                }
                if ma != mb {
                    skew += 1;
                }
            }
        }
        assert!(
            proven > 200 && beyond > 20 && skew > 100,
            "{proven} {beyond} {skew}"
        );
        // an overlap at a joint is never proven; with a coarse floor its
        // corner is left undecided at that width
        let a = para(&q(1, 50), &q(1, 2));
        for (floor, width) in [
            (JOINT_MIN_WIDTH, 1.0 / 1048576.0),
            (1.0 / 1024.0, 1.0 / 1024.0),
        ] {
            let opts = IntersectOptions {
                joint_min_width: floor,
                ..IntersectOptions::default()
            };
            let r = intersections(&[a.clone(), a.clone()], &opts);
            assert!(!r.complete && r.joints.is_empty(), "{r:?}");
            assert!(
                r.undecided.iter().any(|u| u.reason == "joint"
                    && u.s.1 - u.s.0 == width
                    && u.t.1 - u.t.0 == width),
                "{r:?}"
            );
        }
    }

    #[test]
    fn minus_corners_covers_the_rest() {
        let e = q(1, 8);
        let boxes = minus_corners(&[((1, 0), e.clone()), ((0, 1), e.clone())]);
        // sample points: covered unless in a cut corner
        for k in 0..=16 {
            for l in 0..=16 {
                let (s, t) = (q(k, 16), q(l, 16));
                let in_corner = (s >= <Rational as One>::one() - &e && t <= e)
                    || (s <= e && t >= <Rational as One>::one() - &e);
                let covered = boxes
                    .iter()
                    .any(|b| s >= b.x.0 && s <= b.x.1 && t >= b.y.0 && t <= b.y.1);
                assert!(covered || in_corner, "({s}, {t}) not covered");
            }
        }
    }
}
