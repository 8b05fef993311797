//! Whether rounding a result's vertices to `f64` kept it valid, and the repair when it
//! may not have.
//!
//! A boolean result is exact and valid before its vertices are rounded: input points
//! stay where they are, but a constructed crossing moves to its nearest `f64` point, by
//! at most half the gap between floats around it. Where some other part of the result
//! passes within such a distance, the rounded rings can touch or cross, a hole can end
//! up outside its shell, or a ring can turn over.
//!
//! [`failing_rings`] decides, exactly and conservatively, that this did not happen.
//! Think of every vertex moving in a straight line from its exact point `p` to its
//! rounded point `r`, all at once. The drawing changes its topology only at a moment when
//! some vertex touches an edge it is not an end of (two edges begin to cross, overlap or
//! fold over only at such a moment; a ring turns over or leaves its shell only through
//! one). A moving vertex stays in the box of its float's neighbours around `r` (half
//! gaps are below one gap); a moving edge stays in the hull of its ends' boxes, within
//! one box of its rounded position. So when no rounded edge comes within the sum of the
//! two boxes of a vertex's rounded point (each box zero for a point that did not move),
//! for every vertex and edge not incident to it with at least one of them moved, no such
//! moment exists and the rounded result is the exact one, deformed: valid. The test
//! "segment meets box" is exact (orientations of the box's corners), on boxes enlarged
//! so that their `f64` corners are on the safe side.
//!
//! Real data has such near pairs (vertices a fraction of a float gap from an edge, where
//! near-coincident input edges cross): most of the JTS robustness pairs and the GEOS-837
//! dissolve. For them the final positions decide: the pair is accepted when the rounded
//! vertex lies strictly on the same side of the rounded edge as the exact vertex of the
//! exact edge. A vertex exactly on the edge's line (beyond its ends: the exact result is
//! valid) has no such side; it is accepted when only one of the three points moved (it
//! then never touches the edge on the way, see [`passes`]). Before any of this, a pair
//! whose point is beyond both ends of the edge in x or in y, on one side both where
//! rounding to nearest put them and where they end, passes: being rounded to nearest,
//! their exact points are apart so too, and they stay apart on the way
//! ([`apart_along_an_axis`]; most crossings along one input edge). With every near pair
//! accepted and every other pair out of reach, no edges cross or touch that did not,
//! and no ring is carried across another's edge: the rounded rings keep the exact
//! result's topology.
//!
//! Where a pair fails on a side flip, [`nudge`] moves its crossings, one at a time, to
//! other floats around their exact points (at most one float away per axis, so within
//! the reach the argument allows) until the pair passes without another failing: a
//! corner of the float box around the exact point is always on the exact side of a
//! line, so a pair failing alone with one of its points moved is mended so unless that
//! float is a neighbour's point (a pair needing two points moved together is united
//! again). On the GEOS-837
//! dissolve this mends both failing pairs.
//!
//! The test sees the points a ring keeps. Where two consecutive vertices of a ring round
//! to one point, the edge between them collapsed: the point stands for both (edges
//! leave it from the second), and the collapsed edge is tested as an edge of no length,
//! which nothing may come near. Three vertices on one point the tracing reports, and
//! that result is not taken as it is: it is united again, with the polygons near it
//! (the check does not follow such a ring against them either). A ring left with fewer than three points was
//! thinner than the rounding (a sliver between near-coincident edges): the tracing
//! drops it, as a second union would, and the check decides the rings left (the exact
//! result without a ring of it is still valid: a polygon without one of its holes, or
//! the other polygons without one). Except where other polygons lie inside a dropped
//! hole (an island in a sliver of a lake, which rounding need not flatten): they would
//! overlap the hole's polygon, so they and that polygon are united again (merged).
//!
//! Otherwise [`super::trace::traced_boolean`] unites the polygons of the failing rings
//! again with the [`super::FillRule::Positive`] rule (the arrangement of their rounded
//! rings has the new crossings as vertices; the union of each polygon's shell minus its
//! holes is the result, moved by no more than the rounding), keeps the other polygons as
//! they are (a point of theirs on the new rings stays a vertex there), and checks the
//! new polygons' vertices the same way, among the kept ones (whose points do not move; a
//! kept polygon that fails joins the next union). Measured, before nudging: on random
//! float rings of 3–20 vertices about one result in 10⁴ needed this; on nested shapes
//! shifted by thirds a fifth; on the JTS robustness pairs and the GEOS-837 dissolve
//! most results. With it and the rules for vertices on an edge's line and beyond an
//! edge along an axis, nudging, and slivers rounded to fewer than three points dropped:
//! the dissolve none; of the 52 JTS pairs' results 1 intersection, 1 union, 1
//! difference and 14 symmetric differences, 4 of them united a second time (before
//! slivers were dropped 1, 3, 3 and 19, 5 twice: a dropped sliver flagged its polygon
//! and kept the check from nudging anywhere in that result; without the axis rule 2,
//! 7, 4 and 27, 6 twice). Two unions have always sufficed (the bound [`REPAIRS`] is a
//! guard: past it the result is returned as it is).
//!
//! The faces of an overlay go through the same check and mending ([`mend_faces`]); they
//! are not united again (the faces are a partition with labels): the faces near what
//! is left are reported.

use crate::kernel::{orient2d, Orientation, Point2};
use crate::scratch::{self, Scratch};
use grid::{Grid, Line};
use mend::nudge;
use sieve::Sieve;
use std::cmp::Ordering;
use strips::Strips;
use tree::Tree;

mod faces;
mod grid;
mod mend;
mod sieve;
mod straight;
mod strips;
mod tree;

pub(super) use faces::{mend_faces, suspect_faces};
pub(super) use straight::{stands_for_any, straighten_all, without_straight_points};

/// At most this many re-unions of a result whose rounding may have broken it (each
/// checked as the first one was); the last one is returned as it is.
pub(super) const REPAIRS: usize = 4;

/// What the check knows of a kept point of a ring: the arrangement vertices the ring
/// enters it at and leaves it from (two different ones where rounding made two
/// consecutive vertices one point: the edge between them collapsed), and whether
/// rounding moved it.
#[derive(Clone, Copy, Debug, PartialEq)]
pub(super) struct PointIds {
    pub(super) enter: u32,
    pub(super) leave: u32,
    pub(super) moved: bool,
}
crate::scratch::reusable!(PointIds);

impl PointIds {
    /// A point of one vertex.
    pub(super) fn of(vertex: u32, moved: bool) -> PointIds {
        PointIds {
            enter: vertex,
            leave: vertex,
            moved,
        }
    }

    /// `self` followed by `next` rounded onto the same point; `false` (and `self`
    /// unchanged) when either already stands for two vertices (the check does not
    /// follow three).
    pub(super) fn merge(&mut self, next: PointIds) -> bool {
        if self.enter != self.leave || next.enter != next.leave {
            return false;
        }
        self.leave = next.leave;
        // (Two distinct exact points on one rounded point: at least one moved.)
        self.moved = true;
        true
    }
}

/// A result's rings before they are grouped into polygons: ring `k` is
/// `points[starts[k]..starts[k + 1]]` (closed implicitly), with what the check knows of
/// each point.
#[derive(Default)]
pub(super) struct RoundedRings {
    pub(super) points: Scratch<Point2>,
    pub(super) ids: Scratch<PointIds>,
    pub(super) starts: Scratch<usize>,
    /// How many points [`failing_rings`] moved off their nearest floats.
    pub(super) nudged: usize,
    /// Whether every point was rounded to nearest from its exact vertices (as the
    /// tracing rounds them): then [`apart_along_an_axis`] may decide pairs.
    pub(super) at_nearest: bool,
    /// The points as they were before [`nudge`] moved any (empty until it does).
    pub(super) nearest: Vec<Point2>,
}

/// An edge for the check: from point `i` to point `j` of the rings, between the exact
/// vertices `a` and `b`. A collapsed edge (both ends rounded onto one point) has
/// `i == j`.
#[derive(Clone, Copy)]
struct Edge {
    i: usize,
    j: usize,
    a: u32,
    b: u32,
}
scratch::reusable!(Edge, (u32, Edge), [Option<Orientation>; 2]);

impl RoundedRings {
    /// The ring edge from point `i` to point `j`.
    fn ring_edge(&self, i: usize, j: usize) -> Edge {
        Edge {
            i,
            j,
            a: self.ids[i].leave,
            b: self.ids[j].enter,
        }
    }

    /// Calls `f` with each edge with a moved end, from `moved` (the moved points, in
    /// increasing order): the ring edges at each (each edge once: from its start when
    /// that moved, else from its end) and the collapsed edge a point stands for (such a
    /// point is moved). O(moved + rings): the other edges are not looked at.
    fn for_each_moved_edge(&self, moved: &[usize], mut f: impl FnMut(Edge)) {
        let mut ring = 0;
        for &i in moved {
            while self.starts[ring + 1] <= i {
                ring += 1;
            }
            let (s, e) = (self.starts[ring], self.starts[ring + 1]);
            let prev = if i == s { e - 1 } else { i - 1 };
            let next = if i + 1 == e { s } else { i + 1 };
            if !self.moved(prev) {
                f(self.ring_edge(prev, i));
            }
            f(self.ring_edge(i, next));
            let id = self.ids[i];
            if id.enter != id.leave {
                f(Edge {
                    i,
                    j: i,
                    a: id.enter,
                    b: id.leave,
                });
            }
        }
    }

