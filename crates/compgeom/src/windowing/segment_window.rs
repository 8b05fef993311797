//! Windowing on arbitrary non-crossing segments (§10.3): report the segments that intersect
//! a closed query rectangle (window).
//!
//! A segment meets the window iff an endpoint lies in it (found with a
//! [`LayeredRangeTree`] on the endpoints, §5.6) or it meets one of the window's four edges. Edges are queried with
//! segment trees (§10.3): for the left and right edges, a segment tree on the segments'
//! x-extents whose every node keeps its segments sorted bottom to top (they all span the
//! node's slab, and non-crossing segments are totally ordered there); a query walks one
//! root-to-leaf path and searches each node's list for the edge's ends. Each list entry
//! carries bounds (rounded outward to `f32`) on its segment's y over the node's slab,
//! monotone along the list: the search runs over these contiguous keys (interpolation
//! probes guarded by bisection, so never worse than twice a binary search; galloping for
//! the second end) and only the few entries whose bounds straddle the edge's end get the
//! exact orientation test. The bottom edge uses a second tree built with x and y
//! exchanged (the top edge is not needed: see [`SegmentWindow::query`]).
//! Segments of zero extent in one direction are left out of that direction's tree: a
//! vertical segment meeting the left edge without an endpoint inside also crosses the
//! bottom edge, and the other tree finds it.
//!
//! **Compact layout.** The tree's elementary intervals are not cut at every endpoint but at
//! every sixteenth or so (an x carrying many endpoints is always a cut): a segment is stored
//! at the canonical nodes of the intervals it covers whole, and in the *bucket* of the (at
//! most two) open intervals holding one of its endpoints strictly inside, which a query
//! scans with exact tests. Node lists, buckets and the tree are flat `u32` arrays; lists are
//! sorted in parallel. This keeps the book's bounds, O(log² n + k) for the edges, with a
//! fraction of the storage (most of a segment's O(log n) canonical nodes lie near the
//! leaves, which buckets replace). The endpoint part is a layered range tree with
//! fractional cascading, O(log n + k), so the whole query is O(log² n + k); it is the
//! largest part of the storage (about 400 of the 540 bytes per segment in the benchmark;
//! a kd-tree would take 48 but answer in O(√n + k)). Answers are sorted (each reported once, ascending); build O(n log² n).
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
use crate::range::{LayeredRangeTree, PARALLEL};
use crate::{Error, Result};
use rayon::prelude::*;
use std::cmp::Ordering;

