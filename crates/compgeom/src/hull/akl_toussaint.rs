//! The default hull: an Akl–Toussaint extreme-point filter, then the monotone chain on the
//! points that survive it.
//!
//! The filter picks the input points extreme in eight directions (the minimum and maximum
//! of x, y, x + y and x − y) and discards every point that lies *strictly inside* the
//! polygon Q of those points. Such a point is interior to the hull, so it is neither a
//! vertex nor on an edge, and the hull of the survivors equals the hull of the input (also
//! with `keep_collinear`).
//!
//! Exactness: x + y and x − y are rounded, so the "extreme" points are only candidates
//! chosen by the rounded keys, and Q need not even be convex. That does not matter: a point
//! is discarded only when the exact [`orient2d`] puts it strictly left of every directed
//! edge of Q (taken counter-clockwise). If p is strictly left of every edge of any closed
//! polygon, the polygon winds around p with positive winding number, so p lies in the
//! interior of the convex hull of Q's vertices, which are input points. A cheaper
//! pre-test, "strictly inside an axis-parallel box", discards most points with four
//! comparisons; the box is used only after its four corners are checked, exactly, to lie
//! left of or on every edge of Q (so the open box lies in the region above).
//!
//! Cost: O(n) for the extreme points and the filter (both on the rayon pool above 100 000
//! points), then O(m log m) for the m survivors (sorted as in [`super::sort`]). For points
//! spread over a region m is far smaller than n (O(√n)-ish for a square, about a tenth of
//! a disc); for points in convex position (all on a circle) nothing can be discarded, so a
//! sample of about a thousand points is tried first and, if the filter would discard fewer
//! than one in eight, it is skipped and the method costs what the monotone chain costs.

use super::andrew::{monotone_chain, sort_dedup};
use crate::kernel::{orient2d, Orientation, Point2};
use rayon::prelude::*;

/// Below this many points the filter is not worth its set-up.
const FILTER_MIN: usize = 64;
/// Above this many points the filter runs on the rayon pool.
const PARALLEL_MIN: usize = 100_000;
/// Points per parallel filter task.
const CHUNK: usize = 1 << 15;
/// Points tried before filtering everything (see [`Filter::worth_it`]).
const SAMPLE: usize = 1024;

/// The indices of the extreme points in eight directions, counter-clockwise from the
/// leftmost: min x, min x+y, min y, max x−y, max x, max x+y, max y, min x−y.
#[derive(Clone, Copy)]
struct Extremes {
    best: [(f64, usize); 8],
}

impl Extremes {
    /// Keys are oriented so that each slot keeps the *largest* key. (x ± y are rounded:
    /// they only nominate candidates; see the module doc.)
    #[inline(always)]
    fn keys(p: Point2) -> [f64; 8] {
        let s = p.x + p.y;
        let d = p.x - p.y;
        [-p.x, -s, -p.y, d, p.x, s, p.y, -d]
    }

    /// The extremes of `chunk`, whose first point has index `offset` in the input.
    fn of_chunk(chunk: &[Point2], offset: usize) -> Self {
        let k0 = Self::keys(chunk[0]);
        let mut key = k0;
        let mut idx = [offset; 8];
        for (i, &p) in chunk.iter().enumerate().skip(1) {
            let k = Self::keys(p);
            for s in 0..8 {
                if k[s] > key[s] {
                    key[s] = k[s];
                    idx[s] = offset + i;
                }
            }
        }
        let mut best = [(0.0, 0); 8];
        for s in 0..8 {
            best[s] = (key[s], idx[s]);
        }
        Extremes { best }
    }

    fn merge(mut self, other: Self) -> Self {
        for (mine, theirs) in self.best.iter_mut().zip(other.best) {
            if theirs.0 > mine.0 {
                *mine = theirs;
            }
        }
        self
    }
}

/// The discard test: the polygon Q (counter-clockwise, consecutive repeats removed) and an
/// optional box whose open interior is known to lie inside it.
struct Filter {
    q: Vec<Point2>,
    /// (min x, min y, max x, max y) of the verified inner box; `None` if unusable.
    inner: Option<[f64; 4]>,
}

