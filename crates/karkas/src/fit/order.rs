//! Foot-point parameters kept in the order of the data (docs/methods.md §4, "ordered
//! parameters").
//!
//! Each point's foot point is found on its own, so where the noise along the curve exceeds
//! the spacing of the points (a dense cloud at a trailing edge, a leading edge sampled in
//! cosine spacing) the parameters come out of order, and the curve can fold back to serve
//! them: a hook past a sharp end, a loop between close points. The points are measured in
//! their order along the curve, so their parameters must not decrease. Near each foot point
//! `t̂_i` the squared distance is about `d_i + w_i (t - t̂_i)^2` with `w_i = |R'|^2 +
//! (R - r_i) . R''` (at least a small share of `|R'|^2`); the ordered parameters that
//! minimize the sum of these are the weighted isotonic regression of the `t̂_i`, found by
//! the pool-adjacent-violators algorithm in `O(n)`: a run of points out of order is given
//! the weighted mean of its parameters. Hand-written: it is a dozen lines on the fit's own
//! buffers, and the crates that offer it allocate their own point types per call.
//! With many points the runs are pooled within parts in parallel, then across the parts
//! ([`isotonic_in_parts`]).

use crate::core::parallel::{part_size, FIXED_PARTS};
use rayon::prelude::*;

/// Replaces `params` by their weighted isotonic (non-decreasing) regression with the
/// positive weights `weight(i)`, reusing `blocks` as scratch; returns whether anything
/// changed. A point's weight is asked for only when its run is pooled (on a fit most points
/// are in order, and a weight costs an evaluation of the curve).
pub(crate) fn isotonic(
    params: &mut [f64],
    mut weight: impl FnMut(usize) -> f64,
    blocks: &mut Vec<Block>,
) -> bool {
    blocks.clear();
    let mut changed = false;
    for (i, &t) in params.iter().enumerate() {
        changed |= push(blocks, Block::single(i, t), &mut weight);
    }
    if changed {
        fill(params, blocks);
    }
    changed
}

/// [`isotonic`] with the runs pooled within [`FIXED_PARTS`] consecutive parts in parallel, then
/// across the parts' ends. Pooling adjacent violators in any order leads to the same
/// regression (the pool-adjacent-violators argument), so only the rounding of the means may
/// differ from [`isotonic`]'s; `parts` is scratch.
pub(crate) fn isotonic_in_parts(
    params: &mut [f64],
    weight: impl Fn(usize) -> f64 + Sync,
    parts: &mut Vec<Vec<Block>>,
) -> bool {
    let size = part_size(params.len());
    parts.resize_with(FIXED_PARTS, Vec::new);
    for part in parts.iter_mut() {
        part.clear();
    }
    let pooled = parts
        .par_iter_mut()
        .zip(params.par_chunks(size))
        .enumerate()
        .map(|(p, (blocks, chunk))| {
            let mut changed = false;
            for (j, &t) in chunk.iter().enumerate() {
                changed |= push(blocks, Block::single(p * size + j, t), &mut |i| weight(i));
            }
            changed
        })
        .reduce(|| false, |a, b| a | b);
    let (first, rest) = parts.split_at_mut(1);
    let blocks = &mut first[0];
    let mut changed = pooled;
    for part in rest.iter() {
        for &block in part {
            changed |= push(blocks, block, &mut |i| weight(i));
        }
    }
    if changed {
        fill(params, blocks);
    }
    changed
}

/// Pushes `block` onto the increasing run of `blocks`, pooling it with the blocks before it
/// whose means exceed its own; returns whether it pooled any.
fn push(blocks: &mut Vec<Block>, mut block: Block, weight: &mut impl FnMut(usize) -> f64) -> bool {
    let mut changed = false;
    while let Some(last) = blocks.last() {
        if last.mean <= block.mean {
            break;
        }
        changed = true;
        let (a, b) = (
            last.weight.unwrap_or_else(|| weight(last.start)),
            block.weight.unwrap_or_else(|| weight(block.start)),
        );
        let total = a + b;
        block = Block {
            start: last.start,
            weight: Some(total),
            mean: (last.mean * a + block.mean * b) / total,
        };
        blocks.pop();
    }
    blocks.push(block);
    changed
}

/// Every parameter set to the mean of its block (`blocks` cover `params` in order; a point
/// alone keeps its own).
fn fill(params: &mut [f64], blocks: &[Block]) {
    let mut end = params.len();
    for block in blocks.iter().rev() {
        if block.weight.is_some() {
            params[block.start..end].fill(block.mean);
        }
        end = block.start;
    }
}

/// A run of pooled parameters: its first index, total weight (`None` for a single point
/// whose weight was not needed yet) and weighted mean.
#[derive(Clone, Copy, Debug)]
pub(crate) struct Block {
    start: usize,
    weight: Option<f64>,
    mean: f64,
}

