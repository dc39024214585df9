//! The geometry methods (`arc_length`, `curvature`, `project`, `normal`, ...) on derivative
//! curves and surfaces: a derivative object is seen as a library curve or surface evaluating
//! its parent's higher derivatives, and handed to the same generic code as every other class.

use std::sync::Arc;

use karkas::geometry::PrincipalCurvatures;
use karkas::{Curve, Interval, PiecewiseCurve, Point, Side, Surface};

use crate::convert::by_dim;
use crate::curve_eval::DerivativeCurve;
use crate::geometry_interface::{CurveGeometryImpl, SurfaceGeometryImpl};
use crate::surface_eval::DerivativeSurface;
use crate::wrapper::{CurveImpl, SurfaceImpl, Wrapped, WrappedSurface};

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
