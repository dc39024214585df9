//! Banded linear solvers.
//!
//! The methods of karkas lead to tridiagonal and cyclic tridiagonal systems whose right-hand
//! sides are points. These are solved in `O(n)` by the Thomas algorithm and, for the cyclic
//! case, the Sherman–Morrison correction. They are written here because no maintained crate
//! solves a banded system with vector-valued right-hand sides in place without allocating
//! dense matrices; the routines are short and tested against dense solves.

mod tridiagonal;

pub use tridiagonal::{solve_cyclic_tridiagonal, solve_tridiagonal};
