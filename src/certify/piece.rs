//! The parametrisations of the shapes of [`crate::shape`] as [`Jet`]
//! evaluators: the certification engine's view of each piece.
//!
//! | shape | parametrisation over `t` |
//! |---|---|
//! | Bézier piece (any degree) | `B(t)`, `t ∈ [0, 1]` (de Casteljau) |
//! | circular arc, centre `c`, radius `R`, counter-clockwise from direction `d0` to `d1` | `c + R (cos φ e0 + sin φ e0⊥)` with `φ = 4 atan t`, i.e. `cos φ = ((1−t²)² − 4t²)/(1+t²)²`, `sin φ = 4t(1−t²)/(1+t²)²`, `t ∈ [0, tan(Θ/4)]` (`Θ` the sweep, `0 < Θ < 2π`) |
//! | offset `x + r N` of a polynomial piece | `x(t) + sign(r) Q n / √(nᵀ Q n)` with `n = x′(t)⊥` (left normal, not normalised) and `Q = r² I` |
//! | convolution of a polynomial piece with the ellipse `M · unit circle` | the same with `Q = M Mᵀ` and `side = ±1`: the ellipse point whose outer normal is `± n` |
//!
//! No sine or cosine is ever needed: `d0`, `d1` are vectors and the arc's end
//! parameter `tan(Θ/4)` is enclosed from half-angle identities.  The end parameter
//! is known only as an interval `[u⁻, u⁺]`, so each piece has an *outer* domain
//! `[0, u⁺]` (covers the whole arc: used where a superset is sound, i.e. upper
//! bounds on distances *from* the shape and lower bounds on distances *to* it) and
//! an *inner* domain `[0, u⁻]` (every parameter is a true point: used for foot
//! points and witnesses).  For the other shapes both are `[0, 1]`.

use super::jet::{Jet, JetPoint, JetScalar};
use super::CertifyError;
use crate::curve::{Bezier, V2};
use crate::scalar::{interval_from_rational, Interval, Rational, Scalar, ScalarSqrt, Sign};
use crate::shape::{ArcDesc, ShapeDesc};
use num_traits::{Signed, Zero};
/// Interval and float data of one parametrised piece.
#[derive(Clone, Debug)]
pub(crate) enum PieceData<S> {
    /// `pts` and its first and second hodographs (`d1`, `d2`; a single zero
    /// point where the degree is too low).
    Bez {
        pts: Vec<(S, S)>,
        d1: Vec<(S, S)>,
        d2: Vec<(S, S)>,
    },
    Arc {
        c: (S, S),
        r: S,
        e0: (S, S),
    },
    /// An elliptic arc `c + M (cos φ e0 + sin φ e0⊥)` (the unit-circle arc of
    /// the pre-image mapped by `M = [[m.0, m.1], [m.2, m.3]]`).
    EArc {
        c: (S, S),
        m: (S, S, S, S),
        e0: (S, S),
    },
    /// The curve `pts`, its hodographs `hod` (x′), `hod2` (x″), `hod3` (x‴).
    Conv {
        pts: Vec<(S, S)>,
        hod: Vec<(S, S)>,
        hod2: Vec<(S, S)>,
        hod3: Vec<(S, S)>,
        q: (S, S, S),
        sigma: S,
    },
}

/// One parametrised piece of a shape.
#[derive(Clone, Debug)]
pub(crate) struct Piece {
    pub iv: PieceData<Interval>,
    pub fl: PieceData<f64>,
    /// A parameter range covering the whole piece.
    pub outer: (f64, f64),
    /// A parameter range of true points of the piece (`⊆` the exact domain).
    pub inner: (f64, f64),
}

fn iv(r: &Rational) -> Interval {
    interval_from_rational(r)
}

fn mid(x: Interval) -> f64 {
    x.mid()
}

