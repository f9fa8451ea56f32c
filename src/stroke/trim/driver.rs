//! The driver: [`stroke`] and its phases.

use super::add_note;
use super::chain::{chain, check_simple, Known};
use super::classify::{foot, prove_kept, prove_removed, ExactCurve, Part, KEPT_MAX_PARTS};
use super::pinch::pinched_loops;
use super::sides::{check, dist_hi, raw_contours, Kind, Raw};
use super::split::{
    drop_coincident, find_crossings, share_circle_splits, split_piece, Bridge, Sub,
};
use super::types::{Cap, CapReport, Claim, Classified, Piece, Stroke, StrokeError, StrokeOptions};
use crate::curve::{Bezier, V2};
use crate::scalar::{rational_from_f64, Rational, Scalar};
use crate::stroke::ellipse::Form;
use crate::stroke::intersect::IntersectOptions;
use crate::stroke::onside::Input;
use num_traits::Zero;
use rayon::prelude::*;
use std::time::Instant;

/// Builds the proven stroke outline of `curve` with a circular pen of radius
/// `opts.radius` (see the module docs and `proofs/trimming.md`).
///
/// Errors name the field: an empty or disconnected curve, a point piece, a
/// radius that is not positive, a tolerance that is not a positive number, or
/// an offset error (a singular input piece). Claims that cannot be decided are
/// not errors: they come back unproven with a note.
///
/// # Examples
/// ```
/// use lncert::stroke::{stroke, StrokeOptions, Orientation};
/// use lncert::shape::parse_curve;
/// use lncert::parse_rational;
/// // a straight segment: the stadium, two segments and two half circles
/// let x = parse_curve("M 0 0 L 2 0").unwrap();
/// let s = stroke(&x, &StrokeOptions::new(parse_rational("1/2").unwrap(), "1e-3".parse().unwrap())).unwrap();
/// assert!(s.proven(), "{:?} {:?} {:?}", s.a, s.b, s.c);
/// assert_eq!(s.contours.len(), 1);
/// assert_eq!(s.contours[0].orientation, Orientation::CounterClockwise);
/// assert!(s.contours[0].closed);
/// ```
pub fn stroke(curve: &[Bezier<Rational>], opts: &StrokeOptions) -> Result<Stroke, StrokeError> {
    let first = stroke_at(curve, opts, 8.0)?;
    if first.classified.undecided == 0 && first.c.proven {
        return Ok(first);
    }
    // refinement on demand: sub-pieces that neither test decides are most
    // often a raw piece whose error bound `e` is as large as the geometry it
    // must resolve (a shallow crossing, a tail inside S by less than `e`);
    // the sides are rebuilt once at TOL/64 and the better outcome is kept
    let second = stroke_at(curve, opts, 64.0)?;
    let score = |s: &Stroke| {
        (
            [s.a.proven, s.b.proven, s.c.proven]
                .iter()
                .filter(|p| **p)
                .count(),
            std::cmp::Reverse(s.classified.undecided),
        )
    };
    if score(&second) > score(&first) {
        let mut second = second;
        second.notes.push(format!(
            "the sides were rebuilt at TOL/64 (at TOL/8 {} sub-pieces were undecided{})",
            first.classified.undecided,
            if first.c.proven {
                ""
            } else {
                ", claim (c) not proven"
            }
        ));
        Ok(second)
    } else {
        Ok(first)
    }
}

/// The raw arrangement's self-intersection search stops refining at this
/// parameter width (see [`IntersectOptions::self_min_width`]; the test cubic
/// at `r = 0.4`, TOL 1e-3: a raw piece through a cusp took 1,227 boxes,
/// 9 ms, and ended undecided all the same; 455 boxes at this width).
const RAW_SELF_MIN_WIDTH: f64 = 1e-7;

/// The raw arrangement's joint proofs stop at corners this wide, and a joint
/// they do not prove leaves a corner this wide undecided (see
/// [`IntersectOptions::joint_min_width`]): at a cusp of the exact offset that
/// the sides are split at, both pieces leave the joint in nearly one
/// direction; the corner proven there was `2⁻⁴⁷` wide after 22 exact tries,
/// and the solver then spent 27,000 boxes (80 ms on the test cubic's cubic
/// output) next to it, undecided all the same.
const RAW_JOINT_MIN_WIDTH: f64 = 1.0 / 1024.0;

