//! The sweep order of the book (§2.1): the sweep line is horizontal and moves down, so
//! point `p` comes before `q` when `p.y > q.y`, or `p.y = q.y` and `p.x < q.x`. A
//! segment's *upper* endpoint is the one that comes first in this order (for a
//! horizontal segment, the left one).
//!
//! Event points are input points or constructed crossings. Each carries its nearest
//! `f64` point: correct rounding is monotone (`x < y` implies `round(x) <= round(y)`), so
//! when two rounded y values differ they already decide the y order exactly; only when
//! they tie does the kernel's exact y comparison run (and likewise for x, which is looked
//! at only when the exact y values are equal).

use crate::kernel::{ExactPoint, Point2, Segment2};
use std::cmp::Ordering;

/// An event point with its nearest `f64` point cached; ordered in sweep order (exactly).
#[derive(Debug, Clone, Copy)]
pub(crate) struct EventPoint {
    /// The exact point.
    pub exact: ExactPoint,
    /// Its nearest `f64` point (the point itself for an input point).
    pub approx: Point2,
}

impl EventPoint {
    /// An input point.
    pub fn input(p: Point2) -> Self {
        EventPoint {
            exact: ExactPoint::Input(p),
            approx: p,
        }
    }

    /// Any exact point (rounds a crossing once).
    pub fn new(exact: ExactPoint) -> Self {
        EventPoint {
            exact,
            approx: exact.approx(),
        }
    }

    /// The input point, if this is one.
    pub fn as_input(&self) -> Option<Point2> {
        match self.exact {
            ExactPoint::Input(p) => Some(p),
            ExactPoint::Crossing(_) => None,
        }
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
            return sweep_cmp_points(self.approx, other.approx);
        }
        // Rounded y values that differ decide y exactly; equal ones do not (the exact
        // values may still differ), so then y is compared exactly before x is looked at.
        let by_y = match other.approx.y.partial_cmp(&self.approx.y) {
            Some(Ordering::Equal) | None => other.exact.compare_y(&self.exact),
            Some(o) => o,
        };
        by_y.then_with(|| match self.approx.x.partial_cmp(&other.approx.x) {
            Some(Ordering::Equal) | None => self.exact.compare_x(&other.exact),
            Some(o) => o,
        })
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
