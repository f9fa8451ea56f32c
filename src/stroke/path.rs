//! Exact paths as stroke input: Bézier pieces and circular arcs in one chain
//! (SVG `A` commands, `<circle>`, `<rect rx>`), stroked without replacing
//! the arcs by their approximations in what is claimed.
//!
//! [`stroke_path`] builds the outline from certified cubic approximations
//! of the arcs (at half the tolerance) and then proves claims (a) and (b)
//! **against the exact path** by a stroke certificate
//! ([`super::certificate_path`]) that [`crate::certify::verify::verify`]
//! checks on its own: its families of `∂S` are the exact arcs' offsets
//! (concentric arcs) and the cones at the exact joints, its points outside
//! `S` are tested against the exact arcs. Claim (c) is about the outline
//! alone. Where the certificate cannot be built or is refused, claims (a)
//! and (b) are reported undecided, never taken from the approximation.

use super::circle::Arc;
use super::{Claim, Stroke, StrokeOptions};
use crate::certify::verify::stroke::{exact_points, CurvePiece};
use crate::curve::{Bezier, V2};
use crate::scalar::Rational;
use crate::shape::svgarc::{ApproxElement, ApproxKind, ExactElement, ExactPiece};
use crate::shape::InputApprox;
use crate::{Error, Tolerance};
use num_traits::{Signed, Zero};

/// One piece of an exact path: a Bézier or a circular arc (end points
/// exactly on its circle, any sweep below a full turn; `from = to` is a
/// whole circle).
#[derive(Clone, Debug, PartialEq)]
#[allow(clippy::large_enum_variant)]
pub enum PathPiece {
    /// A Bézier with exact control points.
    Bezier(Bezier<Rational>),
    /// An exact circular arc.
    Arc(Arc),
}

impl PathPiece {
    /// An arc as read by [`crate::shape::parse_arc_input`], when its end
    /// points are rational (its direction vectors have rational lengths);
    /// `None` otherwise.
    ///
    /// # Examples
    /// ```
    /// use lncert::shape::parse_arc_input;
    /// use lncert::stroke::PathPiece;
    /// let arcs = parse_arc_input(r#"{"arc": {"center": [0, 0], "radius": 2, "from": [3, 4], "to": [0, 1]}}"#)
    ///     .unwrap()
    ///     .unwrap();
    /// let p = PathPiece::from_travelled(&arcs[0]).unwrap();
    /// assert_eq!(p.start().x, lncert::parse_rational("6/5").unwrap());
    /// ```
    pub fn from_travelled(t: &crate::shape::TravelledArc) -> Option<PathPiece> {
        let a = &t.arc;
        let (p, q) = (
            on_circle(&a.center, &a.radius, &a.from)?,
            on_circle(&a.center, &a.radius, &a.to)?,
        );
        let (from, to) = if t.clockwise { (q, p) } else { (p, q) };
        Some(PathPiece::Arc(Arc {
            center: a.center.clone(),
            radius: a.radius.clone(),
            from,
            to,
            clockwise: t.clockwise,
        }))
    }

    /// The start point.
    pub fn start(&self) -> &V2<Rational> {
        match self {
            PathPiece::Bezier(b) => &b.points()[0],
            PathPiece::Arc(a) => &a.from,
        }
    }
    /// The end point.
    pub fn end(&self) -> &V2<Rational> {
        match self {
            PathPiece::Bezier(b) => b.points().last().expect("nonempty"),
            PathPiece::Arc(a) => &a.to,
        }
    }
}

/// The point of the circle `(c, r)` in the direction `d`, when `|d|` is
/// rational (then the point is).
pub(super) fn on_circle(c: &V2<Rational>, r: &Rational, d: &V2<Rational>) -> Option<V2<Rational>> {
    let n = crate::shape::svgarc::rational_sqrt(&d.dot(d))?;
    (!n.is_zero()).then(|| V2::new(&c.x + &d.x * r / &n, &c.y + &d.y * r / &n))
}

fn bad(field: &str, reason: impl Into<String>) -> Error {
    Error {
        field: field.into(),
        reason: reason.into(),
    }
}

