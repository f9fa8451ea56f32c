#![no_main]
//! Fuzz target `convolve`: a small curve, an elliptical pen, a side, a
//! tolerance and budgets built from the input -> `lncert::offset::convolve`
//! (seed 001's G²/C¹ convolution approximant), and the result's contract. The
//! structure follows `offset.rs` (same curves, tolerances and budgets, so an
//! input costs a few ms to a few tens of ms).
//!
//! Input (one byte per choice, see [`input`]): 1-2 Bézier pieces of degree
//! 1-4 (degree 4 on one piece in 8, see `offset_oracle::curve`; coordinates `k/16`, `k` an `i8`; the second piece free, joined, or
//! closing the curve, as in `offset.rs`). A pen, either
//! * by its matrix `M` (entries `num/den`, `num` in `-4..=4`, `den` in `1..=4`;
//!   singular matrices included: `Pen::from_matrix` must refuse them naming
//!   `pen.matrix`), or
//! * by semi-axes `a`, `b` (`num/den`, `num` in `-2..=16`, `den` in `1..=8`;
//!   `b <= 0` must be an error naming `pen.b`, else `a < b` one naming `pen.a`)
//!   and an angle string from [`ANGLES`] (good ones, strings `Angle::parse`
//!   must refuse naming `angle`, and ones it reads but `Pen::ellipse` must
//!   refuse naming `pen.angle`), represented within a bound from [`MAX_ANGLES`]
//!   (`Pen::ellipse` for 1e-12, else `Pen::ellipse_within`).
//!
//! A side from `{1, -1, 0, 2}` (0 and 2 must be errors naming `side`), a
//! tolerance from [`TOLS`] (absurd values included), one input in eight by
//! seed 000 §5's LN pairs (cubic segments), and small budgets (`max_depth` 0..=3,
//! `max_segments` 1..=8, `max_boxes` 8..=64).
//!
//! Checks (exact consequences of the contract and of the driver in
//! src/offset/; no sampled "expected" geometry):
//! * no panic; an `Err` names a non-empty field and reason, both in its
//!   `Display`; the expected field where the input decides it (above);
//! * the pen: `q = M Mᵀ` exactly; a matrix pen is exact (`margin` and
//!   `rotation_error` 0); an axes pen is `M = R diag(a, b)` with an exactly
//!   rational rotation (`c² + s² = 1`), within `rotation_error` of the
//!   requested angle (checked against f64 `cos`/`sin`), `rotation_error <=`
//!   the requested bound, `margin >= (a + a²/b) rotation_error` and `margin = 0`
//!   iff `rotation_error = 0`, which holds for every quarter turn;
//! * a tolerance that is not a finite number `> 0` is refused by
//!   `lncert::Tolerance` (checked in `offset_oracle::tol`); one with
//!   `tol - margin < 1e-11` (so below `1e-11 (1 + scale)`) must be an error;
//! * the result: `tol` and the method as given, distance 0, no offset cusps or
//!   corners, `convolution` set with this pen and side and
//!   `certified_tol = tol - pen.margin` rounded down to a float (`tol` itself
//!   when the margin is 0), checked exactly;
//! * every segment has `0 <= lo <= hi` (no NaN); `certified_hi` is the max of
//!   the segments' `hi`; `unreached` is exactly the (sorted) indices of the
//!   segments with `hi > certified_tol` — **not** `tol`: `convolve` runs the
//!   offset driver with `opts.tol` replaced by `certified_tol`, and the driver
//!   accepts a segment iff `hi <= opts.tol` of those inner options; `reached()`
//!   iff `certified_hi <= certified_tol` (so `certified_hi` may lie in
//!   `(certified_tol, tol]` with `reached()` false);
//! * segments are sorted by `(piece, t0)` and tile every piece's `[0, 1]`
//!   exactly; the segment counts of `offset.rs` (the initial spans now also
//!   split at the side's cusps);
//! * a segment of degree 1 is the placeholder of a span without a
//!   construction (error `(0, inf)`, unreached); every other segment has degree
//!   `n + 3` (G2) or 3 (LN pair); consecutive constructed segments of one piece share their joint
//!   control point exactly; the control point count as in `offset.rs`;
//! * pinning: a constructed segment's first and last control points are within
//!   `1e-9 (1 + scale)` of the convolution point
//!   `C(t) = x(t) + σ Q n / √(nᵀ Q n)` (`n = x′(t)⊥`) at `t0` and `t1`, with
//!   `x(t)`, `Q n` and `nᵀ Q n` exact and one float square root;
//! * soundness of `hi`: `C(t)`, `t` in `{t0, (t0 + t1)/2, t1}`, lies on the
//!   exact convolution of the span, and the approximant lies in the convex hull
//!   of its control points, so `hi >= dist(C(t), hull)` up to float slack;
//! * soundness of `lo`: `d_H <= max(max_j |B_j - C(t0)|, max_i |X_i - B_0| +
//!   R)` with `R = √(q₁₁ + q₂₂) >=` the pen's major semi-axis, so `lo` is at
//!   most that;
//! * cusps (`convolution.cusps`): on an existing piece, the exact interval
//!   `lo <= hi` in `[0, 1]` of width at most 2⁻⁴⁰, `t_approx` in it; the
//!   interval holds a root of the cusp polynomial `(det Q)² k² - (nᵀQn)³`
//!   (`k = x′ × x″`, rebuilt here from the module docs: a sign change, else
//!   Sturm); `σ k > 0` at its midpoint (exactly) unless the interval holds a
//!   root of `k`; `point` within `1e-9 (1 + scale)` of `C(t_approx)`.

