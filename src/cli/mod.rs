//! What both command-line tools share (the `cli` feature, which the Python package does not
//! enable): one error and exit-code convention, notes, `--quiet`, progress on stderr, value
//! parsers for every flag ([`values`]), shell completions and man pages, and the Markdown
//! command-line reference generated from the clap definitions (`docs/cli/<tool>.md`, checked
//! by each tool's tests).
//!
//! The convention (docs/cli/README.md): every error is one line `<tool>: error: <message>` on
//! stderr; exit status 0 on success (also when the reader of standard output closed it early,
//! `… | head`), 1 when a run failed, 2 for a command-line usage error: an unknown flag, a
//! missing subcommand (then the help of the command is printed), and every bad value — a
//! value of the wrong form or out of its range (refused by the flag's value parser), or
//! values that contradict each other or exceed a limit (an
//! [`ArgumentError`] anywhere in the error's causes). Notes, progress and summary lines are
//! `<tool>: <text>` on stderr, best-effort (a full or closed stderr costs no result), and
//! `--quiet` silences them.

mod display;
mod reference;
pub mod values;

pub use display::TerminalProgress;
pub use reference::{check_reference, markdown_reference};

use crate::arguments::ArgumentError;
use crate::diagnostics::error_line;
use std::fmt::Display;
use std::io::Write;
use std::path::PathBuf;
use std::process::ExitCode;
use std::sync::OnceLock;

/// Exit status of a command-line usage error.
const USAGE_ERROR: u8 = 2;

/// A command-line tool: its name, the prefix of every line it writes to stderr, and whether
/// `--quiet` was given (set once, right after parsing, read by [`Tool::say`]).
pub struct Tool {
    /// Program name.
    pub name: &'static str,
    /// `--quiet`.
    quiet: OnceLock<bool>,
}

/// The shell of `completions SHELL` (shared by both tools).
#[derive(clap::Args, Debug)]
pub struct CompletionsArgs {
    /// Shell to write the completion script for.
    #[arg(value_enum)]
    pub shell: clap_complete::Shell,
}

/// The man pages of `man` (shared by both tools).
#[derive(clap::Args, Debug)]
pub struct ManArgs {
    /// The subcommand whose page to print (e.g. `convert` or `point` for polargen,
    /// `study wing` for gyro); the tool's own page when absent.
    #[arg(value_name = "SUBCOMMAND")]
    pub subcommand: Vec<String>,
    /// Write every page (`<tool>.1`, `<tool>-<subcommand>.1`, …) into this folder instead.
    #[arg(long, value_name = "DIR", conflicts_with = "subcommand")]
    pub out: Option<PathBuf>,
}

impl Tool {
    /// The tool called `name`, before its command line is parsed.
    pub const fn new(name: &'static str) -> Self {
        Self {
            name,
            quiet: OnceLock::new(),
        }
    }

    /// Parses the command line. Help and version go to stdout (exit 0); a missing subcommand
    /// or a bare command prints the help to stderr (exit 2); any other clap error becomes one
    /// line `<name>: error: <message>` on stderr without the usage block (exit 2): a refused
    /// value reads `--flag value: rule`. `quiet` reads the parsed `--quiet` flag.
    pub fn parse<P: clap::Parser>(&self, quiet: impl Fn(&P) -> bool) -> Result<P, ExitCode> {
        use clap::error::ErrorKind;
        match P::try_parse() {
            Ok(p) => {
                let _ = self.quiet.set(quiet(&p));
                Ok(p)
            }
            Err(e) if !e.use_stderr() => {
                let _ = e.print();
                Err(ExitCode::SUCCESS)
            }
            Err(e) if e.kind() == ErrorKind::DisplayHelpOnMissingArgumentOrSubcommand => {
                let _ = e.print();
                Err(ExitCode::from(USAGE_ERROR))
            }
            Err(e) => {
                self.error(usage_message(&e));
                Err(ExitCode::from(USAGE_ERROR))
            }
        }
    }

    /// The exit of a run: success; quietly success when standard output was closed by its
    /// reader (`… | head`); a usage error (exit 2) when a user-given value was refused (an
    /// [`ArgumentError`] among the causes); otherwise the error and its causes as one line on
    /// stderr, exit 1.
    pub fn finish(&self, result: anyhow::Result<()>) -> ExitCode {
        match result {
            Ok(()) => ExitCode::SUCCESS,
            Err(e) if closed_pipe(&e) => ExitCode::SUCCESS,
            Err(e) => {
                self.error(error_line(e.as_ref()));
                if e.chain().any(|c| c.is::<ArgumentError>()) {
                    ExitCode::from(USAGE_ERROR)
                } else {
                    ExitCode::FAILURE
                }
            }
        }
    }

