//! The raw sides before trimming: the offsets of each side chained with
//! join arcs and connectors, the round (or elliptical, or butt) caps, and the
//! input checks (steps 1 and 2 of the module docs).

use super::types::{bad, Cap, CapReport, Piece, StrokeError, StrokeOptions};
use crate::curve::{Bezier, V2};
use crate::offset::conv::Pen;
use crate::offset::prep::Junction;
use crate::offset::{convolve, exact_bezier, offset, OffsetOptions, OffsetResult};
use crate::scalar::{interval_from_rational, rational_from_f64, Interval, Rational, Scalar};
use crate::stroke::circle::{snap, Arc};
use crate::stroke::ellipse::{half_ellipse_cap, pen_point_enclosure};
use crate::Tolerance;
use num_traits::{Signed, Zero};

/// What a raw piece is.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub(super) enum Kind {
    /// Approximates an exact part of a candidate boundary (offset span, cap, join).
    Boundary,
    /// A concave-corner chord: no exact counterpart, inside `S`.
    Connector,
    /// A butt cap: always part of the outline (no distance claims).
    Butt,
}

#[derive(Clone, Debug)]
pub(super) struct Raw {
    pub(super) piece: Piece,
    /// Hausdorff bound to its exact counterpart (Boundary) — also a bound of
    /// the distance of each of its points to `S`.
    pub(super) e: f64,
    /// For connectors: every point is within `e_in` of `S`.
    pub(super) e_in: f64,
    pub(super) kind: Kind,
    /// For offset segments proven by the parametric path: the map from the
    /// segment's parameter onto its span's exact offset (see [`Link`]).
    pub(super) link: Option<Link>,
}

/// How a raw offset segment's points correspond to exact offset points:
/// every `B(s)` is within the raw piece's `e_in` of `E(t)` for some `t` in
/// `span.0 + hull(c)·(span.1 − span.0)` over the map boxes whose range meets
/// `s` (the parametric proof of [`crate::certify::param`]; `B` with its end
/// moves, fact 4, which `e_in` includes).
#[derive(Clone, Debug)]
pub(super) struct Link {
    /// The input piece (index into the whole curve).
    pub(super) piece: usize,
    /// Its span (dyadic floats).
    span: (f64, f64),
    /// The signed offset distance.
    pub(super) d: Rational,
    /// The map's cover of the segment's parameter.
    boxes: std::sync::Arc<Vec<crate::certify::ParamBox>>,
    /// The raw piece runs against the segment's parameter (the `+r` side).
    reversed: bool,
    /// The segment's certified error when the link was made: `raw.e − seg_e`
    /// bounds how far the raw piece's points have moved since (end snaps).
    pub(super) seg_e: f64,
}

impl Link {
    /// The largest certified `|B(t) − A(φ(t))|` over the map's boxes that meet
    /// the raw parameters `[s0, s1]` (`None` if none does).
    pub(super) fn local_bound(&self, s0: f64, s1: f64) -> Option<f64> {
        let (lo, hi) = if self.reversed {
            (1.0 - s1, 1.0 - s0)
        } else {
            (s0, s1)
        };
        self.boxes
            .iter()
            .filter(|b| b.t.1 >= lo && b.t.0 <= hi)
            .map(|b| b.bound)
            .reduce(f64::max)
    }
    /// The exact parameters (on the input piece) whose offset points lie
    /// within `e_in` of the raw piece's points over `[s0, s1]`, enclosed.
    pub(super) fn exact_range(&self, s0: f64, s1: f64) -> Option<(f64, f64)> {
        let (lo, hi) = if self.reversed {
            (1.0 - s1, 1.0 - s0)
        } else {
            (s0, s1)
        };
        let iv = |x: f64| Interval::try_from((x, x)).ok();
        let (mut u0, mut u1) = (f64::INFINITY, f64::NEG_INFINITY);
        for b in self.boxes.iter() {
            if b.t.1 >= lo && b.t.0 <= hi {
                // φ on the part of the box inside [lo, hi]: the cubic's
                // Bernstein coefficients restricted there (interval blossom)
                let w = iv(b.t.1)? - iv(b.t.0)?;
                let a = (iv(lo.max(b.t.0))? - iv(b.t.0)?) / w;
                let z = (iv(hi.min(b.t.1))? - iv(b.t.0)?) / w;
                let coef = Bezier::new(
                    b.c.iter()
                        .map(|&c| Some(V2::new(iv(c)?, iv(0.0)?)))
                        .collect::<Option<Vec<_>>>()?,
                );
                for p in coef.restrict(&a, &z).points() {
                    u0 = u0.min(p.x.inf());
                    u1 = u1.max(p.x.sup());
                }
            }
        }
        if u0.is_nan() || u1.is_nan() || u0 > u1 || u0 < 0.0 || u1 > 1.0 {
            return None;
        }
        let (a, b) = (iv(self.span.0)?, iv(self.span.1)?);
        let t0 = a + iv(u0)? * (b - a);
        let t1 = a + iv(u1)? * (b - a);
        Some((t0.inf().max(0.0), t1.sup().min(1.0)))
    }
}

