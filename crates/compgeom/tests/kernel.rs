//! Kernel tests: every predicate and every crossing comparison against an exact
//! rational oracle (num-rational's BigRational; every f64 converts exactly), on random,
//! grid (degenerate), nearly degenerate, huge, tiny and mixed-magnitude input.

use compgeom::kernel::{
    compare_slopes, compare_xy, compare_y_at_x, crossing_fallbacks, incircle, insphere, on_segment,
    orient2d, orient3d, orient_exact, predicate_fallbacks, segment_intersection, CircleSide,
    Crossing, ExactPoint, Orientation, PlaneSide, SegmentIntersection, SphereSide,
};
use compgeom::{Point2, Point3, Segment2};
use num_bigint::BigInt;
use num_rational::BigRational;
use num_traits::{One, Signed, Zero};
use proptest::prelude::*;
use std::cmp::Ordering;

// ---------------------------------------------------------------- exact oracle

type Q = BigRational;

fn q(x: f64) -> Q {
    Q::from_float(x).expect("finite")
}

fn sign(x: &Q) -> Ordering {
    x.cmp(&Q::zero())
}

fn det2(a: &Q, b: &Q, c: &Q, d: &Q) -> Q {
    a * d - b * c
}

fn orient2d_oracle(a: Point2, b: Point2, c: Point2) -> Ordering {
    let (acx, acy) = (q(a.x) - q(c.x), q(a.y) - q(c.y));
    let (bcx, bcy) = (q(b.x) - q(c.x), q(b.y) - q(c.y));
    sign(&det2(&acx, &acy, &bcx, &bcy))
}

fn incircle_oracle(a: Point2, b: Point2, c: Point2, d: Point2) -> Ordering {
    let rows: Vec<[Q; 3]> = [a, b, c]
        .iter()
        .map(|p| {
            let (x, y) = (q(p.x) - q(d.x), q(p.y) - q(d.y));
            let l = &x * &x + &y * &y;
            [x, y, l]
        })
        .collect();
    sign(&det3(&rows))
}

fn det3(r: &[[Q; 3]]) -> Q {
    &r[0][0] * det2(&r[1][1], &r[1][2], &r[2][1], &r[2][2])
        - &r[0][1] * det2(&r[1][0], &r[1][2], &r[2][0], &r[2][2])
        + &r[0][2] * det2(&r[1][0], &r[1][1], &r[2][0], &r[2][1])
}

fn orient3d_oracle(a: Point3, b: Point3, c: Point3, d: Point3) -> Ordering {
    let rows: Vec<[Q; 3]> = [a, b, c]
        .iter()
        .map(|p| [q(p.x) - q(d.x), q(p.y) - q(d.y), q(p.z) - q(d.z)])
        .collect();
    sign(&det3(&rows))
}

fn insphere_oracle(a: Point3, b: Point3, c: Point3, d: Point3, e: Point3) -> Ordering {
    let rows: Vec<[Q; 4]> = [a, b, c, d]
        .iter()
        .map(|p| {
            let (x, y, z) = (q(p.x) - q(e.x), q(p.y) - q(e.y), q(p.z) - q(e.z));
            let l = &x * &x + &y * &y + &z * &z;
            [x, y, z, l]
        })
        .collect();
    // Laplace expansion along the last column.
    let mut det = Q::zero();
    for (i, row) in rows.iter().enumerate() {
        let minor: Vec<[Q; 3]> = rows
            .iter()
            .enumerate()
            .filter(|(j, _)| *j != i)
            .map(|(_, r)| [r[0].clone(), r[1].clone(), r[2].clone()])
            .collect();
        let term = &row[3] * det3(&minor);
        // Cofactor sign for (i, 3): (-1)^(i+3).
        if (i + 3) % 2 == 0 {
            det += term;
        } else {
            det -= term;
        }
    }
    // Shewchuk's insphere is this determinant: positive for "inside" with a
    // positively oriented tetrahedron.
    sign(&det)
}

