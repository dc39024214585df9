//! Checking and closing a grid of points: the rules every grid-built surface applies to its
//! input (enough rows and columns, finite points, a closed direction's seam line).

use super::{Grid, Point};
use crate::{Error, Result};

/// Relative distance under which two grid points count as the same (a seam line that repeats
/// the first). Relative to the largest coordinate of the grid, at least 1.
const COINCIDENCE: f64 = 1e-12;

impl<const D: usize> Grid<Point<D>> {
    /// Checks at least `needed` rows and columns (else [`Error::TooFewPoints`] naming `what`)
    /// and finite points (else [`Error::NonFiniteCell`] naming the first such cell).
    pub(crate) fn check_points(&self, needed: usize, what: &'static str) -> Result<()> {
        let (rows, cols) = (self.rows(), self.cols());
        if rows < needed || cols < needed {
            return Err(Error::TooFewPoints {
                what,
                needed,
                got: rows.min(cols),
            });
        }
        match self.as_slice().iter().position(|p| !p.is_finite()) {
            Some(k) => Err(Error::NonFiniteCell {
                row: k / cols,
                col: k % cols,
            }),
            None => Ok(()),
        }
    }

    /// The grid closed in the closed directions: a last line that repeats the first (relative
    /// tolerance `1e-12`) becomes an exact copy of it, otherwise the first line is appended.
    /// A closed direction needs 3 distinct lines (else [`Error::TooFewPoints`] naming `what`).
    /// A grid closed this way and then interpolated as an open one has a `C^0` seam (a
    /// crease) where the first line is repeated.
    pub fn closed(&self, closed_u: bool, closed_v: bool, what: &'static str) -> Result<Self> {
        if !closed_u && !closed_v {
            return Ok(self.clone());
        }
        let (rows, cols) = (self.rows(), self.cols());
        let scale = self
            .as_slice()
            .iter()
            .fold(1.0f64, |m, p| m.max(p.max_abs()));
        let same = |a: &Point<D>, b: &Point<D>| (*a - *b).max_abs() <= COINCIDENCE * scale;
        let mut lines: Vec<Vec<Point<D>>> = (0..rows).map(|i| self.row(i).to_vec()).collect();
        if closed_v {
            let repeats = lines.iter().all(|r| same(&r[0], &r[cols - 1]));
            for r in &mut lines {
                close_line(r, repeats);
            }
        }
        if closed_u {
            let repeats = lines[0]
                .iter()
                .zip(&lines[rows - 1])
                .all(|(a, b)| same(a, b));
            close_line(&mut lines, repeats);
        }
        let (n, m) = (lines.len(), lines[0].len());
        if (closed_u && n < 4) || (closed_v && m < 4) {
            return Err(Error::TooFewPoints {
                what,
                needed: 3,
                got: if closed_u && n < 4 { n - 1 } else { m - 1 },
            });
        }
        Grid::from_row_major(n, m, lines.concat())
    }
}

/// Makes the last item an exact copy of the first when it repeats it, else appends the first.
fn close_line<T: Clone>(items: &mut Vec<T>, repeats_first: bool) {
    if repeats_first {
        let last = items.len() - 1;
        items[last] = items[0].clone();
    } else {
        items.push(items[0].clone());
    }
}
