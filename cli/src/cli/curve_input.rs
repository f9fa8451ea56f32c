//! The `CURVE` argument of `lncert offset` and `lncert stroke` (and
//! `offset --trim`), read one way for both: a curve file (`{"bezier": ...}`,
//! `{"beziers": ...}`, `{"bspline": ...}`, SVG path data or an SVG document,
//! with the report of what was approximated), an arc (`{"arc": {...}}`), a
//! circle (`{"circle": {"center": [x, y], "radius": r}}`), or with `--glyph
//! ITEM` a TrueType/OpenType font and the contours of one glyph (`--em`: in
//! em). `ITEM` names exactly one glyph: a character (`A`), a code point
//! (`uni0041`, `u1F600`) or a glyph name (`@A`, or `Aacute`, `at`), read as
//! `lncert font --glyphs` reads one item ([`super::glyph_item`]).

use super::args::{bad, offset_err};
use super::glyph_item::Resolver;
use super::CliError;
use lncert::curve::{Bezier, V2};
use lncert::scalar::Rational;
use lncert::shape::{parse_arc_input, parse_curve_reported, InputApprox, TravelledArc};
use std::path::Path;

/// Largest curve or shape file read (`CURVE`, and the shapes of `hausdorff`
/// and `verify --against`).
pub const MAX_FILE_BYTES: u64 = 16 << 20;

/// Largest font file read by `--glyph`.
pub const MAX_FONT_BYTES: u64 = 64 << 20;

/// What `CURVE` holds.
#[derive(Clone, Debug)]
pub enum CurveInput {
    /// Polynomial pieces, and what of the input was approximated to get them
    /// (empty when the pieces are exactly the input).
    Curve {
        /// The pieces, exact.
        pieces: Vec<Bezier<Rational>>,
        /// The report of approximated SVG arcs, circles, ellipses, rounded rects.
        approx: InputApprox,
        /// The coordinates are SVG's (path data or a document): y points down
        /// on the screen, and pictures are drawn without flipping y. JSON
        /// curves and font glyphs are y-up.
        y_down: bool,
    },
    /// One circular arc (`{"arc": ...}`), exact.
    Arc(Box<TravelledArc>),
    /// A full circle (`{"circle": ...}`), exact, travelled counter-clockwise.
    Circle {
        /// The centre.
        center: V2<Rational>,
        /// The radius (`> 0`).
        radius: Rational,
        /// The circle as its four counter-clockwise quarter arcs.
        arcs: Vec<TravelledArc>,
    },
}

/// The bytes of `path`, at most `limit` of them (checked before reading and
/// again while reading, should the file grow); errors name `flag`. Every
/// input file of the CLI is read here.
pub fn read_limited(flag: &str, path: &Path, limit: u64) -> Result<Vec<u8>, CliError> {
    use std::io::Read;
    let io = |e: std::io::Error| bad(flag, format!("{}: {e}", path.display()));
    let too_big = || {
        bad(
            flag,
            format!("{}: larger than the limit of {limit} bytes", path.display()),
        )
    };
    let file = std::fs::File::open(path).map_err(io)?;
    if file.metadata().map_err(io)?.len() > limit {
        return Err(too_big());
    }
    let mut bytes = Vec::new();
    file.take(limit + 1).read_to_end(&mut bytes).map_err(io)?;
    if bytes.len() as u64 > limit {
        return Err(too_big());
    }
    Ok(bytes)
}

/// [`read_limited`] as UTF-8 text.
pub fn read_text_limited(flag: &str, path: &Path, limit: u64) -> Result<String, CliError> {
    String::from_utf8(read_limited(flag, path, limit)?)
        .map_err(|e| bad(flag, format!("{}: not UTF-8 text ({e})", path.display())))
}

/// Reads `path` (the argument CURVE) as a text file of at most
/// [`MAX_FILE_BYTES`] bytes.
pub fn read_text(path: &Path) -> Result<String, CliError> {
    read_text_limited("CURVE", path, MAX_FILE_BYTES)
}

