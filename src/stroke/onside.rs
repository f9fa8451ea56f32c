//! Exact offset points proven **on ∂S**, a parameter interval at a time
//! (issue 27: a decision per sub-piece instead of one witness per `tol`).
//!
//! For an input piece `x = x_i`, a signed distance `d` (`|d| = r`) and a
//! parameter interval `T`, let `E(t) = x(t) + d·N(t)` (`N` the left unit
//! normal) be the exact offset. [`Input::on_boundary`] proves, in outward
//! rounded interval arithmetic (no float shortcut), that **every** `E(t)`,
//! `t ∈ T`, has `x(t)` as its unique nearest point on the whole input:
//!
//! * **local** (`K2`): on a window `W ⊇ T` of `x_i`,
//!   `g(t') = |E(t) − x(t')|²` has `g″ = 2|x′|² − 2(E(t) − x(t'))·x″ > 0` for
//!   every `t ∈ T`, `t' ∈ W` (interval hulls of the restricted control points
//!   and hodographs). Since `g′(t) = −2 d N(t)·x′(t) = 0`, `g` is strictly
//!   convex on `W` with its minimum `r²` at `t' = t` only. Where `W` reaches a
//!   joint, the neighbour's window `W_j` is also proven convex in `t'`, and
//!   the derivative at the joint points away from it: for a G¹ joint (exact
//!   check) `g_j′ = λ g′` at the joint with `λ > 0`, and `g′ ≤ 0` at `t' = 0`
//!   (resp. `≥ 0` at `1`) because the minimum is at `t ∈ W`; for a G⁰ joint
//!   `(E(t) − c)·x_j′ > 0` at the joint (resp. `< 0`) is proven directly.
//!   So `g_j` decreases towards the joint point `c`, where `g_j = g(joint) ≥ r²`
//!   with equality only at the same point `c = x(t)`. A window from a joint
//!   or from the foot `c` of a cap or join arc may instead be **monotone**:
//!   `g′/2 = (x − E)·x′` of one strict sign on it (Bernstein coefficients),
//!   `g` decreasing towards `c` — needed where the input bends more sharply
//!   than the pen (curvature radius below `r`), so `g` is not convex there
//!   although `c` is still the nearest point.
//! * **far** (`K1`): every other part of every input piece has a bounding box
//!   at squared distance `> r²` from the box of `E(T)` (subdividing `t'`).
//!
//! Then `f(E(t)) = r` with a unique nearest point, so `f` is differentiable
//! at `E(t)` with gradient `(E(t) − x(t))/r ≠ 0`: points arbitrarily close to
//! `E(t)` have `f > r`, and `E(t) ∈ ∂S`. The driver ([`Input::prove_interval`])
//! splits `T` where a test fails; the parts left unproven (near crossings,
//! cusps and concave corners) are charged by an enclosure of their arc length:
//! every point of `E` over an unproven run is within the run's length of an
//! endpoint of it that is proven (at least one leaf must be proven).
//!
//! See `proofs/trimming.md`, "Kept by exact ∂S intervals".

use super::circle::{Arc, ArcBox};
use crate::curve::{Bezier, V2};
use crate::scalar::{interval_from_rational, ulp, Interval, Rational};
use num_traits::{Signed, Zero};

type IB = Bezier<Interval>;
type IV = V2<Interval>;

fn point(x: f64) -> Interval {
    Interval::try_from((x, x)).unwrap_or(Interval::ENTIRE)
}

fn hull(xs: impl Iterator<Item = Interval>) -> Interval {
    let (mut lo, mut hi) = (f64::INFINITY, f64::NEG_INFINITY);
    for x in xs {
        if x.is_empty() {
            return Interval::ENTIRE;
        }
        lo = lo.min(x.inf());
        hi = hi.max(x.sup());
    }
    Interval::try_from((lo, hi)).unwrap_or(Interval::ENTIRE)
}

/// Every number of `v` is `> 0` (an empty `v`, whose ends are `+∞` and
/// `−∞`, is not).
fn above(v: Interval) -> bool {
    !v.is_empty() && v.inf() > 0.0
}

/// Every number of `v` is `< 0` (an empty `v` is not).
fn below(v: Interval) -> bool {
    !v.is_empty() && v.sup() < 0.0
}

/// The box of an interval Bézier's control points.
pub(crate) fn bbox(b: &IB) -> IV {
    V2::new(
        hull(b.points().iter().map(|p| p.x)),
        hull(b.points().iter().map(|p| p.y)),
    )
}

fn dot(a: &IV, b: &IV) -> Interval {
    a.x * b.x + a.y * b.y
}

/// The centre `c` of a box (a point) and the box minus it.
fn centre(e: &IV) -> (IV, IV) {
    let c = V2::new(point(e.x.mid()), point(e.y.mid()));
    let eps = V2::new(e.x - c.x, e.y - c.y);
    (c, eps)
}

fn coords(b: &IB) -> (Vec<Interval>, Vec<Interval>) {
    (
        b.points().iter().map(|p| p.x).collect(),
        b.points().iter().map(|p| p.y).collect(),
    )
}

fn add(a: &[Interval], b: &[Interval]) -> Vec<Interval> {
    a.iter().zip(b).map(|(x, y)| *x + *y).collect()
}

/// Rows of Pascal's triangle held exactly in `f64` (every entry below 2⁵³).
const EXACT_ROWS: usize = 56;

/// `C(n, k)` for `n < EXACT_ROWS`, exact `f64`s (sums of exact integers below
/// 2⁵³ are exact), computed once.
fn pascal() -> &'static [Vec<f64>] {
    static ROWS: std::sync::OnceLock<Vec<Vec<f64>>> = std::sync::OnceLock::new();
    ROWS.get_or_init(|| {
        let mut rows: Vec<Vec<f64>> = vec![vec![1.0]];
        for n in 1..EXACT_ROWS {
            let prev = &rows[n - 1];
            let row = (0..=n)
                .map(|k| {
                    let a = if k > 0 { prev[k - 1] } else { 0.0 };
                    let b = if k < n { prev[k] } else { 0.0 };
                    a + b
                })
                .collect();
            rows.push(row);
        }
        rows
    })
}

/// An enclosure of `C(n, k)`: exact from the table below [`EXACT_ROWS`], an
/// outward rounded product beyond (still an enclosure at any degree).
pub(crate) fn binom(n: usize, k: usize) -> Interval {
    if n < EXACT_ROWS {
        return point(pascal()[n][k]);
    }
    (0..k).fold(point(1.0), |acc, i| {
        acc * point((n - i) as f64) / point((i + 1) as f64)
    })
}

/// The Bernstein coefficients of a product (interval arithmetic, outward):
/// in the scaled basis `C(n, i)·a_i` a product is a convolution, so
/// `c_k = Σ C(m, i) C(n, j) a_i b_j / C(m + n, k)` with one division per
/// coefficient.
pub(crate) fn bprod(a: &[Interval], b: &[Interval]) -> Vec<Interval> {
    if a.is_empty() || b.is_empty() {
        return Vec::new();
    }
    let (m, n) = (a.len() - 1, b.len() - 1);
    // sums and products in `ulp` arithmetic, the division correctly rounded
    let sa: Vec<Interval> = a
        .iter()
        .enumerate()
        .map(|(i, x)| ulp::mul(binom(m, i), *x))
        .collect();
    let sb: Vec<Interval> = b
        .iter()
        .enumerate()
        .map(|(j, x)| ulp::mul(binom(n, j), *x))
        .collect();
    (0..=m + n)
        .map(|k| {
            let mut s = point(0.0);
            for i in k.saturating_sub(n)..=k.min(m) {
                s = ulp::add(s, ulp::mul(sa[i], sb[k - i]));
            }
            s / binom(m + n, k)
        })
        .collect()
}

