//! B-spline input: the exact Bézier pieces of `BSpline::to_beziers` against
//! de Boor's evaluation, continuity at the knots, the B-splines of
//! `data/offset_test_curves.json`, and bad input (typed errors naming the field).

use lncert::curve::{BSpline, Bezier, V2};
use lncert::scalar::{frac, parse_rational, Rational};
use lncert::shape::{parse_json_curve, CurveParseError, MAX_SEGMENTS};
use proptest::prelude::*;
use serde_json::Value;

mod common;
use common::qs as q;

fn int(n: i64) -> Rational {
    Rational::from_integer(n.into())
}

fn pt(x: &str, y: &str) -> V2<Rational> {
    V2::new(q(x), q(y))
}

fn config(cases: u32) -> ProptestConfig {
    ProptestConfig {
        cases,
        failure_persistence: None,
        ..ProptestConfig::default()
    }
}

// ---------------------------------------------------------------------------
// Generators
// ---------------------------------------------------------------------------

/// `n/d` with `|n| <= 20`, `1 <= d <= 6`.
fn small_rational() -> impl Strategy<Value = Rational> {
    (-20i64..=20, 1i64..=6).prop_map(|(n, d)| frac(n, d))
}

/// A positive knot increment `n/d`, `1 <= n <= 12`, `1 <= d <= 4`.
fn positive_rational() -> impl Strategy<Value = Rational> {
    (1i64..=12, 1i64..=4).prop_map(|(n, d)| frac(n, d))
}

fn point() -> impl Strategy<Value = V2<Rational>> {
    (small_rational(), small_rational()).prop_map(|(x, y)| V2::new(x, y))
}

/// How the knot vector is made.
#[derive(Clone, Copy, Debug)]
enum Kind {
    /// Random non-decreasing knots with multiplicities up to `degree + 1`.
    General,
    Clamped,
    Periodic,
}

/// A non-decreasing knot vector from a start and increments, repaired so that
/// no value repeats more than `degree + 1` times and `knots[p] < knots[n]`.
fn repaired_knots(
    p: usize,
    n: usize,
    start: Rational,
    increments: &[(bool, Rational)],
) -> Vec<Rational> {
    let mut inc: Vec<Rational> = increments
        .iter()
        .map(|(zero, r)| if *zero { int(0) } else { r.clone() })
        .collect();
    let mut run = 1;
    for d in inc.iter_mut() {
        if *d == int(0) {
            run += 1;
            if run > p + 1 {
                *d = int(1);
                run = 1;
            }
        } else {
            run = 1;
        }
    }
    // increment j leads from knots[j] to knots[j+1].
    if inc[p..n].iter().all(|d| *d == int(0)) {
        inc[p] = int(1);
    }
    let mut knots = vec![start];
    for d in inc {
        let next = knots.last().unwrap().clone() + d;
        knots.push(next);
    }
    knots
}

/// Random B-splines of degree 1..=4: general knots (with multiplicities),
/// clamped or periodic, small rational control points.
fn spline() -> impl Strategy<Value = (BSpline, Kind)> {
    (1usize..=4, 0usize..=6, 0u8..3)
        .prop_flat_map(|(p, extra, kind)| {
            let kind = match kind {
                0 => Kind::General,
                1 => Kind::Clamped,
                _ => Kind::Periodic,
            };
            let m = match kind {
                Kind::Periodic => 2 + extra,
                _ => p + 1 + extra,
            };
            (
                Just(p),
                Just(kind),
                prop::collection::vec(point(), m),
                small_rational(),
                prop::collection::vec((prop::bool::weighted(0.4), positive_rational()), m + p),
            )
        })
        .prop_map(|(p, kind, pts, start, incs)| {
            let n = pts.len();
            let s = match kind {
                Kind::General => BSpline::new(p, repaired_knots(p, n, start, &incs), pts),
                Kind::Clamped => BSpline::clamped_uniform(p, pts),
                Kind::Periodic => BSpline::periodic_uniform(p, pts),
            };
            (s.expect("the generator makes valid B-splines"), kind)
        })
}

