//! Windowing on axis-parallel segments (§10.1–10.2): report the segments that intersect a
//! closed query rectangle (window).
//!
//! A segment meets the window iff an endpoint lies in it, or it crosses the window's
//! boundary. Endpoints inside are found with a layered range tree (§5.6). A horizontal
//! segment that meets the window with no endpoint inside spans it and so crosses the left
//! edge: horizontal segments go into an interval tree on their x-extents whose nodes carry
//! priority search trees (§10.2) on `(left end, y)` and `(−right end, y)`, which answer
//! "x-extent contains qx and y in [y, y']" for the node's intervals in O(log n + k).
//! Vertical segments are handled the same way with x and y exchanged (bottom edge).
//! Query O(log n + k) plus sorting the k answers; storage O(n log n); build O(n log n).
//!
//! Degenerate input: point segments (found by their endpoint), overlapping and touching
//! segments, segments on the window's boundary, zero-width windows. A segment that is
//! neither horizontal nor vertical is `Err(InvalidInput)` (use
//! [`SegmentWindow`](super::SegmentWindow) for those).

use super::interval_tree::build_splits;
use super::PrioritySearchTree;
use crate::kernel::{Bbox2, Point2, Segment2};
use crate::range::LayeredRangeTree;
use crate::{Error, Result};

/// Horizontal segments (in their own frame) for stabbing by vertical query segments.
#[derive(Debug, Clone)]
struct HStabber {
    /// Per node: x_mid, children, and the two priority search trees with their local→input maps.
    nodes: Vec<HNode>,
}

#[derive(Debug, Clone)]
struct HNode {
    x_mid: f64,
    left: Option<u32>,
    right: Option<u32>,
    ids: Vec<u32>,
    by_lo: PrioritySearchTree,
    by_hi: PrioritySearchTree,
}

impl HStabber {
    /// `segs`: `(lo, hi, y, input index)` with `lo <= hi`.
    fn new(segs: &[(f64, f64, f64, u32)]) -> Result<HStabber> {
        let iv: Vec<(f64, f64)> = segs.iter().map(|s| (s.0, s.1)).collect();
        let splits = build_splits(&iv)?;
        let nodes = splits
            .into_iter()
            .map(|sp| {
                let lo: Vec<Point2> = sp
                    .mid
                    .iter()
                    .map(|&i| Point2::new(segs[i as usize].0, segs[i as usize].2))
                    .collect();
                let hi: Vec<Point2> = sp
                    .mid
                    .iter()
                    .map(|&i| Point2::new(-segs[i as usize].1, segs[i as usize].2))
                    .collect();
                HNode {
                    x_mid: sp.x_mid,
                    left: sp.left,
                    right: sp.right,
                    ids: sp.mid.iter().map(|&i| segs[i as usize].3).collect(),
                    by_lo: PrioritySearchTree::from_checked(&lo),
                    by_hi: PrioritySearchTree::from_checked(&hi),
                }
            })
            .collect();
        Ok(HStabber { nodes })
    }

    /// Segments with `lo <= qx <= hi` and `y1 <= y <= y2`.
    fn query(&self, qx: f64, y1: f64, y2: f64, out: &mut Vec<usize>) {
        let mut node = (!self.nodes.is_empty()).then_some(0u32);
        while let Some(k) = node {
            let n = &self.nodes[k as usize];
            let push = |i: usize| out.push(n.ids[i] as usize);
            if qx > n.x_mid {
                n.by_hi.for_each(-qx, y1, y2, push);
                node = n.right;
            } else {
                n.by_lo.for_each(qx, y1, y2, push);
                node = n.left;
            }
        }
    }
}

/// Windowing queries on axis-parallel segments; answers are input indices.
///
/// ```
/// use compgeom::windowing::AxisParallelWindow;
/// use compgeom::{Bbox2, Point2, Segment2};
/// let s = |a: (f64, f64), b: (f64, f64)| Segment2::new(Point2::new(a.0, a.1), Point2::new(b.0, b.1));
/// let segs = [s((-5.0, 1.0), (5.0, 1.0)), s((0.5, -9.0), (0.5, 9.0)), s((3.0, 3.0), (4.0, 3.0))];
/// let w = AxisParallelWindow::new(&segs).unwrap();
/// let window = Bbox2 { min: Point2::new(0.0, 0.0), max: Point2::new(2.0, 2.0) };
/// assert_eq!(w.query(&window), vec![0, 1]); // both cross it without an endpoint inside
/// ```
#[derive(Debug, Clone)]
pub struct AxisParallelWindow {
    endpoints: LayeredRangeTree,
    /// The closed box of all segments: windows are clipped to it.
    bounds: Bbox2,
    horizontal: HStabber,
    /// Vertical segments with x and y exchanged.
    vertical: HStabber,
}

impl AxisParallelWindow {
    /// Build the structure. `Err(NonFinite)` names a segment with a NaN or infinite
    /// coordinate; `Err(InvalidInput)` one that is neither horizontal nor vertical.
    pub fn new(segments: &[Segment2]) -> Result<AxisParallelWindow> {
        let endpoints = super::checked_endpoints(segments)?;
        let (mut h, mut v) = (Vec::new(), Vec::new());
        for (i, s) in segments.iter().enumerate() {
            let i = i as u32;
            if s.a.y == s.b.y {
                h.push((s.a.x.min(s.b.x) + 0.0, s.a.x.max(s.b.x) + 0.0, s.a.y, i));
            } else if s.a.x == s.b.x {
                v.push((s.a.y.min(s.b.y) + 0.0, s.a.y.max(s.b.y) + 0.0, s.a.x, i));
            } else {
                return Err(Error::InvalidInput(format!(
                    "segment {i} is neither horizontal nor vertical"
                )));
            }
        }
        Ok(AxisParallelWindow {
            bounds: Bbox2::of_points(&endpoints),
            endpoints: LayeredRangeTree::new(&endpoints)?,
            horizontal: HStabber::new(&h)?,
            vertical: HStabber::new(&v)?,
        })
    }

    /// The segments meeting the closed window, each once, indices ascending. An empty
    /// window (`min > max`) or one with a NaN bound reports nothing; infinite bounds work.
    pub fn query(&self, window: &Bbox2) -> Vec<usize> {
        let mut out = Vec::new();
        let Some(w) = super::clip(window, &self.bounds) else {
            return out;
        };
        let w = &w;
        self.endpoints.for_each(w, |i| out.push(i / 2));
        self.horizontal.query(w.min.x, w.min.y, w.max.y, &mut out);
        self.vertical.query(w.min.y, w.min.x, w.max.x, &mut out);
        out.sort_unstable();
        out.dedup();
        out
    }
}
