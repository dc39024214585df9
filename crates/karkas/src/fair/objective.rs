//! The objective of the fairer on a fixed spline space and fixed point parameters, and its
//! Gauss–Newton gradient and matrix (docs/methods.md §8).
//!
//! `Ψ_t(x) = t (E(x) + α R(x)) / 2 - sum_i ln(T^2 - |r(u_i) - p_i|^2)`:
//!
//! - `E = ∫ (dκ/ds)^2 ds`, the curvature-variation energy, by four-point Gauss–Legendre
//!   quadrature on every span of `(dκ/ds)^2 |r'(t)|` (exact for the integrand's polynomial
//!   part, and the pieces are short). Its residual at a node, `F = dκ/ds sqrt(w |r'|)`, is
//!   linearized for the Gauss–Newton matrix: its gradient with respect to the node's first
//!   three derivatives in closed form (by central differences only where a space curve's
//!   curvature vanishes and `F` is not differentiable), then through the basis weights to
//!   the span's four controls.
//! - `R = ∫ |r'''(t)|^2 dt`, constant on every span of a cubic, weighted `α` small: `E` does not
//!   change when the curve is reparameterized, and `R` keeps the parameter even where `E`
//!   alone would leave it free.
//! - The logarithmic barrier of the hard bound `|r(u_i) - p_i| < T` (a ball around every point
//!   at its parameter `u_i`): its gradient and matrix are exact. Or, first, of the slab
//!   `|e_⊥|^2 + β (e . τ)^2 < T^2` around the tangent at `u_i`, the tangent held in the
//!   Gauss–Newton matrix (docs/methods.md §8).
//!
//! Every term touches the four controls of one span, so the matrix is banded (the terms are
//! summed span by span first, `fair/blocks.rs`).

use super::blocks::Blocks;
use super::layout::{Layout, Row};
use super::space::{Space, NODES};
use crate::geometry::curvature_rate::curvature_and_rate;
use crate::solve::BandedSpd;
use crate::Point;

/// The Gauss–Legendre weights of the four inner [`NODES`] (positions 1 to 4).
const GAUSS_WEIGHTS: [f64; 4] = [
    0.173_927_422_568_726_93,
    0.326_072_577_431_273_07,
    0.326_072_577_431_273_07,
    0.173_927_422_568_726_93,
];
/// Nodes per span where the sign of `dκ/ds` is watched: all [`NODES`] (the span's ends
/// one-sided: `dκ/ds` jumps at a break of a cubic).
pub(crate) const NODES_PER_SPAN: usize = NODES.len();
/// Relative step of the central differences in `r'`.
const DIFFERENCE_STEP: f64 = 1e-5;

/// The fixed data of the objective: the space, the unknowns' layout, the points, their
/// parameters and the bound.
pub(crate) struct Objective<'a, const D: usize> {
    pub(crate) space: &'a Space,
    pub(crate) layout: &'a Layout<D>,
    pub(crate) points: &'a [Point<D>],
    /// The span of every point's parameter and the value weights there.
    pub(crate) basis: &'a [Basis],
    /// The bound `T`.
    pub(crate) tolerance: f64,
    /// The weight `α` of `R`.
    pub(crate) alpha: f64,
    /// The sign asked of `dκ/ds` at every quadrature node, if any.
    pub(crate) shape: Option<&'a Shape>,
    /// Whether the bound is taken mostly across the curve: `|e_⊥|^2 + β (e . τ)^2 < T^2`,
    /// `e_⊥` the part of `e = r(u_i) - p_i` normal to the unit tangent `τ` at `u_i` (a slab
    /// around the tangent line), instead of the ball `|e| < T`.
    pub(crate) slab: bool,
}

/// The span of a point's parameter and the weights of the value and of the first derivative
/// there.
pub(crate) type Basis = (usize, [f64; 4], [f64; 4]);

/// The signs asked of `dκ/ds` at the quadrature nodes (span by span, node by node; 0 where
/// free) and the penalty on the wrong sign: `ρ sum w h (min(0, σ F - margin))^2`.
#[derive(Clone, Debug)]
pub(crate) struct Shape {
    pub(crate) signs: Vec<i8>,
    pub(crate) rho: f64,
    pub(crate) margin: f64,
}

/// The samples of the curvature at the quadrature nodes: `κ`, `dκ/ds sqrt(|r'|)` and the
/// arc position of every node, and the length.
pub(crate) struct NodeSamples {
    pub(crate) curvature: Vec<f64>,
    pub(crate) rate: Vec<f64>,
    pub(crate) s: Vec<f64>,
    pub(crate) length: f64,
}

