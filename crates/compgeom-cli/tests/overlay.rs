//! `compgeom overlay`, `boolean` and `make-valid` end to end.

use assert_cmd::Command;
use serde_json::Value;
use std::fs;
use tempfile::TempDir;

fn compgeom() -> Command {
    Command::new(env!("CARGO_BIN_EXE_compgeom"))
}

const A: &str = "POLYGON((0 0,4 0,4 4,0 4,0 0))\n";
const B: &str = "POLYGON((2 2,6 2,6 6,2 6,2 2))\n";

fn files() -> (TempDir, std::path::PathBuf, std::path::PathBuf) {
    let dir = TempDir::new().unwrap();
    let a = dir.path().join("a.wkt");
    let b = dir.path().join("b.wkt");
    fs::write(&a, A).unwrap();
    fs::write(&b, B).unwrap();
    (dir, a, b)
}

fn json(args: &[&std::ffi::OsStr]) -> Value {
    let out = compgeom().args(args).assert().success();
    serde_json::from_slice(&out.get_output().stdout).expect("JSON")
}

#[test]
fn boolean_ops_json_areas() {
    let (_d, a, b) = files();
    let area = |op: &str| {
        let v = json(&[
            "boolean".as_ref(),
            op.as_ref(),
            a.as_os_str(),
            b.as_os_str(),
        ]);
        let ring = &v["result"]["coordinates"][0][0];
        let pts: Vec<(f64, f64)> = ring
            .as_array()
            .unwrap()
            .iter()
            .map(|p| (p[0].as_f64().unwrap(), p[1].as_f64().unwrap()))
            .collect();
        (0..pts.len() - 1)
            .map(|i| pts[i].0 * pts[i + 1].1 - pts[i + 1].0 * pts[i].1)
            .sum::<f64>()
            / 2.0
    };
    assert_eq!(area("union"), 28.0);
    assert_eq!(area("intersection"), 4.0);
    assert_eq!(area("difference"), 12.0);
}

#[test]
fn boolean_wkt_output_and_svg() {
    let (d, a, b) = files();
    let svg = d.path().join("x.svg");
    let out = compgeom()
        .args(["boolean", "intersection"])
        .arg(&a)
        .arg(&b)
        .args(["-f", "wkt", "--svg"])
        .arg(&svg)
        .assert()
        .success();
    let text = String::from_utf8(out.get_output().stdout.clone()).unwrap();
    assert_eq!(text.trim(), "MULTIPOLYGON (((2 2, 4 2, 4 4, 2 4, 2 2)))");
    assert!(fs::read_to_string(svg).unwrap().contains("<svg"));
}

/// `-o out.geojson` writes the result as GeoJSON (the format the name says), which
/// `validate` reads back; a format the command cannot write, named by the file's
/// extension, is bad input that names the file, and nothing is written.
#[test]
fn output_format_from_the_file_extension() {
    let (d, a, b) = files();
    let out = d.path().join("x.geojson");
    compgeom()
        .args(["boolean", "intersection"])
        .arg(&a)
        .arg(&b)
        .arg("-o")
        .arg(&out)
        .assert()
        .success();
    let v: Value = serde_json::from_str(&fs::read_to_string(&out).unwrap()).unwrap();
    assert_eq!(v["type"], "MultiPolygon", "{v}");
    let report = json(&["validate".as_ref(), out.as_os_str()]);
    assert_eq!(report["valid"], true, "{report}");
    let faces = d.path().join("faces.geojson");
    compgeom()
        .arg("overlay")
        .arg(&a)
        .arg(&b)
        .arg("-o")
        .arg(&faces)
        .assert()
        .success();
    let v: Value = serde_json::from_str(&fs::read_to_string(&faces).unwrap()).unwrap();
    assert_eq!(v["type"], "FeatureCollection", "{v}");
    let csv = d.path().join("faces.csv");
    // The format is reported before any input is read (or found missing).
    for first in [a.clone(), d.path().join("missing.geojson")] {
        compgeom()
            .arg("overlay")
            .arg(&first)
            .arg(&b)
            .arg("-o")
            .arg(&csv)
            .assert()
            .code(2)
            .stderr(predicates::str::contains(
                "overlay writes json or geojson, not csv",
            ))
            .stderr(predicates::str::contains("faces.csv"));
        assert!(!csv.exists());
    }
    // `validate` writes its report as JSON only, whatever the name asks.
    for format in ["wkt", "geojson"] {
        compgeom()
            .arg("validate")
            .arg(&a)
            .args(["--format", format])
            .assert()
            .code(2)
            .stderr(predicates::str::contains(format!(
                "validate writes json only, not {format}"
            )));
    }
}

