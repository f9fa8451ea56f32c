//! Whole SVG documents: every rendered `<path>`, `<line>`, `<polyline>`,
//! `<polygon>`, `<rect>`, `<circle>` and `<ellipse>`, with the `transform`s
//! of the element and its ancestors applied, `<use>` instances resolved, and
//! each element's stroke ([`parse_svg_document_elements`]).
//!
//! The XML is read by roxmltree; the path data and every number (coordinates,
//! transform arguments) by lncert's own exact reader, never through `f64`: an
//! affine map of a Bézier curve is the Bézier curve of the mapped control
//! points, so exact transforms round nothing. Transforms: `matrix`,
//! `translate`, `scale`, `rotate` and `skewX`/`skewY`. A rotation by a
//! multiple of 90° is exact; any other angle has an irrational cosine or sine
//! (or is given in degrees that are not), and is replaced by the **exactly
//! rational rotation** of the point `((1 − u²)/(1 + u²), 2u/(1 + u²))` of the
//! unit circle, `u` a continued-fraction convergent of `tan(θ/2)` (after exact
//! quarter turns), with `‖R_θ − R′‖₂ ≤ 10⁻¹²` certified (`sin`/`cos` enclosed
//! from an enclosure of `π`). Skews likewise use a rational `t` with
//! `|tan θ − t| ≤ 10⁻¹² max(1, |t|)` (90° is refused). The element is then
//! mapped exactly by that rational matrix, and the report
//! ([`ApproxKind::Rotation`], [`ApproxKind::Skew`]) says which matrix and the
//! certified displacement `sup |M(p) − M′(p)|` over the element (`err · |p −
//! centre|` summed over the approximated factors, times the Lipschitz bound
//! of the transforms above them; see [`parse_svg_document_elements`]).
//!
//! Elliptical arcs are *approximated* by cubic pieces with a certified
//! Hausdorff bound (see [`super::svgarc`]), reported per element by
//! [`parse_svg_document_reported`]: `A`/`a` in path data; `<circle cx cy r>`
//! and `<ellipse cx cy rx ry>` (a missing or `auto` `rx` or `ry` is the other
//! one, as in SVG 2; a zero radius draws nothing) as two half arcs, starting at
//! `(cx + rx, cy)` and running counter-clockwise in the user coordinate
//! system (from +x towards +y: clockwise on a y-down screen), as SVG 2 draws
//! them; rounded `<rect rx ry>` (one given is both, each clamped to half the
//! side) as SVG 2's path: lines and four quarter arcs, from `(x + rx, y)`.
//! The pieces are mapped through the transforms exactly, and each bound is
//! multiplied by an upper bound of the transform's norm `‖T‖₂` (its largest
//! singular value, enclosed from the exact matrix), plus the displacement of
//! an approximated rotation or skew above the element.
//!
//! Refused with an error naming the element (nothing is dropped silently):
//! `<text>`, `<image>`, `<foreignObject>`, negative radii, and unit
//! suffixes on coordinates. Elements inside `<defs>`, `<clipPath>`, `<mask>`,
//! `<symbol>`, `<marker>` and `<pattern>` are not rendered, and are skipped
//! (a `<use>` draws them); so are `display="none"` subtrees and
//! `visibility="hidden"` elements.
//!
//! # Examples
//! ```
//! use lncert::shape::parse_svg_document;
//! let doc = r#"<svg xmlns="http://www.w3.org/2000/svg">
//!   <g transform="translate(10, 0) scale(2)">
//!     <path d="M 0 0 C 1 1 2 1 3 0"/>
//!   </g>
//!   <line x1="0" y1="0" x2="1" y2="0.1"/>
//! </svg>"#;
//! let pieces = parse_svg_document(doc).unwrap();
//! assert_eq!(pieces.len(), 2);
//! // (3, 0) scaled by 2, then moved by 10: (16, 0), exactly
//! assert_eq!(pieces[0].points()[3].x, lncert::scalar::parse_rational("16").unwrap());
//! // a circle: two half arcs of cubic pieces, certified within 1e-7 of r = 1
//! let (circle, approx) = lncert::shape::parse_svg_document_reported(
//!     r#"<svg><circle r="1"/></svg>"#).unwrap();
//! assert_eq!(circle[0].points()[0].x, lncert::scalar::parse_rational("1").unwrap());
//! assert!(approx.bound() <= 1e-7);
//! assert!(parse_svg_document(r#"<svg><text>1</text></svg>"#).is_err());
//! ```

use super::io::{parse_svg_path_reported, svg_number_list, CurveParseError, MAX_SEGMENTS};
use super::svgarc::{axis_arc, format_up, ApproxElement, ApproxKind, InputApprox};
use crate::curve::{Bezier, V2};
use crate::scalar::{interval_from_rational, rational_from_f64, Interval, Rational};
use num_traits::{One, Signed, Zero};

/// Largest SVG document read, in bytes.
pub const MAX_DOCUMENT_BYTES: usize = 16 << 20;

/// An affine map `(x, y) ↦ (a x + c y + e, b x + d y + f)`, SVG's
/// `matrix(a b c d e f)`.
#[derive(Clone, Debug, PartialEq)]
struct Affine([Rational; 6]);

impl Affine {
    fn identity() -> Self {
        let (o, z) = (Rational::one(), Rational::zero());
        Affine([o.clone(), z.clone(), z.clone(), o, z.clone(), z])
    }
    /// `self ∘ other` (apply `other` first).
    fn then_inner(&self, o: &Affine) -> Affine {
        let [a, b, c, d, e, f] = &self.0;
        let [a2, b2, c2, d2, e2, f2] = &o.0;
        Affine([
            a * a2 + c * b2,
            b * a2 + d * b2,
            a * c2 + c * d2,
            b * c2 + d * d2,
            a * e2 + c * f2 + e,
            b * e2 + d * f2 + f,
        ])
    }
    fn apply(&self, p: &V2<Rational>) -> V2<Rational> {
        let [a, b, c, d, e, f] = &self.0;
        V2::new(a * &p.x + c * &p.y + e, b * &p.x + d * &p.y + f)
    }
    /// An upper bound of `‖L‖₂` for the linear part `L`, its largest singular
    /// value `√((s + √(s² − 4 det²))/2)`, `s = a² + b² + c² + d²`, enclosed
    /// from the exact `s` and `s² − 4 det² ≥ 0`: `d_H(T X, T Y) ≤ ‖L‖₂ d_H(X, Y)`.
    fn norm_sup(&self) -> f64 {
        let [a, b, c, d, _, _] = &self.0;
        let s = a * a + b * b + c * c + d * d;
        let det = a * d - b * c;
        let four = Rational::from_integer(4.into());
        if s == Rational::one() + Rational::one() && det.abs() == Rational::one() {
            return 1.0; // a rotation or reflection by a multiple of 90°
        }
        let disc = &s * &s - four * &det * &det;
        let half = Interval::try_from((0.5, 0.5)).unwrap_or(Interval::ENTIRE);
        let sigma2 = (interval_from_rational(&s) + interval_from_rational(&disc).sqrt()) * half;
        let n = sigma2.sqrt();
        if n.is_empty() {
            f64::INFINITY
        } else {
            n.sup()
        }
    }
}

