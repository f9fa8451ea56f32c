//! The writer of stroke certificates ([`certificate`]): the cover of a proven
//! outline by parts between a point of `S` and a point outside `S` (claim
//! (a)), and the cover of the exact boundary's families by boxes near the
//! outline or strictly inside `S` (claim (b)). The boxes are chosen with float
//! nearest points and accepted by the verifier's own tests
//! ([`crate::certify::verify::stroke`]), bisected where a test fails; the
//! format and the argument are in that module and in
//! `proofs/stroke-certificate.md`.

use super::{Piece, Stroke};
use crate::certify::verify::stroke::geom::{arc_hull, ip, iq, BoxT, Path};
use crate::certify::verify::stroke::{
    check_bbox, check_part, exact_points, BBox, CurvePiece, Input, Inside, OPiece, PenMap, Span,
    CLAIM, CLAIM_ELLIPSE, FORMAT, Q2, VERSION,
};
use crate::curve::Bezier;
use crate::scalar::{rational_from_f64, rational_to_string, Interval, Rational, Scalar};
use crate::Error;
use glam::DVec2;
use rayon::prelude::*;
use serde_json::{json, Value};

fn err(reason: impl Into<String>) -> Error {
    Error {
        field: "certificate".into(),
        reason: reason.into(),
    }
}

fn q(x: f64) -> Result<Rational, Error> {
    rational_from_f64(x).ok_or_else(|| err("a non-finite number"))
}
fn qs(r: &Rational) -> Value {
    Value::String(rational_to_string(r))
}
fn pt(p: &Q2) -> Value {
    json!([qs(&p[0]), qs(&p[1])])
}
fn ptf(p: DVec2) -> Result<(Q2, Value), Error> {
    let e = [q(p.x)?, q(p.y)?];
    let v = pt(&e);
    Ok((e, v))
}
/// `x` rounded to a multiple of the power of two `g` (unchanged where that
/// multiple is not exact): witnesses need only be about right, and short
/// rationals read faster.
fn snap(x: f64, g: f64) -> f64 {
    if g > 0.0 && (x / g).abs() < 2f64.powi(52) {
        (x / g).round() * g
    } else {
        x
    }
}

/// `x` rounded to `bits` significant bits (a short number to write); `x`
/// itself when it is 0, not finite or beyond the normal range.
fn round_bits(x: f64, bits: i32) -> f64 {
    if x == 0.0 || !x.is_normal() {
        return x;
    }
    // |x| ∈ [2^e, 2^(e+1)), e ∈ [−1022, 1023]
    let e = x.abs().log2().floor() as i32;
    let r = snap(x, 2f64.powi(e - bits));
    if r.is_finite() {
        r
    } else {
        x
    }
}

/// A power of two about `tol / 1024`: the grid of witness coordinates.
fn coord_grid(tol: f64) -> f64 {
    2f64.powi((tol / 1024.0).log2().floor().clamp(-1000.0, 1000.0) as i32)
}

/// The grid of a witness parameter on a piece whose control polygon is `p`
/// (a step moves the point by less than `tol / 1024`, and by at most 2⁻¹⁶).
fn param_grid(p: &[DVec2], tol: f64) -> f64 {
    let len: f64 = p.windows(2).map(|w| (w[1] - w[0]).length()).sum();
    coord_grid(tol / len.max(tol)).min(2f64.powi(-16))
}

fn mid(x: Interval) -> f64 {
    0.5 * (x.inf() + x.sup())
}
fn point_iv(t: f64) -> Interval {
    crate::scalar::point_interval(t)
}

/// Float Bézier evaluation (on the stack up to degree 15).
fn bez_at(p: &[DVec2], t: f64) -> DVec2 {
    let mut buf = [DVec2::ZERO; 16];
    let mut heap;
    let b: &mut [DVec2] = if p.len() <= buf.len() {
        buf[..p.len()].copy_from_slice(p);
        &mut buf[..p.len()]
    } else {
        heap = p.to_vec();
        &mut heap
    };
    for k in (1..b.len()).rev() {
        for i in 0..k {
            b[i] = b[i] * (1.0 - t) + b[i + 1] * t;
        }
    }
    b[0]
}
fn hodo(p: &[DVec2]) -> Vec<DVec2> {
    let n = (p.len() - 1) as f64;
    p.windows(2).map(|w| (w[1] - w[0]) * n).collect()
}

/// A float model of a Bézier for nearest-point queries.
struct FBez {
    p: Vec<DVec2>,
    d: Vec<DVec2>,
    dd: Vec<DVec2>,
    lo: DVec2,
    hi: DVec2,
}

impl FBez {
    fn new(p: Vec<DVec2>) -> FBez {
        let d = hodo(&p);
        let dd = if d.len() > 1 {
            hodo(&d)
        } else {
            vec![DVec2::ZERO]
        };
        let lo = p.iter().fold(p[0], |a, b| a.min(*b));
        let hi = p.iter().fold(p[0], |a, b| a.max(*b));
        FBez { p, d, dd, lo, hi }
    }
    fn box_dist(&self, q: DVec2) -> f64 {
        let c = q.clamp(self.lo, self.hi);
        (q - c).length()
    }
    /// The nearest point: `(u, distance)`.
    fn nearest(&self, q: DVec2) -> (f64, f64) {
        let n = 8 * self.p.len();
        let mut best = (0.0, f64::INFINITY);
        for k in 0..=n {
            let u = k as f64 / n as f64;
            let d = (bez_at(&self.p, u) - q).length();
            if d < best.1 {
                best = (u, d);
            }
        }
        let mut u = best.0;
        for _ in 0..12 {
            let x = bez_at(&self.p, u) - q;
            let d1 = bez_at(&self.d, u);
            let d2 = bez_at(&self.dd, u);
            let g = x.dot(d1);
            let h = d1.length_squared() + x.dot(d2);
            if h <= 0.0 {
                break;
            }
            let nu = (u - g / h).clamp(0.0, 1.0);
            if (nu - u).abs() < 1e-16 {
                u = nu;
                break;
            }
            u = nu;
        }
        let d = (bez_at(&self.p, u) - q).length();
        if d < best.1 {
            (u, d)
        } else {
            best
        }
    }
}

/// A float model of an input arc `c + ρ d(λ)/|d(λ)|`, `d(λ) = (1 − λ) a +
/// λ b` (`a`, `b` the end radius vectors, less than `π` apart).
struct FArc {
    c: DVec2,
    rho: f64,
    a: DVec2,
    b: DVec2,
}

