//! The wgpu backend of [`super::raster_gpu`]: a process-wide cached device with the three
//! compute pipelines of `raster.wgsl` (pass 0 `row_inner`: inner Horner values per node row,
//! pass 1 `node_codes`: sign code per node, pass 2 `cell_mask`: packed candidate bits).

use super::{
    cpu, is_candidate, node_code, BackendUsed, Cell, DensePoly2, Grid, Precision, RasterError,
    RasterOutput,
};
use std::panic::{catch_unwind, AssertUnwindSafe};
use std::sync::{mpsc, Arc, Mutex, OnceLock};
use wgpu::util::DeviceExt;

/// Largest node-code buffer of one band (64 MiB): a band holds `BAND_BYTES / (4 n)` node rows
/// (1024 rows at `n = 16384`, the whole grid at `n = 1024`).
pub(super) const BAND_BYTES: u64 = 64 << 20;

/// Workgroup width of the three entry points in `raster.wgsl`.
const WORKGROUP: u32 = 64;

/// The WGSL template; `REAL` becomes `f64` or `f32`.
const SHADER: &str = include_str!("raster.wgsl");

/// Device, queue and pipelines, created once per process.
struct Context {
    device: wgpu::Device,
    queue: wgpu::Queue,
    layout: wgpu::BindGroupLayout,
    inner_pipeline: wgpu::ComputePipeline,
    codes_pipeline: wgpu::ComputePipeline,
    mask_pipeline: wgpu::ComputePipeline,
    precision: Precision,
    adapter: String,
    software: bool,
    /// Largest buffer / storage binding the device accepts (bytes).
    max_binding: u64,
    /// Errors reported by the device's uncaptured-error handler since the last check.
    errors: Arc<Mutex<Vec<String>>>,
    /// Serializes raster calls (one band sequence at a time, errors attributed to the caller).
    call: Mutex<()>,
}

static CONTEXT: OnceLock<Result<Context, RasterError>> = OnceLock::new();

/// Whether an adapter is a CPU-emulated driver.
fn is_software(info: &wgpu::AdapterInfo) -> bool {
    let name = info.name.to_lowercase();
    info.device_type == wgpu::DeviceType::Cpu
        || ["llvmpipe", "lavapipe", "swiftshader"]
            .iter()
            .any(|s| name.contains(s))
}

/// Drains the device errors collected so far into one `RasterError::Gpu`, if any.
fn take_errors(errors: &Mutex<Vec<String>>) -> Result<(), RasterError> {
    let mut errors = errors.lock().unwrap_or_else(|e| e.into_inner());
    if errors.is_empty() {
        Ok(())
    } else {
        let msg = errors.join("; ");
        errors.clear();
        Err(RasterError::Gpu(msg))
    }
}

impl Context {
    /// Picks an adapter (compute capable; `f64` shaders first, then hardware before software,
    /// then discrete before integrated) and builds the pipelines.
    fn new() -> Result<Context, RasterError> {
        Context::new_with(false)
    }

