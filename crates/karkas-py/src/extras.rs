//! Sections, Coons/Gordon surfaces, implicit surfaces, Hausdorff distances, the surface
//! variation method and parameterizations.

use std::sync::Arc;

use karkas::coons::{CoonsSurface, CurveFit, PointNetwork};
use karkas::implicit::{
    closest_point_on, trace_net, ExpressionSurface, ImplicitSurface, NetDirections, NetSpec,
    SurfaceFrame,
};
use karkas::ll::{vary as ll_vary, FixedEntries, SumTargets, VariationOptions};
use karkas::measure::{hausdorff_sets, DirectedDistance, Hausdorff};
use karkas::param::{curve_parameters as param_curve, grid_parameters as param_grid};
use karkas::{Grid, Point, Point3};
use numpy::{AllowTypeChange, PyArrayDyn, PyArrayLike2, PyUntypedArrayMethods};
use pyo3::prelude::*;
use pyo3::types::PyDict;

use crate::convert::{
    as_points, check_dim, grid_to_array, invalid, maybe_detach, points_to_array, value_error,
    vector_to_array, GridArray, PointsArray,
};
use crate::curves::{by_dim, count, py_bool};
use crate::surface::{FlatSection, PySurface, SurfaceImpl, WrappedSurface};
use crate::surfaces::parse_grid_parameterization;

/// One connected piece of a plane section: a polyline on the surface.
#[pyclass(module = "karkas", name = "SectionCurve", frozen)]
pub struct PySectionCurve {
    points: Vec<f64>,
    params: Vec<f64>,
    dim: usize,
    /// True when the last point joins the first (which is not repeated).
    #[pyo3(get)]
    closed: bool,
    /// The polyline's length (the closing chord included when closed).
    #[pyo3(get)]
    length: f64,
}

#[pymethods]
impl PySectionCurve {
    /// The points, (n, d); each is the surface at its params.
    #[getter]
    fn points<'py>(&self, py: Python<'py>) -> PyResult<Bound<'py, PyArrayDyn<f64>>> {
        by_dim!(self.dim, D => points_to_array::<D>(py, as_points::<D>(&self.points)))
    }

    /// The surface parameters (u, v) of the points, (n, 2).
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

/// The Python objects of a section's pieces.
pub fn section_curves(section: FlatSection, dim: usize) -> Vec<PySectionCurve> {
    section
        .curves
        .into_iter()
        .map(|c| PySectionCurve {
            points: c.points,
            params: c.params,
            dim,
            closed: c.closed,
            length: c.length,
        })
        .collect()
}

