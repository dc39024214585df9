//! Interpolation on parameters (Kuznetsov, Filatov): the Python classes `CubicSpline` and
//! `BicubicSurface`, and the parameterizations of point lists and grids.
//!
//! `karkas.relay_grid`: a grid re-laid along the lines of curvature of its own bicubic
//! interpolant (Kuznetsov and Filatov, Theorem 2.1; docs/methods.md §5), as
//! `karkas surface relay` does.

use std::sync::Arc;

use karkas::param::{
    curve_parameters as param_curve, grid_parameters as param_grid, relay_grid as relay,
    BicubicSurface, CubicSpline, CurveParameterization, GridParameterization, RelayOptions,
    SplineEnds,
};
use numpy::PyArrayDyn;
use pyo3::prelude::*;

use crate::convert::{
    as_points, by_dim, count, creased, extract_vector, grid_to_array, maybe_detach,
    points_to_array, py_bool, small_vector, vector_to_array, FlatPoints, GridArray, Numbers,
    PointsArray,
};
use crate::curve::{Extrapolate, PyCurve};
use crate::erased::{
    in_plane_or_space, CurveImpl, PlaneOrSpace, SurfaceImpl, Wrapped, WrappedSurface,
};
use crate::errors::{library_error, OptionError, PointsError};
use crate::surface::PySurface;

/// A float64 array returned to Python.
type Array<'py> = Bound<'py, PyArrayDyn<f64>>;

/// The curve parameterization named `name` (the library's names, [`CurveParameterization::NAMES`]).
pub fn parse_parameterization(name: &str) -> PyResult<CurveParameterization> {
    name.parse().map_err(library_error)
}

/// The end conditions of a cubic spline as given, for pickling: a name, or the clamped
/// derivatives.
#[derive(Clone)]
pub enum Ends {
    /// 'not-a-knot', 'natural' or 'periodic'.
    Named(&'static str),
    /// ('clamped', start_derivative, end_derivative).
    Clamped(Vec<f64>, Vec<f64>),
}

/// The end conditions named by `bc`: a name, `('clamped', start, end)`, or SciPy's pairs
/// `((order, value), (order, value))` (order 1: clamped; order 2 with zero values: natural).
fn parse_ends<const D: usize>(bc: &Bound<'_, PyAny>) -> PyResult<SplineEnds<D>> {
    if let Ok(name) = bc.extract::<String>() {
        return match name.as_str() {
            "not-a-knot" => Ok(SplineEnds::NotAKnot),
            "natural" => Ok(SplineEnds::Natural),
            "periodic" => Ok(SplineEnds::Periodic),
            "clamped" => Ok(SplineEnds::Clamped {
                start: karkas::Point::ZERO,
                end: karkas::Point::ZERO,
            }),
            _ => Err(OptionError::new_err(format!(
                "unknown bc {name:?} (expected 'not-a-knot', 'natural', 'periodic', 'clamped' \
                 or ('clamped', start_derivative, end_derivative))"
            ))),
        };
    }
    if let Ok((start, end)) = bc.extract::<(Bound<'_, PyAny>, Bound<'_, PyAny>)>() {
        if let (Some(a), Some(b)) = (scipy_end(&start)?, scipy_end(&end)?) {
            return match (a, b) {
                (ScipyEnd::Named(a), ScipyEnd::Named(b)) if a == b => parse_ends(&start),
                (ScipyEnd::Named(_), ScipyEnd::Named(_)) => Err(OptionError::new_err(
                    "bc_type: ends of different kinds are not supported (both ends \
                     'not-a-knot', 'natural', 'clamped' or 'periodic')",
                )),
                (a, b) => scipy_ends::<D>(a.pair(start.py())?, b.pair(end.py())?),
            };
        }
    }
    let (name, start, end): (String, Bound<'_, PyAny>, Bound<'_, PyAny>) =
        bc.extract().map_err(|_| {
            OptionError::new_err(
                "bc must be a name or ('clamped', start_derivative, end_derivative)",
            )
        })?;
    let start = small_vector(&start, "the start derivative of bc")?;
    let end = small_vector(&end, "the end derivative of bc")?;
    if name != "clamped" || start.len() != D || end.len() != D {
        return Err(OptionError::new_err(format!(
            "bc must be ('clamped', start, end) with {D} coordinates each"
        )));
    }
    let mut s = karkas::Point::<D>::ZERO;
    let mut e = karkas::Point::<D>::ZERO;
    s.0.copy_from_slice(&start);
    e.0.copy_from_slice(&end);
    Ok(SplineEnds::Clamped { start: s, end: e })
}

/// One end of SciPy's `bc_type` pairs: a name, or `(order, value)`.
enum ScipyEnd<'py> {
    /// `'not-a-knot'`, `'natural'`, `'clamped'`, `'periodic'`.
    Named(String),
    /// `(order, value)`.
    Pair(i64, Bound<'py, PyAny>),
}

impl<'py> ScipyEnd<'py> {
    /// The end as `(order, value)`: `'natural'` is `(2, 0)`, `'clamped'` `(1, 0)`; other names
    /// have no such form (an `OptionError`).
    fn pair(self, py: Python<'py>) -> PyResult<(i64, Bound<'py, PyAny>)> {
        let zero = || 0.0f64.into_pyobject(py).map(|z| z.into_any());
        match self {
            ScipyEnd::Pair(order, value) => Ok((order, value)),
            ScipyEnd::Named(name) if name == "natural" => Ok((2, zero()?)),
            ScipyEnd::Named(name) if name == "clamped" => Ok((1, zero()?)),
            ScipyEnd::Named(name) => Err(OptionError::new_err(format!(
                "bc_type: '{name}' at one end needs it at the other end too"
            ))),
        }
    }
}

/// One end of a `bc_type` pair as SciPy writes it; `None` for anything else.
fn scipy_end<'py>(end: &Bound<'py, PyAny>) -> PyResult<Option<ScipyEnd<'py>>> {
    if let Ok(name) = end.extract::<String>() {
        return Ok(Some(ScipyEnd::Named(name)));
    }
    Ok(end
        .extract::<(i64, Bound<'py, PyAny>)>()
        .ok()
        .map(|(order, value)| ScipyEnd::Pair(order, value)))
}

