//! A static box index (a bounding-volume hierarchy over axis-aligned boxes)
//! for the verifier's spatial searches: which input pieces are within reach
//! of a disk (claim (a) of a stroke certificate), which outline parts' boxes
//! meet (claim (c)).
//!
//! The index only *orders and prunes* work. Soundness rests on one fact: a
//! node's box holds the boxes of everything below it (unions of float boxes,
//! computed with `min`/`max`, which are exact), so a predicate that proves a
//! node's box out of reach proves every item below it out of reach. Items
//! with unbounded or undefined boxes are given the whole plane and are never
//! pruned.

/// A box `[lo, hi]` in floats.
pub(crate) type FBox = ([f64; 2], [f64; 2]);

const LEAF: usize = 8;

struct Node {
    lo: [f64; 2],
    hi: [f64; 2],
    /// The items `order[start..end]` below this node.
    start: u32,
    end: u32,
    /// The two children (`left`, `left + 1`); 0 for a leaf.
    left: u32,
}

/// The index over a list of boxes (item `i` is `boxes[i]`).
pub(crate) struct BoxIndex {
    nodes: Vec<Node>,
    order: Vec<u32>,
    boxes: Vec<FBox>,
}

fn whole() -> FBox {
    ([f64::NEG_INFINITY; 2], [f64::INFINITY; 2])
}

fn valid(b: &FBox) -> bool {
    (0..2).all(|i| !b.0[i].is_nan() && !b.1[i].is_nan() && b.0[i] <= b.1[i])
}

/// A box's centre coordinate, finite for sorting (0 for an unbounded side).
fn centre(b: &FBox, axis: usize) -> f64 {
    let c = 0.5 * b.0[axis] + 0.5 * b.1[axis];
    if c.is_finite() {
        c
    } else {
        0.0
    }
}

impl BoxIndex {
    /// Builds the index (`O(n log n)`); a box that is not a valid box
    /// (`NaN`, `lo > hi`) is replaced by the whole plane.
    pub(crate) fn new(boxes: Vec<FBox>) -> BoxIndex {
        let boxes: Vec<FBox> = boxes
            .into_iter()
            .map(|b| if valid(&b) { b } else { whole() })
            .collect();
        let mut order: Vec<u32> = (0..boxes.len() as u32).collect();
        let mut nodes = Vec::with_capacity(2 * boxes.len() / LEAF + 1);
        if !boxes.is_empty() {
            nodes.push(Node {
                lo: [0.0; 2],
                hi: [0.0; 2],
                start: 0,
                end: boxes.len() as u32,
                left: 0,
            });
            // breadth-first: split each node on its items' longer centre axis
            let mut k = 0;
            while k < nodes.len() {
                let (s, e) = (nodes[k].start as usize, nodes[k].end as usize);
                let mut lo = [f64::INFINITY; 2];
                let mut hi = [f64::NEG_INFINITY; 2];
                let mut clo = [f64::INFINITY; 2];
                let mut chi = [f64::NEG_INFINITY; 2];
                for &i in &order[s..e] {
                    let b = &boxes[i as usize];
                    for a in 0..2 {
                        lo[a] = lo[a].min(b.0[a]);
                        hi[a] = hi[a].max(b.1[a]);
                        let c = centre(b, a);
                        clo[a] = clo[a].min(c);
                        chi[a] = chi[a].max(c);
                    }
                }
                nodes[k].lo = lo;
                nodes[k].hi = hi;
                if e - s > LEAF {
                    let axis = usize::from(chi[1] - clo[1] > chi[0] - clo[0]);
                    let m = s + (e - s) / 2;
                    order[s..e].select_nth_unstable_by(m - s, |&a, &b| {
                        centre(&boxes[a as usize], axis)
                            .total_cmp(&centre(&boxes[b as usize], axis))
                    });
                    nodes[k].left = nodes.len() as u32;
                    for (a, b) in [(s, m), (m, e)] {
                        nodes.push(Node {
                            lo: [0.0; 2],
                            hi: [0.0; 2],
                            start: a as u32,
                            end: b as u32,
                            left: 0,
                        });
                    }
                }
                k += 1;
            }
        }
        BoxIndex {
            nodes,
            order,
            boxes,
        }
    }

