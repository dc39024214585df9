//! Helpers every test module may use: evenly spaced parameters, point comparisons, a dense
//! linear solver (the slow, obviously correct reference for the library's banded and FFT
//! solves) and a seeded random source. Each existed once per test file before; one copy now.

use karkas::Point;

/// Parameters of `n` evenly spaced samples in `[a, b]`, ends included.
pub fn linspace(a: f64, b: f64, n: usize) -> Vec<f64> {
    (0..n)
        .map(|k| a + (b - a) * k as f64 / (n - 1) as f64)
        .collect()
}

/// Largest absolute coordinate over `pts` (at least 1).
pub fn max_abs<const D: usize>(pts: &[Point<D>]) -> f64 {
    pts.iter().fold(1.0, |m, p| m.max(p.max_abs()))
}

/// Asserts `|a - b|_max <= tol`.
#[track_caller]
pub fn assert_near<const D: usize>(a: Point<D>, b: Point<D>, tol: f64, what: &str) {
    let e = (a - b).max_abs();
    assert!(
        e <= tol,
        "{what}: {a:?} vs {b:?}, difference {e:e} > tolerance {tol:e}"
    );
}

/// Dense Gaussian elimination with partial pivoting; `b` holds one right-hand side per
/// column (`b[row][col]`). The slow, obviously correct reference for the banded solves.
pub fn dense_solve(mut a: Vec<Vec<f64>>, mut b: Vec<Vec<f64>>) -> Vec<Vec<f64>> {
    let n = a.len();
    for c in 0..n {
        let p = (c..n)
            .max_by(|&i, &j| a[i][c].abs().total_cmp(&a[j][c].abs()))
            .unwrap();
        a.swap(c, p);
        b.swap(c, p);
        assert!(a[c][c].abs() > 1e-12, "singular dense system");
        let (top, rest) = a.split_at_mut(c + 1);
        let (btop, brest) = b.split_at_mut(c + 1);
        let (pivot, bpivot) = (&top[c], &btop[c]);
        for (row, brow) in rest.iter_mut().zip(brest.iter_mut()) {
            let f = row[c] / pivot[c];
            if f == 0.0 {
                continue;
            }
            for (x, p) in row[c..].iter_mut().zip(&pivot[c..]) {
                *x -= f * p;
            }
            for (x, p) in brow.iter_mut().zip(bpivot) {
                *x -= f * p;
            }
        }
    }
    let m = b[0].len();
    let mut x = vec![vec![0.0; m]; n];
    for r in (0..n).rev() {
        for col in 0..m {
            let s: f64 = (r + 1..n).map(|k| a[r][k] * x[k][col]).sum();
            x[r][col] = (b[r][col] - s) / a[r][r];
        }
    }
    x
}

/// [`dense_solve`] for a single right-hand side.
pub fn dense_solve_vector(a: Vec<Vec<f64>>, b: Vec<f64>) -> Vec<f64> {
    let columns = b.into_iter().map(|v| vec![v]).collect();
    dense_solve(a, columns).into_iter().map(|x| x[0]).collect()
}

/// A xorshift generator with a fixed seed: reproducible "random" data without a dependency.
pub struct Rng(u64);

impl Rng {
    /// The generator started from `seed` (zero, a fixed point of xorshift, becomes one).
    pub fn new(seed: u64) -> Self {
        Rng(seed.max(1))
    }

    /// The next 53 random bits.
    fn bits(&mut self) -> u64 {
        self.0 ^= self.0 << 13;
        self.0 ^= self.0 >> 7;
        self.0 ^= self.0 << 17;
        self.0 >> 11
    }

    /// Uniform in `[0, 1)`.
    pub fn uniform(&mut self) -> f64 {
        self.bits() as f64 / (1u64 << 53) as f64
    }

    /// Uniform in `[-1, 1)`.
    pub fn signed(&mut self) -> f64 {
        self.bits() as f64 / (1u64 << 52) as f64 - 1.0
    }

    /// Standard normal (Box–Muller).
    pub fn normal(&mut self) -> f64 {
        let u = self.uniform().max(1e-300);
        let v = self.uniform();
        (-2.0 * u.ln()).sqrt() * (2.0 * std::f64::consts::PI * v).cos()
    }

    /// A point with coordinates uniform in `[-1, 1)`.
    pub fn point<const D: usize>(&mut self) -> Point<D> {
        let mut p = Point::ZERO;
        for c in 0..D {
            p[c] = self.signed();
        }
        p
    }

    /// `count` points of [`Rng::point`].
    pub fn points<const D: usize>(&mut self, count: usize) -> Vec<Point<D>> {
        (0..count).map(|_| self.point()).collect()
    }
}

/// The nearest distance by sampling `n` parameters and refining the best by golden section.
pub fn nearest_by_sampling<C: karkas::Curve<2>>(c: &C, q: karkas::Point2, n: usize) -> f64 {
    let d = c.domain();
    let mut best = (f64::INFINITY, 0.0);
    for k in 0..=n {
        let t = d.start + d.length() * k as f64 / n as f64;
        let dist = c.eval(t).distance(q);
        if dist < best.0 {
            best = (dist, t);
        }
    }
    let h = d.length() / n as f64;
    let (mut lo, mut hi) = ((best.1 - h).max(d.start), (best.1 + h).min(d.end));
    let g = 0.5 * (5f64.sqrt() - 1.0);
    for _ in 0..200 {
        let (x1, x2) = (hi - g * (hi - lo), lo + g * (hi - lo));
        if c.eval(x1).distance(q) < c.eval(x2).distance(q) {
            hi = x2;
        } else {
            lo = x1;
        }
    }
    best.0.min(c.eval(0.5 * (lo + hi)).distance(q))
}

/// Pavlov's hydrofoil profile (data/hydrofoil-profile.csv, the paper's table): 20 sparse
/// points whose polygon crosses itself.
pub fn hydrofoil() -> Vec<karkas::Point2> {
    let path = concat!(
        env!("CARGO_MANIFEST_DIR"),
        "/../../data/hydrofoil-profile.csv"
    );
    let text = std::fs::read_to_string(path).unwrap();
    let points: Vec<karkas::Point2> = text
        .lines()
        .filter(|l| !l.starts_with('#') && !l.starts_with('x'))
        .map(|l| {
            let v: Vec<f64> = l.split(',').map(|s| s.trim().parse().unwrap()).collect();
            karkas::Point2::new([v[0], v[1]])
        })
        .collect();
    assert_eq!(points.len(), 20, "{path}");
    points
}
