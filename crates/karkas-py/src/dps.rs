//! Discrete periodic splines (Malozemov, Khorokhonov, Chashnikov): `DiscreteSpline` and
//! `TubeSurface`.

use karkas::dps::{DiscreteSpline, TubeSurface};
use karkas::{Grid, Point};
use numpy::PyArrayDyn;
use pyo3::prelude::*;

use crate::convert::{
    as_points, as_points_mut, by_dim, check_dim, count, each, grid_to_array, maybe_detach,
    output_array, points_to_array, variant, write_flat, ByDim, GridArray, Int, PointsArray,
};
use crate::errors::{library_error, PointsError};
use crate::limits::{bytes_of, check_memory};

/// The dimension `D` of points.
fn point_dim<const D: usize>(_: &[Point<D>]) -> usize {
    D
}

/// A discrete spline of either dimension.
type AnySpline = ByDim<DiscreteSpline<2>, DiscreteSpline<3>>;

/// A closed discrete curve: the N = m n periodic values of a discrete spline of order r with m
/// poles (or through m nodes) and n values per pole.
///
/// DiscreteSpline(poles, order=3, n=10): from poles (m, d).
/// DiscreteSpline.interpolate(nodes, order=3, n=10): through the nodes, S(l n) = nodes[l].
/// values(out=None) -> (m n, d).
#[pyclass(module = "karkas", name = "DiscreteSpline", frozen)]
pub struct PyDiscreteSpline {
    spline: AnySpline,
    interpolating: bool,
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
        Ok(PyDiscreteSpline {
            spline,
            interpolating,
        })
    }

    fn parts(&self) -> (usize, usize, usize, usize) {
        each!(&self.spline, s => (point_dim(s.poles()), s.poles().len(), s.order(), s.step()))
    }
}

#[pymethods]
impl PyDiscreteSpline {
    #[new]
    #[pyo3(signature = (poles, order = 3, n = 10))]
    fn py_new(py: Python<'_>, poles: &Bound<'_, PyAny>, order: i64, n: i64) -> PyResult<Self> {
        Self::build(py, poles, order, n, false)
    }

    /// DiscreteSpline.interpolate(nodes, order=3, n=10): the spline through nodes (m, d) at
    /// j = l n (solved by the DFT in O(m log m + N)); among all N-periodic sequences through
    /// the nodes it has the least sum of squared r-th differences.
    #[staticmethod]
    #[pyo3(signature = (nodes, order = 3, n = 10))]
    fn interpolate(py: Python<'_>, nodes: &Bound<'_, PyAny>, order: i64, n: i64) -> PyResult<Self> {
        Self::build(py, nodes, order, n, true)
    }

    /// values(out=None): the N = m n values S(0), ..., S(N-1), shape (N, d).
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

    /// The poles a_0..a_{m-1}, (m, d).
    #[getter]
    fn poles<'py>(&self, py: Python<'py>) -> PyResult<Bound<'py, PyArrayDyn<f64>>> {
        each!(&self.spline, s => points_to_array(py, s.poles()))
    }

    /// The order r.
    #[getter]
    fn order(&self) -> usize {
        self.parts().2
    }

    /// The step n (values per pole).
    #[getter]
    fn n(&self) -> usize {
        self.parts().3
    }

    /// The period N = m n (the number of values).
    #[getter]
    fn period(&self) -> usize {
        let (_, m, _, n) = self.parts();
        m * n
    }

    /// The dimension d.
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
/// TubeSurface(along, across, n1, n2, r1=3, r2=3): along (m1, N2, d) are m1 closed curves of
/// N2 = m2 n2 samples, across (m2, N1, d) are m2 closed curves of N1 = m1 n1 samples, with
/// along[i][j n2] == across[j][i n1]. values() -> (N1, N2, d); closed_grid() -> (N1+1, N2+1, d)
/// with the seams repeated, for meshing.
#[pyclass(module = "karkas", name = "TubeSurface", frozen)]
pub struct PyTubeSurface {
    tube: AnyTube,
}

#[pymethods]
impl PyTubeSurface {
    #[new]
    #[pyo3(signature = (along, across, n1, n2, r1 = 3, r2 = 3))]
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
        let tube = by_dim!(dim, D => {
            let (ga, gb): (Grid<Point<D>>, Grid<Point<D>>) = (a.grid::<D>()?, b.grid::<D>()?);
            let t = maybe_detach(py, ga.as_slice().len(), || TubeSurface::<D>::new(&ga, &gb, n1, n2, r1, r2))
                .map_err(library_error)?;
            AnyTube::of(t)
        });
        Ok(PyTubeSurface { tube })
    }

    /// The values c(p, q), shape (N1, N2, d).
    fn values<'py>(&self, py: Python<'py>) -> PyResult<Bound<'py, PyArrayDyn<f64>>> {
        each!(&self.tube, t => grid_to_array(py, t.values()))
    }

    /// The values with the first row and column repeated at the end, (N1+1, N2+1, d).
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