/// SciPy's end conditions `((order, value), (order, value))`: first derivatives at both ends
/// (clamped), or zero second derivatives at both (natural). Other forms (a second derivative
/// other than zero, two kinds of ends) are refused: the library's ends are not-a-knot,
/// natural, clamped and periodic.
fn scipy_ends<const D: usize>(
    (o1, v1): (i64, Bound<'_, PyAny>),
    (o2, v2): (i64, Bound<'_, PyAny>),
) -> PyResult<SplineEnds<D>> {
    let (v1, v2) = (&v1, &v2);
    let vector = |v: &Bound<'_, PyAny>, what: &str| -> PyResult<karkas::Point<D>> {
        let values = match v.extract::<f64>() {
            Ok(x) => vec![x; D],
            Err(_) => small_vector(v, what)?,
        };
        if values.len() != D {
            return Err(OptionError::new_err(format!(
                "bc_type: {what} has {} values, the points {D} coordinates",
                values.len()
            )));
        }
        let mut p = karkas::Point::<D>::ZERO;
        p.0.copy_from_slice(&values);
        Ok(p)
    };
    match (o1, o2) {
        (1, 1) => Ok(SplineEnds::Clamped {
            start: vector(v1, "the start derivative")?,
            end: vector(v2, "the end derivative")?,
        }),
        (2, 2) => {
            let zero = |v: karkas::Point<D>| v.0.iter().all(|&x| x == 0.0);
            if zero(vector(v1, "the start second derivative")?)
                && zero(vector(v2, "the end second derivative")?)
            {
                Ok(SplineEnds::Natural)
            } else {
                Err(OptionError::new_err(
                    "bc_type: end second derivatives other than 0 are not supported (the ends \
                     are 'not-a-knot', 'natural', 'clamped' with given first derivatives, or \
                     'periodic')",
                ))
            }
        }
        _ => Err(OptionError::new_err(format!(
            "bc_type: ends of derivative orders {o1} and {o2} are not supported (both 1: \
             clamped; both 2 with value 0: natural)"
        ))),
    }
}

/// A cubic interpolating spline through points (C^2), SciPy's ``CubicSpline`` for parametric
/// curves (Kuznetsov, Filatov).
///
/// The curve passes through ``points[k]`` at ``t[k]``; its domain is ``(t[0], t[-1])``.
/// Calling the curve is described in ``Curve``.
///
/// Outside the domain (the rule of every curve class): a closed curve wraps the parameter by
/// its period; an open curve continues its end polynomial pieces when ``extrapolate`` is None
/// or True (SciPy's ``BSpline`` default; the values of ``BSpline(*c.to_bspline())``) and gives
/// NaN when ``extrapolate=False``.
///
/// Parameters
/// ----------
/// points : array_like
///     The points, shape ``(n, d)``, ``d`` in {2, 3}.
/// t : array_like, optional
///     Strictly increasing parameters ``(n,)``; None: computed from the points by
///     ``parameterization``, starting at 0.
/// parameterization : str, optional
///     ``'uniform'`` (0, 1, 2, ...), ``'chord'`` (chord lengths) or ``'centripetal'``
///     (square roots of chord lengths); ignored when ``t`` is given.
/// bc : str or tuple, optional
///     The end conditions: ``'not-a-knot'`` (when None), ``'natural'``, ``'periodic'`` (closes
///     the curve: the first point is appended unless the last repeats it),
///     ``('clamped', start_derivative, end_derivative)`` or ``'clamped'`` (zero first
///     derivatives, as SciPy's).
/// extrapolate : bool or 'periodic', optional
///     What a call with ``extrapolate=None`` gives outside the domain of an open spline, as
///     SciPy's ``CubicSpline``: the end pieces continued (None, True), NaN (False), or the
///     parameter wrapped into the domain (``'periodic'``).
/// bc_type : str or tuple, optional
///     SciPy's name of ``bc`` (give one of the two), also in SciPy's forms: a pair of ends,
///     each a name or ``(order, value)``, ``((1, start_derivative), (1, end_derivative))``
///     for clamped ends and ``((2, 0), (2, 0))`` for natural ones (``'clamped'`` is
///     ``(1, 0)``, ``'natural'`` ``(2, 0)``); the two ends of one kind.
///
/// Raises
/// ------
/// PointsError
///     Too few points, a non-finite coordinate, coinciding neighbours, or a wrong shape.
/// KnotsError
///     ``t`` is not finite and strictly increasing, or not one per point.
/// OptionError
///     An unknown ``parameterization``, ``bc`` or ``extrapolate``; ``bc`` and ``bc_type``
///     both given; end second derivatives other than zero (``((2, v), ...)``).
///
/// Examples
/// --------
/// >>> pts = np.array([[0.0, 0.0], [1.0, 1.0], [2.0, 0.0], [3.0, 1.0]])
/// >>> c = karkas.CubicSpline(pts, t=[0.0, 1.0, 2.0, 3.0])
/// >>> c.domain
/// (0.0, 3.0)
/// >>> bool(np.allclose(c(c.knots), pts))
/// True
///
/// It equals SciPy's interpolant on the same parameters, and takes SciPy's names:
///
/// >>> from scipy.interpolate import CubicSpline
/// >>> s = np.linspace(0.0, 3.0, 11)
/// >>> bool(np.allclose(c(s), CubicSpline([0.0, 1.0, 2.0, 3.0], pts)(s), atol=1e-12))
/// True
/// >>> n = karkas.CubicSpline(pts, t=[0, 1, 2, 3], bc_type="natural", extrapolate=False)
/// >>> sp = CubicSpline([0, 1, 2, 3], pts, bc_type="natural", extrapolate=False)
/// >>> bool(np.allclose(n(s), sp(s), atol=1e-12)), bool(np.isnan(n(4.0)).all())
/// (True, True)
#[pyclass(extends = PyCurve, module = "karkas", name = "CubicSpline", frozen)]
pub struct PyCubicSpline {
    /// The parameters given (None: computed by the parameterization).
    pub(crate) t: Option<Vec<f64>>,
    /// The parameterization's name as given.
    pub(crate) parameterization: String,
    /// The end conditions.
    pub(crate) ends: Ends,
}

/// The library's cubic spline behind a `CubicSpline`, of either dimension.
type SplineRef<'a> = PlaneOrSpace<'a, CubicSpline<2>, CubicSpline<3>>;

/// The cubic spline behind `base` (always present for a `CubicSpline`): its knots, values and
/// slopes are read from it, not kept twice.
fn spline_of(base: &PyCurve) -> PyResult<SplineRef<'_>> {
    in_plane_or_space(base.inner.library_curve(), "CubicSpline")
}

