//! Convex hulls in the plane (book chapter 1). (API skeleton; the hull work fills it in.)

use crate::kernel::Point2;
use crate::Result;

/// Which algorithm computes the hull.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default)]
pub enum HullAlgorithm {
    /// The fastest exact method.
    #[default]
    Default,
    /// Andrew's monotone chain, the book's CONVEXHULL (§1.1).
    Andrew,
    /// The book's SLOWCONVEXHULL, O(n³) (§1.1).
    Slow,
}

/// Options for [`convex_hull`].
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default)]
#[non_exhaustive]
pub struct HullOptions {
    /// The algorithm.
    pub algorithm: HullAlgorithm,
    /// Keep input points that lie on hull edges (between two hull vertices).
    pub keep_collinear: bool,
}

/// The convex hull of `points`, clockwise from the lexicographically smallest point.
pub fn convex_hull(points: &[Point2], options: &HullOptions) -> Result<Vec<Point2>> {
    let _ = (points, options);
    Ok(Vec::new())
}

/// Andrew's monotone chain (the book's CONVEXHULL).
pub fn andrew_convex_hull(points: &[Point2]) -> Result<Vec<Point2>> {
    convex_hull(points, &HullOptions::default())
}

/// The book's SLOWCONVEXHULL.
pub fn slow_convex_hull(points: &[Point2]) -> Result<Vec<Point2>> {
    convex_hull(points, &HullOptions::default())
}

/// Check exactly that `hull` is the convex hull of `points`.
pub fn verify_convex_hull(points: &[Point2], hull: &[Point2], keep_collinear: bool) -> Result<()> {
    let _ = (points, hull, keep_collinear);
    Ok(())
}
