//! The library carries no terminal concerns into the Python package: its dependency tree (with
//! the `Cargo.lock` of this workspace) holds neither clap (argument parsing, completions, man
//! pages) nor indicatif (the terminal progress bar), which only the command-line tools need
//! (the `cli` feature).

use std::process::Command;

#[test]
fn the_python_package_builds_without_clap_and_indicatif() {
    let out = Command::new(env!("CARGO"))
        .args([
            "tree",
            "--offline",
            "-p",
            "polargen-python",
            "-e",
            "normal",
            "--prefix",
            "none",
        ])
        .current_dir(env!("CARGO_MANIFEST_DIR"))
        .output()
        .expect("run cargo tree");
    let tree = String::from_utf8_lossy(&out.stdout);
    assert!(
        out.status.success(),
        "{}",
        String::from_utf8_lossy(&out.stderr)
    );
    assert!(tree.lines().any(|l| l.starts_with("polargen v")), "{tree}");
    for crate_name in ["clap", "clap_complete", "clap_mangen", "indicatif"] {
        assert!(
            !tree
                .lines()
                .any(|l| l.starts_with(&format!("{crate_name} v"))),
            "{crate_name} is a dependency of the Python package:\n{tree}"
        );
    }
}
