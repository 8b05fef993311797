//! The `compgeom` binary end to end: arguments, formats, files, exit codes, demo.
//!
//! Tests at the top level check the CLI's own behaviour (usage errors, missing files,
//! atomic output, help, demo files). Tests in `mod with_io_and_hull` check real results and
//! need the library's readers/writers (`compgeom::io`) and hull (`compgeom::hull`).

use assert_cmd::Command;
use predicates::prelude::*;
use serde_json::Value;
use std::fs;
use std::path::Path;
use tempfile::TempDir;

fn compgeom() -> Command {
    Command::new(env!("CARGO_BIN_EXE_compgeom"))
}

/// A temporary directory holding `name` with `content`.
fn input(name: &str, content: &str) -> (TempDir, std::path::PathBuf) {
    let dir = TempDir::new().unwrap();
    let path = dir.path().join(name);
    fs::write(&path, content).unwrap();
    (dir, path)
}

/// The names of the files in `dir`, sorted.
fn files_in(dir: &Path) -> Vec<String> {
    let mut v: Vec<String> = fs::read_dir(dir)
        .unwrap()
        .map(|e| e.unwrap().file_name().to_string_lossy().into_owned())
        .collect();
    v.sort();
    v
}

/// Vertices of CSV output (`x,y` lines). A polygon ring may be written closed (first vertex
/// repeated at the end); the repeat is dropped.
fn csv_vertices(text: &str) -> Vec<(f64, f64)> {
    let mut v: Vec<(f64, f64)> = text
        .lines()
        .filter(|l| !l.trim().is_empty())
        .map(|l| {
            let (x, y) = l.split_once(',').expect("x,y");
            (x.trim().parse().unwrap(), y.trim().parse().unwrap())
        })
        .collect();
    if v.len() > 3 && v.first() == v.last() {
        v.pop();
    }
    v
}

#[test]
fn usage_errors_exit_2() {
    compgeom()
        .assert()
        .code(2)
        .stderr(predicate::str::contains("Usage"));
    compgeom()
        .arg("hull")
        .assert()
        .code(2)
        .stderr(predicate::str::contains("<INPUT>"));
    compgeom().args(["frobnicate"]).assert().code(2);
    for bad in [
        ["--format", "xml"],
        ["--input-format", "shp"],
        ["--algorithm", "quick"],
    ] {
        compgeom()
            .args(["hull", "-"])
            .args(bad)
            .write_stdin("0,0\n")
            .assert()
            .code(2)
            .stderr(predicate::str::contains("error:"))
            .stderr(predicate::str::contains(bad[1]));
    }
}

#[test]
fn help_documents_the_json_fields() {
    let out = compgeom().args(["hull", "--help"]).assert().success();
    let text = String::from_utf8(out.get_output().stdout.clone()).unwrap();
    for field in [
        "hull",
        "algorithm",
        "input_points",
        "keep_collinear",
        "verified",
    ] {
        assert!(
            text.contains(&format!("  {field} ")),
            "--help lacks {field}:\n{text}"
        );
    }
    for flag in [
        "--input-format",
        "--format",
        "--output",
        "--svg",
        "--verify",
        "--keep-collinear",
    ] {
        assert!(text.contains(flag), "--help lacks {flag}");
    }
    compgeom()
        .arg("--version")
        .assert()
        .success()
        .stdout(predicate::str::contains("compgeom"));
}

#[test]
fn missing_input_is_bad_input_and_writes_nothing() {
    let dir = TempDir::new().unwrap();
    let out = dir.path().join("out.json");
    let svg = dir.path().join("out.svg");
    compgeom()
        .arg("hull")
        .arg(dir.path().join("nope.csv"))
        .arg("-o")
        .arg(&out)
        .arg("--svg")
        .arg(&svg)
        .assert()
        .code(2)
        .stdout("")
        .stderr(predicate::str::starts_with("error: "))
        .stderr(predicate::str::contains("nope.csv"));
    assert!(
        files_in(dir.path()).is_empty(),
        "{:?}",
        files_in(dir.path())
    );
}

#[test]
fn input_that_is_not_text_is_bad_input() {
    let (_dir, path) = input("points.csv", "");
    fs::write(&path, [0xff, 0xfe, 0x00, 0x31]).unwrap();
    compgeom()
        .arg("hull")
        .arg(&path)
        .assert()
        .code(2)
        .stderr(predicate::str::contains("error:").and(predicate::str::contains("UTF-8")));
}

#[test]
fn unwritable_output_exits_1() {
    let (dir, path) = input("points.csv", "0,0\n1,0\n0,1\n");
    let out = dir.path().join("no-such-dir").join("out.json");
    compgeom()
        .arg("hull")
        .arg(&path)
        .arg("-o")
        .arg(&out)
        .assert()
        .code(1)
        .stderr(predicate::str::starts_with("error: "))
        .stderr(predicate::str::contains("out.json"));
    assert!(!out.exists());
}

#[test]
fn output_file_is_written_whole_without_leftovers() {
    let (dir, path) = input("points.csv", "0,0\n1,0\n0,1\n");
    let out = dir.path().join("out.json");
    let svg = dir.path().join("pic.svg");
    // An existing target is replaced, not appended to.
    fs::write(
        &out,
        "old content that is longer than the new one ".repeat(100),
    )
    .unwrap();
    compgeom()
        .arg("hull")
        .arg(&path)
        .arg("-o")
        .arg(&out)
        .arg("--svg")
        .arg(&svg)
        .assert()
        .success()
        .stdout("");
    let text = fs::read_to_string(&out).unwrap();
    let v: Value = serde_json::from_str(&text).expect("valid JSON");
    assert!(v.get("hull").is_some_and(Value::is_array));
    assert!(text.ends_with('\n'));
    let svg_text = fs::read_to_string(&svg).unwrap();
    assert!(svg_text.starts_with("<svg") && svg_text.trim_end().ends_with("</svg>"));
    // No temporary files left beside the outputs.
    assert_eq!(files_in(dir.path()), ["out.json", "pic.svg", "points.csv"]);
    #[cfg(unix)]
    {
        use std::os::unix::fs::PermissionsExt as _;
        let mode = fs::metadata(&svg).unwrap().permissions().mode() & 0o777;
        assert_eq!(mode, 0o644, "new files are readable like other files");
    }
}

