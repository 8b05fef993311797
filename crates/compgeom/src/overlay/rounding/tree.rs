//! An adaptive quadtree over a result's points, for the rounding check's search for near
//! pairs where the uniform grid ([`super::grid`]) crowds.
//!
//! The grid has about two cells per moved item over the items' extent. Where the points
//! and the long moved edges gather in a small part of it, one cell holds hundreds of
//! each and the search is quadratic there: 10⁴ long strips across a triangle took
//! seconds, nearly all of it in tests of points against the edges of their cells (a
//! star's spikes meeting near its centre, the same). Here the cells follow the points:
//! a node with more than [`LEAF_POINTS`] of them is cut into four at its centre (in two
//! where one side cannot be cut in floats), so the leaves are small where the points
//! are dense and large where they are sparse. A moved item is listed in every leaf its
//! footprint may meet: its box overlaps the leaf's and, for a segment, its widened
//! segment is not clearly apart from it ([`super::clearly_apart`], a float test that
//! never says apart where they meet).
//!
//! The leaves cover the items' extent (the closed quarters of a closed box make it up),
//! so where a query's footprint meets an item's, at a point of the item's box, some
//! leaf holds that point: the item is listed there and the query, which visits every
//! leaf its footprint may meet, finds it. (The search's exact test of a widened segment
//! widens the point's box, rounded outward, where the tree's leaves met the segment
//! widened by its pad: the two differ by less than a float gap, far within the margin
//! of [`super::clearly_apart`].)

use super::{clearly_apart, Box2, ItemIndex};
use crate::kernel::Point2;

/// A node with more points than this is cut (into four, or two).
const LEAF_POINTS: usize = 8;

/// Nodes are not cut below this depth (points close to each other for the extent, or
/// equal ones, would otherwise be cut for as long as the floats allow; a leaf at this
/// depth is 2⁻⁴⁸ of the extent across).
const MOST_DEPTH: u32 = 48;

/// No node or no leaf list, in [`Node`].
const NONE: u32 = u32::MAX;

/// A node of the tree: its box, and its first child and how many (two or four,
/// consecutive) or, for a leaf, its number.
#[derive(Clone, Copy)]
struct Node {
    bx: Box2,
    first_child: u32,
    children: u32,
    leaf: u32,
}

/// The tree, with each moved item listed in the leaves its footprint may meet.
pub(super) struct Tree {
    nodes: Vec<Node>,
    /// Leaf `l`'s items are `items[starts[l]..starts[l + 1]]`.
    starts: Vec<u32>,
    items: Vec<u32>,
    /// Items below this number are segments (widened by their pads).
    segments: usize,
}

/// The centre of `lo..=hi` where it lies strictly between them (else the side cannot be
/// cut in floats); of the side between ±`f64::MAX` where it ends at an infinity (boxes
/// widened outward from points next to `f64::MAX`), so that such a side is cut too.
fn middle(lo: f64, hi: f64) -> Option<f64> {
    let m = 0.5 * lo.max(-f64::MAX) + 0.5 * hi.min(f64::MAX);
    (lo < m && m < hi).then_some(m)
}

