//! `compgeom voronoi`: the default (dual) against `--algorithm fortune`, clipping to a
//! non-convex polygon with a hole, and `--farthest`, end to end.

use assert_cmd::Command;
use serde_json::Value;
use std::fs;
use tempfile::TempDir;

fn compgeom() -> Command {
    Command::new(env!("CARGO_BIN_EXE_compgeom"))
}

fn run(dir: &TempDir, points: &str, args: &[&str]) -> Value {
    let p = dir.path().join("points.csv");
    fs::write(&p, points).unwrap();
    let out = compgeom()
        .arg("voronoi")
        .arg(&p)
        .args(args)
        .assert()
        .success();
    serde_json::from_slice(&out.get_output().stdout).unwrap()
}

fn shoelace(ring: &Value) -> f64 {
    let r: Vec<(f64, f64)> = ring
        .as_array()
        .unwrap()
        .iter()
        .map(|p| (p[0].as_f64().unwrap(), p[1].as_f64().unwrap()))
        .collect();
    let k = r.len();
    (0..k)
        .map(|i| r[i].0 * r[(i + 1) % k].1 - r[(i + 1) % k].0 * r[i].1)
        .sum::<f64>()
        / 2.0
}

const GRID: &str = "0,0\n1,0\n2,0\n0,1\n1,1\n2,1\n0,2\n1,2\n2,2\n1,1\n";

#[test]
fn default_and_fortune_give_the_same_diagram() {
    let dir = TempDir::new().unwrap();
    let a = run(&dir, GRID, &["--verify"]);
    let b = run(&dir, GRID, &["--verify", "--algorithm", "fortune"]);
    assert_eq!(a["algorithm"], "default");
    assert_eq!(b["algorithm"], "fortune");
    let sets = |v: &Value| {
        let mut s: Vec<String> = v["vertex_sites"]
            .as_array()
            .unwrap()
            .iter()
            .map(|x| x.to_string())
            .collect();
        s.sort();
        s
    };
    assert_eq!(sets(&a), sets(&b));
    assert_eq!(sets(&a).len(), 4);
    // The same cells, up to the ring's starting corner.
    let canon = |v: &Value| -> Vec<Vec<(f64, f64)>> {
        v["cells"]
            .as_array()
            .unwrap()
            .iter()
            .map(|c| {
                let mut r: Vec<(f64, f64)> = c["polygon"]
                    .as_array()
                    .unwrap()
                    .iter()
                    .map(|p| (p[0].as_f64().unwrap(), p[1].as_f64().unwrap()))
                    .collect();
                let k = (0..r.len())
                    .min_by(|&i, &j| r[i].partial_cmp(&r[j]).unwrap())
                    .unwrap_or(0);
                r.rotate_left(k);
                r
            })
            .collect()
    };
    assert_eq!(canon(&a), canon(&b));
    assert_eq!(
        a["edges"].as_array().unwrap().len(),
        b["edges"].as_array().unwrap().len()
    );
}

#[test]
fn clip_to_non_convex_polygon_with_hole() {
    let dir = TempDir::new().unwrap();
    // A U shape (area 100 - 28 = 72) with a small square hole (area 1) in its bar.
    let poly = dir.path().join("u.wkt");
    fs::write(
        &poly,
        "POLYGON ((0 0, 10 0, 10 10, 7 10, 7 3, 3 3, 3 10, 0 10, 0 0), (4 1, 4 2, 5 2, 5 1, 4 1))",
    )
    .unwrap();
    let p = poly.to_str().unwrap();
    let v = run(&dir, "5,12\n5,-5\n", &["--clip-polygon", p, "--verify"]);
    assert_eq!(v["verified"], true);
    let cells = v["cells"].as_array().unwrap();
    // The upper site's cell holds both arms: two parts; the lower one holds the bar with the
    // hole: one part with a hole.
    assert_eq!(cells[0]["parts"].as_array().unwrap().len(), 2);
    let lower = cells[1]["parts"].as_array().unwrap();
    assert_eq!(lower.len(), 1);
    assert_eq!(lower[0].as_array().unwrap().len(), 2);
    let total: f64 = cells
        .iter()
        .flat_map(|c| c["parts"].as_array().unwrap().iter())
        .flat_map(|part| part.as_array().unwrap().iter())
        .map(shoelace)
        .sum();
    assert!((total - 71.0).abs() < 1e-9, "{total}");
    // GeoJSON: the split cell is a MultiPolygon.
    let g = run(
        &dir,
        "5,12\n5,-5\n",
        &["--clip-polygon", p, "--format", "geojson"],
    );
    let f = g["features"].as_array().unwrap();
    assert_eq!(f[0]["geometry"]["type"], "MultiPolygon");
    assert_eq!(f[1]["geometry"]["type"], "Polygon");
}

#[test]
fn farthest_point_diagram() {
    let dir = TempDir::new().unwrap();
    let svg = dir.path().join("f.svg");
    let v = run(
        &dir,
        "0,0\n4,0\n4,4\n0,4\n2,2\n1,3\n",
        &[
            "--farthest",
            "--verify",
            "--clip=-10,-10,14,14",
            "--svg",
            svg.to_str().unwrap(),
        ],
    );
    assert_eq!(v["algorithm"], "farthest");
    assert_eq!(v["vertices"], serde_json::json!([[2.0, 2.0]]));
    assert_eq!(v["vertex_sites"], serde_json::json!([[0, 1, 2, 3]]));
    let cells = v["cells"].as_array().unwrap();
    // Interior points have no cell; the four corners split the box into quadrants.
    assert_eq!(cells[4]["polygon"], serde_json::json!([]));
    assert_eq!(cells[5]["polygon"], serde_json::json!([]));
    for c in &cells[..4] {
        assert!((shoelace(&c["polygon"]) - 144.0).abs() < 1e-9);
    }
    // The farthest cell of (0, 0) is the quadrant away from it.
    let ring = cells[0]["polygon"].as_array().unwrap();
    assert!(ring.iter().any(|p| p == &serde_json::json!([14.0, 14.0])));
    assert!(fs::read_to_string(&svg).unwrap().contains("Farthest-point"));
}
