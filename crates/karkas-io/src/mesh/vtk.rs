//! Meshes and sampled surfaces for VTK and ParaView: legacy `.vtk` files and XML structured
//! grids (`.vts`).
//!
//! - A sampled surface (a mesh that keeps its grid shape) is written as a legacy
//!   `DATASET STRUCTURED_GRID` (`.vtk`) or as an XML `StructuredGrid` (`.vts`): the points in
//!   VTK order (the first index fastest, so `DIMENSIONS nv nu 1` for a row-major `nu x nv`
//!   grid) and the point normals. ParaView shows it as a surface of
//!   `(nu-1)(nv-1)` quadrilateral cells.
//! - A general triangle mesh is written as a legacy `DATASET UNSTRUCTURED_GRID` of triangles
//!   (`CELLS`, `CELL_TYPES 5`; meshio reads this dataset but not `POLYDATA`); a structured grid
//!   cannot hold it, so `.vts` refuses it.
//!
//! The normals are point data `NORMALS Normals float` in the legacy file (the attribute VTK
//! and ParaView shade with; meshio 5 does not know the keyword, see
//! `tests/mesh/check_meshes.py`) and the `Normals` array of the XML file. Both keep the full
//! sample grid: a structured grid has no shared-vertex seam to weld.
//!
//! Both are ASCII text with shortest round-trip decimals (exact values). They are written
//! directly: the `vtkio` crate covers the same ground but pulls a large dependency tree for a
//! format of a dozen lines.

use std::io::{self, Write};
use std::path::Path;

use crate::error::IoError;
use crate::mesh::error::MeshError;
use crate::mesh::triangle_mesh::TriangleMesh;
use crate::write::write_atomic;

/// Writes `mesh` as a legacy VTK file at `path`, atomically: a structured grid when the mesh
/// has a grid shape, an unstructured grid of triangles otherwise.
pub fn write_mesh_vtk(path: &Path, mesh: &TriangleMesh) -> Result<(), IoError> {
    mesh.check_writable(path)?;
    write_atomic(path, |out| render_mesh_vtk(mesh, out))
}

/// Writes the sampled surface `mesh` as an XML structured grid (`.vts`) at `path`, atomically.
/// A mesh without a grid shape is an [`IoError::InvalidMesh`] ([`MeshError::NotStructured`])
/// and nothing is written.
pub fn write_mesh_vts(path: &Path, mesh: &TriangleMesh) -> Result<(), IoError> {
    mesh.check_writable(path)?;
    if mesh.grid.is_none() {
        return Err(IoError::invalid_mesh(path)(MeshError::NotStructured));
    }
    write_atomic(path, |out| render_mesh_vts(mesh, out))
}

/// Writes the legacy VTK text of `mesh` into `out` (the mesh is assumed valid).
pub fn render_mesh_vtk(mesh: &TriangleMesh, out: &mut dyn Write) -> io::Result<()> {
    let n = mesh.positions.len();
    writeln!(out, "# vtk DataFile Version 3.0\nkarkas mesh\nASCII")?;
    match mesh.grid {
        Some((nu, nv)) => {
            writeln!(out, "DATASET STRUCTURED_GRID\nDIMENSIONS {nv} {nu} 1")?;
        }
        None => writeln!(out, "DATASET UNSTRUCTURED_GRID")?,
    }
    writeln!(out, "POINTS {n} double")?;
    for p in &mesh.positions {
        writeln!(out, "{} {} {}", p[0], p[1], p[2])?;
    }
    if mesh.grid.is_none() {
        let m = mesh.triangles.len();
        writeln!(out, "CELLS {m} {}", 4 * m)?;
        for t in &mesh.triangles {
            writeln!(out, "3 {} {} {}", t[0], t[1], t[2])?;
        }
        writeln!(out, "CELL_TYPES {m}")?;
        for _ in 0..m {
            writeln!(out, "5")?;
        }
    }
    writeln!(out, "POINT_DATA {n}\nNORMALS Normals float")?;
    for p in mesh.vertex_normals() {
        writeln!(out, "{} {} {}", p[0] as f32, p[1] as f32, p[2] as f32)?;
    }
    Ok(())
}

