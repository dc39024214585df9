//! Reading an ordered list of curve points.
//!
//! The user's points come in whatever a spreadsheet, a script or an airfoil database produced,
//! so the format is recognised from the content rather than trusted from the extension. The
//! first content line (neither blank nor a `#` comment) decides:
//!
//! - numbers: the first row of a column file, CSV when it holds a comma, else whitespace
//!   columns; two columns are planar points, three spatial ones;
//! - a header naming `x` and `y` (an optional `z` makes the points spatial): a column file
//!   whose columns are then taken by name, so the `t,x,y[,z]` files of
//!   [`crate::write::write_curve_csv`] read back as points;
//! - anything else is a name, and the file an airfoil ([`crate::airfoil`]: Selig or
//!   Lednicer), whatever the extension and even with a comma in the name, when its data lines
//!   are whitespace pairs (or the file is a `.dat`); followed by comma-separated rows it is
//!   a CSV header that names no `x` and `y` columns, an error.
//!
//! Column files follow the rules of `columns.rs`: `#` comments and blank lines
//! skipped, notes after the data ignored, damaged rows refused naming their line.
//!
//! Every input is opened once and read in one pass ([`crate::input::Input`]; `-` is standard
//! input, named `<stdin>` in messages), so pipes, FIFOs and `<(...)` work. Memory is the
//! points themselves plus one line (`store.rs`), charged against the memory cap.

use std::io::BufRead;
use std::path::Path;

use karkas::{Point, Point2, Point3};

use crate::airfoil::AirfoilReader;
use crate::columns::{read_columns, Either, Found, Layout};
use crate::dialect::{join_units, parse_number, Separator};
pub use crate::dialect::{ColumnChoice, ColumnRef, ReadOptions};
use crate::error::{IoError, Location};
use crate::input::{display_name, Input};
use crate::lines::{
    check_held_at, first_token, looks_numeric, split_fields, strip_comment, LineReader,
};
use crate::order_check;
use crate::range::check_coordinate_range;
use crate::store::{input_size, Flat, Store};

/// An ordered list of curve points, planar or spatial as the file says.
#[derive(Clone, Debug, PartialEq)]
pub enum CurvePoints {
    /// Points in the plane (two coordinates each).
    Planar(Vec<Point2>),
    /// Points in space (three coordinates each).
    Spatial(Vec<Point3>),
}

impl CurvePoints {
    /// Number of points.
    pub fn len(&self) -> usize {
        match self {
            CurvePoints::Planar(p) => p.len(),
            CurvePoints::Spatial(p) => p.len(),
        }
    }

    /// True when there are no points.
    pub fn is_empty(&self) -> bool {
        self.len() == 0
    }

    /// The dimension of the points: 2 or 3.
    pub fn dim(&self) -> usize {
        match self {
            CurvePoints::Planar(_) => 2,
            CurvePoints::Spatial(_) => 3,
        }
    }
}

/// Curve points as read, and the warnings of the reader about them (one line each, without
/// the file's name): a first column that counts the rows, points far out of order
/// (`order_check.rs`), a header read in order.
#[derive(Clone, Debug, PartialEq)]
pub struct CurveRead<T> {
    /// The points.
    pub points: T,
    /// What the reader noticed, each a sentence for the user.
    pub warnings: Vec<String>,
}

/// Reads the curve points of the file at `path` (`-`: standard input; see the
/// [module docs](self) for the formats), in one pass. The warnings are dropped: see
/// [`read_curve_points_with`].
pub fn read_curve_points(path: &Path) -> Result<CurvePoints, IoError> {
    Ok(read_curve_points_with(path, &ReadOptions::default())?.points)
}

/// Reads the curve points of the file at `path` (`-`: standard input) with the user's
/// `options` (`--columns`, `--decimal-comma`), in one pass, with the reader's warnings.
pub fn read_curve_points_with(
    path: &Path,
    options: &ReadOptions,
) -> Result<CurveRead<CurvePoints>, IoError> {
    let name = display_name(path);
    let mut lines = LineReader::new(Input::open(path)?, &name);
    let (either, found) =
        read_any::<_, Vec<Point2>, Vec<Point3>>(&mut lines, path, input_size(path), options)?;
    typed(either, &found, &name)
}

/// Reads the curve points of the file at `path` (`-`: standard input) as one flat array of
/// coordinates, point after point, and the dimension (2 or 3): the layout NumPy takes without
/// a copy. Column files are parsed straight into the array. The warnings are dropped: see
/// [`read_curve_coordinates_with`].
pub fn read_curve_coordinates(path: &Path) -> Result<(Vec<f64>, usize), IoError> {
    Ok(read_curve_coordinates_with(path, &ReadOptions::default())?.points)
}

