//! Interval Krawczyk operator for a 2×2 polynomial system `F = (p, q)` with
//! exact rational coefficients (enclosed with the tightest outward intervals).
//!
//! For a box `X`, a point `c ∈ X` and any real matrix `Y`,
//! `K(X) = c - Y F(c) + (I - Y J(X)) (X - c)`,
//! where `F(c)` and `J(X)` (an enclosure of the Jacobian over `X`) are
//! evaluated in outward-rounded interval arithmetic; `c` is the f64 midpoint
//! and `Y` the f64 inverse of the midpoint Jacobian (any `Y` is sound).
//!
//! Krawczyk's theorem (Krawczyk 1969; Moore 1977; Neumaier, *Interval methods
//! for systems of equations*, Thm 5.1.8):
//! * every zero of `F` in `X` lies in `K(X)`, so `K(X) ∩ X = ∅` proves that `X`
//!   holds no zero, and `X ∩ K(X)` may replace `X`;
//! * `K(X) ⊂ int X` proves that `F` has exactly one zero in `X` (and that it
//!   is simple: `Y` and every matrix of `J(X)` are nonsingular).
//!
//! Enclosures over a box use the centred (Taylor) form: the coefficients of
//! `p(c + h, d + k)` are computed by an interval Taylor shift and evaluated on
//! the small intervals `h ∈ X - c`, `k ∈ Y - d` (overestimation `O(width²)`
//! instead of the `O(width)` of naive Horner), which also gives `∂p/∂x`,
//! `∂p/∂y` over the box and `p(c)` (the constant term) at no extra cost.

use super::poly2::Poly2;
use crate::scalar::{interval_from_rational, Interval, Rational};

/// A box `[x] × [y]`.
pub type IBox = [Interval; 2];

/// A point interval (the whole line for NaN, which is always sound).
pub(crate) fn pt(x: f64) -> Interval {
    Interval::try_from((x, x)).unwrap_or(Interval::ENTIRE)
}

/// The interval `[lo, hi]` (the whole line if the ends are not ordered numbers).
pub(crate) fn iv(lo: f64, hi: f64) -> Interval {
    Interval::try_from((lo, hi)).unwrap_or(Interval::ENTIRE)
}

/// A box from `[(x_lo, x_hi), (y_lo, y_hi)]`.
pub fn ibox(b: &[(f64, f64); 2]) -> IBox {
    [iv(b[0].0, b[0].1), iv(b[1].0, b[1].1)]
}

/// Interval hull of two boxes.
pub fn hull(a: &IBox, b: &IBox) -> IBox {
    [a[0].convex_hull(b[0]), a[1].convex_hull(b[1])]
}

/// Whether two boxes share a point.
pub fn intersects(a: &IBox, b: &IBox) -> bool {
    !a[0].disjoint(b[0]) && !a[1].disjoint(b[1])
}

/// A bivariate polynomial with interval coefficients enclosing exact ones.
#[derive(Clone, Debug)]
pub struct IPoly2 {
    dx: usize,
    dy: usize,
    c: Vec<Interval>,
}

