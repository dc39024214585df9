//! The command-line contract of `karkas`, as one test binary: one module per command or
//! concern, the helpers they share in `common`.

mod bad_input;
mod batch;
mod cad;
mod common;
mod contract;
mod convert;
mod curve_analyze;
mod curve_fit;
mod curve_spline;
mod demo_hydrofoil;
mod demo_report;
mod dialects;
mod dps;
mod dxf;
mod export;
mod fit_tolerance;
mod hausdorff;
mod ll_within;
mod meshes;
mod npy;
mod output_bounds;
mod outputs;
mod pictures;
mod reading;
mod scale;
mod section;
mod section_methods;
mod section_poles;
mod section_scale;
mod surface_bicubic;
mod surface_coons;
mod surface_implicit;
mod surface_relay;
mod vary;
