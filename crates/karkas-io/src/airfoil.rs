//! Airfoil coordinate files (`.dat`) in the two layouts of the UIUC airfoil database, read
//! as a careful person reads the files found in the wild.
//!
//! - **Selig**: a name line, then `x y` rows from the trailing edge over the upper surface to
//!   the leading edge and back along the lower surface to the trailing edge.
//! - **Lednicer**: a name line, a line with the point counts of the two surfaces (`17.  17.`),
//!   then the upper surface from leading to trailing edge, then the lower surface from leading
//!   to trailing edge. Blank lines usually separate the blocks, but only the counts are trusted.
//!
//! What is read:
//! - the first line that is neither blank nor starts with `#` is the name, taken whole
//!   (commas, `#` and all);
//! - further text lines before the first pair are skipped (a second title, a source), and so
//!   is one line of exactly four numbers (the domain line of MSES and TASOPT files,
//!   `xmin xmax ymin ymax`, right after the name);
//! - the data are the pairs `x y` that follow (whitespace-separated; `#` starts a comment),
//!   blank lines between them allowed;
//! - the data end at the first line that is not a pair: that line and the rest of the file
//!   are notes (a URL, `Thickness: 7.99%`, a table of coefficients, `ZZ`), ignored;
//! - refused, naming the line: a would-be pair that is damaged (a line whose first field is
//!   or looks like a number, `0.5 abc`, `......`, `(0.0022)`, `0.5 0.1 0.2`; among the data
//!   also two fields one of which is a number, `x 0.5`), and a pair after the notes; a line
//!   of three or more fields that starts with a number but holds words (a date,
//!   `20 nov 2005`) is a note.
//!
//! The whole input counts against the memory cap ([`crate::input::max_input_bytes`]), notes
//! included, so an endless stream ends with the cap's error.
//!
//! The layouts are told apart by the first pair: two integral numbers both at least 2 are
//! Lednicer counts; a Selig point has `x <= 1` on a unit chord. Both are returned in Selig
//! order, one closed-looking loop, which is what a curve through the points wants.
//!
//! The reader takes one line at a time (`AirfoilReader`), so a file is read in one pass
//! and only its points are kept.
//!
//! Hand-written: no crate reads these files, and the format is a few lines of whitespace
//! columns.

use std::io::BufRead;
use std::path::Path;

use karkas::{Point, Point2};

use crate::error::{data_error, IoError, Location};
use crate::input::excerpt;
use crate::lines::{
    check_held_at, first_token, is_number, looks_numeric, parse_coordinate, strip_comment,
    LineReader,
};

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
    read_airfoil_lines(&mut LineReader::new(text.as_bytes(), path))
}

/// Reads an airfoil from the file at `path` (`-`: standard input) in one pass.
pub fn read_airfoil(path: &Path) -> Result<Airfoil, IoError> {
    let name = crate::input::display_name(path);
    let input = crate::input::Input::open(path)?;
    read_airfoil_lines(&mut LineReader::new(input, &name))
}

/// Reads an airfoil from the remaining lines of `lines`.
pub(crate) fn read_airfoil_lines<R: BufRead>(
    lines: &mut LineReader<'_, R>,
) -> Result<Airfoil, IoError> {
    let mut reader = AirfoilReader::new(lines.name());
    while let Some((line, text)) = lines.next_line()? {
        reader.feed(line, text)?;
        if line.is_multiple_of(4096) {
            // Skipped lines are charged too, so that endless notes end.
            check_held_at(lines.name(), line, u128::from(lines.consumed()))?;
        }
    }
    reader.finish()
}

/// Where the reader is in the file.
#[derive(Clone, Debug, PartialEq)]
enum Stage {
    /// Before the name line.
    Name,
    /// After the name, before the first pair; `true` until a domain line has been skipped.
    Preamble(bool),
    /// Among the pairs.
    Data,
    /// In the notes that began on a line, quoted.
    Notes(usize, String),
}

