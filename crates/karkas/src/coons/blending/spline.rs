//! Cubic-spline cardinal blending: the functions CAD systems use to blend curve networks
//! (Chashnikov's generalized Coons surfaces), because Lagrange blending oscillates when there
//! are many curves.
//!
//! The cardinal function `C_j` is the cubic spline through the values `delta_jk` at the nodes.
//! A spline's `k`-th derivative at `t` is `a(t) . y + c(t) . m` with the Hermite weights `a`,
//! `c` of the piece holding `t` and the node slopes `m = S y`, so the weights of all cardinal
//! functions at `t` are `C(t) = a(t) + S^T c(t)`: one transposed solve of the spline system of
//! [`crate::spline`] per parameter, `O(m)` time and memory per evaluation line, never the
//! dense `m x m` table of all cardinal functions.

use super::{locate, reduce, BlendingFamily, LagrangeBlending};
use crate::coons::Functional;
use crate::core::knots::{check_knots, Knots};
use crate::core::Interval;
use crate::spline::{hermite_basis, SlopeSystem, SplineEnds};
use crate::{Error, Result};

use core::ops::Range;

/// Cubic-spline cardinal blending on nodes `x_0 < ... < x_m`: functionals `L_j f = f(x_j)`
/// and the cardinal splines `C_j` with `C_j(x_k) = delta_jk`.
///
/// For [`SplineEnds::Periodic`] the last node closes the period: `m` functions on `m + 1`
/// nodes, periodic with period `x_m - x_0`. The functions are `C^2`; their third derivative
/// jumps at the nodes (the piece above is used there) and the fourth is zero.
#[derive(Clone, Debug, PartialEq)]
pub struct SplineBlending {
    nodes: Knots,
    ends: SplineEnds,
    system: SlopeSystem,
    functionals: Vec<Functional>,
    /// Not-a-knot on two or three nodes is the interpolating polynomial.
    polynomial: Option<LagrangeBlending>,
}

impl SplineBlending {
    /// The family on `nodes` with the end conditions `ends`.
    ///
    /// Errors: fewer than two nodes (four, one of them the closing node, when periodic), a
    /// non-finite node, nodes not strictly increasing ([`Error::InvalidKnot`]), clamped ends
    /// ([`Error::UnsupportedEnds`]: the functions blend values only).
    ///
    /// # Examples
    ///
    /// ```
    /// use karkas::coons::{BlendingFamily, SplineBlending};
    /// use karkas::param::SplineEnds;
    ///
    /// let family = SplineBlending::new(&[0.0, 1.0, 2.0, 3.0], SplineEnds::Natural)?;
    /// assert_eq!(family.len(), 4);
    /// let clamped = SplineEnds::Clamped { start: karkas::Point([0.0]), end: karkas::Point([0.0]) };
    /// assert!(SplineBlending::new(&[0.0, 1.0, 2.0], clamped).is_err());
    /// # Ok::<(), karkas::Error>(())
    /// ```
    pub fn new(nodes: &[f64], ends: SplineEnds) -> Result<Self> {
        if let SplineEnds::Clamped { .. } = ends {
            return Err(Error::UnsupportedEnds {
                what: "a cubic-spline blending family",
                ends: "clamped",
            });
        }
        let needed = if ends.is_periodic() { 4 } else { 2 };
        check_knots(nodes, needed, "a cubic-spline blending family")?;
        let system = SlopeSystem::new(nodes, &ends)?;
        let count = nodes.len() - usize::from(ends.is_periodic());
        let functionals = nodes[..count]
            .iter()
            .map(|&at| Functional::Value { at })
            .collect();
        let polynomial = match ends {
            SplineEnds::NotAKnot if nodes.len() <= 3 => Some(LagrangeBlending::new(nodes)?),
            _ => None,
        };
        Ok(SplineBlending {
            nodes: Knots::from_checked(nodes.to_vec()),
            ends,
            system,
            functionals,
            polynomial,
        })
    }

    /// The nodes (for a periodic family, the closing node last).
    pub fn nodes(&self) -> &[f64] {
        &self.nodes
    }

    /// The end conditions.
    pub fn ends(&self) -> SplineEnds {
        self.ends
    }
}

impl BlendingFamily for SplineBlending {
    fn len(&self) -> usize {
        self.functionals.len()
    }

    fn domain(&self) -> Interval {
        self.nodes.domain()
    }

    fn is_periodic(&self) -> bool {
        self.ends.is_periodic()
    }

    fn polynomial_pieces(&self) -> Option<crate::bspline::PolynomialPieces> {
        if let Some(p) = &self.polynomial {
            return p.polynomial_pieces();
        }
        Some(crate::bspline::PolynomialPieces::uniform_continuity(
            3,
            self.nodes.to_vec(),
            2,
        ))
    }

    fn functionals(&self) -> &[Functional] {
        &self.functionals
    }

    fn eval_into(&self, t: f64, k: usize, out: &mut [f64]) -> Range<usize> {
        if let Some(p) = &self.polynomial {
            return p.eval_into(t, k, out);
        }
        let count = self.functionals.len();
        out[..count].fill(0.0);
        if k >= 4 {
            return 0..0;
        }
        let periodic = self.ends.is_periodic();
        let t = reduce(self.nodes.domain(), periodic, t);
        let (l, s) = locate(&self.nodes, t);
        let n = self.nodes.len();
        let b = hermite_basis(s, self.nodes[l + 1] - self.nodes[l], k);
        let mut weights = vec![0.0; n];
        let mut slopes = vec![0.0; n];
        weights[l] = b[0];
        weights[l + 1] = b[2];
        slopes[l] = b[1];
        slopes[l + 1] = b[3];
        self.system.add_transposed(&mut slopes, &mut weights);
        if periodic {
            // The closing node is the first one.
            weights[0] += weights[n - 1];
        }
        out[..count].copy_from_slice(&weights[..count]);
        0..count
    }
}