/// [`stroke`] with the sides built within `TOL / raw_div`.
fn stroke_at(
    curve: &[Bezier<Rational>],
    opts: &StrokeOptions,
    raw_div: f64,
) -> Result<Stroke, StrokeError> {
    let comps = check(curve, opts)?;
    let closed = comps.iter().all(|c| c.2);
    let form = opts.form()?;
    let t0 = Instant::now();
    let (raws, mut notes, caps) = build_raw(curve, opts, &comps, raw_div)?;
    log::debug!("offsets: {:?}", t0.elapsed());

    // --- crossings of the raw arrangement, and the split
    let iopts = IntersectOptions {
        max_boxes_per_pair: opts.max_boxes_per_pair,
        self_intersections: true,
        ..IntersectOptions::default()
    };
    // arc–arc crossings are split this far (arc length) from the crossing:
    // far beyond the enclosures' widths, well inside λ ≥ TOL/2
    let bridge_mu = opts.tol.value() / 1024.0;
    // the raw search gives up sooner near cusps (the constants' docs); no
    // claim needs it complete (proofs/trimming.md, "Classification"), and
    // what it gives up on is reported undecided and left unsplit
    let raw_iopts = IntersectOptions {
        self_min_width: RAW_SELF_MIN_WIDTH,
        joint_min_width: RAW_JOINT_MIN_WIDTH,
        ..iopts
    };
    let mut found = find_crossings(&raws, &raw_iopts, bridge_mu, &mut notes, t0);
    let circles = share_circle_splits(&raws, &mut found);
    let mut subs: Vec<Sub> = Vec::new();
    for (i, raw) in raws.iter().enumerate() {
        subs.extend(split_piece(i, &raw.piece, &mut found.splits[i]));
    }
    let (subs, dropped) = drop_coincident(&raws, subs, &circles);
    if dropped > 0 {
        add_note(
            &mut notes,
            format!("{dropped} sub-arcs coincide exactly with sub-arcs of other caps or joins on one circle: one copy of each kept"),
        );
    }

    // --- classify, then drop pinched loops and spurs
    let run = Run {
        curve,
        curve_f: curve.iter().map(|b| b.map(Scalar::approx)).collect(),
        exact: ExactCurve::new(curve),
        comps: &comps,
        opts,
        form: &form,
        raws: &raws,
        tol: opts.tol.value(),
        t0,
    };
    let classes = classify(&run, &subs);
    let mut tally = tally(&run, &subs, &classes, &mut notes);
    log::debug!("classified: {:?}", t0.elapsed());
    let mut bridges = bridge_connectors(&subs, &tally.keep, &classes.kept, &found.bridges);
    for b in &bridges {
        tally.a_bound = tally.a_bound.max(b.bound);
    }
    drop_pinched(
        &run,
        &subs,
        &classes.near,
        &mut tally,
        &mut bridges,
        &mut notes,
    );
    log::debug!("pinched: {:?}", t0.elapsed());

    // --- chain, and claim (c)
    // a kept sub-piece that is its whole raw piece, unmoved, is tagged with
    // it: (c) reuses the raw search's answers for such pieces (`Known`)
    let out_pieces: Vec<(Piece, Option<usize>)> = subs
        .iter()
        .zip(&tally.keep)
        .filter(|(_, k)| **k)
        .map(|(s, _)| {
            let whole = s.end_splits == [false, false] && s.post == raws[s.raw].piece;
            (s.post.clone(), whole.then_some(s.raw))
        })
        .chain(
            bridges
                .into_iter()
                .filter(|b| b.keep)
                .map(|b| (b.piece, None)),
        )
        .collect();
    let (contours, origin) = chain(out_pieces);
    log::debug!("chained: {:?}", t0.elapsed());
    let known = Known {
        origin,
        unsure: &found.unsure,
    };
    #[cfg(test)]
    let reuse = REUSE_RAW.with(std::cell::Cell::get);
    #[cfg(not(test))]
    let reuse = true;
    // (the raw search answers for single pieces only if it solved them)
    let reuse = reuse && raw_iopts.self_intersections;
    let (c_ok, c_complete, c_note) = check_simple(&contours, &iopts, reuse.then_some(&known));
    log::debug!("checked: {:?}", t0.elapsed());
    if log::log_enabled!(log::Level::Trace) {
        for (k, s) in subs.iter().enumerate() {
            log::trace!(
                "sub {k}: raw {} [{:.6}, {:.6}] keep {} kept {:?} removed {:?} est {:.6} delta {:.2e}",
                s.raw, s.range.0.approx(), s.range.1.approx(), tally.keep[k], classes.kept[k], classes.removed[k], classes.estimates[k], s.delta
            );
        }
    }

    let butt = !closed && opts.cap == Cap::Butt;
    let (a, b) = claims_ab(&tally, &notes, opts.tol.value(), butt);
    let c = Claim {
        proven: c_ok,
        bound: 0.0,
        note: c_note,
    };
    Ok(Stroke {
        contours,
        crossings: found.crossings,
        raw_pieces: raws.len(),
        raw_complete: found.complete,
        complete: c_complete,
        a,
        b,
        c,
        classified: tally.classified,
        tol: opts.tol.clone(),
        closed_curve: closed,
        notes,
        pen: opts.ellipse.clone(),
        caps,
        certificate: None,
    })
}

