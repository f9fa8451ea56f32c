//! The divide-and-conquer driver of [`offset`]: initial spans, the
//! construction of each span's approximant, its certification, and the
//! splitting of the spans that miss the tolerance.

use super::corners::{absorb_kinks, corners};
use super::fit::{self, Output};
use super::options::{check_options, OffsetError, OffsetMethod, OffsetOptions};
use super::prep::{self, OffsetCusp};
use super::results::{exact_bezier, sub_exact, OffsetResult, OffsetSegment, SegmentProof};
use super::{conv, convolve::conv_paper_error, g2, lnpair};
use crate::certify::piece::Piece;
use crate::certify::{hausdorff, Config, HausdorffBounds};
use crate::curve::{Bezier, V2};
use crate::scalar::{interval_from_rational, rational_from_f64, Interval, Rational, Scalar};
use crate::shape::ShapeDesc;
use rayon::prelude::*;

/// What the driver approximates: the offset at a distance, or the
/// convolution with a pen on one side.
#[derive(Clone, Debug)]
pub(super) enum Kernel {
    Offset {
        d: Rational,
        df: f64,
    },
    Conv {
        // boxed: a pen (exact matrix, rotation, margin) is far larger than an offset's distance
        pen: Box<conv::Pen>,
        qf: [f64; 3],
        sigma: i8,
    },
}

impl Kernel {
    /// The exact curve's piece over the span `t` of `x`, enclosed.
    pub(super) fn span_piece(
        &self,
        x: &Bezier<Rational>,
        t: (f64, f64),
    ) -> Option<crate::certify::piece::Piece> {
        match self {
            Kernel::Offset { d, .. } => crate::certify::piece::offset_span(x, t, d),
            Kernel::Conv { pen, sigma, .. } => {
                crate::certify::piece::conv_span(x, t, pen.q_interval(), *sigma)
            }
        }
    }
    /// The size of the offset vector (for scale-aware gaps).
    fn reach(&self) -> f64 {
        match self {
            Kernel::Offset { df, .. } => df.abs(),
            Kernel::Conv { qf, .. } => qf[0].max(qf[2]).abs().sqrt(),
        }
    }
}

#[derive(Clone, Debug)]
struct Task {
    piece: usize,
    t: (f64, f64),
    depth: u32,
    /// The parent's certification ran out of budget on a (nearly) exact
    /// approximant; a second such level stops splitting.
    stuck_before: bool,
}

struct Outcome {
    task: Task,
    segment: Option<OffsetSegment>,
    /// Where to split when not accepted.
    split: f64,
    /// Splitting would not help (see `certify_segment`).
    stuck: bool,
}

/// Initial spans of one piece: split at inflections (unless `inflections` is
/// false: fitted cubics, which may inflect) and at the `extra` cuts (the cusps
/// of a convolution side, or of a fitted offset); then, for G², halve until the Gauss map
/// of each span turns by less than 0.9π ([`prep::MAX_TURN`]), and for LN
/// pairs split a span turning by `Δ ≥ π` into the `k` pieces of equal turn
/// of seed 000 §5 ([`lnpair::k_piece_split`], `k` the smallest integer with
/// `Δ/k < π`).
fn initial_spans(
    x: &Bezier<Rational>,
    extra: &[f64],
    method: OffsetMethod,
    inflections: bool,
) -> Vec<(f64, f64)> {
    let mut cuts = vec![0.0];
    if inflections {
        cuts.extend(prep::inflections(x));
    }
    cuts.extend(extra.iter().copied().filter(|t| *t > 0.0 && *t < 1.0));
    cuts.push(1.0);
    cuts.sort_by(f64::total_cmp);
    cuts.dedup();
    let mut out = Vec::new();
    for w in cuts.windows(2) {
        if method == OffsetMethod::LnPair {
            let mut ends = vec![w[0]];
            if let Some(sub) = span_f64(x, (w[0], w[1])) {
                let k = lnpair::k_piece_split(&sub, std::f64::consts::PI);
                ends.extend(k.iter().map(|u| w[0] + (w[1] - w[0]) * u));
            }
            ends.push(w[1]);
            out.extend(
                ends.windows(2)
                    .filter(|e| e[0] < e[1])
                    .map(|e| (e[0], e[1])),
            );
            continue;
        }
        let mut stack = vec![(w[0], w[1], 0u32)];
        while let Some((a, b, depth)) = stack.pop() {
            let sub = span_f64(x, (a, b));
            if depth >= 8 || sub.as_ref().is_some_and(prep::gauss_map_short) {
                out.push((a, b));
            } else {
                let m = 0.5 * (a + b);
                stack.push((m, b, depth + 1));
                stack.push((a, m, depth + 1));
            }
        }
    }
    out.sort_by(|p, q| p.0.total_cmp(&q.0));
    out
}