    /// The error line `<name>: error: <text>` on stderr (best-effort).
    fn error(&self, text: impl Display) {
        let _ = writeln!(std::io::stderr().lock(), "{}: error: {text}", self.name);
    }

    /// Whether `--quiet` was given.
    pub fn quiet(&self) -> bool {
        self.quiet.get().copied().unwrap_or(false)
    }

    /// A line on stderr, `<name>: <text>`, unless `--quiet` was given. Best-effort: a failed
    /// write (a full disk, a closed stderr) is ignored.
    pub fn say(&self, text: impl Display) {
        if !self.quiet() {
            let _ = writeln!(std::io::stderr().lock(), "{}: {text}", self.name);
        }
    }

    /// A block of text on stderr as it is (a summary moved off standard output), unless
    /// `--quiet` was given. Best-effort like [`say`](Self::say).
    pub fn say_text(&self, text: &str) {
        if !self.quiet() {
            let _ = std::io::stderr().lock().write_all(text.as_bytes());
        }
    }

    /// The progress display of a long job: nothing with `--quiet`; a start line and a bar
    /// when stderr is a terminal; a start line and a plain line every
    /// [`PLAIN_LINE_INTERVAL`](crate::progress::PLAIN_LINE_INTERVAL) otherwise.
    pub fn progress(&'static self) -> TerminalProgress {
        TerminalProgress::new(self)
    }
}

/// The one-line message of a clap error: `--flag value: rule` for a refused value (the
/// value parsers' [`ArgumentError`] or another parser's error), else clap's text without
/// its usage block, with the pointer to `--help` kept.
fn usage_message(e: &clap::Error) -> String {
    use clap::error::{ContextKind, ContextValue, ErrorKind};
    let flag = match e.get(ContextKind::InvalidArg) {
        Some(ContextValue::String(s)) => Some(
            s.split_whitespace()
                .next()
                .unwrap_or(s)
                .trim_matches(['<', '>'])
                .to_string(),
        ),
        _ => None,
    };
    let cause = std::error::Error::source(e);
    if let (ErrorKind::ValueValidation, Some(flag), Some(cause)) = (e.kind(), &flag, cause) {
        let value = match e.get(ContextKind::InvalidValue) {
            Some(ContextValue::String(v)) => crate::limits::short_text(v),
            _ => String::new(),
        };
        let cause = cause.to_string();
        return match cause_argument(e) {
            Some(a) if a.value.is_empty() => format!("{flag}: {}", a.rule),
            Some(a) => format!("{flag} {}: {}", a.value, a.rule),
            None if value.is_empty() || cause.contains(&value) => format!("{flag}: {cause}"),
            None => format!("{flag} {value}: {cause}"),
        };
    }
    if let (ErrorKind::InvalidValue, Some(flag)) = (e.kind(), &flag) {
        let strings = |kind| match e.get(kind) {
            Some(ContextValue::String(s)) => vec![s.clone()],
            Some(ContextValue::Strings(v)) => v.clone(),
            _ => Vec::new(),
        };
        let value = strings(ContextKind::InvalidValue).join(" ");
        let valid = strings(ContextKind::ValidValue);
        if !valid.is_empty() {
            let value = crate::limits::short_text(&value);
            return format!("{flag} {value}: must be one of {}", valid.join(", "));
        }
    }
    let text = e.render().to_string();
    let mut parts: Vec<String> = Vec::new();
    let mut in_usage = false;
    for line in text.lines().map(str::trim) {
        if line.starts_with("Usage:") {
            in_usage = true;
        }
        if line.is_empty() {
            in_usage = false;
        }
        if in_usage || line.is_empty() {
            continue;
        }
        match line.strip_prefix("For more information, try ") {
            Some(tip) => parts.push(format!("try {}", tip.trim_end_matches('.'))),
            None => parts.push(line.trim_start_matches("error: ").to_string()),
        }
    }
    parts.join("; ")
}

/// The [`ArgumentError`] a value parser refused a value with, if that is the cause.
fn cause_argument(e: &clap::Error) -> Option<&ArgumentError> {
    std::error::Error::source(e)?.downcast_ref::<ArgumentError>()
}