/// Step 1: every component's sides and caps as raw pieces, with the notes of
/// their construction and the elliptical pen's cap reports. The trimming is
/// over all of them (the region is the union of the components' regions).
#[allow(clippy::type_complexity)]
fn build_raw(
    curve: &[Bezier<Rational>],
    opts: &StrokeOptions,
    comps: &[(usize, usize, bool)],
    raw_div: f64,
) -> Result<(Vec<Raw>, Vec<String>, Vec<CapReport>), StrokeError> {
    let mut raw_contours_all = Vec::new();
    let mut notes = Vec::new();
    let mut caps = Vec::new();
    for &(first, end, c_closed) in comps {
        let (rc, n, cp) = raw_contours(&curve[first..end], opts, c_closed, first, raw_div)?;
        raw_contours_all.extend(rc);
        notes.extend(n);
        caps.extend(cp);
    }
    let raws: Vec<Raw> = raw_contours_all.into_iter().flatten().collect();
    Ok((raws, notes, caps))
}

#[cfg(test)]
thread_local! {
    /// Claim (c) reuses the raw search's answers (`Known`); tests turn this
    /// off on their thread to compare with the full search.
    pub(super) static REUSE_RAW: std::cell::Cell<bool> = const { std::cell::Cell::new(true) };
}

/// What the classification phases share: the input, the pen and the raw
/// pieces the sub-pieces come from.
struct Run<'a> {
    curve: &'a [Bezier<Rational>],
    /// The input in floats (for estimates and feet only).
    curve_f: Vec<Bezier<f64>>,
    /// The input with the boxes of the exact outside test.
    exact: ExactCurve<'a>,
    comps: &'a [(usize, usize, bool)],
    opts: &'a StrokeOptions,
    form: &'a Form,
    raws: &'a [Raw],
    tol: f64,
    /// The start of the run (for the phase timings in the log).
    t0: Instant,
}

/// The per-sub-piece outcome of the tests.
struct Classes {
    /// Float estimate of the pen distance of the sub-piece's midpoint (pushed
    /// out along its right normal) to the input.
    estimates: Vec<f64>,
    /// Proven kept, with the bound of claim (a).
    kept: Vec<Option<f64>>,
    /// Proven removed, with the points of `near` its test leant on (the
    /// near-end relaxation; empty when none was needed).
    removed: Vec<Option<Vec<usize>>>,
    /// The end points of kept sub-pieces the removal test may lean on, each
    /// with the kept sub-pieces that end there.
    near: Vec<(V2<Rational>, Vec<usize>)>,
}

/// λ of the removal: a removed part within λ of a kept end point costs
/// (b) `e + λ`, so λ may use what TOL leaves above `e` (at least TOL/2).
fn lambda_f(tol: f64, e: f64) -> f64 {
    (0.95 * (tol - e)).max(tol / 2.0)
}

/// Step 4: kept first (the near-crossing relaxation of removal needs them),
/// then removal of the rest.
fn classify(run: &Run, subs: &[Sub]) -> Classes {
    let estimates: Vec<f64> = subs
        .par_iter()
        .map(|s| {
            let (m, _) = Part::initial(&s.pre)
                .and_then(|p| p.into_iter().next())
                .map(|p| p.mid_right_normal())
                .unwrap_or(((0.0, 0.0), (0.0, 0.0)));
            foot(&run.curve_f, run.form, m).0
        })
        .collect();
    log::debug!("estimates: {:?}", run.t0.elapsed());
    let onside_input = run
        .form
        .circle
        .then(|| Input::new(run.curve, run.comps, &run.opts.radius));
    let kept: Vec<Option<f64>> = subs
        .par_iter()
        .zip(&estimates)
        .map(|(s, est)| {
            let tt = Instant::now();
            let r = kept_bound(run, onside_input.as_ref(), s, *est);
            log::trace!("kept raw {} {:?} {:?}", s.raw, tt.elapsed(), r);
            r
        })
        .collect();
    log::debug!("kept: {:?}", run.t0.elapsed());
    let mut near: Vec<(V2<Rational>, Vec<usize>)> = Vec::new();
    let mut near_of: std::collections::HashMap<(Rational, Rational), usize> =
        std::collections::HashMap::new();
    for (k, s) in subs.iter().enumerate() {
        if kept[k].is_none() {
            continue;
        }
        for p in [s.post.start(), s.post.end()] {
            let i = *near_of
                .entry((p.x.clone(), p.y.clone()))
                .or_insert_with(|| {
                    near.push((p.clone(), Vec::new()));
                    near.len() - 1
                });
            if !near[i].1.contains(&k) {
                near[i].1.push(k);
            }
        }
    }
    let points: Vec<V2<Rational>> = near.iter().map(|(p, _)| p.clone()).collect();
    let removed: Vec<Option<Vec<usize>>> = subs
        .par_iter()
        .zip(&kept)
        .map(|(s, k)| removal(run, s, *k, &points))
        .collect();
    Classes {
        estimates,
        kept,
        removed,
        near,
    }
}

