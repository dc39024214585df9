//! The two alternating steps of a closed fit (docs/methods.md §4, "Closed curves"): the
//! least-squares periodic spline with the foot parameters held (a cyclic band solved with
//! [`BorderedSpd`]), each point's error measured in the squared-distance metric
//! `N N^T + w T T^T` of the last curve (Wang, Pottmann and Liu's squared-distance
//! minimization: the along-curve part, which the next projection removes, weighted by `w`
//! only; `w = 1` is the paper's plain alternation), and the projection of every point onto
//! the closed curve, its parameter wrapping over the period.
//!
//! The period `[0, 1]` has the knots `0 = T_0 < ... < T_M = 1`; the unknowns are `R_L, H_L`
//! of the knots `L = 0..M-1` (knot `M` is knot 0). Piece `k` joins knots `k` and `k + 1`
//! (mod `M`), the jump `J_L` (Pavlov's formula (2)) knots `L - 1, L, L + 1` (mod `M`), so the
//! seam knot 0 carries a jump like any other. Ordering knots 0 and `M - 1` last leaves the
//! others a band of 6 diagonals: nothing couples knot 1 with knot `M - 2` directly.

use super::hermite::{bending_gram, hermite_basis, jump_coefficients, HermiteSpline};
use crate::solve::BorderedSpd;
use crate::{Point, Result};

/// Newton steps of a foot-point projection, at most.
const PROJECTION_STEPS: usize = 30;

/// The normal equations of a periodic defect-2 spline on fixed knots, the `D` coordinates
/// of every coefficient side by side (the squared-distance terms couple them).
pub(crate) struct PeriodicSystem<const D: usize> {
    knots: Vec<f64>,
    matrix: BorderedSpd,
    rhs: Vec<f64>,
}

impl<const D: usize> PeriodicSystem<D> {
    /// The system on `knots` (`0 = T_0 < ... < T_M = 1`, `M >= 2`).
    pub(crate) fn new(knots: &[f64]) -> Self {
        let m = knots.len() - 1;
        PeriodicSystem {
            knots: knots.to_vec(),
            matrix: BorderedSpd::new(2 * D * (m - 2), 6 * D, 4 * D),
            rhs: vec![0.0; 2 * D * m],
        }
    }

    fn pieces(&self) -> usize {
        self.knots.len() - 1
    }

    /// The first row of unknown `part` (0: value, 1: derivative) of knot `knot` (mod `M`);
    /// its `D` coordinates follow.
    fn index(&self, knot: usize, part: usize) -> usize {
        let m = self.pieces();
        let knot = knot % m;
        let slot = if knot == 0 {
            m - 2
        } else if knot == m - 1 {
            m - 1
        } else {
            knot - 1
        };
        (2 * slot + part) * D
    }

    /// The rows of the coefficients `[R_a, H_a, R_b, H_b, ...]` of consecutive knots from
    /// `first` (mod `M`).
    fn rows<const K: usize>(&self, first: usize) -> [usize; K] {
        std::array::from_fn(|a| self.index(first + a / 2, a % 2))
    }

    /// Adds `weight (c c^T) (x) W` on `rows` (`W` the `D x D` metric; a row met twice, when
    /// the period has two pieces, gets both products).
    fn add_outer(&mut self, rows: &[usize], c: &[f64], weight: f64, metric: &[[f64; D]; D]) {
        for a in 0..rows.len() {
            for b in 0..=a {
                let mut v = weight * c[a] * c[b];
                if a != b && rows[a] == rows[b] {
                    v *= 2.0;
                }
                for (x, metric_row) in metric.iter().enumerate() {
                    for (y, &w) in metric_row.iter().enumerate() {
                        // Within one coefficient pair only the lower triangle once.
                        if (a != b || x >= y) && w != 0.0 {
                            self.matrix.add(rows[a] + x, rows[b] + y, v * w);
                        }
                    }
                }
            }
        }
    }

