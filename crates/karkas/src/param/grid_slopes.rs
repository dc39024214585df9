//! The slope solves of the bicubic surface (Kuznetsov and Filatov, steps 1-3 of (3.8);
//! docs/methods.md §5): one spline system per grid direction, solved for every line of the
//! grid at once.
//!
//! The factored system ([`SlopeSystem`]) takes `width` lines stored k-major (the `k`-th value
//! of every line side by side), so its sweeps run across the lines: independent chains that
//! the processor overlaps and vectorizes, where one line alone is a chain of dependent
//! multiply-adds. Columns of the row-major grid are already k-major; rows are gathered a
//! block at a time into that layout ([`ROW_BLOCK`] rows, small enough to stay in cache) and
//! scattered back. Every line gets the same arithmetic as when solved alone, so the slopes do
//! not depend on the blocks or on the threads.

use crate::core::parallel::PARALLEL_THRESHOLD;
use crate::core::Grid;
use crate::spline::SlopeSystem;
use crate::Point;
use rayon::prelude::*;

/// Columns per parallel block of [`solve_columns`].
const COLUMN_BLOCK: usize = 32;
/// Rows per block of [`solve_rows`].
const ROW_BLOCK: usize = 8;

/// The `u`-slopes of every column of `grid` (step 1). Large grids are solved in blocks of
/// columns in parallel: each block is gathered into a contiguous buffer, solved there (the
/// same arithmetic per column as one solve over all columns) and copied back. The blocks go
/// in waves of a few per thread, so the buffers in flight stay a small part of the grid.
pub(super) fn solve_columns<const D: usize>(
    system: &SlopeSystem,
    grid: &Grid<Point<D>>,
) -> Vec<Point<D>> {
    let (rows, cols) = (grid.rows(), grid.cols());
    let mut ru = vec![Point::ZERO; rows * cols];
    if rows * cols < PARALLEL_THRESHOLD || cols < 2 * COLUMN_BLOCK {
        system.solve(grid.as_slice(), &mut ru, cols, None);
        return ru;
    }
    let starts: Vec<usize> = (0..cols).step_by(COLUMN_BLOCK).collect();
    let wave = 2 * rayon::current_num_threads().max(1);
    for starts in starts.chunks(wave) {
        let blocks: Vec<Vec<Point<D>>> = starts
            .par_iter()
            .map(|&a| {
                let width = COLUMN_BLOCK.min(cols - a);
                let mut values = Vec::with_capacity(rows * width);
                for i in 0..rows {
                    values.extend_from_slice(&grid.row(i)[a..a + width]);
                }
                let mut slopes = vec![Point::ZERO; rows * width];
                system.solve(&values, &mut slopes, width, None);
                slopes
            })
            .collect();
        ru.par_chunks_mut(cols).enumerate().for_each(|(i, row)| {
            for (&a, block) in starts.iter().zip(&blocks) {
                let width = COLUMN_BLOCK.min(cols - a);
                row[a..a + width].copy_from_slice(&block[i * width..(i + 1) * width]);
            }
        });
    }
    ru
}

/// The slopes along every row of the row-major `lines` (`cols` values a row), solved
/// [`ROW_BLOCK`] rows at a time (blocks in parallel on large grids).
pub(super) fn solve_rows<const D: usize>(
    system: &SlopeSystem,
    lines: &[Point<D>],
    cols: usize,
) -> Vec<Point<D>> {
    let mut slopes = vec![Point::ZERO; lines.len()];
    // Scratch of one block (the gathered values and their slopes), reused block after block.
    let scratch = || (Vec::with_capacity(ROW_BLOCK * cols), Vec::new());
    let block = |(values, solved): &mut (Vec<Point<D>>, Vec<Point<D>>),
                 (rows_in, rows_out): (&[Point<D>], &mut [Point<D>])| {
        let width = rows_in.len() / cols;
        values.clear();
        for k in 0..cols {
            values.extend((0..width).map(|r| rows_in[r * cols + k]));
        }
        solved.resize(rows_in.len(), Point::ZERO);
        system.solve(values, solved, width, None);
        for (k, at_k) in solved.chunks_exact(width).enumerate() {
            for (r, &m) in at_k.iter().enumerate() {
                rows_out[r * cols + k] = m;
            }
        }
    };
    let span = ROW_BLOCK * cols;
    if lines.len() < PARALLEL_THRESHOLD {
        let mut buffers = scratch();
        lines
            .chunks(span)
            .zip(slopes.chunks_mut(span))
            .for_each(|pair| block(&mut buffers, pair));
    } else {
        lines
            .par_chunks(span)
            .zip(slopes.par_chunks_mut(span))
            .for_each_init(scratch, block);
    }
    slopes
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::spline::SplineEnds;
    use crate::Point2;

    #[test]
    fn rows_in_blocks_equal_rows_solved_one_by_one() {
        // 13 rows: one full block and a partial one; and a single row.
        for rows in [13, 1] {
            let cols = 40;
            let knots: Vec<f64> = (0..cols)
                .map(|j| j as f64 + 0.3 * (j as f64).sin())
                .collect();
            for ends in [SplineEnds::<2>::NotAKnot, SplineEnds::Periodic] {
                let system = SlopeSystem::new(&knots, &ends).unwrap();
                let lines: Vec<Point2> = (0..rows * cols)
                    .map(|k| {
                        let (i, j) = ((k / cols) as f64, (k % cols) as f64);
                        let periodic = if j as usize == cols - 1 { 0.0 } else { j };
                        Point2::new([
                            (0.7 * i + 0.2 * periodic).sin(),
                            i - 0.1 * periodic * periodic,
                        ])
                    })
                    .collect();
                let blocked = solve_rows(&system, &lines, cols);
                for i in 0..rows {
                    let mut one = vec![Point2::ZERO; cols];
                    system.solve(&lines[i * cols..(i + 1) * cols], &mut one, 1, None);
                    assert_eq!(&blocked[i * cols..(i + 1) * cols], &one[..], "row {i}");
                }
            }
        }
    }
}
