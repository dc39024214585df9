//! The conditioning of a parameterization: the measure (2.4) of the continuation system (2.3)
//! of Kuznetsov and Filatov (docs/methods.md §5), for a parameterized surface.
//!
//! Along a surface `W(u, v)` the parameter differentials are `du = alpha . dx`,
//! `dv = beta . dx` (2.1), where `alpha`, `beta` are the dual basis of the tangents `W_u`,
//! `W_v` in the tangent plane (`alpha . W_u = 1`, `alpha . W_v = 0`, `beta . W_u = 0`,
//! `beta . W_v = 1`, both orthogonal to the unit normal `n`); the continuation system is
//! `[alpha; beta; n] dx = (du, dv, 0)` (2.3). The paper measures its conditioning by
//! `|D| = |Delta| / d` (2.4), the determinant over the product of the row norms, for *unit*
//! `alpha`, `beta` (2.2); Theorem 2.1: the best conditioning, `|D| = 1`, is reached exactly
//! when `u`, `v` are arc lengths along two orthogonal directions.
//!
//! A parameterized surface does not keep its rows unit (a stretched parameter scales a row),
//! so karkas extends (2.4) to any rows as the inverse 2-norm condition number
//!
//! `kappa^-1 = sigma_min / sigma_max` of `[alpha; beta; n]`
//!
//! (the same as that of `[W_u W_v n]`, its inverse). With `s_1 >= s_2` the singular values
//! of the Jacobian `[W_u W_v]` (square roots of the eigenvalues of the first fundamental form
//! `[[E, F], [F, G]]`) and the unit normal contributing `1`, it is
//! `min(1, s_2) / max(1, s_1)`: equal to `1` exactly when `E = G = 1`, `F = 0` (Theorem 2.1's
//! arc lengths along orthogonal directions) and below `1` otherwise, `0` where the tangents
//! are parallel. Closed forms: tangents of unit length at an angle `theta` give
//! `tan(theta / 2)` (for unit rows this is `|D| / (1 + sqrt(1 - D^2))`, increasing with the
//! paper's `|D| = sin theta`); orthogonal tangents of lengths `a`, `b` give
//! `min(1, a, b) / max(1, a, b)`. `O(1)` per point, `O(N M)` per grid.
//!
//! The paper's own measure is kept beside it ([`paper_condition_measure`]): with the rows
//! scaled to unit length, `|D| = |det [alpha; beta; n]|` is the sine of the angle between the
//! rows, which (each row being orthogonal to the other tangent) is the sine of the angle
//! between `W_u` and `W_v`: `|D| = sqrt(E G - F^2) / sqrt(E G)`. It sees skew only, not
//! stretch, which is why the extension above is what karkas reports first.

use crate::core::Grid;
use crate::Point;

/// The condition measure of the continuation system of a parameterization with tangents
/// `wu = W_u`, `wv = W_v` at a point: `min(1, s_2) / max(1, s_1)` for the singular values
/// `s_1 >= s_2` of `[W_u W_v]` (the module's extension of (2.4) to rows of any length), in
/// `[0, 1]`, `1` exactly for unit orthogonal tangents. A non-finite tangent gives NaN.
pub fn condition_measure<const D: usize>(wu: Point<D>, wv: Point<D>) -> f64 {
    let (e, f, g) = (wu.dot(wu), wu.dot(wv), wv.dot(wv));
    let mean = 0.5 * (e + g);
    let radius = (0.25 * (e - g) * (e - g) + f * f).sqrt();
    let largest = mean + radius;
    // det = s_1^2 s_2^2, so the smaller eigenvalue without cancellation.
    let det = (e * g - f * f).max(0.0);
    let smallest = if largest > 0.0 { det / largest } else { 0.0 };
    let (s1, s2) = (largest.sqrt(), smallest.sqrt());
    s2.min(1.0) / s1.max(1.0)
}

/// Kuznetsov and Filatov's measure (2.4) itself at a point with tangents `wu = W_u`,
/// `wv = W_v`: `|D| = |Delta| / d` for the rows `alpha`, `beta` of (2.3) scaled to unit
/// length, which is `|sin theta|` for the angle `theta` between `W_u` and `W_v`,
/// `sqrt(E G - F^2) / sqrt(E G)`. In `[0, 1]`: `1` for orthogonal tangents of any lengths,
/// `0` for parallel ones or a zero tangent; NaN for a non-finite tangent. Unlike
/// [`condition_measure`] it does not see stretched parameters (unit rows are the paper's
/// premise (2.2)).
///
/// # Examples
///
/// ```
/// use karkas::param::{condition_measure, paper_condition_measure};
/// use karkas::Point3;
///
/// let (wu, wv) = (Point3::new([2.0, 0.0, 0.0]), Point3::new([1.0, 1.0, 0.0]));
/// // 45 degrees apart: |D| = sin 45; the extension also sees the stretch of W_u.
/// assert!((paper_condition_measure(wu, wv) - 0.5f64.sqrt()).abs() < 1e-15);
/// assert!(condition_measure(wu, wv) < 0.5);
/// ```
pub fn paper_condition_measure<const D: usize>(wu: Point<D>, wv: Point<D>) -> f64 {
    let (Some(a), Some(b)) = (unit_direction(wu), unit_direction(wv)) else {
        return if is_finite(wu) && is_finite(wv) {
            0.0
        } else {
            f64::NAN
        };
    };
    // For unit a, b at an angle theta: |a - b| = 2 sin(theta / 2), |a + b| = 2 cos(theta / 2),
    // so their product over 2 is sin theta, accurate for small and near-straight angles alike
    // (unlike sqrt(1 - cos^2)).
    ((a - b).norm() * (a + b).norm() * 0.5).min(1.0)
}

