//! Removal of staged (temporary) output files when the process is interrupted (SIGINT,
//! SIGTERM, SIGHUP), so that a killed run leaves neither a half-written set nor hidden
//! temporary files behind (only SIGKILL cannot be caught; `.gitignore` covers its leftovers).
//!
//! Global state, and why: a signal handler runs with no access to anything but static data
//! and may only do async-signal-safe work, so it stores the signal number in an atomic
//! ([`CAUGHT`]); a watcher thread, started with the handlers, sees it, removes what the
//! registry ([`PENDING`]) lists and exits with 128 + the signal number, as a shell reports a
//! killed process. The registry is a `Mutex` so that a set's renaming and the removal never
//! overlap: a set is either renamed completely or removed. Nothing else is global.

use std::path::{Path, PathBuf};
use std::sync::atomic::{AtomicI32, Ordering};
use std::sync::{Mutex, Once};
use std::time::Duration;

/// The staged files and folders to remove on interruption.
static PENDING: Mutex<Vec<PathBuf>> = Mutex::new(Vec::new());

/// The number of the signal caught (0: none yet).
static CAUGHT: AtomicI32 = AtomicI32::new(0);

/// How often the watcher thread looks for a caught signal.
const WATCH_INTERVAL: Duration = Duration::from_millis(20);

/// A staged file or folder listed for removal on interruption while this guard lives.
pub(crate) struct Registration(PathBuf);

impl Registration {
    /// Lists `path` (a staged file or folder) for removal on interruption.
    pub(crate) fn new(path: &Path) -> Self {
        pending().push(path.to_path_buf());
        Self(path.to_path_buf())
    }
}

impl Drop for Registration {
    /// Takes the path off the list (it was renamed into place or removed).
    fn drop(&mut self) {
        pending().retain(|p| *p != self.0);
    }
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

/// Makes SIGINT, SIGTERM and SIGHUP remove every staged output file and folder, then end the
/// process with status 128 + the signal number. For programs (the command-line tools call it
/// first thing); a library user decides about signal handling itself. Idempotent.
pub fn remove_staged_files_on_signals() {
    static INSTALL: Once = Once::new();
    INSTALL.call_once(|| {
        #[cfg(unix)]
        unix::install();
        std::thread::spawn(|| loop {
            std::thread::sleep(WATCH_INTERVAL);
            let signal = CAUGHT.load(Ordering::SeqCst);
            if signal != 0 {
                let staged = pending();
                for path in staged.iter() {
                    let _ = if path.is_dir() {
                        std::fs::remove_dir_all(path)
                    } else {
                        std::fs::remove_file(path)
                    };
                }
                std::process::exit(128 + signal);
            }
        });
    });
}

#[cfg(unix)]
mod unix {
    use super::CAUGHT;
    use std::sync::atomic::Ordering;

    /// SIGHUP, SIGINT and SIGTERM (the same numbers on every Unix).
    const SIGNALS: [i32; 3] = [1, 2, 15];

    extern "C" {
        /// POSIX `signal(2)`: the C library std already links.
        fn signal(signum: i32, handler: usize) -> usize;
    }

    /// The handler: only an atomic store (async-signal-safe).
    extern "C" fn on_signal(signum: i32) {
        CAUGHT.store(signum, Ordering::SeqCst);
    }

    pub(super) fn install() {
        for s in SIGNALS {
            // SAFETY: `on_signal` is an `extern "C" fn(i32)` that only stores into an atomic,
            // which is async-signal-safe; `signal` is called with valid signal numbers.
            unsafe {
                signal(s, on_signal as extern "C" fn(i32) as usize);
            }
        }
    }
}
