//! Seed 003 §4: LN curves tangent to a circle.
//!
//! | module | content |
//! |---|---|
//! | [`poly2`] | dense bivariate polynomials over any scalar, exact expression parser |
//! | [`system`] | eq. (6), (7) in the unknowns `(m, a2)`, degrees 10 and 6, Bézout bound 60 |
//! | [`krawczyk`] | interval Krawczyk operator, ε-inflation, centred-form enclosures |
//! | [`complete`] | complete branch-and-prune solver (soundness argument in its docs), candidate certification |
//! | [`eliminate`] | exact oracle: eq. (7) is linear in `a2`, elimination to one univariate polynomial, Sturm isolation |
//! | [`solve`] | the tangency problem end to end: domain, default `a2` range, per-root curve, nonsingularity, side |
//! | [`radii`] | beyond the paper: certified inner/outer enclosures of the valid signed radii for a fixed centre |
//!
//! Coordinates: `x = m` (the parameter of the tangency point), `y = a2` (the
//! free coefficient of the quartic), as in the raster module.

pub mod complete;
pub mod eliminate;
pub mod krawczyk;
pub mod poly2;
pub mod radii;
pub mod solve;
pub mod system;
