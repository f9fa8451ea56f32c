//! The verifier's strict reader of the canonical shape form (certificate
//! format 2). It accepts exactly the canonical documents that
//! [`ShapeDesc::to_json`](crate::shape::ShapeDesc::to_json) writes and
//! nothing else; the specification is in `proofs/certify-hausdorff.md`
//! ("The canonical shape form"). Every rejection names the field.

use super::eval::{ic, Exact, VPiece, VShape};
use super::{inv, Invalid};
use crate::json::Json;
use crate::scalar::{abs_le_pow10, interval_from_rational, Interval, Rational};
use crate::shape::io::{MAX_CONTROL_POINTS, MAX_NUMBER_CHARS, MAX_SEGMENTS};
use num_bigint::BigInt;
use num_traits::{Signed, Zero};

/// `|x| ≤ 10^MAX_EXPONENT10` for every number of a certificate (the shape
/// language's coordinate limit, `1e100`, compared exactly).
pub(crate) const MAX_EXPONENT10: u32 = 100;

/// Reads a canonical rational string: `"0"`, `"-3"`, `"7/2"` — lowest terms,
/// denominator ≥ 2 when written, no `+`, no leading zeros, no `-0`, at most
/// `MAX_NUMBER_CHARS` characters, magnitude ≤ 10¹⁰⁰.
pub(crate) fn canonical_rational(v: &Json, at: &str) -> Result<Rational, Invalid> {
    let s = v.as_str().ok_or_else(|| {
        inv(
            at,
            format!(
                "expected an exact rational string such as \"-7/2\", found {}",
                v.describe()
            ),
        )
    })?;
    if s.len() > MAX_NUMBER_CHARS {
        return Err(inv(
            at,
            format!("longer than the limit of {MAX_NUMBER_CHARS} characters"),
        ));
    }
    let (num, den) = match s.split_once('/') {
        Some((n, d)) => (n, Some(d)),
        None => (s, None),
    };
    let digits_ok = |d: &str| {
        !d.is_empty() && d.bytes().all(|c| c.is_ascii_digit()) && (d == "0" || !d.starts_with('0'))
    };
    let bare = num.strip_prefix('-').unwrap_or(num);
    if !digits_ok(bare) || !den.is_none_or(digits_ok) {
        return Err(inv(
            at,
            format!("{s:?} is not a canonical rational (\"p\" or \"p/q\", digits only)"),
        ));
    }
    let n: BigInt = int(num).ok_or_else(|| inv(at, "unreadable integer"))?;
    let noncanonical = |r: &Rational| {
        inv(
            at,
            format!(
                "{s:?} is not in canonical form: write it as \"{r}\" (lowest terms, no -0, no /1)"
            ),
        )
    };
    // The digits are canonical (checked above); the value is in canonical form
    // iff it is not "-0", and a written denominator is ≥ 2, coprime to the
    // numerator, with a nonzero numerator (the test is cheap for the powers of
    // two lncert writes: then coprime means odd).
    let r = match den {
        None if num == "-0" => return Err(noncanonical(&Rational::zero())),
        None => Rational::from_integer(n),
        Some(d) => {
            let d: BigInt = int(d).ok_or_else(|| inv(at, "unreadable integer"))?;
            if d.is_zero() {
                return Err(inv(at, "zero denominator"));
            }
            let bits = d.bits();
            let coprime = if d.trailing_zeros() == Some(bits - 1) {
                n.trailing_zeros() == Some(0)
            } else {
                num_integer::Integer::gcd(&n, &d) == BigInt::from(1)
            };
            if !coprime || d == BigInt::from(1) || n.is_zero() {
                return Err(noncanonical(&Rational::new(n, d)));
            }
            Rational::new_raw(n, d)
        }
    };
    if !abs_le_pow10(&r, MAX_EXPONENT10) {
        return Err(inv(at, "magnitude above the limit 1e100"));
    }
    Ok(r)
}

/// A decimal integer (optional `-`, digits checked by the caller): through
/// `i64` when it has at most 18 digits (every number lncert writes but the
/// long ones), which is several times faster than the general reader.
fn int(s: &str) -> Option<BigInt> {
    if s.len() <= 18 {
        s.parse::<i64>().ok().map(BigInt::from)
    } else {
        s.parse().ok()
    }
}

