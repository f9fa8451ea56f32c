//! The picture of `lncert offset --svg`: the input curve (blue), the exact
//! offset (green, drawn from samples), the approximant (magenta) with its control
//! polygons (grey), cusps of the exact offset (red), and below it a curvature
//! plot of the exact offset against the approximant over the input parameter.
//!
//! A picture is an illustration drawn in `f64` from samples; the proof is the
//! certified bound printed by the command, not this drawing.

use lncert::curve::{Bezier, V2};
use lncert::offset::OffsetResult;
use lncert::scalar::{Rational, Scalar};
use std::fmt::Write as _;

const W: f64 = 640.0;
const H_MAIN: f64 = 480.0;
const H_PLOT: f64 = 200.0;
const PAD: f64 = 20.0;
const SAMPLES: usize = 64;

fn curvature(b: &Bezier<f64>, t: f64) -> f64 {
    let d1 = b.hodograph();
    let d2 = d1.hodograph();
    let v = d1.eval(&t);
    let a = if d1.degree() == 0 {
        V2::new(0.0, 0.0)
    } else {
        d2.eval(&t)
    };
    let s = v.norm2().sqrt();
    v.cross(&a) / (s * s * s)
}

/// Samples `(global parameter, point, curvature)` of the exact offset.
fn exact_samples(curve: &[Bezier<Rational>], d: f64) -> Vec<Vec<(f64, V2<f64>, f64)>> {
    curve
        .iter()
        .enumerate()
        .map(|(i, x)| {
            let xf = x.map(|v| v.approx());
            (0..=SAMPLES)
                .map(|k| {
                    let t = k as f64 / SAMPLES as f64;
                    let p = xf.eval(&t);
                    let v = xf.hodograph().eval(&t);
                    let l = v.norm2().sqrt();
                    let n = V2::new(-v.y / l, v.x / l);
                    let kx = curvature(&xf, t);
                    // offset curvature κ/|1 − dκ|
                    (i as f64 + t, p.add(&n.scale(&d)), kx / (1.0 - d * kx).abs())
                })
                .collect()
        })
        .collect()
}

fn poly(points: &[V2<f64>], map: &dyn Fn(&V2<f64>) -> (f64, f64)) -> String {
    points
        .iter()
        .map(|p| {
            let (x, y) = map(p);
            format!("{x:.2},{y:.2}")
        })
        .collect::<Vec<_>>()
        .join(" ")
}

