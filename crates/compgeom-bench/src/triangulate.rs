//! Polygon triangulation (book chapter 3): compgeom's `triangulate` (MAKEMONOTONE +
//! monotone triangulation) against earcut (ear clipping) and spade's constrained Delaunay
//! triangulation (`bulk_load_cdt`, which triangulates the whole convex hull and removes
//! nothing), on random star-shaped polygons of 1e3 … 1e6 vertices, a polygon with 100
//! holes, and a y-monotone polygon (compgeom's fast path); the 1e5 → 1e6 growth of each.
//!
//! Answers are checked once, outside the clock: compgeom's by its exact verifier (up to
//! 1e5 vertices), earcut must give n − 2 + 2h triangles, spade at least as many.

use crate::util::{best_of, ms, Rng};
use compgeom::triangulate::{triangulate, verify_triangulation};
use compgeom::{Point2, Polygon};
use std::time::Duration;

/// A random star-shaped polygon: n angles with jitter, radii in [0.5, 1).
fn star(n: usize, seed: u64) -> Vec<Point2> {
    let mut r = Rng::new(seed);
    let step = std::f64::consts::TAU / n as f64;
    (0..n)
        .map(|i| {
            let t = (i as f64 + 0.4 * r.unit()) * step;
            let rad = 0.5 + 0.5 * r.unit();
            Point2::new(rad * t.cos(), rad * t.sin())
        })
        .collect()
}

/// A star with 100 holes: 10 × 10 small 8-gons (clockwise) inside the radius-0.5 disc.
fn holey(n: usize, seed: u64) -> Polygon {
    let mut holes = Vec::new();
    for i in 0..10 {
        for j in 0..10 {
            let (cx, cy) = (-0.3 + 0.066 * i as f64, -0.3 + 0.066 * j as f64);
            holes.push(
                (0..8)
                    .rev()
                    .map(|k| {
                        let t = k as f64 * std::f64::consts::TAU / 8.0;
                        Point2::new(cx + 0.02 * t.cos(), cy + 0.02 * t.sin())
                    })
                    .collect(),
            );
        }
    }
    Polygon::new(star(n, seed), holes)
}

/// A y-monotone polygon: a zigzag left chain and right chain, n vertices.
fn monotone(n: usize, seed: u64) -> Polygon {
    let mut r = Rng::new(seed);
    let half = n / 2;
    let mut ring: Vec<Point2> = (0..half)
        .map(|i| Point2::new(-1.0 - r.unit(), 1.0 - 2.0 * i as f64 / half as f64))
        .collect();
    ring.extend((0..n - half).map(|i| {
        Point2::new(
            1.0 + r.unit(),
            -1.0 + 2.0 * (i as f64 + 0.5) / (n - half) as f64,
        )
    }));
    Polygon::new(ring, vec![])
}

struct Row {
    ours: Duration,
    earcut: Duration,
    spade: Duration,
}

/// `earcut: false` skips earcut (at 1e6 random-star vertices it runs for minutes: its
/// growth is quadratic there; the 1e5 row shows it).
fn measure(
    name: &str,
    poly: &Polygon,
    runs: usize,
    verify: bool,
    earcut: bool,
) -> Result<Row, String> {
    let n: usize = poly.rings().map(Vec::len).sum();
    let h = poly.holes.len();
    let mut flat: Vec<[f64; 2]> = Vec::with_capacity(n);
    let mut hole_starts: Vec<usize> = Vec::new();
    let mut edges: Vec<[usize; 2]> = Vec::with_capacity(n);
    for (k, ring) in poly.rings().enumerate() {
        let base = flat.len();
        if k > 0 {
            hole_starts.push(base);
        }
        flat.extend(ring.iter().map(|p| [p.x, p.y]));
        edges.extend((0..ring.len()).map(|i| [base + i, base + (i + 1) % ring.len()]));
    }
    let sp: Vec<spade::Point2<f64>> = flat
        .iter()
        .map(|p| spade::Point2::new(p[0], p[1]))
        .collect();
    let run_earcut = || {
        let mut out: Vec<usize> = Vec::new();
        earcut::Earcut::new().earcut(flat.iter().copied(), &hole_starts, &mut out);
        out
    };
    let run_spade = || {
        spade::ConstrainedDelaunayTriangulation::<spade::Point2<f64>>::bulk_load_cdt(
            sp.clone(),
            edges.clone(),
        )
    };
    // Check once, outside the clock.
    let ours = triangulate(poly).map_err(|e| e.to_string())?;
    if verify {
        verify_triangulation(poly, &ours).map_err(|e| e.to_string())?;
    }
    let want = n - 2 + 2 * h;
    if ours.triangles.len() != want {
        return Err(format!(
            "{name}: compgeom gave {} triangles, not {want}",
            ours.triangles.len()
        ));
    }
    let ec = if earcut { run_earcut().len() / 3 } else { want };
    if ec != want {
        return Err(format!("{name}: earcut gave {ec} triangles, not {want}"));
    }
    use spade::Triangulation as _;
    let st = run_spade().map_err(|e| format!("spade: {e:?}"))?;
    if st.num_inner_faces() < want {
        return Err(format!(
            "{name}: spade gave {} triangles",
            st.num_inner_faces()
        ));
    }
    let row = Row {
        ours: best_of(runs, || triangulate(poly)),
        earcut: if earcut {
            best_of(runs, run_earcut)
        } else {
            Duration::ZERO
        },
        spade: best_of(runs, run_spade),
    };
    println!(
        "{name:<28} {n:>8} {:>10.2} {:>10.2} {:>10.2} {:>9.2} {:>9.2}",
        ms(row.ours),
        ms(row.earcut),
        ms(row.spade),
        ms(row.earcut) / ms(row.ours),
        ms(row.spade) / ms(row.ours),
    );
    Ok(row)
}

/// Run the group.
pub fn run(quick: bool) -> Result<(), String> {
    println!("triangulate: best-of-k wall times in ms; ratios > 1 mean compgeom is faster");
    println!(
        "{:<28} {:>8} {:>10} {:>10} {:>10} {:>9} {:>9}",
        "input", "n", "compgeom", "earcut", "spade cdt", "earcut/cg", "spade/cg"
    );
    let sizes: &[usize] = if quick {
        &[1_000, 10_000, 100_000]
    } else {
        &[1_000, 10_000, 100_000, 1_000_000]
    };
    let mut rows = Vec::new();
    for &n in sizes {
        let runs = if n >= 1_000_000 { 1 } else { 3 };
        let poly = Polygon::new(star(n, 7 + n as u64), vec![]);
        rows.push(measure(
            &format!("random star {n}"),
            &poly,
            runs,
            n <= 100_000,
            n < 1_000_000,
        )?);
    }
    let hn = if quick { 10_000 } else { 100_000 };
    measure(
        &format!("star {hn} + 100 holes"),
        &holey(hn, 11),
        3,
        true,
        true,
    )?;
    let mn = if quick { 100_000 } else { 1_000_000 };
    measure(
        &format!("y-monotone {mn}"),
        &monotone(mn, 5),
        3,
        mn <= 100_000,
        // earcut's ear search is quadratic on this comb-like outline too (minutes at 1e6).
        mn <= 100_000,
    )?;
    if rows.len() >= 4 {
        let (a, b) = (&rows[2], &rows[3]);
        println!(
            "growth 1e5 -> 1e6 (n log n predicts ~12): compgeom {:.1}x, spade {:.1}x (earcut not run at 1e6)",
            ms(b.ours) / ms(a.ours),
            ms(b.spade) / ms(a.spade)
        );
    }
    Ok(())
}
