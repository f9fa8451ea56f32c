//! The result of one `lncert prop` run, printed either as readable text lines
//! or as one JSON document:
//!
//! ```json
//! {"id": "003:2.1", "title": "...", "inputs": {...}, "results": {...},
//!  "verdict": true, "direct": true, "agrees": true}
//! ```
//!
//! Exact values are `"p/q"` strings, intervals `[lo, hi]` (outward rounded).
//! `verdict` is what the proposition predicts for the given data, `direct` what
//! the engine finds by looking at the curve itself (exact root isolation or a
//! certified enclosure); `agrees` is present when both are.
//!
//! Exit code: 1 if the proposition disagrees with the direct check (an
//! erratum), 3 if a verdict is undecided, else 0.

use super::args::q;
use super::print_out;
use lncert::scalar::{interval_to_json, Interval, Rational};
use serde_json::{json, Map, Value};
use std::fmt::Write as _;

/// One proposition's report under construction.
#[derive(Debug)]
pub struct Report {
    id: String,
    title: String,
    inputs: Map<String, Value>,
    results: Map<String, Value>,
    lines: Vec<String>,
    verdict: Option<Value>,
    direct: Option<Value>,
    /// `Some(None)`: a comparison was attempted but is undecided.
    agrees: Option<Option<bool>>,
    undecided: bool,
}

/// `"yes"`/`"no"`/`"undecided"` words for a decision.
pub fn word(v: Option<bool>, yes: &str, no: &str) -> String {
    match v {
        Some(true) => yes.to_string(),
        Some(false) => no.to_string(),
        None => "undecided".to_string(),
    }
}

/// An interval as `[lo, hi]` text.
pub fn show_interval(x: &Interval) -> String {
    format!("[{}, {}]", x.inf(), x.sup())
}