/// Local parameters: a few in `[0, 1]` plus the ends.
fn local_params() -> impl Strategy<Value = Vec<Rational>> {
    prop::collection::vec((0i64..=12, 1i64..=12), 0..4).prop_map(|v| {
        let mut s: Vec<Rational> = v.into_iter().map(|(a, b)| frac(a.min(b), b)).collect();
        s.push(int(0));
        s.push(int(1));
        s
    })
}

// ---------------------------------------------------------------------------
// Helpers, independent of BSpline's own span bookkeeping
// ---------------------------------------------------------------------------

/// Indices `i` of the non-empty spans `[k_i, k_{i+1}]`, `p <= i < n`.
fn span_indices(s: &BSpline) -> Vec<usize> {
    let (p, n, k) = (s.degree(), s.control_points().len(), s.knots());
    (p..n).filter(|&i| k[i] < k[i + 1]).collect()
}

fn multiplicity(knots: &[Rational], value: &Rational) -> usize {
    knots.iter().filter(|k| *k == value).count()
}

/// The `r`-th derivative curve.
fn derivative(b: &Bezier<Rational>, r: usize) -> Bezier<Rational> {
    (0..r).fold(b.clone(), |c, _| c.hodograph())
}

fn pow(x: &Rational, r: usize) -> Rational {
    (0..r).fold(int(1), |acc, _| acc * x.clone())
}

/// Checks that the pieces `left` over a span of length `hl` and `right` over
/// a span of length `hr` meet with equal `u`-derivatives of orders `0..=order`.
fn assert_joins(
    left: &Bezier<Rational>,
    hl: &Rational,
    right: &Bezier<Rational>,
    hr: &Rational,
    order: usize,
) -> Result<(), TestCaseError> {
    for r in 0..=order {
        // d^r/du^r = (d^r/dt^r) / h^r; compare cross-multiplied.
        let l = derivative(left, r).eval(&int(1)).scale(&pow(hr, r));
        let rr = derivative(right, r).eval(&int(0)).scale(&pow(hl, r));
        prop_assert_eq!(l, rr, "derivative of order {} at the junction", r);
    }
    Ok(())
}

// ---------------------------------------------------------------------------
// Properties
// ---------------------------------------------------------------------------

