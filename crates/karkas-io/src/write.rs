//! Writing output files atomically (or to standard output), and the CSV writers of sampled
//! curves and surfaces.
//!
//! Every output goes through [`write_atomic`]: the content is written to a temporary file in
//! the destination's directory and renamed over the destination only when complete, so a
//! failed or interrupted run never leaves a truncated file or destroys the previous one. The
//! path `-` means standard output, written as the content is produced. The temporary file is
//! synced to disk before the rename; a large one is synced in the background while it is
//! written (the private `writeback` module), so that last sync waits for its tail only.
//!
//! The temporary file is named after the destination and the writing process,
//! `.NAME.karkas-tmp-PID-N`: a file left by a killed run is obviously stale, and the next write
//! to the same destination removes those whose process is gone (on systems with `/proc`). The
//! name is hand-made rather than `tempfile`'s random one for this reason, and so that no
//! message ever names it: errors name only the destination.
//!
//! CSV is written with the `csv` crate. Numbers use Rust's shortest round-trip formatting of
//! `f64` (`{}`, written fast by `shortest.rs`), so a file read back gives bit-identical
//! values.

use std::fs::{File, OpenOptions};
use std::io::{self, BufWriter, Write};
use std::path::{Path, PathBuf};
use std::sync::atomic::{AtomicUsize, Ordering};

use karkas::{Grid, Point, Point3};

use crate::error::IoError;
use crate::writeback::Writeback;

/// The output path that means standard output.
pub const STDOUT: &str = "-";

/// How standard output is named in messages.
pub const STDOUT_NAME: &str = "<stdout>";

/// What marks a temporary file of [`write_atomic`], between the destination's name and the
/// writer's process id.
const TEMP_MARK: &str = ".karkas-tmp-";

/// The longest part of a destination's name kept in its temporary file's name (file names
/// are limited to 255 bytes on most file systems).
const TEMP_NAME_BYTES: usize = 200;

/// True when the output `path` means standard output (`-`).
pub fn is_stdout(path: &Path) -> bool {
    path.as_os_str() == STDOUT
}

/// The name of the output `path` in messages: the path itself, or [`STDOUT_NAME`] for `-`.
pub fn output_name(path: &Path) -> PathBuf {
    if is_stdout(path) {
        PathBuf::from(STDOUT_NAME)
    } else {
        path.to_path_buf()
    }
}

/// Writes `path` atomically with the bytes `fill` produces; `-` writes to standard output.
///
/// `fill` writes into a buffered temporary file created in the directory of `path` (the
/// current directory for a bare file name); on success the file is renamed over `path`. On any
/// error, from `fill` or from the file system, the destination is left untouched, the temporary
/// file is removed, and the error is an [`IoError::Write`] naming `path` (never the temporary
/// file). An existing destination keeps its permissions; a new one gets the usual ones for a
/// new file. Temporary files of earlier runs that were killed while writing `path` are removed
/// first.
///
/// To standard output the bytes go out as they are produced (a pipe cannot be replaced
/// atomically); a reader that closes the pipe early makes the error's source
/// [`io::ErrorKind::BrokenPipe`].
pub fn write_atomic(
    path: &Path,
    fill: impl FnOnce(&mut dyn Write) -> io::Result<()>,
) -> Result<(), IoError> {
    if is_stdout(path) {
        return write_stdout(fill);
    }
    let error = |source: io::Error| IoError::Write {
        path: path.to_path_buf(),
        source: without_paths(source),
    };
    let dir = match path.parent() {
        Some(p) if !p.as_os_str().is_empty() => p,
        _ => Path::new("."),
    };
    let stem = temp_stem(path);
    remove_stale(dir, &stem);
    let (file, temp) = create_temp(dir, &stem, path).map_err(error)?;
    let guard = TempGuard(Some(temp));
    let mut out = BufWriter::with_capacity(1 << 16, Writeback::new(file));
    fill(&mut out).map_err(error)?;
    let file = out.into_inner().map_err(|e| error(e.into_error()))?;
    drop(file.finish().map_err(error)?);
    let temp = guard.0.as_deref().unwrap_or(path);
    std::fs::rename(temp, path).map_err(error)?;
    guard.persisted();
    Ok(())
}

/// Writes what `fill` produces to standard output. A reader that went away makes the error's
/// source a plain [`io::ErrorKind::BrokenPipe`], however `fill` wrapped it.
fn write_stdout(fill: impl FnOnce(&mut dyn Write) -> io::Result<()>) -> Result<(), IoError> {
    let stdout = io::stdout();
    let mut out = PipeSink {
        inner: BufWriter::with_capacity(1 << 16, stdout.lock()),
        broken: false,
    };
    let result = fill(&mut out).and_then(|()| out.flush());
    result.map_err(|source| IoError::Write {
        path: PathBuf::from(STDOUT_NAME),
        source: if out.broken {
            io::Error::from(io::ErrorKind::BrokenPipe)
        } else {
            source
        },
    })
}

/// Standard output, remembering whether its reader went away.
struct PipeSink<W: Write> {
    inner: W,
    broken: bool,
}

impl<W: Write> PipeSink<W> {
    fn note<T>(&mut self, result: io::Result<T>) -> io::Result<T> {
        if let Err(e) = &result {
            self.broken |= e.kind() == io::ErrorKind::BrokenPipe;
        }
        result
    }
}

