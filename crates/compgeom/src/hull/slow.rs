//! The book's SLOWCONVEXHULL (§1.1), O(n³).
//!
//! For every ordered pair `(p, q)` of distinct points, the directed edge `pq` is a hull edge
//! when no other point lies to its left. The book's rule for points on the line through `p`
//! and `q`: the edge is valid only if every such point lies on the open segment `pq`, so a
//! valid edge spans a whole side of the hull and the collinear points between its ends are
//! not vertices. With `keep_collinear` the rule is mirrored: a point on the open segment
//! makes `pq` invalid (it is the next boundary point) and points on the line outside the
//! segment are allowed, so the edges join consecutive boundary points.
//!
//! Repeated points are merged first (a repeated point would otherwise sit "on the segment"
//! of the zero-length pair and the book's rule is stated for distinct points). The valid
//! edges are then chained, starting from the lexicographically smallest point, into the
//! clockwise vertex list (the interior lies to the right of each edge).

use super::andrew::sort_dedup;
use crate::kernel::{compare_xy, orient2d, Orientation, Point2};
use crate::{Error, Result};
use std::cmp::Ordering;

/// True when `r`, known to be on the line through `p` and `q`, lies strictly between them.
fn strictly_between(p: Point2, q: Point2, r: Point2) -> bool {
    let (pr, rq) = (compare_xy(p, r), compare_xy(r, q));
    pr != Ordering::Equal && pr == rq
}

/// Whether the directed edge `pq` is a hull edge under the book's rule (see the module doc).
fn is_hull_edge(points: &[Point2], i: usize, j: usize, keep_collinear: bool) -> bool {
    let (p, q) = (points[i], points[j]);
    points.iter().enumerate().all(|(k, &r)| {
        if k == i || k == j {
            return true;
        }
        match orient2d(p, q, r) {
            Orientation::Clockwise => true,
            Orientation::CounterClockwise => false,
            Orientation::Collinear => strictly_between(p, q, r) != keep_collinear,
        }
    })
}

/// SLOWCONVEXHULL on finite points. See the module doc.
pub(crate) fn slow(points: &[Point2], keep_collinear: bool) -> Result<Vec<Point2>> {
    let mut pts = points.to_vec();
    sort_dedup(&mut pts);
    let n = pts.len();
    if n <= 2 {
        return Ok(pts);
    }
    // Points all on one line: the hull is a segment (the book assumes positive area).
    let (a, b) = (pts[0], pts[1]);
    if pts
        .iter()
        .all(|&r| orient2d(a, b, r) == Orientation::Collinear)
    {
        if keep_collinear {
            return Ok(pts);
        }
        return Ok(vec![pts[0], pts[n - 1]]);
    }
    // E: the valid directed edges, stored as successor links.
    let mut next: Vec<Option<usize>> = vec![None; n];
    for (i, successor) in next.iter_mut().enumerate() {
        for j in 0..n {
            if i != j && is_hull_edge(&pts, i, j, keep_collinear) {
                if successor.is_some() {
                    return Err(internal("two hull edges leave one point"));
                }
                *successor = Some(j);
            }
        }
    }
    // Chain the edges clockwise from the lexicographically smallest point (index 0 after
    // sorting), which is always a hull vertex.
    let mut hull = vec![pts[0]];
    let mut at = 0;
    loop {
        at = next[at].ok_or_else(|| internal("the hull edges do not close"))?;
        if at == 0 {
            break;
        }
        if hull.len() == n {
            return Err(internal(
                "the hull edges form a cycle that misses the start",
            ));
        }
        hull.push(pts[at]);
    }
    Ok(hull)
}

/// With exact predicates the edge set is always one cycle; this reports a broken invariant
/// instead of panicking, should it ever happen.
fn internal(what: &str) -> Error {
    Error::Verification(format!(
        "slow convex hull: {what} (internal error; please report)"
    ))
}
