//! The kernel's crossing comparisons on arbitrary segments, against exact rationals: the sign
//! of `compare_xy` between a crossing and an input point must match the exact coordinates.
#![no_main]

use compgeom::kernel::Crossing;
use compgeom::{Point2, Segment2};
use libfuzzer_sys::fuzz_target;

fuzz_target!(|data: &[u8]| {
    if data.len() < 8 * 10 {
        return;
    }
    let f: Vec<f64> = data
        .chunks_exact(8)
        .take(10)
        .map(|c| f64::from_le_bytes(c.try_into().unwrap()))
        .collect();
    if f.iter().any(|v| !v.is_finite()) {
        return;
    }
    let s = Segment2::new(Point2::new(f[0], f[1]), Point2::new(f[2], f[3]));
    let t = Segment2::new(Point2::new(f[4], f[5]), Point2::new(f[6], f[7]));
    let p = Point2::new(f[8], f[9]);
    let Some(c) = Crossing::new(s, t) else {
        return;
    };
    let (x, y) = c
        .exact()
        .expect("a constructed crossing has exact coordinates");
    let px = num_rational::BigRational::from_float(p.x).unwrap();
    let py = num_rational::BigRational::from_float(p.y).unwrap();
    let expected = x.cmp(&px).then(y.cmp(&py));
    assert_eq!(c.compare_xy_point(p), expected);
    let a = c.approx();
    if a.is_finite() {
        // The exact comparison against the rounded point agrees with the rationals too.
        let ord = c.compare_xy_point(a);
        let ax = num_rational::BigRational::from_float(a.x).unwrap();
        let ay = num_rational::BigRational::from_float(a.y).unwrap();
        let ex = x.cmp(&ax).then(y.cmp(&ay));
        assert_eq!(ord, ex);
    }
});
