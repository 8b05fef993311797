//! Point location (chapter 6) against brute-force exact oracles: point-in-polygon with
//! boundary detection for subdivisions, "lowest segment above / highest below" in the
//! sheared order for the raw trapezoidal map. Subdivisions: Delaunay triangulations of
//! random points on small integer grids (many equal x), random rectangle grids, random
//! polygon layers with shared edges, holes and T-junctions; queries on a half-integer
//! grid (exactly on edges and at vertices) and at random.
use compgeom::dcel::{FaceId, HalfEdgeId};
use compgeom::delaunay::delaunay;
use compgeom::kernel::{orient2d, orient_exact, ExactPoint, Orientation};
use compgeom::locate::{
    check_interior_disjoint_segments, check_no_crossings, polygons_at, Location, MapHit,
    PointLocator, SlabLocator, TrapezoidalMap,
};
use compgeom::overlay::overlay_polygons;
use compgeom::{MultiPolygon, Point2, Polygon, Segment2};
use proptest::prelude::*;
use std::cmp::Ordering;

fn p(x: f64, y: f64) -> Point2 {
    Point2::new(x, y)
}

fn lex(a: Point2, b: Point2) -> Ordering {
    a.x.partial_cmp(&b.x)
        .unwrap()
        .then(a.y.partial_cmp(&b.y).unwrap())
}

/// Exact: is q on the closed segment ab?
fn on_segment(q: Point2, a: Point2, b: Point2) -> bool {
    orient2d(a, b, q) == Orientation::Collinear
        && q.x >= a.x.min(b.x)
        && q.x <= a.x.max(b.x)
        && q.y >= a.y.min(b.y)
        && q.y <= a.y.max(b.y)
}

/// Exact even-odd containment of q in a ring, q not on the ring (crossing number of the
/// rightward horizontal ray, half-open rule on edge endpoints).
fn in_ring(q: Point2, ring: &[Point2]) -> bool {
    let mut inside = false;
    for i in 0..ring.len() {
        let (a, b) = (ring[i], ring[(i + 1) % ring.len()]);
        if (a.y > q.y) != (b.y > q.y) {
            // Does the edge cross the ray to the right of q?
            let o = orient2d(a, b, q);
            let right = if b.y > a.y {
                o == Orientation::CounterClockwise
            } else {
                o == Orientation::Clockwise
            };
            if right {
                inside = !inside;
            }
        }
    }
    inside
}

/// The brute-force answer for a polygon layer: (kind, polygons whose closed region holds q).
fn brute(polys: &MultiPolygon, q: Point2) -> (&'static str, Vec<usize>) {
    let mut kind = "face";
    let mut out = Vec::new();
    for (i, poly) in polys.0.iter().enumerate() {
        let mut on = false;
        let mut inside = false;
        for ring in poly.rings() {
            for j in 0..ring.len() {
                let (a, b) = (ring[j], ring[(j + 1) % ring.len()]);
                if a == q {
                    kind = "vertex";
                    on = true;
                } else if on_segment(q, a, b) {
                    if kind == "face" {
                        kind = "edge";
                    }
                    on = true;
                }
            }
            if in_ring(q, ring) {
                inside = !inside;
            }
        }
        if on || inside {
            out.push(i);
        }
    }
    (kind, out)
}

fn kind(l: Location) -> &'static str {
    match l {
        Location::Face(_) => "face",
        Location::Edge(_) => "edge",
        Location::Vertex(_) => "vertex",
    }
}

