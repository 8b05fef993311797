//! `compgeom-bench kernel`: the cost of exactness in the kernel.
//!
//! * `orient2d`: compgeom's predicate (a float filter, then a range check and `robust`)
//!   against raw `robust::orient2d` (what spade and geo call) on the same random triples.
//! * crossing comparisons: `Crossing::compare_xy` on random crossings (the interval
//!   filter decides) and on crossings that all coincide (every comparison falls back
//!   to exact arithmetic), with the measured fallback rate.
//!
//! Answers are checked once, outside the clock; timings are the best of a few runs.

use compgeom::kernel::{crossing_fallbacks, orient2d, Crossing, Orientation};
use compgeom::{Point2, Segment2};
use std::hint::black_box;
use std::time::Instant;

/// A small deterministic generator (splitmix64), so runs are reproducible.
struct Rng(u64);

impl Rng {
    fn next_u64(&mut self) -> u64 {
        self.0 = self.0.wrapping_add(0x9e37_79b9_7f4a_7c15);
        let mut z = self.0;
        z = (z ^ (z >> 30)).wrapping_mul(0xbf58_476d_1ce4_e5b9);
        z = (z ^ (z >> 27)).wrapping_mul(0x94d0_49bb_1331_11eb);
        z ^ (z >> 31)
    }

    /// Uniform in [0, 1).
    fn unit(&mut self) -> f64 {
        (self.next_u64() >> 11) as f64 / (1u64 << 53) as f64
    }

    fn point(&mut self) -> Point2 {
        Point2::new(self.unit(), self.unit())
    }
}

/// Best wall time of `runs` runs of `f`, in seconds.
fn best_of(runs: usize, mut f: impl FnMut()) -> f64 {
    (0..runs)
        .map(|_| {
            let t = Instant::now();
            f();
            t.elapsed().as_secs_f64()
        })
        .fold(f64::INFINITY, f64::min)
}

fn robust_sign(a: Point2, b: Point2, c: Point2) -> Orientation {
    let v = robust::orient2d(
        robust::Coord { x: a.x, y: a.y },
        robust::Coord { x: b.x, y: b.y },
        robust::Coord { x: c.x, y: c.y },
    );
    if v > 0.0 {
        Orientation::CounterClockwise
    } else if v < 0.0 {
        Orientation::Clockwise
    } else {
        Orientation::Collinear
    }
}

/// Runs `calls` orientation tests over consecutive triples of `pts` (cyclically).
fn run_orient(
    pts: &[Point2],
    calls: usize,
    f: impl Fn(Point2, Point2, Point2) -> Orientation,
) -> usize {
    let n = pts.len();
    let mut ccw = 0;
    for i in 0..calls {
        let j = i % (n - 2);
        ccw += usize::from(
            f(black_box(pts[j]), pts[j + 1], pts[j + 2]) == Orientation::CounterClockwise,
        );
    }
    ccw
}

fn row(name: &str, secs: f64, ops: usize, extra: &str) {
    println!(
        "| {name:<44} | {:>9.2} | {:>9.3} | {extra} |",
        secs * 1e9 / ops as f64,
        secs
    );
}

/// Random crossings in the unit square (pairs of random segments that cross).
fn random_crossings(rng: &mut Rng, n: usize) -> Vec<Crossing> {
    let mut out = Vec::with_capacity(n);
    while out.len() < n {
        let s = Segment2::new(rng.point(), rng.point());
        let t = Segment2::new(rng.point(), rng.point());
        if let Some(c) = Crossing::new(s, t) {
            out.push(c);
        }
    }
    out
}

/// Crossings that all coincide at (1/3, 1/3) (not a dyadic point), built from lines
/// through integer points, so every comparison among them is a tie that the filter
/// cannot decide.
fn coincident_crossings(n: usize) -> Vec<Crossing> {
    // For an integer point p, the segment p -> (1 - 2p) passes through (1/3, 1/3).
    let mut lines = Vec::new();
    for i in -4i32..=4 {
        for j in -4i32..=4 {
            let p = Point2::new(f64::from(i), f64::from(j));
            let q = Point2::new(f64::from(1 - 2 * i), f64::from(1 - 2 * j));
            lines.push(Segment2::new(p, q));
        }
    }
    let mut out = Vec::new();
    for (i, s) in lines.iter().enumerate() {
        for t in &lines[i + 1..] {
            if let Some(c) = Crossing::new(*s, *t) {
                out.push(c);
            }
        }
    }
    out.truncate(n);
    out
}