/// A list of point arrays (each (k, d)) as karkas point lists of dimension `D`.
fn point_lists<const D: usize>(
    lists: &[Bound<'_, PyAny>],
    what: &str,
) -> PyResult<Vec<Vec<Point<D>>>> {
    lists
        .iter()
        .enumerate()
        .map(|(i, obj)| {
            let pts = PointsArray::extract(obj, &format!("{what}[{i}]"))?;
            if pts.dim() != D {
                return Err(invalid(format!(
                    "{what}[{i}] has {} coordinates per point, expected {D}",
                    pts.dim()
                )));
            }
            Ok(as_points::<D>(&pts.flat()).to_vec())
        })
        .collect()
}

/// The dimension of the first array of a list.
fn first_dim(lists: &[Bound<'_, PyAny>], what: &str) -> PyResult<usize> {
    let first = lists
        .first()
        .ok_or_else(|| invalid(format!("{what} must not be empty")))?;
    check_dim(
        PointsArray::extract(first, &format!("{what}[0]"))?.dim(),
        what,
    )
}

/// Generalized Coons surfaces (Chashnikov) over a network of curves given by points.
///
/// CoonsSurface(v_curves, u_curves, kind="gordon-spline", u_derivs=None, v_derivs=None,
/// fit="spline", crossing_tolerance=1e-6, tolerance=1e-4): v_curves run along v (listed by
/// increasing u), u_curves along u (by increasing v); each a (k, d) array, interpolated by a
/// not-a-knot cubic spline (fit="spline") or an interpolating LL curve (fit=("ll", order)).
/// kind: 'bilinear' and 'bicubic' (two curves a family), 'gordon' (Lagrange blending),
/// 'gordon-spline' (cubic-spline blending), 'composite' (C^1 piecewise bicubic).
/// u_derivs / v_derivs: dS/dv along the u-curves and dS/du along the v-curves (one vector per
/// point) for 'bicubic' and 'composite'. A family whose curves repeat their first point at the
/// end is closed.
#[pyclass(extends = PySurface, module = "karkas", name = "CoonsSurface", frozen)]
pub struct PyCoonsSurface {
    /// The kind of surface.
    #[pyo3(get)]
    kind: String,
}

#[pymethods]
impl PyCoonsSurface {
    #[new]
    #[pyo3(signature = (v_curves, u_curves, kind = "gordon-spline", u_derivs = None, v_derivs = None, fit = None, crossing_tolerance = 1e-6, tolerance = 1e-4))]
    #[allow(clippy::too_many_arguments)]
    fn py_new(
        py: Python<'_>,
        v_curves: Vec<Bound<'_, PyAny>>,
        u_curves: Vec<Bound<'_, PyAny>>,
        kind: &str,
        u_derivs: Option<Vec<Bound<'_, PyAny>>>,
        v_derivs: Option<Vec<Bound<'_, PyAny>>>,
        fit: Option<Bound<'_, PyAny>>,
        crossing_tolerance: f64,
        tolerance: f64,
    ) -> PyResult<PyClassInitializer<Self>> {
        let fit = match fit {
            None => CurveFit::CubicSpline,
            Some(f) => {
                if let Ok(name) = f.extract::<String>() {
                    match name.as_str() {
                        "spline" => CurveFit::CubicSpline,
                        _ => {
                            return Err(invalid(format!(
                                "unknown fit {name:?} (expected 'spline' or ('ll', order))"
                            )))
                        }
                    }
                } else {
                    let (name, order): (String, i64) = f
                        .extract()
                        .map_err(|_| invalid("fit must be 'spline' or ('ll', order)"))?;
                    if name != "ll" {
                        return Err(invalid("fit must be 'spline' or ('ll', order)"));
                    }
                    CurveFit::Ll(count(order, "order")?)
                }
            }
        };
        let known = [
            "bilinear",
            "bicubic",
            "gordon",
            "gordon-spline",
            "composite",
        ];
        if !known.contains(&kind) {
            return Err(invalid(format!(
                "unknown kind {kind:?} (expected one of {known:?})"
            )));
        }
        let dim = first_dim(&v_curves, "v_curves")?;
        let (inner, counts): (Arc<dyn SurfaceImpl>, (usize, usize)) = by_dim!(dim, D => {
            let v = point_lists::<D>(&v_curves, "v_curves")?;
            let u = point_lists::<D>(&u_curves, "u_curves")?;
            let derivs = match (&u_derivs, &v_derivs) {
                (Some(du), Some(dv)) => Some((point_lists::<D>(du, "u_derivs")?, point_lists::<D>(dv, "v_derivs")?)),
                (None, None) => None,
                _ => return Err(invalid("give both u_derivs and v_derivs, or neither")),
            };
            let surface = py.detach(|| -> karkas::Result<CoonsSurface<D>> {
                let network = PointNetwork::new(&v, &u, fit, crossing_tolerance)?;
                let cross = match &derivs {
                    Some((du, dv)) => Some(network.cross_derivatives(dv, du)?),
                    None => None,
                };
                let net = network.network();
                match kind {
                    "bilinear" => CoonsSurface::bilinear(net, tolerance),
                    "bicubic" => CoonsSurface::bicubic(net, cross.as_ref(), tolerance),
                    "gordon" => CoonsSurface::gordon(net, tolerance),
                    "composite" => CoonsSurface::composite(net, cross.as_ref(), tolerance),
                    _ => CoonsSurface::gordon_spline(
                        net,
                        karkas::coons::SplineEnds::NotAKnot,
                        tolerance,
                    ),
                }
            })
            .map_err(value_error)?;
            (Arc::new(WrappedSurface::<_, D>(surface)) as Arc<dyn SurfaceImpl>, (v.len(), u.len()))
        });
        let description = format!(
            "<karkas.CoonsSurface kind='{kind}', {} v-curves x {} u-curves in {dim}-D",
            counts.0, counts.1
        );
        Ok(
            PyClassInitializer::from(PySurface::new(inner, description)).add_subclass(
                PyCoonsSurface {
                    kind: kind.to_string(),
                },
            ),
        )
    }
}

/// A float64 array returned to Python.
type Array<'py> = Bound<'py, PyArrayDyn<f64>>;

/// A 3-D point from a sequence of 3 numbers.
fn point3(p: &[f64], what: &str) -> PyResult<Point3> {
    match p {
        [x, y, z] => Ok(Point3::new([*x, *y, *z])),
        _ => Err(invalid(format!("{what} must have 3 coordinates"))),
    }
}

/// (n, 3) points.
fn points3(obj: &Bound<'_, PyAny>, what: &str) -> PyResult<Vec<Point3>> {
    let pts = PointsArray::extract(obj, what)?;
    if pts.dim() != 3 {
        return Err(invalid(format!(
            "{what} must have 3 coordinates per point (got {})",
            pts.dim()
        )));
    }
    Ok(as_points::<3>(&pts.flat()).to_vec())
}

/// An implicit surface F(x, y, z) = 0 given as an expression, e.g. "x^2 + y^2 - 4" (exact
/// first and second derivatives, by symbolic differentiation).
///
/// ImplicitSurface(expression): value(points), gradient(points), project(points) (closest
/// points on F = 0), curvatures(point), trace_net(...) (a node grid along lines of curvature).
#[pyclass(module = "karkas", name = "ImplicitSurface", frozen)]
pub struct PyImplicitSurface {
    surface: ExpressionSurface,
}

#[pymethods]
impl PyImplicitSurface {
    #[new]
    fn py_new(expression: &str) -> PyResult<Self> {
        Ok(PyImplicitSurface {
            surface: ExpressionSurface::parse(expression).map_err(value_error)?,
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
        Ok(vector_to_array(py, &values))
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
        .map_err(value_error)?;
        points_to_array(py, &feet)
    }

    /// The curvature frame at a point on the surface: a dict with normal, k1 >= k2 (principal
    /// curvatures), their directions d1, d2, gaussian and mean curvature.
    fn curvatures<'py>(&self, py: Python<'py>, point: Vec<f64>) -> PyResult<Bound<'py, PyDict>> {
        let f = SurfaceFrame::at(&self.surface, point3(&point, "point")?).map_err(value_error)?;
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
    /// normal to plane_normal). nodes = (nu, nv); steps = arc lengths between nodes.
    #[pyo3(signature = (start, nodes, steps, directions = "principal", angle = 0.0, plane_normal = None, closed_v = false, substeps = 32))]
    #[allow(clippy::too_many_arguments)]
    fn trace_net<'py>(
        &self,
        py: Python<'py>,
        start: Vec<f64>,
        nodes: (i64, i64),
        steps: (f64, f64),
        directions: &str,
        angle: f64,
        plane_normal: Option<Vec<f64>>,
        closed_v: bool,
        substeps: i64,
    ) -> PyResult<Bound<'py, PyArrayDyn<f64>>> {
        let directions = match directions {
            "principal" => NetDirections::Principal,
            "turned" => NetDirections::Turned { angle },
            "turned-u" => NetDirections::TurnedU { angle },
            "plane-sections" => NetDirections::PlaneSections {
                plane_normal: point3(
                    &plane_normal.ok_or_else(|| invalid("'plane-sections' needs plane_normal"))?,
                    "plane_normal",
                )?,
            },
            other => {
                return Err(invalid(format!(
                    "unknown directions {other:?} (expected 'principal', 'turned', 'turned-u' or 'plane-sections')"
                )))
            }
        };
        let mut spec = NetSpec::new(
            point3(&start, "start")?,
            directions,
            (count(nodes.0, "nodes")?, count(nodes.1, "nodes")?),
            steps,
        );
        spec.closed_v = closed_v;
        spec.substeps = count(substeps, "substeps")?;
        let surface = &self.surface;
        let grid = py
            .detach(|| trace_net(surface, &spec))
            .map_err(value_error)?;
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

/// A Hausdorff result as a dict: distance, and each direction's distance and the points
/// where it is attained.
fn hausdorff_dict<'py>(py: Python<'py>, h: &Hausdorff) -> PyResult<Bound<'py, PyDict>> {
    let side = |d: &DirectedDistance| -> PyResult<Bound<'py, PyDict>> {
        let s = PyDict::new(py);
        s.set_item("distance", d.distance)?;
        s.set_item("from", d.from.0.to_vec())?;
        s.set_item("to", d.to.0.to_vec())?;
        Ok(s)
    };
    let out = PyDict::new(py);
    out.set_item("distance", h.distance)?;
    out.set_item("forward", side(&h.forward)?)?;
    out.set_item("backward", side(&h.backward)?)?;
    Ok(out)
}