/// Exact crossing point of the lines through s and t, or None when parallel/degenerate.
fn crossing_oracle(s: Segment2, t: Segment2) -> Option<(Q, Q)> {
    let (dx, dy) = (q(s.b.x) - q(s.a.x), q(s.b.y) - q(s.a.y));
    let (ex, ey) = (q(t.b.x) - q(t.a.x), q(t.b.y) - q(t.a.y));
    let den = det2(&dx, &dy, &ex, &ey);
    if den.is_zero() || s.a == s.b || t.a == t.b {
        return None;
    }
    let (wx, wy) = (q(t.a.x) - q(s.a.x), q(t.a.y) - q(s.a.y));
    let lambda = det2(&wx, &wy, &ex, &ey) / den;
    Some((q(s.a.x) + &dx * &lambda, q(s.a.y) + &dy * &lambda))
}

fn exact_of(p: &ExactPoint) -> (Q, Q) {
    match p {
        ExactPoint::Input(p) => (q(p.x), q(p.y)),
        ExactPoint::Crossing(c) => crossing_oracle(c.s, c.t).expect("valid crossing"),
    }
}

fn orient_q(a: &(Q, Q), b: &(Q, Q), c: &(Q, Q)) -> Ordering {
    let (bx, by) = (&b.0 - &a.0, &b.1 - &a.1);
    let (cx, cy) = (&c.0 - &a.0, &c.1 - &a.1);
    sign(&det2(&bx, &by, &cx, &cy))
}

fn to_orientation(o: Ordering) -> Orientation {
    match o {
        Ordering::Greater => Orientation::CounterClockwise,
        Ordering::Less => Orientation::Clockwise,
        Ordering::Equal => Orientation::Collinear,
    }
}

/// Asserts that `a` is the f64 nearest to `x` (ties to even; ±inf beyond the range).
fn assert_nearest(a: f64, x: &Q) {
    if a.is_infinite() {
        let limit = q(f64::MAX) + q(2f64.powi(970)) / Q::from_integer(BigInt::from(2));
        assert!(x.abs() >= limit, "{a} for {x}");
        assert_eq!(a > 0.0, x.is_positive());
        return;
    }
    let err = (q(a) - x).abs();
    for nb in [next_up(a), next_down(a)] {
        if nb.is_infinite() {
            continue;
        }
        let e2 = (q(nb) - x).abs();
        assert!(err <= e2, "{a} is not nearest to {x}: {nb} is closer");
        if err == e2 {
            assert_eq!(a.to_bits() & 1, 0, "tie not to even: {a} vs {nb} for {x}");
        }
    }
}

fn next_up(x: f64) -> f64 {
    if x == 0.0 {
        return f64::from_bits(1);
    }
    let b = x.to_bits();
    f64::from_bits(if x > 0.0 { b + 1 } else { b - 1 })
}

fn next_down(x: f64) -> f64 {
    -next_up(-x)
}

fn ulp_shift(mut x: f64, k: i64) -> f64 {
    for _ in 0..k.abs() {
        x = if k > 0 { next_up(x) } else { next_down(x) };
    }
    x
}

fn pow2(k: i32) -> f64 {
    f64::from_bits(((k + 1023) as u64) << 52)
}

// ---------------------------------------------------------------- generators

/// One coordinate family: 0 random, 1 small grid, 2 huge, 3 tiny (with subnormals),
/// 4 mixed.
fn scalar(kind: u8) -> BoxedStrategy<f64> {
    let random = (-1e6..1e6f64).boxed();
    let grid = (-4i32..=4).prop_map(f64::from).boxed();
    let huge = (1.0..10.0f64, 200i32..300, any::<bool>())
        .prop_map(|(m, e, neg)| if neg { -m } else { m } * 10f64.powi(e))
        .boxed();
    let tiny = (1.0..10.0f64, 290i32..323, any::<bool>())
        .prop_map(|(m, e, neg)| if neg { -m } else { m } * 1e-10 * 10f64.powi(-(e - 10)))
        .boxed();
    match kind {
        0 => random,
        1 => grid,
        2 => huge,
        3 => tiny,
        _ => prop_oneof![random, grid.clone(), grid, huge, tiny].boxed(),
    }
}

/// `n` points of one family; grid points are scaled by a common power of two (exact, so
/// degeneracies survive at extreme magnitudes) and coordinates are sometimes nudged by
/// a few ulps (nearly degenerate).
fn points(n: usize) -> impl Strategy<Value = Vec<Point2>> {
    (
        0u8..6,
        prop::sample::select(vec![0, 0, -1000, -600, -300, 300, 600, 900]),
    )
        .prop_flat_map(move |(kind, e)| {
            let kind = kind.min(4);
            let s = if kind == 1 { pow2(e) } else { 1.0 };
            let nudge = prop_oneof![3 => Just(0i64), 1 => -2i64..=2];
            let pt = (scalar(kind), scalar(kind), nudge.clone(), nudge).prop_map(
                move |(x, y, kx, ky)| Point2::new(ulp_shift(x * s, kx), ulp_shift(y * s, ky)),
            );
            prop::collection::vec(pt, n)
        })
}

