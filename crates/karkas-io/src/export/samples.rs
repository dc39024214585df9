//! How many samples a result is written with by default, and uniform sampling over a domain.

use karkas::{Curve, Point, Point3, Surface};

/// The largest number of samples one request writes (a guard against a mistyped count
/// exhausting memory).
pub const MAX_SAMPLES: usize = 50_000_000;

/// The default number of curve samples for `k` input points: 10 per point, at least 200.
pub fn default_curve_samples(k: usize) -> usize {
    (10 * k).max(200)
}

/// The default number of surface samples along a direction with `k` grid lines: 4 per line,
/// at least 50.
pub fn default_surface_samples(k: usize) -> usize {
    (4 * k).max(50)
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
    }
}
