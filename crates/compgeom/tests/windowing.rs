//! Windowing (chapter 10) against brute force, on random and degenerate input: interval
//! trees and segment trees (stabbing), priority search trees, and window queries on
//! axis-parallel and on arbitrary non-crossing segments, including segments that cross
//! the window with no endpoint inside, touching segments, point segments and degenerate
//! windows.

use compgeom::kernel::{segment_intersection, SegmentIntersection};
use compgeom::windowing::{
    AxisParallelWindow, IntervalTree, PrioritySearchTree, SegmentTree, SegmentWindow,
};
use compgeom::{Bbox2, Point2, Segment2};
use proptest::prelude::*;

fn p(x: f64, y: f64) -> Point2 {
    Point2::new(x, y)
}

fn win(x0: f64, y0: f64, x1: f64, y1: f64) -> Bbox2 {
    Bbox2 {
        min: p(x0, y0),
        max: p(x1, y1),
    }
}

/// Exact brute force: an endpoint inside, or a common point with an edge of the window.
fn meets(s: &Segment2, w: &Bbox2) -> bool {
    if w.is_empty() {
        return false;
    }
    if w.contains(s.a) || w.contains(s.b) {
        return true;
    }
    let c = [w.min, p(w.max.x, w.min.y), w.max, p(w.min.x, w.max.y)];
    (0..4).any(|k| {
        let e = Segment2::new(c[k], c[(k + 1) % 4]);
        !matches!(segment_intersection(*s, e), SegmentIntersection::None)
    })
}

fn brute(segs: &[Segment2], w: &Bbox2) -> Vec<usize> {
    (0..segs.len()).filter(|&i| meets(&segs[i], w)).collect()
}

struct Lcg(u64);
impl Lcg {
    fn next(&mut self, m: u32) -> i64 {
        self.0 = self
            .0
            .wrapping_mul(6364136223846793005)
            .wrapping_add(1442695040888963407);
        ((self.0 >> 33) as u32 % m) as i64
    }
}

/// Random horizontal and vertical segments (and points) on a small grid: many crossings,
/// overlaps, shared endpoints and equal coordinates.
fn axis_parallel(n: usize, side: u32, seed: u64) -> Vec<Segment2> {
    let mut r = Lcg(seed);
    (0..n)
        .map(|_| {
            let (x, y, l) = (
                r.next(side) as f64,
                r.next(side) as f64,
                r.next(side / 2 + 1) as f64,
            );
            let (a, b) = match r.next(3) {
                0 => (p(x, y), p(x + l, y)),
                1 => (p(x, y + l), p(x, y)),
                _ => (p(x, y), p(x, y)),
            };
            Segment2::new(a, b)
        })
        .collect()
}

/// Non-crossing segments in general directions: `k` x-monotone polylines over columns at
/// irregular x, with y-values sorted per column (so they touch and overlap but never
/// cross), plus vertical segments between consecutive polylines and some points.
#[allow(clippy::needless_range_loop)]
fn non_crossing(k: usize, cols: usize, seed: u64) -> Vec<Segment2> {
    let mut r = Lcg(seed);
    let mut xs = vec![0.0];
    for _ in 1..cols {
        let last = *xs.last().unwrap();
        xs.push(last + 0.25 + r.next(8) as f64 * 0.375);
    }
    let cols_y: Vec<Vec<f64>> = (0..cols)
        .map(|_| {
            let mut v: Vec<f64> = (0..k).map(|_| r.next(12) as f64 * 0.5).collect();
            v.sort_by(f64::total_cmp);
            v
        })
        .collect();
    let mut segs = Vec::new();
    for c in 0..cols - 1 {
        for j in 0..k {
            let (a, b) = (p(xs[c], cols_y[c][j]), p(xs[c + 1], cols_y[c + 1][j]));
            segs.push(if r.next(2) == 0 {
                Segment2::new(a, b)
            } else {
                Segment2::new(b, a)
            });
        }
    }
    for c in 0..cols {
        // A vertical segment between two consecutive values of a column lies between the
        // polylines there and crosses nothing.
        if k >= 2 && r.next(2) == 0 {
            let j = r.next(k as u32 - 1) as usize;
            segs.push(Segment2::new(
                p(xs[c], cols_y[c][j]),
                p(xs[c], cols_y[c][j + 1]),
            ));
        }
        let y = cols_y[c][0];
        segs.push(Segment2::new(p(xs[c], y), p(xs[c], y)));
    }
    // Shuffle so that indices are not in construction order.
    for i in (1..segs.len()).rev() {
        let j = r.next(i as u32 + 1) as usize;
        segs.swap(i, j);
    }
    segs
}