/// `-o` naming a named pipe (or `/dev/null`, a device) writes into it: the output is not
/// renamed over it, which replaced the pipe or device itself with a regular file (run as
/// root, `-o /dev/null` did that to the machine's `/dev/null`).
#[cfg(unix)]
#[test]
fn output_to_a_pipe_goes_into_the_pipe() {
    use std::os::unix::fs::FileTypeExt as _;
    let (dir, path) = input("points.csv", "0,0\n1,0\n0,1\n");
    let fifo = dir.path().join("pipe");
    let made = std::process::Command::new("mkfifo").arg(&fifo).status();
    if !made.is_ok_and(|s| s.success()) {
        eprintln!("skipped: mkfifo is not available");
        return;
    }
    // The reader opens the pipe (blocking until the command opens it to write) and reads
    // to the end.
    let reading = fifo.clone();
    let reader = std::thread::spawn(move || fs::read_to_string(reading).unwrap());
    compgeom()
        .arg("hull")
        .arg(&path)
        .arg("-o")
        .arg(&fifo)
        .timeout(std::time::Duration::from_secs(60))
        .assert()
        .success();
    // Checked before joining: were the pipe replaced, the reader would wait forever.
    let still_a_pipe = fs::symlink_metadata(&fifo).unwrap().file_type().is_fifo();
    assert!(still_a_pipe, "the pipe was replaced by a file");
    let text = reader.join().unwrap();
    let v: Value = serde_json::from_str(&text).expect("valid JSON through the pipe");
    assert!(v.get("hull").is_some_and(Value::is_array));
    assert_eq!(files_in(dir.path()), ["pipe", "points.csv"]);
}

#[test]
fn dash_output_means_stdout() {
    compgeom()
        .args(["hull", "-", "-o", "-", "--input-format", "csv"])
        .write_stdin("0,0\n")
        .assert()
        .success()
        .stdout(predicate::str::contains("\"algorithm\":\"default\""));
}

#[test]
fn demo_writes_a_gallery() {
    let dir = TempDir::new().unwrap();
    let out = dir.path().join("gallery");
    let assert = compgeom()
        .arg("demo")
        .arg("--out")
        .arg(&out)
        .assert()
        .success();
    let index = out.join("index.html");
    let stdout = String::from_utf8(assert.get_output().stdout.clone()).unwrap();
    assert_eq!(stdout.trim(), index.display().to_string());
    let html = fs::read_to_string(&index).unwrap();
    assert!(html.contains("Chapter 1 — convex hull"));
    let svgs: Vec<String> = files_in(&out)
        .into_iter()
        .filter(|f| f.ends_with(".svg"))
        .collect();
    assert!(svgs.len() >= 5, "{svgs:?}");
    for f in &svgs {
        assert!(
            html.contains(&format!("src=\"{f}\"")),
            "{f} not in the gallery"
        );
        let svg = fs::read_to_string(out.join(f)).unwrap();
        assert!(
            svg.starts_with("<svg") && svg.trim_end().ends_with("</svg>"),
            "{f}"
        );
        assert!(!svg.contains("NaN"), "{f}");
    }
    for fact in [
        "<th>n</th>",
        "<th>h</th>",
        "<th>time</th>",
        "slow",
        "andrew",
    ] {
        assert!(html.contains(fact), "gallery lacks {fact}");
    }
    // Deterministic: a second run writes the same pictures.
    let again = dir.path().join("again");
    compgeom()
        .arg("demo")
        .arg("--out")
        .arg(&again)
        .assert()
        .success();
    for f in &svgs {
        assert_eq!(
            fs::read(out.join(f)).unwrap(),
            fs::read(again.join(f)).unwrap(),
            "{f} differs between runs"
        );
    }
}

/// These need the merged `compgeom::io` (readers, writers, format detection) and
/// `compgeom::hull` (convex hull, verifier).
mod with_io_and_hull {
    use super::*;

    /// Run `compgeom hull ARGS` on `path` and parse the JSON output.
    fn hull_json(path: &Path, args: &[&str]) -> Value {
        let out = compgeom()
            .arg("hull")
            .arg(path)
            .args(args)
            .assert()
            .success();
        serde_json::from_slice(&out.get_output().stdout).expect("JSON output")
    }

    /// The hull array as (x, y) pairs.
    fn hull_of(v: &Value) -> Vec<(f64, f64)> {
        v["hull"]
            .as_array()
            .expect("hull array")
            .iter()
            .map(|p| (p[0].as_f64().unwrap(), p[1].as_f64().unwrap()))
            .collect()
    }

    /// A square with an interior point, a point on the bottom edge and a duplicate corner.
    const SQUARE_CSV: &str = "# a square\n2,2\n0,0\n1,1\n2,0\n1,0\n0,2\n0,0\n";
    /// Clockwise from the lexicographically smallest point.
    const SQUARE_HULL: [(f64, f64); 4] = [(0.0, 0.0), (0.0, 2.0), (2.0, 2.0), (2.0, 0.0)];

    #[test]
    fn csv_to_json_clockwise_from_smallest() {
        let (_d, path) = input("square.csv", SQUARE_CSV);
        let v = hull_json(&path, &[]);
        assert_eq!(hull_of(&v), SQUARE_HULL);
        assert_eq!(v["algorithm"], "default");
        assert_eq!(v["input_points"], 7);
        assert_eq!(v["keep_collinear"], false);
        assert!(v.get("verified").is_none());
        for alg in ["andrew", "slow"] {
            let v = hull_json(&path, &["--algorithm", alg]);
            assert_eq!(hull_of(&v), SQUARE_HULL, "{alg}");
            assert_eq!(v["algorithm"], alg);
        }
    }

    #[test]
    fn keep_collinear_keeps_edge_points() {
        let (_d, path) = input("square.csv", SQUARE_CSV);
        let v = hull_json(
            &path,
            &["--algorithm", "andrew", "--keep-collinear", "--verify"],
        );
        assert_eq!(
            hull_of(&v),
            [(0.0, 0.0), (0.0, 2.0), (2.0, 2.0), (2.0, 0.0), (1.0, 0.0)]
        );
        assert_eq!(v["keep_collinear"], true);
        assert_eq!(v["verified"], true);
    }

