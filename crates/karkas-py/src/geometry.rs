//! Curve and surface geometry on the base classes: arc length and its inverse, curvature and
//! torsion, projection of points onto curves; unit normals, principal curvatures and
//! projection of points onto surfaces (the library's [`karkas::geometry`]).
//!
//! Also `Curve.fairness(points=None)` on every curve class: the library's fairness figures
//! ([`karkas::geometry::curve_fairness`]) as a dict with the keys of `karkas curve analyze
//! --json`.
//!
//! And the same methods on derivative curves and surfaces: a derivative object is seen as a library curve or surface evaluating
//! its parent's higher derivatives, and handed to the same generic code as every other class.

use std::sync::Arc;

use karkas::geometry::{
    self, ArcLengthTable, CurveGeometry, CurveProjector, PrincipalCurvatures, SurfaceProjector,
};
use karkas::{Curve, Interval, PiecewiseCurve, Point, Point3, Side, Surface};
use numpy::PyArrayDyn;
use pyo3::prelude::*;
use pyo3::types::{PyDict, PyFloat, PyTuple};

use crate::convert::{as_points, as_points_mut, by_dim, maybe_detach, Params, PointsArray};
use crate::curve::{DerivativeCurve, PyCurve};
use crate::erased::{
    CurveGeometryImpl, CurveImpl, CurveLift, Lift, SurfaceGeometryImpl, SurfaceImpl, Wrapped,
    WrappedSurface,
};
use crate::errors::{library_error, KarkasError, OptionError, PointsError};
use crate::limits::{bytes_of, check_memory, zeros};
use crate::surface::{DerivativeSurface, PySurface};

/// Batches of at least this many lengths measure the curve's pieces once
/// ([`ArcLengthTable`]) instead of integrating from `t0` for each.
const TABLE_BATCH: usize = 16;

impl<C, const D: usize> CurveGeometryImpl for Wrapped<C, D>
where
    C: PiecewiseCurve<D> + Send + Sync,
{
    fn arc_lengths(&self, t0: f64, t1s: &[f64], tol: f64, out: &mut [f64]) {
        if t1s.len() < TABLE_BATCH {
            for (o, &t1) in out.iter_mut().zip(t1s) {
                *o = self.0.arc_length(t0, t1, tol);
            }
        } else {
            ArcLengthTable::new(&self.0, tol).arc_lengths_into(&self.0, t0, t1s, out);
        }
    }
    fn inverse_arc_lengths(&self, t0: f64, lengths: &[f64], tol: f64, out: &mut [f64]) {
        if lengths.len() < TABLE_BATCH {
            for (o, &s) in out.iter_mut().zip(lengths) {
                *o = self.0.inverse_arc_length(t0, s, tol);
            }
        } else {
            ArcLengthTable::new(&self.0, tol).inverses_into(&self.0, t0, lengths, out);
        }
    }
    fn curvatures(&self, ts: &[f64], out: &mut [f64]) {
        for (o, &t) in out.iter_mut().zip(ts) {
            *o = self.0.curvature(t);
        }
    }
    fn fairness(&self, points: &[f64]) -> geometry::CurveFairness {
        geometry::curve_fairness(&self.0, as_points::<D>(points))
    }
    fn torsions(&self, ts: &[f64], out: &mut [f64]) -> bool {
        if D != 3 {
            return false;
        }
        let lifted = CurveLift(&self.0);
        for (o, &t) in out.iter_mut().zip(ts) {
            *o = geometry::torsion(&lifted, t);
        }
        true
    }
    fn project(
        &self,
        qs: &[f64],
        tol: f64,
        t: &mut [f64],
        distance: &mut [f64],
        foot: &mut [f64],
    ) -> karkas::Result<()> {
        let projector = CurveProjector::new(&self.0, tol)?;
        let found = projector.nearest_all(as_points::<D>(qs));
        let foot = as_points_mut::<D>(foot);
        for (i, n) in found.iter().enumerate() {
            t[i] = n.t;
            distance[i] = n.distance;
            foot[i] = n.point;
        }
        Ok(())
    }
}