impl Tree {
    /// The tree over `points` (those in the items' extent) for the items with boxes
    /// `boxes`, the first `segments` of them the segments `line_of(k)` widened by their
    /// pads (`boxes[k]` holds that footprint); `None` where the items would be listed
    /// more than `most` times in all, or there are none.
    pub(super) fn new(
        points: &[Point2],
        boxes: &[Box2],
        segments: usize,
        line_of: impl Fn(usize) -> super::grid::Line,
        most: usize,
    ) -> Option<Tree> {
        let extent = boxes.iter().copied().reduce(|a, b| a.union(&b))?;
        let inside = |p: &Point2| {
            extent.x0 <= p.x && p.x <= extent.x1 && extent.y0 <= p.y && p.y <= extent.y1
        };
        let mut order: Vec<Point2> = points.iter().copied().filter(inside).collect();
        let mut nodes = vec![Node {
            bx: extent,
            first_child: NONE,
            children: 0,
            leaf: NONE,
        }];
        // Cut the nodes with too many points, each over its run of `order`: in four at
        // its centre, or in two where only one side can be cut in floats.
        let mut todo = vec![(0usize, 0usize, order.len(), 0u32)];
        let mut leaves = 0u32;
        while let Some((node, from, to, depth)) = todo.pop() {
            let bx = nodes[node].bx;
            let (mx, my) = (middle(bx.x0, bx.x1), middle(bx.y0, bx.y1));
            if to - from <= LEAF_POINTS || depth >= MOST_DEPTH || (mx.is_none() && my.is_none()) {
                nodes[node].leaf = leaves;
                leaves += 1;
                continue;
            }
            // The parts, low y first, low x first within (a point on a cut goes to the
            // low side; either would do: the points only say where to cut).
            let run = &mut order[from..to];
            let halves = |lo: f64, m: Option<f64>, hi: f64| match m {
                Some(m) => vec![(lo, m), (m, hi)],
                None => vec![(lo, hi)],
            };
            let (halves_x, halves_y) = (halves(bx.x0, mx, bx.x1), halves(bx.y0, my, bx.y1));
            let low_y = my.map_or(run.len(), |my| partition(run, |p| p.y <= my));
            let rows = if my.is_some() {
                vec![(0, low_y), (low_y, run.len())]
            } else {
                vec![(0, run.len())]
            };
            // Where each part's run ends (parts in the order of the boxes below).
            let mut ends = vec![0];
            for (lo, hi) in rows {
                if let Some(mx) = mx {
                    ends.push(lo + partition(&mut run[lo..hi], |p| p.x <= mx));
                }
                ends.push(hi);
            }
            let first = nodes.len();
            nodes[node].first_child = first as u32;
            nodes[node].children = (halves_x.len() * halves_y.len()) as u32;
            let mut part = 0;
            for &(y0, y1) in &halves_y {
                for &(x0, x1) in &halves_x {
                    nodes.push(Node {
                        bx: Box2 { x0, x1, y0, y1 },
                        first_child: NONE,
                        children: 0,
                        leaf: NONE,
                    });
                    todo.push((
                        first + part,
                        from + ends[part],
                        from + ends[part + 1],
                        depth + 1,
                    ));
                    part += 1;
                }
            }
        }
        drop(order);
        // Each item in the leaves it may meet, as (leaf, item), then grouped by leaf.
        let mut listed: Vec<(u32, u32)> = Vec::new();
        let mut stack = Vec::new();
        for (k, b) in boxes.iter().enumerate() {
            let line = (k < segments).then(|| line_of(k));
            stack.push(0usize);
            while let Some(n) = stack.pop() {
                let node = &nodes[n];
                if !node.bx.overlaps(b)
                    || line.is_some_and(|l| clearly_apart(l.a, l.b, l.pad, &node.bx))
                {
                    continue;
                }
                if node.first_child == NONE {
                    listed.push((node.leaf, k as u32));
                    if listed.len() > most {
                        return None;
                    }
                } else {
                    let c = node.first_child as usize;
                    stack.extend(c..c + node.children as usize);
                }
            }
        }
        let mut starts = vec![0u32; leaves as usize + 1];
        for &(leaf, _) in &listed {
            starts[leaf as usize + 1] += 1;
        }
        for l in 1..starts.len() {
            starts[l] += starts[l - 1];
        }
        let mut at = starts.clone();
        let mut items = vec![0u32; listed.len()];
        for &(leaf, k) in &listed {
            items[at[leaf as usize] as usize] = k;
            at[leaf as usize] += 1;
        }
        Some(Tree {
            nodes,
            starts,
            items,
            segments,
        })
    }

    /// Calls `f` for each item listed in a leaf that `meets` may meet (given the leaf's
    /// box), once per `query` (`stamp` as in [`super::grid::Grid::visit`]).
    #[inline(always)]
    fn visit_by(
        &self,
        meets: impl Fn(&Box2) -> bool,
        query: usize,
        stamp: &mut [usize],
        mut f: impl FnMut(usize),
    ) {
        // (Depth at most 48: three children waiting per level, and the root.)
        let mut stack = [0u32; 4 * MOST_DEPTH as usize + 4];
        let mut len = 1;
        while len > 0 {
            len -= 1;
            let node = &self.nodes[stack[len] as usize];
            if !meets(&node.bx) {
                continue;
            }
            if node.first_child == NONE {
                let l = node.leaf as usize;
                for &item in &self.items[self.starts[l] as usize..self.starts[l + 1] as usize] {
                    let item = item as usize;
                    if stamp[item] != query {
                        stamp[item] = query;
                        f(item);
                    }
                }
            } else {
                for c in 0..node.children {
                    stack[len] = node.first_child + c;
                    len += 1;
                }
            }
        }
    }
}

impl ItemIndex for Tree {
    /// Whether item `k` is a segment, listed where its widened segment may meet a leaf
    /// (the search then tests it against a point's box exactly).
    fn is_long(&self, k: usize) -> bool {
        k < self.segments
    }

