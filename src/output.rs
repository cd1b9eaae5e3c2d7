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
//! * An existing device or FIFO — opened and written in place (streamed), never renamed over.
//! * Anything else names a regular file, written atomically: into a fresh temporary file in
//!   the target's folder (the `tempfile` crate; `.<name>.<random>.tmp`), flushed and synced,
//!   then renamed over the target. Missing folders are created; a symbolic link is written
//!   through (its target is replaced, the link stays). A failure at any step removes the
//!   temporary file and leaves the target as it was.
//!
//! Several files that belong together (a set of polars, a report) go through an
//! [`OutputSet`]: staged in a hidden folder beside their targets and renamed into place
//! together, or not at all. [`remove_staged_files_on_signals`] makes SIGINT/SIGTERM remove
//! whatever is staged.
//!
//! Paths are checked by [`check_output_path`] before a long computation: the path itself,
//! and that the folder that will hold the file accepts new files (a temporary probe file is
//! created and removed). Every error is an [`OutputError`] naming the path it concerns, never
//! a temporary name.

mod interrupt;
mod set;

pub use interrupt::remove_staged_files_on_signals;
pub use set::OutputSet;

use std::fs::{self, File, OpenOptions};
use std::io::{self, BufWriter, Write};
use std::path::{Component, Path, PathBuf};

/// The output path that means standard output.
pub const STDOUT_PATH: &str = "-";

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

    fn bad(path: impl Into<PathBuf>, reason: &'static str) -> Self {
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
/// permission-denied folder is found here, not after the computation).
pub fn check_output_path(path: &Path) -> Result<(), OutputError> {
    if let Target::File(target) = resolve(path)? {
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
        Target::File(target) => {
            let mut staged = Staged::create(path, &target, ".tmp")?;
            {
                let mut w = BufWriter::new(staged.file.as_file_mut());
                body(&mut w)?;
                w.flush().map_err(|e| OutputError::io(path, e))?;
            }
            Ok(staged.commit()?)
        }
        stream => stream_into(path, &stream, body),
    }
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
    let suffix = format!(".tmp.{extension}");
    match resolve(path)? {
        Target::File(target) => {
            let staged = Staged::create(path, &target, &suffix)?;
            body(staged.file.path())?;
            Ok(staged.commit()?)
        }
        stream => {
            let scratch = tempfile::Builder::new()
                .prefix(".polargen-output.")
                .suffix(&suffix)
                .tempfile()
                .map_err(|e| OutputError::io(path, e))?;
            body(scratch.path())?;
            let mut bytes = File::open(scratch.path()).map_err(|e| OutputError::io(path, e))?;
            stream_into(path, &stream, |w| {
                io::copy(&mut bytes, w)
                    .map(|_| ())
                    .map_err(|e| E::from(OutputError::io(path, e)))
            })
        }
    }
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
            // Append: never truncate what is connected to a device, pipe or descriptor.
            let file = OpenOptions::new().append(true).open(p).map_err(io_err)?;
            let mut w = BufWriter::new(file);
            body(&mut w)?;
            w.flush().map_err(io_err)
        }
    }
}

/// A temporary file next to its target, renamed over the target by [`Staged::commit`] and
/// removed when dropped uncommitted.
struct Staged {
    /// The path as requested (named in errors).
    requested: PathBuf,
    /// The file to replace.
    target: PathBuf,
    /// The temporary file.
    file: tempfile::NamedTempFile,
    /// Its listing for removal on interruption.
    _registration: interrupt::Registration,
}

impl Staged {
    /// Create the missing folders above `target` and a temporary file beside it, named
    /// `.<name>.<random><suffix>`.
    fn create(requested: &Path, target: &Path, suffix: &str) -> Result<Self, OutputError> {
        let dir = match target.parent().filter(|d| !d.as_os_str().is_empty()) {
            Some(d) => {
                fs::create_dir_all(d).map_err(|e| OutputError::io(d, e))?;
                d
            }
            None => Path::new("."),
        };
        let name = target
            .file_name()
            .map(|n| n.to_string_lossy().into_owned())
            .unwrap_or_default();
        let prefix = format!(".{name}.");
        let mut builder = tempfile::Builder::new();
        builder.prefix(&prefix).suffix(suffix);
        // Like a file created by `File::create`: 0666 less the umask (tempfile's own default
        // is 0600, which would hide results from other users).
        #[cfg(unix)]
        {
            use std::os::unix::fs::PermissionsExt;
            builder.permissions(fs::Permissions::from_mode(0o666));
        }
        let file = builder
            .tempfile_in(dir)
            .map_err(|e| OutputError::io(requested, without_path(e)))?;
        Ok(Self {
            requested: requested.to_path_buf(),
            target: target.to_path_buf(),
            _registration: interrupt::Registration::new(file.path()),
            file,
        })
    }

    /// Sync the temporary file and rename it over the target.
    fn commit(self) -> Result<(), OutputError> {
        let requested = self.requested;
        self.file
            .as_file()
            .sync_all()
            .map_err(|e| OutputError::io(&requested, e))?;
        self.file
            .persist(&self.target)
            .map(|_| ())
            .map_err(|e| OutputError::io(&requested, without_path(e.error)))
    }
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
    match inner {
        Some(code) => io::Error::from_raw_os_error(code),
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