use libfuzzer_sys::arbitrary::{Result, Unstructured};
use libfuzzer_sys::{fuzz_target, Corpus};
use lncert::curve::{Bezier, V2};
use lncert::offset::{convolve, OffsetError, OffsetMethod, OffsetOptions, OffsetResult};
use lncert::offset::{Angle, Pen};
use lncert::poly::{has_root_in, Poly, Span};
use lncert::scalar::{rational_from_f64, Rational};
use lncert::ShapeError;

#[path = "common/offset_oracle.rs"]
mod offset_oracle;
#[allow(unused_imports)] // [`TOLS`] in the docs
use offset_oracle::TOLS;
use offset_oracle::{budgets, curve, dist, f, fp, in_scale, q};

/// What must happen to an angle string.
#[derive(Clone, Copy, Debug, PartialEq)]
enum Expect {
    /// Read by `Angle::parse` and accepted by `Pen::ellipse`.
    Good,
    /// Refused by `Angle::parse` (field `angle`).
    ParseErr,
    /// Read by `Angle::parse` (it is an exact number) but refused by
    /// `Pen::ellipse` (field `pen.angle`): `1e400` is within the exponent
    /// limit of `parse_rational` (|e| <= 400); the pen needs |θ| < 1e6.
    PenErr,
}

/// Angle strings: quarter turns (exact: `margin = 0`), other angles, bad ones.
const ANGLES: [(&str, Expect); 20] = [
    ("pi/6", Expect::Good),
    ("30deg", Expect::Good),
    ("0.5", Expect::Good),
    ("-2pi/3", Expect::Good),
    ("90deg", Expect::Good),
    ("0", Expect::Good),
    ("pi", Expect::Good),
    ("-pi/2", Expect::Good),
    ("45deg", Expect::Good),
    ("1/3", Expect::Good),
    ("7pi/5", Expect::Good),
    ("3.14159", Expect::Good),
    ("pi/0", Expect::ParseErr),
    ("", Expect::ParseErr),
    ("abc", Expect::ParseErr),
    ("1e401", Expect::ParseErr),
    ("NaN", Expect::ParseErr),
    ("pi*", Expect::ParseErr),
    ("1e400", Expect::PenErr),
    ("1e6", Expect::PenErr),
];

/// Bounds on the rotation error (`Pen::ellipse` for the first).
const MAX_ANGLES: [f64; 3] = [1e-12, 1e-6, 1e-3];

/// Sides: the two valid ones and two that must be errors.
const SIDES: [i8; 4] = [1, -1, 0, 2];

fn ratio(u: &mut Unstructured, num: (i8, i8), den: u8) -> Result<Rational> {
    let n: i8 = u.int_in_range(num.0..=num.1)?;
    let d: u8 = u.int_in_range(1..=den)?;
    Ok(q(n.into(), d.into()))
}

