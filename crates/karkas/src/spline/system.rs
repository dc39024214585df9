//! The node slopes of a cubic interpolating spline, factored once: [`SlopeSystem`].
//!
//! The rows (the C^2 conditions and the end conditions, see the [module docs](super)) depend
//! on the knots only, so the system is factored once (Thomas algorithm, plus the
//! Sherman–Morrison vector when periodic) and then solves any number of lines of values: a
//! bicubic surface solves all its columns in one sweep over contiguous grid rows. The
//! right-hand sides are formed on the fly from the differences of the values ([`row_rhs`]),
//! so that values offset far from zero keep their digits.

use super::SplineEnds;

use crate::{Error, Point, Result};

/// Three weighted values `sum w y_k` (an end slope's value part).
pub(super) type Taps = [(usize, f64); 3];

/// The weights of `y_{c-1}, y_c, y_{c+1}` in the right-hand side of the row of unknown `c`
/// (`c - 1` wraps to `p - 1` in a periodic system; a weight beyond the ends is zero).
pub(super) type Weights = [f64; 3];

/// The right-hand side `w_0 y_{c-1} + w_1 y_c + w_2 y_{c+1}` of a row whose weights sum to
/// zero (every row's do: constant values have zero slopes), formed from the differences of
/// the values, `w_2 (y_{c+1} - y_c) - w_0 (y_c - y_{c-1})`: values far from zero (`1e8` plus
/// a ripple) keep their digits, where the weighted sum of the raw values would cancel them.
#[inline]
pub(super) fn row_rhs<const D: usize>(
    ya: Point<D>,
    yc: Point<D>,
    yb: Point<D>,
    w: Weights,
) -> Point<D> {
    (yb - yc) * w[2] - (yc - ya) * w[0]
}

/// `sum w y_k` over `taps` (weights summing to zero), formed from the differences to the
/// middle tap's value, as [`row_rhs`] forms a row's.
#[inline]
pub(super) fn tap_sum<const D: usize>(taps: &Taps, y: impl Fn(usize) -> Point<D>) -> Point<D> {
    let middle = y(taps[1].0);
    taps.iter()
        .fold(Point::ZERO, |s, &(k, w)| s.add_scaled(w, y(k) - middle))
}

/// How the slopes follow from the solved unknowns.
#[derive(Clone, Debug, PartialEq)]
pub(super) enum Shape {
    /// `n == 2` (not-a-knot): both slopes are `delta_0`; `h` is the knot step.
    Segment { h: f64 },
    /// `n == 3` (not-a-knot): the parabola; the middle slope is the three-point derivative
    /// (the single row), the others `2 delta_k - m_1`.
    Parabola { h: [f64; 2] },
    /// Unknowns `m_first..m_first+len` from a tridiagonal system; with not-a-knot ends the
    /// end slopes follow from (3.11), (3.12): `m = a m_near + b m_next + taps`.
    Tridiagonal {
        first: usize,
        ends: Option<[(f64, f64, Taps); 2]>,
    },
    /// Unknowns `m_0..m_{p-1}`, `m_{n-1} = m_0`, cyclic: `m = y - factor z` with
    /// `factor = (y_0 + ratio y_{p-1}) / denom` (Sherman–Morrison).
    Cyclic {
        z: Vec<f64>,
        /// `B^-T v` for the transposed solve.
        zt: Vec<f64>,
        ratio: f64,
        denom: f64,
        corner_bottom: f64,
    },
    /// Periodic with two distinct points: `2 m_0 + m_1 = r_0`, `m_0 + 2 m_1 = r_1`.
    CyclicPair,
    /// Periodic through one point (its value twice, as SciPy's `CubicSpline` takes it): the
    /// constant, every slope zero.
    Constant,
}

/// The rows of a tridiagonal system being assembled.
struct Rows {
    lower: Vec<f64>,
    diag: Vec<f64>,
    upper: Vec<f64>,
    rhs: Vec<Weights>,
}

