//! `compgeom halfplanes` end to end: the default (slope sort and sweep), `--algorithm dc`
//! (the book's divide and conquer) and --incremental give the same region, verified.

use assert_cmd::Command;
use serde_json::Value;
use std::fs;
use tempfile::TempDir;

fn run(args: &[&str], content: &str) -> Value {
    let dir = TempDir::new().unwrap();
    let path = dir.path().join("hp.txt");
    fs::write(&path, content).unwrap();
    let out = Command::new(env!("CARGO_BIN_EXE_compgeom"))
        .arg("halfplanes")
        .arg(&path)
        .args(args)
        .assert()
        .success();
    serde_json::from_slice(&out.get_output().stdout).expect("JSON")
}

#[test]
fn default_and_incremental_agree() {
    // A square given twice, a redundant constraint and a cut corner.
    let square = "-1 0 0\n1 0 4\n0 -1 0\n0 1 4\n-1 0 0\n1 1 7\n9 9 100\n";
    let dc = run(&["--verify"], square);
    let inc = run(&["--verify", "--incremental", "--seed", "5"], square);
    assert_eq!(dc["kind"], "polygon");
    assert_eq!(dc["verified"], true);
    assert_eq!(
        dc["vertices"],
        serde_json::json!([[0.0, 0.0], [4.0, 0.0], [4.0, 3.0], [3.0, 4.0], [0.0, 4.0]])
    );
    assert_eq!(dc["vertices"], inc["vertices"]);
    let book = run(&["--verify", "--algorithm", "dc"], square);
    assert_eq!(book, dc);
    let inc2 = run(&["--algorithm", "incremental", "--seed", "5"], square);
    assert_eq!(inc2["vertices"], dc["vertices"]);
    assert_eq!(dc["constraints"], serde_json::json!([2, 1, 5, 3, 0]));
    // A strip and a point: the degenerate kinds.
    let strip = run(&[], "0 1 1\n0 -1 1\n");
    assert_eq!(strip["kind"], "unbounded");
    let point = run(&["--incremental"], "1 1 0\n-1 1 0\n0 -1 0\n");
    assert_eq!(point["kind"], "point");
    assert_eq!(
        run(&[], "1 1 0\n-1 1 0\n0 -1 0\n")["vertices"],
        point["vertices"]
    );
}
