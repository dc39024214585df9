//! Writing a result in any output format, chosen by the output's extension: a curve, a
//! surface, a discrete periodic spline or tube, a grid of points, a point list or a triangle
//! mesh, sampled with the default counts and drawn with the defaults of the command line (the
//! curvature comb, the isoparametric lines, the default view), or the exact B-spline forms as
//! STEP or IGES (and curves as DXF).
//!
//! The command line and the Python package both write through this module, so that a file
//! written either way is the same byte for byte. Every file is written atomically
//! ([`write_atomic`](crate::write::write_atomic)): an error leaves an existing file as it was.
//! What the command line adds around it (its memory estimates, `--format`, `-` for standard
//! output, the lines that report what was written) stays in the command line.
//!
//! - [`formats`]: which formats each kind of result is written in.
//! - [`samples`]: the default sample counts and uniform sampling.
//! - [`curve`]: sampled curves (CSV, pictures with the curvature comb, the viewer page) and
//!   discrete periodic curves.
//! - [`stream`]: sampled curves and surfaces as CSV or `.npy`, written block by block as
//!   they are sampled.
//! - [`surface`]: sampled surfaces and grids (CSV, meshes, pictures, the viewer page).
//! - [`mesh`]: triangle meshes (mesh formats and the viewer page).
//! - [`cad`]: the exact B-spline forms as STEP or IGES, and curves with their input points
//!   as DXF.

pub mod cad;
pub mod curve;
pub mod formats;
pub mod mesh;
pub mod samples;
pub mod stream;
pub mod surface;
