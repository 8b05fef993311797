//! Convex hull: the three algorithms against each other, against a brute-force oracle in
//! exact rational arithmetic (independent of the kernel), and through the exact verifier,
//! on random and deliberately degenerate input. Plus negative tests of the verifier.

use compgeom::hull::{
    andrew_convex_hull, convex_hull, convex_hull_indices, slow_convex_hull, verify_convex_hull,
    HullAlgorithm, HullOptions,
};
use compgeom::{Error, Point2};
use num_rational::BigRational;
use num_traits::Zero;
use proptest::prelude::*;
use std::collections::HashSet;

// ---------------------------------------------------------------------------------------
// Oracle: exact rational orientation and brute-force hull membership.

fn rat(v: f64) -> BigRational {
    BigRational::from_float(v).expect("finite")
}

/// Sign of the orientation determinant of a, b, c, computed exactly in rationals.
fn orient_exact(a: Point2, b: Point2, c: Point2) -> i8 {
    let (ax, ay) = (rat(a.x), rat(a.y));
    let d = (rat(b.x) - &ax) * (rat(c.y) - &ay) - (rat(b.y) - &ay) * (rat(c.x) - &ax);
    if d.is_zero() {
        0
    } else if d > BigRational::zero() {
        1
    } else {
        -1
    }
}

fn key(p: Point2) -> (u64, u64) {
    ((p.x + 0.0).to_bits(), (p.y + 0.0).to_bits())
}

fn distinct(points: &[Point2]) -> Vec<Point2> {
    let mut seen = HashSet::new();
    points
        .iter()
        .copied()
        .filter(|&p| seen.insert(key(p)))
        .collect()
}

/// `p` on the closed segment `ab` (exact).
fn on_segment(a: Point2, b: Point2, p: Point2) -> bool {
    orient_exact(a, b, p) == 0
        && a.x.min(b.x) <= p.x
        && p.x <= a.x.max(b.x)
        && a.y.min(b.y) <= p.y
        && p.y <= a.y.max(b.y)
}

/// `p` in the closed triangle `abc` (any orientation, maybe degenerate).
fn in_triangle(a: Point2, b: Point2, c: Point2, p: Point2) -> bool {
    let (s1, s2, s3) = (
        orient_exact(a, b, p),
        orient_exact(b, c, p),
        orient_exact(c, a, p),
    );
    let has_neg = s1 < 0 || s2 < 0 || s3 < 0;
    let has_pos = s1 > 0 || s2 > 0 || s3 > 0;
    if orient_exact(a, b, c) == 0 {
        return on_segment(a, b, p) || on_segment(b, c, p) || on_segment(a, c, p);
    }
    !(has_neg && has_pos)
}

/// The corners of the hull (strict vertices): distinct points not in the convex hull of
/// the others (Carathéodory: in the hull of some three of them).
fn oracle_corners(points: &[Point2]) -> HashSet<(u64, u64)> {
    let d = distinct(points);
    let mut out = HashSet::new();
    for (i, &p) in d.iter().enumerate() {
        let others: Vec<Point2> = d
            .iter()
            .enumerate()
            .filter(|&(j, _)| j != i)
            .map(|(_, &q)| q)
            .collect();
        let m = others.len();
        let mut inside = false;
        'search: for a in 0..m {
            for b in a..m {
                for c in b..m {
                    if in_triangle(others[a], others[b], others[c], p) {
                        inside = true;
                        break 'search;
                    }
                }
            }
        }
        if !inside {
            out.insert(key(p));
        }
    }
    out
}

/// The distinct points on the hull boundary: those with a line through them and another
/// point that has every point on one closed side.
fn oracle_boundary(points: &[Point2]) -> HashSet<(u64, u64)> {
    let d = distinct(points);
    if d.len() == 1 {
        return d.iter().map(|&p| key(p)).collect();
    }
    let mut out = HashSet::new();
    for &p in &d {
        let supported = d.iter().filter(|&&q| q != p).any(|&q| {
            let signs: Vec<i8> = d.iter().map(|&r| orient_exact(p, q, r)).collect();
            signs.iter().all(|&s| s >= 0) || signs.iter().all(|&s| s <= 0)
        });
        if supported {
            out.insert(key(p));
        }
    }
    out
}

fn keys(hull: &[Point2]) -> HashSet<(u64, u64)> {
    hull.iter().map(|&p| key(p)).collect()
}

const ALGORITHMS: [HullAlgorithm; 3] = [
    HullAlgorithm::Default,
    HullAlgorithm::Andrew,
    HullAlgorithm::Slow,
];