impl<W: Write> Write for PipeSink<W> {
    fn write(&mut self, buf: &[u8]) -> io::Result<usize> {
        let result = self.inner.write(buf);
        self.note(result)
    }

    fn flush(&mut self) -> io::Result<()> {
        let result = self.inner.flush();
        self.note(result)
    }
}

/// The name of the temporary files of `path` without the process id: `.NAME.karkas-tmp-`.
fn temp_stem(path: &Path) -> String {
    let name = path
        .file_name()
        .map_or_else(|| "output".into(), |n| n.to_string_lossy());
    let mut cut = name.len().min(TEMP_NAME_BYTES);
    while !name.is_char_boundary(cut) {
        cut -= 1;
    }
    format!(".{}{TEMP_MARK}", &name[..cut])
}

/// Creates a new temporary file `STEM PID-N` in `dir`, with the permissions of the existing
/// destination `path` if any.
fn create_temp(dir: &Path, stem: &str, path: &Path) -> io::Result<(File, PathBuf)> {
    static COUNTER: AtomicUsize = AtomicUsize::new(0);
    let existing = std::fs::metadata(path).ok().map(|m| m.permissions());
    loop {
        let n = COUNTER.fetch_add(1, Ordering::Relaxed);
        let temp = dir.join(format!("{stem}{}-{n}", std::process::id()));
        let mut options = OpenOptions::new();
        options.write(true).create_new(true);
        match options.open(&temp) {
            Ok(file) => {
                if let Some(permissions) = &existing {
                    if let Err(e) = file.set_permissions(permissions.clone()) {
                        let _ = std::fs::remove_file(&temp);
                        return Err(e);
                    }
                }
                return Ok((file, temp));
            }
            // Left by an earlier process with the same id: try the next number.
            Err(e) if e.kind() == io::ErrorKind::AlreadyExists && n < 1 << 20 => continue,
            Err(e) => return Err(e),
        }
    }
}

/// Removes the temporary files `STEM PID-N` in `dir` whose process is gone: left by a run
/// killed while writing the same destination. Only where `/proc` tells which processes live;
/// any failure leaves the files (they are named as stale).
fn remove_stale(dir: &Path, stem: &str) {
    let proc = Path::new("/proc");
    if !proc.join("self").exists() {
        return;
    }
    let Ok(entries) = std::fs::read_dir(dir) else {
        return;
    };
    for entry in entries.flatten() {
        let name = entry.file_name();
        let Some(rest) = name.to_str().and_then(|n| n.strip_prefix(stem)) else {
            continue;
        };
        let Some((pid, n)) = rest.split_once('-') else {
            continue;
        };
        let numeric = |s: &str| !s.is_empty() && s.bytes().all(|b| b.is_ascii_digit());
        if numeric(pid) && numeric(n) && !proc.join(pid).exists() {
            let _ = std::fs::remove_file(entry.path());
        }
    }
}

/// Removes the temporary file on drop unless [`TempGuard::persisted`] was called.
struct TempGuard(Option<PathBuf>);

impl TempGuard {
    /// The temporary file has been renamed over the destination: nothing to remove.
    fn persisted(mut self) {
        self.0 = None;
    }
}

impl Drop for TempGuard {
    fn drop(&mut self) {
        if let Some(temp) = self.0.take() {
            let _ = std::fs::remove_file(temp);
        }
    }
}

/// The operating system's error without any path it carries (a temporary file's name must
/// not reach a message): its kind and text as the system reports them.
fn without_paths(e: io::Error) -> io::Error {
    match e.raw_os_error() {
        Some(code) => io::Error::from_raw_os_error(code),
        None => e,
    }
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
    write_atomic(path, |out| render_curve_csv(ts, points, out))
}

/// The CSV text [`write_curve_csv`] writes, into `out` (`ts` and `points` of one length;
/// extra entries of the longer are left out).
pub fn render_curve_csv<const D: usize>(
    ts: &[f64],
    points: &[Point<D>],
    out: &mut dyn Write,
) -> io::Result<()> {
    let mut header = vec!["t".to_owned()];
    header.extend(coordinate_names(D));
    let mut csv = CsvRows::new(out, &header)?;
    for (&t, p) in ts.iter().zip(points) {
        csv.row(std::iter::once(t).chain(p.0))?;
    }
    csv.finish()
}

/// The header line of the curve samples CSV of dimension `dim`: `t,x,y\n`, `t,x,y,z\n`, ...
pub(crate) fn curve_csv_header(dim: usize) -> String {
    let mut names = vec!["t".to_owned()];
    names.extend(coordinate_names(dim));
    names.join(",") + "\n"
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
    number: Vec<u8>,
}

impl<'a> CsvRows<'a> {
    /// Starts the file with `header`.
    fn new(out: &'a mut dyn Write, header: &[String]) -> io::Result<Self> {
        let mut writer = csv::Writer::from_writer(out);
        writer.write_record(header)?;
        Ok(CsvRows {
            writer,
            number: Vec::new(),
        })
    }

    /// Writes one row.
    fn row(&mut self, values: impl IntoIterator<Item = f64>) -> io::Result<()> {
        for v in values {
            self.number.clear();
            crate::shortest::push(&mut self.number, v);
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
            write!(self.number, "{k}")?;
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
