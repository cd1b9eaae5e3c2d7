//! [`OutputSet`]: files that appear together or not at all (XFOIL polars per (Re, M), C81 files
//! per Re, the report's figures and text, any batch of files, and every single result file).

use super::{interrupt, resolve, without_path, OutputError, Target};
use std::fs::{self, File};
use std::io::{self, BufWriter, Write};
use std::path::{Path, PathBuf};

/// Subfolder of a staging folder holding the new files, under their own names.
const NEW: &str = "n";

/// Subfolder of a staging folder holding the files the set replaces (hard links), numbered.
const OLD: &str = "o";

/// A set of output files written all together or not at all.
///
/// Each file is first written into a hidden staging folder beside its target
/// (`.polargen-set-<pid>.<random>/`, one per target folder, on the same file system), under
/// its own name. [`commit`](Self::commit), after every file was written and synced, keeps each
/// existing target as a hard link in the stage, then renames the new files into place
/// (renames are atomic and take microseconds); if one rename fails, the files already
/// renamed are put back (the kept targets renamed back, new files removed), so the targets
/// are all new or all as they were. An error, or dropping the set uncommitted, removes the
/// staging folders and leaves every target as it was; so does SIGINT/SIGTERM once
/// [`remove_staged_files_on_signals`](super::remove_staged_files_on_signals) is set up.
/// Errors name the files as requested, never the staging folder.
#[derive(Default)]
pub struct OutputSet {
    /// Staging folder per target folder.
    stages: Vec<(PathBuf, tempfile::TempDir, interrupt::Registration)>,
    /// Every file: (path as requested, target to replace, staged file, its stage).
    files: Vec<(PathBuf, PathBuf, PathBuf, usize)>,
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
        self.stage_as(path, None)
    }

    /// [`stage`](Self::stage), the staged file's name ending in `.{extension}` (for encoders
    /// that pick their format from the name) even when `path`'s does not.
    pub(crate) fn stage_with_extension(
        &mut self,
        path: &Path,
        extension: &str,
    ) -> Result<PathBuf, OutputError> {
        let suffix = format!(".{extension}");
        let keeps = path
            .file_name()
            .and_then(|n| n.to_str())
            .is_some_and(|n| n.ends_with(&suffix) && n.len() > suffix.len());
        let name = (!keeps).then(|| format!("output{suffix}"));
        self.stage_as(path, name)
    }

    /// The staged file of `path`, named `name` in the stage (default: the target's name).
    fn stage_as(&mut self, path: &Path, name: Option<String>) -> Result<PathBuf, OutputError> {
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
                let (temp, registration) = interrupt::create_stage(&dir)
                    .and_then(|(t, r)| fs::create_dir(t.path().join(NEW)).map(|()| (t, r)))
                    .map_err(|e| OutputError::io(path, without_path(e)))?;
                self.stages.push((dir, temp, registration));
                self.stages.len() - 1
            }
        };
        let staged_name = match name {
            Some(n) => n.into(),
            None => target.file_name().unwrap_or_default().to_os_string(),
        };
        let staged = self.stages[stage].1.path().join(NEW).join(staged_name);
        if self.files.iter().any(|f| f.2 == staged) {
            return Err(OutputError::BadPath {
                path: path.to_path_buf(),
                reason: "is written twice in one set",
            });
        }
        self.files
            .push((path.to_path_buf(), target, staged.clone(), stage));
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

    /// Sync every staged file, keep the targets it replaces, and rename the set into place
    /// (uninterrupted by signals); on a failure put back what was renamed. Then remove the
    /// staging folders. Returns the paths as requested.
    pub fn commit(mut self) -> Result<Vec<PathBuf>, OutputError> {
        for (requested, _, staged, _) in &self.files {
            File::open(staged)
                .and_then(|f| f.sync_all())
                .map_err(|e| OutputError::io(requested, e))?;
        }
        let backups = self.keep_targets()?;
        interrupt::uninterrupted(|| {
            for (k, (requested, target, staged, _)) in self.files.iter().enumerate() {
                if let Err(e) = fs::rename(staged, target) {
                    let undo = self.put_back(&backups[..k]);
                    return Err(OutputError::io(requested, with_undo(e, undo)));
                }
            }
            Ok(())
        })?;
        let written = self.paths();
        self.files.clear();
        Ok(written)
    }

    /// Hard links of the existing targets in their stage (`None` for a target that does not
    /// exist yet), one per file.
    fn keep_targets(&self) -> Result<Vec<Option<PathBuf>>, OutputError> {
        let mut backups = Vec::with_capacity(self.files.len());
        for (k, (requested, target, _, stage)) in self.files.iter().enumerate() {
            if fs::symlink_metadata(target).is_err() {
                backups.push(None);
                continue;
            }
            let old = self.stages[*stage].1.path().join(OLD);
            let keep = old.join(k.to_string());
            fs::create_dir_all(&old)
                .and_then(|()| fs::hard_link(target, &keep))
                .map_err(|e| {
                    let why =
                        format!("cannot keep the file it replaces until the set is complete: {e}");
                    OutputError::io(requested, io::Error::new(e.kind(), why))
                })?;
            backups.push(Some(keep));
        }
        Ok(backups)
    }

    /// Undo the renames of the first `backups.len()` files: each kept target renamed back,
    /// each file that did not exist before removed. The first failure, if any.
    fn put_back(&self, backups: &[Option<PathBuf>]) -> Result<(), (PathBuf, io::Error)> {
        let mut first = Ok(());
        for ((requested, target, _, _), backup) in self.files.iter().zip(backups) {
            let undone = match backup {
                Some(keep) => fs::rename(keep, target),
                None => fs::remove_file(target),
            };
            if let (Err(e), Ok(())) = (undone, &first) {
                first = Err((requested.clone(), e));
            }
        }
        first
    }
}

/// The error of a failed rename, saying when putting the earlier files back failed too.
fn with_undo(e: io::Error, undo: Result<(), (PathBuf, io::Error)>) -> io::Error {
    let e = without_path(e);
    match undo {
        Ok(()) => e,
        Err((path, u)) => io::Error::new(
            e.kind(),
            format!("{e}; putting {} back failed too: {u}", path.display()),
        ),
    }
}
