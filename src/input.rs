//! Input files: the one reader every input goes through (coordinate files, tables of every
//! format, aircraft presets). It reads a regular file, or standard input where a caller allows
//! `-`, up to [`MAX_INPUT_BYTES`]; a folder, a FIFO, a device (`/dev/null`, a link to
//! `/dev/zero`), a socket or an oversized file is refused at once with a one-line
//! [`InputError`], before anything blocks or fills memory.

use crate::limits::MAX_INPUT_BYTES;
use std::fs::{self, File};
use std::io::{self, Read};
use std::path::{Path, PathBuf};

/// The input path that means standard input (where a command allows it).
pub const STDIN_PATH: &str = "-";

/// Why an input file was not read.
#[derive(Clone, Debug, PartialEq, Eq, thiserror::Error)]
#[error("{}: {problem}", path.display())]
pub struct InputError {
    /// The path as given.
    pub path: PathBuf,
    /// What is wrong with it.
    pub problem: InputProblem,
}

/// What is wrong with an input path.
#[derive(Clone, Debug, PartialEq, Eq, thiserror::Error)]
pub enum InputProblem {
    /// Nothing exists at the path (or a symbolic link leads nowhere).
    #[error("no such file")]
    NotFound,
    /// The path is a folder.
    #[error("is a folder, not a file")]
    Folder,
    /// The path is a FIFO, a device or a socket (`kind`), not a regular file.
    #[error("not a regular file (a {0})")]
    NotRegular(&'static str),
    /// The file is larger than [`MAX_INPUT_BYTES`].
    #[error("larger than the input limit of {limit_mib} MiB")]
    TooLarge {
        /// The limit in MiB.
        limit_mib: u64,
    },
    /// The operating system refused (permission denied, I/O error …): its message.
    #[error("{0}")]
    Os(String),
}

impl InputError {
    fn new(path: &Path, problem: InputProblem) -> Self {
        Self {
            path: path.to_path_buf(),
            problem,
        }
    }

    fn os(path: &Path, e: &io::Error) -> Self {
        let problem = match e.kind() {
            io::ErrorKind::NotFound => InputProblem::NotFound,
            _ => InputProblem::Os(e.to_string()),
        };
        Self::new(path, problem)
    }
}

/// The bytes of the regular file `path` (links followed), at most [`MAX_INPUT_BYTES`].
pub fn read_input(path: &Path) -> Result<Vec<u8>, InputError> {
    let meta = fs::metadata(path).map_err(|e| InputError::os(path, &e))?;
    check_kind(path, &meta)?;
    if meta.len() > MAX_INPUT_BYTES {
        return Err(too_large(path));
    }
    let file = open_without_blocking(path).map_err(|e| InputError::os(path, &e))?;
    // The path may have been replaced between the check and the open: check what was opened.
    let opened = file.metadata().map_err(|e| InputError::os(path, &e))?;
    check_kind(path, &opened)?;
    read_capped(path, file)
}

/// Opens `path` for reading without waiting for a writer: a FIFO put in place of the checked
/// file between the check and the open would otherwise block the open until something writes
/// to it (O_NONBLOCK; a regular file reads as without it).
fn open_without_blocking(path: &Path) -> io::Result<File> {
    let mut options = fs::OpenOptions::new();
    options.read(true);
    #[cfg(unix)]
    {
        use std::os::unix::fs::OpenOptionsExt;
        options.custom_flags(libc::O_NONBLOCK);
    }
    options.open(path)
}

/// [`read_input`], or standard input when `path` is `-` (read through the same cap).
pub fn read_input_or_stdin(path: &Path) -> Result<Vec<u8>, InputError> {
    if path.as_os_str() == STDIN_PATH {
        read_capped(path, io::stdin().lock())
    } else {
        read_input(path)
    }
}

/// Whether something (a file, folder, device, or a link, even a broken one) exists at `path`.
pub fn exists(path: &Path) -> bool {
    fs::symlink_metadata(path).is_ok()
}

/// Read all of `r`, refusing more than [`MAX_INPUT_BYTES`].
fn read_capped(path: &Path, r: impl Read) -> Result<Vec<u8>, InputError> {
    let mut bytes = Vec::new();
    r.take(MAX_INPUT_BYTES + 1)
        .read_to_end(&mut bytes)
        .map_err(|e| InputError::os(path, &e))?;
    if bytes.len() as u64 > MAX_INPUT_BYTES {
        return Err(too_large(path));
    }
    Ok(bytes)
}

fn too_large(path: &Path) -> InputError {
    InputError::new(
        path,
        InputProblem::TooLarge {
            limit_mib: MAX_INPUT_BYTES >> 20,
        },
    )
}

/// A regular file, else the error naming what it is.
fn check_kind(path: &Path, meta: &fs::Metadata) -> Result<(), InputError> {
    if meta.is_file() {
        return Ok(());
    }
    let problem = if meta.is_dir() {
        InputProblem::Folder
    } else {
        InputProblem::NotRegular(special_kind(meta))
    };
    Err(InputError::new(path, problem))
}

/// What a non-regular, non-folder file is.
#[cfg(unix)]
fn special_kind(meta: &fs::Metadata) -> &'static str {
    use std::os::unix::fs::FileTypeExt;
    let t = meta.file_type();
    if t.is_fifo() {
        "FIFO"
    } else if t.is_char_device() {
        "character device"
    } else if t.is_block_device() {
        "block device"
    } else if t.is_socket() {
        "socket"
    } else {
        "special file"
    }
}

