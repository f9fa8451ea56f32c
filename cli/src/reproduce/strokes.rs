//! Proven stroke outlines (issue 13, closed outlines): the circle-pen stroke
//! ([`lncert::stroke::stroke`]) of every test curve of
//! `data/offset_test_curves.json` at each listed distance (as pen radius), and
//! the inner offset of a closed B-spline whose loops must go.
//!
//! A claim is `certified` only when all three claims of the stroke are proven
//! ((a) output within TOL of the exact boundary, (b) the exact boundary within
//! TOL of the output, (c) closed, simple, oriented — `proofs/trimming.md`);
//! anything else is `undecided`, never guessed.
//!
//! The comparison with kurbo's stroker (its loops and its certified distance to
//! the exact boundary) is `cargo run --release --example stroke_compare`.

use super::{Claim, Verdict};
use lncert::curve::{BSpline, Bezier, V2};
use lncert::offset::Output;
use lncert::scalar::{Rational, Scalar};
use lncert::shape::{ShapeDesc, ShapeError};
use lncert::stroke::{stroke, Orientation, Piece, Stroke, StrokeOptions};
use rayon::prelude::*;
use std::time::Instant;

/// The tolerance of the `stroke-…` claims (chosen for run time: the whole
/// family runs in seconds with [`OUTPUT`]; TOL 1e-1 … 1e-3 and both outputs
/// are in `cli/examples/stroke_compare.rs`).
pub const TOL: f64 = 1e-2;

/// A finer tolerance tried when the stroke at [`TOL`] leaves a claim
/// unproven: an outline proven within `FINER_TOL ≤ TOL` proves the claim at
/// `TOL` as well (each bound is at most `FINER_TOL`). The finer outline's
/// pieces are smaller, which is where an undecided joint region of the raw
/// crossing search (an open contour, claim (c)) often goes away.
pub const FINER_TOL: f64 = 1e-3;

/// The offset segments' form of the `stroke-…` claims: fitted cubics (SVG
/// path data; at TOL 1e-2 they prove as often as the native segments, in
/// about a third of the time — `proofs/trimming.md`).
pub const OUTPUT: Output = Output::Cubic;

/// A stroke case: curve name, pieces, pen radius.
pub type Case = (String, Vec<Bezier<Rational>>, Rational);

/// The test curves of `data/offset_test_curves.json`, once per distinct `|d|`
/// of their listed offsets (the pen radius).
pub fn test_cases() -> Result<Vec<Case>, String> {
    let mut out: Vec<Case> = Vec::new();
    for (name, pieces, ds) in super::offsets::test_curves()? {
        let mut radii: Vec<Rational> = Vec::new();
        for d in ds {
            let r = if d < Rational::from_integer(0.into()) {
                -d
            } else {
                d
            };
            if !radii.contains(&r) {
                radii.push(r);
            }
        }
        for r in radii {
            out.push((name.clone(), pieces.clone(), r));
        }
    }
    Ok(out)
}

/// A closed periodic cubic B-spline (a lens with a dent in its lower side):
/// at its two tips the curvature radius is far below the pen radius
/// [`lens_radius`], so the raw inner offset has swallowtail loops there.
pub fn lens() -> Vec<Bezier<Rational>> {
    let q = |n: i64, d: i64| Rational::new(n.into(), d.into());
    let pts = [
        (-3, 1, 0, 1),
        (-1, 1, -3, 5),
        (0, 1, -1, 5),
        (1, 1, -3, 5),
        (3, 1, 0, 1),
        (0, 1, 4, 5),
    ]
    .iter()
    .map(|&(a, b, c, d)| V2::new(q(a, b), q(c, d)))
    .collect();
    BSpline::periodic_uniform(3, pts)
        .expect("a valid periodic B-spline")
        .to_beziers()
}

/// The pen radius of the lens case, `1/4` (the tips' curvature radius is
/// about 0.10; the largest inscribed disk of the lens has radius about 0.45).
pub fn lens_radius() -> Rational {
    Rational::new(1.into(), 4.into())
}

/// The output as one exact shape for the Hausdorff engine
/// ([`Stroke::outline_shape`]).
pub fn outline_shape(s: &Stroke) -> Result<ShapeDesc, ShapeError> {
    s.outline_shape()
}

/// Control points of the output: `degree` per Bézier piece, 2 per arc (its
/// end point and centre), plus 1 per contour (its start point).
pub fn control_points(s: &Stroke) -> usize {
    s.contours
        .iter()
        .map(|c| {
            1 + c
                .pieces
                .iter()
                .map(|p| match p {
                    Piece::Bezier(b) => b.degree(),
                    Piece::Arc(_) => 2,
                })
                .sum::<usize>()
        })
        .sum()
}

/// One computed stroke of the reproduce family.
pub struct Run {
    /// Claim id.
    pub id: String,
    /// Curve name.
    pub name: String,
    /// The curve.
    pub curve: Vec<Bezier<Rational>>,
    /// Pen radius.
    pub radius: Rational,
    /// The stroke, or why it could not be computed.
    pub stroke: Result<Stroke, String>,
    /// Seconds (all attempts).
    pub seconds: f64,
    /// The tolerance of the returned stroke: [`TOL`], or [`FINER_TOL`] when
    /// the stroke at `TOL` left a claim unproven.
    pub tol: f64,
}

