//! # karkas-io
//!
//! Files in and out of [`karkas`]: the library itself does no I/O, this crate reads the point
//! frames a user hands over and writes the sampled results.
//!
//! Reading:
//! - [`points`]: an ordered list of curve points from CSV, whitespace-separated columns or an
//!   airfoil `.dat` ([`airfoil`]), chosen by content;
//! - [`grid`]: a surface frame as CSV rows `i,j,x,y,z`;
//! - [`skeleton`]: the skeleton curves of a tube as CSV rows `i,q,x,y,z` (along) and
//!   `j,p,x,y,z` (across);
//! - [`pointset`]: a point set in space from OBJ vertices or CSV columns `x,y,z`;
//! - [`mask`]: a set of grid cells as CSV rows `i,j` (e.g. the entries a variation keeps).
//! - [`network`]: a family of curves of a curve network as CSV rows `curve,x,y,z`.
//!
//! Writing (always atomically, see [`write::write_atomic`]):
//! - [`write`](mod@write): sampled curves and surfaces, discrete curves, grids, indexed grids
//!   and sections as CSV;
//! - [`svg`]: pictures of a planar curve over its input points, of a discrete curve, and of
//!   wireframes;
//! - [`scene`]: a shaded surface in space with curves on it, hidden parts removed;
//! - [`png`]: any of these pictures rendered to PNG (with a compiled-in font);
//! - [`obj`]: a sampled surface as a Wavefront OBJ triangle mesh;
//! - [`stl`]: a sampled surface or a triangle mesh as binary or ASCII STL;
//! - [`mesh`]: the triangle mesh every mesh writer takes, and [`mesh_io::write_mesh`] choosing
//!   the writer by format: [`ply`] (PLY), [`vtk`] (legacy VTK and XML structured grids),
//!   [`glb`] (binary glTF); [`mesh_io`] also reads OBJ, STL and PLY meshes back;
//! - [`viewer`]: a self-contained HTML page showing surfaces and curves in 3-D.
//! - [`step`] and [`iges`]: exact B-spline curves and surfaces ([`cad::CadEntity`], from
//!   [`karkas::bspline`]) as STEP AP214 and IGES 5.3 (entities 126, 128) files;
//!
//! Every error is an [`IoError`] naming the file and, where there is one, the 1-based line or
//! the grid cell. No input, however malformed, makes these functions panic.

pub mod airfoil;
pub mod cad;
pub mod error;
pub mod format;
pub mod glb;
pub mod grid;
pub mod iges;
pub mod mask;
pub mod mesh;
pub mod mesh_io;
pub mod network;
pub mod obj;
pub mod ply;
pub mod png;
pub mod points;
pub mod pointset;
pub mod scene;
pub mod skeleton;
pub mod step;
pub mod stl;
pub mod svg;
pub mod viewer;
pub mod vtk;
pub mod write;

mod lines;

pub use error::{IoError, Location};
pub use format::OutputFormat;

/// The [`IoError::Write`] for a mesh that fails [`mesh::TriangleMesh::validate`].
fn mesh_check(path: &std::path::Path, mesh: &mesh::TriangleMesh) -> Result<(), IoError> {
    mesh.validate().map_err(|message| IoError::Write {
        path: path.to_path_buf(),
        source: std::io::Error::new(std::io::ErrorKind::InvalidInput, message),
    })
}
