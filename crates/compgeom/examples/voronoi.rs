//! Voronoi diagram of a small point set: Fortune's sweep, the cells clipped to a box, the
//! exact verifier, and a nearest-site query.
//!
//! `cargo run --example voronoi [GRID_SIDE]` — with an argument, times a k × k grid instead.

use compgeom::voronoi::{
    clip_cells, fortune_voronoi, verify_cells, verify_voronoi, ClipRegion, NearestSite,
};
use compgeom::Point2;

fn main() -> Result<(), compgeom::Error> {
    if std::env::args().nth(1).as_deref() == Some("uniform") {
        // `cargo run --release --example voronoi uniform`: time the sweep and the clipping.
        let mut s: u64 = 1;
        let mut rnd = || {
            s = s
                .wrapping_mul(6364136223846793005)
                .wrapping_add(1442695040888963407);
            (s >> 11) as f64 / (1u64 << 53) as f64
        };
        let pts: Vec<Point2> = (0..100_000).map(|_| Point2::new(rnd(), rnd())).collect();
        let t = std::time::Instant::now();
        let d = fortune_voronoi(&pts)?;
        let t1 = t.elapsed();
        let region = ClipRegion::rect(0.0, 0.0, 1.0, 1.0)?;
        let t = std::time::Instant::now();
        let cells = clip_cells(&d, &region);
        println!(
            "1e5 uniform: sweep {t1:?}, clip {:?} ({} cells)",
            t.elapsed(),
            cells.len()
        );
        return Ok(());
    }
    if let Some(k) = std::env::args()
        .nth(1)
        .and_then(|a| a.parse::<usize>().ok())
    {
        let pts: Vec<Point2> = (0..k * k)
            .map(|i| Point2::new((i % k) as f64, (i / k) as f64))
            .collect();
        let t = std::time::Instant::now();
        let d = fortune_voronoi(&pts)?;
        println!(
            "{k}x{k} grid: {} vertices in {:?}",
            d.vertices.len(),
            t.elapsed()
        );
        return Ok(());
    }
    let pts = [
        Point2::new(0.0, 0.0),
        Point2::new(4.0, 0.0),
        Point2::new(4.0, 4.0),
        Point2::new(0.0, 4.0),
        Point2::new(2.0, 2.0),
        Point2::new(0.0, 0.0), // a duplicate: shares cell 0
    ];
    let d = fortune_voronoi(&pts)?;
    verify_voronoi(&pts, &d)?;
    let region = ClipRegion::rect(-1.0, -1.0, 5.0, 5.0)?;
    let cells = clip_cells(&d, &region);
    verify_cells(&d, &region, &cells)?;
    for (s, cell) in cells.iter().enumerate() {
        println!(
            "site {} at {:?}: {:?}",
            d.site_input_index[s], d.sites[s], cell
        );
    }
    for v in &d.vertices {
        println!(
            "vertex {:?} on the circle through sites {:?}",
            v.point, v.sites
        );
    }
    let post = NearestSite::new(&d);
    println!(
        "nearest to (3, 0.5): site {:?}",
        post.nearest(Point2::new(3.0, 0.5))
    );
    Ok(())
}
