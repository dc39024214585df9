//! Pictures as PNG: an SVG document rendered to pixels.
//!
//! Every picture of karkas is drawn as SVG first; PNG is that SVG rendered by `resvg`, a
//! maintained pure-Rust renderer, so the two formats always show the same thing. Text needs a
//! font and a machine may have none installed: the Noto Sans font is compiled in (from the
//! `ttf-noto-sans` crate) and every family name maps to it, so labels render the same
//! everywhere and rendering never depends on the system.

use std::path::Path;
use std::sync::{Arc, OnceLock};

use resvg::tiny_skia::{Pixmap, Transform};
use resvg::usvg::{fontdb, Options, Tree};

use crate::error::IoError;
use crate::picture::budget;
use crate::picture::error::PictureError;
use crate::write::write_atomic;

/// The family name of the compiled-in font.
const FONT_FAMILY: &str = "Noto Sans";

/// The font database with the compiled-in font, built once.
fn fonts() -> Arc<fontdb::Database> {
    static FONTS: OnceLock<Arc<fontdb::Database>> = OnceLock::new();
    FONTS
        .get_or_init(|| {
            let mut db = fontdb::Database::new();
            db.load_font_data(ttf_noto_sans::REGULAR.to_vec());
            db.set_sans_serif_family(FONT_FAMILY);
            db.set_serif_family(FONT_FAMILY);
            db.set_monospace_family(FONT_FAMILY);
            db.set_cursive_family(FONT_FAMILY);
            db.set_fantasy_family(FONT_FAMILY);
            Arc::new(db)
        })
        .clone()
}

/// Renders the SVG document `svg` to PNG bytes at its own size (`scale` times larger: 2 for
/// a sharp picture on high-density screens); the error carries the renderer's.
pub fn render_png(svg: &str, scale: f32) -> Result<Vec<u8>, PictureError> {
    let options = Options {
        font_family: FONT_FAMILY.to_owned(),
        fontdb: fonts(),
        ..Options::default()
    };
    let tree = Tree::from_str(svg, &options)?;
    let size = tree.size();
    let (width, height) = (
        (size.width() * scale).ceil() as u32,
        (size.height() * scale).ceil() as u32,
    );
    let mut pixmap =
        Pixmap::new(width.max(1), height.max(1)).ok_or(PictureError::Size { width, height })?;
    pixmap.fill(resvg::tiny_skia::Color::WHITE);
    resvg::render(
        &tree,
        Transform::from_scale(scale, scale),
        &mut pixmap.as_mut(),
    );
    pixmap
        .encode_png()
        .map_err(|e| PictureError::Encode(Box::new(e)))
}

/// Renders `svg` (at twice its size) and writes the PNG to `path`, atomically.
/// Refuses (before rendering) a document whose rendering would take more memory than the cap
/// ([`budget::png_bytes`]).
pub fn write_svg_as_png(path: &Path, svg: &str) -> Result<(), IoError> {
    budget::check_output_memory(path, "the PNG picture", budget::png_bytes(svg.len()))?;
    let png = render_png(svg, 2.0).map_err(IoError::picture(path))?;
    write_atomic(path, |out| out.write_all(&png))
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn text_renders_with_the_compiled_in_font() {
        let svg = r#"<svg xmlns="http://www.w3.org/2000/svg" width="60" height="20">
            <text x="2" y="15" font-family="sans-serif" font-size="14">Hi</text></svg>"#;
        let png = render_png(svg, 1.0).unwrap();
        assert_eq!(&png[..8], b"\x89PNG\r\n\x1a\n");
        // Dark pixels exist only if the text was drawn.
        let blank = r#"<svg xmlns="http://www.w3.org/2000/svg" width="60" height="20"></svg>"#;
        assert_ne!(png, render_png(blank, 1.0).unwrap());
        assert!(render_png("not svg", 1.0).is_err());
    }
}
