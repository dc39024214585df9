//! Checking and closing a grid of points: the rules every grid-built surface applies to its
//! input (enough rows and columns, finite points, a closed direction's seam line).

use super::{Grid, Point};
use crate::{Error, Result};

/// Relative distance under which two grid points count as the same (a seam line that repeats
/// the first). Relative to the largest coordinate of the grid (no floor: a grid of size 1e-20
/// has its seam told as one of size 1).
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
            .fold(0.0f64, |m, p| m.max(p.max_abs()));
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

#[cfg(test)]
mod tests {
    use crate::{Grid, Point2};

    /// A ring of `n` points about the origin scaled by `s`, as a 2 x n grid (two rings).
    fn rings(n: usize, s: f64, last_repeats: bool) -> Grid<Point2> {
        let count = if last_repeats { n + 1 } else { n };
        let ring: Vec<Point2> = (0..count)
            .map(|j| {
                let a = 2.0 * std::f64::consts::PI * (j % n) as f64 / n as f64;
                Point2::new([s * a.cos(), s * a.sin()])
            })
            .collect();
        let doubled: Vec<Point2> = ring.iter().chain(&ring).map(|&p| p * 2.0).collect();
        Grid::from_row_major(2, count, [ring, doubled[count..].to_vec()].concat()).unwrap()
    }

    #[test]
    fn a_seam_is_told_the_same_way_at_every_scale() {
        for s in [1e-200, 1e-20, 1e-6, 1.0, 1e6, 1e200] {
            // Distinct last column: the first is appended.
            let open = rings(12, s, false).closed(false, true, "test").unwrap();
            assert_eq!(open.cols(), 13, "scale {s}");
            assert_eq!(open.get(0, 11), rings(12, s, false).get(0, 11), "scale {s}");
            // A last column that repeats the first: kept, made an exact copy.
            let repeated = rings(12, s, true).closed(false, true, "test").unwrap();
            assert_eq!(repeated.cols(), 13, "scale {s}");
            assert_eq!(repeated.get(1, 12), repeated.get(1, 0), "scale {s}");
        }
    }
}
