//! The 2D range tree of §5.3: a balanced binary search tree on the composite x-coordinate
//! whose every node carries an associated structure, its points sorted by composite
//! y-coordinate (a sorted array is the book's 1D range tree flattened).
//!
//! A query `[x, x'] × [y, y']` selects the O(log n) canonical nodes whose subsets together
//! are exactly the points with `x <= px <= x'`, and binary-searches `[y, y']` in each
//! associated array: O(log² n + k) reporting, O(log² n) counting. Storage O(n log n)
//! (12 bytes per point per level, with leaf buckets of 8); build O(n log n).
//!
//! Equal coordinates and duplicate points need no special care: the tree orders by
//! `(x | y | i)` and the arrays by `(y | x | i)` (§5.5).

use super::skeleton::{count_piece, for_each_piece, Piece, RangeIter, Skeleton, LEAF};
use crate::kernel::{Bbox2, Point2};
use crate::Result;

/// A static 2D range tree; queries report input indices.
///
/// ```
/// use compgeom::range::RangeTree;
/// use compgeom::{Bbox2, Point2};
/// let pts: Vec<Point2> = (0..100).map(|i| Point2::new((i % 10) as f64, (i / 10) as f64)).collect();
/// let tree = RangeTree::new(&pts).unwrap();
/// let rect = Bbox2 { min: Point2::new(2.0, 3.0), max: Point2::new(4.0, 3.0) };
/// assert_eq!(tree.query(&rect), vec![32, 33, 34]);
/// assert_eq!(tree.count(&rect), 3);
/// ```
#[derive(Debug, Clone)]
pub struct RangeTree {
    skel: Skeleton,
    /// `level_ys[d][j]`: the y-coordinate of `skel.level_ids[d][j]`, for binary search.
    level_ys: Vec<Vec<f64>>,
}

impl RangeTree {
    /// Build the tree. `Err(NonFinite)` names the first point with a NaN or infinite
    /// coordinate; more than `u32::MAX` points is `Err(InvalidInput)`.
    pub fn new(points: &[Point2]) -> Result<RangeTree> {
        let (skel, _) = Skeleton::build(points, false)?;
        let level_ys = skel
            .level_ids
            .iter()
            .map(|ids| ids.iter().map(|&i| points[i as usize].y).collect())
            .collect();
        Ok(RangeTree { skel, level_ys })
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
            + self
                .level_ys
                .iter()
                .map(|v| v.capacity() * 8)
                .sum::<usize>()
    }

    /// The canonical pieces of the answer (O(log² n)).
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
        if lo < hi {
            self.descend(rect, (lo, hi), (0, self.len()), 0, out);
        }
    }

    fn descend(
        &self,
        rect: &Bbox2,
        span: (usize, usize),
        node: (usize, usize),
        d: usize,
        out: &mut impl FnMut(Piece),
    ) {
        let ((lo, hi), (a, b)) = (span, node);
        if b <= lo || a >= hi || a >= b {
            return;
        }
        if lo <= a && b <= hi && d < self.level_ys.len() {
            // A canonical node: binary search [ymin, ymax] in its associated array.
            let ys = &self.level_ys[d][a..b];
            let p1 = ys.partition_point(|&y| y < rect.min.y);
            let p2 = ys.partition_point(|&y| y <= rect.max.y);
            if p1 < p2 {
                out(Piece::Whole {
                    depth: d as u32,
                    from: (a + p1) as u32,
                    to: (a + p2) as u32,
                });
            }
            return;
        }
        if d >= self.level_ys.len() || b - a <= LEAF {
            out(Piece::Scan {
                from: a.max(lo) as u32,
                to: b.min(hi) as u32,
            });
            return;
        }
        let m = a + (b - a) / 2;
        self.descend(rect, span, (a, m), d + 1, out);
        self.descend(rect, span, (m, b), d + 1, out);
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

    /// The number of points in the closed rectangle, in O(log² n).
    pub fn count(&self, rect: &Bbox2) -> usize {
        let mut c = 0;
        self.visit(rect, &mut |p| c += count_piece(&self.skel, rect, p));
        c
    }
}