impl PyCubicSpline {
    /// The points to build it again, for pickling: the spline's values (the points given,
    /// with the seam point a periodic spline appended; built again they give the same
    /// spline).
    pub(crate) fn points_given(slf: &Bound<'_, Self>) -> PyResult<FlatPoints> {
        Ok(match spline_of(slf.as_super().get())? {
            SplineRef::D2(s) => FlatPoints::of(s.values()),
            SplineRef::D3(s) => FlatPoints::of(s.values()),
        })
    }
}

#[pymethods]
impl PyCubicSpline {
    #[new]
    #[pyo3(signature = (points, t = None, parameterization = CurveParameterization::default().name(), bc = None, extrapolate = None, *, bc_type = None))]
    #[pyo3(
        text_signature = "(points, t=None, parameterization='chord', bc=None, extrapolate=None, *, bc_type=None)"
    )]
    #[allow(clippy::too_many_arguments)]
    fn py_new(
        py: Python<'_>,
        points: &Bound<'_, PyAny>,
        t: Option<&Bound<'_, PyAny>>,
        parameterization: &str,
        bc: Option<&Bound<'_, PyAny>>,
        extrapolate: Option<&Bound<'_, PyAny>>,
        bc_type: Option<&Bound<'_, PyAny>>,
    ) -> PyResult<PyClassInitializer<Self>> {
        let extrapolate = Extrapolate::extract(extrapolate)?;
        let bc = match (
            bc.filter(|b| !b.is_none()),
            bc_type.filter(|b| !b.is_none()),
        ) {
            (Some(_), Some(_)) => {
                return Err(OptionError::new_err(
                    "give the end conditions as bc or as bc_type (SciPy's name), not both",
                ))
            }
            (bc, bc_type) => bc.or(bc_type),
        };
        let (pts, dim) = PointsArray::extract_checked(points, "points")?;
        let rule = parse_parameterization(parameterization)?;
        let knots = t.map(|t| extract_vector(t, "t")).transpose()?;
        let flat = pts.flat();
        let n = pts.len();
        let (bc_name, built) = by_dim!(dim, D => {
            let ends: SplineEnds<D> = match bc {
                Some(bc) => parse_ends::<D>(bc)?,
                None => SplineEnds::NotAKnot,
            };
            let p = as_points::<D>(&flat);
            let spline = maybe_detach(py, n, || match &knots {
                Some(knots) => CubicSpline::<D>::new(knots, p, ends),
                None => CubicSpline::<D>::through(p, rule, ends),
            })
            .map_err(library_error)?;
            let (name, given_ends) = match ends {
                SplineEnds::NotAKnot => ("not-a-knot", Ends::Named("not-a-knot")),
                SplineEnds::Natural => ("natural", Ends::Named("natural")),
                SplineEnds::Periodic => ("periodic", Ends::Named("periodic")),
                SplineEnds::Clamped { start, end } => {
                    ("clamped", Ends::Clamped(start.0.to_vec(), end.0.to_vec()))
                }
            };
            let knot_count = spline.knots().len();
            let sub = PyCubicSpline {
                t: knots.clone(),
                parameterization: parameterization.to_string(),
                ends: given_ends,
            };
            let inner: Arc<dyn CurveImpl> = Arc::new(Wrapped::<_, D>(spline));
            (name, (inner, sub, knot_count))
        });
        let (inner, sub, knot_count) = built;
        let params = if knots.is_some() {
            "given t"
        } else {
            parameterization
        };
        let description = format!(
            "<karkas.CubicSpline bc='{bc_name}', parameterization='{params}', {knot_count} knots in {dim}-D"
        );
        let base = PyCurve::new(inner, description).with_extrapolate(extrapolate);
        Ok(PyClassInitializer::from(base).add_subclass(sub))
    }

    /// The knots t_0 < ... < t_{n-1}.
    #[getter]
    fn knots<'py>(slf: &Bound<'py, Self>) -> PyResult<Bound<'py, PyArrayDyn<f64>>> {
        let py = slf.py();
        match spline_of(slf.as_super().get())? {
            SplineRef::D2(s) => vector_to_array(py, s.knots()),
            SplineRef::D3(s) => vector_to_array(py, s.knots()),
        }
    }

    /// The interpolated values P(t_k), (n, d).
    #[getter]
    fn values<'py>(slf: &Bound<'py, Self>) -> PyResult<Bound<'py, PyArrayDyn<f64>>> {
        let py = slf.py();
        match spline_of(slf.as_super().get())? {
            SplineRef::D2(s) => points_to_array(py, s.values()),
            SplineRef::D3(s) => points_to_array(py, s.values()),
        }
    }

    /// The node slopes P'(t_k), (n, d).
    #[getter]
    fn slopes<'py>(slf: &Bound<'py, Self>) -> PyResult<Bound<'py, PyArrayDyn<f64>>> {
        let py = slf.py();
        match spline_of(slf.as_super().get())? {
            SplineRef::D2(s) => points_to_array(py, s.slopes()),
            SplineRef::D3(s) => points_to_array(py, s.slopes()),
        }
    }
}

