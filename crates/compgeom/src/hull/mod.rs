//! Convex hulls in the plane (book chapter 1, §1.1).
//!
//! This module owns the planar convex hull problem; it uses only the kernel's exact
//! predicates ([`orient2d`](crate::kernel::orient2d) for every turn,
//! [`compare_xy`](crate::kernel::compare_xy) for every ordering).
//!
//! | function | method | time |
//! |---|---|---|
//! | [`convex_hull`] (default) | Akl–Toussaint filter (8 extreme points) + monotone chain on the survivors; the filter runs in parallel above 100 000 points | O(n log n) worst case; near-linear on typical input (the filter discards almost everything) |
//! | [`andrew_convex_hull`] | the book's CONVEXHULL, Andrew's monotone chain | O(n log n) |
//! | [`slow_convex_hull`] | the book's SLOWCONVEXHULL, every ordered pair tested against every point | O(n³) |
//! | [`convex_hull_indices`] | as [`convex_hull`], reporting input indices | + O(n) |
//! | [`verify_convex_hull`] | exact check of a claimed hull | O(n log h) |
//!
//! All three give the same answer (the tests hold them to it), in one convention:
//!
//! - the **strict** hull: its vertices only, no point in the middle of an edge;
//! - **clockwise**, starting at the **lexicographically smallest** point (smallest x, then
//!   smallest y), not closed (the first vertex is not repeated);
//! - every vertex is one of the input points, copied exactly.
//!
//! With [`HullOptions::keep_collinear`], input points that lie on an edge are listed too, in
//! clockwise boundary order, each distinct point once.
//!
//! # Degenerate input
//!
//! | input | hull |
//! |---|---|
//! | empty | empty |
//! | one distinct point (maybe repeated) | that point |
//! | all points on one line | its two extreme points, smaller first (with `keep_collinear`: every distinct point, in lexicographic order from the smallest) |
//! | repeated points | merged (compared exactly; `-0.0 == 0.0`, and either may be reported) |
//! | collinear points on an edge | dropped (kept with `keep_collinear`) |
//! | a NaN or infinite coordinate | `Err(Error::NonFinite)` naming the first such point |
//!
//! # Example
//!
//! ```
//! use compgeom::hull::{convex_hull, HullOptions};
//! use compgeom::Point2;
//!
//! let pts = [(0.0, 0.0), (2.0, 0.0), (1.0, 1.0), (2.0, 2.0), (0.0, 2.0), (1.0, 2.0)]
//!     .map(Point2::from);
//! let hull = convex_hull(&pts, &HullOptions::default())?;
//! // Clockwise from the smallest point; (1, 2) is on an edge and (1, 1) inside.
//! let expected = [(0.0, 0.0), (0.0, 2.0), (2.0, 2.0), (2.0, 0.0)].map(Point2::from);
//! assert_eq!(hull, expected);
//!
//! let with_edges = convex_hull(&pts, &HullOptions::new().with_keep_collinear(true))?;
//! assert_eq!(with_edges.len(), 5);
//! assert_eq!(with_edges[2], Point2::new(1.0, 2.0));
//! # Ok::<(), compgeom::Error>(())
//! ```

mod akl_toussaint;
mod andrew;
mod slow;
mod sort;
mod verify;

use crate::kernel::{ensure_finite, Point2};
use crate::Result;
use std::collections::HashMap;

/// Which algorithm computes the hull.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default)]
pub enum HullAlgorithm {
    /// The fastest exact method: an Akl–Toussaint extreme-point filter (parallel on large
    /// input), then the monotone chain on the points that survive it. O(n log n).
    #[default]
    Default,
    /// Andrew's monotone chain, the book's CONVEXHULL (§1.1). O(n log n).
    Andrew,
    /// The book's SLOWCONVEXHULL (§1.1). O(n³): for teaching and testing only.
    Slow,
}

