//! `lncert offset … --output cubic|quadratic --grid G --tol T` with `T ≤ G·√2/2`: the
//! tolerance is below what rounding a fitted spline to the grid can keep, so
//! the joints are placed where the exact offset passes near a grid point and
//! every cubic is proven against the exact curve between its joints
//! ([`lncert::offset::offset_on_grid`]).

use super::args::offset_err;
use super::args::{bad, q};
use super::{print_report, CliError};
use lncert::curve::Bezier;
use lncert::offset::OffsetOptions;
use lncert::offset::{offset_on_grid, GridOffset, Target};
use lncert::scalar::Rational;
use serde_json::json;
use std::path::Path;

fn target_json(t: &Target) -> serde_json::Value {
    match t {
        Target::Span { piece, t } => json!({"piece": piece, "t": [t.0, t.1]}),
        Target::Arc(a) => json!({"arc": {
            "center": [q(&a.center.x), q(&a.center.y)], "radius": q(&a.radius),
            "from": [q(&a.from.x), q(&a.from.y)], "to": [q(&a.to.x), q(&a.to.y)],
        }}),
    }
}

/// The flags of `lncert offset` that the grid path reads (the others are
/// refused by [`super::offset::run`] before it calls [`run`]).
pub struct GridFlags<'a> {
    /// `CURVE`.
    pub curve: &'a Path,
    /// `--glyph` was given (the input is y-up font units).
    pub glyph: bool,
    /// `--tol` as given.
    pub tol: &'a str,
    /// `--json`.
    pub json: bool,
    /// `--certificate`.
    pub certificate: Option<&'a Path>,
    /// `--curve-out`.
    pub curve_out: Option<&'a Path>,
    /// `--exact-out`.
    pub exact_out: Option<&'a Path>,
    /// `--path-out`.
    pub path_out: Option<&'a Path>,
    /// `--out`.
    pub out: Option<&'a Path>,
}

/// Runs the grid path of `lncert offset` (called by [`super::offset::run`]).
pub fn run(
    a: &GridFlags,
    curve: &[Bezier<Rational>],
    opts: &OffsetOptions,
    y_down: bool,
) -> Result<i32, CliError> {
    let start = std::time::Instant::now();
    let r = offset_on_grid(curve, opts).map_err(offset_err)?;
    let secs = start.elapsed().as_secs_f64();
    let cert_note = write_files(a, curve, opts, &r)?;
    let grid = opts.grid.clone().unwrap_or_default();
    let how = format!(
        "joints placed where the exact offset passes within {:e} of a grid point, inner control points searched on the grid; each cubic proven against the exact curve between its joints (corner arcs included)",
        0.5 * opts.tol.value()
    );
    let verdict = if r.reached() {
        "certified"
    } else {
        "not reached"
    };
    if let Some(path) = a.out {
        let frame = super::svg_out::frame(a.curve, a.glyph, y_down)?;
        let shape = lncert::write::SvgShape::grid_offset(&r).map_err(|e| bad("--out", e))?;
        let shape = super::svg_out::proven(shape, r.reached());
        super::svg_out::write(path, &[shape], &frame)?;
    }
    let report = Report {
        a,
        opts,
        r: &r,
        grid: &grid,
        how: &how,
        verdict,
        secs,
        cert_note: &cert_note,
    };
    print_report(a.json, || report.json(), || report.text());
    Ok(if r.reached() {
        super::EXIT_OK
    } else {
        super::EXIT_UNDECIDED
    })
}

/// `--certificate`, `--curve-out`, `--exact-out` and `--path-out`; returns
/// the note printed about the certificate.
fn write_files(
    a: &GridFlags,
    curve: &[Bezier<Rational>],
    opts: &OffsetOptions,
    r: &GridOffset,
) -> Result<Option<String>, CliError> {
    let mut cert_note = None;
    if let Some(path) = a.certificate {
        cert_note = Some(match &r.certificate {
            Some(c) => {
                std::fs::write(path, c.to_json_string())
                    .map_err(|e| bad("--certificate", format!("{}: {e}", path.display())))?;
                format!("written to {} ({} boxes)", path.display(), c.box_count())
            }
            None => "not written: the tolerance is not certified".to_string(),
        });
    }
    if let Some(path) = a.curve_out {
        let shape = r.approximant_shape().map_err(offset_err)?;
        std::fs::write(path, format!("{}\n", shape.to_json()))
            .map_err(|e| bad("--curve-out", format!("{}: {e}", path.display())))?;
    }
    if let Some(path) = a.exact_out {
        let shape = r.exact_shape(curve, &opts.distance).map_err(offset_err)?;
        std::fs::write(path, format!("{}\n", shape.to_json()))
            .map_err(|e| bad("--exact-out", format!("{}: {e}", path.display())))?;
    }
    if let Some(path) = a.path_out {
        let d = lncert::write::grid_path_data(r).map_err(|e| bad("--path-out", e))? + "\n";
        std::fs::write(path, d)
            .map_err(|e| bad("--path-out", format!("{}: {e}", path.display())))?;
    }
    Ok(cert_note)
}

