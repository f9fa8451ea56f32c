//! Exact equality of shapes as geometry: does a certificate speak about *these*
//! shapes? (`lncert verify CERT --against A B`.)
//!
//! Two descriptions are the same shape when they describe the same parametrised
//! geometry up to what does not change the statement `d_H(A, B) ≤ tol`:
//!
//! - **curves**: the same sequence of polynomial arcs, up to splitting a piece at
//!   interior parameters (an offset's certificate stores its input split at
//!   dyadic parameters), degree elevation, and reversal of the whole curve;
//! - **arcs**: the same centre and radius, and direction vectors that are
//!   positive multiples of each other (the counter-clockwise sweep is the same);
//! - **offsets and convolutions**: the same curve up to splitting and elevation
//!   (not reversal: it flips the side), the same `Q = M Mᵀ` (the ellipse `M · unit
//!   circle` is the same set for `M` and `M R`, `R` orthogonal) and the same side;
//!   an offset at distance `r` is the convolution with `Q = r² I` on the side of
//!   `sign r`.
//!
//! Every comparison is exact (rational arithmetic).

use super::verify::{verify_json, Invalid, Valid};
use crate::curve::{Bezier, V2};
use crate::poly::binomial_big;
use crate::scalar::Rational;
use crate::shape::{ArcDesc, EllipseArcDesc, ShapeDesc};
use crate::stroke::PenShape;
use num_bigint::BigInt;
use num_traits::{One, Signed, Zero};

type Piece = Bezier<Rational>;

/// The normal form of an offset or convolution: curve, `Q = M Mᵀ`, side.
fn conv_form(s: &ShapeDesc) -> Option<(&[Piece], [Rational; 3], i8)> {
    match s {
        ShapeDesc::Offset { curve, distance } => {
            let r2 = distance * distance;
            let side = if distance.is_positive() { 1 } else { -1 };
            Some((curve, [r2.clone(), Rational::zero(), r2], side))
        }
        ShapeDesc::Convolution {
            curve,
            ellipse: m,
            side,
        } => Some((
            curve,
            [
                &m[0][0] * &m[0][0] + &m[0][1] * &m[0][1],
                &m[0][0] * &m[1][0] + &m[0][1] * &m[1][1],
                &m[1][0] * &m[1][0] + &m[1][1] * &m[1][1],
            ],
            *side,
        )),
        _ => None,
    }
}

impl ShapeDesc {
    /// `Ok(())` if `self` and `other` are the same shape (see the module docs),
    /// otherwise the first difference found.
    ///
    /// # Examples
    /// ```
    /// use lncert::shape::ShapeDesc;
    /// let whole = ShapeDesc::parse("M 0 0 Q 1 2 2 0").unwrap();
    /// let halves = ShapeDesc::parse(r#"{"beziers": [[[0, 0], ["1/2", 1], [1, 1]], [[1, 1], ["3/2", 1], [2, 0]]]}"#).unwrap();
    /// assert!(whole.same_as(&halves).is_ok());
    /// // the quadratic elevated to a cubic and reversed: the same point set
    /// let cubic = ShapeDesc::parse(r#"{"bezier": [[2, 0], ["4/3", "4/3"], ["2/3", "4/3"], [0, 0]]}"#).unwrap();
    /// assert!(whole.same_as(&cubic).is_ok());
    /// // decimals are exact: 1.3333 is not 4/3
    /// let near = ShapeDesc::parse("M 2 0 C 1.3333 1.3333 0.6667 1.3333 0 0").unwrap();
    /// assert!(whole.same_as(&near).is_err());
    /// // a union of one member is that member
    /// let one = ShapeDesc::union(vec![cubic.clone()]).unwrap();
    /// assert!(one.same_as(&whole).is_ok() && whole.same_as(&one).is_ok());
    /// assert!(one.same_as(&near).is_err());
    /// ```
    pub fn same_as(&self, other: &ShapeDesc) -> Result<(), String> {
        match (self, other) {
            (ShapeDesc::Curve(x), ShapeDesc::Curve(y)) => same_curve(x, y).or_else(|e| {
                let rev: Vec<Piece> = y
                    .iter()
                    .rev()
                    .map(|b| Bezier::new(b.points().iter().rev().cloned().collect()))
                    .collect();
                same_curve(x, &rev).map_err(|_| e)
            }),
            (ShapeDesc::Arc(a), ShapeDesc::Arc(b)) => same_arc(a, b),
            (ShapeDesc::EllipseArc(a), ShapeDesc::EllipseArc(b)) => same_ellipse_arc(a, b),
            // a union of one member is that member's point set
            (ShapeDesc::Union(x), y) if x.len() == 1 && !matches!(y, ShapeDesc::Union(_)) => {
                x[0].same_as(y)
            }
            (x, ShapeDesc::Union(y)) if y.len() == 1 && !matches!(x, ShapeDesc::Union(_)) => {
                x.same_as(&y[0])
            }
            (ShapeDesc::Union(x), ShapeDesc::Union(y)) => {
                let member_by_member = || {
                    if x.len() != y.len() {
                        return Err(format!("unions of {} and {} members", x.len(), y.len()));
                    }
                    for (i, (a, b)) in x.iter().zip(y).enumerate() {
                        a.same_as(b).map_err(|e| format!("member {i}: {e}"))?;
                    }
                    Ok(())
                };
                member_by_member().or_else(|e| same_regrouped(x, y).map_err(|_| e))
            }
            // a union against one member that is split there (an arc as
            // quarters)
            (ShapeDesc::Union(x), y) if matches!(y, ShapeDesc::Arc(_)) => {
                same_regrouped(x, std::slice::from_ref(y))
            }
            (x, ShapeDesc::Union(y)) if matches!(x, ShapeDesc::Arc(_)) => {
                same_regrouped(std::slice::from_ref(x), y)
            }
            _ => match (conv_form(self), conv_form(other)) {
                (Some((cx, qx, sx)), Some((cy, qy, sy))) => {
                    if qx != qy {
                        return Err(
                            "different pen: the matrices Q = M Mᵀ (r² I for an offset) differ"
                                .into(),
                        );
                    }
                    if sx != sy {
                        return Err(
                            "different side (sign of the distance, or convolution side)".into()
                        );
                    }
                    same_curve(cx, cy).map_err(|e| format!("the curve: {e}"))
                }
                _ => Err(format!(
                    "different kinds of shape: {} against {}",
                    self.summary(),
                    other.summary()
                )),
            },
        }
    }
}