fn err(field: impl Into<String>, reason: impl Into<String>) -> CurveParseError {
    CurveParseError::Field {
        field: field.into(),
        reason: reason.into(),
    }
}

/// Largest error allowed of the rational rotation or skew that replaces an
/// irrational one: `‖R_θ − R′‖₂` (the chord between the two unit vectors,
/// about the angle error) or `|tan θ − t|` relative to `max(1, |t|)`.
pub const TRANSFORM_TARGET: f64 = 1e-12;

/// Largest nesting of `<use>` instances.
pub const MAX_USE_DEPTH: usize = 16;

/// Most element visits of a document (`<use>` instances count every time).
const MAX_VISITS: usize = 1_000_000;

/// `(cos, sin)` of a multiple of 90°, exactly; `None` for any other angle.
fn quarter_turn(deg: &Rational) -> Option<(Rational, Rational)> {
    let q = deg / Rational::from_integer(90.into());
    if !q.is_integer() {
        return None;
    }
    let four = num_bigint::BigInt::from(4);
    let k: num_bigint::BigInt = (q.to_integer() % &four + &four) % &four;
    let (o, z) = (Rational::one(), Rational::zero());
    Some(match k.to_string().as_str() {
        "0" => (o, z),
        "1" => (z, o),
        "2" => (-o, z),
        _ => (z, -o),
    })
}

/// The convergent of `x`'s continued fraction with the smallest denominator
/// within `tol` of `x` (`x` itself when none is closer first).
fn best_rational(x: &Rational, tol: &Rational) -> Rational {
    use num_bigint::BigInt;
    let (mut h0, mut h1) = (BigInt::zero(), BigInt::one());
    let (mut k0, mut k1) = (BigInt::one(), BigInt::zero());
    let mut rest = x.clone();
    for _ in 0..200 {
        let a = rest.floor().to_integer();
        let h2 = &a * &h1 + &h0;
        let k2 = &a * &k1 + &k0;
        (h0, h1, k0, k1) = (h1, h2, k1, k2);
        let c = Rational::new(h1.clone(), k1.clone());
        let frac = &rest - Rational::from_integer(a);
        if (&c - x).abs() <= *tol || frac.is_zero() {
            return c;
        }
        rest = frac.recip();
    }
    x.clone()
}

/// An irrational `rotate(θ)`: `θ = 90° k + r` with `|r| ≤ 45°`, the quarter
/// turns exact, `r` replaced by the rotation of the rational point
/// `((1 − u²)/(1 + u²), 2u/(1 + u²))` of the unit circle, `u ≈ tan(r/2)` (a
/// continued-fraction convergent). Returns `(cos, sin)` of the rotation used
/// and a certified upper bound of `‖R_θ − R′‖₂ = |(cos θ, sin θ) − (cos′,
/// sin′)|` (the difference of two rotations is a scaled rotation).
fn rational_rotation(deg: &Rational) -> Result<(Rational, Rational, f64), String> {
    let ninety = Rational::from_integer(90.into());
    let half = Rational::new(1.into(), 2.into());
    let k = (deg / &ninety + half).floor();
    let r = deg - &k * &ninety;
    let (qc, qs) = quarter_turn(&(&k * &ninety)).ok_or("a quarter turn")?;
    let rad = to_f64(&r) * std::f64::consts::PI / 180.0;
    let u_f = (rad / 2.0).tan();
    let u = rational_from_f64(u_f).ok_or("the angle is not finite")?;
    let u = best_rational(&u, &Rational::new(1.into(), 40_000_000_000_000i64.into()));
    let (one, two) = (Rational::one(), Rational::from_integer(2.into()));
    let den = &one + &u * &u;
    let (c, s) = ((&one - &u * &u) / &den, &two * &u / &den);
    // certify: θ_r enclosed from the exact r and an enclosure of π
    let theta = interval_from_rational(&r) * Interval::PI / point(180.0);
    let (si, ci) = crate::scalar::sin_cos_enclosure(theta);
    let (dc, ds) = (
        ci - interval_from_rational(&c),
        si - interval_from_rational(&s),
    );
    let err = (dc * dc + ds * ds).sqrt().sup();
    if err.is_nan() || err > TRANSFORM_TARGET {
        return Err(format!(
            "the rational rotation found is not within {TRANSFORM_TARGET:e} (certified {err:e})"
        ));
    }
    // the quarter turns, exactly: (qc + i qs)(c + i s)
    Ok((&qc * &c - &qs * &s, &qs * &c + &qc * &s, err))
}

/// An irrational `tan θ` (`skewX`/`skewY`): a rational `t` and a certified
/// bound of `|tan θ − t|`; an error at `θ ≡ 90°` (mod 180°).
fn rational_tan(deg: &Rational) -> Result<(Rational, f64), String> {
    let d180 = Rational::from_integer(180.into());
    let half = Rational::new(1.into(), 2.into());
    let r = deg - (deg / &d180 + half).floor() * &d180; // in [−90°, 90°)
    if r.abs() == Rational::from_integer(90.into()) {
        return Err("tan(90°) is infinite".to_string());
    }
    // the rational tangents of rational degrees: 0 and ±1 (tan 0°, ±45°)
    for (deg, t) in [(0, 0), (45, 1), (-45, -1)] {
        if r == Rational::from_integer(deg.into()) {
            return Ok((Rational::from_integer(t.into()), 0.0));
        }
    }
    let t_f = (to_f64(&r) * std::f64::consts::PI / 180.0).tan();
    let t = rational_from_f64(t_f).ok_or("tan θ is not finite")?;
    let scale = Rational::one().max(t.abs());
    let t = best_rational(
        &t,
        &(scale.clone() * Rational::new(1.into(), 40_000_000_000_000i64.into())),
    );
    let theta = interval_from_rational(&r) * Interval::PI / point(180.0);
    let (si, ci) = crate::scalar::sin_cos_enclosure(theta);
    if ci.contains(0.0) {
        return Err("the angle is too close to 90° for tan θ to be enclosed".to_string());
    }
    let err = (si / ci - interval_from_rational(&t)).mag();
    if err.is_nan() || err > TRANSFORM_TARGET * to_f64(&scale).max(1.0) {
        return Err(format!(
            "the rational tangent found is not within {TRANSFORM_TARGET:e} (certified {err:e})"
        ));
    }
    Ok((t, err))
}

