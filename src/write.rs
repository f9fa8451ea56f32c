//! Writers: results out as SVG path data and SVG documents (kurbo's
//! `BezPath` out is in `kurbo_bridge`, feature `kurbo`).
//!
//! | what | function |
//! |---|---|
//! | outline contours (stroke outlines: exact Béziers and exact arcs) → path data | [`path_data`] |
//! | Bézier pieces (an input curve) → path data | [`beziers_path_data`] |
//! | an offset approximant (segments and join arcs) → path data | [`offset_path_data`] |
//! | a grid-rounded offset → path data | [`grid_path_data`] |
//! | shapes → a whole SVG document | [`svg_document`], [`SvgShape`], [`SvgOptions`] |
//! | bounds of contours | [`contour_bounds`] |
//!
//! Coordinates are written in the contours' own coordinates: exact rationals
//! as their nearest `f64`, printed as the shortest decimal that reads back to
//! that float ([`Numbers::Shortest`]), or as the float's exact decimal
//! expansion ([`Numbers::Exact`]: lncert's exact reader reads it back as the
//! very same dyadic rational). Béziers of degree 1, 2, 3 are `L`, `Q`, `C`;
//! SVG has no command for higher degrees, which are refused (an error naming
//! the piece): fit them first (`approx::Output::Cubic`). Arcs are `A` commands
//! (radius and end point rounded to floats; the large-arc and sweep flags
//! decided exactly). A closed contour ends with `Z`, an open one does not.
//!
//! Orientation: lncert's stroke outlines are oriented, outer contours
//! counter-clockwise (positive area in the contours' coordinates) and holes
//! clockwise, so the filled region is the **nonzero** fill of the path data
//! (also when several outlines overlap); [`SvgShape::outline`] writes
//! `fill-rule="nonzero"`.
//!
//! # Examples
//! ```
//! use lncert::write::{beziers_path_data, svg_document, SvgOptions, SvgShape};
//! let c = lncert::parse_curve("M 0 0 C 1 1 2 1 3 0").unwrap();
//! assert_eq!(beziers_path_data(&c).unwrap(), "M 0 0 C 1 1 2 1 3 0");
//! let doc = svg_document(&[SvgShape::curve(&c).unwrap()], &SvgOptions::default()).unwrap();
//! assert!(doc.starts_with("<svg"));
//! ```

use crate::curve::{Bezier, V2};
use crate::offset::gridfit::GridOffset;
use crate::offset::prep::Junction;
use crate::offset::OffsetResult;
use crate::scalar::{rational_from_f64, Rational, Scalar};
use crate::stroke::circle::Arc;
use crate::stroke::trim::{Contour, Piece};
use crate::Error;
use num_traits::Signed;

/// How numbers are printed in path data.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub enum Numbers {
    /// The shortest decimal that reads back to the same `f64` (Rust's `{}`).
    #[default]
    Shortest,
    /// The exact decimal expansion of the `f64` ([`exact_decimal`]): any float
    /// reader reads the same float, and lncert's exact reader the same
    /// dyadic rational.
    Exact,
}

/// The exact decimal expansion of a finite float: `m 2^e` with `e < 0` is
/// `m 5^-e / 10^-e` (`"NaN"` for a non-finite one).
///
/// # Examples
/// ```
/// assert_eq!(lncert::write::exact_decimal(0.1), "0.1000000000000000055511151231257827021181583404541015625");
/// assert_eq!(lncert::write::exact_decimal(-3.0), "-3");
/// ```
pub fn exact_decimal(x: f64) -> String {
    use num_bigint::BigInt;
    let Some(r) = rational_from_f64(x) else {
        return "NaN".to_string();
    };
    let (n, d) = (r.numer().clone(), r.denom().clone());
    // d = 2^k
    let k = d.bits() - 1;
    if k == 0 {
        return n.to_string();
    }
    let digits = (n.magnitude() * num_traits::pow(BigInt::from(5).magnitude().clone(), k as usize))
        .to_string();
    let k = k as usize;
    let (int, frac) = if digits.len() > k {
        (
            digits[..digits.len() - k].to_string(),
            digits[digits.len() - k..].to_string(),
        )
    } else {
        (
            "0".to_string(),
            format!("{}{}", "0".repeat(k - digits.len()), digits),
        )
    };
    let frac = frac.trim_end_matches('0');
    let sign = if x < 0.0 { "-" } else { "" };
    format!("{sign}{int}.{frac}")
}