/// One input's polygons are united (positive fill rule unless another is asked for:
/// even-odd makes their overlap a hole); other operations need B.
#[test]
fn union_of_one_input_and_missing_b() {
    let (d, a, _b) = files();
    let both = d.path().join("both.wkt");
    fs::write(
        &both,
        format!("GEOMETRYCOLLECTION ({}, {})", A.trim(), B.trim()),
    )
    .unwrap();
    let union = |rule: Option<&str>| {
        let mut args = vec!["boolean", "union", both.to_str().unwrap(), "-f", "wkt"];
        args.extend(rule.map(|r| ["--fill-rule", r]).into_iter().flatten());
        let out = compgeom().args(&args).assert().success();
        String::from_utf8(out.get_output().stdout.clone()).unwrap()
    };
    let united = "MULTIPOLYGON (((0 0, 4 0, 4 2, 6 2, 6 6, 2 6, 2 4, 0 4, 0 0)))";
    assert_eq!(union(None).trim(), united);
    assert_eq!(union(Some("positive")).trim(), united);
    assert_eq!(
        union(Some("evenodd")).trim(),
        "MULTIPOLYGON (((0 0, 4 0, 4 2, 2 2, 2 4, 0 4, 0 0)), ((2 4, 4 4, 4 2, 6 2, 6 6, 2 6, 2 4)))"
    );
    let v = json(&["boolean".as_ref(), "union".as_ref(), both.as_os_str()]);
    assert_eq!(v["fill_rule"], "positive");
    let v = json(&[
        "boolean".as_ref(),
        "union".as_ref(),
        a.as_os_str(),
        both.as_os_str(),
    ]);
    assert_eq!(v["fill_rule"], "evenodd");
    compgeom().args(["boolean", "xor"]).arg(&a).assert().code(2);
}

#[test]
fn overlay_labels_faces() {
    let (_d, a, b) = files();
    let v = json(&[
        "overlay".as_ref(),
        a.as_os_str(),
        b.as_os_str(),
        "--verify".as_ref(),
    ]);
    assert_eq!(v["vertices"], 10);
    assert_eq!(v["edges"], 12);
    assert_eq!(v["verified"], true);
    assert_eq!(v["rounding_suspect_faces"], serde_json::json!([]));
    let faces = v["faces"].as_array().unwrap();
    assert_eq!(faces.len(), 4);
    assert!(faces[0]["polygon"].is_null());
    let both = faces.iter().filter(|f| f["a"] == 0 && f["b"] == 0).count();
    assert_eq!(both, 1);
}

/// The picture colours faces by label: each pair of labels in a colour of its own, named
/// in the legend, where there are few pairs (two squares: three); by which layers
/// contain them, with counts, where there are more (two grids of 30 squares: 91 pairs).
#[test]
fn overlay_picture_colours_faces_by_label() {
    let (d, a, b) = files();
    let svg = d.path().join("o.svg");
    let draw = |a: &std::path::Path, b: &std::path::Path| {
        compgeom()
            .arg("overlay")
            .arg(a)
            .arg(b)
            .arg("--svg")
            .arg(&svg)
            .assert()
            .success();
        fs::read_to_string(&svg).unwrap()
    };
    let picture = draw(&a, &b);
    for pair in ["A 0, B none", "A none, B 0", "A 0, B 0"] {
        assert!(picture.contains(pair), "{pair}");
    }
    assert!(!picture.contains("Some("));
    let grid = |name: &str, offset: f64| {
        let path = d.path().join(name);
        let mut text = String::new();
        for k in 0..30 {
            let (x, y) = (
                f64::from(k % 6) * 2.0 + offset,
                f64::from(k / 6) * 2.0 + offset,
            );
            let (u, v) = (x + 1.5, y + 1.5);
            text += &format!("POLYGON(({x} {y},{u} {y},{u} {v},{x} {v},{x} {y}))\n");
        }
        fs::write(&path, text).unwrap();
        path
    };
    let picture = draw(&grid("ga.wkt", 0.0), &grid("gb.wkt", 0.5));
    for class in [
        "in A and B (30 faces)",
        "in A only (30 faces)",
        "in B only (30 faces)",
        "in neither (40 faces)",
    ] {
        assert!(picture.contains(class), "{class}");
    }
    assert!(!picture.contains("A 0, B"));
}