/// Everything the printed report (JSON or text) shows.
struct Report<'a> {
    a: &'a GridFlags<'a>,
    opts: &'a OffsetOptions,
    r: &'a GridOffset,
    grid: &'a Rational,
    /// How the joints and control points were found.
    how: &'a str,
    verdict: &'a str,
    secs: f64,
    cert_note: &'a Option<String>,
}

impl Report<'_> {
    /// The `--json` document.
    fn json(&self) -> serde_json::Value {
        let Report {
            a,
            opts,
            r,
            grid,
            how,
            verdict,
            secs,
            cert_note,
        } = self;
        json!({
            "method": "grid-fit",
            "output": opts.output.name(),
            "degree": if opts.output == lncert::offset::Output::Quadratic { 2 } else { 3 },
            "grid": {"grid": q(grid), "rounding_move": lncert::offset::kernels::rounding_move(grid), "how": how},
            "distance": q(&opts.distance),
            "tol": a.tol,
            "segments": r.segments.len(),
            "control_points": r.control_points(),
            "certified_error": r.reached().then_some(json!([0.0, r.certified_hi])),
            "proven": r.reached(),
            "verdict": verdict,
            "contours": r.contours.iter().map(|&(first, n, closed)| json!({"first": first, "segments": n, "closed": closed})).collect::<Vec<_>>(),
            "pieces": r.segments.iter().map(|s| json!({
                "contour": s.contour,
                "control_points": s.bezier.points().iter().map(|p| json!([p.x, p.y])).collect::<Vec<_>>(),
                "targets": s.targets.iter().map(target_json).collect::<Vec<_>>(),
                "error": [s.error.0, s.error.1],
                "proof": s.proof.map(|p| p.name()),
            })).collect::<Vec<_>>(),
            "unreached": r.unreached,
            "corner_arcs": r.corner_arcs,
            "base_segments": r.base_segments,
            "refits": r.refits,
            "certifications": r.certifications,
            "max_joint_offset": r.max_joint_offset,
            "seconds": {"total": secs},
            "certificate": cert_note,
        })
    }

    /// The text report.
    fn text(&self) -> String {
        let Report {
            a,
            opts,
            r,
            grid,
            how,
            secs,
            cert_note,
            ..
        } = self;
        let mut s = format!(
            "offset at distance {} on the grid {}: {} {} segment(s) in {} contour(s), {} control points, every coordinate a multiple of the grid\n",
            q(&opts.distance),
            q(grid),
            r.segments.len(),
            opts.output.name(),
            r.contours.len(),
            r.control_points()
        );
        s += &format!("  {how}\n");
        s += &format!(
            "  tolerance {} below the rounding move {:.3e} (grid·√2/2)\n",
            a.tol,
            lncert::offset::kernels::rounding_move(grid)
        );
        s += &format!(
            "  {} segment(s) of the grid-free fit at tol/2, {} corner arc(s), {} re-fit(s) after a failed proof, {} certified search(es), largest joint offset {:.3e}\n",
            r.base_segments, r.corner_arcs, r.refits, r.certifications, r.max_joint_offset
        );
        if r.reached() {
            s += &format!("  certified: d_H ≤ {:.6e} ≤ {}\n", r.certified_hi, a.tol);
        } else {
            s += &format!(
                "  not reached: {} segment(s) above the tolerance (largest certified bound {:.3e})\n",
                r.unreached.len(),
                r.certified_hi
            );
        }
        if let Some(n) = &cert_note {
            s += &format!("  certificate: {n}\n");
        }
        s += &format!("  time {secs:.2} s\n");
        s
    }
}
