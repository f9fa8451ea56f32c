//! The kurbo bridge (feature `kurbo`): kurbo's curves as lncert shapes,
//! converted **exactly** (every `f64` is a dyadic rational; nothing is
//! rounded), certified verdicts on tolerance claims about them, and lncert's
//! results back out as kurbo paths (exact rationals rounded to the nearest
//! `f64`: [`path_from_beziers`], [`path_from_contours`]).
//!
//! | kurbo | lncert |
//! |---|---|
//! | [`kurbo::BezPath`] (`MoveTo`, `LineTo`, `QuadTo`, `CurveTo`, `ClosePath`) | [`shape_from_path`]: one Bézier piece per segment |
//! | [`kurbo::CubicBez`], [`kurbo::QuadBez`], [`kurbo::Line`] | [`shape_from_cubic`], [`shape_from_quad`], [`shape_from_line`] |
//! | [`kurbo::Circle`] | [`shapes_from_circle`]: four quarter arcs, exactly (centre and radius are floats, the directions `(±1, 0)`, `(0, ±1)`) |
//! | [`kurbo::Arc`] (circular: `radii.x == radii.y`) | [`arc_enclosure`]: an exact lncert arc **and** a proven `eps` with `d_H(kurbo's arc, lncert's arc) ≤ eps` (kurbo's end points are `cos`/`sin` of angles: not exact numbers) |
//! | out: [`kurbo::BezPath`] | [`path_from_beziers`] (Bézier pieces), [`path_from_contours`] (outlines: stroke contours, arcs as kurbo's cubics within a tolerance) |
//!
//! [`certify_within`] decides `d_H(a, b) ≤ tol` for any two shapes,
//! [`certify_union_within`] for unions of shapes (a circle is the union of its
//! four quarter arcs: [`circle_within`]); [`offset_within`] decides it for the
//! exact offset of a cubic against a path (such as the output of
//! `kurbo::offset::offset_cubic`), [`arc_within`] for a kurbo arc against a path
//! (the enclosure's `eps` is charged to the verdict by the triangle inequality).
//! A claim is reported exceeded only when a certified lower bound proves it.
//!
//! # Examples
//! ```
//! use kurbo::{BezPath, CubicBez};
//! use lncert::kurbo_bridge::{certify_within, shape_from_cubic, shape_from_path, Verdict};
//! let c = CubicBez::new((0.0, 0.0), (1.0, 1.0), (2.0, 1.0), (3.0, 0.0));
//! let mut flat = BezPath::new();
//! kurbo::flatten(c.path_elements(0.1), 1e-3, |el| flat.push(el));
//! let v = certify_within(&shape_from_cubic(c).unwrap(), &shape_from_path(&flat).unwrap(), 1e-3).unwrap();
//! assert!(matches!(v, Verdict::Within { .. }), "{v:?}");
//! # use kurbo::Shape;
//! ```

use crate::certify::piece::Pieces;
use crate::certify::{hausdorff, hausdorff_pieces, Config};
use crate::curve::{Bezier, V2};
use crate::scalar::{rational_from_f64, sin_cos_enclosure, Interval, Rational, Scalar, ScalarSqrt};
use crate::shape::{ArcDesc, ShapeDesc};
use crate::{Error, Tolerance};
use kurbo::{Arc, BezPath, Circle, CubicBez, Line, PathEl, Point, QuadBez};

/// A certified verdict on `d_H(a, b) ≤ tol`.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum Verdict {
    /// Proven: `d_H ≤ hi ≤ tol`.
    Within {
        /// The certified upper bound.
        hi: f64,
    },
    /// Proven false: `tol < lo ≤ d_H`.
    Exceeds {
        /// The certified lower bound.
        lo: f64,
    },
    /// Not decided within the budget: `lo ≤ d_H ≤ hi`, `lo ≤ tol < hi`.
    Undecided {
        /// The certified lower bound.
        lo: f64,
        /// The certified upper bound.
        hi: f64,
    },
}

fn exact(x: f64, field: &str) -> Result<Rational, Error> {
    rational_from_f64(x).ok_or_else(|| Error {
        field: field.to_string(),
        reason: format!("{x} is not a finite number"),
    })
}

fn point(p: Point, field: &str) -> Result<V2<Rational>, Error> {
    Ok(V2::new(
        exact(p.x, &format!("{field}.x"))?,
        exact(p.y, &format!("{field}.y"))?,
    ))
}

fn bezier(pts: &[Point], field: &str) -> Result<Bezier<Rational>, Error> {
    let pts = pts
        .iter()
        .enumerate()
        .map(|(i, p)| point(*p, &format!("{field}[{i}]")))
        .collect::<Result<Vec<_>, _>>()?;
    Ok(Bezier::new(pts))
}

