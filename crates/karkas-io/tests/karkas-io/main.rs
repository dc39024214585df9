//! The integration tests of karkas-io, one binary: one module per reader or writer, shared
//! helpers in [`util`].

mod cad_hostile;
mod errors;
mod grid;
mod indexed_csv;
mod mesh;
mod mesh_files;
mod network;
mod obj;
mod points;
mod reading;
mod robustness;
mod skeleton;
mod stl;
mod stream;
mod svg;
mod util;
mod write;
