//! Circular SVG arcs whose centre is irrational, replaced by circular arcs
//! with a **rational** centre and radius, certified near them
//! ([`NearElement`]).
//!
//! `A r r φ large sweep p₁` from `p₀` has its centre at `m + h (−d_y, d_x)`
//! (`d = p₁ − p₀`, `m` the chord's midpoint, `h² = r²/|d|² − 1/4`), which is
//! irrational unless `h²` is the square of a rational: icon sets draw
//! rounded corners as `a1 1 0 0 0 0 1.414`, whose chord is not `√2`. Engines
//! that decide a stroke exactly on lines and circles with rational data
//! ([`crate::stroke::exact_path`]) take the near arc instead of the cubic
//! approximation, and report the element within the near arc's bound.
//!
//! Two constructions, the first preferred:
//!
//! * **The radius kept** (`ρ′ = r`): the near arc starts at its start point
//!   `s` (the arc's `p₀`, or where the near arc before it ended), its centre
//!   is `c′ = s + r u` and its end `e = c′ + r v`, with `u`, `v` rational
//!   unit vectors (`((1 − τ²)/(1 + τ²), 2τ/(1 + τ²))`, `τ` rational) nearest
//!   the exact directions. The end `e` is not `p₁`, so the piece after the
//!   arc must start at `e`: a segment or Bézier of the same subpath (its
//!   first control point moved to `e`, within `|p₁ − e|` of itself: a
//!   Bézier moves by at most its largest control-point move), or the next
//!   arc of this kind (which then starts at `e`). Keeping `r` keeps what the
//!   designer made exact: a corner of radius exactly the pen's radius has
//!   no inner offset, and its end disks meet exactly at the centre.
//! * **The end points kept**: otherwise the near arc runs from `s` to `p₁`
//!   and its centre `m + t (−d_y, d_x)` lies on their bisector, with `t`
//!   rational near the exact offset and the radius `|d| √(1/4 + t²)`
//!   rational: with `D = d_x + i d_y` and `z = 1 + i k`, `u = 2t =
//!   Im w / Re w` for `w = z² D̄` makes `|d|² (1 + u²) = (|d|² |z|² / Re w)²`.
//!
//! **The bound** (intervals, outward rounding, the exact centre `c` enclosed
//! through an interval square root). Parameterise both arcs linearly in
//! their angles over `[0, 1]`, the same way round. When `(p₀ − c) × (p₁ − c)`
//! and `(s − c′) × (e − c′)` have the same strict sign, both sweeps are below
//! π or both above, so they differ by less than π, and `θ(σ) − θ′(σ) =
//! (1 − σ) δ₀ + σ δ₁` with `δᵢ` the angle between the unit directions `eᵢ`
//! (from `c` to the exact end `i`) and `e′ᵢ` (from `c′` to the near one).
//! Hence every point of either arc is within `|c − c′| + |r − ρ′| + ρ′
//! max |δᵢ|` of the other, and `|δᵢ| = 2 asin(|eᵢ − e′ᵢ|/2) ≤ 2 |eᵢ − e′ᵢ|`
//! when `|eᵢ − e′ᵢ| ≤ 1`. A replacement whose bound exceeds `10⁻⁹ r` is not
//! used (the cubic approximation stays).

use super::{ExactElement, ExactPiece, InputApprox, NearElement};
use crate::curve::{Bezier, V2};
use crate::scalar::{interval_from_rational, rational_from_f64, Interval, Rational};
use crate::shape::desc::ArcDesc;
use num_bigint::BigInt;
use num_traits::{One, Signed, ToPrimitive, Zero};

/// Largest denominator of the rational slopes chosen: the replacement is
/// then within about `10⁻¹²` of the arc's size, with small numbers for the
/// exact predicates downstream.
const MAX_DENOM: u64 = 1_000_000;

/// Largest certified bound accepted, relative to the radius.
const MAX_REL_BOUND: f64 = 1e-9;

/// A circular arc of SVG path data whose centre is irrational, as read: its
/// approximated element and the range of cubic pieces that stand for it.
#[derive(Clone, Debug)]
pub(crate) struct Pending {
    /// Index of its element in the reader's report.
    pub element: usize,
    /// Its cubic pieces: `first .. first + count` of the reader's output.
    pub first: usize,
    pub count: usize,
    pub p0: V2<Rational>,
    pub p1: V2<Rational>,
    pub r: Rational,
    pub large: bool,
    pub sweep: bool,
}

/// What the reader knows of its pieces besides the arcs.
pub(crate) struct Layout<'a> {
    /// Every piece index that begins a subpath.
    pub subpath_starts: &'a [usize],
    /// Every arc's range of pieces (all arcs, not only these).
    pub arc_ranges: &'a [(usize, usize)],
}

