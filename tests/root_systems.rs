//! The complete interval solver on the 2-D root-isolation systems of
//! `data/root_systems.json` (IntervalRootFinding.jl test suite, Smiley & Chun
//! 2001): every listed root (written like `1/sqrt(5)`, `sqrt2`, enclosed here by
//! interval arithmetic, independently of the solver) lies in exactly one
//! certified box, the number of certified roots equals the expected count,
//! nothing spurious, no undecided box.

use lncert::scalar::{parse_rational, Interval, IntervalExt, Rational};
use lncert::tangency::parse_poly2;
use lncert::tangency::System2;
use lncert::tangency::{solve, RationalBox, Solution, SolveOptions};
use serde_json::Value;

fn data() -> Value {
    let text = std::fs::read_to_string(concat!(
        env!("CARGO_MANIFEST_DIR"),
        "/data/root_systems.json"
    ))
    .expect("data/root_systems.json");
    serde_json::from_str(&text).expect("valid JSON")
}

fn num(v: &Value) -> Rational {
    let s = match v {
        Value::String(s) => s.clone(),
        other => other.to_string(),
    };
    parse_rational(&s).expect("exact number")
}

fn point(x: f64) -> Interval {
    Interval::point(x).unwrap()
}

/// Encloses `[-] a [/ b]` where `a`, `b` are numbers, `sqrtN` or `sqrt(N)`.
fn enclose_root(text: &str) -> Interval {
    let t = text.trim();
    let (neg, t) = match t.strip_prefix('-') {
        Some(rest) => (true, rest),
        None => (false, t),
    };
    let atom = |s: &str| -> Interval {
        let s = s.trim();
        if let Some(rest) = s.strip_prefix("sqrt") {
            let inner = rest.trim_start_matches('(').trim_end_matches(')');
            let r = parse_rational(inner).expect("radicand");
            lncert::scalar::interval_from_rational(&r).sqrt()
        } else {
            lncert::scalar::interval_from_rational(&parse_rational(s).expect("number"))
        }
    };
    let v = match t.split_once('/') {
        Some((a, b)) => atom(a) / atom(b),
        None => atom(t),
    };
    if neg {
        -v
    } else {
        v
    }
}

fn solve_system(sys: &Value) -> Solution {
    let f = sys["f"].as_array().unwrap();
    let p = parse_poly2(f[0].as_str().unwrap()).unwrap();
    let q = parse_poly2(f[1].as_str().unwrap()).unwrap();
    let b = sys["box"].as_array().unwrap();
    let domain = RationalBox {
        x: (num(&b[0][0]), num(&b[0][1])),
        y: (num(&b[1][0]), num(&b[1][1])),
    };
    solve(&System2::new(&p, &q), &domain, &SolveOptions::default())
}

/// Each expected root meets exactly one certified enclosure and lies in that
/// root's region (where the solver proved uniqueness).
fn assert_found(name: &str, sol: &Solution, expected: &[[Interval; 2]]) {
    for e in expected {
        let hits: Vec<_> = sol
            .roots
            .iter()
            .filter(|r| !r.enclosure[0].disjoint(e[0]) && !r.enclosure[1].disjoint(e[1]))
            .collect();
        assert_eq!(
            hits.len(),
            1,
            "{name}: expected root {e:?} in {} boxes: {:?}",
            hits.len(),
            sol.roots
        );
        assert!(e[0].subset(hits[0].region[0]) && e[1].subset(hits[0].region[1]));
    }
}

#[test]
fn every_listed_system_is_solved_completely() {
    let d = data();
    let systems = d["systems"].as_array().unwrap();
    assert!(systems.len() >= 4);
    for sys in systems {
        let name = sys["name"].as_str().unwrap();
        let sol = solve_system(sys);
        assert!(sol.complete, "{name}: undecided boxes {:?}", sol.undecided);
        assert!(sol.undecided.is_empty());
        if let Some(roots) = sys["roots"].as_array() {
            let expected: Vec<[Interval; 2]> = roots
                .iter()
                .map(|r| {
                    [
                        enclose_root(r[0].as_str().unwrap()),
                        enclose_root(r[1].as_str().unwrap()),
                    ]
                })
                .collect();
            assert_eq!(sol.roots.len(), expected.len(), "{name}: {:?}", sol.roots);
            assert_found(name, &sol, &expected);
        }
        if let Some(n) = sys["roots_count"].as_u64() {
            assert_eq!(sol.roots.len() as u64, n, "{name}: {:?}", sol.roots);
        }
        // Pairwise distinct: enclosures are disjoint.
        for (i, a) in sol.roots.iter().enumerate() {
            for b in &sol.roots[i + 1..] {
                assert!(
                    a.enclosure[0].disjoint(b.enclosure[0])
                        || a.enclosure[1].disjoint(b.enclosure[1])
                );
            }
        }
    }
}

