//! Boolean operations against the polygon-clipping, martinez, iOverlay and Clipper2 fixture suites in the
//! shared cases folder (see its README): for every case and operation the output must be
//! valid and the area of its symmetric difference with the expected result must be
//! ≈ 0 (relative tolerance 1e-9 of the squared coordinate magnitude).
use compgeom::overlay::{boolean, boolean_with, BooleanOp, BooleanOptions, FillRule};
use compgeom::{MultiPolygon, Point2, Polygon};
use serde_json::Value;
use std::path::{Path, PathBuf};

mod common;
use common::{area, assert_valid_with, existing_cases_dir};

fn ring(v: &Value) -> Vec<Point2> {
    v.as_array()
        .unwrap()
        .iter()
        .map(|p| Point2::new(p[0].as_f64().unwrap(), p[1].as_f64().unwrap()))
        .collect()
}

fn polygon(v: &Value) -> Option<Polygon> {
    let rings: Vec<Vec<Point2>> = v.as_array()?.iter().map(ring).collect();
    let mut it = rings.into_iter();
    Some(Polygon::new(it.next()?, it.collect()))
}

/// A GeoJSON geometry (or a Feature holding one) as polygons.
fn geometry(v: &Value) -> MultiPolygon {
    let g = if v["type"] == "Feature" {
        &v["geometry"]
    } else {
        v
    };
    let c = &g["coordinates"];
    match g["type"].as_str() {
        Some("Polygon") => MultiPolygon(polygon(c).into_iter().collect()),
        Some("MultiPolygon") => MultiPolygon(
            c.as_array()
                .map(|ps| ps.iter().filter_map(polygon).collect())
                .unwrap_or_default(),
        ),
        _ => MultiPolygon::default(),
    }
}

fn read(path: &Path) -> Value {
    serde_json::from_str(&std::fs::read_to_string(path).unwrap()).unwrap()
}

fn scale(ms: &[&MultiPolygon]) -> f64 {
    ms.iter()
        .flat_map(|m| m.0.iter().flat_map(|p| p.rings().flatten()))
        .fold(1e-300f64, |s, p| s.max(p.x.abs()).max(p.y.abs()))
}

const POSITIVE: BooleanOptions = BooleanOptions {
    fill_rule: FillRule::Positive,
    keep_collinear: false,
};

/// `got` equals `want` as a point set: area(got △ want) ≈ 0; `got` is valid.
fn compare(name: &str, got: &MultiPolygon, want: &MultiPolygon) -> Result<(), String> {
    assert_valid_with(got, true);
    let diff = boolean_with(got, want, BooleanOp::Xor, &POSITIVE).map_err(|e| e.to_string())?;
    let s = scale(&[got, want]);
    let err = area(&diff).abs();
    if err > 1e-9 * s * s {
        return Err(format!(
            "{name}: area of symmetric difference {err} (got area {}, want {})",
            area(got),
            area(want)
        ));
    }
    Ok(())
}

const NONZERO: BooleanOptions = BooleanOptions {
    fill_rule: FillRule::NonZero,
    keep_collinear: false,
};

/// polygon-clipping's reading of a polygon set: each ring by the non-zero rule, each
/// polygon its exterior minus its holes, the polygons united.
fn norm(m: &MultiPolygon) -> compgeom::Result<MultiPolygon> {
    let empty = MultiPolygon::default();
    let mut parts = Vec::new();
    for p in &m.0 {
        let ring = |r: &Vec<Point2>| {
            boolean_with(
                &MultiPolygon(vec![Polygon::new(r.clone(), vec![])]),
                &empty,
                BooleanOp::Union,
                &NONZERO,
            )
        };
        let mut shell = ring(&p.exterior)?;
        for h in &p.holes {
            shell = boolean(&shell, &ring(h)?, BooleanOp::Difference)?;
        }
        parts.extend(shell.0);
    }
    boolean_with(&MultiPolygon(parts), &empty, BooleanOp::Union, &POSITIVE)
}

/// The N-argument operations of polygon-clipping, each argument read by [`norm`].
fn apply_n(op: BooleanOp, args: &[MultiPolygon]) -> compgeom::Result<MultiPolygon> {
    let mut acc = norm(&args[0])?;
    match op {
        BooleanOp::Difference => {
            let all: Vec<Polygon> = args[1..].iter().flat_map(|m| m.0.clone()).collect();
            let rest = norm(&MultiPolygon(all))?;
            boolean(&acc, &rest, op)
        }
        _ => {
            for m in &args[1..] {
                acc = boolean(&acc, &norm(m)?, op)?;
            }
            Ok(acc)
        }
    }
}

/// Cases left out, with the reason (none: every polygon-clipping case passes).
const PC_EXCLUDED: &[(&str, &str)] = &[];

/// Expected results left out of the martinez-style suites, with the reason.
const MARTINEZ_EXCLUDED: &[(&str, &str, &str)] = &[
    (
        "martinez/genericTestCases/fatal4.geojson",
        "union",
        "upstream marks this expected result as wrong (comment in the file); the \
         rust-geo-booleanop copy of the case, with corrected output, passes",
    ),
    (
        "martinez/genericTestCases/fatal4.geojson",
        "intersection",
        "upstream marks this expected result as wrong (it is a two-point sliver)",
    ),
];

