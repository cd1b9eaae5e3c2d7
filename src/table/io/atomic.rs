//! Output files: the checks every writer makes on its target path, and atomic writing (to a
//! temporary file in the target's folder, then renamed).

use crate::table::TableError;
use std::fs::{self, File, OpenOptions};
use std::io::{BufWriter, Write};
use std::path::{Path, PathBuf};

/// Write `path` atomically: create missing parent folders, let `body` write into a temporary
/// file next to the target (`.<name>.tmp<pid>-<k>`), flush and sync it, then rename it over
/// `path`. If `body` or any step fails the temporary file is removed and `path` is left as it
/// was (absent or with its old content).
pub fn write_atomic<F>(path: &Path, body: F) -> Result<(), TableError>
where
    F: FnOnce(&mut dyn Write) -> Result<(), TableError>,
{
    let (dir, name) = prepare_output_path(path)?;
    let (tmp, file) = create_temp(&dir, &name)?;
    let result = (|| {
        let mut w = BufWriter::new(file);
        body(&mut w)?;
        let file = w
            .into_inner()
            .map_err(|e| TableError::io(&tmp, e.into_error()))?;
        file.sync_all().map_err(|e| TableError::io(&tmp, e))?;
        fs::rename(&tmp, path).map_err(|e| TableError::io(path, e))
    })();
    if result.is_err() {
        // Best effort: the temporary file may already be gone.
        let _ = fs::remove_file(&tmp);
    }
    result
}

/// Check that `path` can name an output file, without touching the file system: it must have a
/// file name (not end in `/`, `.` or `..`), must not be an existing folder, and the nearest
/// existing folder above it must be a folder (not a regular file). Lets a program reject a bad
/// output path before a long computation instead of after it.
pub fn check_output_path(path: &Path) -> Result<(), TableError> {
    let bad = |at: &Path, why: &str| {
        TableError::io(
            at,
            std::io::Error::new(std::io::ErrorKind::InvalidInput, why.to_string()),
        )
    };
    let text = path.as_os_str().to_string_lossy();
    if text.is_empty() {
        return Err(bad(path, "empty file name"));
    }
    if path.is_dir() || text.ends_with(std::path::MAIN_SEPARATOR) || text.ends_with('/') {
        return Err(bad(path, "is a folder, not a file name"));
    }
    if path.file_name().is_none() {
        return Err(bad(path, "not a file name"));
    }
    let mut above = path.parent();
    while let Some(d) = above {
        if d.as_os_str().is_empty() {
            break;
        }
        if d.is_dir() {
            break;
        }
        if d.exists() {
            return Err(bad(d, "is not a folder"));
        }
        above = d.parent();
    }
    Ok(())
}

/// [`check_output_path`], then create the missing folders above `path`. Returns the folder and
/// the file name, for writers that put a temporary sibling next to the target.
pub fn prepare_output_path(path: &Path) -> Result<(PathBuf, String), TableError> {
    check_output_path(path)?;
    let dir = match path.parent() {
        Some(d) if !d.as_os_str().is_empty() => d.to_path_buf(),
        _ => PathBuf::from("."),
    };
    fs::create_dir_all(&dir).map_err(|e| TableError::io(&dir, e))?;
    let name = path
        .file_name()
        .map(|n| n.to_string_lossy().into_owned())
        .unwrap_or_default();
    Ok((dir, name))
}

/// Create a fresh temporary file in `dir` (never overwriting an existing one).
fn create_temp(dir: &Path, name: &str) -> Result<(PathBuf, File), TableError> {
    let pid = std::process::id();
    let mut k = 0u32;
    loop {
        let tmp = dir.join(format!(".{name}.tmp{pid}-{k}"));
        match OpenOptions::new().write(true).create_new(true).open(&tmp) {
            Ok(f) => return Ok((tmp, f)),
            Err(e) if e.kind() == std::io::ErrorKind::AlreadyExists && k < 10_000 => k += 1,
            Err(e) => return Err(TableError::io(&tmp, e)),
        }
    }
}
