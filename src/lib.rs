//! # lncert — proven answers about curves with linear normals
//!
//! lncert implements the constructions and tests of four papers on planar curves
//! with linear normals (LN curves) as kernels written once and run in three
//! arithmetics: exact rationals, certified intervals and `f64`. See the
//! [`scalar`] module for the design and [`ln`] for the propositions.
//!
//! # The root API
//!
//! The entry points a downstream crate needs are re-exported here, with one
//! error type, [`Error`] (the field and the reason), into which every error of
//! every engine converts:
//!
//! | task | entry points |
//! |---|---|
//! | read curves and shapes | [`parse_curve`], [`ShapeDesc::parse`], [`parse_rational`] |
//! | a tolerance, given once to the options and the certificates | [`Tolerance`] (exact, and the largest `f64` below it) |
//! | certify a Hausdorff distance or a tolerance | [`hausdorff`], [`HausdorffConfig`], [`HausdorffBounds`], [`Certificate`] |
//! | re-check a certificate | [`verify`] |
//! | a proven offset | [`offset()`], [`OffsetOptions`], [`OffsetResult`], [`union_certificate`] |
//! | a proven stroke outline | [`stroke()`], [`StrokeOptions`], [`Stroke`] |
//! | results out: SVG path data, SVG documents (kurbo `BezPath`: `kurbo_bridge`) | [`write::path_data`], [`write::offset_path_data`], [`svg_document`], [`SvgShape`], [`SvgOptions`] |
//! | circle tangency (seed 003 §4) | [`TangencySystem`], [`TangencyProblem`], [`solve_complete`] |
//! | property tests of your own geometry code | `lncert::gen` (feature `proptest`: strategies; `arbitrary`: fuzz inputs) |
//!
//! # Modules
//!
//! | layer | modules |
//! |---|---|
//! | arithmetic | [`scalar`] (exact rationals, certified intervals, `f64`, filters) , [`poly`] (exact root isolation) |
//! | curves and propositions | [`curve`] (Bézier, B-spline), [`ln`] (the seeds' propositions) |
//! | the geometry model | [`shape`] (exact shapes, readers, limits) |
//! | engines | [`certify`] (Hausdorff bounds, certificates, [`verify`]), [`offset`](mod@offset) (proven offsets and convolutions), [`stroke`](mod@stroke) (proven stroke outlines), [`tangency`] (seed 003's circle tangency) |
//! | writers and bridges | [`write`](mod@write) (path data, SVG documents), `kurbo_bridge` (feature `kurbo`: both ways), `gen` (features `proptest` / `arbitrary`) |
//!
//! Dependencies point down the table. The engines' internals (search,
//! parametric proofs, jets, Bernstein hulls, the piece parametrisations) are
//! private, and so is the bounded JSON reader. The `lncert`
//! command line, `lncert reproduce` and `lncert audit` live in the crate
//! `lncert-cli` (directory `cli/` of the repository).
//!
//! # Using lncert as a library
//!
//! The certified arithmetic is [inari](https://docs.rs/inari), which needs the
//! CPU's AVX/FMA instructions and refuses to compile without them: a crate that
//! depends on lncert must build with `-C target-cpu=haswell` (or newer), e.g. in
//! its `.cargo/config.toml`:
//!
//! ```toml
//! [build]
//! rustflags = ["-C", "target-cpu=haswell"]
//! ```
//!
//! With `default-features = false` the library builds without the command line
//! (`cli`: clap), the GPU raster (`gpu`: wgpu) and the fuzz generators
//! (`arbitrary`); add `features = ["proptest"]` for the proptest strategies.
//!
//! # Examples
//! ```
//! use lncert::{hausdorff, verify, Certificate, HausdorffConfig, ShapeDesc, Tolerance};
//! # fn main() -> Result<(), lncert::Error> {
//! let a = ShapeDesc::parse("M 0 0 Q 0.5 0.5 1 0")?;
//! let b = ShapeDesc::parse("M 0 0 L 1 0")?;
//! // claim: d_H(a, b) ≤ 0.26 (the true distance is 1/4), exactly 13/50
//! let tol: Tolerance = "0.26".parse()?;
//! let cfg = HausdorffConfig { tol: Some(tol.clone()), ..Default::default() };
//! let r = hausdorff(&a, &b, &cfg)?;
//! assert!(r.hi <= tol.value()); // the largest f64 ≤ 13/50
//! let cert = Certificate::new(&a, &b, &tol, &r).expect("proven");
//! let valid = verify(&cert.to_json_string())?;
//! assert_eq!(&valid.tol, tol.exact());
//! # Ok(())
//! # }
//! ```

pub mod offset;

// The Rust examples of the README and of docs/library.md, compiled and run as
// doctests by `cargo test` (never part of the built library).
#[cfg(doctest)]
#[doc = include_str!("../README.md")]
pub struct ReadmeDoctests;
#[cfg(doctest)]
#[doc = include_str!("../docs/library.md")]
pub struct LibraryDocDoctests;
pub mod certify;
pub mod curve;
#[cfg(feature = "arbitrary")]
pub mod gen;
// Internal: the bounded JSON reader of every input.
mod json;
#[cfg(feature = "kurbo")]
pub mod kurbo_bridge;
pub mod ln;
pub mod poly;
pub mod scalar;
pub mod shape;
pub mod stroke;
pub mod tangency;
#[cfg(test)]
mod test_util;
pub mod write;

mod error;
pub use error::Error;

mod tolerance;
pub use tolerance::Tolerance;

pub use certify::verify::{verify, Valid};
pub use certify::{
    hausdorff, sampled_estimate, Certificate, Config as HausdorffConfig, HausdorffBounds,
};
pub use curve::{Bezier, V2};
pub use offset::{offset, union_certificate, OffsetMethod, OffsetOptions, OffsetResult};
pub use scalar::{parse_rational, Interval, Rational};
pub use shape::{parse_curve, ArcDesc, ShapeDesc, ShapeError, TravelledArc};
pub use stroke::{stroke, Stroke, StrokeOptions};
pub use tangency::{solve_complete, SolveOptions, TangencyProblem, TangencyReport, TangencySystem};
pub use write::{svg_document, SvgOptions, SvgShape};