/// Path data being written: commands separated by spaces, subpaths by lines.
struct PathWriter {
    d: String,
    numbers: Numbers,
}

impl PathWriter {
    fn new(numbers: Numbers) -> Self {
        PathWriter {
            d: String::new(),
            numbers,
        }
    }
    fn num(&mut self, x: f64, field: &str) -> Result<(), Error> {
        if !x.is_finite() {
            return Err(Error::new(
                field,
                format!("{x}: not a finite float (a coordinate beyond the f64 range)"),
            ));
        }
        self.d.push(' ');
        match self.numbers {
            Numbers::Shortest => self.d.push_str(&format!("{x}")),
            Numbers::Exact => self.d.push_str(&exact_decimal(x)),
        }
        Ok(())
    }
    fn point(&mut self, p: (f64, f64), field: &str) -> Result<(), Error> {
        self.num(p.0, field)?;
        self.num(p.1, field)
    }
    fn command(&mut self, c: &str) {
        if !self.d.is_empty() && !self.d.ends_with('\n') {
            self.d.push(' ');
        }
        self.d.push_str(c);
    }
    /// `M`, on a new line after an earlier subpath.
    fn move_to(&mut self, p: (f64, f64), field: &str) -> Result<(), Error> {
        if !self.d.is_empty() {
            self.d.push('\n');
        }
        self.command("M");
        self.point(p, field)
    }
    /// `L`, `Q` or `C` through `pts` (the control points after the start).
    fn bezier_to(&mut self, pts: &[(f64, f64)], field: &str) -> Result<(), Error> {
        let cmd = match pts.len() {
            1 => "L",
            2 => "Q",
            3 => "C",
            n => {
                return Err(Error::new(
                    field,
                    format!(
                        "a degree-{n} Bézier piece has no SVG path command (degree ≤ 3: fit it as cubics)"
                    ),
                ))
            }
        };
        self.command(cmd);
        for p in pts {
            self.point(*p, field)?;
        }
        Ok(())
    }
    fn arc_to(
        &mut self,
        r: f64,
        large: bool,
        sweep: bool,
        to: (f64, f64),
        field: &str,
    ) -> Result<(), Error> {
        self.command("A");
        self.num(r, field)?;
        self.num(r, field)?;
        self.d += &format!(" 0 {} {}", large as u8, sweep as u8);
        self.point(to, field)
    }
    fn close(&mut self) {
        self.command("Z");
    }
}

fn fp(p: &V2<Rational>) -> (f64, f64) {
    (p.x.approx(), p.y.approx())
}

/// An exact arc as SVG arc commands: `(large-arc, sweep, end)` for each, two
/// halves (through the antipode of the start) for a full circle.
fn arc_commands(a: &Arc) -> Vec<(bool, bool, V2<Rational>)> {
    if a.from == a.to {
        let anti = a.center.add(&a.center.sub(&a.from));
        let sweep = !a.clockwise;
        return vec![(false, sweep, anti), (false, sweep, a.to.clone())];
    }
    let (u, v) = (a.from.sub(&a.center), a.to.sub(&a.center));
    let cross = u.cross(&v);
    // large-arc: the travelled angle exceeds π (decided exactly)
    let large = if a.clockwise {
        cross.is_positive()
    } else {
        cross.is_negative()
    };
    // sweep 1: the positive angle direction of the coordinates (from +x to +y)
    vec![(large, !a.clockwise, a.to.clone())]
}