fn to_f64(r: &Rational) -> f64 {
    <Rational as crate::scalar::Scalar>::approx(r)
}

fn point(x: f64) -> Interval {
    Interval::try_from((x, x)).unwrap_or(Interval::ENTIRE)
}

/// What one factor of a transform list approximated: for every point `p`,
/// `|F(p) − F′(p)| ≤ err · |p − centre|`, `F` the exact map, `F′` the
/// rational one; `lip` bounds the exact map's Lipschitz constant.
#[derive(Clone, Debug)]
struct FactorApprox {
    kind: ApproxKind,
    err: f64,
    centre: V2<Rational>,
    lip: f64,
    detail: String,
}

/// One factor of the transforms above an element, with the rational map used.
#[derive(Clone, Debug)]
struct Factor {
    m: Affine,
    approx: Option<FactorApprox>,
}

fn translation(x: &Rational, y: &Rational) -> Affine {
    let (o, z) = (Rational::one(), Rational::zero());
    Affine([o.clone(), z.clone(), z, o, x.clone(), y.clone()])
}

/// Reads an SVG `transform` attribute into its factors (outermost first;
/// consecutive exact ones merged).
fn parse_transform(text: &str, at: &str) -> Result<Vec<Factor>, CurveParseError> {
    let mut factors: Vec<Factor> = Vec::new();
    let mut rest = text.trim();
    while !rest.is_empty() {
        let open = rest
            .find('(')
            .ok_or_else(|| err(at, format!("expected name(arguments) in {rest:?}")))?;
        let close = rest
            .find(')')
            .filter(|c| *c > open)
            .ok_or_else(|| err(at, "a transform function is not closed by ')'"))?;
        let name = rest[..open].trim().trim_start_matches(',').trim();
        let args =
            svg_number_list(&rest[open + 1..close]).map_err(|e| err(at, format!("{name}: {e}")))?;
        let (o, z) = (Rational::one(), Rational::zero());
        let mut approx = None;
        let f = match (name, args.as_slice()) {
            ("matrix", [a, b, c, d, e, f]) => Affine([
                a.clone(),
                b.clone(),
                c.clone(),
                d.clone(),
                e.clone(),
                f.clone(),
            ]),
            ("translate", [x]) => translation(x, &z),
            ("translate", [x, y]) => translation(x, y),
            ("scale", [s]) => Affine([s.clone(), z.clone(), z.clone(), s.clone(), z.clone(), z]),
            ("scale", [sx, sy]) => {
                Affine([sx.clone(), z.clone(), z.clone(), sy.clone(), z.clone(), z])
            }
            ("rotate", [a, centre @ ..]) if centre.is_empty() || centre.len() == 2 => {
                let (c, s) = match quarter_turn(a) {
                    Some(cs) => cs,
                    None => {
                        let (c, s, e) = rational_rotation(a)
                            .map_err(|reason| err(at, format!("rotate({a}): {reason}")))?;
                        let centre = match centre {
                            [cx, cy] => V2::new(cx.clone(), cy.clone()),
                            _ => V2::new(z.clone(), z.clone()),
                        };
                        approx = Some(FactorApprox {
                            kind: ApproxKind::Rotation,
                            err: e,
                            centre,
                            lip: 1.0,
                            detail: format!(
                                "rotate({a}) as cos = {c}, sin = {s}, exactly on the unit circle, ‖R − R′‖ ≤ {}",
                                format_up(e)
                            ),
                        });
                        (c, s)
                    }
                };
                let r = Affine([c.clone(), s.clone(), -s, c, z.clone(), z.clone()]);
                match centre {
                    [cx, cy] => translation(cx, cy)
                        .then_inner(&r)
                        .then_inner(&translation(&-cx.clone(), &-cy.clone())),
                    _ => r,
                }
            }
            ("skewX" | "skewY", [a]) if a.is_zero() => Affine::identity(),
            ("skewX" | "skewY", [a]) => {
                let (t, e) =
                    rational_tan(a).map_err(|reason| err(at, format!("{name}({a}): {reason}")))?;
                let m = if name == "skewX" {
                    Affine([o.clone(), z.clone(), t.clone(), o, z.clone(), z.clone()])
                } else {
                    Affine([o.clone(), t.clone(), z.clone(), o, z.clone(), z.clone()])
                };
                if e > 0.0 {
                    approx = Some(FactorApprox {
                        kind: ApproxKind::Skew,
                        err: e,
                        centre: V2::new(z.clone(), z),
                        lip: (point(m.norm_sup()) + point(e)).sup(),
                        detail: format!(
                            "{name}({a}) with tan = {t}, |tan θ − t| ≤ {}",
                            format_up(e)
                        ),
                    });
                }
                m
            }
            _ => {
                return Err(err(
                    at,
                    format!("unknown transform {name:?} with {} argument(s)", args.len()),
                ))
            }
        };
        match factors.last_mut() {
            Some(last) if last.approx.is_none() && approx.is_none() => {
                last.m = last.m.then_inner(&f);
            }
            _ => factors.push(Factor { m: f, approx }),
        }
        rest = rest[close + 1..].trim_start();
    }
    Ok(factors)
}

/// A certified upper bound of `sup |M(p) − M′(p)|` over the exact element
/// `E`, `M` the exact composition of `factors` (outermost first) and `M′` the
/// rational one, given the element's pieces `B` (in its own coordinates) and
/// `b ≥ d_H(E, B)`. With `Hᵢ` the map exact in the factors above `i` and
/// rational from `i` down, `M − M′ = Σᵢ (Hᵢ₋₁ − Hᵢ)` and
/// `|Hᵢ₋₁(p) − Hᵢ(p)| ≤ Lip(Fₖ ∘ … ∘ Fᵢ₊₁) · errᵢ · |qᵢ − cᵢ|`,
/// `qᵢ = F′ᵢ₋₁ ∘ … ∘ F′₁(p)`; `|qᵢ − cᵢ|` is at most its largest value over
/// the control points of the mapped pieces (convexity) plus `‖F′ᵢ₋₁ ⋯ F′₁‖ b`.
fn displacement(factors: &[Factor], pieces: &[Bezier<Rational>], b: f64) -> f64 {
    let up = |x: Interval| if x.is_empty() { f64::INFINITY } else { x.sup() };
    let mut pts: Vec<V2<Rational>> = pieces.iter().flat_map(|p| p.points().to_vec()).collect();
    let mut pad = point(b);
    let mut total = point(0.0);
    for (i, f) in factors.iter().enumerate().rev() {
        if let Some(a) = &f.approx {
            let mut far = point(0.0);
            let c = a.centre.map(interval_from_rational);
            for p in &pts {
                let (dx, dy) = (
                    interval_from_rational(&p.x) - c.x,
                    interval_from_rational(&p.y) - c.y,
                );
                far = far.max((dx * dx + dy * dy).sqrt());
            }
            let lip_above = factors[..i].iter().fold(point(1.0), |acc, g| {
                acc * point(g.approx.as_ref().map_or_else(|| g.m.norm_sup(), |a| a.lip))
            });
            total += lip_above * point(a.err) * (far + pad);
        }
        if i > 0 {
            pts = pts.iter().map(|p| f.m.apply(p)).collect();
            pad *= point(f.m.norm_sup());
        }
    }
    up(total)
}