/// Check a layer at every query: the kind of location and the polygons containing it.
fn check_layer(polys: &MultiPolygon, queries: &[Point2], seed: u64) {
    let (loc, dcel) = PointLocator::from_polygons(polys).unwrap();
    loc.map().validate().unwrap();
    let seeded =
        PointLocator::from_dcel_with_seed(&dcel, seed).expect("the same subdivision, reseeded");
    seeded.map().validate().unwrap();
    let all = seeded.locate_all(queries).unwrap();
    // The slab method gives the same answers (checked against brute force below).
    let slab = SlabLocator::from_dcel(&dcel).unwrap();
    assert_eq!(slab.locate_all(queries).unwrap(), all);
    for (i, &q) in queries.iter().enumerate() {
        let got = loc.locate(q).unwrap();
        assert_eq!(got, all[i], "seeds disagree at {q:?}");
        let (k, want) = brute(polys, q);
        assert_eq!(kind(got), k, "kind at {q:?}");
        assert_eq!(polygons_at(&dcel, got), want, "polygons at {q:?}");
        if let Location::Vertex(v) = got {
            assert_eq!(dcel.vertex(v).approx, q);
        }
        if let Location::Edge(h) = got {
            let (a, b) = (
                dcel.vertex(dcel.half_edge(h).origin).approx,
                dcel.vertex(dcel.destination(h)).approx,
            );
            assert!(on_segment(q, a, b) && q != a && q != b);
            assert_eq!(
                lex(a, b),
                Ordering::Less,
                "edge half-edge runs left to right"
            );
        }
    }
}

/// Queries on the half-integer grid covering [lo, hi]² plus a margin.
fn grid_queries(lo: f64, hi: f64) -> Vec<Point2> {
    let mut q = Vec::new();
    let mut x = lo - 1.0;
    while x <= hi + 1.0 {
        let mut y = lo - 1.0;
        while y <= hi + 1.0 {
            q.push(p(x, y));
            y += 0.5;
        }
        x += 0.5;
    }
    q
}

fn triangles_layer(pts: &[Point2]) -> Option<MultiPolygon> {
    let t = delaunay(pts).ok()?;
    let v = t.vertices();
    let polys: Vec<Polygon> = t
        .triangles()
        .iter()
        .map(|tr| Polygon::new(tr.iter().map(|&i| v[i as usize]).collect(), vec![]))
        .collect();
    (!polys.is_empty()).then_some(MultiPolygon(polys))
}

