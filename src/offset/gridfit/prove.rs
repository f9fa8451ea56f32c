//! The proof of each cubic against its targets (splitting on failure), the
//! numbering of the results and the certificate.

use super::fitting::two_sided_capped;
use super::outline::{Contour, Ctx, Joint, Part, Pos};
use super::{
    GridOffset, GridSegment, OffsetError, ProofPath, Target, MAX_DEPTH, SPLIT_SHARE, WINDOW_STEPS,
};
use crate::certify::piece::Piece as CPiece;
use crate::certify::{Certificate, Config, CoverBox, HausdorffBounds, MapCover};
use crate::curve::{Bezier, V2};
use crate::scalar::Rational;
use crate::shape::ArcDesc;
use glam::DVec2;
use rayon::prelude::*;

/// One proven (or failed) cubic before numbering.
pub(super) struct Built {
    pub(super) bezier: Bezier<f64>,
    pub(super) targets: Vec<Target>,
    pub(super) bounds: Option<HausdorffBounds>,
    pub(super) error: (f64, f64),
}

impl Ctx<'_> {
    /// Fits and proves the cubic between two joints, splitting on failure.
    pub(super) fn segment(
        &self,
        c: &Contour,
        a: Joint,
        b: Joint,
        depth: u32,
        stats: &Stats,
    ) -> Vec<Built> {
        let ranges = self.ranges(c, a.pos, b.pos);
        let targets: Option<Vec<Target>> = ranges
            .iter()
            .map(|&(k, u0, u1)| self.target_of(&c.parts[k], u0, u1))
            .collect();
        let dense = self.dense(c, &ranges, 48);
        let fitted = dense.as_ref().and_then(|d| self.fit(c, &a, &b, d));
        let split = |stats: &Stats| -> Option<Vec<Built>> {
            if depth >= MAX_DEPTH
                || stats.refits.load(std::sync::atomic::Ordering::Relaxed) >= self.max_splits
            {
                log::trace!("gridfit split refused at depth {depth}: depth or split budget spent");
                return None;
            }
            let d = dense.as_ref()?;
            let mid = d[d.len() / 2].0;
            if mid == a.pos || mid == b.pos {
                log::trace!("gridfit split refused at depth {depth}: the middle is a joint");
                return None;
            }
            // the walk stays inside (a, b); across the closing joint of a
            // closed contour it stays on mid's side of it
            let (lo, hi) = if a.pos.before(b.pos) {
                (a.pos, b.pos)
            } else if a.pos.before(mid) {
                (
                    a.pos,
                    Pos {
                        part: c.parts.len() - 1,
                        u: 1.0,
                    },
                )
            } else {
                (Pos { part: 0, u: 0.0 }, b.pos)
            };
            let len = self.length(c, a.pos, b.pos);
            let window = (0.25 * len).min(WINDOW_STEPS * self.gf);
            let Some((m, dist)) = self.snap_split(c, mid, lo, hi, window, &[a.g, b.g]) else {
                log::trace!("gridfit split refused at depth {depth}: no joint near {mid:?}");
                return None;
            };
            // a joint off the curve by more than tol/2 leaves the cubics less
            // room, but may still be proven: up to 0.9 tol
            if dist.is_nan()
                || dist > SPLIT_SHARE * self.tol.value()
                || m.pos == a.pos
                || m.pos == b.pos
                || m.g == a.g
                || m.g == b.g
            {
                log::trace!(
                    "gridfit split refused at depth {depth}: mid {mid:?} -> {m:?} (off {dist}), joints {a:?} {b:?}"
                );
                return None;
            }
            stats
                .refits
                .fetch_add(1, std::sync::atomic::Ordering::Relaxed);
            let (l, r) = rayon::join(
                || self.segment(c, a, m, depth + 1, stats),
                || self.segment(c, m, b, depth + 1, stats),
            );
            Some(l.into_iter().chain(r).collect())
        };
        // nothing to prove: a straight placeholder keeps the contour closed and
        // is reported unreached
        let placeholder = |targets: Option<Vec<Target>>| {
            let v = |p: DVec2| V2::new(p.x, p.y);
            let bezier = if self.quadratic {
                Bezier::new(vec![v(a.g), v(a.g), v(b.g)])
            } else {
                Bezier::new(vec![v(a.g), v(a.g), v(b.g), v(b.g)])
            };
            vec![Built {
                bezier,
                targets: targets.unwrap_or_default(),
                bounds: None,
                error: (0.0, f64::INFINITY),
            }]
        };
        let (Some(targets), Some(bez)) = (targets.clone(), fitted) else {
            return split(stats).unwrap_or_else(|| placeholder(targets));
        };
        let pieces: Option<Vec<CPiece>> = targets.iter().map(|t| self.target_piece(t)).collect();
        let (Some(pa), Some(pb)) = (pieces, crate::certify::piece::bezier_f64(&bez)) else {
            return split(stats).unwrap_or_else(|| placeholder(Some(targets)));
        };
        // a sampled error above the tolerance: split without a proof
        let pts: Vec<DVec2> = dense
            .as_ref()
            .map_or(Vec::new(), |d| d.iter().map(|p| p.1).collect());
        let thr = self.tol.value();
        if depth < MAX_DEPTH && two_sided_capped(&pts, &bez, thr.next_up()) > thr {
            if let Some(v) = split(stats) {
                return v;
            }
        }
        let cfg = Config {
            tol: Some(self.tol.clone()),
            max_boxes: self.max_boxes,
            verdict_only: depth < MAX_DEPTH,
            ..Config::default()
        };
        stats
            .certifications
            .fetch_add(1, std::sync::atomic::Ordering::Relaxed);
        let abs = || 1e-10 * (1.0 + a.g.abs().max_element() + b.g.abs().max_element());
        let r = crate::certify::hausdorff_pieces(&pa, &[pb], &cfg, &abs);
        if r.hi <= self.tol.value() {
            return vec![Built {
                bezier: bez,
                targets,
                error: (r.lo, r.hi),
                bounds: Some(r),
            }];
        }
        if let Some(v) = split(stats) {
            return v;
        }
        vec![Built {
            bezier: bez,
            targets,
            error: (r.lo, r.hi),
            bounds: None,
        }]
    }

    /// Fits and proves the cubics between consecutive joints (cyclically on
    /// a closed contour), in parallel.
    pub(super) fn build(&self, c: &Contour, joints: &[Joint], stats: &Stats) -> Vec<Built> {
        let pairs: Vec<(Joint, Joint)> = if c.closed {
            (0..joints.len())
                .map(|i| (joints[i], joints[(i + 1) % joints.len()]))
                .collect()
        } else {
            joints.windows(2).map(|w| (w[0], w[1])).collect()
        };
        let built: Vec<Vec<Built>> = pairs
            .par_iter()
            .map(|(a, b)| self.segment(c, *a, *b, 0, stats))
            .collect();
        built.into_iter().flatten().collect()
    }

    fn target_of(&self, part: &Part, u0: f64, u1: f64) -> Option<Target> {
        match part {
            Part::Span { piece, .. } => Some(Target::Span {
                piece: *piece,
                t: (part.param(u0), part.param(u1)),
            }),
            Part::Arc {
                center,
                radius,
                sweep,
                ..
            } => {
                let (d0, d1) = (part.arc_dir(u0)?, part.arc_dir(u1)?);
                let (from, to) = if *sweep > 0.0 { (d0, d1) } else { (d1, d0) };
                Some(Target::Arc(ArcDesc {
                    center: center.clone(),
                    radius: radius.clone(),
                    from,
                    to,
                }))
            }
        }
    }

    fn target_piece(&self, t: &Target) -> Option<CPiece> {
        match t {
            Target::Span { piece, t } => match self.kernel {
                Some(k) => k.span_piece(&self.curve[*piece], *t),
                None => crate::certify::piece::bezier_span(&self.curve[*piece], *t),
            },
            Target::Arc(a) => CPiece::arc(a).ok(),
        }
    }
}

