//! Meshes of bodies: the mesh of a sample grid with its poles closed by fans and its seams
//! welded, its open planar boundary loops capped, turned so that its normals point out of
//! the volume it encloses, and that volume.
//!
//! - Poles and seams ([`weld_grid_mesh`]): a sample row or column whose samples all
//!   coincide (within `1e-12` of the largest coordinate, as the seams of
//!   `mesh/triangulate.rs`) is a pole, the nose or tail of a body: its samples become one
//!   vertex, and of the two triangles of each grid cell next to it the one with two corners
//!   at the pole is left out, so the pole is closed by a fan and no triangle has zero area.
//!   A closed direction's repeated row (column) is the first one (its seam welded).
//! - Caps ([`cap_open_loops`]): the edges used by one triangle form the open boundary; each
//!   of its loops must lie in a plane (within `CAP_RELATIVE_FLATNESS` (1e-6) of the mesh's size,
//!   the rule of the CAD caps, [`crate::cad::CadShell::cap_free_loops`]) and is closed by
//!   the triangles of its polygon in that plane, found by ear clipping
//!   ([`earcutr`], Mapbox's earcut: right for any simple polygon, star-shaped or not), over
//!   the loop's own vertices, so the cap shares its edges with the surface.
//! - Closed and outward ([`is_closed`], [`signed_volume`], [`orient_outward`]): a mesh is
//!   closed when every edge is used once in each direction (watertight, its winding
//!   consistent); its volume is the divergence theorem's sum of `a . (b x c) / 6` over its
//!   triangles, positive when the normals point outwards.
//!
//! Cost: O(triangles) with a hash map of the edges; the caps O(m^2) in the worst case for a
//! loop of `m` vertices (earcut's z-order hashing makes it near O(m log m) on large loops).

use std::collections::HashMap;

use karkas::geometry::polygon_plane;
use karkas::{Grid, Point3};

use crate::cad::shell::{CapError, CAP_RELATIVE_FLATNESS};
use crate::mesh::error::MeshError;
use crate::mesh::normals::{averaged_normals, cross};
use crate::mesh::triangle_mesh::TriangleMesh;
use crate::mesh::triangulate::GridSeams;

/// The lines of a sample grid that are poles (every sample one point).
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub(crate) struct GridPoles {
    /// The first row (`u` = start).
    pub first_row: bool,
    /// The last row.
    pub last_row: bool,
    /// The first column (`v` = start).
    pub first_col: bool,
    /// The last column.
    pub last_col: bool,
}

impl GridPoles {
    /// The pole lines of the `nu x nv` grid `points` (see the module docs).
    pub(crate) fn detect(nu: usize, nv: usize, points: &[Point3]) -> GridPoles {
        if nu < 2 || nv < 2 || nu.checked_mul(nv) != Some(points.len()) {
            return GridPoles::default();
        }
        let scale = points.iter().fold(0.0_f64, |s, p| s.max(p.max_abs()));
        let tolerance = 1e-12 * scale;
        let at = |a: usize, b: usize| points[a * nv + b];
        let row = |a: usize| (1..nv).all(|b| at(a, b).distance(at(a, 0)) <= tolerance);
        let col = |b: usize| (1..nu).all(|a| at(a, b).distance(at(0, b)) <= tolerance);
        GridPoles {
            first_row: row(0),
            last_row: row(nu - 1),
            first_col: col(0),
            last_col: col(nv - 1),
        }
    }

    /// True when some line is a pole.
    pub fn any(&self) -> bool {
        self.first_row || self.last_row || self.first_col || self.last_col
    }
}

/// True when the mesh of the sample grid `mesh` has a pole line (see the module docs); false
/// for a general mesh.
pub(crate) fn has_poles(mesh: &TriangleMesh) -> bool {
    match mesh.grid {
        Some((nu, nv)) => GridPoles::detect(nu, nv, &mesh.positions).any(),
        None => false,
    }
}

