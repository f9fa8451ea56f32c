//! Contours of Bézier pieces refitted on a grid: the same joints, fits and
//! proofs as [`super::offset_on_grid`], with the exact curve the contours
//! themselves (no offset) and their sharp corners as nominal joints.

use super::outline::{Contour, Ctx, Part};
use super::prove::{self, Built, Stats};
use super::{GridOffset, OffsetError};
use crate::curve::Bezier;
use crate::offset::fit::{self, Reach};
use crate::offset::options::bad;
use crate::scalar::{Rational, Scalar};
use crate::Tolerance;
use num_traits::{Signed, Zero};

/// What [`chain_on_grid`] fits and proves to.
#[derive(Clone, Debug)]
pub struct ChainGridOptions {
    /// The grid (a positive dyadic rational: `1` is integer font units).
    pub grid: Rational,
    /// Every output piece is proven within `tol` of its part of the chain.
    pub tol: Tolerance,
    /// Quadratic output (TrueType) instead of cubic.
    pub quadratic: bool,
    /// Cover boxes per certified search.
    pub max_boxes: usize,
    /// Splits after failed proofs, in all.
    pub max_splits: usize,
    /// A quadratic, or a cubic with both inner points at one place, may turn
    /// by less than `acos(−hairpin_cos)`: `1` (the default) allows any turn
    /// short of a reversal (the sharp tips of `V`, `w`); `0.9` stops at about
    /// 154° (a tip that sharp may cross its neighbours next to its joint).
    pub hairpin_cos: f64,
}

impl ChainGridOptions {
    /// Cubic output with the offset engine's default limits.
    pub fn new(grid: Rational, tol: Tolerance) -> ChainGridOptions {
        ChainGridOptions {
            grid,
            tol,
            quadratic: false,
            max_boxes: 50_000,
            max_splits: 20_000,
            hairpin_cos: 1.0,
        }
    }
}