    /// Solves for the spline nearest the points at `params` (in `[0, 1)`) in the metric of
    /// each point (`tangents`: the squared-distance metric `N N^T + w T T^T` with the unit
    /// tangent `T` of the last curve at the point; `None` or the first point: the
    /// identity), plus `p sum_L delta_L |J_L|^2` (`deltas` per knot `0..M`) and
    /// `lambda int |R''|^2`.
    #[allow(clippy::needless_range_loop)] // knots mod M index the rows and deltas alike
    pub fn solve(
        &mut self,
        points: &[Point<D>],
        params: &[f64],
        tangents: Option<(&[Point<D>], f64)>,
        deltas: &[f64],
        p: f64,
        lambda: f64,
    ) -> Result<HermiteSpline<D>> {
        let m = self.pieces();
        self.matrix.clear();
        self.rhs.fill(0.0);
        let identity: [[f64; D]; D] =
            std::array::from_fn(|x| std::array::from_fn(|y| if x == y { 1.0 } else { 0.0 }));
        let shape = HermiteSpline::<D>::from_parts(
            self.knots.clone(),
            vec![Point::ZERO; m + 1],
            vec![Point::ZERO; m + 1],
        );
        let mut hint = 0;
        for (i, (r, &t)) in points.iter().zip(params).enumerate() {
            let k = shape.piece_near(t, hint).min(m - 1);
            hint = k;
            let h = self.knots[k + 1] - self.knots[k];
            let b = hermite_basis((t - self.knots[k]) / h, h, 0);
            let rows: [usize; 4] = self.rows(k);
            let metric = match tangents {
                Some((tangents, w)) if i > 0 => {
                    let u = tangents[i];
                    std::array::from_fn(|x| {
                        std::array::from_fn(|y| identity[x][y] - (1.0 - w) * u[x] * u[y])
                    })
                }
                _ => identity,
            };
            self.add_outer(&rows, &b, 1.0, &metric);
            let wr: [f64; D] = std::array::from_fn(|x| (0..D).map(|y| metric[x][y] * r[y]).sum());
            for (a, &row) in rows.iter().enumerate() {
                for (x, v) in wr.iter().enumerate() {
                    self.rhs[row + x] += b[a] * v;
                }
            }
        }
        for k in 0..m {
            let h = self.knots[k + 1] - self.knots[k];
            if lambda > 0.0 {
                let g = bending_gram(h);
                let rows: [usize; 4] = self.rows(k);
                for a in 0..4 {
                    for b in 0..=a {
                        for x in 0..D {
                            self.matrix.add(rows[a] + x, rows[b] + x, lambda * g[a][b]);
                        }
                    }
                }
            }
            if p > 0.0 && deltas[k] > 0.0 {
                let c = jump_coefficients(self.piece_before(k), h);
                let rows: [usize; 6] = self.rows(k + m - 1);
                self.add_outer(&rows, &c, p * deltas[k], &identity);
            }
        }
        self.matrix.factor()?;
        self.matrix.solve_factored(&mut self.rhs);
        let mut values = vec![Point::ZERO; m + 1];
        let mut derivatives = vec![Point::ZERO; m + 1];
        for knot in 0..m {
            let (v, d) = (self.index(knot, 0), self.index(knot, 1));
            values[knot] = Point(std::array::from_fn(|x| self.rhs[v + x]));
            derivatives[knot] = Point(std::array::from_fn(|x| self.rhs[d + x]));
        }
        values[m] = values[0];
        derivatives[m] = derivatives[0];
        Ok(HermiteSpline::from_parts(
            self.knots.clone(),
            values,
            derivatives,
        ))
    }

    /// The length of the piece before knot `k` (mod `M`).
    fn piece_before(&self, k: usize) -> f64 {
        let m = self.pieces();
        let before = (k + m - 1) % m;
        self.knots[before + 1] - self.knots[before]
    }
}

/// `J_L` at every knot `0..M` of a periodic spline (knot `M` is knot 0).
pub(crate) fn periodic_jumps<const D: usize>(spline: &HermiteSpline<D>) -> Vec<Point<D>> {
    let knots = spline.knots();
    let m = knots.len() - 1;
    (0..m)
        .map(|l| {
            let before = (l + m - 1) % m;
            let c = jump_coefficients(knots[before + 1] - knots[before], knots[l + 1] - knots[l]);
            let q = |knot: usize, part: usize| {
                let knot = knot % m;
                if part == 0 {
                    spline.values()[knot]
                } else {
                    spline.derivatives()[knot]
                }
            };
            (0..6).fold(Point::ZERO, |j, a| {
                j.add_scaled(c[a], q(l + m - 1 + a / 2, a % 2))
            })
        })
        .collect()
}

/// The value and first two derivatives of the closed `spline` at `t` taken mod 1.
fn jet<const D: usize>(spline: &HermiteSpline<D>, t: f64) -> [Point<D>; 3] {
    let (k, s) = spline.locate(t.rem_euclid(1.0));
    std::array::from_fn(|order| spline.deriv_on_piece(k, s, order))
}

/// The foot parameter of `r` on the closed `spline` nearest `t` (Newton's method on
/// `(R(t) - r) . R'(t) = 0` with halving, the parameter wrapping over the period), in
/// `[0, 1)`, and the distance.
pub(crate) fn periodic_foot_point<const D: usize>(
    spline: &HermiteSpline<D>,
    r: Point<D>,
    mut t: f64,
) -> (f64, f64) {
    let [mut value, mut first, mut second] = jet(spline, t);
    let mut distance = value.distance(r);
    for _ in 0..PROJECTION_STEPS {
        let residual = value - r;
        let g = residual.dot(first);
        let curvature = first.norm_sq() + residual.dot(second);
        let speed = first.norm_sq();
        if speed.is_nan() || speed <= 0.0 {
            break;
        }
        let mut step = -g / if curvature > 0.0 { curvature } else { speed };
        step = step.clamp(-0.25, 0.25);
        let mut moved = false;
        for _ in 0..40 {
            let [v, d1, d2] = jet(spline, t + step);
            let dist = v.distance(r);
            if dist <= distance {
                (value, first, second, distance) = (v, d1, d2, dist);
                t += step;
                moved = true;
                break;
            }
            step *= 0.5;
        }
        if !moved || step.abs() < 1e-15 {
            break;
        }
    }
    (t.rem_euclid(1.0), distance)
}