impl Rows {
    fn with_capacity(n: usize) -> Self {
        Rows {
            lower: Vec::with_capacity(n),
            diag: Vec::with_capacity(n),
            upper: Vec::with_capacity(n),
            rhs: Vec::with_capacity(n),
        }
    }

    /// Appends the row `lower x_{r-1} + diag x_r + upper x_{r+1} = rhs`.
    fn push(&mut self, (lower, diag, upper, rhs): (f64, f64, f64, Weights)) {
        self.lower.push(lower);
        self.diag.push(diag);
        self.upper.push(upper);
        self.rhs.push(rhs);
    }
}

/// The slope equations of a cubic spline on fixed knots, factored once.
#[derive(Clone, Debug, PartialEq)]
pub(crate) struct SlopeSystem {
    pub(super) n: usize,
    pub(super) shape: Shape,
    /// Right-hand side of every unknown's row.
    pub(super) rhs: Vec<Weights>,
    /// `p - 1` for a periodic system (the wrapped neighbour of unknown 0).
    pub(super) wrap: Option<usize>,
    /// Thomas factorization: sub-diagonal, inverse pivots, scaled super-diagonal.
    pub(super) lower: Vec<f64>,
    pub(super) inv_pivot: Vec<f64>,
    pub(super) upper_prime: Vec<f64>,
}

/// The C^2 row of an inner knot between steps `hp` and `hc`: `lambda`, `mu`, and the weights
/// of `3 y'_i`.
fn inner_row(hp: f64, hc: f64) -> (f64, f64, Weights) {
    let lambda = hc / (hp + hc);
    let mu = 1.0 - lambda;
    let weights = [
        -3.0 * lambda / hp,
        3.0 * lambda / hp - 3.0 * mu / hc,
        3.0 * mu / hc,
    ];
    (lambda, mu, weights)
}

/// The rows of not-a-knot ends on `n = h.len() + 1 >= 4` knots: the inner rows with `m_0` and
/// `m_{n-1}` eliminated (3.10), and the end slopes (3.11), (3.12) to recover them.
fn not_a_knot_rows(h: &[f64], rows: &mut Rows) -> Shape {
    let n = h.len() + 1;
    let (gs, ge) = (h[0] / h[1], h[n - 2] / h[n - 3]);
    for k in 1..n - 1 {
        let (lambda, mu, taps) = inner_row(h[k - 1], h[k]);
        rows.push(if k == 1 {
            // y'_1 + 2 g delta_1, eliminated m_0 (3.10).
            let w = mu + 2.0 * gs;
            let weights = [-lambda / h[0], lambda / h[0] - w / h[1], w / h[1]];
            (0.0, 1.0 + gs, gs, weights)
        } else if k == n - 2 {
            let w = lambda + 2.0 * ge;
            let weights = [-w / h[n - 3], w / h[n - 3] - mu / h[n - 2], mu / h[n - 2]];
            (ge, 1.0 + ge, 0.0, weights)
        } else {
            (lambda, 2.0, mu, taps)
        });
    }
    let (gs2, ge2) = (gs * gs, ge * ge);
    // (3.11): m_0 = (g^2 - 1) m_1 + g^2 m_2 + 2 delta_0 - 2 g^2 delta_1.
    let start = (
        gs2 - 1.0,
        gs2,
        [
            (0, -2.0 / h[0]),
            (1, 2.0 / h[0] + 2.0 * gs2 / h[1]),
            (2, -2.0 * gs2 / h[1]),
        ],
    );
    // (3.12): m_{n-1} = (g^2 - 1) m_{n-2} + g^2 m_{n-3} + 2 delta_{n-2} - 2 g^2 delta_{n-3}.
    let end = (
        ge2 - 1.0,
        ge2,
        [
            (n - 1, 2.0 / h[n - 2]),
            (n - 2, -2.0 / h[n - 2] - 2.0 * ge2 / h[n - 3]),
            (n - 3, 2.0 * ge2 / h[n - 3]),
        ],
    );
    Shape::Tridiagonal {
        first: 1,
        ends: Some([start, end]),
    }
}

