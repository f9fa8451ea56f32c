//! Complete interval branch-and-prune solver for a 2×2 polynomial system on a
//! rational box, and the certification of candidate boxes (raster cells).
//!
//! # Algorithm
//!
//! The exact domain `D = [x_lo, x_hi] × [y_lo, y_hi]` (rational ends) is
//! enclosed by the f64 box `D'` (ends rounded outward). A work list starts with
//! `D'`; each box `X` taken from it is, in this order,
//!
//! 0. **contracted** with the equations linear in one variable
//!    ([`System2::contract_linear`]: the removed part provably holds no zero),
//!    or excluded when nothing is left;
//! 1. **excluded** if `0 ∉ p(X)` or `0 ∉ q(X)` (centred Taylor-form
//!    enclosure, [`System2::enclose`]);
//! 2. **excluded** if a Krawczyk step gives `K(X) ∩ X = ∅`, or **settled** if
//!    (possibly after contractions `X ← K(X) ∩ X`) `K(X) ⊂ int X`: one zero in
//!    `X`, recorded with its region and a contracted enclosure;
//! 3. if `X` is small (relative width below `inflate_below`), **settled** by
//!    Krawczyk with ε-inflation on a region `R ⊇ X` (one zero in `R`, recorded),
//!    or excluded if the inflated box provably holds no zero;
//! 4. reported **undecided** if its relative width is below `min_width`, or if
//!    the box budget is exhausted (every box left in the work list is reported);
//! 5. otherwise the Krawczyk-contracted box `K(X) ∩ X` (which holds every
//!    zero of `X`) is bisected (at the f64 midpoint, along the relatively
//!    wider side).
//!
//! # Soundness
//!
//! The boxes taken from the work list cover the zeros of `D'` (bisection
//! splits a box into two closed halves whose union is the box; contractions —
//! by linear equations or `X ← K(X) ∩ X` — drop only points that are not
//! zeros), so every zero in `D` lies in some processed box, and that box was
//! not excluded (exclusion is proof of no zero: steps 1–3 are Krawczyk's
//! theorem or an enclosure not containing 0): it was settled or reported
//! undecided. A settled box `X` holds at most one zero, namely the unique zero
//! of its recorded region `R ⊇ X` (for step 2 after contractions: all zeros of
//! `X` lie in the contracted box, which holds exactly one); so every zero of `D` outside the undecided boxes is
//! the recorded zero of some settled box — *no zero is lost*, also when it lies
//! on the common edge of two boxes: a zero on the boundary of `X` can never be
//! proven by `K(X) ⊂ int X` (the zero lies in `K(X)`), and such boxes are then
//! settled by step 3, whose region contains `X` and its boundary.
//!
//! The same zero may be recorded by several boxes (neighbours, inflated
//! regions). The records are merged soundly: two records whose contracted
//! enclosures are disjoint are distinct zeros; two whose enclosures intersect
//! are merged only if a Krawczyk test on (an inflation of) their hull proves a
//! unique zero there (then both are that zero); otherwise both are reported as
//! an undecided box. So the merged records are pairwise distinct proven zeros —
//! *nothing is double counted*. Finally a record counts as a zero of `D` when
//! its contracted enclosure lies inside `D` (compared exactly with the rational
//! ends), is dropped when disjoint from `D`, and is reported undecided when it
//! straddles the boundary of `D`.
//!
//! `complete = true` only if no undecided box remains: then the reported roots
//! are exactly the zeros in `D`, each with an enclosure holding exactly one.

use super::krawczyk::{hull, inflate, intersects, iv, IBox, KOutcome, KStep, System2};
use crate::scalar::{interval_from_rational, rational_from_f64, Interval, Rational};

/// Tuning knobs and the budget of [`solve`].
#[derive(Clone, Copy, Debug)]
pub struct SolveOptions {
    /// Boxes processed at most; beyond it the remaining boxes are reported
    /// undecided (never an endless loop).
    pub max_boxes: usize,
    /// Relative width (per side, relative to the domain) below which a box
    /// that is neither excluded nor settled is reported undecided.
    pub min_width: f64,
    /// Relative width below which a box that Krawczyk cannot settle on its own
    /// is tried with ε-inflation.
    pub inflate_below: f64,
    /// Krawczyk steps per test.
    pub max_iter: usize,
}

impl Default for SolveOptions {
    fn default() -> Self {
        SolveOptions {
            max_boxes: 200_000,
            min_width: 1e-10,
            inflate_below: 1.0 / 64.0,
            max_iter: 12,
        }
    }
}