/// The path's pieces as a stroke certificate states them: Béziers as they
/// are, each arc split at rational points of its circle a quarter turn
/// apart (from its start) so that every piece turns by more than 0 and at
/// most `π/2`. Errors name the piece (`path[k]`): an arc off its circle or
/// with a radius `≤ 0`.
pub(crate) fn curve_pieces(path: &[PathPiece]) -> Result<Vec<CurvePiece>, Error> {
    let mut out = Vec::new();
    for (k, p) in path.iter().enumerate() {
        match p {
            PathPiece::Bezier(b) => out.push(CurvePiece::Bezier(exact_points(b))),
            PathPiece::Arc(a) => {
                for (u, v) in quarters(a).map_err(|e| bad(&format!("path[{k}]"), e))? {
                    let c = [a.center.x.clone(), a.center.y.clone()];
                    let pt = |d: &V2<Rational>| [&a.center.x + &d.x, &a.center.y + &d.y];
                    out.push(
                        CurvePiece::checked_arc(c, a.radius.clone(), pt(&u), pt(&v), a.clockwise)
                            .map_err(|e| bad(&format!("path[{k}]"), e))?,
                    );
                }
            }
        }
    }
    Ok(out)
}

/// One step of an arc: its start and end radius vectors.
type Step = (V2<Rational>, V2<Rational>);

/// An arc's radius vectors split into steps of more than 0 and at most a
/// quarter turn in its direction: quarter turns `±J` from the start (exact,
/// on the circle), then the rest.
pub(super) fn quarters(a: &Arc) -> Result<Vec<Step>, String> {
    if !a.radius.is_positive() {
        return Err("the arc's radius must be > 0".into());
    }
    let (u, v) = (a.from.sub(&a.center), a.to.sub(&a.center));
    let r2 = &a.radius * &a.radius;
    if u.dot(&u) != r2 || v.dot(&v) != r2 {
        return Err("an end point of the arc is not exactly on its circle".into());
    }
    // a quarter turn in the arc's direction
    let turn = |w: &V2<Rational>| {
        if a.clockwise {
            V2::new(w.y.clone(), -w.x.clone())
        } else {
            V2::new(-w.y.clone(), w.x.clone())
        }
    };
    let sign = |x: Rational| if a.clockwise { -x } else { x };
    let mut out = Vec::new();
    let mut cur = u;
    for _ in 0..5 {
        let (cr, d) = (sign(cur.cross(&v)), cur.dot(&v));
        if cr.is_positive() && !d.is_negative() {
            out.push((cur, v));
            return Ok(out);
        }
        if cr.is_zero() && d.is_positive() && !out.is_empty() {
            return Ok(out);
        }
        let next = turn(&cur);
        out.push((cur, next.clone()));
        cur = next;
    }
    Err("internal error: an arc of more than a full turn (please report)".into())
}

/// Whether `p` has `at` as one of its end points (where a piece of a path
/// can begin, travelled one way or the other).
fn starts_at(p: &ExactPiece, at: &V2<Rational>) -> bool {
    match p {
        ExactPiece::Bezier(b) => b.points()[0] == *at || b.points().last() == Some(at),
        ExactPiece::Arc(a) => [&a.from, &a.to]
            .into_iter()
            .any(|u| on_circle(&a.center, &a.radius, u).as_ref() == Some(at)),
        ExactPiece::EllipseArc(_) => false,
    }
}

