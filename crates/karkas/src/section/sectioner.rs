//! Sections of one surface by many planes: the surface is sampled on the coarse grid once.

use super::lines::sample_line;
use super::plane::{LevelFunction, Plane};
use super::result::{condense, Section, SectionWarning};
use super::sample_grid::SampleGrid;
use super::scan::trace_all;
use super::trace::Tracer;
use crate::core::Surface;
use crate::{Error, Result};

/// The largest number of cells of the coarse grid in one direction.
pub const MAX_CELLS: usize = 4096;

/// The cells of a surface built from a grid of `rows x cols` points when none are given (the
/// command line's `section --cells`, Python's `LLSurface.section(cells=None)`): 2 per grid
/// line in each direction, at least 16, at most [`MAX_CELLS`].
pub fn cells_for_grid(rows: usize, cols: usize) -> (usize, usize) {
    let cells = |lines: usize| lines.saturating_mul(2).clamp(16, MAX_CELLS);
    (cells(rows), cells(cols))
}

/// The default tolerance, as a fraction of the diagonal of the surface's bounding box.
pub const DEFAULT_RELATIVE_TOLERANCE: f64 = 1e-4;

/// The smallest tolerance, as a fraction of the larger of the diagonal and the largest
/// coordinate of the surface's samples: a chord error below it is under the rounding of the
/// points (about `1e-16` of their size) times the conditioning of the continuation, cannot be
/// measured, and would split every chord to its depth limit (millions of points).
pub const MIN_RELATIVE_TOLERANCE: f64 = 1e-12;

/// How sections are traced.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct SectionOptions {
    /// The largest distance allowed between a section polyline and the true section curve
    /// (the chord error: every chord is measured against the arc it spans and split until it is
    /// within the tolerance), in the surface's units. `None` (the default):
    /// [`DEFAULT_RELATIVE_TOLERANCE`] times the diagonal of the surface's bounding box (as
    /// sampled on the grid). The points themselves are always on the section to rounding.
    pub tolerance: Option<f64>,
    /// Cells of the coarse grid in `u` and `v` (each `3..=`[`MAX_CELLS`]), uniform over the
    /// domain: every piece of a section must cross a cell edge to be found, so a closed piece
    /// smaller than a cell may be missed. Default `(64, 64)`; for a piecewise surface, one or
    /// two cells per patch.
    pub cells: (usize, usize),
    /// The most continuation steps of one piece in one direction (default 100 000): a trace
    /// that reaches it stops with [`SectionWarning::StepLimit`](super::SectionWarning).
    pub max_steps: usize,
}

impl Default for SectionOptions {
    fn default() -> Self {
        SectionOptions {
            tolerance: None,
            cells: (64, 64),
            max_steps: 100_000,
        }
    }
}

/// Cuts one surface by any number of planes or level functions.
///
/// [`new`](Self::new) samples the surface at the vertices of the coarse grid, once; each
/// section then costs one pass over those samples, a root search on each crossed edge not yet
/// traced, and the continuation steps along its pieces.
#[derive(Debug)]
pub struct Sectioner<'s, S: ?Sized, const D: usize> {
    surface: &'s S,
    grid: SampleGrid<D>,
    tolerance: f64,
    max_steps: usize,
}

impl<'s, S: Surface<D> + ?Sized, const D: usize> Sectioner<'s, S, D> {
    /// Prepares sections of `surface`.
    ///
    /// Errors: [`Error::InvalidSetting`] for cells outside `3..=MAX_CELLS`, a tolerance that is
    /// not positive and finite or below [`MIN_RELATIVE_TOLERANCE`] of the surface's size, a
    /// zero step budget; [`Error::InvalidDomain`] for a surface whose
    /// parameter domain is empty or not finite.
    ///
    /// # Examples
    ///
    /// ```
    /// use karkas::bspline::BSplineSurface;
    /// use karkas::section::{Plane, SectionOptions, Sectioner};
    /// use karkas::{Grid, Point};
    ///
    /// // The saddle patch z = x y over the unit square, cut by the plane x = 0.5.
    /// let control = Grid::from_fn(2, 2, |i, j| Point([i as f64, j as f64, (i * j) as f64]));
    /// let linear = (1, vec![0.0, 0.0, 1.0, 1.0]);
    /// let patch = BSplineSurface::new(linear.clone(), linear, control)?;
    /// let sectioner = Sectioner::new(&patch, &SectionOptions::default())?;
    /// let section = sectioner.plane(&Plane::coordinate(0, 0.5)?);
    /// assert_eq!(section.curves.len(), 1);
    /// assert!(section.curves[0].points.iter().all(|p| (p.0[2] - 0.5 * p.0[1]).abs() < 1e-6));
    /// # Ok::<(), karkas::Error>(())
    /// ```
    pub fn new(surface: &'s S, options: &SectionOptions) -> Result<Self> {
        for (name, cells) in [("cells_u", options.cells.0), ("cells_v", options.cells.1)] {
            if !(3..=MAX_CELLS).contains(&cells) {
                return Err(Error::InvalidSetting {
                    name,
                    value: cells as f64,
                    reason: "the coarse grid needs 3 to 4096 cells in each direction",
                });
            }
        }
        if let Some(t) = options.tolerance {
            if !(t > 0.0 && t.is_finite()) {
                return Err(Error::InvalidSetting {
                    name: "tolerance",
                    value: t,
                    reason: "the tolerance must be positive and finite",
                });
            }
        }
        if options.max_steps == 0 {
            return Err(Error::InvalidSetting {
                name: "max_steps",
                value: 0.0,
                reason: "at least one step is needed",
            });
        }
        for domain in [surface.domain_u(), surface.domain_v()] {
            let length = domain.length();
            if !(length > 0.0 && length.is_finite() && domain.start.is_finite()) {
                return Err(Error::InvalidDomain {
                    start: domain.start,
                    end: domain.end,
                });
            }
        }
        let grid = SampleGrid::new(surface, options.cells);
        let size = grid.diagonal.max(grid.scale);
        if let Some(t) = options.tolerance {
            if t < MIN_RELATIVE_TOLERANCE * size {
                return Err(Error::InvalidSetting {
                    name: "tolerance",
                    value: t,
                    reason: "below 1e-12 of the surface's size, where chord errors are rounding",
                });
            }
        }
        let tolerance = options.tolerance.unwrap_or_else(|| {
            (DEFAULT_RELATIVE_TOLERANCE * grid.diagonal.max(grid.scale)).max(f64::MIN_POSITIVE)
        });
        Ok(Sectioner {
            surface,
            grid,
            tolerance,
            max_steps: options.max_steps,
        })
    }