impl FArc {
    fn at(&self, u: f64) -> DVec2 {
        let d = self.a.lerp(self.b, u);
        self.c + d * (self.rho / d.length())
    }
    /// The nearest point: `(λ, distance)` — the direction of `p − c` where
    /// it lies between `a` and `b`, an end otherwise.
    fn nearest(&self, p: DVec2) -> (f64, f64) {
        let v = p - self.c;
        let den = (self.a - self.b).perp_dot(v);
        if den != 0.0 {
            let l = self.a.perp_dot(v) / den;
            if (0.0..=1.0).contains(&l) && self.a.lerp(self.b, l).dot(v) > 0.0 {
                return (l, (v.length() - self.rho).abs());
            }
        }
        let (d0, d1) = ((p - self.at(0.0)).length(), (p - self.at(1.0)).length());
        if d0 <= d1 {
            (0.0, d0)
        } else {
            (1.0, d1)
        }
    }
}

/// A float input piece.
enum FIn {
    Bez(FBez),
    Arc(FArc),
}

impl FIn {
    fn new(p: &CurvePiece) -> FIn {
        match p {
            CurvePiece::Bezier(p) => FIn::Bez(FBez::new(p.iter().map(v2).collect())),
            CurvePiece::Arc {
                c, rho, from, to, ..
            } => {
                let c = v2(c);
                FIn::Arc(FArc {
                    c,
                    rho: rho.approx(),
                    a: v2(from) - c,
                    b: v2(to) - c,
                })
            }
        }
    }
    fn nearest(&self, p: DVec2) -> (f64, f64) {
        match self {
            FIn::Bez(b) => b.nearest(p),
            FIn::Arc(a) => a.nearest(p),
        }
    }
    /// A lower bound of the distance (floats; it only orders the search).
    fn box_dist(&self, p: DVec2) -> f64 {
        match self {
            FIn::Bez(b) => b.box_dist(p),
            FIn::Arc(a) => ((p - a.c).length() - a.rho).abs(),
        }
    }
    fn at(&self, u: f64) -> DVec2 {
        match self {
            FIn::Bez(b) => bez_at(&b.p, u),
            FIn::Arc(a) => a.at(u),
        }
    }
    /// [`param_grid`] of the piece (an arc by its end and middle points).
    fn grid(&self, tol: f64) -> f64 {
        match self {
            FIn::Bez(b) => param_grid(&b.p, tol),
            FIn::Arc(a) => param_grid(&[a.at(0.0), a.at(0.5), a.at(1.0)], tol),
        }
    }
}

/// The nearest input point of all pieces: `(piece, u, distance)`.
fn nearest_input(input: &[FIn], p: DVec2) -> (usize, f64, f64) {
    let mut best = (0, 0.0, f64::INFINITY);
    for (j, b) in input.iter().enumerate() {
        if b.box_dist(p) >= best.2 {
            continue;
        }
        let (u, d) = b.nearest(p);
        if d < best.2 {
            best = (j, u, d);
        }
    }
    best
}

/// Every input piece is farther than `d` from `p` (floats: it only chooses
/// which witnesses are tried).
fn clear_of(input: &[FIn], p: DVec2, d: f64) -> bool {
    input
        .iter()
        .all(|b| b.box_dist(p) > d || b.nearest(p).1 > d)
}

/// A float outline piece.
enum FPiece {
    Bez(FBez),
    /// centre, radius, start angle, counter-clockwise sweep
    Arc(DVec2, f64, f64, f64),
}

impl FPiece {
    /// `(parameter or 0, distance)`.
    fn nearest(&self, p: DVec2) -> (f64, f64) {
        match self {
            FPiece::Bez(b) => b.nearest(p),
            FPiece::Arc(c, r, a0, sw) => {
                let v = p - *c;
                let a = (v.y.atan2(v.x) - a0).rem_euclid(std::f64::consts::TAU);
                if a <= *sw {
                    (0.0, (v.length() - r).abs())
                } else {
                    let e0 = *c + DVec2::new(a0.cos(), a0.sin()) * *r;
                    let e1 = *c + DVec2::new((a0 + sw).cos(), (a0 + sw).sin()) * *r;
                    (0.0, (p - e0).length().min((p - e1).length()))
                }
            }
        }
    }
    fn box_dist(&self, p: DVec2) -> f64 {
        match self {
            FPiece::Bez(b) => b.box_dist(p),
            FPiece::Arc(c, r, ..) => ((p - *c).length() - r).max(0.0),
        }
    }
}

fn v2(p: &Q2) -> DVec2 {
    DVec2::new(p[0].approx(), p[1].approx())
}

/// Why [`adaptive`] stopped: a step it could not shorten further (its
/// parameters), or an error of the step's test.
enum Stuck {
    At(f64, f64),
    Err(Error),
}

/// Covers `[0, 1]` by consecutive steps `[s0, s1]`, each accepted by `step`
/// (which returns the accepted step's bound, or `None`): the first about
/// `h0` long (at most `h_max`), each next one scaled by `√(0.8·tol / bound)`
/// of the last (between 1× and 2×; always 2× when `tol` is 0: the bound
/// does not tell how long a step may be), halved on a refusal, at most
/// `halvings` times in a row and never below `halvings` halvings of the
/// first. Steps end on a dyadic grid about 1/8 of their
/// length (short rationals in the certificate), the last at exactly 1. Only
/// the choice of the steps is here; every step is proven by `step`.
fn adaptive(
    h0: f64,
    h_max: f64,
    halvings: u32,
    tol: f64,
    mut step: impl FnMut(f64, f64) -> Result<Option<f64>, Error>,
) -> Result<(), Stuck> {
    let (mut s, mut h, mut fails) = (0.0f64, h0.clamp(f64::MIN_POSITIVE, h_max), 0u32);
    // no step shorter than `halvings` halvings of the first
    let h_min = h * 0.5f64.powi(halvings as i32);
    while s < 1.0 {
        let rem = 1.0 - s;
        // equal steps over what remains, so the last one is not a sliver
        let n = (rem / h).ceil().max(1.0);
        let len = rem / n;
        let s1 = if n <= 1.0 {
            1.0
        } else {
            let g = (2.0f64).powi(len.log2().floor() as i32 - 3);
            let t = ((s + len) / g).round() * g;
            if t > s && t < 1.0 {
                t
            } else {
                s + len
            }
        };
        if (n > 1.0 && len < h_min)
            || s1.partial_cmp(&s) != Some(std::cmp::Ordering::Greater)
            || s1 > 1.0
        {
            return Err(Stuck::At(s, s + len));
        }
        match step(s, s1).map_err(Stuck::Err)? {
            Some(b) => {
                let f = if b > 0.0 && tol > 0.0 {
                    (0.8 * tol / b).sqrt()
                } else {
                    2.0
                };
                // never shorter after a success: where the bound is mostly
                // not the step's (an outline farther than 0.8·tol from ∂S)
                // shrinking would go on and never reach 1
                h = ((s1 - s) * f.clamp(1.0, 2.0)).min(h_max);
                s = s1;
                fails = 0;
            }
            None => {
                fails += 1;
                if fails > halvings {
                    return Err(Stuck::At(s, s1));
                }
                h = 0.5 * (s1 - s);
            }
        }
    }
    Ok(())
}

