//! The kd-tree of §5.2 (BUILDKDTREE / SEARCHKDTREE), plus k-nearest-neighbour and radius
//! queries.
//!
//! **Build.** The book's median split, alternating x and y by depth, on composite
//! coordinates (§5.5): the median is taken in `(x | y | i)` order at even depths and
//! `(y | x | i)` order at odd depths, so equal coordinates and duplicate points split
//! cleanly. Subsets of at most [`KdTree::LEAF_SIZE`] points become leaf buckets. The
//! permutation is built by linear-time selection (`select_nth_unstable`), O(n log n) in
//! total, with the two halves built in parallel (rayon) for large subsets. Each node keeps
//! the bounding box of its points (the book's `region(v)`, shrunk to the points), which
//! lets a query report a whole subtree at once and lets counting skip it.
//!
//! **Queries.** Closed rectangles ([`Bbox2`]): O(√n + k) reporting, O(√n) counting. Every
//! decision compares input coordinates with query coordinates, which is exact.
//! [`KdTree::nearest`] and [`KdTree::within_radius`] compare squared distances exactly
//! (floating-point filter, exact rational fallback); ties in distance are broken by the
//! smaller input index, so answers are deterministic. k-NN descends as Arya and Mount do:
//! nearer child first, the farther one only if the query's distance to its cell (kept per
//! axis from the split values, a compact array that stays in cache) can still beat the
//! worst of the `k` best, which live in a short sorted array (on the stack for small `k`).
//! Each candidate carries bounds on its exact squared distance derived from the rounded
//! one; a point or subtree is skipped only when its bound exceeds the worst kept one's, so
//! only near-ties reach the exact comparison.
//!
//! Memory: 20 bytes per point plus a 32-byte box and an 8-byte split value per node (about
//! `2n / LEAF_SIZE` nodes).

use super::composite::{check_points, cmp_composite_x, cmp_composite_y, PARALLEL};
use super::distance::{
    box_dist2_lower, compare_distance, compare_distance_to_radius, dist2, dist2_bounds,
    dist2_lower, prune_bound,
};
use crate::kernel::{Bbox2, Point2};
use crate::Result;
use std::cmp::Ordering;

/// A static kd-tree over points in the plane; queries report input indices.
///
/// ```
/// use compgeom::range::KdTree;
/// use compgeom::{Bbox2, Point2};
/// let pts = [Point2::new(0.0, 0.0), Point2::new(1.0, 1.0), Point2::new(1.0, 1.0), Point2::new(3.0, 1.0)];
/// let tree = KdTree::new(&pts).unwrap();
/// let rect = Bbox2 { min: Point2::new(1.0, 0.0), max: Point2::new(3.0, 1.0) };
/// assert_eq!(tree.query(&rect), vec![1, 2, 3]); // closed: the boundary counts
/// assert_eq!(tree.count(&rect), 3);
/// assert_eq!(tree.nearest(Point2::new(0.9, 0.9), 2), vec![1, 2]);
/// assert_eq!(tree.within_radius(Point2::new(2.0, 1.0), 1.0), vec![1, 2, 3]);
/// ```
#[derive(Debug, Clone)]
pub struct KdTree {
    /// The points, permuted into tree order.
    pts: Vec<Point2>,
    /// `ids[j]`: the input index of `pts[j]`.
    ids: Vec<u32>,
    /// Bounding box of each node, heap-indexed (children of `k` are `2k+1`, `2k+2`).
    boxes: Vec<Bbox2>,
    /// The split value of each internal node, heap-indexed like `boxes`: the coordinate
    /// (x at even depths, y at odd) of the median, the least of the right half's. A
    /// compact copy (8 bytes a node, small enough to stay in cache) for k-NN descents.
    splits: Vec<f64>,
    /// The depth of every leaf (all leaves lie at this depth or one above).
    depth: u32,
}

/// One node to visit: heap index, depth, and its range of `pts`.
#[derive(Debug, Clone, Copy)]
struct Node {
    k: u32,
    depth: u32,
    lo: u32,
    hi: u32,
}