/// The grid parameterization named `name` (the library's names, [`GridParameterization::NAMES`],
/// those of the command line's `--param` among them).
pub fn parse_grid_parameterization(name: &str) -> PyResult<GridParameterization> {
    name.parse().map_err(library_error)
}

/// The grid rule named `name` with the origin node `origin` of the chord rule (Kuznetsov and
/// Filatov's `(i*, j*)`, the command line's `--origin I,J`) inside a `rows x cols` grid.
pub fn grid_rule(
    name: &str,
    origin: Option<(i64, i64)>,
    (rows, cols): (usize, usize),
) -> PyResult<GridParameterization> {
    let rule = parse_grid_parameterization(name)?;
    let Some((i, j)) = origin else {
        return Ok(rule);
    };
    let (i, j) = (count(i, "origin")?, count(j, "origin")?);
    if !matches!(rule, GridParameterization::Chord { .. }) {
        return Err(OptionError::new_err(format!(
            "origin belongs to parameterization='chord', not {name:?}"
        )));
    }
    if i >= rows || j >= cols {
        return Err(OptionError::new_err(format!(
            "origin ({i}, {j}) is outside the {rows} x {cols} grid"
        )));
    }
    Ok(GridParameterization::Chord {
        origin_row: i,
        origin_col: j,
    })
}

/// Where the parameters of a bicubic surface come from.
#[derive(Clone)]
pub enum GridParameters {
    /// Computed from the grid.
    Rule(GridParameterization),
    /// Given: the u parameters of the rows, the v parameters of the columns.
    Knots(Vec<f64>, Vec<f64>),
}

/// What a bicubic surface was built from, for pickling. The grid itself is not kept: it is
/// the surface's own nodes (the values of an open direction are the grid as given; a closed
/// direction's seam line was made an exact copy of the first, or appended, and pickling drops
/// an appended line), read back by [`PyBicubicSurface::grid_given`].
pub struct BicubicInput {
    /// The rows and columns of the grid given.
    pub shape: (usize, usize),
    /// The parameterization's name, or the knots given.
    pub how: Result<String, (Vec<f64>, Vec<f64>)>,
    /// Closed in u, in v.
    pub closed: (bool, bool),
    /// The origin node of the chord rule, as given.
    pub origin: Option<(i64, i64)>,
}

