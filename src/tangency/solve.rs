//! The circle-tangency problem end to end (seed 003 §4): search domain,
//! default `a2` window, the complete interval solver or the exact oracle, and
//! per root the quartic (`a2, a3, a4`), its nonsingularity on `[0, u]` and
//! the side of the circle.
//!
//! **Side convention.** The radius is signed: `r > 0` asks for the centre on
//! the side of the curve normal `(m, 1)` at the tangency point, i.e.
//! `(O - K(m))·(m, 1) > 0`; `r < 0` for the opposite side. Eq. (6), (7) only
//! see `r²`, so every solution is classified afterwards: `Requested` when the
//! sign of `(O - K(m))·(m, 1)` (never 0 at a solution, it is `±|r|√(1+m²)`)
//! equals the sign of `r`, `Opposite` otherwise, `Undecided` if the interval
//! enclosure straddles 0.
//!
//! **Default `a2` window** (when none is given): the nonsingular interval `I`
//! of Prop 3.2 (corrected, [`HermiteData::nonsingular_a2_interval`], enclosed
//! with intervals) widened by its width on each side, ends rounded outward to
//! f64 — so solutions just outside `I` are found and reported singular. When
//! `I` is empty (no nonsingular quartic exists: `u ∉ ((3-√3)s, (3+√3)s)`) or
//! cannot be enclosed, the fallback is `c ± 4(1 + |c|)` around the `a2` of the
//! cubic interpolant (the member with `a4 = 0`), `c = -(2u x1 + 3 y1)/u²`.
//! Solutions outside the window are not searched for; pass `--a2-range` to
//! choose another one.

use super::complete::{solve, RationalBox, SolveOptions, UndecidedBox};
use super::eliminate::exact_solutions;
use super::krawczyk::System2;
use super::system::{SolutionLine, TangencyError, TangencySystem};
use crate::ln::hermite::HermiteData;
use crate::scalar::{interval_from_rational, rational_from_f64, Interval, Rational, Scalar, Sign};
use num_traits::{Signed, Zero};

/// Where the `a2` window came from.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum A2WindowSource {
    /// Given by the user.
    User,
    /// Prop 3.2's nonsingular interval, widened.
    Nonsingular,
    /// The documented fallback around the cubic interpolant.
    Fallback,
}

/// A tangency problem: the system and the search domain
/// `m ∈ [0, u]`, `a2 ∈ [a2_lo, a2_hi]`.
#[derive(Clone, Debug)]
pub struct TangencyProblem {
    /// Eq. (6), (7) over Q.
    pub system: TangencySystem,
    /// Eq. (6), (7) with enclosed coefficients (built once).
    pub interval_system: System2,
    /// The `a2` search window `[lo, hi]` (exact).
    pub a2_window: (Rational, Rational),
    /// Where the window came from.
    pub a2_source: A2WindowSource,
}

/// Checks an `a2` window: `lo < hi`, both within the f64 range (field `a2_range`).
pub fn check_a2_window(lo: &Rational, hi: &Rational) -> Result<(), TangencyError> {
    if lo > hi {
        return Err(TangencyError::new(
            "a2_range",
            "inverted (lo > hi); give LO,HI with LO < HI",
        ));
    }
    if lo == hi {
        return Err(TangencyError::new(
            "a2_range",
            "empty (lo = hi); give LO,HI with LO < HI",
        ));
    }
    let finite = |v: &Rational| {
        let i = interval_from_rational(v);
        i.inf().is_finite() && i.sup().is_finite()
    };
    if !(finite(lo) && finite(hi)) {
        return Err(TangencyError::new(
            "a2_range",
            "not finite in f64 (|value| beyond 1.8e308)",
        ));
    }
    Ok(())
}

/// The interval version of the Hermite data (tightest enclosures).
pub fn hermite_interval(h: &HermiteData<Rational>) -> Option<HermiteData<Interval>> {
    HermiteData::new(
        interval_from_rational(&h.x1),
        interval_from_rational(&h.y1),
        interval_from_rational(&h.u),
    )
    .ok()
}