/// How the pen is given.
#[derive(Debug)]
enum PenSpec {
    Matrix([[Rational; 2]; 2]),
    Axes {
        a: Rational,
        b: Rational,
        angle: usize,
        max_angle: f64,
    },
}

struct Input {
    curve: Vec<Bezier<Rational>>,
    pen: PenSpec,
    side: i8,
    opts: OffsetOptions,
}

fn input(u: &mut Unstructured) -> Result<Input> {
    let curve = curve(u)?;
    let pen = if u.int_in_range(0..=1u8)? == 0 {
        let mut e = || ratio(u, (-4, 4), 4);
        PenSpec::Matrix([[e()?, e()?], [e()?, e()?]])
    } else {
        let a = ratio(u, (-2, 16), 8)?;
        let b = ratio(u, (-2, 16), 8)?;
        let angle = usize::from(u.int_in_range(0..=(ANGLES.len() - 1) as u8)?);
        let max_angle = MAX_ANGLES[usize::from(u.int_in_range(0..=(MAX_ANGLES.len() - 1) as u8)?)];
        PenSpec::Axes {
            a,
            b,
            angle,
            max_angle,
        }
    };
    let side = SIDES[usize::from(u.int_in_range(0..=(SIDES.len() - 1) as u8)?)];
    let tol = offset_oracle::tol(u)?;
    let mut opts = OffsetOptions::new(q(0, 1), tol);
    // seed 000 §5's LN pairs, one input in eight
    opts.method = if u.int_in_range(0..=7u8)? == 7 {
        OffsetMethod::LnPair
    } else {
        OffsetMethod::G2
    };
    // and seed 000 §5's subdivision rule (a), (b) or (c) for them
    budgets(u, &mut opts)?;
    Ok(Input {
        curve,
        pen,
        side,
        opts,
    })
}

/// `Q = M Mᵀ` as `[q₁₁, q₁₂, q₂₂]`, exactly.
fn q_of(m: &[[Rational; 2]; 2]) -> [Rational; 3] {
    [
        &m[0][0] * &m[0][0] + &m[0][1] * &m[0][1],
        &m[0][0] * &m[1][0] + &m[0][1] * &m[1][1],
        &m[1][0] * &m[1][0] + &m[1][1] * &m[1][1],
    ]
}

/// `(nᵀ Q n, Q n)` exactly for `n = d⊥ = (-d_y, d_x)`.
fn nqn(d: &V2<Rational>, qm: &[Rational; 3]) -> (Rational, V2<Rational>) {
    let (nx, ny) = (-d.y.clone(), d.x.clone());
    let qn = V2::new(&qm[0] * &nx + &qm[1] * &ny, &qm[1] * &nx + &qm[2] * &ny);
    let s = &nx * &qn.x + &ny * &qn.y;
    (s, qn)
}

/// The exact convolution point `x(t) + σ Q n / √(nᵀ Q n)` in f64: `x(t)`,
/// `Q n` and `nᵀ Q n` exact, then one rounding each and a float square root.
fn conv_point(x: &Bezier<Rational>, t: f64, qm: &[Rational; 3], sigma: i8) -> (f64, f64) {
    let tr = rational_from_f64(t).expect("finite parameter");
    let p = fp(&x.eval(&tr));
    let d = x.hodograph().eval(&tr);
    let (s, qn) = nqn(&d, qm);
    let (sf, qx, qy) = (f(&s), f(&qn.x), f(&qn.y));
    assert!(
        sf > 0.0 && sf.is_finite(),
        "nᵀQn = {sf} at t = {t} on a piece the engine accepted (zero derivative?)"
    );
    let k = f64::from(sigma) / sf.sqrt();
    (p.0 + qx * k, p.1 + qy * k)
}

/// `k = x′ × x″` and `nᵀ Q n` as exact power-form polynomials (the module
/// docs' formulas), and the cusp polynomial `(det Q)² k² - (nᵀQn)³`.
struct CuspPolys {
    k: Poly<Rational>,
    p: Poly<Rational>,
}

