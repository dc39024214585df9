//! The output path: refused when it names an input file.

use anyhow::{bail, Result};
use std::path::Path;

/// Refuses an output path that names the input file: the atomic rename would replace the
/// user's data with the result.
pub fn ensure_distinct(input: &Path, output: &Path) -> Result<()> {
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
