//! Discrete periodic splines with vector coefficients: closed discrete curves and tube
//! surfaces (Malozemov, Khorokhonov, Chashnikov; docs/methods.md §3).
//!
//! A discrete `N`-periodic spline of order `r` (`N = m n`, `m, n >= 2`) is
//! `S_r(j) = sum_{p<m} a_p Q_r(j - p n)`, `j` in `0..N`, with vector poles `a_p` in R^D and the
//! discrete periodic B-spline `Q_r`: the hat `Q_1` of half-width `n`, and
//! `Q_v = (1/n) Q_1 (*) Q_{v-1}` (cyclic convolution). Order `r` behaves like a spline of degree
//! `2r - 1`. Such splines are point sets, not functions of a real parameter (docs/methods.md §6): they
//! export as closed polylines and meshes, and do not implement [`Curve`](crate::Curve).
//!
//! - [`discrete_bspline`]: `Q_r` on `0..N`;
//! - [`DiscreteSpline`]: a closed discrete curve from its poles, or through `m` nodes
//!   (`S_r(l n) = z(l)`, problem (1));
//! - [`InterpolationPlan`]: the DFT solution of (1), reusable for many right-hand sides;
//! - [`TubeSurface`]: a closed tube by formula (3) from curves along and across it.
//!
//! Guarantees (each is a test): `Q_r >= 0` and `sum_p Q_r(j - p n) = 1`, so every value is a
//! convex combination of the poles; the interpolating spline passes through its nodes and, among
//! all `N`-periodic sequences through them, minimises `sum_j ||Delta^r x(j)||^2`; the tube
//! contains its skeleton, `c(i n1, .) = f_i` and `c(., j n2) = g_j`.
//!
//! Complexity: values in `O(r N)` by moving sums (the hat is a box convolved with a box, see
//! `smoothing.rs`); interpolation in `O(m log m + N)` with real FFTs from the `realfft` crate;
//! a tube in `O((r1 + r2) N1 N2)`. Hand-written: the moving sums (a few lines no crate offers
//! for periodic data in place) and the symbol `T_r`.

mod interpolation;
mod period;
mod smoothing;
mod spline;
mod tube;

pub use interpolation::InterpolationPlan;
pub use spline::{discrete_bspline, DiscreteSpline};
pub use tube::{compatibility_residual, TubeSurface, COMPATIBILITY_TOLERANCE};

/// The largest order accepted. Evaluation costs `O(r N)`, and the interpolation matrix has
/// condition number about `(pi/2)^(2r) / 2` (`3e24` at 64), so higher orders only lose
/// accuracy.
pub const MAX_ORDER: usize = 64;

/// The spline orders `r1`, `r2` of a [`TubeSurface`] when none are given (the command line's
/// `--r1`, `--r2`, Python's `r1=`, `r2=`): order 2 behaves like a cubic in each direction.
pub const DEFAULT_TUBE_ORDER: usize = 2;

/// The order `r` of a [`DiscreteSpline`] when none is given (Python's `order=`).
pub const DEFAULT_ORDER: usize = 3;

/// The step `n` (values per point) of a [`DiscreteSpline`] when none is given (Python's `n=`).
pub const DEFAULT_STEP: usize = 10;
