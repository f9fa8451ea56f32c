// Raster of two bivariate polynomials (seed 003 §4.2), lncert::tangency::raster.
//
// `REAL` is replaced by `f64` (devices with SHADER_F64) or `f32` before compilation.
// Values are computed as DensePoly2::eval does (inner Horner in y per power of x, outer Horner
// in x, one fma() per step). Vulkan allows fma() to be evaluated unfused (Mesa's llvmpipe does),
// so the shader also evaluates the a-priori Horner error bound and flags every node whose value
// is not clearly away from zero; the CPU re-evaluates the cells touching such nodes.

alias real = REAL;

struct Params {
    n: u32,             // nodes per axis
    row0: u32,          // first node row of this band
    rows: u32,          // node rows in this band (cell rows: rows - 1)
    words_per_row: u32, // packed candidate words per cell row
    p_dx: u32,
    p_dy: u32,
    p_off: u32,         // offset of p's coefficients in `data`
    q_dx: u32,
    q_dy: u32,
    q_off: u32,
    pa_off: u32,        // offset of |p| coefficients (padded, see gpu.rs)
    qa_off: u32,        // offset of |q| coefficients (padded)
    ys_off: u32,        // offset of the node ordinates (abscissae start at 0)
    c_off: u32,         // offset of the error-bound factor
    pad0: u32,
    pad1: u32,
}

@group(0) @binding(0) var<uniform> params: Params;
// [x_0..x_{n-1}, y_0..y_{n-1}, p, q, |p|, |q|, error factor]
@group(0) @binding(1) var<storage, read> data: array<real>;
// Node code of the band: bit 0 = p > 0, bit 1 = q > 0, bit 2 = p uncertain, bit 3 = q uncertain.
@group(0) @binding(2) var<storage, read_write> codes: array<u32>;
// Per cell row and word: [candidate bits, uncertain bits], row-major over the whole grid.
@group(0) @binding(3) var<storage, read_write> bits: array<u32>;
// Inner Horner values per node row of the band (pass 0), `inner_stride()` per row:
// [p_0..p_dx, q_0..q_dx, |p|_0..|p|_dx, |q|_0..|q|_dx].
@group(0) @binding(4) var<storage, read_write> inner_vals: array<real>;

// Inner Horner in y of the coefficient row starting at `base` (dy + 1 coefficients).
fn inner(base: u32, dy: u32, y: real) -> real {
    var c: real = data[base + dy];
    var j: u32 = dy;
    loop {
        if j == 0u {
            break;
        }
        j = j - 1u;
        c = fma(c, y, data[base + j]);
    }
    return c;
}

fn inner_count() -> u32 {
    return params.p_dx + params.q_dx + 2u;
}

fn inner_stride() -> u32 {
    return 2u * inner_count();
}

// Pass 0: the inner Horner values of every node row of the band (they depend on y only).
@compute @workgroup_size(64, 1, 1)
fn row_inner(@builtin(global_invocation_id) gid: vec3<u32>) {
    let k = gid.x;
    let r = gid.y;
    if k >= inner_stride() || r >= params.rows {
        return;
    }
    let y = data[params.ys_off + params.row0 + r];
    let half = inner_count();
    let abs_part = k >= half;
    var kk = k;
    var yy = y;
    var p_base = params.p_off;
    var q_base = params.q_off;
    if abs_part {
        kk = k - half;
        yy = abs(y);
        p_base = params.pa_off;
        q_base = params.qa_off;
    }
    var c: real;
    if kk <= params.p_dx {
        c = inner(p_base + kk * (params.p_dy + 1u), params.p_dy, yy);
    } else {
        let i = kk - params.p_dx - 1u;
        c = inner(q_base + i * (params.q_dy + 1u), params.q_dy, yy);
    }
    inner_vals[r * inner_stride() + k] = c;
}

// Outer Horner over inner_vals[base ..= base + dx].
fn outer(base: u32, dx: u32, x: real) -> real {
    var r: real = inner_vals[base + dx];
    var i: u32 = dx;
    loop {
        if i == 0u {
            break;
        }
        i = i - 1u;
        r = fma(r, x, inner_vals[base + i]);
    }
    return r;
}

// Pass 1: sign codes of the nodes (i, row0 + r), r < rows, with uncertainty flags.
@compute @workgroup_size(64, 1, 1)
fn node_codes(@builtin(global_invocation_id) gid: vec3<u32>) {
    let i = gid.x;
    let r = gid.y;
    if i >= params.n || r >= params.rows {
        return;
    }
    let x = data[i];
    let ax = abs(x);
    let half = inner_count();
    let pb = r * inner_stride();
    let qb = pb + params.p_dx + 1u;
    let pv = outer(pb, params.p_dx, x);
    let qv = outer(qb, params.q_dx, x);
    let ps = outer(pb + half, params.p_dx, ax);
    let qs = outer(qb + half, params.q_dx, ax);
    let c = data[params.c_off];
    var code: u32 = select(0u, 1u, pv > real(0.0)) | select(0u, 2u, qv > real(0.0));
    if !(abs(pv) > c * ps) {
        code = code | 4u;
    }
    if !(abs(qv) > c * qs) {
        code = code | 8u;
    }
    codes[r * params.n + i] = code;
}

// Pass 2: the 2 x 2 mask. One invocation packs 32 cells of cell row row0 + r: a candidate bit
// when both sign bits change over the corners, an uncertain bit when a corner is uncertain.
@compute @workgroup_size(64, 1, 1)
fn cell_mask(@builtin(global_invocation_id) gid: vec3<u32>) {
    let w = gid.x;
    let r = gid.y;
    if w >= params.words_per_row || r + 1u >= params.rows {
        return;
    }
    let n = params.n;
    let lower = r * n;
    let upper = lower + n;
    var cand: u32 = 0u;
    var unsure: u32 = 0u;
    for (var b: u32 = 0u; b < 32u; b = b + 1u) {
        let i = w * 32u + b;
        if i + 1u >= n {
            break;
        }
        let a = codes[lower + i];
        let c = codes[lower + i + 1u];
        let d = codes[upper + i];
        let e = codes[upper + i + 1u];
        let all = a & c & d & e;
        let any = a | c | d | e;
        if ((all ^ any) & 3u) == 3u {
            cand = cand | (1u << b);
        }
        if (any & 12u) != 0u {
            unsure = unsure | (1u << b);
        }
    }
    let at = 2u * ((params.row0 + r) * params.words_per_row + w);
    bits[at] = cand;
    bits[at + 1u] = unsure;
}