fn points3(n: usize) -> impl Strategy<Value = Vec<Point3>> {
    (0u8..6, prop::sample::select(vec![0, -900, -300, 150, 600])).prop_flat_map(move |(kind, e)| {
        let kind = kind.min(4);
        let s = if kind == 1 { pow2(e) } else { 1.0 };
        let nudge = prop_oneof![3 => Just(0i64), 1 => -2i64..=2];
        let pt = (scalar(kind), scalar(kind), scalar(kind), nudge)
            .prop_map(move |(x, y, z, k)| Point3::new(x * s, y * s, ulp_shift(z * s, k)));
        prop::collection::vec(pt, n)
    })
}

fn segs(v: &[Point2]) -> Vec<Segment2> {
    v.chunks(2).map(|c| Segment2::new(c[0], c[1])).collect()
}

// ---------------------------------------------------------------- predicates

proptest! {
    #![proptest_config(ProptestConfig::with_cases(600))]

    #[test]
    fn orient2d_is_exact(p in points(3)) {
        prop_assert_eq!(orient2d(p[0], p[1], p[2]), to_orientation(orient2d_oracle(p[0], p[1], p[2])));
    }

    #[test]
    fn incircle_is_exact(p in points(4)) {
        let want = match incircle_oracle(p[0], p[1], p[2], p[3]) {
            Ordering::Greater => CircleSide::Inside,
            Ordering::Less => CircleSide::Outside,
            Ordering::Equal => CircleSide::OnCircle,
        };
        prop_assert_eq!(incircle(p[0], p[1], p[2], p[3]), want);
    }

    #[test]
    fn orient3d_is_exact(p in points3(4)) {
        let want = match orient3d_oracle(p[0], p[1], p[2], p[3]) {
            Ordering::Greater => PlaneSide::Below,
            Ordering::Less => PlaneSide::Above,
            Ordering::Equal => PlaneSide::Coplanar,
        };
        prop_assert_eq!(orient3d(p[0], p[1], p[2], p[3]), want);
    }

    #[test]
    fn insphere_is_exact(p in points3(5)) {
        let want = match insphere_oracle(p[0], p[1], p[2], p[3], p[4]) {
            Ordering::Greater => SphereSide::Inside,
            Ordering::Less => SphereSide::Outside,
            Ordering::Equal => SphereSide::OnSphere,
        };
        prop_assert_eq!(insphere(p[0], p[1], p[2], p[3], p[4]), want);
    }
}

// ---------------------------------------------------------------- crossings

