//! Triangulation of a planar subdivision inside its bounding box (book Theorem 3.9):
//! property tests on Delaunay-based subdivisions (with edges dropped, so faces merge and
//! edges dangle), rectangle grids with overlapping collinear pieces, axis-parallel and
//! diagonal segments on a small grid (equal y, collinear runs, crossings at grid points),
//! and polygon layers with holes. Oracles: the exact verifier, and independently the exact
//! area of every face (triangles labelled with a face sum to its area) and, for layers,
//! point-in-polygon of each triangle's centroid.

mod common;
use common::exact_shoelace2;
use compgeom::dcel::{Dcel, FaceId};
use compgeom::delaunay::delaunay;
use compgeom::triangulate::{
    triangulate_segments, triangulate_subdivision, verify_subdivision_triangulation,
    SubdivisionTriangulation,
};
use compgeom::{MultiPolygon, Point2, Polygon, Segment2};
use num_rational::BigRational;
use num_traits::Zero;
use proptest::prelude::*;

fn p(x: f64, y: f64) -> Point2 {
    Point2::new(x, y)
}

/// Verify, then check every bounded face's area against the triangles labelled with it.
fn check<V, E, F>(dcel: &Dcel<V, E, F>, t: &SubdivisionTriangulation) {
    verify_subdivision_triangulation(dcel, t).unwrap_or_else(|e| panic!("{e}"));
    let mut sums = vec![BigRational::zero(); dcel.face_count()];
    for (tri, f) in t.triangles.iter().zip(&t.faces) {
        sums[f.0] += exact_shoelace2(&tri.map(|v| t.vertices[v]));
    }
    for f in dcel.face_ids().skip(1) {
        assert_eq!(
            sums[f.0],
            dcel.face_area_exact(f) * BigRational::from_integer(2.into()),
            "face {}",
            f.0
        );
    }
}

fn segments_check(segs: &[Segment2], margin: f64) {
    let dcel = Dcel::from_segments(segs).unwrap();
    let t = triangulate_segments(segs, margin).unwrap_or_else(|e| panic!("{e}: {segs:?}"));
    assert_eq!(t, triangulate_subdivision(&dcel, margin).unwrap());
    check(&dcel, &t);
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(48))]

    #[test]
    fn delaunay_subdivisions(pts in prop::collection::vec((0i32..12, 0i32..12), 3..60),
                             keep in prop::collection::vec(any::<bool>(), 200),
                             margin in prop::sample::select(vec![0.0, 0.5, 3.0])) {
        let pts: Vec<Point2> = pts.iter().map(|&(x, y)| p(x as f64, y as f64)).collect();
        let Ok(d) = delaunay(&pts) else { return Ok(()) };
        let v = d.vertices();
        let segs: Vec<Segment2> = d.edges().iter().enumerate()
            .filter(|(i, _)| keep[i % keep.len()] || i % 7 == 0)
            .map(|(_, &(a, b))| Segment2::new(v[a as usize], v[b as usize]))
            .collect();
        prop_assume!(!segs.is_empty());
        let xs: Vec<f64> = segs.iter().flat_map(|s| [s.a.x, s.b.x]).collect();
        let ys: Vec<f64> = segs.iter().flat_map(|s| [s.a.y, s.b.y]).collect();
        let flat = xs.iter().all(|&x| x == xs[0]) || ys.iter().all(|&y| y == ys[0]);
        if flat && margin == 0.0 {
            prop_assert!(triangulate_segments(&segs, margin).is_err());
        } else {
            segments_check(&segs, margin);
        }
    }

    #[test]
    fn grid_segments_with_collinear_runs(
        segs in prop::collection::vec((0i32..8, 0i32..8, 0u8..4, 1i32..5), 1..25),
        margin in prop::sample::select(vec![0.0, 1.0]),
    ) {
        // Horizontal, vertical and ±45° segments on a small grid: equal y everywhere,
        // overlapping collinear pieces, crossings at grid or half-grid points (exact f64).
        let segs: Vec<Segment2> = segs.iter().map(|&(x, y, dir, len)| {
            let (dx, dy) = [(1, 0), (0, 1), (1, 1), (1, -1)][dir as usize];
            Segment2::new(p(x as f64, y as f64), p((x + dx * len) as f64, (y + dy * len) as f64))
        }).collect();
        let xs: Vec<f64> = segs.iter().flat_map(|s| [s.a.x, s.b.x]).collect();
        let ys: Vec<f64> = segs.iter().flat_map(|s| [s.a.y, s.b.y]).collect();
        let flat = xs.iter().all(|&x| x == xs[0]) || ys.iter().all(|&y| y == ys[0]);
        prop_assume!(!(flat && margin == 0.0));
        segments_check(&segs, margin);
    }

    #[test]
    fn rectangle_grids(cols in 1usize..6, rows in 1usize..6,
                       drop in prop::collection::vec(any::<bool>(), 80),
                       margin in prop::sample::select(vec![0.0, 2.0])) {
        // The lines of a cols × rows grid as unit pieces, some dropped, plus the full
        // outer rectangle drawn again as four long segments (overlapping the pieces).
        let (w, h) = (cols as f64, rows as f64);
        let mut segs = vec![
            Segment2::new(p(0., 0.), p(w, 0.)), Segment2::new(p(w, 0.), p(w, h)),
            Segment2::new(p(w, h), p(0., h)), Segment2::new(p(0., h), p(0., 0.)),
        ];
        let mut k = 0;
        for i in 0..=cols {
            for j in 0..=rows {
                let (x, y) = (i as f64, j as f64);
                if i < cols && !drop[k % 80] { segs.push(Segment2::new(p(x, y), p(x + 1., y))); }
                if j < rows && !drop[(k + 41) % 80] { segs.push(Segment2::new(p(x, y), p(x, y + 1.))); }
                k += 1;
            }
        }
        segments_check(&segs, margin);
    }

    #[test]
    fn polygon_layers_with_holes(cells in prop::collection::btree_set((0i32..4, 0i32..4), 1..10),
                                 holes in any::<bool>(),
                                 margin in prop::sample::select(vec![0.0, 1.0])) {
        // Square polygons of side 2 on a grid of pitch 2 (neighbours share edges), each
        // with a diamond hole touching its edges' midpoints when `holes`.
        let polys: Vec<Polygon> = cells.iter().map(|&(i, j)| {
            let (x, y) = (2.0 * i as f64, 2.0 * j as f64);
            let outer = vec![p(x, y), p(x + 2., y), p(x + 2., y + 2.), p(x, y + 2.)];
            let hole = vec![p(x + 1., y + 0.5), p(x + 1.5, y + 1.), p(x + 1., y + 1.5), p(x + 0.5, y + 1.)];
            Polygon::new(outer, if holes { vec![hole] } else { vec![] })
        }).collect();
        let layer = MultiPolygon(polys.clone());
        let dcel = Dcel::from_polygons(&layer).unwrap();
        let t = triangulate_subdivision(&dcel, margin).unwrap();
        check(&dcel, &t);
        // Each triangle's label set is the polygons containing its centroid.
        for (tri, f) in t.triangles.iter().zip(&t.faces) {
            let [a, b, c] = tri.map(|v| t.vertices[v]);
            let (cx, cy) = ((a.x + b.x + c.x) / 3.0, (a.y + b.y + c.y) / 3.0);
            let inside: Vec<usize> = cells.iter().enumerate().filter(|(_, &(i, j))| {
                let (x, y) = (cx - 2.0 * i as f64, cy - 2.0 * j as f64);
                let in_square = x > 0.0 && x < 2.0 && y > 0.0 && y < 2.0;
                let in_hole = holes && (x - 1.0).abs() + (y - 1.0).abs() < 0.5;
                in_square && !in_hole
            }).map(|(k, _)| k).collect();
            prop_assert_eq!(&dcel.face(*f).data, &inside);
        }
    }
}

