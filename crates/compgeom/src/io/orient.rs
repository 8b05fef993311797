//! The exact orientation of a polygon ring, used to write GeoJSON rings the way RFC 7946
//! asks (exteriors counter-clockwise, holes clockwise).

use crate::kernel::{Orientation, Point2};
use num_bigint::BigInt;
use num_traits::{Float, Signed, Zero};

/// The orientation of the closed ring through `ring` (open or closed: a repeated closing
/// vertex changes nothing): the sign of its signed area, computed exactly.
///
/// `CounterClockwise` for positive area, `Clockwise` for negative, `Collinear` for zero
/// area (fewer than 3 distinct vertices, all vertices on a line, or a self-crossing ring
/// whose lobes cancel) and for rings with a non-finite coordinate.
///
/// The signed area is the shoelace sum Σ (xᵢ·yᵢ₊₁ − xᵢ₊₁·yᵢ) / 2. It is first summed in
/// `f64` with a rigorous error bound; when the bound cannot certify the sign, the sum is
/// recomputed exactly in big integers (every `f64` is an integer times a power of two).
/// O(n) time; the exact path costs O(n · b) for b-bit numbers, b ≤ about 4,100.
///
/// ```
/// use compgeom::io::ring_orientation;
/// use compgeom::{Orientation, Point2};
/// let tri = [Point2::new(0.0, 0.0), Point2::new(1.0, 0.0), Point2::new(0.0, 1.0)];
/// assert_eq!(ring_orientation(&tri), Orientation::CounterClockwise);
/// // A sliver far from the origin: the float area is pure rounding noise; the exact one is not.
/// let sliver = [Point2::new(1e15, 1e15), Point2::new(1e15 + 2.0, 1e15 + 2.0),
///               Point2::new(1e15 + 1.0, 1e15 + 1.0 + 0.125)];
/// assert_eq!(ring_orientation(&sliver), Orientation::CounterClockwise);
/// ```
pub fn ring_orientation(ring: &[Point2]) -> Orientation {
    let n = ring.len();
    if n < 3 || ring.iter().any(|p| !p.is_finite()) {
        return Orientation::Collinear;
    }
    if let Some(sign) = filtered_sign(ring) {
        return sign;
    }
    exact_sign(ring)
}

fn orientation_of_sign(positive: bool, zero: bool) -> Orientation {
    if zero {
        Orientation::Collinear
    } else if positive {
        Orientation::CounterClockwise
    } else {
        Orientation::Clockwise
    }
}

/// The sign from an `f64` shoelace sum, when its error bound certifies it.
fn filtered_sign(ring: &[Point2]) -> Option<Orientation> {
    let n = ring.len();
    let mut sum = 0.0f64;
    let mut magnitude = 0.0f64;
    // Each vertex with the next, the last with the first (no division per vertex).
    let nexts = ring[1..].iter().chain(std::iter::once(&ring[0]));
    for (p, q) in ring.iter().zip(nexts) {
        let (a, b) = (p.x * q.y, q.x * p.y);
        sum += a - b;
        magnitude += a.abs() + b.abs();
    }
    // Each product, difference and addition rounds with relative error at most
    // u = EPSILON / 2, so |sum − exact| ≤ γ_{n+2} · magnitude with γ_k = k·u / (1 − k·u);
    // (n + 3)·EPSILON·magnitude bounds that for any n < 2⁵⁰. The absolute term covers
    // products that underflow (each loses at most one subnormal unit).
    let bound = (n as f64 + 3.0) * f64::EPSILON * magnitude + (n as f64) * f64::MIN_POSITIVE;
    (sum.is_finite() && bound.is_finite() && sum.abs() > bound)
        .then(|| orientation_of_sign(sum > 0.0, false))
}

/// `x` as `(m, e)` with `x = m · 2^e` exactly.
fn decompose(x: f64) -> (BigInt, i32) {
    let (mantissa, exponent, sign) = x.integer_decode();
    (
        BigInt::from(sign) * BigInt::from(mantissa),
        i32::from(exponent),
    )
}

/// The exact sign of the shoelace sum, in big integers.
fn exact_sign(ring: &[Point2]) -> Orientation {
    let n = ring.len();
    let mut terms: Vec<(BigInt, i32)> = Vec::with_capacity(2 * n);
    for (i, p) in ring.iter().enumerate() {
        let q = ring[(i + 1) % n];
        for (u, v, negate) in [(p.x, q.y, false), (q.x, p.y, true)] {
            let ((mu, eu), (mv, ev)) = (decompose(u), decompose(v));
            let m = mu * mv;
            if !m.is_zero() {
                terms.push((if negate { -m } else { m }, eu + ev));
            }
        }
    }
    let Some(min_exp) = terms.iter().map(|t| t.1).min() else {
        return Orientation::Collinear;
    };
    let mut total = BigInt::zero();
    for (m, e) in terms {
        // e − min_exp ≤ about 4,100: the shift is bounded.
        total += m << ((e - min_exp) as usize);
    }
    orientation_of_sign(total.is_positive(), total.is_zero())
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn exact_path_agrees_with_filter_on_plain_rings() {
        let ring = [
            Point2::new(0.0, 0.0),
            Point2::new(4.0, 0.0),
            Point2::new(4.0, 3.0),
            Point2::new(0.0, 3.0),
        ];
        assert_eq!(exact_sign(&ring), Orientation::CounterClockwise);
        assert_eq!(filtered_sign(&ring), Some(Orientation::CounterClockwise));
        let rev: Vec<Point2> = ring.iter().rev().copied().collect();
        assert_eq!(exact_sign(&rev), Orientation::Clockwise);
    }

    #[test]
    fn zero_area_rings_are_collinear() {
        let line = [
            Point2::new(0.0, 0.0),
            Point2::new(1.0, 1.0),
            Point2::new(3.0, 3.0),
        ];
        assert_eq!(ring_orientation(&line), Orientation::Collinear);
        // A figure eight whose lobes cancel.
        let eight = [
            Point2::new(0.0, 0.0),
            Point2::new(1.0, 1.0),
            Point2::new(1.0, 0.0),
            Point2::new(0.0, 1.0),
        ];
        assert_eq!(ring_orientation(&eight), Orientation::Collinear);
    }

    #[test]
    fn tiny_and_huge_coordinates() {
        let tiny = [
            Point2::new(0.0, 0.0),
            Point2::new(5e-324, 0.0),
            Point2::new(0.0, 5e-324),
        ];
        // The float products underflow to zero; the exact area is 2^-2149 > 0.
        assert_eq!(ring_orientation(&tiny), Orientation::CounterClockwise);
        let huge = [
            Point2::new(0.0, 0.0),
            Point2::new(0.0, 1e300),
            Point2::new(1e300, 0.0),
        ];
        // The float products overflow; the exact sign is still clockwise.
        assert_eq!(ring_orientation(&huge), Orientation::Clockwise);
    }
}
