//! `LLSurface.section` with the command line's default cells (`karkas section --method ll`):
//! 2 per grid line in each direction, at least 16 ([`karkas::section::cells_for_grid`]),
//! instead of the fixed default of `Surface.section`.

use pyo3::prelude::*;

use crate::ll::PyLlSurface;
use crate::surface::PySurface;

#[pymethods]
impl PyLlSurface {
    /// Where the plane ``normal . x = offset`` cuts the surface, as polylines on it.
    ///
    /// As ``Surface.section``, with the command line's default search grid (``karkas section
    /// --method ll``): ``cells=None`` means 2 cells per grid line in each direction, at least 16.
    ///
    /// Parameters
    /// ----------
    /// normal : sequence of float
    ///     The plane's normal, ``d`` coordinates (need not be a unit vector).
    /// offset : float
    ///     The plane is ``normal . x = offset``.
    /// tolerance : float, optional
    ///     The largest chord error of the polylines; None: 1e-4 of the diagonal of the
    ///     surface's bounding box.
    /// cells : tuple of int, optional
    ///     The ``(nu, nv)`` cells of the search grid; None: the command line's default.
    ///
    /// Returns
    /// -------
    /// list of SectionCurve
    ///     The connected pieces of the section (empty when the plane misses the surface).
    ///
    /// Raises
    /// ------
    /// OptionError
    ///     ``normal`` has the wrong number of coordinates or is zero, or ``tolerance`` or
    ///     ``cells`` is out of range.
    /// ConvergenceError
    ///     The continuation could not follow the section.
    ///
    /// Examples
    /// --------
    /// >>> grid = np.array([[[i, j, i * j] for j in range(5)] for i in range(5)], float)
    /// >>> S = karkas.LLSurface(grid, order=3)
    /// >>> pieces = S.section([1.0, 0.0, 0.0], 2.0)
    /// >>> len(pieces)
    /// 1
    /// >>> bool(np.allclose(pieces[0].points[:, 0], 2.0))
    /// True
    #[pyo3(signature = (normal, offset, tolerance = None, cells = None))]
    fn section<'py>(
        slf: &Bound<'py, Self>,
        normal: &Bound<'py, PyAny>,
        offset: f64,
        tolerance: Option<f64>,
        cells: Option<(usize, usize)>,
    ) -> PyResult<Bound<'py, PyAny>> {
        let (rows, cols) = slf.get().shape;
        let cells = cells.unwrap_or_else(|| karkas::section::cells_for_grid(rows, cols));
        let base = slf.py().get_type::<PySurface>().getattr("section")?;
        base.call1((slf, normal, offset, tolerance, cells))
    }
}
