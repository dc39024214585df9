//! Writing output files atomically, and the CSV writers of sampled curves and surfaces.
//!
//! Every output goes through [`write_atomic`]: the content is written to a temporary file in
//! the destination's directory and renamed over the destination only when complete, so a
//! failed or interrupted run never leaves a truncated file or destroys the previous one.
//!
//! CSV is written with the `csv` crate. Numbers use Rust's shortest round-trip formatting of
//! `f64` (`{}`), so a file read back gives bit-identical values.

use std::fmt::Write as _;
use std::io::{self, BufWriter, Write};
use std::path::Path;

use karkas::{Grid, Point, Point3};

use crate::error::IoError;

/// Writes `path` atomically with the bytes `fill` produces.
///
/// `fill` writes into a buffered temporary file created in the directory of `path` (the
/// current directory for a bare file name); on success the file is renamed over `path`. On any
/// error, from `fill` or from the file system, the destination is left untouched, the temporary
/// file is removed, and the error is an [`IoError::Write`] naming `path`. An existing
/// destination keeps its permissions; a new one gets the usual ones for a new file.
pub fn write_atomic(
    path: &Path,
    fill: impl FnOnce(&mut dyn Write) -> io::Result<()>,
) -> Result<(), IoError> {
    let error = |source| IoError::Write {
        path: path.to_path_buf(),
        source,
    };
    let dir = match path.parent() {
        Some(p) if !p.as_os_str().is_empty() => p,
        _ => Path::new("."),
    };
    let mut builder = tempfile::Builder::new();
    builder.prefix(".karkas-").suffix(".tmp");
    #[cfg(unix)]
    {
        use std::os::unix::fs::PermissionsExt;
        let mode = std::fs::metadata(path).map_or(0o666, |m| m.permissions().mode() & 0o7777);
        builder.permissions(std::fs::Permissions::from_mode(mode));
    }
    let mut temp = builder.tempfile_in(dir).map_err(error)?;
    {
        let mut out = BufWriter::new(temp.as_file_mut());
        fill(&mut out).map_err(error)?;
        out.flush().map_err(error)?;
    }
    temp.as_file().sync_all().map_err(error)?;
    temp.persist(path).map_err(|e| error(e.error))?;
    Ok(())
}

/// Writes curve samples as CSV: header `t,x,y` (`D = 2`) or `t,x,y,z` (`D = 3`), one row per
/// sample `(ts[k], points[k])`. Other dimensions name the coordinates `x1, x2, ...`.
///
/// `ts` and `points` must have the same length, else [`IoError::LengthMismatch`] (nothing is written).
pub fn write_curve_csv<const D: usize>(
    path: &Path,
    ts: &[f64],
    points: &[Point<D>],
) -> Result<(), IoError> {
    check_len(path, "parameters", ts.len(), points.len())?;
    let mut header = vec!["t".to_owned()];
    header.extend(coordinate_names(D));
    write_atomic(path, |out| {
        let mut csv = CsvRows::new(out, &header)?;
        for (&t, p) in ts.iter().zip(points) {
            csv.row(std::iter::once(t).chain(p.0))?;
        }
        csv.finish()
    })
}

/// Writes surface samples as CSV: header `u,v,x,y,z`, rows in row-major order of the sample
/// grid (`u` outer, `v` inner): `points[a * vs.len() + b]` is the point at `(us[a], vs[b])`.
///
/// `points.len()` must be `us.len() * vs.len()`, else [`IoError::LengthMismatch`] (nothing is written).
pub fn write_surface_csv(
    path: &Path,
    us: &[f64],
    vs: &[f64],
    points: &[Point3],
) -> Result<(), IoError> {
    let cells = us.len().saturating_mul(vs.len());
    check_len(path, "u x v parameters", cells, points.len())?;
    let header = ["u", "v", "x", "y", "z"].map(str::to_owned);
    write_atomic(path, |out| {
        let mut csv = CsvRows::new(out, &header)?;
        let parameters = us.iter().flat_map(|&u| vs.iter().map(move |&v| (u, v)));
        for ((u, v), p) in parameters.zip(points) {
            csv.row([u, v].into_iter().chain(p.0))?;
        }
        csv.finish()
    })
}

/// Writes the values of a discrete curve as CSV: header `j,x,y` (`D = 2`) or `j,x,y,z`
/// (`D = 3`), one row per value `points[j]`, `j` written as an integer from 0. Other dimensions
/// name the coordinates `x1, x2, ...`.
pub fn write_discrete_curve_csv<const D: usize>(
    path: &Path,
    points: &[Point<D>],
) -> Result<(), IoError> {
    let mut header = vec!["j".to_owned()];
    header.extend(coordinate_names(D));
    write_atomic(path, |out| {
        let mut csv = CsvRows::new(out, &header)?;
        for (j, p) in points.iter().enumerate() {
            csv.indexed_row(&[j], p.0)?;
        }
        csv.finish()
    })
}