/// SVG path data of outline contours (such as [`crate::stroke::trim::Stroke`]'s
/// `contours`): one subpath per contour, one line each, `M` at the first
/// piece's start, `L`/`Q`/`C` for Béziers of degree 1 to 3, `A` for arcs, and
/// `Z` after a closed contour. Numbers: [`Numbers::Shortest`] of the nearest
/// floats. Errors name the piece (`contours[1].pieces[4]`): a Bézier of degree
/// above 3, a coordinate beyond the `f64` range.
///
/// # Examples
/// ```
/// use lncert::stroke::{Contour, Orientation, Piece};
/// use lncert::write::path_data;
/// use lncert::{Bezier, V2};
/// let q = |x: i64| lncert::Rational::from_integer(x.into());
/// let p = |x, y| V2::new(q(x), q(y));
/// let line = |a, b| Piece::Bezier(Bezier::new(vec![a, b]));
/// let square = Contour {
///     pieces: vec![
///         line(p(0, 0), p(2, 0)),
///         line(p(2, 0), p(2, 2)),
///         line(p(2, 2), p(0, 2)),
///         line(p(0, 2), p(0, 0)),
///     ],
///     closed: true,
///     orientation: Orientation::CounterClockwise,
///     area: (4.0, 4.0),
/// };
/// assert_eq!(path_data(&[square]).unwrap(), "M 0 0 L 2 0 L 2 2 L 0 2 L 0 0 Z");
/// ```
pub fn path_data(contours: &[Contour]) -> Result<String, Error> {
    let mut w = PathWriter::new(Numbers::Shortest);
    for (i, c) in contours.iter().enumerate() {
        let Some(first) = c.pieces.first() else {
            continue;
        };
        w.move_to(fp(first.start()), &format!("contours[{i}].pieces[0]"))?;
        for (j, p) in c.pieces.iter().enumerate() {
            let field = format!("contours[{i}].pieces[{j}]");
            match p {
                Piece::Bezier(b) => {
                    let pts: Vec<(f64, f64)> = b.points()[1..].iter().map(fp).collect();
                    w.bezier_to(&pts, &field)?;
                }
                Piece::Arc(a) => {
                    for (large, sweep, to) in arc_commands(a) {
                        w.arc_to(a.radius.approx(), large, sweep, fp(&to), &field)?;
                    }
                }
            }
        }
        if c.closed {
            w.close();
        }
    }
    Ok(w.d)
}

/// SVG path data of Bézier pieces (a curve as lncert reads it): a new
/// subpath wherever a piece does not start exactly where the previous one
/// ended; no `Z` (a curve is not a region). Errors as [`path_data`]'s
/// (`pieces[3]`).
///
/// # Examples
/// ```
/// let c = lncert::parse_curve("M 0 0 Q 1 1 2 0 M 5 5 L 6 5").unwrap();
/// assert_eq!(lncert::write::beziers_path_data(&c).unwrap(), "M 0 0 Q 1 1 2 0\nM 5 5 L 6 5");
/// ```
pub fn beziers_path_data(pieces: &[Bezier<Rational>]) -> Result<String, Error> {
    let mut w = PathWriter::new(Numbers::Shortest);
    let mut last: Option<&V2<Rational>> = None;
    for (i, b) in pieces.iter().enumerate() {
        let field = format!("pieces[{i}]");
        let pts = b.points();
        if last != Some(&pts[0]) {
            w.move_to(fp(&pts[0]), &field)?;
        }
        let rest: Vec<(f64, f64)> = pts[1..].iter().map(fp).collect();
        w.bezier_to(&rest, &field)?;
        last = pts.last();
    }
    Ok(w.d)
}