fn hull_with(points: &[Point2], algorithm: HullAlgorithm, keep: bool) -> Vec<Point2> {
    let opts = HullOptions::new()
        .with_algorithm(algorithm)
        .with_keep_collinear(keep);
    convex_hull(points, &opts).expect("finite input")
}

/// The whole check on one input: every algorithm, both modes, equal outputs, verifier,
/// and (when `oracle`) the exact brute-force vertex and boundary sets.
fn check_all(points: &[Point2], oracle: bool) -> Result<(), TestCaseError> {
    for keep in [false, true] {
        let reference = hull_with(points, HullAlgorithm::Slow, keep);
        if let Err(e) = verify_convex_hull(points, &reference, keep) {
            return Err(TestCaseError::fail(format!(
                "slow hull (keep={keep}) fails verification: {e}"
            )));
        }
        for alg in ALGORITHMS {
            let h = hull_with(points, alg, keep);
            prop_assert_eq!(&h, &reference, "{:?} keep={} differs from slow", alg, keep);
        }
        if oracle {
            let expected = if keep {
                oracle_boundary(points)
            } else {
                oracle_corners(points)
            };
            let d = distinct(points);
            // All collinear: the strict hull is the two ends, which the corner oracle finds.
            prop_assert_eq!(keys(&reference), expected, "keep={} vs oracle", keep);
            prop_assert!(reference.len() <= d.len());
        }
    }
    Ok(())
}

// ---------------------------------------------------------------------------------------
// Generators that make degenerate input on purpose.

fn p(x: f64, y: f64) -> Point2 {
    Point2::new(x, y)
}

/// Points on a small integer grid: many collinear triples and duplicates.
fn grid_points(max_len: usize) -> impl Strategy<Value = Vec<Point2>> {
    prop::collection::vec((-3i32..=3, -3i32..=3), 0..max_len)
        .prop_map(|v| v.into_iter().map(|(x, y)| p(x as f64, y as f64)).collect())
}

/// Points all on one line through a random point, with a random integer direction.
fn line_points(max_len: usize) -> impl Strategy<Value = Vec<Point2>> {
    (
        -50i32..50,
        -50i32..50,
        -3i32..=3,
        -3i32..=3,
        prop::collection::vec(-6i32..=6, 1..max_len),
    )
        .prop_map(|(ox, oy, dx, dy, ts)| {
            ts.into_iter()
                .map(|t| p((ox + t * dx) as f64, (oy + t * dy) as f64))
                .collect()
        })
}

/// Collinear runs on the sides of a triangle, plus a few random interior/exterior points.
fn collinear_runs(max_len: usize) -> impl Strategy<Value = Vec<Point2>> {
    (
        prop::collection::vec((0usize..3, 0i32..=8), 1..max_len),
        prop::collection::vec((-2i32..=10, -2i32..=10), 0..4),
    )
        .prop_map(|(runs, extra)| {
            let corners = [(0, 0), (8, 0), (0, 8)];
            let mut v: Vec<Point2> = runs
                .into_iter()
                .map(|(side, t)| {
                    let (a, b) = (corners[side], corners[(side + 1) % 3]);
                    let x = a.0 + (b.0 - a.0) * t / 8;
                    let y = a.1 + (b.1 - a.1) * t / 8;
                    p(x as f64, y as f64)
                })
                .collect();
            v.extend(extra.into_iter().map(|(x, y)| p(x as f64, y as f64)));
            v
        })
}

/// Points differing from a few base points in the last bits of their coordinates, so that
/// float arithmetic cannot decide their orientations.
fn ulp_points(max_len: usize) -> impl Strategy<Value = Vec<Point2>> {
    let base = prop::sample::select(vec![0.5, 1.0, 0.1, 12.0, 1e-3, 3.3e7]);
    (
        base,
        prop::collection::vec((-4i64..=4, -4i64..=4, 0usize..3), 0..max_len),
    )
        .prop_map(|(b, v)| {
            v.into_iter()
                .map(|(dx, dy, which)| {
                    let (x0, y0) = [(b, b), (2.0 * b, 2.0 * b), (3.0 * b, 3.0 * b)][which];
                    let bump = |v: f64, k: i64| f64::from_bits((v.to_bits() as i64 + k) as u64);
                    p(bump(x0, dx), bump(y0, dy))
                })
                .collect()
        })
}

