//! Profiling driver for the dense case of `compgeom-bench intersect` (n long random
//! segments across the unit square, about n²/4 crossings):
//! `cargo run --release -p compgeom --example intersect_profile -- find|count [n] [reps]`.
use compgeom::intersect::{count_intersections, find_intersections};
use compgeom::{Point2, Segment2};
use std::time::Instant;

mod common;
use common::Rng;

fn main() {
    let args: Vec<String> = std::env::args().collect();
    let what = args.get(1).map(String::as_str).unwrap_or("find");
    let n: usize = args.get(2).and_then(|s| s.parse().ok()).unwrap_or(1000);
    let reps: usize = args.get(3).and_then(|s| s.parse().ok()).unwrap_or(5);
    let mut rng = Rng(3);
    let segs: Vec<Segment2> = (0..n)
        .map(|_| Segment2::new(Point2::new(0.0, rng.unit()), Point2::new(1.0, rng.unit())))
        .collect();
    let mut best = f64::MAX;
    let mut size = 0;
    for _ in 0..reps {
        let t = Instant::now();
        size = match what {
            "count" => count_intersections(&segs).unwrap().points,
            _ => find_intersections(&segs).unwrap().points.len(),
        };
        best = best.min(t.elapsed().as_secs_f64());
    }
    println!("{what} n {n}: {size} points, best {best:.4} s");
}
