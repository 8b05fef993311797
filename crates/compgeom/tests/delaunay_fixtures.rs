//! Delaunay fixtures from ../shared/cases: delaunator's robustness sets and JTS's Delaunay
//! unit cases. Every case must pass.

mod common;
use common::existing_cases_dir;
use compgeom::delaunay::{
    delaunay, delaunay_with, verify_delaunay, DelaunayAlgorithm, DelaunayOptions, Triangulation,
};
use compgeom::Point2;
use serde_json::Value;

fn both(pts: &[Point2]) -> Triangulation {
    let f = delaunay(pts).unwrap();
    verify_delaunay(&f).unwrap();
    let b = delaunay_with(
        pts,
        &DelaunayOptions::new().with_algorithm(DelaunayAlgorithm::Incremental),
    )
    .unwrap();
    verify_delaunay(&b).unwrap();
    assert_eq!(f.triangles().len(), b.triangles().len());
    f
}

fn json_points(v: &Value) -> Vec<Point2> {
    v.as_array()
        .unwrap()
        .iter()
        .map(|p| Point2::new(p[0].as_f64().unwrap(), p[1].as_f64().unwrap()))
        .collect()
}

#[test]
fn delaunator_fixtures() {
    let Some(dir) = existing_cases_dir() else {
        return;
    };
    let dir = dir.join("delaunator");
    let expected: Value =
        serde_json::from_str(&std::fs::read_to_string(dir.join("expected.json")).unwrap()).unwrap();
    let mut ran = 0;
    for (file, exp) in expected["fixtures"].as_object().unwrap() {
        let text = std::fs::read_to_string(dir.join("fixtures").join(file)).unwrap();
        let mut pts = json_points(&serde_json::from_str(&text).unwrap());
        let t = both(&pts);
        assert!(exp["valid"].as_bool().unwrap_or(true));
        if let Some(n) = exp["triangles"].as_u64() {
            assert_eq!(t.triangles().len() as u64, n, "{file}");
        }
        if let Some(p) = exp.get("after_replacing_point_0_with") {
            pts[0] = Point2::new(p[0].as_f64().unwrap(), p[1].as_f64().unwrap());
            let t = both(&pts);
            assert_eq!(
                t.triangles().len() as u64,
                exp["triangles_after_replacement"].as_u64().unwrap(),
                "{file}"
            );
        }
        ran += 1;
    }
    for case in expected["inline_cases"].as_array().unwrap() {
        let pts = json_points(&case["points"]);
        let t = both(&pts);
        let n = case["triangles"].as_array().unwrap().len() / 3;
        assert_eq!(t.triangles().len(), n, "{}", case["name"]);
        if let Some(h) = case["hull_point_count"].as_u64() {
            // Collinear: every distinct point is on the "hull" (the line).
            assert_eq!(t.vertices().len() as u64, h);
        }
        ran += 1;
    }
    assert_eq!(ran, 7);
}

/// All coordinate pairs of a WKT text (a third coordinate, if any, is dropped).
fn wkt_coords(wkt: &str) -> Vec<Vec<Point2>> {
    // Innermost parenthesised lists: one per ring/linestring/point.
    let mut groups = Vec::new();
    let mut rest = wkt;
    while let Some(close) = rest.find(')') {
        let Some(open) = rest[..close].rfind('(') else {
            rest = &rest[close + 1..];
            continue;
        };
        let inner = &rest[open + 1..close];
        if !inner.trim().is_empty() {
            let pts: Vec<Point2> = inner
                .split(',')
                .map(|c| {
                    let n: Vec<f64> = c.split_whitespace().map(|s| s.parse().unwrap()).collect();
                    Point2::new(n[0], n[1])
                })
                .collect();
            groups.push(pts);
        }
        rest = &rest[close + 1..];
    }
    groups
}

