//! Exact comparisons of squared Euclidean distances, for nearest-neighbour and radius
//! queries.
//!
//! `|a - q|^2` is computed in `f64` first; when both values lie in the normal range the
//! rounding error is below 5 units in the last place (two subtractions, two squares, one
//! sum), so a relative gap of `1e-15` decides the comparison. Otherwise (near-ties, values
//! that underflow or overflow) both sides are evaluated exactly with big rationals, into
//! which every `f64` converts exactly.

use crate::Point2;
use num_rational::BigRational;
use num_traits::FromPrimitive;
use std::cmp::Ordering;

/// Relative error bound used by the filter (five half-ulps is about `5.6e-16`).
const EPS: f64 = 1e-15;
/// Below this the relative bound could fail through underflow.
const TINY: f64 = 1e-290;
/// Above this an intermediate could overflow.
const HUGE: f64 = 1e290;

/// The rounded squared distance (for filtering and pruning only).
#[inline]
pub(crate) fn dist2(a: Point2, q: Point2) -> f64 {
    let dx = a.x - q.x;
    let dy = a.y - q.y;
    dx * dx + dy * dy
}

fn rat(x: f64) -> BigRational {
    // Finite input only (checked by the structures): the conversion is exact.
    BigRational::from_f64(x).unwrap_or_default()
}

fn exact_dist2(a: Point2, q: Point2) -> BigRational {
    let dx = rat(a.x) - rat(q.x);
    let dy = rat(a.y) - rat(q.y);
    &dx * &dx + &dy * &dy
}

/// The order of two rounded squared distances when the rounding cannot change it.
#[inline]
pub(crate) fn filtered(da: f64, db: f64) -> Option<Ordering> {
    let ok = |d: f64| (TINY..=HUGE).contains(&d);
    if !(ok(da) && ok(db)) {
        return None;
    }
    if da * (1.0 + EPS) < db * (1.0 - EPS) {
        Some(Ordering::Less)
    } else if db * (1.0 + EPS) < da * (1.0 - EPS) {
        Some(Ordering::Greater)
    } else {
        None
    }
}

/// `|a - q|^2` against `|b - q|^2`, exactly.
pub fn compare_distance(q: Point2, a: Point2, b: Point2) -> Ordering {
    if a == b {
        return Ordering::Equal;
    }
    filtered(dist2(a, q), dist2(b, q)).unwrap_or_else(|| exact_dist2(a, q).cmp(&exact_dist2(b, q)))
}

/// `|a - q|^2` against `r^2`, exactly (`r` is taken as `|r|`).
pub fn compare_distance_to_radius(q: Point2, a: Point2, r: f64) -> Ordering {
    if a == q {
        return 0.0f64.partial_cmp(&r.abs()).unwrap_or(Ordering::Equal);
    }
    filtered(dist2(a, q), r * r).unwrap_or_else(|| {
        let rr = rat(r);
        exact_dist2(a, q).cmp(&(&rr * &rr))
    })
}

/// Bounds `(lo, hi)` on the exact squared distance whose rounded value [`dist2`] gave `d2`.
/// Finite: the relative bound plus an absolute term for underflow. Infinite (an operation
/// overflowed): the exact value is still at least about `f64::MAX`.
#[inline]
pub(crate) fn dist2_bounds(d2: f64) -> (f64, f64) {
    if d2.is_finite() {
        (d2 * (1.0 - EPS) - TINY, d2 * (1.0 + EPS) + TINY)
    } else {
        (f64::MAX * (1.0 - EPS), f64::INFINITY)
    }
}

/// A bound on rounded squared distances (from [`dist2`]) such that a point whose rounded
/// value exceeds it is farther, exactly, than anything whose upper bound
/// ([`dist2_bounds`]) is `hi`: its lower bound exceeds `hi`.
#[inline]
pub(crate) fn prune_bound(hi: f64) -> f64 {
    (hi + TINY) * (1.0 + 3.0 * EPS)
}

/// A lower bound of the squared distance from `q` to the closed box
/// `[minx, maxx] x [miny, maxy]`, safe under rounding (for pruning).
#[inline]
pub(crate) fn box_dist2_lower(q: Point2, minx: f64, miny: f64, maxx: f64, maxy: f64) -> f64 {
    let dx = (minx - q.x).max(q.x - maxx).max(0.0);
    let dy = (miny - q.y).max(q.y - maxy).max(0.0);
    dist2_lower(dx, dy)
}

/// A lower bound of `dx^2 + dy^2`, safe under rounding, where `dx` and `dy` are rounded
/// differences of coordinates (each within half an ulp of the exact difference, since
/// rounding is monotone and the exact difference is what it rounds).
#[inline]
pub(crate) fn dist2_lower(dx: f64, dy: f64) -> f64 {
    (dx * dx + dy * dy) * (1.0 - 4.0 * EPS) - 4.0 * TINY
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn near_ties_are_decided_exactly() {
        let q = Point2::new(0.0, 0.0);
        // 0.1 + 0.2 style near-tie: (1e8+1)^2 vs (1e8)^2 + (2e4+...)... use representable values
        let a = Point2::new(3.0, 4.0);
        let b = Point2::new(5.0, 0.0);
        assert_eq!(compare_distance(q, a, b), Ordering::Equal);
        let c = Point2::new(5.0, f64::MIN_POSITIVE);
        assert_eq!(compare_distance(q, a, c), Ordering::Less);
        let t = Point2::new(1e-200, 0.0);
        let u = Point2::new(0.0, 1e-200);
        assert_eq!(compare_distance(q, t, u), Ordering::Equal);
        assert_eq!(compare_distance_to_radius(q, a, 5.0), Ordering::Equal);
        assert_eq!(
            compare_distance_to_radius(q, a, 5.0 - 1e-15),
            Ordering::Greater
        );
        let big = Point2::new(1e300, 1e300);
        assert_eq!(
            compare_distance(q, big, Point2::new(-1e300, 1e300)),
            Ordering::Equal
        );
        assert_eq!(
            compare_distance(q, big, Point2::new(1e300, 0.0)),
            Ordering::Greater
        );
    }
}