fn cusp_polys(x: &Bezier<Rational>, qm: &[Rational; 3]) -> CuspPolys {
    let (dx, dy) = x.hodograph().power_coords();
    let (ddx, ddy) = (dx.derivative(), dy.derivative());
    let k = dx.mul(&ddy).sub(&dy.mul(&ddx));
    let nqn = Poly::constant(qm[0].clone())
        .mul(&dy.mul(&dy))
        .sub(&Poly::constant(q(2, 1) * qm[1].clone()).mul(&dx.mul(&dy)))
        .add(&Poly::constant(qm[2].clone()).mul(&dx.mul(&dx)));
    let det = &qm[0] * &qm[2] - &qm[1] * &qm[1];
    let p = Poly::constant(&det * &det)
        .mul(&k)
        .mul(&k)
        .sub(&nqn.mul(&nqn).mul(&nqn));
    CuspPolys { k, p }
}

/// `poly` has a root in `[lo, hi]`: a sign change at the ends, else Sturm.
fn root_in(poly: &Poly<Rational>, lo: &Rational, hi: &Rational) -> bool {
    let zero = q(0, 1);
    let (a, b) = (poly.eval(lo), poly.eval(hi));
    if a == zero || b == zero || (a < zero) != (b < zero) {
        return true;
    }
    has_root_in(poly, &Span::closed(lo.clone(), hi.clone()))
}

fn check_fields(field: &str, reason: &str, shown: &str, what: &str) {
    assert!(
        !field.is_empty() && !reason.is_empty() && shown.contains(field) && shown.contains(reason),
        "{what}: error without a field or reason: {shown:?} (field {field:?}, reason {reason:?})"
    );
}

fn check_shape_error(e: &ShapeError, want: &str, what: &str) {
    check_fields(&e.field, &e.reason, &e.to_string(), what);
    assert_eq!(e.field, want, "{what}: error {e} names the wrong field");
}

fn check_error(e: &OffsetError, inp: &Input) -> String {
    check_fields(
        &e.field,
        &e.reason,
        &e.to_string(),
        &format!("convolve (tol {}, side {})", inp.opts.tol, inp.side),
    );
    e.field.clone()
}