/// [`read_curve_coordinates`] with the user's `options`, and the reader's warnings.
pub fn read_curve_coordinates_with(
    path: &Path,
    options: &ReadOptions,
) -> Result<CurveRead<(Vec<f64>, usize)>, IoError> {
    let name = display_name(path);
    let mut lines = LineReader::new(Input::open(path)?, &name);
    let (either, found) = read_any::<_, Flat, Flat>(&mut lines, path, input_size(path), options)?;
    let (flat, dim) = match either {
        Either::Planar(p) => (p.0, 2),
        Either::Spatial(p) => (p.0, 3),
    };
    check_coordinate_range(flat.iter().copied(), &name)?;
    let n = flat.len() / dim;
    let warnings = warnings_of(n, dim, |k, c| flat[k * dim + c], &found);
    Ok(CurveRead {
        points: (flat, dim),
        warnings,
    })
}

/// Reads curve points from `text` already in memory; `path` names the file in error messages
/// and its extension (`.dat`) takes part in recognising the format.
pub fn parse_curve_points(text: &str, path: &Path) -> Result<CurvePoints, IoError> {
    Ok(parse_curve_points_with(text, path, &ReadOptions::default())?.points)
}

/// [`parse_curve_points`] with the user's `options`, and the reader's warnings.
pub fn parse_curve_points_with(
    text: &str,
    path: &Path,
    options: &ReadOptions,
) -> Result<CurveRead<CurvePoints>, IoError> {
    let mut lines = LineReader::new(text.as_bytes(), path);
    let size = Some(text.len() as u64);
    let (either, found) = read_any::<_, Vec<Point2>, Vec<Point3>>(&mut lines, path, size, options)?;
    typed(either, &found, path)
}

/// The points read, checked for their range, with the warnings about them.
fn typed(
    either: Either<Vec<Point2>, Vec<Point3>>,
    found: &Found,
    name: &Path,
) -> Result<CurveRead<CurvePoints>, IoError> {
    Ok(match either {
        Either::Planar(p) => {
            let warnings = warnings_of(p.len(), 2, |k, c| p[k][c], found);
            CurveRead {
                points: CurvePoints::Planar(in_range(p, name)?),
                warnings,
            }
        }
        Either::Spatial(p) => {
            let warnings = warnings_of(p.len(), 3, |k, c| p[k][c], found);
            CurveRead {
                points: CurvePoints::Spatial(in_range(p, name)?),
                warnings,
            }
        }
    })
}

/// The warnings about `n` points of dimension `dim` (`coord(k, c)`) whose columns were
/// `found` so.
fn warnings_of(
    n: usize,
    dim: usize,
    coord: impl Fn(usize, usize) -> f64,
    found: &Found,
) -> Vec<String> {
    let mut warnings = Vec::new();
    if let Found::InOrder(header) = found {
        let names = if dim == 3 { "x, y, z" } else { "x, y" };
        warnings.push(format!(
            "the header '{header}' names no x and y columns: its {dim} columns are read in \
             order as {names} (--columns A,B[,C] chooses others)"
        ));
    }
    if dim == 3 && matches!(found, Found::NoHeader | Found::InOrder(_)) {
        warnings.extend(order_check::counting_column(n, |k| coord(k, 0)));
    }
    warnings.extend(order_check::out_of_order(n, dim, coord));
    warnings
}

/// `points`, unless their coordinates are out of karkas's range ([`check_coordinate_range`]).
fn in_range<const D: usize>(points: Vec<Point<D>>, path: &Path) -> Result<Vec<Point<D>>, IoError> {
    check_coordinate_range(points.iter().flat_map(|p| p.0), path)?;
    Ok(points)
}