#[test]
fn polygon_clipping_suite() {
    let Some(dir) = existing_cases_dir() else {
        println!("skipped: shared cases not found");
        return;
    };
    let dir = dir.join("polygon-clipping");
    let mut entries: Vec<PathBuf> = std::fs::read_dir(&dir)
        .unwrap()
        .map(|e| e.unwrap().path())
        .filter(|p| p.is_dir())
        .collect();
    entries.sort();
    let mut failures = Vec::new();
    let mut run = 0;
    for case in entries {
        let name = case.file_name().unwrap().to_string_lossy().to_string();
        if PC_EXCLUDED.iter().any(|(n, _)| *n == name) {
            continue;
        }
        let args: Vec<MultiPolygon> = read(&case.join("args.geojson"))["features"]
            .as_array()
            .unwrap()
            .iter()
            .map(geometry)
            .collect();
        for (file, op) in [
            ("union", BooleanOp::Union),
            ("intersection", BooleanOp::Intersection),
            ("difference", BooleanOp::Difference),
            ("xor", BooleanOp::Xor),
        ] {
            let want = if case.join(format!("{file}.geojson")).exists() {
                geometry(&read(&case.join(format!("{file}.geojson"))))
            } else if case.join("all.geojson").exists() {
                geometry(&read(&case.join("all.geojson")))
            } else {
                continue;
            };
            run += 1;
            let label = format!("{name}/{file}");
            match apply_n(op, &args) {
                Ok(got) => {
                    if let Err(e) = compare(&label, &got, &want) {
                        failures.push(e);
                    }
                }
                Err(e) => failures.push(format!("{label}: error {e}")),
            }
        }
    }
    println!("polygon-clipping: {run} operations checked");
    assert!(run > 30);
    assert!(
        failures.is_empty(),
        "{} failures:\n{}",
        failures.len(),
        failures.join("\n")
    );
}

#[test]
fn martinez_suites() {
    let Some(dir) = existing_cases_dir() else {
        println!("skipped: shared cases not found");
        return;
    };
    let mut failures = Vec::new();
    let mut run = 0;
    for suite in [
        "martinez/genericTestCases",
        "rust-geo-booleanop/generic_test_cases",
    ] {
        let d = dir.join(suite);
        let Ok(rd) = std::fs::read_dir(&d) else {
            println!("skipped: {suite} not found");
            continue;
        };
        let mut files: Vec<PathBuf> = rd.map(|e| e.unwrap().path()).collect();
        files.sort();
        for f in files
            .into_iter()
            .filter(|f| f.extension().is_some_and(|e| e == "geojson"))
        {
            let v = read(&f);
            let feats = v["features"].as_array().unwrap();
            let (a, b) = (geometry(&feats[0]), geometry(&feats[1]));
            for exp in &feats[2..] {
                let opname = exp["properties"]["operation"].as_str().unwrap_or("");
                let (x, y, op) = match opname {
                    "intersection" => (&a, &b, BooleanOp::Intersection),
                    "union" => (&a, &b, BooleanOp::Union),
                    "xor" => (&a, &b, BooleanOp::Xor),
                    "diff" => (&a, &b, BooleanOp::Difference),
                    "diff_ba" => (&b, &a, BooleanOp::Difference),
                    _ => continue,
                };
                let rel = f.strip_prefix(&dir).unwrap().to_string_lossy().to_string();
                if MARTINEZ_EXCLUDED
                    .iter()
                    .any(|(c, o, _)| *c == rel && *o == opname)
                {
                    continue;
                }
                run += 1;
                let label = format!("{rel}/{opname}");
                let want = geometry(exp);
                // Martinez reads every ring of an operand even-odd.
                match boolean(x, y, op) {
                    Ok(got) => {
                        if let Err(e) = compare_loose(&label, &got, &want) {
                            failures.push(e);
                        }
                    }
                    Err(e) => failures.push(format!("{label}: error {e}")),
                }
            }
        }
    }
    println!("martinez-style suites: {run} operations checked");
    assert!(run > 20);
    assert!(
        failures.is_empty(),
        "{} failures:\n{}",
        failures.len(),
        failures.join("\n")
    );
}

/// As [`compare`], but the expected rings are not oriented (martinez outputs holes in
/// either orientation): the expected set is read even-odd.
fn compare_loose(name: &str, got: &MultiPolygon, want: &MultiPolygon) -> Result<(), String> {
    assert_valid_with(got, true);
    let opts = BooleanOptions::default();
    // Drop the degenerate slivers (fewer than 3 distinct points) some expected outputs hold.
    let distinct = |r: &Vec<Point2>| {
        let mut k: Vec<(u64, u64)> = r.iter().map(|p| (p.x.to_bits(), p.y.to_bits())).collect();
        k.sort_unstable();
        k.dedup();
        k.len() >= 3
    };
    let want = MultiPolygon(
        want.0
            .iter()
            .filter(|p| distinct(&p.exterior))
            .map(|p| {
                Polygon::new(
                    p.exterior.clone(),
                    p.holes.iter().filter(|h| distinct(h)).cloned().collect(),
                )
            })
            .collect(),
    );
    let want = boolean_with(&want, &MultiPolygon::default(), BooleanOp::Union, &opts)
        .map_err(|e| format!("{name}: expected output unreadable: {e}"))?;
    compare(name, got, &want)
}

/// iOverlay cases left out, with the reason.
const IOVERLAY_EXCLUDED: &[(&str, &str)] = &[
    (
        "test_144.json",
        "expected values never executed upstream (MANIFEST: unverified)",
    ),
    (
        "test_147.json",
        "expected values never executed upstream (MANIFEST: unverified)",
    ),
    (
        "test_153.json",
        "expected values never executed upstream (MANIFEST: unverified)",
    ),
    (
        "test_156.json",
        "expected values never executed upstream (MANIFEST: unverified)",
    ),
];

fn io_contour(v: &Value) -> Vec<Point2> {
    v.as_array()
        .unwrap()
        .iter()
        .map(|p| Point2::new(p[0].as_f64().unwrap(), p[1].as_f64().unwrap()))
        .collect()
}