fn fsq(v: &V2<Rational>) -> Interval {
    let w = v.map(interval_from_rational);
    (w.x * w.x + w.y * w.y).sqrt()
}

/// `|p − q|` upper bound.
pub(super) fn dist_hi(p: &V2<Rational>, q: &V2<Rational>) -> f64 {
    fsq(&p.sub(q)).sup()
}

fn unit_normal_point(c: &V2<Rational>, r: &Rational, dir: &V2<Rational>) -> V2<Interval> {
    let d = dir.map(interval_from_rational);
    let n = (d.x * d.x + d.y * d.y).sqrt();
    let ri = interval_from_rational(r);
    let ci = c.map(interval_from_rational);
    V2::new(ci.x + ri * d.x / n, ci.y + ri * d.y / n)
}

fn dist_hi_iv(p: &V2<Rational>, q: &V2<Interval>) -> f64 {
    let pi = p.map(interval_from_rational);
    let (dx, dy) = (pi.x - q.x, pi.y - q.y);
    (dx * dx + dy * dy).sqrt().sup()
}

pub(super) fn set_end(
    b: &Bezier<Rational>,
    first: Option<&V2<Rational>>,
    last: Option<&V2<Rational>>,
) -> Bezier<Rational> {
    let mut p = b.points().to_vec();
    if let Some(f) = first {
        p[0] = f.clone();
    }
    if let Some(l) = last {
        let n = p.len() - 1;
        p[n] = l.clone();
    }
    Bezier::new(p)
}

/// The first nonzero derivative direction at an end (`e = 0` or `1`), exact.
fn end_tangent(b: &Bezier<Rational>, e: u8) -> Option<V2<Rational>> {
    let h = b.hodograph();
    let hp = h.points();
    let z = |v: &&V2<Rational>| !v.x.is_zero() || !v.y.is_zero();
    if e == 0 {
        hp.iter().find(z).cloned()
    } else {
        hp.iter().rev().find(z).cloned()
    }
}

pub(super) fn approx_dir(v: &V2<Rational>) -> (f64, f64) {
    (v.x.approx(), v.y.approx())
}

