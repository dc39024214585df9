//! A ship's table of offsets: CSV rows `station,waterline,half_breadth`, the rows of one
//! station together, stations in increasing order, each station's waterlines increasing from
//! the keel up.
//!
//! The header is required; columns are found by name (any order, any case), extra columns are
//! ignored; `#` comments and blank lines are skipped as in the other formats. The loft places
//! each station's section in its plane `x = station` with `y` the half-breadth and `z` the
//! waterline (`karkas loft --offsets`).

use std::path::Path;

use karkas::Point2;

use crate::error::{data_error, IoError, Location};
use crate::input::display_name;
use crate::lines::{
    csv_rows, header_columns, parse_coordinate, read_text, row_location, strip_bom,
};
use crate::range::check_coordinate_range;

/// The required columns of a table of offsets.
const NAMES: [&str; 3] = ["station", "waterline", "half_breadth"];

/// One station of a table of offsets.
#[derive(Clone, Debug, PartialEq)]
pub struct OffsetStation {
    /// The 1-based line of the station's first row.
    pub line: usize,
    /// The station (the position along the length).
    pub station: f64,
    /// The offsets `(half_breadth, waterline)` from the keel up.
    pub offsets: Vec<Point2>,
}

/// Reads the table of offsets at `path` (`-`: standard input).
pub fn read_offsets_table(path: &Path) -> Result<Vec<OffsetStation>, IoError> {
    parse_offsets_table(&read_text(path)?, &display_name(path))
}

/// Reads a table of offsets from `text`; `path` names it in messages.
///
/// Errors naming the line: a missing column, a cell that is not a finite number, a negative
/// half-breadth, a station that comes after a larger one or appears again after another
/// station, a waterline that is not above the one before in its station.
pub fn parse_offsets_table(text: &str, path: &Path) -> Result<Vec<OffsetStation>, IoError> {
    let rows = csv_rows(strip_bom(text), path)?;
    let Some((header, data)) = rows.split_first() else {
        return Err(data_error(path, "no offsets found"));
    };
    let index = header_columns(header, path, NAMES, "station,waterline,half_breadth")?;
    let width = header.fields.len();
    let mut stations: Vec<OffsetStation> = Vec::new();
    for row in data {
        let at: Location = row_location(row, path, width)?;
        let number = |k: usize| parse_coordinate(&row.fields[index[k]], index[k] + 1, at);
        let (station, waterline, half_breadth) = (number(0)?, number(1)?, number(2)?);
        if half_breadth < 0.0 {
            return Err(at.error(format!(
                "the half-breadth {half_breadth} is negative (column {})",
                index[2] + 1
            )));
        }
        let point = Point2::new([half_breadth, waterline]);
        match stations.last_mut() {
            Some(last) if last.station == station => {
                let below = last.offsets[last.offsets.len() - 1][1];
                if waterline <= below {
                    return Err(at.error(format!(
                        "the waterline {waterline} of station {station} is not above the one \
                         before it ({below}): each station's rows run from the keel up"
                    )));
                }
                last.offsets.push(point);
            }
            Some(last) if station < last.station => {
                return Err(at.error(format!(
                    "the stations are out of order: station {station} after station {} (line {})",
                    last.station, last.line
                )));
            }
            _ => stations.push(OffsetStation {
                line: row.line,
                station,
                offsets: vec![point],
            }),
        }
    }
    if stations.is_empty() {
        return Err(data_error(path, "no offsets found"));
    }
    check_coordinate_range(
        stations
            .iter()
            .flat_map(|s| s.offsets.iter().flat_map(|p| p.0).chain([s.station])),
        path,
    )?;
    Ok(stations)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn stations_group_their_rows() {
        let text = "# hull\nStation,Waterline,Half_Breadth\n0,0,0\n0,1,0.5\n2,0,0.2\n2,1,0.7\n";
        let table = parse_offsets_table(text, Path::new("o.csv")).unwrap();
        assert_eq!(table.len(), 2);
        assert_eq!((table[1].line, table[1].station), (5, 2.0));
        assert_eq!(table[1].offsets[1], Point2::new([0.7, 1.0]));
    }

    #[test]
    fn bad_rows_name_their_line() {
        let cases = [
            (
                "station,waterline,half_breadth\n0,0,0\n0,0,1\n",
                "o.csv:3: the waterline 0",
            ),
            (
                "station,waterline,half_breadth\n1,0,0\n0,0,1\n",
                "o.csv:3: the stations are out of order",
            ),
            (
                "station,waterline,half_breadth\n0,0,-1\n",
                "o.csv:2: the half-breadth -1",
            ),
            ("station,waterline\n0,0\n", "half_breadth"),
            ("station,waterline,half_breadth\n", "no offsets"),
        ];
        for (text, needle) in cases {
            let e = parse_offsets_table(text, Path::new("o.csv")).unwrap_err();
            assert!(e.to_string().contains(needle), "{needle}: {e}");
        }
    }
}