    /// Calls `f` once for each item listed in a leaf box `b` overlaps: every item whose
    /// footprint meets `b`, and others (as [`super::grid::Grid::visit`]).
    fn visit(&self, b: &Box2, query: usize, stamp: &mut [usize], f: impl FnMut(usize)) {
        self.visit_by(|leaf| leaf.overlaps(b), query, stamp, f);
    }

    /// [`Tree::visit`] for the segment `a b` (whose box is `bx`): the leaves it may meet.
    /// `f(item, true)`: the search tests the segment against the item exactly.
    fn visit_segment(
        &self,
        a: Point2,
        b: Point2,
        bx: &Box2,
        query: usize,
        stamp: &mut [usize],
        mut f: impl FnMut(usize, bool),
    ) {
        let meets = |leaf: &Box2| leaf.overlaps(bx) && !clearly_apart(a, b, (0.0, 0.0), leaf);
        self.visit_by(meets, query, stamp, |k| f(k, true));
    }
}

/// Moves the points for which `low` holds to the front of `run`; their count.
fn partition(run: &mut [Point2], low: impl Fn(&Point2) -> bool) -> usize {
    let mut at = 0;
    for k in 0..run.len() {
        if low(&run[k]) {
            run.swap(at, k);
            at += 1;
        }
    }
    at
}

#[cfg(test)]
mod tests {
    use super::super::grid::tests::{assert_visits_every_footprint, random_lines};
    use super::super::grid::Line;
    use super::super::segment_meets_box;
    use super::*;

    /// The leaf whose box holds `p` (a point on a cut: the low side's).
    fn leaf_box(tree: &Tree, p: Point2) -> Box2 {
        let mut n = 0;
        loop {
            let node = &tree.nodes[n];
            if node.first_child == NONE {
                return node.bx;
            }
            let first = node.first_child as usize;
            let holds = |b: &Box2| b.x0 <= p.x && p.x <= b.x1 && b.y0 <= p.y && p.y <= b.y1;
            n = (first..first + node.children as usize)
                .find(|&c| holds(&tree.nodes[c].bx))
                .expect("the children cover their parent");
        }
    }

    /// Every query meets every item whose footprint meets it, once (boxes of points and
    /// segments at every angle, widened; point-sized and larger queries; segments as
    /// queries against the boxes), on trees over points spread out, gathered in a small
    /// part of the extent, repeated, and all on one vertical line (the tree then cuts
    /// only in y), at unit scale, near 1e-300 and 3e15 from the origin. Where the points
    /// gather, the leaves there are small.
    #[test]
    fn queries_meet_every_item_whose_footprint_meets_them() {
        let mut below = crate::testing::below(0x7_4ee5);
        let rounds = [(0.0, 1.0, false), (0.0, 1e-300, false), (3e15, 1.0, false)];
        for (round, (offset, scale, flat)) in
            rounds.into_iter().chain([(0.0, 1.0, true)]).enumerate()
        {
            let at = |q: Point2| Point2::new(offset + q.x * scale, offset + q.y * scale);
            let squash = |q: Point2| if flat { Point2::new(5_000.0, q.y) } else { q };
            let lines: Vec<Line> = random_lines(&mut below, 400)
                .iter()
                .map(|l| Line {
                    a: at(squash(l.a)),
                    b: at(squash(l.b)),
                    pad: if flat {
                        (0.0, l.pad.1 * scale)
                    } else {
                        (l.pad.0 * scale, l.pad.1 * scale)
                    },
                })
                .collect();
            let mut boxes: Vec<Box2> = lines
                .iter()
                .map(|l| Box2::around(l.a, l.b, l.pad))
                .collect();
            let mut points = Vec::new();
            for k in 0..3000u64 {
                let q = match k % 3 {
                    // Gathered within 10 units (of an extent of 10⁴), spread, repeated.
                    0 => Point2::new(
                        4_000.0 + below(1_000) as f64 / 100.0,
                        6_000.0 + below(1_000) as f64 / 100.0,
                    ),
                    1 => Point2::new(below(10_000) as f64, below(10_000) as f64),
                    _ => Point2::new(7_000.0, 2_000.0),
                };
                points.push(at(squash(q)));
            }
            // (And small boxes around some of them, as moved points have.)
            for &c in points.iter().step_by(10) {
                let s = below(3) as f64 * scale;
                boxes.push(Box2::around(c, c, (if flat { 0.0 } else { s }, s)));
            }
            let tree = Tree::new(&points, &boxes, lines.len(), |k| lines[k], usize::MAX)
                .expect("no bound");
            if !flat {
                let small = leaf_box(&tree, at(Point2::new(4_005.0, 6_005.0)));
                assert!(
                    small.x1 - small.x0 < 20.0 * scale,
                    "round {round}: {:?}",
                    (small.x0, small.x1)
                );
            }
            let mut queries: Vec<Box2> = (0..3000)
                .map(|k| {
                    let (x, y) = if k % 2 == 0 {
                        (3_990.0 + below(30) as f64, 5_990.0 + below(30) as f64)
                    } else {
                        (below(10_400) as f64 - 200.0, below(10_400) as f64 - 200.0)
                    };
                    let c = at(squash(Point2::new(x, y)));
                    let s = [0.0, 0.5, 3.0, 40.0][below(4) as usize] * scale;
                    Box2::around(c, c, (s, 0.5 * s))
                })
                .collect();
            queries.extend_from_slice(&boxes);
            let visit = |b: &Box2, q: usize, stamp: &mut [usize], f: &mut dyn FnMut(usize)| {
                tree.visit(b, q, stamp, f)
            };
            assert_visits_every_footprint(&visit, &boxes, &lines, &queries, 1, round);
            let mut stamp = vec![usize::MAX; boxes.len()];
            for (q, s) in random_lines(&mut below, 300).iter().enumerate() {
                let (a, b) = (at(squash(s.a)), at(squash(s.b)));
                let bx = Box2::around(a, b, (0.0, 0.0));
                let mut got = Vec::new();
                tree.visit_segment(a, b, &bx, q, &mut stamp, |k, _| {
                    if k >= lines.len() && segment_meets_box(a, b, &boxes[k]) {
                        got.push(k);
                    }
                });
                got.sort_unstable();
                let want: Vec<usize> = (lines.len()..boxes.len())
                    .filter(|&k| segment_meets_box(a, b, &boxes[k]))
                    .collect();
                assert_eq!(got, want, "round {round}, segment {q}");
            }
        }
    }