/// One side's segments chained forward, with join arcs and connectors at the
/// corners (the closing corner too when `closed`).
/// The raw pieces of one offset side, in order, joined exactly.
///
/// **Joints are not crossings** (issue 27): at a G⁰ corner whose join arc or
/// concave connector would be shorter than `merge` (a corner of a few ulps in
/// data written by float code, a path whose tangents agree to a few digits),
/// no piece is inserted: the next segment's start control point is moved onto
/// the previous segment's end (fact 4: the move `d` is added to its bounds),
/// so the two segments meet at one exact point with nearly opposite
/// directions, a joint the crossing search decides to first order. For a
/// convex corner the exact join arc (from `E₁ = c + r·from/|from|` to `E₂`,
/// turning by less than π) has every point within `|E₁ − E₂|` of `E₁`, hence
/// within `e_J = 2|x₁ − E₁| + |x₁ − x₂| + |x₂ − E₂|` of the kept end `x₁`:
/// the previous segment stands for its exact span **and** the join arc, its
/// bound `e` raised to `e_J` (claim (b) uses `e` only through "every exact
/// point is within `e` of the raw piece"; `e_in` is unchanged since the raw
/// piece still lies within `e_in` of `S`). A concave connector's points are
/// never needed for (b) (fact 3), so dropping a short one costs only the move.
fn chain_side(
    res: &OffsetResult,
    r: &Rational,
    closed: bool,
    merge: f64,
    first: usize,
    lines: Option<&[Bezier<Rational>]>,
) -> Result<Vec<Raw>, StrokeError> {
    let segs: Vec<(usize, Bezier<Rational>, f64)> = res
        .segments
        .iter()
        .map(|s| {
            exact_bezier(&s.bezier)
                .map(|b| (s.piece, b, s.error.1))
                .ok_or_else(|| bad("curve", "an offset control point is not finite"))
        })
        .collect::<Result<_, _>>()?;
    if segs.is_empty() {
        return Err(bad("curve", "no offset segments"));
    }
    let link = |s: &crate::offset::OffsetSegment| -> Option<Link> {
        let proof = s.proof.as_ref()?;
        let map = proof.map.as_ref()?;
        if map.source_a || map.boxes.is_empty() || s.error.1.is_nan() || s.error.1 > res.tol.value()
        {
            return None;
        }
        Some(Link {
            piece: first + s.piece,
            span: s.t,
            d: res.distance.clone(),
            boxes: std::sync::Arc::new(map.boxes.clone()),
            reversed: false,
            seg_e: s.error.1,
        })
    };
    let mut raws: Vec<Raw> = segs
        .iter()
        .zip(&res.segments)
        .map(|((_, b, e), s)| {
            // a straight input piece with a rational unit normal: its exact
            // offset is the piece translated, written exactly (error 0, the
            // identity map), not the float construction
            if let Some(x) = lines.and_then(|c| c.get(s.piece)) {
                if let Some(exact) = exact_line_offset(x, &res.distance, s.t) {
                    return Raw {
                        piece: Piece::Bezier(exact),
                        e: 0.0,
                        e_in: 0.0,
                        kind: Kind::Boundary,
                        link: Some(Link {
                            piece: first + s.piece,
                            span: s.t,
                            d: res.distance.clone(),
                            boxes: std::sync::Arc::new(vec![crate::certify::ParamBox {
                                t: (0.0, 1.0),
                                c: [0.0, 1.0 / 3.0, 2.0 / 3.0, 1.0],
                                bound: 0.0,
                            }]),
                            reversed: false,
                            seg_e: 0.0,
                        }),
                    };
                }
            }
            Raw {
                piece: Piece::Bezier(b.clone()),
                e: *e,
                e_in: *e,
                kind: Kind::Boundary,
                link: link(s),
            }
        })
        .collect();
    let n = raws.len();
    let mut out: Vec<Raw> = Vec::new();
    // junction k: between segment k and k + 1 (cyclic for closed)
    let mut inserts: Vec<Option<Raw>> = vec![None; n];
    let last = if closed { n } else { n - 1 };
    for k in 0..last {
        let k1 = (k + 1) % n;
        let corner = if segs[k].0 != segs[k1].0 || (closed && k1 == 0) {
            res.corners
                .iter()
                .find(|c| c.after == segs[k].0)
                .map(|c| c.kind.clone())
        } else {
            None
        };
        let (p1, p2) = (raws[k].piece.end().clone(), raws[k1].piece.start().clone());
        match corner {
            Some(Junction::Join {
                center,
                from,
                to,
                clockwise,
            }) => {
                let x1 = on_or_snap(&center, r, &p1, &from).ok_or_else(|| bad("curve", "join"))?;
                let x2 = on_or_snap(&center, r, &p2, &to).ok_or_else(|| bad("curve", "join"))?;
                let d1 = dist_hi(&p1, &x1);
                let e1 = dist_hi_iv(&x1, &unit_normal_point(&center, r, &from));
                let e2 = dist_hi_iv(&x2, &unit_normal_point(&center, r, &to));
                let gap = dist_hi(&x1, &x2);
                if gap <= merge {
                    // a join arc shorter than `merge`: no arc, one exact point
                    let e_j = (2.0 * e1 + gap + e2) * (1.0 + 1e-12);
                    if let Piece::Bezier(b) = &raws[k].piece {
                        raws[k].piece = Piece::Bezier(set_end(b, None, Some(&x1)));
                    }
                    raws[k].e = (raws[k].e + d1).max(e_j);
                    raws[k].e_in += d1;
                    let d = dist_hi(&p2, &x1);
                    if let Piece::Bezier(b) = &raws[k1].piece {
                        raws[k1].piece = Piece::Bezier(set_end(b, Some(&x1), None));
                    }
                    raws[k1].e += d;
                    raws[k1].e_in += d;
                    continue;
                }
                attach(&mut raws[k], true, &x1, &center, merge);
                attach(&mut raws[k1], false, &x2, &center, merge);
                if x1 != x2 {
                    inserts[k] = Some(Raw {
                        piece: Piece::Arc(Arc {
                            center,
                            radius: r.clone(),
                            from: x1,
                            to: x2,
                            clockwise,
                        }),
                        e: e1.max(e2),
                        e_in: 0.0,
                        kind: Kind::Boundary,
                        link: None,
                    });
                } else if let Piece::Bezier(b) = &raws[k1].piece {
                    let _ = b;
                }
            }
            Some(Junction::Overlap { center }) => {
                let d = dist_hi(&p1, &p2);
                if p1 != p2 && d <= merge {
                    // a connector shorter than `merge`: move the next start
                    if let Piece::Bezier(b) = &raws[k1].piece {
                        raws[k1].piece = Piece::Bezier(set_end(b, Some(&p1), None));
                    }
                    raws[k1].e += d;
                    raws[k1].e_in += d;
                } else if p1 != p2 {
                    let e_in = (dist_hi(&p1, &center).max(dist_hi(&p2, &center)) - r.approx())
                        .max(0.0)
                        * (1.0 + 1e-12);
                    inserts[k] = Some(Raw {
                        piece: Piece::Bezier(Bezier::new(vec![p1, p2])),
                        e: f64::INFINITY,
                        e_in,
                        kind: Kind::Connector,
                        link: None,
                    });
                }
            }
            _ => {
                if p1 != p2 {
                    // smooth junction with float ends that differ: move the next start
                    let d = dist_hi(&p1, &p2);
                    if let Piece::Bezier(b) = &raws[k1].piece {
                        raws[k1].piece = Piece::Bezier(set_end(b, Some(&p1), None));
                    }
                    raws[k1].e += d;
                    raws[k1].e_in += d;
                }
            }
        }
    }
    for (k, r) in raws.into_iter().enumerate() {
        out.push(r);
        if let Some(ins) = inserts[k].take() {
            out.push(ins);
        }
    }
    Ok(out)
}