    #[test]
    fn wkt_geojson_and_stdin_inputs() {
        let (_d, wkt) = input(
            "pts.wkt",
            "MULTIPOINT ((2 2), (0 0), (1 1), (2 0), (0 2))\n",
        );
        assert_eq!(hull_of(&hull_json(&wkt, &[])), SQUARE_HULL);
        let gj = r#"{"type":"FeatureCollection","features":[
            {"type":"Feature","properties":{},"geometry":{"type":"MultiPoint","coordinates":[[2,2],[0,0],[1,1]]}},
            {"type":"Feature","properties":{},"geometry":{"type":"Point","coordinates":[2,0]}},
            {"type":"Feature","properties":{},"geometry":{"type":"Point","coordinates":[0,2]}}]}"#;
        let (_d2, gj) = input("pts.geojson", gj);
        let v = hull_json(&gj, &[]);
        assert_eq!(hull_of(&v), SQUARE_HULL);
        assert_eq!(v["input_points"], 5);

        // Standard input, format detected from the content or given.
        for (text, fmt) in [
            (SQUARE_CSV, None),
            ("MULTIPOINT ((2 2), (0 0), (2 0), (0 2))", Some("wkt")),
            ("2 2\n0 0\n2 0\n0 2\n", Some("csv")),
        ] {
            let mut cmd = compgeom();
            cmd.args(["hull", "-"]);
            if let Some(f) = fmt {
                cmd.args(["--input-format", f]);
            }
            let out = cmd.write_stdin(text).assert().success();
            let v: Value = serde_json::from_slice(&out.get_output().stdout).unwrap();
            assert_eq!(hull_of(&v), SQUARE_HULL, "{text}");
        }
    }

    #[test]
    fn each_output_format() {
        let (_d, path) = input("square.csv", SQUARE_CSV);
        let run = |fmt: &str| {
            let out = compgeom()
                .arg("hull")
                .arg(&path)
                .args(["--format", fmt])
                .assert()
                .success();
            String::from_utf8(out.get_output().stdout.clone()).unwrap()
        };
        // CSV: the hull vertices in order, one per line.
        assert_eq!(csv_vertices(&run("csv")), SQUARE_HULL);
        // WKT: a polygon.
        let wkt = run("wkt");
        assert!(wkt.trim_start().starts_with("POLYGON"), "{wkt}");
        for (x, y) in SQUARE_HULL {
            assert!(wkt.contains(&format!("{x} {y}")) || wkt.contains(&format!("{x:?} {y:?}")));
        }
        // GeoJSON: a polygon whose closed ring has the hull's vertices.
        let gj: Value = serde_json::from_str(&run("geojson")).unwrap();
        assert_eq!(gj["type"], "Polygon");
        let ring: Vec<(f64, f64)> = gj["coordinates"][0]
            .as_array()
            .unwrap()
            .iter()
            .map(|p| (p[0].as_f64().unwrap(), p[1].as_f64().unwrap()))
            .collect();
        assert_eq!(ring.len(), 5);
        assert_eq!(ring[0], ring[4]);
        let mut got = ring[..4].to_vec();
        let mut want = SQUARE_HULL.to_vec();
        got.sort_by(|a, b| a.partial_cmp(b).unwrap());
        want.sort_by(|a, b| a.partial_cmp(b).unwrap());
        assert_eq!(got, want);
    }

    /// Without `--format`, the `-o` file's extension names the format (in any case);
    /// `--format` wins over it; another extension, or standard output, gets JSON.
    #[test]
    fn output_format_from_the_file_extension() {
        let (dir, path) = input("square.csv", SQUARE_CSV);
        let write = |name: &str, extra: &[&str]| {
            let out = dir.path().join(name);
            compgeom()
                .arg("hull")
                .arg(&path)
                .arg("-o")
                .arg(&out)
                .args(extra)
                .assert()
                .success()
                .stdout("");
            fs::read_to_string(&out).unwrap()
        };
        let gj: Value = serde_json::from_str(&write("hull.geojson", &[])).unwrap();
        assert_eq!(gj["type"], "Polygon");
        let gj: Value = serde_json::from_str(&write("HULL.GeoJSON", &[])).unwrap();
        assert_eq!(gj["type"], "Polygon");
        assert!(write("hull.wkt", &[]).starts_with("POLYGON"));
        assert_eq!(csv_vertices(&write("hull.csv", &[])), SQUARE_HULL);
        for (name, extra) in [
            ("hull.json", &[][..]),
            ("hull.txt", &[]),
            ("hull.geojson", &["--format", "json"]),
        ] {
            let v: Value = serde_json::from_str(&write(name, extra)).unwrap();
            assert_eq!(hull_of(&v), SQUARE_HULL, "{name} {extra:?}");
        }
        // `--format` over the extension, the other way too.
        assert!(write("hull.json", &["--format", "wkt"]).starts_with("POLYGON"));
    }

    #[test]
    fn small_hulls_take_smaller_shapes() {
        let wkt_of = |text: &str| {
            let out = compgeom()
                .args(["hull", "-", "--input-format", "csv", "--format", "wkt"])
                .write_stdin(text.to_string())
                .assert()
                .success();
            String::from_utf8(out.get_output().stdout.clone()).unwrap()
        };
        assert!(wkt_of("3,4\n3,4\n").trim().starts_with("POINT"));
        assert!(wkt_of("0,0\n1,1\n2,2\n").trim().starts_with("LINESTRING"));
        let out = compgeom()
            .args(["hull", "-", "--input-format", "csv"])
            .write_stdin("# nothing\n")
            .assert()
            .success();
        let v: Value = serde_json::from_slice(&out.get_output().stdout).unwrap();
        assert_eq!(v["hull"], serde_json::json!([]));
        assert_eq!(v["input_points"], 0);
    }

    #[test]
    fn coordinates_round_trip_exactly() {
        let pts = [
            (0.1, 0.1),
            (1e200, 0.1),
            (0.1, 1e200),
            (0.30000000000000004, 0.2),
        ];
        let text: String = pts.iter().map(|(x, y)| format!("{x:?},{y:?}\n")).collect();
        let (_d, path) = input("exact.csv", &text);
        let v = hull_json(&path, &["--verify"]);
        let hull = hull_of(&v);
        let want: [(f64, f64); 3] = [(0.1, 0.1), (0.1, 1e200), (1e200, 0.1)];
        assert_eq!(hull.len(), 3);
        for (got, want) in hull.iter().zip(want) {
            assert_eq!(got.0.to_bits(), want.0.to_bits());
            assert_eq!(got.1.to_bits(), want.1.to_bits());
        }
        // The same through CSV output.
        let out = compgeom()
            .arg("hull")
            .arg(&path)
            .args(["-f", "csv"])
            .assert()
            .success();
        let csv = String::from_utf8(out.get_output().stdout.clone()).unwrap();
        assert_eq!(csv_vertices(&csv), want);
    }

    #[test]
    fn output_file_and_svg() {
        let (dir, path) = input("square.csv", SQUARE_CSV);
        let out = dir.path().join("hull.json");
        let svg = dir.path().join("hull.svg");
        compgeom()
            .arg("hull")
            .arg(&path)
            .arg("-o")
            .arg(&out)
            .arg("--svg")
            .arg(&svg)
            .arg("--verify")
            .assert()
            .success()
            .stdout("");
        let v: Value = serde_json::from_str(&fs::read_to_string(&out).unwrap()).unwrap();
        assert_eq!(hull_of(&v), SQUARE_HULL);
        let svg = fs::read_to_string(&svg).unwrap();
        assert!(svg.contains("n = 7, h = 4"), "title with n and h");
        assert!(svg.contains("class=\"legend\""));
        for label in [">0</text>", ">1</text>", ">2</text>", ">3</text>"] {
            assert!(svg.contains(label), "vertex label {label}");
        }
        assert!(!svg.contains(">4</text>"));
    }

    #[test]
    fn malformed_line_names_file_and_line() {
        let (dir, path) = input("bad.csv", "0,0\n1,1\n1,x\n2,2\n");
        let out = dir.path().join("out.json");
        compgeom()
            .arg("hull")
            .arg(&path)
            .arg("-o")
            .arg(&out)
            .assert()
            .code(2)
            .stdout("")
            .stderr(predicate::str::starts_with("error: "))
            .stderr(predicate::str::contains("bad.csv:3"));
        assert!(!out.exists(), "no output file on error");
        assert_eq!(files_in(dir.path()), ["bad.csv"]);
    }

    #[test]
    fn non_finite_coordinates_are_bad_input() {
        for text in ["0,0\nNaN,1\n", "0,0\n1,inf\n", "0,0\n-inf,1\n"] {
            compgeom()
                .args(["hull", "-", "--input-format", "csv"])
                .write_stdin(text)
                .assert()
                .code(2)
                .stdout("")
                .stderr(predicate::str::starts_with("error: "));
        }
    }

    #[test]
    fn undetectable_format_is_bad_input() {
        let (_d, path) = input("points.dat", "{ this is not geometry ]\n");
        compgeom()
            .arg("hull")
            .arg(&path)
            .assert()
            .code(2)
            .stderr(predicate::str::starts_with("error: "));
    }

    #[test]
    fn demo_hulls_are_real() {
        let dir = TempDir::new().unwrap();
        compgeom()
            .arg("demo")
            .arg("--out")
            .arg(dir.path())
            .assert()
            .success();
        let html = fs::read_to_string(dir.path().join("index.html")).unwrap();
        // Table rows: caption, n, h, …
        let h_of = |caption_start: &str| -> usize {
            let row = html
                .lines()
                .find(|l| l.starts_with(&format!("<tr><td>{caption_start}")))
                .unwrap_or_else(|| panic!("no row {caption_start}"));
            let cells: Vec<&str> = row
                .split("<td>")
                .skip(1)
                .map(|c| c.split("</td>").next().unwrap())
                .collect();
            cells[2].parse().unwrap()
        };
        assert_eq!(h_of("9×9 integer grid"), 4);
        assert_eq!(h_of("the same grid"), 32);
        assert_eq!(h_of("64 points on a circle"), 64);
        let disc = h_of("200 random points");
        assert!((8..200).contains(&disc), "{disc}");
        assert!(h_of("the book&apos;s slow hull") >= 3);
    }
}