impl<S, const D: usize> SurfaceGeometryImpl for WrappedSurface<S, D>
where
    S: Surface<D> + Send + Sync,
{
    fn normals(&self, us: &[f64], vs: &[f64], out: &mut [f64]) {
        let lifted = Lift(&self.0);
        let out = as_points_mut::<3>(out);
        for ((o, &u), &v) in out.iter_mut().zip(us).zip(vs) {
            *o = geometry::normal(&lifted, u, v);
        }
    }
    fn principal(&self, us: &[f64], vs: &[f64]) -> Vec<PrincipalCurvatures> {
        let lifted = Lift(&self.0);
        us.iter()
            .zip(vs)
            .map(|(&u, &v)| geometry::principal_curvatures(&lifted, u, v))
            .collect()
    }
    fn project(
        &self,
        qs: &[f64],
        cells: (usize, usize),
        tol: f64,
        u: &mut [f64],
        v: &mut [f64],
        distance: &mut [f64],
        foot: &mut [f64],
    ) -> karkas::Result<()> {
        let projector = SurfaceProjector::new(&self.0, cells, tol)?;
        let found = projector.nearest_all(as_points::<D>(qs));
        let foot = as_points_mut::<D>(foot);
        for (i, n) in found.iter().enumerate() {
            u[i] = n.u;
            v[i] = n.v;
            distance[i] = n.distance;
            foot[i] = n.point;
        }
        Ok(())
    }
}

/// A float for a scalar parameter, else an array of the parameters' shape.
fn scalar_or_array<'py>(
    py: Python<'py>,
    scalar: bool,
    shape: &[usize],
    values: &[f64],
) -> PyResult<Bound<'py, PyAny>> {
    if scalar {
        return Ok(PyFloat::new(py, values[0]).into_any());
    }
    Ok(array_of(py, shape, values)?.into_any())
}

/// One value a parameter of `p` by `f` (given the flat parameters and the output; `work` a
/// parameter, for [`maybe_detach`]): a float for a scalar parameter, else an array of its shape.
fn per_parameter<'py>(
    py: Python<'py>,
    p: &Params<'_>,
    work: usize,
    f: impl FnOnce(&[f64], &mut [f64]) + Send,
) -> PyResult<Bound<'py, PyAny>> {
    let flat = p.flat().into_owned();
    let mut out = vec![0.0; flat.len()];
    maybe_detach(py, work * flat.len(), || f(&flat, &mut out));
    scalar_or_array(py, matches!(p, Params::Scalar(_)), &p.shape(), &out)
}

/// A new float64 array of `shape` holding `values` (row-major).
fn array_of<'py>(
    py: Python<'py>,
    shape: &[usize],
    values: &[f64],
) -> PyResult<Bound<'py, PyArrayDyn<f64>>> {
    let array = zeros(py, shape)?;
    crate::convert::write_flat(&array, |flat| flat.copy_from_slice(values))?;
    Ok(array)
}

/// A tolerance that must be a non-negative number.
fn check_tol(tol: f64) -> PyResult<f64> {
    if tol.is_nan() || tol < 0.0 {
        return Err(OptionError::new_err(format!(
            "tol must be a non-negative number (got {tol})"
        )));
    }
    Ok(tol)
}

/// Points `(n, d)` of the object's dimension `d`, flat.
fn query_points(points: &Bound<'_, PyAny>, dim: usize) -> PyResult<(Vec<f64>, usize)> {
    let array = PointsArray::extract(points, "points")?;
    if array.dim() != dim {
        return Err(PointsError::new_err(format!(
            "points must have {dim} coordinates like the object (got {})",
            array.dim()
        )));
    }
    let n = array.len();
    Ok((array.flat().into_owned(), n))
}

