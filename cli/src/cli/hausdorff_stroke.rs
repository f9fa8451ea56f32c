//! `lncert hausdorff OUTLINE STROKE.json [--tol T] [--stroke-tol E]`: certified
//! bounds on `d_H(OUTLINE, ∂S)` where `STROKE.json` names the exact stroke
//! boundary `{"stroke": {"curve": CURVE, "pen": {"circle": R} | {"ellipse": M}}}`
//! — the referee for any stroker's output ([`lncert::stroke::distance_to_stroke`]:
//! lncert's proven outline `L` at tolerance `E` and the triangle inequality;
//! without `--stroke-tol`, [`lncert::stroke::referee`]'s default `E` and its
//! fallbacks).
//! Either argument may be the stroke. With `--tol T --certificate C` (circular
//! pens) a proven `d_H ≤ T` is written as a stroke distance certificate
//! (`lncert-stroke-distance-certificate`: a Hausdorff certificate of
//! `d_H(X, L) ≤ T − E` and the stroke certificate of `d_H(L, ∂S) ≤ E`),
//! which `lncert verify` re-checks on its own.

use super::args::{bad, number};
use super::hausdorff::{approx_json, Arg, HausdorffArgs};
use super::{print_report, CliError, EXIT_OK, EXIT_REFUTED, EXIT_UNDECIDED};
use lncert::certify::Config;
use lncert::shape::{InputApprox, ShapeDesc};
use lncert::stroke::{
    distance_to_stroke, referee, PenShape, StrokeDistance, StrokeShape, StrokeVerdict,
};
use lncert::Tolerance;
use serde_json::json;

/// Runs the stroke form of `hausdorff`; `x`, `y` are A and B, one of them
/// the stroke. Returns the exit code.
pub(crate) fn run(
    a: &HausdorffArgs,
    x: Arg,
    y: Arg,
    rel_f: f64,
    tol: Option<Tolerance>,
) -> Result<i32, CliError> {
    let (stroke_is_a, shape, approx_shape, st, approx_st) = match (x, y) {
        (Arg::Stroke(s, ps), Arg::Shape(o, po)) => (true, o, po, s, ps),
        (Arg::Shape(o, po), Arg::Stroke(s, ps)) => (false, o, po, s, ps),
        _ => unreachable!("the caller passes exactly one stroke"),
    };
    if a.certificate.is_some() {
        if tol.is_none() {
            return Err(bad(
                "--certificate",
                "needs --tol T: the certificate states d_H ≤ T",
            ));
        }
        if let Some(p) = &a.certificate {
            super::args::output_file("--certificate", p)?;
        }
    }
    let cfg = Config {
        rel: rel_f,
        max_boxes: a.max_boxes,
        ..Config::default()
    };
    let start = std::time::Instant::now();
    let d = match &a.stroke_tol {
        Some(t) => {
            let e = Tolerance::new(number("--stroke-tol", t)?)
                .map_err(|e| bad("--stroke-tol", e.reason))?;
            match &st.path {
                Some(p) => lncert::stroke::distance_to_stroke_path(&shape, p, &st.options(e), &cfg),
                None => distance_to_stroke(&shape, &st.curve, &st.options(e), &cfg),
            }
        }
        None => referee(&shape, &st, tol.as_ref(), &cfg),
    }
    .map_err(|e| CliError {
        field: format!("{}.stroke.{}", if stroke_is_a { "A" } else { "B" }, e.field),
        reason: e.reason,
    })?;
    let stroke_tol = d.stroke.tol.clone();
    let verdict = tol.as_ref().map(|t| match d.verdict(t) {
        StrokeVerdict::Within => "certified",
        StrokeVerdict::Over => "refuted",
        StrokeVerdict::Undecided => "undecided",
    });
    let report = Report {
        d: &d,
        stroke_is_a,
        shape: &shape,
        stroke: &st,
        approx: (&approx_shape, &approx_st),
        stroke_tol: &stroke_tol,
        rel_f,
        tol: &tol,
        verdict,
        seconds: start.elapsed().as_secs_f64(),
    };
    print_report(a.json, || report.json(), || report.text());
    if let (Some(path), Some(t)) = (&a.certificate, &tol) {
        if verdict == Some("certified") {
            let r = match &st.pen {
                PenShape::Circle(r) => r.clone(),
                // the stroke's own pen matrix is stated; no radius is used
                PenShape::Ellipse(_) => lncert::Rational::from_integer(1.into()),
            };
            match lncert::stroke::distance_certificate(&shape, &d, &st.curve, &r, t) {
                Ok(doc) => {
                    let text = doc.to_string();
                    std::fs::write(path, &text).map_err(|e| bad("--certificate", e))?;
                    eprintln!(
                        "lncert: certificate of d_H ≤ {} written to {} ({} kB); check it with: lncert verify {}",
                        t.exact(),
                        path.display(),
                        text.len().div_ceil(1000),
                        path.display()
                    );
                }
                Err(e) => {
                    eprintln!(
                        "lncert: --certificate {}: not written: {}",
                        path.display(),
                        e.reason
                    );
                    return Ok(EXIT_UNDECIDED);
                }
            }
        } else {
            eprintln!(
                "lncert: --certificate {}: not written (the claim d_H ≤ TOL is not proven)",
                path.display()
            );
        }
    }
    Ok(match verdict {
        Some("certified") => EXIT_OK,
        Some("refuted") => EXIT_REFUTED,
        Some(_) => EXIT_UNDECIDED,
        None if d.complete() => EXIT_OK,
        None => EXIT_UNDECIDED,
    })
}

