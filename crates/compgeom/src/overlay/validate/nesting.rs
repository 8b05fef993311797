//! Which rings lie inside which, for [`super::validity_problems`], once no edges cross or
//! overlap and no rings of a polygon touch in a loop.
//!
//! Then two rings of one polygon meet at one point at most (the touches the intersection
//! sweep found, [`Touches`]), so a vertex of one that is not that point lies strictly
//! inside the other or strictly outside it, and so does the whole ring: one exact
//! winding number decides. The winding numbers are taken in one pass over the edges of
//! the ring around, for all the points asked of it at once ([`windings`]): a shell of s
//! edges with h holes costs O((s + h) log h) plus, per edge, the holes level with it
//! (usually few; O(s h) only where many edges span the heights of many holes, as the
//! test of each hole against the whole shell always cost).

use super::{ring_name, Problem, Ring};
use crate::kernel::{orient2d, Orientation, Point2};
use crate::overlay::trace::box_of;
use std::ops::Range;

/// The point where each pair of rings of one polygon touch, `(ring, ring, point)` with
/// the smaller ring first, sorted.
#[derive(Default)]
pub(super) struct Touches(Vec<(usize, usize, Point2)>);

impl Touches {
    /// Records that rings `a` and `b` (of one polygon) meet at `at`.
    pub(super) fn add(&mut self, a: usize, b: usize, at: Point2) {
        self.0.push((a.min(b), a.max(b), at));
    }

    /// Ready for [`Touches::between`].
    pub(super) fn sort(&mut self) {
        self.0.sort_unstable_by_key(|&(a, b, _)| (a, b));
    }

    /// Where rings `a` and `b` touch, if they do (at one point: with no loops there is
    /// no second).
    fn between(&self, a: usize, b: usize) -> Option<Point2> {
        let key = (a.min(b), a.max(b));
        let k = self.0.partition_point(|&(s, t, _)| (s, t) < key);
        self.0
            .get(k)
            .filter(|&&(s, t, _)| (s, t) == key)
            .map(|&(_, _, p)| p)
    }

    /// A vertex of `ring` (number `k`) that is not on ring `other`: its first, or its
    /// second where the first is where they touch (consecutive vertices differ).
    pub(super) fn off(&self, ring: &[Point2], k: usize, other: usize) -> Point2 {
        if self.between(k, other) == Some(ring[0]) {
            ring[1]
        } else {
            ring[0]
        }
    }
}

/// The winding number of the closed `ring` around `q` (not on it), exactly, edge by
/// edge: for one point (the batched [`windings`] is tested against it).
pub(super) fn winding(ring: &[Point2], q: Point2) -> i32 {
    let mut w = 0;
    for (i, &a) in ring.iter().enumerate() {
        let b = ring[(i + 1) % ring.len()];
        if a.y <= q.y && b.y > q.y && orient2d(a, b, q) == Orientation::CounterClockwise {
            w += 1;
        } else if a.y > q.y && b.y <= q.y && orient2d(a, b, q) == Orientation::Clockwise {
            w -= 1;
        }
    }
    w
}

/// The winding number of the closed `ring` around each of `queries`, none of which is on
/// it, exactly; O((n + m) log m) for n edges and m queries, plus the queries within each
/// edge's span of y.
pub(super) fn windings(ring: &[Point2], queries: &[Point2]) -> Vec<i32> {
    if queries.is_empty() {
        // (Most polygons have no holes: no pass over their shells.)
        return Vec::new();
    }
    let mut by_y: Vec<usize> = (0..queries.len()).collect();
    by_y.sort_unstable_by(|&i, &j| queries[i].y.total_cmp(&queries[j].y));
    let ys: Vec<f64> = by_y.iter().map(|&i| queries[i].y).collect();
    let mut out = vec![0; queries.len()];
    for (i, &a) in ring.iter().enumerate() {
        let b = ring[(i + 1) % ring.len()];
        // An edge counts for the points level with it from its lower end up to, not
        // including, its upper end: +1 going up with the point on its left, -1 going
        // down with the point on its right.
        let (lo, hi, up) = if a.y < b.y {
            (a.y, b.y, true)
        } else {
            (b.y, a.y, false)
        };
        let from = ys.partition_point(|&y| y < lo);
        let to = ys.partition_point(|&y| y < hi);
        for &q in &by_y[from..to] {
            match (orient2d(a, b, queries[q]), up) {
                (Orientation::CounterClockwise, true) => out[q] += 1,
                (Orientation::Clockwise, false) => out[q] -= 1,
                _ => {}
            }
        }
    }
    out
}

