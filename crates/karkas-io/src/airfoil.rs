//! Airfoil coordinate files (`.dat`) in the two layouts of the UIUC airfoil database.
//!
//! - **Selig**: a name line, then `x y` rows from the trailing edge over the upper surface to
//!   the leading edge and back along the lower surface to the trailing edge.
//! - **Lednicer**: a name line, a line with the point counts of the two surfaces (`17.  17.`),
//!   then the upper surface from leading to trailing edge, then the lower surface from leading
//!   to trailing edge. Blank lines usually separate the blocks, but only the counts are trusted.
//!
//! The layouts are told apart by the first numeric line: two integral numbers both at least 2
//! are Lednicer counts; a Selig point has `x <= 1` on a unit chord. Both are returned in Selig
//! order, one closed-looking loop, which is what a curve through the points wants.
//!
//! Hand-written: no crate reads these files, and the format is a few lines of whitespace
//! columns.

use std::path::Path;

use karkas::{Point, Point2};

use crate::error::{data_error, IoError, Location};
use crate::lines::{is_number, parse_coordinate, strip_bom, whitespace_rows, Row};

/// An airfoil read from a `.dat` file.
#[derive(Clone, Debug, PartialEq)]
pub struct Airfoil {
    /// The name line, trimmed.
    pub name: String,
    /// The contour in Selig order: trailing edge, upper surface, leading edge, lower surface,
    /// trailing edge.
    pub points: Vec<Point2>,
}

/// Reads an airfoil from `text` in either layout; `path` names the file in error messages.
pub fn parse_airfoil(text: &str, path: &Path) -> Result<Airfoil, IoError> {
    let text = strip_bom(text);
    // The name line is taken whole (a name may contain '#'); only lines that start with '#'
    // before it are comments.
    let Some((name_index, name_line)) = text
        .lines()
        .enumerate()
        .map(|(k, l)| (k, l.trim()))
        .find(|(_, l)| !l.is_empty() && !l.starts_with('#'))
    else {
        return Err(data_error(path, "no points found"));
    };
    if name_line.split_whitespace().all(is_number) {
        return Err(Location::new(path, name_index + 1)
            .error("expected the airfoil name line, found numbers"));
    }
    let mut rows = whitespace_rows(text);
    rows.retain(|r| r.line > name_index + 1);
    let points = rows
        .iter()
        .map(|row| point(row, path))
        .collect::<Result<Vec<_>, _>>()?;
    let Some(&first) = points.first() else {
        return Err(data_error(path, "no points found"));
    };
    let points = match lednicer_counts(first) {
        Some((upper, lower)) => lednicer_to_selig(&points[1..], upper, lower, &rows, path)?,
        None => points,
    };
    Ok(Airfoil {
        name: name_line.to_owned(),
        points,
    })
}

/// The point of a row of exactly two finite numbers.
fn point(row: &Row, path: &Path) -> Result<Point2, IoError> {
    let at = Location::new(path, row.line);
    if row.fields.len() != 2 {
        return Err(at.error(format!(
            "expected 2 fields (x y), found {}",
            row.fields.len()
        )));
    }
    Ok(Point([
        parse_coordinate(&row.fields[0], 1, at)?,
        parse_coordinate(&row.fields[1], 2, at)?,
    ]))
}

/// The two surface point counts when `p` reads as a Lednicer count line.
fn lednicer_counts(p: Point2) -> Option<(usize, usize)> {
    let count = |v: f64| (v >= 2.0 && v.fract() == 0.0).then_some(v as usize);
    Some((count(p[0])?, count(p[1])?))
}

/// Reorders Lednicer surfaces (`points` after the count line, `rows[0]` being that line) into
/// Selig order, checking the counts.
fn lednicer_to_selig(
    points: &[Point2],
    upper: usize,
    lower: usize,
    rows: &[Row],
    path: &Path,
) -> Result<Vec<Point2>, IoError> {
    let count_line = rows.first().map_or(0, |r| r.line);
    let expected = upper.saturating_add(lower);
    if points.len() < expected {
        return Err(data_error(
            path,
            format!(
                "the counts on line {count_line} announce {upper} upper + {lower} lower = \
                 {expected} points, but only {} follow",
                points.len()
            ),
        ));
    }
    if points.len() > expected {
        let extra_line = rows.get(expected + 1).map_or(0, |r| r.line);
        return Err(Location::new(path, extra_line).error(format!(
            "more points than the {upper} upper + {lower} lower announced on line {count_line}"
        )));
    }
    let (upper, lower) = points.split_at(upper);
    let mut selig: Vec<Point2> = upper.iter().rev().copied().collect();
    let skip = usize::from(lower.first() == upper.first());
    selig.extend_from_slice(&lower[skip..]);
    Ok(selig)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn counts_are_integral_and_at_least_two() {
        assert_eq!(lednicer_counts(Point([17.0, 17.0])), Some((17, 17)));
        assert_eq!(lednicer_counts(Point([1.0, 0.0])), None);
        assert_eq!(lednicer_counts(Point([17.5, 17.0])), None);
        assert_eq!(lednicer_counts(Point([2.0, 1.0])), None);
    }

    #[test]
    fn count_mismatch_is_reported() {
        let text = "NAME\n3. 3.\n0 0\n0.5 0.1\n1 0\n\n0 0\n0.5 -0.1\n";
        let e = parse_airfoil(text, Path::new("a.dat"))
            .unwrap_err()
            .to_string();
        assert!(e.contains("line 2") && e.contains("only 5 follow"), "{e}");
        let text = "NAME\n2. 2.\n0 0\n1 0\n\n0 0\n1 0\n1 0\n";
        let e = parse_airfoil(text, Path::new("a.dat"))
            .unwrap_err()
            .to_string();
        assert!(e.starts_with("a.dat:8: more points"), "{e}");
    }
}
