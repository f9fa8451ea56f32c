//! Univariate polynomials (power and Bernstein form), exact root isolation over
//! Q (Sturm sequences), root enclosure with intervals, and multivariate
//! polynomials / rational functions over Q for machine-checked identities.

mod univariate;

pub use univariate::{binomial, Poly};
mod enclose;
mod multi;
mod roots;
