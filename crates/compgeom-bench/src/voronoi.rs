//! Voronoi diagrams (book chapter 7): compgeom's Fortune sweep (exact) against voronoice
//! (the dual of delaunator's triangulation, floating point, cells clipped to a box), with
//! delaunator's triangulation alone as the floor any dual-based method pays.
//!
//! Inputs: uniform points in the unit square (1e5 and 1e6) and the full 1000 × 1000 integer
//! grid, shuffled (10⁶ points, every grid square cocircular: the degenerate workload).
//! `--quick` uses 1e4, 1e5 and a 300 × 300 grid.
//!
//! Timed: compgeom `fortune_voronoi` (diagram) and `fortune_voronoi` + `clip_cells` (cells
//! in input order, clipped to the bounding box: the same output as voronoice's);
//! voronoice `VoronoiBuilder::build` with `ClipBehavior::Clip` (sites copied outside the
//! clock; its builder takes them by value); delaunator `triangulate`.
//! Checked once outside the clock: compgeom's diagram with the exact verifier (1e5 and
//! below; the full verifier at 1e6 would dominate the run), cell areas tile the box.

use crate::util::{best_of, ms, Rng};
use compgeom::voronoi::{clip_cells, fortune_voronoi, verify_cells, verify_voronoi, ClipRegion};
use compgeom::Point2;
use std::time::Duration;

fn uniform(n: usize, seed: u64) -> Vec<Point2> {
    let mut r = Rng::new(seed);
    (0..n).map(|_| Point2::new(r.unit(), r.unit())).collect()
}

fn grid(k: usize, seed: u64) -> Vec<Point2> {
    let mut v: Vec<Point2> = (0..k * k)
        .map(|i| Point2::new((i % k) as f64, (i / k) as f64))
        .collect();
    let mut r = Rng::new(seed);
    for i in (1..v.len()).rev() {
        let j = (r.next_u64() % (i as u64 + 1)) as usize;
        v.swap(i, j);
    }
    v
}

/// The best of `runs` times reported by `f` (for calls whose setup must stay off the clock).
fn best_inner(runs: usize, mut f: impl FnMut() -> Duration) -> Duration {
    (0..runs.max(1)).map(|_| f()).min().unwrap_or_default()
}

fn row(name: &str, what: &str, t: Duration, base: Duration) {
    println!(
        "{name:<22} {what:<34} {:>10.1} ms   ratio {:>5.2}",
        ms(t),
        ms(t) / ms(base)
    );
}

/// Run the group.
pub fn run(quick: bool) -> Result<(), String> {
    let (small, large, k) = if quick {
        (10_000, 100_000, 300)
    } else {
        (100_000, 1_000_000, 1000)
    };
    let inputs = [
        (format!("uniform {small}"), uniform(small, 1)),
        (format!("uniform {large}"), uniform(large, 2)),
        (format!("grid {k}x{k}"), grid(k, 3)),
    ];
    let runs = if quick { 1 } else { 3 };
    println!("voronoi: ratio = time / voronoice time (lower is better); best of {runs}");
    let mut fortune_times = Vec::new();
    for (name, pts) in &inputs {
        let b = compgeom::Bbox2::of_points(pts);
        let region = ClipRegion::from_bbox(b).map_err(|e| e.to_string())?;
        // Check once, outside the clock.
        let d = fortune_voronoi(pts).map_err(|e| e.to_string())?;
        if pts.len() <= 100_000 {
            verify_voronoi(pts, &d).map_err(|e| format!("{name}: {e}"))?;
        } else {
            d.validate().map_err(|e| format!("{name}: {e}"))?;
        }
        let cells = clip_cells(&d, &region);
        verify_cells(&d, &region, &cells).map_err(|e| format!("{name}: {e}"))?;
        drop((d, cells));

        let vp: Vec<voronoice::Point> = pts
            .iter()
            .map(|p| voronoice::Point { x: p.x, y: p.y })
            .collect();
        let bbox = voronoice::BoundingBox::new(
            voronoice::Point {
                x: (b.min.x + b.max.x) / 2.0,
                y: (b.min.y + b.max.y) / 2.0,
            },
            b.width(),
            b.height(),
        );
        let check = voronoice::VoronoiBuilder::default()
            .set_sites(vp.clone())
            .set_bounding_box(bbox.clone())
            .set_clip_behavior(voronoice::ClipBehavior::Clip)
            .build()
            .ok_or("voronoice failed")?;
        let vcells = check.cells().len();
        drop(check);

        let t_voronoice = best_inner(runs, || {
            let sites = vp.clone();
            let t0 = std::time::Instant::now();
            let v = voronoice::VoronoiBuilder::default()
                .set_sites(sites)
                .set_bounding_box(bbox.clone())
                .set_clip_behavior(voronoice::ClipBehavior::Clip)
                .build();
            let e = t0.elapsed();
            drop(v);
            e
        });
        let t_delaunator = best_of(runs, || delaunator::triangulate(&vp));
        let t_fortune = best_of(runs, || fortune_voronoi(pts));
        let t_cells = best_of(runs, || {
            fortune_voronoi(pts).map(|d| clip_cells(&d, &region))
        });
        println!(
            "{name} ({} points; voronoice gave {vcells} cells)",
            pts.len()
        );
        row(
            "  voronoice",
            "dual of delaunator, clipped cells",
            t_voronoice,
            t_voronoice,
        );
        row(
            "  delaunator",
            "triangulation only",
            t_delaunator,
            t_voronoice,
        );
        row(
            "  compgeom fortune",
            "diagram (exact)",
            t_fortune,
            t_voronoice,
        );
        row(
            "  compgeom fortune+clip",
            "diagram + clipped cells",
            t_cells,
            t_voronoice,
        );
        fortune_times.push(t_cells);
    }
    if fortune_times.len() >= 2 {
        let g = ms(fortune_times[1]) / ms(fortune_times[0]);
        println!(
            "growth {small} -> {large} (fortune+clip): x{g:.1} for x{} points",
            large / small
        );
    }
    Ok(())
}