/// One alternative of an iOverlay expectation: shapes of contours (outer first).
fn io_shapes(v: &Value) -> MultiPolygon {
    MultiPolygon(
        v.as_array()
            .unwrap()
            .iter()
            .filter_map(|shape| {
                let mut cs = shape.as_array()?.iter().map(io_contour);
                Some(Polygon::new(cs.next()?, cs.collect()))
            })
            .collect(),
    )
}

fn perimeter(m: &MultiPolygon) -> f64 {
    m.0.iter()
        .flat_map(|p| p.rings())
        .map(|r| {
            (0..r.len())
                .map(|i| {
                    let (a, b) = (r[i], r[(i + 1) % r.len()]);
                    (b.x - a.x).hypot(b.y - a.y)
                })
                .sum::<f64>()
        })
        .sum()
}

/// iOverlay's integer suite: each operand is a flat list of contours read with the case's
/// fill rule (0 even-odd, 1 non-zero, rings as given). iOverlay snaps crossings to the
/// integer grid, so a result matches an expected alternative when the area of their
/// symmetric difference is at most half a unit times the sum of both perimeters (every
/// snapped vertex moves less than a unit; e.g. in test_75 the exact difference is a
/// sliver of area 1706.7, a third of a unit wide, that iOverlay snaps away).
#[test]
fn ioverlay_suite() {
    let Some(dir) = existing_cases_dir() else {
        println!("skipped: shared cases not found");
        return;
    };
    let Ok(rd) = std::fs::read_dir(dir.join("ioverlay/boolean")) else {
        println!("skipped: ioverlay not found");
        return;
    };
    let mut files: Vec<PathBuf> = rd.map(|e| e.unwrap().path()).collect();
    files.sort();
    let mut failures = Vec::new();
    let mut run = 0;
    for f in files {
        let name = f.file_name().unwrap().to_string_lossy().to_string();
        if IOVERLAY_EXCLUDED.iter().any(|(n, _)| *n == name) {
            continue;
        }
        let v = read(&f);
        let paths = |k: &str| {
            MultiPolygon(
                v[k].as_array()
                    .map(|a| {
                        // iOverlay ignores contours with fewer than 3 distinct points;
                        // our API rejects them as bad input, so they are dropped here.
                        a.iter()
                            .map(io_contour)
                            .filter(|c| {
                                let mut k: Vec<(u64, u64)> =
                                    c.iter().map(|p| (p.x.to_bits(), p.y.to_bits())).collect();
                                k.sort_unstable();
                                k.dedup();
                                k.len() >= 3
                            })
                            .map(|c| Polygon::new(c, vec![]))
                            .collect()
                    })
                    .unwrap_or_default(),
            )
        };
        let (subj, clip) = (paths("subjPaths"), paths("clipPaths"));
        let rule = match v["fillRule"].as_u64() {
            Some(1) => FillRule::NonZero,
            _ => FillRule::EvenOdd,
        };
        let opts = BooleanOptions {
            fill_rule: rule,
            keep_collinear: false,
        };
        for (key, x, y, op) in [
            ("intersect", &subj, &clip, BooleanOp::Intersection),
            ("union", &subj, &clip, BooleanOp::Union),
            ("difference", &subj, &clip, BooleanOp::Difference),
            ("inverseDifference", &clip, &subj, BooleanOp::Difference),
            ("xor", &subj, &clip, BooleanOp::Xor),
        ] {
            let Some(alts) = v[key].as_array() else {
                continue;
            };
            run += 1;
            let label = format!("{name}/{key}");
            let got = match boolean_with(x, y, op, &opts) {
                Ok(g) => g,
                Err(e) => {
                    failures.push(format!("{label}: error {e}"));
                    continue;
                }
            };
            assert_valid_with(&got, true);
            let mut best = f64::INFINITY;
            let mut ok = false;
            for alt in alts {
                let want = io_shapes(alt);
                let want = boolean_with(
                    &want,
                    &MultiPolygon::default(),
                    BooleanOp::Union,
                    &BooleanOptions::default(),
                );
                let Ok(want) = want else { continue };
                let Ok(diff) = boolean(&got, &want, BooleanOp::Xor) else {
                    continue;
                };
                let err = area(&diff).abs();
                best = best.min(err);
                if err <= 0.5 * (perimeter(&want) + perimeter(&got)) + 1e-9 {
                    ok = true;
                }
            }
            if !ok {
                failures.push(format!("{label}: area of symmetric difference {best}"));
            }
        }
    }
    println!("ioverlay: {run} operations checked");
    assert!(run > 50);
    assert!(
        failures.is_empty(),
        "{} failures:\n{}",
        failures.len(),
        failures.join("\n")
    );
}

/// One case of Clipper2's `Polygons.txt`.
struct ClipperCase {
    caption: String,
    op: BooleanOp,
    fill: String,
    area: f64,
    count: i64,
    subjects: Vec<Vec<Point2>>,
    clips: Vec<Vec<Point2>>,
}

