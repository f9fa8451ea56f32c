//! `lncert reproduce`: every worked example and printed value of the seeds that
//! lncert implements, recomputed from the built-in data (`data/`), each with a
//! verdict.
//!
//! * `certified` — the printed value or statement is proven (exactly, or as an
//!   interval containing the printed digits);
//! * `erratum` — the printed value is proven wrong; `detail` gives the corrected value;
//! * `refuted` — a printed statement is proven false (no single corrected value);
//! * `undecided` — the engine could not decide (never guessed).
//!
//! Inconsistent printed values are found from the data alone: every printed
//! value is compared with the engine's exact result; nothing is hard-coded as
//! "known wrong".

pub mod offsets;
pub mod printed;
mod scans;
mod seed000;
pub mod seed001;
mod seed003;
pub mod strokes;

use serde::Serialize;

/// The verdict of one claim.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Serialize)]
#[serde(rename_all = "lowercase")]
pub enum Verdict {
    /// The printed value or statement is proven (exactly, or as an interval
    /// containing the printed digits).
    Certified,
    /// A printed statement is proven false (no single corrected value).
    Refuted,
    /// The printed value is proven wrong; the claim's `detail` gives the corrected value.
    Erratum,
    /// The engine could not decide (never guessed).
    Undecided,
}

impl std::fmt::Display for Verdict {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        let s = match self {
            Verdict::Certified => "certified",
            Verdict::Refuted => "refuted",
            Verdict::Erratum => "erratum",
            Verdict::Undecided => "undecided",
        };
        f.write_str(s)
    }
}

/// A group of claims, pushed by one function (an `Err` becomes one undecided claim).
type ClaimGroup = fn(&mut Vec<Claim>) -> Result<(), String>;

/// One checked claim of a seed.
#[derive(Clone, Debug, Serialize)]
pub struct Claim {
    /// Stable identifier, e.g. `000-fig5a-delta-l`.
    pub id: String,
    /// The paper and place, e.g. `seed 000 Fig. 5(a)`.
    pub source: String,
    /// What the paper states.
    pub statement: String,
    /// Whether the statement was proven, refuted or corrected, or left undecided.
    pub verdict: Verdict,
    /// The engine's figures, and the correction for an erratum.
    pub detail: String,
}

impl Claim {
    pub(crate) fn new(
        id: &str,
        source: &str,
        statement: impl Into<String>,
        verdict: Verdict,
        detail: impl Into<String>,
    ) -> Claim {
        Claim {
            id: id.into(),
            source: source.into(),
            statement: statement.into(),
            verdict,
            detail: detail.into(),
        }
    }
}

/// An exact number from the built-in JSON: a string (`"5/2"`, `"-1"`) or a
/// JSON number read from its printed digits (`0.17346`), never through f64.
pub(crate) fn json_rational(v: &serde_json::Value) -> Result<lncert::scalar::Rational, String> {
    let text = match v {
        serde_json::Value::String(s) => s.clone(),
        serde_json::Value::Number(n) => n.to_string(),
        _ => return Err(format!("{v} is not a number")),
    };
    lncert::scalar::parse_rational(&text).map_err(|e| e.to_string())
}

/// Built-in data (copies of `../shared/data` plus values transcribed from the seed texts).
pub mod data {
    /// Seed 000 §4, Fig. 5: the two worked pair examples, as printed
    /// (`data/seed000_fig5_examples.json`).
    pub const FIG5: &str = include_str!("../../../data/seed000_fig5_examples.json");
    /// Seed 003 §6: the two normal-form cubics with a common Gauss map, as
    /// printed (`data/seed003_sec6_example.json`).
    pub const SEC6: &str = include_str!("../../../data/seed003_sec6_example.json");
    /// Printed values transcribed from the seed texts that the other files lack
    /// (`data/printed_text_values.json`).
    pub const TEXT: &str = include_str!("../../../data/printed_text_values.json");
}

/// Runs every claim. Errors in the built-in data become `undecided` claims
/// naming the problem (never a panic).
///
/// # Examples
/// ```
/// let claims = lncert_cli::reproduce::run_all();
/// assert!(claims.iter().any(|c| c.source.starts_with("seed 000 Fig. 5(a)")));
/// assert!(claims.iter().all(|c| c.verdict != lncert_cli::reproduce::Verdict::Undecided));
/// ```
pub fn run_all() -> Vec<Claim> {
    run_all_with_strokes().0
}

/// [`run_all`], also returning the computed strokes of the `stroke-…` claims
/// ([`strokes::runs`]) for pictures.
pub fn run_all_with_strokes() -> (Vec<Claim>, Vec<strokes::Run>) {
    let mut out = Vec::new();
    seed000::claims(&mut out);
    seed003::claims(&mut out);
    scans::claims(&mut out);
    offsets::claims(&mut out);
    seed001::claims(&mut out);
    let runs = strokes::runs();
    strokes::claims_of(&runs, &mut out);
    (out, runs)
}