/// The exact offset at signed distance `d` (to the left) of the span
/// `[t₀, t₁]` of a straight piece `x` whose unit normal is rational: every
/// hodograph control point a positive multiple of `v = x(1) − x(0)` (so
/// `x′ ≠ 0` and the direction is constant) and `|v|` rational. Then
/// `E(t) = x(t) + d·n` for the one normal `n = (−v_y, v_x)/|v|`: the control
/// points shifted by `d·n`, restricted to the span — exactly `E` with the
/// same parameter (the identity map).
fn exact_line_offset(
    x: &Bezier<Rational>,
    d: &Rational,
    t: (f64, f64),
) -> Option<Bezier<Rational>> {
    let p = x.points();
    let v = p[p.len() - 1].sub(&p[0]);
    for w in p.windows(2) {
        let h = w[1].sub(&w[0]);
        if !(&h.x * &v.y - &h.y * &v.x).is_zero() || !(&h.x * &v.x + &h.y * &v.y).is_positive() {
            return None;
        }
    }
    let n2 = &v.x * &v.x + &v.y * &v.y;
    let (sn, sd) = (n2.numer().sqrt(), n2.denom().sqrt());
    if &sn * &sn != *n2.numer() || &sd * &sd != *n2.denom() {
        return None;
    }
    let len = Rational::new(sn, sd);
    let shift = V2::new(-(&v.y) * d / &len, &v.x * d / &len);
    let moved = Bezier::new(p.iter().map(|q| q.add(&shift)).collect());
    Some(moved.restrict(&rational_from_f64(t.0)?, &rational_from_f64(t.1)?))
}

/// The end of a raw offset segment where it meets an exact arc about
/// `center` at the arc's end point `x` (on the circle): the end control point
/// becomes `x` (fact 4: the move is added to `e`, `e_in`), and the control
/// point next to it is projected onto the circle's tangent at `x`, so the
/// segment leaves the arc with an **exactly** common tangent (its float
/// construction is tangent up to rounding, which would leave a second
/// contact with the circle a few ulps from the joint that no interval test
/// can place). Both moves add up: a point of the Bézier moves by at most
/// `B_n(t)·δ_end + B_{n−1}(t)·δ_handle ≤ δ_end + δ_handle`. The projection
/// is skipped for lines and when it would move the handle by more than
/// `max_move`.
fn attach(raw: &mut Raw, at_end: bool, x: &V2<Rational>, center: &V2<Rational>, max_move: f64) {
    let Piece::Bezier(b) = &raw.piece else {
        return;
    };
    let p = b.points();
    let n = p.len() - 1;
    let old = if at_end { &p[n] } else { &p[0] };
    let d = dist_hi(old, x);
    let mut pts = p.to_vec();
    if at_end {
        pts[n] = x.clone();
    } else {
        pts[0] = x.clone();
    }
    let mut moved = d;
    if n >= 2 {
        let k = if at_end { n - 1 } else { 1 };
        // the tangent line at x: x + s·τ, τ ⟂ (x − c)
        let tau = x.sub(center).rot90();
        let t2 = tau.norm2();
        if !t2.is_zero() {
            let s = pts[k].sub(x).dot(&tau) / &t2;
            let q = x.add(&tau.scale(&s));
            let dq = dist_hi(&pts[k], &q);
            if dq <= max_move {
                pts[k] = q;
                moved += dq;
            }
        }
    }
    raw.piece = Piece::Bezier(Bezier::new(pts));
    raw.e += moved;
    raw.e_in += moved;
}

/// `p` itself when it lies exactly on the circle (an exact offset end),
/// else a rational point exactly on it in the direction `dir`.
fn on_or_snap(
    c: &V2<Rational>,
    r: &Rational,
    p: &V2<Rational>,
    dir: &V2<Rational>,
) -> Option<V2<Rational>> {
    if crate::stroke::circle::on_circle(c, r, p) && !p.sub(c).dot(dir).is_negative() {
        return Some(p.clone());
    }
    snap(c, r, approx_dir(dir))
}

fn reverse_side(side: Vec<Raw>) -> Vec<Raw> {
    side.into_iter()
        .rev()
        .map(|r| Raw {
            piece: r.piece.reversed(),
            link: r.link.map(|l| Link {
                reversed: !l.reversed,
                ..l
            }),
            ..r
        })
        .collect()
}

