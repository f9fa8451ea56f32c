//! Seed 003 §4: LN curves tangent to a circle.
//!
//! | step | entry points |
//! |---|---|
//! | the problem end to end: domain, default `a2` window, per-root curve, nonsingularity, side | [`TangencyProblem`], [`solve_complete`] (complete and proven), [`solve_exact`] (the exact oracle), [`solve_candidates`] (from raster cells), [`TangencyReport`], [`RootReport`], [`Side`] |
//! | eq. (6), (7) in the unknowns `(m, a2)`, degrees 10 and 6, Bézout bound 60 | [`TangencySystem`], [`curve_polys`], [`SolutionLine`] |
//! | dense bivariate polynomials over any scalar, exact expression parser | [`Poly2`], [`parse_poly2`], [`Poly2ParseError`] |
//! | the complete branch-and-prune solver (soundness argument in [`solve`]'s docs), candidate certification | [`solve`], [`SolveOptions`], [`Solution`], [`CertifiedRoot`], [`UndecidedBox`], [`UndecidedReason`], [`certify_candidates`] |
//! | interval Krawczyk operator, ε-inflation, centred-form enclosures | [`System2`], [`IPoly2`], [`IBox`], [`ibox`], [`KOutcome`], [`EnclosureForm`] |
//! | exact oracle: eq. (7) is linear in `a2`, elimination to one univariate polynomial, Sturm isolation | [`exact_solutions`], [`eliminant`], [`eliminant_prime_part`], [`OracleSolution`], [`OracleRoot`] |
//! | the paper's raster: signs of both equations on an N×N grid, CPU (rayon) and GPU (wgpu) backends | the module [`raster`] |
//! | beyond the paper: certified inner/outer enclosures of the valid signed radii for a fixed centre | [`valid_radii`], [`RadiiSet`], [`RadiusComponent`] |
//!
//! Coordinates: `x = m` (the parameter of the tangency point), `y = a2` (the
//! free coefficient of the quartic), as in the raster module.
//!
//! # Raster candidates (seed 003 §4.2)
//!
//! The raster backends sample `p = eq. (6)` and `q = eq. (7)` on a grid over the
//! domain `[0, u] × [a2_lo, a2_hi]` of a [`TangencyProblem`]: the f64
//! coefficients are [`Poly2::coeffs_f64`] of `problem.system.eq6` and
//! `.eq7` (layout `coeffs[i*(deg_y+1)+j]`, `x = m`, `y = a2`). Each candidate
//! cell `[x_i, x_{i+1}] × [y_j, y_{j+1}]` becomes the box
//! `[(x_i, x_{i+1}), (y_j, y_{j+1})]`; [`solve_candidates`] (or
//! [`certify_candidates`] with `problem.interval_system`) proves a
//! unique root near each cell by Krawczyk with ε-inflation, rejects empty
//! cells, merges cells of the same root soundly and reports the rest as
//! undecided. A raster can miss roots, so such a report is never `complete`.

pub(crate) mod complete;
pub(crate) mod eliminate;
pub(crate) mod krawczyk;
pub(crate) mod poly2;
pub(crate) mod radii;
pub mod raster;
pub(crate) mod solve;
pub(crate) mod system;

pub use complete::{
    certify_candidates, solve, CandidateResult, CertifiedRoot, RationalBox, Solution, SolveOptions,
    UndecidedBox, UndecidedReason,
};
pub use eliminate::{eliminant, eliminant_prime_part, exact_solutions, OracleRoot, OracleSolution};
pub use krawczyk::{ibox, BoxEnclosure, EnclosureForm, IBox, IPoly2, KOutcome, KStep, System2};
pub use poly2::{parse_poly2, Poly2, Poly2ParseError, MAX_DEGREE, MAX_INPUT, MAX_NESTING};
pub use radii::{valid_radii, RadiiSet, RadiusComponent};
pub use solve::{
    default_a2_window, nonsingular_a2_ends, solve_candidates, solve_complete, solve_exact,
    A2WindowSource, RootReport, Side, TangencyProblem, TangencyReport,
};
pub use system::{curve_polys, SolutionLine, TangencyError, TangencySystem};
