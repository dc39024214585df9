//! Exact B-spline geometry for CAD programs: [`step`] (STEP AP214) and [`iges`] (IGES 5.3,
//! entities 126 and 128), both writing the [`CadEntity`] items of [`entity`]; [`dxf`] (DXF
//! R2000 SPLINE and POINT entities) for the curves that go to CAM and laser cutting.
//! [`shell`] joins B-spline faces and planar caps into shells and solids.
//! Both CAD formats carry the moment they were written ([`time_stamp`]); [`units`] says in
//! which length unit all three state their coordinates, and at which scale.

pub mod dxf;
pub mod entity;
pub mod iges;
pub mod read;
pub mod shell;
pub mod step;
pub mod time_stamp;
pub mod units;

pub use entity::{
    curve_closed, curve_in_space, surface_closed, CadEntity, CadError, MAX_CAD_DEGREE,
};
pub use shell::{
    CadShell, Cap, CapError, FaceSurface, OrientedEdge, ParameterSegment, ShellEdge, ShellFace,
};
