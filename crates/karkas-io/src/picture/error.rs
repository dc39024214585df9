//! Why a picture could not be drawn or rendered: the drawing library's (plotters) or the
//! renderer's (resvg) error, kept as the source.

use plotters::drawing::DrawingAreaErrorKind;

/// A picture that could not be drawn (SVG) or rendered (PNG).
#[derive(Debug, thiserror::Error)]
#[non_exhaustive]
pub enum PictureError {
    /// The drawing library failed while drawing the SVG document.
    #[error("{0}")]
    Draw(#[from] DrawingAreaErrorKind<std::io::Error>),
    /// The renderer could not read the SVG document.
    #[error("{0}")]
    Svg(#[from] resvg::usvg::Error),
    /// The picture has a size no pixel buffer can hold.
    #[error("cannot make a {width} x {height} picture")]
    Size {
        /// The width in pixels.
        width: u32,
        /// The height in pixels.
        height: u32,
    },
    /// The pixels could not be encoded as PNG.
    #[error("{0}")]
    Encode(#[source] Box<dyn std::error::Error + Send + Sync>),
}