/// The path read from `pieces` and the report of a curve reader
/// ([`crate::shape::parse_curve_reported`]): every approximated element that
/// is exactly a chain of lines and circular arcs (SVG arcs with a rational
/// centre, `<circle>`, rounded `<rect>` with equal radii) is put in place
/// of its cubic pieces, each arc travelled the way the pieces it replaces
/// are. A circular arc with an irrational centre is replaced by its near arc
/// ([`crate::shape::NearElement`]: rational centre and radius, certified
/// within a small bound) and stays reported as
/// [`ApproxKind::NearArc`] within that bound. Returns the path and
/// the elements still approximated (ellipses, near arcs, rotations), or
/// `None` when no element was exact.
///
/// # Examples
/// ```
/// use lncert::shape::parse_curve_reported;
/// use lncert::stroke::{exact_path, PathPiece};
/// let doc = r#"<svg><rect width="10" height="6" rx="2"/></svg>"#;
/// let (pieces, approx) = parse_curve_reported(doc).unwrap();
/// let (path, rest) = exact_path(&pieces, &approx).unwrap();
/// assert_eq!(path.iter().filter(|p| matches!(p, PathPiece::Arc(_))).count(), 4);
/// assert!(rest.is_empty());
/// ```
pub fn exact_path(
    pieces: &[Bezier<Rational>],
    approx: &InputApprox,
) -> Option<(Vec<PathPiece>, InputApprox)> {
    let mut rest = InputApprox::default();
    let mut exact = Vec::new();
    let usable = |x: &ExactElement| {
        x.count > 0
            && x.first + x.count <= pieces.len()
            && x.pieces
                .iter()
                .all(|p| !matches!(p, ExactPiece::EllipseArc(_)))
    };
    for e in &approx.elements {
        match (&e.exact, &e.near) {
            (Some(x), _) if usable(x) => exact.push(x),
            // a rational arc near the element: the element stays reported,
            // within the near arc's bound
            (None, Some(n)) if usable(&n.element) => {
                exact.push(&n.element);
                rest.push(ApproxElement {
                    kind: ApproxKind::NearArc,
                    pieces: n.element.pieces.len(),
                    bound: n.bound,
                    near: None,
                    ..e.clone()
                });
            }
            _ => rest.push(e.clone()),
        }
    }
    if exact.is_empty() {
        return None;
    }
    exact.sort_by_key(|x| x.first);
    if exact
        .windows(2)
        .any(|w| w[0].first + w[0].count > w[1].first)
    {
        return None;
    }
    let mut out: Vec<PathPiece> = Vec::new();
    let mut i = 0;
    for x in exact {
        out.extend(pieces[i..x.first].iter().cloned().map(PathPiece::Bezier));
        // the element starts where its first replaced piece starts, or (a
        // near arc after another) where the element before it ended
        let mut at = pieces[x.first].points()[0].clone();
        if let (true, Some(last), Some(p)) = (x.first == i && i > 0, out.last(), x.pieces.first()) {
            if !starts_at(p, &at) && starts_at(p, last.end()) {
                at = last.end().clone();
            }
        }
        for p in &x.pieces {
            let next = match p {
                ExactPiece::Bezier(b) => {
                    let b = if b.points()[0] == at {
                        b.clone()
                    } else if b.points().last() == Some(&at) {
                        Bezier::new(b.points().iter().rev().cloned().collect())
                    } else {
                        return None;
                    };
                    PathPiece::Bezier(b)
                }
                ExactPiece::Arc(a) => {
                    let (p, q) = (
                        on_circle(&a.center, &a.radius, &a.from)?,
                        on_circle(&a.center, &a.radius, &a.to)?,
                    );
                    let arc = |from: V2<Rational>, to: V2<Rational>, clockwise| Arc {
                        center: a.center.clone(),
                        radius: a.radius.clone(),
                        from,
                        to,
                        clockwise,
                    };
                    if p == at {
                        PathPiece::Arc(arc(p, q, false))
                    } else if q == at {
                        PathPiece::Arc(arc(q, p, true))
                    } else {
                        return None;
                    }
                }
                ExactPiece::EllipseArc(_) => return None,
            };
            at = next.end().clone();
            out.push(next);
        }
        i = x.first + x.count;
    }
    out.extend(pieces[i..].iter().cloned().map(PathPiece::Bezier));
    Some((out, rest))
}

/// Reads a curve as [`crate::shape::parse_curve_reported`] does (JSON, SVG
/// path data or an SVG document) with its circular arcs exact
/// ([`exact_path`]); the elements that stay approximated are returned in the
/// report.
///
/// # Examples
/// ```
/// use lncert::stroke::{parse_path, PathPiece};
/// let (path, rest) = parse_path("M 2 0 A 2 2 0 0 1 -2 0 L 2 0").unwrap();
/// assert!(matches!(path[0], PathPiece::Arc(_)) && rest.is_empty());
/// ```
pub fn parse_path(text: &str) -> Result<(Vec<PathPiece>, InputApprox), Error> {
    let (pieces, approx) = crate::shape::parse_curve_reported(text)?;
    Ok(match exact_path(&pieces, &approx) {
        Some(x) => x,
        None => (pieces.into_iter().map(PathPiece::Bezier).collect(), approx),
    })
}

