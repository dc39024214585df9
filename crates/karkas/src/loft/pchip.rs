//! Fritsch and Carlson's shape-preserving slopes of a piecewise cubic Hermite interpolant
//! (docs/methods.md §7.3), as SciPy's `PchipInterpolator` chooses them: the slopes every
//! quantity of the monotone spanwise rule is interpolated with.
//!
//! Hand-written: a few lines; no maintained Rust crate gives the slopes alone.

/// The slopes of the shape-preserving piecewise cubic Hermite interpolant of `(x, y)`
/// (Fritsch and Carlson's, with SciPy's `PchipInterpolator` choices: the weighted harmonic
/// mean of the neighbouring secants inside, zero where they differ in sign, and the
/// shape-preserving three-point formula at the ends; the secant for two points).
pub fn pchip_slopes(x: &[f64], y: &[f64], out: &mut [f64]) {
    let n = x.len();
    debug_assert!(n >= 2 && y.len() == n && out.len() == n);
    let h: Vec<f64> = x.windows(2).map(|w| w[1] - w[0]).collect();
    let delta: Vec<f64> = (0..n - 1).map(|k| (y[k + 1] - y[k]) / h[k]).collect();
    pchip_from_secants(&h, &delta, out);
}

/// [`pchip_slopes`] from the steps `h` between the stations and the secants `delta` over
/// them (one fewer than the stations; `out` one per station).
pub(crate) fn pchip_from_secants(h: &[f64], delta: &[f64], out: &mut [f64]) {
    let n = h.len() + 1;
    debug_assert!(n >= 2 && delta.len() == n - 1 && out.len() == n);
    if n == 2 {
        out[0] = delta[0];
        out[1] = delta[0];
        return;
    }
    for k in 1..n - 1 {
        let (d0, d1) = (delta[k - 1], delta[k]);
        out[k] = if d0 * d1 <= 0.0 {
            0.0
        } else {
            let (h0, h1) = (h[k - 1], h[k]);
            let (w1, w2) = (2.0 * h1 + h0, h1 + 2.0 * h0);
            (w1 + w2) / (w1 / d0 + w2 / d1)
        };
    }
    let edge = |h0: f64, h1: f64, d0: f64, d1: f64| -> f64 {
        let d = ((2.0 * h0 + h1) * d0 - h0 * d1) / (h0 + h1);
        if d.signum() != d0.signum() || d0 == 0.0 {
            0.0
        } else if d0.signum() != d1.signum() && d.abs() > 3.0 * d0.abs() {
            3.0 * d0
        } else {
            d
        }
    };
    out[0] = edge(h[0], h[1], delta[0], delta[1]);
    out[n - 1] = edge(h[n - 2], h[n - 3], delta[n - 2], delta[n - 3]);
}