/// hausdorff(a, b) -> dict: the two-sided Hausdorff distance between point sets a (n, 3) and
/// b (m, 3) (k-d tree, O((n + m) log)), with where each one-sided distance is attained.
#[pyfunction]
pub fn hausdorff<'py>(
    py: Python<'py>,
    a: &Bound<'py, PyAny>,
    b: &Bound<'py, PyAny>,
) -> PyResult<Bound<'py, PyDict>> {
    let (a, b) = (points3(a, "a")?, points3(b, "b")?);
    let h = py.detach(|| hausdorff_sets(&a, &b)).map_err(value_error)?;
    hausdorff_dict(py, &h)
}

/// hausdorff_to_implicit(surface, implicit, patch, samples=(50, 50)) -> dict: the two-sided
/// Hausdorff distance between a 3-D surface (sampled on samples) and the patch of an implicit
/// surface given by points on it (patch (n, 3)).
#[pyfunction]
#[pyo3(signature = (surface, implicit, patch, samples = (50, 50)))]
pub fn hausdorff_to_implicit<'py>(
    py: Python<'py>,
    surface: &Bound<'py, PySurface>,
    implicit: &Bound<'py, PyImplicitSurface>,
    patch: &Bound<'py, PyAny>,
    samples: (usize, usize),
) -> PyResult<Bound<'py, PyDict>> {
    let s = surface.get();
    if s.inner.dim() != 3 {
        return Err(invalid("the surface must be 3-D"));
    }
    let patch = points3(patch, "patch")?;
    let inner = &s.inner;
    let expr = &implicit.get().surface;
    let h = py
        .detach(|| inner.hausdorff_implicit(expr, &patch, samples))
        .map_err(value_error)?;
    hausdorff_dict(py, &h)
}