/// A canonical non-negative integer (a JSON number token such as `0` or `17`).
pub(crate) fn canonical_index(v: &Json, at: &str) -> Result<usize, Invalid> {
    match v {
        Json::Number(t)
            if t.len() <= 12
                && t.bytes().all(|c| c.is_ascii_digit())
                && (&**t == "0" || !t.starts_with('0')) =>
        {
            t.parse()
                .map_err(|_| inv(at, "expected a non-negative integer"))
        }
        other => Err(inv(
            at,
            format!(
                "expected a non-negative integer such as 3, found {}",
                match other {
                    Json::Number(t) => format!("the number {t}"),
                    o => o.describe(),
                }
            ),
        )),
    }
}

/// The members of an object with exactly the keys `keys` (all required).
pub(crate) fn exact_object<'j, 'a, const N: usize>(
    v: &'j Json<'a>,
    at: &str,
    keys: [&str; N],
) -> Result<[&'j Json<'a>; N], Invalid> {
    let m = v.as_object().ok_or_else(|| {
        inv(
            at,
            format!(
                "expected an object with the keys {keys:?}, found {}",
                v.describe()
            ),
        )
    })?;
    if let Some((k, _)) = m.iter().find(|(k, _)| !keys.iter().any(|x| k == x)) {
        return Err(inv(
            join(at, &k.text()),
            format!("unknown key: the canonical form has exactly the keys {keys:?}"),
        ));
    }
    let mut out = [v; N];
    for (i, key) in keys.iter().enumerate() {
        out[i] = v.get(key).ok_or_else(|| inv(join(at, key), "missing"))?;
    }
    Ok(out)
}

pub(crate) fn join(at: &str, key: &str) -> String {
    if at.is_empty() {
        key.to_string()
    } else {
        format!("{at}.{key}")
    }
}

fn point(v: &Json, at: &str) -> Result<[Rational; 2], Invalid> {
    match v.as_array() {
        Some([x, y]) => Ok([
            canonical_rational(x, &format!("{at}[0]"))?,
            canonical_rational(y, &format!("{at}[1]"))?,
        ]),
        _ => Err(inv(at, format!("expected [x, y], found {}", v.describe()))),
    }
}

fn ivp(p: &[Rational; 2]) -> [Interval; 2] {
    [interval_from_rational(&p[0]), interval_from_rational(&p[1])]
}

/// `{"beziers": [[P, P, ...], ...]}`: 1 to `MAX_SEGMENTS` pieces of 2 to
/// `MAX_CONTROL_POINTS` points.
fn beziers(v: &Json, at: &str) -> Result<Vec<Vec<[Rational; 2]>>, Invalid> {
    let [list] = exact_object(v, at, ["beziers"])?;
    let at = join(at, "beziers");
    let list = list
        .as_array()
        .filter(|l| !l.is_empty() && l.len() <= MAX_SEGMENTS)
        .ok_or_else(|| {
            inv(
                &at,
                format!("expected a list of 1 to {MAX_SEGMENTS} pieces"),
            )
        })?;
    list.iter()
        .enumerate()
        .map(|(i, b)| {
            let pts = b
                .as_array()
                .filter(|p| (2..=MAX_CONTROL_POINTS).contains(&p.len()))
                .ok_or_else(|| {
                    inv(
                        format!("{at}[{i}]"),
                        format!("expected 2 to {MAX_CONTROL_POINTS} control points"),
                    )
                })?;
            pts.iter()
                .enumerate()
                .map(|(k, p)| point(p, &format!("{at}[{i}][{k}]")))
                .collect()
        })
        .collect()
}

fn fmt_pt(p: &[Rational; 2]) -> String {
    format!("({}, {})", p[0], p[1])
}

fn describe_curve(bs: &[Vec<[Rational; 2]>]) -> String {
    let deg = bs.iter().map(|b| b.len() - 1).max().unwrap_or(0);
    let first = &bs[0][0];
    let last = &bs[bs.len() - 1][bs[bs.len() - 1].len() - 1];
    format!(
        "{} Bézier piece{} of degree ≤ {deg} from {} to {}",
        bs.len(),
        if bs.len() == 1 { "" } else { "s" },
        fmt_pt(first),
        fmt_pt(last)
    )
}