#[pymethods]
impl PyCurve {
    /// Arc length of the curve.
    ///
    /// ``c.arc_length(t0=None, t1=None, tol=1e-10)`` is the length from ``t0`` to ``t1``
    /// (negative when ``t1 < t0``), computed by adaptive Gauss-Legendre quadrature of the
    /// speed on every polynomial piece, split at the breakpoints. The length is measured along
    /// the curve itself: an open curve's parameters are clamped to its domain (no length along
    /// the continued end pieces); a closed curve's wrap, a whole period counting once per turn.
    ///
    /// Parameters
    /// ----------
    /// t0 : float, optional
    ///     Start parameter; the domain start by default.
    /// t1 : float or array_like, optional
    ///     End parameter(s); the domain end by default.
    /// tol : float, optional
    ///     Absolute accuracy of each length (in the curve's units).
    ///
    /// Returns
    /// -------
    /// float or ndarray
    ///     The length, or an array of ``t1``'s shape.
    ///
    /// Raises
    /// ------
    /// OptionError
    ///     When ``tol`` is negative or NaN.
    ///
    /// Examples
    /// --------
    /// >>> import karkas
    /// >>> c = karkas.CubicSpline([[0.0, 0.0], [3.0, 4.0], [6.0, 8.0]], t=[0.0, 1.0, 2.0])
    /// >>> round(c.arc_length(), 12)
    /// 10.0
    #[pyo3(signature = (t0 = None, t1 = None, tol = 1e-10))]
    fn arc_length<'py>(
        &self,
        py: Python<'py>,
        t0: Option<f64>,
        t1: Option<&Bound<'py, PyAny>>,
        tol: f64,
    ) -> PyResult<Bound<'py, PyAny>> {
        let tol = check_tol(tol)?;
        let (a, b) = self.inner.domain();
        let t0 = t0.unwrap_or(a);
        let t1 = match t1 {
            None => Params::Scalar(b),
            Some(obj) => Params::extract(obj, "t1")?,
        };
        let inner = &self.inner;
        per_parameter(py, &t1, 64, |t1s, out| inner.arc_lengths(t0, t1s, tol, out))
    }

    /// Parameter reached after a given arc length.
    ///
    /// ``c.inverse_arc_length(s, t0=None, tol=1e-10)`` walks ``s`` along the curve from
    /// ``t0`` (backwards when ``s < 0``) and returns the parameter reached, with
    /// ``|c.arc_length(t0, t) - s| <= tol``. On an open curve the walk starts from ``t0``
    /// clamped to the domain and stops at the domain end; a closed one goes round and the
    /// parameter is wrapped into the domain.
    ///
    /// Parameters
    /// ----------
    /// s : float or array_like
    ///     Length(s) to walk.
    /// t0 : float, optional
    ///     Start parameter; the domain start by default.
    /// tol : float, optional
    ///     Absolute accuracy of the walked length.
    ///
    /// Returns
    /// -------
    /// float or ndarray
    ///     The parameter(s), of ``s``'s shape.
    ///
    /// Raises
    /// ------
    /// OptionError
    ///     When ``tol`` is negative or NaN.
    ///
    /// Examples
    /// --------
    /// >>> import karkas
    /// >>> c = karkas.CubicSpline([[0.0, 0.0], [3.0, 4.0], [6.0, 8.0]], t=[0.0, 1.0, 2.0])
    /// >>> round(c.inverse_arc_length(5.0), 9)
    /// 1.0
    #[pyo3(signature = (s, t0 = None, tol = 1e-10))]
    fn inverse_arc_length<'py>(
        &self,
        py: Python<'py>,
        s: &Bound<'py, PyAny>,
        t0: Option<f64>,
        tol: f64,
    ) -> PyResult<Bound<'py, PyAny>> {
        let tol = check_tol(tol)?;
        let t0 = t0.unwrap_or(self.inner.domain().0);
        let s = Params::extract(s, "s")?;
        let inner = &self.inner;
        per_parameter(py, &s, 256, |lengths, out| {
            inner.inverse_arc_lengths(t0, lengths, tol, out)
        })
    }

    /// Curvature of the curve.
    ///
    /// Signed in 2-D (positive where the curve turns counter-clockwise), non-negative in 3-D:
    /// ``(x' y'' - y' x'') / |c'|^3`` and ``|c' x c''| / |c'|^3``; NaN where ``c' = 0``.
    ///
    /// Parameters
    /// ----------
    /// t : float or array_like
    ///     Parameter(s).
    ///
    /// Returns
    /// -------
    /// float or ndarray
    ///     The curvature, of ``t``'s shape.
    ///
    /// Raises
    /// ------
    /// TypeError
    ///     ``t`` is not a number or an array of numbers.
    ///
    /// Examples
    /// --------
    /// >>> import numpy as np, karkas
    /// >>> s = np.linspace(0, 2 * np.pi, 200)
    /// >>> c = karkas.CubicSpline(np.c_[2 * np.cos(s), 2 * np.sin(s)], t=s, bc="periodic")
    /// >>> bool(abs(c.curvature(1.0) - 0.5) < 1e-4)
    /// True
    fn curvature<'py>(
        &self,
        py: Python<'py>,
        t: &Bound<'py, PyAny>,
    ) -> PyResult<Bound<'py, PyAny>> {
        let inner = &self.inner;
        let t = Params::extract(t, "t")?;
        per_parameter(py, &t, 1, |ts, out| inner.curvatures(ts, out))
    }

    /// Torsion of a space curve.
    ///
    /// ``(c' x c'') . c''' / |c' x c''|^2``: positive where the curve winds like a
    /// right-handed helix; NaN where ``c' x c'' = 0`` (straight stretches).
    ///
    /// Parameters
    /// ----------
    /// t : float or array_like
    ///     Parameter(s).
    ///
    /// Returns
    /// -------
    /// float or ndarray
    ///     The torsion, of ``t``'s shape.
    ///
    /// Raises
    /// ------
    /// KarkasError
    ///     For a 2-D curve.
    ///
    /// Examples
    /// --------
    /// >>> import numpy as np, karkas
    /// >>> s = np.linspace(0, 4 * np.pi, 400)
    /// >>> c = karkas.CubicSpline(np.c_[np.cos(s), np.sin(s), s], t=s)
    /// >>> bool(abs(c.torsion(5.0) - 0.5) < 1e-4)
    /// True
    fn torsion<'py>(&self, py: Python<'py>, t: &Bound<'py, PyAny>) -> PyResult<Bound<'py, PyAny>> {
        if self.inner.dim() != 3 {
            return Err(KarkasError::new_err(
                "torsion is defined for curves in 3-D only (this curve is 2-D)",
            ));
        }
        let inner = &self.inner;
        let t = Params::extract(t, "t")?;
        per_parameter(py, &t, 1, |ts, out| {
            inner.torsions(ts, out);
        })
    }

    /// Nearest points of the curve (orthogonal projection).
    ///
    /// For every point, the globally nearest point of the curve: candidates from a sampled
    /// polyline in a k-d tree, refined by safeguarded Newton. The foot parameters stay in the domain
    /// (an open curve's end may be the foot; a closed curve's parameter is wrapped).
    ///
    /// Parameters
    /// ----------
    /// points : array_like, shape (n, d)
    ///     The points, of the curve's dimension.
    /// tol : float, optional
    ///     Tolerance on the foot parameters (0: full precision).
    ///
    /// Returns
    /// -------
    /// t : ndarray, shape (n,)
    ///     Parameters of the foot points.
    /// distance : ndarray, shape (n,)
    ///     Distances to the curve.
    /// foot : ndarray, shape (n, d)
    ///     The foot points ``c(t)``.
    ///
    /// Raises
    /// ------
    /// PointsError
    ///     When ``points`` is not (n, d) with the curve's d.
    ///
    /// Examples
    /// --------
    /// >>> import karkas
    /// >>> c = karkas.CubicSpline([[0.0, 0.0], [1.0, 0.0], [2.0, 0.0]], t=[0.0, 1.0, 2.0])
    /// >>> t, dist, foot = c.project([[0.5, 2.0]])
    /// >>> float(t[0]), float(dist[0])
    /// (0.5, 2.0)
    #[pyo3(signature = (points, tol = 0.0))]
    #[allow(clippy::type_complexity)]
    fn project<'py>(
        &self,
        py: Python<'py>,
        points: &Bound<'py, PyAny>,
        tol: f64,
    ) -> PyResult<(
        Bound<'py, PyArrayDyn<f64>>,
        Bound<'py, PyArrayDyn<f64>>,
        Bound<'py, PyArrayDyn<f64>>,
    )> {
        let tol = check_tol(tol)?;
        let d = self.inner.dim();
        let (qs, n) = query_points(points, d)?;
        let (mut t, mut dist, mut foot) = (vec![0.0; n], vec![0.0; n], vec![0.0; n * d]);
        let inner = &self.inner;
        py.detach(|| inner.project(&qs, tol, &mut t, &mut dist, &mut foot))
            .map_err(library_error)?;
        Ok((
            array_of(py, &[n], &t)?,
            array_of(py, &[n], &dist)?,
            array_of(py, &[n, d], &foot)?,
        ))
    }
}

