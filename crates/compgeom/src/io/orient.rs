//! The exact orientation of a polygon ring, used to write GeoJSON rings the way RFC 7946
//! asks (exteriors counter-clockwise, holes clockwise).

use crate::kernel::filter::{product_error, two_sum};
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
/// `f64` with a rigorous error bound; when the bound cannot certify the sign (slivers,
/// rings far from the origin), the sum is made exactly as a floating-point expansion
/// (each product split into two `f64` exactly, all added without error), and only where
/// a coordinate is too small or too large for that, in big integers (every `f64` is an
/// integer times a power of two). O(n) time; the expansion costs O(n · m) for m
/// components (a few as a rule; at most one per term, 4n), the big integers O(n · b)
/// for b-bit numbers, b ≤ about 4,100.
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
    if ring.len() < 3 {
        return Orientation::Collinear;
    }
    // (A certified sign needs every product finite, so every coordinate: the check for
    // non-finite ones only where the filter fails.)
    if let Some(sign) = filtered_sign(ring) {
        return sign;
    }
    if ring.iter().any(|p| !p.is_finite()) {
        return Orientation::Collinear;
    }
    expansion_sign(ring).unwrap_or_else(|| exact_sign(ring))
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
    // Each vertex with the one before, the first with the last (no division per
    // vertex). Every coordinate is in two products.
    let mut p = ring[n - 1];
    for &q in ring {
        let (a, b) = (p.x * q.y, q.x * p.y);
        sum += a - b;
        magnitude += a.abs() + b.abs();
        p = q;
    }
    // Each product, difference and addition rounds with relative error at most
    // u = EPSILON / 2, so |sum − exact| ≤ γ_{n+2} · magnitude with γ_k = k·u / (1 − k·u);
    // (n + 3)·EPSILON·magnitude bounds that for any n < 2⁵⁰. The absolute term covers
    // products that underflow (each loses at most one subnormal unit).
    let bound = (n as f64 + 3.0) * f64::EPSILON * magnitude + (n as f64) * f64::MIN_POSITIVE;
    (sum.is_finite() && bound.is_finite() && sum.abs() > bound)
        .then(|| orientation_of_sign(sum > 0.0, false))
}

/// Nonzero magnitudes in `[2⁻⁴⁸⁰, 2⁴⁸⁰]` keep [`expansion_sign`] exact: a product is at
/// least 2⁻⁹⁶⁰ with its lowest bit at least 2⁻¹⁰⁶⁴ (so its rounding error is an `f64`),
/// and no sum of up to 2⁶⁰ products of at most 2⁹⁶⁰ overflows.
const EXPANSION_RANGE: (f64, f64) = (1.0 / TWO_480, TWO_480);

/// 2⁴⁸⁰, exactly (2¹²⁰ is an exact `f64`, and so are its powers here).
const TWO_480: f64 = {
    let two_120 = (1u128 << 120) as f64;
    two_120 * two_120 * two_120 * two_120
};