    /// [`Context::new`], optionally with the `f32` shader even on an `f64` adapter (tests).
    fn new_with(force_f32: bool) -> Result<Context, RasterError> {
        // Vulkan / Metal / DX12 first; OpenGL (no f64, noisy EGL probing on headless Linux) only
        // if none of those has an adapter. `WGPU_BACKEND` overrides the choice.
        let descriptor = wgpu::InstanceDescriptor::from_env_or_default();
        let tiers = match wgpu::Backends::from_env() {
            Some(backends) => vec![backends],
            None => vec![wgpu::Backends::PRIMARY, wgpu::Backends::SECONDARY],
        };
        let mut candidates = Vec::new();
        for backends in tiers {
            let instance = wgpu::Instance::new(&wgpu::InstanceDescriptor {
                backends,
                ..descriptor.clone()
            });
            candidates = instance
                .enumerate_adapters(backends)
                .into_iter()
                .filter(|a| {
                    a.get_downlevel_capabilities()
                        .flags
                        .contains(wgpu::DownlevelFlags::COMPUTE_SHADERS)
                })
                .collect();
            if !candidates.is_empty() {
                break;
            }
        }
        let rank = |a: &wgpu::Adapter| {
            let info = a.get_info();
            let kind = match info.device_type {
                wgpu::DeviceType::DiscreteGpu => 3,
                wgpu::DeviceType::IntegratedGpu => 2,
                wgpu::DeviceType::VirtualGpu => 1,
                _ => 0,
            };
            (
                a.features().contains(wgpu::Features::SHADER_F64),
                !is_software(&info),
                kind,
            )
        };
        let adapter = candidates.into_iter().max_by_key(rank).ok_or_else(|| {
            RasterError::NoAdapter(
                "no wgpu adapter with compute shaders found (on Linux without a GPU, install \
                     Mesa's software Vulkan driver: mesa-vulkan-drivers and libvulkan1)"
                    .to_string(),
            )
        })?;
        let info = adapter.get_info();
        let f64_ok = !force_f32 && adapter.features().contains(wgpu::Features::SHADER_F64);
        let required_features = if f64_ok {
            wgpu::Features::SHADER_F64
        } else {
            wgpu::Features::empty()
        };
        let limits = adapter.limits();
        let (device, queue) = pollster::block_on(adapter.request_device(&wgpu::DeviceDescriptor {
            label: Some("lncert raster"),
            required_features,
            required_limits: limits.clone(),
            ..Default::default()
        }))
        .map_err(|e| RasterError::NoAdapter(format!("adapter {:?}: {e}", info.name)))?;
        let errors = Arc::new(Mutex::new(Vec::new()));
        let sink = Arc::clone(&errors);
        device.on_uncaptured_error(Arc::new(move |e: wgpu::Error| {
            sink.lock()
                .unwrap_or_else(|p| p.into_inner())
                .push(e.to_string());
        }));
        let source = SHADER.replace("REAL", if f64_ok { "f64" } else { "f32" });
        let module = device.create_shader_module(wgpu::ShaderModuleDescriptor {
            label: Some("raster.wgsl"),
            source: wgpu::ShaderSource::Wgsl(source.into()),
        });
        let storage = |binding, read_only| wgpu::BindGroupLayoutEntry {
            binding,
            visibility: wgpu::ShaderStages::COMPUTE,
            ty: wgpu::BindingType::Buffer {
                ty: wgpu::BufferBindingType::Storage { read_only },
                has_dynamic_offset: false,
                min_binding_size: None,
            },
            count: None,
        };
        let layout = device.create_bind_group_layout(&wgpu::BindGroupLayoutDescriptor {
            label: Some("raster layout"),
            entries: &[
                wgpu::BindGroupLayoutEntry {
                    binding: 0,
                    visibility: wgpu::ShaderStages::COMPUTE,
                    ty: wgpu::BindingType::Buffer {
                        ty: wgpu::BufferBindingType::Uniform,
                        has_dynamic_offset: false,
                        min_binding_size: None,
                    },
                    count: None,
                },
                storage(1, true),
                storage(2, false),
                storage(3, false),
                storage(4, false),
            ],
        });
        let pipeline_layout = device.create_pipeline_layout(&wgpu::PipelineLayoutDescriptor {
            label: Some("raster pipeline layout"),
            bind_group_layouts: &[&layout],
            push_constant_ranges: &[],
        });
        let pipeline = |entry: &str| {
            device.create_compute_pipeline(&wgpu::ComputePipelineDescriptor {
                label: Some(entry),
                layout: Some(&pipeline_layout),
                module: &module,
                entry_point: Some(entry),
                compilation_options: Default::default(),
                cache: None,
            })
        };
        let inner_pipeline = pipeline("row_inner");
        let codes_pipeline = pipeline("node_codes");
        let mask_pipeline = pipeline("cell_mask");
        take_errors(&errors)?;
        Ok(Context {
            device,
            queue,
            layout,
            inner_pipeline,
            codes_pipeline,
            mask_pipeline,
            precision: if f64_ok {
                Precision::F64
            } else {
                Precision::F32
            },
            software: is_software(&info),
            adapter: info.name,
            max_binding: u64::from(limits.max_storage_buffer_binding_size)
                .min(limits.max_buffer_size),
            errors,
            call: Mutex::new(()),
        })
    }

