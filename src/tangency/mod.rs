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
//! | [`raster`] | the paper's raster: signs of both equations on an N×N grid, CPU (rayon) and GPU (wgpu) backends |
//! | [`radii`] | beyond the paper: certified inner/outer enclosures of the valid signed radii for a fixed centre |
//!
//! Coordinates: `x = m` (the parameter of the tangency point), `y = a2` (the
//! free coefficient of the quartic), as in the raster module.
//!
//! # Raster candidates (seed 003 §4.2)
//!
//! The raster backends sample `p = eq. (6)` and `q = eq. (7)` on a grid over the
//! domain `[0, u] × [a2_lo, a2_hi]` of a [`solve::TangencyProblem`]: the f64
//! coefficients are [`poly2::Poly2::coeffs_f64`] of `problem.system.eq6` and
//! `.eq7` (layout `coeffs[i*(deg_y+1)+j]`, `x = m`, `y = a2`). Each candidate
//! cell `[x_i, x_{i+1}] × [y_j, y_{j+1}]` becomes the box
//! `[(x_i, x_{i+1}), (y_j, y_{j+1})]`; [`solve::solve_candidates`] (or
//! [`complete::certify_candidates`] with `problem.interval_system`) proves a
//! unique root near each cell by Krawczyk with ε-inflation, rejects empty
//! cells, merges cells of the same root soundly and reports the rest as
//! undecided. A raster can miss roots, so such a report is never `complete`.

pub mod complete;
pub mod eliminate;
pub mod krawczyk;
pub mod poly2;
pub mod radii;
pub mod raster;
pub mod solve;
pub mod system;
