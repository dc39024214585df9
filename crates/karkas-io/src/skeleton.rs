//! The skeleton curves of a tube (Malozemov et al.'s §4–5): two CSV files of indexed points.
//!
//! - Curves along the tube, `f_i(q)`: header `i,q,x,y,z`, curve `i` in `0..m1`, sample `q` in
//!   `0..N2`;
//! - curves across it, `g_j(p)`: header `j,p,x,y,z`, curve `j` in `0..m2`, sample `p` in
//!   `0..N1`.
//!
//! The layout is that of a grid file ([`crate::grid`]): one row per point, indices from 0,
//! rows in any order, columns found by name (any order, any case, extra columns ignored),
//! every `(curve, sample)` given exactly once. The result is a [`Grid`] with one row per curve.
//! Errors name the file and the line, or the curve and sample (`f.csv: i=1, q=7: missing`).

use std::path::Path;

use karkas::{Grid, Point3};

use crate::error::IoError;
use crate::grid::{parse_indexed, IndexedLayout};
use crate::input::display_name;
use crate::lines::read_text;

/// The layout of a file of curves along a tube.
const ALONG: IndexedLayout = IndexedLayout {
    names: ["i", "q", "x", "y", "z"],
    header: "i,q,x,y,z",
    what: "skeleton points (along)",
    cell_error: |path, curve, sample, message| {
        sample_error(path, ["i", "q"], curve, sample, message)
    },
};

/// The layout of a file of curves across a tube.
const ACROSS: IndexedLayout = IndexedLayout {
    names: ["j", "p", "x", "y", "z"],
    header: "j,p,x,y,z",
    what: "skeleton points (across)",
    cell_error: |path, curve, sample, message| {
        sample_error(path, ["j", "p"], curve, sample, message)
    },
};

fn sample_error(
    path: &Path,
    [curve_column, sample_column]: [&'static str; 2],
    curve: usize,
    sample: usize,
    message: String,
) -> IoError {
    IoError::Sample {
        path: path.to_path_buf(),
        curve_column,
        curve,
        sample_column,
        sample,
        message,
    }
}

/// Reads the curves along a tube (`i,q,x,y,z`) from `path` (`-`: standard input): row `i`
/// of the grid is `f_i`.
pub fn read_along_curves(path: &Path) -> Result<Grid<Point3>, IoError> {
    parse_along_curves(&read_text(path)?, &display_name(path))
}

/// Reads curves along a tube from `text` already in memory; `path` names it in errors.
pub fn parse_along_curves(text: &str, path: &Path) -> Result<Grid<Point3>, IoError> {
    parse_indexed(text, path, &ALONG)
}

/// Reads the curves across a tube (`j,p,x,y,z`) from `path` (`-`: standard input): row `j`
/// of the grid is `g_j`.
pub fn read_across_curves(path: &Path) -> Result<Grid<Point3>, IoError> {
    parse_across_curves(&read_text(path)?, &display_name(path))
}

/// Reads curves across a tube from `text` already in memory; `path` names it in errors.
pub fn parse_across_curves(text: &str, path: &Path) -> Result<Grid<Point3>, IoError> {
    parse_indexed(text, path, &ACROSS)
}
