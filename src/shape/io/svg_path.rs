//! SVG path data (`M 0 0 C 1 2 3 4 5 6 …`): the scanner, the exact
//! path-data state machine, and SVG's number lists.

use super::{exact_number, CurveParseError, MAX_SEGMENTS, MAX_SVG_BYTES};
use crate::curve::{Bezier, V2};
use crate::scalar::Rational;
use crate::shape::svgarc::{
    attach_near, svg_arc, svg_exact_arc, ApproxElement, ApproxKind, ExactElement, InputApprox,
    Layout, Pending, SvgArc,
};

/// The exact path-data state machine: scanner plus current point, subpath
/// start and the control points that `S` and `T` reflect.
struct SvgParser<'a> {
    text: &'a str,
    bytes: &'a [u8],
    pos: usize,
    out: Vec<Bezier<Rational>>,
    cur: V2<Rational>,
    start: V2<Rational>,
    /// `out.len()` when the current subpath began (its moveto).
    subpath_first: usize,
    /// Second control point of the previous segment if it was `C`/`S`.
    last_cubic: Option<V2<Rational>>,
    /// Control point of the previous segment if it was `Q`/`T`.
    last_quad: Option<V2<Rational>>,
    /// The approximated arcs.
    approx: InputApprox,
    /// Every piece index that begins a subpath.
    subpath_starts: Vec<usize>,
    /// Every arc's range of cubic pieces.
    arc_ranges: Vec<(usize, usize)>,
    /// The circular arcs with an irrational centre (their near arcs are
    /// found at the end, when the pieces after them are known).
    pending: Vec<Pending>,
}

fn is_wsp(b: u8) -> bool {
    matches!(b, b' ' | b'\t' | b'\n' | b'\r' | 0x0C)
}

fn is_number_start(b: u8) -> bool {
    b.is_ascii_digit() || matches!(b, b'.' | b'+' | b'-')
}

/// Parameter names of a command (its length is the parameter count).
fn params(cmd: u8) -> &'static [&'static str] {
    match cmd.to_ascii_uppercase() {
        b'M' | b'L' | b'T' => &["x", "y"],
        b'H' => &["x"],
        b'V' => &["y"],
        b'C' => &["x1", "y1", "x2", "y2", "x", "y"],
        b'S' => &["x2", "y2", "x", "y"],
        b'Q' => &["x1", "y1", "x", "y"],
        b'A' => &[
            "rx",
            "ry",
            "x-axis-rotation",
            "large-arc-flag",
            "sweep-flag",
            "x",
            "y",
        ],
        _ => &[],
    }
}

impl<'a> SvgParser<'a> {
    fn new(text: &'a str) -> Self {
        SvgParser {
            text,
            bytes: text.as_bytes(),
            pos: 0,
            out: Vec::new(),
            cur: V2::new(zero(), zero()),
            start: V2::new(zero(), zero()),
            subpath_first: 0,
            last_cubic: None,
            last_quad: None,
            approx: InputApprox::default(),
            subpath_starts: Vec::new(),
            arc_ranges: Vec::new(),
            pending: Vec::new(),
        }
    }

    fn err(&self, position: usize, reason: impl Into<String>) -> CurveParseError {
        CurveParseError::Svg {
            position,
            reason: reason.into(),
        }
    }

    fn peek(&self) -> Option<u8> {
        self.bytes.get(self.pos).copied()
    }

    /// The character at `pos`, for messages.
    fn char_at(&self, pos: usize) -> String {
        match self.text.get(pos..).and_then(|s| s.chars().next()) {
            Some(c) => format!("{c:?}"),
            None => "the end of the data".to_string(),
        }
    }

    fn skip_wsp(&mut self) {
        while self.peek().is_some_and(is_wsp) {
            self.pos += 1;
        }
    }