/// The pieces of a path, exactly: one Bézier piece per `LineTo` / `QuadTo` /
/// `CurveTo`, and a line back to the subpath's start at `ClosePath` (when it
/// is not already there). Errors name the element (`path[3]`).
pub fn shape_from_path(path: &BezPath) -> Result<ShapeDesc, Error> {
    let mut pieces = Vec::new();
    let (mut start, mut last): (Option<Point>, Option<Point>) = (None, None);
    for (i, el) in path.elements().iter().enumerate() {
        let field = format!("path[{i}]");
        let from = || {
            last.ok_or_else(|| Error {
                field: field.clone(),
                reason: "a segment before any MoveTo".to_string(),
            })
        };
        match *el {
            PathEl::MoveTo(p) => {
                start = Some(p);
                last = Some(p);
            }
            PathEl::LineTo(p) => {
                pieces.push(bezier(&[from()?, p], &field)?);
                last = Some(p);
            }
            PathEl::QuadTo(p1, p2) => {
                pieces.push(bezier(&[from()?, p1, p2], &field)?);
                last = Some(p2);
            }
            PathEl::CurveTo(p1, p2, p3) => {
                pieces.push(bezier(&[from()?, p1, p2, p3], &field)?);
                last = Some(p3);
            }
            PathEl::ClosePath => {
                if let (Some(s), Some(l)) = (start, last) {
                    if s != l {
                        pieces.push(bezier(&[l, s], &field)?);
                    }
                    last = Some(s);
                }
            }
        }
    }
    ShapeDesc::curve(pieces)
}

/// A point of lncert's as kurbo's: each coordinate the nearest `f64`.
fn kpoint(p: &V2<Rational>, field: &str) -> Result<Point, Error> {
    let (x, y) = (p.x.approx(), p.y.approx());
    if !(x.is_finite() && y.is_finite()) {
        return Err(Error {
            field: field.to_string(),
            reason: "a coordinate beyond the f64 range".to_string(),
        });
    }
    Ok(Point::new(x, y))
}

/// One Bézier piece appended to `path` (from its current point): `LineTo`,
/// `QuadTo` or `CurveTo`; a higher degree has no kurbo element.
fn push_bezier(path: &mut BezPath, b: &Bezier<Rational>, field: &str) -> Result<(), Error> {
    let p = b
        .points()
        .iter()
        .map(|v| kpoint(v, field))
        .collect::<Result<Vec<_>, _>>()?;
    match p[..] {
        [_, p1] => path.line_to(p1),
        [_, p1, p2] => path.quad_to(p1, p2),
        [_, p1, p2, p3] => path.curve_to(p1, p2, p3),
        _ => {
            return Err(Error {
                field: field.to_string(),
                reason: format!(
                "a degree-{} Bézier piece has no kurbo path element (degree ≤ 3: fit it as cubics)",
                p.len() - 1
            ),
            })
        }
    }
    Ok(())
}

/// Bézier pieces (a curve as lncert reads it) as a kurbo path, the reverse
/// of [`shape_from_path`]: a `MoveTo` wherever a piece does not start exactly
/// where the previous one ended, then one `LineTo` / `QuadTo` / `CurveTo`
/// per piece, every coordinate the nearest `f64` (exact for pieces read from
/// floats, so that [`shape_from_path`] gives the same pieces back). No
/// `ClosePath`: a curve is not a region. Errors name the piece (`pieces[2]`):
/// a degree above 3, a coordinate beyond the `f64` range.
///
/// # Examples
/// ```
/// use lncert::kurbo_bridge::{path_from_beziers, shape_from_path};
/// let c = lncert::parse_curve("M 0 0 Q 1 1 2 0 L 3 0").unwrap();
/// let path = path_from_beziers(&c).unwrap();
/// assert_eq!(path.elements().len(), 3);
/// assert_eq!(shape_from_path(&path).unwrap(), lncert::ShapeDesc::curve(c).unwrap());
/// ```
pub fn path_from_beziers(pieces: &[Bezier<Rational>]) -> Result<BezPath, Error> {
    let mut path = BezPath::new();
    let mut last: Option<&V2<Rational>> = None;
    for (i, b) in pieces.iter().enumerate() {
        let field = format!("pieces[{i}]");
        let pts = b.points();
        if last != Some(&pts[0]) {
            path.move_to(kpoint(&pts[0], &field)?);
        }
        push_bezier(&mut path, b, &field)?;
        last = pts.last();
    }
    Ok(path)
}

/// Outline contours (such as a stroke's, [`crate::stroke::trim::stroke`]) as
/// a kurbo path: per contour a `MoveTo`, one element per Bézier piece (as in
/// [`path_from_beziers`]), each exact arc as kurbo's cubic approximation of
/// the circular arc within `arc_tolerance` (`kurbo::Arc::append_iter`), its
/// last point replaced by the arc's exact end point rounded (so consecutive
/// pieces still meet exactly), and a `ClosePath` after a closed contour. The
/// orientation is kept: kurbo's signed area (`Shape::area`) of a stroke's
/// outline is positive (outer contours counter-clockwise, holes clockwise).
/// Errors name the piece (`contours[0].pieces[3]`): a degree above 3, a
/// coordinate beyond the `f64` range; or `arc_tolerance` (not `> 0`).
///
/// # Examples
/// ```
/// use kurbo::Shape;
/// use lncert::kurbo_bridge::path_from_contours;
/// use lncert::stroke::{Contour, Orientation, Piece};
/// use lncert::stroke::Arc;
/// use lncert::V2;
/// let q = |x: i64| lncert::Rational::from_integer(x.into());
/// // a unit circle as two exact half arcs, counter-clockwise
/// let half = |from: V2<_>, to: V2<_>| Piece::Arc(Arc {
///     center: V2::new(q(0), q(0)), radius: q(1), from, to, clockwise: false });
/// let c = Contour {
///     pieces: vec![half(V2::new(q(1), q(0)), V2::new(q(-1), q(0))),
///                  half(V2::new(q(-1), q(0)), V2::new(q(1), q(0)))],
///     closed: true, orientation: Orientation::CounterClockwise, area: (3.14, 3.15),
/// };
/// let path = path_from_contours(&[c], 1e-6).unwrap();
/// assert!((path.area() - std::f64::consts::PI).abs() < 1e-5);
/// ```
pub fn path_from_contours(
    contours: &[crate::stroke::trim::Contour],
    arc_tolerance: f64,
) -> Result<BezPath, Error> {
    use crate::stroke::trim::Piece;
    if !(arc_tolerance.is_finite() && arc_tolerance > 0.0) {
        return Err(Error {
            field: "arc_tolerance".to_string(),
            reason: format!("{arc_tolerance}: must be a finite number > 0"),
        });
    }
    let mut path = BezPath::new();
    for (i, c) in contours.iter().enumerate() {
        let Some(first) = c.pieces.first() else {
            continue;
        };
        path.move_to(kpoint(first.start(), &format!("contours[{i}].pieces[0]"))?);
        for (j, p) in c.pieces.iter().enumerate() {
            let field = format!("contours[{i}].pieces[{j}]");
            match p {
                Piece::Bezier(b) => push_bezier(&mut path, b, &field)?,
                Piece::Arc(a) => push_arc(&mut path, a, arc_tolerance, &field)?,
            }
        }
        if c.closed {
            path.close_path();
        }
    }
    Ok(path)
}