/// The SVG document. `y_down`: the input's coordinates are SVG's (path data
/// or a document), drawn as a browser draws the input; otherwise y points up
/// (JSON curves, glyphs), and the picture flips it.
pub fn render(curve: &[Bezier<Rational>], res: &OffsetResult, y_down: bool) -> String {
    let d = res.distance.approx();
    let input: Vec<Bezier<f64>> = curve.iter().map(|b| b.map(|v| v.approx())).collect();
    let exact = exact_samples(curve, d);
    let approx = approx_samples(res);
    let view = View::new(&input, res, &exact, y_down);
    let map = |p: &V2<f64>| view.map(p);
    let mut s = String::new();
    let _ = writeln!(
        s,
        r#"<svg xmlns="http://www.w3.org/2000/svg" width="{W}" height="{}" viewBox="0 0 {W} {}">"#,
        H_MAIN + H_PLOT,
        H_MAIN + H_PLOT
    );
    let _ = writeln!(
        s,
        r#"<title>lncert offset: {} segment(s), degree {}, {} control points, {} (tol {:e})</title>"#,
        res.segments.len(),
        res.degree(),
        res.control_points(),
        match res.estimated_hi() {
            None => format!("certified d_H ≤ {:.3e}", res.certified_hi),
            Some(e) => format!("UNPROVEN sampled estimate d_H ≈ {e:.3e}"),
        },
        res.tol.value()
    );
    let _ = writeln!(s, r#"<rect width="100%" height="100%" fill="white"/>"#);
    draw_main(&mut s, res, &input, &exact, &approx, &map);
    draw_curvature(&mut s, curve.len(), &exact, &approx);
    s.push_str("</svg>\n");
    s
}

/// Samples `(global parameter, point, curvature)` of the approximant.
fn approx_samples(res: &OffsetResult) -> Vec<Vec<(f64, V2<f64>, f64)>> {
    res.segments
        .iter()
        .map(|s| {
            (0..=SAMPLES / 4)
                .map(|k| {
                    let u = k as f64 / (SAMPLES / 4) as f64;
                    let g = s.piece as f64 + s.t.0 + u * (s.t.1 - s.t.0);
                    (g, s.bezier.eval(&u), curvature(&s.bezier, u))
                })
                .collect()
        })
        .collect()
}

/// Where the main picture puts a point: the bounding box of everything
/// drawn, scaled into it.
struct View {
    x0: f64,
    y0: f64,
    sc: f64,
    y_down: bool,
}

impl View {
    fn new(
        input: &[Bezier<f64>],
        res: &OffsetResult,
        exact: &[Vec<(f64, V2<f64>, f64)>],
        y_down: bool,
    ) -> View {
        let all = input
            .iter()
            .flat_map(|b| b.points().iter().cloned())
            .chain(
                res.segments
                    .iter()
                    .flat_map(|s| s.bezier.points().iter().cloned()),
            )
            .chain(exact.iter().flatten().map(|s| s.1.clone()))
            .filter(|p| p.x.is_finite() && p.y.is_finite());
        let (mut x0, mut x1, mut y0, mut y1) = (f64::MAX, f64::MIN, f64::MAX, f64::MIN);
        for p in all {
            x0 = x0.min(p.x);
            x1 = x1.max(p.x);
            y0 = y0.min(p.y);
            y1 = y1.max(p.y);
        }
        let span = (x1 - x0).max(y1 - y0).max(1e-300);
        let sc = ((W - 2.0 * PAD) / span).min((H_MAIN - 2.0 * PAD) / span);
        View { x0, y0, sc, y_down }
    }

    fn map(&self, p: &V2<f64>) -> (f64, f64) {
        let View { x0, y0, sc, y_down } = *self;
        let y = if y_down {
            PAD + (p.y - y0) * sc
        } else {
            H_MAIN - PAD - (p.y - y0) * sc
        };
        (PAD + (p.x - x0) * sc, y)
    }
}

/// The main picture: control polygons, input, exact offset, approximant, cusps.
fn draw_main(
    s: &mut String,
    res: &OffsetResult,
    input: &[Bezier<f64>],
    exact: &[Vec<(f64, V2<f64>, f64)>],
    approx: &[Vec<(f64, V2<f64>, f64)>],
    map: &dyn Fn(&V2<f64>) -> (f64, f64),
) {
    for seg in &res.segments {
        let _ = writeln!(
            s,
            r##"<polyline fill="none" stroke="#aaa" stroke-width="0.6" points="{}"/>"##,
            poly(seg.bezier.points(), map)
        );
    }
    for b in input {
        let pts: Vec<V2<f64>> = (0..=SAMPLES)
            .map(|k| b.eval(&(k as f64 / SAMPLES as f64)))
            .collect();
        let _ = writeln!(
            s,
            r##"<polyline fill="none" stroke="#1f4fd1" stroke-width="1.5" points="{}"/>"##,
            poly(&pts, map)
        );
    }
    for e in exact {
        let pts: Vec<V2<f64>> = e.iter().map(|x| x.1.clone()).collect();
        let _ = writeln!(
            s,
            r##"<polyline fill="none" stroke="#1a9c3a" stroke-width="3" stroke-opacity="0.5" points="{}"/>"##,
            poly(&pts, map)
        );
    }
    for a in approx {
        let pts: Vec<V2<f64>> = a.iter().map(|x| x.1.clone()).collect();
        let _ = writeln!(
            s,
            r##"<polyline fill="none" stroke="#c2188f" stroke-width="1" points="{}"/>"##,
            poly(&pts, map)
        );
    }
    for c in &res.cusps {
        let (x, y) = map(&V2::new(c.point.0, c.point.1));
        let _ = writeln!(
            s,
            r##"<circle cx="{x:.2}" cy="{y:.2}" r="3" fill="#d11f1f"/>"##
        );
    }
}

/// The curvature plot: exact offset (green) vs approximant (magenta), clipped
/// to a robust range; `pieces` input pieces on the horizontal axis.
fn draw_curvature(
    s: &mut String,
    pieces: usize,
    exact: &[Vec<(f64, V2<f64>, f64)>],
    approx: &[Vec<(f64, V2<f64>, f64)>],
) {
    let ks: Vec<f64> = exact
        .iter()
        .flatten()
        .map(|x| x.2)
        .filter(|k| k.is_finite())
        .collect();
    let mut sorted = ks.clone();
    sorted.sort_by(f64::total_cmp);
    let (klo, khi) = if sorted.is_empty() {
        (-1.0, 1.0)
    } else {
        let q = |f: f64| sorted[((sorted.len() - 1) as f64 * f) as usize];
        let (a, b) = (q(0.02), q(0.98));
        if b > a {
            (a - 0.1 * (b - a), b + 0.1 * (b - a))
        } else {
            (a - 1.0, a + 1.0)
        }
    };
    let n = pieces.max(1) as f64;
    let top = H_MAIN + 10.0;
    let pmap = |g: f64, k: f64| {
        let k = k.clamp(klo, khi);
        (
            PAD + g / n * (W - 2.0 * PAD),
            top + (H_PLOT - 20.0) * (1.0 - (k - klo) / (khi - klo)),
        )
    };
    let _ = writeln!(
        s,
        r##"<text x="{PAD}" y="{:.1}" font-size="10" fill="#333">curvature over the input parameter: exact offset (green), approximant (magenta), clipped to [{klo:.3}, {khi:.3}]</text>"##,
        top + H_PLOT - 4.0
    );
    let line = |pts: &[(f64, f64)], color: &str, w: f64| {
        let p = pts
            .iter()
            .map(|(g, k)| {
                let (x, y) = pmap(*g, *k);
                format!("{x:.2},{y:.2}")
            })
            .collect::<Vec<_>>()
            .join(" ");
        format!(r#"<polyline fill="none" stroke="{color}" stroke-width="{w}" points="{p}"/>"#)
    };
    for e in exact {
        let pts: Vec<(f64, f64)> = e
            .iter()
            .map(|x| (x.0, x.2))
            .filter(|x| x.1.is_finite())
            .collect();
        let _ = writeln!(s, "{}", line(&pts, "#1a9c3a", 3.0));
    }
    for a in approx {
        let pts: Vec<(f64, f64)> = a
            .iter()
            .map(|x| (x.0, x.2))
            .filter(|x| x.1.is_finite())
            .collect();
        let _ = writeln!(s, "{}", line(&pts, "#c2188f", 1.0));
    }
}
