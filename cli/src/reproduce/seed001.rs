//! Seed 001 §4 (and seed 000 §5's font 'H' data): the convolution of the nonic
//! skeleton with the elliptical pen (full axes 1.4 and 0.6, i.e. semi-axes 0.7
//! and 0.3, rotated by π/6 — see proofs/001-convolution.md for why full axes),
//! approximated by seed 001's G² method on both sides and certified at
//! `TOL = 1e-1 … 1e-5`: seed 001 Table 2, lncert's column beside the printed
//! \[12\] (LN-pair) column. Also the cusp counts of §4, decided exactly.

use super::{json_rational, Claim, Verdict};
use lncert::curve::{Bezier, V2};
use lncert::offset::kernels::Subdivision;
use lncert::offset::{convolve, OffsetMethod, OffsetOptions, OffsetResult};
use lncert::offset::{kernels::conv_cusps, Angle, Pen};
use lncert::scalar::Rational;

/// The built-in copy of `../shared/data/seed000_nonic_ellipse.json`.
pub const NONIC: &str = include_str!("../../../data/seed000_nonic_ellipse.json");

/// Seed 001 Table 2, the [12] column (LN pairs): right and left boundary, at
/// `TOL = 1e-1 … 1e-5`.
const TABLE2_LN_PAIRS: [(f64, &str, u32, u32); 5] = [
    (1e-1, "1e-1", 13, 14),
    (1e-2, "1e-2", 24, 25),
    (1e-3, "1e-3", 42, 43),
    (1e-4, "1e-4", 77, 79),
    (1e-5, "1e-5", 141, 143),
];

/// The nonic skeleton, exactly.
pub fn nonic() -> Result<Vec<Bezier<Rational>>, String> {
    let doc: serde_json::Value =
        serde_json::from_str(NONIC).map_err(|e| format!("seed000_nonic_ellipse.json: {e}"))?;
    let pts = doc["skeleton_bezier_degree9"]
        .as_array()
        .ok_or("seed000_nonic_ellipse.json: no skeleton_bezier_degree9")?
        .iter()
        .map(|p| Ok(V2::new(json_rational(&p[0])?, json_rational(&p[1])?)))
        .collect::<Result<Vec<_>, String>>()?;
    Ok(vec![Bezier::new(pts)])
}

/// The pen of the font 'H': semi-axes 0.7, 0.3, rotated by π/6, its rotation
/// represented within `max_angle`.
pub fn pen(max_angle: f64) -> Result<Pen, String> {
    let q = |s: &str| lncert::scalar::parse_rational(s).map_err(|e| e.to_string());
    Pen::ellipse_within(
        &q("0.7")?,
        &q("0.3")?,
        &Angle::PiTimes(q("1/6")?),
        max_angle,
    )
    .map_err(|e| e.to_string())
}

/// Both sides at one tolerance by seed 001's G² method: `(side −, side +)`.
pub fn both_sides(tol: f64) -> Result<(OffsetResult, OffsetResult), String> {
    both_sides_by(tol, OffsetMethod::G2)
}

/// Both sides at one tolerance by a method: `(side −, side +)`.
pub fn both_sides_by(
    tol: f64,
    method: OffsetMethod,
) -> Result<(OffsetResult, OffsetResult), String> {
    both_sides_with(tol, method, false)
}

/// [`both_sides_by`], optionally with the paper's acceptance (LN pairs),
/// LN-pair spans split by the paper's rule (c) ([`Subdivision::Weighted`]).
pub fn both_sides_with(
    tol: f64,
    method: OffsetMethod,
    accept_paper: bool,
) -> Result<(OffsetResult, OffsetResult), String> {
    both_sides_rule(tol, method, accept_paper, Subdivision::Weighted)
}

