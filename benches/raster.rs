//! Time per raster (seed 003 §4.2) on the CPU (rayon, f64) and on the GPU (wgpu compute shader)
//! at n = 256 and n = 1024 (the paper's 1K × 1K), for a pair of bidegrees (10, 6) and (6, 6)
//! with pseudo-random coefficients in [-1, 1] on [-1.5, 1.5]². GPU results are labelled with
//! the adapter name: on a machine without a GPU this is Mesa's llvmpipe, a *software* Vulkan
//! driver running on the CPU, so the "GPU" numbers there say nothing about real GPUs.
//!
//! Before the criterion runs, prints one timed call per backend and size (the first GPU call
//! includes creating the device and pipelines) and whether the GPU cells equal the CPU cells.
//!
//! Run: `cargo bench --bench raster`.

// `criterion_group!` defines an undocumented `pub fn benches`.
#![allow(missing_docs)]

use criterion::{criterion_group, criterion_main, BenchmarkId, Criterion};
use lncert::tangency::raster::{
    raster_cpu, raster_gpu, BackendUsed, DensePoly2, Grid, RasterError,
};
use std::hint::black_box;
use std::time::{Duration, Instant};

/// Bidegree (dx, dy) polynomial with coefficients from a 64-bit LCG in [-1, 1].
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
    match DensePoly2::new(dx, dy, coeffs) {
        Ok(p) => p,
        Err(e) => panic!("benchmark polynomial: {e}"),
    }
}

fn grid(n: u32) -> Grid {
    Grid {
        n,
        x_lo: -1.5,
        x_hi: 1.5,
        y_lo: -1.5,
        y_hi: 1.5,
    }
}

fn bench(c: &mut Criterion) {
    let p = lcg_poly(10, 6, 1);
    let q = lcg_poly(6, 6, 2);
    let sizes = [256u32, 1024];

    // One timed call per backend and size, in this process, before criterion.
    let mut gpu_label = None;
    for &n in &sizes {
        let g = grid(n);
        let t = Instant::now();
        let cpu = raster_cpu(&p, &q, &g).expect("valid input");
        let t_cpu = t.elapsed();
        let t = Instant::now();
        match raster_gpu(&p, &q, &g) {
            Ok(gpu) => {
                let t_gpu = t.elapsed();
                let BackendUsed::Gpu { adapter, software } = &gpu.backend else {
                    panic!("raster_gpu reported {:?}", gpu.backend);
                };
                println!(
                    "n = {n}: cpu {t_cpu:?} ({} cells), gpu {t_gpu:?} on {adapter} \
                     (software: {software}, {:?}), identical: {}",
                    cpu.cells.len(),
                    gpu.precision,
                    gpu.cells == cpu.cells
                );
                let kind = if *software { "software" } else { "hardware" };
                gpu_label = Some(format!("gpu [{adapter}, {kind}]"));
            }
            Err(RasterError::NoAdapter(msg)) => {
                println!("n = {n}: cpu {t_cpu:?}; no GPU benchmark: {msg}");
            }
            Err(e) => panic!("GPU raster failed: {e}"),
        }
    }

    let mut group = c.benchmark_group("raster");
    group
        .sample_size(10)
        .warm_up_time(Duration::from_millis(300))
        .measurement_time(Duration::from_secs(3));
    for &n in &sizes {
        let g = grid(n);
        group.bench_with_input(BenchmarkId::new("cpu", n), &g, |b, g| {
            b.iter(|| raster_cpu(black_box(&p), black_box(&q), g))
        });
        if let Some(label) = &gpu_label {
            group.bench_with_input(BenchmarkId::new(label.as_str(), n), &g, |b, g| {
                b.iter(|| raster_gpu(black_box(&p), black_box(&q), g))
            });
        }
    }
    group.finish();
}

criterion_group!(benches, bench);
criterion_main!(benches);
