//! Discrete periodic splines with vector poles: closed discrete curves in R^D (Malozemov et al.'s §1 and
//! §3; docs/methods.md §3).

use super::interpolation::InterpolationPlan;
use super::period::check_period;
use super::smoothing::{broken_line, raise_order};
use crate::{Error, Point, Result};

/// A discrete `N`-periodic spline of order `r` with vector poles,
/// `S_r(j) = sum_{p=0}^{m-1} a_p Q_r(j - p n)`, `N = m n`.
///
/// It is a point set, the `N` values `S_r(0..N)`: joined by segments they make a closed
/// polygon, the discrete curve of the paper. For every `j` the weights `Q_r(j - p n)` are
/// non-negative and sum to 1, so each value is a convex combination of the poles and the curve
/// lies in their convex hull. Order `r` is the discrete analogue of a spline of degree
/// `2r - 1` (`r = 2` is "cubic").
///
/// ```
/// use karkas::dps::DiscreteSpline;
/// use karkas::Point;
/// // The four corners of a square as poles, order 2, 8 values per pole.
/// let poles = [Point([0.0, 0.0]), Point([1.0, 0.0]), Point([1.0, 1.0]), Point([0.0, 1.0])];
/// let spline = DiscreteSpline::from_poles(&poles, 2, 8).unwrap();
/// let mut values = vec![Point::ZERO; spline.period()];
/// spline.values(&mut values);
/// // A rounded square inside the square, symmetric about its centre.
/// assert!(values.iter().all(|v| v[0] > 0.0 && v[0] < 1.0 && v[1] > 0.0 && v[1] < 1.0));
/// let opposite = values[0] + values[16];
/// assert!(opposite.distance(Point([1.0, 1.0])) < 1e-14);
/// ```
#[derive(Clone, Debug, PartialEq)]
pub struct DiscreteSpline<const D: usize> {
    poles: Vec<Point<D>>,
    order: usize,
    n: usize,
}

impl<const D: usize> DiscreteSpline<D> {
    /// The spline of order `order` with poles `poles` (`m = poles.len()`) and step `n`.
    ///
    /// Errors: fewer than 2 poles, `n < 2`, `order` outside `1..=`[`MAX_ORDER`](super::MAX_ORDER),
    /// a non-finite pole, `m n` overflowing.
    ///
    /// # Examples
    ///
    /// ```
    /// use karkas::dps::DiscreteSpline;
    /// use karkas::Point;
    ///
    /// let poles = [[0.0, 0.0], [1.0, 0.0], [1.0, 1.0], [0.0, 1.0]].map(Point);
    /// let spline = DiscreteSpline::from_poles(&poles, 2, 5)?;
    /// assert_eq!(spline.period(), 20); // m n values per period
    /// assert_eq!(spline.to_values().len(), 20);
    /// assert!(DiscreteSpline::from_poles(&poles, 2, 1).is_err()); // n < 2
    /// # Ok::<(), karkas::Error>(())
    /// ```
    pub fn from_poles(poles: &[Point<D>], order: usize, n: usize) -> Result<Self> {
        check_period(poles.len(), n, order, "a discrete periodic spline")?;
        if let Some(index) = poles.iter().position(|p| !p.is_finite()) {
            return Err(Error::NonFinitePoint { index });
        }
        Ok(DiscreteSpline {
            poles: poles.to_vec(),
            order,
            n,
        })
    }

    /// The spline of order `order` and step `n` through `nodes`: `S_r(l n) = nodes[l]` for
    /// `l` in `0..m` (problem (1) of the paper, solved by the DFT formula in `O(m log m + N)`,
    /// see [`InterpolationPlan`]).
    ///
    /// Among all `N`-periodic sequences `x` with `x(l n) = nodes[l]` it has the least
    /// `sum_j ||Delta^r x(j)||^2` (the extremal property of the paper).
    ///
    /// Errors: as [`from_poles`](Self::from_poles).
    ///
    /// ```
    /// use karkas::dps::DiscreteSpline;
    /// use karkas::Point;
    ///
    /// // A closed discrete curve of order 3 through 6 nodes, 10 values between nodes.
    /// let nodes: Vec<Point<2>> = (0..6)
    ///     .map(|k| {
    ///         let a = std::f64::consts::TAU * k as f64 / 6.0;
    ///         Point([a.cos(), a.sin()])
    ///     })
    ///     .collect();
    /// let spline = DiscreteSpline::interpolating(&nodes, 3, 10)?;
    /// assert_eq!(spline.poles().len(), 6);
    /// # Ok::<(), karkas::Error>(())
    /// ```
    pub fn interpolating(nodes: &[Point<D>], order: usize, n: usize) -> Result<Self> {
        let mut plan = InterpolationPlan::new(nodes.len(), n, order)?;
        let mut poles = vec![Point::ZERO; nodes.len()];
        plan.poles_into(nodes, &mut poles)?;
        Ok(DiscreteSpline { poles, order, n })
    }