/// The restriction of `x` to `[a, b]` (point parameters), reparametrised to
/// `[0, 1]`: control point `i` is the blossom `x(a^(n−i), b^i)`, each by de
/// Casteljau steps `(1 − u)·p + u·q` in [`ulp`] arithmetic (`1 − u`
/// enclosed), so each encloses the exact restriction's control point.
fn restrict(x: &IB, a: f64, b: f64) -> IB {
    let pts = x.points();
    let n = pts.len() - 1;
    let one = point(1.0);
    let (ua, ub) = (point(a), point(b));
    let (va, vb) = (ulp::sub(one, ua), ulp::sub(one, ub));
    let mut w: Vec<IV> = pts.to_vec();
    let out = (0..=n)
        .map(|i| {
            w.clone_from_slice(pts);
            for r in 0..n {
                let (u, v) = if r < n - i { (ua, va) } else { (ub, vb) };
                for j in 0..n - r {
                    w[j] = V2::new(
                        ulp::add(ulp::mul(w[j].x, v), ulp::mul(w[j + 1].x, u)),
                        ulp::add(ulp::mul(w[j].y, v), ulp::mul(w[j + 1].y, u)),
                    );
                }
            }
            w[0].clone()
        })
        .collect();
    Bezier::new(out)
}

/// Every Bernstein coefficient of `|x − c|²` (degree `2n`) is above `r2`,
/// so `|x(t) − c|² > r2` on `[0, 1]`: the test of [`bprod`]-built
/// coefficients, with the division by `C(2n, k)` moved to the other side
/// (`Σ_{i+j=k} C(n,i) C(n,j) δ_i·δ_j > C(2n, k)·r2`, `δ = x − c`), each
/// unordered pair once (weight `2 C(n,i) C(n,j)`, exact in `f64` below
/// [`EXACT_ROWS`]) and each square as a square, in [`ulp`] arithmetic; stops
/// at the first coefficient that fails.
fn sq_dist_above(pts: &[IV], c: &IV, r2: Interval) -> bool {
    let n = pts.len() - 1;
    if 2 * n >= EXACT_ROWS {
        // beyond the exact table: the general products
        let xs: Vec<Interval> = pts.iter().map(|p| p.x).collect();
        let ys: Vec<Interval> = pts.iter().map(|p| p.y).collect();
        let dx: Vec<Interval> = xs.iter().map(|v| *v - c.x).collect();
        let dy: Vec<Interval> = ys.iter().map(|v| *v - c.y).collect();
        let g = add(&bprod(&dx, &dx), &bprod(&dy, &dy));
        return g.iter().all(|v| above(*v - r2));
    }
    let d: Vec<(Interval, Interval)> = pts
        .iter()
        .map(|p| (ulp::sub(p.x, c.x), ulp::sub(p.y, c.y)))
        .collect();
    let row = &pascal()[n];
    let row2 = &pascal()[2 * n];
    (0..=2 * n).all(|k| {
        let mut sum = point(0.0);
        for i in k.saturating_sub(n)..=k / 2 {
            let j = k - i;
            let term = if i == j {
                let sq = ulp::add(ulp::sqr(d[i].0), ulp::sqr(d[i].1));
                ulp::mul(point(row[i] * row[i]), sq)
            } else {
                let pr = ulp::add(ulp::mul(d[i].0, d[j].0), ulp::mul(d[i].1, d[j].1));
                ulp::mul(point(2.0 * row[i] * row[j]), pr)
            };
            sum = ulp::add(sum, term);
        }
        above(ulp::sub(sum, ulp::mul(point(row2[k]), r2)))
    })
}

/// The Bernstein coefficients raised to degree `deg` (`≥` the current one).
fn elevate(a: &[Interval], deg: usize) -> Vec<Interval> {
    let n = a.len().saturating_sub(1);
    if deg <= n {
        return a.to_vec();
    }
    bprod(a, &vec![point(1.0); deg - n + 1])
}

/// The Bernstein coefficients, at one degree, of `g″/2 = |x′|² + (x − c)·x″`
/// (the convexity form of `g(t') = |p − x(t')|²` at the point `c`) and of
/// `x″`: `[q, x″_x, x″_y]`, so that the form at `p = c + ε` is
/// `q − ε·x″` (linear in `ε`, see [`whole_positive`]). `h`, `h2`: the
/// hodographs of `x`. The polynomial part is computed as one, so the
/// dependency of `x` and `x″` is not lost.
fn convex_form(x: &IB, h: &IB, h2: &IB, c: &IV) -> [Vec<Interval>; 3] {
    let n = x.degree();
    let (xs, ys) = coords(x);
    let dx: Vec<Interval> = xs.iter().map(|v| *v - c.x).collect();
    let dy: Vec<Interval> = ys.iter().map(|v| *v - c.y).collect();
    let (hx, hy) = coords(h);
    let (h2x, h2y) = coords(h2);
    let deg = (2 * n).saturating_sub(2).max(n);
    let q = add(
        &add(
            &elevate(&bprod(&hx, &hx), deg),
            &elevate(&bprod(&hy, &hy), deg),
        ),
        &add(
            &elevate(&bprod(&dx, &h2x), deg),
            &elevate(&bprod(&dy, &h2y), deg),
        ),
    );
    [q, elevate(&h2x, deg), elevate(&h2y, deg)]
}

/// As [`convex_form`] for the monotony form `g′/2 = (x − c)·x′`:
/// `[q, x′_x, x′_y]` (`x` of degree ≥ 1).
fn monotone_form(x: &IB, h: &IB, c: &IV) -> [Vec<Interval>; 3] {
    let deg = (2 * x.degree()).saturating_sub(1);
    let (xs, ys) = coords(x);
    let dx: Vec<Interval> = xs.iter().map(|v| *v - c.x).collect();
    let dy: Vec<Interval> = ys.iter().map(|v| *v - c.y).collect();
    let (hx, hy) = coords(h);
    [
        add(&bprod(&dx, &hx), &bprod(&dy, &hy)),
        elevate(&hx, deg),
        elevate(&hy, deg),
    ]
}

/// `sign · (q_k − p·(a_k, b_k)) > 0` for every `k` and every point `p` of
/// the box `e` (`[q, a, b]` from [`convex_form`] or [`monotone_form`]):
/// each coefficient of the form at `p ∈ e` lies in the interval computed,
/// since it is linear in `p`. With `e` the whole box of `E` and forms at the
/// origin (cached per piece) it is a fast first try on `[0, 1]`; with `e`
/// the box minus its centre it is the centred form on windows.
fn whole_positive(f: &[Vec<Interval>; 3], e: &IV, sign: i8) -> bool {
    let [q, hx, hy] = f;
    !q.is_empty()
        && q.len() == hx.len()
        && q.len() == hy.len()
        && q.iter().zip(hx).zip(hy).all(|((q, a), b)| {
            let v = *q - e.x * *a - e.y * *b;
            if sign > 0 {
                above(v)
            } else {
                below(v)
            }
        })
}

/// The unproven run at the end of `leaves` (in order) is already longer
/// than `budget`: the interval cannot be kept this way (stop early).
fn run_over(leaves: &[(bool, f64)], budget: f64) -> bool {
    let mut run = 0.0;
    for &(proven, len) in leaves.iter().rev() {
        if proven {
            break;
        }
        run += len;
    }
    run > budget
}

/// The largest unproven run of `leaves` (in order: proven, length bound),
/// rounded up; `None` when nothing is proven or a run exceeds `budget`.
fn charge(leaves: &[(bool, f64)], budget: f64) -> Option<f64> {
    if !leaves.iter().any(|l| l.0) {
        return None;
    }
    let mut worst: f64 = 0.0;
    let mut run: f64 = 0.0;
    for &(proven, len) in leaves {
        if proven {
            run = 0.0;
        } else {
            run += len;
            worst = worst.max(run);
        }
    }
    let worst = worst * (1.0 + 1e-12);
    (worst <= budget).then_some(worst)
}

/// A certain lower bound of the squared distance between two boxes, in
/// floats: each result rounded to nearest and stepped down once, which is
/// below the exact value (the argument of [`ulp`]); a gap rounded below 0
/// counts as 0, and so does every gap of an empty box (no bound).
fn box_dist2_lo(a: &IV, b: &IV) -> f64 {
    if [a.x, a.y, b.x, b.y].iter().any(|c| c.is_empty()) {
        return 0.0;
    }
    let gap = |p: Interval, q: Interval| -> f64 {
        let g = (q.inf() - p.sup())
            .next_down()
            .max((p.inf() - q.sup()).next_down());
        if g > 0.0 {
            g
        } else if g.is_nan() {
            f64::NAN
        } else {
            0.0
        }
    };
    // (a result rounded to 0 is below the exact non-negative value already)
    let down = |x: f64| if x > 0.0 { x.next_down() } else { x };
    let (gx, gy) = (gap(a.x, b.x), gap(a.y, b.y));
    down(down(gx * gx) + down(gy * gy))
}

