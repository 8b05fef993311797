//! Range searching (book chapter 5) and windowing (chapter 10): compgeom's kd-tree, range
//! tree and layered range tree against kiddo (kd-tree) and rstar (R*-tree), on the same
//! points and the same query rectangles; compgeom's segment windowing against rstar.
//!
//! Workload (full size): 1,000,000 uniform points in the unit square; 100,000 square
//! queries of side 0.01 (about 100 points each). Reported: build time, reporting
//! throughput (each structure pushes the indices into a reused `Vec`), count-only
//! throughput (kiddo and rstar have no count: they report and count), 10-NN throughput,
//! and heap bytes per point (measured with a counting allocator around the build).
//! kiddo has no rectangle query: squares are asked as Chebyshev (L∞) balls, which is the
//! same set. Answers are compared once, outside the clock.
//!
//! Measured (full size, release, 2-core machine shared with other jobs, load average
//! 4 to 5, so absolute times are inflated; ratios come from one run):
//!
//! | structure | build ms | bytes/point | report | count | 10-NN |
//! |---|---|---|---|---|---|
//! | compgeom KdTree | 139 | 24.7 | 0.35 M/s | 0.66 M/s | 0.47 M/s |
//! | compgeom RangeTree | 703 | 200 | 0.08 M/s | 0.12 M/s | — |
//! | compgeom LayeredRangeTree | 951 | 204 | 0.16 M/s | 0.19 M/s | — |
//! | kiddo ImmutableKdTree | 248 | 20.8 | — | — | 0.28 M/s |
//! | kiddo KdTree (Chebyshev) | 318 | 50 | 0.10 M/s | 0.11 M/s | — |
//! | rstar RTree | 306 | 72 | 0.10 M/s | 0.12 M/s | 0.19 M/s |
//!
//! Under such load, times taken a minute apart swing by ±40%, so the kd-tree's build and
//! 10-NN are also timed against kiddo in alternating rounds (median ratio): build 0.56,
//! 10-NN 0.96 in the run above (wall clock; the same comparison in thread CPU time gives
//! 0.81 to 0.88; the build uses both cores, kiddo's is sequential).
//!
//! Windowing, 1,000,000 segments, 100,000 windows: compgeom SegmentWindow 5.3 s build,
//! 666 bytes/segment, 0.03 M/s; rstar + exact filter 1.8 s, 72 bytes/segment, 0.04 M/s.
//! Profile of `SegmentWindow::query` (callgrind, 9e4 segments, windows of ~106 results):
//! 49% of its instructions sort the ~200 raw hits (each inner segment comes once per
//! endpoint), 24% the endpoint range query, 24% the three edge stabbings. Dropping the
//! second endpoint's hit by looking up the first endpoint (32 more bytes/segment) cut the
//! sort but was slower at 1e6 segments (a cache miss per hit); leaving out edge hits with
//! an endpoint inside saved only 3% of instructions. Neither was kept.

use crate::util::{best_of, ms, Rng};
use compgeom::range::{KdTree, LayeredRangeTree, RangeTree};
use compgeom::windowing::SegmentWindow;
use compgeom::{Bbox2, Point2, Segment2};
use kiddo::immutable::float::kdtree::ImmutableKdTree;
use kiddo::{Chebyshev, SquaredEuclidean};
use rstar::primitives::{GeomWithData, Line};
use rstar::{RTree, AABB};
use std::alloc::{GlobalAlloc, Layout, System};
use std::sync::atomic::{AtomicBool, AtomicUsize, Ordering};
use std::time::Duration;

/// Counts live heap bytes, so that memory per point can be measured for every library.
struct Counting;
static LIVE: AtomicUsize = AtomicUsize::new(0);
static COUNTING: AtomicBool = AtomicBool::new(false);

