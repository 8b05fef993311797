//! Segments whose contributions to the winding numbers cancel, left out before the
//! noding of a boolean operation.
//!
//! A ring edge `a → b` adds one to the winding number of the points just left of it and
//! takes one from those just right of it; a second edge `b → a` of the same input undoes
//! exactly that, everywhere. Neighbouring polygons of one layer run their shared side
//! that way (every inner side of a dissolve, of a map's union), and so the side is no
//! boundary of any result. Left out before the noding, such pairs cost nothing further:
//! no pair tests, no pieces, no edges to link, sort and walk. The winding numbers of
//! every point off the segments left are unchanged, and a boolean operation reads only
//! those: its result is the same region, with the same vertices where its boundary
//! turns (a vertex only the left-out segments made lies where the boundary goes straight
//! on, and is dropped from the output anyway).
//!
//! Session 27, GEOS-837 dissolve (2580 segments, about 650 shared sides): the noding and
//! every later stage see about half the segments.

use crate::kernel::{Point2, Segment2};

const NONE: u32 = u32::MAX;

/// The segments of `segs` (the first `na` from input A, the rest from B) without those
/// whose contributions to the winding numbers cancel, and how many of those left are
/// from A; `None` when none is left out. Only input of many short rings (maps,
/// dissolves: [`super::noding::short_rings`]) is looked at; on other input a shared side
/// is rare and the look would cost more than it finds.
pub(crate) fn without_cancelling(segs: &[Segment2], na: usize) -> Option<(Vec<Segment2>, usize)> {
    if !super::noding::short_rings(segs) || !sides_shared(segs) {
        return None;
    }
    let left = left_after_cancelling(segs, |k| k < na)?;
    let left_in_a = left.partition_point(|&k| k < na);
    Some((left.into_iter().map(|k| segs[k]).collect(), left_in_a))
}

/// The numbers (ascending) of the segments of `segs` left when every class of equal
/// segments whose contributions cancel is left out: as many of its segments from input A
/// (`in_a`) run one way as the other, and likewise from input B. `None` when no class
/// cancels. (Segments of zero length count as running one way: they never cancel, and
/// add nothing to any winding number anyway.) An open-addressing hash of the segments'
/// end points (exact equality, -0 = 0), O(n) expected.
fn left_after_cancelling(segs: &[Segment2], in_a: impl Fn(usize) -> bool) -> Option<Vec<usize>> {
    let n = segs.len();
    // A table at most half full.
    let bits = (2 * n).max(16).next_power_of_two().trailing_zeros();
    let mask = (1usize << bits) - 1;
    // Per slot the first segment of a class.
    let mut slots = vec![NONE; 1 << bits];
    // Per segment the first of its class; per first the class's net count of segments
    // running from its smaller end (lexicographic) to its larger, in A and in B.
    let mut first_of: Vec<u32> = Vec::with_capacity(n);
    let mut net = vec![[0i32; 2]; n];
    let mut shared = false;
    for (k, s) in segs.iter().enumerate() {
        let (lo, hi) = ends(s);
        let up = if lo == s.a { 1 } else { -1 };
        let mut at = (hash(lo, hi) >> (64 - bits)) as usize;
        let first = loop {
            let f = slots[at];
            if f == NONE {
                slots[at] = k as u32;
                break k;
            }
            if ends(&segs[f as usize]) == (lo, hi) {
                shared = true;
                break f as usize;
            }
            at = (at + 1) & mask;
        };
        net[first][usize::from(!in_a(k))] += up;
        first_of.push(first as u32);
    }
    if !shared {
        return None;
    }
    let left: Vec<usize> = (0..n)
        .filter(|&k| net[first_of[k] as usize] != [0, 0])
        .collect();
    (left.len() < n).then_some(left)
}

/// Segments spread evenly over the input whose equals are looked for by
/// [`sides_shared`].
const SAMPLE: usize = 256;

