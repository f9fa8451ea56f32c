//! Certified Hausdorff bounds (issue 4): time per segment pair at rel = 1e-3 and
//! 1e-6 (the default path: the radial proof for the arc, else the parametric
//! proof, else the search; for the arc also without the radial proof), the tightness of the bounds, and the time to verify the
//! certificate of `d_H ≤ 1.01 · hi` compared with the proof that produced it
//! (the default path — the radial cells or the parametric map where they
//! decide — and the search).
//!
//! Run: `cargo bench --bench hausdorff`.

// `criterion_group!` defines an undocumented `pub fn benches`.
#![allow(missing_docs)]

use criterion::{criterion_group, criterion_main, Criterion};
use lncert::certify::verify::verify;
use lncert::certify::{hausdorff, Certificate, Config};
use lncert::scalar::Rational;
use lncert::shape::ShapeDesc;
use std::hint::black_box;

fn pairs() -> Vec<(&'static str, ShapeDesc, ShapeDesc)> {
    let s = |t: &str| ShapeDesc::parse(t).unwrap();
    vec![
        (
            "arc_vs_cubic",
            s(r#"{"arc": {"center": [0, 0], "radius": 1, "from": [1, 0], "to": [0, 1]}}"#),
            s("M 1 0 C 1 0.5523 0.5523 1 0 1"),
        ),
        (
            // an SVG <circle> (two half arcs) against four cubics
            "circle_vs_4_cubics",
            s(r#"<svg xmlns="http://www.w3.org/2000/svg"><circle cx="0" cy="0" r="1"/></svg>"#),
            s("M 1 0 C 1 0.5523 0.5523 1 0 1 C -0.5523 1 -1 0.5523 -1 0 C -1 -0.5523 -0.5523 -1 0 -1 C 0.5523 -1 1 -0.5523 1 0"),
        ),
        (
            "cubic_vs_cubic",
            s("M 0 0 C 1 1 2 1 3 0"),
            s("M 0 0 C 1.01 1.02 1.98 0.99 3 0.01"),
        ),
        (
            "offset_vs_quadratic",
            s(r#"{"offset": {"curve": {"bezier": [[0, 0], [1, 1], [2, 0]]}, "distance": "1/10"}}"#),
            s("M -0.0707 0.0707 Q 1 1.2 2.0707 0.0707"),
        ),
        (
            "ellipse_conv_vs_cubic",
            s(
                r#"{"convolution": {"curve": {"bezier": [[0, 0], [1, 1], [2, 1], [3, 0]]}, "ellipse": [["1/5", 0], [0, "1/10"]], "side": 1}}"#,
            ),
            s("M -0.07 0.07 C 0.95 1.15 2.05 1.15 3.07 0.07"),
        ),
    ]
}

fn bench(c: &mut Criterion) {
    let mut g = c.benchmark_group("hausdorff");
    g.sample_size(20);
    for (name, a, b) in pairs() {
        for rel in [1e-3, 1e-6] {
            let cfg = Config {
                rel,
                ..Config::default()
            };
            let r = hausdorff(&a, &b, &cfg).unwrap();
            println!(
                "{name} rel {rel:e}: [{:.9e}, {:.9e}], gap/hi {:.1e}, boxes {} + {} (evaluated {} + {}){}",
                r.lo,
                r.hi,
                (r.hi - r.lo) / r.hi,
                r.a_to_b.boxes.len(),
                r.b_to_a.boxes.len(),
                r.a_to_b.evaluated,
                r.b_to_a.evaluated,
                if r.incomplete() { " INCOMPLETE" } else { "" }
            );
            g.bench_function(format!("search/{name}/rel={rel:e}"), |bch| {
                bch.iter(|| hausdorff(black_box(&a), black_box(&b), &cfg).unwrap())
            });
            if r.radial.is_some() {
                // the same pair without the radial proof (parametric, then search)
                let cfg_nr = Config {
                    radial: false,
                    ..cfg.clone()
                };
                g.bench_function(format!("no_radial/{name}/rel={rel:e}"), |bch| {
                    bch.iter(|| hausdorff(black_box(&a), black_box(&b), &cfg_nr).unwrap())
                });
            }
        }
        // certificate of d_H ≤ 1.01 hi, searched with that tolerance
        let r = hausdorff(
            &a,
            &b,
            &Config {
                rel: 1e-3,
                ..Config::default()
            },
        )
        .unwrap();
        let tol = lncert::Tolerance::new(Rational::from_float(r.hi * 1.01).unwrap()).unwrap();
        // the default path (parametric proof first) and the two-directional
        // search, whose box covers a certificate is built from
        let cfg = Config {
            tol: Some(tol.clone()),
            ..Config::default()
        };
        let cfg_search = Config {
            parametric: false,
            ..cfg.clone()
        };
        let rp = hausdorff(&a, &b, &cfg).unwrap();
        let rt = hausdorff(&a, &b, &cfg_search).unwrap();
        let cert = Certificate::new(&a, &b, &tol, &rt).expect("certified");
        let cert_p = Certificate::new(&a, &b, &tol, &rp).expect("certified");
        println!(
            "{name}: d_H ≤ 1.01·hi by the {} path ({} boxes evaluated, certificate of {} boxes); by the search: certificate of {} boxes",
            if rp.parametric.is_some() {
                "parametric"
            } else if rp.radial.is_some() && cert_p.is_radial() {
                "radial (a version 4 certificate of its cells)"
            } else if rp.radial.is_some() {
                "radial (the certificate proven again)"
            } else {
                "search"
            },
            rp.a_to_b.evaluated + rp.b_to_a.evaluated,
            cert_p.box_count(),
            cert.box_count()
        );
        g.bench_function(format!("certify_tol/{name}"), |bch| {
            bch.iter(|| hausdorff(black_box(&a), black_box(&b), &cfg).unwrap())
        });
        g.bench_function(format!("certify_tol_search/{name}"), |bch| {
            bch.iter(|| hausdorff(black_box(&a), black_box(&b), &cfg_search).unwrap())
        });
        let text = cert.to_json_string();
        g.bench_function(format!("verify_search/{name}"), |bch| {
            bch.iter(|| verify(black_box(&text)).unwrap())
        });
        // the certificate of the default path (a parametric map where it decided)
        let text_p = cert_p.to_json_string();
        g.bench_function(format!("verify/{name}"), |bch| {
            bch.iter(|| verify(black_box(&text_p)).unwrap())
        });
    }
    g.finish();
}

criterion_group!(benches, bench);
criterion_main!(benches);
