//! Triangle meshes: the mesh type, its normals and the triangulation of a sample grid (once,
//! for every format), one file per format that both writes and reads it, and one entry
//! choosing the format by the file's extension.
//!
//! - [`TriangleMesh`]: the mesh every writer takes, from a sampled surface grid
//!   ([`TriangleMesh::from_grid`]) or read from a file; [`MeshError`] says what is wrong with
//!   one.
//! - [`write_mesh`] / [`read_mesh`] ([`MeshOptions`]): any format by extension, standard
//!   input by content ([`sniff_mesh_format`]).
//! - [`closed`]: bodies: poles closed by fans, seams welded, planar caps, outward normals
//!   and the enclosed volume ([`body_mesh`]).
//! - [`shape_mesh`]: the faces of a CAD shape (a STEP or IGES model) to a chordal tolerance.
//! - [`obj`] (Wavefront OBJ), [`stl`] (binary and ASCII STL), [`ply`] (Stanford PLY),
//!   [`vtk`] (legacy VTK and XML structured grids `.vts`), [`glb`] (binary glTF 2.0).

mod any_format;
pub mod closed;
pub(crate) mod error;
mod face_loops;
mod face_orientation;
pub mod glb;
pub(crate) mod normals;
pub mod obj;
pub mod ply;
mod ply_read;
mod shape_mesh;
mod shape_seams;
pub(crate) mod shared_vertices;
pub mod stl;
mod stl_read;
pub(crate) mod triangle_mesh;
pub(crate) mod triangulate;
pub mod vtk;

pub use any_format::{
    is_mesh_prefix, read_mesh, read_mesh_from, sniff_mesh_format, write_mesh, write_mesh_as,
    write_surface_mesh, write_surface_mesh_as, MeshFormat, MeshOptions, SNIFF_BYTES,
};
pub use closed::{body_mesh, closed_grid_mesh, BodyMeshError, MeshBody, MeshCap};
pub use error::MeshError;
pub use shape_mesh::{shape_mesh, ShapeMeshError};
pub use triangle_mesh::TriangleMesh;