    /// Calls `f` on every item whose box `reach` accepts, in no particular
    /// order, visiting only nodes whose box `reach` accepts (it must accept a
    /// box whenever it accepts one inside it). Returns the number of nodes
    /// visited (the work, for the budget), or `f`'s first error.
    pub(crate) fn query<E>(
        &self,
        reach: impl Fn(&[f64; 2], &[f64; 2]) -> bool,
        mut f: impl FnMut(usize) -> Result<(), E>,
    ) -> Result<u64, E> {
        if self.nodes.is_empty() {
            return Ok(0);
        }
        let mut visited = 0u64;
        let mut stack = vec![0u32];
        while let Some(k) = stack.pop() {
            visited += 1;
            let n = &self.nodes[k as usize];
            if !reach(&n.lo, &n.hi) {
                continue;
            }
            if n.left == 0 {
                for &i in &self.order[n.start as usize..n.end as usize] {
                    let b = &self.boxes[i as usize];
                    if reach(&b.0, &b.1) {
                        f(i as usize)?;
                    }
                }
            } else {
                stack.push(n.left + 1);
                stack.push(n.left);
            }
        }
        Ok(visited)
    }
}

/// Two closed boxes meet.
pub(crate) fn meet(a: &FBox, lo: &[f64; 2], hi: &[f64; 2]) -> bool {
    a.0[0] <= hi[0] && lo[0] <= a.1[0] && a.0[1] <= hi[1] && lo[1] <= a.1[1]
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Every query finds exactly the items a direct scan finds.
    #[test]
    fn queries_find_what_a_scan_finds() {
        let mut seed = 12345u64;
        let mut rnd = || {
            seed = seed
                .wrapping_mul(6364136223846793005)
                .wrapping_add(1442695040888963407);
            (seed >> 11) as f64 / (1u64 << 53) as f64
        };
        let mut boxes: Vec<FBox> = (0..1000)
            .map(|_| {
                let (x, y, w, h) = (rnd() * 100.0, rnd() * 100.0, rnd() * 5.0, rnd() * 5.0);
                ([x, y], [x + w, y + h])
            })
            .collect();
        // an unbounded box, and an undefined one (the whole plane: never pruned)
        boxes.push(([f64::NEG_INFINITY, 0.0], [1.0, f64::INFINITY]));
        boxes.push(([f64::NAN, 0.0], [1.0, 1.0]));
        let index = BoxIndex::new(boxes.clone());
        for q in 0..200 {
            let (x, y, w) = (rnd() * 110.0 - 5.0, rnd() * 110.0 - 5.0, rnd() * 10.0);
            let (lo, hi) = ([x, y], [x + w, y + w]);
            let mut found = Vec::new();
            let visited = index
                .query(
                    |a, b| meet(&(*a, *b), &lo, &hi),
                    |i| {
                        found.push(i);
                        Ok::<(), ()>(())
                    },
                )
                .unwrap();
            found.sort();
            let scan: Vec<usize> = (0..boxes.len())
                .filter(|&i| {
                    let b = if valid(&boxes[i]) { boxes[i] } else { whole() };
                    meet(&b, &lo, &hi)
                })
                .collect();
            assert_eq!(found, scan, "query {q}");
            assert!(found.contains(&1001));
            // pruned: far fewer nodes than items for a small query
            assert!(visited < 400, "{visited} nodes visited");
        }
    }

    #[test]
    fn an_empty_index_finds_nothing() {
        let index = BoxIndex::new(Vec::new());
        let r = index.query(|_, _| true, |_| Err::<(), _>("called"));
        assert_eq!(r, Ok(0));
    }
}