/// A proven zero: exactly one zero of the system lies in `region`, and it
/// lies in the (much smaller) `enclosure`.
#[derive(Clone, Copy, Debug)]
pub struct CertifiedRoot {
    /// Contracted enclosure of the zero.
    pub enclosure: IBox,
    /// The box in which the zero was proven unique.
    pub region: IBox,
}

/// Why a box is undecided.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum UndecidedReason {
    /// Too small to bisect further; `near_double_root` when `det J` encloses 0
    /// there (a tangential / multiple zero is likely).
    MinWidth {
        /// True when `det J` encloses 0 on the box (a tangential / multiple zero is likely).
        near_double_root: bool,
    },
    /// The box budget ran out before the box was processed.
    Budget,
    /// A proven zero whose enclosure straddles the domain boundary.
    DomainBoundary,
    /// Two proven zeros whose enclosures overlap and could not be merged.
    Ambiguous,
    /// A candidate box neither proven nor rejected ([`certify_candidates`]).
    Unresolved,
}

/// A box that may hold zeros that are not reported as roots.
#[derive(Clone, Copy, Debug)]
pub struct UndecidedBox {
    /// The box `[x] × [y]` (`x = m`, `y = a2` for the tangency system).
    pub bx: IBox,
    /// Why it is undecided.
    pub reason: UndecidedReason,
}

/// The result of [`solve`].
#[derive(Clone, Debug, Default)]
pub struct Solution {
    /// Pairwise distinct proven zeros inside the domain.
    pub roots: Vec<CertifiedRoot>,
    /// Boxes that may hold further zeros.
    pub undecided: Vec<UndecidedBox>,
    /// True iff `undecided` is empty: `roots` are then all zeros in the domain.
    pub complete: bool,
    /// Boxes processed.
    pub boxes: usize,
    /// Krawczyk steps performed.
    pub krawczyk_iterations: usize,
}

/// An exact rational box `[x_lo, x_hi] × [y_lo, y_hi]` (the search domain).
#[derive(Clone, Debug, PartialEq)]
pub struct RationalBox {
    /// `[x_lo, x_hi]`.
    pub x: (Rational, Rational),
    /// `[y_lo, y_hi]`.
    pub y: (Rational, Rational),
}

impl RationalBox {
    /// The tightest f64 box containing it.
    pub fn outward(&self) -> IBox {
        let e = |(a, b): &(Rational, Rational)| {
            interval_from_rational(a).convex_hull(interval_from_rational(b))
        };
        [e(&self.x), e(&self.y)]
    }
    /// Whether the enclosure lies inside (`Some(true)`), outside
    /// (`Some(false)`) or straddles the boundary (`None`), decided exactly.
    pub fn contains_box(&self, b: &IBox) -> Option<bool> {
        let q = |v: f64| rational_from_f64(v);
        let side = |i: Interval, (lo, hi): &(Rational, Rational)| -> Option<bool> {
            let (l, h) = (q(i.inf())?, q(i.sup())?);
            if &l >= lo && &h <= hi {
                Some(true)
            } else if &h < lo || &l > hi {
                Some(false)
            } else {
                None
            }
        };
        match (side(b[0], &self.x), side(b[1], &self.y)) {
            (Some(false), _) | (_, Some(false)) => Some(false),
            (Some(true), Some(true)) => Some(true),
            _ => None,
        }
    }
}

fn rel_width(b: &IBox, dom: &IBox) -> f64 {
    let r = |i: usize| {
        let d = dom[i].wid();
        if d > 0.0 {
            b[i].wid() / d
        } else {
            0.0
        }
    };
    r(0).max(r(1))
}

fn bisect(b: &IBox, dom: &IBox) -> (IBox, IBox) {
    let r = |i: usize| b[i].wid() / dom[i].wid().max(f64::MIN_POSITIVE);
    let i = if r(0) >= r(1) { 0 } else { 1 };
    let m = b[i].mid();
    let (mut lo, mut hi) = (*b, *b);
    lo[i] = iv(b[i].inf(), m);
    hi[i] = iv(m, b[i].sup());
    (lo, hi)
}

