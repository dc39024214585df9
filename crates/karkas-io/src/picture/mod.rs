//! Pictures: [`svg`] (planar curves over their points, discrete curves, wireframes), [`scene`]
//! (a shaded surface in space with curves on it, hidden parts removed) and [`png`] (any of
//! these rendered to pixels with a compiled-in font), and the memory each takes ([`budget`]).

pub mod budget;
pub mod curvature_plot;
pub(crate) mod error;
pub mod png;
pub mod scene;
pub mod svg;

pub use error::PictureError;
