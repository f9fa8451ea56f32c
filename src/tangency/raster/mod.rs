//! Raster sampling of two bivariate polynomials: candidate cells for their common roots
//! (seed 003 §4.2, "Solving the Equations").
//!
//! # The paper's scheme
//!
//! Seed 003 reduces tangency of a quartic LN curve to a circle to two polynomial equations in
//! the unknowns `(m, a2)`: eq. (7), rendered as Φ(m, a2) of eq. (8) (algebraic degree six), and
//! eq. (6) (degree ten). It samples both on a 1K × 1K raster on the GPU: the sign of Φ selects
//! the red channel (red = positive, black = negative), the sign of eq. (6) the blue channel, so
//! every pixel is black, red, blue or cyan (red + blue). A 2 × 2 mask then selects the blocks
//! "whose four pixels have more than two colours": those straddle both zero sets and lie near
//! an intersection, i.e. a candidate root.
//!
//! # Our mask rule
//!
//! Nodes are the `n × n` points of a [`Grid`]; a node's code holds two sign bits, `p > 0` and
//! `q > 0` (zero and NaN count as "not positive"). A [`Cell`] (a 2 × 2 block of nodes) is a
//! *candidate* iff **both** sign bits change over its four corners. The paper's rule "more than
//! two colours" is a strict subset of ours: three or four distinct colours always force both
//! bits to change, but a block whose corners show exactly the two colours {black, cyan}
//! (both signs flip together) or {red, blue} (both flip in opposite directions) also has both
//! bits changing, and the paper's rule misses it. Such blocks occur where the two zero curves
//! run through the block side by side, in particular at a crossing aligned with the grid
//! diagonal, so our rule lists every cell the paper lists and some more.
//!
//! # Backends and reproducibility
//!
//! [`raster_cpu`] runs on the CPU (rayon over rows, `f64`); [`raster_gpu`] runs the same
//! computation as a wgpu compute shader (`raster.wgsl`, feature `gpu`). Both evaluate every
//! node as [`DensePoly2::eval`] does: nested Horner with a fused multiply-add (`f64::mul_add`,
//! WGSL `fma()`) for every step, at the node coordinates of [`Grid::x`] / [`Grid::y`] (computed
//! once on the CPU and uploaded, so both backends use the same bits). A fused multiply-add is
//! one correctly rounded IEEE operation, so a device that really fuses computes the same bits
//! as the CPU; the shader spells out every `fma` rather than `a * b + c`, which a shader
//! compiler may contract or not at will.
//!
//! Fusing alone does not make the GPU output identical, though: Vulkan allows a driver to
//! evaluate `fma()` as a multiply and an add, and Mesa's llvmpipe does so for `f64` (observed
//! in `tests/raster.rs`, `fused_and_unfused_signs_differ`). So the `f64` shader also evaluates
//! the a-priori error bound of Horner's scheme, `|v̂ − p(x, y)| ≤ γ_{2K} Σ |a_ij| |x|^i |y|^j`
//! with `K = deg_x + deg_y`, `γ_k = k u / (1 − k u)`, `u = 2^-53` (Higham, *Accuracy and
//! Stability of Numerical Algorithms*, §5.1; it holds for fused and unfused steps alike), with a
//! factor 2 margin and a padding of the coefficients for underflow. A node whose GPU value is
//! not larger in magnitude than the bound could have the other sign (or be 0) on the CPU, so
//! every cell touching such a node is re-decided on the CPU with [`DensePoly2::eval`]; every
//! other node has the same sign bit on both backends. The [`Precision::F64`] output of
//! [`raster_gpu`] therefore equals that of [`raster_cpu`] cell for cell, assuming only that the
//! device's `f64` add and multiply are correctly (or at least faithfully) rounded. Inputs
//! whose values could approach the `f64` overflow threshold are rastered on the CPU inside
//! [`raster_gpu`] (reported as [`BackendUsed::Cpu`]), so the shader never sees `inf` or NaN.
//!
//! Without `f64` shaders the GPU evaluates in `f32` ([`Precision::F32`]): coefficients and
//! nodes are rounded to `f32`, and the output is only an approximation of the `f64` raster
//! (cells near a sign boundary can come and go).
//!
//! # A heuristic, not a proof
//!
//! The raster is a sampling heuristic: a root whose cell shows no sign change (a tangential
//! intersection, two roots in one cell, a curve component smaller than a cell) is missed, and a
//! listed cell need not contain a root. Nothing here is "certified": completeness and soundness
//! of the tangency solutions are proven by the complete solver, which uses these cells only as
//! starting points.

mod cpu;
#[cfg(feature = "gpu")]
mod gpu;

