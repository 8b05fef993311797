//! Areas of rings and polygons: in `f64` (the shoelace formula) and exactly.

use super::arith::Arith;
use super::exact::Dyadic;
use super::types::{MultiPolygon, Point2, Polygon};
use num_rational::BigRational;
use num_traits::{Signed, ToPrimitive, Zero};

/// Signed area of a ring (positive when counter-clockwise), in `f64`: the shoelace
/// formula relative to the ring's first vertex (no cancellation against large absolute
/// coordinates). Infinite when the area is beyond the `f64` range; NaN only for
/// non-finite coordinates. O(n).
pub fn ring_area(ring: &[Point2]) -> f64 {
    let area = ring_area_scaled(ring, 1.0);
    if area.is_finite() || !ring.iter().all(|p| p.is_finite()) {
        return area;
    }
    // Finite coordinates more than the f64 range apart (their differences overflowed),
    // or products beyond it: the exact area, rounded (rare, so the big numbers' cost
    // does not matter).
    let half = ring_area2_exact(ring) / BigRational::from_integer(2.into());
    half.to_f64().unwrap_or(if half.is_negative() {
        f64::NEG_INFINITY
    } else {
        f64::INFINITY
    })
}

/// Signed area of the ring shrunk by the factor `scale` (coordinates divided by it): with
/// a power-of-two `scale` this avoids overflow for huge coordinates.
pub(crate) fn ring_area_scaled(ring: &[Point2], scale: f64) -> f64 {
    let k = ring.len();
    let Some(&o) = ring.first() else {
        return 0.0;
    };
    let mut s = 0.0;
    for i in 0..k {
        let (a, b) = (ring[i], ring[(i + 1) % k]);
        let (ax, ay) = ((a.x - o.x) / scale, (a.y - o.y) / scale);
        let (bx, by) = ((b.x - o.x) / scale, (b.y - o.y) / scale);
        s += ax * by - ay * bx;
    }
    s / 2.0
}

/// Twice the signed area of a ring, exactly (every product of two `f64`s and their sum
/// is a dyadic rational), for finite coordinates (a NaN or infinite one counts as 0).
/// O(n) big-number operations.
pub fn ring_area2_exact(ring: &[Point2]) -> BigRational {
    let k = ring.len();
    let mut s = Dyadic::zero();
    for i in 0..k {
        let (a, b) = (ring[i], ring[(i + 1) % k]);
        let cross = Dyadic::val(a.x)
            .times(&Dyadic::val(b.y))
            .minus(&Dyadic::val(b.x).times(&Dyadic::val(a.y)));
        s = s.plus(&cross);
    }
    s.to_rational()
}

impl Polygon {
    /// The area: the exterior ring's minus the holes', whatever the rings' orientations
    /// (as in a valid polygon, holes inside the exterior and apart). `f64`, by
    /// [`ring_area`] (infinite beyond the `f64` range, NaN only for non-finite
    /// coordinates). O(n).
    ///
    /// ```
    /// use compgeom::{Point2, Polygon};
    /// let p = |x, y| Point2::new(x, y);
    /// let square = vec![p(0.0, 0.0), p(4.0, 0.0), p(4.0, 4.0), p(0.0, 4.0)];
    /// let hole = vec![p(1.0, 1.0), p(2.0, 1.0), p(2.0, 2.0), p(1.0, 2.0)];
    /// assert_eq!(Polygon::new(square, vec![hole]).area(), 15.0);
    /// ```
    pub fn area(&self) -> f64 {
        let holes: f64 = self.holes.iter().map(|h| ring_area(h).abs()).sum();
        ring_area(&self.exterior).abs() - holes
    }

    /// Twice [`Polygon::area`], exactly ([`ring_area2_exact`]: finite coordinates). O(n)
    /// big-number operations.
    pub fn area2_exact(&self) -> BigRational {
        self.holes
            .iter()
            .fold(ring_area2_exact(&self.exterior).abs(), |a, h| {
                a - ring_area2_exact(h).abs()
            })
    }
}

impl MultiPolygon {
    /// The sum of the polygons' areas ([`Polygon::area`]; the area of the region when the
    /// polygons do not overlap, as in a valid set). O(n).
    ///
    /// ```
    /// use compgeom::overlay::{boolean, BooleanOp};
    /// use compgeom::{MultiPolygon, Point2, Polygon};
    /// let square = |x: f64| MultiPolygon(vec![Polygon::new(vec![Point2::new(x, 0.0),
    ///     Point2::new(x + 2.0, 0.0), Point2::new(x + 2.0, 2.0), Point2::new(x, 2.0)], vec![])]);
    /// let union = boolean(&square(0.0), &square(1.0), BooleanOp::Union).unwrap();
    /// assert_eq!(union.area(), 6.0);
    /// ```
    pub fn area(&self) -> f64 {
        self.0.iter().map(Polygon::area).sum()
    }

    /// Twice [`MultiPolygon::area`], exactly. O(n) big-number operations.
    pub fn area2_exact(&self) -> BigRational {
        self.0
            .iter()
            .fold(BigRational::zero(), |a, p| a + p.area2_exact())
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn p(x: f64, y: f64) -> Point2 {
        Point2::new(x, y)
    }

    #[test]
    fn holes_and_orientation() {
        let square = vec![p(0.0, 0.0), p(4.0, 0.0), p(4.0, 4.0), p(0.0, 4.0)];
        let clockwise: Vec<Point2> = square.iter().rev().copied().collect();
        let hole = vec![p(1.0, 1.0), p(1.0, 3.0), p(3.0, 3.0), p(3.0, 1.0)];
        for outer in [&square, &clockwise] {
            let poly = Polygon::new(outer.clone(), vec![hole.clone()]);
            assert_eq!(poly.area(), 12.0);
            assert_eq!(poly.area2_exact(), BigRational::from_integer(24.into()));
        }
        let far = Polygon::new(square.iter().map(|q| p(q.x + 1e9, q.y)).collect(), vec![]);
        let set = MultiPolygon(vec![far, Polygon::new(square.clone(), vec![hole])]);
        assert_eq!(set.area(), 28.0);
        assert_eq!(set.area2_exact(), BigRational::from_integer(56.into()));
        assert_eq!(MultiPolygon::default().area(), 0.0);
    }

    #[test]
    fn areas_beyond_the_range_are_infinite_not_nan() {
        let huge = [p(-1e308, 0.0), p(1e308, 0.0), p(0.0, 1e308)];
        assert_eq!(ring_area(&huge), f64::INFINITY);
        // More than the range apart in x, thin in y: a finite area (2e308 · 1e-300 / 2).
        let thin = [p(-1e308, 0.0), p(1e308, 0.0), p(1e308, 1e-300)];
        let got = ring_area(&thin);
        assert!((got - 1e8).abs() <= 1e-7, "{got}");
        // Flat along the diagonal: huge terms that cancel exactly.
        let diagonal = [p(-1e308, -1e308), p(1e308, 1e308), p(0.0, 0.0)];
        assert_eq!(ring_area(&diagonal), 0.0);
        let clockwise: Vec<Point2> = huge.iter().rev().copied().collect();
        assert_eq!(ring_area(&clockwise), f64::NEG_INFINITY);
        assert!(ring_area(&[p(f64::NAN, 0.0), p(1.0, 0.0), p(0.0, 1.0)]).is_nan());
    }
}
