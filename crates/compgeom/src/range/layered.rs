//! The layered range tree of §5.6: the 2D range tree with **fractional cascading**.
//!
//! The associated arrays are those of [`RangeTree`](super::RangeTree) (each node's points in
//! `(y | x | i)` order), and every entry of a node's array also stores where the first entry
//! at or after it lies in the left child's array; where it lies in the right child's array
//! follows by arithmetic (entries before it that went right), so one 32-bit pointer per
//! entry suffices. A query binary-searches `[y, y']` once, in the root's array, then follows
//! pointers down the two search paths: every canonical node gets its answer range in O(1).
//! O(log n + k) reporting, O(log n) counting; storage O(n log n) (12 bytes per point per
//! level: input index, x-rank and pointer; plus the root's y-values); build O(n log n).
//!
//! One departure from the book, for speed: a partly covered node whose cascaded range holds
//! at most 128 candidates (points with y in range) is not descended further; its candidates
//! are filtered by their x-rank in one contiguous scan. That is O(1) work per such node, so
//! the bounds stand, and it replaces two root-to-leaf chains of cache misses (one pointer
//! lookup per level) with a short sequential read, which is what small queries spend their
//! time on.
//!
//! Why the pointers stay right with equal y-values: the entry at position `p` of a node is
//! the first whose y is at least `y` (or more than `y'`); since keys are distinct composite
//! numbers, the entries of a child at or after it in composite order are exactly the
//! child's entries with y at least `y` (more than `y'`).

use super::skeleton::{
    count_piece, for_each_piece, sampled_partition, Piece, RangeIter, Skeleton, LEAF, SAMPLE,
};
use crate::kernel::{Bbox2, Point2};
use crate::Result;

/// A partly covered node with at most this many candidates (points with y in range) is
/// filtered by a scan of its entries.
const FEW: usize = 128;

/// A static layered range tree (fractional cascading); queries report input indices.
///
/// ```
/// use compgeom::range::LayeredRangeTree;
/// use compgeom::{Bbox2, Point2};
/// let pts: Vec<Point2> = (0..1000).map(|i| Point2::new((i % 7) as f64, (i % 13) as f64)).collect();
/// let tree = LayeredRangeTree::new(&pts).unwrap();
/// let rect = Bbox2 { min: Point2::new(1.0, 2.0), max: Point2::new(2.0, 2.0) };
/// let brute: Vec<usize> = (0..1000).filter(|&i| rect.contains(pts[i])).collect();
/// assert_eq!(tree.query(&rect), brute);
/// assert_eq!(tree.count(&rect), brute.len());
/// ```
#[derive(Debug, Clone)]
pub struct LayeredRangeTree {
    skel: Skeleton,
    /// y-coordinates of the root's array (the one binary search of a query).
    root_ys: Vec<f64>,
    /// Every `SAMPLE`-th entry of `root_ys`.
    root_samples: Vec<f64>,
    /// `lefts[d][j] = a + (entries of the node before position j that go left)`: the
    /// position in depth `d + 1` of the first left-child entry at or after entry `j`.
    lefts: Vec<Vec<u32>>,
}

impl LayeredRangeTree {
    /// Build the tree. `Err(NonFinite)` names the first point with a NaN or infinite
    /// coordinate; more than `u32::MAX` points is `Err(InvalidInput)`.
    pub fn new(points: &[Point2]) -> Result<LayeredRangeTree> {
        let (skel, mut lefts) = Skeleton::build(points, true)?;
        // The deepest level's pointers would lead to leaves, which are scanned instead.
        lefts.pop();
        let root_ys: Vec<f64> = skel
            .level_ids
            .first()
            .map(|ids| ids.iter().map(|&i| points[i as usize].y).collect())
            .unwrap_or_default();
        let root_samples = root_ys.iter().step_by(SAMPLE).copied().collect();
        Ok(LayeredRangeTree {
            skel,
            root_ys,
            root_samples,
            lefts,
        })
    }

    /// Number of points.
    pub fn len(&self) -> usize {
        self.skel.len()
    }

    /// True when there are no points.
    pub fn is_empty(&self) -> bool {
        self.skel.len() == 0
    }

