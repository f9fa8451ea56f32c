//! Glyph outlines of TrueType and OpenType fonts (feature `font`, read with
//! ttf-parser), converted exactly: every coordinate is in font units, an `f32`
//! that is an exact rational. TrueType glyphs give quadratic pieces, CFF glyphs
//! cubic ones, both as they are stored (nothing is approximated).
//!
//! Each contour is closed (a line back to its start when the last point is
//! not already there); zero-length pieces (a point repeated in the font) are
//! dropped, since they are not curves.
//!
//! **Degenerate pieces are read as what they are** ([`regularize`]): a
//! quadratic whose control point coincides with an end point, or a cubic whose
//! two control points lie on its end points, is the straight segment between
//! its end points (degree 1) — its derivative vanishes at an end, which the
//! offset and stroke engines refuse as a singular curve; a quadratic whose
//! control point lies on the line of its end points but outside their segment
//! runs out to the turning point `e` and back, and is read as the two segments
//! `p0 → e → p1` (`e` exact). The point set is the same in every case.
//!
//! Glyphs are found by character ([`glyph_outline`]), by id
//! ([`glyph_outline_by_id`]) or by name ([`glyph_id_by_name`]); [`font_info`]
//! lists every glyph with its name, code points (the Unicode cmap subtables)
//! and advance width, and the font's metrics and names.

use super::io::CurveParseError;
use crate::curve::{Bezier, V2};
use crate::scalar::{rational_from_f64, Rational};

fn bad(field: &str, reason: impl Into<String>) -> CurveParseError {
    CurveParseError::Field {
        field: field.to_string(),
        reason: reason.into(),
    }
}

struct Outline {
    pieces: Vec<Bezier<Rational>>,
    start: Option<[f32; 2]>,
    last: Option<[f32; 2]>,
    error: Option<CurveParseError>,
}

impl Outline {
    fn push(&mut self, pts: &[[f32; 2]]) {
        let Some(from) = self.last else {
            self.error
                .get_or_insert_with(|| bad("glyph", "a segment before the contour's start"));
            return;
        };
        let all: Vec<[f32; 2]> = std::iter::once(from).chain(pts.iter().copied()).collect();
        self.last = pts.last().copied();
        if all.iter().all(|p| *p == from) {
            return; // zero length: not a curve
        }
        let exact = all
            .iter()
            .map(|p| {
                Some(V2::new(
                    rational_from_f64(f64::from(p[0]))?,
                    rational_from_f64(f64::from(p[1]))?,
                ))
            })
            .collect::<Option<Vec<_>>>();
        match exact {
            Some(e) => self.pieces.extend(regularize(Bezier::new(e))),
            None => {
                self.error
                    .get_or_insert_with(|| bad("glyph", "a coordinate is not a finite number"));
            }
        }
    }
}

impl ttf_parser::OutlineBuilder for Outline {
    fn move_to(&mut self, x: f32, y: f32) {
        self.start = Some([x, y]);
        self.last = Some([x, y]);
    }
    fn line_to(&mut self, x: f32, y: f32) {
        self.push(&[[x, y]]);
    }
    fn quad_to(&mut self, x1: f32, y1: f32, x: f32, y: f32) {
        self.push(&[[x1, y1], [x, y]]);
    }
    fn curve_to(&mut self, x1: f32, y1: f32, x2: f32, y2: f32, x: f32, y: f32) {
        self.push(&[[x1, y1], [x2, y2], [x, y]]);
    }
    fn close(&mut self) {
        if let (Some(s), Some(l)) = (self.start, self.last) {
            if s != l {
                self.push(&[s]);
            }
        }
        self.start = None;
    }
}