/// Solves `p = q = 0` on the rational box `domain` (see the module docs for
/// the algorithm and the soundness argument).
///
/// # Examples
/// ```
/// use lncert::tangency::{solve, RationalBox, SolveOptions};
/// use lncert::tangency::System2;
/// use lncert::tangency::parse_poly2;
/// use lncert::scalar::frac;
/// let s = System2::new(&parse_poly2("x^2 + y^2 - 1").unwrap(), &parse_poly2("y - x").unwrap());
/// let d = RationalBox { x: (frac(-2, 1), frac(2, 1)), y: (frac(-2, 1), frac(2, 1)) };
/// let sol = solve(&s, &d, &SolveOptions::default());
/// assert!(sol.complete);
/// assert_eq!(sol.roots.len(), 2);
/// ```
pub fn solve(sys: &System2, domain: &RationalBox, opts: &SolveOptions) -> Solution {
    let dom = domain.outward();
    let mut sol = Solution::default();
    let mut records: Vec<CertifiedRoot> = Vec::new();
    let mut work = vec![dom];
    while let Some(b) = work.pop() {
        if sol.boxes >= opts.max_boxes {
            sol.undecided.push(UndecidedBox {
                bx: b,
                reason: UndecidedReason::Budget,
            });
            sol.undecided.extend(work.drain(..).map(|bx| UndecidedBox {
                bx,
                reason: UndecidedReason::Budget,
            }));
            break;
        }
        sol.boxes += 1;
        // All zeros of b lie in the contracted box (equations linear in one variable).
        let Some(b) = sys.contract_linear(&b) else {
            continue;
        };
        let Some(e) = sys.enclose_or_exclude(&b) else {
            continue;
        };
        sol.krawczyk_iterations += 1;
        match sys.step(&b, &e) {
            KStep::NoRoot => continue,
            KStep::Unique(k) => {
                // k ⊂ int b holds the unique zero of b; contract it.
                let (tight, n) = sys.contract(k, opts.max_iter);
                sol.krawczyk_iterations += n;
                records.push(CertifiedRoot {
                    enclosure: tight,
                    region: b,
                });
                continue;
            }
            KStep::Contracted(c) => {
                let rw = rel_width(&b, &dom);
                // Every zero of b lies in `keep` (Krawczyk contractions).
                let mut keep = c;
                if rel_width(&c, &dom) < 0.5 * rw {
                    // Good contraction: all zeros of b lie in c, iterate there.
                    let (o, n) = sys.krawczyk(&c, opts.max_iter);
                    sol.krawczyk_iterations += n;
                    match o {
                        KOutcome::NoRoot => continue,
                        KOutcome::Unique { tight, .. } => {
                            records.push(CertifiedRoot {
                                enclosure: tight,
                                region: b,
                            });
                            continue;
                        }
                        KOutcome::Undecided { last } => keep = last,
                    }
                }
                if rw < opts.inflate_below {
                    let (o, n) = sys.inflate_and_prove(&b, opts.max_iter);
                    sol.krawczyk_iterations += n;
                    match o {
                        KOutcome::NoRoot => continue,
                        KOutcome::Unique { region, tight } => {
                            records.push(CertifiedRoot {
                                enclosure: tight,
                                region,
                            });
                            continue;
                        }
                        KOutcome::Undecided { .. } => {}
                    }
                }
                if rw < opts.min_width {
                    sol.undecided.push(UndecidedBox {
                        bx: b,
                        reason: UndecidedReason::MinWidth {
                            near_double_root: e.det_contains_zero(),
                        },
                    });
                    continue;
                }
                let (lo, hi) = bisect(&keep, &dom);
                work.push(hi);
                work.push(lo);
            }
        }
    }
    let (merged, ambiguous, n) = merge_records(sys, records, opts.max_iter);
    sol.krawczyk_iterations += n;
    sol.undecided.extend(ambiguous);
    for r in merged {
        match domain.contains_box(&r.enclosure) {
            Some(true) => sol.roots.push(r),
            Some(false) => {}
            None => sol.undecided.push(UndecidedBox {
                bx: r.enclosure,
                reason: UndecidedReason::DomainBoundary,
            }),
        }
    }
    sol.roots
        .sort_by(|a, b| a.enclosure[0].inf().total_cmp(&b.enclosure[0].inf()));
    sol.complete = sol.undecided.is_empty();
    sol
}

