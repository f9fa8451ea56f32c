//! Transforms: the exact affine maps of SVG's `transform` attribute, the
//! exactly rational rotations and skews that replace irrational ones, and the
//! certified displacement of that replacement over an element.

use super::{err, CurveParseError, TRANSFORM_TARGET};
use crate::curve::{Bezier, V2};
use crate::scalar::{interval_from_rational, rational_from_f64, Interval, Rational};
use crate::shape::io::svg_number_list;
use crate::shape::svgarc::{format_up, rational_sqrt, ApproxKind};
use num_traits::{One, Signed, Zero};

/// An affine map `(x, y) ↦ (a x + c y + e, b x + d y + f)`, SVG's
/// `matrix(a b c d e f)`.
#[derive(Clone, Debug, PartialEq)]
pub(super) struct Affine(pub(super) [Rational; 6]);

impl Affine {
    pub(super) fn identity() -> Self {
        let (o, z) = (Rational::one(), Rational::zero());
        Affine([o.clone(), z.clone(), z.clone(), o, z.clone(), z])
    }
    /// `self ∘ other` (apply `other` first).
    pub(super) fn then_inner(&self, o: &Affine) -> Affine {
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
    pub(super) fn apply(&self, p: &V2<Rational>) -> V2<Rational> {
        let [a, b, c, d, e, f] = &self.0;
        V2::new(a * &p.x + c * &p.y + e, b * &p.x + d * &p.y + f)
    }
    /// An upper bound of `‖L‖₂` for the linear part `L`, its largest singular
    /// value `√((s + √(s² − 4 det²))/2)`, `s = a² + b² + c² + d²`, enclosed
    /// from the exact `s` and `s² − 4 det² ≥ 0`: `d_H(T X, T Y) ≤ ‖L‖₂ d_H(X, Y)`.
    pub(super) fn norm_sup(&self) -> f64 {
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
    /// The scale of the linear part when it is a similarity (rotation or
    /// reflection times a scale) with a rational scale factor.
    pub(super) fn similarity_scale(&self) -> Option<Rational> {
        let [a, b, c, d, _, _] = &self.0;
        let conformal = (a == d && *b == -c.clone()) || (*a == -d.clone() && b == c);
        if !conformal {
            return None;
        }
        rational_sqrt(&(a * a + b * b))
    }
}

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
pub(super) fn rational_rotation(deg: &Rational) -> Result<(Rational, Rational, f64), String> {
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

pub(super) fn to_f64(r: &Rational) -> f64 {
    <Rational as crate::scalar::Scalar>::approx(r)
}

pub(super) fn point(x: f64) -> Interval {
    Interval::try_from((x, x)).unwrap_or(Interval::ENTIRE)
}

/// What one factor of a transform list approximated: for every point `p`,
/// `|F(p) − F′(p)| ≤ err · |p − centre|`, `F` the exact map, `F′` the
/// rational one; `lip` bounds the exact map's Lipschitz constant.
#[derive(Clone, Debug)]
pub(super) struct FactorApprox {
    pub(super) kind: ApproxKind,
    err: f64,
    centre: V2<Rational>,
    lip: f64,
    pub(super) detail: String,
}

/// One factor of the transforms above an element, with the rational map used.
#[derive(Clone, Debug)]
pub(super) struct Factor {
    pub(super) m: Affine,
    pub(super) approx: Option<FactorApprox>,
}

pub(super) fn translation(x: &Rational, y: &Rational) -> Affine {
    let (o, z) = (Rational::one(), Rational::zero());
    Affine([o.clone(), z.clone(), z, o, x.clone(), y.clone()])
}

/// Reads an SVG `transform` attribute into its factors (outermost first;
/// consecutive exact ones merged).
pub(super) fn parse_transform(text: &str, at: &str) -> Result<Vec<Factor>, CurveParseError> {
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
        let z = Rational::zero();
        let (f, approx) = match (name, args.as_slice()) {
            ("matrix", [a, b, c, d, e, f]) => (
                Affine([
                    a.clone(),
                    b.clone(),
                    c.clone(),
                    d.clone(),
                    e.clone(),
                    f.clone(),
                ]),
                None,
            ),
            ("translate", [x]) => (translation(x, &z), None),
            ("translate", [x, y]) => (translation(x, y), None),
            ("scale", [s]) => (
                Affine([s.clone(), z.clone(), z.clone(), s.clone(), z.clone(), z]),
                None,
            ),
            ("scale", [sx, sy]) => (
                Affine([sx.clone(), z.clone(), z.clone(), sy.clone(), z.clone(), z]),
                None,
            ),
            ("rotate", [a, centre @ ..]) if centre.is_empty() || centre.len() == 2 => {
                rotate_factor(a, centre, at)?
            }
            ("skewX" | "skewY", [a]) if a.is_zero() => (Affine::identity(), None),
            ("skewX" | "skewY", [a]) => skew_factor(name, a, at)?,
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

/// `rotate(a)` or `rotate(a cx cy)`: exact for a multiple of 90°, otherwise
/// the exactly rational rotation, with what it approximated.
fn rotate_factor(
    a: &Rational,
    centre: &[Rational],
    at: &str,
) -> Result<(Affine, Option<FactorApprox>), CurveParseError> {
    let z = Rational::zero();
    let mut approx = None;
    let (c, s) = match quarter_turn(a) {
        Some(cs) => cs,
        None => {
            let (c, s, e) =
                rational_rotation(a).map_err(|reason| err(at, format!("rotate({a}): {reason}")))?;
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
    let m = match centre {
        [cx, cy] => translation(cx, cy)
            .then_inner(&r)
            .then_inner(&translation(&-cx.clone(), &-cy.clone())),
        _ => r,
    };
    Ok((m, approx))
}

/// `skewX(a)` or `skewY(a)` (`name`), `a` not 0: the rational tangent, with
/// what it approximated (nothing when it is exact).
fn skew_factor(
    name: &str,
    a: &Rational,
    at: &str,
) -> Result<(Affine, Option<FactorApprox>), CurveParseError> {
    let (o, z) = (Rational::one(), Rational::zero());
    let (t, e) = rational_tan(a).map_err(|reason| err(at, format!("{name}({a}): {reason}")))?;
    let m = if name == "skewX" {
        Affine([o.clone(), z.clone(), t.clone(), o, z.clone(), z.clone()])
    } else {
        Affine([o.clone(), t.clone(), z.clone(), o, z.clone(), z.clone()])
    };
    let approx = (e > 0.0).then(|| FactorApprox {
        kind: ApproxKind::Skew,
        err: e,
        centre: V2::new(z.clone(), z),
        lip: (point(m.norm_sup()) + point(e)).sup(),
        detail: format!("{name}({a}) with tan = {t}, |tan θ − t| ≤ {}", format_up(e)),
    });
    Ok((m, approx))
}

/// A certified upper bound of `sup |M(p) − M′(p)|` over the exact element
/// `E`, `M` the exact composition of `factors` (outermost first) and `M′` the
/// rational one, given the element's pieces `B` (in its own coordinates) and
/// `b ≥ d_H(E, B)`. With `Hᵢ` the map exact in the factors above `i` and
/// rational from `i` down, `M − M′ = Σᵢ (Hᵢ₋₁ − Hᵢ)` and
/// `|Hᵢ₋₁(p) − Hᵢ(p)| ≤ Lip(Fₖ ∘ … ∘ Fᵢ₊₁) · errᵢ · |qᵢ − cᵢ|`,
/// `qᵢ = F′ᵢ₋₁ ∘ … ∘ F′₁(p)`; `|qᵢ − cᵢ|` is at most its largest value over
/// the control points of the mapped pieces (convexity) plus `‖F′ᵢ₋₁ ⋯ F′₁‖ b`.
pub(super) fn displacement(factors: &[Factor], pieces: &[Bezier<Rational>], b: f64) -> f64 {
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