struct Report<'a> {
    d: &'a StrokeDistance,
    stroke_is_a: bool,
    shape: &'a ShapeDesc,
    stroke: &'a StrokeShape,
    /// The outline's and the stroke curve's approximations.
    approx: (&'a InputApprox, &'a InputApprox),
    stroke_tol: &'a Tolerance,
    rel_f: f64,
    tol: &'a Option<Tolerance>,
    verdict: Option<&'a str>,
    seconds: f64,
}

fn pen_text(p: &PenShape) -> String {
    match p {
        PenShape::Circle(r) => format!("disk(r = {r})"),
        PenShape::Ellipse(pen) => pen.description.clone(),
    }
}

impl Report<'_> {
    /// `(h(A→B), h(B→A))` bounds, A and B as the user gave them.
    fn directions(&self) -> ((f64, f64), (f64, f64)) {
        let d = self.d;
        if self.stroke_is_a {
            (d.from_stroke, d.to_stroke)
        } else {
            (d.to_stroke, d.from_stroke)
        }
    }

    fn json(&self) -> serde_json::Value {
        let d = self.d;
        let s = &d.stroke;
        let (ab, ba) = self.directions();
        let (ap_a, ap_b) = if self.stroke_is_a {
            (self.approx.1, self.approx.0)
        } else {
            (self.approx.0, self.approx.1)
        };
        json!({
            "lo": d.lo, "hi": d.hi,
            "a_to_b": {"lo": ab.0, "hi": ab.1},
            "b_to_a": {"lo": ba.0, "hi": ba.1},
            "stroke_shape": if self.stroke_is_a { "A" } else { "B" },
            "stroke": {
                "tol": self.stroke_tol.to_string(),
                "pieces": s.pieces(),
                "contours": s.contours.len(),
                "a": s.a.proven.then_some(s.a.bound),
                "b": s.b.proven.then_some(s.b.bound),
                "c": s.c.proven,
            },
            "outline_search": d.outline.as_ref().map(|o| json!({
                "to_outline": {"lo": o.a_to_b.lo, "hi": o.a_to_b.hi},
                "from_outline": {"lo": o.b_to_a.lo, "hi": o.b_to_a.hi},
                "incomplete": o.incomplete(),
            })),
            "rel": self.rel_f,
            "tol": self.tol.as_ref().map(|t| t.to_string()),
            "verdict": self.verdict,
            "incomplete": !d.complete(),
            "proof": "stroke",
            "certificate": serde_json::Value::Null, // written after the report, see stderr
            "seconds": self.seconds,
            "input_approximation": approx_json(ap_a, ap_b),
        })
    }

    fn text(&self) -> String {
        let d = self.d;
        let s = &d.stroke;
        let (na, nb) = if self.stroke_is_a {
            ("∂S", "X")
        } else {
            ("X", "∂S")
        };
        let mut out = format!(
            "X ({}): {}\n∂S ({}): the exact boundary of the stroke of {} with the pen {}\n",
            if self.stroke_is_a { "B" } else { "A" },
            self.shape.summary(),
            if self.stroke_is_a { "A" } else { "B" },
            match &self.stroke.path {
                Some(p) => format!(
                    "{} piece(s) ({} exact arcs)",
                    p.len(),
                    p.iter()
                        .filter(|q| matches!(q, lncert::stroke::PathPiece::Arc(_)))
                        .count()
                ),
                None => format!("{} piece(s)", self.stroke.curve.len()),
            },
            pen_text(&self.stroke.pen),
        );
        for (name, ap) in [
            ("outline X", self.approx.0),
            ("stroke curve", self.approx.1),
        ] {
            if let Some(line) = super::curve_input::input_line(name, ap) {
                out += &line;
            }
        }
        let claim = |c: &lncert::stroke::Claim| {
            if c.proven {
                format!("≤ {:.3e}", c.bound)
            } else {
                format!("not proven ({})", c.note)
            }
        };
        out += &format!(
            "  through lncert's outline L at stroke tol {}: {} pieces, {} contour(s), (a) {}, (b) {}\n",
            self.stroke_tol,
            s.pieces(),
            s.contours.len(),
            claim(&s.a),
            claim(&s.b)
        );
        out += &format!(
            "d_H({na}, {nb}) ∈ [{:e}, {:e}]  (certified: the search between X and L, and L's claims)\n",
            d.lo, d.hi
        );
        out += &format!(
            "  h(X→∂S) ∈ [{:e}, {:e}]  (how far X strays from ∂S)\n  h(∂S→X) ∈ [{:e}, {:e}]  (how far ∂S is from X)\n",
            d.to_stroke.0, d.to_stroke.1, d.from_stroke.0, d.from_stroke.1
        );
        if let Some(o) = &d.outline {
            if o.incomplete() {
                out += "note: the box budget or the float resolution stopped the search; the bounds are sound but wider than asked\n";
            }
        } else {
            out += "note: the stroke's claims (a), (b) are not both proven at this stroke tol: nothing is known (try another --stroke-tol)\n";
        }
        if let (Some(v), Some(t)) = (self.verdict, self.tol) {
            out += &format!("verdict: {v} (d_H ≤ {t}?)\n");
        }
        out += &format!("time: {:.3} ms\n", self.seconds * 1e3);
        out
    }
}
