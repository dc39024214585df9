//! # karkas-io
//!
//! Files in and out of [`karkas`]: the library itself does no I/O, this crate reads the point
//! frames a user hands over and writes the sampled results.
//!
//! Reading:
//! - [`points`]: an ordered list of curve points from CSV, whitespace-separated columns or an
//!   airfoil `.dat` ([`airfoil`]), chosen by content;
//! - [`grid`]: a surface frame as CSV rows `i,j,x,y,z`;
//! - [`network`]: a family of curves of a curve network as CSV rows `curve,x,y,z`.
//!
//! Writing (always atomically, see [`write::write_atomic`]):
//! - [`write`](mod@write): sampled curves and surfaces as CSV;
//! - [`svg`]: a picture of a planar curve over its input points;
//! - [`obj`]: a sampled surface as a Wavefront OBJ triangle mesh.
//!
//! Every error is an [`IoError`] naming the file and, where there is one, the 1-based line or
//! the grid cell. No input, however malformed, makes these functions panic.

pub mod airfoil;
pub mod error;
pub mod format;
pub mod grid;
pub mod network;
pub mod obj;
pub mod points;
pub mod svg;
pub mod write;

mod lines;

pub use error::{IoError, Location};
pub use format::OutputFormat;
