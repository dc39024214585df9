//! The ways results leave the program: files in every format or standard output (sampled curves and surfaces,
//! the exact B-spline forms as STEP or IGES), the caps on what one request may write, the
//! lines that report what was written, and the one-line error message.

pub mod cad;
pub mod console;
pub mod curve;
pub mod formats;
pub mod memory;
pub mod message;
pub mod overwrite;
pub mod samples;
pub mod self_crossing;
pub mod surface;
pub mod target;
