//! UFO input of `lncert font` (read with norad): every glyph of the default
//! layer, in the order of `public.glyphOrder` (then the others by name),
//! with its code points and advance width, the font's units per em, names
//! and metrics; outlines exact.
//!
//! * **Numbers.** norad gives every coordinate and component transform entry
//!   as an `f64` parsed from the `.glif` text; it is read back as the
//!   shortest decimal that gives the same `f64` (Rust's `Display`), exactly:
//!   `12`, `0.5`, `0.7` (as `7/10`, not the nearest float) — the number as
//!   written, for every text of at most 15 significant digits.
//! * **Contours** (UFO 3 `.glif`): `line` (a segment), `curve` (its two
//!   off-curve points: a cubic; one: a quadratic; none: a segment), `qcurve`
//!   (TrueType style: a run of `n` off-curve points is `n` quadratics with
//!   the implied on-curve points at the midpoints of consecutive off-curve
//!   points), a closed contour of off-curve points only (the same run
//!   around the whole contour). A contour starting with `move` is open: a
//!   glyph with one is refused (the filled region needs closed contours). A
//!   `curve` with more than two off-curve points is refused. Pieces are read
//!   as what they are ([`lncert::shape::regularize`]), as for TrueType input.
//! * **Components** are decomposed: the base glyph's outline under the exact
//!   affine map `(x, y) ↦ (xx·x + yx·y + dx, xy·x + yy·y + dy)`, nested up to
//!   [`MAX_COMPONENT_DEPTH`]; a missing base or a cycle is the glyph's error.

use lncert::curve::{Bezier, V2};
use lncert::scalar::{parse_rational, Rational};
use lncert::shape::{FontInfo, GlyphInfo};
use norad::PointType;
use std::collections::HashMap;
use std::path::Path;

/// Deepest nesting of components.
pub const MAX_COMPONENT_DEPTH: usize = 16;

/// A UFO read for `lncert font`.
pub struct UfoSource {
    /// Names, metrics and the glyph list (ids are positions in it).
    pub info: FontInfo,
    /// Advance widths by id, as in the UFO.
    pub widths: Vec<f64>,
    /// Every glyph's decomposed outline, or why it cannot be read.
    pub outlines: Vec<Result<Vec<Bezier<Rational>>, String>>,
    /// Code point → glyph id (the first glyph that lists it).
    pub by_codepoint: HashMap<u32, u16>,
}

/// `x` as the shortest decimal that round-trips, exactly.
fn exact(x: f64, what: &str) -> Result<Rational, String> {
    if !x.is_finite() {
        return Err(format!("{what}: not a finite number"));
    }
    parse_rational(&format!("{x}")).map_err(|e| format!("{what}: {e}"))
}

fn point(p: &norad::ContourPoint) -> Result<V2<Rational>, String> {
    Ok(V2::new(exact(p.x, "x")?, exact(p.y, "y")?))
}

fn mid(a: &V2<Rational>, b: &V2<Rational>) -> V2<Rational> {
    let two = Rational::from_integer(2.into());
    V2::new((&a.x + &b.x) / &two, (&a.y + &b.y) / &two)
}

