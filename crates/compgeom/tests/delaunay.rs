//! Delaunay triangulation: the exact verifier and a brute-force empty-circle oracle on
//! random and degenerate input; the book variant against the default.

mod common;
use compgeom::delaunay::{
    delaunay, delaunay_with, verify_delaunay, DelaunayAlgorithm, DelaunayOptions, InsertionOrder,
    Triangulation,
};
use compgeom::kernel::{incircle, orient2d, CircleSide, Orientation};
use compgeom::Point2;
use proptest::prelude::*;

fn book(pts: &[Point2]) -> Triangulation {
    book_in(pts, InsertionOrder::Biased)
}

fn book_in(pts: &[Point2], order: InsertionOrder) -> Triangulation {
    let o = DelaunayOptions::new()
        .with_algorithm(DelaunayAlgorithm::Incremental)
        .with_insertion_order(order);
    delaunay_with(pts, &o).unwrap()
}

/// Brute force: no vertex strictly inside any triangle's circumcircle; input map correct;
/// triangle count = 2n - 2 - h (h = boundary vertices) unless degenerate.
fn oracle(pts: &[Point2], t: &Triangulation) {
    let v = t.vertices();
    for (i, p) in pts.iter().enumerate() {
        assert_eq!(
            v[t.input_to_vertex()[i] as usize],
            *p,
            "input {i} mapped wrongly"
        );
    }
    for tri in t.triangles() {
        let [a, b, c] = tri.map(|i| v[i as usize]);
        assert_eq!(orient2d(a, b, c), Orientation::CounterClockwise);
        if v.len() <= 300 {
            for q in v {
                assert_ne!(incircle(a, b, c, *q), CircleSide::Inside);
            }
        }
    }
    if !t.is_degenerate() {
        let h = t.hull().len();
        assert_eq!(t.triangles().len(), 2 * v.len() - 2 - h);
    }
}

fn check_both(pts: &[Point2]) -> (Triangulation, Triangulation) {
    let f = delaunay(pts).unwrap();
    verify_delaunay(&f).unwrap();
    oracle(pts, &f);
    let b = book(pts);
    verify_delaunay(&b).unwrap();
    oracle(pts, &b);
    assert_eq!(f.vertices(), b.vertices());
    assert_eq!(f.input_to_vertex(), b.input_to_vertex());
    assert_eq!(f.triangles().len(), b.triangles().len());
    // The book's own uniform order: also Delaunay, and the same triangle set in general
    // position (the caller compares `b`; here it is held to `b` where that is unique).
    let u = book_in(pts, InsertionOrder::Uniform);
    verify_delaunay(&u).unwrap();
    oracle(pts, &u);
    assert_eq!(u.input_to_vertex(), b.input_to_vertex());
    assert_eq!(u.triangles().len(), b.triangles().len());
    (f, b)
}

#[test]
fn random_points_book_equals_default() {
    let mut unit = common::units(7);
    for n in [3, 4, 5, 10, 50, 200, 2000] {
        let pts: Vec<Point2> = (0..n).map(|_| Point2::new(unit(), unit())).collect();
        let (f, b) = check_both(&pts);
        assert_eq!(f.canonical_triangles(), b.canonical_triangles(), "n = {n}");
        let u = book_in(&pts, InsertionOrder::Uniform);
        assert_eq!(f.canonical_triangles(), u.canonical_triangles(), "n = {n}");
    }
}

#[test]
fn larger_random_input_verifies() {
    let mut unit = common::units(11);
    let pts: Vec<Point2> = (0..30_000)
        .map(|_| Point2::new(unit() * 1e3 - 500.0, unit() * 10.0))
        .collect();
    let (f, b) = check_both(&pts);
    assert_eq!(f.canonical_triangles(), b.canonical_triangles());
}

#[test]
fn integer_grids() {
    for (w, h) in [(2, 2), (3, 7), (10, 10), (40, 25)] {
        let pts: Vec<Point2> = (0..w)
            .flat_map(|i| (0..h).map(move |j| Point2::new(i as f64, j as f64)))
            .collect();
        let (f, _) = check_both(&pts);
        assert_eq!(f.triangles().len(), 2 * (w - 1) * (h - 1));
    }
}