/// The parts of the objective at one set of controls.
#[derive(Clone, Copy, Debug, Default)]
pub(crate) struct Parts {
    /// `E`.
    pub(crate) energy: f64,
    /// `R`.
    pub(crate) smoothness: f64,
    /// `-sum ln(T^2 - |e_i|^2)`, infinite when a point is not strictly inside its ball.
    pub(crate) barrier: f64,
    /// The penalty on the wrong sign of `dκ/ds` (see [`Shape`]).
    pub(crate) shape: f64,
}

impl Parts {
    /// The fairing terms `E + α R` (the barrier's gap is measured against them).
    pub(crate) fn fairing(&self, alpha: f64) -> f64 {
        self.energy + alpha * self.smoothness
    }

    /// `Ψ_t`, with the energy terms halved as the Gauss–Newton model has them.
    pub(crate) fn value(&self, t: f64, alpha: f64) -> f64 {
        0.5 * t * (self.energy + alpha * self.smoothness + self.shape) + self.barrier
    }
}

/// `dκ/ds sqrt(|r'|)` from the first three derivatives (0 where the speed vanishes).
fn residual<const D: usize>(d1: Point<D>, d2: Point<D>, d3: Point<D>) -> f64 {
    let (_, rate) = curvature_and_rate(d1, d2, d3);
    let value = rate * d1.norm().sqrt();
    if value.is_finite() {
        value
    } else {
        0.0
    }
}