/// The halves `[0, 1/2]` and `[1/2, 1]` of `x` (de Casteljau at `1/2`), each
/// step `(a + b)·(1/2)` in [`ulp`] arithmetic: enclosures of the exact halves'
/// control points.
fn halves(x: &IB) -> (IB, IB) {
    let half = point(0.5);
    x.split_by(|a, b| {
        V2::new(
            ulp::mul(ulp::add(a.x, b.x), half),
            ulp::mul(ulp::add(a.y, b.y), half),
        )
    })
}

/// Remembered one-form tests of one box on one piece: `(kind, w0, w1)` →
/// proven (`kind` 0 for convexity, the sign for monotony).
#[derive(Default)]
struct Memo(Vec<((i8, u64, u64), bool)>);

impl Memo {
    fn get_or(&mut self, kind: i8, w0: f64, w1: f64, test: impl FnOnce() -> bool) -> bool {
        let key = (kind, w0.to_bits(), w1.to_bits());
        if let Some(&(_, v)) = self.0.iter().find(|(k, _)| *k == key) {
            return v;
        }
        let v = test();
        self.0.push((key, v));
        v
    }
}

/// A joint of two input pieces, seen from one of them.
#[derive(Clone, Copy, Debug)]
struct Joint {
    /// The neighbour piece.
    piece: usize,
    /// The tangents are exactly parallel with the same direction.
    g1: bool,
}

struct InPiece {
    x: IB,
    /// The box of `x`'s control points.
    bb: IV,
    h: IB,
    h2: IB,
    /// The whole piece's Bernstein coefficients of `|x′|² + x·x″` and of
    /// `x″` (both coordinates), at one degree: the convexity test on the
    /// window `[0, 1]` is `q − p·x″ > 0` for every point `p` of the box
    /// ([`Input::convex_at`]), computed once per piece.
    convex_whole: [Vec<Interval>; 3],
    /// The same for the monotony test: `x·x′` and `x′`.
    monotone_whole: [Vec<Interval>; 3],
    /// The piece ending at this piece's start.
    prev: Option<Joint>,
    /// The piece starting at this piece's end.
    next: Option<Joint>,
}

/// The input curve in interval form with its joints, and the pen radius.
pub(crate) struct Input {
    pieces: Vec<InPiece>,
    /// Exact end points of each piece (start, end).
    ends: Vec<(V2<Rational>, V2<Rational>)>,
    r: Interval,
    r2: Interval,
}

fn end_dir(b: &Bezier<Rational>, end: bool) -> Option<V2<Rational>> {
    let p = b.points();
    let n = p.len();
    if end {
        (0..n - 1)
            .rev()
            .map(|k| p[n - 1].sub(&p[k]))
            .find(|v| !v.x.is_zero() || !v.y.is_zero())
    } else {
        (1..n)
            .map(|k| p[k].sub(&p[0]))
            .find(|v| !v.x.is_zero() || !v.y.is_zero())
    }
}

fn same_direction(u: &V2<Rational>, v: &V2<Rational>) -> bool {
    (&u.x * &v.y - &u.y * &v.x).is_zero() && (&u.x * &v.x + &u.y * &v.y).is_positive()
}

/// The widest window (parameter units) tried around an interval.
const MAX_WINDOW: f64 = 1.0;
/// Most neighbours a window runs through beyond a joint.
const MAX_CHAIN: usize = 16;
/// Subdivision depth of a far range.
const FAR_DEPTH: u32 = 10;
/// The floors tried in turn for unproven leaves, as divisors of the budget:
/// `budget/8` first (few nodes); where a run exceeds the budget — next to a
/// shallow crossing, where the clearance grows only like `s·sin θ` with the
/// distance `s` from it, so the unproven run is about `floor / sin θ` long —
/// again at `budget/128`.
const FLOOR_DIVS: [f64; 2] = [8.0, 128.0];

impl Input {
    /// `comps`: the connected components `(first, end, closed)` of `curve`.
    pub(crate) fn new(
        curve: &[Bezier<Rational>],
        comps: &[(usize, usize, bool)],
        r: &Rational,
    ) -> Self {
        let mut pieces: Vec<InPiece> = curve
            .iter()
            .map(|b| {
                let x = b.map(interval_from_rational);
                let h = x.hodograph();
                let h2 = h.hodograph();
                let zero = V2::new(point(0.0), point(0.0));
                let convex_whole = convex_form(&x, &h, &h2, &zero);
                let monotone_whole = monotone_form(&x, &h, &zero);
                InPiece {
                    convex_whole,
                    monotone_whole,
                    bb: bbox(&x),
                    x,
                    h,
                    h2,
                    prev: None,
                    next: None,
                }
            })
            .collect();
        for &(first, end, closed) in comps {
            let n = end - first;
            let links = if closed { n } else { n.saturating_sub(1) };
            for k in 0..links {
                let (a, b) = (first + k, first + (k + 1) % n);
                let g1 = match (end_dir(&curve[a], true), end_dir(&curve[b], false)) {
                    (Some(u), Some(v)) => same_direction(&u, &v),
                    _ => false,
                };
                pieces[a].next = Some(Joint { piece: b, g1 });
                pieces[b].prev = Some(Joint { piece: a, g1 });
            }
        }
        let ri = interval_from_rational(r);
        let ends = curve
            .iter()
            .map(|b| {
                let p = b.points();
                (p[0].clone(), p[p.len() - 1].clone())
            })
            .collect();
        Input {
            pieces,
            ends,
            r: ri,
            r2: ri * ri,
        }
    }

    /// Enclosures over `t ∈ [t0, t1]` of `E(t)` and of the arc length of `E`.
    fn offset_box(&self, i: usize, d: Interval, t0: f64, t1: f64) -> Option<(IV, f64)> {
        let p = &self.pieces[i];
        let (a, b) = (point(t0), point(t1));
        let xb = bbox(&restrict(&p.x, t0, t1));
        let hb = bbox(&restrict(&p.h, t0, t1));
        let h2b = bbox(&restrict(&p.h2, t0, t1));
        let n2 = dot(&hb, &hb);
        if n2.inf().is_nan() || n2.inf() <= 0.0 || !n2.sup().is_finite() {
            return None;
        }
        let len = n2.sqrt();
        let e = V2::new(xb.x - d * hb.y / len, xb.y + d * hb.x / len);
        // |E′| ≤ |x′| + |d|·|x′ × x″| / |x′|²
        let cross = hb.x * h2b.y - hb.y * h2b.x;
        let speed = len + d.abs() * cross.abs() / n2;
        let arc = (speed * (b - a)).sup();
        if !arc.is_finite() || !e.x.inf().is_finite() || !e.y.sup().is_finite() {
            return None;
        }
        Some((e, arc))
    }

    /// `g″ > 0` on `E × [w0, w1]` of piece `j`: with `c` the centre of the
    /// box `E` and `ε = E − c`, `g″/2 = |x′|² + (x − c)·x″ − ε·x″`, whose
    /// Bernstein coefficients on the window (a polynomial part computed as
    /// one, the small box `ε` apart) are all proven positive, halving the
    /// window up to twice.
    fn convex(&self, j: usize, e: &IV, w0: f64, w1: f64) -> bool {
        self.convex_at(j, e, w0, w1, 2)
    }

    fn convex_at(&self, j: usize, e: &IV, w0: f64, w1: f64, depth: u32) -> bool {
        self.convex_memo(j, e, w0, w1, depth, &mut Memo::default())
    }

    /// [`Input::convex_at`] with the one-form tests of this box `e` on piece
    /// `j` remembered in `memo`: a window search halves its window, whose
    /// halves and quarters are then the previous try's (same exact test, same
    /// answer; only the work is shared).
    fn convex_memo(&self, j: usize, e: &IV, w0: f64, w1: f64, depth: u32, memo: &mut Memo) -> bool {
        if w0 == 0.0 && w1 == 1.0 && whole_positive(&self.pieces[j].convex_whole, e, 1) {
            return true;
        }
        let one = memo.get_or(0, w0, w1, || {
            let xr = restrict(&self.pieces[j].x, w0, w1);
            let (c, eps) = centre(e);
            let h = xr.hodograph();
            whole_positive(&convex_form(&xr, &h, &h.hodograph(), &c), &eps, 1)
        });
        if one {
            return true;
        }
        if depth == 0 {
            return false;
        }
        let m = 0.5 * (w0 + w1);
        self.convex_memo(j, e, w0, m, depth - 1, memo)
            && self.convex_memo(j, e, m, w1, depth - 1, memo)
    }

