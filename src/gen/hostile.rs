//! Hostile stroke certificates: documents built to make a verifier spend
//! time or memory out of proportion to their size. The resource tests
//! (`tests/verifier_resources.rs`), the bench `verify_resources` and the
//! fuzz targets' seeds use them; a verifier of your own can be tried on them
//! too.
//!
//! Each is a well-formed `lncert-stroke-certificate` whose claims hold at a
//! large tolerance (so a verifier cannot dodge the work by failing early on
//! a false claim; [`wiggly_witnesses`] only for claims (a) and (c)):
//!
//! - [`stacked_rectangles`]: `k` thin rectangles stacked in `y`. Every pair
//!   of the `4k` outline parts overlaps in `x`, so a sweep over `x` alone
//!   lists about `8k²` candidate pairs for claim (c) (simple, disjoint
//!   contours), where the parts' boxes meet only within a rectangle.
//! - [`wiggly_witnesses`]: `copies` copies of one wiggly input piece and
//!   `parts` outline segments whose outside witnesses are disks that almost
//!   touch every copy: claim (a)'s Bernstein exclusion of each witness
//!   against each copy is deep, `parts × copies` times.
//! - [`far_pieces`]: `n` input pieces far from an `n`-part outline: claim
//!   (a) tests each witness against pieces nowhere near it, `n²` times, unless
//!   the verifier indexes the pieces.
//!
//! # Examples
//! ```
//! use lncert::gen::hostile;
//! let doc = hostile::stacked_rectangles(3);
//! let valid = lncert::verify(&doc).unwrap();
//! assert!(valid.a.contains("3 closed contour(s)"));
//! ```

use serde_json::{json, Value};

fn q(n: i64) -> Value {
    Value::String(n.to_string())
}

/// The canonical rational `p/d` (lowest terms, as the verifier reads it).
fn frac(p: i128, d: i128) -> Value {
    let r = crate::scalar::Rational::new(p.into(), d.into());
    Value::String(crate::scalar::rational_to_string(&r))
}

fn seg(a: [Value; 2], b: [Value; 2]) -> Value {
    json!({"bezier": [a, b]})
}

/// The families of `∂S` of `pieces` unjoined straight segments (each its own
/// component): both offsets, the start cap's halves, the end cap's halves,
/// each covered by one box near outline piece 0 of contour 0 (foot map
/// constant `1/2`): true at a tolerance above every distance.
fn far_families(pieces: usize, boxes: i128) -> Vec<Value> {
    let near = Value::Array(
        (0..boxes)
            .map(|i| json!({"t": [frac(i, boxes), frac(i + 1, boxes)], "near": {"contour": 0, "piece": 0, "s": "1/2", "k": "0"}}))
            .collect(),
    );
    let mut out = Vec::new();
    for j in 0..pieces {
        for side in ["left", "right"] {
            out.push(json!({"of": format!("piece {j} {side}"), "boxes": near.clone()}));
        }
    }
    for j in 0..pieces {
        for name in ["start", "end"] {
            for half in ["a", "b"] {
                out.push(json!({"of": format!("{name} {j} {half}"), "boxes": near.clone()}));
            }
        }
    }
    out
}

fn certificate(
    tol: Value,
    radius: Value,
    curve: Vec<Value>,
    outline: Vec<Vec<Value>>,
    cover: Vec<Vec<Value>>,
    boundary: Vec<Value>,
) -> String {
    json!({
        "format": "lncert-stroke-certificate", "version": 1,
        "claim": "hausdorff(outline, boundary(curve + disk(radius))) <= tol",
        "tol": tol, "radius": radius, "curve": curve, "outline": outline,
        "cover": cover, "boundary": boundary, "simple": true
    })
    .to_string()
}

/// `k` rectangles `(0, 4i)–(1, 4i)–(1, 4i + 1)–(0, 4i + 1)` as the outline
/// of the stroke of one unit segment far away (radius 1, tolerance `10⁶`):
/// a valid certificate of about `430 k` bytes whose claim (c) a sweep in `x`
/// alone makes quadratic.
pub fn stacked_rectangles(k: usize) -> String {
    let far = 1000;
    // one part per side: inside the disk about the curve's start, outside
    // the point disk at (−1, 0)
    let part = json!([{"s": ["0", "1"], "o": {"piece": 0, "u": "0"}, "w": {"at": ["-1", "0"], "mu": "0"}}]);
    let mut outline = Vec::new();
    let mut cover = Vec::new();
    for i in 0..k as i64 {
        let (y0, y1) = (4 * i, 4 * i + 1);
        let p = [[0, y0], [1, y0], [1, y1], [0, y1]];
        outline.push(
            (0..4)
                .map(|s| {
                    let (a, b) = (p[s], p[(s + 1) % 4]);
                    seg([q(a[0]), q(a[1])], [q(b[0]), q(b[1])])
                })
                .collect(),
        );
        cover.push(vec![part.clone(); 4]);
    }
    certificate(
        q(1_000_000),
        q(1),
        vec![json!([[q(far), "0"], [q(far + 1), "0"]])],
        outline,
        cover,
        far_families(1, 4),
    )
}

/// A point on the circle of radius `rho_n / rho_d` about the origin at the
/// rational parameter `t = tan(θ/2)`, exactly: `ρ ((1 − t²), 2t) / (1 + t²)`.
fn circle_point(t: (i128, i128), rho: (i128, i128)) -> [Value; 2] {
    let (a, b) = t;
    let (n, d) = rho;
    let den = (a * a + b * b) * d;
    [frac((b * b - a * a) * n, den), frac(2 * a * b * n, den)]
}

