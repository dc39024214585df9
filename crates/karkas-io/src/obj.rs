//! A sampled surface as a Wavefront OBJ triangle mesh.
//!
//! OBJ is the plainest mesh format every 3-D viewer and modeller opens. It is a few kinds of
//! text lines, so it is written by hand rather than through a crate.
//!
//! The mesh is the sample grid itself (`nu x nv` points, row-major, `u` outer): `v` lines for
//! the points, `vn` lines for one normal per point, and two triangles per grid cell, all
//! counter-clockwise seen from the side the normals point to. Normals are the normalised cross
//! product of the grid differences along `u` and along `v` (central inside, one-sided at the
//! borders; a zero normal, e.g. at a pole, is written as `0 0 1`). When the last sample row
//! (column) coincides with the first, as for a closed surface sampled over its whole period, the
//! differences wrap around the seam so that both copies of the seam get the same normal; the
//! seam points themselves are still written twice (no welding).

use std::io::{self, Write};
use std::path::Path;

use karkas::{Point, Point3};

use crate::error::IoError;
use crate::mesh::TriangleMesh;
use crate::write::write_atomic;

/// Writes the `nu x nv` sample grid `points` (row-major, `u` outer) as an OBJ mesh at `path`,
/// atomically. A `points.len()` other than `nu * nv` is an [`IoError::Write`].
pub fn write_surface_obj(
    path: &Path,
    nu: usize,
    nv: usize,
    points: &[Point3],
) -> Result<(), IoError> {
    if nu.checked_mul(nv) != Some(points.len()) {
        return Err(IoError::Write {
            path: path.to_path_buf(),
            source: shape_error(nu, nv, points.len()),
        });
    }
    write_atomic(path, |out| render_surface_obj(nu, nv, points, out))
}

/// Writes the OBJ text of the `nu x nv` sample grid `points` into `out`.
///
/// Fails with [`io::ErrorKind::InvalidInput`] when `points.len() != nu * nv`.
pub fn render_surface_obj(
    nu: usize,
    nv: usize,
    points: &[Point3],
    out: &mut dyn Write,
) -> io::Result<()> {
    if nu.checked_mul(nv) != Some(points.len()) {
        return Err(shape_error(nu, nv, points.len()));
    }
    writeln!(out, "# karkas surface, {nu} x {nv} samples")?;
    for p in points {
        writeln!(out, "v {} {} {}", p[0], p[1], p[2])?;
    }
    let grid = SampleGrid::new(nu, nv, points);
    for a in 0..nu {
        for b in 0..nv {
            let n = grid.normal(a, b);
            writeln!(out, "vn {} {} {}", n[0], n[1], n[2])?;
        }
    }
    // 1-based index of sample (a, b).
    let index = |a: usize, b: usize| a * nv + b + 1;
    for a in 0..nu.saturating_sub(1) {
        for b in 0..nv.saturating_sub(1) {
            let (p, q, r, s) = (
                index(a, b),
                index(a + 1, b),
                index(a + 1, b + 1),
                index(a, b + 1),
            );
            writeln!(out, "f {p}//{p} {q}//{q} {r}//{r}")?;
            writeln!(out, "f {p}//{p} {r}//{r} {s}//{s}")?;
        }
    }
    Ok(())
}

/// The unit normals of every sample of the `nu x nv` grid `points` (`points.len() == nu nv`),
/// row-major (see the module docs): `d/du x d/dv`, or `0 0 1` where that vanishes.
pub(crate) fn grid_normals(nu: usize, nv: usize, points: &[Point3]) -> Vec<Point3> {
    let grid = SampleGrid::new(nu, nv, points);
    (0..nu)
        .flat_map(|a| (0..nv).map(move |b| (a, b)))
        .map(|(a, b)| grid.normal(a, b))
        .collect()
}

/// Writes the triangle mesh `mesh` as OBJ at `path`, atomically: `v`, `vn` (the mesh's
/// normals, or face-averaged ones, see [`TriangleMesh::vertex_normals`]) and `f a//a b//b c//c`
/// lines. A mesh failing [`TriangleMesh::validate`] is an [`IoError::Write`], nothing written.
pub fn write_mesh_obj(path: &Path, mesh: &TriangleMesh) -> Result<(), IoError> {
    crate::mesh_check(path, mesh)?;
    write_atomic(path, |out| render_mesh_obj(mesh, out))
}

/// Writes the OBJ text of `mesh` into `out` (the mesh is assumed valid).
pub fn render_mesh_obj(mesh: &TriangleMesh, out: &mut dyn Write) -> io::Result<()> {
    writeln!(
        out,
        "# karkas mesh, {} vertices, {} triangles",
        mesh.positions.len(),
        mesh.triangles.len()
    )?;
    for p in &mesh.positions {
        writeln!(out, "v {} {} {}", p[0], p[1], p[2])?;
    }
    for n in mesh.vertex_normals() {
        writeln!(out, "vn {} {} {}", n[0], n[1], n[2])?;
    }
    for t in &mesh.triangles {
        let (p, q, r) = (t[0] + 1, t[1] + 1, t[2] + 1);
        writeln!(out, "f {p}//{p} {q}//{q} {r}//{r}")?;
    }
    Ok(())
}