/// Writes a grid of spatial points with their indices as CSV: header `A,B,x,y,z` with
/// `[A, B] = names` (e.g. `p,q` for the values of a tube, `i,q` for curves along it), one row
/// per point in row-major order, indices written as integers from 0.
pub fn write_indexed_grid_csv(
    path: &Path,
    names: [&str; 2],
    grid: &Grid<Point3>,
) -> Result<(), IoError> {
    let header: Vec<String> = names
        .iter()
        .map(|s| (*s).to_owned())
        .chain(coordinate_names(3))
        .collect();
    write_atomic(path, |out| {
        let mut csv = CsvRows::new(out, &header)?;
        for a in 0..grid.rows() {
            for (b, p) in grid.row(a).iter().enumerate() {
                csv.indexed_row(&[a, b], p.0)?;
            }
        }
        csv.finish()
    })
}

/// Writes a grid of points as CSV with header `i,j,x,y,z`, row-major (row index `i`, column
/// index `j`, from 0): the format [`read_grid`](crate::grid::read_grid) reads back bit for bit.
pub fn write_grid_csv(path: &Path, grid: &Grid<Point3>) -> Result<(), IoError> {
    write_indexed_grid_csv(path, ["i", "j"], grid)
}

/// Writes polylines (the pieces of sections) as CSV with header `section,t,x,y,z`: one block
/// of rows per polyline, numbered from 0 in the order given; `t` is the length along the
/// polyline from its first point. A closed polyline should repeat its first point at the end.
pub fn write_sections_csv(path: &Path, lines: &[Vec<Point3>]) -> Result<(), IoError> {
    let header = ["section", "t", "x", "y", "z"].map(str::to_owned);
    write_atomic(path, |out| {
        let mut csv = CsvRows::new(out, &header)?;
        for (k, line) in lines.iter().enumerate() {
            let mut t = 0.0;
            for (n, p) in line.iter().enumerate() {
                if n > 0 {
                    t += p.distance(line[n - 1]);
                }
                csv.row([k as f64, t].into_iter().chain(p.0))?;
            }
        }
        csv.finish()
    })
}

/// `x, y, z` for up to three dimensions, `x1, x2, ...` beyond.
fn coordinate_names(dim: usize) -> Vec<String> {
    if dim <= 3 {
        ["x", "y", "z"][..dim]
            .iter()
            .map(|s| (*s).to_owned())
            .collect()
    } else {
        (1..=dim).map(|k| format!("x{k}")).collect()
    }
}

/// [`IoError::LengthMismatch`] unless `parameters == points`.
fn check_len(
    path: &Path,
    what: &'static str,
    parameters: usize,
    points: usize,
) -> Result<(), IoError> {
    if parameters == points {
        return Ok(());
    }
    Err(IoError::LengthMismatch {
        path: path.to_path_buf(),
        what,
        parameters,
        points,
    })
}

/// A CSV writer of rows of numbers in shortest round-trip form.
struct CsvRows<'a> {
    writer: csv::Writer<&'a mut dyn Write>,
    number: String,
}

impl<'a> CsvRows<'a> {
    /// Starts the file with `header`.
    fn new(out: &'a mut dyn Write, header: &[String]) -> io::Result<Self> {
        let mut writer = csv::Writer::from_writer(out);
        writer.write_record(header)?;
        Ok(CsvRows {
            writer,
            number: String::new(),
        })
    }

    /// Writes one row.
    fn row(&mut self, values: impl IntoIterator<Item = f64>) -> io::Result<()> {
        for v in values {
            self.number.clear();
            // Writing into a String cannot fail.
            let _ = write!(self.number, "{v}");
            self.writer.write_field(&self.number)?;
        }
        self.writer.write_record(None::<&[u8]>)?;
        Ok(())
    }

    /// Writes one row that starts with integer indices.
    fn indexed_row(
        &mut self,
        indices: &[usize],
        values: impl IntoIterator<Item = f64>,
    ) -> io::Result<()> {
        for k in indices {
            self.number.clear();
            let _ = write!(self.number, "{k}");
            self.writer.write_field(&self.number)?;
        }
        self.row(values)
    }

    /// Flushes the rows into the output.
    fn finish(mut self) -> io::Result<()> {
        self.writer.flush()
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn names_of_coordinates() {
        assert_eq!(coordinate_names(2), ["x", "y"]);
        assert_eq!(coordinate_names(3), ["x", "y", "z"]);
        assert_eq!(coordinate_names(4), ["x1", "x2", "x3", "x4"]);
    }
}