/// Enclosures of the ends of the open nonsingular `a2` interval (corrected
/// Prop 3.2), sorted; `None` when it is empty. Which case of the table applies
/// (comparisons of `u` with `(3 ∓ √3)s`, `4s/3`, `2s`, `4s`) is decided
/// exactly over Q; only the irrational ends `α0, α1 = x1(6s - 5u ∓ √D1)/(2u²)`
/// are enclosed (the rational ends `0` and `α2` are enclosed tightly).
pub fn nonsingular_a2_ends(h: &HermiteData<Rational>) -> Option<(Interval, Interval)> {
    use crate::ln::hermite::A2Case;
    use crate::scalar::ScalarSqrt;
    if h.x1.is_negative() {
        // Mirror (x1, y1, a2) -> (-x1, -y1, -a2), see proofs/003-prop-3.2.md.
        let m = HermiteData::new(-h.x1.clone(), -h.y1.clone(), h.u.clone()).ok()?;
        let (lo, hi) = nonsingular_a2_ends(&m)?;
        return Some((-hi, -lo));
    }
    let case = h.prop_3_2_case()?;
    let u2 = &h.u * &h.u;
    let k = interval_from_rational(&(&h.x1 / (Rational::from_integer(2.into()) * u2)));
    let v = interval_from_rational(
        &(h.s() * Rational::from_integer(6.into()) - &h.u * Rational::from_integer(5.into())),
    );
    let alpha = |sign: f64| -> Option<Interval> {
        let r = ScalarSqrt::sqrt(&interval_from_rational(&h.d1()))?;
        Some(k * (v + Interval::try_from((sign, sign)).ok()? * r))
    };
    let a0 = alpha(-1.0)?;
    match case {
        A2Case::Empty => None,
        A2Case::Alpha0Alpha1 => Some((a0, alpha(1.0)?)),
        A2Case::Alpha0Zero => Some((
            a0,
            interval_from_rational(&Rational::from_integer(0.into())),
        )),
        A2Case::Alpha0Alpha2 => Some((a0, interval_from_rational(&h.alpha2()))),
    }
}

/// Whether every `a2` of the enclosure gives a quartic nonsingular on `[0, u]`
/// (`Some(true)`), none does (`Some(false)`), or the enclosure straddles an
/// end of the open nonsingular interval (`None`).
pub fn nonsingular_enclosure(h: &HermiteData<Rational>, a2: Interval) -> Option<bool> {
    let Some((lo, hi)) = nonsingular_a2_ends(h) else {
        // Empty (decided exactly): no nonsingular quartic at all.
        return h.prop_3_2_case().map(|_| false);
    };
    if a2.inf() > lo.sup() && a2.sup() < hi.inf() {
        Some(true)
    } else if a2.sup() <= lo.inf() || a2.inf() >= hi.sup() {
        Some(false)
    } else {
        None
    }
}

/// The default `a2` window (see the module docs) and its source.
pub fn default_a2_window(h: &HermiteData<Rational>) -> ((Rational, Rational), A2WindowSource) {
    let from = |lo: f64, hi: f64| Some((rational_from_f64(lo)?, rational_from_f64(hi)?));
    if let Some((lo, hi)) = nonsingular_a2_ends(h) {
        let (l, r) = (lo.inf(), hi.sup());
        let w = r - l;
        if w.is_finite() && w > 0.0 {
            // The window is whatever these f64 ends are, exactly.
            if let Some(win) = from(l - w, r + w) {
                return (win, A2WindowSource::Nonsingular);
            }
        }
    }
    let (x1, y1, u) = (&h.x1, &h.y1, &h.u);
    let two = Rational::from_integer(2.into());
    let three = Rational::from_integer(3.into());
    let c = -(&two * u * x1 + &three * y1) / (u * u);
    let w = Rational::from_integer(4.into()) * (Rational::from_integer(1.into()) + c.abs());
    ((&c - &w, &c + &w), A2WindowSource::Fallback)
}

