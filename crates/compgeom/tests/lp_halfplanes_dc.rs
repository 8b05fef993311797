//! Half-plane intersection by divide and conquer (book §4.2) against the randomized
//! incremental method and an exact brute-force oracle, on random input and on the inputs
//! that stress it: lines tangent to a circle (where incremental clipping is quadratic),
//! parallel families, all lines through one point, integer-grid coefficients.

mod common;
mod lp_oracle;

use compgeom::lp::{
    intersect_halfplanes, intersect_halfplanes_dc, intersect_halfplanes_dc_leaf,
    intersect_halfplanes_incremental, intersect_halfplanes_scan, verify_region, HalfPlane,
    RegionKind,
};
use lp_oracle::*;
use num_traits::Zero;
use proptest::prelude::*;

/// Do `h` and `g` describe the same half-plane (positive multiples of each other)?
fn same_halfplane(h: &HalfPlane, g: &HalfPlane) -> bool {
    let cross = r(h.a) * r(g.b) - r(g.a) * r(h.b);
    let dot = r(h.a) * r(g.a) + r(h.b) * r(g.b);
    // g = λ·h with λ = dot / |h|² > 0.
    let nn = r(h.a) * r(h.a) + r(h.b) * r(h.b);
    cross.is_zero() && dot > Q::zero() && r(g.c) * &nn == dot * r(h.c)
}

/// Divide and conquer agrees with the incremental method (same set, same description up to
/// the choice among identical lines), passes the exact verifier, and, for small inputs,
/// has exactly the corners the brute-force oracle finds.
fn check(hs: &[HalfPlane], seed: u64) -> Result<RegionKind, TestCaseError> {
    let dc = intersect_halfplanes_dc(hs).expect("valid input");
    verify_region(hs, &dc).map_err(|e| TestCaseError::fail(e.to_string()))?;
    let inc = intersect_halfplanes_incremental(hs, seed).expect("valid input");
    prop_assert_eq!(dc.kind, inc.kind);
    prop_assert_eq!(&dc.vertices, &inc.vertices);
    prop_assert_eq!(&dc.outline, &inc.outline);
    if matches!(dc.kind, RegionKind::Polygon | RegionKind::Unbounded) {
        prop_assert_eq!(dc.constraints.len(), inc.constraints.len());
        for (&p, &q) in dc.constraints.iter().zip(&inc.constraints) {
            prop_assert!(same_halfplane(&hs[p], &hs[q]), "constraints {} vs {}", p, q);
        }
    }
    if hs.len() <= 24 {
        let mut want: Vec<(f64, f64)> = vertices(hs).iter().map(|p| (f(&p.0), f(&p.1))).collect();
        let mut have: Vec<(f64, f64)> = dc.vertices.iter().map(|p| (p.x, p.y)).collect();
        want.sort_by(|a, b| a.partial_cmp(b).unwrap());
        have.sort_by(|a, b| a.partial_cmp(b).unwrap());
        prop_assert_eq!(have, want);
    }
    // The book's recursion down to single half-planes gives the same region; of several
    // constraints through an end of a point, segment or ray another may be listed.
    for leaf in [1, 3] {
        let other = intersect_halfplanes_dc_leaf(hs, leaf).expect("valid input");
        prop_assert_eq!(other.kind, dc.kind);
        prop_assert_eq!(&other.vertices, &dc.vertices);
        prop_assert_eq!(&other.outline, &dc.outline);
        if matches!(dc.kind, RegionKind::Polygon | RegionKind::Unbounded) {
            prop_assert_eq!(&other.constraints, &dc.constraints);
        }
        verify_region(hs, &other).map_err(|e| TestCaseError::fail(e.to_string()))?;
    }
    // One exact slope sort and one sweep: the same region.
    let scan = intersect_halfplanes_scan(hs).expect("valid input");
    prop_assert_eq!(scan.kind, dc.kind);
    prop_assert_eq!(&scan.vertices, &dc.vertices);
    prop_assert_eq!(&scan.outline, &dc.outline);
    if matches!(dc.kind, RegionKind::Polygon | RegionKind::Unbounded) {
        prop_assert_eq!(&scan.constraints, &dc.constraints);
    }
    verify_region(hs, &scan).map_err(|e| TestCaseError::fail(e.to_string()))?;
    // The default entry point is the slope sort and sweep.
    prop_assert_eq!(intersect_halfplanes(hs, seed).expect("valid input"), scan);
    Ok(dc.kind)
}

