//! What the CAD writers (the `step` and `iges` modules) write: exact B-spline
//! curves and surfaces of karkas (see [`karkas::bspline`]), in 3-D, and the number and knot
//! formatting both formats share.

use karkas::bspline::{BSplineCurve, BSplineSurface, NurbsCurve, NurbsSurface};
use karkas::Point;

use crate::cad::shell::{CadShell, FaceSurface};
use crate::error::IoError;
use crate::write::write_atomic;

/// One geometric item of a CAD file.
#[derive(Clone, Copy, Debug)]
pub enum CadEntity<'a> {
    /// A B-spline curve (in STEP: a `B_SPLINE_CURVE_WITH_KNOTS` in a wireframe
    /// representation; in IGES: entity 126).
    Curve(&'a BSplineCurve<3>),
    /// A B-spline surface (in STEP: a `B_SPLINE_SURFACE_WITH_KNOTS` as the one face of a
    /// shell bounded by its boundary curves, with poles and seams as [`CadShell`] makes
    /// them, a solid when the surface closes on itself; in IGES: entity 128).
    Surface(&'a BSplineSurface<3>),
    /// A rational B-spline curve (in STEP: the complex instance of `B_SPLINE_CURVE_WITH_KNOTS`
    /// and `RATIONAL_B_SPLINE_CURVE`; in IGES: entity 126 with its weights).
    RationalCurve(&'a NurbsCurve<3>),
    /// A rational B-spline surface (in STEP: the complex instance of
    /// `B_SPLINE_SURFACE_WITH_KNOTS` and `RATIONAL_B_SPLINE_SURFACE` as a face; in IGES:
    /// entity 128 with its weights).
    RationalSurface(&'a NurbsSurface<3>),
    /// A shell of B-spline faces and planar caps (in STEP: an open shell, or a solid when
    /// it is closed; in IGES: its faces, entity 128, and its caps, trimmed planes, entity
    /// 144).
    Shell(&'a CadShell),
}

/// The one-face shell of the surface `s`, turned outwards when it is closed (a body closed by
/// its poles and seams).
pub(crate) fn surface_shell(s: &BSplineSurface<3>) -> CadShell {
    let mut shell = CadShell::of_surfaces(std::slice::from_ref(s));
    if shell.is_closed() {
        shell.orient_outward();
    }
    shell
}

/// A curve of dimension `D <= 3` in 3-D space (missing coordinates 0: a planar curve lies
/// in the plane `z = 0`), with the same degree and knots.
///
/// Errors: `D > 3` ([`CadError::TooManyDimensions`]); the library refusing the curve
/// ([`CadError::Geometry`]).
pub fn curve_in_space<const D: usize>(
    curve: &BSplineCurve<D>,
) -> Result<BSplineCurve<3>, CadError> {
    if D > 3 {
        return Err(CadError::TooManyDimensions { dimensions: D });
    }
    let control = curve
        .control_points()
        .iter()
        .map(|p| Point(core::array::from_fn(|c| if c < D { p[c] } else { 0.0 })))
        .collect();
    BSplineCurve::new(curve.degree(), curve.knots().to_vec(), control).map_err(CadError::Geometry)
}

/// Why a curve cannot be placed in a CAD file.
#[derive(Debug, thiserror::Error)]
#[non_exhaustive]
pub enum CadError {
    /// The curve has more than three coordinates.
    #[error("a curve in {dimensions} dimensions cannot be written to a CAD file (at most 3)")]
    TooManyDimensions {
        /// Its number of coordinates.
        dimensions: usize,
    },
    /// The library refused the curve in space.
    #[error("{0}")]
    Geometry(#[source] karkas::Error),
}

/// The highest degree written to STEP and IGES: Open CASCADE reads B-splines of higher degree
/// as empty shapes (its `Geom_BSplineCurve` stops at degree 25).
pub const MAX_CAD_DEGREE: usize = 25;

/// Whether the clamped curve `c` is closed: marked so, or its ends (its first and last control
/// points) coincide to `1e-12` of the control polygon's size (a closed curve whose mark was
/// lost on the way, as a SciPy `(t, c, k)` or a curve placed in space).
pub fn curve_closed(c: &BSplineCurve<3>) -> bool {
    use karkas::Curve;
    c.is_closed()
        || lines_meet(c.control_points(), |k| {
            c.control_points()[k * (c.control_points().len() - 1)]
        })
}

/// Whether the surface `s` is closed in `u` and in `v`: marked so, or its first and last
/// rows (columns) of control points coincide, as [`curve_closed`] tells for curves.
pub fn surface_closed(s: &BSplineSurface<3>) -> (bool, bool) {
    use karkas::Surface;
    let grid = s.control_points();
    let (rows, cols) = (grid.rows(), grid.cols());
    let all = grid.as_slice();
    let u = (0..cols).all(|j| lines_meet(all, |k| *grid.get(k * (rows - 1), j)));
    let v = (0..rows).all(|i| lines_meet(all, |k| *grid.get(i, k * (cols - 1))));
    (s.is_closed_u() || u, s.is_closed_v() || v)
}

/// True when `end(0)` and `end(last)` coincide to `1e-12` of the size of `points` (`end(k)`
/// gives the first point for `k = 0` and the last for `k = 1`).
fn lines_meet(points: &[Point<3>], end: impl Fn(usize) -> Point<3>) -> bool {
    let (first, last) = (end(0), end(1));
    let size = points
        .iter()
        .map(|p| (*p - points[0]).norm())
        .fold(0.0, f64::max);
    size > 0.0 && (last - first).norm() <= 1e-12 * size
}

/// The largest absolute coordinate of the control points of `entities` (IGES's global
/// "maximum coordinate value").
pub(crate) fn max_coordinate(entities: &[CadEntity<'_>]) -> f64 {
    let largest = |points: &[Point<3>]| points.iter().map(|p| p.max_abs()).fold(0.0, f64::max);
    entities
        .iter()
        .map(|e| match e {
            CadEntity::Curve(c) => largest(c.control_points()),
            CadEntity::Surface(s) => largest(s.control_points().as_slice()),
            CadEntity::Shell(shell) => shell
                .faces()
                .iter()
                .map(|f| match &f.surface {
                    FaceSurface::BSpline(s) => largest(s.control_points().as_slice()),
                    FaceSurface::Plane(_) => 0.0,
                })
                .chain(
                    shell
                        .edges()
                        .iter()
                        .map(|e| largest(e.curve.control_points())),
                )
                .fold(0.0, f64::max),
            CadEntity::RationalCurve(c) => largest(c.control_points()),
            CadEntity::RationalSurface(s) => largest(s.control_points().as_slice()),
        })
        .fold(0.0, f64::max)
}

/// Writes the CAD file `path` atomically with the text `render(entities, name)`, `name` being
/// the file stem (`karkas` when it has none).
pub(crate) fn write_named(
    path: &std::path::Path,
    entities: &[CadEntity<'_>],
    render: fn(&[CadEntity<'_>], &str) -> String,
) -> Result<(), IoError> {
    let name = path
        .file_stem()
        .and_then(|s| s.to_str())
        .unwrap_or("karkas");
    let text = render(entities, name);
    write_atomic(path, |out| out.write_all(text.as_bytes()))
}

/// A real number with 17 significant digits (round-trips every `f64`) and an exponent, with
/// the decimal point that STEP and IGES require: `-1.2345678901234567E-3`.
pub(crate) fn real(x: f64) -> String {
    let x = if x == 0.0 { 0.0 } else { x }; // no "-0"
    format!("{x:.16E}")
}

/// The distinct values of a sorted knot vector and their multiplicities.
pub(crate) fn knot_runs(knots: &[f64]) -> (Vec<f64>, Vec<usize>) {
    let mut values: Vec<f64> = Vec::new();
    let mut counts: Vec<usize> = Vec::new();
    for &k in knots {
        if values.last() == Some(&k) {
            if let Some(c) = counts.last_mut() {
                *c += 1;
            }
        } else {
            values.push(k);
            counts.push(1);
        }
    }
    (values, counts)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn reals_round_trip_and_carry_a_point() {
        for x in [
            0.0,
            -0.0,
            1.0,
            -2.5e-300,
            1.0 / 3.0,
            123456789.123,
            f64::MAX,
        ] {
            let s = real(x);
            assert!(s.contains('.') && s.contains('E'), "{s}");
            assert_eq!(s.parse::<f64>().unwrap(), x);
        }
        assert_eq!(real(-0.0), "0.0000000000000000E0");
    }

    #[test]
    fn knot_runs_count_multiplicities() {
        let (v, m) = knot_runs(&[0.0, 0.0, 0.0, 0.5, 0.5, 1.0, 1.0, 1.0]);
        assert_eq!(v, vec![0.0, 0.5, 1.0]);
        assert_eq!(m, vec![3, 2, 3]);
    }
}
