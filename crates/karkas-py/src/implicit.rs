//! Implicit surfaces F(x, y, z) = 0: the Python class `ImplicitSurface` (projection,
//! curvatures, nets along lines of curvature).

use karkas::implicit::{
    closest_point_on, trace_net, ExpressionSurface, ImplicitSurface, NetDirections, NetSpec,
    SurfaceFrame,
};
use karkas::Point3;
use numpy::PyArrayDyn;
use pyo3::prelude::*;
use pyo3::types::PyDict;

use crate::convert::{
    count, grid_to_array, maybe_detach, point3, points3, points_to_array, small_vector,
    vector_to_array, Int,
};
use crate::errors::{library_error, OptionError};
use crate::limits::{bytes_of, check_memory};

/// The most Runge-Kutta substeps per node step `trace_net` takes: a classical Runge-Kutta
/// step's error falls as the fifth power of its length, so more substeps than this change
/// nothing in double precision and only make a mistyped count run for hours.
pub const MAX_SUBSTEPS: usize = 4096;

/// An implicit surface F(x, y, z) = 0 given as an expression, e.g. "x^2 + y^2 - 4" (exact
/// first and second derivatives, by symbolic differentiation).
///
/// ImplicitSurface(expression): value(points), gradient(points), project(points) (closest
/// points on F = 0), curvatures(point), trace_net(...) (a node grid along lines of curvature).
#[pyclass(module = "karkas", name = "ImplicitSurface", frozen)]
pub struct PyImplicitSurface {
    /// The parsed expression.
    pub surface: ExpressionSurface,
}

#[pymethods]
impl PyImplicitSurface {
    #[new]
    fn py_new(expression: &str) -> PyResult<Self> {
        Ok(PyImplicitSurface {
            surface: ExpressionSurface::parse(expression).map_err(library_error)?,
        })
    }

    /// F at the points (n, 3) -> (n,).
    fn value<'py>(
        &self,
        py: Python<'py>,
        points: &Bound<'py, PyAny>,
    ) -> PyResult<Bound<'py, PyArrayDyn<f64>>> {
        let pts = points3(points, "points")?;
        let values: Vec<f64> = pts.iter().map(|&p| self.surface.value(p)).collect();
        vector_to_array(py, &values)
    }

    /// grad F at the points (n, 3) -> (n, 3).
    fn gradient<'py>(
        &self,
        py: Python<'py>,
        points: &Bound<'py, PyAny>,
    ) -> PyResult<Bound<'py, PyArrayDyn<f64>>> {
        let pts = points3(points, "points")?;
        let g: Vec<Point3> = pts.iter().map(|&p| self.surface.gradient(p)).collect();
        points_to_array(py, &g)
    }

    /// The closest point on F = 0 of every point (n, 3) -> (n, 3).
    fn project<'py>(
        &self,
        py: Python<'py>,
        points: &Bound<'py, PyAny>,
    ) -> PyResult<Bound<'py, PyArrayDyn<f64>>> {
        let pts = points3(points, "points")?;
        let surface = &self.surface;
        let feet = maybe_detach(py, pts.len() * 64, || {
            pts.iter()
                .map(|&p| closest_point_on(surface, p))
                .collect::<karkas::Result<Vec<Point3>>>()
        })
        .map_err(library_error)?;
        points_to_array(py, &feet)
    }

    /// The curvature frame at a point on the surface: a dict with normal, k1 >= k2 (principal
    /// curvatures), their directions d1, d2, gaussian and mean curvature.
    fn curvatures<'py>(
        &self,
        py: Python<'py>,
        point: &Bound<'py, PyAny>,
    ) -> PyResult<Bound<'py, PyDict>> {
        let point = point3(&small_vector(point, "point")?, "point")?;
        let f = SurfaceFrame::at(&self.surface, point).map_err(library_error)?;
        let d = PyDict::new(py);
        d.set_item("normal", f.normal.0.to_vec())?;
        d.set_item("k1", f.first_curvature)?;
        d.set_item("k2", f.second_curvature)?;
        d.set_item("d1", f.first_direction.0.to_vec())?;
        d.set_item("d2", f.second_direction.0.to_vec())?;
        d.set_item("gaussian", f.gaussian_curvature())?;
        d.set_item("mean", f.mean_curvature())?;
        Ok(d)
    }

    /// trace_net(start, nodes, steps, directions="principal", angle=0.0, plane_normal=None,
    /// closed_v=False, substeps=32) -> (nu, nv, 3): a node grid on F = 0 from start (projected
    /// first) along two direction fields: 'principal' (lines of curvature), 'turned' (both
    /// turned by angle), 'turned-u' (u lines turned), 'plane-sections' (v lines in planes
    /// normal to plane_normal). nodes = (nu, nv); steps = arc lengths between nodes; substeps:
    /// Runge-Kutta steps per node step, at most 4096.
    #[pyo3(signature = (start, nodes, steps, directions = "principal", angle = 0.0, plane_normal = None, closed_v = false, substeps = 32))]
    #[allow(clippy::too_many_arguments)]
    fn trace_net<'py>(
        &self,
        py: Python<'py>,
        start: &Bound<'py, PyAny>,
        nodes: (Int, Int),
        steps: (f64, f64),
        directions: &str,
        angle: f64,
        plane_normal: Option<Bound<'py, PyAny>>,
        closed_v: bool,
        substeps: i64,
    ) -> PyResult<Bound<'py, PyArrayDyn<f64>>> {
        let directions = match directions {
            "principal" => NetDirections::Principal,
            "turned" => NetDirections::Turned { angle },
            "turned-u" => NetDirections::TurnedU { angle },
            "plane-sections" => NetDirections::PlaneSections {
                plane_normal: point3(
                    &small_vector(
                        &plane_normal.ok_or_else(|| OptionError::new_err("'plane-sections' needs plane_normal"))?,
                        "plane_normal",
                    )?,
                    "plane_normal",
                )?,
            },
            other => {
                return Err(OptionError::new_err(format!(
                    "unknown directions {other:?} (expected 'principal', 'turned', 'turned-u' or 'plane-sections')"
                )))
            }
        };
        let nodes = (count(nodes.0, "nodes")?, count(nodes.1, "nodes")?);
        // The traced grid and the returned array.
        check_memory(
            py,
            &format!(
                "ImplicitSurface.trace_net(nodes=({}, {}))",
                nodes.0, nodes.1
            ),
            bytes_of(&[nodes.0, nodes.1, 3], 16),
        )?;
        let mut spec = NetSpec::new(
            point3(&small_vector(start, "start")?, "start")?,
            directions,
            nodes,
            steps,
        );
        spec.closed_v = closed_v;
        spec.substeps = count(substeps, "substeps")?;
        if spec.substeps > MAX_SUBSTEPS {
            return Err(OptionError::new_err(format!(
                "substeps must be at most {MAX_SUBSTEPS} (got {}): the Runge-Kutta steps are \
                 then already far below double precision",
                spec.substeps
            )));
        }
        let surface = &self.surface;
        let grid = py
            .detach(|| trace_net(surface, &spec))
            .map_err(library_error)?;
        grid_to_array(py, &grid)
    }

    /// The expression as given.
    #[getter]
    fn expression(&self) -> &str {
        self.surface.text()
    }

    fn __repr__(&self) -> String {
        format!("<karkas.ImplicitSurface {:?} = 0>", self.surface.text())
    }
}
