//! Convex hull (book chapter 1): compgeom's default and Andrew's monotone chain against
//! geo's quickhull and Graham scan, on the same generated points.
//!
//! geo is given its most favourable call: `quick_hull` / `graham_hull` on a mutable copy of
//! the coordinates made *outside* the clock (its `ConvexHull` trait would copy inside).
//! compgeom's functions take `&[Point2]` and their own copying is timed.

use crate::util::{best_of, ms, Rng};
use compgeom::hull::{andrew_convex_hull, convex_hull, verify_convex_hull, HullOptions};
use compgeom::kernel::{orient2d, Orientation};
use compgeom::Point2;
use geo::algorithm::convex_hull::{graham_hull, quick_hull};
use geo::Coord;
use std::collections::HashSet;
use std::time::{Duration, Instant};

/// One generated input.
struct Input {
    name: &'static str,
    points: Vec<Point2>,
}

fn square(n: usize, seed: u64) -> Vec<Point2> {
    let mut r = Rng::new(seed);
    (0..n).map(|_| Point2::new(r.unit(), r.unit())).collect()
}

fn disc(n: usize, seed: u64) -> Vec<Point2> {
    let mut r = Rng::new(seed);
    let mut v = Vec::with_capacity(n);
    while v.len() < n {
        let (x, y) = (2.0 * r.unit() - 1.0, 2.0 * r.unit() - 1.0);
        if x * x + y * y < 1.0 {
            v.push(Point2::new(x, y));
        }
    }
    v
}

/// Points on the unit circle at random angles, rounded to f64: nearly all are extreme.
fn circle(n: usize, seed: u64) -> Vec<Point2> {
    let mut r = Rng::new(seed);
    (0..n)
        .map(|_| {
            let t = r.unit() * std::f64::consts::TAU;
            Point2::new(t.cos(), t.sin())
        })
        .collect()
}

/// Points on a 1000 x 1000 integer grid: many duplicates and long collinear runs on the
/// hull's sides (a workload that hurts careless implementations).
fn grid(n: usize, seed: u64) -> Vec<Point2> {
    let mut r = Rng::new(seed);
    (0..n)
        .map(|_| Point2::new((r.next_u64() % 1000) as f64, (r.next_u64() % 1000) as f64))
        .collect()
}

fn key(p: Point2) -> (u64, u64) {
    ((p.x + 0.0).to_bits(), (p.y + 0.0).to_bits())
}

/// The corners (non-collinear vertices) of a closed or open ring, as a set.
fn corner_set(ring: &[Point2]) -> HashSet<(u64, u64)> {
    let mut r = ring.to_vec();
    if r.len() > 1 && r.first() == r.last() {
        r.pop();
    }
    let h = r.len();
    if h < 3 {
        return r.iter().map(|&p| key(p)).collect();
    }
    (0..h)
        .filter(|&i| orient2d(r[(i + h - 1) % h], r[i], r[(i + 1) % h]) != Orientation::Collinear)
        .map(|i| key(r[i]))
        .collect()
}

fn from_geo(ls: &geo::LineString<f64>) -> Vec<Point2> {
    ls.0.iter().map(|c| Point2::new(c.x, c.y)).collect()
}

/// Best of `runs` for a geo call that consumes a fresh copy of the coordinates, the copy
/// made outside the clock.
fn best_of_on_copy<T>(
    runs: usize,
    coords: &[Coord<f64>],
    mut f: impl FnMut(&mut [Coord<f64>]) -> T,
) -> Duration {
    let mut best = Duration::MAX;
    for _ in 0..runs.max(1) {
        let mut buf = coords.to_vec();
        let start = Instant::now();
        let out = f(&mut buf);
        best = best.min(start.elapsed());
        drop(std::hint::black_box(out));
    }
    best
}

struct Row {
    name: &'static str,
    n: usize,
    hull_size: usize,
    default: Duration,
    andrew: Duration,
    quick: Duration,
    graham: Duration,
}

