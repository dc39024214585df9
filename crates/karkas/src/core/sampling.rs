//! Sampling helpers that write into caller-provided buffers.

use super::Interval;

/// Fills `out` with `out.len()` uniformly spaced values over `domain`, both ends included
/// (the last value is exactly `domain.end`; a single value is `domain.start`).
pub fn uniform_into(domain: Interval, out: &mut [f64]) {
    let n = out.len();
    for (k, t) in out.iter_mut().enumerate() {
        *t = domain.uniform(k, n);
    }
}

/// Panics unless an output buffer of `out` points matches `ts` parameters.
#[track_caller]
#[inline]
pub(crate) fn assert_buffer_len(ts: usize, out: usize) {
    assert_eq!(ts, out, "parameter and output buffers differ in length");
}

/// Panics unless an output buffer of `out` points holds the grid `us x vs`.
#[track_caller]
#[inline]
pub(crate) fn assert_grid_len(us: usize, vs: usize, out: usize) {
    assert_eq!(out, us * vs, "output buffer does not fit the grid");
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn ends_are_exact() {
        let mut ts = [0.0; 7];
        uniform_into(Interval::new(0.1, 0.9), &mut ts);
        assert_eq!(ts[0], 0.1);
        assert_eq!(ts[6], 0.9);
        for w in ts.windows(2) {
            assert!((w[1] - w[0] - 0.8 / 6.0).abs() < 1e-15);
        }
    }
}
