//! The smallest enclosing disc on the shared fixture suite jts-unit/smallest-enclosing-circle.json
//! (read in place; see the cases README). Each case: centre and radius are within the suite's
//! 1e-5 tolerance, compgeom's support points are among the expected extremal points, and every
//! expected extremal point lies exactly on compgeom's circle. (The defining set is not unique:
//! for a right triangle JTS lists all three corners, compgeom the two ends of the diameter,
//! which define the same disc.) An empty input has no disc: JTS returns no centre, compgeom
//! an `Err`.

mod common;
use common::cases_dir;
use compgeom::io::{read_points, Format};
use compgeom::kernel::{incircle, orient2d, CircleSide, Orientation};
use compgeom::lp::smallest_enclosing_disc;
use compgeom::Point2;
use num_rational::BigRational;

/// Exactly: does `p` lie on the circle through the support points?
fn on_circle(support: &[Point2], p: Point2) -> bool {
    match *support {
        [a] => a == p,
        // Thales: p is on the circle with diameter ab iff (p − a)·(p − b) = 0.
        [a, b] => {
            let r = |v: f64| BigRational::from_float(v).unwrap();
            let dot = (r(p.x) - r(a.x)) * (r(p.x) - r(b.x)) + (r(p.y) - r(a.y)) * (r(p.y) - r(b.y));
            dot == BigRational::from_integer(0.into())
        }
        [a, b, c] => {
            orient2d(a, b, c) != Orientation::Collinear
                && incircle(a, b, c, p) == CircleSide::OnCircle
        }
        _ => false,
    }
}

#[test]
fn jts_smallest_enclosing_circle() {
    let path = cases_dir().join("jts-unit/smallest-enclosing-circle.json");
    let Ok(text) = std::fs::read_to_string(&path) else {
        println!("skipped: {} not found", path.display());
        return;
    };
    let suite: serde_json::Value = serde_json::from_str(&text).unwrap();
    let cases = suite["cases"].as_array().unwrap();
    assert!(!cases.is_empty());
    for case in cases {
        let name = case["test"].as_str().unwrap();
        let input = read_points(case["input"].as_str().unwrap(), Format::Wkt, name).unwrap();
        let expected = read_points(
            case["expected_extremal_points"].as_str().unwrap(),
            Format::Wkt,
            name,
        )
        .unwrap();
        let result = smallest_enclosing_disc(&input, 0);
        if case["expected_centre"].is_null() {
            assert!(input.is_empty() && expected.is_empty(), "{name}");
            assert!(result.is_err(), "{name}: the disc of no points");
            continue;
        }
        let disc = result.unwrap_or_else(|e| panic!("{name}: {e}"));
        for s in &disc.support {
            assert!(
                expected.contains(s),
                "{name}: support point {s:?} not expected"
            );
        }
        for e in &expected {
            assert!(
                on_circle(&disc.support, *e),
                "{name}: {e:?} is not on the circle"
            );
        }
        let c = case["expected_centre"].as_array().unwrap();
        let (cx, cy) = (c[0].as_f64().unwrap(), c[1].as_f64().unwrap());
        let r = case["expected_radius"].as_f64().unwrap();
        assert!(
            (disc.center.x - cx).hypot(disc.center.y - cy) <= 1e-5,
            "{name}"
        );
        assert!((disc.radius - r).abs() <= 1e-5, "{name}");
    }
}