    /// `g′` has the strict sign `sign` on `E × [w0, w1]` of piece `j`: with
    /// `c` the centre of the box `E` and `ε = E − c`, `g′/2 = (x − c)·x′ −
    /// ε·x′`, whose Bernstein coefficients on the window are all proven of
    /// that sign (halving the window up to twice). `sign > 0`: `g` strictly
    /// increases on the window, so a window from a point `x(w0)` where
    /// `g = r²` holds no other point as near; `sign < 0` the mirror image.
    fn monotone(&self, j: usize, e: &IV, w0: f64, w1: f64, sign: i8, depth: u32) -> bool {
        self.monotone_memo(j, e, (w0, w1), sign, depth, &mut Memo::default())
    }

    /// [`Input::monotone`] with its one-form tests remembered (see
    /// [`Input::convex_memo`]).
    fn monotone_memo(
        &self,
        j: usize,
        e: &IV,
        (w0, w1): (f64, f64),
        sign: i8,
        depth: u32,
        memo: &mut Memo,
    ) -> bool {
        if w0 == 0.0
            && w1 == 1.0
            && self.pieces[j].x.degree() > 0
            && whole_positive(&self.pieces[j].monotone_whole, e, sign)
        {
            return true;
        }
        let one = memo.get_or(sign, w0, w1, || {
            let xr = restrict(&self.pieces[j].x, w0, w1);
            if xr.degree() == 0 {
                return false;
            }
            let (c, eps) = centre(e);
            whole_positive(&monotone_form(&xr, &xr.hodograph(), &c), &eps, sign)
        });
        if one {
            return true;
        }
        if depth == 0 {
            return false;
        }
        let m = 0.5 * (w0 + w1);
        self.monotone_memo(j, e, (w0, m), sign, depth - 1, memo)
            && self.monotone_memo(j, e, (m, w1), sign, depth - 1, memo)
    }

    /// Every point of piece `j` over `[a, b]` is at distance `> r` from the
    /// box `e`: its bounding box is, or `|x − c|² − (r + ρ)² > 0` by Bernstein
    /// coefficients (`c` the box's centre, `ρ ≥` its half diagonal, so every
    /// point of the box is within `ρ` of `c`); subdividing `[a, b]`.
    fn far(&self, j: usize, e: &IV, a: f64, b: f64, depth: u32) -> bool {
        if b <= a {
            return true;
        }
        let p = &self.pieces[j];
        if a == 0.0 && b == 1.0 {
            // the whole piece: its box is computed once
            if box_dist2_lo(e, &p.bb) > self.r2.sup() {
                return true;
            }
            return self.far_part(&p.x, e, depth);
        }
        let xr = restrict(&p.x, a, b);
        if box_dist2_lo(e, &bbox(&xr)) > self.r2.sup() {
            return true;
        }
        self.far_part(&xr, e, depth)
    }

    /// [`Input::far`] on an enclosure `xr` of a part of a piece whose box is
    /// not already far: Bernstein coefficients, then de Casteljau halves
    /// (each an enclosure of its exact half).
    fn far_part(&self, xr: &IB, e: &IV, depth: u32) -> bool {
        let (c, eps) = centre(e);
        let (ex, ey) = (point(eps.x.mag()), point(eps.y.mag()));
        let reach = self.r + (ex * ex + ey * ey).sqrt();
        let r2 = reach * reach;
        self.far_pts(xr, e, &c, r2, depth)
    }

    /// [`Input::far_part`] on control points, with the box's centre `c` and
    /// `r2 ≥ (r + ρ)²` computed once.
    fn far_pts(&self, x: &IB, e: &IV, c: &IV, r2: Interval, depth: u32) -> bool {
        let pts = x.points();
        if sq_dist_above(pts, c, r2) {
            return true;
        }
        if depth == 0 {
            return false;
        }
        // hopeless: an end point of the part (a point of the piece) is
        // within `reach` of the centre, so no subdivision can prove it (an
        // early `false` only gives up; near a joint this saves 2^depth parts)
        for q in [&pts[0], &pts[pts.len() - 1]] {
            let (qx, qy) = (ulp::sub(q.x, c.x), ulp::sub(q.y, c.y));
            if ulp::add(ulp::sqr(qx), ulp::sqr(qy)).sup() < r2.inf() {
                return false;
            }
        }
        let (l, r) = halves(x);
        [l, r].iter().all(|h| {
            box_dist2_lo(e, &bbox(h)) > self.r2.sup() || self.far_pts(h, e, c, r2, depth - 1)
        })
    }

    /// The widest window `[w0, w1] ⊇ [t0, t1]` of piece `j` on which `g` is
    /// proven convex (`w` halved from `w_max`, not below `min_w`).
    fn window(
        &self,
        j: usize,
        e: &IV,
        (t0, t1): (f64, f64),
        w_max: f64,
        min_w: f64,
    ) -> Option<(f64, f64)> {
        let mut w = w_max;
        // a window from an end of the piece towards which g decreases (the
        // foot of a cap or join, a joint of a chain) may also be monotone
        let end_sign = match (t0, t1) {
            (a, b) if a == 0.0 && b == 0.0 => Some(1),
            (a, b) if a == 1.0 && b == 1.0 => Some(-1),
            _ => None,
        };
        // one box, one piece: the halved windows share their sub-windows
        let mut memo = Memo::default();
        loop {
            let (w0, w1) = ((t0 - w).max(0.0), (t1 + w).min(1.0));
            if self.convex_memo(j, e, w0, w1, 2, &mut memo)
                || end_sign.is_some_and(|sg| self.monotone_memo(j, e, (w0, w1), sg, 2, &mut memo))
            {
                return Some((w0, w1));
            }
            w *= 0.5;
            if w < min_w {
                return None;
            }
        }
    }

    /// `K1 ∧ K2` for `t ∈ [t0, t1]` of piece `i` (see the module docs): the
    /// widest own window from `start` down first, then narrower ones (a
    /// window that reaches a concave joint fails where a narrower one does
    /// not). Returns the arc length bound when it holds, and the margin `w`
    /// of the first convex window tried (`0` when there was none): a hint
    /// for the halves of `[t0, t1]` (where to start their window search;
    /// any window is proven before it is used, so only the work depends on
    /// the hint).
    fn holds(&self, i: usize, d: Interval, (t0, t1): (f64, f64), start: f64) -> (Option<f64>, f64) {
        let Some((e, arc)) = self.offset_box(i, d, t0, t1) else {
            return (None, 0.0);
        };
        let min_w = (t1 - t0) / 4.0;
        let mut w_max = start.max(min_w);
        let mut found = 0.0;
        while w_max >= min_w {
            let Some((w0, w1)) = self.window(i, &e, (t0, t1), w_max, min_w) else {
                return (None, found);
            };
            if found == 0.0 {
                found = (t0 - w0).max(w1 - t1);
            }
            if self.holds_with(i, &e, w0, w1) {
                return (Some(arc), found);
            }
            // a narrower window helps only where this one reached a piece end
            // that the interval does not touch
            if !((w0 == 0.0 && t0 > 0.0) || (w1 == 1.0 && t1 < 1.0)) {
                return (None, found);
            }
            w_max = ((t0 - w0).max(w1 - t1)) * 0.5;
        }
        (None, found)
    }

