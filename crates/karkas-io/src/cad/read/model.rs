//! What reading a CAD file gives: the shape, its unit, and what was not read.

use std::path::PathBuf;

use karkas::shape::Shape;

/// A length unit: its name and its size in metres.
#[derive(Clone, Debug, PartialEq)]
pub struct LengthUnit {
    /// The unit's name as the file gives it, lower case: `millimetre`, `inch`, `metre`.
    pub name: String,
    /// One unit in metres.
    pub metres: f64,
}

/// Items of a file that were not read: how many, of which entity type, and why.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct Unread {
    /// What was not read: an entity type, or the items that depend on one ("faces on
    /// OFFSET_SURFACE").
    pub what: String,
    /// How many.
    pub count: usize,
    /// Why.
    pub reason: String,
}

/// The format of a CAD file.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum CadFormat {
    /// STEP (ISO 10303-21).
    Step,
    /// IGES 5.3.
    Iges,
}

/// A CAD file as read: its shape, unit, and what was not read.
#[derive(Clone, Debug)]
pub struct CadModel {
    /// The file's name in messages.
    pub path: PathBuf,
    /// Its format.
    pub format: CadFormat,
    /// The faces and curves read.
    pub shape: Shape,
    /// The length unit of the coordinates.
    pub unit: LengthUnit,
    /// What was not read.
    pub unread: Vec<Unread>,
    /// Notes on the file as a whole (other length units met, assembly placements).
    pub notes: Vec<String>,
    /// The number of entities (STEP instances, IGES directory entries) in the file.
    pub entities: usize,
}

impl CadModel {
    /// One line naming what was not read, with counts and reasons; `None` when everything
    /// was.
    pub fn warning(&self) -> Option<String> {
        if self.unread.is_empty() && self.notes.is_empty() {
            return None;
        }
        let mut parts: Vec<String> = self
            .unread
            .iter()
            .map(|u| format!("{} {} ({})", u.count, u.what, u.reason))
            .collect();
        parts.extend(self.notes.iter().cloned());
        Some(format!(
            "{}: not read: {}",
            self.path.display(),
            parts.join("; ")
        ))
    }
}