/// The cap at the end `e` (0: start, 1: end) of the curve: returns the arc or
/// chord from `p_from` (moved to the snapped point) to `p_to`.
fn cap_piece(
    x: &Bezier<Rational>,
    e: u8,
    r: &Rational,
    cap: Cap,
    from_piece: &mut Raw,
    to_piece: &mut Raw,
    max_move: f64,
) -> Result<Raw, StrokeError> {
    let c = if e == 0 {
        x.points()[0].clone()
    } else {
        x.points().last().expect("nonempty").clone()
    };
    let t = end_tangent(x, e).ok_or_else(|| bad("curve", "a degenerate end"))?;
    let n = t.rot90(); // left normal (not unit)
    let neg_n = n.neg();
    // at the end: from −N (the −r side) to +N; at the start: from +N to −N
    let (dir_from, dir_to) = if e == 1 { (neg_n, n) } else { (n, neg_n) };
    let p1 = from_piece.piece.end().clone();
    let p2 = to_piece.piece.start().clone();
    match cap {
        Cap::Butt => {
            let ex1 = unit_normal_point(&c, r, &dir_from);
            let ex2 = unit_normal_point(&c, r, &dir_to);
            let e = dist_hi_iv(&p1, &ex1).max(dist_hi_iv(&p2, &ex2));
            let e_in =
                (dist_hi(&p1, &c).max(dist_hi(&p2, &c)) - r.approx()).max(0.0) * (1.0 + 1e-12);
            Ok(Raw {
                piece: Piece::Bezier(Bezier::new(vec![p1, p2])),
                e,
                e_in,
                kind: Kind::Butt,
                link: None,
            })
        }
        Cap::Round => {
            let x1 = on_or_snap(&c, r, &p1, &dir_from).ok_or_else(|| bad("curve", "cap"))?;
            let x2 = on_or_snap(&c, r, &p2, &dir_to).ok_or_else(|| bad("curve", "cap"))?;
            attach(from_piece, true, &x1, &c, max_move);
            attach(to_piece, false, &x2, &c, max_move);
            let e1 = dist_hi_iv(&x1, &unit_normal_point(&c, r, &dir_from));
            let e2 = dist_hi_iv(&x2, &unit_normal_point(&c, r, &dir_to));
            Ok(Raw {
                piece: Piece::Arc(Arc {
                    center: c,
                    radius: r.clone(),
                    from: x1,
                    to: x2,
                    clockwise: false,
                }),
                e: e1.max(e2),
                e_in: 0.0,
                kind: Kind::Boundary,
                link: None,
            })
        }
    }
}

/// Checks the inputs; `true` when the curve is closed.
/// The connected components of the curve (pieces joined end to start):
/// `(first, end, closed)` with `curve[first..end]` one component.
fn components(curve: &[Bezier<Rational>]) -> Vec<(usize, usize, bool)> {
    let mut out: Vec<(usize, usize, bool)> = Vec::new();
    for i in 0..curve.len() {
        let joined = i > 0 && curve[i - 1].points().last() == curve[i].points().first();
        match out.last_mut() {
            Some(c) if joined => c.1 = i + 1,
            _ => out.push((i, i + 1, false)),
        }
    }
    for c in &mut out {
        let part = &curve[c.0..c.1];
        let closed = part.len() > 1 || part[0].degree() > 1;
        c.2 = closed && part.last().and_then(|b| b.points().last()) == part[0].points().first();
    }
    out
}

pub(super) fn check(
    curve: &[Bezier<Rational>],
    opts: &StrokeOptions,
) -> Result<Vec<(usize, usize, bool)>, StrokeError> {
    if curve.is_empty() {
        return Err(bad("curve", "no pieces"));
    }
    if opts.ellipse.is_none() && !opts.radius.is_positive() {
        return Err(bad("radius", "must be > 0"));
    }
    for (i, b) in curve.iter().enumerate() {
        if b.degree() == 0 {
            return Err(bad("curve", format!("piece {i} is a point")));
        }
    }
    check_range(curve, opts)?;
    let comps = components(curve);
    if comps.len() > MAX_COMPONENTS {
        return Err(bad(
            "curve",
            format!(
                "{} separate contours (at most {MAX_COMPONENTS})",
                comps.len()
            ),
        ));
    }
    for &(first, end, closed) in &comps {
        if opts.ellipse.is_none() {
            continue;
        }
        // the elliptical pen has no join pieces yet: the curve must be G¹
        let part = &curve[first..end];
        let n = part.len();
        let joints = if closed { n } else { n - 1 };
        for i in 0..joints {
            let (a, b) = (&part[i], &part[(i + 1) % n]);
            let g1 = match (end_tangent(a, 1), end_tangent(b, 0)) {
                (Some(u), Some(v)) => u.cross(&v).is_zero() && u.dot(&v).is_positive(),
                _ => false,
            };
            if !g1 {
                return Err(bad(
                    "curve",
                    format!("a G⁰ corner after piece {}: the elliptical pen needs a G¹ curve (join pieces are not supported yet)", first + i),
                ));
            }
        }
    }
    Ok(comps)
}

