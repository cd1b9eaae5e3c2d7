//! Output files: the checks every writer makes on its target path, and the one way every
//! result (table, figure, report, time history) reaches the file system.
//!
//! What an output path means:
//!
//! * `-` ([`STDOUT_PATH`]) — standard output.
//! * A path that leads to one of this process's open descriptors (`/dev/stdout`,
//!   `/dev/stderr`, `/dev/fd/N`, `/proc/self/fd/N`) — that descriptor, written in place.
//!   Renaming over such a path would replace whatever the descriptor is connected to: with
//!   `( echo a; polargen … --out /dev/stdout; echo b ) > f` the shell's file `f` would be
//!   swapped for a new one and lose `a` and `b`.
//! * An existing device or FIFO — opened and written in place (streamed), never renamed over;
//!   a FIFO that no process opens for reading within 30 s is an error.
//! * Anything else names a regular file, written atomically as a one-file [`OutputSet`]: into
//!   a hidden staging folder beside the target (`.polargen-set-<pid>.<random>/`, a short
//!   name, so any legal file name can be staged under its own name), flushed and synced, then
//!   renamed over the target. Missing folders are created; a symbolic link is written through
//!   (its target is replaced, the link stays). A failure at any step removes the staging
//!   folder and leaves the target as it was.
//!
//! Several files that belong together (a set of polars, a report) go through one
//! [`OutputSet`]: renamed into place together, or not at all (the targets they replace are
//! kept as hard links in the stage until the set is complete, and put back on any failure).
//! [`remove_staged_files_on_signals`] makes SIGINT/SIGTERM/SIGHUP remove whatever is staged;
//! the staging folders of a process that was killed outright are removed by the next run
//! that writes into the same folder.
//!
//! Standard output is a result like any file: when it is closed (`>&-`; the Rust runtime then
//! leaves `/dev/null` open in its place) or cannot be written, the write is an error.
//!
//! Paths are checked by [`check_output_path`] before a long computation: the path itself (a
//! file name longer than [`MAX_FILE_NAME_BYTES`] is refused), and that the folder that will
//! hold the file accepts new files (a probe file is created and removed). Every error is an
//! [`OutputError`] naming the path it concerns, never a temporary name.

mod interrupt;
mod set;

pub use interrupt::remove_staged_files_on_signals;
pub use set::OutputSet;

use std::fs::{self, File, OpenOptions};
use std::io::{self, BufWriter, Write};
use std::path::{Component, Path, PathBuf};

/// The output path that means standard output.
pub const STDOUT_PATH: &str = "-";

/// Longest file name (one path component) the file systems in use accept, in bytes (NAME_MAX
/// of Linux and the BSDs, the limit of ext4, XFS, btrfs, APFS).
pub const MAX_FILE_NAME_BYTES: usize = 255;

/// Longest output path, in bytes: Linux's PATH_MAX (4096 with the terminating NUL) less room
/// for the staging folder a file passes through (`.polargen-set-<pid>.<random>/`).
pub const MAX_PATH_BYTES: usize = 4000;

/// Longest chain of symbolic links followed when looking for an open descriptor.
const MAX_LINK_HOPS: usize = 40;

/// Why an output could not be written.
#[derive(Debug, thiserror::Error)]
pub enum OutputError {
    /// The path cannot name an output file: `path` (the path itself or a folder above it)
    /// is `reason`.
    #[error("{path}: {reason}")]
    BadPath {
        /// The path, or the folder above it, that is wrong.
        path: PathBuf,
        /// What is wrong with it.
        reason: &'static str,
    },
    /// Creating a folder, writing, syncing or renaming failed.
    #[error("{path}: {source}")]
    Io {
        /// The file (or folder) concerned.
        path: PathBuf,
        /// The operating-system error.
        #[source]
        source: io::Error,
    },
}

impl OutputError {
    /// Wrap an I/O error with the path it concerns.
    pub fn io(path: impl Into<PathBuf>, source: io::Error) -> Self {
        Self::Io {
            path: path.into(),
            source,
        }
    }

    /// The path the error concerns (the requested path or a folder above it).
    pub fn path(&self) -> &Path {
        match self {
            Self::BadPath { path, .. } | Self::Io { path, .. } => path,
        }
    }

    /// The error's text without its path when that path is `requested` (for messages that
    /// name the requested path themselves).
    pub fn detail_for(&self, requested: &Path) -> String {
        match self {
            Self::BadPath { path, reason } if path == requested => (*reason).to_string(),
            Self::Io { path, source } if path == requested => source.to_string(),
            other => other.to_string(),
        }
    }

