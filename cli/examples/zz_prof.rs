//! temp
use lncert::offset::Output;
use lncert::scalar::Rational;
use lncert::stroke::{certificate, stroke, PenShape, StrokeOptions};
fn main() {
    let el = std::env::args()
        .nth(1)
        .unwrap_or(r#"<ellipse cx="12" cy="12" rx="8" ry="4"/>"#.into());
    let n: usize = std::env::args().nth(2).map_or(300, |s| s.parse().unwrap());
    let doc = format!(
        r#"<svg xmlns="http://www.w3.org/2000/svg" viewBox="0 0 24 24" fill="none" stroke="currentColor" stroke-width="2">{el}</svg>"#
    );
    let curve = lncert::shape::parse_svg_document(&doc).unwrap();
    let one = Rational::from_integer(1.into());
    let mut o = StrokeOptions::with_pen(
        PenShape::Circle(one.clone()),
        lncert::Tolerance::from_f64(1e-2).unwrap(),
    );
    o.output = Output::Cubic;
    let s = stroke(&curve, &o).unwrap();
    let c = certificate(&curve, &s, &one).unwrap();
    let text = c.to_string();
    std::fs::write("/tmp/zz_cert.json", &text).unwrap();
    let t = std::time::Instant::now();
    for _ in 0..n {
        lncert::certify::verify::verify(&text).unwrap();
    }
    eprintln!(
        "verify {:.3} ms",
        t.elapsed().as_secs_f64() * 1e3 / n as f64
    );
    let t = std::time::Instant::now();
    if std::env::var("NOSTROKE").is_ok() {
        return;
    }
    for _ in 0..n / 4 {
        stroke(&curve, &o).unwrap();
    }
    eprintln!(
        "stroke {:.3} ms",
        t.elapsed().as_secs_f64() * 1e3 / (n / 4) as f64
    );
}