impl TangencyProblem {
    /// The problem with the given window (checked) or the default one.
    pub fn new(
        system: TangencySystem,
        a2_window: Option<(Rational, Rational)>,
    ) -> Result<Self, TangencyError> {
        let (a2_window, a2_source) = match a2_window {
            Some((lo, hi)) => {
                check_a2_window(&lo, &hi)?;
                ((lo, hi), A2WindowSource::User)
            }
            None => default_a2_window(&system.hermite),
        };
        Ok(TangencyProblem {
            interval_system: System2::new(&system.eq6, &system.eq7),
            system,
            a2_window,
            a2_source,
        })
    }
    /// The exact search domain `[0, u] × [a2_lo, a2_hi]`.
    pub fn domain(&self) -> RationalBox {
        RationalBox {
            x: (<Rational as Zero>::zero(), self.system.u().clone()),
            y: self.a2_window.clone(),
        }
    }
}

/// Which side of the curve the circle lies on (see the module docs).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Side {
    /// The side the sign of `r` asks for.
    Requested,
    /// The other side (a solution of eq. (6), (7) for `-r`).
    Opposite,
    /// The enclosure cannot decide.
    Undecided,
}

impl Side {
    /// `"requested"`, `"opposite"`, `"undecided"`.
    pub fn as_str(self) -> &'static str {
        match self {
            Side::Requested => "requested",
            Side::Opposite => "opposite",
            Side::Undecided => "undecided",
        }
    }
}

/// One solution with its quartic.
#[derive(Clone, Copy, Debug)]
pub struct RootReport {
    /// Enclosure of the tangency parameter `m`.
    pub m: Interval,
    /// Enclosure of `a2`, and of `a3`, `a4` by eq. (3).
    pub a2: Interval,
    /// Enclosure of `a3` (eq. (3)).
    pub a3: Interval,
    /// Enclosure of `a4` (eq. (3)).
    pub a4: Interval,
    /// Proven to hold exactly one solution (complete solver) or exact (oracle).
    pub certified: bool,
    /// Nonsingular on `[0, u]` (corrected Prop 3.2 on the `a2` enclosure;
    /// `None` if it straddles an end of the nonsingular interval).
    pub nonsingular: Option<bool>,
    /// Side of the circle.
    pub side: Side,
}

/// The result of a tangency solve.
#[derive(Clone, Debug)]
pub struct TangencyReport {
    /// The solutions (pairwise distinct).
    pub roots: Vec<RootReport>,
    /// Lines of solutions `m = 0` or `m = u` (not isolated, never certified).
    pub lines: Vec<SolutionLine>,
    /// True when `roots` are provably all solutions in the domain.
    pub complete: bool,
    /// `"complete"` or `"exact"`.
    pub backend: &'static str,
    /// Boxes of the domain that may hold unreported solutions.
    pub undecided: Vec<UndecidedBox>,
    /// Krawczyk steps (complete solver; 0 for the oracle).
    pub krawczyk_iterations: usize,
    /// Boxes processed (complete solver; 0 for the oracle).
    pub boxes: usize,
    /// The `a2` search window.
    pub a2_window: (Rational, Rational),
    /// Where the window came from.
    pub a2_source: A2WindowSource,
}

/// The quartic, nonsingularity and side of a solution enclosure.
pub fn root_report(sys: &TangencySystem, m: Interval, a2: Interval, certified: bool) -> RootReport {
    let hi = hermite_interval(&sys.hermite);
    let (a3, a4) = hi
        .as_ref()
        .map(|h| h.quartic_coefficients(&a2))
        .unwrap_or((Interval::ENTIRE, Interval::ENTIRE));
    let nonsingular = nonsingular_enclosure(&sys.hermite, a2);
    let sv = Scalar::sign(&sys.side_value::<Interval>(&m, &a2));
    let side = match (sv, sys.r.is_positive()) {
        (Sign::Positive, true) | (Sign::Negative, false) => Side::Requested,
        (Sign::Positive, false) | (Sign::Negative, true) => Side::Opposite,
        _ => Side::Undecided,
    };
    RootReport {
        m,
        a2,
        a3,
        a4,
        certified,
        nonsingular,
        side,
    }
}