    /// The windows beyond the joint at the start (`forward = false`) or end
    /// of piece `i`: whole neighbours while `g` is proven convex on them (and,
    /// at a G⁰ joint, its derivative points towards `i`), then the widest
    /// proven part of the next one (windows only exempt parts from the far
    /// test: a chain that stops early leaves more to it).
    fn chain_windows(&self, i: usize, e: &IV, forward: bool) -> Vec<(usize, f64, f64)> {
        let mut out: Vec<(usize, f64, f64)> = Vec::new();
        let mut cur = i;
        for _ in 0..MAX_CHAIN {
            let p = &self.pieces[cur];
            let Some(jn) = (if forward { p.next } else { p.prev }) else {
                break;
            };
            let j = jn.piece;
            if j == i || out.iter().any(|w| w.0 == j) {
                break;
            }
            let q = &self.pieces[j];
            // a neighbour wholly farther than r needs no window: the far
            // test passes it by the same box test (stopping a chain early is
            // always sound, it only leaves more to the far test)
            if box_dist2_lo(e, &q.bb) > self.r2.sup() {
                break;
            }
            if !jn.g1 {
                // g_j′ at the joint (towards i) must be ≤ 0: for a previous
                // piece (E − c)·x_j′(1) > 0, for a next one (E − c)·x_j′(0) < 0
                let (c, tj) = if forward {
                    (&q.x.points()[0], &q.h.points()[0])
                } else {
                    (
                        q.x.points().last().expect("nonempty"),
                        q.h.points().last().expect("nonempty"),
                    )
                };
                let s = dot(&V2::new(e.x - c.x, e.y - c.y), tj);
                let ok = if forward { below(s) } else { above(s) };
                if !ok {
                    break;
                }
            }
            // g_j towards the joint: convex (its derivative there points to
            // i, shown above or by the G¹ argument), or monotone decreasing
            // towards it over the whole piece
            let towards = if forward { 1 } else { -1 };
            if self.convex(j, e, 0.0, 1.0) || self.monotone(j, e, 0.0, 1.0, towards, 2) {
                out.push((j, 0.0, 1.0));
                cur = j;
                continue;
            }
            let at = if forward { (0.0, 0.0) } else { (1.0, 1.0) };
            if let Some((w0, w1)) = self.window(j, e, at, 0.5, 1.0 / 1024.0) {
                out.push((j, w0, w1));
            }
            break;
        }
        out
    }

    fn holds_with(&self, i: usize, e: &IV, w0: f64, w1: f64) -> bool {
        let mut windows: Vec<(usize, f64, f64)> = vec![(i, w0, w1)];
        if w0 == 0.0 {
            windows.extend(self.chain_windows(i, e, false));
        }
        if w1 == 1.0 {
            windows.extend(self.chain_windows(i, e, true));
        }
        self.far_outside(e, &windows)
    }

    /// The windows from the point `c` along every piece that ends or starts
    /// there (the foot of a cap or join arc), with the derivative at `c`
    /// proven to point towards it, continued through joints
    /// ([`Input::chain_windows`]). `None` when some piece at `c` fails.
    fn point_windows(&self, c: &V2<Rational>, e: &IV) -> Option<Vec<(usize, f64, f64)>> {
        self.point_windows_from(c, e, &|_| MAX_WINDOW)
    }

    /// [`Input::point_windows`] with the window search on piece `j` starting
    /// at width `start(j)` instead of [`MAX_WINDOW`] (a hint from a
    /// neighbouring part of the same arc: only the order of the tries, and
    /// so possibly a narrower window, depends on it).
    fn point_windows_from(
        &self,
        c: &V2<Rational>,
        e: &IV,
        start: &dyn Fn(usize) -> f64,
    ) -> Option<Vec<(usize, f64, f64)>> {
        let ci = V2::new(interval_from_rational(&c.x), interval_from_rational(&c.y));
        let diff = V2::new(e.x - ci.x, e.y - ci.y);
        let mut out = Vec::new();
        for (j, ends) in self.ends.iter().enumerate() {
            let (at_start, at_end) = (ends.0 == *c, ends.1 == *c);
            if at_start && at_end {
                return None;
            }
            let p = &self.pieces[j];
            if at_end {
                // g_j′(1) = −2(p − c)·x_j′(1) < 0 and g_j convex: decreasing to c
                let t = p.h.points().last().expect("nonempty");
                if dot(&diff, t).inf().partial_cmp(&0.0) != Some(std::cmp::Ordering::Greater) {
                    return None;
                }
                let (w0, _) = self.window(j, e, (1.0, 1.0), start(j), 1.0 / 1024.0)?;
                out.push((j, w0, 1.0));
                if w0 == 0.0 {
                    out.extend(self.chain_windows(j, e, false));
                }
            }
            if at_start {
                let t = &p.h.points()[0];
                if dot(&diff, t).sup().partial_cmp(&0.0) != Some(std::cmp::Ordering::Less) {
                    return None;
                }
                let (_, w1) = self.window(j, e, (0.0, 0.0), start(j), 1.0 / 1024.0)?;
                out.push((j, 0.0, w1));
                if w1 == 1.0 {
                    out.extend(self.chain_windows(j, e, true));
                }
            }
        }
        (!out.is_empty()).then_some(out)
    }

    /// Everything outside `windows` is farther than `r` from the box `e`.
    fn far_outside(&self, e: &IV, windows: &[(usize, f64, f64)]) -> bool {
        for j in 0..self.pieces.len() {
            let mut ranges: Vec<(f64, f64)> = windows
                .iter()
                .filter(|w| w.0 == j)
                .map(|w| (w.1, w.2))
                .collect();
            ranges.sort_by(|a, b| a.0.total_cmp(&b.0));
            let mut at = 0.0;
            for (a, b) in ranges.iter().copied().chain(std::iter::once((1.0, 1.0))) {
                if a > at && !self.far(j, e, at, a, FAR_DEPTH) {
                    return false;
                }
                at = at.max(b);
            }
        }
        true
    }

    /// Proves every point of an exact arc of radius `r` about an end point
    /// or corner `c` of the input (a cap or join arc) on `∂S`, except
    /// unproven runs (charged by the length of their tangent polygons, as in
    /// [`Input::prove_interval`]): on each minor part, with `e` the box of
    /// its hull, every piece at `c` has `g_j = |p − x_j|²` convex or monotone on a window
    /// from `c` and decreasing towards it (so `≥ |p − c|² = r²`, equality at
    /// `c` only), and everything else is farther than `r`.
    pub(crate) fn prove_arc(&self, arc: &Arc, budget: f64, max_nodes: usize) -> Option<f64> {
        FLOOR_DIVS
            .iter()
            .find_map(|&div| self.prove_arc_at(arc, budget, budget / div, max_nodes))
    }

    /// [`Input::prove_arc`] with unproven parts split down to a tangent
    /// polygon length of `floor`.
    fn prove_arc_at(&self, arc: &Arc, budget: f64, floor: f64, max_nodes: usize) -> Option<f64> {
        let ri = interval_from_rational(&arc.radius);
        if !(ri.inf() <= self.r.sup() && self.r.inf() <= ri.sup()) {
            return None;
        }
        let mut parts = arc
            .minor_parts()?
            .iter()
            .map(ArcBox::new)
            .collect::<Option<Vec<_>>>()?;
        parts.reverse();
        let mut leaves: Vec<(bool, f64)> = Vec::new();
        let mut nodes = 0;
        let mut hints: std::collections::BTreeMap<usize, f64> = Default::default();
        while let Some(a) = parts.pop() {
            nodes += 1;
            if nodes > max_nodes {
                return None;
            }
            let hv = a.hull();
            let e = V2::new(hull(hv.iter().map(|p| p.x)), hull(hv.iter().map(|p| p.y)));
            let side = |p: &IV, q: &IV| {
                let d = V2::new(q.x - p.x, q.y - p.y);
                dot(&d, &d).sqrt().sup()
            };
            let len = side(&hv[0], &hv[1]) + side(&hv[1], &hv[2]);
            // the search starts at twice the window the last proven part
            // needed on each piece, and from the widest when that fails
            let hinted = self
                .point_windows_from(&arc.center, &e, &|j| {
                    hints.get(&j).copied().unwrap_or(MAX_WINDOW)
                })
                .filter(|w| self.far_outside(&e, w));
            let proven = match hinted {
                Some(w) => Some(w),
                None if !hints.is_empty() => self
                    .point_windows(&arc.center, &e)
                    .filter(|w| self.far_outside(&e, w)),
                None => None,
            };
            if let Some(w) = &proven {
                for &(j, w0, w1) in w {
                    hints.insert(j, (2.0 * (w1 - w0)).min(MAX_WINDOW));
                }
            }
            let ok = proven.is_some();
            if ok {
                leaves.push((true, len));
                continue;
            }
            match a.halves() {
                Some((l, r)) if len > floor => {
                    parts.push(r);
                    parts.push(l);
                }
                _ => {
                    leaves.push((false, len));
                    if run_over(&leaves, budget) {
                        log::trace!("onside: arc: unproven run over {budget} ({nodes} nodes)");
                        return None;
                    }
                }
            }
        }
        log::trace!(
            "onside: arc floor {floor}: {nodes} nodes, {} leaves, {} unproven",
            leaves.len(),
            leaves.iter().filter(|l| !l.0).count()
        );
        charge(&leaves, budget)
    }

