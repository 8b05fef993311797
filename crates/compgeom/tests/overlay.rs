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
fn overlay_rejects_constructed_vertices() {
    let s = |a: (f64, f64), b: (f64, f64)| Segment2::new(a.into(), b.into());
    let x = Dcel::from_segments(&[s((0., 0.), (2., 2.)), s((0., 2.), (2., 0.))]).unwrap();
    let y = Dcel::from_segments(&[s((5., 5.), (6., 6.))]).unwrap();
    assert!(overlay(&x, &y).is_err());
    assert!(overlay(&y, &y).is_ok());
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
    let inside = MultiPolygon(vec![rect(0., 0., 4., 4.), rect(1., 1., 1., 1.)]);
    let p = validity_problems(&inside).unwrap();
    assert!(p.iter().any(|q| q.message.contains("overlap")), "{p:?}");
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

fn grid_ring() -> impl Strategy<Value = Vec<Point2>> {
    prop::collection::vec((0..6i32, 0..6i32), 3..8)
        .prop_map(|v| v.into_iter().map(|(x, y)| pt(x as f64, y as f64)).collect())
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(100))]
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
