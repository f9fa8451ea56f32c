//! Point pieces: Bézier pieces whose control points all coincide (a
//! zero-length `L`/`h`/`v`, `<line>` with equal ends, a cubic with four equal
//! points). They have no tangent, so no offset; what they draw is decided
//! exactly here, from the pieces around them:
//!
//! - a point piece that touches the rest of its path — the piece before it
//!   ends there, or the piece after it starts there — draws nothing that
//!   the rest does not: with round caps and joins the pen's disk at that
//!   point is already in the stroke of the touching piece (its end), and with
//!   butt caps SVG draws nothing for it. It is removed.
//! - an isolated one (a zero-length subpath) is a **dot**: with round caps
//!   SVG strokes it as the pen's disk about the point (SVG 2, "zero-length
//!   subpaths"), with butt caps it draws nothing. It is returned as a point,
//!   never dropped silently: the caller strokes it or says why not.

use crate::curve::{Bezier, V2};
use crate::scalar::Rational;
use crate::shape::InputApprox;

/// Whether every control point of `b` is the same point.
pub fn is_point_piece(b: &Bezier<Rational>) -> bool {
    let p = b.points();
    p.iter().all(|q| *q == p[0])
}

/// Removes the point pieces of `pieces` (see the module): returns the other
/// pieces, in order, and the points of the isolated ones (the dots), in
/// order. The indices of `approx` are moved with the pieces; a point piece
/// inside an element stated exactly (`approx`'s exact ranges) is kept, as
/// that element's exact form counts it.
///
/// # Examples
/// ```
/// use lncert::shape::{parse_svg_path, split_dots, InputApprox};
/// let q = |x: i64| lncert::Rational::from_integer(x.into());
/// // a line, a zero-length segment at its end, and a dot elsewhere
/// let pieces = parse_svg_path("M 0 0 L 4 0 L 4 0 M 9 9 L 9 9").unwrap();
/// let (rest, dots) = split_dots(pieces, &mut InputApprox::default());
/// assert_eq!(rest.len(), 1);
/// assert_eq!(dots.len(), 1);
/// assert_eq!((dots[0].x.clone(), dots[0].y.clone()), (q(9), q(9)));
/// ```
pub fn split_dots(
    pieces: Vec<Bezier<Rational>>,
    approx: &mut InputApprox,
) -> (Vec<Bezier<Rational>>, Vec<V2<Rational>>) {
    let n = pieces.len();
    let protected = |i: usize| {
        approx.elements.iter().any(|e| {
            e.exact
                .iter()
                .chain(e.near.iter().map(|n| &n.element))
                .any(|x| (x.first..x.first + x.count).contains(&i))
        })
    };
    let point: Vec<bool> = pieces.iter().map(is_point_piece).collect();
    if !point.iter().any(|p| *p) {
        return (pieces, Vec::new());
    }
    let removed: Vec<bool> = (0..n).map(|i| point[i] && !protected(i)).collect();
    let mut dots = Vec::new();
    for i in (0..n).filter(|&i| removed[i]) {
        let p = &pieces[i].points()[0];
        // the nearest pieces before and after that are not point pieces
        let before = (0..i).rev().find(|&j| !point[j]);
        let after = (i + 1..n).find(|&j| !point[j]);
        // consecutive point pieces at one point: one dot (the first of the run)
        let run_start = i == 0 || !(point[i - 1] && pieces[i - 1].points()[0] == *p);
        let touches = before.is_some_and(|j| pieces[j].points().last() == Some(p))
            || after.is_some_and(|j| pieces[j].points()[0] == *p);
        if !touches && run_start {
            dots.push(p.clone());
        }
    }
    // the approximated elements' piece indices, moved past the removed pieces
    let shift = |i: usize| i - removed[..i.min(n)].iter().filter(|r| **r).count();
    for e in &mut approx.elements {
        for x in e
            .exact
            .iter_mut()
            .chain(e.near.iter_mut().map(|n| &mut n.element))
        {
            x.first = shift(x.first);
        }
    }
    let rest = pieces
        .into_iter()
        .zip(&removed)
        .filter(|(_, r)| !**r)
        .map(|(b, _)| b)
        .collect();
    (rest, dots)
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::shape::parse_svg_path;

    fn q(x: i64) -> Rational {
        Rational::from_integer(x.into())
    }

    #[test]
    fn isolated_point_pieces_are_dots_and_touching_ones_vanish() {
        // (path data, pieces kept, the dots)
        type Case<'a> = (&'a str, usize, &'a [(i64, i64)]);
        let cases: [Case; 8] = [
            // a closed subpath of one point; closing a drawn subpath adds none
            ("M 0 0 L 1 0 M 3 3 z", 1, &[(3, 3)]),
            ("M 0 0 L 1 0 L 0 0 z", 2, &[]),
            ("M 0 0 L 4 0", 1, &[]),
            ("M 1 1 L 1 1", 0, &[(1, 1)]),
            // zero-length segments inside, at the start and at the end of a path
            ("M 0 0 L 0 0 L 4 0 L 4 0 L 4 3", 2, &[]),
            // a subpath that starts where the previous ends: covered
            ("M 0 0 L 4 0 M 4 0 L 4 0", 1, &[]),
            // two dots, one of them drawn twice; a degenerate cubic
            (
                "M 7 7 L 7 7 L 7 7 M 0 0 L 1 0 M 5 5 C 5 5 5 5 5 5",
                1,
                &[(7, 7), (5, 5)],
            ),
            ("M 0 0 L 1 0 M 3 3 h 0 M 1 0 L 2 0", 2, &[(3, 3)]),
        ];
        for (d, kept, want) in cases {
            let (rest, dots) = split_dots(parse_svg_path(d).unwrap(), &mut InputApprox::default());
            assert_eq!(rest.len(), kept, "{d}");
            assert!(rest.iter().all(|b| !is_point_piece(b)), "{d}");
            let got: Vec<(Rational, Rational)> =
                dots.iter().map(|p| (p.x.clone(), p.y.clone())).collect();
            let want: Vec<(Rational, Rational)> =
                want.iter().map(|(x, y)| (q(*x), q(*y))).collect();
            assert_eq!(got, want, "{d}");
        }
    }

    #[test]
    fn exact_arc_indices_follow_the_removed_pieces() {
        let (pieces, mut approx) =
            crate::shape::parse_svg_path_reported("M 9 9 L 9 9 M 0 0 L 1 0 A 1 1 0 0 1 3 0")
                .unwrap();
        let first = approx.elements[0].exact.as_ref().unwrap().first;
        let arc0 = pieces[first].clone();
        let (rest, dots) = split_dots(pieces, &mut approx);
        assert_eq!(dots.len(), 1);
        let x = approx.elements[0].exact.as_ref().unwrap();
        assert_eq!(x.first, first - 1);
        assert_eq!(rest[x.first], arc0);
    }
}