fn clipper_cases(text: &str) -> Vec<ClipperCase> {
    let mut out: Vec<ClipperCase> = Vec::new();
    let mut in_clips = false;
    for line in text.lines().map(str::trim) {
        if let Some(c) = line.strip_prefix("CAPTION:") {
            out.push(ClipperCase {
                caption: c.trim().trim_end_matches('.').to_string(),
                op: BooleanOp::Union,
                fill: String::new(),
                area: 0.0,
                count: 0,
                subjects: Vec::new(),
                clips: Vec::new(),
            });
            in_clips = false;
            continue;
        }
        let Some(case) = out.last_mut() else { continue };
        if let Some(t) = line.strip_prefix("CLIPTYPE:") {
            case.op = match t.trim() {
                "UNION" => BooleanOp::Union,
                "INTERSECTION" => BooleanOp::Intersection,
                "DIFFERENCE" => BooleanOp::Difference,
                "XOR" => BooleanOp::Xor,
                other => panic!("clip type {other}"),
            };
        } else if let Some(t) = line.strip_prefix("FILLRULE:") {
            case.fill = t.trim().to_string();
        } else if let Some(t) = line.strip_prefix("SOL_AREA:") {
            case.area = t.trim().parse().unwrap();
        } else if let Some(t) = line.strip_prefix("SOL_COUNT:") {
            case.count = t.trim().parse().unwrap();
        } else if line == "SUBJECTS" {
            in_clips = false;
        } else if line == "CLIPS" {
            in_clips = true;
        } else if !line.is_empty() {
            let nums: Vec<f64> = line
                .split(',')
                .map(str::trim)
                .filter(|s| !s.is_empty())
                .map(|s| s.parse().unwrap())
                .collect();
            let path: Vec<Point2> = nums.chunks(2).map(|c| Point2::new(c[0], c[1])).collect();
            if in_clips {
                case.clips.push(path);
            } else {
                case.subjects.push(path);
            }
        }
    }
    out
}

/// Paths as a polygon set (one polygon per path, rings as given). A path with fewer than
/// three distinct points encloses nothing and adds zero winding anywhere, so it is left
/// out (the polygon model rejects such rings).
fn clipper_set(paths: &[Vec<Point2>]) -> MultiPolygon {
    MultiPolygon(
        paths
            .iter()
            .filter(|p| {
                let mut k: Vec<_> = p.iter().map(|q| (q.x.to_bits(), q.y.to_bits())).collect();
                k.sort_unstable();
                k.dedup();
                k.len() >= 3
            })
            .map(|p| Polygon::new(p.clone(), vec![]))
            .collect(),
    )
}

/// Clipper2's Polygons.txt: for every case the exact area of the result region (from the
/// labelled arrangement, in rationals) against SOL_AREA, and the number of output rings
/// against SOL_COUNT. SOL_AREA comes from Clipper's integer-rounded output, so the
/// tolerances are Clipper's own (tolerances.json: 1% of the area unless overridden,
/// count exact unless overridden; see below for why the count is a lower bound).
/// POSITIVE/NEGATIVE fill are winding > 0 / < 0 with the
/// rings as given, read from the same winding numbers.
#[test]
fn clipper2_polygons_suite() {
    use compgeom::overlay::{boolean_dcel, faces_to_polygons};
    use num_traits::ToPrimitive;
    let Some(dir) = existing_cases_dir() else {
        return;
    };
    let dir = dir.join("clipper2");
    let text = std::fs::read_to_string(dir.join("Polygons.txt")).unwrap();
    let tol: Value = read(&dir.join("tolerances.json"));
    let cases = clipper_cases(&text);
    assert_eq!(cases.len(), 65);
    let mut failures = Vec::new();
    let mut split = 0;
    for c in &cases {
        let (a, b) = (clipper_set(&c.subjects), clipper_set(&c.clips));
        let d = boolean_dcel(&a, &b, FillRule::NonZero).unwrap();
        d.validate().unwrap();
        let rule = |w: i32| match c.fill.as_str() {
            "EVENODD" => w % 2 != 0,
            "NONZERO" => w != 0,
            "POSITIVE" => w > 0,
            "NEGATIVE" => w < 0,
            other => panic!("fill rule {other}"),
        };
        let inside = |f| {
            let (wa, wb) = d.face(f).data;
            c.op.apply(rule(wa), rule(wb))
        };
        let exact: f64 = d
            .face_ids()
            .skip(1)
            .filter(|&f| inside(f))
            .map(|f| d.face_area_exact(f).to_f64().unwrap())
            .sum();
        let out = faces_to_polygons(&d, inside, |e| e.carrier, false);
        assert_valid_with(&out, true);
        assert!(
            (area(&out) - exact).abs() <= 1e-9 * exact.max(1.0),
            "{}",
            c.caption
        );
        let rings: i64 = out.0.iter().map(|p| 1 + p.holes.len() as i64).sum();
        let area_rel = tol["area_rel"][&c.caption].as_f64().unwrap_or(0.01);
        let count_abs = tol["count_abs"][&c.caption].as_i64().unwrap_or(0);
        if c.area > 0.0 && (exact - c.area).abs() > area_rel * exact {
            failures.push(format!("case {}: area {exact} vs {}", c.caption, c.area));
        }
        // Clipper keeps a boundary that touches itself at a vertex as one path; valid OGC
        // output splits it there into simple rings (e.g. a shell and a hole touching it),
        // so the ring count can only be higher: SOL_COUNT is a lower bound here.
        if c.count > 0 && rings < c.count - count_abs {
            failures.push(format!("case {}: {rings} rings vs {}", c.caption, c.count));
        }
        if c.count > 0 && rings != c.count {
            split += 1;
        }
    }
    assert!(failures.is_empty(), "{failures:#?}");
    println!("clipper2: 65 cases, areas within tolerance; {split} with more (split) rings than Clipper's paths");
}

/// Text between `<tag ...>` and `</tag>` after `from`, with the opening tag's attributes.
fn xml_element<'a>(s: &'a str, tag: &str) -> Option<(&'a str, &'a str, &'a str)> {
    let open = s.find(&format!("<{tag}"))?;
    let attrs_end = open + s[open..].find('>')?;
    let close = attrs_end + s[attrs_end..].find(&format!("</{tag}>"))?;
    let rest = &s[close + tag.len() + 3..];
    Some((
        &s[open + tag.len() + 1..attrs_end],
        s[attrs_end + 1..close].trim(),
        rest,
    ))
}

