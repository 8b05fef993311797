//! Profiling driver for the dense case of `compgeom-bench intersect` (n long random
//! segments across the unit square, about n²/4 crossings):
//! `cargo run --release -p compgeom --example intersect_profile -- find|count [n] [reps] [input]`.
//! `input` is `long` (the default), `short` (length below 0.008) or `grid` (ends on
//! the 100×100 integer grid within 4 of each other), as the bench's three rows are
//! made (not the same random numbers), or `bench-long`: the bench's long row exactly. With `COMPGEOM_PROFILE_CHURN=1` every call is
//! preceded by what the bench runs between two finds (a count, and a 27 MB vector grown
//! by pushes and dropped, as geo's `collect()`), and the minor page faults of the calls
//! are printed (the bench's memory state: fresh pages or reused ones).
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
    // `bench-long` is the bench's long row itself: its seed, advanced past the 400,000
    // draws of the short row generated first.
    let mut rng = match input {
        "bench-long" => {
            Rng(0x5eed_0002u64.wrapping_add(400_000u64.wrapping_mul(0x9E37_79B9_7F4A_7C15)))
        }
        _ => Rng(3),
    };
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
    let churn = std::env::var("COMPGEOM_PROFILE_CHURN").is_ok_and(|v| v == "1");
    let mut best = f64::MAX;
    let mut size = 0;
    let mut faults = 0;
    for _ in 0..reps {
        if churn {
            std::hint::black_box(count_intersections(&segs).unwrap());
            let mut v: Vec<[u64; 13]> = Vec::new();
            for k in 0..size.max(1) as u64 {
                v.push([k; 13]);
            }
            std::hint::black_box(v);
        }
        let before = minor_faults();
        let t = Instant::now();
        let out = std::hint::black_box(match what {
            "count" => (count_intersections(&segs).unwrap().points, None),
            _ => {
                let found = find_intersections(&segs).unwrap();
                (found.points.len(), Some(found))
            }
        });
        best = best.min(t.elapsed().as_secs_f64());
        faults += minor_faults() - before;
        size = out.0;
    }
    println!(
        "{what} {input} n {n}: {size} points, best {best:.4} s, {} minor faults per call",
        faults / reps.max(1) as u64
    );
}

/// The process's minor page faults so far (`/proc/self/stat`; 0 where it cannot be read).
fn minor_faults() -> u64 {
    let stat = std::fs::read_to_string("/proc/self/stat").unwrap_or_default();
    // Field 10, counted after the command name (which ends with the last ')').
    let rest = stat.rsplit_once(')').map_or("", |(_, r)| r);
    rest.split_whitespace()
        .nth(7)
        .and_then(|f| f.parse().ok())
        .unwrap_or(0)
}
