//! The unknowns of the fairer: which controls are free, held, or free along one direction
//! only, and where each one's unknowns sit in the banded systems.
//!
//! Control `j` is `base_j + E_j x_j` with `x_j` its own unknowns: `D` of them when free, none
//! when held (a kept end), one when it may only slide along a fixed direction (the second
//! control of a kept tangent). The unknowns are numbered control by control in the order of
//! the curve, or, for a periodic space, interleaved from both ends (`0, m-1, 1, m-2, ...`),
//! which turns the wrapped band of a closed curve into an ordinary band about twice as wide
//! and keeps every solve banded (`O(m)`).

use crate::solve::BandedSpd;
use crate::Point;

/// How one control depends on the unknowns.
#[derive(Clone, Copy, Debug)]
pub(crate) enum Control<const D: usize> {
    /// `D` unknowns: the control itself.
    Free,
    /// No unknown: the control is this point.
    Held(Point<D>),
    /// One unknown `beta`: the control is `base + beta direction`.
    Along {
        /// The point at `beta = 0`.
        base: Point<D>,
        /// The direction.
        direction: Point<D>,
    },
}

/// The unknowns of every control and the band of their systems.
#[derive(Clone, Debug)]
pub(crate) struct Layout<const D: usize> {
    kinds: Vec<Control<D>>,
    offsets: Vec<usize>,
    size: usize,
    width: usize,
}

/// A linear function of the controls: the four controls of a span with a coefficient vector
/// each.
pub(crate) type Row<const D: usize> = [(usize, Point<D>); 4];

impl<const D: usize> Layout<D> {
    /// The layout of `kinds`, whose rows touch four consecutive controls (wrapping around
    /// when `closed`).
    pub(crate) fn new(kinds: Vec<Control<D>>, closed: bool) -> Self {
        let n = kinds.len();
        let order: Vec<usize> = if closed {
            (0..n)
                .map(|i| if i % 2 == 0 { i / 2 } else { n - 1 - i / 2 })
                .collect()
        } else {
            (0..n).collect()
        };
        let mut offsets = vec![0; n];
        let mut size = 0;
        for &j in &order {
            offsets[j] = size;
            size += Self::count(&kinds[j]);
        }
        let spans = if closed { n } else { n.saturating_sub(3) };
        let mut width = 1;
        for k in 0..spans {
            let (mut lo, mut hi) = (usize::MAX, 0);
            for c in 0..4 {
                let j = (k + c) % n;
                let count = Self::count(&kinds[j]);
                if count > 0 {
                    lo = lo.min(offsets[j]);
                    hi = hi.max(offsets[j] + count);
                }
            }
            if hi > lo {
                width = width.max(hi - lo);
            }
        }
        Layout {
            kinds,
            offsets,
            size,
            width,
        }
    }

    fn count(kind: &Control<D>) -> usize {
        match kind {
            Control::Free => D,
            Control::Held(_) => 0,
            Control::Along { .. } => 1,
        }
    }

    /// The number of unknowns.
    pub(crate) fn size(&self) -> usize {
        self.size
    }

    /// The number of stored diagonals of the systems.
    pub(crate) fn width(&self) -> usize {
        self.width
    }

    /// The unknowns of `controls` (free ones as they are, sliding ones by their projection on
    /// the direction).
    pub(crate) fn unknowns(&self, controls: &[Point<D>]) -> Vec<f64> {
        let mut x = vec![0.0; self.size];
        for (j, kind) in self.kinds.iter().enumerate() {
            let o = self.offsets[j];
            match kind {
                Control::Free => x[o..o + D].copy_from_slice(&controls[j].0),
                Control::Held(_) => {}
                Control::Along { base, direction } => {
                    x[o] = (controls[j] - *base).dot(*direction) / direction.norm_sq();
                }
            }
        }
        x
    }

    /// The controls of the unknowns `x`, written into `out`.
    pub(crate) fn controls_into(&self, x: &[f64], out: &mut [Point<D>]) {
        for (j, kind) in self.kinds.iter().enumerate() {
            let o = self.offsets[j];
            out[j] = match kind {
                Control::Free => {
                    let mut p = Point::ZERO;
                    p.0.copy_from_slice(&x[o..o + D]);
                    p
                }
                Control::Held(p) => *p,
                Control::Along { base, direction } => base.add_scaled(x[o], *direction),
            };
        }
    }

    /// The unknown that axis `axis` of control `j` moves with, and its coefficient (`None`
    /// for a held control).
    #[inline]
    pub(crate) fn unknown(&self, j: usize, axis: usize) -> Option<(usize, f64)> {
        let o = self.offsets[j];
        match self.kinds[j] {
            Control::Free => Some((o + axis, 1.0)),
            Control::Held(_) => None,
            Control::Along { direction, .. } => Some((o, direction[axis])),
        }
    }

    /// The unknowns a row touches with their coefficients (at most `4 D`), written into
    /// `out`; returns how many.
    fn scatter(&self, row: &Row<D>, out: &mut [(usize, f64); 32]) -> usize {
        let mut len = 0;
        for &(j, v) in row {
            let o = self.offsets[j];
            match self.kinds[j] {
                Control::Free => {
                    for d in 0..D {
                        out[len] = (o + d, v[d]);
                        len += 1;
                    }
                }
                Control::Held(_) => {}
                Control::Along { direction, .. } => {
                    out[len] = (o, v.dot(direction));
                    len += 1;
                }
            }
        }
        len
    }

    /// Adds `weight * residual * row` to the gradient `g` and `weight * row row^T` to the
    /// matrix `h` (the Gauss–Newton terms of `weight / 2 * residual^2`).
    pub(crate) fn add_square(
        &self,
        row: &Row<D>,
        weight: f64,
        residual: f64,
        g: &mut [f64],
        h: &mut BandedSpd,
    ) {
        let mut entries = [(0, 0.0); 32];
        let len = self.scatter(row, &mut entries);
        let entries = &entries[..len];
        for (a, &(i, vi)) in entries.iter().enumerate() {
            g[i] += weight * residual * vi;
            h.add(i, i, weight * vi * vi);
            for &(j, vj) in &entries[..a] {
                // A pair of distinct entries on one unknown (a control serving a span twice
                // on a short closed curve) adds twice to its diagonal.
                let twice = if i == j { 2.0 } else { 1.0 };
                h.add(i, j, twice * weight * vi * vj);
            }
        }
    }
}
