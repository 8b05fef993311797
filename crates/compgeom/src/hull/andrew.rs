//! Andrew's monotone chain: the book's CONVEXHULL (§1.1).
//!
//! Sort the points lexicographically (x, then y), walk left to right keeping the upper hull
//! as a stack whose last three points must make a right turn, then walk right to left for the
//! lower hull. Every turn is decided by the exact [`orient2d`]; a collinear triple counts as
//! "not a right turn", so its middle point is removed (or, with `keep_collinear`, kept).
//! O(n log n) for the sort, O(n) for the two walks.

use super::sort::sort_lex;
use crate::kernel::{orient2d, Orientation, Point2};

/// Sort `points` lexicographically and drop repeated points (exact comparisons; `-0.0` and
/// `0.0` are the same coordinate).
pub(crate) fn sort_dedup(points: &mut Vec<Point2>) {
    sort_lex(points);
    points.dedup_by(|a, b| a == b);
}

/// True when the chain `stack + [p]` must drop its last point: the last three points do not
/// make a right turn (strict hull), or make a left turn (`keep_collinear`).
#[inline(always)]
fn must_pop(a: Point2, b: Point2, p: Point2, keep_collinear: bool) -> bool {
    match orient2d(a, b, p) {
        Orientation::Clockwise => false,
        Orientation::Collinear => !keep_collinear,
        Orientation::CounterClockwise => true,
    }
}

/// Push `p` onto a hull chain, first popping the points it makes redundant; `floor` is the
/// number of points at the bottom of `chain` that belong to an earlier chain and stay.
#[inline(always)]
fn push_point(chain: &mut Vec<Point2>, floor: usize, p: Point2, keep_collinear: bool) {
    while chain.len() >= floor + 2 {
        let n = chain.len();
        if must_pop(chain[n - 2], chain[n - 1], p, keep_collinear) {
            chain.pop();
        } else {
            break;
        }
    }
    chain.push(p);
}

/// The hull of lexicographically sorted, pairwise distinct points, clockwise from the first.
///
/// All points on one line give the two extreme points (or, with `keep_collinear`, every
/// point, in sorted order).
pub(crate) fn monotone_chain(sorted: &[Point2], keep_collinear: bool) -> Vec<Point2> {
    let n = sorted.len();
    if n <= 2 {
        return sorted.to_vec();
    }
    let mut hull: Vec<Point2> = Vec::with_capacity(64.min(n));
    // Upper hull, left to right: a clockwise chain from the first to the last point.
    for &p in sorted {
        push_point(&mut hull, 0, p, keep_collinear);
    }
    let upper_len = hull.len();
    // Lower hull, right to left; it starts at the last point (already in `hull`), so the
    // points of the upper chain below it are never popped.
    for &p in sorted[..n - 1].iter().rev() {
        push_point(&mut hull, upper_len - 1, p, keep_collinear);
    }
    // The walk ends where it started.
    hull.pop();
    if keep_collinear && is_flat(&hull) {
        // All points on one line: both walks listed every point, once in each direction.
        hull.truncate(upper_len);
    }
    hull
}

/// True when all points of `chain` lie on one line (the hull has no area).
fn is_flat(chain: &[Point2]) -> bool {
    let a = chain[0];
    let Some(&b) = chain.iter().find(|&&p| p != a) else {
        return true;
    };
    chain
        .iter()
        .all(|&p| orient2d(a, b, p) == Orientation::Collinear)
}

/// The hull of arbitrary finite points by the monotone chain (copies and sorts them).
pub(crate) fn andrew(points: &[Point2], keep_collinear: bool) -> Vec<Point2> {
    let mut sorted = points.to_vec();
    sort_dedup(&mut sorted);
    monotone_chain(&sorted, keep_collinear)
}
