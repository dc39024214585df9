//! How many samples a command writes: the defaults, the cap, and the line that reports them.

use std::path::Path;

/// The largest number of samples one command writes (a guard against a mistyped count
/// exhausting memory).
pub const MAX_SAMPLES: usize = 50_000_000;

/// The default number of curve samples for `k` input points: 10 per point, at least 200.
pub fn default_curve_samples(k: usize) -> usize {
    (10 * k).max(200)
}

/// The default number of surface samples along a direction with `k` grid lines.
pub fn default_surface_samples(k: usize) -> usize {
    (4 * k).max(50)
}

/// Prints what was written: `karkas: wrote OUTPUT (N samples)`.
pub fn report_samples(output: &Path, samples: usize) {
    eprintln!("karkas: wrote {} ({samples} samples)", output.display());
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn default_counts() {
        assert_eq!(default_curve_samples(5), 200);
        assert_eq!(default_curve_samples(53), 530);
        assert_eq!(default_surface_samples(5), 50);
        assert_eq!(default_surface_samples(31), 124);
    }
}