/// `p` scaled to unit length without overflow or underflow (divided by its largest
/// component first, so that any finite `p` from 1e-300 to 1e300 works); `None` for a zero or
/// non-finite `p`.
fn unit_direction<const D: usize>(p: Point<D>) -> Option<Point<D>> {
    let largest = p.max_abs();
    if !(largest.is_finite() && largest > 0.0) {
        return None;
    }
    let scaled = p * (1.0 / largest);
    Some(scaled * (1.0 / scaled.norm()))
}

fn is_finite<const D: usize>(p: Point<D>) -> bool {
    p.0.iter().all(|c| c.is_finite())
}

/// The condition measures of a grid of nodes, summarized.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct ConditionSummary {
    /// The smallest measure (the worst conditioned node).
    pub min: f64,
    /// The mean measure over the nodes.
    pub mean: f64,
    /// The worst node `(i, j)` (the first of the smallest).
    pub worst: (usize, usize),
    /// How many nodes were summarized.
    pub nodes: usize,
}

impl ConditionSummary {
    /// The summary of `measures` over rows `0..rows` and columns `0..cols` (a closed
    /// direction passes one less than stored, so that its seam counts once). A NaN measure
    /// counts as the worst. `None` for an empty range.
    ///
    /// # Examples
    ///
    /// ```
    /// use karkas::param::ConditionSummary;
    /// use karkas::Grid;
    ///
    /// let measures = Grid::from_row_major(2, 2, vec![1.0, 0.5, 0.9, 0.7])?;
    /// let summary = ConditionSummary::of(&measures, 2, 2).expect("four nodes");
    /// assert_eq!((summary.min, summary.worst, summary.nodes), (0.5, (0, 1), 4));
    /// assert!(ConditionSummary::of(&measures, 0, 2).is_none());
    /// # Ok::<(), karkas::Error>(())
    /// ```
    pub fn of(measures: &Grid<f64>, rows: usize, cols: usize) -> Option<ConditionSummary> {
        let (rows, cols) = (rows.min(measures.rows()), cols.min(measures.cols()));
        let nodes = rows * cols;
        if nodes == 0 {
            return None;
        }
        let (mut min, mut worst, mut sum) = (measures.row(0)[0], (0, 0), 0.0);
        for i in 0..rows {
            for (j, &m) in measures.row(i)[..cols].iter().enumerate() {
                sum += m;
                if m < min || (m.is_nan() && !min.is_nan()) {
                    (min, worst) = (m, (i, j));
                }
            }
        }
        Some(ConditionSummary {
            min,
            mean: sum / nodes as f64,
            worst,
            nodes,
        })
    }
}

