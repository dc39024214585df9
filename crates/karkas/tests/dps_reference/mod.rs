//! Slow, independent references for the discrete periodic spline tests: the B-spline by the
//! seed's definition (explicit hat, cyclic convolution), a dense linear solver, the roughness
//! `sum ||Delta^r x||^2`, and a fixed-seed random generator.

#![allow(dead_code)]

use karkas::Point;

/// `Q_1(j)`, `j` in `0..N`, exactly as printed in seed 002, §1.
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

/// Solves the dense system `a x = b` by Gaussian elimination with partial pivoting (in place).
pub fn dense_solve(mut a: Vec<Vec<f64>>, mut b: Vec<f64>) -> Vec<f64> {
    let size = b.len();
    for col in 0..size {
        let pivot = (col..size)
            .max_by(|&x, &y| a[x][col].abs().total_cmp(&a[y][col].abs()))
            .unwrap();
        a.swap(col, pivot);
        b.swap(col, pivot);
        let (upper, lower) = a.split_at_mut(col + 1);
        let pivot_row = &upper[col];
        for (offset, row) in lower.iter_mut().enumerate() {
            let f = row[col] / pivot_row[col];
            for (x, p) in row[col..].iter_mut().zip(&pivot_row[col..]) {
                *x -= f * p;
            }
            b[col + 1 + offset] -= f * b[col];
        }
    }
    let mut x = vec![0.0; size];
    for row in (0..size).rev() {
        let s: f64 = (row + 1..size).map(|k| a[row][k] * x[k]).sum();
        x[row] = (b[row] - s) / a[row][row];
    }
    x
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

/// A small xorshift generator with a fixed seed: reproducible "random" data without a
/// dependency.
pub struct Rng(u64);

impl Rng {
    pub fn new(seed: u64) -> Rng {
        Rng(seed.max(1))
    }

    /// Uniform in `[-1, 1)`.
    pub fn next(&mut self) -> f64 {
        self.0 ^= self.0 << 13;
        self.0 ^= self.0 >> 7;
        self.0 ^= self.0 << 17;
        (self.0 >> 11) as f64 / (1u64 << 52) as f64 - 1.0
    }

    pub fn point<const D: usize>(&mut self) -> Point<D> {
        let mut p = Point::ZERO;
        for c in 0..D {
            p[c] = self.next();
        }
        p
    }

    pub fn points<const D: usize>(&mut self, count: usize) -> Vec<Point<D>> {
        (0..count).map(|_| self.point()).collect()
    }
}