fn grid_points(max: u32, n: usize) -> impl Strategy<Value = Vec<Point2>> {
    prop::collection::vec((0..=max, 0..=max), n..=n)
        .prop_map(|v| v.into_iter().map(|(x, y)| p(x as f64, y as f64)).collect())
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(40))]

    /// Delaunay triangulations of points on a small grid: many equal x, collinear runs,
    /// duplicates; every half-integer query (vertices, edge midpoints, interiors).
    #[test]
    fn delaunay_triangulations(pts in grid_points(8, 24), seed in any::<u64>()) {
        if let Some(layer) = triangles_layer(&pts) {
            check_layer(&layer, &grid_queries(0.0, 8.0), seed);
        }
    }

    /// Random rectangle grids (random cut positions, random cells left out).
    #[test]
    fn rectangle_grids(
        xs in prop::collection::btree_set(0u32..20, 2..7),
        ys in prop::collection::btree_set(0u32..20, 2..7),
        keep in prop::collection::vec(any::<bool>(), 36),
        seed in any::<u64>(),
    ) {
        let xs: Vec<f64> = xs.into_iter().map(f64::from).collect();
        let ys: Vec<f64> = ys.into_iter().map(f64::from).collect();
        let mut polys = Vec::new();
        for i in 0..xs.len() - 1 {
            for j in 0..ys.len() - 1 {
                if keep[(i * 6 + j) % keep.len()] {
                    let (x0, x1, y0, y1) = (xs[i], xs[i + 1], ys[j], ys[j + 1]);
                    polys.push(Polygon::new(vec![p(x0, y0), p(x1, y0), p(x1, y1), p(x0, y1)], vec![]));
                }
            }
        }
        if !polys.is_empty() {
            check_layer(&MultiPolygon(polys), &grid_queries(0.0, 19.0), seed);
        }
    }

    /// Random polygon layers: in each cell of a 3×3 grid of 4×4 cells, a random polygon
    /// with corners on the cell (so neighbours share edges, touch at vertices, or meet in
    /// T-junctions), some with a hole holding another polygon.
    #[test]
    fn polygon_layers(cells in prop::collection::vec((0u8..6, 0u32..=4, 0u32..=4), 9), seed in any::<u64>()) {
        let mut polys = Vec::new();
        for (c, &(shape, a, b)) in cells.iter().enumerate() {
            let (ox, oy) = (4.0 * (c % 3) as f64, 4.0 * (c / 3) as f64);
            let q = |x: f64, y: f64| p(ox + x, oy + y);
            let (a, b) = (f64::from(a), f64::from(b));
            match shape {
                0 => {}
                1 => polys.push(Polygon::new(vec![q(0., 0.), q(4., 0.), q(4., 4.), q(0., 4.)], vec![])),
                2 => polys.push(Polygon::new(vec![q(0., 0.), q(4., 0.), q(a, 4.)], vec![])),
                3 if orient2d(q(0., b), q(a, 0.), q(4., 4.)) != Orientation::Collinear => {
                    polys.push(Polygon::new(vec![q(0., b), q(a, 0.), q(4., 4.)], vec![]))
                }
                3 => {}
                4 => {
                    // A square with a hole, and a triangle in the hole touching it.
                    polys.push(Polygon::new(
                        vec![q(0., 0.), q(4., 0.), q(4., 4.), q(0., 4.)],
                        vec![vec![q(1., 1.), q(1., 3.), q(3., 3.), q(3., 1.)]],
                    ));
                    polys.push(Polygon::new(vec![q(1., 1.), q(3., 1.), q(2., 3.)], vec![]));
                }
                _ => polys.push(Polygon::new(vec![q(0., 0.), q(2., 0.), q(4., 0.), q(4., 2.), q(0., 4.)], vec![])),
            }
        }
        if !polys.is_empty() {
            check_layer(&MultiPolygon(polys), &grid_queries(0.0, 12.0), seed);
        }
    }

    /// The raw map of interior-disjoint segments (Delaunay edges: shared endpoints, equal
    /// x, vertical edges) against the brute-force segments above and below each query.
    #[test]
    fn trapezoidal_map_vs_brute_force(
        pts in grid_points(6, 16),
        seed in any::<u64>(),
        scale in prop::sample::select(vec![1.0, 0.1, 1e-300, 1e300, 3.0e-320]),
    ) {
        // Scaled copies: tiny (subnormal) and huge coordinates exercise the exact fallback.
        let pts: Vec<Point2> = pts.iter().map(|q| p(q.x * scale, q.y * scale)).collect();
        let Ok(t) = delaunay(&pts) else { return Ok(()) };
        let v = t.vertices();
        let segs: Vec<Segment2> = t.edges().iter().map(|&(a, b)| Segment2::new(v[a as usize], v[b as usize])).collect();
        let map = TrapezoidalMap::with_seed(&segs, seed).unwrap();
        map.validate().unwrap();
        prop_assert!(map.trapezoid_count() <= 3 * segs.len() + 1);
        for q in grid_queries(0.0, 6.0) {
            check_map_query(&map, &segs, p(q.x * scale, q.y * scale));
        }
    }
}

/// Is segment s (left-to-right endpoints) spanning q in the sheared order?
fn spans(s: Segment2, q: Point2) -> bool {
    lex(s.a, q) == Ordering::Less && lex(q, s.b) == Ordering::Less
}

fn sorted(s: Segment2) -> Segment2 {
    if lex(s.a, s.b) == Ordering::Greater {
        Segment2::new(s.b, s.a)
    } else {
        s
    }
}

/// In the sheared order, is segment a below segment b where both span a common x?
fn below(a: Segment2, b: Segment2) -> bool {
    let side = |s: Segment2, p: Point2, alt: Point2| match orient2d(s.a, s.b, p) {
        Orientation::Collinear => orient2d(s.a, s.b, alt),
        o => o,
    };
    if lex(b.a, a.a) != Ordering::Greater {
        // a starts within b's range.
        side(b, a.a, a.b) == Orientation::Clockwise
    } else {
        side(a, b.a, b.b) == Orientation::CounterClockwise
    }
}

