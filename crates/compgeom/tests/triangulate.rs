//! Polygon triangulation (book chapter 3): property tests on random star-shaped polygons,
//! untangled random walks on an integer grid (many collinear and equal-y vertices), combs,
//! and polygons with holes (some touching each other or the outer ring at a vertex), with
//! the exact verifiers and an independent exact area sum as oracles.

mod common;
use common::exact_shoelace2;
use compgeom::intersect::is_simple;
use compgeom::kernel::{orient2d, Orientation};
use compgeom::triangulate::{
    art_gallery, classify_vertices, is_y_monotone, monotone_partition, triangulate,
    triangulate_monotone_polygon, verify_art_gallery, verify_triangulation, ArtGallery,
    Triangulation, VertexType,
};
use compgeom::{Error, Point2, Polygon};
use num_rational::BigRational;
use num_traits::Zero;
use proptest::prelude::*;

fn p(x: f64, y: f64) -> Point2 {
    Point2::new(x, y)
}

/// Twice the exact area of the triangles.
fn triangles_area2(t: &Triangulation) -> BigRational {
    t.triangles
        .iter()
        .map(|tri| exact_shoelace2(&tri.map(|v| t.vertices[v])))
        .fold(BigRational::zero(), |a, b| a + b)
}

/// Twice the exact area of the polygon (|outer| − Σ|holes|).
fn polygon_area2(poly: &Polygon) -> BigRational {
    let abs = |x: BigRational| if x < BigRational::zero() { -x } else { x };
    let mut a = abs(exact_shoelace2(&poly.exterior));
    for h in &poly.holes {
        a -= abs(exact_shoelace2(h));
    }
    a
}

/// Everything the oracles say about a triangulation of a valid polygon.
fn check(poly: &Polygon) -> Triangulation {
    let t = triangulate(poly).unwrap_or_else(|e| panic!("{e}: {poly:?}"));
    verify_triangulation(poly, &t).unwrap_or_else(|e| panic!("{e}: {poly:?}"));
    assert_eq!(triangles_area2(&t), polygon_area2(poly), "{poly:?}");
    if t.triangles.len() <= 120 {
        assert_interiors_disjoint(&t);
    }
    let g = art_gallery(&t);
    verify_art_gallery(&t, &g).unwrap_or_else(|e| panic!("{e}: {poly:?}"));
    check_guards(&t, &g, poly);
    // The partition's pieces are monotone and their triangulations agree in number.
    let part = monotone_partition(poly).unwrap();
    for piece in &part.pieces {
        let ring: Vec<Point2> = piece.iter().map(|&v| part.vertices[v]).collect();
        let piece = Polygon::new(ring, vec![]);
        if is_simple(&piece).unwrap() {
            assert!(is_y_monotone(&piece).unwrap(), "{piece:?}");
        }
    }
    t
}

/// Brute force, independent of the library's verifier: no two triangles share an interior
/// point. Two convex polygons have disjoint interiors iff the line through some edge of
/// one has the whole other polygon on its closed outer side (exact `orient2d`).
fn assert_interiors_disjoint(t: &Triangulation) {
    let tri = |i: usize| t.triangles[i].map(|v| t.vertices[v]);
    let separates = |a: [Point2; 3], b: [Point2; 3]| {
        (0..3).any(|s| {
            b.iter()
                .all(|&q| orient2d(a[s], a[(s + 1) % 3], q) != Orientation::CounterClockwise)
        })
    };
    for i in 0..t.triangles.len() {
        for j in i + 1..t.triangles.len() {
            let (a, b) = (tri(i), tri(j));
            assert!(
                separates(a, b) || separates(b, a),
                "triangles {i} {a:?} and {j} {b:?} overlap"
            );
        }
    }
}

