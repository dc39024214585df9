//! Curve families of a curve network: CSV rows `curve,x,y,z`.
//!
//! One row per point; the `curve` column (a number from 0) says which curve the point belongs
//! to, and the points of a curve are its rows in file order. Each curve's rows form one block
//! (a curve that resumes after another began is an error: it is almost always a mistake in
//! the file), blocks may come in any order, and the curves must be numbered from 0 without
//! gaps. The header is required; columns are found by name (any order, any case), extra
//! columns are ignored. Read with the `csv` crate; `#` comments and blank lines are skipped as
//! in the other formats.

use std::path::Path;

use karkas::{Point, Point3};

use crate::error::{data_error, IoError, Location};
use crate::input::display_name;
use crate::input::excerpt;
use crate::lines::{
    csv_rows, header_columns, parse_coordinate, read_text, row_location, strip_bom, Row,
};
use crate::range::{check_coordinate_range, check_stray_point};

/// The column names of a curve-family file.
const NAMES: [&str; 4] = ["curve", "x", "y", "z"];

/// The curves of one family, in the order of their numbers.
#[derive(Clone, Debug, PartialEq)]
pub struct CurveFamily {
    /// The points of curve `k`, in file order.
    pub curves: Vec<Vec<Point3>>,
    /// The 1-based line of the first point of curve `k`.
    pub first_lines: Vec<usize>,
}

/// Reads the curve family of the CSV file at `path` (`-`: standard input).
pub fn read_curve_family(path: &Path) -> Result<CurveFamily, IoError> {
    parse_curve_family(&read_text(path)?, &display_name(path))
}

/// Reads a curve family from CSV `text` already in memory; `path` names the file in error
/// messages.
pub fn parse_curve_family(text: &str, path: &Path) -> Result<CurveFamily, IoError> {
    let rows = csv_rows(&crate::dialect::normalized_csv(strip_bom(text)), path)?;
    let Some((header, data)) = rows.split_first() else {
        return Err(data_error(path, "no curve points found"));
    };
    let columns = Columns::from_header(header, path)?;
    if data.is_empty() {
        return Err(data_error(path, "no curve points found"));
    }
    let mut curves: Vec<Option<(usize, Vec<Point3>)>> = Vec::new();
    let mut current: Option<usize> = None;
    for row in data {
        let (id, p) = columns.read(row, path)?;
        let at = Location::new(path, row.line);
        // With no gaps allowed, a valid id is below the number of data rows: larger ids are
        // refused before they can size an allocation.
        if id >= data.len() {
            return Err(at.error(format!(
                "curve {id}: curves must be numbered from 0 without gaps, and there are only {} \
                 points",
                data.len()
            )));
        }
        if curves.len() <= id {
            curves.resize(id + 1, None);
        }
        match (&mut curves[id], current == Some(id)) {
            (Some((_, points)), true) => points.push(p),
            (Some((first, _)), false) => {
                return Err(at.error(format!(
                    "curve {id} resumes here, but its points began on line {first} and another \
                     curve came in between (give each curve's points together)"
                )))
            }
            (slot @ None, _) => *slot = Some((row.line, vec![p])),
        }
        current = Some(id);
    }
    let mut family = CurveFamily {
        curves: Vec::with_capacity(curves.len()),
        first_lines: Vec::with_capacity(curves.len()),
    };
    for (id, curve) in curves.into_iter().enumerate() {
        let Some((line, points)) = curve else {
            return Err(data_error(
                path,
                format!("curve {id} is missing (curves are numbered from 0 without gaps)"),
            ));
        };
        family.curves.push(points);
        family.first_lines.push(line);
    }
    check_coordinate_range(family.curves.iter().flatten().flat_map(|p| p.0), path)?;
    let all: Vec<Point3> = family.curves.iter().flatten().copied().collect();
    check_stray_point(&all, path)?;
    Ok(family)
}

/// Where the named columns are in the rows of a curve-family file (0-based field indices).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
struct Columns {
    index: [usize; 4],
    width: usize,
}

impl Columns {
    fn from_header(header: &Row, path: &Path) -> Result<Columns, IoError> {
        let index = header_columns(header, path, NAMES, "curve,x,y,z")?;
        Ok(Columns {
            index,
            width: header.fields.len(),
        })
    }

    fn read(&self, row: &Row, path: &Path) -> Result<(usize, Point3), IoError> {
        let at = row_location(row, path, self.width)?;
        let field = |k: usize| row.fields[self.index[k]].as_str();
        let id = field(0).parse::<usize>().map_err(|_| {
            at.error(format!(
                "'{}' is not a curve number (a non-negative integer, column {})",
                excerpt(field(0)),
                self.index[0] + 1
            ))
        })?;
        let coordinate = |k: usize| parse_coordinate(field(k), self.index[k] + 1, at);
        Ok((id, Point([coordinate(1)?, coordinate(2)?, coordinate(3)?])))
    }
}