/// The segment tree of one frame (§10.3) over slabs of x, with bucket leaves: segments
/// of positive x-extent are stored at the canonical nodes of the units they cover, each
/// node's list sorted bottom to top; a unit an endpoint lies strictly inside keeps the
/// segment in its bucket instead, scanned at query time.
#[derive(Debug, Clone)]
struct Stabber {
    /// The stored segments in this frame, `a.x < b.x`, by left end.
    segs: Vec<Segment2>,
    /// `ids[j]`: the input index of `segs[j]`.
    ids: Vec<u32>,
    /// Node lists of input indices; boundaries every few endpoints (see [`boundaries`]).
    skel: Skeleton,
    /// Bucket `b` (of the open unit `2b + 1`) is `bucket_items[bucket_starts[b]..][..]`.
    bucket_starts: Vec<u32>,
    bucket_items: Vec<u32>,
    /// Alongside each list entry (the flat array of the skeleton's lists): a lower and an
    /// upper bound of the segment's y over the node's slab, made monotone along the list
    /// and rounded outward to `f32` (see [`slab_keys`]: 8 bytes an entry). Queries binary-search these contiguous numbers and leave the
    /// exact orientation tests to the few entries they cannot place.
    keys: Vec<(f32, f32)>,
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

/// Endpoints strictly inside one open unit (between two consecutive boundaries) at most
/// this many, where equal x-values allow: the bound on a bucket scan.
const BUCKET: usize = 16;

/// Every distinct x is a boundary when it carries at least [`BUCKET`] endpoints; otherwise
/// x-values are grouped so that at most `BUCKET` endpoints lie strictly between two
/// consecutive boundaries. `xs` ascending, not empty.
fn boundaries(xs: &[f64]) -> Vec<f64> {
    let mut out = Vec::with_capacity(2 * xs.len() / BUCKET + 2);
    let mut inside = 0usize;
    let mut j = 0;
    while j < xs.len() {
        let v = xs[j];
        let mut c = 1;
        while j + c < xs.len() && xs[j + c] == v {
            c += 1;
        }
        j += c;
        if out.is_empty() || j == xs.len() || c >= BUCKET || inside + c > BUCKET {
            out.push(v);
            inside = 0;
        } else {
            inside += c;
        }
    }
    out
}

impl Stabber {
    /// `frame[i]`: input segment `i` in this frame, `a.x <= b.x`; those with `a.x < b.x`
    /// are stored.
    fn new(frame: Vec<Segment2>) -> Result<Stabber> {
        // Stored in the order of their left ends: the segments of a node's list near the
        // leaves, and of a bucket, then lie close together in memory, which is what the
        // binary searches and bucket scans touch.
        let mut ids: Vec<u32> = (0..frame.len() as u32)
            .filter(|&i| frame[i as usize].a.x < frame[i as usize].b.x)
            .collect();
        // (Only the memory layout: -0 before 0 changes no answer.)
        let by_left = |&i: &u32, &j: &u32| frame[i as usize].a.x.total_cmp(&frame[j as usize].a.x);
        if ids.len() >= PARALLEL {
            ids.par_sort_unstable_by(by_left);
        } else {
            ids.sort_unstable_by(by_left);
        }
        let segs: Vec<Segment2> = ids.iter().map(|&i| frame[i as usize]).collect();
        drop(frame);
        let mut xs: Vec<f64> = segs
            .iter()
            .flat_map(|s| [s.a.x + 0.0, s.b.x + 0.0])
            .collect();
        if xs.len() >= PARALLEL {
            xs.par_sort_unstable_by(f64::total_cmp);
        } else {
            xs.sort_unstable_by(f64::total_cmp);
        }
        let bounds = if xs.is_empty() {
            Vec::new()
        } else {
            boundaries(&xs)
        };
        drop(xs);
        let iv: Vec<(f64, f64)> = segs.iter().map(|s| (s.a.x, s.b.x)).collect();
        let spans = Skeleton::spans(&bounds, &iv);
        drop(iv);
        let (bucket_starts, bucket_items) = buckets(&bounds, &spans, &segs);
        let mut skel = Skeleton::from_spans(bounds, &spans);
        drop(spans);
        let lists = skel.lists_mut();
        let work = |(slab, list): ((f64, f64), &mut [u32])| sort_list(&segs, &ids, slab, list);
        if segs.len() >= PARALLEL {
            lists.into_par_iter().try_for_each(work)?;
        } else {
            lists.into_iter().try_for_each(work)?;
        }
        let keys = slab_keys(&skel, &segs);
        Ok(Stabber {
            segs,
            ids,
            skel,
            bucket_starts,
            bucket_items,
            keys,
        })
    }

    /// Segments meeting the vertical segment `x = qx, y1 <= y <= y2`.
    fn query(&self, qx: f64, y1: f64, y2: f64, out: &mut Vec<usize>) {
        let Some(u) = self.skel.unit_of(qx) else {
            return;
        };
        let (lo, hi) = (Point2::new(qx, y1), Point2::new(qx, y2));
        let seg = |i: u32| &self.segs[i as usize];
        self.skel.path(u, |k, _, _| {
            let range = self.skel.list_range(k);
            if range.is_empty() {
                return;
            }
            let list = &self.skel.items()[range.clone()];
            let keys = &self.keys[range];
            // Segments strictly below (qx, y1) (the point strictly left of, above, a → b)
            // form a prefix; the keys settle all but the entries whose y-range over the
            // slab contains y1, which the exact test decides.
            let p1 = locate(list, keys, 0, y1, |i| {
                orient2d(seg(i).a, seg(i).b, lo) == Orientation::CounterClockwise
            });
            // Segments on or below (qx, y2): a longer prefix.
            let p2 = locate(list, keys, p1, y2, |i| {
                orient2d(seg(i).a, seg(i).b, hi) != Orientation::Clockwise
            });
            for &i in &list[p1..p2] {
                out.push(self.ids[i as usize] as usize);
            }
        });
        if u % 2 == 1 {
            // The unit's partly covering segments, tested one by one (at most a few dozen
            // when x-values are not massively repeated).
            let b = (u - 1) / 2;
            let bucket = &self.bucket_items
                [self.bucket_starts[b] as usize..self.bucket_starts[b + 1] as usize];
            for &i in bucket {
                let s = seg(i);
                if qx < s.a.x || s.b.x < qx || s.a.y.max(s.b.y) < y1 || s.a.y.min(s.b.y) > y2 {
                    continue;
                }
                if orient2d(s.a, s.b, lo) != Orientation::CounterClockwise
                    && orient2d(s.a, s.b, hi) != Orientation::Clockwise
                {
                    out.push(self.ids[i as usize] as usize);
                }
            }
        }
    }

