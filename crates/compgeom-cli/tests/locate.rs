//! `compgeom locate` end to end: polygon layers and segments, answers on faces, edges and
//! vertices, seeds, pictures, and bad input.

use assert_cmd::Command;
use serde_json::{json, Value};
use std::fs;
use tempfile::TempDir;

fn compgeom() -> Command {
    Command::new(env!("CARGO_BIN_EXE_compgeom"))
}

/// Two squares sharing an edge; the right one has a square hole.
const LAYER: &str = "MULTIPOLYGON (((0 0, 2 0, 2 2, 0 2, 0 0)), ((2 0, 4 0, 4 2, 2 2, 2 0), (2.5 0.5, 3.5 0.5, 3.5 1.5, 2.5 1.5, 2.5 0.5)))\n";
const QUERIES: &str = "1,1\n3,1\n2,1\n2,2\n9,9\n3,0.5\n3,0.25\n";

fn setup(
    map_name: &str,
    map: &str,
    queries: &str,
) -> (TempDir, std::path::PathBuf, std::path::PathBuf) {
    let dir = TempDir::new().unwrap();
    let m = dir.path().join(map_name);
    let q = dir.path().join("q.csv");
    fs::write(&m, map).unwrap();
    fs::write(&q, queries).unwrap();
    (dir, m, q)
}

fn run(args: &[&std::ffi::OsStr]) -> Value {
    let out = compgeom().arg("locate").args(args).assert().success();
    serde_json::from_slice(&out.get_output().stdout).expect("JSON")
}

#[test]
fn polygon_layer_answers_feature_and_kind() {
    let (_d, m, q) = setup("map.wkt", LAYER, QUERIES);
    let v = run(&[m.as_os_str(), "--queries".as_ref(), q.as_os_str()]);
    assert_eq!(
        v,
        json!({"results": [
            {"feature": 0, "on": "face"},
            {"feature": null, "on": "face"},
            {"feature": 0, "on": "edge"},
            {"feature": 0, "on": "vertex"},
            {"feature": null, "on": "face"},
            {"feature": 1, "on": "edge"},
            {"feature": 1, "on": "face"},
        ]})
    );
    // The answers do not depend on the seed.
    for seed in ["0", "7", "123456789"] {
        let w = run(&[
            m.as_os_str(),
            "--queries".as_ref(),
            q.as_os_str(),
            "--seed".as_ref(),
            seed.as_ref(),
            "--verify".as_ref(),
        ]);
        assert_eq!(w["results"], v["results"]);
        assert_eq!(w["verified"], json!(true));
    }
}

#[test]
fn geojson_layer_and_segments() {
    let gj = r#"{"type":"FeatureCollection","features":[
      {"type":"Feature","properties":{},"geometry":{"type":"Polygon","coordinates":[[[0,0],[1,0],[1,1],[0,1],[0,0]]]}},
      {"type":"Feature","properties":{},"geometry":{"type":"Polygon","coordinates":[[[1,0],[2,0],[2,1],[1,1],[1,0]]]}}]}"#;
    let (_d, m, q) = setup("map.geojson", gj, "0.5,0.5\n1.5,0.5\n1,0.5\n5,5\n");
    let v = run(&[m.as_os_str(), "--queries".as_ref(), q.as_os_str()]);
    let feats: Vec<Value> = v["results"]
        .as_array()
        .unwrap()
        .iter()
        .map(|r| r["feature"].clone())
        .collect();
    assert_eq!(feats, vec![json!(0), json!(1), json!(0), Value::Null]);

    // Segments: a square with one diagonal (vertical edges, equal x).
    let segs = "0,0,4,0\n4,0,4,4\n4,4,0,4\n0,4,0,0\n0,0,4,4\n";
    let (_e, m, q) = setup("walls.csv", segs, "1,3\n3,1\n2,2\n0,2\n0,0\n9,9\n");
    let v = run(&[m.as_os_str(), "--queries".as_ref(), q.as_os_str()]);
    let r = v["results"].as_array().unwrap();
    assert_eq!(r[0]["on"], "face");
    assert_eq!(r[1]["on"], "face");
    assert_ne!(
        r[0]["face"], r[1]["face"],
        "the two triangles are different faces"
    );
    assert_ne!(r[0]["face"], json!(0));
    assert_eq!(r[2], json!({"feature": 4, "on": "edge"}));
    assert_eq!(r[3], json!({"feature": 3, "on": "edge"}));
    assert_eq!(r[4], json!({"feature": 0, "on": "vertex"}));
    assert_eq!(r[5], json!({"feature": null, "on": "face", "face": 0}));
}