/// The kept test of one sub-piece: its bound for claim (a) when proven.
fn kept_bound(run: &Run, onside_input: Option<&Input>, s: &Sub, est: f64) -> Option<f64> {
    let tol = run.tol;
    let raw = &run.raws[s.raw];
    // f64 sums of bounds are rounded up (`next_up` of the rounded sum)
    let e_in = (raw.e_in + s.delta).next_up();
    if raw.kind == Kind::Butt {
        return Some(e_in);
    }
    // witnesses outside S for the whole sub-piece, in at most `parts` parts
    let witnesses = |parts| {
        prove_kept(
            &run.exact,
            &run.curve_f,
            &s.post,
            e_in,
            run.form,
            tol,
            parts,
        )
    };
    if est < run.form.reach - 4.0 * e_in.max(tol / 8.0) {
        return None;
    }
    // one decision for the whole sub-piece where the exact offset
    // points it stands for are proven on ∂S (module `onside`); an
    // exact cap or join arc is its own exact counterpart
    if let (Piece::Arc(arc), Some(input)) = (&s.pre, onside_input) {
        let budget = tol - e_in;
        if budget > 0.0 {
            if let Some(l) = input.prove_arc(arc, budget, 2048) {
                return Some((e_in + l).next_up());
            }
        }
        log::trace!("onside failed: raw {} (arc)", s.raw);
    }
    if let (Some(link), Some(input)) = (&raw.link, onside_input) {
        let budget = tol - e_in;
        let range = (s.range.0.approx(), s.range.1.approx());
        let pad = 1e-12;
        if budget > 0.0 {
            if let Some((t0, t1)) = link.exact_range(range.0 - pad, range.1 + pad) {
                // cheap tries first: a few exact ∂S intervals, then a few
                // witnesses outside S (a sub-piece about TOL long between a
                // near-G¹ joint and a crossing has no point the ∂S test can
                // prove, and failing it at full depth costs 100–400 ms)
                if polygon_length(&s.post) <= 2.0 * tol {
                    if let Some(l) = input.prove_interval(link.piece, &link.d, t0, t1, budget, 64) {
                        return Some((e_in + l).next_up());
                    }
                    if let Some(b) = witnesses(4) {
                        return Some(b);
                    }
                }
                // an exact offset that dips into `S` (by floats: only the
                // order of the tries depends on it) has no ∂S points there:
                // witnesses first, the failing ∂S search after them
                let dips = est < run.form.reach * (1.0 - DIP)
                    && offset_dips(run, link.piece, link.d.approx(), (t0, t1));
                if dips {
                    if let Some(b) = witnesses(KEPT_MAX_PARTS) {
                        return Some(b);
                    }
                }
                if let Some(l) = input.prove_interval(link.piece, &link.d, t0, t1, budget, 512) {
                    return Some((e_in + l).next_up());
                }
                log::trace!(
                    "onside failed: raw {} piece {} t [{t0}, {t1}]",
                    s.raw,
                    link.piece
                );
                // what failed is usually local (a shallow crossing or a
                // joint at an end): halve, and give witnesses to the failing
                // chunks only
                if let Piece::Bezier(pre) = &s.pre {
                    let k = KeptChunks {
                        run,
                        input,
                        link,
                        s,
                        pre,
                        e_in,
                        budget,
                    };
                    if let Some(b) = k.bound(0.0, 1.0, 0) {
                        return Some(b);
                    }
                }
            } else {
                log::trace!("onside: no exact range for raw {}", s.raw);
            }
        }
    }
    witnesses(KEPT_MAX_PARTS)
}

