//! Where every reader's bytes come from, and the bounds every reader keeps.
//!
//! - An input is a file or, when its path is `-`, standard input ([`STDIN`]). It is opened
//!   once and read in one pass, so pipes, process substitutions (`<(...)`) and FIFOs work.
//! - No line may be longer than [`MAX_LINE_BYTES`]: `/dev/zero`, a binary file or a file
//!   without line breaks is refused after reading at most that much.
//! - A NUL byte, or a line that is not UTF-8, is refused with its line number: text formats
//!   hold neither.
//! - What a reader keeps (the text of a file read whole, or the points of a streamed one) is
//!   charged against one process-wide cap, [`max_input_bytes`] (set by the command line's
//!   `--max-memory`), so an endless or huge input fails instead of exhausting the machine.
//! - Error messages quote at most [`EXCERPT_CHARS`] characters of the input ([`excerpt`]).
//!
//! Hand-written: the standard library's `read_line` has no length bound, and the bound is
//! what turns `/dev/zero` from an out-of-memory abort into a one-line error.

use std::io::{BufRead, Read};
use std::path::{Path, PathBuf};
use std::sync::atomic::{AtomicU64, Ordering};

use crate::error::{data_error, IoError, Location};

/// The path that means standard input.
pub const STDIN: &str = "-";

/// How standard input is named in messages.
pub const STDIN_NAME: &str = "<stdin>";

/// The longest line any text reader accepts, in bytes (1 MiB).
pub const MAX_LINE_BYTES: usize = 1 << 20;

/// The most characters of input an error message quotes.
pub const EXCERPT_CHARS: usize = 100;

/// The default cap on what one read may keep: 2 GiB, as the command line's default.
pub const DEFAULT_MAX_INPUT_BYTES: u64 = 2 << 30;

static MAX_INPUT_BYTES: AtomicU64 = AtomicU64::new(DEFAULT_MAX_INPUT_BYTES);

/// Sets the cap on what one read may keep in memory (process-wide).
pub fn set_max_input_bytes(bytes: u64) {
    MAX_INPUT_BYTES.store(bytes.max(1), Ordering::Relaxed);
}

/// The cap on what one read may keep in memory, in bytes.
pub fn max_input_bytes() -> u64 {
    MAX_INPUT_BYTES.load(Ordering::Relaxed)
}

/// Fails when a reader of `path` would keep `bytes` in memory, more than the cap.
pub fn check_held(path: &Path, bytes: u128) -> Result<(), IoError> {
    let cap = max_input_bytes();
    if bytes > u128::from(cap) {
        return Err(data_error(
            path,
            format!(
                "the input needs more than the memory cap of {cap} bytes (raise it with \
                 --max-memory or KARKAS_MAX_MEMORY on the command line, \
                 karkas.set_max_input_bytes in Python)"
            ),
        ));
    }
    Ok(())
}

/// True when `path` means standard input.
pub fn is_stdin(path: &Path) -> bool {
    path.as_os_str() == STDIN
}

/// The name of `path` in messages: the path itself, or [`STDIN_NAME`] for `-`.
pub fn display_name(path: &Path) -> PathBuf {
    if is_stdin(path) {
        PathBuf::from(STDIN_NAME)
    } else {
        path.to_path_buf()
    }
}

/// An opened input: a buffered byte stream (itself [`BufRead`], for binary formats whose
/// readers bound what they keep with [`check_held`]) and the name errors give it.
pub struct Input {
    /// The name of the input in messages (see [`display_name`]).
    pub name: PathBuf,
    reader: Box<dyn BufRead + Send>,
    /// The file's size when known (0 for a stream): what [`Input::read_text`] reserves.
    size: u64,
}

impl std::fmt::Debug for Input {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.debug_struct("Input").field("name", &self.name).finish()
    }
}

impl Input {
    /// Opens `path` (`-`: standard input) for one buffered pass.
    ///
    /// # Examples
    ///
    /// ```
    /// use std::path::Path;
    /// use karkas_io::input::Input;
    ///
    /// let missing = Input::open(Path::new("no-such-folder/points.csv"));
    /// assert!(missing.unwrap_err().to_string().contains("points.csv")); // the error names the file
    /// ```
    pub fn open(path: &Path) -> Result<Input, IoError> {
        let name = display_name(path);
        let mut size = 0;
        let reader: Box<dyn BufRead + Send> = if is_stdin(path) {
            Box::new(std::io::BufReader::with_capacity(1 << 16, std::io::stdin()))
        } else {
            let file = std::fs::File::open(path).map_err(IoError::open(&name))?;
            let metadata = file.metadata();
            if metadata.as_ref().is_ok_and(|m| m.is_dir()) {
                return Err(data_error(&name, "is a directory, not a file"));
            }
            size = metadata.map_or(0, |m| m.len());
            Box::new(std::io::BufReader::with_capacity(1 << 16, file))
        };
        Ok(Input { name, reader, size })
    }

