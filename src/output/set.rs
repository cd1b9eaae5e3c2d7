//! [`OutputSet`]: files that appear together or not at all (XFOIL polars per (Re, M), C81 files
//! per Re, the report's figures and text, any batch of files).

use super::{interrupt, resolve, OutputError, Target};
use std::fs::{self, File};
use std::io::{BufWriter, Write};
use std::path::{Path, PathBuf};

/// A set of output files written all together or not at all.
///
/// Each file is first written into a hidden staging folder beside its target
/// (`.polargen-set-<pid>.<random>/`, one per target folder, on the same file system); only
/// [`commit`](Self::commit), after every file was written and synced, renames them into place
/// (renames are atomic and take microseconds). An error, or dropping the set uncommitted,
/// removes the staging folders (`TempDir` removes itself when dropped) and leaves every target as it was; so does SIGINT/SIGTERM
/// once [`remove_staged_files_on_signals`](super::remove_staged_files_on_signals) is set up.
/// Errors name the files as requested, never the staging folder.
#[derive(Default)]
pub struct OutputSet {
    /// Staging folder per target folder.
    stages: Vec<(PathBuf, tempfile::TempDir, interrupt::Registration)>,
    /// Every file: (path as requested, target to replace, staged file).
    files: Vec<(PathBuf, PathBuf, PathBuf)>,
}

impl OutputSet {
    /// An empty set (nothing is created before the first file).
    pub fn new() -> Self {
        Self::default()
    }

    /// The paths of the set's files, as requested, in the order they were added.
    pub fn paths(&self) -> Vec<PathBuf> {
        self.files.iter().map(|f| f.0.clone()).collect()
    }

    /// The staged file for the output `path` (a regular file, checked like
    /// [`check_output_path`](super::check_output_path)): write it by any means, e.g. an
    /// encoder that needs a file name (it has `path`'s file name and extension).
    pub fn stage(&mut self, path: &Path) -> Result<PathBuf, OutputError> {
        let target = match resolve(path)? {
            Target::File(t) => t,
            _ => {
                return Err(OutputError::BadPath {
                    path: path.to_path_buf(),
                    reason: "is a stream or device: a set of files needs file names",
                })
            }
        };
        if self.files.iter().any(|f| f.1 == target) {
            return Err(OutputError::BadPath {
                path: path.to_path_buf(),
                reason: "is written twice in one set",
            });
        }
        let dir = match target.parent().filter(|d| !d.as_os_str().is_empty()) {
            Some(d) => d.to_path_buf(),
            None => PathBuf::from("."),
        };
        let stage = match self.stages.iter().position(|s| s.0 == dir) {
            Some(k) => k,
            None => {
                fs::create_dir_all(&dir).map_err(|e| OutputError::io(&dir, e))?;
                let temp = tempfile::Builder::new()
                    .prefix(&format!(".polargen-set-{}.", std::process::id()))
                    .tempdir_in(&dir)
                    .map_err(|e| OutputError::io(path, super::without_path(e)))?;
                let registration = interrupt::Registration::new(temp.path());
                self.stages.push((dir, temp, registration));
                self.stages.len() - 1
            }
        };
        let name = target.file_name().unwrap_or_default();
        let staged = self.stages[stage].1.path().join(name);
        self.files
            .push((path.to_path_buf(), target, staged.clone()));
        Ok(staged)
    }

    /// Write the set's file `path` with `body`, which writes the whole content into the
    /// writer it is given.
    pub fn write<E, F>(&mut self, path: &Path, body: F) -> Result<(), E>
    where
        E: From<OutputError>,
        F: FnOnce(&mut dyn Write) -> Result<(), E>,
    {
        let staged = self.stage(path)?;
        let file = File::create(&staged).map_err(|e| OutputError::io(path, e))?;
        let mut w = BufWriter::new(file);
        body(&mut w)?;
        w.flush().map_err(|e| OutputError::io(path, e))?;
        Ok(())
    }

    /// Sync every staged file and rename the set into place (uninterrupted by signals), then
    /// remove the staging folders. Returns the paths as requested.
    pub fn commit(mut self) -> Result<Vec<PathBuf>, OutputError> {
        for (requested, _, staged) in &self.files {
            File::open(staged)
                .and_then(|f| f.sync_all())
                .map_err(|e| OutputError::io(requested, e))?;
        }
        interrupt::uninterrupted(|| {
            for (requested, target, staged) in &self.files {
                fs::rename(staged, target).map_err(|e| OutputError::io(requested, e))?;
            }
            Ok::<(), OutputError>(())
        })?;
        let written = self.paths();
        self.files.clear();
        Ok(written)
    }
}
