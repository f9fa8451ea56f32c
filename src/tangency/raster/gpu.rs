//! The wgpu backend of [`super::raster_gpu`]: a process-wide cached device with the two compute
//! pipelines of `raster.wgsl` (pass 1 `node_codes`, pass 2 `cell_mask`).

use super::{unpack_cells, BackendUsed, DensePoly2, Grid, Precision, RasterError, RasterOutput};
use std::panic::{catch_unwind, AssertUnwindSafe};
use std::sync::{mpsc, Arc, Mutex, OnceLock};
use wgpu::util::DeviceExt;

/// Largest node-code buffer of one band (64 MiB): a band holds `BAND_BYTES / (4 n)` node rows
/// (1024 rows at `n = 16384`, the whole grid at `n = 1024`).
pub(super) const BAND_BYTES: u64 = 64 << 20;

/// Workgroup width of both entry points in `raster.wgsl`.
const WORKGROUP: u32 = 64;

/// The WGSL template; `REAL` becomes `f64` or `f32`.
const SHADER: &str = include_str!("raster.wgsl");

/// Device, queue and pipelines, created once per process.
struct Context {
    device: wgpu::Device,
    queue: wgpu::Queue,
    layout: wgpu::BindGroupLayout,
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
        let f64_ok = adapter.features().contains(wgpu::Features::SHADER_F64);
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
        let codes_pipeline = pipeline("node_codes");
        let mask_pipeline = pipeline("cell_mask");
        take_errors(&errors)?;
        Ok(Context {
            device,
            queue,
            layout,
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

    /// The shader's `data` array: `[x_lo, step_x, y_lo, step_y, p..., q...]` as little-endian
    /// bytes of `f64` or `f32`.
    fn data_bytes(&self, p: &DensePoly2, q: &DensePoly2, grid: &Grid) -> Vec<u8> {
        let values: Vec<f64> = [grid.x_lo, grid.step_x(), grid.y_lo, grid.step_y()]
            .into_iter()
            .chain(p.coeffs.iter().copied())
            .chain(q.coeffs.iter().copied())
            .collect();
        match self.precision {
            Precision::F64 => bytemuck::cast_slice(&values).to_vec(),
            Precision::F32 => {
                let v32: Vec<f32> = values.iter().map(|&v| v as f32).collect();
                bytemuck::cast_slice(&v32).to_vec()
            }
        }
    }

    /// Runs both passes band by band (at most `band_bytes` of node codes per band) and returns
    /// the candidate cells sorted by `(j, i)`.
    fn run(
        &self,
        p: &DensePoly2,
        q: &DensePoly2,
        grid: &Grid,
        band_bytes: u64,
    ) -> Result<RasterOutput, RasterError> {
        let _guard = self.call.lock().unwrap_or_else(|e| e.into_inner());
        take_errors(&self.errors)?;
        let n = grid.n;
        let n64 = u64::from(n);
        let cell_rows = n - 1;
        let words_per_row = cell_rows.div_ceil(32);
        let bits_bytes = u64::from(cell_rows) * u64::from(words_per_row) * 4;
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
        let data = device.create_buffer_init(&wgpu::util::BufferInitDescriptor {
            label: Some("raster data"),
            contents: &self.data_bytes(p, q, grid),
            usage: wgpu::BufferUsages::STORAGE,
        });
        let params = device.create_buffer(&wgpu::BufferDescriptor {
            label: Some("raster params"),
            size: 48,
            usage: wgpu::BufferUsages::UNIFORM | wgpu::BufferUsages::COPY_DST,
            mapped_at_creation: false,
        });
        let codes = device.create_buffer(&wgpu::BufferDescriptor {
            label: Some("raster codes"),
            size: codes_bytes,
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
            ],
        });
        let p_off = 4u32;
        let q_off = p_off + p.coeffs.len() as u32;
        let mut row0 = 0u32;
        while row0 < cell_rows {
            // Node rows row0 ..= row0 + rows - 1, cell rows row0 .. row0 + rows - 1.
            let rows = band_rows.min(n - row0);
            let words: [u32; 12] = [
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
        let cells = {
            let view = slice.get_mapped_range();
            let words: &[u32] = bytemuck::cast_slice(&view);
            unpack_cells(words, words_per_row as usize, cell_rows)
        };
        staging.unmap();
        Ok(RasterOutput {
            cells,
            precision: self.precision,
            backend: BackendUsed::Gpu {
                adapter: self.adapter.clone(),
                software: self.software,
            },
        })
    }
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
    let ctx = context()?;
    catch_unwind(AssertUnwindSafe(|| ctx.run(p, q, grid, band_bytes))).unwrap_or_else(|_| {
        Err(RasterError::Gpu(
            "wgpu panicked during the raster".to_string(),
        ))
    })
}

#[cfg(test)]
mod tests {
    use super::super::{raster_cpu, DensePoly2, Grid};
    use super::*;

    /// Several bands (a budget of 7 node rows) give the same cells as the CPU raster.
    #[test]
    fn bands_match_cpu() {
        // p = x^2 + y^2 - 0.8 (circle), q = x y^3 - 0.1 + 0.3 x^3 (curve through it).
        let p = DensePoly2::new(2, 2, vec![-0.8, 0.0, 1.0, 0.0, 0.0, 0.0, 1.0, 0.0, 0.0]);
        let q = DensePoly2::new(
            3,
            3,
            vec![
                -0.1, 0.0, 0.0, 0.0, //
                0.0, 0.0, 0.0, 1.0, //
                0.0, 0.0, 0.0, 0.0, //
                0.3, 0.0, 0.0, 0.0,
            ],
        );
        let (Ok(p), Ok(q)) = (p, q) else {
            panic!("test polynomials are valid");
        };
        let grid = Grid {
            n: 203,
            x_lo: -1.3,
            x_hi: 1.1,
            y_lo: -1.2,
            y_hi: 1.25,
        };
        let cpu = raster_cpu(&p, &q, &grid).expect("valid input");
        assert!(!cpu.cells.is_empty());
        for rows in [2u64, 3, 7, 64, 202, 203] {
            match raster(&p, &q, &grid, rows * 4 * u64::from(grid.n)) {
                Ok(out) if out.precision == Precision::F64 => {
                    assert_eq!(out.cells, cpu.cells, "band of {rows} node rows");
                }
                Ok(out) => {
                    // f32 shaders: only approximately the f64 raster; every cell must lie
                    // within 2 cells of an f64 candidate.
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
                Err(RasterError::NoAdapter(msg))
                    if std::env::var("LNCERT_REQUIRE_GPU").as_deref() != Ok("1") =>
                {
                    eprintln!("skipping GPU band test: {msg}");
                    return;
                }
                Err(e) => panic!("GPU raster failed: {e}"),
            }
        }
    }
}