/// `compgeom range` and `compgeom window` (book chapters 5 and 10).
mod range_commands {
    use super::*;

    fn json(args: &[&str]) -> Value {
        let out = compgeom()
            .args(args)
            .assert()
            .success()
            .get_output()
            .stdout
            .clone();
        serde_json::from_slice(&out).unwrap()
    }

    fn lists(v: &Value) -> Vec<Vec<u64>> {
        v.as_array()
            .unwrap()
            .iter()
            .map(|l| {
                l.as_array()
                    .unwrap()
                    .iter()
                    .map(|i| i.as_u64().unwrap())
                    .collect()
            })
            .collect()
    }

    const POINTS: &str = "x,y\n0,0\n1,1\n1,1\n2,0\n3,3\n1,2\n";
    const RECTS: &str = "# xmin,ymin,xmax,ymax\n0,0,1,1\n2,2,1,1\n1,0,3,3\n1,1,1,1\n";

    #[test]
    fn every_structure_gives_the_same_closed_answers() {
        let dir = TempDir::new().unwrap();
        let p = dir.path().join("p.csv");
        let q = dir.path().join("q.csv");
        fs::write(&p, POINTS).unwrap();
        fs::write(&q, RECTS).unwrap();
        let want = vec![vec![0, 1, 2], vec![], vec![1, 2, 3, 4, 5], vec![1, 2]];
        for s in ["layered", "rangetree", "kdtree"] {
            let v = json(&[
                "range",
                p.to_str().unwrap(),
                "--queries",
                q.to_str().unwrap(),
                "--structure",
                s,
                "--verify",
            ]);
            assert_eq!(lists(&v["results"]), want, "{s}");
            assert_eq!(v["structure"], s);
            assert_eq!(v["input_points"], 6);
            assert_eq!(v["queries"], 4);
            assert_eq!(v["verified"], true);
            let c = json(&[
                "range",
                p.to_str().unwrap(),
                "--queries",
                q.to_str().unwrap(),
                "--structure",
                s,
                "--count",
            ]);
            assert_eq!(c["counts"], serde_json::json!([3, 0, 5, 2]));
            assert!(c.get("results").is_none());
        }
    }

    #[test]
    fn knn_svg_and_geometry_output() {
        let dir = TempDir::new().unwrap();
        let p = dir.path().join("p.csv");
        let at = dir.path().join("at.csv");
        let svg = dir.path().join("k.svg");
        fs::write(&p, POINTS).unwrap();
        fs::write(&at, "1,1\n3,3\n").unwrap();
        let v = json(&[
            "range",
            p.to_str().unwrap(),
            "--knn",
            "3",
            "--at",
            at.to_str().unwrap(),
            "--verify",
            "--svg",
            svg.to_str().unwrap(),
        ]);
        // From (1,1): the two copies of (1,1), then (1,2) at distance 1 (index 5).
        assert_eq!(lists(&v["results"]), vec![vec![1, 2, 5], vec![4, 5, 1]]);
        assert!(fs::read_to_string(&svg).unwrap().contains("<svg"));
        let q = dir.path().join("q.csv");
        fs::write(&q, "0,0,0.5,0.5\n").unwrap();
        let ksvg = dir.path().join("kd.svg");
        compgeom()
            .args([
                "range",
                p.to_str().unwrap(),
                "--queries",
                q.to_str().unwrap(),
                "-f",
                "wkt",
                "--structure",
                "kdtree",
                "--svg",
                ksvg.to_str().unwrap(),
            ])
            .assert()
            .success()
            .stdout("MULTIPOINT ((0 0))\n");
        // So few points make one leaf bucket: no splitting lines, and no empty legend entry.
        assert!(!fs::read_to_string(&ksvg)
            .unwrap()
            .contains("kd-tree splitting lines"));
        let many = dir.path().join("many.csv");
        let grid: String = (0..64).map(|i| format!("{},{}\n", i % 8, i / 8)).collect();
        fs::write(&many, grid).unwrap();
        compgeom()
            .args([
                "range",
                many.to_str().unwrap(),
                "--queries",
                q.to_str().unwrap(),
                "--structure",
                "kdtree",
                "--svg",
                ksvg.to_str().unwrap(),
            ])
            .assert()
            .success();
        let picture = fs::read_to_string(&ksvg).unwrap();
        let lines = picture
            .split("kd-tree splitting lines")
            .nth(1)
            .and_then(|rest| rest.split("</g>").next())
            .unwrap_or_default();
        assert!(lines.contains("<line"), "splitting lines drawn: {picture}");
        // --count prints numbers: a geometry format is refused, and nothing is written.
        let out = dir.path().join("out.wkt");
        compgeom()
            .args([
                "range",
                many.to_str().unwrap(),
                "--queries",
                q.to_str().unwrap(),
                "--count",
                "-f",
                "wkt",
                "-o",
                out.to_str().unwrap(),
            ])
            .assert()
            .code(2)
            .stderr(predicate::str::contains("--count"));
        assert!(!out.exists());
    }

