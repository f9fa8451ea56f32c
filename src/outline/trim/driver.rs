//! The driver: [`stroke`] and its phases.

use super::chain::{chain, check_simple};
use super::classify::{foot, prove_kept, prove_removed, Part};
use super::pinch::pinched_loops;
use super::sides::{approx_dir, check, raw_contours, Kind, Raw};
use super::split::{mid_rational, project_on_segment, segment_crossing, split_piece, Split, Sub};
use super::types::{
    Cap, Claim, Classified, Piece, RawCrossing, Stroke, StrokeError, StrokeOptions,
};
use crate::curve::{Bezier, V2};
use crate::outline::circle::{arcs_meet, bezier_arc, snap};
use crate::outline::intersect::{intersections, IntersectOptions};
use crate::scalar::{rational_from_f64, Rational, Scalar};
use num_traits::{One, Zero};

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
/// use lncert::outline::trim::{stroke, StrokeOptions, Orientation};
/// use lncert::shape::parse_curve;
/// use lncert::parse_rational;
/// // a straight segment: the stadium, two segments and two half circles
/// let x = parse_curve("M 0 0 L 2 0").unwrap();
/// let s = stroke(&x, &StrokeOptions::new(parse_rational("1/2").unwrap(), 1e-3)).unwrap();
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