fn xml_attr<'a>(attrs: &'a str, name: &str) -> Option<&'a str> {
    let i = attrs.find(&format!("{name}=\""))? + name.len() + 2;
    Some(&attrs[i..i + attrs[i..].find('"')?])
}

fn perimeter_of(m: &MultiPolygon) -> f64 {
    m.0.iter()
        .flat_map(|p| p.rings())
        .map(|r| {
            (0..r.len())
                .map(|i| {
                    let (p, q) = (r[i], r[(i + 1) % r.len()]);
                    (q.x - p.x).hypot(q.y - p.y)
                })
                .sum::<f64>()
        })
        .sum()
}

/// Polygonal WKT read as a polygon set; `None` for other geometry types (points, lines,
/// collections) and for hex WKB.
fn polygonal(wkt: &str) -> Option<MultiPolygon> {
    let head = wkt.trim_start().to_ascii_uppercase();
    if head.contains("EMPTY") && !head.contains('(') {
        // An empty result of any type (JTS types it by the operation's dimension).
        return Some(MultiPolygon::default());
    }
    if !(head.starts_with("POLYGON") || head.starts_with("MULTIPOLYGON")) {
        return None;
    }
    compgeom::io::read_polygons(wkt, compgeom::io::Format::Wkt, "case").ok()
}

/// The XML test files of the JTS and GEOS suites under `dir`, sorted.
fn xml_suite_files(dir: &Path) -> Vec<PathBuf> {
    let mut files = Vec::new();
    let mut stack = vec![dir.join("jts-testxml"), dir.join("geos-xmltester")];
    while let Some(d) = stack.pop() {
        for e in std::fs::read_dir(&d).unwrap() {
            let p = e.unwrap().path();
            if p.is_dir() {
                stack.push(p);
            } else if p.extension().is_some_and(|x| x == "xml") {
                files.push(p);
            }
        }
    }
    files.sort();
    files
}

/// The polygon–polygon overlay cases of the JTS and GEOS XML test suites
/// (`intersection`, `union`, `difference`, `symdifference` and their `…ng` variants, on
/// two polygonal operands): the result is valid and its symmetric difference with the
/// expected geometry (computed exactly by the crate) has area ≈ 0. Tolerances: with a
/// floating precision model 1e-9 of the inputs' area; where the run's precision model is
/// a grid of cell 1/S the expected output was snapped to that grid by its producer, so
/// the allowed area is the perimeter of both results times one cell (each vertex moves by
/// at most √2/2 cell). Cases left out, counted and asserted by kind: operands that are
/// not polygonal or are hex WKB (not polygon booleans / not read by compgeom::io), and
/// `…sr` ops (snap-rounding to a grid given in the case).
#[test]
fn jts_and_geos_xml_overlay_suites() {
    let Some(dir) = existing_cases_dir() else {
        return;
    };
    let files = xml_suite_files(&dir);
    let (mut run, mut not_polygonal, mut snap_rounded) = (0, 0, 0);
    let mut failures = Vec::new();
    for f in &files {
        let text = std::fs::read_to_string(f).unwrap();
        let cell = text
            .find("<precisionModel")
            .and_then(|i| xml_attr(&text[i..i + text[i..].find('>').unwrap()], "scale"))
            .and_then(|s| s.parse::<f64>().ok())
            .map_or(0.0, |s| 1.0 / s);
        for (ci, case) in text.split("<case").skip(1).enumerate() {
            let a = xml_element(case, "a").map(|(_, t, _)| t);
            let b = xml_element(case, "b").map(|(_, t, _)| t);
            let mut rest = case;
            while let Some((attrs, expected, after)) = xml_element(rest, "op") {
                rest = after;
                let name = xml_attr(attrs, "name").unwrap_or("").to_ascii_lowercase();
                let base = name.strip_suffix("ng").unwrap_or(&name);
                let op = match base.strip_suffix("sr").unwrap_or(base) {
                    "intersection" => BooleanOp::Intersection,
                    "union" => BooleanOp::Union,
                    "difference" => BooleanOp::Difference,
                    "symdifference" => BooleanOp::Xor,
                    _ => continue,
                };
                if base.ends_with("sr") {
                    snap_rounded += 1;
                    continue;
                }
                let operand = |n: Option<&str>| match n.map(str::to_ascii_uppercase).as_deref() {
                    Some("A") => a,
                    Some("B") => b,
                    _ => None,
                };
                let x = operand(xml_attr(attrs, "arg1")).and_then(polygonal);
                let y = match xml_attr(attrs, "arg2") {
                    None => Some(MultiPolygon::default()),
                    arg => operand(arg).and_then(polygonal),
                };
                let (Some(x), Some(y), Some(want)) = (x, y, polygonal(expected)) else {
                    not_polygonal += 1;
                    continue;
                };
                run += 1;
                let label = format!("{}#{ci} {name}", f.file_name().unwrap().to_string_lossy());
                let got = if xml_attr(attrs, "arg2").is_none() {
                    compgeom::overlay::union_all(&x)
                } else {
                    boolean_with(&x, &y, op, &POSITIVE)
                };
                let got = match got {
                    Ok(g) => g,
                    Err(e) => {
                        failures.push(format!("{label}: {e}"));
                        continue;
                    }
                };
                assert_valid_with(&got, true);
                let want =
                    boolean_with(&want, &MultiPolygon::default(), BooleanOp::Union, &POSITIVE)
                        .unwrap();
                let diff = area(&boolean(&got, &want, BooleanOp::Xor).unwrap());
                let tol = if cell > 0.0 {
                    (perimeter_of(&got) + perimeter_of(&want)) * cell
                } else {
                    1e-9 * (area(&x) + area(&y)).max(scale(&[&x, &y]).powi(2) * 1e-6)
                };
                if diff > tol {
                    failures.push(format!("{label}: area(got △ want) = {diff:e} > {tol:e}"));
                }
            }
        }
    }
    println!("jts/geos xml: {run} polygon overlay tests run, {not_polygonal} with non-polygonal or WKB operands, {snap_rounded} snap-rounding ops left out");
    assert!(run >= 60, "only {run} cases ran");
    assert!(
        failures.is_empty(),
        "{} failures: {failures:#?}",
        failures.len()
    );
}

