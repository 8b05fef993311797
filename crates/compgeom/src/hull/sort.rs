//! Lexicographic sorting of points (x, then y) for the monotone chain.
//!
//! Small inputs use a comparison sort with [`compare_xy`]. Large inputs are first
//! distributed into about n/2 buckets by `floor((x - min x) * scale)` and each bucket is
//! then sorted with [`compare_xy`]. The order stays exact: the bucket map is computed with
//! correctly rounded operations, which are monotone, so `x < x'` never puts `x'` in an
//! earlier bucket, and equal x share a bucket; only the speed depends on how evenly the
//! points spread (skewed input degrades to the comparison sort, O(n log n)).

use crate::kernel::{compare_xy, Point2};

/// Below this many points a comparison sort is faster.
const BUCKET_MIN: usize = 1 << 12;

/// Sort finite points lexicographically (x, then y).
pub(crate) fn sort_lex(points: &mut Vec<Point2>) {
    let n = points.len();
    // Counters are u32: beyond that size use the comparison sort.
    if n < BUCKET_MIN || n > u32::MAX as usize {
        points.sort_unstable_by(|a, b| compare_xy(*a, *b));
        return;
    }
    let (mut lo, mut hi) = (points[0].x, points[0].x);
    for p in points.iter() {
        lo = lo.min(p.x);
        hi = hi.max(p.x);
    }
    let buckets = n / 2;
    // A non-finite or zero scale still gives a monotone map (see the module doc); the
    // clamp below keeps every index in range.
    let scale = buckets as f64 / (hi - lo);
    let last = buckets - 1;
    let bucket = |x: f64| -> usize {
        let t = (x - lo) * scale;
        // `as` saturates (NaN -> 0); both are monotone.
        (t as usize).min(last)
    };
    let mut start = vec![0u32; buckets + 1];
    let ids: Vec<u32> = points
        .iter()
        .map(|p| {
            let b = bucket(p.x);
            start[b + 1] += 1;
            b as u32
        })
        .collect();
    for b in 0..buckets {
        start[b + 1] += start[b];
    }
    let mut next = start.clone();
    let mut out = vec![Point2::default(); n];
    for (p, &b) in points.iter().zip(&ids) {
        let slot = &mut next[b as usize];
        out[*slot as usize] = *p;
        *slot += 1;
    }
    for w in start.windows(2) {
        let bucket = &mut out[w[0] as usize..w[1] as usize];
        if bucket.len() > 1 {
            bucket.sort_unstable_by(|a, b| compare_xy(*a, *b));
        }
    }
    *points = out;
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn bucket_order_matches_compare_xy() {
        let mut s = 0x1234_5678_9abc_def0u64;
        let mut next = || {
            s ^= s << 13;
            s ^= s >> 7;
            s ^= s << 17;
            s
        };
        let specials = [0.0, -0.0, 1e-310, -1e-310, 1e300, -1e300, 1.0, -1.0, 0.5];
        // Ranges that are huge (overflowing to infinity), tiny (subnormal) and ordinary.
        for spread in [f64::MAX, 1e-318, 1.0] {
            let mut pts: Vec<Point2> = (0..10_000)
                .map(|i| {
                    let t = ((next() % 2001) as f64 - 1000.0) / 1000.0;
                    Point2::new(t * spread, (i % 5) as f64)
                })
                .collect();
            let mut expected = pts.clone();
            expected.sort_by(|a, b| compare_xy(*a, *b));
            sort_lex(&mut pts);
            assert_eq!(pts, expected, "spread {spread}");
        }
        let mut pts: Vec<Point2> = (0..20_000)
            .map(|i| {
                let x = if i % 3 == 0 {
                    specials[(next() % 9) as usize]
                } else {
                    f64::from_bits(next() >> 2) - 1.0
                };
                Point2::new(x, (next() % 7) as f64 - 3.0)
            })
            .collect();
        let mut expected = pts.clone();
        expected.sort_by(|a, b| compare_xy(*a, *b));
        sort_lex(&mut pts);
        assert_eq!(pts.len(), expected.len());
        for (a, b) in pts.iter().zip(&expected) {
            assert_eq!(compare_xy(*a, *b), std::cmp::Ordering::Equal);
        }
    }
}
