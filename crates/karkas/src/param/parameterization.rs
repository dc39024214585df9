//! Parameter values for ordered points and for grids of points (Kuznetsov and Filatov, section 3;
//! docs/methods.md §5, "Point grids").
//!
//! A curve or surface through given points needs a parameter value at every point, and the
//! choice decides the shape between the points. For a curve through `p_0..p_{n-1}`:
//!
//! - uniform: `t_k = k`;
//! - chord length: `t_k - t_{k-1} = |p_k - p_{k-1}|` (the paper's choice: close to the best,
//!   arc-length parameters of Theorem 2.1);
//! - centripetal: `t_k - t_{k-1} = |p_k - p_{k-1}|^(1/2)`.
//!
//! For a grid `r_ij` (row `i` along `u`, column `j` along `v`) one sequence `u_i` and one
//! `v_j` serve every line:
//!
//! - [`GridParameterization::Uniform`]: `u_i = i`, `v_j = j`;
//! - [`GridParameterization::Chord`]: the paper's rule: an origin node `(i*, j*)` gets
//!   `(u, v) = (0, 0)`, and `u_i` (`v_j`) is the signed cumulative chord length along the grid
//!   line `j = j*` (`i = i*`) through it; when that line is a pole (all its points one
//!   point, within `1e-9` of the grid's extent: the nose of a body), the
//!   nearest line that is not a pole is measured instead;
//! - [`GridParameterization::AveragedChord`]: the step `u_i - u_{i-1}` is the mean over all
//!   columns `j` of `|r_ij - r_{i-1,j}|` (likewise for `v`), starting at 0: less sensitive to
//!   the choice of one line;
//! - [`GridParameterization::Centripetal`]: the averaged rule with square roots of chords.
//!
//! All are `O(n)` (curves) or `O(N M)` (grids). Parameters always strictly increase; a zero
//! step (coincident consecutive points or lines) is an error naming them.

use crate::core::Grid;
use crate::{Error, Point, Result};

/// How parameter values are given to the points of a curve.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Default)]
pub enum CurveParameterization {
    /// `t_k = k`.
    Uniform,
    /// Cumulative chord length (the paper's choice).
    #[default]
    ChordLength,
    /// Cumulative square root of the chord length.
    Centripetal,
}

/// How parameter values `u_i`, `v_j` are given to the nodes of a grid.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum GridParameterization {
    /// `u_i = i`, `v_j = j`.
    Uniform,
    /// Chord lengths along the two grid lines through the origin node (Kuznetsov and Filatov's rule):
    /// `u` along column `origin_col`, `v` along row `origin_row`, zero at the origin node.
    Chord {
        /// `i*`: the row through the origin node (its chords give `v`).
        origin_row: usize,
        /// `j*`: the column through the origin node (its chords give `u`).
        origin_col: usize,
    },
    /// Chord lengths averaged over all grid lines, starting at 0.
    AveragedChord,
    /// Square roots of chord lengths averaged over all grid lines, starting at 0.
    Centripetal,
}

impl Default for GridParameterization {
    /// The paper's rule with the origin at node `(0, 0)`.
    fn default() -> Self {
        GridParameterization::Chord {
            origin_row: 0,
            origin_col: 0,
        }
    }
}

/// The parameter values of `points` (starting at 0) by the rule `kind`.
///
/// Errors: fewer than 2 points, a non-finite point, two consecutive points that coincide
/// ([`Error::CoincidentPoints`]) for chord-length and centripetal parameters.
pub fn curve_parameters<const D: usize>(
    points: &[Point<D>],
    kind: CurveParameterization,
) -> Result<Vec<f64>> {
    if points.len() < 2 {
        return Err(Error::TooFewPoints {
            what: "a parameterization",
            needed: 2,
            got: points.len(),
        });
    }
    if let Some(index) = points.iter().position(|p| !p.is_finite()) {
        return Err(Error::NonFinitePoint { index });
    }
    let mut ts = Vec::with_capacity(points.len());
    ts.push(0.0);
    let mut t = 0.0;
    for (k, w) in points.windows(2).enumerate() {
        let step = match kind {
            CurveParameterization::Uniform => 1.0,
            CurveParameterization::ChordLength => w[0].distance(w[1]),
            CurveParameterization::Centripetal => w[0].distance(w[1]).sqrt(),
        };
        if step <= 0.0 || t + step <= t {
            return Err(Error::CoincidentPoints {
                first: k,
                second: k + 1,
            });
        }
        t += step;
        ts.push(t);
    }
    Ok(ts)
}