/// Whether another segment has the same two end points as one of [`SAMPLE`] segments
/// spread evenly over `segs` (all of them for small input): where neighbouring rings
/// share sides, about half the segments have such a twin and the first is met early;
/// where none do (separate footprints, overlapping squares) the look costs one probe of
/// a table that stays in the L1 cache per segment, instead of the full hash's cache
/// misses (90,000 disjoint quads: the full hash took 6-7% of `union_all` for nothing).
fn sides_shared(segs: &[Segment2]) -> bool {
    let n = segs.len();
    if n <= 4 * SAMPLE {
        return true;
    }
    const BITS: u32 = 10; // 1024 slots for 256 samples
    let mut slots = [NONE; 1 << BITS];
    let step = n / SAMPLE;
    let slot_of = |(lo, hi): (Point2, Point2)| (hash(lo, hi) >> (64 - BITS)) as usize;
    for k in (0..n).step_by(step).take(SAMPLE) {
        let mut at = slot_of(ends(&segs[k]));
        while slots[at] != NONE {
            at = (at + 1) & ((1 << BITS) - 1);
        }
        slots[at] = k as u32;
    }
    segs.iter().enumerate().any(|(k, s)| {
        let (lo, hi) = ends(s);
        let mut at = slot_of((lo, hi));
        while slots[at] != NONE {
            let f = slots[at] as usize;
            if f != k && ends(&segs[f]) == (lo, hi) {
                return true;
            }
            at = (at + 1) & ((1 << BITS) - 1);
        }
        false
    })
}

/// The ends of `s`, the lexicographically smaller first.
#[inline(always)]
fn ends(s: &Segment2) -> (Point2, Point2) {
    if (s.a.x, s.a.y) < (s.b.x, s.b.y) {
        (s.a, s.b)
    } else {
        (s.b, s.a)
    }
}

/// A hash of the segment `lo`–`hi` (-0 folded into 0, so that equal points hash alike).
#[inline(always)]
fn hash(lo: Point2, hi: Point2) -> u64 {
    let word = |v: f64| (v + 0.0).to_bits();
    let mut h = word(lo.x).wrapping_mul(0x9E37_79B9_7F4A_7C15);
    for v in [lo.y, hi.x, hi.y] {
        h = (h.rotate_left(29) ^ word(v)).wrapping_mul(0xD6E8_FEB8_6659_FD93);
    }
    h
}

#[cfg(test)]
mod tests {
    use super::*;

    fn seg(a: (f64, f64), b: (f64, f64)) -> Segment2 {
        Segment2::new(Point2::new(a.0, a.1), Point2::new(b.0, b.1))
    }

    #[test]
    fn opposite_sides_of_one_input_cancel() {
        // Two triangles sharing the side (1,0)–(0,1), run both ways.
        let segs = [
            seg((0.0, 0.0), (1.0, 0.0)),
            seg((1.0, 0.0), (0.0, 1.0)),
            seg((0.0, 1.0), (0.0, 0.0)),
            seg((1.0, 0.0), (1.0, 1.0)),
            seg((1.0, 1.0), (0.0, 1.0)),
            seg((0.0, 1.0), (1.0, 0.0)),
        ];
        assert_eq!(
            left_after_cancelling(&segs, |_| true),
            Some(vec![0, 2, 3, 4])
        );
        // From different inputs they do not cancel.
        assert_eq!(left_after_cancelling(&segs, |k| k < 3), None);
    }