/// The art-gallery guarantees, checked from the outside: every triangle has a guard at one
/// of its corners (so the guards see the polygon), guards stand at distinct points, the
/// vertices coloured with the guard colour are guards, and their number is at most
/// ⌊n/3⌋ without holes (with a proper colouring of every edge) or ⌊(n + 2h)/3⌋ with h holes.
fn check_guards(t: &Triangulation, g: &ArtGallery, poly: &Polygon) {
    let guard_points: Vec<Point2> = g.guards.iter().map(|&v| t.vertices[v]).collect();
    for (i, tri) in t.triangles.iter().enumerate() {
        assert!(
            tri.iter().any(|&v| guard_points.contains(&t.vertices[v])),
            "triangle {i} has no guard: {poly:?}"
        );
    }
    for (k, q) in guard_points.iter().enumerate() {
        assert!(!guard_points[..k].contains(q), "guard {q:?} twice");
    }
    for &v in &g.guards {
        assert_eq!(g.colors[v], g.guard_color, "guard {v}");
    }
    for (v, &c) in g.colors.iter().enumerate() {
        // (Of the visits of a point where rings touch, one may carry another colour.)
        if c == g.guard_color {
            assert!(
                guard_points.contains(&t.vertices[v]),
                "vertex {v} of the guard colour"
            );
        }
    }
    let h = t.holes();
    if h == 0 {
        assert_eq!(g.cuts, 0);
        assert!(g.guards.len() <= t.vertices.len() / 3);
        for tri in &t.triangles {
            let c = tri.map(|v| g.colors[v]);
            assert!(c[0] != c[1] && c[1] != c[2] && c[0] != c[2], "{c:?}");
        }
    } else {
        assert!(g.guards.len() <= (t.vertices.len() + 2 * h) / 3);
    }
}

/// A star-shaped polygon around the origin from angles (sorted) and radii.
fn star(angles: &[f64], radii: &[f64]) -> Polygon {
    let mut a: Vec<f64> = angles.to_vec();
    a.sort_by(f64::total_cmp);
    a.dedup();
    let ring = a
        .iter()
        .zip(radii)
        .map(|(&t, &r)| p((r * t.cos() * 64.0).round(), (r * t.sin() * 64.0).round()))
        .collect();
    Polygon::new(ring, vec![])
}

/// Proper or improper contact between edges (i, i+1) and (j, j+1) that are not adjacent.
fn touch(a: Point2, b: Point2, c: Point2, d: Point2) -> bool {
    use compgeom::kernel::segment_intersection;
    use compgeom::Segment2;
    !matches!(
        segment_intersection(Segment2::new(a, b), Segment2::new(c, d)),
        compgeom::kernel::SegmentIntersection::None
    )
}

/// A random walk through distinct grid points, untangled by 2-opt moves (bounded).
fn untangled(points: Vec<(i32, i32)>) -> Polygon {
    let mut pts: Vec<Point2> = Vec::new();
    for (x, y) in points {
        let q = p(x as f64, y as f64);
        if !pts.contains(&q) {
            pts.push(q);
        }
    }
    let n = pts.len();
    'outer: for _ in 0..200 {
        for i in 0..n {
            for j in i + 2..n {
                if i == 0 && j == n - 1 {
                    continue;
                }
                let (a, b, c, d) = (pts[i], pts[(i + 1) % n], pts[j], pts[(j + 1) % n]);
                if touch(a, b, c, d) {
                    pts[i + 1..=j].reverse();
                    continue 'outer;
                }
            }
        }
        break;
    }
    Polygon::new(pts, vec![])
}

/// Triangulate when simple; otherwise the triangulation must refuse.
fn check_or_refuse(poly: &Polygon) {
    match is_simple(poly) {
        Ok(true) => {
            check(poly);
        }
        _ => {
            // A ring touching itself at a vertex, or with a vertex inside one of its own
            // edges, is allowed (when the boundary still alternates in and out there);
            // otherwise it must be an error, never a panic or a wrong answer. Oracle: the
            // exact area of what was accepted.
            if let Ok(t) = triangulate(poly) {
                verify_triangulation(poly, &t).unwrap_or_else(|e| panic!("{e}: {poly:?}"));
                assert_eq!(triangles_area2(&t), polygon_area2(poly), "{poly:?}");
            }
        }
    }
}

