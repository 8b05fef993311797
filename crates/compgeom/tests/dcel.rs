//! DCEL builders: counts, invariants (validate after every build), Euler, hole linking.
use compgeom::dcel::{Dcel, FaceId, HalfEdgeId, VertexId};
use compgeom::{MultiPolygon, Point2, Polygon, Segment2};
use num_rational::BigRational;
use num_traits::Zero;
use proptest::prelude::*;

fn s(a: (f64, f64), b: (f64, f64)) -> Segment2 {
    Segment2::new(a.into(), b.into())
}

fn square(x: f64, y: f64, w: f64) -> Vec<Point2> {
    vec![
        Point2::new(x, y),
        Point2::new(x + w, y),
        Point2::new(x + w, y + w),
        Point2::new(x, y + w),
    ]
}

fn ring_segments(r: &[Point2]) -> Vec<Segment2> {
    (0..r.len())
        .map(|i| Segment2::new(r[i], r[(i + 1) % r.len()]))
        .collect()
}

#[test]
fn crossing_segments_make_an_x() {
    let d = Dcel::from_segments(&[s((0., 0.), (2., 2.)), s((0., 2.), (2., 0.))]).unwrap();
    d.validate().unwrap();
    assert_eq!(
        (d.vertex_count(), d.edge_count(), d.face_count()),
        (5, 4, 1)
    );
    // The crossing is a constructed vertex with degree 4.
    let centre = d
        .vertex_ids()
        .find(|&v| d.vertex(v).approx == Point2::new(1.0, 1.0))
        .unwrap();
    assert_eq!(d.around(centre).count(), 4);
}

#[test]
fn nested_squares_link_hole_to_the_ring_face() {
    let mut segs = ring_segments(&square(0., 0., 10.));
    segs.extend(ring_segments(&square(3., 3., 2.)));
    segs.extend(ring_segments(&square(20., 0., 1.)));
    let d = Dcel::from_segments(&segs).unwrap();
    d.validate().unwrap();
    assert_eq!(d.face_count(), 4);
    // The big square's face has the small square as its one hole.
    let big = d
        .face_ids()
        .find(|&f| d.face(f).outer.is_some() && !d.face(f).inner.is_empty())
        .unwrap();
    assert_eq!(d.face(big).inner.len(), 1);
    assert_eq!(d.face_area_exact(big), BigRational::from_integer(96.into()));
    // The unbounded face has two components: the big square and the far one.
    assert_eq!(d.face(FaceId::UNBOUNDED).inner.len(), 2);
    let p = d.face_polygon(big).unwrap();
    assert_eq!(p.exterior.len(), 4);
    assert_eq!(p.holes.len(), 1);
}

#[test]
fn overlapping_and_touching_segments_merge() {
    // Two overlapping collinear segments, a duplicate and a T-junction.
    let segs = [
        s((0., 0.), (4., 0.)),
        s((2., 0.), (6., 0.)),
        s((6., 0.), (2., 0.)),
        s((3., 0.), (3., 3.)),
        s((1., 1.), (1., 1.)),
    ];
    let d = Dcel::from_segments(&segs).unwrap();
    d.validate().unwrap();
    // Vertices 0, 2, 3, 4, 6 on the axis and (3, 3).
    assert_eq!(d.vertex_count(), 6);
    assert_eq!(d.edge_count(), 5);
    let overlap = d
        .half_edge_ids()
        .find(|&h| d.half_edge(h).data.len() == 3)
        .expect("the piece 2..4 carries three segments");
    assert!(d.half_edge(overlap).data.iter().any(|s| s.segment == 2));
}

#[test]
fn polygon_faces_are_labelled() {
    let a = Polygon::new(square(0., 0., 4.), vec![square(1., 1., 1.)]);
    let b = Polygon::new(square(2., 2., 4.), vec![]);
    let d = Dcel::from_polygons(&MultiPolygon(vec![a, b])).unwrap();
    d.validate().unwrap();
    let area = |label: &[usize]| {
        d.face_ids()
            .filter(|&f| d.face(f).data == label)
            .map(|f| d.face_area_exact(f))
            .fold(BigRational::zero(), |x, y| x + y)
    };
    let int = |n: i64| BigRational::from_integer(n.into());
    assert_eq!(area(&[0]), int(16 - 1 - 4));
    assert_eq!(area(&[1]), int(12));
    assert_eq!(area(&[0, 1]), int(4));
}

