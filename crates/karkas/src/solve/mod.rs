//! Banded linear solvers.
//!
//! The methods of karkas lead to tridiagonal and cyclic tridiagonal systems whose right-hand
//! sides are points. These are solved in `O(n)` by the Thomas algorithm and, for the cyclic
//! case, the Sherman–Morrison correction. They are written here because no maintained crate
//! solves a banded system with vector-valued right-hand sides in place without allocating
//! dense matrices; the routines are short and tested against dense solves.
//!
//! The spline fits of Pavlov lead to banded least-squares problems, solved by Givens
//! rotations in [`BandedLeastSquares`], and to banded symmetric positive definite Newton
//! systems, solved by Cholesky factorization in [`BandedSpd`], with a dense border for the
//! cyclic band of a periodic fit in [`BorderedSpd`] (see their docs for why no crate is used).

mod banded_cholesky;
mod banded_qr;
mod bordered;
mod tridiagonal;

pub use banded_cholesky::BandedSpd;
pub use banded_qr::BandedLeastSquares;
pub use bordered::BorderedSpd;
pub use tridiagonal::{solve_cyclic_tridiagonal, solve_tridiagonal};