/// The stroke of an exact path with a circular pen.
///
/// A path of segments and arcs only, with round caps, is first stroked
/// **exactly** (its boundary from the offset lines, concentric arcs and the
/// pen's circles about the end points, each stretch decided by exact
/// predicates; `proofs/trimming.md`, "Lines and arcs exactly"), with claims
/// (a) and (b) proven by its stroke certificate (kept in
/// [`Stroke::certificate`]). Where that is not proven, or for other paths:
/// without arcs, [`super::stroke`]; with arcs, the outline is built from
/// the arcs' certified cubic approximations at half the tolerance, then
/// claims (a) and (b) are proven against the exact path by its stroke
/// certificate, checked by the independent verifier (kept in
/// [`Stroke::certificate`]); claim (c) concerns the outline alone. Where
/// that certificate is not built or not accepted, (a) and (b) are
/// undecided, with the reason.
///
/// Errors: an elliptical pen with arcs (field `pen`), an arc off its circle
/// (field `path[k]`), and the errors of [`super::stroke`].
///
/// # Examples
/// ```
/// use lncert::stroke::{parse_path, stroke_path, StrokeOptions};
/// # fn main() -> Result<(), lncert::Error> {
/// let (path, _) = parse_path(r#"<svg><circle cx="0" cy="0" r="3"/></svg>"#)?;
/// let opts = StrokeOptions::new(lncert::parse_rational("1/2")?, "1e-3".parse()?);
/// let s = stroke_path(&path, &opts)?;
/// assert!(s.proven() && s.certificate.is_some());
/// assert_eq!(s.contours.len(), 2); // the outer and the inner circle
/// # Ok(())
/// # }
/// ```
pub fn stroke_path(path: &[PathPiece], opts: &StrokeOptions) -> Result<Stroke, Error> {
    // lines and arcs: constructed exactly, proven by their certificate
    let exact = super::lines_arcs::stroke(path, opts);
    if let Some(s) = &exact {
        if s.proven() {
            return Ok(s.clone());
        }
    }
    let mut s = stroke_approximated(path, opts)?;
    if let Some(e) = exact {
        let why = [&e.a, &e.b, &e.c]
            .iter()
            .find(|c| !c.proven)
            .map_or(String::new(), |c| c.note.clone());
        // first: the general construction's notes may fill the list
        s.notes.insert(
            0,
            format!("the exact construction of lines and arcs was not proven: {why}"),
        );
    }
    Ok(s)
}