/// The finest detail of a stroke the engine resolves, relative to its
/// extent: `2⁻⁶⁴ ≈ 5.4·10⁻²⁰` (see [`check_range`]).
pub const MIN_RELATIVE_DETAIL_LOG2: i32 = -64;

/// The dynamic range of a stroke's input, refused early where the engine
/// cannot work (issue 65): with `E` the larger of the control points'
/// bounding-box width and height and the pen's size (radius, or the largest
/// matrix entry), every nonzero step between consecutive control points
/// (its larger coordinate difference) and the pen's size must be at least
/// `2⁻⁶⁴ E`, and the tolerance at least `2⁻⁵⁰ E`. Below that, the f64
/// enclosures every certified test starts from (relative width ≈ 2⁻⁵² of
/// the coordinates) cannot tell the detail from nothing: the search would
/// subdivide to its budget and stay undecided. A step of exactly zero (a
/// retracted handle) is exact degeneracy and is fine; real designs sit many
/// orders of magnitude inside these limits (fonts: integer steps against
/// extents below 2¹⁶).
fn check_range(curve: &[Bezier<Rational>], opts: &StrokeOptions) -> Result<(), StrokeError> {
    let pts = || curve.iter().flat_map(|b| b.points().iter());
    let Some(first) = pts().next() else {
        return Ok(());
    };
    let (mut lo, mut hi) = (first.clone(), first.clone());
    for p in pts() {
        if p.x < lo.x {
            lo.x = p.x.clone();
        }
        if p.y < lo.y {
            lo.y = p.y.clone();
        }
        if p.x > hi.x {
            hi.x = p.x.clone();
        }
        if p.y > hi.y {
            hi.y = p.y.clone();
        }
    }
    let pen = match &opts.ellipse {
        Some(p) => {
            p.m.iter()
                .flatten()
                .map(|x| x.abs())
                .max()
                .unwrap_or_default()
        }
        None => opts.radius.abs(),
    };
    let extent = [&hi.x - &lo.x, &hi.y - &lo.y, pen.clone()]
        .into_iter()
        .max()
        .unwrap_or_default();
    let scaled = |log2: i32| {
        &extent / Rational::from_integer(num_bigint::BigInt::from(1u8) << (-log2) as usize)
    };
    let floor = scaled(MIN_RELATIVE_DETAIL_LOG2);
    let approx = |r: &Rational| r.approx();
    if pen < floor {
        return Err(bad(
            if opts.ellipse.is_some() { "pen" } else { "radius" },
            format!(
                "the pen's size {:.3e} is below 2^{MIN_RELATIVE_DETAIL_LOG2} of the stroke's extent {:.3e}: finer than the engine's f64 enclosures resolve",
                approx(&pen),
                approx(&extent)
            ),
        ));
    }
    for (i, b) in curve.iter().enumerate() {
        for (k, w) in b.points().windows(2).enumerate() {
            let (dx, dy) = ((&w[1].x - &w[0].x).abs(), (&w[1].y - &w[0].y).abs());
            let step = if dx > dy { dx } else { dy };
            if step.is_positive() && step < floor {
                return Err(bad(
                    "curve",
                    format!(
                        "piece {i}: control points {k} and {} are {:.3e} apart, below 2^{MIN_RELATIVE_DETAIL_LOG2} of the stroke's extent {:.3e}: finer than the engine's f64 enclosures resolve (make them coincide exactly, or drop the detail)",
                        k + 1,
                        approx(&step),
                        approx(&extent)
                    ),
                ));
            }
        }
    }
    if *opts.tol.exact() < scaled(-50) {
        return Err(bad(
            "tol",
            format!(
                "{:.3e} is below 2^-50 of the stroke's extent {:.3e}: finer than the engine's f64 enclosures resolve",
                opts.tol.value(),
                approx(&extent)
            ),
        ));
    }
    Ok(())
}

/// Most separate contours of one stroke.
const MAX_COMPONENTS: usize = 256;

