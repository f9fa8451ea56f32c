//! SVG arcs, circles, ellipses and rounded rectangles read **exactly**: the
//! circular and elliptic arcs (and lines) that an approximated element *is*,
//! when its centre and radii are rational.
//!
//! The curve readers still return cubic pieces (the offset and stroke
//! engines take polynomial curves); each approximated element of their
//! [`InputApprox`] report may carry an [`ExactElement`]: the same point set
//! as exact [`ArcDesc`]/[`EllipseArcDesc`] arcs and line pieces, and the
//! range of the reader's pieces it replaces. The shape readers
//! ([`crate::shape::ShapeDesc::parse_reported`]) put them in place
//! ([`exact_mixed`]), so `hausdorff`, certificates and `verify --against`
//! compare with the exact element, with nothing to add for it.
//!
//! Which elements are exact:
//!
//! * `<circle>` and `<ellipse>`: two halves;
//! * rounded `<rect>`: its lines and four quarter arcs (circular when the
//!   radii are equal after SVG's clamping, elliptic otherwise);
//! * path data `A rx ry φ large sweep p1` from `p0` whose centre is
//!   rational. With `rx = ry = r` (any `φ`: a circle has no axis) the
//!   centre is `m ± h (−d_y, d_x)`, `d = p1 − p0`, `m` the chord's
//!   midpoint, `h = √(r²/|d|² − 1/4)` (SVG F.6.5), rational exactly when
//!   `r²/|d|² − 1/4` is the square of a rational — quarter and half circles
//!   between rational points are; a radius below half the chord is enlarged
//!   to it (F.6.6), exact when `|d|` is rational. With `rx ≠ ry`, `φ` must be
//!   a multiple of 90° (the only angles in degrees with rational cosine and
//!   sine) and the same test applies to the pre-image `A⁻¹ p`,
//!   `A = R(φ) diag(rx, ry)`, whose arc is circular.
//!
//! Under an SVG transform `x ↦ L x + t` (rational), every arc stays exact:
//! an elliptic arc `c + M u` becomes `L c + t + (L M) u`; a circle stays a
//! circle when `L` is a similarity with a rational scale, and becomes an
//! elliptic arc otherwise. An irrational `rotate(θ)` is replaced by a
//! rational rotation as before (its displacement stays reported).

use super::InputApprox;
use crate::curve::{Bezier, V2};
use crate::scalar::Rational;
use crate::shape::desc::{
    checked_arc, checked_curve, checked_ellipse_arc, err, ArcDesc, EllipseArcDesc, ShapeDesc,
};
use crate::shape::ShapeError;
use num_bigint::BigInt;
use num_traits::{One, Signed, Zero};

/// One exact piece of an element: a polynomial piece or a circular arc.
#[derive(Clone, Debug, PartialEq)]
pub enum ExactPiece {
    /// A polynomial piece (the sides of a rounded rectangle).
    Bezier(Bezier<Rational>),
    /// A circular arc.
    Arc(Box<ArcDesc>),
    /// An elliptic arc.
    EllipseArc(Box<EllipseArcDesc>),
}

/// The exact form of an approximated element: its pieces are the reader's
/// pieces `first .. first + n` (`n` = the element's
/// [`ApproxElement::pieces`](super::ApproxElement::pieces) for arcs and
/// circles; all the element's pieces for a rounded rectangle, see `count`).
#[derive(Clone, Debug, PartialEq)]
pub struct ExactElement {
    /// Index of the first piece it replaces in the reader's output.
    pub first: usize,
    /// How many consecutive pieces it replaces.
    pub count: usize,
    /// The exact pieces, in the order of the input (the same point set as
    /// the element itself).
    pub pieces: Vec<ExactPiece>,
}