struct Ctx<'a> {
    input: Input,
    fin: Vec<FIn>,
    outline: Vec<Vec<OPiece>>,
    fout: Vec<(usize, usize, FPiece)>,
    r: f64,
    tol: f64,
    tol_i: Interval,
    /// Claim (b)'s tolerance for its near tests (`tol_i`, or for an
    /// elliptical pen the stated `tol`, measured through `M`), and the
    /// pre-image distance within which outline candidates are sought.
    tol_b_i: Interval,
    near_tol: f64,
    _s: &'a Stroke,
}

impl Ctx<'_> {
    /// A first guess of a part's length: the disks' gaps to `∂S` grow like
    /// `(ℓ/2)²/(2r)` over a part of length `ℓ`, so parts of about `2√(tol·r)`
    /// fit within `tol` (longer ones are bisected).
    fn part_len(&self) -> f64 {
        2.0 * (self.tol * self.r).sqrt().max(self.tol)
    }

    /// The outline pieces within `lim` of `p`, nearest first (at most 3):
    /// `(contour, piece, parameter, distance)`.
    fn near_outline(&self, p: DVec2, lim: f64) -> Vec<(usize, usize, f64, f64)> {
        let mut all: Vec<(usize, usize, f64, f64)> = Vec::new();
        for (c, i, f) in &self.fout {
            if f.box_dist(p) >= lim {
                continue;
            }
            let (s, d) = f.nearest(p);
            if d < lim {
                all.push((*c, *i, s, d));
            }
        }
        all.sort_by(|a, b| a.3.total_cmp(&b.3));
        all.truncate(3);
        all
    }

    /// Candidate sets for a part whose middle is `m`: the input point `y`
    /// nearest to `m` (the disk `B(y, r)`; first the capsule about the whole
    /// piece when that piece is straight, with larger disks outside, since a
    /// capsule's gap does not grow along it), and disks `B(w, μ)` outside `S`
    /// along the normal through `m`, largest first; with `corners`, only
    /// points (`μ = 0`) around `m`, for a corner of `∂S` (tried when the
    /// others fail).
    fn witnesses(&self, m: DVec2, corners: bool) -> Vec<(Inside, DVec2, f64)> {
        let (j, u, d) = nearest_input(&self.fin, m);
        let y = self.fin[j].at(u);
        if d <= 0.0 {
            return vec![];
        }
        let n = (m - y) / d;
        let gap = self.tol / 64.0;
        let mut ws = Vec::new();
        let outside = |mu: f64| {
            let w = y + n * (self.r + mu + gap);
            clear_of(&self.fin, w, self.r + mu + 0.5 * gap).then_some(w)
        };
        if self.input.straight[j] && !corners {
            for mu in [64.0 * self.r, 16.0 * self.r, 4.0 * self.r, self.r] {
                if let Some(w) = outside(mu) {
                    ws.push((Inside::Segment { piece: j }, w, mu));
                }
            }
        }
        // (the nearest point's parameter is a finite float in [0, 1])
        let Ok(uq) = q(snap(u, self.fin[j].grid(self.tol))) else {
            return ws;
        };
        let disk = |w, mu| {
            (
                Inside::Disk {
                    piece: j,
                    u: uq.clone(),
                },
                w,
                mu,
            )
        };
        // the largest disk outside first (its gap to a curved `∂S` shrinks
        // as μ grows): the largest of a ladder that the float test accepts,
        // raised by bisection towards the next one, rounded down to 6 bits
        let ladder = [
            4.0 * self.r,
            self.r,
            self.r / 4.0,
            self.r / 16.0,
            4.0 * self.tol,
            self.tol / 4.0,
        ];
        if corners {
            for rho in [self.tol / 16.0, self.tol / 4.0] {
                for k in 0..16 {
                    let a = k as f64 * std::f64::consts::TAU / 16.0;
                    let w = m + DVec2::new(a.cos(), a.sin()) * rho;
                    if clear_of(&self.fin, w, self.r + 0.25 * gap) {
                        ws.push(disk(w, 0.0));
                    }
                }
            }
            return ws;
        }
        if let Some(k) = ladder.iter().position(|mu| outside(*mu).is_some()) {
            let (mut lo, mut hi) = (ladder[k], if k > 0 { ladder[k - 1] } else { ladder[0] });
            for _ in 0..6 {
                let m = 0.5 * (lo + hi);
                if outside(m).is_some() {
                    lo = m;
                } else {
                    hi = m;
                }
            }
            let e = (2.0f64).powi(lo.log2().floor() as i32 - 5);
            let mu = (lo / e).floor() * e;
            if mu > ladder[k] {
                if let Some(w) = outside(mu) {
                    ws.push(disk(w, mu));
                }
            }
            for mu in &ladder[k..] {
                if let Some(w) = outside(*mu) {
                    ws.push(disk(w, *mu));
                }
            }
        }
        ws
    }

    /// One part (hull given): tries the disks; the JSON part on success.
    fn try_part(
        &self,
        hull: &crate::certify::verify::stroke::geom::Hull,
        m: DVec2,
        key: (&str, Value),
    ) -> Result<Option<(Value, f64)>, Error> {
        // at most 16 tries: the disks first, then the corner points
        let first = self.witnesses(m, false);
        let n = first.len().min(16);
        let rest = || self.witnesses(m, true).into_iter().take(16 - n);
        for (inside, w, mu) in first
            .into_iter()
            .take(16)
            .chain(std::iter::once(()).flat_map(|()| rest()))
        {
            let g = coord_grid(self.tol);
            let (wq, wv) = ptf(DVec2::new(snap(w.x, g), snap(w.y, g)))?;
            let muq = q(mu)?;
            if let Ok(b) = check_part(&self.input, hull, &inside, &wq, &muq, self.tol_i) {
                let o = match &inside {
                    Inside::Disk { piece, u } => json!({"piece": piece, "u": qs(u)}),
                    Inside::Segment { piece } => json!({"segment": piece}),
                };
                let mut v = json!({
                    "o": o,
                    "w": {"at": wv, "mu": qs(&muq)},
                });
                v.as_object_mut()
                    .expect("object")
                    .insert(key.0.into(), key.1);
                return Ok(Some((v, b)));
            }
        }
        Ok(None)
    }

    fn cover_bezier(
        &self,
        iv: &crate::certify::verify::stroke::geom::Bez,
        f: &FBez,
    ) -> Result<Vec<Value>, Error> {
        let len: f64 = f.p.windows(2).map(|w| (w[1] - w[0]).length()).sum();
        // a straight piece may be one part (a capsule inside, a large disk
        // outside); halved where that fails
        let chord = f.p[f.p.len() - 1] - f.p[0];
        let straight = chord.length() > 0.0
            && f.p
                .iter()
                .all(|p| (*p - f.p[0]).perp_dot(chord).abs() <= 1e-9 * chord.length_squared());
        let h0 = if straight {
            1.0
        } else {
            (self.part_len() / len).min(1.0)
        };
        let mut out = Vec::new();
        adaptive(h0, 1.0, 24, self.tol, |s0, s1| {
            let hull = iv.restrict(point_iv(s0), point_iv(s1));
            let m = bez_at(&f.p, 0.5 * (s0 + s1));
            let s = json!([qs(&q(s0)?), qs(&q(s1)?)]);
            Ok(self.try_part(&hull, m, ("s", s))?.map(|(v, b)| {
                out.push(v);
                b
            }))
        })
        .map_err(|e| match e {
            Stuck::At(s0, s1) => {
                let m = bez_at(&f.p, 0.5 * (s0 + s1));
                err(format!(
                    "no witnesses for the outline part [{s0}, {s1}] near ({}, {})",
                    m.x, m.y
                ))
            }
            Stuck::Err(e) => e,
        })?;
        Ok(out)
    }

    /// The parts of an arc, counter-clockwise from `u` to `v` (radius
    /// vectors); `c`, `rho`: its float centre and radius; `t`: its enclosure.
    fn cover_arc(
        &self,
        (u, v): (&Q2, &Q2),
        c: DVec2,
        rho: f64,
        t: &crate::certify::verify::stroke::geom::ArcT,
    ) -> Result<Vec<Value>, Error> {
        let (rho_i, full) = (t.rho, t.full);
        let a0 = v2(u).y.atan2(v2(u).x);
        let a1 = v2(v).y.atan2(v2(v).x);
        let mut sweep = (a1 - a0).rem_euclid(std::f64::consts::TAU);
        if full || sweep == 0.0 {
            sweep = std::f64::consts::TAU;
        }
        // a part turns by less than π/2 (checked): at most π/2.2 here
        let h_max = (std::f64::consts::PI / 2.2 / sweep).min(1.0);
        let h0 = (self.part_len() / (sweep * rho)).min(h_max);
        // directions: the exact ends, floats between
        let dir = |s: f64| -> Result<Q2, Error> {
            if s == 0.0 {
                return Ok(u.clone());
            }
            if s == 1.0 {
                return Ok(v.clone());
            }
            let a = a0 + sweep * s;
            Ok([q(a.cos())?, q(a.sin())?])
        };
        let mut out = Vec::new();
        let mut d0 = u.clone();
        adaptive(h0, h_max, 24, self.tol, |s0, s1| {
            let d1 = dir(s1)?;
            let hull = arc_hull(t.c, rho_i, ip(&d0), ip(&d1))
                .ok_or_else(|| err("an arc part's hull is not finite"))?;
            let am = a0 + sweep * 0.5 * (s0 + s1);
            let m = c + DVec2::new(am.cos(), am.sin()) * rho;
            let dv = json!([pt(&d0), pt(&d1)]);
            Ok(self.try_part(&hull, m, ("dirs", dv))?.map(|(v, b)| {
                out.push(v);
                d0 = d1;
                b
            }))
        })
        .map_err(|e| match e {
            Stuck::At(s0, s1) => {
                let am = a0 + sweep * 0.5 * (s0 + s1);
                let m = c + DVec2::new(am.cos(), am.sin()) * rho;
                err(format!(
                    "no witnesses for an arc part near ({}, {})",
                    m.x, m.y
                ))
            }
            Stuck::Err(e) => e,
        })?;
        Ok(out)
    }

    /// The boxes of one family of `∂S`.
    fn family_boxes(&self, path: &dyn Path) -> Result<Vec<Value>, Error> {
        let fval = |t: f64| {
            path.val(point_iv(t))
                .map(|p| DVec2::new(mid(p[0]), mid(p[1])))
        };
        // initial boxes: about tol·64 long, at least 4, a power of two
        let mut len = 0.0;
        let mut prev =
            fval(0.0).ok_or_else(|| err("the boundary is undefined (a singular input piece?)"))?;
        for k in 1..=32 {
            let p = fval(k as f64 / 32.0)
                .ok_or_else(|| err("the boundary is undefined (a singular input piece?)"))?;
            len += (p - prev).length();
            prev = p;
        }
        // boxes start about 128·tol long, double after each success and
        // halve after a refusal (a box's bound does not grow with its length
        // as a part's does)
        let h0 = (128.0 * self.tol / len).min(0.5);
        let mut out = Vec::new();
        adaptive(h0, 1.0, 44, 0.0, |t0, t1| {
            let (q0, q1) = (q(t0)?, q(t1)?);
            let bx = BoxT::new(&q0, &q1);
            let tv = json!([qs(&q0), qs(&q1)]);
            Ok(self
                .one_box(path, &bx, 0.5 * (t0 + t1), fval(0.5 * (t0 + t1)))?
                .map(|(mut v, b)| {
                    v.as_object_mut().expect("object").insert("t".into(), tv);
                    out.push(v);
                    b
                }))
        })
        .map_err(|e| match e {
            Stuck::At(t0, _) => {
                let p = fval(t0).unwrap_or(DVec2::NAN);
                let near = self.near_outline(p, f64::INFINITY);
                let (_, _, d_in) = nearest_input(&self.fin, p);
                err(format!(
                    "the boundary near parameter {t0}, at ({:.6}, {:.6}), is neither proven near the outline nor inside the stroke (outline {:.3e} away, input {:.6e} for r {})",
                    p.x,
                    p.y,
                    near.first().map_or(f64::INFINITY, |n| n.3),
                    d_in,
                    self.r
                ))
            }
            Stuck::Err(e) => e,
        })?;
        Ok(out)
    }

    fn one_box(
        &self,
        path: &dyn Path,
        bx: &BoxT,
        tm: f64,
        p: Option<DVec2>,
    ) -> Result<Option<(Value, f64)>, Error> {
        let Some(p) = p else { return Ok(None) };
        let mut tries: Vec<(BBox, Value)> = Vec::new();
        let near = self.near_outline(p, self.near_tol);
        let (j, u, d_in) = nearest_input(&self.fin, p);
        let inside_first =
            d_in < self.r * (1.0 - 1e-12) && near.first().is_none_or(|n| n.3 > 0.5 * self.near_tol);
        let mut inside_try = Vec::new();
        if d_in < self.r {
            let uq = q(snap(u, self.fin[j].grid(self.tol)))?;
            inside_try.push((
                BBox::Inside {
                    piece: j,
                    u: uq.clone(),
                },
                json!({"inside": {"piece": j, "u": qs(&uq)}}),
            ));
        }
        let mut near_try = Vec::new();
        for (c, i, s, _) in near {
            {
                match &self.outline[c][i] {
                    OPiece::Bezier { .. } => {
                        let FPiece::Bez(f) = &self
                            .fout
                            .iter()
                            .find(|x| x.0 == c && x.1 == i)
                            .expect("piece")
                            .2
                        else {
                            unreachable!()
                        };
                        let dp = path
                            .der(point_iv(tm))
                            .map(|v| DVec2::new(mid(v[0]), mid(v[1])))
                            .unwrap_or(DVec2::ZERO);
                        let dl = bez_at(&f.d, s);
                        let k = if dl.length_squared() > 0.0 {
                            dp.dot(dl) / dl.length_squared()
                        } else {
                            0.0
                        };
                        // the foot map must stay in [0, 1] over the box
                        // (with room for the enclosure's rounding)
                        let width = bx.all.sup() - bx.all.inf();
                        let reach = |k: f64| k.abs() * 0.5 * width * (1.0 + 1e-9) + 1e-15;
                        let clamp = |s: f64, k: f64| {
                            let r = reach(k);
                            if r < 0.5 {
                                s.clamp(r, 1.0 - r)
                            } else {
                                s
                            }
                        };
                        // first short numbers: `k` to 20 bits, `s` to the
                        // piece's parameter grid, moved inward by whole
                        // steps where the clamp needs it (fewer digits to
                        // write and read); then the full floats, which the
                        // clamp alone keeps in [0, 1]
                        let g = param_grid(&f.p, self.tol);
                        let kr = round_bits(k, 20);
                        let sr = {
                            let (r, x) = (reach(kr), snap(s, g));
                            if r >= 0.5 {
                                x
                            } else if x < r {
                                (r / g).ceil() * g
                            } else if x > 1.0 - r {
                                ((1.0 - r) / g).floor() * g
                            } else {
                                x
                            }
                        };
                        let full = (clamp(s, k), k);
                        let short = (sr, kr);
                        let tries = if short == full {
                            vec![full]
                        } else {
                            vec![short, full]
                        };
                        for (s, k) in tries {
                            let (sq, kq) = (q(s)?, q(k)?);
                            near_try.push((
                                BBox::NearBezier {
                                    contour: c,
                                    piece: i,
                                    s: sq.clone(),
                                    k: kq.clone(),
                                },
                                json!({"near": {"contour": c, "piece": i, "s": qs(&sq), "k": qs(&kq)}}),
                            ));
                        }
                    }
                    OPiece::Arc { .. } => near_try.push((
                        BBox::NearArc {
                            contour: c,
                            piece: i,
                        },
                        json!({"near": {"contour": c, "piece": i}}),
                    )),
                }
            }
        }
        if inside_first {
            tries.extend(inside_try);
            tries.extend(near_try);
        } else {
            tries.extend(near_try);
            tries.extend(inside_try);
        }
        for (what, v) in tries {
            if let Ok(b) = check_bbox(path, bx, &what, &self.outline, &self.input, self.tol_b_i) {
                return Ok(Some((v, b)));
            }
        }
        Ok(None)
    }
}

