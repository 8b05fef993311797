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
//! The classes of equal segments come from the end vertices the noding hashes anyway
//! (input of many short rings, see [`super::noding`]; other input is not looked at: a
//! shared side is rare there and the look would cost more than it finds), and they are
//! also the noding's copies (a class's segments left are tested once).
//!
//! Session 27, GEOS-837 dissolve (2580 segments, about 650 shared sides): the noding and
//! every later stage see about half the segments.

const NONE: u32 = u32::MAX;

/// The classes of segments with the same two end vertices (either way round) and which of
/// them cancel, from the segments' end vertices `of` (equal points one vertex: the
/// noding's hashed ends). A class cancels when as many of its segments from input A
/// (`in_a`) run one way as the other, and likewise from input B. Returns per segment the
/// first segment of its class, and the numbers (ascending) of the segments left when
/// every class that cancels is left out (`None` when none does). (Segments of zero
/// length count as running one way: they never cancel, and add nothing to any winding
/// number anyway.) An open-addressing hash of the vertex pairs, O(n) expected.
pub(super) fn classes(
    of: &[[u32; 2]],
    in_a: impl Fn(usize) -> bool,
) -> (Vec<u32>, Option<Vec<usize>>) {
    let n = of.len();
    // A table at most half full.
    let bits = (2 * n).max(16).next_power_of_two().trailing_zeros();
    let mask = (1usize << bits) - 1;
    let key = |[u, v]: [u32; 2]| {
        let (lo, hi) = if u <= v { (u, v) } else { (v, u) };
        u64::from(lo) << 32 | u64::from(hi)
    };
    // Per slot the first segment of a class (its key read from `of`).
    let mut slots = vec![NONE; 1 << bits];
    // Per first the class's net count of segments running from its smaller vertex to
    // its larger, in A and in B.
    let mut net = vec![[0i32; 2]; n];
    let mut first_of: Vec<u32> = Vec::with_capacity(n);
    let mut shared = false;
    for (k, &e) in of.iter().enumerate() {
        let want = key(e);
        let up = if e[0] <= e[1] { 1 } else { -1 };
        let mut at = (want.wrapping_mul(0x9E37_79B9_7F4A_7C15) >> (64 - bits)) as usize;
        let first = loop {
            let f = slots[at];
            if f == NONE {
                slots[at] = k as u32;
                break k;
            }
            if key(of[f as usize]) == want {
                shared = true;
                break f as usize;
            }
            at = (at + 1) & mask;
        };
        net[first][usize::from(!in_a(k))] += up;
        first_of.push(first as u32);
    }
    if !shared {
        return (first_of, None);
    }
    // (Room for all: growing the list from empty cost the GEOS-837 dissolve 0.3%.)
    let mut left: Vec<usize> = Vec::with_capacity(n);
    left.extend((0..n).filter(|&k| net[first_of[k] as usize] != [0, 0]));
    let left = (left.len() < n).then_some(left);
    (first_of, left)
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::dcel::Flat;
    use crate::kernel::{Point2, Segment2};

    fn seg(a: (f64, f64), b: (f64, f64)) -> Segment2 {
        Segment2::new(Point2::new(a.0, a.1), Point2::new(b.0, b.1))
    }

    /// The segments left by [`classes`], with vertices from a plain map of the points
    /// (exact equality, -0 = 0).
    fn left_of(segs: &[Segment2], in_a: impl Fn(usize) -> bool) -> Option<Vec<usize>> {
        let mut vertex = std::collections::HashMap::new();
        let mut id = |p: Point2| {
            let n = vertex.len() as u32;
            *vertex
                .entry(((p.x + 0.0).to_bits(), (p.y + 0.0).to_bits()))
                .or_insert(n)
        };
        let of: Vec<[u32; 2]> = segs.iter().map(|s| [id(s.a), id(s.b)]).collect();
        classes(&of, in_a).1
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
        assert_eq!(left_of(&segs, |_| true), Some(vec![0, 2, 3, 4]));
        // From different inputs they do not cancel.
        assert_eq!(left_of(&segs, |k| k < 3), None);
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
        let left = |na: usize| {
            let (left, flat, deltas) = Flat::of_segments_summed_cancelling(&segs, na).unwrap();
            let (left, in_a) = left.expect("inner sides cancel");
            // The arrangement of the segments left, as if they were the input.
            let (again, deltas_again) = Flat::of_segments_summed(&left, in_a).unwrap();
            assert_eq!(flat.edges, again.edges);
            assert_eq!(deltas, deltas_again);
            (left, in_a)
        };
        let (all, in_a) = left(segs.len());
        assert_eq!((all.len(), in_a), (8, 8));
        // Every segment left lies on the square's outline.
        let on_outline =
            |p: Point2| p.x == 0.0 || p.y == 0.0 || p.x == q(2, 2).x || p.y == q(2, 2).y;
        assert!(all.iter().all(|s| on_outline(s.a) && on_outline(s.b)));
        // The bottom row in A, the top row in B: the two sides between the rows stay,
        // once in each.
        let (rows, in_a) = left(12);
        assert_eq!((rows.len(), in_a), (12, 6));
        assert_eq!(
            rows.iter()
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
    fn shared_sides_cancel_wherever_they_are() {
        // 2000 separate unit squares: no side shared, nothing cancelled.
        let square = |x: f64, y: f64| {
            let p = [(x, y), (x + 1.0, y), (x + 1.0, y + 1.0), (x, y + 1.0)];
            (0..4).map(move |i| seg(p[i], p[(i + 1) % 4]))
        };
        let apart: Vec<Segment2> = (0..2000)
            .flat_map(|k| square(2.0 * f64::from(k % 50), 2.0 * f64::from(k / 50)))
            .collect();
        assert_eq!(left_of(&apart, |_| true), None);
        // Touching squares (a grid of them) share sides: cancelled, leaving the outline
        // of the 50 × 40 block, 2 · (50 + 40) unit sides.
        let grid: Vec<Segment2> = (0..2000)
            .flat_map(|k| square(f64::from(k % 50), f64::from(k / 50)))
            .collect();
        assert_eq!(left_of(&grid, |_| true).map(|l| l.len()), Some(180));
        // A reversed copy of any one segment cancels it.
        for k in [0, 777, 7999] {
            let mut one = apart.clone();
            one.push(Segment2::new(one[k].b, one[k].a));
            let left = left_of(&one, |_| true).unwrap();
            assert_eq!(left.len(), apart.len() - 1);
            assert!(!left.contains(&k));
        }
    }

    #[test]
    fn classes_cancel_only_when_their_net_count_is_zero() {
        let ab = seg((0.0, 0.0), (2.0, 1.0));
        let ba = seg((2.0, 1.0), (0.0, 0.0));
        let other = seg((-0.0, 0.0), (2.0, 3.0));
        // Twice one way, once the other: +1 left, all three kept.
        assert_eq!(left_of(&[ab, ab, ba, other], |_| true), None);
        // Twice each way, -0 equal to 0: the class goes.
        let ab0 = seg((-0.0, 0.0), (2.0, 1.0));
        assert_eq!(left_of(&[ab, other, ba, ab0, ba], |_| true), Some(vec![1]));
        // A and B each cancel on their own: +1 -1 in A, +1 -1 in B.
        assert_eq!(left_of(&[ab, ba, ab, ba, other], |k| k < 2), Some(vec![4]));
        // +1 in A and -1 in B do not cancel.
        assert_eq!(left_of(&[ab, ba], |k| k < 1), None);
        // A point never cancels (it runs "one way" both times).
        let dot = seg((1.0, 1.0), (1.0, 1.0));
        assert_eq!(left_of(&[dot, dot, ab, ba], |_| true), Some(vec![0, 1]));
    }
}