fn check_map_query(map: &TrapezoidalMap, segs: &[Segment2], q: Point2) {
    let hit = map.locate(q).unwrap();
    let on: Vec<usize> = (0..segs.len())
        .filter(|&i| on_segment(q, segs[i].a, segs[i].b))
        .collect();
    let is_vertex = segs.iter().any(|s| s.a == q || s.b == q);
    match hit {
        MapHit::Vertex(v) => {
            assert!(is_vertex, "{q:?} reported as a vertex");
            assert_eq!(map.vertices()[v], q);
        }
        MapHit::Segment(i) => {
            assert!(
                !is_vertex && on.contains(&i),
                "{q:?} not inside segment {i}"
            );
        }
        MapHit::Trapezoid(t) => {
            assert!(on.is_empty(), "{q:?} is on segments {on:?}");
            let tr = map.trapezoid(t);
            let sheared: Vec<Segment2> = segs.iter().map(|&s| sorted(s)).collect();
            let spanning: Vec<usize> = (0..segs.len()).filter(|&i| spans(sheared[i], q)).collect();
            let above = spanning
                .iter()
                .copied()
                .filter(|&i| orient2d(sheared[i].a, sheared[i].b, q) == Orientation::Clockwise)
                .min_by(|&a, &b| {
                    if below(sheared[a], sheared[b]) {
                        Ordering::Less
                    } else {
                        Ordering::Greater
                    }
                });
            let under = spanning
                .iter()
                .copied()
                .filter(|&i| {
                    orient2d(sheared[i].a, sheared[i].b, q) == Orientation::CounterClockwise
                })
                .max_by(|&a, &b| {
                    if below(sheared[a], sheared[b]) {
                        Ordering::Less
                    } else {
                        Ordering::Greater
                    }
                });
            assert_eq!(tr.top, above, "top of the trapezoid of {q:?}");
            assert_eq!(tr.bottom, under, "bottom of the trapezoid of {q:?}");
            if let Some(l) = tr.left {
                assert_eq!(lex(map.vertices()[l], q), Ordering::Less);
            }
            if let Some(r) = tr.right {
                assert_eq!(lex(q, map.vertices()[r]), Ordering::Less);
            }
        }
    }
}

#[test]
fn equal_x_and_vertical_segments() {
    let s = |a: (f64, f64), b: (f64, f64)| Segment2::new(a.into(), b.into());
    // A vertical fan: verticals stacked at x = 1, segments leaving their ends.
    let segs = vec![
        s((1., 0.), (1., 1.)),
        s((1., 1.), (1., 2.)),
        s((1., 2.), (1., 3.)),
        s((1., 0.), (3., 0.)),
        s((1., 1.), (3., 1.)),
        s((1., 3.), (3., 3.)),
        s((0., 1.), (1., 1.)),
        s((3., 0.), (3., 1.)),
        s((3., 1.), (3., 3.)),
        s((1., 2.), (2., 2.)),
    ];
    for seed in 0..30 {
        let map = TrapezoidalMap::with_seed(&segs, seed).unwrap();
        map.validate().unwrap();
        for q in grid_queries(0.0, 3.0) {
            check_map_query(&map, &segs, q);
        }
    }
}

#[test]
fn crossing_input_is_an_error_naming_the_segments() {
    let s = |a: (f64, f64), b: (f64, f64)| Segment2::new(a.into(), b.into());
    let segs = [
        s((0., 0.), (4., 0.)),
        s((0., 1.), (4., 1.)),
        s((1., -1.), (2., 5.)),
    ];
    let e = TrapezoidalMap::new(&segs).unwrap_err().to_string();
    assert!(
        e.contains("segments 0 and 2") || e.contains("segments 1 and 2"),
        "{e}"
    );
    let e = PointLocator::from_segments(&segs).unwrap_err().to_string();
    assert!(e.contains("and 2"), "{e}");
    // A T-junction is not interior-disjoint, but the subdivision builders accept it.
    let t = [s((0., 0.), (4., 0.)), s((2., 0.), (2., 3.))];
    assert!(check_interior_disjoint_segments(&t).is_err());
    assert!(check_no_crossings(&t).is_ok());
    let (loc, d) = PointLocator::from_segments(&t).unwrap();
    assert!(
        matches!(loc.locate(p(2., 0.)).unwrap(), Location::Vertex(v) if d.vertex(v).approx == p(2., 0.))
    );
    // Crossing polygons are named as polygons.
    let sq = |o: f64| {
        Polygon::new(
            vec![p(o, o), p(o + 2., o), p(o + 2., o + 2.), p(o, o + 2.)],
            vec![],
        )
    };
    let e = PointLocator::from_polygons(&MultiPolygon(vec![sq(0.), sq(5.), sq(1.)]))
        .unwrap_err()
        .to_string();
    assert!(e.contains("polygons 0 and 2"), "{e}");
    // Non-finite input and queries.
    assert!(TrapezoidalMap::new(&[s((0., 0.), (f64::NAN, 1.))]).is_err());
    let map = TrapezoidalMap::new(&segs[..2]).unwrap();
    assert!(map.locate(p(f64::INFINITY, 0.)).is_err());
    let e = loc
        .locate_all(&[p(0., 0.), p(0., f64::NAN)])
        .unwrap_err()
        .to_string();
    assert!(e.contains("query point 1"), "{e}");
}