impl Node {
    fn children(self) -> (Node, Node) {
        let mid = self.lo + (self.hi - self.lo) / 2;
        (
            Node {
                k: 2 * self.k + 1,
                depth: self.depth + 1,
                lo: self.lo,
                hi: mid,
            },
            Node {
                k: 2 * self.k + 2,
                depth: self.depth + 1,
                lo: mid,
                hi: self.hi,
            },
        )
    }
}

impl KdTree {
    /// Subsets of at most this many points are leaf buckets.
    pub const LEAF_SIZE: usize = 16;

    /// Build the tree (BUILDKDTREE). `Err(NonFinite)` names the first point with a NaN or
    /// infinite coordinate; more than `u32::MAX` points is `Err(InvalidInput)`.
    pub fn new(points: &[Point2]) -> Result<KdTree> {
        check_points(points)?;
        let n = points.len();
        let mut depth = 0u32;
        let mut size = n;
        while size > Self::LEAF_SIZE {
            size = size.div_ceil(2);
            depth += 1;
        }
        // Points travel with their indices: selection then compares local data instead of
        // chasing indices into `points`.
        let mut items: Vec<(Point2, u32)> = points.iter().copied().zip(0..n as u32).collect();
        split(&mut items, 0, depth);
        let pts: Vec<Point2> = items.iter().map(|e| e.0).collect();
        let ids: Vec<u32> = items.iter().map(|e| e.1).collect();
        let mut boxes = vec![Bbox2::EMPTY; (1usize << (depth + 1)) - 1];
        let mut splits = vec![0.0; (1usize << depth) - 1];
        if n > 0 {
            fill_boxes(&pts, &mut boxes, &mut splits, Self::root(n), depth);
        }
        Ok(KdTree {
            pts,
            ids,
            boxes,
            splits,
            depth,
        })
    }

    fn root(n: usize) -> Node {
        Node {
            k: 0,
            depth: 0,
            lo: 0,
            hi: n as u32,
        }
    }

    /// Number of points.
    pub fn len(&self) -> usize {
        self.pts.len()
    }

    /// True when there are no points.
    pub fn is_empty(&self) -> bool {
        self.pts.is_empty()
    }

    /// Approximate heap memory in bytes.
    pub fn memory_bytes(&self) -> usize {
        self.pts.capacity() * 16
            + self.ids.capacity() * 4
            + self.boxes.capacity() * 32
            + self.splits.capacity() * 8
    }

