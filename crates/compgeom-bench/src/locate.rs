//! Point location (book chapter 6): compgeom's trapezoidal map with its randomized
//! search structure (`PointLocator`) against an rstar R*-tree of the faces' bounding
//! boxes followed by an exact point-in-triangle test (what a user of the Rust ecosystem
//! would write), and against a brute-force scan of every face at the small size.
//!
//! Workload: the Delaunay triangulation of uniform random points, sized to about 1e4,
//! 1e5 and 1e6 edges (segments); 1,000,000 uniform query points in the points' bounding
//! box (100,000 in `--quick`; 1,000 for the brute-force scan). Queries run on one thread
//! for both libraries (compgeom's parallel `locate_all` is reported separately).
//! Reported: build time (the DCEL is built outside the clock; the R-tree's bulk load is
//! its build), query throughput, the ratio, and the search structure's size and depth.
//! Answers are compared once, outside the clock: every query that compgeom puts in a
//! bounded face must be in the same triangle for rstar (a consistent face ↔ triangle
//! bijection), and the unbounded face must be rstar's "no triangle".
//!
//! The slab method (`SlabLocator`) is run at 1e4 and 1e5 (its space is about n^1.5
//! here; quadratic in the worst case), and its answers must equal the map's.
//!
//! Measured (release, shared 2-core machine, load average 3.3–4.7; several runs, the
//! range shown; rstar time / compgeom time, >1 means compgeom is faster; query grid of
//! tall cells, about eight per segment, with nodes laid out per cell):
//!
//! | segments | compgeom build | rstar build | compgeom q/s | rstar q/s | ratio | slab: build, q/s, pairs | DAG nodes/segment | depth |
//! |---|---|---|---|---|---|---|---|---|
//! | 1e4 | 24–39 ms | 1–2 ms | 3.8–6.6 M | 1.7–2.4 M | 1.6–3.0 | 4 ms, 1.2 M, 0.4 M | 4.2 | 50 |
//! | 1e5 | 0.32–0.66 s | 13–29 ms | 0.8–1.7 M | 0.8–1.3 M | 0.97–1.53 (mostly 1.2–1.4) | 115 ms, 0.29 M, 13.5 M | 4.2 | 66 |
//! | 1e6 | 9–12 s | 0.24–0.31 s | 0.50–0.66 M | 0.33–0.47 M | 1.40–1.56 | — | 4.3 | 83 |
//!
//! Brute force (1e4 segments, exact point-in-triangle over every face): 0.004–0.009 M q/s.
//! The mean search path is 25 / 33 / 38 nodes from the root at 1e4 / 1e5 / 1e6, and
//! 7 / 8 / 10 from the grid's start nodes. Construction is cache-bound (about one miss
//! per level of D per insert) and 15–40× rstar's bulk load.

use crate::util::{best_of, ms, Rng};
use compgeom::dcel::{Dcel, FaceId};
use compgeom::delaunay::delaunay;
use compgeom::kernel::{orient2d, Orientation};
use compgeom::locate::{Location, PointLocator, SlabLocator};
use compgeom::{Point2, Segment2};
use rstar::primitives::{GeomWithData, Rectangle};
use rstar::RTree;
use std::collections::HashMap;

type Boxed = GeomWithData<Rectangle<[f64; 2]>, u32>;

/// Exact closed point-in-triangle.
fn in_triangle(t: &[Point2; 3], q: Point2) -> bool {
    let o = [
        orient2d(t[0], t[1], q),
        orient2d(t[1], t[2], q),
        orient2d(t[2], t[0], q),
    ];
    !(o.contains(&Orientation::Clockwise) && o.contains(&Orientation::CounterClockwise))
}

fn rtree_locate(tree: &RTree<Boxed>, tris: &[[Point2; 3]], q: Point2) -> Option<u32> {
    tree.locate_all_at_point(&[q.x, q.y])
        .find(|g| in_triangle(&tris[g.data as usize], q))
        .map(|g| g.data)
}

fn brute_locate(tris: &[[Point2; 3]], q: Point2) -> Option<u32> {
    tris.iter()
        .position(|t| in_triangle(t, q))
        .map(|i| i as u32)
}

