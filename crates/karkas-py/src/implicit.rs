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

/// An implicit surface ``F(x, y, z) = 0`` given as an expression, with exact first and second
/// derivatives (by symbolic differentiation).
///
/// Parameters
/// ----------
/// expression : str
///     ``F`` in ``x``, ``y``, ``z``: numbers, ``+ - * / ^``, parentheses and the usual
///     functions (``sin``, ``cos``, ``exp``, ``sqrt``, ...), e.g. ``"x^2 + y^2 - 4"``.
///
/// Raises
/// ------
/// ExpressionError
///     The expression does not parse (the message gives the position).
///
/// Examples
/// --------
/// >>> sphere = karkas.ImplicitSurface("x^2 + y^2 + z^2 - 4")
/// >>> sphere.expression
/// 'x^2 + y^2 + z^2 - 4'
/// >>> sphere.value([[2.0, 0.0, 0.0], [0.0, 0.0, 0.0]])
/// array([ 0., -4.])
#[pyclass(module = "karkas", name = "ImplicitSurface", frozen)]
pub struct PyImplicitSurface {
    /// The parsed expression.
    pub surface: ExpressionSurface,
}

/// The steps of `trace_net`: `steps=(hu, hv)`, or `step=h` or `step=(hu, hv)`.
fn net_steps(steps: Option<(f64, f64)>, step: Option<&Bound<'_, PyAny>>) -> PyResult<(f64, f64)> {
    Ok(match (steps, step) {
        (Some(s), None) => s,
        (None, Some(h)) => match h.extract::<f64>() {
            Ok(h) => (h, h),
            Err(_) => h
                .extract::<(f64, f64)>()
                .map_err(|_| OptionError::new_err("step must be a number H or a pair (HU, HV)"))?,
        },
        _ => return Err(OptionError::new_err("give steps or step, one of them")),
    })
}

/// The directions of `trace_net`: `directions` (and `angle`, `plane_normal`), or `turn`
/// (degrees) for `'turned'`.
fn net_directions(
    directions: &str,
    angle: f64,
    plane_normal: Option<Bound<'_, PyAny>>,
    turn: Option<f64>,
) -> PyResult<NetDirections> {
    let (directions, angle) = match turn {
        None => (directions, angle),
        Some(_) if directions != "principal" || angle != 0.0 => {
            return Err(OptionError::new_err(
                "turn is the angle of directions='turned' in degrees: give turn, or directions and angle",
            ))
        }
        Some(0.0) => ("principal", 0.0),
        Some(t) => ("turned", t.to_radians()),
    };
    Ok(match directions {
        "principal" => NetDirections::Principal,
        "turned" => NetDirections::Turned { angle },
        "turned-u" => NetDirections::TurnedU { angle },
        "turned-v" => NetDirections::TurnedV { angle },
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
                "unknown directions {other:?} (expected 'principal', 'turned', 'turned-u', 'turned-v' or 'plane-sections')"
            )))
        }
    })
}

#[pymethods]
impl PyImplicitSurface {
    #[new]
    fn py_new(expression: &str) -> PyResult<Self> {
        Ok(PyImplicitSurface {
            surface: ExpressionSurface::parse(expression).map_err(library_error)?,
        })
    }