    #[test]
    fn a_triangulated_square_keeps_only_its_outline() {
        // A 2 × 2 grid of cells, each cut by a diagonal: 8 counter-clockwise triangles,
        // 24 segments, of which 16 run the 8 inner sides both ways.
        let q = |x: i32, y: i32| Point2::new(f64::from(x) * 0.1, f64::from(y) * 0.1);
        let mut polygons = Vec::new();
        for (x, y) in [(0, 0), (1, 0), (0, 1), (1, 1)] {
            let (p00, p10, p11, p01) = (q(x, y), q(x + 1, y), q(x + 1, y + 1), q(x, y + 1));
            polygons.push(crate::Polygon::new(vec![p00, p10, p11], vec![]));
            polygons.push(crate::Polygon::new(vec![p00, p11, p01], vec![]));
        }
        let set = crate::MultiPolygon(polygons);
        let (segs, _) = crate::dcel::polygon_segments(&set).unwrap();
        assert_eq!(segs.len(), 24);
        let (left, in_a) = without_cancelling(&segs, segs.len()).unwrap();
        assert_eq!((left.len(), in_a), (8, 8));
        // Every segment left lies on the square's outline.
        let on_outline =
            |p: Point2| p.x == 0.0 || p.y == 0.0 || p.x == q(2, 2).x || p.y == q(2, 2).y;
        assert!(left.iter().all(|s| on_outline(s.a) && on_outline(s.b)));
        // The bottom row in A, the top row in B: the two sides between the rows stay,
        // once in each.
        let (left, in_a) = without_cancelling(&segs, 12).unwrap();
        assert_eq!((left.len(), in_a), (12, 6));
        assert_eq!(
            left.iter()
                .filter(|s| s.a.y == q(0, 1).y && s.b.y == s.a.y)
                .count(),
            4
        );
        // The dissolve: one square (its sides' midpoints dropped: collinear).
        let union = crate::overlay::union_all(&set).unwrap();
        assert_eq!(union.0.len(), 1);
        assert_eq!(union.0[0].exterior.len(), 4);
        assert!(union.0[0].holes.is_empty());
    }

    #[test]
    fn shared_sides_are_seen_from_a_sample() {
        // 2000 separate unit squares: no side shared, so nothing is looked up.
        let square = |x: f64, y: f64| {
            let p = [(x, y), (x + 1.0, y), (x + 1.0, y + 1.0), (x, y + 1.0)];
            (0..4).map(move |i| seg(p[i], p[(i + 1) % 4]))
        };
        let apart: Vec<Segment2> = (0..2000)
            .flat_map(|k| square(2.0 * f64::from(k % 50), 2.0 * f64::from(k / 50)))
            .collect();
        assert!(!sides_shared(&apart));
        assert_eq!(without_cancelling(&apart, apart.len()), None);
        // Touching squares (a grid of them) share sides: seen, and cancelled.
        let grid: Vec<Segment2> = (0..2000)
            .flat_map(|k| square(f64::from(k % 50), f64::from(k / 50)))
            .collect();
        assert!(sides_shared(&grid));
        let (left, _) = without_cancelling(&grid, grid.len()).unwrap();
        // The outline of the 50 × 40 block: 2 · (50 + 40) unit sides.
        assert_eq!(left.len(), 180);
        // A reversed copy of a sampled segment (the first is) is seen wherever it is;
        // one of a segment between the samples may not be (then nothing is cancelled,
        // which is still right).
        let mut one = apart.clone();
        one.push(Segment2::new(one[0].b, one[0].a));
        assert!(sides_shared(&one));
        let (left, _) = without_cancelling(&one, one.len()).unwrap();
        assert_eq!(left.len(), apart.len() - 1);
    }

    #[test]
    fn classes_cancel_only_when_their_net_count_is_zero() {
        let ab = seg((0.0, 0.0), (2.0, 1.0));
        let ba = seg((2.0, 1.0), (0.0, 0.0));
        let other = seg((-0.0, 0.0), (2.0, 3.0));
        // Twice one way, once the other: +1 left, all three kept.
        assert_eq!(left_after_cancelling(&[ab, ab, ba, other], |_| true), None);
        // Twice each way, -0 equal to 0: the class goes.
        let ab0 = seg((-0.0, 0.0), (2.0, 1.0));
        assert_eq!(
            left_after_cancelling(&[ab, other, ba, ab0, ba], |_| true),
            Some(vec![1])
        );
        // A and B each cancel on their own: +1 -1 in A, +1 -1 in B.
        assert_eq!(
            left_after_cancelling(&[ab, ba, ab, ba, other], |k| k < 2),
            Some(vec![4])
        );
        // +1 in A and -1 in B do not cancel.
        assert_eq!(left_after_cancelling(&[ab, ba], |k| k < 1), None);
    }
}
