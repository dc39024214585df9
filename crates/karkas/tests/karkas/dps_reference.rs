//! Slow, independent references for the discrete periodic spline tests: the B-spline by the
//! paper's definition (explicit hat, cyclic convolution) and the roughness
//! `sum ||Delta^r x||^2`.

use karkas::Point;

/// `Q_1(j)`, `j` in `0..N`, exactly as printed in Malozemov et al.'s §1.
pub fn hat(m: usize, n: usize, j: usize) -> f64 {
    let (jf, nf, mf) = (j as f64, n as f64, m as f64);
    let big_n = m * n;
    if j < n {
        1.0 - jf / nf
    } else if j <= big_n - n {
        0.0
    } else {
        jf / nf - mf + 1.0
    }
}

/// `Q_r(0..N)` by the definition: `Q_v(j) = (1/n) sum_k Q_1(k) Q_{v-1}(j - k)`, `O(r N^2)`.
pub fn bspline_by_convolution(m: usize, n: usize, r: usize) -> Vec<f64> {
    let big_n = m * n;
    let q1: Vec<f64> = (0..big_n).map(|j| hat(m, n, j)).collect();
    let mut q = q1.clone();
    for _ in 1..r {
        q = (0..big_n)
            .map(|j| {
                (0..big_n)
                    .map(|k| q1[k] * q[(j + big_n - k) % big_n])
                    .sum::<f64>()
                    / n as f64
            })
            .collect();
    }
    q
}

/// `S(j) = sum_p a_p Q(j - p n)` directly from a table of `Q` on `0..N`.
pub fn spline_by_definition<const D: usize>(
    q: &[f64],
    poles: &[Point<D>],
    n: usize,
) -> Vec<Point<D>> {
    let big_n = q.len();
    (0..big_n)
        .map(|j| {
            poles.iter().enumerate().fold(Point::ZERO, |s, (p, a)| {
                s.add_scaled(q[(j + big_n - (p * n) % big_n) % big_n], *a)
            })
        })
        .collect()
}

/// The periodic forward difference of order `r`: `(Delta^r x)(j)`.
pub fn difference<const D: usize>(x: &[Point<D>], r: usize) -> Vec<Point<D>> {
    let mut d = x.to_vec();
    let len = d.len();
    for _ in 0..r {
        d = (0..len).map(|j| d[(j + 1) % len] - d[j]).collect();
    }
    d
}

/// `sum_j ||Delta^r x(j)||^2`, periodic.
pub fn roughness<const D: usize>(x: &[Point<D>], r: usize) -> f64 {
    difference(x, r).iter().map(|p| p.norm_sq()).sum()
}

/// `(Delta^r)^T Delta^r x`: half the gradient of [`roughness`].
pub fn roughness_gradient<const D: usize>(x: &[Point<D>], r: usize) -> Vec<Point<D>> {
    let mut d = difference(x, r);
    let len = d.len();
    // The transpose of the forward difference is minus the backward difference.
    for _ in 0..r {
        d = (0..len).map(|j| d[(j + len - 1) % len] - d[j]).collect();
    }
    d
}