/// A comb: `teeth` teeth of height `h` over a base, all tips at one height.
fn comb(teeth: usize, h: f64) -> Polygon {
    let w = 2 * teeth;
    let mut ring = vec![p(0.0, 0.0), p(w as f64, 0.0)];
    for k in (0..teeth).rev() {
        let x = (2 * k) as f64;
        ring.push(p(x + 2.0, h));
        ring.push(p(x + 1.0, 1.0));
    }
    ring.push(p(0.0, h));
    ring.dedup();
    Polygon::new(ring, vec![])
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(96))]

    #[test]
    fn random_stars(angles in prop::collection::vec(0.0f64..std::f64::consts::TAU, 3..80),
                    radii in prop::collection::vec(1.0f64..8.0, 80)) {
        check_or_refuse(&star(&angles, &radii));
    }

    #[test]
    fn grid_stars_with_collinear_runs(cells in prop::collection::vec((0i32..7, 0i32..7), 3..40)) {
        // Grid points in angular order around an off-grid centre: collinear runs and
        // equal-y vertices galore.
        let c = (3.01, 2.97);
        let mut pts: Vec<(i32, i32)> = cells;
        pts.sort_unstable();
        pts.dedup();
        pts.sort_by(|a, b| {
            let ta = (a.1 as f64 - c.1).atan2(a.0 as f64 - c.0);
            let tb = (b.1 as f64 - c.1).atan2(b.0 as f64 - c.0);
            ta.total_cmp(&tb)
        });
        let ring: Vec<Point2> = pts.iter().map(|&(x, y)| p(x as f64, y as f64)).collect();
        if ring.len() >= 3 {
            check_or_refuse(&Polygon::new(ring, vec![]));
        }
    }

    #[test]
    fn untangled_random_walks(points in prop::collection::vec((0i32..6, 0i32..6), 3..24)) {
        check_or_refuse(&untangled(points));
    }

    #[test]
    fn tangled_random_walks_are_refused_or_correct(
        points in prop::collection::vec((0i32..5, 0i32..5), 3..16)
    ) {
        // Mostly self-intersecting: an error naming edges, never a panic or a wrong answer.
        let ring: Vec<Point2> = points.iter().map(|&(x, y)| p(x as f64, y as f64)).collect();
        let poly = Polygon::new(ring, vec![]);
        if let Err(e) = triangulate(&poly) {
            let m = e.to_string();
            prop_assert!(m.contains("not simple") || m.contains("fewer than 3") || m.contains("nested"), "{}", m);
        }
        check_or_refuse(&poly);
    }

    #[test]
    fn orthogonal_grid_polygons(cells in prop::collection::btree_set((0i32..6, 0i32..6), 1..20)) {
        // The boundary of a union of unit cells, traced exactly by the boolean operations,
        // then triangulated (every vertex kept, many collinear and equal-y vertices).
        use compgeom::overlay::union_all;
        use compgeom::MultiPolygon;
        let squares: Vec<Polygon> = cells.iter().map(|&(x, y)| {
            let (x, y) = (x as f64, y as f64);
            Polygon::new(vec![p(x, y), p(x + 1.0, y), p(x + 1.0, y + 1.0), p(x, y + 1.0)], vec![])
        }).collect();
        let u = union_all(&MultiPolygon(squares)).unwrap();
        for poly in &u.0 {
            check_or_refuse(poly);
        }
    }

    #[test]
    fn combs_need_a_third_of_the_vertices(teeth in 1usize..12, h in 2.0f64..5.0) {
        let poly = comb(teeth, h.round());
        let t = check(&poly);
        let g = art_gallery(&t);
        prop_assert_eq!(poly.exterior.len(), 2 * teeth + 3);
        prop_assert!(g.guards.len() <= poly.exterior.len() / 3);
    }

    #[test]
    fn square_with_grid_holes(holes in prop::collection::btree_set((0i32..5, 0i32..5), 0..12),
                              diamonds in any::<bool>()) {
        // Outer 12 × 12 square with a vertex at every integer point of its boundary; holes
        // are unit squares (or diamonds) in the cells (2i + 1, 2j + 1): diamonds in
        // neighbouring cells touch each other at a vertex.
        let mut outer = Vec::new();
        for k in 0..12 { outer.push(p(k as f64, 0.0)); }
        for k in 0..12 { outer.push(p(12.0, k as f64)); }
        for k in 0..12 { outer.push(p(12.0 - k as f64, 12.0)); }
        for k in 0..12 { outer.push(p(0.0, 12.0 - k as f64)); }
        let rings: Vec<Vec<Point2>> = holes.iter().map(|&(i, j)| {
            let (x, y) = (2.0 * i as f64 + 1.0, 2.0 * j as f64 + 1.0);
            if diamonds {
                vec![p(x + 1.0, y), p(x + 2.0, y + 1.0), p(x + 1.0, y + 2.0), p(x, y + 1.0)]
            } else {
                vec![p(x, y), p(x, y + 1.0), p(x + 1.0, y + 1.0), p(x + 1.0, y)]
            }
        }).collect();
        let poly = Polygon::new(outer, rings);
        let t = check(&poly);
        if !diamonds {
            prop_assert_eq!(t.triangles.len(), t.vertices.len() - 2 + 2 * holes.len());
        }
    }
}