/// How far (relative to the pen's reach) a float distance estimate must fall
/// below the reach to count as a dip into `S`.
const DIP: f64 = 1e-7;

/// The float exact offset `x_i(t) + d·N(t)` over `[t0, t1]` (9 samples) has a
/// point whose float distance to the input is below the reach by more than
/// [`DIP`]: such a point is inside `S`, where the ∂S test cannot prove
/// anything. A float heuristic that only orders the kept tries.
fn offset_dips(run: &Run, piece: usize, d: f64, (t0, t1): (f64, f64)) -> bool {
    let x = &run.curve_f[piece];
    let h = x.hodograph();
    (1..10).any(|k| {
        let t = t0 + (t1 - t0) * k as f64 / 10.0;
        let (p, v) = (x.eval_fast(t), h.eval_fast(t));
        let n = v.x.hypot(v.y);
        // (a zero or NaN speed gives no normal: no dip seen there)
        if n.is_nan() || n <= 0.0 {
            return false;
        }
        let e = (p.x - d * v.y / n, p.y + d * v.x / n);
        foot(&run.curve_f, run.form, e).0 < run.form.reach * (1.0 - DIP)
    })
}

/// The length of a Bézier piece's control polygon in floats (an estimate
/// that only orders the tries; infinite for an arc).
fn polygon_length(p: &Piece) -> f64 {
    match p {
        Piece::Bezier(b) => b
            .points()
            .windows(2)
            .map(|w| (w[1].x.approx() - w[0].x.approx()).hypot(w[1].y.approx() - w[0].y.approx()))
            .sum(),
        Piece::Arc(_) => f64::INFINITY,
    }
}

/// Depth of the halving in [`KeptChunks::bound`]: a chunk that the exact ∂S
/// intervals cannot keep is halved down to 1/16 of the sub-piece before its
/// points get witnesses outside `S` (the per-part test, slow on long chunks).
const KEPT_CHUNK_DEPTH: u32 = 4;

/// The kept test of one Bézier sub-piece with a link to its exact offset,
/// chunk by chunk (`proofs/trimming.md`, "Kept by exact ∂S intervals", and
/// "Kept by chunks"): a chunk `u ∈ [u0, u1]` of `pre` is kept either by
/// [`Input::prove_interval`] on the exact parameters it stands for (its
/// unproven runs charged to proven leaves of the same chunk, so chunks are
/// independent), or by witnesses outside `S` for `pre` restricted to it.
struct KeptChunks<'a, 'b> {
    run: &'a Run<'b>,
    input: &'a Input,
    link: &'a super::sides::Link,
    s: &'a Sub,
    pre: &'a Bezier<Rational>,
    /// The sub-piece's `raw.e_in + delta`, rounded up.
    e_in: f64,
    /// `tol − e_in`: what a chunk's unproven run may use.
    budget: f64,
}

impl KeptChunks<'_, '_> {
    /// A bound of claim (a) over the points of `post` whose parameter `u`
    /// (the parameter of `pre`) is in `[u0, u1]`, or `None`.
    fn bound(&self, u0: f64, u1: f64, depth: u32) -> Option<f64> {
        // (the whole sub-piece's ∂S test has failed before depth 0)
        if depth > 0 {
            if let Some(b) = self.on_boundary(u0, u1, (512usize >> depth).max(64)) {
                return Some(b);
            }
        }
        // a few witnesses outside S may cover the chunk (near a corner or a
        // crossing, where the ∂S test proves nothing)
        if let Some(b) = self.witnesses(u0, u1, 4) {
            return Some(b);
        }
        if depth == 0 {
            if let Some(b) = self.ends_apart() {
                return Some(b);
            }
        }
        let m = 0.5 * (u0 + u1);
        if depth < KEPT_CHUNK_DEPTH && u0 < m && m < u1 {
            let l = self.bound(u0, m, depth + 1)?;
            let r = self.bound(m, u1, depth + 1)?;
            return Some(l.max(r));
        }
        self.witnesses(u0, u1, KEPT_MAX_PARTS)
    }

    /// The sub-piece with its end sixteenths (the halving's last depth) by
    /// witnesses and the rest by [`KeptChunks::on_boundary`]: what fails is
    /// usually at the ends (a crossing or a joint near each).
    fn ends_apart(&self) -> Option<f64> {
        let e = 0.5f64.powi(KEPT_CHUNK_DEPTH as i32);
        // the middle first: where it fails, no witness is tried
        tiled(&[(e, 1.0 - e), (0.0, e), (1.0 - e, 1.0)], |k, u0, u1| {
            if k == 0 {
                self.on_boundary(u0, u1, 512)
            } else {
                self.witnesses(u0, u1, 4)
                    .or_else(|| self.witnesses(u0, u1, 64))
            }
        })
    }

