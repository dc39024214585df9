//! Interpolating cubic-spline curves through points at given parameters: how the curves of a
//! [`PointNetwork`](super::PointNetwork) are made by default.
//!
//! On the piece `[t_l, t_{l+1}]` the spline is
//! `S(t) = (1 - s) p_l + s p_{l+1} + h^2/6 [((1 - s)^3 - (1 - s)) M_l + (s^3 - s) M_{l+1}]`
//! with the second derivatives `M` from one tridiagonal solve (`O(K)`, the system of
//! [`SplineBlending`](super::SplineBlending) with vector right-hand sides). Not-a-knot ends
//! reproduce cubics, so values are `O(h^4)` and tangents `O(h^3)` accurate for smooth data,
//! at the ends too; periodic ends close the curve `C^2`.

use super::blending::{check_nodes, SplineEnds, SplineSystem};
use crate::core::{Curve, Interval, PiecewiseCurve, Side};
use crate::{Error, Point, Result};

/// A `C^2` cubic spline through points `p_k` at parameters `t_k`.
#[derive(Clone, Debug, PartialEq)]
pub struct CubicSplineCurve<const D: usize> {
    system: SplineSystem,
    /// `p_0..p_{K-1}` (closed: the first repeated last).
    values: Vec<Point<D>>,
    /// `M_0..M_{K-1}` (closed: the first repeated last).
    second: Vec<Point<D>>,
}

impl<const D: usize> CubicSplineCurve<D> {
    /// The spline through `points` at `params` (strictly increasing, one per point).
    ///
    /// With [`SplineEnds::Periodic`] the curve is closed: the last point must repeat the first
    /// (to a relative `1e-12`) and the last parameter closes the period.
    ///
    /// Errors: fewer than two points (four with the repeat when periodic), lengths that
    /// differ, a non-finite coordinate, parameters not finite and strictly increasing, a
    /// periodic curve whose last point differs from its first.
    pub fn new(points: &[Point<D>], params: &[f64], ends: SplineEnds) -> Result<Self> {
        if points.len() != params.len() {
            return Err(Error::InvalidInput(format!(
                "a spline curve needs one parameter per point: {} points, {} parameters",
                points.len(),
                params.len()
            )));
        }
        let needed = if ends == SplineEnds::Periodic { 4 } else { 2 };
        check_nodes(params, needed, "a cubic spline curve")?;
        if let Some(index) = points.iter().position(|p| !p.is_finite()) {
            return Err(Error::NonFinitePoint { index });
        }
        let mut values = points.to_vec();
        let count = values.len();
        if ends == SplineEnds::Periodic {
            let scale = values.iter().fold(1.0f64, |m, p| m.max(p.max_abs()));
            if (values[0] - values[count - 1]).max_abs() > 1e-12 * scale {
                return Err(Error::InvalidInput(
                    "a periodic spline curve needs its last point to repeat the first".into(),
                ));
            }
            values[count - 1] = values[0];
        }
        let system = SplineSystem::new(params, ends);
        let second = Self::second_derivatives(&system, &values)?;
        Ok(CubicSplineCurve {
            system,
            values,
            second,
        })
    }

    /// The spline through `points` at the uniform parameters `k / (K - 1)`, `K` points: the
    /// parameter is proportional to the point index, from 0 to 1.
    pub fn uniform(points: &[Point<D>], ends: SplineEnds) -> Result<Self> {
        let k = points.len().max(2);
        let params: Vec<f64> = (0..points.len())
            .map(|i| i as f64 / (k - 1) as f64)
            .collect();
        Self::new(points, &params, ends)
    }