    /// ``F`` at points.
    ///
    /// Parameters
    /// ----------
    /// points : array_like
    ///     Shape ``(n, 3)``.
    ///
    /// Returns
    /// -------
    /// numpy.ndarray
    ///     float64, shape ``(n,)``.
    ///
    /// Raises
    /// ------
    /// PointsError
    ///     Not an ``(n, 3)`` array of finite numbers.
    ///
    /// Examples
    /// --------
    /// >>> karkas.ImplicitSurface("x^2 + y^2 - 4").value([[1.0, 1.0, 5.0]])
    /// array([-2.])
    fn value<'py>(
        &self,
        py: Python<'py>,
        points: &Bound<'py, PyAny>,
    ) -> PyResult<Bound<'py, PyArrayDyn<f64>>> {
        let pts = points3(points, "points")?;
        let values: Vec<f64> = pts.iter().map(|&p| self.surface.value(p)).collect();
        vector_to_array(py, &values)
    }

    /// The gradient of ``F`` at points.
    ///
    /// Parameters
    /// ----------
    /// points : array_like
    ///     Shape ``(n, 3)``.
    ///
    /// Returns
    /// -------
    /// numpy.ndarray
    ///     float64, shape ``(n, 3)``.
    ///
    /// Raises
    /// ------
    /// PointsError
    ///     Not an ``(n, 3)`` array of finite numbers.
    ///
    /// Examples
    /// --------
    /// >>> karkas.ImplicitSurface("x^2 + y^2 - 4").gradient([[1.0, 2.0, 5.0]])
    /// array([[2., 4., 0.]])
    fn gradient<'py>(
        &self,
        py: Python<'py>,
        points: &Bound<'py, PyAny>,
    ) -> PyResult<Bound<'py, PyArrayDyn<f64>>> {
        let pts = points3(points, "points")?;
        let g: Vec<Point3> = pts.iter().map(|&p| self.surface.gradient(p)).collect();
        points_to_array(py, &g)
    }

    /// The closest point on ``F = 0`` of every point.
    ///
    /// Parameters
    /// ----------
    /// points : array_like
    ///     Shape ``(n, 3)``.
    ///
    /// Returns
    /// -------
    /// numpy.ndarray
    ///     float64, shape ``(n, 3)``: the foot points on the surface.
    ///
    /// Raises
    /// ------
    /// PointsError
    ///     Not an ``(n, 3)`` array of finite numbers.
    /// ConvergenceError
    ///     The projection of a point did not converge (e.g. at a singular point of ``F``).
    ///
    /// Examples
    /// --------
    /// >>> sphere = karkas.ImplicitSurface("x^2 + y^2 + z^2 - 4")
    /// >>> np.round(sphere.project([[3.0, 0.0, 0.0], [0.0, 1.0, 0.0]]), 6)
    /// array([[2., 0., 0.],
    ///        [0., 2., 0.]])
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

    /// The curvature frame at a point on the surface.
    ///
    /// Parameters
    /// ----------
    /// point : sequence of float
    ///     A point on ``F = 0`` (3 coordinates).
    ///
    /// Returns
    /// -------
    /// dict
    ///     ``normal`` (unit, along the gradient), ``k1 >= k2`` (the principal curvatures),
    ///     ``d1``, ``d2`` (their unit directions), ``gaussian`` and ``mean`` curvature.
    ///
    /// Raises
    /// ------
    /// PointsError
    ///     Not 3 finite coordinates.
    /// ConvergenceError
    ///     A singular point (zero gradient).
    ///
    /// Examples
    /// --------
    /// >>> cylinder = karkas.ImplicitSurface("x^2 + y^2 - 4")
    /// >>> f = cylinder.curvatures([2.0, 0.0, 0.0])
    /// >>> sorted(f)
    /// ['d1', 'd2', 'gaussian', 'k1', 'k2', 'mean', 'normal']
    /// >>> round(abs(f["k1"]) + abs(f["k2"]), 6), abs(f["gaussian"]) < 1e-12
    /// (0.5, True)
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

    /// A node grid on ``F = 0`` traced along two direction fields.
    ///
    /// Parameters
    /// ----------
    /// start : sequence of float
    ///     The first node (3 coordinates), projected onto the surface first.
    /// nodes : tuple of int
    ///     ``(nu, nv)``, the grid's size.
    /// steps : tuple of float, optional
    ///     The arc lengths between neighbouring nodes along ``u`` and along ``v`` (or give
    ///     ``step``).
    /// directions : str, optional
    ///     ``'principal'`` (lines of curvature), ``'turned'`` (both fields turned by
    ///     ``angle``), ``'turned-u'`` (the ``u`` lines turned), ``'turned-v'`` (the ``v``
    ///     lines turned) or ``'plane-sections'`` (``v`` lines in planes normal to
    ///     ``plane_normal``).
    /// angle : float, optional
    ///     The turn in radians for ``'turned'``, ``'turned-u'`` and ``'turned-v'``.
    /// plane_normal : sequence of float, optional
    ///     The normal of the planes for ``'plane-sections'``.
    /// closed_v : bool, optional
    ///     The ``v`` lines close on themselves (around a tube).
    /// substeps : int, optional
    ///     Integration steps between two nodes (at most 4096).
    /// step : float or tuple of float, optional
    ///     The command line's name (``karkas surface implicit --step``): ``H`` or ``(HU, HV)``,
    ///     instead of ``steps``.
    /// turn : float, optional
    ///     The command line's ``--turn``, in degrees: ``directions='turned'`` with ``angle`` in
    ///     radians (0 is ``'principal'``).
    ///
    /// Returns
    /// -------
    /// numpy.ndarray
    ///     float64, shape ``(nu, nv, 3)``: the nodes, on the surface.
    ///
    /// Raises
    /// ------
    /// OptionError
    ///     An unknown ``directions``, a missing ``plane_normal``, or a count out of range.
    /// ConvergenceError
    ///     The tracing met an umbilic or singular point, or did not converge.
    ///
    /// Examples
    /// --------
    /// >>> cylinder = karkas.ImplicitSurface("x^2 + y^2 - 4")
    /// >>> net = cylinder.trace_net([2.0, 0.0, 0.0], nodes=(3, 4), steps=(0.5, 0.5))
    /// >>> net.shape
    /// (3, 4, 3)
    /// >>> bool(np.allclose(cylinder.value(net.reshape(-1, 3)), 0.0, atol=1e-8))
    /// True
    #[pyo3(signature = (start, nodes, steps = None, directions = "principal", angle = 0.0, plane_normal = None, closed_v = false, substeps = 32, *, step = None, turn = None))]
    #[allow(clippy::too_many_arguments)]
    fn trace_net<'py>(
        &self,
        py: Python<'py>,
        start: &Bound<'py, PyAny>,
        nodes: (Int, Int),
        steps: Option<(f64, f64)>,
        directions: &str,
        angle: f64,
        plane_normal: Option<Bound<'py, PyAny>>,
        closed_v: bool,
        substeps: i64,
        step: Option<&Bound<'py, PyAny>>,
        turn: Option<f64>,
    ) -> PyResult<Bound<'py, PyArrayDyn<f64>>> {
        let steps = net_steps(steps, step)?;
        let directions = net_directions(directions, angle, plane_normal, turn)?;
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

    /// The expression ``F`` as given.
    #[getter]
    fn expression(&self) -> &str {
        self.surface.text()
    }

    fn __repr__(&self) -> String {
        format!("<karkas.ImplicitSurface {:?} = 0>", self.surface.text())
    }
}
