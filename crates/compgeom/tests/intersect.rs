//! Segment intersection (book §2.1): the sweep against the exact brute-force oracle on
//! random and deliberately degenerate input, plus hand-made cases for every degenerate
//! situation, the O(n) queue bound, Shamos–Hoey / is_simple and red/blue.
mod common;

use compgeom::intersect::{
    any_intersection, brute_force_intersections, count_intersections, count_intersections_with,
    find_intersections, find_intersections_with, is_simple, pairwise_intersections,
    red_blue_intersections, sweep_intersections, sweep_intersections_with_stats, sweep_status_at,
    verify_intersections, IntersectAlgorithm, IntersectionCount, Intersections, Overlap,
};
use compgeom::kernel::{orient2d, segment_intersection, Orientation, SegmentIntersection};
use compgeom::{Error, Point2, Polygon, Segment2};
use proptest::prelude::*;

fn p(x: f64, y: f64) -> Point2 {
    Point2::new(x, y)
}

fn s(ax: f64, ay: f64, bx: f64, by: f64) -> Segment2 {
    Segment2::new(p(ax, ay), p(bx, by))
}

/// The sweep's answer, checked against the oracle (full comparison); the pairwise method
/// and the default must give exactly the same answer.
fn checked(segs: &[Segment2]) -> Intersections {
    let found = sweep_intersections(segs).unwrap();
    let expected = brute_force_intersections(segs).unwrap();
    assert_eq!(
        pairwise_intersections(segs).unwrap(),
        expected,
        "pairwise for {segs:?}"
    );
    assert_eq!(
        find_intersections(segs).unwrap(),
        expected,
        "default for {segs:?}"
    );
    assert_eq!(
        found.points.len(),
        expected.points.len(),
        "point count for {segs:?}"
    );
    for (f, e) in found.points.iter().zip(&expected.points) {
        assert_eq!(f.point, e.point, "{segs:?}");
        assert_eq!(
            (f.segments(), f.upper(), f.lower(), f.interior()),
            (e.segments(), e.upper(), e.lower(), e.interior()),
            "at {:?} for {segs:?}",
            f.point
        );
    }
    assert_eq!(found.overlaps, expected.overlaps, "overlaps for {segs:?}");
    verify_intersections(segs, &found).unwrap();
    let want = IntersectionCount {
        points: expected.points.len(),
        overlaps: expected.overlaps.len(),
        pairs: expected.pair_count(),
    };
    assert_eq!(
        count_intersections(segs).unwrap(),
        want,
        "count for {segs:?}"
    );
    for how in [IntersectAlgorithm::Pairwise, IntersectAlgorithm::Sweep] {
        let got = count_intersections_with(segs, how).unwrap();
        assert_eq!(got, want, "{how:?} count for {segs:?}");
    }
    rounded_by_the_kernel(segs, &expected);
    found
}

/// Every reported point is the kernel's correctly rounded point of its exact point
/// (`ExactPoint::approx`, independent of the fast rounding the methods use), bit for bit.
fn rounded_by_the_kernel(segs: &[Segment2], found: &Intersections) {
    for p in &found.points {
        let exact = p.exact(segs);
        let want = exact.approx();
        assert_eq!(
            (p.point.x.to_bits(), p.point.y.to_bits()),
            (want.x.to_bits(), want.y.to_bits()),
            "{exact:?}"
        );
        // A crossing is no input point, and its defining pair is two of its segments
        // that are not collinear (so they meet in that one point only).
        if let Some((i, j)) = p.crossing_pair() {
            assert!(p.upper().is_empty() && p.lower().is_empty(), "{p:?}");
            assert_eq!(p.interior(), p.segments(), "{p:?}");
            assert!(i < j && p.segments().contains(&j), "{p:?}");
            let (s, t) = (segs[i], segs[j]);
            let on_line = |q| orient2d(s.a, s.b, q) == Orientation::Collinear;
            assert!(!(on_line(t.a) && on_line(t.b)), "{p:?}");
        }
    }
}

