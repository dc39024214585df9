//! The base classes' dimension-free curves and surfaces seen again as karkas curves and
//! surfaces of a fixed dimension, for karkas-io's writers: sampled with the library's own
//! uniform parameters ([`karkas::Curve::sample_into`]), so that a file written from Python is
//! the file the command line writes.

use karkas::{Curve, Interval, Point, Point3, Surface};

use crate::wrapper::{CurveImpl, SurfaceImpl};

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
