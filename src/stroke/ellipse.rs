//! The pen of a stroke as a quadratic form, and proven half-ellipse caps for
//! an elliptical pen (see `proofs/trimming.md`, "Elliptical pens").
//!
//! # The membership form
//!
//! A pen `E = M · disk(1)` (`Q = M Mᵀ`, [`Pen`]) contains `z` iff
//! `zᵀ Q⁻¹ z ≤ 1`, i.e. (multiplying by `det Q > 0`)
//!
//! ```text
//! g(z) = q₂₂ z_x² − 2 q₁₂ z_x z_y + q₁₁ z_y² ≤ det Q ,
//! ```
//!
//! all exact rationals. A circle of radius `r` is the form `|z|² ≤ r²`.
//! [`Form`] also carries a rational `a2_hi ≥ λ_max(Q)` (so `E ⊆ disk(√a2_hi)`)
//! and a rational `0 < b_lo ≤ √λ_min(Q)` (so `disk(b_lo) ⊆ E`), both from
//! outward-rounded interval enclosures, and floats for the estimates.
//!
//! # Caps
//!
//! The end of an open curve is closed by the half of the translated pen
//! `c + E` between the two convolution ends. In the pre-image `M⁻¹(E − c)`
//! that is a half of the unit circle: [`half_ellipse_cap`] approximates it by
//! `k` cubics with exact rational control points whose ends are rational points
//! exactly on the unit circle, proves each cubic's radial deviation `ε` and
//! that its angle is strictly monotone (so its radial projection covers its
//! arc), and maps by `M`: the cap is within `‖M‖₂ (ε + δ)` of the exact half
//! ellipse (`δ` the distance of the rational end on the unit circle to the
//! exact one).

use crate::curve::{bernstein_halves, bernstein_product, Bezier, V2};
use crate::offset::conv::Pen;
use crate::scalar::{interval_from_rational, rational_from_f64, Interval, Rational, Scalar};
use num_traits::{One, Signed, Zero};

/// The exact membership test of a pen: `z ∈ E ⇔ a z_x² + 2 b z_x z_y + c z_y² ≤ d`.
#[derive(Clone, Debug, PartialEq)]
pub struct Form {
    /// Coefficient of `z_x²`.
    pub a: Rational,
    /// Half the coefficient of `z_x z_y`.
    pub b: Rational,
    /// Coefficient of `z_y²`.
    pub c: Rational,
    /// The threshold (`> 0`).
    pub d: Rational,
    /// A rational upper bound of the squared major semi-axis.
    pub a2_hi: Rational,
    /// A rational lower bound (`> 0`) of the minor semi-axis.
    pub b_lo: Rational,
    /// The pen is a circle (`a = c = 1`, `b = 0`, `d = r²`).
    pub circle: bool,
    /// The major semi-axis, float (estimates only).
    pub reach: f64,
    /// `[a, b, c, d]` as floats (estimates only).
    pub ff: [f64; 4],
}

impl Form {
    /// The circle of radius `r > 0`: `|z|² ≤ r²`.
    ///
    /// # Examples
    /// ```
    /// use lncert::stroke::Form;
    /// use lncert::curve::V2;
    /// let q = |s: &str| lncert::parse_rational(s).unwrap();
    /// let f = Form::circle(&q("2"));
    /// assert!(f.contains(&V2::new(q("1.2"), q("1.6")))); // on the circle
    /// assert!(!f.contains(&V2::new(q("1.3"), q("1.6"))));
    /// ```
    pub fn circle(r: &Rational) -> Form {
        let one = <Rational as One>::one();
        let zero = <Rational as Zero>::zero();
        let rf = r.approx();
        Form {
            a: one.clone(),
            b: zero,
            c: one,
            d: r * r,
            a2_hi: r * r,
            b_lo: r.clone(),
            circle: true,
            reach: rf,
            ff: [1.0, 0.0, 1.0, rf * rf],
        }
    }

