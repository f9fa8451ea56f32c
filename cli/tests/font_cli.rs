//! `lncert font`: the glyphs of every installed DejaVu font are read (none
//! refused, no singular piece), a UFO of a DejaVu Sans subset is written and
//! read back with norad, and each proven glyph is checked independently
//! (dense float samples against a polyline of the input glyph), plus every
//! typed error. Skips without DejaVu unless `LNCERT_REQUIRE_FONT=1`.

mod common;

use common::{dejavu, lncert};
use lncert::curve::Bezier;
use lncert::scalar::{Rational, Scalar};
use serde_json::Value;
use std::path::{Path, PathBuf};

fn dir(name: &str) -> PathBuf {
    let d = std::env::temp_dir().join(format!("lncert-font-cli-{}", std::process::id()));
    std::fs::create_dir_all(&d).unwrap();
    d.join(name)
}

fn run_ok(args: &[&str]) -> std::process::Output {
    let o = lncert(args);
    assert!(
        o.status.code() == Some(0) || o.status.code() == Some(3),
        "exit {:?}\nstdout: {}\nstderr: {}",
        o.status.code(),
        String::from_utf8_lossy(&o.stdout),
        String::from_utf8_lossy(&o.stderr)
    );
    o
}

fn report(p: &Path) -> Value {
    serde_json::from_str(&std::fs::read_to_string(p).unwrap()).unwrap()
}

/// Every glyph of every installed DejaVu font is read, and no piece is
/// singular (its derivative vanishes nowhere on [0, 1]): TrueType quadratics
/// decided from their control points, other pieces by exact root isolation.
#[test]
fn every_glyph_of_every_installed_dejavu_font_is_read() {
    let Some(sans) = dejavu() else { return };
    let fonts: Vec<PathBuf> = std::fs::read_dir(sans.parent().unwrap())
        .unwrap()
        .map(|e| e.unwrap().path())
        .filter(|p| p.extension().is_some_and(|e| e == "ttf"))
        .collect();
    assert!(!fonts.is_empty());
    let mut glyphs = 0;
    for f in &fonts {
        let data = std::fs::read(f).unwrap();
        let info = lncert::shape::font_info(&data).unwrap();
        for g in &info.glyphs {
            let pieces = lncert::shape::glyph_outline_by_id(&data, g.id)
                .unwrap_or_else(|e| panic!("{} {}: refused: {e}", f.display(), g.name));
            for (i, b) in pieces.iter().enumerate() {
                assert!(
                    regular(b),
                    "{} {}: piece {i} is singular: {:?}",
                    f.display(),
                    g.name,
                    b.points()
                );
            }
            glyphs += 1;
        }
    }
    eprintln!("{} fonts, {glyphs} glyphs read", fonts.len());
}

fn regular(b: &Bezier<Rational>) -> bool {
    let p = b.points();
    let zero = Rational::from_integer(0.into());
    match p.len() {
        2 => p[0] != p[1],
        3 => {
            let (a, d) = (p[1].sub(&p[0]), p[2].sub(&p[1]));
            // B'(t) = 2((1 − t) a + t d): zero somewhere iff a = 0, d = 0 or a, d antiparallel
            !(a.dot(&a) == zero || d.dot(&d) == zero || (a.cross(&d) == zero && a.dot(&d) < zero))
        }
        _ => {
            let (dx, dy) = b.hodograph().power_coords();
            !lncert::poly::has_common_root_in(&dx, &dy, &lncert::poly::Span::unit_closed())
        }
    }
}

/// The glyphs the engine used to refuse as singular ("curve[21]: the curve is
/// singular") are offset now.
#[test]
fn formerly_singular_glyphs_are_offset() {
    let Some(sans) = dejavu() else { return };
    let serif = sans.with_file_name("DejaVuSerif.ttf");
    for (font, glyphs) in [(sans.clone(), "ʓ,ƺ,ʧ"), (serif, "Ɂ,ɤ,ʽ,˞")] {
        if !font.exists() {
            eprintln!("skipped: {}", font.display());
            continue;
        }
        let out = dir(&format!(
            "sing-{}.ufo",
            font.file_stem().unwrap().to_string_lossy()
        ));
        let rep = out.with_extension("json");
        run_ok(&[
            "font",
            font.to_str().unwrap(),
            "--offset",
            "20",
            "--tol",
            "1",
            "--glyphs",
            glyphs,
            "--out",
            out.to_str().unwrap(),
            "--report",
            rep.to_str().unwrap(),
            "--force",
        ]);
        let r = report(&rep);
        for g in r["glyphs"].as_array().unwrap() {
            assert_ne!(g["verdict"], "error", "{g}");
            assert!(!g["reason"].as_str().unwrap().contains("singular"), "{g}");
            assert!(g["pieces"].as_u64().unwrap() > 0, "{g}");
        }
    }
}

