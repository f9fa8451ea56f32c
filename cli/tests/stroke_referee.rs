//! The referee (`lncert::stroke::distance_to_stroke`, `lncert hausdorff X
//! STROKE.json`): certified bounds on `d_H(X, ∂S)` for outlines made by other
//! strokers, checked against an independent dense sampling of `∂S` and of `X`.

mod common;
use common::{json_of, lncert};
use kurbo::{BezPath, Point};
use lncert::certify::Config;
use lncert::curve::Bezier;
use lncert::kurbo_bridge::shape_from_path;
use lncert::scalar::{Rational, Scalar};
use lncert::shape::parse_curve;
use lncert::stroke::{distance_to_stroke, StrokeDistance, StrokeOptions};

fn dist(p: (f64, f64), q: (f64, f64)) -> f64 {
    ((p.0 - q.0).powi(2) + (p.1 - q.1).powi(2)).sqrt()
}

fn seg_dist(a: (f64, f64), b: (f64, f64), p: (f64, f64)) -> f64 {
    let (dx, dy) = (b.0 - a.0, b.1 - a.1);
    let l2 = dx * dx + dy * dy;
    let t = if l2 > 0.0 {
        (((p.0 - a.0) * dx + (p.1 - a.1) * dy) / l2).clamp(0.0, 1.0)
    } else {
        0.0
    };
    dist(p, (a.0 + t * dx, a.1 + t * dy))
}

/// Distance from `p` to the input curve: dense samples, then golden section.
fn dist_to_curve(curve: &[Bezier<f64>], p: (f64, f64)) -> f64 {
    let mut best = f64::INFINITY;
    for b in curve {
        let d = |t: f64| {
            let v = b.eval_fast(t);
            dist((v.x, v.y), p)
        };
        let n = 200;
        let k = (0..=n)
            .min_by(|&i, &j| d(i as f64 / n as f64).total_cmp(&d(j as f64 / n as f64)))
            .unwrap();
        let (mut lo, mut hi) = (
            (k as f64 - 1.0).max(0.0) / n as f64,
            (k as f64 + 1.0).min(n as f64) / n as f64,
        );
        for _ in 0..60 {
            let (m1, m2) = (lo + (hi - lo) * 0.382, lo + (hi - lo) * 0.618);
            if d(m1) < d(m2) {
                hi = m2;
            } else {
                lo = m1;
            }
        }
        best = best.min(d(0.5 * (lo + hi))).min(d(k as f64 / n as f64));
    }
    best
}

/// Samples of the exact boundary `∂S` of `curve ⊕ disk(r)` (open curve,
/// round caps): offset points `x ± rN` and cap points whose distance to the
/// curve is not below `r` (the others are inside S), and the largest gap
/// between consecutive candidates (every point of `∂S` is within it of a
/// sample).
fn boundary_samples(curve: &[Bezier<f64>], r: f64, n: usize) -> (Vec<(f64, f64)>, f64) {
    let mut runs: Vec<Vec<(f64, f64)>> = Vec::new();
    for b in curve {
        let h = b.hodograph();
        for s in [r, -r] {
            runs.push(
                (0..=n)
                    .map(|k| {
                        let t = k as f64 / n as f64;
                        let (p, d) = (b.eval_fast(t), h.eval_fast(t));
                        let l = d.length();
                        (p.x - s * d.y / l, p.y + s * d.x / l)
                    })
                    .collect(),
            );
        }
    }
    for (b, e) in [(&curve[0], 0.0), (&curve[curve.len() - 1], 1.0)] {
        let c = b.eval_fast(e);
        runs.push(
            (0..=n)
                .map(|k| {
                    let t = k as f64 / n as f64 * std::f64::consts::TAU;
                    (c.x + r * t.cos(), c.y + r * t.sin())
                })
                .collect(),
        );
    }
    let gap = runs
        .iter()
        .flat_map(|run| run.windows(2).map(|w| dist(w[0], w[1])))
        .fold(0.0, f64::max);
    let pts = runs
        .into_iter()
        .flatten()
        .filter(|p| dist_to_curve(curve, *p) >= r - 1e-9)
        .collect();
    (pts, gap)
}

