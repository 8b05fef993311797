//! Convex hull on the shared fixture suites (read in place; see /work/shared/cases/README.md):
//! jts-unit/convex-hull.json, georust-geo/convex-hull, jts-testxml/general/TestConvexHull*.xml
//! and turf/convex. Every case runs through all three algorithms and the verifier, and the
//! result is compared with the expected hull as a cyclic sequence (any start vertex, either
//! orientation), exactly unless the fixture gives a tolerance.

mod common;
use common::cases_dir;
use compgeom::hull::{convex_hull, verify_convex_hull, HullAlgorithm, HullOptions};
use compgeom::Point2;
use geo_types::Geometry;
use std::path::{Path, PathBuf};
use wkt::TryFromWkt;

/// The fixture path, or `None` (after saying so) when the suite is not present.
fn fixture(rel: &str) -> Option<PathBuf> {
    let p = cases_dir().join(rel);
    if p.exists() {
        Some(p)
    } else {
        println!("skipped: {} not found", p.display());
        None
    }
}

fn read(p: &Path) -> String {
    std::fs::read_to_string(p).unwrap_or_else(|e| panic!("{}: {e}", p.display()))
}

/// Every coordinate of a geometry, in order (rings of polygons included).
fn coords(g: &Geometry<f64>) -> Vec<Point2> {
    let c = |c: &geo_types::Coord<f64>| Point2::new(c.x, c.y);
    match g {
        Geometry::Point(p) => vec![c(&p.0)],
        Geometry::Line(l) => vec![c(&l.start), c(&l.end)],
        Geometry::LineString(ls) => ls.0.iter().map(c).collect(),
        Geometry::Polygon(poly) => poly
            .exterior()
            .0
            .iter()
            .chain(poly.interiors().iter().flat_map(|r| r.0.iter()))
            .map(c)
            .collect(),
        Geometry::MultiPoint(mp) => mp.0.iter().map(|p| c(&p.0)).collect(),
        Geometry::MultiLineString(m) => m.0.iter().flat_map(|ls| ls.0.iter().map(c)).collect(),
        Geometry::MultiPolygon(m) => {
            m.0.iter()
                .flat_map(|p| coords(&Geometry::Polygon(p.clone())))
                .collect()
        }
        Geometry::GeometryCollection(gc) => gc.0.iter().flat_map(coords).collect(),
        Geometry::Rect(r) => coords(&Geometry::Polygon(r.to_polygon())),
        Geometry::Triangle(t) => coords(&Geometry::Polygon(t.to_polygon())),
    }
}

fn parse_wkt(s: &str) -> Result<Geometry<f64>, String> {
    Geometry::<f64>::try_from_wkt_str(s.trim()).map_err(|e| format!("bad WKT {s:?}: {e}"))
}

/// The expected hull as an open vertex cycle: a polygon's exterior ring or a closed
/// linestring loses its closing point; POINT and 2-point LINESTRING stay as they are.
fn expected_cycle(g: &Geometry<f64>) -> Vec<Point2> {
    let mut v = match g {
        Geometry::Polygon(p) => coords(&Geometry::LineString(p.exterior().clone())),
        other => coords(other),
    };
    if v.len() > 2 && v.first() == v.last() {
        v.pop();
    }
    v
}

fn close(a: Point2, b: Point2, tol: f64) -> bool {
    if tol == 0.0 {
        a == b
    } else {
        (a.x - b.x).hypot(a.y - b.y) <= tol
    }
}

/// Equal as cyclic sequences, up to start vertex and orientation.
fn same_cycle(ours: &[Point2], expected: &[Point2], tol: f64) -> bool {
    let n = ours.len();
    if n != expected.len() {
        return false;
    }
    if n == 0 {
        return true;
    }
    (0..n).any(|r| {
        let fwd = (0..n).all(|i| close(ours[(r + i) % n], expected[i], tol));
        let bwd = (0..n).all(|i| close(ours[(r + n - i) % n], expected[i], tol));
        fwd || bwd
    })
}

/// Run one case through every algorithm; `Err` describes the first mismatch.
fn check_case(name: &str, input: &[Point2], expected: &[Point2], tol: f64) -> Result<(), String> {
    for alg in [
        HullAlgorithm::Default,
        HullAlgorithm::Andrew,
        HullAlgorithm::Slow,
    ] {
        let hull = convex_hull(input, &HullOptions::new().with_algorithm(alg))
            .map_err(|e| format!("{name}: {alg:?}: {e}"))?;
        verify_convex_hull(input, &hull, false).map_err(|e| format!("{name}: {alg:?}: {e}"))?;
        if !same_cycle(&hull, expected, tol) {
            return Err(format!(
                "{name}: {alg:?} gave {hull:?}, expected {expected:?} (tolerance {tol})"
            ));
        }
    }
    Ok(())
}