#[test]
fn bad_input_is_an_error() {
    let nan = Segment2::new(Point2::new(f64::NAN, 0.0), Point2::new(1.0, 1.0));
    assert!(Dcel::from_segments(&[nan]).is_err());
    let two = Polygon::new(vec![Point2::new(0., 0.), Point2::new(1., 0.)], vec![]);
    let err = Dcel::from_polygons(&MultiPolygon(vec![two])).unwrap_err();
    assert!(err.to_string().contains("polygon 0"), "{err}");
}

fn small_segments(n: usize, range: i32) -> impl Strategy<Value = Vec<Segment2>> {
    prop::collection::vec(((0..range, 0..range), (0..range, 0..range)), 1..n).prop_map(|v| {
        v.into_iter()
            .map(|((a, b), (c, d))| s((a as f64, b as f64), (c as f64, d as f64)))
            .collect()
    })
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(200))]
    #[test]
    fn arrangements_of_grid_segments_are_valid(segs in small_segments(12, 6)) {
        let d = Dcel::from_segments(&segs).unwrap();
        d.validate().unwrap();
        // The bounded faces tile the union of bounded regions: areas are positive.
        for f in d.face_ids().skip(1) {
            prop_assert!(d.face_area_exact(f) > BigRational::zero());
        }
    }

    #[test]
    fn arrangements_of_float_segments_are_valid(
        v in prop::collection::vec(((-1e3f64..1e3, -1e3f64..1e3), (-1e3f64..1e3, -1e3f64..1e3)), 1..15)
    ) {
        let segs: Vec<Segment2> = v.into_iter().map(|(a, b)| s(a, b)).collect();
        let d = Dcel::from_segments(&segs).unwrap();
        d.validate().unwrap();
        for f in d.face_ids().skip(1) {
            prop_assert!(d.face_area_exact(f) > BigRational::zero());
        }
    }
}

/// Brute-force oracle for the graph G: the face holding the points just left of vertex
/// `v`, found by testing every edge and vertex against the leftward ray, in rationals.
fn face_left_of<V, E, F>(d: &Dcel<V, E, F>, v: VertexId) -> FaceId {
    use compgeom::dcel::exact_coords;
    let (px, py) = exact_coords(&d.vertex(v).point);
    // (x of the hit, half-edge whose left face holds the points just right of it)
    let mut best: Option<(BigRational, HalfEdgeId)> = None;
    let mut consider = |x: BigRational, h: HalfEdgeId| {
        if x < px && best.as_ref().map_or(true, |(b, _)| x > *b) {
            best = Some((x, h));
        }
    };
    for w in d.vertex_ids() {
        let (wx, wy) = exact_coords(&d.vertex(w).point);
        if w == v || wy != py || d.vertex(w).incident.is_none() {
            continue;
        }
        // The wedge at w holding direction +x: left of the outgoing half-edge with the
        // largest counter-clockwise angle from +x.
        let key = |h: HalfEdgeId| {
            let (ax, ay) = exact_coords(&d.vertex(d.destination(h)).point);
            let (dx, dy) = (ax - &wx, ay - &wy);
            let half =
                u8::from(!(dy > BigRational::zero() || (dy.is_zero() && dx > BigRational::zero())));
            (half, dx, dy)
        };
        let last = d
            .around(w)
            .max_by(|&a, &b| {
                let (ha, ax, ay) = key(a);
                let (hb, bx, by) = key(b);
                ha.cmp(&hb).then_with(|| (bx * ay).cmp(&(ax * by)))
            })
            .unwrap();
        consider(wx, last);
    }
    for i in 0..d.edge_count() {
        let h = HalfEdgeId(2 * i);
        let (ax, ay) = exact_coords(&d.vertex(d.half_edge(h).origin).point);
        let (bx, by) = exact_coords(&d.vertex(d.destination(h)).point);
        if (ay > py) == (by > py) || ay == py || by == py {
            continue;
        }
        let x = &ax + (&bx - &ax) * (&py - &ay) / (&by - &ay);
        consider(x, if ay > by { h } else { d.twin(h) });
    }
    best.map_or(FaceId::UNBOUNDED, |(_, h)| d.half_edge(h).face)
}