#[test]
fn duplicates_and_zero_length_segments() {
    let s = |a: (f64, f64), b: (f64, f64)| Segment2::new(a.into(), b.into());
    let segs = [
        s((0., 0.), (2., 0.)),
        s((2., 0.), (0., 0.)),
        s((5., 5.), (5., 5.)),
    ];
    let map = TrapezoidalMap::new(&segs).unwrap();
    assert_eq!(map.segment_count(), 1);
    assert_eq!(map.locate(p(1., 0.)).unwrap(), MapHit::Segment(0));
    assert!(matches!(
        map.locate(p(5., 5.)).unwrap(),
        MapHit::Trapezoid(_)
    ));
}

#[test]
fn empty_map_is_one_unbounded_face() {
    let map = TrapezoidalMap::new(&[]).unwrap();
    assert_eq!(map.trapezoid_count(), 1);
    assert_eq!(map.locate(p(1., 2.)).unwrap(), MapHit::Trapezoid(0));
    let (loc, _) = PointLocator::from_segments(&[]).unwrap();
    assert_eq!(
        loc.locate(p(0., 0.)).unwrap(),
        Location::Face(FaceId::UNBOUNDED)
    );
}

#[test]
fn default_seed_is_deterministic_and_seeds_differ() {
    let pts: Vec<Point2> = (0..400)
        .map(|i| p(((i * 7919) % 401) as f64, ((i * 104_729) % 397) as f64))
        .collect();
    let t = delaunay(&pts).unwrap();
    let v = t.vertices();
    let segs: Vec<Segment2> = t
        .edges()
        .iter()
        .map(|&(a, b)| Segment2::new(v[a as usize], v[b as usize]))
        .collect();
    let a = TrapezoidalMap::new(&segs).unwrap();
    let b = TrapezoidalMap::new(&segs).unwrap();
    assert_eq!(a.stats(), b.stats());
    let c = TrapezoidalMap::with_seed(&segs, 12345).unwrap();
    assert_eq!(
        a.trapezoid_count(),
        c.trapezoid_count(),
        "the map does not depend on the order"
    );
    assert_ne!(a.stats(), c.stats(), "the search structure does");
}

/// Random orders give a search structure of expected O(n) size and O(log n) depth
/// (Theorem 6.8): check generous bounds over several seeds and sizes.
#[test]
fn dag_size_and_depth_are_linear_and_logarithmic() {
    for (n, seeds) in [(200usize, 6u64), (2000, 4), (12000, 2)] {
        // Points on a grid with many equal x: a Delaunay triangulation's edges.
        let mut state = 0x1234_5678_u64 ^ n as u64;
        let mut next = move || {
            state = state
                .wrapping_mul(6_364_136_223_846_793_005)
                .wrapping_add(1_442_695_040_888_963_407);
            (state >> 33) as f64
        };
        let side = (n as f64).sqrt() as u64 * 4;
        let pts: Vec<Point2> = (0..n)
            .map(|_| p((next() as u64 % side) as f64, (next() as u64 % side) as f64))
            .collect();
        let t = delaunay(&pts).unwrap();
        let v = t.vertices();
        let segs: Vec<Segment2> = t
            .edges()
            .iter()
            .map(|&(a, b)| Segment2::new(v[a as usize], v[b as usize]))
            .collect();
        let m = segs.len() as f64;
        for seed in 0..seeds {
            let map = TrapezoidalMap::with_seed(&segs, seed).unwrap();
            let st = map.stats();
            assert!(st.trapezoids <= 3 * segs.len() + 1);
            assert!(st.x_nodes + st.y_nodes + st.trapezoids == st.nodes);
            assert!(
                (st.nodes as f64) < 12.0 * m + 10.0,
                "size {} for {m} segments",
                st.nodes
            );
            let bound = 12.0 * (m + 1.0).ln() + 10.0;
            assert!(
                (st.depth as f64) < bound,
                "depth {} for {m} segments (bound {bound})",
                st.depth
            );
        }
    }
}

