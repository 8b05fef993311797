//! `compgeom triangulate` and `compgeom guard` end to end.

use assert_cmd::Command;
use serde_json::Value;
use std::fs;
use tempfile::TempDir;

fn compgeom() -> Command {
    Command::new(env!("CARGO_BIN_EXE_compgeom"))
}

/// A comb of three teeth with a square hole: 8 + 4 vertices, one hole.
const GALLERY: &str =
    "POLYGON((0 0, 10 0, 10 6, 8 3, 6 6, 4 3, 2 6, 0 6, 0 0), (1 1, 1 2, 2 2, 2 1, 1 1))\n";

fn run_json(args: &[&str], stdin: &str) -> Value {
    let out = compgeom().args(args).write_stdin(stdin).assert().success();
    serde_json::from_slice(&out.get_output().stdout).expect("JSON")
}

/// Twice the signed area of triangle `t` in `v`.
fn area2(v: &Value, t: &Value) -> f64 {
    let p = |k: usize| {
        let i = t[k].as_u64().unwrap() as usize;
        (v[i][0].as_f64().unwrap(), v[i][1].as_f64().unwrap())
    };
    let (a, b, c) = (p(0), p(1), p(2));
    (b.0 - a.0) * (c.1 - a.1) - (b.1 - a.1) * (c.0 - a.0)
}

#[test]
fn triangulate_json_counts_areas_and_pieces() {
    let v = run_json(
        &[
            "triangulate",
            "-",
            "--input-format",
            "wkt",
            "--verify",
            "--monotone-pieces",
        ],
        GALLERY,
    );
    let (verts, tris) = (&v["vertices"], v["triangles"].as_array().unwrap());
    assert_eq!(verts.as_array().unwrap().len(), 12);
    // n - 2 + 2h = 12 - 2 + 2.
    assert_eq!(tris.len(), 12);
    assert!(tris.iter().all(|t| area2(verts, t) > 0.0));
    // The outer ring encloses 60 − 2 · 6 = 48, the hole 1.
    let total: f64 = tris.iter().map(|t| area2(verts, t)).sum::<f64>() / 2.0;
    assert_eq!(total, 47.0);
    assert_eq!(v["verified"], Value::Bool(true));
    // 12 triangles have 36 edge slots: 12 polygon edges + 2 · diagonals.
    assert_eq!(v["diagonals"].as_array().unwrap().len(), 12);
    let pieces = v["pieces"].as_array().unwrap();
    assert!(pieces.len() >= 2);
    let covered: usize = pieces.iter().map(|p| p.as_array().unwrap().len()).sum();
    assert!(covered >= 12);
}

#[test]
fn triangulate_wkt_and_svg() {
    let dir = TempDir::new().unwrap();
    let input = dir.path().join("g.wkt");
    let svg = dir.path().join("t.svg");
    fs::write(&input, GALLERY).unwrap();
    let out = compgeom()
        .arg("triangulate")
        .arg(&input)
        .args(["--format", "wkt", "--monotone-pieces", "--svg"])
        .arg(&svg)
        .assert()
        .success();
    let text = String::from_utf8(out.get_output().stdout.clone()).unwrap();
    assert!(text.starts_with("MULTIPOLYGON"), "{text}");
    assert_eq!(text.matches("((").count(), 12);
    let pic = fs::read_to_string(&svg).unwrap();
    assert!(
        pic.contains("<svg") && pic.contains("merge vertices") && pic.contains("monotone piece 1")
    );
}

#[test]
fn guard_json_bound_and_colours() {
    let comb = "POLYGON((0 0, 10 0, 10 6, 8 3, 6 6, 4 3, 2 6, 0 6, 0 0))";
    let v = run_json(&["guard", "-", "--input-format", "wkt", "--verify"], comb);
    let guards = v["guards"].as_array().unwrap();
    assert!(!guards.is_empty() && guards.len() <= 8 / 3, "{v}");
    let colors: Vec<u64> = v["colors"]
        .as_array()
        .unwrap()
        .iter()
        .map(|c| c.as_u64().unwrap())
        .collect();
    assert_eq!(colors.len(), 8);
    // Proper on every triangle.
    for t in v["triangles"].as_array().unwrap() {
        let c: Vec<u64> = (0..3)
            .map(|k| colors[t[k].as_u64().unwrap() as usize])
            .collect();
        assert!(c[0] != c[1] && c[1] != c[2] && c[0] != c[2]);
    }
}