impl Filter {
    fn new(points: &[Point2], ext: &Extremes) -> Option<Self> {
        let mut q: Vec<Point2> = ext.best.iter().map(|&(_, i)| points[i]).collect();
        q.dedup();
        while q.len() > 1 && q.first() == q.last() {
            q.pop();
        }
        if q.len() < 3 {
            return None;
        }
        let mut f = Filter { q, inner: None };
        f.inner = f.inner_box(points, ext);
        Some(f)
    }

    /// A box from the extreme points (left side = the largest x among the three left-most
    /// extremes, and so on), kept only if its corners are exactly inside Q's half-planes.
    fn inner_box(&self, points: &[Point2], ext: &Extremes) -> Option<[f64; 4]> {
        let at = |k: usize| points[ext.best[k].1];
        let max3 = |a: f64, b: f64, c: f64| a.max(b).max(c);
        let min3 = |a: f64, b: f64, c: f64| a.min(b).min(c);
        // Slots: 0 W, 1 SW, 2 S, 3 SE, 4 E, 5 NE, 6 N, 7 NW.
        let x0 = max3(at(0).x, at(1).x, at(7).x);
        let y0 = max3(at(1).y, at(2).y, at(3).y);
        let x1 = min3(at(3).x, at(4).x, at(5).x);
        let y1 = min3(at(5).y, at(6).y, at(7).y);
        if x0 >= x1 || y0 >= y1 {
            return None;
        }
        let corners = [
            Point2::new(x0, y0),
            Point2::new(x1, y0),
            Point2::new(x1, y1),
            Point2::new(x0, y1),
        ];
        let ok = corners.iter().all(|&c| self.not_right_of_any_edge(c));
        ok.then_some([x0, y0, x1, y1])
    }

    /// Whether the filter discards enough of a regular sample of the points (at least one
    /// in eight) to pay for itself; on points in convex position it discards nothing.
    /// Either way the hull is the same; this only chooses the faster route.
    fn worth_it(&self, points: &[Point2]) -> bool {
        let step = (points.len() / SAMPLE).max(1);
        let tried = points.len().div_ceil(step);
        let hits = points
            .iter()
            .step_by(step)
            .filter(|&&p| self.discards(p))
            .count();
        hits * 8 >= tried
    }

    fn not_right_of_any_edge(&self, p: Point2) -> bool {
        let n = self.q.len();
        (0..n).all(|i| orient2d(self.q[i], self.q[(i + 1) % n], p) != Orientation::Clockwise)
    }

    /// True when `p` is certainly interior to the hull (exact; see the module doc).
    #[inline(always)]
    fn discards(&self, p: Point2) -> bool {
        if let Some([x0, y0, x1, y1]) = self.inner {
            if (x0 < p.x) & (p.x < x1) & (y0 < p.y) & (p.y < y1) {
                return true;
            }
        }
        let q = &self.q;
        let n = q.len();
        let mut prev = q[n - 1];
        for &v in q {
            if orient2d(prev, v, p) != Orientation::CounterClockwise {
                return false;
            }
            prev = v;
        }
        true
    }
}

/// The convex hull of finite points: filter, then monotone chain on the survivors.
pub(crate) fn akl_toussaint(points: &[Point2], keep_collinear: bool) -> Vec<Point2> {
    let n = points.len();
    if n < FILTER_MIN {
        return super::andrew::andrew(points, keep_collinear);
    }
    let parallel = n >= PARALLEL_MIN;
    let ext = if parallel {
        points
            .par_chunks(CHUNK)
            .enumerate()
            .map(|(c, chunk)| Extremes::of_chunk(chunk, c * CHUNK))
            // Any point's extremes are a harmless identity for the merge.
            .reduce(|| Extremes::of_chunk(&points[..1], 0), Extremes::merge)
    } else {
        Extremes::of_chunk(points, 0)
    };
    let mut survivors: Vec<Point2> = match Filter::new(points, &ext) {
        Some(f) if f.worth_it(points) => {
            if parallel {
                points
                    .par_chunks(CHUNK)
                    .map(|c| c.iter().copied().filter(|&p| !f.discards(p)).collect())
                    .collect::<Vec<Vec<Point2>>>()
                    .concat()
            } else {
                points.iter().copied().filter(|&p| !f.discards(p)).collect()
            }
        }
        _ => points.to_vec(),
    };
    sort_dedup(&mut survivors);
    monotone_chain(&survivors, keep_collinear)
}
