//! Orthogonal range searching (book chapter 5): which points lie in an axis-parallel
//! rectangle?
//!
//! This module owns the point-location-free range structures of chapter 5; it uses the
//! kernel's [`Point2`] and [`Bbox2`] (a closed rectangle) and nothing else. Every structure
//! is static (built in bulk), reports **input indices** (keep your data in a `Vec` and
//! index it), answers **closed** rectangles (boundary points are inside), and offers a lazy
//! iterator (`iter`), a callback (`for_each`, fastest), a sorted `Vec` (`query`, ascending
//! indices) and a count (`count`).
//!
//! | structure | book | build | query (report k) | count | memory |
//! |---|---|---|---|---|---|
//! | [`KdTree`] | §5.2 | O(n log n), parallel | O(√n + k) | O(√n) | O(n) |
//! | [`RangeTree`] | §5.3 | O(n log n), parallel | O(log² n + k) | O(log² n) | O(n log n) |
//! | [`LayeredRangeTree`] | §5.6 (fractional cascading) | O(n log n), parallel | O(log n + k) | O(log n) | O(n log n) |
//! | [`RangeTreeD`] | §5.4 (d dimensions) | O(n log^d n) | O(log^d n + k) | O(log^d n) | O(n log^{d−1} n) |
//!
//! Which to use: for small queries on large inputs the [`KdTree`] is the fastest and the
//! leanest (about 25 bytes per point); the [`LayeredRangeTree`] guarantees O(log n + k)
//! whatever the data (no O(√n) worst case) and counts in O(log n), at about 150 bytes per
//! point. The compgeom-bench `range` group measures all three against kiddo and rstar.
//!
//! The kd-tree also answers k-nearest-neighbour ([`KdTree::nearest`]) and radius
//! ([`KdTree::within_radius`]) queries, comparing squared distances exactly
//! ([`compare_distance`]).
//!
//! # Degenerate input
//!
//! - Equal x- or y-coordinates and duplicate points: handled by the composite-number space
//!   of §5.5 (see [`cmp_composite_x`]): every key is `(x | y | index)`, a strict total order.
//!   Duplicates are all reported, each with its own index.
//! - Points all on a line, all equal, or none: ordinary input.
//! - Empty rectangles (`min > max` on an axis) report nothing; zero-width or zero-height
//!   rectangles (a segment or a point) report the points on them.
//! - A NaN or infinite input coordinate: `Err(NonFinite)` naming the point. Query bounds
//!   may be infinite (a half-plane or quadrant); a NaN bound reports nothing.
//!
//! All decisions compare input coordinates with query coordinates (exact) or use the exact
//! distance comparison.
//!
//! # Query files
//!
//! [`read_rects`] reads rectangles as `xmin,ymin,xmax,ymax` lines, with the same rules and
//! located errors as [`crate::io`]'s CSV reader.

mod composite;
mod distance;
mod kdtree;
mod layered;
mod range_tree;
mod range_tree_d;
mod rects;
mod skeleton;
mod verify;

pub use composite::{cmp_composite_x, cmp_composite_y};
pub use distance::{compare_distance, compare_distance_to_radius};
pub use kdtree::{KdRangeIter, KdTree};
pub use layered::LayeredRangeTree;
pub use range_tree::RangeTree;
pub use range_tree_d::RangeTreeD;
pub use rects::read_rects;
pub use skeleton::RangeIter;
pub use verify::{verify_nearest, verify_query};

pub(crate) use composite::check_len as check_count;
pub(crate) use composite::PARALLEL;

#[cfg(doc)]
use crate::kernel::{Bbox2, Point2};