impl ExactElement {
    /// The element mapped by `x ↦ L x + t`, `L = [[a, c], [b, d]]` (SVG's
    /// `matrix(a b c d e f)`). A circle stays a circle when `L` is a
    /// similarity with the rational scale `k` (`Lᵀ L = k² I`; a mirror,
    /// `det L < 0`, reverses the arc: `from` and `to` swap); otherwise it
    /// becomes the elliptic arc `L c + t + (r L) u` over the same pre-image
    /// directions, as every elliptic arc does (`M ↦ L M`).
    pub(crate) fn mapped(&self, m: &[Rational; 6], k: Option<&Rational>) -> ExactElement {
        let [a, b, c, d, e, f] = m;
        let lin = |p: &V2<Rational>| V2::new(a * &p.x + c * &p.y, b * &p.x + d * &p.y);
        let aff = |p: &V2<Rational>| {
            let q = lin(p);
            V2::new(q.x + e, q.y + f)
        };
        // L M, M by rows
        let times = |mm: &[[Rational; 2]; 2]| {
            [
                [a * &mm[0][0] + c * &mm[1][0], a * &mm[0][1] + c * &mm[1][1]],
                [b * &mm[0][0] + d * &mm[1][0], b * &mm[0][1] + d * &mm[1][1]],
            ]
        };
        let mirror = (a * d - b * c).is_negative();
        let k = k.filter(|k| k.is_positive());
        let pieces = self
            .pieces
            .iter()
            .map(|p| match p {
                ExactPiece::Bezier(bz) => {
                    ExactPiece::Bezier(Bezier::new(bz.points().iter().map(aff).collect()))
                }
                ExactPiece::Arc(arc) => match k {
                    Some(k) => {
                        let (from, to) = (lin(&arc.from), lin(&arc.to));
                        let (from, to) = if mirror { (to, from) } else { (from, to) };
                        ExactPiece::Arc(Box::new(ArcDesc {
                            center: aff(&arc.center),
                            radius: &arc.radius * k,
                            from,
                            to,
                        }))
                    }
                    None => {
                        let (r, z) = (arc.radius.clone(), Rational::zero());
                        ExactPiece::EllipseArc(Box::new(EllipseArcDesc {
                            center: aff(&arc.center),
                            matrix: times(&[[r.clone(), z.clone()], [z, r]]),
                            from: arc.from.clone(),
                            to: arc.to.clone(),
                        }))
                    }
                },
                ExactPiece::EllipseArc(arc) => ExactPiece::EllipseArc(Box::new(EllipseArcDesc {
                    center: aff(&arc.center),
                    matrix: times(&arc.matrix),
                    from: arc.from.clone(),
                    to: arc.to.clone(),
                })),
            })
            .collect();
        ExactElement {
            first: self.first,
            count: self.count,
            pieces,
        }
    }
}

/// `√r` when `r ≥ 0` is the square of a rational.
pub(crate) fn rational_sqrt(r: &Rational) -> Option<Rational> {
    if r.is_negative() {
        return None;
    }
    let root = |n: &BigInt| -> Option<BigInt> {
        let s = n.sqrt();
        (&s * &s == *n).then_some(s)
    };
    Some(Rational::new(root(r.numer())?, root(r.denom())?))
}

/// The circular arc of SVG's `A r r φ large sweep p1` from `p0` (`r > 0`,
/// `p0 ≠ p1`; `φ` does not matter for a circle), when its centre and radius
/// are rational; `None` otherwise. The arc runs counter-clockwise (in the
/// coordinates as given, from +x towards +y) from `from` to `to`: from `p0`
/// to `p1` for `sweep`, the other way round otherwise (the same point set).
pub(crate) fn circular_svg_arc(
    p0: &V2<Rational>,
    p1: &V2<Rational>,
    r: &Rational,
    large: bool,
    sweep: bool,
) -> Option<ArcDesc> {
    let r = r.abs();
    let d = p1.sub(p0);
    let len2 = d.norm2();
    if !r.is_positive() || len2.is_zero() {
        return None;
    }
    let two = Rational::from_integer(2.into());
    let quarter = Rational::new(BigInt::one(), 4.into());
    let mid = V2::new((&p0.x + &p1.x) / &two, (&p0.y + &p1.y) / &two);
    let h2 = &r * &r / &len2 - &quarter;
    let (center, radius) = if h2.is_positive() {
        let h = rational_sqrt(&h2)?;
        // SVG F.6.5: the centre's offset has sign + when large ≠ sweep
        let h = if large != sweep { h } else { -h };
        let center = V2::new(&mid.x - &h * &d.y, &mid.y + &h * &d.x);
        (center, r)
    } else {
        // a radius at most half the chord is enlarged to it (F.6.6)
        (mid, rational_sqrt(&len2)? / &two)
    };
    let (u0, u1) = (p0.sub(&center), p1.sub(&center));
    let (from, to) = if sweep { (u0, u1) } else { (u1, u0) };
    Some(ArcDesc {
        center,
        radius,
        from,
        to,
    })
}