/// The mesh of a sample grid with its poles and seams welded (see the module docs), as a
/// general mesh (no grid shape); a general mesh is returned as it is. Every vertex keeps its
/// sample's normal, but a pole's, which is the area-weighted mean of its fan's.
pub fn weld_grid_mesh(mesh: &TriangleMesh) -> TriangleMesh {
    let Some((nu, nv)) = mesh.grid else {
        return mesh.clone();
    };
    if nu.checked_mul(nv) != Some(mesh.positions.len()) {
        return mesh.clone();
    }
    let seams = GridSeams::detect(nu, nv, &mesh.positions);
    let poles = GridPoles::detect(nu, nv, &mesh.positions);
    // The sample every sample is welded to: its seam's first line, its pole's first sample.
    let canonical = |k: usize| {
        let (mut a, mut b) = (k / nv, k % nv);
        for _ in 0..2 {
            if seams.closed_u && a == nu - 1 {
                a = 0;
            }
            if seams.closed_v && b == nv - 1 {
                b = 0;
            }
            if (poles.first_row && a == 0) || (poles.last_row && a == nu - 1) {
                b = 0;
            }
            if (poles.first_col && b == 0) || (poles.last_col && b == nv - 1) {
                a = 0;
            }
        }
        a * nv + b
    };
    let mut vertex = vec![u32::MAX; mesh.positions.len()];
    let mut positions = Vec::new();
    let mut normals = Vec::new();
    let mut pole_vertex = Vec::new();
    for k in 0..mesh.positions.len() {
        let c = canonical(k);
        if vertex[c] == u32::MAX {
            vertex[c] = positions.len() as u32;
            positions.push(mesh.positions[c]);
            normals.push(mesh.normals.get(c).copied().unwrap_or(Point3::ZERO));
            let (a, b) = (c / nv, c % nv);
            pole_vertex.push(
                (poles.first_row && a == 0)
                    || (poles.last_row && a == nu - 1)
                    || (poles.first_col && b == 0)
                    || (poles.last_col && b == nv - 1),
            );
        }
        vertex[k] = vertex[c];
    }
    let triangles: Vec<[u32; 3]> = mesh
        .triangles
        .iter()
        .map(|t| t.map(|k| vertex[k as usize]))
        .filter(|t| t[0] != t[1] && t[1] != t[2] && t[2] != t[0])
        .collect();
    if pole_vertex.iter().any(|&p| p) || mesh.normals.len() != mesh.positions.len() {
        let averaged = averaged_normals(&positions, &triangles);
        for ((n, a), &pole) in normals.iter_mut().zip(averaged).zip(&pole_vertex) {
            if pole || mesh.normals.len() != mesh.positions.len() {
                *n = a;
            }
        }
    }
    TriangleMesh {
        positions,
        normals,
        triangles,
        grid: None,
    }
}

/// A planar cap that [`cap_open_loops`] added.
#[derive(Clone, Debug, PartialEq)]
pub struct MeshCap {
    /// The loop's vertices, in the order the cap runs around them.
    pub vertices: Vec<u32>,
    /// The area of the cap's triangles.
    pub area: f64,
}