fn windows(m: usize, lo: f64, hi: f64, seed: u64) -> Vec<Bbox2> {
    let mut r = Lcg(seed);
    let span = ((hi - lo) * 4.0) as u32 + 1;
    let mut v: Vec<Bbox2> = (0..m)
        .map(|_| {
            let c = |r: &mut Lcg| lo + r.next(span) as f64 * 0.25;
            let (a, b, c2, d) = (c(&mut r), c(&mut r), c(&mut r), c(&mut r));
            win(a.min(c2), b.min(d), a.max(c2), b.max(d))
        })
        .collect();
    v.push(win(1.0, 1.0, 1.0, 1.0)); // a point
    v.push(win(2.0, -10.0, 2.0, 50.0)); // a vertical line piece
    v.push(win(-10.0, 1.5, 50.0, 1.5)); // a horizontal line piece
    v.push(win(3.0, 3.0, 2.0, 4.0)); // empty
    v.push(win(-100.0, -100.0, 100.0, 100.0)); // everything
    v
}

fn check_window_structures(segs: &[Segment2], ws: &[Bbox2], axis_parallel: bool) {
    let sw = SegmentWindow::new(segs).unwrap();
    let ap = axis_parallel.then(|| AxisParallelWindow::new(segs).unwrap());
    for w in ws {
        let want = brute(segs, w);
        assert_eq!(sw.query(w), want, "segment window {w:?}");
        if let Some(ap) = &ap {
            assert_eq!(ap.query(w), want, "axis-parallel window {w:?}");
        }
    }
}

#[test]
fn axis_parallel_windowing_matches_brute_force() {
    for (n, side, seed) in [
        (0, 4, 1),
        (1, 4, 2),
        (60, 6, 3),
        (400, 10, 4),
        (1500, 30, 5),
    ] {
        let segs = axis_parallel(n, side, seed);
        check_window_structures(
            &segs,
            &windows(60, -1.0, side as f64 + 1.0, seed + 10),
            true,
        );
    }
}

#[test]
fn non_crossing_windowing_matches_brute_force() {
    for (k, cols, seed) in [(1, 2, 1), (3, 4, 2), (6, 10, 3), (12, 30, 4), (30, 60, 5)] {
        let segs = non_crossing(k, cols, seed);
        let maxx = segs.iter().map(|s| s.a.x.max(s.b.x)).fold(0.0, f64::max);
        check_window_structures(
            &segs,
            &windows(80, -1.0, maxx.max(7.0) + 1.0, seed + 20),
            false,
        );
    }
}

#[test]
fn window_cutting_a_corner_is_found() {
    // No endpoint inside, crossing the top and right edges only.
    let s = Segment2::new(p(1.0, 3.0), p(3.0, 1.0));
    let segs = [s];
    let w = win(0.0, 0.0, 2.1, 2.1);
    assert_eq!(SegmentWindow::new(&segs).unwrap().query(&w), vec![0]);
    // Touching the corner exactly at (2, 2): still meets the closed window.
    assert_eq!(
        SegmentWindow::new(&[Segment2::new(p(1.0, 3.0), p(3.0, 1.0))])
            .unwrap()
            .query(&win(0.0, 0.0, 2.0, 2.0)),
        vec![0]
    );
    // Just missing it: x + y = 4 against the window [0, 1.9999999999999998]².
    let m = 2.0f64.next_down();
    assert!(SegmentWindow::new(&segs)
        .unwrap()
        .query(&win(0.0, 0.0, m, m))
        .is_empty());
}