/// -0 and 0 are one coordinate: the sweep once ordered -0 below 0, and triangles came
/// out turned over.
#[test]
fn negative_zero_is_zero() {
    let s = |a: (f64, f64), b: (f64, f64)| Segment2::new(p(a.0, a.1), p(b.0, b.1));
    let cases = [
        vec![
            s((2.0, -0.0), (1.0, -2.0)),
            s((0.0, 0.0), (2.0, 1.0)),
            s((-2.0, -0.0), (2.0, 0.0)),
        ],
        vec![
            s((1.0, -1.0), (-2.0, 1.0)),
            s((-0.0, -2.0), (1.0, -1.0)),
            s((2.0, 0.0), (-2.0, -0.0)),
        ],
    ];
    for segs in cases {
        segments_check(&segs, 1.0);
    }
}

#[test]
fn dangling_edges_isolated_parts_and_errors() {
    let s = |a: (f64, f64), b: (f64, f64)| Segment2::new(p(a.0, a.1), p(b.0, b.1));
    // A path, a star and a lone segment: no bounded face at all, every triangle unbounded.
    let segs = [
        s((0., 0.), (1., 1.)),
        s((1., 1.), (2., 0.)),
        s((2., 0.), (3., 1.)),
        s((5., 5.), (6., 5.)),
        s((5., 5.), (5., 6.)),
        s((5., 5.), (4., 4.)),
        s((0., 5.), (1., 5.)),
    ];
    let t = triangulate_segments(&segs, 1.0).unwrap();
    check(&Dcel::from_segments(&segs).unwrap(), &t);
    assert!(t.faces.iter().all(|&f| f == FaceId::UNBOUNDED));
    // Crossing segments meet at a point that is not an f64: refused.
    let e = triangulate_segments(&[s((0., 0.), (1., 3.)), s((0., 1.), (3., 0.))], 1.0)
        .unwrap_err()
        .to_string();
    assert!(e.contains("crossing"), "{e}");
    // Crossing at a representable point is fine.
    let x = [s((0., 0.), (2., 2.)), s((0., 2.), (2., 0.))];
    let t = triangulate_segments(&x, 0.0).unwrap();
    check(&Dcel::from_segments(&x).unwrap(), &t);
    assert_eq!(t.triangles.len(), 4);
    // Margins and boxes without area.
    assert!(triangulate_segments(&x, -1.0).is_err());
    assert!(triangulate_segments(&x, f64::NAN).is_err());
    assert!(triangulate_segments(&[s((0., 0.), (3., 0.))], 0.0).is_err());
    assert!(triangulate_segments(&[], 1.0).is_err());
}