/// Bicubic interpolation of a grid of points (Kuznetsov, Filatov): a C^2 surface through every
/// grid point, on parameters computed from the grid.
///
/// Not-a-knot ends in an open direction, periodic in a closed one.
/// ``BicubicSurface.from_knots`` takes the parameters instead. Calling the surface is
/// described in ``Surface``.
///
/// Outside the domain (the rule of every surface class, per direction): a closed direction
/// wraps the parameter by its period; an open one continues the end polynomial pieces when
/// ``extrapolate`` is None or True (the values of ``NdBSpline(*S.to_bspline())``) and gives
/// NaN when ``extrapolate=False``.
///
/// Parameters
/// ----------
/// grid : array_like
///     The grid, shape ``(nu, nv, d)``, ``d`` in {2, 3}.
/// parameterization : str, optional
///     ``'uniform'``, ``'chord'`` (chord lengths along the first column for ``u`` and the
///     first row for ``v``), ``'averaged'`` or ``'averaged-chord'`` (averaged over all rows
///     and columns) or ``'centripetal'``; the command line's ``--param`` names.
/// closed_u, closed_v : bool, optional
///     Closed (periodic) in ``u``, in ``v``.
/// origin : tuple of int, optional
///     ``(i, j)``: the origin node of ``'chord'`` (the paper's ``(i*, j*)``, the command
///     line's ``--origin I,J``): ``u`` is the chord length along column ``j``, ``v`` along row
///     ``i``, both zero at the node. Default ``(0, 0)``.
/// crease_u, crease_v : bool, optional
///     Close the surface in ``u`` (``v``) with a crease, a ``C^0`` seam (a wing's sharp
///     trailing edge stays sharp): the first row (column) is appended after the last unless
///     the last repeats it, and the direction is interpolated as an open one (``karkas
///     surface bicubic --crease-u/--crease-v``). Not with ``closed_u`` (``closed_v``).
///
/// Raises
/// ------
/// PointsError
///     Too few grid points, a non-finite coordinate, coinciding neighbours, or a wrong shape.
/// OptionError
///     An unknown ``parameterization``, an ``origin`` outside the grid or given with another
///     parameterization than ``'chord'``; a crease in a direction also closed.
///
/// Examples
/// --------
/// >>> grid = np.array([[[i, j, i * j] for j in range(4)] for i in range(3)], float)
/// >>> S = karkas.BicubicSurface(grid, parameterization="uniform")
/// >>> S.knots_u, S.knots_v
/// (array([0., 1., 2.]), array([0., 1., 2., 3.]))
/// >>> bool(np.allclose(S(S.knots_u, S.knots_v), grid))
/// True
///
/// A wing of sharp-edged sections closed with a crease at the trailing edge, capped at root
/// and tip into a solid:
///
/// >>> t = np.linspace(0, 2 * np.pi, 13)[:-1]
/// >>> foil = np.stack([0.5 + 0.5 * np.cos(t), 0.06 * np.sin(t) * (1 - np.cos(t)) ** 0.5], axis=-1)
/// >>> wing = np.array([[[x, y, z] for x, y in foil] for z in (0.0, 1.0, 2.0)])
/// >>> W = karkas.BicubicSurface(wing, crease_v=True)
/// >>> W.knots_v.size
/// 13
/// >>> import os, tempfile
/// >>> path = karkas.export(W, os.path.join(tempfile.mkdtemp(), "wing.step"), cap=True)
/// >>> "MANIFOLD_SOLID_BREP" in open(path).read()
/// True
#[pyclass(extends = PySurface, module = "karkas", name = "BicubicSurface", frozen)]
pub struct PyBicubicSurface {
    /// The u parameters of the grid rows (a closed direction includes the closing step).
    #[pyo3(get)]
    knots_u: Numbers,
    /// The v parameters of the grid columns.
    #[pyo3(get)]
    knots_v: Numbers,
    /// What it was built from (for pickling).
    pub(crate) input: BicubicInput,
}

/// The library's bicubic surface behind a `BicubicSurface`, of either dimension.
type BicubicRef<'a> = PlaneOrSpace<'a, BicubicSurface<2>, BicubicSurface<3>>;

/// The bicubic surface behind `base` (always present for a `BicubicSurface`).
fn bicubic_of(base: &PySurface) -> PyResult<BicubicRef<'_>> {
    in_plane_or_space(base.inner.library_surface(), "BicubicSurface")
}

/// The nodes `r_ij`, `i < rows`, `j < cols`, row-major.
fn nodes_of<const D: usize>(s: &BicubicSurface<D>, (rows, cols): (usize, usize)) -> FlatPoints {
    let mut coords = Vec::with_capacity(rows * cols * D);
    for i in 0..rows {
        for j in 0..cols {
            coords.extend_from_slice(&s.node(i, j).0);
        }
    }
    FlatPoints { coords, dim: D }
}

impl PyBicubicSurface {
    /// The grid as given, for pickling: the surface's nodes over the given shape (an
    /// appended seam line left out).
    pub(crate) fn grid_given(slf: &Bound<'_, Self>) -> PyResult<FlatPoints> {
        let shape = slf.get().input.shape;
        Ok(match bicubic_of(slf.as_super().get())? {
            BicubicRef::D2(s) => nodes_of(s, shape),
            BicubicRef::D3(s) => nodes_of(s, shape),
        })
    }