proptest! {
    #![proptest_config(ProptestConfig::with_cases(400))]

    #[test]
    fn crossing_new_and_approx_are_exact(p in points(4)) {
        let s = segs(&p);
        let c = Crossing::new(s[0], s[1]);
        let want = crossing_oracle(s[0], s[1]);
        prop_assert_eq!(c.is_some(), want.is_some());
        if let (Some(c), Some((x, y))) = (c, want) {
            let a = c.approx();
            assert_nearest(a.x, &x);
            assert_nearest(a.y, &y);
            prop_assert_eq!(c.exact(), Some((x, y)));
        }
    }

    #[test]
    fn crossing_comparisons_are_exact(p in points(12)) {
        let s = segs(&p);
        let (Some(c1), Some(c2)) = (Crossing::new(s[0], s[1]), Crossing::new(s[2], s[3])) else {
            return Ok(());
        };
        // Also a crossing sharing a segment with c1 (often the same point on grids).
        let c3 = Crossing::new(s[0], s[4]);
        let (x1, x2) = (exact_of(&c1.into()), exact_of(&c2.into()));
        prop_assert_eq!(c1.compare_xy(&c2), x1.cmp(&x2));
        let r = p[10];
        prop_assert_eq!(c1.compare_xy_point(r), x1.cmp(&(q(r.x), q(r.y))));
        // An input endpoint of another segment, and a point of c1's own segment.
        prop_assert_eq!(c1.compare_xy_point(s[1].a), x1.cmp(&(q(s[1].a.x), q(s[1].a.y))));
        let (a, b) = (p[10], p[11]);
        let want = orient_q(&(q(a.x), q(a.y)), &(q(b.x), q(b.y)), &x1);
        prop_assert_eq!(Crossing::orient(a, b, &c1), to_orientation(want));
        prop_assert_eq!(Crossing::orient(s[0].a, s[0].b, &c1), Orientation::Collinear);
        if let Some(c3) = c3 {
            let x3 = exact_of(&c3.into());
            prop_assert_eq!(c1.compare_xy(&c3), x1.cmp(&x3));
            let pts = [ExactPoint::from(c1), c2.into(), c3.into()];
            prop_assert_eq!(orient_exact(&pts[0], &pts[1], &pts[2]), to_orientation(orient_q(&x1, &x2, &x3)));
            let mixed = [ExactPoint::from(c1), a.into(), c3.into()];
            let xa = (q(a.x), q(a.y));
            prop_assert_eq!(orient_exact(&mixed[0], &mixed[1], &mixed[2]), to_orientation(orient_q(&x1, &xa, &x3)));
        }
    }

    #[test]
    fn segment_queries_are_exact(p in points(8)) {
        let s = segs(&p);
        let Some(c) = Crossing::new(s[0], s[1]) else { return Ok(()); };
        let x = exact_of(&c.into());
        let seg = s[2];
        // compare_y_at_x against the oracle: side of the sorted segment's line.
        let (l, r) = if compare_xy(seg.a, seg.b) == Ordering::Greater { (seg.b, seg.a) } else { (seg.a, seg.b) };
        let (lq, rq) = ((q(l.x), q(l.y)), (q(r.x), q(r.y)));
        let want = if l.x != r.x {
            orient_q(&lq, &rq, &x)
        } else if x.1 < lq.1 {
            Ordering::Less
        } else if x.1 > rq.1 {
            Ordering::Greater
        } else {
            Ordering::Equal
        };
        prop_assert_eq!(compare_y_at_x(&c.into(), seg), want);
        let on = lq <= x && x <= rq && (l == r || orient_q(&lq, &rq, &x) == Ordering::Equal);
        prop_assert_eq!(on_segment(&c.into(), seg), on);
        // Slopes: directions from the smaller endpoint; vertical = +inf.
        let dir = |s: Segment2| {
            let (a, b) = if compare_xy(s.a, s.b) == Ordering::Greater { (s.b, s.a) } else { (s.a, s.b) };
            (q(b.x) - q(a.x), q(b.y) - q(a.y))
        };
        let (ds, dt) = (dir(s[2]), dir(s[3]));
        prop_assert_eq!(compare_slopes(s[2], s[3]), sign(&det2(&dt.0, &dt.1, &ds.0, &ds.1)));
    }

    #[test]
    fn segment_intersection_is_exact(p in points(4), share in 0u8..4) {
        let mut s = segs(&p);
        // Often make the segments share or touch endpoints, or collapse one.
        match share {
            1 => s[1].a = s[0].b,
            2 => s[1].b = s[1].a,
            _ => {}
        }
        check_intersection(s[0], s[1]);
    }
}

enum Expected {
    None,
    Point((Q, Q)),
    Overlap((Q, Q), (Q, Q)),
}

fn on_closed(p: &(Q, Q), s: Segment2) -> bool {
    let (a, b) = ((q(s.a.x), q(s.a.y)), (q(s.b.x), q(s.b.y)));
    let (lo, hi) = if a <= b { (a, b) } else { (b, a) };
    lo <= *p && *p <= hi && orient_q(&lo, &hi, p) == Ordering::Equal
}

fn intersection_oracle(s: Segment2, t: Segment2) -> Expected {
    if let Some(x) = crossing_oracle(s, t) {
        return if on_closed(&x, s) && on_closed(&x, t) {
            Expected::Point(x)
        } else {
            Expected::None
        };
    }
    // Parallel or degenerate: the common set is spanned by endpoints lying on the other.
    let mut cands: Vec<(Q, Q)> = Vec::new();
    for (p, other) in [(s.a, t), (s.b, t), (t.a, s), (t.b, s)] {
        let pq = (q(p.x), q(p.y));
        if on_closed(&pq, other) {
            cands.push(pq);
        }
    }
    cands.sort();
    cands.dedup();
    match cands.len() {
        0 => Expected::None,
        1 => Expected::Point(cands.pop().unwrap()),
        _ => Expected::Overlap(cands[0].clone(), cands[cands.len() - 1].clone()),
    }
}