/// Smiley–Chun 2.2: the 8 roots computed independently: the ellipse
/// `x² + 4y² = 4` meets `y = 0` at `(±2, 0)`, `x = 1.995` at
/// `(1.995, ±√(4 - 1.995²)/2)`, `y = x²` at `x² = (√65 - 1)/8`, and `y = x - 1`
/// at `(0, -1)` and `(8/5, 3/5)`.
#[test]
fn smiley_chun_clustered_roots() {
    let d = data();
    let sys = d["systems"]
        .as_array()
        .unwrap()
        .iter()
        .find(|s| s["name"] == "smiley-chun-2.2")
        .expect("smiley-chun-2.2 in the data")
        .clone();
    let sol = solve_system(&sys);
    assert!(sol.complete, "{:?}", sol.undecided);
    let x5 = lncert::scalar::interval_from_rational(&parse_rational("1.995").unwrap());
    let y5 = (point(4.0) - x5.sqr()).sqrt() / point(2.0);
    let y2 = ((point(65.0)).sqrt() - point(1.0)) / point(8.0);
    let x2 = y2.sqrt();
    let expected = [
        [point(2.0), point(0.0)],
        [point(-2.0), point(0.0)],
        [x5, y5],
        [x5, -y5],
        [x2, y2],
        [-x2, y2],
        [point(0.0), point(-1.0)],
        [point(1.6), point(0.6)],
    ];
    assert_eq!(sol.roots.len(), 8, "{:?}", sol.roots);
    assert_found("smiley-chun-2.2", &sol, &expected);
    // The clustered pair near (2, 0) is resolved: y = 0.0706665 (rounded).
    assert!(y5.inf() > 0.07066645 && y5.sup() < 0.07066655);
}

#[test]
fn tiny_budget_is_reported_not_looped() {
    let d = data();
    let sys = &d["systems"][3];
    let f = sys["f"].as_array().unwrap();
    let p = parse_poly2(f[0].as_str().unwrap()).unwrap();
    let q = parse_poly2(f[1].as_str().unwrap()).unwrap();
    let domain = RationalBox {
        x: (num(&Value::from(-3)), num(&Value::from(3))),
        y: (num(&Value::from(-3)), num(&Value::from(3))),
    };
    let opts = SolveOptions {
        max_boxes: 20,
        ..SolveOptions::default()
    };
    let sol = solve(&System2::new(&p, &q), &domain, &opts);
    assert!(!sol.complete);
    assert_eq!(sol.boxes, 20);
    assert!(sol
        .undecided
        .iter()
        .any(|u| u.reason == lncert::tangency::UndecidedReason::Budget));
}

/// A tangential (double) zero cannot be proven by Krawczyk (singular
/// Jacobian): it must be reported undecided, flagged as near a double root,
/// never as a certified root; the simple zero of the system is certified.
#[test]
fn tangential_double_root_is_flagged_not_certified() {
    // y = x² touches y = 0 at the origin (a double zero); the factor x - 3/4 of
    // the second equation gives the simple zero (3/4, 9/16).
    let p = parse_poly2("y - x^2").unwrap();
    let q = parse_poly2("y*(x - 3/4)").unwrap();
    let domain = RationalBox {
        x: (parse_rational("-1").unwrap(), parse_rational("1").unwrap()),
        y: (parse_rational("-1").unwrap(), parse_rational("1").unwrap()),
    };
    let sol = solve(&System2::new(&p, &q), &domain, &SolveOptions::default());
    assert!(!sol.complete);
    assert_eq!(sol.roots.len(), 1, "{:?}", sol.roots);
    assert!(sol.roots[0].enclosure[0].contains(0.75) && sol.roots[0].enclosure[1].contains(0.5625));
    assert!(!sol.undecided.is_empty());
    for u in &sol.undecided {
        assert!(u.bx[0].contains(0.0) || u.bx[0].mag() < 1e-3, "{u:?}");
        assert!(
            matches!(
                u.reason,
                lncert::tangency::UndecidedReason::MinWidth {
                    near_double_root: true
                }
            ),
            "{u:?}"
        );
    }
}