impl IPoly2 {
    /// Encloses every coefficient with [`interval_from_rational`].
    pub fn new(p: &Poly2<Rational>) -> Self {
        IPoly2 {
            dx: p.deg_x(),
            dy: p.deg_y(),
            c: p.coeffs().iter().map(interval_from_rational).collect(),
        }
    }
    /// `∂p/∂x`, enclosed: each coefficient `(i + 1)·c_{i+1,j}` as the
    /// outward-rounded product of the integer and the enclosure of `c`
    /// (encloses the exact derivative's coefficient).
    fn dx(&self) -> Self {
        let w = self.dy + 1;
        if self.dx == 0 {
            return IPoly2 {
                dx: 0,
                dy: self.dy,
                c: vec![pt(0.0); w],
            };
        }
        let c = (0..self.dx)
            .flat_map(|i| (0..w).map(move |j| (i, j)))
            .map(|(i, j)| pt((i + 1) as f64) * self.c[(i + 1) * w + j])
            .collect();
        IPoly2 {
            dx: self.dx - 1,
            dy: self.dy,
            c,
        }
    }
    /// `∂p/∂y`, enclosed as [`IPoly2::dx`].
    fn dy(&self) -> Self {
        let w = self.dy + 1;
        if self.dy == 0 {
            return IPoly2 {
                dx: self.dx,
                dy: 0,
                c: vec![pt(0.0); self.dx + 1],
            };
        }
        let c = (0..=self.dx)
            .flat_map(|i| (0..self.dy).map(move |j| (i, j)))
            .map(|(i, j)| pt((j + 1) as f64) * self.c[i * w + j + 1])
            .collect();
        IPoly2 {
            dx: self.dx,
            dy: self.dy - 1,
            c,
        }
    }
    /// Interval Horner evaluation at a box.
    pub fn eval(&self, x: Interval, y: Interval) -> Interval {
        let w = self.dy + 1;
        let mut acc = pt(0.0);
        for i in (0..=self.dx).rev() {
            let mut inner = pt(0.0);
            for j in (0..=self.dy).rev() {
                inner = inner.mul_add(y, self.c[i * w + j]);
            }
            acc = acc.mul_add(x, inner);
        }
        acc
    }
    /// Centred-form enclosures `(p(c), p(X), ∂p/∂x(X), ∂p/∂y(X))` with
    /// `c = (cx, cy)`, `h = X - c`.
    fn centred(&self, cx: f64, cy: f64, h: Interval, k: Interval) -> [Interval; 4] {
        let w = self.dy + 1;
        let mut s = self.c.clone();
        let (cxi, cyi) = (pt(cx), pt(cy));
        // Taylor shift in x (column by column), then in y (row by row).
        if cx != 0.0 {
            for j in 0..w {
                for kk in 0..self.dx {
                    for i in (kk..self.dx).rev() {
                        s[i * w + j] = s[(i + 1) * w + j].mul_add(cxi, s[i * w + j]);
                    }
                }
            }
        }
        if cy != 0.0 {
            for i in 0..=self.dx {
                let row = &mut s[i * w..(i + 1) * w];
                for kk in 0..self.dy {
                    for j in (kk..self.dy).rev() {
                        row[j] = row[j + 1].mul_add(cyi, row[j]);
                    }
                }
            }
        }
        // p(X) = Σ s_ij h^i k^j and its partial derivatives, by simultaneous
        // Horner schemes (d ← d·t + r; r ← r·t + a gives r and r').
        let (mut val, mut px, mut py) = (pt(0.0), pt(0.0), pt(0.0));
        for i in (0..=self.dx).rev() {
            let row = &s[i * w..(i + 1) * w];
            let (mut r, mut ry) = (pt(0.0), pt(0.0));
            for a in row.iter().rev() {
                ry = ry.mul_add(k, r);
                r = r.mul_add(k, *a);
            }
            px = px.mul_add(h, val);
            val = val.mul_add(h, r);
            py = py.mul_add(h, ry);
        }
        [s[0], val, px, py]
    }
}

/// Which interval form encloses `F` and `J` over a box.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum EnclosureForm {
    /// Mean-value form with naive-Horner derivative enclosures (default, cheaper).
    MeanValue,
    /// Centred form by an interval Taylor shift (tighter, costlier).
    Taylor,
}

/// Interval enclosures of `F` and its Jacobian over a box.
#[derive(Clone, Copy, Debug)]
pub struct BoxEnclosure {
    /// The centre `c` (f64, inside the box).
    pub c: [f64; 2],
    /// `F(c)`.
    pub fc: [Interval; 2],
    /// `F(X)`.
    pub fx: [Interval; 2],
    /// `J(X)`: `jac[r][s] = ∂F_r/∂x_s`.
    pub jac: [[Interval; 2]; 2],
}

impl BoxEnclosure {
    /// Whether `0 ∉ F_r(X)` for some `r` (the box holds no zero).
    pub fn excludes_zero(&self) -> bool {
        !self.fx[0].contains(0.0) || !self.fx[1].contains(0.0)
    }
    /// Whether the determinant of `J(X)` encloses 0 (the box may hold a
    /// singular, e.g. tangential double, zero).
    pub fn det_contains_zero(&self) -> bool {
        let j = &self.jac;
        (j[0][0] * j[1][1] - j[0][1] * j[1][0]).contains(0.0)
    }
}

