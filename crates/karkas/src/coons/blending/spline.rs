//! Cubic-spline cardinal blending: the functions CAD systems use to blend curve networks
//! (METHODS.md §2), because Lagrange blending oscillates when there are many curves.
//!
//! The cardinal function `C_j` is the cubic spline through the values `delta_jk` at the nodes.
//! On the piece `[x_l, x_{l+1}]` (`h = x_{l+1} - x_l`, `s = (t - x_l)/h`) a cubic spline with
//! values `y` and second derivatives `M` is
//!
//! ```text
//! S(t) = (1 - s) y_l + s y_{l+1} + h^2/6 [((1 - s)^3 - (1 - s)) M_l + (s^3 - s) M_{l+1}]
//! ```
//!
//! and `M` solves the tridiagonal system `T M = R y` whose interior rows are
//! `h_{l-1} M_{l-1} + 2 (h_{l-1} + h_l) M_l + h_l M_{l+1} = 6 ((y_{l+1} - y_l)/h_l - (y_l - y_{l-1})/h_{l-1})`.
//! The end rows depend on [`SplineEnds`]. So `S(t) = a(t) . y + c(t) . M` with `a`, `c`
//! nonzero only at `l`, `l + 1`, and the weights of all cardinal functions at `t` are
//!
//! ```text
//! C(t) = a(t) + R^T T^-T c(t)
//! ```
//!
//! one tridiagonal solve with the transposed matrix per parameter: `O(m)` time and memory per
//! evaluation line, never the dense `m x m` table of all cardinal functions.
//! [`solve_tridiagonal`] and [`solve_cyclic_tridiagonal`] do the solves.

use super::{check_nodes, locate, reduce, BlendingFamily, LagrangeBlending};
use crate::coons::Functional;
use crate::core::Interval;
use crate::solve::{solve_cyclic_tridiagonal, solve_tridiagonal};
use crate::{Point, Result};

use core::ops::Range;

/// The end conditions of a cubic spline.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum SplineEnds {
    /// Zero second derivative at both ends. Two nodes give a straight line.
    Natural,
    /// The third derivative is continuous at the second and the next-to-last node (the
    /// default of most libraries, e.g. SciPy's `CubicSpline`). Two nodes give a line, three a
    /// parabola.
    NotAKnot,
    /// Periodic: the last node closes the period (it is the first node moved by one period and
    /// carries no function of its own). At least three distinct nodes.
    Periodic,
}

/// The tridiagonal system `T M = R y` of the second derivatives `M` of a cubic spline with
/// values `y` on a node set, with its end conditions (shared by the cardinal functions and by
/// [`CubicSplineCurve`](crate::coons::CubicSplineCurve)).
///
/// For [`SplineEnds::NotAKnot`] the unknowns solved are `M_1..M_{count-2}` (after eliminating
/// `M_0` and `M_{count-1}`, four nodes at least); otherwise all `M`.
#[derive(Clone, Debug, PartialEq)]
pub(crate) struct SplineSystem {
    nodes: Vec<f64>,
    ends: SplineEnds,
}

/// `(lower, diagonal, upper)` of a matrix row.
pub(crate) type Row = (f64, f64, f64);

/// A parameter's piece and the coefficients of the `k`-th derivative there:
/// `S^(k)(t) = a.0 y_l + a.1 y_next + c.0 M_l + c.1 M_next`.
#[derive(Clone, Copy, Debug, PartialEq)]
pub(crate) struct Local {
    pub l: usize,
    pub next: usize,
    pub a: (f64, f64),
    pub c: (f64, f64),
}

impl SplineSystem {
    /// The system on `nodes` (already checked: finite, increasing, enough of them).
    pub(crate) fn new(nodes: &[f64], ends: SplineEnds) -> Self {
        SplineSystem {
            nodes: nodes.to_vec(),
            ends,
        }
    }

    /// The nodes (for periodic ends, the closing node last).
    pub(crate) fn nodes(&self) -> &[f64] {
        &self.nodes
    }

    /// The number of values `y` (one fewer than the nodes when periodic).
    pub(crate) fn count(&self) -> usize {
        match self.ends {
            SplineEnds::Periodic => self.nodes.len() - 1,
            _ => self.nodes.len(),
        }
    }

    /// The number of unknowns actually solved for.
    pub(crate) fn unknowns(&self) -> usize {
        match self.ends {
            SplineEnds::NotAKnot => self.count() - 2,
            _ => self.count(),
        }
    }

    /// The row of `M` the first unknown stands for (1 for not-a-knot, else 0).
    pub(crate) fn offset(&self) -> usize {
        usize::from(self.ends == SplineEnds::NotAKnot)
    }