/// The pieces of one closed contour (see the module docs).
fn contour(c: &norad::Contour) -> Result<Vec<Bezier<Rational>>, String> {
    let pts = &c.points;
    if pts.is_empty() {
        return Ok(Vec::new());
    }
    if pts[0].typ == PointType::Move {
        return Err("an open contour (it starts with a move point)".into());
    }
    let mut out = Vec::new();
    let push = |pieces: Vec<V2<Rational>>, out: &mut Vec<Bezier<Rational>>| {
        if pieces.iter().all(|p| *p == pieces[0]) {
            return; // zero length: not a curve
        }
        out.extend(lncert::shape::regularize(Bezier::new(pieces)));
    };
    let Some(first_on) = pts.iter().position(|p| p.typ != PointType::OffCurve) else {
        // only off-curve points: a closed TrueType run, every on-curve point implied
        let offs: Vec<V2<Rational>> = pts.iter().map(point).collect::<Result<_, _>>()?;
        let n = offs.len();
        for i in 0..n {
            let (a, b, c) = (&offs[i], &offs[(i + 1) % n], &offs[(i + 2) % n]);
            push(vec![mid(a, b), b.clone(), mid(b, c)], &mut out);
        }
        return Ok(out);
    };
    let n = pts.len();
    let mut cur = point(&pts[first_on])?;
    let mut offs: Vec<V2<Rational>> = Vec::new();
    for k in 1..=n {
        let p = &pts[(first_on + k) % n];
        if p.typ == PointType::OffCurve {
            offs.push(point(p)?);
            continue;
        }
        let end = point(p)?;
        match (p.typ, offs.len()) {
            (PointType::Move, _) => return Err("a move point inside a closed contour".into()),
            (PointType::Line, 0) | (PointType::Curve, 0) | (PointType::QCurve, 0) => {
                push(vec![cur.clone(), end.clone()], &mut out)
            }
            (PointType::Line, k) => {
                return Err(format!("a line point after {k} off-curve point(s)"))
            }
            (PointType::Curve, 1) => {
                push(vec![cur.clone(), offs[0].clone(), end.clone()], &mut out)
            }
            (PointType::Curve, 2) => push(
                vec![cur.clone(), offs[0].clone(), offs[1].clone(), end.clone()],
                &mut out,
            ),
            (PointType::Curve, k) => {
                return Err(format!(
                    "a curve point after {k} off-curve points (at most 2 are read)"
                ))
            }
            (PointType::QCurve, k) => {
                // implied on-curve points between consecutive off-curve points
                let mut from = cur.clone();
                for i in 0..k {
                    let to = if i + 1 < k {
                        mid(&offs[i], &offs[i + 1])
                    } else {
                        end.clone()
                    };
                    push(vec![from, offs[i].clone(), to.clone()], &mut out);
                    from = to;
                }
            }
            (PointType::OffCurve, _) => unreachable!("handled above"),
        }
        offs.clear();
        cur = end;
    }
    Ok(out)
}

/// The affine map of a component, exactly.
fn transform(t: &norad::AffineTransform) -> Result<[Rational; 6], String> {
    Ok([
        exact(t.x_scale, "xScale")?,
        exact(t.xy_scale, "xyScale")?,
        exact(t.yx_scale, "yxScale")?,
        exact(t.y_scale, "yScale")?,
        exact(t.x_offset, "xOffset")?,
        exact(t.y_offset, "yOffset")?,
    ])
}

fn apply(m: &[Rational; 6], p: &V2<Rational>) -> V2<Rational> {
    let [xx, xy, yx, yy, dx, dy] = m;
    V2::new(xx * &p.x + yx * &p.y + dx, xy * &p.x + yy * &p.y + dy)
}

/// The outline of `name` with its components decomposed.
fn outline(
    layer: &norad::Layer,
    name: &str,
    stack: &mut Vec<String>,
) -> Result<Vec<Bezier<Rational>>, String> {
    let g = layer
        .get_glyph(name)
        .ok_or_else(|| format!("component base {name:?} is not in the UFO"))?;
    let mut out = Vec::new();
    for (k, c) in g.contours.iter().enumerate() {
        out.extend(contour(c).map_err(|e| format!("{name}: contour {k}: {e}"))?);
    }
    for (k, c) in g.components.iter().enumerate() {
        let base = c.base.as_str();
        if stack.iter().any(|s| s == base) || base == name {
            return Err(format!("{name}: component {k} ({base}) is a cycle"));
        }
        if stack.len() >= MAX_COMPONENT_DEPTH {
            return Err(format!(
                "{name}: components nested deeper than {MAX_COMPONENT_DEPTH}"
            ));
        }
        let m = transform(&c.transform).map_err(|e| format!("{name}: component {k}: {e}"))?;
        stack.push(name.to_string());
        let inner = outline(layer, base, stack);
        stack.pop();
        for b in inner? {
            out.push(Bezier::new(
                b.points().iter().map(|p| apply(&m, p)).collect(),
            ));
        }
    }
    Ok(out)
}

