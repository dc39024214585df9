//! Generalized Coons surfaces (Chashnikov): the Python class `CoonsSurface`.

use std::sync::Arc;

use karkas::coons::{
    CoonsKind, CoonsSurface, CrossDerivatives, CurveFit, PointNetwork, CROSSING_TOLERANCE,
    POINT_NETWORK_TOLERANCE,
};
use karkas::{Grid, Point};
use pyo3::prelude::*;

use crate::convert::{
    as_points, by_dim, check_dim, count, object_list, FlatPoints, GridArray, Int, PointsArray,
};
use crate::erased::{SurfaceImpl, WrappedSurface};
use crate::errors::{library_error, KarkasWarning, OptionError, PointsError};
use crate::limits::{bytes_of, check_memory};
use crate::surface::PySurface;

/// A list of point arrays (each (k, d)) as karkas point lists of dimension `D`.
///
/// The copies together are checked against `karkas.max_memory` before each is made (a list
/// of broadcast views can be small in memory and huge once copied).
fn point_lists<const D: usize>(
    lists: &[Bound<'_, PyAny>],
    what: &str,
) -> PyResult<Vec<Vec<Point<D>>>> {
    let of_dimension = |i, pts: &PointsArray<'_>| match pts.dim() {
        d if d == D => Ok(()),
        d => Err(PointsError::new_err(format!(
            "{what}[{i}] has {d} coordinates per point, expected {D}"
        ))),
    };
    let copy = |pts: &PointsArray<'_>| as_points::<D>(&pts.flat()).to_vec();
    counted_copies(lists, what, of_dimension, copy)
}

