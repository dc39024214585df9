//! Sampled curves and surfaces written as they are sampled: the `t,x,y[,z]` and `u,v,x,y,z`
//! CSV, and `.npy` arrays, in blocks of [`BLOCK`] samples.
//!
//! Each block is evaluated (the library's batch evaluation, itself parallel), formatted in
//! parallel chunks into byte buffers (`shortest.rs` for the numbers), and written in
//! order before the next block starts: memory stays a few megabytes whatever the number of
//! samples, and the file is the one [`write_curve_csv`](crate::write::write_curve_csv) and
//! [`write_surface_csv`](crate::write::write_surface_csv) write from samples held in memory,
//! byte for byte. The parameters are the ones [`Curve::sample_into`] and
//! [`Surface::sample_grid_into`] take (`Interval::uniform`), so the values are those of the
//! whole-array sampling too.
//!
//! `.npy` holds the points only: an `(n, D)` array for a curve, `(nu, nv, 3)` for a surface
//! (`u` outer), `f64` little-endian in C order ([`crate::npy`]).

use crate::write::write_atomic;
use crate::{npy, IoError, OutputFormat};
use karkas::{Curve, Point, Point3, Surface};
use rayon::prelude::*;
use std::io::{self, Write};
use std::path::Path;

/// Samples per block: evaluated, formatted and written before the next.
pub const BLOCK: usize = 1 << 16;

/// Rows per parallel formatting chunk of a block.
const CHUNK: usize = 4096;

/// True for the formats written here: CSV and `.npy`.
pub fn streams(format: OutputFormat) -> bool {
    matches!(format, OutputFormat::Csv | OutputFormat::Npy)
}

/// Writes `n` samples of `curve`, uniform over its domain, ends included, to `path` as the
/// `t,x,y[,z]` CSV or an `(n, D)` `.npy` array, by `format` (one of [`streams`]).
pub fn write_curve_samples<const D: usize>(
    curve: &(impl Curve<D> + Sync),
    n: usize,
    format: OutputFormat,
    path: &Path,
) -> Result<(), IoError> {
    let format = format.allowed_for(path, &[OutputFormat::Csv, OutputFormat::Npy])?;
    let domain = curve.domain();
    write_atomic(path, |out| {
        if format == OutputFormat::Npy {
            out.write_all(&npy::header(&[n, D]))?;
        } else {
            out.write_all(crate::write::curve_csv_header(D).as_bytes())?;
        }
        let (mut ts, mut points) = (Vec::new(), Vec::new());
        let (mut bytes, mut texts) = (Vec::new(), Vec::new());
        for first in (0..n).step_by(BLOCK) {
            let count = BLOCK.min(n - first);
            ts.clear();
            ts.extend((first..first + count).map(|k| domain.uniform(k, n)));
            points.clear();
            points.resize(count, Point::<D>::ZERO);
            curve.eval_into(&ts, &mut points);
            if format == OutputFormat::Npy {
                npy::write_points(out, &points, &mut bytes)?;
            } else {
                write_rows(out, &ts, &mut texts, |k, text| {
                    push_row(text, std::iter::once(ts[k]).chain(points[k].0));
                })?;
            }
        }
        Ok(())
    })
}