/// Contours of Bézier pieces (each contour's pieces joined end to start,
/// closed when its last end is its first start) as cubics (or quadratics)
/// whose every control point is a multiple of `opts.grid`, each proven
/// within `opts.tol` of its part of the input, even when `tol` is below the
/// grid's rounding move `grid·√2/2` (where rounding the control points
/// cannot be proven).
///
/// The joints between output pieces are moved along the input to places
/// where it passes near a grid point (the input's sharp corners are nominal
/// joints, and one piece turns round a corner when no grid point is near
/// it); the output pieces' targets — spans `t` of the input pieces, numbered
/// across the contours in order — partition the input, so
/// `d_H(input, output) ≤ certified_hi` contour by contour. The result has no
/// certificate (`certificate: None`); `base_segments` counts the input
/// pieces and `corner_arcs` is 0.
///
/// Errors: no contour, a contour that is not joined end to start, a piece
/// of degree 0, or a grid that is not dyadic or whose multiples are not
/// exact `f64` numbers over the input's coordinates.
///
/// # Examples
/// ```
/// use lncert::offset::{chain_on_grid, ChainGridOptions};
/// use lncert::shape::parse_curve;
/// let q = |s: &str| lncert::parse_rational(s).unwrap();
/// // a closed contour with a sharp corner at an irrational-looking place
/// let x = parse_curve("M 0.3 0.4 C 100.3 -30 200 60 150.7 150.2 L 0.3 0.4").unwrap();
/// let opts = ChainGridOptions::new(q("1"), "0.4".parse().unwrap());
/// let r = chain_on_grid(&[x], &opts).unwrap();
/// assert!(r.reached() && r.certified_hi <= 0.4);
/// for s in &r.segments {
///     assert!(s.bezier.points().iter().all(|p| p.x.fract() == 0.0 && p.y.fract() == 0.0));
/// }
/// ```
pub fn chain_on_grid(
    contours: &[Vec<Bezier<Rational>>],
    opts: &ChainGridOptions,
) -> Result<GridOffset, OffsetError> {
    if contours.iter().all(|c| c.is_empty()) {
        return Err(bad("curve", "no pieces"));
    }
    let mut curve: Vec<Bezier<Rational>> = Vec::new();
    let mut parts_of: Vec<Contour> = Vec::new();
    let mut scale: f64 = 0.0;
    for (k, c) in contours.iter().enumerate() {
        if c.is_empty() {
            continue;
        }
        for (i, b) in c.iter().enumerate() {
            if b.degree() == 0 {
                return Err(bad(
                    "curve",
                    format!("contour {k}, piece {i}: a single point"),
                ));
            }
            for p in b.points() {
                let m = p.x.approx().abs().max(p.y.approx().abs());
                if !m.is_finite() {
                    return Err(bad("curve", format!("contour {k}, piece {i}: too large")));
                }
                scale = scale.max(m);
            }
            if i > 0 && c[i - 1].points().last() != b.points().first() {
                return Err(bad(
                    "curve",
                    format!(
                        "contour {k}, piece {i} does not start where piece {} ends",
                        i - 1
                    ),
                ));
            }
        }
        let closed = c.last().and_then(|b| b.points().last()) == c[0].points().first();
        let first = curve.len();
        curve.extend(c.iter().cloned());
        parts_of.push(Contour {
            parts: (first..curve.len())
                .map(|piece| Part::Span {
                    piece,
                    t: (0.0, 1.0),
                })
                .collect(),
            closed,
        });
    }
    fit::check_grid_storage(&opts.grid, scale)?;
    let ctx = Ctx {
        curve: &curve,
        xf: curve.iter().map(|x| x.map(|v| v.approx())).collect(),
        kernel: None,
        corner_joints: true,
        hairpin_cos: opts.hairpin_cos,
        reach: Reach::Offset(0.0),
        gf: opts.grid.approx(),
        grid: opts.grid.clone(),
        tol: opts.tol.clone(),
        max_boxes: opts.max_boxes,
        max_splits: opts.max_splits,
        quadratic: opts.quadratic,
    };
    let stats = Stats::default();
    let mut max_joint: f64 = 0.0;
    let mut built: Vec<Vec<Built>> = Vec::new();
    for c in &parts_of {
        let joints = ctx.joints(c)?;
        for j in &joints {
            if let Some(p) = ctx.point(&c.parts[j.pos.part], j.pos.u) {
                max_joint = max_joint.max((p - j.g).length());
            }
        }
        let mut b = ctx.build(c, &joints, &stats);
        for x in &mut b {
            if let Some(line) = as_segment(&x.bezier) {
                x.bezier = line;
            }
        }
        built.push(b);
    }
    let (segments, bounds, ranges) = prove::number(built, &parts_of);
    let unreached: Vec<usize> = segments
        .iter()
        .enumerate()
        .filter(|(_, s)| s.proof.is_none())
        .map(|(i, _)| i)
        .collect();
    for &i in &unreached {
        let s = &segments[i];
        log::debug!(
            "chain_on_grid: segment {i} not proven: {:?} against {:?}, error {:?}",
            s.bezier.points(),
            s.targets
                .iter()
                .map(|t| match t {
                    super::Target::Span { piece, t } => {
                        let x = curve[*piece].map(|v| v.approx());
                        (x.eval_fast(t.0), x.eval_fast(t.1))
                    }
                    super::Target::Arc(_) => (glam::DVec2::ZERO, glam::DVec2::ZERO),
                })
                .collect::<Vec<_>>(),
            s.error
        );
    }
    let hi = segments.iter().map(|s| s.error.1).fold(0.0, f64::max);
    Ok(GridOffset {
        grid: opts.grid.clone(),
        tol: opts.tol.clone(),
        certified_hi: if bounds.is_empty() { f64::INFINITY } else { hi },
        segments,
        contours: ranges,
        unreached,
        base_segments: curve.len(),
        refits: stats.refits.into_inner(),
        certifications: stats.certifications.into_inner(),
        corner_arcs: 0,
        max_joint_offset: max_joint,
        certificate: None,
    })
}