/// The stroke certificate of a proven stroke outline `s` of `curve` with the
/// circular pen of radius `radius`, at the stroke's tolerance: a JSON
/// document that [`crate::certify::verify::verify`] checks on its own.
///
/// For an elliptical pen `E = M · disk(1)` (`s.pen`; `radius` is not used)
/// the certificate states `d_H(L, ∂(x ⊕ E)) ≤ tol` with the exact matrix `M`
/// (key `"pen"`); its parts and boxes are those of the disk certificate of
/// the pre-images `M⁻¹L`, `M⁻¹x` at `tol / ‖M‖₂` (rounded down), since
/// `x ⊕ E = M (M⁻¹x ⊕ disk(1))` (`proofs/stroke-certificate.md`,
/// "Elliptical pens"). The outline must then be Bézier pieces only (the
/// elliptical pen's caps are).
///
/// Errors (field `certificate`): claims (a) or (c) not proven, an arc with
/// equal ends, or a part or box the tests cannot decide within their depth
/// (for an elliptical pen: the pre-image is farther than `tol / ‖M‖₂` from
/// its stroke — stroke at a smaller tolerance).
///
/// # Examples
/// ```
/// use lncert::stroke::{certificate, stroke, StrokeOptions};
/// use lncert::{parse_curve, parse_rational};
/// # fn main() -> Result<(), lncert::Error> {
/// let x = parse_curve("M 0 0 L 4 0")?;
/// let r = parse_rational("1")?;
/// let s = stroke(&x, &StrokeOptions::new(r.clone(), "1e-2".parse()?))?;
/// let cert = certificate(&x, &s, &r)?;
/// let valid = lncert::certify::verify::verify(&cert.to_string()).unwrap();
/// assert!(valid.max_bound <= 1e-2);
/// # Ok(())
/// # }
/// ```
pub fn certificate(
    curve: &[Bezier<Rational>],
    s: &Stroke,
    radius: &Rational,
) -> Result<Value, Error> {
    if let Some(pen) = &s.pen {
        return ellipse_certificate(curve, s, pen);
    }
    let pieces: Vec<CurvePiece> = curve
        .iter()
        .map(|b| CurvePiece::Bezier(exact_points(b)))
        .collect();
    disk_certificate(&pieces, s, radius, None)
}