/// The rows of natural (zero second derivative) or clamped (given slope) ends: every slope an
/// unknown, the end rows `2 m_0 + m_1 = 3 delta_0` or `m_0 = given`.
fn natural_or_clamped_rows(h: &[f64], natural: bool, rows: &mut Rows) -> Shape {
    let n = h.len() + 1;
    let none = [0.0; 3];
    rows.push(if natural {
        (0.0, 2.0, 1.0, [0.0, -3.0 / h[0], 3.0 / h[0]])
    } else {
        (0.0, 1.0, 0.0, none)
    });
    for k in 1..n - 1 {
        let (lambda, mu, taps) = inner_row(h[k - 1], h[k]);
        rows.push((lambda, 2.0, mu, taps));
    }
    rows.push(if natural {
        let hl = h[n - 2];
        (1.0, 2.0, 0.0, [-3.0 / hl, 3.0 / hl, 0.0])
    } else {
        (0.0, 1.0, 0.0, none)
    });
    Shape::Tridiagonal {
        first: 0,
        ends: None,
    }
}

/// The periodic rows of the `p = h.len() >= 2` distinct points; for `p > 2` the corners moved
/// out of the tridiagonal part for Sherman–Morrison (`z`, `zt`, `denom` filled once it is
/// factored, by [`SlopeSystem::finish_cyclic`]).
fn periodic_rows(h: &[f64], rows: &mut Rows) -> Shape {
    let p = h.len();
    for i in 0..p {
        let prev = if i == 0 { p - 1 } else { i - 1 };
        let (lambda, mu, taps) = inner_row(h[prev], h[i]);
        rows.push((lambda, 2.0, mu, taps));
    }
    if p == 2 {
        return Shape::CyclicPair;
    }
    // T = B + w v^T, w = (gamma, 0, .., corner_bottom), v = (1, 0, .., ratio).
    let corner_top = rows.lower[0];
    let corner_bottom = rows.upper[p - 1];
    let gamma = -rows.diag[0];
    rows.lower[0] = 0.0;
    rows.diag[0] -= gamma;
    rows.upper[p - 1] = 0.0;
    rows.diag[p - 1] -= corner_bottom * corner_top / gamma;
    Shape::Cyclic {
        z: Vec::new(),
        zt: Vec::new(),
        ratio: corner_top / gamma,
        denom: 0.0,
        corner_bottom,
    }
}

impl SlopeSystem {
    /// Factors the system of `knots` (strictly increasing, at least 2; periodic through 2
    /// knots: the constant) for the end conditions `ends` (only their kind matters here: clamped slopes
    /// are given to [`solve`](Self::solve)).
    pub(crate) fn new<const D: usize>(knots: &[f64], ends: &SplineEnds<D>) -> Result<Self> {
        let n = knots.len();
        debug_assert!(n >= 2);
        let h: Vec<f64> = knots.windows(2).map(|w| w[1] - w[0]).collect();
        let mut rows = Rows::with_capacity(n);
        let shape = match ends {
            SplineEnds::NotAKnot if n == 2 => Shape::Segment { h: h[0] },
            SplineEnds::NotAKnot if n == 3 => {
                let (_, _, taps) = inner_row(h[0], h[1]);
                rows.push((0.0, 1.0, 0.0, taps.map(|w| w / 3.0)));
                Shape::Parabola { h: [h[0], h[1]] }
            }
            SplineEnds::NotAKnot => not_a_knot_rows(&h, &mut rows),
            SplineEnds::Natural => natural_or_clamped_rows(&h, true, &mut rows),
            SplineEnds::Clamped { .. } => natural_or_clamped_rows(&h, false, &mut rows),
            SplineEnds::Periodic if n == 2 => Shape::Constant,
            SplineEnds::Periodic => periodic_rows(&h, &mut rows),
        };
        let wrap = matches!(ends, SplineEnds::Periodic).then_some(n - 2);
        let mut system = Self::factor(n, shape, wrap, rows)?;
        system.finish_cyclic()?;
        Ok(system)
    }

