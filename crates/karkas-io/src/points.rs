//! Reading an ordered list of curve points.
//!
//! The user's points come in whatever a spreadsheet, a script or an airfoil database produced,
//! so the format is recognised from the content rather than trusted from the extension:
//!
//! - an airfoil `.dat` (Selig or Lednicer, see [`crate::airfoil`]): a `.dat` file, or any file
//!   without commas, whose first line is a name rather than numbers (or a column header
//!   naming `x` and `y`);
//! - CSV, read with the `csv` crate, when the first data line contains a comma;
//! - otherwise whitespace-separated columns (hand-split: there is nothing to a whitespace split
//!   that a crate would add).
//!
//! In the two column formats `#` starts a comment and blank lines are skipped. The first line
//! may be a header (it is one when any of its fields is not a number); a header must name an
//! `x` and a `y` column (an optional `z` makes the points spatial), which are then taken by name,
//! so the `t,x,y[,z]` files of [`crate::write::write_curve_csv`] read back as points. Without a
//! header, two columns are planar points and three are spatial ones.

use std::io::BufRead;
use std::path::Path;

use karkas::{Point, Point2, Point3};

use crate::airfoil::parse_airfoil;
use crate::error::{data_error, IoError, Location};
use crate::lines::{
    first_content_line, is_number, open_buffered, parse_coordinate, read_text, strip_bom, RowReader,
};

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

/// Reads the curve points of the file at `path` (see the [module docs](self) for the formats).
///
/// Column files are streamed line by line: memory is the points themselves (16 or 24 bytes
/// each) plus one line. Only a file whose first line is a name (an airfoil `.dat`, small by
/// nature) is read whole.
pub fn read_curve_points(path: &Path) -> Result<CurvePoints, IoError> {
    let mut rows = RowReader::new(open_buffered(path)?, path);
    let Some((_, first)) = rows.next_content_line()? else {
        return Err(data_error(path, "no points found"));
    };
    if first_line_is_a_name(first) {
        return parse_curve_points(&read_text(path)?, path);
    }
    let csv = first.contains(',');
    points_from_rows(RowReader::new(open_buffered(path)?, path), csv, path)
}

/// Reads the curve points of the file at `path` as one flat array of coordinates, point after
/// point, and the dimension (2 or 3): the layout NumPy takes without a copy.
pub fn read_curve_coordinates(path: &Path) -> Result<(Vec<f64>, usize), IoError> {
    Ok(match read_curve_points(path)? {
        CurvePoints::Planar(p) => (p.iter().flat_map(|q| q.0).collect(), 2),
        CurvePoints::Spatial(p) => (p.iter().flat_map(|q| q.0).collect(), 3),
    })
}

/// Reads curve points from `text` already in memory; `path` names the file in error messages
/// and its extension (`.dat`) takes part in recognising the format.
pub fn parse_curve_points(text: &str, path: &Path) -> Result<CurvePoints, IoError> {
    let text = strip_bom(text);
    let Some((_, first)) = first_content_line(text) else {
        return Err(data_error(path, "no points found"));
    };
    if looks_like_airfoil(text, first, path) {
        return Ok(CurvePoints::Planar(parse_airfoil(text, path)?.points));
    }
    let csv = first.contains(',');
    points_from_rows(RowReader::new(text.as_bytes(), path), csv, path)
}

/// True when the first content line is neither numbers, nor comma-separated, nor a column
/// header naming `x` and `y`: the name line of an airfoil (or a mistake).
fn first_line_is_a_name(first: &str) -> bool {
    if first.contains(',') || first.split_whitespace().all(is_number) {
        return false;
    }
    let fields: Vec<String> = first.split_whitespace().map(str::to_owned).collect();
    Columns::from_header(&fields).is_none()
}

/// True when the file should be read as an airfoil `.dat`: its first line is a name (not
/// numbers, not a column header naming `x` and `y`) and it is either a `.dat` or has no comma.
fn looks_like_airfoil(text: &str, first: &str, path: &Path) -> bool {
    let is_dat = path
        .extension()
        .is_some_and(|e| e.eq_ignore_ascii_case("dat"));
    first_line_is_a_name(first) && (is_dat || !text.contains(','))
}

/// Which fields of a row hold x, y and (for spatial points) z, 0-based.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
struct Columns {
    x: usize,
    y: usize,
    z: Option<usize>,
}

