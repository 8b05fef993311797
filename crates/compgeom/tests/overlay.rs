//! MAPOVERLAY labels, validity reports and make_valid.
use compgeom::dcel::{Dcel, FaceId};
use compgeom::overlay::{make_valid, overlay, overlay_polygons, validity_problems, FillRule};
use compgeom::{MultiPolygon, Point2, Polygon, Segment2};
use num_rational::BigRational;
use num_traits::Zero;
use proptest::prelude::*;

mod common;
use common::{area, assert_valid};

fn pt(x: f64, y: f64) -> Point2 {
    Point2::new(x, y)
}

fn rect(x: f64, y: f64, w: f64, h: f64) -> Polygon {
    Polygon::new(
        vec![pt(x, y), pt(x + w, y), pt(x + w, y + h), pt(x, y + h)],
        vec![],
    )
}

#[test]
fn overlay_of_two_maps_labels_every_face() {
    // A: two fields side by side; B: a river across both, and a lake inside field 0.
    let a = MultiPolygon(vec![rect(0., 0., 4., 4.), rect(4., 0., 4., 4.)]);
    let b = MultiPolygon(vec![rect(-1., 1., 10., 1.), rect(1., 2.5, 1., 1.)]);
    let o = overlay_polygons(&a, &b).unwrap();
    o.validate().unwrap();
    let int = |n: i64| BigRational::from_integer(n.into());
    let area_of = |la: &[usize], lb: &[usize]| {
        o.face_ids()
            .filter(|&f| o.face(f).data.0 == la && o.face(f).data.1 == lb)
            .map(|f| o.face_area_exact(f))
            .fold(BigRational::zero(), |x, y| x + y)
    };
    assert_eq!(area_of(&[0], &[0]), int(4));
    assert_eq!(area_of(&[1], &[0]), int(4));
    assert_eq!(area_of(&[0], &[1]), int(1));
    assert_eq!(area_of(&[0], &[]), int(16 - 4 - 1));
    assert_eq!(area_of(&[], &[0]), int(2));
    // The unbounded face has no labels.
    assert_eq!(o.face(FaceId::UNBOUNDED).data, (vec![], vec![]));
}

#[test]
fn overlay_takes_subdivisions_with_constructed_vertices() {
    let s = |a: (f64, f64), b: (f64, f64)| Segment2::new(a.into(), b.into());
    // An X (a crossing vertex) overlaid with a segment through the crossing and one
    // cutting both arms: the pieces find the X's edges they lie in.
    let x = Dcel::from_segments(&[s((0., 0.), (2., 2.)), s((0., 2.), (2., 0.))]).unwrap();
    let y = Dcel::from_segments(&[s((1., -1.), (1., 3.)), s((-1., 1.5), (3., 1.5))]).unwrap();
    let o = overlay(&x, &y).unwrap();
    o.validate().unwrap();
    for h in o.half_edge_ids() {
        let e = o.half_edge(h).data;
        assert!(e.s1.is_some() || e.s2.is_some());
        if let Some(g) = e.s1 {
            // The piece lies on its S1 edge and runs the same way.
            assert_eq!(x.carrier(g).seg, o.carrier(h).seg);
            assert_eq!(x.carrier(g).forward, o.carrier(h).forward);
        }
    }
    // 4 ends of the X and its centre (shared with the vertical line), 4 ends of the two
    // lines, the horizontal line meeting both upper arms and the vertical line.
    assert_eq!(o.vertex_count(), 12);
}

/// Exact area of every label triple (faces of A, B, C containing a region).
type Areas = std::collections::BTreeMap<(Vec<usize>, Vec<usize>, Vec<usize>), BigRational>;

fn add(m: &mut Areas, k: (Vec<usize>, Vec<usize>, Vec<usize>), a: BigRational) {
    if !a.is_zero() {
        *m.entry(k).or_insert_with(BigRational::zero) += a;
    }
}

