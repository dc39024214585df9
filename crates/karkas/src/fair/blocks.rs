//! The Gauss–Newton terms of the fairer gathered span by span before they enter the banded
//! system (docs/methods.md §8).
//!
//! Every term of the objective touches the four controls of one span: its gradient and matrix
//! are summed first in a dense `4 D` by `4 D` block per span (in the controls' coordinates),
//! then every block is mapped once through the [`Layout`] to the unknowns (free controls,
//! sliding ones, none for held ones) and added to the band. One pass through the layout per
//! span instead of one per term.

use super::layout::Layout;
use super::space::Space;
use crate::solve::BandedSpd;
use crate::Point;

/// The gradient and matrix of every span in the controls' coordinates: entry `c D + a` is
/// axis `a` of the span's `c`-th control.
pub(crate) struct Blocks<const D: usize> {
    gradient: Vec<f64>,
    matrix: Vec<f64>,
}

impl<const D: usize> Blocks<D> {
    const SIDE: usize = 4 * D;

    /// Zero blocks for `spans` spans.
    pub(crate) fn new(spans: usize) -> Self {
        Blocks {
            gradient: vec![0.0; spans * Self::SIDE],
            matrix: vec![0.0; spans * Self::SIDE * Self::SIDE],
        }
    }

    /// Sets every block to zero.
    pub(crate) fn clear(&mut self) {
        self.gradient.fill(0.0);
        self.matrix.fill(0.0);
    }

    /// Adds the Gauss–Newton terms of `weight / 2 * residual^2` on span `k`, the residual's
    /// gradient being `row[c]` on the span's `c`-th control: `weight * residual * row` to the
    /// gradient, `weight * row row^T` to the matrix.
    pub(crate) fn add_square(&mut self, k: usize, row: &[Point<D>; 4], weight: f64, residual: f64) {
        let n = Self::SIDE;
        let gradient = &mut self.gradient[k * n..(k + 1) * n];
        let matrix = &mut self.matrix[k * n * n..(k + 1) * n * n];
        for c in 0..4 {
            for a in 0..D {
                let p = c * D + a;
                let scaled = weight * row[c][a];
                gradient[p] += residual * scaled;
                let line = &mut matrix[p * n..(p + 1) * n];
                for (e, x) in row.iter().enumerate() {
                    for b in 0..D {
                        line[e * D + b] += scaled * x[b];
                    }
                }
            }
        }
    }

    /// Adds `value * row` to the gradient of span `k` only.
    pub(crate) fn add_gradient(&mut self, k: usize, row: &[Point<D>; 4], value: f64) {
        let n = Self::SIDE;
        let gradient = &mut self.gradient[k * n..(k + 1) * n];
        for c in 0..4 {
            for a in 0..D {
                gradient[c * D + a] += value * row[c][a];
            }
        }
    }

    /// Adds `weight * w w^T` on every axis alike to the matrix of span `k` (the terms of
    /// `weight / 2 |sum_c w_c P_c - q|^2`, whose gradient goes in apart).
    pub(crate) fn add_isotropic(&mut self, k: usize, w: &[f64; 4], weight: f64) {
        let n = Self::SIDE;
        let matrix = &mut self.matrix[k * n * n..(k + 1) * n * n];
        for c in 0..4 {
            let scaled = weight * w[c];
            for (e, &we) in w.iter().enumerate() {
                for a in 0..D {
                    matrix[(c * D + a) * n + e * D + a] += scaled * we;
                }
            }
        }
    }

    /// Writes the sum of the blocks, mapped to the unknowns of `layout`, into `g` and `h`
    /// (overwritten).
    pub(crate) fn scatter(
        &self,
        space: &Space,
        layout: &Layout<D>,
        g: &mut [f64],
        h: &mut BandedSpd,
    ) {
        g.fill(0.0);
        h.clear();
        let n = Self::SIDE;
        let mut map: Vec<Option<(usize, f64)>> = vec![None; n];
        for k in 0..space.spans() {
            for c in 0..4 {
                let j = space.control(k, c);
                for a in 0..D {
                    map[c * D + a] = layout.unknown(j, a);
                }
            }
            let gradient = &self.gradient[k * n..(k + 1) * n];
            let matrix = &self.matrix[k * n * n..(k + 1) * n * n];
            for p in 0..n {
                let Some((i, cp)) = map[p] else { continue };
                g[i] += cp * gradient[p];
                for q in 0..n {
                    // Each stored entry K[i][j], i >= j, from every pair mapped to it.
                    match map[q] {
                        Some((j, cq)) if j <= i => h.add(i, j, cp * cq * matrix[p * n + q]),
                        _ => {}
                    }
                }
            }
        }
    }
}
