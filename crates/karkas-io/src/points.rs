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
//! Column files follow the rules of [`crate::columns`]: `#` comments and blank lines
//! skipped, notes after the data ignored, damaged rows refused naming their line.
//!
//! Every input is opened once and read in one pass ([`crate::input::Input`]; `-` is standard
//! input, named `<stdin>` in messages), so pipes, FIFOs and `<(...)` work. Memory is the
//! points themselves plus one line ([`crate::store`]), charged against the memory cap.

use std::io::BufRead;
use std::path::Path;

use karkas::{Point, Point2, Point3};

use crate::airfoil::AirfoilReader;
use crate::columns::{read_columns, Either, Layout};
use crate::error::{IoError, Location};
use crate::input::{display_name, excerpt, Input};
use crate::lines::{
    check_held_at, first_token, is_number, looks_numeric, strip_comment, LineReader,
};
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

/// Reads the curve points of the file at `path` (`-`: standard input; see the
/// [module docs](self) for the formats), in one pass.
pub fn read_curve_points(path: &Path) -> Result<CurvePoints, IoError> {
    let name = display_name(path);
    let mut lines = LineReader::new(Input::open(path)?, &name);
    Ok(
        match read_any::<_, Vec<Point2>, Vec<Point3>>(&mut lines, path, input_size(path))? {
            Either::Planar(p) => CurvePoints::Planar(in_range(p, &name)?),
            Either::Spatial(p) => CurvePoints::Spatial(in_range(p, &name)?),
        },
    )
}

/// Reads the curve points of the file at `path` (`-`: standard input) as one flat array of
/// coordinates, point after point, and the dimension (2 or 3): the layout NumPy takes without
/// a copy. Column files are parsed straight into the array.
pub fn read_curve_coordinates(path: &Path) -> Result<(Vec<f64>, usize), IoError> {
    let name = display_name(path);
    let mut lines = LineReader::new(Input::open(path)?, &name);
    Ok(
        match read_any::<_, Flat, Flat>(&mut lines, path, input_size(path))? {
            Either::Planar(p) => (p.0, 2),
            Either::Spatial(p) => (p.0, 3),
        },
    )
    .and_then(|(flat, dim)| {
        check_coordinate_range(flat.iter().copied(), &name)?;
        Ok((flat, dim))
    })
}

/// Reads curve points from `text` already in memory; `path` names the file in error messages
/// and its extension (`.dat`) takes part in recognising the format.
pub fn parse_curve_points(text: &str, path: &Path) -> Result<CurvePoints, IoError> {
    let mut lines = LineReader::new(text.as_bytes(), path);
    Ok(
        match read_any::<_, Vec<Point2>, Vec<Point3>>(&mut lines, path, Some(text.len() as u64))? {
            Either::Planar(p) => CurvePoints::Planar(in_range(p, path)?),
            Either::Spatial(p) => CurvePoints::Spatial(in_range(p, path)?),
        },
    )
}

/// `points`, unless their coordinates are out of karkas's range ([`check_coordinate_range`]).
fn in_range<const D: usize>(points: Vec<Point<D>>, path: &Path) -> Result<Vec<Point<D>>, IoError> {
    check_coordinate_range(points.iter().flat_map(|p| p.0), path)?;
    Ok(points)
}

/// Reads the points of `lines` (the input `path`, of `size` bytes when known) into the store
/// of their dimension.
fn read_any<R: BufRead + Send, A: Store<2>, B: Store<3>>(
    lines: &mut LineReader<'_, R>,
    path: &Path,
    size: Option<u64>,
) -> Result<Either<A, B>, IoError> {
    let name = lines.name();
    let first = loop {
        let Some((line, text)) = lines.next_line()? else {
            return Err(crate::error::data_error(name, "no points found"));
        };
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
    if !first_line_is_a_name(&content) {
        let layout = Layout::from_first_line(&content, line, name)?;
        return read_columns(lines, layout, size);
    }
    // A name: an airfoil, unless comma-separated rows follow (a CSV header without x and y).
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
                if row.contains(',') {
                    return Err(Location::new(name, line).error(format!(
                        "the header '{}' names no 'x' and 'y' columns",
                        excerpt(&content)
                    )));
                }
                decided = true;
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
    Ok(Either::Planar(store))
}

/// True when the first content line is neither numbers nor a column header naming `x` and
/// `y` (split at commas when it holds one, else at whitespace): the name line of an airfoil
/// (or a mistake).
fn first_line_is_a_name(first: &str) -> bool {
    let fields: Vec<String> = if first.contains(',') {
        first.split(',').map(|f| f.trim().to_owned()).collect()
    } else {
        first.split_whitespace().map(str::to_owned).collect()
    };
    if fields.iter().all(|f| is_number(f)) {
        return false;
    }
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
        assert!(first_line_is_a_name("NACA 63,3-418"));
        assert!(first_line_is_a_name("a,b"));
        assert!(!first_line_is_a_name("t, X ,y"));
        assert!(!first_line_is_a_name("x y z"));
        assert!(!first_line_is_a_name("1,2"));
    }
}