/// Two unions compared with their curve members gathered: every Bézier piece
/// of every curve member, in order, as one curve, and the other members (arcs,
/// offsets, …) in order. A union's point set is the union of its members', and
/// a curve's the union of its pieces', so equal gathered curves and equal other
/// members are the same point set, however the members were grouped: an
/// outline read from SVG path data (`L` runs between `A` arcs, in path order)
/// against a stroke certificate's (all its Bézier pieces, then its arcs).
fn same_regrouped(x: &[ShapeDesc], y: &[ShapeDesc]) -> Result<(), String> {
    fn gathered(members: &[ShapeDesc]) -> (Vec<Piece>, Vec<&ShapeDesc>) {
        let mut pieces = Vec::new();
        let mut rest = Vec::new();
        for m in members {
            match m {
                ShapeDesc::Curve(p) => pieces.extend(p.iter().cloned()),
                other => rest.push(other),
            }
        }
        (pieces, rest)
    }
    let ((px, rx), (py, ry)) = (gathered(x), gathered(y));
    let ((ax, rx), (ay, ry)) = (merged_arcs(&rx), merged_arcs(&ry));
    if rx.len() != ry.len() || px.is_empty() != py.is_empty() {
        return Err("different members".into());
    }
    if !px.is_empty() {
        ShapeDesc::Curve(px).same_as(&ShapeDesc::Curve(py))?;
    }
    for (a, b) in rx.iter().zip(&ry) {
        a.same_as(b)?;
    }
    // the merged arcs, as sets: each of one side matched once on the other
    if ax.len() != ay.len() {
        return Err(format!(
            "{} and {} arcs after joining the chained arcs of each circle",
            ax.len(),
            ay.len()
        ));
    }
    let mut used = vec![false; ay.len()];
    for a in &ax {
        let k = (0..ay.len()).find(|&k| !used[k] && a.same(&ay[k])).ok_or(
            "an arc (chained arcs of one circle joined) with no equal arc on the other side",
        )?;
        used[k] = true;
    }
    Ok(())
}

/// Counter-clockwise arcs of one circle joined where one ends in the
/// direction the next starts (the same point set, split differently: a
/// `<circle>` read as two halves, a certificate's curve as quarters); a
/// chain that closes is the whole circle.
struct MergedArc {
    center: V2<Rational>,
    radius: Rational,
    from: V2<Rational>,
    to: V2<Rational>,
    full: bool,
}

impl MergedArc {
    fn same(&self, o: &MergedArc) -> bool {
        self.center == o.center
            && self.radius == o.radius
            && self.full == o.full
            && (self.full
                || (positively_parallel(&self.from, &o.from)
                    && positively_parallel(&self.to, &o.to)))
    }
}

/// The angle of `x` counter-clockwise from `a` is below that of `y`
/// (angles in `[0, 2π)`), exactly.
fn ccw_before(a: &V2<Rational>, x: &V2<Rational>, y: &V2<Rational>) -> bool {
    // half 0: angle in [0, π); half 1: [π, 2π)
    let half = |v: &V2<Rational>| {
        let c = a.cross(v);
        u8::from(!(c.is_positive() || (c.is_zero() && a.dot(v).is_positive())))
    };
    let (hx, hy) = (half(x), half(y));
    hx < hy || (hx == hy && x.cross(y).is_positive())
}