    /// The shader's `data` array: `[x_0.., y_0.., p, q, |p| + δ, |q| + δ, c]` as bytes of `f64`
    /// or `f32`, and the offsets `(p, q, |p|, |q|, y, c)`.
    fn data_bytes(&self, p: &DensePoly2, q: &DensePoly2, grid: &Grid) -> (Vec<u8>, [u32; 6]) {
        let (_, delta) = bound_constants(self.precision);
        let factor = error_factor(p, q, self.precision);
        let n = grid.n;
        let mut values: Vec<f64> = (0..n).map(|i| grid.x(i)).collect();
        values.extend((0..n).map(|j| grid.y(j)));
        let ys_off = n;
        let p_off = 2 * n;
        let q_off = p_off + p.coeffs.len() as u32;
        let pa_off = q_off + q.coeffs.len() as u32;
        let qa_off = pa_off + p.coeffs.len() as u32;
        let c_off = qa_off + q.coeffs.len() as u32;
        values.extend_from_slice(&p.coeffs);
        values.extend_from_slice(&q.coeffs);
        values.extend(p.coeffs.iter().map(|a| a.abs() + delta));
        values.extend(q.coeffs.iter().map(|a| a.abs() + delta));
        values.push(factor);
        let bytes = match self.precision {
            Precision::F64 => bytemuck::cast_slice(&values).to_vec(),
            Precision::F32 => {
                let v32: Vec<f32> = values.iter().map(|&v| v as f32).collect();
                bytemuck::cast_slice(&v32).to_vec()
            }
        };
        (bytes, [p_off, q_off, pa_off, qa_off, ys_off, c_off])
    }

    /// Whether some intermediate value of the shader could overflow (or come near it) on this
    /// grid: `Σ (|a_ij| + δ) X^i Y^j` with `X, Y` the largest node magnitudes must stay below
    /// 2^1000 (`f64`) or 2^100 (`f32`). Every Horner partial sum of the values and of the bounds
    /// is at most about this sum, so below it no `inf`/NaN can arise and the shader's
    /// comparisons mean what they say even under a compiler's finite-math assumptions.
    fn may_overflow(&self, p: &DensePoly2, q: &DensePoly2, grid: &Grid) -> bool {
        let (_, delta) = bound_constants(self.precision);
        let limit = match self.precision {
            Precision::F64 => 2f64.powi(1000),
            Precision::F32 => 2f64.powi(100),
        };
        let pad = 1.0 + 2f64.powi(-40);
        let big_x = grid.x_lo.abs().max(grid.x_hi.abs()) * pad;
        let big_y = grid.y_lo.abs().max(grid.y_hi.abs()) * pad;
        [p, q].iter().any(|poly| {
            let mut sum = 0.0;
            for (k, a) in poly.coeffs.iter().enumerate() {
                let (i, j) = (k / (poly.deg_y + 1), k % (poly.deg_y + 1));
                sum += (a.abs() + delta) * big_x.powi(i as i32) * big_y.powi(j as i32);
            }
            // NaN (impossible for finite input, but cheap to exclude) counts as overflow.
            (sum * 2.0).partial_cmp(&limit) != Some(std::cmp::Ordering::Less)
        })
    }