/// The span `t` of `x` in floats, the input of the constructions (heuristics:
/// only tightness depends on it): [`Bezier::restrict`] of the float control
/// points, whose end points are one canonical float de Casteljau at `t₀`, `t₁`,
/// so that neighbouring spans share them bit for bit.
pub fn span_f64(x: &Bezier<Rational>, t: (f64, f64)) -> Option<Bezier<f64>> {
    let sub = x.map(|v| v.approx()).restrict(&t.0, &t.1);
    sub.points()
        .iter()
        .all(|p| p.x.is_finite() && p.y.is_finite())
        .then_some(sub)
}

/// Builds the approximant of one span: the construction with canonical end
/// normals (so neighbours share end points exactly).
fn construct(
    method: OffsetMethod,
    output: Output,
    x: &Bezier<Rational>,
    t: (f64, f64),
    kernel: &Kernel,
    target: f64,
) -> Option<(Bezier<f64>, Option<lnpair::LnPairPiece>)> {
    if output != Output::Native {
        return fit::construct(output, x, t, kernel, target).map(|b| (b, None));
    }
    let sub = span_f64(x, t)?;
    let d = match kernel {
        Kernel::Offset { df, .. } => *df,
        Kernel::Conv { qf, sigma, .. } => {
            // seed 001: the ends pinned to the canonical pen points
            let e0 = conv::pen_point_at(x, t.0, *qf, *sigma)?;
            let e1 = conv::pen_point_at(x, t.1, *qf, *sigma)?;
            return match method {
                OffsetMethod::G2 => conv::convolution_approximant_f64(&sub, &e0, &e1, *qf, *sigma)
                    .map(|(c, _)| (c, None)),
                OffsetMethod::LnPair => {
                    let n0 = prep::unit_left_normal(x, t.0)?;
                    let n1 = prep::unit_left_normal(x, t.1)?;
                    let pair = lnpair::ln_pair_pen(&sub, &n0, &n1, &e0, &e1).ok()?;
                    Some((pair.offset.clone(), Some(pair)))
                }
            };
        }
    };
    let n0 = prep::unit_left_normal(x, t.0)?;
    let n1 = prep::unit_left_normal(x, t.1)?;
    match method {
        OffsetMethod::G2 => {
            let (mut o, _) = g2::offset_approximant_f64(&sub, d)?;
            // pin the ends to x(tᵢ) + d Nᵢ with the canonical normals
            let p = sub.points();
            let last = o.points().len() - 1;
            let e0 = p[0].add(&n0.scale(&d));
            let e1 = p[p.len() - 1].add(&n1.scale(&d));
            let mut pts = o.points().to_vec();
            pts[0] = e0;
            pts[last] = e1;
            o = Bezier::new(pts);
            Some((o, None))
        }
        OffsetMethod::LnPair => {
            let pair = lnpair::ln_pair(&sub, &n0, &n1, d).ok()?;
            Some((pair.offset.clone(), Some(pair)))
        }
    }
}