/// [`certificate`] of an outline `s` against an exact path of Bézier pieces
/// and circular arcs (each arc is split where it turns by more than a
/// quarter, at rational points of its circle; the certificate's `curve`
/// states the pieces so split). A circular pen only.
///
/// # Examples
/// ```
/// use lncert::stroke::{certificate_path, parse_path, stroke_path, StrokeOptions};
/// # fn main() -> Result<(), lncert::Error> {
/// // a half circle of radius 2 and its diameter, read exactly
/// let (path, _) = parse_path("M 2 0 A 2 2 0 0 1 -2 0 L 2 0")?;
/// let r = lncert::parse_rational("1/2")?;
/// let s = stroke_path(&path, &StrokeOptions::new(r.clone(), "1e-2".parse()?))?;
/// assert!(s.proven());
/// let cert = certificate_path(&path, &s, &r)?;
/// let valid = lncert::certify::verify::verify(&cert.to_string()).unwrap();
/// assert!(valid.max_bound <= 1e-2);
/// # Ok(())
/// # }
/// ```
pub fn certificate_path(
    path: &[super::PathPiece],
    s: &Stroke,
    radius: &Rational,
) -> Result<Value, Error> {
    if s.pen.is_some() {
        return Err(err(
            "an exact path with arcs is certified with a circular pen only",
        ));
    }
    if !(s.a.proven && s.b.proven) {
        return Err(err(
            "the stroke is not proven: no certificate is written for an unproven outline",
        ));
    }
    certificate_unproven(path, s, radius)
}