/// The exact arc, enclosed.
struct Exact<'a> {
    p: &'a Pending,
    r: Rational,
    /// The sign of `h`: the centre is `m + h (−d_y, d_x)`.
    positive: bool,
    /// The centre, enclosed, and in floats.
    c: [Interval; 2],
    cf: (f64, f64),
}

/// A near arc: centre, radius, travelled from `s` to `e` (counter-clockwise
/// when the SVG arc's `sweep` is set).
struct Near {
    center: V2<Rational>,
    radius: Rational,
    s: V2<Rational>,
    e: V2<Rational>,
}

fn iv(q: &Rational) -> Interval {
    interval_from_rational(q)
}

fn norm(v: [Interval; 2]) -> Interval {
    (v[0].sqr() + v[1].sqr()).sqrt()
}

fn half() -> Rational {
    Rational::new(BigInt::one(), 2.into())
}

fn midpoint(a: &V2<Rational>, b: &V2<Rational>) -> V2<Rational> {
    V2::new((&a.x + &b.x) * half(), (&a.y + &b.y) * half())
}

impl<'a> Exact<'a> {
    fn new(p: &'a Pending) -> Option<Exact<'a>> {
        let r = p.r.abs();
        let d = p.p1.sub(&p.p0);
        let len2 = d.norm2();
        if !r.is_positive() || len2.is_zero() {
            return None;
        }
        let h2 = &r * &r / &len2 - Rational::new(BigInt::one(), 4.into());
        if !h2.is_positive() || super::rational_sqrt(&h2).is_some() {
            return None;
        }
        // SVG F.6.5: the centre's offset has sign + when large ≠ sweep
        let positive = p.large != p.sweep;
        let h = {
            let s = iv(&h2).sqrt();
            if positive {
                s
            } else {
                -s
            }
        };
        let m = midpoint(&p.p0, &p.p1);
        let c = [iv(&m.x) - h * iv(&d.y), iv(&m.y) + h * iv(&d.x)];
        let cf = (c[0].mid(), c[1].mid());
        (cf.0.is_finite() && cf.1.is_finite()).then_some(Exact {
            p,
            r,
            positive,
            c,
            cf,
        })
    }

    /// The certified Hausdorff distance between this arc and `n`, or `None`
    /// when the argument does not apply or the bound is too large.
    fn bound(&self, n: &Near) -> Option<f64> {
        let cq = [iv(&n.center.x), iv(&n.center.y)];
        let (ri, rhoi) = (iv(&self.r), iv(&n.radius));
        let rel = |a: &V2<Rational>, c: &[Interval; 2]| [iv(&a.x) - c[0], iv(&a.y) - c[1]];
        // the same side: both sweeps below π or both above
        let (a0, a1) = (rel(&self.p.p0, &self.c), rel(&self.p.p1, &self.c));
        let cross = a0[0] * a1[1] - a0[1] * a1[0];
        let (b0, b1) = (n.s.sub(&n.center), n.e.sub(&n.center));
        let near_cross = b0.cross(&b1);
        let same = if near_cross.is_positive() {
            cross.inf() > 0.0
        } else if near_cross.is_negative() {
            cross.sup() < 0.0
        } else {
            false
        };
        if !same {
            return None;
        }
        let mut chord = Interval::try_from((0.0, 0.0)).ok()?;
        for (a, b) in [(&self.p.p0, &n.s), (&self.p.p1, &n.e)] {
            let ea = rel(a, &self.c);
            let eb = rel(b, &cq);
            let diff = [ea[0] / ri - eb[0] / rhoi, ea[1] / ri - eb[1] / rhoi];
            chord = chord.max(norm(diff));
        }
        let dc = norm([self.c[0] - cq[0], self.c[1] - cq[1]]);
        let dr = iv(&(&self.r - &n.radius).abs());
        let two = Interval::try_from((2.0, 2.0)).ok()?;
        let bound = (dc + dr + two * rhoi * chord).sup();
        let limit = MAX_REL_BOUND * self.r.to_f64()?;
        (chord.sup() <= 1.0 && bound.is_finite() && bound <= limit).then_some(bound)
    }

    /// The near arc from `s` with the radius kept: `c′ = s + r u`,
    /// `e = c′ + r v` (see the module docs).
    fn keep_radius(&self, s: &V2<Rational>) -> Option<Near> {
        let (sx, sy) = (s.x.to_f64()?, s.y.to_f64()?);
        let u = rational_unit((self.cf.1 - sy).atan2(self.cf.0 - sx))?;
        let center = V2::new(&s.x + &self.r * &u.x, &s.y + &self.r * &u.y);
        let (cx, cy) = (center.x.to_f64()?, center.y.to_f64()?);
        let (px, py) = (self.p.p1.x.to_f64()?, self.p.p1.y.to_f64()?);
        let v = rational_unit((py - cy).atan2(px - cx))?;
        let e = V2::new(&center.x + &self.r * &v.x, &center.y + &self.r * &v.y);
        Some(Near {
            center,
            radius: self.r.clone(),
            s: s.clone(),
            e,
        })
    }

    /// The near arcs from `s` to `p₁` with their centres on the bisector
    /// (see the module docs), those with the smaller radius first.
    fn keep_ends(&self, s: &V2<Rational>) -> Vec<Near> {
        let p1 = &self.p.p1;
        let d = p1.sub(s);
        let len2 = d.norm2();
        let quarter = Rational::new(BigInt::one(), 4.into());
        let two = Rational::from_integer(2.into());
        if len2.is_zero() {
            return Vec::new();
        }
        // the offset of the arc of radius r through s and p₁, in floats
        let h2 = &self.r * &self.r / &len2 - &quarter;
        let (Some(h2f), Some(dx), Some(dy)) = (h2.to_f64(), d.x.to_f64(), d.y.to_f64()) else {
            return Vec::new();
        };
        if h2f.is_nan() || h2f <= 0.0 {
            return Vec::new();
        }
        let hf = h2f.sqrt() * if self.positive { 1.0 } else { -1.0 };
        // arg z = (atan(2h) + arg D) / 2, modulo π/2 (z ↦ i z only flips z²)
        let q = std::f64::consts::FRAC_PI_4;
        let mut alpha = ((2.0 * hf).atan() + dy.atan2(dx)) / 2.0;
        while alpha > q {
            alpha -= 2.0 * q;
        }
        while alpha <= -q {
            alpha += 2.0 * q;
        }
        let Some(slope) = rational_from_f64(alpha.tan()) else {
            return Vec::new();
        };
        let m = midpoint(s, p1);
        let mut out: Vec<(bool, Near)> = Vec::new();
        for k in convergents(&slope, MAX_DENOM).iter().rev().take(2) {
            let (a, b) = (Rational::one() - k * k, k * &two);
            let (re, im) = (&a * &d.x + &b * &d.y, &b * &d.x - &a * &d.y);
            if re.is_zero() {
                continue;
            }
            let t = im / re / &two;
            if t.is_positive() != self.positive || t.is_zero() {
                continue;
            }
            let Some(radius) = super::rational_sqrt(&(&len2 * (&quarter + &t * &t))) else {
                continue;
            };
            let center = V2::new(&m.x - &t * &d.y, &m.y + &t * &d.x);
            // the smaller radius: ρ′² = |d|² (1/4 + t²) < r² ⇔ t² < h²
            let inside = &t * &t < h2;
            out.push((
                !inside,
                Near {
                    center,
                    radius,
                    s: s.clone(),
                    e: p1.clone(),
                },
            ));
        }
        out.sort_by_key(|(outside, _)| *outside);
        out.into_iter().map(|(_, n)| n).collect()
    }
}

/// The continued-fraction convergents `p/q` of `x` with `q ≤ max_denom`, in
/// order (they alternate sides of `x`).
fn convergents(x: &Rational, max_denom: u64) -> Vec<Rational> {
    let mut out = Vec::new();
    let (mut p0, mut q0) = (BigInt::zero(), BigInt::one());
    let (mut p1, mut q1) = (BigInt::one(), BigInt::zero());
    let limit = BigInt::from(max_denom);
    let mut rest = x.clone();
    for _ in 0..80 {
        let a = rest.floor().to_integer();
        let (p2, q2) = (&a * &p1 + &p0, &a * &q1 + &q0);
        if q2 > limit {
            break;
        }
        out.push(Rational::new(p2.clone(), q2.clone()));
        (p0, q0, p1, q1) = (p1, q1, p2, q2);
        let frac = &rest - Rational::from_integer(a);
        if frac.is_zero() {
            break;
        }
        rest = frac.recip();
    }
    out
}

/// A rational unit vector near the direction `θ` (radians):
/// `((1 − τ²)/(1 + τ²), 2τ/(1 + τ²))` with `τ` the last convergent of
/// `tan(θ/2)`, reduced to `|θ| ≤ π/2` (the vector negated back).
fn rational_unit(theta: f64) -> Option<V2<Rational>> {
    if !theta.is_finite() {
        return None;
    }
    let pi = std::f64::consts::PI;
    let (theta, flip) = if theta > pi / 2.0 {
        (theta - pi, true)
    } else if theta < -pi / 2.0 {
        (theta + pi, true)
    } else {
        (theta, false)
    };
    let tau = convergents(&rational_from_f64((theta / 2.0).tan())?, MAX_DENOM)
        .pop()
        .unwrap_or_else(Rational::zero);
    let den = Rational::one() + &tau * &tau;
    let (x, y) = (
        (Rational::one() - &tau * &tau) / &den,
        Rational::from_integer(2.into()) * &tau / &den,
    );
    Some(if flip { V2::new(-x, -y) } else { V2::new(x, y) })
}

fn arc_piece(n: &Near, sweep: bool) -> ExactPiece {
    let (u0, u1) = (n.s.sub(&n.center), n.e.sub(&n.center));
    let (from, to) = if sweep { (u0, u1) } else { (u1, u0) };
    ExactPiece::Arc(Box::new(ArcDesc {
        center: n.center.clone(),
        radius: n.radius.clone(),
        from,
        to,
    }))
}

fn is_point(b: &Bezier<Rational>) -> bool {
    b.points().iter().all(|p| *p == b.points()[0])
}

/// Gives every pending arc its [`NearElement`] in `approx` where one is
/// certified: the radius kept when the piece after it can move (a segment
/// or Bézier of the same subpath that is not part of an arc, or the next
/// pending arc), else the end points kept. An arc whose start moved (the
/// near arc before it ended elsewhere) and that gets no near arc takes the
/// arcs before it back to their cubic pieces.
pub(crate) fn attach_near(
    out: &[Bezier<Rational>],
    approx: &mut InputApprox,
    pending: &[Pending],
    layout: &Layout,
) {
    let exact: Vec<Option<Exact>> = pending.iter().map(Exact::new).collect();
    let starts_subpath = |j: usize| layout.subpath_starts.contains(&j);
    let in_arc = |j: usize| {
        layout
            .arc_ranges
            .iter()
            .any(|&(a, n)| (a..a + n).contains(&j))
    };
    let mut found: Vec<Option<NearElement>> = vec![None; pending.len()];
    // whether arc k's start is the end of arc k − 1's near arc
    let mut chained = vec![false; pending.len()];
    let mut moved: Option<V2<Rational>> = None;
    for (k, p) in pending.iter().enumerate() {
        let from_prev = moved.take();
        chained[k] = from_prev.is_some();
        let s = from_prev.unwrap_or_else(|| p.p0.clone());
        let j = p.first + p.count;
        let next_arc = pending
            .get(k + 1)
            .filter(|q| q.first == j && exact[k + 1].is_some() && !starts_subpath(j))
            .is_some();
        let neighbour = (!next_arc
            && j < out.len()
            && !starts_subpath(j)
            && !in_arc(j)
            && out[j].points()[0] == p.p1
            && !is_point(&out[j]))
        .then_some(j);
        let near = exact[k].as_ref().and_then(|x| {
            let kept = (next_arc || neighbour.is_some())
                .then(|| x.keep_radius(&s))
                .flatten()
                .and_then(|n| x.bound(&n).map(|b| (n, b)));
            // with the end fixed the next piece stays as it is
            kept.map(|(n, b)| (n, b, true)).or_else(|| {
                x.keep_ends(&s)
                    .into_iter()
                    .find_map(|n| x.bound(&n).map(|b| (n, b, false)))
            })
        });
        let Some((n, mut bound, moved_end)) = near else {
            // the arcs before that ended where this one should start go back
            let mut i = k;
            while chained[i] {
                i -= 1;
                found[i] = None;
            }
            continue;
        };
        let mut pieces = vec![arc_piece(&n, p.sweep)];
        let mut count = p.count;
        if moved_end {
            if let Some(j) = neighbour {
                let mut pts = out[j].points().to_vec();
                pts[0] = n.e.clone();
                pieces.push(ExactPiece::Bezier(Bezier::new(pts)));
                count += 1;
                let dp = p.p1.sub(&n.e);
                let step = norm([iv(&dp.x), iv(&dp.y)]).sup();
                bound = bound.max(step);
            } else {
                moved = Some(n.e.clone());
            }
        }
        found[k] = Some(NearElement {
            element: ExactElement {
                first: p.first,
                count,
                pieces,
            },
            bound,
        });
    }
    for (p, f) in pending.iter().zip(found) {
        if let Some(e) = approx.elements.get_mut(p.element) {
            e.near = f;
        }
    }
}

#[cfg(test)]
mod tests;