    /// The chunk `[u0, u1]` by [`Input::prove_interval`] on the exact
    /// parameters it stands for (at most `nodes` nodes).
    fn on_boundary(&self, u0: f64, u1: f64, nodes: usize) -> Option<f64> {
        let (r0, r1) = (self.s.range.0.approx(), self.s.range.1.approx());
        // the raw parameters of the chunk, padded so that the exact range
        // covers every raw point of the chunk whatever the float rounding
        let pad = 1e-12;
        let (a, b) = (r0 + u0 * (r1 - r0) - pad, r0 + u1 * (r1 - r0) + pad);
        let (t0, t1) = self.link.exact_range(a.max(0.0), b.min(1.0))?;
        let l =
            self.input
                .prove_interval(self.link.piece, &self.link.d, t0, t1, self.budget, nodes)?;
        Some((self.e_in + l).next_up())
    }

    /// Witnesses outside `S` for the exact chunk `[u0, u1]` of `pre` (at most
    /// `max_parts` parts): each of its points is within `raw.e_in` of `S` (of
    /// a point of `S`) and within `rho` of a point outside, so within
    /// `max(rho, raw.e_in)` of `∂S`; `post` moves it by at most `delta`
    /// (`e_in` holds both).
    fn witnesses(&self, u0: f64, u1: f64, max_parts: usize) -> Option<f64> {
        let (q0, q1) = (rational_from_f64(u0)?, rational_from_f64(u1)?);
        let chunk = Piece::Bezier(self.pre.restrict(&q0, &q1));
        let raw_e_in = self.run.raws[self.s.raw].e_in;
        let kept = prove_kept(
            &self.run.exact,
            &self.run.curve_f,
            &chunk,
            raw_e_in,
            self.run.form,
            self.run.tol - self.s.delta,
            max_parts,
        )?;
        log::trace!("kept chunk [{u0}, {u1}] of raw {} by witnesses", self.s.raw);
        Some((kept + self.s.delta).next_up().max(self.e_in))
    }
}

/// A bound over a whole sub-piece from bounds of its chunks `[u0, u1]` of
/// `[0, 1]`, proven in the order given (`prove(k, u0, u1)` for chunk `k`):
/// the largest, or `None` unless every chunk is proven and the chunks, in
/// order of their starts, tile `[0, 1]` exactly (no gap, no overlap).
pub(super) fn tiled(
    chunks: &[(f64, f64)],
    prove: impl Fn(usize, f64, f64) -> Option<f64>,
) -> Option<f64> {
    let mut sorted = chunks.to_vec();
    sorted.sort_by(|a, b| a.0.total_cmp(&b.0));
    let tiles = sorted.first().is_some_and(|c| c.0 == 0.0)
        && sorted.last().is_some_and(|c| c.1 == 1.0)
        && sorted.windows(2).all(|w| w[0].1 == w[1].0)
        && sorted.iter().all(|c| c.0 < c.1);
    if !tiles {
        return None;
    }
    chunks
        .iter()
        .enumerate()
        .try_fold(0.0f64, |m, (k, &(u0, u1))| Some(m.max(prove(k, u0, u1)?)))
}

/// The removal test of one sub-piece that is not kept (only boundary pieces
/// are tested): `Some(used)` when proven, `used` the points of `near` (ends
/// of kept sub-pieces) it needed.
fn removal(run: &Run, s: &Sub, kept: Option<f64>, near: &[V2<Rational>]) -> Option<Vec<usize>> {
    let raw = &run.raws[s.raw];
    if kept.is_some() || raw.kind != Kind::Boundary {
        return None;
    }
    let tt = Instant::now();
    // the error bound of a part of `pre` (parameters `[t0, t1]` on it):
    // the map's boxes over it plus the raw piece's moves since
    let local = |t0: f64, t1: f64| -> Option<f64> {
        let link = raw.link.as_ref()?;
        let (r0, r1) = (s.range.0.approx(), s.range.1.approx());
        let pad = 1e-9;
        let lb = link.local_bound(r0 + t0 * (r1 - r0) - pad, r0 + t1 * (r1 - r0) + pad)?;
        // `raw.e − seg_e` is a float difference: a few ulps of
        // `raw.e` cover its rounding (and that of raw.e's sums)
        let moved = (raw.e - link.seg_e).max(0.0) + 8.0 * f64::EPSILON * raw.e;
        Some((lb + moved) * (1.0 + 1e-12))
    };
    let lambda =
        rational_from_f64(lambda_f(run.tol, raw.e)).unwrap_or_else(<Rational as Zero>::zero);
    let r = prove_removed(
        run.curve,
        &run.curve_f,
        &s.pre,
        raw.e,
        &local,
        run.form,
        near,
        &lambda,
    );
    log::trace!("removed raw {} {:?} {:?}", s.raw, tt.elapsed(), r);
    r
}

