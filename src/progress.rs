//! Progress of long jobs (table builds, batches, studies, the report), reported to what the
//! caller supplies: the library never picks a display. A job tells its [`Progress`] the
//! [`Work`] of each phase when it starts, the steps done as they finish, and the end of the
//! phase. The command-line tools draw a bar on a terminal and print [`PlainLines`]
//! otherwise (a log file, `nohup`, CI, a notebook cell); [`Silent`] shows nothing.

use std::sync::{mpsc, Arc, Mutex};
use std::time::{Duration, Instant};

/// The work of one phase of a job.
#[derive(Clone, Debug, PartialEq)]
pub struct Work {
    /// Steps of the phase.
    pub total: usize,
    /// What one step is, in the plural (`table points`, `trims`).
    pub unit: &'static str,
    /// The work in words for the start line (`3 tables of naca8h12 to solve`).
    pub what: String,
    /// Estimated duration \[s\], when the job can tell.
    pub estimate_s: Option<f64>,
}

impl Work {
    /// `total` steps of `unit`, described by `what`, without an estimate.
    pub fn new(total: usize, unit: &'static str, what: impl Into<String>) -> Self {
        Self {
            total,
            unit,
            what: what.into(),
            estimate_s: None,
        }
    }
}

/// Where a job reports its progress. Called from the job's worker threads.
pub trait Progress: Sync {
    /// A phase with `work` begins.
    fn start(&self, work: &Work);
    /// `steps` more steps of the current phase are done.
    fn advance(&self, steps: usize);
    /// The current phase is over.
    fn finish(&self);
}

/// Progress that shows nothing.
#[derive(Clone, Copy, Debug, Default)]
pub struct Silent;

impl Progress for Silent {
    fn start(&self, _: &Work) {}
    fn advance(&self, _: usize) {}
    fn finish(&self) {}
}

/// Interval of [`PlainLines`]' progress lines.
pub const PLAIN_LINE_INTERVAL: Duration = Duration::from_secs(15);

/// Progress as plain text lines handed to `say`: a start line with the work and its
/// estimate, then one line per interval while the phase runs, `done/total unit, elapsed,
/// about ETA left` — from a ticker thread, so the lines keep their pace when steps are slow.
pub struct PlainLines<F: Fn(&str) + Send + Sync + 'static> {
    shared: Arc<Shared<F>>,
    /// The ticker of the phase under way: its stop signal and thread.
    ticker: Mutex<Option<(mpsc::Sender<()>, std::thread::JoinHandle<()>)>>,
}

/// What the caller and the ticker share.
struct Shared<F> {
    say: F,
    interval: Duration,
    phase: Mutex<Option<Phase>>,
}

/// The phase under way.
struct Phase {
    total: usize,
    unit: &'static str,
    done: usize,
    started: Instant,
}

impl<F: Fn(&str) + Send + Sync + 'static> PlainLines<F> {
    /// Lines to `say` every [`PLAIN_LINE_INTERVAL`].
    pub fn new(say: F) -> Self {
        Self::every(PLAIN_LINE_INTERVAL, say)
    }

    /// Lines to `say` every `interval`.
    pub fn every(interval: Duration, say: F) -> Self {
        Self {
            shared: Arc::new(Shared {
                say,
                interval,
                phase: Mutex::new(None),
            }),
            ticker: Mutex::new(None),
        }
    }

    /// Stops the ticker of the phase under way, if any.
    fn stop(&self) {
        let ticker = self.ticker.lock().unwrap_or_else(|p| p.into_inner()).take();
        if let Some((stop, thread)) = ticker {
            drop(stop);
            let _ = thread.join();
        }
    }
}

impl<F> Shared<F> {
    fn phase(&self) -> std::sync::MutexGuard<'_, Option<Phase>> {
        self.phase.lock().unwrap_or_else(|p| p.into_inner())
    }
}

impl<F: Fn(&str) + Send + Sync + 'static> Progress for PlainLines<F> {
    fn start(&self, work: &Work) {
        self.stop();
        (self.shared.say)(&start_line(work));
        *self.shared.phase() = Some(Phase {
            total: work.total,
            unit: work.unit,
            done: 0,
            started: Instant::now(),
        });
        let (stop, stopped) = mpsc::channel::<()>();
        let shared = Arc::clone(&self.shared);
        let thread = std::thread::spawn(move || {
            while let Err(mpsc::RecvTimeoutError::Timeout) = stopped.recv_timeout(shared.interval) {
                let line = shared.phase().as_ref().and_then(|p| {
                    (p.done < p.total)
                        .then(|| progress_line(p.done, p.total, p.unit, p.started.elapsed()))
                });
                if let Some(line) = line {
                    (shared.say)(&line);
                }
            }
        });
        *self.ticker.lock().unwrap_or_else(|p| p.into_inner()) = Some((stop, thread));
    }

    fn advance(&self, steps: usize) {
        if let Some(p) = self.shared.phase().as_mut() {
            p.done = (p.done + steps).min(p.total);
        }
    }

    fn finish(&self) {
        self.stop();
        *self.shared.phase() = None;
    }
}

