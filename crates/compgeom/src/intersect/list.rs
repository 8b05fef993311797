//! [`IntersectionPoint`]: one reported point, kept small.
//!
//! Dense inputs report hundreds of thousands of points, nearly all of them two segments
//! crossing. The record is 40 bytes: the rounded point and the four segment lists, with
//! which two segments define the point when it is a crossing (the exact point is rebuilt
//! from them on demand, [`IntersectionPoint::exact`], instead of carrying two copies of
//! the segments). Writing the records was most of the cost of the dense case when they
//! were 184 bytes (the memory is fresh, so every page is a fault); 56 → 40 bytes cut the
//! result of long 1e3 (251k points) from 14 to 10 MB.
//!
//! The lists: with at most two segments every list is a sub-slice of the sorted pair
//! (`[]`, `[i]`, `[j]` or `[i, j]`), so they are kept inline as ranges into it (no heap
//! allocation: a crossing, a shared endpoint, an endpoint on another segment). With more
//! segments one heap slice holds where the first three lists end and the defining pair's
//! second position, then `segments ++ upper ++ lower ++ interior`.

use crate::kernel::{orient2d, Crossing, ExactPoint, Orientation, Point2, Segment2};
use std::fmt;

/// Marks an input point in [`Lists::Heap`]'s header (no defining pair).
const INPUT: usize = usize::MAX;

/// In [`Lists::Inline`]'s `len`: the point is a crossing of the two segments (the
/// defining pair is both of them; an input point has none).
const CROSSING: u8 = 0x80;

/// The lists of an [`IntersectionPoint`] (24 bytes: the tag and the small fields of
/// `Inline` share the first word).
#[derive(Clone)]
enum Lists {
    /// At most two segments, sorted in `ids[..len & !CROSSING]`; `ranges` are the
    /// sub-slices of U(p), L(p) and C(p).
    Inline {
        ids: [usize; 2],
        len: u8,
        ranges: [[u8; 2]; 3],
    },
    /// `[end of segments, end of upper, end of lower, second] ++ segments ++ upper ++
    /// lower ++ interior`, the ends counted from the start of `segments`; `second` is
    /// the position in `segments` of the defining pair's second segment, [`INPUT`] for an
    /// input point.
    Heap { ids: Box<[usize]> },
}

/// Where [`Lists::Heap`]'s lists start.
const HEADER: usize = 4;

/// A point where two or more segments meet, with the segments through it.
///
/// The lists are slices, ascending: [`segments`](Self::segments) (all of them),
/// [`upper`](Self::upper) U(p), [`lower`](Self::lower) L(p) and
/// [`interior`](Self::interior) C(p). A point is either an input point (an endpoint of
/// some segment; then [`point`](Self::point) is it exactly) or a proper crossing, whose
/// exact point [`exact`](Self::exact) rebuilds from the two segments that define it.
///
/// Two values are equal when they have the same rounded point, the same lists and the same
/// defining pair. For results on the same input that is the same exact point: a crossing's
/// segments include two that are not collinear, and those meet in one point only.
///
/// ```
/// use compgeom::intersect::find_intersections;
/// use compgeom::{Point2, Segment2};
/// let s = |a: (f64, f64), b: (f64, f64)| Segment2::new(a.into(), b.into());
/// let segs = [s((0.0, 0.0), (3.0, 1.0)), s((0.0, 1.0), (3.0, 0.0))];
/// let found = find_intersections(&segs).unwrap();
/// let p = &found.points[0];
/// assert_eq!(p.point, Point2::new(1.5, 0.5));
/// assert_eq!(p.segments(), [0, 1]);
/// assert_eq!(p.interior(), [0, 1]);
/// assert!(p.upper().is_empty() && p.lower().is_empty());
/// assert_eq!(p.crossing_pair(), Some((0, 1)));
/// assert_eq!(p.exact(&segs).approx(), p.point);
/// ```
#[derive(Clone)]
pub struct IntersectionPoint {
    /// The nearest `f64` point (the exact point for input points).
    pub point: Point2,
    lists: Lists,
}

/// The position in a list of `u8` indices (lists of at most two).
fn range_in(all: &[usize], part: &[usize]) -> [u8; 2] {
    match part.first() {
        None => [0, 0],
        Some(first) => {
            let start = all.iter().position(|s| s == first).unwrap_or(0);
            [start as u8, (start + part.len()) as u8]
        }
    }
}