/// SVG path data of an offset approximant ([`crate::offset::offset`]'s segments):
/// `M` at the start of each run of segments that meet exactly, then
/// `L`/`Q`/`C` by degree, and each join arc of a G⁰ corner (not absorbed) as
/// an `A` command from the end of the piece before the corner to the start of
/// the next (radius `|distance|`). Numbers: [`Numbers::Exact`] — the
/// segments' control points are dyadic rationals, and lncert reads the data
/// back as exactly the certified curve; the join arcs' end points are the
/// segments' float end points (a reader approximates the arc, as lncert's
/// does, within a certified bound). Errors name the segment
/// (`segments[4]`): a native G2 segment has degree `n + 3 ≥ 4` (use
/// `Output::Cubic` or the LN-pair method).
///
/// # Examples
/// ```
/// use lncert::{offset, parse_curve, OffsetMethod, OffsetOptions};
/// let c = parse_curve("M 0 0 L 4 0").unwrap();
/// let mut o = OffsetOptions::new(lncert::parse_rational("1").unwrap(), "1e-3".parse().unwrap());
/// o.method = OffsetMethod::LnPair;
/// let d = lncert::write::offset_path_data(&offset(&c, &o).unwrap()).unwrap();
/// assert!(d.starts_with("M 0 1 C "), "{d}");
/// ```
pub fn offset_path_data(res: &OffsetResult) -> Result<String, Error> {
    // the join arcs: (piece after which it comes, SVG sweep flag): sweep 1
    // for a counter-clockwise turn (the positive angle direction)
    let joins: Vec<(usize, bool)> = res
        .corners
        .iter()
        .filter(|c| !c.absorbed)
        .filter_map(|c| match &c.kind {
            Junction::Join { clockwise, .. } => Some((c.after, !clockwise)),
            _ => None,
        })
        .collect();
    // the shortest decimal of the nearest float: an SVG arc is defined by its
    // end points, the radius only picks the circle through them
    let radius = res.distance.abs().approx();
    let segments = &res.segments;
    let mut w = PathWriter::new(Numbers::Exact);
    let mut last: Option<(f64, f64)> = None;
    let arc_to = |w: &mut PathWriter, after: usize, to: (f64, f64), field: &str| {
        match joins.iter().find(|j| j.0 == after) {
            Some(&(_, sweep)) => {
                // the radius as its shortest decimal, the end point exact
                w.command("A");
                w.d += &format!(" {radius} {radius} 0 0 {}", sweep as u8);
                w.point(to, field).map(|_| true)
            }
            None => Ok(false),
        }
    };
    for (i, s) in segments.iter().enumerate() {
        let field = format!("segments[{i}]");
        let pts: Vec<(f64, f64)> = s.bezier.points().iter().map(|p| (p.x, p.y)).collect();
        let p0 = pts[0];
        // a join arc from the previous piece's end to this piece's start
        let joined = i > 0
            && segments[i - 1].piece != s.piece
            && last.is_some()
            && last != Some(p0)
            && arc_to(&mut w, segments[i - 1].piece, p0, &field)?;
        if joined {
            last = Some(p0);
        }
        if last != Some(p0) {
            w.move_to(p0, &field)?;
        }
        w.bezier_to(&pts[1..], &field)?;
        last = pts.last().copied();
    }
    // the closing corner of a closed curve: back to the first segment's start
    if let (Some(first), Some(end), Some(l)) = (segments.first(), last, segments.last()) {
        let p0 = (first.bezier.points()[0].x, first.bezier.points()[0].y);
        if end != p0 {
            arc_to(&mut w, l.piece, p0, "segments[0]")?;
        }
    }
    Ok(w.d)
}

/// SVG path data of a grid-rounded offset ([`crate::offset::offset_on_grid`]): one
/// subpath per contour (`Z` when closed), the cubics (`C`) or quadratics
/// (`Q`) with [`Numbers::Exact`] (the control points are on the grid, and
/// read back exactly).
///
/// # Examples
/// ```no_run
/// # fn show(r: &lncert::offset::GridOffset) {
/// println!("{}", lncert::write::grid_path_data(r).unwrap());
/// # }
/// ```
pub fn grid_path_data(r: &GridOffset) -> Result<String, Error> {
    let mut w = PathWriter::new(Numbers::Exact);
    for &(first, n, closed) in &r.contours {
        for (k, s) in r.segments[first..first + n].iter().enumerate() {
            let field = format!("segments[{}]", first + k);
            let p: Vec<(f64, f64)> = s.bezier.points().iter().map(|v| (v.x, v.y)).collect();
            if k == 0 {
                w.move_to(p[0], &field)?;
            }
            w.bezier_to(&p[1..], &field)?;
        }
        if closed {
            w.close();
        }
    }
    Ok(w.d)
}