/// An exact arc as kurbo's cubics (see [`path_from_contours`]). The travelled
/// angle is `atan2(u × v, u · v)` of the exact end directions `u`, `v`, taken
/// in `(0, 2π]` counter-clockwise or `[−2π, 0)` clockwise (a whole turn when
/// the end points are equal): the side is decided exactly, also for tiny arcs.
fn push_arc(
    path: &mut BezPath,
    a: &crate::stroke::circle::Arc,
    tol: f64,
    field: &str,
) -> Result<(), Error> {
    use std::f64::consts::TAU;
    let center = kpoint(&a.center, field)?;
    let end = kpoint(&a.to, field)?;
    let (u, v) = (a.from.sub(&a.center), a.to.sub(&a.center));
    let turn = u.cross(&v).approx().atan2(u.dot(&v).approx());
    let sweep = match (a.clockwise, a.from == a.to) {
        (false, true) => TAU,
        (true, true) => -TAU,
        (false, false) if turn > 0.0 => turn,
        (false, false) => turn + TAU,
        (true, false) if turn < 0.0 => turn,
        (true, false) => turn - TAU,
    };
    let (ux, uy) = (u.x.approx(), u.y.approx());
    let r = a.radius.approx();
    let arc = Arc {
        center,
        radii: kurbo::Vec2::new(r, r),
        start_angle: uy.atan2(ux),
        sweep_angle: sweep,
        x_rotation: 0.0,
    };
    let mut els: Vec<PathEl> = arc.append_iter(tol).collect();
    match els.last_mut() {
        Some(PathEl::CurveTo(_, _, p3)) => *p3 = end,
        _ => path.line_to(end),
    }
    for el in els {
        path.push(el);
    }
    Ok(())
}

/// A cubic, exactly.
pub fn shape_from_cubic(c: CubicBez) -> Result<ShapeDesc, Error> {
    ShapeDesc::curve(vec![bezier(&[c.p0, c.p1, c.p2, c.p3], "cubic")?])
}

/// A quadratic, exactly.
pub fn shape_from_quad(q: QuadBez) -> Result<ShapeDesc, Error> {
    ShapeDesc::curve(vec![bezier(&[q.p0, q.p1, q.p2], "quad")?])
}

/// A line segment, exactly.
pub fn shape_from_line(l: Line) -> Result<ShapeDesc, Error> {
    ShapeDesc::curve(vec![bezier(&[l.p0, l.p1], "line")?])
}

/// The exact offset `c + d N` of a cubic (`N` the unit normal to the left of
/// the direction of travel in a y-up frame — the side of kurbo's
/// `offset_cubic` for `d > 0`). The cubic must be regular (`c′ ≠ 0`).
pub fn exact_offset(c: CubicBez, d: f64) -> Result<ShapeDesc, Error> {
    ShapeDesc::offset(
        vec![bezier(&[c.p0, c.p1, c.p2, c.p3], "cubic")?],
        exact(d, "distance")?,
    )
}

/// Decides `d_H(a, b) ≤ tol` with certified bounds (the default budget).
pub fn certify_within(a: &ShapeDesc, b: &ShapeDesc, tol: f64) -> Result<Verdict, Error> {
    check_tol(tol)?;
    let r = hausdorff(
        a,
        b,
        &Config {
            // the search's goal (a tolerance 0 aims at the smallest float);
            // the verdict compares the bounds with `tol` itself
            tol: Tolerance::goal(tol),
            ..Config::default()
        },
    )?;
    Ok(if r.hi <= tol {
        Verdict::Within { hi: r.hi }
    } else if r.lo > tol {
        Verdict::Exceeds { lo: r.lo }
    } else {
        Verdict::Undecided { lo: r.lo, hi: r.hi }
    })
}

/// Decides whether `path` is within `tol` of the exact offset of `c` by `d`
/// (for instance `kurbo::offset::offset_cubic(c, d, tol, &mut path)`'s claim).
pub fn offset_within(c: CubicBez, d: f64, path: &BezPath, tol: f64) -> Result<Verdict, Error> {
    certify_within(&exact_offset(c, d)?, &shape_from_path(path)?, tol)
}

