//! The control net of the bicubic surface (Kuznetsov and Filatov, steps 1-3 of (3.8);
//! docs/methods.md §5): its B-spline coefficients over the clamped knot vectors of the node
//! parameters, `(N + 2) x (M + 2)` points for `N x M` nodes.
//!
//! The surface is the tensor product of 1-D `C^2` cubic splines, so its net is built one
//! direction at a time. Along `u`, every grid column's spline (its slopes from the factored
//! [`SlopeSystem`]) is turned into its `N + 2` B-spline coefficients; those form the rows of
//! the net. Along `v`, every such row is a line of data like a grid row: its spline's slopes,
//! then its `M + 2` coefficients, in place. Two slope solves per node instead of the three of
//! the Hermite form (which needs `r_u`, `r_v` and `r_uv`), and the surface keeps one point per
//! node instead of four.
//!
//! A cubic with Hermite data on `[u_k, u_{k+1}]` has Bezier points `b_0 = r_k`,
//! `b_1 = r_k + h m_k / 3`, `b_2 = r_{k+1} - h m_{k+1} / 3`, `b_3 = r_{k+1}`; coefficient `c_k`
//! is the blossom at the knots `u_{k-2}, u_{k-1}, u_k` (clamped at the ends), taken on the
//! longer of the two pieces those knots bound, so the one argument outside it is at most one
//! piece length away (the conversion of `crate::bspline`, specialised).
//!
//! The sweeps take `width` lines stored k-major (the `k`-th value of every line side by
//! side): independent chains that the processor overlaps and vectorizes. Columns are gathered
//! in blocks ([`COLUMN_BLOCK`] wide, in parallel waves of one per thread, so the buffers in
//! flight stay a small part of the grid; one after another on the calling thread when the
//! pool has one thread), rows [`ROW_BLOCK`] at a time. Every line gets the same arithmetic as
//! when converted alone, so the net does not depend on blocks or threads.

use crate::core::parallel::{worth_splitting, PARALLEL_THRESHOLD};
use crate::core::Grid;
use crate::spline::SlopeSystem;
use crate::Point;
use rayon::prelude::*;

/// Columns per parallel block of the `u` step.
const COLUMN_BLOCK: usize = 32;
/// Rows per block of the `v` step.
const ROW_BLOCK: usize = 8;

/// The control net of the bicubic interpolant of `grid` (row-major, `grid.cols() + 2` points
/// a row), with the slope systems and node parameters of each direction.
pub(super) fn control_net<const D: usize>(
    (system_u, knots_u): (&SlopeSystem, &[f64]),
    (system_v, knots_v): (&SlopeSystem, &[f64]),
    grid: &Grid<Point<D>>,
) -> Vec<Point<D>> {
    let stride = grid.cols() + 2;
    let mut net = vec![Point::ZERO; (grid.rows() + 2) * stride];
    u_step(system_u, knots_u, grid, &mut net);
    v_step(system_v, knots_v, &mut net, grid.cols());
    net
}

/// Step 1: the `u` coefficients of every grid column into the first `cols` points of every
/// row of `net`.
fn u_step<const D: usize>(
    system: &SlopeSystem,
    knots: &[f64],
    grid: &Grid<Point<D>>,
    net: &mut [Point<D>],
) {
    let (rows, cols) = (grid.rows(), grid.cols());
    let stride = cols + 2;
    // The columns a..a + width as a k-major block of their coefficients.
    let block = |a: usize, width: usize| -> Vec<Point<D>> {
        let mut lines = Vec::with_capacity((rows + 2) * width);
        for i in 0..rows {
            lines.extend_from_slice(&grid.row(i)[a..a + width]);
        }
        lines.resize((rows + 2) * width, Point::ZERO);
        let mut slopes = vec![Point::ZERO; rows * width];
        system.solve(&lines[..rows * width], &mut slopes, width, None);
        hermite_to_controls(knots, &mut lines, &slopes, width);
        lines
    };
    let small = rows * cols < PARALLEL_THRESHOLD || cols < 2 * COLUMN_BLOCK;
    let widths = if small { cols } else { COLUMN_BLOCK };
    let starts: Vec<usize> = (0..cols).step_by(widths).collect();
    if small || !worth_splitting(rows * cols) {
        // One block, or the blocks one after the other (cache-sized) on the calling thread.
        for &a in &starts {
            let width = widths.min(cols - a);
            let lines = block(a, width);
            for (row, coefficients) in net.chunks_exact_mut(stride).zip(lines.chunks_exact(width)) {
                row[a..a + width].copy_from_slice(coefficients);
            }
        }
        return;
    }
    let wave = rayon::current_num_threads().max(1);
    for starts in starts.chunks(wave) {
        let blocks: Vec<Vec<Point<D>>> = starts
            .par_iter()
            .map(|&a| block(a, COLUMN_BLOCK.min(cols - a)))
            .collect();
        net.par_chunks_mut(stride).enumerate().for_each(|(k, row)| {
            for (&a, lines) in starts.iter().zip(&blocks) {
                let width = COLUMN_BLOCK.min(cols - a);
                row[a..a + width].copy_from_slice(&lines[k * width..(k + 1) * width]);
            }
        });
    }
}

