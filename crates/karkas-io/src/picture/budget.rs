//! The memory a picture or page takes while it is drawn, rendered and written, estimated from
//! what it shows, and checked against the process-wide cap ([`max_input_bytes`], which the
//! CLI's `--max-memory` sets) before the work starts.
//!
//! The costs per item were measured on the release build (peak resident memory against the
//! number of mesh cells or curve points, then rounded up by about a third): the SVG text and
//! the cells sorted for the painter's algorithm, the renderer's tree of the SVG document, and
//! the pixel buffers of PNG (the picture at twice its size, and one layer as large).

use std::path::Path;

use crate::error::IoError;
use crate::input::max_input_bytes;

/// Bytes per mesh cell of a scene picture as SVG: the cell (corners, depth, shade), its
/// `<polygon>` text and the text's growth while the document is built.
pub const SCENE_CELL_SVG: u128 = 400;
/// Bytes per mesh cell added by rendering it to PNG: the renderer's path node for it.
pub const SCENE_CELL_PNG: u128 = 900;
/// Bytes per point of a curve drawn in a picture, as SVG (projected point, text).
pub const CURVE_POINT_SVG: u128 = 120;
/// Bytes per point of a curve rendered to PNG (the renderer's path).
pub const CURVE_POINT_PNG: u128 = 120;
/// Bytes per byte of SVG text rendered to PNG: the renderer's tree of the document.
pub const PNG_PER_SVG_BYTE: u128 = 10;
/// The depth buffer of a scene picture: one `f64` per pixel of the largest drawing area.
pub const DEPTH_BUFFER: u128 = 1100 * 1100 * 8;
/// The pixel buffers of the largest PNG: 2280 x 2504 RGBA pixels (pictures are rendered at
/// twice their size), twice (the picture and one layer).
pub const PIXELS: u128 = 2 * 2280 * 2504 * 4;

/// What a scene picture of a `rows x cols` sampled surface with `curve_points` points of
/// curves on it takes, as PNG when `png`, else as SVG (the samples included).
pub fn scene_bytes(rows: usize, cols: usize, curve_points: usize, png: bool) -> u128 {
    let cells = (rows.saturating_sub(1) as u128) * (cols.saturating_sub(1) as u128);
    let samples = (rows as u128) * (cols as u128) * 24;
    let svg = samples + cells * SCENE_CELL_SVG + curve_points as u128 * CURVE_POINT_SVG;
    if png {
        svg + DEPTH_BUFFER
            + cells * SCENE_CELL_PNG
            + curve_points as u128 * CURVE_POINT_PNG
            + PIXELS
    } else {
        svg + DEPTH_BUFFER
    }
}

/// What a chart (a curve picture) of `points` points in all takes, as PNG when `png`.
pub fn chart_bytes(points: usize, png: bool) -> u128 {
    let per_point = if png {
        CURVE_POINT_SVG + CURVE_POINT_PNG
    } else {
        CURVE_POINT_SVG
    };
    points as u128 * per_point + if png { PIXELS } else { 0 }
}

/// What rendering an SVG document of `svg_bytes` bytes to PNG takes.
pub fn png_bytes(svg_bytes: usize) -> u128 {
    svg_bytes as u128 * PNG_PER_SVG_BYTE + PIXELS
}

/// Fails with an [`IoError::Write`] of `path` (kind [`std::io::ErrorKind::OutOfMemory`])
/// when `what` (like "the picture") would need `bytes`, more than the cap.
pub fn check_output_memory(path: &Path, what: &str, bytes: u128) -> Result<(), IoError> {
    let cap = max_input_bytes();
    if bytes <= u128::from(cap) {
        return Ok(());
    }
    Err(IoError::Write {
        path: crate::write::output_name(path),
        source: std::io::Error::new(
            std::io::ErrorKind::OutOfMemory,
            format!(
                "{what} would need {}, above the memory cap of {} (raise it with --max-memory \
                 or KARKAS_MAX_MEMORY, or ask for fewer samples)",
                human_bytes(bytes),
                human_bytes(u128::from(cap))
            ),
        ),
    })
}

/// Parses a size: a whole number of bytes with an optional suffix `K`, `M`, `G`, `T`
/// (powers of 1024, an optional trailing `B` or `iB`), e.g. `512M`, `2G`, `1500000`.
pub fn parse_size(text: &str) -> Result<u64, String> {
    let upper = text.trim().to_ascii_uppercase();
    let t = upper
        .strip_suffix("IB")
        .or_else(|| upper.strip_suffix('B'))
        .unwrap_or(&upper);
    let (digits, shift) = match t.char_indices().last() {
        Some((k, c)) if c.is_ascii_alphabetic() => {
            let shift = match c.to_ascii_uppercase() {
                'K' => 10,
                'M' => 20,
                'G' => 30,
                'T' => 40,
                _ => return Err(format!("'{text}': unknown unit (use K, M, G or T)")),
            };
            (&t[..k], shift)
        }
        _ => (t, 0),
    };
    let n: u64 = digits
        .trim()
        .parse()
        .map_err(|_| format!("'{text}' is not a size like 512M or 2G"))?;
    match n.checked_mul(1 << shift) {
        Some(bytes) if bytes > 0 => Ok(bytes),
        Some(_) => Err(format!("'{text}': the cap must be positive")),
        None => Err(format!("'{text}' is too large")),
    }
}

/// `bytes` in the largest binary unit that keeps it at least 1, like `1.5 GiB`.
pub fn human_bytes(bytes: u128) -> String {
    let units = ["B", "KiB", "MiB", "GiB", "TiB"];
    let mut value = bytes as f64;
    let mut unit = 0;
    while value >= 1024.0 && unit + 1 < units.len() {
        value /= 1024.0;
        unit += 1;
    }
    if unit == 0 {
        format!("{bytes} B")
    } else {
        format!("{value:.1} {}", units[unit])
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn estimates_grow_with_what_is_drawn() {
        assert!(scene_bytes(800, 800, 0, true) > 600 << 20);
        assert!(scene_bytes(800, 800, 0, false) < scene_bytes(800, 800, 0, true));
        assert!(chart_bytes(10, true) >= PIXELS);
        assert_eq!(human_bytes(3 << 29), "1.5 GiB");
    }
}