fn mid_data(d: &PieceData<Interval>) -> PieceData<f64> {
    let m2 = |p: &(Interval, Interval)| (mid(p.0), mid(p.1));
    let m2s = |v: &[(Interval, Interval)]| v.iter().map(m2).collect::<Vec<_>>();
    match d {
        PieceData::Bez { pts, d1, d2 } => PieceData::Bez {
            pts: m2s(pts),
            d1: m2s(d1),
            d2: m2s(d2),
        },
        PieceData::Arc { c, r, e0 } => PieceData::Arc {
            c: m2(c),
            r: mid(*r),
            e0: m2(e0),
        },
        PieceData::EArc { c, m, e0 } => PieceData::EArc {
            c: m2(c),
            m: (mid(m.0), mid(m.1), mid(m.2), mid(m.3)),
            e0: m2(e0),
        },
        PieceData::Conv {
            pts,
            hod,
            hod2,
            hod3,
            q,
            sigma,
        } => PieceData::Conv {
            pts: m2s(pts),
            hod: m2s(hod),
            hod2: m2s(hod2),
            hod3: m2s(hod3),
            q: (mid(q.0), mid(q.1), mid(q.2)),
            sigma: mid(*sigma),
        },
    }
}

impl Piece {
    fn from_iv(iv: PieceData<Interval>, outer: (f64, f64), inner: (f64, f64)) -> Piece {
        let fl = mid_data(&iv);
        Piece {
            iv,
            fl,
            outer,
            inner,
        }
    }

    pub(crate) fn bezier(b: &Bezier<Rational>) -> Piece {
        let [pts, d1, d2, _] = hodographs(b);
        Piece::from_iv(PieceData::Bez { pts, d1, d2 }, (0.0, 1.0), (0.0, 1.0))
    }

    fn conv(b: &Bezier<Rational>, q: [&Rational; 3], sigma: i8) -> Piece {
        let [pts, hod, hod2, hod3] = hodographs(b);
        let data = PieceData::Conv {
            pts,
            hod,
            hod2,
            hod3,
            q: (iv(q[0]), iv(q[1]), iv(q[2])),
            sigma: Interval::from_i64(sigma as i64),
        };
        Piece::from_iv(data, (0.0, 1.0), (0.0, 1.0))
    }

    pub(crate) fn arc(a: &ArcDesc) -> Result<Piece, CertifyError> {
        let (e0, u) = arc_frame(&a.from, &a.to)?;
        let data = PieceData::Arc {
            c: (iv(&a.center.x), iv(&a.center.y)),
            r: iv(&a.radius),
            e0,
        };
        Ok(Piece::from_iv(data, (0.0, u.sup()), (0.0, inner_end(u))))
    }

    /// The elliptic arc `c + M·(unit-circle arc counter-clockwise from the
    /// direction `from` to `to`)` (directions of the pre-image, any nonzero
    /// length, not the same direction), parametrised as [`Piece::arc`].
    pub(crate) fn ellipse_arc(
        c: &V2<Rational>,
        m: &[[Rational; 2]; 2],
        from: &V2<Rational>,
        to: &V2<Rational>,
    ) -> Result<Piece, CertifyError> {
        let (e0, u) = arc_frame(from, to)?;
        let data = PieceData::EArc {
            c: (iv(&c.x), iv(&c.y)),
            m: (iv(&m[0][0]), iv(&m[0][1]), iv(&m[1][0]), iv(&m[1][1])),
            e0,
        };
        Ok(Piece::from_iv(data, (0.0, u.sup()), (0.0, inner_end(u))))
    }
}

/// The end of an arc's inner domain: `u⁻ (1 − 10⁻¹²) ≤ u⁻`, a margin below the
/// enclosure of the end parameter, so that a foot map the search keeps inside
/// it stays inside the verifier's own (separately computed) enclosure too —
/// for identical arcs the foot of the end point is the end point itself.
/// Any value `≤ u⁻` is sound: every parameter of the inner domain is a true
/// point of the arc.
fn inner_end(u: Interval) -> f64 {
    u.inf() * (1.0 - 1e-12)
}

/// The unit start direction `e0` (enclosed) and the end parameter
/// `tan(Θ/4)` (enclosed, `> 0` and finite) of the counter-clockwise arc from
/// the direction `from` to `to`: shared by circular and elliptic arcs.
fn arc_frame(
    from: &V2<Rational>,
    to: &V2<Rational>,
) -> Result<((Interval, Interval), Interval), CertifyError> {
    let unit = |v: &V2<Rational>| -> Option<(Interval, Interval)> {
        let (x, y) = (iv(&v.x), iv(&v.y));
        let n = ScalarSqrt::sqrt(&(x.sqr() + y.sqr()))?;
        Some((x.div(&n)?, y.div(&n)?))
    };
    let bad = || {
        err(
            "arc",
            "the directions cannot be normalised in interval arithmetic",
        )
    };
    let e0 = unit(from).ok_or_else(bad)?;
    let e1 = unit(to).ok_or_else(bad)?;
    let u = arc_end_parameter(from, to, e0, e1)
        .filter(|u| u.inf() > 0.0 && u.sup().is_finite())
        .ok_or_else(|| {
            err(
                "arc.to",
                "the sweep is too close to 0 or 2π to enclose its end parameter",
            )
        })?;
    Ok((e0, u))
}