/// Steps 2 and 3: every row of `net`, holding `cols` `u` coefficients, replaced by its `v`
/// coefficients (`cols + 2` points), [`ROW_BLOCK`] rows at a time.
fn v_step<const D: usize>(system: &SlopeSystem, knots: &[f64], net: &mut [Point<D>], cols: usize) {
    let stride = cols + 2;
    let scratch = || (Vec::with_capacity(ROW_BLOCK * stride), Vec::new());
    let block = |(lines, slopes): &mut (Vec<Point<D>>, Vec<Point<D>>), rows: &mut [Point<D>]| {
        let width = rows.len() / stride;
        lines.clear();
        for k in 0..cols {
            lines.extend((0..width).map(|r| rows[r * stride + k]));
        }
        lines.resize(stride * width, Point::ZERO);
        slopes.resize(cols * width, Point::ZERO);
        system.solve(&lines[..cols * width], slopes, width, None);
        hermite_to_controls(knots, lines, slopes, width);
        for (k, at_k) in lines.chunks_exact(width).enumerate() {
            for (r, &c) in at_k.iter().enumerate() {
                rows[r * stride + k] = c;
            }
        }
    };
    let span = ROW_BLOCK * stride;
    if !worth_splitting(net.len()) {
        let mut buffers = scratch();
        net.chunks_mut(span)
            .for_each(|rows| block(&mut buffers, rows));
    } else {
        net.par_chunks_mut(span).for_each_init(scratch, block);
    }
}