/// The error for a point count that does not match the grid size.
fn shape_error(nu: usize, nv: usize, len: usize) -> io::Error {
    io::Error::new(
        io::ErrorKind::InvalidInput,
        format!("{len} points do not form a {nu} x {nv} grid"),
    )
}

/// A row-major grid of samples, for normals.
struct SampleGrid<'a> {
    nu: usize,
    nv: usize,
    points: &'a [Point3],
    /// The last row coincides with the first.
    closed_u: bool,
    /// The last column coincides with the first.
    closed_v: bool,
}

impl<'a> SampleGrid<'a> {
    /// The grid of `nu x nv` `points` (`points.len() == nu * nv`), its seams detected.
    fn new(nu: usize, nv: usize, points: &'a [Point3]) -> Self {
        let scale = points.iter().fold(0.0_f64, |s, p| s.max(p.max_abs()));
        let tolerance = 1e-12 * scale.max(1.0);
        let at = |a: usize, b: usize| points[a * nv + b];
        let closed_u = nu >= 3 && (0..nv).all(|b| at(0, b).distance(at(nu - 1, b)) <= tolerance);
        let closed_v = nv >= 3 && (0..nu).all(|a| at(a, 0).distance(at(a, nv - 1)) <= tolerance);
        SampleGrid {
            nu,
            nv,
            points,
            closed_u,
            closed_v,
        }
    }

    fn at(&self, a: usize, b: usize) -> Point3 {
        self.points[a * self.nv + b]
    }

    /// The unit normal at sample `(a, b)`: `d/du x d/dv`, or `0 0 1` when that vanishes.
    fn normal(&self, a: usize, b: usize) -> Point3 {
        let du = difference(a, self.nu, self.closed_u, |k| self.at(k, b));
        let dv = difference(b, self.nv, self.closed_v, |k| self.at(a, k));
        let n = cross(du, dv);
        let len = n.norm();
        if len > 0.0 && len.is_finite() {
            n * (1.0 / len)
        } else {
            Point([0.0, 0.0, 1.0])
        }
    }
}

/// The difference of `line` across index `k` of `0..n`: central inside, one-sided at the ends
/// of an open line, wrapping over the seam (`0 == n - 1`) of a closed one.
fn difference(k: usize, n: usize, closed: bool, line: impl Fn(usize) -> Point3) -> Point3 {
    if n < 2 {
        return Point::ZERO;
    }
    let last = n - 1;
    let (before, after) = match (k, closed) {
        (0, true) => (last - 1, 1),
        (k, true) if k == last => (last - 1, 1),
        (0, false) => (0, 1),
        (k, false) if k == last => (last - 1, last),
        (k, _) => (k - 1, k + 1),
    };
    line(after) - line(before)
}

/// The cross product `p x q`.
fn cross(p: Point3, q: Point3) -> Point3 {
    Point([
        p[1] * q[2] - p[2] * q[1],
        p[2] * q[0] - p[0] * q[2],
        p[0] * q[1] - p[1] * q[0],
    ])
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn differences_at_borders_and_seams() {
        let line = |k: usize| Point([k as f64, 0.0, 0.0]);
        assert_eq!(difference(0, 4, false, line)[0], 1.0);
        assert_eq!(difference(3, 4, false, line)[0], 1.0);
        assert_eq!(difference(1, 4, false, line)[0], 2.0);
        assert_eq!(difference(0, 4, true, line)[0], -1.0);
        assert_eq!(difference(0, 1, false, line), Point::ZERO);
    }

    /// The mesh writer gives the same text as the grid writer, apart from the comment line.
    #[test]
    fn mesh_writer_matches_grid_writer() {
        let grid = karkas::Grid::from_fn(3, 2, |a, b| Point([a as f64, b as f64, (a * b) as f64]));
        let mesh = TriangleMesh::from_grid(&grid).unwrap();
        let (mut a, mut b) = (Vec::new(), Vec::new());
        render_surface_obj(3, 2, grid.as_slice(), &mut a).unwrap();
        render_mesh_obj(&mesh, &mut b).unwrap();
        let body = |v: Vec<u8>| {
            String::from_utf8(v)
                .unwrap()
                .split_once('\n')
                .unwrap()
                .1
                .to_owned()
        };
        assert_eq!(body(a), body(b));
    }

    #[test]
    fn cylinder_seam_normals_agree() {
        // A cylinder around z sampled over the full turn: first and last columns coincide.
        let (nu, nv) = (3, 9);
        let pts: Vec<Point3> = (0..nu)
            .flat_map(|a| {
                (0..nv).map(move |b| {
                    let phi = std::f64::consts::TAU * b as f64 / (nv - 1) as f64;
                    let phi = if b == nv - 1 { 0.0 } else { phi };
                    Point([phi.cos(), phi.sin(), a as f64])
                })
            })
            .collect();
        let grid = SampleGrid::new(nu, nv, &pts);
        let (n0, n1) = (grid.normal(1, 0), grid.normal(1, nv - 1));
        assert!(n0.distance(n1) < 1e-12);
        // Radial (up to sign): no z component, unit length, parallel to the point.
        assert!(n0[2].abs() < 1e-12 && (n0.norm() - 1.0).abs() < 1e-12);
        assert!((n0[0].abs() - 1.0).abs() < 1e-12);
    }
}