    /// The chord tolerance in use.
    pub fn tolerance(&self) -> f64 {
        self.tolerance
    }

    /// The section by `plane`: the surface's own parameter lines when it offers them (the
    /// fast path, formula (21)), else the traced level set.
    pub fn plane(&self, plane: &Plane<D>) -> Section<D> {
        if let Some(lines) = self
            .surface
            .level_parameter_lines(plane.normal(), plane.offset())
        {
            let mut curves = Vec::new();
            let mut warnings = Vec::new();
            for line in lines {
                let curve = sample_line(self.surface, &self.grid, line, self.tolerance);
                if !self.grid.is_one_point(curve.points.iter().copied()) {
                    curves.push(curve);
                } else if let Some(&(u, v)) = curve.params.first() {
                    // A line that is one point (a pole): the plane touches the surface there.
                    warnings.push(SectionWarning::SingularPoint { u, v });
                }
            }
            return Section {
                curves,
                warnings,
                fast_path: true,
            };
        }
        self.level_set(plane)
    }

    /// The traced curves where `level` vanishes on the surface (never the fast path).
    pub fn level_set<F: LevelFunction<D>>(&self, level: &F) -> Section<D> {
        // The size of the values, for Newton's stopping test: rounding in `f(p)` is relative
        // to `|f(p)| + |grad f| |p|`. Only its order of magnitude matters: every 16th vertex.
        let value_scale = self
            .grid
            .points
            .iter()
            .step_by(16)
            .map(|&p| level.value(p).abs() + level.gradient(p).norm() * self.grid.scale)
            .filter(|s| s.is_finite())
            .fold(f64::MIN_POSITIVE, f64::max);
        let tracer = Tracer {
            surface: self.surface,
            level,
            grid: &self.grid,
            tolerance: self.tolerance,
            max_steps: self.max_steps,
            converged: 1e-14 * value_scale,
            acceptable: 1e-11 * value_scale,
        };
        let (curves, warnings) = trace_all(&tracer);
        Section {
            curves,
            warnings: condense(warnings),
            fast_path: false,
        }
    }
}

/// The section of `surface` by `plane` (see [`Sectioner`] to cut one surface many times).
///
/// ```
/// use karkas::ll::LlSurface;
/// use karkas::section::{plane_section, Plane, SectionOptions};
/// use karkas::{Grid, Point3, Surface};
/// // A bumpy sheet over the unit square; cut it by the plane x + y = 1.
/// let grid = Grid::from_fn(6, 6, |i, j| {
///     let (x, y) = (i as f64 / 5.0, j as f64 / 5.0);
///     Point3::new([x, y, (3.0 * x).sin() * y])
/// });
/// let sheet = LlSurface::new(&grid, 3, false, false).unwrap();
/// let plane = Plane::new(Point3::new([1.0, 1.0, 0.0]), 1.0).unwrap();
/// let section = plane_section(&sheet, &plane, &SectionOptions::default()).unwrap();
/// assert_eq!(section.curves.len(), 1);
/// let curve = &section.curves[0];
/// assert!(!curve.closed);
/// for (&(u, v), p) in curve.params.iter().zip(&curve.points) {
///     assert!((p[0] + p[1] - 1.0).abs() < 1e-12);
///     assert_eq!(sheet.eval(u, v), *p);
/// }
/// ```
pub fn plane_section<S: Surface<D> + ?Sized, const D: usize>(
    surface: &S,
    plane: &Plane<D>,
    options: &SectionOptions,
) -> Result<Section<D>> {
    Ok(Sectioner::new(surface, options)?.plane(plane))
}
