//! Removal of staged output files when the process is interrupted (SIGINT, SIGTERM, SIGHUP),
//! so that an interrupted run leaves neither a half-written set nor hidden staging folders
//! behind. (SIGKILL cannot be caught: the next run that stages files in the same folder
//! removes the staging folders of processes that are gone, see [`create_stage`].)
//!
//! Global state, and why: signals are delivered to one watcher thread (the `signal-hook`
//! crate's self-pipe, started with [`remove_staged_files_on_signals`]), which must find every
//! staging folder of the process; they are listed in [`PENDING`]. The list is a `Mutex`, and
//! the watcher keeps it locked from the signal to the exit: no staging folder is created
//! (creation happens under the same lock) and no set is renamed into place (renaming too)
//! while it cleans up, so a set is either renamed completely or removed. A writer still
//! encoding a file into a staging folder cannot put a file back after the removal: the
//! watcher first renames the folder to a name no writer knows, then removes it. Nothing else
//! is global.

use std::io;
use std::path::{Path, PathBuf};
use std::sync::{Mutex, Once};

/// The staging folders to remove on interruption.
static PENDING: Mutex<Vec<PathBuf>> = Mutex::new(Vec::new());

/// Name prefix of a staging folder; the process id and a random part follow
/// (`.polargen-set-<pid>.<random>`).
pub(crate) const STAGE_PREFIX: &str = ".polargen-set-";

/// A staging folder listed for removal on interruption while this guard lives.
pub(crate) struct Registration(PathBuf);

impl Drop for Registration {
    /// Takes the folder off the list (its files were renamed into place or it was removed).
    fn drop(&mut self) {
        pending().retain(|p| *p != self.0);
    }
}

/// Creates a staging folder in `dir` and lists it for removal on interruption, both under the
/// lock of the list (so that an interruption never misses a folder). Staging folders of
/// processes that no longer run (killed by SIGKILL) found in `dir` are removed first.
pub(crate) fn create_stage(dir: &Path) -> io::Result<(tempfile::TempDir, Registration)> {
    remove_stale_stages(dir);
    let mut list = pending();
    let stage = tempfile::Builder::new()
        .prefix(&format!("{STAGE_PREFIX}{}.", std::process::id()))
        .rand_bytes(6)
        .tempdir_in(dir)?;
    list.push(stage.path().to_path_buf());
    let registration = Registration(stage.path().to_path_buf());
    Ok((stage, registration))
}

/// Runs `f` while no interruption can remove staged files (for renaming a set into place).
pub(crate) fn uninterrupted<T>(f: impl FnOnce() -> T) -> T {
    let _guard = pending();
    f()
}

fn pending() -> std::sync::MutexGuard<'static, Vec<PathBuf>> {
    PENDING
        .lock()
        .unwrap_or_else(|poisoned| poisoned.into_inner())
}

/// Removes the staging folders in `dir` whose process is gone (best-effort: a folder that
/// cannot be read or removed stays).
fn remove_stale_stages(dir: &Path) {
    let Ok(entries) = std::fs::read_dir(dir) else {
        return;
    };
    for entry in entries.flatten() {
        let name = entry.file_name();
        let Some(pid) = name
            .to_str()
            .and_then(|n| n.strip_prefix(STAGE_PREFIX))
            .and_then(|rest| rest.split('.').next())
            .and_then(|pid| pid.parse::<u32>().ok())
        else {
            continue;
        };
        let is_dir = entry.file_type().is_ok_and(|t| t.is_dir());
        if is_dir && pid != std::process::id() && !process_alive(pid) {
            let _ = std::fs::remove_dir_all(entry.path());
        }
    }
}

/// Whether a process with id `pid` exists (one of another user counts as alive).
#[cfg(unix)]
fn process_alive(pid: u32) -> bool {
    let Ok(pid) = libc::pid_t::try_from(pid) else {
        return true;
    };
    // SAFETY: kill with signal 0 sends nothing; it only checks that the process exists.
    let result = unsafe { libc::kill(pid, 0) };
    result == 0 || io::Error::last_os_error().raw_os_error() != Some(libc::ESRCH)
}

/// Whether a process with id `pid` exists (unknown here: assumed alive, nothing is removed).
#[cfg(not(unix))]
fn process_alive(_pid: u32) -> bool {
    true
}

/// Removes the staging folder `path`: renamed first to a name no writer knows, so that a
/// writer that is still encoding cannot create a file in it again, then removed.
fn remove_stage(path: &Path) {
    let mut hidden = path.as_os_str().to_owned();
    hidden.push(".x");
    let hidden = PathBuf::from(hidden);
    let gone = if std::fs::rename(path, &hidden).is_ok() {
        &hidden
    } else {
        path
    };
    for _ in 0..50 {
        if std::fs::remove_dir_all(gone).is_ok() || !gone.exists() {
            return;
        }
        std::thread::sleep(std::time::Duration::from_millis(10));
    }
}

/// Makes SIGINT, SIGTERM and SIGHUP remove every staging folder, then end the process with
/// status 128 + the signal number (as a shell reports a killed process). For programs (the
/// command-line tools call it first thing); a library user decides about signal handling
/// itself. Idempotent; without effect where signals cannot be watched.
pub fn remove_staged_files_on_signals() {
    static INSTALL: Once = Once::new();
    INSTALL.call_once(|| {
        #[cfg(unix)]
        {
            use signal_hook::consts::{SIGHUP, SIGINT, SIGTERM};
            let Ok(mut signals) = signal_hook::iterator::Signals::new([SIGHUP, SIGINT, SIGTERM])
            else {
                return;
            };
            std::thread::spawn(move || {
                if let Some(signal) = signals.forever().next() {
                    let staged = pending();
                    staged.iter().for_each(|p| remove_stage(p));
                    std::process::exit(128 + signal);
                }
            });
        }
    });
}