    /// `M` at every point: one tridiagonal solve (not-a-knot on two or three points is the
    /// line or the parabola through them).
    fn second_derivatives(system: &SplineSystem, values: &[Point<D>]) -> Result<Vec<Point<D>>> {
        let count = values.len();
        let t = system.nodes();
        if system_is_polynomial(system) {
            let m = if count == 3 {
                // 2 f[t0, t1, t2].
                let d0 = (values[1] - values[0]) * (t[1] - t[0]).recip();
                let d1 = (values[2] - values[1]) * (t[2] - t[1]).recip();
                (d1 - d0) * (2.0 / (t[2] - t[0]))
            } else {
                Point::ZERO
            };
            return Ok(vec![m; count]);
        }
        let periodic = system.is_periodic();
        let distinct = system.count();
        let offset = system.offset();
        let mut rhs: Vec<Point<D>> = (0..system.unknowns())
            .map(|p| {
                let r = p + offset;
                let (lower, diag, upper) = system.full_row(r).1;
                let y = |i: usize| values[i % distinct];
                let mut sum = y(r) * diag;
                if lower != 0.0 {
                    sum = sum.add_scaled(lower, y((r + distinct - 1) % distinct));
                }
                if upper != 0.0 {
                    sum = sum.add_scaled(upper, y(r + 1));
                }
                sum
            })
            .collect();
        system.solve(&mut rhs, false)?;
        let mut second = vec![Point::ZERO; count];
        second[offset..offset + rhs.len()].copy_from_slice(&rhs);
        if system.offset() == 1 {
            let [e0, f0, e1, f1] = system.not_a_knot_ends();
            second[0] = second[1] * e0 + second[2] * f0;
            second[count - 1] = second[count - 2] * e1 + second[count - 3] * f1;
        }
        if periodic {
            second[count - 1] = second[0];
        }
        Ok(second)
    }

    /// The points.
    pub fn points(&self) -> &[Point<D>] {
        &self.values
    }

    /// The parameters of the points.
    pub fn params(&self) -> &[f64] {
        self.system.nodes()
    }

    fn deriv_at(&self, t: f64, k: usize, side: Side) -> Point<D> {
        let nodes = self.system.nodes();
        let mut t = t;
        // The piece below a node: evaluate just inside it (the pieces are polynomials, so
        // moving by an ulp changes nothing but the piece).
        if side == Side::Below && t > nodes[0] && nodes.contains(&t) {
            t = next_down(t);
        }
        let Some(local) = self.system.local(t, k) else {
            return Point::ZERO;
        };
        // `values` and `second` repeat the first entry last when closed, so the piece's upper
        // end is always at `l + 1`.
        let (l, next) = (local.l, local.l + 1);
        (self.values[l] * local.a.0)
            .add_scaled(local.a.1, self.values[next])
            .add_scaled(local.c.0, self.second[l])
            .add_scaled(local.c.1, self.second[next])
    }
}

/// The largest `f64` below the finite `t`.
fn next_down(t: f64) -> f64 {
    if t == 0.0 {
        -f64::from_bits(1)
    } else if t > 0.0 {
        f64::from_bits(t.to_bits() - 1)
    } else {
        f64::from_bits(t.to_bits() + 1)
    }
}

/// Not-a-knot on two or three points: no system, the interpolating polynomial.
fn system_is_polynomial(system: &SplineSystem) -> bool {
    system.offset() == 1 && system.count() <= 3
}

impl<const D: usize> Curve<D> for CubicSplineCurve<D> {
    fn domain(&self) -> Interval {
        self.system.domain()
    }

    fn is_closed(&self) -> bool {
        self.system.is_periodic()
    }

    fn eval(&self, t: f64) -> Point<D> {
        self.deriv_at(t, 0, Side::Above)
    }

    fn deriv(&self, t: f64, k: usize) -> Point<D> {
        self.deriv_at(t, k, Side::Above)
    }

    fn polynomial_pieces(&self) -> Option<crate::bspline::PolynomialPieces> {
        Some(crate::bspline::PolynomialPieces::uniform_continuity(
            3,
            self.system.nodes().to_vec(),
            2,
        ))
    }
}

impl<const D: usize> PiecewiseCurve<D> for CubicSplineCurve<D> {
    fn breakpoints(&self) -> Vec<f64> {
        self.system.nodes().to_vec()
    }

    fn continuity(&self) -> usize {
        2
    }

    fn deriv_on_side(&self, t: f64, k: usize, side: Side) -> Point<D> {
        self.deriv_at(t, k, side)
    }
}