impl Report {
    /// A new report for the qualified ID `seed:prop`.
    pub fn new(id: &str, title: &str) -> Report {
        Report {
            id: id.to_string(),
            title: title.to_string(),
            inputs: Map::new(),
            results: Map::new(),
            lines: Vec::new(),
            verdict: None,
            direct: None,
            agrees: None,
            undecided: false,
        }
    }
    /// Records an input as its exact string.
    pub fn input(&mut self, key: &str, value: impl Into<String>) {
        self.inputs
            .insert(key.to_string(), Value::String(value.into()));
    }
    /// Records an input as JSON (points, frames, lists).
    pub fn input_json(&mut self, key: &str, value: Value) {
        self.inputs.insert(key.to_string(), value);
    }
    /// A text line only.
    pub fn line(&mut self, text: impl Into<String>) {
        self.lines.push(text.into());
    }
    /// A result value with its text line.
    pub fn value(&mut self, key: &str, value: Value, text: impl Into<String>) {
        self.results.insert(key.to_string(), value);
        self.lines.push(text.into());
    }
    /// An exact result `label = p/q`.
    pub fn exact(&mut self, key: &str, label: &str, r: &Rational) {
        self.value(key, json!(q(r)), format!("{label} = {}", q(r)));
    }
    /// A certified result `label ∈ [lo, hi]`.
    pub fn interval(&mut self, key: &str, label: &str, x: &Interval) {
        self.value(
            key,
            interval_to_json(x),
            format!("{label} ∈ {}", show_interval(x)),
        );
    }
    /// A decision among the results (`null` in JSON when undecided).
    pub fn decision(&mut self, key: &str, label: &str, v: Option<bool>, yes: &str, no: &str) {
        self.value(key, json!(v), format!("{label}: {}", word(v, yes, no)));
    }
    /// The proposition's verdict for this data (`None` = undecided).
    pub fn verdict(&mut self, label: &str, v: Option<bool>, yes: &str, no: &str) {
        self.undecided |= v.is_none();
        self.verdict = Some(json!(v));
        self.lines
            .push(format!("verdict ({label}): {}", word(v, yes, no)));
    }
    /// The direct check, compared with a boolean verdict.
    pub fn direct(
        &mut self,
        label: &str,
        d: Option<bool>,
        yes: &str,
        no: &str,
        verdict: Option<bool>,
    ) {
        self.direct = Some(json!(d));
        self.lines
            .push(format!("direct check ({label}): {}", word(d, yes, no)));
        let agrees = match (verdict, d) {
            (Some(v), Some(d)) => Some(v == d),
            _ => None,
        };
        self.set_agrees(agrees);
    }
    /// A verdict and direct check given as JSON values with an explicit comparison.
    pub fn compared(&mut self, verdict: Value, direct: Value, agrees: Option<bool>) {
        self.verdict = Some(verdict);
        self.direct = Some(direct);
        self.set_agrees(agrees);
    }
    /// Records a further comparison: the report agrees only if all comparisons do.
    pub fn set_agrees(&mut self, a: Option<bool>) {
        let combined = match (self.agrees, a) {
            (None, a) => a,
            (Some(Some(false)), _) | (_, Some(false)) => Some(false),
            (Some(None), _) | (_, None) => None,
            (Some(Some(true)), Some(true)) => Some(true),
        };
        self.agrees = Some(combined);
    }
    /// The exit code: 1 on disagreement, 3 when undecided, else 0.
    pub fn exit_code(&self) -> i32 {
        match self.agrees {
            Some(Some(false)) => super::EXIT_REFUTED,
            Some(None) => super::EXIT_UNDECIDED,
            _ if self.undecided => super::EXIT_UNDECIDED,
            _ => super::EXIT_OK,
        }
    }
    /// Prints the report (text or JSON) and returns the exit code.
    pub fn emit(self, as_json: bool) -> i32 {
        let code = self.exit_code();
        if as_json {
            print_out(&format!(
                "{}\n",
                serde_json::to_string_pretty(&self.to_json()).expect("JSON values serialize")
            ));
        } else {
            print_out(&self.to_text());
        }
        code
    }
    fn to_json(&self) -> Value {
        let mut doc = Map::new();
        doc.insert("id".into(), json!(self.id));
        doc.insert("title".into(), json!(self.title));
        doc.insert("inputs".into(), Value::Object(self.inputs.clone()));
        doc.insert("results".into(), Value::Object(self.results.clone()));
        if let Some(v) = &self.verdict {
            doc.insert("verdict".into(), v.clone());
        }
        if let Some(d) = &self.direct {
            doc.insert("direct".into(), d.clone());
        }
        if let Some(a) = self.agrees {
            doc.insert("agrees".into(), json!(a));
        }
        Value::Object(doc)
    }
    fn to_text(&self) -> String {
        let mut s = format!("prop {} — {}\n", self.id, self.title);
        let inputs: Vec<String> = self
            .inputs
            .iter()
            .map(|(k, v)| format!("{k} = {}", plain(v)))
            .collect();
        if !inputs.is_empty() {
            let _ = writeln!(s, "  inputs: {}", inputs.join(", "));
        }
        for l in self.lines.iter().filter(|l| !l.is_empty()) {
            let _ = writeln!(s, "  {l}");
        }
        let last = match self.agrees {
            Some(Some(true)) => "agrees: yes (the proposition matches the direct check)",
            Some(Some(false)) => "ERRATUM: the proposition disagrees with the direct check",
            Some(None) => "agrees: undecided",
            None => return s,
        };
        let _ = writeln!(s, "  {last}");
        s
    }
}

/// A JSON value without string quotes, for text output.
fn plain(v: &Value) -> String {
    match v {
        Value::String(s) => s.clone(),
        Value::Array(a) => format!("[{}]", a.iter().map(plain).collect::<Vec<_>>().join(", ")),
        other => other.to_string(),
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn exit_codes_follow_the_comparison() {
        let mut r = Report::new("003:2.1", "t");
        assert_eq!(r.exit_code(), 0);
        r.verdict("v", Some(true), "y", "n");
        r.direct("d", Some(true), "y", "n", Some(true));
        assert_eq!(r.exit_code(), 0);
        r.set_agrees(Some(false));
        assert_eq!(r.exit_code(), 1);
        let mut u = Report::new("x", "t");
        u.verdict("v", None, "y", "n");
        assert_eq!(u.exit_code(), 3);
    }
}
