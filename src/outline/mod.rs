//! Outlines: what turns offset and convolution approximants into the boundary
//! of a swept region. So far: certified intersections of polynomial pieces
//! ([`intersect`]), complete over the parameter domain, the first step of
//! trimming.

pub mod intersect;