/// `(cos φ, sin φ)` of `φ = 4 atan t` as jets: the rational parametrisation
/// of the unit circle that circular and elliptic arcs share.
fn unit_arc<S: ScalarSqrt + JetScalar>(t: Jet<S>) -> Option<(Jet<S>, Jet<S>)> {
    let one = Jet::constant(S::one());
    let t2 = t * t;
    let a = one - t2;
    let inv = ((one + t2) * (one + t2)).recip()?;
    Some((
        (a * a - t2.scale(S::from_i64(4))) * inv,
        (t * a).scale(S::from_i64(4)) * inv,
    ))
}

/// Enclosures of the control points of `b` and of its first three hodographs:
/// the points enclosed once from the exact rationals, the hodographs
/// `m (pᵢ₊₁ − pᵢ)` then in interval arithmetic (sound enclosures of the exact
/// hodographs, without the rational arithmetic on large denominators).
fn hodographs(b: &Bezier<Rational>) -> [Vec<(Interval, Interval)>; 4] {
    hodographs_iv(b.points().iter().map(|p| (iv(&p.x), iv(&p.y))).collect())
}

/// [`hodographs`] from enclosures of the control points.
fn hodographs_iv(pts: Vec<(Interval, Interval)>) -> [Vec<(Interval, Interval)>; 4] {
    let hod = |c: &[(Interval, Interval)]| -> Vec<(Interval, Interval)> {
        let m = c.len().saturating_sub(1);
        if m == 0 {
            // the derivative of a constant: the zero polynomial
            let z = Interval::zero();
            return vec![(z, z)];
        }
        let k = Interval::from_i64(m as i64);
        c.windows(2)
            .map(|w| (k * (w[1].0 - w[0].0), k * (w[1].1 - w[0].1)))
            .collect()
    };
    let h1 = hod(&pts);
    let h2 = hod(&h1);
    let h3 = hod(&h2);
    [pts, h1, h2, h3]
}

/// The piece of the exact offset at `distance` of the span `[t₀, t₁]` of `x`
/// (reparametrised to `[0, 1]`), the same piece as
/// `ShapeDesc::Offset { curve: [x restricted to the span], distance }`, without
/// rational arithmetic: [`Bezier::restrict`] (blossoms, one *point* parameter
/// per level) in interval arithmetic on enclosures of `x`'s control points. `None` if `t` is not a finite span or the input pieces are
/// degenerate (checked by the caller's shape validation).
pub(crate) fn offset_span(
    x: &Bezier<Rational>,
    t: (f64, f64),
    distance: &Rational,
) -> Option<Piece> {
    let r2 = iv(&(distance * distance));
    let sigma = if distance.is_positive() { 1 } else { -1 };
    conv_span(x, t, (r2, Interval::zero(), r2), sigma)
}

/// The piece of the exact convolution of the span `[t₀, t₁]` of `x` with the
/// ellipse of `Q = M Mᵀ` (given as enclosures of `q₁₁, q₁₂, q₂₂`) on side
/// `sigma`, the same piece as `ShapeDesc::Convolution` of the exact
/// restriction (see [`offset_span`], its special case `Q = r² I`).
pub(crate) fn conv_span(
    x: &Bezier<Rational>,
    t: (f64, f64),
    q: (Interval, Interval, Interval),
    sigma: i8,
) -> Option<Piece> {
    let [pts, hod, hod2, hod3] = hodographs_iv(span_iv(x, t)?);
    let data = PieceData::Conv {
        pts,
        hod,
        hod2,
        hod3,
        q,
        sigma: Interval::from_i64(sigma as i64),
    };
    Some(Piece::from_iv(data, (0.0, 1.0), (0.0, 1.0)))
}