/// The parameter pairs of `(u, v, grid)` and the result's leading shape.
fn parameter_pairs(
    py: Python<'_>,
    u: &Bound<'_, PyAny>,
    v: &Bound<'_, PyAny>,
    grid: bool,
) -> PyResult<(Vec<f64>, Vec<f64>, Vec<usize>)> {
    let (pu, pv) = (Params::extract(u, "u")?, Params::extract(v, "v")?);
    let (su, sv) = (pu.shape(), pv.shape());
    let (fu, fv) = (pu.flat(), pv.flat());
    if grid {
        if su.len() > 1 || sv.len() > 1 {
            return Err(KarkasError::new_err(
                "with grid=True, u and v must be floats or 1-D arrays",
            ));
        }
        // The pairs, and per pair a result of up to 3 x 3 numbers (curvatures and directions).
        check_memory(
            py,
            &format!("a {} x {} parameter grid", fu.len(), fv.len()),
            bytes_of(&[fu.len(), fv.len()], 8 * 11),
        )?;
        let mut us = Vec::with_capacity(fu.len() * fv.len());
        let mut vs = Vec::with_capacity(fu.len() * fv.len());
        for &a in fu.iter() {
            for &b in fv.iter() {
                us.push(a);
                vs.push(b);
            }
        }
        let mut shape = su;
        shape.extend(sv);
        Ok((us, vs, shape))
    } else {
        if su != sv {
            return Err(KarkasError::new_err(format!(
                "with grid=False, u and v must have one shape (got {su:?} and {sv:?})"
            )));
        }
        Ok((fu.into_owned(), fv.into_owned(), su))
    }
}

