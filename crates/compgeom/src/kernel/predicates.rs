//! Exact predicates on input points. (Initial version: robust's adaptive predicates;
//! the kernel work adds the out-of-range fallback.)

use super::types::{Point2, Point3};
use std::cmp::Ordering;

/// The turn made by three points in the plane.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
pub enum Orientation {
    /// `a, b, c` turn left (positive signed area).
    CounterClockwise,
    /// `a, b, c` turn right (negative signed area).
    Clockwise,
    /// `a, b, c` lie on one line (includes repeated points).
    Collinear,
}

/// Where `d` lies with respect to the circle through `a, b, c`.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
pub enum CircleSide {
    /// Inside the circle (for `a, b, c` counter-clockwise).
    Inside,
    /// On the circle (or `a, b, c` collinear and `d` on their line).
    OnCircle,
    /// Outside the circle.
    Outside,
}

/// Where `d` lies with respect to the oriented plane through `a, b, c`.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
pub enum PlaneSide {
    /// Below: `a, b, c` appear counter-clockwise seen from above, `d` is below
    /// (Shewchuk's positive orient3d).
    Below,
    /// On the plane.
    Coplanar,
    /// Above.
    Above,
}

/// Where `e` lies with respect to the sphere through `a, b, c, d`.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
pub enum SphereSide {
    /// Inside (for `a, b, c, d` positively oriented, i.e. `orient3d` = [`PlaneSide::Below`]).
    Inside,
    /// On the sphere.
    OnSphere,
    /// Outside.
    Outside,
}

fn c2(p: Point2) -> robust::Coord<f64> {
    robust::Coord { x: p.x, y: p.y }
}

fn c3(p: Point3) -> robust::Coord3D<f64> {
    robust::Coord3D {
        x: p.x,
        y: p.y,
        z: p.z,
    }
}

/// The exact orientation of the triple `a, b, c`.
pub fn orient2d(a: Point2, b: Point2, c: Point2) -> Orientation {
    let d = robust::orient2d(c2(a), c2(b), c2(c));
    if d > 0.0 {
        Orientation::CounterClockwise
    } else if d < 0.0 {
        Orientation::Clockwise
    } else {
        Orientation::Collinear
    }
}

/// Exactly where `d` lies relative to the circle through `a, b, c`.
pub fn incircle(a: Point2, b: Point2, c: Point2, d: Point2) -> CircleSide {
    let v = robust::incircle(c2(a), c2(b), c2(c), c2(d));
    if v > 0.0 {
        CircleSide::Inside
    } else if v < 0.0 {
        CircleSide::Outside
    } else {
        CircleSide::OnCircle
    }
}

/// Exactly where `d` lies relative to the plane through `a, b, c`.
pub fn orient3d(a: Point3, b: Point3, c: Point3, d: Point3) -> PlaneSide {
    let v = robust::orient3d(c3(a), c3(b), c3(c), c3(d));
    if v > 0.0 {
        PlaneSide::Below
    } else if v < 0.0 {
        PlaneSide::Above
    } else {
        PlaneSide::Coplanar
    }
}

/// Exactly where `e` lies relative to the sphere through `a, b, c, d`.
pub fn insphere(a: Point3, b: Point3, c: Point3, d: Point3, e: Point3) -> SphereSide {
    let v = robust::insphere(c3(a), c3(b), c3(c), c3(d), c3(e));
    if v > 0.0 {
        SphereSide::Inside
    } else if v < 0.0 {
        SphereSide::Outside
    } else {
        SphereSide::OnSphere
    }
}

/// Lexicographic order: by x, then by y. Exact (it only compares values).
/// Both points must be finite (NaN compares as equal here).
pub fn compare_xy(a: Point2, b: Point2) -> Ordering {
    a.x.partial_cmp(&b.x)
        .unwrap_or(Ordering::Equal)
        .then(a.y.partial_cmp(&b.y).unwrap_or(Ordering::Equal))
}

/// Lexicographic order in space: by x, then y, then z.
pub fn compare_xyz(a: Point3, b: Point3) -> Ordering {
    a.x.partial_cmp(&b.x)
        .unwrap_or(Ordering::Equal)
        .then(a.y.partial_cmp(&b.y).unwrap_or(Ordering::Equal))
        .then(a.z.partial_cmp(&b.z).unwrap_or(Ordering::Equal))
}