impl Columns {
    /// The columns named `x`, `y` and optionally `z` (case-insensitive) in a header; `None`
    /// unless both `x` and `y` are there.
    fn from_header(fields: &[String]) -> Option<Columns> {
        let find = |name: &str| fields.iter().position(|f| f.eq_ignore_ascii_case(name));
        Some(Columns {
            x: find("x")?,
            y: find("y")?,
            z: find("z"),
        })
    }
}

/// The points of a stream of rows: an optional header, then data rows of equal length.
fn points_from_rows<R: BufRead>(
    mut rows: RowReader<'_, R>,
    csv: bool,
    path: &Path,
) -> Result<CurvePoints, IoError> {
    let at = |line| Location::new(path, line);
    let Some((first_line, first)) = rows.next_row(csv)? else {
        return Err(data_error(path, "no points found"));
    };
    let width = first.len();
    let has_header = !first.iter().all(|f| is_number(f));
    let columns = if has_header {
        let columns = Columns::from_header(first).ok_or_else(|| {
            at(first_line).error(format!(
                "the header '{}' names no 'x' and 'y' columns",
                first.join(",")
            ))
        })?;
        if let Some(name) = duplicated_name(first) {
            return Err(at(first_line).error(format!("the header names column '{name}' twice")));
        }
        columns
    } else {
        match width {
            2 => Columns {
                x: 0,
                y: 1,
                z: None,
            },
            3 => Columns {
                x: 0,
                y: 1,
                z: Some(2),
            },
            n => {
                return Err(at(first_line).error(format!(
                    "expected 2 columns (x y) or 3 columns (x y z), found {n}"
                )))
            }
        }
    };
    let first_data = if has_header {
        None
    } else {
        Some((first_line, first.to_vec()))
    };
    match columns.z {
        None => collect_points(rows, csv, first_data, width, [columns.x, columns.y], path)
            .map(CurvePoints::Planar),
        Some(z) => collect_points(
            rows,
            csv,
            first_data,
            width,
            [columns.x, columns.y, z],
            path,
        )
        .map(CurvePoints::Spatial),
    }
}

/// The points of the data rows (`first`, if the first row was data, then the rest of
/// `rows`), coordinate `k` from field `columns[k]`; every row `width` fields long.
fn collect_points<R: BufRead, const D: usize>(
    mut rows: RowReader<'_, R>,
    csv: bool,
    first: Option<(usize, Vec<String>)>,
    width: usize,
    columns: [usize; D],
    path: &Path,
) -> Result<Vec<Point<D>>, IoError> {
    let mut points = Vec::new();
    let mut push = |line: usize, fields: &[String]| -> Result<(), IoError> {
        let at = Location::new(path, line);
        if fields.len() != width {
            return Err(at.error(format!("expected {width} fields, found {}", fields.len())));
        }
        let mut p = [0.0; D];
        for (c, &k) in p.iter_mut().zip(&columns) {
            *c = parse_coordinate(&fields[k], k + 1, at)?;
        }
        points.push(Point(p));
        Ok(())
    };
    if let Some((line, fields)) = first {
        push(line, &fields)?;
    }
    while let Some((line, fields)) = rows.next_row(csv)? {
        push(line, fields)?;
    }
    if points.is_empty() {
        return Err(data_error(path, "no points found"));
    }
    Ok(points)
}

/// A coordinate column name (`x`, `y`, `z`) that a header gives twice, if any.
fn duplicated_name(fields: &[String]) -> Option<&'static str> {
    ["x", "y", "z"].into_iter().find(|name| {
        fields
            .iter()
            .filter(|f| f.eq_ignore_ascii_case(name))
            .count()
            > 1
    })
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn header_columns_are_found_by_name() {
        let h = |s: &str| s.split(',').map(str::to_owned).collect::<Vec<_>>();
        assert_eq!(
            Columns::from_header(&h("t,X,y")),
            Some(Columns {
                x: 1,
                y: 2,
                z: None
            })
        );
        assert_eq!(
            Columns::from_header(&h("z,y,x")),
            Some(Columns {
                x: 2,
                y: 1,
                z: Some(0)
            })
        );
        assert_eq!(Columns::from_header(&h("a,b")), None);
        assert_eq!(duplicated_name(&h("x,y,x")), Some("x"));
    }

    #[test]
    fn dimension_and_length() {
        let p = parse_curve_points("1 2 3\n4 5 6\n", Path::new("p.txt")).unwrap();
        assert_eq!((p.dim(), p.len(), p.is_empty()), (3, 2, false));
    }
}
