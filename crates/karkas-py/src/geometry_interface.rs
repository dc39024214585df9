//! The dimension-free geometry interfaces every wrapped curve and surface provides (arc
//! length, curvature, projection; normals, principal curvatures, projection), on flat buffers.
//! Their implementations for the library's types are in `geometry`.

use karkas::geometry::{CurveFairness, PrincipalCurvatures};

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