// ------------------------------------------------------------------ hand-made cases

#[test]
fn a_proper_crossing_is_rounded_to_nearest() {
    let found = checked(&[s(0.0, 0.0, 3.0, 1.0), s(0.0, 1.0, 3.0, 0.0)]);
    assert_eq!(found.points.len(), 1);
    assert_eq!(found.points[0].point, p(1.5, 0.5));
    assert_eq!(found.points[0].interior(), vec![0, 1]);
    // A crossing at x = 1/3: reported as the nearest double.
    let found = checked(&[s(0.0, 0.0, 1.0, 3.0), s(0.0, 1.0, 1.0, 0.0)]);
    assert_eq!(found.points[0].point, p(0.25, 0.75));
    let found = checked(&[s(0.0, 0.0, 3.0, 3.0), s(0.0, 1.0, 1.0, 0.0)]);
    assert_eq!(found.points[0].point, p(0.5, 0.5));
    let found = checked(&[s(0.0, 0.0, 2.0, 2.0), s(0.0, 2.0, 3.0, 0.0)]);
    assert_eq!(found.points[0].point, p(1.2, 1.2));
}

/// Crossings on a grid of the smallest subnormals, many at a coordinate between
/// −½ and 0 of a float gap: every method reports `-0.0` there, bit for bit the nearest
/// float as [`Crossing::approx`] rounds it (the pair scans key points with `-0.0` as
/// `0.0` to group them, and once reported `0.0`).
#[test]
fn a_crossing_rounded_to_zero_keeps_its_sign() {
    use compgeom::kernel::Crossing;
    let tiny = f64::from_bits(1);
    let mut seed = 99u64;
    let mut grid = || {
        seed ^= seed << 13;
        seed ^= seed >> 7;
        seed ^= seed << 17;
        ((seed >> 11) % 41) as f64 * tiny - 20.0 * tiny
    };
    let mut negative_zeros = 0;
    for _ in 0..8000 {
        let mut seg = || Segment2::new(p(grid(), grid()), p(grid(), grid()));
        let (a, b) = (seg(), seg());
        let Some(c) = Crossing::new(a, b) else {
            continue;
        };
        // (Only where the segments cross properly: in the interior of both.)
        if !matches!(segment_intersection(a, b), SegmentIntersection::Crossing(_)) {
            continue;
        }
        let q = c.approx();
        negative_zeros += usize::from(q.x.is_sign_negative() && q.x == 0.0);
        negative_zeros += usize::from(q.y.is_sign_negative() && q.y == 0.0);
        let bits = |r: Point2| (r.x.to_bits(), r.y.to_bits());
        for how in [
            IntersectAlgorithm::Default,
            IntersectAlgorithm::Pairwise,
            IntersectAlgorithm::Sweep,
        ] {
            let found = find_intersections_with(&[a, b], how).unwrap();
            let crossing = found.points.iter().find(|x| x.interior() == [0, 1]);
            if let Some(x) = crossing {
                assert_eq!(bits(x.point), bits(q), "{how:?} {a:?} {b:?}");
            }
        }
    }
    assert!(negative_zeros > 40, "{negative_zeros}");
}

#[test]
fn upper_lower_interior_follow_the_book() {
    // Three segments through (2, 2): 0 ends there (lower), 1 starts there (upper,
    // going down), 2 passes through; 3 is horizontal with its left (upper) end there.
    let segs = [
        s(0.0, 4.0, 2.0, 2.0),
        s(2.0, 2.0, 4.0, 0.0),
        s(2.0, 0.0, 2.0, 4.0),
        s(2.0, 2.0, 5.0, 2.0),
    ];
    let found = checked(&segs);
    assert_eq!(found.points.len(), 1);
    let q = &found.points[0];
    assert_eq!(q.point, p(2.0, 2.0));
    assert_eq!(q.segments(), vec![0, 1, 2, 3]);
    assert_eq!(q.upper(), vec![1, 3]);
    assert_eq!(q.lower(), vec![0]);
    assert_eq!(q.interior(), vec![2]);
}