    /// The Thomas factorization of `rows` in place: the diagonal becomes the inverse pivots,
    /// the super-diagonal the scaled one.
    fn factor(n: usize, shape: Shape, wrap: Option<usize>, rows: Rows) -> Result<Self> {
        let Rows {
            lower,
            diag: mut inv_pivot,
            upper: mut upper_prime,
            rhs,
        } = rows;
        let mut previous = 0.0;
        for r in 0..rhs.len() {
            let pivot = inv_pivot[r] - lower[r] * previous;
            if pivot.abs() <= 1e-300 || !pivot.is_finite() {
                return Err(Error::SingularSystem { row: r, pivot });
            }
            inv_pivot[r] = 1.0 / pivot;
            upper_prime[r] *= inv_pivot[r];
            previous = upper_prime[r];
        }
        Ok(SlopeSystem {
            n,
            shape,
            rhs,
            wrap,
            lower,
            inv_pivot,
            upper_prime,
        })
    }

    /// For a cyclic system (a no-op otherwise), the Sherman–Morrison vectors of the factored
    /// tridiagonal part `B`: `B z = w`, `B^T zt = v`, and `denom = 1 + v . z`.
    fn finish_cyclic(&mut self) -> Result<()> {
        let Shape::Cyclic {
            ratio,
            corner_bottom,
            ..
        } = self.shape
        else {
            return Ok(());
        };
        // B z = w with w = (gamma, 0, .., corner_bottom), gamma = -(diagonal of row 0).
        let p = self.rhs.len();
        let mut w = vec![Point([0.0]); p];
        w[0] = Point([-2.0]);
        w[p - 1] = Point([corner_bottom]);
        self.sweep(&mut w, 1);
        let z: Vec<f64> = w.iter().map(|v| v[0]).collect();
        let denom = 1.0 + z[0] + ratio * z[p - 1];
        if denom.abs() <= 1e-300 || !denom.is_finite() {
            return Err(Error::SingularSystem {
                row: p - 1,
                pivot: denom,
            });
        }
        // B^T zt = v with v = (1, 0, .., ratio).
        let mut zt = vec![0.0; p];
        zt[0] = 1.0;
        zt[p - 1] += ratio;
        self.sweep_transposed(&mut zt);
        self.shape = Shape::Cyclic {
            z,
            zt,
            ratio,
            denom,
            corner_bottom,
        };
        Ok(())
    }

    /// The Thomas sweeps on `width` lines stored k-major (`x[r * width + line]`), in place.
    fn sweep<const D: usize>(&self, x: &mut [Point<D>], width: usize) {
        let len = self.inv_pivot.len();
        for v in &mut x[..width] {
            *v *= self.inv_pivot[0];
        }
        for r in 1..len {
            let (l, ip) = (self.lower[r], self.inv_pivot[r]);
            let (done, rest) = x.split_at_mut(r * width);
            let previous = &done[(r - 1) * width..];
            for (xi, &xp) in rest[..width].iter_mut().zip(previous) {
                *xi = xi.add_scaled(-l, xp) * ip;
            }
        }
        for r in (0..len.saturating_sub(1)).rev() {
            let c = self.upper_prime[r];
            let (head, tail) = x.split_at_mut((r + 1) * width);
            for (xi, &xn) in head[r * width..].iter_mut().zip(&tail[..width]) {
                *xi = xi.add_scaled(-c, xn);
            }
        }
    }