/// The exact sign of the shoelace sum as a floating-point expansion (nonoverlapping
/// components by increasing magnitude, zeros left out; Shewchuk's grow-expansion):
/// every product is `p + err` exactly ([`product_error`]), and each of these is added
/// without error ([`two_sum`]). The sign is the largest component's. `None` when a
/// nonzero coordinate is outside [`EXPANSION_RANGE`].
fn expansion_sign(ring: &[Point2]) -> Option<Orientation> {
    let (lo, hi) = EXPANSION_RANGE;
    let fits = |v: f64| v == 0.0 || (v.abs() >= lo && v.abs() <= hi);
    if !ring.iter().all(|p| fits(p.x) && fits(p.y)) {
        return None;
    }
    let mut sum: Vec<f64> = Vec::new();
    let mut add = |b: f64| {
        if b == 0.0 {
            return;
        }
        let mut q = b;
        let mut kept = 0;
        for i in 0..sum.len() {
            let (s, err) = two_sum(q, sum[i]);
            q = s;
            if err != 0.0 {
                sum[kept] = err;
                kept += 1;
            }
        }
        sum.truncate(kept);
        if q != 0.0 {
            sum.push(q);
        }
    };
    let nexts = ring[1..].iter().chain(std::iter::once(&ring[0]));
    for (p, q) in ring.iter().zip(nexts) {
        for (u, v, sign) in [(p.x, q.y, 1.0), (q.x, p.y, -1.0)] {
            let product = u * v;
            add(sign * product);
            add(sign * product_error(u, v, product));
        }
    }
    let top = sum.last().copied().unwrap_or(0.0);
    Some(orientation_of_sign(top > 0.0, top == 0.0))
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

    /// A 4 × 3 rectangle, counter-clockwise.
    const RECTANGLE: [Point2; 4] = [
        Point2::new(0.0, 0.0),
        Point2::new(4.0, 0.0),
        Point2::new(4.0, 3.0),
        Point2::new(0.0, 3.0),
    ];

    #[test]
    fn exact_path_agrees_with_filter_on_plain_rings() {
        let ring = RECTANGLE;
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

    /// A ring with a NaN or infinite coordinate anywhere (first, middle or last vertex, x
    /// or y) has no orientation: a product with it is infinite or NaN, so the filter
    /// never certifies a sign, and the check after it answers.
    #[test]
    fn non_finite_rings_are_collinear() {
        for bad in [f64::NAN, f64::INFINITY, f64::NEG_INFINITY] {
            for at in 0..RECTANGLE.len() {
                for axis in 0..2 {
                    let mut ring = RECTANGLE;
                    if axis == 0 {
                        ring[at].x = bad;
                    } else {
                        ring[at].y = bad;
                    }
                    assert_eq!(ring_orientation(&ring), Orientation::Collinear, "{ring:?}");
                }
            }
        }
    }

    /// The expansion decides as the big integers do: slivers and collinear runs near and
    /// far from the origin (the filter fails on them), integer grids, random rings, and
    /// runs with x and y of very different sizes, at scales 2⁻⁴⁵⁰ … 2⁴⁵⁰ (products past
    /// 10^±250 take `product_error`'s fused path); rings at the ends of its range; outside
    /// it, it declines.
    #[test]
    fn expansion_agrees_with_big_integers() {
        assert_eq!(EXPANSION_RANGE.0, 2f64.powi(-480));
        assert_eq!(EXPANSION_RANGE.1, 2f64.powi(480));
        let mut unit = crate::testing::units(0x5eed_0fa1_e4a1_u64);
        let (mut decided, mut unfiltered, mut fused) = ([0usize; 3], 0, 0);
        for round in 0..5000 {
            let n = 3 + round % 7;
            let scale = 2f64.powi((round % 61) * 15 - 450);
            let far = if (round / 5) % 2 == 0 {
                1e6 * scale
            } else {
                0.0
            };
            let ring: Vec<Point2> = (0..n)
                .map(|k| match round % 5 {
                    // Integer grid.
                    0 => Point2::new((unit() * 5.0).floor(), (unit() * 5.0).floor()),
                    // On a line y = x, an ulp off here and there.
                    1 => {
                        let t = far + (1.0 + (unit() * 8.0).floor()) * scale;
                        let y = if k % 3 == 0 { t.next_up() } else { t };
                        Point2::new(t, y)
                    }
                    // A sliver: two nearly equal paths.
                    2 => {
                        let t = far + (k + 1) as f64 * scale;
                        Point2::new(t, t + unit() * f64::EPSILON * t)
                    }
                    // On a line through the origin, x huge and y tiny, an ulp off.
                    3 => {
                        let t = (1 + k % 4) as f64;
                        let y = t * 2f64.powi(-470);
                        Point2::new(t * 2f64.powi(470), if k == 1 { y.next_up() } else { y })
                    }
                    _ => Point2::new(scale * (1.0 + unit()), scale * (1.0 + unit())),
                })
                .collect();
            let want = exact_sign(&ring);
            let got = expansion_sign(&ring).expect("in range");
            assert_eq!(got, want, "round {round}: {ring:?}");
            assert_eq!(ring_orientation(&ring), want);
            let k = match want {
                Orientation::CounterClockwise => 0,
                Orientation::Clockwise => 1,
                Orientation::Collinear => 2,
            };
            decided[k] += 1;
            unfiltered += usize::from(filtered_sign(&ring).is_none());
            let outside = |v: f64| v != 0.0 && !(1e-250..1e250).contains(&v.abs());
            fused += usize::from(ring.iter().any(|p| outside(p.x * p.y)));
        }
        // The ends of the range, and x and y at opposite ends.
        let (lo, hi) = EXPANSION_RANGE;
        for ring in [
            [(lo, lo), (hi, lo), (lo, hi)],
            [(lo, lo.next_up()), (lo.next_up(), lo), (hi, hi)],
            [(hi, lo), (hi.next_down(), lo.next_up()), (lo, hi)],
            [(lo, 0.0), (0.0, lo), (-lo, -lo)],
        ] {
            let ring: Vec<Point2> = ring.iter().map(|&(x, y)| Point2::new(x, y)).collect();
            assert_eq!(expansion_sign(&ring), Some(exact_sign(&ring)), "{ring:?}");
        }
        assert!(fused > 200, "{fused}");
        // Every answer occurs, and most rings need more than the filter.
        assert!(
            decided[0] > 100 && decided[1] > 100 && decided[2] > 10,
            "{decided:?}"
        );
        assert!(unfiltered > 1000, "{unfiltered}");
        let tiny = [
            Point2::new(0.0, 0.0),
            Point2::new(1e-300, 0.0),
            Point2::new(0.0, 1.0),
        ];
        assert_eq!(expansion_sign(&tiny), None);
        let huge = [
            Point2::new(0.0, 0.0),
            Point2::new(1e300, 0.0),
            Point2::new(0.0, 1.0),
        ];
        assert_eq!(expansion_sign(&huge), None);
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