/// The control points of the derivative (a single zero point for a constant).
fn hodograph(p: &[[Rational; 2]]) -> Vec<[Rational; 2]> {
    if p.len() < 2 {
        return vec![[Rational::zero(), Rational::zero()]];
    }
    let n = Rational::from_integer(((p.len() - 1) as i64).into());
    p.windows(2)
        .map(|w| [&n * (&w[1][0] - &w[0][0]), &n * (&w[1][1] - &w[0][1])])
        .collect()
}

/// Enclosures of the control points of `p`, `p′`, …, `p⁽ᴺ⁻¹⁾`.
fn derivatives<const N: usize>(p: &[[Rational; 2]]) -> [Vec<[Interval; 2]>; N] {
    let mut cur = p.to_vec();
    std::array::from_fn(|_| {
        let out = cur.iter().map(ivp).collect();
        cur = hodograph(&cur);
        out
    })
}

/// The pieces `x(t) + σ Q n/√(nᵀQn)` of an offset or convolution.
fn conv_shape(bs: &[Vec<[Rational; 2]>], q: [Rational; 3], sigma: i64, text: String) -> VShape {
    let qi = [
        interval_from_rational(&q[0]),
        interval_from_rational(&q[1]),
        interval_from_rational(&q[2]),
    ];
    VShape {
        ends: vec![ic(1); bs.len()],
        pieces: bs
            .iter()
            .map(|b| VPiece::Conv {
                pts: derivatives::<4>(b),
                q: qi,
                sigma: ic(sigma),
            })
            .collect(),
        text,
        exact: None,
    }
}

/// Reads one canonical shape (the value of `a` or `b`): one of the four
/// kinds, or `{"union": [SHAPE, …]}` of 1 or more members of those kinds
/// (no nested unions), at most `MAX_SEGMENTS` pieces in all, its pieces
/// numbered member after member.
pub(crate) fn read_shape(v: &Json, at: &str) -> Result<VShape, Invalid> {
    if let Some([(k, members)]) = v.as_object() {
        if *k == "union" {
            let at = join(at, "union");
            let list = members
                .as_array()
                .filter(|l| !l.is_empty())
                .ok_or_else(|| inv(&at, "expected a list of 1 or more shapes"))?;
            let mut out = VShape {
                pieces: Vec::new(),
                ends: Vec::new(),
                text: String::new(),
                exact: None,
            };
            let mut texts = Vec::new();
            // arcs of one circle, all of them: their exact data, joined
            let mut circle: Option<Exact> = None;
            let mut all_arcs = true;
            for (i, m) in list.iter().enumerate() {
                let at_i = format!("{at}[{i}]");
                let s = read_member(m, &at_i)?;
                match (&mut circle, &s.exact) {
                    (_, _) if !all_arcs => {}
                    (None, Some(Exact::Circle { c, r, arcs })) => {
                        circle = Some(Exact::Circle {
                            c: c.clone(),
                            r: r.clone(),
                            arcs: arcs.clone(),
                        })
                    }
                    (
                        Some(Exact::Circle { c, r, arcs }),
                        Some(Exact::Circle {
                            c: c2,
                            r: r2,
                            arcs: a2,
                        }),
                    ) if c == c2 && r == r2 => arcs.extend(a2.iter().cloned()),
                    _ => all_arcs = false,
                }
                if out.pieces.len() + s.pieces.len() > MAX_SEGMENTS {
                    return Err(inv(
                        &at_i,
                        format!("more than {MAX_SEGMENTS} pieces in all"),
                    ));
                }
                texts.push(format!(
                    "({}) pieces {}–{}: {}",
                    i + 1,
                    out.pieces.len(),
                    out.pieces.len() + s.pieces.len() - 1,
                    s.text
                ));
                out.pieces.extend(s.pieces);
                out.ends.extend(s.ends);
            }
            out.text = format!("the union of {} shapes: {}", list.len(), texts.join("; "));
            out.exact = circle.filter(|_| all_arcs);
            return Ok(out);
        }
    }
    read_member(v, at)
}

