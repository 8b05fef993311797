//! Chapter 4 in a few lines: a 2D linear program on random constraints, the half-plane
//! intersection of a few of them, and the smallest enclosing disc of random points.
//!
//! ```text
//! cargo run --release -p compgeom --example lp [N]
//! ```

use compgeom::lp::{intersect_halfplanes, lp2d, smallest_enclosing_disc, HalfPlane, Lp2Options};
use compgeom::{Point2, Vector2};
use std::time::Instant;

fn main() -> Result<(), compgeom::Error> {
    let n: usize = std::env::args()
        .nth(1)
        .and_then(|s| s.parse().ok())
        .unwrap_or(100_000);
    // Constraints tangent to the unit circle (golden-angle spacing), slightly offset.
    let hs: Vec<HalfPlane> = (0..n)
        .map(|k| {
            // A scrambled angle: the order of the constraints does not follow the circle.
            let t = ((k as u64).wrapping_mul(0x9e37_79b9_7f4a_7c15) >> 11) as f64
                / (1u64 << 53) as f64
                * std::f64::consts::TAU;
            HalfPlane::new(
                t.cos(),
                t.sin(),
                1.0 + 1e-3 * ((k * 7919) % 1000) as f64 / 1000.0,
            )
        })
        .collect();
    let start = Instant::now();
    let sol = lp2d(&hs, Vector2::new(0.3, 0.7), &Lp2Options::default())?;
    println!(
        "lp2d on {n} constraints: {sol:?} in {:?} ({} exact fallbacks)",
        start.elapsed(),
        compgeom::lp::exact_fallbacks()
    );

    let m = 2000.min(n);
    let before = compgeom::lp::exact_fallbacks();
    let start = Instant::now();
    let region = intersect_halfplanes(&hs[..m], 1)?;
    println!(
        "intersection of the first {m} half-planes: {} with {} corners in {:?} ({} exact fallbacks)",
        region.kind.name(),
        region.vertices.len(),
        start.elapsed(),
        compgeom::lp::exact_fallbacks() - before
    );

    let pts: Vec<Point2> = (0..n)
        .map(|k| {
            let t = k as f64 * 0.618_033_988_75;
            let r = ((k * 7919) % 1000) as f64 / 1000.0;
            Point2::new(r * t.cos(), r * t.sin())
        })
        .collect();
    let start = Instant::now();
    let disc = smallest_enclosing_disc(&pts, 0)?;
    println!(
        "smallest enclosing disc of {n} points: centre ({}, {}), radius {}, {} support points, in {:?}",
        disc.center.x,
        disc.center.y,
        disc.radius,
        disc.support.len(),
        start.elapsed()
    );
    Ok(())
}