/// The raw contours (before trimming).
#[allow(clippy::type_complexity)]
pub(super) fn raw_contours(
    curve: &[Bezier<Rational>],
    opts: &StrokeOptions,
    closed: bool,
    first: usize,
    raw_div: f64,
) -> Result<(Vec<Vec<Raw>>, Vec<String>, Vec<CapReport>), StrokeError> {
    let r = &opts.radius;
    let tol_off = Tolerance::from_f64(opts.tol.value() / raw_div)?;
    let run = |d: Rational| {
        let mut o = OffsetOptions::new(d.clone(), tol_off.clone());
        o.output = opts.output;
        o.method = opts.method;
        match &opts.ellipse {
            // the convolution sides x ∗ e_σ, σ = sign(d), certified for the exact pen
            Some(pen) => {
                let side = if d.is_negative() { -1 } else { 1 };
                convolve(curve, pen, side, &o).map_err(|e| bad("curve", e.to_string()))
            }
            None => offset(curve, &o).map_err(|e| bad("curve", e.to_string())),
        }
    };
    let (minus, plus) = rayon::join(|| run(-r.clone()), || run(r.clone()));
    let (minus, plus) = (minus?, plus?);
    let mut notes = Vec::new();
    for (name, res) in [("-r", &minus), ("+r", &plus)] {
        if !res.reached() || !res.proven {
            notes.push(format!(
                "the {name} offset did not reach tol/{raw_div} (certified {:.3e})",
                res.certified_hi
            ));
        }
    }
    // joins and connectors shorter than this are merged into one exact point
    let merge = opts.tol.value() / 64.0;
    // the exact-interval kept test is for a circular pen (offset sides)
    let strip = |mut side: Vec<Raw>| {
        if opts.ellipse.is_some() {
            for raw in &mut side {
                raw.link = None;
            }
        }
        side
    };
    // exact offsets of straight pieces: for a circular pen only
    let lines = opts.ellipse.is_none().then_some(curve);
    let a = strip(chain_side(&minus, r, closed, merge, first, lines)?);
    let b = strip(reverse_side(chain_side(
        &plus, r, closed, merge, first, lines,
    )?));
    if closed {
        return Ok((vec![a, b], notes, Vec::new()));
    }
    let (mut a, mut b) = (a, b);
    let x_end = curve.last().expect("nonempty");
    let (na, nb) = (a.len() - 1, b.len() - 1);
    let mut caps = Vec::new();
    let end_cap = {
        let (a_last, b_first) = (&mut a[na].clone(), &mut b[0].clone());
        let cap = match &opts.ellipse {
            Some(pen) => ellipse_cap_piece(x_end, 1, pen, opts, a_last, b_first, &mut caps)?,
            None => vec![cap_piece(x_end, 1, r, opts.cap, a_last, b_first, merge)?],
        };
        a[na] = a_last.clone();
        b[0] = b_first.clone();
        cap
    };
    let start_cap = {
        let (b_last, a_first) = (&mut b[nb].clone(), &mut a[0].clone());
        let cap = match &opts.ellipse {
            Some(pen) => ellipse_cap_piece(&curve[0], 0, pen, opts, b_last, a_first, &mut caps)?,
            None => vec![cap_piece(
                &curve[0], 0, r, opts.cap, b_last, a_first, merge,
            )?],
        };
        b[nb] = b_last.clone();
        a[0] = a_first.clone();
        cap
    };
    let mut all = a;
    all.extend(end_cap);
    all.extend(b);
    all.extend(start_cap);
    Ok((vec![all], notes, caps))
}

/// The cap of an elliptical pen at the end `e` (0: start, 1: end): the half
/// ellipse as proven cubics ([`half_ellipse_cap`], within `tol/8`), the
/// neighbouring sides' end control points replaced by its exact ends (the
/// moves added to their bounds), or the butt chord.
#[allow(clippy::too_many_arguments)]
fn ellipse_cap_piece(
    x: &Bezier<Rational>,
    e: u8,
    pen: &Pen,
    opts: &StrokeOptions,
    from_piece: &mut Raw,
    to_piece: &mut Raw,
    caps: &mut Vec<CapReport>,
) -> Result<Vec<Raw>, StrokeError> {
    let c = if e == 0 {
        x.points()[0].clone()
    } else {
        x.points().last().expect("nonempty").clone()
    };
    let t = end_tangent(x, e).ok_or_else(|| bad("curve", "a degenerate end"))?;
    let n = t.rot90();
    let (dir_from, dir_to, out) = if e == 1 {
        (n.neg(), n, t)
    } else {
        (n.clone(), n.neg(), t.neg())
    };
    let p1 = from_piece.piece.end().clone();
    let p2 = to_piece.piece.start().clone();
    let ex1 = pen_point_enclosure(&c, pen, &dir_from);
    let ex2 = pen_point_enclosure(&c, pen, &dir_to);
    if opts.cap == Cap::Butt {
        let err = dist_hi_iv(&p1, &ex1).max(dist_hi_iv(&p2, &ex2));
        // the chord lies within `err` of the convex c + E
        return Ok(vec![Raw {
            piece: Piece::Bezier(Bezier::new(vec![p1, p2])),
            e: err,
            e_in: err,
            kind: Kind::Butt,
            link: None,
        }]);
    }
    let cap = half_ellipse_cap(&c, pen, &dir_from, &out, opts.tol.value() / 8.0)
        .ok_or_else(|| bad("pen", "the half-ellipse cap could not be proven"))?;
    let x1 = cap.pieces[0].points()[0].clone();
    let x2 = cap.pieces.last().expect("k ≥ 2").points()[3].clone();
    let d1 = dist_hi(&p1, &x1);
    let d2 = dist_hi(&p2, &x2);
    if let Piece::Bezier(b) = &from_piece.piece {
        from_piece.piece = Piece::Bezier(set_end(b, None, Some(&x1)));
    }
    from_piece.e += d1;
    from_piece.e_in += d1;
    if let Piece::Bezier(b) = &to_piece.piece {
        to_piece.piece = Piece::Bezier(set_end(b, Some(&x2), None));
    }
    to_piece.e += d2;
    to_piece.e_in += d2;
    caps.push(CapReport {
        end: if e == 1 { "end" } else { "start" },
        pieces: cap.pieces.len(),
        error: cap.error,
        circle_error: cap.circle_error,
    });
    Ok(cap
        .pieces
        .into_iter()
        .map(|b| Raw {
            piece: Piece::Bezier(b),
            e: cap.error,
            e_in: cap.error,
            kind: Kind::Boundary,
            link: None,
        })
        .collect())
}

