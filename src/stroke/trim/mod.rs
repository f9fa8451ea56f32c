//! Proven stroke outlines for a circular pen: the boundary of the swept region
//! `S = x ⊕ disk(r)` as closed contours of exact Bézier pieces and exact arcs —
//! and for an elliptical pen `E` ([`StrokeOptions::with_pen`],
//! [`PenShape::Ellipse`]): `S = x ⊕ E`, the sides the convolution curves
//! `x ∗ e_∓` ([`crate::offset::convolve`], certified within `tol/8`), round caps
//! half ellipses of proven cubics ([`super::ellipse::half_ellipse_cap`]), and
//! the kept/removed tests below with the pen's exact quadratic form
//! ([`super::ellipse::Form`]; see `proofs/trimming.md`, "Elliptical pens").
//!
//! # Construction
//!
//! 1. The offsets at `−r` and `+r` ([`crate::offset::offset`], each segment
//!    certified within `tol/8` of the exact offset of its span) are chained
//!    into raw contours: the `−r` side forward, the `+r` side reversed, joined by
//!    round caps (exact arcs of radius `r` about the end points) for an open
//!    curve, or kept as two contours for a closed one. At G⁰ corners a join
//!    arc is added on the convex side and a straight *connector* chord on the
//!    concave side (its points lie inside the disk of the corner, so inside `S`).
//!    With this order the outside of `S` is locally on the **right** of every
//!    raw piece.
//! 2. Exact closure: arc end points are rational points **exactly on** the
//!    circle ([`super::circle::snap`], the rational parametrisation of the
//!    circle); the neighbouring offset segment's end control point is replaced
//!    by that point. Replacing an end control point by a point `δ` away moves
//!    every point of the Bézier by at most `δ` (the end basis function is ≤ 1),
//!    so `δ` (enclosed exactly) is added to the piece's certified bound.
//! 3. The raw pieces are split at their certified crossings
//!    ([`super::intersect::intersections`] for Bézier pairs,
//!    [`super::circle::bezier_arc`] for a Bézier and an arc). **Split
//!    convention**: a Bézier–Bézier crossing with enclosures `s`, `t` and point
//!    box `P` is split at the dyadic midpoints `s*`, `t*` of the enclosures, and
//!    the crossing is represented by one exact point `X` (the dyadic midpoint of
//!    `P`) that replaces the end control points of the halves on both pieces; a
//!    Bézier–arc crossing is split at the midpoint `s*` of an isolating interval
//!    refined to `2⁻⁴⁰`, and `X` is a rational point exactly on the circle near
//!    `B(s*)` (so the arc splits exactly at `X`). Each half moves by at most
//!    `|B(s*) − X|` (enclosed), added to its bound. An arc–arc crossing
//!    (irrational in general) splits each arc at its own rational point on
//!    its circle, `TOL/1024` beside the crossing outside the other arc's
//!    disk; kept halves ending there are joined by a short straight *bridge*
//!    whose length is added to claim (a).
//! 4. Every sub-piece is classified (see `proofs/trimming.md`):
//!    **kept** when every point `q` of it has, within the claimed bound, a point
//!    `w` proven outside `S` (`dist(w, x) > r`, exact Bernstein signs of
//!    `|w − x(t)|² − r²` on every input piece) — together with a point of `S`
//!    within the piece's certified bound, the segment between them crosses `∂S`;
//!    **removed** when every point `q` of it has `dist(q, x) < r − e` (`e` the
//!    piece's two-sided bound; an exact witness point of `x` for each part of a
//!    subdivision) or lies within `λ = tol/2` of an end point of a kept sub-piece;
//!    otherwise **undecided**, never guessed.
//! 5. Kept pieces are chained into contours by their exact shared end points;
//!    the orientation is the sign of the enclosed area `½∮(x dy − y dx)`
//!    (exact for Bézier pieces, an enclosure for arcs); outer contours come out
//!    counter-clockwise, holes clockwise.
//! 6. Claim (c) is checked on the output: [`super::intersect::intersections`]
//!    on its Bézier pieces, [`super::circle::bezier_arc`] and
//!    [`super::circle::arcs_meet`] for the arcs; contours must be closed, with no
//!    crossing and no contact besides the joints of consecutive pieces.
//!
//! # Logging
//!
//! The phases and their timings are logged through the `log` crate (`debug`;
//! each raw piece, sub-piece and failed test at `trace`): install any `log`
//! logger to see them; the `lncert` binary prints them to stderr with
//! `RUST_LOG=debug` (or `trace`).

mod chain;
mod classify;
mod driver;
mod pinch;
mod sides;
mod split;
#[cfg(test)]
mod tests;
mod types;

pub(crate) use chain::{chain, check_simple};
pub(crate) use classify::{outside, positive_bernstein, positive_bernstein_iv};
pub use driver::stroke;
pub use types::{
    Cap, CapReport, Claim, Classified, Contour, Orientation, PenShape, Piece, RawCrossing, Stroke,
    StrokeError, StrokeOptions,
};

/// Adds a note to a stroke's notes: at most 20 of them, no repeats.
pub(crate) fn add_note(notes: &mut Vec<String>, s: String) {
    if notes.len() < 20 && !notes.contains(&s) {
        notes.push(s);
    }
}