    #[test]
    fn bad_range_input_exits_2_with_file_and_line() {
        let dir = TempDir::new().unwrap();
        let p = dir.path().join("p.csv");
        let q = dir.path().join("q.csv");
        fs::write(&p, POINTS).unwrap();
        fs::write(&q, "0,0,1,1\n0,0,1\n").unwrap();
        compgeom()
            .args([
                "range",
                p.to_str().unwrap(),
                "--queries",
                q.to_str().unwrap(),
            ])
            .assert()
            .code(2)
            .stderr(predicate::str::contains("q.csv:2"));
        fs::write(&q, "0,0,1,nan\n").unwrap();
        compgeom()
            .args([
                "range",
                p.to_str().unwrap(),
                "--queries",
                q.to_str().unwrap(),
            ])
            .assert()
            .code(2)
            .stderr(predicate::str::contains("q.csv:1"));
        let bad = dir.path().join("bad.csv");
        fs::write(&bad, "0,0\n1,x\n").unwrap();
        compgeom()
            .args([
                "range",
                bad.to_str().unwrap(),
                "--queries",
                q.to_str().unwrap(),
            ])
            .assert()
            .code(2)
            .stderr(predicate::str::contains("bad.csv:2"));
        // --queries or --knn is required; --knn needs --at.
        compgeom()
            .args(["range", p.to_str().unwrap()])
            .assert()
            .code(2);
        compgeom()
            .args(["range", p.to_str().unwrap(), "--knn", "2"])
            .assert()
            .code(2);
        compgeom()
            .args([
                "range",
                p.to_str().unwrap(),
                "--queries",
                "/no/such/rects.csv",
            ])
            .assert()
            .code(2)
            .stderr(predicate::str::contains("/no/such/rects.csv"));
    }

    #[test]
    fn window_finds_segments_crossing_without_endpoints_inside() {
        let dir = TempDir::new().unwrap();
        let s = dir.path().join("s.csv");
        let q = dir.path().join("q.csv");
        // 0 cuts the window's corner, 1 passes through it, 2 is outside, 3 touches a corner,
        // 4 is a point inside.
        fs::write(
            &s,
            "1,2.5,2.5,1\n-5,0.5,5,0.5\n5,5,6,7\n2,2,3,3\n0.5,0.5,0.5,0.5\n",
        )
        .unwrap();
        fs::write(&q, "0,0,2,2\n10,10,9,9\n").unwrap();
        let v = json(&[
            "window",
            s.to_str().unwrap(),
            "--queries",
            q.to_str().unwrap(),
            "--verify",
        ]);
        assert_eq!(lists(&v["results"]), vec![vec![0, 1, 3, 4], vec![]]);
        assert_eq!(v["structure"], "segment-tree");
        assert_eq!(v["input_segments"], 5);
        // Axis-parallel input through the interval-tree structure.
        fs::write(&s, "-5,1,5,1\n1,-5,1,5\n3,3,4,3\n").unwrap();
        let svg = dir.path().join("w.svg");
        let v = json(&[
            "window",
            s.to_str().unwrap(),
            "--queries",
            q.to_str().unwrap(),
            "--structure",
            "interval-tree",
            "--verify",
            "--svg",
            svg.to_str().unwrap(),
        ]);
        assert_eq!(lists(&v["results"]), vec![vec![0, 1], vec![]]);
        assert!(fs::read_to_string(&svg)
            .unwrap()
            .contains("reported segments"));
        compgeom()
            .args([
                "window",
                s.to_str().unwrap(),
                "--queries",
                q.to_str().unwrap(),
                "-f",
                "csv",
            ])
            .assert()
            .success()
            .stdout(predicate::str::contains("-5,1,5,1"));
    }

    #[test]
    fn bad_window_input_exits_2() {
        let dir = TempDir::new().unwrap();
        let s = dir.path().join("s.csv");
        let q = dir.path().join("q.csv");
        fs::write(&q, "0,0,1,1\n").unwrap();
        fs::write(&s, "0,0,2,2\n0,2,2,0\n").unwrap();
        compgeom()
            .args([
                "window",
                s.to_str().unwrap(),
                "--queries",
                q.to_str().unwrap(),
            ])
            .assert()
            .code(2)
            .stderr(predicate::str::contains("segments 0 and 1 cross"));
        compgeom()
            .args([
                "window",
                s.to_str().unwrap(),
                "--queries",
                q.to_str().unwrap(),
                "--structure",
                "interval-tree",
            ])
            .assert()
            .code(2)
            .stderr(predicate::str::contains("neither horizontal nor vertical"));
        fs::write(&s, "0,0,1,1\n0,0,1\n").unwrap();
        compgeom()
            .args([
                "window",
                s.to_str().unwrap(),
                "--queries",
                q.to_str().unwrap(),
            ])
            .assert()
            .code(2)
            .stderr(predicate::str::contains("s.csv:2"));
        fs::write(&s, "0,0,1,1\n").unwrap();
        fs::write(&q, "0,0,1,1,5\n").unwrap();
        compgeom()
            .args([
                "window",
                s.to_str().unwrap(),
                "--queries",
                q.to_str().unwrap(),
            ])
            .assert()
            .code(2)
            .stderr(predicate::str::contains("q.csv:1"));
    }

    #[test]
    fn demo_has_the_range_and_window_pictures() {
        let dir = TempDir::new().unwrap();
        compgeom()
            .args(["demo", "--out"])
            .arg(dir.path())
            .assert()
            .success();
        let files = files_in(dir.path());
        for f in [
            "range-kdtree.svg",
            "range-layered.svg",
            "range-knn.svg",
            "window-segments.svg",
        ] {
            assert!(files.contains(&f.to_string()), "{f} missing from {files:?}");
        }
        let index = fs::read_to_string(dir.path().join("index.html")).unwrap();
        assert!(index.contains("range searching and windowing"));
        let svg = fs::read_to_string(dir.path().join("window-segments.svg")).unwrap();
        assert!(
            svg.contains("reported segments (16)"),
            "the long segment and corner-crossing ones"
        );
    }
}

/// Chapter 4 commands: `halfplanes`, `lp`, `enclose`, `cast`.
mod lp_commands {
    use super::*;

    fn json(args: &[&str]) -> Value {
        let out = compgeom()
            .args(args)
            .assert()
            .success()
            .get_output()
            .stdout
            .clone();
        serde_json::from_slice(&out).expect("JSON")
    }

    fn pairs(v: &Value) -> Vec<(f64, f64)> {
        v.as_array()
            .unwrap()
            .iter()
            .map(|p| (p[0].as_f64().unwrap(), p[1].as_f64().unwrap()))
            .collect()
    }

    const TRIANGLE: &str =
        "# x >= 0, y >= 0, x + y <= 2, redundant x <= 5\n-1 0 0\n0 -1 0\n1,1,2\n1 0 5\n";