/// The `isValid` cases of the JTS and GEOS XML suites on polygonal input (POLYGON and
/// MULTIPOLYGON WKT): `compgeom::overlay::validity_problems_as_written` finds a problem
/// exactly where JTS says the geometry is not valid. Ring orientation is left out (OGC,
/// and JTS, do not ask for one; RFC 7946 does, and the check reports it too). Cases
/// on other geometry types and in hex WKB are counted and left out.
#[test]
fn jts_and_geos_xml_validity_suites() {
    let Some(dir) = existing_cases_dir() else {
        return;
    };
    let (mut run, mut invalid, mut other) = (0, 0, 0);
    let mut failures = Vec::new();
    for f in &xml_suite_files(&dir) {
        let text = std::fs::read_to_string(f).unwrap();
        for (ci, case) in text.split("<case").skip(1).enumerate() {
            let Some((_, a, _)) = xml_element(case, "a") else {
                continue;
            };
            let mut rest = case;
            while let Some((attrs, expected, after)) = xml_element(rest, "op") {
                rest = after;
                if !xml_attr(attrs, "name").is_some_and(|n| n.eq_ignore_ascii_case("isvalid")) {
                    continue;
                }
                let head = a.trim_start().to_ascii_uppercase();
                if !(head.starts_with("POLYGON") || head.starts_with("MULTIPOLYGON")) {
                    other += 1;
                    continue;
                }
                let want = expected.trim() == "true";
                let label = format!("{}#{ci}", f.file_name().unwrap().to_string_lossy());
                let read = match compgeom::io::read_polygons_as_written(
                    a,
                    compgeom::io::Format::Wkt,
                    "case",
                ) {
                    Ok(read) => read,
                    Err(e) => {
                        failures.push(format!("{label}: {e}"));
                        continue;
                    }
                };
                let problems: Vec<String> = compgeom::overlay::validity_problems_as_written(
                    &read.polygons,
                    &read.open_rings,
                )
                .unwrap()
                .into_iter()
                .map(|p| p.message)
                .filter(|m| !m.contains("(RFC 7946)"))
                .collect();
                run += 1;
                invalid += usize::from(!want);
                if problems.is_empty() != want {
                    failures.push(format!(
                        "{label}: JTS says valid = {want}, problems {problems:?}"
                    ));
                }
            }
        }
    }
    println!("jts/geos xml: {run} polygonal isValid tests run ({invalid} of them not valid), {other} on other geometry types left out");
    assert!(
        run >= 130 && invalid >= 35,
        "only {run} cases ran, {invalid} not valid"
    );
    assert!(
        failures.is_empty(),
        "{} failures: {failures:#?}",
        failures.len()
    );
}

/// Where rounding made the edges of `d` meet (found by the exact intersection sweep over
/// all its edges, rounded): a point inside an edge, an overlap, or two different
/// vertices on one point. Returns the number of such places and the faces beside the
/// edges there.
fn faces_beside_meetings<V, E, F>(
    d: &compgeom::dcel::Dcel<V, E, F>,
) -> (usize, Vec<compgeom::dcel::FaceId>) {
    use compgeom::dcel::HalfEdgeId;
    use compgeom::intersect::find_intersections;
    use compgeom::Segment2;
    let edges: Vec<HalfEdgeId> = d.half_edge_ids().step_by(2).collect();
    let ends = |k: usize| (d.half_edge(edges[k]).origin, d.destination(edges[k]));
    let segs: Vec<Segment2> = (0..edges.len())
        .map(|k| {
            let (u, v) = ends(k);
            Segment2::new(d.vertex(u).approx, d.vertex(v).approx)
        })
        .collect();
    let x = find_intersections(&segs).unwrap();
    let mut meetings: Vec<Vec<usize>> = x.overlaps.iter().map(|o| o.segments.clone()).collect();
    for p in &x.points {
        let mut at: Vec<usize> = p
            .segments()
            .iter()
            .flat_map(|&k| {
                let (u, v) = ends(k);
                [u, v]
            })
            .filter(|&v| d.vertex(v).approx == p.point)
            .map(|v| v.0)
            .collect();
        at.sort_unstable();
        at.dedup();
        if !p.interior().is_empty() || at.len() > 1 {
            meetings.push(p.segments().to_vec());
        }
    }
    let mut faces: Vec<_> = meetings
        .iter()
        .flatten()
        .flat_map(|&k| [edges[k], d.twin(edges[k])])
        .map(|h| d.half_edge(h).face)
        .collect();
    faces.sort_unstable_by_key(|f| f.0);
    faces.dedup();
    (meetings.len(), faces)
}

