//! `compgeom intersect` end to end: JSON fields, formats, --count-only, --verify, --svg,
//! bad input.

use assert_cmd::Command;
use predicates::prelude::*;
use serde_json::Value;
use std::fs;
use tempfile::TempDir;

fn compgeom() -> Command {
    Command::new(env!("CARGO_BIN_EXE_compgeom"))
}

fn input(name: &str, content: &str) -> (TempDir, std::path::PathBuf) {
    let dir = TempDir::new().unwrap();
    let path = dir.path().join(name);
    fs::write(&path, content).unwrap();
    (dir, path)
}

/// Two diagonals of a square, a vertical through their crossing, a piece overlapping a
/// diagonal, and a lone point segment.
const SEGMENTS: &str = "0,0,4,4\n0,4,4,0\n2,0,2,4\n0,0,2,2\n5,5,5,5\n";

fn json(args: &[&str], content: &str) -> Value {
    let (_dir, path) = input("segs.csv", content);
    let out = compgeom()
        .arg("intersect")
        .arg(&path)
        .args(args)
        .assert()
        .success();
    serde_json::from_slice(&out.get_output().stdout).expect("JSON")
}

#[test]
fn json_lists_points_with_upper_lower_interior_and_overlaps() {
    let v = json(&[], SEGMENTS);
    assert_eq!(v["segments"], 5);
    let pts = v["intersections"].as_array().unwrap();
    assert_eq!(pts.len(), 2);
    // Sweep order: (2, 2) (higher) first, then (0, 0).
    assert_eq!(pts[0]["point"], serde_json::json!([2.0, 2.0]));
    assert_eq!(pts[0]["segments"], serde_json::json!([0, 1, 2, 3]));
    assert_eq!(pts[0]["upper"], serde_json::json!([3]));
    assert_eq!(pts[0]["lower"], serde_json::json!([]));
    assert_eq!(pts[0]["interior"], serde_json::json!([0, 1, 2]));
    assert_eq!(pts[1]["point"], serde_json::json!([0.0, 0.0]));
    assert_eq!(pts[1]["lower"], serde_json::json!([0, 3]));
    let ov = v["overlaps"].as_array().unwrap();
    assert_eq!(ov.len(), 1);
    assert_eq!(ov[0]["segments"], serde_json::json!([0, 3]));
    assert_eq!(ov[0]["from"], serde_json::json!([2.0, 2.0]));
    assert_eq!(ov[0]["to"], serde_json::json!([0.0, 0.0]));
    assert!(v.get("verified").is_none());
}

#[test]
fn crossings_are_the_nearest_double() {
    // The crossing of these lines is (0.25, 0.75) exactly; of the next pair, x = 1/3.
    let v = json(&[], "0,0,1,3\n0,1,1,0\n");
    assert_eq!(
        v["intersections"][0]["point"],
        serde_json::json!([0.25, 0.75])
    );
    let v = json(&[], "0,0,1,1\n0,0.5,1,0\n");
    assert_eq!(
        v["intersections"][0]["point"],
        serde_json::json!([1.0 / 3.0, 1.0 / 3.0])
    );
}

#[test]
fn count_only_verify_and_other_formats() {
    let v = json(&["--count-only", "--verify"], SEGMENTS);
    assert_eq!(
        v,
        serde_json::json!({"intersections": 2, "overlaps": 1, "segments": 5, "verified": true})
    );
    let (_dir, path) = input("segs.csv", SEGMENTS);
    compgeom()
        .args(["intersect", "--count-only", "-f", "csv"])
        .arg(&path)
        .assert()
        .success()
        .stdout("2\n");
    compgeom()
        .args(["intersect", "-f", "wkt"])
        .arg(&path)
        .assert()
        .success()
        .stdout(predicate::str::contains("MULTIPOINT"));
}