#[pymethods]
impl PySurface {
    /// Unit normals of the surface.
    ///
    /// ``S_u x S_v / |S_u x S_v|`` (a 2-D surface is seen in the plane z = 0); NaN where the
    /// surface is singular.
    ///
    /// Parameters
    /// ----------
    /// u, v : float or array_like
    ///     Parameters: pairs ``(u[i], v[i])`` of one shape (grid=False), or the grid
    ///     ``u x v`` of two 1-D arrays (grid=True).
    /// grid : bool, optional
    ///     As in evaluation; False by default.
    ///
    /// Returns
    /// -------
    /// ndarray
    ///     Shape ``u.shape + (3,)`` (grid=False) or ``(len(u), len(v), 3)``.
    ///
    /// Raises
    /// ------
    /// KarkasError
    ///     When the shapes of u and v do not fit ``grid``.
    ///
    /// Examples
    /// --------
    /// >>> import numpy as np, karkas
    /// >>> g = np.zeros((4, 4, 3)); g[..., 0], g[..., 1] = np.meshgrid(range(4), range(4), indexing="ij")
    /// >>> S = karkas.BicubicSurface(g)
    /// >>> bool(np.allclose(S.normal(0.5, 0.5), [0.0, 0.0, 1.0], atol=1e-12))
    /// True
    #[pyo3(signature = (u, v, grid = false))]
    fn normal<'py>(
        &self,
        py: Python<'py>,
        u: &Bound<'py, PyAny>,
        v: &Bound<'py, PyAny>,
        grid: bool,
    ) -> PyResult<Bound<'py, PyArrayDyn<f64>>> {
        let (us, vs, mut shape) = parameter_pairs(py, u, v, grid)?;
        let mut out = vec![0.0; 3 * us.len()];
        let inner = &self.inner;
        maybe_detach(py, us.len(), || inner.normals(&us, &vs, &mut out));
        shape.push(3);
        array_of(py, &shape, &out)
    }

    /// Principal curvatures (and directions) of the surface.
    ///
    /// From the first and second fundamental forms, signed with respect to the unit normal
    /// ``S.normal(u, v)`` (positive where the surface bends towards it: a sphere with its
    /// outward normal has ``k1 = k2 = -1/r``); ``k1 >= k2``. NaN where the surface is
    /// singular.
    ///
    /// Parameters
    /// ----------
    /// u, v : float or array_like
    ///     Parameters, as in ``normal``.
    /// grid : bool, optional
    ///     As in evaluation; False by default.
    /// directions : bool, optional
    ///     Also return the unit principal directions.
    ///
    /// Returns
    /// -------
    /// k1, k2 : float or ndarray
    ///     The larger and the smaller curvature, of the parameters' shape.
    /// d1, d2 : ndarray
    ///     Only with ``directions=True``: the unit tangent directions of k1 and k2, shape
    ///     ``(..., 3)``, with ``d1 x d2 = normal``.
    ///
    /// Raises
    /// ------
    /// TypeError
    ///     ``u`` or ``v`` is not a number or an array of numbers.
    /// ValueError
    ///     ``u`` and ``v`` of different shapes with ``grid=False``.
    ///
    /// Examples
    /// --------
    /// >>> import numpy as np, karkas
    /// >>> g = np.zeros((4, 4, 3)); g[..., 0], g[..., 1] = np.meshgrid(range(4), range(4), indexing="ij")
    /// >>> k1, k2 = karkas.BicubicSurface(g).principal_curvatures(0.5, 0.5)
    /// >>> float(k1), float(k2)
    /// (0.0, 0.0)
    #[pyo3(signature = (u, v, grid = false, directions = false))]
    fn principal_curvatures<'py>(
        &self,
        py: Python<'py>,
        u: &Bound<'py, PyAny>,
        v: &Bound<'py, PyAny>,
        grid: bool,
        directions: bool,
    ) -> PyResult<Bound<'py, PyAny>> {
        let scalar = !grid
            && Params::extract(u, "u").is_ok_and(|p| matches!(p, Params::Scalar(_)))
            && Params::extract(v, "v").is_ok_and(|p| matches!(p, Params::Scalar(_)));
        let (us, vs, shape) = parameter_pairs(py, u, v, grid)?;
        let inner = &self.inner;
        let found = maybe_detach(py, us.len(), || inner.principal(&us, &vs));
        let k1: Vec<f64> = found.iter().map(|p| p.k1).collect();
        let k2: Vec<f64> = found.iter().map(|p| p.k2).collect();
        let (k1, k2) = (
            scalar_or_array(py, scalar, &shape, &k1)?,
            scalar_or_array(py, scalar, &shape, &k2)?,
        );
        if !directions {
            return Ok((k1, k2).into_pyobject(py)?.into_any());
        }
        let flat = |f: fn(&PrincipalCurvatures) -> Point3| -> Vec<f64> {
            found.iter().flat_map(|p| f(p).0).collect()
        };
        let mut dshape = shape.clone();
        dshape.push(3);
        let d1 = array_of(py, &dshape, &flat(|p| p.dir1))?;
        let d2 = array_of(py, &dshape, &flat(|p| p.dir2))?;
        Ok((k1, k2, d1, d2).into_pyobject(py)?.into_any())
    }

    /// Nearest points of the surface (orthogonal projection).
    ///
    /// For every point, the globally nearest point of the surface: candidates from a
    /// ``cells[0] x cells[1]`` grid of samples in a k-d tree, refined by Newton's method.
    /// The foot parameters stay in the domain (clamped in an open direction, wrapped in a
    /// closed one).
    ///
    /// Parameters
    /// ----------
    /// points : array_like, shape (n, d)
    ///     The points, of the surface's dimension.
    /// cells : (int, int), optional
    ///     The sampling grid in (u, v); more cells for wavy surfaces.
    /// tol : float, optional
    ///     Tolerance on the foot parameters (0: full precision).
    /// foot : bool, optional
    ///     Also return the foot points.
    ///
    /// Returns
    /// -------
    /// u, v : ndarray, shape (n,)
    ///     Parameters of the foot points.
    /// distance : ndarray, shape (n,)
    ///     Distances to the surface.
    /// foot : ndarray, shape (n, d)
    ///     Only with ``foot=True``: the foot points ``S(u, v)``.
    ///
    /// Raises
    /// ------
    /// PointsError
    ///     When ``points`` is not (n, d) with the surface's d.
    ///
    /// Examples
    /// --------
    /// >>> import numpy as np, karkas
    /// >>> g = np.zeros((4, 4, 3)); g[..., 0], g[..., 1] = np.meshgrid(range(4), range(4), indexing="ij")
    /// >>> u, v, dist = karkas.BicubicSurface(g).project([[1.5, 2.0, 3.0]])
    /// >>> u.round(12).tolist(), v.round(12).tolist(), dist.round(12).tolist()
    /// ([1.5], [2.0], [3.0])
    /// >>> karkas.BicubicSurface(g).project([[1.5, 2.0, 3.0]], foot=True)[3].round(12).tolist()
    /// [[1.5, 2.0, 0.0]]
    #[pyo3(signature = (points, cells = (64, 64), tol = 0.0, foot = false))]
    #[pyo3(text_signature = "(self, points, cells=(64, 64), tol=0.0, foot=False)")]
    fn project<'py>(
        &self,
        py: Python<'py>,
        points: &Bound<'py, PyAny>,
        cells: (usize, usize),
        tol: f64,
        foot: bool,
    ) -> PyResult<Bound<'py, PyTuple>> {
        let tol = check_tol(tol)?;
        if cells.0 == 0 || cells.1 == 0 || cells.0.saturating_mul(cells.1) > 1 << 24 {
            return Err(OptionError::new_err(format!(
                "cells must be two positive counts with a product at most 2^24 (got {cells:?})"
            )));
        }
        let d = self.inner.dim();
        let (qs, n) = query_points(points, d)?;
        let (mut u, mut v, mut dist, mut feet) =
            (vec![0.0; n], vec![0.0; n], vec![0.0; n], vec![0.0; n * d]);
        let inner = &self.inner;
        py.detach(|| inner.project(&qs, cells, tol, &mut u, &mut v, &mut dist, &mut feet))
            .map_err(library_error)?;
        let mut parts = vec![
            array_of(py, &[n], &u)?,
            array_of(py, &[n], &v)?,
            array_of(py, &[n], &dist)?,
        ];
        if foot {
            parts.push(array_of(py, &[n, d], &feet)?);
        }
        PyTuple::new(py, parts)
    }
}