/// The axis direction `k` (0: +x, 1: +y, 2: −x, 3: −y).
fn axis(k: u8) -> V2<Rational> {
    let (x, y) = match k % 4 {
        0 => (1, 0),
        1 => (0, 1),
        2 => (-1, 0),
        _ => (0, -1),
    };
    V2::new(
        Rational::from_integer(x.into()),
        Rational::from_integer(y.into()),
    )
}

/// The arc of the axis-aligned ellipse about `c` with radii `rx`, `ry > 0`
/// from the axis direction `start` through `quarters` quarter turns
/// counter-clockwise: a circular arc when `rx = ry`.
pub(crate) fn axis_ellipse_arc(
    c: &V2<Rational>,
    rx: &Rational,
    ry: &Rational,
    start: u8,
    quarters: u8,
) -> ExactPiece {
    let (from, to) = (axis(start), axis(start + quarters));
    if rx == ry {
        ExactPiece::Arc(Box::new(ArcDesc {
            center: c.clone(),
            radius: rx.clone(),
            from,
            to,
        }))
    } else {
        let z = Rational::zero();
        ExactPiece::EllipseArc(Box::new(EllipseArcDesc {
            center: c.clone(),
            matrix: [[rx.clone(), z.clone()], [z, ry.clone()]],
            from,
            to,
        }))
    }
}

/// The whole axis-aligned ellipse (a circle when `rx = ry`) as two halves
/// from `(cx + rx, cy)`.
pub(crate) fn ellipse(c: &V2<Rational>, rx: &Rational, ry: &Rational) -> Vec<ExactPiece> {
    vec![
        axis_ellipse_arc(c, rx, ry, 0, 2),
        axis_ellipse_arc(c, rx, ry, 2, 2),
    ]
}

/// The exact arc of SVG's `A rx ry φ large sweep p1` from `p0` (`p0 ≠ p1`,
/// `rx, ry ≠ 0`), when it has one: a circular arc when `|rx| = |ry|` and
/// its centre is rational ([`circular_svg_arc`]); an elliptic arc when `φ`
/// is a multiple of 90° (exact cosine and sine) and the centre of the
/// pre-image circle is rational: with `A = R(φ) diag(|rx|, |ry|)`, the
/// pre-image `A⁻¹ p` of the arc is the circular arc of radius 1 (or, by
/// F.6.6, larger) from `A⁻¹ p0` to `A⁻¹ p1` with the same flags.
pub(crate) fn svg_exact_arc(
    p0: &V2<Rational>,
    p1: &V2<Rational>,
    [rx, ry, phi]: [&Rational; 3],
    large: bool,
    sweep: bool,
) -> Option<ExactPiece> {
    let (rx, ry) = (rx.abs(), ry.abs());
    if rx == ry {
        return circular_svg_arc(p0, p1, &rx, large, sweep).map(|a| ExactPiece::Arc(Box::new(a)));
    }
    if !rx.is_positive() || !ry.is_positive() {
        return None;
    }
    let turn = Rational::from_integer(360.into());
    let deg = phi - (phi / &turn).floor() * &turn;
    let (cs, sn) = super::quarter(&deg)?;
    // A⁻¹ p = diag(1/rx, 1/ry) R(−φ) p
    let pre = |p: &V2<Rational>| {
        V2::new(
            (&cs * &p.x + &sn * &p.y) / &rx,
            (&cs * &p.y - &sn * &p.x) / &ry,
        )
    };
    let unit = circular_svg_arc(&pre(p0), &pre(p1), &Rational::one(), large, sweep)?;
    // A by rows, scaled by the pre-image radius s
    let s = &unit.radius;
    let a = [
        [&cs * &rx * s, -(&sn * &ry) * s],
        [&sn * &rx * s, &cs * &ry * s],
    ];
    let c = &unit.center;
    let center = V2::new(
        (&a[0][0] * &c.x + &a[0][1] * &c.y) / s,
        (&a[1][0] * &c.x + &a[1][1] * &c.y) / s,
    );
    Some(ExactPiece::EllipseArc(Box::new(EllipseArcDesc {
        center,
        matrix: a,
        from: unit.from,
        to: unit.to,
    })))
}