#[test]
fn a_multipolygon_feature_is_one_feature() {
    // Feature 0 is two squares (a MultiPolygon), feature 1 one square between them; a
    // feature with no geometry still takes its index.
    let gj = r#"{"type":"FeatureCollection","features":[
      {"type":"Feature","properties":{},"geometry":{"type":"MultiPolygon","coordinates":[[[[0,0],[1,0],[1,1],[0,1],[0,0]]],[[[5,0],[6,0],[6,1],[5,1],[5,0]]]]}},
      {"type":"Feature","properties":{},"geometry":null},
      {"type":"Feature","properties":{},"geometry":{"type":"Polygon","coordinates":[[[2,0],[3,0],[3,1],[2,1],[2,0]]]}}]}"#;
    let (_d, m, q) = setup("map.geojson", gj, "0.5,0.5\n5.5,0.5\n2.5,0.5\n6,1\n9,9\n");
    for locator in ["trap", "slab"] {
        let v = run(&[
            m.as_os_str(),
            "--queries".as_ref(),
            q.as_os_str(),
            "--locator".as_ref(),
            locator.as_ref(),
            "--verify".as_ref(),
        ]);
        let feats: Vec<Value> = v["results"]
            .as_array()
            .unwrap()
            .iter()
            .map(|r| r["feature"].clone())
            .collect();
        assert_eq!(
            feats,
            vec![json!(0), json!(0), json!(2), json!(0), Value::Null],
            "{locator}"
        );
    }
}

#[test]
fn svg_draws_the_trapezoidal_map() {
    let (d, m, q) = setup("map.wkt", LAYER, QUERIES);
    let svg = d.path().join("map.svg");
    compgeom()
        .args([
            "locate".as_ref(),
            m.as_os_str(),
            "--queries".as_ref(),
            q.as_os_str(),
            "--svg".as_ref(),
            svg.as_os_str(),
        ])
        .assert()
        .success();
    let text = fs::read_to_string(&svg).unwrap();
    assert!(text.starts_with("<svg"));
    assert!(text.contains("trapezoids (") && text.contains("vertical extensions"));
    assert!(text.contains("queries on an edge") && text.contains("queries at a vertex"));
    assert!(text.contains("queries in feature 1"));
}

#[test]
fn crossing_maps_and_bad_queries_are_errors() {
    let (_d, m, q) = setup("x.csv", "0,0,4,4\n0,4,4,0\n", "1,1\n");
    let out = compgeom()
        .args([
            "locate".as_ref(),
            m.as_os_str(),
            "--queries".as_ref(),
            q.as_os_str(),
        ])
        .assert()
        .code(2);
    let err = String::from_utf8_lossy(&out.get_output().stderr).to_string();
    assert!(err.contains("segments 0 and 1 cross"), "{err}");

    let bow = "POLYGON ((0 0, 2 0, 2 2, 0 2, 0 0))\nPOLYGON ((1 1, 3 1, 3 3, 1 3, 1 1))\n";
    let (_e, m, q) = setup("b.wkt", bow, "1,1\n");
    let out = compgeom()
        .args([
            "locate".as_ref(),
            m.as_os_str(),
            "--queries".as_ref(),
            q.as_os_str(),
        ])
        .assert()
        .code(2);
    let err = String::from_utf8_lossy(&out.get_output().stderr).to_string();
    assert!(err.contains("polygons 0 and 1 cross"), "{err}");

    let (_f, m, q) = setup("map.wkt", LAYER, "1,1\nnope\n");
    compgeom()
        .args([
            "locate".as_ref(),
            m.as_os_str(),
            "--queries".as_ref(),
            q.as_os_str(),
        ])
        .assert()
        .code(2);
    compgeom()
        .args([
            "locate".as_ref(),
            m.as_os_str(),
            "--queries".as_ref(),
            "missing.csv".as_ref(),
        ])
        .assert()
        .code(2);
    compgeom()
        .args([
            "locate".as_ref(),
            m.as_os_str(),
            "--queries".as_ref(),
            q.as_os_str(),
            "--format".as_ref(),
            "wkt".as_ref(),
        ])
        .assert()
        .code(2);
}
