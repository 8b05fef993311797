//! Terrain interpolation and the Euclidean minimum spanning tree.

mod common;
use compgeom::delaunay::{euclidean_mst, Terrain};
use compgeom::{Point2, Point3};

#[test]
fn a_plane_is_reproduced_inside_and_none_outside() {
    let mut unit = common::units(5);
    let plane = |x: f64, y: f64| 2.0 * x - 3.0 * y + 1.0;
    let mut s: Vec<Point3> = (0..500)
        .map(|_| {
            let (x, y) = (unit() * 10.0, unit() * 10.0);
            Point3::new(x, y, plane(x, y))
        })
        .collect();
    for (x, y) in [(0.0, 0.0), (10.0, 0.0), (10.0, 10.0), (0.0, 10.0)] {
        s.push(Point3::new(x, y, plane(x, y)));
    }
    let t = Terrain::new(&s).unwrap();
    for _ in 0..2000 {
        let (x, y) = (unit() * 10.0, unit() * 10.0);
        let h = t.height_at(Point2::new(x, y)).unwrap();
        assert!((h - plane(x, y)).abs() < 1e-9, "{h} vs {}", plane(x, y));
    }
    assert_eq!(
        t.height_at(Point2::new(10.0, 10.0)),
        Some(plane(10.0, 10.0))
    );
    assert_eq!(
        t.height_at(Point2::new(5.0, 0.0))
            .map(|h| (h - 11.0).abs() < 1e-12),
        Some(true)
    );
    for q in [(-0.001, 5.0), (5.0, 10.0001), (11.0, 11.0), (-1e9, 0.0)] {
        assert_eq!(t.height_at(Point2::from(q)), None, "{q:?}");
    }
    assert_eq!(t.height_at(Point2::new(f64::NAN, 0.0)), None);
}

#[test]
fn collinear_samples_only_answer_at_sites() {
    let s: Vec<Point3> = (0..5)
        .map(|i| Point3::new(i as f64, i as f64, i as f64 * 10.0))
        .collect();
    let t = Terrain::new(&s).unwrap();
    assert_eq!(t.height_at(Point2::new(2.0, 2.0)), Some(20.0));
    assert_eq!(t.height_at(Point2::new(2.5, 2.5)), None);
    assert!(Terrain::new(&[Point3::new(0.0, 0.0, f64::NAN)]).is_err());
}

fn brute_mst_weight(v: &[Point2]) -> f64 {
    // Prim's algorithm over all pairs.
    let n = v.len();
    let d = |a: usize, b: usize| ((v[a].x - v[b].x).powi(2) + (v[a].y - v[b].y).powi(2)).sqrt();
    let mut in_tree = vec![false; n];
    let mut best = vec![f64::INFINITY; n];
    best[0] = 0.0;
    let mut total = 0.0;
    for _ in 0..n {
        let u = (0..n)
            .filter(|&i| !in_tree[i])
            .min_by(|&a, &b| best[a].total_cmp(&best[b]))
            .unwrap();
        in_tree[u] = true;
        total += best[u];
        for w in 0..n {
            if !in_tree[w] {
                best[w] = best[w].min(d(u, w));
            }
        }
    }
    total
}

#[test]
fn emst_matches_prim_on_random_and_grid_input() {
    let mut unit = common::units(9);
    for n in [2, 3, 10, 100, 400] {
        let pts: Vec<Point2> = (0..n).map(|_| Point2::new(unit(), unit())).collect();
        let (t, tree) = euclidean_mst(&pts).unwrap();
        assert_eq!(tree.len(), t.vertices().len() - 1);
        let v = t.vertices();
        let w: f64 = tree
            .iter()
            .map(|&(a, b)| {
                ((v[a as usize].x - v[b as usize].x).powi(2)
                    + (v[a as usize].y - v[b as usize].y).powi(2))
                .sqrt()
            })
            .sum();
        assert!((w - brute_mst_weight(v)).abs() < 1e-9);
    }
    // Grid with duplicates: all unit edges, n - 1 of them.
    let pts: Vec<Point2> = (0..60)
        .map(|i| Point2::new((i % 6) as f64, ((i / 6) % 5) as f64))
        .collect();
    let (t, tree) = euclidean_mst(&pts).unwrap();
    assert_eq!(t.vertices().len(), 30);
    assert_eq!(tree.len(), 29);
    let v = t.vertices();
    for (a, b) in tree {
        let (p, q) = (v[a as usize], v[b as usize]);
        assert_eq!((p.x - q.x).abs() + (p.y - q.y).abs(), 1.0);
    }
    // Collinear.
    let line: Vec<Point2> = [3.0, 1.0, 2.0, 0.0]
        .iter()
        .map(|&x| Point2::new(x, 2.0 * x))
        .collect();
    let (_, tree) = euclidean_mst(&line).unwrap();
    assert_eq!(tree.len(), 3);
}