/// [`both_sides_with`] with a subdivision rule for the LN pairs.
pub fn both_sides_rule(
    tol: f64,
    method: OffsetMethod,
    accept_paper: bool,
    rule: Subdivision,
) -> Result<(OffsetResult, OffsetResult), String> {
    let x = nonic()?;
    let pen = pen((tol * 1e-3 / 2.5).clamp(1e-12, 1e-6))?;
    let tol = lncert::Tolerance::from_f64(tol).map_err(|e| e.to_string())?;
    let mut opts = OffsetOptions::new(Rational::from_integer(0.into()), tol);
    opts.method = method;
    opts.accept_paper = accept_paper;
    opts.subdivision = rule;
    let minus = convolve(&x, &pen, -1, &opts).map_err(|e| e.to_string())?;
    let plus = convolve(&x, &pen, 1, &opts).map_err(|e| e.to_string())?;
    Ok((minus, plus))
}

/// The cusps of an LN-pair approximant of the font 'H' (one side), decided
/// exactly on the stored cubics: for each segment `c = pa + qa`, the
/// parameters in `(0, 1)` where `c′ · pa′` changes sign — `c′ = (1 + μ/λ) pa′`
/// for a pair with parallel hodographs, so the approximant turns back there
/// (with float control points the hodographs are parallel only to rounding,
/// and the cusp is a turn through 180° within a rounding-sized loop).
/// `pa` is rebuilt exactly as the driver built it. `(segment, t)`.
pub fn ln_pair_cusps(r: &OffsetResult, side: i8) -> Vec<(usize, f64)> {
    use lncert::poly::{isolate_roots, refine_root, square_free, Span};
    use lncert::scalar::{rational_from_f64, Scalar};
    use num_traits::Signed;
    let (Ok(x), Some(c)) = (nonic(), r.convolution.as_ref()) else {
        return Vec::new();
    };
    let qf = c.pen.q_f64();
    let mut out = Vec::new();
    for (i, g) in r.segments.iter().enumerate() {
        let Some(xp) = x.get(g.piece) else { continue };
        let pair = (|| {
            let sub = lncert::offset::span_f64(xp, g.t)?;
            let n0 = lncert::offset::kernels::unit_left_normal(xp, g.t.0)?;
            let n1 = lncert::offset::kernels::unit_left_normal(xp, g.t.1)?;
            let e0 = lncert::offset::kernels::pen_point_at(xp, g.t.0, qf, side)?;
            let e1 = lncert::offset::kernels::pen_point_at(xp, g.t.1, qf, side)?;
            lncert::offset::kernels::ln_pair_pen(&sub, &n0, &n1, &e0, &e1).ok()
        })();
        let (Some(pair), Some(cb)) = (pair, lncert::offset::exact_bezier(&g.bezier)) else {
            continue;
        };
        if pair.offset != g.bezier {
            continue; // not this segment's pair
        }
        let Some(pa) = lncert::offset::exact_bezier(&pair.pa) else {
            continue;
        };
        let (cx, cy) = cb.hodograph().power_coords();
        let (px, py) = pa.hodograph().power_coords();
        let f = cx.mul(&px).add(&cy.mul(&py)).trimmed();
        if f.coeffs().len() < 2 {
            continue;
        }
        let sf = square_free(&f);
        let width = Rational::new(1.into(), num_bigint::BigInt::from(1u64 << 40));
        for root in isolate_roots(&sf, &Span::unit_open()) {
            let root = refine_root(&sf, &root, &width);
            // a sign change of f across the root (odd multiplicity)
            let (lo, hi) = (root.lo.clone(), root.hi.clone());
            let eps = rational_from_f64(1e-12).unwrap_or_else(|| root.width());
            let (a, b) = if root.is_exact() {
                (&lo - &eps, &hi + &eps)
            } else {
                (lo, hi)
            };
            let (fa, fb) = (f.eval(&a), f.eval(&b));
            if (fa.is_positive() && fb.is_negative()) || (fa.is_negative() && fb.is_positive()) {
                out.push((i, root.midpoint().approx()));
            }
        }
    }
    out
}