/// One Krawczyk step.
#[derive(Clone, Copy, Debug)]
pub enum KStep {
    /// `K(X) ⊂ int X`: exactly one zero in `X`, and it lies in the returned `K(X)`.
    Unique(IBox),
    /// `K(X) ∩ X = ∅` or `0 ∉ F(X)`: no zero in `X`.
    NoRoot,
    /// Neither; every zero of `X` lies in the returned `K(X) ∩ X`.
    Contracted(IBox),
}

/// The outcome of an iterated Krawczyk test on a box.
#[derive(Clone, Copy, Debug)]
pub enum KOutcome {
    /// Exactly one zero in `region`; every zero of the input box lies in
    /// `region`; `tight ⊆ region` is a contracted enclosure of that zero.
    Unique {
        /// A box holding exactly one zero, and every zero of the input box.
        region: IBox,
        /// Contracted enclosure of that zero (`tight ⊆ region`).
        tight: IBox,
    },
    /// No zero in the input box.
    NoRoot,
    /// Undecided; every zero of the input box lies in `last`.
    Undecided {
        /// The last contracted box: it holds every zero of the input box.
        last: IBox,
    },
}

/// A 2×2 polynomial system with enclosed coefficients.
///
/// # Examples
/// ```
/// use lncert::tangency::{ibox, KOutcome, System2};
/// use lncert::tangency::parse_poly2;
/// let s = System2::new(&parse_poly2("x^2 - 2").unwrap(), &parse_poly2("y - x").unwrap());
/// let (out, _iters) = s.krawczyk(&ibox(&[(1.0, 2.0), (1.0, 2.0)]), 20);
/// match out {
///     KOutcome::Unique { tight, .. } => assert!(tight[0].contains(2f64.sqrt())),
///     _ => panic!("sqrt 2 is a simple root"),
/// }
/// ```
#[derive(Clone, Debug)]
pub struct System2 {
    p: IPoly2,
    q: IPoly2,
    /// `[∂p/∂x, ∂p/∂y, ∂q/∂x, ∂q/∂y]` enclosed (for the mean-value form).
    grad: [IPoly2; 4],
    /// Which enclosure [`System2::enclose`] uses.
    pub form: EnclosureForm,
    exact: [Poly2<Rational>; 2],
    /// Equations linear in one variable: `(v, A, B)` with `A(w) x_v + B(w) = 0`,
    /// `w` the other variable (coefficients enclosed, constant term first).
    linear: Vec<(usize, Vec<Interval>, Vec<Interval>)>,
}

fn horner(c: &[Interval], t: Interval) -> Interval {
    c.iter().rev().fold(pt(0.0), |acc, a| acc.mul_add(t, *a))
}

/// `(v, A, B)` for each variable `v` in which `e` has degree exactly 1.
fn linear_parts(e: &Poly2<Rational>) -> Vec<(usize, Vec<Interval>, Vec<Interval>)> {
    let e = e.trimmed();
    let enc = |v: Vec<Rational>| v.iter().map(interval_from_rational).collect::<Vec<_>>();
    let mut out = Vec::new();
    if e.deg_y() == 1 {
        let a = (0..=e.deg_x()).map(|i| e.coeff(i, 1)).collect();
        let b = (0..=e.deg_x()).map(|i| e.coeff(i, 0)).collect();
        out.push((1, enc(a), enc(b)));
    }
    if e.deg_x() == 1 {
        let a = (0..=e.deg_y()).map(|j| e.coeff(1, j)).collect();
        let b = (0..=e.deg_y()).map(|j| e.coeff(0, j)).collect();
        out.push((0, enc(a), enc(b)));
    }
    out
}

