//! The sweep order of the book (§2.1): the sweep line is horizontal and moves down, so
//! point `p` comes before `q` when `p.y > q.y`, or `p.y = q.y` and `p.x < q.x`. A
//! segment's *upper* endpoint is the one that comes first in this order (for a
//! horizontal segment, the left one).
//!
//! Event points are input points or constructed crossings. A crossing carries a small
//! box that surely contains it, from plain `f64` arithmetic with a rigorous error bound:
//! when two boxes are disjoint in y they decide the y order exactly; only when they
//! overlap does the kernel's exact comparison run (likewise for x, looked at only when
//! the exact y values are equal). The nearest `f64` point (the kernel's correctly rounded
//! `approx`) is computed only for points that are reported.

use super::small_int;
use crate::kernel::{Crossing, ExactPoint, Point2, Segment2};
use std::cmp::Ordering;

/// An event point with a cheap enclosing box of its exact position (a point box for an
/// input point); ordered in sweep order, exactly.
#[derive(Debug, Clone, Copy)]
pub(crate) struct EventPoint {
    /// The exact point.
    pub exact: ExactPoint,
    /// A floating-point estimate of the point (the point itself for an input point).
    pub mid: Point2,
    /// Half-widths of a box around `mid` that surely contains the exact point; they
    /// also absorb the rounding of `mid ± rad`.
    pub rad: Point2,
}

const U: f64 = 1.1102230246251565e-16; // 2^-53, the unit roundoff

/// An estimate of a crossing's coordinates with a rigorous error bound, in plain `f64`
/// arithmetic: `x = a.x + dx·num/den` (see [`crate::kernel::Crossing`]). Each difference
/// of inputs carries a relative error of at most `u`, each product of two at most `3u`
/// (first order), each sum or difference of two products at most `4u` of the sum of
/// their magnitudes; the bound below doubles every first-order term to cover the
/// higher-order ones. `None` when the denominator's sign is uncertain or a value is not
/// finite.
fn crossing_box(c: &Crossing) -> Option<(Point2, Point2)> {
    let (t, e_t) = crossing_param(c)?;
    let s = c.s;
    let (x, rx) = box_coord(s.a.x, s.b.x - s.a.x, t, e_t);
    let (y, ry) = box_coord(s.a.y, s.b.y - s.a.y, t, e_t);
    let all = [x, y, rx, ry];
    all.iter()
        .all(|v| v.is_finite())
        .then_some((Point2::new(x, y), Point2::new(rx, ry)))
}

/// The parameter `t` of the crossing along `c.s` and a bound on its error (see
/// [`crossing_box`]).
#[inline(always)]
fn crossing_param(c: &Crossing) -> Option<(f64, f64)> {
    let (s, t) = (c.s, c.t);
    let (dx, dy) = (s.b.x - s.a.x, s.b.y - s.a.y);
    let (ex, ey) = (t.b.x - t.a.x, t.b.y - t.a.y);
    let (wx, wy) = (t.a.x - s.a.x, t.a.y - s.a.y);
    let (d1, d2) = (dx * ey, dy * ex);
    let (n1, n2) = (wx * ey, wy * ex);
    let (den, num) = (d1 - d2, n1 - n2);
    let e_den = 10.0 * U * (d1.abs() + d2.abs());
    let e_num = 10.0 * U * (n1.abs() + n2.abs());
    // (NaN fails the comparison too.)
    if den.abs().partial_cmp(&(2.0 * e_den)) != Some(Ordering::Greater) {
        return None;
    }
    let t = num / den;
    // |T - t| for the exact parameter T = N / D.
    let e_t = 2.0 * (e_num + t.abs() * e_den) / (den.abs() - e_den) + 2.0 * U * t.abs();
    Some((t, e_t))
}

/// One coordinate `a + d·t` of the crossing box and its half-width.
#[inline(always)]
fn box_coord(a: f64, d: f64, t: f64, e_t: f64) -> (f64, f64) {
    let v = a + d * t;
    let err = 2.0 * (d.abs() * e_t + 4.0 * U * (d * t).abs()) + 8.0 * U * v.abs() + 1e-300;
    (v, err)
}

