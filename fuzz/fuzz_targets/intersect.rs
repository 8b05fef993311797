//! Segment intersection on arbitrary segments (raw f64 bit patterns, so NaN, infinities,
//! subnormals and huge values occur; or snapped to a small grid for heavy degeneracy), with
//! the exact brute-force verifier as the oracle: finite input must give a result that passes
//! `verify_intersections`, the same from the sweep, the pairwise method and the default;
//! `any_intersection` must return the sweep's first point; non-finite input must give an
//! error. Never a panic.
#![no_main]

use compgeom::intersect::{
    any_intersection, find_intersections, pairwise_intersections, sweep_intersections,
    verify_intersections,
};
use compgeom::{Point2, Segment2};
use libfuzzer_sys::fuzz_target;

fuzz_target!(|data: &[u8]| {
    let Some((&flags, rest)) = data.split_first() else {
        return;
    };
    let snap = flags & 1 == 1;
    let coord = |b: &[u8]| {
        if snap {
            (b[0] % 6) as f64
        } else {
            f64::from_le_bytes(b.try_into().unwrap())
        }
    };
    let segments: Vec<Segment2> = rest
        .chunks_exact(32)
        .take(40)
        .map(|c| {
            Segment2::new(
                Point2::new(coord(&c[..8]), coord(&c[8..16])),
                Point2::new(coord(&c[16..24]), coord(&c[24..])),
            )
        })
        .collect();
    let finite = segments.iter().all(|s| s.a.is_finite() && s.b.is_finite());
    match sweep_intersections(&segments) {
        Ok(found) => {
            assert!(finite, "non-finite input accepted");
            verify_intersections(&segments, &found).unwrap_or_else(|e| panic!("sweep: {e}"));
            assert_eq!(
                pairwise_intersections(&segments).unwrap(),
                found,
                "pairwise"
            );
            assert_eq!(find_intersections(&segments).unwrap(), found, "default");
            assert_eq!(
                any_intersection(&segments).unwrap(),
                found.points.first().cloned()
            );
        }
        Err(_) => assert!(!finite, "finite input rejected"),
    }
});
