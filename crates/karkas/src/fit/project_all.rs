//! Every data point projected onto the spline of a [`State`] from its previous foot point
//! ([`foot_point_near`]), in parallel chunks, with the squared distances refreshed; the
//! projection can be abandoned as soon as the distances exceed a budget.

use super::power::PowerForm;
use super::problem::State;
use super::project::foot_point_near;
use crate::core::parallel::PARALLEL_THRESHOLD;
use crate::Point;
use rayon::prelude::*;
use std::sync::atomic::{AtomicBool, AtomicU64, Ordering};

/// Re-projects every inner point of `points` onto `state.spline` from its current parameter
/// when `foot_points` (the ends keep theirs), and refreshes the squared distances; `form` is
/// scratch space for the power form of the spline (same knots).
pub(crate) fn project<const D: usize>(
    points: &[Point<D>],
    foot_points: bool,
    state: &mut State<D>,
    form: &mut PowerForm<D>,
) {
    project_within(points, foot_points, state, form, f64::INFINITY);
}

/// A chunk of the projection: its index, and its parameters, squared distances and pieces.
type ChunkSlices<'s> = (usize, ((&'s mut [f64], &'s mut [f64]), &'s mut [usize]));

/// Points per chunk of the projection: chunks are projected in parallel when there are
/// enough points (every point is projected on its own, from its own previous foot point).
const PROJECTION_CHUNK: usize = 1 << 12;

/// [`project`], abandoned (returning `false`) once the sum of the squared distances exceeds
/// `budget`.
///
/// The points are projected in chunks of [`PROJECTION_CHUNK`], in parallel above
/// [`PARALLEL_THRESHOLD`] points. A chunk gives up when its own sum plus those of the chunks
/// already done exceeds the budget by a margin larger than any rounding of the sum (the
/// distances are not negative, so the total exceeds it too); otherwise the total, summed in
/// chunk order, decides. So the result does not depend on the number of threads.
pub(crate) fn project_within<const D: usize>(
    points: &[Point<D>],
    foot_points: bool,
    state: &mut State<D>,
    form: &mut PowerForm<D>,
    budget: f64,
) -> bool {
    form.update(&state.spline);
    let form = &*form;
    let n = points.len();
    let limit = budget * (1.0 + 1e-6);
    // The sum of the chunks done (f64 bits), and whether one gave up.
    let done = AtomicU64::new(0f64.to_bits());
    let abandoned = AtomicBool::new(false);
    let chunk = |(c, ((params, dist_sq), piece)): ChunkSlices<'_>| {
        let first = c * PROJECTION_CHUNK;
        let mut sum = 0.0;
        for (j, ((t, d), piece)) in params.iter_mut().zip(dist_sq).zip(piece).enumerate() {
            let i = first + j;
            let r = points[i];
            if foot_points && i > 0 && i + 1 < n {
                (*t, *d) = foot_point_near(form, r, *t, piece);
            } else {
                *piece = form.piece_near(*t, *piece);
                *d = form.point(*piece, *t).distance_sq(r);
            }
            sum += *d;
            if j % 64 == 63
                && (abandoned.load(Ordering::Relaxed)
                    || sum + f64::from_bits(done.load(Ordering::Relaxed)) > limit)
            {
                abandoned.store(true, Ordering::Relaxed);
                return None;
            }
        }
        // Lock-free `done += sum`.
        let mut old = done.load(Ordering::Relaxed);
        while let Err(now) = done.compare_exchange_weak(
            old,
            (f64::from_bits(old) + sum).to_bits(),
            Ordering::Relaxed,
            Ordering::Relaxed,
        ) {
            old = now;
        }
        Some(sum)
    };
    if n < PARALLEL_THRESHOLD {
        let chunks = state
            .params
            .chunks_mut(PROJECTION_CHUNK)
            .zip(state.dist_sq.chunks_mut(PROJECTION_CHUNK))
            .zip(state.piece.chunks_mut(PROJECTION_CHUNK))
            .enumerate();
        let mut total = 0.0;
        for item in chunks {
            match chunk(item) {
                Some(sum) => total += sum,
                None => return false,
            }
        }
        total <= budget
    } else {
        let sums: Vec<Option<f64>> = state
            .params
            .par_chunks_mut(PROJECTION_CHUNK)
            .zip(state.dist_sq.par_chunks_mut(PROJECTION_CHUNK))
            .zip(state.piece.par_chunks_mut(PROJECTION_CHUNK))
            .enumerate()
            .map(chunk)
            .collect();
        sums.iter()
            .try_fold(0.0, |total, sum| sum.map(|sum| total + sum))
            .is_some_and(|total| total <= budget)
    }
}