/// [`certificate`] for a disk pen; with `metric = (M, tol)`, of the
/// pre-images `curve = M⁻¹x`, `s = M⁻¹L` (radius 1, `s.tol = t′`), claim
/// (b)'s near tests measured through `M` at the stated `tol`.
fn disk_certificate(
    curve: &[CurvePiece],
    s: &Stroke,
    radius: &Rational,
    metric: Option<(&PenMap, &Rational)>,
) -> Result<Value, Error> {
    if !(s.a.proven && s.b.proven && s.c.proven) {
        return Err(err(
            "the stroke is not proven: no certificate is written for an unproven outline",
        ));
    }
    outline_certificate(curve, s, radius, metric)
}

/// [`certificate_path`] of an outline whose claims (a) and (b) are still to
/// be proven, by this certificate once the verifier accepts it (the exact
/// construction of [`super::lines_arcs`]); claim (c) must be proven.
pub(crate) fn certificate_unproven(
    path: &[super::PathPiece],
    s: &Stroke,
    radius: &Rational,
) -> Result<Value, Error> {
    if !s.c.proven {
        return Err(err("claim (c) is not proven: no certificate is written"));
    }
    let pieces = super::path::curve_pieces(path).map_err(|e| err(e.reason))?;
    outline_certificate(&pieces, s, radius, None)
}

/// The certificate's parts and boxes for the outline `s` (see
/// [`disk_certificate`]), whatever the stroke's claims say.
fn outline_certificate(
    curve: &[CurvePiece],
    s: &Stroke,
    radius: &Rational,
    metric: Option<(&PenMap, &Rational)>,
) -> Result<Value, Error> {
    let mut input = Input::with_pieces(curve.to_vec(), radius.clone(), "curve")
        .map_err(|e| err(e.to_string()))?;
    input.metric = metric.map(|(m, _)| m.metric());
    let fin: Vec<FIn> = curve.iter().map(FIn::new).collect();
    let mut outline = Vec::new();
    let mut fout = Vec::new();
    let mut outline_json = Vec::new();
    for (ci, c) in s.contours.iter().enumerate() {
        let mut ps = Vec::new();
        let mut js = Vec::new();
        for (i, p) in c.pieces.iter().enumerate() {
            match p {
                Piece::Bezier(b) => {
                    let e: Vec<Q2> = exact_points(b);
                    js.push(json!({"bezier": e.iter().map(pt).collect::<Vec<_>>()}));
                    fout.push((ci, i, FPiece::Bez(FBez::new(e.iter().map(v2).collect()))));
                    ps.push(OPiece::bezier(e));
                }
                Piece::Arc(a) => {
                    if a.from == a.to {
                        return Err(err("an outline arc with equal ends"));
                    }
                    let cq = [a.center.x.clone(), a.center.y.clone()];
                    let from = [a.from.x.clone(), a.from.y.clone()];
                    let to = [a.to.x.clone(), a.to.y.clone()];
                    js.push(json!({"arc": {"center": pt(&cq), "radius": qs(&a.radius), "from": pt(&from), "to": pt(&to), "clockwise": a.clockwise}}));
                    let op = OPiece::arc(cq.clone(), a.radius.clone(), from, to, a.clockwise)
                        .map_err(err)?;
                    let OPiece::Arc { ccw_u, ccw_v, .. } = &op else {
                        unreachable!()
                    };
                    let a0 = v2(ccw_u).y.atan2(v2(ccw_u).x);
                    let a1 = v2(ccw_v).y.atan2(v2(ccw_v).x);
                    let sw = (a1 - a0).rem_euclid(std::f64::consts::TAU);
                    fout.push((ci, i, FPiece::Arc(v2(&cq), a.radius.approx(), a0, sw)));
                    ps.push(op);
                }
            }
        }
        outline.push(ps);
        outline_json.push(Value::Array(js));
    }
    let tol_q = s.tol.exact().clone();
    let ctx = Ctx {
        input,
        fin,
        outline,
        fout,
        r: radius.approx(),
        tol: s.tol.value(),
        tol_i: iq(&tol_q),
        tol_b_i: metric.map_or_else(|| iq(&tol_q), |(_, t)| iq(t)),
        // ‖M⁻¹‖₂ ≤ ‖M⁻¹‖_F: a pre-image distance that may be within tol
        near_tol: metric.map_or(s.tol.value(), |(m, t)| {
            let f: f64 = m.inv.iter().flatten().map(|x| x.approx().powi(2)).sum();
            t.approx() * f.sqrt()
        }),
        _s: s,
    };
    // (a)
    let jobs: Vec<(usize, usize)> = ctx
        .outline
        .iter()
        .enumerate()
        .flat_map(|(c, ps)| (0..ps.len()).map(move |i| (c, i)))
        .collect();
    let covers: Vec<Result<Vec<Value>, Error>> = jobs
        .par_iter()
        .map(|&(c, i)| match &ctx.outline[c][i] {
            OPiece::Bezier { iv, .. } => {
                let f = match &ctx
                    .fout
                    .iter()
                    .find(|x| x.0 == c && x.1 == i)
                    .expect("piece")
                    .2
                {
                    FPiece::Bez(f) => f,
                    FPiece::Arc(..) => unreachable!(),
                };
                ctx.cover_bezier(iv, f)
            }
            OPiece::Arc {
                ccw_u, ccw_v, t, ..
            } => {
                let (cc, rho) = match &ctx
                    .fout
                    .iter()
                    .find(|x| x.0 == c && x.1 == i)
                    .expect("piece")
                    .2
                {
                    FPiece::Arc(cc, rho, ..) => (*cc, *rho),
                    FPiece::Bez(_) => unreachable!(),
                };
                ctx.cover_arc((ccw_u, ccw_v), cc, rho, t)
            }
        })
        .collect();
    let mut cover: Vec<Vec<Value>> = ctx.outline.iter().map(|_| Vec::new()).collect();
    let mut spans: Vec<Vec<Vec<Span>>> = ctx.outline.iter().map(|_| Vec::new()).collect();
    for ((c, _), v) in jobs.iter().zip(covers) {
        let v = v?;
        spans[*c].push(v.iter().map(span_of).collect::<Result<_, _>>()?);
        cover[*c].push(Value::Array(v));
    }
    // claim (c), as the verifier will check it
    let simple = crate::certify::verify::stroke::simple_check(&ctx.outline, &spans).is_ok();
    // (b)
    let fams = ctx.input.families();
    let boundary: Vec<Result<Value, Error>> = fams
        .par_iter()
        .map(|f| {
            let boxes = ctx
                .family_boxes(&*f.path)
                .map_err(|e| err(format!("{}: {}", f.name, e.reason)))?;
            Ok(json!({"of": f.name, "boxes": boxes}))
        })
        .collect();
    let boundary: Vec<Value> = boundary.into_iter().collect::<Result<_, _>>()?;
    Ok(json!({
        "format": FORMAT,
        "version": VERSION,
        "claim": CLAIM,
        "tol": qs(&tol_q),
        "radius": qs(radius),
        "curve": curve.iter().map(curve_json).collect::<Vec<_>>(),
        "outline": outline_json,
        "cover": cover,
        "boundary": boundary,
        "simple": simple,
    }))
}