/// Builds the pen and checks its contract; `None` when it must be (and is)
/// refused.
fn make_pen(spec: &PenSpec) -> Option<Pen> {
    let zero = q(0, 1);
    match spec {
        PenSpec::Matrix(m) => {
            let det = &m[0][0] * &m[1][1] - &m[0][1] * &m[1][0];
            match Pen::from_matrix(m.clone()) {
                Err(e) => {
                    assert!(
                        det == zero,
                        "Pen::from_matrix refused a regular matrix {m:?}: {e}"
                    );
                    check_shape_error(&e, "pen.matrix", "Pen::from_matrix");
                    None
                }
                Ok(pen) => {
                    assert!(
                        det != zero,
                        "Pen::from_matrix accepted a singular matrix {m:?}"
                    );
                    assert!(&pen.m == m, "the pen's matrix is not the one given");
                    assert!(pen.q == q_of(m), "q != M Mᵀ for {m:?}");
                    assert!(
                        pen.margin == 0.0 && pen.rotation_error == 0.0,
                        "a matrix pen is not exact: margin {}, rotation_error {}",
                        pen.margin,
                        pen.rotation_error
                    );
                    Some(pen)
                }
            }
        }
        PenSpec::Axes {
            a,
            b,
            angle,
            max_angle,
        } => {
            let (text, expect) = ANGLES[*angle];
            let theta = match Angle::parse(text) {
                Err(e) => {
                    assert_eq!(
                        expect,
                        Expect::ParseErr,
                        "Angle::parse({text:?}) refused: {e}"
                    );
                    check_shape_error(&e, "angle", &format!("Angle::parse({text:?})"));
                    return None;
                }
                Ok(th) => {
                    assert!(
                        expect != Expect::ParseErr,
                        "Angle::parse({text:?}) accepted a bad angle: {th:?}"
                    );
                    th
                }
            };
            let res = if *max_angle == 1e-12 {
                Pen::ellipse(a, b, &theta)
            } else {
                Pen::ellipse_within(a, b, &theta, *max_angle)
            };
            let want_field = if *b <= zero {
                Some("pen.b")
            } else if a < b {
                Some("pen.a")
            } else if expect == Expect::PenErr {
                Some("pen.angle")
            } else {
                None
            };
            let what = format!("Pen::ellipse({a}, {b}, {text:?}, {max_angle:e})");
            let pen = match (res, want_field) {
                (Err(e), Some(w)) => {
                    check_shape_error(&e, w, &what);
                    return None;
                }
                (Err(e), None) => panic!("{what} refused: {e}"),
                (Ok(p), Some(w)) => panic!("{what} accepted (must be refused naming {w}): {p:?}"),
                (Ok(p), None) => p,
            };
            // M = R(θ') diag(a, b) with an exactly rational rotation
            let c = &pen.m[0][0] / a;
            let s = &pen.m[1][0] / a;
            assert!(
                &c * &c + &s * &s == q(1, 1),
                "{what}: the rotation ({c}, {s}) is not exactly a unit vector"
            );
            assert!(
                pen.m[0][1] == -(&s * b) && pen.m[1][1] == &c * b,
                "{what}: M is not R diag(a, b): {:?}",
                pen.m
            );
            assert!(pen.q == q_of(&pen.m), "{what}: q != M Mᵀ");
            let delta = pen.rotation_error;
            assert!(
                delta >= 0.0 && delta <= *max_angle,
                "{what}: rotation_error {delta} outside [0, {max_angle}]"
            );
            // the rational rotation against f64 cos/sin of the angle (|θ| < 4:
            // the f64 angle and libm add well below 1e-14)
            let th = match &theta {
                Angle::Radians(r) => f(r),
                Angle::Degrees(d) => f(d) / 180.0 * std::f64::consts::PI,
                Angle::PiTimes(k) => f(k) * std::f64::consts::PI,
            };
            let err = (f(&c) - th.cos()).hypot(f(&s) - th.sin());
            assert!(
                err <= delta + 1e-14,
                "{what}: rotation ({c}, {s}) is {err} from θ = {th}, beyond rotation_error {delta}"
            );
            let quarter = match &theta {
                Angle::PiTimes(k) => (k * q(2, 1)).is_integer(),
                Angle::Degrees(d) => (d / q(90, 1)).is_integer(),
                Angle::Radians(r) => *r == zero,
            };
            if quarter {
                assert!(
                    delta == 0.0 && pen.margin == 0.0,
                    "{what}: a quarter turn is not exact: rotation_error {delta}, margin {}",
                    pen.margin
                );
            }
            let (af, bf) = (f(a), f(b));
            assert!(
                (pen.margin == 0.0) == (delta == 0.0)
                    && pen.margin >= (af + af * af / bf) * delta * (1.0 - 1e-12),
                "{what}: margin {} below (a + a²/b) δ = {}",
                pen.margin,
                (af + af * af / bf) * delta
            );
            Some(pen)
        }
    }
}

