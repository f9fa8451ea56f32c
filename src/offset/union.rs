//! Whole-result bounds and certificates: [`global_bounds`], and the union
//! certificates assembled from the per-segment proofs.

use super::corners::{arc_cover, corner_segments};
use super::options::{bad, OffsetError};
use super::results::{exact_offset_shape, join_arc_of, join_arcs, OffsetResult};
use crate::certify::{hausdorff, Certificate, Config, CoverBox, HausdorffBounds, MapCover};
use crate::curve::Bezier;
use crate::scalar::Rational;
use crate::shape::ShapeDesc;
use crate::Tolerance;

/// Certified global bounds `lo ≤ d_H ≤ hi` between the exact offset of the
/// whole input and the whole approximant (relative gap `rel`), by a two-sided
/// search over all pieces (opt-in: its cost grows with the square of the number
/// of segments; the tolerance itself is proven by the per-segment proofs).
pub fn global_bounds(
    curve: &[Bezier<Rational>],
    res: &OffsetResult,
    rel: f64,
) -> Result<HausdorffBounds, OffsetError> {
    let a = exact_offset_shape(curve, res)?;
    let b = res.approximant_shape()?;
    hausdorff(
        &a,
        &b,
        &Config {
            rel,
            ..Config::default()
        },
    )
    .map_err(|e| bad("certify", e.to_string()))
}

/// The certificate of `d_H(exact offset, approximant) ≤ tol`, assembled from the
/// per-segment proofs without any further search (linear in the segments), or
/// `None` when the tolerance was not reached. The claim is the result's own
/// tolerance, exactly as the user gave it ([`Tolerance::exact`] of
/// [`OffsetResult::tol`]; every segment's bound is ≤ its
/// [`value`](Tolerance::value), the largest float ≤ it) — for a convolution
/// whose pen rotation is represented within a margin, the tolerance certified
/// for the exact pen used ([`OffsetResult::certified_tol`]).
///
/// Shapes: the exact offset of the input split exactly at the segments'
/// parameters ([`exact_offset_shape`], piece `i` = segment `i`'s span) and the
/// approximant (piece `i` = segment `i`). Proofs: each segment's parametric
/// map (source and target `i`), or its two search covers (piece and target
/// `i`). Sound because `h(∪Aᵢ, ∪Bᵢ) ≤ maxᵢ h(Aᵢ, Bᵢ)`
/// (a point of `Aᵢ` within `tol` of `Bᵢ` is within `tol` of `∪B`), and
/// [`crate::certify::verify::verify`] re-checks every box against the whole
/// shapes. When the result has join arcs at G⁰ corners ([`join_arcs`]), both
/// shapes are unions ending with those exact arcs (the same in both, each
/// covered by its own search), so the certificate covers the whole offset
/// with its round joins.
pub fn union_certificate(
    curve: &[Bezier<Rational>],
    res: &OffsetResult,
) -> Result<Option<Certificate>, OffsetError> {
    assemble(curve, &[res], false)
}

/// The claim of a certificate of `results`: the smallest tolerance they are
/// certified within ([`OffsetResult::certified_tol`]); an error (field
/// `results`) when there are none or their tolerances differ.
fn claim(results: &[&OffsetResult]) -> Result<Tolerance, OffsetError> {
    let Some(first) = results.first() else {
        return Err(bad("results", "no results"));
    };
    if let Some(i) = results.iter().position(|r| r.tol != first.tol) {
        return Err(bad(
            "results",
            format!(
                "one tolerance for all results: result {i} has {}, result 0 {}",
                results[i].tol, first.tol
            ),
        ));
    }
    Ok(results
        .iter()
        .map(|r| r.certified_tol())
        .min_by(|a, b| a.exact().cmp(b.exact()))
        .unwrap_or(&first.tol)
        .clone())
}

/// The certificate of [`union_certificate`] (one result) or
/// [`union_certificate_all`] (several; always a union): the exact curves and
/// approximants, then the join arcs of every result ([`join_arcs`], the same
/// exact arc in both shapes, proven by its own cover). Without join arcs, one
/// result keeps the plain shapes.
fn assemble(
    curve: &[Bezier<Rational>],
    results: &[&OffsetResult],
    always_union: bool,
) -> Result<Option<Certificate>, OffsetError> {
    let tol = &claim(results)?;
    if results
        .iter()
        .any(|r| !r.reached() || r.segments.iter().any(|s| s.proof.is_none()))
    {
        return Ok(None);
    }
    let mut parts = Parts::default();
    for res in results {
        parts.add_segments(curve, res)?;
    }
    // the join arcs: the same exact arc on both sides, covered by a search
    for res in results {
        if !parts.add_join_arcs(res, tol)? {
            return Ok(None);
        }
    }
    // absorbed corners: the exact arc (in `a` only) covered by the two
    // segments that meet there
    let mut seg_base = 0usize;
    for res in results {
        if !parts.add_absorbed_arcs(res, seg_base, tol)? {
            return Ok(None);
        }
        seg_base += res.segments.len();
    }
    let Parts {
        mut a_members,
        mut b_members,
        maps,
        ab,
        ba,
        ..
    } = parts;
    let (a, b) = if a_members.len() == 1 && !always_union {
        (a_members.remove(0), b_members.remove(0))
    } else {
        (ShapeDesc::union(a_members)?, ShapeDesc::union(b_members)?)
    };
    Ok(Certificate::assemble(&a, &b, tol, &maps, &ab, &ba))
}