/// Every inner cycle sits in the face the brute-force ray finds.
fn check_holes<V, E, F>(d: &Dcel<V, E, F>) -> Result<(), TestCaseError> {
    for f in d.face_ids() {
        for &start in &d.face(f).inner {
            let v = d
                .cycle(start)
                .map(|h| d.half_edge(h).origin)
                .min_by(|&a, &b| d.vertex(a).point.compare_xy(&d.vertex(b).point))
                .unwrap();
            prop_assert_eq!(
                face_left_of(d, v),
                f,
                "inner cycle at {:?}",
                d.vertex(v).approx
            );
        }
    }
    Ok(())
}

fn grid_squares(n: usize, range: i32) -> impl Strategy<Value = Vec<Segment2>> {
    prop::collection::vec((0..range, 0..range, 1..5i32), 1..n).prop_map(|v| {
        v.into_iter()
            .flat_map(|(x, y, w)| ring_segments(&square(x as f64, y as f64, w as f64)))
            .collect()
    })
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(150))]
    #[test]
    fn holes_link_to_the_face_left_of_them_grid(segs in small_segments(25, 14)) {
        let d = Dcel::from_segments(&segs).unwrap();
        d.validate().unwrap();
        check_holes(&d)?;
    }

    #[test]
    fn holes_link_to_the_face_left_of_them_squares(segs in grid_squares(14, 16)) {
        let d = Dcel::from_segments(&segs).unwrap();
        d.validate().unwrap();
        check_holes(&d)?;
    }

    #[test]
    fn holes_link_to_the_face_left_of_them_float(
        v in prop::collection::vec(((-10f64..10.0, -10f64..10.0), (-1f64..1.0, -1f64..1.0)), 1..20)
    ) {
        let segs: Vec<Segment2> = v.into_iter().map(|((x, y), (dx, dy))| s((x, y), (x + dx, y + dy))).collect();
        let d = Dcel::from_segments(&segs).unwrap();
        d.validate().unwrap();
        check_holes(&d)?;
    }
}

/// A component whose smallest vertex has, before it on its horizontal line, a vertex
/// with edges up-left, up-right and down (a "Y" splitting a square in three faces of
/// different areas) and between them a zero-length segment: that segment leaves no
/// vertex (so the search for the face around a component never meets an isolated
/// vertex), and the component is a hole of the face east of the Y, which holds the
/// points just left of it.
#[test]
fn hole_found_east_of_a_vertex_on_its_line_past_a_zero_length_segment() {
    let square = [(-10.0, -10.0), (10.0, -10.0), (10.0, 10.0), (-10.0, 10.0)];
    let mut segs: Vec<Segment2> = (0..4).map(|i| s(square[i], square[(i + 1) % 4])).collect();
    for end in [(-10.0, 10.0), (10.0, 10.0), (-5.0, -10.0)] {
        segs.push(s((0.0, 0.0), end));
    }
    segs.push(s((2.0, 0.0), (2.0, 0.0)));
    let unit = [(3.0, 0.0), (4.0, 0.0), (4.0, 1.0), (3.0, 1.0)];
    segs.extend((0..4).map(|i| s(unit[i], unit[(i + 1) % 4])));
    let d = Dcel::from_segments(&segs).unwrap();
    d.validate().unwrap();
    // The square's corners, the Y's centre and its foot on the bottom side, the unit square's.
    assert_eq!(d.vertex_count(), 10);
    let mut areas: Vec<BigRational> = d.face_ids().skip(1).map(|f| d.face_area_exact(f)).collect();
    areas.sort();
    let want: Vec<BigRational> = [1, 100, 125, 174]
        .into_iter()
        .map(|a| BigRational::from_integer(a.into()))
        .collect();
    assert_eq!(
        areas, want,
        "east face 175 - 1, west 125, top 100, the unit square"
    );
}