    fn build(
        py: Python<'_>,
        grid: &Bound<'_, PyAny>,
        how: Result<&str, (Vec<f64>, Vec<f64>)>,
        closed_u: bool,
        closed_v: bool,
        origin: Option<(i64, i64)>,
        crease: (bool, bool),
    ) -> PyResult<PyClassInitializer<Self>> {
        let (g, dim) = GridArray::extract_checked(grid, "grid")?;
        let mut input = BicubicInput {
            shape: g.rows_cols(),
            how: how.clone().map(str::to_string),
            closed: (closed_u, closed_v),
            origin,
        };
        let (label, parameters) = match how {
            Ok(name) => (
                name.to_string(),
                GridParameters::Rule(grid_rule(name, origin, g.rows_cols())?),
            ),
            Err((ku, kv)) => ("given knots".to_string(), GridParameters::Knots(ku, kv)),
        };
        let (sub, inner, rows, cols): (Self, Arc<dyn SurfaceImpl>, usize, usize) = by_dim!(dim, D => {
            // One copy of the input: the surface keeps it as its values. A creased grid is
            // closed by its appended line and pickled as the open grid it then is.
            let grid = creased(g.grid::<D>()?, crease, (closed_u, closed_v))?;
            let (rows, cols) = (grid.rows(), grid.cols());
            input.shape = (rows, cols);
            let surface = maybe_detach(py, rows * cols, || match &parameters {
                GridParameters::Knots(ku, kv) => BicubicSurface::<D>::from_grid_knots(grid, ku, kv, closed_u, closed_v),
                GridParameters::Rule(rule) => BicubicSurface::<D>::from_grid(grid, *rule, closed_u, closed_v),
            })
            .map_err(library_error)?;
            let sub = PyBicubicSurface {
                knots_u: Numbers(surface.knots_u().to_vec()),
                knots_v: Numbers(surface.knots_v().to_vec()),
                input,
            };
            (sub, Arc::new(WrappedSurface::<_, D>(surface)), rows, cols)
        });
        let description = format!(
            "<karkas.BicubicSurface parameterization='{label}', closed_u={}, closed_v={}, {rows}x{cols} grid in {dim}-D",
            py_bool(closed_u),
            py_bool(closed_v)
        );
        Ok(PyClassInitializer::from(PySurface::new(inner, description)).add_subclass(sub))
    }
}