/// Options for [`convex_hull`].
///
/// ```
/// use compgeom::hull::{HullAlgorithm, HullOptions};
/// let opts = HullOptions::new().with_algorithm(HullAlgorithm::Andrew).with_keep_collinear(true);
/// assert_eq!(opts.algorithm, HullAlgorithm::Andrew);
/// assert!(opts.keep_collinear);
/// assert_eq!(HullOptions::DEFAULT, HullOptions::default());
/// ```
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default)]
#[non_exhaustive]
pub struct HullOptions {
    /// The algorithm. Default: [`HullAlgorithm::Default`].
    pub algorithm: HullAlgorithm,
    /// Keep input points that lie on hull edges (between two hull vertices). Default: `false`.
    pub keep_collinear: bool,
}

impl HullOptions {
    /// The default options: fastest algorithm, strict hull.
    pub const DEFAULT: HullOptions = HullOptions {
        algorithm: HullAlgorithm::Default,
        keep_collinear: false,
    };

    /// The default options.
    pub const fn new() -> Self {
        Self::DEFAULT
    }

    /// The same options with another algorithm.
    pub const fn with_algorithm(mut self, algorithm: HullAlgorithm) -> Self {
        self.algorithm = algorithm;
        self
    }

    /// The same options with `keep_collinear` set.
    pub const fn with_keep_collinear(mut self, keep_collinear: bool) -> Self {
        self.keep_collinear = keep_collinear;
        self
    }
}

/// The convex hull of `points`, clockwise from the lexicographically smallest point.
///
/// See the [module documentation](self) for the output convention and degenerate cases.
/// Time O(n log n) (O(n³) with [`HullAlgorithm::Slow`]).
///
/// # Errors
///
/// [`Error::NonFinite`](crate::Error::NonFinite) if a coordinate is NaN or infinite
/// ("point i").
///
/// ```
/// use compgeom::hull::{convex_hull, HullOptions};
/// use compgeom::Point2;
/// // All on one line: the two ends.
/// let pts = [(2.0, 2.0), (0.0, 0.0), (1.0, 1.0), (0.0, 0.0)].map(Point2::from);
/// let hull = convex_hull(&pts, &HullOptions::default())?;
/// assert_eq!(hull, [Point2::new(0.0, 0.0), Point2::new(2.0, 2.0)]);
/// # Ok::<(), compgeom::Error>(())
/// ```
pub fn convex_hull(points: &[Point2], options: &HullOptions) -> Result<Vec<Point2>> {
    ensure_finite(points, "point")?;
    let keep = options.keep_collinear;
    match options.algorithm {
        HullAlgorithm::Default => Ok(akl_toussaint::akl_toussaint(points, keep)),
        HullAlgorithm::Andrew => Ok(andrew::andrew(points, keep)),
        HullAlgorithm::Slow => slow::slow(points, keep),
    }
}

/// Like [`convex_hull`], but returns for each hull vertex the index of the first input
/// point equal to it.
///
/// ```
/// use compgeom::hull::{convex_hull_indices, HullOptions};
/// use compgeom::Point2;
/// let pts = [(1.0, 1.0), (0.0, 0.0), (2.0, 0.0), (0.0, 0.0), (1.0, 3.0)].map(Point2::from);
/// assert_eq!(convex_hull_indices(&pts, &HullOptions::default())?, [1, 4, 2]);
/// # Ok::<(), compgeom::Error>(())
/// ```
pub fn convex_hull_indices(points: &[Point2], options: &HullOptions) -> Result<Vec<usize>> {
    let hull = convex_hull(points, options)?;
    let slot: HashMap<(u64, u64), usize> = hull
        .iter()
        .enumerate()
        .map(|(i, &p)| (verify::key(p), i))
        .collect();
    let mut index = vec![usize::MAX; hull.len()];
    let mut missing = hull.len();
    for (j, &p) in points.iter().enumerate() {
        if missing == 0 {
            break;
        }
        if let Some(&i) = slot.get(&verify::key(p)) {
            if index[i] == usize::MAX {
                index[i] = j;
                missing -= 1;
            }
        }
    }
    Ok(index)
}

