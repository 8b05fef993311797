//! Segment intersection on fixtures from other projects (read in place from
//! `COMPGEOM_CASES` or `../shared/cases`; skipped with a notice where absent):
//!
//! * `sweepline-intersections`: counts of self-intersection points between non-adjacent
//!   edges;
//! * `turf/kinks` (self-intersection points) and `turf/line-intersect` (points where
//!   the first feature meets the second);
//! * `jts-unit/segment-intersection.json` (two-segment cases, ill-conditioned);
//! * `jts-testxml/general/TestSimple.xml` (`isSimple`, the only file with that op).
//!
//! Every case must pass; the one exclusion is listed with its reason next to it.

mod common;
use common::cases_dir;
use compgeom::intersect::{
    any_intersection_where, find_intersections, is_simple, IntersectionPoint,
};
use compgeom::{Point2, Polygon, Segment2};
use serde_json::Value;
use std::path::{Path, PathBuf};

fn dir_or_skip(rel: &str) -> Option<PathBuf> {
    let d = cases_dir().join(rel);
    if d.exists() {
        Some(d)
    } else {
        println!("skipped: {} not found", d.display());
        None
    }
}

fn read_json(path: &Path) -> Value {
    serde_json::from_str(&std::fs::read_to_string(path).expect("readable")).expect("JSON")
}

// ------------------------------------------------------------------ paths and edges

/// A polyline (open) or ring (closed), repeated consecutive vertices dropped.
struct Path2 {
    pts: Vec<Point2>,
    closed: bool,
}

fn path(mut pts: Vec<Point2>, closed: bool) -> Path2 {
    pts.dedup();
    if closed {
        while pts.len() > 1 && pts.first() == pts.last() {
            pts.pop();
        }
    }
    Path2 { pts, closed }
}

fn coords(v: &Value) -> Vec<Point2> {
    v.as_array()
        .expect("coordinate list")
        .iter()
        .map(|c| Point2::new(c[0].as_f64().expect("x"), c[1].as_f64().expect("y")))
        .collect()
}

/// The rings and lines of a GeoJSON geometry.
fn geojson_paths(g: &Value) -> Vec<Path2> {
    let c = &g["coordinates"];
    match g["type"].as_str().expect("type") {
        "LineString" => vec![path(coords(c), false)],
        "MultiLineString" => c
            .as_array()
            .unwrap()
            .iter()
            .map(|l| path(coords(l), false))
            .collect(),
        "Polygon" => c
            .as_array()
            .unwrap()
            .iter()
            .map(|r| path(coords(r), true))
            .collect(),
        "MultiPolygon" => c
            .as_array()
            .unwrap()
            .iter()
            .flat_map(|p| p.as_array().unwrap().iter().map(|r| path(coords(r), true)))
            .collect(),
        other => panic!("unexpected geometry {other}"),
    }
}

fn features(doc: &Value) -> Vec<Value> {
    match doc["type"].as_str() {
        Some("FeatureCollection") => doc["features"]
            .as_array()
            .unwrap()
            .iter()
            .map(|f| f["geometry"].clone())
            .collect(),
        Some("Feature") => vec![doc["geometry"].clone()],
        _ => vec![doc.clone()],
    }
}

/// Edge `k` of path `p`: (path, position, path length, closed).
#[derive(Clone, Copy)]
struct EdgeOf {
    path: usize,
    k: usize,
    m: usize,
    closed: bool,
}

fn edges(paths: &[Path2]) -> (Vec<Segment2>, Vec<EdgeOf>) {
    let (mut segs, mut of) = (Vec::new(), Vec::new());
    for (pi, p) in paths.iter().enumerate() {
        let n = p.pts.len();
        let m = if p.closed && n >= 3 {
            n
        } else {
            n.saturating_sub(1)
        };
        for k in 0..m {
            segs.push(Segment2::new(p.pts[k], p.pts[(k + 1) % n]));
            of.push(EdgeOf {
                path: pi,
                k,
                m,
                closed: p.closed && n >= 3,
            });
        }
    }
    (segs, of)
}

/// True when edges `i` and `j` are consecutive in one path and `at` is their common vertex.
fn adjacent_at(segs: &[Segment2], of: &[EdgeOf], i: usize, j: usize, at: Point2) -> bool {
    let (a, b) = (of[i], of[j]);
    if a.path != b.path {
        return false;
    }
    let common = if a.k + 1 == b.k || (a.closed && (a.k + 1) % a.m == b.k) {
        segs[i].b
    } else if b.k + 1 == a.k || (b.closed && (b.k + 1) % b.m == a.k) {
        segs[j].b
    } else {
        return false;
    };
    common == at
}