fn check_intersection(s: Segment2, t: Segment2) {
    let ends = [s.a, s.b, t.a, t.b];
    let qp = |p: Point2| (q(p.x), q(p.y));
    match (segment_intersection(s, t), intersection_oracle(s, t)) {
        (SegmentIntersection::None, Expected::None) => {}
        (SegmentIntersection::Endpoint(p), Expected::Point(x)) => {
            assert!(ends.contains(&p), "endpoint {p:?} is not an input endpoint");
            assert_eq!(qp(p), x);
        }
        (SegmentIntersection::Crossing(c), Expected::Point(x)) => {
            assert!(
                ends.iter().all(|e| qp(*e) != x),
                "crossing at an input endpoint"
            );
            assert_eq!(exact_of(&c.into()), x);
        }
        (SegmentIntersection::Overlap(a, b), Expected::Overlap(x, y)) => {
            assert!(ends.contains(&a) && ends.contains(&b));
            assert_eq!((qp(a), qp(b)), (x, y));
        }
        (got, _) => panic!("wrong intersection {got:?} for {s:?} {t:?}"),
    }
}

// ---------------------------------------------------------------- explicit cases

fn p(x: f64, y: f64) -> Point2 {
    Point2::new(x, y)
}

fn naive_orient(a: Point2, b: Point2, c: Point2) -> f64 {
    (b.x - a.x) * (c.y - a.y) - (b.y - a.y) * (c.x - a.x)
}

#[test]
fn collinear_and_near_collinear_at_1e200() {
    let x = 1e200;
    let (a, b, c) = (p(x, x), p(2.0 * x, 2.0 * x), p(-x, -x));
    assert!(naive_orient(a, b, c).is_nan(), "naive: inf - inf");
    assert_eq!(orient2d(a, b, c), Orientation::Collinear);
    // One ulp above the diagonal: a left turn.
    let c = p(3.0 * x, next_up(3.0 * x));
    assert!(!naive_orient(a, b, c).is_finite());
    assert_eq!(orient2d(a, b, c), Orientation::CounterClockwise);
    assert_eq!(orient2d(a, c, b), Orientation::Clockwise);
}

#[test]
fn collinear_and_near_collinear_at_1e_minus_300() {
    let x = 1e-300;
    let (a, b) = (p(x, x), p(2.0 * x, 2.0 * x));
    let c = p(3.0 * x, next_up(3.0 * x));
    assert_eq!(
        naive_orient(a, b, c),
        0.0,
        "naive products underflow to zero"
    );
    assert_eq!(orient2d(a, b, c), Orientation::CounterClockwise);
    assert_eq!(orient2d(a, b, p(-x, -x)), Orientation::Collinear);
    // Subnormal coordinates.
    let t = 5e-324;
    assert_eq!(
        orient2d(p(0.0, 0.0), p(t, t), p(3.0 * t, 4.0 * t)),
        Orientation::CounterClockwise
    );
}

#[test]
fn mixed_magnitudes_use_the_exact_fallback() {
    let before = predicate_fallbacks();
    // 1e200 and 1e-300 together: no common scaling fits robust's range.
    let (a, b) = (p(1e-300, 1e-300), p(1e200, 1e200));
    let c = p(2e200, next_up(2e200));
    assert_eq!(orient2d(a, b, c), to_orientation(orient2d_oracle(a, b, c)));
    assert_eq!(orient2d(a, b, p(-1e200, -1e200)), Orientation::Collinear);
    assert!(predicate_fallbacks() >= before + 2);
}

#[test]
fn cocircular_at_extreme_scales() {
    for e in [-1000, -600, 0, 600, 900] {
        let s = pow2(e);
        let (a, b, c) = (p(5.0 * s, 0.0), p(3.0 * s, 4.0 * s), p(0.0, 5.0 * s));
        assert_eq!(
            incircle(a, b, c, p(-3.0 * s, -4.0 * s)),
            CircleSide::OnCircle,
            "2^{e}"
        );
        let d = p(-3.0 * s, next_up(-4.0 * s));
        assert_eq!(incircle(a, b, c, d), CircleSide::Inside, "2^{e}");
    }
}