    /// Proves `E(t) ∈ ∂S` on `[t0, t1]` of piece `i` except unproven runs,
    /// splitting where a test fails. Returns the largest unproven run's arc
    /// length bound (`0` when all is proven), or `None` when nothing is proven
    /// or a run exceeds `budget`.
    ///
    /// The floors of [`FLOOR_DIVS`] are tried in turn, each from where the
    /// previous one stopped: its proven leaves stay proven (the same tests on
    /// the same intervals), its unproven leaves are split further and the
    /// nodes it did not reach are searched at the finer floor.
    pub(crate) fn prove_interval(
        &self,
        i: usize,
        d: &Rational,
        t0: f64,
        t1: f64,
        budget: f64,
        max_nodes: usize,
    ) -> Option<f64> {
        if !(0.0..=1.0).contains(&t0) || !(0.0..=1.0).contains(&t1) || t0 > t1 {
            return None;
        }
        let di = interval_from_rational(d);
        let mut items = vec![Item::Node(t0, t1, MAX_WINDOW)];
        for div in FLOOR_DIVS {
            match self.prove_interval_at(i, di, items, budget, budget / div, max_nodes) {
                Ok(l) => return l,
                Err(rest) => items = rest,
            }
        }
        None
    }

    /// One floor of [`Input::prove_interval`]: `items` (in order) searched
    /// with unproven leaves split down to an arc length bound of `floor`.
    /// `Ok` with the charge when the search ran to the end (`None` when
    /// nothing is proven or a run exceeds `budget`); `Err` with the items in
    /// order where it stopped (a run over `budget`, or `max_nodes`), for a
    /// finer floor.
    fn prove_interval_at(
        &self,
        i: usize,
        di: Interval,
        items: Vec<Item>,
        budget: f64,
        floor: f64,
        max_nodes: usize,
    ) -> Result<Option<f64>, Vec<Item>> {
        // leaves in order: (proven, arc), and the unproven ones' nodes
        let mut leaves: Vec<(bool, f64)> = Vec::new();
        let mut done: Vec<Item> = Vec::new();
        let mut todo: Vec<Item> = items;
        todo.reverse();
        let mut nodes = 0;
        let stop = |done: Vec<Item>, todo: Vec<Item>| {
            let mut rest = done;
            rest.extend(todo.into_iter().rev());
            Err(rest)
        };
        while let Some(item) = todo.pop() {
            // (a, b, where the window search starts), and whether `holds`
            // already failed on it (an unproven leaf of a coarser floor)
            let (a, b, start, failed) = match item {
                Item::Proven(arc) => {
                    leaves.push((true, arc));
                    done.push(item);
                    continue;
                }
                Item::Node(a, b, start) => (a, b, start, false),
                Item::Open(a, b, next) => (a, b, next, true),
            };
            nodes += 1;
            if nodes > max_nodes {
                log::trace!("onside: piece {i}: more than {max_nodes} nodes");
                todo.push(item);
                return stop(done, todo);
            }
            // the halves' windows start one doubling above this node's first
            // convex window (their boxes are smaller, so at least as wide a
            // window is usually convex), or at this node's width without one
            let next = if failed {
                start
            } else {
                let (held, found) = self.holds(i, di, (a, b), start);
                if let Some(arc) = held {
                    leaves.push((true, arc));
                    done.push(Item::Proven(arc));
                    continue;
                }
                if found > 0.0 { 2.0 * found } else { b - a }.min(MAX_WINDOW)
            };
            let arc = self
                .offset_box(i, di, a, b)
                .map(|x| x.1)
                .unwrap_or(f64::INFINITY);
            let m = 0.5 * (a + b);
            if arc <= floor || !(a < m && m < b) {
                leaves.push((false, arc));
                done.push(Item::Open(a, b, next));
                if run_over(&leaves, budget) {
                    log::trace!("onside: piece {i}: unproven run over {budget} at t {b}");
                    return stop(done, todo);
                }
                continue;
            }
            todo.push(Item::Node(m, b, next));
            todo.push(Item::Node(a, m, next));
        }
        log::trace!(
            "onside: piece {i} floor {floor}: {nodes} nodes, {} leaves, {} unproven",
            leaves.len(),
            leaves.iter().filter(|l| !l.0).count()
        );
        Ok(charge(&leaves, budget))
    }
}

/// A part of a parameter interval in the ∂S search of
/// [`Input::prove_interval`], in order along it.
#[derive(Clone, Copy, Debug)]
enum Item {
    /// Not searched yet: `[a, b]` and where its window search starts.
    Node(f64, f64, f64),
    /// A proven leaf and its arc length bound.
    Proven(f64),
    /// An unproven leaf `[a, b]` (its test failed) and where its halves'
    /// window searches start.
    Open(f64, f64, f64),
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::shape::parse_curve;
    use crate::test_util::q;
    use proptest::prelude::*;

    #[test]
    fn a_segment_s_offsets_are_boundary_and_a_cusp_region_is_not() {
        let x = parse_curve("M 0 0 L 4 0").unwrap();
        let inp = Input::new(&x, &[(0, 1, false)], &q("1"));
        for d in ["1", "-1"] {
            assert_eq!(inp.prove_interval(0, &q(d), 0.0, 1.0, 0.1, 64), Some(0.0));
        }
        // a circle of radius 3 read as four quarter cubics: the inner offset
        // at r = 1 is proven; at r = 4 it is past the centre (inside S)
        let c = parse_curve(
            "M 3 0 C 3 1.6568542494923801 1.6568542494923801 3 0 3 \
             C -1.6568542494923801 3 -3 1.6568542494923801 -3 0 \
             C -3 -1.6568542494923801 -1.6568542494923801 -3 0 -3 \
             C 1.6568542494923801 -3 3 -1.6568542494923801 3 0 Z",
        )
        .unwrap();
        let inp = Input::new(&c, &[(0, 4, true)], &q("1"));
        // left of travel (counter-clockwise) is the inside
        assert_eq!(
            inp.prove_interval(0, &q("1"), 0.0, 1.0, 0.1, 256),
            Some(0.0)
        );
        assert_eq!(
            inp.prove_interval(0, &q("-1"), 0.0, 1.0, 0.1, 256),
            Some(0.0)
        );
        let inp4 = Input::new(&c, &[(0, 4, true)], &q("4"));
        assert_eq!(inp4.prove_interval(0, &q("4"), 0.0, 1.0, 0.1, 256), None);
        assert_eq!(
            inp4.prove_interval(0, &q("-4"), 0.0, 1.0, 0.1, 256),
            Some(0.0)
        );
    }

    #[test]
    fn crossing_ends_are_charged_not_proven() {
        // two parallel segments 1.5 apart with r = 1: the inner offsets are
        // inside S (the other segment is 0.5 away), the outer ones on ∂S
        let x = parse_curve("M 0 0 L 4 0 M 0 1.5 L 4 1.5").unwrap();
        let inp = Input::new(&x, &[(0, 1, false), (1, 2, false)], &q("1"));
        assert_eq!(inp.prove_interval(0, &q("1"), 0.0, 1.0, 0.1, 256), None);
        assert_eq!(
            inp.prove_interval(0, &q("-1"), 0.0, 1.0, 0.1, 256),
            Some(0.0)
        );
        // a corner: the outer offset of an L near the convex corner is proven
        let l = parse_curve("M 0 0 L 4 0 L 4 4").unwrap();
        let inp = Input::new(&l, &[(0, 2, false)], &q("1"));
        // the right side of travel is outside the turn (a left turn)
        assert_eq!(
            inp.prove_interval(0, &q("-1"), 0.0, 1.0, 0.1, 256),
            Some(0.0)
        );
        // the inner side ends in the concave corner: its end is charged
        let inner = inp.prove_interval(0, &q("1"), 0.0, 1.0, 2.0, 256);
        assert!(matches!(inner, Some(l) if l > 0.0), "{inner:?}");
    }