#[test]
fn guards_with_touching_holes_are_distinct_points_of_the_guard_colour() {
    // Two holes touching at (7 5), one touching the outer ring at (0 5).
    let wkt =
        "POLYGON((0 0,10 0,10 10,0 10,0 0),(0 5,3 4,3 6,0 5),(5 5,7 5,6 7,5 5),(7 5,9 4,9 6,7 5))";
    let dir = TempDir::new().unwrap();
    let svg = dir.path().join("g.svg");
    let svg_arg = svg.to_str().unwrap();
    let v = run_json(
        &[
            "guard",
            "-",
            "--input-format",
            "wkt",
            "--verify",
            "--svg",
            svg_arg,
        ],
        wkt,
    );
    let point = |p: &Value| (p[0].as_f64().unwrap(), p[1].as_f64().unwrap());
    let guards: Vec<(f64, f64)> = v["guards"].as_array().unwrap().iter().map(point).collect();
    let vertices: Vec<(f64, f64)> = v["vertices"]
        .as_array()
        .unwrap()
        .iter()
        .map(point)
        .collect();
    let colors: Vec<u64> = v["colors"]
        .as_array()
        .unwrap()
        .iter()
        .map(|c| c.as_u64().unwrap())
        .collect();
    for (k, g) in guards.iter().enumerate() {
        assert!(!guards[..k].contains(g), "guard {g:?} listed twice: {v}");
    }
    // Every guard is a vertex of one colour class, and every vertex of that colour is a guard.
    let guard_colors: Vec<u64> = guards
        .iter()
        .map(|g| colors[vertices.iter().position(|p| p == g).unwrap()])
        .collect();
    let c = guard_colors[0];
    assert!(guard_colors.iter().all(|&k| k == c), "{v}");
    for (p, &k) in vertices.iter().zip(&colors) {
        if k == c {
            assert!(guards.contains(p), "{p:?} has the guard colour: {v}");
        }
    }
    // Every triangle has a guard at a corner; at most floor((n + 2h)/3) guards.
    for t in v["triangles"].as_array().unwrap() {
        assert!((0..3).any(|k| guards.contains(&vertices[t[k].as_u64().unwrap() as usize])));
    }
    assert!(guards.len() <= (vertices.len() + 2 * 3) / 3);
    let picture = fs::read_to_string(&svg).unwrap();
    assert!(
        picture.contains("vertex of two colours"),
        "the SVG rings two-coloured vertices"
    );
}

#[test]
fn self_intersecting_polygon_is_bad_input_naming_edges() {
    let out = compgeom()
        .args(["triangulate", "-", "--input-format", "wkt"])
        .write_stdin("POLYGON((0 0, 4 4, 4 0, 0 4, 0 0))")
        .assert()
        .code(2);
    let err = String::from_utf8(out.get_output().stderr.clone()).unwrap();
    assert!(
        err.contains("not simple")
            && err.contains("ring 0 edge 0")
            && err.contains("ring 0 edge 2"),
        "{err}"
    );
    compgeom()
        .args(["guard", "-", "--input-format", "wkt", "--format", "csv"])
        .write_stdin(GALLERY)
        .assert()
        .code(2);
}

#[test]
fn triangulate_subdivision_of_a_layer_and_of_segments() {
    // Two squares sharing an edge, the left one with a square hole, in a box grown by 1.
    let layer = "MULTIPOLYGON (((0 0, 2 0, 2 2, 0 2, 0 0), (0.5 0.5, 1.5 0.5, 1.5 1.5, 0.5 1.5, 0.5 0.5)), ((2 0, 4 0, 4 2, 2 2, 2 0)))\n";
    let v = run_json(
        &[
            "triangulate",
            "-",
            "--input-format",
            "wkt",
            "--subdivision",
            "--box",
            "1",
            "--verify",
        ],
        layer,
    );
    assert_eq!(v["verified"], true);
    let (verts, tris) = (&v["vertices"], v["triangles"].as_array().unwrap());
    // 10 vertices + 4 box corners, 4 on the box: 2·14 − 4 − 2 triangles.
    assert_eq!(verts.as_array().unwrap().len(), 14);
    assert_eq!(tris.len(), 22);
    let total: f64 = tris.iter().map(|t| area2(verts, t)).sum();
    assert_eq!(total, 2.0 * 6.0 * 4.0);
    // Area per polygon label: 4 − 1 inside polygon 0, 4 inside polygon 1.
    let labels = v["labels"].as_array().unwrap();
    let mut per = [0.0f64; 2];
    for (t, l) in tris.iter().zip(labels) {
        for k in l.as_array().unwrap() {
            per[k.as_u64().unwrap() as usize] += area2(verts, t);
        }
    }
    assert_eq!(per, [6.0, 8.0]);
    // Segments: one diagonal of the box, margin 0: two triangles, both unbounded.
    let v = run_json(
        &[
            "triangulate",
            "-",
            "--input-format",
            "wkt",
            "--subdivision",
            "--verify",
        ],
        "LINESTRING (0 0, 4 4)\n",
    );
    assert_eq!(v["triangles"].as_array().unwrap().len(), 2);
    assert_eq!(v["faces"], serde_json::json!([0, 0]));
    // Bad margin: bad input (exit 2) with a message.
    compgeom()
        .args([
            "triangulate",
            "-",
            "--input-format",
            "wkt",
            "--subdivision",
            "--box=-1",
        ])
        .write_stdin(layer)
        .assert()
        .code(2)
        .stderr(predicates::str::contains("margin"));
}