/// Largest supported degree in each variable of a [`DensePoly2`].
pub const MAX_DEGREE: usize = 16;

/// Largest supported grid resolution `n` (nodes per axis) of a [`Grid`].
pub const MAX_RESOLUTION: u32 = 16384;

/// Why a raster could not be computed. Every variant names the offending input or the device.
#[derive(Clone, Debug, PartialEq, Eq, thiserror::Error)]
pub enum RasterError {
    /// A [`Grid`] field is out of range (`n`, a bound, or the bounds' order).
    #[error("grid.{field}: {reason}")]
    InvalidGrid {
        /// The offending field (shown as `grid.{field}`): `n` or a bound.
        field: &'static str,
        /// Why it is out of range.
        reason: String,
    },
    /// A [`DensePoly2`] field is invalid (degree, coefficient count, non-finite coefficient).
    #[error("{field}: {reason}")]
    InvalidPoly {
        /// The offending field, e.g. `p.deg_x` or `q.coeffs`.
        field: &'static str,
        /// Why it is invalid.
        reason: String,
    },
    /// No usable GPU adapter (or the crate was built without the `gpu` feature).
    #[error("no GPU adapter: {0}")]
    NoAdapter(String),
    /// The GPU device reported an error (validation, out of memory, lost device, mapping).
    #[error("GPU error: {0}")]
    Gpu(String),
}

/// Dense bivariate polynomial `p(x, y) = Σ_{i ≤ deg_x, j ≤ deg_y} coeffs[i·(deg_y+1)+j] xⁱ yʲ`
/// in `f64`, the input of the raster (seed 003 eqs. (6) and (8) with `x = m`, `y = a2`).
#[derive(Clone, Debug, PartialEq)]
pub struct DensePoly2 {
    /// Degree in `x` (at most [`MAX_DEGREE`]).
    pub deg_x: usize,
    /// Degree in `y` (at most [`MAX_DEGREE`]).
    pub deg_y: usize,
    /// `(deg_x + 1) · (deg_y + 1)` finite coefficients, row `i` (power of `x`) after row `i - 1`.
    pub coeffs: Vec<f64>,
}

impl DensePoly2 {
    /// Builds a polynomial, checking the degrees (≤ [`MAX_DEGREE`]), the number of coefficients
    /// and that each coefficient is finite.
    pub fn new(deg_x: usize, deg_y: usize, coeffs: Vec<f64>) -> Result<Self, RasterError> {
        let p = DensePoly2 {
            deg_x,
            deg_y,
            coeffs,
        };
        p.check(["deg_x", "deg_y", "coeffs"])?;
        Ok(p)
    }