/// Grid points scaled to huge or tiny magnitudes (products overflow or underflow in f64).
fn scaled_points(max_len: usize) -> impl Strategy<Value = Vec<Point2>> {
    // 3e307: x + y overflows to infinity in the filter's keys.
    let scale = prop::sample::select(vec![1e200, 1e-300, 1e150, 1e-160, 5e-324, 3e307]);
    (grid_points(max_len), scale, -2i32..=2).prop_map(|(v, s, off)| {
        v.into_iter()
            .map(|q| p(q.x * s + off as f64 * s, q.y * s))
            .collect()
    })
}

/// Points on a circle (rounded: nearly, not exactly, cocircular), possibly repeated.
fn circle_points(max_len: usize) -> impl Strategy<Value = Vec<Point2>> {
    (
        prop::collection::vec(0u32..64, 0..max_len),
        prop::sample::select(vec![1.0, 1e6, 1e-6]),
    )
        .prop_map(|(angles, r)| {
            angles
                .into_iter()
                .map(|a| {
                    let t = a as f64 * std::f64::consts::TAU / 64.0;
                    p(r * t.cos(), r * t.sin())
                })
                .collect()
        })
}

/// Random points with duplicates of some of them appended.
fn with_duplicates(max_len: usize) -> impl Strategy<Value = Vec<Point2>> {
    (
        prop::collection::vec((-1e3f64..1e3, -1e3f64..1e3), 1..max_len),
        prop::collection::vec(any::<prop::sample::Index>(), 0..max_len),
    )
        .prop_map(|(v, dup)| {
            let mut pts: Vec<Point2> = v.into_iter().map(|(x, y)| p(x, y)).collect();
            let extra: Vec<Point2> = dup.iter().map(|i| pts[i.index(pts.len())]).collect();
            pts.extend(extra);
            pts
        })
}

fn any_degenerate(max_len: usize) -> impl Strategy<Value = Vec<Point2>> {
    prop_oneof![
        grid_points(max_len),
        line_points(max_len),
        collinear_runs(max_len),
        ulp_points(max_len),
        circle_points(max_len),
        with_duplicates(max_len),
    ]
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(160))]

    /// Small inputs: all algorithms, both modes, against the exact brute-force oracle.
    #[test]
    fn small_inputs_match_exact_oracle(points in any_degenerate(12)) {
        check_all(&points, true)?;
    }
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(96))]

    /// Medium inputs (past the filter threshold of the default): the three algorithms agree
    /// and the verifier accepts.
    #[test]
    fn medium_inputs_agree_and_verify(points in any_degenerate(120)) {
        check_all(&points, false)?;
    }

    /// The indices name input points equal to the hull vertices, first occurrence.
    #[test]
    fn indices_name_the_hull_points(points in any_degenerate(60)) {
        let opts = HullOptions::default();
        let hull = convex_hull(&points, &opts).unwrap();
        let idx = convex_hull_indices(&points, &opts).unwrap();
        prop_assert_eq!(idx.len(), hull.len());
        for (&i, &v) in idx.iter().zip(&hull) {
            prop_assert_eq!(points[i], v);
            prop_assert!(points[..i].iter().all(|&q| q != v));
        }
    }
}

#[test]
fn huge_and_tiny_magnitudes() {
    let mut runner = proptest::test_runner::TestRunner::new(ProptestConfig::with_cases(96));
    runner
        .run(&scaled_points(12), |points| check_all(&points, true))
        .unwrap();
    runner
        .run(&scaled_points(120), |points| check_all(&points, false))
        .unwrap();
}

// ---------------------------------------------------------------------------------------
// The parallel path (large n) against Andrew.

/// A small deterministic generator (xorshift), so large inputs need no extra crate.
struct Rng(u64);
impl Rng {
    fn next(&mut self) -> u64 {
        self.0 ^= self.0 << 13;
        self.0 ^= self.0 >> 7;
        self.0 ^= self.0 << 17;
        self.0
    }
    fn unit(&mut self) -> f64 {
        (self.next() >> 11) as f64 / (1u64 << 53) as f64
    }
}

fn check_large(points: &[Point2]) {
    for keep in [false, true] {
        let a = hull_with(points, HullAlgorithm::Andrew, keep);
        let d = hull_with(points, HullAlgorithm::Default, keep);
        assert_eq!(a, d, "default (parallel) differs from Andrew, keep={keep}");
        verify_convex_hull(points, &d, keep).unwrap();
    }
}