    /// Runs the three passes band by band (at most `band_bytes` of node codes per band) and
    /// returns the candidate cells sorted by `(j, i)`, and how many cells the CPU decided.
    fn run(
        &self,
        p: &DensePoly2,
        q: &DensePoly2,
        grid: &Grid,
        band_bytes: u64,
    ) -> Result<(RasterOutput, usize), RasterError> {
        let _guard = self.call.lock().unwrap_or_else(|e| e.into_inner());
        take_errors(&self.errors)?;
        let n = grid.n;
        let n64 = u64::from(n);
        let cell_rows = n - 1;
        let words_per_row = cell_rows.div_ceil(32);
        // Two words (candidates, uncertain) per 32 cells.
        let bits_bytes = u64::from(cell_rows) * u64::from(words_per_row) * 8;
        if bits_bytes > self.max_binding {
            return Err(RasterError::Gpu(format!(
                "candidate bits of n = {n} need {bits_bytes} bytes, the adapter allows {}",
                self.max_binding
            )));
        }
        let budget = band_bytes.min(self.max_binding);
        // Node rows per band: at least 2 (one cell row), at most n.
        let band_rows = (budget / (4 * n64)).clamp(2, n64) as u32;
        let codes_bytes = u64::from(band_rows) * n64 * 4;
        if codes_bytes > self.max_binding {
            return Err(RasterError::Gpu(format!(
                "two node rows of n = {n} need {codes_bytes} bytes, the adapter allows {}",
                self.max_binding
            )));
        }
        let device = &self.device;
        let (data_bytes, [p_off, q_off, pa_off, qa_off, ys_off, c_off]) =
            self.data_bytes(p, q, grid);
        let data = device.create_buffer_init(&wgpu::util::BufferInitDescriptor {
            label: Some("raster data"),
            contents: &data_bytes,
            usage: wgpu::BufferUsages::STORAGE,
        });
        let params = device.create_buffer(&wgpu::BufferDescriptor {
            label: Some("raster params"),
            size: 64,
            usage: wgpu::BufferUsages::UNIFORM | wgpu::BufferUsages::COPY_DST,
            mapped_at_creation: false,
        });
        let codes = device.create_buffer(&wgpu::BufferDescriptor {
            label: Some("raster codes"),
            size: codes_bytes,
            usage: wgpu::BufferUsages::STORAGE,
            mapped_at_creation: false,
        });
        let real_bytes = match self.precision {
            Precision::F64 => 8,
            Precision::F32 => 4,
        };
        let inner_stride = 2 * (p.deg_x + q.deg_x + 2) as u32;
        let inner = device.create_buffer(&wgpu::BufferDescriptor {
            label: Some("raster inner values"),
            size: u64::from(band_rows) * u64::from(inner_stride) * real_bytes,
            usage: wgpu::BufferUsages::STORAGE,
            mapped_at_creation: false,
        });
        let bits = device.create_buffer(&wgpu::BufferDescriptor {
            label: Some("raster bits"),
            size: bits_bytes,
            usage: wgpu::BufferUsages::STORAGE | wgpu::BufferUsages::COPY_SRC,
            mapped_at_creation: false,
        });
        let staging = device.create_buffer(&wgpu::BufferDescriptor {
            label: Some("raster readback"),
            size: bits_bytes,
            usage: wgpu::BufferUsages::MAP_READ | wgpu::BufferUsages::COPY_DST,
            mapped_at_creation: false,
        });
        let bind_group = device.create_bind_group(&wgpu::BindGroupDescriptor {
            label: Some("raster bind group"),
            layout: &self.layout,
            entries: &[
                wgpu::BindGroupEntry {
                    binding: 0,
                    resource: params.as_entire_binding(),
                },
                wgpu::BindGroupEntry {
                    binding: 1,
                    resource: data.as_entire_binding(),
                },
                wgpu::BindGroupEntry {
                    binding: 2,
                    resource: codes.as_entire_binding(),
                },
                wgpu::BindGroupEntry {
                    binding: 3,
                    resource: bits.as_entire_binding(),
                },
                wgpu::BindGroupEntry {
                    binding: 4,
                    resource: inner.as_entire_binding(),
                },
            ],
        });
        let mut row0 = 0u32;
        while row0 < cell_rows {
            // Node rows row0 ..= row0 + rows - 1, cell rows row0 .. row0 + rows - 1.
            let rows = band_rows.min(n - row0);
            let words: [u32; 16] = [
                n,
                row0,
                rows,
                words_per_row,
                p.deg_x as u32,
                p.deg_y as u32,
                p_off,
                q.deg_x as u32,
                q.deg_y as u32,
                q_off,
                pa_off,
                qa_off,
                ys_off,
                c_off,
                0,
                0,
            ];
            self.queue
                .write_buffer(&params, 0, bytemuck::cast_slice(&words));
            let mut encoder = device.create_command_encoder(&wgpu::CommandEncoderDescriptor {
                label: Some("raster band"),
            });
            {
                let mut pass = encoder.begin_compute_pass(&wgpu::ComputePassDescriptor {
                    label: Some("row inner values"),
                    timestamp_writes: None,
                });
                pass.set_pipeline(&self.inner_pipeline);
                pass.set_bind_group(0, &bind_group, &[]);
                pass.dispatch_workgroups(inner_stride.div_ceil(WORKGROUP), rows, 1);
            }
            {
                let mut pass = encoder.begin_compute_pass(&wgpu::ComputePassDescriptor {
                    label: Some("node codes"),
                    timestamp_writes: None,
                });
                pass.set_pipeline(&self.codes_pipeline);
                pass.set_bind_group(0, &bind_group, &[]);
                pass.dispatch_workgroups(n.div_ceil(WORKGROUP), rows, 1);
            }
            {
                let mut pass = encoder.begin_compute_pass(&wgpu::ComputePassDescriptor {
                    label: Some("cell mask"),
                    timestamp_writes: None,
                });
                pass.set_pipeline(&self.mask_pipeline);
                pass.set_bind_group(0, &bind_group, &[]);
                pass.dispatch_workgroups(words_per_row.div_ceil(WORKGROUP), rows - 1, 1);
            }
            self.queue.submit([encoder.finish()]);
            take_errors(&self.errors)?;
            row0 += rows - 1;
        }
        let mut encoder = device.create_command_encoder(&wgpu::CommandEncoderDescriptor {
            label: Some("raster readback"),
        });
        encoder.copy_buffer_to_buffer(&bits, 0, &staging, 0, bits_bytes);
        self.queue.submit([encoder.finish()]);
        let slice = staging.slice(..);
        let (tx, rx) = mpsc::channel();
        slice.map_async(wgpu::MapMode::Read, move |r| {
            // The receiver outlives the poll below; a send error cannot be acted on.
            let _ = tx.send(r);
        });
        device
            .poll(wgpu::PollType::wait_indefinitely())
            .map_err(|e| RasterError::Gpu(format!("waiting for the device: {e}")))?;
        take_errors(&self.errors)?;
        match rx.recv() {
            Ok(Ok(())) => {}
            Ok(Err(e)) => return Err(RasterError::Gpu(format!("mapping the result: {e}"))),
            Err(_) => return Err(RasterError::Gpu("mapping callback never ran".to_string())),
        }
        let (cells, resolved) = {
            let view = slice.get_mapped_range();
            let words: &[u32] = bytemuck::cast_slice(&view);
            unpack_cells(p, q, grid, words, words_per_row as usize)
        };
        staging.unmap();
        let out = RasterOutput {
            cells,
            precision: self.precision,
            backend: BackendUsed::Gpu {
                adapter: self.adapter.clone(),
                software: self.software,
            },
        };
        Ok((out, resolved))
    }
}

