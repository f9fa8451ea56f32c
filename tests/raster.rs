//! The raster backends of seed 003 §4.2 (`lncert::tangency::raster`):
//! (a) CPU raster against a brute-force reference written here (all node values in a Vec,
//!     then a scan of the 2 x 2 blocks with a differently spelled mask rule);
//! (b) GPU against CPU, bit-identical cell lists in f64;
//! (c) known geometry: unit circle and the line y = 2x;
//! (d) bad input gives typed errors;
//! (e) a grid needing two GPU bands (n = 4097 with the default 64 MiB band budget).
//!
//! GPU tests print a note and pass when no adapter exists, unless `LNCERT_REQUIRE_GPU=1`.
//! Cases per property: `LNCERT_PROPTEST_CASES / 20` (default 100) for the CPU reference,
//! `/ 50` (default 40) for GPU vs CPU.

mod common;

use common::cases;
use lncert::tangency::raster::{
    raster_cpu, raster_gpu, BackendUsed, Cell, DensePoly2, Grid, Precision, RasterError,
    RasterOutput, MAX_RESOLUTION,
};
use proptest::prelude::*;
use std::cmp::Ordering;

fn config(divisor: u32) -> ProptestConfig {
    ProptestConfig {
        cases: (cases() / divisor).max(1),
        failure_persistence: None,
        ..ProptestConfig::default()
    }
}

fn gpu_required() -> bool {
    std::env::var("LNCERT_REQUIRE_GPU").as_deref() == Ok("1")
}

/// The GPU raster, or `None` (with a note) when there is no adapter and none is required, or
/// when the adapter only has f32 shaders (no bit-identity to check).
fn gpu_f64(p: &DensePoly2, q: &DensePoly2, grid: &Grid) -> Option<RasterOutput> {
    match raster_gpu(p, q, grid) {
        Ok(out) => {
            // Inputs that might overflow the shader are rastered on the CPU (reported as such).
            if out.precision == Precision::F64 {
                Some(out)
            } else {
                static NOTE: std::sync::Once = std::sync::Once::new();
                NOTE.call_once(|| eprintln!("note: GPU adapter has no f64 shaders; not compared"));
                None
            }
        }
        Err(RasterError::NoAdapter(msg)) if !gpu_required() => {
            static NOTE: std::sync::Once = std::sync::Once::new();
            NOTE.call_once(|| eprintln!("note: skipping GPU checks, no adapter: {msg}"));
            None
        }
        Err(e) => panic!("GPU raster failed: {e}"),
    }
}

/// Node value by the documented formula, spelled out independently of the crate:
/// c_i = Horner in y of row i (mul_add), then Horner in x over the c_i.
fn reference_eval(p: &DensePoly2, x: f64, y: f64) -> f64 {
    let w = p.deg_y + 1;
    let mut acc = 0.0;
    for i in (0..=p.deg_x).rev() {
        let mut c = p.coeffs[i * w + p.deg_y];
        for j in (0..p.deg_y).rev() {
            c = c.mul_add(y, p.coeffs[i * w + j]);
        }
        acc = if i == p.deg_x { c } else { acc.mul_add(x, c) };
    }
    acc
}

/// Brute force: all n^2 node values, then every block; a cell is listed when among its corners
/// there is a positive and a non-positive p value, and likewise for q.
fn reference_cells(p: &DensePoly2, q: &DensePoly2, grid: &Grid) -> Vec<Cell> {
    let n = grid.n as usize;
    let sx = (grid.x_hi - grid.x_lo) / (n - 1) as f64;
    let sy = (grid.y_hi - grid.y_lo) / (n - 1) as f64;
    let mut pv = vec![0.0; n * n];
    let mut qv = vec![0.0; n * n];
    for j in 0..n {
        let y = sy.mul_add(j as f64, grid.y_lo);
        for i in 0..n {
            let x = sx.mul_add(i as f64, grid.x_lo);
            pv[j * n + i] = reference_eval(p, x, y);
            qv[j * n + i] = reference_eval(q, x, y);
        }
    }
    let mut cells = Vec::new();
    for j in 0..n - 1 {
        for i in 0..n - 1 {
            let corners = [
                j * n + i,
                j * n + i + 1,
                (j + 1) * n + i,
                (j + 1) * n + i + 1,
            ];
            let mixed = |v: &[f64]| {
                let positive = |k: &usize| v[*k].partial_cmp(&0.0) == Some(Ordering::Greater);
                corners.iter().any(positive) && !corners.iter().all(positive)
            };
            if mixed(&pv) && mixed(&qv) {
                cells.push(Cell {
                    i: i as u32,
                    j: j as u32,
                });
            }
        }
    }
    cells
}

