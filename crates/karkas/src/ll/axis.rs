//! The uniform parameter grid of one LL direction (Aulchenko et al.; docs/methods.md §1.2).
//!
//! With `K` nodes, `Delta = 1/(K+1)` and node `i` (1-based) sits at `t_i = i Delta`. Segment
//! `i` covers `t` in `[t_i - Delta/2, t_i + Delta/2]` with the local coordinate
//! `xi = t (K+1) - i + 1/2` in `[0, 1]`. The working domain is `[Delta, 1 - Delta]`: from the
//! first node to the last. For a closed direction node `K` repeats node 1, so the domain is
//! exactly one period.

use crate::core::{Interval, Side};

/// Relative distance (in `s = t (K+1) + 1/2`) within which a parameter counts as lying on a
/// segment border. A breakpoint `(i - 1/2)/(K+1)` does not survive the product with `K+1`
/// (nor the period wrap of a closed direction) exactly: without this, about one border in
/// twenty-five was given to the wrong segment.
const BORDER_ULPS: f64 = 8.0 * f64::EPSILON;

/// The uniform nodes of one parameter direction.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct NodeAxis {
    nodes: usize,
    closed: bool,
}

impl NodeAxis {
    /// `nodes` = K (counting the repeated node of a closed direction), `nodes >= 2`.
    pub(crate) fn new(nodes: usize, closed: bool) -> Self {
        debug_assert!(nodes >= 2);
        NodeAxis { nodes, closed }
    }

    /// The number of nodes K (a closed direction counts node 1 twice, as node 1 and node K).
    #[inline]
    pub fn nodes(&self) -> usize {
        self.nodes
    }

    /// True when the direction is periodic.
    #[inline]
    pub fn is_closed(&self) -> bool {
        self.closed
    }

    /// `K + 1`: the factor from `d/dt` to `d/dxi`.
    #[inline]
    pub fn scale(&self) -> f64 {
        (self.nodes + 1) as f64
    }

    /// `Delta = 1/(K+1)`.
    #[inline]
    pub fn spacing(&self) -> f64 {
        1.0 / self.scale()
    }

    /// The parameter of node `i` (1-based, `1..=K`): `i / (K+1)`.
    #[inline]
    pub fn node(&self, i: usize) -> f64 {
        i as f64 / self.scale()
    }

    /// The working domain `[Delta, K Delta]`.
    #[inline]
    pub fn domain(&self) -> Interval {
        Interval::new(self.node(1), self.node(self.nodes))
    }

    /// `t` brought into the domain: wrapped by the period when closed, clamped when open.
    #[inline]
    pub fn reduce(&self, t: f64) -> f64 {
        let d = self.domain();
        if self.closed {
            d.wrap(t)
        } else {
            d.clamp(t)
        }
    }

    /// The segment `i` in `1..=K` holding `t` (after [`reduce`](Self::reduce)) and the local
    /// coordinate `xi` in `[0, 1]`. A border belongs to the segment above it.
    #[inline]
    pub fn locate(&self, t: f64) -> (usize, f64) {
        let s = self.reduce(t) * self.scale() + 0.5;
        // After `reduce`, s >= 1.5, so truncation is the floor (and far cheaper than
        // `f64::floor`, a libm call on baseline x86-64). `as usize` saturates (NaN -> 0), so
        // the clamp keeps the index valid for any input.
        let mut i = s as usize;
        // A border that came out a few ulp low (see `BORDER_ULPS`) still belongs above.
        if (i + 1) as f64 - s <= BORDER_ULPS * s {
            i += 1;
        }
        let i = i.clamp(1, self.nodes);
        (i, s - i as f64)
    }

    /// Like [`locate`](Self::locate), but a parameter on a segment border is given to the
    /// segment on `side` of it (`xi = 1` on the segment below).
    #[inline]
    pub fn locate_on_side(&self, t: f64, side: Side) -> (usize, f64) {
        let mut s = self.reduce(t) * self.scale() + 0.5;
        // Snap a parameter within rounding of a border onto it, so that `side` decides.
        let nearest = (s + 0.5) as usize as f64;
        if (s - nearest).abs() <= BORDER_ULPS * s {
            s = nearest;
        }
        let below = (s.ceil() as usize).saturating_sub(1);
        let raw = match side {
            Side::Above => s.floor() as usize,
            Side::Below => below,
        };
        let i = raw.clamp(1, self.nodes);
        (i, s - i as f64)
    }

    /// The domain ends and the segment borders between them, ascending.
    pub fn breakpoints(&self) -> Vec<f64> {
        let mut b = vec![self.node(1)];
        b.extend((2..=self.nodes).map(|i| (i as f64 - 0.5) / self.scale()));
        b.push(self.node(self.nodes));
        b
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn locate_follows_the_paper() {
        let a = NodeAxis::new(5, false); // Delta = 1/6
        assert_eq!(a.domain(), Interval::new(1.0 / 6.0, 5.0 / 6.0));
        let (i, xi) = a.locate(2.0 / 6.0);
        assert_eq!(i, 2);
        assert!((xi - 0.5).abs() < 1e-14);
        let border = 2.5 / 6.0;
        assert_eq!(a.locate_on_side(border, Side::Above).0, 3);
        let (i, xi) = a.locate_on_side(border, Side::Below);
        assert_eq!(i, 2);
        assert!((xi - 1.0).abs() < 1e-14);
        assert_eq!(a.locate(f64::NAN).0, 1);
        assert_eq!(a.locate(-3.0), (1, 0.5));
        assert_eq!(a.breakpoints().len(), 6);
    }

    #[test]
    fn closed_axis_wraps() {
        let a = NodeAxis::new(5, true);
        let (i, xi) = a.locate(a.node(5));
        assert_eq!((i, xi), a.locate(a.node(1)));
    }
}
