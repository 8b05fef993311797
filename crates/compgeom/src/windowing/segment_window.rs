//! Windowing on arbitrary non-crossing segments (§10.3): report the segments that intersect
//! a closed query rectangle (window).
//!
//! A segment meets the window iff an endpoint lies in it (found with a layered range tree,
//! §5.6) or it meets one of the window's four edges. Edges are queried with segment trees
//! (§10.3): for the left and right edges, a segment tree on the segments' x-extents whose
//! every node keeps its segments sorted bottom to top (they all span the node's slab, and
//! non-crossing segments are totally ordered there); a query walks one root-to-leaf path
//! and binary-searches each node's list with exact orientation tests against the edge's
//! ends. The bottom edge uses a second tree built with x and y exchanged (the top edge is
//! not needed: see [`SegmentWindow::query`]).
//! Segments of zero extent in one direction are left out of that direction's tree: a
//! vertical segment meeting the left edge without an endpoint inside also crosses the
//! bottom edge, and the other tree finds it. Query O(log² n + k) plus sorting the k
//! answers (each reported once, ascending); storage O(n log n); build O(n log² n).
//!
//! **Exactness.** Lists are sorted by the exact y at the slab's left end, then at its right
//! end (constructed points compared via the kernel's [`compare_y_at_x`]), and the build
//! checks that the order also holds at the right end: this is exactly what the binary
//! searches need, so answers are exact. Segments may touch and share endpoints; collinear
//! overlapping segments are fine. Segments that cross inside a common slab make the order
//! impossible: `Err(InvalidInput)` naming two of them. (Crossing segments that never share
//! a node's list are accepted: the answers stay exact.)
//!
//! [`compare_y_at_x`]: crate::kernel::compare_y_at_x

use super::segment_tree::Skeleton;
use crate::kernel::{
    compare_y_at_x, orient2d, Bbox2, Crossing, ExactPoint, Orientation, Point2, Segment2,
};
use crate::range::LayeredRangeTree;
use crate::{Error, Result};
use std::cmp::Ordering;

/// Segments of positive x-extent, each node list sorted bottom to top.
#[derive(Debug, Clone)]
struct Stabber {
    /// Segments in this frame, `a.x < b.x`.
    segs: Vec<Segment2>,
    /// Input index of each.
    ids: Vec<u32>,
    skel: Skeleton,
}

/// The point of `s` (with `a.x < b.x`) at `x`, inside its x-range, exactly.
fn at(s: &Segment2, x: f64) -> ExactPoint {
    if x == s.a.x {
        ExactPoint::Input(s.a)
    } else if x == s.b.x {
        ExactPoint::Input(s.b)
    } else {
        let vertical = Segment2::new(Point2::new(x, 0.0), Point2::new(x, 1.0));
        Crossing::new(*s, vertical).map_or(ExactPoint::Input(s.a), ExactPoint::Crossing)
    }
}

/// y of `s` (with `a.x < b.x`) at `x` in its x-range, rounded, with a bound on the error
/// (none at the endpoints); `None` if an intermediate overflowed.
fn approx_y(s: &Segment2, x: f64) -> Approx {
    if x == s.a.x {
        return Some((s.a.y, 0.0));
    }
    if x == s.b.x {
        return Some((s.b.y, 0.0));
    }
    let t = (x - s.a.x) / (s.b.x - s.a.x);
    let y = s.a.y + (s.b.y - s.a.y) * t;
    // Two subtractions, a division, a subtraction, a product and a sum: under 12 units of
    // roundoff relative to |a.y| + |b.y|; 4e-15 leaves a margin of three. The absolute term
    // covers underflow.
    let err = 4e-15 * (s.a.y.abs() + s.b.y.abs()) + 1e-300;
    (y.is_finite() && t.is_finite() && err.is_finite()).then_some((y, err))
}

/// A rounded y-value and a bound on its error (`None`: overflow, use exact arithmetic).
type Approx = Option<(f64, f64)>;

/// The order of two rounded y-values with error bounds, when the bounds decide it.
#[inline]
fn filter_cmp(a: Approx, b: Approx) -> Option<Ordering> {
    let ((ys, es), (yt, et)) = (a?, b?);
    if ys + es < yt - et {
        Some(Ordering::Less)
    } else if ys - es > yt + et {
        Some(Ordering::Greater)
    } else if es == 0.0 && et == 0.0 {
        ys.partial_cmp(&yt)
    } else {
        None
    }
}

/// y of `s` against y of `t` at `x` (both defined there), exactly: a floating-point
/// filter, then the kernel's exact comparison.
fn cmp_at(s: &Segment2, t: &Segment2, x: f64) -> Ordering {
    filter_cmp(approx_y(s, x), approx_y(t, x)).unwrap_or_else(|| compare_y_at_x(&at(s, x), *t))
}