/// Faces are labelled by input features (a MultiPolygon feature is one, a feature
/// without geometry still counts), and the GeoJSON output carries both features'
/// properties.
#[test]
fn overlay_labels_faces_by_feature_with_their_properties() {
    let d = TempDir::new().unwrap();
    let (a, b) = (d.path().join("a.geojson"), d.path().join("b.geojson"));
    let square = |x: i32| format!("[[[{x},0],[{},0],[{},2],[{x},2],[{x},0]]]", x + 2, x + 2);
    fs::write(
        &a,
        format!(
            r#"{{"type":"FeatureCollection","features":[
            {{"type":"Feature","properties":{{"name":"none"}},"geometry":null}},
            {{"type":"Feature","properties":{{"name":"forest"}},"geometry":{{"type":"MultiPolygon","coordinates":[{},{}]}}}},
            {{"type":"Feature","properties":{{"name":"lake"}},"geometry":{{"type":"Polygon","coordinates":{}}}}}]}}"#,
            square(0),
            square(4),
            square(8)
        ),
    )
    .unwrap();
    fs::write(
        &b,
        r#"{"type":"Feature","properties":{"river":"Rhine"},"geometry":{"type":"Polygon","coordinates":[[[5,-1],[9,-1],[9,1],[5,1],[5,-1]]]}}"#,
    )
    .unwrap();
    let v = json(&[
        "overlay".as_ref(),
        a.as_os_str(),
        b.as_os_str(),
        "-f".as_ref(),
        "geojson".as_ref(),
    ]);
    let mut labels: Vec<String> = v["features"]
        .as_array()
        .unwrap()
        .iter()
        .map(|f| {
            let p = &f["properties"];
            format!(
                "{} {} {} {}",
                p["a"], p["b"], p["a_properties"]["name"], p["b_properties"]["river"]
            )
        })
        .collect();
    labels.sort();
    assert_eq!(
        labels,
        [
            "1 0 \"forest\" \"Rhine\"",
            "1 null \"forest\" null",
            "1 null \"forest\" null",
            "2 0 \"lake\" \"Rhine\"",
            "2 null \"lake\" null",
            "null 0 null \"Rhine\"",
        ],
        "{v}"
    );
    let v = json(&["overlay".as_ref(), a.as_os_str(), b.as_os_str()]);
    let mut a_labels: Vec<String> = v["faces"]
        .as_array()
        .unwrap()
        .iter()
        .map(|f| f["a"].to_string())
        .collect();
    a_labels.sort();
    assert_eq!(a_labels, ["1", "1", "1", "2", "2", "null", "null"], "{v}");
    // WKT input has no properties: each polygon is a feature, its properties null.
    let (_d, wa, wb) = files();
    let v = json(&[
        "overlay".as_ref(),
        wa.as_os_str(),
        wb.as_os_str(),
        "-f".as_ref(),
        "geojson".as_ref(),
    ]);
    let features = v["features"].as_array().unwrap();
    assert_eq!(features.len(), 3, "{v}");
    assert!(features
        .iter()
        .all(|f| f["properties"]["a_properties"].is_null()
            && f["properties"]["b_properties"].is_null()));
}

#[test]
fn make_valid_splits_a_bow_tie_and_bad_input_fails() {
    let d = TempDir::new().unwrap();
    let p = d.path().join("bow.wkt");
    fs::write(&p, "POLYGON((0 0,2 2,2 0,0 2,0 0))\n").unwrap();
    let v = json(&["make-valid".as_ref(), p.as_os_str()]);
    assert_eq!(v["polygons"], 2);
    let bad = d.path().join("bad.wkt");
    fs::write(&bad, "POLYGON((0 0,1 0,0 0))\n").unwrap();
    compgeom().arg("make-valid").arg(&bad).assert().code(2);
}

