//! Output files: the checks every writer makes on its target path, and atomic writing (to a
//! temporary file in the target's folder, then renamed).

use crate::table::TableError;
use std::fs::{self, File, OpenOptions};
use std::io::{BufWriter, Write};
use std::path::{Path, PathBuf};

/// Write `path` atomically: create missing parent folders, let `body` write into a temporary
/// file next to the target (`.<name>.tmp<pid>-<k>`), flush and sync it, then rename it over
/// the target. If `body` or any step fails the temporary file is removed and `path` is left as
/// it was (absent or with its old content). A symbolic link is written through (its target is
/// replaced, the link stays); a path that is a device, pipe or socket is refused
/// ([`prepare_output_path`]).
pub fn write_atomic<F>(path: &Path, body: F) -> Result<(), TableError>
where
    F: FnOnce(&mut dyn Write) -> Result<(), TableError>,
{
    let target = prepare_output_path(path)?;
    let (tmp, file) = create_temp(&target)?;
    let result = (|| {
        let mut w = BufWriter::new(file);
        body(&mut w)?;
        let file = w
            .into_inner()
            .map_err(|e| TableError::io(&tmp, e.into_error()))?;
        file.sync_all().map_err(|e| TableError::io(&tmp, e))?;
        fs::rename(&tmp, &target).map_err(|e| TableError::io(path, e))
    })();
    if result.is_err() {
        // Best effort: the temporary file may already be gone.
        let _ = fs::remove_file(&tmp);
    }
    result
}

/// An output-path error: `why` about `at` (the path itself or a folder above it).
fn bad_path(at: &Path, why: &str) -> TableError {
    TableError::io(
        at,
        std::io::Error::new(std::io::ErrorKind::InvalidInput, why.to_string()),
    )
}

/// Check that `path` can name an output file, without changing the file system: it must have
/// a file name (not end in `/`, `.` or `..`); if it exists, it must be a regular file or a
/// link to one (not a folder, device, pipe or socket, not a broken link); and the nearest
/// existing folder above it must be a folder (not a regular file). Lets a program reject a bad
/// output path before a long computation instead of after it.
pub fn check_output_path(path: &Path) -> Result<(), TableError> {
    output_target(path).map(|_| ())
}

/// The file a writer replaces for `path` (the link's target for a symbolic link), after the
/// checks of [`check_output_path`].
fn output_target(path: &Path) -> Result<PathBuf, TableError> {
    let text = path.as_os_str().to_string_lossy();
    if text.is_empty() {
        return Err(bad_path(path, "empty file name"));
    }
    if path.is_dir() || text.ends_with(std::path::MAIN_SEPARATOR) || text.ends_with('/') {
        return Err(bad_path(path, "is a folder, not a file name"));
    }
    if path.file_name().is_none() {
        return Err(bad_path(path, "not a file name"));
    }
    let target = match fs::symlink_metadata(path) {
        Ok(m) if m.file_type().is_symlink() => match fs::canonicalize(path) {
            Ok(t) => t,
            Err(_) => return Err(bad_path(path, "is a broken symbolic link")),
        },
        _ => path.to_path_buf(),
    };
    match fs::metadata(&target) {
        Ok(m) if m.is_file() => {}
        Ok(_) => return Err(bad_path(path, "is not a regular file")),
        Err(_) => {}
    }
    let mut above = target.parent();
    while let Some(d) = above {
        if d.as_os_str().is_empty() || d.is_dir() {
            break;
        }
        if d.exists() {
            return Err(bad_path(d, "is not a folder"));
        }
        above = d.parent();
    }
    Ok(target)
}

/// [`check_output_path`], then create the missing folders above `path`. Returns the file to
/// replace: `path`, or the target of the symbolic link `path` (so that writers replace the
/// linked file, not the link).
pub fn prepare_output_path(path: &Path) -> Result<PathBuf, TableError> {
    let target = output_target(path)?;
    if let Some(dir) = target.parent().filter(|d| !d.as_os_str().is_empty()) {
        fs::create_dir_all(dir).map_err(|e| TableError::io(dir, e))?;
    }
    Ok(target)
}

/// Create a fresh temporary file next to `target` (never overwriting an existing one).
fn create_temp(target: &Path) -> Result<(PathBuf, File), TableError> {
    let name = target
        .file_name()
        .map(|n| n.to_string_lossy().into_owned())
        .unwrap_or_default();
    let pid = std::process::id();
    let mut k = 0u32;
    loop {
        let tmp = target.with_file_name(format!(".{name}.tmp{pid}-{k}"));
        match OpenOptions::new().write(true).create_new(true).open(&tmp) {
            Ok(f) => return Ok((tmp, f)),
            Err(e) if e.kind() == std::io::ErrorKind::AlreadyExists && k < 10_000 => k += 1,
            Err(e) => return Err(TableError::io(&tmp, e)),
        }
    }
}