fn report(suite: &str, ran: usize, failures: Vec<String>) {
    assert!(ran > 0, "{suite}: no cases found");
    assert!(
        failures.is_empty(),
        "{suite}: {} of {ran} cases failed:\n{}",
        failures.len(),
        failures.join("\n")
    );
    println!("{suite}: {ran} cases passed");
}

#[test]
fn jts_unit_convex_hull() {
    let Some(path) = fixture("jts-unit/convex-hull.json") else {
        return;
    };
    let doc: serde_json::Value = serde_json::from_str(&read(&path)).unwrap();
    let cases = doc["cases"].as_array().expect("cases array");
    let mut failures = Vec::new();
    for c in cases {
        let name = c["test"].as_str().unwrap_or("?");
        let tol = c["tolerance"].as_f64().unwrap_or(0.0);
        let run = || -> Result<(), String> {
            let input = coords(&parse_wkt(c["input"].as_str().ok_or("no input")?)?);
            let expected =
                expected_cycle(&parse_wkt(c["expected"].as_str().ok_or("no expected")?)?);
            check_case(name, &input, &expected, tol)
        };
        if let Err(e) = run() {
            failures.push(e);
        }
    }
    report("jts-unit/convex-hull.json", cases.len(), failures);
}

#[test]
fn georust_geo_convex_hull() {
    let Some(path) = fixture("georust-geo/expected.json") else {
        return;
    };
    let dir = path.parent().unwrap().to_path_buf();
    let doc: serde_json::Value = serde_json::from_str(&read(&path)).unwrap();
    let map = doc.as_object().expect("object");
    let mut failures = Vec::new();
    for (input_rel, exp) in map {
        let expected_rel = exp["expected_hull"].as_str().expect("expected_hull");
        let run = || -> Result<(), String> {
            let input = coords(&parse_wkt(&read(&dir.join(input_rel)))?);
            let expected = expected_cycle(&parse_wkt(&read(&dir.join(expected_rel)))?);
            check_case(input_rel, &input, &expected, 0.0)
        };
        if let Err(e) = run() {
            failures.push(e);
        }
    }
    report("georust-geo", map.len(), failures);
}

/// The text between `<tag ...>` and `</tag>` for each occurrence, with the opening tag.
fn elements<'a>(xml: &'a str, tag: &str) -> Vec<(&'a str, &'a str)> {
    let (open, close) = (format!("<{tag}"), format!("</{tag}>"));
    let mut out = Vec::new();
    let mut rest = xml;
    while let Some(i) = rest.find(&open) {
        let after = &rest[i + open.len()..];
        // Not a longer tag name (e.g. <a> vs <arg>).
        if !after.starts_with(['>', ' ', '\t', '\n', '\r']) {
            rest = after;
            continue;
        }
        let Some(gt) = after.find('>') else { break };
        let attrs = &after[..gt];
        let body_start = &after[gt + 1..];
        let Some(end) = body_start.find(&close) else {
            break;
        };
        out.push((attrs, &body_start[..end]));
        rest = &body_start[end + close.len()..];
    }
    out
}

fn attr<'a>(attrs: &'a str, name: &str) -> Option<&'a str> {
    let key = format!("{name}=\"");
    let i = attrs.find(&key)? + key.len();
    let len = attrs[i..].find('"')?;
    Some(&attrs[i..i + len])
}

fn jts_xml(rel: &str) {
    let Some(path) = fixture(rel) else {
        return;
    };
    let xml = read(&path);
    let tol = elements(&xml, "tolerance")
        .first()
        .map(|(_, t)| t.trim().parse::<f64>().expect("tolerance"))
        .unwrap_or(0.0);
    let mut failures = Vec::new();
    let mut ran = 0;
    for (i, (_, case)) in elements(&xml, "case").into_iter().enumerate() {
        let desc = elements(case, "desc")
            .first()
            .map_or(String::new(), |(_, d)| d.trim().to_string());
        let name = format!("{rel} case {} ({desc})", i + 1);
        let a = elements(case, "a");
        let ops = elements(case, "op");
        if a.len() != 1 || ops.is_empty() {
            failures.push(format!("{name}: expected one <a> and at least one <op>"));
            continue;
        }
        for (attrs, expected) in ops {
            ran += 1;
            let op = attr(attrs, "name").unwrap_or("");
            let arg = attr(attrs, "arg1").unwrap_or("");
            if op != "convexhull" || !arg.eq_ignore_ascii_case("a") {
                failures.push(format!("{name}: unexpected op {op:?} on {arg:?}"));
                continue;
            }
            let run = || -> Result<(), String> {
                let input = coords(&parse_wkt(a[0].1)?);
                let expected = expected_cycle(&parse_wkt(expected)?);
                check_case(&name, &input, &expected, tol)
            };
            if let Err(e) = run() {
                failures.push(e);
            }
        }
    }
    report(rel, ran, failures);
}