/// The overlays of the polygon pairs of the JTS and GEOS XML suites (the robustness
/// cases above all: near-coincident edges): after rounding, every face beside a place
/// where rounding made edges meet ([`faces_beside_meetings`]) is among the faces
/// `rounding_suspects` reports, and the overlay has mended all it could (a second
/// mending moves nothing). Before session 33 the overlay rounded without any check:
/// these overlays had 117 such places (242 faces reported by the check); 54 are left
/// after the mending (137 faces: slivers thinner than a float, or crossings with no
/// float around them that keeps their neighbours on their sides), all reported. The
/// reported faces must stay few (under a tenth), else the check says nothing.
#[test]
fn jts_and_geos_xml_overlay_faces_after_rounding() {
    use compgeom::overlay::{mend_rounding, overlay_polygons, rounding_suspects};
    let Some(dir) = existing_cases_dir() else {
        return;
    };
    let files = xml_suite_files(&dir);
    let (mut overlays, mut faces, mut meetings, mut reported) = (0, 0, 0, 0);
    for f in &files {
        let text = std::fs::read_to_string(f).unwrap();
        for (ci, case) in text.split("<case").skip(1).enumerate() {
            let operand = |tag| xml_element(case, tag).and_then(|(_, t, _)| polygonal(t));
            let (Some(a), Some(b)) = (operand("a"), operand("b")) else {
                continue;
            };
            let label = format!("{}#{ci}", f.file_name().unwrap().to_string_lossy());
            let mut d = overlay_polygons(&a, &b).unwrap_or_else(|e| panic!("{label}: {e}"));
            d.validate().unwrap_or_else(|e| panic!("{label}: {e}"));
            overlays += 1;
            faces += d.face_count();
            let suspects = rounding_suspects(&d);
            reported += suspects.len();
            let (met, beside) = faces_beside_meetings(&d);
            meetings += met;
            for face in beside {
                assert!(
                    suspects.contains(&face),
                    "{label}: face {face:?} beside edges that rounding made meet is not reported"
                );
            }
            let before: Vec<_> = d.vertex_ids().map(|v| d.vertex(v).approx).collect();
            assert_eq!(mend_rounding(&mut d), suspects, "{label}");
            assert!(
                d.vertex_ids().map(|v| d.vertex(v).approx).eq(before),
                "{label}"
            );
        }
    }
    println!(
        "jts/geos xml overlays: {overlays}, {faces} faces, {meetings} places where \
         rounding made edges meet, {reported} faces reported"
    );
    assert!(overlays >= 100, "only {overlays} overlays");
    assert!(
        10 * reported < faces,
        "{reported} of {faces} faces reported"
    );
}

/// An overlay of an overlay (found by a random search, about 1 in 13 000 such triples)
/// where a sliver face rounds to two points and a neighbouring cycle has three vertices
/// on one point: the edge between them is in no cycle the check can merge, and after
/// rounding it lies on another edge. The faces beside that edge must be reported.
#[test]
fn overlay_of_overlays_reports_faces_beside_collapsed_cycles() {
    use compgeom::dcel::Dcel;
    use compgeom::overlay::{overlay, rounding_suspects};
    let ring = |pts: &[(f64, f64)]| {
        Polygon::new(
            pts.iter().map(|&(x, y)| Point2::new(x, y)).collect(),
            vec![],
        )
    };
    let layer = |rings: &[&[(f64, f64)]]| {
        Dcel::from_polygons(&MultiPolygon(rings.iter().map(|r| ring(r)).collect())).unwrap()
    };
    let a = layer(&[&[
        (1.0, 0.3333333333333331),
        (5.0, 1.666666666666667),
        (5.0, 2.666666666666667),
        (1.0, 1.333333333333333),
    ]]);
    let b = layer(&[
        &[
            (0.0, 1.5e-323),
            (4.0, 1.3333333333333324),
            (4.0, 3.333333333333332),
            (0.0, 2.0),
        ],
        &[
            (6.0, 5.0),
            (0.0, 3.0),
            (0.0, 2e-323),
            (6.0, 2.0000000000000004),
        ],
    ]);
    let c = layer(&[
        &[
            (1.0, 0.33333333333333315),
            (5.0, 1.6666666666666672),
            (5.0, 4.666666666666667),
            (1.0, 3.333333333333333),
        ],
        &[
            (8.0, -0.1428571428571427),
            (3.0, 0.5714285714285718),
            (3.0, -2.428571428571428),
            (8.0, -3.142857142857143),
        ],
    ]);
    let d = overlay(&overlay(&a, &b).unwrap(), &c).unwrap();
    d.validate().unwrap();
    let suspects = rounding_suspects(&d);
    let (met, beside) = faces_beside_meetings(&d);
    assert!(
        met > 0,
        "the case no longer has a meeting: it tests nothing"
    );
    for face in beside {
        assert!(suspects.contains(&face), "face {face:?} is not reported");
    }
}

