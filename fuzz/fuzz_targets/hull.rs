//! Every hull algorithm on arbitrary points (raw f64 bit patterns, so NaN, infinities,
//! subnormals and huge values all occur), with the exact verifier as the oracle: finite input
//! must give a hull that passes `verify_convex_hull`, identical across the three algorithms;
//! non-finite input must give an error. Never a panic.
#![no_main]

use compgeom::hull::{convex_hull, verify_convex_hull, HullAlgorithm, HullOptions};
use compgeom::Point2;
use libfuzzer_sys::fuzz_target;

fuzz_target!(|data: &[u8]| {
    let Some((&flags, rest)) = data.split_first() else {
        return;
    };
    // Low bit: keep collinear points. Next bit: snap to a small grid to force degeneracy.
    let keep_collinear = flags & 1 == 1;
    let snap = flags & 2 == 2;
    let points: Vec<Point2> = rest
        .chunks_exact(16)
        .take(48)
        .map(|c| {
            let x = f64::from_le_bytes(c[..8].try_into().unwrap());
            let y = f64::from_le_bytes(c[8..].try_into().unwrap());
            if snap {
                Point2::new((c[0] % 5) as f64, (c[8] % 5) as f64)
            } else {
                Point2::new(x, y)
            }
        })
        .collect();
    let finite = points.iter().all(|p| p.is_finite());
    let mut first: Option<Vec<Point2>> = None;
    for algorithm in [
        HullAlgorithm::Default,
        HullAlgorithm::Andrew,
        HullAlgorithm::Slow,
    ] {
        let options = HullOptions::new()
            .with_algorithm(algorithm)
            .with_keep_collinear(keep_collinear);
        match convex_hull(&points, &options) {
            Ok(hull) => {
                assert!(finite, "non-finite input accepted");
                verify_convex_hull(&points, &hull, keep_collinear)
                    .unwrap_or_else(|e| panic!("{algorithm:?}: {e}"));
                match &first {
                    None => first = Some(hull),
                    Some(h) => assert_eq!(h, &hull, "{algorithm:?} differs from the default"),
                }
            }
            Err(_) => assert!(!finite, "finite input rejected"),
        }
    }
});