fn compare_all(cs: &[Crossing], calls: usize) -> usize {
    let n = cs.len();
    let mut less = 0;
    for i in 0..calls {
        let a = &cs[i % n];
        let b = &cs[(i * 7 + 1) % n];
        less += usize::from(black_box(a).compare_xy(b) == std::cmp::Ordering::Less);
    }
    less
}

/// Entry point of the `kernel` group.
pub fn run() {
    let mut rng = Rng(0x5eed);
    let pts: Vec<Point2> = (0..1_000_002).map(|_| rng.point()).collect();
    let calls = 10_000_000;

    // Check answers once, outside the clock.
    assert_eq!(
        run_orient(&pts, 1_000_000, orient2d),
        run_orient(&pts, 1_000_000, robust_sign)
    );

    println!("## kernel: cost of exactness (best of 3 runs)\n");
    println!("| operation | ns / op | total s | notes |");
    println!("|---|---:|---:|---|");
    let t_ours = best_of(3, || {
        black_box(run_orient(&pts, calls, orient2d));
    });
    let t_robust = best_of(3, || {
        black_box(run_orient(&pts, calls, robust_sign));
    });
    row(
        "orient2d, compgeom (float filter, range check, robust)",
        t_ours,
        calls,
        "1e7 triples from 1e6 random points in [0,1)²",
    );
    row(
        "orient2d, raw robust::orient2d",
        t_robust,
        calls,
        &format!("ratio compgeom/robust = {:.2}", t_ours / t_robust),
    );

    // Scaled (1e250) input: compgeom rescales exactly, robust alone may be wrong there.
    let big: Vec<Point2> = pts
        .iter()
        .map(|p| Point2::new(p.x * 1e250, p.y * 1e250))
        .collect();
    let t_big = best_of(3, || {
        black_box(run_orient(&big, calls, orient2d));
    });
    row(
        "orient2d, compgeom, coordinates ~1e250",
        t_big,
        calls,
        "outside robust's range: exact rescaling",
    );

    let cmp_calls = 2_000_000;
    // A pool that fits in cache: the figure is the cost of the decision, not of memory.
    let random = random_crossings(&mut rng, 1024);
    let f0 = crossing_fallbacks();
    compare_all(&random, cmp_calls);
    let rate_random = (crossing_fallbacks() - f0) as f64 / cmp_calls as f64;
    let t_random = best_of(3, || {
        black_box(compare_all(&random, cmp_calls));
    });
    row(
        "Crossing::compare_xy, random crossings",
        t_random,
        cmp_calls,
        &format!("exact fallback rate {:.4}%", 100.0 * rate_random),
    );

    let same = coincident_crossings(200);
    let deg_calls = 200_000;
    let f0 = crossing_fallbacks();
    let less = compare_all(&same, deg_calls);
    assert_eq!(less, 0, "coincident crossings must compare Equal");
    let rate_same = (crossing_fallbacks() - f0) as f64 / deg_calls as f64;
    let t_same = best_of(3, || {
        black_box(compare_all(&same, deg_calls));
    });
    row(
        "Crossing::compare_xy, coincident crossings",
        t_same,
        deg_calls,
        &format!(
            "exact fallbacks per comparison {:.2} (x and y ties)",
            rate_same
        ),
    );

    let orient_calls = 2_000_000;
    let t_orient = best_of(3, || {
        let mut ccw = 0usize;
        for i in 0..orient_calls {
            let c = &random[i % random.len()];
            let (a, b) = (pts[i % 1000], pts[i % 1000 + 1]);
            ccw +=
                usize::from(Crossing::orient(a, b, black_box(c)) == Orientation::CounterClockwise);
        }
        black_box(ccw);
    });
    row(
        "Crossing::orient(a, b, crossing), random",
        t_orient,
        orient_calls,
        "",
    );

    let approx_calls = 200_000;
    let t_approx = best_of(3, || {
        for c in random.iter().cycle().take(approx_calls) {
            black_box(black_box(c).approx());
        }
    });
    row(
        "Crossing::approx (correctly rounded)",
        t_approx,
        approx_calls,
        "double-double midpoint filter, exact fallback",
    );
}