/// Points where two edges that are not adjacent (at their shared vertex) meet.
fn kinks(paths: &[Path2]) -> Vec<Point2> {
    let (segs, of) = edges(paths);
    let found = find_intersections(&segs).unwrap();
    found
        .points
        .iter()
        .filter(|p| non_adjacent_pair(&segs, &of, p))
        .map(|p| p.point)
        .collect()
}

fn non_adjacent_pair(segs: &[Segment2], of: &[EdgeOf], p: &IntersectionPoint) -> bool {
    let s = p.segments();
    (0..s.len()).any(|x| (x + 1..s.len()).any(|y| !adjacent_at(segs, of, s[x], s[y], p.point)))
}

fn same_point_set(got: &[Point2], expected: &[Point2], tol: f64) -> bool {
    got.len() == expected.len()
        && expected.iter().all(|e| {
            got.iter()
                .any(|g| (g.x - e.x).abs() <= tol && (g.y - e.y).abs() <= tol)
        })
}

// ------------------------------------------------------------------ sweepline-intersections

#[test]
fn sweepline_intersections_counts() {
    let Some(dir) = dir_or_skip("sweepline-intersections") else {
        return;
    };
    let mut checked = 0;
    for sub in ["simple", "notSimple"] {
        let mut files: Vec<_> = std::fs::read_dir(dir.join(sub))
            .unwrap()
            .map(|e| e.unwrap().path())
            .collect();
        files.sort();
        for f in files {
            let name = f.file_name().unwrap().to_string_lossy().to_string();
            if name == "itersect-shared-vertice.geojson" {
                // Excluded: two polylines whose middle vertices coincide at (8, 50), so
                // four edges (two per line) meet in that one point. Our answer is one
                // intersection point (with four segments, 4 non-adjacent edge pairs);
                // the origin's expected count of 3 is neither the number of points (1)
                // nor of non-adjacent meeting pairs (4): a property of its report
                // loop, not of the geometry.
                let doc = read_json(&f);
                let paths: Vec<Path2> = features(&doc).iter().flat_map(geojson_paths).collect();
                let k = kinks(&paths);
                assert_eq!(k, vec![Point2::new(8.0, 50.0)], "{name}");
                continue;
            }
            let doc = read_json(&f);
            let expected = if sub == "simple" {
                0
            } else {
                doc["properties"]["expectedIntersections"]
                    .as_u64()
                    .expect("count") as usize
            };
            let paths: Vec<Path2> = features(&doc).iter().flat_map(geojson_paths).collect();
            assert_eq!(kinks(&paths).len(), expected, "{sub}/{name}");
            checked += 1;
        }
    }
    assert_eq!(checked, 5);
}

// ------------------------------------------------------------------ turf

fn points_of(doc: &Value) -> Vec<Point2> {
    features(doc)
        .iter()
        .filter(|g| g["type"] == "Point")
        .map(|g| {
            Point2::new(
                g["coordinates"][0].as_f64().unwrap(),
                g["coordinates"][1].as_f64().unwrap(),
            )
        })
        .collect()
}

#[test]
fn turf_kinks() {
    let Some(dir) = dir_or_skip("turf/kinks") else {
        return;
    };
    let mut n = 0;
    for name in [
        "hourglass.geojson",
        "multi-polygon.geojson",
        "triple.geojson",
    ] {
        let input = read_json(&dir.join("in").join(name));
        let expected = points_of(&read_json(&dir.join("out").join(name)));
        let paths: Vec<Path2> = features(&input).iter().flat_map(geojson_paths).collect();
        let got = kinks(&paths);
        assert!(
            same_point_set(&got, &expected, 1e-9),
            "{name}: {got:?} vs {expected:?}"
        );
        n += 1;
    }
    assert_eq!(n, 3);
}

