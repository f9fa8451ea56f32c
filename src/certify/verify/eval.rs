//! The verifier's own evaluation: second-order Taylor triples over inari
//! intervals, de Casteljau, the arc and offset/convolution formulas, and the
//! bound of one box. Nothing here is shared with the search.

use crate::scalar::interval_from_rational;
use crate::scalar::{rational_from_f64, Interval, Rational};

// ----- Taylor triples (value, d/ds, d²/ds²) over intervals -------------------

#[derive(Clone, Copy)]
struct T3([Interval; 3]);

pub(crate) fn ic(x: i64) -> Interval {
    Interval::try_from((x as f64, x as f64)).expect("small integer")
}

impl T3 {
    fn c(v: Interval) -> T3 {
        T3([v, ic(0), ic(0)])
    }
    fn add(self, o: T3) -> T3 {
        T3([self.0[0] + o.0[0], self.0[1] + o.0[1], self.0[2] + o.0[2]])
    }
    fn sub(self, o: T3) -> T3 {
        T3([self.0[0] - o.0[0], self.0[1] - o.0[1], self.0[2] - o.0[2]])
    }
    fn mul(self, o: T3) -> T3 {
        let [a, b, c] = self.0;
        let [x, y, z] = o.0;
        T3([a * x, a * y + b * x, a * z + ic(2) * b * y + c * x])
    }
    fn k(self, s: Interval) -> T3 {
        T3([self.0[0] * s, self.0[1] * s, self.0[2] * s])
    }
    /// `1/self`; `None` if the value may vanish.
    fn inv(self) -> Option<T3> {
        let [a, b, c] = self.0;
        if a.contains(0.0) || a.is_empty() {
            return None;
        }
        let r = ic(1) / a;
        Some(T3([r, -b * r * r, ic(2) * b * b * r * r * r - c * r * r]))
    }
    /// `√self`; `None` if the value may be ≤ 0.
    fn sqrt(self) -> Option<T3> {
        let [a, b, c] = self.0;
        if !(a.inf() > 0.0) {
            return None;
        }
        let w = a.sqrt();
        let h = ic(1) / (ic(2) * w);
        Some(T3([w, b * h, c * h - b * b * h * h * h * ic(2)]))
    }
}

// ----- shapes ------------------------------------------------------------------

/// One piece of a shape, with interval data.
pub(crate) enum VPiece {
    Poly(Vec<[Interval; 2]>),
    Arc {
        c: [Interval; 2],
        r: Interval,
        e0: [Interval; 2],
    },
    Conv {
        pts: Vec<[Interval; 2]>,
        hod: Vec<[Interval; 2]>,
        q: [Interval; 3],
        sigma: Interval,
    },
}

/// A shape as the verifier reads it.
pub(crate) struct VShape {
    pub pieces: Vec<VPiece>,
    /// Exact end of each piece's domain as an enclosure (1 for polynomial pieces).
    pub ends: Vec<Interval>,
    /// What the shape is, in words, from the exact data.
    pub text: String,
}

fn casteljau(pts: &[[Interval; 2]], t: T3) -> [T3; 2] {
    let mut x: Vec<T3> = pts.iter().map(|p| T3::c(p[0])).collect();
    let mut y: Vec<T3> = pts.iter().map(|p| T3::c(p[1])).collect();
    for n in (1..pts.len()).rev() {
        for i in 0..n {
            x[i] = x[i].add(t.mul(x[i + 1].sub(x[i])));
            y[i] = y[i].add(t.mul(y[i + 1].sub(y[i])));
        }
    }
    [x[0], y[0]]
}