/// What a non-regular, non-folder file is.
#[cfg(not(unix))]
fn special_kind(_meta: &fs::Metadata) -> &'static str {
    "special file"
}

/// The lines of a text file whatever its line ends: `\n`, `\r\n` or a lone `\r` (old Mac
/// files), without the terminators.
pub fn text_lines(text: &str) -> impl Iterator<Item = &str> {
    let mut rest = Some(text).filter(|t| !t.is_empty());
    std::iter::from_fn(move || {
        let s = rest?;
        match s.find(['\n', '\r']) {
            Some(i) => {
                let skip = if s[i..].starts_with("\r\n") { 2 } else { 1 };
                rest = Some(&s[i + skip..]).filter(|r| !r.is_empty());
                Some(&s[..i])
            }
            None => {
                rest = None;
                Some(s)
            }
        }
    })
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn every_line_end_splits() {
        let lines: Vec<&str> = text_lines("a\r\nb\rc\nd").collect();
        assert_eq!(lines, ["a", "b", "c", "d"]);
        assert_eq!(text_lines("a\n").collect::<Vec<_>>(), ["a"]);
        assert_eq!(text_lines("a\n\nb").collect::<Vec<_>>(), ["a", "", "b"]);
        assert_eq!(text_lines("").count(), 0);
    }

    #[test]
    fn special_files_are_refused_at_once() {
        if Path::new("/dev/null").exists() {
            let e = read_input(Path::new("/dev/null")).unwrap_err();
            assert_eq!(
                e.to_string(),
                "/dev/null: not a regular file (a character device)"
            );
        }
        let e = read_input(Path::new("/")).unwrap_err();
        assert_eq!(e.problem, InputProblem::Folder);
        let e = read_input(Path::new("/no/such/file")).unwrap_err();
        assert_eq!(e.problem, InputProblem::NotFound);
    }

    /// A FIFO without a writer opens at once (the open that follows the kind check cannot be
    /// held by a FIFO swapped in after the check), and the check of what was opened refuses it.
    #[cfg(unix)]
    #[test]
    fn a_fifo_opens_without_waiting_for_a_writer() {
        let dir = std::env::temp_dir().join(format!("polargen-input-fifo-{}", std::process::id()));
        fs::create_dir_all(&dir).unwrap();
        let fifo = dir.join("swapped");
        let made = std::process::Command::new("mkfifo").arg(&fifo).status();
        if !made.is_ok_and(|s| s.success()) {
            fs::remove_dir_all(&dir).ok();
            return; // no mkfifo on this system: nothing to check
        }
        let (tx, rx) = std::sync::mpsc::channel();
        let path = fifo.clone();
        std::thread::spawn(move || {
            let opened = open_without_blocking(&path).and_then(|f| f.metadata());
            tx.send(opened.map(|m| check_kind(&path, &m).map_err(|e| e.problem)))
                .ok();
        });
        let outcome = rx.recv_timeout(std::time::Duration::from_secs(10));
        fs::remove_dir_all(&dir).ok();
        let kind = outcome.expect("the open waited for a writer").unwrap();
        assert!(matches!(kind, Err(InputProblem::NotRegular(_))), "{kind:?}");
    }
}