/// Large enough for the search to start from the grid of cells (at least 64 segments):
/// points on an integer grid (equal x everywhere, cell bounds through vertices), queries
/// on the half-integer grid, every answer against brute force; and a polygon layer.
#[test]
fn grid_started_queries_match_brute_force() {
    let mut state = 99u64;
    let mut next = move |m: u64| {
        state = state
            .wrapping_mul(6_364_136_223_846_793_005)
            .wrapping_add(1_442_695_040_888_963_407);
        ((state >> 33) % m) as f64
    };
    let pts: Vec<Point2> = (0..160).map(|_| p(next(21), next(13))).collect();
    let t = delaunay(&pts).unwrap();
    let v = t.vertices();
    let segs: Vec<Segment2> = t
        .edges()
        .iter()
        .map(|&(a, b)| Segment2::new(v[a as usize], v[b as usize]))
        .collect();
    assert!(segs.len() >= 64);
    for seed in [1, 2] {
        let map = TrapezoidalMap::with_seed(&segs, seed).unwrap();
        map.validate().unwrap();
        for q in grid_queries(0.0, 20.0) {
            check_map_query(&map, &segs, q);
        }
    }
    let layer = triangles_layer(&pts).unwrap();
    let mut queries = grid_queries(0.0, 20.0);
    queries.extend((0..2000).map(|_| p(next(2100) / 100.0, next(1300) / 100.0)));
    check_layer(&layer, &queries, 7);
}

/// Brute-force location in a subdivision whose vertices may be constructed: the vertex
/// equal to q, else the edge (index) whose relative interior holds q, else `None` (in a
/// face). Exact, over every vertex and edge.
fn brute_dcel<V, E, F>(d: &compgeom::dcel::Dcel<V, E, F>, q: Point2) -> Option<Location> {
    let qe = ExactPoint::Input(q);
    for v in d.vertex_ids() {
        if d.vertex(v).point.compare_xy(&qe) == Ordering::Equal {
            return Some(Location::Vertex(v));
        }
    }
    for e in 0..d.edge_count() {
        let h = HalfEdgeId(2 * e);
        let (a, b) = (d.origin_point(h), d.origin_point(d.twin(h)));
        let (lo, hi) = if a.compare_xy(b) == Ordering::Less {
            (a, b)
        } else {
            (b, a)
        };
        if orient_exact(a, b, &qe) == Orientation::Collinear
            && lo.compare_xy(&qe) == Ordering::Less
            && qe.compare_xy(hi) == Ordering::Less
        {
            return Some(Location::Edge(h));
        }
    }
    None
}

