//! The surface traits.

use super::{uniform_into, Interval, Point};

/// A parametric surface `(u, v) -> P(u, v)` in R^D over a rectangle of parameters.
pub trait Surface<const D: usize> {
    /// The interval of `u`.
    fn domain_u(&self) -> Interval;

    /// The interval of `v`.
    fn domain_v(&self) -> Interval;

    /// True when the surface is periodic in `u` with period `domain_u().length()`.
    fn is_closed_u(&self) -> bool;

    /// True when the surface is periodic in `v` with period `domain_v().length()`.
    fn is_closed_v(&self) -> bool;

    /// The point at `(u, v)`.
    fn eval(&self, u: f64, v: f64) -> Point<D>;

    /// The partial derivative `d^(ku+kv) P / du^ku dv^kv` at `(u, v)`.
    fn deriv(&self, u: f64, v: f64, ku: usize, kv: usize) -> Point<D>;

    /// `[S, S_u, S_v, S_uu, S_uv, S_vv]` at `(u, v)`: the point with its first and second
    /// partial derivatives, as [`deriv`](Surface::deriv) gives them. Surfaces that locate
    /// their patch before evaluating override it to locate once (Newton's method on a distance
    /// needs all six per step).
    fn second_order(&self, u: f64, v: f64) -> [Point<D>; 6] {
        [
            self.eval(u, v),
            self.deriv(u, v, 1, 0),
            self.deriv(u, v, 0, 1),
            self.deriv(u, v, 2, 0),
            self.deriv(u, v, 1, 1),
            self.deriv(u, v, 0, 2),
        ]
    }

    /// Evaluates on the tensor grid `us x vs` into `out`, row-major with `u` outer:
    /// `out[a * vs.len() + b] = P(us[a], vs[b])`.
    ///
    /// # Panics
    /// When `out.len() != us.len() * vs.len()`.
    fn eval_grid_into(&self, us: &[f64], vs: &[f64], out: &mut [Point<D>]) {
        super::assert_grid_len(us.len(), vs.len(), out.len());
        for (a, &u) in us.iter().enumerate() {
            for (b, &v) in vs.iter().enumerate() {
                out[a * vs.len() + b] = self.eval(u, v);
            }
        }
    }

    /// The level set `{(u, v) : normal . P(u, v) = level}`, when this surface knows it to be
    /// made of whole parameter lines: the fast path of plane sections for a surface whose `x`
    /// depends on `u` only (Aulchenko et al., formula (21)). The lines are listed in increasing
    /// parameter; an empty list means the level is never reached.
    ///
    /// `None` (the default) when the surface cannot tell, or when it lies in the level set
    /// over a whole strip; [sections](crate::section) then trace the level curve instead.
    fn level_parameter_lines(&self, normal: Point<D>, level: f64) -> Option<Vec<ParameterLine>> {
        let _ = (normal, level);
        None
    }

    /// Samples a uniform `us.len() x vs.len()` grid over the whole domain, ends included,
    /// writing the parameters into `us`, `vs` and the points into `out` (row-major, `u` outer).
    ///
    /// # Panics
    /// When `out.len() != us.len() * vs.len()`.
    fn sample_grid_into(&self, us: &mut [f64], vs: &mut [f64], out: &mut [Point<D>]) {
        uniform_into(self.domain_u(), us);
        uniform_into(self.domain_v(), vs);
        self.eval_grid_into(us, vs, out);
    }
}

/// A line of constant parameter on a surface.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum ParameterLine {
    /// The line `u = value`, running along `v`.
    U(f64),
    /// The line `v = value`, running along `u`.
    V(f64),
}

/// A surface made of polynomial patches on a rectangular grid of breakpoints.
pub trait PiecewiseSurface<const D: usize>: Surface<D> {
    /// Breakpoints in `u` (domain ends included), ascending.
    fn breakpoints_u(&self) -> Vec<f64>;

    /// Breakpoints in `v` (domain ends included), ascending.
    fn breakpoints_v(&self) -> Vec<f64>;

    /// Continuity order in each variable: partial derivatives up to this order in `u`
    /// (resp. `v`) are continuous across the patch borders.
    fn continuity(&self) -> usize;

    /// A partial derivative taken on the patch on the given sides of `(u, v)`.
    fn deriv_on_side(
        &self,
        u: f64,
        v: f64,
        ku: usize,
        kv: usize,
        side_u: super::Side,
        side_v: super::Side,
    ) -> Point<D>;
}
