//! Plain geometric value types. They hold `f64` coordinates and make no decisions;
//! decisions go through the exact predicates in [`super`].

use serde::{Deserialize, Serialize};

/// A point in the plane.
#[derive(Debug, Clone, Copy, PartialEq, Default, Serialize, Deserialize)]
pub struct Point2 {
    /// x coordinate.
    pub x: f64,
    /// y coordinate.
    pub y: f64,
}

impl Point2 {
    /// The point (x, y).
    pub const fn new(x: f64, y: f64) -> Self {
        Point2 { x, y }
    }

    /// True when both coordinates are finite.
    pub fn is_finite(&self) -> bool {
        self.x.is_finite() && self.y.is_finite()
    }

    /// The vector from `self` to `other` (rounded; for drawing and reporting, not decisions).
    pub fn to(&self, other: Point2) -> Vector2 {
        Vector2::new(other.x - self.x, other.y - self.y)
    }
}

impl From<(f64, f64)> for Point2 {
    fn from((x, y): (f64, f64)) -> Self {
        Point2 { x, y }
    }
}

impl From<[f64; 2]> for Point2 {
    fn from([x, y]: [f64; 2]) -> Self {
        Point2 { x, y }
    }
}

/// A point in space.
#[derive(Debug, Clone, Copy, PartialEq, Default, Serialize, Deserialize)]
pub struct Point3 {
    /// x coordinate.
    pub x: f64,
    /// y coordinate.
    pub y: f64,
    /// z coordinate.
    pub z: f64,
}

impl Point3 {
    /// The point (x, y, z).
    pub const fn new(x: f64, y: f64, z: f64) -> Self {
        Point3 { x, y, z }
    }

    /// True when all coordinates are finite.
    pub fn is_finite(&self) -> bool {
        self.x.is_finite() && self.y.is_finite() && self.z.is_finite()
    }
}

impl From<[f64; 3]> for Point3 {
    fn from([x, y, z]: [f64; 3]) -> Self {
        Point3 { x, y, z }
    }
}

/// A vector in the plane.
#[derive(Debug, Clone, Copy, PartialEq, Default, Serialize, Deserialize)]
pub struct Vector2 {
    /// x component.
    pub x: f64,
    /// y component.
    pub y: f64,
}

impl Vector2 {
    /// The vector (x, y).
    pub const fn new(x: f64, y: f64) -> Self {
        Vector2 { x, y }
    }
}

/// A vector in space.
#[derive(Debug, Clone, Copy, PartialEq, Default, Serialize, Deserialize)]
pub struct Vector3 {
    /// x component.
    pub x: f64,
    /// y component.
    pub y: f64,
    /// z component.
    pub z: f64,
}

impl Vector3 {
    /// The vector (x, y, z).
    pub const fn new(x: f64, y: f64, z: f64) -> Self {
        Vector3 { x, y, z }
    }
}

/// A closed line segment from `a` to `b`. `a == b` is allowed (a degenerate, point segment).
#[derive(Debug, Clone, Copy, PartialEq, Default, Serialize, Deserialize)]
pub struct Segment2 {
    /// First endpoint.
    pub a: Point2,
    /// Second endpoint.
    pub b: Point2,
}

impl Segment2 {
    /// The segment from `a` to `b`.
    pub const fn new(a: Point2, b: Point2) -> Self {
        Segment2 { a, b }
    }

    /// True when both endpoints are equal.
    pub fn is_degenerate(&self) -> bool {
        self.a == self.b
    }

    /// The bounding box `[min x, max x, min y, max y]` (exact: comparisons only).
    pub(crate) fn bounds(&self) -> [f64; 4] {
        [
            self.a.x.min(self.b.x),
            self.a.x.max(self.b.x),
            self.a.y.min(self.b.y),
            self.a.y.max(self.b.y),
        ]
    }
}