unsafe impl GlobalAlloc for Counting {
    unsafe fn alloc(&self, l: Layout) -> *mut u8 {
        if COUNTING.load(Ordering::Relaxed) {
            LIVE.fetch_add(l.size(), Ordering::Relaxed);
        }
        System.alloc(l)
    }
    unsafe fn dealloc(&self, p: *mut u8, l: Layout) {
        if COUNTING.load(Ordering::Relaxed) {
            LIVE.fetch_sub(l.size(), Ordering::Relaxed);
        }
        System.dealloc(p, l)
    }
    unsafe fn realloc(&self, p: *mut u8, l: Layout, n: usize) -> *mut u8 {
        if COUNTING.load(Ordering::Relaxed) {
            LIVE.fetch_add(n, Ordering::Relaxed);
            LIVE.fetch_sub(l.size(), Ordering::Relaxed);
        }
        System.realloc(p, l, n)
    }
}

#[global_allocator]
static GLOBAL: Counting = Counting;

/// Build with `f`, returning the structure, the best build time of `runs`, and the heap
/// bytes it holds (the bytes allocated and not freed while one more build runs, by all
/// threads; memory allocated before it and freed during it counts against it).
fn build<T>(runs: usize, mut f: impl FnMut() -> T) -> (T, Duration, usize) {
    let t = best_of(runs, &mut f);
    let before = LIVE.load(Ordering::Relaxed);
    COUNTING.store(true, Ordering::SeqCst);
    let s = f();
    COUNTING.store(false, Ordering::SeqCst);
    let bytes = LIVE.load(Ordering::Relaxed).saturating_sub(before);
    (s, t, bytes)
}

struct Row {
    name: &'static str,
    build: Duration,
    bytes: usize,
    report: Option<Duration>,
    count: Option<Duration>,
    knn: Option<Duration>,
}

type Tree2 = RTree<GeomWithData<[f64; 2], u32>>;
type SegTree = RTree<GeomWithData<Line<[f64; 2]>, u32>>;