/// What sampling says of `h(X, ∂S)` and `h(∂S, X)`, each as an interval
/// `[lo, hi]` that holds the true value (up to float error): `X` flattened by
/// kurbo within `1e-6`, `∂S` sampled as above.
fn sampled(x: &BezPath, curve: &[Bezier<f64>], r: f64) -> ((f64, f64), (f64, f64)) {
    let (bd, gap_b) = boundary_samples(curve, r, 1500);
    let mut poly: Vec<Vec<(f64, f64)>> = Vec::new();
    kurbo::flatten(x, 1e-6, |el| match el {
        kurbo::PathEl::MoveTo(p) => poly.push(vec![(p.x, p.y)]),
        kurbo::PathEl::LineTo(p) => poly.last_mut().unwrap().push((p.x, p.y)),
        kurbo::PathEl::ClosePath => {
            let first = poly.last().unwrap()[0];
            poly.last_mut().unwrap().push(first);
        }
        _ => unreachable!("flatten gives lines"),
    });
    // h(X, ∂S): the distance to ∂S is 1-Lipschitz, so the sup over a chord
    // is at most the larger end value plus half its length; each sampled
    // distance is at least the true one and at most it plus the gap
    let mut to = (0.0f64, 0.0f64);
    for pl in &poly {
        for w in pl.windows(2) {
            let (d0, d1) = (
                bd.iter()
                    .map(|q| dist(*q, w[0]))
                    .fold(f64::INFINITY, f64::min),
                bd.iter()
                    .map(|q| dist(*q, w[1]))
                    .fold(f64::INFINITY, f64::min),
            );
            to.0 = to.0.max(d0.max(d1) - gap_b);
            to.1 = to.1.max(d0.max(d1) + 0.5 * dist(w[0], w[1]));
        }
    }
    // h(∂S, X): the sup over the samples is at most the true one (+1e-6 for
    // the flattening), and the true one at most the samples' plus the gap
    let mut from = 0.0f64;
    for q in &bd {
        let d = poly
            .iter()
            .flat_map(|pl| pl.windows(2).map(|w| seg_dist(w[0], w[1], *q)))
            .fold(f64::INFINITY, f64::min);
        from = from.max(d);
    }
    (to, (from - 1e-6, from + gap_b))
}

fn kurbo_path(curve: &[Bezier<Rational>]) -> BezPath {
    let pt = |v: &lncert::curve::V2<Rational>| Point::new(v.x.approx(), v.y.approx());
    let mut p = BezPath::new();
    p.move_to(pt(&curve[0].points()[0]));
    for b in curve {
        let q = b.points();
        match q.len() {
            2 => p.line_to(pt(&q[1])),
            4 => p.curve_to(pt(&q[1]), pt(&q[2]), pt(&q[3])),
            _ => unreachable!("lines and cubics only here"),
        }
    }
    p
}

fn check(
    name: &str,
    x: &BezPath,
    curve: &[Bezier<Rational>],
    r: &str,
    stroke_tol: &str,
) -> StrokeDistance {
    let rq = common::qs(r);
    let rf = rq.approx();
    let shape = shape_from_path(x).unwrap();
    let opts = {
        let mut o = StrokeOptions::new(rq, stroke_tol.parse().unwrap());
        o.output = lncert::offset::Output::Cubic;
        o
    };
    let d = distance_to_stroke(&shape, curve, &opts, &Config::default()).unwrap();
    assert!(d.complete(), "{name}: stroke or search not complete");
    let cf: Vec<Bezier<f64>> = curve.iter().map(|b| b.map(Scalar::approx)).collect();
    let (to, from) = sampled(x, &cf, rf);
    let eps = 1e-9;
    for (what, got, want) in [
        ("h(X, ∂S)", d.to_stroke, to),
        ("h(∂S, X)", d.from_stroke, from),
    ] {
        // the certified interval and the sampled one must overlap
        assert!(
            got.0 <= want.1 + eps && want.0 <= got.1 + eps,
            "{name}: {what} certified {got:?} but sampled {want:?}"
        );
    }
    // the search stops when d_H's gap is small (the smaller direction's
    // bounds need only stay below the larger one): d_H's interval is no
    // wider than the stroke's bounds and the search's gap allow — the gap of
    // a direction's search is below its relative gap (1e-3, doubled here)
    // or below the referee's absolute gap, a quarter of the stroke's
    // tolerance E (`stroke::referee::distance_through`: the bounds carry the
    // outline's (a), (b) up to E anyway)
    let e = stroke_tol.parse::<f64>().unwrap();
    let allowed = 2.0 * d.stroke.a.bound.max(d.stroke.b.bound) + (2e-3 * d.hi).max(e / 4.0) + 1e-12;
    assert!(
        d.hi - d.lo <= allowed,
        "{name}: d_H in [{}, {}] wider than {allowed}",
        d.lo,
        d.hi
    );
    assert_eq!(d.lo, d.to_stroke.0.max(d.from_stroke.0));
    assert_eq!(d.hi, d.to_stroke.1.max(d.from_stroke.1));
    d
}