    /// Checks the invariants of [`DensePoly2::new`]; `fields` names deg_x, deg_y, coeffs.
    fn check(&self, fields: [&'static str; 3]) -> Result<(), RasterError> {
        for (deg, field) in [(self.deg_x, fields[0]), (self.deg_y, fields[1])] {
            if deg > MAX_DEGREE {
                return Err(RasterError::InvalidPoly {
                    field,
                    reason: format!("degree {deg} exceeds the maximum {MAX_DEGREE}"),
                });
            }
        }
        let expected = (self.deg_x + 1) * (self.deg_y + 1);
        if self.coeffs.len() != expected {
            return Err(RasterError::InvalidPoly {
                field: fields[2],
                reason: format!(
                    "{} coefficients, expected (deg_x + 1)(deg_y + 1) = {expected}",
                    self.coeffs.len()
                ),
            });
        }
        if let Some(k) = self.coeffs.iter().position(|c| !c.is_finite()) {
            return Err(RasterError::InvalidPoly {
                field: fields[2],
                reason: format!(
                    "coefficient {k} (of x^{} y^{}) is {}, not a finite number",
                    k / (self.deg_y + 1),
                    k % (self.deg_y + 1),
                    self.coeffs[k]
                ),
            });
        }
        Ok(())
    }

    /// Whether the shape is valid (degrees, length); guards [`DensePoly2::eval`] against structs
    /// built by hand.
    fn shape_ok(&self) -> bool {
        self.deg_x <= MAX_DEGREE
            && self.deg_y <= MAX_DEGREE
            && self.coeffs.len() == (self.deg_x + 1) * (self.deg_y + 1)
    }

    /// Inner Horner in `y` for every power of `x`: `out[i] = Σ_j coeffs[i][j] yʲ`, each step
    /// `c = mul_add(c, y, coeffs[i][j])` starting from the top coefficient.
    fn inner(&self, y: f64, out: &mut [f64; MAX_DEGREE + 1]) {
        let stride = self.deg_y + 1;
        for (i, row) in self.coeffs.chunks_exact(stride).enumerate() {
            let mut c = row[self.deg_y];
            for &a in row[..self.deg_y].iter().rev() {
                c = c.mul_add(y, a);
            }
            out[i] = c;
        }
    }

    /// Outer Horner in `x` over the inner values: `r = mul_add(r, x, inner[i])` from the top.
    fn outer(&self, inner: &[f64; MAX_DEGREE + 1], x: f64) -> f64 {
        let mut r = inner[self.deg_x];
        for &c in inner[..self.deg_x].iter().rev() {
            r = r.mul_add(x, c);
        }
        r
    }

    /// Reference evaluation, exactly the scheme of both backends: for each power `i` of `x` an
    /// inner Horner over `j` with [`f64::mul_add`] (`c = mul_add(c, y, coeff)`, starting from the
    /// coefficient of `y^deg_y`), then an outer Horner over `i` with `mul_add`. Returns NaN for a
    /// hand-built polynomial whose shape violates the invariants of [`DensePoly2::new`].
    pub fn eval(&self, x: f64, y: f64) -> f64 {
        if !self.shape_ok() {
            return f64::NAN;
        }
        let mut inner = [0.0; MAX_DEGREE + 1];
        self.inner(y, &mut inner);
        self.outer(&inner, x)
    }
}

/// An `n × n` raster of nodes `(x_i, y_j)` over `[x_lo, x_hi] × [y_lo, y_hi]`, with
/// `x_i = mul_add(step_x, i, x_lo)`, `step_x = (x_hi - x_lo) / (n - 1)` (the same for `y`).
/// Cells are the `(n - 1)²` squares `[x_i, x_{i+1}] × [y_j, y_{j+1}]` (seed 003 §4.2 uses
/// `n = 1024`).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Grid {
    /// Nodes per axis, `2 ≤ n ≤ MAX_RESOLUTION`.
    pub n: u32,
    /// Lower `x` bound (finite).
    pub x_lo: f64,
    /// Upper `x` bound (finite, `> x_lo`).
    pub x_hi: f64,
    /// Lower `y` bound (finite).
    pub y_lo: f64,
    /// Upper `y` bound (finite, `> y_lo`).
    pub y_hi: f64,
}

impl Grid {
    /// Checks `2 ≤ n ≤ MAX_RESOLUTION`, finite bounds, `lo < hi`, and that the step neither
    /// underflows to 0 nor overflows (nor the last node).
    pub fn validate(&self) -> Result<(), RasterError> {
        if self.n < 2 || self.n > MAX_RESOLUTION {
            return Err(RasterError::InvalidGrid {
                field: "n",
                reason: format!("{} is outside 2..={MAX_RESOLUTION}", self.n),
            });
        }
        let axes = [
            ("x_lo", "x_hi", self.x_lo, self.x_hi),
            ("y_lo", "y_hi", self.y_lo, self.y_hi),
        ];
        for (lo_name, hi_name, lo, hi) in axes {
            for (field, v) in [(lo_name, lo), (hi_name, hi)] {
                if !v.is_finite() {
                    return Err(RasterError::InvalidGrid {
                        field,
                        reason: format!("{v} is not a finite number"),
                    });
                }
            }
            if lo >= hi {
                return Err(RasterError::InvalidGrid {
                    field: hi_name,
                    reason: format!("{hi} must be greater than {lo_name} = {lo}"),
                });
            }
            let step = (hi - lo) / f64::from(self.n - 1);
            let last = step.mul_add(f64::from(self.n - 1), lo);
            if !step.is_finite() || !last.is_finite() {
                return Err(RasterError::InvalidGrid {
                    field: hi_name,
                    reason: format!("{hi_name} - {lo_name} overflows f64"),
                });
            }
            if step <= 0.0 {
                return Err(RasterError::InvalidGrid {
                    field: hi_name,
                    reason: format!("{hi_name} - {lo_name} is too small for n = {}", self.n),
                });
            }
        }
        Ok(())
    }

    /// Node spacing in `x`, `(x_hi - x_lo) / (n - 1)`.
    fn step_x(&self) -> f64 {
        (self.x_hi - self.x_lo) / f64::from(self.n.saturating_sub(1).max(1))
    }

    /// Node spacing in `y`, `(y_hi - y_lo) / (n - 1)`.
    fn step_y(&self) -> f64 {
        (self.y_hi - self.y_lo) / f64::from(self.n.saturating_sub(1).max(1))
    }

    /// `x_i = mul_add(step_x, i, x_lo)`, the abscissa of node column `i`.
    pub fn x(&self, i: u32) -> f64 {
        self.step_x().mul_add(f64::from(i), self.x_lo)
    }

