//! Voronoi diagrams of point sites (book chapter 7).
//!
//! - [`fortune_voronoi`]: VORONOIDIAGRAM (§7.2), Fortune's sweep with the beach line in a
//!   balanced tree of arcs, site and circle events, false-alarm removal; O(n log n) time,
//!   O(n) space. [`voronoi_diagram`] with [`VoronoiAlgorithm::Default`] uses it too (the
//!   dual of the Delaunay triangulation will become the default once `delaunay` lands).
//! - [`VoronoiDiagram`]: the half-edge output (vertices, half-edges with twin/next/prev
//!   and the site on their left; faces are the sites), with a structural
//!   [`VoronoiDiagram::validate`].
//! - [`clip`]: cells as polygons in input order, clipped to a rectangle or to a convex
//!   polygon (the bounding box of §7.2 that bounds the unbounded edges).
//! - [`verify_voronoi`], [`verify_cells`]: exact verifiers (vertices' circles through their
//!   sites and empty, decided by the exact in-circle test; cells tile the clip region).
//! - [`NearestSite`]: the post-office query (nearest site), by a greedy walk on the
//!   Voronoi neighbours with exact distance comparisons.
//!
//! ## Exactness
//!
//! Voronoi vertices and breakpoints are constructed points. Every decision about them — a
//! new site's position relative to a breakpoint, the order of circle events (the lowest
//! point of a circle, which involves a square root) against sites and each other,
//! whether two vertices coincide — is decided exactly (see [`predicates`]): a rigorous
//! floating-point filter (running error bounds), then an exact-in-`f64` stage (error-free
//! transformations; settles the exact ties of grids and cocircular sites cheaply), then
//! exact dyadic big-integer arithmetic. Reported coordinates of vertices are rounded to
//! `f64`; the topology never depends on them. Clipped cell corners are computed in `f64`.
//!
//! ## Not (yet) here
//!
//! The dual-of-Delaunay method (waits for `compgeom::delaunay`), clipping to non-convex
//! polygons (rejected with an error), and the farthest-point Voronoi diagram.
//!
//! ## Degenerate input
//!
//! Duplicate sites (merged; [`VoronoiDiagram::input_to_site`]), several sites with equal
//! largest `y`, four or more cocircular sites (one vertex of degree > 3), collinear sites
//! (parallel edges, no vertices), a single site (no edges), no sites.

mod beach_line;
pub mod clip;
mod clip_polygon;
mod diagram;
mod dual;
mod farthest;
mod fortune;
mod nearest;
pub mod predicates;
mod snapshot;
mod verify;

pub use clip::{clip_cells, ClipRegion};
pub use clip_polygon::{clip_cells_to_polygon, verify_polygon_cells};
pub use diagram::{HalfEdge, Vertex, VoronoiDiagram};
pub use dual::{dual_voronoi, from_triangulation};
pub use farthest::{farthest_point_voronoi, verify_farthest, FarthestVoronoi};
pub use fortune::fortune_voronoi;
pub use nearest::NearestSite;
pub use snapshot::{beach_line_at, BeachLineSnapshot};
pub use verify::{verify_cells, verify_voronoi};

use crate::kernel::Point2;
use crate::Result;

/// Which method computes the diagram.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default)]
#[non_exhaustive]
pub enum VoronoiAlgorithm {
    /// The fastest exact method: the dual of the Delaunay triangulation
    /// ([`dual_voronoi`]).
    #[default]
    Default,
    /// Fortune's sweep, the book's VORONOIDIAGRAM (§7.2).
    Fortune,
}

/// The Voronoi diagram of `points` with the chosen algorithm.
///
/// ```
/// use compgeom::voronoi::{voronoi_diagram, VoronoiAlgorithm};
/// use compgeom::Point2;
/// let pts = [Point2::new(0.0, 0.0), Point2::new(4.0, 0.0), Point2::new(0.0, 4.0)];
/// let d = voronoi_diagram(&pts, VoronoiAlgorithm::Default).unwrap();
/// assert_eq!(d.vertices.len(), 1);
/// assert_eq!(d.vertices[0].point, Point2::new(2.0, 2.0));
/// assert_eq!(d.edge_count(), 3);
/// ```
pub fn voronoi_diagram(points: &[Point2], algorithm: VoronoiAlgorithm) -> Result<VoronoiDiagram> {
    match algorithm {
        VoronoiAlgorithm::Default => dual_voronoi(points),
        VoronoiAlgorithm::Fortune => fortune_voronoi(points),
    }
}