#[test]
fn results_come_in_the_books_sweep_order() {
    // A grid of 3 horizontal and 3 vertical segments: 9 crossings, top row first, left
    // to right.
    let mut segs = Vec::new();
    for k in 1..=3 {
        segs.push(s(0.0, k as f64, 4.0, k as f64));
        segs.push(s(k as f64, 0.0, k as f64, 4.0));
    }
    let found = checked(&segs);
    let order: Vec<Point2> = found.points.iter().map(|q| q.point).collect();
    let mut expected = Vec::new();
    for y in [3.0, 2.0, 1.0] {
        for x in [1.0, 2.0, 3.0] {
            expected.push(p(x, y));
        }
    }
    assert_eq!(order, expected);
}

#[test]
fn overlaps_are_maximal_pieces_with_their_segment_sets() {
    // 0 and 1 overlap on [2, 4]; 2 duplicates 0; 3 is collinear but only touches 1 at 6.
    let segs = [
        s(0.0, 0.0, 4.0, 0.0),
        s(2.0, 0.0, 6.0, 0.0),
        s(4.0, 0.0, 0.0, 0.0),
        s(6.0, 0.0, 8.0, 0.0),
    ];
    let found = checked(&segs);
    assert_eq!(
        found.overlaps,
        vec![
            Overlap {
                segments: vec![0, 2],
                from: p(0.0, 0.0),
                to: p(2.0, 0.0)
            },
            Overlap {
                segments: vec![0, 1, 2],
                from: p(2.0, 0.0),
                to: p(4.0, 0.0)
            },
        ]
    );
    let points: Vec<Point2> = found.points.iter().map(|q| q.point).collect();
    assert_eq!(
        points,
        vec![p(0.0, 0.0), p(2.0, 0.0), p(4.0, 0.0), p(6.0, 0.0)]
    );
    // A crossing inside an overlap does not split the piece.
    let segs = [
        s(0.0, 0.0, 4.0, 4.0),
        s(1.0, 1.0, 5.0, 5.0),
        s(0.0, 4.0, 4.0, 0.0),
    ];
    let found = checked(&segs);
    assert_eq!(found.overlaps.len(), 1);
    assert_eq!(found.overlaps[0].from, p(4.0, 4.0));
    assert_eq!(found.overlaps[0].to, p(1.0, 1.0));
    assert_eq!(found.points.len(), 3);
}

#[test]
fn zero_length_and_duplicate_segments() {
    let segs = [
        s(1.0, 1.0, 1.0, 1.0), // a point on segment 2
        s(1.0, 1.0, 1.0, 1.0), // the same point again
        s(0.0, 0.0, 2.0, 2.0),
        s(5.0, 5.0, 5.0, 5.0), // alone: no intersection
        s(2.0, 2.0, 0.0, 0.0), // duplicate of 2, reversed
    ];
    let found = checked(&segs);
    let q = found
        .points
        .iter()
        .find(|q| q.point == p(1.0, 1.0))
        .unwrap();
    assert_eq!(q.segments(), vec![0, 1, 2, 4]);
    assert_eq!(q.upper(), vec![0, 1]);
    assert_eq!(q.lower(), vec![0, 1]);
    assert_eq!(q.interior(), vec![2, 4]);
    assert!(found.points.iter().all(|q| q.point != p(5.0, 5.0)));
    assert_eq!(found.overlaps.len(), 1);
    assert_eq!(found.overlaps[0].segments, vec![2, 4]);
    // Two equal point segments meet each other.
    let found = checked(&[s(3.0, 3.0, 3.0, 3.0), s(3.0, 3.0, 3.0, 3.0)]);
    assert_eq!(found.points.len(), 1);
}

#[test]
fn empty_and_single_inputs() {
    assert_eq!(checked(&[]).points.len(), 0);
    assert_eq!(checked(&[s(0.0, 0.0, 1.0, 1.0)]).points.len(), 0);
}

