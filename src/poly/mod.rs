//! Univariate polynomials (power and Bernstein form), exact root isolation over
//! Q (Sturm sequences), root enclosure with intervals, and multivariate
//! polynomials / rational functions over Q for machine-checked identities.

mod univariate;

pub(crate) use univariate::ratio_scalar;
pub use univariate::{binomial, binomial_big, Poly};
mod enclose;
mod multi;
mod roots;
pub(crate) mod scaled;
pub use enclose::{
    certify_no_root, enclose_roots, isolate_simple_roots, isolate_simple_roots_bernstein,
    RootEnclosure,
};
pub use multi::{identity_holds, poly_in, univariate_coeffs, MPoly, RatFunc};
pub(crate) use roots::div_rem;
pub use roots::{
    count_distinct_roots, has_common_root_in, has_root_in, isolate_roots, isolate_roots_all,
    poly_gcd, refine_root, root_bound, square_free, sturm_sequence, RealRoot, RootCount, Span,
};
