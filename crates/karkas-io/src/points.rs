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

use std::path::Path;

use karkas::{Point, Point2, Point3};

use crate::airfoil::parse_airfoil;
use crate::error::{data_error, IoError, Location};
use crate::lines::{
    csv_rows, first_content_line, is_number, parse_coordinate, read_text, strip_bom,
    whitespace_rows, Row,
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
pub fn read_curve_points(path: &Path) -> Result<CurvePoints, IoError> {
    parse_curve_points(&read_text(path)?, path)
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
    let rows = if first.contains(',') {
        csv_rows(text, path)?
    } else {
        whitespace_rows(text)
    };
    points_from_rows(&rows, path)
}

/// True when the file should be read as an airfoil `.dat`: its first line is a name (not
/// numbers, not a column header naming `x` and `y`) and it is either a `.dat` or has no comma.
fn looks_like_airfoil(text: &str, first: &str, path: &Path) -> bool {
    let is_dat = path
        .extension()
        .is_some_and(|e| e.eq_ignore_ascii_case("dat"));
    if first.contains(',') || first.split_whitespace().all(is_number) {
        return false;
    }
    let fields: Vec<String> = first.split_whitespace().map(str::to_owned).collect();
    if Columns::from_header(&fields).is_some() {
        return false;
    }
    is_dat || !text.contains(',')
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

/// The points of rows of fields: an optional header, then data rows of equal length.
fn points_from_rows(rows: &[Row], path: &Path) -> Result<CurvePoints, IoError> {
    let Some(first) = rows.first() else {
        return Err(data_error(path, "no points found"));
    };
    let at = |line| Location::new(path, line);
    let has_header = !first.fields.iter().all(|f| is_number(f));
    let (columns, data) = if has_header {
        let columns = Columns::from_header(&first.fields).ok_or_else(|| {
            at(first.line).error(format!(
                "the header '{}' names no 'x' and 'y' columns",
                first.fields.join(",")
            ))
        })?;
        if let Some(name) = duplicated_name(&first.fields) {
            return Err(at(first.line).error(format!("the header names column '{name}' twice")));
        }
        (columns, &rows[1..])
    } else {
        let columns = match first.fields.len() {
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
                return Err(at(first.line).error(format!(
                    "expected 2 columns (x y) or 3 columns (x y z), found {n}"
                )))
            }
        };
        (columns, rows)
    };
    if data.is_empty() {
        return Err(data_error(path, "no points found"));
    }
    let width = first.fields.len();
    let coordinate = |row: &Row, k: usize| parse_coordinate(&row.fields[k], k + 1, at(row.line));
    let check_width = |row: &Row| {
        if row.fields.len() == width {
            Ok(())
        } else {
            Err(at(row.line).error(format!(
                "expected {width} fields, found {}",
                row.fields.len()
            )))
        }
    };
    match columns.z {
        None => data
            .iter()
            .map(|row| {
                check_width(row)?;
                Ok(Point([
                    coordinate(row, columns.x)?,
                    coordinate(row, columns.y)?,
                ]))
            })
            .collect::<Result<Vec<_>, _>>()
            .map(CurvePoints::Planar),
        Some(z) => data
            .iter()
            .map(|row| {
                check_width(row)?;
                Ok(Point([
                    coordinate(row, columns.x)?,
                    coordinate(row, columns.y)?,
                    coordinate(row, z)?,
                ]))
            })
            .collect::<Result<Vec<_>, _>>()
            .map(CurvePoints::Spatial),
    }
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
