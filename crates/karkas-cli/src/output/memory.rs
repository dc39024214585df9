//! The memory a request's output will take, against the cap of `--max-memory` /
//! `KARKAS_MAX_MEMORY`: checked before any work, so that a mistyped count fails at once.
//!
//! The cap covers the whole request: what the readers keep (they check it as they read), the
//! samples, and what each output format builds on the way out (a picture's text, the
//! renderer's tree and pixels, a page's arrays and text, a mesh's triangles), estimated here
//! and by the picture and page writers of `karkas-io` before they start.

use anyhow::{bail, Context, Result};
use karkas_io::picture::budget::{self, human_bytes};
use karkas_io::viewer::{PAGE_POINT, PAGE_SURFACE_SAMPLE};
use karkas_io::OutputFormat;
use std::sync::atomic::{AtomicU64, Ordering};

/// The default memory cap for one request's output buffers: 2 GiB.
pub const DEFAULT_MAX_MEMORY: u64 = 2 << 30;

/// The cap in force, set from the command line or the environment (0: not set, the default).
static MAX_MEMORY: AtomicU64 = AtomicU64::new(0);

/// Sets the cap: `--max-memory` if given, else `KARKAS_MAX_MEMORY`, else the default.
pub fn set_max_memory(option: Option<u64>) -> Result<()> {
    let cap = match option {
        Some(bytes) => bytes,
        None => match std::env::var("KARKAS_MAX_MEMORY") {
            Ok(text) => parse_size(&text)
                .map_err(anyhow::Error::msg)
                .context("KARKAS_MAX_MEMORY")?,
            Err(_) => DEFAULT_MAX_MEMORY,
        },
    };
    // The readers keep what they read within the same cap.
    set_output_cap(cap);
    karkas_io::input::set_max_input_bytes(cap);
    Ok(())
}

/// Sets the cap on one request's output buffers alone (the readers' cap unchanged): the
/// Python package's `karkas.batch` passes `karkas.max_memory` (no cap: `u64::MAX`).
pub fn set_output_cap(bytes: u64) {
    MAX_MEMORY.store(bytes.max(1), Ordering::Relaxed);
}

pub use karkas_io::picture::budget::parse_size;

/// The cap in force, in bytes.
pub fn memory_cap() -> u64 {
    match MAX_MEMORY.load(Ordering::Relaxed) {
        0 => DEFAULT_MAX_MEMORY,
        cap => cap,
    }
}

/// The most samples of a surface a mesh in `format` may have within the cap (and
/// [`karkas_io::export::samples::MAX_SAMPLES`]).
pub fn mesh_sample_budget(format: OutputFormat) -> usize {
    let per_sample = surface_output_bytes(format, 1, 1).max(1);
    let fit = u128::from(memory_cap()) / per_sample;
    usize::try_from(fit)
        .unwrap_or(usize::MAX)
        .min(karkas_io::export::samples::MAX_SAMPLES)
}

/// Fails early when `request` (e.g. "curve ll: 50000000 samples") needs `bytes` of output
/// buffers, more than the cap.
pub fn check_memory(request: &str, bytes: u128) -> Result<()> {
    let cap = memory_cap();
    if bytes > u128::from(cap) {
        bail!(
            "{request} would need {} of memory, above the cap of {} (raise it with --max-memory \
             or KARKAS_MAX_MEMORY, or ask for fewer samples)",
            human_bytes(bytes),
            human_bytes(u128::from(cap))
        );
    }
    Ok(())
}

/// Bytes per sample of a surface written as a mesh (besides the sample itself): the triangle
/// mesh of the grid (position, normal, two triangles) and the writer's arrays (measured on
/// the release build for STL, PLY, VTK and glTF, rounded up).
const MESH_PER_SAMPLE: u128 = 130;
/// Bytes per vertex and per triangle of a mesh held and written in a mesh format.
const MESH_PER_VERTEX: u128 = 96;
const MESH_PER_TRIANGLE: u128 = 72;

/// What writing `rows x cols` surface samples (held as 24-byte points) in `format` takes,
/// the samples included: a picture and the page as their writers estimate them, a mesh its
/// triangles and arrays, CSV and OBJ (streamed) only the samples.
pub fn surface_output_bytes(format: OutputFormat, rows: usize, cols: usize) -> u128 {
    let samples = rows as u128 * cols as u128;
    // The isoparametric lines drawn over pictures and pages.
    let isolines = 11 * (rows + cols);
    match format {
        OutputFormat::Svg | OutputFormat::Png => {
            budget::scene_bytes(rows, cols, isolines, format == OutputFormat::Png)
        }
        OutputFormat::Html => samples * (24 + PAGE_SURFACE_SAMPLE) + isolines as u128 * PAGE_POINT,
        OutputFormat::Csv | OutputFormat::Obj | OutputFormat::Npy => samples * 24,
        _ => samples * (24 + MESH_PER_SAMPLE),
    }
}

/// What holding and writing a triangle mesh of `vertices` and `triangles` in a mesh format
/// takes.
pub fn mesh_output_bytes(vertices: usize, triangles: usize) -> u128 {
    vertices as u128 * MESH_PER_VERTEX + triangles as u128 * MESH_PER_TRIANGLE
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn sizes_parse_with_binary_units() {
        assert_eq!(parse_size("1500"), Ok(1500));
        assert_eq!(parse_size("512M"), Ok(512 << 20));
        assert_eq!(parse_size("2G"), Ok(2 << 30));
        assert_eq!(parse_size("2GiB"), Ok(2 << 30));
        assert_eq!(parse_size("1kb"), Ok(1024));
        assert!(parse_size("0").is_err());
        assert!(parse_size("12X").is_err());
        assert!(parse_size("lots").is_err());
        assert!(parse_size("99999999999T").is_err());
        assert_eq!(human_bytes(3 << 29), "1.5 GiB");
        assert_eq!(human_bytes(10), "10 B");
    }
}