proptest! {
    #![proptest_config(config(200))]

    /// de Boor's `eval(u)` equals the Bézier piece of `u`'s span at the local
    /// parameter `(u - k_i) / (k_{i+1} - k_i)`, exactly; outside the valid
    /// range, the first/last piece extended.
    #[test]
    fn pieces_equal_de_boor_exactly((s, kind) in spline(), params in local_params()) {
        let p = s.degree();
        let n = s.control_points().len();
        let k = s.knots();
        let spans = span_indices(&s);
        let pieces = s.to_beziers();
        prop_assert_eq!(pieces.len(), spans.len());
        prop_assert_eq!(
            s.spans(),
            spans.iter().map(|&i| (k[i].clone(), k[i + 1].clone())).collect::<Vec<_>>()
        );
        if let Kind::Periodic = kind {
            prop_assert_eq!(pieces.len(), n - p);
        }
        for (piece, &i) in pieces.iter().zip(&spans) {
            prop_assert_eq!(piece.degree(), p);
            let (a, b) = (&k[i], &k[i + 1]);
            let h = b.clone() - a.clone();
            for t in &params {
                let u = a.clone() + h.clone() * t.clone();
                // At a knot of multiplicity p + 1 inside the range the curve
                // may jump, and eval takes the right-hand piece there.
                if *t == int(1) && u != k[n] && multiplicity(k, &u) > p {
                    continue;
                }
                prop_assert_eq!(s.eval(&u), piece.eval(t), "u = {}, span {}", u, i);
            }
        }
        // Extrapolation beyond both ends.
        let (first, last) = (spans[0], *spans.last().unwrap());
        let h0 = k[first + 1].clone() - k[first].clone();
        let u = k[first].clone() - h0.clone() * frac::<Rational>(1, 2);
        prop_assert_eq!(s.eval(&u), pieces[0].eval(&frac(-1, 2)));
        let h1 = k[last + 1].clone() - k[last].clone();
        let u = k[last + 1].clone() + h1 * frac::<Rational>(1, 3);
        prop_assert_eq!(s.eval(&u), pieces.last().unwrap().eval(&frac(4, 3)));
    }

    /// At an interior knot of multiplicity `m <= p` the consecutive pieces
    /// agree in position and in the `u`-derivatives up to order `p - m`
    /// (order `p - 1` at a simple knot), exactly; a periodic spline also
    /// closes with `C^{p-1}` continuity.
    #[test]
    fn pieces_join_with_knot_continuity((s, kind) in spline()) {
        let p = s.degree();
        let k = s.knots();
        let spans = span_indices(&s);
        let pieces = s.to_beziers();
        let len = |i: usize| k[i + 1].clone() - k[i].clone();
        for w in 0..pieces.len().saturating_sub(1) {
            let (i, j) = (spans[w], spans[w + 1]);
            let m = multiplicity(k, &k[j]);
            if m > p {
                continue;
            }
            assert_joins(&pieces[w], &len(i), &pieces[w + 1], &len(j), p - m)?;
        }
        if let Kind::Periodic = kind {
            let last = pieces.len() - 1;
            assert_joins(&pieces[last], &len(spans[last]), &pieces[0], &len(spans[0]), p - 1)?;
        }
        if let Kind::Clamped = kind {
            let cps = s.control_points();
            prop_assert_eq!(&pieces[0].points()[0], &cps[0]);
            prop_assert_eq!(pieces.last().unwrap().points().last().unwrap(), cps.last().unwrap());
        }
    }

    /// JSON with explicit knots gives exactly the pieces of `BSpline::new`.
    #[test]
    fn json_matches_the_api((s, _kind) in spline()) {
        let num = |r: &Rational| format!("\"{r}\"");
        let pts: Vec<String> = s
            .control_points()
            .iter()
            .map(|v| format!("[{}, {}]", num(&v.x), num(&v.y)))
            .collect();
        let knots: Vec<String> = s.knots().iter().map(num).collect();
        let json = format!(
            r#"{{"bspline": {{"degree": {}, "knots": [{}], "control_points": [{}]}}}}"#,
            s.degree(),
            knots.join(", "),
            pts.join(", ")
        );
        prop_assert_eq!(parse_json_curve(&json).unwrap(), s.to_beziers());
    }

    /// Random bspline-shaped JSON never panics.
    #[test]
    fn never_panics_on_bspline_json(
        s in r#"\{"bspline": \{"degree": ("?[0-9e.+-]{0,6}"?|null), "knots": ("clamped"|"periodic"|\[[0-9, ./e"-]{0,24}\]|[0-9]{0,2}), "control_points": \[[\[\]0-9, ./"-]{0,40}\](, "w": 1)?\}\}"#
    ) {
        let _ = parse_json_curve(&s);
    }

    /// Structured random input with out-of-range degrees and counts never
    /// panics, and an accepted spline has the expected number of pieces.
    #[test]
    fn never_panics_on_structured_input(
        degree in prop_oneof![0i64..=6, Just(63), Just(64), Just(-1), Just(i64::MAX)],
        npts in 0usize..=8,
        knots in prop_oneof![
            Just("\"clamped\"".to_string()),
            Just("\"periodic\"".to_string()),
            prop::collection::vec(-3i64..=3, 0..=14).prop_map(|mut v| {
                v.sort();
                format!("{v:?}")
            }),
        ],
    ) {
        let pts = vec!["[0, 1]"; npts].join(", ");
        let json = format!(
            r#"{{"bspline": {{"degree": {degree}, "knots": {knots}, "control_points": [{pts}]}}}}"#
        );
        if let Ok(pieces) = parse_json_curve(&json) {
            prop_assert!(!pieces.is_empty());
            prop_assert!(pieces.iter().all(|b| b.degree() as i64 == degree));
            if knots == "\"clamped\"" {
                prop_assert_eq!(pieces.len() as i64, npts as i64 - degree);
            }
            if knots == "\"periodic\"" {
                prop_assert_eq!(pieces.len(), npts);
            }
        }
    }
}

