//! One entry for every mesh format: [`write_mesh`] and [`read_mesh`] choose the format by the
//! extension of the file name.
//!
//! Written: `.obj`, `.stl`, `.ply`, `.vtk`, `.vts`, `.glb` (STL and PLY binary unless
//! [`MeshOptions::ascii`]; turned over with [`MeshOptions::flip_normals`]). Read: `.obj`,
//! `.stl` (binary or ASCII), `.ply` (any encoding); standard input (`-`, which has no
//! extension) by its content ([`sniff_mesh_format`]). Every input is opened once.

use std::borrow::Cow;
use std::io::{Cursor, Read};
use std::path::Path;

use karkas::{Grid, Point3};

use crate::error::{data_error, IoError};
use crate::format::OutputFormat;
use crate::input::{is_stdin, Input};
use crate::mesh::closed::closed_grid_mesh;
use crate::mesh::glb::write_mesh_glb;
use crate::mesh::obj::{read_obj_mesh, write_mesh_obj};
use crate::mesh::ply::{read_ply_from, write_mesh_ply, PlyEncoding};
use crate::mesh::stl::{read_stl_from, write_mesh_stl};
use crate::mesh::triangle_mesh::TriangleMesh;
use crate::mesh::vtk::{write_mesh_vtk, write_mesh_vts};

/// How [`write_mesh`] writes a mesh.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct MeshOptions {
    /// Write STL and PLY as text instead of binary (the other formats have one encoding).
    pub ascii: bool,
    /// Turn the mesh over: reverse the triangles' winding and the normals
    /// ([`TriangleMesh::flip_orientation`]).
    pub flip_normals: bool,
}

/// The mesh formats read.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum MeshFormat {
    /// Wavefront OBJ.
    Obj,
    /// STL, binary or ASCII.
    Stl,
    /// Stanford PLY, any encoding.
    Ply,
}

/// Writes `mesh` at `path`, atomically, in the format named by the extension of `path` (one of
/// [`OutputFormat::MESHES`]). Another extension is an [`IoError::UnknownExtension`]; a mesh
/// failing [`TriangleMesh::validate`] (or, for `.vts`, without a grid shape) an
/// [`IoError::InvalidMesh`]; nothing is written then. With [`MeshOptions::flip_normals`] a
/// turned-over copy of the mesh is written.
pub fn write_mesh(path: &Path, mesh: &TriangleMesh, options: &MeshOptions) -> Result<(), IoError> {
    let format = OutputFormat::from_path(path, &OutputFormat::MESHES)?;
    write_mesh_as(format, path, mesh, options)
}