/// The classification's counts, the bounds of claims (a) and (b), and which
/// sub-pieces go to the output.
struct Tally {
    classified: Classified,
    a_bound: f64,
    b_bound: f64,
    a_ok: bool,
    b_ok: bool,
    keep: Vec<bool>,
    /// The removals that leant on kept end points: `(e + λ, i)` for the
    /// point `i` of [`Classes::near`]. If every kept piece ending there is
    /// dropped later, its reach adds to that bound.
    near_uses: Vec<(f64, usize)>,
}

/// Counts the classes, raises the claims' bounds, and picks the output: kept
/// pieces, and for undecided ones (shown, not proven) what looks like boundary.
fn tally(run: &Run, subs: &[Sub], classes: &Classes, notes: &mut Vec<String>) -> Tally {
    let mut t = Tally {
        classified: Classified::default(),
        a_bound: 0.0,
        b_bound: 0.0,
        a_ok: true,
        b_ok: true,
        keep: vec![false; subs.len()],
        near_uses: Vec::new(),
    };
    for (k, s) in subs.iter().enumerate() {
        let raw = &run.raws[s.raw];
        if let Some(bd) = classes.kept[k] {
            t.classified.kept += 1;
            t.keep[k] = true;
            t.a_bound = t.a_bound.max(bd);
            if raw.kind == Kind::Boundary {
                t.b_bound = t.b_bound.max((raw.e + s.delta).next_up());
            }
        } else if raw.kind == Kind::Connector {
            t.classified.dropped_connectors += 1;
        } else if let Some(used) = &classes.removed[k] {
            t.classified.removed += 1;
            t.b_bound = t.b_bound.max(raw.e);
            if !used.is_empty() {
                // the λ the removal test was given (its rational is exactly
                // this f64), plus a hair for the sum's rounding
                let near = (raw.e + lambda_f(run.tol, raw.e)) * (1.0 + 1e-12);
                t.b_bound = t.b_bound.max(near);
                t.near_uses.extend(used.iter().map(|&i| (near, i)));
            }
        } else {
            t.classified.undecided += 1;
            t.a_ok = false;
            t.b_ok = false;
            // shown, not proven: keep what looks like boundary
            t.keep[k] = classes.estimates[k] >= run.form.reach - 2.0 * (raw.e_in + s.delta);
            add_note(
                notes,
                format!(
                    "sub-piece of raw piece {} undecided (distance estimate {:.6})",
                    s.raw, classes.estimates[k]
                ),
            );
        }
    }
    for raw in run.raws {
        if raw.kind == Kind::Boundary && !raw.e.is_finite() {
            t.b_ok = false;
        }
    }
    t
}

/// A straight connector across an arc–arc crossing (see
/// [`super::split::Bridge`]).
struct BridgeConnector {
    piece: Piece,
    /// Claim (a) for its points: `|X − Y|` plus the bound of the kept piece
    /// ending at its start `X` (every point is within `|X − Y|` of `X`).
    bound: f64,
    /// Still in the output (not dropped with a pinched loop or spur).
    keep: bool,
}

/// The connectors of the arc–arc bridges: where an output piece ends at one
/// split point and another starts at the other, the segment from the first
/// to the second. Its points are not on any raw piece: claim (a) charges
/// them `|X − Y|` above the bound of the piece ending at `X`; claims (b)
/// and (c) do not need them to be anything but output (and (c) checks the
/// output as it is).
fn bridge_connectors(
    subs: &[Sub],
    keep: &[bool],
    kept: &[Option<f64>],
    bridges: &[Bridge],
) -> Vec<BridgeConnector> {
    let mut out = Vec::new();
    for br in bridges {
        for (x, y) in [(&br.ends[0], &br.ends[1]), (&br.ends[1], &br.ends[0])] {
            if x == y {
                continue;
            }
            let ending = (0..subs.len()).find(|&k| keep[k] && subs[k].post.end() == x);
            let starting = (0..subs.len()).any(|k| keep[k] && subs[k].post.start() == y);
            if let (Some(k), true) = (ending, starting) {
                let len = dist_hi(x, y);
                out.push(BridgeConnector {
                    piece: Piece::Bezier(Bezier::new(vec![x.clone(), y.clone()])),
                    bound: (kept[k].unwrap_or(f64::INFINITY) + len) * (1.0 + 1e-12),
                    keep: true,
                });
            }
        }
    }
    out
}