fn measure(input: &Input, runs: usize) -> Result<Row, String> {
    let pts = &input.points;
    let coords: Vec<Coord<f64>> = pts.iter().map(|p| Coord { x: p.x, y: p.y }).collect();
    let opts = HullOptions::default();

    // Answers, once, outside the clock.
    let ours = convex_hull(pts, &opts).map_err(|e| e.to_string())?;
    verify_convex_hull(pts, &ours, false).map_err(|e| format!("{}: {e}", input.name))?;
    let andrew = andrew_convex_hull(pts).map_err(|e| e.to_string())?;
    if andrew != ours {
        return Err(format!("{}: andrew and default differ", input.name));
    }
    let q = from_geo(&quick_hull(&mut coords.clone()));
    let g = from_geo(&graham_hull(&mut coords.clone(), false));
    let mine = corner_set(&ours);
    for (peer, ring) in [("geo quickhull", &q), ("geo graham", &g)] {
        let theirs = corner_set(ring);
        if theirs != mine {
            return Err(format!(
                "{}: {peer} hull has {} corners, compgeom {} ({} in common)",
                input.name,
                theirs.len(),
                mine.len(),
                theirs.intersection(&mine).count()
            ));
        }
    }

    let default = best_of(runs, || convex_hull(pts, &opts));
    let andrew = best_of(runs, || andrew_convex_hull(pts));
    let quick = best_of_on_copy(runs, &coords, quick_hull);
    let graham = best_of_on_copy(runs, &coords, |c| graham_hull(c, false));
    Ok(Row {
        name: input.name,
        n: pts.len(),
        hull_size: ours.len(),
        default,
        andrew,
        quick,
        graham,
    })
}

/// Run the hull group. `quick` uses inputs ten times smaller.
pub fn run(quick: bool) -> Result<(), String> {
    let scale = if quick { 10 } else { 1 };
    let m = 1_000_000 / scale;
    let inputs = [
        (
            Input {
                name: "square",
                points: square(m, 1),
            },
            3,
        ),
        (
            Input {
                name: "square",
                points: square(10 * m, 2),
            },
            2,
        ),
        (
            Input {
                name: "disc",
                points: disc(m, 3),
            },
            3,
        ),
        (
            Input {
                name: "circle",
                points: circle(m, 4),
            },
            3,
        ),
        (
            Input {
                name: "grid",
                points: grid(m, 5),
            },
            3,
        ),
    ];
    println!("convex hull: times in ms (best of 3; 2 at 10x), ratio = compgeom / fastest geo (< 1 = compgeom faster)");
    println!(
        "{:<8} {:>9} {:>7} | {:>9} {:>9} | {:>9} {:>9} | {:>7} {:>7}",
        "input",
        "n",
        "hull",
        "default",
        "andrew",
        "geo-quick",
        "geo-graham",
        "dflt/geo",
        "andr/geo"
    );
    let mut rows = Vec::new();
    for (input, runs) in &inputs {
        let runs = *runs;
        let r = measure(input, runs)?;
        let best_geo = r.quick.min(r.graham);
        println!(
            "{:<8} {:>9} {:>7} | {:>9.2} {:>9.2} | {:>9.2} {:>9.2} | {:>7.3} {:>7.3}",
            r.name,
            r.n,
            r.hull_size,
            ms(r.default),
            ms(r.andrew),
            ms(r.quick),
            ms(r.graham),
            r.default.as_secs_f64() / best_geo.as_secs_f64(),
            r.andrew.as_secs_f64() / best_geo.as_secs_f64(),
        );
        rows.push(r);
    }
    let (a, b) = (&rows[0], &rows[1]);
    let growth = |x: Duration, y: Duration| y.as_secs_f64() / x.as_secs_f64();
    println!(
        "growth square {}→{} (x10 points): default {:.1}x, andrew {:.1}x, geo-quick {:.1}x, geo-graham {:.1}x",
        a.n,
        b.n,
        growth(a.default, b.default),
        growth(a.andrew, b.andrew),
        growth(a.quick, b.quick),
        growth(a.graham, b.graham),
    );
    Ok(())
}