    /// Approximate heap bytes.
    fn memory_bytes(&self) -> usize {
        self.segs.capacity() * 32
            + self.ids.capacity() * 4
            + self.skel.memory_bytes()
            + (self.bucket_starts.capacity() + self.bucket_items.capacity()) * 4
            + self.keys.capacity() * 8
    }
}

/// The end of the prefix of `list` (at or after `from`, where it is known to hold) on which
/// `pred` holds, `pred` being "the segment's y at the query's x is below `y`" (strictly or
/// not). An entry whose upper key is below `y` surely satisfies it, one whose lower key is
/// above `y` surely does not (the keys bound the y over the whole slab, hence at the
/// query's x); only the entries in between get the exact test.
#[inline]
fn locate(
    list: &[u32],
    keys: &[(f32, f32)],
    from: usize,
    y: f64,
    pred: impl Fn(u32) -> bool,
) -> usize {
    let a = if from == 0 {
        search(keys, y)
    } else {
        gallop(keys, from, |k| (k.1 as f64) < y)
    };
    let b = gallop(keys, a, |k| k.0 as f64 <= y);
    a + list[a..b].partition_point(|&i| pred(i))
}

/// The first index whose upper key is at least `y` (upper keys ascend). Each round makes
/// one interpolation probe (the keys of a list are y-values spread over its slab, so this
/// usually lands within a few entries) and one bisection probe (so the search stays
/// O(log n) whatever the spread): at most twice the probes of a binary search.
#[inline]
fn search(keys: &[(f32, f32)], y: f64) -> usize {
    // `keys[..lo]` are below `y`, `keys[hi..]` are not.
    let (mut lo, mut hi) = (0usize, keys.len());
    while hi - lo > 8 {
        let (v0, v1) = (keys[lo].1 as f64, keys[hi - 1].1 as f64);
        // A float-to-int cast saturates (NaN gives 0): any probe in range is valid.
        let guess = lo + ((y - v0) / (v1 - v0) * (hi - 1 - lo) as f64) as usize;
        let probe = guess.clamp(lo, hi - 1);
        if (keys[probe].1 as f64) < y {
            lo = probe + 1;
        } else {
            hi = probe;
        }
        if hi - lo <= 8 {
            break;
        }
        let mid = lo + (hi - lo) / 2;
        if (keys[mid].1 as f64) < y {
            lo = mid + 1;
        } else {
            hi = mid;
        }
    }
    lo + keys[lo..hi].partition_point(|k| (k.1 as f64) < y)
}

/// The first index at or after `from` where `pred` fails, `pred` holding on a prefix of
/// `keys` and at `from - 1`: O(log d) tests for an answer `d` places on.
#[inline]
fn gallop(keys: &[(f32, f32)], from: usize, pred: impl Fn(&(f32, f32)) -> bool) -> usize {
    let (mut lo, mut probe, mut step) = (from, from, 1);
    // `pred` holds below `lo`; `probe` is the next place tested.
    while probe < keys.len() && pred(&keys[probe]) {
        lo = probe + 1;
        probe += step;
        step *= 2;
    }
    let end = probe.min(keys.len()).max(lo);
    lo + keys[lo..end].partition_point(pred)
}

/// The greatest `f32` at most `v` (`v` not NaN).
fn f32_below(v: f64) -> f32 {
    let f = v as f32;
    if f as f64 <= v {
        f
    } else if f > 0.0 {
        f32::from_bits(f.to_bits() - 1)
    } else if f == 0.0 {
        -f32::from_bits(1)
    } else {
        f32::from_bits(f.to_bits() + 1)
    }
}

/// The least `f32` at least `v` (`v` not NaN).
fn f32_above(v: f64) -> f32 {
    -f32_below(-v)
}

/// The keys of every list entry (see [`Stabber::keys`]): bounds on the segment's y at the
/// two ends of the node's slab, whose hull bounds its y anywhere in the slab. Along a list
/// (bottom to top) the exact y-values never decrease at either end, so a running maximum
/// of the upper bounds and a running minimum from the top of the lower bounds are still
/// bounds, and are monotone, as binary search needs. Overflow gives infinite bounds.
fn slab_keys(skel: &Skeleton, segs: &[Segment2]) -> Vec<(f32, f32)> {
    let mut keys = vec![(0.0f32, 0.0f32); skel.items().len()];
    skel.for_each_node(|k, u0, u1| {
        let range = skel.list_range(k);
        if range.is_empty() {
            return;
        }
        let (xl, xr) = skel.slab(u0, u1);
        let list = &skel.items()[range.clone()];
        let keys = &mut keys[range];
        for (key, &i) in keys.iter_mut().zip(list) {
            let s = &segs[i as usize];
            *key = match (approx_y(s, xl), approx_y(s, xr)) {
                (Some((yl, el)), Some((yr, er))) => (
                    f32_below((yl - el).min(yr - er)),
                    f32_above((yl + el).max(yr + er)),
                ),
                _ => (f32::NEG_INFINITY, f32::INFINITY),
            };
        }
        for j in 1..keys.len() {
            keys[j].1 = keys[j].1.max(keys[j - 1].1);
        }
        for j in (0..keys.len() - 1).rev() {
            keys[j].0 = keys[j].0.min(keys[j + 1].0);
        }
    });
    keys
}

/// The buckets of the open units (unit `2b + 1` is bucket `b`): the stored segments with an
/// endpoint strictly inside, flat (`items[starts[b]..starts[b + 1]]`).
fn buckets(xs: &[f64], spans: &[(usize, usize)], segs: &[Segment2]) -> (Vec<u32>, Vec<u32>) {
    // From the whole units `[ua, ub)`: `a` is strictly inside unit `ua - 1` unless it is
    // the boundary `xs[ua / 2]`; `b` strictly inside unit `ub` unless it is the boundary
    // `xs[(ub - 1) / 2]`.
    let partial = |j: usize| {
        let ((ua, ub), s) = (spans[j], &segs[j]);
        let pa = (xs[ua / 2] != s.a.x).then(|| (ua - 1) / 2);
        let pb = (xs[(ub - 1) / 2] != s.b.x).then_some(ub / 2);
        [pa, pb.filter(|&b| Some(b) != pa)]
    };
    let nb = xs.len().saturating_sub(1);
    let mut starts = vec![0u32; nb + 1];
    for j in 0..segs.len() {
        for b in partial(j).into_iter().flatten() {
            starts[b + 1] += 1;
        }
    }
    for b in 0..nb {
        starts[b + 1] += starts[b];
    }
    let mut cursor = starts.clone();
    let mut items = vec![0u32; starts[nb] as usize];
    for j in 0..segs.len() {
        for b in partial(j).into_iter().flatten() {
            items[cursor[b] as usize] = j as u32;
            cursor[b] += 1;
        }
    }
    (starts, items)
}

/// Sort one node's list bottom to top over its slab `[xl, xr]` (all its segments span it)
/// and check that the order holds at both ends, so that no two cross inside.
fn sort_list(segs: &[Segment2], ids: &[u32], (xl, xr): (f64, f64), list: &mut [u32]) -> Result<()> {
    if list.len() < 2 {
        return Ok(());
    }
    // The rounded y-values at both slab ends are computed once per entry; the exact
    // comparison runs only where they cannot decide.
    let mut keyed: Vec<(Approx, Approx, u32)> = list
        .iter()
        .map(|&i| {
            let s = &segs[i as usize];
            (approx_y(s, xl), approx_y(s, xr), i)
        })
        .collect();
    keyed.sort_unstable_by(|a, b| {
        let (s, t) = (&segs[a.2 as usize], &segs[b.2 as usize]);
        filter_cmp(a.0, b.0)
            .unwrap_or_else(|| cmp_at(s, t, xl))
            .then_with(|| filter_cmp(a.1, b.1).unwrap_or_else(|| cmp_at(s, t, xr)))
            .then(a.2.cmp(&b.2))
    });
    for (slot, e) in list.iter_mut().zip(&keyed) {
        *slot = e.2;
    }
    if xl < xr {
        for w in keyed.windows(2) {
            let (s, t) = (&segs[w[0].2 as usize], &segs[w[1].2 as usize]);
            let order = filter_cmp(w[0].1, w[1].1).unwrap_or_else(|| cmp_at(s, t, xr));
            if order == Ordering::Greater {
                let (i, j) = (ids[w[0].2 as usize], ids[w[1].2 as usize]);
                return Err(Error::InvalidInput(format!(
                    "segments {} and {} cross; windowing needs non-crossing segments",
                    i.min(j),
                    i.max(j)
                )));
            }
        }
    }
    Ok(())
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
    /// The endpoints (segment `i` has points `2i` and `2i + 1`).
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
            let segs = segments
                .iter()
                .map(|s| {
                    let (mut a, mut b) = (s.a, s.b);
                    if swap {
                        a = Point2::new(a.y, a.x);
                        b = Point2::new(b.y, b.x);
                    }
                    if a.x > b.x {
                        std::mem::swap(&mut a, &mut b);
                    }
                    Segment2::new(a, b)
                })
                .collect();
            Stabber::new(segs)
        };
        // The three parts are independent: build them side by side.
        let (tree, (by_x, by_y)) = rayon::join(
            || LayeredRangeTree::new(&endpoints),
            || rayon::join(|| frame(false), || frame(true)),
        );
        Ok(SegmentWindow {
            bounds: Bbox2::of_points(&endpoints),
            endpoints: tree?,
            by_x: by_x?,
            by_y: by_y?,
        })
    }

    /// Approximate heap memory in bytes.
    pub fn memory_bytes(&self) -> usize {
        self.endpoints.memory_bytes() + self.by_x.memory_bytes() + self.by_y.memory_bytes()
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