    /// The form of an elliptical pen; `None` when the bounds of its axes
    /// cannot be enclosed (a degenerate or extreme pen).
    ///
    /// # Examples
    /// ```
    /// use lncert::offset::{Angle, Pen};
    /// use lncert::stroke::Form;
    /// use lncert::curve::V2;
    /// let q = |s: &str| lncert::parse_rational(s).unwrap();
    /// let pen = Pen::ellipse(&q("2"), &q("1"), &Angle::parse("0").unwrap()).unwrap();
    /// let f = Form::ellipse(&pen).unwrap();
    /// assert!(f.contains(&V2::new(q("2"), q("0"))));
    /// assert!(!f.contains(&V2::new(q("0"), q("1.01"))));
    /// assert!(f.b_lo <= q("1") && f.a2_hi >= q("4"));
    /// ```
    pub fn ellipse(pen: &Pen) -> Option<Form> {
        let [q11, q12, q22] = pen.q.clone();
        let det = &q11 * &q22 - &q12 * &q12;
        if !det.is_positive() {
            return None;
        }
        let (i11, _, i22) = pen.q_interval();
        let idet = interval_from_rational(&det);
        let two = Interval::try_from((2.0, 2.0)).ok()?;
        let half_tr = (i11 + i22) / two;
        let disc = (half_tr * half_tr - idet).sqrt();
        let lmax = half_tr + disc;
        let a2_hi = rational_from_f64(lmax.sup())?;
        let b_lo_f = (idet / interval_from_rational(&a2_hi)).sqrt().inf();
        if !(b_lo_f > 0.0 && b_lo_f.is_finite()) {
            return None;
        }
        let b_lo = rational_from_f64(b_lo_f)?;
        let ff = [q22.approx(), -q12.approx(), q11.approx(), det.approx()];
        Some(Form {
            a: q22,
            b: -q12,
            c: q11,
            d: det,
            reach: lmax.mid().sqrt(),
            a2_hi,
            b_lo,
            circle: false,
            ff,
        })
    }

    /// `g(z)`, exact.
    pub fn value(&self, z: &V2<Rational>) -> Rational {
        let mut v = &self.a * &z.x * &z.x + &self.c * &z.y * &z.y;
        if !self.b.is_zero() {
            v += Rational::from_integer(2.into()) * &self.b * &z.x * &z.y;
        }
        v
    }

    /// `z ∈ E`, exact.
    pub fn contains(&self, z: &V2<Rational>) -> bool {
        self.value(z) <= self.d
    }

    /// `g(z)` in floats (estimates only).
    pub fn value_f64(&self, x: f64, y: f64) -> f64 {
        let [a, b, c, _] = self.ff;
        a * x * x + 2.0 * b * x * y + c * y * y
    }

    /// A length-like float estimate from `g` (for a circle the distance
    /// `√g`; for an ellipse `reach · √(g/d)`, the pen's gauge scaled by its
    /// major semi-axis, which equals `reach` on the boundary of the pen).
    pub fn estimate(&self, g: f64) -> f64 {
        if self.circle {
            g.sqrt()
        } else {
            self.reach * (g / self.ff[3]).sqrt()
        }
    }

    /// A proven upper bound of `‖M‖₂ = √λ_max(Q)`.
    pub fn norm_hi(&self) -> f64 {
        interval_from_rational(&self.a2_hi).sqrt().sup()
    }
}

/// A proven cap of an elliptical pen: `k` exact cubics from the start to the
/// end of the half ellipse.
#[derive(Clone, Debug)]
pub struct EllipseCap {
    /// The cubics in travel order; consecutive ones share exact end points.
    pub pieces: Vec<Bezier<Rational>>,
    /// Certified Hausdorff bound to the exact half ellipse `‖M‖₂ (ε + δ)`.
    pub error: f64,
    /// `ε`: the cubics' proven radial deviation from the unit circle (pre-image).
    pub circle_error: f64,
    /// `δ`: distance of the rational end on the unit circle to the exact end.
    pub end_error: f64,
}

fn unit_snap(dir: (f64, f64)) -> Option<V2<Rational>> {
    let zero = V2::new(<Rational as Zero>::zero(), <Rational as Zero>::zero());
    super::circle::snap(&zero, &<Rational as One>::one(), dir)
}

fn m_apply(m: &[[Rational; 2]; 2], v: &V2<Rational>) -> V2<Rational> {
    V2::new(
        &m[0][0] * &v.x + &m[0][1] * &v.y,
        &m[1][0] * &v.x + &m[1][1] * &v.y,
    )
}

fn mt_apply(m: &[[Rational; 2]; 2], v: &V2<Rational>) -> V2<Rational> {
    V2::new(
        &m[0][0] * &v.x + &m[1][0] * &v.y,
        &m[0][1] * &v.x + &m[1][1] * &v.y,
    )
}

