//! The fast path of plane sections of LL surfaces (Aulchenko et al., formula (21); docs/methods.md §1.4).
//!
//! When the grid is laid out as in the paper, `x` depends on the row only (`x_ij = x_i`), and
//! so does every linear function `n . r_ij` that is constant along each row. The LL surface
//! then gives `n . P(u, v) = f(u)`, where `f` is the LL curve of the row values `f_i`: on
//! segment `i`, `f(xi) = (f_{i-1} + f_i)/2 + xi (f_i - f_{i-1}) + h(xi) (f_{i-1} + f_{i+1} -
//! 2 f_i)/2` (formula (21)), and the section `n . p = c` is the set of lines `u = u*` with
//! `f(u*) = c`. The same holds with rows and columns swapped.
//!
//! Roots are found exactly, not by sampling: `f'(xi) = B + h'(xi) C` and `h'` increases on
//! `[0, 1]` (`h'' >= 0`), so `f` is convex or concave on every segment. Each segment is split at
//! its stationary point (found by bisection on `f'`) into at most two monotone pieces, and each
//! piece holds at most one root, found by bisection to the last bit. `O(Kx Ky)` for the test
//! that the function is constant along rows, `O(Kx)` bisections for the roots.

use super::kernel::LlKernel;
use super::surface::LlSurface;
use crate::core::{Grid, ParameterLine};
use crate::Point;

/// Relative size under which a spread of values along a row counts as rounding.
const CONSTANT_ALONG_LINE: f64 = 1e-13;

/// Relative size under which a value of `f - c` counts as zero at a piece's end.
const ROOT_AT_END: f64 = 1e-13;

impl<const D: usize> LlSurface<D> {
    /// The lines where `normal . P = level` when `normal . r_ij` is constant along every row
    /// (lines `u = const`) or along every column (lines `v = const`) of the extended grid.
    pub(super) fn level_lines(&self, normal: Point<D>, level: f64) -> Option<Vec<ParameterLine>> {
        if !normal.is_finite() || !level.is_finite() {
            return None;
        }
        let grid = self.extended();
        let scale = normal.0.iter().map(|c| c.abs()).sum::<f64>()
            * grid
                .as_slice()
                .iter()
                .fold(0.0f64, |m, p| m.max(p.max_abs()));
        let spread_limit = CONSTANT_ALONG_LINE * scale.max(f64::MIN_POSITIVE);
        if let Some(values) = values_along(grid, normal, spread_limit, false) {
            let axis = self.axis_u();
            let us = level_roots(self.kernel(), &values, level, scale, axis.is_closed())?;
            return Some(us.into_iter().map(ParameterLine::U).collect());
        }
        if let Some(values) = values_along(grid, normal, spread_limit, true) {
            let axis = self.axis_v();
            let vs = level_roots(self.kernel(), &values, level, scale, axis.is_closed())?;
            return Some(vs.into_iter().map(ParameterLine::V).collect());
        }
        None
    }
}

/// The value of `normal . r` on every row (or, with `by_column`, every column) of `grid`, if
/// it is constant along each to within `spread_limit`.
fn values_along<const D: usize>(
    grid: &Grid<Point<D>>,
    normal: Point<D>,
    spread_limit: f64,
    by_column: bool,
) -> Option<Vec<f64>> {
    let (lines, along) = if by_column {
        (grid.cols(), grid.rows())
    } else {
        (grid.rows(), grid.cols())
    };
    let at = |line: usize, k: usize| {
        let p = if by_column {
            grid.get(k, line)
        } else {
            grid.get(line, k)
        };
        normal.dot(*p)
    };
    let mut values = Vec::with_capacity(lines);
    for line in 0..lines {
        let first = at(line, 0);
        let (mut lo, mut hi) = (first, first);
        for k in 1..along {
            let f = at(line, k);
            lo = lo.min(f);
            hi = hi.max(f);
        }
        let constant = hi - lo <= spread_limit; // false for NaN too
        if !constant {
            return None;
        }
        values.push(0.5 * lo + 0.5 * hi);
    }
    Some(values)
}

