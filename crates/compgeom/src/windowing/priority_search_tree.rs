//! The priority search tree of §10.2: points in the plane, queries
//! `(-inf : qx] × [qy : qy']` in O(log n + k), storage O(n), build O(n log n).
//!
//! The root holds the point with the smallest x-coordinate; the others are split at the
//! median y-coordinate into two subtrees built the same way. Both orders are composite
//! (§5.5): `(x | y | i)` for "smallest x" and `(y | x | i)` for the median, so equal
//! coordinates and duplicate points need no assumption. Closed query ranges; an empty
//! range (`qy > qy'`) reports nothing. Comparisons are exact.

use crate::kernel::{ensure_finite, Point2};
use crate::range::{cmp_composite_x, cmp_composite_y};
use crate::Result;

#[derive(Debug, Clone, Copy)]
struct PNode {
    p: Point2,
    id: u32,
    /// y of the median: the left subtree's points have y <= split, the right's y >= split.
    split: f64,
    left: u32,
    right: u32,
}

const NONE: u32 = u32::MAX;

/// A static priority search tree; queries report input indices.
///
/// ```
/// use compgeom::windowing::PrioritySearchTree;
/// use compgeom::Point2;
/// let pts = [Point2::new(0.0, 0.0), Point2::new(2.0, 1.0), Point2::new(1.0, 1.0), Point2::new(5.0, 1.0)];
/// let t = PrioritySearchTree::new(&pts).unwrap();
/// assert_eq!(t.query(2.0, 1.0, 3.0), vec![1, 2]);
/// ```
#[derive(Debug, Clone)]
pub struct PrioritySearchTree {
    nodes: Vec<PNode>,
    root: u32,
}

impl PrioritySearchTree {
    /// Build the tree. `Err(NonFinite)` names the first point with a NaN or infinite
    /// coordinate.
    pub fn new(points: &[Point2]) -> Result<PrioritySearchTree> {
        ensure_finite(points, "point")?;
        crate::range::check_count(points.len())?;
        let mut by_y: Vec<u32> = (0..points.len() as u32).collect();
        by_y.sort_unstable_by(|&a, &b| {
            cmp_composite_y(
                points[a as usize],
                a as usize,
                points[b as usize],
                b as usize,
            )
        });
        let mut nodes = Vec::with_capacity(points.len());
        let root = build(points, by_y, &mut nodes);
        Ok(PrioritySearchTree { nodes, root })
    }

    /// Build from (x, y) pairs already checked; used by the windowing structures.
    pub(crate) fn from_checked(points: &[Point2]) -> PrioritySearchTree {
        let mut by_y: Vec<u32> = (0..points.len() as u32).collect();
        by_y.sort_unstable_by(|&a, &b| {
            cmp_composite_y(
                points[a as usize],
                a as usize,
                points[b as usize],
                b as usize,
            )
        });
        let mut nodes = Vec::with_capacity(points.len());
        let root = build(points, by_y, &mut nodes);
        PrioritySearchTree { nodes, root }
    }

    /// Number of points.
    pub fn len(&self) -> usize {
        self.nodes.len()
    }

    /// True when there are no points.
    pub fn is_empty(&self) -> bool {
        self.nodes.is_empty()
    }

    /// Calls `f` with the index of every point with `x <= qx` and `qy <= y <= qy2`
    /// (QUERYPRIOSEARCHTREE).
    pub fn for_each(&self, qx: f64, qy: f64, qy2: f64, mut f: impl FnMut(usize)) {
        if qy <= qy2 {
            self.visit(self.root, qx, qy, qy2, &mut f);
        }
    }

    fn visit(&self, k: u32, qx: f64, qy: f64, qy2: f64, f: &mut impl FnMut(usize)) {
        if k == NONE {
            return;
        }
        let n = &self.nodes[k as usize];
        // Heap order on x: nothing below has a smaller x.
        if n.p.x > qx {
            return;
        }
        if qy <= n.p.y && n.p.y <= qy2 {
            f(n.id as usize);
        }
        if qy <= n.split {
            self.visit(n.left, qx, qy, qy2, f);
        }
        if qy2 >= n.split {
            self.visit(n.right, qx, qy, qy2, f);
        }
    }

    /// The points in `(-inf : qx] × [qy : qy2]`, indices ascending.
    pub fn query(&self, qx: f64, qy: f64, qy2: f64) -> Vec<usize> {
        let mut v = Vec::new();
        self.for_each(qx, qy, qy2, |i| v.push(i));
        v.sort_unstable();
        v
    }
}

/// `by_y`: a subset in `(y | x | i)` order. Returns the subtree's root.
fn build(points: &[Point2], mut by_y: Vec<u32>, nodes: &mut Vec<PNode>) -> u32 {
    if by_y.is_empty() {
        return NONE;
    }
    let key = |i: u32| (points[i as usize], i as usize);
    let pos = (0..by_y.len())
        .min_by(|&a, &b| {
            let ((p, i), (q, j)) = (key(by_y[a]), key(by_y[b]));
            cmp_composite_x(p, i, q, j)
        })
        .unwrap_or(0);
    let top = by_y.remove(pos);
    let me = nodes.len() as u32;
    let half = by_y.len().div_ceil(2);
    let split = if by_y.is_empty() {
        points[top as usize].y
    } else {
        points[by_y[half.saturating_sub(1)] as usize].y
    };
    nodes.push(PNode {
        p: points[top as usize],
        id: top,
        split,
        left: NONE,
        right: NONE,
    });
    let right = by_y.split_off(half);
    let l = build(points, by_y, nodes);
    let r = build(points, right, nodes);
    nodes[me as usize].left = l;
    nodes[me as usize].right = r;
    me
}