impl<const D: usize> Objective<'_, D> {
    /// The row of span `k` with the coefficient `coefficient(c)` on its `c`-th control.
    fn span_row(&self, k: usize, coefficient: impl Fn(usize) -> Point<D>) -> Row<D> {
        std::array::from_fn(|c| (self.space.control(k, c), coefficient(c)))
    }

    /// The error `r(u_i) - p_i` of every point, through `f(i, span, weights, error)`.
    fn errors(&self, controls: &[Point<D>], mut f: impl FnMut(usize, usize, &[f64; 4], Point<D>)) {
        for (i, ((k, w, _), &p)) in self.basis.iter().zip(self.points).enumerate() {
            let value = (0..4).fold(Point::ZERO, |acc, c| {
                acc.add_scaled(w[c], controls[self.space.control(*k, c)])
            });
            f(i, *k, w, value - p);
        }
    }

    /// The error of every point and the unit tangent at its parameter (zero unless the bound
    /// is a slab), through `f(span, weights, error, tangent)`.
    fn bound_errors(
        &self,
        controls: &[Point<D>],
        mut f: impl FnMut(usize, &[f64; 4], Point<D>, Point<D>),
    ) {
        for ((k, w, w1), &p) in self.basis.iter().zip(self.points) {
            let at = |weights: &[f64; 4]| {
                (0..4).fold(Point::ZERO, |acc, c| {
                    acc.add_scaled(weights[c], controls[self.space.control(*k, c)])
                })
            };
            let tangent = if self.slab {
                let d1 = at(w1);
                let speed = d1.norm();
                if speed > 0.0 {
                    d1 * (1.0 / speed)
                } else {
                    Point::ZERO
                }
            } else {
                Point::ZERO
            };
            f(*k, w, at(w) - p, tangent);
        }
    }

    /// `E`, `R` and the barrier at `controls`.
    pub(crate) fn parts(&self, controls: &[Point<D>]) -> Parts {
        let mut parts = Parts::default();
        for k in 0..self.space.spans() {
            let h = self.space.width(k);
            for (node, &w) in GAUSS_WEIGHTS.iter().enumerate() {
                let d: [Point<D>; 3] =
                    std::array::from_fn(|j| self.space.eval_node(controls, k, node + 1, j + 1));
                let f = residual(d[0], d[1], d[2]);
                parts.energy += w * h * f * f;
            }
            if let Some(shape) = self.shape {
                for q in 0..NODES_PER_SPAN {
                    let sign = f64::from(shape.signs[k * NODES_PER_SPAN + q]);
                    if sign == 0.0 {
                        continue;
                    }
                    let d: [Point<D>; 3] =
                        std::array::from_fn(|j| self.space.eval_node(controls, k, q, j + 1));
                    let v = sign * residual(d[0], d[1], d[2]) - shape.margin;
                    if v < 0.0 {
                        parts.shape += shape.rho * h * v * v / NODES_PER_SPAN as f64;
                    }
                }
            }
            parts.smoothness += h * self.space.eval_node(controls, k, 0, 3).norm_sq();
        }
        let t2 = self.tolerance * self.tolerance;
        self.bound_errors(controls, |_, _, e, tangent| {
            let slack = t2 - bound_sq(e, tangent);
            parts.barrier += if slack > 0.0 {
                -(slack / t2).ln()
            } else {
                f64::INFINITY
            };
        });
        parts
    }

    /// The Gauss–Newton gradient `g` and matrix `h` of `Ψ_t` at `controls` (overwritten),
    /// gathered span by span in `blocks`.
    pub(crate) fn assemble(
        &self,
        controls: &[Point<D>],
        t: f64,
        blocks: &mut Blocks<D>,
        g: &mut [f64],
        h: &mut BandedSpd,
    ) {
        blocks.clear();
        let space = self.space;
        // The row of `F` at node `q` of span `k` through its derivatives' gradient `grad`.
        let row = |k: usize, q: usize, grad: &[Point<D>; 3]| -> [Point<D>; 4] {
            let weights: [&[f64; 4]; 3] = std::array::from_fn(|j| space.node_weights(k, q, j + 1));
            std::array::from_fn(|c| {
                (0..3).fold(Point::ZERO, |acc, j| acc.add_scaled(weights[j][c], grad[j]))
            })
        };
        for k in 0..space.spans() {
            let width = space.width(k);
            for (node, &w) in GAUSS_WEIGHTS.iter().enumerate() {
                let d: [Point<D>; 3] =
                    std::array::from_fn(|j| space.eval_node(controls, k, node + 1, j + 1));
                let f = residual(d[0], d[1], d[2]);
                let grad = residual_gradient_exact(d);
                blocks.add_square(k, &row(k, node + 1, &grad), t * w * width, f);
            }
            if let Some(shape) = self.shape {
                for q in 0..NODES_PER_SPAN {
                    let sign = f64::from(shape.signs[k * NODES_PER_SPAN + q]);
                    if sign == 0.0 {
                        continue;
                    }
                    let d: [Point<D>; 3] =
                        std::array::from_fn(|j| space.eval_node(controls, k, q, j + 1));
                    let v = sign * residual(d[0], d[1], d[2]) - shape.margin;
                    if v < 0.0 {
                        let grad = residual_gradient_exact(d).map(|p| p * sign);
                        blocks.add_square(
                            k,
                            &row(k, q, &grad),
                            t * shape.rho * width / NODES_PER_SPAN as f64,
                            v,
                        );
                    }
                }
            }
            let third = space.eval_node(controls, k, 0, 3);
            let w3 = space.node_weights(k, 0, 3);
            let weight = t * self.alpha * width;
            blocks.add_gradient(k, &w3.map(|c| third * c), weight);
            blocks.add_isotropic(k, w3, weight);
        }
        let t2 = self.tolerance * self.tolerance;
        self.bound_errors(controls, |k, w, e, tangent| {
            // `e^T P e` with `P = I - (1 - β) τ τ^T` (`τ` held: Gauss–Newton).
            let slack = t2 - bound_sq(e, tangent);
            let pe = e - tangent * ((1.0 - SLAB_ALONG) * e.dot(tangent));
            let along = w.map(|c| pe * c);
            blocks.add_gradient(k, &along, 2.0 / slack);
            blocks.add_square(k, &along, 4.0 / (slack * slack), 0.0);
            blocks.add_isotropic(k, w, 2.0 / slack);
            if self.slab {
                let row = w.map(|c| tangent * c);
                blocks.add_square(k, &row, -2.0 * (1.0 - SLAB_ALONG) / slack, 0.0);
            }
        });
        blocks.scatter(space, self.layout, g, h);
    }

    /// The weighted least-squares terms `sum_i weight_i / 2 |e_i|^2 + λ / 2 R` (the start's
    /// fit), written into `g` and `h`.
    pub(crate) fn assemble_least_squares(
        &self,
        controls: &[Point<D>],
        weights: &[f64],
        lambda: f64,
        g: &mut [f64],
        h: &mut BandedSpd,
    ) {
        g.fill(0.0);
        h.clear();
        let layout = self.layout;
        for k in 0..self.space.spans() {
            let third = self.space.eval_node(controls, k, 0, 3);
            let w3 = *self.space.node_weights(k, 0, 3);
            for axis in 0..D {
                let row = self.span_row(k, |c| unit::<D>(axis) * w3[c]);
                layout.add_square(&row, lambda * self.space.width(k), third[axis], g, h);
            }
        }
        self.errors(controls, |i, k, w, e| {
            for axis in 0..D {
                let row = self.span_row(k, |c| unit::<D>(axis) * w[c]);
                layout.add_square(&row, weights[i], e[axis], g, h);
            }
        });
    }

    /// `κ`, `dκ/ds sqrt(|r'|)` and the arc position at every quadrature node.
    pub(crate) fn node_samples(&self, controls: &[Point<D>]) -> NodeSamples {
        let m = self.space.spans();
        let mut out = NodeSamples {
            curvature: Vec::with_capacity(m * NODES_PER_SPAN),
            rate: Vec::with_capacity(m * NODES_PER_SPAN),
            s: Vec::with_capacity(m * NODES_PER_SPAN),
            length: 0.0,
        };
        let mut start = 0.0;
        for k in 0..m {
            let h = self.space.width(k);
            let mut previous = 0.0;
            let mut position = start;
            let mut speed = self.space.eval_node(controls, k, 0, 1).norm();
            for (q, &s) in NODES.iter().enumerate() {
                let d: [Point<D>; 3] =
                    std::array::from_fn(|j| self.space.eval_node(controls, k, q, j + 1));
                let (kappa, _) = curvature_and_rate(d[0], d[1], d[2]);
                let now = d[0].norm();
                position += 0.5 * (speed + now) * (s - previous) * h;
                (previous, speed) = (s, now);
                out.curvature.push(kappa);
                out.rate.push(residual(d[0], d[1], d[2]));
                out.s.push(position);
            }
            start = position;
        }
        out.length = start;
        out
    }

    /// The distance `|r(u_i) - p_i|` of every point from its parameter's point.
    pub(crate) fn distances(&self, controls: &[Point<D>]) -> Vec<f64> {
        let mut out = vec![0.0; self.points.len()];
        self.errors(controls, |i, _, _, e| out[i] = e.norm());
        out
    }
}