/// A piece read as what it is: a quadratic with its control point on an end
/// point, or a cubic with both control points on its end points, is the
/// segment between the end points; a quadratic whose control point lies on the
/// line of its end points beyond them is the two segments out to its turning
/// point and back. Anything else is returned unchanged. Exact.
///
/// # Examples
/// ```
/// use lncert::curve::{Bezier, V2};
/// use lncert::shape::regularize;
/// let p = |x: i64, y: i64| V2::new(lncert::Rational::from_integer(x.into()), lncert::Rational::from_integer(y.into()));
/// // control point on the start point: a segment
/// assert_eq!(regularize(Bezier::new(vec![p(0, 0), p(0, 0), p(4, 2)])), vec![Bezier::new(vec![p(0, 0), p(4, 2)])]);
/// // control point beyond the end, on the line: out to x = 4.5 and back to 4
/// let r = regularize(Bezier::new(vec![p(0, 0), p(6, 0), p(4, 0)]));
/// assert_eq!(r.len(), 2);
/// assert_eq!(r[0].points()[1].x, lncert::Rational::new(9.into(), 2.into()));
/// ```
pub fn regularize(b: Bezier<Rational>) -> Vec<Bezier<Rational>> {
    let pts = b.points();
    let line = |p: &V2<Rational>, q: &V2<Rational>| Bezier::new(vec![p.clone(), q.clone()]);
    match pts.len() {
        3 => {
            let (p0, c, p1) = (&pts[0], &pts[1], &pts[2]);
            if c == p0 || c == p1 {
                return vec![line(p0, p1)];
            }
            let (a, d) = (c.sub(p0), p1.sub(c));
            let zero = Rational::from_integer(0.into());
            if a.cross(&d) == zero && a.dot(&d) < zero {
                // B'(t) = 2((1 − t) a + t d) vanishes at t = a·a / (a·a − a·d)
                let aa = a.dot(&a);
                let t = &aa / (&aa - a.dot(&d));
                let e = b.eval(&t);
                return vec![line(p0, &e), line(&e, p1)];
            }
            vec![b]
        }
        // both control points on the end points (in any order): the curve runs
        // monotonically along the chord, B(t) = p0 + s(t)(p3 − p0), s' ≥ 0
        4 if pts[1..3].iter().all(|c| *c == pts[0] || *c == pts[3]) => {
            vec![line(&pts[0], &pts[3])]
        }
        _ => vec![b],
    }
}

/// The font's units per em (face 0): divide a [`glyph_outline`] by it for
/// coordinates in em (exact: a rational scale).
///
/// Errors: the font cannot be read (`font`).
pub fn units_per_em(data: &[u8]) -> Result<u16, CurveParseError> {
    Ok(face(data)?.units_per_em())
}

/// The outline of the glyph of `ch` in the font `data` (face 0), in font
/// units, as exact Bézier pieces, contour after contour: the cmap's glyph
/// read by [`glyph_outline_by_id`].
///
/// Errors: the font cannot be read (`font`), it has no glyph for `ch` or the
/// glyph has no outline (`glyph`).
pub fn glyph_outline(data: &[u8], ch: char) -> Result<Vec<Bezier<Rational>>, CurveParseError> {
    let id = glyph_id_by_char(data, ch)?
        .ok_or_else(|| bad("glyph", format!("the font has no glyph for {ch:?}")))?;
    let pieces = glyph_outline_by_id(data, id)?;
    if pieces.is_empty() {
        return Err(bad("glyph", format!("the glyph for {ch:?} has no outline")));
    }
    Ok(pieces)
}

fn face(data: &[u8]) -> Result<ttf_parser::Face<'_>, CurveParseError> {
    ttf_parser::Face::parse(data, 0)
        .map_err(|e| bad("font", format!("not a TrueType/OpenType font: {e}")))
}

/// One glyph of a font: id, name, code points, advance width.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct GlyphInfo {
    /// The glyph id.
    pub id: u16,
    /// The glyph's name (`post` or CFF charset), `gidN` when the font has none.
    pub name: String,
    /// The Unicode code points mapped to it by the cmap (sorted).
    pub codepoints: Vec<u32>,
    /// The horizontal advance in font units (0 when the font has none).
    pub advance: u16,
}

