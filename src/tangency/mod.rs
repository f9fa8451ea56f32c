//! Tangency of quartic LN curves to a circle (seed 003 §4): the raster solver backends.

pub mod raster;