    /// Calls `f(i, j)` for each ring edge from point `i` to point `j` neither of which
    /// moved (collapsed edges are moved ones).
    fn for_each_unmoved_edge(&self, mut f: impl FnMut(usize, usize)) {
        for w in self.starts.windows(2) {
            let (s, e) = (w[0], w[1]);
            for i in s..e {
                let j = if i + 1 == e { s } else { i + 1 };
                if !self.moved(i) && !self.moved(j) {
                    f(i, j);
                }
            }
        }
    }

    fn moved(&self, i: usize) -> bool {
        self.ids[i].moved
    }

    /// Whether an end of edge `e` moved.
    fn edge_moved(&self, e: &Edge) -> bool {
        self.moved(e.i) || self.moved(e.j)
    }

    /// Whether point `x` is an end of edge `e`: the same arrangement vertex (rings
    /// touching at a point share it; a point standing for a collapsed edge is both of
    /// its vertices). Such a pair always passes: it is not a pair at all.
    fn is_end(&self, x: usize, e: &Edge) -> bool {
        let PointIds { enter, leave, .. } = self.ids[x];
        enter == e.a || enter == e.b || leave == e.a || leave == e.b
    }
}

/// The gap above `|v|`; at `f64::MAX`, where that is infinite, the gap below (as wide:
/// a point there moved by at most half of it).
fn gap(v: f64) -> f64 {
    let a = v.abs();
    if a == f64::MAX {
        return a - f64::from_bits(a.to_bits() - 1);
    }
    f64::from_bits(a.to_bits() + 1) - a
}

/// The next `f64` above `x` (`x` itself for +∞ and NaN).
pub(super) fn up(x: f64) -> f64 {
    if x.is_nan() || x == f64::INFINITY {
        x
    } else if x == 0.0 {
        f64::from_bits(1)
    } else if x > 0.0 {
        f64::from_bits(x.to_bits() + 1)
    } else {
        f64::from_bits(x.to_bits() - 1)
    }
}

/// The next `f64` below `x`.
pub(super) fn down(x: f64) -> f64 {
    -up(-x)
}

/// `[lo - h, hi + h]` with its ends rounded outward (so it holds the exact interval);
/// `[lo, hi]` itself for `h = 0`.
fn widened(lo: f64, hi: f64, h: f64) -> (f64, f64) {
    if h == 0.0 {
        (lo, hi)
    } else {
        (down(lo - h), up(hi + h))
    }
}

/// An axis-parallel box `[x0, x1] × [y0, y1]`.
#[derive(Clone, Copy)]
struct Box2 {
    x0: f64,
    x1: f64,
    y0: f64,
    y1: f64,
}
scratch::reusable!(Box2);

impl Box2 {
    /// The bounding box of `a` and `b`.
    fn of(a: Point2, b: Point2) -> Box2 {
        Box2 {
            x0: a.x.min(b.x),
            x1: a.x.max(b.x),
            y0: a.y.min(b.y),
            y1: a.y.max(b.y),
        }
    }

    /// The bounding box of `a` and `b`, widened by `(hx, hy)` ([`widened`]).
    fn around(a: Point2, b: Point2, (hx, hy): (f64, f64)) -> Box2 {
        let (x0, x1) = widened(a.x.min(b.x), a.x.max(b.x), hx);
        let (y0, y1) = widened(a.y.min(b.y), a.y.max(b.y), hy);
        Box2 { x0, x1, y0, y1 }
    }

    /// The bounding box of both.
    fn union(&self, o: &Box2) -> Box2 {
        Box2 {
            x0: self.x0.min(o.x0),
            x1: self.x1.max(o.x1),
            y0: self.y0.min(o.y0),
            y1: self.y1.max(o.y1),
        }
    }

    fn overlaps(&self, o: &Box2) -> bool {
        self.x0 <= o.x1 && o.x0 <= self.x1 && self.y0 <= o.y1 && o.y0 <= self.y1
    }
}

/// How far a point may have moved, per axis (a full gap: more than the half gap of
/// rounding to nearest).
fn reach(p: Point2, moved: bool) -> (f64, f64) {
    if moved {
        (gap(p.x), gap(p.y))
    } else {
        (0.0, 0.0)
    }
}

/// Whether segment `a b` meets the box of half sizes twice `(hx, hy)` around `c`
/// (its `f64` corners rounded outward, so that it holds the exact box), exactly.
fn meets(a: Point2, b: Point2, c: Point2, (hx, hy): (f64, f64)) -> bool {
    segment_meets_box(a, b, &Box2::around(c, c, (2.0 * hx, 2.0 * hy)))
}

/// Whether segment `a b` meets the closed box `bx`, exactly.
fn segment_meets_box(a: Point2, b: Point2, bx: &Box2) -> bool {
    if !Box2::around(a, b, (0.0, 0.0)).overlaps(bx) {
        return false;
    }
    if a == b {
        return true;
    }
    // The segment meets the box (their boxes overlapping) unless all four corners are
    // strictly on one side of its line. The side is the sign of (b - a) × (q - a),
    // affine in the corner q: largest at the corner furthest left of a → b, smallest at
    // the opposite one (which they are follows from exact comparisons of a and b), so
    // those two decide: the line meets the box iff the first is not right of it and
    // the second not left. (A corner rounded outward to infinity is on the line for
    // `orient2d`: where it is the deciding one the answer is "meets", never wrongly
    // "apart".)
    let (dx_positive, dy_positive) = (b.x > a.x, b.y > a.y);
    let leftmost = Point2::new(
        if dy_positive { bx.x0 } else { bx.x1 },
        if dx_positive { bx.y1 } else { bx.y0 },
    );
    let rightmost = Point2::new(
        if dy_positive { bx.x1 } else { bx.x0 },
        if dx_positive { bx.y0 } else { bx.y1 },
    );
    orient2d(a, b, leftmost) != Orientation::Clockwise
        && orient2d(a, b, rightmost) != Orientation::CounterClockwise
}

/// Whether the line through `a` and `b`, widened by `(hx, hy)`, certainly misses box
/// `bx` (so does the widened segment), decided in floats: the line meets the box iff
/// the centre's offset across it, `|d × (c − a)|` for `d = b − a`, is at most
/// `reach = |d.y| rx + |d.x| ry` for half sizes `(rx, ry)`.
///
/// Rounding errors, u = 2⁻⁵³, every coordinate below `m` in magnitude: `d` and the half
/// sizes are within a few u of themselves (differences of floats), the centre within
/// `u m` plus u of itself (its sum, then the difference); so the products `p = d.x c.y`
/// and `q = d.y c.x` are within `u m |d| + 3u (|p| + |q|)`, their difference within u
/// more of it, `reach` within 4u of itself. The test asks for a margin of 2⁻⁴⁶ = 128u
/// of `m (|d.x| + |d.y|) + |p| + |q| + reach` (and an absolute term for halving
/// subnormal coordinates), and says false where it cannot tell (overflow, NaN). A cheap
/// first test before [`fat_segment_meets_box`] for long edges, which share their
/// cells with many points far from them.
fn clearly_apart(a: Point2, b: Point2, (hx, hy): (f64, f64), bx: &Box2) -> bool {
    let m = [a.x, a.y, b.x, b.y, bx.x0, bx.x1, bx.y0, bx.y1]
        .iter()
        .fold(0.0f64, |m, v| m.max(v.abs()));
    let (dx, dy) = (b.x - a.x, b.y - a.y);
    let (cx, cy) = (
        0.5 * bx.x0 + 0.5 * bx.x1 - a.x,
        0.5 * bx.y0 + 0.5 * bx.y1 - a.y,
    );
    let (rx, ry) = (0.5 * (bx.x1 - bx.x0) + hx, 0.5 * (bx.y1 - bx.y0) + hy);
    let (p, q) = (dx * cy, dy * cx);
    let reach = dy.abs() * rx + dx.abs() * ry;
    let along = dx.abs() + dy.abs();
    let margin = (m * along + p.abs() + q.abs() + reach) / (1u64 << 46) as f64
        + (along + 1.0) * f64::MIN_POSITIVE;
    margin.is_finite() && (p - q).abs() > reach + margin
}

/// Whether segment `a b` widened by `(hx, hy)` (the points within `hx` of it in x and
/// `hy` in y, at once) meets the closed box `bx`, exactly: whether the segment meets
/// `bx` widened so (rounded outward).
fn fat_segment_meets_box(a: Point2, b: Point2, (hx, hy): (f64, f64), bx: &Box2) -> bool {
    let (x0, x1) = widened(bx.x0, bx.x1, hx);
    let (y0, y1) = widened(bx.y0, bx.y1, hy);
    segment_meets_box(a, b, &Box2 { x0, x1, y0, y1 })
}

/// The exact point's side of a rounded point, per axis: `(exact.x` vs `rounded.x`,
/// `exact.y` vs `rounded.y)`.
pub(super) type Toward = (Ordering, Ordering);

/// What [`nudge`] asks of the exact vertices: `toward(vertex, q)`, the [`Toward`] of
/// its exact point from float point `q`, and `order(u, v)`, the lexicographic (x, then
/// y) order of two vertices' exact points (distinct vertices are distinct points: the
/// order in which failing pairs are mended is then the same however the arrangement
/// numbered them).
pub(super) struct ExactPoints<T, O> {
    pub(super) toward: T,
    pub(super) order: O,
}

