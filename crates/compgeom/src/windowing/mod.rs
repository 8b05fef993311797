//! Windowing (book chapter 10): interval trees, priority search trees, segment trees, and
//! the window queries built from them, which report the segments meeting a rectangle.
//!
//! This module owns the chapter 10 structures; it uses the kernel (exact `orient2d`,
//! `compare_y_at_x`) and the kd-tree and layered range tree of [`crate::range`].
//!
//! | structure | book | query | build | memory |
//! |---|---|---|---|---|
//! | [`IntervalTree`] | §10.1 | intervals containing q: O(log n + k) | O(n log n) | O(n) |
//! | [`PrioritySearchTree`] | §10.2 | points in (−∞:qx] × [qy:qy']: O(log n + k) | O(n log n) | O(n) |
//! | [`SegmentTree`] | §10.3 | intervals containing q: O(log n + k) | O(n log n) | O(n log n) |
//! | [`AxisParallelWindow`] | §10.1–10.2 | axis-parallel segments meeting a window: O(log n + k) | O(n log n) | O(n log n) |
//! | [`SegmentWindow`] | §10.3 | non-crossing segments meeting a window: O(log² n + k) | O(n log² n) | O(n log n) |
//!
//! Every answer lists each item once, input indices ascending (the window queries sort
//! their k answers, adding O(k log k)). Windows and intervals are closed. Segments that
//! cross the window's boundary with no endpoint inside are found: that is what the
//! chapter is about. Degenerate input (shared endpoints, point segments, vertical and
//! horizontal segments, duplicates, zero-width windows) is ordinary input; non-finite
//! coordinates are `Err(NonFinite)` naming the segment.
//!
//! Query windows are read with [`crate::range::read_rects`].

mod axis_parallel;
mod interval_tree;
mod priority_search_tree;
mod segment_tree;
mod segment_window;

pub use axis_parallel::AxisParallelWindow;
pub use interval_tree::IntervalTree;
pub use priority_search_tree::PrioritySearchTree;
pub use segment_tree::SegmentTree;
pub use segment_window::SegmentWindow;

use crate::kernel::{Point2, Segment2};
use crate::{Error, Result};

/// `window` clipped to `bounds` (the closed box of all input), which leaves the set of
/// segments meeting it unchanged and makes infinite bounds finite; `None` if nothing can
/// meet it (empty, NaN, or disjoint from the input).
fn clip(window: &crate::Bbox2, bounds: &crate::Bbox2) -> Option<crate::Bbox2> {
    let (w, b) = (window, bounds);
    let nan = [w.min.x, w.min.y, w.max.x, w.max.y]
        .iter()
        .any(|v| v.is_nan());
    let c = crate::Bbox2 {
        min: Point2::new(w.min.x.max(b.min.x), w.min.y.max(b.min.y)),
        max: Point2::new(w.max.x.min(b.max.x), w.max.y.min(b.max.y)),
    };
    (!nan && !w.is_empty() && !b.is_empty() && !c.is_empty()).then_some(c)
}

/// The endpoints `a, b` of every segment (segment `i` gives points `2i`, `2i + 1`), after
/// checking that all are finite.
fn checked_endpoints(segments: &[Segment2]) -> Result<Vec<Point2>> {
    crate::range::check_count(2 * segments.len())?;
    let mut pts = Vec::with_capacity(2 * segments.len());
    for (i, s) in segments.iter().enumerate() {
        for p in [s.a, s.b] {
            if !p.is_finite() {
                return Err(Error::NonFinite {
                    what: format!("segment {i}"),
                    value: if p.x.is_finite() { p.y } else { p.x },
                });
            }
            pts.push(p);
        }
    }
    Ok(pts)
}

/// Check a window answer exactly by brute force: `result` must be the ascending list of
/// the segments with an endpoint in the closed window or a common point with one of its
/// edges (decided by the kernel's exact [`segment_intersection`](crate::kernel::segment_intersection)).
/// `Err(Verification)` names the first discrepancy.
///
/// ```
/// use compgeom::windowing::verify_window;
/// use compgeom::{Bbox2, Point2, Segment2};
/// let s = [Segment2::new(Point2::new(-1.0, 0.5), Point2::new(2.0, 0.5))];
/// let w = Bbox2 { min: Point2::new(0.0, 0.0), max: Point2::new(1.0, 1.0) };
/// assert!(verify_window(&s, &w, &[0]).is_ok());
/// assert!(verify_window(&s, &w, &[]).is_err());
/// ```
pub fn verify_window(segments: &[Segment2], window: &crate::Bbox2, result: &[usize]) -> Result<()> {
    use crate::kernel::{segment_intersection, SegmentIntersection};
    let w = window;
    let meets = |s: &Segment2| {
        if w.is_empty() {
            return false;
        }
        if w.contains(s.a) || w.contains(s.b) {
            return true;
        }
        let c = [
            w.min,
            Point2::new(w.max.x, w.min.y),
            w.max,
            Point2::new(w.min.x, w.max.y),
        ];
        (0..4).any(|k| {
            let e = Segment2::new(c[k], c[(k + 1) % 4]);
            !matches!(segment_intersection(*s, e), SegmentIntersection::None)
        })
    };
    let want: Vec<usize> = (0..segments.len())
        .filter(|&i| meets(&segments[i]))
        .collect();
    if want != result {
        let missing = want.iter().find(|i| !result.contains(i));
        let extra = result.iter().find(|i| !want.contains(i));
        return Err(Error::Verification(format!(
            "window {w:?}: missing {missing:?}, wrongly reported {extra:?} (or out of order)"
        )));
    }
    Ok(())
}