    #[test]
    fn halfplanes_polygon_json_and_svg() {
        let (dir, path) = input("t.txt", TRIANGLE);
        let svg = dir.path().join("r.svg");
        let v = json(&[
            "halfplanes",
            path.to_str().unwrap(),
            "--svg",
            svg.to_str().unwrap(),
        ]);
        assert_eq!(v["kind"], "polygon");
        assert_eq!(
            pairs(&v["vertices"]),
            vec![(0.0, 0.0), (2.0, 0.0), (0.0, 2.0)]
        );
        assert_eq!(v["constraints"], serde_json::json!([1, 2, 0]));
        assert_eq!(v["input_constraints"], 4);
        let text = fs::read_to_string(&svg).unwrap();
        assert!(
            text.starts_with("<") && text.contains("<svg") && text.trim_end().ends_with("</svg>")
        );
    }

    #[test]
    fn halfplanes_every_kind() {
        let cases = [
            ("1 0 0\n-1 0 -1\n", "empty"),
            ("1 1 0\n-1 1 0\n0 -1 0\n", "point"),
            ("1 0 0\n-1 0 0\n0 1 1\n0 -1 1\n", "segment"),
            ("1 0 0\n-1 0 0\n0 1 0\n", "ray"),
            ("1 0 0\n-1 0 0\n", "line"),
            ("0 1 0\n", "unbounded"),
        ];
        for (text, kind) in cases {
            let (_dir, path) = input("h.txt", text);
            let v = json(&["halfplanes", path.to_str().unwrap()]);
            assert_eq!(v["kind"], kind, "{text}");
        }
        // Geometry formats refuse unbounded results (exit 2) and print bounded ones.
        let (_dir, path) = input("h.txt", "0 1 0\n");
        compgeom()
            .args(["halfplanes", path.to_str().unwrap(), "--format", "wkt"])
            .assert()
            .code(2);
        let (_dir, path) = input("t.txt", TRIANGLE);
        compgeom()
            .args(["halfplanes", path.to_str().unwrap(), "--format", "wkt"])
            .assert()
            .success()
            .stdout(predicate::str::starts_with("POLYGON"));
    }

    #[test]
    fn halfplanes_bad_input_names_file_and_line() {
        let (_dir, path) = input("bad.txt", "1 0 1\n\n1 x 2\n");
        compgeom()
            .args(["halfplanes", path.to_str().unwrap()])
            .assert()
            .code(2)
            .stderr(predicate::str::contains("bad.txt:3"));
        let (_dir, path) = input("short.txt", "1 0\n");
        compgeom()
            .args(["halfplanes", path.to_str().unwrap()])
            .assert()
            .code(2)
            .stderr(predicate::str::contains("short.txt:1"));
        let (_dir, path) = input("nan.txt", "1 0 nan\n");
        compgeom()
            .args(["halfplanes", path.to_str().unwrap()])
            .assert()
            .code(2)
            .stderr(predicate::str::contains("nan.txt:1"));
    }

    #[test]
    fn lp_optimal_unbounded_infeasible() {
        let (dir, path) = input("t.txt", TRIANGLE);
        let p = path.to_str().unwrap();
        let v = json(&["lp", p, "--maximize", "1,1", "--verify"]);
        assert_eq!(v["status"], "optimal");
        assert_eq!(v["verified"], true);
        // The optimal edge from (0, 2) to (2, 0): the lexicographically smallest end.
        assert_eq!(pairs(&serde_json::json!([v["point"]])), vec![(0.0, 2.0)]);
        assert_eq!(v["value"], 2.0);
        let v = json(&["lp", p, "--maximize=-1,-1", "--seed", "5"]);
        assert_eq!(pairs(&serde_json::json!([v["point"]])), vec![(0.0, 0.0)]);
        let (_d, open) = input("open.txt", "0 1 0\n");
        let v = json(&["lp", open.to_str().unwrap(), "--maximize=1,-1"]);
        assert_eq!(v["status"], "unbounded");
        let ray = &v["ray"];
        assert!(ray[0].as_f64().unwrap() - ray[1].as_f64().unwrap() > 0.0);
        assert!(ray[1].as_f64().unwrap() <= 0.0);
        let (_d, none) = input("none.txt", "1 0 0\n-1 0 -1\n0 1 4\n");
        let v = json(&["lp", none.to_str().unwrap(), "--maximize", "0,1"]);
        assert_eq!(v["status"], "infeasible");
        assert_eq!(v["certificate"], serde_json::json!([0, 1]));
        assert!(v.get("point").is_none());
        let svg = dir.path().join("lp.svg");
        compgeom()
            .args(["lp", p, "--maximize", "1,2", "--svg", svg.to_str().unwrap()])
            .assert()
            .success();
        assert!(fs::read_to_string(&svg).unwrap().contains("optimum"));
    }

    #[test]
    fn lp_bad_input() {
        let (_dir, path) = input("t.txt", TRIANGLE);
        let p = path.to_str().unwrap();
        // Zero objective, bad objective, wrong number of fields.
        compgeom()
            .args(["lp", p, "--maximize", "0,0"])
            .assert()
            .code(2);
        compgeom()
            .args(["lp", p, "--maximize", "1,x"])
            .assert()
            .code(2)
            .stderr(predicate::str::contains("--maximize"));
        compgeom()
            .args(["lp", p, "--maximize", "1,2,3,4"])
            .assert()
            .code(2)
            .stderr(predicate::str::contains("t.txt:2"));
        compgeom().args(["lp", p]).assert().code(2);
    }
}

/// `enclose` (chapter 4).
mod lp_enclose_command {
    use super::*;

    #[test]
    fn enclose_json_svg_and_errors() {
        let (dir, path) = input("p.csv", "0,0\n4,0\n2,1\n1,-1\n");
        let svg = dir.path().join("d.svg");
        let out = compgeom()
            .args([
                "enclose",
                path.to_str().unwrap(),
                "--verify",
                "--svg",
                svg.to_str().unwrap(),
            ])
            .assert()
            .success()
            .get_output()
            .stdout
            .clone();
        let v: Value = serde_json::from_slice(&out).unwrap();
        assert_eq!(v["center"], serde_json::json!([2.0, 0.0]));
        assert_eq!(v["radius"], 2.0);
        assert_eq!(v["support"].as_array().unwrap().len(), 2);
        assert_eq!(v["verified"], true);
        assert!(fs::read_to_string(&svg).unwrap().contains("support points"));
        let (_d, bad) = input("bad.csv", "0,0\n1,zz\n");
        compgeom()
            .args(["enclose", bad.to_str().unwrap()])
            .assert()
            .code(2)
            .stderr(predicate::str::contains("bad.csv:2"));
        let (_d, empty) = input("empty.csv", "# nothing\n");
        compgeom()
            .args(["enclose", empty.to_str().unwrap()])
            .assert()
            .code(2);
    }
}

/// `lp` in three dimensions (chapter 4).
mod lp_dim_command {
    use super::*;

