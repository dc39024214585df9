//! The reference kernel of docs/methods.md §1.1: exact binomials and rationals, double-double
//! evaluation of the exact monomial coefficients.

// ------------------------------------------------------------------------------------------
// Exact arithmetic
// ------------------------------------------------------------------------------------------

/// `C(n, k)` exactly, from Pascal's triangle (no intermediate overflow up to n = 128).
pub fn binom(n: usize, k: usize) -> u128 {
    static TABLE: std::sync::OnceLock<Vec<Vec<u128>>> = std::sync::OnceLock::new();
    let table = TABLE.get_or_init(|| {
        let mut rows = vec![vec![1u128]];
        for m in 1..=130 {
            let prev: &Vec<u128> = &rows[m - 1];
            let mut next = vec![1u128; m + 1];
            for j in 1..m {
                next[j] = prev[j - 1].saturating_add(prev[j]);
            }
            rows.push(next);
        }
        rows
    });
    assert!(n <= 128, "binomial table ends at 128");
    if k > n {
        0
    } else {
        table[n][k]
    }
}

fn gcd(mut a: i128, mut b: i128) -> i128 {
    a = a.abs();
    b = b.abs();
    while b != 0 {
        (a, b) = (b, a % b);
    }
    a
}

/// An exact rational `n / d` (`d > 0`, reduced); panics on overflow.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct Q {
    pub n: i128,
    pub d: i128,
}

impl Q {
    pub fn new(n: i128, d: i128) -> Q {
        assert!(d != 0);
        let g = gcd(n, d).max(1);
        let s = if d < 0 { -1 } else { 1 };
        Q {
            n: s * n / g,
            d: s * d / g,
        }
    }
    pub fn int(n: i128) -> Q {
        Q { n, d: 1 }
    }
    pub fn add(self, o: Q) -> Q {
        let g = gcd(self.d, o.d);
        let l = self.d / g;
        let n = self
            .n
            .checked_mul(o.d / g)
            .and_then(|a| o.n.checked_mul(l).and_then(|b| a.checked_add(b)))
            .expect("rational overflow");
        Q::new(n, l.checked_mul(o.d).expect("rational overflow"))
    }
    pub fn mul_int(self, m: i128) -> Q {
        self.try_mul_int(m).expect("rational overflow")
    }
    pub fn try_mul_int(self, m: i128) -> Option<Q> {
        let g = gcd(m, self.d).max(1);
        Some(Q::new(self.n.checked_mul(m / g)?, self.d / g))
    }
}

// ------------------------------------------------------------------------------------------
// Double-double evaluation (for polynomials with large alternating coefficients)
// ------------------------------------------------------------------------------------------

type Dd = (f64, f64);

fn two_sum(a: f64, b: f64) -> Dd {
    let s = a + b;
    let bb = s - a;
    (s, (a - (s - bb)) + (b - bb))
}

fn quick_two_sum(a: f64, b: f64) -> Dd {
    let s = a + b;
    (s, b - (s - a))
}

fn dd_mul_f64(a: Dd, x: f64) -> Dd {
    let p = a.0 * x;
    let e = a.0.mul_add(x, -p) + a.1 * x;
    quick_two_sum(p, e)
}

fn dd_add(a: Dd, b: Dd) -> Dd {
    let (s, e) = two_sum(a.0, b.0);
    quick_two_sum(s, e + a.1 + b.1)
}

fn dd_from_int(n: i128) -> Dd {
    let hi = n as f64;
    let lo = (n - hi as i128) as f64;
    (hi, lo)
}

// ------------------------------------------------------------------------------------------
// Reference kernel (§1.1)
// ------------------------------------------------------------------------------------------

/// The kernel of order L computed from the definitions of docs/methods.md §1.1.
pub struct RefKernel {
    pub l: usize,
    /// `eps_k`, k = 0..L (f64 from exact integers).
    pub eps: Vec<f64>,
    /// `d_L = C(2L, L) / 2^(2L+2)`, correctly rounded.
    pub d_l: f64,
    /// Exact monomial coefficients of `h` (index = power of xi), when they fit in i128.
    pub mono: Option<Vec<Q>>,
    /// Integer monomial coefficients of `h^(j)`, `j = 0..=2L` (empty for j < 2 or when the
    /// coefficients overflow i128).
    dcoef: Vec<Vec<i128>>,
    /// `max |h^(j)|` on [0, 1] (at least 1), j = 0..=2L+1, NaN where not computable.
    maxes: Vec<f64>,
}

impl RefKernel {
    pub fn new(l: usize) -> RefKernel {
        let eps = (0..=l)
            .map(|k| binom(l + k, k) as f64 / (l + k) as f64)
            .collect();
        let d_l = binom(2 * l, l) as f64 / 2f64.powi(2 * l as i32 + 2);
        let mono = (l <= 20).then(|| monomial_coeffs(l));
        let mut r = RefKernel {
            l,
            eps,
            d_l,
            mono,
            dcoef: Vec::new(),
            maxes: Vec::new(),
        };
        if r.mono.is_some() {
            r.dcoef = (0..=2 * l)
                .map(|j| {
                    if j < 2 {
                        return Vec::new();
                    }
                    let q = r.try_deriv_coeffs_q(j).unwrap_or_default();
                    q.iter()
                        .map(|q| {
                            assert_eq!(q.d, 1, "h^({j}) must have integer coefficients");
                            q.n
                        })
                        .collect()
                })
                .collect();
        }
        r.maxes = (0..=2 * l + 1)
            .map(|j| {
                if j <= 2 || j > 2 * l || r.has_exact(j) {
                    (0..=400)
                        .map(|s| r.dj(s as f64 / 400.0, j).abs())
                        .fold(1.0, f64::max)
                } else {
                    f64::NAN
                }
            })
            .collect();
        r
    }