/// True when the edge with endpoint keys `e` is interior and its two triangles' four
/// vertices are exactly cocircular (so either diagonal is Delaunay).
fn cocircular_diagonal(t: &Triangulation, e: ((u64, u64), (u64, u64))) -> bool {
    use compgeom::kernel::{incircle, CircleSide};
    let v = t.vertices();
    for (i, tr) in t.triangles().iter().enumerate() {
        for k in 0..3 {
            let (a, b) = (tr[(k + 1) % 3], tr[(k + 2) % 3]);
            let (p, q) = (key(v[a as usize]), key(v[b as usize]));
            if (p.min(q), p.max(q)) != e {
                continue;
            }
            let n = t.neighbors()[i][k];
            if n == compgeom::delaunay::NO_NEIGHBOR {
                return false;
            }
            let d = *t.triangles()[n as usize]
                .iter()
                .find(|&&x| x != a && x != b)
                .unwrap();
            let [x, y, z] = tr.map(|j| v[j as usize]);
            return incircle(x, y, z, v[d as usize]) == CircleSide::OnCircle;
        }
    }
    false
}

fn key(p: Point2) -> (u64, u64) {
    (p.x.to_bits(), p.y.to_bits())
}

#[test]
fn jts_delaunay_cases() {
    let Some(dir) = existing_cases_dir() else {
        return;
    };
    let text = std::fs::read_to_string(dir.join("jts-unit/delaunay.json")).unwrap();
    let cases: Value = serde_json::from_str(&text).unwrap();
    for case in cases["cases"].as_array().unwrap() {
        let name = case["test"].as_str().unwrap();
        let sites: Vec<Point2> = wkt_coords(case["sites"].as_str().unwrap()).concat();
        let t = both(&sites);
        let v = t.vertices();
        match case["output"].as_str().unwrap() {
            "triangles" => {
                let mut ours: Vec<Vec<(u64, u64)>> = t
                    .triangles()
                    .iter()
                    .map(|tr| {
                        let mut k: Vec<_> = tr.iter().map(|&i| key(v[i as usize])).collect();
                        k.sort();
                        k
                    })
                    .collect();
                ours.sort();
                let mut theirs: Vec<Vec<(u64, u64)>> =
                    wkt_coords(case["expected"].as_str().unwrap())
                        .into_iter()
                        .map(|ring| {
                            let mut k: Vec<_> = ring[..3].iter().map(|&p| key(p)).collect();
                            k.sort();
                            k
                        })
                        .collect();
                theirs.sort();
                assert_eq!(ours, theirs, "{name}");
            }
            "edges" => {
                let mut ours: Vec<((u64, u64), (u64, u64))> = t
                    .edges()
                    .iter()
                    .map(|&(a, b)| {
                        let (p, q) = (key(v[a as usize]), key(v[b as usize]));
                        (p.min(q), p.max(q))
                    })
                    .collect();
                ours.sort();
                let mut theirs: Vec<_> = wkt_coords(case["expected"].as_str().unwrap())
                    .into_iter()
                    .map(|s| {
                        let (p, q) = (key(s[0]), key(s[1]));
                        (p.min(q), p.max(q))
                    })
                    .collect();
                theirs.sort();
                assert_eq!(ours.len(), theirs.len(), "{name}");
                if ours != theirs {
                    // Only allowed where the triangulation is not unique: each of our edges
                    // that JTS lacks must be the diagonal of an exactly cocircular quad.
                    let diff: Vec<_> = ours
                        .iter()
                        .filter(|e| theirs.binary_search(e).is_err())
                        .collect();
                    for e in diff {
                        assert!(
                            cocircular_diagonal(&t, *e),
                            "{name}: edge {e:?} differs and is not ambiguous"
                        );
                    }
                }
            }
            // "property": the union of the triangles is the convex hull, which
            // verify_delaunay (inside `both`) checks exactly.
            _ => assert!(!t.is_degenerate(), "{name}"),
        }
    }
}
