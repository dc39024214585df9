//! Discrete periodic splines (Malozemov, Khorokhonov, Chashnikov): `DiscreteSpline` and
//! `TubeSurface`.

use karkas::dps::{DiscreteSpline, TubeSurface, DEFAULT_ORDER, DEFAULT_STEP, DEFAULT_TUBE_ORDER};
use karkas::{Grid, Point};
use numpy::PyArrayDyn;
use pyo3::prelude::*;

use crate::convert::{
    as_points, as_points_mut, by_dim, check_dim, count, each, grid_to_array, maybe_detach,
    output_array, points_to_array, variant, write_flat, ByDim, FlatPoints, GridArray, Int,
    PointsArray,
};
use crate::errors::{library_error, PointsError};
use crate::limits::{bytes_of, check_memory};

/// The dimension `D` of points.
fn point_dim<const D: usize>(_: &[Point<D>]) -> usize {
    D
}

/// A discrete spline of either dimension.
type AnySpline = ByDim<DiscreteSpline<2>, DiscreteSpline<3>>;

/// A closed discrete curve: the ``N = m n`` periodic values of a discrete spline of order ``r``
/// with ``m`` poles and ``n`` values per pole (Malozemov, Khorokhonov, Chashnikov).
///
/// ``DiscreteSpline.interpolate`` makes one through given nodes instead.
///
/// Parameters
/// ----------
/// poles : array_like
///     The poles ``a_0 .. a_{m-1}``, shape ``(m, d)``, ``d`` in {2, 3}, taken cyclically.
/// order : int, optional
///     The order ``r >= 1`` (larger is smoother).
/// n : int, optional
///     The values per pole (the step), at least 1.
///
/// Raises
/// ------
/// PointsError
///     Too few poles, a non-finite coordinate, or a wrong shape.
/// OptionError
///     ``order`` or ``n`` is out of range.
///
/// Examples
/// --------
/// >>> a = np.linspace(0.0, 2.0 * np.pi, 4, endpoint=False)
/// >>> s = karkas.DiscreteSpline(np.column_stack([np.cos(a), np.sin(a)]), order=2, n=5)
/// >>> s.period, s.order, s.n, s.dim
/// (20, 2, 5, 2)
/// >>> s.values().shape
/// (20, 2)
#[pyclass(module = "karkas", name = "DiscreteSpline", frozen)]
pub struct PyDiscreteSpline {
    spline: AnySpline,
    pub(crate) interpolating: bool,
    /// The poles or nodes given (for pickling).
    pub(crate) points: FlatPoints,
}

impl PyDiscreteSpline {
    fn build(
        py: Python<'_>,
        points: &Bound<'_, PyAny>,
        order: i64,
        n: i64,
        interpolating: bool,
    ) -> PyResult<Self> {
        let what = if interpolating { "nodes" } else { "poles" };
        let (pts, dim) = PointsArray::extract_checked(points, what)?;
        let (order, n) = (count(order, "order")?, count(n, "n")?);
        if interpolating {
            // The DFT plan tabulates sin and cos of pi q / n for every q < n.
            check_memory(
                py,
                &format!("DiscreteSpline.interpolate(n={n})"),
                bytes_of(&[n], 16).saturating_add(bytes_of(&[pts.len(), dim], 32)),
            )?;
        }
        let flat = pts.flat();
        let spline = by_dim!(dim, D => {
            let p = as_points::<D>(&flat);
            let s = maybe_detach(py, p.len(), || {
                if interpolating {
                    DiscreteSpline::<D>::interpolating(p, order, n)
                } else {
                    DiscreteSpline::<D>::from_poles(p, order, n)
                }
            })
            .map_err(library_error)?;
            AnySpline::of(s)
        });
        let points = FlatPoints {
            coords: flat.into_owned(),
            dim,
        };
        Ok(PyDiscreteSpline {
            spline,
            interpolating,
            points,
        })
    }

    /// The dimension, the number of poles, the order and the step.
    pub(crate) fn parts(&self) -> (usize, usize, usize, usize) {
        each!(&self.spline, s => (point_dim(s.poles()), s.poles().len(), s.order(), s.step()))
    }
}

#[pymethods]
impl PyDiscreteSpline {
    #[new]
    #[pyo3(signature = (poles, order = DEFAULT_ORDER as i64, n = DEFAULT_STEP as i64))]
    #[pyo3(text_signature = "(poles, order=3, n=10)")]
    fn py_new(py: Python<'_>, poles: &Bound<'_, PyAny>, order: i64, n: i64) -> PyResult<Self> {
        Self::build(py, poles, order, n, false)
    }

