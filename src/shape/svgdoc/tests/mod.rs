//! Tests of SVG documents: the helpers shared by the topics.

mod elements;
mod transforms;
mod walk;

use super::*;
use crate::test_util::q;

fn pts(b: &Bezier<Rational>) -> Vec<(Rational, Rational)> {
    b.points()
        .iter()
        .map(|p| (p.x.clone(), p.y.clone()))
        .collect()
}