#[test]
fn non_finite_input_does_not_panic() {
    let n = f64::NAN;
    assert_eq!(
        orient2d(p(n, 0.0), p(1.0, 1.0), p(2.0, 0.0)),
        Orientation::Collinear
    );
    assert_eq!(
        incircle(p(f64::INFINITY, 0.0), p(1.0, 1.0), p(2.0, 0.0), p(0.0, 0.0)),
        CircleSide::OnCircle
    );
    let s = Segment2::new(p(n, 0.0), p(1.0, 1.0));
    let t = Segment2::new(p(0.0, 1.0), p(1.0, 0.0));
    assert!(Crossing::new(s, t).is_none());
    let _ = segment_intersection(s, t);
    let c = Crossing { s, t };
    let _ = c.compare_xy_point(p(0.0, 0.0));
    let _ = c.approx();
}

#[test]
fn concurrent_crossings_compare_equal_through_the_fallback() {
    // Three lines through (1/3, 1/3): x + 2y = 1, 2x + y = 1, x = y.
    let s1 = Segment2::new(p(1.0, 0.0), p(-1.0, 1.0));
    let s2 = Segment2::new(p(0.0, 1.0), p(1.0, -1.0));
    let s3 = Segment2::new(p(0.0, 0.0), p(1.0, 1.0));
    let c12 = Crossing::new(s1, s2).unwrap();
    let c13 = Crossing::new(s1, s3).unwrap();
    let c23 = Crossing::new(s2, s3).unwrap();
    let before = crossing_fallbacks();
    assert_eq!(c12.compare_xy(&c13), Ordering::Equal);
    assert_eq!(c13.compare_xy(&c23), Ordering::Equal);
    assert_eq!(
        Crossing::orient(p(0.0, 0.0), p(3.0, 3.0), &c12),
        Orientation::Collinear
    );
    assert!(
        crossing_fallbacks() >= before + 3,
        "degenerate comparisons must reach the exact path"
    );
    assert_eq!(c12.approx(), p(1.0 / 3.0, 1.0 / 3.0));
    // The same crossing with its segments swapped is equal by construction.
    let c21 = Crossing::new(s2, s1).unwrap();
    assert_eq!(c12.compare_xy(&c21), Ordering::Equal);
    let x = ExactPoint::from(c12);
    assert_eq!(
        orient_exact(&x, &c21.into(), &p(5.0, -7.0).into()),
        Orientation::Collinear
    );
    // A point one ulp away is ordered correctly.
    assert_eq!(c12.compare_xy_point(p(1.0 / 3.0, 1.0 / 3.0)), {
        let third = Q::new(BigInt::one(), BigInt::from(3));
        third.cmp(&q(1.0 / 3.0)).then(third.cmp(&q(1.0 / 3.0)))
    });
}

#[test]
fn crossing_of_nearly_parallel_lines_far_out_rounds_to_infinity() {
    let s = Segment2::new(p(0.0, 0.0), p(1e300, 1e300));
    // Offset 1e300, slopes differing by about 3e-16: the crossing is near x = 3e315.
    let t = Segment2::new(p(0.0, 1e300), p(1e300, next_up(2e300)));
    let c = Crossing::new(s, t).unwrap();
    let a = c.approx();
    let (x, y) = c.exact().unwrap();
    assert_nearest(a.x, &x);
    assert_nearest(a.y, &y);
    assert!(a.x.is_infinite());
}

#[test]
fn approx_breaks_exact_ties_to_even() {
    // The crossing of y = 0 with the line through (a, -1) and (b, 1) is x = (a + b) / 2.
    let e = f64::EPSILON; // 2^-52
    let horizontal = Segment2::new(p(-4.0, 0.0), p(4.0, 0.0));
    for (a, b, want) in [
        (1.0, 1.0 + e, 1.0),                     // midpoint of 1 and 1 + e: even is 1
        (1.0 + e, 1.0 + 2.0 * e, 1.0 + 2.0 * e), // midpoint of 1 + e and 1 + 2e: even is 1 + 2e
        (1.0, 1.0 + 2.0 * e, 1.0 + e),           // exactly representable
    ] {
        let c = Crossing::new(horizontal, Segment2::new(p(a, -1.0), p(b, 1.0))).unwrap();
        assert_eq!(c.approx(), p(want, 0.0), "({a} + {b}) / 2");
    }
}
