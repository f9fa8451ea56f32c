//! Differential checks of the three arithmetics, kernel by kernel: the engine
//! auditing its own float fast path (`lncert audit`), and the shared check
//! functions of the property tests and the fuzz targets.
//!
//! For every case each kernel runs in `Rational` (exact), `Interval`
//! (certified) and `f64` on the same inputs (finite floats, read exactly), and
//! [`KernelStats`] records:
//!
//! * **certified-path disagreements** — an interval decision contradicting the
//!   exact one, an exact decision left undecided, or an f64 value *outside* the
//!   interval enclosure computed by the same kernel. All must be 0.
//!
//!   Why an f64 value must lie inside the enclosure, with no widening: both are
//!   the same sequence of operations on the same float inputs. By induction,
//!   each f64 intermediate lies in the matching interval: if `x ∈ X`, the exact
//!   `op(x)` lies in the exact range `op(X)`, and round-to-nearest of a number is
//!   between its round-down and round-up, which are monotone; the interval's
//!   ends are the round-down/round-up of that range's ends. So the documented
//!   forward error bound for *same-kernel* values is the enclosure itself.
//! * **f64 decision errors** — where the fast path decides differently from the
//!   exact one, with the *relative distance to degeneracy* of the case (how far
//!   the input is from the nearest boundary of the decision, relative to its
//!   size); the largest such distance is the measured band outside which f64
//!   was always right.
//! * **max f64 error in ulps** against the exact value, and the interval
//!   filter's fallback rate (decisions the interval left to the exact path).

/// The documented near-degeneracy band of the f64 path: on every generated
/// case whose relative distance to the nearest decision boundary is at least
/// this, the f64 decision equals the exact one (asserted by
/// `cli/tests/differential.rs`; `lncert audit` measures the actual band, about
/// 1e-9 at most on the default seed).
pub const F64_DECISION_BAND: f64 = 1e-6;

mod checks;
pub mod fuzz;

pub use checks::{
    check_arc, check_bezier, check_frame, check_hermite, check_hermite_with, check_pair, check_tau,
};

use lncert::scalar::{rational_from_f64, Interval, IntervalExt, Rational};
use serde::Serialize;

/// Counters of one kernel family.
#[derive(Clone, Debug, Default, Serialize)]
pub struct KernelStats {
    /// Name of the kernel family, as in [`KERNELS`] (e.g. `pair`).
    pub name: &'static str,
    /// Cases run (inputs the kernel accepts in exact arithmetic).
    pub cases: u64,
    /// Cases the generator produced but the kernel rejects (typed error in every arithmetic).
    pub rejected: u64,
    /// Decisions compared.
    pub decisions: u64,
    /// Interval decisions contradicting the exact ones, exact decisions left
    /// undecided, f64 values outside the enclosure. Must be 0.
    pub disagreements_certified: u64,
    /// Decisions the interval path left undecided (the filter's fallbacks).
    pub interval_undecided: u64,
    /// f64 decisions different from the exact ones.
    pub f64_decision_errors: u64,
    /// f64 evaluations that could not decide at all (overflow, underflow, NaN):
    /// counted apart from wrong decisions.
    pub f64_failures: u64,
    /// Largest relative distance to degeneracy at which f64 decided wrongly.
    pub f64_error_band: f64,
    /// Values compared (f64 vs enclosure, and vs exact when rational).
    pub values: u64,
    /// Largest |f64 - exact| in ulps of the exact value (nonzero exact values;
    /// large numbers mean cancellation: a tiny exact value computed from large terms).
    pub max_f64_error_ulps: f64,
    /// Exact (engine) decision vs the direct check by root isolation, where a
    /// kernel has one. Must be 0.
    pub direct_disagreements: u64,
    /// The first certified failure, for the report.
    pub first_failure: Option<String>,
}

