//! The stroke verifier on hostile certificates (`lncert::gen::hostile`):
//! documents built so that a verifier whose work multiplies two sizes runs
//! for minutes or takes gigabytes. Each is a true claim: it must verify, and
//! the verifier's work is bounded by its size (the budget of
//! `lncert::certify::verify::WORK_PER_BYTE`), or it is refused as too costly.
use lncert::gen::hostile;

/// 2 000 rectangles stacked in y: 8 000 outline parts, every pair
/// overlapping in x (a sweep in x alone lists 32 million candidate pairs).
#[test]
fn stacked_rectangles_verify() {
    let doc = hostile::stacked_rectangles(2000);
    let v = lncert::verify(&doc).unwrap();
    assert!(v.a.contains("2000 closed contour(s)"), "{}", v.a);
    assert!(
        v.a.contains("simple and disjoint, 2000 counter-clockwise"),
        "{}",
        v.a
    );
}

/// 3 000 input pieces far from a 3 000-part outline: the index tests each
/// witness against nothing.
#[test]
fn far_pieces_verify() {
    let doc = hostile::far_pieces(3000);
    let v = lncert::verify(&doc).unwrap();
    assert!(v.b.contains("3000 Bézier piece(s)"), "{}", v.b);
}

/// Witnesses that almost touch every copy of a wiggly piece: claim (a)'s
/// 40 parts × 20 copies of Bernstein exclusions pass within the document's
/// budget; the refusal comes from claim (b)'s coarse boxes on the singular
/// offset (claim (a) is reported first, so it passed), not from the budget.
#[test]
fn wiggly_witnesses_pass_claim_a_within_the_budget() {
    let doc = hostile::wiggly_witnesses(40, 20, 16);
    let e = lncert::verify(&doc).unwrap_err();
    assert!(e.at.starts_with("boundary"), "{e}");
    assert!(!e.reason.contains("too costly"), "{e}");
}

/// The same attack scaled in the parts (2 000 parts × 20 copies of degree
/// 20, 0.9 MB): every witness is within reach of every copy, so the index
/// prunes nothing and the work grows like parts × copies — past the
/// document's budget, where the verifier stops and refuses the certificate
/// as too costly to check, at the part where the meter ran out (before the
/// budget, `lncert verify` ran for minutes on documents like this).
#[test]
fn wiggly_witnesses_beyond_the_budget_are_refused_as_too_costly() {
    let doc = hostile::wiggly_witnesses(2000, 20, 20);
    let e = lncert::verify(&doc).unwrap_err();
    assert!(e.reason.contains("too costly to check"), "{e}");
    assert!(e.at.starts_with("cover["), "{e}");
}