/// Run the group.
pub fn run(quick: bool) -> Result<(), String> {
    let n = if quick { 100_000 } else { 1_000_000 };
    let m = if quick { 10_000 } else { 100_000 };
    // At least two runs: the first build also starts the rayon pool.
    let runs = if quick { 2 } else { 3 };
    let mut r = Rng::new(7);
    let pts: Vec<Point2> = (0..n).map(|_| Point2::new(r.unit(), r.unit())).collect();
    let side = (100.0 / n as f64).sqrt();
    let rects: Vec<Bbox2> = (0..m)
        .map(|_| {
            let (x, y) = (r.unit() * (1.0 - side), r.unit() * (1.0 - side));
            Bbox2 {
                min: Point2::new(x, y),
                max: Point2::new(x + side, y + side),
            }
        })
        .collect();
    let probes: Vec<Point2> = (0..m).map(|_| Point2::new(r.unit(), r.unit())).collect();
    let arr: Vec<[f64; 2]> = pts.iter().map(|p| [p.x, p.y]).collect();
    println!("range: {n} uniform points, {m} square queries of side {side:.4} (~100 points each), {m} 10-NN queries");

    let mut out: Vec<usize> = Vec::with_capacity(1024);
    let mut rows = Vec::new();

    let (kd, t, b) = build(runs, || KdTree::new(&pts).unwrap());
    let report = best_of(runs, || {
        let mut s = 0;
        for q in &rects {
            out.clear();
            kd.for_each(q, |i| out.push(i));
            s += out.len();
        }
        s
    });
    let count = best_of(runs, || rects.iter().map(|q| kd.count(q)).sum::<usize>());
    let knn = best_of(runs, || {
        probes
            .iter()
            .map(|&q| kd.nearest(q, 10).len())
            .sum::<usize>()
    });
    rows.push(Row {
        name: "compgeom KdTree",
        build: t,
        bytes: b,
        report: Some(report),
        count: Some(count),
        knn: Some(knn),
    });

    let (rt, t, b) = build(runs, || RangeTree::new(&pts).unwrap());
    let report = best_of(runs, || {
        let mut s = 0;
        for q in &rects {
            out.clear();
            rt.for_each(q, |i| out.push(i));
            s += out.len();
        }
        s
    });
    let count = best_of(runs, || rects.iter().map(|q| rt.count(q)).sum::<usize>());
    rows.push(Row {
        name: "compgeom RangeTree",
        build: t,
        bytes: b,
        report: Some(report),
        count: Some(count),
        knn: None,
    });
    drop(rt);

    let (lt, t, b) = build(runs, || LayeredRangeTree::new(&pts).unwrap());
    let report = best_of(runs, || {
        let mut s = 0;
        for q in &rects {
            out.clear();
            lt.for_each(q, |i| out.push(i));
            s += out.len();
        }
        s
    });
    let count = best_of(runs, || rects.iter().map(|q| lt.count(q)).sum::<usize>());
    rows.push(Row {
        name: "compgeom LayeredRangeTree",
        build: t,
        bytes: b,
        report: Some(report),
        count: Some(count),
        knn: None,
    });

    let (ki, t, b) = build(runs, || {
        ImmutableKdTree::<f64, u32, 2, 32>::new_from_slice(&arr)
    });
    let knn = best_of(runs, || {
        probes
            .iter()
            .map(|q| {
                ki.nearest_n::<SquaredEuclidean>(&[q.x, q.y], std::num::NonZero::new(10).unwrap())
                    .len()
            })
            .sum::<usize>()
    });
    rows.push(Row {
        name: "kiddo ImmutableKdTree",
        build: t,
        bytes: b,
        report: None,
        count: None,
        knn: Some(knn),
    });

    let (km, t, b) = build(runs, || kiddo::KdTree::<f64, 2>::from(&arr));
    let half = side / 2.0;
    let kiddo_query =
        |q: &Bbox2| km.within_unsorted::<Chebyshev>(&[q.min.x + half, q.min.y + half], half);
    let report = best_of(runs, || {
        let mut s = 0;
        for q in &rects {
            out.clear();
            out.extend(kiddo_query(q).iter().map(|nb| nb.item as usize));
            s += out.len();
        }
        s
    });
    let count = best_of(runs, || {
        rects.iter().map(|q| kiddo_query(q).len()).sum::<usize>()
    });
    rows.push(Row {
        name: "kiddo KdTree (Chebyshev)",
        build: t,
        bytes: b,
        report: Some(report),
        count: Some(count),
        knn: None,
    });

    let items = || -> Vec<GeomWithData<[f64; 2], u32>> {
        arr.iter()
            .enumerate()
            .map(|(i, p)| GeomWithData::new(*p, i as u32))
            .collect()
    };
    let (rs, t, b): (Tree2, _, _) = build(runs, || RTree::bulk_load(items()));
    let env = |q: &Bbox2| AABB::from_corners([q.min.x, q.min.y], [q.max.x, q.max.y]);
    let report = best_of(runs, || {
        let mut s = 0;
        for q in &rects {
            out.clear();
            out.extend(rs.locate_in_envelope(&env(q)).map(|g| g.data as usize));
            s += out.len();
        }
        s
    });
    let count = best_of(runs, || {
        rects
            .iter()
            .map(|q| rs.locate_in_envelope(&env(q)).count())
            .sum::<usize>()
    });
    let knn = best_of(runs, || {
        probes
            .iter()
            .map(|q| rs.nearest_neighbor_iter(&[q.x, q.y]).take(10).count())
            .sum::<usize>()
    });
    rows.push(Row {
        name: "rstar RTree",
        build: t,
        bytes: b,
        report: Some(report),
        count: Some(count),
        knn: Some(knn),
    });

    // Answers, once, outside the clock.
    for q in rects.iter().take(200) {
        let want = lt.query(q);
        let mut a: Vec<usize> = kd.query(q);
        if a != want {
            return Err(format!("kd-tree and layered range tree disagree on {q:?}"));
        }
        a = rs
            .locate_in_envelope(&env(q))
            .map(|g| g.data as usize)
            .collect();
        a.sort_unstable();
        if a != want {
            return Err(format!("rstar disagrees on {q:?}"));
        }
        a = kiddo_query(q).iter().map(|nb| nb.item as usize).collect();
        a.sort_unstable();
        if a != want {
            return Err(format!("kiddo disagrees on {q:?}"));
        }
    }
    for &q in probes.iter().take(200) {
        let ours = kd.nearest(q, 10);
        let theirs: Vec<usize> = ki
            .nearest_n::<SquaredEuclidean>(&[q.x, q.y], std::num::NonZero::new(10).unwrap())
            .iter()
            .map(|nb| nb.item as usize)
            .collect();
        if ours != theirs {
            return Err(format!(
                "10-NN of {q:?}: compgeom {ours:?}, kiddo {theirs:?}"
            ));
        }
    }

    let qps = |d: Option<Duration>| {
        d.map_or("—".to_string(), |d| {
            format!("{:.2} M/s", m as f64 / d.as_secs_f64() / 1e6)
        })
    };
    println!(
        "| structure | build ms | bytes/point | report queries | count queries | 10-NN queries |"
    );
    println!("|---|---|---|---|---|---|");
    for row in &rows {
        println!(
            "| {} | {:.1} | {:.1} | {} | {} | {} |",
            row.name,
            ms(row.build),
            row.bytes as f64 / n as f64,
            qps(row.report),
            qps(row.count),
            qps(row.knn)
        );
    }
    let get = |name: &str| rows.iter().find(|r| r.name == name).unwrap();
    let (kdr, lr, kir, kmr, rsr) = (
        get("compgeom KdTree"),
        get("compgeom LayeredRangeTree"),
        get("kiddo ImmutableKdTree"),
        get("kiddo KdTree (Chebyshev)"),
        get("rstar RTree"),
    );
    let ratio = |a: Option<Duration>, b: Option<Duration>| match (a, b) {
        (Some(a), Some(b)) => format!("{:.2}", a.as_secs_f64() / b.as_secs_f64()),
        _ => "—".into(),
    };
    println!("ratios (time, < 1 means compgeom is faster):");
    println!(
        "  KdTree build / kiddo ImmutableKdTree build: {}",
        ratio(Some(kdr.build), Some(kir.build))
    );
    println!(
        "  KdTree report / kiddo report: {}   / rstar report: {}",
        ratio(kdr.report, kmr.report),
        ratio(kdr.report, rsr.report)
    );
    println!(
        "  Layered report / kiddo report: {}   / rstar report: {}",
        ratio(lr.report, kmr.report),
        ratio(lr.report, rsr.report)
    );
    println!(
        "  Layered count / kiddo count: {}   / rstar count: {}",
        ratio(lr.count, kmr.count),
        ratio(lr.count, rsr.count)
    );
    println!(
        "  KdTree 10-NN / kiddo 10-NN: {}   / rstar 10-NN: {}",
        ratio(kdr.knn, kir.knn),
        ratio(kdr.knn, rsr.knn)
    );
    // The machine may be shared: time compgeom and kiddo alternately, round by round, and
    // report the median of the per-round ratios, which load swings affect far less than
    // ratios of times taken minutes apart.
    let rounds = if quick { 3 } else { 5 };
    let build_ratio = paired(rounds, || {
        let a = best_of(1, || KdTree::new(&pts).unwrap());
        let b = best_of(1, || {
            ImmutableKdTree::<f64, u32, 2, 32>::new_from_slice(&arr)
        });
        (a, b)
    });
    let knn_ratio = paired(rounds, || {
        let a = best_of(1, || {
            probes
                .iter()
                .map(|&q| kd.nearest(q, 10).len())
                .sum::<usize>()
        });
        let b = best_of(1, || {
            probes
                .iter()
                .map(|q| {
                    ki.nearest_n::<SquaredEuclidean>(
                        &[q.x, q.y],
                        std::num::NonZero::new(10).unwrap(),
                    )
                    .len()
                })
                .sum::<usize>()
        });
        (a, b)
    });
    println!(
        "paired ({rounds} alternating rounds, median ratio): KdTree build / kiddo build: {build_ratio:.2}   KdTree 10-NN / kiddo 10-NN: {knn_ratio:.2}"
    );
    drop((kd, lt, ki, km, rs));
    windowing(quick, runs)
}