    /// An input reading from `reader` (e.g. bytes already in memory), named `name`.
    ///
    /// # Examples
    ///
    /// ```
    /// use karkas_io::input::Input;
    ///
    /// let mut input = Input::from_reader("inline.csv", &b"x,y\n0,1\n"[..]);
    /// assert_eq!(input.read_text()?, "x,y\n0,1\n");
    /// # Ok::<(), karkas_io::IoError>(())
    /// ```
    pub fn from_reader(name: impl Into<PathBuf>, reader: impl BufRead + Send + 'static) -> Input {
        Input {
            name: name.into(),
            reader: Box::new(reader),
            size: 0,
        }
    }

    /// Reads the next line (its end-of-line bytes kept) into `buf`: see [`read_line_bytes`].
    pub fn read_line_bytes(&mut self, buf: &mut Vec<u8>, line: usize) -> Result<bool, IoError> {
        read_line_bytes(&mut *self.reader, &self.name, buf, line)
    }

    /// Reads the next line as text into `buf` (cleared first, end of line kept); `Ok(false)`
    /// at the end. Errors as [`Input::read_line_bytes`], and for a line that is not UTF-8.
    pub fn read_line(
        &mut self,
        bytes: &mut Vec<u8>,
        buf: &mut String,
        line: usize,
    ) -> Result<bool, IoError> {
        buf.clear();
        if !self.read_line_bytes(bytes, line)? {
            return Ok(false);
        }
        match std::str::from_utf8(bytes) {
            Ok(text) => buf.push_str(text),
            Err(_) => return Err(self.at(line).error(not_utf8_message())),
        }
        Ok(true)
    }

    /// The whole input as text, read line by line with the bounds of
    /// [`Input::read_line_bytes`], its size charged against [`max_input_bytes`].
    pub fn read_text(&mut self) -> Result<String, IoError> {
        // A file's text is at most its size: reserved once, not grown by doubling (each
        // doubling copies the text and touches fresh pages). Never more than the cap.
        let reserve = self.size.min(max_input_bytes());
        let mut text = String::with_capacity(usize::try_from(reserve).unwrap_or(0));
        let mut bytes = Vec::new();
        let mut line = 0;
        loop {
            line += self.take_whole_lines(&mut text)?;
            line += 1;
            if !self.read_line_bytes(&mut bytes, line)? {
                return Ok(text);
            }
            match std::str::from_utf8(&bytes) {
                Ok(s) => text.push_str(s),
                Err(_) => return Err(self.at(line).error(not_utf8_message())),
            }
            check_held(&self.name, text.len() as u128)?;
        }
    }

    /// Appends to `text` the whole lines in the reader's buffer when none of them needs the
    /// line-by-line checks of [`read_line_bytes`] (no NUL byte, UTF-8, and the buffer shorter
    /// than [`MAX_LINE_BYTES`], so no line in it is too long); returns how many. A buffer that
    /// needs them is left for the line-by-line reading, which then reports the error at its
    /// line. The text is the same either way, at a few checks per buffer instead of per line.
    fn take_whole_lines(&mut self, text: &mut String) -> Result<usize, IoError> {
        let available = match self.reader.fill_buf() {
            Ok(bytes) => bytes,
            // The line-by-line reading retries or reports it.
            Err(_) => return Ok(0),
        };
        let Some(last) = memchr::memrchr(b'\n', available) else {
            return Ok(0);
        };
        let block = &available[..=last];
        if block.len() > MAX_LINE_BYTES || memchr::memchr(0, block).is_some() {
            return Ok(0);
        }
        let Ok(whole) = std::str::from_utf8(block) else {
            return Ok(0);
        };
        let (lines, used) = (memchr::memchr_iter(b'\n', block).count(), block.len());
        text.push_str(whole);
        self.reader.consume(used);
        check_held(&self.name, text.len() as u128)?;
        Ok(lines)
    }

    /// The whole input as bytes (a binary format), its size charged against
    /// [`max_input_bytes`] as it is read.
    pub fn read_bytes(&mut self) -> Result<Vec<u8>, IoError> {
        let cap = max_input_bytes();
        let mut bytes = Vec::new();
        (&mut self.reader)
            .take(cap.saturating_add(1))
            .read_to_end(&mut bytes)
            .map_err(IoError::open(&self.name))?;
        check_held(&self.name, bytes.len() as u128)?;
        Ok(bytes)
    }

    fn at(&self, line: usize) -> Location<'_> {
        Location::new(&self.name, line)
    }
}

impl Read for Input {
    fn read(&mut self, buf: &mut [u8]) -> std::io::Result<usize> {
        self.reader.read(buf)
    }
}