/// Run the group.
pub fn run(quick: bool) -> Result<(), String> {
    let sizes: &[usize] = if quick {
        &[10_000, 100_000]
    } else {
        &[10_000, 100_000, 1_000_000]
    };
    let nq = if quick { 100_000 } else { 1_000_000 };
    println!("## locate: point location in a Delaunay triangulation, {nq} queries");
    println!(
        "| segments | faces | compgeom build ms | rstar build ms | compgeom queries/s | rstar queries/s | ratio (rstar time / compgeom) | compgeom parallel queries/s | slab method build, queries/s, size | brute force queries/s | DAG nodes | nodes/segment | depth |"
    );
    println!("|---|---|---|---|---|---|---|---|---|---|---|---|---|");
    for &target in sizes {
        let mut rng = Rng::new(0x10CA7E ^ target as u64);
        // A triangulation of n points has about 3n edges.
        let n = target / 3;
        let pts: Vec<Point2> = (0..n)
            .map(|_| Point2::new(rng.unit() * 1000.0, rng.unit() * 1000.0))
            .collect();
        let t = delaunay(&pts).map_err(|e| e.to_string())?;
        let v = t.vertices();
        let segs: Vec<Segment2> = t
            .edges()
            .iter()
            .map(|&(a, b)| Segment2::new(v[a as usize], v[b as usize]))
            .collect();
        let tris: Vec<[Point2; 3]> = t
            .triangles()
            .iter()
            .map(|tr| tr.map(|i| v[i as usize]))
            .collect();
        let dcel = Dcel::from_segments(&segs).map_err(|e| e.to_string())?;
        let queries: Vec<Point2> = (0..nq)
            .map(|_| Point2::new(rng.unit() * 1000.0, rng.unit() * 1000.0))
            .collect();

        let runs = if target >= 1_000_000 { 1 } else { 3 };
        let mut loc = None;
        let build = best_of(runs, || {
            loc = Some(PointLocator::from_dcel(&dcel));
        });
        let loc = loc.ok_or("no locator")?.map_err(|e| e.to_string())?;
        let mut tree = None;
        let rbuild = best_of(runs, || {
            let boxes: Vec<Boxed> = tris
                .iter()
                .enumerate()
                .map(|(i, t)| {
                    let lo = [
                        t[0].x.min(t[1].x).min(t[2].x),
                        t[0].y.min(t[1].y).min(t[2].y),
                    ];
                    let hi = [
                        t[0].x.max(t[1].x).max(t[2].x),
                        t[0].y.max(t[1].y).max(t[2].y),
                    ];
                    GeomWithData::new(Rectangle::from_corners(lo, hi), i as u32)
                })
                .collect();
            tree = Some(RTree::bulk_load(boxes));
        });
        let tree = tree.ok_or("no tree")?;

        // Check the answers once.
        let ours = loc.locate_all(&queries).map_err(|e| e.to_string())?;
        let mut face_of: HashMap<usize, u32> = HashMap::new();
        for (q, a) in queries.iter().zip(&ours) {
            let theirs = rtree_locate(&tree, &tris, *q);
            match (*a, theirs) {
                (Location::Face(FaceId::UNBOUNDED), None) => {}
                (Location::Face(f), Some(t)) if f != FaceId::UNBOUNDED => {
                    if *face_of.entry(f.0).or_insert(t) != t {
                        return Err(format!("face {} is two triangles at {q:?}", f.0));
                    }
                }
                (Location::Edge(_) | Location::Vertex(_), Some(_)) => {}
                (a, b) => return Err(format!("answers differ at {q:?}: {a:?} vs {b:?}")),
            }
        }

        let qruns = 3;
        let ours_t = best_of(qruns, || {
            let mut acc = 0usize;
            for &q in &queries {
                if let Ok(Location::Face(f)) = loc.locate(q) {
                    acc = acc.wrapping_add(f.0);
                }
            }
            acc
        });
        let par_t = best_of(qruns, || loc.locate_all(&queries).map(|v| v.len()));
        let theirs_t = best_of(qruns, || {
            let mut acc = 0usize;
            for &q in &queries {
                if let Some(t) = rtree_locate(&tree, &tris, q) {
                    acc = acc.wrapping_add(t as usize);
                }
            }
            acc
        });
        // The slab method (quadratic worst-case space; about n^1.5 here) at the sizes
        // where its memory is reasonable; its answers must equal the map's.
        let slab = if target <= 100_000 {
            let mut sl = None;
            let sb = best_of(runs, || sl = Some(SlabLocator::from_dcel(&dcel)));
            let sl = sl.ok_or("no slab")?.map_err(|e| e.to_string())?;
            if sl.locate_all(&queries).map_err(|e| e.to_string())? != ours {
                return Err("slab and trapezoidal map answers differ".into());
            }
            let st = best_of(qruns, || {
                let mut acc = 0usize;
                for &q in &queries {
                    if let Ok(Location::Face(f)) = sl.locate(q) {
                        acc = acc.wrapping_add(f.0);
                    }
                }
                acc
            });
            format!(
                "{:.0} ms, {:.2} M q/s, {:.1} M pairs",
                ms(sb),
                nq as f64 / st.as_secs_f64() / 1e6,
                sl.entry_count() as f64 / 1e6
            )
        } else {
            "—".to_string()
        };
        let brute = if target <= 10_000 {
            let few = &queries[..1000];
            for &q in few {
                let b = brute_locate(&tris, q);
                if b != rtree_locate(&tree, &tris, q) {
                    return Err(format!("brute force differs at {q:?}"));
                }
            }
            let d = best_of(1, || {
                few.iter().filter_map(|&q| brute_locate(&tris, q)).count()
            });
            format!("{:.3} M", few.len() as f64 / d.as_secs_f64() / 1e6)
        } else {
            "—".to_string()
        };
        let st = loc.stats();
        let rate = |d: std::time::Duration| nq as f64 / d.as_secs_f64() / 1e6;
        println!(
            "| {} | {} | {:.0} | {:.0} | {:.2} M | {:.2} M | {:.2} | {:.2} M | {} | {} | {} | {:.1} | {} |",
            segs.len(),
            tris.len(),
            ms(build),
            ms(rbuild),
            rate(ours_t),
            rate(theirs_t),
            theirs_t.as_secs_f64() / ours_t.as_secs_f64(),
            rate(par_t),
            slab,
            brute,
            st.nodes,
            st.nodes as f64 / segs.len() as f64,
            st.depth,
        );
    }
    Ok(())
}