/// -0 and 0 are one coordinate: a straight run along y = 0 written with a -0 in the
/// middle was once refused as "doubles back" (the lowest vertex was found with -0 below
/// 0, at a straight angle).
#[test]
fn negative_zero_is_zero() {
    let rings = [
        vec![
            p(-2.0, 0.0),
            p(1.0, -0.0),
            p(2.0, 0.0),
            p(1.0, 2.0),
            p(-1.0, 2.0),
        ],
        vec![
            p(-1.0, 0.0),
            p(-0.0, 0.0),
            p(1.0, -0.0),
            p(2.0, 0.0),
            p(0.0, 2.0),
        ],
        vec![p(0.0, -2.0), p(-0.0, 1.0), p(0.0, 2.0), p(-2.0, 1.0)],
    ];
    for ring in rings {
        let plus: Vec<Point2> = ring.iter().map(|q| p(q.x + 0.0, q.y + 0.0)).collect();
        let t = check(&Polygon::new(ring, vec![]));
        assert_eq!(
            t.triangles.len(),
            check(&Polygon::new(plus, vec![])).triangles.len()
        );
    }
}

#[test]
fn holes_touching_the_outer_ring_and_each_other() {
    // Square 0..4 with two triangular holes touching each other at (2, 2) and the outer
    // ring at (0, 0) and (4, 4) — every touching point a vertex visited twice.
    let outer = vec![p(0., 0.), p(4., 0.), p(4., 4.), p(0., 4.)];
    let h1 = vec![p(0., 0.), p(2., 2.), p(2., 1.)];
    let h2 = vec![p(2., 2.), p(4., 4.), p(3., 2.)];
    let poly = Polygon::new(outer, vec![h1, h2]);
    let t = check(&poly);
    // The chain of holes cuts the square in two: two boundary cycles of 5 visits each,
    // 3 + 3 triangles.
    assert_eq!(t.triangles.len(), 6);
    assert_eq!(t.vertices.len(), 10);
}

#[test]
fn figure_eight_ring_is_two_pieces() {
    // A ring touching itself at (2, 2): two triangles' worth of lobes.
    let ring = vec![
        p(0., 0.),
        p(2., 2.),
        p(4., 0.),
        p(4., 4.),
        p(2., 2.),
        p(0., 4.),
    ];
    let poly = Polygon::new(ring, vec![]);
    let t = triangulate(&poly).unwrap();
    verify_triangulation(&poly, &t).unwrap();
    assert_eq!(t.triangles.len(), 2);
}

#[test]
fn crossing_rings_are_refused_by_name() {
    let bowtie = Polygon::new(vec![p(0., 0.), p(4., 4.), p(4., 0.), p(0., 4.)], vec![]);
    let e = triangulate(&bowtie).unwrap_err().to_string();
    assert!(
        e.contains("not simple") && e.contains("ring 0 edge 0") && e.contains("ring 0 edge 2"),
        "{e}"
    );
    // A hole outside the outer ring, and a hole inside another hole.
    let sq = |x: f64, y: f64, s: f64| vec![p(x, y), p(x + s, y), p(x + s, y + s), p(x, y + s)];
    let outside = Polygon::new(sq(0., 0., 4.), vec![sq(5., 1., 1.)]);
    assert!(matches!(triangulate(&outside), Err(Error::InvalidInput(m)) if m.contains("nested")));
    let nested = Polygon::new(sq(0., 0., 10.), vec![sq(1., 1., 8.), sq(3., 3., 2.)]);
    assert!(matches!(triangulate(&nested), Err(Error::InvalidInput(m)) if m.contains("nested")));
    // Rings crossing at a shared vertex.
    let crossing = Polygon::new(
        sq(0., 0., 4.),
        vec![
            vec![p(2., 2.), p(3., 1.), p(3., 3.)],
            vec![p(2., 2.), p(1., 1.), p(1., 3.)],
        ],
    );
    let outer_touch = triangulate(&crossing);
    if let Ok(t) = &outer_touch {
        verify_triangulation(&crossing, t).unwrap();
    }
    let nan = Polygon::new(vec![p(0., 0.), p(f64::NAN, 0.), p(1., 1.)], vec![]);
    assert!(matches!(triangulate(&nan), Err(Error::NonFinite { .. })));
    let flat = Polygon::new(vec![p(0., 0.), p(1., 1.), p(2., 2.)], vec![]);
    assert!(triangulate(&flat).is_err());
}