/// Closes every loop of the open boundary of `mesh` (edges used by one triangle) with the
/// triangles of its planar polygon (see the module docs), appended to `mesh.triangles` and
/// wound so that each boundary edge is then used once in each direction. Nothing is added on
/// an error.
///
/// Errors: [`CapError::NothingToCap`] (no open edge), [`CapError::NotALoop`] (a vertex
/// where the open edges branch or end), [`CapError::NotPlanar`] (a loop farther than
/// `CAP_RELATIVE_FLATNESS` (1e-6) of the mesh's size from its plane, or enclosing no area).
pub fn cap_open_loops(mesh: &mut TriangleMesh) -> Result<Vec<MeshCap>, CapError> {
    let loops = boundary_loops(mesh)?;
    if loops.is_empty() {
        return Err(CapError::NothingToCap);
    }
    let size = diagonal(&mesh.positions);
    let mut caps = Vec::with_capacity(loops.len());
    let mut added = Vec::new();
    for boundary in loops {
        // The cap runs against the surface along their shared edges.
        let vertices: Vec<u32> = boundary.into_iter().rev().collect();
        let points: Vec<Point3> = vertices
            .iter()
            .map(|&k| mesh.positions[k as usize])
            .collect();
        let at = points[0].0;
        let not_planar = |deviation: f64| CapError::NotPlanar {
            at,
            deviation,
            relative: deviation / size,
            limit: CAP_RELATIVE_FLATNESS,
        };
        let (plane, deviation) = polygon_plane(&points).ok_or_else(|| not_planar(f64::NAN))?;
        if deviation.is_nan() || deviation > CAP_RELATIVE_FLATNESS * size {
            return Err(not_planar(deviation));
        }
        // The polygon in the plane's coordinates, counter-clockwise about its normal.
        let x = plane.x_axis();
        let y = cross(plane.normal, x);
        let flat: Vec<f64> = points
            .iter()
            .flat_map(|&p| {
                let d = p - plane.origin;
                [d.dot(x), d.dot(y)]
            })
            .collect();
        let corners = earcutr::earcut(&flat, &[], 2).map_err(|_| not_planar(deviation))?;
        if corners.len() != 3 * (points.len() - 2) {
            // Ear clipping left part of the polygon out (it crosses itself).
            return Err(not_planar(deviation));
        }
        let twice = |t: &[usize]| {
            let (a, b, c) = (t[0], t[1], t[2]);
            (flat[2 * b] - flat[2 * a]) * (flat[2 * c + 1] - flat[2 * a + 1])
                - (flat[2 * c] - flat[2 * a]) * (flat[2 * b + 1] - flat[2 * a + 1])
        };
        // Ear clipping gives every triangle the same winding: turn them all by the sign of
        // their sum (the polygon's), not one by one, since a sliver over collinear points
        // (a straight trailing edge) has a signed area that is rounding.
        let total: f64 = corners.chunks_exact(3).map(twice).sum();
        let mut area = 0.0;
        for t in corners.chunks_exact(3) {
            let (a, b, c) = (t[0], t[1], t[2]);
            let (b, c) = if total >= 0.0 { (b, c) } else { (c, b) };
            area += 0.5 * twice(t).abs();
            added.push([vertices[a], vertices[b], vertices[c]]);
        }
        caps.push(MeshCap { vertices, area });
    }
    mesh.triangles.extend(added);
    Ok(caps)
}

/// The loops of the open boundary of `mesh`, each in the direction its edges run in their
/// triangles.
fn boundary_loops(mesh: &TriangleMesh) -> Result<Vec<Vec<u32>>, CapError> {
    let edges = directed_edges(mesh);
    let mut next: HashMap<u32, u32> = HashMap::new();
    for &(a, b) in edges.keys() {
        if edges.contains_key(&(b, a)) {
            continue;
        }
        if next.insert(a, b).is_some() {
            return Err(not_a_loop(mesh, a));
        }
    }
    let mut starts: Vec<u32> = next.keys().copied().collect();
    starts.sort_unstable();
    let mut seen = HashMap::new();
    let mut loops = Vec::new();
    for start in starts {
        if seen.contains_key(&start) {
            continue;
        }
        let mut boundary = Vec::new();
        let mut at = start;
        loop {
            if seen.insert(at, ()).is_some() {
                return Err(not_a_loop(mesh, at));
            }
            boundary.push(at);
            at = *next.get(&at).ok_or_else(|| not_a_loop(mesh, at))?;
            if at == start {
                break;
            }
        }
        loops.push(boundary);
    }
    Ok(loops)
}

/// [`CapError::NotALoop`] at vertex `k`.
fn not_a_loop(mesh: &TriangleMesh, k: u32) -> CapError {
    CapError::NotALoop {
        at: mesh.positions[k as usize].0,
    }
}

