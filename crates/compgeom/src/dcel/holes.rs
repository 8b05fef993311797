//! The graph G of book §2.3: which face holds each boundary component, by one sweep.
//!
//! A cycle that is not an outer boundary is the outside of a connected component; it
//! lies in the face of the half-edge immediately to the left of its leftmost vertex.
//! As the book does, that half-edge is read off the sweep status when the vertex is
//! reached: a horizontal line moves down over the vertices (higher y first, then
//! smaller x, the order of [`crate::intersect`]); the status holds the non-horizontal
//! edges crossing the line, left to right. At a query vertex `p` the candidates are the
//! rightmost status edge strictly west of `p` and the previous vertex on the same line;
//! the nearer one wins.
//!
//! Edges of a subdivision never cross, so the status order only changes at vertices
//! and each comparison is one exact orientation test of a vertex (an input point or a
//! constructed crossing) against the input segment carrying an edge. Vertices are
//! ordered by their rounded coordinates where they differ (rounding is monotone, so
//! that is exact) and by exact comparisons where they tie.
//!
//! Cost: O(V log V) for the vertex order plus O(s) per status update (4-byte entries) for a status of
//! at most s edges (a vector: s is small for polygon data — the number of edges a
//! horizontal line meets).
use super::Carrier;
use crate::kernel::{orient_exact, Crossing, ExactPoint, Orientation, Point2};
use std::cmp::Ordering;