impl System2 {
    /// The system `p = q = 0`.
    pub fn new(p: &Poly2<Rational>, q: &Poly2<Rational>) -> Self {
        let mut linear = linear_parts(p);
        linear.extend(linear_parts(q));
        // the partial derivatives from the enclosed coefficients: each
        // coefficient of `p` is converted once (the conversions dominate)
        let (pi, qi) = (IPoly2::new(p), IPoly2::new(q));
        System2 {
            grad: [pi.dx(), pi.dy(), qi.dx(), qi.dy()],
            p: pi,
            q: qi,
            form: EnclosureForm::Taylor,
            exact: [p.clone(), q.clone()],
            linear,
        }
    }
    /// Contracts `x` with the equations that are linear in one variable:
    /// every zero in `x` has `x_v = -B(x_w)/A(x_w)`, so `x_v` may be intersected
    /// with the interval quotient when `0 ∉ A(x_w)`. `None`: no zero in `x`.
    pub fn contract_linear(&self, x: &IBox) -> Option<IBox> {
        let mut b = *x;
        for (v, a, c) in &self.linear {
            let w = 1 - v;
            let av = horner(a, b[w]);
            if av.contains(0.0) {
                continue;
            }
            let val = -horner(c, b[w]) / av;
            b[*v] = b[*v].intersection(val);
            if b[*v].is_empty() {
                return None;
            }
        }
        Some(b)
    }
    /// The exact equations.
    pub fn exact(&self) -> &[Poly2<Rational>; 2] {
        &self.exact
    }
    /// `F(X)` by interval Horner (naive form).
    pub fn eval(&self, x: &IBox) -> [Interval; 2] {
        [self.p.eval(x[0], x[1]), self.q.eval(x[0], x[1])]
    }
    /// Enclosures of `F` and `J` over `x` (centre: the f64 midpoint) in the
    /// form selected by [`System2::form`].
    pub fn enclose(&self, x: &IBox) -> BoxEnclosure {
        match self.form {
            EnclosureForm::MeanValue => self.enclose_mean_value(x),
            EnclosureForm::Taylor => self.enclose_taylor(x),
        }
    }
    /// Mean-value form: `J(X)` by interval Horner of the exact partial
    /// derivatives, `F(X) ⊆ F(c) + J(X)(X - c)` (mean value theorem)
    /// intersected with the naive Horner enclosure.
    pub fn enclose_mean_value(&self, x: &IBox) -> BoxEnclosure {
        let c = [x[0].mid(), x[1].mid()];
        let (cx, cy) = (pt(c[0]), pt(c[1]));
        let (h, k) = (x[0] - cx, x[1] - cy);
        let g = &self.grad;
        let jac = [
            [g[0].eval(x[0], x[1]), g[1].eval(x[0], x[1])],
            [g[2].eval(x[0], x[1]), g[3].eval(x[0], x[1])],
        ];
        let fc = [self.p.eval(cx, cy), self.q.eval(cx, cy)];
        let mv = |r: usize| jac[r][1].mul_add(k, jac[r][0].mul_add(h, fc[r]));
        let naive = self.eval(x);
        let cut = |a: Interval, b: Interval| {
            let i = a.intersection(b);
            if i.is_empty() {
                a
            } else {
                i
            }
        };
        BoxEnclosure {
            c,
            fc,
            fx: [cut(mv(0), naive[0]), cut(mv(1), naive[1])],
            jac,
        }
    }
    /// Centred (Taylor) form: interval Taylor shift to the midpoint, tighter
    /// (`O(width²)` for `F`, also for `J`) but about three times the work.
    pub fn enclose_taylor(&self, x: &IBox) -> BoxEnclosure {
        let c = [x[0].mid(), x[1].mid()];
        let (h, k) = (x[0] - pt(c[0]), x[1] - pt(c[1]));
        let a = self.p.centred(c[0], c[1], h, k);
        let b = self.q.centred(c[0], c[1], h, k);
        BoxEnclosure {
            c,
            fc: [a[0], b[0]],
            fx: [a[1], b[1]],
            jac: [[a[2], a[3]], [b[2], b[3]]],
        }
    }
    /// [`System2::enclose`], or `None` as soon as the enclosure of the cheaper
    /// equation (fewer coefficients, evaluated first) excludes 0 over `x`.
    pub fn enclose_or_exclude(&self, x: &IBox) -> Option<BoxEnclosure> {
        if self.form == EnclosureForm::MeanValue {
            let e = self.enclose_mean_value(x);
            return (!e.excludes_zero()).then_some(e);
        }
        let c = [x[0].mid(), x[1].mid()];
        let (h, k) = (x[0] - pt(c[0]), x[1] - pt(c[1]));
        let (first, second) = if self.q.c.len() <= self.p.c.len() {
            (&self.q, &self.p)
        } else {
            (&self.p, &self.q)
        };
        let a = first.centred(c[0], c[1], h, k);
        if !a[1].contains(0.0) {
            return None;
        }
        let b = second.centred(c[0], c[1], h, k);
        if !b[1].contains(0.0) {
            return None;
        }
        let (pa, qa) = if std::ptr::eq(first, &self.q) {
            (b, a)
        } else {
            (a, b)
        };
        Some(BoxEnclosure {
            c,
            fc: [pa[0], qa[0]],
            fx: [pa[1], qa[1]],
            jac: [[pa[2], pa[3]], [qa[2], qa[3]]],
        })
    }
    /// One Krawczyk step on `x` given its enclosure.
    pub fn step(&self, x: &IBox, e: &BoxEnclosure) -> KStep {
        if e.excludes_zero() {
            return KStep::NoRoot;
        }
        let Some(k) = self.raw_k(x, e) else {
            return KStep::Contracted(*x);
        };
        if k[0].interior(x[0]) && k[1].interior(x[1]) {
            return KStep::Unique(k);
        }
        let cut = [k[0].intersection(x[0]), k[1].intersection(x[1])];
        if cut[0].is_empty() || cut[1].is_empty() {
            KStep::NoRoot
        } else {
            KStep::Contracted(cut)
        }
    }
    /// Iterated Krawczyk on `x` (at most `max_iter` steps), then contraction
    /// of a proven root box. Returns the outcome and the number of steps.
    pub fn krawczyk(&self, x: &IBox, max_iter: usize) -> (KOutcome, usize) {
        self.iterate(
            *x,
            max_iter,
            |k| self.contract(k, max_iter),
            |cur, _, c| {
                // Continue only while the box shrinks substantially.
                let shrink = |a: Interval, b: Interval| a.wid() <= 0.9 * b.wid();
                if !(shrink(c[0], cur[0]) || shrink(c[1], cur[1])) {
                    return Err(c);
                }
                Ok(c)
            },
        )
    }
    /// The loop of [`Self::krawczyk`] and [`Self::inflate_and_prove`]: at
    /// most `max_iter` Krawczyk steps from `start`. A step that excludes a
    /// zero ends with `NoRoot`; one that proves a unique zero in the current
    /// box ends with it and `tighten` of `K(X)` (plus its steps); after a
    /// contraction `c` of the box `cur` (enclosure `e`), `advance(cur, e, c)`
    /// gives the next box, or the box to report as `Undecided`.
    fn iterate(
        &self,
        start: IBox,
        max_iter: usize,
        tighten: impl Fn(IBox) -> (IBox, usize),
        advance: impl Fn(&IBox, &BoxEnclosure, IBox) -> Result<IBox, IBox>,
    ) -> (KOutcome, usize) {
        let mut cur = start;
        let mut iters = 0;
        while iters < max_iter {
            let e = self.enclose(&cur);
            iters += 1;
            match self.step(&cur, &e) {
                KStep::NoRoot => return (KOutcome::NoRoot, iters),
                KStep::Unique(k) => {
                    let (tight, more) = tighten(k);
                    return (KOutcome::Unique { region: cur, tight }, iters + more);
                }
                KStep::Contracted(c) => match advance(&cur, &e, c) {
                    Ok(next) => cur = next,
                    Err(last) => return (KOutcome::Undecided { last }, iters),
                },
            }
        }
        (KOutcome::Undecided { last: cur }, iters)
    }
    /// Contracts a box `k` known to hold exactly one zero: `k ← K(k) ∩ k`
    /// (the zero stays inside) while the width keeps shrinking.
    pub fn contract(&self, k: IBox, max_iter: usize) -> (IBox, usize) {
        let (k, mut iters) = self.contract_steps(k, max_iter);
        let loose = |i: usize| k[i].wid() > 1e-9 * (1.0 + k[i].mag());
        if !(loose(0) || loose(1)) {
            return (k, iters);
        }
        // Stuck: f64 Newton from the midpoint, then a proof on a tiny box
        // around the approximation. Accepted only if the proven region lies
        // in k: its zero is then k's unique zero.
        let mut z = [k[0].mid(), k[1].mid()];
        for _ in 0..8 {
            let e = self.enclose(&[pt(z[0]), pt(z[1])]);
            let j = e.jac.map(|r| r.map(|v| v.mid()));
            let f = e.fc.map(|v| v.mid());
            let det = j[0][0] * j[1][1] - j[0][1] * j[1][0];
            let dz = [
                (j[1][1] * f[0] - j[0][1] * f[1]) / det,
                (-j[1][0] * f[0] + j[0][0] * f[1]) / det,
            ];
            if !(dz[0].is_finite() && dz[1].is_finite()) {
                return (k, iters);
            }
            z = [z[0] - dz[0], z[1] - dz[1]];
        }
        let (o, n) = self.inflate_and_prove(&[pt(z[0]), pt(z[1])], max_iter);
        iters += n;
        if let KOutcome::Unique { region, tight } = o {
            if region[0].subset(k[0]) && region[1].subset(k[1]) {
                return (tight, iters);
            }
        }
        (k, iters)
    }
    fn contract_steps(&self, mut k: IBox, max_iter: usize) -> (IBox, usize) {
        let mut iters = 0;
        while iters < max_iter {
            let e = self.enclose(&k);
            iters += 1;
            let next = match self.step(&k, &e) {
                KStep::Unique(n) | KStep::Contracted(n) => {
                    [n[0].intersection(k[0]), n[1].intersection(k[1])]
                }
                KStep::NoRoot => break, // impossible for a box with a zero; keep k
            };
            if next[0].is_empty() || next[1].is_empty() {
                break;
            }
            let progress = next[0].wid() < 0.9 * k[0].wid() || next[1].wid() < 0.9 * k[1].wid();
            k = next;
            if !progress {
                break;
            }
        }
        (k, iters)
    }
    /// Krawczyk with ε-inflation (Rump) started from `x0`: the iterates always
    /// contain `x0`, `X ← hull(x0, K(X))` widened by `eps` relative plus a few
    /// ulps. `Unique { region, .. }` then proves exactly one zero in a
    /// `region ⊇ x0`; `NoRoot` proves none in an inflated box `⊇ x0`.
    pub fn inflate_and_prove(&self, x0: &IBox, max_iter: usize) -> (KOutcome, usize) {
        self.iterate(
            inflate(x0, 0.1),
            max_iter,
            |k| self.contract_steps(k, max_iter),
            |cur, e, _| {
                // Recompute the full K(X) (not cut by X) for the next iterate.
                let k = self.raw_k(cur, e).unwrap_or(*cur);
                let next = inflate(&hull(x0, &k), 0.1);
                // Give up when the iterate keeps growing beyond the
                // start box (plus numerical slack at f64 accuracy).
                let limit = |i: usize| (4.0 * x0[i].wid()).max(1e-9 * (1.0 + x0[i].mag()));
                if next[0].wid() > limit(0) || next[1].wid() > limit(1) {
                    return Err(*cur);
                }
                Ok(next)
            },
        )
    }
    /// `K(X)` itself (not intersected with `X`), `None` if `Y` is not finite.
    fn raw_k(&self, x: &IBox, e: &BoxEnclosure) -> Option<IBox> {
        let j = &e.jac;
        let m = [
            [j[0][0].mid(), j[0][1].mid()],
            [j[1][0].mid(), j[1][1].mid()],
        ];
        let det = m[0][0] * m[1][1] - m[0][1] * m[1][0];
        let inv = [
            [m[1][1] / det, -m[0][1] / det],
            [-m[1][0] / det, m[0][0] / det],
        ];
        if !inv.iter().flatten().all(|v| v.is_finite()) {
            return None;
        }
        let y = [
            [pt(inv[0][0]), pt(inv[0][1])],
            [pt(inv[1][0]), pt(inv[1][1])],
        ];
        let h = [x[0] - pt(e.c[0]), x[1] - pt(e.c[1])];
        let mut k = [pt(0.0); 2];
        for r in 0..2 {
            let mut acc = pt(e.c[r]) - (y[r][0] * e.fc[0] + y[r][1] * e.fc[1]);
            for s in 0..2 {
                let ident = pt(if r == s { 1.0 } else { 0.0 });
                let mrs = ident - (y[r][0] * j[0][s] + y[r][1] * j[1][s]);
                acc = mrs.mul_add(h[s], acc);
            }
            k[r] = acc;
        }
        Some(k)
    }
}

