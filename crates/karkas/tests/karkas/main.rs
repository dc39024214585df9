//! The integration tests of the karkas library, in one binary (one build and one link for
//! all of them): a module per capability, and the independent references they compare
//! against as shared modules.

mod common;
mod coons_reference;
mod dps_reference;
mod fit_reference;
mod ll_reference;

mod bspline_convert;
mod coons_blending;
mod coons_composite;
mod coons_network;
mod coons_surface;
mod coons_twists;
mod dps_bspline;
mod dps_interpolation;
mod dps_tube;
mod fair;
mod fit_adaptive;
mod fit_closed;
mod fit_dense;
mod fit_faults;
mod fit_guards;
mod fit_limits;
mod fit_naca;
mod fit_noise;
mod fit_optimality;
mod fit_parallel;
mod fit_starts;
mod fit_translation;
mod geometry;
mod geometry_batch;
mod geometry_nearest_batch;
mod ll_curve;
mod ll_curve_closed;
mod ll_curve_interp;
mod ll_errors;
mod ll_kernel;
mod ll_properties;
mod ll_surface;
mod ll_surface_interp;
mod ll_within;
mod loft_hull;
mod loft_wing;
mod param_bicubic;
mod param_condition;
mod param_relay;
mod param_spline;
mod point_parameter;
mod robust_properties;
mod section_poles;
mod section_tolerance;
mod sections;
mod shared_end;
mod variation;