/// Writes `nu x nv` samples of `surface`, uniform over its domain, ends included, to `path`
/// as the `u,v,x,y,z` CSV (`u` outer) or an `(nu, nv, 3)` `.npy` array, by `format` (one of
/// [`streams`]).
pub fn write_surface_samples(
    surface: &(impl Surface<3> + Sync),
    (nu, nv): (usize, usize),
    format: OutputFormat,
    path: &Path,
) -> Result<(), IoError> {
    let format = format.allowed_for(path, &[OutputFormat::Csv, OutputFormat::Npy])?;
    let (domain_u, domain_v) = (surface.domain_u(), surface.domain_v());
    let vs: Vec<f64> = (0..nv).map(|k| domain_v.uniform(k, nv)).collect();
    let rows_per_block = (BLOCK / nv.max(1)).max(1);
    // Each `v` is written on every row of samples, each `u` on `nv` lines: formatted once.
    let v_texts = NumberTexts::of(&vs);
    write_atomic(path, |out| {
        if format == OutputFormat::Npy {
            out.write_all(&npy::header(&[nu, nv, 3]))?;
        } else {
            out.write_all(b"u,v,x,y,z\n")?;
        }
        if nv == 0 {
            return Ok(());
        }
        let (mut us, mut points) = (Vec::new(), Vec::new());
        let (mut bytes, mut texts) = (Vec::new(), Vec::new());
        for first in (0..nu).step_by(rows_per_block) {
            let rows = rows_per_block.min(nu - first);
            us.clear();
            us.extend((first..first + rows).map(|a| domain_u.uniform(a, nu)));
            points.clear();
            points.resize(rows * nv, Point3::ZERO);
            surface.eval_grid_into(&us, &vs, &mut points);
            if format == OutputFormat::Npy {
                npy::write_points(out, &points, &mut bytes)?;
            } else {
                let u_texts = NumberTexts::of(&us);
                write_rows(out, &points, &mut texts, |k, text| {
                    text.extend_from_slice(u_texts.get(k / nv));
                    text.push(b',');
                    text.extend_from_slice(v_texts.get(k % nv));
                    for v in points[k].0 {
                        text.push(b',');
                        crate::shortest::push(text, v);
                    }
                    text.push(b'\n');
                })?;
            }
        }
        Ok(())
    })
}

/// Formats the rows `0..items.len()` of a block with `row` (which appends row `k` to a
/// buffer) in parallel chunks, and writes the chunks to `out` in order.
///
/// The chunks' buffers are `texts`, kept from block to block: their pages are reused, not
/// fresh (and zeroed by the system) for every block.
fn write_rows<T: Sync>(
    out: &mut dyn Write,
    items: &[T],
    texts: &mut Vec<Vec<u8>>,
    row: impl Fn(usize, &mut Vec<u8>) + Sync,
) -> io::Result<()> {
    let chunks = items.len().div_ceil(CHUNK);
    if texts.len() < chunks {
        texts.resize_with(chunks, Vec::new);
    }
    texts[..chunks]
        .par_iter_mut()
        .enumerate()
        .for_each(|(chunk, text)| {
            let first = chunk * CHUNK;
            let end = (first + CHUNK).min(items.len());
            text.clear();
            text.reserve((end - first) * 96);
            for k in first..end {
                row(k, text);
            }
        });
    texts[..chunks]
        .iter()
        .try_for_each(|text| out.write_all(text))
}

/// Numbers formatted once ([`crate::shortest`]) and written many times.
struct NumberTexts {
    bytes: Vec<u8>,
    /// Where each number's text ends in `bytes`.
    ends: Vec<usize>,
}

impl NumberTexts {
    fn of(values: &[f64]) -> Self {
        let mut bytes = Vec::with_capacity(values.len() * 24);
        let ends = values
            .iter()
            .map(|&v| {
                crate::shortest::push(&mut bytes, v);
                bytes.len()
            })
            .collect();
        NumberTexts { bytes, ends }
    }

    /// The text of number `k`.
    fn get(&self, k: usize) -> &[u8] {
        let start = if k == 0 { 0 } else { self.ends[k - 1] };
        &self.bytes[start..self.ends[k]]
    }
}

/// Appends one CSV row of `values` (comma-separated, `\n`-ended) to `text`.
fn push_row(text: &mut Vec<u8>, values: impl IntoIterator<Item = f64>) {
    for (k, v) in values.into_iter().enumerate() {
        if k > 0 {
            text.push(b',');
        }
        crate::shortest::push(text, v);
    }
    text.push(b'\n');
}