    pub(crate) fn bad(path: impl Into<PathBuf>, reason: &'static str) -> Self {
        Self::BadPath {
            path: path.into(),
            reason,
        }
    }
}

/// `v` with `decimals` decimals and never a negative zero (a value that rounds to zero is
/// written `0.000`, not `-0.000`): how numbers are written into text outputs.
pub fn fixed_decimals(v: f64, decimals: usize) -> String {
    let s = format!("{v:.decimals$}");
    match s.strip_prefix('-') {
        Some(rest) if rest.chars().all(|c| c == '0' || c == '.') => rest.to_string(),
        _ => s,
    }
}

/// Where the bytes for an output path go.
#[derive(Clone, Debug, PartialEq, Eq)]
enum Target {
    /// This process's standard output.
    Stdout,
    /// This process's standard error.
    Stderr,
    /// An existing device, FIFO or inherited descriptor, written in place.
    InPlace(PathBuf),
    /// A regular file (existing or not), replaced atomically: the link's target for a link.
    File(PathBuf),
}

/// Check that `path` can name an output: `-`; a path to
/// one of this process's descriptors, a device or a FIFO; or a file name (not ending in `/`,
/// `.` or `..`) that, if it exists, is a regular file or a link to one (not a folder, socket
/// or broken link), below a folder (the nearest existing folder above it must not be a file).
///
/// For a regular file it also checks, by creating and removing a temporary probe file, that
/// the nearest existing folder that will hold it accepts new files (a read-only or
/// permission-denied folder is found here, not after the computation); for standard output,
/// that it is open.
pub fn check_output_path(path: &Path) -> Result<(), OutputError> {
    let target = resolve(path)?;
    if target == Target::Stdout {
        return stdout_open().map_err(|e| OutputError::io(path, e));
    }
    if let Target::File(target) = target {
        let mut dir = match target.parent().filter(|d| !d.as_os_str().is_empty()) {
            Some(d) => d.to_path_buf(),
            None => PathBuf::from("."),
        };
        while !dir.is_dir() {
            match dir.parent().filter(|d| !d.as_os_str().is_empty()) {
                Some(d) => dir = d.to_path_buf(),
                None => {
                    dir = PathBuf::from(".");
                    break;
                }
            }
        }
        tempfile::Builder::new()
            .prefix(".polargen-probe.")
            .tempfile_in(&dir)
            .map_err(|e| OutputError::Io {
                path: dir.clone(),
                source: io::Error::new(
                    e.kind(),
                    format!("cannot create files in this folder: {}", without_path(e)),
                ),
            })?;
    }
    Ok(())
}

/// Write the output `path` (see the module documentation) with `body`, which writes the
/// whole content into the writer it is given. A regular file appears only when `body` and
/// every step after it succeeded.
pub fn write_output<E, F>(path: &Path, body: F) -> Result<(), E>
where
    E: From<OutputError>,
    F: FnOnce(&mut dyn Write) -> Result<(), E>,
{
    match resolve(path)? {
        Target::File(_) => {
            let mut set = OutputSet::new();
            set.write(path, body)?;
            set.commit()?;
            Ok(())
        }
        stream => stream_into(path, &stream, body),
    }
}

/// Writes `bytes` to `path` ([`write_output`]: a regular file appears whole or not at all).
pub fn write_output_bytes(path: &Path, bytes: &[u8]) -> Result<(), OutputError> {
    write_output(path, |w| {
        w.write_all(bytes).map_err(|e| OutputError::io(path, e))
    })
}

/// Writes `bytes` to standard output ([`write_output`] of `-`: an error when standard output
/// is closed or cannot be written).
pub fn write_stdout(bytes: &[u8]) -> Result<(), OutputError> {
    let path = Path::new(STDOUT_PATH);
    write_output(path, |w| {
        w.write_all(bytes).map_err(|e| OutputError::io(path, e))
    })
}