/// Certifies one span: the segment (if constructed and certified at all), the
/// split point, and whether the search ran out of its box budget undecided while
/// its lower bound is far below `tol` ("stuck"). Near a cusp halving helps; on a
/// (nearly) exact approximant it does not (bounds on coinciding curves shrink
/// like `w^{3/2}` however the span is cut), so the driver splits a stuck span
/// once and gives up when a half is stuck again.
fn certify_segment(
    x: &Bezier<Rational>,
    task: &Task,
    opts: &OffsetOptions,
    kernel: &Kernel,
    searches: &std::sync::atomic::AtomicUsize,
) -> (Option<OffsetSegment>, f64, bool) {
    let split = 0.5;
    let target = match &opts.grid {
        None => opts.tol.value(),
        Some(g) => opts.tol.value() - fit::rounding_move(g),
    };
    let Some((built, pair)) = construct(opts.method, opts.output, x, task.t, kernel, target) else {
        return (None, split_point(opts, x, task.t, kernel, None), false);
    };
    let Some((bez, unrounded, fit_tol)) = on_grid(built, opts) else {
        return (
            None,
            split_point(opts, x, task.t, kernel, pair.as_ref()),
            false,
        );
    };
    // The pieces of the span's exact offset (`ShapeDesc::Offset` of the exact
    // restriction of `x`) and of the segment, enclosed without rationals.
    let (Some(pa), Some(pb)) = (
        kernel.span_piece(x, task.t),
        crate::certify::piece::bezier_f64(&bez),
    ) else {
        return (None, split, false);
    };
    let (pa, pb) = ([pa], [pb]);
    // a segment with nothing certified: the trivial bounds (and, with
    // `certify: false`, the sampled estimate apart)
    let unproven = |estimate: Option<f64>| OffsetSegment {
        piece: task.piece,
        t: task.t,
        bezier: bez.clone(),
        error: (0.0, f64::INFINITY),
        paper_error: None,
        proof: None,
        estimate,
    };
    if !opts.certify {
        // the same construction, accepted on a sampled estimate (unproven)
        let e = crate::certify::sampled_pieces(&pa, &pb, 32);
        return (
            Some(unproven(Some(e))),
            split_point(opts, x, task.t, kernel, pair.as_ref()),
            false,
        );
    }
    // A span whose sampled (float, unproven) error is already above `tol` is
    // split without a proof: only acceptance needs one, and refuting the span
    // with a certified lower bound costs more than the rest of its search. At
    // the depth limit the span is bounded anyway, to report it.
    if !opts.accept_paper
        && task.depth < opts.max_depth
        && sampled_above(&pa, &pb, unrounded.as_ref(), fit_tol)
    {
        return (
            Some(unproven(None)),
            split_point(opts, x, task.t, kernel, pair.as_ref()),
            false,
        );
    }
    searches.fetch_add(1, std::sync::atomic::Ordering::Relaxed);
    let r = prove_span(&pa, &pb, &bez, task, opts, kernel.reach());
    let paper_error = paper_error(x, task.t, pair.as_ref(), opts, kernel);
    let proof = (r.hi <= opts.tol.value()).then(|| SegmentProof::of(&r));
    let seg = OffsetSegment {
        piece: task.piece,
        t: task.t,
        bezier: bez,
        error: (r.lo, r.hi),
        paper_error,
        proof,
        estimate: None,
    };
    let stuck = r.incomplete() && r.hi > opts.tol.value() && r.lo * 64.0 < opts.tol.value();
    (
        Some(seg),
        split_point(opts, x, task.t, kernel, pair.as_ref()),
        stuck,
    )
}

/// The segment to prove: without a grid the construction itself; with a grid
/// the written (rounded) numbers, the construction kept to be pre-checked
/// within `tol − rounding move` (the third value: the pre-check's tolerance).
/// `None` when the construction cannot be rounded.
fn on_grid(
    built: Bezier<f64>,
    opts: &OffsetOptions,
) -> Option<(Bezier<f64>, Option<Bezier<f64>>, f64)> {
    match &opts.grid {
        None => Some((built, None, opts.tol.value())),
        Some(g) => {
            let r = fit::round_to_grid(&built, g)?;
            Some((r, Some(built), opts.tol.value() - fit::rounding_move(g)))
        }
    }
}

/// The sampled (unproven) error of the segment `pb` — of the construction
/// before rounding when there is one — is above `fit_tol`.
fn sampled_above(
    pa: &[Piece],
    pb: &[Piece],
    unrounded: Option<&Bezier<f64>>,
    fit_tol: f64,
) -> bool {
    let pre = |pb: &[Piece]| crate::certify::sampled_pieces(pa, pb, 8);
    match unrounded {
        None => pre(pb) > fit_tol,
        Some(u) => crate::certify::piece::bezier_f64(u).is_none_or(|p| pre(&[p]) > fit_tol),
    }
}