/// The oriented line through two distinct points `p` and `q` (kept as the two points, so
/// that every decision about it stays exact).
#[derive(Debug, Clone, Copy, PartialEq, Serialize, Deserialize)]
pub struct Line2 {
    /// A point on the line.
    pub p: Point2,
    /// A second, different point on the line; the line is oriented from `p` to `q`.
    pub q: Point2,
}

impl Line2 {
    /// The line through `p` and `q`, or `None` if `p == q`.
    pub fn through(p: Point2, q: Point2) -> Option<Self> {
        (p != q).then_some(Line2 { p, q })
    }
}

/// An axis-parallel box (closed). An empty box has `min > max`.
#[derive(Debug, Clone, Copy, PartialEq, Serialize, Deserialize)]
pub struct Bbox2 {
    /// Lower-left corner.
    pub min: Point2,
    /// Upper-right corner.
    pub max: Point2,
}

impl Bbox2 {
    /// The empty box (contains nothing; `extend` makes it grow).
    pub const EMPTY: Bbox2 = Bbox2 {
        min: Point2::new(f64::INFINITY, f64::INFINITY),
        max: Point2::new(f64::NEG_INFINITY, f64::NEG_INFINITY),
    };

    /// The smallest box containing all `points` (empty if there are none).
    pub fn of_points<'a>(points: impl IntoIterator<Item = &'a Point2>) -> Self {
        let mut b = Bbox2::EMPTY;
        for p in points {
            b.extend(*p);
        }
        b
    }

    /// Grow the box to contain `p`.
    pub fn extend(&mut self, p: Point2) {
        self.min.x = self.min.x.min(p.x);
        self.min.y = self.min.y.min(p.y);
        self.max.x = self.max.x.max(p.x);
        self.max.y = self.max.y.max(p.y);
    }

    /// True when the box contains no point.
    pub fn is_empty(&self) -> bool {
        self.min.x > self.max.x || self.min.y > self.max.y
    }

    /// True when `p` lies in the closed box.
    pub fn contains(&self, p: Point2) -> bool {
        self.min.x <= p.x && p.x <= self.max.x && self.min.y <= p.y && p.y <= self.max.y
    }

    /// Width (0 for an empty box).
    pub fn width(&self) -> f64 {
        if self.is_empty() {
            0.0
        } else {
            self.max.x - self.min.x
        }
    }

    /// Height (0 for an empty box).
    pub fn height(&self) -> f64 {
        if self.is_empty() {
            0.0
        } else {
            self.max.y - self.min.y
        }
    }
}

/// A polygon: one outer ring and zero or more holes. Rings are stored open (the first
/// vertex is not repeated at the end); orientation is not enforced by the type.
#[derive(Debug, Clone, PartialEq, Default, Serialize, Deserialize)]
pub struct Polygon {
    /// The outer boundary.
    pub exterior: Vec<Point2>,
    /// The holes.
    pub holes: Vec<Vec<Point2>>,
}

impl Polygon {
    /// A polygon with the given outer ring and holes.
    pub fn new(exterior: Vec<Point2>, holes: Vec<Vec<Point2>>) -> Self {
        Polygon { exterior, holes }
    }

    /// All rings, the exterior first.
    pub fn rings(&self) -> impl Iterator<Item = &Vec<Point2>> {
        std::iter::once(&self.exterior).chain(self.holes.iter())
    }
}

/// A set of polygons.
#[derive(Debug, Clone, PartialEq, Default, Serialize, Deserialize)]
pub struct MultiPolygon(pub Vec<Polygon>);

/// `Err(NonFinite)` naming the first point with a NaN or infinite coordinate, as
/// "`what` i" (0-based index), e.g. "point 17".
pub fn ensure_finite(points: &[Point2], what: &str) -> crate::Result<()> {
    match points.iter().position(|p| !p.is_finite()) {
        None => Ok(()),
        Some(i) => {
            let p = points[i];
            let value = if p.x.is_finite() { p.y } else { p.x };
            Err(crate::Error::NonFinite {
                what: format!("{what} {i}"),
                value,
            })
        }
    }
}