/// The circular arcs of `rest` merged ([`MergedArc`]), and the other members.
fn merged_arcs<'a>(rest: &[&'a ShapeDesc]) -> (Vec<MergedArc>, Vec<&'a ShapeDesc>) {
    let mut arcs = Vec::new();
    let mut other = Vec::new();
    for m in rest {
        match m {
            ShapeDesc::Arc(a) => arcs.push(MergedArc {
                center: a.center.clone(),
                radius: a.radius.clone(),
                from: a.from.clone(),
                to: a.to.clone(),
                full: false,
            }),
            o => other.push(*o),
        }
    }
    'merge: loop {
        for i in 0..arcs.len() {
            for j in 0..arcs.len() {
                let (x, y) = (&arcs[i], &arcs[j]);
                if i == j
                    || x.full
                    || y.full
                    || x.center != y.center
                    || x.radius != y.radius
                    || !positively_parallel(&x.to, &y.from)
                {
                    continue;
                }
                let full = positively_parallel(&y.to, &x.from);
                // y must not run past x's start (overlapping arcs are left
                // apart: never the same by mistake)
                if !full && ccw_before(&y.from, &x.from, &y.to) {
                    continue;
                }
                let joined = MergedArc {
                    center: x.center.clone(),
                    radius: x.radius.clone(),
                    from: x.from.clone(),
                    to: y.to.clone(),
                    full,
                };
                let (hi, lo) = (i.max(j), i.min(j));
                arcs.remove(hi);
                arcs.remove(lo);
                arcs.push(joined);
                continue 'merge;
            }
        }
        break;
    }
    (arcs, other)
}

/// `u = λ v` with `λ > 0`, exactly.
pub(crate) fn positively_parallel(u: &V2<Rational>, v: &V2<Rational>) -> bool {
    u.cross(v).is_zero() && u.dot(v).is_positive()
}

fn same_arc(a: &ArcDesc, b: &ArcDesc) -> Result<(), String> {
    if a.center != b.center {
        return Err("arcs with different centres".into());
    }
    if a.radius != b.radius {
        return Err("arcs with different radii".into());
    }
    if !positively_parallel(&a.from, &b.from) || !positively_parallel(&a.to, &b.to) {
        return Err(
            "arcs with different end directions (the counter-clockwise sweep differs)".into(),
        );
    }
    Ok(())
}

/// The same description up to the lengths of the directions (an ellipse
/// written with another matrix `M R`, `R` a rotation, is reported as
/// different: never the same by mistake).
fn same_ellipse_arc(a: &EllipseArcDesc, b: &EllipseArcDesc) -> Result<(), String> {
    if a.center != b.center {
        return Err("elliptic arcs with different centres".into());
    }
    if a.matrix != b.matrix {
        return Err("elliptic arcs with different matrices".into());
    }
    if !positively_parallel(&a.from, &b.from) || !positively_parallel(&a.to, &b.to) {
        return Err(
            "elliptic arcs with different end directions (the counter-clockwise sweep differs)"
                .into(),
        );
    }
    Ok(())
}

/// Verifies a certificate (as [`verify`](super::verify::verify) does) and checks that it is about
/// exactly the shapes `a` and `b` ([`ShapeDesc::same_as`]): what `lncert
/// verify CERT --against A B` runs.
///
/// The certificate's shapes are read back by the user-language reader and
/// must read back to the very document the verifier checked (the canonical
/// form is a fixpoint), so the shapes compared are the shapes proven. The
/// comparison costs `O(n · m)` exact operations per piece of `n + 1` control
/// points matched against a piece of reduced degree `m` (see
/// `proofs/certify-hausdorff.md`, "Same shapes"): about linear in the
/// certificate's size, like the verification itself.
///
/// Shapes read from SVG arcs, circles, ellipses or rounded rects are their
/// certified cubic approximations ([`crate::shape::InputApprox`]): a `Valid`
/// here is then about the approximation, which the caller must say.
///
/// # Examples
/// ```
/// use lncert::certify::{hausdorff, verify_against, Certificate, Config};
/// use lncert::shape::ShapeDesc;
/// use lncert::Tolerance;
/// let a = ShapeDesc::parse("M 0 0 Q 0.5 0.5 1 0").unwrap();
/// let b = ShapeDesc::parse("M 0 0 L 1 0").unwrap();
/// let tol: Tolerance = "0.26".parse().unwrap();
/// let cfg = Config { tol: Some(tol.clone()), parametric: false, ..Config::default() };
/// let r = hausdorff(&a, &b, &cfg).unwrap();
/// let cert = Certificate::new(&a, &b, &tol, &r).unwrap();
/// let text = cert.to_json_string();
/// assert!(verify_against(&text, &a, &b).is_ok());
/// // a dot far away added to B: not the shape the certificate speaks about
/// let b_dot = ShapeDesc::parse("M 0 0 L 1 0 M 5 0 L 5 0").unwrap();
/// assert_eq!(verify_against(&text, &a, &b_dot).unwrap_err().at, "b");
/// ```
pub fn verify_against(text: &str, a: &ShapeDesc, b: &ShapeDesc) -> Result<Valid, Invalid> {
    verify_expecting(
        text,
        &Expected {
            a: Some(a),
            b: Some(b),
            ..Expected::default()
        },
    )
}

