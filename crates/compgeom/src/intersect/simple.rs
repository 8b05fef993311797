//! "Is there any intersection?" (the Shamos–Hoey idea: sweep and stop at the first one)
//! and polygon simplicity built on it.
//!
//! The sweep is the full one of [`super::find_intersections`] stopped at the first
//! intersection point that counts. Intersection points come out in sweep order, so the
//! answer is the first counting point in that order. Time O((n + k) log n), where k is the
//! number of intersection points the caller's rule ignores before the first one that counts
//! (for [`is_simple`], at most the number of vertices): O(n log n).

use super::sweep::{sweep, Flow, Sink};
use super::{IntersectionPoint, Overlap};
use crate::kernel::{Point2, Polygon, Segment2};
use crate::Result;

struct First<F> {
    counts: F,
    found: Option<IntersectionPoint>,
}

impl<F: FnMut(&IntersectionPoint) -> bool> Sink for First<F> {
    fn point(&mut self, point: IntersectionPoint) -> Flow {
        if (self.counts)(&point) {
            self.found = Some(point);
            Flow::Stop
        } else {
            Flow::Continue
        }
    }
    fn overlap(&mut self, _: Overlap) -> Flow {
        // An overlap's first end is an intersection point, already offered to `counts`.
        Flow::Continue
    }
}

/// The first point (in sweep order) shared by two or more of the closed segments, or
/// `None` when no two segments meet. Every kind of contact counts: crossings, shared
/// endpoints, an endpoint on another segment, overlaps (their first end), and a
/// zero-length segment on another segment.
///
/// ```
/// use compgeom::intersect::any_intersection;
/// use compgeom::{Point2, Segment2};
/// let s = |a: (f64, f64), b: (f64, f64)| Segment2::new(a.into(), b.into());
/// assert!(any_intersection(&[s((0.0, 0.0), (1.0, 1.0)), s((2.0, 0.0), (3.0, 1.0))]).unwrap().is_none());
/// let hit = any_intersection(&[s((0.0, 0.0), (2.0, 2.0)), s((0.0, 2.0), (2.0, 0.0))]).unwrap().unwrap();
/// assert_eq!(hit.point, Point2::new(1.0, 1.0));
/// ```
pub fn any_intersection(segments: &[Segment2]) -> Result<Option<IntersectionPoint>> {
    any_intersection_where(segments, |_| true)
}

/// The first intersection point (in sweep order) for which `counts` returns true; points
/// it rejects are skipped. Errors: a non-finite coordinate (naming the segment).
pub fn any_intersection_where(
    segments: &[Segment2],
    counts: impl FnMut(&IntersectionPoint) -> bool,
) -> Result<Option<IntersectionPoint>> {
    let mut sink = First {
        counts,
        found: None,
    };
    sweep(segments, &mut sink)?;
    Ok(sink.found)
}

/// The ring without consecutive repeated vertices (cyclically, so a closing copy of the
/// first vertex goes too).
pub(crate) fn clean_ring(ring: &[Point2]) -> Vec<Point2> {
    let mut out: Vec<Point2> = Vec::with_capacity(ring.len());
    for &p in ring {
        if out.last() != Some(&p) {
            out.push(p);
        }
    }
    while out.len() > 1 && out.first() == out.last() {
        out.pop();
    }
    out
}

/// True when the polygon's boundary is simple: every ring is a simple closed curve and no
/// two rings meet.
///
/// The exact rule: consecutive repeated vertices are ignored (so a closing copy of the
/// first vertex is allowed); then every ring must have at least 3 vertices, and two edges
/// (of any rings) may share a point only when they are consecutive edges of one ring and
/// the point is their common vertex, with no other edge through it. Everything else makes
/// the polygon non-simple: crossings, a vertex touching another edge or another vertex of
/// the same ring (self-tangency), overlapping edges, and rings (shell or holes) touching
/// each other. This is the simplicity of the boundary as a set of disjoint simple closed
/// curves; it does not check orientation or that holes lie inside the shell.
///
/// O(n log n) time for n vertices. Errors: a non-finite coordinate, named as "segment i"
/// where edges are numbered ring by ring (shell first), edge j of a ring going from
/// vertex j to vertex j + 1 after repeated vertices are dropped.
///
/// ```
/// use compgeom::intersect::is_simple;
/// use compgeom::{Point2, Polygon};
/// let p = |x, y| Point2::new(x, y);
/// let square = Polygon::new(vec![p(0.0, 0.0), p(4.0, 0.0), p(4.0, 4.0), p(0.0, 4.0)], vec![]);
/// assert!(is_simple(&square).unwrap());
/// let bowtie = Polygon::new(vec![p(0.0, 0.0), p(4.0, 4.0), p(4.0, 0.0), p(0.0, 4.0)], vec![]);
/// assert!(!is_simple(&bowtie).unwrap());
/// ```
pub fn is_simple(polygon: &Polygon) -> Result<bool> {
    let mut segments = Vec::new();
    // For every edge: (ring, position in the ring, ring length).
    let mut edge_of = Vec::new();
    for (r, ring) in polygon.rings().enumerate() {
        let ring = clean_ring(ring);
        if ring.len() < 3 {
            return Ok(false);
        }
        for k in 0..ring.len() {
            segments.push(Segment2::new(ring[k], ring[(k + 1) % ring.len()]));
            edge_of.push((r, k, ring.len()));
        }
    }
    let consecutive = |i: usize, j: usize| {
        let ((ri, ki, n), (rj, kj, _)) = (edge_of[i], edge_of[j]);
        ri == rj && ((ki + 1) % n == kj || (kj + 1) % n == ki)
    };
    let bad = any_intersection_where(&segments, |p| {
        let s = p.segments();
        !(s.len() == 2 && p.interior().is_empty() && consecutive(s[0], s[1]))
    })?;
    Ok(bad.is_none())
}
