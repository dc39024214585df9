//! Pictures: [`svg`] (planar curves over their points, discrete curves, wireframes), [`scene`]
//! (a shaded surface in space with curves on it, hidden parts removed) and [`png`] (any of
//! these rendered to pixels with a compiled-in font), and the memory each takes ([`budget`]).

pub mod budget;
pub mod curvature_plot;
pub(crate) mod error;
pub mod png;
pub mod scene;
pub mod svg;

// The charts' parts: layout and drawing, comb scale, ticks, SVG text.
pub mod chart;
pub mod comb;
pub mod text;
pub mod ticks;

pub use error::PictureError;