/// For every vertex `v` with `query[v]`, the half-edge whose face contains the points
/// just left of `v`, or `None` (unbounded face). `out[out_start[v]..out_start[v + 1]]`
/// are `v`'s outgoing half-edges in counter-clockwise order from direction +x; `origin[h]`
/// is the vertex half-edge `h` leaves.
pub(crate) fn faces_left_of(
    points: &[ExactPoint],
    approx: &[Rounded],
    origin: &[u32],
    carriers: &[Carrier],
    out_start: &[usize],
    out: &[usize],
    query: &[bool],
) -> Vec<Option<usize>> {
    let n = points.len();
    let cmp_y =
        |a: usize, b: usize| compare_y_filtered(&points[a], &approx[a], &points[b], &approx[b]);
    let cmp_x =
        |a: usize, b: usize| compare_x_filtered(&points[a], &approx[a], &points[b], &approx[b]);
    // Sweep order: higher y first, then smaller x.
    // First by the rounded points as integer keys (rounding is monotone, so where they
    // differ in y that is the exact order); then each run of equal rounded y holding a
    // point with an inexact coordinate is re-sorted exactly.
    let okey = crate::kernel::arith::ordered_key;
    let mut keyed: Vec<(u64, u64, u32)> = (0..n)
        .map(|v| (!okey(approx[v].p.y), okey(approx[v].p.x), v as u32))
        .collect();
    keyed.sort_unstable();
    let mut order: Vec<usize> = keyed.iter().map(|k| k.2 as usize).collect();
    let mut i = 0;
    while i < n {
        let mut j = i + 1;
        while j < n && keyed[j].0 == keyed[i].0 {
            j += 1;
        }
        if j - i > 1
            && order[i..j]
                .iter()
                .any(|&v| !(approx[v].x_exact && approx[v].y_exact))
        {
            order[i..j].sort_by(|&a, &b| cmp_y(b, a).then_with(|| cmp_x(a, b)));
        }
        i = j;
    }
    let mut rank = vec![0usize; n];
    for (r, &v) in order.iter().enumerate() {
        rank[v] = r;
    }
    // The input segment of an edge, upper end first (input points: exact).
    let down = |h: usize| -> (Point2, Point2) {
        let s = carriers[h].seg;
        if s.a.y > s.b.y || (s.a.y == s.b.y && s.a.x < s.b.x) {
            (s.a, s.b)
        } else {
            (s.b, s.a)
        }
    };
    // The side of vertex `q` of the edge of half-edge `h`. An end of the edge lies on its
    // carrier by construction: no arithmetic (the edges ending at a vertex are still in
    // the status when it is reached, and a constructed end would fail the filter there).
    let side_of = |q: usize, h: u32| {
        if origin[h as usize] as usize == q || origin[h as usize ^ 1] as usize == q {
            return Orientation::Collinear;
        }
        let (up, low) = down(h as usize);
        side(&points[q], approx[q].p, up, low)
    };
    // True when vertex `q` lies east of (left of, going down) the edge of half-edge `h`.
    let east = |q: usize, h: u32| side_of(q, h) == Orientation::CounterClockwise;
    let west = |q: usize, h: u32| side_of(q, h) == Orientation::Clockwise;
    let mut answer = vec![None; n];
    // Status entries: half-edges running down (4 bytes each: the updates move entries).
    let mut status: Vec<u32> = Vec::new();
    let mut prev: Option<usize> = None;
    for &v in &order {
        let same_line = prev.filter(|&w| cmp_y(w, v) == Ordering::Equal);
        let at = status.partition_point(|&e| east(v, e));
        if query[v] {
            let a = at.checked_sub(1).map(|i| status[i]);
            answer[v] = match (a, same_line) {
                // The status edge wins when it passes strictly between w and v.
                (Some(e), Some(w)) if west(w, e) => Some(e as usize),
                // (Every vertex of an arrangement has an edge: zero-length segments
                // leave no vertex. The guard only keeps an isolated vertex, were one
                // ever passed, from being read as a wedge.)
                (_, Some(w)) if out_start[w] < out_start[w + 1] => {
                    // The wedge at w holding direction +x lies left of its last
                    // (counter-clockwise) outgoing half-edge.
                    Some(out[out_start[w + 1] - 1])
                }
                (a, _) => a.map(|e| e as usize),
            };
        }
        let list = &out[out_start[v]..out_start[v + 1]];
        let ends_here = |h: usize| {
            let other = origin[h ^ 1] as usize;
            rank[other] < rank[v] && cmp_y(other, v) != Ordering::Equal
        };
        let starts_here = |h: usize| {
            let other = origin[h ^ 1] as usize;
            rank[other] > rank[v] && cmp_y(other, v) != Ordering::Equal
        };
        // Edges starting here enter the status left to right (counter-clockwise order of
        // the downward directions) at the place of v, where the edges ending here leave
        // it: they are the run of status edges through v (edges of a subdivision do not
        // pass through vertices), checked before the run is replaced in one splice.
        let ending = list.iter().filter(|&&h| ends_here(h)).count();
        let run_ok = at + ending <= status.len()
            && status[at..at + ending]
                .iter()
                .all(|&e| list.contains(&(e as usize ^ 1)) && ends_here(e as usize ^ 1));
        let entering = list.iter().filter(|&&h| starts_here(h)).map(|&h| h as u32);
        if run_ok {
            status.splice(at..at + ending, entering);
        } else {
            for &h in list {
                if ends_here(h) {
                    if let Some(i) = status.iter().position(|&e| e as usize == h ^ 1) {
                        status.remove(i);
                    }
                }
            }
            let at = status.partition_point(|&e| east(v, e));
            let entering: Vec<_> = entering.collect();
            status.splice(at..at, entering);
        }
        prev = Some(v);
    }
    answer
}

/// A vertex's rounded point, and which of its coordinates are known to be exact (all of
/// an input point's; x of a crossing with a vertical segment, y of one with a horizontal
/// segment): where both rounded coordinates are equal and exact, the points are equal
/// on that axis with no exact arithmetic (grid and axis-parallel data).
#[derive(Debug, Clone, Copy)]
pub(crate) struct Rounded {
    p: Point2,
    x_exact: bool,
    y_exact: bool,
}
crate::scratch::reusable!(Rounded);

impl Rounded {
    /// The rounded point.
    pub(crate) fn point(&self) -> Point2 {
        self.p
    }

    /// Whether the point is known to be exact without a test (an input point, or a
    /// crossing with an axis-parallel segment along each axis).
    pub(crate) fn surely_exact(&self) -> bool {
        self.x_exact && self.y_exact
    }

    /// The rounded point of `e` (`approx` is its nearest `f64` point).
    pub(crate) fn of(e: &ExactPoint, approx: Point2) -> Rounded {
        match e {
            ExactPoint::Input(p) => Rounded::input(*p),
            ExactPoint::Crossing(c) => Rounded::crossing(c, approx),
        }
    }

    /// An input point (exact).
    #[inline]
    pub(crate) fn input(p: Point2) -> Rounded {
        Rounded {
            p,
            x_exact: true,
            y_exact: true,
        }
    }

