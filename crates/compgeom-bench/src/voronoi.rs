//! Voronoi diagrams (book chapter 7): compgeom's default (the dual of its exact Delaunay
//! triangulation) and Fortune's sweep (the book's VORONOIDIAGRAM, exact) against voronoice
//! (the dual of delaunator's triangulation, floating point, cells clipped to a box), with
//! the Delaunay peers alone (delaunator, spade `bulk_load`) as the floor any dual-based
//! method pays.
//!
//! Inputs: uniform points in the unit square (1e5 and 1e6) and the full 1000 × 1000 integer
//! grid, shuffled (10⁶ points, every grid square cocircular: the degenerate workload).
//! `--quick` uses 1e4, 1e5 and a 300 × 300 grid.
//!
//! Timed: compgeom `voronoi_cells` + `VoronoiCells::clip` (the default dual in its compact
//! form, cells in input order clipped to the bounding box: what voronoice builds — its
//! `Voronoi` holds the triangulation, the circumcentres plus clip corners and one index list
//! per cell — so this is the like-for-like row); `voronoi_diagram` (default and Fortune; the
//! full half-edge diagram) and the same + `clip_cells`; voronoice `VoronoiBuilder::build` with `ClipBehavior::Clip` (sites copied
//! outside the clock; its builder takes them by value); delaunator `triangulate`; spade
//! `bulk_load` (its points copied outside the clock).
//! Checked once outside the clock: both compgeom diagrams with the exact verifier (1e5 and
//! below; the full verifier at 1e6 would dominate the run), the same numbers of vertices
//! and edges from both, cell areas tile the box.
//!
//! Measured (release, 2-core machine shared with other jobs, load average 2.1 → 1.2, best
//! of 3, not alternated; ratio = time / voronoice):
//!
//! | input | voronoice ms | compgeom delaunay | cells | cells+clip | fortune / default diagram |
//! |---|---|---|---|---|---|
//! | uniform 1e5 | 43.4 | 0.61 | 0.88 | 0.98 | 3.03 |
//! | uniform 1e6 | 772.3 | 0.55 | 0.84 | 0.95 | 2.36 |
//! | grid 1000², shuffled | 676.5 | 0.36 | 0.57 | 0.84 | 4.68 |
//!
//! Fortune was over 3× the default diagram on the grid (and on uniform 1e5 in some runs).
//! Session 6 rebuilt its hot paths (compact beach line with one breakpoint test per level,
//! 24-byte heap records with lazy cancellation, plain-`f64` filters with proven bounds,
//! exact `i128` predicates for small-integer sites, zero-length edges found without
//! in-circle tests). Fortune / default diagram, `fortune_profile` example (alternating
//! rounds, the machine shared with other jobs; best-of / median of per-round ratios):
//!
//! | input | load | fortune ms | default ms | best-of | median | before (quiet) |
//! |---|---|---|---|---|---|---|
//! | uniform 1e5 | 2.1 | 189.5 | 114.8 | 1.65 | 1.46 | 3.03 |
//! | uniform 1e6 | 2.1 | 2303 | 1848 | 1.25 | 1.24 | 2.40 |
//! | grid 1000², shuffled | 2.1 | 1731 | 1785 | 0.97 | 1.05 | 4.59 |
//!
//! (The 1e6 times are several times the quiet ones: memory bandwidth was shared.) This
//! group's own paired line (`COMPGEOM_VORONOI_PAIRED` rounds, default 5) at load 7–9 gave
//! medians 1.74 / 1.06 / 0.95. Callgrind instructions (stable under load), Fortune vs the
//! default diagram: uniform 1e5 1751 M → 843 M (default 653 M); grid 300², shuffled,
//! 5862 M → 1090 M (default 501 M). A 300² grid of step 0.5 (dyadic, not integer; now on
//! the same exact integer path by scaling): 5.05× the default before that change, 0.78×
//! after (load 2.8, `fortune_profile halfgrid 300`).
//!
//! Quiet (load ≈ 1, four runs after all the session's changes; ranges over runs, the last
//! run's median of 5 alternating rounds in brackets): Fortune / default diagram 1.63–2.25
//! (1.41) at 1e5, 1.14–1.33 (1.21) at 1e6, 0.98–1.22 (0.97) on the grid; cells+clip /
//! voronoice 0.87–1.04 (1.01), 0.99–1.06 (1.00), 0.80–1.24 (1.01): at parity. `clip` is
//! ~200 ms of it at 1e6 on two threads (~390 ms on one), a third of that in malloc/free of
//! the per-cell vectors; visiting cells in spatial order and scattering was slower.