/// One input piece as the certificate states it.
fn curve_json(p: &CurvePiece) -> Value {
    match p {
        CurvePiece::Bezier(p) => Value::Array(p.iter().map(pt).collect()),
        CurvePiece::Arc {
            c,
            rho,
            from,
            to,
            clockwise,
        } => {
            json!({"arc": {"center": pt(c), "radius": qs(rho), "from": pt(from), "to": pt(to), "clockwise": clockwise}})
        }
    }
}

/// The certificate of an elliptical pen's stroke `∂(x ⊕ M·disk(1))`: since
/// `x ⊕ M·disk(1) = M (M⁻¹x ⊕ disk(1))`, the disk certificate of the
/// pre-image outline `M⁻¹L` of the curve `M⁻¹x` at `t′` (`‖M‖₂ t′ ≤ tol`,
/// [`PenMap::pre_tol`]), stated about `x`, `M` and `L` themselves: the
/// verifier maps them exactly and checks the same parts and boxes.
fn ellipse_certificate(
    curve: &[Bezier<Rational>],
    s: &Stroke,
    pen: &crate::offset::Pen,
) -> Result<Value, Error> {
    let m = [
        [pen.m[0][0].clone(), pen.m[0][1].clone()],
        [pen.m[1][0].clone(), pen.m[1][1].clone()],
    ];
    let map = PenMap::new(m.clone()).ok_or_else(|| err("a singular pen matrix"))?;
    let tol_q = s.tol.exact().clone();
    let t = map
        .pre_tol(&tol_q)
        .ok_or_else(|| err("tol / ‖M‖₂ underflows"))?;
    let pre_bez = |b: &Bezier<Rational>| {
        Bezier::new(
            exact_points(b)
                .iter()
                .map(|q| {
                    let [x, y] = map.pre(q);
                    crate::curve::V2::new(x, y)
                })
                .collect(),
        )
    };
    let mut pre = s.clone();
    pre.pen = None;
    pre.tol = crate::Tolerance::new(t).map_err(|e| err(e.to_string()))?;
    let mut outline_json = Vec::new();
    for (ci, c) in pre.contours.iter_mut().enumerate() {
        let mut js = Vec::new();
        for (i, p) in c.pieces.iter_mut().enumerate() {
            let Piece::Bezier(b) = p else {
                return Err(err(format!(
                    "outline[{ci}][{i}]: an exact circular arc in an elliptical pen's outline"
                )));
            };
            js.push(json!({"bezier": exact_points(b).iter().map(pt).collect::<Vec<_>>()}));
            *b = pre_bez(b);
        }
        outline_json.push(Value::Array(js));
    }
    let pre_curve: Vec<CurvePiece> = curve
        .iter()
        .map(|b| CurvePiece::Bezier(exact_points(&pre_bez(b))))
        .collect();
    let one = Rational::from_integer(1.into());
    let mut doc = disk_certificate(&pre_curve, &pre, &one, Some((&map, &tol_q)))?;
    let o = doc.as_object_mut().expect("the writer writes an object");
    o.remove("radius");
    o.insert("claim".into(), json!(CLAIM_ELLIPSE));
    o.insert("tol".into(), qs(&tol_q));
    o.insert("pen".into(), json!({"ellipse": [pt(&m[0]), pt(&m[1])]}));
    o.insert(
        "curve".into(),
        json!(curve
            .iter()
            .map(|b| exact_points(b).iter().map(pt).collect::<Vec<_>>())
            .collect::<Vec<_>>()),
    );
    o.insert("outline".into(), Value::Array(outline_json));
    Ok(doc)
}

/// A set of stroke certificates (format
/// [`crate::certify::verify::stroke::SET_FORMAT`]): one per stroked element,
/// each `(label, certificate)` — e.g. the elements of an SVG document, each
/// with its own pen. `verify` checks every member on its own.
///
/// # Examples
/// ```
/// use lncert::stroke::{certificate, certificate_set, stroke, StrokeOptions};
/// use lncert::{parse_curve, parse_rational};
/// # fn main() -> Result<(), lncert::Error> {
/// let mut members = Vec::new();
/// for (path, r) in [("M 0 0 L 4 0", "1/2"), ("M 0 3 L 4 3", "1/4")] {
///     let (x, r) = (parse_curve(path)?, parse_rational(r)?);
///     let s = stroke(&x, &StrokeOptions::new(r.clone(), "1e-2".parse()?))?;
///     members.push((path.to_string(), certificate(&x, &s, &r)?));
/// }
/// let set = certificate_set(members);
/// let valid = lncert::certify::verify::verify(&set.to_string()).unwrap();
/// assert!(valid.a.contains("2 stroked element(s)"));
/// # Ok(())
/// # }
/// ```
pub fn certificate_set(members: Vec<(String, Value)>) -> Value {
    use crate::certify::verify::stroke::{SET_CLAIM, SET_FORMAT};
    json!({
        "format": SET_FORMAT,
        "version": VERSION,
        "claim": SET_CLAIM,
        "members": members
            .into_iter()
            .map(|(at, c)| json!({"at": at, "certificate": c}))
            .collect::<Vec<_>>(),
    })
}

/// The range of a written part, read back exactly.
fn span_of(v: &Value) -> Result<Span, Error> {
    let r = |x: &Value| {
        crate::parse_rational(x.as_str().unwrap_or_default()).map_err(|e| err(e.reason))
    };
    if let Some(s) = v.get("s") {
        return Ok(Span::Bez(r(&s[0])?, r(&s[1])?));
    }
    let d = &v["dirs"];
    Ok(Span::arc(
        [r(&d[0][0])?, r(&d[0][1])?],
        [r(&d[1][0])?, r(&d[1][1])?],
    ))
}

