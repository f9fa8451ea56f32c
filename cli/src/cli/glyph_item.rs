//! One item of a glyph selection, resolved to a glyph id in one font: shared
//! by `--glyph ITEM` of `offset` and `stroke` ([`super::curve_input`]), which
//! takes exactly one item, and `--glyphs SPEC` of `font` ([`super::font`]),
//! a comma list of them.
//!
//! An item is
//! * a single character (`a`, `,`, `-`): its code point;
//! * `uniXXXX`, or `uXXXX` to `uXXXXXX` (4 to 6 hex digits): that code point
//!   (`uni0041` is `A`);
//! * `@name`: the glyph named `name` (`@A`, `@period`);
//! * a range `A-Z` (three characters, the middle one `-`): every code point
//!   from the first to the last (`--glyphs` only);
//! * anything else: a glyph name (`Aacute`, `at`, `period`).
//!
//! Code points are looked up in the font's cmap, names in its glyph list
//! ([`FontInfo::glyphs`]: the `post` or CFF names, `gidN` when the font has
//! none). Errors name the flag and quote the item: no glyph named `X`, no
//! glyph for `U+XXXX`, not a Unicode scalar value, an empty item, and for
//! `--glyph` a range or a comma list.

use super::args::bad;
use super::CliError;
use lncert::shape::FontInfo;

/// What one item of a glyph selection names, before the font is asked.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum GlyphItem<'a> {
    /// One code point: a single character, or `uniXXXX` / `uXXXX`…`uXXXXXX`
    /// (not yet checked to be a Unicode scalar value).
    CodePoint(u32),
    /// The code points `first..=last` of a range `A-Z`.
    Range(u32, u32),
    /// A glyph name (`@name` without its `@`, or a bare name).
    Name(&'a str),
}

impl<'a> GlyphItem<'a> {
    /// Reads one item (see the module docs); never fails: what is not a
    /// character, a code point or a range is a name.
    pub fn parse(item: &'a str) -> Self {
        if let Some(name) = item.strip_prefix('@').filter(|n| !n.is_empty()) {
            return GlyphItem::Name(name);
        }
        let mut chars = item.chars();
        match (chars.next(), chars.next(), chars.next(), chars.next()) {
            (Some(c), None, _, _) => return GlyphItem::CodePoint(u32::from(c)),
            (Some(a), Some('-'), Some(b), None) => {
                return GlyphItem::Range(u32::from(a), u32::from(b))
            }
            _ => {}
        }
        item.strip_prefix("uni")
            .or_else(|| item.strip_prefix('u'))
            .filter(|h| (4..=6).contains(&h.len()) && h.chars().all(|c| c.is_ascii_hexdigit()))
            .and_then(|hex| u32::from_str_radix(hex, 16).ok())
            .map_or(GlyphItem::Name(item), GlyphItem::CodePoint)
    }
}

/// Resolves items in one font: code points through `by_char` (the font's
/// cmap), names through `info`'s glyph list. Errors name `flag`.
pub struct Resolver<'f, F> {
    /// The flag the items come from (`--glyph`, `--glyphs`).
    pub flag: &'static str,
    /// The font's glyph list (names and ids).
    pub info: &'f FontInfo,
    /// The glyph id of a character, if the font maps it.
    pub by_char: F,
}