pub(crate) fn claims(out: &mut Vec<Claim>) {
    nonic_cusps(out);
    table2(out);
    gauss_split(out);
    let counterexample = table1(out);
    fig7a_cusps(out);
    paper_measure(out, counterexample);
    font_h_claim(out);
}

/// A claim that could not run.
fn undecided(id: &str, e: String) -> Claim {
    Claim::new(id, "seed 001 §4", "(could not run)", Verdict::Undecided, e)
}

/// Seed 001 §4, Fig. 2: the cusp counts, exactly.
fn nonic_cusps(out: &mut Vec<Claim>) {
    match (nonic(), pen(1e-12)) {
        (Ok(x), Ok(p)) => {
            let minus = conv_cusps(0, &x[0], &p, -1);
            let plus = conv_cusps(0, &x[0], &p, 1);
            let ts = |c: &[lncert::offset::ConvCusp]| {
                c.iter()
                    .map(|k| format!("{:.6}", k.t_approx))
                    .collect::<Vec<_>>()
                    .join(", ")
            };
            let ok = minus.len() == 2 && plus.len() == 4;
            out.push(Claim::new(
                "001-nonic-cusps",
                "seed 001 §4, Fig. 2",
                "the convolution curves x ∗ e₊ and x ∗ e₋ of the nonic and the ellipse have two and four cusps",
                if ok { Verdict::Certified } else { Verdict::Refuted },
                format!(
                    "exact cusp isolation with semi-axes 0.7, 0.3 (the printed 1.4, 0.6 are full axes: with semi-axes 1.4, 0.6 the counts would be 4 and 4): x ∗ e₊ (lncert side −) {} at t ≈ {}; x ∗ e₋ (side +) {} at t ≈ {}",
                    minus.len(),
                    ts(&minus),
                    plus.len(),
                    ts(&plus)
                ),
            ));
        }
        (Err(e), _) | (_, Err(e)) => out.push(undecided("001-nonic-cusps", e)),
    }
}

/// Seed 001 Table 2: G² and LN pairs at `TOL = 1e-1 … 1e-5`.
fn table2(out: &mut Vec<Claim>) {
    for (tol, name, right, left) in TABLE2_LN_PAIRS {
        let id = format!("001-table2-tol-{name}");
        let start = std::time::Instant::now();
        match (both_sides(tol), both_sides_by(tol, OffsetMethod::LnPair)) {
            (Ok((m, p)), Ok((lm, lp))) => {
                let ok = m.reached() && p.reached() && lm.reached() && lp.reached();
                out.push(Claim::new(
                    &id,
                    "seed 001 Table 2",
                    format!(
                        "the convolution of the nonic and the ellipse approximated within TOL = {name} on both sides by seed 001's G² method (degree 12) and by the LN pairs of [12] (seed 000 §5, cubic), whose column prints {right} / {left} segments"
                    ),
                    if ok { Verdict::Certified } else { Verdict::Undecided },
                    format!(
                        "lncert G²: right x ∗ e₊ {} segments (certified d_H ≤ {:.3e}), left x ∗ e₋ {} (≤ {:.3e}), {} + {} control points; lncert LN pairs (certified acceptance, the paper's subdivision rule (c)): {} / {} segments (≤ {:.3e}, ≤ {:.3e}) against the printed {right} / {left}; {:.1} s",
                        m.segments.len(),
                        m.certified_hi,
                        p.segments.len(),
                        p.certified_hi,
                        m.control_points(),
                        p.control_points(),
                        lm.segments.len(),
                        lp.segments.len(),
                        lm.certified_hi,
                        lp.certified_hi,
                        start.elapsed().as_secs_f64()
                    ),
                ));
            }
            (Err(e), _) | (_, Err(e)) => out.push(undecided(&id, e)),
        }
    }
}

