//! Tests of SVG documents: the helpers shared by the topics.

mod elements;
mod transforms;
mod walk;

use super::*;
use crate::scalar::parse_rational;

fn q(s: &str) -> Rational {
    parse_rational(s).unwrap()
}

fn pts(b: &Bezier<Rational>) -> Vec<(Rational, Rational)> {
    b.points()
        .iter()
        .map(|p| (p.x.clone(), p.y.clone()))
        .collect()
}
