//! Counting sign changes of sampled values with a noise threshold: the curvature extrema
//! (sign changes of `dκ/ds`) and inflections (sign changes of the signed curvature) of
//! [`fairness`](super::fairness).

/// The number of sign changes in `values` (in order along a curve; cyclic when `cyclic`,
/// the last value followed by the first), where values with `|x| <= threshold` (or NaN)
/// count as zero and are skipped: a run `+, 0, 0, -` is one change, `+, 0, +` none.
pub(crate) fn sign_changes(
    values: impl IntoIterator<Item = f64>,
    threshold: f64,
    cyclic: bool,
) -> usize {
    let mut first: Option<bool> = None;
    let mut last: Option<bool> = None;
    let mut count = 0;
    for x in values {
        if x.is_nan() || x.abs() <= threshold {
            continue;
        }
        let positive = x > 0.0;
        if first.is_none() {
            first = Some(positive);
        }
        if let Some(previous) = last {
            if previous != positive {
                count += 1;
            }
        }
        last = Some(positive);
    }
    if cyclic {
        if let (Some(a), Some(b)) = (first, last) {
            if a != b {
                count += 1;
            }
        }
    }
    count
}

/// The number of runs of values with `|x| <= threshold` that lie strictly between values
/// above it (the zeros of a non-negative function such as the curvature in 3-D; cyclic as in
/// [`sign_changes`]).
pub(crate) fn interior_zero_runs(values: &[f64], threshold: f64, cyclic: bool) -> usize {
    let is_zero = |x: f64| !x.is_nan() && x.abs() <= threshold;
    let Some(start) = values.iter().position(|&x| !x.is_nan() && !is_zero(x)) else {
        return 0;
    };
    let n = values.len();
    let span = if cyclic { n } else { n - start };
    let (mut count, mut in_run) = (0, false);
    for i in 1..=span {
        if !cyclic && start + i >= n {
            break;
        }
        let x = values[(start + i) % n];
        if x.is_nan() {
            continue;
        }
        if is_zero(x) {
            in_run = true;
        } else {
            if in_run {
                count += 1;
            }
            in_run = false;
        }
    }
    count
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn zeros_inside_a_change_count_once_and_touches_not_at_all() {
        assert_eq!(sign_changes([1.0, 0.0, 0.0, -1.0], 0.0, false), 1);
        assert_eq!(sign_changes([1.0, 1e-12, 2.0], 1e-9, false), 0);
        assert_eq!(sign_changes([1.0, -1e-12, 2.0], 1e-9, false), 0);
        assert_eq!(sign_changes([1.0, -1.0, 1.0, -1.0], 0.0, false), 3);
        assert_eq!(sign_changes([1.0, -1.0, 1.0, -1.0], 0.0, true), 4);
        assert_eq!(sign_changes([f64::NAN, 1.0, f64::NAN, -1.0], 0.0, false), 1);
    }

    #[test]
    fn zero_runs_between_positive_values() {
        assert_eq!(
            interior_zero_runs(&[0.0, 1.0, 0.0, 0.0, 1.0, 0.0], 1e-9, false),
            1
        );
        assert_eq!(
            interior_zero_runs(&[0.0, 1.0, 0.0, 0.0, 1.0, 0.0], 1e-9, true),
            2
        );
        assert_eq!(interior_zero_runs(&[0.0, 0.0], 1e-9, true), 0);
    }
}