/// The arrays of a list (each (k, d), read as `what[i]`) each checked by `check`, then its
/// copy by `copy` counted with the copies before it against `karkas.max_memory`.
fn counted_copies<'py, T>(
    lists: &[Bound<'py, PyAny>],
    what: &str,
    check: impl Fn(usize, &PointsArray<'py>) -> PyResult<()>,
    copy: impl Fn(&PointsArray<'py>) -> T,
) -> PyResult<Vec<T>> {
    let mut total: u128 = 0;
    lists
        .iter()
        .enumerate()
        .map(|(i, obj)| {
            let pts = PointsArray::extract(obj, &format!("{what}[{i}]"))?;
            check(i, &pts)?;
            total = total.saturating_add(bytes_of(&[pts.len(), pts.dim()], 8));
            check_memory(obj.py(), &format!("{what}[..{}]", i + 1), total)?;
            Ok(copy(&pts))
        })
        .collect()
}

/// The dimension of the first array of a list.
fn first_dim(lists: &[Bound<'_, PyAny>], what: &str) -> PyResult<usize> {
    let first = lists
        .first()
        .ok_or_else(|| PointsError::new_err(format!("{what} must not be empty")))?;
    check_dim(
        PointsArray::extract(first, &format!("{what}[0]"))?.dim(),
        what,
    )
}

/// Generalized Coons surfaces (Chashnikov) over a network of curves given by points.
///
/// Each curve of the network is a ``(k, d)`` array of points, interpolated by a not-a-knot
/// cubic spline (``fit='spline'``) or an interpolating LL curve (``fit=('ll', order)``); the
/// surface spans the network. A family whose curves repeat their first point at the end is
/// closed. Calling the surface is described in ``Surface``. Both families are keyword-only
/// arguments, named as ``karkas surface coons``'s ``--u-curves`` and ``--v-curves``.
///
/// Outside the domain (the rule of every surface class, per direction): a closed direction
/// wraps the parameter by its period; an open one continues the end polynomial pieces when
/// ``extrapolate`` is None or True (the values of ``NdBSpline(*S.to_bspline())``) and gives
/// NaN when ``extrapolate=False``.
///
/// Parameters
/// ----------
/// v_curves : sequence of array_like
///     The curves along ``v``, listed by increasing ``u``.
/// u_curves : sequence of array_like
///     The curves along ``u``, listed by increasing ``v``; every one crosses every curve of
///     ``v_curves``.
/// kind : str, optional
///     ``'bilinear'`` and ``'bicubic'`` (two curves a family), ``'gordon'`` (Lagrange
///     blending), ``'gordon-spline'`` (cubic-spline blending) or ``'composite'`` (C^1
///     piecewise bicubic).
/// u_derivs, v_derivs : sequence of array_like, optional
///     For ``'bicubic'`` and ``'composite'``: dS/dv along the u-curves and dS/du along the
///     v-curves, one vector per point (give both or neither). Without them they are built
///     from the twists.
/// twists : array_like, optional
///     For ``'bicubic'`` and ``'composite'``, not with ``u_derivs``: the twist vectors
///     d2S/dudv at the crossings, shape ``(len(v_curves), len(u_curves), d)`` (entry
///     ``[i, j]`` where v-curve ``i`` crosses u-curve ``j``), per unit of the surface
///     parameters; the cross-derivatives are then the cubic Hermite curves of the curves'
///     tangents and these twists (Chashnikov's §4). Without them, twists by the
///     spline-of-derivatives rule.
/// fit : str or tuple, optional
///     How a curve is made from its points: ``'spline'`` (when None) or ``('ll', order)``.
/// crossing_tolerance : float, optional
///     How far apart two curves may pass and still count as crossing.
/// tolerance : float, optional
///     The tolerance of the network's compatibility checks.
///
/// Raises
/// ------
/// PointsError
///     An empty family, a curve of too few points, or a wrong shape or dimension.
/// IncompatibleDataError
///     Curves that do not cross where they must.
/// OptionError
///     An unknown ``kind`` or ``fit``, derivatives for one family only, or twists with
///     derivatives or with a kind that takes neither.
///
/// Warns
/// -----
/// KarkasWarning
///     ``kind='bicubic'`` without ``u_derivs`` and ``v_derivs``: the cross-boundary
///     derivatives are then taken from the two curves of each family, and even a cubic
///     surface is missed.
///
/// Examples
/// --------
/// A bilinear patch over four straight edges:
///
/// >>> s = np.linspace(0.0, 1.0, 5)
/// >>> line = lambda a, b: np.outer(1 - s, a) + np.outer(s, b)
/// >>> v_curves = [line([0, 0, 0], [0, 1, 0]), line([1, 0, 1], [1, 1, 1])]
/// >>> u_curves = [line([0, 0, 0], [1, 0, 1]), line([0, 1, 0], [1, 1, 1])]
/// >>> S = karkas.CoonsSurface(v_curves=v_curves, u_curves=u_curves, kind="bilinear")
/// >>> S.kind
/// 'bilinear'
/// >>> a, b = S.domain_u
/// >>> c, d = S.domain_v
/// >>> np.round(S((a + b) / 2, (c + d) / 2), 6)
/// array([0.5, 0.5, 0.5])
#[pyclass(extends = PySurface, module = "karkas", name = "CoonsSurface", frozen)]
pub struct PyCoonsSurface {
    /// The kind of surface (``'bilinear'``, ``'bicubic'``, ``'gordon'``, ``'gordon-spline'``
    /// or ``'composite'``).
    #[pyo3(get)]
    kind: String,
    /// What it was built from (for pickling).
    pub(crate) input: CoonsInput,
}

/// The inputs of a Coons surface, for pickling.
pub struct CoonsInput {
    /// The u-curves and the v-curves.
    pub curves: (Vec<FlatPoints>, Vec<FlatPoints>),
    /// The cross-derivatives along the u-curves and along the v-curves.
    pub derivs: Option<(Vec<FlatPoints>, Vec<FlatPoints>)>,
    /// The twists: rows, columns and the points row-major.
    pub twists: Option<(usize, usize, FlatPoints)>,
    /// How the curves interpolate their points.
    pub fit: CurveFit,
    /// The crossing tolerance and the compatibility tolerance.
    pub tolerances: (f64, f64),
}

/// The point arrays of a list (each (k, d)), copied.
fn given(lists: &[Bound<'_, PyAny>], what: &str) -> PyResult<Vec<FlatPoints>> {
    counted_copies(
        lists,
        what,
        |_, _| Ok(()),
        |pts| FlatPoints {
            coords: pts.flat().into_owned(),
            dim: pts.dim(),
        },
    )
}

/// The fit of the curves' points from `fit=`: `None` or `'spline'`, or `('ll', order)`.
fn curve_fit(fit: Option<Bound<'_, PyAny>>) -> PyResult<CurveFit> {
    let Some(f) = fit else {
        return Ok(CurveFit::CubicSpline);
    };
    if let Ok(name) = f.extract::<String>() {
        return match name.as_str() {
            "spline" => Ok(CurveFit::CubicSpline),
            _ => Err(OptionError::new_err(format!(
                "unknown fit {name:?} (expected 'spline' or ('ll', order))"
            ))),
        };
    }
    let (name, order): (String, Int) = f
        .extract()
        .map_err(|_| OptionError::new_err("fit must be 'spline' or ('ll', order)"))?;
    if name != "ll" {
        return Err(OptionError::new_err(
            "fit must be 'spline' or ('ll', order)",
        ));
    }
    Ok(CurveFit::Ll(count(order, "order")?))
}

/// Refuses `twists=` where `kind` does not use them, or given with `u_derivs` and `v_derivs`.
fn check_twists(kind: CoonsKind, twists: bool, derivs: bool) -> PyResult<()> {
    if twists && !kind.takes_cross_derivatives() {
        return Err(OptionError::new_err(
            "twists are used only by kind 'bicubic' and 'composite'",
        ));
    }
    if twists && derivs {
        return Err(OptionError::new_err(
            "give twists or u_derivs and v_derivs, not both",
        ));
    }
    Ok(())
}

/// The twists `t` as a grid of points of dimension `D`, the curves' dimension.
fn twists_grid<const D: usize>(t: &GridArray) -> PyResult<Grid<Point<D>>> {
    if t.dim() != D {
        return Err(PointsError::new_err(format!(
            "twists have {} coordinates per point, expected {D}",
            t.dim()
        )));
    }
    t.grid::<D>()
}

/// The twists as [`CoonsInput`] keeps them: rows, columns and the points row-major.
fn twists_input(t: &GridArray) -> (usize, usize, FlatPoints) {
    let (rows, cols) = t.rows_cols();
    let flat = FlatPoints {
        coords: t.flat().into_owned(),
        dim: t.dim(),
    };
    (rows, cols, flat)
}

/// Warns (as `karkas surface coons --kind bicubic` does) that kind 'bicubic' without
/// `u_derivs` and `v_derivs` takes the cross-boundary derivatives from the curves.
fn warn_bicubic_from_curves(py: Python<'_>) -> PyResult<()> {
    let message = c"kind 'bicubic' without u_derivs and v_derivs takes the cross-boundary \
        derivatives from the two curves of each family (their tangents and the twists), \
        which misses even a surface the operator reproduces from its own derivatives (a \
        cubic); give u_derivs and v_derivs (--u-derivs/--v-derivs) to interpolate them";
    PyErr::warn(py, &py.get_type::<KarkasWarning>(), message, 1)
}

#[pymethods]
impl PyCoonsSurface {
    #[new]
    #[pyo3(signature = (*, u_curves, v_curves, kind = "gordon-spline", u_derivs = None, v_derivs = None, fit = None, crossing_tolerance = CROSSING_TOLERANCE, tolerance = POINT_NETWORK_TOLERANCE, twists = None))]
    #[pyo3(
        text_signature = "(*, u_curves, v_curves, kind='gordon-spline', u_derivs=None, v_derivs=None, fit=None, crossing_tolerance=1e-06, tolerance=0.0001, twists=None)"
    )]
    #[allow(clippy::too_many_arguments)]
    fn py_new(
        py: Python<'_>,
        u_curves: &Bound<'_, PyAny>,
        v_curves: &Bound<'_, PyAny>,
        kind: &str,
        u_derivs: Option<&Bound<'_, PyAny>>,
        v_derivs: Option<&Bound<'_, PyAny>>,
        fit: Option<Bound<'_, PyAny>>,
        crossing_tolerance: f64,
        tolerance: f64,
        twists: Option<&Bound<'_, PyAny>>,
    ) -> PyResult<PyClassInitializer<Self>> {
        let fit = curve_fit(fit)?;
        let kind: CoonsKind = kind.parse().map_err(library_error)?;
        check_twists(
            kind,
            twists.is_some(),
            u_derivs.is_some() || v_derivs.is_some(),
        )?;
        let twists = twists
            .map(|t| GridArray::extract(t, "twists"))
            .transpose()?;
        let v_curves = object_list(v_curves, "v_curves")?;
        let u_curves = object_list(u_curves, "u_curves")?;
        let u_derivs = u_derivs.map(|d| object_list(d, "u_derivs")).transpose()?;
        let v_derivs = v_derivs.map(|d| object_list(d, "v_derivs")).transpose()?;
        let input = CoonsInput {
            curves: (given(&u_curves, "u_curves")?, given(&v_curves, "v_curves")?),
            derivs: match (&u_derivs, &v_derivs) {
                (Some(du), Some(dv)) => Some((given(du, "u_derivs")?, given(dv, "v_derivs")?)),
                _ => None,
            },
            twists: twists.as_ref().map(twists_input),
            fit,
            tolerances: (crossing_tolerance, tolerance),
        };
        if kind.name() == "bicubic" && u_derivs.is_none() {
            warn_bicubic_from_curves(py)?;
        }
        let dim = first_dim(&v_curves, "v_curves")?;
        let (inner, counts): (Arc<dyn SurfaceImpl>, (usize, usize)) = by_dim!(dim, D => {
            let v = point_lists::<D>(&v_curves, "v_curves")?;
            let u = point_lists::<D>(&u_curves, "u_curves")?;
            let derivs = match (&u_derivs, &v_derivs) {
                (Some(du), Some(dv)) => Some((point_lists::<D>(du, "u_derivs")?, point_lists::<D>(dv, "v_derivs")?)),
                (None, None) => None,
                _ => return Err(OptionError::new_err("give both u_derivs and v_derivs, or neither")),
            };
            let twists = twists.as_ref().map(twists_grid::<D>).transpose()?;
            let surface = py.detach(|| -> karkas::Result<CoonsSurface<D>> {
                let network = PointNetwork::new(&v, &u, fit, crossing_tolerance)?;
                let cross = match (&derivs, &twists) {
                    (Some((du, dv)), _) => Some(network.cross_derivatives(dv, du)?),
                    (None, Some(t)) => Some(CrossDerivatives::from_twists(network.network(), t)?),
                    (None, None) => None,
                };
                kind.build(network.network(), cross.as_ref(), tolerance)
            })
            .map_err(library_error)?;
            (Arc::new(WrappedSurface::<_, D>(surface)) as Arc<dyn SurfaceImpl>, (v.len(), u.len()))
        });
        let description = format!(
            "<karkas.CoonsSurface kind='{}', {} u-curves x {} v-curves in {dim}-D",
            kind.name(),
            counts.1,
            counts.0
        );
        Ok(
            PyClassInitializer::from(PySurface::new(inner, description)).add_subclass(
                PyCoonsSurface {
                    kind: kind.name().to_string(),
                    input,
                },
            ),
        )
    }
}
