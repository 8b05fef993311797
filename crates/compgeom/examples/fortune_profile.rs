//! Paired timing of Fortune's sweep against the default (dual) Voronoi diagram, for
//! profiling the book variant.
//!
//! `cargo run --release --example fortune_profile -- <uniform N | grid K | halfgrid K> [ROUNDS] [fortune|dual]`
//!
//! With `fortune` or `dual` only that method runs once (for `valgrind --tool=callgrind`);
//! otherwise the two alternate for ROUNDS rounds and the best times and the median of the
//! per-round ratios are printed.

use compgeom::voronoi::{fortune_voronoi, voronoi_diagram, VoronoiAlgorithm};
use compgeom::Point2;
use std::time::Instant;

fn input(kind: &str, n: usize) -> Vec<Point2> {
    let mut s: u64 = 0x1234_5678;
    let mut rnd = || {
        s = s
            .wrapping_mul(6364136223846793005)
            .wrapping_add(1442695040888963407);
        s >> 11
    };
    match kind {
        "grid" | "halfgrid" => {
            // `halfgrid`: the same grid at step 0.5 (dyadic, not integer).
            let step = if kind == "grid" { 1.0 } else { 0.5 };
            let mut v: Vec<Point2> = (0..n * n)
                .map(|i| Point2::new((i % n) as f64 * step, (i / n) as f64 * step))
                .collect();
            for i in (1..v.len()).rev() {
                let j = (rnd() % (i as u64 + 1)) as usize;
                v.swap(i, j);
            }
            v
        }
        _ => (0..n)
            .map(|_| {
                let x = rnd() as f64 / (1u64 << 53) as f64;
                let y = rnd() as f64 / (1u64 << 53) as f64;
                Point2::new(x, y)
            })
            .collect(),
    }
}

fn main() -> Result<(), compgeom::Error> {
    let args: Vec<String> = std::env::args().skip(1).collect();
    let kind = args.first().map(String::as_str).unwrap_or("uniform");
    let n: usize = args.get(1).and_then(|a| a.parse().ok()).unwrap_or(100_000);
    let rounds: usize = args.get(2).and_then(|a| a.parse().ok()).unwrap_or(5);
    let only = args.get(3).map(String::as_str);
    let pts = input(kind, n);
    match only {
        Some("fortune") => {
            let d = fortune_voronoi(&pts)?;
            println!("fortune: {} vertices", d.vertices.len());
            return Ok(());
        }
        Some("dual") => {
            let d = voronoi_diagram(&pts, VoronoiAlgorithm::Default)?;
            println!("dual: {} vertices", d.vertices.len());
            return Ok(());
        }
        _ => {}
    }
    let (mut bf, mut bd) = (f64::INFINITY, f64::INFINITY);
    let mut ratios = Vec::new();
    for r in 0..rounds {
        let go = |fortune: bool| -> Result<f64, compgeom::Error> {
            let t = Instant::now();
            let d = if fortune {
                fortune_voronoi(&pts)?
            } else {
                voronoi_diagram(&pts, VoronoiAlgorithm::Default)?
            };
            let e = t.elapsed().as_secs_f64() * 1e3;
            drop(d);
            Ok(e)
        };
        // Alternate which goes first.
        let (tf, td) = if r % 2 == 0 {
            let f = go(true)?;
            (f, go(false)?)
        } else {
            let d = go(false)?;
            (go(true)?, d)
        };
        bf = bf.min(tf);
        bd = bd.min(td);
        ratios.push(tf / td);
    }
    ratios.sort_by(f64::total_cmp);
    println!(
        "{kind} {n}: fortune {bf:.1} ms, default {bd:.1} ms, best ratio {:.2}, median ratio {:.2}",
        bf / bd,
        ratios[ratios.len() / 2]
    );
    Ok(())
}
