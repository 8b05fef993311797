//! The polygons of a large input put in an order in which polygons near each other in
//! the plane are near each other in memory: along a Z-order curve through the centres of
//! their boxes.
//!
//! The arrangement numbers its edges in the order of the segments and its vertices in
//! the order the edges first use them, and the tracing walks around each face from edge
//! to edge. On a large input listed in no spatial order (random squares, a layer
//! exported in the order its features were digitised) each step of such a walk went to
//! a random place in arrays of hundreds of megabytes: a cache miss, mostly a TLB miss
//! too, at every step. Measured, `union_all` of 10⁶ squares turned by random angles at
//! constant density (`BOOLEAN_INPUT=turned BOOLEAN_SPREAD=1 BOOLEAN_N=1000000`, the
//! call alone): 28.0 s listed at random, 13.4 s listed in Z-order by the caller,
//! 14.6–17.9 s listed at random and reordered here (the page faults' system time varies
//! from run to run on the machine measured).
//!
//! The results do not depend on the order: they are put in a canonical order at the
//! end, and the decisions on the way are made on exact points (where one depends on the
//! numbering, which of three vertices rounded onto one point are merged, the polygon is
//! united again). `boolean::tests::reordering_large_inputs_changes_no_result` compares
//! the results from the given order, the reordered one and a reversed one.

use crate::kernel::Segment2;

/// Inputs of fewer polygons, or of fewer points in their rings (closing points
/// counted), keep their order: their arrays stay in the caches anyway, and the sort and
/// copy would cost them (the GEOS-837 dissolve, 487 polygons of 2 580 points: +7%
/// instructions).
pub(super) const REORDER_FROM: usize = 64;

/// See [`REORDER_FROM`].
pub(super) const REORDER_FROM_POINTS: usize = 1 << 14;

/// Bits per axis of the Z-order key (65 536 cells per axis).
const BITS: u32 = 16;

/// Reorders the blocks `segs[starts[k]..starts[k + 1]]` (the segments of one polygon
/// each; `starts` ascending, the last entry `segs.len()`) along a Z-order curve through
/// the centres of the blocks' boxes, blocks with equal keys in their given order.
/// O(n + b log b) for n segments in b blocks.
pub(super) fn reorder_blocks(segs: &mut [Segment2], starts: &[usize]) {
    let blocks = starts.len().saturating_sub(1);
    if blocks < 2 || blocks > u32::MAX as usize {
        return;
    }
    // The centre of each block's box (of its segments' first points: its ring vertices).
    let centres: Vec<(f64, f64)> = starts
        .windows(2)
        .map(|w| centre(&segs[w[0]..w[1]]))
        .collect();
    let (mut x0, mut x1, mut y0, mut y1) = (f64::MAX, f64::MIN, f64::MAX, f64::MIN);
    for &(x, y) in &centres {
        (x0, x1, y0, y1) = (x0.min(x), x1.max(x), y0.min(y), y1.max(y));
    }
    // (Halves first: the width of boxes near ±f64::MAX would overflow. A zero width
    // gives an infinite scale and 0 · ∞ = NaN, a width below about 1e-304 an infinite
    // scale too: the saturating casts and `spread`'s mask take those to cell 0 or the
    // last cell, still a valid key.)
    let cells = f64::from((1u32 << BITS) - 1);
    let (sx, sy) = (cells / (x1 / 2.0 - x0 / 2.0), cells / (y1 / 2.0 - y0 / 2.0));
    let mut keyed: Vec<u64> = centres
        .iter()
        .enumerate()
        .map(|(k, &(x, y))| {
            let gx = ((x / 2.0 - x0 / 2.0) * sx) as u32;
            let gy = ((y / 2.0 - y0 / 2.0) * sy) as u32;
            (spread(gx) | spread(gy) << 1) << 32 | k as u64
        })
        .collect();
    keyed.sort_unstable();
    let mut ordered: Vec<Segment2> = Vec::with_capacity(segs.len());
    for &kk in &keyed {
        let k = kk as u32 as usize;
        ordered.extend_from_slice(&segs[starts[k]..starts[k + 1]]);
    }
    segs.copy_from_slice(&ordered);
}

/// The centre of the box of the first points of `segs` (the origin for none).
fn centre(segs: &[Segment2]) -> (f64, f64) {
    let Some(first) = segs.first() else {
        return (0.0, 0.0);
    };
    let (mut x0, mut x1, mut y0, mut y1) = (first.a.x, first.a.x, first.a.y, first.a.y);
    for s in segs {
        (x0, x1) = (x0.min(s.a.x), x1.max(s.a.x));
        (y0, y1) = (y0.min(s.a.y), y1.max(s.a.y));
    }
    (x0 / 2.0 + x1 / 2.0, y0 / 2.0 + y1 / 2.0)
}