/// The shape a reader's `pieces` describe exactly: every approximated
/// element of `approx` that has an [`ExactElement`] is put in place of its
/// pieces (a [`ShapeDesc::Union`] of curve runs and arcs, in input order, or
/// the single member), and leaves the report. The other elements stay in the
/// returned report. Without exact elements: [`ShapeDesc::curve`]`(pieces)`.
pub(crate) fn exact_mixed(
    pieces: Vec<Bezier<Rational>>,
    approx: InputApprox,
) -> Result<(ShapeDesc, InputApprox), ShapeError> {
    let mut rest = InputApprox::default();
    let mut exact: Vec<ExactElement> = Vec::new();
    for mut e in approx.elements {
        match e.exact.take() {
            Some(x) if x.count > 0 && x.first + x.count <= pieces.len() => exact.push(x),
            _ => rest.push(e),
        }
    }
    if exact.is_empty() {
        return Ok((ShapeDesc::curve(pieces)?, rest));
    }
    exact.sort_by_key(|x| x.first);
    if exact
        .windows(2)
        .any(|w| w[0].first + w[0].count > w[1].first)
    {
        return Err(err(
            "svg",
            "internal error: exact elements overlap (please report)",
        ));
    }
    let mut members: Vec<ShapeDesc> = Vec::new();
    let mut run: Vec<Bezier<Rational>> = Vec::new();
    let flush = |run: &mut Vec<Bezier<Rational>>, members: &mut Vec<ShapeDesc>| {
        if !run.is_empty() {
            members.push(ShapeDesc::Curve(std::mem::take(run)));
        }
    };
    let mut next = exact.into_iter().peekable();
    let mut skip_to = 0;
    for (i, b) in pieces.into_iter().enumerate() {
        if let Some(x) = next.next_if(|x| x.first == i) {
            skip_to = x.first + x.count;
            for p in x.pieces {
                match p {
                    ExactPiece::Bezier(b) => run.push(b),
                    ExactPiece::Arc(a) => {
                        flush(&mut run, &mut members);
                        let name = format!("union[{}]", members.len());
                        members.push(ShapeDesc::Arc(checked_arc(*a, &name)?));
                    }
                    ExactPiece::EllipseArc(a) => {
                        flush(&mut run, &mut members);
                        let name = format!("union[{}]", members.len());
                        members.push(ShapeDesc::EllipseArc(Box::new(checked_ellipse_arc(
                            *a, &name,
                        )?)));
                    }
                }
            }
        }
        if i >= skip_to {
            run.push(b);
        }
    }
    flush(&mut run, &mut members);
    for (k, m) in members.iter_mut().enumerate() {
        if let ShapeDesc::Curve(c) = m {
            *m = checked_curve(std::mem::take(c), &format!("union[{k}]"))?;
        }
    }
    Ok((
        if members.len() == 1 {
            members.remove(0)
        } else {
            ShapeDesc::Union(members)
        },
        rest,
    ))
}

#[cfg(test)]
mod tests;
