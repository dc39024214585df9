//! A loft's sections table: CSV rows `file,x,y,z,chord,twist,dihedral`, one section per row
//! in span order.
//!
//! `file` is a curve file (an airfoil `.dat` or a point CSV) relative to the table's folder;
//! `x,y,z` the section's leading edge; `chord` its chord; `twist` and `dihedral` in degrees.
//! The `dihedral` column may be left out, and any of its cells left empty: the section then
//! takes the direction of the leading edges around it, as aerosandbox's `WingXSec` does. The
//! header is required; columns are found by name (any order, any case), extra columns are
//! ignored; `#` comments and blank lines are skipped as in the other formats.

use std::path::{Path, PathBuf};

use karkas::loft::WingPlacement;
use karkas::Point3;

use crate::error::{data_error, IoError, Location};
use crate::input::{display_name, excerpt, is_stdin};
use crate::lines::{
    csv_rows, header_columns, parse_coordinate, read_text, row_location, strip_bom, Row,
};
use crate::range::check_coordinate_range;

/// The required columns of a sections table.
const NAMES: [&str; 6] = ["file", "x", "y", "z", "chord", "twist"];

/// One row of a sections table.
#[derive(Clone, Debug, PartialEq)]
pub struct SectionRow {
    /// The 1-based line of the row in the table.
    pub line: usize,
    /// The profile's file as written in the table.
    pub file: String,
    /// The profile's file, relative to the table's folder (as written when absolute).
    pub path: PathBuf,
    /// The leading edge.
    pub leading_edge: Point3,
    /// The chord.
    pub chord: f64,
    /// The twist in degrees.
    pub twist: f64,
    /// The dihedral in degrees, when given.
    pub dihedral: Option<f64>,
}

impl SectionRow {
    /// The row's placement of its section on the wing.
    pub fn placement(&self) -> WingPlacement {
        WingPlacement {
            leading_edge: self.leading_edge,
            chord: self.chord,
            twist: self.twist,
            dihedral: self.dihedral,
        }
    }
}

/// Reads the sections table at `path` (`-`: standard input, whose files are then relative to
/// the working folder).
pub fn read_sections_table(path: &Path) -> Result<Vec<SectionRow>, IoError> {
    let folder = if is_stdin(path) {
        PathBuf::new()
    } else {
        path.parent().map(Path::to_path_buf).unwrap_or_default()
    };
    parse_sections_table(&read_text(path)?, &display_name(path), &folder)
}

/// Reads a sections table from `text`; `path` names it in messages, `folder` is where its
/// files are.
pub fn parse_sections_table(
    text: &str,
    path: &Path,
    folder: &Path,
) -> Result<Vec<SectionRow>, IoError> {
    let rows = csv_rows(strip_bom(text), path)?;
    let Some((header, data)) = rows.split_first() else {
        return Err(data_error(path, "no sections found"));
    };
    let index = header_columns(header, path, NAMES, "file,x,y,z,chord,twist[,dihedral]")?;
    let dihedral = header
        .fields
        .iter()
        .position(|f| f.trim().eq_ignore_ascii_case("dihedral"));
    let width = header.fields.len();
    if data.is_empty() {
        return Err(data_error(path, "no sections found"));
    }
    let sections: Vec<SectionRow> = data
        .iter()
        .map(|row| read_row(row, path, folder, (&index, dihedral, width)))
        .collect::<Result<_, _>>()?;
    // The placed profiles reach about a chord from their leading edges.
    check_coordinate_range(
        sections
            .iter()
            .flat_map(|s| s.leading_edge.0.into_iter().chain([s.chord])),
        path,
    )?;
    Ok(sections)
}

/// One data row.
fn read_row(
    row: &Row,
    path: &Path,
    folder: &Path,
    (index, dihedral, width): (&[usize; 6], Option<usize>, usize),
) -> Result<SectionRow, IoError> {
    let at: Location = row_location(row, path, width)?;
    let field = |k: usize| row.fields[index[k]].as_str();
    let number = |k: usize| parse_coordinate(field(k), index[k] + 1, at);
    let file = field(0).trim().to_owned();
    if file.is_empty() {
        return Err(at.error(format!("no profile file (column {})", index[0] + 1)));
    }
    let written = Path::new(&file);
    let path_of = if written.is_absolute() {
        written.to_path_buf()
    } else {
        folder.join(written)
    };
    let dihedral = match dihedral.map(|k| (k, row.fields[k].trim())) {
        None | Some((_, "")) => None,
        Some((k, text)) => Some(parse_coordinate(text, k + 1, at)?),
    };
    let chord = number(4)?;
    if chord <= 0.0 {
        return Err(at.error(format!(
            "the chord '{}' is not positive (column {})",
            excerpt(field(4)),
            index[4] + 1
        )));
    }
    Ok(SectionRow {
        line: row.line,
        file,
        path: path_of,
        leading_edge: Point3::new([number(1)?, number(2)?, number(3)?]),
        chord,
        twist: number(5)?,
        dihedral,
    })
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn rows_with_and_without_dihedral() {
        let text = "# wing\nfile,x,y,z,chord,twist,dihedral\nroot.dat,0,0,0,2,3,\ntip.dat,0.5,4,0.2,1,-1,5\n";
        let rows = parse_sections_table(text, Path::new("w.csv"), Path::new("d")).unwrap();
        assert_eq!(rows.len(), 2);
        assert_eq!(rows[0].path, Path::new("d").join("root.dat"));
        assert_eq!((rows[0].line, rows[0].dihedral), (3, None));
        assert_eq!(rows[1].dihedral, Some(5.0));
        assert_eq!(rows[1].leading_edge, Point3::new([0.5, 4.0, 0.2]));
        let no_dihedral = "File,X,Y,Z,Chord,Twist\na.dat,0,0,0,1,0\n";
        assert!(parse_sections_table(no_dihedral, Path::new("w.csv"), Path::new("")).is_ok());
    }

    #[test]
    fn bad_rows_name_their_line() {
        let e = parse_sections_table(
            "file,x,y,z,chord,twist\na.dat,0,0,0,-1,0\n",
            Path::new("w.csv"),
            Path::new(""),
        )
        .unwrap_err();
        assert_eq!(
            e.to_string(),
            "w.csv:2: the chord '-1' is not positive (column 5)"
        );
        let e = parse_sections_table(
            "file,x,y,z,chord\na.dat,0,0,0,1\n",
            Path::new("w.csv"),
            Path::new(""),
        )
        .unwrap_err();
        assert!(e.to_string().contains("twist"), "{e}");
    }
}
