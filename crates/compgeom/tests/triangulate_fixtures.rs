//! Polygon triangulation on the earcut fixture suite (read in place; see
//! /work/shared/cases/README.md §8). Every fixture is either triangulated and verified
//! exactly (plus the exact area check at all four quarter-turn rotations, which are exact
//! on f64), or refused with the reason listed here and asserted in the error message.
//!
//! Expected triangle counts are upstream's; for valid input any triangulation has
//! n − 2 + 2h triangles, which is what is asserted (and equals upstream's count where the
//! input is non-degenerate). Degenerate fixtures where upstream's count differs (it
//! drops repeated points, and triangulates invalid input) are listed with the reason.

mod common;
use common::{cases_dir, exact_shoelace2};
use compgeom::triangulate::{art_gallery, triangulate, verify_art_gallery, verify_triangulation};
use compgeom::{Point2, Polygon};
use num_rational::BigRational;
use num_traits::Zero;

/// Fixtures compgeom refuses: a phrase its error must contain, and why.
const REFUSED: &[(&str, &str, &str)] = &[
    (
        "bad-diagonals",
        "two edges overlap",
        "the ring runs twice along one edge",
    ),
    (
        "water",
        "doubles back",
        "the outer ring has a spike along x = 4224",
    ),
];

/// Fixtures whose upstream count is smaller than n − 2 + 2h because upstream drops
/// collinear and repeated vertices (compgeom keeps every vertex: a maximal set of
/// diagonals); the verifier checks ours exactly.
const KEEPS_COLLINEAR: &[&str] = &[
    "eberly-6",
    "issue34",
    "issue52",
    "rain",
    "self-tangent-3",
    "touching-holes4",
    "water-huge3",
];

/// Fixtures upstream gets wrong, with the count the exact verifier accepts from us.
const UPSTREAM_WRONG: &[(&str, usize, &str)] = &[(
    "infinite-loop-jhl",
    2,
    "the hole shares an edge with the outer ring, leaving a thin quadrilateral between \
     (0, 0) and (0, 1e-28) (upstream gives 0 triangles)",
)];

fn load(path: &std::path::Path) -> Polygon {
    let text = std::fs::read_to_string(path).unwrap();
    let rings: Vec<Vec<[f64; 2]>> = serde_json::from_str(&text).unwrap();
    let mut rings: Vec<Vec<Point2>> = rings
        .into_iter()
        .map(|r| r.into_iter().map(|[x, y]| Point2::new(x, y)).collect())
        .collect();
    let exterior = rings.remove(0);
    Polygon::new(exterior, rings)
}

fn rotate(poly: &Polygon, k: usize) -> Polygon {
    let r = |p: &Point2| match k {
        0 => *p,
        1 => Point2::new(-p.y, p.x),
        2 => Point2::new(-p.x, -p.y),
        _ => Point2::new(p.y, -p.x),
    };
    Polygon::new(
        poly.exterior.iter().map(r).collect(),
        poly.holes
            .iter()
            .map(|h| h.iter().map(r).collect())
            .collect(),
    )
}

fn area2(poly: &Polygon) -> BigRational {
    let abs = |x: BigRational| if x < BigRational::zero() { -x } else { x };
    let mut a = abs(exact_shoelace2(&poly.exterior));
    for h in &poly.holes {
        a -= abs(exact_shoelace2(h));
    }
    a
}

#[test]
fn earcut_fixtures() {
    let dir = cases_dir().join("earcut");
    if !dir.exists() {
        println!("skipped: {} not found", dir.display());
        return;
    }
    let expected: serde_json::Value =
        serde_json::from_str(&std::fs::read_to_string(dir.join("expected.json")).unwrap()).unwrap();
    let counts = expected["triangles"].as_object().unwrap();
    let mut names: Vec<&String> = counts.keys().collect();
    names.sort();
    let mut checked = 0;
    for name in names {
        let poly = load(&dir.join("fixtures").join(format!("{name}.json")));
        let want = counts[name].as_u64().unwrap() as usize;
        let result = triangulate(&poly);
        if let Some((_, phrase, why)) = REFUSED.iter().find(|r| r.0 == name) {
            let e = result.expect_err(name).to_string();
            assert!(e.contains(phrase), "{name} ({why}): {e}");
            continue;
        }
        for k in 0..4 {
            let p = rotate(&poly, k);
            let t = triangulate(&p).unwrap_or_else(|e| panic!("{name} rotated {k}: {e}"));
            verify_triangulation(&p, &t).unwrap_or_else(|e| panic!("{name} rotated {k}: {e}"));
            let sum = t
                .triangles
                .iter()
                .map(|tri| exact_shoelace2(&tri.map(|v| t.vertices[v])))
                .fold(BigRational::zero(), |a, b| a + b);
            assert_eq!(sum, area2(&p), "{name} rotated {k}: area");
            let g = art_gallery(&t);
            verify_art_gallery(&t, &g).unwrap_or_else(|e| panic!("{name}: {e}"));
            let ours = t.triangles.len();
            if let Some((_, ours_want, why)) = UPSTREAM_WRONG.iter().find(|r| r.0 == name) {
                assert_eq!(ours, *ours_want, "{name} ({why})");
            } else if KEEPS_COLLINEAR.contains(&name.as_str()) {
                assert!(ours > want, "{name}: {ours} vs upstream {want}");
            } else {
                assert_eq!(ours, want, "{name} rotated {k}");
            }
        }
        checked += 1;
    }
    assert_eq!(checked + REFUSED.len(), counts.len());
}
