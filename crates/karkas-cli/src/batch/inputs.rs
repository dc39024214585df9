//! The inputs of a batch from `--inputs`: a folder (its files), a glob pattern, a `.txt` list
//! of paths, or one file; the pattern matching is the `glob` crate's.

use anyhow::{bail, Context, Result};
use std::collections::{HashMap, HashSet};
use std::io::Read;
use std::path::{Path, PathBuf};

/// The longest list file read (a list of paths, not data): 64 MiB.
const MAX_LIST_BYTES: u64 = 64 << 20;

/// The input files named by `specs`, in order, each once: a folder gives its files (not its
/// sub-folders, nor names starting with `.`) sorted by name; a pattern with `*`, `?` or `[`
/// its matching files sorted; a `.txt` file the paths on its lines (blank lines and lines
/// starting with `#` skipped; relative paths relative to the list's folder); any other
/// existing path itself (a device or a pipe too: the command's reader refuses what it cannot
/// read, as a record of that input). Refuses a spec that names nothing, and an empty result.
pub fn expand(specs: &[String]) -> Result<Vec<PathBuf>> {
    if specs.is_empty() {
        bail!("--inputs: name the inputs (a folder, a glob pattern or a .txt list of paths)");
    }
    let mut seen = HashSet::new();
    let mut inputs = Vec::new();
    for spec in specs {
        for path in expand_one(spec)? {
            if seen.insert(path.clone()) {
                inputs.push(path);
            }
        }
    }
    if inputs.is_empty() {
        bail!("--inputs {}: no input files", specs.join(" "));
    }
    Ok(inputs)
}

/// The files of one `--inputs` value.
fn expand_one(spec: &str) -> Result<Vec<PathBuf>> {
    let path = Path::new(spec);
    if spec == "-" {
        bail!("--inputs -: a batch reads files, not standard input");
    }
    if path.is_dir() {
        let mut files = Vec::new();
        let entries =
            std::fs::read_dir(path).with_context(|| format!("--inputs {spec}: cannot list"))?;
        for entry in entries {
            let entry = entry.with_context(|| format!("--inputs {spec}: cannot list"))?;
            let hidden = entry.file_name().to_string_lossy().starts_with('.');
            let file = entry.path();
            if !hidden && file.is_file() {
                files.push(file);
            }
        }
        files.sort();
        return Ok(files);
    }
    if spec.contains(['*', '?', '[']) && !path.exists() {
        // As a shell expands it: `*` does not match a leading dot.
        let options = glob::MatchOptions {
            require_literal_leading_dot: true,
            ..glob::MatchOptions::new()
        };
        let pattern = glob::glob_with(spec, options)
            .with_context(|| format!("--inputs {spec}: bad pattern"))?;
        let mut files: Vec<PathBuf> = pattern.flatten().filter(|p| p.is_file()).collect();
        if files.is_empty() {
            bail!("--inputs {spec}: the pattern matches no file");
        }
        files.sort();
        return Ok(files);
    }
    if !path.exists() {
        bail!("--inputs {spec}: no such file or folder");
    }
    if path.is_file()
        && path
            .extension()
            .is_some_and(|e| e.eq_ignore_ascii_case("txt"))
    {
        return read_list(path);
    }
    Ok(vec![path.to_path_buf()])
}

/// The paths listed in `list`, one a line.
fn read_list(list: &Path) -> Result<Vec<PathBuf>> {
    let name = list.display();
    let mut bytes = Vec::new();
    std::fs::File::open(list)
        .with_context(|| format!("cannot read {name}"))?
        .take(MAX_LIST_BYTES + 1)
        .read_to_end(&mut bytes)
        .with_context(|| format!("cannot read {name}"))?;
    if bytes.len() as u64 > MAX_LIST_BYTES {
        bail!("{name}: a list of inputs longer than 64 MiB");
    }
    let text = String::from_utf8(bytes)
        .map_err(|e| anyhow::anyhow!("{name}: not a text list of paths ({e})"))?;
    let base = list.parent().unwrap_or(Path::new(""));
    let mut files = Vec::new();
    for (number, line) in text.lines().enumerate() {
        let line = line.trim();
        if line.is_empty() || line.starts_with('#') {
            continue;
        }
        if line.contains('\0') {
            bail!("{name}, line {}: not a path", number + 1);
        }
        let path = Path::new(line);
        files.push(if path.is_absolute() {
            path.to_path_buf()
        } else {
            base.join(path)
        });
    }
    Ok(files)
}

/// Refuses inputs whose outputs would share a name (`a/x.dat` and `b/x.csv` both write
/// `OUT/x.*`), naming the first two.
pub fn check_distinct_stems(inputs: &[PathBuf]) -> Result<()> {
    let mut by_stem: HashMap<&std::ffi::OsStr, &Path> = HashMap::new();
    for input in inputs {
        let Some(stem) = input.file_stem() else {
            bail!("{}: an input needs a file name", input.display());
        };
        if let Some(first) = by_stem.insert(stem, input) {
            bail!(
                "{} and {} would write outputs of the same name ({}); rename one or run them in \
                 two batches",
                first.display(),
                input.display(),
                stem.to_string_lossy()
            );
        }
    }
    Ok(())
}

#[cfg(test)]
mod tests {
    use super::*;

    fn touch(dir: &Path, name: &str) -> PathBuf {
        let path = dir.join(name);
        std::fs::write(&path, "0 0\n1 1\n").unwrap();
        path
    }

    #[test]
    fn folders_patterns_and_lists_expand_in_order() {
        let dir = tempfile::tempdir().unwrap();
        let b = touch(dir.path(), "b.dat");
        let a = touch(dir.path(), "a.dat");
        touch(dir.path(), ".hidden.dat");
        std::fs::create_dir(dir.path().join("sub")).unwrap();
        let folder = dir.path().to_string_lossy().into_owned();
        assert_eq!(expand(&[folder]).unwrap(), [a.clone(), b.clone()]);
        let pattern = dir.path().join("*.dat").to_string_lossy().into_owned();
        assert_eq!(expand(&[pattern]).unwrap(), [a.clone(), b.clone()]);
        let list = dir.path().join("list.txt");
        std::fs::write(&list, "# the foils\nb.dat\n\na.dat\nb.dat\n").unwrap();
        let listed = expand(&[list.to_string_lossy().into_owned()]).unwrap();
        assert_eq!(listed, [b.clone(), a.clone()]);
        let missing = dir.path().join("none.dat").to_string_lossy().into_owned();
        assert!(expand(&[missing])
            .unwrap_err()
            .to_string()
            .contains("no such file"));
        let nothing = dir.path().join("*.csv").to_string_lossy().into_owned();
        assert!(expand(&[nothing])
            .unwrap_err()
            .to_string()
            .contains("matches no file"));
        assert!(expand(&[]).is_err());
    }

    #[test]
    fn inputs_with_one_stem_are_refused() {
        let inputs = [PathBuf::from("a/x.dat"), PathBuf::from("b/x.csv")];
        let error = check_distinct_stems(&inputs).unwrap_err().to_string();
        assert!(error.contains("a/x.dat and b/x.csv"), "{error}");
        assert!(check_distinct_stems(&[PathBuf::from("a/x.dat"), PathBuf::from("y.dat")]).is_ok());
    }
}