    /// The discrete spline through given nodes: ``S(l n) = nodes[l]``.
    ///
    /// Solved by the DFT in O(m log m + N); among all N-periodic sequences through the nodes it
    /// has the least sum of squared ``r``-th differences.
    ///
    /// Parameters
    /// ----------
    /// nodes : array_like
    ///     The nodes, shape ``(m, d)``, ``d`` in {2, 3}, taken cyclically.
    /// order : int, optional
    ///     The order ``r >= 1``.
    /// n : int, optional
    ///     The values per node (the step), at least 1.
    ///
    /// Returns
    /// -------
    /// DiscreteSpline
    ///     The spline; its ``values()[::n]`` are the nodes.
    ///
    /// Raises
    /// ------
    /// PointsError
    ///     Too few nodes, a non-finite coordinate, or a wrong shape.
    /// OptionError
    ///     ``order`` or ``n`` is out of range.
    ///
    /// Examples
    /// --------
    /// >>> a = np.linspace(0.0, 2.0 * np.pi, 5, endpoint=False)
    /// >>> nodes = np.column_stack([np.cos(a), np.sin(a)])
    /// >>> s = karkas.DiscreteSpline.interpolate(nodes, order=3, n=4)
    /// >>> bool(np.allclose(s.values()[::4], nodes))
    /// True
    #[staticmethod]
    #[pyo3(signature = (nodes, order = DEFAULT_ORDER as i64, n = DEFAULT_STEP as i64))]
    #[pyo3(text_signature = "(nodes, order=3, n=10)")]
    fn interpolate(py: Python<'_>, nodes: &Bound<'_, PyAny>, order: i64, n: i64) -> PyResult<Self> {
        Self::build(py, nodes, order, n, true)
    }

    /// The ``N = m n`` values ``S(0), ..., S(N-1)`` of one period.
    ///
    /// Parameters
    /// ----------
    /// out : numpy.ndarray, optional
    ///     A C-contiguous float64 array of shape ``(N, d)``, written and returned.
    ///
    /// Returns
    /// -------
    /// numpy.ndarray
    ///     float64, shape ``(N, d)``.
    ///
    /// Raises
    /// ------
    /// TypeError
    ///     ``out`` is not a C-contiguous float64 array.
    /// ValueError
    ///     ``out`` has the wrong shape.
    ///
    /// Examples
    /// --------
    /// >>> s = karkas.DiscreteSpline([[0.0, 0.0], [1.0, 0.0], [1.0, 1.0], [0.0, 1.0]], order=2, n=3)
    /// >>> out = np.empty((12, 2))
    /// >>> s.values(out=out) is out
    /// True
    /// >>> bool(np.allclose(out.mean(axis=0), [0.5, 0.5]))
    /// True
    #[pyo3(signature = (out = None))]
    fn values<'py>(
        &self,
        py: Python<'py>,
        out: Option<Bound<'py, PyAny>>,
    ) -> PyResult<Bound<'py, PyArrayDyn<f64>>> {
        let (dim, m, _, n) = self.parts();
        // The values (unless out= holds them) and a scratch line of n points.
        let values = if out.is_none() {
            bytes_of(&[m, n, dim], 8)
        } else {
            0
        };
        check_memory(
            py,
            &format!("DiscreteSpline.values() of {m} x {n} values"),
            values.saturating_add(bytes_of(&[n, dim], 8)),
        )?;
        let array = output_array(py, out, &[m * n, dim])?;
        write_flat(&array, |flat| {
            maybe_detach(
                py,
                m * n,
                || each!(&self.spline, s => s.values(as_points_mut(flat))),
            )
        })?;
        Ok(array)
    }

    /// The poles ``a_0 .. a_{m-1}``, float64 ``(m, d)`` (for an interpolating spline, the
    /// poles solved for).
    #[getter]
    fn poles<'py>(&self, py: Python<'py>) -> PyResult<Bound<'py, PyArrayDyn<f64>>> {
        each!(&self.spline, s => points_to_array(py, s.poles()))
    }

    /// The order ``r``.
    #[getter]
    fn order(&self) -> usize {
        self.parts().2
    }

    /// The step ``n`` (values per pole).
    #[getter]
    fn n(&self) -> usize {
        self.parts().3
    }

    /// The period ``N = m n`` (the number of values).
    #[getter]
    fn period(&self) -> usize {
        let (_, m, _, n) = self.parts();
        m * n
    }

    /// The dimension ``d`` of the values (2 or 3).
    #[getter]
    fn dim(&self) -> usize {
        self.parts().0
    }

    fn __repr__(&self) -> String {
        let (dim, m, order, n) = self.parts();
        format!(
            "<karkas.DiscreteSpline {}order={order}, n={n}, {m} poles in {dim}-D, period={}>",
            variant(self.interpolating),
            m * n
        )
    }
}

