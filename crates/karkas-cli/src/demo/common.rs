//! What every example of the demo uses: the output folder that records the files written,
//! the lines of the report, and the 3-D viewer page of a surface.

use crate::output::surface::isoparametric_lines;
use anyhow::{Context, Result};
use karkas::{Grid, Point3};
use karkas_io::viewer::{write_viewer_html, ViewerCurve, ViewerScene, ViewerSurface};
use karkas_io::write::write_atomic;
use std::cell::RefCell;
use std::path::{Path, PathBuf};

/// One line of the report: what was checked, the figure found and the paper's figure.
pub struct Finding {
    /// The example.
    pub example: String,
    /// What the figure measures.
    pub measure: String,
    /// The figure.
    pub value: f64,
    /// The paper's figure for the same measure, where it gives one.
    pub paper: Option<f64>,
    /// A detail row: in the report, not in the terminal's summary.
    pub detail: bool,
}

impl Finding {
    /// A summary line with no figure of the paper's.
    pub fn new(example: impl Into<String>, measure: impl Into<String>, value: f64) -> Finding {
        Finding {
            example: example.into(),
            measure: measure.into(),
            value,
            paper: None,
            detail: false,
        }
    }

    /// With the paper's figure for the same measure.
    pub fn paper(self, paper: f64) -> Finding {
        Finding {
            paper: Some(paper),
            ..self
        }
    }

    /// As a detail row: in the report, not in the terminal's summary.
    pub fn detail(self) -> Finding {
        Finding {
            detail: true,
            ..self
        }
    }
}

/// The output folder of the demo; it records the name of every file an example writes, so
/// that the report lists exactly what is there.
pub struct Output {
    dir: PathBuf,
    written: RefCell<Vec<String>>,
}

impl Output {
    /// An output into `dir` (which must exist).
    pub fn new(dir: &Path) -> Output {
        Output {
            dir: dir.to_path_buf(),
            written: RefCell::new(Vec::new()),
        }
    }

    /// The path of the file `name` in the folder, recorded as written by the running example.
    pub fn file(&self, name: impl AsRef<str>) -> PathBuf {
        let name = name.as_ref();
        self.written.borrow_mut().push(name.to_string());
        self.dir.join(name)
    }

    /// The names recorded since the last call, in order, repeats next to each other dropped.
    pub fn take_written(&self) -> Vec<String> {
        let mut names = std::mem::take(&mut *self.written.borrow_mut());
        names.dedup();
        names
    }
}

/// Writes `text` to the file at `path`.
pub fn write_text(path: &Path, text: &str) -> Result<()> {
    write_atomic(path, |w| w.write_all(text.as_bytes()))?;
    Ok(())
}

/// Writes the 3-D viewer page `name` of a surface sampled `rows x cols` (row-major), with
/// its isoparametric lines, the input grid `net` as the control net where there is one, and
/// named curves on it (sections, network curves).
pub fn write_viewer(
    out: &Output,
    name: &str,
    title: &str,
    (rows, cols): (usize, usize),
    samples: &[Point3],
    net: Option<Grid<Point3>>,
    curves: Vec<(&str, Vec<Vec<Point3>>)>,
) -> Result<()> {
    let samples = Grid::from_row_major(rows, cols, samples.to_vec())
        .context("viewer samples do not fill the grid")?;
    let isolines = isoparametric_lines(&samples);
    let curves = curves
        .into_iter()
        .flat_map(|(label, lines)| {
            lines.into_iter().map(move |points| ViewerCurve {
                name: label.to_string(),
                points,
            })
        })
        .collect();
    let scene = ViewerScene {
        title: title.to_string(),
        surfaces: vec![ViewerSurface {
            name: title.to_string(),
            samples,
            control_net: net,
            isolines,
        }],
        curves,
        ..ViewerScene::default()
    };
    write_viewer_html(&out.file(name), &scene)?;
    Ok(())
}