/// Lists the cells of the read-back words (`[candidates, uncertain]` per 32 cells), sorted by
/// `(j, i)`. A cell with an uncertain corner (a value within the error bound of 0) is decided
/// on the CPU from [`DensePoly2::eval`] at its four corners; the others take the GPU's bit.
/// Also returns the number of cells decided on the CPU.
fn unpack_cells(
    p: &DensePoly2,
    q: &DensePoly2,
    grid: &Grid,
    words: &[u32],
    words_per_row: usize,
) -> (Vec<Cell>, usize) {
    let cells_per_row = grid.n - 1;
    let code = |i: u32, j: u32| {
        let (x, y) = (grid.x(i), grid.y(j));
        node_code(p.eval(x, y), q.eval(x, y))
    };
    let mut cells = Vec::new();
    let mut resolved = 0;
    for (j, row) in words.chunks_exact(2 * words_per_row).enumerate() {
        let j = j as u32;
        for (w, pair) in row.chunks_exact(2).enumerate() {
            let (cand, unsure) = (pair[0], pair[1]);
            let mut word = cand | unsure;
            while word != 0 {
                let b = word.trailing_zeros();
                word &= word - 1;
                let i = (w as u32) * 32 + b;
                if i >= cells_per_row {
                    break;
                }
                let listed = if unsure & (1 << b) != 0 {
                    resolved += 1;
                    is_candidate(
                        code(i, j),
                        code(i + 1, j),
                        code(i, j + 1),
                        code(i + 1, j + 1),
                    )
                } else {
                    true
                };
                if listed {
                    cells.push(Cell { i, j });
                }
            }
        }
    }
    (cells, resolved)
}

/// Unit roundoff `u` and coefficient padding `δ` of the shader's error bound. A node value `v`
/// counts as certain when `|v| > c · Σ (|a_ij| + δ) |x|^i |y|^j` (the sum evaluated by the same
/// Horner scheme, `c` from [`error_factor`]): `c = (8K + 16) u` is twice `4K u ≥ 2 γ_{2K}` (the
/// worst-case distance between a fused CPU value and an unfused GPU value, Horner error bound),
/// the padding `δ` (times `c`, ≥ 2^-1021 (8K + 16) per term in `f64`) covers underflow, even
/// with subnormals flushed to zero (≤ 2^-1022 per operation).
fn bound_constants(precision: Precision) -> (f64, f64) {
    match precision {
        Precision::F64 => (2f64.powi(-53), 2f64.powi(-968)),
        Precision::F32 => (2f64.powi(-24), 2f64.powi(-96)),
    }
}

