//! The dimension-erased layer: karkas curves and surfaces of either dimension behind one
//! interface, and that interface seen again as a karkas curve or surface of a fixed dimension.
//!
//! A karkas curve or surface has its dimension `D` as a type parameter; Python objects do not.
//! - Erasing: [`Wrapped`] and [`WrappedSurface`] put a library object of either dimension
//!   behind [`CurveImpl`] and [`SurfaceImpl`], which evaluate whole parameter arrays into flat
//!   output buffers (one dynamic call per batch, the library's `eval_into` inside), and behind
//!   the geometry interfaces [`CurveGeometryImpl`] and [`SurfaceGeometryImpl`] (arc length,
//!   curvature, projection; normals, principal curvatures, projection; implemented for the
//!   library's types in `geometry`). Every concrete class hands its base class one of these.
//! - Lifting back: [`CurveView`] and [`SurfaceView`] see an erased curve or surface as a karkas
//!   curve of dimension `D` or a surface in space, for karkas-io's writers (sampled with the
//!   library's own uniform parameters, [`karkas::Curve::sample_into`], so that a file written
//!   from Python is the file the command line writes); [`CurveLift`] and [`Lift`] see a plane
//!   curve or surface in space (a derivative object, seen as a library curve or surface of
//!   its parent's higher derivatives, is in `geometry`).

use karkas::bspline::{ToBSplineCurve, ToBSplineSurface, MAX_DEGREE};
use karkas::geometry::{CurveFairness, PrincipalCurvatures};
use karkas::implicit::ExpressionSurface;
use karkas::measure::{hausdorff_surface_implicit, Hausdorff};
use karkas::section::{plane_section, Plane, SectionOptions};
use karkas::{Curve, Interval, PiecewiseCurve, Point, Point3, Surface};

use crate::bspline::{FlatBSpline, FlatBSplineSurface};
use crate::convert::as_points_mut;
use crate::section::PySectionCurve;

/// A karkas curve of either dimension, evaluated on flat buffers.
pub trait CurveImpl: CurveGeometryImpl + Send + Sync {
    /// The dimension `d` (2 or 3).
    fn dim(&self) -> usize;
    /// The parameter domain `(a, b)`.
    fn domain(&self) -> (f64, f64);
    /// True for a closed curve (evaluation wraps by the period).
    fn closed(&self) -> bool;
    /// The parameters where the pieces meet, ends included.
    fn breakpoints(&self) -> Vec<f64>;
    /// The order of continuity at the breakpoints.
    fn continuity(&self) -> usize;
    /// Writes the `k`-th derivative (0: the point) at every `ts[i]` into `out[d i..d i + d]`.
    fn eval_flat(&self, ts: &[f64], k: usize, out: &mut [f64]);
    /// The library curve itself, for a class that reads more of it than this interface gives
    /// (a cubic spline's knots, values and slopes); `None` unless overridden.
    fn library_curve(&self) -> Option<&dyn std::any::Any> {
        None
    }
    /// The exact B-spline form over the domain (one period, clamped, for a closed curve), or
    /// the library's reason why there is none.
    fn to_bspline(&self) -> karkas::Result<FlatBSpline>;
    /// True when the curve's own evaluation continues its end pieces outside the domain (a
    /// rational B-spline, which has no polynomial form to continue): the base class then
    /// extrapolates with it.
    fn extrapolates(&self) -> bool {
        false
    }
}

/// A library object of one of two types: its 2-D or its 3-D form.
pub(crate) enum PlaneOrSpace<'a, A, B> {
    /// The plane form.
    D2(&'a A),
    /// The space form.
    D3(&'a B),
}

/// `library` (from [`CurveImpl::library_curve`] or [`SurfaceImpl::library_surface`]) as the
/// 2-D type `A` or the 3-D type `B`; `what` names the object in the error when it is neither.
pub(crate) fn in_plane_or_space<'a, A: std::any::Any, B: std::any::Any>(
    library: Option<&'a dyn std::any::Any>,
    what: &str,
) -> pyo3::PyResult<PlaneOrSpace<'a, A, B>> {
    if let Some(a) = library.and_then(|l| l.downcast_ref::<A>()) {
        return Ok(PlaneOrSpace::D2(a));
    }
    if let Some(b) = library.and_then(|l| l.downcast_ref::<B>()) {
        return Ok(PlaneOrSpace::D3(b));
    }
    Err(pyo3::exceptions::PyTypeError::new_err(format!(
        "a {what} without its library object"
    )))
}

/// The ends `(a, b)` of an interval.
fn ends(interval: Interval) -> (f64, f64) {
    (interval.start, interval.end)
}

