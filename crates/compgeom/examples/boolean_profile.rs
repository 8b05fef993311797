//! Profiling driver for the boolean pipeline (the inputs of `compgeom-bench boolean`):
//! `cargo run --release -p compgeom --example boolean_profile -- star|squares|cells [n] [reps]`.
//! `cells` is a raster-like coverage: about 70% of the cells of an n × n grid, each a
//! unit square of its own, dissolved by `union_all` (axis-parallel, shared sides).
use compgeom::overlay::{boolean, union_all, BooleanOp};
use compgeom::{MultiPolygon, Point2, Polygon};
use std::time::Instant;

mod common;
use common::Rng;

fn star(rng: &mut Rng, n: usize, cx: f64) -> MultiPolygon {
    let mut angles: Vec<f64> = (0..n).map(|_| std::f64::consts::TAU * rng.unit()).collect();
    angles.sort_by(f64::total_cmp);
    let pts = angles
        .into_iter()
        .map(|a| {
            let r = 0.8 + 0.15 * (5.0 * a).sin() + 2.0 / n as f64 * rng.unit();
            Point2::new(cx + r * a.cos(), r * a.sin())
        })
        .collect();
    MultiPolygon(vec![Polygon::new(pts, vec![])])
}

fn main() {
    let args: Vec<String> = std::env::args().collect();
    let what = args.get(1).map(String::as_str).unwrap_or("star");
    let n: usize = args.get(2).and_then(|s| s.parse().ok()).unwrap_or(100_000);
    let reps: usize = args.get(3).and_then(|s| s.parse().ok()).unwrap_or(5);
    let mut rng = Rng(4);
    let t = Instant::now();
    let mut best = f64::MAX;
    match what {
        "star" => {
            let a = star(&mut rng, n, 0.0);
            let b = star(&mut rng, n, 0.3);
            for _ in 0..reps {
                let t = Instant::now();
                let r = boolean(&a, &b, BooleanOp::Union).unwrap();
                best = best.min(t.elapsed().as_secs_f64());
                std::hint::black_box(r);
            }
        }
        "cells" => {
            let p = |x: usize, y: usize| Point2::new(x as f64, y as f64);
            let mut cells = MultiPolygon::default();
            for y in 0..n {
                for x in 0..n {
                    if rng.unit() < 0.7 {
                        let ring = vec![p(x, y), p(x + 1, y), p(x + 1, y + 1), p(x, y + 1)];
                        cells.0.push(Polygon::new(ring, vec![]));
                    }
                }
            }
            for _ in 0..reps {
                let t = Instant::now();
                let r = union_all(&cells).unwrap();
                best = best.min(t.elapsed().as_secs_f64());
                std::hint::black_box(r);
            }
        }
        _ => {
            let sq = MultiPolygon(
                (0..n)
                    .map(|_| {
                        let (x, y, w) = (rng.unit(), rng.unit(), 0.005 + 0.02 * rng.unit());
                        let p = Point2::new;
                        Polygon::new(
                            vec![p(x, y), p(x + w, y), p(x + w, y + w), p(x, y + w)],
                            vec![],
                        )
                    })
                    .collect(),
            );
            for _ in 0..reps {
                let t = Instant::now();
                let r = union_all(&sq).unwrap();
                best = best.min(t.elapsed().as_secs_f64());
                std::hint::black_box(r);
            }
        }
    }
    println!(
        "{what} {n}: best {:.2} ms, total {:.2} s",
        best * 1e3,
        t.elapsed().as_secs_f64()
    );
}