/// Bytes the figures work in per piece of the curve (its samples and their derivatives).
const BYTES_PER_PIECE: u128 = 80 * 64;

#[pymethods]
impl PyCurve {
    /// How fair the curve is: the figures a designer reads off a curvature plot.
    ///
    /// Curvature extrema are the sign changes of dk/ds over dense samples of every polynomial
    /// piece, both one-sided limits at every breakpoint included (an extremum on a knot
    /// counts); values below ``1e-8 (k_max + 1/L) / L`` are rounding noise. Inflections are
    /// the sign changes of the signed curvature in 2-D, the zeros of the curvature in 3-D.
    /// The same figures as ``karkas curve analyze --json``.
    ///
    /// Parameters
    /// ----------
    /// points : array_like, shape (n, d), optional
    ///     The points the curve was made from: ``max_distance_to_polygon`` is the largest
    ///     distance of the curve from their polyline (closed for a closed curve).
    ///
    /// Returns
    /// -------
    /// dict
    ///     ``length``, ``curvature_min``, ``curvature_max``, ``curvature_extrema`` (int),
    ///     ``inflections`` (int), ``max_distance_to_polygon`` (None without points),
    ///     ``fairness_energy`` (the integral of (dk/ds)^2 over the arc length), ``pieces``
    ///     (int) and ``curvature_jump`` (the largest jump of the curvature at a breakpoint).
    ///
    /// Raises
    /// ------
    /// PointsError
    ///     When ``points`` is not (n, d) with the curve's d.
    ///
    /// Examples
    /// --------
    /// >>> import numpy as np, karkas
    /// >>> s = np.linspace(0, 2 * np.pi, 41)
    /// >>> c = karkas.CubicSpline(np.c_[2 * np.cos(s), 2 * np.sin(s)], t=s, bc="periodic")
    /// >>> f = c.fairness(c(s[:-1]))
    /// >>> f["inflections"], round(f["length"], 4), round(f["curvature_max"], 2)
    /// (0, 12.5664, 0.5)
    #[pyo3(signature = (points = None))]
    fn fairness<'py>(
        &self,
        py: Python<'py>,
        points: Option<&Bound<'py, PyAny>>,
    ) -> PyResult<Bound<'py, PyDict>> {
        let d = self.inner.dim();
        let flat = match points {
            None => Vec::new(),
            Some(points) => {
                let array = PointsArray::extract(points, "points")?;
                if array.dim() != d {
                    return Err(PointsError::new_err(format!(
                        "points must have {d} coordinates like the curve (got {})",
                        array.dim()
                    )));
                }
                array.flat().into_owned()
            }
        };
        let pieces = self.inner.breakpoints().len();
        check_memory(
            py,
            &format!("the fairness of a curve of {pieces} pieces"),
            bytes_of(&[pieces], BYTES_PER_PIECE),
        )?;
        let inner = &self.inner;
        let f = py.detach(|| inner.fairness(&flat));
        fairness_dict(py, &f)
    }
}