/// The factor `c = (8K + 16) u`, `K` the larger total degree `deg_x + deg_y` of `p` and `q`.
fn error_factor(p: &DensePoly2, q: &DensePoly2, precision: Precision) -> f64 {
    let (unit, _) = bound_constants(precision);
    let k = (p.deg_x + p.deg_y).max(q.deg_x + q.deg_y) as f64;
    (8.0 * k + 16.0) * unit
}

/// The cached context, created on first use (a failure is cached too: no retry per call).
fn context() -> Result<&'static Context, RasterError> {
    CONTEXT
        .get_or_init(|| {
            catch_unwind(Context::new).unwrap_or_else(|_| {
                Err(RasterError::NoAdapter(
                    "wgpu panicked while creating the device".to_string(),
                ))
            })
        })
        .as_ref()
        .map_err(Clone::clone)
}

/// [`super::raster_gpu`] after input validation, with a node-code budget of `band_bytes` per
/// band (tests lower it to force several bands).
pub(super) fn raster(
    p: &DensePoly2,
    q: &DensePoly2,
    grid: &Grid,
    band_bytes: u64,
) -> Result<RasterOutput, RasterError> {
    raster_counted(p, q, grid, band_bytes).map(|(out, _)| out)
}

/// [`raster`], also returning how many cells were decided on the CPU (uncertain corners).
/// Inputs whose values might overflow the shader's arithmetic go to the CPU backend entirely
/// (the output then says [`BackendUsed::Cpu`]).
fn raster_counted(
    p: &DensePoly2,
    q: &DensePoly2,
    grid: &Grid,
    band_bytes: u64,
) -> Result<(RasterOutput, usize), RasterError> {
    let ctx = context()?;
    if ctx.may_overflow(p, q, grid) {
        let out = cpu::raster(p, q, grid);
        let all = out.cells.len();
        return Ok((out, all));
    }
    match catch_unwind(AssertUnwindSafe(|| ctx.run(p, q, grid, band_bytes))) {
        Ok(result) => result,
        Err(_) => Err(RasterError::Gpu(
            "wgpu panicked during the raster".to_string(),
        )),
    }
}

#[cfg(test)]
mod tests {
    use super::super::{raster_cpu, DensePoly2, Grid};
    use super::*;

    /// The GPU result, or `None` when there is no adapter and `LNCERT_REQUIRE_GPU` is not 1.
    fn gpu(
        p: &DensePoly2,
        q: &DensePoly2,
        grid: &Grid,
        band_bytes: u64,
    ) -> Option<(RasterOutput, usize)> {
        match raster_counted(p, q, grid, band_bytes) {
            Ok(out) => Some(out),
            Err(RasterError::NoAdapter(msg))
                if std::env::var("LNCERT_REQUIRE_GPU").as_deref() != Ok("1") =>
            {
                eprintln!("skipping GPU test: {msg}");
                None
            }
            Err(e) => panic!("GPU raster failed: {e}"),
        }
    }

    fn poly(dx: usize, dy: usize, c: Vec<f64>) -> DensePoly2 {
        DensePoly2::new(dx, dy, c).expect("valid test polynomial")
    }