/// The share `β` of the error along the tangent that the slab's bound counts (its square):
/// the bound is `|e_⊥|^2 + β (e . τ)^2 < T^2`, so that a point may lie up to `T / sqrt β`
/// along the tangent from its parameter's point between foot-point updates, and no farther.
const SLAB_ALONG: f64 = 0.25;

/// The squared error the bound counts: `|e|^2 - (1 - β) (e . τ)^2` for the unit tangent `τ`
/// (`|e|^2`, the ball, when `τ` is zero).
pub(crate) fn bound_sq<const D: usize>(e: Point<D>, tangent: Point<D>) -> f64 {
    let along = e.dot(tangent);
    e.norm_sq() - (1.0 - SLAB_ALONG) * along * along
}

/// The unit vector along `axis`.
fn unit<const D: usize>(axis: usize) -> Point<D> {
    let mut p = Point::ZERO;
    p[axis] = 1.0;
    p
}

/// The gradient of [`residual`] with respect to `r'`, `r''` and `r'''` in closed form.
///
/// With `v2 = |r'|^2`, `a = r' . r''` and `F = N v2^(-11/4)`:
///
/// - in the plane, `N = c' v2 - 3 c a` with `c = r' x r''` and `c' = r' x r'''`;
/// - in space, `N = w' v2 - 3 w a` with `w = sqrt(v2 |r''|^2 - a^2)` and
///   `w' = (v2 (r'' . r''') - a (r' . r''')) / w`; where `w` is below `1e-6` of
///   `|r'| |r''|` (a zero of the curvature, where `F` has a corner) the central differences of
///   [`residual_gradient`] stand in.
///
/// Zero where `r' = 0`.
fn residual_gradient_exact<const D: usize>(d: [Point<D>; 3]) -> [Point<D>; 3] {
    let [d1, d2, d3] = d;
    let v2 = d1.norm_sq();
    if !(v2.is_finite() && v2 > 0.0) {
        return [Point::ZERO; 3];
    }
    let a = d1.dot(d2);
    let inv = v2.powf(-2.75);
    let (n, dn) = if D == 2 {
        // `perp(q)` turns `q` a quarter: d/dq (p x q) = perp(p), d/dp (p x q) = -perp(q).
        let perp = |p: Point<D>| {
            let mut out = Point::ZERO;
            out[0] = -p[1];
            out[1] = p[0];
            out
        };
        let c = d1[0] * d2[1] - d1[1] * d2[0];
        let dc = d1[0] * d3[1] - d1[1] * d3[0];
        let n = dc * v2 - 3.0 * c * a;
        let dn1 = -perp(d3) * v2 + d1 * (2.0 * dc) - (-perp(d2) * a + d2 * c) * 3.0;
        let dn2 = (perp(d1) * a + d1 * c) * -3.0;
        let dn3 = perp(d1) * v2;
        (n, [dn1, dn2, dn3])
    } else {
        let q = d2.norm_sq();
        let w = (v2 * q - a * a).max(0.0).sqrt();
        if w.is_nan() || w <= 1e-6 * (v2 * q).sqrt() {
            return residual_gradient(d);
        }
        let (g, h) = (d2.dot(d3), d1.dot(d3));
        let p = v2 * g - a * h;
        let wp = p / w;
        let dw = [
            (d1 * q - d2 * a) * (1.0 / w),
            (d2 * v2 - d1 * a) * (1.0 / w),
            Point::ZERO,
        ];
        let dp = [
            d1 * (2.0 * g) - d2 * h - d3 * a,
            d3 * v2 - d1 * h,
            d2 * v2 - d1 * a,
        ];
        let dv2 = [d1 * 2.0, Point::ZERO, Point::ZERO];
        let da = [d2, d1, Point::ZERO];
        let n = wp * v2 - 3.0 * w * a;
        let dn: [Point<D>; 3] = std::array::from_fn(|j| {
            let dwp = dp[j] * (1.0 / w) - dw[j] * (p / (w * w));
            dwp * v2 + dv2[j] * wp - dw[j] * (3.0 * a) - da[j] * (3.0 * w)
        });
        (n, dn)
    };
    let grad = [
        dn[0] * inv - d1 * (5.5 * n * inv / v2),
        dn[1] * inv,
        dn[2] * inv,
    ];
    if grad.iter().all(|g| g.is_finite()) {
        grad
    } else {
        [Point::ZERO; 3]
    }
}

