//! Smallest enclosing disc against an exact brute force (every diametral disc of a pair and
//! every circumcircle of a triple, in exact rationals), on random, duplicate, collinear and
//! cocircular sets.

mod lp_oracle;

use compgeom::lp::{smallest_enclosing_disc, verify_enclosing_disc};
use compgeom::Point2;
use lp_oracle::*;
use num_traits::Zero;
use proptest::prelude::*;

/// Exact centre and squared radius of the disc with `support` on its boundary.
fn disc_of(support: &[Point2]) -> Option<((Q, Q), Q)> {
    let two = r(2.0);
    let c = match support {
        [a] => (r(a.x), r(a.y)),
        [a, b] => ((r(a.x) + r(b.x)) / &two, (r(a.y) + r(b.y)) / &two),
        [a, b, c] => {
            let (ax, ay, bx, by, cx, cy) = (r(a.x), r(a.y), r(b.x), r(b.y), r(c.x), r(c.y));
            let d = &two * (&ax * (&by - &cy) + &bx * (&cy - &ay) + &cx * (&ay - &by));
            if d.is_zero() {
                return None;
            }
            let na = &ax * &ax + &ay * &ay;
            let nb = &bx * &bx + &by * &by;
            let nc = &cx * &cx + &cy * &cy;
            (
                (&na * (&by - &cy) + &nb * (&cy - &ay) + &nc * (&ay - &by)) / &d,
                (&na * (&cx - &bx) + &nb * (&ax - &cx) + &nc * (&bx - &ax)) / &d,
            )
        }
        _ => return None,
    };
    let a = support[0];
    let r2 = (r(a.x) - &c.0) * (r(a.x) - &c.0) + (r(a.y) - &c.1) * (r(a.y) - &c.1);
    Some((c, r2))
}

fn encloses(c: &(Q, Q), r2: &Q, pts: &[Point2]) -> bool {
    pts.iter().all(|p| {
        let (dx, dy) = (r(p.x) - &c.0, r(p.y) - &c.1);
        &(&dx * &dx + &dy * &dy) <= r2
    })
}

/// The smallest enclosing squared radius, by brute force.
fn brute(pts: &[Point2]) -> Q {
    let mut best: Option<Q> = None;
    let mut consider = |s: &[Point2]| {
        if let Some((c, r2)) = disc_of(s) {
            if encloses(&c, &r2, pts) && best.as_ref().map_or(true, |b| r2 < *b) {
                best = Some(r2);
            }
        }
    };
    for i in 0..pts.len() {
        consider(&[pts[i]]);
        for j in i + 1..pts.len() {
            consider(&[pts[i], pts[j]]);
            for k in j + 1..pts.len() {
                consider(&[pts[i], pts[j], pts[k]]);
            }
        }
    }
    best.expect("some disc encloses")
}

fn check(pts: &[Point2], seed: u64) -> Result<(), TestCaseError> {
    let d = smallest_enclosing_disc(pts, seed).expect("valid");
    verify_enclosing_disc(pts, &d).map_err(|e| TestCaseError::fail(e.to_string()))?;
    let (c, r2) = disc_of(&d.support).expect("support defines a disc");
    prop_assert!(encloses(&c, &r2, pts));
    prop_assert_eq!(&r2, &brute(pts));
    prop_assert_eq!(d.center, Point2::new(f(&c.0), f(&c.1)));
    let rr = f(&r2).sqrt();
    prop_assert!((d.radius - rr).abs() <= 4.0 * f64::EPSILON * rr.max(f64::MIN_POSITIVE));
    Ok(())
}

fn grid_point() -> impl Strategy<Value = Point2> {
    (-4i8..=4, -4i8..=4).prop_map(|(x, y)| Point2::new(x as f64, y as f64))
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(150))]

    #[test]
    fn small_grid_sets_with_duplicates(pts in prop::collection::vec(grid_point(), 1..12), seed in any::<u64>()) {
        check(&pts, seed)?;
    }

    #[test]
    fn collinear_sets(t in prop::collection::vec(-6i8..=6, 1..10), dir in (-3i8..=3, -3i8..=3), seed in any::<u64>()) {
        let pts: Vec<Point2> = t.iter().map(|&k| Point2::new(1.0 + (k * dir.0) as f64, -2.0 + (k * dir.1) as f64)).collect();
        check(&pts, seed)?;
    }

    #[test]
    fn cocircular_sets(picks in prop::collection::vec(0usize..12, 2..10), seed in any::<u64>()) {
        // Integer points on the circle of radius 5 (3-4-5 triangles), and the centre.
        let ring = [(5, 0), (4, 3), (3, 4), (0, 5), (-3, 4), (-4, 3), (-5, 0), (-4, -3), (-3, -4), (0, -5), (3, -4), (4, -3)];
        let mut pts: Vec<Point2> = picks.iter().map(|&k| Point2::new(ring[k].0 as f64, ring[k].1 as f64)).collect();
        pts.push(Point2::new(0.0, 0.0));
        check(&pts, seed)?;
    }

    #[test]
    fn fractional_points(pts in prop::collection::vec((-1.0f64..1.0, -1.0f64..1.0).prop_map(Point2::from), 1..12), seed in any::<u64>()) {
        check(&pts, seed)?;
    }
}

#[test]
fn single_and_repeated_points() {
    let p = Point2::new(1.5, -2.0);
    let d = smallest_enclosing_disc(&[p, p, p], 0).unwrap();
    assert_eq!(d.support, vec![p]);
    assert_eq!(d.radius, 0.0);
    assert_eq!(d.center, p);
}

#[test]
fn errors() {
    assert!(smallest_enclosing_disc(&[], 0).is_err());
    let e = smallest_enclosing_disc(&[Point2::new(0.0, 0.0), Point2::new(f64::NAN, 0.0)], 0)
        .unwrap_err();
    assert!(e.to_string().contains("point 1"), "{e}");
}

#[test]
fn many_points_match_across_seeds() {
    let pts: Vec<Point2> = (0..2000)
        .map(|k| {
            let t = k as f64 * 0.7;
            Point2::new(t.sin() * (k % 17) as f64, t.cos() * (k % 13) as f64)
        })
        .collect();
    let first = smallest_enclosing_disc(&pts, 0).unwrap();
    verify_enclosing_disc(&pts, &first).unwrap();
    for seed in 1..5 {
        let d = smallest_enclosing_disc(&pts, seed).unwrap();
        assert_eq!((d.center, d.radius), (first.center, first.radius));
    }
}