fn input_error(field: &str, reason: impl Into<String>) -> Error {
    Error {
        field: field.to_string(),
        reason: reason.into(),
    }
}

fn check_tol(tol: f64) -> Result<(), Error> {
    if tol.is_finite() && tol >= 0.0 {
        Ok(())
    } else {
        Err(input_error(
            "tol",
            format!("{tol} is not a finite number ≥ 0"),
        ))
    }
}

/// An upper bound on the real `x + y` (round to nearest, then one step up).
fn add_up(x: f64, y: f64) -> f64 {
    let s = x + y;
    if s.is_finite() {
        s.next_up()
    } else {
        s
    }
}

/// A lower bound on the real `x − y`, at least 0.
fn sub_down(x: f64, y: f64) -> f64 {
    let s = x - y;
    if s.is_finite() {
        s.next_down().max(0.0)
    } else {
        s.max(0.0)
    }
}

/// A circle as four counter-clockwise quarter arcs, **exactly**: the centre and
/// the radius are floats (dyadic rationals), and the quarters run between the
/// directions `(1, 0)`, `(0, 1)`, `(−1, 0)`, `(0, −1)` (exact). Their union is
/// the circle; compare a path with it by [`certify_union_within`] (or
/// [`circle_within`]), which bounds distances to the union, not to each quarter.
///
/// A negative radius describes the same circle as its absolute value (kurbo
/// draws `center + r (cos θ, sin θ)`); a zero or non-finite radius, or a
/// non-finite centre, is an error naming the field.
///
/// # Examples
/// ```
/// use kurbo::Circle;
/// use lncert::kurbo_bridge::shapes_from_circle;
/// let quarters = shapes_from_circle(Circle::new((1.0, 2.0), 0.5)).unwrap();
/// assert_eq!(quarters.len(), 4);
/// assert_eq!(shapes_from_circle(Circle::new((0.0, 0.0), f64::NAN)).unwrap_err().field, "circle.radius");
/// ```
pub fn shapes_from_circle(c: Circle) -> Result<Vec<ShapeDesc>, Error> {
    let center = point(c.center, "circle.center")?;
    let radius = exact(c.radius.abs(), "circle.radius")?;
    if c.radius == 0.0 {
        return Err(input_error(
            "circle.radius",
            "a circle of radius 0 is a point",
        ));
    }
    let int = |x: i64| Rational::from_integer(x.into());
    let dirs = [(1, 0), (0, 1), (-1, 0), (0, -1)];
    (0..4)
        .map(|i| {
            let (f, t) = (dirs[i], dirs[(i + 1) % 4]);
            ShapeDesc::arc(ArcDesc {
                center: center.clone(),
                radius: radius.clone(),
                from: V2::new(int(f.0), int(f.1)),
                to: V2::new(int(t.0), int(t.1)),
            })
        })
        .collect()
}

/// An exact lncert arc within a proven Hausdorff distance of a kurbo arc
/// ([`arc_enclosure`]).
#[derive(Clone, Debug, PartialEq)]
pub struct ArcWithin {
    /// The exact arc ([`ShapeDesc::Arc`]: float centre and radius, float
    /// directions, counter-clockwise).
    pub arc: ShapeDesc,
    /// Proven: `d_H(kurbo's exact arc, arc) ≤ eps`.
    pub eps: f64,
}

/// Largest accepted `|start_angle|` and `|x_rotation|` (radians): the sum of the
/// angles stays where [`sin_cos_enclosure`] is tight.
pub const MAX_ARC_ANGLE: f64 = 1e5;