/// What a user expects a certificate to state, for [`verify_expecting`]: each
/// field given is confirmed, each left `None` is not looked at.
///
/// | format | `a` | `b` | `pen` |
/// |---|---|---|---|
/// | Hausdorff / offset certificate | its `a` | its `b` | — (refused) |
/// | stroke certificate | its outline | its curve | its pen |
/// | stroke distance certificate | its shape `X` | the stroke certificate's curve | its pen |
/// | certificate set | — (refused) | — (refused) | every member's pen |
#[derive(Clone, Debug, Default)]
pub struct Expected<'a> {
    /// Shape `A` (see the table).
    pub a: Option<&'a ShapeDesc>,
    /// Shape `B`: for stroke certificates, the stroked curve.
    pub b: Option<&'a ShapeDesc>,
    /// The pen of a stroke claim. Two pens are the same set `M · disk(1)`
    /// exactly when their `Q = M Mᵀ` are equal (a disk of radius `r` is `Q =
    /// r² I`): a certificate stating another pen is invalid at `radius` or `pen`.
    pub pen: Option<&'a PenShape>,
    /// The tolerance the user needs: the certificate must prove `d_H ≤ tol'`
    /// with `tol' ≤ tol` (a smaller proven tolerance proves this one too), or
    /// it is invalid at `tol`.
    pub tol: Option<&'a Rational>,
}

fn describe_q(q: &[Rational; 3]) -> String {
    if q[1].is_zero() && q[0] == q[2] {
        match rational_root(&q[0], 2) {
            Some(r) => format!("the disk of radius {r}"),
            None => format!("the disk of radius √({})", q[0]),
        }
    } else {
        format!(
            "the ellipse with Q = M Mᵀ = [[{}, {}], [{}, {}]]",
            q[0], q[1], q[1], q[2]
        )
    }
}

/// Confirms that a valid stroke certificate (`doc`, at `at`) states `pen`.
fn confirm_pen(doc: &crate::json::Json, at: &str, pen: &PenShape) -> Result<(), Invalid> {
    let nest = |k: &str| {
        if at.is_empty() {
            k.to_string()
        } else {
            format!("{at}.{k}")
        }
    };
    let key = if doc.get("pen").is_some() {
        "pen"
    } else {
        "radius"
    };
    let theirs = super::verify::stroke::pen_q(doc).map_err(|e| Invalid {
        at: nest(&e.at),
        reason: e.reason,
    })?;
    let mine = pen.q();
    if theirs != mine {
        return Err(Invalid {
            at: nest(key),
            reason: format!(
                "the certificate's pen is {}, not the pen given ({})",
                describe_q(&theirs),
                describe_q(&mine)
            ),
        });
    }
    Ok(())
}

/// Compares the stated shape `theirs` (at `key`) with `mine` (`--against` `which`).
fn confirm_shape(
    theirs: &ShapeDesc,
    mine: &ShapeDesc,
    key: &str,
    which: &str,
) -> Result<(), Invalid> {
    theirs.same_as(mine).map_err(|why| Invalid {
        at: key.into(),
        reason: format!(
            "the certificate is about another {} than --against {which}: {why}",
            key.rsplit('.').next().unwrap_or(key)
        ),
    })
}