    /// Boxes widened to infinity (from points next to ±`f64::MAX`) still let the tree cut
    /// their extent, and queries meet every item whose box overlaps them.
    #[test]
    fn infinite_extents_are_cut() {
        let mut below = crate::testing::below(0x7_4ee6);
        let huge = |k: u64| (k as f64 - 50_150.0) * 3.5e303;
        let mut boxes: Vec<Box2> = (0..400)
            .map(|_| {
                let (x, y, w, h) = (below(100_000), below(100_000), below(300), below(300));
                Box2 {
                    x0: huge(x),
                    x1: huge(x + w),
                    y0: huge(y),
                    y1: huge(y + h),
                }
            })
            .collect();
        boxes[0].x1 = f64::INFINITY;
        boxes[1].y0 = f64::NEG_INFINITY;
        boxes[2].x0 = f64::NEG_INFINITY;
        boxes[3].y1 = f64::INFINITY;
        let points: Vec<Point2> = (0..2_000)
            .map(|_| Point2::new(huge(below(100_300)), huge(below(100_300))))
            .collect();
        let tree = Tree::new(&points, &boxes, 0, |_| unreachable!(), usize::MAX).expect("no bound");
        assert!(tree.starts.len() > 100, "{} leaves", tree.starts.len() - 1);
        let visit = |b: &Box2, q: usize, stamp: &mut [usize], f: &mut dyn FnMut(usize)| {
            tree.visit(b, q, stamp, f)
        };
        assert_visits_every_footprint(&visit, &boxes, &[], &boxes, 1, 0);
    }

    /// Past `most` entries there is no tree; with no items, none either.
    #[test]
    fn too_many_entries_make_no_tree() {
        let lines: Vec<Line> = (0..100)
            .map(|k| Line {
                a: Point2::new(0.0, k as f64),
                b: Point2::new(1_000.0, k as f64 + 0.5),
                pad: (0.1, 0.1),
            })
            .collect();
        let boxes: Vec<Box2> = lines
            .iter()
            .map(|l| Box2::around(l.a, l.b, l.pad))
            .collect();
        let points: Vec<Point2> = (0..4_000)
            .map(|k| Point2::new((k % 1_000) as f64, (k / 1_000) as f64 * 25.0))
            .collect();
        let tree = Tree::new(&points, &boxes, lines.len(), |k| lines[k], usize::MAX);
        let entries = tree.as_ref().map_or(0, |t| t.items.len());
        assert!(entries > 100);
        assert!(Tree::new(&points, &boxes, lines.len(), |k| lines[k], entries - 1).is_none());
        assert!(Tree::new(&points, &[], 0, |k| lines[k], usize::MAX).is_none());
    }
}