/// The stroke distance certificate of `d_H(x, ∂S) ≤ tol` (format
/// [`crate::certify::verify::stroke::DISTANCE_FORMAT`]) from a referee's run
/// ([`super::distance_to_stroke`], [`super::distance_through`]): a Hausdorff
/// certificate of `d_H(x, L) ≤ tol − E` from the run's outline search and the
/// stroke certificate of `d_H(L, ∂S) ≤ E`, `E` the stroke's tolerance.
///
/// Errors (field `certificate`): the stroke is not proven, `tol ≤ E`, the
/// outline search's bounds exceed `tol − E` (or it stopped early), or
/// [`certificate`]'s errors.
///
/// # Examples
/// ```
/// use lncert::certify::Config;
/// use lncert::shape::ShapeDesc;
/// use lncert::stroke::{distance_certificate, distance_to_stroke, StrokeOptions};
/// use lncert::{parse_curve, parse_rational};
/// # fn main() -> Result<(), lncert::Error> {
/// let curve = parse_curve("M 0 0 L 4 0")?;
/// let r = parse_rational("1/2")?;
/// // a rectangle 0.01 outside the stadium's sides, its corners off the caps
/// let x = ShapeDesc::parse("M -0.5 -0.51 L 4.5 -0.51 L 4.5 0.51 L -0.5 0.51 Z")?;
/// let d = distance_to_stroke(&x, &curve, &StrokeOptions::new(r.clone(), "1e-2".parse()?), &Config::default())?;
/// let tol: lncert::Tolerance = "1/4".parse()?;
/// let cert = distance_certificate(&x, &d, &curve, &r, &tol)?;
/// let v = lncert::certify::verify::verify(&cert.to_string()).unwrap();
/// assert_eq!(v.tol, parse_rational("1/4")?);
/// # Ok(())
/// # }
/// ```
pub fn distance_certificate(
    x: &crate::shape::ShapeDesc,
    d: &super::StrokeDistance,
    curve: &[Bezier<Rational>],
    radius: &Rational,
    tol: &crate::Tolerance,
) -> Result<Value, Error> {
    use crate::certify::verify::stroke::{DISTANCE_CLAIM, DISTANCE_CLAIM_ELLIPSE, DISTANCE_FORMAT};
    let h = d
        .outline
        .as_ref()
        .ok_or_else(|| err("the stroke is not proven: no outline to go through"))?;
    if h.incomplete() {
        return Err(err(
            "the outline search stopped before its gap (its budget)",
        ));
    }
    let e = d.stroke.tol.exact().clone();
    let th = tol.exact() - &e;
    let th = crate::Tolerance::new(th).map_err(|_| {
        err(format!(
            "the stroke's tolerance {e} is not below the claimed {}",
            tol.exact()
        ))
    })?;
    let l = d.stroke.outline_shape().map_err(|e| err(e.to_string()))?;
    let ch = crate::certify::Certificate::new(x, &l, &th, h).ok_or_else(|| {
        err(format!(
            "the outline search proves d_H(shape, outline) ≤ {:e}, above TOL − E = {}",
            h.hi,
            th.exact()
        ))
    })?;
    // a stroke proven against exact arcs carries its certificate (at E)
    let cs = match &d.stroke.certificate {
        Some(c) => c.as_ref().clone(),
        None => certificate(curve, &d.stroke, radius)?,
    };
    Ok(json!({
        "format": DISTANCE_FORMAT,
        "version": VERSION,
        "claim": if d.stroke.pen.is_some() { DISTANCE_CLAIM_ELLIPSE } else { DISTANCE_CLAIM },
        "tol": qs(tol.exact()),
        "shape_to_outline": ch.doc,
        "outline_to_stroke": cs,
    }))
}

#[cfg(test)]
mod tests {
    #[test]
    fn short_numbers_keep_twenty_bits_and_leave_zero_alone() {
        use super::round_bits;
        for x in [0.0, -0.0, f64::MIN_POSITIVE / 4.0, f64::INFINITY, f64::NAN] {
            assert!(round_bits(x, 20).to_bits() == x.to_bits() || x.is_nan());
        }
        for x in [1.0 / 3.0, -1.000_001_7, 12_345.678_9, 3e-300, 1.7e308] {
            let r = round_bits(x, 20);
            assert!(((r - x) / x).abs() <= 2f64.powi(-20), "{x} -> {r}");
            // a multiple of 2^(e − 20): at most 21 significant bits
            let m = r / 2f64.powi(x.abs().log2().floor() as i32 - 20);
            assert_eq!(m, m.round(), "{x} -> {r}");
        }
    }

    use super::{adaptive, Stuck};

    /// The steps of `adaptive`, or where it stopped.
    fn run(
        h0: f64,
        tol: f64,
        mut step: impl FnMut(f64, f64) -> Option<f64>,
    ) -> Result<Vec<(f64, f64)>, (f64, f64)> {
        let mut out = Vec::new();
        adaptive(h0, 1.0, 24, tol, |a, b| {
            let r = step(a, b);
            if r.is_some() {
                out.push((a, b));
            }
            Ok(r)
        })
        .map_err(|e| match e {
            Stuck::At(a, b) => (a, b),
            Stuck::Err(_) => unreachable!(),
        })?;
        Ok(out)
    }

    fn chained(steps: &[(f64, f64)]) -> bool {
        steps.first().is_some_and(|s| s.0 == 0.0)
            && steps.last().is_some_and(|s| s.1 == 1.0)
            && steps
                .windows(2)
                .all(|w| w[0].1 == w[1].0 && w[0].0 < w[0].1)
    }

    /// A bound that grows like the step's square: the steps chain from 0 to
    /// exactly 1, each accepted one within the test's limit, and they come
    /// within a factor of two of the fewest that limit allows.
    #[test]
    fn steps_chain_over_the_unit_interval_and_grow_to_the_limit() {
        let tol = 1e-2;
        for h0 in [1e-3, 0.01, 0.3] {
            let steps = run(h0, tol, |a, b| {
                let bound = 4.0 * (b - a) * (b - a);
                (bound <= tol).then_some(bound)
            })
            .expect("covered");
            assert!(chained(&steps), "h0 {h0}: {steps:?}");
            // bound ≤ tol ⇔ step ≤ 0.05: at least 20 steps, not many more
            assert!(
                steps.len() >= 20 && steps.len() <= 40,
                "h0 {h0}: {} steps",
                steps.len()
            );
        }
    }

    /// A bound that does not depend on the step (an outline at 0.9·tol from
    /// ∂S everywhere): the steps must not shrink after each success, which
    /// never reaches 1 (the step sizes then sum to a finite limit).
    #[test]
    fn a_bound_that_does_not_shrink_with_the_step_still_covers() {
        let steps = run(0.01, 1.0, |a, b| (b - a <= 0.25).then_some(0.9)).expect("covered");
        assert!(chained(&steps));
        // the first step's length kept: about 1/h0 steps
        assert!(steps.len() <= 110, "{} steps", steps.len());
    }

    /// A point no step may touch: `adaptive` closes in on it, down to
    /// `h0·2⁻²⁴`, and stops there, naming where.
    #[test]
    fn an_undecidable_point_stops_the_steps_there() {
        let p = 0.3 + 1e-7;
        let r = run(0.1, 1e-2, |a, b| (!(a <= p && b >= p)).then_some(1e-3));
        let (a, b) = r.expect_err("p is never covered");
        assert!(
            a <= p && (a - p).abs() < 1e-6 && (b - p).abs() < 1e-6,
            "[{a}, {b}]"
        );
    }
}