/// Float samples of a contour of exact pieces.
fn samples(c: &[Bezier<Rational>], n: usize) -> Vec<(f64, f64)> {
    let mut v = Vec::new();
    for b in c {
        let f = b.map(Scalar::approx);
        for k in 0..n {
            let p = f.eval_fast(k as f64 / n as f64);
            v.push((p.x, p.y));
        }
    }
    v
}

fn seg_dist(p: (f64, f64), a: (f64, f64), b: (f64, f64)) -> f64 {
    let (dx, dy) = (b.0 - a.0, b.1 - a.1);
    let l = dx * dx + dy * dy;
    let t = if l == 0.0 {
        0.0
    } else {
        (((p.0 - a.0) * dx + (p.1 - a.1) * dy) / l).clamp(0.0, 1.0)
    };
    ((p.0 - a.0 - t * dx).powi(2) + (p.1 - a.1 - t * dy).powi(2)).sqrt()
}

/// Distance from `p` to closed polylines.
fn dist(p: (f64, f64), polys: &[Vec<(f64, f64)>]) -> f64 {
    let mut m = f64::INFINITY;
    for q in polys {
        for k in 0..q.len() {
            m = m.min(seg_dist(p, q[k], q[(k + 1) % q.len()]));
        }
    }
    m
}

/// Nonzero winding of closed polylines about `p`.
fn winding(p: (f64, f64), polys: &[Vec<(f64, f64)>]) -> i32 {
    let mut w = 0;
    for q in polys {
        for k in 0..q.len() {
            let (a, b) = (q[k], q[(k + 1) % q.len()]);
            let side = (b.0 - a.0) * (p.1 - a.1) - (p.0 - a.0) * (b.1 - a.1);
            if a.1 <= p.1 && b.1 > p.1 && side > 0.0 {
                w += 1;
            } else if a.1 > p.1 && b.1 <= p.1 && side < 0.0 {
                w -= 1;
            }
        }
    }
    w
}

fn area(q: &[(f64, f64)]) -> f64 {
    (0..q.len())
        .map(|k| {
            let (a, b) = (q[k], q[(k + 1) % q.len()]);
            a.0 * b.1 - b.0 * a.1
        })
        .sum::<f64>()
        / 2.0
}

/// The input glyph's contours as float polylines (read by lncert's font
/// reader, sampled here).
fn input_polys(font: &Path, name: &str) -> Vec<Vec<(f64, f64)>> {
    let data = std::fs::read(font).unwrap();
    let info = lncert::shape::font_info(&data).unwrap();
    let id = info.glyphs.iter().find(|g| g.name == name).unwrap().id;
    let pieces = lncert::shape::glyph_outline_by_id(&data, id).unwrap();
    // split into contours at the joints where the next piece does not continue
    let mut out: Vec<Vec<Bezier<Rational>>> = Vec::new();
    for b in pieces {
        match out.last_mut() {
            Some(c) if c.last().unwrap().points().last() == Some(&b.points()[0]) => c.push(b),
            _ => out.push(vec![b]),
        }
    }
    out.iter().map(|c| samples(c, 400)).collect()
}