/// Enclosures of the control points of `x` restricted to `[t₀, t₁]` (`None`
/// unless `t₀ < t₁` are finite and `x` has points).
fn span_iv(x: &Bezier<Rational>, t: (f64, f64)) -> Option<Vec<(Interval, Interval)>> {
    if !(t.0.is_finite() && t.1.is_finite() && t.0 < t.1) || x.points().is_empty() {
        return None;
    }
    let (p0, p1) = (
        Interval::try_from((t.0, t.0)).ok()?,
        Interval::try_from((t.1, t.1)).ok()?,
    );
    let span = x.map(iv).restrict(&p0, &p1);
    Some(span.points().iter().map(|p| (p.x, p.y)).collect())
}

/// The piece of the span `[t₀, t₁]` of the Bézier curve `x` itself (its
/// exact restriction, enclosed in interval arithmetic as [`offset_span`]
/// encloses an offset's).
pub(crate) fn bezier_span(x: &Bezier<Rational>, t: (f64, f64)) -> Option<Piece> {
    let [pts, d1, d2, _] = hodographs_iv(span_iv(x, t)?);
    Some(Piece::from_iv(
        PieceData::Bez { pts, d1, d2 },
        (0.0, 1.0),
        (0.0, 1.0),
    ))
}

/// The piece of a Bézier curve with float (exact dyadic) control points.
pub(crate) fn bezier_f64(b: &Bezier<f64>) -> Option<Piece> {
    let pts = b
        .points()
        .iter()
        .map(|p| {
            Some((
                Interval::try_from((p.x, p.x)).ok()?,
                Interval::try_from((p.y, p.y)).ok()?,
            ))
        })
        .collect::<Option<Vec<_>>>()?;
    if pts.is_empty() {
        return None;
    }
    let [pts, d1, d2, _] = hodographs_iv(pts);
    Some(Piece::from_iv(
        PieceData::Bez { pts, d1, d2 },
        (0.0, 1.0),
        (0.0, 1.0),
    ))
}

/// `tan(Θ/4)` for the counter-clockwise sweep `Θ ∈ (0, 2π)` from `e0` to `e1`:
/// with `sin(Θ/2) = |e1 − e0|/2 > 0` and `cos(Θ/2) = ±|e1 + e0|/2` (the sign of
/// `e0 × e1`, decided exactly from the rational directions),
/// `tan(Θ/4) = sin(Θ/2)/(1 + cos(Θ/2)) = (1 − cos(Θ/2))/sin(Θ/2)`; the first form is
/// used for `Θ ≤ π`, the second beyond (no cancellation in either).
pub(crate) fn arc_end_parameter(
    from: &V2<Rational>,
    to: &V2<Rational>,
    e0: (Interval, Interval),
    e1: (Interval, Interval),
) -> Option<Interval> {
    let half = Interval::from_frac(1, 2);
    // `sqr` (not `x * x`): an interval around 0 must square to a nonnegative one.
    let norm = |x: Interval, y: Interval| ScalarSqrt::sqrt(&(x.sqr() + y.sqr()));
    let sin_h = norm(e1.0 - e0.0, e1.1 - e0.1)? * half;
    let cos_abs = norm(e1.0 + e0.0, e1.1 + e0.1)? * half;
    let cross = from.cross(to);
    let one = Interval::one();
    match cross.sign() {
        Sign::Positive => sin_h.div(&(one + cos_abs)),
        Sign::Zero if from.dot(to).is_negative() => Some(one), // Θ = π: tan(π/4) = 1
        Sign::Zero => None,
        _ => (one + cos_abs).div(&sin_h),
    }
}

impl<S: ScalarSqrt + Copy + Casteljau> PieceData<S> {
    /// The point alone: [`PieceData::eval`]'s value at `Jet::variable(t)`,
    /// the same operations (so the same result, bit for bit), without the
    /// derivatives where they are not needed for it (polynomial pieces).
    pub fn point(&self, t: S) -> Option<(S, S)> {
        match self {
            PieceData::Bez { pts, .. } => Some(S::casteljau(pts, t)),
            _ => self.eval(Jet::variable(t)).map(|(x, y)| (x.v, y.v)),
        }
    }

