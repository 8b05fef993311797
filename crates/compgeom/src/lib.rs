//! # compgeom
//!
//! Exact computational geometry: the algorithms, data structures and applications of
//! de Berg, Cheong, van Kreveld & Overmars, *Computational Geometry: Algorithms and
//! Applications* (3rd ed., Springer 2008), with every geometric decision made exactly.
//!
//! ## Layers
//!
//! - [`kernel`]: points, vectors, segments, lines, boxes, polygons; exact predicates
//!   ([`kernel::orient2d`], [`kernel::incircle`], [`kernel::orient3d`], [`kernel::insphere`]);
//!   exact comparisons of constructed segment crossings ([`kernel::Crossing`]).
//! - Algorithms, one module per problem of the book (see the index below).
//! - [`io`] (CSV, WKT, GeoJSON, OFF) and [`render`] (SVG pictures) at the edge.
//!
//! ## Index, in book order
//!
//! | chapter | problem | entry points |
//! |---|---|---|
//! | 1 | convex hull in the plane | [`hull::convex_hull`], [`hull::andrew_convex_hull`], [`hull::slow_convex_hull`], [`hull::convex_hull_indices`], [`hull::verify_convex_hull`] |
//! | 2.1 | line segment intersection (plane sweep) | [`intersect::find_intersections`], [`intersect::sweep_intersections`], [`intersect::count_intersections`], [`intersect::any_intersection`], [`intersect::is_simple`], [`intersect::red_blue_intersections`], [`intersect::verify_intersections`] |
//! | 2.2 | doubly-connected edge list | [`dcel::Dcel`], [`dcel::Dcel::from_segments`], [`dcel::Dcel::from_polygons`], [`dcel::Dcel::validate`] |
//! | 2.3 | map overlay | [`overlay::overlay`], [`overlay::overlay_polygons`] |
//! | 2.4 | boolean operations | [`overlay::boolean`], [`overlay::boolean_with`], [`overlay::union_all`], [`overlay::make_valid`], [`overlay::make_valid_per_polygon`] |
//! | 3 | polygon triangulation, monotone partition, art gallery, subdivision in its bounding box | [`triangulate::triangulate`], [`triangulate::triangulate_subdivision`], [`triangulate::monotone_partition`], [`triangulate::triangulate_monotone_polygon`], [`triangulate::classify_vertices`], [`triangulate::art_gallery`], [`triangulate::verify_triangulation`] |
//! | 4 | half-plane intersection, linear programming, smallest enclosing disc, casting | [`lp::intersect_halfplanes`], [`lp::intersect_halfplanes_dc`], [`lp::lp2d`], [`lp::lp_d`], [`lp::smallest_enclosing_disc`], [`lp::castability`] |
//! | 5 | orthogonal range searching | [`range::KdTree`], [`range::RangeTree`], [`range::LayeredRangeTree`], [`range::RangeTreeD`] |
//! | 6 | point location: trapezoidal map, randomized incremental search structure, slab method | [`locate::PointLocator`], [`locate::TrapezoidalMap`], [`locate::SlabLocator`], [`locate::check_no_crossings`] |
//! | 7 | Voronoi diagram (dual of Delaunay, Fortune), farthest-point diagram | [`voronoi::voronoi_diagram`], [`voronoi::dual_voronoi`], [`voronoi::voronoi_cells`], [`voronoi::fortune_voronoi`], [`voronoi::clip_cells`], [`voronoi::clip_cells_to_polygon`], [`voronoi::farthest_point_voronoi`], [`voronoi::verify_voronoi`], [`voronoi::NearestSite`] |
//! | 9 | Delaunay triangulation, constrained Delaunay (crossing constraints split), Delaunay refinement (Ruppert), terrains, EMST | [`delaunay::delaunay`], [`delaunay::delaunay_with`], [`delaunay::constrained_delaunay`], [`delaunay::polygon_delaunay`], [`delaunay::refine`], [`delaunay::Terrain`], [`delaunay::euclidean_mst`], [`delaunay::verify_delaunay`], [`delaunay::verify_cdt`] |
//! | 10 | windowing: interval, priority search and segment trees | [`windowing::IntervalTree`], [`windowing::PrioritySearchTree`], [`windowing::SegmentTree`], [`windowing::AxisParallelWindow`], [`windowing::SegmentWindow`] |
//!
//! ## Exactness
//!
//! Every branch taken on geometry is decided exactly, for input points and for points an
//! algorithm constructs. Coordinates are `f64`; non-finite input is rejected with an
//! [`Error`] that says where it was found.
// (`deny`, not `forbid`: one module, `intersect::round::fma`, allows itself the calls
// into functions compiled for FMA once the processor is known to have it; nothing else
// may use `unsafe`.)
#![deny(unsafe_code)]
#![deny(missing_docs)]
#![deny(rustdoc::broken_intra_doc_links)]

pub mod dcel;
pub mod delaunay;
mod error;
pub mod hull;
pub mod intersect;
pub mod io;
pub mod kernel;
pub mod locate;
pub mod lp;
pub mod overlay;
pub mod range;
pub mod render;
mod scratch;
#[cfg(test)]
mod testing;
pub mod triangulate;
pub mod voronoi;
pub mod windowing;

pub use error::{Error, Location, Result};
pub use kernel::{
    Bbox2, Line2, MultiPolygon, Orientation, Point2, Point3, Polygon, Segment2, Vector2, Vector3,
};
