//! Range searching (chapter 5) against brute force, on random and degenerate input: every
//! structure, every query type (iterator, callback, sorted query, count; k-NN and radius
//! for the kd-tree; d dimensions).

mod common;
use compgeom::range::{
    compare_distance, read_rects, KdTree, LayeredRangeTree, RangeTree, RangeTreeD,
};
use compgeom::{Bbox2, Point2};
use proptest::prelude::*;
use std::cmp::Ordering;

fn rect(x0: f64, y0: f64, x1: f64, y1: f64) -> Bbox2 {
    Bbox2 {
        min: Point2::new(x0, y0),
        max: Point2::new(x1, y1),
    }
}

fn brute(points: &[Point2], r: &Bbox2) -> Vec<usize> {
    (0..points.len())
        .filter(|&i| r.contains(points[i]))
        .collect()
}

/// Every structure and every way of asking agrees with brute force on every rectangle.
fn check_all(points: &[Point2], rects: &[Bbox2]) {
    let kd = KdTree::new(points).unwrap();
    let rt = RangeTree::new(points).unwrap();
    let lt = LayeredRangeTree::new(points).unwrap();
    let dpts: Vec<[f64; 2]> = points.iter().map(|p| [p.x, p.y]).collect();
    let dt = RangeTreeD::new(2, &dpts).unwrap();
    for r in rects {
        let want = brute(points, r);
        let sorted = |mut v: Vec<usize>| {
            v.sort_unstable();
            v
        };
        assert_eq!(kd.query(r), want, "kd-tree {r:?}");
        assert_eq!(sorted(kd.iter(r).collect()), want, "kd-tree iter {r:?}");
        assert_eq!(kd.count(r), want.len(), "kd-tree count {r:?}");
        assert_eq!(rt.query(r), want, "range tree {r:?}");
        assert_eq!(sorted(rt.iter(r).collect()), want, "range tree iter {r:?}");
        assert_eq!(rt.count(r), want.len(), "range tree count {r:?}");
        assert_eq!(lt.query(r), want, "layered {r:?}");
        assert_eq!(sorted(lt.iter(r).collect()), want, "layered iter {r:?}");
        assert_eq!(lt.count(r), want.len(), "layered count {r:?}");
        let mut v = Vec::new();
        lt.for_each(r, |i| v.push(i));
        assert_eq!(sorted(v), want);
        let (lo, hi) = ([r.min.x, r.min.y], [r.max.x, r.max.y]);
        assert_eq!(dt.query(&lo, &hi).unwrap(), want, "d-dim {r:?}");
        assert_eq!(dt.count(&lo, &hi).unwrap(), want.len(), "d-dim count {r:?}");
    }
}

fn brute_knn(points: &[Point2], q: Point2, k: usize) -> Vec<usize> {
    let mut ids: Vec<usize> = (0..points.len()).collect();
    ids.sort_by(|&a, &b| compare_distance(q, points[a], points[b]).then(a.cmp(&b)));
    ids.truncate(k);
    ids
}

fn grid_points(n: usize, side: u32, seed: u64) -> Vec<Point2> {
    let mut below = common::below(seed);
    (0..n)
        .map(|_| {
            let x = below(u64::from(side)) as f64;
            Point2::new(x, below(u64::from(side)) as f64)
        })
        .collect()
}

fn grid_rects(m: usize, side: u32, seed: u64) -> Vec<Bbox2> {
    let p = grid_points(2 * m, side + 2, seed);
    p.chunks(2)
        .map(|c| rect(c[0].x - 1.0, c[0].y - 1.0, c[1].x - 1.0, c[1].y - 1.0))
        .collect()
}

#[test]
fn empty_and_tiny_inputs() {
    check_all(&[], &[rect(0.0, 0.0, 1.0, 1.0)]);
    check_all(
        &[Point2::new(1.0, 1.0)],
        &[rect(1.0, 1.0, 1.0, 1.0), rect(0.0, 0.0, 0.5, 2.0)],
    );
    let kd = KdTree::new(&[]).unwrap();
    assert!(kd.nearest(Point2::new(0.0, 0.0), 3).is_empty());
    assert!(kd.within_radius(Point2::new(0.0, 0.0), 3.0).is_empty());
}

#[test]
fn many_equal_coordinates_and_duplicates() {
    for (n, side) in [(50, 3), (300, 5), (2000, 7), (3000, 40)] {
        let pts = grid_points(n, side, n as u64);
        let mut rects = grid_rects(60, side, 7 + n as u64);
        // Degenerate rectangles: a point, a vertical and a horizontal segment, an empty one,
        // half-planes with infinite bounds.
        rects.push(rect(1.0, 1.0, 1.0, 1.0));
        rects.push(rect(2.0, 0.0, 2.0, 4.0));
        rects.push(rect(0.0, 3.0, 9.0, 3.0));
        rects.push(rect(2.0, 2.0, 1.0, 5.0));
        rects.push(rect(f64::NEG_INFINITY, 1.0, f64::INFINITY, 2.0));
        rects.push(rect(
            f64::NEG_INFINITY,
            f64::NEG_INFINITY,
            f64::INFINITY,
            f64::INFINITY,
        ));
        check_all(&pts, &rects);
    }
}