#[test]
fn vertex_types_and_monotone_fast_path() {
    // The book's Figure 3.3-like polygon: a split vertex from below, a merge from above.
    let poly = Polygon::new(
        vec![
            p(0., 0.),
            p(2., 1.),
            p(4., 0.),
            p(4., 4.),
            p(2., 3.),
            p(0., 4.),
        ],
        vec![],
    );
    let types = classify_vertices(&poly).unwrap();
    assert_eq!(types[1], VertexType::Split);
    assert_eq!(types[4], VertexType::Merge);
    assert!(!is_y_monotone(&poly).unwrap());
    assert!(triangulate_monotone_polygon(&poly).is_err());
    let part = monotone_partition(&poly).unwrap();
    // One diagonal serves both: the split vertex meets the merge vertex as helper.
    assert_eq!(part.diagonals, vec![[1, 4]]);
    assert_eq!(part.pieces.len(), 2);
    let dcel = part.to_dcel().unwrap();
    dcel.validate().unwrap();
    assert_eq!(dcel.face_count(), 3);
    // An equal-y staircase is monotone; the fast path agrees with the verifier.
    let stairs = Polygon::new(
        vec![
            p(0., 0.),
            p(3., 0.),
            p(3., 1.),
            p(2., 1.),
            p(2., 2.),
            p(1., 2.),
            p(1., 3.),
            p(0., 3.),
        ],
        vec![],
    );
    assert!(is_y_monotone(&stairs).unwrap());
    let t = triangulate_monotone_polygon(&stairs).unwrap();
    verify_triangulation(&stairs, &t).unwrap();
    assert_eq!(t, triangulate(&stairs).unwrap());
}

#[test]
fn collinear_vertices_stay_vertices() {
    // A triangle with 3 extra vertices on each side: 12 vertices, 10 triangles, none flat.
    let mut ring = Vec::new();
    for k in 0..4 {
        ring.push(p(k as f64, 0.0));
    }
    for k in 0..4 {
        ring.push(p(4.0 - k as f64, k as f64));
    }
    for k in 0..4 {
        ring.push(p(0.0, 4.0 - k as f64));
    }
    let poly = Polygon::new(ring, vec![]);
    let t = check(&poly);
    assert_eq!(t.triangles.len(), 10);
}

#[test]
fn hole_vertex_inside_another_rings_edge() {
    let square = vec![p(0., 0.), p(4., 0.), p(4., 4.), p(0., 4.)];
    // A hole touching the bottom edge at (2, 0), a vertex of the hole only: the edge is
    // split there, one boundary cycle of 4 + 1 + 3 visits, 6 triangles.
    let poly = Polygon::new(square.clone(), vec![vec![p(2., 0.), p(3., 1.), p(1., 1.)]]);
    let t = check(&poly);
    assert_eq!(t.vertices.len(), 8);
    assert_eq!(t.triangles.len(), 6);
    assert!(t.vertices[..5].contains(&p(2., 0.)), "{:?}", t.vertices);
    // A hole touching another hole's edge inside it, and that hole touching the outer
    // ring's edge inside it.
    let h1 = vec![p(1., 1.), p(3., 1.), p(3., 2.), p(1., 2.)];
    let h2 = vec![p(2., 2.), p(2.5, 3.), p(1.5, 3.)];
    let h3 = vec![p(3.5, 2.), p(4., 3.), p(3.5, 3.)];
    let poly = Polygon::new(square.clone(), vec![h1, h2, h3]);
    check(&poly);
    // Holes sharing a stretch of edge with the outer ring and with each other: the shared
    // stretches bound no part of the polygon.
    let cell = |x: f64, y: f64| vec![p(x, y), p(x + 1., y), p(x + 1., y + 1.), p(x, y + 1.)];
    let poly = Polygon::new(
        square.clone(),
        vec![cell(0., 0.), cell(1., 0.), cell(2., 2.), cell(2.5, 1.)],
    );
    let t = check(&poly);
    assert!(!t.triangles.is_empty());
}