/// How often each directed edge `(a, b)` is used by the triangles of `mesh`.
fn directed_edges(mesh: &TriangleMesh) -> HashMap<(u32, u32), u32> {
    let mut edges = HashMap::with_capacity(3 * mesh.triangles.len());
    for t in &mesh.triangles {
        for e in 0..3 {
            *edges.entry((t[e], t[(e + 1) % 3])).or_insert(0) += 1;
        }
    }
    edges
}

/// True when every edge of `mesh` is used once in each direction: the mesh is watertight and
/// its winding consistent (see the module docs).
pub fn is_closed(mesh: &TriangleMesh) -> bool {
    let edges = directed_edges(mesh);
    !edges.is_empty()
        && edges
            .iter()
            .all(|(&(a, b), &n)| n == 1 && edges.get(&(b, a)) == Some(&1))
}

/// The signed volume enclosed by the triangles of `mesh`: `sum a . (b x c) / 6`, positive when
/// a closed mesh's normals point outwards (meaningful for a closed mesh only).
pub fn signed_volume(mesh: &TriangleMesh) -> f64 {
    mesh.triangles
        .iter()
        .map(|t| {
            let [a, b, c] = t.map(|k| mesh.positions[k as usize]);
            a.dot(cross(b, c))
        })
        .sum::<f64>()
        / 6.0
}

/// Turns a closed `mesh` (see [`is_closed`]) over when its normals point inwards, and returns
/// the volume it encloses; `None`, the mesh untouched, when it is not closed.
pub fn orient_outward(mesh: &mut TriangleMesh) -> Option<f64> {
    if !is_closed(mesh) {
        return None;
    }
    let volume = signed_volume(mesh);
    if volume < 0.0 {
        mesh.flip_orientation();
    }
    Some(volume.abs())
}

/// What [`body_mesh`] made of a sample grid.
#[derive(Clone, Debug, Default, PartialEq)]
pub struct MeshBody {
    /// The planar caps added.
    pub caps: Vec<MeshCap>,
    /// The volume enclosed, when the mesh is closed (it is then turned outwards).
    pub volume: Option<f64>,
}

