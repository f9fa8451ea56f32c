// Raster of two bivariate polynomials (seed 003 §4.2), lncert::tangency::raster.
//
// `REAL` is replaced by `f64` (devices with SHADER_F64) or `f32` before compilation.
// Every multiply-add is an explicit fma(): it must round exactly like f64::mul_add on the CPU,
// and a compiler may contract or not contract a plain `a * b + c`.

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
    pad0: u32,
    pad1: u32,
}

@group(0) @binding(0) var<uniform> params: Params;
// [x_lo, step_x, y_lo, step_y, p coefficients..., q coefficients...]
@group(0) @binding(1) var<storage, read> data: array<real>;
// Sign code per node of the band: bit 0 = p > 0, bit 1 = q > 0.
@group(0) @binding(2) var<storage, read_write> codes: array<u32>;
// One candidate bit per cell of the whole grid, row-major.
@group(0) @binding(3) var<storage, read_write> bits: array<u32>;

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

// p(x, y) exactly as DensePoly2::eval: inner Horner over y per power of x, outer Horner over x.
fn eval_poly(off: u32, dx: u32, dy: u32, x: real, y: real) -> real {
    let stride = dy + 1u;
    var r: real = inner(off + dx * stride, dy, y);
    var i: u32 = dx;
    loop {
        if i == 0u {
            break;
        }
        i = i - 1u;
        r = fma(r, x, inner(off + i * stride, dy, y));
    }
    return r;
}

// Pass 1: sign codes of the nodes (i, row0 + r), r < rows.
@compute @workgroup_size(64, 1, 1)
fn node_codes(@builtin(global_invocation_id) gid: vec3<u32>) {
    let i = gid.x;
    let r = gid.y;
    if i >= params.n || r >= params.rows {
        return;
    }
    let j = params.row0 + r;
    let x = fma(data[1], real(i), data[0]);
    let y = fma(data[3], real(j), data[2]);
    let pv = eval_poly(params.p_off, params.p_dx, params.p_dy, x, y);
    let qv = eval_poly(params.q_off, params.q_dx, params.q_dy, x, y);
    codes[r * params.n + i] = select(0u, 1u, pv > real(0.0)) | select(0u, 2u, qv > real(0.0));
}

// Pass 2: the 2 x 2 mask. One invocation packs 32 cells of cell row row0 + r.
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
    var word: u32 = 0u;
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
            word = word | (1u << b);
        }
    }
    bits[(params.row0 + r) * params.words_per_row + w] = word;
}