/// `x` widened by `rel` of its width on each side plus a few ulps (ε-inflation).
pub fn inflate(x: &IBox, rel: f64) -> IBox {
    let f = |a: Interval| {
        let w = a.wid() * rel;
        let tiny = 4.0 * f64::EPSILON * a.mag() + f64::MIN_POSITIVE;
        iv(a.inf() - w - tiny, a.sup() + w + tiny)
    };
    [f(x[0]), f(x[1])]
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::tangency::poly2::parse_poly2;

    fn sys(p: &str, q: &str) -> System2 {
        System2::new(&parse_poly2(p).unwrap(), &parse_poly2(q).unwrap())
    }

    #[test]
    fn centred_form_encloses_sampled_values() {
        let s = sys("x^3*y - 2*x*y^2 + 5", "y^3 - x + 1/3");
        let b = ibox(&[(0.3, 0.7), (-1.2, -0.4)]);
        let e = s.enclose(&b);
        for i in 0..=10 {
            for j in 0..=10 {
                let x = 0.3 + 0.04 * i as f64;
                let y = -1.2 + 0.08 * j as f64;
                let v = s.eval(&[pt(x), pt(y)]);
                assert!(!e.fx[0].disjoint(v[0]));
                assert!(!e.fx[1].disjoint(v[1]));
                let px = 3.0 * x * x * y - 2.0 * y * y;
                let py = x * x * x - 4.0 * x * y;
                assert!(e.jac[0][0].contains(px) && e.jac[0][1].contains(py));
                assert!(e.jac[1][0].contains(-1.0) && e.jac[1][1].contains(3.0 * y * y));
            }
        }
    }

    /// The gradient enclosed from the enclosed coefficients holds the exact
    /// derivative's coefficients (computed in rationals), at every degree
    /// pattern, including constant and linear variables.
    #[test]
    fn interval_partials_enclose_the_exact_ones() {
        for (p, q) in [
            ("x^3*y - 2*x*y^2 + 5", "y^3 - x + 1/3"),
            ("1/3*x^6*y^5 - 7/11*x^2*y^4 + 10^30/7*x*y - 3", "x - 2/3"),
            ("5", "y^2 - 1/10"),
        ] {
            let (p, q) = (parse_poly2(p).unwrap(), parse_poly2(q).unwrap());
            let s = System2::new(&p, &q);
            let exact = [p.dx(), p.dy(), q.dx(), q.dy()];
            for (g, e) in s.grad.iter().zip(&exact) {
                let e = IPoly2::new(e);
                assert_eq!((g.dx, g.dy), (e.dx, e.dy));
                for (a, b) in g.c.iter().zip(&e.c) {
                    assert!(b.subset(*a), "{a:?} does not hold {b:?}");
                    assert!(a.wid() <= 4.0 * b.wid() + b.mag() * 1e-15, "{a:?} {b:?}");
                }
            }
        }
    }

    #[test]
    fn proves_and_rejects() {
        let s = sys("x^2 + y^2 - 1", "y - 2*x");
        let (o, _) = s.krawczyk(&ibox(&[(0.3, 0.6), (0.7, 1.0)]), 30);
        let KOutcome::Unique { tight, .. } = o else {
            panic!("{o:?}")
        };
        let r = 1.0 / 5f64.sqrt();
        assert!(tight[0].contains(r) || (tight[0].mid() - r).abs() < 1e-15);
        assert!(tight[0].wid() < 1e-12);
        let (o, _) = s.krawczyk(&ibox(&[(0.0, 0.2), (0.0, 0.2)]), 30);
        assert!(matches!(o, KOutcome::NoRoot));
        // Inflation from a cell slightly off the root.
        let (o, _) = s.inflate_and_prove(&ibox(&[(0.4472, 0.4473), (0.8944, 0.8945)]), 30);
        assert!(matches!(o, KOutcome::Unique { .. }), "{o:?}");
        // A cell 8 widths away holds no root, even inflated.
        let (o, _) = s.inflate_and_prove(&ibox(&[(0.4480, 0.4481), (0.8950, 0.8951)]), 30);
        assert!(matches!(o, KOutcome::NoRoot), "{o:?}");
    }
}