impl BufRead for Input {
    fn fill_buf(&mut self) -> std::io::Result<&[u8]> {
        self.reader.fill_buf()
    }

    fn consume(&mut self, amount: usize) {
        self.reader.consume(amount)
    }
}

/// Reads the next line of `reader` (its end-of-line bytes kept) into `buf`, which is cleared
/// first; `Ok(false)` at the end of the input. `line` is the 1-based number of the line being
/// read and `name` the input's name, for the errors: a line longer than [`MAX_LINE_BYTES`] or
/// holding a NUL byte (binary data).
pub fn read_line_bytes<R: BufRead + ?Sized>(
    reader: &mut R,
    name: &Path,
    buf: &mut Vec<u8>,
    line: usize,
) -> Result<bool, IoError> {
    buf.clear();
    loop {
        let available = match reader.fill_buf() {
            Ok(bytes) => bytes,
            Err(e) if e.kind() == std::io::ErrorKind::Interrupted => continue,
            Err(e) => return Err(IoError::open(name)(e)),
        };
        if available.is_empty() {
            return Ok(!buf.is_empty());
        }
        let (take, done) = match available.iter().position(|&b| b == b'\n') {
            Some(k) => (k + 1, true),
            None => (available.len(), false),
        };
        let room = (MAX_LINE_BYTES + 2).saturating_sub(buf.len());
        let chunk = &available[..take.min(room)];
        if chunk.contains(&0) {
            return Err(Location::new(name, line)
                .error("binary data (a NUL byte): expected a text file, one line per record"));
        }
        buf.extend_from_slice(chunk);
        let used = chunk.len();
        reader.consume(used);
        if buf.len() > MAX_LINE_BYTES + 1 {
            return Err(Location::new(name, line).error(format!(
                "line longer than {} MiB: not a text file of records, or a file without line \
                 breaks",
                MAX_LINE_BYTES >> 20
            )));
        }
        if done {
            return Ok(true);
        }
    }
}

/// The message for a line that is not UTF-8.
pub(crate) fn not_utf8_message() -> &'static str {
    "not UTF-8 text (binary data, or a file saved in another encoding: save it as UTF-8)"
}

/// Reads the whole text file `path` (`-`: standard input), with the bounds of [`Input`].
pub fn read_text(path: &Path) -> Result<String, IoError> {
    Input::open(path)?.read_text()
}

/// At most [`EXCERPT_CHARS`] characters of `text`, with `...` when cut: what an error message
/// may quote of the input.
pub fn excerpt(text: &str) -> String {
    let mut chars = text.char_indices();
    match chars.nth(EXCERPT_CHARS) {
        Some((k, _)) => format!("{}...", &text[..k]),
        None => text.to_owned(),
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn input(bytes: &'static [u8]) -> Input {
        Input::from_reader("f.csv", bytes)
    }

    #[test]
    fn lines_are_read_whole_with_their_numbers_in_errors() {
        let mut inp = input(b"a,b\r\n1,2\n3,4");
        let (mut bytes, mut buf) = (Vec::new(), String::new());
        assert!(inp.read_line(&mut bytes, &mut buf, 1).unwrap());
        assert_eq!(buf, "a,b\r\n");
        assert!(inp.read_line(&mut bytes, &mut buf, 2).unwrap());
        assert!(inp.read_line(&mut bytes, &mut buf, 3).unwrap());
        assert_eq!(buf, "3,4");
        assert!(!inp.read_line(&mut bytes, &mut buf, 4).unwrap());
        let e = input(b"1,2\n\xff\xfe,3\n").read_text().unwrap_err();
        assert!(e.to_string().starts_with("f.csv:2: not UTF-8 text"), "{e}");
        let e = input(b"1,2\n3\x004\n").read_text().unwrap_err();
        assert!(e.to_string().starts_with("f.csv:2: binary data"), "{e}");
    }

    #[test]
    fn an_endless_line_is_refused_after_the_bound() {
        let endless = std::io::BufReader::new(std::io::repeat(b'7'));
        let mut inp = Input::from_reader("zeros", endless);
        let e = inp.read_text().unwrap_err().to_string();
        assert!(e.starts_with("zeros:1: line longer than 1 MiB"), "{e}");
    }

    #[test]
    fn excerpts_are_bounded() {
        assert_eq!(excerpt("short"), "short");
        let long = "é".repeat(300);
        let e = excerpt(&long);
        assert_eq!(e.chars().count(), EXCERPT_CHARS + 3);
        assert!(e.ends_with("..."));
    }

    #[test]
    fn the_standard_input_has_a_name() {
        assert!(is_stdin(Path::new("-")));
        assert_eq!(display_name(Path::new("-")), PathBuf::from("<stdin>"));
        assert_eq!(display_name(Path::new("a.csv")), PathBuf::from("a.csv"));
    }
}