/// The error of [`body_mesh`].
#[derive(Debug, Clone, PartialEq, thiserror::Error)]
#[non_exhaustive]
pub enum BodyMeshError {
    /// The grid is too large for a mesh.
    #[error(transparent)]
    Mesh(#[from] MeshError),
    /// The caps asked for cannot be made.
    #[error(transparent)]
    Cap(#[from] CapError),
}

/// The mesh of the sample grid `grid` as a body (see the module docs): its poles closed by
/// fans and its seams welded, with `cap` its open boundary loops capped, turned outwards when
/// closed. A grid without poles and caps stays a grid-shaped mesh (its writers weld its
/// seams); otherwise the mesh is a general one.
pub fn body_mesh(
    grid: &Grid<Point3>,
    cap: bool,
) -> Result<(TriangleMesh, MeshBody), BodyMeshError> {
    let mesh = TriangleMesh::from_grid(grid)?;
    if !cap {
        let (mesh, volume) = closed_grid_mesh(mesh);
        return Ok((
            mesh,
            MeshBody {
                caps: Vec::new(),
                volume,
            },
        ));
    }
    let mut welded = weld_grid_mesh(&mesh);
    let caps = cap_open_loops(&mut welded)?;
    let volume = orient_outward(&mut welded);
    Ok((welded, MeshBody { caps, volume }))
}

/// The mesh of a sample grid `mesh` with its poles closed by fans (then a general mesh; else
/// it keeps its grid shape), turned outwards when it is closed, and the volume it then
/// encloses (see the module docs).
pub fn closed_grid_mesh(mesh: TriangleMesh) -> (TriangleMesh, Option<f64>) {
    let (mut out, volume) = if has_poles(&mesh) {
        let welded = weld_grid_mesh(&mesh);
        let volume = is_closed(&welded).then(|| signed_volume(&welded));
        (welded, volume)
    } else {
        // Without poles a grid closes only when both directions are closed (a torus): no
        // copy and no edge map for the large sample grids.
        let closed = match mesh.grid {
            Some((nu, nv)) if nu.checked_mul(nv) == Some(mesh.positions.len()) => {
                let seams = GridSeams::detect(nu, nv, &mesh.positions);
                seams.closed_u && seams.closed_v
            }
            _ => is_closed(&mesh),
        };
        let volume = closed.then(|| signed_volume(&mesh));
        (mesh, volume)
    };
    if volume.is_some_and(|v| v < 0.0) {
        out.flip_orientation();
    }
    (out, volume.map(f64::abs))
}

/// The diagonal of the bounding box of `points`.
fn diagonal(points: &[Point3]) -> f64 {
    let mut low = [f64::INFINITY; 3];
    let mut high = [f64::NEG_INFINITY; 3];
    for p in points {
        for c in 0..3 {
            low[c] = low[c].min(p[c]);
            high[c] = high[c].max(p[c]);
        }
    }
    (0..3)
        // `hypot` on the sides: their squares would underflow below about 1e-154 units.
        .fold(0.0f64, |d, c| d.hypot(high[c] - low[c]))
}

#[cfg(test)]
mod tests {
    use super::*;

    /// A body of revolution about x sampled `nu x nv`, v around (its last column the first);
    /// its first and last rows one point (poles) when `poles`, else rings of radius 0.5.
    fn body(nu: usize, nv: usize, poles: bool) -> Grid<Point3> {
        Grid::from_fn(nu, nv, |a, b| {
            let s = a as f64 / (nu - 1) as f64;
            let r = if poles {
                (std::f64::consts::PI * s).sin()
            } else {
                0.5 + 0.5 * (std::f64::consts::PI * s).sin()
            };
            let r = if poles && (a == 0 || a == nu - 1) {
                0.0
            } else {
                r
            };
            let phi = std::f64::consts::TAU * (b % (nv - 1)) as f64 / (nv - 1) as f64;
            Point3::new([2.0 * s, r * phi.cos(), r * phi.sin()])
        })
    }

    #[test]
    fn poles_close_with_fans_and_seams_weld() {
        let (nu, nv) = (9, 13);
        let (mesh, body) = body_mesh(&body(nu, nv, true), false).unwrap();
        // (nu - 2) rings of nv - 1 vertices and two poles; the cells next to a pole give one
        // triangle each.
        assert_eq!(mesh.positions.len(), (nu - 2) * (nv - 1) + 2);
        assert_eq!(mesh.triangles.len(), 2 * (nu - 1) * (nv - 1) - 2 * (nv - 1));
        assert!(mesh.grid.is_none());
        for t in &mesh.triangles {
            assert!(
                mesh.face_normal(*t).norm() > 0.5,
                "zero-area triangle {t:?}"
            );
        }
        assert!(is_closed(&mesh));
        let volume = body.volume.unwrap();
        assert!((signed_volume(&mesh) - volume).abs() <= 1e-12 * volume);
        assert!(volume > 0.0);
        // The pole's normal points along the axis, out of the body.
        let nose = mesh.positions.iter().position(|p| p[0] == 0.0).unwrap();
        assert!(mesh.normals[nose][0] < -0.99, "{:?}", mesh.normals[nose]);
    }

    #[test]
    fn open_ends_are_capped_into_a_closed_outward_mesh() {
        let (nu, nv) = (6, 17);
        let grid = body(nu, nv, false);
        let (open, plain) = body_mesh(&grid, false).unwrap();
        assert!(plain.volume.is_none() && plain.caps.is_empty());
        assert_eq!(open.grid, Some((nu, nv)));
        let (mesh, body) = body_mesh(&grid, true).unwrap();
        assert_eq!(body.caps.len(), 2);
        for cap in &body.caps {
            // A regular 16-gon of radius 0.5.
            let area = 0.5 * 16.0 * 0.25 * (std::f64::consts::TAU / 16.0).sin();
            assert!((cap.area - area).abs() < 1e-12, "{}", cap.area);
            assert_eq!(cap.vertices.len(), nv - 1);
        }
        assert!(is_closed(&mesh));
        assert!(signed_volume(&mesh) > 0.0);
        assert_eq!(body.volume, Some(signed_volume(&mesh)));
        // Turned over first, it comes back outwards.
        let mut inward = mesh.clone();
        inward.flip_orientation();
        assert!(signed_volume(&inward) < 0.0);
        let volume = orient_outward(&mut inward).unwrap();
        assert!((volume - body.volume.unwrap()).abs() < 1e-12);
        assert!(signed_volume(&inward) > 0.0);
    }

    #[test]
    fn a_concave_loop_is_capped_by_its_own_polygon() {
        // A prism over an L-shaped (not star-shaped from its centroid) section, the section a
        // closed direction: a fan from the centroid would cross the outline.
        let outline = [
            [0.0, 0.0],
            [3.0, 0.0],
            [3.0, 0.2],
            [0.2, 0.2],
            [0.2, 3.0],
            [0.0, 3.0],
        ];
        let nv = outline.len() + 1;
        let grid = Grid::from_fn(2, nv, |a, b| {
            let [y, z] = outline[b % outline.len()];
            Point3::new([a as f64, y, z])
        });
        let (mesh, body) = body_mesh(&grid, true).unwrap();
        assert!(is_closed(&mesh));
        let section = 3.0 * 0.2 + 2.8 * 0.2;
        for cap in &body.caps {
            assert!((cap.area - section).abs() < 1e-12, "{}", cap.area);
        }
        assert!((body.volume.unwrap() - section).abs() < 1e-12);
    }

    #[test]
    fn a_loop_with_a_long_straight_run_is_capped_with_one_winding() {
        // A half ellipse closed by a straight side of 299 collinear samples (and a short
        // blunt edge), far from the origin, where ear clipping leaves slivers whose signed
        // area is rounding.
        let mut outline: Vec<[f64; 2]> = (0..=40)
            .map(|k| {
                let phi = std::f64::consts::PI * k as f64 / 40.0;
                [phi.cos(), 0.06 * phi.sin()]
            })
            .collect();
        outline.extend((1..300).map(|k| {
            let s = k as f64 / 300.0;
            [-1.0 + 2.0 * s, -1e-3 * s]
        }));
        let nv = outline.len() + 1;
        let grid = Grid::from_fn(3, nv, |a, b| {
            let [y, z] = outline[b % outline.len()];
            Point3::new([700.0 + a as f64, 300.0 + y, -50.0 + z])
        });
        let (mesh, body) = body_mesh(&grid, true).unwrap();
        assert_eq!(body.caps.len(), 2);
        assert!(is_closed(&mesh), "the caps' winding is not consistent");
        assert!(body.volume.unwrap() > 0.0);
    }

    #[test]
    fn caps_refuse_a_closed_body_and_a_warped_loop() {
        let closed = body(7, 9, true);
        assert_eq!(
            body_mesh(&closed, true).unwrap_err(),
            CapError::NothingToCap.into()
        );
        let warped = Grid::from_fn(3, 9, |a, b| {
            let phi = std::f64::consts::TAU * (b % 8) as f64 / 8.0;
            let lift = if a == 0 { 0.1 * (2.0 * phi).cos() } else { 0.0 };
            Point3::new([a as f64 + lift, phi.cos(), phi.sin()])
        });
        let err = body_mesh(&warped, true).unwrap_err();
        assert!(err.to_string().contains("not planar"), "{err}");
        // An open sheet's boundary is one planar loop: capped by a polygon of the sheet's
        // area (the flat pillow encloses nothing).
        let sheet = Grid::from_fn(3, 4, |a, b| Point3::new([a as f64, b as f64, 0.0]));
        let (_, body) = body_mesh(&sheet, true).unwrap();
        assert_eq!(body.caps.len(), 1);
        assert!(
            (body.caps[0].area - 6.0).abs() < 1e-12,
            "{}",
            body.caps[0].area
        );
        assert!(body.volume.unwrap_or(0.0).abs() < 1e-12);
    }
}