    pub(crate) fn is_periodic(&self) -> bool {
        self.ends == SplineEnds::Periodic
    }

    /// The parameter interval.
    pub(crate) fn domain(&self) -> Interval {
        Interval::new(self.nodes[0], self.nodes[self.nodes.len() - 1])
    }

    /// `h_l = x_{l+1} - x_l` (`l < nodes.len() - 1`).
    #[inline]
    fn gap(&self, l: usize) -> f64 {
        self.nodes[l + 1] - self.nodes[l]
    }

    /// The row `r` of the full system `T M = R y` (`r` in `0..count`): `T`'s coefficients on
    /// `M_{r-1}, M_r, M_{r+1}` and `R`'s on `y_{r-1}, y_r, y_{r+1}` (indices cyclic when
    /// periodic). The natural end rows are `M = 0` with `R = 0`.
    pub(crate) fn full_row(&self, r: usize) -> (Row, Row) {
        let count = self.count();
        let periodic = self.is_periodic();
        if !periodic && (r == 0 || r + 1 == count) {
            return ((0.0, 1.0, 0.0), (0.0, 0.0, 0.0));
        }
        let before = if periodic {
            self.gap((r + count - 1) % count)
        } else {
            self.gap(r - 1)
        };
        let after = self.gap(r);
        (
            (before, 2.0 * (before + after), after),
            (
                6.0 / before,
                -6.0 * (before.recip() + after.recip()),
                6.0 / after,
            ),
        )
    }

    /// The not-a-knot elimination `M_0 = e0 M_1 + f0 M_2`,
    /// `M_last = e1 M_{last-1} + f1 M_{last-2}` (continuous third derivative at the second
    /// and the next-to-last node).
    pub(crate) fn not_a_knot_ends(&self) -> [f64; 4] {
        let count = self.count();
        let (h0, h1) = (self.gap(0), self.gap(1));
        let (hl, hp) = (self.gap(count - 2), self.gap(count - 3));
        [1.0 + h0 / h1, -h0 / h1, 1.0 + hl / hp, -hl / hp]
    }

    /// Row `p` of the matrix actually solved: the full system for natural and periodic ends;
    /// for not-a-knot the rows `1..count-1` on the unknowns `M_1..M_{count-2}` after
    /// eliminating `M_0` and `M_{count-1}`.
    pub(crate) fn solved_row(&self, p: usize) -> Row {
        if self.ends != SplineEnds::NotAKnot {
            return self.full_row(p).0;
        }
        let count = self.count();
        let r = p + 1;
        let (mut lower, mut diag, mut upper) = self.full_row(r).0;
        let [e0, f0, e1, f1] = self.not_a_knot_ends();
        if r == 1 {
            let h0 = lower;
            diag += h0 * e0;
            upper += h0 * f0;
            lower = 0.0;
        }
        if r == count - 2 {
            let hl = upper;
            diag += hl * e1;
            lower += hl * f1;
            upper = 0.0;
        }
        (lower, diag, upper)
    }

    /// The piece holding `t` (brought into the domain) and the coefficients of the `k`-th
    /// derivative on it; `None` for `k >= 4` (zero).
    pub(crate) fn local(&self, t: f64, k: usize) -> Option<Local> {
        let t = reduce(self.domain(), self.is_periodic(), t);
        let (l, s) = locate(&self.nodes, t);
        let next = (l + 1) % self.count();
        let h = self.gap(l);
        let u = 1.0 - s;
        let (a, c) = match k {
            0 => (
                (u, s),
                (h * h / 6.0 * (u * u * u - u), h * h / 6.0 * (s * s * s - s)),
            ),
            1 => (
                (-1.0 / h, 1.0 / h),
                (h / 6.0 * (1.0 - 3.0 * u * u), h / 6.0 * (3.0 * s * s - 1.0)),
            ),
            2 => ((0.0, 0.0), (u, s)),
            3 => ((0.0, 0.0), (-1.0 / h, 1.0 / h)),
            _ => return None,
        };
        Some(Local { l, next, a, c })
    }

    /// Solves `A x = rhs` in place, where `A` is the solved matrix (`transposed`: its
    /// transpose), with the Thomas algorithm or its cyclic variant.
    pub(crate) fn solve<const D: usize>(
        &self,
        rhs: &mut [Point<D>],
        transposed: bool,
    ) -> Result<()> {
        let n = self.unknowns();
        let periodic = self.is_periodic();
        let row = |i: usize| {
            if !transposed {
                return self.solved_row(i);
            }
            // Row i of the transpose: (A[i-1][i], A[i][i], A[i+1][i]).
            let diag = self.solved_row(i).1;
            let lower = if periodic || i > 0 {
                self.solved_row((i + n - 1) % n).2
            } else {
                0.0
            };
            let upper = if periodic || i + 1 < n {
                self.solved_row((i + 1) % n).0
            } else {
                0.0
            };
            (lower, diag, upper)
        };
        if periodic {
            solve_cyclic_tridiagonal(row, rhs)
        } else {
            solve_tridiagonal(row, rhs)
        }
    }
}