#[test]
fn jts_testxml_convex_hull() {
    jts_xml("jts-testxml/general/TestConvexHull.xml");
}

#[test]
fn jts_testxml_convex_hull_big() {
    jts_xml("jts-testxml/general/TestConvexHull-big.xml");
}

/// GeoJSON position -> point (a third coordinate, if any, is ignored).
fn position(v: &serde_json::Value) -> Result<Point2, String> {
    let a = v.as_array().ok_or("position is not an array")?;
    match (
        a.first().and_then(|x| x.as_f64()),
        a.get(1).and_then(|y| y.as_f64()),
    ) {
        (Some(x), Some(y)) => Ok(Point2::new(x, y)),
        _ => Err(format!("bad position {v}")),
    }
}

#[test]
fn turf_convex() {
    let Some(dir) = fixture("turf/convex") else {
        return;
    };
    let mut names: Vec<_> = std::fs::read_dir(dir.join("in"))
        .unwrap()
        .map(|e| e.unwrap().file_name())
        .collect();
    names.sort();
    let mut failures = Vec::new();
    for name in &names {
        let name = name.to_string_lossy().to_string();
        let run = || -> Result<(), String> {
            let input: serde_json::Value = serde_json::from_str(&read(&dir.join("in").join(&name)))
                .map_err(|e| e.to_string())?;
            let output: serde_json::Value =
                serde_json::from_str(&read(&dir.join("out").join(&name)))
                    .map_err(|e| e.to_string())?;
            let mut pts = Vec::new();
            for f in input["features"].as_array().ok_or("no features")? {
                let g = &f["geometry"];
                if g["type"] != "Point" {
                    return Err(format!("input feature of type {}", g["type"]));
                }
                pts.push(position(&g["coordinates"])?);
            }
            let last = output["features"]
                .as_array()
                .and_then(|f| f.last())
                .ok_or("no output features")?;
            if last["geometry"]["type"] != "Polygon" {
                return Err(format!(
                    "expected a Polygon, found {}",
                    last["geometry"]["type"]
                ));
            }
            let ring = last["geometry"]["coordinates"][0]
                .as_array()
                .ok_or("no ring")?
                .iter()
                .map(position)
                .collect::<Result<Vec<_>, _>>()?;
            let expected = expected_cycle(&Geometry::LineString(geo_types::LineString::from(
                ring.iter().map(|p| (p.x, p.y)).collect::<Vec<_>>(),
            )));
            check_case(&name, &pts, &expected, 0.0)
        };
        if let Err(e) = run() {
            failures.push(e);
        }
    }
    report("turf/convex", names.len(), failures);
}

#[test]
fn cyclic_comparison_is_strict() {
    let p = |x: f64, y: f64| Point2::new(x, y);
    let sq = [p(0.0, 0.0), p(0.0, 1.0), p(1.0, 1.0), p(1.0, 0.0)];
    let rotated_reversed = [p(1.0, 1.0), p(0.0, 1.0), p(0.0, 0.0), p(1.0, 0.0)];
    assert!(same_cycle(&sq, &rotated_reversed, 0.0));
    let swapped = [p(0.0, 0.0), p(1.0, 1.0), p(0.0, 1.0), p(1.0, 0.0)];
    assert!(!same_cycle(&sq, &swapped, 0.0));
    assert!(!same_cycle(&sq, &sq[..3], 0.0));
    let nudged = [p(0.0, 0.0), p(0.0, 1.0), p(1.0, 1.0), p(1.0, 1e-12)];
    assert!(!same_cycle(&sq, &nudged, 0.0));
    assert!(same_cycle(&sq, &nudged, 1e-9));
    let poly = expected_cycle(&parse_wkt("POLYGON ((0 0, 0 1, 1 1, 1 0, 0 0))").unwrap());
    assert_eq!(poly, sq);
}
