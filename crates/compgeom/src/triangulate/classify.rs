//! The five vertex types of §3.2 (start, split, end, merge, regular) under the book's
//! order: `p` is below `q` when `p.y < q.y`, or `p.y = q.y` and `p.x > q.x`.
//!
//! With that order no two vertices are level, so a horizontal edge counts as going down
//! to the right, and the types are exactly those of the polygon turned by an
//! infinitesimal angle. Exact: coordinate comparisons and one [`crate::kernel::orient2d`]
//! per vertex. O(n).
use super::geometry::Geometry;
use std::cmp::Ordering;

/// The type of a polygon vertex in the sweep of §3.2.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
pub enum VertexType {
    /// Both neighbours below, interior angle < π.
    Start,
    /// Both neighbours below, interior angle > π.
    Split,
    /// Both neighbours above, interior angle < π.
    End,
    /// Both neighbours above, interior angle > π.
    Merge,
    /// One neighbour above and one below.
    Regular,
}

impl VertexType {
    /// The lower-case name ("start", "split", ...).
    pub fn name(self) -> &'static str {
        match self {
            VertexType::Start => "start",
            VertexType::Split => "split",
            VertexType::End => "end",
            VertexType::Merge => "merge",
            VertexType::Regular => "regular",
        }
    }
}

/// The type of vertex `v`.
#[inline]
pub(crate) fn vertex_type(g: &Geometry, v: u32) -> VertexType {
    let (p, q) = (g.prev[v as usize], g.next[v as usize]);
    let (p_below, q_below) = (g.above(v, p), g.above(v, q));
    if p_below == q_below {
        // Interior on the left: a left turn at v is an interior angle below π.
        let convex = g.orient(p, v, q) == Ordering::Greater;
        match (p_below, convex) {
            (true, true) => VertexType::Start,
            (true, false) => VertexType::Split,
            (false, true) => VertexType::End,
            (false, false) => VertexType::Merge,
        }
    } else {
        VertexType::Regular
    }
}
