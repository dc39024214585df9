//! `Curve.fairness(points=None)` on every curve class: the library's fairness figures
//! ([`karkas::geometry::curve_fairness`]) as a dict with the keys of `karkas curve analyze
//! --json`.

use pyo3::prelude::*;
use pyo3::types::PyDict;

use crate::convert::PointsArray;
use crate::curve::PyCurve;
use crate::errors::PointsError;
use crate::limits::{bytes_of, check_memory};

/// Bytes the figures work in per piece of the curve (its samples and their derivatives).
const BYTES_PER_PIECE: u128 = 80 * 64;

#[pymethods]
impl PyCurve {
    /// How fair the curve is: the figures a designer reads off a curvature plot.
    ///
    /// Curvature extrema are the sign changes of dk/ds over dense samples of every polynomial
    /// piece, both one-sided limits at every breakpoint included (an extremum on a knot
    /// counts); values below ``1e-8 (k_max + 1/L) / L`` are rounding noise. Inflections are
    /// the sign changes of the signed curvature in 2-D, the zeros of the curvature in 3-D.
    /// The same figures as ``karkas curve analyze --json``.
    ///
    /// Parameters
    /// ----------
    /// points : array_like, shape (n, d), optional
    ///     The points the curve was made from: ``max_distance_to_polygon`` is the largest
    ///     distance of the curve from their polyline (closed for a closed curve).
    ///
    /// Returns
    /// -------
    /// dict
    ///     ``length``, ``curvature_min``, ``curvature_max``, ``curvature_extrema`` (int),
    ///     ``inflections`` (int), ``max_distance_to_polygon`` (None without points),
    ///     ``fairness_energy`` (the integral of (dk/ds)^2 over the arc length), ``pieces``
    ///     (int) and ``curvature_jump`` (the largest jump of the curvature at a breakpoint).
    ///
    /// Raises
    /// ------
    /// PointsError
    ///     When ``points`` is not (n, d) with the curve's d.
    ///
    /// Examples
    /// --------
    /// >>> import numpy as np, karkas
    /// >>> s = np.linspace(0, 2 * np.pi, 41)
    /// >>> c = karkas.CubicSpline(np.c_[2 * np.cos(s), 2 * np.sin(s)], t=s, bc="periodic")
    /// >>> f = c.fairness(c(s[:-1]))
    /// >>> f["inflections"], round(f["length"], 4), round(f["curvature_max"], 2)
    /// (0, 12.5664, 0.5)
    #[pyo3(signature = (points = None))]
    fn fairness<'py>(
        &self,
        py: Python<'py>,
        points: Option<&Bound<'py, PyAny>>,
    ) -> PyResult<Bound<'py, PyDict>> {
        let d = self.inner.dim();
        let flat = match points {
            None => Vec::new(),
            Some(points) => {
                let array = PointsArray::extract(points, "points")?;
                if array.dim() != d {
                    return Err(PointsError::new_err(format!(
                        "points must have {d} coordinates like the curve (got {})",
                        array.dim()
                    )));
                }
                array.flat().into_owned()
            }
        };
        let pieces = self.inner.breakpoints().len();
        check_memory(
            py,
            &format!("the fairness of a curve of {pieces} pieces"),
            bytes_of(&[pieces], BYTES_PER_PIECE),
        )?;
        let inner = &self.inner;
        let f = py.detach(|| inner.fairness(&flat));
        let out = PyDict::new(py);
        out.set_item("length", f.length)?;
        out.set_item("curvature_min", f.curvature_min)?;
        out.set_item("curvature_max", f.curvature_max)?;
        out.set_item("curvature_extrema", f.curvature_extrema)?;
        out.set_item("inflections", f.inflections)?;
        let distance = f.max_distance_to_polygon;
        out.set_item(
            "max_distance_to_polygon",
            distance.is_finite().then_some(distance),
        )?;
        out.set_item("fairness_energy", f.fairness_energy)?;
        out.set_item("pieces", f.pieces)?;
        out.set_item("curvature_jump", f.curvature_jump)?;
        Ok(out)
    }
}
