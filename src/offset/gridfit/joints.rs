//! The joints between the cubics: nominal positions on the exact outline,
//! moved along it to grid points.

use super::outline::{Contour, Ctx, Joint, Part, Pos};
use super::{bad, OffsetError, JOINT_SHARE, MIN_GAP_STEPS, SPLIT_SHARE, WINDOW_STEPS};
use glam::DVec2;

impl Ctx<'_> {
    /// [`Self::snap_within`] in `window`, then (when nothing there is within
    /// `tol/2` of a grid point) anywhere between `lo` and `hi`.
    pub(super) fn snap(
        &self,
        c: &Contour,
        nominal: Pos,
        lo: Pos,
        hi: Pos,
        window: f64,
    ) -> Option<(Joint, f64)> {
        let first = self.snap_within(c, nominal, (lo, hi), window, &[], JOINT_SHARE)?;
        if first.1 <= JOINT_SHARE * self.tol.value() {
            return Some(first);
        }
        self.snap_within(c, nominal, (lo, hi), f64::INFINITY, &[], JOINT_SHARE)
    }

    /// A split's joint: [`Self::snap`] among the positions whose nearest grid
    /// point is none of `avoid` (the joints it splits between), and when no
    /// grid point in `window` is within `tol/2` of the curve, the one within
    /// `SPLIT_SHARE·tol` closest to `nominal` before any farther one.
    pub(super) fn snap_split(
        &self,
        c: &Contour,
        nominal: Pos,
        lo: Pos,
        hi: Pos,
        window: f64,
        avoid: &[DVec2],
    ) -> Option<(Joint, f64)> {
        for share in [JOINT_SHARE, SPLIT_SHARE] {
            let found = self.snap_within(c, nominal, (lo, hi), window, avoid, share)?;
            if found.1 <= share * self.tol.value() {
                return Some(found);
            }
        }
        self.snap_within(c, nominal, (lo, hi), f64::INFINITY, avoid, SPLIT_SHARE)
    }

    /// Moves a joint from `nominal` along the exact curve, strictly between
    /// `lo` and `hi` (or onto them when they equal `nominal`), by at most
    /// `window` of arc length, to the position closest to `nominal` whose
    /// nearest grid point (none of `avoid`) is within `share·tol`; else to the
    /// position with the nearest grid point. Returns the joint and its grid
    /// point's distance from the curve.
    fn snap_within(
        &self,
        c: &Contour,
        nominal: Pos,
        (lo, hi): (Pos, Pos),
        window: f64,
        avoid: &[DVec2],
        share: f64,
    ) -> Option<(Joint, f64)> {
        let delta = share * self.tol.value();
        let h = self.gf / 16.0;
        let p0 = self.point(&c.parts[nominal.part], nominal.u)?;
        let score = |p: DVec2| {
            let g = self.nearest_grid(p);
            if avoid.contains(&g) {
                f64::INFINITY
            } else {
                (p - g).length()
            }
        };
        let mut best = (score(p0), 0.0, nominal);
        let mut good: Option<(f64, Pos)> = (best.0 <= delta).then_some((0.0, nominal));
        for dir in [1.0f64, -1.0] {
            let (mut pos, mut walked, mut prev) = (nominal, 0.0, p0);
            for _ in 0..65536 {
                let part = &c.parts[pos.part];
                let sp = self.speed(part, pos.u);
                let du = if sp > 0.0 {
                    (h / sp).min(1.0 / 64.0)
                } else {
                    1.0 / 64.0
                };
                let mut u = pos.u + dir * du;
                let mut k = pos.part;
                if u >= 1.0 {
                    if k + 1 >= c.parts.len() {
                        break;
                    }
                    k += 1;
                    u = 0.0;
                } else if u < 0.0 {
                    if pos.u > 0.0 {
                        u = 0.0;
                    } else if k == 0 {
                        break;
                    } else {
                        k -= 1;
                        u = (1.0 - du).max(0.0);
                    }
                }
                pos = Pos { part: k, u };
                if !(lo.before(pos) && pos.before(hi)) {
                    break;
                }
                let Some(p) = self.point(&c.parts[k], u) else {
                    break;
                };
                walked += (p - prev).length();
                prev = p;
                if walked > window {
                    break;
                }
                let d = score(p);
                if d < best.0 {
                    best = (d, walked, pos);
                }
                if d <= delta && good.is_none_or(|g| walked < g.0) {
                    good = Some((walked, pos));
                }
            }
        }
        let pos = good.map_or(best.2, |g| g.1);
        let p = self.point(&c.parts[pos.part], pos.u)?;
        let g = self.exact_grid(p)?;
        Some((Joint { pos, g }, (p - g).length()))
    }

    /// The exact outline turns back at the start of part `k` (a cusp: the
    /// ends of a concave corner's arc, a cusp of the offset of a piece).
    fn is_cusp(&self, c: &Contour, k: usize) -> bool {
        let prev = if k > 0 {
            k - 1
        } else if c.closed {
            c.parts.len() - 1
        } else {
            return false;
        };
        let e = 1e-4;
        let pts = (
            self.point(&c.parts[prev], 1.0 - e),
            self.point(&c.parts[prev], 1.0),
            self.point(&c.parts[k], 0.0),
            self.point(&c.parts[k], e),
        );
        match pts {
            (Some(a0), Some(a1), Some(b0), Some(b1)) => (a1 - a0).dot(b1 - b0) < 0.0,
            _ => false,
        }
    }

    /// The initial joints of a contour: the starts of its parts, except at
    /// cusps (a joint there could not move to a grid point: one cubic turns
    /// round the cusp instead) and within `MIN_GAP_STEPS` grid steps of the
    /// previous joint; arcs over 90° (and a concave corner's arc, whose two
    /// ends are cusps) get joints inside.
    fn nominal_joints(&self, c: &Contour) -> Vec<Pos> {
        let min_gap = MIN_GAP_STEPS * self.gf;
        let mut cands = Vec::new();
        for (k, p) in c.parts.iter().enumerate() {
            let cusp = !self.corner_joints && self.is_cusp(c, k);
            if !cusp || (k == 0 && !c.closed) {
                cands.push(Pos { part: k, u: 0.0 });
            }
            // a part between two cusps (the middle of a swallowtail) gets a
            // joint in its middle
            if cusp
                && k + 1 < c.parts.len()
                && self.is_cusp(c, k + 1)
                && !matches!(p, Part::Arc { .. })
            {
                cands.push(Pos { part: k, u: 0.5 });
            }
            if let Part::Arc { sweep, r, .. } = p {
                let quarter = std::f64::consts::FRAC_PI_2;
                let mut n = (sweep.abs() / quarter).ceil().max(1.0) as usize;
                if cusp && sweep.abs() * r >= 2.0 * min_gap {
                    n = n.max(2);
                }
                cands.extend((1..n).map(|j| Pos {
                    part: k,
                    u: j as f64 / n as f64,
                }));
            }
        }
        let mut out: Vec<Pos> = Vec::new();
        for p in cands {
            if let Some(&q) = out.last() {
                if self.length(c, q, p) < min_gap {
                    continue;
                }
            }
            out.push(p);
        }
        if c.closed && out.len() > 1 {
            if let (Some(&l), Some(&f)) = (out.last(), out.first()) {
                if self.length(c, l, f) < min_gap {
                    out.pop();
                }
            }
        }
        if out.is_empty() {
            out.push(Pos { part: 0, u: 0.0 });
        }
        out
    }

    /// The joints of a contour (step 2 of the module docs): its nominal
    /// joints moved along the exact curve to grid points, those with no grid
    /// point near the curve dropped, and an open contour's ends moved inwards
    /// by `tol/2` at most.
    pub(super) fn joints(&self, c: &Contour) -> Result<Vec<Joint>, OffsetError> {
        let nominal = self.nominal_joints(c);
        let last = Pos {
            part: c.parts.len() - 1,
            u: 1.0,
        };
        let mut joints: Vec<Joint> = Vec::new();
        let n = nominal.len();
        for (i, &pos) in nominal.iter().enumerate() {
            let lo = match joints.last() {
                Some(j) => j.pos,
                None => pos,
            };
            let hi = if i + 1 < n { nominal[i + 1] } else { last };
            let prev_len = if i > 0 {
                self.length(c, nominal[i - 1], pos)
            } else {
                f64::INFINITY
            };
            let next_len = self.length(c, pos, hi);
            let open_end = i == 0 && !c.closed;
            let found = if open_end {
                // an open end moves inwards by tol/2 at most
                self.snap_within(
                    c,
                    pos,
                    (lo, hi),
                    JOINT_SHARE * self.tol.value(),
                    &[],
                    JOINT_SHARE,
                )
            } else {
                let window = (WINDOW_STEPS * self.gf).min(0.45 * prev_len.min(next_len));
                self.snap(c, pos, lo, hi, window)
            };
            let (j, dist) = found
                .ok_or_else(|| bad("curve", "the exact offset cannot be evaluated at a joint"))?;
            // no grid point near the curve up to the next joint: no joint here
            // (the cubic runs on), unless it is an open end
            if dist <= JOINT_SHARE * self.tol.value()
                || open_end
                || (i + 1 == n && joints.is_empty())
            {
                joints.push(j);
            }
        }
        if !c.closed {
            let lo = joints.last().map_or(last, |j| j.pos);
            let (j, _) = self
                .snap_within(
                    c,
                    last,
                    (lo, last),
                    JOINT_SHARE * self.tol.value(),
                    &[],
                    JOINT_SHARE,
                )
                .ok_or_else(|| bad("curve", "the exact offset cannot be evaluated at its end"))?;
            joints.push(j);
        }
        Ok(joints)
    }
}