#[test]
fn all_points_on_a_line_or_equal() {
    let diag: Vec<Point2> = (0..500)
        .map(|i| Point2::new(i as f64, 2.0 * i as f64))
        .collect();
    let vert: Vec<Point2> = (0..500)
        .map(|i| Point2::new(3.0, (i % 37) as f64))
        .collect();
    let same = vec![Point2::new(-0.0, 0.0); 100];
    for pts in [diag, vert, same] {
        let rects = vec![
            rect(10.0, 0.0, 100.0, 50.0),
            rect(3.0, 5.0, 3.0, 5.0),
            rect(0.0, 0.0, 0.0, 0.0),
            rect(-1.0, -1.0, 1000.0, 1000.0),
            rect(3.5, 0.0, 2.5, 40.0),
        ];
        check_all(&pts, &rects);
    }
}

#[test]
fn non_finite_points_are_errors_naming_the_point() {
    let pts = [Point2::new(0.0, 0.0), Point2::new(f64::NAN, 1.0)];
    for e in [
        KdTree::new(&pts).err(),
        RangeTree::new(&pts).err(),
        LayeredRangeTree::new(&pts).err(),
    ] {
        assert!(e.unwrap().to_string().contains("point 1"));
    }
    let e = RangeTreeD::new(2, &[vec![0.0, f64::INFINITY]]).unwrap_err();
    assert!(e.to_string().contains("point 0"));
    assert!(RangeTreeD::new(2, &[vec![0.0]]).is_err());
    assert!(RangeTreeD::new(0, &[[0.0; 0]]).is_err());
    let t = RangeTreeD::new(1, &[[1.0]]).unwrap();
    assert!(t.query(&[0.0, 1.0], &[1.0]).is_err());
    assert!(t.query(&[f64::NAN], &[1.0]).is_err());
}

#[test]
fn knn_and_radius_on_grid_with_ties() {
    let pts = grid_points(800, 9, 3);
    let kd = KdTree::new(&pts).unwrap();
    for (i, q) in grid_points(40, 11, 5).into_iter().enumerate() {
        let q = Point2::new(q.x - 0.5 * (i % 2) as f64, q.y);
        for k in [1, 2, 7, 50, 900] {
            assert_eq!(kd.nearest(q, k), brute_knn(&pts, q, k), "knn {q:?} {k}");
        }
        for r in [0.0, 1.0, 1.5, 2.0f64.sqrt(), 3.0] {
            let want: Vec<usize> = (0..pts.len())
                .filter(|&j| {
                    let (dx, dy) = (pts[j].x - q.x, pts[j].y - q.y);
                    dx * dx + dy * dy <= r * r // small integers and halves: exact in f64
                })
                .collect();
            assert_eq!(kd.within_radius(q, r), want, "radius {q:?} {r}");
        }
    }
}

#[test]
fn knn_decides_near_ties_exactly() {
    // Two points whose squared distances from q differ in the last bits.
    let q = Point2::new(0.1, 0.2);
    let a = Point2::new(0.1 + 3.0, 0.2 + 4.0);
    let b = Point2::new(0.1 + 5.0, 0.2);
    let pts = vec![b, a, Point2::new(100.0, 100.0)];
    let kd = KdTree::new(&pts).unwrap();
    let want = brute_knn(&pts, q, 1);
    assert_eq!(kd.nearest(q, 1), want);
    let o = compare_distance(q, a, b);
    assert_eq!(
        kd.nearest(q, 2),
        if o == Ordering::Greater {
            vec![0, 1]
        } else {
            vec![1, 0]
        }
    );
}

#[test]
fn three_dimensional_range_tree() {
    let pts: Vec<[f64; 3]> = grid_points(700, 6, 11)
        .iter()
        .zip(grid_points(700, 4, 12))
        .map(|(p, q)| [p.x, p.y, q.x])
        .collect();
    let t = RangeTreeD::new(3, &pts).unwrap();
    let boxes = grid_points(100, 7, 13);
    for w in boxes.chunks(4) {
        let lo = [w[0].x - 1.0, w[0].y - 1.0, w[1].x - 2.0];
        let hi = [w[2].x, w[2].y, w[3].y - 1.0];
        let want: Vec<usize> = (0..pts.len())
            .filter(|&i| (0..3).all(|k| lo[k] <= pts[i][k] && pts[i][k] <= hi[k]))
            .collect();
        assert_eq!(t.query(&lo, &hi).unwrap(), want);
        assert_eq!(t.count(&lo, &hi).unwrap(), want.len());
    }
    let one = RangeTreeD::new(1, &pts.iter().map(|p| [p[0]]).collect::<Vec<_>>()).unwrap();
    let want: Vec<usize> = (0..pts.len())
        .filter(|&i| (1.0..=3.0).contains(&pts[i][0]))
        .collect();
    assert_eq!(one.query(&[1.0], &[3.0]).unwrap(), want);
}

