//! Reads a curve point file (`-`: standard input) as the Python package does, one flat array
//! of coordinates, and prints the count, the dimension and the time the read took: the Rust
//! side of the point-reading benchmark.
//!
//! `cargo run --release -p karkas-io --example read_points -- points.csv`

use std::path::PathBuf;
use std::time::Instant;

fn main() {
    let Some(path) = std::env::args_os().nth(1).map(PathBuf::from) else {
        eprintln!("usage: read_points FILE");
        std::process::exit(2);
    };
    let start = Instant::now();
    match karkas_io::points::read_curve_coordinates(&path) {
        Ok((coordinates, dim)) => println!(
            "{} points of dimension {dim} in {:.3} s",
            coordinates.len() / dim,
            start.elapsed().as_secs_f64()
        ),
        Err(e) => {
            eprintln!("error: {e}");
            std::process::exit(2);
        }
    }
}