impl Stabber {
    fn new(segs: Vec<Segment2>, ids: Vec<u32>) -> Result<Stabber> {
        let iv: Vec<(f64, f64)> = segs.iter().map(|s| (s.a.x, s.b.x)).collect();
        let mut skel = Skeleton::new(&iv);
        let mut slabs = Vec::new();
        skel.for_each_node(|k, u0, u1| slabs.push((k, u0, u1)));
        for (k, u0, u1) in slabs {
            if skel.list(k).len() < 2 {
                continue;
            }
            let (xl, xr) = skel.slab(u0, u1);
            let list = skel.list_mut(k);
            // The rounded y-values at both slab ends are computed once per entry; the exact
            // comparison runs only where they cannot decide.
            let mut keyed: Vec<(Approx, Approx, u32)> = list
                .iter()
                .map(|&i| {
                    (
                        approx_y(&segs[i as usize], xl),
                        approx_y(&segs[i as usize], xr),
                        i,
                    )
                })
                .collect();
            keyed.sort_by(|a, b| {
                let (s, t) = (&segs[a.2 as usize], &segs[b.2 as usize]);
                filter_cmp(a.0, b.0)
                    .unwrap_or_else(|| cmp_at(s, t, xl))
                    .then_with(|| filter_cmp(a.1, b.1).unwrap_or_else(|| cmp_at(s, t, xr)))
                    .then(ids[a.2 as usize].cmp(&ids[b.2 as usize]))
            });
            for (slot, e) in list.iter_mut().zip(&keyed) {
                *slot = e.2;
            }
            if xl < xr {
                for w in list.windows(2) {
                    let (s, t) = (&segs[w[0] as usize], &segs[w[1] as usize]);
                    if cmp_at(s, t, xr) == Ordering::Greater {
                        return Err(Error::InvalidInput(format!(
                            "segments {} and {} cross; windowing needs non-crossing segments",
                            ids[w[0] as usize].min(ids[w[1] as usize]),
                            ids[w[0] as usize].max(ids[w[1] as usize])
                        )));
                    }
                }
            }
        }
        Ok(Stabber { segs, ids, skel })
    }

    /// Segments meeting the vertical segment `x = qx, y1 <= y <= y2`.
    fn query(&self, qx: f64, y1: f64, y2: f64, out: &mut Vec<usize>) {
        let Some(u) = self.skel.unit_of(qx) else {
            return;
        };
        let (lo, hi) = (Point2::new(qx, y1), Point2::new(qx, y2));
        self.skel.path(u, |k, _, _| {
            let list = self.skel.list(k);
            let seg = |i: u32| &self.segs[i as usize];
            // Below (qx, y1): the point is strictly left of (above) a → b.
            let p1 = list.partition_point(|&i| {
                orient2d(seg(i).a, seg(i).b, lo) == Orientation::CounterClockwise
            });
            let p2 = list
                .partition_point(|&i| orient2d(seg(i).a, seg(i).b, hi) != Orientation::Clockwise);
            for &i in list.get(p1..p2.max(p1)).unwrap_or(&[]) {
                out.push(self.ids[i as usize] as usize);
            }
        });
    }
}

/// Windowing queries on non-crossing segments in general position or not; answers are
/// input indices.
///
/// ```
/// use compgeom::windowing::SegmentWindow;
/// use compgeom::{Bbox2, Point2, Segment2};
/// let s = |a: (f64, f64), b: (f64, f64)| Segment2::new(Point2::new(a.0, a.1), Point2::new(b.0, b.1));
/// // The first segment cuts the window's corner; no endpoint is inside.
/// let segs = [s((1.0, 2.5), (2.5, 1.0)), s((5.0, 5.0), (6.0, 7.0)), s((-1.0, 1.0), (1.0, -1.0))];
/// let w = SegmentWindow::new(&segs).unwrap();
/// let window = Bbox2 { min: Point2::new(0.0, 0.0), max: Point2::new(2.0, 2.0) };
/// assert_eq!(w.query(&window), vec![0, 2]);
/// ```
#[derive(Debug, Clone)]
pub struct SegmentWindow {
    endpoints: LayeredRangeTree,
    /// The closed box of all segments: windows are clipped to it.
    bounds: Bbox2,
    /// For the left and right edges.
    by_x: Stabber,
    /// For the bottom edge, in the frame with x and y exchanged.
    by_y: Stabber,
}

impl SegmentWindow {
    /// Build the structure. `Err(NonFinite)` names a segment with a NaN or infinite
    /// coordinate; `Err(InvalidInput)` two segments that cross where the structure needs
    /// them ordered.
    pub fn new(segments: &[Segment2]) -> Result<SegmentWindow> {
        let endpoints = super::checked_endpoints(segments)?;
        let frame = |swap: bool| {
            let (mut segs, mut ids) = (Vec::new(), Vec::new());
            for (i, s) in segments.iter().enumerate() {
                let (mut a, mut b) = (s.a, s.b);
                if swap {
                    a = Point2::new(a.y, a.x);
                    b = Point2::new(b.y, b.x);
                }
                if a.x == b.x {
                    continue;
                }
                if a.x > b.x {
                    std::mem::swap(&mut a, &mut b);
                }
                segs.push(Segment2::new(a, b));
                ids.push(i as u32);
            }
            Stabber::new(segs, ids)
        };
        Ok(SegmentWindow {
            bounds: Bbox2::of_points(&endpoints),
            endpoints: LayeredRangeTree::new(&endpoints)?,
            by_x: frame(false)?,
            by_y: frame(true)?,
        })
    }

    /// The segments meeting the closed window, each once, indices ascending. An empty
    /// window (`min > max`) or one with a NaN bound reports nothing; infinite bounds work
    /// (a half-plane, a strip); a zero-width or zero-height window is a segment or a point
    /// and works.
    pub fn query(&self, window: &Bbox2) -> Vec<usize> {
        let mut out = Vec::new();
        let Some(w) = super::clip(window, &self.bounds) else {
            return out;
        };
        let w = &w;
        self.endpoints.for_each(w, |i| out.push(i / 2));
        self.by_x.query(w.min.x, w.min.y, w.max.y, &mut out);
        self.by_x.query(w.max.x, w.min.y, w.max.y, &mut out);
        // Three edges suffice: a segment meeting the window with no endpoint inside meets
        // its boundary in two points, or in one point of a corner or along a whole edge;
        // either way it meets the left, right or bottom edge (a segment meeting only the
        // top edge would touch it at one interior point, which a straight segment can do
        // only by running along it, and then it meets the left and right edges too).
        self.by_y.query(w.min.y, w.min.x, w.max.x, &mut out);
        out.sort_unstable();
        out.dedup();
        out
    }
}
