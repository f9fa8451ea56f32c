//! The independent certificate checker behind `lncert verify`.
//!
//! It shares nothing with the search but the scalar layer (inari intervals,
//! exact rationals and their parser): its own reader of the canonical shapes, its
//! own de Casteljau evaluation, arc and offset formulas and its own second-order
//! Taylor arithmetic. It never searches: it walks the boxes of the certificate,
//! checks that they cover every parameter domain exactly (rational comparisons),
//! that each foot map stays inside its target's domain, and that the recomputed
//! bound of each box is ≤ the tolerance; the first failure is reported with its
//! direction and box index.

use super::cert::{digest_of, FORMAT, VERSION};
use crate::scalar::{
    interval_from_rational, parse_rational, rational_from_f64, Interval, Rational,
};
use num_traits::{One, Signed, Zero};
use serde_json::Value;

/// Why a certificate is invalid.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct Invalid {
    /// Where: a field, or `directions[d].boxes[i]`.
    pub at: String,
    /// What failed.
    pub reason: String,
}

impl std::fmt::Display for Invalid {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        write!(f, "{}: {}", self.at, self.reason)
    }
}

/// A valid certificate's figures.
#[derive(Clone, Debug, PartialEq)]
pub struct Valid {
    /// The tolerance proven.
    pub tol: Rational,
    /// The largest recomputed box bound (an upper bound on the Hausdorff distance).
    pub max_bound: f64,
    /// Boxes checked.
    pub boxes: usize,
}

fn inv(at: impl Into<String>, reason: impl Into<String>) -> Invalid {
    Invalid {
        at: at.into(),
        reason: reason.into(),
    }
}

// ----- Taylor triples (value, d/ds, d²/ds²) over intervals -------------------

#[derive(Clone, Copy)]
struct T3([Interval; 3]);