/// Write the output `path` with `body`, which writes the whole content into the file named by
/// the path it is given (for encoders that only write to named files, such as the PNG
/// encoder, which picks its format from the name: the name given ends in `.{extension}`).
/// The file is then renamed over `path`, or, for a stream target, copied into it.
pub fn write_output_via_file<E, F>(path: &Path, extension: &str, body: F) -> Result<(), E>
where
    E: From<OutputError>,
    F: FnOnce(&Path) -> Result<(), E>,
{
    match resolve(path)? {
        Target::File(_) => {
            let mut set = OutputSet::new();
            let staged = set.stage_with_extension(path, extension)?;
            body(&staged)?;
            set.commit()?;
            Ok(())
        }
        stream => {
            // Encoded into a staging folder in the system's temporary folder, then copied.
            let scratch = tempfile::Builder::new()
                .prefix(".polargen-output.")
                .tempdir()
                .map_err(|e| OutputError::io(path, without_path(e)))?;
            let file = scratch.path().join(format!("output.{extension}"));
            body(&file)?;
            let mut bytes = File::open(&file).map_err(|e| OutputError::io(path, e))?;
            stream_into(path, &stream, |w| {
                io::copy(&mut bytes, w)
                    .map(|_| ())
                    .map_err(|e| E::from(OutputError::io(path, e)))
            })
        }
    }
}

/// Whether `path` names a regular file (existing or not, through a link), not a stream:
/// standard output, a descriptor, a device or a FIFO.
pub fn names_a_file(path: &Path) -> bool {
    matches!(resolve(path), Ok(Target::File(_)))
}

/// Whether `path` means this process's standard output (`-`, `/dev/stdout`, `/proc/self/fd/1`
/// …): a caller that writes data there keeps its other output off standard output.
pub fn is_stdout(path: &Path) -> bool {
    matches!(resolve(path), Ok(Target::Stdout))
}

/// Run `body` on a buffered writer into the stream `target` of `path`, then flush.
fn stream_into<E, F>(path: &Path, target: &Target, body: F) -> Result<(), E>
where
    E: From<OutputError>,
    F: FnOnce(&mut dyn Write) -> Result<(), E>,
{
    let io_err = |e| E::from(OutputError::io(path, e));
    match target {
        Target::Stdout => {
            stdout_open().map_err(io_err)?;
            let mut w = BufWriter::new(io::stdout().lock());
            body(&mut w)?;
            w.flush().map_err(io_err)
        }
        Target::Stderr => {
            let mut w = BufWriter::new(io::stderr().lock());
            body(&mut w)?;
            w.flush().map_err(io_err)
        }
        Target::InPlace(p) | Target::File(p) => {
            let file = open_in_place(p).map_err(io_err)?;
            let mut w = BufWriter::new(file);
            body(&mut w)?;
            w.flush().map_err(io_err)
        }
    }
}

/// How long a write into a FIFO waits for a process to open it for reading: long enough for
/// a reader started after the run (`cat fifo` in another shell), short of a hang.
const FIFO_READER_WAIT: std::time::Duration = std::time::Duration::from_secs(30);

/// Open the stream `p` for appending (never truncate what is connected to a device, pipe or
/// descriptor). A FIFO is opened without blocking, so that one nobody reads is an error after
/// [`FIFO_READER_WAIT`] instead of a process that waits for ever; once open, writes block as
/// usual while the reader is slow.
#[cfg(unix)]
fn open_in_place(p: &Path) -> io::Result<File> {
    open_in_place_within(p, FIFO_READER_WAIT)
}

/// [`open_in_place`] waiting at most `wait` for a FIFO's reader.
#[cfg(unix)]
fn open_in_place_within(p: &Path, wait: std::time::Duration) -> io::Result<File> {
    use std::os::unix::fs::{FileTypeExt, OpenOptionsExt};
    use std::os::unix::io::AsRawFd;
    if !fs::metadata(p).is_ok_and(|m| m.file_type().is_fifo()) {
        return OpenOptions::new().append(true).open(p);
    }
    let deadline = std::time::Instant::now() + wait;
    loop {
        match OpenOptions::new()
            .append(true)
            .custom_flags(libc::O_NONBLOCK)
            .open(p)
        {
            Ok(file) => {
                let fd = file.as_raw_fd();
                // SAFETY: F_GETFL/F_SETFL on a descriptor this function owns change only its
                // status flags (clearing O_NONBLOCK: writes then wait for a slow reader).
                let cleared = unsafe {
                    let flags = libc::fcntl(fd, libc::F_GETFL);
                    flags != -1 && libc::fcntl(fd, libc::F_SETFL, flags & !libc::O_NONBLOCK) != -1
                };
                return if cleared {
                    Ok(file)
                } else {
                    Err(io::Error::last_os_error())
                };
            }
            Err(e) if e.raw_os_error() == Some(libc::ENXIO) => {
                if std::time::Instant::now() >= deadline {
                    return Err(io::Error::other(format!(
                        "a FIFO that no process reads (waited {:.1} s for a reader)",
                        wait.as_secs_f64()
                    )));
                }
                std::thread::sleep(std::time::Duration::from_millis(20));
            }
            Err(e) => return Err(e),
        }
    }
}