#[test]
fn non_finite_input_names_the_segment() {
    let segs = [s(0.0, 0.0, 1.0, 1.0), s(0.0, f64::NAN, 1.0, 1.0)];
    let err = find_intersections(&segs).unwrap_err();
    assert!(
        matches!(err, Error::NonFinite { ref what, .. } if what == "segment 1"),
        "{err}"
    );
    assert!(brute_force_intersections(&segs).is_err());
    assert!(any_intersection(&[s(0.0, 0.0, f64::INFINITY, 1.0)]).is_err());
}

#[test]
fn nearly_parallel_and_huge_coordinates_are_exact() {
    // Crossings of nearly parallel segments, and their order, decided exactly.
    let e = f64::EPSILON;
    let segs = [
        s(0.0, 0.0, 1.0, 1.0),
        s(0.0, e, 1.0, 1.0 - e),
        s(0.0, 2.0 * e, 1.0, 1.0 - 3.0 * e),
        s(1e200, -1e200, -1e200, 1e200),
        s(-1e-300, -1e-300, 1e-300, 1e-300),
    ];
    checked(&segs);
}

#[test]
fn the_queue_holds_o_n_events() {
    // 60 long segments with ~900 crossings: only adjacent pairs' crossings stay queued.
    let n = 60;
    let segs: Vec<Segment2> = (0..n)
        .map(|i| {
            let t = i as f64 / n as f64;
            s(0.0, t, 1.0, 1.0 - t * 0.999)
        })
        .collect();
    let (found, stats) = sweep_intersections_with_stats(&segs).unwrap();
    assert!(found.points.len() > n * (n - 1) / 4);
    assert!(
        stats.max_queue <= 3 * n,
        "queue grew to {}",
        stats.max_queue
    );
    assert_eq!(
        stats.events,
        found.points.len() + 2 * n - shared_endpoints(&segs)
    );
}

fn shared_endpoints(segs: &[Segment2]) -> usize {
    let mut pts: Vec<(u64, u64)> = segs
        .iter()
        .flat_map(|s| [s.a, s.b])
        .map(|q| (q.x.to_bits(), q.y.to_bits()))
        .collect();
    let all = pts.len();
    pts.sort_unstable();
    pts.dedup();
    all - pts.len()
}

#[test]
fn status_snapshot_is_the_order_below_the_event() {
    let segs = [
        s(0.0, 4.0, 4.0, 0.0),
        s(3.0, 3.0, 1.0, 0.0),
        s(2.0, 5.0, 2.0, -1.0),
    ];
    // Events: (2,5) [2 in], (0,4) [0 in], (3,3) [1 in], ...
    let snap = sweep_status_at(&segs, 2).unwrap().unwrap();
    assert_eq!(snap.at, p(3.0, 3.0));
    assert_eq!(snap.status, vec![0, 2, 1]);
    assert!(sweep_status_at(&segs, 100).unwrap().is_none());
}

// ------------------------------------------------------------------ generators

fn grid_point(k: i32) -> impl Strategy<Value = Point2> {
    (0..=k, 0..=k).prop_map(|(x, y)| p(x as f64, y as f64))
}

/// Endpoints on a small grid: shared endpoints, overlaps, duplicates, zero-length.
fn grid_segments(k: i32, n: usize) -> impl Strategy<Value = Vec<Segment2>> {
    prop::collection::vec((grid_point(k), grid_point(k)), 0..n)
        .prop_map(|v| v.into_iter().map(|(a, b)| Segment2::new(a, b)).collect())
}

/// Only horizontal and vertical segments on a grid.
fn axis_segments() -> impl Strategy<Value = Vec<Segment2>> {
    prop::collection::vec((any::<bool>(), 0..7i32, 0..7i32, 0..7i32), 0..30).prop_map(|v| {
        v.into_iter()
            .map(|(h, c, a, b)| {
                let (c, a, b) = (c as f64, a as f64, b as f64);
                if h {
                    s(a, c, b, c)
                } else {
                    s(c, a, c, b)
                }
            })
            .collect()
    })
}