use crate::util::{best_of, ms, Rng};
use compgeom::voronoi::{
    clip_cells, fortune_voronoi, verify_cells, verify_voronoi, voronoi_cells, voronoi_diagram,
    ClipRegion, VoronoiAlgorithm,
};
use compgeom::Point2;
use spade::Triangulation as _;
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
    let mut times: Vec<[Duration; 4]> = Vec::new();
    for (name, pts) in &inputs {
        let b = compgeom::Bbox2::of_points(pts);
        let region = ClipRegion::from_bbox(b).map_err(|e| e.to_string())?;
        // Check once, outside the clock.
        let dual = voronoi_diagram(pts, VoronoiAlgorithm::Default).map_err(|e| e.to_string())?;
        let d = fortune_voronoi(pts).map_err(|e| e.to_string())?;
        for x in [&dual, &d] {
            if pts.len() <= 100_000 {
                verify_voronoi(pts, x).map_err(|e| format!("{name}: {e}"))?;
            } else {
                x.validate().map_err(|e| format!("{name}: {e}"))?;
            }
        }
        if (dual.vertices.len(), dual.edge_count()) != (d.vertices.len(), d.edge_count()) {
            return Err(format!("{name}: the dual and Fortune's sweep differ"));
        }
        let cells = clip_cells(&dual, &region);
        verify_cells(&dual, &region, &cells).map_err(|e| format!("{name}: {e}"))?;
        let compact = voronoi_cells(pts).map_err(|e| e.to_string())?;
        if compact.clip(&region) != cells || compact.edge_count() != dual.edge_count() {
            return Err(format!("{name}: voronoi_cells differs from the diagram"));
        }
        drop(compact);
        drop((d, dual, cells));

        let vp: Vec<voronoice::Point> = pts
            .iter()
            .map(|p| voronoice::Point { x: p.x, y: p.y })
            .collect();
        let sp: Vec<spade::Point2<f64>> =
            pts.iter().map(|p| spade::Point2::new(p.x, p.y)).collect();
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

        // voronoice's build, its input copy outside the clock.
        let voronoice_once = || {
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
        };
        let t_voronoice = best_inner(runs, voronoice_once);
        let t_delaunator = best_of(runs, || delaunator::triangulate(&vp));
        let t_spade = best_inner(runs, || {
            let p = sp.clone();
            let t0 = std::time::Instant::now();
            let t = spade::DelaunayTriangulation::<spade::Point2<f64>>::bulk_load(p);
            let e = t0.elapsed();
            drop(t);
            e
        });
        let t_tri = best_of(runs, || compgeom::delaunay::delaunay(pts));
        let t_compact = best_of(runs, || voronoi_cells(pts));
        let t_compact_cells = best_of(runs, || voronoi_cells(pts).map(|c| c.clip(&region)));
        let t_dual = best_of(runs, || voronoi_diagram(pts, VoronoiAlgorithm::Default));
        let t_dual_cells = best_of(runs, || {
            voronoi_diagram(pts, VoronoiAlgorithm::Default).map(|d| clip_cells(&d, &region))
        });
        let t_fortune = best_of(runs, || fortune_voronoi(pts));
        let t_cells = best_of(runs, || {
            fortune_voronoi(pts).map(|d| clip_cells(&d, &region))
        });
        println!(
            "{name} ({} points; voronoice gave {vcells} cells)",
            pts.len()
        );
        let rows = [
            (
                "  voronoice",
                "dual of delaunator, clipped cells",
                t_voronoice,
            ),
            ("  delaunator", "triangulation only", t_delaunator),
            ("  spade", "bulk_load triangulation only", t_spade),
            ("  compgeom delaunay", "triangulation only (exact)", t_tri),
            ("  compgeom cells", "voronoi_cells (dual, exact)", t_compact),
            (
                "  compgeom cells+clip",
                "voronoi_cells + clip (like-for-like)",
                t_compact_cells,
            ),
            ("  compgeom default", "diagram (dual, exact)", t_dual),
            (
                "  compgeom default+clip",
                "diagram + clipped cells",
                t_dual_cells,
            ),
            ("  compgeom fortune", "diagram (exact)", t_fortune),
            (
                "  compgeom fortune+clip",
                "diagram + clipped cells",
                t_cells,
            ),
        ];
        for (who, what, t) in rows {
            row(who, what, t, t_voronoice);
        }
        // Paired: Fortune and the default diagram alternate (which one goes first
        // alternates too), so both see the same machine load; the median of the per-round
        // ratios is the figure to judge the book variant by.
        let paired = std::env::var("COMPGEOM_VORONOI_PAIRED")
            .ok()
            .and_then(|v| v.parse::<usize>().ok())
            .unwrap_or(if quick { 3 } else { 5 });
        let mut ratios = Vec::new();
        for r in 0..paired {
            let mut pair = [0.0f64; 2];
            for k in 0..2 {
                let fortune = (r + k) % 2 == 0;
                let t = if fortune {
                    best_of(1, || fortune_voronoi(pts))
                } else {
                    best_of(1, || voronoi_diagram(pts, VoronoiAlgorithm::Default))
                };
                pair[usize::from(!fortune)] = ms(t);
            }
            ratios.push(pair[0] / pair[1]);
        }
        ratios.sort_by(f64::total_cmp);
        let median = ratios.get(ratios.len() / 2).copied().unwrap_or(f64::NAN);
        println!(
            "  fortune / default (diagram): {:.2} best-of, {median:.2} median of {paired} alternating rounds",
            ms(t_fortune) / ms(t_dual)
        );
        // Paired the same way: the like-for-like output (clipped cells) against voronoice.
        let mut ratios = Vec::new();
        for r in 0..paired {
            let mut pair = [0.0f64; 2];
            for k in 0..2 {
                let ours = (r + k) % 2 == 0;
                pair[usize::from(!ours)] = if ours {
                    ms(best_of(1, || voronoi_cells(pts).map(|c| c.clip(&region))))
                } else {
                    ms(best_inner(1, voronoice_once))
                };
            }
            ratios.push(pair[0] / pair[1]);
        }
        ratios.sort_by(f64::total_cmp);
        let median = ratios.get(ratios.len() / 2).copied().unwrap_or(f64::NAN);
        println!(
            "  cells+clip / voronoice: {:.2} best-of, {median:.2} median of {paired} alternating rounds",
            ms(t_compact_cells) / ms(t_voronoice)
        );
        times.push([t_compact_cells, t_dual_cells, t_cells, t_voronoice]);
    }
    if times.len() >= 2 {
        let g = |i: usize| ms(times[1][i]) / ms(times[0][i]);
        println!(
            "growth {small} -> {large} (x{} points): cells+clip x{:.1}, default+clip x{:.1}, fortune+clip x{:.1}, voronoice x{:.1}",
            large / small,
            g(0),
            g(1),
            g(2),
            g(3)
        );
    }
    Ok(())
}
