//! Half-plane intersection against an exact brute-force oracle: every result kind, on
//! random and deliberately degenerate input.

mod lp_oracle;

use compgeom::lp::{intersect_halfplanes, verify_region, HalfPlane, Region, RegionKind};
use compgeom::Point2;
use lp_oracle::*;
use num_traits::Zero;
use proptest::prelude::*;

/// Is there a direction d != 0 with a·d <= 0 for every constraint (the region, if not
/// empty, is unbounded)?
fn unbounded(hs: &[HalfPlane]) -> bool {
    let mut dirs = vec![(r(1.0), r(0.0)), (r(0.0), r(1.0))];
    for h in hs.iter().filter(|h| h.a != 0.0 || h.b != 0.0) {
        dirs.push((r(h.b), -r(h.a)));
        dirs.push((-r(h.b), r(h.a)));
        dirs.push((-r(h.a), -r(h.b)));
    }
    dirs.iter().any(|d| {
        hs.iter()
            .all(|h| r(h.a) * &d.0 + r(h.b) * &d.1 <= Q::zero())
    })
}

/// Two constraints with opposite normals and the same line: the region lies on that line.
fn flat(hs: &[HalfPlane]) -> bool {
    hs.iter().enumerate().any(|(i, h)| {
        hs[i + 1..].iter().any(|g| {
            let cross = r(h.a) * r(g.b) - r(g.a) * r(h.b);
            let dot = r(h.a) * r(g.a) + r(h.b) * r(g.b);
            let nn = r(h.a) * r(h.a) + r(h.b) * r(h.b);
            // g = λ·h with λ = dot/nn < 0 and g.c = λ·h.c.
            (h.a != 0.0 || h.b != 0.0)
                && cross.is_zero()
                && dot < Q::zero()
                && r(g.c) * &nn == dot * r(h.c)
        })
    })
}

fn expected_kind(hs: &[HalfPlane], nv: usize) -> RegionKind {
    if !feasible(hs) {
        return RegionKind::Empty;
    }
    match (unbounded(hs), flat(hs), nv) {
        (false, _, 1) => RegionKind::Point,
        (false, _, 2) => RegionKind::Segment,
        (false, _, _) => RegionKind::Polygon,
        (true, true, 0) => RegionKind::Line,
        (true, true, _) => RegionKind::Ray,
        (true, false, _) => RegionKind::Unbounded,
    }
}

fn check(hs: &[HalfPlane], seed: u64, edges: bool) -> Result<Region, TestCaseError> {
    let got = intersect_halfplanes(hs, seed).expect("valid input");
    verify_region(hs, &got).map_err(|e| TestCaseError::fail(e.to_string()))?;
    let exact = vertices(hs);
    let kind = expected_kind(hs, exact.len());
    prop_assert_eq!(got.kind, kind, "vertices {:?}", got.vertices);
    let mut want: Vec<(f64, f64)> = exact.iter().map(|p| (f(&p.0), f(&p.1))).collect();
    let mut have: Vec<(f64, f64)> = got.vertices.iter().map(|p| (p.x, p.y)).collect();
    want.sort_by(|a, b| a.partial_cmp(b).unwrap());
    have.sort_by(|a, b| a.partial_cmp(b).unwrap());
    prop_assert_eq!(&have, &want);
    if kind == RegionKind::Polygon {
        // Counter-clockwise, and constraint k carries the edge from vertex k to k + 1.
        let n = got.vertices.len();
        prop_assert_eq!(got.constraints.len(), n);
        let find = |p: Point2| {
            exact
                .iter()
                .find(|e| (f(&e.0), f(&e.1)) == (p.x, p.y))
                .unwrap()
                .clone()
        };
        let mut area = Q::zero();
        for k in 0..n {
            let (p, q) = (find(got.vertices[k]), find(got.vertices[(k + 1) % n]));
            area += &p.0 * &q.1 - &q.0 * &p.1;
            if edges {
                let h = &hs[got.constraints[k]];
                prop_assert!(slack(h, &p).is_zero() && slack(h, &q).is_zero(), "edge {k}");
            }
        }
        prop_assert!(area > Q::zero());
    }
    for &k in &got.constraints {
        prop_assert!(k < hs.len());
    }
    Ok(got)
}