/// `--per-polygon`: a polygon drawn twice stays (read together by even-odd, it cancels).
#[test]
fn make_valid_per_polygon_keeps_a_polygon_drawn_twice() {
    let d = TempDir::new().unwrap();
    let p = d.path().join("twice.wkt");
    fs::write(
        &p,
        "MULTIPOLYGON(((0 0,2 0,2 2,0 2,0 0)),((0 0,2 0,2 2,0 2,0 0)),((1 1,3 1,3 3,1 3,1 1)))\n",
    )
    .unwrap();
    let together = json(&["make-valid".as_ref(), p.as_os_str()]);
    assert_eq!(together["per_polygon"], false);
    // Even-odd over all rings: the squares drawn twice cancel, the third stays whole
    // (where it overlaps them it is covered three times).
    assert_eq!(together["polygons"], 1);
    let ring = together["result"]["coordinates"][0][0]
        .as_array()
        .unwrap()
        .len();
    assert_eq!(ring, 5, "{together}");
    let each = json(&[
        "make-valid".as_ref(),
        p.as_os_str(),
        "--per-polygon".as_ref(),
    ]);
    assert_eq!(each["per_polygon"], true);
    assert_eq!(each["polygons"], 1);
    // The union of the squares: an eight-corner outline (closed: nine positions).
    let ring = each["result"]["coordinates"][0][0]
        .as_array()
        .unwrap()
        .len();
    assert_eq!(ring, 9, "{each}");
}

#[test]
fn validate_reports_a_crossing() {
    let d = TempDir::new().unwrap();
    let p = d.path().join("bow.wkt");
    fs::write(&p, "POLYGON((0 0,2 2,2 0,0 2,0 0))\n").unwrap();
    let svg = d.path().join("bow.svg");
    let v = json(&[
        "validate".as_ref(),
        p.as_os_str(),
        "--svg".as_ref(),
        svg.as_os_str(),
    ]);
    assert_eq!(v["valid"], false);
    assert_eq!(v["problems"][0]["at"], serde_json::json!([1.0, 1.0]));
    // The picture: the input and a mark per problem, the count in the title.
    let picture = fs::read_to_string(&svg).unwrap();
    assert!(picture.contains("validate: 1 problem(s)"), "{picture}");
    // (The problem's mark and the legend's.)
    assert_eq!(picture.matches("<circle").count(), 1 + 1, "{picture}");
    let (_d, a, _b) = files();
    let v = json(&["validate".as_ref(), a.as_os_str()]);
    assert_eq!(v["valid"], true);
}

/// An open WKT or GeoJSON ring is bad input for every polygon command but `validate`
/// (below): exit 2, the ring named, and no output file written.
#[test]
fn open_rings_are_bad_input_and_nothing_is_written() {
    let d = TempDir::new().unwrap();
    let open_wkt = d.path().join("open.wkt");
    fs::write(&open_wkt, "POLYGON((0 0,4 0,4 4,0 4))\n").unwrap();
    let open_json = d.path().join("open.geojson");
    fs::write(
        &open_json,
        r#"{"type":"Polygon","coordinates":[[[0,0],[4,0],[4,4],[0,4]]]}"#,
    )
    .unwrap();
    let (_d, a, _b) = files();
    let out = d.path().join("out.wkt");
    for open in [&open_wkt, &open_json] {
        let runs: [Vec<&std::ffi::OsStr>; 4] = [
            vec!["boolean".as_ref(), "union".as_ref(), open.as_os_str()],
            vec![
                "boolean".as_ref(),
                "intersection".as_ref(),
                a.as_os_str(),
                open.as_os_str(),
            ],
            vec!["overlay".as_ref(), open.as_os_str(), a.as_os_str()],
            vec!["make-valid".as_ref(), open.as_os_str()],
        ];
        for args in runs {
            // (overlay writes JSON: a WKT output would be the first error.)
            let out = if args[0] == "overlay" {
                out.with_extension("json")
            } else {
                out.clone()
            };
            compgeom()
                .args(&args)
                .arg("-o")
                .arg(&out)
                .assert()
                .code(2)
                .stderr(predicates::str::contains("ring 1 is not closed"));
            assert!(!out.exists(), "{args:?} wrote {out:?}");
        }
    }
}

