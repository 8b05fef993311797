//! Voronoi diagrams: Fortune's sweep against a brute-force exact oracle, the exact
//! verifier, clipping, nearest-site queries, on random and deliberately degenerate input.

mod common;

use compgeom::kernel::CircleSide;
use compgeom::voronoi::{
    beach_line_at, clip_cells, fortune_voronoi, verify_cells, verify_voronoi, ClipRegion,
    NearestSite, VoronoiDiagram,
};
use compgeom::Point2;
use proptest::prelude::*;
use std::collections::BTreeSet;

fn pts(v: &[(f64, f64)]) -> Vec<Point2> {
    v.iter().map(|&(x, y)| Point2::new(x, y)).collect()
}

/// Brute-force oracle, O(n⁴): the Voronoi vertices are the empty circles through three or
/// more sites; each is given by the set of sites on it (as indices into `sites`).
fn oracle_vertices(sites: &[Point2]) -> BTreeSet<Vec<usize>> {
    common::site_circles(sites, CircleSide::Inside)
}

fn diagram_vertices(d: &VoronoiDiagram) -> BTreeSet<Vec<usize>> {
    d.vertices.iter().map(|v| v.sites.clone()).collect()
}

/// Full check: oracle (small inputs), exact verifier, clipped cells tile a box.
fn check(points: &[Point2]) -> VoronoiDiagram {
    let d = fortune_voronoi(points).unwrap();
    let shown = |p: &[Point2]| {
        if p.len() <= 40 {
            format!("{p:?}")
        } else {
            format!("{} points", p.len())
        }
    };
    verify_voronoi(points, &d).unwrap_or_else(|e| panic!("{e} for {}", shown(points)));
    assert_eq!(
        d.vertices.len(),
        diagram_vertices(&d).len(),
        "duplicate vertices"
    );
    if d.sites.len() <= 40 {
        assert_eq!(
            diagram_vertices(&d),
            oracle_vertices(&d.sites),
            "vertices differ for {points:?}"
        );
    }
    if !d.sites.is_empty() {
        let region = ClipRegion::around(&d.sites, 0.5).unwrap();
        let cells = clip_cells(&d, &region);
        verify_cells(&d, &region, &cells).unwrap_or_else(|e| panic!("{e} for {}", shown(points)));
        // Post office: the nearest site by brute force has the same distance.
        let post = NearestSite::new(&d);
        for q in d.sites.iter().take(20) {
            let q = Point2::new(q.x + 0.37, q.y - 0.21);
            let got = post.nearest(q).unwrap();
            let dist = |s: &Point2| (s.x - q.x).powi(2) + (s.y - q.y).powi(2);
            let best = d.sites.iter().map(dist).fold(f64::INFINITY, f64::min);
            assert!(
                dist(&d.sites[got]) <= best * (1.0 + 1e-12),
                "nearest for {q:?}"
            );
        }
    }
    d
}

#[test]
fn three_sites() {
    let d = check(&pts(&[(0.0, 0.0), (4.0, 0.0), (0.0, 4.0)]));
    assert_eq!(d.vertices.len(), 1);
    assert_eq!(d.vertices[0].point, Point2::new(2.0, 2.0));
    assert_eq!(d.edge_count(), 3);
}

#[test]
fn empty_single_and_two() {
    let d = check(&[]);
    assert!(d.sites.is_empty() && d.half_edges.is_empty());
    let d = check(&pts(&[(1.0, 2.0)]));
    assert_eq!(d.sites.len(), 1);
    assert!(d.half_edges.is_empty());
    let d = check(&pts(&[(1.0, 2.0), (3.0, 2.0)]));
    assert_eq!(d.edge_count(), 1);
    assert!(d.vertices.is_empty());
}

#[test]
fn duplicates_are_merged() {
    let p = pts(&[
        (0.0, 0.0),
        (1.0, 0.0),
        (0.0, 0.0),
        (0.0, 1.0),
        (1.0, 0.0),
        (-0.0, 0.0),
    ]);
    let d = check(&p);
    assert_eq!(d.sites.len(), 3);
    assert_eq!(d.input_to_site, vec![0, 1, 0, 2, 1, 0]);
    assert_eq!(d.site_input_index, vec![0, 1, 3]);
}