    #[test]
    fn the_binomial_table_is_exact() {
        for n in 0..EXACT_ROWS {
            for k in 0..=n {
                let exact = crate::poly::binomial_big(n, k);
                let b = binom(n, k);
                assert_eq!(b.inf(), b.sup());
                assert_eq!(
                    format!("{}", b.inf() as u64),
                    exact.to_string(),
                    "C({n}, {k})"
                );
            }
        }
    }

    #[test]
    fn interval_products_enclose_the_exact_ones_at_high_degree() {
        // degree 40 × 40: binomials far beyond f64's 53 bits
        let a: Vec<Rational> = (0..=40)
            .map(|k| Rational::new(((k * 7) % 11 - 5).into(), 3.into()))
            .collect();
        let b: Vec<Rational> = (0..=40)
            .map(|k| Rational::new(((k * 5) % 13 - 6).into(), 7.into()))
            .collect();
        let exact = crate::curve::bernstein_product(&a, &b);
        let iv = |v: &[Rational]| v.iter().map(interval_from_rational).collect::<Vec<_>>();
        let enclosed = bprod(&iv(&a), &iv(&b));
        assert_eq!(exact.len(), enclosed.len());
        for (e, i) in exact.iter().zip(&enclosed) {
            let x = interval_from_rational(e);
            assert!(i.inf() <= x.inf() && x.sup() <= i.sup(), "{e} not in {i:?}");
        }
    }

    /// The far form against the exact coefficients of `|x − c|²` (rational
    /// Bernstein products): it never claims "above" where an exact
    /// coefficient is not, and claims it wherever every exact coefficient
    /// is above by a relative hair (degrees 1–5, both outcomes many times).
    #[test]
    fn far_form_matches_the_exact_coefficients() {
        let mut rng = crate::test_util::TestRng::new(0x243f_6a88_85a3_08d3);
        let (mut above, mut not) = (0, 0);
        for case in 0..600 {
            let n = 1 + case % 5;
            let mut r = |m: i64| Rational::new(rng.int(m).into(), 64.into());
            let pts: Vec<V2<Rational>> = (0..=n).map(|_| V2::new(r(640), r(640))).collect();
            let c = V2::new(r(640), r(640));
            let r2 = r(6400).abs();
            let dx: Vec<Rational> = pts.iter().map(|p| &p.x - &c.x).collect();
            let dy: Vec<Rational> = pts.iter().map(|p| &p.y - &c.y).collect();
            let g: Vec<Rational> = crate::curve::bernstein_product(&dx, &dx)
                .iter()
                .zip(crate::curve::bernstein_product(&dy, &dy))
                .map(|(a, b)| a + b)
                .collect();
            let x = Bezier::new(pts.clone()).map(interval_from_rational);
            let ci = c.map(interval_from_rational);
            let got = sq_dist_above(x.points(), &ci, interval_from_rational(&r2));
            let exact = g.iter().all(|v| v > &r2);
            let hair = &r2 * Rational::new(1.into(), 1_000_000_000.into())
                + Rational::new(1.into(), 1_000_000_000.into());
            let clear = g.iter().all(|v| v > &(&r2 + &hair));
            assert!(!got || exact, "claimed above: {pts:?} c {c:?} r2 {r2}");
            assert!(!clear || got, "missed: {pts:?} c {c:?} r2 {r2}");
            if got {
                above += 1;
            } else {
                not += 1;
            }
        }
        assert!(above > 100 && not > 100, "{above} above, {not} not");
    }

    /// The exact squared distance of two boxes with float ends (rationals).
    fn exact_box_dist2(a: &IV, b: &IV) -> Rational {
        let q = |f: f64| crate::scalar::rational_from_f64(f).unwrap();
        let gap = |p: Interval, o: Interval| {
            let (g1, g2) = (q(o.inf()) - q(p.sup()), q(p.inf()) - q(o.sup()));
            let g = if g1 > g2 { g1 } else { g2 };
            if g.is_negative() {
                Rational::zero()
            } else {
                g
            }
        };
        let (gx, gy) = (gap(a.x, b.x), gap(a.y, b.y));
        &gx * &gx + &gy * &gy
    }

    /// The `ulp` geometry of the far and window tests against exact rational
    /// geometry: the restriction to `[a, b]` (blossoms), the halves at `1/2`
    /// and the products of Bernstein forms enclose the exact control points
    /// and coefficients; the boxes' squared distance is a lower bound of the
    /// exact one, and tight (within a relative `1e-12`). Control points with
    /// denominators 3 and 7 (never floats) and full-mantissa parameters.
    #[test]
    fn ulp_geometry_encloses_the_exact_geometry() {
        use crate::scalar::{rational_from_f64, IntervalExt};
        let mut rng = crate::test_util::TestRng::new(0x1319_8a2e_0370_7344);
        let mut apart = 0;
        for case in 0..400 {
            let n = 1 + case % 5;
            let mut r = |m: i64, d: i64| Rational::new(rng.int(m).into(), d.into());
            let pts: Vec<V2<Rational>> = (0..=n).map(|_| V2::new(r(3000, 3), r(7000, 7))).collect();
            let (dx, dy) = (r(9000, 3), r(9000, 7));
            let x = Bezier::new(pts.clone());
            let xi = x.map(interval_from_rational);
            let has =
                |iv: &IB, ex: &Bezier<Rational>| {
                    iv.points().len() == ex.points().len()
                        && iv.points().iter().zip(ex.points()).all(|(i, e)| {
                            i.x.contains_rational(&e.x) && i.y.contains_rational(&e.y)
                        })
                };
            // parameters with full mantissas (1 − a is not a float)
            let u = (rng.int(1 << 20) as f64 / f64::from(1 << 20)).abs() / 3.0;
            let v = u + (1.0 - u) * ((rng.int(1 << 20) as f64).abs() / f64::from(1 << 20)) / 1.1;
            let (a, b) = (u.min(v), u.max(v));
            let (qa, qb) = (rational_from_f64(a).unwrap(), rational_from_f64(b).unwrap());
            assert!(
                has(&restrict(&xi, a, b), &x.restrict(&qa, &qb)),
                "restrict {a} {b}"
            );
            let half = Rational::new(1.into(), 2.into());
            let (l, rr) = x.split(&half);
            let (li, ri) = halves(&xi);
            assert!(has(&li, &l), "left half");
            assert!(has(&ri, &rr), "right half");
            // a product of two Bernstein forms
            let (xs, ys) = x.coords();
            let (xsi, ysi) = coords(&xi);
            let exact = crate::curve::bernstein_product(&xs, &ys);
            let got = bprod(&xsi, &ysi);
            assert!(
                got.iter().zip(&exact).all(|(g, e)| g.contains_rational(e)),
                "bprod"
            );
            // two boxes: the hull of the control points and a moved one
            let b1 = bbox(&xi);
            let moved = Bezier::new(
                pts.iter()
                    .map(|p| V2::new(&p.x + &dx, &p.y + &dy))
                    .collect(),
            )
            .map(interval_from_rational);
            let b2 = bbox(&moved);
            let q = |f: f64| rational_from_f64(f).unwrap();
            let d2 = exact_box_dist2(&b1, &b2);
            let lo = box_dist2_lo(&b1, &b2);
            assert!(q(lo) <= d2, "box distance {lo} above the exact {d2}");
            let slack = &d2 * Rational::new(1.into(), 1_000_000_000_000i64.into());
            assert!(q(lo) >= &d2 - &slack, "box distance {lo} far below {d2}");
            if d2.is_positive() {
                apart += 1;
            }
        }
        assert!(apart > 100, "{apart} pairs of boxes apart");
    }