/// A box's sides: `[x0, x1, y0, y1]`, as [`box_of`] gives them.
type Bounds = [f64; 4];

/// Calls `f(inner, outer)` for the pairs of `boxes` where the box of `outer` holds that
/// of `inner` (both ways for equal boxes), each box against those it overlaps along one
/// axis: the one along which the boxes are spread wider for their size (a column of
/// holes is swept in y).
pub(super) fn for_each_box_within(boxes: &[Bounds], f: impl FnMut(usize, usize)) {
    let spread = |lo: fn(&Bounds) -> f64, hi: fn(&Bounds) -> f64| {
        let extent = boxes.iter().map(hi).fold(f64::NEG_INFINITY, f64::max)
            - boxes.iter().map(lo).fold(f64::INFINITY, f64::min);
        let sizes: f64 = boxes.iter().map(|b| hi(b) - lo(b)).sum();
        extent * boxes.len() as f64 / sizes
    };
    // (Holding is the same with x and y swapped.)
    if spread(|b| b[2], |b| b[3]) > spread(|b| b[0], |b| b[1]) {
        let swapped: Vec<Bounds> = boxes.iter().map(|b| [b[2], b[3], b[0], b[1]]).collect();
        for_each_box_within_by_x(&swapped, f);
    } else {
        for_each_box_within_by_x(boxes, f);
    }
}

/// [`for_each_box_within`], sweeping in x.
fn for_each_box_within_by_x(boxes: &[Bounds], mut f: impl FnMut(usize, usize)) {
    let holds =
        |o: &Bounds, i: &Bounds| o[0] <= i[0] && i[1] <= o[1] && o[2] <= i[2] && i[3] <= o[3];
    let mut by_x: Vec<usize> = (0..boxes.len()).collect();
    by_x.sort_unstable_by(|&i, &j| boxes[i][0].total_cmp(&boxes[j][0]));
    for (k, &i) in by_x.iter().enumerate() {
        for &j in &by_x[k + 1..] {
            if boxes[j][0] > boxes[i][1] {
                break;
            }
            if holds(&boxes[i], &boxes[j]) {
                f(j, i);
            }
            if holds(&boxes[j], &boxes[i]) {
                f(i, j);
            }
        }
    }
}

/// Reports each hole with a point outside its shell (so all of it, as nothing crosses);
/// true per such hole.
pub(super) fn holes_outside_shells(
    rings: &[Ring],
    spans: &[Range<usize>],
    touches: &Touches,
    out: &mut Vec<Problem>,
) -> Vec<bool> {
    let mut outside = vec![false; rings.len()];
    for span in spans {
        let (shell, holes) = (span.start, span.start + 1..span.end);
        let queries: Vec<Point2> = holes
            .clone()
            .map(|h| touches.off(&rings[h].2, h, shell))
            .collect();
        let windings = windings(&rings[shell].2, &queries);
        for ((h, q), w) in holes.zip(queries).zip(windings) {
            if w == 0 {
                outside[h] = true;
                out.push(Problem {
                    message: format!(
                        "{}: lies outside its shell",
                        ring_name(rings[h].0, rings[h].1)
                    ),
                    at: Some(q),
                    polygon: Some(rings[h].0),
                });
            }
        }
    }
    outside
}

/// Pairs of holes [`holes_inside_holes`] collects before it tests them (a batch: the
/// pairs of nested boxes can be quadratic in number, the holes found inside another
/// are not tested again).
const NESTING_BATCH: usize = 1 << 14;