impl IntersectionPoint {
    /// Two segments `i < j` crossing properly at `point` (no input point there).
    #[inline]
    pub(crate) fn crossing(point: Point2, i: usize, j: usize) -> IntersectionPoint {
        IntersectionPoint {
            point,
            lists: Lists::Inline {
                ids: [i, j],
                len: 2 | CROSSING,
                ranges: [[0, 0], [0, 0], [0, 2]],
            },
        }
    }

    /// A point from its sorted lists (U, L and C subsets of `segments`). `second`: for
    /// a crossing, the position in `segments` of the defining pair's second segment
    /// ([`defining_second`]); `None` for an input point.
    pub(crate) fn new(
        point: Point2,
        segments: &[usize],
        [upper, lower, interior]: [&[usize]; 3],
        second: Option<usize>,
    ) -> IntersectionPoint {
        let lists = if segments.len() <= 2 {
            let mut ids = [0; 2];
            ids[..segments.len()].copy_from_slice(segments);
            // A crossing of at most two segments is defined by both (`second` is 1).
            debug_assert!(matches!(second, None | Some(1)), "second {second:?}");
            let flag = if second.is_some() { CROSSING } else { 0 };
            // Every subset of a sorted list of two is a contiguous sub-slice of it.
            Lists::Inline {
                ids,
                len: segments.len() as u8 | flag,
                ranges: [
                    range_in(segments, upper),
                    range_in(segments, lower),
                    range_in(segments, interior),
                ],
            }
        } else {
            let mut ends = [0; 3];
            let mut at = 0;
            for (k, part) in [segments, upper, lower].into_iter().enumerate() {
                at += part.len();
                ends[k] = at;
            }
            let mut ids = Vec::with_capacity(HEADER + at + interior.len());
            ids.extend_from_slice(&ends);
            ids.push(second.unwrap_or(INPUT));
            for part in [segments, upper, lower, interior] {
                ids.extend_from_slice(part);
            }
            Lists::Heap {
                ids: ids.into_boxed_slice(),
            }
        };
        IntersectionPoint { point, lists }
    }

    fn list(&self, k: usize) -> &[usize] {
        match &self.lists {
            Lists::Inline { ids, len, ranges } => {
                if k == 0 {
                    &ids[..usize::from(len & !CROSSING)]
                } else {
                    let [a, b] = ranges[k - 1];
                    &ids[usize::from(a)..usize::from(b)]
                }
            }
            Lists::Heap { ids } => {
                let (header, lists) = ids.split_at(HEADER);
                let start = if k == 0 { 0 } else { header[k - 1] };
                let end = if k == 3 { lists.len() } else { header[k] };
                &lists[start..end]
            }
        }
    }

    /// For a crossing: the position in `segments()` of the defining pair's second
    /// segment (the first is `segments()[0]`).
    fn second(&self) -> Option<usize> {
        match &self.lists {
            Lists::Inline { len, .. } => (len & CROSSING != 0).then_some(1),
            Lists::Heap { ids } => (ids[HEADER - 1] != INPUT).then_some(ids[HEADER - 1]),
        }
    }

    /// Every segment containing the point, ascending.
    #[inline]
    pub fn segments(&self) -> &[usize] {
        self.list(0)
    }

    /// U(p): segments whose upper endpoint (first in sweep order) is the point, ascending.
    #[inline]
    pub fn upper(&self) -> &[usize] {
        self.list(1)
    }

    /// L(p): segments whose lower endpoint is the point, ascending.
    #[inline]
    pub fn lower(&self) -> &[usize] {
        self.list(2)
    }

    /// C(p): segments with the point in their interior, ascending.
    #[inline]
    pub fn interior(&self) -> &[usize] {
        self.list(3)
    }

    /// Whether the point is a proper crossing (no input point lies there).
    pub fn is_crossing(&self) -> bool {
        self.second().is_some()
    }

    /// For a crossing, the two segments (ascending) that define it: the first of
    /// [`segments`](Self::segments) and the next one not collinear with it.
    pub fn crossing_pair(&self) -> Option<(usize, usize)> {
        let s = self.segments();
        self.second().map(|k| (s[0], s[k]))
    }