    /// The points in the closed rectangle, as an iterator of input indices in tree order
    /// (SEARCHKDTREE, lazily). An empty rectangle (`min > max`) reports nothing.
    pub fn iter(&self, rect: &Bbox2) -> KdRangeIter<'_> {
        let mut stack = Vec::with_capacity(2 * self.depth as usize + 2);
        if !self.is_empty() && !rect.is_empty() {
            stack.push(Self::root(self.len()));
        }
        KdRangeIter {
            tree: self,
            rect: *rect,
            stack,
            run: 0..0,
            check: false,
        }
    }

    /// The points in the closed rectangle, as input indices in ascending order.
    pub fn query(&self, rect: &Bbox2) -> Vec<usize> {
        let mut v: Vec<usize> = self.iter(rect).collect();
        v.sort_unstable();
        v
    }

    /// Calls `f` with the input index of each point in the closed rectangle (tree order).
    /// The fastest way to consume a query.
    pub fn for_each(&self, rect: &Bbox2, mut f: impl FnMut(usize)) {
        if self.is_empty() || rect.is_empty() {
            return;
        }
        self.visit(rect, Self::root(self.len()), &mut |lo, hi, check| {
            for j in lo..hi {
                if !check || rect.contains(self.pts[j]) {
                    f(self.ids[j] as usize);
                }
            }
        });
    }

    /// The number of points in the closed rectangle, without reporting them: subtrees whose
    /// box lies inside the rectangle are counted whole.
    pub fn count(&self, rect: &Bbox2) -> usize {
        let mut c = 0;
        if self.is_empty() || rect.is_empty() {
            return 0;
        }
        self.visit(rect, Self::root(self.len()), &mut |lo, hi, check| {
            c += if check {
                self.pts[lo..hi]
                    .iter()
                    .filter(|p| rect.contains(**p))
                    .count()
            } else {
                hi - lo
            };
        });
        c
    }

    /// The recursion of SEARCHKDTREE: `out(lo, hi, check)` receives runs of `pts`, whole
    /// (`check == false`) or to be tested one by one.
    fn visit(&self, rect: &Bbox2, node: Node, out: &mut impl FnMut(usize, usize, bool)) {
        let b = &self.boxes[node.k as usize];
        if disjoint(b, rect) {
            return;
        }
        if inside(b, rect) {
            out(node.lo as usize, node.hi as usize, false);
        } else if node.depth == self.depth || (node.hi - node.lo) as usize <= Self::LEAF_SIZE {
            out(node.lo as usize, node.hi as usize, true);
        } else {
            let (l, r) = node.children();
            self.visit(rect, l, out);
            self.visit(rect, r, out);
        }
    }

    /// The `k` points nearest to `q`, nearest first; equal distances are ordered by input
    /// index. Distances are compared exactly. Fewer than `k` if there are fewer points.
    pub fn nearest(&self, q: Point2, k: usize) -> Vec<usize> {
        if k == 0 || self.is_empty() || !q.is_finite() {
            return Vec::new();
        }
        let k = k.min(self.len());
        let mut inline = [Candidate::NONE; INLINE_K];
        let mut heap = Vec::new();
        let items = if k <= INLINE_K {
            &mut inline[..k]
        } else {
            heap.resize(k, Candidate::NONE);
            &mut heap[..]
        };
        let mut best = Best {
            q,
            ids: &self.ids,
            items,
            len: 0,
            prune: f64::INFINITY,
        };
        self.knn(Self::root(self.len()), [0.0; 2], &mut best);
        best.items[..best.len]
            .iter()
            .map(|c| self.ids[c.j as usize] as usize)
            .collect()
    }

    /// The descent of Arya and Mount: the child on the query's side of the split first,
    /// then the other one if the query's distance to its cell can still beat the worst kept
    /// point. `off` holds the query's per-axis distances to the current cell (the cell is
    /// bounded by the ancestors' split lines: left points have coordinate at most the split
    /// value, right points at least), so the bound costs a subtraction and no memory beyond
    /// the compact split array.
    fn knn(&self, node: Node, off: [f64; 2], best: &mut Best) {
        if node.depth == self.depth || (node.hi - node.lo) as usize <= Self::LEAF_SIZE {
            for j in node.lo as usize..node.hi as usize {
                let p = self.pts[j];
                let d2 = dist2(p, best.q);
                // Rounded distances beyond the prune bound cannot beat the worst kept.
                if d2 <= best.prune {
                    best.offer(p, d2, j as u32);
                }
            }
            return;
        }
        let axis = (node.depth % 2) as usize;
        let d = [best.q.x, best.q.y][axis] - self.splits[node.k as usize];
        let (l, r) = node.children();
        let (near, far) = if d <= 0.0 { (l, r) } else { (r, l) };
        self.knn(near, off, best);
        let mut far_off = off;
        far_off[axis] = d.abs();
        if dist2_lower(far_off[0], far_off[1]) <= best.prune {
            self.knn(far, far_off, best);
        }
    }

    fn node_dist(&self, q: Point2, n: Node) -> f64 {
        let b = &self.boxes[n.k as usize];
        box_dist2_lower(q, b.min.x, b.min.y, b.max.x, b.max.y)
    }

    /// The points at distance at most `r` from `q` (closed disc), as input indices in
    /// ascending order. Distances are compared exactly; a negative `r` means `|r|`.
    pub fn within_radius(&self, q: Point2, r: f64) -> Vec<usize> {
        let mut out = Vec::new();
        if self.is_empty() || !q.is_finite() || !r.is_finite() {
            return out;
        }
        let r2 = r * r * (1.0 + 1e-14) + 1e-280;
        self.radius(q, r, r2, Self::root(self.len()), &mut out);
        out.sort_unstable();
        out
    }

    fn radius(&self, q: Point2, r: f64, r2: f64, node: Node, out: &mut Vec<usize>) {
        if self.node_dist(q, node) > r2 {
            return;
        }
        if node.depth == self.depth || (node.hi - node.lo) as usize <= Self::LEAF_SIZE {
            for j in node.lo as usize..node.hi as usize {
                if compare_distance_to_radius(q, self.pts[j], r) != Ordering::Greater {
                    out.push(self.ids[j] as usize);
                }
            }
            return;
        }
        let (l, rr) = node.children();
        self.radius(q, r, r2, l, out);
        self.radius(q, r, r2, rr, out);
    }

    /// The splitting lines of the tree, for pictures: one segment per internal node, the
    /// median line clipped to the node's region (the book's Figure 5.3). `bounds` is the
    /// region of the root.
    pub fn splits(&self, bounds: Bbox2) -> Vec<crate::Segment2> {
        let mut out = Vec::new();
        if !self.is_empty() {
            self.collect_splits(Self::root(self.len()), bounds, &mut out);
        }
        out
    }

    fn collect_splits(&self, node: Node, region: Bbox2, out: &mut Vec<crate::Segment2>) {
        if node.depth == self.depth || (node.hi - node.lo) as usize <= Self::LEAF_SIZE {
            return;
        }
        let (l, r) = node.children();
        let m = self.splits[node.k as usize];
        let (mut lreg, mut rreg) = (region, region);
        let seg = if node.depth % 2 == 0 {
            lreg.max.x = m;
            rreg.min.x = m;
            crate::Segment2::new(Point2::new(m, region.min.y), Point2::new(m, region.max.y))
        } else {
            lreg.max.y = m;
            rreg.min.y = m;
            crate::Segment2::new(Point2::new(region.min.x, m), Point2::new(region.max.x, m))
        };
        out.push(seg);
        self.collect_splits(l, lreg, out);
        self.collect_splits(r, rreg, out);
    }
}