impl<F: Fn(char) -> Result<Option<u16>, CliError>> Resolver<'_, F> {
    /// The glyph of the code point `cp` (given as `item`).
    pub fn code_point(&self, cp: u32, item: &str) -> Result<u16, CliError> {
        let ch = char::from_u32(cp)
            .ok_or_else(|| bad(self.flag, format!("{item:?}: not a Unicode scalar value")))?;
        (self.by_char)(ch)?.ok_or_else(|| {
            bad(
                self.flag,
                format!("{item:?}: the font has no glyph for U+{cp:04X}"),
            )
        })
    }

    /// The glyph named `name` (given as `item`).
    pub fn name(&self, name: &str, item: &str) -> Result<u16, CliError> {
        self.info
            .glyphs
            .iter()
            .find(|g| g.name == name)
            .map(|g| g.id)
            .ok_or_else(|| {
                bad(
                    self.flag,
                    format!("{item:?}: the font has no glyph named {name:?}"),
                )
            })
    }

    /// The glyphs of one item of a list (`--glyphs`): one glyph, or a
    /// range's in code point order (code points that are not scalar values
    /// skipped).
    pub fn ids(&self, item: &str) -> Result<Vec<u16>, CliError> {
        match GlyphItem::parse(item) {
            GlyphItem::Range(a, b) => self.range(a, b, item),
            one => self.one_glyph(one, item).map(|id| vec![id]),
        }
    }

    fn range(&self, a: u32, b: u32, item: &str) -> Result<Vec<u16>, CliError> {
        if a > b {
            return Err(bad(self.flag, format!("{item:?}: an empty range")));
        }
        if b - a > 0x10000 {
            return Err(bad(
                self.flag,
                format!("{item:?}: a range of more than 65536 code points"),
            ));
        }
        (a..=b)
            .filter(|&cp| char::from_u32(cp).is_some())
            .map(|cp| self.code_point(cp, item))
            .collect()
    }

    /// The glyph of an item that must name exactly one glyph (`--glyph`):
    /// not empty, not a comma list, not a range.
    pub fn one(&self, item: &str) -> Result<u16, CliError> {
        if item.is_empty() {
            return Err(bad(
                self.flag,
                "empty: give one character, uniXXXX, uXXXX, @name or a glyph name",
            ));
        }
        if item.chars().nth(1).is_some() && item.contains(',') {
            return Err(bad(
                self.flag,
                format!("{item:?}: one glyph, not a comma list (lncert font --glyphs takes lists)"),
            ));
        }
        self.one_glyph(GlyphItem::parse(item), item)
    }

    fn one_glyph(&self, parsed: GlyphItem<'_>, item: &str) -> Result<u16, CliError> {
        match parsed {
            GlyphItem::CodePoint(cp) => self.code_point(cp, item),
            GlyphItem::Name(name) => self.name(name, item),
            GlyphItem::Range(..) => Err(bad(
                self.flag,
                format!(
                    "{item:?}: a range; {} takes one glyph (lncert font --glyphs takes ranges)",
                    self.flag
                ),
            )),
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use lncert::shape::GlyphInfo;

    #[test]
    fn items_are_read_as_characters_code_points_ranges_and_names() {
        use GlyphItem::*;
        assert_eq!(GlyphItem::parse("a"), CodePoint(0x61));
        assert_eq!(GlyphItem::parse(","), CodePoint(0x2c));
        assert_eq!(GlyphItem::parse("@"), CodePoint(0x40));
        assert_eq!(GlyphItem::parse("é"), CodePoint(0xe9));
        assert_eq!(GlyphItem::parse("uni0041"), CodePoint(0x41));
        assert_eq!(GlyphItem::parse("u1F600"), CodePoint(0x1f600));
        assert_eq!(GlyphItem::parse("u10FFFF"), CodePoint(0x10ffff));
        assert_eq!(GlyphItem::parse("uD800"), CodePoint(0xd800));
        assert_eq!(GlyphItem::parse("A-Z"), Range(0x41, 0x5a));
        assert_eq!(GlyphItem::parse("@A"), Name("A"));
        assert_eq!(GlyphItem::parse("@-z"), Name("-z"));
        assert_eq!(GlyphItem::parse("Aacute"), Name("Aacute"));
        // too few or too many hex digits, or not hex: names
        assert_eq!(GlyphItem::parse("uni41"), Name("uni41"));
        assert_eq!(GlyphItem::parse("uniE0FF0"), CodePoint(0xe0ff0));
        assert_eq!(GlyphItem::parse("u1234567"), Name("u1234567"));
        assert_eq!(GlyphItem::parse("uni004G"), Name("uni004G"));
        assert_eq!(GlyphItem::parse("u"), CodePoint(0x75));
        assert_eq!(GlyphItem::parse("uni"), Name("uni"));
    }

    fn font() -> FontInfo {
        let g = |id: u16, name: &str, cp: &[u32]| GlyphInfo {
            id,
            name: name.to_string(),
            codepoints: cp.to_vec(),
            advance: 0,
        };
        FontInfo {
            units_per_em: 1000,
            family: None,
            style: None,
            ascender: 800,
            descender: -200,
            x_height: None,
            cap_height: None,
            cff: false,
            glyphs: vec![
                g(0, ".notdef", &[]),
                g(1, "A", &[0x41]),
                g(2, "B", &[0x42]),
                g(3, "comma", &[0x2c]),
            ],
        }
    }

    #[test]
    fn one_item_names_one_glyph_or_says_why_not() {
        let info = font();
        let by_char = |ch: char| -> Result<Option<u16>, CliError> {
            Ok(info
                .glyphs
                .iter()
                .find(|g| g.codepoints.contains(&u32::from(ch)))
                .map(|g| g.id))
        };
        let r = Resolver {
            flag: "--glyph",
            info: &info,
            by_char,
        };
        for item in ["A", "uni0041", "u0041", "u000041", "@A"] {
            assert_eq!(r.one(item).unwrap(), 1, "{item}");
        }
        assert_eq!(r.one(",").unwrap(), 3);
        assert_eq!(r.one("comma").unwrap(), 3);
        assert_eq!(r.ids("A-B").unwrap(), vec![1, 2]);
        assert_eq!(r.ids("uni0042").unwrap(), vec![2]);
        assert!(r.ids("B-A").unwrap_err().reason.contains("an empty range"));
        assert!(r.ids("A-C").unwrap_err().reason.contains("U+0043"));
        let why = |item: &str| {
            let e = r.one(item).unwrap_err();
            assert_eq!(e.field, "--glyph", "{item}");
            e.reason
        };
        assert!(why("").contains("empty"));
        assert!(why("A,B").contains("comma list"));
        assert!(why("A-B").contains("a range"));
        assert!(why("Aacute").contains("no glyph named \"Aacute\""));
        assert!(why("@at").contains("no glyph named \"at\""));
        assert!(why("uni0043").contains("no glyph for U+0043"));
        assert!(why("uD800").contains("not a Unicode scalar value"));
        assert!(why("u110000").contains("not a Unicode scalar value"));
    }
}