/// The written contours of a UFO glyph as float polylines (curve points by
/// the cubic formula, lines as they are).
fn ufo_polys(g: &norad::Glyph) -> Vec<Vec<(f64, f64)>> {
    use norad::PointType;
    let mut out = Vec::new();
    for c in &g.contours {
        let pts = &c.points;
        let n = pts.len();
        // start at the last on-curve point
        let start = (0..n)
            .rev()
            .find(|&k| pts[k].typ != PointType::OffCurve)
            .unwrap();
        let mut cur = (pts[start].x, pts[start].y);
        let mut off: Vec<(f64, f64)> = Vec::new();
        let mut poly = Vec::new();
        for k in 1..=n {
            let p = &pts[(start + k) % n];
            let xy = (p.x, p.y);
            match p.typ {
                PointType::OffCurve => off.push(xy),
                PointType::Line => {
                    for s in 0..50 {
                        let t = s as f64 / 50.0;
                        poly.push((cur.0 + t * (xy.0 - cur.0), cur.1 + t * (xy.1 - cur.1)));
                    }
                    cur = xy;
                }
                PointType::Curve => {
                    assert_eq!(off.len(), 2);
                    let (a, b, c, d) = (cur, off[0], off[1], xy);
                    for s in 0..200 {
                        let t = s as f64 / 200.0;
                        let u = 1.0 - t;
                        let w = [u * u * u, 3.0 * u * u * t, 3.0 * u * t * t, t * t * t];
                        poly.push((
                            w[0] * a.0 + w[1] * b.0 + w[2] * c.0 + w[3] * d.0,
                            w[0] * a.1 + w[1] * b.1 + w[2] * c.1 + w[3] * d.1,
                        ));
                    }
                    off.clear();
                    cur = xy;
                }
                PointType::QCurve => {
                    // a TrueType run: implied on-curve points between off-curve points
                    let mut from = cur;
                    for (i, &c) in off.iter().enumerate() {
                        let to = match off.get(i + 1) {
                            Some(&n) => ((c.0 + n.0) / 2.0, (c.1 + n.1) / 2.0),
                            None => xy,
                        };
                        for s in 0..100 {
                            let t = s as f64 / 100.0;
                            let u = 1.0 - t;
                            let w = [u * u, 2.0 * u * t, t * t];
                            poly.push((
                                w[0] * from.0 + w[1] * c.0 + w[2] * to.0,
                                w[0] * from.1 + w[1] * c.1 + w[2] * to.1,
                            ));
                        }
                        from = to;
                    }
                    off.clear();
                    cur = xy;
                }
                t => panic!("unexpected point type {t:?}"),
            }
        }
        out.push(poly);
    }
    out
}

#[test]
fn subset_ufo_is_written_proven_and_checked_independently() {
    let Some(sans) = dejavu() else { return };
    let out = dir("subset.ufo");
    let rep = dir("subset.json");
    let t0 = std::time::Instant::now();
    let o = run_ok(&[
        "font",
        sans.to_str().unwrap(),
        "--glyphs",
        "o,l,H,uni0041,period,space",
        "--offset",
        "20",
        "--tol",
        "1",
        "--grid",
        "1",
        "--out",
        out.to_str().unwrap(),
        "--report",
        rep.to_str().unwrap(),
        "--force",
    ]);
    eprintln!("{}", String::from_utf8_lossy(&o.stdout));
    eprintln!("{:.1} s", t0.elapsed().as_secs_f64());
    let r = report(&rep);
    let ufo = norad::Font::load(&out).unwrap();
    assert_eq!(ufo.font_info.units_per_em.map(|u| u.as_f64()), Some(2048.0));
    let layer = ufo.default_layer();
    let mut names: Vec<String> = layer.iter().map(|g| g.name().to_string()).collect();
    names.sort();
    assert_eq!(names, ["A", "H", "l", "o", "period", "space"]);
    assert_eq!(
        layer
            .get_glyph("A")
            .unwrap()
            .codepoints
            .iter()
            .collect::<Vec<_>>(),
        ['A']
    );
    assert_eq!(
        layer
            .get_glyph("period")
            .unwrap()
            .codepoints
            .iter()
            .collect::<Vec<_>>(),
        ['.']
    );
    assert!(layer.get_glyph("space").unwrap().contours.is_empty());
    let mut proven = 0;
    for g in r["glyphs"].as_array().unwrap() {
        let name = g["name"].as_str().unwrap();
        let glyph = layer.get_glyph(name).unwrap();
        let mark = glyph
            .lib
            .get("org.lncert.proven")
            .and_then(|v| v.as_boolean());
        let v = g["verdict"].as_str().unwrap();
        assert_eq!(mark, Some(v == "proven" || v == "empty"), "{name}: {g}");
        assert!(glyph.width > 0.0);
        if v != "proven" {
            eprintln!("{name}: {v}: {}", g["reason"]);
            continue;
        }
        proven += 1;
        let bound = g["bound"].as_f64().unwrap();
        assert!(bound <= 1.0, "{name}: bound {bound}");
        assert_eq!(
            glyph.lib.get("org.lncert.bound").and_then(|v| v.as_real()),
            Some(bound)
        );
        // integers on the grid
        for c in &glyph.contours {
            for p in &c.points {
                assert!(p.x.fract() == 0.0 && p.y.fract() == 0.0, "{name}: {p:?}");
            }
        }
        let input = input_polys(&sans, name);
        let output = ufo_polys(glyph);
        // (a): every written point at distance 20 ± bound from the input glyph,
        // and outside its fill
        let eps = 0.05; // the polylines' chord error
        for q in &output {
            for &p in q {
                let d = dist(p, &input);
                assert!((d - 20.0).abs() <= bound + eps, "{name}: {p:?} at {d}");
                assert_eq!(winding(p, &input), 0, "{name}: {p:?} inside the fill");
            }
        }
        // (b): every point of the exact grown boundary (found as the input's
        // points moved by 20 along the outward normal that stay at distance 20)
        // is within bound of the output
        for c in &input {
            for k in 0..c.len() {
                let (a, b) = (c[k], c[(k + 1) % c.len()]);
                let (tx, ty) = (b.0 - a.0, b.1 - a.1);
                let l = (tx * tx + ty * ty).sqrt();
                if l == 0.0 {
                    continue;
                }
                // TrueType: the fill is on the right of the travel, outward is left
                let p = (a.0 - 20.0 * ty / l, a.1 + 20.0 * tx / l);
                if dist(p, &input) < 20.0 - 1e-6 {
                    continue;
                }
                let d = dist(p, &output);
                assert!(
                    d <= bound + eps,
                    "{name}: exact boundary point {p:?} at {d} from the output"
                );
            }
        }
        // orientation (the UFO convention): outer contours counter-clockwise, holes clockwise
        for (i, q) in output.iter().enumerate() {
            let depth = output
                .iter()
                .enumerate()
                .filter(|(j, o)| *j != i && winding(q[0], std::slice::from_ref(o)) != 0)
                .count();
            let a = area(q);
            assert!(
                (depth % 2 == 0) == (a > 0.0),
                "{name}: contour {i} depth {depth} area {a}"
            );
        }
    }
    assert_eq!(r["summary"]["empty"], 1);
    assert_eq!(r["summary"]["proven"], proven);
    assert!(proven >= 4, "{r}");
    assert_eq!(layer.get_glyph("o").unwrap().contours.len(), 2);
}