/// Reorder `items` so that each node's median split holds (recursively, to `max_depth`).
fn split(items: &mut [(Point2, u32)], depth: u32, max_depth: u32) {
    if depth >= max_depth || items.len() <= KdTree::LEAF_SIZE {
        return;
    }
    let mid = items.len() / 2;
    if depth % 2 == 0 {
        items.select_nth_unstable_by(mid, |a, b| {
            cmp_composite_x(a.0, a.1 as usize, b.0, b.1 as usize)
        });
    } else {
        items.select_nth_unstable_by(mid, |a, b| {
            cmp_composite_y(a.0, a.1 as usize, b.0, b.1 as usize)
        });
    }
    let (l, r) = items.split_at_mut(mid);
    if l.len() + r.len() >= PARALLEL {
        rayon::join(
            || split(l, depth + 1, max_depth),
            || split(r, depth + 1, max_depth),
        );
    } else {
        split(l, depth + 1, max_depth);
        split(r, depth + 1, max_depth);
    }
}

/// Bounding boxes bottom-up, and the split values of internal nodes; returns the node's box.
fn fill_boxes(
    pts: &[Point2],
    boxes: &mut [Bbox2],
    splits: &mut [f64],
    node: Node,
    max_depth: u32,
) -> Bbox2 {
    let b = if node.depth == max_depth || (node.hi - node.lo) as usize <= KdTree::LEAF_SIZE {
        Bbox2::of_points(&pts[node.lo as usize..node.hi as usize])
    } else {
        let (l, r) = node.children();
        let bl = fill_boxes(pts, boxes, splits, l, max_depth);
        let br = fill_boxes(pts, boxes, splits, r, max_depth);
        // The median itself may have moved within the right half (the children's
        // selections reorder it); the least coordinate of the right half is the median's.
        splits[node.k as usize] = if node.depth % 2 == 0 {
            br.min.x
        } else {
            br.min.y
        };
        let mut b = bl;
        if !br.is_empty() {
            b.extend(br.min);
            b.extend(br.max);
        }
        b
    };
    boxes[node.k as usize] = b;
    b
}

#[inline]
fn disjoint(b: &Bbox2, r: &Bbox2) -> bool {
    b.is_empty() || b.max.x < r.min.x || b.min.x > r.max.x || b.max.y < r.min.y || b.min.y > r.max.y
}

