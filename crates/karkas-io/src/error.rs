//! The one error type of this crate.
//!
//! Every variant names the file it is about, so the message alone tells the user where to look;
//! line numbers are 1-based physical lines of the file, grid indices are 0-based like the `i`
//! and `j` columns of a grid file.

use std::fmt;
use std::path::{Path, PathBuf};

use crate::mesh::error::MeshError;
use crate::picture::error::PictureError;

/// Anything that went wrong reading or writing a file.
#[derive(Debug, thiserror::Error)]
#[non_exhaustive]
pub enum IoError {
    /// The file could not be opened or read.
    #[error("cannot read {}: {source}", .path.display())]
    Open {
        /// The file.
        path: PathBuf,
        /// What the operating system reported.
        source: std::io::Error,
    },
    /// A line of the file is malformed.
    #[error("{}:{line}: {message}", .path.display())]
    Parse {
        /// The file.
        path: PathBuf,
        /// The 1-based line number.
        line: usize,
        /// What is wrong with the line.
        message: String,
    },
    /// A cell of a grid file is missing or given more than once.
    #[error("{}: grid cell (i={i}, j={j}): {message}", .path.display())]
    Cell {
        /// The file.
        path: PathBuf,
        /// The row index of the cell.
        i: usize,
        /// The column index of the cell.
        j: usize,
        /// What is wrong with the cell.
        message: String,
    },
    /// A problem with the file as a whole: empty, too few points, mixed dimensions.
    #[error("{}: {message}", .path.display())]
    Data {
        /// The file.
        path: PathBuf,
        /// What is wrong.
        message: String,
    },
    /// The output file could not be written; the destination is left as it was.
    #[error("cannot write {}: {source}", .path.display())]
    Write {
        /// The destination file.
        path: PathBuf,
        /// What the operating system (or the writer) reported.
        source: std::io::Error,
    },
    /// A sample of a skeleton curve file is missing or given more than once.
    #[error("{}: {curve_column}={curve}, {sample_column}={sample}: {message}", .path.display())]
    Sample {
        /// The file.
        path: PathBuf,
        /// The name of the curve index column (`i` or `j`).
        curve_column: &'static str,
        /// The curve index.
        curve: usize,
        /// The name of the sample index column (`q` or `p`).
        sample_column: &'static str,
        /// The sample index.
        sample: usize,
        /// What is wrong with the sample.
        message: String,
    },
    /// The data read from the file is refused by the geometry library (e.g. a grid it cannot
    /// hold); the library's error is the source.
    #[error(transparent)]
    Geometry(Box<GeometryError>),
    /// The file is not readable as the format its name says (the decoder's error is the
    /// source).
    #[error("{}: not a readable {format} file: {source}", .path.display())]
    Decode {
        /// The file.
        path: PathBuf,
        /// The format, like `"STL"`.
        format: &'static str,
        /// What the decoder reported.
        source: std::io::Error,
    },
    /// A mesh (or sample grid) handed to a mesh writer fails its checks; nothing is written.
    #[error("cannot write {}: {source}", .path.display())]
    InvalidMesh {
        /// The destination file.
        path: PathBuf,
        /// What is wrong with the mesh.
        source: MeshError,
    },
    /// A mesh read from the file fails the checks of a mesh (e.g. a face names a vertex the
    /// file does not have).
    #[error("{}: {source}", .path.display())]
    MalformedMesh {
        /// The file.
        path: PathBuf,
        /// What is wrong with the mesh.
        source: MeshError,
    },
    /// The columns handed to a CSV writer differ in length; nothing is written.
    #[error("cannot write {}: {parameters} {what} for {points} points", .path.display())]
    LengthMismatch {
        /// The destination file.
        path: PathBuf,
        /// What the parameters are, like `"parameters"` or `"u x v parameters"`.
        what: &'static str,
        /// The number of parameters (or parameter pairs).
        parameters: usize,
        /// The number of points.
        points: usize,
    },
    /// A picture could not be drawn or rendered; nothing is written.
    #[error("cannot write {}: {source}", .path.display())]
    Picture {
        /// The destination file.
        path: PathBuf,
        /// What the drawing or rendering library reported.
        source: PictureError,
    },
    /// The output file name has an extension no writer of the command handles.
    #[error("{}: unknown output extension (use one of: {allowed})", .path.display())]
    UnknownExtension {
        /// The requested output file.
        path: PathBuf,
        /// The accepted extensions, like `".csv, .svg"`.
        allowed: String,
    },
}