/// Coefficients: mostly uniform in [-1, 1], sometimes small integers (exact zeros on nodes).
fn coeff() -> impl Strategy<Value = f64> {
    prop_oneof![3 => -1.0f64..1.0, 1 => (-3i32..=3).prop_map(f64::from)]
}

fn poly(max_deg: usize) -> impl Strategy<Value = DensePoly2> {
    (0..=max_deg, 0..=max_deg).prop_flat_map(|(dx, dy)| {
        proptest::collection::vec(coeff(), (dx + 1) * (dy + 1))
            .prop_map(move |c| DensePoly2::new(dx, dy, c).expect("finite coefficients"))
    })
}

fn grid(n: std::ops::RangeInclusive<u32>) -> impl Strategy<Value = Grid> {
    (n, -2.0f64..0.0, 0.1f64..3.0, -2.0f64..0.0, 0.1f64..3.0).prop_map(|(n, x0, wx, y0, wy)| Grid {
        n,
        x_lo: x0,
        x_hi: x0 + wx,
        y_lo: y0,
        y_hi: y0 + wy,
    })
}

proptest! {
    #![proptest_config(config(20))]

    /// (a) CPU raster == brute-force reference, and eval == the reference formula bit for bit.
    #[test]
    fn cpu_matches_brute_force(p in poly(4), q in poly(4), g in grid(17..=65)) {
        let out = raster_cpu(&p, &q, &g).expect("valid input");
        prop_assert_eq!(out.precision, Precision::F64);
        prop_assert_eq!(&out.backend, &BackendUsed::Cpu);
        prop_assert_eq!(&out.cells, &reference_cells(&p, &q, &g));
        for k in 0..g.n {
            let (x, y) = (g.x(k), g.y(g.n - 1 - k));
            prop_assert_eq!(p.eval(x, y).to_bits(), reference_eval(&p, x, y).to_bits());
        }
    }
}

proptest! {
    #![proptest_config(config(50))]

    /// (b) GPU == CPU on random f64 polynomials up to degree 10 x 10, grids up to 257.
    #[test]
    fn gpu_matches_cpu(p in poly(10), q in poly(10), g in grid(2..=257)) {
        let cpu = raster_cpu(&p, &q, &g).expect("valid input");
        if let Some(gpu) = gpu_f64(&p, &q, &g) {
            prop_assert_eq!(gpu.cells, cpu.cells);
        }
    }
}

/// A fixed pair of degrees (10, 6) and (6, 6), coefficients from a 64-bit LCG in [-1, 1].
fn lcg_poly(dx: usize, dy: usize, seed: u64) -> DensePoly2 {
    let mut s = seed;
    let coeffs = (0..(dx + 1) * (dy + 1))
        .map(|_| {
            s = s
                .wrapping_mul(6364136223846793005)
                .wrapping_add(1442695040888963407);
            ((s >> 11) as f64 / (1u64 << 53) as f64) * 2.0 - 1.0
        })
        .collect();
    DensePoly2::new(dx, dy, coeffs).expect("finite coefficients")
}

/// (b) GPU == CPU on one 1024 x 1024 raster (the paper's size).
#[test]
fn gpu_matches_cpu_1024() {
    let p = lcg_poly(10, 6, 1);
    let q = lcg_poly(6, 6, 2);
    let g = Grid {
        n: 1024,
        x_lo: -1.5,
        x_hi: 1.5,
        y_lo: -1.5,
        y_hi: 1.5,
    };
    let cpu = raster_cpu(&p, &q, &g).expect("valid input");
    assert!(!cpu.cells.is_empty(), "test pair should have candidates");
    if let Some(gpu) = gpu_f64(&p, &q, &g) {
        assert!(
            matches!(gpu.backend, BackendUsed::Gpu { .. }),
            "{:?}",
            gpu.backend
        );
        assert_eq!(gpu.cells, cpu.cells);
    }
}

