//! The README documents every command: each subcommand listed by `compgeom --help` has a
//! `### \`compgeom NAME\`` section (regenerate them from `compgeom NAME --help`).

use assert_cmd::Command;

#[test]
fn readme_has_a_section_for_every_command() {
    let out = Command::cargo_bin("compgeom")
        .unwrap()
        .arg("--help")
        .output()
        .unwrap();
    let help = String::from_utf8(out.stdout).unwrap();
    let readme = std::fs::read_to_string(concat!(env!("CARGO_MANIFEST_DIR"), "/../../README.md"))
        .expect("README.md at the workspace root");
    let commands: Vec<&str> = help
        .lines()
        .skip_while(|l| !l.starts_with("Commands:"))
        .skip(1)
        .take_while(|l| !l.trim().is_empty())
        // A command's line starts with two spaces; wrapped descriptions are indented further.
        .filter(|l| l.starts_with("  ") && !l.starts_with("   "))
        .filter_map(|l| l.split_whitespace().next())
        .filter(|c| *c != "help")
        .collect();
    assert!(commands.contains(&"hull"), "no commands parsed from --help");
    for c in commands {
        assert!(
            readme.contains(&format!("### `compgeom {c}")),
            "README.md has no section for `compgeom {c}`"
        );
    }
}