/// A kurbo circular arc (`radii.x == radii.y`) as an exact lncert arc with a
/// proven bound `eps` on the Hausdorff distance between them.
///
/// **What kurbo's arc is.** The points `center + R(x_rotation) (r cos θ, r sin θ)`
/// for `θ` between `start_angle` and `start_angle + sweep_angle`, with the
/// inputs' float values as real numbers: for a circle, the points
/// `center + |r| (cos φ, sin φ)` for `φ` between `α₀ = start_angle + x_rotation
/// (+ π if r < 0)` and `α₁ = α₀ + sweep_angle`, the sums taken in the reals (the
/// f64 sum of the angles is *not* the true sum; here they are enclosed by
/// outward-rounded intervals `A₀ ∋ α₀`, `A₁ ∋ α₁`).
///
/// **The lncert arc.** [`sin_cos_enclosure`] gives boxes `C × S` containing
/// `u(α) = (cos α, sin α)` for every `α ∈ A₀` (resp. `A₁`); the direction `d` is the
/// box's float midpoint (an exact rational). The arc runs counter-clockwise from
/// the direction of the smaller angle to the larger one (a negative sweep swaps
/// them), with kurbo's centre and `|r|`.
///
/// **The bound.** Let `v = d/|d|` (enclosed in intervals). The chord
/// `χ = |v − u(α)| ≤ sup √((v_x − C)² + (v_y − S)²)`, and the angle `δ ∈ [0, π]`
/// between `v` and `u(α)` satisfies `χ = 2 sin(δ/2) ≥ 2δ/π`, so `δ ≤ (π/2) χ`.
/// Write `a ≤ b` for the true end angles (`b − a = |sweep_angle| = Θ`) and `β₀ ∈
/// [a − δ₀, a + δ₀]`, `β₁ ∈ [b − δ₁, b + δ₁]` for angles of the two lncert
/// directions. If `Θ − δ₀ − δ₁ > 0` and `Θ + δ₀ + δ₁ < 2π` (checked in intervals,
/// else an error), then `β₁ − β₀ ∈ (0, 2π)` *is* lncert's counter-clockwise sweep
/// from the first direction to the second, so lncert's arc is exactly
/// `{c + |r| u(ψ) : β₀ ≤ ψ ≤ β₁}`. Each `φ ∈ [a, b]` is within `max(δ₀, δ₁)` of
/// `clamp(φ, β₀, β₁)` and each `ψ ∈ [β₀, β₁]` of `clamp(ψ, a, b)`, and two points
/// of the circle at angles `Δ` apart are `2|r| sin(Δ/2) ≤ |r| Δ` apart; hence
/// `d_H ≤ eps = |r| · max(δ₀, δ₁)`, rounded up.
///
/// **Refused** (an [`Error`] naming the field, never a panic): a non-finite
/// number (`arc.center.x`, `arc.radii.y`, `arc.start_angle`, …), an elliptical arc
/// (`arc.radii`: `radii.x ≠ radii.y`), a zero radius, `|start_angle|` or
/// `|x_rotation|` above [`MAX_ARC_ANGLE`], a sweep of 0 or with
/// `|sweep_angle| ≥ 2π` (kurbo would then retrace the circle; lncert has no full
/// circle: use [`shapes_from_circle`]), or a sweep too close to 0 or 2π for the
/// check above (`arc.sweep_angle`).
///
/// # Examples
/// ```
/// use kurbo::Arc;
/// use lncert::kurbo_bridge::arc_enclosure;
/// let a = arc_enclosure(&Arc::new((0.0, 0.0), (2.0, 2.0), 0.3, 1.2, 0.0)).unwrap();
/// assert!(a.eps < 1e-14);
/// let e = arc_enclosure(&Arc::new((0.0, 0.0), (2.0, 1.0), 0.3, 1.2, 0.0)).unwrap_err();
/// assert_eq!(e.field, "arc.radii");
/// ```
pub fn arc_enclosure(a: &Arc) -> Result<ArcWithin, Error> {
    let center = point(a.center, "arc.center")?;
    exact(a.radii.x, "arc.radii.x")?;
    exact(a.radii.y, "arc.radii.y")?;
    if a.radii.x != a.radii.y {
        return Err(input_error(
            "arc.radii",
            format!(
                "an elliptical arc (radii {} ≠ {}): only circular arcs are converted",
                a.radii.x, a.radii.y
            ),
        ));
    }
    let r = a.radii.x;
    if r == 0.0 {
        return Err(input_error("arc.radii", "a radius of 0 is a point"));
    }
    for (x, field) in [
        (a.start_angle, "arc.start_angle"),
        (a.x_rotation, "arc.x_rotation"),
    ] {
        if !x.is_finite() {
            return Err(input_error(field, format!("{x} is not a finite number")));
        }
        if x.abs() > MAX_ARC_ANGLE {
            return Err(input_error(
                field,
                format!("|{x}| is above the supported {MAX_ARC_ANGLE:e} rad"),
            ));
        }
    }
    let sweep = a.sweep_angle;
    if !sweep.is_finite() {
        return Err(input_error(
            "arc.sweep_angle",
            format!("{sweep} is not a finite number"),
        ));
    }
    // every f64 ≤ TAU is < 2π (TAU rounds down), every larger one is > 2π
    if sweep == 0.0 || sweep.abs() > std::f64::consts::TAU {
        return Err(input_error(
            "arc.sweep_angle",
            format!(
                "|{sweep}| is not in (0, 2π): zero sweeps and full circles are not arcs (use shapes_from_circle for a circle)"
            ),
        ));
    }
    let pt = |x: f64| Interval::try_from((x, x)).expect("a finite float");
    let mut a0 = pt(a.start_angle) + pt(a.x_rotation);
    if r < 0.0 {
        // center + r u(φ) = center + |r| u(φ + π)
        a0 += Interval::PI;
    }
    let a1 = a0 + pt(sweep);
    let too_wide = |field: &str| {
        input_error(
            field,
            "the end point's direction cannot be enclosed tightly enough",
        )
    };
    // (direction as exact rationals, angle bound δ)
    let direction = |angle: Interval, field: &str| -> Result<(V2<Rational>, f64), Error> {
        let (s, c) = sin_cos_enclosure(angle);
        let (dx, dy) = (c.mid(), s.mid());
        if !(c.wid() < 1e-6 && s.wid() < 1e-6 && dx.is_finite() && dy.is_finite()) {
            return Err(too_wide(field));
        }
        let n = ScalarSqrt::sqrt(&(pt(dx).sqr() + pt(dy).sqr())).ok_or_else(|| too_wide(field))?;
        if n.inf() <= 0.0 {
            return Err(too_wide(field));
        }
        let (vx, vy) = (pt(dx) / n, pt(dy) / n);
        let chord =
            ScalarSqrt::sqrt(&((vx - c).sqr() + (vy - s).sqr())).ok_or_else(|| too_wide(field))?;
        let delta = (Interval::PI / pt(2.0) * chord).sup();
        if !(delta.is_finite() && delta < 1e-3) {
            return Err(too_wide(field));
        }
        Ok((V2::new(exact(dx, field)?, exact(dy, field)?), delta))
    };
    let (d0, delta0) = direction(a0, "arc.start_angle")?;
    let (d1, delta1) = direction(a1, "arc.sweep_angle")?;
    let theta = pt(sweep.abs());
    let deltas = pt(delta0) + pt(delta1);
    if !((theta - deltas).inf() > 0.0 && (theta + deltas).sup() < (pt(2.0) * Interval::PI).inf()) {
        return Err(input_error(
            "arc.sweep_angle",
            format!(
                "|{sweep}| is too close to 0 or 2π: the rounded end directions could sweep the other way round"
            ),
        ));
    }
    let eps = (pt(r.abs()) * pt(delta0.max(delta1))).sup();
    let (from, to) = if sweep > 0.0 { (d0, d1) } else { (d1, d0) };
    let arc = ShapeDesc::arc(ArcDesc {
        center,
        radius: exact(r.abs(), "arc.radii.x")?,
        from,
        to,
    })?;
    Ok(ArcWithin { arc, eps })
}