/// A plain coordinate attribute (no unit suffix), exactly; a missing one is 0.
fn coordinate(node: roxmltree::Node, name: &str, at: &str) -> Result<Rational, CurveParseError> {
    match node.attribute(name) {
        None => Ok(Rational::zero()),
        Some(v) => match svg_number_list(v) {
            Ok(xs) if xs.len() == 1 => Ok(xs[0].clone()),
            _ => Err(err(
                format!("{at}.{name}"),
                format!("{v:?} is not a plain number (units such as px or % are not read)"),
            )),
        },
    }
}

fn polyline(points: &[V2<Rational>], closed: bool) -> Vec<Bezier<Rational>> {
    let mut out: Vec<Bezier<Rational>> = points
        .windows(2)
        .filter(|w| w[0] != w[1])
        .map(|w| Bezier::new(vec![w[0].clone(), w[1].clone()]))
        .collect();
    if closed {
        if let (Some(a), Some(b)) = (points.last(), points.first()) {
            if a != b {
                out.push(Bezier::new(vec![a.clone(), b.clone()]));
            }
        }
    }
    out
}

/// The elements whose content is not rendered.
const NOT_RENDERED: [&str; 6] = ["defs", "clipPath", "mask", "symbol", "marker", "pattern"];

/// A radius attribute: `None` when absent or `auto` (SVG 2), an error when
/// negative.
fn radius(
    node: roxmltree::Node,
    name: &str,
    at: &str,
) -> Result<Option<Rational>, CurveParseError> {
    match node.attribute(name) {
        None => return Ok(None),
        Some(v) if v.trim() == "auto" => return Ok(None),
        Some(_) => {}
    }
    let r = coordinate(node, name, at)?;
    if r.is_negative() {
        return Err(err(format!("{at}.{name}"), "a radius must be ≥ 0"));
    }
    Ok(Some(r))
}

/// The arcs of an axis-aligned ellipse about `c`: `(start, quarters)` runs,
/// each a run of quarter turns counter-clockwise from an axis direction.
fn ellipse_arcs(
    c: &V2<Rational>,
    rx: &Rational,
    ry: &Rational,
    runs: &[(u8, u8)],
    at: &str,
) -> Result<(Vec<Bezier<Rational>>, f64), CurveParseError> {
    let mut out = Vec::new();
    let mut bound = 0.0f64;
    for &(start, quarters) in runs {
        let (pieces, b, _) =
            axis_arc(c, rx, ry, start, quarters).map_err(|reason| err(at, reason))?;
        out.extend(pieces);
        bound = bound.max(b);
    }
    Ok((out, bound))
}

/// The shapes of one element in its own coordinates, with what was
/// approximated, or `None` for an element that draws nothing (groups,
/// metadata, …).
#[allow(clippy::type_complexity)]
fn element_pieces(
    node: roxmltree::Node,
    at: &str,
) -> Result<Option<(Vec<Bezier<Rational>>, InputApprox)>, CurveParseError> {
    let name = node.tag_name().name();
    let mut approx = InputApprox::default();
    let approximated = |approx: &mut InputApprox, kind, pieces: &[Bezier<Rational>], bound| {
        approx.push(ApproxElement {
            kind,
            at: at.to_string(),
            pieces: pieces.iter().filter(|b| b.degree() == 3).count(),
            bound,
            detail: String::new(),
        })
    };
    let pieces = match name {
        "path" => match node.attribute("d") {
            None => Vec::new(),
            Some(d) => {
                let (pieces, a) = parse_svg_path_reported(d)
                    .map_err(|e| err(format!("{at}.d"), e.to_string()))?;
                approx.extend_scaled(a, &format!("{at}.d"), 1.0);
                pieces
            }
        },
        "line" => {
            let p = |x: &str, y: &str| -> Result<V2<Rational>, CurveParseError> {
                Ok(V2::new(coordinate(node, x, at)?, coordinate(node, y, at)?))
            };
            polyline(&[p("x1", "y1")?, p("x2", "y2")?], false)
        }
        "polyline" | "polygon" => {
            let xs = svg_number_list(node.attribute("points").unwrap_or(""))
                .map_err(|e| err(format!("{at}.points"), e.to_string()))?;
            if xs.len() % 2 != 0 {
                return Err(err(format!("{at}.points"), "an odd number of coordinates"));
            }
            let pts: Vec<V2<Rational>> = xs
                .chunks(2)
                .map(|c| V2::new(c[0].clone(), c[1].clone()))
                .collect();
            polyline(&pts, name == "polygon")
        }
        "rect" => {
            let (x, y) = (coordinate(node, "x", at)?, coordinate(node, "y", at)?);
            let (w, h) = (
                coordinate(node, "width", at)?,
                coordinate(node, "height", at)?,
            );
            // SVG 2: one radius given is both; each at most half the side
            let (rx, ry) = match (radius(node, "rx", at)?, radius(node, "ry", at)?) {
                (None, None) => (Rational::zero(), Rational::zero()),
                (Some(r), None) | (None, Some(r)) => (r.clone(), r),
                (Some(rx), Some(ry)) => (rx, ry),
            };
            let two = Rational::from_integer(2.into());
            let (rx, ry) = (rx.min(w.abs() / &two), ry.min(h.abs() / &two));
            if rx.is_zero() || ry.is_zero() {
                let pts = [
                    V2::new(x.clone(), y.clone()),
                    V2::new(&x + &w, y.clone()),
                    V2::new(&x + &w, &y + &h),
                    V2::new(x, &y + &h),
                ];
                polyline(&pts, true)
            } else {
                let (x1, y1, x2, y2) = (&x + &rx, &y + &ry, &x + &w - &rx, &y + &h - &ry);
                let mut out = Vec::new();
                let mut bound = 0.0f64;
                // SVG 2's path: M (x+rx, y) H (x+w−rx) A … (x+w, y+ry) V … Z
                for (corner, start, line_to) in [
                    (V2::new(x2.clone(), y1.clone()), 3, V2::new(&x + &w, y2.clone())),
                    (V2::new(x2.clone(), y2.clone()), 0, V2::new(x1.clone(), &y + &h)),
                    (V2::new(x1.clone(), y2.clone()), 1, V2::new(x.clone(), y1.clone())),
                    (V2::new(x1.clone(), y1.clone()), 2, V2::new(x2.clone(), y.clone())),
                ] {
                    let (pieces, b, end) = axis_arc(&corner, &rx, &ry, start, 1)
                        .map_err(|reason| err(at, reason))?;
                    out.extend(pieces);
                    bound = bound.max(b);
                    if end != line_to {
                        out.push(Bezier::new(vec![end, line_to]));
                    }
                }
                // start at (x + rx, y): the last line (into it) first
                if let Some(last) = out.last().filter(|b| b.degree() == 1).cloned() {
                    out.pop();
                    out.insert(0, last);
                }
                approximated(&mut approx, ApproxKind::RoundedRect, &out, bound);
                out
            }
        }
        "circle" | "ellipse" => {
            let c = V2::new(coordinate(node, "cx", at)?, coordinate(node, "cy", at)?);
            let (rx, ry) = if name == "circle" {
                let r = radius(node, "r", at)?.unwrap_or_else(Rational::zero);
                (r.clone(), r)
            } else {
                match (radius(node, "rx", at)?, radius(node, "ry", at)?) {
                    (None, None) => (Rational::zero(), Rational::zero()),
                    (Some(r), None) | (None, Some(r)) => (r.clone(), r),
                    (Some(rx), Some(ry)) => (rx, ry),
                }
            };
            if rx.is_zero() || ry.is_zero() {
                Vec::new() // SVG: a zero radius disables rendering
            } else {
                let (pieces, bound) = ellipse_arcs(&c, &rx, &ry, &[(0, 2), (2, 2)], at)?;
                let kind = if name == "circle" {
                    ApproxKind::Circle
                } else {
                    ApproxKind::Ellipse
                };
                approximated(&mut approx, kind, &pieces, bound);
                pieces
            }
        }
        "text" | "image" | "foreignObject" => {
            return Err(err(
                at,
                format!(
                    "<{name}> is not read (only path, line, polyline, polygon, rect, circle and ellipse)"
                ),
            ))
        }
        _ => return Ok(None),
    };
    Ok(Some((pieces, approx)))
}