/// Seed 000 §5: the inflection and the k-piece Gauss-map split of the nonic.
fn gauss_split(out: &mut Vec<Claim>) {
    match nonic() {
        Ok(x) => {
            let infl = lncert::offset::kernels::inflections(&x[0]);
            let mut ends = vec![0.0];
            ends.extend(infl.iter().copied());
            ends.push(1.0);
            let mut parts = Vec::new();
            let mut splits = Vec::new();
            for w in ends.windows(2) {
                let Some(sub) = lncert::offset::span_f64(&x[0], (w[0], w[1])) else {
                    continue;
                };
                let turn = lncert::offset::kernels::total_turn(&sub).unwrap_or(f64::NAN);
                let k: Vec<f64> =
                    lncert::offset::kernels::k_piece_split(&sub, std::f64::consts::PI)
                        .iter()
                        .map(|u| w[0] + (w[1] - w[0]) * u)
                        .collect();
                parts.push(format!(
                    "[{:.4}, {:.4}] turns by {:.1}° → k = {}{}",
                    w[0],
                    w[1],
                    turn.abs().to_degrees(),
                    k.len() + 1,
                    if k.is_empty() {
                        String::new()
                    } else {
                        format!(
                            ", split at t = {}",
                            k.iter()
                                .map(|t| format!("{t:.4}"))
                                .collect::<Vec<_>>()
                                .join(", ")
                        )
                    }
                ));
                splits.extend(k);
            }
            let ok = infl.len() == 1 && (infl[0] - 0.349).abs() < 5e-4;
            out.push(Claim::new(
                "000-sec5-gauss-split",
                "seed 000 §5",
                "the nonic has a unique inflection at t_A ≈ 0.349; a segment whose Gauss map is longer than π is split into the k pieces of equal turn",
                if ok { Verdict::Certified } else { Verdict::Refuted },
                format!(
                    "inflections (exact isolation): {}; {} (turns are float estimates; the split is a heuristic, every piece is certified afterwards)",
                    infl.iter().map(|t| format!("{t:.6}")).collect::<Vec<_>>().join(", "),
                    parts.join("; ")
                ),
            ));
        }
        Err(e) => out.push(undecided("000-sec5-gauss-split", e)),
    }
}

/// Seed 000 Table 1: the font 'H' by cubic LN pairs at TOL = 1, 0.1, 0.01,
/// with lncert's acceptance (certified true error) and the paper's. Returns
/// a segment the paper's measure accepts while its certified true error
/// exceeds TOL, if any.
fn table1(out: &mut Vec<Claim>) -> Option<String> {
    let mut counterexample: Option<String> = None;
    for (tol, name) in [(1.0, "1"), (0.1, "0.1"), (0.01, "0.01")] {
        let id = format!("000-table1-tol-{name}");
        match (
            both_sides_by(tol, OffsetMethod::LnPair),
            both_sides_with(tol, OffsetMethod::LnPair, true),
        ) {
            (Ok((m, p)), Ok((pm, pp))) => {
                let ok = m.reached() && p.reached();
                let spans = |r: &OffsetResult| {
                    r.segments
                        .iter()
                        .map(|g| {
                            format!(
                                "[{:.4}, {:.4}] true ≤ {:.2e}, paper ≤ {}",
                                g.t.0,
                                g.t.1,
                                g.error.1,
                                g.paper_error.map_or("-".into(), |e| format!("{e:.2e}"))
                            )
                        })
                        .collect::<Vec<_>>()
                        .join("; ")
                };
                for (side, r) in [("+", &pp), ("−", &pm)] {
                    if counterexample.is_none() {
                        if let Some(g) = r
                            .segments
                            .iter()
                            .find(|g| g.paper_error.is_some_and(|e| e <= tol) && g.error.0 > tol)
                        {
                            counterexample = Some(format!(
                                "TOL {name}, side {side}, t ∈ [{:.6}, {:.6}]: the measure is ≤ {:.4e} ≤ TOL while the certified true error is ≥ {:.4e} > TOL",
                                g.t.0,
                                g.t.1,
                                g.paper_error.unwrap_or(f64::NAN),
                                g.error.0
                            ));
                        }
                    }
                }
                out.push(Claim::new(
                    &id,
                    "seed 000 §5, Table 1",
                    format!("the font 'H' (nonic ∗ ellipse) approximated by pairs of cubic LN curves within TOL = {name}"),
                    if ok { Verdict::Certified } else { Verdict::Undecided },
                    format!(
                        "lncert, accepting by the certified true error d_H(p ∗ q, pa ∗ qa): side − {} segments, side + {}; accepting as the paper does, by d_H(p, pa) + d_H(q, qa) ≤ TOL (both split by the paper's rule (c)): side − {}, side + {} (true error ≤ {:.3e} / {:.3e}). Side − pieces (paper acceptance): {}; side +: {}",
                        m.segments.len(),
                        p.segments.len(),
                        pm.segments.len(),
                        pp.segments.len(),
                        pm.certified_hi,
                        pp.certified_hi,
                        spans(&pm),
                        spans(&pp)
                    ),
                ));
            }
            (Err(e), _) | (_, Err(e)) => out.push(undecided(&id, e)),
        }
    }
    counterexample
}