/// The polygon of `2m` vertices exactly on the circle of radius `rho` about
/// the origin (`m = ⌈parts/2⌉`, at least 2), one closed contour of straight
/// pieces, counter-clockwise: the right half from `(0, −ρ)` to `(0, ρ)` at
/// `t = tan(θ/2) = (2k − m)/m`, then its mirror image back down.
fn polygon(parts: usize, rho: (i128, i128)) -> Vec<Value> {
    let m = parts.div_ceil(2).max(2) as i128;
    let neg = |v: Value| match v.as_str() {
        Some(s) if s.starts_with('-') => Value::String(s[1..].to_string()),
        Some("0") | None => v,
        Some(s) => Value::String(format!("-{s}")),
    };
    let mut pts: Vec<[Value; 2]> = (0..=m).map(|k| circle_point((2 * k - m, m), rho)).collect();
    for k in (1..m).rev() {
        let [x, y] = circle_point((2 * k - m, m), rho);
        pts.push([neg(x), y]);
    }
    let n = pts.len();
    (0..n)
        .map(|i| seg(pts[i].clone(), pts[(i + 1) % n].clone()))
        .collect()
}

/// `copies` copies of one wiggly Bézier of degree `degree` (control points at
/// radii alternating 1 and 21/20 over a quarter turn), pen radius 1/4, and
/// an outline of about `parts` segments on the circle of radius 3/4, each
/// part's outside witness the disk `B(0, μ)` with `μ` a hair below the
/// copies' least radius minus 1/4: every exclusion of a witness against a
/// copy subdivides deeply. Claims (a) and (c) hold at tolerance 16; claim
/// (b)'s boxes are uniform (64 per family) and the wiggle may make the
/// piece's offset singular, so a verifier may refuse the document at
/// `boundary` — after claim (a), the costly part, is checked.
pub fn wiggly_witnesses(parts: usize, copies: usize, degree: usize) -> String {
    let degree = degree.clamp(2, 63);
    // control points at angles k/degree · π/2 (rational circle points)
    let ctrl: Vec<([i128; 2], [i128; 2])> = (0..=degree as i128)
        .map(|k| {
            // t = tan(θ/2) ≈ k/(degree) · tan(π/4) scaled: any increasing
            // rational t in [0, 1/2] is a rational point
            let t = (k, 2 * degree as i128);
            let rho = if k % 2 == 0 { (1, 1) } else { (21, 20) };
            let (a, b) = t;
            let den = (a * a + b * b) * rho.1;
            ([(b * b - a * a) * rho.0, den], [2 * a * b * rho.0, den])
        })
        .collect();
    // the least radius, sampled densely (a float generator, not a proof:
    // if it overshoots, the certificate is invalid, and as costly)
    let f = |c: &[i128; 2]| c[0] as f64 / c[1] as f64;
    let pts: Vec<[f64; 2]> = ctrl.iter().map(|(x, y)| [f(x), f(y)]).collect();
    let at = |t: f64| {
        let mut b = pts.clone();
        for k in (1..b.len()).rev() {
            for i in 0..k {
                b[i] = [
                    (1.0 - t) * b[i][0] + t * b[i + 1][0],
                    (1.0 - t) * b[i][1] + t * b[i + 1][1],
                ];
            }
        }
        (b[0][0] * b[0][0] + b[0][1] * b[0][1]).sqrt()
    };
    let min_r = (0..=20_000)
        .map(|i| at(i as f64 / 20_000.0))
        .fold(f64::INFINITY, f64::min);
    let scale = 1i128 << 40;
    let mu = ((min_r - 0.25 - 1e-9) * scale as f64).floor() as i128;
    let curve: Vec<Value> = (0..copies)
        .map(|_| {
            Value::Array(
                ctrl.iter()
                    .map(|(x, y)| json!([frac(x[0], x[1]), frac(y[0], y[1])]))
                    .collect(),
            )
        })
        .collect();
    let outline = polygon(parts, (3, 4));
    let part = json!([{"s": ["0", "1"], "o": {"piece": 0, "u": "1/2"}, "w": {"at": ["0", "0"], "mu": frac(mu, scale)}}]);
    let cover = vec![vec![part; outline.len()]];
    certificate(
        q(16),
        frac(1, 4),
        curve,
        vec![outline],
        cover,
        far_families(copies, 64),
    )
}

/// `n` unit segments on the line `y = 10⁴`, unjoined, pen radius 1/2, and an
/// outline of about `n` segments on the unit circle whose outside witnesses
/// are the point disk at the origin: nothing of the curve is within reach of
/// any witness. Valid at tolerance `10⁵`.
pub fn far_pieces(n: usize) -> String {
    let far = 10_000i64;
    let curve: Vec<Value> = (0..n as i64)
        .map(|i| json!([[q(2 * i), q(far)], [q(2 * i + 1), q(far)]]))
        .collect();
    let outline = polygon(n.max(4), (1, 1));
    let part =
        json!([{"s": ["0", "1"], "o": {"piece": 0, "u": "0"}, "w": {"at": ["0", "0"], "mu": "0"}}]);
    let cover = vec![vec![part; outline.len()]];
    certificate(
        q(100_000),
        frac(1, 2),
        curve,
        vec![outline],
        cover,
        far_families(n, 4),
    )
}