/// A proven enclosure of the radial deviation `max ||B(t)| − 1|` of a cubic
/// in the pre-image, after checking that its angle is strictly monotone in
/// the sense `s` (`s (B × B′) > 0` on `[0, 1]`). `None` when not proven.
pub fn circle_deviation(b: &Bezier<Rational>, s: i8) -> Option<f64> {
    let (xs, ys) = b.coords();
    let (hx, hy) = b.hodograph().coords();
    let cross: Vec<Rational> = bernstein_product(&xs, &hy)
        .into_iter()
        .zip(bernstein_product(&ys, &hx))
        .map(|(p, q)| if s > 0 { p - q } else { q - p })
        .collect();
    let civ: Vec<Interval> = cross.iter().map(interval_from_rational).collect();
    let monotone = match super::trim::positive_bernstein_iv(civ, 10) {
        Some(v) => v,
        None => super::trim::positive_bernstein(cross, 10),
    };
    if !monotone {
        return None;
    }
    let xi: Vec<Interval> = xs.iter().map(interval_from_rational).collect();
    let yi: Vec<Interval> = ys.iter().map(interval_from_rational).collect();
    let one = Interval::try_from((1.0, 1.0)).ok()?;
    let g: Vec<Interval> = bernstein_product(&xi, &xi)
        .into_iter()
        .zip(bernstein_product(&yi, &yi))
        .map(|(p, q)| p + q - one)
        .collect();
    // subdivide to 2^6 pieces: min / max of the coefficients enclose g
    let mut parts = vec![g];
    for _ in 0..6 {
        parts = parts
            .iter()
            .flat_map(|p| {
                let (l, r) = bernstein_halves(p);
                [l, r]
            })
            .collect();
    }
    let lo = parts
        .iter()
        .flatten()
        .map(|c| c.inf())
        .fold(f64::INFINITY, f64::min);
    let hi = parts
        .iter()
        .flatten()
        .map(|c| c.sup())
        .fold(f64::NEG_INFINITY, f64::max);
    if !(lo > -1.0 && hi.is_finite()) {
        return None;
    }
    let lo_i = Interval::try_from((lo, lo)).ok()?;
    let hi_i = Interval::try_from((hi, hi)).ok()?;
    let below = (one - (one + lo_i).sqrt()).sup();
    let above = ((one + hi_i).sqrt() - one).sup();
    Some(below.max(above).max(0.0))
}

/// The cap of `c + E` from the pen point whose outer normal is `from` to the
/// one whose outer normal is `−from`, through the one whose outer normal is
/// `out` (the outward tangent of the curve's end), as the smallest number
/// `k ∈ 2..=16` of exact cubics whose certified error is at most `budget`
/// (or `k = 16` when none is). `None` when it cannot be proven.
///
/// # Examples
/// ```
/// use lncert::offset::{Angle, Pen};
/// use lncert::stroke::half_ellipse_cap;
/// use lncert::curve::V2;
/// let q = |s: &str| lncert::parse_rational(s).unwrap();
/// let pen = Pen::ellipse(&q("0.7"), &q("0.3"), &Angle::parse("pi/6").unwrap()).unwrap();
/// let c = V2::new(q("0"), q("0"));
/// let cap = half_ellipse_cap(&c, &pen, &V2::new(q("0"), q("-1")), &V2::new(q("1"), q("0")), 1e-3).unwrap();
/// assert!(cap.error <= 1e-3);
/// assert!(cap.pieces.len() >= 2);
/// ```
pub fn half_ellipse_cap(
    c: &V2<Rational>,
    pen: &Pen,
    from: &V2<Rational>,
    out: &V2<Rational>,
    budget: f64,
) -> Option<EllipseCap> {
    let m = &pen.m;
    let form = Form::ellipse(pen)?;
    let norm = form.norm_hi();
    let vf = mt_apply(m, from);
    let w0 = unit_snap((vf.x.approx(), vf.y.approx()))?;
    // δ = |w0 − Mᵀfrom/|Mᵀfrom||, enclosed
    let vi = vf.map(interval_from_rational);
    let len = (vi.x * vi.x + vi.y * vi.y).sqrt();
    let wi = w0.map(interval_from_rational);
    let (dx, dy) = (wi.x - vi.x / len, wi.y - vi.y / len);
    let delta = (dx * dx + dy * dy).sqrt().sup();
    // NaN or too far: no cap
    if delta.is_nan() || delta >= 1e-6 {
        return None;
    }
    // the sense: the half circle from w0 that holds Mᵀout
    let vo = mt_apply(m, out);
    let sc = w0.cross(&vo);
    let s: i8 = if sc.is_positive() {
        1
    } else if sc.is_negative() {
        -1
    } else {
        return None;
    };
    let phi0 = (w0.y.approx()).atan2(w0.x.approx());
    let mut best: Option<EllipseCap> = None;
    for k in 2..=16usize {
        let Some(cap) = cap_k(c, m, &w0, s, phi0, k, norm, delta) else {
            continue;
        };
        let ok = cap.error <= budget;
        best = Some(cap);
        if ok {
            break;
        }
    }
    best
}