    /// [`box_dist2_lo`] on float boxes (full mantissas, exponents over 30
    /// binades or within 2, so that the gaps, squares and sums round):
    /// never above the exact squared distance, and within a relative `1e-12`.
    #[test]
    fn box_distance_is_a_tight_lower_bound() {
        use crate::scalar::rational_from_f64;
        let mut rng = crate::test_util::TestRng::new(0xa409_3822_299f_31d0);
        // half the cases over 30 binades, half within 2 (so that both
        // squares are of one size and their rounding errors add up)
        let mut k = 0;
        let mut f = || {
            k += 1;
            let m = 1.0 + (rng.int(1 << 52) as f64).abs() / 2f64.powi(52);
            let e = if k % 8 < 4 { rng.int(15) } else { rng.int(1) } as i32;
            m * 2f64.powi(e) * if rng.int(2) == 0 { 1.0 } else { -1.0 }
        };
        let q = |x: f64| rational_from_f64(x).unwrap();
        let mut rounded = 0;
        for _ in 0..40_000 {
            let iv = |a: f64, b: f64| Interval::try_from((a.min(b), a.max(b))).unwrap();
            let a = V2::new(iv(f(), f()), iv(f(), f()));
            let b = V2::new(iv(f(), f()), iv(f(), f()));
            let d2 = exact_box_dist2(&a, &b);
            let lo = box_dist2_lo(&a, &b);
            assert!(q(lo) <= d2, "{lo} above the exact {d2}: {a:?} {b:?}");
            let slack = &d2 * Rational::new(1.into(), 1_000_000_000_000i64.into());
            assert!(q(lo) >= &d2 - &slack, "{lo} far below {d2}");
            if q(lo) != d2 {
                rounded += 1;
            }
        }
        assert!(rounded > 1000, "{rounded} inexact cases");
        // an empty coordinate (inari's ends +∞, −∞) bounds nothing
        let one = Interval::try_from((1.0, 2.0)).unwrap();
        for (a, b) in [
            (V2::new(Interval::EMPTY, one), V2::new(one, one)),
            (V2::new(one, one), V2::new(one, Interval::EMPTY)),
        ] {
            assert_eq!(box_dist2_lo(&a, &b), 0.0);
        }
        // nor does it prove a sign or a far part
        assert!(!above(Interval::EMPTY) && !below(Interval::EMPTY));
        let c = V2::new(one, one);
        let pts = [V2::new(Interval::EMPTY, one), V2::new(one, one)];
        assert!(!sq_dist_above(&pts, &c, one));
    }

    // ----------------------------------------------------------------------
    // Independent oracle: dense sampling of the input can only show a point
    // of x closer than r to a point the lemma put on ∂S (a refutation).
    // ----------------------------------------------------------------------

    fn sampled_min_dist(curve: &[Bezier<f64>], p: (f64, f64)) -> f64 {
        let mut best = f64::INFINITY;
        for b in curve {
            let d2 = |t: f64| {
                let v = b.eval_fast(t);
                (v.x - p.0).powi(2) + (v.y - p.1).powi(2)
            };
            let n = 2000;
            let (mut bt, mut bd) = (0.0, f64::INFINITY);
            for k in 0..=n {
                let t = k as f64 / n as f64;
                if d2(t) < bd {
                    bd = d2(t);
                    bt = t;
                }
            }
            let (mut lo, mut hi) = (
                (bt - 1.0 / n as f64).max(0.0),
                (bt + 1.0 / n as f64).min(1.0),
            );
            for _ in 0..60 {
                let (m1, m2) = (lo + (hi - lo) * 0.382, lo + (hi - lo) * 0.618);
                if d2(m1) < d2(m2) {
                    hi = m2;
                } else {
                    lo = m1;
                }
            }
            best = best.min(d2(0.5 * (lo + hi))).min(bd);
        }
        best.sqrt()
    }

    fn offset_point(b: &Bezier<f64>, d: f64, t: f64) -> (f64, f64) {
        let p = b.eval_fast(t);
        let h = b.hodograph().eval_fast(t);
        let l = h.length();
        (p.x - d * h.y / l, p.y + d * h.x / l)
    }

    fn chain() -> impl Strategy<Value = Vec<Bezier<Rational>>> {
        // 1 to 3 cubics joined end to start, coordinates on a 1/64 grid
        let c = || (-128i64..=128).prop_map(|k| Rational::new(k.into(), 64.into()));
        let pt = move || (c(), c()).prop_map(|(x, y)| V2::new(x, y));
        (pt(), proptest::collection::vec((pt(), pt(), pt()), 1..=3)).prop_map(|(p0, rest)| {
            let mut start = p0;
            let mut out = Vec::new();
            for (a, b, e) in rest {
                out.push(Bezier::new(vec![start.clone(), a, b, e.clone()]));
                start = e;
            }
            out
        })
    }

    proptest! {
        #![proptest_config(ProptestConfig::with_cases(96))]

        #[test]
        fn proven_offset_points_have_no_closer_input_point(
            curve in chain(),
            rk in 1i64..=8,
            left in any::<bool>(),
            piece in 0usize..3,
            a in 0.0f64..1.0,
            w in 0.05f64..1.0,
        ) {
            let r = Rational::new(rk.into(), 8.into());
            let rf = rk as f64 / 8.0;
            let n = curve.len();
            let i = piece % n;
            let cf: Vec<Bezier<f64>> = curve.iter().map(|b| b.map(crate::scalar::Scalar::approx)).collect();
            // regular pieces only (the lemma needs x′ ≠ 0 on T anyway)
            let inp = Input::new(&curve, &[(0, n, false)], &r);
            let d = if left { r.clone() } else { -r.clone() };
            let (t0, t1) = (a, (a + w).min(1.0));
            if let Some(l) = inp.prove_interval(i, &d, t0, t1, 0.05, 512) {
                prop_assert!(l <= 0.05);
                let df = if left { rf } else { -rf };
                for k in 0..=40 {
                    let t = t0 + (t1 - t0) * k as f64 / 40.0;
                    if cf[i].hodograph().eval_fast(t).length() < 1e-9 {
                        continue;
                    }
                    let e = offset_point(&cf[i], df, t);
                    let m = sampled_min_dist(&cf, e);
                    // on ∂S up to the charged runs: a sampled point of x
                    // clearly closer than r − ℓ refutes the proof
                    prop_assert!(
                        m >= rf - l - 1e-9,
                        "E({t}) = {e:?} has a point of x at {m} < r = {rf} (charged {l})"
                    );
                }
            }
        }

        #[test]
        fn proven_cap_points_have_no_closer_input_point(
            curve in chain(),
            rk in 1i64..=8,
            clockwise in any::<bool>(),
        ) {
            let r = Rational::new(rk.into(), 8.into());
            let rf = rk as f64 / 8.0;
            let n = curve.len();
            let cf: Vec<Bezier<f64>> = curve.iter().map(|b| b.map(crate::scalar::Scalar::approx)).collect();
            let last = &cf[n - 1];
            let h = last.hodograph().eval_fast(1.0);
            prop_assume!(h.length() > 1e-6);
            let c = curve[n - 1].points()[3].clone();
            let nl = (-h.y, h.x);
            let from = crate::stroke::circle::snap(&c, &r, nl);
            let to = crate::stroke::circle::snap(&c, &r, (-nl.0, -nl.1));
            let (Some(from), Some(to)) = (from, to) else { return Ok(()); };
            let arc = Arc { center: c.clone(), radius: r.clone(), from, to, clockwise };
            let inp = Input::new(&curve, &[(0, n, false)], &r);
            if let Some(l) = inp.prove_arc(&arc, 0.05, 512) {
                let cx = (crate::scalar::Scalar::approx(&c.x), crate::scalar::Scalar::approx(&c.y));
                let (a0, a1) = {
                    let f = |p: &V2<Rational>| {
                        let (x, y) = (crate::scalar::Scalar::approx(&p.x) - cx.0, crate::scalar::Scalar::approx(&p.y) - cx.1);
                        y.atan2(x)
                    };
                    (f(&arc.from), f(&arc.to))
                };
                let mut sweep = a1 - a0;
                let tau = std::f64::consts::TAU;
                if clockwise { while sweep > 0.0 { sweep -= tau; } } else { while sweep < 0.0 { sweep += tau; } }
                for k in 0..=40 {
                    let th = a0 + sweep * k as f64 / 40.0;
                    let p = (cx.0 + rf * th.cos(), cx.1 + rf * th.sin());
                    let m = sampled_min_dist(&cf, p);
                    prop_assert!(m >= rf - l - 1e-9, "arc point {p:?}: a point of x at {m} < r = {rf}");
                }
            }
        }
    }
}