fn ic(x: i64) -> Interval {
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

enum VPiece {
    Poly(Vec<[Interval; 2]>),
    Arc {
        c: [Interval; 2],
        r: Interval,
        e0: [Interval; 2],
    },
    Conv {
        pts: Vec<[Interval; 2]>,
        q: [Interval; 3],
        sigma: Interval,
    },
}

struct VShape {
    pieces: Vec<VPiece>,
    /// Exact end of each piece's domain as an enclosure (1 for polynomial pieces).
    ends: Vec<Interval>,
}

fn num(v: &Value, at: &str) -> Result<Rational, Invalid> {
    let s = v
        .as_str()
        .ok_or_else(|| inv(at, "expected an exact rational string"))?;
    parse_rational(s).map_err(|e| inv(at, e.to_string()))
}

fn pt(v: &Value, at: &str) -> Result<[Rational; 2], Invalid> {
    match v.as_array().map(Vec::as_slice) {
        Some([x, y]) => Ok([num(x, &format!("{at}[0]"))?, num(y, &format!("{at}[1]"))?]),
        _ => Err(inv(at, "expected [x, y]")),
    }
}

fn ivp(p: &[Rational; 2]) -> [Interval; 2] {
    [interval_from_rational(&p[0]), interval_from_rational(&p[1])]
}

fn beziers(v: &Value, at: &str) -> Result<Vec<Vec<[Rational; 2]>>, Invalid> {
    let list = v
        .get("beziers")
        .and_then(Value::as_array)
        .filter(|l| !l.is_empty() && l.len() <= 100_000)
        .ok_or_else(|| inv(at, "expected {\"beziers\": [...]} with 1 to 100000 pieces"))?;
    list.iter()
        .enumerate()
        .map(|(i, b)| {
            let pts = b
                .as_array()
                .filter(|p| (2..=64).contains(&p.len()))
                .ok_or_else(|| {
                    inv(
                        format!("{at}.beziers[{i}]"),
                        "expected 2 to 64 control points",
                    )
                })?;
            pts.iter()
                .enumerate()
                .map(|(k, p)| pt(p, &format!("{at}.beziers[{i}][{k}]")))
                .collect()
        })
        .collect()
}

fn hodograph(p: &[[Rational; 2]]) -> Vec<[Rational; 2]> {
    let n = Rational::from_integer(((p.len() - 1) as i64).into());
    p.windows(2)
        .map(|w| [&n * (&w[1][0] - &w[0][0]), &n * (&w[1][1] - &w[0][1])])
        .collect()
}

fn read_shape(v: &Value, at: &str) -> Result<VShape, Invalid> {
    let one = ic(1);
    if let Some(a) = v.get("arc") {
        let c = pt(&a["center"], &format!("{at}.arc.center"))?;
        let r = num(&a["radius"], &format!("{at}.arc.radius"))?;
        let d0 = pt(&a["from"], &format!("{at}.arc.from"))?;
        let d1 = pt(&a["to"], &format!("{at}.arc.to"))?;
        if !r.is_positive() {
            return Err(inv(format!("{at}.arc.radius"), "must be > 0"));
        }
        let unit = |d: &[Rational; 2]| -> Option<[Interval; 2]> {
            let [x, y] = ivp(d);
            let n = (x * x + y * y).sqrt();
            (n.inf() > 0.0).then(|| [x / n, y / n])
        };
        let bad = || inv(format!("{at}.arc"), "degenerate directions");
        let (e0, e1) = (unit(&d0).ok_or_else(bad)?, unit(&d1).ok_or_else(bad)?);
        // tan(Θ/4) from the half-angle: sin(Θ/2) = |e1 − e0|/2, |cos(Θ/2)| = |e1 + e0|/2.
        let two = ic(2);
        let sh = ((e1[0] - e0[0]).sqr() + (e1[1] - e0[1]).sqr()).sqrt() / two;
        let ch = ((e1[0] + e0[0]).sqr() + (e1[1] + e0[1]).sqr()).sqrt() / two;
        let cross = &d0[0] * &d1[1] - &d0[1] * &d1[0];
        let dot = &d0[0] * &d1[0] + &d0[1] * &d1[1];
        let u = if cross.is_positive() {
            sh / (one + ch)
        } else if cross.is_zero() && dot.is_negative() {
            one
        } else if cross.is_zero() {
            return Err(inv(format!("{at}.arc"), "zero sweep"));
        } else {
            if sh.contains(0.0) {
                return Err(inv(format!("{at}.arc"), "sweep too close to 2π"));
            }
            (one + ch) / sh
        };
        if !(u.inf() > 0.0 && u.sup().is_finite()) {
            return Err(inv(format!("{at}.arc"), "cannot enclose the end parameter"));
        }
        return Ok(VShape {
            pieces: vec![VPiece::Arc {
                c: ivp(&c),
                r: interval_from_rational(&r),
                e0,
            }],
            ends: vec![u],
        });
    }
    let conv = |curve: &Value, q: [Rational; 3], sigma: i64, at: &str| -> Result<VShape, Invalid> {
        let bs = beziers(curve, &format!("{at}.curve"))?;
        let qi = [
            interval_from_rational(&q[0]),
            interval_from_rational(&q[1]),
            interval_from_rational(&q[2]),
        ];
        Ok(VShape {
            ends: vec![one; bs.len()],
            pieces: bs
                .iter()
                .map(|b| {
                    let mut pts: Vec<[Interval; 2]> = b.iter().map(ivp).collect();
                    // the hodograph's points follow the curve's, after a marker count
                    pts.extend(hodograph(b).iter().map(ivp));
                    VPiece::Conv {
                        pts,
                        q: qi,
                        sigma: ic(sigma),
                    }
                })
                .collect(),
        })
    };
    if let Some(o) = v.get("offset") {
        let r = num(&o["distance"], &format!("{at}.offset.distance"))?;
        if r.is_zero() {
            return Err(inv(format!("{at}.offset.distance"), "must be nonzero"));
        }
        let r2 = &r * &r;
        let sigma = if r.is_positive() { 1 } else { -1 };
        return conv(
            &o["curve"],
            [r2.clone(), Rational::zero(), r2],
            sigma,
            &format!("{at}.offset"),
        );
    }
    if let Some(c) = v.get("convolution") {
        let at2 = format!("{at}.convolution");
        let rows = c["ellipse"]
            .as_array()
            .filter(|r| r.len() == 2)
            .ok_or_else(|| inv(&at2, "bad ellipse"))?;
        let r0 = pt(&rows[0], &format!("{at2}.ellipse[0]"))?;
        let r1 = pt(&rows[1], &format!("{at2}.ellipse[1]"))?;
        let side = match c["side"].as_i64() {
            Some(1) => 1,
            Some(-1) => -1,
            _ => return Err(inv(format!("{at2}.side"), "expected 1 or -1")),
        };
        let q = [
            &r0[0] * &r0[0] + &r0[1] * &r0[1],
            &r0[0] * &r1[0] + &r0[1] * &r1[1],
            &r1[0] * &r1[0] + &r1[1] * &r1[1],
        ];
        return conv(&c["curve"], q, side, &at2);
    }
    let bs = beziers(v, at)?;
    Ok(VShape {
        ends: vec![one; bs.len()],
        pieces: bs
            .iter()
            .map(|b| VPiece::Poly(b.iter().map(ivp).collect()))
            .collect(),
    })
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
            VPiece::Conv { pts, q, sigma } => {
                // pts holds n+1 curve points followed by n hodograph points
                let n = (pts.len() - 1) / 2;
                let [x, y] = casteljau(&pts[..=n], t);
                let [dx, dy] = casteljau(&pts[n + 1..], t);
                let (n1, n2) = (T3::c(ic(0)).sub(dy), dx);
                let m1 = n1.k(q[0]).add(n2.k(q[1]));
                let m2 = n1.k(q[1]).add(n2.k(q[2]));
                let s = n1.mul(m1).add(n2.mul(m2)).sqrt()?.inv()?;
                Some([x.add(m1.mul(s).k(*sigma)), y.add(m2.mul(s).k(*sigma))])
            }
        }
    }
}