fn check_ok(inp: &Input, pen: &Pen, r: &OffsetResult) {
    let curve = &inp.curve;
    let opts = &inp.opts;
    let tol = opts.tol.value();
    let segs = &r.segments;
    let sigma = inp.side;
    let qm = &pen.q;
    let zero = q(0, 1);
    assert!(r.tol == opts.tol && r.method == opts.method && r.distance == zero);
    assert!(r.proven, "certify is on but the result is not proven");
    assert!(
        r.cusps.is_empty() && r.corners.is_empty(),
        "offset cusps or corners in a convolution result"
    );
    let conv = r
        .convolution
        .as_ref()
        .expect("convolve's result has no `convolution`");
    assert!(conv.pen == *pen, "the result's pen is not the pen given");
    assert_eq!(conv.side, sigma, "the result's side");
    // certified_tol: tol itself without a margin, else tol − margin rounded
    // down to a float (checked exactly: ≤ the difference, the next float above)
    let ctol = conv.certified_tol.value();
    if pen.margin == 0.0 {
        assert!(
            conv.certified_tol == opts.tol,
            "certified_tol {ctol} != tol {tol}"
        );
    } else {
        let exact = rational_from_f64(tol).unwrap() - rational_from_f64(pen.margin).unwrap();
        let (c, up) = (
            rational_from_f64(ctol).unwrap(),
            rational_from_f64(ctol.next_up()).unwrap(),
        );
        assert!(
            c <= exact && up > exact,
            "certified_tol {ctol} is not tol {tol} - margin {} rounded down",
            pen.margin
        );
    }
    assert!(r.certified_tol() == &conv.certified_tol);
    offset_oracle::check_spans(
        curve,
        opts,
        r,
        ctol,
        &format!("certified_tol {ctol} (tol {tol})"),
    );
    offset_oracle::check_degrees(
        curve,
        opts,
        r,
        &format!("degree of the approximant ({:?})", opts.method),
    );
    for (i, s) in segs.iter().enumerate() {
        assert!(
            s.paper_error.is_none() && s.estimate.is_none(),
            "segment {i}: paper_error or estimate without the options"
        );
        assert_eq!(
            s.proof.is_some(),
            s.error.1 <= ctol,
            "segment {i}: proof present iff hi <= certified_tol"
        );
    }
    offset_oracle::check_joints(r);
    // R = √(q₁₁ + q₂₂) = |M|_F >= the major semi-axis (the largest eigenvalue of Q
    // is at most its trace), rounded up a little
    let reach = (f(&qm[0]) + f(&qm[2])).sqrt() * (1.0 + 1e-12);
    offset_oracle::check_pinning(curve, r, reach, "convolution", |x, t| {
        conv_point(x, t, qm, sigma)
    });

    // cusps of the convolution side
    let np = curve.len();
    let (one, width) = (q(1, 1), q(1, 1 << 40));
    let mut polys: Vec<Option<CuspPolys>> = (0..np).map(|_| None).collect();
    for cu in &conv.cusps {
        assert!(cu.piece < np, "cusp on piece {} of {np}", cu.piece);
        let (lo, hi) = (&cu.t.0, &cu.t.1);
        assert!(
            zero <= *lo && lo <= hi && *hi <= one,
            "cusp parameter interval [{lo}, {hi}] outside [0, 1]"
        );
        assert!(
            hi - lo <= width,
            "cusp interval [{lo}, {hi}] wider than 2^-40"
        );
        assert!(
            f(lo) <= cu.t_approx && cu.t_approx <= f(hi),
            "cusp t_approx {} outside [{lo}, {hi}]",
            cu.t_approx
        );
        let x = &curve[cu.piece];
        let cp = polys[cu.piece].get_or_insert_with(|| cusp_polys(x, qm));
        assert!(
            root_in(&cp.p, lo, hi),
            "cusp interval [{lo}, {hi}] on piece {} holds no root of (det Q)² k² - (nᵀQn)³",
            cu.piece
        );
        let mid = (lo + hi) / q(2, 1);
        let sk = cp.k.eval(&mid) * q(sigma.into(), 1);
        assert!(
            sk > zero || root_in(&cp.k, lo, hi),
            "cusp at [{lo}, {hi}] on piece {}: σ k = {} <= 0 at the midpoint and no root of k (a cusp of the other side)",
            cu.piece,
            f(&sk)
        );
        let want = conv_point(x, cu.t_approx, qm, sigma);
        let eps = 1e-9 * (1.0 + in_scale(curve) + reach);
        assert!(
            dist(want, cu.point) <= eps,
            "cusp point {:?} is not the convolution point {want:?} at t = {}",
            cu.point,
            cu.t_approx
        );
    }
}

fuzz_target!(|data: &[u8]| -> Corpus {
    let mut u = Unstructured::new(data);
    let Ok(inp) = input(&mut u) else {
        return Corpus::Reject;
    };
    let Some(pen) = make_pen(&inp.pen) else {
        return Corpus::Reject;
    };
    let tol = inp.opts.tol.value();
    let bad_side = inp.side != 1 && inp.side != -1;
    let bad_tol = tol - pen.margin < 1e-11;
    match convolve(&inp.curve, &pen, inp.side, &inp.opts) {
        Err(e) => {
            let field = check_error(&e, &inp);
            if bad_side {
                assert_eq!(field, "side", "side {} refused naming {e}", inp.side);
            }
            Corpus::Reject
        }
        Ok(r) => {
            assert!(
                !bad_side && !bad_tol,
                "accepted side {} / method {:?} / tolerance {tol} with margin {} (must be errors)",
                inp.side,
                inp.opts.method,
                pen.margin
            );
            check_ok(&inp, &pen, &r);
            Corpus::Keep
        }
    }
});