/// Seed 000 Fig. 7(a), (d)–(i): the approximant's cusps at TOL 0.1 (the
/// paper's acceptance).
fn fig7a_cusps(out: &mut Vec<Claim>) {
    match both_sides_with(0.1, OffsetMethod::LnPair, true) {
        Ok((m, p)) => {
            let (cm, cp) = (ln_pair_cusps(&m, -1), ln_pair_cusps(&p, 1));
            let list = |r: &OffsetResult, c: &[(usize, f64)]| {
                c.iter()
                    .map(|(i, t)| {
                        let g = &r.segments[*i];
                        format!(
                            "segment {i} (t ∈ [{:.4}, {:.4}]) at s ≈ {t:.4}",
                            g.t.0, g.t.1
                        )
                    })
                    .collect::<Vec<_>>()
                    .join("; ")
            };
            let pieces: std::collections::BTreeSet<(i8, usize)> = cm
                .iter()
                .map(|c| (-1, c.0))
                .chain(cp.iter().map(|c| (1, c.0)))
                .collect();
            let six = cm.len() + cp.len() == 6 && pieces.len() == 6;
            out.push(Claim::new(
                "000-fig7a-cusps",
                "seed 000 §5, Fig. 7(a), (d)–(i)",
                "the cubic LN-pair approximation of the font 'H' at TOL 0.1 has cusps; Fig. 7(d)–(i) plot six Bézier pieces that have one",
                if six { Verdict::Certified } else { Verdict::Refuted },
                format!(
                    "lncert's approximant (LN pairs, the paper's acceptance and its subdivision rule (c)): {} cusps, decided exactly on the stored cubics (sign changes of c′ · pa′): side − {}: {}; side + {}: {}",
                    cm.len() + cp.len(),
                    cm.len(),
                    list(&m, &cm),
                    cp.len(),
                    list(&p, &cp)
                ),
            ));
        }
        Err(e) => out.push(undecided("000-fig7a-cusps", e)),
    }
}

/// Seed 000 §5: the paper's error measure, refuted by `counterexample`.
fn paper_measure(out: &mut Vec<Claim>, counterexample: Option<String>) {
    out.push(match counterexample {
        Some(c) => Claim::new(
            "000-sec5-paper-measure",
            "seed 000 §5",
            "the error of a pair is measured by d_H(p, pa) + d_H(q, qa) instead of d_H(p ∗ q, pa ∗ qa)",
            Verdict::Refuted,
            format!("the measure does not bound the convolution's error: {c}"),
        ),
        None => Claim::new(
            "000-sec5-paper-measure",
            "seed 000 §5",
            "the error of a pair is measured by d_H(p, pa) + d_H(q, qa) instead of d_H(p ∗ q, pa ∗ qa)",
            Verdict::Undecided,
            "no segment separated the two on the font 'H' at TOL 1, 0.1, 0.01",
        ),
    });
}