/// Merges records of the same zero (see the module docs): returns the
/// pairwise distinct zeros, the undecided boxes of unmergeable overlaps and
/// the Krawczyk steps used.
fn merge_records(
    sys: &System2,
    records: Vec<CertifiedRoot>,
    max_iter: usize,
) -> (Vec<CertifiedRoot>, Vec<UndecidedBox>, usize) {
    let mut out: Vec<CertifiedRoot> = Vec::new();
    let mut bad: Vec<UndecidedBox> = Vec::new();
    let mut iters = 0;
    'next: for r in records {
        for i in 0..out.len() {
            if !intersects(&out[i].enclosure, &r.enclosure) {
                continue;
            }
            // A zero enclosed in the other record's region is that region's
            // unique zero.
            let within = |a: &IBox, b: &IBox| a[0].subset(b[0]) && a[1].subset(b[1]);
            if within(&r.enclosure, &out[i].region) {
                continue 'next;
            }
            if within(&out[i].enclosure, &r.region) {
                out[i] = r;
                continue 'next;
            }
            let h = hull(&out[i].enclosure, &r.enclosure);
            let (o, n) = sys.inflate_and_prove(&h, max_iter);
            iters += n;
            if let KOutcome::Unique { region, tight } = o {
                // region ⊇ h holds exactly one zero: both records are that zero.
                out[i] = CertifiedRoot {
                    enclosure: tight,
                    region,
                };
                continue 'next;
            }
            bad.push(UndecidedBox {
                bx: h,
                reason: UndecidedReason::Ambiguous,
            });
            out.remove(i);
            continue 'next;
        }
        out.push(r);
    }
    // Final guard: the distinctness argument needs pairwise disjoint enclosures.
    let n = out.len();
    let mut clash = vec![false; n];
    for i in 0..n {
        for j in i + 1..n {
            if intersects(&out[i].enclosure, &out[j].enclosure) {
                clash[i] = true;
                clash[j] = true;
            }
        }
    }
    let mut keep = Vec::with_capacity(n);
    for (r, c) in out.into_iter().zip(clash) {
        if c {
            bad.push(UndecidedBox {
                bx: r.enclosure,
                reason: UndecidedReason::Ambiguous,
            });
        } else {
            keep.push(r);
        }
    }
    (keep, bad, iters)
}

/// The result of [`certify_candidates`].
#[derive(Clone, Debug, Default)]
pub struct CandidateResult {
    /// Pairwise distinct proven zeros (merged soundly).
    pub roots: Vec<CertifiedRoot>,
    /// Indices of input boxes proven to hold no zero (in an inflation of the box).
    pub rejected: Vec<usize>,
    /// Input boxes neither proven nor rejected, and unmergeable overlaps.
    pub undecided: Vec<UndecidedBox>,
    /// Krawczyk steps performed.
    pub krawczyk_iterations: usize,
}

/// Certifies candidate boxes (e.g. raster cells, in `(x, y) = (m, a2)`): each
/// box is tested by Krawczyk with ε-inflation ([`System2::inflate_and_prove`],
/// starting from the box widened by 10 %); a proof gives a zero unique in a
/// region containing the box, a rejection proves no zero in the inflated box.
/// Proven zeros are merged as in [`solve`], so `roots` are pairwise distinct.
/// Candidate certification is *not* complete: zeros missed by the raster are
/// not found here (use [`solve`] for completeness).
///
/// # Examples
/// ```
/// use lncert::tangency::certify_candidates;
/// use lncert::tangency::System2;
/// use lncert::tangency::parse_poly2;
/// let s = System2::new(&parse_poly2("x^2 + y^2 - 1").unwrap(), &parse_poly2("y - x").unwrap());
/// let h = 0.5f64.sqrt();
/// let cells = [[(h - 0.01, h), (h, h + 0.01)], [(h - 0.01, h), (h - 0.01, h)], [(0.0, 0.1), (0.0, 0.1)]];
/// let r = certify_candidates(&s, &cells);
/// assert_eq!(r.roots.len(), 1); // both cells touch the same root
/// assert_eq!(r.rejected, vec![2]);
/// ```
pub fn certify_candidates(sys: &System2, boxes: &[[(f64, f64); 2]]) -> CandidateResult {
    let mut res = CandidateResult::default();
    let mut records = Vec::new();
    for (idx, b) in boxes.iter().enumerate() {
        let ok = b
            .iter()
            .all(|(l, h)| l.is_finite() && h.is_finite() && l <= h);
        let bx = super::krawczyk::ibox(b);
        if !ok {
            res.undecided.push(UndecidedBox {
                bx,
                reason: UndecidedReason::Unresolved,
            });
            continue;
        }
        let (o, n) = sys.inflate_and_prove(&bx, 16);
        res.krawczyk_iterations += n;
        match o {
            KOutcome::Unique { region, tight } => records.push(CertifiedRoot {
                enclosure: tight,
                region,
            }),
            KOutcome::NoRoot => res.rejected.push(idx),
            KOutcome::Undecided { .. } => res.undecided.push(UndecidedBox {
                bx: inflate(&bx, 0.1),
                reason: UndecidedReason::Unresolved,
            }),
        }
    }
    let (merged, bad, n) = merge_records(sys, records, 16);
    res.krawczyk_iterations += n;
    res.roots = merged;
    res.undecided.extend(bad);
    res
}