/// Turf's intersect / difference / union fixtures: the output is valid and its symmetric
/// difference with turf's expected result has area ≈ 0 (the [`compare`] tolerance).
/// Features that are not polygons (the linestring and multipoint cases) contribute no
/// area, so those cases expect an empty result; a union case without an expected file
/// is not run.
#[test]
fn turf_suite() {
    let Some(dir) = existing_cases_dir() else {
        return;
    };
    let dir = dir.join("turf");
    let mut run = 0;
    let mut failures = Vec::new();
    let mut invalid: Vec<String> = Vec::new();
    for op in ["intersect", "difference", "union"] {
        let mut names: Vec<PathBuf> = std::fs::read_dir(dir.join(op).join("in"))
            .unwrap()
            .map(|e| e.unwrap().path())
            .collect();
        names.sort();
        for input in names {
            let out = dir.join(op).join("out").join(input.file_name().unwrap());
            if !out.exists() {
                continue;
            }
            let feats: Vec<MultiPolygon> = read(&input)["features"]
                .as_array()
                .unwrap()
                .iter()
                .map(geometry)
                .collect();
            let want_v = read(&out);
            let (got, want) = match op {
                "union" => (
                    compgeom::overlay::union_all(&MultiPolygon(
                        feats.iter().flat_map(|m| m.0.clone()).collect(),
                    )),
                    geometry(&want_v),
                ),
                _ => {
                    let outs = want_v["features"].as_array().unwrap();
                    let want = if outs.len() > feats.len() {
                        geometry(&outs[outs.len() - 1])
                    } else {
                        MultiPolygon::default()
                    };
                    let bop = if op == "intersect" {
                        BooleanOp::Intersection
                    } else {
                        BooleanOp::Difference
                    };
                    let mut acc: compgeom::Result<MultiPolygon> = Ok(feats[0].clone());
                    for f in &feats[1..] {
                        acc = acc.and_then(|a| boolean_with(&a, f, bop, &POSITIVE));
                    }
                    (acc, want)
                }
            };
            run += 1;
            let name = format!("{op}/{}", input.file_name().unwrap().to_string_lossy());
            match got {
                Ok(g) => {
                    let problems = compgeom::overlay::validity_problems(&g).unwrap();
                    if !problems.is_empty() {
                        // Still the right point set: exact symmetric difference ≈ 0.
                        let d = boolean_with(&g, &want, BooleanOp::Xor, &NONZERO).unwrap();
                        let s = scale(&[&g, &want]);
                        assert!(area(&d).abs() <= 1e-9 * s * s, "{name}");
                        invalid.push(name.clone());
                        continue;
                    }
                    if let Err(e) = compare(&name, &g, &want) {
                        failures.push(e);
                    }
                }
                Err(e) => failures.push(format!("{name}: {e}")),
            }
        }
    }
    println!("turf: {run} cases");
    assert!(run >= 9, "only {run} turf cases ran");
    // Every output valid. (intersect/issue-412 and difference/issue-#721-inverse were
    // not until results were checked after rounding and repaired: an edge crossing and
    // a ring orientation, from rounded crossings on thin parts; see
    // compgeom::overlay's "Validity of the output".)
    assert_eq!(invalid, Vec::<String>::new());
    assert!(failures.is_empty(), "{failures:#?}");
}

/// Reads a little-endian WKB polygon or multipolygon (the hex text of a JTS test
/// operand); `None` for anything else.
struct Wkb {
    bytes: Vec<u8>,
    at: usize,
}

impl Wkb {
    fn of_hex(hex: &str) -> Option<Wkb> {
        let bytes = (0..hex.len() / 2)
            .map(|k| u8::from_str_radix(hex.get(2 * k..2 * k + 2)?, 16).ok())
            .collect::<Option<_>>()?;
        Some(Wkb { bytes, at: 0 })
    }

    fn take<const N: usize>(&mut self) -> Option<[u8; N]> {
        let s = self.bytes.get(self.at..self.at + N)?.try_into().ok()?;
        self.at += N;
        Some(s)
    }

    /// The byte-order mark (little-endian only) and the geometry type.
    fn header(&mut self) -> Option<u32> {
        (self.take::<1>()? == [1]).then_some(())?;
        Some(u32::from_le_bytes(self.take()?))
    }

    fn count(&mut self) -> Option<usize> {
        Some(u32::from_le_bytes(self.take()?) as usize)
    }

    fn polygon(&mut self) -> Option<Polygon> {
        let mut rings = Vec::new();
        for _ in 0..self.count()? {
            let n = self.count()?;
            let mut ring = Vec::with_capacity(n);
            for _ in 0..n {
                let x = f64::from_le_bytes(self.take()?);
                let y = f64::from_le_bytes(self.take()?);
                ring.push(Point2::new(x, y));
            }
            rings.push(ring);
        }
        let mut it = rings.into_iter();
        Some(Polygon::new(it.next()?, it.collect()))
    }

    fn polygons(mut self) -> Option<MultiPolygon> {
        match self.header()? {
            3 => Some(MultiPolygon(vec![self.polygon()?])),
            6 => {
                let n = self.count()?;
                let mut v = Vec::with_capacity(n);
                for _ in 0..n {
                    (self.header()? == 3).then_some(())?;
                    v.push(self.polygon()?);
                }
                Some(MultiPolygon(v))
            }
            _ => None,
        }
    }
}

/// GEOS ticket 837's operand (487 polygons of a land-use map, 3074 points; WKB, which
/// the XML suites test above leave out) dissolved with `union_all`: valid, and of the
/// exact area of the faces of positive winding. Its crossings are within a float gap of
/// other vertices: rounded as they come, a vertex ends up on the wrong side of a 200 m
/// edge and edges cross and overlap (caught and repaired by overlay::rounding).
#[test]
fn geos_837_dissolves_into_valid_polygons() {
    let Some(dir) = existing_cases_dir() else {
        return;
    };
    let path = dir.join("jts-testxml/robust/overlay/TestOverlay-geos-837.xml");
    let text = std::fs::read_to_string(&path).expect("the GEOS-837 case");
    let (_, body, _) = xml_element(&text, "a").expect("operand a");
    let m = Wkb::of_hex(body.trim())
        .and_then(Wkb::polygons)
        .expect("a WKB multipolygon");
    assert_eq!(m.0.len(), 487);
    let out = compgeom::overlay::union_all(&m).unwrap();
    assert_eq!(compgeom::overlay::validity_problems(&out).unwrap(), []);
    let d =
        compgeom::overlay::boolean_dcel(&m, &MultiPolygon::default(), FillRule::Positive).unwrap();
    use num_traits::{ToPrimitive, Zero};
    let exact = d
        .face_ids()
        .skip(1)
        .filter(|&f| d.face(f).data.0 > 0)
        .fold(num_rational::BigRational::zero(), |sum, f| {
            sum + d.face_area_exact(f)
        })
        .to_f64()
        .unwrap();
    let got = area(&out);
    assert!(
        (got - exact).abs() <= 1e-9 * exact,
        "area {got} vs exact {exact}"
    );
}
