//! Glyph outlines of TrueType and OpenType fonts (feature `font`, read with
//! ttf-parser), converted exactly: every coordinate is in font units, an `f32`
//! that is an exact rational. TrueType glyphs give quadratic pieces, CFF glyphs
//! cubic ones, both as they are stored (nothing is approximated).
//!
//! Each contour is closed (a line back to its start when the last point is
//! not already there); zero-length pieces (a point repeated in the font) are
//! dropped, since they are not curves.

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
            Some(e) => self.pieces.push(Bezier::new(e)),
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

/// The font's units per em (face 0): divide a [`glyph_outline`] by it for
/// coordinates in em (exact: a rational scale).
///
/// Errors: the font cannot be read (`font`).
pub fn units_per_em(data: &[u8]) -> Result<u16, CurveParseError> {
    let face = ttf_parser::Face::parse(data, 0)
        .map_err(|e| bad("font", format!("not a TrueType/OpenType font: {e}")))?;
    Ok(face.units_per_em())
}

/// The outline of the glyph of `ch` in the font `data` (face 0), in font
/// units, as exact Bézier pieces, contour after contour.
///
/// Errors: the font cannot be read (`font`), it has no glyph for `ch` or the
/// glyph has no outline (`glyph`).
pub fn glyph_outline(data: &[u8], ch: char) -> Result<Vec<Bezier<Rational>>, CurveParseError> {
    let face = ttf_parser::Face::parse(data, 0)
        .map_err(|e| bad("font", format!("not a TrueType/OpenType font: {e}")))?;
    let id = face
        .glyph_index(ch)
        .ok_or_else(|| bad("glyph", format!("the font has no glyph for {ch:?}")))?;
    let mut out = Outline {
        pieces: Vec::new(),
        start: None,
        last: None,
        error: None,
    };
    face.outline_glyph(id, &mut out)
        .ok_or_else(|| bad("glyph", format!("the glyph for {ch:?} has no outline")))?;
    if let Some(e) = out.error {
        return Err(e);
    }
    if out.pieces.is_empty() {
        return Err(CurveParseError::Empty {
            what: format!("the glyph for {ch:?}"),
        });
    }
    Ok(out.pieces)
}