    #[test]
    fn lp_in_three_dimensions() {
        let cube = "1 0 0 1\n-1 0 0 0\n0 1 0 1\n0 -1 0 0\n0 0 1 1\n0 0 -1 0\n";
        let (_dir, path) = input("cube.txt", cube);
        let out = compgeom()
            .args(["lp", path.to_str().unwrap(), "--maximize", "1,1,1"])
            .assert()
            .success()
            .get_output()
            .stdout
            .clone();
        let v: Value = serde_json::from_slice(&out).unwrap();
        assert_eq!(v["status"], "optimal");
        assert_eq!(v["point"], serde_json::json!([1.0, 1.0, 1.0]));
        assert_eq!(v["value"], 3.0);
        compgeom()
            .args([
                "lp",
                path.to_str().unwrap(),
                "--maximize",
                "1,1,1",
                "--svg",
                "x.svg",
            ])
            .assert()
            .code(2);
    }
}

/// `cast` (chapter 4).
mod lp_cast_command {
    use super::*;

    const CUBE: &str = "OFF\n8 6 0\n0 0 0\n1 0 0\n1 1 0\n0 1 0\n0 0 1\n1 0 1\n1 1 1\n0 1 1\n\
4 0 3 2 1\n4 4 5 6 7\n4 0 1 5 4\n4 1 2 6 5\n4 2 3 7 6\n4 3 0 4 7\n";

    #[test]
    fn cube_json_svg_and_errors() {
        let (dir, path) = input("cube.off", CUBE);
        let svg = dir.path().join("c.svg");
        let out = compgeom()
            .args([
                "cast",
                path.to_str().unwrap(),
                "--svg",
                svg.to_str().unwrap(),
                "--facet",
                "1",
            ])
            .assert()
            .success()
            .get_output()
            .stdout
            .clone();
        let v: Value = serde_json::from_slice(&out).unwrap();
        assert_eq!(v["castable"], true);
        assert_eq!(v["input_facets"], 6);
        let tops = v["top_facets"].as_array().unwrap();
        assert_eq!(tops.len(), 6);
        assert_eq!(tops[1]["facet"], 1);
        assert_eq!(tops[1]["direction"], serde_json::json!([0.0, 0.0, 1.0]));
        assert!(fs::read_to_string(&svg)
            .unwrap()
            .contains("removal directions"));
        // Open mesh: exit 2 naming the file.
        let open = CUBE.replace("8 6 0", "8 5 0").replace("4 3 0 4 7\n", "");
        let (_d, bad) = input("open.off", &open);
        compgeom()
            .args(["cast", bad.to_str().unwrap()])
            .assert()
            .code(2)
            .stderr(predicate::str::contains("open.off"));
        let (_d, bad) = input("bad.off", "OFF\n1 1 0\n0 0 0\n3 0 1 2\n");
        compgeom()
            .args(["cast", bad.to_str().unwrap()])
            .assert()
            .code(2)
            .stderr(predicate::str::contains("bad.off:4"));
    }
}

mod delaunay_commands {
    use super::*;

    fn run_json(args: &[&str], path: &Path) -> Value {
        let out = compgeom().args(args).arg(path).output().unwrap();
        assert!(
            out.status.success(),
            "{}",
            String::from_utf8_lossy(&out.stderr)
        );
        serde_json::from_slice(&out.stdout).unwrap()
    }

    #[test]
    fn delaunay_json_fields_and_duplicates() {
        let (_d, p) = input("pts.csv", "0 0\n1 0\n0 1\n1 1.5\n1 0\n");
        for (alg, order) in [
            ("default", "biased"),
            ("incremental", "biased"),
            ("incremental", "uniform"),
        ] {
            let args = ["delaunay", "--verify", "--algorithm", alg];
            let v = run_json(&[&args[..], &["--insertion-order", order]].concat(), &p);
            assert_eq!(v["vertices"].as_array().unwrap().len(), 4);
            assert_eq!(v["triangles"].as_array().unwrap().len(), 2);
            assert_eq!(v["input_to_vertex"], serde_json::json!([0, 1, 2, 3, 1]));
            assert_eq!(v["verified"], true);
            assert_eq!(v["algorithm"], alg);
            // The diagonal is (1, 2): (0,0) is outside the circle through the others.
            let tris: Vec<Vec<u64>> = serde_json::from_value(v["triangles"].clone()).unwrap();
            assert!(tris.iter().all(|t| t.contains(&1) && t.contains(&2)));
        }
    }

    #[test]
    fn delaunay_collinear_input_is_not_an_error() {
        let (_d, p) = input("line.csv", "0 0\n1 1\n2 2\n");
        let v = run_json(&["delaunay", "--verify"], &p);
        assert_eq!(v["triangles"].as_array().unwrap().len(), 0);
        assert!(v["note"].as_str().unwrap().contains("collinear"));
    }

    #[test]
    fn delaunay_geojson_and_svg() {
        let (d, p) = input("pts.csv", "0 0\n4 0\n0 3\n4 3\n2 1\n");
        let svg = d.path().join("t.svg");
        let out = compgeom()
            .args(["delaunay", "-f", "geojson", "--circumcircles", "2", "--svg"])
            .arg(&svg)
            .arg(&p)
            .output()
            .unwrap();
        assert!(out.status.success());
        let v: Value = serde_json::from_slice(&out.stdout).unwrap();
        assert_eq!(v["type"], "MultiPolygon");
        assert_eq!(v["coordinates"].as_array().unwrap().len(), 4);
        let text = fs::read_to_string(&svg).unwrap();
        assert!(text.contains("circumcircles"));
    }

    #[test]
    fn delaunay_constraints_and_polygon() {
        let (d, p) = input("p.csv", "0 0\n4 0\n4 4\n0 4\n2 1\n2 3\n");
        let segs = d.path().join("s.csv");
        fs::write(&segs, "0,0,4,4\n").unwrap();
        let out = compgeom()
            .args(["delaunay", "--verify", "--constraints"])
            .arg(&segs)
            .arg(&p)
            .output()
            .unwrap();
        assert!(
            out.status.success(),
            "{}",
            String::from_utf8_lossy(&out.stderr)
        );
        let v: Value = serde_json::from_slice(&out.stdout).unwrap();
        assert_eq!(v["constraints"], serde_json::json!([[0, 2]]));
        // Crossing constraints: split at the crossing (2, 2), a Steiner vertex.
        fs::write(&segs, "0,0,4,4\n4,0,0,4\n").unwrap();
        let out = compgeom()
            .args(["delaunay", "--verify", "--constraints"])
            .arg(&segs)
            .arg(&p)
            .assert()
            .success();
        let v: Value = serde_json::from_slice(&out.get_output().stdout).unwrap();
        assert_eq!(v["vertices"][6], serde_json::json!([2.0, 2.0]));
        let poly = d.path().join("poly.wkt");
        fs::write(
            &poly,
            "POLYGON ((0 0, 12 0, 12 12, 0 12, 0 0), (2 2, 4 2, 4 4, 2 4, 2 2))",
        )
        .unwrap();
        let (_e, empty) = input("empty.csv", "");
        let out = compgeom()
            .args(["delaunay", "--verify", "--polygon"])
            .arg(&poly)
            .arg(&empty)
            .output()
            .unwrap();
        assert!(
            out.status.success(),
            "{}",
            String::from_utf8_lossy(&out.stderr)
        );
        let v: Value = serde_json::from_slice(&out.stdout).unwrap();
        assert_eq!(v["triangles"].as_array().unwrap().len(), 8);
        assert_eq!(v["constraints"].as_array().unwrap().len(), 8);
    }