    /// The point of the piece at the parameter jet `t`, or `None` where the
    /// evaluation is undefined (a possibly vanishing normal or denominator).
    ///
    /// Polynomial parts are evaluated through their hodographs with scalar de
    /// Casteljau at `t.v` and the chain rule (`B(τ)′ = B′(τ) τ′`,
    /// `B(τ)″ = B″(τ) τ′² + B′(τ) τ″`): about a third of the interval products of
    /// de Casteljau on jets, and no wider.
    pub fn eval(&self, t: Jet<S>) -> Option<JetPoint<S>> {
        match self {
            PieceData::Bez { pts, d1, d2 } => {
                let p = S::casteljau(pts, t.v);
                let p1 = S::casteljau(d1, t.v);
                let p2 = S::casteljau(d2, t.v);
                Some(chain(p, p1, p2, t))
            }
            PieceData::Arc { c, r, e0 } => {
                let (cs, sn) = unit_arc(t)?;
                // c + r (cos φ e0 + sin φ e0⊥), e0⊥ = (−e0y, e0x)
                let x = Jet::constant(c.0) + (cs.scale(e0.0) - sn.scale(e0.1)).scale(*r);
                let y = Jet::constant(c.1) + (cs.scale(e0.1) + sn.scale(e0.0)).scale(*r);
                Some((x, y))
            }
            PieceData::EArc { c, m, e0 } => {
                let (cs, sn) = unit_arc(t)?;
                // the pre-image point u = cos φ e0 + sin φ e0⊥, then c + M u
                let u = cs.scale(e0.0) - sn.scale(e0.1);
                let v = cs.scale(e0.1) + sn.scale(e0.0);
                let x = Jet::constant(c.0) + u.scale(m.0) + v.scale(m.1);
                let y = Jet::constant(c.1) + u.scale(m.2) + v.scale(m.3);
                Some((x, y))
            }
            PieceData::Conv {
                pts,
                hod,
                hod2,
                hod3,
                q,
                sigma,
            } => {
                let p1 = S::casteljau(hod, t.v);
                let p2 = S::casteljau(hod2, t.v);
                let (x, y) = chain(S::casteljau(pts, t.v), p1, p2, t);
                let (dx, dy) = chain(p1, p2, S::casteljau(hod3, t.v), t);
                // n = (−y′, x′); Q n; nᵀ Q n
                let (n1, n2) = (-dy, dx);
                let qn1 = n1.scale(q.0) + n2.scale(q.1);
                let qn2 = n1.scale(q.1) + n2.scale(q.2);
                let nqn = n1 * qn1 + n2 * qn2;
                let inv = nqn.sqrt()?.recip()?;
                Some((x + (qn1 * inv).scale(*sigma), y + (qn2 * inv).scale(*sigma)))
            }
        }
    }
}

/// The jet of `B(τ(s))` from `B(τ)`, `B′(τ)`, `B″(τ)` and the jet `τ`.
fn chain<S: JetScalar>(p: (S, S), p1: (S, S), p2: (S, S), t: Jet<S>) -> JetPoint<S> {
    let d2 = t.d.times(t.d);
    let coord = |v: S, d: S, dd: S| Jet {
        v,
        d: d.times(t.d),
        dd: dd.times(d2).plus(d.times(t.dd)),
    };
    (coord(p.0, p1.0, p2.0), coord(p.1, p1.1, p2.1))
}

/// De Casteljau's algorithm at a scalar parameter (on the stack up to
/// [`STACK_POINTS`] control points: this runs for every box of a search).
fn casteljau<S: Scalar + Copy>(pts: &[(S, S)], t: S) -> (S, S) {
    fn run<S: Scalar + Copy>(buf: &mut [(S, S)], t: S) -> (S, S) {
        let n = buf.len();
        for level in 1..n {
            for i in 0..n - level {
                let (a, b) = (buf[i], buf[i + 1]);
                buf[i] = (a.0 + t * (b.0 - a.0), a.1 + t * (b.1 - a.1));
            }
        }
        buf[0]
    }
    let n = pts.len();
    if n <= STACK_POINTS {
        let mut buf = [pts[0]; STACK_POINTS];
        buf[..n].copy_from_slice(pts);
        run(&mut buf[..n], t)
    } else {
        run(&mut pts.to_vec(), t)
    }
}

/// Control points evaluated without a heap allocation.
const STACK_POINTS: usize = 24;

/// De Casteljau's algorithm as each scalar runs it in the hot loop of a search.
pub(crate) trait Casteljau: JetScalar {
    /// The point with Bézier control points `pts` at `t` (an enclosure of the
    /// range over `t` for intervals).
    fn casteljau(pts: &[(Self, Self)], t: Self) -> (Self, Self);
}

impl Casteljau for f64 {
    fn casteljau(pts: &[(f64, f64)], t: f64) -> (f64, f64) {
        casteljau(pts, t)
    }
}