/// The rings near which rounding may not have kept the result's topology (module docs;
/// each ring once or more, in no order), after moving points that fail to other floats
/// around their exact ones where that makes them pass.
///
/// A pair is a vertex and an edge not incident to it, at least one of them moved; it
/// passes when they stay apart as rounding moves them, or, where they may not, when the
/// rounded vertex lies strictly on the side of the rounded edge where
/// `exact_side(edge start, edge end, vertex)` (the exact orientation of the vertices with
/// these ids) puts it. Where a pair fails, its moved vertices may be moved to any of the
/// (at most four) floats `f64` points around their exact ones, `toward(vertex, rounded)`
/// telling on which side of the rounded point the exact one is (see [`nudge`]): the
/// points are changed in `r`. Conservative: a ring listed only may have been broken.
/// Empty when no point moved.
#[inline(never)]
pub(super) fn failing_rings(
    r: &mut RoundedRings,
    exact_side: impl Fn(u32, u32, u32) -> Orientation,
    exact: Option<ExactPoints<impl Fn(u32, Point2) -> Toward, impl Fn(u32, u32) -> Ordering>>,
) -> Vec<usize> {
    if !r.ids.iter().any(|p| p.moved) {
        return Vec::new();
    }
    let pairs = near_pairs(r);
    let mut sides = ExactSides {
        side: exact_side,
        known: scratch::filled(pairs.len(), [None; 2]),
    };
    let mut failing: Scratch<usize> = scratch::with_capacity(16);
    failing.extend((0..pairs.len()).filter(|&k| !passes(r, &pairs, k, &mut sides)));
    if let Some(exact) = exact.filter(|_| !failing.is_empty()) {
        nudge(r, &pairs, &mut failing, &mut sides, &exact);
    }
    let ring_of = |i: usize| r.starts.partition_point(|&s| s <= i) - 1;
    failing
        .iter()
        .flat_map(|&k| {
            let (x, e) = pairs[k];
            [ring_of(x as usize), ring_of(e.i)]
        })
        .collect()
}

/// A point (its index in the rings' points) and an edge that may come near each other
/// as rounding moves them, or as [`nudge`] moves their points further (by at most one
/// float per axis: a pair left out stays on its side, see `line_of` in
/// [`near_pairs_indexed`]).
type Pair = (u32, Edge);

/// The pairs [`passes`] has to decide: every point against the moved edges near it,
/// every edge whose ends did not move against the moved points near it (a moved edge
/// against a point is in the first), each pair once, with boxes that overlap (on the
/// grid, a long edge only where its widened segment meets the point's box, and on the
/// quadtree every edge so: see `line_of` in [`near_pairs_indexed`]).
fn near_pairs(r: &RoundedRings) -> Scratch<Pair> {
    near_pairs_by(r, Search::Auto)
}

/// How [`near_pairs_by`] makes its box tests (tests force each).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
#[cfg_attr(not(test), allow(dead_code))]
enum Search {
    /// One by one when there are few ([`BRUTE_FORCE_TESTS`]), else on a grid or a
    /// quadtree ([`Index`]).
    Auto,
    /// Each point and edge against the moved items' boxes ([`Near`]).
    OneByOne,
    /// On a grid.
    Grid,
    /// On a quadtree over the points ([`Tree`]; on the grid where it would list the
    /// items too many times).
    Tree,
}

/// [`near_pairs`] by the search `how`: the same pairs either way, but for the pairs of
/// edges with points in their boxes and far from them, which the grid (for long edges)
/// and the quadtree (for all) leave out.
fn near_pairs_by(r: &RoundedRings, how: Search) -> Scratch<Pair> {
    let point_box = |i: usize| point_box(r, i);
    let moves = |e: &Edge| r.edge_moved(e);
    let edge_box = |e: &Edge| {
        let (a, b) = (r.points[e.i], r.points[e.j]);
        if moves(e) {
            let (hx, hy) = edge_reach(r, e);
            Box2::around(a, b, (4.0 * hx, 4.0 * hy))
        } else {
            // (Nothing to widen: most edges, looked at for every moved point.)
            Box2::of(a, b)
        }
    };
    let moved = r.ids.iter().filter(|id| id.moved).count();
    let mut moved_points: Scratch<usize> = scratch::with_capacity(moved);
    moved_points.extend((0..r.points.len()).filter(|&i| r.moved(i)));
    // (Two ring edges at each moved point, fewer where they share one: sized once,
    // mostly.)
    let mut moved_edges: Scratch<Edge> = scratch::with_capacity(2 * moved_points.len());
    r.for_each_moved_edge(&moved_points, |e| moved_edges.push(e));
    let mut boxes: Scratch<Box2> = scratch::with_capacity(moved_edges.len() + moved_points.len());
    boxes.extend(moved_edges.iter().map(edge_box));
    boxes.extend(moved_points.iter().map(|&i| point_box(i)));
    // Few moved items against few points and edges (most results of small inputs):
    // every box against every box, cheaper than building the grid.
    // (Points, and edges: a ring has as many as points; collapsed edges left out.)
    let queries = 2 * r.points.len();
    let one_by_one = match how {
        Search::Auto => queries * boxes.len() <= BRUTE_FORCE_TESTS,
        Search::OneByOne => true,
        Search::Grid | Search::Tree => false,
    };
    if one_by_one {
        near_pairs_one_by_one(r, &moved_points, &moved_edges, &boxes)
    } else {
        near_pairs_indexed(r, &moved_points, &moved_edges, &boxes, how)
    }
}

/// Boxes twice the sizes `passes` tests around point `i`, two gaps of its own
/// coordinates wider (more than the outward rounding of the box `meets` tests).
fn point_box(r: &RoundedRings, i: usize) -> Box2 {
    let (hx, hy) = reach_of(r, i);
    let c = r.points[i];
    Box2::around(c, c, (4.0 * hx + 2.0 * gap(c.x), 4.0 * hy + 2.0 * gap(c.y)))
}

/// [`near_pairs_by`] testing the boxes one by one; `boxes` are those of `moved_edges`,
/// then those of `moved_points`.
fn near_pairs_one_by_one(
    r: &RoundedRings,
    moved_points: &[usize],
    moved_edges: &[Edge],
    boxes: &[Box2],
) -> Scratch<Pair> {
    // (About as many pairs as moved items, mostly.)
    let mut pairs = scratch::with_capacity(boxes.len());
    let (edge_boxes, point_boxes) = boxes.split_at(moved_edges.len());
    let around_edges = edge_boxes.iter().copied().reduce(|a, b| a.union(&b));
    let (edge_strips, point_strips) = (Near::new(edge_boxes), Near::new(point_boxes));
    for x in 0..r.points.len() {
        let rough = rough_box(r.points[x]);
        if !around_edges.is_some_and(|a| a.overlaps(&rough)) {
            continue;
        }
        // (The precise box only where the cheap one, which holds it, meets an edge's:
        // most points are near no moved edge.)
        let mut precise = None;
        edge_strips.for_each_overlapping(&rough, |k| {
            let (e, eb) = (&moved_edges[k], &edge_boxes[k]);
            // (Its own edges first: a point next to a moved one meets them.)
            if !r.is_end(x, e) && eb.overlaps(precise.get_or_insert_with(|| point_box(r, x))) {
                pairs.push((x as u32, *e));
            }
        });
    }
    let around_points = point_boxes.iter().copied().reduce(|a, b| a.union(&b));
    r.for_each_unmoved_edge(|i, j| {
        let b = Box2::of(r.points[i], r.points[j]);
        if !around_points.is_some_and(|a| a.overlaps(&b)) {
            return;
        }
        let e = r.ring_edge(i, j);
        point_strips.for_each_overlapping(&b, |k| {
            if !r.is_end(moved_points[k], &e) {
                pairs.push((moved_points[k] as u32, e));
            }
        });
    });
    pairs
}

/// [`near_pairs_by`] on a grid of the moved items' boxes, or where the grid crowds (or
/// `how` asks for it) on a quadtree over the points ([`Index`]); other arguments as in
/// [`near_pairs_one_by_one`].
fn near_pairs_indexed(
    r: &RoundedRings,
    moved_points: &[usize],
    moved_edges: &[Edge],
    boxes: &[Box2],
    how: Search,
) -> Scratch<Pair> {
    // An edge's footprint: its segment widened as its box is, by four reaches (looked
    // at for long edges on the grid, for every edge on the quadtree). A point whose box
    // (four of its reaches and two gaps) misses it is more than four edge reaches and
    // four of its own from the segment; after nudges (the ends moved by up to a reach,
    // the point by up to its own) the rounded edge is still more than two reaches from
    // the point, and the exact edge is within half a reach of the first rounded one:
    // the point stays strictly on its exact side, so `passes` holds for the pair,
    // listed or not (as for the boxes, which `meets` may find touching after a nudge
    // where the side decides). The length of the edge plays no part.
    let line_of = |k: usize| {
        let e = &moved_edges[k];
        let (hx, hy) = edge_reach(r, e);
        Line {
            a: r.points[e.i],
            b: r.points[e.j],
            pad: (4.0 * hx, 4.0 * hy),
        }
    };
    match Index::new(r, boxes, moved_edges.len(), line_of, how) {
        Index::Grid(grid) => near_pairs_in(r, moved_points, moved_edges, boxes, &grid, line_of),
        Index::Tree(tree) => near_pairs_in(r, moved_points, moved_edges, boxes, &tree, line_of),
    }
}