/// The segment a Bézier traces when its control points lie on one line with
/// the inner ones between the ends: the curve stays in the segment (convex
/// hull) and runs from one end to the other, so its point set is the
/// segment and every bound proven for it holds for the segment. Exact: the
/// control points are grid multiples, compared as rationals.
pub(super) fn as_segment(b: &Bezier<f64>) -> Option<Bezier<f64>> {
    let pts = b.points();
    if pts.len() < 3 {
        return None;
    }
    let exact = crate::offset::exact_bezier(b)?;
    let q = exact.points();
    let (a, z) = (&q[0], &q[q.len() - 1]);
    let d = z.sub(a);
    let len2 = d.dot(&d);
    if len2.is_zero() {
        return None;
    }
    let inside = q[1..q.len() - 1].iter().all(|p| {
        let v = p.sub(a);
        v.cross(&d).is_zero() && !v.dot(&d).is_negative() && v.dot(&d) <= len2
    });
    inside.then(|| Bezier::new(vec![pts[0].clone(), pts[pts.len() - 1].clone()]))
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::curve::V2;
    use crate::test_util::{qi, tol, TestRng};
    use glam::DVec2;

    /// A closed contour round a star-shaped polygon of `n` vertices at
    /// `k/7`-unit coordinates (sharp corners off the integer grid), each
    /// side a line or a cubic bulging sideways.
    fn contour(rng: &mut TestRng, n: usize) -> Vec<Bezier<Rational>> {
        let verts: Vec<V2<Rational>> = (0..n)
            .map(|i| {
                let a = std::f64::consts::TAU * i as f64 / n as f64;
                let r = 80.0 + rng.int(40) as f64;
                let x = (r * a.cos() * 7.0).round() as i64 + rng.int(3);
                let y = (r * a.sin() * 7.0).round() as i64 + rng.int(3);
                V2::new(qi(x, 7), qi(y, 7))
            })
            .collect();
        (0..n)
            .map(|i| {
                let (p, r) = (&verts[i], &verts[(i + 1) % n]);
                if rng.int(1) == 0 {
                    return Bezier::new(vec![p.clone(), r.clone()]);
                }
                let d = r.sub(p);
                let s = qi(rng.int(4), 16);
                let side = V2::new(-d.y.clone() * &s, d.x.clone() * &s);
                let third = |k: i64| p.add(&d.scale(&qi(k, 3))).add(&side);
                Bezier::new(vec![p.clone(), third(1), third(2), r.clone()])
            })
            .collect()
    }

    /// `max` over dense samples of `a` of the distance to the polyline of
    /// dense samples of `b` (the polyline's chords stand within 1e-4 of the
    /// curves at these sizes): an independent estimate of the directed
    /// Hausdorff distance, from curve evaluation alone.
    fn directed(a: &[Bezier<f64>], b: &[Bezier<f64>]) -> f64 {
        let samples = |c: &[Bezier<f64>], n: usize| -> Vec<DVec2> {
            c.iter()
                .flat_map(|x| (0..=n).map(move |i| x.eval_fast(i as f64 / n as f64)))
                .collect()
        };
        let (pa, pb) = (samples(a, 200), samples(b, 2000));
        pa.iter()
            .map(|p| {
                pb.windows(2)
                    .map(|w| {
                        let d = w[1] - w[0];
                        let l2 = d.length_squared();
                        let s = if l2 > 0.0 {
                            ((*p - w[0]).dot(d) / l2).clamp(0.0, 1.0)
                        } else {
                            0.0
                        };
                        (w[0] + d * s - *p).length()
                    })
                    .fold(f64::INFINITY, f64::min)
            })
            .fold(0.0, f64::max)
    }

    /// Closed contours with sharp corners off the grid, at a tolerance below
    /// the grid's rounding move (0.3 < √2/2): every control point of the
    /// output is an integer, every contour is closed, and where the result
    /// says reached, the sampled Hausdorff distance both ways is within the
    /// certified bound (up to the sampling's own error).
    #[test]
    fn chains_on_the_integer_grid_are_within_their_certified_bound() {
        let mut rng = TestRng::new(0x5eed_c4a1);
        let (mut reached, cases) = (0, 24);
        for case in 0..cases {
            let n = 3 + (case % 5);
            let c = contour(&mut rng, n);
            let opts = ChainGridOptions::new(qi(1, 1), tol(0.3));
            let r = chain_on_grid(std::slice::from_ref(&c), &opts).unwrap();
            assert_eq!(r.contours.len(), 1);
            let (first, len, closed) = r.contours[0];
            assert!(closed && first == 0 && len == r.segments.len());
            let out: Vec<Bezier<f64>> = r.segments.iter().map(|s| s.bezier.clone()).collect();
            for (i, b) in out.iter().enumerate() {
                for p in b.points() {
                    assert!(
                        p.x.fract() == 0.0 && p.y.fract() == 0.0,
                        "case {case}: {p:?}"
                    );
                }
                let next = &out[(i + 1) % out.len()];
                assert_eq!(b.points().last(), next.points().first(), "case {case}");
            }
            if !r.reached() {
                continue;
            }
            reached += 1;
            assert!(r.certified_hi <= 0.3, "case {case}");
            let input: Vec<Bezier<f64>> = c.iter().map(|x| x.map(|v| v.approx())).collect();
            let (ab, ba) = (directed(&input, &out), directed(&out, &input));
            assert!(
                ab <= r.certified_hi + 1e-3 && ba <= r.certified_hi + 1e-3,
                "case {case}: sampled {ab} / {ba} above the certified {}",
                r.certified_hi
            );
        }
        // (measured: 16 of 24 — sharp corners at tol 0.3 on the integer grid
        // are the hard case — enough for the check above to bite)
        assert!(reached * 2 >= cases, "only {reached} of {cases} reached");
    }

    /// A Bézier with collinear control points is a segment only when its
    /// inner points lie between its ends.
    #[test]
    fn collinear_cubics_are_segments_only_when_they_do_not_overshoot() {
        let b = |p: &[(f64, f64)]| Bezier::new(p.iter().map(|&(x, y)| V2::new(x, y)).collect());
        let seg = as_segment(&b(&[(0.0, 0.0), (2.0, 2.0), (1.0, 1.0), (3.0, 3.0)]));
        assert_eq!(seg, Some(b(&[(0.0, 0.0), (3.0, 3.0)])));
        assert_eq!(
            as_segment(&b(&[(0.0, 0.0), (4.0, 4.0), (1.0, 1.0), (3.0, 3.0)])),
            None
        );
        assert_eq!(
            as_segment(&b(&[(0.0, 0.0), (-1.0, -1.0), (3.0, 3.0)])),
            None
        );
        assert_eq!(as_segment(&b(&[(0.0, 0.0), (1.0, 1.5), (3.0, 3.0)])), None);
        assert_eq!(
            as_segment(&b(&[(0.0, 0.0), (0.0, 0.0), (0.0, 0.0), (0.0, 0.0)])),
            None
        );
    }

    /// Bad input is refused with the field and the reason.
    #[test]
    fn chains_that_are_not_joined_are_refused() {
        let b = |p: &[(i64, i64)]| {
            Bezier::new(
                p.iter()
                    .map(|&(x, y)| V2::new(qi(x, 1), qi(y, 1)))
                    .collect(),
            )
        };
        let opts = ChainGridOptions::new(qi(1, 1), tol(0.3));
        let broken = vec![b(&[(0, 0), (10, 0)]), b(&[(11, 0), (0, 10)])];
        let e = chain_on_grid(&[broken], &opts).unwrap_err().to_string();
        assert!(e.contains("does not start where piece 0 ends"), "{e}");
        let e = chain_on_grid(&[vec![b(&[(1, 1)])]], &opts)
            .unwrap_err()
            .to_string();
        assert!(e.contains("a single point"), "{e}");
        assert!(chain_on_grid(&[], &opts).is_err());
        let bad_grid = ChainGridOptions::new(qi(1, 3), tol(0.3));
        let e = chain_on_grid(&[vec![b(&[(0, 0), (10, 0), (0, 10), (0, 0)])]], &bad_grid)
            .unwrap_err()
            .to_string();
        assert!(e.contains("dyadic"), "{e}");
    }
}