impl KernelStats {
    /// Zeroed counters for the kernel family `name`.
    pub fn new(name: &'static str) -> Self {
        KernelStats {
            name,
            ..Default::default()
        }
    }
    /// `interval_undecided / decisions`.
    pub fn fallback_rate(&self) -> f64 {
        if self.decisions == 0 {
            0.0
        } else {
            self.interval_undecided as f64 / self.decisions as f64
        }
    }
    /// True when the certified path never failed.
    pub fn certified_ok(&self) -> bool {
        self.disagreements_certified == 0 && self.direct_disagreements == 0
    }
    fn fail(&mut self, what: String) {
        self.disagreements_certified += 1;
        if self.first_failure.is_none() {
            self.first_failure = Some(what);
        }
    }
    /// Compares one decision across the arithmetics; `degeneracy` is the
    /// relative distance of the case to the decision's boundary.
    pub fn decision<T: PartialEq + std::fmt::Debug>(
        &mut self,
        what: &str,
        exact: Option<T>,
        interval: Option<T>,
        float: Option<T>,
        degeneracy: f64,
    ) {
        self.decisions += 1;
        let Some(e) = exact else {
            self.fail(format!("{what}: exact path undecided"));
            return;
        };
        match interval {
            None => self.interval_undecided += 1,
            Some(i) if i != e => self.fail(format!("{what}: interval says {i:?}, exact {e:?}")),
            _ => {}
        }
        match float {
            None => self.f64_failures += 1,
            Some(f) if f != e => {
                self.f64_decision_errors += 1;
                if degeneracy.is_finite() {
                    self.f64_error_band = self.f64_error_band.max(degeneracy);
                }
            }
            _ => {}
        }
    }
    /// Compares one value: the f64 result must lie in the enclosure; its error
    /// against the exact value (when rational) is measured in ulps.
    pub fn value(
        &mut self,
        what: &str,
        exact: Option<&Rational>,
        enclosure: Option<Interval>,
        float: f64,
    ) {
        self.values += 1;
        if let Some(e) = enclosure {
            if float.is_finite() && !e.contains(float) {
                self.fail(format!(
                    "{what}: f64 value {float:e} outside the enclosure [{:e}, {:e}]",
                    e.inf(),
                    e.sup()
                ));
            }
            if let Some(x) = exact {
                if !e.contains_rational(x) {
                    self.fail(format!("{what}: exact value {x} outside the enclosure"));
                }
            }
        }
        // Exact zeros are skipped: an error "in ulps of 0" is meaningless (the
        // enclosure check above still applies to them).
        if let (Some(x), Some(f)) = (
            exact.filter(|x| **x != Rational::default()),
            rational_from_f64(float),
        ) {
            let ulps = ulps_between(x, &f);
            if ulps > self.max_f64_error_ulps {
                self.max_f64_error_ulps = ulps;
            }
        }
    }
    /// Records a disagreement between the engine's exact decision and the direct check.
    pub fn direct(&mut self, what: &str, engine: Option<bool>, direct: bool) {
        if engine != Some(direct) {
            self.direct_disagreements += 1;
            if self.first_failure.is_none() {
                self.first_failure =
                    Some(format!("{what}: engine {engine:?}, direct check {direct}"));
            }
        }
    }
    /// Adds another run's counters.
    pub fn merge(&mut self, o: &KernelStats) {
        self.cases += o.cases;
        self.rejected += o.rejected;
        self.decisions += o.decisions;
        self.disagreements_certified += o.disagreements_certified;
        self.interval_undecided += o.interval_undecided;
        self.f64_decision_errors += o.f64_decision_errors;
        self.f64_failures += o.f64_failures;
        self.f64_error_band = self.f64_error_band.max(o.f64_error_band);
        self.values += o.values;
        self.max_f64_error_ulps = self.max_f64_error_ulps.max(o.max_f64_error_ulps);
        self.direct_disagreements += o.direct_disagreements;
        if self.first_failure.is_none() {
            self.first_failure.clone_from(&o.first_failure);
        }
    }
}

/// |x - f| in units in the last place of the float nearest to `x` (the
/// smallest subnormal when `x` is 0); capped at 2^64.
pub fn ulps_between(x: &Rational, f: &Rational) -> f64 {
    use lncert::scalar::Scalar;
    let xa = x.approx().abs();
    let ulp = if xa == 0.0 || !xa.is_finite() {
        f64::from_bits(1)
    } else {
        xa.next_up() - xa
    };
    let diff = (x - f).approx().abs();
    (diff / ulp).min(18_446_744_073_709_551_616.0)
}

/// The kernel families audited, in report order.
pub const KERNELS: [&str; 6] = ["bezier", "frame", "cubic", "pair", "hermite", "arc"];

/// Runs `cases` generated cases (seeded, reproducible) through one kernel family.
pub fn run_kernel(name: &str, cases: usize, seed: u64) -> KernelStats {
    use lncert::gen::cases_from_seed;
    let mut st = KernelStats::new(
        KERNELS
            .iter()
            .copied()
            .find(|k| *k == name)
            .unwrap_or("unknown"),
    );
    match name {
        "bezier" => cases_from_seed(seed, cases)
            .iter()
            .for_each(|c| check_bezier(c, &mut st)),
        "frame" => cases_from_seed(seed, cases)
            .iter()
            .for_each(|c| check_frame(c, &mut st)),
        "cubic" => cases_from_seed(seed, cases)
            .iter()
            .for_each(|c| check_tau(c, &mut st)),
        "pair" => cases_from_seed(seed, cases)
            .iter()
            .for_each(|c| check_pair(c, &mut st)),
        "hermite" => cases_from_seed(seed, cases)
            .iter()
            .for_each(|c| check_hermite(c, &mut st)),
        "arc" => cases_from_seed(seed, cases)
            .iter()
            .for_each(|c| check_arc(c, &mut st)),
        _ => {}
    }
    st
}