/// An interval `[lo, hi]` that surely holds the y of the crossing: the y-extent of its
/// [`EventPoint`] box, computed alone (the whole line when there is no usable box).
#[inline]
pub(crate) fn crossing_y_interval(c: &Crossing) -> (f64, f64) {
    crossing_interval(c, 1)
}

/// [`crossing_y_interval`] for the coordinate `axis` (0: x, 1: y).
#[inline]
pub(crate) fn crossing_interval(c: &Crossing, axis: usize) -> (f64, f64) {
    if let Some((t, e_t)) = crossing_param(c) {
        let (a, b) = if axis == 0 {
            (c.s.a.x, c.s.b.x)
        } else {
            (c.s.a.y, c.s.b.y)
        };
        let (y, ry) = box_coord(a, b - a, t, e_t);
        let (lo, hi) = (y - ry, y + ry);
        if lo.is_finite() && hi.is_finite() {
            return (lo, hi);
        }
    }
    (f64::NEG_INFINITY, f64::INFINITY)
}

impl EventPoint {
    /// An input point.
    pub fn input(p: Point2) -> Self {
        EventPoint {
            exact: ExactPoint::Input(p),
            mid: p,
            rad: Point2::new(0.0, 0.0),
        }
    }

    /// Any exact point.
    pub fn new(exact: ExactPoint) -> Self {
        match exact {
            ExactPoint::Input(p) => EventPoint::input(p),
            ExactPoint::Crossing(c) => {
                let (mid, rad) = crossing_box(&c).unwrap_or((
                    Point2::new(0.0, 0.0),
                    Point2::new(f64::INFINITY, f64::INFINITY),
                ));
                EventPoint { exact, mid, rad }
            }
        }
    }

    /// The input point, if this is one.
    pub fn as_input(&self) -> Option<Point2> {
        match self.exact {
            ExactPoint::Input(p) => Some(p),
            ExactPoint::Crossing(_) => None,
        }
    }

    /// The nearest `f64` point (correctly rounded; computed on demand for a crossing).
    pub fn approx(&self) -> Point2 {
        self.exact.approx()
    }

    /// The sign of `x - v` (exact).
    pub fn compare_x_with(&self, v: f64) -> Ordering {
        if self.mid.x + self.rad.x < v {
            Ordering::Less
        } else if self.mid.x - self.rad.x > v {
            Ordering::Greater
        } else {
            let q = ExactPoint::Input(Point2::new(v, 0.0));
            small_int::compare_coord(&self.exact, &q, 0).unwrap_or_else(|| self.exact.compare_x(&q))
        }
    }
}

/// Compare one coordinate of two boxes: decided when they are disjoint, else `exact()`.
fn by_box(a: f64, ra: f64, b: f64, rb: f64, exact: impl FnOnce() -> Ordering) -> Ordering {
    if a + ra < b - rb {
        Ordering::Less
    } else if a - ra > b + rb {
        Ordering::Greater
    } else {
        exact()
    }
}

/// Sweep order of two `f64` points: y decreasing, then x increasing.
pub(crate) fn sweep_cmp_points(a: Point2, b: Point2) -> Ordering {
    // partial_cmp, not total_cmp: -0.0 and 0.0 are the same coordinate. Inputs are finite.
    let by_y = b.y.partial_cmp(&a.y).unwrap_or(Ordering::Equal);
    by_y.then(a.x.partial_cmp(&b.x).unwrap_or(Ordering::Equal))
}

impl Ord for EventPoint {
    fn cmp(&self, other: &Self) -> Ordering {
        let inputs = matches!(
            (self.exact, other.exact),
            (ExactPoint::Input(_), ExactPoint::Input(_))
        );
        if inputs {
            return sweep_cmp_points(self.mid, other.mid);
        }
        let (a, b) = (self, other);
        let exact_y = || {
            small_int::compare_coord(&b.exact, &a.exact, 1)
                .unwrap_or_else(|| b.exact.compare_y(&a.exact))
        };
        let exact_x = || {
            small_int::compare_coord(&a.exact, &b.exact, 0)
                .unwrap_or_else(|| a.exact.compare_x(&b.exact))
        };
        by_box(b.mid.y, b.rad.y, a.mid.y, a.rad.y, exact_y)
            .then_with(|| by_box(a.mid.x, a.rad.x, b.mid.x, b.rad.x, exact_x))
    }
}