#[test]
fn negative_offset_keeps_the_contours_inside_the_fill() {
    let Some(sans) = dejavu() else { return };
    let out = dir("shrink.ufo");
    let rep = dir("shrink.json");
    run_ok(&[
        "font",
        sans.to_str().unwrap(),
        "--glyphs",
        "o",
        "--offset",
        "-20",
        "--tol",
        "1",
        "--out",
        out.to_str().unwrap(),
        "--report",
        rep.to_str().unwrap(),
        "--force",
    ]);
    let r = report(&rep);
    assert_eq!(r["glyphs"][0]["verdict"], "proven", "{r}");
    let bound = r["glyphs"][0]["bound"].as_f64().unwrap();
    let ufo = norad::Font::load(&out).unwrap();
    let glyph = ufo.default_layer().get_glyph("o").unwrap();
    assert_eq!(glyph.contours.len(), 2);
    let input = input_polys(&sans, "o");
    for q in ufo_polys(glyph) {
        for p in q {
            assert_ne!(winding(p, &input), 0, "{p:?} outside the fill");
            assert!((dist(p, &input) - 20.0).abs() <= bound + 0.05);
        }
    }
}

#[test]
fn stroke_and_html_report_and_no_grid() {
    let Some(sans) = dejavu() else { return };
    let out = dir("stroke.ufo");
    let rep = dir("stroke.html");
    let o = run_ok(&[
        "font",
        sans.to_str().unwrap(),
        "--glyphs",
        "l,@period",
        "--stroke",
        "10",
        "--tol",
        "1/2",
        "--grid",
        "none",
        "--jobs",
        "2",
        "--out",
        out.to_str().unwrap(),
        "--report",
        rep.to_str().unwrap(),
        "--json",
    ]);
    let doc: Value = serde_json::from_slice(&o.stdout).unwrap();
    assert_eq!(doc["summary"]["glyphs"], 2);
    assert_eq!(doc["summary"]["proven"], 2, "{doc}");
    let html = std::fs::read_to_string(&rep).unwrap();
    assert!(html.contains("<table") && html.contains("<svg"));
    let ufo = norad::Font::load(&out).unwrap();
    // a rectangle stroked: an outer and an inner contour
    assert_eq!(
        ufo.default_layer().get_glyph("l").unwrap().contours.len(),
        2
    );
}