#[pymethods]
impl PyBicubicSurface {
    #[new]
    #[pyo3(signature = (grid, parameterization = GridParameterization::DEFAULT_NAME, closed_u = false, closed_v = false, origin = None, crease_u = false, crease_v = false))]
    #[pyo3(
        text_signature = "(grid, parameterization='chord', closed_u=False, closed_v=False, origin=None, crease_u=False, crease_v=False)"
    )]
    #[allow(clippy::too_many_arguments)]
    fn py_new(
        py: Python<'_>,
        grid: &Bound<'_, PyAny>,
        parameterization: &str,
        closed_u: bool,
        closed_v: bool,
        origin: Option<(i64, i64)>,
        crease_u: bool,
        crease_v: bool,
    ) -> PyResult<PyClassInitializer<Self>> {
        let how = Ok(parameterization);
        let crease = (crease_u, crease_v);
        Self::build(py, grid, how, closed_u, closed_v, origin, crease)
    }

    /// How well the parameters condition the continuation system at every node (Kuznetsov
    /// and Filatov's measure (2.4), extended to tangents of any length; ``surface bicubic
    /// --report`` on the command line).
    ///
    /// At a node with tangents ``W_u``, ``W_v`` it is ``min(1, s2) / max(1, s1)`` for the
    /// singular values ``s1 >= s2`` of ``[W_u W_v]``: the inverse 2-norm condition number of
    /// ``[alpha; beta; n]`` (``alpha``, ``beta`` the dual basis of the tangents, ``n`` the unit
    /// normal). It is 1 exactly for arc lengths along orthogonal directions (Theorem 2.1) and
    /// smaller otherwise: ``tan(theta / 2)`` for unit tangents at an angle ``theta``,
    /// ``min(1, a, b) / max(1, a, b)`` for orthogonal tangents of lengths ``a``, ``b``.
    ///
    /// Parameters
    /// ----------
    /// paper : bool, optional
    ///     The paper's own ``|D|`` of (2.4) instead (rows scaled to unit length): the sine of
    ///     the angle between the parameter lines, ``sqrt(E G - F^2) / sqrt(E G)``, blind to
    ///     stretched parameters (the second line of ``--report``).
    ///
    /// Returns
    /// -------
    /// numpy.ndarray
    ///     float64, shape ``(nu, nv)`` of the grid (a closed direction includes its repeated
    ///     seam line, like ``knots_u``, ``knots_v``), values in ``[0, 1]``.
    ///
    /// Raises
    /// ------
    /// TypeError
    ///     If ``paper`` is not a bool.
    ///
    /// Examples
    /// --------
    /// >>> grid = np.array([[[i, j, 0.0] for j in range(3)] for i in range(3)], float)
    /// >>> m = karkas.BicubicSurface(grid).condition_measure()
    /// >>> m.shape, bool(np.allclose(m, 1.0))
    /// ((3, 3), True)
    /// >>> stretched = karkas.BicubicSurface(grid * [2.0, 1.0, 1.0], "uniform")
    /// >>> bool(np.allclose(stretched.condition_measure(), 0.5))
    /// True
    /// >>> bool(np.allclose(stretched.condition_measure(paper=True), 1.0))
    /// True
    #[pyo3(signature = (paper = false))]
    #[pyo3(text_signature = "($self, paper=False)")]
    fn condition_measure<'py>(slf: &Bound<'py, Self>, paper: bool) -> PyResult<Bound<'py, PyAny>> {
        let measures = match (bicubic_of(slf.as_super().get())?, paper) {
            (BicubicRef::D2(s), false) => s.condition_measures(),
            (BicubicRef::D3(s), false) => s.condition_measures(),
            (BicubicRef::D2(s), true) => s.paper_condition_measures(),
            (BicubicRef::D3(s), true) => s.paper_condition_measures(),
        };
        let flat = vector_to_array(slf.py(), measures.as_slice())?;
        flat.call_method1("reshape", ((measures.rows(), measures.cols()),))
    }

    /// The bicubic interpolant of a grid on given parameters.
    ///
    /// Parameters
    /// ----------
    /// grid : array_like
    ///     The grid, shape ``(nu, nv, d)``, ``d`` in {2, 3}; a closed direction's last grid
    ///     line must repeat its first.
    /// knots_u : array_like
    ///     The ``u`` parameters of the rows, ``(nu,)``, strictly increasing.
    /// knots_v : array_like
    ///     The ``v`` parameters of the columns, ``(nv,)``, strictly increasing.
    /// closed_u, closed_v : bool, optional
    ///     Closed (periodic) in ``u``, in ``v``.
    ///
    /// Returns
    /// -------
    /// BicubicSurface
    ///     The surface through ``grid[i, j]`` at ``(knots_u[i], knots_v[j])``.
    ///
    /// Raises
    /// ------
    /// PointsError
    ///     Too few grid points, a non-finite coordinate, or a wrong shape.
    /// KnotsError
    ///     Knots not finite and strictly increasing, or not one per grid line.
    ///
    /// Examples
    /// --------
    /// >>> grid = np.array([[[i, j, i * j] for j in range(4)] for i in range(3)], float)
    /// >>> S = karkas.BicubicSurface.from_knots(grid, [0.0, 0.5, 1.0], [0.0, 1.0, 2.0, 4.0])
    /// >>> bool(np.allclose(S(0.5, 4.0), grid[1, 3]))
    /// True
    #[staticmethod]
    #[pyo3(signature = (grid, knots_u, knots_v, closed_u = false, closed_v = false))]
    fn from_knots(
        py: Python<'_>,
        grid: &Bound<'_, PyAny>,
        knots_u: &Bound<'_, PyAny>,
        knots_v: &Bound<'_, PyAny>,
        closed_u: bool,
        closed_v: bool,
    ) -> PyResult<Py<Self>> {
        let ku = extract_vector(knots_u, "knots_u")?;
        let kv = extract_vector(knots_v, "knots_v")?;
        Py::new(
            py,
            Self::build(
                py,
                grid,
                Err((ku, kv)),
                closed_u,
                closed_v,
                None,
                (false, false),
            )?,
        )
    }
}

/// The parameters of a list of points, starting at 0, as ``CubicSpline`` computes them.
///
/// Parameters
/// ----------
/// points : array_like
///     The points, shape ``(n, d)``, ``d`` in {2, 3}.
/// parameterization : str, optional
///     ``'uniform'`` (0, 1, 2, ...), ``'chord'`` (cumulative chord lengths) or
///     ``'centripetal'`` (cumulative square roots of chord lengths).
///
/// Returns
/// -------
/// numpy.ndarray
///     float64, shape ``(n,)``.
///
/// Raises
/// ------
/// PointsError
///     Too few points, a non-finite coordinate, coinciding neighbours, or a wrong shape.
/// OptionError
///     An unknown ``parameterization``.
///
/// Examples
/// --------
/// >>> pts = [[0.0, 0.0], [3.0, 4.0], [3.0, 5.0]]
/// >>> karkas.curve_parameters(pts, "chord")
/// array([0., 5., 6.])
/// >>> karkas.curve_parameters(pts, "uniform")
/// array([0., 1., 2.])
#[pyfunction]
#[pyo3(signature = (points, parameterization = "chord"))]
pub fn curve_parameters<'py>(
    py: Python<'py>,
    points: &Bound<'py, PyAny>,
    parameterization: &str,
) -> PyResult<Bound<'py, PyArrayDyn<f64>>> {
    let rule = parse_parameterization(parameterization)?;
    let (pts, dim) = PointsArray::extract_checked(points, "points")?;
    let flat = pts.flat();
    let t = by_dim!(dim, D => param_curve(as_points::<D>(&flat), rule)).map_err(library_error)?;
    vector_to_array(py, &t)
}