/// Lines of a grid whose points all lie within this fraction of the grid's extent of the
/// first are poles (one point, e.g. the nose of a body).
const POLE_RELATIVE_TOLERANCE: f64 = 1e-9;

/// The line nearest to `line` (of `count`, nearer first, then lower) that is not a pole.
fn nearest_line(line: usize, count: usize, pole: impl Fn(usize) -> bool) -> usize {
    (0..count)
        .flat_map(|d| [line.checked_sub(d), Some(line + d)])
        .flatten()
        .filter(|&k| k < count)
        .find(|&k| !pole(k))
        .unwrap_or(line)
}

/// The diagonal of the bounding box of the grid's points.
fn grid_extent<const D: usize>(grid: &Grid<Point<D>>) -> f64 {
    let (mut low, mut high) = ([f64::INFINITY; D], [f64::NEG_INFINITY; D]);
    for p in grid.as_slice() {
        for c in 0..D {
            low[c] = low[c].min(p[c]);
            high[c] = high[c].max(p[c]);
        }
    }
    (0..D)
        // `hypot` on the sides: their squares would underflow below about 1e-154 units.
        .fold(0.0f64, |d, c| d.hypot(high[c] - low[c]))
}

/// The parameters `(u_i, v_j)` of the nodes of `grid` by the rule `kind`.
///
/// Errors: fewer than 2 rows or columns, a non-finite point, an origin node outside the grid,
/// a zero parameter step ([`Error::CoincidentGridLines`]).
pub fn grid_parameters<const D: usize>(
    grid: &Grid<Point<D>>,
    kind: GridParameterization,
) -> Result<(Vec<f64>, Vec<f64>)> {
    grid.check_points(2, "a grid parameterization (in each grid direction)")?;
    let (rows, cols) = (grid.rows(), grid.cols());
    let u_steps: Vec<f64>;
    let v_steps: Vec<f64>;
    let mut origin = (0, 0);
    match kind {
        GridParameterization::Uniform => {
            u_steps = vec![1.0; rows - 1];
            v_steps = vec![1.0; cols - 1];
        }
        GridParameterization::Chord {
            origin_row,
            origin_col,
        } => {
            if origin_row >= rows || origin_col >= cols {
                return Err(Error::OutsideGrid {
                    what: "the origin node",
                    row: origin_row,
                    col: origin_col,
                    rows,
                    cols,
                });
            }
            origin = (origin_row, origin_col);
            // A pole (a line that is one point) has no chords: measure the nearest line that
            // is not one instead.
            let tolerance = POLE_RELATIVE_TOLERANCE * grid_extent(grid);
            let pole_col =
                |j: usize| (1..rows).all(|i| grid.get(i, j).distance(*grid.get(0, j)) <= tolerance);
            let pole_row = |i: usize| {
                grid.row(i)
                    .iter()
                    .all(|p| p.distance(grid.row(i)[0]) <= tolerance)
            };
            let column = nearest_line(origin_col, cols, pole_col);
            let row = nearest_line(origin_row, rows, pole_row);
            u_steps = (1..rows)
                .map(|i| grid.get(i, column).distance(*grid.get(i - 1, column)))
                .collect();
            let line = grid.row(row);
            v_steps = line.windows(2).map(|w| w[0].distance(w[1])).collect();
        }
        GridParameterization::AveragedChord | GridParameterization::Centripetal => {
            let power = |d: f64| {
                if kind == GridParameterization::Centripetal {
                    d.sqrt()
                } else {
                    d
                }
            };
            u_steps = (1..rows)
                .map(|i| {
                    let (a, b) = (grid.row(i - 1), grid.row(i));
                    a.iter()
                        .zip(b)
                        .map(|(p, q)| power(p.distance(*q)))
                        .sum::<f64>()
                        / cols as f64
                })
                .collect();
            let mut sums = vec![0.0; cols - 1];
            for i in 0..rows {
                for (s, w) in sums.iter_mut().zip(grid.row(i).windows(2)) {
                    *s += power(w[0].distance(w[1]));
                }
            }
            v_steps = sums.into_iter().map(|s| s / rows as f64).collect();
        }
    }
    let us = cumulative(&u_steps, origin.0, "i")?;
    let vs = cumulative(&v_steps, origin.1, "j")?;
    Ok((us, vs))
}

