//! The constrained Delaunay triangulation of the benchmark's polygon with holes (a circle of
//! 20 000 vertices around a 30 × 30 grid of circular holes of 100 vertices each), once, for
//! `valgrind --tool=callgrind`; with an argument `N`, timed N times (best printed).
//!
//! `cargo run --release --example cdt_profile [N]`

use compgeom::delaunay::constrained_delaunay;
use compgeom::{Point2, Segment2};
use std::time::Instant;

fn main() -> Result<(), compgeom::Error> {
    let ring = |cx: f64, cy: f64, r: f64, n: usize, ccw: bool| -> Vec<Point2> {
        (0..n)
            .map(|i| {
                let t = i as f64 / n as f64 * std::f64::consts::TAU;
                let t = if ccw { t } else { -t };
                Point2::new(cx + r * t.cos(), cy + r * t.sin())
            })
            .collect()
    };
    let (outer, k, hole) = (20_000, 30, 100);
    let mut rings = vec![ring(0.0, 0.0, 1.0, outer, true)];
    let step = 1.2 / k as f64;
    for i in 0..k {
        for j in 0..k {
            let c = (
                -0.6 + (i as f64 + 0.5) * step,
                -0.6 + (j as f64 + 0.5) * step,
            );
            rings.push(ring(c.0, c.1, step * 0.3, hole, false));
        }
    }
    let mut verts = Vec::new();
    let mut segs = Vec::new();
    for r in &rings {
        for i in 0..r.len() {
            verts.push(r[i]);
            segs.push(Segment2::new(r[i], r[(i + 1) % r.len()]));
        }
    }
    let runs: usize = std::env::args()
        .nth(1)
        .and_then(|a| a.parse().ok())
        .unwrap_or(1);
    let mut best = f64::INFINITY;
    let mut tris = 0;
    for _ in 0..runs {
        let t = Instant::now();
        let cdt = constrained_delaunay(&verts, &segs)?;
        best = best.min(t.elapsed().as_secs_f64() * 1e3);
        tris = cdt.triangulation.triangles().len();
    }
    println!(
        "{} vertices, {tris} triangles, best {best:.1} ms",
        verts.len()
    );
    Ok(())
}