/// (e) n = 4097 needs two bands of the default 64 MiB node-code budget on the GPU.
#[test]
fn gpu_two_bands_match_cpu() {
    // Circle of radius 0.9 and the cubic y = x^3 - 0.5 x.
    let p = DensePoly2::new(2, 2, vec![-0.81, 0.0, 1.0, 0.0, 0.0, 0.0, 1.0, 0.0, 0.0]);
    let q = DensePoly2::new(3, 1, vec![0.0, 1.0, 0.5, 0.0, 0.0, 0.0, -1.0, 0.0]);
    let (p, q) = (p.expect("valid"), q.expect("valid"));
    let g = Grid {
        n: 4097,
        x_lo: -1.0,
        x_hi: 1.0,
        y_lo: -1.0,
        y_hi: 1.0,
    };
    let cpu = raster_cpu(&p, &q, &g).expect("valid input");
    assert!(!cpu.cells.is_empty());
    if let Some(gpu) = gpu_f64(&p, &q, &g) {
        assert_eq!(gpu.cells, cpu.cells);
    }
}

/// The cell (i, j) with x_i <= x < x_{i+1}, y_j <= y < y_{j+1}, by scanning the nodes.
fn cell_of(g: &Grid, x: f64, y: f64) -> (i64, i64) {
    let find = |v: f64, node: &dyn Fn(u32) -> f64| {
        (0..g.n - 1)
            .find(|&k| node(k) <= v && v < node(k + 1))
            .expect("point inside the grid") as i64
    };
    (find(x, &|k| g.x(k)), find(y, &|k| g.y(k)))
}

/// (c) p = x^2 + y^2 - 1, q = y - 2x on [-2, 2]^2, n = 101: the roots are ±(1/√5, 2/√5).
fn check_circle_line(out: &RasterOutput) {
    let g = circle_grid();
    let r = 1.0 / 5f64.sqrt();
    let roots = [cell_of(&g, r, 2.0 * r), cell_of(&g, -r, -2.0 * r)];
    let cheb = |c: &Cell, (i, j): (i64, i64)| (c.i as i64 - i).abs().max((c.j as i64 - j).abs());
    for root in roots {
        assert!(
            out.cells.iter().any(|c| cheb(c, root) <= 1),
            "no candidate at or next to root cell {root:?}: {:?}",
            out.cells
        );
    }
    for c in &out.cells {
        assert!(
            roots.iter().any(|&root| cheb(c, root) <= 2),
            "cell {c:?} is more than 2 cells from both roots {roots:?}"
        );
    }
}

fn circle_grid() -> Grid {
    Grid {
        n: 101,
        x_lo: -2.0,
        x_hi: 2.0,
        y_lo: -2.0,
        y_hi: 2.0,
    }
}

fn circle_line() -> (DensePoly2, DensePoly2) {
    // coeffs[i * (deg_y + 1) + j] is the coefficient of x^i y^j.
    let p = DensePoly2::new(2, 2, vec![-1.0, 0.0, 1.0, 0.0, 0.0, 0.0, 1.0, 0.0, 0.0]);
    let q = DensePoly2::new(1, 1, vec![0.0, 1.0, -2.0, 0.0]);
    (p.expect("valid"), q.expect("valid"))
}

#[test]
fn circle_line_cpu() {
    let (p, q) = circle_line();
    assert_eq!(
        p.eval(0.6, 0.8),
        0.6f64.mul_add(0.6, 0.8f64.mul_add(0.8, -1.0))
    );
    check_circle_line(&raster_cpu(&p, &q, &circle_grid()).expect("valid input"));
}