impl PartialOrd for EventPoint {
    fn partial_cmp(&self, other: &Self) -> Option<Ordering> {
        Some(self.cmp(other))
    }
}

impl PartialEq for EventPoint {
    fn eq(&self, other: &Self) -> bool {
        self.cmp(other) == Ordering::Equal
    }
}

impl Eq for EventPoint {}

/// A segment with its endpoints in sweep order: `upper` first.
#[derive(Debug, Clone, Copy, PartialEq)]
pub(crate) struct Oriented {
    /// The endpoint met first by the sweep (higher, or left when horizontal).
    pub upper: Point2,
    /// The other endpoint.
    pub lower: Point2,
}

impl Oriented {
    /// `s` with its endpoints in sweep order.
    pub fn of(s: Segment2) -> Self {
        if sweep_cmp_points(s.a, s.b) == Ordering::Greater {
            Oriented {
                upper: s.b,
                lower: s.a,
            }
        } else {
            Oriented {
                upper: s.a,
                lower: s.b,
            }
        }
    }

    /// The segment from `upper` to `lower`.
    pub fn segment(&self) -> Segment2 {
        Segment2::new(self.upper, self.lower)
    }

    /// True for a zero-length segment.
    pub fn is_point(&self) -> bool {
        self.upper == self.lower
    }

    /// True for a horizontal segment of positive length.
    pub fn is_horizontal(&self) -> bool {
        self.upper.y == self.lower.y && self.upper.x != self.lower.x
    }

    /// The class of direction, for the order just below a common point: going down and
    /// to the left (positive slope) or straight down (0), down and to the right (1),
    /// horizontal (2, last as the book asks).
    pub fn direction_class(&self) -> u8 {
        if self.upper.y == self.lower.y {
            2
        } else if self.lower.x > self.upper.x {
            1
        } else {
            0
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use num_rational::BigRational;

    /// The box of every crossing contains the exact crossing, for random, nearly
    /// parallel, huge and tiny input.
    #[test]
    fn crossing_boxes_contain_the_exact_point() {
        let mut unit = crate::testing::units(7u64);
        let mut boxed = 0;
        for k in 0..20000 {
            let scale = [1.0, 1e-150, 1e150, 3.0e-7][k % 4];
            let mut pt = || Point2::new(unit() * scale, unit() * scale);
            let (a, b, c) = (pt(), pt(), pt());
            // Every third case nearly parallel to the first segment.
            let d = if k % 3 == 0 {
                Point2::new(c.x + (b.x - a.x), c.y + (b.y - a.y) * (1.0 + 1e-13))
            } else {
                pt()
            };
            let Some(cr) = Crossing::new(Segment2::new(a, b), Segment2::new(c, d)) else {
                continue;
            };
            let e = EventPoint::new(ExactPoint::Crossing(cr));
            if e.rad.x.is_infinite() {
                continue;
            }
            // The y interval alone is the box's y extent.
            assert_eq!(
                crossing_y_interval(&cr),
                (e.mid.y - e.rad.y, e.mid.y + e.rad.y)
            );
            boxed += 1;
            let (x, y) = cr.exact().expect("crossing");
            let q = |v: f64| BigRational::from_float(v).expect("finite");
            assert!(
                q(e.mid.x - e.rad.x) <= x && x <= q(e.mid.x + e.rad.x),
                "x of {cr:?}"
            );
            assert!(
                q(e.mid.y - e.rad.y) <= y && y <= q(e.mid.y + e.rad.y),
                "y of {cr:?}"
            );
        }
        assert!(boxed > 15000, "only {boxed} boxes");
    }
}