/// The parameters `t` in the working domain where the LL curve of the extended values
/// `values` (`f_0..f_{K+1}`) equals `level`, ascending, without repeats. `None` when the curve
/// equals `level` over a whole segment.
fn level_roots(
    kernel: &LlKernel,
    values: &[f64],
    level: f64,
    scale: f64,
    closed: bool,
) -> Option<Vec<f64>> {
    let nodes = values.len() - 2;
    let step = 1.0 / (nodes + 1) as f64;
    let zero = ROOT_AT_END * (scale + level.abs()).max(f64::MIN_POSITIVE);
    let mut roots: Vec<f64> = Vec::new();
    for i in 1..=nodes {
        // Formula (21): f(xi) = a + xi b + h(xi) c on segment i.
        let a = 0.5 * (values[i - 1] + values[i]) - level;
        let b = values[i] - values[i - 1];
        let c = 0.5 * (values[i - 1] + values[i + 1] - 2.0 * values[i]);
        if a.abs() <= zero && b.abs() <= zero && c.abs() <= zero {
            return None;
        }
        // The working domain covers half of the first and of the last segment.
        let lo = if i == 1 { 0.5 } else { 0.0 };
        let hi = if i == nodes { 0.5 } else { 1.0 };
        let f = |xi: f64| a + xi * b + kernel.h(xi) * c;
        let slope = |xi: f64| b + kernel.derivative(xi, 1) * c;
        for xi in segment_roots(&f, &slope, lo, hi, zero) {
            roots.push((i as f64 - 0.5 + xi) * step);
        }
    }
    roots.sort_by(f64::total_cmp);
    let period = (nodes - 1) as f64 * step;
    let first = roots.first().copied();
    roots.dedup_by(|b, a| (*b - *a).abs() <= 1e-12);
    if closed {
        // The domain end is the domain start again.
        if let (Some(first), Some(&last)) = (first, roots.last()) {
            if roots.len() > 1 && (last - period - first).abs() <= 1e-12 {
                roots.pop();
            }
        }
    }
    Some(roots)
}

/// The roots of `f` on `[lo, hi]`, given that `slope` (its derivative) is monotone there: at
/// most two. Values within `zero` of 0 at a piece's end count as roots.
fn segment_roots(
    f: &impl Fn(f64) -> f64,
    slope: &impl Fn(f64) -> f64,
    lo: f64,
    hi: f64,
    zero: f64,
) -> Vec<f64> {
    let mut cuts = vec![lo];
    let (s_lo, s_hi) = (slope(lo), slope(hi));
    if (s_lo < 0.0 && s_hi > 0.0) || (s_lo > 0.0 && s_hi < 0.0) {
        cuts.push(bisect(slope, lo, hi, s_lo));
    }
    cuts.push(hi);
    let mut roots = Vec::new();
    for piece in cuts.windows(2) {
        let (a, b) = (piece[0], piece[1]);
        let (fa, fb) = (f(a), f(b));
        if fa.abs() <= zero {
            roots.push(a);
        } else if fb.abs() <= zero {
            roots.push(b);
        } else if (fa < 0.0) != (fb < 0.0) {
            roots.push(bisect(f, a, b, fa));
        }
    }
    roots.dedup_by(|b, a| (*b - *a).abs() <= 1e-15);
    roots
}

/// A sign change of the monotone `g` in `[a, b]` (`ga = g(a)`), bisected to the last bit.
fn bisect(g: &impl Fn(f64) -> f64, mut a: f64, mut b: f64, ga: f64) -> f64 {
    let below = ga < 0.0;
    for _ in 0..128 {
        let m = 0.5 * (a + b);
        if m <= a || m >= b {
            break;
        }
        let gm = g(m);
        if gm == 0.0 {
            return m;
        }
        if (gm < 0.0) == below {
            a = m;
        } else {
            b = m;
        }
    }
    0.5 * (a + b)
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::Surface;

    /// A cone-like grid whose x depends on the row only and is not monotone.
    fn hump() -> Grid<Point<3>> {
        let xs = [0.0, 1.0, 3.0, 4.0, 3.5, 2.0, 1.0];
        Grid::from_fn(xs.len(), 5, |i, j| {
            let a = j as f64;
            Point([xs[i], (1.0 + i as f64) * a.cos(), a.sin()])
        })
    }

    #[test]
    fn roots_solve_the_1d_equation_and_find_both_branches() {
        let s = LlSurface::new(&hump(), 3, false, false).unwrap();
        let normal = Point([1.0, 0.0, 0.0]);
        // x = 2.5 is crossed on the way up and on the way down.
        let lines = s.level_lines(normal, 2.5).unwrap();
        assert_eq!(lines.len(), 2);
        for line in lines {
            let ParameterLine::U(u) = line else {
                panic!("expected u lines")
            };
            for k in 0..7 {
                let v = s.domain_v().uniform(k, 7);
                assert!((s.eval(u, v)[0] - 2.5).abs() < 1e-12);
            }
        }
        // The ends of the domain are roots too; beyond the maximum there are none.
        assert_eq!(s.level_lines(normal, 0.0).unwrap().len(), 1);
        assert!(s.level_lines(normal, 10.0).unwrap().is_empty());
        // y varies along rows: no fast path.
        assert!(s.level_lines(Point([0.0, 1.0, 0.0]), 0.5).is_none());
    }

    #[test]
    fn a_segment_lying_in_the_plane_gives_up() {
        let g = Grid::from_fn(5, 4, |i, j| Point([(i.min(2)) as f64, j as f64, 0.0]));
        let s = LlSurface::new(&g, 2, false, false).unwrap();
        assert!(s.level_lines(Point([1.0, 0.0, 0.0]), 2.0).is_none());
    }
}