/// [`near_pairs_indexed`] with the moved items looked up in `grid` (each search its
/// own copy: a choice per query cost the water map's search 2%); `line_of(k)` is moved
/// edge `k`'s footprint.
#[inline(always)]
fn near_pairs_in(
    r: &RoundedRings,
    moved_points: &[usize],
    moved_edges: &[Edge],
    boxes: &[Box2],
    grid: &impl ItemIndex,
    line_of: impl Fn(usize) -> Line,
) -> Scratch<Pair> {
    // A long edge is listed along its length (on the quadtree, every edge where it may
    // meet a leaf), and its box holds many points that are nowhere near it: those it is
    // tested against exactly before they make a pair (so is an unmoved edge looked up
    // along its length, against the moved points' boxes).
    // Each point against the moved edges near it, then each unmoved edge (query
    // `points + i` for the one from point i) against the moved points near it; `stamp` as in
    // [`Grid::visit`].
    // (The cells of the rough box, which holds the precise one; the precise box only
    // where an edge's box meets the rough one: most points on a large result have moved
    // edges in their cells, few near them.)
    let point_pairs = |x: usize, stamp: &mut [usize], pairs: &mut Vec<Pair>| {
        let rough = rough_box(r.points[x]);
        let mut precise = None;
        grid.visit(&rough, x, stamp, |item| {
            // (Not against its own edges, which every point next to a moved one meets:
            // looked at before the precise box is made.)
            if item < moved_edges.len()
                && boxes[item].overlaps(&rough)
                && !r.is_end(x, &moved_edges[item])
            {
                let b = precise.get_or_insert_with(|| point_box(r, x));
                if boxes[item].overlaps(b)
                    && (!grid.is_long(item) || {
                        let l = line_of(item);
                        !clearly_apart(l.a, l.b, l.pad, b)
                            && fat_segment_meets_box(l.a, l.b, l.pad, b)
                    })
                {
                    pairs.push((x as u32, moved_edges[item]));
                }
            }
        });
    };
    let points = r.points.len();
    // The unmoved ring edge from point i to j, whose box is `b` (query `points + i`).
    let edge_pairs = |i: usize, j: usize, b: &Box2, stamp: &mut [usize], pairs: &mut Vec<Pair>| {
        let e = r.ring_edge(i, j);
        let (pi, pj) = (r.points[i], r.points[j]);
        grid.visit_segment(pi, pj, b, points + i, stamp, |item, long| {
            if item >= moved_edges.len()
                && boxes[item].overlaps(b)
                && (!long
                    || !clearly_apart(pi, pj, (0.0, 0.0), &boxes[item])
                        && segment_meets_box(pi, pj, &boxes[item]))
            {
                let x = moved_points[item - moved_edges.len()];
                if !r.is_end(x, &e) {
                    pairs.push((x as u32, e));
                }
            }
        });
    };
    let mut stamp = scratch::filled(boxes.len(), usize::MAX);
    let mut pairs = scratch::with_capacity(boxes.len());
    // (Most points and edges of a large result are nowhere near a moved item: the
    // sieve passes over those in a few instructions.)
    let sieve = Sieve::new(boxes, points);
    for x in 0..points {
        if sieve.as_ref().map_or(true, |s| s.near_point(r.points[x])) {
            point_pairs(x, &mut stamp, &mut pairs);
        }
    }
    r.for_each_unmoved_edge(|i, j| {
        let b = Box2::of(r.points[i], r.points[j]);
        if sieve.as_ref().map_or(true, |s| s.near_box(&b)) {
            edge_pairs(i, j, &b, &mut stamp, &mut pairs);
        }
    });
    pairs
}

/// Where [`near_pairs_indexed`] looks the moved items up: the grid, or where the points
/// of its cells meet too many items there ([`CROWDED`]) or the items would be listed
/// in too many of its cells ([`FIRST_GRID_ENTRIES`]), a quadtree over the points (and
/// where that lists too many entries, a coarser grid).
enum Index {
    Grid(Grid),
    Tree(Tree),
}

/// Where the points of a result meet more than this many items per point and item on
/// average in their cells of the grid (looked at only where some cell holds more than
/// [`CROWDED_CELL`] items), the search takes a quadtree over the points instead: 10⁴
/// long strips across a triangle gathered about 600 long edges and as many points in
/// the cells along the triangle's sides (3.2 s for their symmetric difference), and a
/// result gathered in a corner of the extent of its moved items has most of them in a
/// cell or two.
const CROWDED: usize = 32;

/// The grid's points are counted against its items ([`CROWDED`]) only where some cell
/// lists more than this many items.
const CROWDED_CELL: usize = 64;

/// The first grid lists at most this many entries per item, and
/// [`FIRST_GRID_SLACK`] more (with two cells per item, that many cells per item on
/// average); past it the quadtree is tried before a coarser grid (each grid tried
/// costs up to its bound).
const FIRST_GRID_ENTRIES: usize = 16;
const FIRST_GRID_SLACK: usize = 1 << 16;

impl Index {
    fn new(
        r: &RoundedRings,
        boxes: &[Box2],
        segments: usize,
        line_of: impl Fn(usize) -> Line + Copy,
        how: Search,
    ) -> Index {
        let count = boxes.len();
        if how == Search::Auto {
            // The first grid, unless it crowds or lists too many entries (long edges
            // across many of its cells: where there are few, it is mostly kept).
            let most = FIRST_GRID_ENTRIES * count + FIRST_GRID_SLACK;
            if let Some(grid) = Grid::first_at_most(boxes, segments, line_of, most) {
                let crowded = grid.fullest_cell() > CROWDED_CELL
                    && grid.listed_at(&r.points) > CROWDED * (r.points.len() + count);
                if !crowded {
                    return Index::Grid(grid);
                }
            }
        }
        if how != Search::Grid {
            let most = grid::most_entries(count);
            if let Some(tree) = Tree::new(&r.points, boxes, segments, line_of, most) {
                return Index::Tree(tree);
            }
        }
        // (A grid made coarser until it lists few enough entries.)
        Index::Grid(Grid::new(boxes, segments, line_of))
    }
}

/// What the search for near pairs asks of where the moved items are listed ([`Grid`]
/// or [`Tree`]): every item whose footprint meets a query's is met, once per query.
trait ItemIndex {
    /// Whether item `k` is a segment the search tests exactly against a point's box.
    fn is_long(&self, k: usize) -> bool;
    /// Calls `f` once for each item whose footprint may meet box `b` ([`Grid::visit`]).
    fn visit(&self, b: &Box2, query: usize, stamp: &mut [usize], f: impl FnMut(usize));
    /// The same for segment `a b` with box `bx`; `f(item, long)`, with `long` where the
    /// search is to test the segment against the item's box exactly.
    fn visit_segment(
        &self,
        a: Point2,
        b: Point2,
        bx: &Box2,
        query: usize,
        stamp: &mut [usize],
        f: impl FnMut(usize, bool),
    );
}

/// Calls `f(k)` for each box `boxes[k]` that overlaps `b`, in order. The tests of 64
/// boxes at a time run without branches, into a mask (most fail, but which ones is a
/// coin toss for the branch predictor, and one by one they were most of the search).
#[inline(always)]
fn for_each_overlapping(boxes: &[Box2], b: &Box2, mut f: impl FnMut(usize)) {
    for (c, chunk) in boxes.chunks(64).enumerate() {
        let mut hits = 0u64;
        for (k, o) in chunk.iter().enumerate() {
            let hit = (o.x0 <= b.x1) & (b.x0 <= o.x1) & (o.y0 <= b.y1) & (b.y0 <= o.y1);
            hits |= u64::from(hit) << k;
        }
        while hits != 0 {
            f(64 * c + hits.trailing_zeros() as usize);
            hits &= hits - 1;
        }
    }
}