/// Many segments through one point (through it, ending at it, starting at it).
fn star_segments() -> impl Strategy<Value = Vec<Segment2>> {
    let spoke = (-4..=4i32, -4..=4i32, 0..=2i32, 0..=2i32, any::<bool>());
    (
        grid_point(3),
        prop::collection::vec(spoke, 1..20),
        grid_segments(6, 6),
    )
        .prop_map(|(c, spokes, extra)| {
            let mut v: Vec<Segment2> = spokes
                .into_iter()
                .map(|(dx, dy, k1, k2, rev)| {
                    let (dx, dy) = (dx as f64 * 0.5, dy as f64 * 0.5);
                    let a = p(c.x - k1 as f64 * dx, c.y - k1 as f64 * dy);
                    let b = p(c.x + k2 as f64 * dx, c.y + k2 as f64 * dy);
                    if rev {
                        Segment2::new(b, a)
                    } else {
                        Segment2::new(a, b)
                    }
                })
                .collect();
            v.extend(extra);
            v
        })
}

/// Long random segments across the unit square: quadratically many proper crossings.
fn long_segments() -> impl Strategy<Value = Vec<Segment2>> {
    prop::collection::vec(
        (0.0..1.0f64, 0.0..1.0f64, 0.0..1.0f64, 0.0..1.0f64, 0..4u8),
        2..30,
    )
    .prop_map(|v| {
        v.into_iter()
            .map(|(a, b, c, d, side)| match side {
                0 => s(0.0, a, 1.0, b),
                1 => s(a, 0.0, b, 1.0),
                2 => s(a, b, c, d),
                _ => s(0.0, a, c, 1.0),
            })
            .collect()
    })
}

/// Random segments, then some duplicated (possibly reversed) and some collapsed.
fn with_duplicates() -> impl Strategy<Value = Vec<Segment2>> {
    (
        grid_segments(8, 12),
        prop::collection::vec((0..12usize, 0..3u8), 0..8),
    )
        .prop_map(|(mut v, picks)| {
            if v.is_empty() {
                return v;
            }
            for (k, how) in picks {
                let t = v[k % v.len()];
                v.push(match how {
                    0 => t,
                    1 => Segment2::new(t.b, t.a),
                    _ => Segment2::new(t.a, t.a),
                });
            }
            v
        })
}

/// Crossings that coincide at non-grid points: lines through a common rational point.
fn concurrent_crossings() -> impl Strategy<Value = Vec<Segment2>> {
    // All segments pass through (1/3, 1/3) scaled: lines through (1, 1) on a 3x grid,
    // then every coordinate divided by 3 (rounded: the lines then nearly meet).
    (grid_segments(9, 10), any::<bool>()).prop_map(|(v, scale)| {
        v.into_iter()
            .map(|t| {
                if scale {
                    s(t.a.x / 3.0, t.a.y / 3.0, t.b.x / 3.0, t.b.y / 3.0)
                } else {
                    t
                }
            })
            .collect()
    })
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(1000))]

    #[test]
    fn grid_input_matches_the_oracle(segs in grid_segments(4, 22)) {
        checked(&segs);
    }

    /// The same degenerate grids, scaled and shifted so that coordinates are not small
    /// integers: the kernel's exact comparisons decide instead of the integer fast path.
    #[test]
    fn scaled_and_shifted_grids_match_the_oracle(segs in grid_segments(4, 18), how in 0..3u8) {
        let f = |v: f64| match how {
            0 => v * 0.25,
            1 => v + 4_194_304.0,
            _ => v * 1e-3,
        };
        let segs: Vec<Segment2> = segs.iter().map(|t| s(f(t.a.x), f(t.a.y), f(t.b.x), f(t.b.y))).collect();
        checked(&segs);
    }

    #[test]
    fn axis_parallel_input_matches_the_oracle(segs in axis_segments()) {
        checked(&segs);
    }

    #[test]
    fn stars_match_the_oracle(segs in star_segments()) {
        checked(&segs);
    }

    #[test]
    fn duplicates_match_the_oracle(segs in with_duplicates()) {
        checked(&segs);
    }

    #[test]
    fn concurrent_crossings_match_the_oracle(segs in concurrent_crossings()) {
        checked(&segs);
    }
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(300))]

    #[test]
    fn long_segments_match_the_oracle(segs in long_segments()) {
        checked(&segs);
    }

    #[test]
    fn any_intersection_is_the_first_point(segs in grid_segments(6, 12)) {
        let all = sweep_intersections(&segs).unwrap();
        let first = any_intersection(&segs).unwrap();
        prop_assert_eq!(first, all.points.first().cloned());
    }
}

