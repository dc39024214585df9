//! # karkas-io
//!
//! Files in and out of [`karkas`]: the library itself does no I/O, this crate reads the point
//! frames a user hands over and writes the sampled results.
//!
//! Reading (every input opened once, `-` for standard input, bounded as [`input`] says):
//! - [`points`]: an ordered list of curve points from CSV, whitespace-separated columns or an
//!   airfoil `.dat` ([`airfoil`]), chosen by content;
//! - [`grid`]: a surface frame as CSV rows `i,j,x,y,z`;
//! - [`skeleton`]: the skeleton curves of a tube as CSV rows `i,q,x,y,z` (along) and
//!   `j,p,x,y,z` (across);
//! - [`pointset`]: a point set in space from OBJ vertices or CSV columns `x,y,z`;
//! - [`samples`]: a sampled surface as CSV rows `u,v,x,y,z`, back into its grid;
//! - [`mask`]: a set of grid cells as CSV rows `i,j` (e.g. the entries a variation keeps).
//! - [`sections_table`]: a loft's sections as CSV rows `file,x,y,z,chord,twist,dihedral`.
//! - [`network`]: a family of curves of a curve network as CSV rows `curve,x,y,z`.
//!
//! Writing (always atomically, see [`write::write_atomic`]):
//! - [`write`](mod@write): sampled curves and surfaces, discrete curves, grids, indexed grids
//!   and sections as CSV;
//! - [`picture`]: [`svg`] pictures of a planar curve over its input points, of a
//!   discrete curve, and of wireframes; a shaded surface in space with curves on it
//!   ([`scene`]); any of these rendered to PNG ([`png`]);
//! - [`mesh`]: the triangle mesh every mesh format takes and one file per format, each
//!   writing and reading it: [`obj`], [`stl`], [`ply`],
//!   [`vtk`] (legacy VTK and XML structured grids), [`glb`] (binary
//!   glTF); [`mesh::write_mesh`] and [`mesh::read_mesh`] choose the format by extension;
//! - [`npy`]: NumPy `.npy` arrays of `f64` (the header; values written as sampled by
//!   [`export::stream`]);
//! - [`viewer`]: a self-contained HTML page showing surfaces and curves in 3-D.
//! - [`cad`]: exact B-spline curves and surfaces ([`cad::CadEntity`], from
//!   [`karkas::bspline`]) as STEP AP214 and IGES 5.3 (entities 126, 128) files;
//!
//! Every error is an [`IoError`] naming the file and, where there is one, the 1-based line or
//! the grid cell; an error of the geometry library or of a mesh check is carried as its
//! source. No input, however malformed, makes these functions panic.
//!
//! The formats used to sit at the top level; those paths (`karkas_io::obj`, `karkas_io::svg`,
//! `karkas_io::step`, ...) are kept as re-exports of the modules in [`mesh`], [`picture`] and
//! [`cad`].

pub mod airfoil;
pub mod cad;
pub mod dialect;
pub mod error;
pub mod export;
pub mod format;
pub mod grid;
pub mod input;
pub mod mask;
pub mod mesh;
pub mod network;
pub mod npy;
pub mod offsets_table;
pub mod picture;
pub mod points;
pub mod pointset;
pub mod range;
pub mod samples;
pub mod sections_table;
pub mod shortest;
pub mod skeleton;
pub mod viewer;
pub mod windio;
pub mod write;

mod columns;
mod lines;
mod order_check;
mod plain_decimal;
mod store;
mod writeback;

pub use cad::{iges, step};
pub use error::{GeometryError, IoError, Location};
pub use format::OutputFormat;
pub use mesh::{glb, obj, ply, stl, vtk};
pub use picture::{curvature_plot, png, scene, svg};
