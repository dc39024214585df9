//! What the CAD writers (the `step` and `iges` modules) write: exact B-spline
//! curves and surfaces of karkas (see [`karkas::bspline`]), in 3-D, and the number and knot
//! formatting both formats share.

use karkas::bspline::{BSplineCurve, BSplineSurface};
use karkas::Point;

use crate::error::IoError;
use crate::write::write_atomic;

/// One geometric item of a CAD file.
#[derive(Clone, Copy, Debug)]
pub enum CadEntity<'a> {
    /// A B-spline curve (in STEP: a `B_SPLINE_CURVE_WITH_KNOTS` in a wireframe
    /// representation; in IGES: entity 126).
    Curve(&'a BSplineCurve<3>),
    /// A B-spline surface (in STEP: a `B_SPLINE_SURFACE_WITH_KNOTS` as the face of an open
    /// shell, bounded by its four boundary curves; in IGES: entity 128).
    Surface(&'a BSplineSurface<3>),
}

/// A curve of dimension `D <= 3` in 3-D space (missing coordinates 0: a planar curve lies
/// in the plane `z = 0`), with the same degree and knots.
///
/// Errors: `D > 3` ([`CadError::TooManyDimensions`]); the library refusing the curve
/// ([`CadError::Geometry`]).
pub fn curve_in_space<const D: usize>(
    curve: &BSplineCurve<D>,
) -> Result<BSplineCurve<3>, CadError> {
    if D > 3 {
        return Err(CadError::TooManyDimensions { dimensions: D });
    }
    let control = curve
        .control_points()
        .iter()
        .map(|p| Point(core::array::from_fn(|c| if c < D { p[c] } else { 0.0 })))
        .collect();
    BSplineCurve::new(curve.degree(), curve.knots().to_vec(), control).map_err(CadError::Geometry)
}

/// Why a curve cannot be placed in a CAD file.
#[derive(Debug, thiserror::Error)]
#[non_exhaustive]
pub enum CadError {
    /// The curve has more than three coordinates.
    #[error("a curve in {dimensions} dimensions cannot be written to a CAD file (at most 3)")]
    TooManyDimensions {
        /// Its number of coordinates.
        dimensions: usize,
    },
    /// The library refused the curve in space.
    #[error("{0}")]
    Geometry(#[source] karkas::Error),
}

/// Writes the CAD file `path` atomically with the text `render(entities, name)`, `name` being
/// the file stem (`karkas` when it has none).
pub(crate) fn write_named(
    path: &std::path::Path,
    entities: &[CadEntity<'_>],
    render: fn(&[CadEntity<'_>], &str) -> String,
) -> Result<(), IoError> {
    let name = path
        .file_stem()
        .and_then(|s| s.to_str())
        .unwrap_or("karkas");
    let text = render(entities, name);
    write_atomic(path, |out| out.write_all(text.as_bytes()))
}

/// A real number with 17 significant digits (round-trips every `f64`) and an exponent, with
/// the decimal point that STEP and IGES require: `-1.2345678901234567E-3`.
pub(crate) fn real(x: f64) -> String {
    let x = if x == 0.0 { 0.0 } else { x }; // no "-0"
    format!("{x:.16E}")
}

/// The distinct values of a sorted knot vector and their multiplicities.
pub(crate) fn knot_runs(knots: &[f64]) -> (Vec<f64>, Vec<usize>) {
    let mut values: Vec<f64> = Vec::new();
    let mut counts: Vec<usize> = Vec::new();
    for &k in knots {
        if values.last() == Some(&k) {
            if let Some(c) = counts.last_mut() {
                *c += 1;
            }
        } else {
            values.push(k);
            counts.push(1);
        }
    }
    (values, counts)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn reals_round_trip_and_carry_a_point() {
        for x in [
            0.0,
            -0.0,
            1.0,
            -2.5e-300,
            1.0 / 3.0,
            123456789.123,
            f64::MAX,
        ] {
            let s = real(x);
            assert!(s.contains('.') && s.contains('E'), "{s}");
            assert_eq!(s.parse::<f64>().unwrap(), x);
        }
        assert_eq!(real(-0.0), "0.0000000000000000E0");
    }

    #[test]
    fn knot_runs_count_multiplicities() {
        let (v, m) = knot_runs(&[0.0, 0.0, 0.0, 0.5, 0.5, 1.0, 1.0, 1.0]);
        assert_eq!(v, vec![0.0, 0.5, 1.0]);
        assert_eq!(m, vec![3, 2, 3]);
    }
}