#[inline]
fn inside(b: &Bbox2, r: &Bbox2) -> bool {
    r.min.x <= b.min.x && b.max.x <= r.max.x && r.min.y <= b.min.y && b.max.y <= r.max.y
}

/// A k-NN candidate: a point, bounds on its exact squared distance to the query (from the
/// rounded one, see [`dist2_bounds`]), its position in the tree order (its input index is
/// looked up only to break exact ties, and for the answer: fewer cache lines touched).
#[derive(Debug, Clone, Copy)]
struct Candidate {
    p: Point2,
    lo: f64,
    hi: f64,
    j: u32,
}

impl Candidate {
    const NONE: Candidate = Candidate {
        p: Point2 { x: 0.0, y: 0.0 },
        lo: 0.0,
        hi: 0.0,
        j: 0,
    };
}

/// Queries for at most this many neighbours keep their candidates on the stack.
const INLINE_K: usize = 16;

/// The `k` best candidates so far, nearest first (a short sorted array: cheaper than a heap
/// for the small `k` of typical queries), and the prune bound they imply.
#[derive(Debug)]
struct Best<'a> {
    q: Point2,
    /// The tree's input indices, for ties.
    ids: &'a [u32],
    /// Room for `k` candidates; the first `len` are kept, in order.
    items: &'a mut [Candidate],
    len: usize,
    /// Once `k` are kept: a bound on rounded squared distances above which nothing can beat
    /// the worst kept (see [`prune_bound`]); else infinity.
    prune: f64,
}

impl Best<'_> {
    /// `a` before `b`: exact distance to `q`, then input index. The bounds decide all but
    /// near-ties, which go to the exact comparison.
    #[inline]
    fn before(&self, a: &Candidate, b: &Candidate) -> bool {
        if a.hi < b.lo {
            return true;
        }
        if b.hi < a.lo {
            return false;
        }
        compare_distance(self.q, a.p, b.p)
            .then_with(|| self.ids[a.j as usize].cmp(&self.ids[b.j as usize]))
            == Ordering::Less
    }

    /// Keep the point `p` (tree position `j`, rounded squared distance `d2`) if it is among
    /// the `k` best so far.
    #[inline]
    fn offer(&mut self, p: Point2, d2: f64, j: u32) {
        let (lo, hi) = dist2_bounds(d2);
        let c = Candidate { p, lo, hi, j };
        let k = self.items.len();
        if self.len == k {
            if !self.before(&c, &self.items[k - 1]) {
                return;
            }
            self.len -= 1;
        }
        let mut at = self.len;
        while at > 0 && self.before(&c, &self.items[at - 1]) {
            self.items[at] = self.items[at - 1];
            at -= 1;
        }
        self.items[at] = c;
        self.len += 1;
        if self.len == k {
            self.prune = prune_bound(self.items[k - 1].hi);
        }
    }
}

/// The lazy result of [`KdTree::iter`]: input indices of the points in a rectangle.
#[derive(Debug, Clone)]
pub struct KdRangeIter<'a> {
    tree: &'a KdTree,
    rect: Bbox2,
    stack: Vec<Node>,
    run: std::ops::Range<usize>,
    check: bool,
}

impl Iterator for KdRangeIter<'_> {
    type Item = usize;

    fn next(&mut self) -> Option<usize> {
        let t = self.tree;
        loop {
            for j in self.run.by_ref() {
                if !self.check || self.rect.contains(t.pts[j]) {
                    return Some(t.ids[j] as usize);
                }
            }
            let node = self.stack.pop()?;
            let b = &t.boxes[node.k as usize];
            if disjoint(b, &self.rect) {
                continue;
            }
            if inside(b, &self.rect) {
                self.run = node.lo as usize..node.hi as usize;
                self.check = false;
            } else if node.depth == t.depth || (node.hi - node.lo) as usize <= KdTree::LEAF_SIZE {
                self.run = node.lo as usize..node.hi as usize;
                self.check = true;
            } else {
                let (l, r) = node.children();
                self.stack.push(r);
                self.stack.push(l);
            }
        }
    }
}
