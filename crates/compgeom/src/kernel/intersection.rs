//! Exact intersection of two closed segments (book §2.1: the test behind every
//! intersection event).
//!
//! Decided with four exact orientations; degenerate cases (touching at an endpoint,
//! an endpoint on the other segment, collinear overlap, zero-length segments) are
//! ordinary answers. A common point that is an input endpoint is reported as that
//! input point, never recomputed.

use super::crossing::Crossing;
use super::predicates::{compare_xy, orient2d, Orientation};
use super::types::{Point2, Segment2};
use std::cmp::Ordering;

/// How two closed segments meet.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum SegmentIntersection {
    /// No common point.
    None,
    /// Exactly one common point, and it is an endpoint of `s` or `t` (or the point of a
    /// zero-length segment): reported as that input point.
    Endpoint(Point2),
    /// Exactly one common point, interior to both segments: a constructed crossing.
    Crossing(Crossing),
    /// The segments are collinear and share a part of positive length, from the first
    /// point to the second (lexicographic order); both are input endpoints.
    Overlap(Point2, Point2),
}

fn sorted(s: Segment2) -> (Point2, Point2) {
    if compare_xy(s.a, s.b) == Ordering::Greater {
        (s.b, s.a)
    } else {
        (s.a, s.b)
    }
}

/// True when `p` lies on the closed segment `s` (exact; `s` may be a point).
fn contains(s: Segment2, p: Point2) -> bool {
    let (lo, hi) = sorted(s);
    compare_xy(lo, p) != Ordering::Greater
        && compare_xy(p, hi) != Ordering::Greater
        && orient2d(s.a, s.b, p) == Orientation::Collinear
}

/// Shewchuk's `ccwerrboundA`, `(3 + 16ε)ε` with `ε = 2^-53`: a plain `f64` orientation
/// whose magnitude exceeds this times `|l| + |r|` has the exact sign (absent underflow).
const CCW_ERRBOUND_A: f64 = 3.330_669_073_875_472e-16;

/// Below this, `|l| + |r|` is too small for the relative bound: no decision.
const FILTER_FLOOR: f64 = 1e-290;

/// The sign of the orientation of `(a, b, c)` (`1` counter-clockwise, `-1` clockwise) when
/// plain `f64` arithmetic decides it, else `0` (collinear or too close to tell).
#[inline(always)]
pub(crate) fn orient_filtered(a: Point2, b: Point2, c: Point2) -> i8 {
    let l = (b.x - a.x) * (c.y - a.y);
    let r = (b.y - a.y) * (c.x - a.x);
    let det = l - r;
    let mag = l.abs() + r.abs();
    // NaN or infinite values fail every comparison: undecided.
    if !(FILTER_FLOOR..f64::MAX).contains(&mag) {
        return 0;
    }
    // The absolute term covers the underflow of the smaller product.
    let bound = CCW_ERRBOUND_A * mag + 1e-300;
    if det > bound {
        1
    } else if -det > bound {
        -1
    } else {
        0
    }
}

/// The answer of [`segment_intersection`] when four filtered orientations decide it
/// (no common point, or a proper crossing), `None` when some orientation is zero or
/// too close to zero to tell (the exact code then decides).
#[inline(always)]
fn straddle_filter(s: Segment2, t: Segment2) -> Option<SegmentIntersection> {
    let o1 = orient_filtered(s.a, s.b, t.a);
    let o2 = orient_filtered(s.a, s.b, t.b);
    if o1 == 0 || o2 == 0 {
        return None;
    }
    if o1 == o2 {
        return Some(SegmentIntersection::None);
    }
    let o3 = orient_filtered(t.a, t.b, s.a);
    let o4 = orient_filtered(t.a, t.b, s.b);
    if o3 == 0 || o4 == 0 {
        return None;
    }
    if o3 == o4 {
        return Some(SegmentIntersection::None);
    }
    // Each segment's ends lie strictly on both sides of the other's line: the lines are
    // not parallel and meet in one point interior to both segments.
    Some(SegmentIntersection::Crossing(Crossing { s, t }))
}