#[test]
fn circle_line_gpu() {
    let (p, q) = circle_line();
    if let Some(out) = gpu_f64(&p, &q, &circle_grid()) {
        assert!(
            matches!(out.backend, BackendUsed::Gpu { .. }),
            "{:?}",
            out.backend
        );
        check_circle_line(&out);
    }
}

/// (d) Bad input: typed errors naming the field, from both backends, before any device work.
#[test]
fn bad_input_is_typed() {
    let (p, q) = circle_line();
    let good = circle_grid();
    let grid_err = |g: Grid, want: &str| {
        for out in [raster_cpu(&p, &q, &g), raster_gpu(&p, &q, &g)] {
            match out {
                Err(RasterError::InvalidGrid { field, .. }) => assert_eq!(field, want, "{g:?}"),
                other => panic!("{g:?}: expected InvalidGrid({want}), got {other:?}"),
            }
        }
    };
    for n in [0, 1, MAX_RESOLUTION + 1, u32::MAX] {
        grid_err(Grid { n, ..good }, "n");
    }
    grid_err(
        Grid {
            x_lo: f64::NAN,
            ..good
        },
        "x_lo",
    );
    grid_err(
        Grid {
            y_hi: f64::NAN,
            ..good
        },
        "y_hi",
    );
    grid_err(
        Grid {
            y_lo: f64::NEG_INFINITY,
            ..good
        },
        "y_lo",
    );
    grid_err(
        Grid {
            x_lo: 2.0,
            x_hi: -2.0,
            ..good
        },
        "x_hi",
    );
    grid_err(
        Grid {
            y_lo: 1.0,
            y_hi: 1.0,
            ..good
        },
        "y_hi",
    );
    grid_err(
        Grid {
            x_lo: -f64::MAX,
            x_hi: f64::MAX,
            ..good
        },
        "x_hi",
    );
    grid_err(
        Grid {
            x_lo: 0.0,
            x_hi: 1e-320,
            n: MAX_RESOLUTION,
            ..good
        },
        "x_hi",
    );
    assert!(good.validate().is_ok());
    assert!(Grid { n: 2, ..good }.validate().is_ok());
    assert!(Grid {
        n: MAX_RESOLUTION,
        ..good
    }
    .validate()
    .is_ok());

    let poly_err = |r: Result<DensePoly2, RasterError>, want: &str| match r {
        Err(RasterError::InvalidPoly { field, .. }) => assert_eq!(field, want),
        other => panic!("expected InvalidPoly({want}), got {other:?}"),
    };
    poly_err(DensePoly2::new(1, 1, vec![1.0; 3]), "coeffs");
    poly_err(DensePoly2::new(1, 1, vec![1.0; 5]), "coeffs");
    poly_err(
        DensePoly2::new(1, 1, vec![1.0, f64::NAN, 0.0, 0.0]),
        "coeffs",
    );
    poly_err(DensePoly2::new(0, 0, vec![f64::INFINITY]), "coeffs");
    poly_err(DensePoly2::new(17, 0, vec![1.0; 18]), "deg_x");
    poly_err(DensePoly2::new(0, usize::MAX, vec![]), "deg_y");
    assert!(DensePoly2::new(16, 16, vec![1.0; 289]).is_ok());

    // Hand-built polynomials bypassing `new` are re-checked by both backends.
    let bad_len = DensePoly2 {
        deg_x: 2,
        deg_y: 2,
        coeffs: vec![1.0; 4],
    };
    let bad_nan = DensePoly2 {
        deg_x: 0,
        deg_y: 1,
        coeffs: vec![1.0, f64::NAN],
    };
    assert!(bad_len.eval(0.5, 0.5).is_nan());
    for out in [
        raster_cpu(&bad_len, &q, &good),
        raster_gpu(&bad_len, &q, &good),
    ] {
        assert!(
            matches!(
                out,
                Err(RasterError::InvalidPoly {
                    field: "p.coeffs",
                    ..
                })
            ),
            "{out:?}"
        );
    }
    for out in [
        raster_cpu(&p, &bad_nan, &good),
        raster_gpu(&p, &bad_nan, &good),
    ] {
        assert!(
            matches!(
                out,
                Err(RasterError::InvalidPoly {
                    field: "q.coeffs",
                    ..
                })
            ),
            "{out:?}"
        );
    }
    // The error messages name the field.
    let msg = raster_cpu(&p, &bad_nan, &good).unwrap_err().to_string();
    assert!(msg.contains("q.coeffs") && msg.contains("NaN"), "{msg}");
}