/// What [`IoError::Geometry`] holds: the file and the error of the geometry library (its
/// source), boxed so that every `Result<_, IoError>` stays small.
#[derive(Debug, thiserror::Error)]
#[error("{}: {source}", .path.display())]
pub struct GeometryError {
    /// The file.
    pub path: PathBuf,
    /// What the library reported.
    pub source: karkas::Error,
}

impl IoError {
    /// An [`IoError::Geometry`]: the library refused what `path` holds.
    ///
    /// # Examples
    ///
    /// ```
    /// use std::path::Path;
    /// use karkas_io::IoError;
    ///
    /// let refused = karkas::Error::NonFinitePoint { index: 3 };
    /// let error = IoError::geometry(Path::new("wing.csv"), refused);
    /// assert!(error.to_string().contains("wing.csv"));
    /// ```
    pub fn geometry(path: &Path, source: karkas::Error) -> IoError {
        IoError::Geometry(Box::new(GeometryError {
            path: path.to_path_buf(),
            source,
        }))
    }

    /// For `map_err`: an [`IoError::Open`] of `path`.
    pub(crate) fn open(path: &Path) -> impl Fn(std::io::Error) -> IoError + '_ {
        |source| IoError::Open {
            path: path.to_path_buf(),
            source,
        }
    }

    /// For `map_err`: an [`IoError::InvalidMesh`] for the destination `path`.
    pub(crate) fn invalid_mesh(path: &Path) -> impl Fn(MeshError) -> IoError + '_ {
        |source| IoError::InvalidMesh {
            path: path.to_path_buf(),
            source,
        }
    }

    /// For `map_err`: an [`IoError::Picture`] for the destination `path`.
    pub(crate) fn picture(path: &Path) -> impl Fn(PictureError) -> IoError + '_ {
        |source| IoError::Picture {
            path: path.to_path_buf(),
            source,
        }
    }
}

/// A 1-based line of a named file: where a parse error points.
///
/// Displays as `path:line`, the form editors and terminals recognise.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct Location<'a> {
    /// The file.
    pub path: &'a Path,
    /// The 1-based line number.
    pub line: usize,
}

impl<'a> Location<'a> {
    /// Line `line` (1-based) of `path`.
    ///
    /// # Examples
    ///
    /// ```
    /// use std::path::Path;
    /// use karkas_io::Location;
    ///
    /// let at = Location::new(Path::new("wing.csv"), 3);
    /// assert_eq!((at.path, at.line), (Path::new("wing.csv"), 3));
    /// ```
    pub fn new(path: &'a Path, line: usize) -> Self {
        Location { path, line }
    }

    /// An [`IoError::Parse`] at this location.
    pub fn error(self, message: impl Into<String>) -> IoError {
        IoError::Parse {
            path: self.path.to_path_buf(),
            line: self.line,
            message: message.into(),
        }
    }
}

impl fmt::Display for Location<'_> {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        write!(f, "{}:{}", self.path.display(), self.line)
    }
}

/// An [`IoError::Data`] about the whole of `path`.
pub(crate) fn data_error(path: &Path, message: impl Into<String>) -> IoError {
    IoError::Data {
        path: path.to_path_buf(),
        message: message.into(),
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn messages_are_one_line_and_name_the_file() {
        let p = Path::new("dir/a.csv");
        assert_eq!(
            Location::new(p, 7).error("bad").to_string(),
            "dir/a.csv:7: bad"
        );
        let e = IoError::Cell {
            path: p.into(),
            i: 1,
            j: 2,
            message: "missing".into(),
        };
        assert_eq!(e.to_string(), "dir/a.csv: grid cell (i=1, j=2): missing");
        let e = IoError::UnknownExtension {
            path: "out.png".into(),
            allowed: ".csv, .svg".into(),
        };
        assert_eq!(
            e.to_string(),
            "out.png: unknown output extension (use one of: .csv, .svg)"
        );
        let e = IoError::Open {
            path: p.into(),
            source: std::io::Error::new(std::io::ErrorKind::NotFound, "gone"),
        };
        assert_eq!(e.to_string(), "cannot read dir/a.csv: gone");
        assert_eq!(
            data_error(p, "no points found").to_string(),
            "dir/a.csv: no points found"
        );
    }
}