/// Pinched loops, spurs, isolated loops and surplus pieces: kept pieces that
/// close a loop at an exact point X of the output, or dangle from one, each
/// within a certified reach of the pieces that stay at X, and small closed
/// chains touching nothing or second paths between two points, within a
/// certified reach of the pieces near them, are dropped (a boundary point
/// near them is within
/// `e + δ + reach` of the output).
fn drop_pinched(
    run: &Run,
    subs: &[Sub],
    near: &[(V2<Rational>, Vec<usize>)],
    tally: &mut Tally,
    bridges: &mut [BridgeConnector],
    notes: &mut Vec<String>,
) {
    let kept_idx: Vec<usize> = (0..subs.len()).filter(|&k| tally.keep[k]).collect();
    // a spur may reach as far from the live pieces as keeps (b) within tol
    let spur_caps: Vec<f64> = kept_idx
        .iter()
        .map(|&k| {
            let raw = &run.raws[subs[k].raw];
            if raw.kind == Kind::Boundary {
                run.tol - raw.e - subs[k].delta
            } else {
                // a connector or butt chord stands for no point of ∂S
                run.tol
            }
        })
        // a bridge connector stands for no point of ∂S either
        .chain(bridges.iter().map(|_| run.tol))
        .collect();
    let dropped = pinched_loops(
        &kept_idx
            .iter()
            .map(|&k| &subs[k].post)
            .chain(bridges.iter().map(|b| &b.piece))
            .collect::<Vec<_>>(),
        &spur_caps,
    );
    if !dropped.is_empty() {
        let mut reach_of: std::collections::HashMap<usize, f64> = std::collections::HashMap::new();
        for &(d, reach) in &dropped {
            if d >= kept_idx.len() {
                bridges[d - kept_idx.len()].keep = false;
                continue;
            }
            let k = kept_idx[d];
            tally.keep[k] = false;
            reach_of.insert(k, reach);
            let raw = &run.raws[subs[k].raw];
            if raw.kind == Kind::Boundary {
                tally.b_bound = tally
                    .b_bound
                    .max(((raw.e + subs[k].delta).next_up() + reach).next_up());
            }
        }
        // a removal that leant on an end point of dropped pieces only: that
        // point is within their reach of the pieces that stay
        for &(bound, i) in &tally.near_uses {
            let owners = &near[i].1;
            if owners.iter().all(|k| !tally.keep[*k]) {
                let reach = owners
                    .iter()
                    .map(|k| reach_of.get(k).copied().unwrap_or(f64::INFINITY))
                    .fold(0.0, f64::max);
                tally.b_bound = tally.b_bound.max((bound + reach).next_up());
            }
        }
        add_note(
            notes,
            format!(
                "{} kept pieces forming pinched loops, spurs, isolated loops or surplus paths dropped (each within a certified reach of the pieces that stay, added to (b))",
                dropped.len()
            ),
        );
    }
}

/// Claims (a) and (b) from the tally (not claimed for butt caps; not proven
/// when an offset did not reach its tolerance).
fn claims_ab(tally: &Tally, notes: &[String], tol: f64, butt: bool) -> (Claim, Claim) {
    let offsets_ok = notes.iter().all(|n| !n.contains("did not reach"));
    let claim = |ok: bool, bound: f64, shown: String| Claim {
        proven: ok && offsets_ok && bound <= tol && !butt,
        bound: if ok { bound } else { f64::INFINITY },
        note: if butt {
            "not claimed for butt caps (the region is not x ⊕ pen)".into()
        } else if ok {
            shown
        } else {
            "some sub-pieces could not be classified".into()
        },
    };
    let (a_bound, b_bound) = (tally.a_bound, tally.b_bound);
    let a = claim(
        tally.a_ok,
        a_bound,
        format!("every kept sub-piece is within {a_bound:.3e} of exact offset points proven on ∂S, or of a point proven outside S and a point of S"),
    );
    let b = claim(
        tally.b_ok,
        b_bound,
        format!(
            "every sub-piece of the raw pieces is kept or proven interior; bound {b_bound:.3e}"
        ),
    );
    (a, b)
}