/// One shape of the four kinds (not a union).
fn read_member(v: &Json, at: &str) -> Result<VShape, Invalid> {
    let kinds = ["beziers", "arc", "ellipse_arc", "offset", "convolution"];
    let m = v.as_object().ok_or_else(|| {
        inv(
            at,
            format!("expected a shape object, found {}", v.describe()),
        )
    })?;
    let kind = match m {
        [(k, _)] => match kinds.iter().copied().find(|x| k == x) {
            Some(kind) => kind,
            None => {
                return Err(inv(
                    join(at, &k.text()),
                    format!("unknown key: a canonical shape has exactly one of the keys {kinds:?}"),
                ))
            }
        },
        _ => {
            return Err(inv(
                at,
                format!(
                    "a canonical shape has exactly one key, one of {kinds:?}; found {}",
                    m.len()
                ),
            ))
        }
    };
    match kind {
        "beziers" => {
            let bs = beziers(v, at)?;
            Ok(VShape {
                ends: vec![ic(1); bs.len()],
                pieces: bs
                    .iter()
                    .map(|b| VPiece::Poly(derivatives::<3>(b)))
                    .collect(),
                text: format!("the curve of {}", describe_curve(&bs)),
                exact: Some(Exact::Curve(bs)),
            })
        }
        "arc" => read_arc(&m[0].1, &join(at, "arc"), false),
        "ellipse_arc" => read_arc(&m[0].1, &join(at, "ellipse_arc"), true),
        "offset" => {
            let at = join(at, "offset");
            let [curve, distance] = exact_object(&m[0].1, &at, ["curve", "distance"])?;
            let bs = beziers(curve, &join(&at, "curve"))?;
            let r = canonical_rational(distance, &join(&at, "distance"))?;
            if r.is_zero() {
                return Err(inv(join(&at, "distance"), "must be nonzero"));
            }
            let r2 = &r * &r;
            let sigma = if r.is_positive() { 1 } else { -1 };
            let text = format!(
                "the exact offset at signed distance {r} ({} side) of the curve of {}",
                if sigma > 0 { "left" } else { "right" },
                describe_curve(&bs)
            );
            Ok(conv_shape(
                &bs,
                [r2.clone(), Rational::zero(), r2],
                sigma,
                text,
            ))
        }
        _ => {
            let at = join(at, "convolution");
            let [curve, ellipse, side] = exact_object(&m[0].1, &at, ["curve", "ellipse", "side"])?;
            let bs = beziers(curve, &join(&at, "curve"))?;
            let [r0, r1] = nonsingular_matrix(ellipse, &join(&at, "ellipse"))?;
            let sigma = match side {
                Json::Number(t) if *t == "1" => 1,
                Json::Number(t) if *t == "-1" => -1,
                other => {
                    return Err(inv(
                        join(&at, "side"),
                        format!("expected the number 1 or -1, found {}", other.describe()),
                    ))
                }
            };
            let q = [
                &r0[0] * &r0[0] + &r0[1] * &r0[1],
                &r0[0] * &r1[0] + &r0[1] * &r1[1],
                &r1[0] * &r1[0] + &r1[1] * &r1[1],
            ];
            let text = format!(
                "the exact convolution (side {sigma:+}) of the curve of {} with the ellipse M·(unit circle), M = [[{}, {}], [{}, {}]]",
                describe_curve(&bs),
                r0[0], r0[1], r1[0], r1[1]
            );
            Ok(conv_shape(&bs, q, sigma, text))
        }
    }
}

/// A nonsingular 2×2 matrix `[[m11, m12], [m21, m22]]`, by rows.
fn nonsingular_matrix(v: &Json, at: &str) -> Result<[[Rational; 2]; 2], Invalid> {
    let rows = v
        .as_array()
        .filter(|r| r.len() == 2)
        .ok_or_else(|| inv(at, "expected the 2×2 matrix [[m11, m12], [m21, m22]]"))?;
    let r0 = point(&rows[0], &format!("{at}[0]"))?;
    let r1 = point(&rows[1], &format!("{at}[1]"))?;
    if (&r0[0] * &r1[1] - &r0[1] * &r1[0]).is_zero() {
        return Err(inv(
            at,
            "the matrix is singular (the ellipse is degenerate)",
        ));
    }
    Ok([r0, r1])
}