/// Reads the UFO at `path` (errors name `IN`).
pub fn read_ufo(path: &Path) -> Result<UfoSource, String> {
    let font = norad::Font::load(path).map_err(|e| format!("{}: {e}", path.display()))?;
    let layer = font.default_layer();
    let mut names: Vec<String> = Vec::new();
    if let Some(plist::Value::Array(order)) = font.lib.get("public.glyphOrder") {
        for v in order {
            if let Some(s) = v.as_string() {
                if layer.get_glyph(s).is_some() && !names.iter().any(|n| n == s) {
                    names.push(s.to_string());
                }
            }
        }
    }
    let mut rest: Vec<String> = layer
        .iter()
        .map(|g| g.name().as_str().to_string())
        .filter(|n| !names.contains(n))
        .collect();
    rest.sort();
    names.extend(rest);
    if names.len() > usize::from(u16::MAX) {
        return Err(format!("{} glyphs (at most 65535 are read)", names.len()));
    }
    let mut glyphs = Vec::new();
    let mut widths = Vec::new();
    let mut outlines = Vec::new();
    let mut by_codepoint = HashMap::new();
    for (id, name) in names.iter().enumerate() {
        let id = id as u16;
        let g = layer.get_glyph(name.as_str()).ok_or("a glyph vanished")?;
        let mut codepoints: Vec<u32> = g.codepoints.iter().map(u32::from).collect();
        for &cp in &codepoints {
            by_codepoint.entry(cp).or_insert(id);
        }
        codepoints.sort_unstable();
        glyphs.push(GlyphInfo {
            id,
            name: name.clone(),
            codepoints,
            advance: g.width.round().clamp(0.0, f64::from(u16::MAX)) as u16,
        });
        widths.push(g.width);
        outlines.push(outline(layer, name, &mut Vec::new()));
    }
    let fi = &font.font_info;
    let upm = fi.units_per_em.map_or(1000.0, |u| u.as_f64());
    if !(1.0..=16384.0).contains(&upm) {
        return Err(format!("unitsPerEm {upm} is out of range (1 to 16384)"));
    }
    let metric = |v: Option<f64>| v.map(|x| x.round().clamp(-32768.0, 32767.0) as i16);
    let info = FontInfo {
        units_per_em: upm.round() as u16,
        family: fi.family_name.clone(),
        style: fi.style_name.clone(),
        ascender: metric(fi.ascender).unwrap_or((0.8 * upm) as i16),
        descender: metric(fi.descender).unwrap_or((-0.2 * upm) as i16),
        x_height: metric(fi.x_height),
        cap_height: metric(fi.cap_height),
        cff: true,
        glyphs,
    };
    Ok(UfoSource {
        info,
        widths,
        outlines,
        by_codepoint,
    })
}

#[cfg(test)]
mod tests {
    use super::*;
    use norad::ContourPoint;

    fn pt(x: f64, y: f64, t: PointType) -> ContourPoint {
        ContourPoint::new(x, y, t, false, None, None)
    }
    fn q(s: &str) -> Rational {
        parse_rational(s).unwrap()
    }

    /// A TrueType run: off-curve points with implied midpoints, exactly.
    #[test]
    fn qcurve_runs_and_off_curve_only_contours() {
        use PointType::*;
        let c = norad::Contour::new(
            vec![
                pt(0.0, 0.0, Line),
                pt(10.0, 0.0, OffCurve),
                pt(10.0, 10.0, OffCurve),
                pt(0.0, 10.0, QCurve),
            ],
            None,
        );
        let p = contour(&c).unwrap();
        assert_eq!(p.len(), 3);
        assert_eq!(
            p[0].points()[2],
            V2::new(q("10"), q("5")),
            "the implied point"
        );
        assert_eq!(p[1].points()[0], V2::new(q("10"), q("5")));
        assert_eq!(p[2].degree(), 1, "the closing line");
        // a circle-like contour of four off-curve points: four quadratics
        let c = norad::Contour::new(
            vec![
                pt(1.0, 1.0, OffCurve),
                pt(-1.0, 1.0, OffCurve),
                pt(-1.0, -1.0, OffCurve),
                pt(1.0, -1.0, OffCurve),
            ],
            None,
        );
        let p = contour(&c).unwrap();
        assert_eq!(p.len(), 4);
        assert_eq!(p[0].points()[0], V2::new(q("0"), q("1")));
        assert_eq!(p[3].points()[2], p[0].points()[0], "closed");
        // decimals are read as written
        assert_eq!(exact(0.7, "x").unwrap(), q("7/10"));
        // an open contour is refused
        let c = norad::Contour::new(vec![pt(0.0, 0.0, Move), pt(1.0, 0.0, Line)], None);
        assert!(contour(&c).unwrap_err().contains("open contour"));
    }
}