/// A tube of either dimension.
type AnyTube = ByDim<TubeSurface<2>, TubeSurface<3>>;

/// A closed tube through a skeleton of closed discrete curves (formula (3) of Malozemov,
/// Khorokhonov and Chashnikov).
///
/// The skeleton is two families of closed discrete curves that cross:
/// ``along[i][j n2] == across[j][i n1]``.
///
/// Parameters
/// ----------
/// along : array_like
///     ``m1`` closed curves of ``N2 = m2 n2`` samples each, shape ``(m1, N2, d)``.
/// across : array_like
///     ``m2`` closed curves of ``N1 = m1 n1`` samples each, shape ``(m2, N1, d)``.
/// n1, n2 : int
///     The steps: samples per skeleton curve across, along.
/// r1, r2 : int, optional
///     The orders of the discrete splines in the two directions (default 2 each, as
///     ``karkas surface dps-tube``).
///
/// Raises
/// ------
/// PointsError
///     Arrays of the wrong shape or dimension, or a non-finite coordinate.
/// IncompatibleDataError
///     The skeleton curves do not meet where they must.
/// OptionError
///     A step or order out of range.
///
/// Examples
/// --------
/// A torus from 3 circles along and 4 across, 4 samples per skeleton step:
///
/// >>> def torus(p, q):
/// ...     return np.stack([(2 + np.cos(q)) * np.cos(p), (2 + np.cos(q)) * np.sin(p),
/// ...                      np.sin(q) + 0 * p], axis=-1)
/// >>> m1, m2, n1, n2 = 3, 4, 4, 4
/// >>> p = 2 * np.pi * np.arange(m1 * n1) / (m1 * n1)
/// >>> q = 2 * np.pi * np.arange(m2 * n2) / (m2 * n2)
/// >>> along = torus(p[::n1, None], q[None, :])
/// >>> across = torus(p[None, :], q[::n2, None])
/// >>> tube = karkas.TubeSurface(along, across, n1, n2, r1=2, r2=2)
/// >>> tube.values().shape, tube.closed_grid().shape
/// ((12, 16, 3), (13, 17, 3))
#[pyclass(module = "karkas", name = "TubeSurface", frozen)]
pub struct PyTubeSurface {
    tube: AnyTube,
    /// The skeleton given, each as (row-major points, rows, columns) (for pickling).
    pub(crate) skeleton: [(FlatPoints, usize, usize); 2],
    /// n1, n2, r1, r2 as given (for pickling).
    pub(crate) counts: [usize; 4],
}