/// Bounds `[min_x, min_y, max_x, max_y]` of outline contours (floats): the
/// Béziers' control polygons (which hold the curves) and the arcs' whole
/// circles — a box that holds the outline, not the tightest one. `None` when
/// there is no piece.
///
/// # Examples
/// ```
/// # use lncert::stroke::{Contour, Orientation, Piece};
/// # use lncert::{Bezier, V2};
/// let q = |x: i64| lncert::Rational::from_integer(x.into());
/// let c = Contour {
///     pieces: vec![Piece::Bezier(Bezier::new(vec![V2::new(q(0), q(0)), V2::new(q(1), q(2)), V2::new(q(3), q(0))]))],
///     closed: false, orientation: Orientation::Undecided, area: (0.0, 0.0),
/// };
/// assert_eq!(lncert::write::contour_bounds(&[c]), Some([0.0, 0.0, 3.0, 2.0]));
/// ```
pub fn contour_bounds(contours: &[Contour]) -> Option<[f64; 4]> {
    let mut b: Option<[f64; 4]> = None;
    let mut add = |x: f64, y: f64| {
        let v = b.get_or_insert([x, y, x, y]);
        *v = [v[0].min(x), v[1].min(y), v[2].max(x), v[3].max(y)];
    };
    for p in contours.iter().flat_map(|c| &c.pieces) {
        match p {
            Piece::Bezier(bz) => {
                for v in bz.points() {
                    add(v.x.approx(), v.y.approx());
                }
            }
            Piece::Arc(a) => {
                let (c, r) = (fp(&a.center), a.radius.approx());
                add(c.0 - r, c.1 - r);
                add(c.0 + r, c.1 + r);
            }
        }
    }
    b
}

fn bezier_bounds(pieces: &[Bezier<Rational>]) -> Option<[f64; 4]> {
    let pts: Vec<(f64, f64)> = pieces.iter().flat_map(|b| b.points()).map(fp).collect();
    float_bounds(&pts)
}

fn float_bounds(pts: &[(f64, f64)]) -> Option<[f64; 4]> {
    let (x, y) = *pts.first()?;
    Some(pts.iter().fold([x, y, x, y], |v, &(x, y)| {
        [v[0].min(x), v[1].min(y), v[2].max(x), v[3].max(y)]
    }))
}

/// One `<path>` of an SVG document: its path data, how it is painted, the
/// bounds of what it draws (for a computed `viewBox`), and extra attributes.
#[derive(Clone, Debug, PartialEq)]
pub struct SvgShape {
    /// The path data (`d`).
    pub d: String,
    /// A region (`fill="black" fill-rule="nonzero"`, no stroke) or a curve
    /// (`fill="none"`, a black hairline stroke that does not scale).
    pub filled: bool,
    /// `[min_x, min_y, max_x, max_y]` in the path data's coordinates.
    pub bounds: Option<[f64; 4]>,
    /// Extra attributes, written after `d` and the paint, values escaped
    /// (e.g. `("data-lncert-proven", "false")`).
    pub attributes: Vec<(String, String)>,
}

