//! Point location (book chapter 6): the trapezoidal map of a set of non-crossing
//! segments and the randomized incremental search structure.
//!
//! * [`TrapezoidalMap`] (§6.1–6.2): trapezoids with their top and bottom segments, left
//!   and right points and up to four neighbours; built by TRAPEZOIDALMAP, inserting the
//!   segments in a random order drawn from a seed (deterministic by default,
//!   [`DEFAULT_SEED`]) while maintaining the search structure D, a DAG of x-nodes
//!   (endpoints) and y-nodes (segments). Expected O(n log n) build, O(n) size, O(log n)
//!   query ([`TrapezoidalMap::stats`] reports the size and the longest search path).
//! * [`PointLocator`]: the map of a [`crate::dcel::Dcel`] subdivision's edges, each
//!   trapezoid labelled with its face: a query answers the face, or the edge or vertex
//!   it lies on ([`Location`]). Built from a DCEL, from segments or from polygons;
//!   [`PointLocator::locate_all`] answers batches in parallel.
//! * [`SlabLocator`] (§6.1, introduction): the simple slab method, O(log n) query but
//!   up to O(n²) space; the same answers, for comparison.
//!
//! ## Exactness and degenerate input (§6.3)
//!
//! Points are compared lexicographically (x, then y): the book's shear transformation,
//! which makes equal x coordinates and vertical segments ordinary. "Above or below a
//! segment" is an exact orientation (a floating-point filter first, the adaptive exact
//! [`crate::kernel::orient2d`] when it cannot decide). Segments may share endpoints
//! (handled by comparing the new segment's other endpoint where the search meets a
//! segment through the shared one); queries exactly on a segment or at a vertex are
//! reported as such. The map reaches to infinity (no bounding box is computed), so
//! every finite point is located.
//!
//! The segments must not cross: [`TrapezoidalMap::new`] requires interior-disjoint
//! segments ([`check_interior_disjoint_segments`]); the [`PointLocator`] builders accept
//! touching and overlapping segments (the subdivision splits and merges them) but not
//! proper crossings ([`check_no_crossings`]). Both checks are exact (the intersection
//! sweep) and name the offending pair.
//!
//! Layout: flat `Vec` arenas with `u32` indices. For queries D is frozen into 40-byte
//! nodes holding the coordinates they test; a uniform grid of cells taller than wide
//! (about eight per segment) gives each cell the deepest node that all its points pass
//! (computed exactly), so a query skips the top of D, and the nodes below each cell's
//! start are stored together.
mod check;
mod locator;
mod map;
mod slab;
mod trapmap;

pub use check::{check_interior_disjoint_segments, check_no_crossings};
pub use locator::{
    polygons_at, polygons_dcel, segments_dcel, Location, PointLocator, PolygonsDcel, SegmentsDcel,
};
pub use map::{DagStats, MapHit, Trapezoid, TrapezoidalMap, DEFAULT_SEED};
pub use slab::{SlabLocator, SLAB_MAX_ENTRIES};
