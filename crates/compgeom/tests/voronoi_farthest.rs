//! The farthest-point Voronoi diagram against brute force: its vertices are exactly the
//! circles through three or more sites that contain every site, and for query points the
//! cells containing them (decided exactly from the cells' neighbours) are exactly the
//! farthest sites; on random, grid, cocircular, collinear and duplicate input.
//!
//! Coordinates are small multiples of 1/8 so that squared distances are exact in `f64`
//! and the brute-force oracle is exact without special arithmetic.

mod common;

use compgeom::kernel::CircleSide;
use compgeom::voronoi::{farthest_point_voronoi, verify_farthest, ClipRegion, FarthestVoronoi};
use compgeom::Point2;
use proptest::prelude::*;
use std::collections::BTreeSet;

fn d2(a: Point2, b: Point2) -> f64 {
    (a.x - b.x) * (a.x - b.x) + (a.y - b.y) * (a.y - b.y)
}

/// Circles through three or more sites with every site inside or on them, as site sets.
fn oracle_vertices(sites: &[Point2]) -> BTreeSet<Vec<usize>> {
    common::site_circles(sites, CircleSide::Outside)
}

/// Full check; `queries` are points at which cells are compared with brute force.
fn check(points: &[Point2], queries: &[Point2]) -> FarthestVoronoi {
    let f = farthest_point_voronoi(points).unwrap();
    verify_farthest(points, &f).unwrap_or_else(|e| panic!("{e} for {points:?}"));
    let vs: BTreeSet<Vec<usize>> = f.vertices.iter().map(|v| v.sites.clone()).collect();
    assert_eq!(vs.len(), f.vertices.len(), "repeated vertex");
    if f.sites.len() <= 30 {
        assert_eq!(vs, oracle_vertices(&f.sites), "vertices for {points:?}");
    }
    // Every cell is unbounded: one half-edge from infinity per hull corner.
    let h = f.hull.len();
    if h >= 2 {
        let rays = f.half_edges.iter().filter(|e| e.origin.is_none()).count();
        assert_eq!(rays, h, "one ray between each pair of adjacent corners");
    }
    let adj = f.neighbours();
    for &q in queries {
        let far = f
            .sites
            .iter()
            .map(|&s| d2(q, s))
            .fold(f64::NEG_INFINITY, f64::max);
        let want: BTreeSet<usize> = (0..f.sites.len())
            .filter(|&s| d2(q, f.sites[s]) == far)
            .collect();
        let got: BTreeSet<usize> = (0..f.sites.len())
            .filter(|&s| {
                f.site_half_edge[s].is_some()
                    && adj[s]
                        .iter()
                        .all(|&t| d2(q, f.sites[s]) >= d2(q, f.sites[t]))
            })
            .collect();
        if h >= 2 {
            assert_eq!(got, want, "cells containing {q:?} for {points:?}");
        }
        if f.sites.is_empty() {
            assert_eq!(f.farthest(q), None);
            continue;
        }
        let one = f.farthest(q).unwrap();
        assert!(want.contains(&one), "farthest({q:?}) = {one}");
    }
    f
}

fn pts(v: &[(f64, f64)]) -> Vec<Point2> {
    v.iter().map(|&(x, y)| Point2::new(x, y)).collect()
}

fn grid_queries(lo: i32, hi: i32, step: f64) -> Vec<Point2> {
    let mut q = Vec::new();
    for i in lo..=hi {
        for j in lo..=hi {
            q.push(Point2::new(i as f64 * step, j as f64 * step));
        }
    }
    q
}

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
fn small_and_degenerate() {
    let q = grid_queries(-6, 6, 1.0);
    assert_eq!(check(&[], &[]).edge_count(), 0);
    let one = check(&pts(&[(1.0, 1.0), (1.0, 1.0)]), &q);
    assert_eq!(one.hull, vec![0]);
    assert_eq!(one.farthest(Point2::new(5.0, 5.0)), Some(0));
    // Collinear: only the extremes have cells, split by one edge.
    let line = check(
        &pts(&[(0.0, 0.0), (2.0, 1.0), (4.0, 2.0), (-2.0, -1.0)]),
        &q,
    );
    assert_eq!(line.edge_count(), 1);
    assert!(line.vertices.is_empty());
    assert_eq!(line.site_half_edge[0], None);
    let tri = check(&pts(&[(0.0, 0.0), (4.0, 0.0), (0.0, 3.0), (1.0, 1.0)]), &q);
    assert_eq!(tri.vertices.len(), 1);
    assert_eq!(tri.vertices[0].point, Point2::new(2.0, 1.5));
    assert_eq!(tri.edge_count(), 3);
    // Points on hull edges have no cell.
    let sq = check(
        &pts(&[
            (0.0, 0.0),
            (2.0, 0.0),
            (4.0, 0.0),
            (4.0, 4.0),
            (0.0, 4.0),
            (0.0, 2.0),
            (2.0, 2.0),
        ]),
        &q,
    );
    assert_eq!(sq.hull.len(), 4);
    assert_eq!(sq.vertices.len(), 1);
    assert_eq!(sq.vertices[0].sites.len(), 4);
}