/// A karkas curve of dimension `D` behind [`CurveImpl`].
pub struct Wrapped<C, const D: usize>(pub C);

impl<C, const D: usize> CurveImpl for Wrapped<C, D>
where
    C: PiecewiseCurve<D> + ToBSplineCurve<D> + Send + Sync + 'static,
{
    fn library_curve(&self) -> Option<&dyn std::any::Any> {
        Some(&self.0)
    }
    fn to_bspline(&self) -> karkas::Result<FlatBSpline> {
        Ok(FlatBSpline::of(&self.0.to_bspline()?))
    }
    fn extrapolates(&self) -> bool {
        (&self.0 as &dyn std::any::Any).is::<karkas::bspline::NurbsCurve<D>>()
    }
    fn dim(&self) -> usize {
        D
    }
    fn domain(&self) -> (f64, f64) {
        ends(self.0.domain())
    }
    fn closed(&self) -> bool {
        self.0.is_closed()
    }
    fn breakpoints(&self) -> Vec<f64> {
        self.0.breakpoints()
    }
    fn continuity(&self) -> usize {
        self.0.continuity()
    }
    fn eval_flat(&self, ts: &[f64], k: usize, out: &mut [f64]) {
        if k > MAX_DEGREE {
            // Beyond every piece's degree (and where the library's factorials overflow).
            out.fill(0.0);
            return;
        }
        let out = as_points_mut::<D>(out);
        if k == 0 {
            self.0.eval_into(ts, out);
        } else {
            self.0.deriv_into(ts, k, out);
        }
    }
}
/// A karkas surface of either dimension, evaluated on flat buffers.
pub trait SurfaceImpl: SurfaceGeometryImpl + Send + Sync {
    /// The dimension `d` (2 or 3).
    fn dim(&self) -> usize;
    /// The `u` domain.
    fn domain_u(&self) -> (f64, f64);
    /// The `v` domain.
    fn domain_v(&self) -> (f64, f64);
    /// Closed in `u`, in `v`.
    fn closed(&self) -> (bool, bool);
    /// The derivative `(ku, kv)` ((0, 0): the point) on the grid `us x vs`, row-major with `u`
    /// outer, into `out`.
    fn grid_flat(&self, us: &[f64], vs: &[f64], ku: usize, kv: usize, out: &mut [f64]);
    /// The derivative `(ku, kv)` at the pairs `(us[i], vs[i])` into `out`.
    fn points_flat(&self, us: &[f64], vs: &[f64], ku: usize, kv: usize, out: &mut [f64]);
    /// The exact B-spline form over the domain (closed directions over one period, clamped),
    /// or the library's reason why there is none.
    fn to_bspline(&self) -> karkas::Result<FlatBSplineSurface>;
    /// The section by the plane `normal . x = offset` (`normal.len() == dim`).
    fn section(
        &self,
        normal: &[f64],
        offset: f64,
        options: &SectionOptions,
    ) -> karkas::Result<Vec<PySectionCurve>>;
    /// The two-sided Hausdorff distance to the patch of an implicit surface (3-D only).
    fn hausdorff_implicit(
        &self,
        implicit: &ExpressionSurface,
        patch: &[Point3],
        samples: (usize, usize),
    ) -> karkas::Result<Hausdorff>;
    /// The library surface itself, for a class that reads more of it than this interface
    /// gives (the bicubic surface's nodes and condition measures); `None` unless overridden.
    fn library_surface(&self) -> Option<&dyn std::any::Any> {
        None
    }
    /// True when the surface's own evaluation continues its end pieces outside the domain
    /// (a rational B-spline surface).
    fn extrapolates(&self) -> bool {
        false
    }
}

/// A curve of dimension `D <= 3` seen as one in 3-D (missing coordinates zero).
pub(crate) struct CurveLift<'a, C, const D: usize>(pub(crate) &'a C);

impl<C: Curve<D>, const D: usize> Curve<3> for CurveLift<'_, C, D> {
    fn domain(&self) -> Interval {
        self.0.domain()
    }
    fn is_closed(&self) -> bool {
        self.0.is_closed()
    }
    fn eval(&self, t: f64) -> Point3 {
        lift(self.0.eval(t))
    }
    fn deriv(&self, t: f64, k: usize) -> Point3 {
        lift(self.0.deriv(t, k))
    }
}

/// A surface of dimension `D` seen as one in 3-D (used only when `D == 3`: the coordinates
/// are copied, missing ones are zero).
pub(crate) struct Lift<'a, S, const D: usize>(pub(crate) &'a S);

pub(crate) fn lift<const D: usize>(p: Point<D>) -> Point3 {
    let mut q = Point3::ZERO;
    for (a, b) in q.0.iter_mut().zip(p.0) {
        *a = b;
    }
    q
}