fn test_cubic() -> Vec<Bezier<Rational>> {
    parse_curve(r#"{"bezier": [[-0.95, 0.7], [-0.3, 0.5], [0.3, -2.5], [0.9, -0.2]]}"#).unwrap()
}

#[test]
fn kurbo_strokes_are_bracketed_against_sampling() {
    // kurbo's stroke of the test cubic (a swallowtail inside) and of a
    // polyline with a sharp corner (its inner join runs through the corner)
    let cases = [
        ("test cubic", test_cubic(), "0.4"),
        ("polyline", parse_curve("M 0 0 L 3 0 L 1 1").unwrap(), "1/4"),
    ];
    for (name, curve, r) in cases {
        let w = 2.0 * common::qs(r).approx();
        let k = kurbo::stroke(
            kurbo_path(&curve),
            &kurbo::Stroke::new(w),
            &kurbo::StrokeOpts::default(),
            1e-3,
        );
        let d = check(&format!("kurbo {name}"), &k, &curve, r, "1e-2");
        // kurbo's outline keeps parts inside S: it is not within its 1e-3
        // of ∂S as a point set, while it does cover ∂S
        assert!(d.to_stroke.0 > 1e-2, "kurbo {name}: {:?}", d.to_stroke);
        assert!(
            d.from_stroke.1 < 2.5e-2,
            "kurbo {name}: {:?}",
            d.from_stroke
        );
    }
}

#[test]
fn an_outline_near_the_stroke_is_bracketed() {
    // lncert's own outline at a coarser tolerance, written as a kurbo path:
    // within its proven bound of ∂S, and the referee's (finer) stroke says so
    let curve = test_cubic();
    let o = {
        let mut o = StrokeOptions::new(common::qs("0.4"), "5e-2".parse().unwrap());
        o.output = lncert::offset::Output::Cubic;
        o
    };
    let s = lncert::stroke::stroke(&curve, &o).unwrap();
    assert!(s.proven());
    let path = lncert::kurbo_bridge::path_from_contours(&s.contours, 1e-7).unwrap();
    let d = check("lncert at 5e-2", &path, &curve, "0.4", "1e-3");
    let claimed = s.a.bound.max(s.b.bound);
    assert!(
        d.hi <= claimed + 3e-3,
        "{} against the claimed {claimed}",
        d.hi
    );
}

#[test]
fn cli_referee_verdicts_and_errors() {
    let st = common::tmp(
        "s.json",
        r#"{"stroke": {"curve": "M 0 0 L 4 0", "pen": {"circle": "1/2"}}}"#,
    );
    // corners √(0.5² + 0.53²) − 0.5 = 0.228629… from the caps
    let x = common::tmp("x.svg", "M -0.5 -0.53 L 4.5 -0.53 L 4.5 0.53 L -0.5 0.53 Z");
    let (xs, ss) = (x.to_str().unwrap(), st.to_str().unwrap());
    let exact = (0.5f64 * 0.5 + 0.53 * 0.53).sqrt() - 0.5;
    for (args, code) in [
        (vec![xs, ss, "--tol", "0.25", "--json"], 0),
        (vec![ss, xs, "--tol", "0.2", "--json"], 1),
        (vec![xs, ss, "--tol", "0.2286", "--json"], 1),
        // the bounds straddle the claim: a coarse search and a coarse stroke
        (
            vec![
                xs,
                ss,
                "--tol",
                "0.22863",
                "--rel",
                "0.5",
                "--stroke-tol",
                "0.05",
                "--json",
            ],
            3,
        ),
    ] {
        let o = lncert(
            &["hausdorff"]
                .into_iter()
                .chain(args.clone())
                .collect::<Vec<_>>(),
        );
        assert_eq!(
            o.status.code(),
            Some(code),
            "{args:?}: {}",
            String::from_utf8_lossy(&o.stderr)
        );
        let j = json_of(&o);
        let (lo, hi) = (j["lo"].as_f64().unwrap(), j["hi"].as_f64().unwrap());
        assert!(
            lo <= exact && exact <= hi,
            "{args:?}: [{lo}, {hi}] misses {exact}"
        );
        assert_eq!(j["proof"], "stroke");
        assert_eq!(j["stroke_shape"], if args[0] == ss { "A" } else { "B" });
    }
    // errors: exit 2 naming the field
    let bad = common::tmp("bad.json", "");
    for (text, field) in [
        (
            r#"{"stroke": {"curve": "M 0 0 L 4 0", "pen": {"circle": 0}}}"#,
            "stroke.pen.circle",
        ),
        (
            r#"{"stroke": {"curve": "M 0 0 L 4 0", "pen": {"square": 1}}}"#,
            "stroke.pen",
        ),
        (r#"{"stroke": {"curve": "M 0 0 L 4 0"}}"#, "stroke.pen"),
        (
            r#"{"stroke": {"curve": "M 0 0 L 4 0", "pen": {"circle": 1}, "cap": "butt"}}"#,
            "stroke.cap",
        ),
        (
            r#"{"stroke": {"curve": "M 0 0 L 4 0", "pen": {"ellipse": [[1, 2], [2, 4]]}}}"#,
            "stroke.pen.ellipse",
        ),
        (
            r#"{"stroke": {"curve": "M 0 0 L 0 0", "pen": {"circle": 1}}}"#,
            "stroke.curve",
        ),
    ] {
        std::fs::write(&bad, text).unwrap();
        let o = lncert(&["hausdorff", xs, bad.to_str().unwrap(), "--json"]);
        assert_eq!(o.status.code(), Some(2), "{text}");
        let j = json_of(&o);
        let f = format!("{} {}", j["error"]["field"], j["error"]["reason"]);
        assert!(f.contains(field), "{text}: {j}");
    }
    // two strokes are refused, and a certificate without --tol
    let o = lncert(&["hausdorff", ss, ss]);
    assert_eq!(o.status.code(), Some(2));
    let cert = common::tmp("c.json", "");
    std::fs::remove_file(&cert).unwrap();
    let o = lncert(&["hausdorff", xs, ss, "--certificate", cert.to_str().unwrap()]);
    assert_eq!(o.status.code(), Some(2));
    assert!(String::from_utf8_lossy(&o.stderr).contains("--certificate"));
    assert!(!cert.exists());
    // with --tol, a certified verdict comes with a stroke distance certificate
    let o = lncert(&[
        "hausdorff",
        xs,
        ss,
        "--tol",
        "1",
        "--certificate",
        cert.to_str().unwrap(),
    ]);
    assert_eq!(
        o.status.code(),
        Some(0),
        "{}",
        String::from_utf8_lossy(&o.stderr)
    );
    let v = lncert(&["verify", cert.to_str().unwrap()]);
    assert_eq!(
        v.status.code(),
        Some(0),
        "{}",
        String::from_utf8_lossy(&v.stdout)
    );
}

/// Skia's committed outline of the heart icon (`cli/examples/data/`, made by
/// `skia_stroke_dump.py`): certified within 1e-2 of the exact stroke
/// boundary, and refuted against a wrong pen.
#[test]
fn cli_referees_a_committed_skia_outline() {
    let data: serde_json::Value = serde_json::from_str(
        &std::fs::read_to_string(concat!(
            env!("CARGO_MANIFEST_DIR"),
            "/examples/data/skia_strokes.json"
        ))
        .unwrap(),
    )
    .unwrap();
    let heart = "M20.84 4.61a5.5 5.5 0 0 0-7.78 0L12 5.67l-1.06-1.06a5.5 5.5 0 0 0-7.78 7.78l1.06 1.06L12 21.23l7.78-7.78 1.06-1.06a5.5 5.5 0 0 0 0-7.78z";
    let x = common::tmp(
        "skia-heart.svg",
        data["outlines"]["icon heart"].as_str().unwrap(),
    );
    for (r, code, verdict) in [("1", 0, "certified"), ("0.9", 1, "refuted")] {
        let st = common::tmp(
            &format!("heart-{r}.json"),
            &serde_json::json!({"stroke": {"curve": heart, "pen": {"circle": r}}}).to_string(),
        );
        let o = lncert(&[
            "hausdorff",
            x.to_str().unwrap(),
            st.to_str().unwrap(),
            "--tol",
            "1e-2",
            "--json",
        ]);
        assert_eq!(
            o.status.code(),
            Some(code),
            "r {r}: {}",
            String::from_utf8_lossy(&o.stderr)
        );
        let j = json_of(&o);
        assert_eq!(j["verdict"], verdict);
        // the icon's arcs are read as cubics within a certified bound, and
        // the report says so
        assert!(
            j["input_approximation"]["bound"].as_f64().unwrap() < 1e-6,
            "{j}"
        );
        if r == "0.9" {
            // a pen 0.1 too small: ∂S is 0.1 inside Skia's outline
            assert!(j["lo"].as_f64().unwrap() > 0.09, "{j}");
        }
    }
}
