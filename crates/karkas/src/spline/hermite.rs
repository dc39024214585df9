//! The cubic Hermite basis: the four cubics on a piece that carry the values and the first
//! derivatives at its two ends (Kuznetsov and Filatov's (3.7); Chashnikov's (3); Pavlov's
//! `F_0..F_3`).
//!
//! On a piece of length `h` with local coordinate `s = (t - t_k) / h`:
//!
//! ```text
//! P(t) = y_k (1-s)^2 (1+2s) + m_k h s (1-s)^2 + y_{k+1} s^2 (3-2s) - m_{k+1} h s^2 (1-s)
//! ```
//!
//! with values `y` and derivatives `m` (per unit of `t`) at the ends.

/// The four Hermite basis functions of a piece of length `h` at local coordinate `s`,
/// differentiated `k` times with respect to `t`, in the order `[y_k, m_k, y_{k+1}, m_{k+1}]`
/// (value, derivative at the start; value, derivative at the end). Zero for `k > 3`.
#[inline]
pub fn hermite_basis(s: f64, h: f64, k: usize) -> [f64; 4] {
    let s2 = s * s;
    match k {
        0 => {
            let v1 = s2 * (3.0 - 2.0 * s);
            [
                1.0 - v1,
                h * s * (1.0 - s) * (1.0 - s),
                v1,
                -h * s2 * (1.0 - s),
            ]
        }
        1 => {
            let d = 6.0 * s * (1.0 - s) / h;
            [-d, 1.0 - 4.0 * s + 3.0 * s2, d, 3.0 * s2 - 2.0 * s]
        }
        2 => {
            let d = (12.0 * s - 6.0) / (h * h);
            [d, (6.0 * s - 4.0) / h, -d, (6.0 * s - 2.0) / h]
        }
        3 => {
            let h2 = h * h;
            let d = 12.0 / (h2 * h);
            [d, 6.0 / h2, -d, 6.0 / h2]
        }
        _ => [0.0; 4],
    }
}

/// The `k`-th derivative (in `s`) of the cubic Hermite polynomials on `[0, 1]` at `s`, in
/// Chashnikov's order (3): `H_1 = 2s^3 - 3s^2 + 1` (value 1 at 0), `H_2 = s^3 - 2s^2 + s`
/// (derivative 1 at 0), `H_3 = s^3 - s^2` (derivative 1 at 1), `H_4 = -2s^3 + 3s^2` (value 1
/// at 1). [`hermite_basis`] on a piece of length 1, reordered. Zero for `k >= 4`.
#[inline]
pub fn hermite_cubic(s: f64, k: usize) -> [f64; 4] {
    let [v0, d0, v1, d1] = hermite_basis(s, 1.0, k);
    [v0, d0, d1, v1]
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn hermite_conditions() {
        // H_1(0)=1, H_2'(0)=1, H_3'(1)=1, H_4(1)=1, all other conditions zero.
        assert_eq!(hermite_cubic(0.0, 0), [1.0, 0.0, 0.0, 0.0]);
        assert_eq!(hermite_cubic(0.0, 1), [0.0, 1.0, 0.0, 0.0]);
        assert_eq!(hermite_cubic(1.0, 1), [0.0, 0.0, 1.0, 0.0]);
        assert_eq!(hermite_cubic(1.0, 0), [0.0, 0.0, 0.0, 1.0]);
    }

    #[test]
    fn derivatives_match_differences() {
        let h = 0.7;
        let e = 1e-6;
        for k in 0..4 {
            for s in [0.1, 0.37, 0.8] {
                let (a, b) = (hermite_basis(s - e, h, k), hermite_basis(s + e, h, k));
                let d = hermite_basis(s, h, k + 1);
                for c in 0..4 {
                    let fd = (b[c] - a[c]) / (2.0 * e * h);
                    assert!((fd - d[c]).abs() < 1e-5, "k={k} c={c}: {fd} vs {}", d[c]);
                }
            }
        }
        assert_eq!(hermite_basis(0.3, 1.0, 4), [0.0; 4]);
    }
}
