//! The evaluation recurrence of Malozemov et al.'s §1 (docs/methods.md §3): `S_1` is the broken line through
//! the poles, and `S_v = (1/n) Q_1 (*) S_{v-1}` (cyclic convolution) raises the order by one.
//!
//! The hat `Q_1` is a box convolved with a box: with `b(j) = 1` for `j` in `0..n-1`,
//! `n Q_1(j) = sum_k b(k) b(k - j)`, so
//!
//! ```text
//! (1/n) Q_1 (*) x (j) = (1/n^2) sum_{k=j}^{j+n-1} y(k),   y(k) = sum_{i=k-n+1}^{k} x(i),
//! ```
//!
//! two moving sums of width `n`. Each is done in place in one pass: the first runs downwards
//! (it reads only values below the one it writes), the second upwards (it reads only values
//! above), and the `n - 1` values a pass needs across the wrap of the period are copied aside
//! first. A moving sum updated by one addition and one subtraction per step accumulates
//! rounding over its whole run, so every pass restarts its sum from scratch at each node `p n`:
//! the rounding error stays that of a sum of `n` terms, at the cost of one more addition per
//! value. One order costs `O(N)` (about 6 additions of points per value), so `S_r` costs
//! `O(r N)`, never `O(N n)`.

use crate::Point;

/// Writes `S_1(j) = sum_p a_p Q_1(j - p n)` for `j` in `0..N` into `out` (`N = m n`, `m`
/// poles): on `p n + t`, `t < n`, it is `a_p + (t/n) (a_{p+1} - a_p)`, poles `m`-periodic.
pub(crate) fn broken_line<const D: usize>(poles: &[Point<D>], n: usize, out: &mut [Point<D>]) {
    let m = poles.len();
    debug_assert_eq!(out.len(), m * n);
    let step = 1.0 / n as f64;
    for (p, block) in out.chunks_exact_mut(n).enumerate() {
        let a = poles[p];
        let next = poles[if p + 1 == m { 0 } else { p + 1 }];
        let delta = next - a;
        for (t, value) in block.iter_mut().enumerate() {
            *value = a.add_scaled(t as f64 * step, delta);
        }
    }
}

/// Replaces one period `values` (length `N = m n`, `m >= 1`, `n >= 2`) by
/// `(1/n) Q_1 (*) values`. `wrap` is scratch for `n - 1` points (resized here, so a buffer
/// kept between calls is allocated once).
pub(crate) fn raise_order<const D: usize>(
    values: &mut [Point<D>],
    n: usize,
    wrap: &mut Vec<Point<D>>,
) {
    let len = values.len();
    debug_assert!(n >= 2 && len.is_multiple_of(n) && len >= n);
    backward_window_sums(values, n, wrap);
    forward_window_sums(values, n, 1.0 / (n as f64 * n as f64), wrap);
}

/// `values[j] <- sum_{k=j-n+1}^{j} values[k]` (indices modulo `N`), in place, downwards.
fn backward_window_sums<const D: usize>(
    values: &mut [Point<D>],
    n: usize,
    tail: &mut Vec<Point<D>>,
) {
    let len = values.len();
    // tail[i] = x(N - n + 1 + i): what the windows of j < n - 1 reach across the wrap.
    tail.clear();
    tail.extend_from_slice(&values[len - (n - 1)..]);
    for block in (0..len / n).rev() {
        let start = block * n;
        let top = start + n - 1;
        // The window of the block's top value lies inside the block.
        let mut sum = Point::ZERO;
        for v in &values[start..=top] {
            sum += *v;
        }
        let mut above = values[top];
        values[top] = sum;
        for j in (start..top).rev() {
            // Slide from [j - n + 2, j + 1] to [j - n + 1, j]; x(j + 1) is `above`.
            let entering = if j + 1 >= n {
                values[j + 1 - n]
            } else {
                tail[j]
            };
            sum += entering;
            sum -= above;
            above = values[j];
            values[j] = sum;
        }
    }
}

/// `values[j] <- scale * sum_{k=j}^{j+n-1} values[k]` (indices modulo `N`), in place, upwards.
fn forward_window_sums<const D: usize>(
    values: &mut [Point<D>],
    n: usize,
    scale: f64,
    head: &mut Vec<Point<D>>,
) {
    let len = values.len();
    // head[i] = y(i): what the windows of j > N - n reach across the wrap.
    head.clear();
    head.extend_from_slice(&values[..n - 1]);
    for block in 0..len / n {
        let start = block * n;
        let last = start + n - 1;
        // The window of the block's first value lies inside the block.
        let mut sum = Point::ZERO;
        for v in &values[start..=last] {
            sum += *v;
        }
        let mut below = values[start];
        values[start] = sum * scale;
        for j in start + 1..=last {
            // Slide from [j - 1, j + n - 2] to [j, j + n - 1]; y(j - 1) is `below`.
            let k = j + n - 1;
            let entering = if k < len { values[k] } else { head[k - len] };
            sum += entering;
            sum -= below;
            below = values[j];
            values[j] = sum * scale;
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The moving sums against their definition, for every wrap case.
    #[test]
    fn window_sums_match_their_definition() {
        for (m, n) in [(1, 2), (2, 2), (3, 4), (2, 7), (5, 3)] {
            let len = m * n;
            let x: Vec<Point<1>> = (0..len)
                .map(|j| Point([((j * 7919) % 13) as f64 - 6.0]))
                .collect();
            let at = |k: isize| x[k.rem_euclid(len as isize) as usize][0];
            let mut scratch = Vec::new();
            let mut back = x.clone();
            backward_window_sums(&mut back, n, &mut scratch);
            let mut fwd = x.clone();
            forward_window_sums(&mut fwd, n, 0.5, &mut scratch);
            for j in 0..len as isize {
                let b: f64 = (j - n as isize + 1..=j).map(at).sum();
                let f: f64 = (j..j + n as isize).map(at).sum();
                assert_eq!(back[j as usize][0], b, "backward m={m} n={n} j={j}");
                assert_eq!(fwd[j as usize][0], 0.5 * f, "forward m={m} n={n} j={j}");
            }
        }
    }
}