/// Verifies a certificate of any format ([`super::verify::verify`]) and then
/// confirms that it states what the user expects: the shapes, the pen and
/// the tolerance of [`Expected`] (`lncert verify CERT --against … --pen …
/// --tol …`). A valid certificate about anything else is [`Invalid`] at the
/// field that differs.
///
/// # Examples
/// ```
/// use lncert::certify::{verify_expecting, Expected};
/// use lncert::shape::ShapeDesc;
/// use lncert::stroke::{certificate, stroke, PenShape, StrokeOptions};
/// let q = |s: &str| lncert::parse_rational(s).unwrap();
/// let x = lncert::parse_curve("M 0 0 L 4 0").unwrap();
/// let s = stroke(&x, &StrokeOptions::new(q("1/2"), "0.01".parse().unwrap())).unwrap();
/// let text = certificate(&x, &s, &q("1/2")).unwrap().to_string();
/// let curve = ShapeDesc::parse("M 0 0 L 4 0").unwrap();
/// let (pen, tol) = (PenShape::Circle(q("1/2")), q("0.01"));
/// let want = Expected { b: Some(&curve), pen: Some(&pen), tol: Some(&tol), ..Default::default() };
/// assert!(verify_expecting(&text, &want).is_ok());
/// // another pen, or a tolerance smaller than the proven one: invalid
/// let wide = PenShape::Circle(q("1"));
/// let e = verify_expecting(&text, &Expected { pen: Some(&wide), ..Default::default() });
/// assert_eq!(e.unwrap_err().at, "radius");
/// let tight = q("0.001");
/// let e = verify_expecting(&text, &Expected { tol: Some(&tight), ..Default::default() });
/// assert_eq!(e.unwrap_err().at, "tol");
/// ```
pub fn verify_expecting(text: &str, want: &Expected) -> Result<Valid, Invalid> {
    use super::verify::stroke::{DISTANCE_FORMAT, FORMAT, SET_FORMAT};
    let doc = super::verify::read_document(text)?;
    let valid = verify_json(&doc)?;
    if let Some(t) = want.tol {
        if &valid.tol > t {
            return Err(Invalid {
                at: "tol".into(),
                reason: format!(
                    "the certificate proves d_H ≤ {}, more than the tolerance given ({t})",
                    valid.tol
                ),
            });
        }
    }
    let format = doc.get("format").and_then(|f| f.as_str());
    match format {
        Some(f) if f == SET_FORMAT => {
            if want.a.is_some() || want.b.is_some() {
                return Err(Invalid {
                    at: "format".into(),
                    reason: "a certificate set holds one outline and one curve per member: --against compares a single certificate's".into(),
                });
            }
            if let Some(pen) = want.pen {
                let members = doc.get("members").and_then(|m| m.as_array()).unwrap_or(&[]);
                for (k, m) in members.iter().enumerate() {
                    let cert = m.get("certificate").ok_or_else(|| Invalid {
                        at: format!("members[{k}].certificate"),
                        reason: "missing".into(),
                    })?;
                    confirm_pen(cert, &format!("members[{k}].certificate"), pen)?;
                }
            }
            return Ok(valid);
        }
        Some(f) if f == FORMAT => {
            // A is its outline, B its curve
            if let Some(pen) = want.pen {
                confirm_pen(&doc, "", pen)?;
            }
            if want.a.is_some() || want.b.is_some() {
                let (outline, curve) = super::verify::stroke::shapes(&doc)?;
                if let Some(a) = want.a {
                    confirm_shape(&outline, a, "outline", "A")?;
                }
                if let Some(b) = want.b {
                    confirm_shape(&curve, b, "curve", "B")?;
                }
            }
            return Ok(valid);
        }
        Some(f) if f == DISTANCE_FORMAT => {
            // A is the shape X of its Hausdorff part, B the curve of its stroke part
            let st = doc.get("outline_to_stroke").ok_or_else(|| Invalid {
                at: "outline_to_stroke".into(),
                reason: "missing".into(),
            })?;
            if let Some(pen) = want.pen {
                confirm_pen(st, "outline_to_stroke", pen)?;
            }
            if let Some(a) = want.a {
                let h = doc.get("shape_to_outline").ok_or_else(|| Invalid {
                    at: "shape_to_outline".into(),
                    reason: "missing".into(),
                })?;
                let theirs = stated_shape(h, "shape_to_outline.a", "a")?;
                confirm_shape(&theirs, a, "shape_to_outline.a", "A")?;
            }
            if let Some(b) = want.b {
                let (_, curve) = super::verify::stroke::shapes(st).map_err(|e| Invalid {
                    at: format!("outline_to_stroke.{}", e.at),
                    reason: e.reason,
                })?;
                confirm_shape(&curve, b, "outline_to_stroke.curve", "B")?;
            }
            return Ok(valid);
        }
        _ => {}
    }
    if want.pen.is_some() {
        return Err(Invalid {
            at: "format".into(),
            reason: "a Hausdorff certificate states no pen: --pen confirms stroke certificates"
                .into(),
        });
    }
    for (key, mine) in [("a", want.a), ("b", want.b)] {
        let Some(mine) = mine else { continue };
        let theirs = stated_shape(&doc, key, key)?;
        theirs.same_as(mine).map_err(|why| Invalid {
            at: key.into(),
            reason: format!(
                "the certificate is about another shape than --against {}: {why}{}",
                key.to_uppercase(),
                if has_arcs(mine) && !has_arcs(&theirs) {
                    " (circles, ellipses and SVG arcs with a rational centre are read as exact arcs; a certificate has none of them when it is about their cubic approximation, as those written by lncert before they were read exactly: certify the exact shapes again with `lncert hausdorff`)"
                } else {
                    ""
                }
            ),
        })?;
    }
    Ok(valid)
}