/// The completion script of `cmd` for `shell`.
pub fn completions(mut cmd: clap::Command, shell: clap_complete::Shell) -> Vec<u8> {
    let name = cmd.get_name().to_string();
    let mut out = Vec::new();
    clap_complete::generate(shell, &mut cmd, name, &mut out);
    out
}

/// `man`: the page of `cmd` or of the subcommand `args` names, to print; or, with
/// `--out DIR`, every page written into that folder (nothing to print).
pub fn man(cmd: clap::Command, args: &ManArgs) -> anyhow::Result<Vec<u8>> {
    match &args.out {
        Some(dir) => man_pages(cmd, dir).map(|_| Vec::new()),
        None => Ok(man_page(cmd, &args.subcommand)?),
    }
}

/// The man page (roff) of `cmd` or of its subcommand `path` (`["plot", "alpha"]`), with the
/// page names of its subcommands (`<tool>-<subcommand>(1)`) that [`man_pages`] writes.
pub fn man_page(cmd: clap::Command, path: &[String]) -> Result<Vec<u8>, ArgumentError> {
    let mut cmd = cmd;
    cmd.build();
    let mut page = cmd;
    let mut name = page.get_name().to_string();
    for sub in path {
        let next = page
            .get_subcommands()
            .find(|c| c.get_name() == sub)
            .cloned()
            .ok_or_else(|| {
                ArgumentError::with_text(
                    "SUBCOMMAND",
                    sub.clone(),
                    format!("{name} has no such subcommand"),
                )
            })?;
        name = format!("{name}-{sub}");
        page = next.name(name.clone());
    }
    let mut out = Vec::new();
    clap_mangen::Man::new(page)
        .render(&mut out)
        .map_err(|e| ArgumentError::with_text("SUBCOMMAND", "", e.to_string()))?;
    Ok(out)
}

/// Every man page of `cmd` into the folder `dir` (`<tool>.1`, `<tool>-<subcommand>.1`, …,
/// as `clap_mangen` names them), all together or none. Returns the files written.
pub fn man_pages(cmd: clap::Command, dir: &std::path::Path) -> anyhow::Result<Vec<PathBuf>> {
    let mut cmd = cmd;
    cmd.build();
    let mut set = crate::output::OutputSet::new();
    let mut pages: Vec<(String, clap::Command)> = vec![(cmd.get_name().to_string(), cmd)];
    while let Some((name, page)) = pages.pop() {
        for sub in page.get_subcommands() {
            let sub_name = format!("{name}-{}", sub.get_name());
            pages.push((sub_name.clone(), sub.clone().name(sub_name)));
        }
        let path = dir.join(format!("{name}.1"));
        set.write(&path, |w| {
            clap_mangen::Man::new(page.clone())
                .render(w)
                .map_err(|e| crate::output::OutputError::io(&path, e))
        })?;
    }
    Ok(set.commit()?)
}

/// Whether `e` comes from writing into a pipe whose reader has gone (also when an encoder
/// such as the CSV writer wrapped the I/O error).
fn closed_pipe(e: &anyhow::Error) -> bool {
    e.chain().any(broken_pipe)
}

/// Whether `e`, or the I/O error it wraps, is a broken pipe.
fn broken_pipe(e: &(dyn std::error::Error + 'static)) -> bool {
    if let Some(io) = e.downcast_ref::<std::io::Error>() {
        return io.kind() == std::io::ErrorKind::BrokenPipe
            || io.get_ref().is_some_and(|inner| broken_pipe(inner));
    }
    match e.downcast_ref::<csv::Error>().map(csv::Error::kind) {
        Some(csv::ErrorKind::Io(io)) => io.kind() == std::io::ErrorKind::BrokenPipe,
        _ => e.source().is_some_and(broken_pipe),
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_closed_pipe_is_recognised_through_context_and_wrappers() {
        let io = std::io::Error::from(std::io::ErrorKind::BrokenPipe);
        let e = anyhow::Error::new(io).context("writing the table");
        assert!(closed_pipe(&e));
        assert!(!closed_pipe(&anyhow::anyhow!("other")));
        let pipe = std::io::Error::from(std::io::ErrorKind::BrokenPipe);
        let csv_error = csv::Error::from(pipe);
        let wrapped = std::io::Error::other(csv_error);
        assert!(closed_pipe(
            &anyhow::Error::new(wrapped).context("--history")
        ));
    }
}