    /// Solves for the slopes of `width` lines of values stored k-major
    /// (`values[k * width + line]`, `k < n`), writing `slopes` in the same layout. `O(n width)`.
    /// `clamped` gives the end slopes of clamped ends (the same for every line).
    pub(crate) fn solve<const D: usize>(
        &self,
        values: &[Point<D>],
        slopes: &mut [Point<D>],
        width: usize,
        clamped: Option<(Point<D>, Point<D>)>,
    ) {
        let n = self.n;
        debug_assert!(values.len() == n * width && slopes.len() == n * width);
        let delta = |k: usize, h: f64, line: usize| {
            (values[(k + 1) * width + line] - values[k * width + line]) * (1.0 / h)
        };
        let first = match &self.shape {
            Shape::Tridiagonal { first, .. } => *first,
            Shape::Parabola { .. } => 1,
            Shape::Constant => {
                slopes.fill(Point::ZERO);
                return;
            }
            Shape::Segment { h } => {
                for line in 0..width {
                    let d = delta(0, *h, line);
                    slopes[line] = d;
                    slopes[width + line] = d;
                }
                return;
            }
            _ => 0,
        };
        self.form_rhs(values, slopes, width, first);
        let span = first * width..(first + self.rhs.len()) * width;
        match &self.shape {
            Shape::Segment { .. } | Shape::Constant => {}
            Shape::Parabola { h } => {
                for line in 0..width {
                    let m1 = slopes[width + line];
                    slopes[line] = (delta(0, h[0], line) * 2.0) - m1;
                    slopes[2 * width + line] = (delta(1, h[1], line) * 2.0) - m1;
                }
            }
            Shape::CyclicPair => {
                for line in 0..width {
                    let (r0, r1) = (slopes[line], slopes[width + line]);
                    slopes[line] = (r0 * 2.0 - r1) * (1.0 / 3.0);
                    slopes[width + line] = (r1 * 2.0 - r0) * (1.0 / 3.0);
                    slopes[2 * width + line] = slopes[line];
                }
            }
            Shape::Cyclic {
                z, ratio, denom, ..
            } => {
                self.sweep(&mut slopes[span], width);
                self.correct_cyclic(slopes, width, z, *ratio, *denom);
            }
            Shape::Tridiagonal { ends, .. } => {
                if let (Some((start, end)), None) = (clamped, ends) {
                    for line in 0..width {
                        slopes[line] = start;
                        slopes[(n - 1) * width + line] = end;
                    }
                }
                self.sweep(&mut slopes[span], width);
                if let Some(ends) = ends {
                    self.not_a_knot_end_slopes(values, slopes, width, ends);
                }
            }
        }
    }

    /// The right-hand sides of the rows, formed row by row over all lines (contiguous), into
    /// the rows' unknowns `first..first + rhs.len()` of `slopes`.
    fn form_rhs<const D: usize>(
        &self,
        values: &[Point<D>],
        slopes: &mut [Point<D>],
        width: usize,
        first: usize,
    ) {
        let line_of = |k: usize| &values[k * width..(k + 1) * width];
        for (r, w) in self.rhs.iter().enumerate() {
            let c = first + r;
            let prev = match (c, self.wrap) {
                (0, Some(p)) => Some(p),
                (0, None) => None,
                _ => Some(c - 1),
            };
            let row = &mut slopes[c * width..(c + 1) * width];
            let center = line_of(c);
            match (prev, c + 1 < self.n) {
                (Some(pk), true) => {
                    let (a, b) = (line_of(pk), line_of(c + 1));
                    for (((s, &ya), &yc), &yb) in row.iter_mut().zip(a).zip(center).zip(b) {
                        *s = row_rhs(ya, yc, yb, *w);
                    }
                }
                (Some(pk), false) => {
                    for ((s, &ya), &yc) in row.iter_mut().zip(line_of(pk)).zip(center) {
                        *s = row_rhs(ya, yc, yc, *w);
                    }
                }
                (None, _) => {
                    for ((s, &yc), &yb) in row.iter_mut().zip(center).zip(line_of(c + 1)) {
                        *s = row_rhs(yc, yc, yb, *w);
                    }
                }
            }
        }
    }

