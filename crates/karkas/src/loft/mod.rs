//! Lofting: a surface through sections placed along a span (wings, blades, fins, hulls;
//! docs/methods.md §7).
//!
//! Designers describe a body by its sections: airfoil files of different point counts placed
//! with chord, twist, sweep and dihedral, or a ship's sections at its stations. A loft makes
//! them one tensor-product B-spline surface:
//!
//! 1. **Compatible sections** ([`Profile`], `compatible.rs`): every section is fitted to a
//!    tolerance (a share of its chord) by a cubic B-spline on one knot vector shared by all
//!    sections, an airfoil's leading edge at `v = 1/2` and its trailing-edge ends at `v = 0`
//!    and `v = 1` on every section, passing through those points exactly. Least squares with
//!    foot-point parameter correction and knots halved where a point is off, as Piegl and
//!    Tiller fit curves to a tolerance (The NURBS Book, §9.4) but on one knot vector for all.
//! 2. **Placement** ([`SectionFrame`], [`wing_frames`]): each section's plane goes into space
//!    by an affine map, for a wing exactly as aerosandbox's `WingXSec` places it, for a
//!    wind-turbine blade as windIO places it ([`BladeShape`]).
//! 3. **Spanwise rule** ([`SpanRule`]): ruled, shape-preserving cubic Hermite (Fritsch and
//!    Carlson) or not-a-knot cubic (Kuznetsov and Filatov's splines, formulas (3.10)–(3.12)) in
//!    the span direction, through the placed control points.
//!
//! The result, [`Loft`], is a B-spline surface (`to_bspline` returns it as it is): what karkas
//! evaluates is what a CAD system reads.
//!
//! Complexity: `O(n log k)` for `n` points in all and `k` knots per section (the rounds of knot
//! refinement), then `O(s m)` for `s` sections of `m` control points.
//!
//! Hand-written: no maintained Rust crate fits several curves on one shared knot vector or
//! lofts; the least squares reuse [`BandedLeastSquares`](crate::solve::BandedLeastSquares),
//! the spanwise splines [`CubicSpline`](crate::param::CubicSpline) and the B-spline
//! conversion of [`bspline`](crate::bspline).
//!
//! ```
//! use karkas::loft::{Loft, LoftOptions, WingPlacement};
//! use karkas::{Point2, Point3, Surface};
//! // A thin symmetric section (a NACA 0012 sampled at 41 points), root and tip.
//! let foil: Vec<Point2> = (0..41)
//!     .map(|k| {
//!         let a = std::f64::consts::PI * k as f64 / 20.0; // 0..2 pi, trailing edge to trailing edge
//!         let x = 0.5 * (1.0 + a.cos());
//!         let t = 0.6 * (0.2969 * x.sqrt() - 0.126 * x - 0.3516 * x * x + 0.2843 * x.powi(3) - 0.1036 * x.powi(4));
//!         Point2::new([x, if k <= 20 { t } else { -t }])
//!     })
//!     .collect();
//! let at = |y: f64, chord: f64, twist: f64| WingPlacement {
//!     leading_edge: Point3::new([0.2 * y, y, 0.05 * y]),
//!     chord,
//!     twist,
//!     dihedral: None,
//! };
//! let wing = Loft::wing(&[foil.clone(), foil], &[at(0.0, 1.0, 2.0), at(4.0, 0.5, -1.0)], &LoftOptions::default())?;
//! assert!(wing.tolerance_met());
//! // The leading edge of the tip section, exactly where it was placed.
//! let tip_le = wing.eval(wing.stations()[1], 0.5);
//! assert!(tip_le.distance(Point3::new([0.8, 4.0, 0.2])) < 1e-12);
//! # Ok::<(), karkas::Error>(())
//! ```

mod blade;
mod compatible;
mod mirror;
mod pchip;
mod placed_slopes;
mod placement;
mod profile;
mod span;
mod surface;
mod wing_path;

pub use blade::{blade_frames, BladeShape, Distribution};
pub use pchip::pchip_slopes;
pub use placement::{wing_frames, SectionFrame, WingPlacement};
pub use profile::{Profile, MIN_SECTION_POINTS, UNIT_CHORD_SLACK};
pub use span::SpanRule;
pub use surface::{Loft, LoftOptions, LoftSection, DEFAULT_TOLERANCE};
