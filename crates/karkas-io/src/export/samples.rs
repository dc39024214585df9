//! How many samples a result is written with by default, and uniform sampling over a domain.

use karkas::{Curve, Point, Point3, Surface};

/// The largest number of samples one request writes (a guard against a mistyped count
/// exhausting memory).
pub const MAX_SAMPLES: usize = 50_000_000;

/// The most curve samples written by default ([`default_curve_samples`]): more are written
/// only when asked for (`--samples`, `samples=`), so that a dense input does not write ten
/// times its size unasked.
pub const DEFAULT_CURVE_SAMPLES_BOUND: usize = 100_000;

/// The most surface samples along a direction written by default
/// ([`default_surface_samples`]; a million samples in all).
pub const DEFAULT_SURFACE_SAMPLES_BOUND: usize = 1000;

/// The default number of curve samples for `k` input points: 10 per point, at least 200, at
/// most [`DEFAULT_CURVE_SAMPLES_BOUND`].
pub fn default_curve_samples(k: usize) -> usize {
    unbounded_curve_samples(k).min(DEFAULT_CURVE_SAMPLES_BOUND)
}

/// 10 samples per input point of `k`, at least 200: the default before its bound.
pub fn unbounded_curve_samples(k: usize) -> usize {
    k.saturating_mul(10).max(200)
}

/// The default number of surface samples along a direction with `k` grid lines: 4 per line,
/// at least 50, at most [`DEFAULT_SURFACE_SAMPLES_BOUND`].
pub fn default_surface_samples(k: usize) -> usize {
    unbounded_surface_samples(k).min(DEFAULT_SURFACE_SAMPLES_BOUND)
}

/// 4 samples per grid line of `k`, at least 50: the default before its bound.
pub fn unbounded_surface_samples(k: usize) -> usize {
    k.saturating_mul(4).max(50)
}

/// `n` samples of `curve`, uniform over its domain, ends included: the parameters and points.
pub fn sample_curve<const D: usize>(curve: &impl Curve<D>, n: usize) -> (Vec<f64>, Vec<Point<D>>) {
    let (mut ts, mut points) = (vec![0.0; n], vec![Point::ZERO; n]);
    curve.sample_into(&mut ts, &mut points);
    (ts, points)
}

/// `nu x nv` samples of `surface`, uniform over its domain, ends included: the parameters
/// `u`, `v` and the points (row-major, `u` outer).
pub fn sample_surface(
    surface: &impl Surface<3>,
    nu: usize,
    nv: usize,
) -> (Vec<f64>, Vec<f64>, Vec<Point3>) {
    let (mut us, mut vs) = (vec![0.0; nu], vec![0.0; nv]);
    let mut points = vec![Point3::ZERO; nu * nv];
    surface.sample_grid_into(&mut us, &mut vs, &mut points);
    (us, vs, points)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn default_counts() {
        assert_eq!(default_curve_samples(5), 200);
        assert_eq!(default_curve_samples(53), 530);
        assert_eq!(default_surface_samples(5), 50);
        assert_eq!(default_surface_samples(31), 124);
        assert_eq!(
            default_curve_samples(2_000_000),
            DEFAULT_CURVE_SAMPLES_BOUND
        );
        assert_eq!(unbounded_curve_samples(2_000_000), 20_000_000);
        assert_eq!(default_surface_samples(2000), DEFAULT_SURFACE_SAMPLES_BOUND);
    }
}