/// Runs every stroke of the family (in parallel) with [`OUTPUT`] at [`TOL`],
/// and again at [`FINER_TOL`] when a claim is left unproven at `TOL`.
pub fn runs() -> Vec<Run> {
    let mut cases: Vec<(String, String, Vec<Bezier<Rational>>, Rational)> = match test_cases() {
        Ok(c) => c
            .into_iter()
            .map(|(n, p, r)| (format!("stroke-{n}-r{}", r.approx()), n, p, r))
            .collect(),
        Err(e) => {
            return vec![Run {
                id: "stroke-data".into(),
                name: "data".into(),
                curve: Vec::new(),
                radius: Rational::from_integer(0.into()),
                stroke: Err(e),
                seconds: 0.0,
                tol: TOL,
            }]
        }
    };
    cases.push((
        "stroke-closed-lens-inner-loops".into(),
        "closed lens B-spline".into(),
        lens(),
        lens_radius(),
    ));
    cases
        .into_par_iter()
        .map(|(id, name, curve, radius)| {
            let t0 = Instant::now();
            let attempt = |tol: f64| {
                let tol = lncert::Tolerance::from_f64(tol).map_err(|e| e.to_string())?;
                let mut opts = StrokeOptions::new(radius.clone(), tol);
                opts.output = OUTPUT;
                stroke(&curve, &opts).map_err(|e| e.to_string())
            };
            let mut tol = TOL;
            let mut s = attempt(tol);
            if !s.as_ref().is_ok_and(proven_closed) {
                tol = FINER_TOL;
                s = attempt(tol);
            }
            Run {
                id,
                name,
                curve,
                radius,
                stroke: s,
                seconds: t0.elapsed().as_secs_f64(),
                tol,
            }
        })
        .collect()
}

fn describe(s: &Stroke, secs: f64) -> String {
    let contours: Vec<String> = s
        .contours
        .iter()
        .map(|c| {
            format!(
                "{} pieces {} {}",
                c.pieces.len(),
                if c.closed { "closed" } else { "open" },
                c.orientation.name()
            )
        })
        .collect();
    let claim = |c: &lncert::stroke::Claim| {
        if c.proven {
            format!("proven ({:.1e})", c.bound)
        } else {
            format!("unproven: {}", c.note)
        }
    };
    format!(
        "{} contours [{}]; {} raw pieces, {} crossings cut, {} sub-pieces removed, {} output pieces; \
         (a) {}, (b) {}, (c) {}; {:.2} s",
        s.contours.len(),
        contours.join("; "),
        s.raw_pieces,
        s.crossings.len(),
        s.classified.removed,
        s.pieces(),
        claim(&s.a),
        claim(&s.b),
        if s.c.proven {
            "proven".to_string()
        } else {
            format!("unproven: {}", s.c.note)
        },
        secs
    )
}

/// Is the stroke a proven closed outline (claims (a)–(c), every contour closed)?
pub fn proven_closed(s: &Stroke) -> bool {
    s.proven() && !s.contours.is_empty() && s.contours.iter().all(|c| c.closed)
}

/// The claims of the family from computed [`runs`].
pub fn claims_of(runs: &[Run], out: &mut Vec<Claim>) {
    const SOURCE: &str = "issue 13 (closed outlines), data/offset_test_curves.json";
    for run in runs {
        let lens = run.id == "stroke-closed-lens-inner-loops";
        let statement = if lens {
            format!(
                "the raw inner offset of a closed B-spline lens at r = {} has self-intersection \
                 loops; the stroke's hole contour comes out simple with them cut away, \
                 claims (a)–(c) proven at TOL {TOL:e}",
                run.radius
            )
        } else {
            format!(
                "the circle-pen stroke of {} at r = {} is a closed simple outline within \
                 TOL {TOL:e} of the exact boundary (claims (a)–(c) proven, cubic output)",
                run.name, run.radius
            )
        };
        let (verdict, detail) = match &run.stroke {
            Err(e) => (Verdict::Undecided, format!("stroke failed: {e}")),
            Ok(s) => {
                let mut ok = proven_closed(s);
                let mut detail = describe(s, run.seconds);
                if run.tol != TOL {
                    detail = format!(
                        "not all proven at TOL {TOL:e}; at TOL {:e}: {detail}",
                        run.tol
                    );
                }
                if lens {
                    let holes = s
                        .contours
                        .iter()
                        .filter(|c| c.orientation == Orientation::Clockwise)
                        .count();
                    let loops_cut = !s.crossings.is_empty() && s.classified.removed > 0;
                    ok &= holes == 1 && loops_cut;
                    if !loops_cut {
                        detail.push_str("; no loop was found to cut");
                    }
                }
                (
                    if ok {
                        Verdict::Certified
                    } else {
                        Verdict::Undecided
                    },
                    detail,
                )
            }
        };
        out.push(Claim::new(&run.id, SOURCE, statement, verdict, detail));
    }
}