/// Andrew's monotone chain (the book's CONVEXHULL), strict hull. O(n log n).
///
/// Same output as [`convex_hull`]; use [`HullOptions::with_algorithm`] for
/// `keep_collinear`.
///
/// ```
/// use compgeom::hull::andrew_convex_hull;
/// use compgeom::Point2;
/// let pts = [(0.0, 0.0), (4.0, 0.0), (2.0, 1.0), (2.0, 3.0)].map(Point2::from);
/// let hull = andrew_convex_hull(&pts)?;
/// assert_eq!(hull, [(0.0, 0.0), (2.0, 3.0), (4.0, 0.0)].map(Point2::from));
/// # Ok::<(), compgeom::Error>(())
/// ```
///
/// # Errors
///
/// [`Error::NonFinite`](crate::Error::NonFinite) for a NaN or infinite coordinate.
pub fn andrew_convex_hull(points: &[Point2]) -> Result<Vec<Point2>> {
    convex_hull(
        points,
        &HullOptions::new().with_algorithm(HullAlgorithm::Andrew),
    )
}

/// The book's SLOWCONVEXHULL, strict hull. O(n³): for teaching and as a test oracle.
///
/// ```
/// use compgeom::hull::slow_convex_hull;
/// use compgeom::Point2;
/// let pts = [(0.0, 0.0), (4.0, 0.0), (2.0, 1.0), (2.0, 3.0)].map(Point2::from);
/// assert_eq!(slow_convex_hull(&pts)?, [(0.0, 0.0), (2.0, 3.0), (4.0, 0.0)].map(Point2::from));
/// # Ok::<(), compgeom::Error>(())
/// ```
///
/// # Errors
///
/// [`Error::NonFinite`](crate::Error::NonFinite) for a NaN or infinite coordinate.
pub fn slow_convex_hull(points: &[Point2]) -> Result<Vec<Point2>> {
    convex_hull(
        points,
        &HullOptions::new().with_algorithm(HullAlgorithm::Slow),
    )
}

/// Check exactly that `hull` is the convex hull of `points` in this module's convention.
///
/// Checks, in this order, and reports the first broken invariant as
/// [`Error::Verification`](crate::Error::Verification): every hull vertex is an input
/// point and none repeats; the hull starts at the lexicographically smallest input point;
/// for a hull with area, every turn is clockwise (strict hull: no collinear vertex;
/// `keep_collinear`: a vertex may lie straight between its neighbours) and the corners go
/// around once; every input point lies inside or on the hull; with `keep_collinear`, every
/// input point on the boundary is listed. Degenerate hulls (0, 1 points, a segment) are
/// checked against the conventions of the [module documentation](self).
///
/// Time O(n log h) plus hashing. Non-finite coordinates give
/// [`Error::NonFinite`](crate::Error::NonFinite).
///
/// ```
/// use compgeom::hull::verify_convex_hull;
/// use compgeom::Point2;
/// let pts = [(0.0, 0.0), (4.0, 0.0), (2.0, 1.0), (2.0, 3.0)].map(Point2::from);
/// let good = [(0.0, 0.0), (2.0, 3.0), (4.0, 0.0)].map(Point2::from);
/// assert!(verify_convex_hull(&pts, &good, false).is_ok());
/// let counter_clockwise = [(0.0, 0.0), (4.0, 0.0), (2.0, 3.0)].map(Point2::from);
/// assert!(verify_convex_hull(&pts, &counter_clockwise, false).is_err());
/// ```
pub fn verify_convex_hull(points: &[Point2], hull: &[Point2], keep_collinear: bool) -> Result<()> {
    verify::verify(points, hull, keep_collinear)
}
