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
use crate::mesh::glb::write_mesh_glb;
use crate::mesh::obj::{parse_obj_mesh, write_mesh_obj};
use crate::mesh::ply::{read_ply, write_mesh_ply, PlyEncoding};
use crate::mesh::stl::{read_stl, write_mesh_stl};
use crate::mesh::triangle_mesh::TriangleMesh;
use crate::mesh::vtk::{write_mesh_vtk, write_mesh_vts};

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
    let format = OutputFormat::from_path(path, &OutputFormat::MESHES)?;
    write_mesh_as(format, path, mesh, options)
}

/// Writes `mesh` at `path` (`-`: standard output) in `format`, whatever the extension of
/// `path`, as [`write_mesh`] does; a `format` that is not a mesh format writes binary glTF.
pub fn write_mesh_as(
    format: OutputFormat,
    path: &Path,
    mesh: &TriangleMesh,
    options: &MeshOptions,
) -> Result<(), IoError> {
    match format {
        OutputFormat::Obj => write_mesh_obj(path, mesh),
        OutputFormat::Stl => write_mesh_stl(path, mesh, options.ascii),
        OutputFormat::Ply => {
            let encoding = if options.ascii {
                PlyEncoding::Ascii
            } else {
                PlyEncoding::BinaryLittleEndian
            };
            write_mesh_ply(path, mesh, encoding)
        }
        OutputFormat::Vtk => write_mesh_vtk(path, mesh),
        OutputFormat::Vts => write_mesh_vts(path, mesh),
        _ => write_mesh_glb(path, mesh),
    }
}

/// Writes the sampled surface `grid` (row-major, `u` outer) as a mesh at `path` (see
/// [`write_mesh`]); a grid of `2^32` or more samples is an [`IoError::InvalidMesh`].
pub fn write_surface_mesh(
    path: &Path,
    grid: &Grid<Point3>,
    options: &MeshOptions,
) -> Result<(), IoError> {
    let format = OutputFormat::from_path(path, &OutputFormat::MESHES)?;
    write_surface_mesh_as(format, path, grid, options)
}

/// Writes the sampled surface `grid` as a mesh in `format` (see [`write_mesh_as`]).
pub fn write_surface_mesh_as(
    format: OutputFormat,
    path: &Path,
    grid: &Grid<Point3>,
    options: &MeshOptions,
) -> Result<(), IoError> {
    let mesh = TriangleMesh::from_grid(grid).map_err(IoError::invalid_mesh(path))?;
    write_mesh_as(format, path, &mesh, options)
}

/// Reads the triangle mesh of `path` by its extension: `.obj`, `.stl` or `.ply`. A mesh
/// without faces is an [`IoError::Data`].
pub fn read_mesh(path: &Path) -> Result<TriangleMesh, IoError> {
    let ext = path
        .extension()
        .and_then(|e| e.to_str())
        .map(str::to_ascii_lowercase);
    let mesh = match ext.as_deref() {
        Some("obj") => parse_obj_mesh(&read_text(path)?, path)?,
        Some("stl") => read_stl(path)?,
        Some("ply") => read_ply(path)?,
        _ => return Err(data_error(path, "not a mesh file (use .obj, .stl or .ply)")),
    };
    if mesh.triangles.is_empty() {
        return Err(data_error(path, "the mesh has no faces"));
    }
    Ok(mesh)
}