/// Open the stream `p` for appending (never truncate what is connected to a device).
#[cfg(not(unix))]
fn open_in_place(p: &Path) -> io::Result<File> {
    OpenOptions::new().append(true).open(p)
}

/// `Ok` when standard output is open. A process started with standard output closed (`>&-`)
/// finds `/dev/null` there, opened read-write by the Rust runtime (a shell's `>/dev/null`
/// opens it write-only): writing would succeed and lose the result, so that case is an error.
#[cfg(unix)]
fn stdout_open() -> io::Result<()> {
    use std::os::unix::fs::FileTypeExt;
    use std::os::unix::fs::MetadataExt;
    use std::os::unix::io::AsFd;
    let closed = || io::Error::other("standard output is closed: the result has nowhere to go");
    let fd = io::stdout()
        .as_fd()
        .try_clone_to_owned()
        .map_err(|_| closed())?;
    // SAFETY: F_GETFL on a descriptor this process owns reads its status flags only.
    let flags = unsafe { libc::fcntl(std::os::unix::io::AsRawFd::as_raw_fd(&fd), libc::F_GETFL) };
    if flags == -1 {
        return Err(closed());
    }
    if flags & libc::O_ACCMODE != libc::O_RDWR {
        return Ok(());
    }
    let here = File::from(fd).metadata()?;
    let null = fs::metadata("/dev/null")?;
    if here.file_type().is_char_device() && here.rdev() == null.rdev() {
        return Err(closed());
    }
    Ok(())
}

/// `Ok` (no way to tell a closed standard output here).
#[cfg(not(unix))]
fn stdout_open() -> io::Result<()> {
    Ok(())
}

/// `e` without the temporary path the `tempfile` crate adds to its messages (errors name the
/// file as the user requested it, never a hidden temporary name).
pub(crate) fn without_path(e: io::Error) -> io::Error {
    if let Some(code) = e.raw_os_error() {
        return io::Error::from_raw_os_error(code);
    }
    let inner = e
        .get_ref()
        .and_then(|r| r.source())
        .and_then(|s| s.downcast_ref::<io::Error>())
        .and_then(io::Error::raw_os_error);
    if let Some(code) = inner {
        return io::Error::from_raw_os_error(code);
    }
    // tempfile's own wording: "<cause> at path \"<temporary path>\"".
    let text = e.to_string();
    match text.split_once(" at path ") {
        Some((cause, _)) => io::Error::new(e.kind(), cause.to_string()),
        None => e,
    }
}

/// What writing to `path` means (see the module documentation), after its checks.
fn resolve(path: &Path) -> Result<Target, OutputError> {
    let text = path.as_os_str().to_string_lossy();
    if text.is_empty() {
        return Err(OutputError::bad(path, "empty file name"));
    }
    if text == STDOUT_PATH {
        return Ok(Target::Stdout);
    }
    if let Some(fd) = own_descriptor(path) {
        return Ok(match fd {
            1 => Target::Stdout,
            2 => Target::Stderr,
            _ => Target::InPlace(path.to_path_buf()),
        });
    }
    if path.is_dir() || text.ends_with(std::path::MAIN_SEPARATOR) || text.ends_with('/') {
        return Err(OutputError::bad(path, "is a folder, not a file name"));
    }
    if path.file_name().is_none() {
        return Err(OutputError::bad(path, "not a file name"));
    }
    if path.as_os_str().len() > MAX_PATH_BYTES {
        return Err(OutputError::bad(
            path,
            "the path is longer than 4000 bytes, more than the system takes with a staging folder",
        ));
    }
    if path.iter().any(|c| c.len() > MAX_FILE_NAME_BYTES) {
        return Err(OutputError::bad(
            path,
            "a file or folder name in it is longer than 255 bytes, more than file systems take",
        ));
    }
    let target = match fs::symlink_metadata(path) {
        Ok(m) if m.file_type().is_symlink() => fs::canonicalize(path)
            .map_err(|_| OutputError::bad(path, "is a broken symbolic link"))?,
        _ => path.to_path_buf(),
    };
    if let Ok(m) = fs::metadata(&target) {
        if m.is_file() {
            return Ok(Target::File(target));
        }
        return if is_stream(&m) {
            Ok(Target::InPlace(target))
        } else {
            Err(OutputError::bad(path, "is not a regular file"))
        };
    }
    let mut above = target.parent();
    while let Some(d) = above {
        if d.as_os_str().is_empty() || d.is_dir() {
            break;
        }
        if d.exists() {
            return Err(OutputError::bad(d, "is not a folder"));
        }
        above = d.parent();
    }
    Ok(Target::File(target))
}