/// A font's names, metrics and glyph list (face 0).
#[derive(Clone, Debug)]
pub struct FontInfo {
    /// Units per em.
    pub units_per_em: u16,
    /// Family name (name id 16, else 1), when the font has one.
    pub family: Option<String>,
    /// Style name (name id 17, else 2), when the font has one.
    pub style: Option<String>,
    /// Ascender (hhea / OS/2), font units.
    pub ascender: i16,
    /// Descender (negative below the baseline), font units.
    pub descender: i16,
    /// OS/2 x height, when the font has it.
    pub x_height: Option<i16>,
    /// OS/2 cap height, when the font has it.
    pub cap_height: Option<i16>,
    /// The outlines are CFF (cubic, outer contours counter-clockwise); else
    /// TrueType `glyf` (quadratic, outer contours clockwise).
    pub cff: bool,
    /// Every glyph, by id.
    pub glyphs: Vec<GlyphInfo>,
}

fn name_of(face: &ttf_parser::Face<'_>, ids: &[u16]) -> Option<String> {
    for &id in ids {
        let found = face
            .names()
            .into_iter()
            .filter(|n| n.name_id == id && n.is_unicode())
            .find_map(|n| n.to_string());
        if found.is_some() {
            return found;
        }
    }
    None
}

/// The glyph names of a version 2.0 `post` table, read once: ttf-parser's
/// `glyph_name` walks the name list from its start for every glyph, which
/// is quadratic in the glyph count (0.2 s for the 6,000 glyphs of DejaVu
/// Sans); this reads the list once.
struct PostNames<'a> {
    /// The name index of each glyph (below 258: a standard Macintosh name).
    indexes: Vec<u16>,
    /// The font's own names, in order (index 258 onwards).
    names: Vec<&'a str>,
}

impl<'a> PostNames<'a> {
    fn read(face: &ttf_parser::Face<'a>) -> Option<Self> {
        let data = face
            .raw_face()
            .table(ttf_parser::Tag::from_bytes(b"post"))?;
        let be16 = |at: usize| {
            data.get(at..at + 2)
                .map(|b| u16::from_be_bytes([b[0], b[1]]))
        };
        if data.get(0..4)? != [0, 2, 0, 0] {
            return None;
        }
        let count = usize::from(be16(32)?);
        let indexes = (0..count)
            .map(|k| be16(34 + 2 * k))
            .collect::<Option<Vec<u16>>>()?;
        let mut names = Vec::new();
        let mut at = 34 + 2 * count;
        while let Some(&len) = data.get(at) {
            let len = usize::from(len);
            if len == 0 {
                break;
            }
            let Some(Ok(name)) = data.get(at + 1..at + 1 + len).map(std::str::from_utf8) else {
                break;
            };
            names.push(name);
            at += 1 + len;
        }
        Some(PostNames { indexes, names })
    }

    /// The name of glyph `g`: a standard name through ttf-parser (a table
    /// look-up there), the font's own from the list read once.
    fn name<'f>(&self, face: &'f ttf_parser::Face<'a>, g: ttf_parser::GlyphId) -> Option<&'f str> {
        let index = usize::from(*self.indexes.get(usize::from(g.0))?);
        if index < 258 {
            face.glyph_name(g)
        } else {
            self.names.get(index - 258).copied()
        }
    }
}

/// The font's names, metrics and every glyph with its name, code points and
/// advance width (face 0).
///
/// Errors: the font cannot be read (`font`).
pub fn font_info(data: &[u8]) -> Result<FontInfo, CurveParseError> {
    use ttf_parser::name_id;
    let face = face(data)?;
    let n = face.number_of_glyphs();
    let mut cps: Vec<Vec<u32>> = vec![Vec::new(); usize::from(n)];
    if let Some(cmap) = face.tables().cmap {
        for sub in cmap.subtables {
            if !sub.is_unicode() {
                continue;
            }
            sub.codepoints(|cp| {
                if let Some(g) = sub.glyph_index(cp) {
                    if let Some(v) = cps.get_mut(usize::from(g.0)) {
                        v.push(cp);
                    }
                }
            });
        }
    }
    let post_names = PostNames::read(&face);
    let glyphs = (0..n)
        .map(|id| {
            let g = ttf_parser::GlyphId(id);
            let mut codepoints = std::mem::take(&mut cps[usize::from(id)]);
            codepoints.sort_unstable();
            codepoints.dedup();
            GlyphInfo {
                id,
                name: post_names
                    .as_ref()
                    .and_then(|p| p.name(&face, g))
                    .or_else(|| face.glyph_name(g))
                    .map(str::to_string)
                    .unwrap_or_else(|| format!("gid{id}")),
                codepoints,
                advance: face.glyph_hor_advance(g).unwrap_or(0),
            }
        })
        .collect();
    let t = face.tables();
    Ok(FontInfo {
        units_per_em: face.units_per_em(),
        family: name_of(&face, &[name_id::TYPOGRAPHIC_FAMILY, name_id::FAMILY]),
        style: name_of(&face, &[name_id::TYPOGRAPHIC_SUBFAMILY, name_id::SUBFAMILY]),
        ascender: face.ascender(),
        descender: face.descender(),
        x_height: face.x_height(),
        cap_height: face.capital_height(),
        cff: t.glyf.is_none() && (t.cff.is_some() || t.cff2.is_some()),
        glyphs,
    })
}