#[test]
fn turf_line_intersect() {
    let Some(dir) = dir_or_skip("turf/line-intersect") else {
        return;
    };
    for name in [
        "2-vertex-segment.geojson",
        "polygons-with-holes.geojson",
        "self-intersecting-multiline.geojson",
    ] {
        let input = read_json(&dir.join("in").join(name));
        let expected = points_of(&read_json(&dir.join("out").join(name)));
        let geoms = features(&input);
        let (first, second) = (geojson_paths(&geoms[0]), geojson_paths(&geoms[1]));
        let (a, _) = edges(&first);
        let (b, _) = edges(&second);
        let all: Vec<Segment2> = a.iter().chain(&b).copied().collect();
        let found = find_intersections(&all).unwrap();
        let got: Vec<Point2> = found
            .points
            .iter()
            .filter(|p| {
                p.segments().iter().any(|&i| i < a.len())
                    && p.segments().iter().any(|&i| i >= a.len())
            })
            .map(|p| p.point)
            .collect();
        // The origin rounds its output to 6 decimals.
        assert!(
            same_point_set(&got, &expected, 0.6e-6),
            "{name}: {got:?} vs {expected:?}"
        );
    }
}

// ------------------------------------------------------------------ JTS

/// The numbers in a WKT text, in order.
fn numbers(text: &str) -> Vec<f64> {
    text.split(|c: char| {
        !(c.is_ascii_digit() || c == '.' || c == '-' || c == 'e' || c == 'E' || c == '+')
    })
    .filter(|t| !t.is_empty() && t.chars().any(|c| c.is_ascii_digit()))
    .map(|t| t.parse().expect("number"))
    .collect()
}

fn wkt_segment(text: &str) -> Segment2 {
    let v = numbers(text);
    assert_eq!(v.len(), 4, "{text}");
    Segment2::new(Point2::new(v[0], v[1]), Point2::new(v[2], v[3]))
}

#[test]
fn jts_segment_intersection() {
    let Some(dir) = dir_or_skip("jts-unit") else {
        return;
    };
    let doc = read_json(&dir.join("segment-intersection.json"));
    let cases = doc["cases"].as_array().unwrap();
    assert_eq!(cases.len(), 3);
    for c in cases {
        let name = c["test"].as_str().unwrap();
        let segs = [
            wkt_segment(c["segment_a"].as_str().unwrap()),
            wkt_segment(c["segment_b"].as_str().unwrap()),
        ];
        let found = find_intersections(&segs).unwrap();
        let count = if found.overlaps.is_empty() {
            found.points.len()
        } else {
            2
        };
        assert_eq!(
            count,
            c["expected_count"].as_u64().unwrap() as usize,
            "{name}"
        );
        if let Some(wkt) = c["expected_points"].as_str() {
            let v = numbers(wkt);
            let e = Point2::new(v[0], v[1]);
            let g = found.points[0].point;
            // JTS rounds its constructions (and in testCentralEndpointHeuristicFailure snaps
            // to the nearest endpoint); ours is the nearest double to the exact point. They
            // must agree to within a few units in the last place of the coordinates.
            let tol = 1e-12 * (e.x.abs() + e.y.abs()).max(1.0);
            assert!(
                (g.x - e.x).abs() <= tol && (g.y - e.y).abs() <= tol,
                "{name}: {g:?} vs {e:?}"
            );
        }
    }
}

/// A tiny WKT reader for the geometry kinds in TestSimple.xml.
#[derive(Debug)]
enum Geom {
    Points(Vec<Point2>),
    Line(Vec<Point2>),
    Lines(Vec<Vec<Point2>>),
    Polygons(Vec<Polygon>),
    Collection(Vec<Geom>),
}

fn split_top(body: &str) -> Vec<&str> {
    // Split at commas at depth 0.
    let (mut parts, mut depth, mut start) = (Vec::new(), 0, 0);
    for (i, ch) in body.char_indices() {
        match ch {
            '(' => depth += 1,
            ')' => depth -= 1,
            ',' if depth == 0 => {
                parts.push(body[start..i].trim());
                start = i + 1;
            }
            _ => {}
        }
    }
    parts.push(body[start..].trim());
    parts.into_iter().filter(|p| !p.is_empty()).collect()
}

fn inner(text: &str) -> &str {
    let t = text.trim();
    match (t.find('('), t.rfind(')')) {
        (Some(a), Some(b)) => &t[a + 1..b],
        _ => "",
    }
}

fn pts(text: &str) -> Vec<Point2> {
    numbers(text)
        .chunks(2)
        .map(|c| Point2::new(c[0], c[1]))
        .collect()
}

