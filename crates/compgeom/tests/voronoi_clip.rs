//! Voronoi cells clipped to non-convex polygons (with holes, several parts): against the
//! slow exact path (every cell intersected with the polygon by the boolean operation),
//! areas tile the region, the verifier, degenerate alignments and errors.

use compgeom::overlay::{boolean, BooleanOp};
use compgeom::voronoi::clip::ring_area;
use compgeom::voronoi::{
    clip_cells, clip_cells_to_polygon, dual_voronoi, verify_polygon_cells, ClipRegion,
    VoronoiDiagram,
};
use compgeom::{Bbox2, MultiPolygon, Point2, Polygon};
use proptest::prelude::*;

fn area(m: &MultiPolygon) -> f64 {
    m.0.iter()
        .map(|p| ring_area(&p.exterior) + p.holes.iter().map(|h| ring_area(h)).sum::<f64>())
        .sum()
}

fn ring(v: &[(f64, f64)]) -> Vec<Point2> {
    v.iter().map(|&(x, y)| Point2::new(x, y)).collect()
}

/// The fast clipper against the slow one (boolean on every cell), and the verifier.
fn check(d: &VoronoiDiagram, clip: &MultiPolygon) -> Vec<MultiPolygon> {
    let cells = clip_cells_to_polygon(d, clip).unwrap();
    verify_polygon_cells(d, clip, &cells).unwrap_or_else(|e| panic!("{e}"));
    let pts: Vec<Point2> = clip
        .0
        .iter()
        .flat_map(|p| p.rings().flatten().copied())
        .collect();
    let region = ClipRegion::from_bbox(Bbox2::of_points(&pts)).unwrap();
    let boxed = clip_cells(d, &region);
    let total = area(&boolean(clip, &MultiPolygon::default(), BooleanOp::Union).unwrap());
    for (s, c) in boxed.iter().enumerate() {
        let slow = if c.is_empty() {
            MultiPolygon::default()
        } else {
            boolean(
                &MultiPolygon(vec![Polygon::new(c.clone(), vec![])]),
                clip,
                BooleanOp::Intersection,
            )
            .unwrap()
        };
        let (a, b) = (area(&cells[s]), area(&slow));
        assert!(
            (a - b).abs() <= 1e-9 * total.abs(),
            "cell {s}: area {a}, slow path {b}"
        );
        assert_eq!(cells[s].0.is_empty(), slow.0.is_empty(), "cell {s}");
    }
    cells
}

fn grid_sites(k: usize, step: f64) -> Vec<Point2> {
    (0..k * k)
        .map(|i| Point2::new((i % k) as f64 * step, (i / k) as f64 * step))
        .collect()
}

#[test]
fn u_shape_splits_a_cell() {
    // Sites on a row: the middle cell meets both arms of the U and the bar.
    let d = dual_voronoi(&ring(&[(1.0, 5.0), (5.0, 5.0), (9.0, 5.0), (5.0, -3.0)])).unwrap();
    let u = ring(&[
        (0.0, 0.0),
        (10.0, 0.0),
        (10.0, 10.0),
        (7.0, 10.0),
        (7.0, 3.0),
        (3.0, 3.0),
        (3.0, 10.0),
        (0.0, 10.0),
    ]);
    let clip = MultiPolygon(vec![Polygon::new(u, vec![])]);
    let cells = check(&d, &clip);
    // The middle site's cell (3 <= x <= 7, above y = 1) meets the U in the bar only.
    assert_eq!(cells[1].0.len(), 1);
    let total: f64 = cells.iter().map(area).sum();
    assert!((total - (100.0 - 28.0)).abs() < 1e-9, "{total}");
    // A site whose cell is cut in two: the wide cell of (5, 12) above both arms.
    let d = dual_voronoi(&ring(&[(5.0, 12.0), (5.0, -5.0)])).unwrap();
    let cells = check(&d, &clip);
    assert_eq!(cells[0].0.len(), 2, "{:?}", cells[0]);
}

#[test]
fn polygon_with_hole_and_two_parts() {
    let sites = grid_sites(6, 2.0);
    let d = dual_voronoi(&sites).unwrap();
    let outer = ring(&[(-1.0, -1.0), (6.0, -1.0), (6.0, 6.0), (-1.0, 6.0)]);
    let hole = ring(&[(1.0, 1.0), (1.0, 4.0), (4.0, 4.0), (4.0, 1.0)]);
    let other = ring(&[(7.0, 7.0), (11.0, 7.5), (8.0, 11.0)]);
    let clip = MultiPolygon(vec![
        Polygon::new(outer, vec![hole]),
        Polygon::new(other, vec![]),
    ]);
    let cells = check(&d, &clip);
    // 7² − 3² for the square with its hole, 7.75 for the triangle.
    let total: f64 = cells.iter().map(area).sum();
    assert!((total - (49.0 - 9.0 + 7.75)).abs() < 1e-9, "{total}");
    // The cell of (0, 0) touches the hole at a corner only: whole.
    assert_eq!(cells[0].0.len(), 1);
    assert!(cells[0].0[0].holes.is_empty());
    assert!((area(&cells[0]) - 4.0).abs() < 1e-12);
    // The cell of (4, 4) is [3, 5]²: the hole takes [3, 4]².
    assert!((area(&cells[14]) - 3.0).abs() < 1e-12);
    // The cell of (10, 10) meets only the triangle, partly.
    let a = area(&cells[35]);
    assert!(a > 0.0 && a < 4.0, "{a}");
}

