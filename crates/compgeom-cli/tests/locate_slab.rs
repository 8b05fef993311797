//! `compgeom locate --locator slab` and `--verify`'s answer checks, end to end.

use assert_cmd::Command;
use serde_json::{json, Value};
use std::fs;
use tempfile::TempDir;

/// Two squares sharing an edge; the right one has a square hole.
const LAYER: &str = "MULTIPOLYGON (((0 0, 2 0, 2 2, 0 2, 0 0)), ((2 0, 4 0, 4 2, 2 2, 2 0), (2.5 0.5, 3.5 0.5, 3.5 1.5, 2.5 1.5, 2.5 0.5)))\n";

fn run(map: &str, name: &str, queries: &str, extra: &[&str]) -> Value {
    let dir = TempDir::new().unwrap();
    let (m, q) = (dir.path().join(name), dir.path().join("q.csv"));
    fs::write(&m, map).unwrap();
    fs::write(&q, queries).unwrap();
    let out = Command::new(env!("CARGO_BIN_EXE_compgeom"))
        .arg("locate")
        .arg(&m)
        .arg("--queries")
        .arg(&q)
        .args(extra)
        .assert()
        .success();
    serde_json::from_slice(&out.get_output().stdout).expect("JSON")
}

#[test]
fn slab_locator_gives_the_trapezoidal_maps_answers() {
    // Queries on a quarter grid: inside faces, on edges, at vertices, in the hole, outside.
    let mut qs = String::new();
    for i in -2..=18 {
        for j in -2..=10 {
            qs.push_str(&format!("{},{}\n", i as f64 / 4.0, j as f64 / 4.0));
        }
    }
    let trap = run(LAYER, "map.wkt", &qs, &["--verify"]);
    let slab = run(LAYER, "map.wkt", &qs, &["--locator", "slab", "--verify"]);
    assert_eq!(trap["verified"], json!(true));
    assert_eq!(slab, trap);
    let r = &slab["results"];
    // (1, 1) is the 13 * 6 + 6 = 84th query: inside square 0.
    assert_eq!(r[6 * 13 + 6], json!({"feature": 0, "on": "face"}));
    // (3, 1) is in the hole of polygon 1: outside every feature.
    assert_eq!(r[14 * 13 + 6], json!({"feature": null, "on": "face"}));
    // (2, 1) is on the shared edge.
    assert_eq!(r[10 * 13 + 6], json!({"feature": 0, "on": "edge"}));
    // Segments too.
    let segs = "MULTILINESTRING ((0 0, 4 0), (2 0, 2 3), (0 0, 2 3))\n";
    let q = "2,1\n2,0\n1,1\n3,1\n1,0\n";
    let a = run(segs, "s.wkt", q, &["--verify"]);
    let b = run(segs, "s.wkt", q, &["--locator", "slab", "--verify"]);
    assert_eq!(a, b);
    assert_eq!(b["results"][0], json!({"feature": 1, "on": "edge"}));
    assert_eq!(b["results"][1]["on"], json!("vertex"));
}

#[test]
fn bad_locator_is_a_usage_error() {
    let dir = TempDir::new().unwrap();
    let (m, q) = (dir.path().join("m.wkt"), dir.path().join("q.csv"));
    fs::write(&m, LAYER).unwrap();
    fs::write(&q, "1,1\n").unwrap();
    Command::new(env!("CARGO_BIN_EXE_compgeom"))
        .arg("locate")
        .arg(&m)
        .arg("--queries")
        .arg(&q)
        .args(["--locator", "walk"])
        .assert()
        .code(2);
}