/// Three polygon layers overlaid as (A ⊕ B) ⊕ C, A ⊕ (B ⊕ C) and in one arrangement of
/// all rings: the same exact area for every label triple.
fn three_layers_agree(a: &MultiPolygon, b: &MultiPolygon, c: &MultiPolygon) {
    let (da, db, dc) = (
        Dcel::from_polygons(a).unwrap(),
        Dcel::from_polygons(b).unwrap(),
        Dcel::from_polygons(c).unwrap(),
    );
    let ab = overlay(&da, &db).unwrap();
    let ab_c = overlay(&ab, &dc).unwrap();
    ab_c.validate().unwrap();
    let bc = overlay(&db, &dc).unwrap();
    let a_bc = overlay(&da, &bc).unwrap();
    a_bc.validate().unwrap();
    let mut left = Areas::new();
    for f in ab_c.face_ids().skip(1) {
        let l = ab_c.face(f).data;
        let m = ab.face(l.s1).data;
        let key = (
            da.face(m.s1).data.clone(),
            db.face(m.s2).data.clone(),
            dc.face(l.s2).data.clone(),
        );
        add(&mut left, key, ab_c.face_area_exact(f));
    }
    let mut right = Areas::new();
    for f in a_bc.face_ids().skip(1) {
        let l = a_bc.face(f).data;
        let m = bc.face(l.s2).data;
        let key = (
            da.face(l.s1).data.clone(),
            db.face(m.s1).data.clone(),
            dc.face(m.s2).data.clone(),
        );
        add(&mut right, key, a_bc.face_area_exact(f));
    }
    // One arrangement of all rings, labelled by the polygons containing each face.
    let (na, nb) = (a.0.len(), b.0.len());
    let all = MultiPolygon(a.0.iter().chain(&b.0).chain(&c.0).cloned().collect());
    let flat = Dcel::from_polygons(&all).unwrap();
    let mut direct = Areas::new();
    for f in flat.face_ids().skip(1) {
        let l = &flat.face(f).data;
        let key = (
            l.iter().copied().filter(|&i| i < na).collect(),
            l.iter()
                .filter(|&&i| i >= na && i < na + nb)
                .map(|i| i - na)
                .collect(),
            l.iter()
                .filter(|&&i| i >= na + nb)
                .map(|i| i - na - nb)
                .collect(),
        );
        add(&mut direct, key, flat.face_area_exact(f));
    }
    assert_eq!(left, direct);
    assert_eq!(right, direct);
}

#[test]
fn overlay_of_an_overlay_three_layers() {
    // C's diagonal edges cross the constructed vertices' edges of A ⊕ B.
    let tri =
        |pts: &[(f64, f64)]| Polygon::new(pts.iter().map(|&(x, y)| pt(x, y)).collect(), vec![]);
    let a = MultiPolygon(vec![
        rect(0., 0., 4., 4.),
        tri(&[(5., 0.), (9., 1.), (6., 4.)]),
    ]);
    let b = MultiPolygon(vec![tri(&[(-1., -1.), (7., 2.), (1., 5.)])]);
    let c = MultiPolygon(vec![
        tri(&[(0.5, 3.), (8., -0.5), (8., 4.5)]),
        rect(2., 1., 1., 1.),
    ]);
    three_layers_agree(&a, &b, &c);
    // And a fourth layer on top of the three.
    let d = MultiPolygon(vec![rect(1.5, -2., 0.25, 9.)]);
    let abc = overlay(
        &overlay(
            &Dcel::from_polygons(&a).unwrap(),
            &Dcel::from_polygons(&b).unwrap(),
        )
        .unwrap(),
        &Dcel::from_polygons(&c).unwrap(),
    )
    .unwrap();
    let four = overlay(&abc, &Dcel::from_polygons(&d).unwrap()).unwrap();
    four.validate().unwrap();
    let total: BigRational = four
        .face_ids()
        .skip(1)
        .map(|f| four.face_area_exact(f))
        .sum();
    let flat = Dcel::from_polygons(&MultiPolygon(
        a.0.iter()
            .chain(&b.0)
            .chain(&c.0)
            .chain(&d.0)
            .cloned()
            .collect(),
    ))
    .unwrap();
    let want: BigRational = flat
        .face_ids()
        .skip(1)
        .map(|f| flat.face_area_exact(f))
        .sum();
    assert_eq!(total, want);
}

fn float_tri() -> impl Strategy<Value = Polygon> {
    prop::collection::vec((-5f64..5.0, -5f64..5.0), 3)
        .prop_map(|v| Polygon::new(v.into_iter().map(|(x, y)| pt(x, y)).collect(), vec![]))
}