/// Exact zeros count as "not positive": q = y vanishes on the whole node row y = 0, so the row
/// of cells below it (y from -step to 0) has q-corners {-, -, 0, 0}: no q sign change there.
#[test]
fn zero_is_not_positive() {
    // p = x, q = y on [-1, 1]^2 with n = 5: nodes -1, -0.5, 0, 0.5, 1 (exact).
    let p = DensePoly2::new(1, 0, vec![0.0, 1.0]).expect("valid");
    let q = DensePoly2::new(0, 1, vec![0.0, 1.0]).expect("valid");
    let g = Grid {
        n: 5,
        x_lo: -1.0,
        x_hi: 1.0,
        y_lo: -1.0,
        y_hi: 1.0,
    };
    // p > 0 only at x in {0.5, 1}, q > 0 only at y in {0.5, 1}: the only block with both
    // changes is the one spanning x in [0, 0.5], y in [0, 0.5].
    let want = vec![Cell { i: 2, j: 2 }];
    assert_eq!(raster_cpu(&p, &q, &g).expect("valid").cells, want);
    if let Some(out) = gpu_f64(&p, &q, &g) {
        assert_eq!(out.cells, want);
    }
}

/// The sign of the last rounding decides the cells: p = x^2 - c with c = fl(t^2) at a node
/// t = x_i vanishes in unfused arithmetic (fl(t·t) - c = 0) but equals the correctly rounded
/// t^2 - c ≠ 0 with a fused multiply-add. p > 0 at x_i moves the p sign change from cell i to
/// cell i - 1. The expected cell comes from the exact sign of t^2 - c over the rationals; both
/// backends must agree with it, so an unfused shader (or CPU) fails here. The same with y^2 - c
/// exercises the inner Horner in y.
#[test]
fn last_rounding_decides_cells() {
    use lncert::scalar::rational_from_f64;
    use num_traits::Signed;
    let mut s: u64 = 7;
    let mut unit = || {
        s = s
            .wrapping_mul(6364136223846793005)
            .wrapping_add(1442695040888963407);
        (s >> 11) as f64 / (1u64 << 53) as f64
    };
    let mut positive = 0;
    let mut not_positive = 0;
    for case in 0..60 {
        let lo = 0.1 + 0.4 * unit();
        let g = Grid {
            n: 33,
            x_lo: lo,
            x_hi: lo + 0.3 + unit(),
            y_lo: lo,
            y_hi: lo + 0.3 + unit(),
        };
        let k = 1 + (unit() * 30.0) as u32; // node 1..=30
        let along_y = case % 2 == 1;
        let t = if along_y { g.y(k) } else { g.x(k) };
        let c = t * t;
        let exact = {
            let tr = rational_from_f64(t).expect("finite");
            tr.clone() * tr - rational_from_f64(c).expect("finite")
        };
        let t_positive = exact.is_positive();
        if t_positive {
            positive += 1;
        } else {
            not_positive += 1;
        }
        // The other polynomial changes sign between nodes 10 and 11 of the other axis.
        let (p, q, want) = if along_y {
            let mid = 0.5 * (g.x(10) + g.x(11));
            let p = DensePoly2::new(0, 2, vec![-c, 0.0, 1.0]).expect("valid");
            let q = DensePoly2::new(1, 0, vec![-mid, 1.0]).expect("valid");
            let j = if t_positive { k - 1 } else { k };
            (p, q, vec![Cell { i: 10, j }])
        } else {
            let mid = 0.5 * (g.y(10) + g.y(11));
            let p = DensePoly2::new(2, 0, vec![-c, 0.0, 1.0]).expect("valid");
            let q = DensePoly2::new(0, 1, vec![-mid, 1.0]).expect("valid");
            let i = if t_positive { k - 1 } else { k };
            (p, q, vec![Cell { i, j: 10 }])
        };
        let cpu = raster_cpu(&p, &q, &g).expect("valid input");
        assert_eq!(cpu.cells, want, "CPU, case {case}, t = {t:e}");
        if let Some(gpu) = gpu_f64(&p, &q, &g) {
            assert_eq!(gpu.cells, want, "GPU, case {case}, t = {t:e}");
        }
    }
    // Both outcomes occur, so the test tells fused from unfused arithmetic.
    assert!(
        positive >= 5 && not_positive >= 5,
        "{positive} / {not_positive}"
    );
}