#[test]
fn rect_files_have_located_errors() {
    let r = read_rects("# queries\nxmin ymin xmax ymax\n0 0 1 1\n2;3;4;5\n", "q").unwrap();
    assert_eq!(r, vec![rect(0.0, 0.0, 1.0, 1.0), rect(2.0, 3.0, 4.0, 5.0)]);
    for (text, line, what) in [
        ("0,0,1,1\n0,0,1\n", 2, "expected 4 fields"),
        ("0,0,1,x\n", 1, "malformed number"),
        ("\n\n0,0,1,inf\n", 3, "non-finite"),
        ("0,,1,1\n", 1, "field 2 is empty"),
    ] {
        let e = read_rects(text, "q.csv").unwrap_err().to_string();
        assert!(
            e.contains(&format!("q.csv:{line}")) && e.contains(what),
            "{e}"
        );
    }
}

fn degenerate_points() -> impl Strategy<Value = Vec<Point2>> {
    prop_oneof![
        prop::collection::vec((0i32..6, 0i32..6), 0..120).prop_map(|v| v
            .into_iter()
            .map(|(x, y)| Point2::new(x as f64, y as f64))
            .collect()),
        prop::collection::vec((-1e3f64..1e3, -1e3f64..1e3), 0..200)
            .prop_map(|v| v.into_iter().map(|(x, y)| Point2::new(x, y)).collect()),
        prop::collection::vec(0i32..20, 0..100).prop_map(|v| v
            .into_iter()
            .map(|t| Point2::new(t as f64, 7.0 - 0.5 * t as f64))
            .collect()),
        // All on one vertical line (every x equal), with repeated y.
        prop::collection::vec(0i32..8, 0..100).prop_map(|v| v
            .into_iter()
            .map(|t| Point2::new(2.0, t as f64 * 0.5))
            .collect()),
        // One point, many times, and -0.0 beside 0.0.
        (0usize..60, prop::bool::ANY).prop_map(|(n, neg)| (0..n)
            .map(|i| if neg && i % 2 == 0 {
                Point2::new(-0.0, 3.0)
            } else {
                Point2::new(0.0, 3.0)
            })
            .collect()),
    ]
}

fn any_rect() -> impl Strategy<Value = Bbox2> {
    prop_oneof![
        (-1i32..7, -1i32..7, -1i32..7, -1i32..7)
            .prop_map(|(a, b, c, d)| rect(a as f64, b as f64, c as f64, d as f64)),
        (-1e3f64..1e3, -1e3f64..1e3, 0f64..800.0, 0f64..800.0).prop_map(|(x, y, w, h)| rect(
            x,
            y,
            x + w,
            y + h
        )),
        (0i32..20).prop_map(|t| rect(t as f64, -10.0, 20.0, 10.0)),
    ]
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(96))]

    #[test]
    fn structures_agree_with_brute_force(pts in degenerate_points(), rects in prop::collection::vec(any_rect(), 1..8)) {
        check_all(&pts, &rects);
    }

    #[test]
    fn knn_agrees_with_brute_force(pts in degenerate_points(), qx in -2i32..8, qy in -2i32..8, k in 0usize..12) {
        let kd = KdTree::new(&pts).unwrap();
        let q = Point2::new(qx as f64 * 0.5, qy as f64);
        prop_assert_eq!(kd.nearest(q, k), brute_knn(&pts, q, k));
    }
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(24))]

    /// Trees several levels deep (split values matter) on small integer grids: many
    /// duplicates, equal x and equal y, and ties in distance from half-integer queries;
    /// `k` from 0 to beyond `n`.
    #[test]
    fn knn_on_deep_trees_with_ties(n in 0usize..600, side in 1u32..12, seed in 0u64..1000,
                                   qs in prop::collection::vec((-4i32..28, -4i32..28), 1..6),
                                   k in prop_oneof![Just(0usize), 1usize..12, 590usize..620]) {
        let pts = grid_points(n, side, seed);
        let kd = KdTree::new(&pts).unwrap();
        for (qx, qy) in qs {
            let q = Point2::new(qx as f64 * 0.5, qy as f64 * 0.5);
            prop_assert_eq!(kd.nearest(q, k), brute_knn(&pts, q, k), "q {:?} k {}", q, k);
        }
    }
}

#[test]
fn parallel_build_matches_brute_force() {
    // Above the parallel threshold (32768 points), with many duplicates.
    let pts = grid_points(40_000, 300, 21);
    let rects = grid_rects(30, 300, 22);
    check_all(&pts, &rects);
}