/// The certified bounds of one span's segment `bez` (enclosed as `pb`)
/// against the span's exact offset `pa`; `d` the size of the offset vector.
fn prove_span(
    pa: &[Piece],
    pb: &[Piece],
    bez: &Bezier<f64>,
    task: &Task,
    opts: &OffsetOptions,
    d: f64,
) -> HausdorffBounds {
    let cfg = Config {
        tol: Some(opts.tol.clone()),
        max_boxes: opts.max_boxes,
        // a refuted span is split: its other direction is not needed — unless it
        // cannot be split any more and its bounds are reported
        verdict_only: task.depth < opts.max_depth && !opts.accept_paper,
        parametric: !opts.search_only,
        ..Config::default()
    };
    // the absolute gap of `hausdorff` for these shapes, from the float data
    let abs_of = || {
        let scale = bez
            .points()
            .iter()
            .map(|p| p.x.abs().max(p.y.abs()))
            .fold(0.0, f64::max);
        1e-10 * (1.0 + scale + d)
    };
    crate::certify::hausdorff_pieces(pa, pb, &cfg, &abs_of)
}

/// Seed 000's error measure of an LN-pair segment over the span `t`, when
/// asked for ([`OffsetOptions::paper_error`], [`OffsetOptions::accept_paper`]).
fn paper_error(
    x: &Bezier<Rational>,
    t: (f64, f64),
    pair: Option<&lnpair::LnPairPiece>,
    opts: &OffsetOptions,
    kernel: &Kernel,
) -> Option<f64> {
    match (pair, opts.paper_error || opts.accept_paper, kernel) {
        (Some(p), true, Kernel::Offset { df, .. }) => {
            sub_exact(x, t).and_then(|e| paper_error_of(x, t, &e, p, *df))
        }
        (Some(p), true, Kernel::Conv { pen, sigma, .. }) => {
            sub_exact(x, t).and_then(|e| conv_paper_error(&e, p, pen, *sigma))
        }
        _ => None,
    }
}

/// Where to split a span that missed the tolerance, as a fraction of it: the
/// middle for G², the LN-pair rule of `opts.subdivision` (its pair when one was
/// built; rule (a) otherwise).
fn split_point(
    opts: &OffsetOptions,
    x: &Bezier<Rational>,
    t: (f64, f64),
    kernel: &Kernel,
    pair: Option<&lnpair::LnPairPiece>,
) -> f64 {
    if opts.method == OffsetMethod::G2 {
        return 0.5;
    }
    let Some(s) = span_f64(x, t) else {
        return 0.5;
    };
    match (opts.subdivision, pair) {
        (lnpair::Subdivision::Chord, Some(p)) => lnpair::chord_param(&s, p),
        (lnpair::Subdivision::Weighted, Some(p)) => {
            // the exact pen (or offset-circle) point compatible with s(u)
            let h = s.hodograph();
            let q = |u: f64| {
                let d = h.eval(&u);
                let l = d.norm2().sqrt();
                if !(l > 0.0 && l.is_finite()) {
                    return None;
                }
                let n = V2::new(-d.y / l, d.x / l);
                match kernel {
                    Kernel::Offset { df, .. } => Some(n.scale(df)),
                    Kernel::Conv { qf, sigma, .. } => conv::pen_point(&n, *qf, *sigma),
                }
            };
            lnpair::weighted_param(&s, p, &q)
        }
        _ => lnpair::mid_angle_param(&s),
    }
}

/// Interval enclosure of the unit left normal of `x` at `t`.
fn normal_enclosure(x: &Bezier<Rational>, t: f64) -> Option<V2<Interval>> {
    let d = x.hodograph().eval(&rational_from_f64(t)?);
    let v = V2::new(interval_from_rational(&d.x), interval_from_rational(&d.y));
    let l = crate::scalar::ScalarSqrt::sqrt(&v.norm2())?;
    let inv = Scalar::recip(&l)?;
    Some(V2::new(-v.y * inv, v.x * inv))
}

fn paper_error_of(
    x: &Bezier<Rational>,
    t: (f64, f64),
    exact: &Bezier<Rational>,
    p: &lnpair::LnPairPiece,
    d: f64,
) -> Option<f64> {
    let pa = exact_bezier(&p.pa)?;
    let r = hausdorff(
        &ShapeDesc::Curve(vec![exact.clone()]),
        &ShapeDesc::Curve(vec![pa]),
        &Config {
            rel: 1e-2,
            ..Config::default()
        },
    )
    .ok()?;
    let arc = lnpair::arc_term(
        &normal_enclosure(x, t.0)?,
        &normal_enclosure(x, t.1)?,
        p.kappa,
        d,
    )?;
    Some(lnpair::paper_error(r.hi, arc))
}

