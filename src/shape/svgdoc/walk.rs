//! The document walk: the readers of whole documents, the inherited style
//! and transforms, `<use>` instances, and each drawn element's mapping.

use super::elements::{coordinate, element_pieces};
use super::transform::{
    displacement, parse_transform, point, translation, Affine, Factor, FactorApprox,
};
use super::{err, CurveParseError, SvgElement, MAX_DOCUMENT_BYTES, MAX_USE_DEPTH};
use crate::curve::Bezier;
use crate::scalar::Rational;
use crate::shape::io::{svg_number_list, MAX_SEGMENTS};
use crate::shape::svgarc::{ApproxElement, InputApprox, NearElement};
use num_traits::{One, Signed, Zero};

/// Most element visits of a document (`<use>` instances count every time).
const MAX_VISITS: usize = 1_000_000;

/// The elements whose content is not rendered.
const NOT_RENDERED: [&str; 6] = ["defs", "clipPath", "mask", "symbol", "marker", "pattern"];

/// Every rendered shape of an SVG document, transformed to the document's
/// user coordinates, as Bézier pieces in document order. Errors name the
/// element (`svg/g[1]/path[0]`) and the attribute. Arcs, circles, ellipses
/// and rounded rectangles are approximated within a certified bound, and
/// this function drops the report of what was approximated:
/// [`parse_svg_document_reported`] returns it.
pub fn parse_svg_document(text: &str) -> Result<Vec<Bezier<Rational>>, CurveParseError> {
    parse_svg_document_reported(text).map(|(pieces, _)| pieces)
}

/// [`parse_svg_document`], with the list of the approximated elements, each
/// with its certified Hausdorff bound in the document's user coordinates
/// (the transforms' norms applied, irrational rotations' displacement added).
pub fn parse_svg_document_reported(
    text: &str,
) -> Result<(Vec<Bezier<Rational>>, InputApprox), CurveParseError> {
    let elements = parse_svg_document_elements(text)?;
    let mut out = Vec::new();
    let mut approx = InputApprox::default();
    for mut e in elements {
        if let Some(p) = e.dots.first() {
            return Err(err(
                &e.at,
                format!(
                    "a zero-length subpath (a dot) at ({}, {}): one curve has no place for a point; dots are read per element (parse_svg_document_elements; `lncert stroke DOC.svg` without --pen strokes them as disks)",
                    p.x,
                    p.y
                ),
            ));
        }
        e.approx.shift(out.len());
        out.extend(e.pieces);
        approx.extend_scaled(e.approx, "", 1.0);
    }
    Ok((out, approx))
}

/// The drawn elements of an SVG document, each with its pieces, what was
/// approximated, and its stroke (`stroke`, `stroke-width`, from attributes,
/// `style` and the ancestors). Skipped: `display="none"` subtrees (attribute
/// or `style`), `visibility="hidden"`/`collapse` elements (a descendant may
/// set `visible` again), the content of `<defs>`, `<symbol>`, `<clipPath>`,
/// `<mask>`, `<marker>`, `<pattern>` — drawn only through `<use>`, whose
/// `href`/`xlink:href` (`#id`) is instanced under the `<use>`'s transform and
/// `translate(x, y)`, inheriting its style. A `<use>` cycle, nesting deeper
/// than [`MAX_USE_DEPTH`], a missing id or a `<symbol>` with a `viewBox`
/// (not read) is an error naming the `<use>`.
///
/// # Examples
/// ```
/// use lncert::shape::parse_svg_document_elements;
/// let doc = r##"<svg stroke="black" stroke-width="2">
///   <defs><path id="a" d="M 0 0 L 1 0"/></defs>
///   <use href="#a" x="5"/>
///   <g style="stroke-width: 4"><use href="#a" y="1" stroke="none"/></g>
///   <line x2="1" display="none"/>
/// </svg>"##;
/// let e = parse_svg_document_elements(doc).unwrap();
/// assert_eq!(e.len(), 2);
/// assert_eq!(e[0].at, "svg/use[0]/#a");
/// let q = |x: i64| lncert::Rational::from_integer(x.into());
/// assert_eq!(e[0].pieces[0].points()[0].x, q(5));
/// assert!(e[0].stroked && !e[1].stroked);
/// assert_eq!(e[1].pen_radius, Ok(q(2)));
/// ```
pub fn parse_svg_document_elements(text: &str) -> Result<Vec<SvgElement>, CurveParseError> {
    if text.len() > MAX_DOCUMENT_BYTES {
        return Err(CurveParseError::TooLarge {
            what: "the SVG document (bytes)".to_string(),
            limit: MAX_DOCUMENT_BYTES,
        });
    }
    let doc = roxmltree::Document::parse(text)
        .map_err(|e| err("(document)", format!("not a well-formed XML document: {e}")))?;
    let root = doc.root_element();
    if root.tag_name().name() != "svg" {
        return Err(err(
            "(document)",
            format!(
                "the root element is <{}>, not <svg>",
                root.tag_name().name()
            ),
        ));
    }
    let mut ids = std::collections::HashMap::new();
    for n in doc.descendants().filter(|n| n.is_element()) {
        if let Some(id) = n.attribute("id") {
            ids.entry(id).or_insert(n);
        }
    }
    let mut w = Walker {
        ids,
        out: Vec::new(),
        segments: 0,
        visits: 0,
        uses: Vec::new(),
    };
    let ctx = Ctx {
        factors: Vec::new(),
        m: Affine::identity(),
        stroke: false,
        stroke_width: Rational::one(),
        visible: true,
    };
    w.walk(root, "svg".to_string(), &ctx)?;
    let draws = |e: &SvgElement| !e.pieces.is_empty() || !e.dots.is_empty();
    if !w.out.iter().any(draws) {
        return Err(CurveParseError::Empty {
            what: "the SVG document".to_string(),
        });
    }
    w.out.retain(draws);
    Ok(w.out)
}

