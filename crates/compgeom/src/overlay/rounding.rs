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
//! exact edge (a collinear pair never is). With every near pair on its side and every
//! other pair out of reach, no edges cross or touch that did not, and no ring is carried
//! across another's edge: the rounded rings keep the exact result's topology.
//!
//! The test sees the points a ring keeps. Where two consecutive vertices of a ring round
//! to one point, the edge between them collapsed: the point stands for both (edges
//! leave it from the second), and the collapsed edge is tested as an edge of no length,
//! which nothing may come near. Three vertices on one point, or a ring left with fewer
//! than three points, the tracing reports and the result is not taken as it is.
//!
//! Otherwise [`super::trace::traced_boolean`] unites the polygons of the failing rings
//! again with the [`super::FillRule::Positive`] rule (the arrangement of their rounded
//! rings has the new crossings as vertices; the union of each polygon's shell minus its
//! holes is the result, moved by no more than the rounding), keeps the other polygons as
//! they are (a point of theirs on the new rings stays a vertex there), and checks the
//! new polygons' vertices the same way, among the kept ones (whose points do not move; a
//! kept polygon that fails joins the next union). Measured: on random float rings of
//! 3–20 vertices about one result in 10⁴ needs this; on nested shapes shifted by thirds
//! a fifth; on the JTS robustness pairs and the GEOS-837 dissolve most results, where
//! a rounded vertex really does land on the wrong side of an edge. One union has always
//! sufficed (the bound [`REPAIRS`] is a guard: past it the result is returned as it is).

use crate::kernel::{orient2d, Orientation, Point2};

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
    pub(super) points: Vec<Point2>,
    pub(super) ids: Vec<PointIds>,
    pub(super) starts: Vec<usize>,
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

impl RoundedRings {
    fn rings(&self) -> impl Iterator<Item = std::ops::Range<usize>> + '_ {
        self.starts.windows(2).map(|w| w[0]..w[1])
    }

    /// The ring edges, and the collapsed ones.
    fn edges(&self) -> impl Iterator<Item = Edge> + '_ {
        let ring_edges = self.rings().flat_map(move |r| {
            r.clone().map(move |i| {
                let j = if i + 1 == r.end { r.start } else { i + 1 };
                Edge {
                    i,
                    j,
                    a: self.ids[i].leave,
                    b: self.ids[j].enter,
                }
            })
        });
        let collapsed = (0..self.points.len())
            .filter(|&i| self.ids[i].enter != self.ids[i].leave)
            .map(|i| Edge {
                i,
                j: i,
                a: self.ids[i].enter,
                b: self.ids[i].leave,
            });
        ring_edges.chain(collapsed)
    }

    fn moved(&self, i: usize) -> bool {
        self.ids[i].moved
    }
}

/// The gap above `|v|` (0 for a point that did not move: it stays where it is).
fn gap(v: f64) -> f64 {
    let a = v.abs();
    f64::from_bits(a.to_bits() + 1) - a
}

