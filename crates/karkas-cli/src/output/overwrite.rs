//! The output path: refused when it names an input file (standard output never does).

use anyhow::{bail, Result};
use std::path::Path;

/// Refuses an output path that names the input file: the atomic rename would replace the
/// user's data with the result.
pub fn ensure_distinct(input: &Path, output: &Path) -> Result<()> {
    if karkas_io::write::is_stdout(output) {
        return Ok(());
    }
    let same = match (input.canonicalize(), output.canonicalize()) {
        (Ok(a), Ok(b)) => a == b,
        _ => false,
    };
    if same {
        bail!(
            "{}: the output would overwrite the input file; choose another output name",
            output.display()
        );
    }
    Ok(())
}