/// Reports each hole inside another hole of its polygon, once (holes overlapping in
/// area without crossing are nested): tested where the box of one holds the other's,
/// in batches, each batch by outer hole (one pass over its edges for all its inner
/// candidates), a hole already found inside another left out of later batches.
pub(super) fn holes_inside_holes(
    rings: &[Ring],
    spans: &[Range<usize>],
    touches: &Touches,
    outside: &[bool],
    out: &mut Vec<Problem>,
) {
    for span in spans {
        let holes: Vec<usize> = (span.start + 1..span.end)
            .filter(|&h| !outside[h])
            .collect();
        if holes.len() < 2 {
            continue;
        }
        let boxes: Vec<_> = holes.iter().map(|&h| box_of(&rings[h].2)).collect();
        // Per hole (by its place in `holes`), the hole it was found inside and where.
        let mut inside: Vec<Option<(usize, Point2)>> = vec![None; holes.len()];
        let mut batch: Vec<(usize, usize)> = Vec::new();
        let test = |batch: &mut Vec<(usize, usize)>, inside: &mut [Option<(usize, Point2)>]| {
            batch.sort_unstable_by_key(|&(inner, outer)| (outer, inner));
            for group in batch.chunk_by(|a, b| a.1 == b.1) {
                let g = holes[group[0].1];
                let inner: Vec<usize> = group
                    .iter()
                    .map(|&(i, _)| i)
                    .filter(|&i| inside[i].is_none())
                    .collect();
                let queries: Vec<Point2> = inner
                    .iter()
                    .map(|&i| touches.off(&rings[holes[i]].2, holes[i], g))
                    .collect();
                for ((&i, &q), w) in inner
                    .iter()
                    .zip(&queries)
                    .zip(windings(&rings[g].2, &queries))
                {
                    if w != 0 {
                        inside[i] = Some((g, q));
                    }
                }
            }
            batch.clear();
        };
        for_each_box_within(&boxes, |inner, outer| {
            if inside[inner].is_none() {
                batch.push((inner, outer));
                if batch.len() == NESTING_BATCH {
                    test(&mut batch, &mut inside);
                }
            }
        });
        test(&mut batch, &mut inside);
        for (&h, found) in holes.iter().zip(inside) {
            if let Some((g, q)) = found {
                out.push(Problem {
                    message: format!(
                        "{}: lies inside hole {}",
                        ring_name(rings[h].0, rings[h].1),
                        rings[g].1 - 1
                    ),
                    at: Some(q),
                    polygon: Some(rings[h].0),
                });
            }
        }
    }
}

/// A point strictly inside the polygon with exterior `outer` and holes `holes` (rings of
/// any orientation), checked exactly: near a convex vertex `v` of the exterior, between
/// its neighbours `u` and `w`, the point `v + t (u − v) + t (w − v)` rounded, for `t`
/// from 1/3 (the centroid of the triangle) down to 2⁻²⁰ (close to `v`, clear of a hole
/// over the triangle), at the first vertices that have one. None where none is (a
/// sliver thinner than the rounding).
pub(super) fn point_inside(outer: &[Point2], holes: &[Vec<Point2>]) -> Option<Point2> {
    let n = outer.len();
    let turn = super::ring_orientation(outer);
    let inside = |q: Point2| {
        let mut rings = std::iter::once(outer).chain(holes.iter().map(Vec::as_slice));
        rings.all(|r| !super::on_ring(r, q))
            && winding(outer, q) != 0
            && holes.iter().all(|h| winding(h, q) == 0)
    };
    let corner = |i: usize| (outer[(i + n - 1) % n], outer[i], outer[(i + 1) % n]);
    (0..n)
        .filter(|&i| {
            let (u, v, w) = corner(i);
            orient2d(u, v, w) == turn
        })
        .take(CANDIDATES)
        .flat_map(|i| {
            let (u, v, w) = corner(i);
            STEPS.iter().map(move |&t| {
                Point2::new(
                    v.x + t * ((u.x - v.x) + (w.x - v.x)),
                    v.y + t * ((u.y - v.y) + (w.y - v.y)),
                )
            })
        })
        .find(|&q| q.is_finite() && inside(q))
}