#[test]
fn crossing_segments_are_refused_and_bad_input_named() {
    let x = [
        Segment2::new(p(0.0, 0.0), p(2.0, 2.0)),
        Segment2::new(p(0.0, 2.0), p(2.0, 0.0)),
    ];
    let e = SegmentWindow::new(&x).unwrap_err().to_string();
    assert!(e.contains("segments 0 and 1 cross"), "{e}");
    let bad = [Segment2::new(p(0.0, 0.0), p(f64::NAN, 1.0))];
    assert!(SegmentWindow::new(&bad)
        .unwrap_err()
        .to_string()
        .contains("segment 0"));
    assert!(AxisParallelWindow::new(&bad)
        .unwrap_err()
        .to_string()
        .contains("segment 0"));
    let e = AxisParallelWindow::new(&[x[0]]).unwrap_err().to_string();
    assert!(e.contains("neither horizontal nor vertical"), "{e}");
    assert!(IntervalTree::new(&[(1.0, 0.0)]).is_err());
    assert!(SegmentTree::new(&[(0.0, f64::INFINITY)]).is_err());
    assert!(PrioritySearchTree::new(&[p(f64::NAN, 0.0)]).is_err());
}

fn brute_stab(iv: &[(f64, f64)], q: f64) -> Vec<usize> {
    (0..iv.len())
        .filter(|&i| iv[i].0 <= q && q <= iv[i].1)
        .collect()
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(96))]

    #[test]
    fn stabbing_matches_brute_force(raw in prop::collection::vec((0i32..12, 0i32..6), 0..80), qs in prop::collection::vec(-2i32..30, 1..10)) {
        let iv: Vec<(f64, f64)> = raw.iter().map(|&(a, l)| (a as f64 * 0.5, (a + l) as f64 * 0.5)).collect();
        let it = IntervalTree::new(&iv).unwrap();
        let st = SegmentTree::new(&iv).unwrap();
        for q in qs {
            let q = q as f64 * 0.25;
            let want = brute_stab(&iv, q);
            prop_assert_eq!(it.stab(q), want.clone());
            prop_assert_eq!(st.stab(q), want);
        }
    }

    #[test]
    fn priority_search_tree_matches_brute_force(raw in prop::collection::vec((0i32..8, 0i32..8), 0..100), qx in -1i32..9, y1 in -1i32..9, y2 in -1i32..9) {
        let pts: Vec<Point2> = raw.iter().map(|&(x, y)| p(x as f64, y as f64)).collect();
        let t = PrioritySearchTree::new(&pts).unwrap();
        let (qx, y1, y2) = (qx as f64, y1 as f64, y2 as f64);
        let want: Vec<usize> = (0..pts.len()).filter(|&i| pts[i].x <= qx && y1 <= pts[i].y && pts[i].y <= y2).collect();
        prop_assert_eq!(t.query(qx, y1, y2), want);
    }

    #[test]
    fn windowing_random_matches_brute_force(n in 0usize..120, side in 2u32..12, k in 1usize..8, cols in 2usize..12, seed in 0u64..1000) {
        let segs = axis_parallel(n, side, seed);
        check_window_structures(&segs, &windows(12, -1.0, side as f64 + 1.0, seed), true);
        let segs = non_crossing(k, cols, seed);
        check_window_structures(&segs, &windows(12, -1.0, 40.0, seed), false);
    }

    /// Long sorted lists in few slabs (the searches over list keys and the exact tests
    /// at their fringe): many stacked sloped segments, several on one line (collinear,
    /// overlapping or duplicated), windows with edges on the segments' coordinates.
    #[test]
    fn windowing_on_stacked_segments_matches_brute_force(
        raw in prop::collection::vec((0i32..40, 0i32..4, 0i32..4), 0..150),
        ws in prop::collection::vec((-4i32..20, -8i32..170, 0i32..12, 0i32..40), 1..10),
    ) {
        // Row r is the line y = r + slope * x, slope in {-1/8, 0, 1/8}: exact, and rows
        // never meet for x in [0, 3].
        let line = |r: i32, x: i32| p(x as f64, r as f64 + ((r % 3) - 1) as f64 * 0.125 * x as f64);
        let segs: Vec<Segment2> = raw
            .iter()
            .map(|&(r, a, b)| Segment2::new(line(r, a), line(r, b)))
            .collect();
        let ws: Vec<Bbox2> = ws
            .iter()
            .map(|&(x, y, w, h)| win(x as f64 * 0.25, y as f64 * 0.25, (x + w) as f64 * 0.25, (y + h) as f64 * 0.25))
            .collect();
        check_window_structures(&segs, &ws, false);
    }
}