/// Reads the points of `lines` (the input `path`, of `size` bytes when known) into the store
/// of their dimension, read with `options`; with how their columns were found.
fn read_any<R: BufRead + Send, A: Store<2>, B: Store<3>>(
    lines: &mut LineReader<'_, R>,
    path: &Path,
    size: Option<u64>,
    options: &ReadOptions,
) -> Result<(Either<A, B>, Found), IoError> {
    let name = lines.name();
    let mut seen = 0usize;
    let first = loop {
        let Some((line, text)) = lines.next_line()? else {
            let message = if seen == 0 {
                "no points found: the input is empty".to_owned()
            } else {
                format!("no points found: its {seen} lines are blank or comments ('#')")
            };
            return Err(crate::error::data_error(name, message));
        };
        seen = line;
        let content = strip_comment(text).trim();
        if !content.is_empty() {
            break (line, content.to_owned(), text.trim().to_owned());
        }
        if line.is_multiple_of(4096) {
            // Skipped lines count against the cap, so that an endless stream of them ends.
            check_held_at(name, line, u128::from(lines.consumed()))?;
        }
    };
    let (line, content, whole) = first;
    if options.columns.is_some() || !first_line_is_a_name(&content, options.decimal_comma) {
        let layout = Layout::from_first_line(&content, line, name, options)?;
        let found = layout.found.clone();
        return Ok((read_columns(lines, layout, size)?, found));
    }
    // A name: an airfoil, unless rows separated by commas or semicolons (or as many fields as
    // the first line, two or three) follow: the first line is then a column file's header.
    let is_dat = path
        .extension()
        .is_some_and(|e| e.eq_ignore_ascii_case("dat"));
    let mut airfoil = AirfoilReader::new(name);
    airfoil.feed(line, &whole)?;
    let mut decided = is_dat;
    while let Some((next, text)) = lines.next_line()? {
        if !decided {
            let row = strip_comment(text).trim();
            if first_token(row).is_some_and(looks_numeric) {
                decided = true;
                if let Some(layout) = header_of_rows(&content, line, row, next, name, options)? {
                    let found = layout.found.clone();
                    return Ok((read_columns(lines, layout, size)?, found));
                }
            }
        }
        airfoil.feed(next, text)?;
        if next.is_multiple_of(4096) {
            check_held_at(name, next, u128::from(lines.consumed()))?;
        }
    }
    let points = airfoil.finish()?.points;
    let mut store = A::default();
    store.reserve_exact(points.len());
    for p in points {
        store.push(p.0);
    }
    Ok((Either::Planar(store), Found::ByName))
}

/// The layout of a column file whose header is the first content line `header` (line
/// `line`) when its first row `row` (line `row_line`) is separated by commas or semicolons,
/// or has as many fields as the header and three of them; `None` for an airfoil (a name, then
/// pairs separated by spaces).
fn header_of_rows(
    header: &str,
    line: usize,
    row: &str,
    row_line: usize,
    name: &Path,
    options: &ReadOptions,
) -> Result<Option<Layout>, IoError> {
    let row_sep = Separator::of_line(row, options.decimal_comma);
    let head_sep = Separator::of_line(header, options.decimal_comma);
    let at = Location::new(name, line);
    let head_fields = split_fields(header, head_sep, at)?;
    let head_fields = if head_sep == Separator::Whitespace {
        join_units(head_fields)
    } else {
        head_fields
    };
    let row_fields = split_fields(row, row_sep, Location::new(name, row_line))?;
    let columns = matches!(row_sep, Separator::Comma | Separator::Semicolon)
        || (row_fields.len() == 3 && head_fields.len() == 3);
    if !columns {
        return Ok(None);
    }
    let sep = if head_fields.len() == row_fields.len() {
        row_sep
    } else {
        head_sep
    };
    let head_fields = if sep == head_sep {
        head_fields
    } else {
        split_fields(header, sep, at)?
    };
    let mut layout = Layout::from_header(head_fields, sep, line, name, options)?;
    layout.first_row = Some((row_line, row.to_owned()));
    Ok(Some(layout))
}

/// True when the first content line is neither numbers nor a column header naming `x` and
/// `y` (split at its separator, [`Separator::of_line`]): the name line of an airfoil, or
/// the header of a file whose columns are named otherwise.
fn first_line_is_a_name(first: &str, decimal_comma: bool) -> bool {
    let sep = Separator::of_line(first, decimal_comma);
    let Ok(fields) = split_fields(first, sep, Location::new(Path::new(""), 1)) else {
        return true;
    };
    let comma = sep.allows_decimal_comma() || decimal_comma;
    if fields.iter().all(|f| parse_number(f, comma).is_some()) {
        return false;
    }
    let fields = if sep == Separator::Whitespace {
        join_units(fields)
    } else {
        fields
    };
    crate::columns::Columns::from_header(&fields).is_none()
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn dimension_and_length() {
        let p = parse_curve_points("1 2 3\n4 5 6\n", Path::new("p.txt")).unwrap();
        assert_eq!((p.dim(), p.len(), p.is_empty()), (3, 2, false));
    }

    #[test]
    fn names_and_headers_are_told_apart() {
        assert!(first_line_is_a_name("NACA 63,3-418", false));
        assert!(first_line_is_a_name("a,b", false));
        assert!(!first_line_is_a_name("t, X ,y", false));
        assert!(!first_line_is_a_name("x y z", false));
        assert!(!first_line_is_a_name("1,2", false));
        assert!(!first_line_is_a_name("x [mm] y [mm]", false));
        assert!(!first_line_is_a_name("\"x\",\"y\"", false));
        assert!(!first_line_is_a_name("x;y", false));
        assert!(!first_line_is_a_name("0,5\t1,5", false));
    }
}
