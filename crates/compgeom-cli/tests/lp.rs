//! `compgeom lp` end to end: zero-normal constraints (`0·x <= c`) are ignored when true and
//! make the program infeasible, with that constraint as the certificate, when false — in
//! two dimensions and in three.

use assert_cmd::Command;
use serde_json::Value;
use std::fs;
use tempfile::TempDir;

fn run(content: &str, objective: &str) -> Value {
    let dir = TempDir::new().unwrap();
    let path = dir.path().join("lp.txt");
    fs::write(&path, content).unwrap();
    let out = Command::new(env!("CARGO_BIN_EXE_compgeom"))
        .arg("lp")
        .arg(&path)
        .args(["--maximize", objective])
        .assert()
        .success();
    serde_json::from_slice(&out.get_output().stdout).expect("JSON")
}

#[test]
fn zero_normals_in_two_and_three_dimensions() {
    let square = "1 0 1\n-1 0 0\n0 1 1\n0 -1 0\n";
    let ok = run(&format!("{square}0 0 5\n"), "1,1");
    assert_eq!(ok["status"], "optimal");
    assert_eq!(ok["point"], serde_json::json!([1.0, 1.0]));
    assert_eq!(ok["constraints"], serde_json::json!([0, 2]));
    let bad = run(&format!("{square}0 0 5\n0 0 -0.5\n"), "1,1");
    assert_eq!(bad["status"], "infeasible");
    assert_eq!(bad["certificate"], serde_json::json!([5]));

    let cube = "1 0 0 1\n-1 0 0 0\n0 1 0 1\n0 -1 0 0\n0 0 1 1\n0 0 -1 0\n";
    let ok = run(&format!("0 0 0 0\n{cube}"), "1,2,3");
    assert_eq!(ok["status"], "optimal");
    assert_eq!(ok["point"], serde_json::json!([1.0, 1.0, 1.0]));
    assert_eq!(ok["value"], serde_json::json!(6.0));
    let bad = run(&format!("{cube}0 0 0 -1\n"), "1,2,3");
    assert_eq!(bad["status"], "infeasible");
    assert_eq!(bad["certificate"], serde_json::json!([6]));
}
