//! The application side of lncert: the `lncert` command line's two jobs that
//! are more than a call into the engine, shared with the tests, benches and
//! fuzz targets of this crate.
//!
//! - [`reproduce`]: the claims of `lncert reproduce` (every worked example of
//!   the seeds, with verdicts) and the seed data they are built from;
//! - [`audit`]: the self-audit behind `lncert audit` and the fuzz targets
//!   (float fast path against the exact and interval results).
//!
//! The engine is the `lncert` crate; nothing here is part of its API.

pub mod audit;
pub mod reproduce;