    /// The crossing `c` rounded to `approx`.
    #[inline]
    pub(crate) fn crossing(c: &Crossing, approx: Point2) -> Rounded {
        Rounded {
            p: approx,
            x_exact: c.s.a.x == c.s.b.x || c.t.a.x == c.t.b.x,
            y_exact: c.s.a.y == c.s.b.y || c.t.a.y == c.t.b.y,
        }
    }
}

/// Exact comparison of x coordinates, decided by the rounded points where they differ
/// (rounding to nearest is monotone) or are both exact.
pub(super) fn compare_x_filtered(
    a: &ExactPoint,
    ra: &Rounded,
    b: &ExactPoint,
    rb: &Rounded,
) -> Ordering {
    compare_filtered(ra.p.x, rb.p.x, ra.x_exact && rb.x_exact, || a.compare_x(b))
}

/// Two rounded coordinates' order where they differ, equal where both are exact (-0 and
/// 0 are one value: `total_cmp` would put -0 first, against every exact test), else
/// `compare()`, the exact comparison. (Rounded points are never NaN.)
#[inline]
fn compare_filtered(u: f64, v: f64, exact: bool, compare: impl FnOnce() -> Ordering) -> Ordering {
    if u < v {
        Ordering::Less
    } else if u > v {
        Ordering::Greater
    } else if exact {
        Ordering::Equal
    } else {
        compare()
    }
}

/// As [`compare_x_filtered`] for y.
pub(crate) fn compare_y_filtered(
    a: &ExactPoint,
    ra: &Rounded,
    b: &ExactPoint,
    rb: &Rounded,
) -> Ordering {
    compare_filtered(ra.p.y, rb.p.y, ra.y_exact && rb.y_exact, || a.compare_y(b))
}

/// [`compare_xy_filtered`] of two points with rounded points `ra` and `rb`, the exact
/// points made by `exact` only where the rounded ones do not decide.
#[inline]
pub(crate) fn compare_xy_filtered_by(
    ra: &Rounded,
    rb: &Rounded,
    exact: impl Fn() -> (ExactPoint, ExactPoint),
) -> Ordering {
    compare_filtered(ra.p.x, rb.p.x, ra.x_exact && rb.x_exact, || {
        let (a, b) = exact();
        a.compare_x(&b)
    })
    .then_with(|| {
        compare_filtered(ra.p.y, rb.p.y, ra.y_exact && rb.y_exact, || {
            let (a, b) = exact();
            a.compare_y(&b)
        })
    })
}

/// Exact lexicographic (x, then y) comparison, filtered as [`compare_x_filtered`].
pub(crate) fn compare_xy_filtered(
    a: &ExactPoint,
    ra: &Rounded,
    b: &ExactPoint,
    rb: &Rounded,
) -> Ordering {
    compare_x_filtered(a, ra, b, rb).then_with(|| compare_y_filtered(a, ra, b, rb))
}

/// Orientation of `(u, l, q)`, exactly: first in `f64` from `q`'s rounded point `pq`
/// with an error bound covering both the arithmetic and the rounding of a constructed
/// `q` (at most half an ulp per coordinate), then, when that cannot decide, by
/// [`orient_exact`].
pub(crate) fn side(q: &ExactPoint, pq: Point2, u: Point2, l: Point2) -> Orientation {
    let (dx, dy) = (l.x - u.x, l.y - u.y);
    let (qx, qy) = (pq.x - u.x, pq.y - u.y);
    let (left, right) = (dx * qy, dy * qx);
    let det = left - right;
    // Arithmetic: the bound of the classic orientation filter, generously rounded up.
    let mut err = 4.0e-16 * (left.abs() + right.abs());
    if let ExactPoint::Crossing(_) = q {
        // |q - pq| <= 2^-53 |pq| per coordinate; |dx|, |dy| carry relative error 2^-53.
        err += 1.2e-16 * (dx.abs() + dy.abs()) * (pq.x.abs() + pq.y.abs()) * 1.01;
    }
    if det.abs() > err && det.abs() > 1e-280 && err.is_finite() {
        if det > 0.0 {
            Orientation::CounterClockwise
        } else {
            Orientation::Clockwise
        }
    } else {
        orient_exact(&ExactPoint::Input(u), &ExactPoint::Input(l), q)
    }
}
