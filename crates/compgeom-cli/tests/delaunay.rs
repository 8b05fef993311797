//! `compgeom delaunay` with crossing constraints and `--refine`, and `compgeom interpolate
//! --svg`, end to end.

use assert_cmd::Command;
use serde_json::Value;
use std::fs;
use tempfile::TempDir;

fn compgeom() -> Command {
    Command::new(env!("CARGO_BIN_EXE_compgeom"))
}

fn write(dir: &TempDir, name: &str, content: &str) -> std::path::PathBuf {
    let path = dir.path().join(name);
    fs::write(&path, content).unwrap();
    path
}

fn run_json(args: &[&std::ffi::OsStr]) -> Value {
    let out = compgeom().args(args).assert().success();
    serde_json::from_slice(&out.get_output().stdout).expect("JSON")
}

#[test]
fn crossing_constraints_get_a_steiner_vertex() {
    let dir = TempDir::new().unwrap();
    let pts = write(&dir, "p.csv", "0,0\n2,0\n2,2\n0,2\n");
    let segs = write(&dir, "s.csv", "0,0,2,2\n2,0,0,2\n");
    let v = run_json(&[
        "delaunay".as_ref(),
        pts.as_os_str(),
        "--constraints".as_ref(),
        segs.as_os_str(),
        "--verify".as_ref(),
    ]);
    let verts = v["vertices"].as_array().unwrap();
    assert_eq!(verts.len(), 5);
    assert_eq!(verts[4], serde_json::json!([1.0, 1.0]));
    assert_eq!(v["constraints"].as_array().unwrap().len(), 4);
    assert_eq!(v["verified"], true);
}

#[test]
fn refine_adds_steiner_points_after_the_inputs() {
    let dir = TempDir::new().unwrap();
    let pts = write(&dir, "empty.csv", "");
    let poly = write(
        &dir,
        "poly.wkt",
        "POLYGON((0 0, 10 0, 10 1, 0 1, 0 0), (2 0.25, 3 0.25, 3 0.75, 2 0.75, 2 0.25))",
    );
    let svg = dir.path().join("mesh.svg");
    let v = run_json(&[
        "delaunay".as_ref(),
        pts.as_os_str(),
        "--polygon".as_ref(),
        poly.as_os_str(),
        "--refine".as_ref(),
        "25".as_ref(),
        "--max-area".as_ref(),
        "0.2".as_ref(),
        "--verify".as_ref(),
        "--svg".as_ref(),
        svg.as_os_str(),
    ]);
    let steiner = v["steiner"].as_u64().unwrap() as usize;
    assert!(steiner > 10);
    let verts = v["vertices"].as_array().unwrap();
    assert_eq!(verts.len(), 8 + steiner);
    assert_eq!(verts[0], serde_json::json!([0.0, 0.0]));
    assert_eq!(v["exempt"].as_array().unwrap().len(), 0);
    let text = fs::read_to_string(&svg).unwrap();
    assert!(text.contains("refined") && text.contains("constrained edges"));
    // Out-of-range angle: a usage error naming the bound.
    compgeom()
        .args([
            "delaunay".as_ref(),
            pts.as_os_str(),
            "--polygon".as_ref(),
            poly.as_os_str(),
            "--refine".as_ref(),
            "50".as_ref(),
        ])
        .assert()
        .code(2)
        .stderr(predicates::str::contains("minimum angle"));
}

#[test]
fn interpolate_draws_the_terrain_and_the_queries() {
    let dir = TempDir::new().unwrap();
    let samples = write(&dir, "s.csv", "0,0,0\n4,0,4\n0,4,8\n4,4,2\n2,2,5\n");
    let queries = write(&dir, "q.csv", "1,1\n3,2\n9,9\n");
    let svg = dir.path().join("t.svg");
    let v = run_json(&[
        "interpolate".as_ref(),
        samples.as_os_str(),
        "--at".as_ref(),
        queries.as_os_str(),
        "--svg".as_ref(),
        svg.as_os_str(),
    ]);
    assert_eq!(v["heights"][2], Value::Null);
    let text = fs::read_to_string(&svg).unwrap();
    assert!(text.contains("height"), "no height bands");
    assert!(text.contains("queries with a height (2)"));
    assert!(text.contains("queries outside the hull (1)"));
    assert!(text.matches("<polygon").count() + text.matches("<path").count() >= 4);
}