    /// `h(xi) = xi^(L+1) sum_{k=0..L} eps_k (L-k) (1-xi)^k`, summed term by term.
    pub fn h(&self, xi: f64) -> f64 {
        let l = self.l;
        let s: f64 = (0..=l)
            .map(|k| self.eps[k] * (l - k) as f64 * (1.0 - xi).powi(k as i32))
            .sum();
        xi.powi(l as i32 + 1) * s
    }

    /// `h'(xi) = 2 I_xi(L, L) = 2 sum_{j=L..2L-1} C(2L-1, j) xi^j (1-xi)^(2L-1-j)`.
    pub fn h1(&self, xi: f64) -> f64 {
        let l = self.l;
        let n = 2 * l - 1;
        let s: f64 = (l..=n)
            .map(|j| binom(n, j) as f64 * xi.powi(j as i32) * (1.0 - xi).powi((n - j) as i32))
            .sum();
        2.0 * s
    }

    /// `h''(xi) = 2L C(2L-1, L) xi^(L-1) (1-xi)^(L-1)`.
    pub fn h2(&self, xi: f64) -> f64 {
        let l = self.l;
        2.0 * l as f64 * binom(2 * l - 1, l) as f64 * (xi * (1.0 - xi)).powi(l as i32 - 1)
    }

    /// Exact monomial coefficients of `h^(j)` (index = power of xi); `None` on overflow.
    fn try_deriv_coeffs_q(&self, j: usize) -> Option<Vec<Q>> {
        let mono = self.mono.as_ref()?;
        let mut out = Vec::new();
        for (n, c) in mono.iter().enumerate().skip(j) {
            let mut f: i128 = 1;
            for m in 0..j {
                f = f.checked_mul((n - m) as i128)?;
            }
            out.push(c.try_mul_int(f)?);
        }
        Some(out)
    }

    /// Exact monomial coefficients of `h^(j)` (index = power of xi).
    pub fn deriv_coeffs_q(&self, j: usize) -> Vec<Q> {
        self.try_deriv_coeffs_q(j)
            .expect("order too large for exact coefficients")
    }

    /// True when the exact coefficients of `h^(j)` are available (`2 <= j <= 2L`).
    pub fn has_exact(&self, j: usize) -> bool {
        self.dcoef.get(j).is_some_and(|c| !c.is_empty())
    }

    /// Exact integer monomial coefficients of `h^(j)`, `2 <= j <= 2L` (index = power of xi).
    pub fn deriv_coeffs(&self, j: usize) -> Vec<i128> {
        assert!(
            self.has_exact(j),
            "no exact coefficients for h^({j}), L = {}",
            self.l
        );
        self.dcoef[j].clone()
    }

    /// `h^(j)(xi)`: the closed forms for j <= 2, the exact monomial coefficients (evaluated
    /// in double-double arithmetic) for j >= 3.
    pub fn dj(&self, xi: f64, j: usize) -> f64 {
        match j {
            0 => self.h(xi),
            1 => self.h1(xi),
            2 => self.h2(xi),
            _ if j > 2 * self.l => 0.0,
            _ => {
                assert!(self.has_exact(j), "no exact h^({j}) for L = {}", self.l);
                let c = &self.dcoef[j];
                let mut acc = dd_from_int(*c.last().unwrap());
                for &ci in c.iter().rev().skip(1) {
                    acc = dd_add(dd_mul_f64(acc, xi), dd_from_int(ci));
                }
                acc.0 + acc.1
            }
        }
    }

    /// The segment weights `[c_-, c_0, c_+]` of the k-th xi-derivative, from
    /// `c_- = (1 - 2xi + h)/2`, `c_0 = (1 + 2xi - 2h)/2`, `c_+ = h/2`.
    pub fn weights(&self, xi: f64, k: usize) -> [f64; 3] {
        match k {
            0 => {
                let h = self.h(xi);
                [
                    (1.0 - 2.0 * xi + h) / 2.0,
                    (1.0 + 2.0 * xi - 2.0 * h) / 2.0,
                    h / 2.0,
                ]
            }
            1 => {
                let h = self.h1(xi);
                [(h - 2.0) / 2.0, (2.0 - 2.0 * h) / 2.0, h / 2.0]
            }
            _ => {
                let h = self.dj(xi, k);
                [h / 2.0, -h, h / 2.0]
            }
        }
    }

    /// `max |h^(j)|` over 401 samples of [0, 1] (at least 1).
    pub fn max_abs(&self, j: usize) -> f64 {
        let m = self.maxes.get(j).copied().unwrap_or(1.0);
        assert!(!m.is_nan(), "no exact h^({j}) for L = {}", self.l);
        m
    }
}

/// Exact monomial coefficients of `h` for order `l`.
fn monomial_coeffs(l: usize) -> Vec<Q> {
    let mut c = vec![Q::int(0); 2 * l + 1];
    for k in 0..l {
        let eps_k = Q::new(binom(l + k, k) as i128, (l + k) as i128);
        let a = eps_k.mul_int((l - k) as i128);
        for m in 0..=k {
            let sign = if m % 2 == 0 { 1 } else { -1 };
            let term = a.mul_int(sign * binom(k, m) as i128);
            c[l + 1 + m] = c[l + 1 + m].add(term);
        }
    }
    c
}