/// Decides `d_H(∪a, ∪b) ≤ tol` for unions of shapes, with certified bounds (the
/// default budget): the distance from a point of one union to the other is to
/// the nearest of its shapes, so a circle given as its four quarter arcs
/// ([`shapes_from_circle`]) is compared as a whole.
pub fn certify_union_within(a: &[ShapeDesc], b: &[ShapeDesc], tol: f64) -> Result<Verdict, Error> {
    check_tol(tol)?;
    let r = union_bounds(a, b, tol)?;
    Ok(if r.0 > tol {
        Verdict::Exceeds { lo: r.0 }
    } else if r.1 <= tol {
        Verdict::Within { hi: r.1 }
    } else {
        Verdict::Undecided { lo: r.0, hi: r.1 }
    })
}

/// Certified `(lo, hi)` on `d_H(∪a, ∪b)`, the search aimed at `goal`.
fn union_bounds(a: &[ShapeDesc], b: &[ShapeDesc], goal: f64) -> Result<(f64, f64), Error> {
    let pieces = |s: &[ShapeDesc], field: &str| -> Result<Vec<_>, Error> {
        if s.is_empty() {
            return Err(input_error(field, "no shapes"));
        }
        let mut all = Vec::new();
        for x in s {
            all.extend(x.pieces()?);
        }
        Ok(all)
    };
    let (pa, pb) = (pieces(a, "a")?, pieces(b, "b")?);
    let cfg = Config {
        tol: Tolerance::goal(goal),
        ..Config::default()
    };
    let scale = a.iter().chain(b).map(ShapeDesc::scale).fold(0.0, f64::max);
    let r = hausdorff_pieces(&pa, &pb, &cfg, &|| 1e-10 * (1.0 + scale));
    Ok((r.lo, r.hi))
}

/// Decides whether `path` is within `tol` of the circle `c` (for instance
/// `c.path_elements(tol)`'s claim): the path against the union of the four exact
/// quarter arcs of [`shapes_from_circle`].
pub fn circle_within(c: Circle, path: &BezPath, tol: f64) -> Result<Verdict, Error> {
    certify_union_within(&shapes_from_circle(c)?, &[shape_from_path(path)?], tol)
}

/// Decides `d_H(X, b) ≤ tol` for a shape `X` known only through a shape `a` with
/// `d_H(X, a) ≤ eps`: by the triangle inequality
/// `d_H(a, b) − eps ≤ d_H(X, b) ≤ d_H(a, b) + eps`, so `X` is within when the
/// certified upper bound on `d_H(a, b)` plus `eps` (rounded up) is `≤ tol`, and
/// exceeds only when the certified lower bound minus `eps` (rounded down) is
/// `> tol`. The reported bounds are those on `d_H(X, b)`.
pub fn certify_within_margin(
    a: &ShapeDesc,
    b: &ShapeDesc,
    tol: f64,
    eps: f64,
) -> Result<Verdict, Error> {
    check_tol(tol)?;
    if !(eps.is_finite() && eps >= 0.0) {
        return Err(input_error(
            "eps",
            format!("{eps} is not a finite number ≥ 0"),
        ));
    }
    let (a, b) = (std::slice::from_ref(a), std::slice::from_ref(b));
    let decide = |(lo, hi): (f64, f64)| {
        let (lo, hi) = (sub_down(lo, eps), add_up(hi, eps));
        if lo > tol {
            Verdict::Exceeds { lo }
        } else if hi <= tol {
            Verdict::Within { hi }
        } else {
            Verdict::Undecided { lo, hi }
        }
    };
    // the search stops at the first goal it decides: aim below the tolerance
    // first (to prove it within), then above (to prove it exceeded)
    let below = sub_down(tol, eps);
    let r = union_bounds(a, b, below)?;
    match decide(r) {
        Verdict::Undecided { .. } if r.0 > below => {
            Ok(decide(union_bounds(a, b, add_up(tol, eps))?))
        }
        v => Ok(v),
    }
}

/// Decides whether `path` is within `tol` of kurbo's exact arc `a` (for
/// instance `a.path_elements(tol)`'s claim): against the lncert arc of
/// [`arc_enclosure`], its `eps` charged by [`certify_within_margin`].
pub fn arc_within(a: &Arc, path: &BezPath, tol: f64) -> Result<Verdict, Error> {
    let enc = arc_enclosure(a)?;
    certify_within_margin(&enc.arc, &shape_from_path(path)?, tol, enc.eps)
}

#[cfg(test)]
mod tests {
    use super::*;
    use kurbo::{ParamCurve, Shape};
    use std::f64::consts::{FRAC_PI_2, PI, TAU};