/// Writes the XML structured grid text of the grid-shaped `mesh` into `out`; a mesh without a
/// grid shape is [`io::ErrorKind::InvalidInput`] carrying [`MeshError::NotStructured`].
pub fn render_mesh_vts(mesh: &TriangleMesh, out: &mut dyn Write) -> io::Result<()> {
    let Some((nu, nv)) = mesh.grid else {
        return Err(io::Error::new(
            io::ErrorKind::InvalidInput,
            MeshError::NotStructured,
        ));
    };
    let extent = format!("0 {} 0 {} 0 0", nv.saturating_sub(1), nu.saturating_sub(1));
    writeln!(
        out,
        "<?xml version=\"1.0\"?>\n\
         <VTKFile type=\"StructuredGrid\" version=\"0.1\" byte_order=\"LittleEndian\">\n\
         <StructuredGrid WholeExtent=\"{extent}\">\n<Piece Extent=\"{extent}\">\n\
         <PointData Normals=\"Normals\">\n\
         <DataArray type=\"Float64\" Name=\"Normals\" NumberOfComponents=\"3\" format=\"ascii\">"
    )?;
    for p in mesh.vertex_normals() {
        writeln!(out, "{} {} {}", p[0], p[1], p[2])?;
    }
    writeln!(
        out,
        "</DataArray>\n</PointData>\n<Points>\n\
         <DataArray type=\"Float64\" Name=\"Points\" NumberOfComponents=\"3\" format=\"ascii\">"
    )?;
    for p in &mesh.positions {
        writeln!(out, "{} {} {}", p[0], p[1], p[2])?;
    }
    writeln!(
        out,
        "</DataArray>\n</Points>\n</Piece>\n</StructuredGrid>\n</VTKFile>"
    )
}

#[cfg(test)]
mod tests {
    use super::*;
    use karkas::{Grid, Point3};

    fn grid_mesh() -> TriangleMesh {
        // 2 rows (u) x 3 columns (v); the point of (a, b) is (b, a, 0) so VTK order is visible.
        let grid = Grid::from_fn(2, 3, |a, b| Point3::new([b as f64, a as f64, 0.0]));
        TriangleMesh::from_grid(&grid).unwrap()
    }

    #[test]
    fn legacy_structured_grid_golden() {
        let mut out = Vec::new();
        render_mesh_vtk(&grid_mesh(), &mut out).unwrap();
        let text = String::from_utf8(out).unwrap();
        let expected = "# vtk DataFile Version 3.0\nkarkas mesh\nASCII\n\
            DATASET STRUCTURED_GRID\nDIMENSIONS 3 2 1\nPOINTS 6 double\n\
            0 0 0\n1 0 0\n2 0 0\n0 1 0\n1 1 0\n2 1 0\n\
            POINT_DATA 6\nNORMALS Normals float\n";
        assert!(text.starts_with(expected), "{text}");
        // d/du = +y, d/dv = +x: the normal is -z at every point.
        assert_eq!(text.matches("\n0 0 -1").count(), 6);
    }

    #[test]
    fn legacy_unstructured_grid_for_a_general_mesh() {
        let mut mesh = grid_mesh();
        mesh.grid = None;
        let mut out = Vec::new();
        render_mesh_vtk(&mesh, &mut out).unwrap();
        let text = String::from_utf8(out).unwrap();
        assert!(text.contains("DATASET UNSTRUCTURED_GRID\nPOINTS 6 double\n"));
        assert!(text.contains(
            "CELLS 4 16\n3 0 3 4\n3 0 4 1\n3 1 4 5\n3 1 5 2\nCELL_TYPES 4\n5\n5\n5\n5\nPOINT_DATA 6\n"
        ));
    }

    #[test]
    fn xml_structured_grid_extents_and_counts() {
        let mut out = Vec::new();
        render_mesh_vts(&grid_mesh(), &mut out).unwrap();
        let text = String::from_utf8(out).unwrap();
        assert!(text.contains("<StructuredGrid WholeExtent=\"0 2 0 1 0 0\">"));
        assert!(text.contains("<Piece Extent=\"0 2 0 1 0 0\">"));
        let points = text.split("<Points>").nth(1).unwrap();
        let values = points
            .split("format=\"ascii\">")
            .nth(1)
            .unwrap()
            .split("</DataArray>")
            .next()
            .unwrap();
        assert_eq!(values.split_whitespace().count(), 18);
        let mut general = grid_mesh();
        general.grid = None;
        assert!(render_mesh_vts(&general, &mut Vec::new()).is_err());
    }
}
