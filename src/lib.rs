//! # lncert — proven answers about curves with linear normals
//!
//! lncert implements the constructions and tests of four papers on planar curves
//! with linear normals (LN curves) as kernels written once and run in three
//! arithmetics: exact rationals, certified intervals and `f64`. See the
//! [`scalar`] module for the design and [`ln`] for the propositions.

pub mod approx;
#[cfg(feature = "arbitrary")]
pub mod audit;
pub mod certify;
pub mod curve;
#[cfg(feature = "arbitrary")]
pub mod gen;
pub mod json;
pub mod ln;
pub mod poly;
pub mod reproduce;
pub mod scalar;
pub mod tangency;