/// Boxes [`near_pairs`] tests one by one: all of them when they are few, else by
/// [`Strips`].
enum Near<'a> {
    Few(&'a [Box2]),
    Strips(Strips<'a>),
}

/// From this many boxes on, [`Near`] sorts them into strips (instructions for the JTS
/// pairs, strips from 8, 16, 32 and 64 boxes: xor 94.8 M, 94.8 M, 95.7 M, 96.0 M for
/// five calls; every box tested, 95.6 M).
const STRIPS_FROM: usize = 16;

impl<'a> Near<'a> {
    fn new(boxes: &'a [Box2]) -> Near<'a> {
        if boxes.len() < STRIPS_FROM {
            Near::Few(boxes)
        } else {
            Near::Strips(Strips::new(boxes))
        }
    }

    /// Calls `f(k)` for each box `k` that overlaps `b`, in increasing order.
    #[inline(always)]
    fn for_each_overlapping(&self, b: &Box2, f: impl FnMut(usize)) {
        match self {
            Near::Few(boxes) => for_each_overlapping(boxes, b, f),
            Near::Strips(strips) => strips.for_each_overlapping(b, f),
        }
    }
}

/// Up to this many box tests (points and edges times moved items) [`near_pairs`] looks
/// for pairs one by one, each point and edge against the moved items' boxes ([`Near`]:
/// all of them, or those in its strips), instead of building a grid (after one test
/// against the box around all moved edges, or all moved points, which most points and
/// edges fail). Instructions counted (callgrind) for the 52 JTS pairs: against a bound
/// of 512, intersection −3% and xor −2% at 16 384, with every box tested; with the
/// strips, against 16 384, intersection −0.5% and xor −1.3% at 262 144 (all of those
/// results one by one). The GEOS-837 dissolve (2 378 queries, 219 moved items) stays on
/// the grid: one by one it counted 0.8% more.
const BRUTE_FORCE_TESTS: usize = 262_144;

/// The relative and absolute terms of [`rough_box`]'s half sizes: 2⁻⁴⁸ and 2⁻¹⁰⁶⁸.
const REL_ROUGH: (f64, f64) = (
    1.0 / (1u64 << 48) as f64,
    f64::MIN_POSITIVE / (1u64 << 46) as f64,
);

/// A box around `c` holding its `point_box` in `near_pairs` (half sizes 4·reach + 2
/// gaps, reach at most a gap, rounded outward by a float: at most 7 gaps per axis,
/// and a gap is at most 2⁻⁵² |v|, or 2⁻¹⁰⁷⁴ below the normal range), from a few float
/// operations: half sizes 2⁻⁴⁸ |v| + 2⁻¹⁰⁶⁸, whose own rounding is far below the
/// margin.
fn rough_box(c: Point2) -> Box2 {
    let (rel, abs) = REL_ROUGH;
    let (hx, hy) = (c.x.abs() * rel + abs, c.y.abs() * rel + abs);
    Box2 {
        x0: c.x - hx,
        x1: c.x + hx,
        y0: c.y - hy,
        y1: c.y + hy,
    }
}

fn reach_of(r: &RoundedRings, i: usize) -> (f64, f64) {
    reach(r.points[i], r.moved(i))
}

fn edge_reach(r: &RoundedRings, e: &Edge) -> (f64, f64) {
    let ((ax, ay), (bx, by)) = (reach_of(r, e.i), reach_of(r, e.j));
    (ax.max(bx), ay.max(by))
}

/// Whether point x and edge e (a [`Pair`]) pass, with the rings' current points: x is an
/// end of e (the same arrangement vertex: rings touching at a point share it; for a
/// point that stands for a collapsed edge, either of its two vertices), or they stay
/// apart, or x is strictly on its exact side of e, or x is exactly on e's line and
/// only one of the three points moved (then they never touch, below). A collapsed edge
/// has no side: anything near it fails.
fn passes(
    r: &RoundedRings,
    pairs: &[Pair],
    k: usize,
    sides: &mut ExactSides<impl Fn(u32, u32, u32) -> Orientation>,
) -> bool {
    let (x, e) = pairs[k];
    let x = x as usize;
    let PointIds { enter, leave, .. } = r.ids[x];
    if r.is_end(x, &e) {
        return true;
    }
    if apart_along_an_axis(r, x, &e) {
        return true;
    }
    let (ex, ey) = edge_reach(r, &e);
    let (px, py) = reach_of(r, x);
    let (a, b, c) = (r.points[e.i], r.points[e.j], r.points[x]);
    if !meets(a, b, c, (ex + px, ey + py)) {
        return true;
    }
    let rounded = orient2d(a, b, c);
    if rounded == Orientation::Collinear {
        return false;
    }
    let mut exact = |which: usize, v: u32| {
        *sides.known[k][which].get_or_insert_with(|| (sides.side)(e.a, e.b, v))
    };
    let on_line = exact(0, enter);
    if on_line != Orientation::Collinear {
        return on_line == rounded && (leave == enter || exact(1, leave) == rounded);
    }
    // Exactly on the edge's line (outside the edge: the exact result is valid), and
    // only one of the three points moved, standing for one vertex: a moving x leaves
    // the line at once, off the edge; a moving end c of a → c sweeps the triangle
    // (a, c exact, c rounded), which the line meets only in its side on the line (the
    // rounded x is off the line, so the triangle is not flat). They never touch.
    let alone = |i: usize| r.ids[i].enter == r.ids[i].leave;
    let points = [x, e.i, e.j];
    e.i != e.j
        && points.iter().all(|&i| alone(i))
        && points.iter().filter(|&&i| r.moved(i)).count() == 1
}

/// Whether point x is strictly beyond both ends of edge e in x, or in y, on the same
/// side, both where rounding to nearest put them and where they are now (after
/// [`nudge`]), with every point rounded to nearest ([`RoundedRings::at_nearest`]).
///
/// Then they never touch as the vertices move from their exact points: rounding to
/// nearest (correctly, ties to even: the arrangement's rounded points are bit for bit
/// [`crate::kernel::ExactPoint`]'s nearest ones, which `ExactVertices::push` checks in
/// debug builds, up to the sign of zero, and the noding's tests check) is monotone, so
/// from `r(x) > r(end)` follows `x > end` for the exact
/// coordinates (equal ones round alike). Along the straight moves, the difference of
/// two vertices' coordinates is linear in time, positive at both ends, so positive
/// throughout: x stays strictly beyond the edge's shadow on that axis. (For a point
/// standing for two vertices, each of them; for a collapsed edge, both its vertices.)
/// This decides most pairs of crossings along one input edge, which are exactly
/// collinear and often turned over by rounding, without an exact test.
fn apart_along_an_axis(r: &RoundedRings, x: usize, e: &Edge) -> bool {
    if !r.at_nearest {
        return false;
    }
    let beyond = |points: &[Point2], axis: fn(Point2) -> f64| {
        let (v, s, t) = (axis(points[x]), axis(points[e.i]), axis(points[e.j]));
        if v > s.max(t) {
            Ordering::Greater
        } else if v < s.min(t) {
            Ordering::Less
        } else {
            Ordering::Equal
        }
    };
    let start = if r.nearest.is_empty() {
        &r.points
    } else {
        &r.nearest
    };
    [|p: Point2| p.x, |p: Point2| p.y].into_iter().any(|axis| {
        let side = beyond(start, axis);
        side.is_ne() && beyond(&r.points, axis) == side
    })
}

/// `exact_side` of the pairs' edges and points' vertices (enter, leave), each computed
/// once: [`nudge`] decides pairs again.
struct ExactSides<F> {
    side: F,
    known: Scratch<[Option<Orientation>; 2]>,
}

#[cfg(test)]
mod tests {
    use super::{
        apart_along_an_axis, clearly_apart, edge_reach, failing_rings, fat_segment_meets_box, gap,
        meets, near_pairs_by, point_box, reach_of, segment_meets_box, Box2, Edge, ExactPoints,
        Grid, Index, Line, Pair, PointIds, RoundedRings, Search, Toward, FIRST_GRID_ENTRIES,
        FIRST_GRID_SLACK,
    };
    use crate::kernel::{orient2d, Orientation, Point2};
    use std::cmp::Ordering;

    fn p(x: f64, y: f64) -> Point2 {
        Point2::new(x, y)
    }

    /// Rings from (point, vertex id, moved) lists.
    fn rings(list: &[&[(Point2, u32, bool)]]) -> RoundedRings {
        let mut r = RoundedRings {
            starts: vec![0].into(),
            ..RoundedRings::default()
        };
        for ring in list {
            for &(q, id, moved) in *ring {
                r.points.push(q);
                r.ids.push(PointIds::of(id, moved));
            }
            r.starts.push(r.points.len());
        }
        r
    }

    fn next(v: f64) -> f64 {
        f64::from_bits(v.to_bits() + 1)
    }

    /// Every pair the rounding check must decide, by definition: each point against
    /// each edge (ring edges and collapsed ones) that it is not an end of, one of them
    /// moved, whose boxes (as `passes` needs them) overlap; with `exactly`, only those
    /// where the edge itself, widened as its box is, meets the point's box.
    fn every_near_pair(r: &RoundedRings, exactly: bool) -> Vec<(u32, usize, usize, u32, u32)> {
        let point_box = |i: usize| {
            let (hx, hy) = reach_of(r, i);
            let c = r.points[i];
            Box2::around(c, c, (4.0 * hx + 2.0 * gap(c.x), 4.0 * hy + 2.0 * gap(c.y)))
        };
        let edge_box = |e: &Edge| {
            let (hx, hy) = edge_reach(r, e);
            Box2::around(r.points[e.i], r.points[e.j], (4.0 * hx, 4.0 * hy))
        };
        // (Listed here, not by `for_each_edge`: that is under test too.)
        let mut edges = Vec::new();
        for ring in r.starts.windows(2) {
            for i in ring[0]..ring[1] {
                let j = if i + 1 == ring[1] { ring[0] } else { i + 1 };
                let (a, b) = (r.ids[i].leave, r.ids[j].enter);
                edges.push(Edge { i, j, a, b });
            }
        }
        for (i, id) in r.ids.iter().enumerate() {
            if id.enter != id.leave {
                let (a, b) = (id.enter, id.leave);
                edges.push(Edge { i, j: i, a, b });
            }
        }
        let mut pairs = Vec::new();
        for x in 0..r.points.len() {
            for e in &edges {
                let moved = r.moved(x) || r.moved(e.i) || r.moved(e.j);
                let id = r.ids[x];
                let own = [id.enter, id.leave].iter().any(|&v| v == e.a || v == e.b);
                let (hx, hy) = edge_reach(r, e);
                let (a, b) = (r.points[e.i], r.points[e.j]);
                let fat = |bx: &Box2| fat_segment_meets_box(a, b, (4.0 * hx, 4.0 * hy), bx);
                let near = point_box(x).overlaps(&edge_box(e)) && (!exactly || fat(&point_box(x)));
                if moved && !own && near {
                    pairs.push((x as u32, e.i, e.j, e.a, e.b));
                }
            }
        }
        pairs.sort_unstable();
        pairs
    }

    /// The near pairs, found one by one, on the grid or on the quadtree, are pairs whose
    /// boxes overlap, once, and among them every pair whose edge (widened) meets the
    /// point's box (on the grid, long edges are listed along their length, and on the
    /// tree all edges: pairs in their boxes but far from them are not found there):
    /// random rings on a small integer grid (shared points, collinear runs), around one
    /// point with coordinates a few floats apart, at ±1e300, among subnormals, near
    /// ±`f64::MAX`, and with x and y at scales from 1e-300 to 1e300 in one ring (grids of one cell, of a subnormal cell size, cells numbered past 2³²),
    /// sometimes with only one or two points moved, the collapsed edges included, and
    /// rings touching at shared vertices.
    #[test]
    fn near_pairs_are_every_pair_whose_boxes_overlap() {
        let mut int = crate::testing::below(0x0dd_ba11_u64);
        let key = |(x, e): Pair| (x, e.i, e.j, e.a, e.b);
        let below_max = |k: u64| f64::from_bits(f64::MAX.to_bits() - k);
        let (mut found, mut left_out) = (0, 0);
        for round in 0..1600 {
            let kind = round % 7;
            let moved_one_in = [2, 3, 10, 40][int(4) as usize];
            let mut r = RoundedRings {
                starts: vec![0].into(),
                ..RoundedRings::default()
            };
            let mut id = 0;
            for _ in 0..1 + int(4) {
                for _ in 0..3 + int(if round % 5 == 0 { 40 } else { 12 }) {
                    let (kx, ky) = if kind == 6 {
                        (int(6), int(6))
                    } else {
                        (kind, kind)
                    };
                    let mut coord = |kind: u64| match kind {
                        0 => int(8) as f64,
                        1 => f64::from_bits(1.0f64.to_bits() + int(6)),
                        2 => (int(7) as f64 - 3.0) * 1e300,
                        3 => f64::from_bits(int(8)) * if int(2) == 0 { -1.0 } else { 1.0 },
                        4 => {
                            [f64::MAX, -below_max(2), below_max(1), 0.0, -0.0, 1.0][int(6) as usize]
                        }
                        _ => {
                            (int(9) as f64 - 4.0)
                                * [1e-300, 1.0, 1e10, 1e300, 5e-324][int(5) as usize]
                        }
                    };
                    let q = p(coord(kx), coord(ky));
                    let mut ids = PointIds::of(id, int(moved_one_in) == 0);
                    if int(10) == 0 {
                        ids.merge(PointIds::of(id + 1, true));
                        id += 1;
                    }
                    // Now and then a point of an earlier ring again: rings touching there
                    // share its vertex, and pairs of that vertex and its edges are none.
                    let ring_start = *r.starts.last().expect("starts at 0");
                    if ring_start > 0 && int(6) == 0 {
                        let k = int(ring_start as u64) as usize;
                        let (q, id) = (r.points[k], r.ids[k]);
                        r.points.push(q);
                        r.ids.push(id);
                    } else {
                        r.points.push(q);
                        r.ids.push(ids);
                    }
                    id += 1;
                }
                r.starts.push(r.points.len());
            }
            let (want, must) = (every_near_pair(&r, false), every_near_pair(&r, true));
            for how in [Search::OneByOne, Search::Grid, Search::Tree] {
                let mut got: Vec<_> = near_pairs_by(&r, how).iter().copied().map(key).collect();
                got.sort_unstable();
                let once = got.windows(2).all(|w| w[0] != w[1]);
                let within = got.iter().all(|p| want.binary_search(p).is_ok());
                let all = must.iter().all(|p| got.binary_search(p).is_ok());
                assert!(once && within && all, "round {round}, {how:?}");
                if how == Search::OneByOne {
                    assert_eq!(got, want, "round {round}");
                }
                if how == Search::Grid {
                    left_out += want.len() - got.len();
                }
            }
            found += must.len();
        }
        assert!(found > 20_000, "only {found} pairs");
        // (Some pairs of long edges were passed over on the grid.)
        assert!(left_out > 0);
    }

    /// A comb of `teeth` thin teeth `spacing` apart and `height` high whose feet moved
    /// (crossings), each seventh tooth with a point of another ring within a float or so
    /// of its first side (its middle, computed in floats: pairs the search must find),
    /// and with `far` a moved point far from the comb (which then lies in a corner of
    /// the moved items' extent).
    fn comb(teeth: u32, spacing: f64, height: f64, far: bool) -> RoundedRings {
        let mut r = RoundedRings {
            starts: vec![0].into(),
            ..RoundedRings::default()
        };
        for i in 0..teeth {
            let x = spacing * i as f64;
            r.points.push(p(x, 0.0));
            r.ids.push(PointIds::of(2 * i, true));
            r.points.push(p(x + 0.5 * spacing, height + (i % 3) as f64));
            r.ids.push(PointIds::of(2 * i + 1, false));
        }
        r.starts.push(r.points.len());
        for i in (0..teeth as usize).step_by(7) {
            let (a, b) = (r.points[2 * i], r.points[2 * i + 1]);
            r.points.push(p(0.5 * (a.x + b.x), 0.5 * (a.y + b.y)));
            r.ids.push(PointIds::of(2 * teeth + i as u32, false));
        }
        r.starts.push(r.points.len());
        if far {
            for (k, q) in [p(1e6, 1e6), p(1e6 + 1.0, 1e6), p(1e6, 1e6 + 1.0)]
                .into_iter()
                .enumerate()
            {
                r.points.push(q);
                r.ids.push(PointIds::of(3 * teeth + k as u32, k == 0));
            }
            r.starts.push(r.points.len());
        }
        r
    }

    /// Where the points and the moved edges of a result gather in a few of the grid's
    /// cells, the search takes the quadtree: long teeth close together (the first grid
    /// would list each tooth in hundreds of cells), or short ones in a corner of the
    /// extent (the first grid lists each in a cell or two, most of them in one); spread
    /// out, it keeps the grid. Each way it finds pairs whose boxes overlap, once, among
    /// them every pair whose edge (widened) meets the point's box, the points on the
    /// teeth's sides among them.
    #[test]
    fn crowded_results_are_searched_on_the_tree() {
        let teeth: u32 = 2_000;
        let cases = [
            (comb(teeth, 0.05, 1_000.0, false), false, true),
            (comb(teeth, 0.05, 10.0, true), true, true),
            (comb(teeth, 5.0, 10.0, false), true, false),
        ];
        for (case, (r, first_fits, tree)) in cases.iter().enumerate() {
            let moved: Vec<usize> = (0..r.points.len()).filter(|&i| r.moved(i)).collect();
            let mut edges = Vec::new();
            r.for_each_moved_edge(&moved, |e| edges.push(e));
            let boxes: Vec<Box2> = edges
                .iter()
                .map(|e| {
                    let (hx, hy) = edge_reach(r, e);
                    Box2::around(r.points[e.i], r.points[e.j], (4.0 * hx, 4.0 * hy))
                })
                .chain(moved.iter().map(|&i| point_box(r, i)))
                .collect();
            let line_of = |k: usize| {
                let e = &edges[k];
                let (hx, hy) = edge_reach(r, e);
                Line {
                    a: r.points[e.i],
                    b: r.points[e.j],
                    pad: (4.0 * hx, 4.0 * hy),
                }
            };
            let most = FIRST_GRID_ENTRIES * boxes.len() + FIRST_GRID_SLACK;
            let first = Grid::first_at_most(&boxes, edges.len(), line_of, most);
            assert_eq!(first.is_some(), *first_fits, "case {case}");
            let index = Index::new(r, &boxes, edges.len(), line_of, Search::Auto);
            assert_eq!(matches!(index, Index::Tree(_)), *tree, "case {case}");
            let key = |(x, e): Pair| (x, e.i, e.j, e.a, e.b);
            let sorted = |how: Search| {
                let mut got: Vec<_> = near_pairs_by(r, how).iter().copied().map(key).collect();
                got.sort_unstable();
                got
            };
            let (want, got) = (sorted(Search::OneByOne), sorted(Search::Auto));
            let must: Vec<_> = want
                .iter()
                .copied()
                .filter(|&(x, i, j, _, _)| {
                    let e = Edge { i, j, a: 0, b: 0 };
                    let (hx, hy) = edge_reach(r, &e);
                    let (a, b) = (r.points[i], r.points[j]);
                    fat_segment_meets_box(a, b, (4.0 * hx, 4.0 * hy), &point_box(r, x as usize))
                })
                .collect();
            assert!(got.windows(2).all(|w| w[0] != w[1]), "case {case}");
            assert!(
                got.iter().all(|q| want.binary_search(q).is_ok()),
                "case {case}"
            );
            assert!(
                must.iter().all(|q| got.binary_search(q).is_ok()),
                "case {case}"
            );
            assert!(
                must.len() >= (teeth / 7) as usize,
                "case {case}: {}",
                must.len()
            );
        }
    }

    /// The float first test never calls apart a widened segment and box that meet
    /// (exactly), at every scale and offset (coordinates near 1e6, 1e15, 1e300 and
    /// subnormal ones, boxes a few floats across, segments through, beside and far from
    /// them), and does call apart most of those far from each other where the
    /// coordinates are units apart.
    #[test]
    fn clearly_apart_is_never_wrong() {
        let mut int = crate::testing::below(0x00c1_ea71);
        let (mut far, mut told) = (0, 0);
        for round in 0..200_000 {
            let scale: f64 = [1.0, 1e-3, 1e6, 1e15, 1e300, 1e-310][round % 6];
            let offset = [0.0, 1.0, 1e6, -3e15][(round / 6) % 4] * scale.min(1e280);
            // (A few units, or a few floats, apart.)
            let spread = if int(3) == 0 { 4.0 * f64::EPSILON } else { 1.0 };
            let mut v = || offset + (int(2001) as f64 - 1000.0) * scale * spread;
            let (a, b) = (p(v(), v()), p(v(), v()));
            let c = p(v(), v());
            let w = (int(4) as f64) * scale * spread;
            let bx = Box2::around(c, c, (w, w * 0.5));
            let pad = [(0.0, 0.0), (w, w), (scale * spread, 0.0)][int(3) as usize];
            let meets = fat_segment_meets_box(a, b, pad, &bx);
            let apart = clearly_apart(a, b, pad, &bx);
            assert!(
                !(meets && apart),
                "round {round}: {a:?} {b:?} {pad:?} {c:?} {w}"
            );
            // (Far: the line misses the box by more than a tenth of the segment.)
            let line_meets = {
                let (dx, dy) = (b.x - a.x, b.y - a.y);
                let len = dx.abs() + dy.abs();
                let far_out =
                    Box2::around(c, c, (w + pad.0 + 0.1 * len, 0.5 * w + pad.1 + 0.1 * len));
                len == 0.0
                    || segment_meets_box(
                        p(a.x - 10.0 * dx, a.y - 10.0 * dy),
                        p(b.x + 10.0 * dx, b.y + 10.0 * dy),
                        &far_out,
                    )
            };
            // (Counted where the coordinates are units apart: at a few floats apart
            // far from the origin, the margin is larger than the distances.)
            if !line_meets && spread == 1.0 && scale < 1e300 && scale > 1e-300 {
                far += 1;
                told += usize::from(apart);
            }
        }
        assert!(
            far > 10_000 && told * 10 > far * 9,
            "{told} of {far} told apart"
        );
    }

    #[test]
    fn a_segment_meets_a_box_exactly() {
        // Box of half sizes 0.5 around (1, 1), enlarged to [0, 2]²: a segment through its
        // corner meets it.
        let c = p(1.0, 1.0);
        assert!(!meets(p(2.0, 4.0), p(4.0, 2.0), c, (0.5, 0.5)));
        assert!(meets(p(1.0, 3.0), p(3.0, 1.0), c, (0.5, 0.5)));
        assert!(!meets(p(2.0, 3.0), p(3.0, 2.0), c, (0.5, 0.5)));
        assert!(meets(p(-1.0, 3.0), p(3.0, -1.0), c, (0.5, 0.5)));
        assert!(meets(p(0.0, 4.0), p(4.0, 0.0), c, (0.5, 0.5)));
        // The box's ends are rounded outward by one float: x + y = 4 + ulp(4) touches
        // its corner (2 + ulp(2), 2 + ulp(2)); a line an ulp further does not.
        assert!(meets(p(0.0, next(4.0)), p(next(4.0), 0.0), c, (0.5, 0.5)));
        let beyond = next(next(4.0));
        assert!(!meets(p(0.0, beyond), p(beyond, 0.0), c, (0.5, 0.5)));
        // A point box (nothing moved): only an exact hit.
        assert!(meets(p(0.0, 0.0), p(2.0, 2.0), c, (0.0, 0.0)));
        assert!(!meets(p(0.0, 0.0), p(2.0, next(2.0)), c, (0.0, 0.0)));
    }

    /// [`meets`] by its two extreme corners agrees with testing all four corners, on
    /// segments and boxes of a small grid (every slope sign, axis-parallel and
    /// point-like boxes, corners on the line).
    #[test]
    fn two_corners_decide_as_four() {
        let mut below = crate::testing::below(7);
        let mut met = [0usize; 2];
        for _ in 0..20_000 {
            let mut q = || below(9) as f64 - 4.0;
            let (a, b, c) = (p(q(), q()), p(q(), q()), p(q(), q()));
            let h = (below(3) as f64 * 0.5, below(2) as f64 * 0.5);
            let bx = Box2::around(c, c, (2.0 * h.0, 2.0 * h.1));
            let four = Box2::around(a, b, (0.0, 0.0)).overlaps(&bx)
                && (a == b || {
                    let sides: Vec<Orientation> = [
                        p(bx.x0, bx.y0),
                        p(bx.x1, bx.y0),
                        p(bx.x1, bx.y1),
                        p(bx.x0, bx.y1),
                    ]
                    .iter()
                    .map(|&k| orient2d(a, b, k))
                    .collect();
                    sides[0] == Orientation::Collinear || sides.iter().any(|&o| o != sides[0])
                });
            assert_eq!(meets(a, b, c, h), four, "{a:?} {b:?} {c:?} {h:?}");
            met[usize::from(four)] += 1;
        }
        assert!(met[0] > 2000 && met[1] > 2000, "{met:?}");
    }

    /// The rings after [`failing_rings`], and whether no ring fails, with the exact points
    /// given per id (f64 points stand for exact ones here).
    fn checked(list: &[&[(Point2, u32, bool)]], exact: &[(u32, Point2)]) -> (RoundedRings, bool) {
        checked_with(list, exact, false)
    }

    /// [`checked`], the points taken as rounded to nearest (`at_nearest`) or not.
    fn checked_with(
        list: &[&[(Point2, u32, bool)]],
        exact: &[(u32, Point2)],
        at_nearest: bool,
    ) -> (RoundedRings, bool) {
        let at = |id: u32| exact.iter().find(|e| e.0 == id).expect("exact point").1;
        // (The tests' points have no -0; the real closures compare exactly, -0 as 0.)
        let exact = ExactPoints {
            toward: |id: u32, q: Point2| (at(id).x.total_cmp(&q.x), at(id).y.total_cmp(&q.y)),
            order: |u: u32, v: u32| {
                let (p, q) = (at(u), at(v));
                p.x.total_cmp(&q.x).then(p.y.total_cmp(&q.y))
            },
        };
        let mut r = rings(list);
        r.at_nearest = at_nearest;
        let side = |a, b, c| orient2d(at(a), at(b), at(c));
        let kept = failing_rings(&mut r, side, Some(exact)).is_empty();
        (r, kept)
    }

    /// No ring fails [`failing_rings`] and no point was moved.
    fn kept(list: &[&[(Point2, u32, bool)]], exact: &[(u32, Point2)]) -> bool {
        let (r, kept) = checked(list, exact);
        let unmoved = list
            .iter()
            .flat_map(|ring| ring.iter())
            .map(|q| q.0)
            .eq(r.points.iter().copied());
        kept && unmoved
    }

    #[test]
    fn a_vertex_on_an_edges_line_passes_when_only_one_point_moved() {
        let e = f64::EPSILON;
        // Edge a → c of a triangle, c exactly (1, 1) rounded (as if) to (1 − ε/2, 1 + ε),
        // one float off per axis; x = (1 + ε, 1), a vertex of a steep triangle, exactly on
        // the line a → c, beyond c and near it: its side of the rounded edge turns from
        // collinear to clockwise, but c's move sweeps a triangle the line meets only in
        // a → c.
        let triangle = |a_moved: bool| {
            vec![
                (p(0.0, 1.0), 40, a_moved),
                (p(1.0 - e / 2.0, 1.0 + e), 41, true),
                (p(0.5, 2.0), 42, false),
            ]
        };
        let steep = vec![
            (p(1.0 + e, 1.0), 50, false),
            (p(1.5, -9.0), 51, false),
            (p(1.5, 11.0), 52, false),
        ];
        let exact = [
            (40, p(0.0, 1.0)),
            (41, p(1.0, 1.0)),
            (42, p(0.5, 2.0)),
            (50, p(1.0 + e, 1.0)),
            (51, p(1.5, -9.0)),
            (52, p(1.5, 11.0)),
        ];
        assert!(kept(&[&triangle(false), &steep], &exact));
        // With a moving too, the edge's sweep is not that triangle: not decided so (and
        // no float around c puts x back on the line but c's exact point, on it too).
        assert!(!checked(&[&triangle(true), &steep], &exact).1);
    }

    /// Crossings along one input edge: x exactly on the line of the edge a → c, beyond c
    /// and an ulp from it, c and x both moved (each flagged so here; their points are
    /// their exact ones, so that they are their nearest floats too). The sides cannot
    /// decide the pair (collinear, two points moved) and no nudge helps (the exact
    /// points are floats); x being beyond the edge in x (and in y), before and after
    /// rounding, does, but only for points rounded to nearest.
    #[test]
    fn a_point_beyond_an_edge_along_an_axis_passes_when_rounded_to_nearest() {
        let e = f64::EPSILON;
        let (a, c, x) = (p(0.0, 0.0), p(1.0, 1.0), p(1.0 + e, 1.0 + e));
        let triangle = [(a, 0, false), (c, 1, true), (p(0.0, 1.0), 2, false)];
        let steep = [
            (x, 10, true),
            (p(3.0, 0.0), 11, false),
            (p(3.0, 5.0), 12, false),
        ];
        let exact = [
            (0, a),
            (1, c),
            (2, p(0.0, 1.0)),
            (10, x),
            (11, p(3.0, 0.0)),
            (12, p(3.0, 5.0)),
        ];
        let list: [&[(Point2, u32, bool)]; 2] = [&triangle, &steep];
        assert!(checked_with(&list, &exact, true).1);
        assert!(!checked_with(&list, &exact, false).1);
    }

    /// [`apart_along_an_axis`] itself: strictly beyond, on one axis and one side, both
    /// where rounding to nearest put the points and where they are now, and only for
    /// points rounded to nearest.
    #[test]
    fn apart_along_an_axis_needs_strict_separation_before_and_after() {
        let e = f64::EPSILON;
        // Edge 0 → 1 from (0, 0) to (1, 1), point 2 somewhere (each a ring of its own
        // here: only the points and the edge matter).
        let case = |x: Point2, nearest_x: Option<Point2>, at_nearest: bool| {
            let mut r = rings(&[
                &[(p(0.0, 0.0), 0, false), (p(1.0, 1.0), 1, true)],
                &[(x, 2, true)],
            ]);
            r.at_nearest = at_nearest;
            if let Some(n) = nearest_x {
                r.nearest = r.points.clone();
                r.nearest[2] = n;
            }
            let edge = Edge {
                i: 0,
                j: 1,
                a: 0,
                b: 1,
            };
            apart_along_an_axis(&r, 2, &edge)
        };
        // Beyond in x (and y), or in x only, or in y only: apart.
        assert!(case(p(1.0 + e, 1.0 + e), None, true));
        assert!(case(p(1.0 + e, 0.5), None, true));
        assert!(case(p(0.5, -e), None, true));
        // Not for points that may not be at their nearest floats.
        assert!(!case(p(1.0 + e, 1.0 + e), None, false));
        // Level with an end on each axis it is beyond on neither: not apart.
        assert!(!case(p(1.0, 0.5), None, true));
        assert!(!case(p(0.5, 1.0), None, true));
        // Beyond now but not where rounding to nearest put it (before a nudge), or the
        // other way round: not apart (either end of the move may be level).
        assert!(!case(p(1.0 + e, 1.0 + e), Some(p(1.0, 1.0)), true));
        assert!(!case(p(1.0, 1.0), Some(p(1.0 + e, 1.0 + e)), true));
        // Beyond on x at both ends: apart, even where the move changed y.
        assert!(case(p(1.0 + e, 0.5), Some(p(1.0 + e, 0.25)), true));
        // Beyond on opposite sides before and after: not apart.
        assert!(!case(p(-e, 0.5), Some(p(1.0 + e, 0.5)), true));
    }

    /// A nudge is judged by where rounding to nearest put the points too: a point
    /// rounded onto another vertex's point c, at the end of an edge a → c, and moved one
    /// float on (to its exact point, beyond c on the edge's line) to mend its pairs with
    /// c, is level with c where it was rounded to: the axis rule does not decide its
    /// pair with a → c, and, collinear there, the pair fails.
    #[test]
    fn a_nudged_point_is_not_apart_where_it_was_level_before() {
        let e = f64::EPSILON;
        let (a, c, x) = (p(0.0, 0.0), p(1.0, 0.0), p(1.0 + e, 0.0));
        let triangle = [(a, 0, false), (c, 1, false), (p(0.5, -1.0), 2, false)];
        // x rounded (as if) onto c.
        let wedge = [
            (c, 10, true),
            (p(3.0, 1.0), 11, false),
            (p(3.0, -1.0), 12, false),
        ];
        let exact = [
            (0, a),
            (1, c),
            (2, p(0.5, -1.0)),
            (10, x),
            (11, p(3.0, 1.0)),
            (12, p(3.0, -1.0)),
        ];
        let list: [&[(Point2, u32, bool)]; 2] = [&triangle, &wedge];
        let (r, ok) = checked_with(&list, &exact, true);
        assert!(!ok);
        // (The nudge was taken: it mends c's pairs with x's edges.)
        assert!(r.points.contains(&x));
        assert_eq!(r.nearest[3], c);
    }

    /// A nudge that would put a point onto its ring's neighbour (collapsing the edge
    /// between them) is not taken, even where it would mend the pair.
    #[test]
    fn a_nudge_onto_a_ring_neighbour_is_not_taken() {
        let e = f64::EPSILON;
        // The square's side x = 2; a spike whose tip, exactly two floats left of it, was
        // rounded (as if) onto it, and whose next point is one float left of it: the
        // float towards the tip's exact point.
        let square = [
            (p(2.0, 0.0), 0, false),
            (p(3.0, 0.0), 1, false),
            (p(3.0, 1.0), 2, false),
            (p(2.0, 1.0), 3, false),
        ];
        let spike = [
            (p(0.0, 2.0), 20, false),
            (p(2.0, 0.5), 21, true),
            (p(2.0 - e, 0.5), 23, false),
            (p(0.0, -1.0), 22, false),
        ];
        let exact = [
            (0, p(2.0, 0.0)),
            (1, p(3.0, 0.0)),
            (2, p(3.0, 1.0)),
            (3, p(2.0, 1.0)),
            (20, p(0.0, 2.0)),
            (21, p(2.0 - 2.0 * e, 0.5)),
            (23, p(2.0 - e, 0.5)),
            (22, p(0.0, -1.0)),
        ];
        let (r, ok) = checked(&[&square, &spike], &exact);
        assert!(!ok);
        assert_eq!(r.nudged, 0);
        assert!(r.points.contains(&p(2.0, 0.5)));
    }

    #[test]
    fn a_vertex_rounded_across_another_rings_edge_is_flagged() {
        let square = |x: f64, id: u32| {
            vec![
                (p(x, 0.0), id, false),
                (p(x + 1.0, 0.0), id + 1, false),
                (p(x + 1.0, 1.0), id + 2, false),
                (p(x, 1.0), id + 3, false),
            ]
        };
        let square_exact = |x: f64, id: u32| {
            vec![
                (id, p(x, 0.0)),
                (id + 1, p(x + 1.0, 0.0)),
                (id + 2, p(x + 1.0, 1.0)),
                (id + 3, p(x, 1.0)),
            ]
        };
        // Nothing moved: kept, however close the rings are.
        let (s, t) = (square(0.0, 0), square(next(1.0), 10));
        assert!(kept(&[&s, &t], &[]));
        // A triangle whose tip was exactly two ulps left of the square's side x = 2 and
        // was rounded to `x` (moved).
        let tip = |x: f64, moved: bool| {
            vec![
                (p(0.0, 2.0), 20, false),
                (p(x, 0.5), 21, moved),
                (p(0.0, -1.0), 22, false),
            ]
        };
        let mut exact = square_exact(2.0, 0);
        let two_left = 2.0 - 2.0 * f64::EPSILON;
        exact.extend([
            (20, p(0.0, 2.0)),
            (21, p(two_left, 0.5)),
            (22, p(0.0, -1.0)),
        ]);
        let sq = square(2.0, 0);
        // Rounded an ulp towards the side: near it, but on the same side (kept); onto it
        // or across it: not kept.
        assert!(kept(&[&sq, &tip(2.0 - f64::EPSILON, true)], &exact));
        // Onto it: the tip is moved one float towards its exact point, back on its side.
        let (r, ok) = checked(&[&sq, &tip(2.0, true)], &exact);
        assert!(ok);
        assert!(r.points.contains(&p(2.0 - f64::EPSILON, 0.5)));
        assert!(!kept(&[&sq, &tip(2.0, true)], &exact));
        // Two floats across: one float back is still on the side, not kept.
        let (r, ok) = checked(&[&sq, &tip(next(2.0), true)], &exact);
        assert!(!ok);
        assert!(r.points.contains(&p(next(2.0), 0.5)));
        // Far from the square: kept without a look at the sides.
        let far =
            |a: u32, b: u32, c: u32| -> Orientation { panic!("no pair is near: {a} {b} {c}") };
        let tip_far = tip(1.0, true);
        let no_move = ExactPoints {
            toward: |_: u32, _: Point2| -> Toward { panic!("nothing fails") },
            order: |_: u32, _: u32| -> Ordering { panic!("nothing fails") },
        };
        assert!(failing_rings(&mut rings(&[&sq, &tip_far]), far, Some(no_move)).is_empty());
        // The square's corner moved (exactly a little right of x = 2): its side, rounded
        // to x = 2, passes the unmoved tip an ulp away on the same side (kept), or its
        // rounded side crosses the tip (not kept).
        let tip_exact = tip(2.0 - f64::EPSILON, false);
        let mut exact = square_exact(2.0, 0);
        exact[3].1 = p(2.0 + 4.0 * f64::EPSILON, 1.0);
        exact.extend([
            (20, p(0.0, 2.0)),
            (21, p(2.0 - f64::EPSILON, 0.5)),
            (22, p(0.0, -1.0)),
        ]);
        let mut moved_corner = square(2.0, 0);
        moved_corner[3].2 = true;
        assert!(kept(&[&moved_corner, &tip_exact], &exact));
        moved_corner[3].0 = p(2.0 - 4.0 * f64::EPSILON, 1.0);
        assert!(!kept(&[&moved_corner, &tip_exact], &exact));
        // Two rings touching at one shared vertex (the same arrangement vertex) that moved.
        let a = vec![
            (p(0.0, 0.0), 30, false),
            (p(1.0, 0.0), 31, false),
            (p(1.0 / 3.0, 1.0 / 3.0), 32, true),
        ];
        let b = vec![
            (p(1.0 / 3.0, 1.0 / 3.0), 32, true),
            (p(1.0, 1.0), 33, false),
            (p(0.0, 1.0), 34, false),
        ];
        let third = 1.0 / 3.0 + f64::EPSILON / 8.0;
        let exact = [
            (30, p(0.0, 0.0)),
            (31, p(1.0, 0.0)),
            (32, p(third, third)),
            (33, p(1.0, 1.0)),
            (34, p(0.0, 1.0)),
            (35, p(third, third + f64::EPSILON)),
        ];
        assert!(kept(&[&a, &b], &exact));
        // The same, but two distinct vertices rounded onto one point.
        let mut c = b.clone();
        c[0].1 = 35;
        assert!(!kept(&[&a, &c], &exact));
    }
}