/// [`stroke_path`] through the general construction: Bézier pieces as they
/// are, arcs by their certified cubic approximations.
fn stroke_approximated(path: &[PathPiece], opts: &StrokeOptions) -> Result<Stroke, Error> {
    let beziers: Option<Vec<Bezier<Rational>>> = path
        .iter()
        .map(|p| match p {
            PathPiece::Bezier(b) => Some(b.clone()),
            PathPiece::Arc(_) => None,
        })
        .collect();
    if let Some(b) = beziers {
        return super::stroke(&b, opts);
    }
    if opts.ellipse.is_some() {
        return Err(bad(
            "pen",
            "a path with exact arcs is stroked with a circular pen only (give the arcs as cubics for an elliptical pen)",
        ));
    }
    // the approximation: each arc piece of at most a quarter turn by cubics
    let mut approx: Vec<Bezier<Rational>> = Vec::new();
    let mut delta = 0.0f64;
    for (k, p) in path.iter().enumerate() {
        match p {
            PathPiece::Bezier(b) => approx.push(b.clone()),
            PathPiece::Arc(a) => {
                for (u, v) in quarters(a).map_err(|e| bad(&format!("path[{k}]"), e))? {
                    let p0 = a.center.add(&u);
                    let p1 = a.center.add(&v);
                    let (c, d) = crate::shape::svgarc::circular_arc_cubics(
                        &p0,
                        &a.radius,
                        false,
                        !a.clockwise,
                        &p1,
                    )
                    .map_err(|e| bad(&format!("path[{k}]"), e))?;
                    delta = delta.max(d);
                    approx.extend(c);
                }
            }
        }
    }
    let half = Tolerance::new(opts.tol.exact() / Rational::from_integer(2.into()))?;
    let mut inner = opts.clone();
    inner.tol = half;
    let mut s = super::stroke(&approx, &inner)?;
    s.tol = opts.tol.clone();
    let what = format!(
        "the outline was built from the arcs' cubic approximations (within {}) at tol/2; claims (a) and (b) are about the exact arcs",
        crate::shape::format_up(delta)
    );
    super::trim::add_note(&mut s.notes, what);
    // butt caps on an open path: (a) and (b) are not claimed (the region is
    // not x ⊕ pen), as the engine says
    if opts.cap == super::Cap::Butt && !(s.a.proven && s.b.proven) {
        return Ok(s);
    }
    if !(s.a.proven && s.b.proven && s.c.proven) {
        let why =
            "not proven against the exact arcs: the outline of their approximation is not proven"
                .to_string();
        s.a = undecided(why.clone());
        s.b = undecided(why);
        return Ok(s);
    }
    // the certificate at a tolerance near the outline's own bounds first
    // (twice the larger; the arcs' cubics are within `delta`), so that the
    // proven bound is about the outline's and not the tolerance asked for;
    // at the tolerance asked for where that is refused
    let certify = |s: &mut Stroke, t: Tolerance| {
        s.tol = t;
        let r = verified(super::certificate_path(path, s, &opts.radius));
        s.tol = opts.tol.clone();
        r
    };
    let tight = (2.0 * s.a.bound.max(s.b.bound) + 4.0 * delta).next_up();
    let checked = match short_above(tight) {
        Some(t) if t.value() < 0.5 * opts.tol.value() => {
            certify(&mut s, t).or_else(|_| certify(&mut s, opts.tol.clone()))
        }
        _ => certify(&mut s, opts.tol.clone()),
    };
    prove_ab(
        &mut s,
        checked,
        "against the exact arcs, by the stroke certificate (checked by the independent verifier)",
        "not proven against the exact arcs",
    );
    Ok(s)
}

/// A tolerance `≥ x` with two significant decimal digits (a short number
/// for the certificate to state), `None` when `x` is not a normal positive
/// float.
fn short_above(x: f64) -> Option<Tolerance> {
    if !(x.is_normal() && x > 0.0) {
        return None;
    }
    let mut y = x;
    for _ in 0..4 {
        let t: Tolerance = format!("{y:.1e}").parse().ok()?;
        if t.value() >= x {
            return Some(t);
        }
        y *= 1.05;
    }
    None
}

/// A stroke certificate checked by the independent verifier: the
/// certificate and the bound the verifier proved, or why it was not
/// written or was refused (field `certificate`).
pub(super) fn verified(
    cert: Result<serde_json::Value, Error>,
) -> Result<(serde_json::Value, f64), Error> {
    let cert = cert?;
    let v = crate::certify::verify::verify(&cert.to_string())
        .map_err(|e| bad("certificate", format!("refused at {}: {}", e.at, e.reason)))?;
    Ok((cert, v.max_bound))
}

/// Claims (a) and (b) of `s` from a [`verified`] certificate, proven with
/// its bound (`by`: how, in the notes) and the certificate kept; else
/// undecided, the reason after `refused`.
pub(super) fn prove_ab(
    s: &mut Stroke,
    checked: Result<(serde_json::Value, f64), Error>,
    by: &str,
    refused: &str,
) {
    match checked {
        Ok((cert, bound)) => {
            s.a = Claim {
                proven: true,
                bound,
                note: format!("every outline point is within {bound:.3e} of ∂S, {by}"),
            };
            s.b = Claim {
                proven: true,
                bound,
                note: format!("every point of ∂S is within {bound:.3e} of the outline, {by}"),
            };
            s.certificate = Some(Box::new(cert));
        }
        Err(e) => {
            let why = format!("{refused}: {}", e.reason);
            s.a = undecided(why.clone());
            s.b = undecided(why);
        }
    }
}

pub(super) fn undecided(note: String) -> Claim {
    Claim {
        proven: false,
        bound: f64::INFINITY,
        note,
    }
}