    /// Scans one number in SVG syntax (`-1.5e-3`, `.5`, `1.`) and reads its
    /// text exactly.
    fn number(&mut self) -> Result<Rational, CurveParseError> {
        let begin = self.pos;
        let mut p = self.pos;
        let at = |i: usize| self.bytes.get(i).copied();
        if matches!(at(p), Some(b'+') | Some(b'-')) {
            p += 1;
        }
        let int_start = p;
        while at(p).is_some_and(|b| b.is_ascii_digit()) {
            p += 1;
        }
        let mut digits = p - int_start;
        if at(p) == Some(b'.') {
            p += 1;
            let frac_start = p;
            while at(p).is_some_and(|b| b.is_ascii_digit()) {
                p += 1;
            }
            digits += p - frac_start;
        }
        if digits == 0 {
            return Err(self.err(
                begin,
                format!("expected a number, found {}", self.char_at(begin)),
            ));
        }
        if matches!(at(p), Some(b'e') | Some(b'E')) {
            let mut q = p + 1;
            if matches!(at(q), Some(b'+') | Some(b'-')) {
                q += 1;
            }
            if at(q).is_some_and(|b| b.is_ascii_digit()) {
                while at(q).is_some_and(|b| b.is_ascii_digit()) {
                    q += 1;
                }
                p = q;
            }
        }
        self.pos = p;
        let text = self.text.get(begin..p).unwrap_or("");
        exact_number(text).map_err(|reason| self.err(begin, reason))
    }

    /// Reads the parameters of one segment of `cmd`; `first` says whether
    /// they directly follow the command letter (no comma allowed there).
    fn read_params(&mut self, cmd: u8, first: bool) -> Result<Vec<Rational>, CurveParseError> {
        let names = params(cmd);
        let mut vals = Vec::with_capacity(names.len());
        for (i, name) in names.iter().enumerate() {
            self.skip_wsp();
            if (i > 0 || !first) && self.peek() == Some(b',') {
                self.pos += 1;
                self.skip_wsp();
            }
            if name.ends_with("-flag") {
                // a flag is the single character 0 or 1 (SVG's path grammar:
                // `A 1 1 0 1120 20` has the flags 1, 1 and then x = 20)
                match self.peek() {
                    Some(c @ (b'0' | b'1')) => {
                        self.pos += 1;
                        vals.push(Rational::from_integer(i64::from(c - b'0').into()));
                        continue;
                    }
                    _ => {
                        return Err(self.err(
                            self.pos,
                            format!(
                                "command {} expects the flag `{name}` (0 or 1), found {}",
                                cmd as char,
                                self.char_at(self.pos)
                            ),
                        ))
                    }
                }
            }
            if !self.peek().is_some_and(is_number_start) {
                return Err(self.err(
                    self.pos,
                    format!(
                        "missing parameter: command {} takes {} number{} ({}), expected `{name}` but found {}",
                        cmd as char,
                        names.len(),
                        if names.len() == 1 { "" } else { "s" },
                        names.join(" "),
                        self.char_at(self.pos)
                    ),
                ));
            }
            vals.push(self.number()?);
        }
        Ok(vals)
    }

    fn push(&mut self, pts: Vec<V2<Rational>>, at: usize) -> Result<(), CurveParseError> {
        // Every caller passes at least two points.
        self.push_bezier(Bezier::new(pts), at)
    }

    fn push_bezier(&mut self, b: Bezier<Rational>, at: usize) -> Result<(), CurveParseError> {
        if self.out.len() >= MAX_SEGMENTS {
            return Err(CurveParseError::TooLarge {
                what: format!("the number of segments in the SVG path data (at byte {at})"),
                limit: MAX_SEGMENTS,
            });
        }
        self.out.push(b);
        Ok(())
    }

    /// Point `(x, y)`, relative to the current point for lower-case commands.
    fn point(&self, relative: bool, x: &Rational, y: &Rational) -> V2<Rational> {
        let p = V2::new(x.clone(), y.clone());
        if relative {
            self.cur.add(&p)
        } else {
            p
        }
    }