/// The shape at `key` of a valid Hausdorff certificate `doc`, read back by
/// the user-language reader; it must be in the canonical form (errors at `at`).
fn stated_shape(doc: &crate::json::Json, at: &str, key: &str) -> Result<ShapeDesc, Invalid> {
    // a valid certificate has both keys, in the canonical form
    let value = doc
        .get(key)
        .ok_or_else(|| Invalid {
            at: at.into(),
            reason: "missing".into(),
        })?
        .to_value();
    let theirs = ShapeDesc::from_value(&value).map_err(|e| Invalid {
        at: at.into(),
        reason: e.to_string(),
    })?;
    if theirs.to_json() != value {
        return Err(Invalid {
            at: at.into(),
            reason: "the shape does not read back to itself in the canonical form".into(),
        });
    }
    Ok(theirs)
}

/// The shape has a circular or an elliptic arc.
fn has_arcs(s: &ShapeDesc) -> bool {
    match s {
        ShapeDesc::Arc(_) | ShapeDesc::EllipseArc(_) => true,
        ShapeDesc::Union(m) => m.iter().any(has_arcs),
        _ => false,
    }
}

/// The exact `k`-th root of a positive rational, if it is rational.
fn rational_root(r: &Rational, k: u32) -> Option<Rational> {
    let root = |n: &BigInt| {
        let x = n.nth_root(k);
        (num_traits::pow(x.clone(), k as usize) == *n).then_some(x)
    };
    Some(Rational::new(root(r.numer())?, root(r.denom())?))
}

/// A polynomial piece in the power basis, `p(t) = Σ c[k] tᵏ`, of exact degree
/// `c.len() − 1` (the last coefficient is nonzero unless the piece is a point).
type Power = Vec<V2<Rational>>;

fn is_zero(v: &V2<Rational>) -> bool {
    v.x.is_zero() && v.y.is_zero()
}

/// A Bézier piece in the power basis, if its exact degree is at most `limit`.
///
/// A Bézier curve of degree `n` has degree `≤ m` exactly when its control
/// points are a polynomial of degree `≤ m` in their index, i.e. when all the
/// `(m+1)`-th forward differences `Δᵐ⁺¹Pᵢ` vanish (a degree-`m` curve written
/// with `n + 1` points has `Pᵢ = Σₖ aₖ C(i, k)/C(n, k)`, of degree `m` in `i`).
/// Its power coefficients are then `aₖ = C(n, k) ΔᵏP₀`. Only the differences
/// up to order `limit + 1` are formed: `O(n · limit)` operations, so a piece
/// of high written degree costs little when it is compared with one of low
/// degree (the cost of `--against` stays linear in the certificate's size).
fn power_basis(b: &Piece, limit: usize) -> Option<Power> {
    let n = b.degree();
    let mut level: Vec<V2<Rational>> = b.points().to_vec();
    let mut first = vec![level[0].clone()];
    for k in 1..=n {
        level = level.windows(2).map(|w| w[1].sub(&w[0])).collect();
        if level.iter().all(is_zero) {
            break;
        }
        if k > limit {
            return None;
        }
        first.push(level[0].clone());
    }
    Some(
        first
            .into_iter()
            .enumerate()
            .map(|(k, d)| d.scale(&Rational::from_integer(binomial_big(n, k))))
            .collect(),
    )
}

/// The coefficients of `p(a + u)` in `u` (Taylor shift, `O(deg²)`).
fn taylor(p: &Power, a: &Rational) -> Power {
    let mut c = p.clone();
    if a.is_zero() {
        return c;
    }
    let m = c.len() - 1;
    for i in 0..m {
        for j in (i..m).rev() {
            let t = c[j + 1].scale(a);
            c[j] = c[j].add(&t);
        }
    }
    c
}

fn is_point(b: &Piece) -> bool {
    b.points().iter().all(|p| *p == b.points()[0])
}

/// One side of the match: the pieces, their power bases once formed, and the
/// cursor (the piece and the parameter where its unmatched part starts).
struct Side<'a> {
    pieces: &'a [Piece],
    power: Vec<Option<Power>>,
    at: usize,
    t: Rational,
}