/// Approximates the offset at `opts.distance` of a piecewise polynomial curve
/// within `opts.tol`, proving every segment (see the module docs).
///
/// Errors: a typed [`OffsetError`] naming the field for a singular or cusped
/// input piece (its normal is undefined), a zero distance, a tolerance that is
/// not a positive number or is below [`MIN_REL_TOL`](super::MIN_REL_TOL) × (1 + scale), or
/// coordinates beyond `1e100`. A tolerance that cannot be reached within the
/// depth and segment limits is not an error: the result lists the segments in
/// [`OffsetResult::unreached`] with their certified bounds.
pub fn offset(
    curve: &[Bezier<Rational>],
    opts: &OffsetOptions,
) -> Result<OffsetResult, OffsetError> {
    check_options(curve, opts)?;
    let find_cusps = || -> Vec<OffsetCusp> {
        curve
            .iter()
            .enumerate()
            .flat_map(|(i, x)| prep::offset_cusps(i, x, &opts.distance))
            .collect()
    };
    let kernel = Kernel::Offset {
        d: opts.distance.clone(),
        df: opts.distance.approx(),
    };
    let (cusps, segs) = if opts.output == Output::Native {
        // the exact cusp isolation does not depend on the segments: beside them
        rayon::join(find_cusps, || offset_segments(curve, opts, &kernel, &[]))
    } else {
        // a fitted cubic or quadratic cannot turn back: cut at the cusps first
        let cusps = find_cusps();
        let cuts = cusp_cuts(
            curve.len(),
            fit::cusps_to_cut(&cusps, opts.tol.value()).into_iter(),
        );
        let segs = offset_segments(curve, opts, &kernel, &cuts);
        (cusps, segs)
    };
    let (segments, unreached, certified_hi, certifications, spans) = segs;
    let mut res = OffsetResult {
        method: opts.method,
        distance: opts.distance.clone(),
        tol: opts.tol.clone(),
        segments,
        unreached,
        certified_hi,
        cusps,
        corners: corners(curve, &opts.distance),
        certifications,
        spans,
        proven: opts.certify,
        convolution: None,
    };
    if opts.smooth_kinks && opts.output != Output::Native && opts.grid.is_none() && opts.certify {
        absorb_kinks(curve, &mut res, opts, &kernel);
    }
    Ok(res)
}

/// The segments of [`offset`]: `(segments, unreached, certified_hi, certified
/// searches, spans tried)`.
pub(super) fn offset_segments(
    curve: &[Bezier<Rational>],
    opts: &OffsetOptions,
    kernel: &Kernel,
    cuts: &[Vec<f64>],
) -> (Vec<OffsetSegment>, Vec<usize>, f64, usize, usize) {
    let mut spans = 0usize;
    let mut tasks = initial_tasks(curve, opts, cuts);
    let mut done: Vec<OffsetSegment> = Vec::new();
    let mut unreached_segs: Vec<OffsetSegment> = Vec::new();
    let searches = std::sync::atomic::AtomicUsize::new(0);
    while !tasks.is_empty() {
        spans += tasks.len();
        let outcomes: Vec<Outcome> = tasks
            .par_iter()
            .map(|task| {
                let (segment, s, stuck) =
                    certify_segment(&curve[task.piece], task, opts, kernel, &searches);
                Outcome {
                    task: task.clone(),
                    segment,
                    split: s,
                    stuck,
                }
            })
            .collect();
        tasks = next_round(curve, opts, outcomes, &mut done, &mut unreached_segs);
    }
    let (segments, unreached, certified_hi) = in_order(done, unreached_segs);
    (
        segments,
        unreached,
        certified_hi,
        searches.into_inner(),
        spans,
    )
}

/// The first round's tasks: the initial spans of every piece.
fn initial_tasks(curve: &[Bezier<Rational>], opts: &OffsetOptions, cuts: &[Vec<f64>]) -> Vec<Task> {
    let mut tasks: Vec<Task> = Vec::new();
    for (i, x) in curve.iter().enumerate() {
        // a fitted cubic may have an inflection: the native constructions (and
        // a quadratic) need the input cut there
        let inflections = opts.output != Output::Cubic;
        for t in initial_spans(
            x,
            cuts.get(i).map_or(&[][..], |c| &c[..]),
            opts.method,
            inflections,
        ) {
            tasks.push(Task {
                piece: i,
                t,
                depth: 0,
                stuck_before: false,
            });
        }
    }
    tasks
}