/// One drawn element of an SVG document, in the document's user coordinates.
#[derive(Clone, Debug, PartialEq)]
pub struct SvgElement {
    /// Where it is: `svg/g[0]/path[1]`; an instance of `<use>` is
    /// `svg/use[0]/#id` (then the referenced element's own children).
    pub at: String,
    /// Its pieces, mapped exactly by the rational transform.
    pub pieces: Vec<Bezier<Rational>>,
    /// What was approximated to get them (arcs; irrational rotations and
    /// skews above it), bounds in the document's user coordinates.
    pub approx: InputApprox,
    /// The computed `stroke` is set and not `none` (SVG's initial value is
    /// `none`: an element without a `stroke` anywhere above it is not stroked).
    pub stroked: bool,
    /// The computed `stroke-width` (inherited; default 1), in the element's
    /// own coordinates.
    pub stroke_width: Rational,
    /// Half the stroke width in the document's user coordinates — the radius
    /// of the circular pen that strokes it — or why there is no such circle
    /// (a transform that is not a similarity with a rational scale).
    pub pen_radius: Result<Rational, String>,
}

/// The exact square root of a rational, when it is one.
fn rational_sqrt(x: &Rational) -> Option<Rational> {
    if x.is_negative() {
        return None;
    }
    let (n, d) = (x.numer().sqrt(), x.denom().sqrt());
    (&n * &n == *x.numer() && &d * &d == *x.denom()).then(|| Rational::new(n, d))
}