fn triangle_layer(tris: &[[(u8, u8); 3]]) -> MultiPolygon {
    MultiPolygon(
        tris.iter()
            .filter(|t| {
                let [a, b, c] = t.map(|(x, y)| p(x as f64, y as f64));
                orient2d(a, b, c) != Orientation::Collinear
            })
            .map(|t| {
                Polygon::new(
                    t.iter().map(|&(x, y)| p(x as f64, y as f64)).collect(),
                    vec![],
                )
            })
            .collect(),
    )
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(24))]

    /// Location in an overlay of two layers of crossing triangles, whose vertices are
    /// mostly constructed crossings: against brute force over the overlay's vertices and
    /// edges, and point-in-polygon over both input layers for the faces. Queries on the
    /// half-integer grid, at every vertex (rounded) and at random.
    #[test]
    fn overlay_results_with_constructed_vertices(
        a in prop::collection::vec(prop::array::uniform3((0u8..=8, 0u8..=8)), 1..5),
        b in prop::collection::vec(prop::array::uniform3((0u8..=8, 0u8..=8)), 1..5),
        rnd in prop::collection::vec((0.0f64..8.0, 0.0f64..8.0), 40),
        seed in any::<u64>(),
    ) {
        let (la, lb) = (triangle_layer(&a), triangle_layer(&b));
        let o = overlay_polygons(&la, &lb).unwrap();
        let loc = PointLocator::from_dcel_with_seed(&o, seed).unwrap();
        loc.map().validate().unwrap();
        let mut queries = grid_queries(0.0, 8.0);
        queries.extend(o.vertex_ids().map(|v| o.vertex(v).approx));
        queries.extend(rnd.iter().map(|&(x, y)| p(x, y)));
        let all = loc.locate_all(&queries).unwrap();
        let slab = SlabLocator::from_dcel(&o).unwrap();
        for (&q, &got) in queries.iter().zip(&all) {
            prop_assert_eq!(got, loc.locate(q).unwrap());
            prop_assert_eq!(got, slab.locate(q).unwrap());
            match (brute_dcel(&o, q), got) {
                (Some(Location::Vertex(v)), Location::Vertex(w)) => prop_assert_eq!(v, w),
                (Some(Location::Edge(h)), Location::Edge(g)) => {
                    prop_assert_eq!(h.0 / 2, g.0 / 2, "edge at {:?}", q);
                    // The reported half-edge runs left to right.
                    let (s, t) = (o.origin_point(g), o.origin_point(o.twin(g)));
                    prop_assert_eq!(s.compare_xy(t), Ordering::Less);
                }
                (None, Location::Face(f)) => {
                    let (ka, wa) = brute(&la, q);
                    let (kb, wb) = brute(&lb, q);
                    prop_assert_eq!((ka, kb), ("face", "face"));
                    prop_assert_eq!(&o.face(f).data, &(wa, wb), "labels at {:?}", q);
                }
                (want, got) => prop_assert!(false, "at {:?}: want {:?}, got {:?}", q, want, got),
            }
        }
    }
}

/// A larger overlay (hundreds of edges, so the query grid is used, and exact nodes meet
/// the grid's box tests) against the same brute force.
#[test]
fn large_overlay_with_constructed_vertices() {
    let mut s = 0x2545_F491_4F6C_DD1Du64;
    let mut next = |m: u64| {
        s ^= s << 13;
        s ^= s >> 7;
        s ^= s << 17;
        (s % m) as u8
    };
    let mut layer = || -> Vec<[(u8, u8); 3]> {
        (0..14)
            .map(|_| {
                [
                    (next(30), next(30)),
                    (next(30), next(30)),
                    (next(30), next(30)),
                ]
            })
            .collect()
    };
    let (la, lb) = (triangle_layer(&layer()), triangle_layer(&layer()));
    let o = overlay_polygons(&la, &lb).unwrap();
    assert!(o.edge_count() > 200, "{}", o.edge_count());
    let loc = PointLocator::from_dcel(&o).unwrap();
    loc.map().validate().unwrap();
    let mut queries = grid_queries(0.0, 30.0);
    queries.extend(o.vertex_ids().map(|v| o.vertex(v).approx));
    let all = loc.locate_all(&queries).unwrap();
    assert_eq!(
        SlabLocator::from_dcel(&o)
            .unwrap()
            .locate_all(&queries)
            .unwrap(),
        all
    );
    let mut constructed_hits = 0;
    for (&q, &got) in queries.iter().zip(&all) {
        match (brute_dcel(&o, q), got) {
            (Some(Location::Vertex(v)), Location::Vertex(w)) => {
                assert_eq!(v, w);
                if matches!(o.vertex(v).point, ExactPoint::Crossing(_)) {
                    constructed_hits += 1;
                }
            }
            (Some(Location::Edge(h)), Location::Edge(g)) => assert_eq!(h.0 / 2, g.0 / 2),
            (None, Location::Face(f)) => {
                let (wa, wb) = (brute(&la, q).1, brute(&lb, q).1);
                assert_eq!(o.face(f).data, (wa, wb), "labels at {q:?}");
            }
            (want, got) => panic!("at {q:?}: want {want:?}, got {got:?}"),
        }
    }
    assert!(
        constructed_hits > 0,
        "no query hit a constructed vertex exactly"
    );
}