#[test]
fn equal_top_row_and_horizontal_line() {
    let row: Vec<(f64, f64)> = (0..7).map(|i| (i as f64 * 1.5, 3.0)).collect();
    let d = check(&pts(&row));
    assert!(d.vertices.is_empty());
    assert_eq!(d.edge_count(), 6);
    let mut more = row.clone();
    more.extend([(2.0, 0.0), (5.0, -1.0), (0.7, 1.0)]);
    check(&pts(&more));
}

#[test]
fn collinear_diagonal_and_vertical() {
    let diag: Vec<(f64, f64)> = (0..9).map(|i| (i as f64, -2.0 * i as f64)).collect();
    let d = check(&pts(&diag));
    assert!(d.vertices.is_empty());
    assert_eq!(d.edge_count(), 8);
    let nb = d.neighbours();
    assert_eq!(nb[4], vec![3, 5]);
    let vert: Vec<(f64, f64)> = (0..6).map(|i| (2.0, i as f64)).collect();
    let d = check(&pts(&vert));
    assert_eq!(d.edge_count(), 5);
}

#[test]
fn square_gives_one_degree_four_vertex() {
    let d = check(&pts(&[(0.0, 0.0), (2.0, 0.0), (2.0, 2.0), (0.0, 2.0)]));
    assert_eq!(d.vertices.len(), 1);
    assert_eq!(d.vertices[0].sites, vec![0, 1, 2, 3]);
    assert_eq!(d.edge_count(), 4);
}

/// Integer points on x² + y² = r²: r² = 5525 = 5²·13·17 has many lattice points.
fn lattice_circle(r2: i64) -> Vec<Point2> {
    let r = (r2 as f64).sqrt() as i64 + 1;
    let mut v = Vec::new();
    for x in -r..=r {
        for y in -r..=r {
            if x * x + y * y == r2 {
                v.push(Point2::new(x as f64, y as f64));
            }
        }
    }
    v
}

#[test]
fn cocircular_lattice_points() {
    let c = lattice_circle(5525);
    assert!(c.len() >= 40, "{}", c.len());
    let d = check(&c);
    assert_eq!(d.vertices.len(), 1);
    assert_eq!(d.vertices[0].sites.len(), c.len());
    assert_eq!(d.vertices[0].point, Point2::new(0.0, 0.0));
    // With the centre added: a wheel.
    let mut w = c.clone();
    w.push(Point2::new(0.0, 0.0));
    check(&w);
    // Two concentric lattice circles plus shifted copies.
    let mut two = lattice_circle(25);
    two.extend(
        lattice_circle(65)
            .iter()
            .map(|p| Point2::new(p.x + 3.0, p.y)),
    );
    check(&two);
}

#[test]
fn integer_grids() {
    for (w, h) in [(2, 2), (3, 3), (5, 4), (7, 7)] {
        let mut g = Vec::new();
        for i in 0..w {
            for j in 0..h {
                g.push(Point2::new(i as f64, j as f64));
            }
        }
        let d = check(&g);
        // Each inner grid square has its centre as a degree-4 vertex.
        assert_eq!(d.vertices.len(), (w - 1) * (h - 1));
    }
    // A bigger grid: verifier only.
    let mut g = Vec::new();
    for i in 0..40 {
        for j in 0..40 {
            g.push(Point2::new(i as f64 * 0.5, j as f64 * 0.25));
        }
    }
    let d = check(&g);
    assert_eq!(d.vertices.len(), 39 * 39);
}

#[test]
fn random_larger_inputs() {
    let mut s: u64 = 12345;
    let mut rnd = || {
        s ^= s << 13;
        s ^= s >> 7;
        s ^= s << 17;
        (s >> 11) as f64 / (1u64 << 53) as f64
    };
    let p: Vec<Point2> = (0..3000)
        .map(|_| Point2::new(rnd() * 100.0, rnd() * 100.0))
        .collect();
    let d = check(&p);
    assert_eq!(d.sites.len(), 3000);
    // Tiny and huge magnitudes.
    let q: Vec<Point2> = p
        .iter()
        .take(300)
        .map(|p| Point2::new(p.x * 1e-200, p.y * 1e-200))
        .collect();
    check(&q);
    let q: Vec<Point2> = p
        .iter()
        .take(300)
        .map(|p| Point2::new(p.x * 1e200, p.y * 1e200))
        .collect();
    check(&q);
}