/// Turns the `n = knots.len()` values of `width` k-major lines in `lines` (the first
/// `n * width` points; `(n + 2) * width` in all), with their `slopes`, into the lines' `n + 2`
/// B-spline coefficients over the clamped knot vector of `knots`, in place.
///
/// Coefficient `c_k` needs the values and slopes at nodes `k - 2..=k` only, so going down
/// from `k = n + 1` every value is read before its place is written.
pub(super) fn hermite_to_controls<const D: usize>(
    knots: &[f64],
    lines: &mut [Point<D>],
    slopes: &[Point<D>],
    width: usize,
) {
    let n = knots.len();
    debug_assert!(n >= 2 && lines.len() == (n + 2) * width && slopes.len() == n * width);
    let h = |k: usize| knots[k + 1] - knots[k];
    let at = |k: usize| k * width..(k + 1) * width;
    // c_{n+1} = r_{n-1}, c_n = r_{n-1} - h_{n-2} m_{n-1} / 3.
    let third = h(n - 2) / 3.0;
    let (head, tail) = lines.split_at_mut(n * width);
    for (line, (last, m)) in head[at(n - 1)].iter().zip(&slopes[at(n - 1)]).enumerate() {
        tail[width + line] = *last;
        tail[line] = last.add_scaled(-third, *m);
    }
    for k in (2..n).rev() {
        let (before, here) = (h(k - 2), h(k - 1));
        // The blossom on the piece k-1 (extrapolated back by `before`) or k-2 (forward).
        let (piece, reach) = if before <= here {
            (k - 1, -before / here)
        } else {
            (k - 2, 1.0 + here / before)
        };
        let third = h(piece) / 3.0;
        let (done, rest) = lines.split_at_mut(k * width);
        let out = &mut rest[..width];
        let (r0, r1) = (
            &done[at(piece)],
            if piece + 1 == k {
                None
            } else {
                Some(&done[at(piece + 1)])
            },
        );
        for line in 0..width {
            let a = r0[line];
            let b = r1.map_or(out[line], |r| r[line]);
            let b1 = a.add_scaled(third, slopes[piece * width + line]);
            let b2 = b.add_scaled(-third, slopes[(piece + 1) * width + line]);
            // The blossom at (0, 1, reach) of the piece: b1 + reach (b2 - b1).
            out[line] = b1.add_scaled(reach, b2 - b1);
        }
    }
    // c_1 = r_0 + h_0 m_0 / 3; c_0 = r_0 stays.
    let third = h(0) / 3.0;
    let (first, second) = lines.split_at_mut(width);
    for line in 0..width {
        second[line] = first[line].add_scaled(third, slopes[line]);
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::bspline::{hermite_curve, knot_vector};
    use crate::spline::SplineEnds;
    use crate::Point2;

    fn knots(n: usize) -> Vec<f64> {
        // Uneven: some pieces 10x their neighbours, both ways.
        (0..n)
            .map(|j| j as f64 + if j % 3 == 1 { 0.9 } else { 0.0 })
            .collect()
    }

    fn values(rows: usize, cols: usize) -> Vec<Point2> {
        (0..rows * cols)
            .map(|k| {
                let (i, j) = ((k / cols) as f64, (k % cols) as f64);
                let periodic = if j as usize == cols - 1 { 0.0 } else { j };
                Point2::new([
                    (0.7 * i + 0.2 * periodic).sin(),
                    i - 0.1 * periodic * periodic,
                ])
            })
            .collect()
    }

    #[test]
    fn one_line_gives_the_exported_b_spline() {
        // Against the general conversion of crate::bspline (Bezier pieces, blossoms).
        for n in [2, 3, 4, 11] {
            let knots = knots(n);
            for ends in [SplineEnds::<2>::NotAKnot, SplineEnds::Periodic] {
                if n < 4 && ends == SplineEnds::Periodic {
                    continue;
                }
                let system = SlopeSystem::new(&knots, &ends).unwrap();
                let data = values(1, n);
                let mut slopes = vec![Point2::ZERO; n];
                system.solve(&data, &mut slopes, 1, None);
                let want = hermite_curve(&knots, &data, &slopes, 1).unwrap();
                let mut lines = data.clone();
                lines.resize(n + 2, Point2::ZERO);
                hermite_to_controls(&knots, &mut lines, &slopes, 1);
                assert_eq!(want.knots(), knot_vector(3, &knots, &vec![1; n - 2]));
                for (got, want) in lines.iter().zip(want.control_points()) {
                    assert!(got.distance(*want) < 1e-13, "n {n}: {got:?} {want:?}");
                }
            }
        }
    }

    #[test]
    fn blocks_equal_lines_converted_one_by_one() {
        // 13 rows: one full row block and a partial one; 2600 columns: parallel column
        // blocks of 32 (and a partial one), 70 columns: one block.
        for ((rows, cols), ends) in [(13, 70), (13, 2600)].into_iter().flat_map(|size| {
            [
                (size, SplineEnds::<2>::NotAKnot),
                (size, SplineEnds::Periodic),
            ]
        }) {
            let (ku, kv) = (knots(rows), knots(cols));
            let su = SlopeSystem::new(&ku, &SplineEnds::<2>::NotAKnot).unwrap();
            let sv = SlopeSystem::new(&kv, &ends).unwrap();
            let grid = Grid::from_row_major(rows, cols, values(rows, cols)).unwrap();
            let net = control_net((&su, &ku), (&sv, &kv), &grid);
            // Column by column, then row by row.
            let mut by_columns = vec![Point2::ZERO; (rows + 2) * cols];
            for j in 0..cols {
                let mut line: Vec<Point2> = (0..rows).map(|i| *grid.get(i, j)).collect();
                let mut slopes = vec![Point2::ZERO; rows];
                su.solve(&line, &mut slopes, 1, None);
                line.resize(rows + 2, Point2::ZERO);
                hermite_to_controls(&ku, &mut line, &slopes, 1);
                for (k, &c) in line.iter().enumerate() {
                    by_columns[k * cols + j] = c;
                }
            }
            for k in 0..rows + 2 {
                let mut line = by_columns[k * cols..(k + 1) * cols].to_vec();
                let mut slopes = vec![Point2::ZERO; cols];
                sv.solve(&line, &mut slopes, 1, None);
                line.resize(cols + 2, Point2::ZERO);
                hermite_to_controls(&kv, &mut line, &slopes, 1);
                assert_eq!(
                    &net[k * (cols + 2)..(k + 1) * (cols + 2)],
                    &line[..],
                    "row {k}"
                );
            }
        }
    }
}