#[test]
fn parallel_path_matches_andrew() {
    let mut rng = Rng(0x9E37_79B9_7F4A_7C15);
    let n = 250_000;
    // Uniform in a square.
    let square: Vec<Point2> = (0..n).map(|_| p(rng.unit(), rng.unit())).collect();
    check_large(&square);
    // A small integer grid: massive duplication and collinearity.
    let grid: Vec<Point2> = (0..n)
        .map(|_| p((rng.next() % 9) as f64, (rng.next() % 9) as f64))
        .collect();
    check_large(&grid);
    // On a circle: almost everything survives the filter.
    let circle: Vec<Point2> = (0..n)
        .map(|_| {
            let t = rng.unit() * std::f64::consts::TAU;
            p(t.cos(), t.sin())
        })
        .collect();
    check_large(&circle);
    // All on one line.
    let line: Vec<Point2> = (0..n)
        .map(|_| {
            let t = (rng.next() % 1000) as f64;
            p(3.0 * t - 7.0, -2.0 * t)
        })
        .collect();
    check_large(&line);
}

// ---------------------------------------------------------------------------------------
// Fixed cases.

#[test]
fn degenerate_conventions() {
    let none: [Point2; 0] = [];
    for alg in ALGORITHMS {
        for keep in [false, true] {
            assert!(hull_with(&none, alg, keep).is_empty());
            let one = [p(1.0, 2.0); 3];
            assert_eq!(hull_with(&one, alg, keep), [p(1.0, 2.0)]);
            let line = [
                p(2.0, 2.0),
                p(0.0, 0.0),
                p(1.0, 1.0),
                p(0.0, 0.0),
                p(3.0, 3.0),
            ];
            let expected: Vec<Point2> = if keep {
                vec![p(0.0, 0.0), p(1.0, 1.0), p(2.0, 2.0), p(3.0, 3.0)]
            } else {
                vec![p(0.0, 0.0), p(3.0, 3.0)]
            };
            assert_eq!(hull_with(&line, alg, keep), expected, "{alg:?} keep={keep}");
            // -0.0 and 0.0 are the same point.
            let zeros = [p(0.0, -0.0), p(-0.0, 0.0), p(1.0, 0.0)];
            assert_eq!(hull_with(&zeros, alg, keep).len(), 2);
        }
    }
}

#[test]
fn square_with_edge_points() {
    let pts: Vec<Point2> = (0..=4)
        .flat_map(|i| (0..=4).map(move |j| p(i as f64, j as f64)))
        .collect();
    let strict = [p(0.0, 0.0), p(0.0, 4.0), p(4.0, 4.0), p(4.0, 0.0)];
    assert_eq!(andrew_convex_hull(&pts).unwrap(), strict);
    assert_eq!(slow_convex_hull(&pts).unwrap(), strict);
    let keep = hull_with(&pts, HullAlgorithm::Default, true);
    assert_eq!(keep.len(), 16);
    assert_eq!(
        &keep[..6],
        &[
            p(0.0, 0.0),
            p(0.0, 1.0),
            p(0.0, 2.0),
            p(0.0, 3.0),
            p(0.0, 4.0),
            p(1.0, 4.0)
        ]
    );
    verify_convex_hull(&pts, &keep, true).unwrap();
}

#[test]
fn non_finite_input_is_an_error() {
    let pts = [p(0.0, 0.0), p(1.0, f64::NAN), p(2.0, 0.0)];
    for alg in ALGORITHMS {
        let e = convex_hull(&pts, &HullOptions::new().with_algorithm(alg)).unwrap_err();
        assert!(
            matches!(&e, Error::NonFinite { what, .. } if what == "point 1"),
            "{e}"
        );
    }
    let inf = [p(f64::INFINITY, 0.0)];
    assert!(andrew_convex_hull(&inf).is_err());
    assert!(verify_convex_hull(&inf, &inf, false).is_err());
}

#[test]
fn near_collinear_in_the_last_bit() {
    // (0.1, 0.1), (0.2, 0.2), (0.3, 0.3) as doubles are not collinear; the middle one is
    // exactly decided.
    let a = p(0.1, 0.1);
    let c = p(0.3, 0.3);
    for k in -3i64..=3 {
        let b = p(0.2, f64::from_bits((0.2f64.to_bits() as i64 + k) as u64));
        let pts = [a, b, c];
        let reference = slow_convex_hull(&pts).unwrap();
        let expected = match orient_exact(a, b, c) {
            0 => vec![a, c],
            1 => vec![a, c, b], // b below: clockwise a, c, b
            _ => vec![a, b, c],
        };
        assert_eq!(reference, expected, "k={k}");
        for alg in ALGORITHMS {
            assert_eq!(hull_with(&pts, alg, false), expected, "{alg:?} k={k}");
        }
    }
}

