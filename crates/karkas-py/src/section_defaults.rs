//! `LLSurface.section` with the command line's default cells (`karkas section --method ll`):
//! 2 per grid line in each direction, at least 16 ([`karkas::section::cells_for_grid`]),
//! instead of the fixed default of `Surface.section`.

use pyo3::prelude::*;

use crate::ll::PyLlSurface;
use crate::surface::PySurface;

#[pymethods]
impl PyLlSurface {
    /// S.section(normal, offset, tolerance=None, cells=None) -> list[SectionCurve]: as
    /// Surface.section, with cells=None meaning 2 per grid line in each direction, at least
    /// 16 (the default of karkas section --method ll).
    #[pyo3(signature = (normal, offset, tolerance = None, cells = None))]
    fn section<'py>(
        slf: &Bound<'py, Self>,
        normal: Vec<f64>,
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
