//! The Markdown command-line reference generated from the clap definitions (`docs/cli/<tool>.md`).

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