/// What an element inherits: the transforms above it and the style.
#[derive(Clone, Debug)]
struct Ctx {
    factors: Vec<Factor>,
    m: Affine,
    stroke: bool,
    stroke_width: Rational,
    visible: bool,
}

struct Walker<'a, 'input> {
    ids: std::collections::HashMap<&'a str, roxmltree::Node<'a, 'input>>,
    out: Vec<SvgElement>,
    segments: usize,
    visits: usize,
    uses: Vec<String>,
}

/// A presentation property: the `style` attribute's declaration (the last
/// one) over the attribute; `inherit` (or absent) is `None`.
fn property<'a>(node: roxmltree::Node<'a, '_>, name: &str) -> Option<&'a str> {
    let from_style = node.attribute("style").and_then(|st| {
        st.split(';')
            .filter_map(|decl| decl.split_once(':'))
            .filter(|(k, _)| k.trim() == name)
            .map(|(_, v)| v.trim().trim_end_matches("!important").trim())
            .next_back()
    });
    from_style
        .or_else(|| node.attribute(name).map(str::trim))
        .filter(|v| *v != "inherit")
}

impl<'a, 'input> Walker<'a, 'input> {
    fn walk(
        &mut self,
        node: roxmltree::Node<'a, 'input>,
        at: String,
        parent: &Ctx,
    ) -> Result<(), CurveParseError> {
        self.visits += 1;
        if self.visits > MAX_VISITS {
            return Err(CurveParseError::TooLarge {
                what: "element visits in the SVG document (<use> instances included)".to_string(),
                limit: MAX_VISITS,
            });
        }
        if property(node, "display") == Some("none") {
            return Ok(());
        }
        let mut ctx = parent.clone();
        if let Some(t) = node.attribute("transform") {
            for f in parse_transform(t, &format!("{at}.transform"))? {
                ctx.m = ctx.m.then_inner(&f.m);
                ctx.factors.push(f);
            }
        }
        if let Some(v) = property(node, "stroke") {
            ctx.stroke = v != "none";
        }
        if let Some(v) = property(node, "stroke-width") {
            let w = svg_number_list(v)
                .ok()
                .filter(|xs| xs.len() == 1)
                .map(|mut xs| xs.remove(0))
                .ok_or_else(|| {
                    err(
                        format!("{at}.stroke-width"),
                        format!("{v:?} is not a plain number (units such as px or % are not read)"),
                    )
                })?;
            if w.is_negative() {
                return Err(err(format!("{at}.stroke-width"), "must be ≥ 0"));
            }
            ctx.stroke_width = w;
        }
        if let Some(v) = property(node, "visibility") {
            ctx.visible = v == "visible";
        }
        if node.tag_name().name() == "use" {
            return self.instance(node, at, ctx);
        }
        if let Some((pieces, a)) = element_pieces(node, &at)? {
            if ctx.visible && !pieces.is_empty() {
                self.draw(at.clone(), &ctx, pieces, a)?;
            }
        }
        let mut counts: std::collections::HashMap<&str, usize> = Default::default();
        for child in node.children().filter(|c| c.is_element()) {
            let name = child.tag_name().name();
            let i = counts.entry(name).or_insert(0);
            let child_at = format!("{at}/{name}[{i}]");
            *i += 1;
            if NOT_RENDERED.contains(&name) {
                continue;
            }
            self.walk(child, child_at, &ctx)?;
        }
        Ok(())
    }