#[test]
fn validity_reasons() {
    let ok = MultiPolygon(vec![rect(0., 0., 2., 2.)]);
    assert!(validity_problems(&ok).unwrap().is_empty());
    let bow = MultiPolygon(vec![Polygon::new(
        vec![pt(0., 0.), pt(2., 2.), pt(2., 0.), pt(0., 2.)],
        vec![],
    )]);
    assert!(validity_problems(&bow).unwrap()[0]
        .message
        .contains("cross"));
    let over = MultiPolygon(vec![rect(0., 0., 2., 2.), rect(1., 1., 2., 2.)]);
    let p = validity_problems(&over).unwrap();
    assert!(p.iter().any(|q| q.message.contains("cross")), "{p:?}");
    // Interiors overlapping are named by the polygons that overlap (once a pair), at a
    // point inside both: one inside another, a diamond touching its square at every
    // vertex (no vertex of it inside the other), one inside another's hole (valid).
    let inside = MultiPolygon(vec![
        rect(0., 0., 4., 4.),
        rect(1., 1., 1., 1.),
        rect(2.5, 2.5, 1., 1.),
    ]);
    let p = validity_problems(&inside).unwrap();
    let named: Vec<_> = p.iter().map(|q| (q.message.as_str(), q.polygon)).collect();
    assert_eq!(
        named,
        [
            ("interiors of polygon 0 and polygon 1 overlap", Some(0)),
            ("interiors of polygon 0 and polygon 2 overlap", Some(0)),
        ],
        "{p:?}"
    );
    let at = p[1].at.unwrap();
    assert!(
        at.x > 2.5 && at.x < 3.5 && at.y > 2.5 && at.y < 3.5,
        "{p:?}"
    );
    let diamond = Polygon::new(vec![pt(2., 0.), pt(4., 2.), pt(2., 4.), pt(0., 2.)], vec![]);
    let p = validity_problems(&MultiPolygon(vec![rect(0., 0., 4., 4.), diamond.clone()])).unwrap();
    assert_eq!(p.len(), 1, "{p:?}");
    assert_eq!(p[0].message, "interiors of polygon 0 and polygon 1 overlap");
    // Three piled up: every one named (not every pair); an overlap with a hole in it
    // (no point near the middle of its corners is inside it), beside another overlap.
    let wkt = |text: &str| {
        let polygons = compgeom::io::read_polygons(text, compgeom::io::Format::Wkt, "t").unwrap();
        validity_problems(&polygons).unwrap()
    };
    let messages =
        |p: &[compgeom::overlay::Problem]| p.iter().map(|q| q.message.clone()).collect::<Vec<_>>();
    let p = wkt("MULTIPOLYGON (((0 0, 8 0, 8 8, 0 8, 0 0)), ((2 2, 6 2, 6 6, 2 6, 2 2)), ((3 3, 5 3, 5 5, 3 5, 3 3)))");
    assert_eq!(
        messages(&p),
        [
            "interiors of polygon 0 and polygon 1 overlap",
            "interiors of polygon 0 and polygon 2 overlap"
        ]
    );
    let p = wkt("MULTIPOLYGON (((0 0, 10 0, 10 10, 0 10, 0 0)), ((2 2, 8 2, 8 8, 2 8, 2 2), (3 3, 3 7, 7 7, 7 3, 3 3)), ((20 20, 21 20, 21 21, 20 21, 20 20)), ((20.2 20.2, 20.8 20.2, 20.8 20.8, 20.2 20.8, 20.2 20.2)))");
    assert_eq!(
        messages(&p),
        [
            "interiors of polygon 0 and polygon 1 overlap",
            "interiors of polygon 2 and polygon 3 overlap"
        ]
    );
    let at = p[0].at.unwrap();
    let in_frame = |v: f64| (2.0..3.0).contains(&v) || (7.0..8.0).contains(&v);
    assert!(
        (in_frame(at.x) && (2.0..8.0).contains(&at.y))
            || (in_frame(at.y) && (2.0..8.0).contains(&at.x)),
        "{p:?}"
    );
    // An overlap with no float point inside it (a triangle less than a float gap high
    // over its whole length, inside a square): reported, without names.
    let p = wkt("MULTIPOLYGON (((0 1, 9007199254740992 1, 9007199254740992 1.0000000000000002, 0 1)), ((-1 0, 18014398509481984 0, 18014398509481984 2, -1 2, -1 0)))");
    assert_eq!(messages(&p), ["polygon interiors overlap"]);
    assert_eq!(p[0].polygon, None);
    let mut square_hole = rect(0., 0., 4., 4.).exterior;
    square_hole.reverse();
    let frame = Polygon::new(rect(-1., -1., 6., 6.).exterior, vec![square_hole]);
    assert_eq!(
        validity_problems(&MultiPolygon(vec![frame, diamond])).unwrap(),
        []
    );
    let mut hole = rect(5., 5., 1., 1.).exterior;
    hole.reverse();
    let outside = MultiPolygon(vec![Polygon::new(
        rect(0., 0., 2., 2.).exterior,
        vec![hole],
    )]);
    let p = validity_problems(&outside).unwrap();
    assert!(
        p.iter().any(|q| q.message.contains("outside its shell")),
        "{p:?}"
    );
    // (Its winding below zero is that hole, not holes nesting.)
    assert!(
        !p.iter().any(|q| q.message.contains("holes overlap")),
        "{p:?}"
    );
    // Empty rings are no rings (an empty polygon, an empty hole), as the readers take EMPTY.
    let empty = MultiPolygon(vec![
        Polygon::new(vec![], vec![]),
        Polygon::new(rect(0., 0., 2., 2.).exterior, vec![vec![]]),
    ]);
    assert_eq!(validity_problems(&empty).unwrap(), []);
    let mut cw = rect(0., 0., 1., 1.).exterior;
    cw.reverse();
    let p = validity_problems(&MultiPolygon(vec![Polygon::new(cw, vec![])])).unwrap();
    assert!(p[0].message.contains("counter-clockwise"), "{p:?}");
    let short = MultiPolygon(vec![Polygon::new(
        vec![pt(0., 0.), pt(1., 1.), pt(0., 0.)],
        vec![],
    )]);
    assert!(validity_problems(&short).unwrap()[0]
        .message
        .contains("3 distinct"));
    let nan = MultiPolygon(vec![Polygon::new(
        vec![pt(0., 0.), pt(f64::NAN, 1.), pt(1., 0.)],
        vec![],
    )]);
    assert!(validity_problems(&nan).unwrap()[0]
        .message
        .contains("non-finite"));
}