fn le_rational(x: f64, r: &Rational) -> bool {
    rational_from_f64(x).is_some_and(|q| &q <= r)
}

/// Checks one box; `Ok(bound)` or the reason it fails.
#[allow(clippy::too_many_arguments)]
fn check_box(
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

/// Verifies a certificate document.
///
/// # Examples
/// ```
/// use lncert::certify::{hausdorff, Certificate, Config, ShapeDesc};
/// use lncert::certify::verify::verify;
/// use lncert::scalar::parse_rational;
/// let a = ShapeDesc::parse("M 0 0 Q 0.5 0.5 1 0").unwrap();
/// let b = ShapeDesc::parse("M 0 0 L 1 0").unwrap();
/// let tol = parse_rational("0.26").unwrap();
/// let r = hausdorff(&a, &b, &Config { tol: Some(0.26), ..Config::default() }).unwrap();
/// let cert = Certificate::new(&a, &b, &tol, &r).unwrap();
/// assert!(verify(&cert.doc).is_ok());
/// let mut forged = cert.doc.clone();
/// forged["tol"] = "1/5".into(); // 0.2 < 1/4: false claim
/// assert!(verify(&forged).is_err());
/// ```
pub fn verify(doc: &Value) -> Result<Valid, Invalid> {
    if doc["format"].as_str() != Some(FORMAT) {
        return Err(inv("format", format!("expected \"{FORMAT}\"")));
    }
    if doc["version"].as_u64() != Some(VERSION) {
        return Err(inv(
            "version",
            format!("unsupported; this verifier reads version {VERSION}"),
        ));
    }
    match doc["digest"].as_str() {
        Some(d) if d == digest_of(doc) => {}
        Some(_) => {
            return Err(inv(
                "digest",
                "does not match the content: the certificate was altered",
            ))
        }
        None => return Err(inv("digest", "missing")),
    }
    let tol = num(&doc["tol"], "tol")?;
    if tol.is_negative() {
        return Err(inv("tol", "negative"));
    }
    let shapes = [read_shape(&doc["a"], "a")?, read_shape(&doc["b"], "b")?];
    let dirs = doc["directions"]
        .as_array()
        .filter(|d| d.len() == 2)
        .ok_or_else(|| inv("directions", "expected the two directions a→b and b→a"))?;
    let mut max_bound = 0.0f64;
    let mut count = 0;
    for (di, (from, to)) in [(0usize, 1usize), (1, 0)].into_iter().enumerate() {
        let names = ["a", "b"];
        let d = &dirs[di];
        if d["from"].as_str() != Some(names[from]) || d["to"].as_str() != Some(names[to]) {
            return Err(inv(
                format!("directions[{di}]"),
                format!("expected from {} to {}", names[from], names[to]),
            ));
        }
        let boxes = d["boxes"]
            .as_array()
            .ok_or_else(|| inv(format!("directions[{di}].boxes"), "missing"))?;
        let (src, dst) = (&shapes[from], &shapes[to]);
        // coverage: per piece, boxes in increasing order, contiguous, from 0 to ≥ the end
        let mut cursor: Vec<Option<Rational>> = vec![Some(Rational::zero()); src.pieces.len()];
        let mut last_piece = 0usize;
        for (bi, bx) in boxes.iter().enumerate() {
            let at = format!("directions[{di}].boxes[{bi}]");
            let piece = bx["piece"]
                .as_u64()
                .map(|p| p as usize)
                .filter(|&p| p < src.pieces.len());
            let target = bx["target"]
                .as_u64()
                .map(|p| p as usize)
                .filter(|&p| p < dst.pieces.len());
            let (Some(piece), Some(target)) = (piece, target) else {
                return Err(inv(at, "piece or target index out of range"));
            };
            if piece < last_piece {
                return Err(inv(at, "boxes are not ordered by piece"));
            }
            last_piece = piece;
            let s = bx["s"]
                .as_array()
                .filter(|s| s.len() == 2)
                .ok_or_else(|| inv(&at, "expected s: [s0, s1]"))?;
            let (s0, s1) = (
                num(&s[0], &format!("{at}.s[0]"))?,
                num(&s[1], &format!("{at}.s[1]"))?,
            );
            match &cursor[piece] {
                Some(c) if *c == s0 && s0 < s1 => {}
                Some(c) => {
                    return Err(inv(at, format!("gap or overlap in the cover of piece {piece}: expected a box starting at {c}, ending after it")))
                }
                None => return Err(inv(at, format!("piece {piece} is already covered"))),
            }
            let end = src.ends[piece];
            cursor[piece] = if le_rational(end.sup(), &s1) {
                None
            } else {
                Some(s1.clone())
            };
            let t = num(&bx["t"], &format!("{at}.t"))?;
            let k = num(&bx["k"], &format!("{at}.k"))?;
            let bound = check_box(
                &src.pieces[piece],
                &s0,
                &s1,
                &dst.pieces[target],
                dst.ends[target],
                &t,
                &k,
            )
            .map_err(|r| inv(&at, r))?;
            if !le_rational(bound, &tol) {
                return Err(inv(
                    at,
                    format!(
                        "the recomputed bound {bound:e} exceeds the tolerance {}",
                        tol
                    ),
                ));
            }
            max_bound = max_bound.max(bound);
            count += 1;
        }
        if let Some(p) = cursor.iter().position(Option::is_some) {
            return Err(inv(
                format!("directions[{di}].boxes"),
                format!("piece {p} of {} is not covered to its end", names[from]),
            ));
        }
    }
    let _ = Rational::one();
    Ok(Valid {
        tol,
        max_bound,
        boxes: count,
    })
}