    /// `<use>`: the referenced element under `translate(x, y)`.
    fn instance(
        &mut self,
        node: roxmltree::Node<'a, 'input>,
        at: String,
        mut ctx: Ctx,
    ) -> Result<(), CurveParseError> {
        let href = node
            .attribute("href")
            .or_else(|| node.attribute(("http://www.w3.org/1999/xlink", "href")))
            .ok_or_else(|| err(format!("{at}.href"), "a <use> without href"))?;
        let id = href.trim().strip_prefix('#').ok_or_else(|| {
            err(
                format!("{at}.href"),
                format!("{href:?}: only references into the document (#id) are read"),
            )
        })?;
        let target = *self
            .ids
            .get(id)
            .ok_or_else(|| err(format!("{at}.href"), format!("no element has id {id:?}")))?;
        if self.uses.iter().any(|u| u == id) {
            return Err(err(
                format!("{at}.href"),
                format!("#{id} refers to itself through <use> (a cycle)"),
            ));
        }
        if self.uses.len() >= MAX_USE_DEPTH {
            return Err(err(
                format!("{at}.href"),
                format!("<use> nested deeper than {MAX_USE_DEPTH}"),
            ));
        }
        if target.tag_name().name() == "symbol" && target.attribute("viewBox").is_some() {
            return Err(err(
                format!("{at}.href"),
                format!("#{id} is a <symbol> with a viewBox (its viewport scaling is not read)"),
            ));
        }
        let (x, y) = (coordinate(node, "x", &at)?, coordinate(node, "y", &at)?);
        if !(x.is_zero() && y.is_zero()) {
            let t = translation(&x, &y);
            ctx.m = ctx.m.then_inner(&t);
            ctx.factors.push(Factor { m: t, approx: None });
        }
        self.uses.push(id.to_string());
        let r = self.walk(target, format!("{at}/#{id}"), &ctx);
        self.uses.pop();
        r
    }

    fn draw(
        &mut self,
        at: String,
        ctx: &Ctx,
        pieces: Vec<Bezier<Rational>>,
        a: InputApprox,
    ) -> Result<(), CurveParseError> {
        let mut approx = InputApprox::default();
        let own = a.bound();
        let scale = ctx.m.similarity_scale();
        let mut a = a;
        for e in &mut a.elements {
            // arcs stay exact under rational affine maps (circles stay circles
            // under similarities with a rational scale)
            e.exact = e.exact.as_ref().map(|x| x.mapped(&ctx.m.0, scale.as_ref()));
            // a near element is kept only under an exact map (its bound is
            // then scaled with the element's, below)
            e.near = if ctx.factors.iter().any(|f| f.approx.is_some()) {
                None
            } else {
                e.near.take().map(|n| NearElement {
                    element: n.element.mapped(&ctx.m.0, scale.as_ref()),
                    bound: n.bound,
                })
            };
        }
        if !a.is_empty() {
            approx.extend_scaled(a, "", ctx.m.norm_sup());
        }
        let inexact: Vec<&FactorApprox> = ctx
            .factors
            .iter()
            .filter_map(|f| f.approx.as_ref())
            .collect();
        if let Some(first) = inexact.first() {
            // d_H(M E, M′ B) ≤ sup_E |M − M′| + ‖M′‖ d_H(E, B)
            let delta = displacement(&ctx.factors, &pieces, own);
            for e in &mut approx.elements {
                e.bound = (point(e.bound) + point(delta)).sup();
            }
            approx.push(ApproxElement {
                kind: first.kind,
                at: at.clone(),
                pieces: pieces.len(),
                bound: delta,
                exact: None,
                near: None,
                detail: inexact
                    .iter()
                    .map(|f| f.detail.clone())
                    .collect::<Vec<_>>()
                    .join("; "),
            });
        }
        self.segments += pieces.len();
        if self.segments > MAX_SEGMENTS {
            return Err(CurveParseError::TooLarge {
                what: "segments in the SVG document".to_string(),
                limit: MAX_SEGMENTS,
            });
        }
        let pieces: Vec<Bezier<Rational>> = pieces
            .iter()
            .map(|b| Bezier::new(b.points().iter().map(|p| ctx.m.apply(p)).collect()))
            .collect();
        let (pieces, dots) = crate::shape::split_dots(pieces, &mut approx);
        let two = Rational::from_integer(2.into());
        let pen_radius = match scale {
            Some(k) => Ok(&ctx.stroke_width / &two * k),
            None => Err(format!(
                "{at}: its transform is not a similarity with a rational scale (the pen of its stroke-width would be an ellipse)"
            )),
        };
        self.out.push(SvgElement {
            at,
            pieces,
            dots,
            approx,
            stroked: ctx.stroke,
            stroke_width: ctx.stroke_width.clone(),
            pen_radius,
        });
        Ok(())
    }
}