    /// The Sherman–Morrison correction of the cyclic solve, `m = y - factor z` with
    /// `factor = (y_0 + ratio y_{p-1}) / denom`, and the repeated last slope `m_{n-1} = m_0`.
    fn correct_cyclic<const D: usize>(
        &self,
        slopes: &mut [Point<D>],
        width: usize,
        z: &[f64],
        ratio: f64,
        denom: f64,
    ) {
        let p = z.len();
        for line in 0..width {
            let factor = (slopes[line] + slopes[(p - 1) * width + line] * ratio) * (1.0 / denom);
            for (k, &zk) in z.iter().enumerate() {
                let s = &mut slopes[k * width + line];
                *s = s.add_scaled(-zk, factor);
            }
            slopes[(self.n - 1) * width + line] = slopes[line];
        }
    }

    /// The not-a-knot end slopes (3.11), (3.12) from the solved ones:
    /// `m = a m_near + b m_next + taps`.
    fn not_a_knot_end_slopes<const D: usize>(
        &self,
        values: &[Point<D>],
        slopes: &mut [Point<D>],
        width: usize,
        [start, end]: &[(f64, f64, Taps); 2],
    ) {
        let n = self.n;
        for line in 0..width {
            let combine = |taps: &Taps| tap_sum(taps, |k| values[k * width + line]);
            let (a, b, taps) = start;
            slopes[line] =
                (slopes[width + line] * *a + slopes[2 * width + line] * *b) + combine(taps);
            let (a, b, taps) = end;
            slopes[(n - 1) * width + line] = (slopes[(n - 2) * width + line] * *a
                + slopes[(n - 3) * width + line] * *b)
                + combine(taps);
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn p(x: f64) -> Point<1> {
        Point([x])
    }

    #[test]
    fn cubics_are_reproduced_by_not_a_knot() {
        // Not-a-knot reproduces every cubic exactly, on any knots.
        let f = |t: f64| 1.0 - 2.0 * t + 0.5 * t * t - 0.3 * t * t * t;
        let df = |t: f64| -2.0 + t - 0.9 * t * t;
        for n in [2usize, 3, 4, 5, 9] {
            let knots: Vec<f64> = (0..n).map(|k| (k as f64).powf(1.3) * 0.7 - 0.2).collect();
            let values: Vec<Point<1>> = knots.iter().map(|&t| p(f(t))).collect();
            let mut m = vec![p(0.0); n];
            let system = SlopeSystem::new(&knots, &SplineEnds::<1>::NotAKnot).unwrap();
            system.solve(&values, &mut m, 1, None);
            if n >= 4 {
                for (t, mk) in knots.iter().zip(&m) {
                    assert!(
                        (mk[0] - df(*t)).abs() < 1e-12,
                        "n={n}: {} vs {}",
                        mk[0],
                        df(*t)
                    );
                }
            }
        }
    }

    #[test]
    fn many_lines_at_once_equal_one_at_a_time() {
        // The layout of a grid's columns (k-major, lines contiguous) against single lines.
        for knots in [
            &[0.0, 0.3, 1.0, 1.2, 2.0, 2.9][..],
            &[0.0, 1.0, 1.5],
            &[0.0, 2.0],
        ] {
            let (n, width) = (knots.len(), 4);
            let mut values: Vec<Point<1>> = (0..n * width)
                .map(|k| p(((k * 7 % 11) as f64).sin()))
                .collect();
            for line in 0..width {
                values[(n - 1) * width + line] = values[line]; // periodic-ready
            }
            let mut all_ends: Vec<SplineEnds<1>> = vec![SplineEnds::NotAKnot, SplineEnds::Natural];
            if n >= 3 {
                all_ends.push(SplineEnds::Periodic);
            }
            for ends in all_ends {
                let system = SlopeSystem::new(knots, &ends).unwrap();
                let mut all = vec![p(0.0); n * width];
                system.solve(&values, &mut all, width, None);
                for line in 0..width {
                    let one: Vec<Point<1>> = (0..n).map(|k| values[k * width + line]).collect();
                    let mut m = vec![p(0.0); n];
                    system.solve(&one, &mut m, 1, None);
                    for k in 0..n {
                        assert!((m[k][0] - all[k * width + line][0]).abs() < 1e-14);
                    }
                }
            }
        }
    }
}
