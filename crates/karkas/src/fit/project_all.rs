//! Every data point projected onto the spline of a [`State`] from its previous foot point
//! ([`foot_point_near`]), in parallel chunks, with the squared distances refreshed; the
//! projection can be abandoned as soon as the distances exceed a budget. With
//! [`Projection::ordered`] the parameters are then made non-decreasing along the points
//! ([`isotonic`]; with many points [`isotonic_in_parts`], in parallel) and the distances of
//! the points moved are refreshed. Free points are searched two at a time
//! ([`foot_point_pair`]), which overlaps their chains of dependent evaluations.

use super::order::{isotonic, isotonic_in_parts};
use super::power::PowerForm;
use super::problem::{Projection, State};
use super::project::{foot_point_near, foot_point_pair};
use crate::core::parallel::PARALLEL_THRESHOLD;
use crate::Point;
use rayon::prelude::*;
use std::sync::atomic::{AtomicBool, AtomicU64, Ordering};

/// Re-projects every inner point of `points` onto `state.spline` from its current parameter
/// unless the projection holds them (the ends keep theirs), and refreshes the squared
/// distances; `form` is scratch space for the power form of the spline (same knots).
pub(crate) fn project<const D: usize>(
    points: &[Point<D>],
    projection: Projection,
    state: &mut State<D>,
    form: &mut PowerForm<D>,
) {
    project_within(points, projection, state, form, f64::INFINITY);
}

/// A chunk of the projection: its index, and its parameters and squared distances.
type ChunkSlices<'s> = (usize, (&'s mut [f64], &'s mut [f64]));

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
    projection: Projection,
    state: &mut State<D>,
    form: &mut PowerForm<D>,
    budget: f64,
) -> bool {
    let finished = project_each(points, projection, state, form, budget);
    if !finished || !projection.ordered {
        return finished;
    }
    order_parameters(points, projection, state, form) <= budget
}

/// Makes the parameters of `state` non-decreasing ([`isotonic`], weighted by the curvature of
/// each point's squared distance at its foot point) and refreshes the distances of the points
/// moved; returns the new sum of squared distances.
fn order_parameters<const D: usize>(
    points: &[Point<D>],
    projection: Projection,
    state: &mut State<D>,
    form: &PowerForm<D>,
) -> f64 {
    let n = points.len();
    if state.params.windows(2).all(|pair| pair[0] <= pair[1]) {
        return state.data_term();
    }
    let order = &mut state.order;
    order.previous.clear();
    order.previous.extend_from_slice(&state.params);
    let previous = &order.previous;
    // The curvature of a point's squared distance at its foot point (held parameters stay).
    let weight = |i: usize| {
        if !projection.is_free(i, n) {
            return f64::MAX;
        }
        let t = previous[i];
        let [p, d1, d2] = form.jet(form.piece_near(t, 0), t);
        let speed_sq = d1.norm_sq();
        (speed_sq + (p - points[i]).dot(d2))
            .max(1e-3 * speed_sq)
            .max(f64::MIN_POSITIVE)
    };
    let parallel = n >= PARALLEL_THRESHOLD;
    if parallel {
        isotonic_in_parts(&mut state.params, weight, &mut order.parts);
    } else {
        isotonic(&mut state.params, weight, &mut order.blocks);
    }
    // The distance of a point whose parameter moved, at its new parameter.
    type Moved<'s> = (usize, ((&'s f64, &'s f64), &'s mut f64));
    let refresh = |(i, ((t, old), d)): Moved<'_>| {
        if t != old {
            *d = form
                .point(form.piece_near(*t, 0), *t)
                .distance_sq(points[i]);
        }
    };
    let (params, previous) = (&state.params, &state.order.previous);
    let dist_sq = &mut state.dist_sq;
    if parallel {
        params
            .par_iter()
            .zip(previous)
            .zip(dist_sq.par_iter_mut())
            .enumerate()
            .for_each(refresh);
    } else {
        params
            .iter()
            .zip(previous)
            .zip(dist_sq.iter_mut())
            .enumerate()
            .for_each(refresh);
    }
    // Released: the states of a fit would otherwise keep one each.
    state.order.previous = Vec::new();
    state.data_term()
}

/// Projects the point of chunk index `j` (point `first + j`), or it and the next as a pair
/// of free points (see `foot_point_pair`), adding their squared distances to `sum`; returns
/// how many were projected. `piece` is a hint for the piece of the point's parameter (the
/// previous point's piece), updated to the piece of the last point projected.
fn project_next<const D: usize>(
    form: &PowerForm<D>,
    points: &[Point<D>],
    projection: Projection,
    (first, j): (usize, usize),
    (params, dist_sq, piece): (&mut [f64], &mut [f64], &mut usize),
    sum: &mut f64,
) -> usize {
    let (n, len, i) = (points.len(), params.len(), first + j);
    if j + 1 < len && projection.is_free(i, n) && projection.is_free(i + 1, n) {
        let (mut pa, mut pb) = (*piece, *piece);
        let [a, b] = foot_point_pair(
            form,
            [points[i], points[i + 1]],
            [params[j], params[j + 1]],
            [&mut pa, &mut pb],
        );
        *piece = pb;
        (params[j], dist_sq[j]) = a;
        (params[j + 1], dist_sq[j + 1]) = b;
        *sum += a.1;
        *sum += b.1;
        return 2;
    }
    let r = points[i];
    if projection.is_free(i, n) {
        (params[j], dist_sq[j]) = foot_point_near(form, r, params[j], piece);
    } else {
        *piece = form.piece_near(params[j], *piece);
        dist_sq[j] = form.point(*piece, params[j]).distance_sq(r);
    }
    *sum += dist_sq[j];
    1
}

/// Lock-free `done += sum` on the bits of an `f64`.
fn add_to(done: &AtomicU64, sum: f64) {
    let mut old = done.load(Ordering::Relaxed);
    while let Err(now) = done.compare_exchange_weak(
        old,
        (f64::from_bits(old) + sum).to_bits(),
        Ordering::Relaxed,
        Ordering::Relaxed,
    ) {
        old = now;
    }
}

/// [`project_within`] without the ordering.
fn project_each<const D: usize>(
    points: &[Point<D>],
    projection: Projection,
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
    let chunk = |(c, (params, dist_sq)): ChunkSlices<'_>| {
        let first = c * PROJECTION_CHUNK;
        let len = params.len();
        let mut sum = 0.0;
        let mut j = 0;
        let mut piece = 0;
        while j < len {
            let slices = (&mut *params, &mut *dist_sq, &mut piece);
            let taken = project_next(form, points, projection, (first, j), slices, &mut sum);
            j += taken;
            if j % 64 < taken
                && (abandoned.load(Ordering::Relaxed)
                    || sum + f64::from_bits(done.load(Ordering::Relaxed)) > limit)
            {
                abandoned.store(true, Ordering::Relaxed);
                return None;
            }
        }
        add_to(&done, sum);
        Some(sum)
    };
    if n < PARALLEL_THRESHOLD {
        let chunks = state
            .params
            .chunks_mut(PROJECTION_CHUNK)
            .zip(state.dist_sq.chunks_mut(PROJECTION_CHUNK))
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
            .enumerate()
            .map(chunk)
            .collect();
        sums.iter()
            .try_fold(0.0, |total, sum| sum.map(|sum| total + sum))
            .is_some_and(|total| total <= budget)
    }
}