/// The parameters of a grid of points, as ``BicubicSurface`` computes them.
///
/// Parameters
/// ----------
/// grid : array_like
///     The grid, shape ``(nu, nv, d)``, ``d`` in {2, 3}.
/// parameterization : str, optional
///     ``'uniform'``, ``'chord'`` (chord lengths along the first column for ``u`` and the
///     first row for ``v``), ``'averaged-chord'`` or ``'centripetal'``.
/// origin : tuple of int, optional
///     ``(i, j)``: the origin node of ``'chord'``: ``u`` along column ``j``, ``v`` along row
///     ``i``, both zero at the node (default ``(0, 0)``).
///
/// Returns
/// -------
/// u : numpy.ndarray
///     float64, shape ``(nu,)``, the parameters of the rows, from 0.
/// v : numpy.ndarray
///     float64, shape ``(nv,)``, the parameters of the columns, from 0.
///
/// Raises
/// ------
/// PointsError
///     Too few grid points, a non-finite coordinate, coinciding neighbours, or a wrong shape.
/// OptionError
///     An unknown ``parameterization``.
///
/// Examples
/// --------
/// >>> grid = np.array([[[2.0 * i, 3.0 * j] for j in range(3)] for i in range(2)])
/// >>> karkas.grid_parameters(grid, "chord")
/// (array([0., 2.]), array([0., 3., 6.]))
#[pyfunction]
#[pyo3(signature = (grid, parameterization = "chord", origin = None))]
pub fn grid_parameters<'py>(
    py: Python<'py>,
    grid: &Bound<'py, PyAny>,
    parameterization: &str,
    origin: Option<(i64, i64)>,
) -> PyResult<(Array<'py>, Array<'py>)> {
    let (g, dim) = GridArray::extract_checked(grid, "grid")?;
    let rule = grid_rule(parameterization, origin, g.rows_cols())?;
    let (u, v) = by_dim!(dim, D => param_grid(&g.grid::<D>()?, rule)).map_err(library_error)?;
    Ok((vector_to_array(py, &u)?, vector_to_array(py, &v)?))
}

/// Re-lays a grid of 3-D points along the lines of curvature of its bicubic interpolant.
///
/// The interpolant (chord-length parameters, not-a-knot ends) is built, the two families of
/// lines of curvature are traced through the start node, spaced by arc length, and node
/// ``(i, j)`` of the new grid is the crossing of the ``i``-th ``v`` line with the ``j``-th
/// ``u`` line (Kuznetsov and Filatov: arc lengths along lines of curvature are the best
/// parameters). The new nodes lie on the input's interpolant, so they are only as accurate
/// as it is.
///
/// Parameters
/// ----------
/// grid : array_like
///     ``(nu, nv, 3)`` points.
/// size : tuple of int, optional
///     Rows and columns ``(M, N)`` of the new grid, each at least 2; default the input's.
/// start : tuple of int, optional
///     The start node ``(i, j)`` of the input; default its centre.
///
/// Returns
/// -------
/// numpy.ndarray
///     float64, shape ``(M, N, 3)``, the re-laid nodes.
///
/// Raises
/// ------
/// PointsError
///     A grid that is not ``(nu, nv, 3)``, too small or with coinciding nodes, a size below
///     2, a start outside the grid, or an umbilic region (a plane or a sphere: the principal
///     directions are undefined).
/// ConvergenceError
///     A singular point, or a net that does not fit the interpolant's domain.
///
/// Examples
/// --------
/// A grid on the unit cylinder along helices turned by 30 degrees comes back to circles
/// ``z = const`` (its rows or its columns):
///
/// >>> a = np.radians(30.0)
/// >>> s, t = np.meshgrid(np.linspace(-0.6, 0.6, 9), np.linspace(-0.9, 0.9, 13), indexing="ij")
/// >>> z, angle = np.cos(a) * s - np.sin(a) * t, np.sin(a) * s + np.cos(a) * t
/// >>> grid = np.stack([np.cos(angle), np.sin(angle), z], axis=-1)
/// >>> relaid = karkas.relay_grid(grid, size=(5, 7))
/// >>> relaid.shape
/// (5, 7, 3)
/// >>> bool(min(np.ptp(relaid[..., 2], axis=1).max(), np.ptp(relaid[..., 2], axis=0).max()) < 1e-3)
/// True
#[pyfunction]
#[pyo3(signature = (grid, size = None, start = None))]
pub fn relay_grid<'py>(
    py: Python<'py>,
    grid: &Bound<'py, PyAny>,
    size: Option<(usize, usize)>,
    start: Option<(usize, usize)>,
) -> PyResult<Bound<'py, PyArrayDyn<f64>>> {
    let (g, dim) = GridArray::extract_checked(grid, "grid")?;
    if dim != 3 {
        return Err(PointsError::new_err(format!(
            "grid: relay_grid needs 3-D points, got {dim}-D"
        )));
    }
    let nodes = g.grid::<3>()?;
    let options = RelayOptions {
        size,
        start,
        ..RelayOptions::default()
    };
    let relaid = relay(&nodes, &options).map_err(library_error)?;
    grid_to_array(py, &relaid.nodes)
}