    fn arc_desc(s: &ShapeDesc) -> &ArcDesc {
        match s {
            ShapeDesc::Arc(a) => a,
            other => panic!("not an arc: {other:?}"),
        }
    }

    fn r(x: f64) -> Rational {
        rational_from_f64(x).unwrap()
    }

    #[test]
    fn circle_is_four_exact_quarters() {
        for (c, rad) in [((0.1, -2.5), 0.3), ((1e10, 3.0), 1e-7), ((0.0, 0.0), -2.0)] {
            let quarters = shapes_from_circle(Circle::new(c, rad)).unwrap();
            assert_eq!(quarters.len(), 4);
            let dirs = [(1, 0), (0, 1), (-1, 0), (0, -1)];
            for (i, q) in quarters.iter().enumerate() {
                let a = arc_desc(q);
                assert_eq!(a.center, V2::new(r(c.0), r(c.1)));
                assert_eq!(a.radius, r(rad.abs()));
                let d = |k: usize| {
                    let (x, y) = dirs[k % 4];
                    V2::new(r(x as f64), r(y as f64))
                };
                assert_eq!((a.from.clone(), a.to.clone()), (d(i), d(i + 1)));
            }
        }
    }

    #[test]
    fn circle_bad_inputs_are_typed_errors() {
        let field = |c: Circle| shapes_from_circle(c).unwrap_err().field;
        assert_eq!(field(Circle::new((0.0, 0.0), 0.0)), "circle.radius");
        assert_eq!(field(Circle::new((0.0, 0.0), f64::NAN)), "circle.radius");
        assert_eq!(
            field(Circle::new((0.0, 0.0), f64::INFINITY)),
            "circle.radius"
        );
        assert_eq!(field(Circle::new((f64::NAN, 0.0), 1.0)), "circle.center.x");
        assert_eq!(
            field(Circle::new((0.0, f64::NEG_INFINITY), 1.0)),
            "circle.center.y"
        );
    }

    #[test]
    fn circle_against_kurbo_paths() {
        let c = Circle::new((0.5, -0.25), 1.0);
        // kurbo's four-cubic circle is within 2e-4 of the circle (≈ 1.96e-4 r)
        let path = c.to_path(1e-3);
        let v = circle_within(c, &path, 1e-3).unwrap();
        assert!(matches!(v, Verdict::Within { hi } if hi <= 1e-3), "{v:?}");
        // ... and provably not within 1e-4
        let v = circle_within(c, &path, 1e-4).unwrap();
        assert!(matches!(v, Verdict::Exceeds { lo } if lo > 1e-4), "{v:?}");
        // a quarter of the circle alone is far from the whole circle
        let quarter = shapes_from_circle(c).unwrap();
        let v = certify_union_within(&quarter[..1], &quarter, 0.5).unwrap();
        assert!(matches!(v, Verdict::Exceeds { .. }), "{v:?}");
        assert!(certify_union_within(&[], &quarter, 0.5).is_err());
        assert!(certify_union_within(&quarter, &quarter, f64::NAN).is_err());
    }

    /// kurbo's f64 end points (start, end) against the lncert arc's end points
    /// (the directions normalised in f64): within eps plus f64 rounding.
    fn check_ends(a: &Arc) {
        let enc = arc_enclosure(a).unwrap_or_else(|e| panic!("{a:?}: {e}"));
        let d = arc_desc(&enc.arc);
        let (cx, cy) = (a.center.x, a.center.y);
        let rad = a.radii.x.abs();
        let end = |v: &V2<Rational>| {
            let (x, y) = (
                crate::scalar::Scalar::approx(&v.x),
                crate::scalar::Scalar::approx(&v.y),
            );
            let n = x.hypot(y);
            Point::new(cx + rad * x / n, cy + rad * y / n)
        };
        let (p_from, p_to) = (end(&d.from), end(&d.to));
        let (k0, k1) = if a.sweep_angle > 0.0 {
            (a.start(), a.end())
        } else {
            (a.end(), a.start())
        };
        // f64 slack: a few ulps of the coordinates and of the angle sums
        let angles = a.start_angle.abs() + a.sweep_angle.abs() + a.x_rotation.abs() + PI;
        let slack = 1e-14 * (cx.abs() + cy.abs() + rad) + 4.0 * f64::EPSILON * angles * rad;
        assert!(enc.eps <= 1e-12 * rad.max(1.0), "{a:?}: eps {}", enc.eps);
        for (p, k) in [(p_from, k0), (p_to, k1)] {
            assert!(
                p.distance(k) <= enc.eps + slack,
                "{a:?}: {p:?} vs kurbo {k:?}, eps {}",
                enc.eps
            );
        }
    }