#[test]
fn boundary_along_voronoi_edges_and_through_vertices() {
    // Sites on the integer grid: cell edges on half-integer lines; the polygon's edges run
    // along them and its corners sit on Voronoi vertices.
    let d = dual_voronoi(&grid_sites(8, 1.0)).unwrap();
    let stair = ring(&[
        (0.5, 0.5),
        (6.5, 0.5),
        (6.5, 2.5),
        (4.5, 2.5),
        (4.5, 4.5),
        (2.5, 4.5),
        (2.5, 6.5),
        (0.5, 6.5),
    ]);
    let cells = check(&d, &MultiPolygon(vec![Polygon::new(stair, vec![])]));
    let full = cells
        .iter()
        .filter(|c| (area(c) - 1.0).abs() < 1e-12)
        .count();
    assert_eq!(full, 12 + 8 + 4);
    // A diagonal notch through vertices.
    let notch = ring(&[(0.5, 0.5), (6.5, 0.5), (3.5, 3.5), (6.5, 6.5), (0.5, 6.5)]);
    check(&d, &MultiPolygon(vec![Polygon::new(notch, vec![])]));
}

#[test]
fn errors_are_named() {
    let d = dual_voronoi(&grid_sites(3, 1.0)).unwrap();
    assert!(clip_cells_to_polygon(&d, &MultiPolygon::default()).is_err());
    let thin = ring(&[(0.0, 0.0), (1.0, 1.0), (0.0, 0.0)]);
    let e = clip_cells_to_polygon(&d, &MultiPolygon(vec![Polygon::new(thin, vec![])])).unwrap_err();
    assert!(e.to_string().contains("ring 0"), "{e}");
    let nan = ring(&[(0.0, 0.0), (1.0, f64::NAN), (0.0, 1.0)]);
    let e = clip_cells_to_polygon(&d, &MultiPolygon(vec![Polygon::new(nan, vec![])])).unwrap_err();
    assert!(e.to_string().contains("vertex 1"), "{e}");
}

/// A star-shaped (simple, usually non-convex) polygon around `c`.
fn star(c: (f64, f64), radii: &[f64]) -> Vec<Point2> {
    let k = radii.len();
    radii
        .iter()
        .enumerate()
        .map(|(i, r)| {
            let a = std::f64::consts::TAU * i as f64 / k as f64;
            Point2::new(c.0 + r * a.cos(), c.1 + r * a.sin())
        })
        .collect()
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(40))]

    #[test]
    fn random_sites_random_star(
        sites in prop::collection::vec((-50i32..50, -50i32..50), 1..60),
        radii in prop::collection::vec(5.0f64..60.0, 3..24),
    ) {
        let p: Vec<Point2> = sites.iter().map(|&(x, y)| Point2::new(x as f64, y as f64)).collect();
        let d = dual_voronoi(&p).unwrap();
        check(&d, &MultiPolygon(vec![Polygon::new(star((3.0, -2.0), &radii), vec![])]));
    }

    #[test]
    fn grid_sites_integer_polygon(
        k in 2usize..7,
        corners in prop::collection::vec((0i32..12, 0i32..12), 3..9),
    ) {
        // Integer corners sorted by angle around their centroid: a simple polygon unless
        // degenerate (then the boolean reading of it is still well defined).
        let mut c: Vec<Point2> = corners.iter().map(|&(x, y)| Point2::new(x as f64 / 2.0, y as f64 / 2.0)).collect();
        c.sort_by(|a, b| a.x.total_cmp(&b.x).then(a.y.total_cmp(&b.y)));
        c.dedup();
        prop_assume!(c.len() >= 3);
        let (mx, my) = (c.iter().map(|p| p.x).sum::<f64>() / c.len() as f64, c.iter().map(|p| p.y).sum::<f64>() / c.len() as f64);
        c.sort_by(|a, b| (a.y - my).atan2(a.x - mx).total_cmp(&(b.y - my).atan2(b.x - mx)));
        let poly = MultiPolygon(vec![Polygon::new(c, vec![])]);
        prop_assume!(area(&boolean(&poly, &MultiPolygon::default(), BooleanOp::Union).unwrap()) > 0.0);
        let d = dual_voronoi(&grid_sites(k, 1.0)).unwrap();
        check(&d, &poly);
    }
}