/// The measures of every node of a grid from its tangents `(W_u, W_v)`, row-major, by
/// `measure` ([`condition_measure`] or [`paper_condition_measure`]).
pub(super) fn node_measures<const D: usize>(
    rows: usize,
    cols: usize,
    tangents: impl Fn(usize, usize) -> (Point<D>, Point<D>),
    measure: fn(Point<D>, Point<D>) -> f64,
) -> Grid<f64> {
    Grid::from_fn(rows, cols, |i, j| {
        let (wu, wv) = tangents(i, j);
        measure(wu, wv)
    })
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::Point3;

    #[test]
    fn closed_forms_of_the_measure() {
        let (ex, ey) = (Point3::new([1.0, 0.0, 0.0]), Point3::new([0.0, 1.0, 0.0]));
        assert_eq!(condition_measure(ex, ey), 1.0);
        for deg in [15.0f64, 30.0, 60.0, 89.0, 120.0] {
            let t = deg.to_radians();
            let skew = ex * t.cos() + ey * t.sin();
            let expected = if deg <= 90.0 {
                (t / 2.0).tan()
            } else {
                ((std::f64::consts::PI - t) / 2.0).tan()
            };
            assert!(
                (condition_measure(ex, skew) - expected).abs() < 1e-15,
                "{deg}"
            );
        }
        assert!((condition_measure(ex * 2.5, ey) - 0.4).abs() < 1e-16);
        assert!((condition_measure(ex * 0.5, ey * 3.0) - 0.5 / 3.0).abs() < 1e-16);
        assert_eq!(condition_measure(ex, ex * 2.0), 0.0);
        assert_eq!(condition_measure(Point3::ZERO, ey), 0.0);
    }

    #[test]
    fn the_papers_measure_is_the_sine_of_the_angle_between_the_tangents() {
        // Checked against the determinant of (2.3) with the dual rows scaled to unit length.
        let (ex, ey) = (Point3::new([1.0, 0.0, 0.0]), Point3::new([0.0, 1.0, 0.0]));
        let n = Point3::new([0.0, 0.0, 1.0]);
        for (deg, a, b) in [
            (90.0f64, 1.0, 1.0),
            (60.0, 2.0, 0.5),
            (15.0, 3.0, 7.0),
            (120.0, 1.0, 0.1),
        ] {
            let t = deg.to_radians();
            let (wu, wv) = (ex * a, (ex * t.cos() + ey * t.sin()) * b);
            // Dual rows in the plane: alpha . wv = 0, beta . wu = 0, each then unit.
            let alpha = Point3::new([wv.0[1], -wv.0[0], 0.0]);
            let beta = Point3::new([wu.0[1], -wu.0[0], 0.0]);
            let (alpha, beta) = (alpha * (1.0 / alpha.norm()), beta * (1.0 / beta.norm()));
            let det = alpha.0[0] * (beta.0[1] * n.0[2] - beta.0[2] * n.0[1])
                - alpha.0[1] * (beta.0[0] * n.0[2] - beta.0[2] * n.0[0])
                + alpha.0[2] * (beta.0[0] * n.0[1] - beta.0[1] * n.0[0]);
            let d = paper_condition_measure(wu, wv);
            assert!((d - det.abs()).abs() < 1e-15, "{deg}: {d} vs {det}");
            assert!((d - t.sin().abs()).abs() < 1e-15, "{deg}");
        }
        // Blind to stretch, where the extension is not.
        assert_eq!(paper_condition_measure(ex * 5.0, ey), 1.0);
        assert!((condition_measure(ex * 5.0, ey) - 0.2).abs() < 1e-16);
        assert_eq!(paper_condition_measure(ex, ex * 2.0), 0.0);
        assert_eq!(paper_condition_measure(Point3::ZERO, ey), 0.0);
        assert!(paper_condition_measure(Point3::new([f64::NAN, 0.0, 0.0]), ey).is_nan());
    }

    #[test]
    fn the_papers_measure_does_not_depend_on_the_scale_of_the_tangents() {
        // The sine of an angle: the same for tangents of 1e-150 and 1e150 as for unit ones,
        // where forming E G directly underflows to 0 or overflows to NaN.
        let t = 50f64.to_radians();
        let (wu, wv) = (
            Point3::new([1.0, 0.2, -0.3]),
            Point3::new([t.cos(), t.sin(), 0.4]),
        );
        let unit = paper_condition_measure(wu, wv);
        let (a, b) = (wu * (1.0 / wu.norm()), wv * (1.0 / wv.norm()));
        let cross = Point3::new([
            a.0[1] * b.0[2] - a.0[2] * b.0[1],
            a.0[2] * b.0[0] - a.0[0] * b.0[2],
            a.0[0] * b.0[1] - a.0[1] * b.0[0],
        ]);
        assert!(
            (unit - cross.norm()).abs() < 1e-15,
            "{unit} vs {}",
            cross.norm()
        );
        for scale in [1e-300, 1e-150, 1e-20, 1e20, 1e150, 1e300] {
            let d = paper_condition_measure(wu * scale, wv * scale);
            assert!((d - unit).abs() < 1e-15, "scale {scale}: {d} vs {unit}");
            let d = paper_condition_measure(wu * scale, wv);
            assert!(
                (d - unit).abs() < 1e-15,
                "one tangent scaled by {scale}: {d}"
            );
        }
        // Small angles keep their digits (1e-9 rad; sqrt(1 - cos^2) would give 0 or 1.5e-8).
        let tiny =
            paper_condition_measure(Point3::new([1.0, 0.0, 0.0]), Point3::new([1.0, 1e-9, 0.0]));
        assert!((tiny - 1e-9).abs() < 1e-22, "{tiny}");
        assert!(paper_condition_measure(Point3::new([f64::INFINITY, 0.0, 0.0]), wv).is_nan());
    }

    #[test]
    fn summary_finds_the_worst_node_and_skips_the_seam() {
        let g = Grid::from_fn(2, 3, |i, j| [[1.0, 0.5, 0.9], [0.8, 1.0, 0.2]][i][j]);
        let s = ConditionSummary::of(&g, 2, 3).unwrap();
        assert_eq!((s.min, s.worst, s.nodes), (0.2, (1, 2), 6));
        assert!((s.mean - 4.4 / 6.0).abs() < 1e-15);
        let s = ConditionSummary::of(&g, 2, 2).unwrap();
        assert_eq!((s.min, s.worst, s.nodes), (0.5, (0, 1), 4));
        assert_eq!(ConditionSummary::of(&g, 0, 2), None);
    }
}
