//! Differential property tests of the three arithmetics, on the exported
//! generators (`lncert::gen`, the same ones the fuzz targets and `lncert audit`
//! use). For every kernel family and every case:
//! (a) every interval decision agrees with the exact one (or is undecided);
//! (b) every f64 value lies inside the interval enclosure of the same kernel;
//! (c) f64 decisions equal the exact ones outside the documented band
//!     [`F64_DECISION_BAND`] of relative distance to degeneracy;
//! and the engine's exact decisions agree with root isolation.
//! Cases per property: `LNCERT_PROPTEST_CASES` (default 2000).

use lncert::gen::{strategy, ArcCase, BezierCase, FrameCase, HermiteCase, PairCase, TauCase};
use lncert_cli::audit::{
    check_arc, check_bezier, check_frame, check_hermite, check_pair, check_tau, KernelStats,
    F64_DECISION_BAND,
};
use proptest::prelude::*;

fn config() -> ProptestConfig {
    let cases = std::env::var("LNCERT_PROPTEST_CASES")
        .ok()
        .and_then(|v| v.parse().ok())
        .unwrap_or(2000);
    ProptestConfig {
        cases,
        failure_persistence: None,
        ..ProptestConfig::default()
    }
}

fn verdict(st: &KernelStats) -> Result<(), TestCaseError> {
    prop_assert!(
        st.certified_ok(),
        "certified path failed: {:?}",
        st.first_failure
    );
    prop_assert!(
        st.f64_decision_errors == 0 || st.f64_error_band < F64_DECISION_BAND,
        "f64 decided wrongly {} units of relative distance from the nearest boundary",
        st.f64_error_band
    );
    Ok(())
}

proptest! {
    #![proptest_config(config())]

    #[test]
    fn bezier(c in strategy::<BezierCase>()) {
        let mut st = KernelStats::new("bezier");
        check_bezier(&c, &mut st);
        verdict(&st)?;
    }

    #[test]
    fn frame(c in strategy::<FrameCase>()) {
        let mut st = KernelStats::new("frame");
        check_frame(&c, &mut st);
        verdict(&st)?;
    }

    #[test]
    fn cubic(c in strategy::<TauCase>()) {
        let mut st = KernelStats::new("cubic");
        check_tau(&c, &mut st);
        verdict(&st)?;
    }

    #[test]
    fn pair(c in strategy::<PairCase>()) {
        let mut st = KernelStats::new("pair");
        check_pair(&c, &mut st);
        verdict(&st)?;
    }

    #[test]
    fn hermite(c in strategy::<HermiteCase>()) {
        let mut st = KernelStats::new("hermite");
        check_hermite(&c, &mut st);
        verdict(&st)?;
    }

    #[test]
    fn arc(c in strategy::<ArcCase>()) {
        let mut st = KernelStats::new("arc");
        check_arc(&c, &mut st);
        verdict(&st)?;
    }
}

/// The checks can fail: a deliberately wrong f64 value outside its enclosure
/// and a contradicting interval decision are both reported.
#[test]
fn the_checks_detect_failures() {
    use lncert::scalar::{Interval, IntervalExt};
    let mut st = KernelStats::new("self-test");
    st.value("x", None, Interval::point(1.0), 1.0f64.next_up());
    assert!(!st.certified_ok());
    let mut st = KernelStats::new("self-test");
    st.decision("d", Some(true), Some(false), Some(true), 1.0);
    assert!(!st.certified_ok());
    let mut st = KernelStats::new("self-test");
    st.decision("d", Some(true), None, Some(false), 0.5);
    assert!(st.certified_ok() && st.f64_decision_errors == 1 && st.f64_error_band == 0.5);
}
