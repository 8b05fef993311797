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

/// Run `compgeom ARGS.. --svg FILE` in `dir` and return the SVG text.
fn svg_of(dir: &TempDir, args: &[&str]) -> String {
    let svg = dir.path().join("out.svg");
    Command::new(env!("CARGO_BIN_EXE_compgeom"))
        .args(args)
        .arg("--svg")
        .arg(&svg)
        .assert()
        .success();
    fs::read_to_string(&svg).unwrap()
}

#[test]
fn lp_pictures_show_the_certificate_and_the_ray() {
    let dir = TempDir::new().unwrap();
    let infeasible = dir.path().join("inf.txt");
    // x <= 0 and x >= 1 contradict; the other three are innocent.
    fs::write(&infeasible, "1 0 0\n-1 0 -1\n0 1 3\n0 -1 3\n1 1 5\n").unwrap();
    let text = svg_of(
        &dir,
        &["lp", infeasible.to_str().unwrap(), "--maximize", "1,0"],
    );
    assert!(
        text.contains("certificate: constraints 0, 1 contradict"),
        "{text}"
    );
    let unbounded = dir.path().join("unb.txt");
    fs::write(&unbounded, "1 0 1\n").unwrap();
    let text = svg_of(
        &dir,
        &["lp", unbounded.to_str().unwrap(), "--maximize", "0,1"],
    );
    assert!(
        text.contains("ray: the objective grows without bound"),
        "{text}"
    );
    assert!(!text.contains("certificate"), "{text}");
}

/// A cube taken out through its top face has exactly one removal direction (straight up):
/// the picture must say "point", as the exact castability does (`interior: false`), not
/// show a rounded sliver as a polygon. The pyramid's base has a whole square of directions.
#[test]
fn cast_picture_kind_is_exact() {
    let dir = TempDir::new().unwrap();
    let cube = dir.path().join("cube.off");
    fs::write(
        &cube,
        "OFF\n8 6 0\n0 0 0\n1 0 0\n1 1 0\n0 1 0\n0 0 1\n1 0 1\n1 1 1\n0 1 1\n\
         4 0 3 2 1\n4 4 5 6 7\n4 0 1 5 4\n4 1 2 6 5\n4 2 3 7 6\n4 3 0 4 7\n",
    )
    .unwrap();
    let pyramid = dir.path().join("pyramid.off");
    fs::write(
        &pyramid,
        "OFF\n5 5 0\n0 0 0\n2 0 0\n2 2 0\n0 2 0\n1 1 1\n\
         4 0 3 2 1\n3 0 1 4\n3 1 2 4\n3 2 3 4\n3 3 0 4\n",
    )
    .unwrap();
    for (mesh, facet, kind) in [
        (&cube, "1", "(point)"),
        (&cube, "2", "(point)"),
        (&pyramid, "0", "(polygon)"),
        (&pyramid, "1", "(point)"),
    ] {
        let text = svg_of(&dir, &["cast", mesh.to_str().unwrap(), "--facet", facet]);
        let title = format!("removal directions for top facet {facet}: d = n + x·u + y·v {kind}");
        assert!(text.contains(&title), "{mesh:?} facet {facet}: {text}");
    }
}

/// A row with the wrong number of fields: exit 2, the line named, the expected form spelt
/// for the dimension, and no output file.
#[test]
fn malformed_rows_name_the_line_and_the_form() {
    let dir = TempDir::new().unwrap();
    let out = dir.path().join("out.json");
    for (content, objective, form) in [
        (
            "1 0 1\n1 2\n",
            "1,0",
            "expected 3 numbers (a b c, meaning a·x + b·y <= c), found 2",
        ),
        (
            "1 0 0 1\n1 0 1\n",
            "0,0,1",
            "expected 4 numbers (a1 a2 a3 c,",
        ),
        (
            "1 1\n1 1 1\n",
            "1",
            "expected 2 numbers (a c, meaning a·x <= c), found 3",
        ),
    ] {
        let path = dir.path().join("bad.txt");
        fs::write(&path, content).unwrap();
        let r = Command::new(env!("CARGO_BIN_EXE_compgeom"))
            .arg("lp")
            .arg(&path)
            .args(["--maximize", objective, "-o"])
            .arg(&out)
            .assert()
            .code(2);
        let err = String::from_utf8_lossy(&r.get_output().stderr).to_string();
        assert!(err.contains(form), "{err}");
        assert!(err.contains("bad.txt:2)"), "{err}");
        assert!(!out.exists());
    }
}

