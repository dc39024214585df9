//! Cubic Hermite blending: the bicubic Coons family (Chashnikov, formulas (1)–(3)) and its
//! piecewise version on a node set, the composite Coons family (formulas (15)–(18)).

use super::{locate, powi, reduce, BlendingFamily};
use crate::coons::Functional;
use crate::core::knots::check_knots;
use crate::core::Interval;
use crate::spline::hermite_cubic;
use crate::Result;
use core::ops::Range;

/// The bicubic Coons family on an interval `[a, b]` (Chashnikov, (1)–(3)): functionals
/// `f(a), f'(a), f'(b), f(b)` (the paper's order) and the cubic Hermite polynomials scaled to
/// the interval, `H_1(s), h H_2(s), h H_3(s), H_4(s)` with `s = (t - a)/h`, `h = b - a` (the
/// factor `h` makes the derivative functionals return 1 per unit of `t`).
#[derive(Clone, Debug, PartialEq)]
pub struct CubicHermiteBlending {
    domain: Interval,
    functionals: [Functional; 4],
}

impl CubicHermiteBlending {
    /// The family on `[a, b]`; fails unless `a < b` are finite.
    ///
    /// # Examples
    ///
    /// ```
    /// use karkas::coons::{BlendingFamily, CubicHermiteBlending};
    ///
    /// let family = CubicHermiteBlending::new(0.0, 2.0)?;
    /// assert_eq!(family.len(), 4); // values and derivatives at both ends
    /// assert!(CubicHermiteBlending::new(1.0, 1.0).is_err());
    /// # Ok::<(), karkas::Error>(())
    /// ```
    pub fn new(a: f64, b: f64) -> Result<Self> {
        check_knots(&[a, b], 2, "a cubic Hermite blending family")?;
        Ok(CubicHermiteBlending {
            domain: Interval::new(a, b),
            functionals: [
                Functional::Value { at: a },
                Functional::Derivative { at: a, order: 1 },
                Functional::Derivative { at: b, order: 1 },
                Functional::Value { at: b },
            ],
        })
    }
}

impl BlendingFamily for CubicHermiteBlending {
    fn len(&self) -> usize {
        4
    }

    fn polynomial_pieces(&self) -> Option<crate::bspline::PolynomialPieces> {
        Some(crate::bspline::PolynomialPieces::uniform_continuity(
            3,
            vec![self.domain.start, self.domain.end],
            3,
        ))
    }

    fn domain(&self) -> Interval {
        self.domain
    }

    fn is_periodic(&self) -> bool {
        false
    }

    fn functionals(&self) -> &[Functional] {
        &self.functionals
    }

    fn eval_into(&self, t: f64, k: usize, out: &mut [f64]) -> Range<usize> {
        let h = self.domain.length();
        let s = (reduce(self.domain, false, t) - self.domain.start) / h;
        let w = hermite_cubic(s, k);
        let scale = powi(h, k).recip();
        out[0] = w[0] * scale;
        out[1] = w[1] * h * scale;
        out[2] = w[2] * h * scale;
        out[3] = w[3] * scale;
        0..4
    }
}

/// The composite Coons family on nodes `u_0 < ... < u_m` (Chashnikov, (15)–(18)), generalised
/// to uneven nodes: functionals `L_{2i} f = f(u_i)`, `L_{2i+1} f = f'(u_i)`, and functions
///
/// ```text
/// H_{2i}(t)   = H_1((t - u_i)/h_i)            on [u_i, u_{i+1}],   H_4((t - u_{i-1})/h_{i-1})          on [u_{i-1}, u_i]
/// H_{2i+1}(t) = h_i H_2((t - u_i)/h_i)        on [u_i, u_{i+1}],   h_{i-1} H_3((t - u_{i-1})/h_{i-1})  on [u_{i-1}, u_i]
/// ```
///
/// (`h_i = u_{i+1} - u_i`), zero elsewhere. With the paper's integer nodes `u_i = i` this is
/// exactly (17)–(18). The functions are `C^1`; at any parameter at most four are nonzero.
#[derive(Clone, Debug, PartialEq)]
pub struct PiecewiseHermiteBlending {
    nodes: Vec<f64>,
    functionals: Vec<Functional>,
}

impl PiecewiseHermiteBlending {
    /// The family on `nodes` (at least two, finite, strictly increasing): `2 * nodes.len()`
    /// functions.
    ///
    /// # Examples
    ///
    /// ```
    /// use karkas::coons::{BlendingFamily, PiecewiseHermiteBlending};
    ///
    /// let family = PiecewiseHermiteBlending::new(&[0.0, 1.0, 3.0])?;
    /// assert_eq!(family.len(), 6);
    /// assert!(PiecewiseHermiteBlending::new(&[0.0, 2.0, 1.0]).is_err());
    /// # Ok::<(), karkas::Error>(())
    /// ```
    pub fn new(nodes: &[f64]) -> Result<Self> {
        check_knots(nodes, 2, "a piecewise Hermite blending family")?;
        let functionals = nodes
            .iter()
            .flat_map(|&at| {
                [
                    Functional::Value { at },
                    Functional::Derivative { at, order: 1 },
                ]
            })
            .collect();
        Ok(PiecewiseHermiteBlending {
            nodes: nodes.to_vec(),
            functionals,
        })
    }

    /// The nodes `u_0..u_m`.
    pub fn nodes(&self) -> &[f64] {
        &self.nodes
    }
}

impl BlendingFamily for PiecewiseHermiteBlending {
    fn len(&self) -> usize {
        2 * self.nodes.len()
    }

    fn domain(&self) -> Interval {
        Interval::new(self.nodes[0], self.nodes[self.nodes.len() - 1])
    }

    fn is_periodic(&self) -> bool {
        false
    }

    fn polynomial_pieces(&self) -> Option<crate::bspline::PolynomialPieces> {
        Some(crate::bspline::PolynomialPieces::uniform_continuity(
            3,
            self.nodes.clone(),
            1,
        ))
    }

    fn functionals(&self) -> &[Functional] {
        &self.functionals
    }

    fn eval_into(&self, t: f64, k: usize, out: &mut [f64]) -> Range<usize> {
        let m = self.len();
        out[..m].fill(0.0);
        let t = reduce(self.domain(), false, t);
        let (l, s) = locate(&self.nodes, t);
        let h = self.nodes[l + 1] - self.nodes[l];
        let w = hermite_cubic(s, k);
        let scale = powi(h, k).recip();
        // Formula (17): on [u_l, u_{l+1}] the nonzero functions are H_{2l} = H_1, H_{2l+1} = h H_2,
        // H_{2l+2} = H_4, H_{2l+3} = h H_3.
        out[2 * l] = w[0] * scale;
        out[2 * l + 1] = w[1] * h * scale;
        out[2 * l + 2] = w[3] * scale;
        out[2 * l + 3] = w[2] * h * scale;
        2 * l..2 * l + 4
    }
}