/// How many convex vertices [`point_inside`] tries.
const CANDIDATES: usize = 16;

/// The steps from a vertex towards its neighbours [`point_inside`] tries.
const STEPS: [f64; 4] = [1.0 / 3.0, 1.0 / 16.0, 1.0 / 1024.0, 1.0 / 1_048_576.0];

#[cfg(test)]
mod tests {
    use super::*;

    fn p(x: f64, y: f64) -> Point2 {
        Point2::new(x, y)
    }

    /// The batched winding numbers are those of one point at a time, on rings of both
    /// orientations with points level with vertices and horizontal edges.
    #[test]
    fn windings_at_once_match_one_by_one() {
        let mut below = crate::testing::below(0x71d1);
        for _ in 0..300 {
            let n = 3 + below(9) as usize;
            let ring: Vec<Point2> = (0..n)
                .map(|_| p(below(8) as f64, below(8) as f64))
                .collect();
            let queries: Vec<Point2> = (0..20)
                .map(|_| p(below(16) as f64 / 2.0, below(16) as f64 / 2.0))
                .filter(|&q| !super::super::on_ring(&ring, q))
                .collect();
            let got = windings(&ring, &queries);
            for (q, w) in queries.iter().zip(got) {
                assert_eq!(w, winding(&ring, *q), "{ring:?} {q:?}");
            }
        }
    }

    #[test]
    fn boxes_within_lists_every_held_box() {
        let mut below = crate::testing::below(0xb0c5);
        for _ in 0..200 {
            let boxes: Vec<Bounds> = (0..12)
                .map(|_| {
                    let (x, y) = (below(10) as f64, below(10) as f64);
                    [x, x + below(5) as f64, y, y + below(5) as f64]
                })
                .collect();
            let collect = |by_x: bool| {
                let mut pairs = Vec::new();
                if by_x {
                    for_each_box_within_by_x(&boxes, |i, o| pairs.push((i, o)));
                } else {
                    for_each_box_within(&boxes, |i, o| pairs.push((i, o)));
                }
                pairs.sort_unstable();
                pairs
            };
            let got = collect(false);
            assert_eq!(got, collect(true));
            let mut want = Vec::new();
            for (i, a) in boxes.iter().enumerate() {
                for (o, b) in boxes.iter().enumerate() {
                    if i != o && b[0] <= a[0] && a[1] <= b[1] && b[2] <= a[2] && a[3] <= b[3] {
                        want.push((i, o));
                    }
                }
            }
            assert_eq!(got, want);
        }
    }

    #[test]
    fn a_point_inside_is_inside() {
        let square = vec![p(0.0, 0.0), p(4.0, 0.0), p(4.0, 4.0), p(0.0, 4.0)];
        let q = point_inside(&square, &[]).unwrap();
        assert!(q.x > 0.0 && q.x < 4.0 && q.y > 0.0 && q.y < 4.0);
        // Clockwise, with a hole over the first ear's centroid.
        let mut cw = square.clone();
        cw.reverse();
        let hole = vec![p(0.5, 0.5), p(2.0, 0.5), p(2.0, 2.0), p(0.5, 2.0)];
        let q = point_inside(&cw, std::slice::from_ref(&hole)).unwrap();
        assert_eq!(winding(&hole, q), 0);
        assert!(!super::super::on_ring(&hole, q));
        // A reflex vertex is not a candidate: an L whose first vertex is reflex.
        let l = vec![
            p(2.0, 2.0),
            p(2.0, 4.0),
            p(0.0, 4.0),
            p(0.0, 0.0),
            p(4.0, 0.0),
            p(4.0, 2.0),
        ];
        let q = point_inside(&l, &[]).unwrap();
        assert_ne!(winding(&l, q), 0);
    }
}