/// How two segments meet when four filtered orientations decide it: `Some(false)` no
/// common point, `Some(true)` a proper crossing (interior to both), `None` when the exact
/// [`segment_intersection`] must decide. Cheap and inlined, for loops over many pairs.
#[inline(always)]
pub(crate) fn quick_crossing(s: Segment2, t: Segment2) -> Option<bool> {
    match straddle_filter(s, t)? {
        SegmentIntersection::None => Some(false),
        _ => Some(true),
    }
}

/// A static error bound for the filtered orientation of points whose coordinates are
/// all at most `m` in magnitude: [`quick_crossing_static`] with it decides only where
/// the dynamic filter decides, and the same way. Infinite (never decides) when `8m²`
/// could overflow or the bound would be below the filter's floor.
///
/// Why: differences of such coordinates round to at most `2m`, so the products to at
/// most `fl(4m²)` and `mag = |l| + |r|` to at most `fl(8m²)` (rounding is monotone and
/// scaling by a power of two exact); the dynamic bound `A·mag + 10^-300`, evaluated in
/// the same order, is then at most this one. A determinant above it has
/// `mag ≥ |det| >` the floor, and `mag` stays finite: the dynamic filter decides it too.
pub(crate) fn static_orient_bound(m: f64) -> f64 {
    let sq8 = 8.0 * m * m;
    let bound = CCW_ERRBOUND_A * sq8 + 1e-300;
    if sq8 <= 1e300 && bound >= FILTER_FLOOR {
        bound
    } else {
        f64::INFINITY
    }
}

/// The orientation sign when `|det| > bound` (the same `det` as [`orient_filtered`]).
#[inline(always)]
pub(crate) fn orient_static(a: Point2, b: Point2, c: Point2, bound: f64) -> i8 {
    let det = (b.x - a.x) * (c.y - a.y) - (b.y - a.y) * (c.x - a.x);
    if det > bound {
        1
    } else if -det > bound {
        -1
    } else {
        0
    }
}

/// [`quick_crossing`] with a [`static_orient_bound`] for the input tried first: one
/// comparison per orientation in the common case; the dynamic filter otherwise.
#[inline(always)]
pub(crate) fn quick_crossing_static(s: Segment2, t: Segment2, bound: f64) -> Option<bool> {
    let o1 = orient_static(s.a, s.b, t.a, bound);
    let o2 = orient_static(s.a, s.b, t.b, bound);
    if o1 != 0 && o1 == o2 {
        return Some(false);
    }
    if o1 != 0 && o2 != 0 {
        let o3 = orient_static(t.a, t.b, s.a, bound);
        let o4 = orient_static(t.a, t.b, s.b, bound);
        if o3 != 0 && o4 != 0 {
            return Some(o3 != o4);
        }
    }
    quick_crossing(s, t)
}