#[test]
fn near_degenerate_perturbed_square() {
    let e = f64::EPSILON;
    check(&pts(&[(0.0, 0.0), (1.0, 0.0), (1.0, 1.0 + e), (0.0, 1.0)]));
    check(&pts(&[
        (0.0, 0.0),
        (1.0, 0.0),
        (1.0, 1.0 - e / 2.0),
        (0.0, 1.0),
    ]));
    check(&pts(&[
        (0.1, 0.1),
        (0.3, 0.1),
        (0.3, 0.3),
        (0.1, 0.3),
        (0.2, 0.2),
    ]));
}

#[test]
fn non_finite_is_an_error() {
    let e = fortune_voronoi(&pts(&[(0.0, 0.0), (f64::NAN, 1.0)])).unwrap_err();
    assert!(e.to_string().contains("point 1"), "{e}");
}

#[test]
fn clip_to_convex_polygon_and_rejects_non_convex() {
    let d = fortune_voronoi(&pts(&[(0.0, 0.0), (2.0, 0.0), (1.0, 2.0), (1.0, 0.7)])).unwrap();
    let tri = pts(&[(-5.0, -5.0), (6.0, -4.0), (1.0, 8.0)]);
    let region = ClipRegion::convex_polygon(&tri).unwrap();
    let cells = clip_cells(&d, &region);
    verify_cells(&d, &region, &cells).unwrap();
    // Clockwise input is accepted and reoriented.
    let mut cw = tri.clone();
    cw.reverse();
    assert!((ClipRegion::convex_polygon(&cw).unwrap().area() - region.area()).abs() < 1e-12);
    let notch = pts(&[(0.0, 0.0), (4.0, 0.0), (2.0, 1.0), (4.0, 4.0), (0.0, 4.0)]);
    assert!(ClipRegion::convex_polygon(&notch).is_err());
    assert!(ClipRegion::rect(0.0, 0.0, 0.0, 1.0).is_err());
}

#[test]
fn beach_line_snapshot() {
    let p = pts(&[(0.0, 4.0), (3.0, 3.0), (1.0, 1.0)]);
    let s = beach_line_at(&p, 2.0).unwrap();
    // Site 1 split site 0's arc; site 2 is below the sweep line.
    assert_eq!(s.arcs, vec![0, 1, 0]);
    let y = s.height_at(3.0).unwrap();
    assert!((y - 2.5).abs() < 1e-12, "{y}");
}

fn small_grid_points() -> impl Strategy<Value = Vec<Point2>> {
    prop::collection::vec((0i32..6, 0i32..6), 0..14).prop_map(|v| {
        v.into_iter()
            .map(|(x, y)| Point2::new(x as f64, y as f64))
            .collect()
    })
}

fn random_points() -> impl Strategy<Value = Vec<Point2>> {
    prop::collection::vec((-1e3f64..1e3, -1e3f64..1e3), 0..25)
        .prop_map(|v| v.into_iter().map(|(x, y)| Point2::new(x, y)).collect())
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(160))]

    #[test]
    fn grid_points_match_oracle(p in small_grid_points()) {
        check(&p);
    }

    #[test]
    fn random_points_match_oracle(p in random_points()) {
        check(&p);
    }

    #[test]
    fn lattice_circle_subsets_match_oracle(mask in prop::collection::vec(any::<bool>(), 36), extra in prop::collection::vec((-80i32..80, -80i32..80), 0..4)) {
        let c = lattice_circle(5525);
        let mut p: Vec<Point2> = c.iter().zip(mask.iter().cycle()).filter(|(_, &m)| m).map(|(p, _)| *p).collect();
        p.extend(extra.iter().map(|&(x, y)| Point2::new(x as f64, y as f64)));
        check(&p);
    }
}