    /// `y_j = mul_add(step_y, j, y_lo)`, the ordinate of node row `j`.
    pub fn y(&self, j: u32) -> f64 {
        self.step_y().mul_add(f64::from(j), self.y_lo)
    }
}

/// A cell `[x_i, x_{i+1}] × [y_j, y_{j+1}]` of a [`Grid`], `i, j < n - 1`. (The derived `Ord`
/// compares `i` first; [`RasterOutput::cells`] is sorted row-major by `(j, i)`.)
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash, PartialOrd, Ord)]
pub struct Cell {
    /// Column: the cell spans nodes `i` and `i + 1` in `x`.
    pub i: u32,
    /// Row: the cell spans nodes `j` and `j + 1` in `y`.
    pub j: u32,
}

/// Arithmetic the node values were computed in.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum Precision {
    /// IEEE `f64` with fused multiply-adds: identical on every backend.
    F64,
    /// `f32` (GPU without `f64` shaders): an approximation of the `f64` raster.
    F32,
}

/// Which backend produced a [`RasterOutput`].
#[derive(Clone, Debug, PartialEq, Eq, Hash)]
pub enum BackendUsed {
    /// [`raster_cpu`].
    Cpu,
    /// [`raster_gpu`] on the named adapter; `software` is true for a CPU-emulated driver
    /// (llvmpipe / lavapipe / SwiftShader, or an adapter of type `Cpu`).
    Gpu {
        /// Name of the adapter, as the driver reports it.
        adapter: String,
        /// True for a CPU-emulated driver.
        software: bool,
    },
}

/// Candidate cells of a raster and how they were computed.
#[derive(Clone, Debug, PartialEq)]
pub struct RasterOutput {
    /// Cells where both `p` and `q` change sign over the four corners, sorted by `(j, i)`.
    pub cells: Vec<Cell>,
    /// Arithmetic of the node values.
    pub precision: Precision,
    /// Backend that produced the cells.
    pub backend: BackendUsed,
}

/// Validates both polynomials (named `p.*`, `q.*`) and the grid.
fn check_inputs(p: &DensePoly2, q: &DensePoly2, grid: &Grid) -> Result<(), RasterError> {
    p.check(["p.deg_x", "p.deg_y", "p.coeffs"])?;
    q.check(["q.deg_x", "q.deg_y", "q.coeffs"])?;
    grid.validate()
}

/// Sign code of a node: bit 0 = `p > 0`, bit 1 = `q > 0` (seed 003's red and blue channels).
fn node_code(pv: f64, qv: f64) -> u8 {
    u8::from(pv > 0.0) | (u8::from(qv > 0.0) << 1)
}

/// The mask rule: both sign bits change over the four corner codes.
fn is_candidate(a: u8, b: u8, c: u8, d: u8) -> bool {
    let all = a & b & c & d;
    let any = a | b | c | d;
    (all ^ any) & 3 == 3
}

/// The raster on the CPU (rayon over rows, `f64`, [`DensePoly2::eval`]'s arithmetic). Node
/// rows are computed in bands of at most 128 rows, so memory is `O(n)` bytes per band row,
/// never `n²` values.
pub fn raster_cpu(
    p: &DensePoly2,
    q: &DensePoly2,
    grid: &Grid,
) -> Result<RasterOutput, RasterError> {
    check_inputs(p, q, grid)?;
    Ok(cpu::raster(p, q, grid))
}

/// The raster on the GPU (wgpu compute shader `raster.wgsl`): for a band of node rows, pass 0
/// evaluates the inner Horner values (one per power of `x`, they depend on `y` only), pass 1
/// the sign code of every node, pass 2 applies the 2 × 2 mask and packs one candidate bit per
/// cell plus one "uncertain" bit per cell with a corner value within the Horner error bound of
/// 0; the bits are read back and listed on the CPU, which re-decides the uncertain cells with
/// [`DensePoly2::eval`]. Uses `f64` when the adapter offers `SHADER_F64` (output identical to
/// [`raster_cpu`], see the module docs), else `f32` (approximate). The device and pipelines are created once per process and cached; calls are
/// serialized. Errors: invalid input as in [`raster_cpu`]; [`RasterError::NoAdapter`] without
/// a usable adapter or without the `gpu` feature; [`RasterError::Gpu`] for device failures.
pub fn raster_gpu(
    p: &DensePoly2,
    q: &DensePoly2,
    grid: &Grid,
) -> Result<RasterOutput, RasterError> {
    check_inputs(p, q, grid)?;
    #[cfg(feature = "gpu")]
    {
        gpu::raster(p, q, grid, gpu::BAND_BYTES)
    }
    #[cfg(not(feature = "gpu"))]
    {
        Err(RasterError::NoAdapter(
            "built without the `gpu` feature".to_string(),
        ))
    }
}