    /// Applies one parameter set of `cmd`; `repeat` marks implicit repetitions.
    fn apply(
        &mut self,
        cmd: u8,
        v: &[Rational],
        repeat: bool,
        at: usize,
    ) -> Result<(), CurveParseError> {
        let rel = cmd.is_ascii_lowercase();
        let arg = |i: usize| -> Result<&Rational, CurveParseError> {
            v.get(i).ok_or_else(|| CurveParseError::Svg {
                position: at,
                reason: "internal error: missing parameter".to_string(),
            })
        };
        let mut cubic = None;
        let mut quad = None;
        match cmd.to_ascii_uppercase() {
            b'M' if !repeat => {
                let p = self.point(rel, arg(0)?, arg(1)?);
                self.start = p.clone();
                self.subpath_first = self.out.len();
                self.subpath_starts.push(self.out.len());
                self.cur = p;
            }
            b'M' | b'L' => {
                let p = self.point(rel, arg(0)?, arg(1)?);
                self.line_to(p, at)?;
            }
            b'H' => {
                let x = if rel {
                    self.cur.x.clone() + arg(0)?.clone()
                } else {
                    arg(0)?.clone()
                };
                let p = V2::new(x, self.cur.y.clone());
                self.line_to(p, at)?;
            }
            b'V' => {
                let y = if rel {
                    self.cur.y.clone() + arg(0)?.clone()
                } else {
                    arg(0)?.clone()
                };
                let p = V2::new(self.cur.x.clone(), y);
                self.line_to(p, at)?;
            }
            b'C' => {
                let c1 = self.point(rel, arg(0)?, arg(1)?);
                let c2 = self.point(rel, arg(2)?, arg(3)?);
                let p = self.point(rel, arg(4)?, arg(5)?);
                self.push(vec![self.cur.clone(), c1, c2.clone(), p.clone()], at)?;
                self.cur = p;
                cubic = Some(c2);
            }
            b'S' => {
                let c1 = self.reflect(&self.last_cubic);
                let c2 = self.point(rel, arg(0)?, arg(1)?);
                let p = self.point(rel, arg(2)?, arg(3)?);
                self.push(vec![self.cur.clone(), c1, c2.clone(), p.clone()], at)?;
                self.cur = p;
                cubic = Some(c2);
            }
            b'Q' => {
                let c = self.point(rel, arg(0)?, arg(1)?);
                let p = self.point(rel, arg(2)?, arg(3)?);
                self.push(vec![self.cur.clone(), c.clone(), p.clone()], at)?;
                self.cur = p;
                quad = Some(c);
            }
            b'T' => {
                let c = self.reflect(&self.last_quad);
                let p = self.point(rel, arg(0)?, arg(1)?);
                self.push(vec![self.cur.clone(), c.clone(), p.clone()], at)?;
                self.cur = p;
                quad = Some(c);
            }
            b'A' => {
                // (an arc resets what S and T reflect: neither `cubic` nor `quad`)
                let p = self.point(rel, arg(5)?, arg(6)?);
                let (large, sweep) = (
                    !num_traits::Zero::is_zero(arg(3)?),
                    !num_traits::Zero::is_zero(arg(4)?),
                );
                self.arc_to([arg(0)?, arg(1)?, arg(2)?], (large, sweep), p, at)?;
            }
            _ => return Err(self.err(at, format!("unknown command {:?}", cmd as char))),
        }
        self.last_cubic = cubic;
        self.last_quad = quad;
        Ok(())
    }

    /// An elliptical arc (`rx`, `ry`, `x-axis-rotation`; `large-arc-flag`,
    /// `sweep-flag`) from the current point to `p`: nothing, a line, or cubic
    /// pieces within a certified bound, reported.
    fn arc_to(
        &mut self,
        [rx, ry, rotation]: [&Rational; 3],
        (large, sweep): (bool, bool),
        p: V2<Rational>,
        at: usize,
    ) -> Result<(), CurveParseError> {
        let arc = svg_arc(&self.cur, rx, ry, rotation, large, sweep, &p)
            .map_err(|reason| self.err(at, reason))?;
        match arc {
            SvgArc::Omitted => {}
            SvgArc::Line => self.line_to(p.clone(), at)?,
            SvgArc::Cubics { pieces, bound } => {
                let (n, first) = (pieces.len(), self.out.len());
                for b in pieces {
                    self.push_bezier(b, at)?;
                }
                // the arc exactly, when its (pre-image) centre is rational
                let exact =
                    svg_exact_arc(&self.cur, &p, [rx, ry, rotation], large, sweep).map(|arc| {
                        ExactElement {
                            first,
                            count: n,
                            pieces: vec![arc],
                        }
                    });
                self.arc_ranges.push((first, n));
                if exact.is_none() && num_traits::Signed::abs(rx) == num_traits::Signed::abs(ry) {
                    self.pending.push(Pending {
                        element: self.approx.elements.len(),
                        first,
                        count: n,
                        p0: self.cur.clone(),
                        p1: p.clone(),
                        r: rx.clone(),
                        large,
                        sweep,
                    });
                }
                self.approx.push(ApproxElement {
                    kind: ApproxKind::Arc,
                    at: format!("byte {at}"),
                    pieces: n,
                    bound,
                    detail: String::new(),
                    exact,
                    near: None,
                });
            }
        }
        self.cur = p;
        Ok(())
    }