// ------------------------------------------------------------------ is_simple

/// The brute-force rule of `is_simple`: after dropping repeated consecutive vertices,
/// every ring has >= 3 vertices and two edges meet only if consecutive in one ring, in
/// exactly their common vertex.
fn simple_by_brute_force(poly: &Polygon) -> bool {
    let mut edges = Vec::new();
    for (r, ring) in poly.rings().enumerate() {
        let mut v: Vec<Point2> = Vec::new();
        for &q in ring {
            if v.last() != Some(&q) {
                v.push(q);
            }
        }
        while v.len() > 1 && v.first() == v.last() {
            v.pop();
        }
        if v.len() < 3 {
            return false;
        }
        for k in 0..v.len() {
            edges.push((r, k, v.len(), v[k], v[(k + 1) % v.len()]));
        }
    }
    for i in 0..edges.len() {
        for j in i + 1..edges.len() {
            let (ri, ki, n, a, b) = edges[i];
            let (rj, kj, _, c, d) = edges[j];
            let hit = segment_intersection(Segment2::new(a, b), Segment2::new(c, d));
            let shared = if ri != rj {
                None
            } else if (ki + 1) % n == kj {
                Some(b)
            } else if (kj + 1) % n == ki {
                Some(d)
            } else {
                None
            };
            match (hit, shared) {
                (SegmentIntersection::None, _) => {}
                (SegmentIntersection::Endpoint(q), Some(v)) if q == v => {}
                _ => return false,
            }
        }
    }
    true
}

fn small_polygon() -> impl Strategy<Value = Polygon> {
    (
        prop::collection::vec(grid_point(4), 3..8),
        prop::option::of(prop::collection::vec(grid_point(4), 3..5)),
    )
        .prop_map(|(ext, hole)| Polygon::new(ext, hole.into_iter().collect()))
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(400))]

    #[test]
    fn is_simple_matches_brute_force(poly in small_polygon()) {
        prop_assert_eq!(is_simple(&poly).unwrap(), simple_by_brute_force(&poly));
    }
}

#[test]
fn is_simple_cases() {
    let ring = |v: &[(f64, f64)]| v.iter().map(|&(x, y)| p(x, y)).collect::<Vec<_>>();
    let square = ring(&[(0.0, 0.0), (4.0, 0.0), (4.0, 4.0), (0.0, 4.0)]);
    let hole = ring(&[(1.0, 1.0), (1.0, 2.0), (2.0, 2.0)]);
    assert!(is_simple(&Polygon::new(square.clone(), vec![hole])).unwrap());
    // Closed ring (first vertex repeated) and repeated vertices are fine.
    let mut closed = square.clone();
    closed.push(square[0]);
    closed.insert(1, square[0]);
    assert!(is_simple(&Polygon::new(closed, vec![])).unwrap());
    // A hole touching the shell at a vertex is not simple.
    let touching = ring(&[(0.0, 0.0), (1.0, 2.0), (2.0, 1.0)]);
    assert!(!is_simple(&Polygon::new(square.clone(), vec![touching])).unwrap());
    // Self-tangent ring: vertex (2, 0) touches the edge (0,0)-(4,0)? It is on it.
    let tangent = ring(&[(0.0, 0.0), (4.0, 0.0), (2.0, 2.0), (2.0, 0.0), (1.0, 3.0)]);
    assert!(!is_simple(&Polygon::new(tangent, vec![])).unwrap());
    assert!(!is_simple(&Polygon::new(ring(&[(0.0, 0.0), (1.0, 1.0)]), vec![])).unwrap());
}