/// Writes `mesh` at `path` (`-`: standard output) in `format`, whatever the extension of
/// `path`, as [`write_mesh`] does (turned over with [`MeshOptions::flip_normals`]); a `format`
/// that is not a mesh format writes binary glTF.
pub fn write_mesh_as(
    format: OutputFormat,
    path: &Path,
    mesh: &TriangleMesh,
    options: &MeshOptions,
) -> Result<(), IoError> {
    let mesh = if options.flip_normals {
        let mut flipped = mesh.clone();
        flipped.flip_orientation();
        Cow::Owned(flipped)
    } else {
        Cow::Borrowed(mesh)
    };
    let mesh = mesh.as_ref();
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
/// [`write_mesh`]; the seam of a closed grid is welded in OBJ, PLY and glTF); a grid of
/// `2^32` or more samples is an [`IoError::InvalidMesh`].
pub fn write_surface_mesh(
    path: &Path,
    grid: &Grid<Point3>,
    options: &MeshOptions,
) -> Result<(), IoError> {
    let format = OutputFormat::from_path(path, &OutputFormat::MESHES)?;
    write_surface_mesh_as(format, path, grid, options)
}

/// Writes the sampled surface `grid` as a mesh in `format` (see [`write_mesh_as`]; the seam of
/// a closed grid is welded in OBJ, PLY and glTF, its poles closed by fans in every format but
/// the VTK grids, and a closed mesh turned so that its normals point outwards: see
/// [`closed_grid_mesh`]).
pub fn write_surface_mesh_as(
    format: OutputFormat,
    path: &Path,
    grid: &Grid<Point3>,
    options: &MeshOptions,
) -> Result<(), IoError> {
    let mesh = TriangleMesh::from_grid(grid).map_err(IoError::invalid_mesh(path))?;
    let mut mesh = if matches!(format, OutputFormat::Vtk | OutputFormat::Vts) {
        // Structured grids: the samples as they are.
        mesh
    } else {
        closed_grid_mesh(mesh).0
    };
    if options.flip_normals {
        mesh.flip_orientation();
    }
    let options = MeshOptions {
        flip_normals: false,
        ..*options
    };
    write_mesh_as(format, path, &mesh, &options)
}

/// Reads the triangle mesh of `path` by its extension: `.obj`, `.stl` or `.ply`; `-` reads
/// standard input, its format told by its content ([`sniff_mesh_format`]). A mesh without
/// faces is an [`IoError::Data`].
pub fn read_mesh(path: &Path) -> Result<TriangleMesh, IoError> {
    let ext = path
        .extension()
        .and_then(|e| e.to_str())
        .map(str::to_ascii_lowercase);
    let format = match ext.as_deref() {
        Some("obj") => Some(MeshFormat::Obj),
        Some("stl") => Some(MeshFormat::Stl),
        Some("ply") => Some(MeshFormat::Ply),
        _ if is_stdin(path) => None,
        _ => return Err(data_error(path, "not a mesh file (use .obj, .stl or .ply)")),
    };
    read_mesh_from(Input::open(path)?, format)
}

/// Reads the triangle mesh of `input` in `format`, or (`None`) in the format its first bytes
/// tell ([`sniff_mesh_format`]). A mesh without faces is an [`IoError::Data`].
pub fn read_mesh_from(
    mut input: Input,
    format: Option<MeshFormat>,
) -> Result<TriangleMesh, IoError> {
    let (format, mut input) = match format {
        Some(format) => (format, input),
        None => {
            let prefix = read_prefix(&mut input)?;
            let format = sniff_mesh_format(&prefix);
            let name = input.name.clone();
            let rejoined = Cursor::new(prefix).chain(input);
            (format, Input::from_reader(name, rejoined))
        }
    };
    let mesh = match format {
        MeshFormat::Obj => read_obj_mesh(&mut input)?,
        MeshFormat::Stl => read_stl_from(&mut input)?,
        MeshFormat::Ply => read_ply_from(&mut input)?,
    };
    if mesh.triangles.is_empty() {
        return Err(data_error(&input.name, "the mesh has no faces"));
    }
    Ok(mesh)
}

/// The bytes [`sniff_mesh_format`] looks at.
pub const SNIFF_BYTES: usize = 512;

/// The first [`SNIFF_BYTES`] bytes of `input` (fewer when it is shorter).
fn read_prefix(input: &mut Input) -> Result<Vec<u8>, IoError> {
    let mut prefix = Vec::with_capacity(SNIFF_BYTES);
    let name = input.name.clone();
    input
        .by_ref()
        .take(SNIFF_BYTES as u64)
        .read_to_end(&mut prefix)
        .map_err(IoError::open(&name))?;
    Ok(prefix)
}

/// The mesh format the first bytes `prefix` of an input show (at least [`SNIFF_BYTES`]
/// of them unless the input is shorter):
/// - a first line `ply`: PLY;
/// - a first line starting with `solid` (after blanks), or binary data (a NUL byte, or bytes
///   that are not UTF-8 text, in the prefix): STL, ASCII or binary as its size tells;
/// - anything else (text): OBJ.
pub fn sniff_mesh_format(prefix: &[u8]) -> MeshFormat {
    let text = prefix.strip_prefix(b"\xef\xbb\xbf").unwrap_or(prefix);
    let first_line = text.split(|&b| b == b'\n').next().unwrap_or(&[]);
    if first_line.trim_ascii() == b"ply" {
        return MeshFormat::Ply;
    }
    let start = text.trim_ascii_start();
    if start.len() >= 5 && start[..5].eq_ignore_ascii_case(b"solid") {
        return MeshFormat::Stl;
    }
    let binary = text.contains(&0)
        || match std::str::from_utf8(text) {
            Ok(_) => false,
            // A character cut at the end of the prefix is still text.
            Err(e) => e.error_len().is_some(),
        };
    if binary {
        MeshFormat::Stl
    } else {
        MeshFormat::Obj
    }
}

/// True when the first bytes `prefix` of an input of unknown kind are a mesh rather than
/// point or grid text: PLY or STL by [`sniff_mesh_format`] (binary data included), or text
/// whose first content line is an OBJ statement (`v`, `vn`, `vt`, `f`, `o`, `g`, `s`,
/// `mtllib`, `usemtl`). Only the first [`SNIFF_BYTES`] are looked at.
pub fn is_mesh_prefix(prefix: &[u8]) -> bool {
    let prefix = &prefix[..prefix.len().min(SNIFF_BYTES)];
    if sniff_mesh_format(prefix) != MeshFormat::Obj {
        return true;
    }
    let text = String::from_utf8_lossy(prefix);
    text.lines()
        .map(|l| l.split('#').next().unwrap_or("").trim())
        .find(|l| !l.is_empty())
        .and_then(|l| l.split_whitespace().next())
        .is_some_and(|k| ["v", "vn", "vt", "f", "o", "g", "s", "mtllib", "usemtl"].contains(&k))
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn mesh_prefixes_are_told_from_points_and_grids() {
        assert!(is_mesh_prefix(b"ply\nformat ascii 1.0\n"));
        assert!(is_mesh_prefix(b"solid part\n"));
        assert!(is_mesh_prefix(b"\x00\x01binary"));
        assert!(is_mesh_prefix(b"# Blender\nmtllib a.mtl\nv 0 0 0\n"));
        assert!(!is_mesh_prefix(b"x,y\n0,0\n1,1\n"));
        assert!(!is_mesh_prefix(b"i,j,x,y,z\n0,0,0,0,0\n"));
        assert!(!is_mesh_prefix(b"NACA 0012\n1 0\n"));
    }

    #[test]
    fn content_tells_the_format() {
        assert_eq!(
            sniff_mesh_format(b"ply\r\nformat ascii 1.0\n"),
            MeshFormat::Ply
        );
        assert_eq!(sniff_mesh_format(b"solid\n"), MeshFormat::Stl);
        assert_eq!(sniff_mesh_format(b"  SOLID\tpart\r\n"), MeshFormat::Stl);
        let mut binary = vec![b'x'; 80];
        binary.extend_from_slice(&1u32.to_le_bytes());
        binary.extend_from_slice(&[0; 50]);
        assert_eq!(sniff_mesh_format(&binary), MeshFormat::Stl);
        assert_eq!(sniff_mesh_format(b"# exported\nv 0 0 0\n"), MeshFormat::Obj);
        assert_eq!(sniff_mesh_format("v 0 0 0 # é".as_bytes()), MeshFormat::Obj);
        assert_eq!(sniff_mesh_format(b"v 0 0 0\n\xc3"), MeshFormat::Obj);
        assert_eq!(sniff_mesh_format(b"\xff\xfe\x01"), MeshFormat::Stl);
    }

    #[test]
    fn standard_input_is_read_after_sniffing() {
        let text = b"v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n";
        let input = Input::from_reader("<stdin>", &text[..]);
        let mesh = read_mesh_from(input, None).unwrap();
        assert_eq!(mesh.triangles, vec![[0, 1, 2]]);
    }
}