fn bad_input(args: &[&str], field: &str) {
    let o = lncert(args);
    let err = String::from_utf8_lossy(&o.stderr);
    assert_eq!(o.status.code(), Some(2), "{args:?}: {err}");
    assert!(err.contains(field), "{args:?}: {err}");
    assert!(!err.contains("panicked"), "{err}");
}

#[test]
fn typed_errors() {
    let Some(sans) = dejavu() else { return };
    let f = sans.to_str().unwrap();
    let out = dir("err.ufo");
    let o = out.to_str().unwrap();
    let base = |extra: &[&str]| -> Vec<String> {
        let mut v: Vec<String> = ["font", f, "--out", o]
            .iter()
            .map(|s| s.to_string())
            .collect();
        v.extend(extra.iter().map(|s| s.to_string()));
        v
    };
    let check = |extra: &[&str], field: &str| {
        let v = base(extra);
        let r: Vec<&str> = v.iter().map(String::as_str).collect();
        bad_input(&r, field);
    };
    check(&["--tol", "1"], "--offset"); // neither
    check(
        &["--offset", "2", "--stroke", "2", "--tol", "1"],
        "--offset",
    ); // both
    check(&["--offset", "0", "--tol", "1"], "--offset");
    check(&["--stroke", "-2", "--tol", "1"], "--stroke");
    check(&["--offset", "2", "--tol", "0"], "--tol");
    check(&["--offset", "2", "--tol", "-1"], "--tol");
    check(
        &["--offset", "2", "--tol", "1", "--glyphs", "a,,b"],
        "--glyphs",
    );
    check(
        &["--offset", "2", "--tol", "1", "--glyphs", "Z-A"],
        "--glyphs",
    );
    check(
        &["--offset", "2", "--tol", "1", "--glyphs", "@nosuchglyph"],
        "--glyphs",
    );
    check(
        &["--offset", "2", "--tol", "1", "--glyphs", "uniE0FF0"],
        "--glyphs",
    );
    check(&["--offset", "2", "--tol", "1", "--grid", "1/3"], "--grid");
    check(&["--offset", "2", "--tol", "1", "--jobs", "0"], "--jobs");
    check(
        &["--offset", "2", "--tol", "1", "--report", "r.txt"],
        "--report",
    );
    // an unreadable font
    let junk = common::tmp("junk.ttf", "not a font");
    bad_input(
        &[
            "font",
            junk.to_str().unwrap(),
            "--offset",
            "2",
            "--tol",
            "1",
            "--out",
            o,
        ],
        "IN",
    );
    bad_input(
        &[
            "font",
            "/nonexistent/font.ttf",
            "--offset",
            "2",
            "--tol",
            "1",
            "--out",
            o,
        ],
        "IN",
    );
    // a directory that is not a UFO, and a UFO glyph with a component cycle
    let not_ufo = dir("not.ufo");
    std::fs::create_dir_all(&not_ufo).unwrap();
    bad_input(
        &[
            "font",
            not_ufo.to_str().unwrap(),
            "--offset",
            "2",
            "--tol",
            "1",
            "--out",
            o,
        ],
        "IN",
    );
    // an existing output directory is refused without --force
    std::fs::create_dir_all(&out).unwrap();
    check(
        &["--offset", "2", "--tol", "1", "--glyphs", "period"],
        "--out",
    );
    let v = base(&[
        "--offset", "20", "--tol", "1", "--glyphs", "period", "--force",
    ]);
    let r: Vec<&str> = v.iter().map(String::as_str).collect();
    run_ok(&r);
    assert!(out.join("glyphs").join("period.glif").exists());
}