/// The values whose consecutive differences are `steps`, zero at index `origin`.
fn cumulative(steps: &[f64], origin: usize, direction: &'static str) -> Result<Vec<f64>> {
    let mut out = Vec::with_capacity(steps.len() + 1);
    let mut t = 0.0;
    out.push(t);
    for (index, &s) in steps.iter().enumerate() {
        if s <= 0.0 || t + s <= t || !s.is_finite() {
            return Err(Error::CoincidentGridLines { direction, index });
        }
        t += s;
        out.push(t);
    }
    let shift = out[origin];
    for t in &mut out {
        *t -= shift;
    }
    Ok(out)
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::Point2;

    #[test]
    fn curve_rules() {
        let pts = [
            Point2::new([0.0, 0.0]),
            Point2::new([3.0, 4.0]),
            Point2::new([3.0, 8.0]),
        ];
        let chord = curve_parameters(&pts, CurveParameterization::ChordLength).unwrap();
        assert_eq!(chord, [0.0, 5.0, 9.0]);
        let cp = curve_parameters(&pts, CurveParameterization::Centripetal).unwrap();
        assert!((cp[2] - (5f64.sqrt() + 2.0)).abs() < 1e-15);
        let uni = curve_parameters(&pts, CurveParameterization::Uniform).unwrap();
        assert_eq!(uni, [0.0, 1.0, 2.0]);
        let dup = [pts[0], pts[1], pts[1]];
        assert_eq!(
            curve_parameters(&dup, CurveParameterization::ChordLength),
            Err(Error::CoincidentPoints {
                first: 1,
                second: 2
            })
        );
    }

    #[test]
    fn grid_rules() {
        // r_ij = (i^2, j, 0): rows 0, 1, 4; chords along every column are 1, 3.
        let g = Grid::from_fn(3, 4, |i, j| {
            Point::new([(i * i) as f64, (j * j) as f64, 0.0])
        });
        let (u, v) = grid_parameters(&g, GridParameterization::default()).unwrap();
        assert_eq!(u, [0.0, 1.0, 4.0]);
        assert_eq!(v, [0.0, 1.0, 4.0, 9.0]);
        let (u, _) = grid_parameters(
            &g,
            GridParameterization::Chord {
                origin_row: 2,
                origin_col: 1,
            },
        )
        .unwrap();
        assert_eq!(u, [-4.0, -3.0, 0.0]);
        let (u, v) = grid_parameters(&g, GridParameterization::AveragedChord).unwrap();
        assert_eq!(u, [0.0, 1.0, 4.0]);
        assert_eq!(v, [0.0, 1.0, 4.0, 9.0]);
        let (u, _) = grid_parameters(&g, GridParameterization::Centripetal).unwrap();
        assert!((u[2] - (1.0 + 3f64.sqrt())).abs() < 1e-15);
        let flat = Grid::from_fn(3, 3, |i, j| Point::new([(i.min(1)) as f64, j as f64]));
        assert_eq!(
            grid_parameters(&flat, GridParameterization::AveragedChord),
            Err(Error::CoincidentGridLines {
                direction: "i",
                index: 1
            })
        );
    }
}
