//! A user's float geometry code, checked by lncert in its tests: the classic
//! cubic approximation of a quarter circle, and de Casteljau evaluation.

/// The control points of the cubic that approximates the quarter circle of
/// radius `r` about the origin from `(r, 0)` to `(0, r)`, with the usual
/// constant `k = 4(√2 − 1)/3`. Claimed error: at most `2.8e-4 · r`.
pub fn quarter_circle_cubic(r: f64) -> [[f64; 2]; 4] {
    let k = 4.0 * (std::f64::consts::SQRT_2 - 1.0) / 3.0 * r;
    [[r, 0.0], [r, k], [k, r], [0.0, r]]
}

/// The claimed relative error of [`quarter_circle_cubic`].
pub const QUARTER_CIRCLE_CLAIM: f64 = 2.8e-4;

/// The point of the Bézier curve with control points `p` at `t`, by de
/// Casteljau in `f64`.
pub fn bezier_point(p: &[[f64; 2]], t: f64) -> [f64; 2] {
    let mut v = p.to_vec();
    for n in (1..v.len()).rev() {
        for i in 0..n {
            v[i] = [
                v[i][0] + t * (v[i + 1][0] - v[i][0]),
                v[i][1] + t * (v[i + 1][1] - v[i][1]),
            ];
        }
    }
    v[0]
}
