//! The fast default for most inputs: exact tests of the pairs of segments whose x-ranges
//! overlap (found by sorting the segments by their left end), with a bounding-box reject
//! first, then the same exact grouping as the brute-force oracle.
//!
//! O(n log n + m + K log K) time for m pairs with overlapping x-ranges and K meeting
//! pairs; O(n + K) space. It beats the sweep whenever m is not much larger than n (most
//! real inputs: short segments, grids, dense crossings), and loses when many long
//! segments share x-ranges without meeting; [`super::find_intersections`] decides between
//! the two by counting m first (O(n log n)).

use super::brute_force::PairResults;
use super::sweep::check_finite;
use super::Intersections;
use crate::kernel::Segment2;
use crate::Result;
use rayon::prelude::*;

/// From this many segments on, the pair scan runs on the rayon pool.
const PARALLEL_SCAN_FROM: usize = 20_000;

/// From this many (point, pair) records on, the points are built (and rounded) on the
/// rayon pool.
pub(crate) const PARALLEL_GROUPING_FROM: usize = 200_000;

/// Bounding boxes `[min x, max x, min y, max y]` and the segment order by min x.
fn boxes(segments: &[Segment2]) -> (Vec<[f64; 4]>, Vec<usize>) {
    let b: Vec<[f64; 4]> = segments
        .iter()
        .map(|s| {
            [
                s.a.x.min(s.b.x),
                s.a.x.max(s.b.x),
                s.a.y.min(s.b.y),
                s.a.y.max(s.b.y),
            ]
        })
        .collect();
    let mut order: Vec<usize> = (0..segments.len()).collect();
    // Finite coordinates (checked by the callers): total_cmp agrees with < except that it
    // orders -0.0 before 0.0, which only makes the scan below test one more pair.
    order.sort_unstable_by(|&i, &j| b[i][0].total_cmp(&b[j][0]));
    (b, order)
}

/// The number of pairs of segments whose x-ranges overlap, or `None` once it exceeds
/// `limit`. O(n log n).
pub(crate) fn x_overlapping_pairs(segments: &[Segment2], limit: usize) -> Option<usize> {
    let (b, order) = boxes(segments);
    let lefts: Vec<f64> = order.iter().map(|&i| b[i][0]).collect();
    let mut total = 0usize;
    for (k, &i) in order.iter().enumerate() {
        // Segments after k in the order that start at or before this one's right end.
        let end = lefts.partition_point(|&x| x <= b[i][1]);
        total += end.saturating_sub(k + 1);
        if total > limit {
            return None;
        }
    }
    Some(total)
}

/// All intersection points and overlaps (the answer of [`super::find_intersections`]) by
/// exact tests of the pairs whose bounding boxes overlap.
///
/// ```
/// use compgeom::intersect::{pairwise_intersections, sweep_intersections};
/// use compgeom::Segment2;
/// let s = |a: (f64, f64), b: (f64, f64)| Segment2::new(a.into(), b.into());
/// let segs = [s((0.0, 0.0), (2.0, 2.0)), s((0.0, 2.0), (2.0, 0.0)), s((1.0, 0.0), (1.0, 3.0))];
/// assert_eq!(pairwise_intersections(&segs).unwrap(), sweep_intersections(&segs).unwrap());
/// ```
pub fn pairwise_intersections(segments: &[Segment2]) -> Result<Intersections> {
    check_finite(segments)?;
    let (b, order) = boxes(segments);
    // The boxes in scan order, so that the inner loop reads memory in sequence.
    let sorted: Vec<([f64; 4], usize)> = order.iter().map(|&i| (b[i], i)).collect();
    // The scan from position k onwards: every pair (order[k], later) whose boxes overlap.
    let scan = |k: usize, found: &mut PairResults| {
        let (bi, i) = sorted[k];
        for &(bj, j) in &sorted[k + 1..] {
            if bj[0] > bi[1] {
                break;
            }
            if bj[2] > bi[3] || bi[2] > bj[3] {
                continue;
            }
            found.test(segments, i.min(j), i.max(j));
        }
    };
    let found = if segments.len() < PARALLEL_SCAN_FROM {
        let mut found = PairResults::default();
        (0..order.len()).for_each(|k| scan(k, &mut found));
        found
    } else {
        // Independent scans on the rayon pool; the grouping sorts everything, so the
        // result does not depend on how the work was split.
        (0..order.len())
            .into_par_iter()
            .with_min_len(1024)
            .fold(PairResults::default, |mut found, k| {
                scan(k, &mut found);
                found
            })
            .reduce(PairResults::default, PairResults::merge)
    };
    Ok(found.assemble(segments))
}
