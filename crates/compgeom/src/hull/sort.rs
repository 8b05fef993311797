//! Lexicographic sorting of points (x, then y) for the monotone chain.
//!
//! Small inputs use a comparison sort with [`compare_xy`]. Large inputs use an LSD radix
//! sort on an order-preserving integer image of x (exact: it orders the f64 values exactly
//! as `<` does, with `-0.0` and `0.0` mapped to the same key), then sort each run of equal
//! x by y. Radix passes in which every key has the same digit are skipped.

use crate::kernel::{compare_xy, Point2};

/// Below this many points a comparison sort is faster.
const RADIX_MIN: usize = 1 << 12;
/// Digit width of the radix sort.
const BITS: u32 = 11;
const BUCKETS: usize = 1 << BITS;
const PASSES: usize = 64usize.div_ceil(BITS as usize);

/// An unsigned key ordered like the finite value `v` (`-0.0` and `0.0` equal).
#[inline(always)]
fn order_key(v: f64) -> u64 {
    let b = (v + 0.0).to_bits();
    if b >> 63 == 1 {
        !b
    } else {
        b | (1 << 63)
    }
}

/// Sort finite points lexicographically (x, then y).
pub(crate) fn sort_lex(points: &mut Vec<Point2>) {
    let n = points.len();
    if n < RADIX_MIN {
        points.sort_unstable_by(|a, b| compare_xy(*a, *b));
        return;
    }
    let mut hist = vec![[0u32; BUCKETS]; PASSES];
    for p in points.iter() {
        let k = order_key(p.x);
        for (pass, h) in hist.iter_mut().enumerate() {
            h[((k >> (pass as u32 * BITS)) as usize) & (BUCKETS - 1)] += 1;
        }
    }
    let mut src = std::mem::take(points);
    let mut dst = vec![Point2::default(); n];
    for (pass, h) in hist.iter().enumerate() {
        // A digit shared by every key does not reorder anything.
        if h.iter().any(|&c| c as usize == n) {
            continue;
        }
        let mut offset = [0usize; BUCKETS];
        let mut sum = 0usize;
        for (o, &c) in offset.iter_mut().zip(h.iter()) {
            *o = sum;
            sum += c as usize;
        }
        let shift = pass as u32 * BITS;
        for &p in src.iter() {
            let d = ((order_key(p.x) >> shift) as usize) & (BUCKETS - 1);
            dst[offset[d]] = p;
            offset[d] += 1;
        }
        std::mem::swap(&mut src, &mut dst);
    }
    // Runs of equal x: order by y.
    let mut i = 0;
    while i < n {
        let mut j = i + 1;
        while j < n && src[j].x == src[i].x {
            j += 1;
        }
        if j - i > 1 {
            src[i..j].sort_unstable_by(|a, b| compare_xy(*a, *b));
        }
        i = j;
    }
    *points = src;
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn radix_order_matches_compare_xy() {
        let mut s = 0x1234_5678_9abc_def0u64;
        let mut next = || {
            s ^= s << 13;
            s ^= s >> 7;
            s ^= s << 17;
            s
        };
        let specials = [0.0, -0.0, 1e-310, -1e-310, 1e300, -1e300, 1.0, -1.0, 0.5];
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
