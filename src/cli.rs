//! What both command-line tools share: one error and exit-code convention, notes, `--quiet`, shell completions and man pages, and
//! the Markdown command-line reference generated from the clap definitions
//! (`docs/cli/<tool>.md`, checked by each tool's tests).
//!
//! The convention (docs/cli/README.md): every error is one line `<tool>: error: <message>` on
//! stderr; exit status 0 on success (also when the reader of standard output closed it early,
//! `… | head`), 1 when a run failed, 2 for a command-line usage error (unknown flag, bad
//! value, missing subcommand: then the help of the command is printed). Notes and progress
//! lines are `<tool>: <text>` on stderr and `--quiet` silences them.

use crate::diagnostics::error_line;
use std::fmt::Display;
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

/// The shell of `completions SHELL` and the man page (shared by both tools).
#[derive(clap::Args, Debug)]
pub struct CompletionsArgs {
    /// Shell to write the completion script for.
    #[arg(value_enum)]
    pub shell: clap_complete::Shell,
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
    /// prints the help to stderr (exit 2); any other clap error becomes one line
    /// `<name>: error: <message>` on stderr without the usage block (exit 2). `quiet` reads
    /// the parsed `--quiet` flag.
    pub fn parse<P: clap::Parser>(&self, quiet: impl Fn(&P) -> bool) -> Result<P, ExitCode> {
        match P::try_parse() {
            Ok(p) => {
                let _ = self.quiet.set(quiet(&p));
                Ok(p)
            }
            Err(e) if !e.use_stderr() => {
                let _ = e.print();
                Err(ExitCode::SUCCESS)
            }
            Err(e)
                if e.kind() == clap::error::ErrorKind::DisplayHelpOnMissingArgumentOrSubcommand =>
            {
                let _ = e.print();
                Err(ExitCode::from(USAGE_ERROR))
            }
            Err(e) => {
                let text = e.render().to_string();
                let message: Vec<&str> = text
                    .lines()
                    .take_while(|l| !l.starts_with("Usage:"))
                    .map(str::trim)
                    .filter(|l| !l.is_empty())
                    .collect();
                self.error(message.join(" ").trim_start_matches("error: "));
                Err(ExitCode::from(USAGE_ERROR))
            }
        }
    }

    /// The exit of a run: success; quietly success when standard output was closed by its
    /// reader (`… | head`); otherwise the error and its causes as one line on stderr, exit 1.
    pub fn finish(&self, result: anyhow::Result<()>) -> ExitCode {
        match result {
            Ok(()) => ExitCode::SUCCESS,
            Err(e) if closed_pipe(&e) => ExitCode::SUCCESS,
            Err(e) => {
                self.error(error_line(e.as_ref()));
                ExitCode::FAILURE
            }
        }
    }

    /// The error line `<name>: error: <text>` on stderr.
    fn error(&self, text: impl Display) {
        eprintln!("{}: error: {text}", self.name);
    }

    /// A line on stderr, `<name>: <text>`, unless `--quiet` was given.
    pub fn say(&self, text: impl Display) {
        if !self.quiet.get().copied().unwrap_or(false) {
            eprintln!("{}: {text}", self.name);
        }
    }
}

/// The completion script of `cmd` for `shell`.
pub fn completions(mut cmd: clap::Command, shell: clap_complete::Shell) -> Vec<u8> {
    let name = cmd.get_name().to_string();
    let mut out = Vec::new();
    clap_complete::generate(shell, &mut cmd, name, &mut out);
    out
}

/// The man page (roff) of `cmd`, its subcommands listed.
pub fn man_page(cmd: clap::Command) -> std::io::Result<Vec<u8>> {
    let mut out = Vec::new();
    clap_mangen::Man::new(cmd).render(&mut out)?;
    Ok(out)
}

/// Whether `e` comes from writing into a pipe whose reader has gone.
fn closed_pipe(e: &anyhow::Error) -> bool {
    e.chain().any(|c| {
        c.downcast_ref::<std::io::Error>()
            .is_some_and(|io| io.kind() == std::io::ErrorKind::BrokenPipe)
    })
}

/// The command-line reference of `cmd` in Markdown: one section per command and subcommand
/// holding its `--help` text.
pub fn markdown_reference(mut cmd: clap::Command) -> String {
    cmd.build();
    let name = cmd.get_name().to_string();
    let mut out = format!(
        "# `{name}` command-line reference\n\n\
         Generated from the tool's argument definitions by its test `cli_reference_is_current` \
         (`UPDATE_CLI_REFERENCE=1 cargo test --bin {name} cli_reference` rewrites it); do not \
         edit by hand.\n"
    );
    push_command(&mut out, &mut cmd, &name);
    out
}

/// Appends the section of `cmd` (called `path` on the command line) and of its subcommands.
fn push_command(out: &mut String, cmd: &mut clap::Command, path: &str) {
    let help = cmd.render_long_help().to_string();
    out.push_str(&format!(
        "\n## `{path}`\n\n```text\n{}\n```\n",
        help.trim_end()
    ));
    for sub in cmd.get_subcommands_mut() {
        if sub.get_name() == "help" {
            continue;
        }
        let sub_path = format!("{path} {}", sub.get_name());
        push_command(out, sub, &sub_path);
    }
}

/// Checks that `docs/cli/<tool>.md` holds the current reference of `cmd`, or rewrites it when
/// the environment variable `UPDATE_CLI_REFERENCE` is set (each tool's test; panics when stale).
pub fn check_reference(cmd: clap::Command) {
    let name = cmd.get_name().to_string();
    let path = std::path::Path::new(env!("CARGO_MANIFEST_DIR"))
        .join("docs/cli")
        .join(format!("{name}.md"));
    let current = markdown_reference(cmd);
    if std::env::var_os("UPDATE_CLI_REFERENCE").is_some() {
        std::fs::create_dir_all(path.parent().unwrap()).unwrap();
        std::fs::write(&path, &current).unwrap();
    }
    let shipped = std::fs::read_to_string(&path).unwrap_or_default();
    assert!(
        shipped == current,
        "{} is stale: run `UPDATE_CLI_REFERENCE=1 cargo test --bin {name} cli_reference`",
        path.display()
    );
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_closed_pipe_is_recognised_through_context() {
        let io = std::io::Error::from(std::io::ErrorKind::BrokenPipe);
        let e = anyhow::Error::new(io).context("writing the table");
        assert!(closed_pipe(&e));
        assert!(!closed_pipe(&anyhow::anyhow!("other")));
    }
}