/// The exact intersection of the closed segments `s` and `t`.
///
/// Coordinates must be finite (non-finite input gives an unspecified answer, no panic).
///
/// ```
/// use compgeom::kernel::{segment_intersection, SegmentIntersection};
/// use compgeom::{Point2, Segment2};
/// let p = |x, y| Point2::new(x, y);
/// let s = Segment2::new(p(0.0, 0.0), p(4.0, 0.0));
/// let t = Segment2::new(p(2.0, 0.0), p(2.0, 5.0));
/// assert_eq!(segment_intersection(s, t), SegmentIntersection::Endpoint(p(2.0, 0.0)));
/// let u = Segment2::new(p(1.0, 0.0), p(9.0, 0.0));
/// assert_eq!(segment_intersection(s, u), SegmentIntersection::Overlap(p(1.0, 0.0), p(4.0, 0.0)));
/// ```
pub fn segment_intersection(s: Segment2, t: Segment2) -> SegmentIntersection {
    use SegmentIntersection as I;
    // The common case, decided by four filtered orientations: both ends of one segment
    // strictly on one side of the other's line, or a proper crossing.
    if let Some(found) = straddle_filter(s, t) {
        return found;
    }
    match (s.is_degenerate(), t.is_degenerate()) {
        (true, true) => {
            return if s.a == t.a {
                I::Endpoint(s.a)
            } else {
                I::None
            }
        }
        (true, false) => {
            return if contains(t, s.a) {
                I::Endpoint(s.a)
            } else {
                I::None
            }
        }
        (false, true) => {
            return if contains(s, t.a) {
                I::Endpoint(t.a)
            } else {
                I::None
            }
        }
        (false, false) => {}
    }
    let o1 = orient2d(s.a, s.b, t.a);
    let o2 = orient2d(s.a, s.b, t.b);
    if o1 == Orientation::Collinear && o2 == Orientation::Collinear {
        // All four points on one line: intersect the lexicographic ranges.
        let (s0, s1) = sorted(s);
        let (t0, t1) = sorted(t);
        let lo = if compare_xy(s0, t0) == Ordering::Less {
            t0
        } else {
            s0
        };
        let hi = if compare_xy(s1, t1) == Ordering::Greater {
            t1
        } else {
            s1
        };
        return match compare_xy(lo, hi) {
            Ordering::Greater => I::None,
            Ordering::Equal => I::Endpoint(lo),
            Ordering::Less => I::Overlap(lo, hi),
        };
    }
    let o3 = orient2d(t.a, t.b, s.a);
    let o4 = orient2d(t.a, t.b, s.b);
    if o1 == o2 || o3 == o4 {
        // Both ends of one segment strictly on one side of the other's line (equal
        // zero orientations on both would mean collinear, handled above).
        return I::None;
    }
    // The lines meet in exactly one point, which lies on both segments. If it is an
    // endpoint, one orientation is zero: report that input point.
    if o1 == Orientation::Collinear {
        I::Endpoint(t.a)
    } else if o2 == Orientation::Collinear {
        I::Endpoint(t.b)
    } else if o3 == Orientation::Collinear {
        I::Endpoint(s.a)
    } else if o4 == Orientation::Collinear {
        I::Endpoint(s.b)
    } else {
        match Crossing::new(s, t) {
            Some(c) => I::Crossing(c),
            // Unreachable for finite input (the segments straddle each other strictly,
            // so the lines are not parallel); kept total for non-finite input.
            None => I::None,
        }
    }
}

#[cfg(test)]
mod static_filter_tests {
    use super::*;

    /// The static filter answers as the dynamic one and the exact test, on random,
    /// grid, tiny and huge coordinates (each set with its own bound).
    #[test]
    fn static_filter_agrees_with_the_exact_test() {
        let mut next = crate::testing::bits(5u64);
        let mut decided = 0;
        for (k, scale) in [1.0, 1e-130, 1e140, 1e-160, 3e150].into_iter().enumerate() {
            for grid in [false, true] {
                let mut coord = || {
                    let v = next();
                    if grid {
                        (v % 7) as f64 * scale
                    } else {
                        v as f64 / (1u64 << 53) as f64 * scale
                    }
                };
                let pts: Vec<Point2> = (0..200).map(|_| Point2::new(coord(), coord())).collect();
                let m = pts
                    .iter()
                    .fold(0.0f64, |m, p| m.max(p.x.abs()).max(p.y.abs()));
                let bound = static_orient_bound(m);
                assert_eq!(bound.is_finite(), k < 3, "scale {scale}");
                for w in pts.windows(4) {
                    let (s, t) = (Segment2::new(w[0], w[1]), Segment2::new(w[2], w[3]));
                    let got = quick_crossing_static(s, t, bound);
                    assert_eq!(got, quick_crossing(s, t));
                    if let Some(cross) = got {
                        decided += 1;
                        let exact = segment_intersection(s, t);
                        assert_eq!(cross, matches!(exact, SegmentIntersection::Crossing(_)));
                        assert!(cross || exact == SegmentIntersection::None);
                    }
                }
            }
        }
        assert!(decided > 1000, "{decided}");
    }
}