    #[test]
    fn interpolate_heights_and_null_outside() {
        let (d, s) = input("s.csv", "0,0,0\n4,0,4\n0,4,8\n4,4,12\n");
        let q = d.path().join("q.csv");
        fs::write(&q, "1 1\n5 5\n2 2\n").unwrap();
        let out = compgeom()
            .args(["interpolate", "--verify", "--at"])
            .arg(&q)
            .arg(&s)
            .output()
            .unwrap();
        assert!(
            out.status.success(),
            "{}",
            String::from_utf8_lossy(&out.stderr)
        );
        let v: Value = serde_json::from_slice(&out.stdout).unwrap();
        assert_eq!(v["heights"], serde_json::json!([3.0, null, 6.0]));
    }

    #[test]
    fn demo_has_the_delaunay_section() {
        let dir = TempDir::new().unwrap();
        compgeom()
            .arg("demo")
            .arg("--out")
            .arg(dir.path())
            .assert()
            .success();
        let html = fs::read_to_string(dir.path().join("index.html")).unwrap();
        assert!(html.contains("Chapter 9"));
        for f in [
            "delaunay-disc.svg",
            "delaunay-book.svg",
            "delaunay-cocircular.svg",
            "delaunay-grid.svg",
            "delaunay-cdt.svg",
        ] {
            let svg = fs::read_to_string(dir.path().join(f)).unwrap();
            assert!(svg.contains("Delaunay"), "{f}");
        }
    }

    #[test]
    fn delaunay_bad_input_exits_2() {
        let (_d, p) = input("bad.csv", "0 0\n1 nan\n");
        compgeom().arg("delaunay").arg(&p).assert().code(2);
    }
}

/// `compgeom voronoi` (book chapter 7).
mod voronoi_commands {
    use super::*;

    fn run_json(args: &[&str], content: &str) -> Value {
        let (_dir, path) = input("points.csv", content);
        let out = compgeom()
            .arg("voronoi")
            .arg(&path)
            .args(args)
            .assert()
            .success();
        serde_json::from_slice(&out.get_output().stdout).unwrap()
    }

    #[test]
    fn square_with_centre_and_duplicate() {
        let v = run_json(
            &["--clip", "0,0,4,4", "--verify"],
            "0,0\n4,0\n0,4\n4,4\n2,2\n0,0\n",
        );
        assert_eq!(v["verified"], true);
        let cells = v["cells"].as_array().unwrap();
        // One cell per distinct point, in input order; the duplicate maps to cell 0.
        let sites: Vec<u64> = cells.iter().map(|c| c["site"].as_u64().unwrap()).collect();
        assert_eq!(sites, vec![0, 1, 2, 3, 4]);
        assert_eq!(v["input_to_cell"], serde_json::json!([0, 1, 2, 3, 4, 0]));
        // The centre's cell is the diamond (2,0),(4,2),(2,4),(0,2), counter-clockwise.
        let centre: Vec<(f64, f64)> = cells[4]["polygon"]
            .as_array()
            .unwrap()
            .iter()
            .map(|p| (p[0].as_f64().unwrap(), p[1].as_f64().unwrap()))
            .collect();
        assert_eq!(centre.len(), 4);
        for corner in [(2.0, 0.0), (4.0, 2.0), (2.0, 4.0), (0.0, 2.0)] {
            assert!(centre.contains(&corner), "{centre:?}");
        }
        assert_eq!(v["vertices"].as_array().unwrap().len(), 4);
        assert_eq!(v["edges"].as_array().unwrap().len(), 8);
        assert_eq!(v["algorithm"], "default");
        assert_eq!(v["input_points"], 6);
    }

    #[test]
    fn cocircular_points_share_one_vertex() {
        let v = run_json(
            &["--algorithm", "fortune", "--verify"],
            "0,0\n2,0\n2,2\n0,2\n",
        );
        assert_eq!(v["vertices"], serde_json::json!([[1.0, 1.0]]));
        assert_eq!(v["vertex_sites"], serde_json::json!([[0, 1, 2, 3]]));
    }

    #[test]
    fn clip_polygon_geojson_and_svg() {
        let (dir, poly) = input("region.wkt", "POLYGON ((-1 -1, 5 -1, 2 6, -1 -1))");
        let pts = dir.path().join("p.csv");
        fs::write(&pts, "0,0\n3,0\n1,2\n2,1\n").unwrap();
        let svg = dir.path().join("v.svg");
        let out = compgeom()
            .arg("voronoi")
            .arg(&pts)
            .arg("--clip-polygon")
            .arg(&poly)
            .args(["--format", "geojson", "--verify", "--svg"])
            .arg(&svg)
            .assert()
            .success();
        let v: Value = serde_json::from_slice(&out.get_output().stdout).unwrap();
        assert_eq!(v["type"], "FeatureCollection");
        assert_eq!(v["features"].as_array().unwrap().len(), 4);
        let text = fs::read_to_string(&svg).unwrap();
        assert!(text.starts_with("<svg") && text.contains("Voronoi"));
    }

    #[test]
    fn bad_clip_and_bad_points_exit_2() {
        let (_dir, path) = input("p.csv", "0,0\n1,1\n");
        compgeom()
            .arg("voronoi")
            .arg(&path)
            .args(["--clip", "0,0,1"])
            .assert()
            .code(2)
            .stderr(predicate::str::contains("--clip"));
        compgeom()
            .arg("voronoi")
            .arg(&path)
            .args(["--clip", "2,0,1,1"])
            .assert()
            .code(2);
        let (_d2, poly) = input("r.wkt", "POLYGON ((0 0, 4 0, 4 0, 0 0))");
        compgeom()
            .arg("voronoi")
            .arg(&path)
            .arg("--clip-polygon")
            .arg(&poly)
            .assert()
            .code(2);
    }

    #[test]
    fn collinear_points_have_no_vertices() {
        let v = run_json(&["--verify"], "0,0\n1,1\n2,2\n3,3\n");
        assert_eq!(v["vertices"].as_array().unwrap().len(), 0);
        let edges = v["edges"].as_array().unwrap();
        assert_eq!(edges.len(), 3);
        assert!(edges
            .iter()
            .all(|e| e["vertices"] == serde_json::json!([null, null])));
    }

    #[test]
    fn help_documents_voronoi_json() {
        compgeom()
            .args(["voronoi", "--help"])
            .assert()
            .success()
            .stdout(predicate::str::contains("input_to_cell"));
    }
}