impl<'a> Side<'a> {
    fn new(pieces: &'a [Piece]) -> Self {
        Side {
            pieces,
            power: vec![None; pieces.len()],
            at: 0,
            t: Rational::zero(),
        }
    }
    fn done(&self) -> bool {
        self.at >= self.pieces.len()
    }
    fn piece(&self) -> &Piece {
        &self.pieces[self.at]
    }
    /// The power basis of the current piece, formed with the degree `limit`.
    fn power(&mut self, limit: usize) -> Option<&Power> {
        if self.power[self.at].is_none() {
            self.power[self.at] = power_basis(&self.pieces[self.at], limit);
        }
        self.power[self.at].as_ref()
    }
    /// The point where the unmatched part starts.
    fn point(&mut self) -> V2<Rational> {
        if self.t.is_zero() {
            return self.piece().points()[0].clone();
        }
        // only a piece matched in part has t > 0, and its power basis is formed
        let t = self.t.clone();
        let p = self.power[self.at].as_ref().expect("formed when matched");
        let mut v = p[p.len() - 1].clone();
        for c in p.iter().rev().skip(1) {
            v = v.scale(&t).add(c);
        }
        v
    }
    fn next(&mut self) {
        self.at += 1;
        self.t = Rational::zero();
    }
    /// The end point of the last piece.
    fn last_point(&self) -> Option<&V2<Rational>> {
        self.pieces.last().map(|b| &b.points()[b.degree()])
    }
}