    /// The poles `a_0..a_{m-1}`.
    pub fn poles(&self) -> &[Point<D>] {
        &self.poles
    }

    /// The order `r`.
    pub fn order(&self) -> usize {
        self.order
    }

    /// The step `n`: values per pole, the distance between nodes `l n`.
    pub fn step(&self) -> usize {
        self.n
    }

    /// The period `N = m n`: the number of values.
    pub fn period(&self) -> usize {
        self.poles.len() * self.n
    }

    /// Writes the values `S_r(0), ..., S_r(N - 1)` into `out`.
    ///
    /// `O(r N)` by the recurrence of the paper with moving sums (see the module docs); besides
    /// `out` it uses one scratch buffer of `n - 1` points.
    ///
    /// # Panics
    /// When `out.len()` is not the [`period`](Self::period).
    pub fn values(&self, out: &mut [Point<D>]) {
        assert_eq!(
            out.len(),
            self.period(),
            "the output buffer must hold one period"
        );
        let mut scratch = Vec::with_capacity(self.n - 1);
        evaluate_into(&self.poles, self.n, self.order, out, &mut scratch);
    }

    /// The values `S_r(0), ..., S_r(N - 1)` in a new vector (see [`values`](Self::values)).
    pub fn to_values(&self) -> Vec<Point<D>> {
        let mut out = vec![Point::ZERO; self.period()];
        self.values(&mut out);
        out
    }
}

/// `S_r(0..N)` of the poles into `out` (`out.len() == poles.len() * n`, checked by callers);
/// `scratch` holds `n - 1` points after the call.
pub(crate) fn evaluate_into<const D: usize>(
    poles: &[Point<D>],
    n: usize,
    order: usize,
    out: &mut [Point<D>],
    scratch: &mut Vec<Point<D>>,
) {
    broken_line(poles, n, out);
    for _ in 1..order {
        raise_order(out, n, scratch);
    }
}

/// The discrete `N`-periodic B-spline `Q_r(0), ..., Q_r(N - 1)` of order `order` for `m`
/// poles and step `n` (`N = m n`), in `O(r N)`.
///
/// `Q_1` is the hat `1 - |j|/n` of half-width `n`, `Q_v = (1/n) Q_1 (*) Q_{v-1}`. It is
/// non-negative, symmetric (`Q_r(j) = Q_r(N - j)`), and its shifts by multiples of `n` sum to 1.
///
/// ```
/// let q = karkas::dps::discrete_bspline(4, 2, 1).unwrap();
/// assert_eq!(q, [1.0, 0.5, 0.0, 0.0, 0.0, 0.0, 0.0, 0.5]);
/// ```
///
/// Errors: `m < 2`, `n < 2`, `order` outside `1..=`[`MAX_ORDER`](super::MAX_ORDER), `m n`
/// overflowing.
pub fn discrete_bspline(m: usize, n: usize, order: usize) -> Result<Vec<f64>> {
    let period = check_period(m, n, order, "a discrete periodic B-spline")?;
    let mut poles = vec![Point([0.0]); m];
    poles[0] = Point([1.0]);
    let mut values = vec![Point([0.0]); period];
    let mut scratch = Vec::with_capacity(n - 1);
    evaluate_into(&poles, n, order, &mut values, &mut scratch);
    // Where Q_r vanishes the moving sums leave rounding residue of either sign (~1e-17);
    // the true values are non-negative, so clamping only moves a value towards its true one.
    Ok(values.into_iter().map(|v| v[0].max(0.0)).collect())
}