/// Huge coefficients: near the overflow guard (1e300, still on the GPU) and beyond it (1e305,
/// rastered on the CPU inside `raster_gpu`), the cells equal the CPU raster.
#[test]
fn huge_coefficients_agree() {
    for scale in [1e300, 1e305] {
        let p = DensePoly2::new(1, 1, vec![-scale, scale, scale, 0.0]).expect("valid");
        let q = DensePoly2::new(1, 1, vec![0.5 * scale, -scale, scale, 0.0]).expect("valid");
        let g = Grid {
            n: 40,
            x_lo: -2.0,
            x_hi: 2.0,
            y_lo: -2.0,
            y_hi: 2.0,
        };
        let cpu = raster_cpu(&p, &q, &g).expect("valid input");
        assert!(!cpu.cells.is_empty());
        if let Some(gpu) = gpu_f64(&p, &q, &g) {
            assert_eq!(gpu.cells, cpu.cells, "scale {scale:e}");
        }
    }
}

/// Where fused and unfused Horner steps give values of opposite signs (two steps and a
/// cancellation: p = a2 x^2 + a1 x + a0 with a0 = -fl(r1·t), r1 = fl(a2 t + a1)), the GPU must
/// still give the CPU's (fused) cells. Vulkan lets a driver evaluate fma() unfused, and Mesa's
/// llvmpipe does; only the error-bound fallback to the CPU makes these cases agree there.
#[test]
fn fused_and_unfused_signs_differ() {
    let mut s: u64 = 11;
    let mut unit = || {
        s = s
            .wrapping_mul(6364136223846793005)
            .wrapping_add(1442695040888963407);
        (s >> 11) as f64 / (1u64 << 53) as f64
    };
    let mut found = 0;
    let mut tries = 0;
    while found < 24 && tries < 100_000 {
        tries += 1;
        let lo = 0.1 + unit();
        let g = Grid {
            n: 33,
            x_lo: lo,
            x_hi: lo + 0.5 + unit(),
            y_lo: -1.0,
            y_hi: 1.0,
        };
        let k = 2 + (unit() * 28.0) as u32;
        let t = g.x(k);
        let (a2, a1) = (unit() * 2.0 - 1.0, unit() * 2.0 - 1.0);
        let r1_fused = a2.mul_add(t, a1);
        let r1_unfused = a2 * t + a1;
        let a0 = -(r1_fused * t);
        let fused = r1_fused.mul_add(t, a0);
        let unfused = r1_unfused * t + a0;
        if (fused > 0.0) == (unfused > 0.0) {
            continue;
        }
        found += 1;
        let p = DensePoly2::new(2, 0, vec![a0, a1, a2]).expect("valid");
        let q = DensePoly2::new(0, 1, vec![-0.5 * (g.y(10) + g.y(11)), 1.0]).expect("valid");
        assert_eq!(p.eval(t, 0.0).to_bits(), fused.to_bits());
        let cpu = raster_cpu(&p, &q, &g).expect("valid input");
        // p's sign at node k decides which cells next to column k are listed.
        assert!(!cpu.cells.is_empty(), "case {found}");
        if let Some(gpu) = gpu_f64(&p, &q, &g) {
            assert_eq!(
                gpu.cells, cpu.cells,
                "case {found}: t = {t:e}, a2 = {a2:e}, a1 = {a1:e}"
            );
        }
    }
    assert_eq!(found, 24, "only {found} sign-flip cases in {tries} tries");
}