/// A hand-written UFO (`tests/data/small.ufo`): a contour of off-curve points
/// only and a `qcurve` run (implied on-curve points), a composite of two
/// components (one scaled by 0.7, offset 400.3: exact decimals) over its own
/// contour, a space; every glyph proven, the width 600.5 kept.
#[test]
fn ufo_input_with_quadratic_runs_and_components() {
    let src = Path::new(env!("CARGO_MANIFEST_DIR"))
        .join("..")
        .join("tests/data/small.ufo");
    let out = dir("small-bold.ufo");
    let o = run_ok(&[
        "font",
        src.to_str().unwrap(),
        "--offset",
        "10",
        "--tol",
        "1",
        "--out",
        out.to_str().unwrap(),
        "--force",
        "--json",
    ]);
    let doc: Value = serde_json::from_slice(&o.stdout).unwrap();
    assert_eq!(doc["summary"]["glyphs"], 4, "{doc}");
    assert_eq!(doc["summary"]["proven"], 3, "{doc}");
    assert_eq!(doc["summary"]["empty"], 1, "{doc}");
    assert_eq!(o.status.code(), Some(0));
    let ufo = norad::Font::load(&out).unwrap();
    let layer = ufo.default_layer();
    let h = layer.get_glyph("H").unwrap();
    assert_eq!(h.width, 600.5);
    assert_eq!(h.codepoints.iter().collect::<Vec<_>>(), vec!['H']);
    // the bars and the crossbar overlap: one outline grown by 10
    assert_eq!(h.contours.len(), 1);
    // (on-curve points: a fitted cubic's handles may stand outside)
    let xs: Vec<f64> = h.contours[0]
        .points
        .iter()
        .filter(|p| p.typ != norad::PointType::OffCurve)
        .map(|p| p.x)
        .collect();
    let (lo, hi) = xs
        .iter()
        .fold((f64::MAX, f64::MIN), |(a, b), &x| (a.min(x), b.max(x)));
    // left bar from x = 70, right bar (scaled 0.7 about 0, moved 400.3) to 505.3
    assert!(
        (lo - 60.0).abs() <= 1.0 && (hi - 515.3).abs() <= 1.0,
        "{lo} {hi}"
    );
    // the o: outer and inner contour
    assert_eq!(layer.get_glyph("o").unwrap().contours.len(), 2);
    assert_eq!(ufo.font_info.units_per_em.map(|u| u.as_f64()), Some(1000.0));
    assert_eq!(layer.get_glyph("space").unwrap().width, 250.0);
}

/// A UFO written by `lncert font` from DejaVu Sans is read back as input and
/// stroked: the round trip of the whole pipeline. (`--grid none` in the
/// first pass: on the integer grid the rounded arc cubics meet at tiny kinks,
/// where today's stroke engine leaves some contours open — `l`, `period` at
/// `--stroke 5` — a limit of the engine, not of the reader.)
#[test]
fn ufo_written_from_dejavu_is_read_back() {
    let Some(sans) = dejavu() else { return };
    let first = dir("roundtrip-1.ufo");
    let second = dir("roundtrip-2.ufo");
    let o = run_ok(&[
        "font",
        sans.to_str().unwrap(),
        "--glyphs",
        "l,o,O,period",
        "--offset",
        "20",
        "--tol",
        "1",
        "--grid",
        "none",
        "--out",
        first.to_str().unwrap(),
        "--force",
        "--json",
    ]);
    assert_eq!(o.status.code(), Some(0));
    let o = run_ok(&[
        "font",
        first.to_str().unwrap(),
        "--glyphs",
        "l,o,O,@period",
        "--stroke",
        "5",
        "--tol",
        "1",
        "--out",
        second.to_str().unwrap(),
        "--force",
        "--json",
    ]);
    let doc: Value = serde_json::from_slice(&o.stdout).unwrap();
    assert_eq!(doc["summary"]["glyphs"], 4, "{doc}");
    assert_eq!(doc["summary"]["proven"], 4, "{doc}");
    let ufo = norad::Font::load(&second).unwrap();
    // an O stroked: each of its two contours gives two
    assert_eq!(
        ufo.default_layer().get_glyph("O").unwrap().contours.len(),
        4
    );
}

