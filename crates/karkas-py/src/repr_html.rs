//! Jupyter's rich display: `_repr_html_` of a curve is its SVG picture with the curvature comb
//! (the command line's `.svg` with `--comb`), of a surface the 3-D viewer page (the command
//! line's `.html`) in an `<iframe srcdoc>`, so that its scripts run inside the notebook. The
//! sample counts are capped, so that the page stays small whatever the object.

use karkas::Grid;
use karkas_io::export::curve::{render_curve_svg, CurveDrawing};
use karkas_io::export::samples::{default_curve_samples, default_surface_samples, sample_surface};
use karkas_io::export::surface::{render_surface_html, SurfaceDrawing};
use karkas_io::mesh::MeshOptions;
use pyo3::prelude::*;

use crate::convert::by_dim;
use crate::curve::PyCurve;
use crate::erased::{CurveView, SurfaceView};
use crate::errors::{library_error, KarkasError};
use crate::surface::PySurface;

/// The most samples of a curve picture.
const MAX_CURVE_SAMPLES: usize = 2000;

/// The most samples of a surface page per direction.
const MAX_SURFACE_SAMPLES: usize = 100;

#[pymethods]
impl PyCurve {
    /// The curve as an SVG picture for Jupyter: the x-y projection with its curvature comb.
    ///
    /// At most 2000 samples (10 per piece, at least 200), titled by the repr.
    ///
    /// Returns
    /// -------
    /// str
    ///     An ``<svg>`` document.
    ///
    /// Examples
    /// --------
    /// >>> import numpy as np, karkas
    /// >>> c = karkas.LLCurve(np.array([[0., 0.], [1., 1.], [2., 0.]]))
    /// >>> c._repr_html_().lstrip().startswith(("<svg", "<?xml"))
    /// True
    fn _repr_html_(&self, py: Python<'_>) -> PyResult<String> {
        let pieces = self.inner.breakpoints().len().saturating_sub(1);
        let n = default_curve_samples(pieces).min(MAX_CURVE_SAMPLES);
        let (inner, title) = (&*self.inner, self.description.as_str());
        by_dim!(inner.dim(), D => {
            let drawing = CurveDrawing::<D> {
                title,
                input: &[],
                closed_input: false,
                comb: true,
            };
            py.detach(|| render_curve_svg(&CurveView::<D>(inner), n, &drawing))
                .map_err(|e| KarkasError::new_err(e.to_string()))
        })
    }
}

#[pymethods]
impl PySurface {
    /// The surface in the 3-D viewer for Jupyter: the command line's ``.html`` page in an
    /// ``<iframe srcdoc>``.
    ///
    /// 50 x 50 samples (at most 100 per direction), titled by the repr.
    ///
    /// Returns
    /// -------
    /// str
    ///     An ``<iframe>`` element holding the page.
    ///
    /// Examples
    /// --------
    /// >>> import numpy as np, karkas
    /// >>> g = np.random.default_rng(0).random((4, 4, 3))
    /// >>> karkas.LLSurface(g)._repr_html_().startswith("<iframe")
    /// True
    fn _repr_html_(&self, py: Python<'_>) -> PyResult<String> {
        let n = default_surface_samples(0).min(MAX_SURFACE_SAMPLES);
        let view = SurfaceView(&*self.inner);
        let title = self.description.as_str();
        let page = py.detach(|| {
            let (_, _, samples) = sample_surface(&view, n, n);
            let grid = Grid::from_row_major(n, n, samples)?;
            let drawing = SurfaceDrawing {
                title,
                net: None,
                mesh: MeshOptions::default(),
            };
            Ok::<_, karkas::Error>(render_surface_html(&grid, &drawing))
        });
        let page = page.map_err(library_error)?;
        Ok(format!(
            "<iframe srcdoc=\"{}\" style=\"width: 100%; height: 480px; border: 0\" \
             sandbox=\"allow-scripts\"></iframe>",
            escape_attribute(&page)
        ))
    }
}

/// `text` as the value of a double-quoted HTML attribute.
fn escape_attribute(text: &str) -> String {
    text.replace('&', "&amp;").replace('"', "&quot;")
}