impl Affine {
    /// The scale of the linear part when it is a similarity (rotation or
    /// reflection times a scale) with a rational scale factor.
    fn similarity_scale(&self) -> Option<Rational> {
        let [a, b, c, d, _, _] = &self.0;
        let conformal = (a == d && *b == -c.clone()) || (*a == -d.clone() && b == c);
        if !conformal {
            return None;
        }
        rational_sqrt(&(a * a + b * b))
    }
}

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
    for e in elements {
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
    if w.out.iter().all(|e| e.pieces.is_empty()) {
        return Err(CurveParseError::Empty {
            what: "the SVG document".to_string(),
        });
    }
    w.out.retain(|e| !e.pieces.is_empty());
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
        let two = Rational::from_integer(2.into());
        let pen_radius = match ctx.m.similarity_scale() {
            Some(k) => Ok(&ctx.stroke_width / &two * k),
            None => Err(format!(
                "{at}: its transform is not a similarity with a rational scale (the pen of its stroke-width would be an ellipse)"
            )),
        };
        self.out.push(SvgElement {
            at,
            pieces,
            approx,
            stroked: ctx.stroke,
            stroke_width: ctx.stroke_width.clone(),
            pen_radius,
        });
        Ok(())
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::scalar::parse_rational;

    fn q(s: &str) -> Rational {
        parse_rational(s).unwrap()
    }

    fn pts(b: &Bezier<Rational>) -> Vec<(Rational, Rational)> {
        b.points()
            .iter()
            .map(|p| (p.x.clone(), p.y.clone()))
            .collect()
    }

    /// Transforms compose as SVG says (the parent's applies last; a list
    /// applies right to left), exactly, checked against hand-computed points.
    #[test]
    fn transforms_compose_exactly() {
        let doc = r#"<svg><g transform="translate(10,0)"><g transform="scale(2 3) rotate(90)">
            <path d="M 1 0 L 0.1 2"/></g></g></svg>"#;
        let p = parse_svg_document(doc).unwrap();
        // rotate(90): (x, y) ↦ (−y, x); scale(2, 3); translate(10, 0)
        // (1, 0) → (0, 1) → (0, 3) → (10, 3); (1/10, 2) → (−2, 1/10) → (−4, 3/10) → (6, 3/10)
        assert_eq!(pts(&p[0]), vec![(q("10"), q("3")), (q("6"), q("3/10"))]);
        // rotate about a centre, and matrix(a b c d e f) as x' = a x + c y + e
        let doc =
            r#"<svg><path transform="rotate(180 1 1) matrix(1 2 3 4 5 6)" d="M 1 1 L 0 0"/></svg>"#;
        let p = parse_svg_document(doc).unwrap();
        // matrix: (1, 1) → (1+3+5, 2+4+6) = (9, 12); rotate 180 about (1, 1): (2−9, 2−12)
        assert_eq!(pts(&p[0])[0], (q("-7"), q("-10")));
        assert_eq!(pts(&p[0])[1], (q("-3"), q("-4")));
        // rotate(-270) = rotate(90); skewX(0) is the identity
        let a = parse_svg_document(
            r#"<svg><path transform="rotate(-270) skewX(0)" d="M 1 0 L 2 0"/></svg>"#,
        )
        .unwrap();
        assert_eq!(pts(&a[0])[0], (q("0"), q("1")));
    }

    /// The simple shapes, closed where SVG closes them; non-rendered content skipped.
    #[test]
    fn shapes_and_skipped_content() {
        let doc = r#"<svg xmlns="http://www.w3.org/2000/svg">
            <defs><path d="M 0 0 L 100 100"/></defs>
            <clipPath><rect width="5" height="5"/></clipPath>
            <rect x="1" y="2" width="3" height="4"/>
            <polygon points="0,0 1,0 1,1"/>
            <polyline points="0 0 1 0 1 1"/>
            <line x1="0" y1="0" x2="0.5" y2="0"/>
        </svg>"#;
        let p = parse_svg_document(doc).unwrap();
        assert_eq!(p.len(), 4 + 3 + 2 + 1);
        assert_eq!(pts(&p[0])[0], (q("1"), q("2")));
        assert_eq!(pts(&p[3])[1], (q("1"), q("2")), "the rectangle closes");
        assert_eq!(pts(&p[6])[1], (q("0"), q("0")), "the polygon closes");
        assert_eq!(pts(&p[9])[1], (q("1/2"), q("0")), "0.5 is read exactly");
    }

    /// What is not read is an error naming the element, never dropped.
    #[test]
    fn unreadable_content_names_the_element() {
        for (doc, at) in [
            (
                r#"<svg><g/><g><circle r="-1"/></g></svg>"#,
                "svg/g[1]/circle[0].r",
            ),
            (
                r#"<svg><g/><g><text>a</text></g></svg>"#,
                "svg/g[1]/text[0]",
            ),
            (
                r#"<svg><path d="M 0 0 A 1 1 0 2 1 2 2"/></svg>"#,
                "svg/path[0].d",
            ),
            (
                r#"<svg><ellipse rx="1" ry="-2"/></svg>"#,
                "svg/ellipse[0].ry",
            ),
            (r#"<svg><circle r="1e101"/></svg>"#, "svg/circle[0]"),
            (
                r#"<svg><g transform="skewY(90)"><path d="M0 0 L1 1"/></g></svg>"#,
                "svg/g[0].transform",
            ),
            (r##"<svg><use href="#nowhere"/></svg>"##, "svg/use[0].href"),
            (
                r##"<svg><g id="a"><use href="#a"/><line x2="1"/></g></svg>"##,
                "svg/g[0]/use[0]/#a/use[0].href",
            ),
            (
                r#"<svg><path stroke-width="2px" d="M0 0 L1 1"/></svg>"#,
                "svg/path[0].stroke-width",
            ),
            (r#"<svg><line x1="1px" x2="2"/></svg>"#, "svg/line[0].x1"),
            (
                r#"<svg><rect rx="-1" width="2" height="2"/></svg>"#,
                "svg/rect[0].rx",
            ),
            (
                r#"<svg><polygon points="0 0 1"/></svg>"#,
                "svg/polygon[0].points",
            ),
            (
                r#"<svg><path transform="wobble(1)" d="M0 0 L1 1"/></svg>"#,
                "svg/path[0].transform",
            ),
            (r#"<svg><path d="M0 0 L1 1"/>"#, "(document)"),
            (r#"<html/>"#, "(document)"),
        ] {
            match parse_svg_document(doc) {
                Err(CurveParseError::Field { field, .. }) => assert_eq!(field, at, "{doc}"),
                other => panic!("{doc}: {other:?}"),
            }
        }
        assert!(matches!(
            parse_svg_document("<svg><g/></svg>"),
            Err(CurveParseError::Empty { .. })
        ));
    }

    /// A lower estimate of the distance of a chain of pieces from the
    /// ellipse `((x − cx)/rx)² + ((y − cy)/ry)² = 1`, in floats: the largest
    /// `|‖((x − cx)/rx, (y − cy)/ry)‖ − 1| · min(rx, ry)` over dense samples
    /// (the map from the unit circle shrinks no distance by more than the
    /// smaller radius).
    fn radial_error(p: &[Bezier<Rational>], c: (f64, f64), r: (f64, f64)) -> f64 {
        use crate::scalar::Scalar;
        let mut worst = 0.0f64;
        for b in p {
            let pts: Vec<(f64, f64)> = b
                .points()
                .iter()
                .map(|q| (q.x.approx(), q.y.approx()))
                .collect();
            for k in 0..=64 {
                let t = k as f64 / 64.0;
                let v = Bezier::new(pts.iter().map(|&(x, y)| V2::new(x, y)).collect()).eval(&t);
                let (u, w) = ((v.x - c.0) / r.0, (v.y - c.1) / r.1);
                worst = worst.max((u.hypot(w) - 1.0).abs() * r.0.min(r.1));
            }
        }
        worst
    }

    /// `<circle>` and `<ellipse>`: two half arcs from (cx + rx, cy), counter-
    /// clockwise in user coordinates, closed exactly, reported with bounds.
    #[test]
    fn circles_and_ellipses_are_approximated_and_reported() {
        let doc = r#"<svg><circle cx="1" cy="2" r="3"/><ellipse cx="-1" cy="0" rx="2" ry="0.5"/>
            <ellipse rx="2"/><circle r="0"/></svg>"#;
        let (p, a) = parse_svg_document_reported(doc).unwrap();
        assert_eq!(a.elements.len(), 3, "the zero circle draws nothing");
        assert_eq!(a.elements[0].at, "svg/circle[0]");
        assert_eq!(a.elements[1].at, "svg/ellipse[0]");
        assert_eq!(a.elements[2].at, "svg/ellipse[1]");
        assert_eq!(a.elements[0].pieces, 18, "9 pieces per half circle");
        assert_eq!(a.pieces(), p.len());
        // starts at (cx + r, cy), goes towards +y first, closes exactly
        let circle = &p[..18];
        assert_eq!(pts(&circle[0])[0], (q("4"), q("2")));
        assert!(
            pts(&circle[0])[3].1 > q("2"),
            "counter-clockwise: y increases first"
        );
        assert_eq!(
            pts(&circle[8])[3],
            (q("-2"), q("2")),
            "the half point is exact"
        );
        assert_eq!(pts(&circle[17])[3], (q("4"), q("2")), "closed exactly");
        // bounds: within the target, and above the measured error
        assert!(a.elements[0].bound <= 3e-7);
        let measured = radial_error(circle, (1.0, 2.0), (3.0, 3.0));
        assert!(
            measured <= a.elements[0].bound,
            "{measured} > {}",
            a.elements[0].bound
        );
        let ellipse = &p[18..36];
        assert_eq!(pts(&ellipse[0])[0], (q("1"), q("0")));
        assert!(a.elements[1].bound <= 2e-7);
        // a missing ry is rx (SVG 2's auto)
        assert_eq!(pts(&p[36])[0], (q("2"), q("0")));
        let (p2, _) =
            parse_svg_document_reported(r#"<svg><ellipse rx="2" ry="auto"/></svg>"#).unwrap();
        assert_eq!(p2, p[36..].to_vec());
    }

    /// Rounded `<rect>`: SVG 2's path — lines and four quarter arcs from
    /// (x + rx, y); one radius given is both; radii clamped to half a side.
    #[test]
    fn rounded_rects_are_lines_and_quarter_arcs() {
        let (p, a) = parse_svg_document_reported(
            r#"<svg><rect x="1" y="2" width="10" height="4" rx="1"/></svg>"#,
        )
        .unwrap();
        assert_eq!(a.elements.len(), 1);
        let lines: Vec<_> = p.iter().filter(|b| b.degree() == 1).collect();
        assert_eq!(lines.len(), 4);
        assert_eq!(pts(lines[0]), vec![(q("2"), q("2")), (q("10"), q("2"))]);
        assert_eq!(a.elements[0].pieces, p.len() - 4);
        for w in p.windows(2) {
            assert_eq!(pts(&w[0]).last(), pts(&w[1]).first(), "connected exactly");
        }
        assert_eq!(pts(&p[p.len() - 1]).last(), pts(&p[0]).first(), "closed");
        assert!(a.bound() <= 1e-7);
        // rx larger than half the width: clamped, the top and bottom lines vanish
        let (p, _) =
            parse_svg_document_reported(r#"<svg><rect width="2" height="4" rx="5" ry="1"/></svg>"#)
                .unwrap();
        assert_eq!(p.iter().filter(|b| b.degree() == 1).count(), 2);
        // rx = 0: a plain rectangle, nothing approximated
        let (p, a) =
            parse_svg_document_reported(r#"<svg><rect width="2" height="4" rx="0" ry="1"/></svg>"#)
                .unwrap();
        assert_eq!(p.len(), 4);
        assert!(a.is_empty());
    }

    /// Transforms map the pieces exactly and scale the bound by ‖T‖₂.
    #[test]
    fn transforms_scale_the_bound() {
        let plain = parse_svg_document_reported(r#"<svg><circle r="1"/></svg>"#).unwrap();
        let (p, a) = parse_svg_document_reported(
            r#"<svg><g transform="translate(5 5) scale(3 2)"><circle r="1"/></g></svg>"#,
        )
        .unwrap();
        // the same pieces mapped: (x, y) ↦ (3x + 5, 2y + 5)
        assert_eq!(pts(&p[0])[1].0, q("3") * &pts(&plain.0[0])[1].0 + q("5"));
        let (b0, b) = (plain.1.bound(), a.bound());
        assert!(b >= 3.0 * b0 && b <= 3.0 * b0 * (1.0 + 1e-12), "{b0} {b}");
        // rotations by 90° keep the bound; a path's arcs are named inside it
        let (_, a) = parse_svg_document_reported(
            r#"<svg><path transform="rotate(90)" d="M 0 0 L 1 0 A 1 1 0 0 1 3 0"/></svg>"#,
        )
        .unwrap();
        assert_eq!(a.elements[0].at, "svg/path[0].d, byte 12");
        let (_, b) =
            parse_svg_document_reported(r#"<svg><path d="M 0 0 L 1 0 A 1 1 0 0 1 3 0"/></svg>"#)
                .unwrap();
        assert_eq!(a.bound(), b.bound());
        // ‖matrix(1 1 0 1 0 0)‖₂ = the golden ratio
        let m = Affine([q("1"), q("1"), q("0"), q("1"), q("0"), q("0")]);
        let g = (1.0 + 5f64.sqrt()) / 2.0;
        assert!(m.norm_sup() >= g && m.norm_sup() <= g * (1.0 + 1e-14));
    }

    /// `rotate(30)`: an exactly rational rotation (a point of the unit
    /// circle), within 1e-12 of the exact one, reported with the displacement.
    #[test]
    fn irrational_rotations_are_exact_rational_rotations() {
        let (c, s, e) = rational_rotation(&q("30")).unwrap();
        assert_eq!(&c * &c + &s * &s, Rational::one(), "on the unit circle");
        assert!(e <= TRANSFORM_TARGET);
        let (cf, sf) = (30f64.to_radians().cos(), 30f64.to_radians().sin());
        assert!((to_f64(&c) - cf).abs() < 1e-12 && (to_f64(&s) - sf).abs() < 1e-12);
        // every angle class: quarter turns exact, the rest within the target
        for deg in ["-179.5", "91", "225.25", "1e-9", "-44.99", "1/3", "720.1"] {
            let (c, s, e) = rational_rotation(&q(deg)).unwrap();
            let a = to_f64(&q(deg)).to_radians();
            assert_eq!(&c * &c + &s * &s, Rational::one());
            assert!(e <= TRANSFORM_TARGET, "{deg}: {e}");
            assert!((to_f64(&c) - a.cos()).abs() < 1e-11, "{deg}");
            assert!((to_f64(&s) - a.sin()).abs() < 1e-11, "{deg}");
        }
        // the document: a segment from (10, 0) to (20, 0) about the centre (10, 0)
        let doc = r#"<svg><g transform="translate(1 2)"><path transform="rotate(30 10 0)" d="M 10 0 L 20 0"/></g></svg>"#;
        let (p, a) = parse_svg_document_reported(doc).unwrap();
        assert_eq!(
            pts(&p[0])[0],
            (q("11"), q("2")),
            "the centre stays, exactly"
        );
        let end = &pts(&p[0])[1];
        assert!((to_f64(&end.0) - (11.0 + 10.0 * cf)).abs() < 1e-10);
        assert!((to_f64(&end.1) - (2.0 + 10.0 * sf)).abs() < 1e-10);
        assert_eq!(a.elements.len(), 1);
        let el = &a.elements[0];
        assert_eq!(
            (el.kind, el.at.as_str()),
            (ApproxKind::Rotation, "svg/g[0]/path[0]")
        );
        // displacement ≤ err · max |p − c| = err · 10
        assert!(el.bound > 0.0 && el.bound <= 10.0 * TRANSFORM_TARGET * (1.0 + 1e-9));
        assert!(
            el.detail.starts_with("rotate(30) as cos = "),
            "{}",
            el.detail
        );
        let summary = a.summary().unwrap();
        assert!(
            summary.contains(
                "1 element(s) under an irrational rotate mapped exactly by a rational matrix"
            ),
            "{summary}"
        );
        assert_eq!(a.pieces(), 0, "no curve was replaced");
    }

    /// A circle under a rotation: its arc bound plus the rotation's
    /// displacement over the circle (radius + its own bound); a skew likewise.
    #[test]
    fn rotated_arcs_add_the_displacement() {
        let (_, plain) =
            parse_svg_document_reported(r#"<svg><circle cx="100" r="1"/></svg>"#).unwrap();
        let (_, a) = parse_svg_document_reported(
            r#"<svg><g transform="scale(2) rotate(10)"><circle cx="100" r="1"/></g></svg>"#,
        )
        .unwrap();
        assert_eq!(a.elements.len(), 2);
        let delta = a.elements[1].bound;
        // |p| ≤ 101 + ε on the circle, times ‖scale(2)‖ = 2
        assert!(delta > 0.0 && delta <= 2.0 * 101.0 * TRANSFORM_TARGET * 1.0001);
        assert!(a.elements[0].bound >= 2.0 * plain.bound() + delta);
        assert!(a.elements[0].bound <= (2.0 * plain.bound() + delta) * (1.0 + 1e-12));
        let (p, a) = parse_svg_document_reported(
            r#"<svg><path transform="skewX(30)" d="M 0 0 L 0 3"/></svg>"#,
        )
        .unwrap();
        let t = 30f64.to_radians().tan();
        assert!((to_f64(&pts(&p[0])[1].0) - 3.0 * t).abs() < 1e-11);
        assert_eq!(a.elements[0].kind, ApproxKind::Skew);
        assert!(a.elements[0].bound <= 3.0 * TRANSFORM_TARGET);
        // skewX(180) and skewY(-45) are exact
        let (p, a) = parse_svg_document_reported(
            r#"<svg><path transform="skewX(180) skewY(-45)" d="M 0 0 L 2 3"/></svg>"#,
        )
        .unwrap();
        assert!(a.is_empty());
        assert_eq!(pts(&p[0])[1], (q("2"), q("1")));
    }

    /// `<use>` instances (with x, y, transforms, nested groups and symbols);
    /// display, visibility and non-rendered containers skipped.
    #[test]
    fn use_display_and_visibility() {
        let doc = r##"<svg xmlns="http://www.w3.org/2000/svg" xmlns:xlink="http://www.w3.org/1999/xlink">
            <defs><g id="pair"><line x2="1"/><line y2="1"/></g></defs>
            <symbol id="s"><use xlink:href="#pair" transform="scale(2)"/></symbol>
            <use href="#s" x="10" y="20"/>
            <g style="display: none"><line x2="5"/></g>
            <g visibility="hidden"><line x2="6"/><line x2="7" visibility="visible"/></g>
            <mask><line x2="8"/></mask>
        </svg>"##;
        let e = parse_svg_document_elements(doc).unwrap();
        let ats: Vec<&str> = e.iter().map(|e| e.at.as_str()).collect();
        assert_eq!(
            ats,
            [
                "svg/use[0]/#s/use[0]/#pair/line[0]",
                "svg/use[0]/#s/use[0]/#pair/line[1]",
                "svg/g[1]/line[1]"
            ]
        );
        // (1, 0) scaled by 2 then moved by (10, 20)
        assert_eq!(pts(&e[0].pieces[0])[1], (q("12"), q("20")));
        assert_eq!(pts(&e[2].pieces[0])[1], (q("7"), q("0")));
        // depth: 16 nested uses are read, 17 are not
        let mut chain = String::from(r#"<svg><defs><line id="u0" x2="1"/>"#);
        for k in 1..=17 {
            chain += &format!(r##"<use id="u{k}" href="#u{}"/>"##, k - 1);
        }
        chain += r##"</defs><use href="#u15"/></svg>"##;
        assert!(parse_svg_document_elements(&chain).is_ok());
        let deeper = chain.replace(
            r##"<use href="#u15"/></svg>"##,
            r##"<use href="#u16"/></svg>"##,
        );
        match parse_svg_document_elements(&deeper) {
            Err(CurveParseError::Field { reason, .. }) => {
                assert!(reason.contains("deeper than 16"))
            }
            other => panic!("{other:?}"),
        }
        // a billion laughs stops at the visit limit
        let mut laughs = String::from(r#"<svg><defs><line id="l0" x2="1"/>"#);
        for k in 1..=9 {
            laughs += &format!(r#"<g id="l{k}">"#);
            for _ in 0..10 {
                laughs += &format!(r##"<use href="#l{}"/>"##, k - 1);
            }
            laughs += "</g>";
        }
        laughs += r##"</defs><use href="#l9"/></svg>"##;
        assert!(matches!(
            parse_svg_document_elements(&laughs),
            Err(CurveParseError::TooLarge { .. })
        ));
    }

    /// stroke and stroke-width: attribute, style over attribute, inherited,
    /// through `<use>`; the pen radius is half the width times the scale.
    #[test]
    fn stroke_widths_per_element() {
        let doc = r##"<svg stroke="#000" stroke-width="3">
            <line x2="1"/>
            <g style="stroke-width:4" stroke-width="9" transform="scale(2) rotate(30)"><line x2="1"/></g>
            <line x2="1" stroke="none"/>
            <line x2="1" style="stroke: none; stroke: red"/>
            <g transform="scale(1 2)"><line x2="1"/></g>
            <g transform="matrix(3 4 -4 3 0 0)"><line x2="1" stroke-width="1"/></g>
        </svg>"##;
        let e = parse_svg_document_elements(doc).unwrap();
        assert_eq!(e.len(), 6);
        assert_eq!(e[0].pen_radius, Ok(q("3/2")));
        assert_eq!(e[1].stroke_width, q("4"));
        assert_eq!(
            e[1].pen_radius,
            Ok(q("4")),
            "4/2 · 2 (the rotation keeps lengths)"
        );
        assert!(!e[2].stroked && e[3].stroked, "the last declaration wins");
        assert!(
            e[4].pen_radius.is_err(),
            "a non-uniform scale makes an elliptical pen"
        );
        assert_eq!(e[5].pen_radius, Ok(q("5/2")), "‖(3, 4)‖ = 5");
        let e = parse_svg_document_elements(r#"<svg><line x2="1"/></svg>"#).unwrap();
        assert!(!e[0].stroked, "SVG's initial stroke is none");
    }
}
