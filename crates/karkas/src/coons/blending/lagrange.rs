//! Lagrange blending: the Gordon surface family (Chashnikov's §3 case 3) and, on two nodes, the
//! bilinear Coons family (Chashnikov's §3 case 1).

use super::{reduce, BlendingFamily};
use crate::coons::Functional;
use crate::core::knots::check_knots;
use crate::core::Interval;
use crate::Result;
use core::ops::Range;

/// Lagrange blending on nodes `u_0 < ... < u_{m-1}`: functionals `L_i f = f(u_i)` and the
/// Lagrange basis `H_i(t) = prod_{k != i} (t - u_k)/(u_i - u_k)`.
///
/// On two nodes this is the bilinear Coons family `1 - x, x` (scaled to the interval). The
/// polynomials have degree `m - 1` and oscillate between the nodes when `m` is large (Runge's
/// phenomenon): use [`SplineBlending`](super::SplineBlending) for many curves. Evaluation costs
/// `O(m^2 (k + 1))` per parameter for the `k`-th derivative: meant for a handful of nodes.
/// Outside the node range the parameter is clamped (no extrapolation).
#[derive(Clone, Debug, PartialEq)]
pub struct LagrangeBlending {
    nodes: Vec<f64>,
    /// `1 / prod_{k != i} (u_i - u_k)`.
    inverse_denominators: Vec<f64>,
    functionals: Vec<Functional>,
}

impl LagrangeBlending {
    /// The family on `nodes` (at least two, finite, strictly increasing).
    ///
    /// # Examples
    ///
    /// ```
    /// use karkas::coons::{BlendingFamily, LagrangeBlending};
    ///
    /// let family = LagrangeBlending::new(&[0.0, 0.5, 1.0])?;
    /// assert_eq!(family.len(), 3);
    /// assert_eq!((family.domain().start, family.domain().end), (0.0, 1.0));
    /// assert!(LagrangeBlending::new(&[0.0]).is_err());
    /// # Ok::<(), karkas::Error>(())
    /// ```
    pub fn new(nodes: &[f64]) -> Result<Self> {
        check_knots(nodes, 2, "a Lagrange blending family")?;
        let inverse_denominators = nodes
            .iter()
            .enumerate()
            .map(|(i, &ui)| {
                let d: f64 = nodes
                    .iter()
                    .enumerate()
                    .filter(|&(k, _)| k != i)
                    .map(|(_, &uk)| ui - uk)
                    .product();
                d.recip()
            })
            .collect();
        let functionals = nodes.iter().map(|&at| Functional::Value { at }).collect();
        Ok(LagrangeBlending {
            nodes: nodes.to_vec(),
            inverse_denominators,
            functionals,
        })
    }

    /// The nodes.
    pub fn nodes(&self) -> &[f64] {
        &self.nodes
    }
}

impl BlendingFamily for LagrangeBlending {
    fn len(&self) -> usize {
        self.nodes.len()
    }

    fn domain(&self) -> Interval {
        Interval::new(self.nodes[0], self.nodes[self.nodes.len() - 1])
    }

    fn polynomial_pieces(&self) -> Option<crate::bspline::PolynomialPieces> {
        let d = self.domain();
        Some(crate::bspline::PolynomialPieces::uniform_continuity(
            (self.nodes.len() - 1).max(1),
            vec![d.start, d.end],
            0,
        ))
    }

    fn is_periodic(&self) -> bool {
        false
    }

    fn functionals(&self) -> &[Functional] {
        &self.functionals
    }

    fn eval_into(&self, t: f64, k: usize, out: &mut [f64]) -> Range<usize> {
        let m = self.nodes.len();
        let t = reduce(self.domain(), false, t);
        if k >= m {
            out[..m].fill(0.0);
            return 0..0;
        }
        if k == 0 {
            for (i, o) in out[..m].iter_mut().enumerate() {
                let p: f64 = self
                    .nodes
                    .iter()
                    .enumerate()
                    .filter(|&(q, _)| q != i)
                    .map(|(_, &uq)| t - uq)
                    .product();
                *o = p * self.inverse_denominators[i];
            }
            return 0..m;
        }
        // Taylor coefficients in e of prod_{q != i} (t - u_q + e), up to e^k: the k-th
        // derivative is k! times the coefficient of e^k.
        let mut taylor = vec![0.0; k + 1];
        let factorial: f64 = (1..=k).map(|x| x as f64).product();
        for (i, o) in out[..m].iter_mut().enumerate() {
            taylor.fill(0.0);
            taylor[0] = 1.0;
            for (q, &uq) in self.nodes.iter().enumerate() {
                if q == i {
                    continue;
                }
                let d = t - uq;
                for c in (1..=k).rev() {
                    taylor[c] = taylor[c] * d + taylor[c - 1];
                }
                taylor[0] *= d;
            }
            *o = taylor[k] * factorial * self.inverse_denominators[i];
        }
        0..m
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn two_nodes_are_the_bilinear_family() {
        let f = LagrangeBlending::new(&[0.0, 1.0]).unwrap();
        let mut w = [0.0; 2];
        f.eval_into(0.3, 0, &mut w);
        assert!((w[0] - 0.7).abs() < 1e-15 && (w[1] - 0.3).abs() < 1e-15);
        f.eval_into(0.3, 1, &mut w);
        assert_eq!(w, [-1.0, 1.0]);
        assert_eq!(f.eval_into(0.3, 2, &mut w), 0..0);
        assert_eq!(w, [0.0, 0.0]);
    }

    #[test]
    fn derivatives_of_a_cubic_basis() {
        // Nodes 0, 1, 2, 3: H_0(t) = -(t-1)(t-2)(t-3)/6, H_0''' = -1.
        let f = LagrangeBlending::new(&[0.0, 1.0, 2.0, 3.0]).unwrap();
        let mut w = [0.0; 4];
        f.eval_into(0.5, 3, &mut w);
        assert!((w[0] + 1.0).abs() < 1e-14);
        // H_0'(t) = -(3t^2 - 12t + 11)/6 at t = 0.5: -(0.75 - 6 + 11)/6.
        f.eval_into(0.5, 1, &mut w);
        assert!((w[0] + 5.75 / 6.0).abs() < 1e-14);
    }
}