/// Sorts the outcomes of one round: accepted segments into `done`, spans that
/// may still be split into the next round's tasks (returned), the others into
/// `unreached_segs`.
fn next_round(
    curve: &[Bezier<Rational>],
    opts: &OffsetOptions,
    outcomes: Vec<Outcome>,
    done: &mut Vec<OffsetSegment>,
    unreached_segs: &mut Vec<OffsetSegment>,
) -> Vec<Task> {
    let mut next = Vec::new();
    let mut pending = outcomes.len();
    for o in outcomes {
        pending -= 1;
        if accepted(&o, opts) {
            done.extend(o.segment);
            continue;
        }
        let (a, b) = o.task.t;
        let m = a + (b - a) * o.split;
        // every outcome still to be looked at ends as at least one segment
        let room =
            done.len() + unreached_segs.len() + next.len() + pending + 2 <= opts.max_segments;
        let give_up = o.stuck && o.task.stuck_before;
        if !give_up && o.task.depth < opts.max_depth && m > a && m < b && room {
            for t in [(a, m), (m, b)] {
                next.push(Task {
                    piece: o.task.piece,
                    t,
                    depth: o.task.depth + 1,
                    stuck_before: o.stuck,
                });
            }
        } else if let Some(s) = o.segment {
            unreached_segs.push(s);
        } else {
            // no construction at all: keep the exact span's chord offset? No —
            // report an unreached segment with an infinite bound.
            unreached_segs.extend(chord_segment(&curve[o.task.piece], &o.task));
        }
    }
    next
}

/// Proven within tol, or (certify: false) estimated within it.
///
/// With the paper's acceptance a segment with a measure is accepted by the
/// measure alone, as the paper does (a segment whose measure is above tol is
/// split even when its true error is below it).
fn accepted(o: &Outcome, opts: &OffsetOptions) -> bool {
    o.segment.as_ref().is_some_and(|s| match s.paper_error {
        Some(e) if opts.accept_paper => e <= opts.tol.value(),
        _ => s.error.1 <= opts.tol.value() || s.estimate.is_some_and(|e| e <= opts.tol.value()),
    })
}

/// The unreached placeholder of a span without any construction: the chord
/// of the span of `x`, with an infinite bound.
fn chord_segment(x: &Bezier<Rational>, task: &Task) -> Option<OffsetSegment> {
    let sub = span_f64(x, task.t)?;
    let p = sub.points();
    Some(OffsetSegment {
        piece: task.piece,
        t: task.t,
        bezier: Bezier::new(vec![p[0].clone(), p[p.len() - 1].clone()]),
        error: (0.0, f64::INFINITY),
        paper_error: None,
        proof: None,
        estimate: None,
    })
}

/// The accepted and unreached segments in input order, the indices of the
/// unreached ones, and the largest certified bound.
fn in_order(
    done: Vec<OffsetSegment>,
    unreached_segs: Vec<OffsetSegment>,
) -> (Vec<OffsetSegment>, Vec<usize>, f64) {
    let mut segments: Vec<(OffsetSegment, bool)> = done
        .into_iter()
        .map(|s| (s, false))
        .chain(unreached_segs.into_iter().map(|s| (s, true)))
        .collect();
    segments.sort_by(|a, b| {
        (a.0.piece, a.0.t.0)
            .partial_cmp(&(b.0.piece, b.0.t.0))
            .unwrap_or(std::cmp::Ordering::Equal)
    });
    let unreached = segments
        .iter()
        .enumerate()
        .filter(|(_, s)| s.1)
        .map(|(i, _)| i)
        .collect();
    let segments: Vec<OffsetSegment> = segments.into_iter().map(|s| s.0).collect();
    let certified_hi = segments.iter().map(|s| s.error.1).fold(0.0, f64::max);
    (segments, unreached, certified_hi)
}

/// Per piece, the parameters `(piece, t)` to cut the initial spans at.
fn cusp_cuts(pieces: usize, at: impl Iterator<Item = (usize, f64)>) -> Vec<Vec<f64>> {
    let mut cuts = vec![Vec::new(); pieces];
    for (i, t) in at {
        if let Some(c) = cuts.get_mut(i) {
            c.push(t);
        }
    }
    cuts
}