    /// The reflection of `ctrl` about the current point, or the current
    /// point when the previous segment was of another kind.
    fn reflect(&self, ctrl: &Option<V2<Rational>>) -> V2<Rational> {
        match ctrl {
            Some(c) => self.cur.add(&self.cur.sub(c)),
            None => self.cur.clone(),
        }
    }

    fn line_to(&mut self, p: V2<Rational>, at: usize) -> Result<(), CurveParseError> {
        self.push(vec![self.cur.clone(), p.clone()], at)?;
        self.cur = p;
        Ok(())
    }

    fn close(&mut self, at: usize) -> Result<(), CurveParseError> {
        if self.cur != self.start {
            let (cur, start) = (self.cur.clone(), self.start.clone());
            self.push(vec![cur, start], at)?;
        } else if self.out.len() == self.subpath_first {
            // `M x y z`: a zero-length closed subpath, a point piece (a dot
            // that round caps draw, SVG 2: `lncert::shape::split_dots`)
            let p = self.start.clone();
            self.push(vec![p.clone(), p], at)?;
        }
        self.cur = self.start.clone();
        self.last_cubic = None;
        self.last_quad = None;
        Ok(())
    }

    /// Reads and applies the parameter sets of the command `c` read at `at`:
    /// the first, then its implicit repetitions while a number follows.
    fn segments(&mut self, c: u8, at: usize) -> Result<(), CurveParseError> {
        let mut repeat = false;
        loop {
            let seg_at = self.pos;
            let vals = self.read_params(c, !repeat)?;
            self.apply(c, &vals, repeat, if repeat { seg_at } else { at })?;
            repeat = true;
            self.skip_wsp();
            if self.peek() == Some(b',') {
                let comma = self.pos;
                self.pos += 1;
                self.skip_wsp();
                if !self.peek().is_some_and(is_number_start) {
                    return Err(self.err(
                        comma,
                        format!(
                            "a comma must be followed by a number, found {}",
                            self.char_at(self.pos)
                        ),
                    ));
                }
            }
            if !self.peek().is_some_and(is_number_start) {
                return Ok(());
            }
        }
    }

    fn run(mut self) -> Result<(Vec<Bezier<Rational>>, InputApprox), CurveParseError> {
        if self.bytes.len() > MAX_SVG_BYTES {
            return Err(CurveParseError::TooLarge {
                what: format!("the SVG path data ({} bytes)", self.bytes.len()),
                limit: MAX_SVG_BYTES,
            });
        }
        self.skip_wsp();
        if self.pos >= self.bytes.len() {
            return Err(CurveParseError::Empty {
                what: "the SVG path data".to_string(),
            });
        }
        let mut seen_move = false;
        while let Some(c) = self.peek() {
            let at = self.pos;
            if !c.is_ascii_alphabetic() {
                let reason = if seen_move {
                    format!("expected a command letter, found {}", self.char_at(at))
                } else {
                    format!(
                        "path data must begin with a moveto command (M or m), found {}",
                        self.char_at(at)
                    )
                };
                return Err(self.err(at, reason));
            }
            self.pos += 1;
            match c {
                b'M' | b'm' | b'L' | b'l' | b'H' | b'h' | b'V' | b'v' | b'C' | b'c' | b'S'
                | b's' | b'Q' | b'q' | b'T' | b't' | b'A' | b'a' | b'Z' | b'z' => {}
                _ => {
                    return Err(self.err(at, format!("unknown command {:?}", c as char)));
                }
            }
            if !seen_move && !matches!(c, b'M' | b'm') {
                return Err(self.err(
                    at,
                    format!(
                        "drawing command {:?} before any moveto: path data must begin with M or m",
                        c as char
                    ),
                ));
            }
            seen_move = true;
            if matches!(c, b'Z' | b'z') {
                self.close(at)?;
                self.skip_wsp();
                continue;
            }
            self.segments(c, at)?;
        }
        if self.out.is_empty() {
            return Err(CurveParseError::Empty {
                what: "the SVG path data (it has only moveto commands)".to_string(),
            });
        }
        let layout = Layout {
            subpath_starts: &self.subpath_starts,
            arc_ranges: &self.arc_ranges,
        };
        attach_near(&self.out, &mut self.approx, &self.pending, &layout);
        Ok((self.out, self.approx))
    }
}

