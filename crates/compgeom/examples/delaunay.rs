//! Delaunay triangulation of random points by both algorithms, checked by the exact verifier.
//!
//! `cargo run --release --example delaunay -- [N]`

use compgeom::delaunay::{
    delaunay, delaunay_with, verify_delaunay, DelaunayAlgorithm, DelaunayOptions,
};
use compgeom::Point2;
use std::time::Instant;

fn main() -> Result<(), compgeom::Error> {
    let n: usize = std::env::args()
        .nth(1)
        .and_then(|s| s.parse().ok())
        .unwrap_or(100_000);
    let mut s = 0x1234_5678_9abc_def0u64;
    let mut r = || {
        s ^= s << 13;
        s ^= s >> 7;
        s ^= s << 17;
        (s >> 11) as f64 / (1u64 << 53) as f64
    };
    let pts: Vec<Point2> = (0..n).map(|_| Point2::new(r(), r())).collect();
    let t0 = Instant::now();
    let fast = delaunay(&pts)?;
    let t1 = Instant::now();
    let book = delaunay_with(
        &pts,
        &DelaunayOptions::new().with_algorithm(DelaunayAlgorithm::Incremental),
    )?;
    let t2 = Instant::now();
    verify_delaunay(&fast)?;
    verify_delaunay(&book)?;
    assert_eq!(fast.canonical_triangles(), book.canonical_triangles());
    println!(
        "{n} points: {} triangles; default {:?}, book {:?}; both verified and equal",
        fast.triangles().len(),
        t1 - t0,
        t2 - t1
    );
    Ok(())
}
