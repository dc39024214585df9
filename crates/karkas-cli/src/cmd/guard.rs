//! Checks every command makes before building: degenerate frames (all points at one place,
//! a grid on one line) and the memory a request's output will take, against the cap of
//! `--max-memory` / `KARKAS_MAX_MEMORY`.

use anyhow::{bail, Result};
use karkas::Point;
use std::path::Path;
use std::sync::OnceLock;

/// The default memory cap for one request's output buffers: 2 GiB.
pub const DEFAULT_MAX_MEMORY: u64 = 2 << 30;

/// The cap in force, set once from the command line or the environment.
static MAX_MEMORY: OnceLock<u64> = OnceLock::new();

/// Sets the cap: `--max-memory` if given, else `KARKAS_MAX_MEMORY`, else the default.
pub fn set_max_memory(option: Option<u64>) -> Result<()> {
    let cap = match option {
        Some(bytes) => bytes,
        None => match std::env::var("KARKAS_MAX_MEMORY") {
            Ok(text) => parse_size(&text).map_err(|e| anyhow::anyhow!("KARKAS_MAX_MEMORY: {e}"))?,
            Err(_) => DEFAULT_MAX_MEMORY,
        },
    };
    // Set once per process; a second call keeps the first value.
    let _ = MAX_MEMORY.set(cap);
    Ok(())
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

/// Fails early when `request` (e.g. "curve ll: 50000000 samples") needs `bytes` of output
/// buffers, more than the cap.
pub fn check_memory(request: &str, bytes: u128) -> Result<()> {
    let cap = *MAX_MEMORY.get_or_init(|| DEFAULT_MAX_MEMORY);
    if bytes > u128::from(cap) {
        bail!(
            "{request} would need {} of memory, above the cap of {} (raise it with --max-memory \
             or KARKAS_MAX_MEMORY, or ask for fewer samples)",
            human(bytes),
            human(u128::from(cap))
        );
    }
    Ok(())
}

/// `bytes` in the largest binary unit that keeps it at least 1.
fn human(bytes: u128) -> String {
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

/// Where the points lie, as far as building a curve or surface goes.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
enum Spread {
    /// Every point is the same point.
    OnePoint,
    /// The points lie on one straight line (relative tolerance `1e-12`).
    OneLine,
    /// Anything else: enough for a surface.
    Surface,
}

/// How `points` spread (finite points assumed; the readers refuse others).
fn spread<const D: usize>(points: &[Point<D>]) -> Spread {
    let Some(&first) = points.first() else {
        return Spread::OnePoint;
    };
    // Scale by the largest coordinate difference so that huge and tiny data compare alike.
    let scale = points
        .iter()
        .fold(0.0f64, |m, &p| m.max((p - first).max_abs()));
    if scale == 0.0 || !scale.is_finite() {
        return if scale == 0.0 {
            Spread::OnePoint
        } else {
            Spread::Surface
        };
    }
    let rel = |p: Point<D>| (p - first) * (1.0 / scale);
    let far = points
        .iter()
        .map(|&p| rel(p))
        .max_by(|a, b| a.norm().total_cmp(&b.norm()))
        .unwrap_or(Point::ZERO);
    let axis = far * (1.0 / far.norm());
    let off_line = points.iter().any(|&p| {
        let q = rel(p);
        (q - axis * q.dot(axis)).norm() > 1e-12
    });
    if off_line {
        Spread::Surface
    } else {
        Spread::OneLine
    }
}

/// Refuses a curve input whose points all coincide.
pub fn curve_points<const D: usize>(input: &Path, points: &[Point<D>]) -> Result<()> {
    if points.len() > 1 && spread(points) == Spread::OnePoint {
        bail!(
            "{}: all {} points coincide (at {}): there is no curve to build",
            input.display(),
            points.len(),
            coordinates(points[0])
        );
    }
    Ok(())
}

/// Refuses a surface grid whose points all coincide or all lie on one line.
pub fn grid_points<const D: usize>(input: &Path, points: &[Point<D>]) -> Result<()> {
    if points.len() > 1 {
        match spread(points) {
            Spread::OnePoint => bail!(
                "{}: all {} grid points coincide (at {}): there is no surface to build",
                input.display(),
                points.len(),
                coordinates(points[0])
            ),
            Spread::OneLine => bail!(
                "{}: all {} grid points lie on one straight line: there is no surface to build",
                input.display(),
                points.len()
            ),
            Spread::Surface => {}
        }
    }
    Ok(())
}

/// `x,y[,z]` of a point.
fn coordinates<const D: usize>(p: Point<D>) -> String {
    p.0.iter()
        .map(|c| c.to_string())
        .collect::<Vec<_>>()
        .join(",")
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn sizes_parse_with_binary_units() {
        assert_eq!(parse_size("1500"), Ok(1500));
        assert_eq!(parse_size("512M"), Ok(512 << 20));
        assert_eq!(parse_size("2G"), Ok(2 << 30));
        assert_eq!(parse_size("2GiB"), Ok(2 << 30));
        assert_eq!(parse_size("1kb"), Ok(1024));
        assert!(parse_size("0").is_err());
        assert!(parse_size("12X").is_err());
        assert!(parse_size("lots").is_err());
        assert!(parse_size("99999999999T").is_err());
        assert_eq!(human(3 << 29), "1.5 GiB");
        assert_eq!(human(10), "10 B");
    }

    #[test]
    fn spread_of_points() {
        let p = |x: f64, y: f64, z: f64| Point([x, y, z]);
        assert_eq!(spread(&[p(1., 1., 1.); 4]), Spread::OnePoint);
        let line: Vec<_> = (0..5).map(|k| p(k as f64, 2.0 * k as f64, 1e150)).collect();
        assert_eq!(spread(&line), Spread::OneLine);
        let tiny: Vec<_> = (0..5)
            .map(|k| p(1e-150 * k as f64, 1e-150 * (k * k) as f64, 0.0))
            .collect();
        assert_eq!(spread(&tiny), Spread::Surface);
        assert_eq!(spread::<3>(&[]), Spread::OnePoint);
    }
}