fn zero() -> Rational {
    Rational::from_integer(0.into())
}

/// Reads SVG path data (`M x y C ...`) exactly: one Bézier curve per drawing
/// segment (lines of degree 1, `Q`/`T` of degree 2, `C`/`S` of degree 3, a
/// closing line for `Z` when needed). Arcs `A`/`a` are *approximated* by
/// cubic pieces within a certified bound, and this function drops the report
/// of what was approximated: [`parse_svg_path_reported`] returns it.
///
/// # Examples
/// ```
/// use lncert::shape::parse_svg_path;
/// use lncert::scalar::parse_rational;
/// let c = parse_svg_path("M 0 0 C 1 2 3 4 5 6 S 7 8 9 10").unwrap();
/// assert_eq!(c.len(), 2);
/// // The S segment's first control point reflects (3, 4) about (5, 6).
/// assert_eq!(c[1].points()[1].x, parse_rational("7").unwrap());
///
/// let square = parse_svg_path("m 1 1 h 0.1 v 0.1 h -0.1 z").unwrap();
/// assert_eq!(square.len(), 4);
/// assert_eq!(square[0].points()[1].x, parse_rational("11/10").unwrap());
///
/// // a half circle: cubic pieces from (0, 0) to (2, 0), exactly
/// let arc = parse_svg_path("M 0 0 A 1 1 0 0 1 2 0").unwrap();
/// assert_eq!(arc[0].points()[0].x, parse_rational("0").unwrap());
/// assert_eq!(arc.last().unwrap().points()[3].x, parse_rational("2").unwrap());
/// ```
pub fn parse_svg_path(d: &str) -> Result<Vec<Bezier<Rational>>, CurveParseError> {
    parse_svg_path_reported(d).map(|(pieces, _)| pieces)
}

/// [`parse_svg_path`], with the list of the arcs it approximated (each named
/// by the byte offset of its command, with the certified Hausdorff bound of
/// its cubic pieces from the exact arc).
///
/// # Examples
/// ```
/// use lncert::shape::parse_svg_path_reported;
/// let (pieces, approx) =
///     parse_svg_path_reported("M 0 0 L 1 0 A 1 1 0 0 1 3 0 a 1 2 30 1 0 1 1").unwrap();
/// assert_eq!(approx.elements.len(), 2);
/// assert_eq!(approx.elements[0].at, "byte 12");
/// assert_eq!(1 + approx.pieces(), pieces.len());
/// assert!(approx.elements[0].bound <= 1e-7);
/// ```
pub fn parse_svg_path_reported(
    d: &str,
) -> Result<(Vec<Bezier<Rational>>, InputApprox), CurveParseError> {
    SvgParser::new(d).run()
}

/// Reads a list of numbers in SVG syntax (separated by whitespace and/or one
/// comma), each exactly: the arguments of an SVG `transform` function.
pub(crate) fn svg_number_list(text: &str) -> Result<Vec<Rational>, CurveParseError> {
    let mut p = SvgParser::new(text);
    let mut out = Vec::new();
    loop {
        p.skip_wsp();
        if !out.is_empty() && p.peek() == Some(b',') {
            p.pos += 1;
            p.skip_wsp();
        }
        if p.peek().is_none() {
            return Ok(out);
        }
        out.push(p.number()?);
    }
}