#[derive(Default)]
pub(super) struct Stats {
    pub(super) refits: std::sync::atomic::AtomicUsize,
    pub(super) certifications: std::sync::atomic::AtomicUsize,
}

/// A contour's first segment, number of segments and closedness.
type ContourRange = (usize, usize, bool);

/// The built cubics as segments, contour after contour, with their bounds
/// and, per contour, its first segment, number of segments and closedness.
pub(super) fn number(
    built_contours: Vec<Vec<Built>>,
    contours: &[Contour],
) -> (
    Vec<GridSegment>,
    Vec<Option<HausdorffBounds>>,
    Vec<ContourRange>,
) {
    let mut segments = Vec::new();
    let mut bounds = Vec::new();
    let mut contour_ranges = Vec::new();
    // number the targets: spans first (the offset member), then arcs
    for (ci, built) in built_contours.into_iter().enumerate() {
        contour_ranges.push((segments.len(), built.len(), contours[ci].closed));
        for b in built {
            segments.push(GridSegment {
                bezier: b.bezier,
                contour: ci,
                targets: b.targets,
                error: b.error,
                proof: b.bounds.as_ref().map(ProofPath::of),
            });
            bounds.push(b.bounds);
        }
    }
    (segments, bounds, contour_ranges)
}

/// The certificate of a reached [`GridOffset`]: every cover box renumbered to
/// the global pieces (`a`: spans, then arcs; `b`: the cubics).
pub(super) fn certificate(
    curve: &[Bezier<Rational>],
    d: &Rational,
    res: &GridOffset,
    bounds: &[Option<HausdorffBounds>],
) -> Result<Option<Certificate>, OffsetError> {
    let spans_total = res
        .segments
        .iter()
        .flat_map(|s| &s.targets)
        .filter(|t| matches!(t, Target::Span { .. }))
        .count();
    let (mut next_span, mut next_arc) = (0usize, spans_total);
    let (mut maps, mut ab, mut ba) = (Vec::new(), Vec::new(), Vec::new());
    for (i, (s, b)) in res.segments.iter().zip(bounds).enumerate() {
        let Some(r) = b else {
            return Ok(None);
        };
        let global: Vec<usize> = s
            .targets
            .iter()
            .map(|t| match t {
                Target::Span { .. } => {
                    next_span += 1;
                    next_span - 1
                }
                Target::Arc(_) => {
                    next_arc += 1;
                    next_arc - 1
                }
            })
            .collect();
        match &r.parametric {
            Some(m) => {
                let a_idx = global[0];
                let (piece, target) = if m.source_a { (a_idx, i) } else { (i, a_idx) };
                maps.push(MapCover {
                    from_a: m.source_a,
                    piece,
                    target,
                    boxes: m.boxes.clone(),
                    hi: m.hi,
                });
            }
            None => {
                ab.extend(r.a_to_b.boxes.iter().map(|bx| CoverBox {
                    piece: global[bx.piece],
                    target: i,
                    ..bx.clone()
                }));
                ba.extend(r.b_to_a.boxes.iter().map(|bx| CoverBox {
                    piece: i,
                    target: global[bx.target],
                    ..bx.clone()
                }));
            }
        }
    }
    // the verifier reads each direction's boxes piece after piece
    for bs in [&mut ab, &mut ba] {
        bs.sort_by(|x: &CoverBox, y: &CoverBox| {
            x.piece.cmp(&y.piece).then(x.s.0.total_cmp(&y.s.0))
        });
    }
    let a = res.exact_shape(curve, d)?;
    let b = res.approximant_shape()?;
    Ok(Certificate::assemble(&a, &b, &res.tol, &maps, &ab, &ba))
}