fn small_hp() -> impl Strategy<Value = HalfPlane> {
    (-3i8..=3, -3i8..=3, -4i8..=4)
        .prop_map(|(a, b, c)| HalfPlane::new(a as f64, b as f64, c as f64))
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(400))]

    #[test]
    fn small_integer_sets(hs in prop::collection::vec(small_hp(), 0..9), seed in any::<u64>()) {
        check(&hs, seed, true)?;
    }

    #[test]
    fn with_opposite_pairs(base in prop::collection::vec(small_hp(), 1..6), flips in prop::collection::vec((0usize..6, 0i8..=1), 0..4), seed in any::<u64>()) {
        // Add negated copies (shifted by 0 or 1): segments, rays, lines, points on purpose.
        let mut hs = base.clone();
        for (k, shift) in flips {
            let h = base[k % base.len()];
            hs.push(HalfPlane::new(-h.a, -h.b, -h.c + shift as f64));
        }
        check(&hs, seed, true)?;
    }

    #[test]
    fn lines_through_one_point(ns in prop::collection::vec((-3i8..=3, -3i8..=3), 1..8), p in (-2i8..=2, -2i8..=2), seed in any::<u64>()) {
        let hs: Vec<HalfPlane> = ns.iter().map(|&(a, b)| {
            let (a, b) = (a as f64, b as f64);
            HalfPlane::new(a, b, a * p.0 as f64 + b * p.1 as f64)
        }).collect();
        check(&hs, seed, true)?;
    }

    #[test]
    fn fractional_sets(hs in prop::collection::vec((-1.0f64..1.0, -1.0f64..1.0, -0.2f64..1.0).prop_map(|(a, b, c)| HalfPlane::new(a, b, c)), 0..9), seed in any::<u64>()) {
        check(&hs, seed, false)?;
    }
}

#[test]
fn every_kind_by_hand() {
    let h = HalfPlane::new;
    let kind = |hs: &[HalfPlane]| intersect_halfplanes(hs, 1).unwrap().kind;
    assert_eq!(kind(&[]), RegionKind::Unbounded);
    assert_eq!(
        kind(&[h(1.0, 0.0, 0.0), h(-1.0, 0.0, -1.0)]),
        RegionKind::Empty
    );
    assert_eq!(kind(&[h(0.0, 0.0, -1.0)]), RegionKind::Empty);
    assert_eq!(
        kind(&[h(1.0, 0.0, 0.0), h(-1.0, 0.0, 0.0)]),
        RegionKind::Line
    );
    assert_eq!(
        kind(&[h(1.0, 0.0, 0.0), h(-1.0, 0.0, 0.0), h(0.0, 1.0, 0.0)]),
        RegionKind::Ray
    );
    let seg = [
        h(1.0, 0.0, 0.0),
        h(-1.0, 0.0, 0.0),
        h(0.0, 1.0, 1.0),
        h(0.0, -1.0, 1.0),
    ];
    let r = intersect_halfplanes(&seg, 3).unwrap();
    assert_eq!(r.kind, RegionKind::Segment);
    assert_eq!(r.vertices.len(), 2);
    let pt = [h(1.0, 1.0, 0.0), h(-1.0, 1.0, 0.0), h(0.0, -1.0, 0.0)];
    let r = intersect_halfplanes(&pt, 3).unwrap();
    assert_eq!(r.kind, RegionKind::Point);
    assert_eq!(r.vertices, vec![Point2::new(0.0, 0.0)]);
    // A strip: unbounded with two boundary lines and no corner.
    let r = intersect_halfplanes(&[h(0.0, 1.0, 1.0), h(0.0, -1.0, 1.0)], 0).unwrap();
    assert_eq!(r.kind, RegionKind::Unbounded);
    assert!(r.vertices.is_empty());
    assert_eq!(r.constraints.len(), 2);
}

#[test]
fn many_tangents_to_a_circle() {
    // 200 tangents: a 200-gon; every vertex is a constructed point.
    let n = 200;
    let hs: Vec<HalfPlane> = (0..n)
        .map(|k| {
            let t = k as f64 * std::f64::consts::TAU / n as f64;
            HalfPlane::new(t.cos(), t.sin(), 1.0)
        })
        .collect();
    let r = intersect_halfplanes(&hs, 9).unwrap();
    assert_eq!(r.kind, RegionKind::Polygon);
    assert_eq!(r.vertices.len(), n);
    let mut cs = r.constraints.clone();
    cs.sort_unstable();
    assert_eq!(cs, (0..n).collect::<Vec<_>>());
}

#[test]
fn the_verifier_rejects_wrong_regions() {
    let hs = [
        HalfPlane::new(-1.0, 0.0, 0.0),
        HalfPlane::new(0.0, -1.0, 0.0),
        HalfPlane::new(1.0, 1.0, 2.0),
    ];
    let mut r = intersect_halfplanes(&hs, 0).unwrap();
    verify_region(&hs, &r).unwrap();
    r.vertices[1] = Point2::new(2.0, 0.5);
    assert!(verify_region(&hs, &r).is_err());
    let mut r = intersect_halfplanes(&hs, 0).unwrap();
    r.kind = RegionKind::Empty;
    assert!(verify_region(&hs, &r).is_err());
}