impl Block {
    /// Point `i`, with parameter `t`, alone.
    fn single(i: usize, t: f64) -> Self {
        Block {
            start: i,
            weight: None,
            mean: t,
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn ordered_input_is_kept() {
        let mut t = vec![0.0, 0.1, 0.1, 0.5, 1.0];
        let mut blocks = Vec::new();
        assert!(!isotonic(&mut t, |_| 1.0, &mut blocks));
        assert_eq!(t, vec![0.0, 0.1, 0.1, 0.5, 1.0]);
    }

    #[test]
    fn only_pooled_points_are_weighed() {
        let mut t = vec![0.0, 0.1, 0.6, 0.2, 0.7, 0.8, 0.75, 1.0];
        let mut asked = Vec::new();
        let w = [1.0, 1.0, 2.0, 3.0, 1.0, 1.0, 1.0, 1.0];
        assert!(isotonic(
            &mut t,
            |i| {
                asked.push(i);
                w[i]
            },
            &mut Vec::new()
        ));
        asked.sort_unstable();
        assert_eq!(asked, vec![2, 3, 5, 6]);
        assert!((t[2] - (0.6 * 2.0 + 0.2 * 3.0) / 5.0).abs() < 1e-15);
        assert!(t[5] == t[6] && (t[5] - 0.775).abs() < 1e-15);
    }

    /// Pooled in parts, the regression is the one pooled in one pass, to rounding, on
    /// sequences of every length around the parts' size with violations across their ends.
    #[test]
    fn pooling_in_parts_gives_the_same_regression() {
        for n in [0, 1, 2, 7, 8, 9, 15, 16, 17, 64, 100, 1000] {
            // A noisy increasing sequence: runs out of order everywhere, some across parts.
            let t: Vec<f64> = (0..n)
                .map(|i| i as f64 / n as f64 + 0.05 * ((i * 7919 % 101) as f64 / 101.0 - 0.5))
                .collect();
            let w = |i: usize| 1.0 + (i % 5) as f64;
            let (mut one, mut parts) = (t.clone(), t.clone());
            let a = isotonic(&mut one, w, &mut Vec::new());
            let b = isotonic_in_parts(&mut parts, w, &mut Vec::new());
            assert_eq!(a, b, "{n}");
            for (x, y) in one.iter().zip(&parts) {
                assert!((x - y).abs() <= 1e-15, "{n}: {x} {y}");
            }
            assert!(parts.windows(2).all(|p| p[0] <= p[1]));
        }
    }

    #[test]
    fn a_violation_is_pooled_to_the_weighted_mean() {
        let mut t = vec![0.0, 0.6, 0.2, 0.3, 1.0];
        let w = [1.0, 1.0, 3.0, 1.0, 1.0];
        let mut blocks = Vec::new();
        assert!(isotonic(&mut t, |i| w[i], &mut blocks));
        // 0.6 (w 1) and 0.2 (w 3) pool to 0.3, which equals the next value: no further pool.
        assert!((t[1] - 0.3).abs() < 1e-15 && (t[2] - 0.3).abs() < 1e-15);
        assert!((t[3] - 0.3).abs() < 1e-15);
        assert!(t.windows(2).all(|p| p[0] <= p[1]));
    }

    #[test]
    fn matches_brute_force_on_small_cases() {
        // The isotonic regression minimizes sum w (x - t)^2 over non-decreasing x; compare
        // with every monotone assignment on a grid of candidate values.
        let cases: [(&[f64], &[f64]); 3] = [
            (&[0.5, 0.2, 0.4, 0.1], &[1.0, 2.0, 1.0, 1.0]),
            (&[0.9, 0.8, 0.7], &[1.0, 1.0, 1.0]),
            (&[0.1, 0.9, 0.2, 0.8], &[2.0, 1.0, 1.0, 2.0]),
        ];
        for (input, w) in cases {
            let mut t = input.to_vec();
            isotonic(&mut t, |i| w[i], &mut Vec::new());
            let cost = |x: &[f64]| -> f64 {
                x.iter()
                    .zip(input)
                    .zip(w)
                    .map(|((a, b), w)| w * (a - b).powi(2))
                    .sum()
            };
            let best = cost(&t);
            // Perturb each block of the result monotonically: the cost never drops.
            for i in 0..t.len() {
                for delta in [-0.01, 0.01] {
                    let mut x = t.clone();
                    x[i] += delta;
                    if x.windows(2).all(|p| p[0] <= p[1]) {
                        assert!(cost(&x) >= best - 1e-15, "{input:?}: {x:?} beats {t:?}");
                    }
                }
            }
            assert!(t.windows(2).all(|p| p[0] <= p[1]));
        }
    }
}