// ---------------------------------------------------------------------------------------
// The verifier rejects wrong hulls.

fn verification_message(points: &[Point2], hull: &[Point2], keep: bool) -> String {
    match verify_convex_hull(points, hull, keep) {
        Err(Error::Verification(m)) => m,
        other => panic!("expected a verification error, got {other:?}"),
    }
}

#[test]
fn verifier_rejects_wrong_hulls() {
    let pts = [
        p(0.0, 0.0),
        p(4.0, 0.0),
        p(4.0, 4.0),
        p(0.0, 4.0),
        p(2.0, 2.0),
        p(2.0, 4.0),
    ];
    let good = [p(0.0, 0.0), p(0.0, 4.0), p(4.0, 4.0), p(4.0, 0.0)];
    verify_convex_hull(&pts, &good, false).unwrap();

    let ccw = [p(0.0, 0.0), p(4.0, 0.0), p(4.0, 4.0), p(0.0, 4.0)];
    assert!(verification_message(&pts, &ccw, false).contains("counter-clockwise"));

    let missing = [p(0.0, 0.0), p(0.0, 4.0), p(4.0, 4.0)];
    assert!(verification_message(&pts, &missing, false).contains("outside"));

    let foreign = [p(0.0, 0.0), p(0.0, 4.0), p(4.0, 4.0), p(5.0, 0.0)];
    assert!(verification_message(&pts, &foreign, false).contains("not an input point"));

    let collinear = [
        p(0.0, 0.0),
        p(0.0, 4.0),
        p(2.0, 4.0),
        p(4.0, 4.0),
        p(4.0, 0.0),
    ];
    assert!(verification_message(&pts, &collinear, false).contains("collinear"));
    // ...which is exactly right with keep_collinear,
    verify_convex_hull(&pts, &collinear, true).unwrap();
    // ...where leaving the edge point out is wrong.
    assert!(verification_message(&pts, &good, true).contains("missing"));

    let wrong_start = [p(0.0, 4.0), p(4.0, 4.0), p(4.0, 0.0), p(0.0, 0.0)];
    assert!(verification_message(&pts, &wrong_start, false).contains("smallest"));

    let repeated = [
        p(0.0, 0.0),
        p(0.0, 4.0),
        p(4.0, 4.0),
        p(4.0, 0.0),
        p(0.0, 4.0),
    ];
    assert!(verification_message(&pts, &repeated, false).contains("repeats"));

    // Does not contain a point: the hull of a subset that leaves out a corner's neighbourhood.
    let more = [
        p(0.0, 0.0),
        p(4.0, 0.0),
        p(4.0, 4.0),
        p(0.0, 4.0),
        p(5.0, 2.0),
    ];
    assert!(verification_message(&more, &good, false).contains("outside"));

    // A pentagram: every turn is clockwise but it winds around twice.
    let star_pts: Vec<Point2> = (0..5)
        .map(|k| {
            let t = std::f64::consts::TAU * k as f64 / 5.0;
            p(t.cos(), t.sin())
        })
        .collect();
    let hull = andrew_convex_hull(&star_pts).unwrap();
    let star: Vec<Point2> = (0..5).map(|k| hull[(2 * k) % 5]).collect();
    assert!(verification_message(&star_pts, &star, false).contains("more than once"));

    // Degenerate hulls.
    let seg = [p(0.0, 0.0), p(1.0, 1.0), p(2.0, 2.0)];
    verify_convex_hull(&seg, &[p(0.0, 0.0), p(2.0, 2.0)], false).unwrap();
    verify_convex_hull(&seg, &seg, true).unwrap();
    assert!(verify_convex_hull(&seg, &seg, false).is_err());
    assert!(verify_convex_hull(&seg, &[p(0.0, 0.0), p(1.0, 1.0)], false).is_err());
    assert!(verify_convex_hull(&seg, &[p(2.0, 2.0), p(0.0, 0.0)], false).is_err());
    assert!(verify_convex_hull(&seg, &[p(0.0, 0.0)], false).is_err());
    assert!(verify_convex_hull(&seg, &[], false).is_err());
    assert!(verify_convex_hull(&[], &[p(0.0, 0.0)], false).is_err());
    verify_convex_hull(&[], &[], false).unwrap();
    verify_convex_hull(&[p(1.0, 1.0); 2], &[p(1.0, 1.0)], false).unwrap();
}