/// A fairness report as the dict of ``Curve.fairness``.
pub(crate) fn fairness_dict<'py>(
    py: Python<'py>,
    f: &geometry::CurveFairness,
) -> PyResult<Bound<'py, PyDict>> {
    let out = PyDict::new(py);
    out.set_item("length", f.length)?;
    out.set_item("curvature_min", f.curvature_min)?;
    out.set_item("curvature_max", f.curvature_max)?;
    out.set_item("curvature_extrema", f.curvature_extrema)?;
    out.set_item("inflections", f.inflections)?;
    let distance = f.max_distance_to_polygon;
    out.set_item(
        "max_distance_to_polygon",
        distance.is_finite().then_some(distance),
    )?;
    out.set_item("fairness_energy", f.fairness_energy)?;
    out.set_item("pieces", f.pieces)?;
    out.set_item("curvature_jump", f.curvature_jump)?;
    Ok(out)
}

/// The `nu`-th derivative of a curve of dimension `D` as a library curve.
struct DerivativeOf<const D: usize> {
    parent: Arc<dyn CurveImpl>,
    nu: usize,
}

impl<const D: usize> Curve<D> for DerivativeOf<D> {
    fn domain(&self) -> Interval {
        let (a, b) = self.parent.domain();
        Interval::new(a, b)
    }
    fn is_closed(&self) -> bool {
        self.parent.closed()
    }
    fn eval(&self, t: f64) -> Point<D> {
        self.deriv(t, 0)
    }
    fn deriv(&self, t: f64, k: usize) -> Point<D> {
        let mut p = Point::<D>::ZERO;
        self.parent.eval_flat(&[t], k + self.nu, &mut p.0);
        p
    }
}