#[test]
fn cocircular_lattice_points_give_one_vertex() {
    let c = lattice_circle(5525);
    let f = check(&c, &grid_queries(-12, 12, 8.0));
    assert_eq!(f.vertices.len(), 1);
    assert_eq!(f.vertices[0].sites.len(), c.len());
    assert_eq!(f.edge_count(), c.len());
    // Two lattice circles: the outer one alone decides.
    let mut two = c.clone();
    two.extend(lattice_circle(65));
    let g = check(&two, &grid_queries(-10, 10, 9.0));
    assert_eq!(g.vertices.len(), 1);
}

#[test]
fn grids_and_random_sets() {
    let mut g = Vec::new();
    for i in 0..9 {
        for j in 0..6 {
            g.push(Point2::new(i as f64, j as f64));
        }
    }
    check(&g, &grid_queries(-4, 12, 0.75));
    let mut s: u64 = 7;
    let mut rnd = || {
        s ^= s << 13;
        s ^= s >> 7;
        s ^= s << 17;
        ((s >> 40) % 1601) as f64 / 8.0 - 100.0
    };
    let p: Vec<Point2> = (0..3000).map(|_| Point2::new(rnd(), rnd())).collect();
    let q: Vec<Point2> = (0..400).map(|_| Point2::new(rnd(), rnd())).collect();
    let f = check(&p, &q);
    assert!(f.hull.len() >= 4);
    // Points in convex position (on a parabola): every site has a cell.
    let para: Vec<Point2> = (-40..=40)
        .map(|i| Point2::new(i as f64, (i * i) as f64 / 8.0))
        .collect();
    let f = check(&para, &grid_queries(-20, 20, 3.0));
    assert_eq!(f.hull.len(), para.len());
    assert_eq!(f.vertices.len(), para.len() - 2);
}

#[test]
fn clipped_cells_tile_the_region() {
    let p = pts(&[(0.0, 0.0), (6.0, 1.0), (5.0, 7.0), (-1.0, 5.0), (2.0, 3.0)]);
    let f = farthest_point_voronoi(&p).unwrap();
    let region = ClipRegion::rect(-20.0, -20.0, 20.0, 20.0).unwrap();
    let cells = f.cells(&region);
    assert!(cells[4].is_empty());
    let area: f64 = cells
        .iter()
        .map(|c| compgeom::voronoi::clip::ring_area(c))
        .sum();
    assert!(
        (area - region.area()).abs() < 1e-9 * region.area(),
        "{area}"
    );
    assert!(cells[..4].iter().all(|c| !c.is_empty()));
}

#[test]
fn non_finite_is_an_error() {
    let e = farthest_point_voronoi(&pts(&[(0.0, 0.0), (f64::NAN, 1.0)])).unwrap_err();
    assert!(e.to_string().contains("point 1"), "{e}");
}

fn dyadic_points(max: usize) -> impl Strategy<Value = Vec<Point2>> {
    prop::collection::vec((-80i32..80, -80i32..80), 0..max).prop_map(|v| {
        v.into_iter()
            .map(|(x, y)| Point2::new(x as f64 / 8.0, y as f64 / 8.0))
            .collect()
    })
}

fn small_grid(max: usize) -> impl Strategy<Value = Vec<Point2>> {
    prop::collection::vec((0i32..5, 0i32..5), 0..max).prop_map(|v| {
        v.into_iter()
            .map(|(x, y)| Point2::new(x as f64, y as f64))
            .collect()
    })
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(150))]

    #[test]
    fn random_dyadic_sets(p in dyadic_points(30), q in dyadic_points(40)) {
        check(&p, &q);
    }

    #[test]
    fn grid_sets_with_duplicates(p in small_grid(20), q in small_grid(30)) {
        let mut p = p;
        let copy = p.clone();
        p.extend(copy.iter().step_by(2));
        // Queries on the half-grid hit bisectors and vertices exactly.
        let q: Vec<Point2> = q.iter().map(|p| Point2::new(p.x - 0.5, p.y * 1.5 - 1.0)).collect();
        check(&p, &q);
    }

    #[test]
    fn lattice_circle_subsets(mask in prop::collection::vec(any::<bool>(), 48), q in dyadic_points(20)) {
        let c = lattice_circle(5525);
        let p: Vec<Point2> = c.iter().zip(mask.iter()).filter(|(_, &m)| m).map(|(p, _)| *p).collect();
        check(&p, &q);
    }
}