#[allow(clippy::too_many_arguments)]
fn cap_k(
    c: &V2<Rational>,
    m: &[[Rational; 2]; 2],
    w0: &V2<Rational>,
    s: i8,
    phi0: f64,
    k: usize,
    norm: f64,
    delta: f64,
) -> Option<EllipseCap> {
    let sf = f64::from(s);
    let mut w = vec![w0.clone()];
    for j in 1..k {
        let phi = phi0 + sf * std::f64::consts::PI * j as f64 / k as f64;
        let wj = unit_snap((phi.cos(), phi.sin()))?;
        // strictly inside the half circle
        let side = w0.cross(&wj);
        if !(if s > 0 {
            side.is_positive()
        } else {
            side.is_negative()
        }) {
            return None;
        }
        w.push(wj);
    }
    w.push(w0.neg());
    let mut eps: f64 = 0.0;
    let mut pieces = Vec::with_capacity(k);
    let sr = Rational::from_integer(i64::from(s).into());
    for j in 0..k {
        let (p0, p3) = (&w[j], &w[j + 1]);
        let step = p0.cross(p3);
        // each step turns by less than π in the sense s
        if !(if s > 0 {
            step.is_positive()
        } else {
            step.is_negative()
        }) {
            return None;
        }
        let ang = step
            .approx()
            .abs()
            .atan2(p0.dot(p3).approx())
            .clamp(0.0, std::f64::consts::PI);
        let h = rational_from_f64(4.0 / 3.0 * (ang / 4.0).tan())?;
        let t0 = p0.rot90().scale(&(&h * &sr));
        let t3 = p3.rot90().scale(&(&h * &sr));
        let b = Bezier::new(vec![p0.clone(), p0.add(&t0), p3.sub(&t3), p3.clone()]);
        eps = eps.max(circle_deviation(&b, s)?);
        pieces.push(Bezier::new(
            b.points().iter().map(|p| c.add(&m_apply(m, p))).collect(),
        ));
    }
    let e = Interval::try_from((eps, eps)).ok()? + Interval::try_from((delta, delta)).ok()?;
    let error = (Interval::try_from((norm, norm)).ok()? * e).sup();
    Some(EllipseCap {
        pieces,
        error,
        circle_error: eps,
        end_error: delta,
    })
}

/// The exact end of the cap, enclosed: `c + Q u/√(uᵀQu)` (the pen point whose
/// outer normal is `u`).
pub fn pen_point_enclosure(c: &V2<Rational>, pen: &Pen, u: &V2<Rational>) -> V2<Interval> {
    let (q11, q12, q22) = pen.q_interval();
    let ui = u.map(interval_from_rational);
    let qx = q11 * ui.x + q12 * ui.y;
    let qy = q12 * ui.x + q22 * ui.y;
    let n = (ui.x * qx + ui.y * qy).sqrt();
    let ci = c.map(interval_from_rational);
    V2::new(ci.x + qx / n, ci.y + qy / n)
}

/// `w ∉ x ⊕ E`, proven by exact Bernstein signs of `g(w − x(t)) − d` on every
/// piece (`false`: not proven — `w` may be inside, or too close to decide).
///
/// # Examples
/// ```
/// use lncert::offset::{Angle, Pen};
/// use lncert::stroke::{outside_of, Form};
/// use lncert::curve::V2;
/// use lncert::shape::parse_curve;
/// let q = |s: &str| lncert::parse_rational(s).unwrap();
/// let x = parse_curve("M 0 0 L 2 0").unwrap();
/// let pen = Pen::ellipse(&q("1"), &q("1/2"), &Angle::parse("0").unwrap()).unwrap();
/// let f = Form::ellipse(&pen).unwrap();
/// assert!(outside_of(&x, &V2::new(q("1"), q("0.51")), &f));
/// assert!(!outside_of(&x, &V2::new(q("1"), q("0.49")), &f));
/// assert!(outside_of(&x, &V2::new(q("3.01"), q("0")), &f));
/// ```
pub fn outside_of(curve: &[Bezier<Rational>], w: &V2<Rational>, form: &Form) -> bool {
    super::trim::outside(curve, w, form)
}