    /// The exact point: the input point, or the crossing of the two defining segments
    /// taken from `segments`, the input the point was found in.
    ///
    /// # Panics
    /// If `segments` is shorter than that input (not the input of this result).
    pub fn exact(&self, segments: &[Segment2]) -> ExactPoint {
        match self.crossing_pair() {
            None => ExactPoint::Input(self.point),
            Some((i, j)) => ExactPoint::Crossing(Crossing {
                s: segments[i],
                t: segments[j],
            }),
        }
    }
}

/// The position in `list` (sorted segments through a crossing, at least two) of the
/// first segment not collinear with `list[0]`: with `list[0]` the canonical defining
/// pair of the crossing (two segments through a point that is no input point; not all
/// of them lie on one line, else the point would be inside an overlap, not a crossing).
pub(crate) fn defining_second(list: &[usize], segment: impl Fn(usize) -> Segment2) -> usize {
    let s = segment(list[0]);
    let collinear = |p| orient2d(s.a, s.b, p) == Orientation::Collinear;
    list.iter()
        .skip(1)
        .position(|&k| {
            let t = segment(k);
            !(collinear(t.a) && collinear(t.b))
        })
        .map_or(1, |k| k + 1)
}

impl fmt::Debug for IntersectionPoint {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.debug_struct("IntersectionPoint")
            .field("point", &self.point)
            .field("segments", &self.segments())
            .field("upper", &self.upper())
            .field("lower", &self.lower())
            .field("interior", &self.interior())
            .field("crossing_pair", &self.crossing_pair())
            .finish()
    }
}

impl PartialEq for IntersectionPoint {
    fn eq(&self, other: &Self) -> bool {
        self.point == other.point
            && self.second() == other.second()
            && (0..4).all(|k| self.list(k) == other.list(k))
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_record_is_small() {
        assert!(std::mem::size_of::<IntersectionPoint>() <= 40);
    }

    #[test]
    fn inline_and_heap_lists_read_back() {
        let p = Point2::new(1.0, 2.0);
        // Every split of one or two segments into U/L/C (a zero-length one in U and L).
        let cases: [(&[usize], [&[usize]; 3]); 7] = [
            (&[4], [&[4], &[4], &[]]),
            (&[3, 9], [&[3], &[], &[9]]),
            (&[3, 9], [&[9], &[3], &[]]),
            (&[3, 9], [&[], &[3, 9], &[]]),
            (&[3, 9], [&[3, 9], &[9], &[]]),
            (&[3, 9], [&[], &[], &[3, 9]]),
            (&[0, 1, 5, 8], [&[1, 8], &[0], &[5]]),
        ];
        for (all, [u, l, c]) in cases {
            let q = IntersectionPoint::new(p, all, [u, l, c], None);
            assert_eq!(
                (q.segments(), q.upper(), q.lower(), q.interior()),
                (all, u, l, c)
            );
            assert!(!q.is_crossing());
            assert_eq!(q.crossing_pair(), None);
        }
        let x = IntersectionPoint::crossing(p, 2, 7);
        assert_eq!(
            x,
            IntersectionPoint::new(p, &[2, 7], [&[], &[], &[2, 7]], Some(1))
        );
        assert_eq!(x.crossing_pair(), Some((2, 7)));
        assert_ne!(
            x,
            IntersectionPoint::new(p, &[2, 7], [&[], &[], &[2, 7]], None)
        );
        let many = IntersectionPoint::new(p, &[1, 2, 3], [&[], &[], &[1, 2, 3]], Some(2));
        assert_eq!(many.crossing_pair(), Some((1, 3)));
        assert_eq!(
            format!("{x:?}"),
            "IntersectionPoint { point: Point2 { x: 1.0, y: 2.0 }, segments: [2, 7], upper: [], \
             lower: [], interior: [2, 7], crossing_pair: Some((2, 7)) }"
        );
    }

    #[test]
    fn the_defining_pair_skips_collinear_segments() {
        let s = |a: (f64, f64), b: (f64, f64)| Segment2::new(a.into(), b.into());
        // Segments 0 and 1 are duplicates, 2 lies on their line, 3 crosses them.
        let segs = [
            s((0.0, 0.0), (4.0, 4.0)),
            s((0.0, 0.0), (4.0, 4.0)),
            s((1.0, 1.0), (3.0, 3.0)),
            s((0.0, 4.0), (4.0, 0.0)),
        ];
        assert_eq!(defining_second(&[0, 1, 2, 3], |k| segs[k]), 3);
        assert_eq!(defining_second(&[0, 3], |k| segs[k]), 1);
    }
}