#[test]
fn genuinely_invalid_contacts_are_still_refused() {
    let square = vec![p(0., 0.), p(4., 0.), p(4., 4.), p(0., 4.)];
    let cell = |x: f64, y: f64| vec![p(x, y), p(x + 1., y), p(x + 1., y + 1.), p(x, y + 1.)];
    // The same hole twice: a stretch covered twice the same way.
    let twice = Polygon::new(square.clone(), vec![cell(1., 1.), cell(1., 1.)]);
    assert!(triangulate(&twice).is_err());
    // A hole crossing the outer ring through a vertex inside its edge.
    let through = Polygon::new(square.clone(), vec![vec![p(2., -1.), p(3., 1.), p(1., 1.)]]);
    let e = triangulate(&through).unwrap_err().to_string();
    assert!(e.contains("not simple"), "{e}");
    // A row of holes cutting the square in two is two polygons, not one.
    let cut = Polygon::new(
        square,
        vec![cell(0., 1.), cell(1., 1.), cell(2., 1.), cell(3., 1.)],
    );
    assert!(triangulate(&cut).is_err());
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(64))]

    #[test]
    fn holes_sharing_edges_and_touching_inside_edges(
        cells in prop::collection::btree_set((0i32..5, 0i32..3), 0..12),
        shifts in prop::collection::vec(any::<bool>(), 3),
        dense in any::<bool>(),
    ) {
        // A 6 × 6 square (corners only, or a vertex at every integer boundary point); unit
        // square holes in rows 0, 2 and 4, each row shifted right by ½ or not: holes share
        // edges with each other and with the outer ring, and shifted corners land inside
        // other edges. Rows 1, 3 and 5 and column 5 stay free, so the polygon is one
        // connected region: it must be accepted, with the exact area.
        let mut outer = Vec::new();
        let steps = if dense { 6 } else { 1 };
        let d = 6.0 / steps as f64;
        for k in 0..steps { outer.push(p(k as f64 * d, 0.0)); }
        for k in 0..steps { outer.push(p(6.0, k as f64 * d)); }
        for k in 0..steps { outer.push(p(6.0 - k as f64 * d, 6.0)); }
        for k in 0..steps { outer.push(p(0.0, 6.0 - k as f64 * d)); }
        let holes: Vec<Vec<Point2>> = cells.iter().map(|&(i, j)| {
            let x = i as f64 + if shifts[j as usize] { 0.5 } else { 0.0 };
            let y = 2.0 * j as f64;
            vec![p(x, y), p(x, y + 1.0), p(x + 1.0, y + 1.0), p(x + 1.0, y)]
        }).collect();
        let poly = Polygon::new(outer, holes);
        let t = check(&poly);
        prop_assert_eq!(triangles_area2(&t), BigRational::from_integer((2 * (36 - cells.len() as i64)).into()));
    }
}

#[test]
fn guards_with_holes_show_the_guard_colour_and_stand_once_per_point() {
    // Two triangular holes touching each other at (7, 5), one touching the outer ring at
    // (0, 5): the dual graph has two independent cycles, so the colouring is cut open along
    // two diagonals and some vertices carry two colours.
    let outer = vec![p(0., 0.), p(10., 0.), p(10., 10.), p(0., 10.)];
    let h1 = vec![p(0., 5.), p(3., 4.), p(3., 6.)];
    let h2 = vec![p(5., 5.), p(7., 5.), p(6., 7.)];
    let h3 = vec![p(7., 5.), p(9., 4.), p(9., 6.)];
    let poly = Polygon::new(outer, vec![h1, h2, h3]);
    let t = check(&poly);
    let g = art_gallery(&t);
    assert!(g.cuts > 0);
    // A vertex carrying the guard colour on any corner shows it.
    for (tri, c) in t.triangles.iter().zip(&g.corner_colors) {
        for s in 0..3 {
            if c[s] == g.guard_color {
                assert_eq!(g.colors[tri[s]], g.guard_color);
            }
        }
    }
    // A corrupted answer is caught by the verifier: a guard of the wrong colour, the same
    // point twice, a triangle without a guard.
    let mut bad = g.clone();
    bad.colors[bad.guards[0]] = (bad.guard_color + 1) % 3;
    assert!(verify_art_gallery(&t, &bad).is_err());
    let mut bad = g.clone();
    let first = bad.guards[0];
    if let Some(twin) =
        (0..t.vertices.len()).find(|&v| v != first && t.vertices[v] == t.vertices[first])
    {
        bad.guards.push(twin);
        bad.colors[twin] = bad.guard_color;
        assert!(verify_art_gallery(&t, &bad).is_err());
    }
    let mut bad = g.clone();
    bad.guards.clear();
    assert!(verify_art_gallery(&t, &bad).is_err());
}
