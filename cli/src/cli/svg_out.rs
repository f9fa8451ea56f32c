//! `--out FILE.svg` of `lncert stroke` and `lncert offset`: the results as an
//! SVG document ([`lncert::write::svg_document`]) in the frame of the input —
//! an SVG document's own `viewBox`, `width` and `height`, y down as read; SVG
//! path data y down with a computed `viewBox`; JSON curves, circles and
//! glyphs (y up) flipped upright. The extension says what is written: `.svg`
//! only so far (path data is `--path-out`, curve files `--curve-out`).

use super::args::bad;
use super::CliError;
use lncert::write::{svg_document, SvgOptions, SvgShape};
use std::path::Path;

/// Checks `--out` before any work: a writable file whose extension is `.svg`.
pub fn check(path: &Path) -> Result<(), CliError> {
    let svg = path
        .extension()
        .and_then(|e| e.to_str())
        .is_some_and(|e| e.eq_ignore_ascii_case("svg"));
    if !svg {
        return Err(bad(
            "--out",
            format!(
                "{}: the extension says what is written, and only .svg (an SVG document) is known; SVG path data: --path-out",
                path.display()
            ),
        ));
    }
    super::args::output_file("--out", path)
}

/// The frame of the document for the input `curve` (read as `offset` and
/// `stroke` read it; `y_down` as [`super::curve_input::CurveInput`] says).
pub fn frame(curve: &Path, glyph: bool, y_down: bool) -> Result<SvgOptions, CliError> {
    if !y_down {
        return Ok(SvgOptions {
            y_up: true,
            ..Default::default()
        });
    }
    let text = super::curve_input::read_text(curve)?;
    if glyph || !text.trim_start().starts_with('<') {
        return Ok(SvgOptions::default());
    }
    SvgOptions::from_svg(&text).map_err(|e| bad("CURVE", e))
}

/// Writes the document of `shapes` to `path`.
pub fn write(path: &Path, shapes: &[SvgShape], frame: &SvgOptions) -> Result<(), CliError> {
    let doc = svg_document(shapes, frame).map_err(|e| bad("--out", e))?;
    std::fs::write(path, doc)
        .map_err(|e| bad("--out", format!("cannot write {}: {e}", path.display())))
}

/// The attribute that marks a result as proven or not (`"true"`/`"false"`).
pub fn proven(shape: SvgShape, proven: bool) -> SvgShape {
    shape.with("data-lncert-proven", if proven { "true" } else { "false" })
}

/// The refusal of `flag` (`--out`, `--path-out`) for native G² segments:
/// SVG path data has no command above degree 3.
pub fn native_g2_refused(flag: &str) -> CliError {
    bad(
        flag,
        "G2 segments have degree n + 3 ≥ 4, which SVG path data cannot store: use --output cubic, --method ln-pair (cubic), or --curve-out",
    )
}
