//! Polygon areas: the exact ones against a term-by-term rational shoelace (an
//! independent oracle), the `f64` ones within rounding of them.

mod common;
use compgeom::kernel::{ring_area, ring_area2_exact};
use compgeom::Point2;
use num_traits::{ToPrimitive, Zero};

#[test]
fn exact_area_is_the_rational_shoelace() {
    let mut unit = common::units(11);
    for k in 0..2000 {
        let scale = [1.0, 1e-300, 1e300, 3.0e-7, 1e15][k % 5];
        let n = 3 + k % 9;
        let ring: Vec<Point2> = (0..n)
            .map(|_| Point2::new((unit() - 0.5) * scale, (unit() + 1e6) * scale))
            .collect();
        let exact = ring_area2_exact(&ring);
        assert_eq!(exact, common::exact_shoelace2(&ring), "{ring:?}");
        if k % 5 == 0 {
            // Scale 1: the f64 area is the exact one up to rounding.
            let want = exact.to_f64().unwrap() / 2.0;
            assert!(
                (ring_area(&ring) - want).abs() <= 1e-6 * (1.0 + want.abs()),
                "{ring:?}"
            );
        }
    }
    assert!(ring_area2_exact(&[]).is_zero());
}
