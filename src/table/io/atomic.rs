//! Atomic file output: write to a temporary file in the target's folder, then rename.

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
    let dir = match path.parent() {
        Some(d) if !d.as_os_str().is_empty() => d.to_path_buf(),
        _ => PathBuf::from("."),
    };
    fs::create_dir_all(&dir).map_err(|e| TableError::io(&dir, e))?;
    let name = path
        .file_name()
        .ok_or_else(|| {
            TableError::io(
                path,
                std::io::Error::new(std::io::ErrorKind::InvalidInput, "not a file name"),
            )
        })?
        .to_string_lossy()
        .into_owned();
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