/// An airfoil read line by line: [`AirfoilReader::feed`] every line, then
/// [`AirfoilReader::finish`].
#[derive(Clone, Debug)]
pub(crate) struct AirfoilReader<'p> {
    path: &'p Path,
    stage: Stage,
    name: String,
    points: Vec<Point2>,
    /// The line of the first pair (the counts of a Lednicer file).
    first_pair_line: usize,
    /// The lines of the pairs just after as many as Lednicer counts announce, if any.
    extra_line: Option<usize>,
}

impl<'p> AirfoilReader<'p> {
    /// A reader of the file `path` (named in errors).
    pub(crate) fn new(path: &'p Path) -> Self {
        AirfoilReader {
            path,
            stage: Stage::Name,
            name: String::new(),
            points: Vec::new(),
            first_pair_line: 0,
            extra_line: None,
        }
    }

    /// Takes line number `line`, `text` (without its end of line).
    pub fn feed(&mut self, line: usize, text: &str) -> Result<(), IoError> {
        let at = Location::new(self.path, line);
        if self.stage == Stage::Name {
            let trimmed = text.trim();
            if trimmed.is_empty() || trimmed.starts_with('#') {
                return Ok(());
            }
            if trimmed.split_whitespace().all(is_number) {
                return Err(at.error("expected the airfoil name line, found numbers"));
            }
            self.name = trimmed.to_owned();
            self.stage = Stage::Preamble(true);
            return Ok(());
        }
        let content = strip_comment(text).trim();
        if content.is_empty() {
            return Ok(());
        }
        let fields: Vec<&str> = content.split_whitespace().collect();
        let pair = fields.len() == 2 && fields.iter().all(|f| is_number(f));
        match &self.stage {
            Stage::Name => {}
            Stage::Preamble(domain_allowed) => {
                if pair {
                    self.first_pair_line = line;
                    self.stage = Stage::Data;
                    return self.push(&fields, at);
                }
                let domain = fields.len() == 4 && fields.iter().all(|f| is_number(f));
                if domain && *domain_allowed {
                    self.stage = Stage::Preamble(false);
                } else if first_token(content).is_some_and(looks_numeric) {
                    return Err(pair_error(&fields, at));
                }
            }
            Stage::Data => {
                if pair {
                    return self.push(&fields, at);
                }
                if damaged(&fields) {
                    return Err(pair_error(&fields, at));
                }
                self.stage = Stage::Notes(line, excerpt(content));
            }
            Stage::Notes(first, note) => {
                if pair {
                    return Err(at.error(format!(
                        "a point after the notes that begin on line {first} ('{note}'): notes \
                         may only follow the coordinates (remove them or start them with '#')"
                    )));
                }
            }
        }
        Ok(())
    }

    /// Appends the pair `fields` at `at`.
    fn push(&mut self, fields: &[&str], at: Location<'_>) -> Result<(), IoError> {
        let p = Point([
            parse_coordinate(fields[0], 1, at)?,
            parse_coordinate(fields[1], 2, at)?,
        ]);
        if let Some((upper, lower)) = self.points.first().and_then(|&c| lednicer_counts(c)) {
            if self.points.len() == upper.saturating_add(lower).saturating_add(1)
                && self.extra_line.is_none()
            {
                self.extra_line = Some(at.line);
            }
        }
        self.points.push(p);
        if self.points.len().is_multiple_of(1 << 16) {
            check_held_at(self.path, at.line, (self.points.len() * 16) as u128)?;
        }
        Ok(())
    }

    /// The airfoil read, in Selig order.
    pub fn finish(self) -> Result<Airfoil, IoError> {
        let Some(&first) = self.points.first() else {
            return Err(data_error(self.path, "no points found"));
        };
        let points = match lednicer_counts(first) {
            Some((upper, lower)) => self.lednicer_to_selig(upper, lower)?,
            None => self.points,
        };
        Ok(Airfoil {
            name: self.name,
            points,
        })
    }