/// The same curve up to splitting pieces and degree elevation (same direction).
///
/// A walk with a cursor on each side. Each step either consumes a single-point
/// piece of one side lying at the other side's cursor point, or matches the
/// unmatched parts as `x(a + s) = y(c + h s)`, `0 ≤ s ≤ ℓ`, for one rational
/// `h > 0` (both Taylor expansions at the cursors agree term by term with the
/// factor `hᵏ`) and advances both cursors to the end of the shorter part.
/// Pieces left over at the end must be single points at the other curve's end
/// point. `proofs/certify-hausdorff.md` ("Same shapes") proves that a curve
/// accepted here has the same point set as the other.
fn same_curve(x: &[Piece], y: &[Piece]) -> Result<(), String> {
    let one = Rational::one();
    let (mut xs, mut ys) = (Side::new(x), Side::new(y));
    while !xs.done() && !ys.done() {
        let at = |xs: &Side, ys: &Side| {
            format!(
                "piece {} (from its parameter {}) against piece {} (from {})",
                xs.at, xs.t, ys.at, ys.t
            )
        };
        // single points add nothing to the point set once the other side's
        // cursor point is that point
        let (px, py) = (
            xs.t.is_zero() && is_point(xs.piece()),
            ys.t.is_zero() && is_point(ys.piece()),
        );
        if px || py {
            if xs.point() != ys.point() {
                return Err(format!("{}: different start points", at(&xs, &ys)));
            }
            if px {
                xs.next();
            }
            if py {
                ys.next();
            }
            continue;
        }
        // the power bases: the piece written with fewer points is reduced in
        // full, the other only up to that degree
        let limit = xs.piece().degree().min(ys.piece().degree());
        let (u, v) = match (xs.power(limit).cloned(), ys.power(limit).cloned()) {
            (Some(u), Some(v)) => (taylor(&u, &xs.t), taylor(&v, &ys.t)),
            _ => return Err(format!("{}: different degrees", at(&xs, &ys))),
        };
        if u.len() != v.len() {
            return Err(format!("{}: different degrees", at(&xs, &ys)));
        }
        if u[0] != v[0] {
            return Err(format!("{}: different start points", at(&xs, &ys)));
        }
        // uₖ = hᵏ vₖ: h from the first nonzero order, then every order checked
        let k0 = (1..u.len())
            .find(|&k| !is_zero(&u[k]) || !is_zero(&v[k]))
            .expect("a piece that is not a point has a nonzero coefficient");
        let (uk, vk) = (&u[k0], &v[k0]);
        let h = if positively_parallel(uk, vk) {
            let ratio = if vk.x.is_zero() {
                &uk.y / &vk.y
            } else {
                &uk.x / &vk.x
            };
            rational_root(&ratio, k0 as u32)
        } else {
            None
        }
        .ok_or_else(|| format!("{}: different directions or speeds", at(&xs, &ys)))?;
        let mut hk = one.clone();
        for k in 1..u.len() {
            hk = &hk * &h;
            if u[k] != v[k].scale(&hk) {
                return Err(format!("{}: different curves", at(&xs, &ys)));
            }
        }
        // x(a + s) = y(c + h s) for s up to the end of the shorter part
        let len = (&one - &xs.t).min((&one - &ys.t) / &h);
        xs.t = &xs.t + &len;
        ys.t = &ys.t + &h * &len;
        if xs.t == one {
            xs.next();
        }
        if ys.t == one {
            ys.next();
        }
    }
    // pieces left over: single points at the other curve's end point
    for (rest, other, name) in [(&xs, &ys, "first"), (&ys, &xs, "second")] {
        if rest.done() {
            continue;
        }
        let end = other.last_point();
        let ok = rest.t.is_zero()
            && rest.pieces[rest.at..]
                .iter()
                .all(|b| is_point(b) && Some(&b.points()[0]) == end);
        if !ok {
            return Err(format!(
                "the {name} curve continues where the other ends (piece {} of {})",
                rest.at,
                rest.pieces.len()
            ));
        }
    }
    Ok(())
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::scalar::parse_rational;

    fn shape(s: &str) -> ShapeDesc {
        ShapeDesc::parse(s).unwrap()
    }

    #[test]
    fn curves_equal_up_to_splitting_elevation_and_reversal() {
        let c = shape("M 0 0 C 1 2 3 2 4 0");
        let ShapeDesc::Curve(p) = &c else {
            unreachable!()
        };
        let third = parse_rational("1/3").unwrap();
        let (l, r) = p[0].split(&third);
        let (rl, rr) = r.split(&parse_rational("5/7").unwrap());
        let split = ShapeDesc::Curve(vec![l.elevate(), rl, rr.elevate().elevate()]);
        assert!(c.same_as(&split).is_ok());
        assert!(split.same_as(&c).is_ok());
        let rev = shape("M 4 0 C 3 2 1 2 0 0");
        assert!(c.same_as(&rev).is_ok());
        // a moved control point, a missing end, a different parametrisation
        assert!(c.same_as(&shape("M 0 0 C 1 2 3 2.001 4 0")).is_err());
        assert!(c.same_as(&ShapeDesc::Curve(vec![l])).is_err());
        assert!(c.same_as(&shape("M 0 0 C 2 4 3 2 4 0")).is_err());
    }

    #[test]
    fn arcs_offsets_and_convolutions() {
        let a = shape(r#"{"arc": {"center": [0, 0], "radius": 1, "from": [1, 0], "to": [0, 1]}}"#);
        let b =
            shape(r#"{"arc": {"center": [0, 0], "radius": 1, "from": [3, 0], "to": [0, "1/2"]}}"#);
        let cw = shape(
            r#"{"arc": {"center": [0, 0], "radius": 1, "from": [1, 0], "to": [0, 1], "clockwise": true}}"#,
        );
        assert!(a.same_as(&b).is_ok());
        assert!(a.same_as(&cw).is_err());
        let o = shape(r#"{"offset": {"curve": "M 0 0 Q 1 1 2 0", "distance": "-1/2"}}"#);
        let conv = shape(
            r#"{"convolution": {"curve": {"beziers": [[[0, 0], ["1/2", "1/2"], [1, "1/2"]], [[1, "1/2"], ["3/2", "1/2"], [2, 0]]]}, "ellipse": [[0, "1/2"], ["-1/2", 0]], "side": -1}}"#,
        );
        assert!(o.same_as(&conv).is_ok());
        let other_side = shape(r#"{"offset": {"curve": "M 0 0 Q 1 1 2 0", "distance": "1/2"}}"#);
        assert!(o.same_as(&other_side).is_err());
        let reversed = shape(r#"{"offset": {"curve": "M 2 0 Q 1 1 0 0", "distance": "-1/2"}}"#);
        assert!(o.same_as(&reversed).is_err());
        assert!(o.same_as(&a).is_err());
    }

    #[test]
    fn chained_arcs_of_one_circle_are_joined_and_overlaps_are_not() {
        let arc = |f: (i64, i64), t: (i64, i64)| {
            ShapeDesc::arc(ArcDesc {
                center: V2::new(Rational::zero(), Rational::zero()),
                radius: Rational::one(),
                from: V2::new(
                    Rational::from_integer(f.0.into()),
                    Rational::from_integer(f.1.into()),
                ),
                to: V2::new(
                    Rational::from_integer(t.0.into()),
                    Rational::from_integer(t.1.into()),
                ),
            })
            .unwrap()
        };
        let u = |m: Vec<ShapeDesc>| ShapeDesc::Union(m);
        // two halves and four quarters (any order): the whole circle
        let halves = u(vec![arc((1, 0), (-1, 0)), arc((-1, 0), (1, 0))]);
        let quarters = u(vec![
            arc((0, -1), (1, 0)),
            arc((1, 0), (0, 1)),
            arc((-1, 0), (0, -1)),
            arc((0, 1), (-1, 0)),
        ]);
        assert!(halves.same_as(&quarters).is_ok());
        assert!(quarters.same_as(&halves).is_ok());
        // three quarters are not the circle; a quarter and its halves
        let three = u(vec![
            arc((1, 0), (0, 1)),
            arc((0, 1), (-1, 0)),
            arc((-1, 0), (0, -1)),
        ]);
        assert!(three.same_as(&halves).is_err());
        assert!(arc((1, 0), (-1, 0))
            .same_as(&u(vec![arc((1, 0), (0, 1)), arc((0, 1), (-1, 0))]))
            .is_ok());
        // 270° and then 180° overlap (the whole circle as a set): not the
        // quarter from (1, 0) to (0, 1) that joining the ends would give
        let overlap = u(vec![arc((1, 0), (0, -1)), arc((0, -1), (0, 1))]);
        assert!(overlap.same_as(&u(vec![arc((1, 0), (0, 1))])).is_err());
    }
}