// ------------------------------------------------------------------ red / blue

/// Keep only segments that meet the kept ones at common endpoints (a noded set).
fn noded(v: Vec<Segment2>) -> Vec<Segment2> {
    let mut kept: Vec<Segment2> = Vec::new();
    for t in v {
        if t.a == t.b {
            continue;
        }
        let ok = kept.iter().all(|&k| match segment_intersection(k, t) {
            SegmentIntersection::None => true,
            SegmentIntersection::Endpoint(q) => (q == k.a || q == k.b) && (q == t.a || q == t.b),
            _ => false,
        });
        if ok {
            kept.push(t);
        }
    }
    kept
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(1000))]

    #[test]
    fn red_blue_matches_the_filtered_oracle(red in grid_segments(5, 14), blue in grid_segments(5, 14)) {
        let (red, blue) = (noded(red), noded(blue));
        let found = red_blue_intersections(&red, &blue).unwrap();
        let all: Vec<Segment2> = red.iter().chain(&blue).copied().collect();
        let oracle = brute_force_intersections(&all).unwrap();
        let r = red.len();
        let expected: Vec<(Point2, Vec<usize>, Vec<usize>)> = oracle
            .points
            .iter()
            .filter(|q| q.segments().iter().any(|&i| i < r) && q.segments().iter().any(|&i| i >= r))
            .map(|q| {
                let reds = q.segments().iter().copied().filter(|&i| i < r).collect();
                let blues = q.segments().iter().filter(|&&i| i >= r).map(|i| i - r).collect();
                (q.point, reds, blues)
            })
            .collect();
        let got: Vec<(Point2, Vec<usize>, Vec<usize>)> =
            found.points.iter().map(|q| (q.point, q.red.clone(), q.blue.clone())).collect();
        prop_assert_eq!(got, expected);
        let expected_overlaps: Vec<_> = oracle
            .overlaps
            .iter()
            .map(|o| (o.from, o.to, o.segments.iter().copied().filter(|&i| i < r).collect::<Vec<_>>()))
            .collect();
        let got_overlaps: Vec<_> = found.overlaps.iter().map(|o| (o.from, o.to, o.red.clone())).collect();
        prop_assert_eq!(got_overlaps, expected_overlaps);
    }
}

#[test]
fn red_blue_rejects_crossings_within_a_set() {
    let red = [s(0.0, 0.0, 2.0, 2.0), s(0.0, 2.0, 2.0, 0.0)];
    let err = red_blue_intersections(&red, &[]).unwrap_err();
    assert!(err.to_string().contains("red segments 0 and 1"), "{err}");
    let blue = [s(0.0, 0.0, 2.0, 0.0), s(1.0, 0.0, 3.0, 0.0)];
    let err = red_blue_intersections(&[], &blue).unwrap_err();
    assert!(err.to_string().contains("blue segments 0 and 1"), "{err}");
    // Meeting at common endpoints is fine.
    let ok = [s(0.0, 0.0, 2.0, 2.0), s(2.0, 2.0, 4.0, 0.0)];
    assert!(red_blue_intersections(&ok, &[]).unwrap().points.is_empty());
}