/// Touching rings by the OGC rules: two rings of a polygon may meet at one point (a
/// vertex of both, or a vertex of one on an edge of the other), polygons may touch at
/// points; a ring may not meet itself, and the rings of a polygon may not meet in a loop
/// (twice, or around a chain) nor holes nest.
#[test]
fn touching_rings_follow_the_ogc_rules() {
    let problems = |wkt: &str| {
        let polygons = compgeom::io::read_polygons(wkt, compgeom::io::Format::Wkt, "t").unwrap();
        validity_problems(&polygons).unwrap()
    };
    for valid in [
        // A hole touching its shell inside an edge, and at a vertex of the shell.
        "POLYGON ((0 0, 10 0, 10 10, 0 10, 0 0), (5 0, 3 3, 7 3, 5 0))",
        "POLYGON ((0 0, 5 0, 10 0, 10 10, 0 10, 0 0), (5 0, 3 3, 7 3, 5 0))",
        // Holes touching the shell and each other in a tree.
        "POLYGON ((0 0, 10 0, 10 10, 0 10, 0 0), (5 0, 4 2, 6 2, 5 0), (4 2, 2 5, 3 6, 4 2), (6 2, 7 6, 8 5, 6 2))",
        // Two polygons, a vertex of one on an edge of the other; and at two points.
        "MULTIPOLYGON (((0 0, 10 0, 10 10, 0 10, 0 0)), ((5 0, 3 -3, 7 -3, 5 0)))",
        "MULTIPOLYGON (((0 0, 10 0, 10 10, 0 10, 0 0)), ((2 0, 0 -3, 10 -3, 8 0, 5 -2, 2 0)))",
    ] {
        assert_eq!(problems(valid), [], "{valid}");
    }
    for (invalid, want) in [
        // A shell and a hole meeting at two points; three holes in a loop.
        (
            "POLYGON ((0 0, 5 0, 10 0, 10 10, 5 10, 0 10, 0 0), (5 0, 3 5, 5 10, 7 5, 5 0))",
            "not connected",
        ),
        (
            "POLYGON ((0 0, 10 0, 10 10, 0 10, 0 0), (5 0, 4 2, 6 2, 5 0), (4 2, 2 5, 5 6, 4 2), (5 6, 8 5, 6 2, 5 6))",
            "not connected",
        ),
        // A hole inside another; also where an island in it covers the nesting, and
        // where another hole of the polygon is outside its shell.
        (
            "POLYGON ((0 0, 10 0, 10 10, 0 10, 0 0), (1 1, 1 9, 9 9, 9 1, 1 1), (2 2, 2 8, 8 8, 8 2, 2 2))",
            "polygon 0 hole 1: lies inside hole 0",
        ),
        (
            "MULTIPOLYGON (((0 0, 10 0, 10 10, 0 10, 0 0), (1 1, 1 9, 9 9, 9 1, 1 1), (2 2, 2 8, 8 8, 8 2, 2 2)), ((3 3, 7 3, 7 7, 3 7, 3 3)))",
            "polygon 0 hole 1: lies inside hole 0",
        ),
        (
            "POLYGON ((0 0, 10 0, 10 10, 0 10, 0 0), (20 0, 21 0, 21 1, 20 0), (2 2, 2 8, 8 8, 8 2, 2 2), (3 3, 3 7, 7 7, 7 3, 3 3))",
            "polygon 0 hole 2: lies inside hole 1",
        ),
        // A ring through one point twice, and a vertex of a ring on its own edge.
        (
            "POLYGON ((0 0, 4 0, 2 2, 4 4, 0 4, 2 2, 0 0))",
            "touches itself",
        ),
        ("POLYGON ((0 0, 10 0, 10 10, 5 0, 0 10, 0 0))", "touches itself"),
        // A hole touching its shell at its first vertex, the rest outside.
        (
            "POLYGON ((0 0, 10 0, 10 10, 0 10, 0 0), (5 0, 7 -3, 3 -3, 5 0))",
            "outside its shell",
        ),
    ] {
        let p = problems(invalid);
        assert!(p.iter().any(|q| q.message.contains(want)), "{invalid}: {p:?}");
    }
    // Each hole inside another is reported once: of three nested holes, the two inner.
    let p = problems("POLYGON ((0 0, 10 0, 10 10, 0 10, 0 0), (1 1, 1 9, 9 9, 9 1, 1 1), (2 2, 2 8, 8 8, 8 2, 2 2), (3 3, 3 7, 7 7, 7 3, 3 3))");
    let named: Vec<&str> = p.iter().map(|q| &q.message[..17]).collect();
    assert_eq!(named, ["polygon 0 hole 1:", "polygon 0 hole 2:"], "{p:?}");
    // A hole touching another at its first vertex is tested from its second, inside the
    // other or not (a triangle in the mouth of a C-shaped hole).
    let p = problems(
        "POLYGON ((0 0, 10 0, 10 10, 0 10, 0 0), (1 1, 1 9, 9 9, 9 1, 1 1), (1 5, 3 6, 3 4, 1 5))",
    );
    let messages: Vec<&str> = p.iter().map(|q| q.message.as_str()).collect();
    assert_eq!(messages, ["polygon 0 hole 1: lies inside hole 0"]);
    assert_eq!(
        problems("POLYGON ((0 0, 10 0, 10 10, 0 10, 0 0), (1 1, 1 9, 9 9, 9 8, 2 8, 2 2, 9 2, 9 1, 1 1), (2 5, 5 6, 5 4, 2 5))"),
        []
    );
    // Nested boxes past one batch of tests (200 concentric holes: 19 900 pairs), each
    // hole inside another reported once.
    let holes: Vec<String> = (1..=200)
        .map(|k| {
            let (a, b) = (k, 402 - k);
            format!("({a} {a}, {a} {b}, {b} {b}, {b} {a}, {a} {a})")
        })
        .collect();
    let p = problems(&format!(
        "POLYGON ((0 0, 402 0, 402 402, 0 402, 0 0), {})",
        holes.join(", ")
    ));
    assert_eq!(p.len(), 199, "{:?}", &p[..3.min(p.len())]);
    assert!(p.iter().all(|q| q.message.contains("lies inside hole")));
    // A hole sharing part of an edge with its shell: the overlap, not also a loop.
    let p = problems("POLYGON ((0 0, 10 0, 10 10, 0 10, 0 0), (0 2, 0 4, 3 3, 0 2))");
    assert!(p.iter().any(|q| q.message.contains("overlap")), "{p:?}");
    assert!(
        !p.iter().any(|q| q.message.contains("not connected")),
        "{p:?}"
    );
}