/// `validate` reports what the other commands reject as a ring: an open ring (at its last
/// position, the rest judged as if it were closed) and a ring of too few points, in
/// both formats, exit 0, and writes its `-o` file.
#[test]
fn validate_reports_open_and_short_rings() {
    let d = TempDir::new().unwrap();
    let wkt = d.path().join("open.wkt");
    fs::write(
        &wkt,
        "POLYGON((0 0,4 0,4 4,0 4),(1 1,2 1,1 2,1 1))\nPOLYGON((5 5,6 5,5 5))\n",
    )
    .unwrap();
    let geojson = d.path().join("open.geojson");
    fs::write(
        &geojson,
        r#"{"type":"MultiPolygon","coordinates":[[[[0,0],[4,0],[4,4],[0,4]],[[1,1],[2,1],[1,2],[1,1]]],[[[5,5],[6,5],[5,5]]]]}"#,
    )
    .unwrap();
    for input in [&wkt, &geojson] {
        let out = d.path().join("report.json");
        compgeom()
            .args([
                "validate".as_ref(),
                input.as_os_str(),
                "-o".as_ref(),
                out.as_os_str(),
            ])
            .assert()
            .success();
        let v: Value = serde_json::from_str(&fs::read_to_string(&out).unwrap()).unwrap();
        assert_eq!(v["valid"], false, "{input:?}: {v}");
        let problems = v["problems"].as_array().unwrap();
        let messages: Vec<&str> = problems
            .iter()
            .map(|p| p["message"].as_str().unwrap())
            .collect();
        assert_eq!(messages.len(), 2, "{input:?}: {messages:?}");
        assert!(
            messages[0].starts_with("polygon 0 exterior: not closed"),
            "{messages:?}"
        );
        assert_eq!(problems[0]["at"], serde_json::json!([0.0, 4.0]));
        assert!(
            messages[1].starts_with("polygon 1 exterior: fewer than 3"),
            "{messages:?}"
        );
        assert_eq!(problems[1]["polygon"], 1);
    }
}

/// `validate` names the polygon and the GeoJSON Feature of each problem: a bow tie as the
/// second polygon of the second feature is polygon 2, feature 1.
#[test]
fn validate_names_the_feature_of_a_problem() {
    let d = TempDir::new().unwrap();
    let input = d.path().join("layer.geojson");
    let square = "[[[0,0],[1,0],[1,1],[0,1],[0,0]]]";
    let bow = "[[[5,5],[7,7],[7,5],[5,7],[5,5]]]";
    let feature = |g: String| format!(r#"{{"type":"Feature","properties":{{}},"geometry":{g}}}"#);
    fs::write(
        &input,
        format!(
            r#"{{"type":"FeatureCollection","features":[{},{}]}}"#,
            feature(format!(r#"{{"type":"Polygon","coordinates":{square}}}"#)),
            feature(format!(
                r#"{{"type":"MultiPolygon","coordinates":[[[[2,0],[3,0],[3,1],[2,1],[2,0]]],{bow}]}}"#
            )),
        ),
    )
    .unwrap();
    let v = json(&["validate".as_ref(), input.as_os_str()]);
    let problem = &v["problems"][0];
    assert!(
        problem["message"].as_str().unwrap().contains("cross"),
        "{v}"
    );
    assert_eq!(
        (&problem["polygon"], &problem["feature"]),
        (&2.into(), &1.into()),
        "{v}"
    );
    // Overlapping polygons are named, the first of them with its feature (the last
    // feature's MultiPolygon starts with an empty polygon, which is none).
    fs::write(
        &input,
        format!(
            r#"{{"type":"FeatureCollection","features":[{},{},{}]}}"#,
            feature(format!(r#"{{"type":"Polygon","coordinates":{square}}}"#)),
            feature(r#"{"type":"Polygon","coordinates":[[[2,0],[6,0],[6,4],[2,4],[2,0]]]}"#.into()),
            feature(
                r#"{"type":"MultiPolygon","coordinates":[[],[[[3,1],[4,1],[4,2],[3,2],[3,1]]]]}"#
                    .into()
            ),
        ),
    )
    .unwrap();
    let v = json(&["validate".as_ref(), input.as_os_str()]);
    let problems = v["problems"].as_array().unwrap();
    assert_eq!(problems.len(), 1, "{v}");
    assert_eq!(
        problems[0]["message"], "interiors of polygon 1 and polygon 2 overlap",
        "{v}"
    );
    assert_eq!(
        (&problems[0]["polygon"], &problems[0]["feature"]),
        (&1.into(), &1.into()),
        "{v}"
    );
}