impl VPiece {
    fn at(&self, t: T3) -> Option<[T3; 2]> {
        match self {
            VPiece::Poly(p) => Some(casteljau(p, t)),
            VPiece::Arc { c, r, e0 } => {
                let one = T3::c(ic(1));
                let t2 = t.mul(t);
                let a = one.sub(t2);
                let d = one.add(t2);
                let inv = d.mul(d).inv()?;
                let cs = a.mul(a).sub(t2.k(ic(4))).mul(inv);
                let sn = t.mul(a).k(ic(4)).mul(inv);
                Some([
                    T3::c(c[0]).add(cs.k(e0[0]).sub(sn.k(e0[1])).k(*r)),
                    T3::c(c[1]).add(cs.k(e0[1]).add(sn.k(e0[0])).k(*r)),
                ])
            }
            VPiece::Conv { pts, hod, q, sigma } => {
                let [x, y] = casteljau(pts, t);
                let [dx, dy] = casteljau(hod, t);
                let (n1, n2) = (T3::c(ic(0)).sub(dy), dx);
                let m1 = n1.k(q[0]).add(n2.k(q[1]));
                let m2 = n1.k(q[1]).add(n2.k(q[2]));
                let s = n1.mul(m1).add(n2.mul(m2)).sqrt()?.inv()?;
                Some([x.add(m1.mul(s).k(*sigma)), y.add(m2.mul(s).k(*sigma))])
            }
        }
    }
}

impl VPiece {
    /// The point at the parameter enclosure `t` (tests compare it with the
    /// search's evaluation).
    #[cfg(test)]
    pub(crate) fn point_at(&self, t: Interval) -> Option<[Interval; 2]> {
        self.at(T3([t, ic(1), ic(0)]))
            .map(|[x, y]| [x.0[0], y.0[0]])
    }
}

pub(crate) fn le_rational(x: f64, r: &Rational) -> bool {
    rational_from_f64(x).is_some_and(|q| &q <= r)
}

/// Checks one box; `Ok(bound)` or the reason it fails.
#[allow(clippy::too_many_arguments)]
pub(crate) fn check_box(
    src: &VPiece,
    s0: &Rational,
    s1: &Rational,
    dst: &VPiece,
    dst_end: Interval,
    t: &Rational,
    k: &Rational,
) -> Result<f64, String> {
    let two = Rational::from_integer(2.into());
    let sc = (s0 + s1) / &two;
    let (i0, i1) = (interval_from_rational(s0), interval_from_rational(s1));
    let sbox = Interval::try_from((i0.inf(), i1.sup())).map_err(|_| "empty box".to_string())?;
    let scv = interval_from_rational(&sc);
    let (tv, kv) = (interval_from_rational(t), interval_from_rational(k));
    let tau = tv + kv * (sbox - scv);
    if !(tau.inf() >= 0.0 && tau.sup() <= dst_end.inf()) {
        return Err(format!(
            "the foot map leaves the target's parameter domain: τ(S) ⊆ [{}, {}]",
            tau.inf(),
            tau.sup()
        ));
    }
    let undefined = || "the shapes cannot be evaluated on this box (undefined normal)".to_string();
    let d2 = |sv: Interval, tauv: Interval| -> Option<T3> {
        let a = src.at(T3([sv, ic(1), ic(0)]))?;
        let b = dst.at(T3([tauv, kv, ic(0)]))?;
        let (dx, dy) = (a[0].sub(b[0]), a[1].sub(b[1]));
        Some(dx.mul(dx).add(dy.mul(dy)))
    };
    let over = d2(sbox, tau).ok_or_else(undefined)?;
    let at_c = d2(scv, tv).ok_or_else(undefined)?;
    let h = (sbox - scv).mag();
    let h = Interval::try_from((h, h)).map_err(|_| undefined())?;
    let curv = Interval::try_from((0.0, over.0[2].sup().max(0.0))).map_err(|_| undefined())?;
    let taylor = at_c.0[0] + at_c.0[1].abs() * h + curv * h * h / ic(2);
    let g = taylor.sup().min(over.0[0].sup());
    if !g.is_finite() {
        return Err(undefined());
    }
    Ok(Interval::try_from((0.0, g.max(0.0)))
        .map_err(|_| undefined())?
        .sqrt()
        .sup())
}