/// [`stroke`] with the sides built within `TOL / raw_div`.
fn stroke_at(
    curve: &[Bezier<Rational>],
    opts: &StrokeOptions,
    raw_div: f64,
) -> Result<Stroke, StrokeError> {
    let comps = check(curve, opts)?;
    let closed = comps.iter().all(|c| c.2);
    let form = opts.form()?;
    let form = &form;
    let dbg = std::env::var("LNCERT_TRIM_DEBUG").is_ok();
    let t0 = std::time::Instant::now();
    // every component's sides and caps; the trimming below is over all of
    // them (the region is the union of the components' regions)
    let mut raw_contours_all = Vec::new();
    let mut notes = Vec::new();
    let mut caps = Vec::new();
    for &(first, end, c_closed) in &comps {
        let (rc, n, cp) = raw_contours(&curve[first..end], opts, c_closed, first, raw_div)?;
        raw_contours_all.extend(rc);
        notes.extend(n);
        caps.extend(cp);
    }
    let raw_contours = raw_contours_all;
    if dbg {
        eprintln!("offsets: {:?}", t0.elapsed());
    }
    let raws: Vec<Raw> = raw_contours.into_iter().flatten().collect();
    let curve_f: Vec<Bezier<f64>> = curve.iter().map(|b| b.map(Scalar::approx)).collect();

    // --- crossings of the raw arrangement
    let iopts = IntersectOptions {
        max_boxes_per_pair: opts.max_boxes_per_pair,
        self_intersections: true,
    };
    let bez_idx: Vec<usize> = (0..raws.len())
        .filter(|&i| matches!(raws[i].piece, Piece::Bezier(_)))
        .collect();
    let arc_idx: Vec<usize> = (0..raws.len())
        .filter(|&i| matches!(raws[i].piece, Piece::Arc(_)))
        .collect();
    let bez: Vec<Bezier<Rational>> = bez_idx
        .iter()
        .map(|&i| match &raws[i].piece {
            Piece::Bezier(b) => b.clone(),
            Piece::Arc(_) => unreachable!(),
        })
        .collect();
    let inter = intersections(&bez, &iopts);
    if dbg {
        eprintln!(
            "raw intersections: {:?} {} boxes",
            t0.elapsed(),
            inter.boxes
        );
        for (k, r) in raws.iter().enumerate() {
            eprintln!(
                "raw {k}: {:?} e={:.3e} {:?}",
                r.kind,
                r.e,
                match &r.piece {
                    Piece::Bezier(b) => format!(
                        "bez deg {} {:?}",
                        b.degree(),
                        b.map(Scalar::approx).points()
                    ),
                    Piece::Arc(a) => format!("arc {:?}", a.desc()),
                }
            );
        }
        for u in &inter.undecided {
            eprintln!("undecided {:?}", u);
        }
    }
    let mut raw_complete = inter.complete;
    let mut splits: Vec<Vec<Split>> = vec![Vec::new(); raws.len()];
    let mut crossings = Vec::new();
    let fail = |notes: &mut Vec<String>, s: String| {
        if notes.len() < 20 && !notes.contains(&s) {
            notes.push(s);
        }
    };
    for u in &inter.undecided {
        fail(
            &mut notes,
            format!(
                "raw pieces {} and {}: {} region undecided",
                bez_idx[u.pieces.0], bez_idx[u.pieces.1], u.reason
            ),
        );
    }
    for c in &inter.crossings {
        let (i, j) = (bez_idx[c.pieces.0], bez_idx[c.pieces.1]);
        let (px, py) = (
            mid_rational(c.point.0 .0, c.point.0 .1),
            mid_rational(c.point.1 .0, c.point.1 .1),
        );
        let (s, t) = (mid_rational(c.s.0, c.s.1), mid_rational(c.t.0, c.t.1));
        // two straight segments: their crossing is rational, split exactly
        // there (no end moves; an exact point keeps later joints exact)
        let exact = match (&raws[i].piece, &raws[j].piece) {
            (Piece::Bezier(a), Piece::Bezier(b)) => segment_crossing(a, b),
            _ => None,
        };
        let (px, py, s, t) = match exact {
            Some((p, s, t)) => (Some(p.x), Some(p.y), Some(s), Some(t)),
            None => match (&raws[i].piece, &raws[j].piece, &px, &py) {
                // one straight segment: the crossing point projected onto
                // it exactly, so its halves stay on its line (a half tilted
                // by an ulp would meet the next join arc almost tangentially)
                (Piece::Bezier(a), _, Some(x), Some(y)) if a.degree() == 1 => {
                    match project_on_segment(a, &V2::new(x.clone(), y.clone())) {
                        Some((q, u)) => (Some(q.x), Some(q.y), Some(u), t),
                        None => (px, py, s, t),
                    }
                }
                (_, Piece::Bezier(b), Some(x), Some(y)) if b.degree() == 1 => {
                    match project_on_segment(b, &V2::new(x.clone(), y.clone())) {
                        Some((q, u)) => (Some(q.x), Some(q.y), s, Some(u)),
                        None => (px, py, s, t),
                    }
                }
                _ => (px, py, s, t),
            },
        };
        if let (Some(xx), Some(xy), Some(s), Some(t)) = (px, py, s, t) {
            let point = V2::new(xx, xy);
            splits[i].push(Split {
                param: s,
                point: point.clone(),
            });
            splits[j].push(Split { param: t, point });
            crossings.push(RawCrossing {
                pieces: (i, j),
                s: c.s,
                t: c.t,
            });
        }
    }
    // Bézier–arc
    for &ai in &arc_idx {
        let Piece::Arc(arc) = &raws[ai].piece else {
            continue;
        };
        for &bi in &bez_idx {
            let Piece::Bezier(b) = &raws[bi].piece else {
                continue;
            };
            let m = bezier_arc(b, arc);
            if dbg && (!m.hits.is_empty() || !m.undecided.is_empty()) {
                eprintln!("bez {bi} arc {ai}: {:?}", m);
            }
            if !m.undecided.is_empty() {
                raw_complete = false;
                fail(
                    &mut notes,
                    format!("raw pieces {bi} and {ai}: arc range undecided"),
                );
            }
            for h in m.hits {
                // the joint: the Bézier's end point is the arc's end point
                if h.t.0 == h.t.1 {
                    let zero = <Rational as Zero>::zero();
                    let one = <Rational as One>::one();
                    let pt = if h.t.0 == zero {
                        Some(b.points()[0].clone())
                    } else if h.t.0 == one {
                        b.points().last().cloned()
                    } else {
                        None
                    };
                    if let Some(pt) = pt {
                        if pt == arc.from || pt == arc.to {
                            continue;
                        }
                    }
                }
                if h.multiple {
                    raw_complete = false;
                    fail(
                        &mut notes,
                        format!("raw pieces {bi} and {ai}: tangential contact"),
                    );
                    continue;
                }
                let s = (&h.t.0 + &h.t.1) / Rational::from_integer(2.into());
                let p = b.eval(&s);
                let x = snap(&arc.center, &arc.radius, approx_dir(&p.sub(&arc.center)));
                match x {
                    Some(x)
                        if arc.contains_dir(&x.sub(&arc.center)) == Some(true)
                            && x != arc.from
                            && x != arc.to =>
                    {
                        splits[bi].push(Split {
                            param: s,
                            point: x.clone(),
                        });
                        splits[ai].push(Split {
                            param: <Rational as Zero>::zero(),
                            point: x,
                        });
                        crossings.push(RawCrossing {
                            pieces: (bi.min(ai), bi.max(ai)),
                            s: (h.t.0.approx(), h.t.1.approx()),
                            t: (0.0, 0.0),
                        });
                    }
                    _ => {
                        raw_complete = false;
                        fail(
                            &mut notes,
                            format!("raw pieces {bi} and {ai}: crossing at an arc end"),
                        );
                    }
                }
            }
        }
    }
    // arc–arc: a crossing cannot be split exactly: undecided
    for (k, &ai) in arc_idx.iter().enumerate() {
        for &aj in &arc_idx[k + 1..] {
            let (Piece::Arc(a), Piece::Arc(b)) = (&raws[ai].piece, &raws[aj].piece) else {
                continue;
            };
            let shared = [&a.from, &a.to]
                .into_iter()
                .find(|p| **p == b.from || **p == b.to);
            if arcs_meet(a, b, shared) != Some(false) {
                raw_complete = false;
                fail(
                    &mut notes,
                    format!("raw arcs {ai} and {aj} may meet (arc–arc crossings are not split)"),
                );
            }
        }
    }

    if dbg {
        eprintln!("arcs: {:?}", t0.elapsed());
    }
    // --- split
    let mut subs: Vec<Sub> = Vec::new();
    for (i, raw) in raws.iter().enumerate() {
        subs.extend(split_piece(i, &raw.piece, &mut splits[i]));
    }

    // --- classify: kept first (the near-crossing relaxation of removal needs them)
    let tol = opts.tol;
    use rayon::prelude::*;
    let estimates: Vec<f64> = subs
        .par_iter()
        .map(|s| {
            let (m, _) = Part::initial(&s.pre)
                .and_then(|p| p.into_iter().next())
                .map(|p| p.mid_right_normal())
                .unwrap_or(((0.0, 0.0), (0.0, 0.0)));
            foot(&curve_f, form, m).0
        })
        .collect();
    if dbg {
        eprintln!("estimates: {:?}", t0.elapsed());
    }
    let rf = form.reach;
    let onside_input = form
        .circle
        .then(|| crate::outline::onside::Input::new(curve, &comps, &opts.radius));
    let kept_bounds: Vec<Option<f64>> = subs
        .par_iter()
        .zip(&estimates)
        .map(|(s, est)| {
            let tt = std::time::Instant::now();
            let r = (|| {
                let raw = &raws[s.raw];
                let e_in = raw.e_in + s.delta;
                if raw.kind == Kind::Butt {
                    return Some(e_in);
                }
                if *est < rf - 4.0 * e_in.max(tol / 8.0) {
                    return None;
                }
                // one decision for the whole sub-piece where the exact offset
                // points it stands for are proven on ∂S (module `onside`); an
                // exact cap or join arc is its own exact counterpart
                if let (Piece::Arc(arc), Some(input)) = (&s.pre, &onside_input) {
                    let budget = tol - e_in;
                    if budget > 0.0 {
                        if let Some(l) = input.prove_arc(arc, budget, 2048) {
                            return Some(e_in + l);
                        }
                    }
                    if dbg {
                        eprintln!("onside failed: raw {} (arc)", s.raw);
                    }
                }
                if let (Some(link), Some(input)) = (&raw.link, &onside_input) {
                    let budget = tol - e_in;
                    let range = (s.range.0.approx(), s.range.1.approx());
                    let pad = 1e-12;
                    if budget > 0.0 {
                        if let Some((t0, t1)) = link.exact_range(range.0 - pad, range.1 + pad) {
                            if let Some(l) =
                                input.prove_interval(link.piece, &link.d, t0, t1, budget, 2048)
                            {
                                return Some(e_in + l);
                            }
                            if dbg {
                                eprintln!(
                                    "onside failed: raw {} piece {} t [{t0}, {t1}]",
                                    s.raw, link.piece
                                );
                            }
                        } else if dbg {
                            eprintln!("onside: no exact range for raw {}", s.raw);
                        }
                    }
                }
                prove_kept(curve, &curve_f, &s.post, e_in, form, tol)
            })();
            if dbg {
                eprintln!("kept raw {} {:?} {:?}", s.raw, tt.elapsed(), r);
            }
            r
        })
        .collect();
    if dbg {
        eprintln!("kept: {:?}", t0.elapsed());
    }
    let near: Vec<V2<Rational>> = subs
        .iter()
        .zip(&kept_bounds)
        .filter(|(_, k)| k.is_some())
        .flat_map(|(s, _)| {
            let mut v = Vec::new();
            if s.end_splits[0] {
                v.push(s.post.start().clone());
            }
            if s.end_splits[1] {
                v.push(s.post.end().clone());
            }
            v
        })
        .collect();
    // λ of the removal: a removed part within λ of a kept crossing point
    // costs (b) e + λ, so λ may use what TOL leaves above e (at least TOL/2)
    let lambda_f = |e: f64| (0.95 * (tol - e)).max(tol / 2.0);
    let lambda_for =
        |e: f64| rational_from_f64(lambda_f(e)).unwrap_or_else(<Rational as Zero>::zero);
    let removed: Vec<Option<bool>> = subs
        .par_iter()
        .zip(&kept_bounds)
        .map(|(s, k)| {
            let raw = &raws[s.raw];
            if k.is_some() || raw.kind != Kind::Boundary {
                return None;
            }
            let tt = std::time::Instant::now();
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
            let lambda = lambda_for(raw.e);
            let r = prove_removed(curve, &curve_f, &s.pre, raw.e, &local, form, &near, &lambda);
            if dbg {
                eprintln!("removed raw {} {:?} {:?}", s.raw, tt.elapsed(), r);
            }
            r
        })
        .collect();
    let mut classified = Classified::default();
    let mut a_bound: f64 = 0.0;
    let mut b_bound: f64 = 0.0;
    let mut a_ok = true;
    let mut b_ok = true;
    let mut keep = vec![false; subs.len()];
    for (k, s) in subs.iter().enumerate() {
        let raw = &raws[s.raw];
        if let Some(bd) = kept_bounds[k] {
            classified.kept += 1;
            keep[k] = true;
            a_bound = a_bound.max(bd);
            if raw.kind == Kind::Boundary {
                b_bound = b_bound.max(raw.e + s.delta);
            }
        } else if raw.kind == Kind::Connector {
            classified.dropped_connectors += 1;
        } else if let Some(used) = removed[k] {
            classified.removed += 1;
            b_bound = b_bound.max(raw.e);
            if used {
                // the λ the removal test was given (its rational is exactly
                // this f64), plus a hair for the sum's rounding
                b_bound = b_bound.max((raw.e + lambda_f(raw.e)) * (1.0 + 1e-12));
            }
        } else {
            classified.undecided += 1;
            a_ok = false;
            b_ok = false;
            // shown, not proven: keep what looks like boundary
            keep[k] = estimates[k] >= rf - 2.0 * (raw.e_in + s.delta);
            fail(
                &mut notes,
                format!(
                    "sub-piece of raw piece {} undecided (distance estimate {:.6})",
                    s.raw, estimates[k]
                ),
            );
        }
    }
    for raw in &raws {
        if raw.kind == Kind::Boundary && !raw.e.is_finite() {
            b_ok = false;
        }
    }

    if dbg {
        eprintln!("classified: {:?}", t0.elapsed());
    }
    // --- pinched loops and spurs: kept pieces that close a loop at an exact
    // point X of the output, or dangle from one, each within a certified reach
    // of the pieces that stay at X, are dropped (a boundary point near them
    // is within e + δ + reach of the output)
    let kept_idx: Vec<usize> = (0..subs.len()).filter(|&k| keep[k]).collect();
    // a spur may reach as far from the live pieces as keeps (b) within tol
    let spur_caps: Vec<f64> = kept_idx
        .iter()
        .map(|&k| {
            let raw = &raws[subs[k].raw];
            if raw.kind == Kind::Boundary {
                tol - raw.e - subs[k].delta
            } else {
                // a connector or butt chord stands for no point of ∂S
                tol
            }
        })
        .collect();
    let dropped = pinched_loops(
        &kept_idx.iter().map(|&k| &subs[k].post).collect::<Vec<_>>(),
        &spur_caps,
    );
    if !dropped.is_empty() {
        for &(d, reach) in &dropped {
            let k = kept_idx[d];
            keep[k] = false;
            let raw = &raws[subs[k].raw];
            if raw.kind == Kind::Boundary {
                b_bound = b_bound.max(raw.e + subs[k].delta + reach);
            }
        }
        fail(
            &mut notes,
            format!(
                "{} kept pieces forming pinched loops or spurs dropped (each within a certified reach of the pieces that stay at its point, added to (b))",
                dropped.len()
            ),
        );
    }
    // --- chain
    let out_pieces: Vec<Piece> = subs
        .iter()
        .zip(&keep)
        .filter(|(_, k)| **k)
        .map(|(s, _)| s.post.clone())
        .collect();
    let contours = chain(out_pieces);

    // --- claim (c)
    let (c_ok, c_complete, c_note) = check_simple(&contours, &iopts);
    if dbg {
        eprintln!("checked: {:?}", t0.elapsed());
        for (k, s) in subs.iter().enumerate() {
            eprintln!(
                "sub {k}: raw {} [{:.6}, {:.6}] keep {} kept {:?} removed {:?} est {:.6} delta {:.2e}",
                s.raw, s.range.0.approx(), s.range.1.approx(), keep[k], kept_bounds[k], removed[k], estimates[k], s.delta
            );
        }
    }
    let offsets_ok = notes.iter().all(|n| !n.contains("did not reach"));
    let butt = !closed && opts.cap == Cap::Butt;
    let a = Claim {
        proven: a_ok && offsets_ok && a_bound <= tol && !butt,
        bound: if a_ok { a_bound } else { f64::INFINITY },
        note: if butt {
            "not claimed for butt caps (the region is not x ⊕ pen)".into()
        } else if a_ok {
            format!("every kept sub-piece is within {a_bound:.3e} of exact offset points proven on ∂S, or of a point proven outside S and a point of S")
        } else {
            "some sub-pieces could not be classified".into()
        },
    };
    let b = Claim {
        proven: b_ok && offsets_ok && b_bound <= tol && !butt,
        bound: if b_ok { b_bound } else { f64::INFINITY },
        note: if butt {
            "not claimed for butt caps (the region is not x ⊕ pen)".into()
        } else if b_ok {
            format!(
                "every sub-piece of the raw pieces is kept or proven interior; bound {b_bound:.3e}"
            )
        } else {
            "some sub-pieces could not be classified".into()
        },
    };
    let c = Claim {
        proven: c_ok,
        bound: 0.0,
        note: c_note,
    };

    Ok(Stroke {
        contours,
        crossings,
        raw_pieces: raws.len(),
        raw_complete,
        complete: c_complete,
        a,
        b,
        c,
        classified,
        tol,
        closed_curve: closed,
        notes,
        pen: opts.ellipse.clone(),
        caps,
    })
}
