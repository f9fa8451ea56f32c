//! The kurbo bridge (feature `kurbo`): kurbo's curves as lncert shapes,
//! converted **exactly** (every `f64` is a dyadic rational; nothing is
//! rounded), and certified verdicts on tolerance claims about them.
//!
//! | kurbo | lncert |
//! |---|---|
//! | [`kurbo::BezPath`] (`MoveTo`, `LineTo`, `QuadTo`, `CurveTo`, `ClosePath`) | [`shape_from_path`]: one Bézier piece per segment |
//! | [`kurbo::CubicBez`], [`kurbo::QuadBez`], [`kurbo::Line`] | [`shape_from_cubic`], [`shape_from_quad`], [`shape_from_line`] |
//!
//! kurbo's `Arc` and `Circle` are given by angles in radians, whose end points
//! are not exact numbers (`cos` and `sin` are rounded), so they are not
//! converted; flatten or fit them with kurbo and certify the result against
//! an lncert arc instead (`ShapeDesc::arc`, exact directions).
//!
//! [`certify_within`] decides `d_H(a, b) ≤ tol` for any two shapes;
//! [`offset_within`] decides it for the exact offset of a cubic against a
//! path (such as the output of `kurbo::offset::offset_cubic`). A claim is
//! reported exceeded only when a certified lower bound proves it.
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

use crate::certify::{hausdorff, Config};
use crate::curve::{Bezier, V2};
use crate::scalar::{rational_from_f64, Rational};
use crate::shape::ShapeDesc;
use crate::Error;
use kurbo::{BezPath, CubicBez, Line, PathEl, Point, QuadBez};

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
    Ok(ShapeDesc::curve(pieces)?)
}

/// A cubic, exactly.
pub fn shape_from_cubic(c: CubicBez) -> Result<ShapeDesc, Error> {
    Ok(ShapeDesc::curve(vec![bezier(
        &[c.p0, c.p1, c.p2, c.p3],
        "cubic",
    )?])?)
}

/// A quadratic, exactly.
pub fn shape_from_quad(q: QuadBez) -> Result<ShapeDesc, Error> {
    Ok(ShapeDesc::curve(vec![bezier(
        &[q.p0, q.p1, q.p2],
        "quad",
    )?])?)
}

/// A line segment, exactly.
pub fn shape_from_line(l: Line) -> Result<ShapeDesc, Error> {
    Ok(ShapeDesc::curve(vec![bezier(&[l.p0, l.p1], "line")?])?)
}

/// The exact offset `c + d N` of a cubic (`N` the unit normal to the left of
/// the direction of travel in a y-up frame — the side of kurbo's
/// `offset_cubic` for `d > 0`). The cubic must be regular (`c′ ≠ 0`).
pub fn exact_offset(c: CubicBez, d: f64) -> Result<ShapeDesc, Error> {
    Ok(ShapeDesc::offset(
        vec![bezier(&[c.p0, c.p1, c.p2, c.p3], "cubic")?],
        exact(d, "distance")?,
    )?)
}

/// Decides `d_H(a, b) ≤ tol` with certified bounds (the default budget).
pub fn certify_within(a: &ShapeDesc, b: &ShapeDesc, tol: f64) -> Result<Verdict, Error> {
    let r = hausdorff(
        a,
        b,
        &Config {
            tol: Some(tol),
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