// ---------------------------------------------------------------------------
// Fixed examples
// ---------------------------------------------------------------------------

#[test]
fn simple_knots_give_c_p_minus_1_and_double_knots_less() {
    // Cubic, knots 0 0 0 0 1 3 4 4 4 4 (simple interior knots 1, 3).
    let pts = vec![
        pt("0", "0"),
        pt("1", "2"),
        pt("3", "3"),
        pt("4", "0"),
        pt("6", "-1"),
        pt("7", "2"),
    ];
    let k: Vec<Rational> = [0, 0, 0, 0, 1, 3, 4, 4, 4, 4].map(int).to_vec();
    let s = BSpline::new(3, k, pts.clone()).unwrap();
    let b = s.to_beziers();
    assert_eq!(b.len(), 3);
    assert_joins(&b[0], &int(1), &b[1], &int(2), 2).unwrap();
    assert_joins(&b[1], &int(2), &b[2], &int(1), 2).unwrap();
    // Here the third derivative jumps at the knot 1 (generic data).
    assert!(assert_joins(&b[0], &int(1), &b[1], &int(2), 3).is_err());

    // Doubling the knot 1 leaves C^1 there; tripling leaves C^0.
    let pts7 = [pts.clone(), vec![pt("8", "0")]].concat();
    let s = BSpline::new(3, [0, 0, 0, 0, 1, 1, 3, 4, 4, 4, 4].map(int).to_vec(), pts7).unwrap();
    let b = s.to_beziers();
    assert_eq!(b.len(), 3);
    assert_joins(&b[0], &int(1), &b[1], &int(2), 1).unwrap();
    // A knot u_4 = u_5 = u_6 of multiplicity p on a cubic: the curve passes
    // through the control point P_3 there.
    let pts8 = [pts.clone(), vec![pt("8", "0"), pt("9", "1")]].concat();
    let s = BSpline::new(
        3,
        [0, 0, 0, 0, 1, 1, 1, 3, 4, 4, 4, 4].map(int).to_vec(),
        pts8,
    )
    .unwrap();
    let b = s.to_beziers();
    assert_eq!(b[0].points()[3], pt("4", "0"));
    assert_eq!(b[1].points()[0], pt("4", "0"));
}

#[test]
fn full_multiplicity_knot_breaks_the_curve() {
    // Degree 1, knot 1 of multiplicity 2 = p + 1: two separate segments.
    let pts = vec![pt("0", "0"), pt("1", "0"), pt("5", "5"), pt("6", "5")];
    let s = BSpline::new(1, [0, 0, 1, 1, 2, 2].map(int).to_vec(), pts).unwrap();
    let b = s.to_beziers();
    assert_eq!(
        b,
        vec![
            Bezier::new(vec![pt("0", "0"), pt("1", "0")]),
            Bezier::new(vec![pt("5", "5"), pt("6", "5")]),
        ]
    );
    // Right-continuous at the break, the end belongs to the last span.
    assert_eq!(s.eval(&int(1)), pt("5", "5"));
    assert_eq!(s.eval(&int(2)), pt("6", "5"));
}

#[test]
fn clamped_and_periodic_knots() {
    let pts = vec![pt("0", "0"); 6];
    let s = BSpline::clamped_uniform(2, pts.clone()).unwrap();
    assert_eq!(s.knots(), [0, 0, 0, 1, 2, 3, 4, 4, 4].map(int));
    assert_eq!(s.domain(), (int(0), int(4)));
    let s = BSpline::periodic_uniform(2, pts[..4].to_vec()).unwrap();
    assert_eq!(s.knots(), (0..=8).map(int).collect::<Vec<_>>());
    assert_eq!(s.control_points().len(), 6);
    assert_eq!(s.domain(), (int(2), int(6)));
    // Fewer points than the degree: the wrap repeats the polygon.
    let tri = vec![pt("0", "0"), pt("1", "0"), pt("0", "1")];
    let s = BSpline::periodic_uniform(4, tri.clone()).unwrap();
    assert_eq!(
        s.control_points(),
        [tri.clone(), tri.clone(), tri[..1].to_vec()].concat()
    );
    let b = s.to_beziers();
    assert_eq!(b.len(), 3);
    assert_eq!(b[2].points()[4], b[0].points()[0]);
}

