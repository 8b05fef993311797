//! Profiling driver for the dense case of `compgeom-bench intersect` (n long random
//! segments across the unit square, about n²/4 crossings):
//! `cargo run --release -p compgeom --example intersect_profile -- find|count [n] [reps] [input]`.
//! `input` is `long` (the default), `short` (length below 0.008) or `grid` (ends on
//! the 100×100 integer grid within 4 of each other), as the bench's three rows are
//! made (not the same random numbers).
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
    let input = args.get(4).map(String::as_str).unwrap_or("long");
    let mut rng = Rng(3);
    let segs: Vec<Segment2> = (0..n)
        .map(|_| match input {
            "short" => {
                let a = Point2::new(rng.unit(), rng.unit());
                let (len, angle) = (0.008 * rng.unit(), std::f64::consts::TAU * rng.unit());
                Segment2::new(
                    a,
                    Point2::new(a.x + len * angle.cos(), a.y + len * angle.sin()),
                )
            }
            "grid" => {
                let mut int = |lo: f64, hi: f64| lo + (rng.unit() * (hi - lo + 1.0)).floor();
                let (x, y) = (int(0.0, 100.0), int(0.0, 100.0));
                let (u, v) = (
                    (x + int(-4.0, 4.0)).clamp(0.0, 100.0),
                    (y + int(-4.0, 4.0)).clamp(0.0, 100.0),
                );
                Segment2::new(Point2::new(x, y), Point2::new(u, v))
            }
            _ => Segment2::new(Point2::new(0.0, rng.unit()), Point2::new(1.0, rng.unit())),
        })
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
    println!("{what} {input} n {n}: {size} points, best {best:.4} s");
}