impl SvgShape {
    /// The filled region of outline contours (a stroke's outline), with the
    /// nonzero rule (see the module's note on orientation); errors as
    /// [`path_data`]'s.
    ///
    /// # Examples
    /// ```
    /// let s = lncert::write::SvgShape::outline(&[]).unwrap().with("class", "stroke");
    /// assert!(s.filled && s.d.is_empty() && s.bounds.is_none());
    /// ```
    pub fn outline(contours: &[Contour]) -> Result<SvgShape, Error> {
        Ok(SvgShape {
            d: path_data(contours)?,
            filled: true,
            bounds: contour_bounds(contours),
            attributes: Vec::new(),
        })
    }
    /// A curve drawn as a line; errors as [`beziers_path_data`]'s.
    ///
    /// # Examples
    /// ```
    /// let c = lncert::parse_curve("M 0 0 L 1 2").unwrap();
    /// let s = lncert::write::SvgShape::curve(&c).unwrap();
    /// assert_eq!((s.filled, s.bounds), (false, Some([0.0, 0.0, 1.0, 2.0])));
    /// ```
    pub fn curve(pieces: &[Bezier<Rational>]) -> Result<SvgShape, Error> {
        Ok(SvgShape {
            d: beziers_path_data(pieces)?,
            filled: false,
            bounds: bezier_bounds(pieces),
            attributes: Vec::new(),
        })
    }
    /// An offset approximant drawn as a line ([`offset_path_data`]); the
    /// bounds are the segments' control points'.
    ///
    /// # Examples
    /// ```
    /// use lncert::{offset, parse_curve, OffsetMethod, OffsetOptions};
    /// let mut o = OffsetOptions::new(lncert::parse_rational("1").unwrap(), "1e-3".parse().unwrap());
    /// o.method = OffsetMethod::LnPair;
    /// let r = offset(&parse_curve("M 0 0 L 4 0").unwrap(), &o).unwrap();
    /// let s = lncert::write::SvgShape::offset(&r).unwrap();
    /// assert_eq!(s.bounds, Some([0.0, 1.0, 4.0, 1.0]));
    /// ```
    pub fn offset(res: &OffsetResult) -> Result<SvgShape, Error> {
        let beziers = res.segments.iter().map(|s| &s.bezier);
        Ok(SvgShape::line(offset_path_data(res)?, beziers))
    }
    /// A grid-rounded offset drawn as a line ([`grid_path_data`]).
    ///
    /// # Examples
    /// ```no_run
    /// # fn show(r: &lncert::offset::GridOffset) {
    /// let doc = lncert::svg_document(
    ///     &[lncert::SvgShape::grid_offset(r).unwrap()],
    ///     &lncert::SvgOptions { y_up: true, ..Default::default() },
    /// );
    /// # }
    /// ```
    pub fn grid_offset(r: &GridOffset) -> Result<SvgShape, Error> {
        let beziers = r.segments.iter().map(|s| &s.bezier);
        Ok(SvgShape::line(grid_path_data(r)?, beziers))
    }
    /// A line with path data `d` drawing float Béziers (bounds: their control points).
    fn line<'a>(d: String, beziers: impl Iterator<Item = &'a Bezier<f64>>) -> SvgShape {
        let pts: Vec<(f64, f64)> = beziers
            .flat_map(|b| b.points().iter().map(|p| (p.x, p.y)))
            .collect();
        SvgShape {
            d,
            filled: false,
            bounds: float_bounds(&pts),
            attributes: Vec::new(),
        }
    }
    /// The shape with one more attribute.
    ///
    /// # Examples
    /// ```
    /// let c = lncert::parse_curve("M 0 0 L 1 0").unwrap();
    /// let s = lncert::SvgShape::curve(&c).unwrap().with("id", "base");
    /// assert_eq!(s.attributes, [("id".to_string(), "base".to_string())]);
    /// ```
    pub fn with(mut self, name: impl Into<String>, value: impl Into<String>) -> SvgShape {
        self.attributes.push((name.into(), value.into()));
        self
    }
}

/// The frame of an SVG document: `viewBox`, size, and which way y points.
#[derive(Clone, Debug, Default, PartialEq)]
pub struct SvgOptions {
    /// `[min_x, min_y, width, height]` **in the shapes' coordinates**; `None`:
    /// the union of the shapes' bounds with a margin of 5 % of the larger side.
    pub view_box: Option<[f64; 4]>,
    /// The shapes' coordinates are y-up (JSON curves, font glyphs): the
    /// document flips them (`<g transform="scale(1,-1)">`, the `viewBox`
    /// mapped) so that the picture is upright. `false` (the default): the
    /// coordinates are SVG's own, y down — an outline computed from an SVG
    /// input is written as it was read, and renders as the input does.
    pub y_up: bool,
    /// The `width` attribute (e.g. `"24"`, `"10cm"`), when given.
    pub width: Option<String>,
    /// The `height` attribute, when given.
    pub height: Option<String>,
}