/// Whether `m` describes a device or a FIFO (written in place).
#[cfg(unix)]
fn is_stream(m: &fs::Metadata) -> bool {
    use std::os::unix::fs::FileTypeExt;
    let t = m.file_type();
    t.is_char_device() || t.is_block_device() || t.is_fifo()
}

/// Whether `m` describes a device or a FIFO (written in place).
#[cfg(not(unix))]
fn is_stream(_m: &fs::Metadata) -> bool {
    false
}

/// The number of this process's open descriptor that `path` leads to, if it does: a path
/// whose folder, or the folder of a link on its way, is this process's descriptor folder
/// (`/proc/<own pid>/fd`, reached as `/proc/self/fd` or `/dev/fd`).
fn own_descriptor(path: &Path) -> Option<u32> {
    let own = PathBuf::from("/proc")
        .join(std::process::id().to_string())
        .join("fd");
    let mut hop = path.to_path_buf();
    for _ in 0..MAX_LINK_HOPS {
        let parent = match hop.parent() {
            Some(p) if !p.as_os_str().is_empty() => p.to_path_buf(),
            _ => PathBuf::from("."),
        };
        let dir = fs::canonicalize(&parent).ok()?;
        if dir == own {
            return hop.file_name()?.to_str()?.parse().ok();
        }
        let link = fs::read_link(&hop).ok()?;
        hop = if link.components().next() == Some(Component::RootDir) {
            link
        } else {
            dir.join(link)
        };
    }
    None
}

#[cfg(test)]
mod tests {
    use super::*;

    /// A path longer than the system takes is refused before any work (it failed only when
    /// the result was written).
    #[test]
    fn an_overlong_path_is_refused_up_front() {
        let long = format!("{}/t.csv", ["d"; 2100].join("/"));
        let err = check_output_path(Path::new(&long)).unwrap_err().to_string();
        assert!(
            err.contains("longer than 4000 bytes"),
            "{}",
            &err[err.len() - 120..]
        );
    }

    /// A FIFO nobody reads is an error after the wait, not a hang; one with a reader gets the
    /// bytes.
    #[cfg(unix)]
    #[test]
    fn a_fifo_without_a_reader_is_an_error() {
        let dir = tempfile::tempdir().unwrap();
        let fifo = dir.path().join("out.fifo");
        let made = std::process::Command::new("mkfifo").arg(&fifo).status();
        if !made.is_ok_and(|s| s.success()) {
            return; // no mkfifo on this system: nothing to check
        }
        let wait = std::time::Duration::from_millis(300);
        let started = std::time::Instant::now();
        let err = open_in_place_within(&fifo, wait).unwrap_err().to_string();
        assert!(err.contains("no process reads"), "{err}");
        assert!(started.elapsed() < wait * 10, "{:?}", started.elapsed());
        let path = fifo.clone();
        let reader = std::thread::spawn(move || fs::read(path).unwrap());
        write_output_bytes(&fifo, b"polar").unwrap();
        assert_eq!(reader.join().unwrap(), b"polar");
    }

    #[test]
    fn dash_and_own_descriptors_are_streams() {
        assert_eq!(resolve(Path::new("-")).unwrap(), Target::Stdout);
        if Path::new("/proc/self/fd").is_dir() {
            assert_eq!(resolve(Path::new("/dev/stdout")).unwrap(), Target::Stdout);
            assert_eq!(resolve(Path::new("/dev/stderr")).unwrap(), Target::Stderr);
            assert_eq!(
                resolve(Path::new("/proc/self/fd/1")).unwrap(),
                Target::Stdout
            );
        }
        if Path::new("/dev/null").exists() {
            assert_eq!(
                resolve(Path::new("/dev/null")).unwrap(),
                Target::InPlace(PathBuf::from("/dev/null"))
            );
        }
    }

    #[test]
    fn plain_names_are_files() {
        assert_eq!(
            resolve(Path::new("t.csv")).unwrap(),
            Target::File(PathBuf::from("t.csv"))
        );
        assert_eq!(
            resolve(Path::new("")).unwrap_err().to_string(),
            ": empty file name"
        );
    }
}