#[test]
fn cocircular_lattice_points() {
    // r² = 5⁴·13² = 105625 has many lattice points on its circle.
    let r2: i64 = 5i64.pow(4) * 13 * 13;
    let r = (r2 as f64).sqrt() as i64;
    let mut pts = Vec::new();
    for x in -r..=r {
        let y2 = r2 - x * x;
        let y = (y2 as f64).sqrt().round() as i64;
        if y * y == y2 {
            pts.push(Point2::new(x as f64, y as f64));
            if y != 0 {
                pts.push(Point2::new(x as f64, -y as f64));
            }
        }
    }
    assert!(pts.len() >= 60, "{} lattice points", pts.len());
    let (f, _) = check_both(&pts);
    assert_eq!(f.triangles().len(), pts.len() - 2);
    // With the centre too, every triangle has the centre as a vertex.
    pts.push(Point2::new(0.0, 0.0));
    let (f, _) = check_both(&pts);
    assert_eq!(f.triangles().len(), pts.len() - 1);
    // Deterministic: the same input gives the same triangles.
    assert_eq!(delaunay(&pts).unwrap(), f);
}

#[test]
fn collinear_and_tiny_inputs_have_no_triangles() {
    let line: Vec<Point2> = (0..20)
        .map(|i| Point2::new(i as f64, 2.0 * i as f64 - 1.0))
        .collect();
    for pts in [
        vec![],
        vec![Point2::new(1.0, 1.0)],
        vec![Point2::new(1.0, 1.0); 5],
        line,
    ] {
        let (f, _) = check_both(&pts);
        assert!(f.is_degenerate());
        assert!(f.triangles().is_empty());
    }
}

#[test]
fn duplicates_are_merged_in_first_seen_order() {
    let pts = [
        (1.0, 1.0),
        (0.0, 0.0),
        (1.0, 1.0),
        (2.0, 0.0),
        (-0.0, 0.0),
        (1.0, 3.0),
    ]
    .map(Point2::from);
    let (f, _) = check_both(&pts);
    assert_eq!(f.vertices().len(), 4);
    assert_eq!(f.input_to_vertex(), &[0, 1, 0, 2, 1, 3]);
}

#[test]
fn nan_is_an_error_naming_the_point() {
    let pts = [(0.0, 0.0), (1.0, f64::NAN)].map(Point2::from);
    let e = delaunay(&pts).unwrap_err().to_string();
    assert!(e.contains("point 1"), "{e}");
}

#[test]
fn extreme_magnitudes() {
    for s in [1e-300, 1e200, 1.0] {
        let pts: Vec<Point2> = [
            (0.0, 0.0),
            (1.0, 0.0),
            (0.0, 1.0),
            (1.0, 1.0),
            (0.5, 0.5),
            (3.0, 0.1),
        ]
        .iter()
        .map(|&(x, y)| Point2::new(x * s, y * s))
        .collect();
        check_both(&pts);
    }
}

#[test]
fn verifier_rejects_a_non_delaunay_diagonal() {
    let v = [(0.0, 0.0), (3.0, 0.0), (0.0, 3.0), (3.0, 3.5)]
        .map(Point2::from)
        .to_vec();
    let bad =
        Triangulation::from_parts(v.clone(), vec![[0, 1, 3], [0, 3, 2]], vec![0, 1, 2, 3]).unwrap();
    assert!(verify_delaunay(&bad).is_err());
    let missing = Triangulation::from_parts(v, vec![[0, 1, 2]], vec![0, 1, 2, 3]).unwrap();
    assert!(verify_delaunay(&missing).is_err());
}

fn small_grid_point() -> impl Strategy<Value = Point2> {
    (0i32..6, 0i32..6).prop_map(|(x, y)| Point2::new(x as f64, y as f64))
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(120))]

    #[test]
    fn degenerate_grid_subsets(pts in prop::collection::vec(small_grid_point(), 0..40)) {
        check_both(&pts);
    }

    #[test]
    fn random_sets_agree(pts in prop::collection::vec((-1e3f64..1e3, -1e3f64..1e3), 3..80)) {
        let pts: Vec<Point2> = pts.into_iter().map(Point2::from).collect();
        let (f, b) = check_both(&pts);
        prop_assert_eq!(f.canonical_triangles(), b.canonical_triangles());
    }
}