impl SvgOptions {
    /// The frame of an SVG document's root `<svg>` — its `viewBox`, `width`
    /// and `height` — so that a result written with it lies on the page
    /// exactly where the input did (lncert's SVG reader reads the root's user
    /// coordinates, y down: `y_up` is `false`). Errors name `svg` or
    /// `svg.viewBox` (not XML, another root, a `viewBox` that is not four
    /// numbers with positive width and height).
    ///
    /// # Examples
    /// ```
    /// let o = lncert::write::SvgOptions::from_svg(r#"<svg viewBox="0 0 24 12" width="48"/>"#).unwrap();
    /// assert_eq!(o.view_box, Some([0.0, 0.0, 24.0, 12.0]));
    /// assert_eq!((o.width.as_deref(), o.height.as_deref(), o.y_up), (Some("48"), None, false));
    /// assert_eq!(lncert::write::SvgOptions::from_svg(r#"<svg viewBox="0 0 24"/>"#).unwrap_err().field, "svg.viewBox");
    /// ```
    pub fn from_svg(text: &str) -> Result<SvgOptions, Error> {
        let doc = roxmltree::Document::parse(text)
            .map_err(|e| Error::new("svg", format!("not an XML document: {e}")))?;
        let root = doc.root_element();
        if root.tag_name().name() != "svg" {
            return Err(Error::new(
                "svg",
                format!(
                    "the root element is <{}>, not <svg>",
                    root.tag_name().name()
                ),
            ));
        }
        let view_box = match root.attribute("viewBox") {
            None => None,
            Some(v) => {
                let nums: Vec<f64> = v
                    .split(|c: char| c.is_whitespace() || c == ',')
                    .filter(|s| !s.is_empty())
                    .map(|s| s.parse::<f64>())
                    .collect::<Result<_, _>>()
                    .map_err(|e| Error::new("svg.viewBox", format!("{v:?}: {e}")))?;
                match nums[..] {
                    [x, y, w, h]
                        if [x, y, w, h].iter().all(|n| n.is_finite()) && w > 0.0 && h > 0.0 =>
                    {
                        Some([x, y, w, h])
                    }
                    _ => {
                        return Err(Error::new(
                            "svg.viewBox",
                            format!("{v:?}: expected four finite numbers min-x min-y width height, width and height > 0"),
                        ))
                    }
                }
            }
        };
        Ok(SvgOptions {
            view_box,
            y_up: false,
            width: root.attribute("width").map(str::to_string),
            height: root.attribute("height").map(str::to_string),
        })
    }
}

/// `s` with the five XML special characters escaped (for attribute values).
fn xml_escape(s: &str) -> String {
    let mut out = String::with_capacity(s.len());
    for c in s.chars() {
        match c {
            '&' => out.push_str("&amp;"),
            '<' => out.push_str("&lt;"),
            '>' => out.push_str("&gt;"),
            '"' => out.push_str("&quot;"),
            '\'' => out.push_str("&apos;"),
            c => out.push(c),
        }
    }
    out
}

/// An XML attribute name (letters, digits, `_`, `-`, `.`, `:`; not starting
/// with a digit, `-` or `.`).
fn is_xml_name(s: &str) -> bool {
    let mut chars = s.chars();
    matches!(chars.next(), Some(c) if c.is_ascii_alphabetic() || c == '_' || c == ':')
        && chars.all(|c| c.is_ascii_alphanumeric() || matches!(c, '_' | '-' | '.' | ':'))
}

fn number_list(v: &[f64]) -> String {
    v.iter()
        .map(|x| format!("{x}"))
        .collect::<Vec<_>>()
        .join(" ")
}