fn parse_wkt(text: &str) -> Geom {
    let t = text.trim();
    let kind: String = t
        .chars()
        .take_while(|c| c.is_ascii_alphabetic())
        .collect::<String>()
        .to_uppercase();
    let body = inner(t);
    match kind.as_str() {
        "POINT" | "MULTIPOINT" => Geom::Points(pts(body)),
        "LINESTRING" => Geom::Line(pts(body)),
        "MULTILINESTRING" => {
            Geom::Lines(split_top(body).into_iter().map(|l| pts(inner(l))).collect())
        }
        "POLYGON" => Geom::Polygons(vec![polygon(body)]),
        "MULTIPOLYGON" => Geom::Polygons(
            split_top(body)
                .into_iter()
                .map(|p| polygon(inner(p)))
                .collect(),
        ),
        "GEOMETRYCOLLECTION" => {
            // Components start with a type name; split at top-level commas.
            Geom::Collection(split_top(body).into_iter().map(parse_wkt).collect())
        }
        other => panic!("unexpected WKT {other}"),
    }
}

fn polygon(body: &str) -> Polygon {
    let mut rings: Vec<Vec<Point2>> = split_top(body).into_iter().map(|r| pts(inner(r))).collect();
    let exterior = rings.remove(0);
    Polygon::new(exterior, rings)
}

/// JTS's (OGC) simplicity of lineal geometry: every line is simple (only consecutive
/// edges meet, at their common vertex; a closed line's first and last edges also at the
/// closing point), no overlaps, and two different lines meet only at points that are
/// endpoints (boundary) of both open lines.
fn lines_simple(lines: &[Vec<Point2>]) -> bool {
    let mut paths: Vec<Path2> = lines.iter().map(|l| path(l.clone(), false)).collect();
    let (segs, mut of) = edges(&paths);
    // A closed line (first vertex = last) lists its closing edge itself; its first and
    // last edges are adjacent at the closing point, as in a ring.
    for p in paths.iter_mut() {
        p.closed = p.pts.len() >= 3 && p.pts.first() == p.pts.last();
    }
    for e in of.iter_mut() {
        e.closed = paths[e.path].closed;
    }
    let boundary = |line: usize, at: Point2| {
        let p = &paths[line];
        !p.closed && (p.pts.first() == Some(&at) || p.pts.last() == Some(&at))
    };
    if !find_intersections(&segs).unwrap().overlaps.is_empty() {
        return false;
    }
    let bad = any_intersection_where(&segs, |p| {
        let s = p.segments();
        (0..s.len()).any(|x| {
            (x + 1..s.len()).any(|y| {
                let (i, j) = (s[x], s[y]);
                if of[i].path == of[j].path {
                    !adjacent_at(&segs, &of, i, j, p.point)
                } else {
                    !(boundary(of[i].path, p.point) && boundary(of[j].path, p.point))
                }
            })
        })
    })
    .unwrap();
    bad.is_none()
}

fn jts_simple(g: &Geom) -> bool {
    match g {
        // Points are simple when no two coincide: as zero-length segments, no two meet.
        Geom::Points(p) => {
            let segs: Vec<Segment2> = p.iter().map(|&q| Segment2::new(q, q)).collect();
            find_intersections(&segs).unwrap().points.is_empty()
        }
        Geom::Line(l) => lines_simple(std::slice::from_ref(l)),
        Geom::Lines(ls) => lines_simple(
            &ls.iter()
                .filter(|l| !l.is_empty())
                .cloned()
                .collect::<Vec<_>>(),
        ),
        // JTS checks each polygon's rings; different polygons of a multipolygon may touch.
        Geom::Polygons(ps) => ps.iter().all(|p| is_simple(p).unwrap()),
        Geom::Collection(parts) => parts.iter().all(jts_simple),
    }
}

#[test]
fn jts_is_simple() {
    let Some(dir) = dir_or_skip("jts-testxml/general") else {
        return;
    };
    let text = std::fs::read_to_string(dir.join("TestSimple.xml")).unwrap();
    let mut n = 0;
    for case in text.split("<case>").skip(1) {
        let case = &case[..case.find("</case>").expect("closed case")];
        let desc = case
            .split("<desc>")
            .nth(1)
            .and_then(|d| d.split("</desc>").next())
            .unwrap_or("")
            .trim();
        let a = case
            .split("<a>")
            .nth(1)
            .and_then(|d| d.split("</a>").next())
            .expect("geometry a");
        let op = case.split("<op").nth(1).expect("op");
        assert!(op.to_lowercase().contains("name=\"issimple\""), "{desc}");
        let expected = op
            .split('>')
            .nth(1)
            .unwrap()
            .split('<')
            .next()
            .unwrap()
            .trim()
            == "true";
        let g = parse_wkt(a);
        assert_eq!(jts_simple(&g), expected, "{desc}: {g:?}");
        n += 1;
    }
    assert_eq!(n, 14);
}
