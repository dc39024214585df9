//! Plane sections of surfaces: the Python class `SectionCurve`, one connected piece of a
//! section (the method of the library's `section` module; `Surface.section` returns them).

use numpy::PyArrayDyn;
use pyo3::prelude::*;

use karkas::section::SectionCurve;

use crate::convert::{as_points, by_dim, flatten, points_to_array, py_bool, PointsArray};
use crate::errors::PointsError;

/// One connected piece of a plane section: a polyline on the surface.
///
/// Returned by ``Surface.section`` (no constructor). ``len(piece)`` is its number of points.
///
/// Examples
/// --------
/// >>> grid = np.array([[[i, j, 0.0] for j in range(4)] for i in range(4)])
/// >>> S = karkas.BicubicSurface(grid, parameterization="uniform")
/// >>> (piece,) = S.section([0.0, 1.0, 0.0], 1.5)
/// >>> piece.closed, round(piece.length, 6)
/// (False, 3.0)
/// >>> len(piece) == len(piece.points) == len(piece.params)
/// True
/// >>> bool(np.allclose(S(piece.params[:, 0], piece.params[:, 1], grid=False), piece.points))
/// True
#[pyclass(module = "karkas", name = "SectionCurve", frozen)]
pub struct PySectionCurve {
    points: Vec<f64>,
    params: Vec<f64>,
    dim: usize,
    /// True when the last point joins the first (which is not repeated).
    #[pyo3(get)]
    pub(crate) closed: bool,
    /// The polyline's length (the closing chord included when closed).
    #[pyo3(get)]
    pub(crate) length: f64,
}

impl PySectionCurve {
    /// The Python object of a piece of a section.
    pub fn of<const D: usize>(curve: &SectionCurve<D>) -> Self {
        PySectionCurve {
            points: flatten(&curve.points).to_vec(),
            params: curve.params.iter().flat_map(|&(u, v)| [u, v]).collect(),
            dim: D,
            closed: curve.closed,
            length: curve.length(),
        }
    }

    /// A piece from its points `(n, d)`, parameters `(n, 2)`, closedness and length.
    pub fn from_parts(
        points: &Bound<'_, PyAny>,
        params: &Bound<'_, PyAny>,
        closed: bool,
        length: f64,
    ) -> PyResult<Self> {
        let (pts, dim) = PointsArray::extract_checked(points, "points")?;
        let uv = PointsArray::extract(params, "params")?;
        if uv.dim() != 2 || uv.len() != pts.len() {
            return Err(PointsError::new_err(
                "params must have shape (n, 2), one pair per point",
            ));
        }
        Ok(PySectionCurve {
            points: pts.flat().into_owned(),
            params: uv.flat().into_owned(),
            dim,
            closed,
            length,
        })
    }
}

#[pymethods]
impl PySectionCurve {
    /// The points, float64 ``(n, d)``; each is the surface at its ``params``.
    #[getter]
    fn points<'py>(&self, py: Python<'py>) -> PyResult<Bound<'py, PyArrayDyn<f64>>> {
        by_dim!(self.dim, D => points_to_array::<D>(py, as_points::<D>(&self.points)))
    }

    /// The surface parameters ``(u, v)`` of the points, float64 ``(n, 2)``.
    #[getter]
    fn params<'py>(&self, py: Python<'py>) -> PyResult<Bound<'py, PyArrayDyn<f64>>> {
        points_to_array::<2>(py, as_points::<2>(&self.params))
    }

    fn __len__(&self) -> usize {
        self.params.len() / 2
    }

    fn __repr__(&self) -> String {
        format!(
            "<karkas.SectionCurve {} points in {}-D, closed={}, length={}>",
            self.params.len() / 2,
            self.dim,
            py_bool(self.closed),
            self.length
        )
    }
}
