//! Convex hull of a few points, by each algorithm, checked by the verifier.
//!
//! `cargo run -p compgeom --example hull`

use compgeom::hull::{convex_hull, verify_convex_hull, HullAlgorithm, HullOptions};
use compgeom::Point2;

fn main() -> Result<(), compgeom::Error> {
    // A 4x3 grid of points, a duplicate, and a point inside: plenty of collinear input.
    let mut points: Vec<Point2> = (0..4)
        .flat_map(|x| (0..3).map(move |y| Point2::new(x as f64, y as f64)))
        .collect();
    points.push(Point2::new(3.0, 2.0));
    points.push(Point2::new(1.5, 0.5));

    for algorithm in [
        HullAlgorithm::Default,
        HullAlgorithm::Andrew,
        HullAlgorithm::Slow,
    ] {
        for keep_collinear in [false, true] {
            let opts = HullOptions::new()
                .with_algorithm(algorithm)
                .with_keep_collinear(keep_collinear);
            let hull = convex_hull(&points, &opts)?;
            verify_convex_hull(&points, &hull, keep_collinear)?;
            let shown: Vec<String> = hull.iter().map(|p| format!("({}, {})", p.x, p.y)).collect();
            println!(
                "{algorithm:?} keep_collinear={keep_collinear}: {} vertices, clockwise: {}",
                hull.len(),
                shown.join(" ")
            );
        }
    }
    let strict = convex_hull(&points, &HullOptions::default())?;
    assert_eq!(strict.len(), 4);
    Ok(())
}