/// Solves with the complete interval solver ([`super::complete::solve`]).
///
/// # Examples
/// ```
/// use lncert::tangency::{solve_complete, TangencyProblem, TangencySystem};
/// use lncert::tangency::SolveOptions;
/// use lncert::scalar::frac;
/// let s = TangencySystem::new(frac(3, 1), frac(-1, 1), frac(1, 1), frac(1, 1), frac(1, 1), frac(1, 2)).unwrap();
/// let rep = solve_complete(&TangencyProblem::new(s, None).unwrap(), &SolveOptions::default());
/// assert!(rep.complete);
/// ```
pub fn solve_complete(p: &TangencyProblem, opts: &SolveOptions) -> TangencyReport {
    let sys = &p.system;
    let sol = solve(&p.interval_system, &p.domain(), opts);
    let roots = sol
        .roots
        .iter()
        .map(|r| root_report(sys, r.enclosure[0], r.enclosure[1], true))
        .collect();
    TangencyReport {
        roots,
        lines: sys.solution_lines(),
        complete: sol.complete && sys.solution_lines().is_empty(),
        backend: "complete",
        undecided: sol.undecided,
        krawczyk_iterations: sol.krawczyk_iterations,
        boxes: sol.boxes,
        a2_window: p.a2_window.clone(),
        a2_source: p.a2_source,
    }
}

/// Solves with the exact oracle ([`super::eliminate::exact_solutions`]).
pub fn solve_exact(p: &TangencyProblem) -> TangencyReport {
    let sys = &p.system;
    let sol = exact_solutions(sys, &p.a2_window);
    let roots = sol
        .roots
        .iter()
        .map(|r| {
            let mut rep = root_report(sys, r.m_enclosure, r.a2, true);
            if let Some(a2) = &r.a2_exact {
                // Exact nonsingularity decision for a rational a2.
                rep.nonsingular = sys.hermite.nonsingular_a2_contains(a2);
            }
            rep
        })
        .collect();
    TangencyReport {
        roots,
        lines: sol.lines.clone(),
        complete: sol.complete(),
        backend: "exact",
        undecided: Vec::new(),
        krawczyk_iterations: 0,
        boxes: 0,
        a2_window: p.a2_window.clone(),
        a2_source: p.a2_source,
    }
}

/// Certifies raster candidate cells (`[(m_lo, m_hi), (a2_lo, a2_hi)]`, e.g. the
/// cells of the raster module's output) with Krawczyk and ε-inflation
/// ([`super::complete::certify_candidates`]) and reports them like the other
/// backends: proven roots inside the domain, unresolved cells (and proven
/// roots straddling the domain boundary) as undecided boxes.
///
/// A raster samples the domain and may miss roots, so `complete` is always
/// `false` here: only the `complete` and `exact` backends can prove that no
/// solution is missing. `boxes` counts the candidate cells.
///
/// # Examples
/// ```
/// use lncert::tangency::{solve_candidates, TangencyProblem, TangencySystem};
/// use lncert::scalar::frac;
/// let s = TangencySystem::new(frac(3, 1), frac(-1, 1), frac(1, 1), frac(15, 16), frac(-319, 128), frac(-5, 2)).unwrap();
/// let p = TangencyProblem::new(s, None).unwrap();
/// let cell = [(0.7499, 0.7501), (-5.0001, -4.9999)]; // around the root (3/4, -5)
/// let rep = solve_candidates(&p, &[cell], "cpu");
/// assert_eq!(rep.roots.len(), 1);
/// assert!(!rep.complete);
/// ```
pub fn solve_candidates(
    p: &TangencyProblem,
    cells: &[[(f64, f64); 2]],
    backend: &'static str,
) -> TangencyReport {
    use super::complete::{certify_candidates, UndecidedReason};
    let sys = &p.system;
    let res = certify_candidates(&p.interval_system, cells);
    let dom = p.domain();
    let mut undecided = res.undecided;
    let mut roots = Vec::new();
    for r in &res.roots {
        match dom.contains_box(&r.enclosure) {
            Some(true) => roots.push(root_report(sys, r.enclosure[0], r.enclosure[1], true)),
            Some(false) => {}
            None => undecided.push(UndecidedBox {
                bx: r.enclosure,
                reason: UndecidedReason::DomainBoundary,
            }),
        }
    }
    roots.sort_by(|a, b| a.m.inf().total_cmp(&b.m.inf()));
    TangencyReport {
        roots,
        lines: sys.solution_lines(),
        complete: false,
        backend,
        undecided,
        krawczyk_iterations: res.krawczyk_iterations,
        boxes: cells.len(),
        a2_window: p.a2_window.clone(),
        a2_source: p.a2_source,
    }
}