#[test]
fn degree_63_is_accepted_and_exact() {
    let pts: Vec<V2<Rational>> = (0..64).map(|i| V2::new(int(i), int(i * i % 7))).collect();
    let s = BSpline::clamped_uniform(63, pts.clone()).unwrap();
    // A single span with clamped ends: the Bézier curve of the control points.
    assert_eq!(s.to_beziers(), vec![Bezier::new(pts.clone())]);
    let s = BSpline::periodic_uniform(63, pts[..3].to_vec()).unwrap();
    let b = s.to_beziers();
    assert_eq!(b.len(), 3);
    let u = int(63) + frac::<Rational>(1, 3);
    assert_eq!(s.eval(&u), b[0].eval(&frac(1, 3)));
    assert!(BSpline::clamped_uniform(64, [pts.clone(), pts].concat()).is_err());
}

// ---------------------------------------------------------------------------
// The B-splines of data/offset_test_curves.json
// ---------------------------------------------------------------------------

fn data() -> Value {
    let path = concat!(env!("CARGO_MANIFEST_DIR"), "/data/offset_test_curves.json");
    let text = std::fs::read_to_string(path).unwrap_or_else(|e| panic!("reading {path}: {e}"));
    serde_json::from_str(&text).unwrap()
}

/// The number's text as written (serde_json's `arbitrary_precision`), read
/// exactly.
fn exact(v: &Value) -> Rational {
    let Value::Number(n) = v else {
        panic!("expected a number, found {v}")
    };
    parse_rational(&n.to_string()).unwrap()
}

/// Degree, knot keyword and control points of a data-file B-spline.
fn data_spline(name: &str) -> (usize, &'static str, Vec<V2<Rational>>, String) {
    let d = data();
    let c = &d[name];
    let degree = c["degree"].as_u64().unwrap() as usize;
    let kind = c["knots"].as_str().unwrap();
    let kind = if kind.contains("clamped") {
        "clamped"
    } else if kind.contains("periodic") {
        "periodic"
    } else {
        panic!("unknown knots {kind:?}")
    };
    let raw = c["control_points"].as_array().unwrap();
    let pts = raw
        .iter()
        .map(|p| V2::new(exact(&p[0]), exact(&p[1])))
        .collect();
    // The same control points as JSON text, numbers as written.
    let json = format!(
        r#"{{"bspline": {{"degree": {degree}, "knots": "{kind}", "control_points": {}}}}}"#,
        c["control_points"]
    );
    (degree, kind, pts, json)
}

/// Consecutive pieces meet.
fn assert_chained(b: &[Bezier<Rational>]) {
    for w in b.windows(2) {
        assert_eq!(w[0].points().last(), w[1].points().first());
    }
}

#[test]
fn pawn_bspline_has_ten_pieces() {
    let (degree, kind, pts, json) = data_spline("pawn_bspline");
    assert_eq!((degree, kind, pts.len()), (3, "clamped", 13));
    assert_eq!(pts[0], pt("19/20", "1/20")); // 0.95, 0.05 read exactly
    let s = BSpline::clamped_uniform(degree, pts.clone()).unwrap();
    let b = s.to_beziers();
    assert_eq!(b.len(), 10);
    assert_eq!(b[0].points()[0], pts[0]);
    assert_eq!(b[9].points()[3], pts[12]);
    assert_chained(&b);
    assert_eq!(parse_json_curve(&json).unwrap(), b);
}