/// A circular arc (`{"center", "radius", "from", "to"}`) or, with
/// `elliptic`, an elliptic one (`{"center", "from", "matrix", "to"}`): both
/// `c + M u`, `u` on the unit-circle arc, `M = r I` for the circle.
fn read_arc(v: &Json, at: &str, elliptic: bool) -> Result<VShape, Invalid> {
    let (c, d0, d1, m, what, radius) = if elliptic {
        let [center, from, matrix, to] = exact_object(v, at, ["center", "from", "matrix", "to"])?;
        let [r0, r1] = nonsingular_matrix(matrix, &join(at, "matrix"))?;
        // M = r I, r > 0: a circle
        let radius = (r0[0] == r1[1] && r0[1].is_zero() && r1[0].is_zero() && r0[0].is_positive())
            .then(|| r0[0].clone());
        let what = format!(
            "the elliptic arc c + M·u of centre c = {} and M = [[{}, {}], [{}, {}]], u",
            fmt_pt(&point(center, &join(at, "center"))?),
            r0[0],
            r0[1],
            r1[0],
            r1[1]
        );
        let m = [&r0[0], &r0[1], &r1[0], &r1[1]].map(interval_from_rational);
        (
            point(center, &join(at, "center"))?,
            point(from, &join(at, "from"))?,
            point(to, &join(at, "to"))?,
            m,
            what,
            radius,
        )
    } else {
        let [center, radius, from, to] = exact_object(v, at, ["center", "radius", "from", "to"])?;
        let c = point(center, &join(at, "center"))?;
        let r = canonical_rational(radius, &join(at, "radius"))?;
        if !r.is_positive() {
            return Err(inv(join(at, "radius"), "must be > 0"));
        }
        let what = format!("the circular arc of centre {} and radius {r},", fmt_pt(&c));
        let ri = interval_from_rational(&r);
        (
            c,
            point(from, &join(at, "from"))?,
            point(to, &join(at, "to"))?,
            [ri, ic(0), ic(0), ri],
            what,
            Some(r),
        )
    };
    for (d, key) in [(&d0, "from"), (&d1, "to")] {
        if d[0].is_zero() && d[1].is_zero() {
            return Err(inv(join(at, key), "the direction vector is zero"));
        }
    }
    let cross = &d0[0] * &d1[1] - &d0[1] * &d1[0];
    let dot = &d0[0] * &d1[0] + &d0[1] * &d1[1];
    if cross.is_zero() && dot.is_positive() {
        return Err(inv(
            join(at, "to"),
            "same direction as `from`: zero sweep (full circles are not supported)",
        ));
    }
    let one = ic(1);
    let unit = |d: &[Rational; 2]| -> Option<[Interval; 2]> {
        let [x, y] = ivp(d);
        let n = (x.sqr() + y.sqr()).sqrt();
        (n.inf() > 0.0).then(|| [x / n, y / n])
    };
    let bad = || {
        inv(
            at,
            "the directions cannot be normalised in interval arithmetic",
        )
    };
    let (e0, e1) = (unit(&d0).ok_or_else(bad)?, unit(&d1).ok_or_else(bad)?);
    // tan(Θ/4) from the half-angle: sin(Θ/2) = |e1 − e0|/2, |cos(Θ/2)| = |e1 + e0|/2.
    let two = ic(2);
    let sh = ((e1[0] - e0[0]).sqr() + (e1[1] - e0[1]).sqr()).sqrt() / two;
    let ch = ((e1[0] + e0[0]).sqr() + (e1[1] + e0[1]).sqr()).sqrt() / two;
    let u = if cross.is_positive() {
        sh / (one + ch)
    } else if cross.is_zero() {
        one // Θ = π
    } else {
        if sh.contains(0.0) {
            return Err(inv(join(at, "to"), "sweep too close to 2π to enclose"));
        }
        (one + ch) / sh
    };
    if !(u.inf() > 0.0 && u.sup().is_finite()) {
        return Err(inv(
            join(at, "to"),
            "cannot enclose the end parameter of the sweep",
        ));
    }
    let text = format!(
        "{what} counter-clockwise from direction {} to direction {}",
        fmt_pt(&d0),
        fmt_pt(&d1)
    );
    Ok(VShape {
        pieces: vec![VPiece::Arc { c: ivp(&c), m, e0 }],
        ends: vec![u],
        text,
        exact: radius.map(|r| Exact::Circle {
            c,
            r,
            arcs: vec![(d0, d1)],
        }),
    })
}