/// The id of the glyph named `name` (face 0), if any.
///
/// Errors: the font cannot be read (`font`).
pub fn glyph_id_by_name(data: &[u8], name: &str) -> Result<Option<u16>, CurveParseError> {
    Ok(face(data)?.glyph_index_by_name(name).map(|g| g.0))
}

/// The id of the glyph of the code point `cp` (face 0), if any.
///
/// Errors: the font cannot be read (`font`).
pub fn glyph_id_by_char(data: &[u8], ch: char) -> Result<Option<u16>, CurveParseError> {
    Ok(face(data)?.glyph_index(ch).map(|g| g.0))
}

/// The outline of glyph `id` (face 0), in font units, exact, contour after
/// contour; composites are decomposed. Empty for a glyph without outline
/// (a space).
///
/// Errors: the font cannot be read (`font`), `id` is out of range or the
/// outline holds a non-finite coordinate (`glyph`).
pub fn glyph_outline_by_id(data: &[u8], id: u16) -> Result<Vec<Bezier<Rational>>, CurveParseError> {
    let face = face(data)?;
    if id >= face.number_of_glyphs() {
        return Err(bad(
            "glyph",
            format!(
                "glyph id {id} out of range (the font has {})",
                face.number_of_glyphs()
            ),
        ));
    }
    let mut out = Outline {
        pieces: Vec::new(),
        start: None,
        last: None,
        error: None,
    };
    if face
        .outline_glyph(ttf_parser::GlyphId(id), &mut out)
        .is_none()
    {
        return Ok(Vec::new());
    }
    if let Some(e) = out.error {
        return Err(e);
    }
    Ok(out.pieces)
}

#[cfg(test)]
mod post_name_tests {
    use super::*;

    /// The names read once from the `post` table are ttf-parser's own,
    /// glyph by glyph (its `glyph_name` is the oracle), on installed fonts.
    #[test]
    fn glyph_names_read_once_match_ttf_parser() {
        let dir = "/usr/share/fonts/truetype/dejavu";
        let mut checked = 0;
        for file in ["DejaVuSans.ttf", "DejaVuSerif.ttf", "DejaVuSansMono.ttf"] {
            let Ok(data) = std::fs::read(format!("{dir}/{file}")) else {
                continue;
            };
            let info = font_info(&data).unwrap();
            let face = face(&data).unwrap();
            assert!(
                PostNames::read(&face).is_some(),
                "{file}: a version 2.0 post table"
            );
            assert_eq!(info.glyphs.len(), usize::from(face.number_of_glyphs()));
            for g in &info.glyphs {
                let want = face
                    .glyph_name(ttf_parser::GlyphId(g.id))
                    .map(str::to_string)
                    .unwrap_or_else(|| format!("gid{}", g.id));
                assert_eq!(g.name, want, "{file}: glyph {}", g.id);
            }
            checked += 1;
        }
        assert!(
            checked > 0 || std::env::var("LNCERT_REQUIRE_FONT").is_err(),
            "LNCERT_REQUIRE_FONT is set but no DejaVu font is in {dir}"
        );
    }
}