impl<S: Surface<D>, const D: usize> Surface<3> for Lift<'_, S, D> {
    fn domain_u(&self) -> Interval {
        self.0.domain_u()
    }
    fn domain_v(&self) -> Interval {
        self.0.domain_v()
    }
    fn is_closed_u(&self) -> bool {
        self.0.is_closed_u()
    }
    fn is_closed_v(&self) -> bool {
        self.0.is_closed_v()
    }
    fn eval(&self, u: f64, v: f64) -> Point3 {
        lift(self.0.eval(u, v))
    }
    fn deriv(&self, u: f64, v: f64, ku: usize, kv: usize) -> Point3 {
        lift(self.0.deriv(u, v, ku, kv))
    }
}

/// A karkas surface of dimension `D` behind [`SurfaceImpl`].
pub struct WrappedSurface<S, const D: usize>(pub S);

impl<S, const D: usize> SurfaceImpl for WrappedSurface<S, D>
where
    S: Surface<D> + ToBSplineSurface<D> + Send + Sync + 'static,
{
    fn library_surface(&self) -> Option<&dyn std::any::Any> {
        Some(&self.0)
    }
    fn extrapolates(&self) -> bool {
        (&self.0 as &dyn std::any::Any).is::<karkas::bspline::NurbsSurface<D>>()
    }
    fn to_bspline(&self) -> karkas::Result<FlatBSplineSurface> {
        Ok(FlatBSplineSurface::of(&self.0.to_bspline()?))
    }
    fn dim(&self) -> usize {
        D
    }
    fn domain_u(&self) -> (f64, f64) {
        ends(self.0.domain_u())
    }
    fn domain_v(&self) -> (f64, f64) {
        ends(self.0.domain_v())
    }
    fn closed(&self) -> (bool, bool) {
        (self.0.is_closed_u(), self.0.is_closed_v())
    }
    fn grid_flat(&self, us: &[f64], vs: &[f64], ku: usize, kv: usize, out: &mut [f64]) {
        if ku > MAX_DEGREE || kv > MAX_DEGREE {
            out.fill(0.0);
            return;
        }
        let out: &mut [Point<D>] = as_points_mut(out);
        if ku == 0 && kv == 0 {
            self.0.eval_grid_into(us, vs, out);
            return;
        }
        for (row, &u) in out.chunks_exact_mut(vs.len().max(1)).zip(us) {
            for (p, &v) in row.iter_mut().zip(vs) {
                *p = self.0.deriv(u, v, ku, kv);
            }
        }
    }
    fn section(
        &self,
        normal: &[f64],
        offset: f64,
        options: &SectionOptions,
    ) -> karkas::Result<Vec<PySectionCurve>> {
        let mut n = Point::<D>::ZERO;
        n.0.copy_from_slice(normal);
        let section = plane_section(&self.0, &Plane::new(n, offset)?, options)?;
        Ok(section.curves.iter().map(PySectionCurve::of).collect())
    }
    fn hausdorff_implicit(
        &self,
        implicit: &ExpressionSurface,
        patch: &[Point3],
        samples: (usize, usize),
    ) -> karkas::Result<Hausdorff> {
        hausdorff_surface_implicit(&Lift(&self.0), implicit, patch, samples)
    }
    fn points_flat(&self, us: &[f64], vs: &[f64], ku: usize, kv: usize, out: &mut [f64]) {
        if ku > MAX_DEGREE || kv > MAX_DEGREE {
            out.fill(0.0);
            return;
        }
        let out: &mut [Point<D>] = as_points_mut(out);
        for ((p, &u), &v) in out.iter_mut().zip(us).zip(vs) {
            *p = if ku == 0 && kv == 0 {
                self.0.eval(u, v)
            } else {
                self.0.deriv(u, v, ku, kv)
            };
        }
    }
}

/// The geometry of a curve of either dimension on flat buffers.
pub trait CurveGeometryImpl {
    /// The arc length from `t0` to every `t1s[i]` into `out[i]`, each to `tol`.
    fn arc_lengths(&self, t0: f64, t1s: &[f64], tol: f64, out: &mut [f64]);
    /// The parameter after walking `lengths[i]` from `t0`, into `out[i]`.
    fn inverse_arc_lengths(&self, t0: f64, lengths: &[f64], tol: f64, out: &mut [f64]);
    /// The curvature at every `ts[i]` into `out[i]`.
    fn curvatures(&self, ts: &[f64], out: &mut [f64]);
    /// The torsion at every `ts[i]` into `out[i]` (3-D only: false otherwise).
    fn torsions(&self, ts: &[f64], out: &mut [f64]) -> bool;
    /// The fairness figures, the distance measured to the polygon of the flat `points`.
    fn fairness(&self, points: &[f64]) -> CurveFairness;
    /// The nearest points to the flat points `qs` (`dim` coordinates each): parameters,
    /// distances, and foot points (flat).
    fn project(
        &self,
        qs: &[f64],
        tol: f64,
        t: &mut [f64],
        distance: &mut [f64],
        foot: &mut [f64],
    ) -> karkas::Result<()>;
}