/// The low [`BITS`] bits of `v` spread to the even bit positions of the result.
fn spread(v: u32) -> u64 {
    let mut x = u64::from(v & ((1 << BITS) - 1));
    x = (x | x << 8) & 0x00ff_00ff;
    x = (x | x << 4) & 0x0f0f_0f0f;
    x = (x | x << 2) & 0x3333_3333;
    x = (x | x << 1) & 0x5555_5555;
    x
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::kernel::Point2;

    fn seg(ax: f64, ay: f64, bx: f64, by: f64) -> Segment2 {
        Segment2::new(Point2::new(ax, ay), Point2::new(bx, by))
    }

    #[test]
    fn spread_interleaves_bits() {
        assert_eq!(spread(0), 0);
        assert_eq!(spread(1), 1);
        assert_eq!(spread(0b11), 0b101);
        assert_eq!(spread(0xffff), 0x5555_5555);
        // Only the low bits count.
        assert_eq!(spread(0x1_0001), 1);
        // Every bit lands on its own even position.
        for b in 0..BITS {
            assert_eq!(spread(1 << b), 1u64 << (2 * b));
        }
    }

    /// Blocks of a 4 × 4 grid of unit squares, listed row by row from the top: the
    /// Z-order visits the four quadrants one after another, each block kept whole.
    #[test]
    fn blocks_go_in_z_order_and_stay_whole() {
        let square = |x: f64, y: f64| {
            vec![
                seg(x, y, x + 1.0, y),
                seg(x + 1.0, y, x + 1.0, y + 1.0),
                seg(x + 1.0, y + 1.0, x, y + 1.0),
                seg(x, y + 1.0, x, y),
            ]
        };
        let mut segs = Vec::new();
        let mut starts = vec![0];
        for y in (0..4).rev() {
            for x in 0..4 {
                segs.extend(square(f64::from(x), f64::from(y)));
                starts.push(segs.len());
            }
        }
        let before = segs.clone();
        reorder_blocks(&mut segs, &starts);
        // The corners of the blocks in their new order.
        let corners: Vec<(f64, f64)> = segs.chunks(4).map(|c| (c[0].a.x, c[0].a.y)).collect();
        let expected: Vec<(f64, f64)> = [
            (0, 0),
            (1, 0),
            (0, 1),
            (1, 1),
            (2, 0),
            (3, 0),
            (2, 1),
            (3, 1),
            (0, 2),
            (1, 2),
            (0, 3),
            (1, 3),
            (2, 2),
            (3, 2),
            (2, 3),
            (3, 3),
        ]
        .iter()
        .map(|&(x, y)| (f64::from(x), f64::from(y)))
        .collect();
        assert_eq!(corners, expected);
        // Each block is one of the squares, whole and in its own order.
        for chunk in segs.chunks(4) {
            assert!(before.chunks(4).any(|b| b == chunk));
        }
    }

    #[test]
    fn degenerate_extents_never_panic_and_permute_the_blocks() {
        // All centres on one point; blocks of different lengths; an empty block;
        // coordinates near the largest floats.
        let big = f64::MAX;
        let cases: Vec<Vec<Segment2>> = vec![
            vec![seg(1.0, 1.0, 2.0, 2.0), seg(1.0, 1.0, 2.0, 2.0)],
            vec![
                seg(-big, -big, big, big),
                seg(big, big, -big, -big),
                seg(big, -big, -big, big),
            ],
        ];
        for segs in cases {
            let mut reordered = segs.clone();
            let starts: Vec<usize> = (0..=segs.len()).collect();
            reorder_blocks(&mut reordered, &starts);
            let mut a = reordered.clone();
            let mut b = segs.clone();
            let key = |s: &Segment2| {
                (
                    s.a.x.to_bits(),
                    s.a.y.to_bits(),
                    s.b.x.to_bits(),
                    s.b.y.to_bits(),
                )
            };
            a.sort_by_key(key);
            b.sort_by_key(key);
            assert_eq!(a, b, "a permutation of the blocks");
        }
        // Equal keys: the given order.
        let mut same = vec![seg(0.0, 0.0, 1.0, 0.0), seg(0.0, 0.0, 0.0, 1.0)];
        let before = same.clone();
        reorder_blocks(&mut same, &[0, 1, 2]);
        assert_eq!(same, before);
        // An empty block among others.
        let mut with_empty = vec![seg(5.0, 5.0, 6.0, 6.0), seg(0.0, 0.0, 1.0, 1.0)];
        reorder_blocks(&mut with_empty, &[0, 1, 1, 2]);
        assert_eq!(with_empty[0], seg(0.0, 0.0, 1.0, 1.0));
    }
}
