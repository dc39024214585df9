//! Implicit surfaces `F(x, y, z) = 0`: curvature and node grids traced by continuation
//! (Kuznetsov, Filatov; docs/methods.md §5).
//!
//! - [`ImplicitSurface`]: `F`, its gradient and Hessian; built in: [`Cylinder`],
//!   [`Hyperboloid`], [`Sphere`]; from a typed expression: [`ExpressionSurface`] (parsed and
//!   differentiated exactly by forward-mode differentiation, errors naming the character);
//! - [`SurfaceFrame`]: unit normal, principal curvatures and directions from the gradient and
//!   Hessian (the second fundamental form of an implicit surface), `O(1)` per point;
//!   [`project_onto`] / [`closest_point_on`]: Newton's projection onto `F = 0`;
//! - [`trace_net`]: a grid of nodes on the net of lines of curvature, or on a net turned by
//!   an angle (one or both families) or of plane sections, traced by predictor-corrector
//!   continuation with arc-length steps: the node sets of the paper's experiments.
//!
//! ```
//! use karkas::implicit::{trace_net, Cylinder, NetDirections, NetSpec};
//! use karkas::Point3;
//! let spec = NetSpec::new(Point3::new([1.0, 0.0, 0.0]), NetDirections::Principal,
//!                         (5, 9), (0.5, std::f64::consts::TAU / 8.0));
//! let nodes = trace_net(&Cylinder { radius: 1.0 }, &spec).unwrap();
//! // Lines of curvature of a cylinder: generators and circles; 8 steps close the circle.
//! assert!(nodes.get(4, 8).distance(Point3::new([1.0, 0.0, 2.0])) < 1e-8);
//! ```

mod expression;
mod frame;
mod net;
mod surface;

pub use expression::ExpressionSurface;
pub use frame::{closest_point_on, cross, project_onto, SurfaceFrame};
pub use net::{trace_net, NetDirections, NetSpec};
pub use surface::{Cylinder, Hyperboloid, ImplicitSurface, Matrix3, Sphere};
