//! Helpers shared by the test modules.

use std::path::PathBuf;

/// A fresh temporary directory and the path of `name` in it; the directory is removed when
/// the returned guard is dropped.
pub fn scratch(name: &str) -> (tempfile::TempDir, PathBuf) {
    let dir = tempfile::tempdir().unwrap();
    let path = dir.path().join(name);
    (dir, path)
}