/// A whole SVG document (UTF-8 text) drawing `shapes`, one `<path>` each, in
/// order, in the frame `opts`: `viewBox` given or computed from the shapes'
/// bounds, `width`/`height` when given, and for y-up coordinates a
/// `scale(1,-1)` group (the path data are never changed). Errors: an extra
/// attribute whose name is not an XML name or is one the writer sets (`d`,
/// `fill`, …) (field `shapes[i].attributes[j]`), a non-finite view box.
///
/// # Examples
/// ```
/// use lncert::write::{svg_document, SvgOptions, SvgShape};
/// let c = lncert::parse_curve("M 0 0 L 10 5").unwrap();
/// let opts = SvgOptions { view_box: Some([0.0, 0.0, 10.0, 5.0]), ..Default::default() };
/// let doc = svg_document(&[SvgShape::curve(&c).unwrap().with("id", "a")], &opts).unwrap();
/// assert!(doc.contains(r#"viewBox="0 0 10 5""#) && doc.contains(r#"d="M 0 0 L 10 5""#));
/// // the same picture for y-up coordinates: flipped, the view box mapped
/// let up = SvgOptions { y_up: true, ..opts };
/// let doc = svg_document(&[SvgShape::curve(&c).unwrap()], &up).unwrap();
/// assert!(doc.contains(r#"viewBox="0 -5 10 5""#) && doc.contains("scale(1,-1)"));
/// ```
pub fn svg_document(shapes: &[SvgShape], opts: &SvgOptions) -> Result<String, Error> {
    const RESERVED: [&str; 7] = [
        "d",
        "fill",
        "fill-rule",
        "stroke",
        "stroke-width",
        "vector-effect",
        "xmlns",
    ];
    let view_box = opts.view_box.or_else(|| {
        let b = shapes.iter().filter_map(|s| s.bounds).reduce(|a, b| {
            [
                a[0].min(b[0]),
                a[1].min(b[1]),
                a[2].max(b[2]),
                a[3].max(b[3]),
            ]
        })?;
        let (w, h) = ((b[2] - b[0]).max(1e-9), (b[3] - b[1]).max(1e-9));
        let m = 0.05 * w.max(h);
        Some([b[0] - m, b[1] - m, w + 2.0 * m, h + 2.0 * m])
    });
    let mut head = String::from(r#"<svg xmlns="http://www.w3.org/2000/svg""#);
    if let Some([x, y, w, h]) = view_box {
        if ![x, y, w, h].iter().all(|v| v.is_finite()) {
            return Err(Error::new("view_box", "not four finite numbers"));
        }
        // y-up: the box [y, y + h] is [−y − h, −y] after the flip
        let y = if opts.y_up { -(y + h) } else { y };
        head += &format!(r#" viewBox="{}""#, number_list(&[x, y, w, h]));
    }
    for (name, v) in [("width", &opts.width), ("height", &opts.height)] {
        if let Some(v) = v {
            head += &format!(r#" {name}="{}""#, xml_escape(v));
        }
    }
    head += ">\n";
    let mut body = String::new();
    for (i, s) in shapes.iter().enumerate() {
        let paint = if s.filled {
            r#"fill="black" fill-rule="nonzero""#
        } else {
            r#"fill="none" stroke="black" stroke-width="1" vector-effect="non-scaling-stroke""#
        };
        body += &format!(r#"<path d="{}" {paint}"#, xml_escape(&s.d));
        for (j, (name, value)) in s.attributes.iter().enumerate() {
            if !is_xml_name(name) || RESERVED.contains(&name.as_str()) {
                return Err(Error::new(
                    format!("shapes[{i}].attributes[{j}]"),
                    format!("{name:?} is not an XML attribute name, or one the writer sets"),
                ));
            }
            body += &format!(r#" {name}="{}""#, xml_escape(value));
        }
        body += "/>\n";
    }
    Ok(if opts.y_up {
        format!("{head}<g transform=\"scale(1,-1)\">\n{body}</g>\n</svg>\n")
    } else {
        format!("{head}{body}</svg>\n")
    })
}