/// The geometry of a surface of either dimension on flat buffers (parameters as pairs).
pub trait SurfaceGeometryImpl {
    /// The unit normal at every `(us[i], vs[i])` into `out[3 i..3 i + 3]`.
    fn normals(&self, us: &[f64], vs: &[f64], out: &mut [f64]);
    /// The principal curvatures and directions at every `(us[i], vs[i])`.
    fn principal(&self, us: &[f64], vs: &[f64]) -> Vec<PrincipalCurvatures>;
    /// The nearest points to the flat points `qs`: `u`, `v`, distances, foot points.
    #[allow(clippy::too_many_arguments)]
    fn project(
        &self,
        qs: &[f64],
        cells: (usize, usize),
        tol: f64,
        u: &mut [f64],
        v: &mut [f64],
        distance: &mut [f64],
        foot: &mut [f64],
    ) -> karkas::Result<()>;
}

/// A curve of the base class `Curve` of dimension `D` (checked by the caller) as a karkas
/// curve.
pub struct CurveView<'a, const D: usize>(pub &'a dyn CurveImpl);

impl<const D: usize> CurveView<'_, D> {
    fn at(&self, t: f64, k: usize) -> Point<D> {
        let mut out = [Point::<D>::ZERO];
        self.deriv_into(&[t], k, &mut out);
        out[0]
    }
}

impl<const D: usize> Curve<D> for CurveView<'_, D> {
    fn domain(&self) -> Interval {
        let (a, b) = self.0.domain();
        Interval::new(a, b)
    }
    fn is_closed(&self) -> bool {
        self.0.closed()
    }
    fn eval(&self, t: f64) -> Point<D> {
        self.at(t, 0)
    }
    fn deriv(&self, t: f64, k: usize) -> Point<D> {
        self.at(t, k)
    }
    fn eval_into(&self, ts: &[f64], out: &mut [Point<D>]) {
        self.deriv_into(ts, 0, out);
    }
    fn deriv_into(&self, ts: &[f64], k: usize, out: &mut [Point<D>]) {
        self.0.eval_flat(ts, k, bytemuck::cast_slice_mut(out));
    }
}

/// A surface of the base class `Surface` as a karkas surface in space (planar surfaces in
/// `z = 0`).
pub struct SurfaceView<'a>(pub &'a dyn SurfaceImpl);

impl SurfaceView<'_> {
    /// The derivative `(ku, kv)` on the grid `us x vs` in space.
    fn grid(&self, us: &[f64], vs: &[f64], ku: usize, kv: usize, out: &mut [Point3]) {
        if self.0.dim() == 3 {
            self.0
                .grid_flat(us, vs, ku, kv, bytemuck::cast_slice_mut(out));
            return;
        }
        let d = self.0.dim();
        let mut flat = vec![0.0; us.len() * vs.len() * d];
        self.0.grid_flat(us, vs, ku, kv, &mut flat);
        for (p, q) in out.iter_mut().zip(flat.chunks_exact(d)) {
            *p = Point3::ZERO;
            p.0[..d].copy_from_slice(q);
        }
    }
    fn at(&self, u: f64, v: f64, ku: usize, kv: usize) -> Point3 {
        let mut out = [Point3::ZERO];
        self.grid(&[u], &[v], ku, kv, &mut out);
        out[0]
    }
}

impl Surface<3> for SurfaceView<'_> {
    fn domain_u(&self) -> Interval {
        let (a, b) = self.0.domain_u();
        Interval::new(a, b)
    }
    fn domain_v(&self) -> Interval {
        let (a, b) = self.0.domain_v();
        Interval::new(a, b)
    }
    fn is_closed_u(&self) -> bool {
        self.0.closed().0
    }
    fn is_closed_v(&self) -> bool {
        self.0.closed().1
    }
    fn eval(&self, u: f64, v: f64) -> Point3 {
        self.at(u, v, 0, 0)
    }
    fn deriv(&self, u: f64, v: f64, ku: usize, kv: usize) -> Point3 {
        self.at(u, v, ku, kv)
    }
    fn eval_grid_into(&self, us: &[f64], vs: &[f64], out: &mut [Point3]) {
        self.grid(us, vs, 0, 0, out);
    }
}