/// `--output quadratic` (TrueType): the stroke's sides fitted by quadratics,
/// its round joins by certified quadratics ([`lncert::certify::circular_arc_quadratics`]),
/// on the integer grid; every glyph proven, only `qcurve` and `line` points
/// written, and every written point at distance 40 ± bound from the input.
#[test]
fn quadratic_output_on_the_grid() {
    let Some(sans) = dejavu() else { return };
    let out = dir("quadratic.ufo");
    let rep = dir("quadratic.json");
    let o = run_ok(&[
        "font",
        sans.to_str().unwrap(),
        "--glyphs",
        "l,o,A,period",
        "--offset",
        "40",
        "--tol",
        "1",
        "--output",
        "quadratic",
        "--jobs",
        "2",
        "--out",
        out.to_str().unwrap(),
        "--report",
        rep.to_str().unwrap(),
    ]);
    assert_eq!(o.status.code(), Some(0));
    let r = report(&rep);
    assert_eq!(r["output"], "quadratic");
    assert_eq!(r["summary"]["proven"], 4, "{r}");
    let ufo = norad::Font::load(&out).unwrap();
    for g in &r["glyphs"].as_array().unwrap()[..] {
        let name = g["name"].as_str().unwrap();
        let bound = g["bound"].as_f64().unwrap();
        assert!(bound <= 1.0);
        let glyph = ufo.default_layer().get_glyph(name).unwrap();
        for c in &glyph.contours {
            for p in &c.points {
                assert!(
                    matches!(
                        p.typ,
                        norad::PointType::Line
                            | norad::PointType::QCurve
                            | norad::PointType::OffCurve
                    ),
                    "{name}: {p:?}"
                );
                assert!(p.x.fract() == 0.0 && p.y.fract() == 0.0, "{name}: {p:?}");
            }
        }
        let input = input_polys(&sans, name);
        for q in ufo_polys(glyph) {
            for p in q {
                let d = dist(p, &input);
                assert!((d - 40.0).abs() <= bound + 0.05, "{name}: {p:?} at {d}");
            }
        }
    }
    // the invalid value is a typed error
    bad_input(
        &[
            "font",
            sans.to_str().unwrap(),
            "--offset",
            "40",
            "--tol",
            "1",
            "--output",
            "cubicle",
            "--out",
            dir("q-err.ufo").to_str().unwrap(),
        ],
        "--output",
    );
}

/// TOL below the default grid's rounding move (`√2/2` font units), where
/// rounding cannot be proven: the stroke's outline is refitted on the grid
/// (`chain_on_grid`). `l` (straight stems) and `K`, `x` (sharp concave
/// corners where offset arms cross at irrational points; quadratic `K` needs
/// the later modes: turns below 154°, a second stroke share) are proven
/// within TOL with every point on integer units, cubic and quadratic; and on
/// the half grid.
#[test]
fn a_tolerance_below_the_rounding_move_is_proven_by_the_grid_fit() {
    let Some(sans) = dejavu() else { return };
    let run = |name: &str, glyphs: &str, extra: &[&str]| {
        let (out, rep) = (dir(&format!("{name}.ufo")), dir(&format!("{name}.json")));
        let mut args = vec![
            "font",
            sans.to_str().unwrap(),
            "--glyphs",
            glyphs,
            "--offset",
            "40",
            "--tol",
            "1/2",
            "--jobs",
            "2",
            "--out",
            out.to_str().unwrap(),
            "--report",
            rep.to_str().unwrap(),
        ];
        args.extend_from_slice(extra);
        (run_ok(&args), report(&rep), out)
    };
    for (name, glyphs, grid, output) in [
        ("fit-cubic", "l,K,x", "1", "cubic"),
        ("fit-quadratic", "l,K,x", "1", "quadratic"),
        ("fit-half", "l", "1/2", "cubic"),
    ] {
        let (o, r, out) = run(name, glyphs, &["--grid", grid, "--output", output]);
        assert_eq!(o.status.code(), Some(0), "{name}: {r}");
        let n = glyphs.split(',').count();
        assert_eq!(r["summary"]["proven"], n, "{name}: {r}");
        let scale = if grid == "1" { 1.0 } else { 2.0 };
        let ufo = norad::Font::load(&out).unwrap();
        for g in r["glyphs"].as_array().unwrap() {
            let bound = g["bound"].as_f64().unwrap();
            assert!(bound <= 0.5, "{name}: {g}");
            let glyph = ufo
                .default_layer()
                .get_glyph(g["name"].as_str().unwrap())
                .unwrap();
            assert!(!glyph.contours.is_empty());
            for c in &glyph.contours {
                for p in &c.points {
                    assert!(
                        (scale * p.x).fract() == 0.0 && (scale * p.y).fract() == 0.0,
                        "{name}: {p:?}"
                    );
                    if output == "quadratic" {
                        assert_ne!(p.typ, norad::PointType::Curve, "{name}");
                    }
                }
            }
        }
    }
}
