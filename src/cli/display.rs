//! Progress of a long job on the tools' stderr: a start line, then a bar on a terminal or a
//! plain line at a steady interval elsewhere (a log file, `nohup`, CI, a notebook cell);
//! nothing with `--quiet`.

use super::Tool;
use crate::progress::{start_line, PlainLines, Progress, Work};
use indicatif::{ProgressBar, ProgressStyle};
use std::io::IsTerminal;
use std::sync::Mutex;

/// The tools' [`Progress`]: see the module documentation.
pub struct TerminalProgress {
    tool: &'static Tool,
    shown: Shown,
}

/// Where plain lines go: the tool's `say`.
type Say = Box<dyn Fn(&str) + Send + Sync>;

/// How progress is shown.
enum Shown {
    /// `--quiet`.
    Nothing,
    /// A bar per phase on a terminal.
    Bar(Mutex<Option<ProgressBar>>),
    /// Plain lines.
    Lines(PlainLines<Say>),
}

impl TerminalProgress {
    /// The display for `tool`, by its `--quiet` and whether stderr is a terminal.
    pub(super) fn new(tool: &'static Tool) -> Self {
        let shown = if tool.quiet() {
            Shown::Nothing
        } else if std::io::stderr().is_terminal() {
            Shown::Bar(Mutex::new(None))
        } else {
            Shown::Lines(PlainLines::new(Box::new(move |line: &str| tool.say(line))))
        };
        Self { tool, shown }
    }
}

impl Progress for TerminalProgress {
    fn start(&self, work: &Work) {
        match &self.shown {
            Shown::Nothing => {}
            Shown::Lines(lines) => lines.start(work),
            Shown::Bar(slot) => {
                self.tool.say(start_line(work));
                let bar = ProgressBar::new(work.total as u64);
                let template = format!("{{bar:40}} {{pos}}/{{len}} {}, eta {{eta}}", work.unit);
                if let Ok(style) = ProgressStyle::with_template(&template) {
                    bar.set_style(style);
                }
                let mut slot = slot.lock().unwrap_or_else(|p| p.into_inner());
                if let Some(old) = slot.replace(bar) {
                    old.finish_and_clear();
                }
            }
        }
    }

    fn advance(&self, steps: usize) {
        match &self.shown {
            Shown::Nothing => {}
            Shown::Lines(lines) => lines.advance(steps),
            Shown::Bar(slot) => {
                let slot = slot.lock().unwrap_or_else(|p| p.into_inner());
                if let Some(bar) = slot.as_ref() {
                    bar.inc(steps as u64);
                }
            }
        }
    }

    fn finish(&self) {
        match &self.shown {
            Shown::Nothing => {}
            Shown::Lines(lines) => lines.finish(),
            Shown::Bar(slot) => {
                let mut slot = slot.lock().unwrap_or_else(|p| p.into_inner());
                if let Some(bar) = slot.take() {
                    bar.finish_and_clear();
                }
            }
        }
    }
}