    /// Several bands (2, 3, 7, ... node rows per band) give the same cells as the CPU raster,
    /// and almost no cell needs the CPU (the uncertainty test is not trivially always on).
    #[test]
    fn bands_match_cpu() {
        // p = x^2 + y^2 - 0.8 (circle), q = x y^3 - 0.1 + 0.3 x^3 (curve through it).
        let p = poly(2, 2, vec![-0.8, 0.0, 1.0, 0.0, 0.0, 0.0, 1.0, 0.0, 0.0]);
        let mut qc = vec![0.0; 16];
        qc[0] = -0.1;
        qc[4 + 3] = 1.0;
        qc[12] = 0.3;
        let q = poly(3, 3, qc);
        let grid = Grid {
            n: 203,
            x_lo: -1.3,
            x_hi: 1.1,
            y_lo: -1.2,
            y_hi: 1.25,
        };
        let cpu = raster_cpu(&p, &q, &grid).expect("valid input");
        assert!(cpu.cells.len() >= 4, "{:?}", cpu.cells);
        for rows in [2u64, 3, 7, 64, 202, 203] {
            let Some((out, resolved)) = gpu(&p, &q, &grid, rows * 4 * u64::from(grid.n)) else {
                return;
            };
            if out.precision == Precision::F64 {
                assert_eq!(out.cells, cpu.cells, "band of {rows} node rows");
                assert!(resolved <= 2, "{resolved} cells decided on the CPU");
            } else {
                // f32 shaders: only approximately the f64 raster.
                assert!(!out.cells.is_empty());
                for c in &out.cells {
                    assert!(
                        cpu.cells
                            .iter()
                            .any(|d| c.i.abs_diff(d.i).max(c.j.abs_diff(d.j)) <= 2),
                        "f32 cell {c:?} far from the f64 raster (band of {rows} rows)"
                    );
                }
            }
        }
    }

    /// A node value that is exactly the rounding error of t·t (p = x^2 - fl(t^2) at x = t) is
    /// flagged uncertain and decided on the CPU.
    #[test]
    fn near_zero_nodes_go_to_the_cpu() {
        let grid = Grid {
            n: 33,
            x_lo: 0.3,
            x_hi: 1.1,
            y_lo: 0.3,
            y_hi: 1.1,
        };
        // A node t with t·t inexact, so that the fused value t^2 - fl(t^2) is not 0.
        let Some(k) =
            (5..25).find(|&k| grid.x(k).mul_add(grid.x(k), -(grid.x(k) * grid.x(k))) != 0.0)
        else {
            panic!("no node with an inexact square");
        };
        let t = grid.x(k);
        let p = poly(2, 0, vec![-(t * t), 0.0, 1.0]);
        let q = poly(0, 1, vec![-0.5 * (grid.y(10) + grid.y(11)), 1.0]);
        let cpu = raster_cpu(&p, &q, &grid).expect("valid input");
        if let Some((out, resolved)) = gpu(&p, &q, &grid, BAND_BYTES) {
            if out.precision == Precision::F64 {
                assert_eq!(out.cells, cpu.cells);
                assert!(resolved >= 1, "the node x_{k} should be uncertain");
            }
        }
    }

    /// Values that could overflow the shader's arithmetic are rastered on the CPU.
    #[test]
    fn huge_values_fall_back_to_the_cpu() {
        let p = poly(1, 1, vec![-1e305, 1e305, 1e305, 0.0]);
        let q = poly(1, 1, vec![0.5e305, -1e305, 1e305, 0.0]);
        let grid = Grid {
            n: 40,
            x_lo: -2.0,
            x_hi: 2.0,
            y_lo: -2.0,
            y_hi: 2.0,
        };
        let cpu = raster_cpu(&p, &q, &grid).expect("valid input");
        assert!(!cpu.cells.is_empty());
        if let Some((out, _)) = gpu(&p, &q, &grid, BAND_BYTES) {
            assert_eq!(out.backend, BackendUsed::Cpu);
            assert_eq!(out.cells, cpu.cells);
        }
    }

    /// Horner as in the shader, each step fused or not by `fuse(step)`.
    fn horner_mixed(
        coeffs: &[f64],
        dx: usize,
        dy: usize,
        x: f64,
        y: f64,
        fuse: &mut dyn FnMut() -> bool,
    ) -> f64 {
        let mut step = |a: f64, b: f64, c: f64| if fuse() { a.mul_add(b, c) } else { a * b + c };
        let w = dy + 1;
        let mut r = 0.0;
        for i in (0..=dx).rev() {
            let mut c = coeffs[i * w + dy];
            for j in (0..dy).rev() {
                c = step(c, y, coeffs[i * w + j]);
            }
            r = if i == dx { c } else { step(r, x, c) };
        }
        r
    }