fn tangents(angles: &[u32], m: u32, offsets: &[i8]) -> Vec<HalfPlane> {
    angles
        .iter()
        .zip(offsets.iter().cycle())
        .map(|(&k, &o)| {
            let t = k as f64 * std::f64::consts::TAU / m as f64;
            HalfPlane::new(t.cos(), t.sin(), 1.0 + o as f64 / 4.0)
        })
        .collect()
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(150))]

    #[test]
    fn random_fractional(hs in prop::collection::vec((-1.0f64..1.0, -1.0f64..1.0, -0.3f64..1.0)
        .prop_map(|(a, b, c)| HalfPlane::new(a, b, c)), 0..24), seed in any::<u64>()) {
        check(&hs, seed)?;
    }

    #[test]
    fn integer_grid(hs in prop::collection::vec((-5i8..=5, -5i8..=5, -6i8..=6)
        .prop_map(|(a, b, c)| HalfPlane::new(a as f64, b as f64, c as f64)), 0..20), seed in any::<u64>()) {
        check(&hs, seed)?;
    }

    #[test]
    fn tangent_lines(angles in prop::collection::vec(0u32..64, 1..24), offsets in prop::collection::vec(-1i8..=1, 1..4), seed in any::<u64>()) {
        // Angles on a grid of 64 directions: duplicates and parallel opposite pairs on purpose.
        check(&tangents(&angles, 64, &offsets), seed)?;
    }

    #[test]
    fn parallel_families(cs in prop::collection::vec((0usize..8, -3i8..=3), 1..22), seed in any::<u64>()) {
        let dirs = [(1.0, 0.0), (-1.0, 0.0), (0.0, 1.0), (0.0, -1.0), (1.0, 1.0), (-2.0, -2.0), (1.0, 2.0), (-1.0, -2.0)];
        let hs: Vec<HalfPlane> = cs.iter().map(|&(d, c)| HalfPlane::new(dirs[d].0, dirs[d].1, c as f64)).collect();
        check(&hs, seed)?;
    }

    #[test]
    fn through_one_point(ns in prop::collection::vec((-4i8..=4, -4i8..=4), 1..20), p in (-3i8..=3, -3i8..=3), extra in prop::collection::vec((-4i8..=4, -4i8..=4, -4i8..=4), 0..3), seed in any::<u64>()) {
        let mut hs: Vec<HalfPlane> = ns.iter().map(|&(a, b)| {
            let (a, b) = (a as f64, b as f64);
            HalfPlane::new(a, b, a * p.0 as f64 + b * p.1 as f64)
        }).collect();
        hs.extend(extra.iter().map(|&(a, b, c)| HalfPlane::new(a as f64, b as f64, c as f64)));
        check(&hs, seed)?;
    }
}

#[test]
fn many_random_tangents_against_incremental() {
    // Every constraint touches the unit circle: all of them bound the region.
    let mut unit = common::units(12345);
    let hs: Vec<HalfPlane> = (0..1500)
        .map(|_| {
            let t = unit() * std::f64::consts::TAU;
            HalfPlane::new(t.cos(), t.sin(), 1.0)
        })
        .collect();
    let dc = intersect_halfplanes_dc(&hs).unwrap();
    assert_eq!(dc.kind, RegionKind::Polygon);
    assert_eq!(dc.vertices.len(), hs.len());
    let inc = intersect_halfplanes_incremental(&hs, 3).unwrap();
    assert_eq!(dc, inc);
    assert_eq!(intersect_halfplanes_dc_leaf(&hs, 1).unwrap(), dc);
}

#[test]
fn every_kind() {
    let h = HalfPlane::new;
    let kind = |hs: &[HalfPlane]| intersect_halfplanes_dc(hs).unwrap().kind;
    assert_eq!(kind(&[]), RegionKind::Unbounded);
    assert_eq!(kind(&[h(0.0, 0.0, -1.0)]), RegionKind::Empty);
    assert_eq!(kind(&[h(0.0, 0.0, 1.0)]), RegionKind::Unbounded);
    assert_eq!(
        kind(&[h(1.0, 0.0, 0.0), h(-1.0, 0.0, -1.0)]),
        RegionKind::Empty
    );
    assert_eq!(
        kind(&[h(0.0, 1.0, 0.0), h(0.0, -1.0, 0.0)]),
        RegionKind::Line
    );
    assert_eq!(
        kind(&[h(0.0, 1.0, 0.0), h(0.0, -1.0, 0.0), h(1.0, 0.0, 2.0)]),
        RegionKind::Ray
    );
    assert_eq!(
        kind(&[
            h(1.0, -1.0, 0.0),
            h(-1.0, 1.0, 0.0),
            h(1.0, 0.0, 2.0),
            h(-1.0, 0.0, 2.0)
        ]),
        RegionKind::Segment
    );
    assert_eq!(
        kind(&[h(1.0, 1.0, 0.0), h(-1.0, 1.0, 0.0), h(0.0, -1.0, 0.0)]),
        RegionKind::Point
    );
    assert_eq!(
        kind(&[h(1.0, 1.0, 0.0), h(-1.0, 1.0, 0.0), h(0.0, -1.0, 1.0)]),
        RegionKind::Polygon
    );
    assert_eq!(
        kind(&[h(1.0, 1.0, 0.0), h(-1.0, 1.0, 0.0)]),
        RegionKind::Unbounded
    );
    // A non-finite coefficient is an error naming the constraint.
    let e = intersect_halfplanes_dc(&[h(1.0, 0.0, 0.0), h(f64::NAN, 0.0, 0.0)]).unwrap_err();
    assert!(e.to_string().contains("constraint 1"), "{e}");
}