fn grid_ring() -> impl Strategy<Value = Vec<Point2>> {
    prop::collection::vec((0..6i32, 0..6i32), 3..8)
        .prop_map(|v| v.into_iter().map(|(x, y)| pt(x as f64, y as f64)).collect())
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(100))]
    #[test]
    fn three_layer_overlays_compose(
        a in prop::collection::vec(float_tri(), 1..3),
        b in prop::collection::vec(float_tri(), 1..3),
        c in prop::collection::vec(grid_ring(), 1..3),
    ) {
        let distinct = |p: &Polygon| {
            let mut k: Vec<_> = p.exterior.iter().map(|q| (q.x.to_bits(), q.y.to_bits())).collect();
            k.sort_unstable();
            k.dedup();
            k.len() >= 3
        };
        let c = MultiPolygon(c.into_iter().map(|r| Polygon::new(r, vec![])).collect());
        let (a, b) = (MultiPolygon(a), MultiPolygon(b));
        prop_assume!(a.0.iter().chain(&b.0).chain(&c.0).all(distinct));
        three_layers_agree(&a, &b, &c);
    }

    #[test]
    fn make_valid_gives_valid_polygons_with_the_even_odd_area(rs in prop::collection::vec(grid_ring(), 1..3)) {
        let m = MultiPolygon(rs.into_iter().map(|r| Polygon::new(r, vec![])).collect());
        let distinct = m.0.iter().all(|p| {
            let mut k: Vec<_> = p.exterior.iter().map(|q| (q.x.to_bits(), q.y.to_bits())).collect();
            k.sort_unstable();
            k.dedup();
            k.len() >= 3
        });
        prop_assume!(distinct);
        let fixed = make_valid(&m, FillRule::EvenOdd).unwrap();
        assert_valid(&fixed);
        prop_assert!(validity_problems(&fixed).unwrap().is_empty(), "{:?}", validity_problems(&fixed));
        // Its area is the exact even-odd area of the input (from the labelled arrangement).
        let d = compgeom::overlay::boolean_dcel(&m, &MultiPolygon::default(), FillRule::EvenOdd).unwrap();
        let exact: f64 = d.face_ids().filter(|&f| d.face(f).data.0 % 2 != 0)
            .map(|f| num_traits::ToPrimitive::to_f64(&d.face_area_exact(f)).unwrap()).sum();
        prop_assert!((area(&fixed) - exact).abs() < 1e-9);
    }
}

#[test]
fn overlay_of_overlays_with_collinear_slivers_composes() {
    // Shrunk from `three_layer_overlays_compose`: a is a degenerate triangle (three
    // points on x = 0), b a thin triangle touching it, c two grid rings, one degenerate.
    let tri = |v: [(f64, f64); 3]| Polygon::new(v.iter().map(|&(x, y)| pt(x, y)).collect(), vec![]);
    let a = MultiPolygon(vec![tri([
        (0., 0.),
        (0., 4.5680605669815675),
        (0., -4.2656810164975285),
    ])]);
    let b = MultiPolygon(vec![tri([
        (0., 0.),
        (1.268110028621112, 0.5676061104175983),
        (0., -0.8410265872885284),
    ])]);
    let c = MultiPolygon(vec![
        tri([(1., 4.), (1., 0.), (1., 1.)]),
        tri([(0., 1.), (0., 2.), (2., 2.)]),
    ]);
    three_layers_agree(&a, &b, &c);
}