    /// Soundness of the uncertainty test, independent of any GPU: on values pushed next to 0
    /// (the constant term adjusted so that p(x, y) nearly cancels), a value that any mix of
    /// fused and unfused steps computes and that passes the test `|v| > c · S` has the sign
    /// of the fused (CPU) value, where S is itself computed with a mix of steps.
    #[test]
    fn uncertainty_test_is_sound() {
        let mut s: u64 = 5;
        let mut next = move || {
            s = s
                .wrapping_mul(6364136223846793005)
                .wrapping_add(1442695040888963407);
            s >> 11
        };
        let mut certain_near_zero = 0;
        for case in 0..20_000 {
            let (dx, dy) = ((next() % 11) as usize, (next() % 11) as usize);
            let unit = |v: u64| (v as f64 / (1u64 << 53) as f64) * 2.0 - 1.0;
            let mut coeffs: Vec<f64> = (0..(dx + 1) * (dy + 1))
                .map(|_| unit(next()) * 2f64.powi((next() % 7) as i32 - 3))
                .collect();
            let (x, y) = (unit(next()) * 2.0, unit(next()) * 2.0);
            let p0 = DensePoly2::new(dx, dy, coeffs.clone()).expect("finite");
            coeffs[0] -= p0.eval(x, y);
            if case % 3 == 0 {
                coeffs[0] -= p0.eval(x, y) * 2f64.powi(-50);
            }
            let p = DensePoly2::new(dx, dy, coeffs.clone()).expect("finite");
            let cpu = p.eval(x, y);
            let (_, delta) = bound_constants(Precision::F64);
            let c = error_factor(&p, &p, Precision::F64);
            let abs: Vec<f64> = coeffs.iter().map(|a| a.abs() + delta).collect();
            for mode in 0..3u64 {
                let mut bits = next();
                let mut fuse = || match mode {
                    0 => true,
                    1 => false,
                    _ => {
                        bits = bits.rotate_left(1);
                        bits & 1 == 1
                    }
                };
                let v = horner_mixed(&coeffs, dx, dy, x, y, &mut fuse);
                let sum = horner_mixed(&abs, dx, dy, x.abs(), y.abs(), &mut fuse);
                if v.abs() > c * sum {
                    assert_eq!(
                        v > 0.0,
                        cpu > 0.0,
                        "case {case} mode {mode}: v = {v:e}, cpu = {cpu:e}, bound {:e}",
                        c * sum
                    );
                    assert!(cpu != 0.0);
                    if v.abs() < 1e-12 {
                        certain_near_zero += 1;
                    }
                }
            }
        }
        // The test is not vacuous: many tiny values are still decided on the device.
        assert!(certain_near_zero > 200, "{certain_near_zero}");
    }

    /// The `f32` shader (forced on this adapter) compiles, runs, reports `F32`, and its cells
    /// stay within 2 cells of the `f64` raster on a well-conditioned pair.
    #[test]
    fn f32_shader_approximates() {
        let ctx = match Context::new_with(true) {
            Ok(ctx) => ctx,
            Err(RasterError::NoAdapter(msg))
                if std::env::var("LNCERT_REQUIRE_GPU").as_deref() != Ok("1") =>
            {
                eprintln!("skipping GPU test: {msg}");
                return;
            }
            Err(e) => panic!("GPU context failed: {e}"),
        };
        let p = poly(2, 2, vec![-0.8, 0.0, 1.0, 0.0, 0.0, 0.0, 1.0, 0.0, 0.0]);
        let q = poly(1, 1, vec![0.05, 1.0, -2.0, 0.0]);
        let grid = Grid {
            n: 301,
            x_lo: -1.3,
            x_hi: 1.1,
            y_lo: -1.2,
            y_hi: 1.25,
        };
        let cpu = raster_cpu(&p, &q, &grid).expect("valid input");
        assert!(cpu.cells.len() >= 2);
        let (out, _) = ctx.run(&p, &q, &grid, BAND_BYTES).expect("GPU run");
        assert_eq!(out.precision, Precision::F32);
        assert!(!out.cells.is_empty());
        let near = |c: &Cell, list: &[Cell]| {
            list.iter()
                .any(|d| c.i.abs_diff(d.i).max(c.j.abs_diff(d.j)) <= 2)
        };
        for c in &out.cells {
            assert!(
                near(c, &cpu.cells),
                "f32 cell {c:?} far from the f64 raster"
            );
        }
        for c in &cpu.cells {
            assert!(
                near(c, &out.cells),
                "f64 cell {c:?} missed by the f32 raster"
            );
        }
    }
}
