//! Constructed segment crossings, kept as the two segments that define them.
//! (Initial API; the kernel work makes every comparison exact.)

use super::predicates::Orientation;
use super::types::{Point2, Segment2};
use std::cmp::Ordering;

/// The crossing point of two non-parallel segments' supporting lines, represented by
/// the segments themselves. Comparisons are exact; [`Crossing::approx`] rounds.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Crossing {
    /// First defining segment.
    pub s: Segment2,
    /// Second defining segment.
    pub t: Segment2,
}

impl Crossing {
    /// The crossing of the lines through `s` and `t`, or `None` when the lines are parallel
    /// (or a segment is degenerate).
    pub fn new(s: Segment2, t: Segment2) -> Option<Crossing> {
        let _ = (s, t);
        None
    }

    /// The nearest `f64` point to the exact crossing (for reporting only).
    pub fn approx(&self) -> Point2 {
        self.s.a
    }

    /// Exact lexicographic comparison (x, then y) of the crossing with an input point.
    pub fn compare_xy_point(&self, p: Point2) -> Ordering {
        let _ = p;
        Ordering::Equal
    }

    /// Exact lexicographic comparison (x, then y) of two crossings.
    pub fn compare_xy(&self, other: &Crossing) -> Ordering {
        let _ = other;
        Ordering::Equal
    }

    /// Exact orientation of `(a, b, crossing)`.
    pub fn orient(a: Point2, b: Point2, c: &Crossing) -> Orientation {
        let _ = (a, b, c);
        Orientation::Collinear
    }
}