#[test]
fn the_default_switches_to_the_sweep_for_long_non_meeting_segments() {
    // 2500 long parallel segments with nearly the same bounding box: 3.1 million
    // candidate pairs share a grid cell and none of them meet, more than the default's
    // pairwise limit (1000 per segment or meeting pair), so the sweep runs; a few
    // vertical segments cross some of them.
    let mut segs: Vec<Segment2> = (0..2500)
        .map(|i| s(0.0, i as f64 * 0.01, 1000.0, 1000.0 + i as f64 * 0.01))
        .collect();
    for k in 0..5 {
        let x = 100.0 * k as f64 + 50.0;
        segs.push(s(x, x + 10.0, x, x + 10.2));
    }
    let by_default = find_intersections(&segs).unwrap();
    let by_pairs = pairwise_intersections(&segs).unwrap();
    assert!(by_default.points.len() > 5 * 10);
    assert_eq!(by_default, by_pairs);
}

#[test]
fn large_inputs_run_in_parallel_with_the_same_answer() {
    // 20 000 short segments on a 150×150 grid (the pairwise method's parallel scan) and
    // the sweep agree exactly.
    let mut next = common::below(99u64);
    let segs: Vec<Segment2> = (0..20_000)
        .map(|_| {
            let (x, y) = (next(151) as f64, next(151) as f64);
            s(x, y, x + next(7) as f64 - 3.0, y + next(7) as f64 - 3.0)
        })
        .collect();
    let by_pairs = pairwise_intersections(&segs).unwrap();
    let by_sweep = sweep_intersections(&segs).unwrap();
    assert!(by_pairs.points.len() > 10_000 && !by_pairs.overlaps.is_empty());
    assert_eq!(by_pairs, by_sweep);
    let count = count_intersections(&segs).unwrap();
    assert_eq!(
        (count.points, count.overlaps, count.pairs),
        (
            by_sweep.points.len(),
            by_sweep.overlaps.len(),
            by_sweep.pair_count()
        )
    );
}

#[test]
fn many_crossings_are_rounded_in_parallel_with_the_same_answer() {
    // 1000 segments across a square: about 250 000 crossings, enough for the pairwise
    // method to build its points on the rayon pool; the sweep must agree exactly.
    let mut unit = common::units(5u64);
    let segs: Vec<Segment2> = (0..1000).map(|_| s(0.0, unit(), 1.0, unit())).collect();
    let by_pairs = pairwise_intersections(&segs).unwrap();
    assert!(by_pairs.points.len() > 200_000);
    rounded_by_the_kernel(&segs, &by_pairs);
    assert_eq!(by_pairs, sweep_intersections(&segs).unwrap());
    let count = count_intersections(&segs).unwrap();
    assert_eq!(
        (count.points, count.overlaps, count.pairs),
        (by_pairs.points.len(), 0, by_pairs.pair_count())
    );
}

#[test]
fn counting_merges_crossings_that_coincide_exactly() {
    // Ten segments through (1/3, 1/3), not an f64 point: (a, b) to (1 - 2a, 1 - 2b)
    // passes through it at a third of its length. Their crossings have overlapping
    // boxes and must merge into one point; sixty random long segments cross them
    // elsewhere. The count and the full answer agree with the oracle.
    let mut unit = common::units(21u64);
    let ends = [
        (0, 0),
        (1, 0),
        (0, 1),
        (2, 1),
        (1, 2),
        (2, -2),
        (5, 1),
        (4, 3),
        (2, 0),
        (0, 2),
    ];
    let mut segs: Vec<Segment2> = ends
        .iter()
        .map(|&(a, b)| s(a as f64, b as f64, (1 - 2 * a) as f64, (1 - 2 * b) as f64))
        .collect();
    for _ in 0..60 {
        segs.push(s(-10.0, 20.0 * unit() - 10.0, 10.0, 20.0 * unit() - 10.0));
    }
    let found = checked(&segs);
    let third = 1.0 / 3.0;
    let star = found
        .points
        .iter()
        .find(|q| q.point == p(third, third))
        .expect("the common point");
    assert_eq!(star.segments(), (0..10).collect::<Vec<_>>());
    assert_eq!(star.interior(), (0..10).collect::<Vec<_>>());
}
