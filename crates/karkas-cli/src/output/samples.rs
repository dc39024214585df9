//! How many samples a command writes: the defaults and the cap (karkas-io's, shared with the
//! Python package), and the line that reports them.

use super::console::note;
pub use karkas_io::export::samples::{
    default_surface_samples, sample_curve, sample_surface, MAX_SAMPLES,
};
use std::path::Path;

/// Prints what was written: `karkas: wrote OUTPUT (N samples)`.
pub fn report_samples(output: &Path, samples: usize) {
    super::console::record("samples", samples);
    note(format!(
        "karkas: wrote {} ({samples} samples)",
        super::target::shown(output).display()
    ));
}
