//! One entry for every mesh format: [`write_mesh`] and [`read_mesh`] choose the format by the
//! extension of the file name.
//!
//! Written: `.obj`, `.stl`, `.ply`, `.vtk`, `.vts`, `.glb` (STL and PLY binary unless
//! [`MeshOptions::ascii`]). Read: `.obj`, `.stl` (binary or ASCII), `.ply` (any encoding).

use std::path::Path;

use karkas::{Grid, Point3};

use crate::error::{data_error, IoError};
use crate::format::OutputFormat;
use crate::lines::read_text;
use crate::mesh::triangle_mesh::TriangleMesh;
use crate::mesh::{glb, obj, ply, stl, vtk};

/// How [`write_mesh`] writes a mesh.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct MeshOptions {
    /// Write STL and PLY as text instead of binary (the other formats have one encoding).
    pub ascii: bool,
}

/// Writes `mesh` at `path`, atomically, in the format named by the extension of `path` (one of
/// [`OutputFormat::MESHES`]). Another extension is an [`IoError::UnknownExtension`]; a mesh
/// failing [`TriangleMesh::validate`] (or, for `.vts`, without a grid shape) an
/// [`IoError::InvalidMesh`]; nothing is written then.
pub fn write_mesh(path: &Path, mesh: &TriangleMesh, options: &MeshOptions) -> Result<(), IoError> {
    match OutputFormat::from_path(path, &OutputFormat::MESHES)? {
        OutputFormat::Obj => obj::write_mesh_obj(path, mesh),
        OutputFormat::Stl => stl::write_mesh_stl(path, mesh, options.ascii),
        OutputFormat::Ply => {
            let encoding = if options.ascii {
                ply::PlyEncoding::Ascii
            } else {
                ply::PlyEncoding::BinaryLittleEndian
            };
            ply::write_mesh_ply(path, mesh, encoding)
        }
        OutputFormat::Vtk => vtk::write_mesh_vtk(path, mesh),
        OutputFormat::Vts => vtk::write_mesh_vts(path, mesh),
        _ => glb::write_mesh_glb(path, mesh),
    }
}

/// Writes the sampled surface `grid` (row-major, `u` outer) as a mesh at `path` (see
/// [`write_mesh`]); a grid of `2^32` or more samples is an [`IoError::InvalidMesh`].
pub fn write_surface_mesh(
    path: &Path,
    grid: &Grid<Point3>,
    options: &MeshOptions,
) -> Result<(), IoError> {
    let mesh = TriangleMesh::from_grid(grid).map_err(|source| IoError::InvalidMesh {
        path: path.to_path_buf(),
        source,
    })?;
    write_mesh(path, &mesh, options)
}

/// Reads the triangle mesh of `path` by its extension: `.obj`, `.stl` or `.ply`. A mesh
/// without faces is an [`IoError::Data`].
pub fn read_mesh(path: &Path) -> Result<TriangleMesh, IoError> {
    let ext = path
        .extension()
        .and_then(|e| e.to_str())
        .map(str::to_ascii_lowercase);
    let mesh = match ext.as_deref() {
        Some("obj") => obj::parse_obj_mesh(&read_text(path)?, path)?,
        Some("stl") => stl::read_stl(path)?,
        Some("ply") => ply::read_ply(path)?,
        _ => return Err(data_error(path, "not a mesh file (use .obj, .stl or .ply)")),
    };
    if mesh.triangles.is_empty() {
        return Err(data_error(path, "the mesh has no faces"));
    }
    Ok(mesh)
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Every format by its extension, the same bytes as its own writer; round trips of the
    /// readable ones; the refused extension and the refused general mesh for `.vts`.
    #[test]
    fn extension_chooses_the_writer() {
        let dir = tempfile::tempdir().unwrap();
        let grid = Grid::from_fn(3, 4, |a, b| {
            Point3::new([a as f64, b as f64 * 0.5, (a * b) as f64 * 0.25])
        });
        let mesh = TriangleMesh::from_grid(&grid).unwrap();
        let file = |name: &str| dir.path().join(name);
        for ascii in [false, true] {
            let options = MeshOptions { ascii };
            for ext in ["obj", "stl", "ply", "vtk", "vts", "glb"] {
                let path = file(&format!("m.{ext}"));
                write_mesh(&path, &mesh, &options).unwrap();
                let mut own = Vec::new();
                match ext {
                    "obj" => obj::render_mesh_obj(&mesh, &mut own).unwrap(),
                    "stl" if ascii => stl::render_mesh_stl_ascii(&mesh, &mut own).unwrap(),
                    "ply" => {
                        let encoding = if ascii {
                            ply::PlyEncoding::Ascii
                        } else {
                            ply::PlyEncoding::BinaryLittleEndian
                        };
                        ply::render_mesh_ply(&mesh, encoding, &mut own).unwrap()
                    }
                    "vtk" => vtk::render_mesh_vtk(&mesh, &mut own).unwrap(),
                    "vts" => vtk::render_mesh_vts(&mesh, &mut own).unwrap(),
                    "glb" => glb::render_mesh_glb(&mesh, &mut own).unwrap(),
                    _ => {
                        stl::write_surface_stl(&file("own.stl"), 3, 4, grid.as_slice()).unwrap();
                        own = std::fs::read(file("own.stl")).unwrap();
                    }
                }
                assert_eq!(std::fs::read(&path).unwrap(), own, "{ext}, ascii {ascii}");
                if matches!(ext, "obj" | "stl" | "ply") {
                    let back = read_mesh(&path).unwrap();
                    assert_eq!(back.triangles.len(), mesh.triangles.len());
                }
            }
        }
        let e = write_mesh(&file("m.csv"), &mesh, &MeshOptions::default()).unwrap_err();
        assert!(e.to_string().ends_with(
            "unknown output extension (use one of: .obj, .stl, .ply, .vtk, .vts, .glb)"
        ));
        let general = TriangleMesh { grid: None, ..mesh };
        let e = write_mesh(&file("g.vts"), &general, &MeshOptions::default()).unwrap_err();
        assert!(matches!(e, IoError::InvalidMesh { .. }), "{e:?}");
        assert!(!file("g.vts").exists());
    }
}