#[test]
fn wkt_linestrings_give_one_segment_per_edge() {
    let (_dir, path) = input(
        "lines.wkt",
        "MULTILINESTRING ((0 0, 2 2, 4 0), (0 2, 4 2))\n",
    );
    let out = compgeom().arg("intersect").arg(&path).assert().success();
    let v: Value = serde_json::from_slice(&out.get_output().stdout).unwrap();
    assert_eq!(v["segments"], 3);
    // (2, 2): the shared vertex of edges 0 and 1, on the interior of edge 2.
    let p = &v["intersections"][0];
    assert_eq!(p["point"], serde_json::json!([2.0, 2.0]));
    assert_eq!(p["segments"], serde_json::json!([0, 1, 2]));
    assert_eq!(p["interior"], serde_json::json!([2]));
}

#[test]
fn svg_shows_the_sweep_status() {
    let (dir, path) = input("segs.csv", SEGMENTS);
    let svg = dir.path().join("out.svg");
    compgeom()
        .arg("intersect")
        .arg(&path)
        .arg("--svg")
        .arg(&svg)
        .assert()
        .success();
    let text = fs::read_to_string(&svg).unwrap();
    for layer in [
        "segments (5)",
        "intersection points (2)",
        "overlaps (1)",
        "sweep line after event",
        "status structure",
    ] {
        assert!(text.contains(layer), "missing {layer}");
    }
}

#[test]
fn bad_input_exits_2() {
    let (_dir, path) = input("bad.csv", "0,0,1,1\n0,0,nan,1\n");
    compgeom()
        .arg("intersect")
        .arg(&path)
        .assert()
        .code(2)
        .stderr(predicate::str::starts_with("error:"));
    // --verify is quadratic: refused beyond its limit, before any work.
    let many: String = (0..5001).map(|i| format!("{i},0,{i},1\n")).collect();
    let (_dir, path) = input("many.csv", &many);
    compgeom()
        .args(["intersect", "--verify"])
        .arg(&path)
        .assert()
        .code(2)
        .stderr(predicate::str::contains("at most 5000"));
}

#[test]
fn help_documents_the_json_fields() {
    let out = compgeom().args(["intersect", "--help"]).assert().success();
    let text = String::from_utf8_lossy(&out.get_output().stdout).to_string();
    for field in [
        "intersections",
        "upper",
        "lower",
        "interior",
        "overlaps",
        "--count-only",
        "--verify",
    ] {
        assert!(text.contains(field), "help lacks {field}");
    }
}

#[test]
fn every_algorithm_gives_the_same_output() {
    let (_dir, path) = input("segs.csv", SEGMENTS);
    let run = |alg: &str| {
        let out = compgeom()
            .args(["intersect", "--algorithm", alg])
            .arg(&path)
            .assert()
            .success();
        out.get_output().stdout.clone()
    };
    let default = run("default");
    assert_eq!(run("sweep"), default);
    assert_eq!(run("pairwise"), default);
    compgeom()
        .args(["intersect", "--algorithm", "nope"])
        .arg(&path)
        .assert()
        .code(2);
}

#[test]
fn count_only_counts_without_building_the_points_and_agrees_with_the_full_answer() {
    // Without --verify or --svg, --count-only takes the counting path; with --verify it
    // counts the full, verified answer. Every method agrees, on the small example and on
    // a grid with concurrent crossings, shared endpoints and overlaps.
    let mut grid = String::new();
    for k in 0..60u32 {
        let (x, y) = (k * 7 % 11, k * 5 % 9);
        grid.push_str(&format!(
            "{x},{y},{},{}\n",
            (x * 3 + k) % 11,
            (y + 2 * k) % 9
        ));
    }
    for content in [SEGMENTS, grid.as_str()] {
        let mut full = json(&["--count-only", "--verify"], content);
        full.as_object_mut().unwrap().remove("verified");
        assert!(full["intersections"].as_u64().unwrap() >= 2);
        for alg in ["default", "sweep", "pairwise"] {
            let counted = json(&["--count-only", "--algorithm", alg], content);
            assert_eq!(counted, full, "--algorithm {alg}");
        }
    }
}