    /// Reorders Lednicer surfaces (the points after the count line) into Selig order,
    /// checking the counts.
    fn lednicer_to_selig(&self, upper: usize, lower: usize) -> Result<Vec<Point2>, IoError> {
        let points = &self.points[1..];
        let count_line = self.first_pair_line;
        let expected = upper.saturating_add(lower);
        if points.len() < expected {
            return Err(data_error(
                self.path,
                format!(
                    "the counts on line {count_line} announce {upper} upper + {lower} lower = \
                     {expected} points, but only {} follow",
                    points.len()
                ),
            ));
        }
        if points.len() > expected {
            let extra_line = self.extra_line.unwrap_or(0);
            return Err(Location::new(self.path, extra_line).error(format!(
                "more points than the {upper} upper + {lower} lower announced on line {count_line}"
            )));
        }
        let (upper, lower) = points.split_at(upper);
        let mut selig: Vec<Point2> = upper.iter().rev().copied().collect();
        let skip = usize::from(lower.first() == upper.first());
        selig.extend_from_slice(&lower[skip..]);
        Ok(selig)
    }
}

/// True when a line that is not a pair was meant to be one: it has at most two fields, or
/// only fields that look like numbers, and its first field is or looks like a number; or it
/// has two fields, one a number. A longer line of words that starts with a number (a date,
/// `20 nov 2005`) is a note.
fn damaged(fields: &[&str]) -> bool {
    let numeric = |f: &&str| first_token(f).is_some_and(looks_numeric);
    (fields.first().is_some_and(numeric) && (fields.len() <= 2 || fields.iter().all(numeric)))
        || (fields.len() == 2 && fields.iter().any(|f| is_number(f)))
}

/// The error of a damaged pair: the field that is not a number, or the count of fields.
fn pair_error(fields: &[&str], at: Location<'_>) -> IoError {
    if fields.len() != 2 {
        return at.error(format!("expected 2 fields (x y), found {}", fields.len()));
    }
    for (k, field) in fields.iter().enumerate() {
        if let Err(e) = parse_coordinate(field, k + 1, at) {
            return e;
        }
    }
    at.error("expected 2 fields (x y)")
}

/// The two surface point counts when `p` reads as a Lednicer count line.
fn lednicer_counts(p: Point2) -> Option<(usize, usize)> {
    let count = |v: f64| (v >= 2.0 && v.fract() == 0.0).then_some(v as usize);
    Some((count(p[0])?, count(p[1])?))
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
    fn counts_too_large_to_add_are_an_error_not_an_overflow() {
        // 1e300 saturates to usize::MAX: the count of points after it must not overflow.
        let text = "NAME\n1e300 4.\n0 0\n1 0\n";
        assert!(parse_airfoil(text, Path::new("a.dat")).is_err());
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

    #[test]
    fn a_note_may_start_with_a_number_but_a_row_of_numbers_is_data() {
        let pairs = "1 0\n0.5 0.05\n0 0\n0.5 -0.05\n1 0\n";
        let text = format!("FOIL\n{pairs}\n20 nov 2005\nsee http://x\n");
        let foil = parse_airfoil(&text, Path::new("a.dat")).unwrap();
        assert_eq!(foil.points.len(), 5);
        for (row, message) in [
            ("0.5 0.1 0.2", "expected 2 fields (x y), found 3"),
            ("0.7", "expected 2 fields (x y), found 1"),
            ("0.7 x", "'x' is not a number (column 2)"),
        ] {
            let text = format!("FOIL\n{pairs}{row}\n");
            let e = parse_airfoil(&text, Path::new("a.dat"))
                .unwrap_err()
                .to_string();
            assert_eq!(e, format!("a.dat:7: {message}"));
        }
    }
}