/// Cubic-spline cardinal blending on nodes `x_0 < ... < x_m`: functionals `L_j f = f(x_j)`
/// and the cardinal splines `C_j` with `C_j(x_k) = delta_jk`.
///
/// For [`SplineEnds::Periodic`] the last node closes the period: `m` functions on `m + 1`
/// nodes, periodic with period `x_m - x_0`. The functions are `C^2`; their third derivative
/// jumps at the nodes (the piece above is used there) and the fourth is zero.
#[derive(Clone, Debug, PartialEq)]
pub struct SplineBlending {
    system: SplineSystem,
    functionals: Vec<Functional>,
    /// Not-a-knot on two or three nodes is the interpolating polynomial.
    polynomial: Option<LagrangeBlending>,
}

impl SplineBlending {
    /// The family on `nodes` with the end conditions `ends`.
    ///
    /// Errors: fewer than two nodes (four, one of them the closing node, when periodic), a
    /// non-finite node, nodes not strictly increasing.
    pub fn new(nodes: &[f64], ends: SplineEnds) -> Result<Self> {
        let needed = if ends == SplineEnds::Periodic { 4 } else { 2 };
        check_nodes(nodes, needed, "a cubic-spline blending family")?;
        let system = SplineSystem::new(nodes, ends);
        let functionals = nodes[..system.count()]
            .iter()
            .map(|&at| Functional::Value { at })
            .collect();
        let polynomial = match ends {
            SplineEnds::NotAKnot if nodes.len() <= 3 => Some(LagrangeBlending::new(nodes)?),
            _ => None,
        };
        Ok(SplineBlending {
            system,
            functionals,
            polynomial,
        })
    }

    /// The nodes (for a periodic family, the closing node last).
    pub fn nodes(&self) -> &[f64] {
        self.system.nodes()
    }

    /// The end conditions.
    pub fn ends(&self) -> SplineEnds {
        self.system.ends
    }
}

impl BlendingFamily for SplineBlending {
    fn len(&self) -> usize {
        self.functionals.len()
    }

    fn domain(&self) -> Interval {
        self.system.domain()
    }

    fn is_periodic(&self) -> bool {
        self.system.is_periodic()
    }

    fn polynomial_pieces(&self) -> Option<crate::bspline::PolynomialPieces> {
        if let Some(p) = &self.polynomial {
            return p.polynomial_pieces();
        }
        Some(crate::bspline::PolynomialPieces::uniform_continuity(
            3,
            self.system.nodes().to_vec(),
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
        let system = &self.system;
        let count = system.count();
        out[..count].fill(0.0);
        let Some(Local { l, next, a, c }) = system.local(t, k) else {
            return 0..0;
        };
        out[l] += a.0;
        out[next] += a.1;
        if c == (0.0, 0.0) {
            return 0..count;
        }
        // z = T^-T c, over the unknowns actually solved.
        let unknowns = system.unknowns();
        let mut z = vec![Point([0.0]); unknowns];
        if system.ends == SplineEnds::NotAKnot {
            let [e0, f0, e1, f1] = system.not_a_knot_ends();
            for (index, value) in [(l, c.0), (next, c.1)] {
                if index == 0 {
                    z[0][0] += value * e0;
                    z[1][0] += value * f0;
                } else if index == count - 1 {
                    z[unknowns - 1][0] += value * e1;
                    z[unknowns - 2][0] += value * f1;
                } else {
                    z[index - 1][0] += value;
                }
            }
        } else {
            z[l][0] += c.0;
            z[next][0] += c.1;
        }
        if system.solve(&mut z, true).is_err() {
            // The matrices are strictly diagonally dominant for increasing nodes: unreachable
            // for a family that passed `new`, but never a panic.
            out[..count].fill(f64::NAN);
            return 0..count;
        }
        // out += R^T z: row r of R touches y_{r-1}, y_r, y_{r+1}.
        for (p, zp) in z.iter().enumerate() {
            let r = p + system.offset();
            let (lower, diag, upper) = system.full_row(r).1;
            let zp = zp[0];
            if lower != 0.0 {
                out[(r + count - 1) % count] += lower * zp;
            }
            out[r] += diag * zp;
            if upper != 0.0 {
                out[(r + 1) % count] += upper * zp;
            }
        }
        0..count
    }
}
