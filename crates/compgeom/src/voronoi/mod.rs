//! Voronoi diagrams of point sites (book chapter 7).
//!
//! | function | method | time |
//! |---|---|---|
//! | [`voronoi_diagram`] (default), [`dual_voronoi`] | the dual of the Delaunay triangulation ([`crate::delaunay::delaunay`]); cocircular triangles merged exactly | O(n log n) |
//! | [`fortune_voronoi`], [`VoronoiAlgorithm::Fortune`] | VORONOIDIAGRAM (§7.2), Fortune's sweep: beach line in a balanced tree of arcs, site and circle events, false-alarm removal | O(n log n) |
//! | [`voronoi_cells`], [`VoronoiCells`] | the same dual in a compact form grouped by cell (8-byte edges, offsets per cell), with [`VoronoiCells::clip`] cutting only the cells that reach the region's boundary; the fastest way to clipped cells | O(n log n) |
//! | [`clip_cells`] | cells in input order clipped to a rectangle or convex polygon (the box of §7.2) | O(n + m·h) |
//! | [`clip_cells_to_polygon`] | cells clipped to any polygon set (non-convex, holes), one [`crate::MultiPolygon`] per cell | O(n + m) + a boolean per boundary cell |
//! | [`farthest_point_voronoi`] | farthest-point diagram (§7.4 notes): hull, randomized incremental farthest-point Delaunay, dual | O(n log n) |
//! | [`NearestSite`] | the post-office query (§7.1): exact greedy walk on the Delaunay graph from a bucket-grid start | O(1) expected per uniform query |
//! | [`verify_voronoi`], [`verify_cells`], [`verify_polygon_cells`], [`verify_farthest`] | exact verifiers | |
//!
//! - [`VoronoiDiagram`]: the half-edge output (vertices, half-edges with twin/next/prev
//!   and the site on their left; faces are the sites), with a structural
//!   [`VoronoiDiagram::validate`]. Both algorithms give the same diagram (same vertices as
//!   sets of sites, same directed edges); the tests hold them to it.
//! - [`beach_line_at`]: Fortune's sweep stopped at a given height, for pictures.
//!
//! ## Exactness
//!
//! Voronoi vertices and breakpoints are constructed points. Every decision about them — a
//! new site's position relative to a breakpoint, the order of circle events (the lowest
//! point of a circle, which involves a square root) against sites and each other,
//! whether two vertices coincide — is decided exactly (see [`predicates`]): a rigorous
//! floating-point filter (running error bounds), then an exact-in-`f64` stage (error-free
//! transformations; settles the exact ties of grids and cocircular sites cheaply), then
//! exact dyadic big-integer arithmetic. The dual decides coincident vertices with the exact
//! in-circle test. Reported coordinates of vertices are rounded to `f64`; the topology
//! never depends on them. Clipped cell corners are computed in `f64`; clipping to a
//! general polygon decides inside/outside and crossings exactly on those corners.
//!
//! ## Degenerate input
//!
//! Duplicate sites (merged; [`VoronoiDiagram::input_to_site`]), several sites with equal
//! largest `y`, four or more cocircular sites (one vertex of degree > 3), collinear sites
//! (parallel edges, no vertices), a single site (no edges), no sites.

mod beach_line;
mod cells;
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

pub use cells::{voronoi_cells, CellEdge, VoronoiCells};
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