#[cfg(test)]
mod range_tests {
    use super::*;

    fn q(s: &str) -> Rational {
        crate::parse_rational(s).unwrap()
    }

    fn opts(r: &str, tol: &str) -> StrokeOptions {
        StrokeOptions::new(q(r), tol.parse().unwrap())
    }

    /// A quadratic `(0,0), (h, 0), (h, 1)` scaled by `s`.
    fn corner(h: &Rational, s: &Rational) -> Vec<Bezier<Rational>> {
        let p = |x: Rational, y: Rational| V2::new(x * s, y * s);
        let z = <Rational as Zero>::zero();
        vec![Bezier::new(vec![
            p(z.clone(), z.clone()),
            p(h.clone(), z),
            p(h.clone(), Rational::from_integer(1.into())),
        ])]
    }

    /// Issue 65: a handle 2⁻⁶⁴ of the extent or longer is taken, a shorter one
    /// refused naming the piece, at every scale (the limit is relative); a
    /// handle of exactly zero is exact degeneracy and taken.
    #[test]
    fn details_below_the_enclosures_resolution_are_refused_at_any_scale() {
        let two = |k: i64| {
            let p = num_bigint::BigInt::from(1u8) << k.unsigned_abs() as usize;
            if k < 0 {
                Rational::new(1.into(), p)
            } else {
                Rational::from_integer(p)
            }
        };
        for scale in [-300i64, 0, 300] {
            let s = two(scale);
            let o = opts(
                &(s.clone() / Rational::from_integer(5.into())).to_string(),
                "1",
            );
            let o = StrokeOptions {
                tol: Tolerance::new(&s / Rational::from_integer(1000.into())).unwrap(),
                ..o
            };
            assert!(
                check_range(&corner(&two(-64), &s), &o).is_ok(),
                "scale 2^{scale}"
            );
            assert!(check_range(&corner(&<Rational as Zero>::zero(), &s), &o).is_ok());
            let e = check_range(&corner(&two(-65), &s), &o).unwrap_err();
            assert_eq!(e.field, "curve");
            assert!(
                e.reason.contains("piece 0: control points 0 and 1"),
                "{}",
                e.reason
            );
        }
        // the pen and the tolerance, against the extent 1
        let x = corner(&q("1/2"), &q("1"));
        assert_eq!(
            check_range(&x, &opts("1/1e20", "1e-3")).unwrap_err().field,
            "radius"
        );
        assert_eq!(
            check_range(&x, &opts("1/4", "1e-16")).unwrap_err().field,
            "tol"
        );
        assert!(check_range(&x, &opts("1/4", "1e-14")).is_ok());
    }

    /// The slow case of issue 65 (`stroke --pen circle:2e99 --tol 1e96` of a
    /// quadratic with a 10⁻¹⁰⁰ handle ran past 60 s) is refused before any work.
    #[test]
    fn the_slow_huge_quadratic_is_refused_before_any_work() {
        let e100 = Rational::from_integer(num_bigint::BigInt::from(10u8).pow(100));
        let x = corner(&(Rational::from_integer(1.into()) / (&e100 * &e100)), &e100);
        let o = StrokeOptions {
            tol: Tolerance::new(&e100 / Rational::from_integer(10_000.into())).unwrap(),
            ..StrokeOptions::new(
                &e100 / Rational::from_integer(5.into()),
                "1".parse().unwrap(),
            )
        };
        let e = crate::stroke::stroke(&x, &o).unwrap_err();
        assert_eq!(e.field, "curve", "{}", e.reason);
    }
}