/// The gradient of [`residual`] with respect to `r'`, `r''` and `r'''`, by central
/// differences with steps relative to each derivative's size.
fn residual_gradient<const D: usize>(d: [Point<D>; 3]) -> [Point<D>; 3] {
    let speed = d[0].norm();
    std::array::from_fn(|j| {
        let scale = match j {
            0 => speed,
            _ => d[j].norm().max(speed),
        };
        let step = DIFFERENCE_STEP * scale.max(f64::MIN_POSITIVE);
        let mut out = Point::ZERO;
        for axis in 0..D {
            let mut plus = d;
            let mut minus = d;
            plus[j][axis] += step;
            minus[j][axis] -= step;
            out[axis] = (residual(plus[0], plus[1], plus[2])
                - residual(minus[0], minus[1], minus[2]))
                / (2.0 * step);
        }
        out
    })
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Derivative triples of many directions and sizes (a fixed xorshift).
    fn triples<const D: usize>() -> Vec<[Point<D>; 3]> {
        let mut state = 0x2545_F491_4F6C_DD1Du64;
        let mut next = move || {
            state ^= state << 13;
            state ^= state >> 7;
            state ^= state << 17;
            (state >> 11) as f64 / (1u64 << 53) as f64 * 2.0 - 1.0
        };
        (0..300)
            .map(|i| {
                let scale = [1.0, 30.0, 900.0][i % 3];
                std::array::from_fn(|j| {
                    let mut p = Point::ZERO;
                    for axis in 0..D {
                        p[axis] = next() * f64::powi(scale, j as i32);
                    }
                    p
                })
            })
            .collect()
    }

    fn agrees<const D: usize>() {
        for d in triples::<D>() {
            let exact = residual_gradient_exact(d);
            let differences = residual_gradient(d);
            // Each part's effect on F, |dF/dr^(j)| |r^(j)|, against the largest of them.
            let size = differences
                .iter()
                .zip(&d)
                .map(|(g, x)| g.norm() * x.norm())
                .fold(0.0_f64, f64::max);
            for j in 0..3 {
                let error = (exact[j] - differences[j]).norm() * d[j].norm();
                assert!(
                    error <= 1e-6 * size,
                    "D = {D}, derivative {j}: {:?} against {:?}",
                    exact[j],
                    differences[j]
                );
            }
        }
    }

    #[test]
    fn exact_gradient_agrees_with_differences_in_the_plane() {
        agrees::<2>();
    }

    #[test]
    fn exact_gradient_agrees_with_differences_in_space() {
        agrees::<3>();
    }
}