#[pymethods]
impl PyTubeSurface {
    #[new]
    #[pyo3(signature = (along, across, n1, n2, r1 = DEFAULT_TUBE_ORDER as i64, r2 = DEFAULT_TUBE_ORDER as i64))]
    #[pyo3(text_signature = "(along, across, n1, n2, r1=2, r2=2)")]
    #[allow(clippy::too_many_arguments)]
    fn py_new(
        py: Python<'_>,
        along: &Bound<'_, PyAny>,
        across: &Bound<'_, PyAny>,
        n1: Int,
        n2: Int,
        r1: i64,
        r2: i64,
    ) -> PyResult<Self> {
        let a = GridArray::extract(along, "along")?;
        let b = GridArray::extract(across, "across")?;
        let dim = check_dim(a.dim(), "along")?;
        if b.dim() != dim {
            return Err(PointsError::new_err(format!(
                "along has {dim} coordinates per point, across {}",
                b.dim()
            )));
        }
        let (n1, n2, r1, r2) = (
            count(n1, "n1")?,
            count(n2, "n2")?,
            count(r1, "r1")?,
            count(r2, "r2")?,
        );
        // The values c(p, q), N1 x N2 points, and a line of work per row and column.
        let (big_n1, big_n2) = (b.columns(), a.columns());
        check_memory(
            py,
            &format!("TubeSurface({big_n1} x {big_n2} values)"),
            bytes_of(&[big_n1, big_n2, dim], 8)
                .saturating_add(bytes_of(&[big_n1.saturating_add(big_n2), dim], 32)),
        )?;
        let given = |g: &GridArray<'_>| -> (FlatPoints, usize, usize) {
            let (rows, cols) = g.rows_cols();
            let coords = g.flat().into_owned();
            (FlatPoints { coords, dim }, rows, cols)
        };
        let skeleton = [given(&a), given(&b)];
        let tube = by_dim!(dim, D => {
            let (ga, gb): (Grid<Point<D>>, Grid<Point<D>>) = (a.grid::<D>()?, b.grid::<D>()?);
            let t = maybe_detach(py, ga.as_slice().len(), || TubeSurface::<D>::new(&ga, &gb, n1, n2, r1, r2))
                .map_err(library_error)?;
            AnyTube::of(t)
        });
        Ok(PyTubeSurface {
            tube,
            skeleton,
            counts: [n1, n2, r1, r2],
        })
    }

    /// The values ``c(p, q)`` of one period in each direction.
    ///
    /// Returns
    /// -------
    /// numpy.ndarray
    ///     float64, shape ``(N1, N2, d)``.
    ///
    /// Examples
    /// --------
    /// >>> def torus(p, q):
    /// ...     return np.stack([(2 + np.cos(q)) * np.cos(p), (2 + np.cos(q)) * np.sin(p),
    /// ...                      np.sin(q) + 0 * p], axis=-1)
    /// >>> p = 2 * np.pi * np.arange(12) / 12
    /// >>> q = 2 * np.pi * np.arange(16) / 16
    /// >>> tube = karkas.TubeSurface(torus(p[::4, None], q[None, :]),
    /// ...                           torus(p[None, :], q[::4, None]), 4, 4, r1=2, r2=2)
    /// >>> v = tube.values()
    /// >>> v.shape
    /// (12, 16, 3)
    /// >>> bool(np.allclose(v[::4, ::4], torus(p[::4, None], q[None, ::4])))
    /// True
    fn values<'py>(&self, py: Python<'py>) -> PyResult<Bound<'py, PyArrayDyn<f64>>> {
        each!(&self.tube, t => grid_to_array(py, t.values()))
    }

    /// The values with the first row and column repeated at the end, for meshing a closed
    /// surface.
    ///
    /// Returns
    /// -------
    /// numpy.ndarray
    ///     float64, shape ``(N1 + 1, N2 + 1, d)``; ``g[-1] == g[0]`` and ``g[:, -1] == g[:, 0]``.
    ///
    /// Examples
    /// --------
    /// >>> def torus(p, q):
    /// ...     return np.stack([(2 + np.cos(q)) * np.cos(p), (2 + np.cos(q)) * np.sin(p),
    /// ...                      np.sin(q) + 0 * p], axis=-1)
    /// >>> p = 2 * np.pi * np.arange(12) / 12
    /// >>> q = 2 * np.pi * np.arange(16) / 16
    /// >>> tube = karkas.TubeSurface(torus(p[::4, None], q[None, :]),
    /// ...                           torus(p[None, :], q[::4, None]), 4, 4, r1=2, r2=2)
    /// >>> g = tube.closed_grid()
    /// >>> g.shape
    /// (13, 17, 3)
    /// >>> bool(np.array_equal(g[-1], g[0]) and np.array_equal(g[:, -1], g[:, 0]))
    /// True
    fn closed_grid<'py>(&self, py: Python<'py>) -> PyResult<Bound<'py, PyArrayDyn<f64>>> {
        let (dim, (p1, p2)) =
            each!(&self.tube, t => (point_dim(t.values().as_slice()), t.periods()));
        // The grid, then the array it is copied into.
        check_memory(
            py,
            &format!(
                "TubeSurface.closed_grid() of {} x {} values",
                p1 + 1,
                p2 + 1
            ),
            bytes_of(&[p1 + 1, p2 + 1, dim], 16),
        )?;
        each!(&self.tube, t => grid_to_array(py, &t.closed_grid()))
    }

    fn __repr__(&self) -> String {
        let (dim, (p1, p2), (s1, s2), (o1, o2)) = each!(&self.tube, t => (point_dim(t.values().as_slice()), t.periods(), t.steps(), t.orders()));
        format!(
            "<karkas.TubeSurface {p1}x{p2} values in {dim}-D, steps=({s1}, {s2}), orders=({o1}, {o2})>"
        )
    }
}
