//! Shapes read from CAD files: trimmed faces of rational B-spline surfaces with their
//! bounding edges kept as curves, and free curves; the distance of points to a shape
//! ([`ShapeProjector`]), its plane sections and its triangle meshes.
//!
//! A [`Face`] is a [`NurbsSurface`] with the loops of [`Edge`]s that bound it, as the CAD
//! file gives them (ISO 10303-42 `ADVANCED_FACE`, IGES entity 144): the face is the part of
//! the surface inside its outer loop and outside its inner loops. Where the face lies on the
//! surface is found once in the surface's parameters ([`FaceDomain`], `trim.rs`): each loop
//! sampled along its edges, every sample inverted onto the surface, the polygons closed
//! across periodic directions on the face's side. [`ShapeProjector`] (`nearest.rs`) finds the
//! nearest point of the faces to any point, signed where a face bounds a solid;
//! [`ShapeSectioner`] (`plane_sections.rs`) cuts the faces by planes.

mod bounds;
mod cylinder;
mod domain;
mod edge_form;
mod face;
mod flat;
mod inside;
mod nearest;
mod plane_sections;

pub use domain::{FaceDomain, ParameterLoop};
pub use face::{Edge, EdgeLoop, Face, Shape};
pub use nearest::{ShapeNearest, ShapeProjector};
pub use plane_sections::{ShapeSection, ShapeSectionPiece, ShapeSectioner};

use crate::bspline::{NurbsCurve, NurbsSurface};