/// Unbounded regions have no WKT/GeoJSON/CSV form: exit 2 with a sentence that reads.
#[test]
fn unbounded_regions_refuse_geometry_formats() {
    let dir = TempDir::new().unwrap();
    for (content, what) in [
        ("1 0 1\n0 1 1\n", "is an unbounded region (unbounded)"),
        ("1 0 1\n-1 0 -1\n0 1 1\n", "is a ray (unbounded)"),
        ("1 0 1\n-1 0 -1\n", "is a line (unbounded)"),
    ] {
        let path = dir.path().join("h.txt");
        fs::write(&path, content).unwrap();
        let r = Command::new(env!("CARGO_BIN_EXE_compgeom"))
            .arg("halfplanes")
            .arg(&path)
            .args(["--format", "wkt"])
            .assert()
            .code(2);
        let err = String::from_utf8_lossy(&r.get_output().stderr).to_string();
        assert!(err.contains(what), "{err}");
    }
}

/// Broken surfaces: exit 2, `error: ... (file:line)` naming the offending face's line, and
/// no output file.
#[test]
fn broken_meshes_name_the_face_line() {
    let dir = TempDir::new().unwrap();
    let out = dir.path().join("out.json");
    let cube = "OFF\n8 6 0\n0 0 0\n1 0 0\n1 1 0\n0 1 0\n0 0 1\n1 0 1\n1 1 1\n0 1 1\n\
                4 0 3 2 1\n4 4 5 6 7\n4 0 1 5 4\n4 1 2 6 5\n4 2 3 7 6\n4 3 0 4 7\n";
    for (text, want, line) in [
        // Face 1 (line 12) wound the wrong way: face 2 (line 13) then uses edge 4-5 in the
        // same direction.
        (
            cube.replace("4 4 5 6 7\n", "4 7 6 5 4\n"),
            "used in the same direction by faces 1 and 2",
            13,
        ),
        // Vertex 7 lifted: face 1 (line 12) is not planar.
        (
            cube.replace("0 1 1\n", "0 1 1.5\n"),
            "face 1 is not planar",
            12,
        ),
        // No top face: the first face with an unmatched edge is now face 1 (the side
        // 0 1 5 4, line 12), whose edge 5-4 the top face would have matched.
        (
            cube.replace("8 6 0", "8 5 0").replace("4 4 5 6 7\n", ""),
            "edge 5-4 of face 1 has no opposite face",
            12,
        ),
    ] {
        let path = dir.path().join("bad.off");
        fs::write(&path, text).unwrap();
        let r = Command::new(env!("CARGO_BIN_EXE_compgeom"))
            .arg("cast")
            .arg(&path)
            .arg("-o")
            .arg(&out)
            .assert()
            .code(2);
        let err = String::from_utf8_lossy(&r.get_output().stderr).to_string();
        assert!(err.starts_with("error: "), "{err}");
        assert!(err.contains(want), "{err}");
        let tail = format!("bad.off:{line})");
        assert!(err.trim_end().ends_with(&tail), "{err}");
        assert!(!out.exists());
    }
}

/// `enclose` on an input with no points: exit 2 and the file is named.
#[test]
fn enclose_of_nothing_names_the_file() {
    let dir = TempDir::new().unwrap();
    let path = dir.path().join("nothing.csv");
    fs::write(&path, "# only a comment\n").unwrap();
    let r = Command::new(env!("CARGO_BIN_EXE_compgeom"))
        .arg("enclose")
        .arg(&path)
        .assert()
        .code(2);
    let err = String::from_utf8_lossy(&r.get_output().stderr).to_string();
    assert!(err.contains("nothing.csv: no points"), "{err}");
}