    /// Approximate heap memory in bytes.
    pub fn memory_bytes(&self) -> usize {
        self.skel.memory_bytes()
            + self.root_ys.capacity() * 8
            + self.lefts.iter().map(|v| v.capacity() * 4).sum::<usize>()
    }

    fn pieces(&self, rect: &Bbox2) -> Vec<Piece> {
        let mut v = Vec::new();
        self.visit(rect, &mut |p| v.push(p));
        v
    }

    /// Hand every canonical piece of the answer to `out`.
    fn visit(&self, rect: &Bbox2, out: &mut impl FnMut(Piece)) {
        if self.is_empty() || rect.is_empty() {
            return;
        }
        let (lo, hi) = self.skel.x_span(rect);
        if lo >= hi {
            return;
        }
        if self.skel.level_ids.is_empty() {
            out(Piece::Scan {
                from: lo as u32,
                to: hi as u32,
            });
            return;
        }
        let (ys, n) = (&self.root_ys, self.root_ys.len());
        let p1 = sampled_partition(&self.root_samples, n, |i| ys[i], |y| y < rect.min.y);
        let p2 = sampled_partition(&self.root_samples, n, |i| ys[i], |y| y <= rect.max.y);
        self.descend((lo, hi), (0, self.len()), 0, (p1, p2), out);
    }

    /// `ps = (p1, p2)`: at this node (depth `d`), the absolute positions of the first entry
    /// with y >= ymin and the first with y > ymax.
    fn descend(
        &self,
        span: (usize, usize),
        node: (usize, usize),
        d: usize,
        ps: (usize, usize),
        out: &mut impl FnMut(Piece),
    ) {
        let ((lo, hi), (a, b), (p1, p2)) = (span, node, ps);
        if b <= lo || a >= hi || p1 >= p2 {
            return;
        }
        if lo <= a && b <= hi {
            out(Piece::Whole {
                depth: d as u32,
                from: p1 as u32,
                to: p2 as u32,
            });
            return;
        }
        if p2 - p1 <= FEW {
            // Few candidates: filter them by x-rank in one contiguous scan rather than
            // descending further (O(1) work, so the bound O(log n + k) stands).
            out(Piece::Ranked {
                depth: d as u32,
                from: p1 as u32,
                to: p2 as u32,
                lo: lo as u32,
                hi: hi as u32,
            });
            return;
        }
        if b - a <= LEAF || d >= self.lefts.len() {
            out(Piece::Scan {
                from: a.max(lo) as u32,
                to: b.min(hi) as u32,
            });
            return;
        }
        let m = a + (b - a) / 2;
        let lefts = &self.lefts[d];
        let left = |p: usize| if p < b { lefts[p] as usize } else { m };
        let right = |p: usize| if p < b { m + p - lefts[p] as usize } else { b };
        self.descend(span, (a, m), d + 1, (left(p1), left(p2)), out);
        self.descend(span, (m, b), d + 1, (right(p1), right(p2)), out);
    }

    /// The points in the closed rectangle as a lazy iterator of input indices (in the order
    /// of the canonical subsets). An empty rectangle (`min > max`) reports nothing.
    pub fn iter(&self, rect: &Bbox2) -> RangeIter<'_> {
        RangeIter::new(&self.skel, *rect, self.pieces(rect))
    }

    /// Calls `f` with the input index of each point in the closed rectangle.
    pub fn for_each(&self, rect: &Bbox2, mut f: impl FnMut(usize)) {
        let skel = &self.skel;
        self.visit(rect, &mut |p| for_each_piece(skel, rect, p, &mut f));
    }

    /// The points in the closed rectangle, as input indices in ascending order.
    pub fn query(&self, rect: &Bbox2) -> Vec<usize> {
        let mut v = Vec::new();
        self.for_each(rect, |i| v.push(i));
        v.sort_unstable();
        v
    }

    /// The number of points in the closed rectangle, in O(log n).
    pub fn count(&self, rect: &Bbox2) -> usize {
        let mut c = 0;
        self.visit(rect, &mut |p| c += count_piece(&self.skel, rect, p));
        c
    }
}