/// The median over `rounds` of the ratio `a / b` of the two times `f` returns.
fn paired(rounds: usize, mut f: impl FnMut() -> (Duration, Duration)) -> f64 {
    let mut r: Vec<f64> = (0..rounds)
        .map(|_| {
            let (a, b) = f();
            a.as_secs_f64() / b.as_secs_f64()
        })
        .collect();
    r.sort_by(f64::total_cmp);
    r[r.len() / 2]
}

/// Windowing on non-crossing segments: short horizontal-ish segments in a grid of cells
/// (one per cell, inside it, so none cross), against rstar's envelope query followed by
/// the exact segment-rectangle test a user of rstar would have to add.
fn windowing(quick: bool, runs: usize) -> Result<(), String> {
    let k = if quick { 300 } else { 1000 };
    let m = if quick { 10_000 } else { 100_000 };
    let mut r = Rng::new(11);
    let cell = 1.0 / k as f64;
    let mut segs = Vec::with_capacity(k * k);
    for i in 0..k {
        for j in 0..k {
            let (x, y) = (i as f64 * cell, j as f64 * cell);
            let a = Point2::new(x + r.unit() * cell * 0.9, y + r.unit() * cell * 0.9);
            let b = Point2::new(x + r.unit() * cell * 0.9, y + r.unit() * cell * 0.9);
            segs.push(Segment2::new(a, b));
        }
    }
    let side = 10.0 * cell;
    let rects: Vec<Bbox2> = (0..m)
        .map(|_| {
            let (x, y) = (r.unit() * (1.0 - side), r.unit() * (1.0 - side));
            Bbox2 {
                min: Point2::new(x, y),
                max: Point2::new(x + side, y + side),
            }
        })
        .collect();
    let (sw, t_sw, b_sw) = build(runs, || SegmentWindow::new(&segs).unwrap());
    let lines = || -> Vec<GeomWithData<Line<[f64; 2]>, u32>> {
        segs.iter()
            .enumerate()
            .map(|(i, s)| GeomWithData::new(Line::new([s.a.x, s.a.y], [s.b.x, s.b.y]), i as u32))
            .collect()
    };
    let (rs, t_rs, b_rs): (SegTree, _, _) = build(runs, || RTree::bulk_load(lines()));
    let rstar_query = |q: &Bbox2, out: &mut Vec<usize>| {
        let env = AABB::from_corners([q.min.x, q.min.y], [q.max.x, q.max.y]);
        for g in rs.locate_in_envelope_intersecting(&env) {
            let i = g.data as usize;
            // rstar gives bounding-box candidates; the exact test is the user's job.
            if compgeom::windowing::verify_window(&segs[i..=i], q, &[0]).is_ok() {
                out.push(i);
            }
        }
    };
    let mut out = Vec::new();
    let q_sw = best_of(runs, || {
        rects.iter().map(|q| sw.query(q).len()).sum::<usize>()
    });
    let q_rs = best_of(runs, || {
        let mut s = 0;
        for q in &rects {
            out.clear();
            rstar_query(q, &mut out);
            s += out.len();
        }
        s
    });
    for q in rects.iter().take(200) {
        let mut theirs = Vec::new();
        rstar_query(q, &mut theirs);
        theirs.sort_unstable();
        if sw.query(q) != theirs {
            return Err(format!("windowing disagrees with rstar on {q:?}"));
        }
    }
    let n = segs.len();
    println!("windowing: {n} non-crossing segments, {m} windows of side {side:.3}");
    println!("| structure | build ms | bytes/segment | window queries |");
    println!("|---|---|---|---|");
    let qps = |d: Duration| format!("{:.2} M/s", m as f64 / d.as_secs_f64() / 1e6);
    println!(
        "| compgeom SegmentWindow | {:.1} | {:.1} | {} |",
        ms(t_sw),
        b_sw as f64 / n as f64,
        qps(q_sw)
    );
    println!(
        "| rstar RTree + exact filter | {:.1} | {:.1} | {} |",
        ms(t_rs),
        b_rs as f64 / n as f64,
        qps(q_rs)
    );
    Ok(())
}