    #[test]
    fn arc_end_points_within_eps_of_kurbo() {
        let mut seed = 0x1234_5678_9abc_def0u64;
        let mut next = || {
            // xorshift: deterministic pseudo-random floats in [0, 1)
            seed ^= seed << 13;
            seed ^= seed >> 7;
            seed ^= seed << 17;
            (seed >> 11) as f64 / (1u64 << 53) as f64
        };
        for _ in 0..500 {
            let c = ((next() - 0.5) * 20.0, (next() - 0.5) * 20.0);
            let rad = (next() * 8.0 + 0.01) * if next() < 0.2 { -1.0 } else { 1.0 };
            let start = (next() - 0.5) * 40.0;
            let sweep = (next() * 6.2 + 0.01) * if next() < 0.5 { -1.0 } else { 1.0 };
            let rot = if next() < 0.5 {
                0.0
            } else {
                (next() - 0.5) * 10.0
            };
            check_ends(&Arc::new(c, (rad, rad), start, sweep, rot));
        }
        // exact quarter: eps of the order of an ulp
        let a = Arc::new((0.0, 0.0), (1.0, 1.0), 0.0, FRAC_PI_2, 0.0);
        check_ends(&a);
        let eps = arc_enclosure(&a).unwrap().eps;
        assert!(eps < 1e-14, "{eps}");
        // large angles are still enclosed (wider, still tiny)
        check_ends(&Arc::new((1.0, 2.0), (3.0, 3.0), 9e4, -2.0, -9e4));
    }

    /// Over the audit's arcs (angles within a few π), eps is a few ulps of r.
    #[test]
    fn arc_eps_is_a_few_ulps_of_the_radius() {
        let mut worst = 0.0f64;
        for i in 0..2000 {
            let x = i as f64 / 2000.0;
            let start = -PI + 2.0 * PI * x;
            let sweep = (0.1 + 5.9 * ((i * 7919) % 2000) as f64 / 2000.0)
                * if i % 2 == 0 { 1.0 } else { -1.0 };
            let rad = 0.25 * (1 + i % 16) as f64;
            let a = Arc::new((0.5, -1.0), (rad, rad), start, sweep, 0.0);
            worst = worst.max(arc_enclosure(&a).unwrap().eps / rad);
        }
        eprintln!("worst eps / r = {worst:e}");
        assert!(worst < 1e-14, "{worst:e}");
    }

    #[test]
    fn arc_against_kurbo_paths() {
        for sweep in [2.5, -2.5, 0.3, -6.0] {
            let a = Arc::new((0.25, -1.0), (1.5, 1.5), 0.7, sweep, 0.2);
            let path = a.to_path(1e-6);
            let v = arc_within(&a, &path, 1e-5).unwrap();
            assert!(
                matches!(v, Verdict::Within { hi } if hi <= 1e-5),
                "{sweep}: {v:?}"
            );
            // the same path is far from the arc of the opposite sweep
            let other = Arc::new(
                (0.25, -1.0),
                (1.5, 1.5),
                0.7,
                sweep - sweep.signum() * 0.1,
                0.2,
            );
            let v = arc_within(&other, &path, 1e-3).unwrap();
            assert!(
                matches!(v, Verdict::Exceeds { lo } if lo > 1e-3),
                "{sweep}: {v:?}"
            );
        }
        assert!(arc_within(
            &Arc::new((0.0, 0.0), (1.0, 1.0), 0.0, 1.0, 0.0),
            &BezPath::new(),
            0.1
        )
        .is_err());
    }

    #[test]
    fn arc_bad_inputs_are_typed_errors() {
        let ok = Arc::new((0.0, 0.0), (1.0, 1.0), 0.5, 1.0, 0.0);
        let field = |f: &dyn Fn(&mut Arc)| {
            let mut a = ok;
            f(&mut a);
            arc_enclosure(&a).map(|_| ()).unwrap_err().field
        };
        assert!(arc_enclosure(&ok).is_ok());
        assert_eq!(field(&|a| a.center.x = f64::NAN), "arc.center.x");
        assert_eq!(field(&|a| a.center.y = f64::INFINITY), "arc.center.y");
        assert_eq!(field(&|a| a.radii.x = f64::NAN), "arc.radii.x");
        assert_eq!(field(&|a| a.radii.y = f64::NAN), "arc.radii.y");
        assert_eq!(field(&|a| a.radii.y = 2.0), "arc.radii");
        assert_eq!(
            field(&|a| a.radii = kurbo::Vec2::new(0.0, 0.0)),
            "arc.radii"
        );
        assert_eq!(field(&|a| a.start_angle = f64::NAN), "arc.start_angle");
        assert_eq!(field(&|a| a.start_angle = 1e6), "arc.start_angle");
        assert_eq!(
            field(&|a| a.x_rotation = f64::NEG_INFINITY),
            "arc.x_rotation"
        );
        assert_eq!(field(&|a| a.x_rotation = -2e5), "arc.x_rotation");
        for sweep in [
            f64::NAN,
            f64::INFINITY,
            0.0,
            -0.0,
            1e-300,
            -1e-17,
            TAU.next_up(),
            -TAU.next_up(),
            7.0,
            -100.0,
        ] {
            assert_eq!(
                field(&|a| a.sweep_angle = sweep),
                "arc.sweep_angle",
                "{sweep}"
            );
        }
        // at the edges: an error or an arc, never a panic
        for sweep in [TAU, -TAU, TAU.next_down(), 1e-12, -1e-12] {
            let mut a = ok;
            a.sweep_angle = sweep;
            if let Err(e) = arc_enclosure(&a) {
                assert_eq!(e.field, "arc.sweep_angle", "{sweep}");
            }
        }
        let path = ok.to_path(0.1);
        assert_eq!(arc_within(&ok, &path, f64::NAN).unwrap_err().field, "tol");
        assert_eq!(
            certify_within_margin(
                &shape_from_path(&path).unwrap(),
                &shape_from_path(&path).unwrap(),
                0.1,
                -1.0
            )
            .unwrap_err()
            .field,
            "eps"
        );
    }
}