/// The contours of the glyph `item` names in the font file `path` (one
/// character, `uniXXXX` / `uXXXX`, `@name` or a glyph name:
/// [`super::glyph_item`]), exactly as stored (font units, or em with `em`).
///
/// Errors (`--glyph`): not a font, no such glyph, an item that is not one
/// glyph (empty, a range, a comma list), a glyph without outline (a space).
pub fn read_glyph(path: &Path, item: &str, em: bool) -> Result<Vec<Bezier<Rational>>, CliError> {
    let data = read_limited("CURVE", path, MAX_FONT_BYTES)?;
    let font_err = |e: lncert::shape::CurveParseError| bad("--glyph", e);
    let info = lncert::shape::font_info(&data).map_err(font_err)?;
    let resolver = Resolver {
        flag: "--glyph",
        info: &info,
        by_char: |ch| lncert::shape::glyph_id_by_char(&data, ch).map_err(font_err),
    };
    let id = resolver.one(item)?;
    let mut outline = lncert::shape::glyph_outline_by_id(&data, id).map_err(font_err)?;
    if outline.is_empty() {
        let name = &info.glyphs[usize::from(id)].name;
        return Err(bad(
            "--glyph",
            format!("{item:?}: the glyph {name:?} has no outline"),
        ));
    }
    if em {
        let upem = info.units_per_em;
        if upem == 0 {
            return Err(bad("--em", "the font says 0 units per em"));
        }
        let k = Rational::new(1.into(), i64::from(upem).into());
        outline = outline.iter().map(|b| b.map(|v| v * &k)).collect();
    }
    Ok(outline)
}

/// Reads `CURVE` (with `--glyph ITEM`: a font), as `offset` and `stroke` do.
pub fn read_curve_input(
    path: &Path,
    glyph: Option<&str>,
    em: bool,
) -> Result<CurveInput, CliError> {
    if let Some(item) = glyph {
        return Ok(CurveInput::Curve {
            pieces: read_glyph(path, item, em)?,
            approx: InputApprox::default(),
            y_down: false,
        });
    }
    if em {
        return Err(bad("--em", "needs --glyph"));
    }
    let text = read_text(path)?;
    if let Some(arcs) = parse_arc_input(&text) {
        let mut arcs = arcs.map_err(offset_err)?;
        // an `{"arc"}` document is one arc, a `{"circle"}` four quarter arcs
        return Ok(if arcs.len() == 1 {
            CurveInput::Arc(Box::new(arcs.remove(0)))
        } else {
            CurveInput::Circle {
                center: arcs[0].arc.center.clone(),
                radius: arcs[0].arc.radius.clone(),
                arcs,
            }
        });
    }
    let (pieces, approx) = parse_curve_reported(&text).map_err(|e| bad("CURVE", e))?;
    let y_down = y_down(&text);
    Ok(CurveInput::Curve {
        pieces,
        approx,
        y_down,
    })
}

/// `{label}: 3 SVG arc(s) approximated by … ; the results are about the
/// approximated curve`, or `None` when the curve is exactly the input.
pub fn input_line(label: &str, approx: &InputApprox) -> Option<String> {
    approx
        .summary()
        .map(|s| format!("{label}: {s}; the results are about the approximated curve\n"))
}

/// Whether a curve file's coordinates are SVG's (y down): SVG path data or a
/// document, not a JSON curve.
pub fn y_down(text: &str) -> bool {
    !text.trim_start().starts_with('{')
}

#[cfg(test)]
mod read_tests {
    use super::*;

    #[test]
    fn files_over_the_limit_are_refused_naming_the_flag() {
        let dir = std::env::temp_dir().join(format!("lncert-read-{}", std::process::id()));
        std::fs::create_dir_all(&dir).unwrap();
        let p = dir.join("five.txt");
        std::fs::write(&p, "12345").unwrap();
        assert_eq!(read_limited("CURVE", &p, 5).unwrap(), b"12345");
        let e = read_limited("IN", &p, 4).unwrap_err();
        assert_eq!(e.field, "IN");
        assert!(
            e.reason.contains("larger than the limit of 4 bytes"),
            "{}",
            e.reason
        );
        std::fs::write(&p, [0xffu8, 0xfe]).unwrap();
        let e = read_text_limited("A", &p, 5).unwrap_err();
        assert!(e.reason.contains("not UTF-8"), "{}", e.reason);
        let e = read_limited("B", &dir.join("missing"), 5).unwrap_err();
        assert_eq!(e.field, "B");
        std::fs::remove_dir_all(&dir).ok();
    }
}