/// vary(matrix, row_sums, column_sums, fixed=None, penalty=None, scale_with_total=False) ->
/// (n, m): the LL paper's surface variation: the least change of matrix (n, m) whose row and
/// column sums become the given ones, entries where fixed (bool (n, m)) is true held exactly
/// (or at penalty times the cost).
#[pyfunction]
#[pyo3(signature = (matrix, row_sums, column_sums, fixed = None, penalty = None, scale_with_total = false))]
pub fn vary<'py>(
    py: Python<'py>,
    matrix: PyArrayLike2<'py, f64, AllowTypeChange>,
    row_sums: Vec<f64>,
    column_sums: Vec<f64>,
    fixed: Option<PyArrayLike2<'py, bool, AllowTypeChange>>,
    penalty: Option<f64>,
    scale_with_total: bool,
) -> PyResult<Bound<'py, PyArrayDyn<f64>>> {
    let (n, m) = (matrix.shape()[0], matrix.shape()[1]);
    let values: Vec<f64> = matrix.as_array().iter().copied().collect();
    let z = Grid::from_row_major(n, m, values).map_err(value_error)?;
    let fixed = match fixed {
        Some(f) => {
            let shape = f.shape();
            Grid::from_row_major(shape[0], shape[1], f.as_array().iter().copied().collect())
                .map_err(value_error)?
        }
        None => Grid::from_fn(n, m, |_, _| false),
    };
    let options = VariationOptions {
        fixed_entries: penalty.map_or(FixedEntries::Exact, FixedEntries::Penalty),
        scale_with_total,
    };
    let targets = SumTargets {
        rows: row_sums,
        columns: column_sums,
    };
    let varied = py
        .detach(|| ll_vary(&z, &fixed, &targets, &options))
        .map_err(value_error)?;
    let out = PyArrayDyn::<f64>::zeros(py, &[n, m][..], false);
    crate::convert::write_flat(&out, |flat| flat.copy_from_slice(varied.as_slice()))?;
    Ok(out)
}

/// curve_parameters(points, parameterization="chord") -> (n,): the parameters of points
/// (n, d) starting at 0: 'uniform', 'chord' or 'centripetal'.
#[pyfunction]
#[pyo3(signature = (points, parameterization = "chord"))]
pub fn curve_parameters<'py>(
    py: Python<'py>,
    points: &Bound<'py, PyAny>,
    parameterization: &str,
) -> PyResult<Bound<'py, PyArrayDyn<f64>>> {
    let rule = crate::curves::parse_parameterization(parameterization)?;
    let pts = PointsArray::extract(points, "points")?;
    let dim = check_dim(pts.dim(), "points")?;
    let flat = pts.flat();
    let t = by_dim!(dim, D => param_curve(as_points::<D>(&flat), rule)).map_err(value_error)?;
    Ok(vector_to_array(py, &t))
}

/// grid_parameters(grid, parameterization="chord") -> (u (nu,), v (nv,)): the parameters of
/// a grid (nu, nv, d): 'uniform', 'chord', 'averaged-chord' or 'centripetal'.
#[pyfunction]
#[pyo3(signature = (grid, parameterization = "chord"))]
pub fn grid_parameters<'py>(
    py: Python<'py>,
    grid: &Bound<'py, PyAny>,
    parameterization: &str,
) -> PyResult<(Array<'py>, Array<'py>)> {
    let rule = parse_grid_parameterization(parameterization)?;
    let g = GridArray::extract(grid, "grid")?;
    let dim = check_dim(g.dim(), "grid")?;
    let (u, v) = by_dim!(dim, D => param_grid(&g.grid::<D>()?, rule)).map_err(value_error)?;
    Ok((vector_to_array(py, &u), vector_to_array(py, &v)))
}
