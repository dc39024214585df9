//! What the curve reader notices about the order of the points it read, said in one line
//! each: a first column that counts the rows, and points far out of their order along the
//! curve.
//!
//! - **A counting column**: a file without a header (or whose header names no columns and is
//!   read in order) whose first column is `0, 1, 2, ...` or `1, 2, 3, ...` holds row numbers,
//!   not x: the points are read as they are, and the warning names `--columns` to read the
//!   others.
//! - **Points out of order**: along a curve, consecutive points lie much closer together than
//!   points a quarter (or a seventh, or a third) of the list apart; in a shuffled list they
//!   lie as far apart as any two. The check compares the median distance of consecutive points
//!   with the median distance at those three lags (the largest of the three ratios, so that a
//!   curve run through several times, whose points come back near themselves after one lap,
//!   is not taken for a shuffled one) and warns when the ratio is below
//!   `OUT_OF_ORDER_RATIO` (2). On ordered airfoil-like contours of 16 to 10^4 points, noisy up to
//!   a quarter of their thickness, the ratio is at least 3.3; on shuffled ones of 20 points
//!   or more it is below 2 in 99 cases of 100, and within 1.1 of 1 from 1000 points.
//!
//! Cost: one pass over the points for the counting column, and at most [`SAMPLES`] distances
//! per lag (evenly spread over the list) and their medians for the order: a few milliseconds
//! for 10^7 points.

/// Below this ratio of the median distance at a long lag to that of consecutive points, the
/// points are taken for far out of order.
const OUT_OF_ORDER_RATIO: f64 = 2.0;

/// Fewer points than this are not checked for their order (the medians of shorter lists
/// vary too much).
const MIN_POINTS_FOR_ORDER: usize = 20;

/// The most distances a median is taken over.
const SAMPLES: usize = 1 << 16;

/// The warning about a first column that counts the rows (`0, 1, 2, ...` or `1, 2, 3, ...`)
/// of `n` points in space read from the first three columns of a file (`first(k)` the first
/// column of row `k`), if it does; `None` otherwise or for fewer than 4 points. (In a file of
/// two columns a counting first column is a graph over whole numbers, and there is nothing
/// else to read.)
pub(crate) fn counting_column(n: usize, first: impl Fn(usize) -> f64) -> Option<String> {
    if n < 4 {
        return None;
    }
    let start = first(0);
    if start != 0.0 && start != 1.0 {
        return None;
    }
    if !(0..n).all(|k| first(k) == start + k as f64) {
        return None;
    }
    Some(format!(
        "the first column counts {}, {}, {}, ... (row numbers?) and is read as x of points in \
         space: give --columns 2,3 (columns=(2, 3) in Python) to read planar points from the \
         other two columns",
        start,
        start + 1.0,
        start + 2.0,
    ))
}

/// The warning about `n` points (coordinate `c` of point `k` being `coord(k, c)`, `dim`
/// coordinates) that lie far out of their order along the curve, if they do (see the
/// [module docs](self)).
pub(crate) fn out_of_order(
    n: usize,
    dim: usize,
    coord: impl Fn(usize, usize) -> f64,
) -> Option<String> {
    if n < MIN_POINTS_FOR_ORDER {
        return None;
    }
    let distance = |a: usize, b: usize| {
        // Scaled by the larger coordinate so that 1e-150 and 1e150 data compare alike.
        let scale = (0..dim)
            .map(|c| coord(a, c).abs().max(coord(b, c).abs()))
            .fold(0.0, f64::max);
        if scale == 0.0 {
            return 0.0;
        }
        let sum: f64 = (0..dim)
            .map(|c| ((coord(a, c) - coord(b, c)) / scale).powi(2))
            .sum();
        sum.sqrt() * scale
    };
    let median_at = |lag: usize| {
        let pairs = n - lag;
        let step = pairs.div_ceil(SAMPLES).max(1);
        let mut d: Vec<f64> = (0..pairs)
            .step_by(step)
            .map(|k| distance(k, k + lag))
            .collect();
        let mid = d.len() / 2;
        d.select_nth_unstable_by(mid, f64::total_cmp);
        d[mid]
    };
    let near = median_at(1);
    if !(near > 0.0 && near.is_finite()) {
        return None;
    }
    let far = [n / 7, n / 4, n / 3]
        .into_iter()
        .map(median_at)
        .fold(0.0, f64::max);
    let ratio = far / near;
    (ratio < OUT_OF_ORDER_RATIO).then(|| {
        format!(
            "the points look far out of order: consecutive points lie {near:.3e} apart (median), \
             about as far as points a quarter of the list apart ({far:.3e}); a curve takes the \
             points in the order given, so sort them along the curve"
        )
    })
}

#[cfg(test)]
mod tests {
    use super::*;

    /// `n` points of an airfoil-like closed contour, from a deterministic generator when
    /// `shuffled`.
    fn contour(n: usize, shuffled: bool) -> Vec<[f64; 2]> {
        let mut points: Vec<[f64; 2]> = (0..n)
            .map(|k| {
                let t = std::f64::consts::TAU * k as f64 / (n - 1) as f64;
                let x = 0.5 + 0.5 * t.cos();
                [x, 0.24 * t.sin() * (1.0 - x).sqrt()]
            })
            .collect();
        if shuffled {
            let mut state: u64 = 0x9e37_79b9_7f4a_7c15;
            for k in (1..n).rev() {
                state ^= state << 13;
                state ^= state >> 7;
                state ^= state << 17;
                points.swap(k, (state % (k as u64 + 1)) as usize);
            }
        }
        points
    }

    #[test]
    fn shuffled_points_are_noticed_and_ordered_ones_are_not() {
        for n in [20, 61, 300, 10_000] {
            let ordered = contour(n, false);
            assert!(out_of_order(n, 2, |k, c| ordered[k][c]).is_none(), "{n}");
            let shuffled = contour(n, true);
            let warning = out_of_order(n, 2, |k, c| shuffled[k][c]);
            assert!(warning.is_some_and(|w| w.contains("out of order")), "{n}");
        }
        // A closed curve run through four times comes back near itself after a quarter.
        let laps: Vec<[f64; 2]> = (0..400)
            .map(|k| {
                let t = std::f64::consts::TAU * k as f64 / 100.0;
                [t.cos(), t.sin()]
            })
            .collect();
        assert!(out_of_order(400, 2, |k, c| laps[k][c]).is_none());
        // Too few points, or all at one place: nothing said.
        assert!(out_of_order(10, 2, |_, _| 0.0).is_none());
        assert!(out_of_order(100, 2, |_, _| 1.0).is_none());
    }

    #[test]
    fn a_counting_first_column_is_noticed() {
        let index = |k: usize| k as f64;
        let warning = counting_column(10, index).unwrap();
        assert!(warning.contains("counts 0, 1, 2"), "{warning}");
        assert!(warning.contains("--columns 2,3"), "{warning}");
        assert!(counting_column(10, |k| 1.0 + k as f64).is_some());
        assert!(counting_column(10, |k| 2.0 + k as f64).is_none());
        assert!(counting_column(10, |k| 0.5 * k as f64).is_none());
        assert!(counting_column(3, index).is_none());
    }
}