#[test]
fn cross_bspline_is_closed_with_four_pieces() {
    let (degree, kind, pts, json) = data_spline("cross_bspline");
    assert_eq!((degree, kind, pts.len()), (3, "periodic", 4));
    let s = BSpline::periodic_uniform(degree, pts.clone()).unwrap();
    let b = s.to_beziers();
    assert_eq!(b.len(), 4);
    assert_chained(&b);
    assert_eq!(b[3].points()[3], b[0].points()[0]);
    // Uniform cubic: the piece starts at (P0 + 4 P1 + P2) / 6.
    assert_eq!(b[0].points()[0], pt("1/3", "-1/3"));
    // C^2 where the curve closes.
    assert_joins(&b[3], &int(1), &b[0], &int(1), 2).unwrap();
    assert_eq!(parse_json_curve(&json).unwrap(), b);
}

#[test]
fn doc_bspline_has_six_pieces() {
    let (degree, kind, pts, json) = data_spline("doc_bspline");
    assert_eq!((degree, kind, pts.len()), (2, "clamped", 8));
    let s = BSpline::clamped_uniform(degree, pts.clone()).unwrap();
    let b = s.to_beziers();
    assert_eq!(b.len(), 6);
    assert_eq!(b[0].points()[0], pts[0]);
    assert_eq!(b[5].points()[2], pts[7]);
    assert_eq!(b[0].points()[1], pt("7/10", "3/50")); // 0.06 exactly
    assert_chained(&b);
    assert_eq!(parse_json_curve(&json).unwrap(), b);
}

// ---------------------------------------------------------------------------
// Bad input: typed errors naming the field
// ---------------------------------------------------------------------------

/// The field of a `Field` error, after checking the message names it.
fn field_of(e: &CurveParseError) -> &str {
    match e {
        CurveParseError::Field { field, .. } => {
            assert!(e.to_string().contains(field.as_str()), "{e}");
            field
        }
        other => panic!("expected a Field error, got {other:?}"),
    }
}