impl<const D: usize> PiecewiseCurve<D> for DerivativeOf<D> {
    fn breakpoints(&self) -> Vec<f64> {
        self.parent.breakpoints()
    }
    fn continuity(&self) -> usize {
        self.parent.continuity().saturating_sub(self.nu)
    }
    fn deriv_on_side(&self, t: f64, k: usize, _side: Side) -> Point<D> {
        self.deriv(t, k)
    }
}

impl DerivativeCurve {
    /// Runs `f` on this derivative seen as a wrapped library curve of its dimension.
    fn with_curve<R>(&self, f: impl FnOnce(&dyn CurveGeometryImpl) -> R) -> R {
        let (parent, nu) = (self.parent.clone(), self.nu);
        by_dim!(self.parent.dim(), D => f(&Wrapped::<_, D>(DerivativeOf::<D> { parent, nu })))
    }
}

impl CurveGeometryImpl for DerivativeCurve {
    fn arc_lengths(&self, t0: f64, t1s: &[f64], tol: f64, out: &mut [f64]) {
        self.with_curve(|c| c.arc_lengths(t0, t1s, tol, out))
    }
    fn inverse_arc_lengths(&self, t0: f64, lengths: &[f64], tol: f64, out: &mut [f64]) {
        self.with_curve(|c| c.inverse_arc_lengths(t0, lengths, tol, out))
    }
    fn curvatures(&self, ts: &[f64], out: &mut [f64]) {
        self.with_curve(|c| c.curvatures(ts, out))
    }
    fn torsions(&self, ts: &[f64], out: &mut [f64]) -> bool {
        self.with_curve(|c| c.torsions(ts, out))
    }
    fn fairness(&self, points: &[f64]) -> karkas::geometry::CurveFairness {
        self.with_curve(|c| c.fairness(points))
    }
    fn project(
        &self,
        qs: &[f64],
        tol: f64,
        t: &mut [f64],
        distance: &mut [f64],
        foot: &mut [f64],
    ) -> karkas::Result<()> {
        self.with_curve(|c| c.project(qs, tol, t, distance, foot))
    }
}

/// The partial derivative `(du, dv)` of a surface of dimension `D` as a library surface.
struct PartialOf<const D: usize> {
    parent: Arc<dyn SurfaceImpl>,
    du: usize,
    dv: usize,
}

impl<const D: usize> Surface<D> for PartialOf<D> {
    fn domain_u(&self) -> Interval {
        let (a, b) = self.parent.domain_u();
        Interval::new(a, b)
    }
    fn domain_v(&self) -> Interval {
        let (a, b) = self.parent.domain_v();
        Interval::new(a, b)
    }
    fn is_closed_u(&self) -> bool {
        self.parent.closed().0
    }
    fn is_closed_v(&self) -> bool {
        self.parent.closed().1
    }
    fn eval(&self, u: f64, v: f64) -> Point<D> {
        self.deriv(u, v, 0, 0)
    }
    fn deriv(&self, u: f64, v: f64, ku: usize, kv: usize) -> Point<D> {
        let mut p = Point::<D>::ZERO;
        self.parent
            .points_flat(&[u], &[v], ku + self.du, kv + self.dv, &mut p.0);
        p
    }
}

impl DerivativeSurface {
    /// Runs `f` on this derivative seen as a wrapped library surface of its dimension.
    fn with_surface<R>(&self, f: impl FnOnce(&dyn SurfaceGeometryImpl) -> R) -> R {
        let (parent, du, dv) = (self.parent.clone(), self.du, self.dv);
        by_dim!(self.parent.dim(), D => f(&WrappedSurface::<_, D>(PartialOf::<D> { parent, du, dv })))
    }
}

impl SurfaceGeometryImpl for DerivativeSurface {
    fn normals(&self, us: &[f64], vs: &[f64], out: &mut [f64]) {
        self.with_surface(|s| s.normals(us, vs, out))
    }
    fn principal(&self, us: &[f64], vs: &[f64]) -> Vec<PrincipalCurvatures> {
        self.with_surface(|s| s.principal(us, vs))
    }
    fn project(
        &self,
        qs: &[f64],
        cells: (usize, usize),
        tol: f64,
        u: &mut [f64],
        v: &mut [f64],
        distance: &mut [f64],
        foot: &mut [f64],
    ) -> karkas::Result<()> {
        self.with_surface(|s| s.project(qs, cells, tol, u, v, distance, foot))
    }
}
