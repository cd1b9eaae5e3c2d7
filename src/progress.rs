//! Progress of long jobs (table builds, batches, studies, the report), reported to what the
//! caller supplies: the library never picks a display. A job tells its [`Progress`] the
//! [`Work`] of each phase when it starts, the steps done as they finish, and the end of the
//! phase. The command-line tools draw a bar on a terminal and print [`PlainLines`]
//! otherwise (a log file, `nohup`, CI, a notebook cell); [`Silent`] shows nothing.

use std::sync::Mutex;
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
/// estimate, then at most one line per interval, `done/total unit, elapsed, about ETA left`,
/// written when a step finishes after the interval has passed.
pub struct PlainLines<F: Fn(&str) + Sync> {
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
    last_line: Instant,
}

impl<F: Fn(&str) + Sync> PlainLines<F> {
    /// Lines to `say` every [`PLAIN_LINE_INTERVAL`].
    pub fn new(say: F) -> Self {
        Self::every(PLAIN_LINE_INTERVAL, say)
    }

    /// Lines to `say` at most once per `interval`.
    pub fn every(interval: Duration, say: F) -> Self {
        Self {
            say,
            interval,
            phase: Mutex::new(None),
        }
    }

    fn phase(&self) -> std::sync::MutexGuard<'_, Option<Phase>> {
        self.phase.lock().unwrap_or_else(|p| p.into_inner())
    }
}

impl<F: Fn(&str) + Sync> Progress for PlainLines<F> {
    fn start(&self, work: &Work) {
        (self.say)(&start_line(work));
        let now = Instant::now();
        *self.phase() = Some(Phase {
            total: work.total,
            unit: work.unit,
            done: 0,
            started: now,
            last_line: now,
        });
    }

    fn advance(&self, steps: usize) {
        let line = {
            let mut slot = self.phase();
            let Some(p) = slot.as_mut() else { return };
            p.done = (p.done + steps).min(p.total);
            let now = Instant::now();
            if p.done >= p.total || now.duration_since(p.last_line) < self.interval {
                return;
            }
            p.last_line = now;
            progress_line(p.done, p.total, p.unit, now.duration_since(p.started))
        };
        (self.say)(&line);
    }

    fn finish(&self) {
        *self.phase() = None;
    }
}

/// The start line of `work`: `what: total unit, about 3 min`.
pub fn start_line(work: &Work) -> String {
    let mut line = format!("{}: {} {}", work.what, work.total, work.unit);
    if let Some(s) = work.estimate_s.filter(|s| s.is_finite()) {
        line.push_str(&format!(", about {}", duration_text(s)));
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

    #[test]
    fn plain_lines_say_the_work_then_done_elapsed_and_eta() {
        let said = Mutex::new(Vec::<String>::new());
        let lines = PlainLines::every(Duration::ZERO, |l: &str| {
            said.lock().unwrap().push(l.to_string())
        });
        lines.start(&Work {
            total: 4,
            unit: "table points",
            what: "1 table to solve".into(),
            estimate_s: Some(130.0),
        });
        lines.advance(1);
        lines.advance(3);
        lines.finish();
        lines.advance(1);
        let said = said.into_inner().unwrap();
        assert_eq!(said.len(), 2, "{said:?}");
        assert_eq!(
            said[0],
            "1 table to solve: 4 table points, about 2 min 10 s"
        );
        assert!(
            said[1].starts_with("1/4 table points, elapsed 0 s, about ")
                && said[1].ends_with(" left"),
            "{}",
            said[1]
        );
    }

    #[test]
    fn plain_lines_wait_for_their_interval() {
        let said = Mutex::new(0usize);
        let lines = PlainLines::every(Duration::from_secs(3600), |_: &str| {
            *said.lock().unwrap() += 1
        });
        let work = Work {
            total: 100,
            unit: "points",
            what: "grid".into(),
            estimate_s: None,
        };
        lines.start(&work);
        (0..99).for_each(|_| lines.advance(1));
        assert_eq!(
            *said.lock().unwrap(),
            1,
            "only the start line within the interval"
        );
        assert_eq!(start_line(&work), "grid: 100 points");
    }
}