/// A certificate under assembly: the members of both shapes, and the proofs
/// numbered by the global piece they cover.
#[derive(Default)]
struct Parts {
    a_members: Vec<ShapeDesc>,
    b_members: Vec<ShapeDesc>,
    maps: Vec<MapCover>,
    ab: Vec<CoverBox>,
    ba: Vec<CoverBox>,
    /// The global index of the next piece of `a`.
    base: usize,
}

/// The boxes `bs` of a proof of piece `i` against piece `i`.
fn renumber(i: usize, bs: &[CoverBox]) -> Vec<CoverBox> {
    bs.iter()
        .map(|bx| CoverBox {
            piece: i,
            target: i,
            ..bx.clone()
        })
        .collect::<Vec<_>>()
}

impl Parts {
    /// The exact curve and approximant of `res`, and its segments' proofs
    /// (piece and target `i`: segment `i`).
    fn add_segments(
        &mut self,
        curve: &[Bezier<Rational>],
        res: &OffsetResult,
    ) -> Result<(), OffsetError> {
        self.a_members.push(exact_offset_shape(curve, res)?);
        self.b_members.push(res.approximant_shape()?);
        for (k, p) in res
            .segments
            .iter()
            .filter_map(|s| s.proof.as_ref())
            .enumerate()
        {
            let i = self.base + k;
            match &p.map {
                Some(m) => self.maps.push(MapCover {
                    from_a: m.source_a,
                    piece: i,
                    target: i,
                    boxes: m.boxes.clone(),
                    hi: m.hi,
                }),
                None => {
                    self.ab.extend(renumber(i, &p.exact_to_segment));
                    self.ba.extend(renumber(i, &p.segment_to_exact));
                }
            }
        }
        self.base += res.segments.len();
        Ok(())
    }

    /// The join arcs of `res` in both shapes, each covered by a search of
    /// the arc against itself; false when one is not proven within `tol`.
    fn add_join_arcs(&mut self, res: &OffsetResult, tol: &Tolerance) -> Result<bool, OffsetError> {
        for arc in join_arcs(res) {
            let shape = ShapeDesc::arc(arc)?;
            let cfg = Config {
                tol: Some(tol.clone()),
                ..Config::default()
            };
            let Ok(h) = hausdorff(&shape, &shape, &cfg) else {
                return Ok(false);
            };
            if h.hi > tol.value() || h.a_to_b.boxes.is_empty() || h.b_to_a.boxes.is_empty() {
                return Ok(false);
            }
            self.ab.extend(renumber(self.base, &h.a_to_b.boxes));
            self.ba.extend(renumber(self.base, &h.b_to_a.boxes));
            self.a_members.push(shape.clone());
            self.b_members.push(shape);
            self.base += 1;
        }
        Ok(true)
    }

    /// The arcs of the absorbed corners of `res` (in `a` only), each covered
    /// by the two segments that meet there (`seg_base`: the global index of
    /// the first segment of `res`); false when a cover is not proven.
    fn add_absorbed_arcs(
        &mut self,
        res: &OffsetResult,
        seg_base: usize,
        tol: &Tolerance,
    ) -> Result<bool, OffsetError> {
        let pieces = res
            .segments
            .iter()
            .map(|s| s.piece)
            .max()
            .map_or(0, |m| m + 1);
        for c in res.corners.iter().filter(|c| c.absorbed) {
            let Some(arc) = join_arc_of(c, &res.distance) else {
                continue;
            };
            let after = (c.after + 1) % pieces.max(1);
            let Some((ia, ib)) = corner_segments(res, c.after, after) else {
                return Ok(false);
            };
            let Some(boxes) = arc_cover(
                &arc,
                &res.segments[ia].bezier,
                &res.segments[ib].bezier,
                tol,
                200_000,
            ) else {
                return Ok(false);
            };
            let a_index = self.base;
            self.ab.extend(boxes.into_iter().map(|bx| CoverBox {
                piece: a_index,
                target: seg_base + if bx.target == 0 { ia } else { ib },
                ..bx
            }));
            self.a_members.push(ShapeDesc::arc(arc)?);
            self.base += 1;
        }
        Ok(true)
    }
}