/// Seed 000 Fig. 7(c): the font 'H' as a proven stroke outline — the nonic
/// ⊕ the pen ([`pen`] with its rotation within 1e-6 rad, as `lncert stroke`
/// represents it at TOL 0.1) at TOL 0.1, sides by cubic LN pairs
/// (seed 000 §5), round caps of proven cubics. Returns the stroke and seconds.
pub fn font_h_stroke() -> Result<(lncert::stroke::Stroke, f64), String> {
    use lncert::stroke::{stroke, PenShape, StrokeOptions};
    let x = nonic()?;
    let pen = pen(1e-6)?;
    let tol = lncert::Tolerance::from_f64(0.1).map_err(|e| e.to_string())?;
    let mut o = StrokeOptions::with_pen(PenShape::Ellipse(pen), tol);
    o.method = OffsetMethod::LnPair;
    let t0 = std::time::Instant::now();
    let s = stroke(&x, &o).map_err(|e| e.to_string())?;
    Ok((s, t0.elapsed().as_secs_f64()))
}

fn font_h_claim(out: &mut Vec<Claim>) {
    use lncert::stroke::Piece;
    let id = "000-fig7c-font-H";
    let statement = "the font 'H' (Fig. 7(c)): the nonic ⊕ the ellipse, trimmed, closed by two half ellipses approximated by cubics (printed errors 8.81e-3 and 1.03e-2), within TOL = 0.1";
    match font_h_stroke() {
        Ok((s, secs)) => {
            let cubic = s.contours.iter().all(|c| {
                c.pieces
                    .iter()
                    .all(|p| matches!(p, Piece::Bezier(b) if b.degree() == 3))
            });
            let holes = s
                .contours
                .iter()
                .filter(|c| c.orientation == lncert::stroke::Orientation::Clockwise)
                .count();
            let caps = s
                .caps
                .iter()
                .map(|c| format!("{} cap {} cubics ≤ {:.3e}", c.end, c.pieces, c.error))
                .collect::<Vec<_>>()
                .join(", ");
            let ok = s.proven() && s.complete && cubic && s.caps.len() == 2;
            out.push(Claim::new(
                id,
                "seed 000 §5, Fig. 7(c)",
                statement,
                if ok { Verdict::Certified } else { Verdict::Undecided },
                format!(
                    "lncert stroke --pen ellipse:0.7,0.3,pi/6 --tol 0.1 --method ln-pair: {} contours ({} holes), {} pieces{}, {} raw pieces, {} crossings cut, {:.1} s; (a) {} (bound {:.3e}), (b) {} (bound {:.3e}), (c) {}; caps (certified Hausdorff bounds to the exact half ellipses of the pen used): {caps} — the seed prints 8.81e-3 and 1.03e-2 for its Floater G¹ cubics; pen used: {} (rotation within {:.1e} rad of π/6){}",
                    s.contours.len(),
                    holes,
                    s.pieces(),
                    if cubic { ", all cubic" } else { ", not all cubic" },
                    s.raw_pieces,
                    s.crossings.len(),
                    secs,
                    if s.a.proven { "proven" } else { "undecided" },
                    s.a.bound,
                    if s.b.proven { "proven" } else { "undecided" },
                    s.b.bound,
                    if s.c.proven { "proven" } else { "undecided" },
                    s.pen.as_ref().map_or(String::new(), |p| p.description.clone()),
                    s.pen.as_ref().map_or(0.0, |p| p.rotation_error),
                    if ok { String::new() } else { format!("; not proven: {}", s.notes.join("; ")) }
                ),
            ));
        }
        Err(e) => out.push(Claim::new(
            id,
            "seed 000 §5, Fig. 7(c)",
            statement,
            Verdict::Undecided,
            e,
        )),
    }
}