impl<F: Fn(&str) + Send + Sync + 'static> Drop for PlainLines<F> {
    fn drop(&mut self) {
        self.stop();
    }
}

/// The start line of `work`: `what: total unit, about 3 min 05 s` (or `under 1 s`).
pub fn start_line(work: &Work) -> String {
    let mut line = format!("{}: {} {}", work.what, work.total, work.unit);
    match work.estimate_s.filter(|s| s.is_finite()) {
        Some(s) if s < 1.0 => line.push_str(", under 1 s"),
        Some(s) => line.push_str(&format!(", about {}", duration_text(s))),
        None => {}
    }
    line
}

/// A progress line: `done/total unit, elapsed 1 min 05 s, about 2 min left`.
pub fn progress_line(done: usize, total: usize, unit: &str, elapsed: Duration) -> String {
    let elapsed_s = elapsed.as_secs_f64();
    let mut line = format!(
        "{done}/{total} {unit}, elapsed {}",
        duration_text(elapsed_s)
    );
    if done > 0 && done < total {
        let left = elapsed_s * (total - done) as f64 / done as f64;
        line.push_str(&format!(", about {} left", duration_text(left)));
    }
    line
}

/// A duration in words: `12 s`, `3 min 05 s`, `2 h 07 min`.
pub fn duration_text(seconds: f64) -> String {
    let s = seconds.max(0.0).round() as u64;
    match s {
        0..=59 => format!("{s} s"),
        60..=3599 => format!("{} min {:02} s", s / 60, s % 60),
        _ => format!("{} h {:02} min", s / 3600, (s % 3600) / 60),
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn durations_read_as_words() {
        assert_eq!(duration_text(0.4), "0 s");
        assert_eq!(duration_text(59.4), "59 s");
        assert_eq!(duration_text(65.0), "1 min 05 s");
        assert_eq!(duration_text(7620.0), "2 h 07 min");
    }

    /// The lines said so far, shared with the `say` of a [`PlainLines`].
    fn recorder() -> (
        Arc<Mutex<Vec<String>>>,
        impl Fn(&str) + Send + Sync + 'static,
    ) {
        let said = Arc::new(Mutex::new(Vec::new()));
        let to = Arc::clone(&said);
        (said, move |l: &str| to.lock().unwrap().push(l.to_string()))
    }

    #[test]
    fn plain_lines_say_the_work_then_done_elapsed_and_eta_at_their_pace() {
        let (said, say) = recorder();
        let lines = PlainLines::every(Duration::from_millis(40), say);
        lines.start(&Work {
            total: 4,
            unit: "table points",
            what: "1 table to solve".into(),
            estimate_s: Some(130.0),
        });
        lines.advance(1);
        // No step finishes for a while: the lines keep coming.
        std::thread::sleep(Duration::from_millis(230));
        lines.finish();
        let count = said.lock().unwrap().len();
        std::thread::sleep(Duration::from_millis(100));
        let said = said.lock().unwrap().clone();
        assert_eq!(said.len(), count, "a line after finish: {said:?}");
        assert_eq!(
            said[0],
            "1 table to solve: 4 table points, about 2 min 10 s"
        );
        assert!((3..=7).contains(&said.len()), "{said:?}");
        for line in &said[1..] {
            assert!(
                line.starts_with("1/4 table points, elapsed 0 s, about ")
                    && line.ends_with(" left"),
                "{line}"
            );
        }
    }

    #[test]
    fn plain_lines_wait_for_their_interval_and_stop_when_done() {
        let (said, say) = recorder();
        let lines = PlainLines::every(Duration::from_secs(3600), say);
        let work = Work {
            total: 100,
            unit: "points",
            what: "grid".into(),
            estimate_s: None,
        };
        lines.start(&work);
        (0..99).for_each(|_| lines.advance(1));
        lines.finish();
        assert_eq!(
            said.lock().unwrap().len(),
            1,
            "only the start line within the interval"
        );
        assert_eq!(start_line(&work), "grid: 100 points");
        drop(lines);
    }
}