/// The next `f64` above `x` (`x` itself for +∞ and NaN).
fn up(x: f64) -> f64 {
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
fn down(x: f64) -> f64 {
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

impl Box2 {
    /// The bounding box of `a` and `b`, widened by `(hx, hy)` ([`widened`]).
    fn around(a: Point2, b: Point2, (hx, hy): (f64, f64)) -> Box2 {
        let (x0, x1) = widened(a.x.min(b.x), a.x.max(b.x), hx);
        let (y0, y1) = widened(a.y.min(b.y), a.y.max(b.y), hy);
        Box2 { x0, x1, y0, y1 }
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
    let bx = Box2::around(c, c, (2.0 * hx, 2.0 * hy));
    if !Box2::around(a, b, (0.0, 0.0)).overlaps(&bx) {
        return false;
    }
    if a == b {
        return true;
    }
    let corners = [
        Point2::new(bx.x0, bx.y0),
        Point2::new(bx.x1, bx.y0),
        Point2::new(bx.x1, bx.y1),
        Point2::new(bx.x0, bx.y1),
    ];
    let mut sides = corners.iter().map(|&q| orient2d(a, b, q));
    let first = sides.next().unwrap_or(Orientation::Collinear);
    first == Orientation::Collinear || sides.any(|o| o != first)
}

/// The rings near which rounding may not have kept the result's topology (module docs;
/// each ring once or more, in no order): those of the points and edges of the pairs that
/// fail. A pair is a vertex and an edge not incident to it, at least one of them moved;
/// it passes when they stay apart as rounding moves them, or, where they may not, when
/// the rounded vertex lies strictly on the side of the rounded edge where
/// `exact_side(edge start, edge end, vertex)` (the exact orientation of the vertices with
/// these ids) puts it. Conservative: a ring listed only may have been broken. Empty
/// when no point moved.
pub(super) fn failing_rings(
    r: &RoundedRings,
    exact_side: impl Fn(u32, u32, u32) -> Orientation,
) -> Vec<usize> {
    let mut failing = Vec::new();
    if !r.ids.iter().any(|p| p.moved) {
        return failing;
    }
    let ring_of = |i: usize| r.starts.partition_point(|&s| s <= i) - 1;
    let reach_of = |i: usize| reach(r.points[i], r.moved(i));
    let edge_reach = |e: &Edge| {
        let ((ax, ay), (bx, by)) = (reach_of(e.i), reach_of(e.j));
        (ax.max(bx), ay.max(by))
    };
    // For the grid, boxes about the items that are sure to overlap where `apart` below
    // may find them near: twice its box sizes, and a point's box two gaps of its own
    // coordinates wider (more than the outward rounding of the box `meets` tests).
    let point_box = |i: usize| {
        let (hx, hy) = reach_of(i);
        let c = r.points[i];
        Box2::around(c, c, (4.0 * hx + 2.0 * gap(c.x), 4.0 * hy + 2.0 * gap(c.y)))
    };
    let edge_box = |e: &Edge| {
        let (hx, hy) = edge_reach(e);
        Box2::around(r.points[e.i], r.points[e.j], (4.0 * hx, 4.0 * hy))
    };
    let moved_edges: Vec<Edge> = r.edges().filter(|e| r.moved(e.i) || r.moved(e.j)).collect();
    let moved_points: Vec<usize> = (0..r.points.len()).filter(|&i| r.moved(i)).collect();
    // Point x against edge e, unless x is an end of e (the same arrangement vertex:
    // rings touching at a point share it; for a point that stands for a collapsed edge,
    // either of its two vertices). A collapsed edge has no side: anything near it fails.
    let apart = |x: usize, e: &Edge| {
        let PointIds { enter, leave, .. } = r.ids[x];
        if [enter, leave].iter().any(|&v| v == e.a || v == e.b) {
            return true;
        }
        let (ex, ey) = edge_reach(e);
        let (px, py) = reach_of(x);
        let (a, b, c) = (r.points[e.i], r.points[e.j], r.points[x]);
        if !meets(a, b, c, (ex + px, ey + py)) {
            return true;
        }
        let rounded = orient2d(a, b, c);
        [enter, leave].iter().all(|&v| {
            let side = exact_side(e.a, e.b, v);
            side != Orientation::Collinear && side == rounded
        })
    };
    let grid = Grid::new(
        moved_edges
            .iter()
            .map(edge_box)
            .chain(moved_points.iter().map(|&i| point_box(i)))
            .collect(),
    );
    // Every point against the moved edges near it; every edge whose ends did not move
    // against the moved points near it (a moved edge against a point: the first pass).
    let mut stamp = vec![usize::MAX; moved_edges.len() + moved_points.len()];
    for x in 0..r.points.len() {
        grid.visit(&point_box(x), x, &mut stamp, |item| {
            if let Some(e) = moved_edges.get(item) {
                if !apart(x, e) {
                    failing.extend([ring_of(x), ring_of(e.i)]);
                }
            }
        });
    }
    let query_base = r.points.len();
    for (k, e) in r.edges().enumerate() {
        if r.moved(e.i) || r.moved(e.j) {
            continue;
        }
        grid.visit(&edge_box(&e), query_base + k, &mut stamp, |item| {
            if item >= moved_edges.len() {
                let x = moved_points[item - moved_edges.len()];
                if !apart(x, &e) {
                    failing.extend([ring_of(x), ring_of(e.i)]);
                }
            }
        });
    }
    failing
}

/// A uniform grid over the boxes of the moved items (about two cells per item), each
/// item listed in the cells its box overlaps; an item over more than [`WIDE_CELLS`]
/// cells is listed once, in `wide`, and met by every query.
struct Grid {
    x0: f64,
    y0: f64,
    inv: f64,
    nx: usize,
    ny: usize,
    extent: Box2,
    starts: Vec<u32>,
    items: Vec<u32>,
    wide: Vec<u32>,
    count: usize,
}

/// An item's box over more cells than this is `wide`.
const WIDE_CELLS: usize = 64;

impl Grid {
    fn new(boxes: Vec<Box2>) -> Grid {
        let mut extent = Box2 {
            x0: f64::INFINITY,
            x1: f64::NEG_INFINITY,
            y0: f64::INFINITY,
            y1: f64::NEG_INFINITY,
        };
        for b in &boxes {
            extent.x0 = extent.x0.min(b.x0);
            extent.x1 = extent.x1.max(b.x1);
            extent.y0 = extent.y0.min(b.y0);
            extent.y1 = extent.y1.max(b.y1);
        }
        let count = boxes.len();
        // Square cells, about two per item (the longer side cut into at most 2·count + 1).
        let (w, h) = (extent.x1 - extent.x0, extent.y1 - extent.y0);
        let longest = w.max(h);
        let by_area = ((w * h) / (2 * count.max(1)) as f64).sqrt();
        let side = by_area.max(longest / (2 * count + 1) as f64);
        let inv = if side > 0.0 && side.is_finite() {
            1.0 / side
        } else {
            0.0
        };
        let cells = |len: f64| ((len * inv) as usize).clamp(0, 2 * count) + 1;
        let mut grid = Grid {
            x0: extent.x0,
            y0: extent.y0,
            inv,
            nx: cells(w),
            ny: cells(h),
            extent,
            starts: Vec::new(),
            items: Vec::new(),
            wide: Vec::new(),
            count,
        };
        grid.fill(&boxes);
        grid
    }

    /// The cell range of a box, clamped to the grid (monotone in the box's bounds, so
    /// boxes that overlap share a cell).
    fn range(&self, b: &Box2) -> (usize, usize, usize, usize) {
        let ix = |x: f64| (((x - self.x0) * self.inv).max(0.0) as usize).min(self.nx - 1);
        let iy = |y: f64| (((y - self.y0) * self.inv).max(0.0) as usize).min(self.ny - 1);
        (ix(b.x0), ix(b.x1), iy(b.y0), iy(b.y1))
    }

    fn fill(&mut self, boxes: &[Box2]) {
        let mut starts = vec![0u32; self.nx * self.ny + 1];
        let cells_of = |b: &Box2| {
            let (x0, x1, y0, y1) = self.range(b);
            let wide = (x1 - x0 + 1) * (y1 - y0 + 1) > WIDE_CELLS;
            (x0, x1, y0, y1, wide)
        };
        for b in boxes {
            let (x0, x1, y0, y1, wide) = cells_of(b);
            if !wide {
                for y in y0..=y1 {
                    for x in x0..=x1 {
                        starts[y * self.nx + x + 1] += 1;
                    }
                }
            }
        }
        for k in 1..starts.len() {
            starts[k] += starts[k - 1];
        }
        let mut at = starts.clone();
        let mut items = vec![0u32; starts[starts.len() - 1] as usize];
        let mut wide_items = Vec::new();
        for (item, b) in boxes.iter().enumerate() {
            let (x0, x1, y0, y1, wide) = cells_of(b);
            if wide {
                wide_items.push(item as u32);
                continue;
            }
            for y in y0..=y1 {
                for x in x0..=x1 {
                    let slot = &mut at[y * self.nx + x];
                    items[*slot as usize] = item as u32;
                    *slot += 1;
                }
            }
        }
        self.starts = starts;
        self.items = items;
        self.wide = wide_items;
    }

    /// Calls `f` once for each item whose cells box `b` overlaps (and for each wide
    /// item), or for every item when `b` covers more cells than there are items;
    /// `stamp[item] == query` marks an item already met by this query.
    fn visit(&self, b: &Box2, query: usize, stamp: &mut [usize], mut f: impl FnMut(usize)) {
        if !b.overlaps(&self.extent) {
            return;
        }
        let (x0, x1, y0, y1) = self.range(b);
        if (x1 - x0 + 1) * (y1 - y0 + 1) > self.count + WIDE_CELLS {
            (0..self.count).for_each(f);
            return;
        }
        for &item in &self.wide {
            f(item as usize);
        }
        for y in y0..=y1 {
            for x in x0..=x1 {
                let cell = y * self.nx + x;
                let list = &self.items[self.starts[cell] as usize..self.starts[cell + 1] as usize];
                for &item in list {
                    let item = item as usize;
                    if stamp[item] != query {
                        stamp[item] = query;
                        f(item);
                    }
                }
            }
        }
    }
}

#[cfg(test)]
mod tests {
    use super::{failing_rings, meets, PointIds, RoundedRings};
    use crate::kernel::{orient2d, Orientation, Point2};

    fn p(x: f64, y: f64) -> Point2 {
        Point2::new(x, y)
    }

    /// Rings from (point, vertex id, moved) lists.
    fn rings(list: &[&[(Point2, u32, bool)]]) -> RoundedRings {
        let mut r = RoundedRings {
            starts: vec![0],
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

    /// No ring fails [`failing_rings`], with the exact points given per id (f64 points stand for
    /// exact ones here).
    fn kept(list: &[&[(Point2, u32, bool)]], exact: &[(u32, Point2)]) -> bool {
        let at = |id: u32| exact.iter().find(|e| e.0 == id).expect("exact point").1;
        failing_rings(&rings(list), |a, b, c| orient2d(at(a), at(b), at(c))).is_empty()
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
        assert!(!kept(&[&sq, &tip(2.0, true)], &exact));
        assert!(!kept(&[&sq, &tip(next(2.0), true)], &exact));
        // Far from the square: kept without a look at the sides.
        let far =
            |a: u32, b: u32, c: u32| -> Orientation { panic!("no pair is near: {a} {b} {c}") };
        let tip_far = tip(1.0, true);
        assert!(failing_rings(&rings(&[&sq, &tip_far]), far).is_empty());
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