/// Large inputs (the slope-sort method first prunes with a sample's region from 512
/// constraints on): the same region as divide and conquer, and it verifies.
fn check_large(hs: &[HalfPlane]) -> Result<(), TestCaseError> {
    let dc = intersect_halfplanes_dc(hs).expect("valid input");
    let scan = intersect_halfplanes_scan(hs).expect("valid input");
    prop_assert_eq!(scan.kind, dc.kind);
    prop_assert_eq!(&scan.vertices, &dc.vertices);
    prop_assert_eq!(&scan.outline, &dc.outline);
    if matches!(dc.kind, RegionKind::Polygon | RegionKind::Unbounded) {
        prop_assert_eq!(&scan.constraints, &dc.constraints);
    }
    verify_region(hs, &scan).map_err(|e| TestCaseError::fail(e.to_string()))?;
    Ok(())
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(12))]

    #[test]
    fn large_random_with_a_few_that_matter(hs in prop::collection::vec((-1.0f64..1.0, -1.0f64..1.0, 0.2f64..1.5)
        .prop_map(|(a, b, c)| HalfPlane::new(a, b, c)), 500..1500),
        extra in prop::collection::vec((-3i8..=3, -3i8..=3, -2i8..=2), 0..6)) {
        // Mostly redundant constraints around the origin, plus a few integer ones that may
        // cut, touch, flatten or empty the region, or leave it unbounded.
        let mut hs = hs;
        hs.extend(extra.iter().map(|&(a, b, c)| HalfPlane::new(a as f64, b as f64, c as f64 / 4.0)));
        check_large(&hs)?;
    }

    #[test]
    fn large_integer_grid(hs in prop::collection::vec((-6i8..=6, -6i8..=6, -8i8..=8)
        .prop_map(|(a, b, c)| HalfPlane::new(a as f64, b as f64, c as f64)), 520..900)) {
        check_large(&hs)?;
    }

    #[test]
    fn large_tangent_lines(angles in prop::collection::vec(0u32..256, 520..900), offsets in prop::collection::vec(-1i8..=1, 1..5)) {
        check_large(&tangents(&angles, 256, &offsets))?;
    }

    #[test]
    fn large_through_one_point(ns in prop::collection::vec((-5i8..=5, -5i8..=5), 520..800), p in (-3i8..=3, -3i8..=3), flat in any::<bool>()) {
        // All through one point (a point or a cone); with `flat`, also both sides of one
        // line through it (a ray or a segment).
        let mut hs: Vec<HalfPlane> = ns.iter().map(|&(a, b)| {
            let (a, b) = (a as f64, b as f64);
            HalfPlane::new(a, b, a * p.0 as f64 + b * p.1 as f64)
        }).collect();
        if flat {
            let (a, b) = (1.0, 2.0);
            let c = a * p.0 as f64 + b * p.1 as f64;
            hs.push(HalfPlane::new(a, b, c));
            hs.push(HalfPlane::new(-a, -b, -c));
        }
        check_large(&hs)?;
    }
}

#[test]
fn large_degenerate_results() {
    // 600 redundant constraints around the origin plus a pinch: a segment, a point, empty.
    let mut base: Vec<HalfPlane> = (0..600)
        .map(|k| {
            let t = k as f64 * 0.37;
            HalfPlane::new(t.cos(), t.sin(), 3.0 + (k % 7) as f64)
        })
        .collect();
    let h = HalfPlane::new;
    base.extend([h(0.0, 1.0, 0.5), h(0.0, -1.0, -0.5)]);
    let r = intersect_halfplanes_scan(&base).unwrap();
    assert_eq!(r.kind, RegionKind::Segment);
    assert_eq!(r, intersect_halfplanes_dc(&base).unwrap());
    base.extend([h(1.0, 0.0, 0.25), h(-1.0, 0.0, -0.25)]);
    let r = intersect_halfplanes_scan(&base).unwrap();
    assert_eq!(r.kind, RegionKind::Point);
    assert_eq!(r.vertices, [compgeom::Point2::new(0.25, 0.5)]);
    base.push(h(1.0, 1.0, 0.5));
    assert_eq!(
        intersect_halfplanes_scan(&base).unwrap().kind,
        RegionKind::Empty
    );
    // Empty already in the sample's region.
    let mut empty: Vec<HalfPlane> = vec![h(1.0, 0.0, -1.0); 300];
    empty.extend(vec![h(-1.0, 0.0, -1.0); 300]);
    assert_eq!(
        intersect_halfplanes_scan(&empty).unwrap().kind,
        RegionKind::Empty
    );
}