impl Casteljau for Interval {
    /// [`super::bern::enclose`] (floats with an a-priori error bound, Bernstein
    /// hull over the parameter box) for parameters in `[0, 1]`; interval de
    /// Casteljau otherwise.
    fn casteljau(pts: &[(Interval, Interval)], t: Interval) -> (Interval, Interval) {
        super::bern::enclose(pts, t).unwrap_or_else(|| casteljau(pts, t))
    }
}

/// The parametrisation of a [`ShapeDesc`] as certification pieces (the
/// geometry model lives in [`crate::shape`]; this is the certification view).
pub(crate) trait Pieces {
    /// The parametrised pieces, with interval and float data.
    fn pieces(&self) -> Result<Vec<Piece>, CertifyError>;
}

impl Pieces for ShapeDesc {
    fn pieces(&self) -> Result<Vec<Piece>, CertifyError> {
        match self {
            ShapeDesc::Curve(c) => Ok(c.iter().map(Piece::bezier).collect()),
            ShapeDesc::Arc(a) => Ok(vec![Piece::arc(a)?]),
            ShapeDesc::EllipseArc(a) => Ok(vec![Piece::ellipse_arc(
                &a.center, &a.matrix, &a.from, &a.to,
            )?]),
            ShapeDesc::Offset { curve, distance } => {
                let r2 = distance * distance;
                let z = <Rational as Zero>::zero();
                let sigma = if distance.is_positive() { 1 } else { -1 };
                Ok(curve
                    .iter()
                    .map(|b| Piece::conv(b, [&r2, &z, &r2], sigma))
                    .collect())
            }
            ShapeDesc::Convolution {
                curve,
                ellipse: m,
                side,
            } => {
                let q11 = &m[0][0] * &m[0][0] + &m[0][1] * &m[0][1];
                let q12 = &m[0][0] * &m[1][0] + &m[0][1] * &m[1][1];
                let q22 = &m[1][0] * &m[1][0] + &m[1][1] * &m[1][1];
                Ok(curve
                    .iter()
                    .map(|b| Piece::conv(b, [&q11, &q12, &q22], *side))
                    .collect())
            }
            ShapeDesc::Union(m) => {
                let mut out = Vec::new();
                for s in m {
                    out.extend(s.pieces()?);
                }
                Ok(out)
            }
        }
    }
}

fn err(field: impl Into<String>, reason: impl Into<String>) -> CertifyError {
    CertifyError {
        field: field.into(),
        reason: reason.into(),
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::shape::ShapeDesc;

    /// [`PieceData::point`] is [`PieceData::eval`]'s value, bit for bit, on
    /// Béziers of degree 1–6, arcs and offsets (float and interval data).
    #[test]
    fn point_is_the_value_of_eval() {
        let shapes = [
            "M 0 0 L 3 1",
            "M 0 0 Q 1 2 3 1",
            "M 0 0 C 1 2 3 -1 4 0",
            r#"{"bezier": [[0, 0], [1, 3], [2, -2], [3, 4], [5, 0], [6, 1], [7, -1]]}"#,
            r#"{"arc": {"center": [1, 2], "radius": 3, "from": [1, 0], "to": [0, 1]}}"#,
            r#"{"offset": {"curve": {"bezier": [[0, 0], [1, 2], [3, 2], [4, 0]]}, "distance": "1/3"}}"#,
        ];
        let mut checked = 0;
        for text in shapes {
            let pieces = ShapeDesc::parse(text).unwrap().pieces().unwrap();
            for p in &pieces {
                for k in 0..=64 {
                    let t = p.inner.0 + (p.inner.1 - p.inner.0) * (k as f64 / 64.0);
                    let bits = |x: f64| x.to_bits();
                    if let Some((x, y)) = p.fl.eval(Jet::variable(t)) {
                        let (px, py) = p.fl.point(t).unwrap();
                        assert_eq!((bits(x.v), bits(y.v)), (bits(px), bits(py)), "{text} {t}");
                        checked += 1;
                    }
                    let ti = Interval::try_from((t, t)).unwrap();
                    if let Some((x, y)) = p.iv.eval(Jet::variable(ti)) {
                        let (px, py) = p.iv.point(ti).unwrap();
                        assert!(x.v == px && y.v == py, "{text} {t}");
                    }
                }
            }
        }
        assert!(checked > 300, "{checked}");
    }
}
