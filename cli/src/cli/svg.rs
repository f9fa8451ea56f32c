//! SVG pictures for `lncert reproduce --out DIR`: seed 000 Fig. 5(a) and 5(b),
//! the compatible pair `bl`, `br` with the paper's κ = √(λl λr) and their
//! convolution `bl + br`, with control polygons.
//!
//! Pictures are illustrations, drawn in `f64`: compatibility and `q = λr/λl`
//! are decided exactly on the built-in data first, then `ρl = √q` and the
//! control points are rounded for drawing.

use super::args::bad;
use super::CliError;
use lncert::curve::{Bezier, V2};
use lncert::ln::cubic::LnFrame;
use lncert::ln::pair::CompatiblePair;
use lncert::scalar::{parse_rational, Rational, Scalar};
use lncert_cli::reproduce::data::FIG5;
use serde_json::Value;
use std::fmt::Write as _;
use std::path::{Path, PathBuf};

/// Writes `fig5a.svg` and `fig5b.svg` into `dir` (created if missing).
pub fn write_fig5(dir: &Path) -> Result<Vec<PathBuf>, CliError> {
    std::fs::create_dir_all(dir)
        .map_err(|e| bad("--out", format!("cannot create {}: {e}", dir.display())))?;
    let data: Value = serde_json::from_str(FIG5)
        .map_err(|e| bad("--out", format!("built-in Fig. 5 data: {e}")))?;
    let mut written = Vec::new();
    for case in ["a", "b"] {
        let curves =
            fig5_curves(&data[case]).map_err(|e| bad("--out", format!("Fig. 5({case}): {e}")))?;
        let path = dir.join(format!("fig5{case}.svg"));
        let title = format!("seed 000 Fig. 5({case}): bl (blue), br (red), bl + br (black)");
        std::fs::write(&path, render(&title, &curves))
            .map_err(|e| bad("--out", format!("cannot write {}: {e}", path.display())))?;
        written.push(path);
    }
    Ok(written)
}

fn frame_of(v: &Value) -> Result<LnFrame<Rational>, String> {
    let pt = |p: &Value| -> Result<V2<Rational>, String> {
        let c = |x: &Value| {
            parse_rational(x.as_str().ok_or("coordinate is not a string")?)
                .map_err(|e| e.to_string())
        };
        Ok(V2::new(c(&p[0])?, c(&p[1])?))
    };
    LnFrame::new(pt(&v["b0"])?, pt(&v["bm"])?, pt(&v["b3"])?).map_err(|e| e.to_string())
}

/// The left, right and convolution curves of one case, in `f64`.
fn fig5_curves(case: &Value) -> Result<[Bezier<f64>; 3], String> {
    let exact = CompatiblePair::new(frame_of(&case["left"])?, frame_of(&case["right"])?)
        .map_err(|e| e.to_string())?;
    let to_f = |f: &LnFrame<Rational>| LnFrame {
        b0: f.b0.map(|x| x.approx()),
        bm: f.bm.map(|x| x.approx()),
        b3: f.b3.map(|x| x.approx()),
    };
    let pair = CompatiblePair {
        left: to_f(&exact.left),
        right: to_f(&exact.right),
        c0: exact.c0.approx(),
        c1: exact.c1.approx(),
    };
    let rho = exact.ratio().approx().sqrt();
    let ln = pair.curves_for_rho(&rho).map_err(|e| e.to_string())?;
    let conv = pair.convolution(&ln).map_err(|e| e.to_string())?;
    Ok([ln.left, ln.right, conv.curve])
}

/// One SVG document: y axis up, control polygons dashed, curves solid.
fn render(title: &str, curves: &[Bezier<f64>; 3]) -> String {
    let pts: Vec<&V2<f64>> = curves.iter().flat_map(|c| c.points()).collect();
    let (x0, x1) = bounds(pts.iter().map(|p| p.x));
    let (y0, y1) = bounds(pts.iter().map(|p| p.y));
    let m = 0.05 * (x1 - x0).max(y1 - y0).max(1e-9);
    let (w, h) = (x1 - x0 + 2.0 * m, y1 - y0 + 2.0 * m);
    let mut s = String::new();
    let _ = writeln!(
        s,
        r#"<svg xmlns="http://www.w3.org/2000/svg" width="640" height="{:.0}" viewBox="{} {} {} {}">"#,
        640.0 * h / w,
        x0 - m,
        -(y1 + m),
        w,
        h
    );
    let _ = writeln!(s, "<title>{title}</title>");
    let _ = writeln!(
        s,
        r#"<g transform="scale(1,-1)" fill="none" stroke-linejoin="round">"#
    );
    for (c, colour) in curves.iter().zip(["#1f5fbf", "#c0392b", "#000000"]) {
        let _ = writeln!(
            s,
            r##"<polyline points="{}" stroke="#999999" stroke-dasharray="4 3" stroke-width="1" vector-effect="non-scaling-stroke"/>"##,
            polyline(c)
        );
        let _ = writeln!(
            s,
            r#"<path d="{}" stroke="{colour}" stroke-width="2" vector-effect="non-scaling-stroke"/>"#,
            path(c)
        );
    }
    s.push_str("</g>\n</svg>\n");
    s
}

fn bounds(it: impl Iterator<Item = f64>) -> (f64, f64) {
    it.fold((f64::INFINITY, f64::NEG_INFINITY), |(lo, hi), v| {
        (lo.min(v), hi.max(v))
    })
}

fn polyline(c: &Bezier<f64>) -> String {
    c.points()
        .iter()
        .map(|p| format!("{},{}", p.x, p.y))
        .collect::<Vec<_>>()
        .join(" ")
}

/// SVG path data `M x y C ...` of a cubic.
fn path(c: &Bezier<f64>) -> String {
    let p = c.points();
    let xy = |v: &V2<f64>| format!("{} {}", v.x, v.y);
    match p.len() {
        4 => format!(
            "M {} C {} {} {}",
            xy(&p[0]),
            xy(&p[1]),
            xy(&p[2]),
            xy(&p[3])
        ),
        _ => format!("M {}", p.iter().map(xy).collect::<Vec<_>>().join(" L ")),
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn fig5_pictures_are_cubics() {
        let data: Value = serde_json::from_str(FIG5).unwrap();
        for case in ["a", "b"] {
            let curves = fig5_curves(&data[case]).unwrap();
            let svg = render("t", &curves);
            assert_eq!(svg.matches("<path").count(), 3);
            assert!(svg.contains(" C "));
        }
    }
}