/// One certificate for several results of the same curve (the two sides of
/// a convolution, or offsets at several distances): `d_H(A, B) ≤ tol` with
/// `A` the union of the exact curves ([`exact_offset_shape`] of each result)
/// and `B` the union of the approximants, each a member of a
/// [`ShapeDesc::Union`] in the order given, with every piece proven against
/// its own span as in [`union_certificate`]. The claim is the results'
/// tolerance (as in [`union_certificate`]: the smallest
/// [`OffsetResult::certified_tol`]). `None` when a result is not
/// reached or a segment has no proof; an error (field `results`) when
/// `results` is empty or their tolerances ([`OffsetResult::tol`]) differ.
///
/// # Examples
/// ```
/// use lncert::offset::{convolve, union_certificate_all, OffsetOptions, Pen};
/// use lncert::shape::parse_curve;
/// let q = |s: &str| lncert::parse_rational(s).unwrap();
/// let x = parse_curve("M 0 0 C 1 0.2 2 1 2.4 2.5").unwrap();
/// let pen = Pen::from_matrix([[q("0.3"), q("0")], [q("0.1"), q("0.2")]]).unwrap();
/// let opts = OffsetOptions::new(q("0"), "1e-3".parse().unwrap());
/// let plus = convolve(&x, &pen, 1, &opts).unwrap();
/// let minus = convolve(&x, &pen, -1, &opts).unwrap();
/// let cert = union_certificate_all(&x, &[&plus, &minus]).unwrap().unwrap();
/// let valid = lncert::verify(&cert.to_json_string()).unwrap();
/// assert!(valid.a.starts_with("the union of 2 shapes"));
/// assert_eq!(valid.tol, q("1/1000"));
/// // results of different tolerances: no one claim
/// let coarse = OffsetOptions::new(q("0"), "1e-2".parse().unwrap());
/// let minus = convolve(&x, &pen, -1, &coarse).unwrap();
/// let e = union_certificate_all(&x, &[&plus, &minus]).unwrap_err();
/// assert_eq!(e.field, "results");
/// ```
pub fn union_certificate_all(
    curve: &[Bezier<Rational>],
    results: &[&OffsetResult],
) -> Result<Option<Certificate>, OffsetError> {
    assemble(curve, results, true)
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::test_util::{q, tol};
    use crate::{offset, parse_curve, OffsetOptions};

    /// The seam of issue 29: `--tol 1e-3` is the rational 1/1000, and the float
    /// the engine compares its bounds with is the largest one ≤ it (below the
    /// f64 `1e-3`, which is above 1/1000), so a result within `tol.value()` is
    /// within 1/1000 exactly, and its certificate claims exactly 1/1000.
    #[test]
    fn proven_within_the_float_is_proven_within_the_exact_tolerance() {
        let t: Tolerance = "1e-3".parse().unwrap();
        assert!(Rational::from_float(1e-3).unwrap() > q("1/1000"));
        assert!(t.value() < 1e-3);
        let curve = parse_curve("M 0 0 C 1 1 2 1 3 0").unwrap();
        let res = offset(&curve, &OffsetOptions::new(q("0.25"), t.clone())).unwrap();
        assert_eq!(res.tol, t);
        assert!(res.reached() && res.certified_hi <= res.tol.value());
        for s in &res.segments {
            assert!(Rational::from_float(s.error.1).unwrap() <= q("1/1000"));
        }
        assert!(Rational::from_float(res.certified_hi).unwrap() <= q("1/1000"));
        let cert = union_certificate(&curve, &res).unwrap().unwrap();
        let valid = crate::verify(&cert.to_json_string()).unwrap();
        assert_eq!(valid.tol, q("1/1000"));
        // a float tolerance claims exactly that float
        let res = offset(&curve, &OffsetOptions::new(q("0.25"), tol(1e-3))).unwrap();
        let cert = union_certificate(&curve, &res).unwrap().unwrap();
        let valid = crate::verify(&cert.to_json_string()).unwrap();
        assert_eq!(valid.tol, Rational::from_float(1e-3).unwrap());
    }

    /// One certificate needs one tolerance: results of different tolerances,
    /// or none, are a typed error of the field `results`.
    #[test]
    fn results_must_share_one_tolerance() {
        let curve = parse_curve("M 0 0 C 1 1 2 1 3 0").unwrap();
        let a = offset(&curve, &OffsetOptions::new(q("0.25"), tol(1e-2))).unwrap();
        let b = offset(&curve, &OffsetOptions::new(q("-0.25"), tol(2e-2))).unwrap();
        let e = union_certificate_all(&curve, &[&a, &b]).unwrap_err();
        assert_eq!(e.field, "results");
        assert!(e.reason.contains("one tolerance"), "{e}");
        assert_eq!(
            union_certificate_all(&curve, &[]).unwrap_err().field,
            "results"
        );
        let b = offset(&curve, &OffsetOptions::new(q("-0.25"), tol(1e-2))).unwrap();
        let cert = union_certificate_all(&curve, &[&a, &b]).unwrap().unwrap();
        let valid = crate::verify(&cert.to_json_string()).unwrap();
        assert_eq!(valid.tol, Rational::from_float(1e-2).unwrap());
    }
}
