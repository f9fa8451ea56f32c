//! The CPU backend of [`super::raster_cpu`]: rayon over node rows, banded so that memory stays
//! `O(n)` bytes per band row.

use super::{
    is_candidate, node_code, BackendUsed, Cell, DensePoly2, Grid, Precision, RasterOutput,
    MAX_DEGREE,
};
use rayon::prelude::*;

/// Node rows computed per CPU band (bounded memory: `CPU_BAND_ROWS · n` bytes of codes).
const CPU_BAND_ROWS: u32 = 128;

/// Sign codes of node row `j` at the node abscissae `xs`.
fn row_codes(p: &DensePoly2, q: &DensePoly2, xs: &[f64], y: f64) -> Vec<u8> {
    let mut ip = [0.0; MAX_DEGREE + 1];
    let mut iq = [0.0; MAX_DEGREE + 1];
    p.inner(y, &mut ip);
    q.inner(y, &mut iq);
    xs.iter()
        .map(|&x| node_code(p.outer(&ip, x), q.outer(&iq, x)))
        .collect()
}

/// Candidate cells of cell row `j` between node rows `lower` (`j`) and `upper` (`j + 1`).
fn row_cells(j: u32, lower: &[u8], upper: &[u8]) -> Vec<Cell> {
    let mut cells = Vec::new();
    for (i, (l, u)) in lower.windows(2).zip(upper.windows(2)).enumerate() {
        if is_candidate(l[0], l[1], u[0], u[1]) {
            // i < n - 1 <= MAX_RESOLUTION, so it fits in u32.
            cells.push(Cell { i: i as u32, j });
        }
    }
    cells
}

/// The raster of validated input (see [`super::raster_cpu`]).
pub(super) fn raster(p: &DensePoly2, q: &DensePoly2, grid: &Grid) -> RasterOutput {
    let n = grid.n;
    let xs: Vec<f64> = (0..n).map(|i| grid.x(i)).collect();
    let mut cells = Vec::new();
    let mut prev = row_codes(p, q, &xs, grid.y(0));
    let mut start = 0u32;
    while start < n - 1 {
        let end = (start + CPU_BAND_ROWS).min(n - 1);
        // Node rows start+1 ..= end; cell rows start .. end.
        let rows: Vec<Vec<u8>> = (start + 1..=end)
            .into_par_iter()
            .map(|j| row_codes(p, q, &xs, grid.y(j)))
            .collect();
        let band: Vec<Vec<Cell>> = (start..end)
            .into_par_iter()
            .map(|j| {
                let k = (j - start) as usize;
                let lower = if k == 0 { &prev } else { &rows[k - 1] };
                row_cells(j, lower, &rows[k])
            })
            .collect();
        cells.extend(band.into_iter().flatten());
        if let Some(last) = rows.into_iter().last() {
            prev = last;
        }
        start = end;
    }
    RasterOutput {
        cells,
        precision: Precision::F64,
        backend: BackendUsed::Cpu,
    }
}