fn json_err(spline_body: &str) -> CurveParseError {
    parse_json_curve(&format!(r#"{{"bspline": {spline_body}}}"#)).unwrap_err()
}

const FOUR: &str = "[[0, 0], [1, 1], [2, 0], [3, 1]]";

#[test]
fn bad_degree() {
    let pts = vec![pt("0", "0"); 4];
    let e = BSpline::new(0, vec![int(0); 5], pts.clone()).unwrap_err();
    assert_eq!(field_of(&e), "bspline.degree");
    let e = BSpline::clamped_uniform(64, pts.clone()).unwrap_err();
    assert_eq!(field_of(&e), "bspline.degree");
    let e = BSpline::periodic_uniform(usize::MAX, pts).unwrap_err();
    assert_eq!(field_of(&e), "bspline.degree");
    for degree in [
        "0",
        "-1",
        "2.5",
        "64",
        "1e999999999",
        "\"1e999999999\"",
        "1e300",
        "\"NaN\"",
        "\"abc\"",
        "null",
        "[3]",
        "18446744073709551617",
    ] {
        let e = json_err(&format!(
            r#"{{"degree": {degree}, "knots": "clamped", "control_points": {FOUR}}}"#
        ));
        assert_eq!(field_of(&e), "bspline.degree", "degree {degree}: {e}");
    }
    // An exactly integral non-integer literal is fine.
    let ok = parse_json_curve(&format!(
        r#"{{"bspline": {{"degree": 3.0, "knots": "clamped", "control_points": {FOUR}}}}}"#
    ));
    assert_eq!(ok.unwrap().len(), 1);
}

#[test]
fn too_few_control_points() {
    let e = BSpline::clamped_uniform(3, vec![pt("0", "0"); 3]).unwrap_err();
    assert_eq!(field_of(&e), "bspline.control_points");
    assert!(e.to_string().contains("at least 4"), "{e}");
    let e = BSpline::new(2, vec![int(0); 5], vec![pt("0", "0"); 2]).unwrap_err();
    assert_eq!(field_of(&e), "bspline.control_points");
    let e = BSpline::periodic_uniform(2, vec![pt("0", "0")]).unwrap_err();
    assert_eq!(field_of(&e), "bspline.control_points");
    for (knots, pts) in [
        ("\"clamped\"", "[]"),
        ("\"periodic\"", "[]"),
        ("\"periodic\"", "[[1, 1]]"),
        ("[0, 0, 1, 1]", "[[1, 1]]"),
        ("[]", "[]"),
    ] {
        let e = json_err(&format!(
            r#"{{"degree": 1, "knots": {knots}, "control_points": {pts}}}"#
        ));
        assert!(
            field_of(&e) == "bspline.control_points" || field_of(&e) == "bspline.knots",
            "{knots} {pts}: {e}"
        );
    }
    let e = json_err(r#"{"degree": 3, "knots": "clamped", "control_points": [[0, 0], [1, 1]]}"#);
    assert_eq!(field_of(&e), "bspline.control_points");
    let e = json_err(r#"{"degree": 1, "knots": "clamped", "control_points": {"a": 1}}"#);
    assert_eq!(field_of(&e), "bspline.control_points");
}

#[test]
fn bad_knots() {
    let pts = vec![pt("0", "0"); 4];
    // Decreasing.
    let e = BSpline::new(2, [0, 0, 0, 2, 1, 3, 3].map(int).to_vec(), pts.clone()).unwrap_err();
    assert_eq!(field_of(&e), "bspline.knots[4]");
    assert!(e.to_string().contains("non-decreasing"), "{e}");
    let e = json_err(&format!(
        r#"{{"degree": 2, "knots": [0, 0, 0, "1/2", 0.4, 1, 1], "control_points": {FOUR}}}"#
    ));
    assert_eq!(field_of(&e), "bspline.knots[4]");
    // Wrong count.
    let e = BSpline::new(2, [0, 0, 0, 1, 1, 1].map(int).to_vec(), pts.clone()).unwrap_err();
    assert_eq!(field_of(&e), "bspline.knots");
    assert!(e.to_string().contains("expected 7 knots"), "{e}");
    let e = json_err(&format!(
        r#"{{"degree": 2, "knots": [0, 0, 0, 1, 1, 1, 1, 1], "control_points": {FOUR}}}"#
    ));
    assert_eq!(field_of(&e), "bspline.knots");
    // Multiplicity above degree + 1.
    let e = BSpline::new(1, [0, 1, 1, 1, 2, 2].map(int).to_vec(), pts.clone()).unwrap_err();
    assert_eq!(field_of(&e), "bspline.knots[3]");
    assert!(e.to_string().contains("repeated 3 times"), "{e}");
    // Empty valid range [knots[1], knots[2]] = [1, 1].
    let e = BSpline::new(1, [0, 1, 1, 2].map(int).to_vec(), vec![pt("0", "0"); 2]).unwrap_err();
    assert_eq!(field_of(&e), "bspline.knots");
    assert!(e.to_string().contains("is empty"), "{e}");
    // Unreadable knot and wrong types.
    let e = json_err(&format!(
        r#"{{"degree": 2, "knots": [0, 0, 0, "x", 1, 1, 1], "control_points": {FOUR}}}"#
    ));
    assert_eq!(field_of(&e), "bspline.knots[3]");
    let e = json_err(&format!(
        r#"{{"degree": 2, "knots": [0, 0, 0, "NaN", 1, 1, 1], "control_points": {FOUR}}}"#
    ));
    assert_eq!(field_of(&e), "bspline.knots[3]");
    let e = json_err(&format!(
        r#"{{"degree": 2, "knots": [0, 0, 0, 1e999999999, 1, 1, 1], "control_points": {FOUR}}}"#
    ));
    assert_eq!(field_of(&e), "bspline.knots[3]");
    for knots in ["\"uniform\"", "5", "{}", "null", "\"Clamped\""] {
        let e = json_err(&format!(
            r#"{{"degree": 2, "knots": {knots}, "control_points": {FOUR}}}"#
        ));
        assert_eq!(field_of(&e), "bspline.knots", "{knots}: {e}");
    }
}

#[test]
fn bad_coordinates() {
    let e =
        json_err(r#"{"degree": 1, "knots": "clamped", "control_points": [[0, 0], ["abc", 1]]}"#);
    assert_eq!(field_of(&e), "bspline.control_points[1][0]");
    assert!(e.to_string().contains("abc"), "{e}");
    let e =
        json_err(r#"{"degree": 1, "knots": "clamped", "control_points": [[0, 0], [1, "NaN"]]}"#);
    assert_eq!(field_of(&e), "bspline.control_points[1][1]");
    let e = json_err(
        r#"{"degree": 1, "knots": "clamped", "control_points": [[0, 1e999999999], [1, 1]]}"#,
    );
    assert_eq!(field_of(&e), "bspline.control_points[0][1]");
    let e = json_err(r#"{"degree": 1, "knots": "clamped", "control_points": [[0, 0], [1]]}"#);
    assert_eq!(field_of(&e), "bspline.control_points[1]");
}

#[test]
fn unknown_and_missing_keys() {
    let e = json_err(&format!(
        r#"{{"degree": 2, "knots": "clamped", "control_points": {FOUR}, "weights": [1, 1, 1, 1]}}"#
    ));
    assert_eq!(field_of(&e), "bspline.weights");
    assert!(e.to_string().contains("unknown field"), "{e}");
    let e = json_err(&format!(
        r#"{{"knots": "clamped", "control_points": {FOUR}}}"#
    ));
    assert_eq!(field_of(&e), "bspline.degree");
    let e = json_err(&format!(r#"{{"degree": 2, "control_points": {FOUR}}}"#));
    assert_eq!(field_of(&e), "bspline.knots");
    let e = json_err(r#"{"degree": 2, "knots": "clamped"}"#);
    assert_eq!(field_of(&e), "bspline.control_points");
    let e = json_err("[1, 2]");
    assert_eq!(field_of(&e), "bspline");
    // Top level: one curve field only, no unknown fields.
    let e = parse_json_curve(&format!(
        r#"{{"bezier": [[0, 0], [1, 1]], "bspline": {{"degree": 1, "knots": "clamped", "control_points": {FOUR}}}}}"#
    ))
    .unwrap_err();
    assert_eq!(field_of(&e), "bspline");
    let e = parse_json_curve(r#"{"bezier": [[0, 0], [1, 1]], "beziers": []}"#).unwrap_err();
    assert_eq!(field_of(&e), "beziers");
    let e = parse_json_curve(r#"{"bsplin": {}}"#).unwrap_err();
    assert_eq!(field_of(&e), "bsplin");
    assert!(e.to_string().contains("bspline"), "{e}");
}

#[test]
fn too_many_control_points() {
    let pts = vec!["[0, 0]"; MAX_SEGMENTS + 1].join(",");
    let e = json_err(&format!(
        r#"{{"degree": 1, "knots": "clamped", "control_points": [{pts}]}}"#
    ));
    assert!(
        matches!(&e, CurveParseError::TooLarge { what, limit } if *limit == MAX_SEGMENTS && what.contains("bspline.control_points")),
        "{e:?}"
    );
}

/// The exact conversion's work is bounded: control points × degree³ ≤ MAX_BSPLINE_WORK.
#[test]
fn conversion_work_is_bounded() {
    let pts = |n: usize| {
        (0..n)
            .map(|i| format!("[{i}, {}]", i % 5))
            .collect::<Vec<_>>()
            .join(",")
    };
    let doc = |deg: usize, n: usize| {
        format!(
            r#"{{"bspline": {{"degree": {deg}, "knots": "clamped", "control_points": [{}]}}}}"#,
            pts(n)
        )
    };
    let e = parse_json_curve(&doc(63, 1000)).unwrap_err();
    assert!(
        matches!(&e, CurveParseError::TooLarge { what, .. } if what.contains("degree³")),
        "{e}"
    );
    assert_eq!(parse_json_curve(&doc(3, 2000)).unwrap().len(), 1997);
}