#[test]
fn infinite_and_nan_windows() {
    let segs = non_crossing(5, 8, 77);
    let all: Vec<usize> = (0..segs.len()).collect();
    let inf = f64::INFINITY;
    let sw = SegmentWindow::new(&segs).unwrap();
    assert_eq!(sw.query(&win(-inf, -inf, inf, inf)), all);
    let half = win(-inf, 2.0, inf, inf);
    assert_eq!(sw.query(&half), brute(&segs, &win(-1e9, 2.0, 1e9, 1e9)));
    assert!(sw.query(&win(f64::NAN, 0.0, 1.0, 1.0)).is_empty());
    let ap_segs = axis_parallel(200, 8, 78);
    let ap = AxisParallelWindow::new(&ap_segs).unwrap();
    let strip = win(3.0, -inf, 4.0, inf);
    assert_eq!(ap.query(&strip), brute(&ap_segs, &win(3.0, -1e9, 4.0, 1e9)));
    assert!(ap.query(&win(0.0, f64::NAN, 1.0, 1.0)).is_empty());
}

/// One short segment in each cell of a `k × k` grid, endpoints anywhere in the cell (so
/// none cross and almost every x is distinct), a few of them vertical, horizontal, points
/// or sharing an endpoint with the next cell's segment; plus long segments between the
/// rows (they span many slabs of the structure).
fn cell_segments(k: usize, seed: u64) -> Vec<Segment2> {
    let mut r = Lcg(seed);
    let mut u =
        |cell: usize| cell as f64 + 0.05 + r.next(1 << 20) as f64 / (1u64 << 20) as f64 * 0.9;
    let mut segs = Vec::new();
    for i in 0..k {
        for j in 0..k {
            let a = p(u(i), u(j));
            let mut b = p(u(i), u(j));
            match (i * 7 + j * 3) % 11 {
                0 => b = p(a.x, b.y),
                1 => b = p(b.x, a.y),
                2 => b = a,
                _ => {}
            }
            segs.push(Segment2::new(a, b));
        }
        // Along the gap between row i and row i + 1, touching at the ends.
        let y = i as f64 + 0.99;
        segs.push(Segment2::new(p(0.0, y), p(k as f64 * 0.5, y + 0.005)));
        segs.push(Segment2::new(p(k as f64 * 0.5, y + 0.005), p(k as f64, y)));
    }
    segs
}

#[test]
fn windowing_on_many_distinct_coordinates_matches_brute_force() {
    for (k, seed) in [(5, 1), (40, 2)] {
        let segs = cell_segments(k, seed);
        let mut ws = windows(150, -1.0, k as f64 + 1.0, seed + 30);
        // Windows at the segments' own coordinates: edges through endpoints.
        for s in segs.iter().step_by(37) {
            ws.push(win(s.a.x, s.a.y, s.a.x + 1.5, s.a.y + 0.7));
            ws.push(win(s.b.x - 0.3, s.b.y - 2.0, s.b.x, s.b.y));
            ws.push(win(s.a.x, s.a.y, s.a.x, s.a.y));
        }
        check_window_structures(&segs, &ws, false);
    }
}

#[test]
fn crossing_long_segments_are_refused() {
    // Two long segments crossing among many short ones: both span everything, so they
    // share the root's list, whose order they break.
    let mut segs = cell_segments(12, 3);
    let n = segs.len();
    segs.push(Segment2::new(p(0.0, 0.995), p(12.0, 1.995)));
    segs.push(Segment2::new(p(12.0, 0.995), p(0.0, 1.995)));
    let e = SegmentWindow::new(&segs).unwrap_err().to_string();
    assert!(
        e.contains(&format!("segments {n} and {} cross", n + 1)),
        "{e}"
    );
}
