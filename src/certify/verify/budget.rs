//! The verifier's work budget: **checking a certificate costs at most a fixed
//! multiple of its size**, or the certificate is refused as too costly.
//!
//! A certificate is a public statement, and anyone may hand one to
//! `lncert verify`: its size, not its author, must bound the work of checking
//! it. Most of the checks are linear in the document (each box, part or cell
//! is one enclosure of bounded degree), but three loops of the stroke
//! verifier multiply two sizes or search: the outside test of claim (a)
//! (Bernstein exclusion of a disk against the input pieces within its reach),
//! the pair search of claim (c) (every two outline parts whose boxes meet,
//! each pair bisected until separated) and the per-box enclosures of claim (b)
//! (de Casteljau steps quadratic in the degree). Each charges its work here,
//! in **work units** of about one interval operation:
//!
//! | work | units charged |
//! |---|---|
//! | one Bernstein subdivision of `n` coefficients (claim (a)) | `n²` |
//! | one disk-against-piece test set up (`n` coefficients) | `n` |
//! | one node of a box index visited | 1 |
//! | one candidate pair of claim (c), each bisection step | `(|a| + |b|)²` hull points |
//! | one box of claim (b) on pieces of `n`, `m` control points | `n² + m²` |
//!
//! The budget of a document of size `S` (its compact JSON length, see
//! [`json_size`]: whitespace buys nothing) is [`WORK_PER_BYTE`]` · S +
//! `[`BASE_WORK`]. Genuine certificates written by `lncert stroke` use a few
//! units per byte (the test curves, icons and glyphs measured in
//! `proofs/stroke-certificate.md`), so the budget ([`WORK_PER_BYTE`] = 48) leaves them a margin of
//! more than 30×; a hostile document that would need more is refused with
//! the reason "too costly to check", in time proportional to its size.
//!
//! The counter is shared by every thread of one check (an atomic add); the
//! limit is checked after each charge, so a check overruns its budget by at
//! most one unit of work per thread.

use crate::json::Json;
use std::sync::atomic::{AtomicU64, Ordering};
use std::sync::Arc;

/// Work units allowed per byte of the document (its length as compact JSON:
/// whitespace counts nothing).
pub const WORK_PER_BYTE: u64 = 48;
/// Work units allowed to every document, whatever its size.
pub const BASE_WORK: u64 = 1 << 21;

/// The work meter of one check: units used so far and the limit, shared
/// (cloning shares the counter: the members of a certificate set draw from
/// their document's one budget).
#[derive(Clone, Debug)]
pub(crate) struct Budget {
    used: Arc<AtomicU64>,
    limit: u64,
}

/// Why a check stopped: the budget is spent.
#[derive(Clone, Debug, PartialEq, Eq)]
pub(crate) struct Exhausted {
    pub(crate) limit: u64,
}

impl std::fmt::Display for Exhausted {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        write!(
            f,
            "too costly to check: the certificate needs more than the {} work units its size allows ({WORK_PER_BYTE} per byte + {BASE_WORK}); a genuine certificate uses a few per byte",
            self.limit
        )
    }
}

impl Budget {
    /// The budget of a document of `size` bytes.
    pub(crate) fn for_size(size: usize) -> Budget {
        let limit = (size as u64)
            .saturating_mul(WORK_PER_BYTE)
            .saturating_add(BASE_WORK);
        Budget::with_limit(limit)
    }

    /// A budget of `limit` units.
    pub(crate) fn with_limit(limit: u64) -> Budget {
        Budget {
            used: Arc::new(AtomicU64::new(0)),
            limit,
        }
    }

    /// No limit: the writer runs the verifier's tests to choose what it
    /// writes, on its own input.
    pub(crate) fn unlimited() -> Budget {
        Budget::with_limit(u64::MAX)
    }

    /// Charges `units`; `Err` once the total exceeds the limit.
    #[inline]
    pub(crate) fn charge(&self, units: u64) -> Result<(), Exhausted> {
        if self.limit == u64::MAX {
            return Ok(());
        }
        let before = self.used.fetch_add(units, Ordering::Relaxed);
        if before.saturating_add(units) > self.limit {
            Err(Exhausted { limit: self.limit })
        } else {
            Ok(())
        }
    }

    /// Whether the budget is spent (a cheap test for loops that stop early).
    pub(crate) fn spent(&self) -> bool {
        self.limit != u64::MAX && self.used.load(Ordering::Relaxed) > self.limit
    }

    /// The error of a spent budget.
    pub(crate) fn exhausted(&self) -> Exhausted {
        Exhausted { limit: self.limit }
    }

    /// Units used so far.
    pub(crate) fn used(&self) -> u64 {
        self.used.load(Ordering::Relaxed)
    }

    /// The limit.
    pub(crate) fn limit(&self) -> u64 {
        self.limit
    }
}

/// The size of a document in bytes as compact JSON: what the budget is
/// proportional to. Whitespace and indentation count nothing, so padding a
/// document buys no work; every value, key and number does.
pub(crate) fn json_size(v: &Json) -> usize {
    match v {
        Json::Null => 4,
        Json::Bool(b) => {
            if *b {
                4
            } else {
                5
            }
        }
        Json::Number(s) => s.len(),
        Json::String(s) => s.len() + 2,
        Json::Array(a) => 2 + a.iter().map(|x| json_size(x) + 1).sum::<usize>(),
        Json::Object(m) => {
            2 + m
                .iter()
                .map(|(k, x)| k.raw().len() + 4 + json_size(x))
                .sum::<usize>()
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_size_is_the_compact_length_whatever_the_whitespace() {
        let compact = r#"{"a":[1,"x",true,null,{"b":-2.5}]}"#;
        let padded = "{ \"a\" : [ 1 ,\n \"x\" , true , null , { \"b\" :   -2.5 } ] }";
        let lim = crate::json::Limits::DEFAULT;
        let (c, p) = (
            crate::json::parse(compact, &lim).unwrap(),
            crate::json::parse(padded, &lim).unwrap(),
        );
        assert_eq!(json_size(&c), json_size(&p));
        // within a few bytes of the compact text (a trailing comma per member)
        let n = json_size(&c);
        assert!(n >= compact.len() && n <= compact.len() + 8, "{n}");
    }

    #[test]
    fn a_budget_refuses_past_its_limit_and_is_shared_by_clones() {
        let b = Budget::with_limit(10);
        let c = b.clone();
        assert!(b.charge(6).is_ok());
        assert!(!b.spent());
        assert_eq!(c.charge(5), Err(Exhausted { limit: 10 }));
        assert!(b.spent() && c.spent());
        assert_eq!(b.used(), 11);
        let u = Budget::unlimited();
        assert!(u.charge(u64::MAX).is_ok() && u.charge(u64::MAX).is_ok());
        assert!(!u.spent());
        let s = Budget::for_size(1000);
        assert_eq!(s.limit(), 1000 * WORK_PER_BYTE + BASE_WORK);
    }
}
