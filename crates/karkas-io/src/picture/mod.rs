//! Pictures: [`svg`] (planar curves over their points, discrete curves, wireframes, drawn on a
//! [`chart`] with [`ticks`] in model units, curvature combs scaled by [`comb`]), [`scene`] (a
//! shaded surface in space with curves on it, hidden parts removed) and [`png`] (any of these
//! rendered to pixels with a compiled-in font), the SVG [`text`] they share, and the memory
//! each takes ([`budget`]).

pub mod budget;
pub mod chart;
pub mod comb;
pub(crate) mod error;
pub mod png;
pub mod scene;
pub mod svg;
pub mod text;
pub mod ticks;

pub use error::PictureError;
