//! The inputs of a batch from `--inputs`: a folder (its files), a glob pattern, a `.txt` list
//! of paths, or one file; the pattern matching is the `glob` crate's.

use anyhow::{bail, Context, Result};
use std::collections::{HashMap, HashSet};
use std::io::Read;
use std::path::{Component, Path, PathBuf};

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

/// The name, without extension, of each input's outputs in the folder `out`: `OUT/<stem>`,
/// or with `tree` the input's path below it, `OUT/<sub/folders/stem>`. Refuses an input
/// outside `tree`, and two inputs whose outputs would share a name (`a/x.dat` and `b/x.csv`
/// without `tree`), naming the first two.
pub fn output_bases(inputs: &[PathBuf], out: &Path, tree: Option<&Path>) -> Result<Vec<PathBuf>> {
    let mut first: HashMap<PathBuf, &Path> = HashMap::new();
    let mut bases = Vec::with_capacity(inputs.len());
    for input in inputs {
        let name = match tree {
            Some(tree) => below(input, tree)?.with_extension(""),
            None => match input.file_stem() {
                Some(stem) => PathBuf::from(stem),
                None => bail!("{}: an input needs a file name", input.display()),
            },
        };
        let base = out.join(&name);
        if let Some(earlier) = first.insert(base.clone(), input) {
            let hint = if tree.is_some() {
                "rename one or run them in two batches"
            } else {
                "name the outputs after their folders with --tree DIR, or run them in two batches"
            };
            bail!(
                "{} and {} would write outputs of the same name ({}); {hint}",
                earlier.display(),
                input.display(),
                name.display()
            );
        }
        bases.push(base);
    }
    Ok(bases)
}

/// The path of `input` below the folder `tree`, with no `..` in it.
fn below(input: &Path, tree: &Path) -> Result<PathBuf> {
    let lexical = |p: &Path| -> PathBuf {
        p.components()
            .filter(|c| !matches!(c, Component::CurDir))
            .collect()
    };
    let relative = lexical(input)
        .strip_prefix(lexical(tree))
        .map(Path::to_path_buf)
        .or_else(|_| {
            let (input, tree) = (input.canonicalize()?, tree.canonicalize()?);
            input
                .strip_prefix(tree)
                .map(Path::to_path_buf)
                .map_err(|_| std::io::Error::other("outside"))
        });
    match relative {
        Ok(relative)
            if relative.file_name().is_some()
                && relative
                    .components()
                    .all(|c| matches!(c, Component::Normal(_))) =>
        {
            Ok(relative)
        }
        _ => bail!(
            "--tree {}: the input {} is not in that folder",
            tree.display(),
            input.display()
        ),
    }
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
    fn outputs_are_named_by_stem_or_by_the_path_below_the_tree() {
        let inputs = [PathBuf::from("a/x.dat"), PathBuf::from("b/x.csv")];
        let out = Path::new("out");
        let error = output_bases(&inputs, out, None).unwrap_err().to_string();
        assert!(error.contains("a/x.dat and b/x.csv"), "{error}");
        assert!(error.contains("--tree"), "{error}");
        let two = [PathBuf::from("a/x.dat"), PathBuf::from("y.v2.dat")];
        assert_eq!(
            output_bases(&two, out, None).unwrap(),
            [PathBuf::from("out/x"), PathBuf::from("out/y.v2")]
        );
        let tree = [PathBuf::from("./db/a/x.dat"), PathBuf::from("db/b/x.csv")];
        assert_eq!(
            output_bases(&tree, out, Some(Path::new("db"))).unwrap(),
            [PathBuf::from("out/a/x"), PathBuf::from("out/b/x")]
        );
        let outside = [PathBuf::from("elsewhere/x.dat")];
        let error = output_bases(&outside, out, Some(Path::new("db")))
            .unwrap_err()
            .to_string();
        assert!(error.contains("not in that folder"), "{error}");
        let up = [PathBuf::from("db/../x.dat")];
        assert!(output_bases(&up, out, Some(Path::new("db"))).is_err());
    }
}
