//! Data-parallel batches: large evaluation and grid jobs are split into chunks that rayon
//! runs on all cores; small ones stay on the calling thread (no scheduling overhead), and so
//! does every batch when rayon's pool has one thread ([`worth_splitting`]).
//!
//! Every chunk is computed by the same serial kernel as a small batch, so results do not
//! depend on the number of threads (bitwise). Threads come from rayon's global pool
//! (`RAYON_NUM_THREADS` limits it).

use rayon::prelude::*;

/// Batches with fewer items than this run serially.
pub(crate) const PARALLEL_THRESHOLD: usize = 1 << 15;

/// True when a batch of `n` items is split among threads: at least [`PARALLEL_THRESHOLD`]
/// items, and more than one thread in rayon's pool. With one thread (`RAYON_NUM_THREADS=1`)
/// a parallel call would only hand the work to the pool's one worker and wait for it, a
/// wake-up and a sleep of two threads per call; the calling thread does it instead.
pub(crate) fn worth_splitting(n: usize) -> bool {
    n >= PARALLEL_THRESHOLD && rayon::current_num_threads() > 1
}

/// Parts a reduction over many items is split into (sums, pooled runs): fixed, not one per
/// thread, so that the result does not depend on the number of threads.
pub(crate) const FIXED_PARTS: usize = 8;

/// Items per part when `n` items are split into [`FIXED_PARTS`] (at least 1).
pub(crate) fn part_size(n: usize) -> usize {
    n.div_ceil(FIXED_PARTS).max(1)
}

/// Items per parallel chunk of a 1-D batch (large enough to amortise the scheduling, small
/// enough to balance two cores).
const CHUNK: usize = 1 << 14;

/// Runs `kernel(ts_chunk, out_chunk)` over matching chunks of `ts` and `out`, in parallel when
/// the batch is large. `ts.len() == out.len()` is the caller's to check.
pub(crate) fn for_each_chunk<T: Send>(
    ts: &[f64],
    out: &mut [T],
    kernel: impl Fn(&[f64], &mut [T]) + Sync,
) {
    if !worth_splitting(out.len()) {
        kernel(ts, out);
    } else {
        out.par_chunks_mut(CHUNK)
            .zip(ts.par_chunks(CHUNK))
            .for_each(|(o, t)| kernel(t, o));
    }
}

/// Runs `kernel(first_row, rows_block)` over blocks of whole rows of a row-major `out` with
/// `row_len` items per row, in parallel when the grid is large. Each block gets its own call,
/// so per-call scratch buffers are allocated once per block.
pub(crate) fn for_each_row_block<T: Send>(
    out: &mut [T],
    row_len: usize,
    kernel: impl Fn(usize, &mut [T]) + Sync,
) {
    let row_len = row_len.max(1);
    let rows = out.len() / row_len;
    if !worth_splitting(out.len()) || rows < 2 {
        kernel(0, out);
    } else {
        let rows_per_block = (CHUNK / row_len).max(1).min(rows.div_ceil(8).max(1));
        out.par_chunks_mut(rows_per_block * row_len)
            .enumerate()
            .for_each(|(b, block)| kernel(b * rows_per_block, block));
    }
}
